"""The shared simplicial core: coefficient checks, closure, boundary signs."""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib._validate import MAX_EXACT_PRIME, check_coefficients
from thesis_lib.homology.simplicial import boundary_matrix, closure


@settings(deadline=None, max_examples=300)
@given(st.integers(min_value=-5, max_value=10**6))
def test_prime_check_matches_sympy(n):
    if n == 0 or sympy.isprime(n):
        assert check_coefficients(n) == n
    else:
        with pytest.raises(ValueError, match="0 \\(the integers\\) or a prime"):
            check_coefficients(n)


def test_large_primes_are_checked_fast():
    assert check_coefficients(2**61 - 1, max_prime=MAX_EXACT_PRIME) == 2**61 - 1
    with pytest.raises(ValueError):
        check_coefficients((2**31 - 1) * (2**31 + 11))


def test_closure_and_boundary_of_a_tetrahedron():
    cells = closure([(0, 1, 2, 3)])
    assert [c.shape[0] for c in cells] == [4, 6, 4, 1]
    for k in (1, 2, 3):
        b = boundary_matrix(cells[k - 1], cells[k])
        assert np.all(np.abs(b.toarray()).sum(axis=0) == k + 1)
    assert abs(boundary_matrix(cells[0], cells[1]) @ boundary_matrix(cells[1], cells[2])).sum() == 0


def test_repeated_vertices_are_refused():
    with pytest.raises(ValueError, match="repeated vertex"):
        closure([(0, 1, 1)])

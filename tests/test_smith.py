"""Tests for thesis_lib.smith: Smith normal form over Z and ranks over Z/p."""

import numpy as np
import pytest
import scipy.sparse as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from helpers import THESIS_M2, sympy_invariants
from thesis_lib.smith import (
    dense_smith_diagonal,
    rank_mod_p,
    reduce_matrix,
    smith_normal_form,
)


def test_example_2_21_m2():
    # Thesis: diagonal (1, ..., 1, 2, 0, ...) with 10 nonzero terms, k_2 = 10.
    assert smith_normal_form(THESIS_M2).tolist() == [1] * 9 + [2]
    assert smith_normal_form(sp.csc_matrix(THESIS_M2)).tolist() == [1] * 9 + [2]
    assert rank_mod_p(THESIS_M2, 2) == 9
    assert rank_mod_p(THESIS_M2, 3) == 10


def test_known_small_cases():
    assert smith_normal_form([[2, 4], [6, -8]]).tolist() == [2, 20]
    assert smith_normal_form([[2, 0], [0, 3]]).tolist() == [1, 6]
    assert smith_normal_form([[4, 0], [0, 6]]).tolist() == [2, 12]
    assert smith_normal_form(np.zeros((3, 4), dtype=int)).tolist() == []
    assert smith_normal_form(np.zeros((0, 4), dtype=int)).tolist() == []
    assert smith_normal_form(np.eye(5, dtype=int)).tolist() == [1] * 5
    assert smith_normal_form([[1.0, 2.0], [3.0, 4.0]]).tolist() == [1, 2]  # integral floats are fine
    assert smith_normal_form(np.array([[True, True], [False, True]])).tolist() == [1, 1]


@settings(deadline=None, max_examples=60)
@given(
    st.integers(1, 7),
    st.integers(1, 7),
    st.integers(0, 2**32 - 1),
    st.sampled_from([1, 3, 9, 40]),
    st.floats(0.2, 1.0),
)
def test_matches_sympy_on_random_matrices(m, n, seed, bound, density):
    rng = np.random.default_rng(seed)
    a = rng.integers(-bound, bound + 1, (m, n)) * (rng.random((m, n)) < density)
    ref = sympy_invariants(a)
    assert smith_normal_form(a).tolist() == ref
    assert smith_normal_form(sp.csr_matrix(a)).tolist() == ref
    # the exact Python-integer engine (used on int64 overflow) agrees
    red = reduce_matrix(a, int64_limit=2)
    assert [1] * (red.rank - len(red.invariants)) + red.invariants == ref
    # rank over Z/p = number of invariant factors prime to p
    for p in (2, 3, 5):
        assert rank_mod_p(a, p) == sum(1 for x in ref if x % p)


@settings(deadline=None, max_examples=15)
@given(st.integers(0, 2**32 - 1))
def test_low_rank_products_match_sympy(seed):
    # products of random integer matrices have nontrivial invariant factors
    rng = np.random.default_rng(seed)
    a = rng.integers(-3, 4, (6, 3)) @ np.diag(rng.integers(1, 5, 3)) @ rng.integers(-3, 4, (3, 7))
    assert smith_normal_form(a).tolist() == sympy_invariants(a)


def test_big_integers_are_exact():
    big = 2**70
    a = np.array([[big, 0, 3], [0, 2 * big, 5], [7, 11, big + 1]], dtype=object)
    ours = smith_normal_form(a)
    assert ours.dtype == object
    assert [int(x) for x in ours] == sympy_invariants(a)
    d = np.array([[2**40, 0], [0, 3 * 2**40]], dtype=object)
    assert [int(x) for x in smith_normal_form(d)] == [2**40, 3 * 2**40]
    assert dense_smith_diagonal(d) == [2**40, 3 * 2**40]


def test_large_sparse_unit_matrix_and_skip():
    # a long path graph's incidence matrix: rank n - 1, all invariant factors 1
    n = 20000
    rows = np.r_[np.arange(n - 1), np.arange(1, n)]
    cols = np.r_[np.arange(n - 1), np.arange(n - 1)]
    vals = np.r_[-np.ones(n - 1, int), np.ones(n - 1, int)]
    a = sp.csc_matrix((vals, (rows, cols)), shape=(n, n - 1))
    red = reduce_matrix(a)
    assert red.rank == n - 1 and red.invariants == [] and red.unit_pivot_rows.sum() == n - 1
    skip = np.zeros(n - 1, bool)
    skip[::2] = True
    assert reduce_matrix(a, skip_columns=skip).rank == (n - 1) // 2
    assert reduce_matrix(a, 7, skip_columns=skip).rank == (n - 1) // 2


def test_large_prime_uses_exact_engine():
    p = 2147483659  # the first prime above 2**31: too big for the int64 kernel
    assert rank_mod_p(THESIS_M2, p) == 10
    assert rank_mod_p([[p, 0], [0, 1]], p) == 1
    assert rank_mod_p([[p, 0], [0, 1]], 2**31 - 1) == 2


@pytest.mark.parametrize(
    "bad, message",
    [
        (np.zeros((2, 2, 2)), "2-D"),
        (np.zeros(3), "2-D"),
        ([[1.5, 0], [0, 1]], "integers"),
        ([[np.nan, 0], [0, 1]], "NaN"),
        ([[np.inf, 0], [0, 1]], "NaN or inf"),
        ([["a", "b"]], "integers"),
        (np.array([[1, None]], dtype=object), "integers"),
    ],
)
def test_bad_matrices(bad, message):
    with pytest.raises(ValueError, match=message):
        smith_normal_form(bad)


def test_bad_coefficients_and_masks():
    with pytest.raises(ValueError, match="prime"):
        rank_mod_p(THESIS_M2, 4)
    with pytest.raises(ValueError, match="prime"):
        rank_mod_p(THESIS_M2, 0)
    with pytest.raises(ValueError, match="prime"):
        reduce_matrix(THESIS_M2, 1)
    with pytest.raises(ValueError, match="skip_columns"):
        reduce_matrix(THESIS_M2, skip_columns=np.zeros(3, bool))
    with pytest.raises(ValueError, match="2-D"):
        dense_smith_diagonal(np.zeros(3))
    with pytest.raises(ValueError, match="integers"):
        dense_smith_diagonal(np.array([[0.5]]))
    with pytest.raises(ValueError, match="integers"):
        dense_smith_diagonal(np.array([[1, "x"]], dtype=object))
    assert dense_smith_diagonal(np.array([[6, 0], [0, 4]], dtype=object)) == [2, 12]


@settings(deadline=None, max_examples=6)
@given(st.integers(0, 2**32 - 1))
def test_sparse_matrices_with_postponed_rows_match_sympy(seed):
    # sparse entries in {-3..3}: many non-unit entries, so rows get postponed and a core remains
    rng = np.random.default_rng(seed)
    a = rng.integers(-3, 4, (18, 22)) * (rng.random((18, 22)) < 0.25)
    red = reduce_matrix(sp.csc_matrix(a))
    assert [1] * (red.rank - len(red.invariants)) + red.invariants == sympy_invariants(a)

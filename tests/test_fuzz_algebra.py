"""Fuzzing homology and discrete Morse theory: hostile complexes, matrices, coefficients,
pairs and Morse functions get a correct value or a ValueError/TypeError with a message — never
another exception, never a hang (the shared fuzz harness counts them under "homology" and "morse")."""

from __future__ import annotations

import itertools

import numpy as np
import sympy
from helpers import fuzz_call, fuzz_settings
from hypothesis import given
from hypothesis import strategies as st

from thesis_lib.homology import betti_numbers, homology
from thesis_lib.homology.smith import smith_normal_form
from thesis_lib.morse.functions import (
    check_discrete_morse_function,
    critical_simplices,
    discrete_morse_function,
    gradient_pairs,
)
from thesis_lib.morse.matching import critical_counts, morse_matching
from thesis_lib.morse.morse_complex import morse_homology
from thesis_lib.morse.vector_field import is_acyclic

FUZZ = fuzz_settings(60)  # 100 times more with --fuzz-long

numbers = st.one_of(st.integers(-3, 7), st.floats(allow_nan=True, allow_infinity=True), st.just(10**30),
                    st.booleans(), st.text(max_size=2), st.none())
vertices = st.integers(0, 6)
good_simplex = st.lists(vertices, min_size=1, max_size=4, unique=True).map(tuple)
simplex = st.one_of(good_simplex, st.lists(numbers, max_size=4).map(tuple), numbers)
complexes = st.one_of(st.lists(good_simplex, min_size=1, max_size=8), st.lists(simplex, max_size=6), numbers,
                      st.just(np.zeros((0, 3))), st.just(np.array([[0, 1], [1, 2]])),
                      st.just([np.array([[0], [1]]), np.array([[0, 1]])]))
coefficients = st.one_of(st.sampled_from([0, 2, 3, 4, 1, -3, 2.5, "2", None, True, 10**30 + 57, 2**31 - 1]),
                         st.integers(-5, 40))
pairs = st.one_of(st.lists(st.tuples(simplex, simplex), max_size=5), numbers, st.lists(numbers, max_size=3))
entries = st.one_of(st.integers(-10**20, 10**20), st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=1),
                    st.none(), st.booleans())


def _clear(module: str, call):
    ok, value = fuzz_call(module, call)
    return value if ok else None


def _euler(obj) -> int:
    """χ of the closure of an accepted complex: a list of simplices or one vertex array per dimension."""
    if isinstance(obj, list) and obj and all(isinstance(a, np.ndarray) and a.ndim == 2 for a in obj):
        simplices = [tuple(int(v) for v in row) for a in obj for row in a]
    else:
        simplices = [tuple(int(v) for v in np.atleast_1d(s)) for s in obj]
    closed = {tuple(sorted(f)) for s in simplices for k in range(1, len(s) + 1)
              for f in itertools.combinations(sorted(s), k)}
    return sum((-1) ** (len(s) - 1) for s in closed)


@FUZZ
@given(obj=complexes, coef=coefficients)
def test_homology_of_hostile_input(obj, coef):
    out = _clear("homology", lambda: homology(obj, coefficients=coef))
    if out is not None:
        ranks = [r for r, _ in out]
        assert all(r >= 0 for r in ranks)
        # the Euler characteristic of whatever complex was accepted (Theorem 2.20's alternating sum)
        assert sum((-1) ** d * r for d, r in enumerate(ranks)) == _euler(obj)
        assert _clear("homology", lambda: betti_numbers(obj, coefficients=coef)) == ranks


def _sympy_invariants(rows: int, cols: int, integers: list[int]) -> list[int]:
    from sympy.matrices.normalforms import smith_normal_form as sympy_snf

    if rows == 0 or cols == 0:
        return []
    d = sympy_snf(sympy.Matrix(rows, cols, integers))
    return sorted(abs(int(d[k, k])) for k in range(min(rows, cols)) if d[k, k] != 0)


@FUZZ
@given(rows=st.integers(0, 4), cols=st.integers(0, 4), data=st.data())
def test_smith_normal_form_of_hostile_matrices(rows, cols, data):
    values = data.draw(st.lists(entries, min_size=rows * cols, max_size=rows * cols))
    shape = data.draw(st.sampled_from(["object array", "nested lists", "flat list"]))
    m = (np.array(values, dtype=object).reshape(rows, cols) if shape == "object array" else
         [values[i * cols:(i + 1) * cols] for i in range(rows)] if shape == "nested lists" else values)
    out = _clear("homology", lambda: smith_normal_form(m))
    if out is not None:  # accepted: integers (bools count as 0/1), and the same invariants as sympy
        assert sorted(int(x) for x in out) == _sympy_invariants(rows, cols, [int(v) for v in values])


@FUZZ
@given(obj=complexes, p=pairs, coef=coefficients)
def test_morse_homology_of_hostile_input(obj, p, coef):
    out = _clear("morse", lambda: morse_homology(obj, p, coefficients=coef))
    if out is not None:  # an acyclic field on an accepted complex: Morse homology is homology (Theorem 4.42)
        assert out == homology(obj, coefficients=coef)
        f = _clear("morse", lambda: discrete_morse_function(obj, p))
        assert f is not None and _clear("morse", lambda: check_discrete_morse_function(f)) is None


@FUZZ
@given(obj=complexes, heuristic=st.one_of(st.sampled_from(["coreduction", "collapse", "lower-star", "x"]), numbers),
       seed=st.one_of(st.none(), st.integers(-2, 5), st.floats()), values=st.one_of(st.none(), st.lists(numbers)))
def test_morse_matching_of_hostile_input(obj, heuristic, seed, values):
    out = _clear("morse", lambda: morse_matching(obj, heuristic=heuristic, values=values, seed=seed))
    if out is not None:
        assert is_acyclic(obj, out)
        counts = critical_counts(obj, out)
        assert sum((-1) ** d * c for d, c in enumerate(counts)) == _euler(obj)  # weak Morse: χ from critical cells


@FUZZ
@given(values=st.one_of(st.dictionaries(simplex, numbers, max_size=6),
                        st.lists(st.tuples(simplex, numbers), max_size=6), numbers))
def test_discrete_morse_functions_of_hostile_input(values):
    crit = _clear("morse", lambda: critical_simplices(values))
    grad = _clear("morse", lambda: gradient_pairs(values))
    if crit is not None and grad is not None:  # Definition 4.20: every simplex critical or in one pair
        paired = {s for pair in grad for s in pair}
        assert not paired & set(crit)

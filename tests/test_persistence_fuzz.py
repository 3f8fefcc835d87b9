"""Fuzzing the persistence layer: hostile filtrations, coefficients and dimensions get a
correct value or a ValueError/TypeError with a message — never another exception."""

from __future__ import annotations

import math

import numpy as np
import pytest
from helpers import fuzz_call, fuzz_settings
from hypothesis import given
from hypothesis import strategies as st

from thesis_lib.datasets import example_filtration
from thesis_lib.persistence import Barcode, compute_intervals, persistence, rips_persistence

FUZZ = fuzz_settings(60)  # 100 times more with --fuzz-long

numbers = st.one_of(st.integers(-3, 6), st.floats(allow_nan=True, allow_infinity=True), st.just(10**30),
                    st.booleans(), st.text(max_size=3), st.none())
simplex = st.one_of(st.lists(numbers, max_size=4).map(tuple), numbers, st.text(max_size=4))
pairs = st.lists(st.tuples(simplex, numbers), max_size=6)
complexes = st.one_of(pairs, st.lists(simplex, max_size=6), numbers, st.dictionaries(st.text(max_size=2), numbers),
                      st.just(np.random.default_rng(0).random((5, 2))), st.just(np.zeros((0, 3))),
                      st.just(np.array([[0, 1], [1, 2]])), st.just([np.array([[0], [1]]), np.array([[0, 1]])]))
coefficients = st.one_of(st.sampled_from([0, 1, 2, 3, 4, -3, 2.5, "2", None, True, 10**30 + 57, 2**31 - 1,
                                           2**61 - 1, np.int64(5)]), st.integers(-10, 100))


def _clear(call):
    """Run call() through the shared fuzz harness: the value, or None after a ValueError/TypeError
    with a message; any other exception, an empty message or a hang fails (and is counted)."""
    ok, value = fuzz_call("persistence", call)
    return value if ok else None


@FUZZ
@given(obj=complexes, coef=coefficients)
def test_persistence_of_hostile_input(obj, coef):
    out = _clear(lambda: persistence(obj, coefficients=coef))
    if out is not None:
        assert isinstance(out, Barcode)
        ref = compute_intervals(obj, coefficients=coef)  # the thesis's algorithm agrees
        assert out == ref


@FUZZ
@given(coef=coefficients, dim=st.one_of(st.integers(-2, 4), st.floats(), st.text(max_size=2), st.none()),
       n=st.one_of(st.integers(-2, 5), st.floats(), st.none()))
def test_barcode_queries_and_coefficients(coef, dim, n):
    out = _clear(lambda: persistence(example_filtration(), coefficients=coef))
    if out is not None:
        assert coef is None or (isinstance(coef, (int, np.integer)) and not isinstance(coef, bool))  # None: Z/2
    bc = persistence(example_filtration())
    iv = _clear(lambda: bc.intervals(dim))
    if iv is not None:
        assert iv.ndim == 2 and iv.shape[1] == 2
    idx = _clear(lambda: bc.longest(0, n=n))
    if idx is not None:
        assert len(idx) == min(int(n), len(bc.intervals(0)))
    b = _clear(lambda: bc.betti(dim, dim=0))
    if b is not None:
        assert b >= 0


@FUZZ
@given(pts=st.one_of(st.lists(st.lists(st.floats(-1e3, 1e3), min_size=2, max_size=2), max_size=8),
                     st.lists(st.lists(st.floats(allow_nan=True), min_size=1, max_size=3), max_size=4), numbers),
       eps=st.one_of(st.floats(allow_nan=True), st.integers(-1, 3), st.text(max_size=1)),
       max_dim=st.one_of(st.integers(-1, 3), st.floats(), st.none()), coef=coefficients)
def test_rips_persistence_of_hostile_input(pts, eps, max_dim, coef):
    out = _clear(lambda: rips_persistence(pts, max_radius=eps, max_dim=max_dim, coefficients=coef))
    if out is not None:
        assert out.complete_dimensions == tuple(range(max_dim))
        assert all(np.all(out.intervals(d)[:, 1] > out.intervals(d)[:, 0]) for d in out.dimensions)


def test_points_given_for_a_filtration_say_how_to_build_one():
    with pytest.raises(ValueError, match="rips"):
        persistence(np.random.default_rng(0).random((10, 2)))
    with pytest.raises(ValueError, match="rips"):
        compute_intervals(np.random.default_rng(0).random((10, 2)))


def test_compute_intervals_raw_errors_are_clear():
    for bad, pattern in [([((0, 1), 0.0)], "face"), ([((0,), math.nan)], "NaN"),
                         ([((0,), 1.0), ((1,), 0.0)], "decrease"), ([((0,), 0.0), ((0,), 0.0)], "twice"),
                         (5, "iterable"), ("ab", "expected")]:
        with pytest.raises((ValueError, TypeError), match=pattern):
            compute_intervals(bad)

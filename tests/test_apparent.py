"""Apparent pairs: a discrete gradient (Definitions 4.30–4.33) whose pairs are persistence pairs."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import rips
from thesis_lib.datasets import example_filtration, two_circles
from thesis_lib.morse.reduction import morse_reduce, reduced_persistence
from thesis_lib.morse.vector_field import is_acyclic
from thesis_lib.persistence import apparent_pairs, apparent_summary, persistence


@settings(deadline=None, max_examples=20)
@given(seed=st.integers(0, 10**6), n=st.integers(4, 14), eps=st.sampled_from([0.3, 0.5, np.inf]))
def test_apparent_pairs_are_an_acyclic_gradient_of_persistence_pairs(seed, n, eps):
    f = rips(np.random.default_rng(seed).random((n, 2)), max_radius=eps, max_dim=3)
    pairs = apparent_pairs(f)
    cells = [c for pair in pairs for c in pair]
    assert len(cells) == len(set(cells))  # a discrete vector field: each simplex in at most one pair
    assert all(len(t) == len(s) + 1 and set(s) < set(t) for s, t in pairs)
    simplices = [tuple(r) for S in f.simplices for r in S.tolist()]
    assert is_acyclic(simplices, pairs)  # Theorem 4.36: the gradient of a discrete Morse function
    # each pair of positive length is an interval of the barcode, created by σ and killed by τ
    bc = persistence(f)
    index = [{tuple(r): i for i, r in enumerate(S.tolist())} for S in f.simplices]
    for s, t in pairs:
        d = len(s) - 1
        a, b = index[d][s], index[d + 1][t]
        if f.values[d][a] < f.values[d + 1][b]:
            assert [a, b] in bc.simplex_pairs(d).tolist()
    # the zero pairs reduce the filtration to a Morse complex with the same barcode (Theorem 4.42)
    zero = apparent_pairs(f, zero=True)
    assert set(zero) <= set(pairs)
    assert reduced_persistence(morse_reduce(f, pairs=zero)) == bc


def test_summary_counts_on_the_example_and_two_circles():
    s = apparent_summary(example_filtration())
    assert s["simplices"] == [5, 6, 1]
    assert sum(s["critical"]) == sum(s["simplices"]) - 2 * len(apparent_pairs(example_filtration()))
    f = rips(two_circles(20, seed=0), max_radius=2.0, max_dim=2)
    s = apparent_summary(f)
    assert s["simplices"] == [40, 780, 9880]
    # Theorem 4.27: at least β_k critical cells (β0 = 1, β1 = 3 up to the death of the holes)
    assert s["critical"][0] >= 1 and s["critical"][1] >= 3
    # below the (truncated) top dimension, a few per cent of the cells are left for the reduction
    assert s["critical_fraction_below_top"] == (s["critical"][0] + s["critical"][1]) / 820 < 0.1
    assert s["zero_critical_fraction"] >= s["critical_fraction"]


def test_bad_input():
    with pytest.raises(ValueError, match="point cloud"):
        apparent_pairs(np.random.default_rng(0).random((5, 2)))

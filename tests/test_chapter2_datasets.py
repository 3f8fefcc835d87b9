"""Tests of the chapter 2 filtrations in thesis_lib.datasets.filtrations (Examples 2.36, 2.40; Algorithm 2)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.datasets import dense_filtration, example_filtration, module_filtration, named_chain
from thesis_lib.datasets.filtrations import EXAMPLE_2_40_CYCLES
from thesis_lib.homology.simplicial import boundary_matrix
from thesis_lib.persistence import compute_intervals, persistence


def _intervals(summands):
    rows = [(a, math.inf if n is None else a + n) for a, n in summands]
    return sorted(rows)


def test_module_filtration_of_example_2_36():
    K = module_filtration([(0, None), (1, None), (2, 2)])
    for bars in (compute_intervals(K), persistence(K)):
        assert sorted(map(tuple, bars.intervals(1).tolist())) == [(0.0, math.inf), (1.0, math.inf), (2.0, 4.0)]
    # Each summand is its own component, born with it: three essential classes in H0.
    assert persistence(K).intervals(0).tolist() == [[0.0, math.inf], [1.0, math.inf], [2.0, math.inf]]


@settings(deadline=None, max_examples=25)
@given(
    summands=st.lists(st.tuples(st.integers(0, 6), st.one_of(st.none(), st.integers(1, 4))), min_size=1, max_size=6),
    dim=st.integers(1, 3),
)
def test_module_filtration_realises_any_module(summands, dim):
    K = module_filtration(summands, dim=dim)
    expected = _intervals(summands)
    for bars in (compute_intervals(K, coefficients=3), persistence(K, coefficients=2)):
        assert sorted(map(tuple, bars.intervals(dim).tolist())) == expected
        for d in range(1, dim):
            assert len(bars.intervals(d)) == 0


def test_module_filtration_rejects_bad_summands():
    with pytest.raises(ValueError, match="at least one summand"):
        module_filtration([])
    with pytest.raises(ValueError, match="shift"):
        module_filtration([(-1, None)])
    with pytest.raises(ValueError, match="torsion order"):
        module_filtration([(0, 0)])
    with pytest.raises(ValueError, match="dim"):
        module_filtration([(0, None)], dim=0)


def test_named_chain_orientation():
    assert named_chain({"da": 1}) == {(0, 3): -1}
    assert named_chain({"ab": 2, "ba": 2}) == {}
    assert named_chain({"ced": 1}) == {(2, 3, 4): -1}  # [c, e, d] is an odd permutation of [c, d, e]
    with pytest.raises(ValueError, match="names a vertex"):
        named_chain({"az": 1})
    with pytest.raises(ValueError, match="repeats"):
        named_chain({"aa": 1})


@pytest.mark.parametrize("name", ["z1", "z2"])
def test_example_2_40_cycles_are_cycles_of_the_example(name):
    K = example_filtration()
    chain = named_chain(EXAMPLE_2_40_CYCLES[name])
    edges = np.array(sorted(chain))
    assert all(any((row == e).all() for row in K.simplices[1]) for e in edges)
    coeffs = np.array([chain[tuple(e)] for e in edges])
    assert not np.any(boundary_matrix(K.simplices[0], edges) @ coeffs)


def test_dense_filtration_counts_and_agreement():
    K = dense_filtration(7, seed=3)
    assert K.counts() == [7, 21, 35]
    assert dense_filtration(7, seed=3).simplices[1].tolist() == K.simplices[1].tolist()
    assert dense_filtration(7, seed=4).simplices[1].tolist() != K.simplices[1].tolist()
    assert compute_intervals(K) == persistence(K)
    with pytest.raises(ValueError, match="n_vertices"):
        dense_filtration(2, seed=0)

"""Morse reduction of filtrations: same barcode as the filtration (thesis §4.2.6 and §2.3)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import Filtration
from thesis_lib.complexes.rips import rips
from thesis_lib.datasets import example_filtration, torus
from thesis_lib.homology import homology
from thesis_lib.homology.simplicial import boundary_matrix
from thesis_lib.morse.matching import critical_counts, morse_matching
from thesis_lib.morse.morse_complex import morse_homology
from thesis_lib.morse.reduction import filtration_matching, lower_star_filtration, morse_reduce, reduced_persistence
from thesis_lib.morse.vector_field import is_acyclic
from thesis_lib.persistence import Barcode, chain_persistence, persistence

seeds = st.integers(0, 2**31 - 1)


def grid_triangles(n: int) -> list[tuple[int, int, int]]:
    out = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, i * n + j + 1, (i + 1) * n + j, (i + 1) * n + j + 1
            out += [(a, b, d), (a, c, d)]
    return out


def lower_star_grid(seed: int, n: int) -> tuple[list[tuple[int, int, int]], np.ndarray, Filtration]:
    """The triangulated n × n grid, random vertex values and their lower-star filtration."""
    values = np.random.default_rng(seed).random(n * n)
    tris = grid_triangles(n)
    return tris, values, lower_star_filtration(tris, values)


def full_barcode(filt: Filtration, p: int) -> Barcode:
    """Our column reduction on the unreduced complex (a second reference)."""
    bds = [np.zeros((0, filt.simplices[0].shape[0]))]
    bds += [boundary_matrix(filt.simplices[d - 1], filt.simplices[d]) for d in range(1, filt.dimension + 1)]
    return chain_persistence(filt.values, bds, coefficients=p)


@settings(deadline=None, max_examples=15)
@given(seeds, st.sampled_from([2, 3]))
def test_rips_reduction_keeps_the_barcode(seed, p):
    rng = np.random.default_rng(seed)
    pts = rng.random((int(rng.integers(6, 16)), 2))
    filt = rips(pts, max_radius=0.45, max_dim=int(rng.integers(1, 4)))
    red = morse_reduce(filt, coefficients=p)
    assert red.n_critical <= red.n_cells
    ours = reduced_persistence(red)
    ref = persistence(filt, coefficients=p)
    assert ours == ref, ours.difference(ref)
    assert full_barcode(filt, p) == ref


@settings(deadline=None, max_examples=10)
@given(seeds)
def test_lower_star_reduction_is_small_and_exact(seed):
    _, _, filt = lower_star_grid(seed, 7)
    red = morse_reduce(filt, coefficients=2)
    assert reduced_persistence(red) == persistence(filt, coefficients=2)
    # a lower-star matching leaves few cells: here less than half
    assert red.critical_fraction < 0.5


@settings(deadline=None, max_examples=8)
@given(seeds)
def test_reduction_with_lower_star_pairs(seed):
    """ProcessLowerStars pairs lie in one lower star, so they are filtration-compatible."""
    tris, values, filt = lower_star_grid(seed, 6)
    pairs = morse_matching(tris, heuristic="lower-star", values=values)
    red = morse_reduce(filt, coefficients=3, pairs=pairs)
    assert red.n_critical == sum(critical_counts(tris, pairs))
    assert reduced_persistence(red) == persistence(filt, coefficients=3)


def test_filtration_matching_pairs_equal_values_and_is_acyclic():
    pts = np.random.default_rng(4).random((14, 2))
    filt = rips(pts, max_radius=0.5, max_dim=3)
    pairs = filtration_matching(filt)
    value = {s: v for s, v in filt}
    assert pairs and all(value[s] == value[t] for s, t in pairs)
    simplices = [s for s, _ in filt]
    assert is_acyclic(simplices, pairs)
    assert morse_homology(simplices, pairs) == homology(simplices)


def test_example_filtration_and_gudhi():
    filt = example_filtration()
    red = morse_reduce(filt, coefficients=2)
    assert reduced_persistence(red) == persistence(filt, coefficients=2)
    gudhi = pytest.importorskip("gudhi")
    pts = np.random.default_rng(7).random((25, 3))
    filt = rips(pts, max_radius=0.35, max_dim=2)
    ours = reduced_persistence(morse_reduce(filt, coefficients=2))
    st_ = gudhi.RipsComplex(points=pts, max_edge_length=0.7).create_simplex_tree(max_dimension=2)
    pairs = st_.persistence(homology_coeff_field=2, min_persistence=0, persistence_dim_max=True)
    ref = Barcode.from_pairs(((d, (b / 2, dd / 2)) for d, (b, dd) in pairs if dd > b), dimensions=range(3))
    assert ours.allclose(ref, atol=1e-12), ours.difference(ref, atol=1e-12)


def test_integer_reduction_and_torus_lower_star():
    tri = torus()
    filt = lower_star_filtration(tri, np.arange(7, dtype=float))
    red = morse_reduce(filt, coefficients=0)
    assert red.coefficients == 0 and red.boundaries[1].dtype == np.int64
    for p in (2, 3):
        assert reduced_persistence(red, coefficients=p) == persistence(filt, coefficients=p)
    b = reduced_persistence(red, coefficients=2)
    assert [len(b.intervals(d)[np.isinf(b.intervals(d)[:, 1])]) for d in range(3)] == [1, 2, 1]


def test_reduction_errors():
    filt = example_filtration()
    with pytest.raises(ValueError, match="prime"):
        morse_reduce(filt, coefficients=4)
    red = morse_reduce(filt, coefficients=3)
    with pytest.raises(ValueError, match="mod 3"):
        reduced_persistence(red, coefficients=2)
    with pytest.raises(ValueError, match="prime field"):
        chain_persistence([np.zeros(1)], [np.zeros((0, 1))], coefficients=0)
    with pytest.raises(ValueError, match="shape"):
        chain_persistence([np.zeros(2), np.ones(1)], [np.zeros((0, 2)), np.ones((3, 1))], coefficients=2)
    with pytest.raises(ValueError, match="larger filtration value"):
        chain_persistence([np.array([0.0, 2.0]), np.ones(1)], [np.zeros((0, 2)), np.ones((2, 1))], coefficients=2)
    with pytest.raises(ValueError, match="one boundary matrix per dimension"):
        chain_persistence([np.zeros(2)], [], coefficients=2)
    with pytest.raises(ValueError, match="finite"):
        lower_star_filtration([(0, 1)], [0.0, np.nan])
    with pytest.raises(ValueError, match="cover 2 vertices"):
        lower_star_filtration([(0, 2)], [0.0, 1.0])
    with pytest.raises(ValueError, match="Filtration"):
        morse_reduce(3.0)
    with pytest.raises(ValueError, match="joins different filtration values"):
        morse_reduce(filt, coefficients=2, pairs=[((0,), (0, 1))])  # a enters at 0, ab at 1
    with pytest.raises(ValueError, match="closed V-path"):
        lower = lower_star_filtration([(0, 1), (1, 2), (0, 2)], [0.0, 0.0, 0.0])
        morse_reduce(lower, coefficients=2, pairs=[((0,), (0, 1)), ((1,), (1, 2)), ((2,), (0, 2))])

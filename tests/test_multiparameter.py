"""Two-parameter persistence (thesis Chapter 5): the Hilbert function, the rank invariant and fibered
barcodes against brute force by GUDHI (the homology of every subcomplex) and against multipers."""

import gudhi
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import rips
from thesis_lib.multiparameter import (
    MAX_GRID_ENTRIES,
    Bifiltration,
    fibered_barcode,
    function_bifiltration,
    hilbert_function,
    line_filtration,
    radius_curvature_bifiltration,
    rank_invariant,
)


def _random_bifiltration(seed, n=14, complex="rips"):
    rng = np.random.default_rng(seed)
    pts = rng.normal(size=(n, 2))
    kappa = rng.normal(size=n)
    if complex == "rips":
        return radius_curvature_bifiltration(pts, kappa, complex="rips", max_radius=1.2, max_dim=2, absolute=False)
    return radius_curvature_bifiltration(pts, kappa, complex="alpha", absolute=True)


def _grid(bif, n_eps, n_kappa):
    lo, hi = bif.bounds()
    return np.linspace(lo[0], hi[0], n_eps), np.linspace(lo[1], hi[1], n_kappa)


def _gudhi_betti(bif, eps, kappa, dims):
    """dim H_k of K_{ε,κ} by GUDHI: the subcomplex as a simplex tree, its Betti numbers."""
    tree = gudhi.SimplexTree()
    for s, g in zip(bif.simplices, bif.grades):
        keep = (g[:, 0] <= eps) & (g[:, 1] <= kappa)
        if keep.any():
            tree.insert_batch(np.ascontiguousarray(s[keep].T), np.zeros(int(keep.sum())))
    if tree.num_vertices() == 0:
        return [0] * len(dims)
    tree.compute_persistence(persistence_dim_max=True)
    betti = tree.betti_numbers() + [0] * 4
    return [betti[d] for d in dims]


def _gudhi_rank(bif, a, b, dim):
    """rank H_dim(K_a) → H_dim(K_b) by GUDHI: the two-step filtration K_a (at 0) ⊆ K_b (at 1)."""
    tree = gudhi.SimplexTree()
    for s, g in zip(bif.simplices, bif.grades):
        in_b = (g[:, 0] <= b[0]) & (g[:, 1] <= b[1])
        in_a = (g[:, 0] <= a[0]) & (g[:, 1] <= a[1])
        if in_b.any():
            tree.insert_batch(np.ascontiguousarray(s[in_b].T), np.where(in_a[in_b], 0.0, 1.0))
    if tree.num_vertices() == 0:
        return 0
    tree.compute_persistence(persistence_dim_max=True)
    return sum(1 for b0, d0 in tree.persistence_intervals_in_dimension(dim) if b0 <= 0 and d0 > 1)


@settings(deadline=None, max_examples=6, derandomize=True)
@given(st.integers(0, 10**6), st.sampled_from(["rips", "alpha"]))
def test_hilbert_function_equals_brute_force(seed, complex):
    bif = _random_bifiltration(seed, complex=complex)
    eps, kappa = _grid(bif, 7, 6)
    dims = list(range(bif.max_homology_dim + 1))
    hf = hilbert_function(bif, eps, kappa)
    ref = np.array([[_gudhi_betti(bif, e, k, dims) for k in kappa] for e in eps]).transpose(2, 0, 1)
    assert hf.shape == (len(dims), len(eps), len(kappa))
    assert np.array_equal(hf, ref)


@settings(deadline=None, max_examples=3, derandomize=True)
@given(st.integers(0, 10**6))
def test_rank_invariant_equals_brute_force(seed):
    bif = _random_bifiltration(seed, n=12)
    eps, kappa = _grid(bif, 5, 4)
    for dim in (0, 1):
        rk = rank_invariant(bif, eps, kappa, dim=dim)
        for i, j, i2, j2 in np.ndindex(rk.shape):
            if i <= i2 and j <= j2:
                assert rk[i, j, i2, j2] == _gudhi_rank(bif, (eps[i], kappa[j]), (eps[i2], kappa[j2]), dim)
            else:
                assert rk[i, j, i2, j2] == 0
        # the diagonal is the Hilbert function
        assert np.array_equal(np.einsum("ijij->ij", rk), hilbert_function(bif, eps, kappa, dims=[dim])[0])


@settings(deadline=None, max_examples=5, derandomize=True)
@given(st.integers(0, 10**6), st.floats(0.2, 5.0), st.floats(-0.5, 0.5), st.floats(-2.0, 0.5))
def test_fibered_barcode_equals_gudhi_on_the_line(seed, slope, b_eps, b_kappa):
    bif = _random_bifiltration(seed)
    base, direction = np.array([b_eps, b_kappa]), np.array([1.0, slope])
    ours = fibered_barcode(bif, base, direction)
    tree = line_filtration(bif, base, direction).to_simplex_tree()
    tree.compute_persistence(persistence_dim_max=True)
    for d in range(bif.max_homology_dim + 1):
        ref = tree.persistence_intervals_in_dimension(d)
        ref = ref[ref[:, 1] > ref[:, 0]] if len(ref) else np.empty((0, 2))
        ref = ref[np.lexsort((ref[:, 1], ref[:, 0]))]
        assert np.allclose(ours.intervals(d), ref)


def test_rank_along_the_line_through_two_grid_points():
    """rk(a, b) = the bars of the fibered barcode of the line through a and b alive at both."""
    bif = _random_bifiltration(3)
    eps, kappa = _grid(bif, 6, 5)
    rk = rank_invariant(bif, eps, kappa, dim=1)
    for i, j, i2, j2 in [(1, 1, 4, 3), (0, 2, 5, 4), (2, 0, 3, 1)]:
        a, b = np.array([eps[i], kappa[j]]), np.array([eps[i2], kappa[j2]])
        bars = fibered_barcode(bif, a, b - a).intervals(1)  # a at t = 0, b at t = 1
        assert rk[i, j, i2, j2] == np.count_nonzero((bars[:, 0] <= 0) & (bars[:, 1] > 1))


def test_circle_with_a_curvature_spike():
    """A sampled circle whose points near angle 0 have a large κ: H₁ needs those points."""
    t = np.linspace(0, 2 * np.pi, 40, endpoint=False)
    pts = np.column_stack([np.cos(t), np.sin(t)])
    kappa = np.where(np.abs(np.angle(np.exp(1j * t))) < 0.3, 10.0, 1.0)
    bif = radius_curvature_bifiltration(pts, kappa, complex="rips", max_radius=1.5, max_dim=2)
    hf = hilbert_function(bif, [0.05, 0.1, 0.5, 1.2], [1.0, 10.0])
    assert hf[0, 0, 1] == 40  # below the sample spacing (0.157 = 2ε at ε = 0.079): points only
    assert hf[0, 1, 0] == 1 and hf[1, 1, 0] == 0  # without the three spiky points: an arc, no loop
    assert hf[1, 1, 1] == 1  # with them: the circle
    assert hf[1, 2, 0] == 1  # a larger ε bridges the gap they leave
    assert hf[1, 3, 1] == 0  # and a still larger one fills the loop


def test_function_bifiltration_grades_are_the_largest_vertex_value():
    K = rips(np.array([[0.0, 0], [1, 0], [0, 1]]), max_radius=2.0, max_dim=2)
    bif = function_bifiltration(K, [3.0, -1.0, 2.0])
    assert np.array_equal(bif.grades[0][:, 1], [3.0, -1.0, 2.0])
    assert np.array_equal(bif.grades[1][:, 1], [3.0, 3.0, 2.0])  # edges 01, 02, 12
    assert bif.grades[2][0, 1] == 3.0 and bif.grades[2][0, 0] == K.values[2][0]


def test_agrees_with_multipers():
    """Hilbert function, rank invariant and fibered barcodes equal multipers 2.3.2's.

    multipers is built here by inserting each simplex with its two grades (its copy of a GUDHI
    simplex tree crashes with GUDHI 3.13); for the grid invariants the grades are first rounded
    up to the grid, which is what an invariant on the grid sees.
    """
    mp = pytest.importorskip("multipers")
    from multipers.simplex_tree_multi import SimplexTreeMulti

    bif = _random_bifiltration(11, n=25)
    eps, kappa = _grid(bif, 8, 6)

    def tree(snap):
        t = SimplexTreeMulti(num_parameters=2)
        for s, g in zip(bif.simplices, bif.grades):
            if snap:
                ie, ik = np.searchsorted(eps, g[:, 0]), np.searchsorted(kappa, g[:, 1])
                keep = (ie < len(eps)) & (ik < len(kappa))
                s, g = s[keep], np.column_stack([eps[ie[keep]], kappa[ik[keep]]])
            t.insert_batch(np.ascontiguousarray(s.T), np.ascontiguousarray(g))
        return t

    snapped = tree(True)
    hf = hilbert_function(bif, eps, kappa)
    for d in range(bif.max_homology_dim + 1):
        locs, w = mp.signed_measure(snapped, degree=d, invariant="hilbert", n_jobs=1)[0]
        ref = np.zeros((len(eps), len(kappa)), dtype=np.int64)
        for x, y, m in zip(np.searchsorted(eps, locs[:, 0]), np.searchsorted(kappa, locs[:, 1]), w):
            ref[x:, y:] += int(m)
        assert np.array_equal(hf[d], ref)
    rk = rank_invariant(bif, eps, kappa, dim=1)
    locs, w = mp.signed_measure(snapped, degree=1, invariant="rank", n_jobs=1)[0]
    idx = [np.searchsorted(g, locs[:, c]) for c, g in enumerate((eps, kappa, eps, kappa))]
    for i, j, i2, j2 in np.ndindex(rk.shape):
        if i <= i2 and j <= j2:
            rect = (idx[0] <= i) & (idx[1] <= j) & (idx[2] > i2) & (idx[3] > j2)  # rectangles [s, t) ∋ a, b
            assert rk[i, j, i2, j2] == w[rect].sum()
    slicer = mp.Slicer(tree(False))
    for base, direction in [((0.0, -1.0), (1.0, 2.0)), ((-0.3, 0.2), (0.5, 1.0))]:
        theirs = slicer.persistence_on_line(np.array(base), np.array(direction))
        ours = fibered_barcode(bif, base, direction)
        for d in range(bif.max_homology_dim + 1):
            m = np.asarray(theirs[d]).reshape(-1, 2)
            m = m[m[:, 1] > m[:, 0]]
            assert np.allclose(ours.intervals(d), m[np.lexsort((m[:, 1], m[:, 0]))])


def test_bad_input():
    pts = np.random.default_rng(0).normal(size=(10, 2))
    kappa = np.ones(10)
    kappa[[3, 7]] = np.nan
    with pytest.raises(ValueError, match=r"NaN or infinite at 2 of 10 points \(rows \[3, 7\]\)"):
        radius_curvature_bifiltration(pts, kappa)
    with pytest.raises(ValueError, match="one value per point"):
        radius_curvature_bifiltration(pts, np.ones(9))
    with pytest.raises(ValueError, match="complex"):
        radius_curvature_bifiltration(pts, np.ones(10), complex="cech")
    bif = radius_curvature_bifiltration(pts, np.ones(10), max_radius=1.0, max_dim=2)
    big = np.linspace(0, 1, 200)
    with pytest.raises(ValueError, match=r"1,600,000,000 rank-invariant entries \(11.9 GiB\)"):
        rank_invariant(bif, big, big, dim=0)
    assert MAX_GRID_ENTRIES < 200**4
    with pytest.raises(ValueError, match="strictly increasing"):
        hilbert_function(bif, [0.1, 0.1], [1.0])
    with pytest.raises(ValueError, match="NaN"):
        hilbert_function(bif, [0.1, np.nan], [1.0])
    with pytest.raises(ValueError, match="H_2 is not determined"):
        hilbert_function(bif, [0.1], [1.0], dims=[2])
    with pytest.raises(ValueError, match="positive slope"):
        fibered_barcode(bif, (0, 0), (1.0, 0.0))
    with pytest.raises(ValueError, match="larger κ-grade"):
        Bifiltration([np.array([[0], [1]]), np.array([[0, 1]])],
                     [np.array([[0.0, 2.0], [0.0, 0.0]]), np.array([[1.0, 1.0]])])
    with pytest.raises(ValueError, match="NaN grade"):
        Bifiltration([np.array([[0]])], [np.array([[np.nan, 0.0]])])

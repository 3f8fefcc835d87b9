"""The implicit Rips engine: same barcodes as GUDHI, Ripser and the explicit engine (§2.3, §4.2)."""

from __future__ import annotations

import gudhi
import numpy as np
import pytest
import scipy.sparse as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from ripser import ripser

from thesis_lib.complexes import rips
from thesis_lib.datasets import two_circles
from thesis_lib.persistence import Barcode, persistence, rips_persistence


def gudhi_rips(points, eps: float, max_dim: int, p: int) -> Barcode:
    """GUDHI's barcode of the Rips complex (diameter ≤ 2ε), in ε, dimensions 0 .. max_dim − 1."""
    st_ = gudhi.RipsComplex(points=points, max_edge_length=2 * eps).create_simplex_tree(max_dimension=max_dim)
    st_.compute_persistence(homology_coeff_field=p, min_persistence=0, persistence_dim_max=True)
    intervals = {d: st_.persistence_intervals_in_dimension(d) / 2 for d in range(max_dim)}
    return Barcode(intervals, dimensions=range(max_dim))


def ripser_rips(points=None, eps=np.inf, max_dim=2, p=2, **kw) -> Barcode:
    dg = ripser(points if points is not None else kw.pop("dm"), maxdim=max_dim - 1, thresh=2 * eps, coeff=p, **kw)
    intervals = {d: np.asarray(dg["dgms"][d], dtype=np.float64) / 2 for d in range(max_dim)}
    return Barcode(intervals, dimensions=range(max_dim))


@settings(deadline=None, max_examples=25)
@given(seed=st.integers(0, 10**6), n=st.integers(3, 28), dim=st.integers(1, 3),
       eps=st.sampled_from([0.15, 0.3, 0.6, np.inf]), max_dim=st.integers(1, 3), p=st.sampled_from([2, 3, 5]))
def test_random_points_agree_with_gudhi_and_the_explicit_engine(seed, n, dim, eps, max_dim, p):
    pts = np.random.default_rng(seed).random((n, dim))
    ours = rips_persistence(pts, max_radius=eps, max_dim=max_dim, coefficients=p)
    assert ours.dimensions == tuple(range(max_dim)) == ours.complete_dimensions
    assert ours.allclose(gudhi_rips(pts, eps, max_dim, p), atol=1e-12)
    f = rips(pts, max_radius=eps, max_dim=max_dim)
    explicit = persistence(f, coefficients=p)
    for d in range(max_dim):
        assert np.array_equal(ours.intervals(d), explicit.intervals(d)), d


@settings(deadline=None, max_examples=15)
@given(seed=st.integers(0, 10**6), n=st.integers(10, 60), p=st.sampled_from([2, 3]))
def test_random_points_agree_with_ripser(seed, n, p):
    pts = np.random.default_rng(seed).normal(size=(n, 2))
    ours = rips_persistence(pts, max_dim=3, coefficients=p)
    assert ours.allclose(ripser_rips(pts, np.inf, 3, p), atol=1e-5)  # ripser works in float32


def test_ties_and_duplicates_on_a_grid():
    """Integer grids have many equal distances (apparent pairs decided by the tie-break) and a
    repeated point (an edge of length 0)."""
    g = np.array([(i, j) for i in range(5) for j in range(5)] + [(2, 2)], dtype=float)
    for p in (2, 3):
        ours = rips_persistence(g, max_radius=1.5, max_dim=3, coefficients=p)
        assert ours.allclose(gudhi_rips(g, 1.5, 3, p), atol=1e-12)


def test_two_circles_three_long_bars():
    pts = two_circles(60, seed=0)
    stats = {}
    b = rips_persistence(pts, max_radius=2.0, max_dim=2, stats=stats)
    assert b == Barcode.from_diagrams(persistence(rips(pts, max_radius=2.0, max_dim=2)).to_diagrams()[:2])
    lengths = b.intervals(1)[:, 1] - b.intervals(1)[:, 0]
    assert lengths.shape == (3,) and lengths.min() > 0.3  # the three holes of Figure 2.14
    # almost every positive edge is in a zero apparent pair: the reduction sees a handful of columns
    assert stats[1]["apparent"] + stats[1]["columns"] == stats[1]["simplices"]
    assert stats[1]["columns"] < 0.01 * stats[1]["simplices"]


def test_distance_matrix_dense_and_sparse_coo():
    rng = np.random.default_rng(7)
    pts = rng.random((25, 3))
    dm = np.sqrt(((pts[:, None] - pts[None]) ** 2).sum(-1))
    ref = rips_persistence(pts, max_radius=0.35, max_dim=3, coefficients=3)
    assert rips_persistence(distance_matrix=dm, max_radius=0.35, max_dim=3, coefficients=3) == ref
    # a sparse matrix: only the stored entries are edges (those above 2ε would be dropped anyway)
    i, j = np.nonzero(np.triu(dm <= 0.7, 1))
    coo = sp.coo_matrix((dm[i, j], (i, j)), shape=dm.shape)
    assert rips_persistence(distance_matrix=coo, max_radius=0.35, max_dim=3, coefficients=3) == ref
    assert rips_persistence(distance_matrix=coo.T.tocsr(), max_radius=0.35, max_dim=3, coefficients=3) == ref
    # a graph that is not a metric: edges missing inside cliques, compared with ripser's sparse mode
    keep = rng.random(i.shape[0]) < 0.7
    graph = sp.coo_matrix((dm[i, j][keep], (i[keep], j[keep])), shape=dm.shape)
    ours = rips_persistence(distance_matrix=graph, max_radius=0.35, max_dim=3)
    theirs = ripser(graph.tocsr(), distance_matrix=True, maxdim=2, thresh=0.7)["dgms"]
    assert ours.allclose(Barcode.from_diagrams([np.asarray(d, float) / 2 for d in theirs]), atol=1e-6)


def test_bad_input():
    pts = np.random.default_rng(0).random((6, 2))
    with pytest.raises(ValueError, match="max_dim must be >= 1"):
        rips_persistence(pts, max_dim=0)
    with pytest.raises(ValueError, match="exactly one"):
        rips_persistence(pts, distance_matrix=np.zeros((6, 6)))
    with pytest.raises(ValueError, match="exactly one"):
        rips_persistence()
    with pytest.raises(ValueError, match="prime"):
        rips_persistence(pts, coefficients=4)
    with pytest.raises(ValueError, match="coefficients"):
        rips_persistence(pts, coefficients=0)
    with pytest.raises(ValueError, match="NaN"):
        rips_persistence(np.array([[0.0, np.nan], [1, 1]]))
    with pytest.raises(ValueError, match="max_radius"):
        rips_persistence(pts, max_radius=-1)
    with pytest.raises(ValueError, match="negative"):
        rips_persistence(distance_matrix=sp.coo_matrix(([-1.0], ([0], [1])), shape=(2, 2)))
    with pytest.raises(ValueError, match="square"):
        rips_persistence(distance_matrix=sp.coo_matrix((2, 3)))
    with pytest.raises(ValueError, match="symmetric"):
        rips_persistence(distance_matrix=sp.coo_matrix(([1.0, 2.0], ([0, 1], [1, 0])), shape=(2, 2)))
    with pytest.raises(ValueError, match="overflow"):
        rips_persistence(distance_matrix=sp.coo_matrix((10**6, 10**6)), max_dim=5)

"""The Crust algorithm [ABK98] and ball pivoting on sampled surfaces."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.curvature import mean_curvature
from thesis_lib.meshes import (
    euler_characteristic,
    facet_degrees,
    sample_catenoid,
    sample_sphere,
    sample_torus,
    torus_grid,
)
from thesis_lib.reconstruction import ball_pivoting, crust, crust_candidates, estimate_normals, extract_manifold, poles
from thesis_lib.surfaces import torus_uv


def _coherent(f):
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    # every directed edge once, and its reverse present
    s = {tuple(x) for x in e.tolist()}
    return len(s) == len(e) and all((b, a) in s for a, b in s)


def _torus_normals(pts, R=10.0, r=5.0):
    u, v = torus_uv(pts, R=R, r=r)
    return np.column_stack([np.cos(u) * np.cos(v), np.sin(u) * np.cos(v), np.sin(v)])


@pytest.fixture(scope="module")
def torus3000():
    pts = sample_torus(3000, R=10.0, r=5.0, seed=11)
    return pts, crust(pts)


def test_crust_closes_the_torus(torus3000):
    pts, f = torus3000
    assert np.all(facet_degrees(f) == 2)  # every edge in exactly two faces
    assert euler_characteristic(f) == 0  # genus one
    assert len(np.unique(f)) == len(pts)  # every sample used
    assert len(f) == 2 * len(pts)  # V - E + F = 0 with 3F = 2E
    assert _coherent(f)
    p = pts[f]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    exact = _torus_normals(p.mean(axis=1))
    cos = np.einsum("ij,ij->i", nrm, exact)
    assert np.all(cos > 0)  # oriented outward
    assert np.median(cos) > 0.98


def test_crust_mesh_feeds_curvature(torus3000):
    pts, f = torus3000
    H = mean_curvature(pts, f, area="mixed")
    assert np.all(np.isfinite(H))
    assert 0.05 < np.median(H) < 0.2  # |H| of the torus lies in [0, 0.1333]


def test_poles_lie_along_normals():
    pts = sample_torus(2000, R=10.0, r=5.0, seed=5)
    pp, pm = poles(pts)
    nrm = _torus_normals(pts)
    for q in (pp, pm):
        d = q - pts
        cos = np.abs(np.einsum("ij,ij->i", d, nrm)) / np.linalg.norm(d, axis=1)
        assert np.median(cos) > 0.95
    # one of the two poles lies inside the tube, near the core circle (the inner medial axis)
    inner = np.where(np.einsum("ij,ij->i", pp - pts, nrm)[:, None] < 0, pp, pm)
    core = np.hypot(np.hypot(inner[:, 0], inner[:, 1]) - 10, inner[:, 2])
    assert np.median(core) < 1.0


def _candidates_by_definition(pts, theta=np.pi / 4):
    """Steps 3-4 as ABK98 state them: Qhull's Delaunay of S ∪ P, triangles with sample vertices."""
    from scipy.spatial import Delaunay

    from thesis_lib.reconstruction.crust_geometry import _normal_filter

    pp, pm = poles(pts)
    n = len(pts)
    tets = Delaunay(np.vstack([pts, np.unique(np.vstack([pp, pm]), axis=0)])).simplices
    tri = np.concatenate([np.delete(tets, k, axis=1) for k in range(4)])
    tri = np.unique(np.sort(tri[(tri < n).all(axis=1)], axis=1), axis=0)
    return tri[_normal_filter(pts, tri, pp, theta)]


@pytest.mark.parametrize(
    "pts",
    [
        sample_torus(1500, R=10.0, r=5.0, seed=3),
        sample_torus(400, R=10.0, r=5.0, seed=4),
        sample_sphere(800, n_dims=3, radius=2.0, seed=6),
        sample_catenoid(1200, seed=7),  # open surface: convex-hull faces with Voronoi rays
    ],
    ids=["torus1500", "torus400", "sphere", "catenoid"],
)
def test_voronoi_filter_equals_delaunay_of_samples_and_poles(pts):
    ours = crust_candidates(pts)
    ref = _candidates_by_definition(pts)
    assert len(ref) > len(pts)
    assert np.array_equal(ours, ref)


def test_crust_on_sphere():
    pts = sample_sphere(1500, n_dims=3, radius=2.0, seed=2)
    f = crust(pts)
    assert np.all(facet_degrees(f) == 2) and euler_characteristic(f) == 2
    p = pts[f]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert np.all(np.einsum("ij,ij->i", nrm, p.mean(axis=1)) > 0)


@settings(deadline=None, max_examples=4, derandomize=True)
@given(st.integers(0, 10**6))
def test_crust_torus_random_seeds(seed):
    pts = sample_torus(2000, R=10.0, r=5.0, seed=seed)
    f = crust(pts)
    deg = facet_degrees(f)
    assert deg.max() <= 2  # always a pseudo-manifold with boundary at worst
    assert np.all(deg == 2) and euler_characteristic(f) == 0


@pytest.mark.parametrize("n", [50, 60])
def test_crust_of_chosen_points_is_closed(n):
    """The thesis's chosen points (§3.4.1): every grid quad is an isosceles trapezoid, four
    co-circular samples, which Qhull separates by a flat tetrahedron.  The Crust must still pick
    one diagonal per quad and leave no boundary."""
    from scipy.spatial import Delaunay

    from thesis_lib.reconstruction.crust_geometry import circumcentres

    vertices, grid_faces = torus_grid(n, R=10.0, r=5.0)
    flat = ~circumcentres(vertices[Delaunay(vertices).simplices])[1]
    assert flat.sum() > n  # the degenerate configuration really occurs
    f = crust(vertices)
    assert np.all(facet_degrees(f) == 2) and euler_characteristic(f) == 0
    assert len(f) == 2 * n * n and len(np.unique(f)) == n * n
    assert _coherent(f)
    # every face is half of a grid quad: its vertices span two consecutive u and two consecutive v
    i, j = np.divmod(f, n)
    for idx in (i, j):
        spread = (np.sort(idx, axis=1)[:, [1, 2]] - np.sort(idx, axis=1)[:, [0, 0]]) % n
        assert np.all((spread <= 1) | (spread == n - 1))
    quads = {tuple(sorted({(a // n, a % n) for a in face})) for face in f.tolist()}
    assert len(quads) == 2 * n * n  # no face repeated
    # outward (the grid's faces are oriented by X_u × X_v)
    p = vertices[f]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert np.all(np.einsum("ij,ij->i", nrm, p.mean(axis=1) - _torus_core(p.mean(axis=1))) > 0)
    # the cotangent formula is blind to the diagonal of a co-circular quad (cot α + cot β = 0 on it),
    # so Voronoi-area curvature on the Crust equals that on the fixed-diagonal grid
    h_crust = mean_curvature(vertices, f, area="voronoi")
    h_grid = mean_curvature(vertices, grid_faces, area="voronoi")
    assert np.allclose(h_crust, h_grid, rtol=1e-9, atol=1e-12)  # H = 0 on the inner equator
    # the barycentric area is not: it counts the faces at a vertex, which the diagonals change
    b_crust = mean_curvature(vertices, f, area="barycentric")
    b_grid = mean_curvature(vertices, grid_faces, area="barycentric")
    assert np.max(np.abs(b_crust / b_grid - 1)) > 0.1


def _torus_core(x, R=10.0):
    rho = np.hypot(x[:, 0], x[:, 1])
    return np.column_stack([R * x[:, 0] / rho, R * x[:, 1] / rho, np.zeros(len(x))])


def test_sparse_sample_falls_back_to_untrimmed_walk():
    pts = sample_torus(100, R=10.0, r=5.0, seed=1)
    f = crust(pts)
    assert len(f) > 0 and facet_degrees(f).max() <= 2
    with pytest.raises(ValueError, match="too sparse"):
        extract_manifold(pts, crust_candidates(pts))


def test_ball_pivoting_reference():
    pts = sample_sphere(1000, n_dims=3, radius=1.0, seed=0)
    n = estimate_normals(pts)
    assert np.all(np.einsum("ij,ij->i", n, pts) > 0.9)
    f = ball_pivoting(pts, n)
    assert f.shape[1] == 3 and f.min() >= 0 and f.max() < len(pts)
    p = pts[f]
    assert np.allclose(np.linalg.norm(p, axis=2), 1.0)
    assert len(f) > 1700 and facet_degrees(f).max() <= 2


def test_bad_input():
    with pytest.raises(ValueError, match=r"^points must lie in R\^3 \(an \(n, 3\) array\), got shape \(20, 2\)$"):
        crust(np.random.default_rng(0).normal(size=(20, 2)))
    with pytest.raises(ValueError, match="duplicate"):
        crust(np.vstack([np.eye(3), np.eye(3), [[1, 1, 1]]]))
    with pytest.raises(ValueError, match="NaN"):
        crust(np.array([[np.nan, 0, 0]] + [[i, i * i, 1.0] for i in range(6)]))
    with pytest.raises(ValueError, match="theta"):
        crust_candidates(sample_sphere(50, n_dims=3), theta=2.0)
    with pytest.raises(ValueError, match="far"):
        crust(sample_sphere(50, n_dims=3), far=-1.0)
    with pytest.raises(ValueError, match="triangles"):
        extract_manifold(np.eye(3), np.zeros((0, 3), dtype=int))
    with pytest.raises(ValueError, match=r"^normals must have shape \(50, 3\), got \(3, 3\)$"):
        ball_pivoting(sample_sphere(50, n_dims=3), normals=np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"^normals contains NaN or infinite values$"):
        ball_pivoting(sample_sphere(50, n_dims=3), normals=np.full((50, 3), np.nan))
    with pytest.raises(ValueError, match=r"^points must lie in R\^3 \(an \(n, 3\) array\), got shape \(50, 2\)$"):
        ball_pivoting(sample_sphere(50, n_dims=2))
    with pytest.raises(ValueError, match=r"^points must lie in R\^3 \(an \(n, 3\) array\), got shape \(50, 4\)$"):
        estimate_normals(sample_sphere(50, n_dims=4))
    with pytest.raises(ValueError, match="radii"):
        ball_pivoting(sample_sphere(50, n_dims=3), radii=[-1.0])


def test_reconstruct_surface_dispatch():
    from thesis_lib.reconstruction import reconstruct_surface

    pts = sample_torus(1500, R=10.0, r=5.0, seed=3)
    assert np.array_equal(reconstruct_surface(pts, algorithm="crust"), crust(pts))
    open_cat = sample_catenoid(800, seed=2)
    assert np.array_equal(reconstruct_surface(open_cat, algorithm="crust", closed=False), crust(open_cat, prune=False))
    f = reconstruct_surface(pts, algorithm="ball-pivoting")
    assert f.shape[1] == 3 and facet_degrees(f).max() <= 2
    with pytest.raises(ValueError, match="unknown reconstruction"):
        reconstruct_surface(pts, algorithm="poisson")

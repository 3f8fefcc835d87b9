"""The Crust for hypersurfaces of R^{n+1} (thesis Chapter 5): equal to the 3-D Crust for n = 2, a
closed 3-manifold on the 3-sphere, manifold checks, curvature on the result, bad input."""

import numpy as np
import pytest
from scipy.spatial import Delaunay

from thesis_lib.curvature import mean_curvature
from thesis_lib.homology import homology
from thesis_lib.meshes import sample_sphere, sample_torus
from thesis_lib.meshes.sampling import sample_n_catenoid
from thesis_lib.reconstruction import crust
from thesis_lib.reconstruction.crust_geometry import _normal_filter, circumcentres, poles_from_delaunay
from thesis_lib.reconstruction.crust_nd import (
    ReconstructionError,
    _delaunay,
    _far,
    crust_nd,
    crust_nd_candidates,
    manifold_report,
    manifold_vertices,
)


def _oriented_set(simplices):
    """Oriented simplices as a set of canonical rows: the sorted row, and the parity of the sort."""
    s = np.asarray(simplices)
    order = np.argsort(s, axis=1)
    inv = np.zeros(len(s), dtype=int)
    for i in range(s.shape[1]):
        for j in range(i + 1, s.shape[1]):
            inv += order[:, i] > order[:, j]
    return {(tuple(r), int(p)) for r, p in zip(np.sort(s, axis=1).tolist(), inv % 2)}


def _s1_times_s2(n, R=2.0, r=1.0, seed=0):
    """Uniform samples of S¹ × S² = {(ρ cos u, ρ sin u, r g₁, r g₂): ρ = R + r g₀, g ∈ S²} ⊂ R⁴."""
    rng = np.random.default_rng(seed)
    out = []
    while sum(map(len, out)) < n:
        u = rng.uniform(0, 2 * np.pi, 4 * n)
        g = rng.normal(size=(4 * n, 3))
        g /= np.linalg.norm(g, axis=1, keepdims=True)
        rho = R + r * g[:, 0]
        keep = rng.uniform(0, R + r, 4 * n) < rho  # volume element ρ du dA(S²)
        out.append(np.column_stack([rho * np.cos(u), rho * np.sin(u), r * g[:, 1], r * g[:, 2]])[keep])
    return np.concatenate(out)[:n]


@pytest.fixture(scope="module")
def sphere3():
    pts = sample_sphere(400, n_dims=4, radius=2.0, seed=3)
    return pts, crust_nd(pts)


@pytest.mark.parametrize("seed", [0, 5])
def test_n2_equals_the_3d_crust(seed):
    pts = sample_torus(1500, R=10.0, r=5.0, seed=seed)
    ours = crust_nd(pts)
    ref = crust(pts)
    assert ours.report.is_closed_manifold
    assert _oriented_set(ours.simplices) == _oriented_set(ref)  # same triangles, same orientation


def test_n2_candidates_equal_the_3d_crust():
    from thesis_lib.reconstruction import crust_candidates

    pts = sample_torus(800, R=10.0, r=5.0, seed=9)
    assert np.array_equal(crust_nd_candidates(pts), crust_candidates(pts))


def test_three_sphere_is_a_closed_3_manifold(sphere3):
    pts, res = sphere3
    rep = res.report
    assert rep.n == 3 and rep.is_closed_manifold
    assert rep.boundary_ridges == 0 and rep.singular_ridges == 0
    assert rep.bad_ridge_links == 0 and rep.bad_vertex_links == 0 and rep.orientation_conflicts == 0
    assert rep.vertex_fraction == 1.0 and rep.euler_characteristic == 0
    s = res.simplices
    # every triangle in exactly two tetrahedra
    tri = np.concatenate([np.sort(np.delete(s, k, axis=1), axis=1) for k in range(4)])
    _, counts = np.unique(tri, axis=0, return_counts=True)
    assert np.all(counts == 2)
    # homology of S³ over Z: Z, 0, 0, Z
    h = homology([tuple(r) for r in np.sort(s, axis=1).tolist()])
    assert [b for b, _ in h] == [1, 0, 0, 1] and all(not t for _, t in h)
    # outward: det[edges; position] > 0 for the cofactor normal (det[E; N] = -|N|² for n = 3)
    p = pts[s]
    mat = np.concatenate([p[:, 1:] - p[:, :1], p.mean(axis=1)[:, None]], axis=1)
    assert np.all(np.linalg.det(mat) < 0) or np.all(np.linalg.det(mat) > 0)


def test_three_sphere_is_the_convex_hull(sphere3):
    from scipy.spatial import ConvexHull

    pts, res = sphere3
    hull = {tuple(r) for r in np.sort(ConvexHull(pts).simplices, axis=1).tolist()}
    assert {tuple(r) for r in np.sort(res.simplices, axis=1).tolist()} == hull


def test_mean_curvature_of_the_reconstructed_three_sphere(sphere3):
    pts, res = sphere3
    H = mean_curvature(pts, res.simplices, area="voronoi")
    err = np.abs(H - 0.5) / 0.5  # Theorem 3.18, |H| = 1/2 on S³(2)
    assert np.all(np.isfinite(H))
    assert np.median(err) < 0.1


def test_s1_times_s2_is_a_closed_3_manifold():
    pts = _s1_times_s2(5000, seed=0)
    res = crust_nd(pts)
    assert res.report.is_closed_manifold and res.report.euler_characteristic == 0
    assert res.report.vertex_fraction == 1.0


def test_voronoi_filter_equals_qhull_in_r4():
    """The 1-D linear-program Voronoi filter equals Qhull's Delaunay of S ∪ P in R⁴."""
    small = _s1_times_s2(300, seed=2)
    pp, pm = _poles_nd(small)
    ours = crust_nd_candidates(small)
    n = len(small)
    tets = Delaunay(np.vstack([small, np.unique(np.vstack([pp, pm]), axis=0)]), qhull_options="QJ").simplices
    faces = np.concatenate([np.delete(tets, k, axis=1) for k in range(5)])
    faces = np.unique(np.sort(faces[(faces < n).all(axis=1)], axis=1), axis=0)
    faces = faces[_normal_filter(small, faces, pp, np.pi / 4)]
    assert len(ours) > len(small)
    assert np.array_equal(ours, faces)


def _poles_nd(pts):
    tri = _delaunay(pts)
    cc, ok = circumcentres(pts[tri.simplices])
    return poles_from_delaunay(pts, tri, cc, ok, _far(pts, None))


def test_curve_in_the_plane():
    t = np.random.default_rng(0).uniform(0, 2 * np.pi, 200)
    pts = np.column_stack([2 * np.cos(t), np.sin(t)])  # an ellipse
    res = crust_nd(pts)
    assert res.report.n == 1 and res.report.is_closed_manifold
    assert len(res.simplices) == 200 and res.report.euler_characteristic == 0


def test_open_three_catenoid_has_clean_interior_stars():
    pts, prm = sample_n_catenoid(3000, seed=0, return_params=True)
    res = crust_nd(pts, closed=False)
    good = manifold_vertices(res.simplices, n_points=len(pts))
    assert good.sum() > 0.25 * len(pts)
    H = mean_curvature(pts, res.simplices, area="voronoi")
    assert np.all(np.isfinite(H[good]))
    # H = 0 exactly; the estimate stays below the principal curvature 1/cosh² v at most points
    assert np.median(H[good] * np.cosh(prm[good, 1]) ** 2) < 0.5


def test_manifold_report_finds_defects():
    # the boundary of a 4-simplex: a closed 3-manifold (S³)
    sphere = np.array([[j for j in range(5) if j != i] for i in range(5)])
    for i in range(1, 5, 2):  # coherent orientation: alternate the sign of each facet
        sphere[i, [0, 1]] = sphere[i, [1, 0]]
    rep = manifold_report(sphere)
    assert rep.is_closed_manifold and rep.euler_characteristic == 0
    # flip one facet: orientation conflicts on its four triangles
    bad = sphere.copy()
    bad[0, [0, 1]] = bad[0, [1, 0]]
    assert manifold_report(bad).orientation_conflicts == 4
    # drop a facet: four boundary triangles, one hole
    rep = manifold_report(sphere[1:])
    assert rep.boundary_ridges == 4 and rep.boundary_components == 1 and not rep.is_closed_manifold
    assert rep.is_manifold  # a 3-ball
    # two spheres sharing one vertex: that vertex's link is two 2-spheres
    other = np.where(sphere == 0, 0, sphere + 4)
    rep = manifold_report(np.vstack([sphere, other]))
    assert rep.bad_vertex_links == 1 and not rep.is_manifold
    assert not manifold_vertices(np.vstack([sphere, other]))[0]
    # three tetrahedra on one triangle
    fan = np.array([[0, 1, 2, 3], [0, 1, 2, 4], [0, 1, 2, 5]])
    assert manifold_report(fan).singular_ridges == 1


def test_bad_input():
    rng = np.random.default_rng(0)
    with pytest.raises(ValueError, match=r"R\^5.*n\^⌈d/2⌉"):
        crust_nd(rng.normal(size=(1000, 5)))
    with pytest.raises(ValueError, match="too few samples"):
        crust_nd(sample_sphere(6, n_dims=4))
    with pytest.raises(ValueError, match="affine subspace"):
        crust_nd(np.column_stack([sample_sphere(100, n_dims=3), np.zeros(100)]))
    with pytest.raises(ValueError, match="theta"):
        crust_nd(sample_sphere(100, n_dims=4), theta=0.0)
    with pytest.raises(TypeError, match="^theta must be a number, got '0.5'$"):  # not read as float('0.5')
        crust_nd(sample_sphere(100, n_dims=4), theta="0.5")
    with pytest.raises(ValueError, match="duplicate"):
        crust_nd(np.vstack([sample_sphere(50, n_dims=4), sample_sphere(50, n_dims=4)[:1]]))
    with pytest.raises(ValueError, match="R\\^d with d >= 2"):
        crust_nd(rng.normal(size=(50, 1)))
    # points filling a 4-D ball are no hypersurface: refused with what failed
    ball = rng.normal(size=(800, 4)) * rng.uniform(0, 1, (800, 1)) ** 0.25
    with pytest.raises(ReconstructionError, match="fill a volume") as err:
        crust_nd(ball)
    assert err.value.pole_ratio < 2.5
    with pytest.raises(ValueError, match="simplices"):
        manifold_report(np.zeros((3,)))

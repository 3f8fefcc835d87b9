"""Near-degenerate geometry: alpha, weighted alpha and Delaunay equal GUDHI's exact construction on
jittered grids, co-circular / co-spherical sets and thin simplices, in 2-D and 3-D.

GUDHI (CGAL with exact predicates and symbolic perturbation) is the reference: same simplices,
values to 1e-12 relative.  Each hard case has its own test.
"""

import itertools

import gudhi
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import alpha, cech, delaunay, regular_triangulation, rips

RTOL = 1e-12


def gudhi_alpha(points, weights=None):
    tree = gudhi.AlphaComplex(points=points, weights=weights, precision="exact").create_simplex_tree()
    return {tuple(s): v for s, v in tree.get_simplices()}  # (the tree must outlive the iteration)


def gudhi_delaunay(points):
    tree = gudhi.DelaunayComplex(points=points).create_simplex_tree()
    return {tuple(s) for s, _ in tree.get_simplices()}


def assert_alpha_equals_gudhi(points, weights=None):
    points = np.asarray(points, dtype=np.float64)
    ours = dict(alpha(points, weights))
    ref = gudhi_alpha(points, weights)
    assert set(ours) == set(ref), f"simplices differ: {sorted(set(ours) ^ set(ref))[:6]}"
    got = np.array([ours[s] for s in ref])
    exp = np.array([ref[s] for s in ref])
    np.testing.assert_allclose(got, exp, rtol=RTOL, atol=1e-300)


def assert_delaunay_matches_gudhi(points):
    """Our triangulation is GUDHI's; our nerve contains it, and equals it unless d + 2 points lie
    exactly on one empty sphere (then the nerve holds the whole cell, GUDHI a triangulation of it)."""
    ref = gudhi_delaunay(points)
    dim = points.shape[1]
    tri, _ = regular_triangulation(points)
    assert {tuple(r) for r in tri.tolist()} == {s for s in ref if len(s) == dim + 1}
    ours = set(delaunay(points))
    assert ref <= ours
    if max(len(s) for s in ours) == dim + 1:
        assert ours == ref


def grid(side: int, dim: int) -> np.ndarray:
    return np.array(list(itertools.product(range(side), repeat=dim)), dtype=np.float64)


def lattice_sphere(radius: int, dim: int) -> np.ndarray:
    """All integer points at distance ``radius`` from the origin: exactly co-spherical."""
    r = range(-radius, radius + 1)
    return np.array([p for p in itertools.product(r, repeat=dim) if sum(x * x for x in p) == radius**2], float)


# ----------------------------------------------------------------------------- hard cases
def test_nearly_collinear_quadrilateral():
    # a point 1e-9 off the line through two others: a nearly singular circumcentre system
    pts = np.array([[0, 0], [0, -1], [1, 1e-9], [-1, 0]], float)
    assert_alpha_equals_gudhi(pts)


@pytest.mark.parametrize("seed", range(3))
def test_noisy_grids(seed):
    # 6 x 6 at noise 1e-9 and 4 x 4 x 4 at 1e-7: nearly co-circular (co-spherical) cells everywhere
    rng = np.random.default_rng(seed)
    for side, dim, noise in [(6, 2, 1e-9), (4, 3, 1e-7)]:
        pts = grid(side, dim) + rng.normal(scale=noise, size=(side**dim, dim))
        assert_alpha_equals_gudhi(pts)
        assert_alpha_equals_gudhi(pts, rng.random(len(pts)) * 0.1)


@pytest.mark.parametrize("height", [1e-5, 1e-7, 1e-9, 1e-12])
def test_thin_simplices_values(height):
    # thin simplices down to height 1e-12: nearly singular circumcentre systems, values still to 1e-12
    assert_alpha_equals_gudhi([[0, 0], [1, 0], [0.5, height], [0.3, 2.0]])
    assert_alpha_equals_gudhi([[0, 0, 0], [1, 0, 0], [0.5, height, 0], [0.2, 0.3, 1.0]])
    assert_alpha_equals_gudhi([[0, 0, 0], [1, 0, 0], [0.5, height, 0], [0.5, 0, height], [0.3, 0.3, 1]])


def test_delaunay_keeps_thin_triangle():
    # a point 5e-14 above an edge: the thin triangle (0, 1, 2) is kept
    pts = np.array([[0, 0], [1, 0], [0.5, 5e-14], [0.5, 1]], float)
    assert set(delaunay(pts)) == gudhi_delaunay(pts)
    assert (0, 1, 2) in delaunay(pts)
    three = np.array([[0, 0], [1, 0], [0.5, 5e-14]])
    assert set(delaunay(three)) == gudhi_delaunay(three)


@pytest.mark.parametrize("scale", [1e160, 1e-170])
def test_huge_and_tiny_coordinates(scale):
    base = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.1]])
    # the Delaunay complex does not depend on the scale
    assert delaunay(base * scale) == delaunay(base)
    # Rips and Čech values scale by s: computed correctly
    for build in (rips, cech):
        got = build(base * scale, max_radius=np.inf, max_dim=2)
        ref = build(base, max_radius=np.inf, max_dim=2)
        for (s1, v1), (s2, v2) in zip(got, ref):
            assert s1 == s2 and v1 == pytest.approx(v2 * scale, rel=1e-14)
    # alpha values scale by s²: 1e320 and 1e-340 do not fit in float64, so alpha refuses clearly
    with pytest.raises(ValueError, match="squared radii"):
        alpha(base * scale)
    # moderately large and small scales are exact (the scaling is by powers of two)
    for s in (2.0**500, 2.0**-500):
        got, ref = dict(alpha(base * s)), dict(alpha(base))
        assert all(got[k] == ref[k] * s * s for k in ref)


def test_dimension_50_refused_up_front():
    pts = np.random.default_rng(0).random((60, 50))
    with pytest.raises(ValueError, match=r"this would build [\d,]+ simplices"):
        alpha(pts)
    with pytest.raises(ValueError, match=r"this would build [\d,]+ simplices"):
        delaunay(pts)


# ----------------------------------------------------------------------------- property tests
noise_levels = st.sampled_from([0.0, 1e-15, 1e-13, 1e-11, 1e-9, 1e-7])


@settings(deadline=None, max_examples=12)
@given(st.integers(0, 2**32 - 1), st.sampled_from([(2, 3), (2, 5), (2, 7), (3, 3), (3, 4)]), noise_levels,
       st.sampled_from(["none", "random", "dyadic"]))
def test_jittered_grids_equal_gudhi(seed, shape, noise, weights):
    dim, side = shape
    rng = np.random.default_rng(seed)
    pts = grid(side, dim)
    if noise:
        pts = pts + rng.normal(scale=noise, size=pts.shape)
    w = None
    if weights == "random":
        w = rng.random(len(pts)) * 0.2
    elif weights == "dyadic":  # exact ties between weighted points
        w = rng.integers(0, 4, len(pts)) / 8.0
    assert_alpha_equals_gudhi(pts, w)
    if w is None:
        assert_delaunay_matches_gudhi(pts)


@settings(deadline=None, max_examples=10)
@given(st.integers(0, 2**32 - 1), st.sampled_from([(2, 65), (2, 25), (3, 3), (3, 5)]), st.integers(6, 40),
       st.booleans())
def test_cospherical_sets_equal_gudhi(seed, shape, count, with_centre):
    dim, radius = shape
    rng = np.random.default_rng(seed)
    ring = lattice_sphere(radius, dim)
    pts = ring[rng.permutation(len(ring))[: min(count, len(ring))]]
    if with_centre:
        pts = np.vstack([pts, np.zeros(dim)])
    if np.linalg.matrix_rank(pts - pts[0]) < dim:
        return
    assert_alpha_equals_gudhi(pts)
    # the triangulation of the exactly co-spherical points is the perturbed one GUDHI builds
    tri, _ = regular_triangulation(pts)
    tops = {tuple(s) for s in gudhi_delaunay(pts) if len(s) == dim + 1}
    assert {tuple(r) for r in tri.tolist()} == tops
    # the nerve holds whole co-spherical cells, so it contains GUDHI's triangulation
    if len(pts) <= 16:
        assert gudhi_delaunay(pts) <= set(delaunay(pts))


@settings(deadline=None, max_examples=12)
@given(st.integers(0, 2**32 - 1), st.sampled_from([2, 3]), st.integers(6, 30),
       st.sampled_from([1e-6, 1e-9, 1e-12, 1e-15]), st.booleans())
def test_thin_simplices_equal_gudhi(seed, dim, n, height, weighted):
    rng = np.random.default_rng(seed)
    pts = rng.random((n, dim))
    # a thin simplex: the last point a tiny distance off the facet spanned by the first dim points
    bary = rng.dirichlet(np.ones(dim))
    pts[dim] = bary @ pts[:dim] + height * rng.normal(size=dim)
    w = rng.random(n) * 0.01 if weighted else None
    assert_alpha_equals_gudhi(pts, w)
    if not weighted:
        assert_delaunay_matches_gudhi(pts)


@settings(deadline=None, max_examples=8)
@given(st.integers(0, 2**32 - 1), st.integers(2, 20), st.booleans())
def test_points_on_a_line_equal_gudhi(seed, n, weighted):
    # R^1: the regular triangulation is a lower hull in the plane, decided exactly (ties on integers)
    rng = np.random.default_rng(seed)
    pts = rng.permutation(np.arange(n, dtype=float) * 0.5)[:, None]
    w = rng.integers(0, 3, n) / 16.0 if weighted else None
    assert_alpha_equals_gudhi(pts, w)

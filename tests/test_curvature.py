"""Tests for thesis_lib.curvature (thesis §3.3): values, libigl/pymeshlab cross-checks, invariants, bad input."""

from __future__ import annotations

from math import factorial

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull

from thesis_lib.curvature import (
    angle_defects,
    boundary_vertices,
    check_orientation,
    check_pseudomanifold,
    circumcentric_fractions,
    gaussian_curvature,
    mean_curvature,
    mean_curvature_vector,
    normal_curvatures,
    pinched_vertices,
    principal_curvatures,
    shape_operator,
    simplex_hyperareas,
    total_hyperarea,
    validate_mesh,
    vertex_areas,
    vertex_normals,
)

igl = pytest.importorskip("igl")

R_TORUS, r_TORUS = 10.0, 5.0


# ----------------------------------------------------------------------------- meshes built inline
def torus_grid(nu: int, nv: int, R: float = R_TORUS, r: float = r_TORUS):
    """Grid triangulation of the torus (outward orientation) and the v parameter of each vertex."""
    u = 2 * np.pi * np.arange(nu) / nu
    v = 2 * np.pi * np.arange(nv) / nv
    U, V = np.meshgrid(u, v, indexing="ij")
    P = np.stack([(R + r * np.cos(V)) * np.cos(U), (R + r * np.cos(V)) * np.sin(U), r * np.sin(V)], -1)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    a, b = i * nv + j, ((i + 1) % nu) * nv + j
    c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    return P.reshape(-1, 3), F, U.ravel(), V.ravel()


def outward(points: np.ndarray, simplices: np.ndarray) -> np.ndarray:
    """Orient the facets of a convex hull (around the origin) outwards, any dimension."""
    p = points[simplices]
    x = p[:, 1:] - p[:, :1]
    sign = np.linalg.det(np.concatenate([p[:, :1], x], axis=1))
    s = simplices.copy()
    s[sign < 0, :2] = s[sign < 0, 1::-1]
    return s


def sphere_hull(n_points: int, dim: int = 3, radius: float = 1.0, seed: int = 0):
    """Convex hull of random points on the sphere S^{dim-1}: a closed (dim-1)-hypersurface."""
    rng = np.random.default_rng(seed)
    x = rng.normal(size=(n_points, dim))
    x *= radius / np.linalg.norm(x, axis=1)[:, None]
    return x, outward(x, ConvexHull(x).simplices)


def fibonacci_sphere(n: int, radius: float = 2.0):
    i = np.arange(n) + 0.5
    phi, th = np.arccos(1 - 2 * i / n), np.pi * (1 + 5**0.5) * i
    x = radius * np.stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)], 1)
    return x, outward(x, ConvexHull(x).simplices)


def open_patch(k: int = 8, seed: int = 0):
    """A triangulated graph z = (x^2 - y^2)/4 over a k x k grid (with boundary), jittered."""
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.linspace(-1, 1, k), np.linspace(-1, 1, k), indexing="ij")
    x = x + rng.uniform(-0.02, 0.02, x.shape)
    y = y + rng.uniform(-0.02, 0.02, y.shape)
    P = np.stack([x, y, (x**2 - y**2) / 4], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(k - 1), np.arange(k - 1), indexing="ij")
    a, b, c, d = i * k + j, (i + 1) * k + j, (i + 1) * k + j + 1, i * k + j + 1
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    boundary = ((np.arange(k * k) // k) % (k - 1) == 0) | ((np.arange(k * k) % k) % (k - 1) == 0)
    return P, F, boundary


def finite_difference_gradient(points: np.ndarray, simplices: np.ndarray, h: float = 1e-6) -> np.ndarray:
    """Central differences of the total hyperarea, moving one vertex coordinate at a time.

    Moving vertex v changes only the simplices containing it, so the change of the total area is
    Σ_{T ∋ v} (A_T(moved) − A_T); all vertices are handled in one batch per (coordinate, sign, corner).
    """
    nv, d = points.shape
    n = simplices.shape[1] - 1

    def areas(q):
        x = q[:, 1:] - q[:, :1]
        return np.sqrt(np.linalg.det(np.einsum("mia,mja->mij", x, x))) / factorial(n)

    q0 = points[simplices]
    base = areas(q0)
    out = np.zeros_like(points)
    for a in range(d):
        change = {}
        for sgn in (1, -1):
            total = np.zeros(nv)
            for k in range(n + 1):
                q = q0.copy()
                q[:, k, a] += sgn * h
                total += np.bincount(simplices[:, k], weights=areas(q) - base, minlength=nv)
            change[sgn] = total
        out[:, a] = (change[1] - change[-1]) / (2 * h)
    return out


# ----------------------------------------------------------------------------- mean curvature vector
@pytest.mark.parametrize("n, n_points", [(2, 40), (3, 30), (4, 25)])
def test_gram_and_cot_agree_with_finite_differences(n, n_points):
    x, s = sphere_hull(n_points, dim=n + 1, seed=n)
    x = x + np.random.default_rng(10 + n).normal(scale=0.05, size=x.shape)
    gram = mean_curvature_vector(x, s, method="gram")
    cot = mean_curvature_vector(x, s, method="cot")
    fd = finite_difference_gradient(x, s)
    scale = np.abs(gram).max()
    assert gram.shape == x.shape
    np.testing.assert_allclose(cot, gram, atol=1e-11 * scale)
    np.testing.assert_allclose(gram, fd, atol=1e-6 * scale)


def test_thesis_corollary_coefficient_needs_n_times_n_minus_1():
    """Corollary 3.19 prints A_G / n!; the gradient needs A_G / (n (n-1)): the same for n = 2, 3 only."""
    x, s = sphere_hull(25, dim=5, seed=4)
    fd = finite_difference_gradient(x, s)
    cot = mean_curvature_vector(x, s, method="cot")
    thesis_literal = cot * (4 * 3) / factorial(4)
    assert np.allclose(cot, fd, atol=1e-6 * np.abs(fd).max())
    assert not np.allclose(thesis_literal, fd, atol=1e-2 * np.abs(fd).max())
    np.testing.assert_allclose(thesis_literal * factorial(4 - 2), fd, atol=1e-6 * np.abs(fd).max())


def test_n2_equals_cotangent_formula_and_libigl():
    rng = np.random.default_rng(1)
    x, f = sphere_hull(300, seed=1)
    x = x + rng.normal(scale=0.02, size=x.shape)  # irregular, with obtuse triangles
    vec = mean_curvature_vector(x, f)
    # (3.18) written out: 1/2 sum_j (cot a_ij + cot b_ij) (p - q_j), accumulated per triangle corner
    expected = np.zeros_like(x)
    for k in range(3):
        i, j, o = f[:, (k + 1) % 3], f[:, (k + 2) % 3], f[:, k]
        e1, e2 = x[i] - x[o], x[j] - x[o]
        cot = np.einsum("ma,ma->m", e1, e2) / np.linalg.norm(np.cross(e1, e2), axis=1)
        np.add.at(expected, i, 0.5 * cot[:, None] * (x[i] - x[j]))
        np.add.at(expected, j, 0.5 * cot[:, None] * (x[j] - x[i]))
    np.testing.assert_allclose(vec, expected, atol=1e-12)
    L = igl.cotmatrix(x, f)  # libigl's L already holds the factor 1/2: grad area = -(L p)
    np.testing.assert_allclose(vec, -(L @ x), atol=1e-12)
    np.testing.assert_allclose(mean_curvature_vector(x, f, method="cot"), -(L @ x), atol=1e-12)


def test_mean_curvature_vector_points_outwards_on_a_convex_surface():
    """The area gradient grows the area: on a convex sphere mesh it has a positive component along
    the outward normal at every vertex (and a finite step along it does grow the area)."""
    x, f = sphere_hull(300, seed=3)
    vec = mean_curvature_vector(x, f)
    assert np.all(np.einsum("ij,ij->i", vec, x) > 0)
    step = 1e-4 * np.abs(vec).max()
    grown = x.copy()
    grown[0] += step * vec[0] / np.linalg.norm(vec[0])
    assert total_hyperarea(grown, f) > total_hyperarea(x, f)


@settings(deadline=None, max_examples=15)
@given(seed=st.integers(0, 10_000), n=st.sampled_from([2, 3, 4]), scale=st.floats(0.1, 10.0))
def test_vector_translation_and_scaling_invariants(seed, n, scale):
    """Σ_p ∇_p area = 0 (area is translation invariant); ∇ scales as s^(n-1), |H| as 1/s; gram = cot."""
    x, s = sphere_hull(20 + seed % 20, dim=n + 1, seed=seed)
    vec = mean_curvature_vector(x, s)
    np.testing.assert_allclose(mean_curvature_vector(x, s, method="cot"), vec, atol=1e-11 * np.abs(vec).max())
    np.testing.assert_allclose(vec.sum(axis=0), 0, atol=1e-12 * len(x))
    np.testing.assert_allclose(mean_curvature_vector(scale * x, s), scale ** (n - 1) * vec, rtol=1e-9, atol=1e-12)
    h = mean_curvature(x, s, area="voronoi" if n > 2 else "mixed")
    np.testing.assert_allclose(mean_curvature(scale * x, s, area="voronoi" if n > 2 else "mixed"), h / scale, rtol=1e-9)


# ----------------------------------------------------------------------------- vertex areas
def test_mixed_area_equals_libigl_voronoi_mass():
    rng = np.random.default_rng(2)
    x, f = sphere_hull(400, seed=2)
    x = x + rng.normal(scale=0.03, size=x.shape)
    ours = vertex_areas(x, f, area="mixed")
    M = igl.massmatrix(x, f, igl.MASSMATRIX_TYPE_VORONOI).diagonal()
    np.testing.assert_allclose(ours, M, rtol=1e-12)
    Mb = igl.massmatrix(x, f, igl.MASSMATRIX_TYPE_BARYCENTRIC).diagonal()
    np.testing.assert_allclose(vertex_areas(x, f, area="barycentric"), Mb, rtol=1e-12)


def test_voronoi_area_thesis_formula_and_libigl_on_non_obtuse():
    rng = np.random.default_rng(3)
    x, f = fibonacci_sphere(400, radius=1.0)  # mostly acute, some obtuse triangles
    x = x + rng.normal(scale=0.01, size=x.shape)
    vor = vertex_areas(x, f, area="voronoi")
    # A_vor = 1/8 sum_j (cot a_ij + cot b_ij) |x_i - x_j|^2 (§3.3.2), written per corner
    expected = np.zeros(len(x))
    obtuse = np.zeros(len(x), dtype=bool)
    for k in range(3):
        i, j, o = f[:, (k + 1) % 3], f[:, (k + 2) % 3], f[:, k]
        e1, e2 = x[i] - x[o], x[j] - x[o]
        dot = np.einsum("ma,ma->m", e1, e2)
        cot = dot / np.linalg.norm(np.cross(e1, e2), axis=1)
        w = cot * np.einsum("ma,ma->m", x[i] - x[j], x[i] - x[j]) / 8
        np.add.at(expected, i, w)
        np.add.at(expected, j, w)
        bad = f[dot < 0].ravel()
        obtuse[bad] = True
    np.testing.assert_allclose(vor, expected, rtol=1e-10)
    M = igl.massmatrix(x, f, igl.MASSMATRIX_TYPE_VORONOI).diagonal()
    assert obtuse.any() and (~obtuse).sum() > 50
    np.testing.assert_allclose(vor[~obtuse], M[~obtuse], rtol=1e-10)
    assert not np.allclose(vor[obtuse], M[obtuse])  # signed circumcentric vs Meyer's rule


@pytest.mark.parametrize("n", [2, 3, 4])
def test_every_area_kind_sums_to_total_area(n):
    x, s = sphere_hull(30, dim=n + 1, seed=20 + n)
    total = total_hyperarea(x, s)
    kinds = ["voronoi", "barycentric"] + (["mixed"] if n == 2 else [])
    for kind in kinds:
        assert vertex_areas(x, s, area=kind).sum() == pytest.approx(total, rel=1e-12)
    np.testing.assert_allclose(simplex_hyperareas(x, s).sum(), total)


def test_circumcentric_fractions_general_n():
    # n = 2 reduces to the cot formula: f_i = (1 - lambda_i) / 2
    rng = np.random.default_rng(5)
    p = rng.normal(size=(50, 3, 3))
    x = validate_mesh(p.reshape(-1, 3), np.arange(150).reshape(50, 3))
    tri = vertex_areas(x.vertices, x.simplices, area="voronoi").reshape(50, 3) / x.areas[:, None]
    np.testing.assert_allclose(circumcentric_fractions(p), tri, atol=1e-10)
    # regular simplex: equal shares; right-corner tetrahedron: the corner gets 3/4 of the volume
    reg = np.eye(4)[None]
    np.testing.assert_allclose(circumcentric_fractions(reg), 0.25)
    corner = np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]]])
    np.testing.assert_allclose(circumcentric_fractions(corner), [[0.75, 1 / 12, 1 / 12, 1 / 12]])
    with pytest.raises(ValueError, match="shape"):
        circumcentric_fractions(corner[0])
    with pytest.raises(ValueError, match="NaN"):
        circumcentric_fractions(np.where(corner == 1, np.nan, corner))


def test_circumcentric_equals_closest_region_on_well_centred_tetrahedron():
    """Monte Carlo: the part of a well-centred 3-simplex closest to each vertex."""
    rng = np.random.default_rng(6)
    tet = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1.0]]) + rng.uniform(-0.1, 0.1, (4, 3))
    w = rng.dirichlet(np.ones(4), size=200_000)
    pts = w @ tet
    closest = np.argmin(((pts[:, None, :] - tet[None]) ** 2).sum(-1), axis=1)
    mc = np.bincount(closest, minlength=4) / len(pts)
    np.testing.assert_allclose(circumcentric_fractions(tet[None, :, :])[0], mc, atol=5e-3)


# ----------------------------------------------------------------------------- mean and Gaussian curvature
def test_torus_mean_and_gaussian_curvature_match_exact():
    P, F, _, V = torus_grid(100, 100)
    H_exact = np.abs((R_TORUS + 2 * r_TORUS * np.cos(V)) / (2 * r_TORUS * (R_TORUS + r_TORUS * np.cos(V))))
    K_exact = np.cos(V) / (r_TORUS * (R_TORUS + r_TORUS * np.cos(V)))
    H = mean_curvature(P, F)  # norm over n * mixed area (Definition 3.15, Theorem 3.12)
    K = gaussian_curvature(P, F)
    # MEASUREMENTS.md: 7.4e-4 (H) and 9.1e-4 (K), errors relative to max |exact|
    assert np.abs(H - H_exact).max() / H_exact.max() < 1e-3
    assert np.abs(K - K_exact).max() / np.abs(K_exact).max() < 1.5e-3
    # the "cot" route and the Voronoi area give the same on this (non-obtuse) grid
    np.testing.assert_allclose(mean_curvature(P, F, method="cot"), H, rtol=1e-10, atol=1e-14)


def test_gaussian_curvature_matches_libigl():
    rng = np.random.default_rng(7)
    x, f = sphere_hull(500, seed=7)
    x = x + rng.normal(scale=0.02, size=x.shape)
    defect = igl.gaussian_curvature(x, f)
    np.testing.assert_allclose(angle_defects(x, f), defect, atol=1e-12)
    M = igl.massmatrix(x, f, igl.MASSMATRIX_TYPE_VORONOI).diagonal()
    np.testing.assert_allclose(gaussian_curvature(x, f), defect / M, rtol=1e-10)
    Mb = vertex_areas(x, f, area="barycentric")
    np.testing.assert_allclose(gaussian_curvature(x, f, area="barycentric"), defect / Mb, rtol=1e-10)


def test_sphere_mean_curvature_n3():
    """A fine hull of the 3-sphere of radius 2 in R^4 (§3.4.2): |H| = 1/2 on average."""
    x, s = sphere_hull(600, dim=4, radius=2.0, seed=8)
    h = mean_curvature(x, s, area="voronoi")
    assert np.median(h) == pytest.approx(0.5, rel=0.05)
    # integrated form: sum of |grad area| / n over the sphere ~ |H| * total area
    vec = mean_curvature_vector(x, s)
    assert np.linalg.norm(vec, axis=1).sum() / 3 == pytest.approx(0.5 * total_hyperarea(x, s), rel=0.05)


@settings(deadline=None, max_examples=20)
@given(
    seed=st.integers(0, 100_000),
    kind=st.sampled_from(["sphere", "torus"]),
    noise=st.floats(0.0, 0.3),
    size=st.integers(6, 14),
)
def test_gauss_bonnet(seed, kind, noise, size):
    """Σ angle defects = 2πχ on random closed meshes (Theorem 3.8)."""
    rng = np.random.default_rng(seed)
    if kind == "sphere":
        x, f = sphere_hull(size * 3, seed=seed)
        x = x * rng.uniform(0.5, 1.5, size=(len(x), 1))  # radial perturbation keeps it embedded
        chi = 2
    else:
        x, f, _, _ = torus_grid(size, size // 2 + 3)
        x = x + rng.normal(scale=noise, size=x.shape)
        chi = 0
    assert angle_defects(x, f).sum() == pytest.approx(2 * np.pi * chi, abs=1e-9)
    edges = {tuple(sorted(e)) for t in f for e in ((t[0], t[1]), (t[1], t[2]), (t[0], t[2]))}
    assert len(x) - len(edges) + len(f) == chi


def test_boundary_vertices_are_nan():
    P, F, boundary = open_patch()
    H = mean_curvature(P, F)
    K = gaussian_curvature(P, F)
    assert np.isnan(H[boundary]).all() and np.isfinite(H[~boundary]).all()
    assert np.isnan(K[boundary]).all() and np.isfinite(K[~boundary]).all()
    assert np.isnan(angle_defects(P, F)[boundary]).all()
    vec = mean_curvature_vector(P, F)
    assert np.isfinite(vec).all()  # the area gradient itself is defined everywhere
    pc = principal_curvatures(P, F)
    assert np.isnan(pc.k1[boundary]).all() and np.isfinite(pc.k1[~boundary]).all()
    # saddle z = (x^2 - y^2)/4 at the centre: principal curvatures -1/2 and 1/2, H = 0, K = -1/4
    centre = np.argmin(np.linalg.norm(P[:, :2], axis=1))
    assert abs(pc.k1[centre] + 0.5) < 0.1 and abs(pc.k2[centre] - 0.5) < 0.1


def test_isolated_vertex_is_nan():
    x, f = sphere_hull(30, seed=9)
    x2 = np.vstack([x, [[5.0, 5.0, 5.0]]])
    assert np.isnan(mean_curvature(x2, f)[-1]) and np.isnan(gaussian_curvature(x2, f)[-1])
    np.testing.assert_allclose(mean_curvature(x2, f)[:-1], mean_curvature(x, f))


def test_orientation_independence_and_detection():
    """|H|, K and the vector do not depend on orientation; signed quantities demand coherence."""
    rng = np.random.default_rng(11)
    x, f = sphere_hull(200, seed=11)
    flipped = f.copy()
    sel = rng.random(len(f)) < 0.3
    flipped[sel] = flipped[sel][:, ::-1]
    np.testing.assert_allclose(mean_curvature_vector(x, flipped), mean_curvature_vector(x, f), atol=1e-14)
    np.testing.assert_allclose(mean_curvature(x, flipped), mean_curvature(x, f))
    np.testing.assert_allclose(gaussian_curvature(x, flipped), gaussian_curvature(x, f))
    with pytest.raises(ValueError, match="inconsistent orientation: faces"):
        check_orientation(flipped)
    with pytest.raises(ValueError, match="inconsistent orientation"):
        shape_operator(x, flipped)
    with pytest.raises(ValueError, match="inconsistent orientation"):
        vertex_normals(x, flipped)
    check_orientation(f)


# ----------------------------------------------------------------------------- shape operator
def test_shape_operator_sphere():
    x, f = fibonacci_sphere(800, radius=2.0)
    _, kappa = normal_curvatures(x, f)
    np.testing.assert_allclose(kappa, 0.5, rtol=1e-9)  # (3.24) with Max's normals is exact here
    pc = principal_curvatures(x, f)
    np.testing.assert_allclose(pc.k1, 0.5, rtol=1e-8)
    np.testing.assert_allclose(pc.k2, 0.5, rtol=1e-8)
    so = shape_operator(x, f)
    np.testing.assert_allclose(so.tensor, 0.5 * np.eye(2)[None].repeat(len(x), 0), atol=1e-8)
    np.testing.assert_allclose(np.einsum("vja,va->vj", so.basis, so.normal), 0, atol=1e-12)
    np.testing.assert_allclose(so.normal, x / 2.0, atol=1e-12)
    # reversing the orientation flips the sign (Definition 3.1 convention vs (3.24))
    pr = principal_curvatures(x, f[:, ::-1])
    np.testing.assert_allclose(pr.k2, -0.5, rtol=1e-8)
    # area-weighted normals are worse on this irregular triangulation but still close on average
    pa = principal_curvatures(x, f, normals="area")
    assert np.median(np.abs(pa.k1 - 0.5)) < 0.05


def test_shape_operator_torus_principal_curvatures_and_directions():
    P, F, U, V = torus_grid(100, 100)
    pc = principal_curvatures(P, F)
    k_u = np.cos(V) / (R_TORUS + r_TORUS * np.cos(V))  # parallel circles
    k_v = np.full_like(V, 1 / r_TORUS)  # meridians
    np.testing.assert_allclose(pc.k1, np.minimum(k_u, k_v), atol=1e-3)
    np.testing.assert_allclose(pc.k2, np.maximum(k_u, k_v), atol=1e-3)
    e_v = np.stack([-np.sin(V) * np.cos(U), -np.sin(V) * np.sin(U), np.cos(V)], 1)  # meridian direction
    assert np.abs(np.einsum("va,va->v", pc.d2, e_v)).min() > 0.999  # k2 = 1/r is along meridians
    np.testing.assert_allclose(np.einsum("va,va->v", pc.d1, pc.d2), 0, atol=1e-12)
    # the least-squares H and K agree with the cotangent/angle-defect estimates
    H = mean_curvature(P, F)
    np.testing.assert_allclose(np.abs(pc.k1 + pc.k2) / 2, H, atol=2e-3)


# ----------------------------------------------------------------------------- pymeshlab
def test_agrees_with_pymeshlab_discrete_curvature():
    """pymeshlab's compute_scalar_by_discrete_curvature_per_vertex (Meyer et al.: cot + mixed area).

    MeshLab stores vertex quality in single precision, so agreement is to float32 accuracy:
    tolerance 1e-5 relative to the largest |value| (observed ~2e-6 for H, ~2e-7 for K).
    """
    pymeshlab = pytest.importorskip("pymeshlab")
    rng = np.random.default_rng(12)
    P, F, _, _ = torus_grid(60, 40)
    P = P + rng.normal(scale=0.15, size=P.shape)  # irregular, many obtuse triangles
    ours = {"Mean Curvature": mean_curvature(P, F), "Gaussian Curvature": gaussian_curvature(P, F)}
    for kind, value in ours.items():
        ms = pymeshlab.MeshSet()
        ms.add_mesh(pymeshlab.Mesh(P, F))
        ms.compute_scalar_by_discrete_curvature_per_vertex(curvaturetype=kind)
        q = ms.current_mesh().vertex_scalar_array()
        if kind == "Mean Curvature":
            q = np.abs(q)  # MeshLab's H is signed; ours is |H|
        np.testing.assert_allclose(value, q, atol=1e-5 * np.abs(value).max())


# ----------------------------------------------------------------------------- bad input
def tetrahedron():
    x = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return x, f


@pytest.mark.parametrize(
    "fn",
    [
        mean_curvature_vector,
        mean_curvature,
        gaussian_curvature,
        angle_defects,
        lambda x, f: vertex_areas(x, f, area="voronoi"),
        shape_operator,
        principal_curvatures,
    ],
)
def test_bad_input_raises_everywhere(fn):
    x, f = tetrahedron()
    # a non-manifold edge: a third triangle on the edge (0, 1)
    x_nm = np.vstack([x, [[0.5, -1.0, 0.5]]])
    with pytest.raises(ValueError, match=r"non-manifold ridge \(0, 1\): it lies in 3"):
        fn(x_nm, np.vstack([f, [[0, 1, 4]]]))
    # degenerate triangle (collinear points)
    x_deg = np.vstack([x, [[2.0, 0, 0]]])
    with pytest.raises(ValueError, match=r"simplex 4 \[0, 1, 4\] is degenerate"):
        fn(x_deg, np.vstack([f, [[0, 1, 4]]]))
    with pytest.raises(ValueError, match="NaN or infinite"):
        fn(np.where(np.arange(12).reshape(4, 3) == 5, np.nan, x), f)
    with pytest.raises(ValueError, match="hypersurface in R\\^3"):
        fn(x, f[:, :2])
    with pytest.raises(ValueError, match="vertex index outside"):
        fn(x, np.vstack([f, [[0, 1, 7]]]))
    with pytest.raises(ValueError, match="repeated vertex"):
        fn(x, np.vstack([f, [[0, 1, 1]]]))
    with pytest.raises(ValueError, match="empty"):
        fn(x, np.empty((0, 3), dtype=int))
    with pytest.raises(ValueError, match="vertices must be"):
        fn(x[:, 0], f)


def test_bad_options_and_dimensions():
    x, f = tetrahedron()
    with pytest.raises(ValueError, match="unknown method"):
        mean_curvature_vector(x, f, method="fem")
    with pytest.raises(ValueError, match="^area must be one of 'mixed', 'voronoi', 'barycentric', got 'hexagonal'$"):
        mean_curvature(x, f, area="hexagonal")
    with pytest.raises(ValueError, match="^area must be one of .*, got 'hexagonal'$"):
        vertex_areas(x, f, area="hexagonal")
    with pytest.raises(ValueError, match="^area must be one of .*, got array"):  # not read as its one element
        vertex_areas(x, f, area=np.array(["mixed", "voronoi"]))
    with pytest.raises(ValueError, match="^edge_weights must be one of 'voronoi', 'uniform', got 'random'$"):
        shape_operator(x, f, edge_weights="random")
    with pytest.raises(ValueError, match="^normals must be one of 'max', 'area', got 'random'$"):
        vertex_normals(x, f, normals="random")
    x4, s4 = sphere_hull(20, dim=4, seed=13)
    with pytest.raises(ValueError, match="mixed area .* n = 2"):
        mean_curvature(x4, s4)  # default area="mixed" is for surfaces
    with pytest.raises(ValueError, match="n = 2"):
        gaussian_curvature(x4, s4)
    with pytest.raises(ValueError, match="n = 2"):
        shape_operator(x4, s4)
    with pytest.raises(ValueError, match="3 vertices each"):
        mean_curvature_vector(x4, s4[:, :3])  # triangles in R^4 are not a hypersurface
    assert np.isfinite(mean_curvature(x4, s4, area="barycentric")).all()


def test_boundary_vertices_and_ridge_keys_for_large_n():
    P, F, boundary = open_patch()
    np.testing.assert_array_equal(boundary_vertices(F, len(P)), boundary)
    x, f = tetrahedron()
    assert not boundary_vertices(f, 4).any()
    # n = 4 with 50,000 vertices: ridge keys do not fit in int64 (nv^4 > 2^62), byte keys are used
    x4, s4 = sphere_hull(25, dim=5, seed=14)
    big = np.vstack([x4, np.random.default_rng(0).normal(size=(50_000, 5)) + 10])  # isolated extras
    np.testing.assert_allclose(mean_curvature_vector(big, s4)[: len(x4)], mean_curvature_vector(x4, s4))
    extra = np.vstack([s4, [[*s4[0, :4], 30]]])  # a third 4-simplex on the ridge s4[0, :4]
    with pytest.raises(ValueError, match=r"non-manifold ridge \(" + ", ".join(map(str, sorted(s4[0, :4]))) + r"\)"):
        mean_curvature_vector(big, extra)


def test_degenerate_and_nonpositive_area_in_higher_dimension():
    x4, s4 = sphere_hull(20, dim=4, seed=15)
    flat = np.vstack([x4, [x4[s4[0, 0]] + 1e-14, 2 * x4[s4[0, 1]] - x4[s4[0, 0]], [9.0, 9, 9, 9]]])
    n0 = len(x4)
    bad = np.vstack([s4, [[s4[0, 0], s4[0, 1], n0 + 1, n0 + 2]]])  # three collinear vertices
    with pytest.raises(ValueError, match=rf"simplex {len(s4)} .* is degenerate"):
        mean_curvature(flat, bad, area="barycentric")


def test_curves_n1_polygon_curvature():
    """n = 1: a regular polygon inscribed in a circle of radius R has |H| = 1/R exactly."""
    k, radius = 37, 3.0
    t = 2 * np.pi * np.arange(k) / k
    x = radius * np.stack([np.cos(t), np.sin(t)], 1)
    e = np.stack([np.arange(k), (np.arange(k) + 1) % k], 1)
    np.testing.assert_allclose(mean_curvature(x, e, area="voronoi"), 1 / radius, rtol=1e-12)
    np.testing.assert_allclose(mean_curvature(x, e, area="barycentric"), 1 / radius, rtol=1e-12)
    np.testing.assert_allclose(finite_difference_gradient(x, e), mean_curvature_vector(x, e), atol=1e-7)
    with pytest.raises(ValueError, match="needs n >= 2"):
        mean_curvature_vector(x, e, method="cot")
    h = mean_curvature(x, e[:-1], area="voronoi")  # open polygon: the two ends are boundary
    assert np.isnan(h[[0, k - 1]]).all() and np.isfinite(h[1:-1]).all()


# ------------------------------------------------------------------------- one vocabulary
def test_the_vertex_region_is_area_and_the_edge_weighting_edge_weights():
    """``area=`` names the vertex region and ``edge_weights=`` the shape operator's edge weights;
    ``kind=`` and ``weights=`` (the points' weights elsewhere) are refused there."""
    x, f = tetrahedron()
    with pytest.raises(TypeError, match="kind"):
        vertex_areas(x, f, kind="barycentric")
    P, F = torus_grid(12, 12)[:2]
    for fn in (shape_operator, principal_curvatures):
        with pytest.raises(TypeError, match="weights"):
            fn(P, F, weights="uniform")


# ------------------------------------------------------------------------- pseudo-manifolds
def _pinched():
    """Two tetrahedron boundaries glued at vertex 3 (the second reflected through it): every edge
    lies in two faces, but the link of vertex 3 is two triangles."""
    x, f = tetrahedron()
    v = np.vstack([x, 2 * x[3] - x[:3]])
    relabel = np.array([4, 5, 6, 3])
    return v, np.vstack([f, relabel[f]])


@pytest.mark.parametrize(
    "fn",
    [
        lambda v, f: vertex_areas(v, f, area="mixed"),
        lambda v, f: mean_curvature(v, f),
        lambda v, f: mean_curvature_vector(v, f),
        lambda v, f: gaussian_curvature(v, f),
        lambda v, f: angle_defects(v, f),
        lambda v, f: principal_curvatures(v, f),
        lambda v, f: shape_operator(v, f),
        lambda v, f: vertex_normals(v, f),
    ],
)
def test_non_manifold_input_is_refused(fn):
    # a doubled triangle: before, every function returned numbers for it
    x, f = tetrahedron()
    with pytest.raises(ValueError, match=r"simplices 0 and 1 have the same vertices"):
        fn(x, np.array([[0, 1, 2], [0, 1, 2]]))


@pytest.mark.parametrize(
    "fn",
    [
        lambda v, f: mean_curvature(v, f),
        lambda v, f: gaussian_curvature(v, f),
        lambda v, f: angle_defects(v, f),
        lambda v, f: principal_curvatures(v, f).k1,
        lambda v, f: shape_operator(v, f).tensor,
    ],
)
def test_pinched_vertices_get_no_estimate(fn):
    # a pinched vertex (principal_curvatures failed inside the SVD): no single fan, so NaN there, as
    # on a boundary vertex; every other vertex keeps the value of its own tetrahedron
    v, g = _pinched()
    assert pinched_vertices(g, len(v)).tolist() == [False] * 3 + [True] + [False] * 3
    with pytest.raises(ValueError, match="vertex 3 is pinched"):
        check_pseudomanifold(g, len(v))
    out = np.asarray(fn(v, g))
    assert np.all(np.isnan(out[3]))
    x, f = tetrahedron()
    alone = np.asarray(fn(x, f))
    np.testing.assert_allclose(out[:3], alone[:3], rtol=1e-12)
    assert np.all(np.isfinite(out[[0, 1, 2, 4, 5, 6]]))


def test_check_pseudomanifold_accepts_manifolds_and_boundaries():
    P, F = torus_grid(20, 20)[:2]
    check_pseudomanifold(F, len(P))
    Q, G, _ = open_patch()
    check_pseudomanifold(G, len(Q))
    # a fan around one vertex of very high degree stays fast and valid (a disk)
    n = 20_000
    t = np.arange(n)
    check_pseudomanifold(np.column_stack([np.full(n, n), t, (t + 1) % n]), n + 1)
    with pytest.raises(ValueError, match="three or more"):
        check_pseudomanifold(np.array([[0, 1, 2], [0, 1, 3], [0, 1, 4]]), 5)
    # curves (n = 1): a vertex in two edges is fine, links are not checked
    check_pseudomanifold(np.array([[0, 1], [1, 2], [2, 0]]), 3)


@pytest.mark.parametrize("n", [2, 3, 4])
def test_scale_covariance_up_to_the_float_range_and_refusal_beyond(n):
    """Mean curvature scales as 1/s and hyperareas as s^n at any representable scale; a mesh so large
    or small that products of 2n lengths leave float64 is refused (it returned NaN at 1e100 and
    called a sphere of extent 1e-100 degenerate)."""
    import warnings

    from thesis_lib.curvature import mean_curvature, total_hyperarea
    from thesis_lib.curvature.validate import SCALE_BITS
    from thesis_lib.meshes import convex_hull_surface, sample_sphere

    pts = sample_sphere(150, n_dims=n + 1, seed=n)
    faces = convex_hull_surface(pts)
    area = "mixed" if n == 2 else "voronoi"
    limit = SCALE_BITS // (2 * n)
    h, a = mean_curvature(pts, faces, area=area), total_hyperarea(pts, faces)
    for bits in (limit - 2, -(limit - 2)):  # the sphere's extent is about 2: just inside the range
        s = 2.0**bits
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            np.testing.assert_allclose(mean_curvature(pts * s, faces, area=area) * s, h, rtol=1e-12)
            np.testing.assert_allclose(total_hyperarea(pts * s, faces) / s**n, a, rtol=1e-12)
    for bits in (limit + 1, -(limit + 2), 300, -300):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # refused with no overflow warning on the way
            with pytest.raises(ValueError, match="rescale the vertices"):
                mean_curvature(pts * 2.0**bits, faces, area=area)


# ----------------------------------------------------------------------------- a triangle soup
def soup(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The mesh split into a triangle soup: each triangle has its own three vertices (as a mesh read
    from a textured OBJ file is split at its seams)."""
    return vertices[faces.ravel()], np.arange(3 * len(faces)).reshape(-1, 3)


@pytest.mark.parametrize("function", [mean_curvature, gaussian_curvature])
def test_a_triangle_soup_warns_with_the_remedy_and_merging_restores_the_curvature(function):
    import warnings

    from thesis_lib.meshes import merge_coincident
    from thesis_lib.meshes import torus_grid as mesh_torus_grid

    vertices, faces = mesh_torus_grid(16)
    original = function(vertices, faces)
    assert np.all(np.isfinite(original))
    sv, sf = soup(vertices, faces)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        split = function(sv, sf)
    assert np.all(np.isnan(split))  # every vertex of a soup is on a boundary
    assert len(caught) == 1 and caught[0].filename == __file__
    message = str(caught[0].message)
    assert "merge_coincident(vertices, simplices)" in message and f"{len(sv)} boundary vertices" in message
    mv, mf, kept = merge_coincident(sv, sf)
    assert len(mv) == len(vertices)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        merged = function(mv, mf)
    # merged vertex i is soup vertex kept[i], that is original vertex faces.ravel()[kept[i]]
    np.testing.assert_allclose(merged, original[faces.ravel()[kept]], rtol=1e-12, atol=0)


def test_a_split_seam_warns_and_an_open_or_closed_mesh_does_not():
    import warnings

    from thesis_lib.meshes import torus_grid as mesh_torus_grid

    vertices, faces = mesh_torus_grid(12)
    # cut the torus along its seam u = 0 by giving the triangles on one side copies of the seam vertices
    seam = np.flatnonzero(np.isclose(np.arctan2(vertices[:, 1], vertices[:, 0]), 0.0))
    copies = np.arange(len(vertices), len(vertices) + len(seam))
    remap = np.arange(len(vertices))
    remap[seam] = copies
    side = np.any(np.arctan2(vertices[faces, 1], vertices[faces, 0]) < -1e-9, axis=1)
    cut = faces.copy()
    cut[side] = remap[faces[side]]
    cut_vertices = np.vstack([vertices, vertices[seam]])
    with pytest.warns(UserWarning, match=f"{2 * len(seam)} boundary vertices lie at exactly") as caught:
        H = mean_curvature(cut_vertices, cut)
    assert len(caught) == 1
    assert np.count_nonzero(np.isnan(H)) == 2 * len(seam)  # the seam's two copies, and nothing else
    # a closed mesh and an open one without coincident vertices are not warned about
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mean_curvature(vertices, faces)
        mean_curvature(vertices, faces[~side])

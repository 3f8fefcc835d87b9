"""Evidence functions for chapter 3's report rows (thesis_lib.curvature.checks)."""

from math import factorial

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.curvature import principal_curvatures, vertex_areas
from thesis_lib.curvature.checks import (
    barycentric_gradients,
    corollary_3_19_coefficient,
    dihedral_cotangent_sum,
    exterior_angles,
    hyperarea_gradient_fd,
    nearest_vertex_volumes,
    principal_curvatures_from_mean_and_gaussian,
    printed_sum_gradient,
    random_simplices,
    thales_obtuse,
)
from thesis_lib.meshes import sphere_hull, torus_grid
from thesis_lib.surfaces import torus_principal_curvatures_at


def test_barycentric_gradients_are_dual_to_the_edges():
    p = random_simplices(4, 20, seed=1)
    g = barycentric_gradients(p)
    # (v_j − v_i)·∇λ_k = δ_jk − δ_ik
    for i, j in [(0, 1), (2, 4), (3, 0)]:
        dots = np.einsum("ma,mka->mk", p[:, j] - p[:, i], g)
        expected = np.zeros(5)
        expected[j] += 1
        expected[i] -= 1
        assert np.allclose(dots, expected, atol=1e-9)


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6])
def test_corollary_3_19_coefficient_is_one_over_n_times_n_minus_one(n):
    c, residual = corollary_3_19_coefficient(n, 60, seed=n)
    assert residual < 1e-5  # the thesis's form Σ −x_i A_G^i cot θ_i is right ...
    assert c * n * (n - 1) == pytest.approx(1.0, rel=1e-6)  # ... with the coefficient 1/(n(n − 1))
    assert c * factorial(n) == pytest.approx(factorial(n) / (n * (n - 1)), rel=1e-6)  # not 1/n! (n ≥ 4)


def test_the_cotangent_sum_for_triangles_is_formula_3_18():
    p = random_simplices(2, 30, seed=3)
    q, a, b = p[:, 0], p[:, 1], p[:, 2]

    def cot(x, y, z):  # angle at x
        u, v = y - x, z - x
        return np.einsum("ma,ma->m", u, v) / np.linalg.norm(np.cross(u, v), axis=1)

    # ∇_q A = ½ Σ_j cot(angle opposite edge q p_j) (q − p_j) for one triangle
    grad = 0.5 * (cot(b, q, a)[:, None] * (q - a) + cot(a, q, b)[:, None] * (q - b))
    assert np.allclose(0.5 * dihedral_cotangent_sum(p), grad, atol=1e-12)
    assert np.allclose(hyperarea_gradient_fd(p), grad, atol=1e-8)


def test_nearest_vertex_volumes_at_the_corner_of_section_3_4_2():
    corner = np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]], dtype=float)
    vol = nearest_vertex_volumes(corner)[0]
    assert vol[0] == pytest.approx(5 / 48, rel=1e-12)  # not 1/12 = half the volume
    assert vol.sum() == pytest.approx(1 / 6, rel=1e-12)
    assert vol[1:] == pytest.approx([1 / 48] * 3, rel=1e-10)


def test_nearest_vertex_volumes_of_regular_simplices_and_segments():
    tri = np.array([[[0, 0], [1, 0], [0.5, np.sqrt(3) / 2]]])
    assert nearest_vertex_volumes(tri)[0] == pytest.approx([np.sqrt(3) / 12] * 3, rel=1e-10)
    tet = np.array([[[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]], dtype=float)
    assert nearest_vertex_volumes(tet)[0] == pytest.approx([8 / 3 / 4] * 4, rel=1e-10)
    seg = np.array([[[0.0, 0.0], [3.0, 4.0]]])
    assert nearest_vertex_volumes(seg)[0] == pytest.approx([2.5, 2.5])


def test_voronoi_formula_holds_on_non_obtuse_triangles_only():
    tri = np.random.default_rng(5).normal(size=(300, 3, 3))
    exact = nearest_vertex_volumes(tri)
    formula = vertex_areas(tri.reshape(-1, 3), np.arange(900).reshape(300, 3), area="voronoi").reshape(300, 3)
    a = tri[:, [1, 2, 0]] - tri
    b = tri[:, [2, 0, 1]] - tri
    obtuse = (np.einsum("mka,mka->mk", a, b) < 0).any(axis=1)
    assert 50 < obtuse.sum() < 290
    agree = np.all(np.abs(formula - exact) <= 1e-9 * exact.sum(axis=1, keepdims=True), axis=1)
    assert np.all(agree[~obtuse]) and not np.any(agree[obtuse])


@settings(deadline=None, max_examples=30)
@given(st.floats(-3, 3), st.floats(-3, 3))
def test_thales(x, y):
    a, b = np.array([-1.0, 0.0]), np.array([1.0, 0.0])
    r2 = x * x + y * y
    if abs(r2 - 1) < 1e-6 or abs(y) < 1e-9:
        return  # on the circle (right angle) or on the line (degenerate)
    assert thales_obtuse(np.array([[x, y]]), a, b)[0] == (r2 < 1)


def test_principal_curvatures_from_h_and_k_on_a_sphere_and_the_torus():
    pts, hull = sphere_hull(n_dims=3, n_points=2000, radius=2.0, seed=0)
    k1, k2 = principal_curvatures_from_mean_and_gaussian(pts, hull)
    assert np.median(k1) == pytest.approx(0.5, rel=0.02) and np.median(k2) == pytest.approx(0.5, rel=0.02)
    v, f = torus_grid(80)
    k1, k2 = principal_curvatures_from_mean_and_gaussian(v, f)
    exact = np.sort(-torus_principal_curvatures_at(v), axis=1)  # shape.py's sign: outward sphere +1/R
    assert np.allclose(np.stack([k1, k2], 1), exact, atol=2e-3)
    ls = principal_curvatures(v, f)
    assert np.allclose(np.stack([ls.k1, ls.k2], 1), exact, atol=2e-3)


def test_printed_sum_has_no_stationary_point():
    v, f = torus_grid(40)
    g = printed_sum_gradient(v, f)
    assert np.all(g >= 1 / np.sqrt(2) - 1e-12) and np.all(g <= 1 + 1e-12)
    pts, hull = sphere_hull(n_dims=3, n_points=500, seed=2)
    assert np.nanmin(printed_sum_gradient(pts, hull)) >= 1 / np.sqrt(2) - 1e-12


def test_exterior_angles_turning_number():
    t = 2 * np.pi * np.arange(400) / 400
    r = 1 + 0.3 * np.cos(3 * t)  # a non-convex closed curve: it turns back and forth
    curve = np.column_stack([r * np.cos(t), r * np.sin(t)])
    delta = exterior_angles(curve)
    assert delta.min() < 0 < delta.max()
    assert delta.sum() == pytest.approx(2 * np.pi, abs=1e-12)
    assert exterior_angles(curve[::-1]).sum() == pytest.approx(-2 * np.pi, abs=1e-12)
    loop = 0.4 + np.cos(t)  # a limaçon with an inner loop turns twice
    limacon = np.column_stack([loop * np.cos(t), loop * np.sin(t)])
    assert exterior_angles(limacon).sum() == pytest.approx(4 * np.pi, abs=1e-9)
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    assert exterior_angles(square) == pytest.approx([np.pi / 2] * 4)  # δ = π − α (Figure 3.1)
    with pytest.raises(ValueError, match="repeated"):
        exterior_angles(np.array([[0, 0], [0, 0], [1, 1]], dtype=float))


def test_bad_input():
    with pytest.raises(ValueError, match="n >= 2"):
        dihedral_cotangent_sum(random_simplices(1, 3))
    with pytest.raises(ValueError, match="shape"):
        barycentric_gradients(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="NaN"):
        nearest_vertex_volumes(np.full((1, 3, 2), np.nan))
    with pytest.raises(ValueError, match="count"):
        random_simplices(2, 0)
    with pytest.raises(ValueError, match=r"^h must be positive, got 0\.0$"):
        hyperarea_gradient_fd(random_simplices(2, 2), h=0.0)

"""thesis_lib.curvature.checks_theory against closed forms: each check gives the known value on an
input where it is known, and a different value where the statement it tests is made false."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib.curvature import checks_theory as ct
from thesis_lib.curvature.checks import hyperarea_gradient_fd, random_simplices
from thesis_lib.meshes import sphere_hull
from thesis_lib.surfaces import ellipsoid_point, hypersphere_point, hypersphere_quadrature


def test_hodge_dual_follows_its_rule_and_is_the_cross_product():
    e = np.eye(3)
    assert np.allclose(ct.hodge_dual(e[1], e[2]), e[0])
    assert np.allclose(ct.hodge_dual(e[0], e[2]), -e[1])
    assert np.allclose(ct.hodge_dual(e[1], e[0]), -e[2])  # the thesis prints +e₃
    u, v = np.random.default_rng(1).normal(size=(2, 20, 3))
    assert np.allclose(ct.hodge_dual(u, v), np.cross(u, v))


def test_wedge_coordinates_norm_is_the_gram_determinant():
    x = np.random.default_rng(2).normal(size=(10, 3, 5))
    gram = np.linalg.det(np.einsum("mka,mla->mkl", x, x))
    assert np.allclose(np.sum(ct.wedge_coordinates(x) ** 2, axis=1), gram)
    assert ct.wedge_coordinates(x).shape == (10, 10)
    with pytest.raises(ValueError):
        ct.wedge_coordinates(np.zeros((4, 3)))


@pytest.mark.parametrize("n", [2, 3, 5])
def test_proposition_3_17_holds(n):
    assert ct.proposition_3_17_residual(n, count=10, seed=n) < 1e-12


def test_jacobi_formula_and_a_wrong_adjugate():
    assert ct.jacobi_formula_residual(4, count=10) < 1e-6
    with pytest.raises(ValueError):
        ct.jacobi_formula_residual(0)


@pytest.mark.parametrize("n", [2, 3, 4])
def test_theorem_3_18_printed_gradient_is_the_area_gradient(n):
    p = random_simplices(n, 20, seed=n)
    assert np.allclose(ct.theorem_3_18_printed_gradient(p), hyperarea_gradient_fd(p), rtol=1e-6, atol=1e-7)


def test_printed_gram_determinant_differs_from_the_gram_determinant():
    x = np.random.default_rng(3).normal(size=(20, 3, 4))
    true = np.sum(ct.wedge_coordinates(x) ** 2, axis=1)
    assert not np.any(np.isclose(ct.printed_gram_determinant(x), true, rtol=1e-6))
    x[:, 1] = x[:, 0]  # ⟨x₁, x₂⟩ = ⟨x₁, x₁⟩: the printed matrix is right (and both vanish)
    assert np.allclose(ct.printed_gram_determinant(x), 0, atol=1e-9)


def _sphere(radius):
    return lambda a: hypersphere_point(a, radius=radius)


def test_first_variation_of_a_sphere_is_its_mean_curvature():
    params, weights = hypersphere_quadrature(2, nodes=16)
    outward = _sphere(1.0)
    dA = ct.first_variation_of_area(_sphere(2.0), outward, params, weights)  # λ = 1: d/dε 4π(2 + ε)²
    assert dA == pytest.approx(16 * np.pi, rel=1e-7)
    lam = lambda a: np.ones(a.shape[:-1])  # noqa: E731
    integral = ct.mean_curvature_integral(_sphere(2.0), outward, lam, params, weights)
    assert integral == pytest.approx(-8 * np.pi, rel=1e-6)  # H = −1/2 over the area 16π
    inward = lambda a: -outward(a)  # noqa: E731
    assert ct.mean_curvature_integral(_sphere(2.0), inward, lam, params, weights) == pytest.approx(8 * np.pi, rel=1e-6)


def test_gauss_map_area_ratio_tends_to_one():
    ell = lambda a: ellipsoid_point(a, [1.0, 1.5, 2.0])  # noqa: E731
    assert abs(ct.gauss_map_area_ratio(ell, [0.7, 0.4], 1e-3) - 1) < 1e-5
    assert abs(ct.gauss_map_area_ratio(ell, [0.7, 0.4], 0.2) - 1) > 1e-3  # a large disc is not the limit


@pytest.mark.parametrize("psi0", [0.5, 1.0, 2.0])
def test_cap_boundary_geodesic_curvature_of_the_unit_sphere(psi0):
    assert ct.cap_boundary_geodesic_curvature(_sphere(1.0), psi0) == pytest.approx(2 * np.pi * np.cos(psi0), abs=1e-6)


@pytest.mark.parametrize("n, sign", [(2, 1), (3, -1)])
def test_gauss_map_pullback_ratio_is_minus_one_to_the_n(n, sign):
    w = np.random.default_rng(4).uniform(0.4, 1.1, (5, n))
    axes = np.linspace(1.0, 2.0, n + 1)
    assert np.allclose(ct.gauss_map_pullback_ratio(lambda a: ellipsoid_point(a, axes), w), sign, atol=1e-3)


def test_cotangent_formulas_are_the_area_gradient():
    pts, hull = sphere_hull(n_dims=3, n_points=80, radius=2.0, seed=5)
    fd = ct.mesh_area_gradient_fd(pts, hull)
    assert np.allclose(ct.cotangent_formula_gradient(pts, hull), fd, atol=1e-7)
    assert np.allclose(ct.example_3_20_gradient(pts, hull), fd, atol=1e-7)


def test_circumcentre_inside_exactly_for_non_obtuse_triangles():
    right = np.array([[[0, 0], [2, 0], [0, 1.0]]])
    obtuse = np.array([[[0, 0], [4, 0], [1, 0.5]]])
    acute = np.array([[[0, 0], [2, 0], [1, 1.5]]])
    assert ct.circumcentre_inside(np.concatenate([right, obtuse, acute])).tolist() == [True, False, True]


def test_statement_and_chapter_of_a_marker():
    text = "2\n\nTitle\nTheorem 2.1. A.\nfoo\nDefinition 2.2. B.\nbar (x)\n3\n\nNext\nbaz"
    assert ct.statement_containing(text, "bar") == "Definition 2.2"
    assert ct.chapter_of(text, "foo") == 2 and ct.chapter_of(text, "baz") == 3
    with pytest.raises(ValueError):
        ct.chapter_of(text, "missing")


def test_bad_inputs_are_refused():
    with pytest.raises(ValueError):
        ct.hodge_dual([1.0, 0.0], [0.0, 1.0])
    with pytest.raises(ValueError):
        ct.theorem_3_18_printed_gradient(np.zeros((3, 2, 3)))  # n = 1
    with pytest.raises(ValueError):
        ct.theorem_3_18_printed_gradient(np.full((1, 3, 3), np.nan))
    with pytest.raises(ValueError):
        ct.printed_gram_determinant(np.zeros((2, 1, 3)))
    with pytest.raises(ValueError):
        ct.proposition_3_17_residual(1)
    params, weights = hypersphere_quadrature(2, nodes=4)
    with pytest.raises(ValueError):
        ct.first_variation_of_area(_sphere(1.0), _sphere(1.0), params, weights[:-1])
    with pytest.raises(ValueError):
        ct.parametric_jacobian(_sphere(1.0), params, h=0.0)
    with pytest.raises(ValueError):
        ct.gauss_map_area_ratio(_sphere(1.0), [0.5, 0.5], -1.0)
    with pytest.raises(ValueError):
        ct.circumcentre_inside(np.zeros((2, 4, 2)))
    with pytest.raises(ValueError):
        ct.cotangent_formula_gradient(np.zeros((3, 3)), np.array([[0, 1, 5]]))
    with pytest.raises(ValueError):
        ct.statement_containing("no statement here", "here")

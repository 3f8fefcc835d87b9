"""The sections of the chapter 3 page (thesis_lib.chapters.curvature_sections) against independent
computations: libigl's cotangent Laplacian and angle defects, closed forms (the volume of Sⁿ by the
Gamma function, the area of a sphere, the thesis's torus formulas) and Monte Carlo."""

from __future__ import annotations

from math import factorial, gamma, pi

import igl
import numpy as np
import pytest

from thesis_lib.chapters import curvature_sections as cs
from thesis_lib.curvature import vertex_areas
from thesis_lib.lab.chapters import read_thesis
from thesis_lib.lab.results import load, round_sig
from thesis_lib.meshes import sphere_hull, torus_grid
from thesis_lib.surfaces import hypersphere_point, hypersphere_quadrature


@pytest.fixture(scope="module")
def sphere():
    """The sphere of radius 2 of the page (the hull of 2000 points)."""
    points, faces = sphere_hull(n_dims=3, n_points=2000, radius=2.0, seed=0)
    return np.ascontiguousarray(points, dtype=float), np.ascontiguousarray(faces, dtype=np.int64)


@pytest.fixture(scope="module")
def thesis():
    return read_thesis()


def test_rounded_error_rounds_and_words():
    assert cs.rounded_error(-1e-14, 12) == (0.0, "below $10^{-12}$")
    assert cs.rounded_error(0.000123, 4) == (0.0001, "0.0001")
    assert cs.rounded_error(2.4e-3, 3)[1] == "0.002"


def test_ellipsoid_normal_is_orthogonal_to_its_tangents():
    X, N = cs.ellipsoid_parametrisation([1.0, 1.25, 1.5, 1.75])
    w = np.random.default_rng(1).uniform(0.3, 1.3, (30, 3))
    h = 1e-6
    for i in range(3):
        e = np.zeros(3)
        e[i] = h
        tangent = (X(w + e) - X(w - e)) / (2 * h)
        assert np.abs(np.einsum("ka,ka->k", tangent, N(w))).max() < 1e-8
    assert np.allclose(np.sum((X(w) / [1.0, 1.25, 1.5, 1.75]) ** 2, axis=1), 1.0)
    assert np.all(np.einsum("ka,ka->k", X(w), N(w)) > 0)  # outward


@pytest.mark.parametrize("axes", [[1.0], [1.0, -2.0], [[1.0, 2.0]]])
def test_ellipsoid_refuses_bad_axes(axes):
    with pytest.raises(ValueError, match="semi-axes"):
        cs.ellipsoid_parametrisation(axes)


def test_hodge_dual_against_the_cross_product():
    sec = cs.hodge_dual_section()
    # *(e_i ∧ e_j) = e_i × e_j: e2 × e3 = e1, e1 × e3 = −e2, e2 × e1 = −e3
    assert sec.results["hodge_e2e3_component_1"] == np.cross([0, 1, 0], [0, 0, 1])[0] == 1
    assert sec.results["hodge_e1e3_component_2"] == np.cross([1, 0, 0], [0, 0, 1])[1] == -1
    assert sec.results["hodge_e2e1_component_3"] == np.cross([0, 1, 0], [1, 0, 0])[2] == -1
    assert sec.results["hodge_cross_product_max_err"] == 0.0
    assert "$*(e_2\\wedge e_1) = - e_3$" in sec.texts[0]


@pytest.mark.parametrize(("R", "r"), [(10.0, 5.0), (3.0, 1.0)])
def test_torus_shape_operator_agrees_with_section_3_4_1(R, r):
    sec = cs.torus_shape_operator_section(R=R, r=r)
    assert [sec.results[f"torus_{k}_disagreements"] for k in "SHK"] == [0, 0, 0]
    assert sec.results["torus_gauss_map_derivative_disagreements"] == 0
    assert sec.results["self_adjoint_n2_max_rel_asymmetry"] == sec.results["self_adjoint_n3_max_rel_asymmetry"] == 0.0


def test_gauss_image_ratio_tends_to_one():
    q = cs.gauss_image_section().results
    errors = [abs(q[f"eq33_gauss_image_ratio_eps_1e_{k}"] - 1) for k in (1, 2, 3)]
    assert errors[0] > errors[1] > errors[2] and errors[2] < 1e-4


def test_gauss_bonnet_on_caps_and_the_statement_of_eq_3_4(thesis):
    sec = cs.gauss_bonnet_caps_section(thesis)
    for p in (8, 13, 22):
        assert sec.results[f"thm35_cap_{p}_total_over_2pi"] == pytest.approx(1.0, abs=1e-7)
    assert sec.results["thm35_number_of_the_statement_with_eq_3_4"] == 3.5
    assert sec.results["thm35_a_theorem_3_4_exists"] is False
    assert sec.texts[0].count("\n| ") == 3


def test_turning_octant_and_hemisphere():
    sec = cs.turning_and_octant_section()
    assert sec.results == {"ex36_turning_over_2pi": 1.0, "eq37_octant_integral_K_over_formula": 1.0,
                           "ex37_hemisphere_integral_K_over_2pi": 1.0}
    assert "90.0000°, 90.0000°, 90.0000°" in sec.texts[0]  # the octant's three right angles


def test_flower_curve_is_non_convex_and_refuses_too_few_samples():
    curve = cs.flower_curve(n=500)
    rho = np.linalg.norm(curve, axis=1)
    assert rho.min() == pytest.approx(0.7, abs=1e-3) and rho.max() == pytest.approx(1.3)
    d1, d2 = np.roll(curve, -1, 0) - curve, curve - np.roll(curve, 1, 0)
    turn = d2[:, 0] * d1[:, 1] - d2[:, 1] * d1[:, 0]
    assert (turn > 0).any() and (turn < 0).any()  # turns both ways: non-convex
    with pytest.raises(ValueError, match="n must be >= 3"):
        cs.flower_curve(n=2)


def test_octant_quadrature_integrates_the_sphere_area_element():
    params, weights = cs.octant_quadrature(nodes=16)
    area = np.sum(weights * np.sin(params[:, 0]))  # dA = sin ψ dψ dφ on the unit sphere
    assert area == pytest.approx(4 * pi / 8, rel=1e-12)


def test_discrete_gauss_bonnet_against_igl():
    sec = cs.discrete_gauss_bonnet_section(n=30)
    V, F = torus_grid(30, R=10.0, r=5.0)
    P, G = sphere_hull(n_dims=3, n_points=500, seed=1)
    for mesh, (v, f) in (("torus_grid", (V, F)), ("sphere_hull", (P, G))):
        defect = igl.gaussian_curvature(np.ascontiguousarray(v, dtype=float), np.ascontiguousarray(f, dtype=np.int64))
        assert sec.results[f"thm38_{mesh}_defects_over_2pi"] == pytest.approx(defect.sum() / (2 * pi), abs=1e-9)
        assert sec.results[f"thm38_{mesh}_3F_minus_2E"] == 0
    assert sec.results["thm38_torus_grid_defects_over_2pi"] == 0.0
    assert sec.results["thm38_sphere_hull_defects_over_2pi"] == 2.0
    assert sec.results["thm38_torus_integral_K_below_1e_6"] is True
    assert sec.results["thm38_ellipsoid_integral_K_over_2pi"] == 2.0
    assert "torus grid 30 × 30" in sec.texts[0]


def test_area_variation_on_a_sphere_against_the_area_4_pi_rho_squared():
    rho = 3.0
    params, weights = hypersphere_quadrature(2, nodes=16)
    printed, with_h, minus_dA, n_int = cs.area_variation_ratios(
        lambda a: hypersphere_point(a, radius=rho), lambda a: hypersphere_point(a, radius=1.0),
        lambda a: np.ones(a.shape[:-1]), params, weights, 2)
    # moving along the outward normal at unit speed: A(t) = 4π(ρ + t)², so δA = 8πρ
    assert minus_dA == pytest.approx(-8 * pi * rho, rel=1e-8)
    assert n_int == pytest.approx(2 * 4 * pi * rho**2, rel=1e-10)
    assert printed == pytest.approx(-1 / rho, rel=1e-8)  # the printed form misses H = −1/ρ
    assert with_h == pytest.approx(1.0, rel=1e-8)


def test_variation_of_area_as_printed_and_with_h():
    sec = cs.variation_of_area_section()
    assert sec.results == {"thm39_disc_minus_dA_over_printed": 0.0, "thm39_sphere_minus_dA_over_printed": -0.5,
                           "thm39_sphere_minus_dA_over_with_H": 1.0, "thm39_ellipsoid_minus_dA_over_with_H": 1.0}
    assert "| — |" in sec.texts[0]  # the flat disc has H = 0


def test_gauss_map_pullback_sign_alternates():
    sec = cs.gauss_map_section()
    assert sec.results["sec32_gauss_map_sphere_dimension_n3"] == 3
    assert [sec.results[f"eq314_pullback_over_K_n{n}"] for n in (2, 3, 4)] == [(-1.0) ** n for n in (2, 3, 4)]


def test_gauss_bonnet_chern_constant_against_the_gamma_function():
    sec = cs.gauss_bonnet_chern_section(dims=(2, 4, 6))
    for n in (2, 4, 6):
        m = n // 2
        volume = 2 * pi ** ((n + 1) / 2) / gamma((n + 1) / 2)  # vol Sⁿ
        assert (volume / 2) / (pi**m * 2**n * factorial(m) / factorial(n)) == pytest.approx(1.0, rel=1e-12)
        assert sec.results[f"thm311_constant_ratio_n{n}"] == 1.0
    assert sec.results["thm311_ellipsoid4_integral_K_over_formula"] == pytest.approx(1.0, abs=1e-4)


def test_theorem_3_12_and_homogeneity():
    assert cs.theorem_3_12_section().results == {"thm312_ellipsoid3_minus_dA_over_n_int_lambda_H": 1.0,
                                                 "thm312_homogeneity_holds": True}


def test_mean_curvature_gradient_section():
    res = cs.mean_curvature_gradient_section().results
    assert res["eq316_fd_over_gradient_sum"] == 1.0
    assert res["eq318_coefficient"] == 1.0
    assert res["thm316_jacobi_max_rel_err"] == res["prop317_max_rel_err"] == 0.0
    assert res["ex320_coefficient"] == 1.0


def test_theorem_3_18_and_corollary_3_19():
    res = cs.theorem_3_18_section(dims=(2, 3, 4)).results
    assert res["thm318_proof_parallelotope_dimension_n3"] == 3
    assert res["thm318_proof_gram_equal_fraction"] == 1.0
    assert res["thm318_proof_printed_gram_equal_fraction"] == 0.0
    assert res["cor319_residual_below_1e_5"] is True
    assert res["cor319_coefficient_times_nfact_n2"] == 1.0  # n! = n(n − 1) for n = 2


def test_printed_height_is_one_over_n_minus_one_of_the_true_height():
    res = cs.corollary_height_section(dims=(2, 3, 4, 5)).results
    assert res == {f"cor319_printed_height_over_true_n{n}": round_sig(1 / (n - 1), 6) for n in (2, 3, 4, 5)}


def test_vector_norm_against_igl_cotangent_laplacian(sphere):
    points, faces = sphere
    res = cs.vector_norm_section(points, faces).results
    Lv = igl.cotmatrix(points, faces) @ points
    norm = np.linalg.norm(Lv, axis=1)
    assert res["sec331_norm_over_n_over_H"] == round_sig(float(np.median(norm / 2 / 0.5)), 4)
    area = vertex_areas(points, faces, area="voronoi")
    assert res["sec331_norm_over_n_area_over_H"] == round_sig(float(np.median(norm / (2 * area) / 0.5)), 4) == 1.0


def test_voronoi_regions_against_thales_and_exact_areas(thesis):
    res = cs.chapter_of_voronoi_section(thesis).results
    assert res["sec332_chapter_of_voronoi_regions"] == 2  # §3.3.2 says "Chapter 1"
    cloud = np.random.default_rng(2).uniform(-1.6, 1.6, (4000, 2))
    obtuse = np.einsum("ka,ka->k", [-1.0, 0.0] - cloud, [1.0, 0.0] - cloud) < 0
    inside = np.linalg.norm(cloud, axis=1) < 1
    assert res["fig32_obtuse_inside_fraction"] == obtuse[inside].mean() == 1.0
    assert res["fig32_obtuse_outside_fraction"] == obtuse[~inside].mean() == 0.0
    assert res["sec332_circumcentre_inside_fraction_nonobtuse"] == 1.0
    assert res["sec332_circumcentre_inside_fraction_obtuse"] == 0.0
    assert res["sec332_formula_exact_fraction_nonobtuse"] == 1.0
    assert res["sec332_formula_exact_fraction_obtuse"] == 0.0


def test_defect_over_voronoi_area_against_igl(sphere):
    points, faces = sphere
    res = cs.voronoi_area_section(points, faces).results
    defect = igl.gaussian_curvature(points, faces)
    expected = round_sig(float(np.median(defect / vertex_areas(points, faces, area="voronoi"))), 4)
    assert res["eq320_defect_over_voronoi_area_sphere_r2"] == expected == pytest.approx(0.25, abs=2e-3)
    # the coordinate planes are planes of symmetry: the octant's edges are geodesics meeting at right angles
    assert res["eq319_ellipsoid_octant_integral_K_over_formula"] == 1.0


def test_shape_operator_section(sphere):
    points, faces = sphere
    sec = cs.shape_operator_section(points, faces)
    res = sec.results
    assert res["eq323_integral_over_k1_plus_k2"] == round_sig(pi, 6)
    # at (0, 0) the principal curvatures are −cos v/(R + r cos v) = −1/15 and −1/r = −1/5
    assert res["def33_max_abs_normal_curvature_torus_00"] == round_sig(1 / 5, 6)
    assert res["def33_extremes_minus_eigenvalues_max_err"] == 0.0
    assert res["eq324_formula_on_sphere_r2"] == pytest.approx(2.0, rel=1e-6)  # the radius, not the curvature
    assert res["sec334_weights_sum_over_voronoi_area_max_err"] == 0.0
    assert res["sec334_printed_sum_min_gradient"] >= 1 / np.sqrt(2)
    assert res["sec334_printed_sum_has_minimiser"] is False


def test_sphere_region_against_monte_carlo():
    sec = cs.sphere_region_section()
    assert sec.results["sec342_sphere_H_disagreements"] == 0
    assert sec.results["sec342_corner_region_volume"] == round_sig(5 / 48, 10)
    corners = np.eye(4)[:, 1:]  # (0,0,0), e₁, e₂, e₃
    weights = np.random.default_rng(0).dirichlet(np.ones(4), 200_000)
    x = weights @ corners
    nearest = np.argmin(np.linalg.norm(x[:, None, :] - corners[None], axis=2), axis=1)
    assert np.mean(nearest == 0) == pytest.approx(sec.results["sec342_corner_region_share"], abs=5e-3)
    assert sec.glued == {"corner_volume_48": "5"}


def test_catenoids_are_minimal():
    res = cs.catenoid_section(dims=(2, 3, 4)).results
    assert all(res[f"catenoid_n{n}_{k}"] == 0 for n in (2, 3, 4) for k in ("H_nonzero", "kappa_disagreements"))


def test_torus_experiment_glue_formats_the_stored_results():
    tc = load("torus-curvature")
    sec = cs.torus_experiment_glue(tc)
    assert sec.glued["tc_crust_grid_max_rel_err_H_voronoi"] == f"{tc['crust_grid_max_rel_err_H_voronoi']:.2g}"
    assert sec.glued["tc_crust_grid_fixed_diagonal_fraction"] == f"{100 * tc['crust_grid_fixed_diagonal_fraction']:.0f}"
    assert sec.glued["tc_z_1000"] == f"{tc['random_1000_outer_inner_z']:.3g}"
    gain = tc["random_1000_outer_inner_z"] - tc["random_100_outer_inner_z"]
    assert sec.results["fig310_z_gain_1000_over_100"] == round_sig(gain, 3)
    assert len(sec.glued) == 11 + 1 + 4 + 15 + 2
    with pytest.raises(ValueError, match="lack.*exact_outer_inner_ratio"):
        cs.torus_experiment_glue({k: v for k, v in tc.items() if k != "exact_outer_inner_ratio"})


def test_hypersurface_experiment_glue():
    hs = load("hypersurfaces")
    glued = cs.hypersurface_experiment_glue(hs).glued
    assert glued["hs_sphere_grid_H_min"] == f"{hs['sphere_grid_H_min']:.4f}"
    assert glued["hs_cloud_H_median"] == f"{hs['cloud_H_median']:.2g}"
    assert len(glued) == 12
    with pytest.raises(ValueError, match="hypersurfaces"):
        cs.hypersurface_experiment_glue({})


@pytest.mark.parametrize(("call", "match"), [
    (lambda: cs.rounded_error(0.1, -1), "digits must be >= 0"),
    (lambda: cs.octant_quadrature(nodes=0), "nodes must be >= 1"),
    (lambda: cs.torus_shape_operator_section(R=5.0, r=5.0), "r < R"),
    (lambda: cs.torus_shape_operator_section(R=10.0, r=-1.0), "r must be positive"),
    (lambda: cs.discrete_gauss_bonnet_section(n=2), "n must be >= 3"),
    (lambda: cs.gauss_image_section(radii=(0.1, 0.0)), "radii must be positive"),
    (lambda: cs.gauss_bonnet_caps_section("no equation here"), "does not occur"),
    (lambda: cs.gauss_bonnet_caps_section("Theorem 3.5. = 2\\pi \\quad (3.4)", psi0=(-1.0,)), "psi0 must be positive"),
    (lambda: cs.gauss_bonnet_chern_section(dims=(2, 3)), "even dimensions"),
    (lambda: cs.gauss_bonnet_chern_section(dims=()), "even dimensions"),
    (lambda: cs.theorem_3_18_section(dims=(1,)), "dims must be >= 2"),
    (lambda: cs.corollary_height_section(dims=()), "dimensions >= 2"),
    (lambda: cs.catenoid_section(dims=(1,)), "dims must be >= 2"),
    (lambda: cs.vector_norm_section(np.eye(3), np.array([[0, 1, 2]]), H=0.0), "H must be positive"),
])
def test_bad_options_are_refused(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_non_integer_dimensions_are_refused():
    with pytest.raises(TypeError, match="dims must be an integer"):
        cs.theorem_3_18_section(dims=(2.5,))
    with pytest.raises(TypeError, match="seed"):
        cs.catenoid_section(seed="x")

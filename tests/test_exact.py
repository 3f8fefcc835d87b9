"""Exact references of §3.4: torus, hypersphere, n-catenoid (thesis_lib.surfaces)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib import surfaces
from thesis_lib.surfaces import (
    catenoid_mean_curvature,
    catenoid_point,
    catenoid_principal_curvatures,
    hypersphere_mean_curvature,
    hypersphere_point,
    hypersurface_normal,
    parametric_shape_operator,
    torus_gaussian_curvature,
    torus_gaussian_curvature_at,
    torus_mean_curvature,
    torus_mean_curvature_at,
    torus_point,
    torus_principal_curvatures,
    torus_principal_curvatures_at,
    torus_shape_operator,
    torus_uv,
)

angle = st.floats(0, 2 * np.pi, allow_nan=False)


def test_torus_values_at_known_points():
    R, r = 10.0, 5.0
    # outer equator v = 0: κ = -1/15, -1/5; inner equator v = π: κ = +1/5, -1/5
    assert np.allclose(torus_principal_curvatures(0.0, 0.0, R=R, r=r), [-0.2, -1 / 15])
    assert np.isclose(torus_mean_curvature(0.0, 0.0, R=R, r=r), -(1 / 15 + 1 / 5) / 2)
    assert np.isclose(torus_gaussian_curvature(0.0, 0.0, R=R, r=r), 1 / 75)
    assert np.isclose(torus_mean_curvature(1.0, np.pi, R=R, r=r), 0.0)  # R + 2r cos v = 0
    assert np.isclose(torus_gaussian_curvature(1.0, np.pi / 2, R=R, r=r), 0.0)
    assert np.allclose(torus_point(0.0, 0.0, R=R, r=r), [15, 0, 0])


@settings(deadline=None, max_examples=25)
@given(u=angle, v=angle)
def test_torus_closed_forms_match_trace_det_and_numerics(u, v):
    R, r = 10.0, 5.0
    S = torus_shape_operator(u, v, R=R, r=r)
    assert np.isclose(np.trace(S) / 2, torus_mean_curvature(u, v, R=R, r=r))
    assert np.isclose(np.linalg.det(S), torus_gaussian_curvature(u, v, R=R, r=r))
    Sn = parametric_shape_operator(lambda w: torus_point(w[..., 0], w[..., 1], R=R, r=r), np.array([u, v]))
    assert np.allclose(Sn, S, atol=1e-6)
    uu, vv = torus_uv(torus_point(u, v, R=R, r=r), R=R, r=r)
    assert np.isclose(np.cos(uu), np.cos(u)) and np.isclose(np.sin(vv), np.sin(v), atol=1e-12)
    assert np.isclose(torus_mean_curvature_at(torus_point(u, v, R=R, r=r), R=R, r=r),
                      torus_mean_curvature(u, v, R=R, r=r))
    k = torus_principal_curvatures_at(torus_point(u, v, R=R, r=r), R=R, r=r)
    assert np.allclose(k, np.sort(np.linalg.eigvals(S).real)) and k[0] <= k[1]
    assert np.isclose(
        torus_gaussian_curvature_at(torus_point(u, v, R=R, r=r), R=R, r=r), torus_gaussian_curvature(u, v, R=R, r=r)
    )


def test_torus_gauss_bonnet_numerically():
    # ∫ K dA = 2πχ = 0, dA = r (R + r cos v) du dv
    R, r = 10.0, 5.0
    v = np.linspace(0, 2 * np.pi, 2001)[:-1]
    integrand = torus_gaussian_curvature(0.0, v, R=R, r=r) * r * (R + r * np.cos(v))
    assert abs(integrand.sum() * (2 * np.pi / 2000) * 2 * np.pi) < 1e-10


def test_hypersphere_points_and_curvature():
    w = np.random.default_rng(0).uniform(0, np.pi, (50, 3))
    x = hypersphere_point(w, radius=2.0)
    assert np.allclose(np.linalg.norm(x, axis=1), 2.0)
    assert np.allclose(hypersphere_point(np.array([0.0, 1.0, 2.0]), radius=2.0), [2, 0, 0, 0])
    S = parametric_shape_operator(lambda a: hypersphere_point(a, radius=2.0), np.array([0.7, 1.1, 0.3]))
    assert np.allclose(np.abs(np.diag(S)), 0.5, atol=1e-6)
    assert hypersphere_mean_curvature(radius=2.0) == 0.5


@pytest.mark.parametrize("n", [2, 3, 4])
def test_catenoid_is_minimal(n):
    w = np.random.default_rng(n).uniform(-1, 1, (5, n))
    assert np.allclose(catenoid_mean_curvature(w), 0.0)
    for p in w:
        S = parametric_shape_operator(catenoid_point, p)
        k = catenoid_principal_curvatures(p)
        sign = 1.0 if n == 2 else np.sign(S[0, 0] * k[0])  # orientation of N depends on n
        assert np.allclose(np.diag(S), sign * k, atol=1e-6)
        assert np.allclose(S - np.diag(np.diag(S)), 0, atol=1e-6)
        assert abs(np.trace(S)) < 1e-6


def test_normal_matches_cross_product_and_orientation():
    J = np.random.default_rng(1).normal(size=(10, 3, 2))
    N = hypersurface_normal(J)
    c = np.cross(J[:, :, 0], J[:, :, 1])
    assert np.allclose(N, c / np.linalg.norm(c, axis=1, keepdims=True))
    J4 = np.random.default_rng(2).normal(size=(10, 4, 3))
    N4 = hypersurface_normal(J4)
    assert np.allclose(np.einsum("mki,mk->mi", J4, N4), 0, atol=1e-12)
    assert np.all(np.linalg.det(np.concatenate([J4, N4[..., None]], axis=2)) > 0)


def test_bad_input():
    with pytest.raises(ValueError, match="0 < r < R"):
        torus_point(0, 0, R=5, r=5)
    with pytest.raises(ValueError, match="NaN"):
        torus_mean_curvature(np.nan, 0.0)
    with pytest.raises(ValueError, match="shape"):
        torus_uv(np.zeros((4, 2)))
    with pytest.raises(ValueError, match="radius"):
        hypersphere_point([0.1, 0.2], radius=-1)
    with pytest.raises(ValueError, match="n >= 2"):
        catenoid_point(np.zeros((3, 1)))
    with pytest.raises(ValueError, match="regular"):
        hypersurface_normal(np.zeros((3, 2)))
    with pytest.raises(ValueError, match="shape"):
        hypersurface_normal(np.zeros((3, 3)))


def test_relative_error_leaves_out_zeros():
    from thesis_lib.chapters.torus_study import relative_error

    exact = np.array([0.0, 1.0, -2.0, 1e-9])
    est = np.array([0.1, 1.1, 1.8, 0.0])
    e = relative_error(est, exact, zero_tol=1e-3)
    assert np.isnan(e[0]) and np.isnan(e[3])
    assert np.allclose(e[1:3], [0.1, 1.9])  # |est - exact| / |exact|
    with pytest.raises(ValueError, match="shape"):
        relative_error(est[:2], exact)
    with pytest.raises(ValueError, match="zero_tol"):
        relative_error(est, exact, zero_tol=2.0)


# ------------------------------------------------ references for the chapter 3 report rows
from math import gamma  # noqa: E402

from thesis_lib.surfaces import (  # noqa: E402
    ellipsoid_point,
    fundamental_forms,
    gauss_bonnet_chern_constant,
    hypersphere_quadrature,
    hypersphere_volume,
    normal_curvature_circle,
    torus_outer_inner_ratio,
    total_gauss_kronecker_curvature,
)


def test_outer_inner_ratio_closed_form_and_brute_force():
    # R = 2r: (π + 2)(π − 1) / ((π + 1)(π − 2))
    closed_form = (np.pi + 2) * (np.pi - 1) / ((np.pi + 1) * (np.pi - 2))
    assert torus_outer_inner_ratio(R=10.0, r=5.0) == pytest.approx(closed_form, rel=1e-12)
    for R, r in [(10.0, 5.0), (10.0, 7.0), (3.0, 1.0)]:  # R < 2r: H changes sign on the inner half
        v = (np.arange(200000) + 0.5) * 2 * np.pi / 200000
        h = np.abs(torus_mean_curvature(0.0, v, R=R, r=r))
        area = R + r * np.cos(v)
        outer = np.cos(v) > 0
        mean_outer = np.sum(h[outer] * area[outer]) / area[outer].sum()
        brute = mean_outer / (np.sum(h[~outer] * area[~outer]) / area[~outer].sum())
        assert torus_outer_inner_ratio(R=R, r=r) == pytest.approx(brute, rel=1e-8)
    with pytest.raises(ValueError, match="radii"):
        torus_outer_inner_ratio(R=1.0, r=2.0)


@pytest.mark.parametrize("n", range(1, 9))
def test_hypersphere_volume_and_the_constant_of_theorem_3_11(n):
    assert hypersphere_volume(n) == pytest.approx(2 * np.pi ** ((n + 1) / 2) / gamma((n + 1) / 2), rel=1e-12)
    if n % 2 == 0:
        assert gauss_bonnet_chern_constant(n) == pytest.approx(hypersphere_volume(n) / 2, rel=1e-12)
    else:
        with pytest.raises(ValueError, match="even"):
            gauss_bonnet_chern_constant(n)


def test_hypersphere_quadrature_integrates_the_volume_element():
    for n in (2, 3, 4):
        params, weights = hypersphere_quadrature(n, nodes=12)
        assert weights.sum() == pytest.approx(np.pi ** (n - 1) * 2 * np.pi, rel=1e-12)
        element = np.prod([np.sin(params[:, k]) ** (n - 1 - k) for k in range(n - 1)], axis=0)
        assert np.sum(weights * element) == pytest.approx(hypersphere_volume(n), rel=1e-10)
    with pytest.raises(ValueError, match="nodes"):
        hypersphere_quadrature(2, nodes=1)


def test_ellipsoid_points_satisfy_the_equation():
    axes = np.array([1.0, 1.5, 2.0, 2.5])
    x = ellipsoid_point(np.random.default_rng(0).uniform(0, np.pi, (50, 3)), axes)
    assert np.allclose(np.sum((x / axes) ** 2, axis=1), 1.0)
    with pytest.raises(ValueError, match="semi-axes"):
        ellipsoid_point(np.zeros((2, 3)), [1.0, 2.0])
    with pytest.raises(ValueError, match="positive"):
        ellipsoid_point(np.zeros((2, 2)), [1.0, -2.0, 1.0])


@pytest.mark.parametrize(
    "n, axes, nodes, rtol",
    [(2, [1.0, 1.5, 2.0], 24, 1e-5), (4, [1.0, 1.1, 1.2, 1.1, 1.0], 10, 1e-4), (4, [2.0] * 5, 12, 1e-6)],
)
def test_gauss_bonnet_chern_on_ellipsoids(n, axes, nodes, rtol):
    params, weights = hypersphere_quadrature(n, nodes=nodes)
    total = total_gauss_kronecker_curvature(lambda a: ellipsoid_point(a, axes), params, weights)
    assert total == pytest.approx(gauss_bonnet_chern_constant(n) * 2, rel=rtol)  # χ(S^n) = 2


def test_gauss_bonnet_on_the_torus_and_fundamental_forms():
    t = 2 * np.pi * np.arange(120) / 120
    uv = np.stack(np.meshgrid(t, t, indexing="ij"), -1).reshape(-1, 2)
    X = lambda w: torus_point(w[..., 0], w[..., 1], R=10.0, r=5.0)  # noqa: E731
    total = total_gauss_kronecker_curvature(X, uv, np.full(len(uv), (2 * np.pi / 120) ** 2))
    assert abs(total) < 1e-6  # χ(torus) = 0
    g, B = fundamental_forms(X, uv[:5])
    v = uv[:5, 1]
    assert np.allclose(g[:, 0, 0], (10 + 5 * np.cos(v)) ** 2, rtol=1e-7)
    assert np.allclose(g[:, 1, 1], 25.0, rtol=1e-7) and np.allclose(g[:, 0, 1], 0.0, atol=1e-7)
    with pytest.raises(ValueError, match="weights"):
        total_gauss_kronecker_curvature(X, uv, np.ones(3))


@settings(deadline=None, max_examples=20)
@given(angle, angle)
def test_normal_curvature_circle_extremes_and_mean(u, v):
    X = lambda w: torus_point(w[..., 0], w[..., 1], R=10.0, r=5.0)  # noqa: E731
    kn = normal_curvature_circle(X, np.array([u, v]), nodes=64)
    k1, k2 = torus_principal_curvatures(u, v)
    # X_u ⊥ X_v, so θ = 0 and θ = π/2 (nodes 0 and 16) are the principal directions
    assert sorted([kn[0], kn[16]]) == pytest.approx([k1, k2], abs=1e-6)
    assert kn.min() == pytest.approx(k1, abs=1e-6) and kn.max() == pytest.approx(k2, abs=1e-6)
    assert kn.mean() == pytest.approx(float(torus_mean_curvature(u, v)), abs=1e-6)  # eq. (3.23)
    assert 2 * np.pi * kn.mean() == pytest.approx(np.pi * (k1 + k2), abs=1e-5)


def test_normal_curvature_circle_needs_a_surface():
    with pytest.raises(ValueError, match="n = 2"):
        normal_curvature_circle(lambda a: hypersphere_point(a, radius=1.0), np.array([0.5, 0.6, 0.7]))
    with pytest.raises(ValueError, match="nodes"):
        normal_curvature_circle(lambda w: torus_point(w[..., 0], w[..., 1]), np.array([0.1, 0.2]), nodes=2)


@pytest.mark.parametrize("call, message", [
    (lambda: surfaces.hypersphere_point([[0.0, 0.0]], radius=-1.0), r"^radius must be positive, got -1\.0$"),
    (lambda: surfaces.hypersphere_point([[0.0, 0.0]], radius="1"), r"^radius must be a number, got '1'$"),
    (lambda: surfaces.hypersphere_mean_curvature(radius=0.0), r"^radius must be positive, got 0\.0$"),
    (lambda: surfaces.torus_uv([[1.0, 0.0]]), r"^points must have shape \(\.\.\., 3\), got \(1, 2\)$"),
    (lambda: surfaces.torus_uv([[1.0, 0.0, np.nan]]), r"^points contains NaN or infinite values$"),
    (lambda: surfaces.fundamental_forms(surfaces.catenoid_point, [[0.1, 0.2]], h=0.0),
     r"^h must be positive, got 0\.0$"),
])
def test_surface_arguments_are_refused_by_name(call, message):
    with pytest.raises(ValueError, match=message):
        call()

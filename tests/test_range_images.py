"""Tests of thesis_lib.applications.range_images: synthetic range images and the Adams–Carlsson patch
pipeline (§2.4.3)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.applications.range_images import (
    contrast_norm,
    dct_basis,
    dct_basis_5x5,
    density_filter,
    gradient_projection,
    high_contrast,
    kth_neighbour_distance,
    normalise,
    patches,
    range_patch_space,
    sample_patches,
    synthetic_range_image,
)


# ----------------------------------------------------------------------------- ray caster
def test_synthetic_image_is_deterministic_and_plausible():
    a = synthetic_range_image(seed=3, size=(48, 64))
    b = synthetic_range_image(seed=3, size=(48, 64))
    assert a.shape == (48, 64)
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, synthetic_range_image(seed=4, size=(48, 64)), equal_nan=True)
    finite = a[np.isfinite(a)]
    assert finite.size > 0.3 * a.size
    assert finite.min() > 0 and finite.max() <= 60.0
    # The sky (top row centre) is out of range unless an object is there; the bottom row is ground.
    assert np.all(np.isfinite(a[-1]))


def test_empty_scene_is_ground_with_exact_ranges():
    h, w = 41, 41
    img = synthetic_range_image(seed=0, size=(h, w), n_boxes=0, n_cylinders=0, n_spheres=0, n_rocks=0,
                                fov_degrees=40.0, camera_height=2.0, max_range=1e9, min_grazing_degrees=0.0, noise=0.0)
    # Only the ground: every pixel below the horizon has range = height / sin(depression angle).
    rows = np.isfinite(img).any(axis=1)
    assert rows[-1] and not rows[0]
    # Recompute the ray of the bottom centre pixel from the camera model with the same seed's rotation.
    rng = np.random.default_rng(0)
    _yaw, pitch = rng.uniform(-0.3, 0.3), rng.uniform(-0.12, 0.05)  # draw yaw too: same stream as the scene
    focal = 0.5 * w / np.tan(np.radians(40.0) / 2)
    d = np.array([0.0, -((h - 1) / 2) / focal, 1.0])
    d /= np.linalg.norm(d)
    cp, sp = np.cos(pitch), np.sin(pitch)
    dy = cp * d[1] - sp * d[2]  # pitch about x, the y component (yaw does not change it)
    np.testing.assert_allclose(img[-1, (w - 1) // 2], 2.0 / -dy, rtol=1e-9)


def test_sphere_in_front_of_camera_distance():
    # A scene with one sphere straight ahead: check against the analytic distance via the private helper.
    from thesis_lib.applications.range_images import _hit_sphere

    orig = np.zeros(3)
    dirs = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]])
    t = _hit_sphere(orig, dirs, np.array([0.0, 0.0, 10.0]), 2.0)
    np.testing.assert_allclose(t, [8.0, np.inf])


def test_synthetic_image_bad_input():
    with pytest.raises(ValueError, match="size"):
        synthetic_range_image(seed=0, size=(0, 10))
    with pytest.raises(ValueError, match="size"):
        synthetic_range_image(seed=0, size=(10,))
    with pytest.raises(ValueError, match="n_spheres"):
        synthetic_range_image(seed=0, n_spheres=-1)
    with pytest.raises(ValueError, match="fov"):
        synthetic_range_image(seed=0, fov_degrees=180)
    with pytest.raises(ValueError, match="noise"):
        synthetic_range_image(seed=0, noise=np.nan)
    with pytest.raises(ValueError, match="max_range"):
        synthetic_range_image(seed=0, max_range=-1.0)


# ----------------------------------------------------------------------------- patches
def test_patches_shapes_log_and_nan_removal():
    img = np.arange(1, 1 + 6 * 7, dtype=float).reshape(6, 7)
    P = patches(img, size=5)
    assert P.shape == ((6 - 4) * (7 - 4), 25)
    np.testing.assert_allclose(P[0], np.log(img[:5, :5]).ravel())
    np.testing.assert_allclose(P[-1], np.log(img[1:, 2:]).ravel())
    raw = patches(img, size=3, log=False)
    assert raw.shape == (4 * 5, 9)
    np.testing.assert_array_equal(raw[1], img[:3, 1:4].ravel())
    img[0, 0] = np.nan
    assert patches(img, size=5).shape[0] == 5  # the one patch touching (0, 0) is gone
    img[5, 6] = 0.0  # non-positive range has no logarithm
    assert patches(img, size=5).shape[0] == 4


def test_patches_bad_input():
    with pytest.raises(ValueError, match="2-D"):
        patches(np.ones(10), size=5)
    with pytest.raises(ValueError, match="smaller"):
        patches(np.ones((4, 10)), size=5)
    with pytest.raises(ValueError, match="patch size"):
        patches(np.ones((10, 10)), size=1)
    with pytest.raises(ValueError, match="infinite"):
        patches(np.full((10, 10), np.inf), size=5)


def test_sample_patches():
    imgs = [synthetic_range_image(seed=s, size=(32, 40)) for s in range(3)]
    pool = np.concatenate([patches(im) for im in imgs])
    S = sample_patches(imgs, n=100, seed=1)
    assert S.shape == (100, 25)
    np.testing.assert_array_equal(S, sample_patches(imgs, n=100, seed=1))
    # The same rows as drawing from the concatenated pool of all patches.
    idx = np.sort(np.random.default_rng(1).choice(pool.shape[0], size=100, replace=False))
    np.testing.assert_array_equal(S, pool[idx])
    raw = sample_patches(imgs, n=50, size=3, seed=2, log=False)
    pool3 = np.concatenate([patches(im, size=3, log=False) for im in imgs])
    idx3 = np.sort(np.random.default_rng(2).choice(pool3.shape[0], size=50, replace=False))
    np.testing.assert_array_equal(raw, pool3[idx3])
    with pytest.raises(ValueError, match="only"):
        sample_patches(imgs, n=pool.shape[0] + 1)
    with pytest.raises(ValueError, match="no images"):
        sample_patches([], n=10)
    with pytest.raises(ValueError, match="^n must be >= 1, got 0$"):
        sample_patches(imgs, n=0)


# ----------------------------------------------------------------------------- contrast and normalisation
def test_contrast_norm_against_laplacian_quadratic_form():
    rng = np.random.default_rng(0)
    X = rng.normal(size=(50, 25))
    # Graph Laplacian of the 5x5 4-neighbour grid: ||x||_D^2 = x^T D x.
    D = np.zeros((25, 25))
    for i in range(5):
        for j in range(5):
            for di, dj in ((0, 1), (1, 0)):
                if i + di < 5 and j + dj < 5:
                    a, b = 5 * i + j, 5 * (i + di) + (j + dj)
                    D[a, a] += 1
                    D[b, b] += 1
                    D[a, b] -= 1
                    D[b, a] -= 1
    np.testing.assert_allclose(contrast_norm(X) ** 2, np.einsum("ni,ij,nj->n", X, D, X))
    # A unit step across the middle of a 3x3 patch crosses 3 neighbour pairs: D-norm sqrt(3).
    step = np.array([[0, 0, 1]] * 3, dtype=float).ravel()
    np.testing.assert_allclose(contrast_norm(step[None]), [np.sqrt(3)])
    np.testing.assert_allclose(contrast_norm(np.ones((2, 9)) * 7), [0, 0])


def test_high_contrast_keeps_the_top_fraction():
    rng = np.random.default_rng(1)
    X = rng.normal(size=(200, 25)) * rng.uniform(0.1, 2, size=(200, 1))
    H = high_contrast(X, top=0.2)
    assert H.shape == (40, 25)
    d = contrast_norm(X)
    assert contrast_norm(H).min() >= np.sort(d)[-40] - 1e-12
    assert high_contrast(X, top=1.0).shape == X.shape
    with pytest.raises(ValueError, match="fraction"):
        high_contrast(X, top=0.0)
    with pytest.raises(ValueError, match="square"):
        high_contrast(np.ones((3, 24)))


def test_normalise_unit_norm_zero_mean():
    rng = np.random.default_rng(2)
    X = rng.normal(size=(100, 25)) + 5
    N = normalise(X)
    np.testing.assert_allclose(N.mean(axis=1), 0, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(N, axis=1), 1, atol=1e-12)
    # Shift and positive scale invariant.
    np.testing.assert_allclose(normalise(3 * X - 2), N, atol=1e-12)
    with pytest.raises(ValueError, match="constant"):
        normalise(np.vstack([X[:2], np.full(25, 4.0)]))
    with pytest.raises(ValueError, match="NaN"):
        normalise(np.full((2, 25), np.nan))


# ----------------------------------------------------------------------------- density
@settings(deadline=None, max_examples=15)
@given(st.integers(0, 10_000), st.integers(1, 8))
def test_kth_neighbour_against_brute_force(seed, k):
    X = np.random.default_rng(seed).normal(size=(40, 3))
    D = np.linalg.norm(X[:, None] - X[None], axis=2)
    brute = np.sort(D, axis=1)[:, k]  # column 0 is the point itself
    np.testing.assert_allclose(kth_neighbour_distance(X, k=k), brute)


@settings(deadline=None, max_examples=10)
@given(st.integers(0, 10_000), st.integers(1, 30))
def test_kth_neighbour_high_dimension_against_brute_force(seed, k):
    X = np.random.default_rng(seed).normal(size=(120, 25))
    X[5] = X[7]  # a duplicate: its nearest other point is at distance 0
    D = np.linalg.norm(X[:, None] - X[None], axis=2)
    np.fill_diagonal(D, -1.0)
    brute = np.sort(D, axis=1)[:, k]
    np.testing.assert_allclose(kth_neighbour_distance(X, k=k), brute, rtol=1e-12, atol=1e-12)
    assert kth_neighbour_distance(X, k=1)[5] == 0.0


def test_density_filter_keeps_densest_in_brute_force_order():
    rng = np.random.default_rng(3)
    X = np.vstack([rng.normal(scale=0.05, size=(30, 2)), rng.normal(scale=2.0, size=(70, 2))])
    D = np.linalg.norm(X[:, None] - X[None], axis=2)
    rho = np.sort(D, axis=1)[:, 5]
    Y, idx = density_filter(X, k=5, percent=30, return_index=True)
    assert Y.shape == (30, 2)
    np.testing.assert_array_equal(idx, np.sort(np.argsort(rho, kind="stable")[:30]))
    np.testing.assert_array_equal(Y, X[idx])
    assert rho[idx].max() <= np.delete(rho, idx).min()
    assert set(idx.tolist()) == set(range(30))  # the tight cluster
    with pytest.raises(ValueError, match="percentage"):
        density_filter(X, k=5, percent=0)
    with pytest.raises(ValueError, match="k ="):
        density_filter(X, k=100, percent=30)
    with pytest.raises(ValueError, match="^k must be >= 1, got 0$"):
        density_filter(X, k=0, percent=30)
    with pytest.raises(ValueError, match="NaN"):
        density_filter(np.full((5, 2), np.nan), k=1, percent=30)
    with pytest.raises(TypeError, match="percent"):
        density_filter(X, k=5)
    with pytest.raises(TypeError, match="'p'"):  # p is not the percentage's name
        density_filter(X, k=5, percent=30, p=30)
    with pytest.raises(ValueError, match="percentage"):
        density_filter(X, k=5, percent=True)


# ----------------------------------------------------------------------------- DCT
def test_dct_basis_orthonormal_and_gradients():
    B = dct_basis_5x5()
    assert B.shape == (25, 25)
    np.testing.assert_allclose(B @ B.T, np.eye(25), atol=1e-12)
    np.testing.assert_allclose(B[0], np.full(25, 0.2))
    horizontal = B[1].reshape(5, 5)
    vertical = B[5].reshape(5, 5)
    assert np.allclose(horizontal, horizontal[0])  # the same in every row: varies along x
    assert np.allclose(vertical.T, vertical[:, 0])  # the same in every column: varies along y
    # c_0 (x) c_1 with c_0 = sqrt(1/5) and c_1(m) = sqrt(2/5) cos(pi (2m+1) / 10), decreasing.
    c1 = np.sqrt(2 / 5) * np.cos(np.pi * (2 * np.arange(5) + 1) / 10)
    np.testing.assert_allclose(horizontal[0], np.sqrt(1 / 5) * c1)
    np.testing.assert_allclose(dct_basis(size=3) @ dct_basis(size=3).T, np.eye(9), atol=1e-12)


def test_gradient_projection_of_pure_gradients_and_steps():
    B = dct_basis_5x5()
    proj = gradient_projection(np.vstack([B[1], B[5], -B[1], (B[1] + B[5]) / np.sqrt(2)]))
    np.testing.assert_allclose(proj, [[1, 0], [0, 1], [-1, 0], [np.sqrt(0.5), np.sqrt(0.5)]], atol=1e-12)
    # A vertical step edge (left low, right high) projects onto the negative horizontal axis,
    # because c_1 decreases along the row.
    step = normalise(np.tile([0, 0, 0, 1, 1], 5)[None].astype(float))
    p = gradient_projection(step)[0]
    assert p[0] < -0.8 and abs(p[1]) < 1e-12
    assert np.linalg.norm(p) <= 1 + 1e-12


def test_pipeline_on_small_synthetic_images():
    imgs = [synthetic_range_image(seed=s, size=(48, 64)) for s in range(4)]
    out = range_patch_space(imgs, n_patches=2000, k=10, percent=30, seed=0)
    default = range_patch_space(imgs, n_patches=2000, k=10, seed=0)  # percent 30 by default
    np.testing.assert_array_equal(default["dense"], out["dense"])
    assert out["patches"].shape == (2000, 25)
    assert out["high"].shape == (400, 25)
    assert out["dense"].shape == (120, 25)
    np.testing.assert_allclose(np.linalg.norm(out["dense"], axis=1), 1)
    np.testing.assert_allclose(out["dense"].sum(axis=1), 0, atol=1e-10)
    proj = gradient_projection(out["dense"])
    assert np.all(np.linalg.norm(proj, axis=1) <= 1 + 1e-9)


def test_grazing_ground_is_out_of_range_and_rocks_change_the_scene():
    kw = dict(size=(60, 80), n_boxes=0, n_cylinders=0, n_spheres=0, n_rocks=0, noise=0.0, max_range=1e9)
    flat = synthetic_range_image(seed=5, min_grazing_degrees=0.0, **kw)
    cut = synthetic_range_image(seed=5, min_grazing_degrees=8.0, **kw)
    lost = np.isfinite(flat) & np.isnan(cut)
    assert lost.any()
    # Only the farthest ground (near the horizon) is lost; what is kept is unchanged.
    assert np.nanmin(flat[lost]) > np.nanmax(cut)
    np.testing.assert_array_equal(cut[np.isfinite(cut)], flat[np.isfinite(cut)])
    rocks = synthetic_range_image(seed=5, min_grazing_degrees=0.0, **{**kw, "n_rocks": 10})
    both = np.isfinite(rocks) & np.isfinite(flat)
    assert np.any(rocks[both] < flat[both])  # rocks occlude some ground ...
    assert np.all(rocks[both] <= flat[both])  # ... and never make anything farther
    with pytest.raises(ValueError, match="min_grazing"):
        synthetic_range_image(seed=0, min_grazing_degrees=90)
    with pytest.raises(ValueError, match="n_rocks"):
        synthetic_range_image(seed=0, n_rocks=1.5)


@pytest.mark.parametrize("options, message", [
    ({"n_boxes": -1}, r"^n_boxes must be >= 0, got -1$"),
    ({"n_spheres": 1.5}, r"^n_spheres must be an integer"),
    ({"camera_height": 0.0}, r"^camera_height must be positive, got 0\.0$"),
    ({"max_range": np.inf}, r"^max_range must be finite, got inf$"),
    ({"noise": -0.1}, r"^noise must be >= 0\.0, got -0\.1$"),
    ({"noise": "0.1"}, r"^noise must be a number, got '0\.1'$"),
])
def test_scene_options_are_refused_by_name(options, message):
    with pytest.raises(ValueError, match=message):
        synthetic_range_image(seed=0, size=(8, 8), **options)

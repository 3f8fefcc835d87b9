"""Curvature of point clouds: the k-neighbourhood least-squares shape operator (§3.3.4) and the
Crust-based estimators of §3.3, on surfaces with exact curvature."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from thesis_lib.curvature.point_curvature import point_curvature
from thesis_lib.curvature.pointcloud import knn_curvature, knn_shape_operator
from thesis_lib.meshes import sample_sphere, sample_torus
from thesis_lib.surfaces import torus_gaussian_curvature_at, torus_mean_curvature_at


@pytest.mark.parametrize("dim, tol", [(2, 0.15), (3, 0.05), (4, 0.05)])
def test_knn_mean_curvature_of_spheres(dim, tol):
    """|H| = 1/ρ on the sphere of radius ρ = 2 in R^2 (a circle), R^3 and R^4.  On a curve the k
    neighbours of a random sample lie unevenly on the two sides, which tilts the fitted normal."""
    pts = sample_sphere(3000, n_dims=dim, radius=2.0, seed=1)
    err = np.abs(knn_curvature(pts, k=30) - 0.5) / 0.5
    assert np.median(err) < tol


def test_knn_shape_operator_of_a_sphere_is_a_multiple_of_the_identity():
    so = knn_shape_operator(sample_sphere(3000, n_dims=3, radius=2.0, seed=2), k=30)
    s = so.tensor * np.sign(np.trace(so.tensor, axis1=1, axis2=2))[:, None, None]
    assert np.allclose(np.median(s, axis=0), 0.5 * np.eye(2), atol=0.02)
    # the normal is radial, the basis orthonormal and tangent
    pts = sample_sphere(3000, n_dims=3, radius=2.0, seed=2)
    assert np.median(np.abs(np.einsum("ij,ij->i", so.normal, pts / 2))) > 0.999
    assert np.allclose(np.einsum("nia,nja->nij", so.basis, so.basis), np.eye(2), atol=1e-9)
    assert np.allclose(np.einsum("nia,na->ni", so.basis, so.normal), 0, atol=1e-9)


def test_knn_gaussian_curvature_of_the_torus():
    pts = sample_torus(4000, seed=3)
    K = knn_curvature(pts, curvature="gaussian", k=40)
    exact = torus_gaussian_curvature_at(pts)
    assert np.mean(np.sign(K) == np.sign(exact)) > 0.95  # outer region K > 0, inner K < 0
    assert np.corrcoef(K, exact)[0, 1] > 0.85


def test_crust_estimators_on_the_torus():
    pts = sample_torus(1500, seed=4)
    K = point_curvature(pts, estimator="crust", curvature="gaussian")
    H = point_curvature(pts, estimator="crust", curvature="mean")
    assert np.all(np.isfinite(K)) and np.all(np.isfinite(H))
    assert np.mean(np.sign(K) == np.sign(torus_gaussian_curvature_at(pts))) > 0.93
    assert np.corrcoef(H, np.abs(torus_mean_curvature_at(pts)))[0, 1] > 0.5


def test_crust_estimator_on_the_three_sphere():
    pts = sample_sphere(500, n_dims=4, radius=2.0, seed=5)
    H = point_curvature(pts, estimator="crust", area="voronoi")
    assert np.median(np.abs(H - 0.5)) < 0.05


@settings(deadline=None, max_examples=5, derandomize=True)
@given(st.integers(0, 10**6), st.floats(-10, 10))
def test_knn_curvature_is_invariant_under_rigid_motions(seed, shift):
    pts = sample_torus(600, seed=seed)
    rot = Rotation.random(random_state=seed).as_matrix()
    moved = pts @ rot.T + shift
    for curvature in ("mean", "gaussian"):
        assert np.allclose(knn_curvature(pts, curvature=curvature), knn_curvature(moved, curvature=curvature),
                           rtol=1e-6, atol=1e-9)


def test_bad_input():
    pts = sample_sphere(100, n_dims=3, seed=0)
    with pytest.raises(ValueError, match="k must be >= 5"):
        knn_curvature(pts, k=3)
    with pytest.raises(ValueError, match="neighbours need more"):
        knn_curvature(pts, k=100)
    with pytest.raises(ValueError, match="curvature must be"):
        knn_curvature(pts, curvature="gauss")
    with pytest.raises(ValueError, match="neighbour_weights"):
        knn_shape_operator(pts, neighbour_weights="cot")
    with pytest.raises(ValueError, match="neighbour_weights"):
        knn_curvature(pts, neighbour_weights=["gaussian"])


def test_neighbour_weights_change_the_fit_and_other_refusals():
    # `weights` means the points' weights everywhere else; the neighbour weighting has its own name
    pts = sample_sphere(100, n_dims=3, seed=1)
    assert not np.array_equal(knn_curvature(pts, neighbour_weights="gaussian"), knn_curvature(pts))
    with pytest.raises(TypeError, match="weights"):
        knn_shape_operator(pts, weights="gaussian")
    with pytest.raises(ValueError, match="n = 2"):
        knn_curvature(sample_sphere(100, n_dims=4, seed=0), curvature="gaussian")
    with pytest.raises(ValueError, match="^estimator must be one of 'knn', 'crust', got 'mls'$"):
        point_curvature(pts, estimator="mls")
    with pytest.raises(ValueError, match="^estimator must be one of 'knn', 'crust', got array"):  # a 0-d array of 'knn'
        point_curvature(pts, estimator=np.array("knn"))
    with pytest.raises(ValueError, match="R³"):
        point_curvature(sample_sphere(100, n_dims=4, seed=0), estimator="crust", curvature="gaussian")
    with pytest.raises(ValueError, match="mixed"):
        point_curvature(sample_sphere(200, n_dims=4, seed=0), estimator="crust", area="mixed")
    with pytest.raises(ValueError, match="NaN"):
        knn_curvature(np.vstack([pts, [[np.nan, 0, 0]]]))


def test_mixed_area_off_r3_is_refused_before_reconstruction(monkeypatch):
    """The refusal of area="mixed" off R³ comes before the Crust runs (no wasted reconstruction)."""
    import thesis_lib.curvature.point_curvature as module

    def no_crust(*args, **kwargs):
        raise AssertionError("the Crust ran before the area was checked")

    monkeypatch.setattr(module, "crust_nd", no_crust)
    with pytest.raises(ValueError, match="mixed area"):
        point_curvature(sample_sphere(200, n_dims=4, seed=0), estimator="crust", area="mixed")
    with pytest.raises(AssertionError, match="Crust ran"):  # the stub is reached for a valid area
        point_curvature(sample_sphere(200, n_dims=4, seed=0), estimator="crust", area="voronoi")

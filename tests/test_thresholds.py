"""Thresholds read off Hilbert functions (multiparameter.thresholds): the torus and the two circles."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib.curvature.point_curvature import point_curvature
from thesis_lib.curvature.pointcloud import neighbour_mean
from thesis_lib.datasets import two_circles, two_circles_intersections
from thesis_lib.meshes import sample_torus
from thesis_lib.multiparameter import hilbert_function, radius_curvature_bifiltration
from thesis_lib.multiparameter.thresholds import circles_run, first_at_least, torus_run
from thesis_lib.surfaces import torus_gaussian_curvature_at


def test_first_at_least_reads_the_first_grade():
    grid = np.linspace(0, 1, 6)
    assert first_at_least([0, 0, 1, 3, 2, 3], grid, 3) == pytest.approx(0.6)
    assert first_at_least([0, 0, 1, 3, 2, 3], grid, 0) == 0.0
    assert np.isnan(first_at_least([0, 0], grid[:2], 1))
    with pytest.raises(ValueError, match="same shape"):
        first_at_least([0, 1], grid, 1)


def test_torus_thresholds_follow_the_hilbert_function():
    X = sample_torus(1000, R=10.0, r=5.0, seed=2)
    K = neighbour_mean(X, point_curvature(X, estimator="crust", curvature="gaussian"), k=16)
    exact = torus_gaussian_curvature_at(X, R=10.0, r=5.0)
    eps = np.linspace(0, 8, 17)
    run = torus_run(X, K, exact=exact, radii=eps, n_kappa=11)
    kappa = np.linspace(K.min(), K.max(), 11)
    hf = hilbert_function(radius_curvature_bifiltration(X, K, complex="alpha", absolute=False), eps, kappa, dims=[1, 2])
    assert np.array_equal(run.hilbert, hf) and np.array_equal(run.curvatures, kappa)
    assert hf[0][run.star, -1] == 2 and hf[1][run.star, -1] == 1
    row = hf[0][run.star]
    assert run.one == first_at_least(row, kappa, 1) and run.transient == row.max()
    assert run.sign == np.mean(np.sign(K) == np.sign(exact)) > 0.9
    assert kappa[0] <= run.one <= kappa[-1] and (np.isnan(run.two) or run.one <= run.two)
    with pytest.raises(ValueError, match="never shows the torus"):
        torus_run(X, K, exact=exact, radii=[0.0, 0.1], n_kappa=5)
    with pytest.raises(ValueError, match="one value per point"):
        torus_run(X, K[:-1], exact=exact, radii=eps, n_kappa=5)


def test_the_circles_junctions_are_the_most_curved_and_come_last():
    X = two_circles(80, seed=1)
    kap = point_curvature(X, estimator="knn", k=10)
    run = circles_run(X, kap, junctions=two_circles_intersections(), max_radius=0.8, n_eps=21, n_kappa=21)
    near = np.min(np.linalg.norm(X[:, None] - two_circles_intersections()[None], axis=2), axis=1) < 0.05
    assert run.junction == np.median(kap[near]) > run.rest == np.median(kap[~near])
    three = run.hilbert == 3
    e3 = np.flatnonzero(three[:, -1])[0]
    assert run.eps3 == run.radii[e3] and run.kappa3 == first_at_least(three[e3], run.curvatures, 1)
    assert run.kappa3_rank == np.mean(kap < run.kappa3) > 0.5  # the loops need the most curved points
    with pytest.raises(ValueError, match="never reaches 3"):
        circles_run(X, kap, junctions=two_circles_intersections(), max_radius=0.01, n_eps=5, n_kappa=5)
    with pytest.raises(ValueError, match="one value per point"):
        circles_run(X, kap[:3], junctions=two_circles_intersections(), max_radius=0.8, n_eps=5, n_kappa=5)

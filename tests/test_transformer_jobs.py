"""RipsDiagrams in parallel (n_jobs) and in giotto-tda's padded layout (output="padded")."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib.persistence import RipsDiagrams, rips_persistence


def _clouds(n=6):
    rng = np.random.default_rng(11)
    return [rng.normal(size=(int(rng.integers(15, 40)), 2)) for _ in range(n)]


def test_parallel_jobs_give_the_same_diagrams():
    clouds = _clouds()
    serial = RipsDiagrams(max_dim=2, scale="diameter").fit_transform(clouds)
    for jobs in (2, -1):
        parallel = RipsDiagrams(max_dim=2, scale="diameter", n_jobs=jobs).fit_transform(clouds)
        assert all(np.array_equal(a, b) for s, p in zip(serial, parallel) for a, b in zip(s, p))
    one = rips_persistence(clouds[3], max_dim=2).to_diagrams(dims=[0, 1], scale="diameter")
    assert all(np.array_equal(a, b) for a, b in zip(serial[3], one))


def test_the_padded_layout_holds_every_point_and_pads_on_the_diagonal():
    clouds = _clouds(4) + [np.zeros((1, 2))]  # a single point: one H0 point, no H1 point
    lists = RipsDiagrams(max_dim=2).fit_transform(clouds)
    padded = RipsDiagrams(max_dim=2, output="padded").fit_transform(clouds)
    n0, n1 = (max(len(d[q]) for d in lists) for q in (0, 1))
    assert padded.shape == (5, n0 + n1, 3)
    for i, d in enumerate(lists):
        for q, start, size in ((0, 0, n0), (1, n0, n1)):
            block = padded[i, start:start + size]
            assert np.array_equal(block[: len(d[q]), :2], d[q]) and np.all(block[:, 2] == q)
            pad = min(dd[q][:, 0].min() for dd in lists if len(dd[q]))
            assert np.all(block[len(d[q]):, 0] == pad) and np.all(block[len(d[q]):, 1] == pad)
    assert np.isinf(padded[:, :n0, 1]).sum() == 5  # each cloud's essential H0 class keeps its death ∞


def test_a_dimension_without_points_gets_one_padding_triple():
    padded = RipsDiagrams(homology_dimensions=(1,), output="padded").fit_transform([np.zeros((1, 2)), np.eye(2)])
    assert padded.tolist() == [[[0.0, 0.0, 1.0]], [[0.0, 0.0, 1.0]]]


@pytest.mark.parametrize("params, match", [
    ({"n_jobs": 0}, "n_jobs"), ({"n_jobs": -2}, "n_jobs"), ({"n_jobs": 1.5}, "n_jobs"), ({"n_jobs": True}, "n_jobs"),
    ({"output": "dict"}, "output must be one of 'list', 'padded'"),
])
def test_bad_options_are_named(params, match):
    with pytest.raises((ValueError, TypeError), match=match):
        RipsDiagrams(**params).fit_transform(_clouds(2))


def test_scikit_learn_clones_the_new_parameters():
    base = pytest.importorskip("sklearn.base")
    copy = base.clone(RipsDiagrams(n_jobs=2, output="padded"))
    assert copy.get_params()["n_jobs"] == 2 and copy.get_params()["output"] == "padded"


def test_distance_matrices_give_the_diagrams_of_their_points():
    import scipy.sparse
    from scipy.spatial.distance import cdist

    clouds = _clouds(3)
    expected = RipsDiagrams(max_dim=2).fit_transform(clouds)
    dense = RipsDiagrams(max_dim=2, metric="precomputed").fit_transform([cdist(c, c) for c in clouds])
    assert all(np.allclose(a, b, rtol=1e-12, atol=0) for e, d in zip(expected, dense) for a, b in zip(e, d))
    D = cdist(clouds[0], clouds[0])
    sparse = scipy.sparse.coo_matrix(np.where(D <= 1.0, D, 0.0))
    thresholded = RipsDiagrams(max_dim=2, max_radius=0.5, metric="precomputed").fit_transform([D])
    from_sparse = RipsDiagrams(max_dim=2, max_radius=0.5, metric="precomputed").fit_transform([sparse])
    assert all(np.array_equal(a, b) for a, b in zip(thresholded[0], from_sparse[0]))
    with pytest.raises(ValueError, match="distance matrix 0"):
        RipsDiagrams(metric="precomputed").fit_transform([np.ones((3, 2))])
    with pytest.raises(ValueError, match="metric must be one of 'euclidean', 'precomputed'"):
        RipsDiagrams(metric="cosine").fit()

"""thesis_lib.compat.ripser against ripser.py itself: same call, same dictionary, same diagrams.

ripser.py computes in float32 and so does the drop-in (it rounds the distances first): the diagrams
are compared to rtol 1e-5 after sorting rows (in practice they agree to the last bit), the
permutations, covering radii and edge counts exactly, ``dperm2all`` to float64 rounding (ripser.py's
distances come from scikit-learn's ``pairwise_distances``, ours from ``scipy.spatial.distance.cdist``).
With ``do_cocycles=True`` the cocycles are compared bar by bar (matched by birth and death, since
bars of equal birth may come in another order) and they are the same arrays, rows in the same order:
the engine's reduction is ripser.py's on the same float32 values, so it picks the same pairs and the
same chains, ties included.  The last part ports ripser.py's own test cases (its package ships no tests).
"""

from __future__ import annotations

import warnings

import numpy as np
import persim
import pytest
import scipy.sparse
from hypothesis import given, settings
from hypothesis import strategies as st
from ripser import ripser as reference

from thesis_lib.compat import ripser

KEYS = {"dgms", "cocycles", "num_edges", "dperm2all", "idx_perm", "r_cover"}


def sorted_rows(dgm: np.ndarray) -> np.ndarray:
    return dgm[np.lexsort((dgm[:, 1], dgm[:, 0]))]


def assert_same_result(ours: dict, theirs: dict, *, dperm2all_rtol: float = 1e-9) -> None:
    assert set(ours) == set(theirs) == KEYS
    assert len(ours["dgms"]) == len(theirs["dgms"])
    for k, (a, b) in enumerate(zip(ours["dgms"], theirs["dgms"])):
        assert a.dtype == b.dtype == np.float64 and a.ndim == 2 and a.shape[1] == 2, k
        assert a.shape == b.shape, (k, a, b)
        np.testing.assert_allclose(sorted_rows(a), sorted_rows(b), rtol=1e-5, atol=1e-12, err_msg=f"H{k}")
    assert_same_cocycles(ours, theirs)
    assert type(ours["num_edges"]) is int and ours["num_edges"] == theirs["num_edges"]
    assert ours["idx_perm"].dtype == theirs["idx_perm"].dtype == np.int64
    np.testing.assert_array_equal(ours["idx_perm"], theirs["idx_perm"])
    assert isinstance(ours["r_cover"], float)
    assert ours["r_cover"] == pytest.approx(theirs["r_cover"], rel=1e-12, abs=1e-15)
    if scipy.sparse.issparse(theirs["dperm2all"]):
        assert ours["dperm2all"] is theirs["dperm2all"]
    else:
        assert ours["dperm2all"].shape == theirs["dperm2all"].shape
        np.testing.assert_allclose(ours["dperm2all"], theirs["dperm2all"], rtol=dperm2all_rtol, atol=1e-12)


def cocycles_by_bar(result: dict, k: int) -> list:
    """Dimension k's (birth, death, cocycle rows) sorted: the bars matched whatever their order."""
    return sorted((b, d, c.tolist()) for (b, d), c in zip(result["dgms"][k].tolist(), result["cocycles"][k]))


def assert_same_cocycles(ours: dict, theirs: dict) -> None:
    assert len(ours["cocycles"]) == len(theirs["cocycles"]) == len(theirs["dgms"])
    assert ours["cocycles"][0] == theirs["cocycles"][0] == []
    for k in range(1, len(theirs["dgms"])):
        a, b = ours["cocycles"][k], theirs["cocycles"][k]
        assert len(a) == len(b), k
        if not b:
            continue
        assert len(a) == ours["dgms"][k].shape[0]
        for c in a:
            assert c.dtype == np.int64 and c.ndim == 2 and c.shape[1] == k + 2
        assert cocycles_by_bar(ours, k) == cocycles_by_bar(theirs, k), k


def both(X, **kw) -> tuple[dict, dict]:
    return ripser(X, **kw), reference(X, **kw)


def distances(points: np.ndarray) -> np.ndarray:
    return np.sqrt(((points[:, None, :] - points[None, :, :]) ** 2).sum(-1))


def births_matrix(rng: np.random.Generator, n: int) -> np.ndarray:
    """A distance matrix with vertex births on the diagonal, each edge no earlier than its vertices."""
    births = rng.uniform(0, 0.3, n)
    dm = np.maximum(distances(rng.random((n, 2))), np.maximum.outer(births, births))
    np.fill_diagonal(dm, births)
    return dm


# ---------------------------------------------------------------------------------------- against ripser.py
@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("d", [2, 3])
@pytest.mark.parametrize("maxdim", [0, 1, 2])
@pytest.mark.parametrize("coeff", [2, 3, 5])
@pytest.mark.parametrize("thresh", [np.inf, 0.45])
@pytest.mark.parametrize("do_cocycles", [False, True])
def test_points_agree_with_ripser(seed, d, maxdim, coeff, thresh, do_cocycles):
    X = np.random.default_rng(seed).random((25, d))
    ours, theirs = both(X, maxdim=maxdim, coeff=coeff, thresh=thresh, do_cocycles=do_cocycles)
    assert_same_result(ours, theirs)
    for a, b in zip(ours["dgms"], theirs["dgms"]):  # float32 distances on both sides: the same values
        np.testing.assert_array_equal(sorted_rows(a), sorted_rows(b))


@pytest.mark.parametrize("seed", range(3))
def test_thresh_at_a_distance_is_compared_in_float32(seed):
    # thresh equal to a float64 distance: both sides round it and the distances to float32 first, so
    # the edge at that distance is in (a float64 comparison could leave it out)
    X = np.random.default_rng(seed).random((30, 2))
    dm = distances(X)
    for t in np.quantile(dm[np.triu_indices(30, 1)], [0.05, 0.1, 0.2], method="nearest"):
        ours, theirs = both(X, maxdim=1, thresh=float(t))
        assert_same_result(ours, theirs)
        assert ours["num_edges"] == int(np.count_nonzero(
            dm[np.triu_indices(30, 1)].astype(np.float32) <= np.float32(t)))


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("n_perm", [1, 5, 17])
@pytest.mark.parametrize("thresh", [np.inf, 0.6])
def test_greedy_permutation_agrees_with_ripser(seed, n_perm, thresh):
    X = np.random.default_rng(seed).normal(size=(40, 3))
    ours, theirs = both(X, maxdim=2, n_perm=n_perm, thresh=thresh, do_cocycles=True)
    assert_same_result(ours, theirs)
    assert ours["dperm2all"].shape == (n_perm, 40) and ours["idx_perm"][0] == 0
    assert len(set(ours["idx_perm"].tolist())) == n_perm
    for cocycles in ours["cocycles"][1:]:  # the vertices are the points' own indices, as ripser.py gives them
        for c in cocycles:
            assert set(c[:, :-1].ravel().tolist()) <= set(ours["idx_perm"].tolist())


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("maxdim", [1, 2])
@pytest.mark.parametrize("thresh", [np.inf, 0.5])
def test_dense_distance_matrix_with_zero_diagonal_agrees_with_ripser(seed, maxdim, thresh):
    dm = distances(np.random.default_rng(seed).random((30, 3)))
    ours, theirs = both(dm, distance_matrix=True, maxdim=maxdim, thresh=thresh, coeff=3, do_cocycles=True)
    assert_same_result(ours, theirs)
    assert ours["dperm2all"] is dm


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("thresh", [np.inf, 0.55])
@pytest.mark.parametrize("n_perm", [None, 12])
def test_dense_distance_matrix_with_births_agrees_with_ripser(seed, thresh, n_perm):
    dm = births_matrix(np.random.default_rng(seed), 25)
    ours, theirs = both(dm, distance_matrix=True, maxdim=2, thresh=thresh, n_perm=n_perm, do_cocycles=True)
    assert_same_result(ours, theirs)
    births = ours["dgms"][0][:, 0]
    assert births.max() > 0  # the diagonal is read as births


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("fmt", ["coo", "csr", "csc", "lil"])
@pytest.mark.parametrize("half", [False, True])
@pytest.mark.parametrize("thresh", [np.inf, 0.4])
def test_sparse_distance_matrix_agrees_with_ripser(seed, fmt, half, thresh):
    rng = np.random.default_rng(seed)
    dm = distances(rng.random((30, 2)))
    dm[dm > 0.5] = 0  # only the short edges are stored
    if half:  # the upper triangle only (ripser.py's sparse tutorial builds its matrices so)
        dm = np.triu(dm)
    sp = scipy.sparse.coo_matrix(dm).asformat(fmt)
    ours, theirs = both(sp, distance_matrix=True, maxdim=2, thresh=thresh, do_cocycles=True)
    assert_same_result(ours, theirs)


def test_sparse_distance_matrix_with_births_agrees_with_ripser():
    dm = births_matrix(np.random.default_rng(7), 25)
    dm[dm > 0.6] = 0
    ours, theirs = both(scipy.sparse.csr_matrix(dm), distance_matrix=True, maxdim=1, do_cocycles=True)
    assert_same_result(ours, theirs)


@pytest.mark.parametrize("metric", ["manhattan", "cityblock", "chebyshev", "cosine", "l2"])
def test_named_metrics_agree_with_ripser(metric):
    X = np.random.default_rng(3).random((25, 3)) + 0.1
    assert_same_result(*both(X, metric=metric, maxdim=1), dperm2all_rtol=1e-7)


def test_callable_metric_and_precomputed_agree_with_ripser():
    X = np.random.default_rng(4).random((20, 2))

    def l1(a, b):
        return float(np.abs(a - b).sum())

    assert_same_result(*both(X, metric=l1))
    dm = distances(X)
    ours = ripser(dm, metric="precomputed")  # scikit-learn's word for a distance matrix: no warning
    np.testing.assert_array_equal(ours["dgms"][1], ripser(dm, distance_matrix=True)["dgms"][1])


def test_rows_come_in_ripsers_order():
    X = np.random.default_rng(11).random((40, 2))
    ours, theirs = both(X, maxdim=2)
    for a, b in zip(ours["dgms"], theirs["dgms"]):  # no ties on random points: the same order
        np.testing.assert_array_equal(a, b)


def test_positional_call_as_ripser_py():
    X = np.random.default_rng(5).random((20, 2))
    for do_cocycles in (False, True):
        ours = ripser(X, 2, 0.8, 3, False, do_cocycles, "euclidean", 10)
        assert_same_result(ours, reference(X, 2, 0.8, 3, False, do_cocycles, "euclidean", 10))


def test_where_the_drop_in_reads_more_than_ripser_py():
    rng = np.random.default_rng(12)
    dm = distances(rng.random((15, 2)))
    dm[dm > 0.5] = 0
    upper, lower = scipy.sparse.coo_matrix(np.triu(dm)), scipy.sparse.coo_matrix(np.tril(dm))
    a, b = ripser(upper, distance_matrix=True), ripser(lower, distance_matrix=True)
    for x, y in zip(a["dgms"], b["dgms"]):  # ripser.py reads no edge from the lower triangle
        np.testing.assert_array_equal(sorted_rows(x), sorted_rows(y))
    assert a["num_edges"] == b["num_edges"] == reference(upper, distance_matrix=True)["num_edges"] > 0
    births = births_matrix(rng, 6)
    births[0, 1] = births[1, 0] = births[0, 0] = births[1, 1] = 0.0  # two points at distance 0
    h0 = ripser(births, distance_matrix=True, maxdim=0)["dgms"][0]
    assert h0.shape[0] == 5  # vertices 0 and 1 are one component from the start (ripser.py: not joined)


# ---------------------------------------------------------------------------------------- ripser.py's cases
def test_defaults():
    result = ripser(np.random.default_rng(0).random((100, 3)))
    assert len(result["dgms"]) == 2 and result["cocycles"] == [[], []]
    assert np.array_equal(result["idx_perm"], np.arange(100)) and result["r_cover"] == 0.0
    assert result["dgms"][0][-1].tolist() == [0.0, np.inf]  # the one essential H0 class
    assert np.isfinite(result["dgms"][0][:-1]).all()


def test_circle_has_one_long_h1_bar():
    t = np.linspace(0, 2 * np.pi, 60, endpoint=False)
    X = np.column_stack([np.cos(t), np.sin(t)]) + np.random.default_rng(1).normal(scale=0.02, size=(60, 2))
    h1 = ripser(X)["dgms"][1]
    lengths = np.sort(h1[:, 1] - h1[:, 0])
    assert lengths[-1] > 1.4 and (lengths.size == 1 or lengths[-2] < 0.2)


@pytest.mark.parametrize("maxdim", [0, 1, 2, 3])
def test_maxdim(maxdim):
    result = ripser(np.random.default_rng(2).random((15, 3)), maxdim=maxdim)
    assert len(result["dgms"]) == len(result["cocycles"]) == maxdim + 1


def test_thresh_cuts_bars_to_essential_ones():
    X = np.random.default_rng(3).random((30, 2))
    full, cut = ripser(X)["dgms"], ripser(X, thresh=0.1)["dgms"]
    assert np.isinf(cut[0][:, 1]).sum() > 1 and np.isinf(full[0][:, 1]).sum() == 1
    assert ripser(X, thresh=0.1)["num_edges"] < ripser(X)["num_edges"]


def test_sparse_matrix_gives_the_dense_thresholded_diagrams():
    dm = distances(np.random.default_rng(4).random((40, 2)))
    dense = ripser(dm, distance_matrix=True, thresh=0.3)["dgms"]
    kept = np.where(dm <= 0.3, dm, 0)
    sparse = ripser(scipy.sparse.coo_matrix(kept), distance_matrix=True)["dgms"]
    for a, b in zip(dense, sparse):
        np.testing.assert_array_equal(sorted_rows(a), sorted_rows(b))


def test_nonzero_diagonal_gives_the_births():
    rng = np.random.default_rng(5)
    dm = births_matrix(rng, 20)
    h0 = ripser(dm, distance_matrix=True, maxdim=0)["dgms"][0]
    # each H0 bar is born at a vertex's birth (float32), the essential one at the earliest
    assert set(h0[:, 0].tolist()) <= set(np.diagonal(dm).astype(np.float32).astype(float).tolist())
    assert h0[np.isinf(h0[:, 1]), 0].tolist() == [float(np.float32(np.diagonal(dm).min()))]


def test_greedy_permutation_bottleneck_bounded_by_cover_radius():
    t = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    X = np.column_stack([np.cos(t), np.sin(t)])
    full = ripser(X)["dgms"][1]
    sub = ripser(X, n_perm=40)
    assert sub["dperm2all"].shape == (40, 200) and sub["r_cover"] > 0
    assert persim.bottleneck(full, sub["dgms"][1]) <= 2 * sub["r_cover"] + 1e-6


def test_permutation_of_all_points_is_no_permutation():
    X = np.random.default_rng(6).random((12, 2))
    for n_perm in (0, 12):
        assert_same_result(*both(X, n_perm=n_perm))
        assert ripser(X, n_perm=n_perm)["r_cover"] == 0.0


def test_a_single_point():
    with pytest.warns(UserWarning, match="more columns than rows"):
        ours = ripser(np.zeros((1, 2)))
    assert ours["dgms"][0].tolist() == [[0.0, np.inf]] and ours["dgms"][1].shape == (0, 2)
    assert ours["num_edges"] == 0


# ---------------------------------------------------------------------------------------- warnings and errors
def test_warnings_as_ripser_py():
    rng = np.random.default_rng(8)
    with pytest.warns(UserWarning, match="distance_matrix=True"):
        ripser(rng.random((5, 5)))
    with pytest.warns(UserWarning, match="transpose"):
        ripser(rng.random((3, 5)))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ripser(rng.random((6, 2)))
        ripser(distances(rng.random((6, 2))), distance_matrix=True)


@pytest.mark.parametrize("kw, error, match", [
    (dict(thresh=-1.0), ValueError, "thresh .* >= 0"),
    (dict(thresh=np.nan), ValueError, "thresh is NaN"),
    (dict(thresh="1"), TypeError, "thresh must be a number"),
    (dict(coeff=4), ValueError, "coeff must be a prime"),
    (dict(coeff=1), ValueError, "coeff must be a prime"),
    (dict(coeff=0), ValueError, "coeff must be a prime"),
    (dict(coeff=2.0), TypeError, "coeff must be an integer"),
    (dict(coeff=2**61 - 1), ValueError, "coeff = .* too large"),
    (dict(maxdim=-1), ValueError, "maxdim must be >= 0"),
    (dict(maxdim=1.5), TypeError, "maxdim must be an integer"),
    (dict(metric="foo"), ValueError, "unknown metric 'foo'; supported: 'euclidean', 'precomputed'"),
    (dict(metric=3), TypeError, "metric must be a string or a callable"),
    (dict(n_perm=-3), ValueError, "n_perm must be >= 0"),
    (dict(n_perm=21), ValueError, "n_perm = 21 is greater than the number of points \\(20\\)"),
    (dict(n_perm=2.5), TypeError, "n_perm must be an integer"),
    (dict(do_cocycles="yes"), ValueError, "do_cocycles must be True or False"),
    (dict(do_cocycles=2), ValueError, "do_cocycles must be True or False"),
])
def test_bad_options(kw, error, match):
    with pytest.raises(error, match=match):
        ripser(np.random.default_rng(9).random((20, 2)), **kw)


@pytest.mark.parametrize("seed", range(6))
def test_cocycles_on_ties_agree_with_ripser(seed):
    """Points on a grid: many equal diameters, so emergent and apparent pairs and ties everywhere."""
    rng = np.random.default_rng(seed)
    X = np.round(rng.random((int(rng.integers(10, 30)), int(rng.integers(2, 4)))) * 4) / 4
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a square grid can look like a distance matrix
        assert_same_result(*both(X, maxdim=2, coeff=[2, 3, 5][seed % 3], do_cocycles=True))


def test_cocycles_come_in_ripsers_order():
    X = np.random.default_rng(11).random((40, 3))
    ours, theirs = both(X, maxdim=2, do_cocycles=True)
    for k in (1, 2):  # no ties on random points: the same bars in the same order, the same arrays
        np.testing.assert_array_equal(ours["dgms"][k], theirs["dgms"][k])
        assert len(ours["cocycles"][k]) == len(theirs["cocycles"][k]) > 0
        for a, b in zip(ours["cocycles"][k], theirs["cocycles"][k]):
            np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("X, kw, match", [
    (np.ones((4, 3)), dict(distance_matrix=True), "square"),
    (np.array([[0.0, 1.0], [2.0, 0.0]]), dict(distance_matrix=True), "not symmetric"),
    (np.array([[0.0, -1.0], [-1.0, 0.0]]), dict(distance_matrix=True), "negative"),
    (np.array([[0.0, np.nan], [np.nan, 0.0]]), dict(distance_matrix=True), "NaN"),
    (scipy.sparse.csr_matrix(np.ones((4, 3))), dict(distance_matrix=True), "square"),
    (scipy.sparse.csr_matrix(np.eye(4)), dict(), "pass distance_matrix=True"),
    (scipy.sparse.csr_matrix(np.eye(4)), dict(distance_matrix=True, n_perm=2), "not supported for sparse"),
    (np.arange(5.0), dict(), "\\(n, d\\) array"),
    (np.array([[0.0, np.inf], [1.0, 2.0], [3.0, 4.0]]), dict(), "NaN or infinite"),
])
def test_bad_inputs(X, kw, match):
    with pytest.raises(ValueError, match=match):
        ripser(X, **kw)


# ---------------------------------------------------------------------------------------- invariants
point_sets = st.integers(0, 2**32 - 1).flatmap(
    lambda seed: st.tuples(st.just(seed), st.integers(4, 18), st.integers(1, 3)))


@settings(deadline=None, max_examples=25)
@given(point_sets, st.integers(0, 2))
def test_threshold_truncates_the_barcode(case, maxdim):
    # the filtration cut at t: bars born after t vanish, bars dying after t become essential
    seed, n, d = case
    X = np.random.default_rng(seed).random((n, d))
    full = ripser(X, maxdim=maxdim)["dgms"]
    t = float(np.float32(np.median(distances(X))))
    cut = ripser(X, maxdim=maxdim, thresh=t)["dgms"]
    for a, b in zip(full, cut):
        kept = a[a[:, 0] <= t].copy()
        kept[kept[:, 1] > t, 1] = np.inf
        np.testing.assert_array_equal(sorted_rows(kept), sorted_rows(b))


@settings(deadline=None, max_examples=25)
@given(point_sets, st.integers(-3, 3))
def test_power_of_two_scaling_scales_everything(case, e):
    seed, n, d = case
    X = np.random.default_rng(seed).random((n, d))
    a, b = ripser(X, maxdim=1, n_perm=n - 1), ripser(np.ldexp(X, e), maxdim=1, n_perm=n - 1)
    for x, y in zip(a["dgms"], b["dgms"]):
        np.testing.assert_array_equal(np.ldexp(sorted_rows(x), e), sorted_rows(y))
    np.testing.assert_array_equal(a["idx_perm"], b["idx_perm"])
    assert b["r_cover"] == np.ldexp(a["r_cover"], e) and a["num_edges"] == b["num_edges"]


@settings(deadline=None, max_examples=20)
@given(point_sets, st.sampled_from([2, 3, 5]))
def test_random_clouds_agree_with_ripser(case, coeff):
    seed, n, d = case
    X = np.random.default_rng(seed).normal(size=(n, d))
    assert_same_result(*both(X, maxdim=2, coeff=coeff, n_perm=n // 2))

"""The compiled implicit Rips engine (src/implicit_rips.cpp): bad input refused with ValueError, the
same barcode on any number of threads and with or without the dense distance matrix (§2.3, §4.2)."""

from __future__ import annotations

import numpy as np
import pytest
from helpers import rips_engine_options

from thesis_lib._core import implicit_rips
from thesis_lib.complexes import rips
from thesis_lib.persistence import persistence, rips_persistence
from thesis_lib.persistence.implicit import PARALLEL_MIN, rips_graph


def _graph(points, eps=np.inf):
    n, indptr, nbr, length = rips_graph(points, max_radius=eps)
    return n, indptr, nbr, length


def _barcode(graph, max_dim=3, p=2, dense=True, n_threads=1, parallel_min=PARALLEL_MIN, births=None):
    n, indptr, nbr, length = graph
    births = np.zeros(max(n, 0)) if births is None else births
    return implicit_rips.rips_barcode(n, indptr, nbr, length, births,
                                      rips_engine_options(max_dim, p, dense, n_threads, parallel_min))


def _same(a, b):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        for u, v in zip(x, y):
            assert u.dtype == v.dtype and u.shape == v.shape and u.tobytes() == v.tobytes()


def test_neighbour_lists_are_symmetric_and_decreasing():
    edges = np.array([[0, 2], [1, 2], [0, 1], [2, 3]], dtype=np.int64)
    lengths = np.array([0.5, 0.25, 1.0, 2.0])
    indptr, nbr, length = implicit_rips.neighbour_lists(4, edges, lengths)
    assert indptr.tolist() == [0, 2, 4, 7, 8]
    assert nbr.tolist() == [2, 1, 2, 0, 3, 1, 0, 2]
    assert length.tolist() == [0.5, 1.0, 0.25, 1.0, 2.0, 0.25, 0.5, 2.0]


def test_neighbour_lists_refuse_bad_edges():
    with pytest.raises(ValueError, match="outside"):
        implicit_rips.neighbour_lists(3, np.array([[0, 3]], dtype=np.int64), np.ones(1))
    with pytest.raises(ValueError, match="outside"):
        implicit_rips.neighbour_lists(3, np.array([[-1, 2]], dtype=np.int64), np.ones(1))
    with pytest.raises(ValueError, match="one entry per edge"):
        implicit_rips.neighbour_lists(3, np.array([[0, 1]], dtype=np.int64), np.ones(2))
    with pytest.raises(ValueError, match=r"shape \(m, 2\)"):
        implicit_rips.neighbour_lists(3, np.zeros((2, 3), dtype=np.int64), np.ones(2))
    with pytest.raises(ValueError, match="n must be"):
        implicit_rips.neighbour_lists(-1, np.zeros((0, 2), dtype=np.int64), np.ones(0))


def test_rips_barcode_refuses_a_graph_it_could_not_walk():
    n, indptr, nbr, length = _graph(np.random.default_rng(0).random((6, 2)))
    with pytest.raises(ValueError, match="n \\+ 1 entries"):
        _barcode((n + 1, indptr, nbr, length))
    with pytest.raises(ValueError, match="disagree"):
        _barcode((n, indptr, nbr[:-1], length[:-1]))
    bad = indptr.copy()
    bad[2], bad[3] = bad[3], bad[2]
    with pytest.raises(ValueError, match="non-decreasing"):
        _barcode((n, bad, nbr, length))
    for value, match in ((n, "outside"), (-1, "outside"), (0, "outside")):  # nbr[0] is vertex 0's
        bad = nbr.copy()
        bad[0] = value
        with pytest.raises(ValueError, match=match):
            _barcode((n, indptr, bad, length))
    bad = nbr.copy()
    bad[indptr[1]], bad[indptr[1] + 1] = bad[indptr[1] + 1], bad[indptr[1]]
    with pytest.raises(ValueError, match="decreasing"):
        _barcode((n, indptr, bad, length))
    bad = length.copy()
    bad[0] += 1.0
    with pytest.raises(ValueError, match="symmetric"):
        _barcode((n, indptr, nbr, bad))
    bad[0] = np.nan
    with pytest.raises(ValueError, match="NaN"):
        _barcode((n, indptr, nbr, bad))
    # an edge listed on one side only
    one = (3, np.array([0, 1, 1, 1]), np.array([2]), np.array([1.0]))
    with pytest.raises(ValueError, match="symmetric"):
        _barcode(one)
    with pytest.raises(ValueError, match="max_dim"):
        _barcode((n, indptr, nbr, length), max_dim=0)
    with pytest.raises(ValueError, match="max_dim"):
        _barcode((n, indptr, nbr, length), max_dim=n + 2)
    with pytest.raises(ValueError, match="prime"):
        _barcode((n, indptr, nbr, length), p=1)
    with pytest.raises(ValueError, match="n must be"):
        _barcode((0, np.zeros(1, np.int64), np.zeros(0, np.int64), np.zeros(0)))
    for births, match in ((np.zeros(n + 1), "one entry per vertex"), (-np.ones(n), "negative"),
                          (np.full(n, np.nan), "NaN")):
        with pytest.raises(ValueError, match=match):
            _barcode((n, indptr, nbr, length), births=births)
    # another integer dtype is converted (a copy), never misread
    _same(_barcode((n, indptr.astype(np.int32), nbr, length)), _barcode((n, indptr, nbr, length)))


def test_threads_do_not_change_the_barcode_on_the_parallel_path():
    """330 points in the plane have 54,285 edges: the positive ones (about 53,956 candidates of H1)
    are searched for apparent pairs in parallel; 120 points in R³ have 280,840 triangles."""
    for pts, max_dim, p in ((np.random.default_rng(1).random((330, 2)), 2, 2),
                            (np.random.default_rng(2).random((120, 3)), 3, 3)):
        stats: dict = {}
        one = rips_persistence(pts, max_dim=max_dim, coefficients=p, n_threads=1, stats=stats)
        assert stats[max_dim - 1]["simplices"] >= PARALLEL_MIN  # the parallel path is taken
        for threads in (2, 3):
            other = rips_persistence(pts, max_dim=max_dim, coefficients=p, n_threads=threads)
            for d in range(max_dim):
                assert one.intervals(d).tobytes() == other.intervals(d).tobytes()
        assert one == rips_persistence(pts, max_dim=max_dim, coefficients=p)  # default: every core


def test_threads_on_small_inputs_forced_parallel():
    for seed in range(5):
        rng = np.random.default_rng(seed)
        graph = _graph(rng.integers(0, 4, size=(int(rng.integers(5, 30)), 3)).astype(float), eps=1.6)
        ref = _barcode(graph, max_dim=3, n_threads=1)
        for threads in (2, 3, 7):
            _same(ref, _barcode(graph, max_dim=3, n_threads=threads, parallel_min=0))


def test_dense_matrix_and_edge_hash_agree():
    """Without the dense matrix (above DENSE_MAX points) lengths come from the edge hash: the same barcode."""
    for seed in range(4):
        rng = np.random.default_rng(seed)
        pts = np.round(rng.random((60, 3)), 1)
        graph = _graph(pts, eps=[0.2, 0.35, 0.6, np.inf][seed])
        for p in (2, 3):
            _same(_barcode(graph, max_dim=4, p=p, dense=True), _barcode(graph, max_dim=4, p=p, dense=False))


def test_sparse_path_agrees_with_the_explicit_engine():
    pts = np.random.default_rng(5).random((40, 3))
    dense = _barcode(_graph(pts, 0.3), max_dim=3, dense=False)
    ref = persistence(rips(pts, max_radius=0.3, max_dim=3), coefficients=2)
    for d in range(3):
        births, deaths, ess = dense[d][:3]
        iv = np.concatenate([np.column_stack([births, deaths]), np.column_stack([ess, np.full(ess.shape, np.inf)])])
        expected = ref.intervals(d)
        assert np.array_equal(np.sort(iv * 0.5, axis=0), np.sort(expected, axis=0))


def test_rips_persistence_n_threads_is_checked():
    pts = np.random.default_rng(0).random((8, 2))
    for bad in (0, -2):
        with pytest.raises(ValueError, match="n_threads"):
            rips_persistence(pts, n_threads=bad)
    for bad in (1.5, True, "2"):
        with pytest.raises(ValueError, match="n_threads"):
            rips_persistence(pts, n_threads=bad)
    assert rips_persistence(pts, n_threads=4) == rips_persistence(pts)


def test_cocycles_come_as_offsets_and_rows_only_when_asked_for():
    n, indptr, nbr, length = graph = _graph(np.random.default_rng(3).random((12, 2)))
    off = _barcode(graph, max_dim=3)
    options = rips_engine_options(3, 2, True, 1, PARALLEL_MIN, cocycles=True)
    on = implicit_rips.rips_barcode(n, indptr, nbr, length, np.zeros(n), options)
    for k, (a, b) in enumerate(zip(off, on)):
        _same([a[:4]], [b[:4]])  # the same bars and statistics
        assert a[4].tolist() == [0] and a[5].shape == (0, k + 2)
        bars = b[0].shape[0] + b[2].shape[0]
        offsets, rows = b[4], b[5]
        assert rows.dtype == np.int64 and rows.shape[1] == k + 2
        if k == 0:  # no cocycles of H0, as ripser.py
            assert offsets.tolist() == [0] and rows.shape[0] == 0
            continue
        assert offsets.shape == (bars + 1,) and offsets[-1] == rows.shape[0] and (np.diff(offsets) >= 1).all()
        assert bars > 0 or k == 2  # two bars of H1 (the points make no H2)

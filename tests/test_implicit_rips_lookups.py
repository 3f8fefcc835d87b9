"""The implicit Rips engine's distance lookups and its high dimensions (§2.3.5, §4.2): the dense matrix
and the hash of the edges give the same bytes and statistics; the upper simplices of zero apparent
pairs found without a table, and the top dimension built from the (k − 2)-simplices, give the
barcode of the explicit engine and of ripser.py up to max_dim 7 on complete and thresholded
filtrations with ties."""

from __future__ import annotations

import numpy as np
import pytest
import ripser
from helpers import rips_engine_options

from thesis_lib._core import implicit_rips
from thesis_lib.complexes import rips
from thesis_lib.persistence import persistence, rips_persistence
from thesis_lib.persistence.implicit import DENSE_FILL, DENSE_FULL_MAX, DENSE_MAX, PARALLEL_MIN, _dense, rips_graph


def _engine(points, eps, max_dim, p, dense, parallel_min=PARALLEL_MIN, n_threads=1):
    n, indptr, nbr, length = rips_graph(points, max_radius=eps)
    return implicit_rips.rips_barcode(n, indptr, nbr, length, np.zeros(n),
                                      rips_engine_options(max_dim, p, dense, n_threads, parallel_min))


@pytest.mark.parametrize("seed", range(12))
def test_dense_matrix_and_edge_hash_give_the_same_bytes_and_statistics(seed):
    rng = np.random.default_rng(seed)
    points = np.round(rng.random((int(rng.integers(8, 40)), int(rng.integers(1, 4)))), 1)  # many ties
    eps = [0.15, 0.3, 0.5, np.inf][seed % 4]
    for max_dim in (2, 4, 5):
        for p in (2, 3):
            one = _engine(points, eps, max_dim, p, dense=True)
            other = _engine(points, eps, max_dim, p, dense=False, parallel_min=0, n_threads=2)
            assert len(one) == len(other) == max_dim
            for a, b in zip(one, other):
                for x, y in zip(a, b):
                    assert x.dtype == y.dtype and x.tobytes() == y.tobytes()


def test_the_dense_matrix_is_kept_for_small_or_well_filled_graphs():
    assert _dense(DENSE_MAX, 0)
    assert not _dense(DENSE_MAX + 1, 0)
    n = DENSE_FULL_MAX
    assert _dense(n, int(np.ceil(DENSE_FILL * n * n)))
    assert not _dense(n, int(DENSE_FILL * n * n) - 1)
    assert not _dense(n + 1, (n + 1) * n)


@pytest.mark.parametrize("seed", range(6))
def test_high_dimensions_agree_with_the_explicit_engine(seed):
    rng = np.random.default_rng(100 + seed)
    n = 11
    matrix = rng.integers(1, 6, size=(n, n)).astype(float)  # few distinct values: many zero apparent pairs
    matrix = np.triu(matrix, 1) + np.triu(matrix, 1).T
    eps = [np.inf, 2.0][seed % 2]
    for max_dim in (3, 4, 6):
        ref = persistence(rips(distance_matrix=matrix, max_radius=eps, max_dim=max_dim), coefficients=3)
        ours = rips_persistence(distance_matrix=matrix, max_radius=eps, max_dim=max_dim, coefficients=3)
        for k in range(max_dim):
            assert np.array_equal(np.sort(ours.intervals(k), axis=0), np.sort(ref.intervals(k), axis=0)), (max_dim, k)


@pytest.mark.parametrize("seed", range(4))
def test_complete_filtrations_up_to_dimension_seven_agree_with_ripser(seed):
    rng = np.random.default_rng(200 + seed)
    n = 14
    a = rng.random((n, n))
    matrix = np.triu(a, 1) + np.triu(a, 1).T
    ours = rips_persistence(distance_matrix=matrix, max_dim=8, min_persistence=1e-12)
    dgms = ripser.ripser(matrix, distance_matrix=True, maxdim=7)["dgms"]
    for k in range(8):
        mine = np.sort(np.asarray(ours.intervals(k), dtype=np.float32) * 2, axis=0)
        theirs = np.sort(np.asarray(dgms[k], dtype=np.float32), axis=0)
        theirs = theirs[theirs[:, 0] != theirs[:, 1]]
        mine = mine[mine[:, 0] != mine[:, 1]]
        assert mine.shape == theirs.shape, k
        assert np.allclose(mine, theirs, rtol=1e-5), k

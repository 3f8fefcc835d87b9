"""A distance matrix's diagonal is the vertices' births, as ripser.py and giotto-ph read it.

Vertex i enters at D[i, i], an edge at the largest of its entry and its vertices' entries (our values
are half of these: ε = diameter / 2); a vertex born above the threshold is not in the complex.
"""

from __future__ import annotations

import warnings

import gph
import numpy as np
import pytest
import ripser
from scipy import sparse

from thesis_lib.complexes import rips
from thesis_lib.persistence import persistence, rips_persistence


def _matrix(seed: int, threshold: float) -> tuple[np.ndarray, np.ndarray]:
    """A distance matrix of random points with random births (some 0) at most the threshold, each
    entry at least its vertices' births (a filtration as ripser.py reads it)."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(2, 22))
    x = rng.random((n, 3))
    d = np.sqrt(((x[:, None] - x[None]) ** 2).sum(-1))
    births = np.minimum(rng.random(n) * rng.choice([0.3, 0.8, 1.5]) * (rng.random(n) < 0.6), threshold)
    d = np.maximum(d, np.maximum(births[:, None], births[None, :]))
    d[np.arange(n), np.arange(n)] = births
    return d, births


def _sparse(d: np.ndarray, births: np.ndarray, threshold: float) -> sparse.coo_matrix:
    """The entries up to the threshold as a sparse matrix, the births stored on its diagonal."""
    n = d.shape[0]
    off = sparse.coo_matrix(np.where((d <= threshold) & ~np.eye(n, dtype=bool), d, 0.0))
    return sparse.coo_matrix((np.r_[off.data, births], (np.r_[off.row, np.arange(n)], np.r_[off.col, np.arange(n)])),
                             shape=(n, n))


def _same(ours: np.ndarray, theirs: np.ndarray) -> bool:
    a, b = np.sort(ours, axis=0), np.sort(np.asarray(theirs, dtype=float), axis=0)
    return a.shape == b.shape and np.allclose(a, b, rtol=1e-6, atol=1e-7)


def test_the_two_vertex_example():
    """D = [[1, 3], [3, 2]]: vertices born at 1 and 2, the younger dies when the edge enters at 3."""
    d = np.array([[1.0, 3.0], [3.0, 2.0]])
    expected = np.array([[1.0, np.inf], [2.0, 3.0]])
    for barcode in (rips_persistence(distance_matrix=d), persistence(rips(distance_matrix=d, max_dim=1)),
                    rips_persistence(distance_matrix=sparse.coo_matrix(d))):
        assert _same(2 * barcode.intervals(0), expected)
    theirs = ripser.ripser(d, distance_matrix=True)["dgms"][0]
    assert _same(2 * rips_persistence(distance_matrix=d).intervals(0), theirs)


@pytest.mark.parametrize("seed", range(45))
def test_births_agree_with_ripser_and_giotto(seed):
    threshold = [np.inf, 1.0, 0.6][seed % 3]
    d, births = _matrix(seed, threshold)
    given = _sparse(d, births, threshold) if seed % 2 else d
    ours = rips_persistence(distance_matrix=given, max_radius=threshold / 2, max_dim=3)
    explicit = persistence(rips(distance_matrix=d, max_radius=threshold / 2, max_dim=3), coefficients=2)
    theirs = ripser.ripser(d, distance_matrix=True, maxdim=2, thresh=threshold)["dgms"]
    giotto = gph.ripser_parallel(d, metric="precomputed", maxdim=2, thresh=threshold)["dgms"]
    for k in range(3):
        assert _same(2 * ours.intervals(k), theirs[k]), k
        assert _same(2 * ours.intervals(k), giotto[k]), k
        assert _same(ours.intervals(k), explicit.intervals(k)), k


def test_a_vertex_born_above_the_threshold_is_left_out():
    d = np.array([[0.0, 1.0, 3.0], [1.0, 0.0, 3.0], [3.0, 3.0, 2.5]])
    for barcode in (rips_persistence(distance_matrix=d, max_radius=1.0),
                    persistence(rips(distance_matrix=d, max_radius=1.0, max_dim=1))):
        assert _same(2 * barcode.intervals(0), np.array([[0.0, 1.0], [0.0, np.inf]]))
    assert len(rips(distance_matrix=d, max_radius=1.0).simplices[0]) == 2
    assert _same(2 * rips_persistence(distance_matrix=d, max_radius=1.5).intervals(0),
                 np.array([[0.0, 1.0], [0.0, np.inf], [2.5, 3.0]]))


def test_an_entry_below_its_vertex_birth_is_raised_to_it_with_a_warning():
    d = np.array([[0.0, 1.0], [1.0, 2.0]])
    with pytest.warns(UserWarning, match="below the diagonal entry"):
        barcode = rips_persistence(distance_matrix=d)
    assert _same(2 * barcode.intervals(0), np.array([[0.0, np.inf]]))  # the edge enters with its vertex, at 2
    with pytest.warns(UserWarning, match="below the diagonal entry"):
        rips(distance_matrix=d)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rips_persistence(distance_matrix=np.array([[0.0, 3.0], [3.0, 2.0]]))  # a filtration: no warning

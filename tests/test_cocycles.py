"""Representative cocycles of the implicit Rips engine (``rips_persistence(..., cocycles=True)``).

The cocycle of a bar [b, d) of dimension k is the reduction chain V_s of the coboundary column of the
k-simplex s that creates it (Theorem 2.39's V, on the coboundary side), as ripser.py's
``do_cocycles`` gives it.  Each is checked on the explicit Rips filtration
(:func:`thesis_lib.complexes.rips`) over Z/p: its first simplex is s (value b, coefficient 1) and
every other comes later; its coboundary vanishes on the (k + 1)-simplices of value < d and not at d
(so restricted to the simplices of value <= t it is a cocycle exactly for b <= t < d; for an
essential bar, for every t >= b); and its class is not zero at b nor just before d (it is not in
the image of the coboundary of the (k − 1)-cochains there: the rank over Z/p grows when it is added).
Note that a cocycle may hold simplices born after b (ripser.py's do too): only its restriction is a
cocycle of the complex at b.  The comparison with ripser.py itself is in test_compat_ripser.py.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse
from helpers import check_every_bar, facet_signs, simplex_vector
from hypothesis import given, settings
from hypothesis import strategies as st
from ripser import ripser as reference

from thesis_lib.complexes import rips
from thesis_lib.homology.smith import rank_mod_p
from thesis_lib.persistence import persistence, rips_persistence


# ---------------------------------------------------------------------------------------- the checks
def _coboundary(K, k: int, c: np.ndarray, p: int) -> np.ndarray:
    """δc on K's (k + 1)-simplices, mod p."""
    F = K.facet_indices(k + 1)
    return (c[F] * facet_signs(k + 1)).sum(axis=1) % p


def _coboundary_values(K, k: int, c: np.ndarray, p: int) -> np.ndarray:
    """The values of the (k + 1)-simplices where δc is not zero."""
    return K.values[k + 1][_coboundary(K, k, c, p) != 0]


def _class_is_nonzero(K, k: int, c: np.ndarray, p: int, t: float) -> bool:
    """Whether c restricted to the simplices of value <= t is not δ of a (k − 1)-cochain there."""
    rows = np.flatnonzero(K.values[k] <= t)
    F = K.facet_indices(k)[rows]
    m = K.simplices[k - 1].shape[0]
    delta = np.zeros((rows.shape[0], m), dtype=np.int64)  # δ_{k−1}: a row per k-simplex, a column per face
    np.put_along_axis(delta, F, np.broadcast_to(facet_signs(k), F.shape), axis=1)
    with_c = np.column_stack([delta, c[rows]])
    return rank_mod_p(with_c, coefficients=p) == rank_mod_p(delta, coefficients=p) + 1


def check_cocycle(K, k: int, p: int, bar: np.ndarray, cocycle: np.ndarray) -> None:
    """Every property of the module docstring for the cocycle of the bar (birth, death) of H_k."""
    birth, death = bar
    assert cocycle.dtype == np.int64 and cocycle.ndim == 2 and cocycle.shape[1] == k + 2
    assert cocycle.shape[0] >= 1
    vertices, coefs = cocycle[:, :-1], cocycle[:, -1]
    assert (np.diff(vertices, axis=1) < 0).all()  # each simplex's vertices decreasing, as ripser.py
    assert ((coefs >= 1) & (coefs < p)).all()
    assert len({tuple(v) for v in vertices.tolist()}) == cocycle.shape[0]
    c = simplex_vector(K, k, cocycle)
    index = {tuple(s): i for i, s in enumerate(K.simplices[k].tolist())}
    values = K.values[k][[index[tuple(sorted(v))] for v in vertices.tolist()]]
    assert values[0] == birth and coefs[0] == 1  # the creating simplex first
    assert (np.diff(values) >= 0).all()  # rows in filtration order, all born at b or later
    bad = _coboundary_values(K, k, c, p)
    if np.isinf(death):
        assert bad.size == 0  # a cocycle of the whole complex
    else:
        assert bad.min() == death  # a cocycle below d, not at d
    assert _class_is_nonzero(K, k, c, p, birth)
    before = K.values[k][K.values[k] < death].max()  # the last value of a k-simplex before d
    assert _class_is_nonzero(K, k, c, p, before)


def check_all(K, barcode, cocycles, p: int, dims) -> int:
    """check_cocycle on every bar of the dimensions; the number of bars checked."""
    return check_every_bar(barcode, cocycles, dims, lambda k, bar, cocycle: check_cocycle(K, k, p, bar, cocycle))


# ---------------------------------------------------------------------------------------- the cocycles
@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("p", [2, 3, 5])
def test_every_cocycle_is_a_nonzero_class_from_birth_to_death(seed, p):
    rng = np.random.default_rng(seed)
    points = rng.random((13, 3))
    eps = [np.inf, 0.35, 0.3, 0.45][seed]  # finite ones leave essential bars of H1 and H2
    barcode, cocycles = rips_persistence(points, max_radius=eps, max_dim=3, coefficients=p, cocycles=True)
    K = rips(points, max_radius=eps, max_dim=3)
    assert check_all(K, barcode, cocycles, p, (1, 2)) > 0
    assert sorted(cocycles) == [1, 2]


@settings(deadline=None, max_examples=25)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(4, 12), d=st.integers(1, 3), p=st.sampled_from([2, 3, 5]),
       ties=st.booleans(), cut=st.booleans())
def test_cocycles_hold_on_random_clouds_with_ties(seed, n, d, p, ties, cut):
    rng = np.random.default_rng(seed)
    points = rng.random((n, d))
    if ties:  # a grid: many equal distances, so equal values, emergent and apparent pairs
        points = np.round(points * 3) / 3
    eps = float(rng.uniform(0.2, 0.6)) if cut else np.inf
    barcode, cocycles = rips_persistence(points, max_radius=eps, max_dim=3, coefficients=p, cocycles=True)
    check_all(rips(points, max_radius=eps, max_dim=3), barcode, cocycles, p, (1, 2))


@pytest.mark.parametrize("seed", range(3))
def test_cocycles_of_a_distance_matrix_and_of_its_sparse_form(seed):
    rng = np.random.default_rng(seed)
    a = rng.random((11, 11))
    dm = a + a.T + 1.0  # symmetric, not Euclidean
    np.fill_diagonal(dm, 0.0)
    eps = 1.4
    barcode, cocycles = rips_persistence(distance_matrix=dm, max_radius=eps, max_dim=3, coefficients=3,
                                         cocycles=True)
    check_all(rips(distance_matrix=dm, max_radius=eps, max_dim=3), barcode, cocycles, 3, (1, 2))
    cut = np.where(dm <= 2 * eps, dm, 0.0)
    sparse, sparse_cocycles = rips_persistence(distance_matrix=scipy.sparse.csr_matrix(cut), max_radius=eps,
                                               max_dim=3, coefficients=3, cocycles=True)
    assert sparse == barcode
    for k in (1, 2):
        assert [c.tolist() for c in sparse_cocycles[k]] == [c.tolist() for c in cocycles[k]]


def test_the_checks_can_fail():
    """A coboundary is a cocycle of zero class; a cocycle cut short is no cocycle; a wrong birth is seen."""
    points = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])  # a square: one loop [1, √2)
    K = rips(points, max_radius=np.inf, max_dim=2)
    barcode, cocycles = rips_persistence(points, max_dim=2, cocycles=True)
    bar, cocycle = barcode.intervals(1)[0], cocycles[1][0]
    check_cocycle(K, 1, 3, bar, cocycle)
    vertex = np.zeros(4, dtype=np.int64)
    vertex[0] = 1
    delta = _coboundary(K, 0, vertex, 3)  # δ of vertex 0: the edges at 0, with signs
    assert _coboundary_values(K, 1, delta, 3).size == 0
    assert not _class_is_nonzero(K, 1, delta, 3, 1.0)
    assert _class_is_nonzero(K, 1, simplex_vector(K, 1, cocycle), 3, 1.0)
    trivial = np.array([[1, 0, 1], [2, 1, 2]])  # side 01 minus side 12: δ of vertex 1, a zero class at 1
    assert not _class_is_nonzero(K, 1, simplex_vector(K, 1, trivial), 3, 1.0)
    with pytest.raises(AssertionError):
        check_cocycle(K, 1, 3, bar, trivial)
    with pytest.raises(AssertionError):
        check_cocycle(K, 1, 3, np.array([0.5, bar[1]]), cocycle)


def test_ripser_py_cocycles_pass_the_same_checks():
    """The checks hold for ripser.py's own cocycles (so they test the convention, not our code only)."""
    points = np.random.default_rng(4).random((20, 2))
    d32 = np.sqrt(((points[:, None] - points[None]) ** 2).sum(-1)).astype(np.float32)  # ripser.py's values
    K = rips(distance_matrix=d32.astype(np.float64), max_dim=3)
    checked = 0
    for p in (2, 3):
        theirs = reference(points, maxdim=2, coeff=p, do_cocycles=True)
        for k in (1, 2):
            for bar, cocycle in zip(theirs["dgms"][k], theirs["cocycles"][k]):
                check_cocycle(K, k, p, bar / 2, cocycle)
                checked += 1
    assert checked >= 6


def test_an_unreduced_bar_has_its_simplex_alone_as_cocycle():
    """A bar whose column needed no addition has the creating simplex, coefficient 1, as cocycle (the
    square's loop); the emergent and zero apparent pairs, which skip the column, give no bar at all."""
    points = np.array([[0.0, 0.0], [3.0, 0.0], [3.0, 2.0], [0.0, 2.0]])
    stats: dict = {}
    barcode, cocycles = rips_persistence(points, max_dim=2, cocycles=True, stats=stats)
    assert barcode.intervals(1).tolist() == [[1.5, np.sqrt(13) / 2]]
    assert cocycles[1][0].tolist() == [[1, 0, 1]]  # the side 0–1 of length 3, the last side
    assert stats[1]["reduced"] == 0
    grid = np.array([[x, y] for x in range(4) for y in range(3)], dtype=float)  # ties: many shortcuts
    stats = {}
    barcode, cocycles = rips_persistence(grid, max_dim=3, cocycles=True, stats=stats)
    assert stats[1]["emergent"] + stats[1]["apparent"] > 0 and stats[2]["emergent"] + stats[2]["apparent"] > 0
    assert [len(cocycles[k]) for k in (1, 2)] == [barcode.intervals(k).shape[0] for k in (1, 2)]
    check_all(rips(grid, max_dim=3), barcode, cocycles, 2, (1, 2))


# ---------------------------------------------------------------------------------------- the barcode
@pytest.mark.parametrize("seed", range(3))
def test_the_barcode_does_not_change_with_cocycles(seed):
    rng = np.random.default_rng(seed)
    points = np.round(rng.random((30, 3)), 1)
    eps = [np.inf, 0.3, 0.45][seed]
    stats_off: dict = {}
    stats_on: dict = {}
    off = rips_persistence(points, max_radius=eps, max_dim=3, coefficients=3, stats=stats_off)
    on, _ = rips_persistence(points, max_radius=eps, max_dim=3, coefficients=3, stats=stats_on, cocycles=True)
    ref = persistence(rips(points, max_radius=eps, max_dim=3), coefficients=3)
    for k in range(3):
        assert off.intervals(k).tobytes() == on.intervals(k).tobytes() == ref.intervals(k).tobytes()
    assert stats_off == stats_on  # the same reduction


def test_cocycles_follow_the_bars_that_are_kept():
    rng = np.random.default_rng(6)
    points = rng.random((25, 2))
    everything, all_cocycles = rips_persistence(points, max_dim=2, cocycles=True)
    cut = float(np.median(np.diff(everything.intervals(1), axis=1)))
    barcode, cocycles = rips_persistence(points, max_dim=2, min_persistence=cut, cocycles=True)
    assert 0 < barcode.intervals(1).shape[0] < everything.intervals(1).shape[0]
    check_all(rips(points, max_dim=2), barcode, cocycles, 2, (1,))
    kept = {(tuple(bar), str(c.tolist())) for bar, c in zip(barcode.intervals(1).tolist(), cocycles[1])}
    every = {(tuple(bar), str(c.tolist())) for bar, c in zip(everything.intervals(1).tolist(), all_cocycles[1])}
    assert kept <= every


def test_dimensions_beyond_the_points_have_no_cocycles():
    points = np.array([[0.0], [1.0], [3.0]])
    barcode, cocycles = rips_persistence(points, max_dim=6, cocycles=True)
    assert sorted(cocycles) == [1, 2, 3, 4, 5] and all(cocycles[k] == [] for k in cocycles)
    assert barcode.intervals(1).shape[0] == 0


@pytest.mark.parametrize("bad", ["yes", 2, None, 0.5, [True]])
def test_cocycles_must_be_true_or_false(bad):
    with pytest.raises(ValueError, match="cocycles must be True or False"):
        rips_persistence(np.random.default_rng(0).random((6, 2)), cocycles=bad)

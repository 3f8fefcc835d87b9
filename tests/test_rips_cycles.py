"""Representative cycles of the fast Rips engine (``rips_persistence(..., cycles=True)``).

Each cycle is checked on the explicit Rips filtration (:func:`thesis_lib.complexes.rips`) of the
whole input over Z/p, independently of how it was computed (the explicit engine on a truncated
complex): its boundary is zero; every simplex of the cycle of the bar [b, d) has value <= b and one
has value b (the creating simplex); for a finite bar it is in the span of the boundaries of the
(k + 1)-simplices of value <= d and not of those of value < d (a rank test over Z/p), and for an
essential bar of none.  The barcode is the same with and without the cycles, to the last bit.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse
from helpers import check_every_bar, facet_signs, simplex_vector
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import rips
from thesis_lib.homology.smith import rank_mod_p
from thesis_lib.persistence import rips_persistence


# ---------------------------------------------------------------------------------------- the checks
def _boundary(K, k: int, columns: np.ndarray) -> np.ndarray:
    """The boundary matrix from the (k + 1)-simplices ``columns`` to K's k-simplices (dense)."""
    F = K.facet_indices(k + 1)[columns]
    M = np.zeros((K.simplices[k].shape[0], columns.shape[0]), dtype=np.int64)
    M[F, np.arange(columns.shape[0])[:, None]] = facet_signs(k + 1)
    return M


def _is_boundary(K, k: int, c: np.ndarray, p: int, columns: np.ndarray) -> bool:
    """Whether c is in the span over Z/p of the boundaries of the (k + 1)-simplices ``columns``."""
    M = _boundary(K, k, columns)
    return rank_mod_p(np.column_stack([M, c]), coefficients=p) == rank_mod_p(M, coefficients=p)


def check_cycle(K, k: int, p: int, bar: np.ndarray, cycle: np.ndarray) -> None:
    """Every property of the module docstring for the cycle of the bar (birth, death) of H_k."""
    birth, death = bar
    assert cycle.dtype == np.int64 and cycle.ndim == 2 and cycle.shape[1] == k + 2 and cycle.shape[0] >= 1
    vertices, coefs = cycle[:, :-1], cycle[:, -1]
    assert (np.diff(vertices, axis=1) > 0).all()  # each simplex's vertices increasing
    assert ((coefs >= 1) & (coefs < p)).all()
    assert len({tuple(v) for v in vertices.tolist()}) == cycle.shape[0]
    c = simplex_vector(K, k, cycle)
    # a cycle: ∂c = 0 over Z/p
    F = K.facet_indices(k)
    boundary = np.zeros(K.simplices[k - 1].shape[0], dtype=np.int64)
    np.add.at(boundary, F.ravel(), (c[:, None] * facet_signs(k)).ravel())
    assert not (boundary % p).any()
    # born at b: every simplex by b, one at b
    values = K.values[k][c != 0]
    assert values.max() == birth
    # dies at d: a boundary at d, not before (an essential bar: never)
    up = K.values[k + 1]
    if np.isinf(death):
        assert not _is_boundary(K, k, c, p, np.arange(up.shape[0]))
    else:
        assert _is_boundary(K, k, c, p, np.flatnonzero(up <= death))
        assert not _is_boundary(K, k, c, p, np.flatnonzero(up < death))


def check_all(K, barcode, cycles, p: int, dims) -> int:
    """check_cycle on every bar of the dimensions; the number of bars checked."""
    assert sorted(cycles) == list(dims)
    return check_every_bar(barcode, cycles, dims, lambda k, bar, cycle: check_cycle(K, k, p, bar, cycle))


def same_barcode(a, b, dims) -> bool:
    return all(a.intervals(k).tobytes() == b.intervals(k).tobytes() for k in dims)


# ---------------------------------------------------------------------------------------- the cycles
@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("p", [2, 3, 5])
def test_every_cycle_is_born_and_dies_on_time(seed, p):
    rng = np.random.default_rng(seed)
    points = rng.random((14, 3))
    eps = [np.inf, 0.3, 0.45][seed]  # finite ones leave essential bars
    barcode, cycles = rips_persistence(points, max_radius=eps, max_dim=3, coefficients=p, cycles=True)
    assert same_barcode(barcode, rips_persistence(points, max_radius=eps, max_dim=3, coefficients=p), range(3))
    assert check_all(rips(points, max_radius=eps, max_dim=3), barcode, cycles, p, (1, 2)) > 0


@settings(deadline=None, max_examples=15)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(4, 12), d=st.integers(1, 3), p=st.sampled_from([2, 3, 5]),
       ties=st.booleans(), cut=st.booleans())
def test_cycles_hold_on_random_clouds_with_ties(seed, n, d, p, ties, cut):
    rng = np.random.default_rng(seed)
    points = rng.random((n, d))
    if ties:  # a grid: many equal distances, so many equal bars
        points = np.round(points * 3) / 3
    eps = float(rng.uniform(0.2, 0.6)) if cut else np.inf
    barcode, cycles = rips_persistence(points, max_radius=eps, max_dim=3, coefficients=p, cycles=True)
    check_all(rips(points, max_radius=eps, max_dim=3), barcode, cycles, p, (1, 2))


@pytest.mark.parametrize("p", [2, 3, 5])
def test_cycles_of_a_distance_matrix_and_of_its_sparse_form(p):
    rng = np.random.default_rng(p)
    a = rng.random((11, 11))
    dm = a + a.T + 1.0  # symmetric, not Euclidean
    np.fill_diagonal(dm, 0.0)
    eps = 1.4
    barcode, cycles = rips_persistence(distance_matrix=dm, max_radius=eps, max_dim=3, coefficients=p, cycles=True)
    assert check_all(rips(distance_matrix=dm, max_radius=eps, max_dim=3), barcode, cycles, p, (1, 2)) > 0
    cut = np.where(dm <= 2 * eps, dm, 0.0)
    sparse, sparse_cycles = rips_persistence(distance_matrix=scipy.sparse.csr_matrix(cut), max_radius=eps,
                                             max_dim=3, coefficients=p, cycles=True)
    assert same_barcode(sparse, barcode, range(3))
    for k in (1, 2):
        assert [c.tolist() for c in sparse_cycles[k]] == [c.tolist() for c in cycles[k]]


def test_short_bars_left_out_do_not_shift_the_cycles():
    """With ``min_persistence`` some bars are not reported; a left-out bar alive at the truncation radius
    is essential in the truncated complex, and must not be taken for a reported one."""
    points = np.random.default_rng(7).random((16, 2))
    bars = rips_persistence(points, max_dim=2, coefficients=3).intervals(1)
    lengths = bars[:, 1] - bars[:, 0]

    def left_out_alive(cut: float) -> bool:  # a dropped bar born by the truncation radius, dying after it
        radius = bars[lengths > cut, 1].max()
        return bool(((lengths <= cut) & (bars[:, 0] <= radius) & (bars[:, 1] > radius)).any())

    cut = next(c for c in np.unique(lengths)[:-1] if left_out_alive(c))
    barcode, cycles = rips_persistence(points, max_dim=2, coefficients=3, min_persistence=cut, cycles=True)
    assert 0 < barcode.intervals(1).shape[0] < bars.shape[0]
    check_all(rips(points, max_dim=2), barcode, cycles, 3, (1,))


def test_cycles_and_cocycles_together():
    points = np.random.default_rng(3).random((12, 3))
    plain = rips_persistence(points, max_radius=0.4, max_dim=3, coefficients=5)
    barcode, cocycles, cycles = rips_persistence(points, max_radius=0.4, max_dim=3, coefficients=5, cocycles=True,
                                                 cycles=True)
    _, alone = rips_persistence(points, max_radius=0.4, max_dim=3, coefficients=5, cocycles=True)
    _, cycles_alone = rips_persistence(points, max_radius=0.4, max_dim=3, coefficients=5, cycles=True)
    assert same_barcode(barcode, plain, range(3))
    for k in (1, 2):
        assert [c.tolist() for c in cocycles[k]] == [c.tolist() for c in alone[k]]
        assert [c.tolist() for c in cycles[k]] == [c.tolist() for c in cycles_alone[k]]
    check_all(rips(points, max_radius=0.4, max_dim=3), barcode, cycles, 5, (1, 2))


def test_the_square():
    """A square of side 2: its one loop [1, √2) is the four sides; over Z/3 one of them has sign 2."""
    square = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    barcode, cycles = rips_persistence(square, max_dim=2, coefficients=3, cycles=True)
    assert sorted(map(tuple, cycles[1][0][:, :2].tolist())) == [(0, 1), (0, 3), (1, 2), (2, 3)]
    check_all(rips(square, max_dim=2), barcode, cycles, 3, (1,))
    assert rips_persistence(square, max_dim=1, cycles=True)[1] == {}  # no dimension k in 1 .. max_dim − 1


def test_the_checks_can_fail():
    """A boundary is no cycle of a bar; a chain cut short is no cycle; a wrong birth or death is seen."""
    square = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    K = rips(square, max_dim=2)
    barcode, cycles = rips_persistence(square, max_dim=2, coefficients=3, cycles=True)
    bar, cycle = barcode.intervals(1)[0], cycles[1][0]
    check_cycle(K, 1, 3, bar, cycle)
    for wrong_bar in ([0.5, bar[1]], [bar[0], 1.2], [bar[0], np.inf]):
        with pytest.raises(AssertionError):
            check_cycle(K, 1, 3, np.array(wrong_bar), cycle)
    with pytest.raises(AssertionError):
        check_cycle(K, 1, 3, bar, cycle[:3])  # three sides: a boundary remains
    with pytest.raises(AssertionError):
        check_cycle(K, 1, 2, bar, cycle)  # over Z/2 the coefficient 2 is not allowed
    triangle = np.array([[0, 1, 1], [0, 2, 2], [1, 2, 1]])  # ∂(012): a cycle that is a boundary at √2
    with pytest.raises(AssertionError):
        check_cycle(K, 1, 3, bar, triangle)


# ---------------------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("bad", ["yes", 2, None, 0.5, [True]])
def test_cycles_must_be_a_flag(bad):
    with pytest.raises(ValueError, match="cycles must be True or False"):
        rips_persistence(np.eye(3), max_dim=2, cycles=bad)

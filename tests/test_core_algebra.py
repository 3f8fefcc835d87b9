"""The compiled elimination and modular Smith kernels (src/sparse_elimination.cpp, src/modular_smith.cpp):
bad shapes, out-of-range indices and entries beyond the int64-safe range are refused with ValueError
(never a crash or a wrapped-around product), and the kernels' answers are right."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
import sympy
from helpers import sympy_invariants

from thesis_lib._core import modular_smith, sparse_elimination
from thesis_lib.homology._elimination import LIMIT

I64 = np.int64


def csc(a):
    m = sp.csc_matrix(np.asarray(a, dtype=I64))
    m.sort_indices()
    return m


def markowitz(m, p=0, skip=None, lim=LIMIT, search=4, density=0.2, max_dense=2 * 10**7, n_rows=None):
    skip = np.zeros(m.shape[1], dtype=bool) if skip is None else skip
    return sparse_elimination.markowitz(m.indptr.astype(I64), m.indices.astype(I64), m.data.astype(I64),
                                        m.shape[0] if n_rows is None else n_rows, skip,
                                        sparse_elimination.Options(p, lim, search, density, max_dense))


def test_markowitz_rank_mod_p_matches_gauss_jordan():
    rng = np.random.default_rng(0)
    for _ in range(20):
        a = np.where(rng.random((15, 12)) < 0.3, rng.integers(-3, 4, (15, 12)), 0)
        for p in (2, 3, 7):
            rank, rows, core_rows, ptr, cols, vals = markowitz(csc(a), p, density=2.0)
            assert core_rows.size == 0 and rows.dtype == np.bool_ and rows.sum() == rank
            assert rank == _rank_mod(a, p)


def _rank_mod(a, p):
    a = [[int(x) % p for x in row] for row in a]
    r = 0
    for c in range(len(a[0]) if a else 0):
        piv = next((i for i in range(r, len(a)) if a[i][c]), None)
        if piv is None:
            continue
        a[r], a[piv] = a[piv], a[r]
        inv = pow(a[r][c], -1, p)
        for i in range(len(a)):
            if i != r and a[i][c]:
                f = a[i][c] * inv % p
                a[i] = [(x - f * y) % p for x, y in zip(a[i], a[r])]
        r += 1
    return r


def test_markowitz_over_z_keeps_the_smith_form():
    rng = np.random.default_rng(1)
    for _ in range(15):
        a = np.where(rng.random((12, 10)) < 0.35, rng.choice([-1, 1, 2, 3], (12, 10)), 0)
        rank, rows, core_rows, ptr, cols, vals = markowitz(csc(a), 0, density=2.0)
        core = np.zeros((core_rows.size, 10), dtype=I64)
        core[np.repeat(np.arange(core_rows.size), np.diff(ptr)), cols] = vals
        assert sorted([1] * rank + sympy_invariants(core)) == sorted(sympy_invariants(a))


def test_markowitz_sets_aside_steps_that_would_overflow():
    # pivot 1 at (0, 0); eliminating row 1 would make 2^31 - (-1)(2^31) = 2^32 > lim
    a = np.array([[1, LIMIT], [-1, LIMIT]], dtype=I64)
    rank, rows, core_rows, ptr, cols, vals = markowitz(csc(a), 0, density=2.0)
    assert np.abs(vals).max() <= LIMIT
    assert rank + core_rows.size >= 1


@pytest.mark.parametrize("bad", [
    dict(indptr=np.array([0, 3], dtype=I64)),  # indptr beyond indices
    dict(indptr=np.array([1, 0], dtype=I64)),  # decreasing
    dict(indptr=np.array([], dtype=I64)),
    dict(indices=np.array([0, 5], dtype=I64)),  # row out of range
    dict(indices=np.array([0, -1], dtype=I64)),
    dict(indices=np.array([1, 0], dtype=I64)),  # unsorted
    dict(indices=np.array([1, 1], dtype=I64)),  # duplicate
    dict(data=np.array([1], dtype=I64)),  # length mismatch
    dict(data=np.array([1, 2**31 + 1], dtype=I64)),  # beyond lim over Z
    dict(data=np.array([1, -(2**63)], dtype=I64)),
    dict(skip=np.zeros(3, dtype=bool)),
    dict(p=1), dict(p=-3), dict(p=2**31), dict(lim=2**31 + 1), dict(lim=-1), dict(search=-1),
    dict(density=float("nan")), dict(n_rows=-1), dict(n_rows=2**31),
])
def test_markowitz_refuses_bad_input(bad):
    args = dict(indptr=np.array([0, 2], dtype=I64), indices=np.array([0, 1], dtype=I64),
                data=np.array([1, 2], dtype=I64), n_rows=2, skip=np.zeros(1, dtype=bool), p=0, lim=LIMIT,
                search=4, density=0.2, max_dense=10)
    args.update(bad)
    options = sparse_elimination.Options(**{k: args.pop(k) for k in ("p", "lim", "search", "density", "max_dense")})
    with pytest.raises(ValueError):
        sparse_elimination.markowitz(**args, options=options)


def test_markowitz_empty_shapes():
    for m, n in ((0, 0), (0, 4), (4, 0), (3, 3)):
        rank, rows, core_rows, ptr, cols, vals = markowitz(csc(np.zeros((m, n))), 0)
        assert rank == 0 and rows.shape == (m,) and core_rows.size == 0 and list(ptr) == [0]


def test_dense_unit_elimination_over_z_and_mod_m():
    a = np.array([[2, 1, 0], [4, 3, 1], [0, 1, 1]], dtype=I64)
    b = a.copy()
    pivots, rows, cols = sparse_elimination.dense_unit_elimination(b, 0, LIMIT)
    assert pivots == 2 and rows.sum() == 2 and cols.sum() == 2
    rest = b[~rows][:, ~cols]
    assert abs(int(rest[0, 0])) == 0  # det a = 0 with two unit pivots: SNF = (1, 1, 0)
    b = np.mod(a, 6).astype(I64)
    pivots, rows, cols = sparse_elimination.dense_unit_elimination(b, 6, 0)
    assert pivots == 2  # 1 and then a unit mod 6


@pytest.mark.parametrize("a,p,lim", [
    (np.array([[7]], dtype=I64), 5, 0),  # entry beyond [0, p)
    (np.array([[-1]], dtype=I64), 5, 0),
    (np.array([[2**40]], dtype=I64), 0, LIMIT),  # beyond lim over Z
    (np.array([[-(2**63)]], dtype=I64), 0, LIMIT),
    (np.array([[1]], dtype=I64), 2**31, 0),
    (np.array([[1]], dtype=I64), -2, 0),
    (np.array([[1]], dtype=I64), 0, 2**32),
])
def test_dense_unit_elimination_refuses_bad_input(a, p, lim):
    with pytest.raises(ValueError):
        sparse_elimination.dense_unit_elimination(a, p, lim)


def test_dense_unit_elimination_never_copies_its_output():
    with pytest.raises(TypeError):  # int32 would be converted silently and the result lost
        sparse_elimination.dense_unit_elimination(np.eye(3, dtype=np.int32), 0, LIMIT)
    with pytest.raises(TypeError):
        sparse_elimination.dense_unit_elimination(np.asfortranarray(np.eye(3, dtype=I64))[:, :2], 0, LIMIT)


Q = 67108859  # the largest prime below 2^26


def test_rank_profile_and_det_adjugate_mod_q():
    rng = np.random.default_rng(3)
    for _ in range(10):
        b = rng.integers(-50, 50, (6, 6))
        y = rng.integers(-50, 50, (6, 2))
        rows, cols = modular_smith.rank_profile(np.mod(b, Q).astype(np.float64), Q)
        assert rows.size == cols.size == sympy.Matrix(b.tolist()).rank()
        det, z, ok = modular_smith.det_adjugate(np.mod(b, Q).astype(np.float64), np.mod(y, Q).astype(np.float64), Q)
        mb = sympy.Matrix(b.tolist())
        assert ok == (mb.det() % Q != 0)
        if ok:
            assert det == mb.det() % Q
            assert (np.array((mb.adjugate() * sympy.Matrix(y.tolist())).tolist(), dtype=object) % Q == z).all()


def test_inverse_mod_and_dixon_digits_solve():
    rng = np.random.default_rng(4)
    q = 2147483629  # prime below 2^31
    for r in (1, 3, 6):
        b = rng.integers(-9, 10, (r, r)).astype(I64)
        inv, ok = modular_smith.inverse_mod(b, q)
        if not ok:
            continue
        assert ((b.astype(object).dot(inv.astype(object))) % q == np.eye(r, dtype=object)).all()
        p = 1000003
        binv, _ = modular_smith.inverse_mod(b, p)
        y = rng.integers(-1000, 1000, (r, 2)).astype(I64)
        res = y.copy()
        d = modular_smith.dixon_digits(b, binv, res, p, 4)
        x = sum(d[i].astype(object) * p**i for i in range(4))  # b x ≡ y (mod p^4), residual carries the rest
        assert (b.astype(object).dot(x) + res.astype(object) * p**4 == y.astype(object)).all()


@pytest.mark.parametrize("call", [
    lambda: modular_smith.rank_profile(np.array([[Q + 0.0]]), Q),  # residue out of range
    lambda: modular_smith.rank_profile(np.array([[0.5]]), Q),
    lambda: modular_smith.rank_profile(np.array([[np.nan]]), Q),
    lambda: modular_smith.rank_profile(np.array([[1.0]]), 2**26 + 1),
    lambda: modular_smith.rank_profile(np.array([[1.0]]), 1),
    lambda: modular_smith.det_adjugate(np.ones((2, 3)), np.ones((2, 1)), Q),  # not square
    lambda: modular_smith.det_adjugate(np.ones((2, 2)), np.ones((3, 1)), Q),
    lambda: modular_smith.det_adjugate(np.ones((2, 2)), np.full((2, 1), -1.0), Q),
    lambda: modular_smith.inverse_mod(np.ones((2, 3), dtype=I64), 7),
    lambda: modular_smith.inverse_mod(np.ones((2, 2), dtype=I64), 2**31),
    lambda: modular_smith.dixon_digits(np.eye(2, dtype=I64), np.eye(3, dtype=I64), np.zeros((2, 1), I64), 7, 1),
    lambda: modular_smith.dixon_digits(np.eye(2, dtype=I64), np.eye(2, dtype=I64), np.zeros((3, 1), I64), 7, 1),
    lambda: modular_smith.dixon_digits(np.eye(2, dtype=I64), np.full((2, 2), 7, I64), np.zeros((2, 1), I64), 7, 1),
    lambda: modular_smith.dixon_digits(np.eye(2, dtype=I64), np.eye(2, dtype=I64), np.zeros((2, 1), I64), 7, -1),
    lambda: modular_smith.dixon_digits(np.eye(2, dtype=I64) * 2**40, np.eye(2, dtype=I64),  # r|b|p >= 2^62
                                       np.zeros((2, 1), I64), 2**31, 1),
    lambda: modular_smith.dixon_digits(np.eye(2, dtype=I64), np.eye(2, dtype=I64),
                                       np.full((2, 1), 2**62, I64), 7, 1),
])
def test_modular_kernels_refuse_bad_input(call):
    with pytest.raises(ValueError):
        call()


def test_modular_outputs_are_never_copies():
    with pytest.raises(TypeError):
        modular_smith.rank_profile(np.ones((2, 2), dtype=np.float32), Q)
    with pytest.raises(TypeError):
        modular_smith.dixon_digits(np.eye(2, dtype=I64), np.eye(2, dtype=I64), np.zeros((2, 1), np.int32), 7, 1)


def test_markowitz_terminates_when_a_row_only_reaches_a_column_set_aside():
    # the pivot 1 at (0, 0) would overflow (2^31 + 2^31 > lim) and the 2-block keeps the matrix sparse: a
    # search that only set the column aside would choose that pivot through row 0 forever; the row is set aside too
    a = np.zeros((52, 52), dtype=I64)
    a[0, 0], a[0, 1], a[1, 0], a[1, 1] = 1, LIMIT, -1, LIMIT
    a[np.arange(2, 52), np.arange(2, 52)] = 2
    rank, rows, core_rows, ptr, cols, vals = markowitz(csc(a), 0)
    assert rank == 0 and core_rows.size == 52
    from thesis_lib.homology.smith import smith_normal_form

    assert smith_normal_form(a).tolist() == [1] + [2] * 50 + [2**32]

"""The compiled stored-matrix reduction (src/reduction.cpp) and the explicit engine's kernels
(src/explicit_cohomology.cpp): values on small inputs, every dtype overload alike, and refusals of bad
shapes and out-of-range indices with ValueError (never a crash)."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib._core import explicit_cohomology, reduction
from thesis_lib.complexes import rips
from thesis_lib.homology.filtration import Filtration
from thesis_lib.persistence import compute_intervals, persistence
from thesis_lib.persistence.kernels import KEEP_REDUCED, KEEP_V, KEEP_V_ALL, reduce_columns


def _triangle_boundary():
    """∂ of the filled triangle (cells in filtration order: vertices 0-2, edges 3-5, triangle 6) as CSC."""
    cols = [[], [], [], [0, 1], [1, 2], [0, 2], [3, 4, 5]]
    coefs = [[], [], [], [-1, 1], [-1, 1], [-1, 1], [1, 1, -1]]
    indptr = np.concatenate([[0], np.cumsum([len(c) for c in cols])]).astype(np.int64)
    rows = np.array([r for c in cols for r in c], dtype=np.int64)
    vals = np.array([x for c in coefs for x in c], dtype=np.int64)
    pivot = np.array([max(c) if c else -1 for c in cols], dtype=np.int64)
    pivot_coef = np.array([cf[c.index(max(c))] if c else 0 for c, cf in zip(cols, coefs)], dtype=np.int64)
    return indptr, rows, vals, -np.arange(7, dtype=np.float64), pivot, pivot_coef


def _args(columns, keep=KEEP_REDUCED, p=3):
    indptr, rows, vals, row_value, pivot, pivot_coef = _triangle_boundary()
    return (indptr, rows, vals, row_value, np.asarray(columns, dtype=np.int64), np.zeros(7, dtype=np.bool_), pivot,
            pivot_coef, p, keep)


def test_the_triangle_reduces_as_by_hand():
    pc, pr, zero, adds, start, length, keys, coefs = reduce_columns(*_args([3, 4, 5, 6]))
    assert pc.tolist() == [3, 4, 6] and pr.tolist() == [1, 2, 5]  # edge 5 = 0-2 reduces to zero
    assert zero.tolist() == [5] and adds == 2
    assert start.tolist() == [-1] * 7  # nothing kept: the zero column is not stored under KEEP_REDUCED
    pc, pr, zero, adds, start, length, keys, coefs = reduce_columns(*_args([3, 4, 5, 6], KEEP_V_ALL))
    s = slice(start[5], start[5] + length[5])  # V_5 = 0-2 − 0-1 − 1-2 (mod 3): the 1-cycle
    assert dict(zip(keys[s].tolist(), coefs[s].tolist())) == {3: 2, 4: 2, 5: 1}
    for key in (KEEP_V, KEEP_V_ALL, KEEP_REDUCED):
        out = reduce_columns(*_args([], key))
        assert [o.shape[0] for o in out if isinstance(o, np.ndarray)] == [0, 0, 0, 7, 7, 0, 0]


def test_every_dtype_overload_gives_the_same_arrays():
    rng = np.random.default_rng(3)
    K = rips(rng.random((40, 2)), max_radius=0.35, max_dim=2)
    F = np.ascontiguousarray(K.facet_indices(2))
    up = np.ascontiguousarray(K.values[2])
    indptr, rows, signs, pivot, pivot_sign = explicit_cohomology.coboundary(F, up, K.simplices[1].shape[0])
    assert rows.dtype == np.int32 and signs.dtype == np.int8
    cols = np.ascontiguousarray(np.argsort(K.values[1], kind="stable")[::-1])
    cleared = np.zeros(K.simplices[1].shape[0], dtype=np.bool_)
    ref = None
    for r_dt in (np.int32, np.int64, np.int16, np.uint32):
        for c_dt in (np.int8, np.int64, np.int32):
            out = reduce_columns(indptr, rows.astype(r_dt), signs.astype(c_dt), up, cols, cleared, pivot, pivot_sign,
                                 np.int64(3), KEEP_V)
            if ref is None:
                ref = out
                assert ref[3] > 0  # the case reduces some columns
            for a, b in zip(ref, out):
                assert np.array_equal(a, b) and np.asarray(a).dtype == np.asarray(b).dtype


@pytest.mark.parametrize("seed", range(12))
def test_engine_agrees_with_the_thesis_algorithm(seed):
    rng = np.random.default_rng(seed)
    K = rips(rng.random((int(rng.integers(3, 14)), 2)), max_radius=0.5, max_dim=int(rng.integers(1, 4)))
    p = int(rng.choice([2, 3, 5]))
    fast, slow = persistence(K, coefficients=p), compute_intervals(K, coefficients=p)
    for d in range(K.dimension):
        assert np.array_equal(np.sort(fast.intervals(d), axis=0), np.sort(slow.intervals(d), axis=0))


def test_h0_pairs_and_essential_vertices():
    edges = np.array([[0, 1], [1, 2], [0, 2], [3, 4]], dtype=np.int64)
    vrank = np.arange(5, dtype=np.int64)
    pv, pe, negative, ess = explicit_cohomology.h0(edges, vrank, np.array([0, 1, 2, 3], dtype=np.int64))
    assert pv.tolist() == [1, 2, 4] and pe.tolist() == [0, 1, 3]
    assert negative.dtype == np.bool_ and negative.tolist() == [True, True, False, True]
    assert ess.tolist() == [0, 3]


def test_coboundary_of_the_triangle():
    edges = np.array([[0, 1], [0, 2], [1, 2]], dtype=np.int64)
    tris = np.array([[0, 1, 2]], dtype=np.int64)
    up = np.array([1.0])
    out = explicit_cohomology.coboundary_triangles(edges, tris, 3, up)
    assert out[5] == -1
    assert out[0].tolist() == [0, 1, 2, 3] and out[1].tolist() == [0, 0, 0]
    assert out[2].tolist() == [1, -1, 1]  # 1-2 omits vertex 0, 0-2 omits 1, 0-1 omits 2
    facets = np.array([[2, 1, 0]], dtype=np.int64)
    general = explicit_cohomology.coboundary(facets, up, 3)
    for a, b in zip(out[:5], general):
        assert np.array_equal(a, b) and a.dtype == b.dtype
    # a missing edge is reported by the triangle's index, not read out of the table
    assert explicit_cohomology.coboundary_triangles(edges[:2], np.array([[0, 1, 2]]), 3, up)[5] == 0


def test_a_missing_edge_is_a_value_error():
    K = Filtration([[[0], [1], [2]], [[0, 1], [1, 2]], [[0, 1, 2]]], [[0, 0, 0], [1, 1], [2]], validate=False)
    with pytest.raises(ValueError, match="missing"):
        persistence(K)


# ---------------------------------------------------------------------------- refusals
def _bad_reduce(**change):
    indptr, rows, vals, row_value, pivot, pivot_coef = _triangle_boundary()
    args = dict(indptr=indptr, rows=rows, coefs=vals, row_value=row_value, columns=np.array([3, 4, 5, 6]),
                cleared=np.zeros(7, dtype=np.bool_), pivot=pivot, pivot_coef=pivot_coef, p=3, keep=KEEP_REDUCED)
    args.update(change)
    return reduce_columns(**args)


@pytest.mark.parametrize("change", [
    {"indptr": np.empty(0, dtype=np.int64)},
    {"indptr": np.array([0, 0, 0, 0, 2, 1, 6, 9])},  # decreasing
    {"indptr": np.array([-1, 0, 0, 0, 2, 4, 6, 9])},
    {"indptr": np.array([0, 0, 0, 0, 2, 4, 6, 10])},  # beyond rows
    {"rows": np.array([0, 1, 1, 2, 0, 7, 3, 4, 5])},  # row 7 of 7 rows, in a column that is reduced
    {"rows": np.array([0, 1, 1, 2, -4, 2, 3, 4, 5])},
    {"coefs": np.ones(3, dtype=np.int64)},
    {"row_value": np.zeros(5)},  # fewer rows than the rows address
    {"columns": np.array([3, 7])},
    {"columns": np.array([-1])},
    {"cleared": np.zeros(6, dtype=np.bool_)},
    {"pivot": np.array([-1, -1, -1, 1, 2, 2, 7])},
    {"pivot": np.array([-1, -1, -1, 1, 2, -2, 5])},
    {"pivot_coef": np.zeros(8, dtype=np.int64)},
    {"p": 1},
    {"p": 2**31},
    {"keep": 3},
])
def test_reduce_columns_refuses_bad_input(change):
    with pytest.raises(ValueError):
        _bad_reduce(**change)


def test_reduce_columns_refuses_bad_dimensions():
    indptr, rows, vals, row_value, pivot, pivot_coef = _triangle_boundary()
    with pytest.raises((ValueError, TypeError)):
        state = reduction.ColumnState(np.array([3]), np.zeros(7, dtype=np.bool_), pivot, pivot_coef)
        reduction.reduce_columns(indptr[None], rows, vals, row_value, state, 3, 0)


def test_explicit_kernels_refuse_bad_input():
    e = np.array([[0, 1], [0, 2], [1, 2]], dtype=np.int64)
    t = np.array([[0, 1, 2]], dtype=np.int64)
    one = np.array([1.0])
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary(np.array([[0, 1, 3]], dtype=np.int64), one, 3)  # facet 3 of 3
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary(np.array([[0, -1, 2]], dtype=np.int64), one, 3)
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary(np.array([[0, 1, 2]], dtype=np.int64), np.ones(2), 3)  # values per coface
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary_triangles(e, np.array([[0, 1, 3]], dtype=np.int64), 3, one)  # vertex 3
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary_triangles(np.array([[0, 5]], dtype=np.int64), t, 3, one)
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary_triangles(e, t, -1, one)
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary_triangles(e, t, 3, np.ones(3))
    with pytest.raises(ValueError):
        explicit_cohomology.coboundary_triangles(e[:, :1].copy(), t, 3, one)  # edges need two columns
    with pytest.raises(ValueError):
        explicit_cohomology.h0(e, np.arange(2, dtype=np.int64), np.arange(3, dtype=np.int64))  # vertex 2 of 2
    with pytest.raises(ValueError):
        explicit_cohomology.h0(e, np.arange(3, dtype=np.int64), np.array([0, 1, 3], dtype=np.int64))  # edge 3
    with pytest.raises(ValueError):
        explicit_cohomology.h0(e[:2], np.arange(3, dtype=np.int64), np.array([0, 1, 2], dtype=np.int64))

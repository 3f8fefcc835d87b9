"""Smith normal form over Z and ranks over Z/p of sparse integer matrices.

The thesis (§2.2.1) reads homology off the Smith normal form of the boundary matrices: the number
of nonzero diagonal entries is the rank, entries ``>= 2`` are torsion.  Boundary matrices are huge
and sparse, and almost all of their elimination can be done with pivots ``±1``; so the engine here
works in three stages:

1. a sparse column echelon reduction (the "lowest nonzero row" reduction of persistence, in numba,
   int64 with overflow detection): a column whose lowest entry meets a pivot is reduced by it,
   exactly when the pivot is a unit, with an extended-gcd pair of column operations otherwise;
2. the few pivots that are not units are reduced against all unit pivots (clearing their rows),
   which splits the matrix, up to unimodular row/column operations, as ``I ⊕ core``;
3. a dense exact Smith normal form of the small ``core`` (int64 with overflow checks, falling back
   to Python integers).

If an int64 bound is hit in stage 1 or 2, the same algorithm is rerun on dictionaries of Python
integers (exact, slower).  Over Z/p every nonzero pivot is a unit and stage 1 alone gives the rank.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numba
import numpy as np
import scipy.sparse as sp

from .simplicial import check_coefficients

__all__ = ["smith_normal_form", "rank_mod_p", "reduce_matrix", "Reduction", "dense_smith_diagonal"]

#: Largest absolute value kept in int64 during sparse elimination: products of two such numbers plus
#: another product stay below 2**62, so one check per stored entry detects every overflow.
INT64_LIMIT = 2**30
#: Largest prime handled by the numba Z/p kernel (products of residues must fit in int64).
_MAX_NUMBA_PRIME = 2**31


class Reduction(NamedTuple):
    """Outcome of :func:`reduce_matrix` for one matrix.

    rank : rank over Z (or over Z/p).
    invariants : invariant factors ``>= 2`` of the Smith normal form over Z (empty over Z/p),
        ascending, each dividing the next (Python ints).
    unit_pivot_rows : boolean mask over the rows: rows that are the lowest entry of a reduced
        column with value ``±1`` (over Z/p: every pivot row).  Used for clearing.
    core_shape : shape of the dense core handed to the exact dense Smith normal form.
    exact_fallback : True if int64 overflowed and Python integers were used.
    """

    rank: int
    invariants: list[int]
    unit_pivot_rows: np.ndarray
    core_shape: tuple[int, int]
    exact_fallback: bool


# --------------------------------------------------------------------------------------------
# numba kernels (int64, overflow-checked)
# --------------------------------------------------------------------------------------------


@numba.njit(cache=True)
def _egcd(a, b):
    """g >= 0, x, y with x*a + y*b = g."""
    x0, y0, x1, y1 = 1, 0, 0, 1
    while b != 0:
        q = a // b
        a, b = b, a - q * b
        x0, x1 = x1, x0 - q * x1
        y0, y1 = y1, y0 - q * y1
    if a < 0:
        a, x0, y0 = -a, -x0, -y0
    return a, x0, y0


@numba.njit(cache=True)
def _combine(ai, av, alen, ca, bi, bv, bstart, blen, cb, p, lim, oi, ov, ostart):
    """Write ``ca * a + cb * b`` (sorted sparse vectors) to ``oi/ov[ostart:]``; return (length, overflow)."""
    i = 0
    j = 0
    n = ostart
    over = False
    while i < alen or j < blen:
        if j >= blen or (i < alen and ai[i] < bi[bstart + j]):
            idx = ai[i]
            val = ca * av[i]
            i += 1
        elif i >= alen or bi[bstart + j] < ai[i]:
            idx = bi[bstart + j]
            val = cb * bv[bstart + j]
            j += 1
        else:
            idx = ai[i]
            val = ca * av[i] + cb * bv[bstart + j]
            i += 1
            j += 1
        if p != 0:
            val = val % p
        elif val > lim or val < -lim:
            over = True
        if val != 0:
            oi[n] = idx
            ov[n] = val
            n += 1
    return n - ostart, over


@numba.njit(cache=True)
def _grow(arr, need):
    if need <= arr.shape[0]:
        return arr
    cap = arr.shape[0] * 2
    while cap < need:
        cap *= 2
    out = np.empty(cap, dtype=arr.dtype)
    out[: arr.shape[0]] = arr
    return out


@numba.njit(cache=True)
def _store(pool_i, pool_v, top, src_i, src_v, n, scale, p):
    pool_i = _grow(pool_i, top + n)
    pool_v = _grow(pool_v, top + n)
    for k in range(n):
        pool_i[top + k] = src_i[k]
        pool_v[top + k] = (src_v[k] * scale) % p if p != 0 else src_v[k]
    return pool_i, pool_v


@numba.njit(cache=True)
def _echelon_kernel(indptr, indices, data, n_rows, skip, p, lim):
    """Column echelon form by lowest-row reduction; pivots are stored per lowest row.

    Over Z only unit pivots (and exact multiples) are used to reduce: a column whose lowest entry
    is ±1 takes over a non-unit pivot (which is then reduced further), and a column that meets a
    non-unit pivot it cannot reduce exactly is set aside ("leftover") for the dense core.
    Over Z/p pivots are scaled to 1.

    Returns (piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, overflow).
    """
    n_cols = indptr.shape[0] - 1
    piv_start = np.full(n_rows, -1, dtype=np.int64)
    piv_len = np.zeros(n_rows, dtype=np.int64)
    pool_i = np.empty(max(16, 2 * indices.shape[0]), dtype=np.int64)
    pool_v = np.empty(pool_i.shape[0], dtype=np.int64)
    left_start = np.empty(16, dtype=np.int64)
    left_len = np.empty(16, dtype=np.int64)
    n_left = 0
    top = 0
    w_i = np.empty(n_rows + 1, dtype=np.int64)
    w_v = np.empty(n_rows + 1, dtype=np.int64)
    t_i = np.empty(n_rows + 1, dtype=np.int64)
    t_v = np.empty(n_rows + 1, dtype=np.int64)
    for j in range(n_cols):
        if skip[j]:
            continue
        n = 0
        for k in range(indptr[j], indptr[j + 1]):
            v = data[k]
            if p != 0:
                v = v % p
            elif v > lim or v < -lim:
                return piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, True
            if v != 0:
                w_i[n] = indices[k]
                w_v[n] = v
                n += 1
        while n > 0:
            r = w_i[n - 1]
            v = w_v[n - 1]
            if piv_len[r] == 0:
                scale = 1
                if p != 0:
                    _, scale, _ = _egcd(v, p)
                pool_i, pool_v = _store(pool_i, pool_v, top, w_i, w_v, n, scale, p)
                piv_start[r] = top
                piv_len[r] = n
                top += n
                break
            s = piv_start[r]
            L = piv_len[r]
            pv = pool_v[s + L - 1]
            if p != 0:
                n, over = _combine(w_i, w_v, n, 1, pool_i, pool_v, s, L, p - v, p, lim, t_i, t_v, 0)
            elif pv == 1 or pv == -1:
                n, over = _combine(w_i, w_v, n, 1, pool_i, pool_v, s, L, -v * pv, 0, lim, t_i, t_v, 0)
            elif v == 1 or v == -1:
                # the unit column becomes the pivot; the old pivot column is reduced by it
                pool_i, pool_v = _store(pool_i, pool_v, top, w_i, w_v, n, 1, 0)
                piv_start[r] = top
                piv_len[r] = n
                n, over = _combine(pool_i[s : s + L], pool_v[s : s + L], L, 1, pool_i, pool_v, top, n,
                                   -pv * v, 0, lim, t_i, t_v, 0)
                top += piv_len[r]
            elif v % pv == 0:
                n, over = _combine(w_i, w_v, n, 1, pool_i, pool_v, s, L, -(v // pv), 0, lim, t_i, t_v, 0)
            else:
                pool_i, pool_v = _store(pool_i, pool_v, top, w_i, w_v, n, 1, 0)
                left_start = _grow(left_start, n_left + 1)
                left_len = _grow(left_len, n_left + 1)
                left_start[n_left] = top
                left_len[n_left] = n
                n_left += 1
                top += n
                break
            if over:
                return piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, True
            w_i, t_i = t_i, w_i
            w_v, t_v = t_v, w_v
    return piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, False


@numba.njit(cache=True)
def _clear_core_kernel(piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, lim):
    """Reduce every non-unit pivot column and every leftover column against all unit pivots (stage 2).

    Returns (core_indptr, core_i, core_v, unit_mask, overflow); the core columns have no entry in
    a unit pivot row.
    """
    n_rows = piv_start.shape[0]
    unit = np.zeros(n_rows, dtype=np.bool_)
    todo_s = np.empty(n_rows + n_left, dtype=np.int64)
    todo_l = np.empty(n_rows + n_left, dtype=np.int64)
    n_todo = 0
    for r in range(n_rows):
        if piv_len[r] > 0:
            v = pool_v[piv_start[r] + piv_len[r] - 1]
            if v == 1 or v == -1:
                unit[r] = True
            else:
                todo_s[n_todo] = piv_start[r]
                todo_l[n_todo] = piv_len[r]
                n_todo += 1
    for k in range(n_left):
        todo_s[n_todo] = left_start[k]
        todo_l[n_todo] = left_len[k]
        n_todo += 1
    core_indptr = np.zeros(n_todo + 1, dtype=np.int64)
    core_i = np.empty(16, dtype=np.int64)
    core_v = np.empty(16, dtype=np.int64)
    w_i = np.empty(n_rows + 1, dtype=np.int64)
    w_v = np.empty(n_rows + 1, dtype=np.int64)
    t_i = np.empty(n_rows + 1, dtype=np.int64)
    t_v = np.empty(n_rows + 1, dtype=np.int64)
    c = 0
    for q in range(n_todo):
        n = todo_l[q]
        s0 = todo_s[q]
        for k in range(n):
            w_i[k] = pool_i[s0 + k]
            w_v[k] = pool_v[s0 + k]
        pos = n - 1
        while pos >= 0:
            row = w_i[pos]
            if not unit[row]:
                pos -= 1
                continue
            s = piv_start[row]
            L = piv_len[row]
            pv = pool_v[s + L - 1]
            n, over = _combine(w_i, w_v, n, 1, pool_i, pool_v, s, L, -w_v[pos] * pv, 0, lim, t_i, t_v, 0)
            if over:
                return core_indptr, core_i, core_v, unit, True
            w_i, t_i = t_i, w_i
            w_v, t_v = t_v, w_v
            # entries at rows above ``row`` are unchanged and the entry at ``row`` vanished
            pos = np.searchsorted(w_i[:n], row) - 1
        start = core_indptr[c]
        core_i = _grow(core_i, start + n)
        core_v = _grow(core_v, start + n)
        core_i[start : start + n] = w_i[:n]
        core_v[start : start + n] = w_v[:n]
        core_indptr[c + 1] = start + n
        c += 1
    return core_indptr, core_i, core_v, unit, False


# --------------------------------------------------------------------------------------------
# exact Python-integer engine (fallback on int64 overflow, and reference in tests)
# --------------------------------------------------------------------------------------------


def _axpy(a: dict, ca: int, b: dict, cb: int, p: int) -> dict:
    out = {}
    for k in a.keys() | b.keys():
        v = ca * a.get(k, 0) + cb * b.get(k, 0)
        if p:
            v %= p
        if v:
            out[k] = v
    return out


def _echelon_python(columns: list[dict], p: int) -> tuple[dict, list[dict]]:
    """Same reduction as :func:`_echelon_kernel` on dict columns of Python ints.

    Returns (pivots by lowest row, leftover columns).
    """
    pivots: dict[int, dict] = {}
    left: list[dict] = []
    for col in columns:
        w = {k: (v % p if p else v) for k, v in col.items()}
        w = {k: v for k, v in w.items() if v}
        while w:
            r = max(w)
            v = w[r]
            if r not in pivots:
                if p:
                    inv = pow(v, -1, p)
                    w = {k: (x * inv) % p for k, x in w.items()}
                pivots[r] = w
                break
            pc = pivots[r]
            pv = pc[r]
            if p:
                w = _axpy(w, 1, pc, p - v, p)
            elif pv in (1, -1):
                w = _axpy(w, 1, pc, -v * pv, 0)
            elif v in (1, -1):
                pivots[r] = w
                w = _axpy(pc, 1, w, -pv * v, 0)
            elif v % pv == 0:
                w = _axpy(w, 1, pc, -(v // pv), 0)
            else:
                left.append(w)
                break
    return pivots, left


def _egcd_py(a: int, b: int) -> tuple[int, int, int]:
    x0, y0, x1, y1 = 1, 0, 0, 1
    while b:
        q = a // b
        a, b = b, a - q * b
        x0, x1 = x1, x0 - q * x1
        y0, y1 = y1, y0 - q * y1
    if a < 0:
        a, x0, y0 = -a, -x0, -y0
    return a, x0, y0


def _clear_core_python(pivots: dict, left: list[dict]) -> tuple[list[dict], set]:
    unit = {r for r, c in pivots.items() if c[r] in (1, -1)}
    core = []
    for col in [c for r, c in pivots.items() if r not in unit] + left:
        w = dict(col)
        while True:
            hits = [k for k in w if k in unit]
            if not hits:
                break
            s = max(hits)
            pc = pivots[s]
            w = _axpy(w, 1, pc, -w[s] * pc[s], 0)
        core.append(w)
    return core, unit


# --------------------------------------------------------------------------------------------
# dense exact Smith normal form (small matrices)
# --------------------------------------------------------------------------------------------


def _dense_diagonal(a: np.ndarray) -> list[int]:
    """Diagonalise ``a`` (int64 or object) by unimodular operations; return |diagonal| entries.

    Raises OverflowError (int64 input only) when an update could leave int64.
    """
    a = a.copy()
    m, n = a.shape
    checked = a.dtype != object
    diag: list[int] = []
    t = 0
    while t < min(m, n):
        sub = a[t:, t:]
        nz = np.nonzero(sub)
        if nz[0].size == 0:
            break
        absv = np.abs(sub[nz])
        k = int(np.argmin(absv))
        i, j = nz[0][k] + t, nz[1][k] + t
        a[[t, i], :] = a[[i, t], :]
        a[:, [t, j]] = a[:, [j, t]]
        while True:
            piv = a[t, t]
            q = a[t + 1 :, t] // piv
            if checked and (np.abs(q).max(initial=0) > INT64_LIMIT or np.abs(a).max() > INT64_LIMIT):
                raise OverflowError
            a[t + 1 :, t:] -= np.outer(q, a[t, t:]).astype(a.dtype)
            q = a[t, t + 1 :] // piv
            if checked and (np.abs(q).max(initial=0) > INT64_LIMIT or np.abs(a).max() > INT64_LIMIT):
                raise OverflowError
            a[t:, t + 1 :] -= np.outer(a[t:, t], q).astype(a.dtype)
            col_nz = np.nonzero(a[t + 1 :, t])[0]
            row_nz = np.nonzero(a[t, t + 1 :])[0]
            if col_nz.size == 0 and row_nz.size == 0:
                break
            # move the smallest remainder into the pivot position; |pivot| strictly decreases
            best, where = None, None
            for ii in col_nz:
                v = abs(int(a[t + 1 + ii, t]))
                if best is None or v < best:
                    best, where = v, ("r", t + 1 + ii)
            for jj in row_nz:
                v = abs(int(a[t, t + 1 + jj]))
                if best is None or v < best:
                    best, where = v, ("c", t + 1 + jj)
            if where[0] == "r":
                a[[t, where[1]], :] = a[[where[1], t], :]
            else:
                a[:, [t, where[1]]] = a[:, [where[1], t]]
        diag.append(abs(int(a[t, t])))
        t += 1
    return diag


def _divisibility_chain(diag: list[int]) -> list[int]:
    """Turn a diagonal into invariant factors: diag(a, b) ~ diag(gcd, lcm)."""
    d = [abs(int(x)) for x in diag if x]
    for i in range(len(d)):
        for j in range(i + 1, len(d)):
            g = math.gcd(d[i], d[j])
            d[i], d[j] = g, d[i] // g * d[j]
    return d


def dense_smith_diagonal(matrix: np.ndarray) -> list[int]:
    """Invariant factors (nonzero Smith normal form diagonal, ascending by divisibility) of a small dense matrix.

    Thesis: Theorem 2.20 (Smith normal form by elementary row and column operations).

    Exact: works in int64 while entries are small and redoes the work with Python integers otherwise.
    """
    a = np.asarray(matrix)
    if a.ndim != 2:
        raise ValueError(f"matrix must be 2-D, got shape {a.shape}")
    if a.size == 0:
        return []
    if a.dtype != object:
        try:
            return _divisibility_chain(_dense_diagonal(a.astype(np.int64)))
        except OverflowError:
            pass
    return _divisibility_chain(_dense_diagonal(np.array([[int(x) for x in row] for row in a], dtype=object)))


# --------------------------------------------------------------------------------------------
# drivers
# --------------------------------------------------------------------------------------------


def _check_integer_entries(data: np.ndarray) -> None:
    dt = data.dtype
    if dt == bool or np.issubdtype(dt, np.integer):
        return
    if np.issubdtype(dt, np.floating):
        d = np.asarray(data, dtype=float)
        if not np.all(np.isfinite(d)):
            raise ValueError("matrix entries must be finite integers, got NaN or inf")
        if not np.all(d == np.round(d)):
            raise ValueError("matrix entries must be integers, got non-integral floats")
        if d.size and np.abs(d).max() >= 2**53:
            raise ValueError("float matrix entries too large to be exact integers")
        return
    raise ValueError(f"matrix entries must be integers, got dtype {dt}")


def _as_integer_csc(matrix) -> sp.csc_matrix | tuple[int, list[dict]]:
    """Validate an integer matrix; return int64 CSC, or (n_rows, dict columns) for huge entries."""
    if sp.issparse(matrix):
        if len(matrix.shape) != 2:
            raise ValueError("matrix must be 2-D")
        mat = sp.csc_matrix(matrix)
        _check_integer_entries(mat.data)
    else:
        arr = np.asarray(matrix)
        if arr.ndim != 2:
            raise ValueError(f"matrix must be 2-D, got shape {arr.shape}")
        if arr.dtype == object:
            if not all(isinstance(x, (int, np.integer)) and not isinstance(x, bool) for x in arr.flat):
                raise ValueError("matrix entries must be integers")
            if any(abs(int(x)) > INT64_LIMIT for x in arr.flat):
                cols = [{i: int(arr[i, j]) for i in range(arr.shape[0]) if arr[i, j]} for j in range(arr.shape[1])]
                return arr.shape[0], cols
            arr = arr.astype(np.int64)
        _check_integer_entries(arr)
        mat = sp.csc_matrix(arr.astype(np.int64))
    mat = sp.csc_matrix(mat, dtype=np.int64)
    mat.sum_duplicates()
    mat.eliminate_zeros()
    mat.sort_indices()
    return mat


def _csc_to_dicts(mat: sp.csc_matrix) -> list[dict]:
    out = []
    for j in range(mat.shape[1]):
        lo, hi = mat.indptr[j], mat.indptr[j + 1]
        out.append({int(i): int(v) for i, v in zip(mat.indices[lo:hi], mat.data[lo:hi])})
    return out


def _reduce_python(n_rows: int, columns: list[dict], p: int) -> Reduction:
    pivots, left = _echelon_python(columns, p)
    mask = np.zeros(n_rows, dtype=bool)
    if p:
        mask[list(pivots)] = True
        return Reduction(len(pivots), [], mask, (0, 0), True)
    core, unit = _clear_core_python(pivots, left)
    mask[list(unit)] = True
    return _finish(len(unit), core, mask, True)


def _finish(n_unit: int, core: list[dict], mask: np.ndarray, fallback: bool) -> Reduction:
    rows = sorted(set().union(*core)) if core else []
    pos = {r: i for i, r in enumerate(rows)}
    big = any(abs(v) > INT64_LIMIT for c in core for v in c.values())
    dense = np.zeros((len(rows), len(core)), dtype=object if big else np.int64)
    for j, c in enumerate(core):
        for r, v in c.items():
            dense[pos[r], j] = v
    inv = dense_smith_diagonal(dense) if core else []
    rank = n_unit + len(inv)
    torsion = [int(x) for x in inv if x > 1]
    return Reduction(rank, torsion, mask, dense.shape, fallback)


def reduce_matrix(
    matrix,
    coefficients: int = 0,
    skip_columns: np.ndarray | None = None,
    *,
    int64_limit: int = INT64_LIMIT,
) -> Reduction:
    """Rank and torsion invariants of an integer matrix by sparse unit-pivot elimination.

    Thesis: §2.2.1 (Smith normal form of boundary matrices, torsion from diagonal entries ≥ 2).

    Parameters
    ----------
    matrix : dense array or scipy sparse matrix with integer entries.
    coefficients : 0 for Z, a prime p for Z/p.
    skip_columns : optional boolean mask of columns to ignore (clearing: columns known to become
        zero after a unimodular change of basis).
    int64_limit : bound on |entries| in the int64 kernel; beyond it the exact Python engine is used
        (lowering it forces that path, e.g. in tests).

    Returns
    -------
    Reduction
    """
    p = check_coefficients(coefficients)
    checked = _as_integer_csc(matrix)
    if isinstance(checked, tuple):
        n_rows, cols = checked
        if skip_columns is not None:
            cols = [c for c, s in zip(cols, np.asarray(skip_columns, bool)) if not s]
        return _reduce_python(n_rows, cols, p)
    mat = checked
    n_rows, n_cols = mat.shape
    if skip_columns is None:
        skip = np.zeros(n_cols, dtype=np.bool_)
    else:
        skip = np.asarray(skip_columns, dtype=np.bool_)
        if skip.shape != (n_cols,):
            raise ValueError(f"skip_columns must be a boolean mask of length {n_cols}, got shape {skip.shape}")
    if p >= _MAX_NUMBA_PRIME:
        cols = [c for c, s in zip(_csc_to_dicts(mat), skip) if not s]
        return _reduce_python(n_rows, cols, p)
    indptr = mat.indptr.astype(np.int64)
    indices = mat.indices.astype(np.int64)
    data = mat.data.astype(np.int64)
    piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, over = _echelon_kernel(
        indptr, indices, data, n_rows, skip, np.int64(p), np.int64(int64_limit)
    )
    if not over and p:
        mask = piv_len > 0
        return Reduction(int(mask.sum()), [], mask, (0, 0), False)
    if not over:
        cptr, ci, cv, unit, over = _clear_core_kernel(
            piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, np.int64(int64_limit)
        )
    if over:
        cols = [c for c, s in zip(_csc_to_dicts(mat), skip) if not s]
        return _reduce_python(n_rows, cols, p)
    core = [
        {int(i): int(v) for i, v in zip(ci[cptr[c] : cptr[c + 1]], cv[cptr[c] : cptr[c + 1]])}
        for c in range(cptr.shape[0] - 1)
    ]
    return _finish(int(unit.sum()), core, unit, False)


def smith_normal_form(matrix) -> np.ndarray:
    """Diagonal of the Smith normal form over Z: the nonzero invariant factors a_1 | a_2 | ... .

    Thesis: Theorem 2.20 and §2.2.1 (PAQ = diag(a_1, ..., a_k, 0, ..., 0) with a_i | a_{i+1}).

    Parameters
    ----------
    matrix : 2-D integer array (numpy, nested lists, object array of Python ints) or scipy sparse.

    Returns
    -------
    numpy array of the positive invariant factors (int64, or object dtype if an entry exceeds int64).

    Raises
    ------
    ValueError
        If the matrix is not 2-D or has non-integer, NaN or infinite entries.
    """
    red = reduce_matrix(matrix, 0)
    n_ones = red.rank - len(red.invariants)
    values = [1] * n_ones + list(red.invariants)
    if any(v >= 2**63 for v in values):
        return np.array(values, dtype=object)
    return np.array(values, dtype=np.int64)


def rank_mod_p(matrix, p: int) -> int:
    """Rank of an integer matrix over the field Z/p (p prime) by sparse elimination mod p.

    Thesis: §2.2.1 (working over Z_p, where every nonzero pivot is invertible).
    """
    if check_coefficients(p) == 0:
        raise ValueError("rank_mod_p needs a prime p, got 0")
    return reduce_matrix(matrix, p).rank

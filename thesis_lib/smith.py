"""Smith normal form over Z and ranks over Z/p of sparse integer matrices.

The thesis (§2.2.1) reads homology off the Smith normal form of the boundary matrices: the number
of nonzero diagonal entries is the rank, entries ``>= 2`` are torsion.  Boundary matrices are huge
and sparse, and almost all of their elimination can be done with pivots ``±1``; so the engine here
works in two stages:

1. a sparse column reduction in numba (int64, overflow detected) that pivots on units only: each
   column is reduced at its lowest entry, by the pivot of that row (always ±1); an entry that is
   not a unit in a row without pivot makes that row "postponed" and the reduction goes on above
   it.  The unit pivots form a unimodular triangular block, so up to unimodular row and column
   operations the matrix is ``I ⊕ core``, where the core is the columns left with entries in
   postponed rows only;
2. the small core: more unit-pivot passes on its transpose (SNF(A) = SNF(Aᵀ)) while they find
   pivots, then a dense exact Smith normal form (int64 with overflow checks, else Python integers).

A column whose stage-1 reduction would overflow int64 is finished with Python integers from the
kernel's state (exact, slower).  Over Z/p every nonzero entry is a unit and stage 1 alone gives the
rank.

Limits: boundary matrices of Rips, alpha and triangulated manifolds leave no or a tiny core.
Random Linial–Meshulam 2-complexes near their homological threshold are the hard case: their core
is dense with entries ~10⁶ (n = 100 vertices: 130 × 1645, about 2 s; n = 150: 337 × 3994, which
the naive dense elimination in Python integers does not finish in minutes).  A modular
(determinant-based) dense Smith normal form would be the remedy there.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numba
import numpy as np
import scipy.sparse as sp

from ._validate import MAX_EXACT_PRIME, check_coefficients

__all__ = ["smith_normal_form", "rank_mod_p", "reduce_matrix", "Reduction", "dense_smith_diagonal"]

#: Largest absolute value kept in int64 during sparse elimination: an update w + c * pivot with
#: |w|, |c|, |pivot| <= 2**30 stays below 2**61, so one check per stored entry detects overflow.
INT64_LIMIT = 2**30
#: Largest prime handled by the numba Z/p kernel (products of residues must fit in int64).
_MAX_NUMBA_PRIME = 2**31


class Reduction(NamedTuple):
    """Outcome of :func:`reduce_matrix` for one matrix.

    Thesis: §2.2.1 (k_p = number of nonzero SNF entries; entries ≥ 2 give torsion).

    rank : rank over Z (or over Z/p).
    invariants : invariant factors ``>= 2`` of the Smith normal form over Z (empty over Z/p),
        ascending, each dividing the next (Python ints).
    unit_pivot_rows : boolean mask over the rows that carry a pivot ±1 (a reduced column that is
        ±1 there and zero on the non-postponed rows below).  Used for clearing.
    core_shape : shape of the core left by the sparse unit-pivot stage (postponed rows x columns).
    exact_fallback : True if some columns were finished with Python integers (int64 would overflow).
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
    """Unit-pivot column reduction; pivots are stored per pivot row.

    A column is reduced at its lowest entry that is not in a "postponed" row.  If that row has a
    pivot (always ±1) the entry is eliminated; if not and the entry is ±1 the column becomes the
    pivot of that row; otherwise the row is postponed (marked bad) and the reduction continues
    above it.  A column supported on postponed rows only is kept as a core column.  Pivot rows are
    never postponed, and every pivot column vanishes on the non-postponed rows below its pivot, so
    the unit pivots form a unimodular triangular block and SNF = I ⊕ SNF(core columns on the
    postponed rows).  Over Z/p every nonzero entry is a unit: nothing is postponed, pivots are 1.

    A column whose reduction would leave int64 is abandoned and listed in ``deferred``; the
    caller finishes it with Python integers (any column order gives a valid reduction).

    Returns (piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, bad, deferred).
    """
    n_cols = indptr.shape[0] - 1
    piv_start = np.full(n_rows, -1, dtype=np.int64)
    piv_len = np.zeros(n_rows, dtype=np.int64)
    bad = np.zeros(n_rows, dtype=np.bool_)
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
    deferred = np.empty(16, dtype=np.int64)
    n_def = 0
    for j in range(n_cols):
        if skip[j]:
            continue
        n = 0
        over = False
        for k in range(indptr[j], indptr[j + 1]):
            v = data[k]
            if p != 0:
                v = v % p
            elif v > lim or v < -lim:
                over = True
            if v != 0:
                w_i[n] = indices[k]
                w_v[n] = v
                n += 1
        pos = n - 1
        while not over:
            while pos >= 0 and bad[w_i[pos]]:
                pos -= 1
            if pos < 0:
                if n > 0:  # supported on postponed rows only: a core column
                    pool_i, pool_v = _store(pool_i, pool_v, top, w_i, w_v, n, 1, 0)
                    left_start = _grow(left_start, n_left + 1)
                    left_len = _grow(left_len, n_left + 1)
                    left_start[n_left] = top
                    left_len[n_left] = n
                    n_left += 1
                    top += n
                break
            r = w_i[pos]
            v = w_v[pos]
            if piv_len[r] == 0:
                if p != 0:
                    _, scale, _ = _egcd(v, p)
                    pool_i, pool_v = _store(pool_i, pool_v, top, w_i, w_v, n, scale, p)
                elif v == 1 or v == -1:
                    pool_i, pool_v = _store(pool_i, pool_v, top, w_i, w_v, n, 1, 0)
                else:
                    bad[r] = True
                    pos -= 1
                    continue
                piv_start[r] = top
                piv_len[r] = n
                top += n
                break
            s = piv_start[r]
            L = piv_len[r]
            pv = pool_v[s + L - 1]
            if p != 0:
                # the pivot is 1 at row r; its last entry is its lowest, which is row r
                n, over = _combine(w_i, w_v, n, 1, pool_i, pool_v, s, L, p - v, p, lim, t_i, t_v, 0)
            else:
                pv = pool_v[s + _find(pool_i, s, L, r)]
                n, over = _combine(w_i, w_v, n, 1, pool_i, pool_v, s, L, -v * pv, 0, lim, t_i, t_v, 0)
            if over:
                break
            w_i, t_i = t_i, w_i
            w_v, t_v = t_v, w_v
            # entries below row r are unchanged and the entry at r vanished
            pos = np.searchsorted(w_i[:n], r) - 1
        if over:  # int64 would overflow: this column is finished exactly in Python
            deferred = _grow(deferred, n_def + 1)
            deferred[n_def] = j
            n_def += 1
    return piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, bad, deferred[:n_def]


@numba.njit(cache=True)
def _find(arr, start, length, value):
    """Offset of ``value`` in the sorted slice ``arr[start : start + length]``."""
    return np.searchsorted(arr[start : start + length], value)


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


def _echelon_python(columns: list[dict], p: int, fetch=None, bad: set | None = None) -> tuple[dict, list[dict]]:
    """The reduction of :func:`_echelon_kernel` on dict columns of Python ints.

    ``fetch(r)`` (optional) returns an existing pivot column of row ``r`` as a dict, or None, and
    ``bad`` the rows already postponed: the reduction then continues the kernel's.
    Returns (pivot columns created or used, by row; core columns supported on postponed rows).
    """
    pivots: dict[int, dict] = {}
    bad = set() if bad is None else bad
    core: list[dict] = []

    def pivot(r: int):
        if r not in pivots and fetch is not None:
            col = fetch(r)
            if col is not None:
                pivots[r] = col
        return pivots.get(r)

    for col in columns:
        w = {k: (v % p if p else v) for k, v in col.items()}
        w = {k: v for k, v in w.items() if v}
        while True:
            live = [k for k in w if k not in bad]
            if not live:
                if w:
                    core.append(w)
                break
            r = max(live)
            v = w[r]
            pc = pivot(r)
            if pc is not None:
                w = _axpy(w, 1, pc, (p - v) if p else -v * pc[r], p)
            elif p:
                inv = pow(v, -1, p)
                pivots[r] = {k: (x * inv) % p for k, x in w.items()}
                break
            elif v in (1, -1):
                pivots[r] = w
                break
            else:
                bad.add(r)
    return pivots, core


# --------------------------------------------------------------------------------------------
# dense exact Smith normal form (small matrices)
# --------------------------------------------------------------------------------------------


def _step_is_safe(q: np.ndarray, vec: np.ndarray, block: np.ndarray) -> bool:
    """Whether ``block - outer(q, vec)`` stays within int64."""
    if q.size == 0 or vec.size == 0:
        return True
    return int(np.abs(q).max()) * int(np.abs(vec).max()) + int(np.abs(block).max()) < 2**62


def _dense_diagonal(a: np.ndarray) -> list[int]:
    """Diagonalise ``a`` by unimodular operations; return the |diagonal| entries.

    Pivots on an entry of least absolute value (ties: least Markowitz cost), clears its row and
    column by integer division, and repeats with the remainders; zero rows and columns are dropped
    as they appear.  Works in int64 while every update provably fits, then switches the (partly
    reduced) matrix to Python integers.
    """
    a = a.copy()
    diag: list[int] = []
    while a.size:
        nz = a != 0
        rows, cols = nz.any(axis=1), nz.any(axis=0)
        a, nz = a[rows][:, cols], nz[rows][:, cols]
        if a.size == 0:
            break
        absa = np.abs(a)
        smallest = absa[nz].min()
        cand = np.argwhere(absa == smallest)
        cost = (nz.sum(axis=1)[cand[:, 0]] - 1) * (nz.sum(axis=0)[cand[:, 1]] - 1)
        i, j = cand[int(np.argmin(cost))]
        a[[0, i], :] = a[[i, 0], :]
        a[:, [0, j]] = a[:, [j, 0]]
        while True:
            piv = a[0, 0]
            q = a[1:, 0] // piv
            if a.dtype != object and not _step_is_safe(q, a[0], a[1:]):
                a, q = a.astype(object), q.astype(object)
            a[1:] -= np.outer(q, a[0]).astype(a.dtype)
            q = a[0, 1:] // piv
            if a.dtype != object and not _step_is_safe(q, a[:, 0], a[:, 1:]):
                a, q = a.astype(object), q.astype(object)
            a[:, 1:] -= np.outer(a[:, 0], q).astype(a.dtype)
            rest_c = np.abs(a[1:, 0])
            rest_r = np.abs(a[0, 1:])
            if not rest_c.any() and not rest_r.any():
                break
            # bring the smallest remainder to the pivot position: |pivot| strictly decreases
            big = max(int(rest_c.max(initial=0)), int(rest_r.max(initial=0))) + 1
            mc = np.where(rest_c != 0, rest_c, big)
            mr = np.where(rest_r != 0, rest_r, big)
            ic = int(np.argmin(mc)) if mc.size else -1
            ir = int(np.argmin(mr)) if mr.size else -1
            if ir < 0 or (ic >= 0 and mc[ic] <= mr[ir]):
                a[[0, ic + 1], :] = a[[ic + 1, 0], :]
            else:
                a[:, [0, ir + 1]] = a[:, [ir + 1, 0]]
        diag.append(abs(int(a[0, 0])))
        a = a[1:, 1:]
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

    Exact: works in int64 while every update provably fits, then continues with Python integers.
    """
    a = np.asarray(matrix)
    if a.ndim != 2:
        raise ValueError(f"matrix must be 2-D, got shape {a.shape}")
    if a.size == 0:
        return []
    if a.dtype == object:
        if not all(isinstance(x, (int, np.integer)) and not isinstance(x, bool) for x in a.flat):
            raise ValueError("matrix entries must be integers")
        a = np.array([[int(x) for x in row] for row in a], dtype=object)
        if all(abs(x) <= INT64_LIMIT for x in a.flat):
            a = a.astype(np.int64)
    else:
        _check_integer_entries(a)
        a = a.astype(np.int64)
    return _divisibility_chain(_dense_diagonal(a))


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


def _sparse_stage(mat: sp.csc_matrix, p: int, skip: np.ndarray, limit: int) -> tuple[int, list[dict], np.ndarray, bool]:
    """Unit-pivot stage on a validated int64 CSC matrix: (n_pivots, core columns, pivot-row mask, exact)."""
    n_rows = mat.shape[0]
    if p >= _MAX_NUMBA_PRIME:
        cols = [c for c, s in zip(_csc_to_dicts(mat), skip) if not s]
        return _python_stage(n_rows, cols, p)
    piv_start, piv_len, pool_i, pool_v, left_start, left_len, n_left, bad, deferred = _echelon_kernel(
        mat.indptr.astype(np.int64), mat.indices.astype(np.int64), mat.data.astype(np.int64),
        n_rows, skip, np.int64(p), np.int64(limit),
    )
    core = [
        {int(i): int(v) for i, v in zip(pool_i[s : s + n], pool_v[s : s + n])}
        for s, n in zip(left_start[:n_left], left_len[:n_left])
    ]
    mask = piv_len > 0
    if deferred.size:  # finish the columns that would overflow int64 with Python integers

        def fetch(r: int):
            if piv_len[r] == 0:
                return None
            s, n = piv_start[r], piv_len[r]
            return {int(i): int(v) for i, v in zip(pool_i[s : s + n], pool_v[s : s + n])}

        cols = []
        for j in deferred:
            lo, hi = mat.indptr[j], mat.indptr[j + 1]
            cols.append({int(i): int(v) for i, v in zip(mat.indices[lo:hi], mat.data[lo:hi])})
        pivots, more = _echelon_python(cols, p, fetch, set(np.flatnonzero(bad).tolist()))
        mask[list(pivots)] = True
        core += more
    return int(mask.sum()), core, mask, bool(deferred.size)


def _python_stage(n_rows: int, columns: list[dict], p: int) -> tuple[int, list[dict], np.ndarray, bool]:
    pivots, core = _echelon_python(columns, p)
    mask = np.zeros(n_rows, dtype=bool)
    mask[list(pivots)] = True
    return len(pivots), core, mask, True


def _core_to_dense(core: list[dict]) -> np.ndarray:
    rows = sorted(set().union(*core)) if core else []
    pos = {r: i for i, r in enumerate(rows)}
    big = any(abs(v) > INT64_LIMIT for c in core for v in c.values())
    dense = np.zeros((len(rows), len(core)), dtype=object if big else np.int64)
    for j, c in enumerate(core):
        for r, v in c.items():
            dense[pos[r], j] = v
    return dense


def _core_invariants(dense: np.ndarray, limit: int) -> list[int]:
    """Invariant factors of the core: more unit-pivot passes on its transpose, then dense SNF."""
    ones = 0
    while dense.size and dense.dtype != object:
        t = sp.csc_matrix(np.ascontiguousarray(dense.T))
        n_unit, core, _, _ = _sparse_stage(t, 0, np.zeros(t.shape[1], dtype=np.bool_), limit)
        if n_unit == 0:
            break
        ones += n_unit
        dense = _core_to_dense(core)
    return [1] * ones + (dense_smith_diagonal(dense) if dense.size else [])


def _finish(stage: tuple[int, list[dict], np.ndarray, bool], limit: int) -> Reduction:
    n_unit, core, mask, fallback = stage
    dense = _core_to_dense(core)
    inv = _core_invariants(dense, limit)
    torsion = [int(x) for x in inv if x > 1]
    return Reduction(n_unit + len(inv), torsion, mask, dense.shape, fallback)


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
    p = check_coefficients(coefficients, max_prime=MAX_EXACT_PRIME)
    checked = _as_integer_csc(matrix)
    if isinstance(checked, tuple):  # entries beyond int64: exact engine throughout
        n_rows, cols = checked
        if skip_columns is not None:
            cols = [c for c, s in zip(cols, np.asarray(skip_columns, bool)) if not s]
        return _finish(_python_stage(n_rows, cols, p), int64_limit)
    n_cols = checked.shape[1]
    if skip_columns is None:
        skip = np.zeros(n_cols, dtype=np.bool_)
    else:
        skip = np.asarray(skip_columns, dtype=np.bool_)
        if skip.shape != (n_cols,):
            raise ValueError(f"skip_columns must be a boolean mask of length {n_cols}, got shape {skip.shape}")
    return _finish(_sparse_stage(checked, p, skip, int64_limit), int64_limit)


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
    if check_coefficients(p, max_prime=MAX_EXACT_PRIME) == 0:
        raise ValueError("rank_mod_p needs a prime p, got 0")
    return reduce_matrix(matrix, p).rank

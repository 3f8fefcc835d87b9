"""Sparse Gaussian elimination with Markowitz pivoting, over Z (unit pivots) or over Z/p.

The first stage of :mod:`thesis_lib.smith`.  A pivot is an entry ``v`` of the active matrix that is
a unit (``±1`` over Z, any nonzero residue over Z/p); eliminating it replaces the active matrix ``A``
by the Schur complement ``A' = A - a_{:,j} a_{i,:} / v`` on the other rows and columns, which over Z
is an exact unimodular step: ``A ~ (v) ⊕ A'``.  After ``t`` pivots,

    SNF(A) = diag(1, ..., 1) ⊕ SNF(core),

where the *core* is the active matrix left when no unit entry can be pivoted on (over Z/p the core
is empty and ``t`` is the rank).  The original rows and columns of the pivots form a ``t × t``
submatrix of determinant ``±1`` (the product of the pivots), which is what clearing needs
(:func:`thesis_lib.homology.homology`).

Pivots are chosen by the Markowitz rule: among the unit entries of the few rows and columns with
the fewest entries, the one with the least ``(r - 1)(c - 1)`` (``r``, ``c`` = entries in its row
and column), which bounds the fill-in of the step.  Over Z each step's new entries are checked
before they are stored: a step that would make an entry exceed ``lim`` (``|entries| ≤ 2³¹``, so
products fit in int64) is not taken and its column is set aside until it changes; such columns
end in the core, which the modular stage finishes exactly at any entry size.

Data layout (all in numba): rows are stored exactly, as sorted ``(column, value)`` runs in a pool
(a row changed by a step is rewritten at the top of the pool); columns keep only the list of rows
that may hold an entry (stale rows are dropped when a column is read) and an exact count.  Two lazy
binary heaps, keyed by ``count · 2³² + index``, give the shortest rows and columns.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["markowitz_eliminate", "dense_kernel", "LIMIT"]

#: largest |entry| kept during elimination over Z: |a - f b| <= 2**31 + 2**62 < 2**63, exact in int64
LIMIT = 2**31
_SHIFT = 32
_LOW = (1 << _SHIFT) - 1


@numba.njit(cache=True)
def _grow(arr, need):
    if need <= arr.shape[0]:
        return arr
    cap = max(16, arr.shape[0] * 2)
    while cap < need:
        cap *= 2
    out = np.empty(cap, dtype=arr.dtype)
    out[: arr.shape[0]] = arr
    return out


@numba.njit(cache=True)
def _push(heap, size, key):
    heap = _grow(heap, size + 1)
    i = size
    heap[i] = key
    while i > 0:
        parent = (i - 1) >> 1
        if heap[parent] <= heap[i]:
            break
        heap[parent], heap[i] = heap[i], heap[parent]
        i = parent
    return heap, size + 1


@numba.njit(cache=True)
def _pop(heap, size):
    top = heap[0]
    size -= 1
    heap[0] = heap[size]
    i = 0
    while True:
        left = 2 * i + 1
        if left >= size:
            break
        child = left
        if left + 1 < size and heap[left + 1] < heap[left]:
            child = left + 1
        if heap[i] <= heap[child]:
            break
        heap[i], heap[child] = heap[child], heap[i]
        i = child
    return top, size


@numba.njit(cache=True)
def mod_inverse(v, p):
    """v^-1 mod p (p prime, v not divisible by p), by the extended Euclidean algorithm."""
    a, b = v % p, p
    x0, x1 = 1, 0
    while b != 0:
        q = a // b
        a, b = b, a - q * b
        x0, x1 = x1, x0 - q * x1
    return x0 % p


@numba.njit(cache=True, inline="always")
def _drop_stale(heap, size, dead, blocked, count):
    """Pop the tops of a heap of ``(count << _SHIFT) | line`` keys that are stale (the line is dead or
    blocked, its count changed or is 0) until a live key is on top; return the new size."""
    while size > 0:
        key = heap[0]
        line = key & _LOW
        if dead[line] or blocked[line] or count[line] != (key >> _SHIFT) or count[line] == 0:
            _, size = _pop(heap, size)
        else:
            break
    return size


@numba.njit(cache=True)
def _locate(pool_c, start, length, col):
    """Offset of ``col`` in the sorted run ``pool_c[start:start+length]``, or -1."""
    lo, hi = start, start + length
    while lo < hi:
        mid = (lo + hi) >> 1
        if pool_c[mid] < col:
            lo = mid + 1
        else:
            hi = mid
    if lo < start + length and pool_c[lo] == col:
        return lo - start
    return -1


@numba.njit(cache=True)
def _eligible(v, p):
    if p != 0:
        return v != 0
    return v == 1 or v == -1


@numba.njit(cache=True)
def _compact_rows(pool_c, pool_v, rs, rl, dead, extra):
    live = 0
    for i in range(rs.shape[0]):
        if not dead[i]:
            live += rl[i]
    cap = max(16, 2 * live + extra)
    nc = np.empty(cap, dtype=np.int64)
    nv = np.empty(cap, dtype=np.int64)
    top = 0
    for i in range(rs.shape[0]):
        if dead[i] or rl[i] == 0:
            rs[i] = top
            continue
        s = rs[i]
        for t in range(rl[i]):
            nc[top + t] = pool_c[s + t]
            nv[top + t] = pool_v[s + t]
        rs[i] = top
        top += rl[i]
    return nc, nv, top


@numba.njit(cache=True)
def _markowitz_kernel(indptr, indices, data, n_rows, skip, p, lim, search, density, max_dense):
    n_cols = indptr.shape[0] - 1
    # ---- rows from the CSC input (values reduced mod p; zeros dropped)
    rl = np.zeros(n_rows, dtype=np.int64)
    for j in range(n_cols):
        if skip[j]:
            continue
        for t in range(indptr[j], indptr[j + 1]):
            v = data[t] % p if p != 0 else data[t]
            if v != 0:
                rl[indices[t]] += 1
    rs = np.zeros(n_rows, dtype=np.int64)
    acc = 0
    for i in range(n_rows):
        rs[i] = acc
        acc += rl[i]
    pool_c = np.empty(max(16, 3 * acc), dtype=np.int64)
    pool_v = np.empty(pool_c.shape[0], dtype=np.int64)
    fill = rs.copy()
    # column lists: rows that may hold an entry; exact live counts
    cs = np.zeros(n_cols, dtype=np.int64)
    cl = np.zeros(n_cols, dtype=np.int64)
    ccap = np.zeros(n_cols, dtype=np.int64)
    cnt = np.zeros(n_cols, dtype=np.int64)
    cpool = np.empty(max(16, 2 * acc + 4 * n_cols), dtype=np.int64)
    ctop = 0
    for j in range(n_cols):  # CSC columns come in column order, so each row run stays sorted
        cs[j] = ctop
        if skip[j]:
            continue
        for t in range(indptr[j], indptr[j + 1]):
            v = data[t] % p if p != 0 else data[t]
            if v != 0:
                i = indices[t]
                pool_c[fill[i]] = j
                pool_v[fill[i]] = v
                fill[i] += 1
                cpool[ctop + cl[j]] = i
                cl[j] += 1
        cnt[j] = cl[j]
        ccap[j] = cl[j] + 4
        ctop += ccap[j]
    top = acc
    row_dead = np.zeros(n_rows, dtype=np.bool_)
    col_dead = np.zeros(n_cols, dtype=np.bool_)
    row_blocked = np.zeros(n_rows, dtype=np.bool_)
    col_blocked = np.zeros(n_cols, dtype=np.bool_)
    pivot_rows = np.zeros(n_rows, dtype=np.bool_)
    # ---- heaps of (count, index)
    cheap = np.empty(n_cols + 16, dtype=np.int64)
    csize = 0
    for j in range(n_cols):
        if cnt[j] > 0:
            cheap, csize = _push(cheap, csize, (cnt[j] << _SHIFT) | j)
    rheap = np.empty(n_rows + 16, dtype=np.int64)
    rsize = 0
    for i in range(n_rows):
        if rl[i] > 0:
            rheap, rsize = _push(rheap, rsize, (rl[i] << _SHIFT) | i)
    # ---- work buffers
    stash = np.empty(2 * search + 2, dtype=np.int64)
    kbuf = np.empty(64, dtype=np.int64)
    fbuf = np.empty(64, dtype=np.int64)
    new_start = np.empty(64, dtype=np.int64)
    new_len = np.empty(64, dtype=np.int64)
    fill_k = np.empty(256, dtype=np.int64)
    fill_j = np.empty(256, dtype=np.int64)
    cancel_j = np.empty(256, dtype=np.int64)
    live_r = 0
    for i in range(n_rows):
        if rl[i] > 0:
            live_r += 1
    live_c = 0
    for j in range(n_cols):
        if cnt[j] > 0:
            live_c += 1
    nnz = acc
    seen = np.zeros(n_rows, dtype=np.int64)  # stamps: a row cancelled then filled again is listed twice
    stamp = 0
    rank = 0
    while True:
        if live_r * live_c <= max_dense and nnz >= density * live_r * live_c:
            break  # dense enough: the caller finishes with the dense kernel
        # ---------------- choose a pivot (Markowitz, limited search)
        best = -1
        bi = -1
        bj = -1
        bv = 0
        n_exam = 0
        n_stash = 0
        while n_exam < search:
            csize = _drop_stale(cheap, csize, col_dead, col_blocked, cnt)
            rsize = _drop_stale(rheap, rsize, row_dead, row_blocked, rl)
            if csize == 0 and rsize == 0:
                break
            use_col = rsize == 0 or (csize > 0 and (cheap[0] >> _SHIFT) <= (rheap[0] >> _SHIFT))
            if use_col:
                key, csize = _pop(cheap, csize)
                j = key & _LOW
                c = cnt[j]
                found = False
                w = cs[j]
                stamp += 1
                for t in range(cs[j], cs[j] + cl[j]):  # read the column, dropping stale and repeated rows
                    k = cpool[t]
                    if row_dead[k] or seen[k] == stamp:
                        continue
                    seen[k] = stamp
                    off = _locate(pool_c, rs[k], rl[k], j)
                    if off < 0:
                        continue
                    cpool[w] = k
                    w += 1
                    v = pool_v[rs[k] + off]
                    if _eligible(v, p):
                        found = True
                        cost = (c - 1) * (rl[k] - 1)
                        if best < 0 or cost < best:
                            best, bi, bj, bv = cost, k, j, v
                cl[j] = w - cs[j]
                if not found:
                    col_blocked[j] = True
                else:
                    stash[n_stash] = (key << 1) | 1
                    n_stash += 1
                    n_exam += 1
            else:
                key, rsize = _pop(rheap, rsize)
                i = key & _LOW
                r = rl[i]
                found = False
                for t in range(rs[i], rs[i] + r):
                    v = pool_v[t]
                    if _eligible(v, p):
                        found = True
                        cost = (r - 1) * (cnt[pool_c[t]] - 1)
                        if best < 0 or cost < best:
                            best, bi, bj, bv = cost, i, pool_c[t], v
                if not found:
                    row_blocked[i] = True
                else:
                    stash[n_stash] = key << 1
                    n_stash += 1
                    n_exam += 1
            if best == 0:
                break
        for s in range(n_stash):
            key = stash[s] >> 1
            if stash[s] & 1:
                cheap, csize = _push(cheap, csize, key)
            else:
                rheap, rsize = _push(rheap, rsize, key)
        if best < 0:
            break
        i, j, v = bi, bj, bv
        # ---------------- rows to update: the other live rows of column j
        nk = 0
        need = 0
        stamp += 1
        for t in range(cs[j], cs[j] + cl[j]):
            k = cpool[t]
            if row_dead[k] or k == i or seen[k] == stamp:
                continue
            seen[k] = stamp
            off = _locate(pool_c, rs[k], rl[k], j)
            if off < 0:
                continue
            kbuf = _grow(kbuf, nk + 1)
            fbuf = _grow(fbuf, nk + 1)
            kbuf[nk] = k
            a = pool_v[rs[k] + off]
            if p != 0:
                fbuf[nk] = (a * mod_inverse(v, p)) % p
            else:
                fbuf[nk] = a * v  # v = ±1 is its own inverse
            nk += 1
            need += rl[k] + rl[i]
        if top + need > pool_c.shape[0]:
            pool_c, pool_v, top = _compact_rows(pool_c, pool_v, rs, rl, row_dead, need)
        new_start = _grow(new_start, nk)
        new_len = _grow(new_len, nk)
        n_fill = 0
        n_cancel = 0
        over = False
        top0 = top
        si, li = rs[i], rl[i]
        for q in range(nk):
            k = kbuf[q]
            f = fbuf[q]
            sk, lk = rs[k], rl[k]
            fill_k = _grow(fill_k, n_fill + li)
            fill_j = _grow(fill_j, n_fill + li)
            cancel_j = _grow(cancel_j, n_cancel + li)
            a_ = 0
            b_ = 0
            out = top
            while a_ < lk or b_ < li:
                if b_ >= li or (a_ < lk and pool_c[sk + a_] < pool_c[si + b_]):
                    pool_c[out] = pool_c[sk + a_]
                    pool_v[out] = pool_v[sk + a_]
                    out += 1
                    a_ += 1
                    continue
                col = pool_c[si + b_]
                if col == j:  # the pivot column: eliminated by construction
                    b_ += 1
                    if a_ < lk and pool_c[sk + a_] == j:
                        a_ += 1
                    continue
                if a_ < lk and pool_c[sk + a_] == col:
                    old = pool_v[sk + a_]
                    a_ += 1
                    fresh = False
                else:
                    old = 0
                    fresh = True
                b_ += 1
                if p != 0:
                    val = (old + p - (f * pool_v[si + b_ - 1]) % p) % p
                else:
                    val = old - f * pool_v[si + b_ - 1]
                    if val > lim or val < -lim:
                        over = True
                        break
                if val == 0:
                    if not fresh:
                        cancel_j[n_cancel] = col
                        n_cancel += 1
                    continue
                if fresh:
                    fill_k[n_fill] = k
                    fill_j[n_fill] = col
                    n_fill += 1
                pool_c[out] = col
                pool_v[out] = val
                out += 1
            if over:
                break
            new_start[q] = top
            new_len[q] = out - top
            top = out
        if over:  # this step would leave int64's safe range: set the column aside
            top = top0
            col_blocked[j] = True
            continue
        # ---------------- commit the step
        for q in range(nk):
            k = kbuf[q]
            nnz += new_len[q] - rl[k]
            if new_len[q] == 0:
                live_r -= 1
            rs[k] = new_start[q]
            rl[k] = new_len[q]
        for t in range(n_fill):
            jj = fill_j[t]
            if cl[jj] == ccap[jj]:  # move the column list to the top of its pool, doubled
                cap = 2 * ccap[jj] + 4
                cpool = _grow(cpool, ctop + cap)
                for u in range(cl[jj]):
                    cpool[ctop + u] = cpool[cs[jj] + u]
                cs[jj] = ctop
                ccap[jj] = cap
                ctop += cap
            cpool[cs[jj] + cl[jj]] = fill_k[t]
            cl[jj] += 1
            cnt[jj] += 1
        for t in range(n_cancel):
            cnt[cancel_j[t]] -= 1
        for t in range(si, si + li):
            jj = pool_c[t]
            if jj != j:
                cnt[jj] -= 1
                if cnt[jj] == 0:
                    live_c -= 1
        nnz -= li
        live_r -= 1
        live_c -= 1
        row_dead[i] = True
        col_dead[j] = True
        pivot_rows[i] = True
        rank += 1
        for t in range(si, si + li):
            jj = pool_c[t]
            if jj != j and cnt[jj] > 0:
                col_blocked[jj] = False
                cheap, csize = _push(cheap, csize, (cnt[jj] << _SHIFT) | jj)
        for q in range(nk):
            k = kbuf[q]
            row_blocked[k] = False
            if rl[k] > 0:
                rheap, rsize = _push(rheap, rsize, (rl[k] << _SHIFT) | k)
    # ---- the core: live rows with entries, as CSR over the original row and column indices
    n_core = 0
    nnz = 0
    for i in range(n_rows):
        if not row_dead[i] and rl[i] > 0:
            n_core += 1
            nnz += rl[i]
    core_rows = np.empty(n_core, dtype=np.int64)
    core_ptr = np.zeros(n_core + 1, dtype=np.int64)
    core_cols = np.empty(nnz, dtype=np.int64)
    core_vals = np.empty(nnz, dtype=np.int64)
    q = 0
    pos = 0
    for i in range(n_rows):
        if not row_dead[i] and rl[i] > 0:
            core_rows[q] = i
            for t in range(rl[i]):
                core_cols[pos + t] = pool_c[rs[i] + t]
                core_vals[pos + t] = pool_v[rs[i] + t]
            pos += rl[i]
            q += 1
            core_ptr[q] = pos
    return rank, pivot_rows, core_rows, core_ptr, core_cols, core_vals


@numba.njit(cache=True)
def _unit(v, p):
    """v is a unit of Z (p = 0) or of Z/p for any modulus p (entries reduced to [0, p))."""
    if p == 0:
        return v == 1 or v == -1
    a, b = v, p
    while b != 0:
        a, b = b, a % b
    return a == 1


@numba.njit(cache=True)
def dense_kernel(a, p, lim):
    """Unit-pivot elimination of a dense int64 matrix in place, column by column.

    The end of the sparse stage, and the unit part of the Smith form modulo M in
    :mod:`thesis_lib._modular` (``p`` is then any modulus M < 2³¹, entries in [0, M)).  For each
    column a row with a unit entry (over Z the one with the smallest entries) is the pivot and every
    other live row is updated (Schur complement).  Over Z a step whose update could exceed ``lim``
    is skipped.  Passes repeat while they make progress (over a field the second finds nothing).
    Returns (pivots, pivot-row mask, eliminated-column mask).
    """
    n_r, n_c = a.shape
    alive = np.ones(n_r, dtype=np.bool_)
    done = np.zeros(n_c, dtype=np.bool_)
    rmax = np.zeros(n_r, dtype=np.int64)  # over Z: an upper bound of |a[i, :]|
    if p == 0:
        for i in range(n_r):
            for c in range(n_c):
                x = abs(a[i, c])
                if x > rmax[i]:
                    rmax[i] = x
    idx = np.empty(n_c, dtype=np.int64)
    pivots = 0
    while True:
        progress = False
        for j in range(n_c):
            if done[j]:
                continue
            k = -1
            for i in range(n_r):
                if alive[i] and _unit(a[i, j], p):
                    if k < 0 or (p == 0 and rmax[i] < rmax[k]):
                        k = i
                        if p != 0:
                            break
            if k < 0:
                continue
            v = a[k, j]
            if p == 0:
                safe = True
                for i in range(n_r):
                    if alive[i] and i != k and a[i, j] != 0 and abs(a[i, j]) * rmax[k] + rmax[i] > lim:
                        safe = False
                        break
                if not safe:
                    continue
                inv = v
            else:
                inv = mod_inverse(v, p)
            nk = 0
            for c in range(n_c):
                if a[k, c] != 0:
                    idx[nk] = c
                    nk += 1
            for i in range(n_r):
                if not alive[i] or i == k or a[i, j] == 0:
                    continue
                f = a[i, j] * inv
                if p != 0:
                    f = f % p
                    for t in range(nk):
                        c = idx[t]
                        a[i, c] = (a[i, c] - f * a[k, c]) % p
                else:
                    top = rmax[i]
                    for t in range(nk):
                        c = idx[t]
                        x = a[i, c] - f * a[k, c]
                        a[i, c] = x
                        if abs(x) > top:
                            top = abs(x)
                    rmax[i] = top
            alive[k] = False
            done[j] = True
            pivots += 1
            progress = True
        if not progress:
            break
    return pivots, ~alive, done


def markowitz_eliminate(indptr: np.ndarray, indices: np.ndarray, data: np.ndarray, n_rows: int,
                        skip: np.ndarray, p: int, *, search: int = 4, density: float = 0.2,
                        max_dense: int = 2 * 10**7, finish: bool = True):
    """Eliminate unit pivots of a CSC matrix (sorted indices, int64, |entries| <= LIMIT over Z).

    Sparse Markowitz steps while the active matrix is sparse; once it holds at least ``density``
    of its ``rows × columns`` (and that is at most ``max_dense`` entries) it is finished densely
    (``finish=False``: returned as it is then).
    Returns ``(rank, pivot_rows, core)``: the number of pivots, a boolean mask of the rows that
    carried one, and the core (over Z/p: empty) as a dense int64 array with its original row and
    column indices ``(core, rows, cols)``.  ``p`` = 0 for Z, a prime < 2³¹ for Z/p.
    """
    rank, pivot_rows, core_rows, core_ptr, core_cols, core_vals = _markowitz_kernel(
        np.ascontiguousarray(indptr, dtype=np.int64), np.ascontiguousarray(indices, dtype=np.int64),
        np.ascontiguousarray(data, dtype=np.int64), np.int64(n_rows), np.ascontiguousarray(skip, dtype=np.bool_),
        np.int64(p), np.int64(LIMIT), np.int64(search), float(density), np.int64(max_dense),
    )
    cols = np.unique(core_cols)
    dense = np.zeros((core_rows.size, cols.size), dtype=np.int64)
    dense[np.repeat(np.arange(core_rows.size), np.diff(core_ptr)), np.searchsorted(cols, core_cols)] = core_vals
    if dense.size and finish:
        more, piv, done = dense_kernel(dense, np.int64(p), np.int64(LIMIT))
        rank += more
        pivot_rows[core_rows[piv]] = True
        keep_r, keep_c = ~piv, ~done
        dense = dense[keep_r][:, keep_c]
        core_rows, cols = core_rows[keep_r], cols[keep_c]
        nz = dense != 0
        rows_nz, cols_nz = nz.any(axis=1), nz.any(axis=0)
        dense, core_rows, cols = dense[rows_nz][:, cols_nz], core_rows[rows_nz], cols[cols_nz]
    return int(rank), pivot_rows, (dense, core_rows, cols)

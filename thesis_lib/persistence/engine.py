"""The fast persistence engine: union–find for H0, then cohomology column reduction with clearing.

Same barcode as :func:`~thesis_lib.persistence.algorithm.compute_intervals` on every input (the
pairs of the boundary and the coboundary reductions coincide, de Silva–Morozov–Vejdemo-Johansson
2011), but with

* the order of each dimension by one stable ``argsort`` (only the order *within* a dimension
  matters: a column of dimension d only ever meets rows of dimension d ± 1);
* facets found by hashing, the coboundary matrix assembled as compressed sparse columns by a
  counting sort whose fill pass visits the cofaces in filtration order (so every column comes out
  sorted, no per-column sort);
* H0 by union–find with the elder rule (the pairs of Reduce on the edge columns);
* dimensions d ≥ 1 on the cohomology side, latest simplex first, pivot = earliest coface;
  columns of simplices already paired one dimension lower are cleared (skipped), columns whose
  pivot is still free (apparent/emergent pairs, the common case) are paired without being copied,
  and only colliding columns are reduced, by sorted merges over Z/p in a numba loop.
"""

from __future__ import annotations

import numba
import numpy as np

from ._input import as_filtration, check_prime
from .barcode import Barcode

__all__ = ["persistence"]


# ---------------------------------------------------------------------------- facet lookup
@numba.njit(cache=True)
def _hash(key: np.int64, mask: np.int64) -> np.int64:
    h = np.uint64(key) * np.uint64(0x9E3779B97F4A7C15)
    return np.int64(h >> np.uint64(20)) & mask


@numba.njit(cache=True)
def _facet_lookup(lower: np.ndarray, upper: np.ndarray, base: np.int64) -> np.ndarray:
    """Index in ``lower`` of facet i (omitting vertex i) of every row of ``upper``; -1 if missing."""
    m0, k = lower.shape
    m1 = upper.shape[0]
    size = 1
    while size < 2 * m0 + 2:
        size *= 2
    mask = np.int64(size - 1)
    keys = np.full(size, -1, dtype=np.int64)
    vals = np.empty(size, dtype=np.int64)
    for r in range(m0):
        key = np.int64(0)
        for c in range(k):
            key = key * base + lower[r, c]
        h = _hash(key, mask)
        while keys[h] != -1:
            h = (h + 1) & mask
        keys[h] = key
        vals[h] = r
    out = np.empty((m1, k + 1), dtype=np.int64)
    for r in range(m1):
        for i in range(k + 1):
            key = np.int64(0)
            for c in range(k + 1):
                if c != i:
                    key = key * base + upper[r, c]
            h = _hash(key, mask)
            found = -1
            while keys[h] != -1:
                if keys[h] == key:
                    found = vals[h]
                    break
                h = (h + 1) & mask
            out[r, i] = found
    return out


def _facets(K, d: int) -> np.ndarray:
    """(m_d, d + 1) indices into ``K.simplices[d - 1]``; column i omits vertex i (as ``facet_indices``)."""
    cache = K.__dict__.get("_facet_cache")
    if cache is not None and d in cache:  # a validated Filtration already found them
        return cache[d]
    lower, upper = K.simplices[d - 1], K.simplices[d]
    base = int(max(lower.max(initial=0), upper.max(initial=0))) + 1
    if d * np.log2(base) >= 62:  # keys would overflow: use the generic lookup
        return K.facet_indices(d)
    out = _facet_lookup(np.ascontiguousarray(lower), np.ascontiguousarray(upper), np.int64(base))
    if (out < 0).any():
        r, i = np.argwhere(out < 0)[0]
        face = tuple(int(v) for j, v in enumerate(upper[r]) if j != i)
        raise ValueError(f"face {face} of {tuple(int(v) for v in upper[r])} is missing from the filtration")
    return out


# ---------------------------------------------------------------------------- H0: union-find
@numba.njit(cache=True)
def _find(parent: np.ndarray, x: np.int64) -> np.int64:
    while parent[x] != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x


@numba.njit(cache=True)
def _h0(edge_facets: np.ndarray, vrank: np.ndarray, order1: np.ndarray):
    """Elder-rule union–find over the edges in filtration order.

    Returns (death pairs as (vertex index, edge index), negative-edge mask, essential vertices).
    """
    n = vrank.shape[0]
    parent = np.arange(n, dtype=np.int64)
    m1 = order1.shape[0]
    pv = np.empty(n, dtype=np.int64)
    pe = np.empty(n, dtype=np.int64)
    negative = np.zeros(m1, dtype=np.bool_)
    count = 0
    for r in range(m1):
        e = order1[r]
        a = _find(parent, edge_facets[e, 0])
        b = _find(parent, edge_facets[e, 1])
        if a == b:
            continue
        if vrank[a] > vrank[b]:  # a is younger: it dies
            a, b = b, a
        parent[b] = a  # b (the younger root) joins the elder a
        pv[count] = b
        pe[count] = e
        count += 1
        negative[e] = True
    ess = np.empty(n - count, dtype=np.int64)
    k = 0
    for v in range(n):
        if parent[v] == v:
            ess[k] = v
            k += 1
    return pv[:count], pe[:count], negative, ess


# ---------------------------------------------------------------------------- coboundary matrix
@numba.njit(cache=True)
def _before(va: float, a: np.int64, vb: float, b: np.int64) -> bool:
    """Filtration order within one dimension: by value, ties by index (the stable sort)."""
    return va < vb or (va == vb and a < b)


@numba.njit(cache=True)
def _coboundary(facets: np.ndarray, up_values: np.ndarray, m_d: int):
    """Compressed columns of δ on the d-simplices (by index): entries are indices of the (d+1)-cofaces.

    One counting pass and one fill pass, both reading the cofaces sequentially; each column comes out
    sorted by coface index (not yet by value).  The fill pass also finds every column's pivot, its
    earliest coface in the filtration order.  The sign of σ in ∂τ is (-1)^i when σ omits vertex i of τ
    (Definition 2.18).
    """
    m_up, w = facets.shape
    indptr = np.zeros(m_d + 1, dtype=np.int64)
    for t in range(m_up):
        for i in range(w):
            indptr[facets[t, i] + 1] += 1
    for c in range(m_d):
        indptr[c + 1] += indptr[c]
    fill = indptr[:-1].copy()
    rows = np.empty(indptr[m_d], dtype=np.int32)
    signs = np.empty(indptr[m_d], dtype=np.int8)
    pivot = np.full(m_d, -1, dtype=np.int64)
    pivot_value = np.full(m_d, np.inf)
    for t in range(m_up):
        v = up_values[t]
        for i in range(w):
            c = facets[t, i]
            rows[fill[c]] = t
            signs[fill[c]] = 1 - 2 * (i & 1)
            fill[c] += 1
            if pivot[c] == -1 or v < pivot_value[c]:  # t ascending: ties keep the smaller index
                pivot[c] = t
                pivot_value[c] = v
    return indptr, rows, signs, pivot


@numba.njit(cache=True)
def _sort_column(rows, signs, a, b, up_values):
    """Sort the slice a:b (already ascending by index) by value, stably: the filtration order."""
    vals = np.empty(b - a)
    for k in range(b - a):
        vals[k] = up_values[rows[a + k]]
    perm = np.argsort(vals, kind="mergesort")
    r = rows[a:b].copy()
    s = signs[a:b].copy()
    for k in range(b - a):
        rows[a + k] = r[perm[k]]
        signs[a + k] = s[perm[k]]


# ---------------------------------------------------------------------------- reduction over Z/p
@numba.njit(cache=True)
def _inv(a: np.int64, p: np.int64) -> np.int64:
    # extended Euclid: a^{-1} mod p
    t, newt, r, newr = np.int64(0), np.int64(1), p, a % p
    while newr != 0:
        q = r // newr
        t, newt = newt, t - q * newt
        r, newr = newr, r - q * newr
    return t % p


@numba.njit(cache=True)
def _reduce_cohomology(indptr, rows, signs, pivot, order_d, cleared, up_values, p):
    """Reduce the coboundary columns, latest d-simplex first, with clearing.

    ``order_d``: the d-simplices in filtration order; ``cleared[c]``: skip column c (its simplex was
    paired one dimension lower).  The pivot of a column is its earliest coface.  A column whose
    pivot is still free is paired as it stands (no copy); the others are sorted into filtration
    order and reduced by sorted merges over Z/p.  Returns (pair columns, pair rows, essential
    columns, number of column additions), all as simplex indices.
    """
    m_d = indptr.shape[0] - 1
    m_up = up_values.shape[0]
    owner = np.full(m_up, -1, dtype=np.int64)
    start = np.full(m_d, -1, dtype=np.int64)  # -1: the reduced column is the original one
    length = np.zeros(m_d, dtype=np.int64)
    is_sorted = np.zeros(m_d, dtype=np.bool_)
    cap = 1024
    pool_r = np.empty(cap, dtype=np.int32)
    pool_v = np.empty(cap, dtype=np.int64)
    used = 0
    wcap = 1024
    w_r = np.empty(wcap, dtype=np.int32)
    w_v = np.empty(wcap, dtype=np.int64)
    t_r = np.empty(wcap, dtype=np.int32)
    t_v = np.empty(wcap, dtype=np.int64)
    npmax = min(m_d, m_up)
    pair_c = np.empty(npmax, dtype=np.int64)
    pair_r = np.empty(npmax, dtype=np.int64)
    npairs = 0
    ess = np.empty(m_d, dtype=np.int64)
    ness = 0
    additions = 0
    for pos in range(m_d - 1, -1, -1):
        c = order_d[pos]
        if cleared[c]:
            continue
        if pivot[c] == -1:  # no cofaces at all
            ess[ness] = c
            ness += 1
            continue
        piv = pivot[c]
        if owner[piv] == -1:  # pivot still free: the column is already reduced (apparent/emergent pair)
            owner[piv] = c
            pair_c[npairs] = c
            pair_r[npairs] = piv
            npairs += 1
            continue
        a, b = indptr[c], indptr[c + 1]
        if not is_sorted[c]:
            _sort_column(rows, signs, a, b, up_values)
            is_sorted[c] = True
        wl = b - a
        if wl > wcap:
            while wcap < wl:
                wcap *= 2
            w_r = np.empty(wcap, dtype=np.int32)
            w_v = np.empty(wcap, dtype=np.int64)
            t_r = np.empty(wcap, dtype=np.int32)
            t_v = np.empty(wcap, dtype=np.int64)
        for k in range(wl):
            w_r[k] = rows[a + k]
            w_v[k] = signs[a + k] % p
        while wl > 0:
            piv = np.int64(w_r[0])
            o = owner[piv]
            if o == -1:
                break
            additions += 1
            # the reduced column of o: the original one (sorted on demand) or a stored one
            if start[o] == -1:
                oa, ol, stored = indptr[o], indptr[o + 1] - indptr[o], False
                if not is_sorted[o]:
                    _sort_column(rows, signs, oa, oa + ol, up_values)
                    is_sorted[o] = True
            else:
                oa, ol, stored = start[o], length[o], True
            q = np.int64(pool_v[oa]) if stored else np.int64(signs[oa]) % p
            factor = w_v[0] * _inv(q, p) % p
            need = wl + ol
            if need > wcap:
                while wcap < need:
                    wcap *= 2
                n_r = np.empty(wcap, dtype=np.int32)
                n_v = np.empty(wcap, dtype=np.int64)
                n_r[:wl] = w_r[:wl]
                n_v[:wl] = w_v[:wl]
                w_r, w_v = n_r, n_v
                t_r = np.empty(wcap, dtype=np.int32)
                t_v = np.empty(wcap, dtype=np.int64)
            # t = w - factor * R_o  (sorted merge in filtration order, zero coefficients dropped)
            i = 0
            j = 0
            n = 0
            while i < wl and j < ol:
                ri = np.int64(w_r[i])
                rj = np.int64(pool_r[oa + j]) if stored else np.int64(rows[oa + j])
                if ri == rj:
                    vj = pool_v[oa + j] if stored else np.int64(signs[oa + j]) % p
                    v = (w_v[i] - factor * vj) % p
                    if v != 0:
                        t_r[n] = ri
                        t_v[n] = v
                        n += 1
                    i += 1
                    j += 1
                elif _before(up_values[ri], ri, up_values[rj], rj):
                    t_r[n] = ri
                    t_v[n] = w_v[i]
                    n += 1
                    i += 1
                else:
                    vj = pool_v[oa + j] if stored else np.int64(signs[oa + j]) % p
                    t_r[n] = rj
                    t_v[n] = (p - factor * vj % p) % p
                    n += 1
                    j += 1
            while i < wl:
                t_r[n] = w_r[i]
                t_v[n] = w_v[i]
                n += 1
                i += 1
            while j < ol:
                vj = pool_v[oa + j] if stored else np.int64(signs[oa + j]) % p
                t_r[n] = pool_r[oa + j] if stored else rows[oa + j]
                t_v[n] = (p - factor * vj % p) % p
                n += 1
                j += 1
            w_r, t_r = t_r, w_r
            w_v, t_v = t_v, w_v
            wl = n
        if wl == 0:
            ess[ness] = c
            ness += 1
            continue
        # store the reduced column
        if used + wl > cap:
            while cap < used + wl:
                cap *= 2
            n_r = np.empty(cap, dtype=np.int32)
            n_v = np.empty(cap, dtype=np.int64)
            n_r[:used] = pool_r[:used]
            n_v[:used] = pool_v[:used]
            pool_r, pool_v = n_r, n_v
        pool_r[used : used + wl] = w_r[:wl]
        pool_v[used : used + wl] = w_v[:wl]
        start[c] = used
        length[c] = wl
        used += wl
        piv = np.int64(w_r[0])
        owner[piv] = c
        pair_c[npairs] = c
        pair_r[npairs] = piv
        npairs += 1
    return pair_c[:npairs], pair_r[:npairs], ess[:ness], additions


# ---------------------------------------------------------------------------- driver
def persistence(filtration, p: int = 2, *, stats: dict | None = None) -> Barcode:
    """Barcode of a filtration over Z/p by the fast engine (same result as :func:`compute_intervals`).

    Thesis: Theorem 2.39 / Algorithm 2, §2.3.5 (the same pairs, computed by the dual reduction).

    Parameters
    ----------
    filtration : a :class:`~thesis_lib.complexes.Filtration` or an iterable of ``(simplex, value)`` pairs.
    p : a prime; the coefficients are the field Z/p.
    stats : optional dict, filled with counts (columns reduced, column additions) per dimension.
    """
    K = as_filtration(filtration)
    p = check_prime(p)
    D = K.dimension
    # the order within each dimension (value, then index); the top dimension is never a column
    orders = [np.argsort(K.values[d], kind="stable") for d in range(D)]
    intervals: dict[int, np.ndarray] = {}
    pairs: dict[int, np.ndarray] = {}
    killers: dict[int, np.ndarray] = {}
    inf = np.inf

    def finish(d: int, born: np.ndarray, dies: np.ndarray, essential: np.ndarray) -> None:
        intervals[d] = np.empty((born.shape[0] + essential.shape[0], 2))
        if born.shape[0]:
            intervals[d][: born.shape[0], 0] = K.values[d][born]
            intervals[d][: born.shape[0], 1] = K.values[d + 1][dies]
        intervals[d][born.shape[0] :, 0] = K.values[d][essential]
        intervals[d][born.shape[0] :, 1] = inf
        pairs[d] = np.empty((born.shape[0] + essential.shape[0], 2), dtype=np.int64)
        pairs[d][: born.shape[0], 0] = born
        pairs[d][: born.shape[0], 1] = dies
        pairs[d][born.shape[0] :, 0] = essential
        pairs[d][born.shape[0] :, 1] = -1
        killers[d] = dies

    empty = np.empty(0, dtype=np.int64)
    if D == 0:
        finish(0, empty, empty, np.arange(K.simplices[0].shape[0]))
        return Barcode(intervals, [0], p=p, simplices=pairs, filtration=K, killers=killers)
    # ---- H0 by union-find (the pairs Reduce finds on the edge columns)
    vrank = np.empty(K.simplices[0].shape[0], dtype=np.int64)
    vrank[orders[0]] = np.arange(orders[0].shape[0])
    order1 = orders[1] if D > 1 else np.argsort(K.values[1], kind="stable")
    pv, pe, cleared, ess = _h0(_facets(K, 1), vrank, order1)
    finish(0, pv, pe, ess)
    if stats is not None:
        stats[0] = {"columns": int(K.simplices[1].shape[0]), "additions": 0}
    # ---- dimensions 1 .. D-1 by cohomology with clearing
    for d in range(1, D):
        m_d = K.simplices[d].shape[0]
        if K.simplices[d + 1].shape[0] >= 2**31:
            raise ValueError("more than 2**31 simplices in one dimension are not supported")
        up_values = np.ascontiguousarray(K.values[d + 1])
        indptr, rows, signs, pivot = _coboundary(_facets(K, d + 1), up_values, m_d)
        born, dies, essential, adds = _reduce_cohomology(indptr, rows, signs, pivot, orders[d], cleared, up_values, np.int64(p))
        del indptr, rows, signs, pivot
        finish(d, born, dies, essential)
        if stats is not None:
            stats[d] = {"columns": int(m_d - cleared.sum()), "additions": int(adds)}
        cleared = np.zeros(K.simplices[d + 1].shape[0], dtype=np.bool_)
        cleared[dies] = True
    # ---- top dimension: every simplex not killing a class creates an essential one
    finish(D, empty, empty, np.flatnonzero(~cleared))
    return Barcode(intervals, range(D + 1), p=p, simplices=pairs, filtration=K, killers=killers)

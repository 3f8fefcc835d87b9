"""Persistence of a general filtered chain complex (cells with values and boundary matrices).

Used for the Morse complex of a filtration (:mod:`thesis_lib.morse.reduction`), whose cells are the
critical simplices and whose boundary comes from gradient paths, not from vertices.  The reduction
is Algorithm 2's column reduction on the boundary side with the twist (clearing): higher dimensions
first, a column whose index is already a pivot is skipped.  Its field arithmetic and its working
column are the library's one kernel (:mod:`.kernels`).
"""

from __future__ import annotations

import numpy as np

from .._validate import check_coefficients
from ..jit import njit
from .barcode import Barcode
from .kernels import grow, heap_push, mod_inverse, pop_pivot

__all__ = ["chain_persistence"]


@njit(cache=True)
def _reduce(n, indptr, indices, data, col_order, p):
    """Column reduction with clearing mod p on a boundary matrix in filtration positions.

    ``indices`` are row positions in the total order; ``col_order`` lists the columns to process
    (higher dimensions first, each by increasing position).  The working column is a heap keyed by
    −row (its pivot is the lowest, i.e. latest, row).  Returns low[col] (−1 for a zero column).
    """
    low = np.full(n, -1, dtype=np.int64)
    owner = np.full(n, -1, dtype=np.int64)
    cleared = np.zeros(n, dtype=np.bool_)
    pcoef = np.zeros(n, dtype=np.int64)
    start = np.zeros(n, dtype=np.int64)
    length = np.zeros(n, dtype=np.int64)
    pool_r = np.empty(max(16, indptr[n]), dtype=np.int64)
    pool_v = np.empty(max(16, indptr[n]), dtype=np.int64)
    used = 0
    hv = np.zeros(64)
    hk = np.empty(64, dtype=np.int64)
    hc = np.empty(64, dtype=np.int64)
    for c in col_order:
        if cleared[c] or indptr[c + 1] == indptr[c]:
            continue
        hn = 0
        hv, hk, hc = grow(hv, hk, hc, 0, indptr[c + 1] - indptr[c])
        for e in range(indptr[c], indptr[c + 1]):
            hn = heap_push(hv, hk, hc, hn, 0.0, -indices[e], data[e] % p)
        piv, pc = np.int64(-1), np.int64(0)
        while True:
            hn, _, key, coef = pop_pivot(hv, hk, hc, hn, p)
            if coef == 0:
                break
            o = owner[-key]
            if o < 0:
                piv, pc = -key, coef
                break
            factor = (p - coef) * mod_inverse(pcoef[o], p) % p  # kills row -key; that entry is not pushed
            hv, hk, hc = grow(hv, hk, hc, hn, hn + length[o])
            for e in range(start[o], start[o] + length[o]):
                hn = heap_push(hv, hk, hc, hn, 0.0, -pool_r[e], factor * pool_v[e] % p)
        if piv < 0:
            continue
        # store the rest of the reduced column (below the pivot) for later additions
        m0 = used
        while True:
            hn, _, key, coef = pop_pivot(hv, hk, hc, hn, p)
            if coef == 0:
                break
            if used == pool_r.shape[0]:
                pool_r, pool_v, _ = grow(pool_r, pool_v, pool_v, used, used + 1)
            pool_r[used] = -key
            pool_v[used] = coef
            used += 1
        start[c], length[c] = m0, used - m0
        owner[piv] = c
        pcoef[c] = pc
        low[c] = piv
        cleared[piv] = True
    return low


def chain_persistence(values: list[np.ndarray], boundaries: list, p: int = 2) -> Barcode:
    """Barcode of a filtered chain complex: cells with values per dimension, boundary matrices per dimension.

    Thesis: Algorithm 2, §2.3.5 (column reduction over Z/p; pairs give P-intervals, Definition 2.34).

    Parameters
    ----------
    values : ``values[d]`` the filtration values of the d-cells.
    boundaries : ``boundaries[d]`` the matrix (dense or scipy.sparse, integer) of ∂ from d-cells
        (columns) to (d−1)-cells (rows); ``boundaries[0]`` is ignored.  Every cell's boundary must
        consist of cells with value ≤ its own (ties: lower dimension first).
    p : a prime, the field Z/p.

    Returns
    -------
    Barcode
    """
    import scipy.sparse as sp

    if check_coefficients(p) == 0:
        raise ValueError("persistence needs a prime field Z/p, got 0")
    counts = [len(v) for v in values]
    if len(boundaries) != len(values):
        raise ValueError("give one boundary matrix per dimension")
    offsets = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
    n = int(offsets[-1])
    dims = np.repeat(np.arange(len(counts)), counts)
    vals = np.concatenate([np.asarray(v, dtype=np.float64) for v in values]) if n else np.empty(0)
    if np.isnan(vals).any():
        raise ValueError("filtration values must not be NaN")
    order = np.lexsort((np.arange(n), dims, vals))
    pos = np.empty(n, dtype=np.int64)
    pos[order] = np.arange(n)
    blocks_r, blocks_c, blocks_v = [], [], []
    for d in range(1, len(counts)):
        b = sp.coo_matrix(boundaries[d])
        if b.shape != (counts[d - 1], counts[d]):
            raise ValueError(f"boundary {d} has shape {b.shape}, expected {(counts[d - 1], counts[d])}")
        r = pos[b.row + offsets[d - 1]]
        c = pos[b.col + offsets[d]]
        if b.nnz and np.any(r > c):
            raise ValueError(f"a {d}-cell has a face with a larger filtration value")
        blocks_r.append(r)
        blocks_c.append(c)
        blocks_v.append(np.asarray(b.data, dtype=np.int64) % p)
    if blocks_r:
        r, c, v = np.concatenate(blocks_r), np.concatenate(blocks_c), np.concatenate(blocks_v)
    else:
        r = c = v = np.empty(0, dtype=np.int64)
    mat = sp.csc_matrix((v, (r, c)), shape=(n, n), dtype=np.int64)
    mat.sum_duplicates()
    mat.data %= p
    mat.eliminate_zeros()
    mat.sort_indices()
    dims_pos = dims[order]
    col_order = np.lexsort((np.arange(n), -dims_pos)).astype(np.int64)
    low = _reduce(n, mat.indptr.astype(np.int64), mat.indices.astype(np.int64), mat.data.astype(np.int64), col_order,
                  np.int64(p))
    vals_pos = vals[order]
    paired = np.zeros(n, dtype=bool)
    has = low >= 0
    cols = np.flatnonzero(has)
    rows = low[has]
    paired[cols] = True
    paired[rows] = True
    intervals: dict[int, list[tuple[float, float]]] = {d: [] for d in range(len(counts))}
    for rr, cc in zip(rows.tolist(), cols.tolist()):
        if vals_pos[cc] > vals_pos[rr]:
            intervals[int(dims_pos[rr])].append((float(vals_pos[rr]), float(vals_pos[cc])))
    for i in np.flatnonzero(~paired).tolist():
        intervals[int(dims_pos[i])].append((float(vals_pos[i]), np.inf))
    return Barcode(intervals, range(len(counts)), p=p)

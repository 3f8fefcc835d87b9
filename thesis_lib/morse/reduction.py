"""Morse reduction of a filtration before persistence (the "simplify large complexes" use of §4.2.6).

A filtration-compatible acyclic matching pairs σ < τ only when both have the same filtration value.
Every gradient path then runs downwards in value, so the Morse complex (Theorem 4.42) is a filtered
chain complex on the critical simplices, each keeping its value; its barcode equals the barcode of the
filtration (each sublevel set's Morse complex is the restriction, Theorems 4.39/4.41).
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np
import scipy.sparse as sp

from ..filtration import Filtration, as_complex
from .._validate import InvalidTypeError, check_coefficients, resolve_coefficients
from ._cells import CellComplex, partner_array
from ._gradient import morse_boundary_ids
from ._kernels import greedy_partner

__all__ = ["MorseReduction", "lower_star_filtration", "filtration_matching", "morse_reduce", "reduced_persistence", "chain_persistence"]


def _cells_and_values(filt: Filtration) -> tuple[CellComplex, np.ndarray]:
    cx = CellComplex(filt)
    return cx, (cx.values if cx.values is not None else np.zeros(cx.n))


def lower_star_filtration(simplices, vertex_values) -> Filtration:
    """The lower-star filtration: each simplex enters at the largest value of its vertices.

    Thesis: §4.2.6 context (discrete Morse functions from vertex values; ProcessLowerStars).

    ``simplices``: any complex (a ``Filtration``, whose values are replaced, or simplices; all faces
    are added).  Raises ValueError for NaN/inf values or values not covering every vertex.
    """
    arrays = as_complex(simplices).simplices
    vals = np.asarray(vertex_values, dtype=np.float64)
    if vals.ndim != 1:
        raise ValueError(f"vertex values must be a 1-D array, got shape {vals.shape}")
    if not np.all(np.isfinite(vals)):
        raise ValueError("vertex values must be finite (no NaN or inf)")
    if int(arrays[0].max()) >= vals.shape[0]:
        raise ValueError(f"vertex values cover {vals.shape[0]} vertices but the complex uses vertex {int(arrays[0].max())}")
    return Filtration(arrays, [vals[a].max(axis=1) for a in arrays], validate=False)


def filtration_matching(filtration) -> list[tuple[tuple[int, ...], tuple[int, ...]]]:
    """An acyclic matching of the filtration's complex that only pairs simplices of equal value.

    Thesis: §4.2.6 (greedy gradient; minimising critical cells is NP-hard) and Theorem 4.36.

    Greedy coreduction inside every level set {σ : f(σ) = t}: a simplex whose only face of the same
    value is σ is paired with σ.  Along a V-path values never increase, and inside a level the
    coreduction order strictly decreases, so the field is acyclic.
    """
    filt = as_complex(filtration)
    cx, vals = _cells_and_values(filt)
    partner = greedy_partner(cx, "coreduction", vals=vals)
    low = np.flatnonzero(partner > np.arange(cx.n))
    return [(cx.simplex(int(a)), cx.simplex(int(partner[a]))) for a in low]


@dataclass
class MorseReduction:
    """The Morse (reduced) filtered chain complex of a filtration.

    Thesis: Theorem 4.41 (the Morse complex M_k on the critical simplices).

    Attributes
    ----------
    critical : ``critical[d]`` the ``(m_d, d + 1)`` array of critical d-simplices.
    values : ``values[d]`` their filtration values.
    boundaries : ``boundaries[d]`` the Morse boundary ∂̃_d (sparse int64, rows critical (d-1)-cells,
        columns critical d-cells), reduced mod p when ``coefficients`` is a prime p.
    n_cells : simplices of the original filtration.
    coefficients : coefficients of the boundaries (0 = Z, a prime p = Z/p).
    """

    critical: list[np.ndarray]
    values: list[np.ndarray]
    boundaries: list[sp.csc_matrix]
    n_cells: int
    coefficients: int

    @property
    def p(self) -> int:
        """Deprecated name of :attr:`coefficients`."""
        return self.coefficients

    @property
    def n_critical(self) -> int:
        return int(sum(c.shape[0] for c in self.critical))

    @property
    def critical_fraction(self) -> float:
        return self.n_critical / self.n_cells


def morse_reduce(filtration, coefficients: int | None = None, pairs=None, *, p: int | None = None) -> MorseReduction:
    """Reduce a filtration to its filtered Morse complex (critical simplices + Morse boundary).

    Thesis: Theorems 4.41–4.42 (Morse complex on critical cells, boundary by gradient paths).

    Parameters
    ----------
    filtration : a :class:`~thesis_lib.complexes.Filtration` (or ``(simplex, value)`` pairs).
    coefficients : a prime p for Z/p (default 2); 0 keeps integer boundaries (then take
        :func:`reduced_persistence` with a prime).
    pairs : optional acyclic matching to use instead of :func:`filtration_matching`, e.g. the
        ``"lower-star"`` matching of a lower-star filtration; every pair must have equal values
        (ValueError naming the first pair that does not).
    p : deprecated alias of ``coefficients``.
    """
    p = resolve_coefficients(coefficients, p, default=2)
    filt = as_complex(filtration)
    cx, vals = _cells_and_values(filt)
    if pairs is None:
        partner = greedy_partner(cx, "coreduction", vals=vals)
    else:
        partner = partner_array(cx, pairs)
        paired = np.flatnonzero(partner >= 0)
        bad = paired[vals[partner[paired]] != vals[paired]]
        if bad.size:
            g = int(bad.min())
            raise ValueError(
                f"pair {cx.simplex(g)} - {cx.simplex(int(partner[g]))} joins different filtration values "
                f"{vals[g]} and {vals[partner[g]]}: the reduced complex would change the barcode"
            )
    crit, mats = morse_boundary_ids(cx, partner, p)
    critical = [cx.arrays[d][ids - cx.offsets[d]] for d, ids in enumerate(crit)]
    values = [vals[ids] for ids in crit]
    return MorseReduction(critical, values, mats, cx.n, p)


# ---------------------------------------------------------------------------- persistence of a chain complex
@numba.njit(cache=True)
def _inv_mod(a, p):
    r = np.int64(1)
    b = a % p
    e = p - 2
    while e > 0:
        if e & 1:
            r = r * b % p
        b = b * b % p
        e >>= 1
    return r


@numba.njit(cache=True)
def _reduce(n, indptr, indices, data, col_order, p):
    """Column reduction with clearing (twist) mod p on a boundary matrix in filtration positions.

    ``indices`` are row positions in the total order; ``col_order`` lists the columns to process
    (higher dimensions first, each by increasing position).  Returns low[col] (-1 if zero).
    """
    low = np.full(n, -1, dtype=np.int64)
    owner = np.full(n, -1, dtype=np.int64)
    cleared = np.zeros(n, dtype=np.bool_)
    acc = np.zeros(n, dtype=np.int64)
    inq = np.zeros(n, dtype=np.bool_)
    start = np.zeros(n, dtype=np.int64)
    length = np.zeros(n, dtype=np.int64)
    cap = max(16, 2 * indptr[n])
    pool_r = np.empty(cap, dtype=np.int64)
    pool_v = np.empty(cap, dtype=np.int64)
    used = 0
    for c in col_order:
        if cleared[c] or indptr[c + 1] == indptr[c]:
            continue
        heap = [np.int64(0)]
        heap.pop()
        for e in range(indptr[c], indptr[c + 1]):
            r = indices[e]
            acc[r] = (acc[r] + data[e]) % p
            if not inq[r]:
                inq[r] = True
                heapq_push(heap, -r)
        piv = -1
        while len(heap) > 0:
            r = -heap[0]
            if acc[r] == 0:
                heapq_pop(heap)
                inq[r] = False
                continue
            o = owner[r]
            if o < 0:
                piv = r
                break
            # acc += factor * column o, with factor killing row r
            lastv = pool_v[start[o] + length[o] - 1]
            factor = (p - acc[r]) * _inv_mod(lastv, p) % p
            for e in range(start[o], start[o] + length[o]):
                rr = pool_r[e]
                acc[rr] = (acc[rr] + factor * pool_v[e]) % p
                if not inq[rr]:
                    inq[rr] = True
                    heapq_push(heap, -rr)
        # collect the reduced column (sorted ascending, pivot last) and reset
        rows = []
        while len(heap) > 0:
            r = -heapq_pop(heap)
            if inq[r]:
                inq[r] = False
                if acc[r] != 0:
                    rows.append(r)
        if piv >= 0:
            m = len(rows)
            if used + m > cap:
                while used + m > cap:
                    cap *= 2
                nr = np.empty(cap, dtype=np.int64)
                nv = np.empty(cap, dtype=np.int64)
                nr[:used] = pool_r[:used]
                nv[:used] = pool_v[:used]
                pool_r = nr
                pool_v = nv
            start[c] = used
            length[c] = m
            for i in range(m):
                rr = rows[m - 1 - i]
                pool_r[used + i] = rr
                pool_v[used + i] = acc[rr]
            used += m
            owner[piv] = c
            low[c] = piv
            cleared[piv] = True
        for r in rows:
            acc[r] = 0
    return low


@numba.njit(cache=True)
def heapq_push(heap, item):
    heap.append(item)
    i = len(heap) - 1
    while i > 0:
        parent = (i - 1) >> 1
        if heap[parent] <= item:
            break
        heap[i] = heap[parent]
        i = parent
    heap[i] = item


@numba.njit(cache=True)
def heapq_pop(heap):
    last = heap.pop()
    if len(heap) == 0:
        return last
    top = heap[0]
    n = len(heap)
    i = 0
    while True:
        child = 2 * i + 1
        if child >= n:
            break
        if child + 1 < n and heap[child + 1] < heap[child]:
            child += 1
        if heap[child] >= last:
            break
        heap[i] = heap[child]
        i = child
    heap[i] = last
    return top


def chain_persistence(values: list[np.ndarray], boundaries: list, p: int = 2):
    """Barcode of a filtered chain complex: cells with values per dimension, boundary matrices per dimension.

    Thesis: Algorithm 2, §2.3.5 (column reduction over Z/p; pairs give P-intervals, Definition 2.34).

    ``boundaries[d]`` maps d-cells to (d-1)-cells; every cell's boundary must consist of cells with
    value ≤ its own (ties: lower dimension first).  Returns a :class:`thesis_lib.persistence.Barcode`.
    """
    from ..persistence import Barcode

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
        blocks_r.append(r); blocks_c.append(c); blocks_v.append(np.asarray(b.data, dtype=np.int64) % p)
    if blocks_r:
        r, c, v = np.concatenate(blocks_r), np.concatenate(blocks_c), np.concatenate(blocks_v)
    else:
        r = c = v = np.empty(0, dtype=np.int64)
    mat = sp.csc_matrix((v, (r, c)), shape=(n, n), dtype=np.int64)
    mat.sum_duplicates()
    mat.eliminate_zeros()
    mat.sort_indices()
    dims_pos = dims[order]
    col_order = np.lexsort((np.arange(n), -dims_pos)).astype(np.int64)
    low = _reduce(n, mat.indptr.astype(np.int64), mat.indices.astype(np.int64), mat.data.astype(np.int64), col_order, p)
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


def reduced_persistence(reduction: MorseReduction, coefficients: int | None = None, *, p: int | None = None):
    """Barcode of the reduced (Morse) filtered complex; equals the filtration's barcode.

    Thesis: Theorems 4.39 and 4.41 applied to every sublevel complex; Algorithm 2 for the reduction.

    ``coefficients``: the prime field of the persistence (default: the reduction's own, or 2 for a
    reduction over Z); ``p=`` is its deprecated alias.
    """
    if not isinstance(reduction, MorseReduction):
        raise InvalidTypeError(f"expected a MorseReduction (from morse_reduce), got {type(reduction).__name__}")
    default = reduction.coefficients or 2
    p = resolve_coefficients(coefficients, p, default=default, field=True)
    if reduction.coefficients not in (0, p):
        raise ValueError(f"the reduction was computed mod {reduction.coefficients}, cannot take persistence mod {p}")
    return chain_persistence(reduction.values, reduction.boundaries, p)

"""The fast persistence engine: union–find for H0, then cohomology column reduction with clearing.

Same barcode as :func:`~thesis_lib.persistence.algorithm.compute_intervals` on every input (the
pairs of the boundary and the coboundary reductions coincide, de Silva–Morozov–Vejdemo-Johansson
2011), but with

* the order of each dimension by one stable ``argsort`` (only the order *within* a dimension
  matters: a column of dimension d only ever meets rows of dimension d ± 1);
* facets found through a dense edge table (triangles; fused with the matrix assembly, so no facet
  array is stored) or a hash table (higher dimensions), and the coboundary matrix assembled as
  compressed sparse columns by a counting sort (two sequential passes over the cofaces, which also
  find each column's pivot);
* H0 by union–find with the elder rule (the pairs of Reduce on the edge columns);
* dimensions d ≥ 1 on the cohomology side, latest simplex first, pivot = earliest coface;
  columns of simplices already paired one dimension lower are cleared (skipped), columns whose
  pivot is still free (apparent/emergent pairs, the common case) are paired without any work,
  and only colliding columns are reduced, lazily as in Ripser (Bauer 2021): a heap of coface
  entries, added columns kept as combinations V of original coboundaries, in the library's one
  stored-matrix reduction loop (:func:`~thesis_lib.persistence.kernels.reduce_columns`).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from .._unionfind import find as _find
from .._validate import resolve_coefficients
from ..filtration import Filtration, as_complex
from ..jit import njit
from .barcode import Barcode
from .kernels import KEEP_V, reduce_columns

__all__ = ["persistence"]


# ---------------------------------------------------------------------------- coboundary columns
@njit(cache=True)
def _column_storage(indptr: np.ndarray, m_d: int):
    """Turn the per-column counts ``indptr[c + 1]`` into offsets (in place) and allocate the columns:
    (fill cursors, rows, signs, pivot, pivot_sign, pivot_value), no pivot found yet.

    The fill passes of :func:`_coboundary_triangles` and :func:`_coboundary` keep their entry code
    inline: an @njit call per entry there measured 8x slower (even with ``inline="always"``).
    """
    for c in range(m_d):
        indptr[c + 1] += indptr[c]
    fill = indptr[:-1].copy()
    rows = np.empty(indptr[m_d], dtype=np.int32)
    signs = np.empty(indptr[m_d], dtype=np.int8)
    pivot = np.full(m_d, -1, dtype=np.int64)
    pivot_sign = np.zeros(m_d, dtype=np.int64)
    pivot_value = np.full(m_d, np.inf)
    return fill, rows, signs, pivot, pivot_sign, pivot_value


@njit(cache=True)
def _coboundary_triangles(edges: np.ndarray, tris: np.ndarray, n: np.int64, up_values: np.ndarray):
    """:func:`_coboundary` of the edges, fused with the dense facet lookup (no facet array at all)."""
    m_d = edges.shape[0]
    table = np.full(n * n, -1, dtype=np.int32)
    for r in range(m_d):
        table[edges[r, 0] * n + edges[r, 1]] = r
    indptr = np.zeros(m_d + 1, dtype=np.int64)
    for t in range(tris.shape[0]):
        a, b, c = tris[t, 0], tris[t, 1], tris[t, 2]
        e0, e1, e2 = table[b * n + c], table[a * n + c], table[a * n + b]
        if e0 < 0 or e1 < 0 or e2 < 0:
            return indptr, np.empty(0, dtype=np.int32), np.empty(0, dtype=np.int8), indptr, indptr, t
        indptr[e0 + 1] += 1
        indptr[e1 + 1] += 1
        indptr[e2 + 1] += 1
    fill, rows, signs, pivot, pivot_sign, pivot_value = _column_storage(indptr, m_d)
    for t in range(tris.shape[0]):
        v = up_values[t]
        a, b, c = tris[t, 0], tris[t, 1], tris[t, 2]
        for i in range(3):
            if i == 0:
                e = table[b * n + c]
            elif i == 1:
                e = table[a * n + c]
            else:
                e = table[a * n + b]
            rows[fill[e]] = t
            signs[fill[e]] = 1 - 2 * (i & 1)
            fill[e] += 1
            if pivot[e] == -1 or v < pivot_value[e]:
                pivot[e] = t
                pivot_sign[e] = 1 - 2 * (i & 1)
                pivot_value[e] = v
    return indptr, rows, signs, pivot, pivot_sign, -1


def _coboundary_matrix(K, d: int, up_values: np.ndarray):
    """(indptr, rows, signs, pivot, pivot_sign) of δ on the d-simplices of K."""
    m_d = K.simplices[d].shape[0]
    if d == 1:  # edges: the triangles' facets through a dense edge table, fused with the assembly
        lower, upper = K.simplices[1], K.simplices[2]
        n = int(max(lower.max(initial=0), upper.max(initial=0))) + 1
        if n * n <= max(1 << 22, 8 * lower.shape[0]):
            out = _coboundary_triangles(np.ascontiguousarray(lower), np.ascontiguousarray(upper), np.int64(n),
                                        up_values)
            if out[5] >= 0:
                t = upper[out[5]]
                raise ValueError(f"an edge of the triangle {tuple(int(v) for v in t)} is missing from the filtration")
            return out[:5]
    return _coboundary(K.facet_indices(d + 1), up_values, m_d)


# ---------------------------------------------------------------------------- H0: union-find
@njit(cache=True)
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
@njit(cache=True)
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
    fill, rows, signs, pivot, pivot_sign, pivot_value = _column_storage(indptr, m_d)
    for t in range(m_up):
        v = up_values[t]
        for i in range(w):
            c = facets[t, i]
            rows[fill[c]] = t
            signs[fill[c]] = 1 - 2 * (i & 1)
            fill[c] += 1
            if pivot[c] == -1 or v < pivot_value[c]:  # t ascending: ties keep the smaller index
                pivot[c] = t
                pivot_sign[c] = 1 - 2 * (i & 1)
                pivot_value[c] = v
    return indptr, rows, signs, pivot, pivot_sign


# ---------------------------------------------------------------------------- driver
def persistence(filtration: Filtration | Iterable[Any], coefficients: int | None = None, *,
                stats: dict[int, dict[str, int]] | None = None, p: int | None = None) -> Barcode:
    """Barcode of a filtration over Z/p by the fast engine (same result as :func:`compute_intervals`).

    Thesis: Theorem 2.39 / Algorithm 2, §2.3.5 (the same pairs, computed by the dual reduction).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        A :class:`~thesis_lib.filtration.Filtration` (e.g. from :func:`~thesis_lib.complexes.rips`),
        or anything :func:`~thesis_lib.filtration.as_complex` takes.
    coefficients : int, optional
        A prime p: the field Z/p (default 2).
    stats : dict, optional
        Filled per dimension d < dim K with ``{"columns": ..., "additions": ...}`` (columns of the
        reduction after clearing, column additions).
    p : int, optional
        Deprecated alias of ``coefficients`` (warns).

    Returns
    -------
    Barcode
        Dimensions 0 .. dim K with the creating and killing simplices of every interval (for
        :meth:`~Barcode.representative`); the top dimension is listed as complete unless the
        filtration is ``truncated``.

    Raises
    ------
    ValueError
        A complex :func:`~thesis_lib.filtration.as_complex` refuses, ``coefficients`` not a prime, a
        triangle with a missing edge, or more than 2³¹ − 1 simplices in one dimension.

    Notes
    -----
    A filtration cut at ``max_dim`` (``filtration.truncated``, set by
    :func:`~thesis_lib.complexes.rips`) has an incomplete top dimension: the barcode marks it
    (``complete_dimensions``) and shows it only when asked.
    The top dimension's essential classes (a truncated Rips complex has millions) are listed lazily:
    they are sorted into ``intervals(dim K)`` only when first asked for.  Memory: the coboundary
    matrix of one dimension at a time (4 + 1 bytes per incidence) plus one int32 per coface.
    """
    K = as_complex(filtration)
    p = resolve_coefficients(coefficients, p, default=2, field=True)
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
    pv, pe, cleared, ess = _h0(K.facet_indices(1), vrank, order1)
    finish(0, pv, pe, ess)
    if stats is not None:
        stats[0] = {"columns": int(K.simplices[1].shape[0]), "additions": 0}
    # ---- dimensions 1 .. D-1 by cohomology with clearing
    for d in range(1, D):
        m_d = K.simplices[d].shape[0]
        if max(K.simplices[d + 1].shape[0], m_d) >= 2**31 - 1:
            raise ValueError("more than 2**31 simplices in one dimension are not supported")
        up_values = np.ascontiguousarray(K.values[d + 1])
        indptr, rows, signs, pivot, pivot_sign = _coboundary_matrix(K, d, up_values)
        # cohomology: latest d-simplex first, pivot = earliest coface (rows ordered by value, then index)
        born, dies, essential, adds, *_ = reduce_columns(
            indptr, rows, signs, up_values, np.ascontiguousarray(orders[d][::-1]), cleared, pivot, pivot_sign,
            np.int64(p), KEEP_V,
        )
        del indptr, rows, signs, pivot, pivot_sign
        finish(d, born, dies, essential)
        if stats is not None:
            stats[d] = {"columns": int(m_d - cleared.sum()), "additions": int(adds)}
        cleared = np.zeros(K.simplices[d + 1].shape[0], dtype=np.bool_)
        cleared[dies] = True
    # ---- top dimension: every simplex not killing a class creates an essential one (listed lazily:
    # often millions of classes of a truncated complex, which nobody reads)
    essential_top = {D: (K.values[D], ~cleared)}
    return Barcode(
        intervals, range(D + 1), p=p, simplices=pairs, filtration=K, killers=killers, essential=essential_top,
        complete=range(D if getattr(K, "truncated", False) else D + 1),
    )

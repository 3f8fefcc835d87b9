"""numba kernels shared by the flag-complex constructions (Rips, Čech candidates, lazy witness).

A graph is stored as an "upper" CSR structure: for every vertex ``v`` the sorted neighbours
``u > v`` (``indices[indptr[v]:indptr[v + 1]]``) and the edge values in the same places.  A level of
the expansion turns the ``d``-simplices (rows sorted ascending, rows in lexicographic order) into
the ``(d + 1)``-simplices that are cliques, again in lexicographic order, with value = the maximum
of the parent's value and the new edges' values.  Output buffers grow by doubling, so one pass is
enough and no Python object is made per simplex.
"""

from __future__ import annotations

import numpy as np

from .._validate import MAX_SIMPLICES
from ..jit import njit


@njit(cache=True)
def _grow(buf, vals, count):
    new_buf = np.empty((2 * buf.shape[0] + 16, buf.shape[1]), dtype=buf.dtype)
    new_vals = np.empty(2 * vals.shape[0] + 16, dtype=vals.dtype)
    new_buf[:count] = buf[:count]
    new_vals[:count] = vals[:count]
    return new_buf, new_vals


@njit(cache=True, inline="always")
def _append_edge(out, out_v, count, i, j, value):
    """Write edge ``(i, j)`` with ``value`` at row ``count`` of the growing buffers; return them
    (new arrays when they had to grow).  Inlined: it runs once per edge found."""
    if count == out.shape[0]:
        out, out_v = _grow(out, out_v, count)
    out[count, 0] = i
    out[count, 1] = j
    out_v[count] = value
    return out, out_v


@njit(cache=True)
def lower_bound(arr, lo, hi, x):
    while lo < hi:
        mid = (lo + hi) >> 1
        if arr[mid] < x:
            lo = mid + 1
        else:
            hi = mid
    return lo


@njit(cache=True)
def _expand_pass(parents, parent_vals, indptr, indices, edge_vals, out, out_v, fill):
    m, width = parents.shape
    count = 0
    ptr = np.empty(width, dtype=np.int64)
    ends = np.empty(width, dtype=np.int64)
    for r in range(m):
        last = parents[r, width - 1]
        start_last = indptr[last]
        end_last = indptr[last + 1]
        if start_last == end_last:
            continue
        first_cand = indices[start_last]
        ok = True
        for i in range(width - 1):
            v = parents[r, i]
            ptr[i] = lower_bound(indices, indptr[v], indptr[v + 1], first_cand)
            ends[i] = indptr[v + 1]
            if ptr[i] == ends[i]:
                ok = False
                break
        if not ok:
            continue
        base = parent_vals[r]
        for q in range(start_last, end_last):
            w = indices[q]
            val = max(base, edge_vals[q])
            found = True
            for i in range(width - 1):
                p = ptr[i]
                e = ends[i]
                while p < e and indices[p] < w:
                    p += 1
                ptr[i] = p
                if p == e:
                    found = False
                    ok = False
                    break
                if indices[p] != w:
                    found = False
                    break
                if edge_vals[p] > val:
                    val = edge_vals[p]
            if not ok:
                break
            if found:
                if fill:
                    for i in range(width):
                        out[count, i] = parents[r, i]
                    out[count, width] = w
                    out_v[count] = val
                count += 1
    return count


@njit(cache=True)
def expand_level(parents, parent_vals, indptr, indices, edge_vals):
    """All cliques one dimension up from ``parents``; returns ``(children, values)``.

    Two passes over the same loop: count, then fill arrays of the exact size.
    """
    width = parents.shape[1]
    dummy = np.empty((0, width + 1), dtype=np.int64)
    dummy_v = np.empty(0, dtype=np.float64)
    count = _expand_pass(parents, parent_vals, indptr, indices, edge_vals, dummy, dummy_v, False)
    out = np.empty((count, width + 1), dtype=np.int64)
    out_v = np.empty(count, dtype=np.float64)
    _expand_pass(parents, parent_vals, indptr, indices, edge_vals, out, out_v, True)
    return out, out_v


@njit(cache=True)
def pairwise_edges(points, threshold):
    """Pairs ``i < j`` with ``|p_i - p_j| <= threshold`` (lexicographic) and their lengths."""
    n, dim = points.shape
    cap = 1024
    out = np.empty((cap, 2), dtype=np.int64)
    out_v = np.empty(cap, dtype=np.float64)
    count = 0
    t2 = threshold * threshold
    for i in range(n):
        for j in range(i + 1, n):
            s = 0.0
            for k in range(dim):
                diff = points[i, k] - points[j, k]
                s += diff * diff
            if s <= t2 * (1.0 + 1e-12) + 1e-300:
                length = np.sqrt(s)
                if length <= threshold:
                    out, out_v = _append_edge(out, out_v, count, i, j, length)
                    count += 1
    return out[:count].copy(), out_v[:count].copy()


@njit(cache=True)
def matrix_edges(matrix, threshold):
    """Pairs ``i < j`` with ``matrix[i, j] <= threshold`` (lexicographic) and their entries."""
    n = matrix.shape[0]
    cap = 1024
    out = np.empty((cap, 2), dtype=np.int64)
    out_v = np.empty(cap, dtype=np.float64)
    count = 0
    for i in range(n):
        for j in range(i + 1, n):
            v = matrix[i, j]
            if v <= threshold:
                out, out_v = _append_edge(out, out_v, count, i, j, v)
                count += 1
    return out[:count].copy(), out_v[:count].copy()


def upper_csr(n: int, edges: np.ndarray, edge_values: np.ndarray):
    """CSR of the upper neighbours of each vertex from lexicographically sorted edges."""
    counts = np.bincount(edges[:, 0], minlength=n) if edges.shape[0] else np.zeros(n, dtype=np.int64)
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(counts, out=indptr[1:])
    return (indptr, np.ascontiguousarray(edges[:, 1], dtype=np.int64),
            np.ascontiguousarray(edge_values, dtype=np.float64))


def check_expansion(indptr: np.ndarray, max_dim: int) -> None:
    """Refuse up front a clique expansion to ``max_dim`` that could build more than ``MAX_SIMPLICES``.

    A d-simplex of a flag complex is counted once by its lowest vertex, whose d other vertices are
    among its forward neighbours (``indptr`` of the upper adjacency), so there are at most
    Σ_v C(deg⁺(v), d) of them.  Summed over d = 2..max_dim in O(n · max_dim), before any level is
    built: a large ``max_dim`` over a dense graph would otherwise expand for hours before a level
    got too large to store.
    """
    from scipy.special import comb

    deg = np.diff(indptr)
    top = min(int(max_dim), int(deg.max(initial=0)))
    bound = float(sum(np.sum(comb(deg, d, exact=False)) for d in range(2, top + 1)))
    if bound > MAX_SIMPLICES:
        raise ValueError(f"simplices of dimension 2 to {max_dim} could number up to {bound:.3g} (more than "
                         f"the limit of {MAX_SIMPLICES:,}): lower max_radius or max_dim")


def flag_levels(n: int, edges: np.ndarray, edge_values: np.ndarray, max_dim: int,
                vertex_values: np.ndarray | None = None):
    """Per-dimension simplex and value arrays of the flag complex of a weighted graph.

    Values: vertices ``vertex_values`` (default 0), a simplex the maximum over its edges.
    """
    simplices = [np.arange(n, dtype=np.int64).reshape(n, 1)]
    values = [np.zeros(n) if vertex_values is None else np.asarray(vertex_values, dtype=np.float64)]
    if max_dim >= 1:
        order = np.lexsort((edges[:, 1], edges[:, 0])) if edges.shape[0] else np.empty(0, np.int64)
        edges = np.ascontiguousarray(edges[order], dtype=np.int64)
        edge_values = np.ascontiguousarray(edge_values[order], dtype=np.float64)
        if vertex_values is not None and edges.shape[0]:
            edge_values = np.maximum(edge_values, np.maximum(values[0][edges[:, 0]], values[0][edges[:, 1]]))
        simplices.append(edges)
        values.append(edge_values)
        indptr, indices, vals = upper_csr(n, edges, edge_values)
        check_expansion(indptr, max_dim)
        for _ in range(2, max_dim + 1):
            if simplices[-1].shape[0] == 0:
                break
            s, v = expand_level(simplices[-1], values[-1], indptr, indices, vals)
            simplices.append(s)
            values.append(v)
    return simplices, values


def edges_within(points: np.ndarray, threshold: float) -> tuple[np.ndarray, np.ndarray]:
    """Lexicographic pairs ``i < j`` at distance <= ``threshold`` and their lengths.

    Brute force in numba for small inputs; a k-d tree (scipy) when there are many points in low
    dimension and the threshold is finite (then far pairs are never looked at).
    """
    n, dim = points.shape
    if n > 2000 and dim <= 8 and np.isfinite(threshold):
        from scipy.spatial import cKDTree

        pairs = cKDTree(points).query_pairs(threshold * (1 + 1e-12), output_type="ndarray").astype(np.int64)
        if pairs.shape[0]:
            pairs.sort(axis=1)
            lengths = np.sqrt(((points[pairs[:, 0]] - points[pairs[:, 1]]) ** 2).sum(axis=1))
            keep = lengths <= threshold
            pairs, lengths = pairs[keep], lengths[keep]
            order = np.lexsort((pairs[:, 1], pairs[:, 0]))
            return np.ascontiguousarray(pairs[order]), lengths[order]
        return np.empty((0, 2), np.int64), np.empty(0)
    return pairwise_edges(points, threshold)

"""The flag-complex constructions shared by Rips, Čech candidates and the lazy witness complex.

A graph is stored as an "upper" CSR structure: for every vertex ``v`` the sorted neighbours
``u > v`` (``indices[indptr[v]:indptr[v + 1]]``) and the edge values in the same places.  A level of
the expansion turns the ``d``-simplices (rows sorted ascending, rows in lexicographic order) into
the ``(d + 1)``-simplices that are cliques, again in lexicographic order, with value = the maximum
of the parent's value and the new edges' values.  The loops are compiled C++ (``src/flag_complex.cpp``):
one pass per level, no Python object made per simplex.
"""

from __future__ import annotations

import numpy as np

from .._core import flag_complex
from .._validate import MAX_SIMPLICES


def lower_bound(arr: np.ndarray, lo: int, hi: int, x) -> int:
    """The first position in ``arr[lo:hi]`` whose entry is not below ``x`` (``arr`` sorted there).

    Thesis: §2.1.2 (cliques and witnesses are found in sorted lists).
    """
    while lo < hi:
        mid = (lo + hi) >> 1
        if arr[mid] < x:
            lo = mid + 1
        else:
            hi = mid
    return lo


def expand_level(parents: np.ndarray, parent_vals: np.ndarray, indptr: np.ndarray, indices: np.ndarray,
                 edge_vals: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """All cliques one dimension up from ``parents``; returns ``(children, values)``.

    ``parents``: the d-simplices (sorted rows, lexicographic), ``parent_vals`` their values; the graph
    is the upper CSR ``indptr, indices, edge_vals`` of :func:`upper_csr`.  A child's value is the
    maximum of its parent's and of its new edges' values; children are lexicographic.
    Compiled C++ (``src/flag_complex.cpp``).  Thesis: §2.1.2 (a flag complex).
    """
    return flag_complex.expand_level(np.ascontiguousarray(parents, dtype=np.int64),
                                     np.ascontiguousarray(parent_vals, dtype=np.float64),
                                     np.ascontiguousarray(indptr, dtype=np.int64),
                                     np.ascontiguousarray(indices, dtype=np.int64),
                                     np.ascontiguousarray(edge_vals, dtype=np.float64))


def pairwise_edges(points: np.ndarray, threshold: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs ``i < j`` with ``|p_i - p_j| <= threshold`` (lexicographic) and their lengths.

    Brute force, compiled C++ (``src/flag_complex.cpp``).  Thesis: Definition 2.11.
    """
    return flag_complex.pairwise_edges(np.ascontiguousarray(points, dtype=np.float64), float(threshold))


def matrix_edges(matrix: np.ndarray, threshold: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs ``i < j`` with ``matrix[i, j] <= threshold`` (lexicographic) and their entries.

    Compiled C++ (``src/flag_complex.cpp``).  Thesis: Definition 2.11.
    """
    return flag_complex.matrix_edges(np.ascontiguousarray(matrix, dtype=np.float64), float(threshold))


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

    Brute force in compiled C++ for small inputs; a k-d tree (scipy) when there are many points in low
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

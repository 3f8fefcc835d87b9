"""Fast facet lookup: where each facet of a simplex sits in the array of the dimension below.

The one kernel behind :meth:`thesis_lib.filtration.Filtration.facet_indices` (and so behind every
boundary and coboundary matrix of the library).  Rows of the lower array are hashed by their
vertices read as digits in base ``n`` (the number of vertices); a table of edge indices is used for
triangles when n² is small.  Keys that would not fit in 63 bits fall back to a sorted search.
"""

from __future__ import annotations

import numpy as np

from .jit import njit
from .simplicial import facets, find_rows

__all__ = ["facet_indices"]


@njit(cache=True)
def _hash(key: np.int64, mask: np.int64) -> np.int64:
    h = np.uint64(key) * np.uint64(0x9E3779B97F4A7C15)
    return np.int64(h >> np.uint64(20)) & mask


@njit(cache=True)
def _hashed(lower: np.ndarray, upper: np.ndarray, base: np.int64) -> np.ndarray:
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


@njit(cache=True)
def _edge_table(edges: np.ndarray, tris: np.ndarray, n: np.int64) -> np.ndarray:
    """Facets of triangles through a dense n × n table of edge indices (small n: cache friendly)."""
    table = np.full(n * n, -1, dtype=np.int64)
    for r in range(edges.shape[0]):
        table[edges[r, 0] * n + edges[r, 1]] = r
    out = np.empty((tris.shape[0], 3), dtype=np.int64)
    for r in range(tris.shape[0]):
        a, b, c = tris[r, 0], tris[r, 1], tris[r, 2]
        out[r, 0] = table[b * n + c]
        out[r, 1] = table[a * n + c]
        out[r, 2] = table[a * n + b]
    return out


def facet_indices(lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """``(m, d + 1)`` indices into ``lower`` ((d−1)-simplices, rows ascending) of the facets of the
    rows of ``upper`` (d-simplices); column i omits vertex i.

    Thesis: Definition 2.18 (the faces in the boundary of a simplex).

    Parameters
    ----------
    lower : numpy.ndarray, shape (m0, d)
        The ``(d−1)``-simplices, sorted rows without duplicates.
    upper : numpy.ndarray, shape (m, d + 1)
        The ``d``-simplices, sorted rows.

    Returns
    -------
    numpy.ndarray of int64, shape (m, d + 1)
        ``lower[out[r, i]]`` is ``upper[r]`` without its vertex ``i``.

    Raises
    ------
    ValueError
        A facet is missing from ``lower`` (naming it and its coface).
    """
    d = upper.shape[1] - 1
    if upper.shape[0] == 0:
        return np.empty((0, d + 1), dtype=np.int64)
    base = int(max(lower.max(initial=0), upper.max(initial=0))) + 1
    lower, upper = np.ascontiguousarray(lower, dtype=np.int64), np.ascontiguousarray(upper, dtype=np.int64)
    if d * np.log2(base) >= 62:  # keys would overflow: sorted search
        return find_rows(lower, facets(upper).reshape(-1, d)).reshape(upper.shape[0], d + 1)
    if d == 2 and base * base <= max(1 << 22, 8 * lower.shape[0]):
        out = _edge_table(lower, upper, np.int64(base))
    else:
        out = _hashed(lower, upper, np.int64(base))
    if (out < 0).any():
        r, i = np.argwhere(out < 0)[0]
        face = tuple(int(v) for j, v in enumerate(upper[r]) if j != i)
        raise ValueError(f"face {face} of {tuple(int(v) for v in upper[r])} is missing from the complex")
    return out

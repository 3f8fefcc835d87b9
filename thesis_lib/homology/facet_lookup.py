"""Fast facet lookup: where each facet of a simplex sits in the array of the dimension below.

The one compiled kernel (C++, ``src/facet_lookup.cpp``) behind
:meth:`thesis_lib.homology.filtration.Filtration.facet_indices` (and so behind every boundary and coboundary
matrix of the library).  Rows of the lower array are hashed by their
vertices read as digits in base ``n`` (the number of vertices); a table of edge indices is used for
triangles when n² is small.  Keys that would not fit in 63 bits fall back to a sorted search.
"""

from __future__ import annotations

import numpy as np

from .._core import facet_lookup
from .simplicial import facets, find_rows

__all__ = ["facet_indices"]


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
        out = facet_lookup.edge_table(lower, upper, base)
    else:
        out = facet_lookup.hashed(lower, upper, base)
    if (out < 0).any():
        r, i = np.argwhere(out < 0)[0]
        face = tuple(int(v) for j, v in enumerate(upper[r]) if j != i)
        raise ValueError(f"face {face} of {tuple(int(v) for v in upper[r])} is missing from the complex")
    return out

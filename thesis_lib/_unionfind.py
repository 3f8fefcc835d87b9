"""Union–find (disjoint sets) with path halving: the one ``find`` of the compiled kernels.

Used by the elder rule of H₀ (Definition 2.31, both persistence engines) and by the link check of
pseudo-manifolds (§3.3).  Compiled by numba on first use (:mod:`thesis_lib.jit`).
"""

from __future__ import annotations

from .jit import njit

__all__ = ["find"]


@njit(cache=True)
def find(parent, x):
    """The root of ``x`` in the forest ``parent`` (halving the path on the way).

    Thesis: §2.3.4 (H₀ by the elder rule joins components as edges enter the filtration).
    """
    while parent[x] != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x

"""Bistellar flips: the cheap repair of a triangulation that is valid but not regular everywhere.

Qhull's triangulation of co-spherical points (an exact grid: every unit square on one circle) is
valid but splits each such cell its own way, where the symbolically perturbed regular triangulation
(GUDHI's) splits it another.  Lawson's algorithm repairs this locally: a facet F = σ ∩ τ whose
opposite vertex y lies inside the orthogonal sphere of σ = F ∪ {x} is flipped.  When the segment xy
crosses the interior of F, the flip replaces σ and τ by the d simplices (F − f_k) ∪ {x, y} (2 → 2
in the plane, 2 → 3 in space); in the plane such a flip always exists while the triangulation is
not regular, and each flip lowers the lifted surface, so the rounds end.  What the flips cannot
reach (3 → 2 flips, flat simplices) is left to the exact re-triangulation of :mod:`.triangulation`.

Flips are done in rounds: all failing facets whose flips are independent (no simplex in two of
them) are flipped at once, vectorised, and the certificate is recomputed.
"""

from __future__ import annotations

import numpy as np

from .predicates import Geometry

__all__ = ["flip_round"]


def flip_round(geo: Geometry, tri: np.ndarray, failing: np.ndarray, orient: np.ndarray) -> np.ndarray | None:
    """One round of independent 2 → d flips of non-regular facets; None if none can be flipped.

    Thesis: Definition 2.13 (the Delaunay complex; Lawson's flips reach it in the plane).

    Parameters
    ----------
    geo : points, weights and predicates.
    tri : (m, d + 1) sorted simplices of a valid triangulation.
    failing : (k, 4) facets that are not locally regular: simplex σ, index of x in σ, simplex τ,
        index of y in τ (the facet is σ without x).
    orient : (m,) orientation signs of the simplices.

    Returns
    -------
    The new (m + k (d − 2), d + 1) triangulation, or None when no failing facet is flippable.
    """
    d = geo.d
    s1, i1, s2, i2 = failing.T
    usable = (orient[s1] != 0) & (orient[s2] != 0)
    s1, i1, s2, i2 = s1[usable], i1[usable], s2[usable], i2[usable]
    if s1.size == 0:
        return None
    x = tri[s1, i1]
    y = tri[s2, i2]
    keep_cols = np.array([[j for j in range(d + 1) if j != i] for i in range(d + 1)])
    f = np.take_along_axis(tri[s1], keep_cols[i1], axis=1)  # (k, d) the common facet
    # the segment xy crosses the interior of F iff every (F with f_k replaced by y, x) has the
    # orientation of (F, x)
    base = geo.orientation(np.column_stack([f, x]))
    crossing = base != 0
    for k in range(d):
        g = f.copy()
        g[:, k] = y
        crossing &= geo.orientation(np.column_stack([g, x])) == base
    rows = np.flatnonzero(crossing)
    # independent flips: no simplex in two of them (greedy in order)
    used = np.zeros(len(tri), dtype=bool)
    chosen = []
    for r in rows.tolist():
        a, b = s1[r], s2[r]
        if not used[a] and not used[b]:
            used[a] = used[b] = True
            chosen.append(r)
    if not chosen:
        return None
    chosen = np.array(chosen)
    new = []
    for k in range(d):
        g = np.delete(f[chosen], k, axis=1)
        new.append(np.column_stack([g, x[chosen], y[chosen]]))
    new = np.sort(np.vstack(new), axis=1)
    return np.vstack([tri[~used], new])

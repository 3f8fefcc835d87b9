"""The (regular) Delaunay complex: the nerve of the (weighted) Voronoi diagram (Definition 2.13).

The weighted Delaunay (regular) triangulation is the lower convex hull of the lifted points
``(x, |x|² − w_x)`` in R^{d+1} (qhull through :class:`scipy.spatial.ConvexHull`); with zero weights it
is the ordinary Delaunay triangulation.  A point whose lifted image lies above the lower hull has an
empty (weighted) Voronoi cell and is not a vertex (§2.1.2).
"""

from __future__ import annotations

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import ConvexHull, QhullError

from .._validate import as_points, check_weights
from ..simplicial import closure

__all__ = ["delaunay", "regular_triangulation"]

#: largest number of co-spherical points in one Delaunay cell we expand into all 2^k − 1 subsets
MAX_CELL_VERTICES = 16


def _prepare(points, weights):
    pts = as_points(points, allow_duplicates=False)
    n, d = pts.shape
    if n < d + 1:
        raise ValueError(f"a Delaunay complex in R^{d} needs at least {d + 1} points, got {n}")
    w = np.zeros(n) if weights is None else check_weights(weights, n)
    return pts, w


def regular_triangulation(points, weights=None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Top simplices of the regular (weighted Delaunay) triangulation, with hull data.

    Thesis: Definition 2.13 (Delaunay complex) for weighted points (§2.1.2, power distance π_x).

    Returns
    -------
    simplices : (m, d + 1) int array, rows ascending (lower facets of the lifted hull).
    equations : (m, d + 2) hyperplane equations of those facets in the lifted space.
    neighbours : (m, d + 1) index of the lower facet opposite each vertex (-1: none).
    lifted : (n, d + 1) the lifted points (centred and scaled), in the frame of ``equations``.
    Degenerate (co-spherical) configurations are triangulated arbitrarily, as qhull does.
    """
    pts, w = _prepare(points, weights)
    return _lower_hull(pts, w)


def _lower_hull(pts: np.ndarray, w: np.ndarray):
    n, d = pts.shape
    centred = pts - pts.mean(axis=0)
    scale = float(np.abs(centred).max()) or 1.0
    centred /= scale
    lift = np.einsum("ij,ij->i", centred, centred) - w / scale**2
    top = lift.max() + (lift.max() - lift.min()) + 1.0
    # an extra point far above the data: the hull is full-dimensional even for co-spherical input
    lifted = np.vstack([np.column_stack([centred, lift]), np.append(np.zeros(d), top)])
    try:
        hull = ConvexHull(lifted, qhull_options="Qt Qbb")
    except QhullError as err:
        raise ValueError(
            f"the points span less than R^{d} (affinely dependent: all on a hyperplane), "
            "so they have no Delaunay triangulation"
        ) from err
    lower = (hull.equations[:, d] < -1e-12) & ~np.any(hull.simplices == n, axis=1)
    if not lower.any():
        raise ValueError("degenerate input: no lower hull facet (points affinely dependent?)")
    ids = np.flatnonzero(lower)
    remap = np.full(hull.simplices.shape[0], -1, dtype=np.int64)
    remap[ids] = np.arange(ids.size)
    tri = hull.simplices[ids]
    nb = remap[hull.neighbors[ids]]
    order = np.argsort(tri, axis=1)
    tri_sorted = np.take_along_axis(tri, order, axis=1)
    nb_sorted = np.take_along_axis(nb, order, axis=1)
    return tri_sorted.astype(np.int64), hull.equations[ids], nb_sorted, lifted[:n]


def delaunay(points, weights=None, *, tol: float = 1e-10) -> list[tuple[int, ...]]:
    """All simplices (every face) of the (regular) Delaunay complex, the nerve of the Voronoi diagram.

    Thesis: Definition 2.13; weighted points use the power distance π_x(u) = |u − x|² − w_x.

    Parameters
    ----------
    points : (n, d) array, n >= d + 1, no duplicate points, not all on a hyperplane.
    weights : optional (n,) squared radii w_x >= 0.
    tol : tolerance on the (unit-normal) hyperplane equations of neighbouring lifted facets deciding
        that they are one facet, i.e. that d + 2 or more points are co-spherical.  Co-spherical cells are kept whole, as the nerve demands: d + 2 points on a
        common sphere give a (d + 1)-simplex (Voronoi cells meeting in one vertex).

    Returns
    -------
    The simplices as ascending vertex tuples, sorted by dimension, then lexicographically.
    Points with an empty weighted Voronoi cell are left out.
    """
    tri, eqs, nb, _ = regular_triangulation(points, weights)
    m, width = tri.shape
    # merge neighbouring lower facets lying on one hyperplane (co-spherical points).  Compare the
    # hyperplanes themselves, not "the opposite vertex lies on my plane": qhull's triangulation of a
    # co-spherical cell may hold flat simplices inside a face shared with the next cell, whose
    # vertices lie on both cells' spheres.
    rows, cols = [], []
    for j in range(width):
        g = nb[:, j]
        has = g >= 0
        f_ids = np.flatnonzero(has)
        g_ids = g[has]
        same = np.max(np.abs(eqs[f_ids] - eqs[g_ids]), axis=1) <= tol
        rows.append(f_ids[same])
        cols.append(g_ids[same])
    rows, cols = np.concatenate(rows), np.concatenate(cols)
    cells: list[tuple[int, ...]]
    if rows.size == 0:
        cells = [tuple(int(v) for v in r) for r in tri]
    else:
        graph = coo_matrix((np.ones(rows.size), (rows, cols)), shape=(m, m))
        _, label = connected_components(graph, directed=False)
        groups: dict[int, set[int]] = {}
        for lab, r in zip(label.tolist(), tri.tolist()):
            groups.setdefault(lab, set()).update(r)
        cells = [tuple(sorted(g)) for g in groups.values()]
        big = max(len(c) for c in cells)
        if big > MAX_CELL_VERTICES:
            raise ValueError(
                f"{big} points lie on one empty sphere: their Delaunay cell would give 2^{big} − 1 "
                "simplices; perturb the points slightly"
            )
    out: list[tuple[int, ...]] = []
    for arr in closure(cells):
        out.extend(tuple(r) for r in arr.tolist())
    return out

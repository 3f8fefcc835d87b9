"""The (regular) Delaunay complex: the nerve of the (weighted) Voronoi diagram (Definition 2.13).

The regular triangulation comes from :mod:`.triangulation` (Qhull, certified and repaired with
exact predicates).  Where d + 2 or more points lie exactly on one empty (orthogonal) sphere, their
Voronoi cells meet in one Voronoi vertex, and the nerve holds the whole cell as one simplex: such
cells are merged from the neighbouring simplices whose common facet is an exact tie.  A point whose
lifted image lies above the lower hull has an empty (weighted) Voronoi cell and is not a vertex.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ..homology.simplicial import closure
from .triangulation import prepare_geometry, triangulate

__all__ = ["delaunay"]

#: largest number of co-spherical points in one Delaunay cell we expand into all 2^k − 1 subsets
MAX_CELL_VERTICES = 16


def delaunay(points: npt.ArrayLike, weights: npt.ArrayLike | None = None) -> list[tuple[int, ...]]:
    """All simplices (every face) of the (regular) Delaunay complex, the nerve of the Voronoi diagram.

    Thesis: Definition 2.13; weighted points use the power distance π_x(u) = |u − x|² − w_x.

    Parameters
    ----------
    points : (n, d) array, n >= d + 1, no duplicate points, not all on a hyperplane.
    weights : optional (n,) squared radii w_x >= 0.

    Returns
    -------
    list of tuple
        The simplices as ascending vertex tuples, sorted by dimension, then lexicographically.
        Points with an empty weighted Voronoi cell are left out.  Co-spherical cells are kept
        whole, as the nerve demands: d + 2 points exactly on a common empty sphere give a
        (d + 1)-simplex (Voronoi cells meeting in one vertex); co-sphericity is decided exactly.
        Without such ties this is GUDHI's ``DelaunayComplex`` (``AlphaComplex`` with weights).

    Raises
    ------
    ValueError
        Invalid points or weights, or a complex estimated above ``MAX_DELAUNAY_SIMPLICES``
        simplices (``check_delaunay_size``).

    Examples
    --------
    Four points in convex position, not co-circular: two triangles sharing the diagonal (1, 2):

    >>> delaunay([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.2]])[4:]
    [(0, 1), (0, 2), (1, 2), (1, 3), (2, 3), (0, 1, 2), (1, 2, 3)]

    The four corners of a square lie on one empty circle, so the nerve keeps the whole cell, a
    tetrahedron:

    >>> delaunay([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])[-1]
    (0, 1, 2, 3)
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    geo, _ = prepare_geometry(points, weights)
    t = triangulate(geo)
    tri, ties = t.simplices, t.ties
    m = len(tri)
    cells: list[tuple[int, ...]]
    if ties.size == 0:
        cells = [tuple(int(v) for v in r) for r in tri]
    else:
        graph = coo_matrix((np.ones(len(ties)), (ties[:, 0], ties[:, 1])), shape=(m, m))
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

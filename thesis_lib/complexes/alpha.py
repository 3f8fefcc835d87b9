"""The (weighted) alpha complex filtration (thesis Definition 2.14 and §2.1.2, weighted points).

Values are ε² (DESIGN.md): σ ∈ A(X, ε) iff its value is <= ε².  For a Delaunay simplex σ with
smallest orthogonal ("circum-") sphere of centre c and squared radius r² — the smallest ball meeting
every weighted point's sphere orthogonally, |c − x|² − w_x = r² for x ∈ σ, c in the affine hull —

* σ is *unattached* (Gabriel) if no vertex y of a coface σ ∪ {y} lies strictly inside that sphere,
  i.e. |c − y|² − w_y >= r²; then its value is r²;
* otherwise σ is *attached* and its value is the smallest value of its cofaces.

Unweighted vertices enter at 0, a weighted vertex at −w (its ball has squared radius w + ε²).  This
is the rule GUDHI's ``AlphaComplex`` implements, computed here one dimension at a time with batched
linear solves.
"""

from __future__ import annotations

import numpy as np

from ..simplicial import facets, find_rows, row_keys
from .delaunay import _lower_hull, _prepare
from ..filtration import Filtration

__all__ = ["alpha", "orthoballs"]


def orthoballs(points: np.ndarray, weights: np.ndarray, simplices: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Centres ``(m, d)`` and squared radii ``(m,)`` of the smallest orthogonal spheres of simplices.

    Thesis: §2.1.2 (weighted point x ↔ sphere of squared radius w_x; power distance π_x).
    With zero weights this is the smallest circumscribed sphere (centre in the affine hull).
    """
    p = points[simplices]  # (m, k+1, d)
    wv = weights[simplices]
    p0 = p[:, 0, :]
    if simplices.shape[1] == 1:
        return p0.copy(), -wv[:, 0]
    a = p[:, 1:, :] - p0[:, None, :]  # (m, k, d)
    gram = 2.0 * np.einsum("mid,mjd->mij", a, a)
    rhs = np.einsum("mid,mid->mi", a, a) - wv[:, 1:] + wv[:, :1]
    lam = np.linalg.solve(gram, rhs[..., None])[..., 0]
    offset = np.einsum("mi,mid->md", lam, a)
    centre = p0 + offset
    r2 = np.einsum("md,md->m", offset, offset) - wv[:, 0]
    return centre, r2


def _face_levels(top: np.ndarray, n: int) -> tuple[list[np.ndarray], dict[int, np.ndarray]]:
    """All faces of the top simplices, per dimension in lexicographic order, with facet indices."""
    k_top = top.shape[1] - 1
    top = top[np.lexsort(top.T[::-1])]
    levels: list[np.ndarray] = [None] * (k_top + 1)  # type: ignore[list-item]
    levels[k_top] = top
    fidx_of: dict[int, np.ndarray] = {}
    for k in range(k_top - 1, -1, -1):
        upper = levels[k + 1]
        f = facets(upper).reshape(-1, k + 1)
        keys = row_keys(f, n)
        if keys is None:  # too many vertices for int64 keys: slower generic path
            lower = np.unique(f, axis=0)
            inverse = find_rows(lower, f)
        else:
            uniq, inverse = np.unique(keys, return_inverse=True)
            lower = np.empty((uniq.shape[0], k + 1), dtype=np.int64)
            rest = uniq.copy()
            for j in range(k, -1, -1):
                lower[:, j] = rest % n
                rest //= n
        levels[k] = lower
        fidx_of[k + 1] = np.asarray(inverse, dtype=np.int64).reshape(upper.shape[0], k + 2)
    return levels, fidx_of


def alpha(points, weights=None) -> Filtration:
    """Alpha filtration of the (weighted) Delaunay complex; values are squared radii ε².

    Thesis: Definition 2.14 (A(X, ε), nerve of R(x, ε) = V_x ∩ B(x, ε)) and the weighted version
    of §2.1.2 (balls of squared radius w_x + ε², so a weighted vertex enters at −w_x).

    Parameters
    ----------
    points : (n, d) array, n >= d + 1, no duplicates, not all on a hyperplane.
    weights : optional (n,) squared radii w_x >= 0.

    Returns
    -------
    Filtration over the Delaunay complex (simplices up to dimension d; co-spherical cells are
    triangulated).  Vertex indices are row numbers of ``points``; with weights, points whose
    Voronoi cell is empty are missing (their rows have no vertex).
    """
    pts, w = _prepare(points, weights)
    tri, _, _, _ = _lower_hull(pts, w)
    weighted = weights is not None
    d = pts.shape[1]
    # drop zero-volume simplices that qhull's triangulation can leave on co-spherical input
    edges_vec = pts[tri[:, 1:]] - pts[tri[:, :1]]
    vol = np.abs(np.linalg.det(edges_vec))
    tri = tri[vol > 1e-12 * vol.max()]
    levels, fidx_of = _face_levels(tri, pts.shape[0])
    top = len(levels) - 1
    values: list[np.ndarray] = [None] * (top + 1)  # type: ignore[list-item]
    # work in coordinates centred at the mean (better conditioned solves)
    centred = pts - pts.mean(axis=0)
    _, r2_top = orthoballs(centred, w, levels[top])
    values[top] = r2_top
    for k in range(top - 1, -1, -1):
        lower = levels[k]
        if k == 0 and not weighted:
            values[0] = np.zeros(lower.shape[0])
            continue
        centre, r2 = orthoballs(centred, w, lower)
        upper = levels[k + 1]
        fidx = fidx_of[k + 1]
        # column i of fidx is the facet omitting vertex i, so upper[:, i] is its opposite vertex
        diff = centred[upper] - centre[fidx]
        power = np.einsum("mid,mid->mi", diff, diff) - w[upper] - r2[fidx]
        attached = np.zeros(lower.shape[0], dtype=bool)
        attached[fidx[power < 0]] = True
        coface_min = np.full(lower.shape[0], np.inf)
        np.minimum.at(coface_min, fidx.ravel(), np.repeat(values[k + 1], k + 2))
        values[k] = np.where(attached, coface_min, r2)
    # a simplex never enters before its faces (rounding), as GUDHI's make_filtration_non_decreasing
    for k in range(1, top + 1):
        values[k] = np.maximum(values[k], values[k - 1][fidx_of[k]].max(axis=1))
    return Filtration(levels, values, validate=False)

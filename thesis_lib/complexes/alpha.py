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
import numpy.typing as npt

from .._core import alpha_complex
from ..homology.filtration import Filtration
from ..homology.simplicial import facets, find_rows, row_keys
from .orthoballs import attached, orthoballs
from .predicates import UNIT
from .scaling import unscale_values
from .triangulation import lexicographic, lexicographic_order, prepare_geometry, triangulate

__all__ = ["alpha"]


def _face_levels(top: np.ndarray, nb: np.ndarray, n: int) -> tuple[list[np.ndarray], dict[int, np.ndarray]]:
    """All faces of the top simplices (lexicographically sorted, with their neighbours), per
    dimension in lexicographic order, with facet indices.

    ``fidx_of[k][r, i]`` is the row in ``levels[k - 1]`` of the facet of ``levels[k][r]`` that omits
    its vertex i.  The facets of the top simplices come from the neighbours (no search), the
    vertices directly; the levels in between by sorting.
    """
    k_top = top.shape[1] - 1
    levels: list[np.ndarray] = [None] * (k_top + 1)  # type: ignore[list-item]
    levels[k_top] = top
    fidx_of: dict[int, np.ndarray] = {}
    for k in range(k_top - 1, -1, -1):
        upper = levels[k + 1]
        if k == 0:  # vertices: the present points, in index order
            present = np.zeros(n, dtype=bool)
            present[upper.ravel()] = True
            lower = np.flatnonzero(present)
            pos = np.full(n, -1, dtype=np.int64)
            pos[lower] = np.arange(len(lower))
            levels[0] = lower.reshape(-1, 1)
            fidx_of[1] = pos[upper[:, ::-1]]
            continue
        if k == k_top - 1:  # facets of the top simplices, numbered through the neighbours
            ids, rep_s, rep_i = alpha_complex.facet_ids(np.ascontiguousarray(nb, dtype=np.int64))
            keep = np.array([[j for j in range(k + 2) if j != i] for i in range(k + 2)])
            lower = np.take_along_axis(upper[rep_s], keep[rep_i], axis=1)
            srt = lexicographic_order(lower, n)
            relabel = np.empty_like(srt)
            relabel[srt] = np.arange(len(srt))
            levels[k] = lower[srt]
            fidx_of[k + 1] = relabel[ids]
            continue
        f = facets(upper).reshape(-1, k + 1)
        keys = row_keys(f, n)
        if keys is None:  # too many vertices for int64 keys: slower generic path
            lower = np.unique(f, axis=0)
            inverse_f = find_rows(lower, f)
        else:
            uniq, inverse_f = np.unique(keys, return_inverse=True)
            lower = np.empty((uniq.shape[0], k + 1), dtype=np.int64)
            rest = uniq.copy()
            for j in range(k, -1, -1):
                lower[:, j] = rest % n
                rest //= n
        levels[k] = lower
        fidx_of[k + 1] = np.asarray(inverse_f, dtype=np.int64).reshape(upper.shape[0], k + 2)
    return levels, fidx_of


def alpha(points: npt.ArrayLike, weights: npt.ArrayLike | None = None) -> Filtration:
    """Alpha filtration of the (weighted) Delaunay complex; values are squared radii ε².

    Thesis: Definition 2.14 (A(X, ε), nerve of R(x, ε) = V_x ∩ B(x, ε)) and the weighted version
    of §2.1.2 (balls of squared radius w_x + ε², so a weighted vertex enters at −w_x).

    Parameters
    ----------
    points : array_like, shape (n, d)
        The point cloud X: at least d + 1 distinct points, not all on a hyperplane.
    weights : array_like, shape (n,), optional
        The points' weights w_x >= 0 (squared radii of the balls at ε = 0); None: unweighted.

    Returns
    -------
    Filtration
        Over the Delaunay complex (simplices up to dimension d).  Vertex indices are row numbers of
        ``points``; with weights, points whose Voronoi cell is empty are missing (their rows have
        no vertex).

    Notes
    -----
    Exact where it matters (``complexes.predicates``): the triangulation is certified with exact
    predicates, d + 2 co-spherical points are triangulated by CGAL's symbolic perturbation, values
    are exactly rounded where floating point could lose digits and attachment is decided exactly,
    so simplices and values equal GUDHI's ``AlphaComplex(..., precision="exact")`` (values to
    about 1e-13 relative).  Coordinates of any magnitude are scaled by a power of two first;
    values that do not fit in float64 raise ``ValueError``.  A complex estimated above
    ``MAX_DELAUNAY_SIMPLICES`` simplices is refused up front.

    Examples
    --------
    Values are squared radii: an edge of length 1 enters at (1/2)² = 0.25, the right triangle at
    the square of half its hypotenuse:

    >>> import numpy as np
    >>> a = alpha([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.2]])
    >>> a.counts()
    [4, 5, 2]
    >>> np.round(a.values[1], 6).tolist(), np.round(a.values[2], 6).tolist()
    ([0.25, 0.25, 0.5, 0.36, 0.26], [0.5, 0.52])
    """
    geo, e = prepare_geometry(points, weights)
    t = lexicographic(triangulate(geo))
    weighted = weights is not None
    levels, fidx_of = _face_levels(t.simplices, t.neighbours, geo.n)
    top = len(levels) - 1
    values: list[np.ndarray] = [None] * (top + 1)  # type: ignore[list-item]
    values[top] = orthoballs(geo, levels[top])[1]
    for k in range(top - 1, -1, -1):
        lower = levels[k]
        if k == 0 and not weighted:
            values[0] = np.zeros(lower.shape[0])
            continue
        centre, r2, err, exact = orthoballs(geo, lower)
        # the float centres' error estimate covers the solve for the offset from a vertex, not the
        # rounding of vertex + offset (up to u·|c|), which dominates for a simplex far smaller than
        # its distance from the origin (points a few ulps apart): without it the attachment filter
        # trusted a wrong sign
        ball = (centre, r2, err + UNIT * np.sqrt((centre * centre).sum(axis=1)), exact)
        upper = levels[k + 1]
        fidx = fidx_of[k + 1]
        # column i of fidx is the facet omitting vertex i, so upper[:, i] is its opposite vertex
        hit = attached(geo, lower, ball, fidx.ravel(), upper.ravel())
        is_attached = np.zeros(lower.shape[0], dtype=bool)
        is_attached[fidx.ravel()[hit]] = True
        coface_min = alpha_complex.coface_min(np.ascontiguousarray(fidx, dtype=np.int64),
                                              np.ascontiguousarray(values[k + 1], dtype=np.float64),
                                              lower.shape[0])
        values[k] = np.where(is_attached, coface_min, ball[1])
    # a simplex never enters before its faces (float rounding), as GUDHI's make_filtration_non_decreasing
    for k in range(1, top + 1):
        values[k] = np.maximum(values[k], values[k - 1][fidx_of[k]].max(axis=1))
    values = [unscale_values(v, -2 * e, "squared radii") for v in values]
    return Filtration(levels, values, validate=False)

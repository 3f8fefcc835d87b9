"""Smallest orthogonal spheres of simplices, accurate to the last digits (thesis §2.1.2).

For a k-simplex σ of weighted points, the smallest orthogonal sphere has centre c in the affine
hull of σ and squared radius r² with |c − x|² − w_x = r² for every vertex x (with zero weights:
the smallest circumsphere).  Its r² is the alpha value of an unattached simplex; the sign of
π_y(c) − r² = |c − y|² − w_y − r² says whether a vertex y of a coface attaches σ.

Computed in floating point from the vertex that gives the best-conditioned linear system.  The
error of that solve is about κ·u (κ the condition number, u = 2⁻⁵³), amplified by the
cancellation in r² = |c − x₀|² − w₀; rows where the product could exceed about 10⁻¹³ relative
(slivers, thin triangles, nearly co-circular points) are recomputed exactly
(:meth:`~.predicates.Geometry.orthoballs_exact`, correctly rounded), and attachment signs the
float error bound cannot decide are decided exactly.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .filters import orthoball_float, power_filter
from .predicates import UNIT, Geometry

__all__ = ["orthoballs", "attached"]

#: rows whose float error amplification (κ times the cancellation in r²) exceeds this are
#: recomputed exactly; the float rows are then accurate to about 100 · 10 · u ≈ 1e-13
_MAX_AMPLIFICATION = 100.0


def orthoballs(geo: Geometry,
               simplices: npt.NDArray[np.int64]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Centres, squared radii, an error bound on the centres and an "exact" flag per simplex.

    Thesis: §2.1.2 (weighted point x ↔ sphere of squared radius w_x; power distance π_x).

    Parameters
    ----------
    geo : the points and weights (scaled coordinates).
    simplices : (m, k + 1) vertex indices, k <= d, affinely independent.

    Returns
    -------
    centre : (m, d) float64.
    r2 : (m,) float64 squared radii (correctly rounded where ``exact``).
    centre_error : (m,) estimated bound on |computed centre − true centre|.
    exact : (m,) bool, the rows computed with exact arithmetic.
    """
    m, w = simplices.shape
    if w == 1:
        return geo.points[simplices[:, 0]].copy(), -geo.weights[simplices[:, 0]], np.zeros(m), np.ones(m, dtype=bool)
    centre, r2, err, exact = orthoball_float(geo.points, geo.weights, np.ascontiguousarray(simplices, dtype=np.int64),
                                             _MAX_AMPLIFICATION)
    rows = np.flatnonzero(exact)
    if rows.size:
        centre[rows], r2[rows] = geo.orthoballs_exact(simplices[rows])
        err[rows] = 2.0 * UNIT * np.abs(centre[rows]).max(axis=1)
    return centre, r2, err, exact


def attached(geo: Geometry, faces: np.ndarray, ball: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray],
             face_idx: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Is π_y(c) < r² for the orthoball (c, r²) of ``faces[face_idx]`` and the points ``y``?  Exact signs.

    Thesis: §2.1.2 and Definition 2.14 (an attached simplex enters with a coface).

    Parameters
    ----------
    geo : Geometry
        The points and weights (scaled coordinates).
    faces : numpy.ndarray of int, shape (m, k + 1)
        ``k``-simplices.
    ball : tuple of numpy.ndarray
        Their orthoballs as returned by :func:`orthoballs` (centre, r2, centre_error, exact).
    face_idx : numpy.ndarray of int, shape (q,)
        The rows of ``faces`` to test.
    y : numpy.ndarray of int, shape (q,)
        One point index per test (the vertex of a coface opposite the face).

    Returns
    -------
    numpy.ndarray of bool, shape (q,)
        True where π_y(c) < r²: ``y`` lies inside the orthogonal sphere and attaches the face
        (float filter first, exact signs where it cannot decide).
    """
    centre, r2, err, _ = ball
    sign = power_filter(geo.points, geo.weights, centre, r2, err, np.ascontiguousarray(faces, dtype=np.int64),
                        np.ascontiguousarray(face_idx, dtype=np.int64), np.ascontiguousarray(y, dtype=np.int64))
    out = sign < 0
    unsure = np.flatnonzero(sign == 0)
    if unsure.size:
        out[unsure] = geo.power_exact(faces[face_idx[unsure]], y[unsure]) < 0
    return out

"""The Crust algorithm of Amenta, Bern and Kamvysselis (SIGGRAPH 1998) for point clouds in R³.

Steps (ABK98, §4–5):

1. Voronoi diagram of the samples S (as the circumcentres of the Delaunay tetrahedra).
2. Poles: for each sample s, p⁺ is the farthest Voronoi vertex of its cell (for a cell that is
   unbounded, a far point along the mean outward normal of the adjacent convex-hull facets), and p⁻
   the farthest Voronoi vertex v with (v - s)·(p⁺ - s) < 0.
3. Voronoi filtering: the triangles of the Delaunay triangulation of S ∪ P (P = all poles) whose
   three vertices are samples.
4. Filtering by normal: drop a triangle when its normal makes an angle larger than θ with the pole
   vector p⁺ - s at its largest-angle vertex s, or larger than 3θ/2 at another vertex.
5. Trimming: repeatedly remove triangles with a sharp edge (an edge in only one triangle, or whose
   incident triangles all lie in a wedge of angle < π/2), then extract the outer oriented
   2-manifold by walking from an outer triangle: across every edge go to the next triangle met
   when turning about the edge through the outside.

Steps 1–5 are those of every dimension (:mod:`.crust_geometry` and :mod:`.crust_trimming`, shared
with the Crust of Chapter 5, :mod:`.crust_nd`); step 3 is decided without triangulating S ∪ P, by a
one-dimensional linear program along each triangle's dual Voronoi edge.  The samples are scaled by a
power of two to coordinates about 1 first (the Crust is scale-equivariant; Qhull crashes on
coordinates near 1e150).

Degenerate samples.  Four co-circular samples (the isosceles-trapezoid quads of a parameter grid,
such as the thesis's chosen points on the torus) make a flat Delaunay tetrahedron with no
circumcentre.  They are resolved as a symbolic perturbation would (:func:`_flat_tetrahedra`, the
three-dimensional treatment of flat cells that :func:`.crust_geometry.filtered_faces` accepts): one
diagonal per quadrilateral, its two triangles joined to the Voronoi vertices on both sides, so the
Crust of such a grid is closed.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from scipy.spatial import Delaunay, QhullError

from .._validate import as_points, check_real, check_simplices
from ..complexes.scaling import scaled
from .crust_geometry import check_theta, circumcentres, filtered_faces, poles_from_delaunay
from .crust_trimming import outer_walk

__all__ = ["crust", "poles", "crust_candidates", "extract_manifold"]


def _samples(points) -> tuple[np.ndarray, int]:
    pts = as_points(points, min_points=5, allow_duplicates=False, dimension=3)
    # the Crust is scale-equivariant: run it on points scaled by a power of two to about 1 (Qhull
    # crashes on coordinates near 1e150, squared distances overflow beyond)
    return scaled(pts)


def _far(pts: np.ndarray, far: float | None, e: int) -> float:
    """``far`` in the scaled units (default: half the bounding-box diagonal)."""
    diag = float(np.linalg.norm(pts.max(0) - pts.min(0)))
    if far is None:
        return 0.5 * diag
    with np.errstate(over="ignore"):
        return float(np.ldexp(check_real(far, "far", positive=True), e))


def _delaunay(pts: np.ndarray) -> Delaunay:
    try:
        return Delaunay(pts)
    except QhullError:
        raise ValueError("the samples lie in a plane (or a line): the Crust needs a surface sampled in R³") from None


def poles(points: npt.ArrayLike, *, far: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The poles p⁺ and p⁻ of every sample (ABK98, §4).

    Thesis: §3.4, "Triangulations" (Crust algorithm [ABK98]).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        The samples, n >= 5, no duplicates, not coplanar.
    far : float or None, default None
        Distance used for poles at infinity, and cap of all pole distances (default: half the
        diagonal of the bounding box).

    Returns
    -------
    p_plus, p_minus : ndarray of float64, shape (n, 3)
        The poles of each sample; p⁻ falls back to the reflection of p⁺ when a cell has no Voronoi
        vertex on the opposite side.

    Raises
    ------
    ValueError
        On invalid or duplicate points, fewer than 5, points not in R³ or in a plane, or a ``far``
        that is not positive.
    """
    pts, e = _samples(points)
    tri = _delaunay(pts)
    p_plus, p_minus = poles_from_delaunay(pts, tri, *circumcentres(pts[tri.simplices]), _far(pts, far, e))
    return np.ldexp(p_plus, -e), np.ldexp(p_minus, -e)


def _flat_tetrahedra(pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray):
    """Degenerate (co-circular) Delaunay cells, seen as a symbolic perturbation would see them.

    Four co-circular samples (an isosceles trapezoid of a parameter grid, say) have a one-parameter
    family of empty spheres, and Qhull's triangulated output puts a flat tetrahedron between the
    two cells on either side of the quadrilateral: one diagonal's two triangles face one side, the
    other diagonal's face the other, and no circumcentre exists.  A slight perturbation of the
    points would keep one diagonal on both sides.  We keep the diagonal through the smallest sample
    index (a combinatorial rule, so the choice does not depend on rounding) and drop the other
    diagonal's two faces; the Voronoi edge dual to a kept face joins the circumcentres of the cells
    on the two sides (all of them lie on the axis of the circle), which is the dual edge the
    perturbed triangulation would have.

    Returns ``(centre, keep, across)``: ``centre`` is ``cc`` with the circle's centre for flat
    tetrahedra; ``keep[t, k]`` says whether face slot k of tetrahedron t stays a Delaunay face;
    ``across[t, k]`` is, for a kept face of a flat tetrahedron, the cell on the far side of the flat
    tetrahedron (a neighbour across a dropped face; -1 for the outside) and otherwise t itself.
    """
    tets, nbr = tri.simplices, tri.neighbors
    n_tets = len(tets)
    centre = cc.copy()
    keep = np.ones((n_tets, 4), dtype=bool)
    across = np.repeat(np.arange(n_tets)[:, None], 4, axis=1)
    flat = np.flatnonzero(~ok)
    if len(flat) == 0:
        return centre, keep, across
    p = pts[tets[flat]]  # (f, 4, 3)
    # circle centre: circumcentre of the largest of the four faces (they share one circle)
    faces = np.stack([np.delete(p, k, axis=1) for k in range(4)], axis=1)  # (f, 4, 3, 3)
    a, b = faces[:, :, 1] - faces[:, :, 0], faces[:, :, 2] - faces[:, :, 0]
    axb = np.cross(a, b)
    big = np.argmax(np.einsum("fkj,fkj->fk", axb, axb), axis=1)
    rows = np.arange(len(flat))
    a, b, axb, p0 = a[rows, big], b[rows, big], axb[rows, big], faces[rows, big, 0]
    num = np.cross(np.einsum("ij,ij->i", a, a)[:, None] * b - np.einsum("ij,ij->i", b, b)[:, None] * a, axb)
    centre[flat] = p0 + num / (2 * np.einsum("ij,ij->i", axb, axb)[:, None] + 1e-300)
    # the diagonals are the pairing of the four vertices with the largest total length
    pairings = (((0, 1), (2, 3)), ((0, 2), (1, 3)), ((0, 3), (1, 2)))
    length = np.stack([sum(np.linalg.norm(p[:, i] - p[:, j], axis=1) for i, j in pr) for pr in pairings], axis=1)
    best = np.argmax(length, axis=1)
    lowest = np.argmin(tets[flat], axis=1)
    for j, t in enumerate(flat):
        d1, d2 = pairings[best[j]]
        kept, other = (d1, d2) if lowest[j] in d1 else (d2, d1)
        # a face keeps the diagonal `kept` when its opposite vertex (its slot) lies on `other`
        keep[t, list(kept)] = False
        far = [int(nbr[t, k]) for k in kept]
        far = sorted(far, key=lambda x: (x < 0, x >= 0 and not ok[x]))[0]
        across[t, list(other)] = far
    return centre, keep, across


def crust_candidates(points: npt.ArrayLike, *, theta: float = np.pi / 4, far: float | None = None) -> np.ndarray:
    """Steps 1–4 of the Crust: Delaunay triangles of S ∪ P with sample vertices, filtered by normal.

    Thesis: §3.4, "Triangulations" ([ABK98]).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        The samples, as in :func:`poles`.
    theta : float, default π/4
        Normal-filter angle in (0, π/2) (see :func:`crust`).
    far : float or None, default None
        Distance of the poles at infinity, as in :func:`poles`.

    Returns
    -------
    ndarray of int, shape (m, 3)
        Vertex triples, each sorted, in lexicographic order (Qhull's index type).

    Raises
    ------
    ValueError
        As :func:`poles`, or a ``theta`` outside (0, π/2).
    """
    theta = check_theta(theta)
    pts, e = _samples(points)
    return _candidates(pts, e, theta, far)


def _candidates(pts: np.ndarray, e: int, theta: float, far: float | None) -> np.ndarray:
    """The Crust's candidate triangles of parsed, scaled samples (steps 1–4)."""
    return filtered_faces(pts, _delaunay(pts), theta, _far(pts, far, e), resolve_flat=_flat_tetrahedra)[0]


def extract_manifold(points: npt.ArrayLike, triangles: npt.ArrayLike, *, prune: bool = True) -> tuple[np.ndarray, int]:
    """Trimming step of the Crust: sharp-edge removal, then the outer walk from an outer triangle.

    Thesis: §3.4, "Triangulations" ([ABK98], manifold extraction).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        The samples, at least 3.
    triangles : array_like of int, shape (m, 3)
        Candidate triangles (indices into ``points``), e.g. :func:`crust_candidates`.
    prune : bool, default True
        Remove triangles with sharp edges first.

    Returns
    -------
    faces : ndarray of int64, shape (k, 3)
        Consistently oriented faces (outward for a closed surface); faces that would put a third
        face on an edge are left out (in visiting order), so every edge of the result lies in one
        or two faces.
    conflicts : int
        The number of orientation conflicts met by the walk (0 for an orientable result).

    Raises
    ------
    ValueError
        On invalid points or triangles, points not in R³, or (with ``prune``) when trimming
        removes every triangle.
    """
    pts = as_points(points, min_points=3)
    if pts.shape[1] != 3:
        raise ValueError(f"the trimming walks surfaces in R³, got points in R^{pts.shape[1]}")
    pts, _ = scaled(pts)  # angles only: scale-invariant, and cross products stay finite
    tris = check_simplices(triangles, len(pts), "triangles", width=3)
    return outer_walk(pts, tris.astype(np.int64), prune=prune)


def crust(points: npt.ArrayLike, *, theta: float = np.pi / 4, prune: bool = True,
          far: float | None = None) -> np.ndarray:
    """Triangulate a point cloud sampled from a surface in R³ with the Crust algorithm [ABK98].

    Thesis: §3.4, "Triangulations" (the Crust algorithm [ABK98], used for Figures 3.8–3.11).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        Samples without duplicates, n >= 5, not coplanar.
    theta : float, default π/4
        Normal-filter angle θ in (0, π/2) (θ at the largest-angle vertex, 3θ/2 at the others).
        ABK98 leave θ as a parameter; π/4 closes the torus R = 10, r = 5 from 1000 uniform
        samples on, while π/8 already opens holes there.
    prune : bool, default True
        Remove triangles with sharp edges before the walk (right for closed surfaces; switch it
        off for a surface with boundary, where it would eat the surface from its border).  When the
        sample is too sparse and trimming removes every triangle, the walk runs on the untrimmed
        candidates instead (the result then has holes and non-manifold edges).
    far : float or None, default None
        Distance of the poles at infinity and cap of all pole distances (default half the
        bounding-box diagonal).

    Returns
    -------
    ndarray of int64, shape (m, 3)
        Faces into ``points``, consistently oriented (outward for a closed surface).

    Raises
    ------
    ValueError
        As :func:`crust_candidates`, or when no triangle survives the filtering.
    """
    theta = check_theta(theta)
    pts, e = _samples(points)
    cand = _candidates(pts, e, theta, far)
    if len(cand) == 0:
        raise ValueError("no triangle survived the Crust's filtering")
    tris = cand.astype(np.int64)  # indices into the samples, which _samples scaled already
    try:
        faces, _ = outer_walk(pts, tris, prune=prune)
    except ValueError:
        if not prune:
            raise
        faces, _ = outer_walk(pts, tris, prune=False)
    return faces

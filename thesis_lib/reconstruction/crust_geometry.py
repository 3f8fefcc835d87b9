"""The geometric steps 1–4 of the Crust (ABK98) in R^d, d = n + 1, for a hypersurface sample S:
circumcentres, poles, the Delaunay n-simplices with their dual Voronoi edges, the Voronoi filter and
the normal filter.  One implementation serves the 3-D Crust (:mod:`.crust`, which adds its
resolution of flat tetrahedra) and the Crust of Chapter 5 (:mod:`.crust_nd`).

Step 3 without triangulating S ∪ P.  An n-simplex with sample vertices lies in Del(S ∪ P) exactly
when some ball through its vertices is empty of S ∪ P; such a ball is empty of S, so the simplex is
in Del(S), and the centres of its S-empty balls form its dual Voronoi edge (a segment between two
circumcentres, or a ray for a convex-hull face).  A pole p lies inside the ball centred at c
through vertex a iff (a - p)·(2c - a - p) < 0, which is linear along the edge: each pole removes a
half-line, and the test is a one-dimensional linear program.  It is solved by bisection: the
vertices' own poles first, then the midpoint of what is left, where a nearest-pole query (k-d tree,
bounded by the ball's radius) either finds the ball empty (keep the simplex) or names a pole whose
half-line removes the midpoint.  This gives the simplices of Del(S ∪ P) — tests compare with Qhull's
triangulation of S ∪ P in R³ and R⁴ — at a fraction of the cost: the poles cluster along the medial
axis, where Qhull builds about 34 tetrahedra per point (6·10⁴ torus samples) and took 70 s at 10⁵
samples for this step alone.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from scipy.spatial import Delaunay, cKDTree

from .._validate import check_real

__all__ = ["check_theta", "circumcentres", "simplex_normals", "poles_from_delaunay", "filtered_faces"]

#: bisection rounds of the Voronoi filter; an edge interval still open after them is narrower than
#: 2⁻⁶⁰ of the edge (a degenerate, co-spherical configuration) and its simplex is dropped
_MAX_ROUNDS = 60
#: a hull face's Voronoi ray is searched up to this many bounding-box diagonals
_RAY_LENGTH = 1e6

#: ``(pts, tri, cc, ok) -> (centre, keep, across)``: how the flat (circumcentre-less) Delaunay
#: simplices are treated, see :func:`_drop_flat` and :func:`thesis_lib.reconstruction.crust._flat_tetrahedra`
FlatResolution = Callable[[np.ndarray, Delaunay, np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


def check_theta(theta: float) -> float:
    """The Crust's angle θ: a number in (0, π/2), or a ``ValueError`` naming it.

    Thesis: §3.4 (the Crust [ABK98]; θ bounds the angle between a triangle's normal and the poles).

    Parameters
    ----------
    theta : float
        The angle, in radians.

    Returns
    -------
    float
        ``theta``.
    """
    theta = check_real(theta, "theta")
    if not 0 < theta < np.pi / 2:
        raise ValueError(f"theta must lie in (0, π/2), got {theta!r}")
    return theta


def _group_argmax(group: np.ndarray, value: np.ndarray, n_groups: int) -> np.ndarray:
    """Index (into ``value``) of the maximum of each group, -1 for empty/all -inf groups."""
    order = np.lexsort((-value, group))
    g = group[order]
    first = np.ones(len(g), dtype=bool)
    first[1:] = g[1:] != g[:-1]
    out = np.full(n_groups, -1, dtype=np.int64)
    idx = order[first]
    good = np.isfinite(value[idx])
    out[group[idx][good]] = idx[good]
    return out


def circumcentres(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Circumcentres of full-dimensional simplices p (m, d + 1, d) (tetrahedra for d = 3); ``ok`` is
    False for (nearly) flat ones.

    Thesis: §2.1.2 (the Voronoi vertices dual to the Delaunay simplices).

    Parameters
    ----------
    p : ndarray of float64, shape (m, d + 1, d)
        Vertex coordinates of m d-simplices in R^d (no validation).

    Returns
    -------
    centres : ndarray of float64, shape (m, d)
        The circumcentre of each simplex; for a flat one, its vertex 0 (a placeholder).
    ok : ndarray of bool, shape (m,)
        False where |det E| <= 1e-12 · ‖E‖_F^d (E the edge vectors): no reliable circumcentre.
    """
    d = p[:, 1:] - p[:, :1]
    rhs = 0.5 * np.einsum("mij,mij->mi", d, d)
    det = np.linalg.det(d)
    scale = np.einsum("mij,mij->m", d, d) ** (0.5 * p.shape[2]) + 1e-300
    ok = np.abs(det) > 1e-12 * scale
    x = np.zeros((len(p), p.shape[2]))
    x[ok] = np.linalg.solve(d[ok], rhs[ok][..., None])[..., 0]
    return p[:, 0] + x, ok


def simplex_normals(p: np.ndarray) -> np.ndarray:
    """Normals (not unit) of n-simplices p (m, n + 1, n + 1) in R^{n+1}: the cofactors
    N_k = (-1)^k det(E without column k) of the edge vectors E = p_i - p_0 (the cross product for
    n = 2), so det[E; N] = (-1)^n |N|^2.

    Thesis: eq. (3.9) (the normal N = X_{u_1} ∧ ... ∧ X_{u_n} of a hypersurface).

    Parameters
    ----------
    p : ndarray of float64, shape (m, n + 1, n + 1)
        Vertex coordinates of m n-simplices in R^{n+1} (no validation).

    Returns
    -------
    ndarray of float64, shape (m, n + 1)
        The normal N of each simplex, of length n! times its hyperarea.
    """
    e = p[:, 1:] - p[:, :1]
    if p.shape[2] == 3:
        return np.cross(e[:, 0], e[:, 1])
    d = p.shape[2]
    return np.stack([(-1) ** k * np.linalg.det(np.delete(e, k, axis=2)) for k in range(d)], axis=1)


def poles_from_delaunay(
    pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray, far: float
) -> tuple[np.ndarray, np.ndarray]:
    """Poles p⁺, p⁻ of every sample from the Delaunay triangulation ``tri`` of the samples and its
    circumcentres ``cc`` (see :func:`thesis_lib.reconstruction.poles`), in any dimension.

    Thesis: §3.4, "Triangulations" (the Crust [ABK98]).

    Parameters
    ----------
    pts : ndarray of float64, shape (N, d)
        The samples (no validation).
    tri : scipy.spatial.Delaunay
        The Delaunay triangulation of ``pts``.
    cc : ndarray of float64, shape (t, d)
        Circumcentres of ``tri.simplices`` (from :func:`circumcentres`).
    ok : ndarray of bool, shape (t,)
        Which circumcentres are reliable; the others are never poles.
    far : float
        Distance cap: a pole farther than ``far`` from its sample is moved to distance ``far``
        along the same direction, and a sample on the convex hull (unbounded Voronoi cell) gets its
        p⁺ at distance ``far`` along the mean outward normal of its hull facets.

    Returns
    -------
    p_plus : ndarray of float64, shape (N, d)
        The pole p⁺ of each sample: its farthest Voronoi vertex (capped).
    p_minus : ndarray of float64, shape (N, d)
        The pole p⁻: the farthest Voronoi vertex on the other side of p⁺ (negative dot product),
        or the reflection of p⁺ through the sample where there is none.
    """
    n = len(pts)
    tets = tri.simplices
    owner = tets.ravel()
    tet = np.repeat(np.arange(len(tets)), tets.shape[1])
    vec = cc[tet] - pts[owner]
    dist = np.linalg.norm(vec, axis=1)
    dist[~ok[tet]] = -np.inf
    best = _group_argmax(owner, dist, n)
    plus_vec = np.zeros_like(pts)
    has = best >= 0
    plus_vec[has] = vec[best[has]]
    # unbounded Voronoi cells: samples on the convex hull, pole at infinity along the mean normal
    hull = tri.convex_hull
    normal = simplex_normals(pts[hull])
    hp = pts[hull]
    centre = pts.mean(axis=0)
    normal *= np.sign(np.einsum("ij,ij->i", normal, hp[:, 0] - centre))[:, None]
    normal /= np.linalg.norm(normal, axis=1, keepdims=True) + 1e-300
    acc = np.zeros_like(pts)
    np.add.at(acc, hull.ravel(), np.repeat(normal, hull.shape[1], axis=0))
    on_hull = np.zeros(n, dtype=bool)
    on_hull[hull.ravel()] = True
    plus_vec[on_hull] = far * acc[on_hull] / np.linalg.norm(acc[on_hull], axis=1, keepdims=True)
    # p⁻: farthest Voronoi vertex on the other side of p⁺
    side = np.einsum("ij,ij->i", vec, plus_vec[owner])
    dist_minus = np.where(side < 0, dist, -np.inf)
    best_m = _group_argmax(owner, dist_minus, n)
    minus_vec = -plus_vec.copy()
    hm = best_m >= 0
    minus_vec[hm] = vec[best_m[hm]]
    # cap the distances (directions are what the normal filter uses)
    for v in (plus_vec, minus_vec):
        ln = np.linalg.norm(v, axis=1, keepdims=True)
        np.divide(v * np.minimum(ln, far), ln, out=v, where=ln > 0)
    return pts + plus_vec, pts + minus_vec


def _drop_flat(pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray):
    """The default treatment of flat Delaunay simplices (no circumcentre): their faces are left out.

    Returns ``(centre, keep, across)`` as :func:`thesis_lib.reconstruction.crust._flat_tetrahedra` does:
    ``centre`` the Voronoi vertex of each simplex, ``keep[t, k]`` whether face slot k of simplex t
    stays, ``across[t, k]`` the cell whose Voronoi vertex ends the face's dual edge on t's side (t).
    """
    m, k1 = tri.simplices.shape
    return cc, np.repeat(ok[:, None], k1, axis=1), np.repeat(np.arange(m)[:, None], k1, axis=1)


def _candidate_edges(pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray, p_plus: np.ndarray,
                     theta: float, resolve_flat: FlatResolution = _drop_flat):
    """The n-simplices of Del(S) that pass the normal filter, with their dual Voronoi edges
    ``c0 + t d``, t ∈ [0, t_max].

    Processed one face slot of the Delaunay cells at a time (peak memory); the normal filter comes
    first as it is cheap and shortens the Voronoi filter's work.  Flat cells (no circumcentre) are
    treated by ``resolve_flat``: left out with their faces by default, resolved as a symbolic
    perturbation would by the 3-D Crust (:func:`thesis_lib.reconstruction.crust._flat_tetrahedra`).
    """
    tets, nbr = tri.simplices, tri.neighbors
    idx = np.arange(len(tets))
    diag = float(np.linalg.norm(pts.max(0) - pts.min(0)))
    centre, keep, across = resolve_flat(pts, tri, cc, ok)
    faces, c0s, ds, tmaxs = [], [], [], []
    for k in range(tets.shape[1]):
        other = nbr[:, k]
        sel = (other == -1) | (other > idx)  # each interior face once, from its lower cell
        i, o = idx[sel], other[sel]
        face = np.delete(tets[i], k, axis=1)
        # the slot of this face in the neighbour (to read the neighbour's flat-cell data)
        ko = np.zeros(len(o), dtype=np.int64)
        inner = o >= 0
        ko[inner] = np.argmax(nbr[o[inner]] == i[inner, None], axis=1)
        good = keep[i, k] & np.where(inner, keep[np.maximum(o, 0), ko], True)
        # the two cells joined by the dual Voronoi edge (-1 = outside: the edge is a ray)
        end0 = across[i, k]
        end1 = np.where(inner, across[np.maximum(o, 0), ko], -1)
        end0, end1 = np.where(end0 < 0, end1, end0), np.where(end0 < 0, end0, end1)
        good &= end0 >= 0
        good[good] = _normal_filter(pts, face[good], p_plus, theta)
        face, end0, end1 = face[good], end0[good], end1[good]
        c0 = centre[end0]
        d = np.empty_like(c0)
        bounded = end1 >= 0
        d[bounded] = centre[end1[bounded]] - c0[bounded]
        # a face on the convex hull: a ray away from the vertex of end0 farthest from its hyperplane
        hp = pts[face[~bounded]]
        nrm = simplex_normals(hp)
        height = np.einsum("ikj,ij->ik", pts[tets[end0[~bounded]]] - hp[:, :1], nrm)
        apex = height[np.arange(len(height)), np.argmax(np.abs(height), axis=1)]
        nrm *= -np.sign(apex)[:, None]
        d[~bounded] = nrm * (diag / (np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-300))
        faces.append(face)
        c0s.append(c0)
        ds.append(d)
        tmaxs.append(np.where(bounded, 1.0, _RAY_LENGTH))
    return np.concatenate(faces), np.concatenate(c0s), np.concatenate(ds), np.concatenate(tmaxs)


def _cut(lo, hi, rows, a, c0, d, p) -> None:
    """Keep on each Voronoi edge ``rows`` only the centres c whose ball through ``a`` excludes pole ``p``."""
    ap = a[rows] - p
    alpha = np.einsum("ij,ij->i", ap, 2 * c0[rows] - a[rows] - p)  # (a-p)·(2c-a-p) = alpha + beta t
    beta = 2 * np.einsum("ij,ij->i", ap, d[rows])
    with np.errstate(divide="ignore", invalid="ignore"):
        root = -alpha / beta
    up, down = beta > 0, beta < 0
    lo[rows[up]] = np.maximum(lo[rows[up]], root[up])
    hi[rows[down]] = np.minimum(hi[rows[down]], root[down])
    hi[rows[~(up | down) & (alpha < 0)]] = -np.inf


def _voronoi_filter(pts, faces, c0, d, t_max, pole_pts) -> np.ndarray:
    """Mask of the n-simplices that lie in Del(S ∪ P): some point of the Voronoi edge is nearer to
    the simplex's vertices than to every pole (module docstring)."""
    n = len(pts)
    a = pts[faces[:, 0]]
    lo, hi = np.zeros(len(faces)), t_max.astype(np.float64).copy()
    rows = np.arange(len(faces))
    for k in range(faces.shape[1]):  # each vertex's own poles cut most edges that run inside the solid
        for offset in (0, n):
            _cut(lo, hi, rows, a, c0, d, pole_pts[faces[:, k] + offset])
    keep = np.zeros(len(faces), dtype=bool)
    live = rows[lo <= hi]
    tree = cKDTree(pole_pts)
    for _ in range(_MAX_ROUNDS):
        if len(live) == 0:
            break
        c = c0[live] + (0.5 * (lo[live] + hi[live]))[:, None] * d[live]
        rho = np.linalg.norm(c - a[live], axis=1)
        near, which = np.empty(len(c)), np.empty(len(c), dtype=np.int64)
        order = np.argsort(rho)  # nearest-pole queries bounded by the ball radius, in 32 batches
        for batch in np.array_split(order, min(32, len(order))):
            near[batch], which[batch] = tree.query(c[batch], distance_upper_bound=float(rho[batch].max()), workers=-1)
        empty = near >= rho
        keep[live[empty]] = True
        hit = live[~empty]
        _cut(lo, hi, hit, a, c0, d, pole_pts[which[~empty]])
        live = hit[lo[hit] <= hi[hit]]
    return keep


def _normal_filter(pts: np.ndarray, faces: np.ndarray, p_plus: np.ndarray, theta: float) -> np.ndarray:
    """Mask of the n-simplices (triangles for n = 2) whose normal is within θ of the pole vector at
    the vertex opposite the largest facet (for a triangle the largest-angle vertex, by the law of
    sines) and within 3θ/2 at the others (ABK98, §5)."""
    p = pts[faces]
    nrm = simplex_normals(p)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-300
    k1 = faces.shape[1]
    size = np.empty((len(faces), k1))  # squared (n-1)-volume (up to a constant) of the facet opposite k
    for k in range(k1):
        q = np.delete(p, k, axis=1)
        e = q[:, 1:] - q[:, :1]
        size[:, k] = np.linalg.det(np.einsum("mia,mja->mij", e, e)) if e.shape[1] else 1.0
    largest = np.argmax(size, axis=1)
    pole = p_plus[faces] - p
    pole /= np.linalg.norm(pole, axis=2, keepdims=True) + 1e-300
    c = np.abs(np.einsum("ij,ikj->ik", nrm, pole))  # |cos| of line angle per vertex
    limit = np.full((len(faces), k1), np.cos(1.5 * theta))
    limit[np.arange(len(faces)), largest] = np.cos(theta)
    return np.all(c >= limit, axis=1)


def filtered_faces(pts: np.ndarray, tri: Delaunay, theta: float, far: float, *,
                   resolve_flat: FlatResolution = _drop_flat) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Steps 1–4 on the Delaunay triangulation ``tri`` of the samples in R^d: the (d−1)-faces of
    Del(S ∪ P) with sample vertices that pass the normal filter, and the poles.

    Thesis: §3.4, "Triangulations" (the Crust [ABK98]), in any dimension (Chapter 5).

    Parameters
    ----------
    pts : ndarray of float64, shape (N, d)
        The samples (validated, scaled by the caller).
    tri : scipy.spatial.Delaunay
        Their Delaunay triangulation.
    theta : float
        Normal-filter angle in (0, π/2) (checked by the caller).
    far : float
        Distance of the poles at infinity and cap of all pole distances.
    resolve_flat : callable, default: leave the faces of flat cells out
        Treatment of flat Delaunay cells: called as ``resolve_flat(pts, tri, cc, ok)`` with the
        circumcentres and their reliability (:func:`circumcentres`), it returns ``(centre, keep,
        across)``: the Voronoi vertex of each cell, whether each face slot stays, and the cell whose
        Voronoi vertex ends each face's dual edge on the cell's side.

    Returns
    -------
    faces : ndarray of int, shape (m, d)
        Vertex rows, each sorted, in lexicographic order.
    p_plus, p_minus : ndarray of float64, shape (N, d)
        The poles (:func:`poles_from_delaunay`).
    """
    cc, ok = circumcentres(pts[tri.simplices])
    p_plus, p_minus = poles_from_delaunay(pts, tri, cc, ok, far)
    faces, c0, d, t_max = _candidate_edges(pts, tri, cc, ok, p_plus, theta, resolve_flat)
    faces = faces[_voronoi_filter(pts, faces, c0, d, t_max, np.vstack([p_plus, p_minus]))]
    faces = np.sort(faces, axis=1)
    return faces[np.lexsort(faces.T[::-1])], p_plus, p_minus

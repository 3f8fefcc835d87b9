"""The geometric steps 1–4 of the Crust (ABK98) in R^d for any d: circumcentres, poles, the
Delaunay (d−1)-faces with their dual Voronoi edges, the Voronoi filter as a one-dimensional linear
program along each edge (see :mod:`.crust`), and the normal filter.  For d = 3 these compute what
:mod:`.crust` computes (a test compares the whole reconstruction); :mod:`.crust_nd` uses them.

They are kept apart from :mod:`.crust`, whose three-dimensional versions other work changes (flat
tetrahedra of parameter grids, scaled coordinates); the two can be made one once those settle.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay, cKDTree

from .crust import _MAX_ROUNDS, _RAY_LENGTH, _cut, _group_argmax

__all__ = ["circumcentres", "simplex_normals", "poles_from_delaunay", "filtered_faces"]


def circumcentres(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Circumcentres of full-dimensional simplices p (m, d + 1, d) (tetrahedra for d = 3); ``ok`` is
    False for (nearly) flat ones.

    Thesis: §2.1.2 (the Voronoi vertices dual to the Delaunay simplices).
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
    """
    e = p[:, 1:] - p[:, :1]
    if p.shape[2] == 3:
        return np.cross(e[:, 0], e[:, 1])
    d = p.shape[2]
    return np.stack([(-1) ** k * np.linalg.det(np.delete(e, k, axis=2)) for k in range(d)], axis=1)


def poles_from_delaunay(pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray, far: float):
    """Poles p⁺, p⁻ of every sample from the Delaunay triangulation ``tri`` of the samples and its
    circumcentres ``cc`` (see :func:`thesis_lib.meshes.poles`), in any dimension.

    Thesis: §3.4, "Triangulations" (the Crust [ABK98]).
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


def _candidate_edges(pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray, p_plus: np.ndarray, theta: float):
    """The triangles of Del(S) that pass the normal filter, with their dual Voronoi edges
    ``c0 + t d``, t ∈ [0, t_max].

    Processed one face slot of the tetrahedra at a time (peak memory); the normal filter comes
    first as it is cheap and shortens the Voronoi filter's work.  Triangles next to a flat
    tetrahedron (no circumcentre) are left out.
    """
    tets, nbr = tri.simplices, tri.neighbors
    idx = np.arange(len(tets))
    diag = float(np.linalg.norm(pts.max(0) - pts.min(0)))
    faces, c0s, ds, tmaxs = [], [], [], []
    for k in range(tets.shape[1]):
        other = nbr[:, k]
        sel = (other == -1) | (other > idx)  # each interior face once, from its lower tetrahedron
        i, o = idx[sel], other[sel]
        face = np.delete(tets[i], k, axis=1)
        good = ok[i] & ok[np.where(o >= 0, o, i)]
        good[good] = _normal_filter(pts, face[good], p_plus, theta)
        i, o, face = i[good], o[good], face[good]
        c0 = cc[i]
        d = np.empty_like(c0)
        inner = o >= 0
        d[inner] = cc[o[inner]] - c0[inner]
        hp = pts[face[~inner]]  # convex-hull face: a ray away from the opposite vertex
        nrm = simplex_normals(hp)
        nrm *= np.sign(np.einsum("ij,ij->i", nrm, hp[:, 0] - pts[tets[i[~inner], k]]))[:, None]
        d[~inner] = nrm * (diag / (np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-300))
        faces.append(face)
        c0s.append(c0)
        ds.append(d)
        tmaxs.append(np.where(inner, 1.0, _RAY_LENGTH))
    return np.concatenate(faces), np.concatenate(c0s), np.concatenate(ds), np.concatenate(tmaxs)


def _voronoi_filter(pts, faces, c0, d, t_max, pole_pts) -> np.ndarray:
    """Mask of the triangles that lie in Del(S ∪ P): some point of the Voronoi edge is nearer to
    the triangle's vertices than to every pole (module docstring)."""
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


def filtered_faces(pts: np.ndarray, tri: Delaunay, theta: float, far: float):
    """Steps 2–4 on the Delaunay triangulation ``tri`` of the samples in R^d: the sorted (d−1)-faces
    of Del(S ∪ P) with sample vertices that pass the normal filter, and the poles p⁺, p⁻.

    Thesis: §3.4, "Triangulations" (the Crust [ABK98]), in any dimension (Chapter 5).
    """
    cc, ok = circumcentres(pts[tri.simplices])
    p_plus, p_minus = poles_from_delaunay(pts, tri, cc, ok, far)
    faces, c0, d, t_max = _candidate_edges(pts, tri, cc, ok, p_plus, theta)
    faces = faces[_voronoi_filter(pts, faces, c0, d, t_max, np.vstack([p_plus, p_minus]))]
    faces = np.sort(faces, axis=1)
    return faces[np.lexsort(faces.T[::-1])], p_plus, p_minus

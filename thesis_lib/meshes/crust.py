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

Step 3 without triangulating S ∪ P.  A triangle with sample vertices lies in Del(S ∪ P) exactly
when some ball through its vertices is empty of S ∪ P; such a ball is empty of S, so the triangle
is in Del(S), and the centres of its S-empty balls form its dual Voronoi edge (a segment between
two circumcentres, or a ray for a convex-hull face).  A pole p lies inside the ball centred at c
through vertex a iff (a - p)·(2c - a - p) < 0, which is linear along the edge: each pole removes a
half-line, and the test is a one-dimensional linear program.  It is solved by bisection: the
vertices' own six poles first, then the midpoint of what is left, where a nearest-pole query
(k-d tree, bounded by the ball's radius) either finds the ball empty (keep the triangle) or names a
pole whose half-line removes the midpoint.  This gives the triangles of Del(S ∪ P) — a test
compares with Qhull's triangulation of S ∪ P — at a fraction of the cost: the poles cluster along
the medial axis, where Qhull builds about 34 tetrahedra per point (6·10⁴ torus samples) and took
70 s at 10⁵ samples for this step alone.

Degenerate samples.  Four co-circular samples (the isosceles-trapezoid quads of a parameter grid,
such as the thesis's chosen points on the torus) make a flat Delaunay tetrahedron with no
circumcentre.  They are resolved as a symbolic perturbation would (:func:`_flat_tetrahedra`): one
diagonal per quadrilateral, its two triangles joined to the Voronoi vertices on both sides, so the
Crust of such a grid is closed.
"""

from __future__ import annotations

from ..jit import njit
import numpy as np
import numpy.typing as npt
from scipy.spatial import Delaunay, QhullError, cKDTree

from .._validate import as_points, check_real, check_simplices
from ..complexes.scaling import scaled

__all__ = ["crust", "poles", "crust_candidates", "extract_manifold"]

#: bisection rounds of the Voronoi filter; an edge interval still open after them is narrower than
#: 2⁻⁶⁰ of the edge (a degenerate, co-spherical configuration) and its triangle is dropped
_MAX_ROUNDS = 60
#: a hull face's Voronoi ray is searched up to this many bounding-box diagonals
_RAY_LENGTH = 1e6


def _circumcentres(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Circumcentres of tetrahedra p (m, 4, 3); ``ok`` is False for (nearly) flat ones."""
    d = p[:, 1:] - p[:, :1]
    rhs = 0.5 * np.einsum("mij,mij->mi", d, d)
    det = np.linalg.det(d)
    scale = np.einsum("mij,mij->m", d, d) ** 1.5 + 1e-300
    ok = np.abs(det) > 1e-12 * scale
    x = np.zeros((len(p), 3))
    x[ok] = np.linalg.solve(d[ok], rhs[ok][..., None])[..., 0]
    return p[:, 0] + x, ok


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


def _samples(points) -> tuple[np.ndarray, int]:
    pts = as_points(points, min_points=5, allow_duplicates=False)
    if pts.shape[1] != 3:
        raise ValueError(f"crust needs points in R³, got dimension {pts.shape[1]}")
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


def _poles(pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray, far: float):
    """Poles from the Delaunay triangulation ``tri`` of the samples and its circumcentres ``cc``."""
    n = len(pts)
    tets = tri.simplices
    owner = tets.ravel()
    tet = np.repeat(np.arange(len(tets)), 4)
    vec = cc[tet] - pts[owner]
    dist = np.linalg.norm(vec, axis=1)
    dist[~ok[tet]] = -np.inf
    best = _group_argmax(owner, dist, n)
    plus_vec = np.zeros((n, 3))
    has = best >= 0
    plus_vec[has] = vec[best[has]]
    # unbounded Voronoi cells: samples on the convex hull, pole at infinity along the mean normal
    hull = tri.convex_hull
    hp = pts[hull]
    normal = np.cross(hp[:, 1] - hp[:, 0], hp[:, 2] - hp[:, 0])
    centre = pts.mean(axis=0)
    normal *= np.sign(np.einsum("ij,ij->i", normal, hp[:, 0] - centre))[:, None]
    normal /= np.linalg.norm(normal, axis=1, keepdims=True) + 1e-300
    acc = np.zeros((n, 3))
    np.add.at(acc, hull.ravel(), np.repeat(normal, 3, axis=0))
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


def poles(points: npt.ArrayLike, far: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The poles p⁺ and p⁻ of every sample (ABK98, §4).

    Thesis: §3.4, "Triangulations" (Crust algorithm [ABK98]).

    Parameters
    ----------
    points : (n, 3) samples, n >= 5, no duplicates, not coplanar.
    far : distance used for poles at infinity, and cap of all pole distances (default: half the
        diagonal of the bounding box).

    Returns
    -------
    p_plus, p_minus : (n, 3) arrays; p⁻ falls back to the reflection of p⁺ when a cell has no
        Voronoi vertex on the opposite side.
    """
    pts, e = _samples(points)
    tri = _delaunay(pts)
    p_plus, p_minus = _poles(pts, tri, *_circumcentres(pts[tri.simplices]), _far(pts, far, e))
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


def _candidate_edges(pts: np.ndarray, tri: Delaunay, cc: np.ndarray, ok: np.ndarray, p_plus: np.ndarray, theta: float):
    """The triangles of Del(S) that pass the normal filter, with their dual Voronoi edges
    ``c0 + t d``, t ∈ [0, t_max].

    Processed one face slot of the tetrahedra at a time (peak memory); the normal filter comes
    first as it is cheap and shortens the Voronoi filter's work.  Flat tetrahedra (co-circular
    samples) are resolved by :func:`_flat_tetrahedra`.
    """
    tets, nbr = tri.simplices, tri.neighbors
    idx = np.arange(len(tets))
    diag = float(np.linalg.norm(pts.max(0) - pts.min(0)))
    centre, keep, across = _flat_tetrahedra(pts, tri, cc, ok)
    faces, c0s, ds, tmaxs = [], [], [], []
    for k in range(4):
        other = nbr[:, k]
        sel = (other == -1) | (other > idx)  # each interior face once, from its lower tetrahedron
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
        # a face on the convex hull: a ray away from the vertex of end0 farthest from its plane
        hp = pts[face[~bounded]]
        nrm = np.cross(hp[:, 1] - hp[:, 0], hp[:, 2] - hp[:, 0])
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
    """Keep on each edge ``rows`` only the centres c whose ball through ``a`` excludes pole ``p``."""
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
    """Mask of the triangles that lie in Del(S ∪ P): some point of the Voronoi edge is nearer to
    the triangle's vertices than to every pole (module docstring)."""
    n = len(pts)
    a = pts[faces[:, 0]]
    lo, hi = np.zeros(len(faces)), t_max.astype(np.float64).copy()
    rows = np.arange(len(faces))
    for k in range(3):  # each vertex's own poles cut most edges that run inside the solid
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
    """Mask of the triangles whose normal is within θ of the pole vector at the largest-angle
    vertex and within 3θ/2 at the others (ABK98, §5)."""
    p = pts[faces]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-300
    cosang = np.empty((len(faces), 3))
    for k in range(3):
        a = p[:, (k + 1) % 3] - p[:, k]
        b = p[:, (k + 2) % 3] - p[:, k]
        cosang[:, k] = np.einsum("ij,ij->i", a, b) / (
            np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1) + 1e-300
        )
    largest = np.argmin(cosang, axis=1)  # largest angle = smallest cosine
    pole = p_plus[faces] - p
    pole /= np.linalg.norm(pole, axis=2, keepdims=True) + 1e-300
    c = np.abs(np.einsum("ij,ikj->ik", nrm, pole))  # |cos| of line angle per vertex
    limit = np.full((len(faces), 3), np.cos(1.5 * theta))
    limit[np.arange(len(faces)), largest] = np.cos(theta)
    return np.all(c >= limit, axis=1)


def crust_candidates(points: npt.ArrayLike, theta: float = np.pi / 4, far: float | None = None) -> np.ndarray:
    """Steps 1–4 of the Crust: Delaunay triangles of S ∪ P with sample vertices, filtered by normal.

    Thesis: §3.4, "Triangulations" ([ABK98]).

    Parameters
    ----------
    points, far
        As in :func:`poles`.
    theta : normal-filter angle in (0, π/2).

    Returns
    -------
    ndarray, shape (m, 3)
        Vertex triples, each sorted, in lexicographic order.
    """
    theta = check_real(theta, "theta")
    if not 0 < theta < np.pi / 2:
        raise ValueError(f"theta must lie in (0, π/2), got {theta!r}")
    pts, e = _samples(points)
    tri = _delaunay(pts)
    cc, ok = _circumcentres(pts[tri.simplices])
    p_plus, p_minus = _poles(pts, tri, cc, ok, _far(pts, far, e))
    faces, c0, d, t_max = _candidate_edges(pts, tri, cc, ok, p_plus, theta)
    faces = faces[_voronoi_filter(pts, faces, c0, d, t_max, np.vstack([p_plus, p_minus]))]
    faces = np.sort(faces, axis=1)
    return faces[np.lexsort(faces.T[::-1])]


def _edge_structure(tris: np.ndarray, nv: int):
    e = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    e.sort(axis=1)
    key = e[:, 0] * nv + e[:, 1]
    uniq, inv = np.unique(key, return_inverse=True)
    edge_of = inv.reshape(3, -1).T  # (t, 3): edge id of side k (opposite vertex k+2)
    order = np.argsort(inv, kind="stable")
    counts = np.bincount(inv, minlength=len(uniq))
    start = np.concatenate([[0], np.cumsum(counts)])
    tri_of = order % len(tris)
    return uniq, edge_of, start, tri_of


@njit(cache=True)
def _sharp_edges(pts, tris, alive, uniq, start, tri_of, nv):
    ne = len(uniq)
    sharp = np.zeros(ne, dtype=np.bool_)
    angles = np.empty(64)
    for e in range(ne):
        a = uniq[e] // nv
        b = uniq[e] % nv
        ax = pts[b] - pts[a]
        ax /= np.sqrt((ax * ax).sum())
        # reference direction perpendicular to the edge
        ref = np.zeros(3)
        got = False
        cnt = 0
        for k in range(start[e], start[e + 1]):
            t = tri_of[k]
            if not alive[t]:
                continue
            c = tris[t, 0] + tris[t, 1] + tris[t, 2] - a - b
            w = pts[c] - pts[a]
            w = w - (w * ax).sum() * ax
            w /= np.sqrt((w * w).sum()) + 1e-300
            if not got:
                ref = w
                got = True
            y = np.cross(ax, ref)
            if cnt < 64:
                angles[cnt] = np.arctan2((w * y).sum(), (w * ref).sum()) % (2 * np.pi)
            cnt += 1
        if cnt == 0:
            continue
        if cnt == 1:
            sharp[e] = True
            continue
        m = min(cnt, 64)
        s = np.sort(angles[:m])
        gap = 2 * np.pi - s[m - 1] + s[0]
        for i in range(1, m):
            gap = max(gap, s[i] - s[i - 1])
        if gap > 1.5 * np.pi:
            sharp[e] = True
    return sharp


def _prune_sharp(pts, tris, max_rounds=10000):
    alive = np.ones(len(tris), dtype=bool)
    uniq, edge_of, start, tri_of = _edge_structure(tris, len(pts))
    for _ in range(max_rounds):
        sharp = _sharp_edges(pts, tris, alive, uniq, start, tri_of, len(pts))
        kill = alive & sharp[edge_of].any(axis=1)
        if not kill.any():
            break
        alive &= ~kill
    return tris[alive]


@njit(cache=True)
def _walk(pts, tris, edge_of, start, tri_of, seed_tri, seed_flip):
    nt = len(tris)
    orient = np.zeros((nt, 3), dtype=np.int64)
    seen = np.zeros(nt, dtype=np.bool_)
    stack = np.empty(nt, dtype=np.int64)
    visit = np.empty(nt, dtype=np.int64)
    nvisit = 0
    a0, b0, c0 = tris[seed_tri, 0], tris[seed_tri, 1], tris[seed_tri, 2]
    if seed_flip:
        a0, b0 = b0, a0
    orient[seed_tri, 0], orient[seed_tri, 1], orient[seed_tri, 2] = a0, b0, c0
    seen[seed_tri] = True
    stack[0] = seed_tri
    top = 1
    conflicts = 0
    while top > 0:
        top -= 1
        t = stack[top]
        visit[nvisit] = t
        nvisit += 1
        o = orient[t]
        nrm = np.cross(pts[o[1]] - pts[o[0]], pts[o[2]] - pts[o[0]])
        nrm /= np.sqrt((nrm * nrm).sum()) + 1e-300
        for k in range(3):
            a, b, c = o[k], o[(k + 1) % 3], o[(k + 2) % 3]
            # edge id of {a, b}
            e = -1
            for s in range(3):
                x, y = tris[t, s], tris[t, (s + 1) % 3]
                if (x == a and y == b) or (x == b and y == a):
                    e = edge_of[t, s]
            ax = pts[b] - pts[a]
            ax /= np.sqrt((ax * ax).sum())
            wc = pts[c] - pts[a]
            wc = wc - (wc * ax).sum() * ax
            wc /= np.sqrt((wc * wc).sum()) + 1e-300
            best = -1
            best_ang = 1e300
            best_d = -1
            for q in range(start[e], start[e + 1]):
                t2 = tri_of[q]
                if t2 == t:
                    continue
                d = tris[t2, 0] + tris[t2, 1] + tris[t2, 2] - a - b
                wd = pts[d] - pts[a]
                wd = wd - (wd * ax).sum() * ax
                ang = np.arctan2((wd * nrm).sum(), (wd * wc).sum()) % (2 * np.pi)
                if ang < best_ang:
                    best_ang = ang
                    best = t2
                    best_d = d
            if best < 0:
                continue
            if seen[best]:
                # consistent if the neighbour traverses the edge as b -> a
                ob = orient[best]
                okk = False
                for s in range(3):
                    if ob[s] == b and ob[(s + 1) % 3] == a:
                        okk = True
                if not okk:
                    conflicts += 1
                continue
            seen[best] = True
            orient[best, 0], orient[best, 1], orient[best, 2] = b, a, best_d
            stack[top] = best
            top += 1
    return orient, visit[:nvisit], conflicts


@njit(cache=True)
def _greedy_manifold(edge_of, order, n_edges):
    """Keep faces in visiting order while each of their edges has fewer than two kept faces."""
    used = np.zeros(n_edges, dtype=np.int64)
    keep = np.zeros(len(order), dtype=np.bool_)
    for i in range(len(order)):
        t = order[i]
        if used[edge_of[t, 0]] < 2 and used[edge_of[t, 1]] < 2 and used[edge_of[t, 2]] < 2:
            keep[i] = True
            for k in range(3):
                used[edge_of[t, k]] += 1
    return keep


def extract_manifold(points: npt.ArrayLike, triangles: npt.ArrayLike, prune: bool = True) -> tuple[np.ndarray, int]:
    """Trimming step of the Crust: sharp-edge removal, then the outer walk from an outer triangle.

    Thesis: §3.4, "Triangulations" ([ABK98], manifold extraction).

    Parameters
    ----------
    points : (n, 3) samples.
    triangles : (m, 3) candidate triangles (indices into ``points``).
    prune : remove triangles with sharp edges first.

    Returns
    -------
    faces : consistently oriented faces (outward for a closed surface); faces that would put a
        third face on an edge are left out (in visiting order), so every edge of the result lies in
        one or two faces.
    conflicts : the number of orientation conflicts met by the walk (0 for an orientable result).
    """
    pts = as_points(points, min_points=3)
    if pts.shape[1] != 3:
        raise ValueError(f"the trimming walks surfaces in R³, got points in R^{pts.shape[1]}")
    pts, _ = scaled(pts)  # angles only: scale-invariant, and cross products stay finite
    tris = check_simplices(triangles, len(pts), "triangles", width=3)
    if prune:
        tris = _prune_sharp(pts, tris)
        if len(tris) == 0:
            raise ValueError("trimming removed every triangle: the sample is too sparse for the Crust")
    _, edge_of, start, tri_of = _edge_structure(tris, len(pts))
    # outer seed: the triangle at the extreme-x sample whose normal is closest to ±x
    top = int(np.argmax(pts[:, 0]))
    cand = np.flatnonzero((tris == top).any(axis=1))
    if len(cand) == 0:
        top_tri = int(np.argmax(pts[tris].max(axis=1)[:, 0]))
        cand = np.array([top_tri])
    p = pts[tris[cand]]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-300
    i = int(np.argmax(np.abs(nrm[:, 0])))
    seed_tri = int(cand[i])
    orient, order, conflicts = _walk(pts, tris, edge_of, start, tri_of, seed_tri, bool(nrm[i, 0] < 0))
    keep = _greedy_manifold(edge_of, order, int(edge_of.max()) + 1)
    return orient[order[keep]], int(conflicts)


def crust(points: npt.ArrayLike, theta: float = np.pi / 4, prune: bool = True, far: float | None = None) -> np.ndarray:
    """Triangulate a point cloud sampled from a surface in R³ with the Crust algorithm [ABK98].

    Parameters
    ----------
    points : ``(n, 3)`` samples without duplicates.
    theta : normal-filter angle θ (θ at the largest-angle vertex, 3θ/2 at the others).  ABK98 leave
        θ as a parameter; π/4 closes the torus R = 10, r = 5 from 1000 uniform samples on, while
        π/8 already opens holes there.
    prune : remove triangles with sharp edges before the walk (right for closed surfaces; switch it
        off for a surface with boundary, where it would eat the surface from its border).  When the
        sample is too sparse and trimming removes every triangle, the walk runs on the untrimmed
        candidates instead (the result then has holes and non-manifold edges).
    far : distance of the poles at infinity and cap of all pole distances (default half the
        bounding-box diagonal).

    Returns
    -------
    ndarray, shape (m, 3)
        Faces into ``points``, consistently oriented (outward for a closed surface).

    Thesis: §3.4, "Triangulations" (the Crust algorithm [ABK98], used for Figures 3.8–3.11).
    """
    cand = crust_candidates(points, theta, far)
    pts, _ = _samples(points)
    if len(cand) == 0:
        raise ValueError("no triangle survived the Crust's filtering")
    try:
        faces, _ = extract_manifold(pts, cand, prune=prune)
    except ValueError:
        if not prune:
            raise
        faces, _ = extract_manifold(pts, cand, prune=False)
    return faces

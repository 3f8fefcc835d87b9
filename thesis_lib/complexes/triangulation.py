"""The regular (weighted Delaunay) triangulation, fast and exact (thesis Definition 2.13, §2.1.2).

The regular triangulation of weighted points is the lower convex hull of the lifted points
``(x, |x|² − w_x)``; with zero weights it is the Delaunay triangulation.  Three steps:

1. **Candidate.**  Qhull (:class:`scipy.spatial.ConvexHull`) computes the lower hull in floating
   point: fast, but on near-degenerate input (noisy grids, thin triangles, co-circular points) it
   may merge facets, leave flat simplices or pick another triangulation of co-spherical points.
2. **Certificate.**  The candidate is the regular triangulation of the (symbolically perturbed)
   points exactly when it is a valid triangulation (every simplex full-dimensional, neighbours on
   opposite sides of their common facet), every interior facet is locally regular (the opposite
   vertex lies outside the orthogonal sphere: the lifted surface is convex there), the boundary is
   convex and is the hull's boundary once (connected, star-shaped from the centroid of a simplex,
   met once by a ray from it: local tests alone accept a boundary that curls twice around a
   cluster of points a few ulps apart, or a sliver covered twice), and every point is a vertex
   or certifiably hidden (weighted points whose lifted point lies above the hull).  All tests
   use the robust predicates of :mod:`.predicates`: a float filter decides almost every test,
   exact arithmetic the rest.
3. **Repair.**  Where the certificate fails, the simplices around the failures are re-triangulated
   exactly (:mod:`.incremental`), growing the region until the whole certificate holds; at worst
   every point is triangulated exactly.

Ties (d + 2 points on one sphere) are broken by CGAL's symbolic perturbation, so the result equals
GUDHI's (which uses CGAL with exact predicates).
"""

from __future__ import annotations

from dataclasses import dataclass
from math import comb, factorial

import numpy as np
import numpy.typing as npt

from .._core import triangulation as triangulation_core
from .._validate import MAX_SIMPLICES, as_points, check_size, check_weights, power_of_two_scale, scale_points
from ..homology.simplicial import facets, row_keys
from .flips import flip_round
from .incremental import DegenerateInput, exact_triangulation
from .predicates import Geometry, expand_det, signs_of

__all__ = ["regular_triangulation", "Triangulation", "prepare_geometry", "triangulate", "lexicographic",
           "lexicographic_order", "check_delaunay_size", "MAX_DELAUNAY_SIMPLICES"]

#: expected number of top simplices per point of the Delaunay triangulation of uniform random points
#: in R^d (d = 1..8; Poisson–Delaunay cell counts), used to refuse constructions that cannot finish
_CELLS_PER_POINT = {1: 1.0, 2: 2.0, 3: 6.77, 4: 31.8, 5: 164.0, 6: 891.0, 7: 5080.0, 8: 30205.0}


@dataclass
class Triangulation:
    """A certified regular triangulation.

    ``simplices`` (m, d + 1) rows ascending (in no particular row order; :func:`lexicographic`
    sorts them); ``neighbours`` (m, d + 1) the simplex across the facet
    opposite each vertex (−1 on the convex hull); ``ties`` (k, 2) pairs of neighbouring simplices
    whose d + 2 vertices lie exactly on one orthogonal sphere (before perturbation).
    """

    simplices: np.ndarray
    neighbours: np.ndarray
    ties: np.ndarray


@dataclass
class _Certificate:
    ok: bool
    bad: np.ndarray  # simplex indices around failures
    loose: np.ndarray  # point ids that are not vertices
    located: np.ndarray  # for each loose point: a simplex near it
    unresolved: np.ndarray  # for each loose point: not certifiably hidden (it must become a vertex)
    neighbours: np.ndarray
    ties: np.ndarray
    orient: np.ndarray  # orientation sign of each simplex (0: flat)
    failing: np.ndarray  # (k, 4) interior facets that are not locally regular: s1, i1, s2, i2


def estimated_size(n: int, d: int) -> int:
    """A lower estimate of the number of simplices of the Delaunay complex of n points in R^d.

    At least one d-simplex with its 2^(d+1) − 1 faces; for many points about n · c_d top
    simplices (c_d the expected Poisson–Delaunay count per point, extrapolated ×6 per dimension
    beyond d = 8), and never more than C(n, d + 1).

    Parameters
    ----------
    n : int
        The number of points.
    d : int
        The dimension of the space, ``d >= 1``.

    Returns
    -------
    int
        The estimate, used to refuse constructions that could not finish.
    """
    per = _CELLS_PER_POINT.get(d, _CELLS_PER_POINT[8] * 6.0 ** max(0, d - 8))
    tops = min(n * per, comb(n, d + 1)) if n <= 10**6 else n * per
    return int(max(2 ** (d + 1) - 1, tops))


def prepare_geometry(points: npt.ArrayLike, weights: npt.ArrayLike | None = None) -> tuple[Geometry, int]:
    """Validate the input and return its :class:`Geometry` (points scaled by 2^e) and e.

    Thesis: §2.1.2 (a weighted point x with weight w_x ≥ 0).

    Parameters
    ----------
    points : array_like, shape (n, d)
        Finite coordinates of at least d + 1 distinct points.
    weights : array_like, shape (n,), optional
        The points' weights w_x >= 0; None: all zero (unweighted).

    Returns
    -------
    geo : Geometry
        Points times 2^e (largest |coordinate| in [0.5, 1)) and weights times 4^e.
    e : int
        The scale exponent.

    Raises
    ------
    ValueError
        Too few or duplicate points, invalid weights, a Delaunay complex estimated too large to
        build, or weights and coordinates too far apart in scale for float64.
    """
    pts = as_points(points)
    n, d = pts.shape
    check_delaunay_size(n, d)
    if n < d + 1:
        raise ValueError(f"a Delaunay complex in R^{d} needs at least {d + 1} points, got {n}")
    w = np.zeros(n) if weights is None else check_weights(weights, n)
    e = power_of_two_scale(pts)
    spts = scale_points(pts, e)
    sw = np.ldexp(w, 2 * e)
    if not np.all(np.isfinite(sw)) or not np.array_equal(np.ldexp(sw, -2 * e), w):
        raise ValueError("weights and coordinates differ too much in scale for float64")
    geo = Geometry(spts, sw)
    # duplicates are neighbours in the lexicographic order the predicates need anyway
    srt = spts[geo.order]
    same = np.all(srt[1:] == srt[:-1], axis=1)
    if same.any():
        i = int(np.argmax(same))
        a, b = sorted((int(geo.order[i]), int(geo.order[i + 1])))
        raise ValueError(f"duplicate points: rows {a} and {b} are equal")
    return geo, e


# ------------------------------------------------------------------------------------- qhull
def _qhull_candidate(geo: Geometry) -> tuple[np.ndarray, np.ndarray] | None:
    """Qhull's lower hull of the lifted points: sorted simplices and their neighbours (unchecked)."""
    from scipy.spatial import ConvexHull, QhullError  # scipy.spatial loads when first needed
    pts, w = geo.points, geo.weights
    n, d = pts.shape
    centred = pts - pts.mean(axis=0)
    scale = float(np.abs(centred).max()) or 1.0
    centred /= scale
    with np.errstate(over="ignore"):  # weights near the float range: refused just below
        lift = np.einsum("ij,ij->i", centred, centred) - w / scale**2
    if not np.all(np.isfinite(lift)):
        return None
    top = lift.max() + (lift.max() - lift.min()) + 1.0
    # a point far above the data: the hull is full-dimensional even for co-spherical input
    lifted = np.vstack([np.column_stack([centred, lift]), np.append(np.zeros(d), top)])
    try:
        hull = ConvexHull(lifted, qhull_options="Qt Qbb")
    except (QhullError, ValueError):
        return None
    lower = (hull.equations[:, d] < 0) & ~np.any(hull.simplices == n, axis=1)
    if not lower.any():
        return None
    ids = np.flatnonzero(lower)
    remap = np.full(len(hull.simplices), -1, dtype=np.int64)
    remap[ids] = np.arange(ids.size)
    tri = hull.simplices[ids].astype(np.int64)
    nb = remap[hull.neighbors[ids]]
    order = np.argsort(tri, axis=1)
    return np.take_along_axis(tri, order, axis=1), np.take_along_axis(nb, order, axis=1)


# ------------------------------------------------------------------------------------- certificate
def _group_rows(rows: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Group equal rows: (group id of each row, size of each group)."""
    keys = row_keys(rows, n + 1) if rows.shape[1] else np.zeros(len(rows), dtype=np.int64)
    if keys is None:
        _, inv, counts = np.unique(rows, axis=0, return_inverse=True, return_counts=True)
    else:
        _, inv, counts = np.unique(keys, return_inverse=True, return_counts=True)
    return inv.ravel(), counts


def _pairs(inv: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """(k, 2) positions of the rows in groups of exactly two."""
    order = np.argsort(inv, kind="stable")
    g = inv[order]
    start = np.flatnonzero(np.r_[True, g[1:] != g[:-1]])
    two = start[counts[g[start]] == 2]
    return np.column_stack([order[two], order[two + 1]])


def _locate(geo: Geometry, tri: np.ndarray, nb: np.ndarray, queries: np.ndarray, start: np.ndarray) -> np.ndarray:
    """Float walk: a simplex containing (about) each query point, −1 if the walk leaves the hull."""
    cur = start.copy()
    pending = np.flatnonzero(cur >= 0)
    for _ in range(4 * int(np.sqrt(len(tri))) + 50):
        if pending.size == 0:
            break
        p = geo.points[tri[cur[pending]]]
        a = np.transpose(p[:, 1:, :] - p[:, :1, :], (0, 2, 1))
        lam = np.einsum("mij,mj->mi", np.linalg.pinv(a), geo.points[queries[pending]] - p[:, 0, :])
        bary = np.column_stack([1.0 - lam.sum(axis=1), lam])
        worst = np.argmin(bary, axis=1)
        done = bary[np.arange(len(pending)), worst] >= -1e-12
        move = pending[~done]
        cur[move] = nb[cur[move], worst[~done]]
        pending = move[cur[move] >= 0]
    cur[pending] = -1
    return cur


def _pairing(tri: np.ndarray, n: int, hint: np.ndarray | None):
    """Interior facet pairs (s1, i1, s2, i2), boundary occurrences (s, i), neighbours, and the
    simplices with a facet in three or more simplices or a neighbour ``hint`` that does not match."""
    m, w = tri.shape
    d = w - 1
    bad = np.zeros(m, dtype=bool)
    if hint is not None:
        s1, i1, s2, i2, same = triangulation_core.hint_pairs(np.ascontiguousarray(tri, dtype=np.int64),
                                                                np.ascontiguousarray(hint, dtype=np.int64))
        bad[s1[~same]] = bad[s2[~same]] = True
        s1, i1, s2, i2 = s1[same], i1[same], s2[same], i2[same]
        nb = np.full((m, w), -1, dtype=np.int64)
        nb[s1, i1], nb[s2, i2] = s2, s1
        single = np.flatnonzero(nb.ravel() < 0)
        return s1, i1, s2, i2, single, nb, bad
    occ = facets(tri).reshape(-1, d)  # occurrence o = s * (d + 1) + i omits vertex i of simplex s
    inv, counts = _group_rows(occ, n)
    bad[np.unique(np.flatnonzero(counts[inv] > 2) // w)] = True
    pairs = _pairs(inv, counts)
    s1, i1 = pairs[:, 0] // w, pairs[:, 0] % w
    s2, i2 = pairs[:, 1] // w, pairs[:, 1] % w
    nb = np.full((m, w), -1, dtype=np.int64)
    nb[s1, i1], nb[s2, i2] = s2, s1
    return s1, i1, s2, i2, np.flatnonzero(counts[inv] == 1), nb, bad


#: for k + 1 columns, the columns kept when column i is dropped
_KEEP = {w: np.array([[j for j in range(w) if j != i] for i in range(w)]) for w in range(2, 12)}


def _certify(geo: Geometry, tri: np.ndarray, hint: np.ndarray | None = None) -> _Certificate:
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    n, d = geo.n, geo.d
    m = len(tri)
    orient = geo.orientation(tri)
    s1, i1, s2, i2, single, nb, bad = _pairing(tri, n, hint)
    bad |= orient == 0
    sign1 = np.where(i1 % 2, -1, 1) * orient[s1]
    sign2 = np.where(i2 % 2, -1, 1) * orient[s2]
    flat = (orient[s1] == 0) | (orient[s2] == 0)
    same_side = ~flat & (sign1 == sign2)
    bad[s1[same_side]] = bad[s2[same_side]] = True
    test = ~flat & ~same_side
    out = np.ones(len(s1), dtype=bool)
    tie = np.zeros(len(s1), dtype=bool)
    if test.any():
        out[test], tie[test] = geo.outside(tri[s1[test]], tri[s2[test], i2[test]], orient[s1[test]])
    bad[s1[~out]] = bad[s2[~out]] = True
    # the boundary must be convex: no boundary vertex strictly outside a neighbouring boundary facet
    if d >= 2 and single.size:
        bs, bi = single // (d + 1), single % (d + 1)
        faces = np.take_along_axis(tri[bs], _KEEP[d + 1][bi], axis=1)  # (b, d) boundary facets
        ridge = facets(faces).reshape(-1, d - 1)
        rinv, rcounts = _group_rows(ridge, n)
        bad[bs[np.unique(np.flatnonzero(rcounts[rinv] != 2) // d)]] = True
        rp = _pairs(rinv, rcounts)
        f1, f2 = rp[:, 0] // d, rp[:, 1] // d
        z = faces[f2, rp[:, 1] % d]  # the vertex of facet 2 off the common ridge
        o_z = geo.orientation(np.column_stack([faces[f1], z]))
        inner = np.where((d - bi[f1]) % 2, -1, 1) * orient[bs[f1]]
        concave = (o_z != 0) & (o_z == -inner)
        bad[bs[f1[concave]]] = bad[bs[f2[concave]]] = True
        # ... and one closed surface: local convexity does not see a second boundary component (a
        # sliver of the plane covered twice, where a near-duplicate point lies just outside the
        # simplex it was put in has a locally convex boundary of its own); all but the largest
        # component are failures
        graph = coo_matrix((np.ones(len(f1)), (f1, f2)), shape=(len(faces), len(faces)))
        n_comp, comp = connected_components(graph, directed=False)
        if n_comp > 1:
            stray = comp != np.argmax(np.bincount(comp))
            bad[bs[stray]] = True
        if not bad.any():
            bad[_wound_more_than_once(geo, tri, orient, bs, bi, faces)] = True
    # points missing from the triangulation: an error unless weighted and certifiably hidden
    present = np.zeros(n, dtype=bool)
    present[tri.ravel()] = True
    loose = np.flatnonzero(~present)
    located = np.full(len(loose), -1, dtype=np.int64)
    if loose.size:
        verts = np.flatnonzero(present)
        near = verts[cKDTree(geo.points[verts]).query(geo.points[loose])[1]]
        some = np.full(n, -1, dtype=np.int64)
        some[tri.ravel()] = np.repeat(np.arange(m), d + 1)
        near_simplex = some[near]
        located = _locate(geo, tri, nb, loose, near_simplex)
        hidden = np.zeros(len(loose), dtype=bool)
        if geo.weighted:
            hidden = located >= 0
            for k in range(d + 2):  # the located simplex and its neighbours must all lie below
                cand = located if k == 0 else np.where(located >= 0, nb[np.maximum(located, 0), k - 1], -1)
                rows = np.flatnonzero(hidden & (cand >= 0))
                if rows.size:
                    c = cand[rows]
                    ok = ~bad[c] & (orient[c] != 0)
                    res = np.zeros(len(rows), dtype=bool)
                    if ok.any():
                        res[ok], _ = geo.outside(tri[c[ok]], loose[rows[ok]], orient[c[ok]])
                    hidden[rows[~res]] = False
        located = np.where(located >= 0, located, near_simplex)
        unresolved = ~hidden
    else:
        unresolved = np.zeros(0, dtype=bool)
    ok = not bad.any() and not unresolved.any()
    tie_pairs = np.column_stack([s1[tie], s2[tie]])
    failing = np.column_stack([s1, i1, s2, i2])[~out]
    return _Certificate(ok, np.flatnonzero(bad), loose, located, unresolved, nb, tie_pairs, orient, failing)


def _wound_more_than_once(geo: Geometry, tri: np.ndarray, orient: np.ndarray, bs: np.ndarray, bi: np.ndarray,
                          faces: np.ndarray) -> np.ndarray:
    """The simplices of boundary facets that show the boundary is not the convex hull's, once.

    A closed, locally convex boundary can still wind twice around the hull (a curl around a cluster
    of points a few ulps apart, all its turns convex).  Exactly: the centroid o of one simplex must
    lie strictly on the inner side of every boundary facet (the boundary is star-shaped from o), and
    the ray from o through the centroid of one boundary facet must meet exactly one closed boundary
    facet (it winds once around o).  Then the boundary is the hull's and the covering degree is 1.
    """
    d = geo.d
    s0 = int(np.flatnonzero(orient != 0)[0])
    idx = np.concatenate([faces.ravel(), tri[s0], faces[0]])
    scale = d * (d + 1)  # o = Σ x / (d + 1) and c = Σ x / d as integers: everything times d (d + 1)
    small = geo.small_ints(idx, d, float(factorial(d)) * float(scale * (d + 1)) ** d)
    x = geo.ints(idx)[0] if small is None else small[0]
    b = len(faces)
    pts = x[: b * d].reshape(b, d, d) * scale
    o = x[b * d : b * d + d + 1].sum(axis=0) * d
    c = x[b * d + d + 1 :].sum(axis=0) * (d + 1)

    def signs(mat):  # signs of det[rows − o], mat (b, d, d)
        return signs_of(expand_det(mat - o[None, None, :]))

    inner = np.where((d - bi) % 2, -1, 1) * orient[bs]  # orientation of (facet, its simplex's apex)
    # orientation of (facet, o) = (−1)^d sign det[f_i − o]
    side = (-1) ** d * signs(pts)
    outside = side != inner
    if outside.any():
        return bs[outside]
    hit = np.ones(b, dtype=bool)
    for i in range(d):  # the cone coordinates of c − o in the cone of (f − o): none negative
        g = pts.copy()
        g[:, i, :] = c
        hit &= (-1) ** d * signs(g) != -inner
    if hit.sum() != 1:
        return bs[hit]
    return np.zeros(0, dtype=np.int64)


# ------------------------------------------------------------------------------------- repair
def _star_growth(tri: np.ndarray, seed: np.ndarray, rounds: int, n: int) -> np.ndarray:
    """Mask of the simplices within ``rounds`` vertex-star steps of the ``seed`` simplices."""
    inside = np.zeros(len(tri), dtype=bool)
    inside[seed] = True
    for _ in range(rounds):
        touched = np.zeros(n, dtype=bool)
        touched[tri[inside].ravel()] = True
        grown = inside | touched[tri].any(axis=1)
        if grown.sum() == inside.sum():
            break
        inside = grown
    return inside


def _abs_dets(geo: Geometry, simplices: np.ndarray) -> list[int]:
    """|det[x_i − x_0]| of each simplex, exactly: integers at one power-of-two scale for the batch."""
    d = geo.d
    small = geo.small_ints(simplices, d, float(factorial(d)))
    x = geo.ints(simplices)[0] if small is None else small[0]
    return [abs(int(v)) for v in expand_det(x[:, 1:, :] - x[:, :1, :]).tolist()]


def _same_volume(geo: Geometry, sub: np.ndarray, old: np.ndarray) -> bool:
    """Do the exact triangulation of a part's points and the part cover the same volume (so the
    part is their convex hull)?  Decided exactly: a loose point a hair outside the part (a
    near-duplicate) enlarges the hull by a volume far below any float tolerance."""
    dets = _abs_dets(geo, np.vstack([sub, old]))
    return sum(dets[: len(sub)]) == sum(dets[len(sub) :])


def _fill(geo: Geometry, sub: np.ndarray, sub_nb: np.ndarray,
          walls: list[tuple[tuple[int, ...], int]]) -> np.ndarray | None:
    """Simplices of ``sub`` on the inner side of the wall facets, by flood fill; None if a wall is missing."""
    d = geo.d
    where: dict[tuple[int, ...], list[tuple[int, int]]] = {}
    for s, row in enumerate(sub.tolist()):
        for i in range(d + 1):
            where.setdefault(tuple(row[:i] + row[i + 1 :]), []).append((s, row[i]))
    wall_keys = {f for f, _ in walls}
    start = []
    for f, v in walls:
        cands = where.get(f)
        if not cands:
            return None
        side = geo.scalar.orient(list(f) + [v])
        hit = [s for s, u in cands if geo.scalar.orient(list(f) + [u]) == side]
        if len(hit) != 1:
            return None
        start.append(hit[0])
    seen = np.zeros(len(sub), dtype=bool)
    stack = list(set(start))
    seen[stack] = True
    while stack:
        s = stack.pop()
        row = sub[s].tolist()
        for i in range(d + 1):
            t = int(sub_nb[s, i])
            if t < 0 or seen[t] or tuple(row[:i] + row[i + 1 :]) in wall_keys:
                continue
            seen[t] = True
            stack.append(t)
    return sub[seen]


def _repair(geo: Geometry, tri: np.ndarray, cert: _Certificate) -> np.ndarray:
    """Re-triangulate exactly around the certificate's failures until it holds.

    Bistellar flips first (:mod:`.flips`: a valid triangulation that splits co-spherical cells
    another way, as Qhull does on exact grids); then each facet-connected group of failing
    simplices is re-triangulated on its own (they are small: a wrongly split co-spherical cell, a
    flat simplex, a point Qhull dropped); the groups that fail, and whatever
    the new certificate still rejects, are grown by vertex stars (1, 2, 4, ... rounds) and tried
    again; at worst all points are triangulated exactly.
    """
    n = geo.n
    for _ in range(30):  # first the cheap repair: rounds of independent 2 → d flips
        if geo.d < 2 or len(cert.failing) == 0:
            break
        flipped = flip_round(geo, tri, cert.failing, cert.orient)
        if flipped is None:
            break
        tri = flipped
        cert = _certify(geo, tri)
        if cert.ok:
            return tri
    rounds = 0
    for _ in range(12):
        seed = np.union1d(cert.bad, cert.located[cert.unresolved]).astype(np.int64)
        inside = _star_growth(tri, seed, rounds, n)
        if inside.all():
            break
        tri = _replace(geo, tri, cert, inside, by_ties=rounds == 0)
        cert = _certify(geo, tri)
        if cert.ok:
            return tri
        rounds = 1 if rounds == 0 else 2 * rounds
    return _exact_all(geo)


def _replace(geo: Geometry, tri: np.ndarray, cert: _Certificate, inside: np.ndarray, by_ties: bool) -> np.ndarray:
    """Re-triangulate each connected part of the marked region exactly; the parts whose exact
    triangulation does not fit their boundary are left as they were.

    With ``by_ties`` the parts are linked only across facets whose d + 2 vertices are exactly
    co-spherical (and through flat simplices): each part is then one Delaunay cell of the
    unperturbed points (a unit cube of a grid) that Qhull split another way.
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    d = geo.d
    nb = cert.neighbours
    idx = np.flatnonzero(inside)
    local = np.full(len(tri), -1, dtype=np.int64)
    local[idx] = np.arange(len(idx))
    if by_ties:
        ties = cert.ties[inside[cert.ties].all(axis=1)] if cert.ties.size else np.zeros((0, 2), np.int64)
        flat = idx[cert.orient[idx] == 0]
        fa, fb = np.repeat(flat, d + 1), nb[flat].ravel()
        ok = (fb >= 0) & inside[np.maximum(fb, 0)]
        a, b = np.concatenate([ties[:, 0], fa[ok]]), np.concatenate([ties[:, 1], fb[ok]])
    else:
        a = np.repeat(idx, d + 1)
        b = nb[idx].ravel()
        keep = (b >= 0) & inside[np.maximum(b, 0)]
        a, b = a[keep], b[keep]
    graph = coo_matrix((np.ones(len(a)), (local[a], local[b])), shape=(len(idx), len(idx)))
    n_parts, label = connected_components(graph, directed=False)
    has = inside[cert.located]
    loose_part = np.full(len(cert.loose), -1, dtype=np.int64)
    loose_part[has] = label[local[cert.located[has]]]
    order = np.argsort(label, kind="stable")
    starts = np.searchsorted(label[order], np.arange(n_parts + 1))
    by_part = np.argsort(loose_part, kind="stable")
    lstarts = np.searchsorted(loose_part[by_part], np.arange(n_parts + 1))
    replaced = np.zeros(len(tri), dtype=bool)
    pieces = []
    for part in range(n_parts):
        mine = idx[order[starts[part] : starts[part + 1]]]
        extra = cert.loose[by_part[lstarts[part] : lstarts[part + 1]]]
        ids = np.union1d(tri[mine].ravel(), extra)
        try:
            sub, sub_nb = exact_triangulation(geo, ids)
        except DegenerateInput:
            continue
        walls = []
        for s, row in zip(mine.tolist(), tri[mine].tolist()):
            for i in range(d + 1):
                t = int(nb[s, i])
                if t >= 0 and not inside[t]:
                    walls.append((tuple(row[:i] + row[i + 1 :]), row[i]))
        if walls and _same_volume(geo, sub, tri[mine]):
            got = sub  # the part is a union of whole cells: its exact triangulation is all of it
        else:
            got = _fill(geo, sub, sub_nb, walls) if walls else sub
        if got is None:
            continue
        replaced[mine] = True
        pieces.append(got)
    return np.vstack([tri[~replaced]] + pieces)


def _exact_all(geo: Geometry) -> np.ndarray:
    try:
        tri, _ = exact_triangulation(geo, np.arange(geo.n))
    except DegenerateInput:
        raise ValueError(
            f"the points span less than R^{geo.d} (affinely dependent: all on a hyperplane), "
            "so they have no Delaunay triangulation"
        ) from None
    return tri


def triangulate(geo: Geometry) -> Triangulation:
    """The certified regular triangulation of prepared points (see the module docstring).

    Thesis: Definition 2.13 (Delaunay complex; weighted points §2.1.2).

    Parameters
    ----------
    geo : Geometry
        Prepared points and weights (``prepare_geometry``).

    Returns
    -------
    Triangulation
        Its top simplices (rows ascending, in no particular row order), neighbours and ties.

    Raises
    ------
    ValueError
        If the points lie on a hyperplane (no full-dimensional triangulation).
    """
    candidate = _qhull_candidate(geo) if geo.d >= 2 else None
    if candidate is None:
        tri, hint = _exact_all(geo), None
    else:
        tri, hint = candidate
    cert = _certify(geo, tri, hint)
    if not cert.ok:
        tri = _repair(geo, tri, cert)
        cert = _certify(geo, tri)
        if not cert.ok:  # pragma: no cover - the exact construction is regular by design
            raise RuntimeError("internal error: the exact regular triangulation failed its certificate")
    return Triangulation(tri, cert.neighbours, cert.ties)


def lexicographic_order(rows: np.ndarray, n: int) -> np.ndarray:
    """The permutation sorting sorted-row simplices (vertices < n) lexicographically.

    Parameters
    ----------
    rows : numpy.ndarray of int, shape (m, k)
        Simplices as ascending rows.
    n : int
        A bound on the vertex indices (every index below it).

    Returns
    -------
    numpy.ndarray of int, shape (m,)
        ``rows[out]`` is in lexicographic order (stable among equal rows).
    """
    keys = row_keys(rows, n)
    return np.lexsort(rows.T[::-1]) if keys is None else np.argsort(keys, kind="stable")


def lexicographic(t: Triangulation) -> Triangulation:
    """The same triangulation with its simplices in lexicographic order (neighbours renumbered).

    Thesis: Definition 2.13 (simplices listed as DESIGN.md orders them).

    Parameters
    ----------
    t : Triangulation
        Any triangulation.

    Returns
    -------
    Triangulation
        A new one: simplices sorted, ``neighbours`` and ``ties`` renumbered to the new rows.
    """
    order = lexicographic_order(t.simplices, int(t.simplices.max()) + 1 if t.simplices.size else 1)
    inverse = np.empty_like(order)
    inverse[order] = np.arange(len(order))
    nb = t.neighbours[order]
    nb = np.where(nb >= 0, inverse[np.maximum(nb, 0)], -1)
    return Triangulation(t.simplices[order], nb, inverse[t.ties] if t.ties.size else t.ties)


#: budget of :func:`~thesis_lib.complexes.delaunay` and :func:`~thesis_lib.complexes.alpha` in R^5 and up: simplices of
#: every dimension, estimated before the triangulation.  There each takes about 20–40 µs (exact
#: predicates, faces, values; measured in R⁵–R⁷ on the build machine), so 10⁷ simplices are about
#: 4 minutes; 400 points in R⁷ are 4·10⁷.  In R¹–R⁴ the vectorised path is far faster per simplex
#: and the limit is ``MAX_SIMPLICES`` (memory).
MAX_DELAUNAY_SIMPLICES = 10**7

#: simplices of every dimension per top simplex of a Delaunay complex of uniform random points,
#: measured (n = 3000 in R³ to n = 120 in R⁷); beyond R⁷ extrapolated by ×1.5 per dimension
_FACES_PER_TOP = {1: 2.0, 2: 3.0, 3: 4.3, 4: 6.3, 5: 9.2, 6: 13.8, 7: 20.4}


def check_delaunay_size(n: int, d: int) -> None:
    """Refuse up front a Delaunay complex estimated above ``MAX_DELAUNAY_SIMPLICES`` simplices
    (R^5 and up; ``MAX_SIMPLICES`` below), for ``n`` points in R^d.

    Thesis: Definition 2.13 (the Delaunay complex; its size grows like n·c_d with c_d exponential
    in d).

    Parameters
    ----------
    n : int
        Number of points.
    d : int
        Their dimension.

    Raises
    ------
    ValueError
        Naming the estimate (top simplices × faces per top simplex) and the budget.
    """
    per_top = _FACES_PER_TOP.get(d, _FACES_PER_TOP[7] * 1.5 ** max(0, d - 7))
    tops = estimated_size(n, d)
    check_size(int(tops * per_top), f"simplices (estimated: {tops:,} top simplices × {per_top:g} faces each, for "
               f"the Delaunay complex of {n:,} points in R^{d})",
               limit=MAX_DELAUNAY_SIMPLICES if d >= 5 else MAX_SIMPLICES)


def regular_triangulation(points: npt.ArrayLike,
                          weights: npt.ArrayLike | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Top simplices of the regular (weighted Delaunay) triangulation and their neighbours.

    Thesis: Definition 2.13 (Delaunay complex) for weighted points (§2.1.2, power distance π_x).

    Decided with exact predicates; d + 2 co-spherical points are triangulated by CGAL's symbolic
    perturbation (as GUDHI).  Points with an empty weighted Voronoi cell are not vertices.

    Parameters
    ----------
    points : array_like, shape (n, d)
        The sites; the triangulation needs n >= d + 1 of them, distinct, spanning R^d.
    weights : array_like, shape (n,), optional
        Weights w_x >= 0 (squared radii); None gives the Delaunay triangulation.

    Returns
    -------
    simplices : numpy.ndarray of int64, shape (m, d + 1)
        The top simplices, rows ascending, in lexicographic order.
    neighbours : numpy.ndarray of int64, shape (m, d + 1)
        Row of the simplex across the facet opposite each vertex (−1 on the convex hull).

    Raises
    ------
    ValueError
        As ``prepare_geometry``, for points on a hyperplane, or for a triangulation estimated above
        the Delaunay budget (``check_delaunay_size``, R^5 and up).

    Examples
    --------
    Without weights, the Delaunay triangulation; each triangle's neighbour across the facet opposite
    vertex i (−1 on the hull):

    >>> simplices, neighbours = regular_triangulation([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.2]])
    >>> simplices.tolist(), neighbours.tolist()
    ([[0, 1, 2], [1, 2, 3]], [[1, -1, -1], [-1, -1, 0]])
    """
    geo, _ = prepare_geometry(points, weights)
    t = lexicographic(triangulate(geo))
    return t.simplices, t.neighbours

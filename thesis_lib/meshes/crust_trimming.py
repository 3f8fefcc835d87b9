"""The trimming step of the Crust (ABK98, step 5) for n-simplices in R^{n+1}, n = 1, 2, 3: one
implementation for the 3-D Crust (:func:`thesis_lib.meshes.extract_manifold`) and the Crust of
Chapter 5 (:func:`thesis_lib.meshes.crust_nd.extract_manifold_nd`).

An (n - 1)-face (a ridge) of an n-simplex in R^{n+1} has a two-dimensional normal plane, in which
every n-simplex through the ridge is a direction — exactly as the triangles about an edge in R³.
So both steps of the 3-D trimming hold in any dimension: remove simplices with a sharp ridge (in one
simplex only, or all its simplices within a wedge of angle < π/2), then walk from an outer simplex
across every ridge to the next simplex met when turning about the ridge through the outside,
orienting coherently; a simplex that would put a third simplex on a ridge is left out.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ..jit import njit
from .crust_geometry import simplex_normals

__all__ = ["unique_rows", "outer_walk", "open_walk"]


def unique_rows(rows: npt.ArrayLike, return_counts: bool = False) -> tuple[np.ndarray, ...]:
    """``np.unique(rows, axis=0, return_inverse=True)`` for non-negative integer rows, by one int64
    key per row (much faster than a row-wise unique).

    Thesis: Chapter 5 (the ridges and links of the reconstructed n-manifolds).

    Parameters
    ----------
    rows : array_like of int, shape (m, k)
        Non-negative integers (not checked).
    return_counts : bool, default False
        Also return how often each distinct row occurs.

    Returns
    -------
    uniq : ndarray of int64, shape (u, k)
        The distinct rows, in lexicographic order.
    inverse : ndarray of int64, shape (m,)
        The index of each row among them: ``uniq[inverse]`` is ``rows``.
    counts : ndarray of int64, shape (u,)
        How often each distinct row occurs; only when ``return_counts``.
    """
    rows = np.asarray(rows, dtype=np.int64)
    base = int(rows.max()) + 1 if rows.size else 1
    if base ** rows.shape[1] >= 2**62:
        out = np.unique(rows, axis=0, return_inverse=True, return_counts=return_counts)
        return (out[0], out[1].reshape(-1)) + tuple(out[2:])
    key = np.zeros(len(rows), dtype=np.int64)
    for c in range(rows.shape[1]):
        key = key * base + rows[:, c]
    out = np.unique(key, return_index=True, return_inverse=True, return_counts=return_counts)
    return (rows[out[1]], out[2].reshape(-1)) + tuple(out[3:])


def _ridge_structure(simplices: np.ndarray, nv: int):
    """Ridges of the n-simplices: ``ridges`` (R, n) sorted rows, ``ridge_of`` (m, n + 1) the ridge
    opposite each local vertex, and per ridge the incident simplices ``tri_of[start[r]:start[r+1]]``
    with their opposite vertices ``opp``.  Slots are listed in the order n, 0, 1, …, n - 1 (for
    n = 2 the edges 01, 12, 20)."""
    m, k1 = simplices.shape
    slots = [k1 - 1] + list(range(k1 - 1))
    r = np.concatenate([np.delete(simplices, k, axis=1) for k in slots])
    r.sort(axis=1)
    ridges, inv = unique_rows(r)
    uniq = ridges
    ridge_of = np.empty((m, k1), dtype=np.int64)
    for j, k in enumerate(slots):
        ridge_of[:, k] = inv[j * m:(j + 1) * m]
    order = np.argsort(inv, kind="stable")
    counts = np.bincount(inv, minlength=len(uniq))
    start = np.concatenate([[0], np.cumsum(counts)])
    tri_of = order % m
    opp = simplices[tri_of, np.asarray(slots)[order // m]]
    return ridges, ridge_of, start, tri_of, opp


@njit(cache=True)
def _edge_vectors(pts, verts):
    """Rows p_{i+1} − p_0 for the vertices ``verts`` (k + 1,) of a simplex: shape (k, d)."""
    k = verts.shape[0] - 1
    e = np.empty((k, pts.shape[1]))
    for i in range(k):
        e[i] = pts[verts[i + 1]] - pts[verts[0]]
    return e


@njit(cache=True)
def _complement_basis(pts, ridge):
    """Orthonormal basis (rows) of the directions of the ridge's affine span (Gram–Schmidt)."""
    q = _edge_vectors(pts, ridge)
    for i in range(q.shape[0]):
        for j in range(i):
            q[i] = q[i] - (q[i] * q[j]).sum() * q[j]
        q[i] = q[i] / (np.sqrt((q[i] * q[i]).sum()) + 1e-300)
    return q


@njit(cache=True)
def _project(w, q):
    """``w`` minus its projection on the span of the rows of ``q``."""
    for j in range(q.shape[0]):
        w = w - (w * q[j]).sum() * q[j]
    return w


@njit(cache=True)
def _sharp_ridges(pts, ridges, alive, start, tri_of, opp, todo, sharp):
    """Update ``sharp`` on the ridges ``todo``: a ridge is sharp when one live simplex contains it,
    or all of them lie in a wedge < π/2."""
    angles = np.empty(64)
    for e in todo:
        sharp[e] = False
        q = _complement_basis(pts, ridges[e])
        a = pts[ridges[e, 0]]
        ref = np.zeros(pts.shape[1])
        y = np.zeros(pts.shape[1])
        got_ref = False
        got_y = False
        cnt = 0
        for s in range(start[e], start[e + 1]):
            if not alive[tri_of[s]]:
                continue
            w = _project(pts[opp[s]] - a, q)
            w = w / (np.sqrt((w * w).sum()) + 1e-300)
            if not got_ref:
                ref = w
                got_ref = True
            elif not got_y:
                yy = w - (w * ref).sum() * ref
                ny = np.sqrt((yy * yy).sum())
                if ny > 1e-9:
                    y = yy / ny
                    got_y = True
            cnt += 1
        if cnt == 0:
            continue
        if cnt == 1:
            sharp[e] = True
            continue
        m = 0
        for s in range(start[e], start[e + 1]):
            if not alive[tri_of[s]] or m >= 64:
                continue
            w = _project(pts[opp[s]] - a, q)
            angles[m] = np.arctan2((w * y).sum(), (w * ref).sum()) % (2 * np.pi)
            m += 1
        srt = np.sort(angles[:m])
        gap = 2 * np.pi - srt[m - 1] + srt[0]
        for i in range(1, m):
            gap = max(gap, srt[i] - srt[i - 1])
        if gap > 1.5 * np.pi:
            sharp[e] = True


def _prune_sharp(pts, simplices, ridges, ridge_of, start, tri_of, opp, max_rounds: int = 10000) -> np.ndarray:
    """Mask of the simplices left after removing those with a sharp ridge until none is left (each
    round re-examines only the ridges of the simplices just removed)."""
    alive = np.ones(len(simplices), dtype=bool)
    sharp = np.zeros(len(ridges), dtype=bool)
    todo = np.arange(len(ridges))
    for _ in range(max_rounds):
        _sharp_ridges(pts, ridges, alive, start, tri_of, opp, todo, sharp)
        kill = alive & sharp[ridge_of].any(axis=1)
        if not kill.any():
            break
        alive &= ~kill
        todo = np.unique(ridge_of[kill])
    return alive


@njit(cache=True)
def _oriented_normal(pts, o):
    """Normal of the oriented simplex o: cofactors of its edge vectors (the cross product for n = 2)."""
    n = o.shape[0] - 1
    d = pts.shape[1]
    e = _edge_vectors(pts, o)
    nrm = np.empty(d)
    sub = np.empty((n, n))
    for k in range(d):
        for i in range(n):
            c = 0
            for j in range(d):
                if j != k:
                    sub[i, c] = e[i, j]
                    c += 1
        sign = 1.0 if k % 2 == 0 else -1.0
        nrm[k] = sign * np.linalg.det(sub)
    return nrm / (np.sqrt((nrm * nrm).sum()) + 1e-300)


@njit(cache=True)
def _parity(a, b):
    """+1 if the vertex list ``b`` is an even permutation of ``a``, -1 if odd (same vertex sets)."""
    k = a.shape[0]
    perm = np.empty(k, dtype=np.int64)
    for i in range(k):
        for j in range(k):
            if b[i] == a[j]:
                perm[i] = j
    inv = 0
    for i in range(k):
        for j in range(i + 1, k):
            if perm[i] > perm[j]:
                inv += 1
    return 1 if inv % 2 == 0 else -1


@njit(cache=True)
def _walk(pts, simplices, alive, ridges, ridge_of, start, tri_of, opp, seed, seed_flip, breadth_first,
             max_fold):
    """Coherently oriented walk from ``seed`` across every ridge to the next live simplex met when
    turning about the ridge through the outside (the side the oriented normal points to).  Depth
    first (a closed hypersurface), or ``breadth_first`` (a piece with boundary: the simplices near the
    seed are claimed before the walk reaches the debris along the boundary)."""
    m, k1 = simplices.shape
    n = k1 - 1
    orient = np.zeros((m, k1), dtype=np.int64)
    seen = np.zeros(m, dtype=np.bool_)
    stack = np.empty(m, dtype=np.int64)
    visit = np.empty(m, dtype=np.int64)
    nvisit = 0
    for i in range(k1):
        orient[seed, i] = simplices[seed, i]
    if seed_flip:
        orient[seed, 0], orient[seed, 1] = orient[seed, 1], orient[seed, 0]
    seen[seed] = True
    stack[0] = seed
    top = 1
    conflicts = 0
    want = np.empty(k1, dtype=np.int64)
    rot = np.empty(k1, dtype=np.int64)
    head = 0
    while top > head:
        if breadth_first:
            t = stack[head]
            head += 1
        else:
            top -= 1
            t = stack[top]
        visit[nvisit] = t
        nvisit += 1
        o = orient[t].copy()
        nrm = _oriented_normal(pts, o)
        for j in range(k1):
            pos_c = (j + n) % k1  # positions n, 0, 1, ..., n - 1
            c = o[pos_c]
            kc = 0
            for i in range(k1):
                if simplices[t, i] == c:
                    kc = i
            e = ridge_of[t, kc]
            q = _complement_basis(pts, ridges[e])
            a = pts[ridges[e, 0]]
            wc = _project(pts[c] - a, q)
            wc = wc / (np.sqrt((wc * wc).sum()) + 1e-300)
            best = -1
            best_ang = 1e300
            best_d = -1
            for s in range(start[e], start[e + 1]):
                t2 = tri_of[s]
                if t2 == t or not alive[t2]:
                    continue
                wd = _project(pts[opp[s]] - a, q)
                ang = np.arctan2((wd * nrm).sum(), (wd * wc).sum()) % (2 * np.pi)
                if ang < best_ang:
                    best_ang = ang
                    best = t2
                    best_d = opp[s]
            if best < 0 or abs(best_ang - np.pi) > max_fold:
                continue
            # the ridge in cyclic order after c, then d; it must induce the opposite orientation
            for i in range(n):
                rot[i] = o[(pos_c + 1 + i) % k1]
            rot[n] = best_d
            # [ridge, c] = sigma [o] with sigma the sign of a cyclic shift by pos_c + 1
            sigma = -1 if (n * (pos_c + 1)) % 2 == 1 else 1
            for i in range(k1):
                want[i] = rot[i]
            if sigma == 1:  # want -[ridge, d]: one transposition (for n = 2: (b, a, d) across the edge a → b)
                want[0], want[1] = rot[1], rot[0]
            if seen[best]:
                if _parity(want, orient[best]) != 1:
                    conflicts += 1
                continue
            seen[best] = True
            for i in range(k1):
                orient[best, i] = want[i]
            stack[top] = best
            top += 1
    return orient, visit[:nvisit], conflicts


@njit(cache=True)
def _greedy_manifold(ridge_of, order, n_ridges):
    """Keep simplices in visiting order while each of their ridges has fewer than two kept ones."""
    used = np.zeros(n_ridges, dtype=np.int64)
    keep = np.zeros(len(order), dtype=np.bool_)
    k1 = ridge_of.shape[1]
    for i in range(len(order)):
        t = order[i]
        ok = True
        for k in range(k1):
            if used[ridge_of[t, k]] >= 2:
                ok = False
        if ok:
            keep[i] = True
            for k in range(k1):
                used[ridge_of[t, k]] += 1
    return keep


@njit(cache=True)
def _openness(pts, simplices, alive, ridges, ridge_of, start, tri_of, opp, t, flip):
    """Smallest turning angle, over the ridges of simplex ``t`` (oriented, flipped or not), to another
    live simplex: about π on a sheet, small on the inner side of a pocket of candidates."""
    o = simplices[t].copy()
    if flip:
        o[0], o[1] = o[1], o[0]
    nrm = _oriented_normal(pts, o)
    worst = 2 * np.pi
    for kc in range(o.shape[0]):
        e = ridge_of[t, kc]
        q = _complement_basis(pts, ridges[e])
        a = pts[ridges[e, 0]]
        wc = _project(pts[simplices[t, kc]] - a, q)
        wc = wc / (np.sqrt((wc * wc).sum()) + 1e-300)
        for s in range(start[e], start[e + 1]):
            if tri_of[s] == t or not alive[tri_of[s]]:
                continue
            wd = _project(pts[opp[s]] - a, q)
            worst = min(worst, np.arctan2((wd * nrm).sum(), (wd * wc).sum()) % (2 * np.pi))
    return worst


#: an open piece is walked from the most open of this many simplices nearest the samples' centroid
_OPEN_SEEDS = 300


def _outer_seed(pts, s, alive) -> tuple[int, bool]:
    """A live simplex at the extreme-x sample whose normal is closest to ±x, oriented to +x."""
    live = np.flatnonzero(alive)
    top = int(np.argmax(pts[:, 0]))
    cand = live[(s[live] == top).any(axis=1)]
    if len(cand) == 0:
        cand = live[[int(np.argmax(pts[s[live]].max(axis=1)[:, 0]))]]
    nrm = simplex_normals(pts[s[cand]])
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-300
    i = int(np.argmax(np.abs(nrm[:, 0])))
    return int(cand[i]), bool(nrm[i, 0] < 0)


def _open_seed(pts, s, structure) -> tuple[int, bool]:
    """The most open (largest :func:`_openness`) simplex and orientation near the samples' centroid."""
    alive = np.ones(len(s), dtype=bool)
    dist = np.linalg.norm(pts[s].mean(axis=1) - pts.mean(axis=0), axis=1)
    near = np.argsort(dist, kind="stable")[:_OPEN_SEEDS]
    best = max((_openness(pts, s, alive, *structure, int(t), f), -i, int(t), f)
               for i, t in enumerate(near) for f in (False, True))
    return best[2], best[3]


def outer_walk(pts: np.ndarray, simplices: np.ndarray, *, prune: bool = True) -> tuple[np.ndarray, int]:
    """Trimming of candidates from a closed hypersurface: remove the simplices with sharp ridges until
    none is left (``prune``), then walk depth first from an outer simplex (at the extreme-x sample).

    Thesis: §3.4, "Triangulations" (the trimming of [ABK98]), in any dimension (Chapter 5).

    Parameters
    ----------
    pts : ndarray of float64, shape (N, n + 1)
        The samples.
    simplices : ndarray of int64, shape (m, n + 1)
        Candidate n-simplices (validated indices into ``pts``).
    prune : bool, default True
        Remove simplices with sharp ridges first.

    Returns
    -------
    simplices : ndarray of int64, shape (k, n + 1)
        Coherently oriented n-simplices (outward for a closed hypersurface), every ridge in one or
        two of them (a simplex that would put a third on a ridge is left out, in visiting order).
    conflicts : int
        The orientation conflicts met by the walk (0 for an orientable result).

    Raises
    ------
    ValueError
        If ``prune`` removes every simplex (the sample is too sparse).
    """
    structure = _ridge_structure(simplices, len(pts))
    alive = np.ones(len(simplices), dtype=bool)
    if prune:
        alive = _prune_sharp(pts, simplices, *structure)
        if not alive.any():
            raise ValueError("trimming removed every simplex: the sample is too sparse for the Crust")
    seed, flip = _outer_seed(pts, simplices, alive)
    return _kept(*_walk(pts, simplices, alive, *structure, seed, flip, False, np.pi), structure)


def open_walk(pts: np.ndarray, simplices: np.ndarray) -> tuple[np.ndarray, int]:
    """Trimming of candidates from a piece of hypersurface with boundary (which erosion would eat from
    its border and which has no outside): walk breadth first from the most open simplex near the
    centroid, stop where the next simplex folds by more than π/2 (the boundary).

    Thesis: Chapter 5 (higher-dimensional Crust; the trimming of [ABK98] used in §3.4).

    Parameters
    ----------
    pts : ndarray of float64, shape (N, n + 1)
        The samples, as in :func:`outer_walk`.
    simplices : ndarray of int64, shape (m, n + 1)
        Candidate n-simplices, as in :func:`outer_walk`.

    Returns
    -------
    simplices : ndarray of int64, shape (k, n + 1)
        Coherently oriented n-simplices reached before the boundary; every ridge in one or two.
    conflicts : int
        The orientation conflicts met by the walk.
    """
    structure = _ridge_structure(simplices, len(pts))
    alive = np.ones(len(simplices), dtype=bool)
    seed, flip = _open_seed(pts, simplices, structure)
    return _kept(*_walk(pts, simplices, alive, *structure, seed, flip, True, np.pi / 2), structure)


def _kept(orient, order, conflicts, structure) -> tuple[np.ndarray, int]:
    """The walked simplices, oriented, that :func:`_greedy_manifold` keeps, and the conflict count."""
    ridges, ridge_of = structure[0], structure[1]
    return orient[order[_greedy_manifold(ridge_of, order, len(ridges))]], int(conflicts)

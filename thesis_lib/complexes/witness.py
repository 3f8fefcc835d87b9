"""Witness complexes W(X, L, ε) (thesis §2.1.2, "The Witness Complex") and JavaPlex's lazy variant.

Notation.  ``m(x)`` is the distance from a point x to its ν-th closest landmark (``nu = ν``), with
``m(x) = 0`` for ν = 0.  The thesis writes m_k(x) for the distance to the (k + 1)-th closest landmark,
so **ν = k + 1**: the thesis's k = 0 is ``nu=1`` (the default), and this ν is JavaPlex's ν.

* :func:`witness` (the thesis's definition): a p-simplex {l_0, ..., l_p} is in W(X, L, ε) when all
  its faces are and some point x ∈ X has max_i |l_i − x| <= ε + m(x).  Its filtration value is
  max(0, min_x (max_i |l_i − x| − m(x))), which already grows with the simplex, so the "all faces"
  condition holds by itself.  One witness sees the whole simplex (a *strong* witness complex with
  plain, not squared, distances).
* :func:`lazy_witness` (JavaPlex ``LazyWitnessStream``): the rule is applied to edges only and the
  complex is the flag complex of those edges (a simplex's value is its largest edge value).

Vertices of both complexes are landmark positions ``0..L-1``: vertex ``i`` is the point
``points[landmarks[i]]``.  Every landmark is its own witness, so vertices enter at 0.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_points, check_indices, check_int, check_max_dim, check_memory, check_radius
from ..filtration import Filtration
from ..jit import load_numba, njit, prange
from ._flag import flag_levels, lower_bound, matrix_edges
from .scaling import scaled, unscale_values

__all__ = ["witness", "lazy_witness", "witness_offsets"]


def _check_landmarks(pts: np.ndarray, landmarks) -> np.ndarray:
    lm = np.asarray(landmarks)
    if lm.ndim == 1 and lm.size > pts.shape[0]:
        raise ValueError(f"{lm.size} landmarks but only {pts.shape[0]} points")
    return check_indices(lm, pts.shape[0], "landmarks", unique=True)


def _check_nu(nu, n_landmarks: int) -> int:
    nu = check_int(nu, "nu", minimum=0)
    if nu > n_landmarks:
        raise ValueError(f"nu = {nu} exceeds the number of landmarks ({n_landmarks})")
    return nu


def witness_offsets(points: npt.ArrayLike, landmarks: npt.ArrayLike, nu: int = 1) -> np.ndarray:
    """The matrix ``D[i, x] = |l_i − x| − m(x)`` (landmark i, point x) both complexes are built from.

    Thesis: §2.1.2, m_k(x) = distance to the (k + 1)-th closest landmark, with ν = k + 1.

    Parameters
    ----------
    points : (N, d) array, the witnesses.
    landmarks : 1-D distinct integer indices into ``points``.
    nu : ν >= 0 (``nu=0``: m(x) = 0).

    Returns
    -------
    ndarray, shape (L, N)
    """
    return _offsets(points, landmarks, nu, 0)


def _offsets(points, landmarks, nu, per_pair: int) -> np.ndarray:
    """:func:`witness_offsets`, refused up front when its L × N matrix (twice: the distances and the
    partition finding m(x)), and ``per_pair`` bytes per pair of landmarks for the caller's L × L
    arrays, exceed the memory budget (5·10⁴ landmarks of 2·10⁵ points: 149 GiB)."""
    pts = as_points(points)
    lm = _check_landmarks(pts, landmarks)
    nu = _check_nu(nu, lm.size)
    n_l, n_x = lm.size, pts.shape[0]
    check_memory(16.0 * n_l * n_x + float(per_pair) * n_l * n_l,
                 f"the witness distances of {n_l:,} landmarks and {n_x:,} points")
    pts, e = scaled(pts)  # power-of-two scaling: squared distances neither overflow nor underflow
    lpts = pts[lm]
    # |l - x|² expanded is cheaper but loses accuracy near 0; chunked direct differences instead
    dist = np.empty((lm.size, pts.shape[0]))
    for start in range(0, lm.size, 64):
        block = lpts[start : start + 64]
        dist[start : start + block.shape[0]] = np.sqrt(((block[:, None, :] - pts[None, :, :]) ** 2).sum(-1))
    if nu > 0:
        dist -= np.partition(dist, nu - 1, axis=0)[nu - 1][None, :]
    return unscale_values(dist, -e, "distances")


_SORTED_LIMIT = 20_000_000  # largest L × N for which the per-landmark sorted witness lists are kept
_BIG = 1e300  # stands for "not a witness" (finite, so the fastmath reductions stay valid)


@njit(cache=True, fastmath=True)
def _minmax_full(cur, row):
    best = _BIG
    for x in range(cur.shape[0]):
        v = cur[x] if cur[x] > row[x] else row[x]
        best = v if v < best else best
    return best


@njit(cache=True)
def _minmax_gather(cur, idx, cnt, row):
    best = _BIG
    for j in range(cnt):
        v = row[idx[j]]
        if cur[j] > v:
            v = cur[j]
        if v < best:
            best = v
    return best


@njit(cache=True)
def _candidate_counts(parents, ev, eps):
    """Per parent: the landmarks w > last vertex whose edges to every vertex have value <= eps."""
    m, width = parents.shape
    n_l = ev.shape[0]
    counts = np.zeros(m, dtype=np.int64)
    for r in range(m):
        c = 0
        for w in range(parents[r, width - 1] + 1, n_l):
            ok = True
            for i in range(width):
                if ev[parents[r, i], w] > eps:
                    ok = False
                    break
            if ok:
                c += 1
        counts[r] = c
    return counts


@njit(cache=True)
def _witness_parent(r, parents, D, ev, arg, eps, order, sorted_d, use_sorted, out, out_v, valid, start,
                    cur, ccur, idx):
    """Children of parent ``r`` written into rows ``start, start + 1, ...`` (one per candidate)."""
    width = parents.shape[1]
    n_l, n_x = D.shape
    cnt = 0
    pv = _BIG
    xp = 0
    for x in range(n_x):
        mx = D[parents[r, 0], x]
        for i in range(1, width):
            v = D[parents[r, i], x]
            if v > mx:
                mx = v
        if mx <= eps:
            cur[x] = mx
            ccur[cnt] = mx
            idx[cnt] = x
            cnt += 1
            if mx < pv:
                pv = mx
                xp = x
        else:
            cur[x] = _BIG
    slot = start
    last = parents[r, width - 1]
    compressed = 4 * cnt < n_x
    for w in range(last + 1, n_l):
        lb = pv
        ok = True
        for i in range(width):
            e = ev[parents[r, i], w]
            if e > eps:
                ok = False
                break
            if e > lb:
                lb = e
        if not ok:
            continue
        # (the parent is in the complex, so cnt > 0 and xp is a real witness)
        ub = max(cur[xp], D[w, xp])
        for i in range(width):
            x = arg[parents[r, i], w]
            v = max(cur[x], D[w, x])
            if v < ub:
                ub = v
        n_scan = n_x + 1
        u_best = 0
        if use_sorted and ub > lb:
            for i in range(width + 1):
                u = parents[r, i] if i < width else w
                c = lower_bound(sorted_d[u], 0, sorted_d.shape[1], ub)
                if c < n_scan:
                    n_scan = c
                    u_best = u
        if ub <= lb:
            best = ub
        elif 3 * n_scan < (cnt if compressed else n_x):
            best = ub
            for k in range(n_scan):
                if sorted_d[u_best, k] >= best:
                    break
                x = order[u_best, k]
                v = cur[x]
                if D[w, x] > v:
                    v = D[w, x]
                if v < best:
                    best = v
        elif compressed:
            best = _minmax_gather(ccur, idx, cnt, D[w])
        else:
            best = _minmax_full(cur, D[w])
        for i in range(width):
            out[slot, i] = parents[r, i]
        out[slot, width] = w
        out_v[slot] = max(best, 0.0)
        valid[slot] = best <= eps
        slot += 1


@njit(cache=True, parallel=True)
def _witness_level(parents, D, ev, arg, eps, order, sorted_d, use_sorted, n_chunks):
    """Children one dimension up with value min_x max_{l in child} D[l, x] (<= eps), lexicographic.

    ``ev[a, b]`` is the (unclamped) value of edge ab and ``arg[a, b]`` a witness realising it; they
    give a lower bound and candidate witnesses, so many simplices need no scan over all points.
    With ``use_sorted``, ``order[l]`` lists the points by increasing ``D[l, x]`` (``sorted_d[l]``):
    a witness beating the current best b has D[u, x] < b for every vertex u, so only the prefix of
    the shortest such list is scanned.  Parents are processed in parallel, each writing its
    candidates into its own rows (so the output order does not depend on the threads).
    """
    m, width = parents.shape
    n_x = D.shape[1]
    counts = _candidate_counts(parents, ev, eps)
    starts = np.zeros(m + 1, dtype=np.int64)
    for r in range(m):
        starts[r + 1] = starts[r] + counts[r]
    total = starts[m]
    out = np.empty((total, width + 1), dtype=np.int64)
    out_v = np.empty(total, dtype=np.float64)
    valid = np.zeros(total, dtype=np.bool_)
    n_chunks = max(1, min(m, n_chunks))
    for c in prange(n_chunks):
        cur = np.empty(n_x)
        ccur = np.empty(n_x)
        idx = np.empty(n_x, dtype=np.int64)
        for r in range(c * m // n_chunks, (c + 1) * m // n_chunks):
            if counts[r] > 0:
                _witness_parent(r, parents, D, ev, arg, eps, order, sorted_d, use_sorted, out, out_v, valid,
                                starts[r], cur, ccur, idx)
    keep = np.flatnonzero(valid)
    return out[keep], out_v[keep]


@njit(cache=True)
def _edge_values(D):
    """Unclamped edge values min_x max(D[a, x], D[b, x]) and a witness realising each."""
    n_l, n_x = D.shape
    out = np.zeros((n_l, n_l))
    arg = np.zeros((n_l, n_l), dtype=np.int64)
    for a in range(n_l):
        best0 = np.inf
        for x in range(n_x):
            if D[a, x] < best0:
                best0 = D[a, x]
                arg[a, a] = x
        out[a, a] = best0
        for b in range(a + 1, n_l):
            best = np.inf
            bx = 0
            for x in range(n_x):
                u = D[a, x]
                v = D[b, x]
                val = u if u > v else v
                if val < best:
                    best = val
                    bx = x
            out[a, b] = best
            out[b, a] = best
            arg[a, b] = bx
            arg[b, a] = bx
    return out, arg


def witness(points: npt.ArrayLike, landmarks: npt.ArrayLike, max_radius: float, max_dim: int,
            nu: int = 1) -> Filtration:
    """Witness filtration W(X, L, ε) with the thesis's (strong, un-squared) rule.

    Thesis: §2.1.2 "The Witness Complex" (Definition 2.16 for landmarks), with m_k and ν = k + 1.

    Parameters
    ----------
    points : (N, d) array, the witnesses X (landmarks included).
    landmarks : 1-D integer indices into ``points`` (e.g. from :func:`maxmin_landmarks`); at most N.
    max_radius : largest ε kept.
    max_dim : largest simplex dimension built (>= 0).
    nu : ν = k + 1 >= 0, the landmark rank defining m(x) (``nu=1``: nearest landmark, thesis k = 0).

    Returns
    -------
    Filtration
        On vertices ``0..L-1`` (landmark positions); the value of σ is
        max(0, min_x (max_{l∈σ} |l − x| − m(x))).
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    D = np.ascontiguousarray(_offsets(points, landmarks, nu, 16))  # + the L × L edge values and witnesses
    n_l = D.shape[0]
    simplices = [np.arange(n_l, dtype=np.int64).reshape(n_l, 1)]
    values = [np.zeros(n_l)]
    if max_dim >= 1:
        ev, arg = _edge_values(D)
        edges, vals = matrix_edges(np.maximum(ev, 0.0), eps)
        simplices.append(edges)
        values.append(vals)
        use_sorted = max_dim >= 2 and D.size <= _SORTED_LIMIT
        if use_sorted:
            order = np.argsort(D, axis=1, kind="stable")
            sorted_d = np.ascontiguousarray(np.take_along_axis(D, order, axis=1))
        else:
            order, sorted_d = np.zeros((1, 1), np.int64), np.zeros((1, 1))
        for _ in range(2, max_dim + 1):
            if simplices[-1].shape[0] == 0:
                break
            s, v = _witness_level(simplices[-1], D, ev, arg, eps, order, sorted_d, use_sorted,
                                  64 * load_numba().get_num_threads())
            simplices.append(s)
            values.append(v)
    return Filtration(simplices, values, validate=False, truncated_at=max_dim)


def lazy_witness(points: npt.ArrayLike, landmarks: npt.ArrayLike, max_radius: float, max_dim: int,
                 nu: int = 1) -> Filtration:
    """Lazy witness filtration (JavaPlex): the witness rule on edges, then the flag complex.

    Thesis: §2.1.2 "The Witness Complex" (edge rule with m_k, ν = k + 1) and the flag-complex
    construction of Definition 2.11's discussion; as JavaPlex's ``LazyWitnessStream`` used in §2.4.

    Parameters
    ----------
    points, landmarks, max_radius, max_dim, nu
        As in :func:`witness`.

    Returns
    -------
    Filtration
        Same vertex numbering as :func:`witness`; a simplex's value is its largest edge value, so
        the lazy complex contains the witness complex at every ε.
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    D = np.ascontiguousarray(_offsets(points, landmarks, nu, 16))
    ev, _ = _edge_values(D)
    edges, vals = matrix_edges(np.maximum(ev, 0.0), eps) if max_dim >= 1 else (np.empty((0, 2), np.int64), np.empty(0))
    simplices, values = flag_levels(D.shape[0], edges, vals, max_dim)
    return Filtration(simplices, values, validate=False, truncated_at=max_dim)

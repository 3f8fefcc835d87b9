"""The implicit Rips engine: persistence of a Vietoris–Rips filtration without storing its simplices.

A Rips complex is a flag complex: every simplex is determined by its vertices, and its value by
the longest edge.  So nothing but the graph of edges (diameter ≤ 2ε) is stored, as neighbour lists
sorted by decreasing vertex; a k-simplex {v_k > … > v_0} is the integer

    idx = C(v_0, 1) + C(v_1, 2) + … + C(v_k, k + 1)         (the combinatorial number system),

its vertices are read back from idx by binary search in a table of binomials, and its coboundary
(the cofaces σ ∪ {j}) is enumerated on the fly by merging the neighbour lists of its vertices, j
decreasing, so that the coface indices come out decreasing.  The filtration order within a
dimension is (diameter ascending, index descending) — Ripser's reverse colexicographic tie-break,
which makes the first coface found with σ's own diameter the *earliest* coface of σ.

The reduction is Ripser's (Bauer 2021), on the cohomology side with clearing:

* **H₀ by union–find** over the edges in filtration order (elder rule); the edges that merge two
  components are the pivots of dimension 0 and are cleared from dimension 1.
* **Apparent pairs, a discrete gradient.**  A pair σ < τ is *apparent* when σ is the latest facet
  of τ and τ the earliest coface of σ.  Each such pair is a persistence pair of the filtration, and
  together they form an acyclic matching — a discrete gradient vector field in the sense of the
  thesis's Definitions 4.30–4.33 — whose critical cells are the only ones the reduction has to look
  at (the barcode is the Morse complex's, Theorem 4.42's idea).  Pairs of equal diameter
  ("zero apparent pairs") have zero persistence: σ is never made a column, and τ is known as the
  pivot of δσ when another column meets it.  Deciding whether σ is in such a pair is local (one
  early-exit coboundary scan and one facet scan), so it runs in parallel over the candidate columns
  (``numba.prange`` on every core; the candidates are independent).
* **Emergent pairs**: a column whose earliest coface has σ's diameter and is not yet a pivot is
  paired at once, without enumerating the rest of its coboundary.
* **The rest is reduced lazily**: the working coboundary is a heap of *coboundary enumerators*,
  one per added coboundary f · δs, each yielding the cofaces of s one at a time in filtration order
  (the cofaces of s's own diameter by decreasing index, then the others by merging the vertices'
  distance-sorted neighbour lists); the heap holds each enumerator's head, equal entries are summed
  only when they reach the top, and an enumerator is advanced only when its head is popped.  So the
  column costs a few words per added coboundary, never its entries (Ripser's heap holds every entry
  pushed and not yet popped).  An added column is regenerated from its reduction chain V (the
  simplices whose coboundaries sum to it), never stored reduced.  This loop is sequential (each
  column depends on the pivots found before it), which is why it does not share the explicit
  engine's loop over stored columns: the field arithmetic, the heap and the chain merging are
  shared (:mod:`.kernels`), the coboundary enumeration cannot be.

The columns of each dimension are only the candidates that survive clearing and the apparent
pairs, so memory holds the graph, one (diameter, index) pair per column, the pivot and apparent
tables, the reduction chains of the columns that needed work and, while a column is reduced, its
enumerators.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._unionfind import find as _find
from .._validate import MAX_DIM, as_distance_matrix, as_points, check_max_dim, check_radius, resolve_coefficients
from ..jit import load_numba, njit, prange
from .barcode import Barcode
from .kernels import grow, heap_pop, heap_push, heap_replace_top, merge_entries, mod_inverse

if TYPE_CHECKING:
    import scipy.sparse

__all__ = ["rips_persistence", "rips_graph"]

#: up to this many points a dense distance matrix (8 n² bytes, 128 MB at the limit) is kept for
#: constant-time lookups; beyond, distances are found by binary search in the neighbour lists
DENSE_MAX = 4096


# ---------------------------------------------------------------------------- the graph
def rips_graph(
    points: npt.ArrayLike | None = None, *, max_radius: float = np.inf,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = None,
) -> tuple[int, npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.float64]]:
    """The neighbour graph of a Rips filtration: ``(n, indptr, neighbours, lengths)``.

    Thesis: Definition 2.11 (an edge when the distance is at most 2ε).

    Parameters
    ----------
    points : array_like, shape (n, d), optional
        The point cloud (Euclidean distances); give exactly one of ``points`` and ``distance_matrix``.
    max_radius : float
        Scale ε: an edge joins two vertices at distance at most 2ε (default ∞: every pair).
    distance_matrix : array_like, shape (n, n), or scipy.sparse matrix, optional
        A dense symmetric matrix of distances, or a scipy.sparse matrix whose stored entries are the
        only edges (as ripser's sparse input; the diagonal is ignored, entries above 2ε dropped).

    Returns
    -------
    n : int
        The number of vertices.
    indptr : numpy.ndarray of int64, shape (n + 1,)
        ``neighbours[indptr[v]:indptr[v + 1]]`` are the vertices adjacent to v.
    neighbours : numpy.ndarray of int64
        Each vertex's neighbours in decreasing order.
    lengths : numpy.ndarray of float64
        The distances, parallel to ``neighbours``.

    Raises
    ------
    ValueError
        Both or neither of ``points`` and ``distance_matrix``; a bad radius, point cloud or
        distance matrix (not square, NaN, negative or asymmetric entries); more edges than
        ``MAX_SIMPLICES`` (refused before they are listed, ``complexes.rips.check_edges``).
    """
    from ..complexes._flag import edges_within, matrix_edges
    from ..complexes.rips import check_edges

    eps = check_radius(max_radius)
    threshold = 2.0 * eps
    if (points is None) == (distance_matrix is None):
        raise ValueError("give exactly one of points and distance_matrix")
    if points is not None:
        pts = np.ascontiguousarray(as_points(points))
        n = pts.shape[0]
        with np.errstate(over="ignore"):
            check_edges(n, threshold, points=pts)  # 10⁵ points at ε = ∞: 5·10⁹ edges, refused up front
        edges, lengths = edges_within(pts, threshold)
    elif hasattr(distance_matrix, "tocoo"):  # scipy.sparse
        coo = distance_matrix.tocoo()
        n = _square(coo.shape)
        r, c, v = np.asarray(coo.row, np.int64), np.asarray(coo.col, np.int64), np.asarray(coo.data, np.float64)
        _check_distances(v)
        off = r != c
        r, c, v = r[off], c[off], v[off]
        lo, hi = np.minimum(r, c), np.maximum(r, c)
        key = lo * n + hi
        order = np.lexsort((v, key))
        key, v = key[order], v[order]
        first = np.ones(key.shape[0], dtype=bool)
        first[1:] = key[1:] != key[:-1]
        dup = np.flatnonzero(~first)
        if dup.size and not np.allclose(v[dup], v[dup - 1], rtol=1e-12, atol=0):
            raise ValueError("distance_matrix is not symmetric: an entry (i, j) differs from (j, i)")
        key, v = key[first], v[first]
        keep = v <= threshold
        edges = np.column_stack([key[keep] // n, key[keep] % n])
        lengths = v[keep]
    else:
        dm = as_distance_matrix(distance_matrix)
        n = dm.shape[0]
        check_edges(n, threshold, matrix=dm)
        edges, lengths = matrix_edges(dm, threshold)
    return (n, *_csr(n, np.asarray(edges, np.int64).reshape(-1, 2), np.asarray(lengths, np.float64)))


def _square(shape) -> int:
    if len(shape) != 2 or shape[0] != shape[1] or shape[0] == 0:
        raise ValueError(f"distance_matrix must be a non-empty square (n, n) matrix, got shape {shape}")
    return int(shape[0])


def _check_distances(v: np.ndarray) -> None:
    if np.isnan(v).any():
        raise ValueError("distance_matrix contains NaN")
    if (v < 0).any():
        raise ValueError("distance_matrix has a negative distance")


def _csr(n: int, edges: np.ndarray, lengths: np.ndarray):
    """Symmetric neighbour lists, each sorted by decreasing neighbour."""
    return _csr_kernel(np.int64(n), np.ascontiguousarray(edges), np.ascontiguousarray(lengths))


@njit(cache=True)
def _csr_kernel(n, edges, lengths):
    indptr = np.zeros(n + 1, dtype=np.int64)
    for e in range(edges.shape[0]):
        indptr[edges[e, 0] + 1] += 1
        indptr[edges[e, 1] + 1] += 1
    for v in range(n):
        indptr[v + 1] += indptr[v]
    fill = indptr[:-1].copy()
    nbr = np.empty(indptr[n], dtype=np.int64)
    length = np.empty(indptr[n], dtype=np.float64)
    # edges (u, v) with u < v in any order: place v in u's list and u in v's, then sort each list
    for e in range(edges.shape[0]):
        u, v = edges[e, 0], edges[e, 1]
        nbr[fill[u]] = v
        length[fill[u]] = lengths[e]
        fill[u] += 1
        nbr[fill[v]] = u
        length[fill[v]] = lengths[e]
        fill[v] += 1
    for v in range(n):
        a, b = indptr[v], indptr[v + 1]
        rising = True  # edges in lexicographic order (every source of ours) fill each list rising
        for e in range(a + 1, b):
            if nbr[e] <= nbr[e - 1]:
                rising = False
                break
        if rising:
            nbr[a:b] = nbr[a:b][::-1].copy()
            length[a:b] = length[a:b][::-1].copy()
        else:
            order = np.argsort(-nbr[a:b])
            nbr[a:b] = nbr[a:b][order]
            length[a:b] = length[a:b][order]
    return indptr, nbr, length


def _by_distance(indptr, nbr, length):
    """The same neighbour lists sorted by increasing distance, ties by decreasing neighbour (for the
    apparent-pair test): one sort of every entry by distance (numpy's), then a stable pass that
    puts each entry back in its vertex's list."""
    return _by_distance_kernel(indptr, nbr, length, np.argsort(length))


@njit(cache=True)
def _by_distance_kernel(indptr, nbr, length, order):
    n = indptr.shape[0] - 1
    owner = np.empty(nbr.shape[0], dtype=np.int64)
    for v in range(n):
        owner[indptr[v] : indptr[v + 1]] = v
    fill = indptr[:-1].copy()
    pos = np.empty(nbr.shape[0], dtype=np.int64)
    for t in range(order.shape[0]):
        e = order[t]
        v = owner[e]
        pos[fill[v]] = e
        fill[v] += 1
    for v in range(n):
        _ties_by_index(pos[indptr[v] : indptr[v + 1]], length, nbr)
    return nbr[pos], length[pos]


@njit(cache=True)
def _ties_by_index(order, key, idx):
    """Within each run of equal ``key[order]``, put ``order`` by decreasing ``idx`` (in place): an
    order by key up and then idx down, from any order by key up."""
    m = order.shape[0]
    a = 0
    while a < m:
        b = a + 1
        while b < m and key[order[b]] == key[order[a]]:
            b += 1
        if b - a > 16:  # a long run (many equal distances): sort it
            run = order[a:b].copy()
            order[a:b] = run[np.argsort(-idx[run], kind="mergesort")]
        else:
            for x in range(a + 1, b):  # insertion sort
                t = order[x]
                y = x - 1
                while y >= a and idx[order[y]] < idx[t]:
                    order[y + 1] = order[y]
                    y -= 1
                order[y + 1] = t
        a = b


@njit(cache=True)
def _dense(n, indptr, nbr, length):
    """The n × n distance matrix of the graph, inf where there is no edge (the diagonal too: as in
    the neighbour lists, a vertex is not its own neighbour)."""
    D = np.full((n, n), np.inf)
    for u in range(n):
        for e in range(indptr[u], indptr[u + 1]):
            D[u, nbr[e]] = length[e]
    return D


# ---------------------------------------------------------------------------- combinatorial number system
@njit(cache=True)
def _binomials(n, kmax):
    """B[v, k] = C(v, k) for 0 <= v <= n, 0 <= k <= kmax."""
    B = np.zeros((n + 1, kmax + 1), dtype=np.int64)
    for v in range(n + 1):
        B[v, 0] = 1
        for k in range(1, min(v, kmax) + 1):
            B[v, k] = B[v - 1, k - 1] + (B[v - 1, k] if k <= v - 1 else 0)
    return B


@njit(cache=True)
def _vertices(idx, k, n, B, out):
    """The vertices of the k-simplex ``idx``, decreasing, into ``out[:k + 1]``."""
    top = n - 1
    for r in range(k + 1):
        kk = k + 1 - r
        lo, hi = kk - 1, top
        while lo < hi:
            mid = (lo + hi + 1) >> 1
            if B[mid, kk] <= idx:
                lo = mid
            else:
                hi = mid - 1
        out[r] = lo
        idx -= B[lo, kk]
        top = lo - 1


@njit(cache=True, inline="always")
def _dist(indptr, nbr, length, D, u, v):
    """Distance of u and v: from the dense matrix ``D`` when there is one (small n), else by binary
    search in u's neighbour list (decreasing); inf if there is no edge."""
    if D.shape[0] > 0:
        return D[u, v]
    lo, hi = indptr[u], indptr[u + 1]
    end = hi
    while lo < hi:
        mid = (lo + hi) >> 1
        if nbr[mid] > v:
            lo = mid + 1
        else:
            hi = mid
    if lo < end and nbr[lo] == v:
        return length[lo]
    return np.inf


@njit(cache=True)
def _cofaces(verts, k, idx, diam, indptr, nbr, length, B, cur, out_d, out_i, out_m, first_equal, above_only):
    """Enumerate the cofaces σ ∪ {j} of the k-simplex σ (vertices ``verts`` decreasing), j decreasing.

    Writes each coface's diameter, index and m = #{vertices of σ above j} (its sign in δσ is (−1)^m)
    into the ``out_*`` arrays and returns their number.  With ``first_equal`` it stops at the first
    coface of diameter ``diam`` (the earliest coface when one has σ's diameter) and returns 1 (0 when
    there is none); with ``above_only`` only cofaces whose new vertex is above σ's are listed (each
    (k+1)-simplex then comes from exactly one facet).
    """
    base = 0
    for i in range(k + 1):
        cur[i] = indptr[verts[i]]
        if indptr[verts[i] + 1] - indptr[verts[i]] < indptr[verts[base] + 1] - indptr[verts[base]]:
            base = i
    vb = verts[base]
    idx_above = np.int64(0)
    idx_below = idx
    m = 0
    count = 0
    for e in range(indptr[vb], indptr[vb + 1]):
        j = nbr[e]
        if above_only and j < verts[0]:
            break
        while m <= k and verts[m] > j:
            idx_below -= B[verts[m], k + 1 - m]
            idx_above += B[verts[m], k + 2 - m]
            m += 1
        dmax = length[e] if length[e] > diam else diam
        ok = True
        for i in range(k + 1):
            if i == base:
                continue
            c = cur[i]
            end = indptr[verts[i] + 1]
            while c < end and nbr[c] > j:
                c += 1
            cur[i] = c
            if c == end or nbr[c] != j:
                ok = False
                break
            if length[c] > dmax:
                dmax = length[c]
        if not ok:
            continue
        if first_equal:
            if dmax == diam:
                out_d[0] = dmax
                out_i[0] = idx_above + B[j, k + 2 - m] + idx_below
                out_m[0] = m
                return 1
            continue
        out_d[count] = dmax
        out_i[count] = idx_above + B[j, k + 2 - m] + idx_below
        out_m[count] = m
        count += 1
    return count


@njit(cache=True)
def _upper(arr, lo, hi, x):
    """First position in the increasing ``arr[lo:hi]`` with a value > x."""
    while lo < hi:
        mid = (lo + hi) >> 1
        if arr[mid] <= x:
            lo = mid + 1
        else:
            hi = mid
    return lo


@njit(cache=True, inline="always")
def _zero_pivot_cofacet(verts, k, idx, diam, indptr, nbr, length, D, dnbr, dlen, B, cur, od, oi, om):
    """The earliest coface of the k-simplex σ if it has σ's diameter (else −1), and its m.

    The cofaces of σ's diameter are σ ∪ {j} for the j within ``diam`` of every vertex; the earliest is
    the one with the largest j.  When one vertex has few neighbours that close, they are read from
    its distance-sorted list and checked (short simplices: a handful); otherwise the coboundary is
    scanned with j decreasing and stops at the first hit (long simplices: found almost at once) —
    with a dense distance matrix, a plain scan of the matrix's columns j = n − 1, n − 2, … (no list
    merging).  Returns (index, m, j) with j the added vertex, (−1, 0, −1) when there is none.
    """
    if D.shape[0] > 0:  # every vertex has more than 1/8 of its neighbours within diam: scan D
        wide = True
        for i in range(k + 1):
            v = verts[i]
            deg = indptr[v + 1] - indptr[v]
            if deg == 0 or dlen[indptr[v] + deg // 8] > diam:
                wide = False
                break
        if wide:
            return _with_vertex(verts, k, idx, _dense_first(verts, k, diam, D), B)
    best = -1
    bcount = np.int64(1) << 62
    for i in range(k + 1):
        v = verts[i]
        c = _upper(dlen, indptr[v], indptr[v + 1], diam) - indptr[v]
        if c < bcount:
            bcount = c
            best = i
    jmax = np.int64(-1)
    if 8 * bcount > indptr[verts[best] + 1] - indptr[verts[best]]:
        if D.shape[0] > 0:
            return _with_vertex(verts, k, idx, _dense_first(verts, k, diam, D), B)
        if _cofaces(verts, k, idx, diam, indptr, nbr, length, B, cur, od, oi, om, True, False):
            return oi[0], om[0], np.int64(-1)  # j unknown: the caller decodes the coface
        return np.int64(-1), np.int64(0), np.int64(-1)
    vb = verts[best]
    for e in range(indptr[vb], indptr[vb] + bcount):
        j = dnbr[e]
        if j <= jmax:
            continue
        ok = True
        for i in range(k + 1):
            if i != best and _dist(indptr, nbr, length, D, verts[i], j) > diam:
                ok = False
                break
        if ok:
            jmax = j
    return _with_vertex(verts, k, idx, jmax, B)


@njit(cache=True)
def _dense_first(verts, k, diam, D):
    """The largest j within ``diam`` of each of the k + 1 vertices ``verts`` in the dense matrix D,
    −1 if there is none (D[v, v] = inf: the vertices themselves never match)."""
    for j in range(D.shape[0] - 1, -1, -1):
        ok = True
        for i in range(k + 1):
            if D[verts[i], j] > diam:
                ok = False
                break
        if ok:
            return np.int64(j)
    return np.int64(-1)


@njit(cache=True)
def _with_vertex(verts, k, idx, j, B):
    """(index of σ ∪ {j}, m = #vertices of σ above j, j) for the k-simplex σ = ``idx``; (−1, 0, −1)
    when j < 0."""
    if j < 0:
        return np.int64(-1), np.int64(0), np.int64(-1)
    idx_above = np.int64(0)
    idx_below = idx
    m = 0
    while m <= k and verts[m] > j:
        idx_below -= B[verts[m], k + 1 - m]
        idx_above += B[verts[m], k + 2 - m]
        m += 1
    return idx_above + B[j, k + 2 - m] + idx_below, np.int64(m), np.int64(j)


@njit(cache=True, inline="always")
def _zero_pivot_facet(tau, k1, n, diam, indptr, nbr, length, D, B, w, pd, known):
    """The latest facet of the (k1)-simplex ``tau`` if it has tau's diameter, else −1; also its
    position r (the omitted vertex is w[r], so its sign in ∂τ is (−1)^r).  With ``known`` the
    vertices of tau are already in ``w`` (decreasing); otherwise they are decoded from ``tau``."""
    if not known:
        _vertices(tau, k1, n, B, w)
    for a in range(k1 + 1):
        for b in range(a + 1, k1 + 1):
            d = _dist(indptr, nbr, length, D, w[a], w[b])
            pd[a, b] = d
            pd[b, a] = d
    idx_above = np.int64(0)
    idx_below = tau
    for r in range(k1 + 1):  # omit w[r]: facet indices increase with r, so the first is the latest
        idx_below -= B[w[r], k1 + 1 - r]
        fd = 0.0
        for a in range(k1 + 1):
            if a == r:
                continue
            for b in range(a + 1, k1 + 1):
                if b != r and pd[a, b] > fd:
                    fd = pd[a, b]
        if fd == diam:
            return idx_above + idx_below, r
        idx_above += B[w[r], k1 - r]
    return np.int64(-1), -1


# ---------------------------------------------------------------------------- hash table of int64 keys
@njit(cache=True)
def _slot(keys, key):
    mask = keys.shape[0] - 1
    h = np.int64((np.uint64(key) * np.uint64(0x9E3779B97F4A7C15)) >> np.uint64(17)) & mask
    while keys[h] != -1 and keys[h] != key:
        h = (h + 1) & mask
    return h


@njit(cache=True)
def _table(size):
    cap = 16
    while cap < 2 * size + 2:
        cap *= 2
    return np.full(cap, -1, dtype=np.int64), np.empty(cap, dtype=np.int64)


# ---------------------------------------------------------------------------- dimension 0
@njit(cache=True)
def _edges(n, indptr, nbr, length):
    """Every edge as (diameter, index = C(u, 2) + v for u > v), by increasing index."""
    m = indptr[n] // 2
    ed = np.empty(m, dtype=np.float64)
    ei = np.empty(m, dtype=np.int64)
    c = 0
    for u in range(n):
        for e in range(indptr[u + 1] - 1, indptr[u] - 1, -1):  # neighbours increasing
            v = nbr[e]
            if v >= u:
                break
            ed[c] = length[e]
            ei[c] = u * (u - 1) // 2 + v
            c += 1
    return ed, ei


@njit(cache=True)
def _h0(n, order, ed, ei, B):
    """Union–find over the edges in filtration order: deaths of H0 classes, and the positive edges."""
    parent = np.arange(n, dtype=np.int64)
    deaths = np.empty(n, dtype=np.float64)
    nd = 0
    positive = np.zeros(order.shape[0], dtype=np.bool_)
    for t in range(order.shape[0]):
        e = order[t]
        u = np.int64((1.0 + np.sqrt(1.0 + 8.0 * ei[e])) / 2.0)  # ei = C(u, 2) + v with v < u
        while u * (u - 1) // 2 > ei[e]:
            u -= 1
        while (u + 1) * u // 2 <= ei[e]:
            u += 1
        a = _find(parent, u)
        b = _find(parent, ei[e] - u * (u - 1) // 2)
        if a == b:
            positive[e] = True
            continue
        if a < b:
            a, b = b, a
        parent[a] = b
        deaths[nd] = ed[e]
        nd += 1
    comps = 0
    for v in range(n):
        if parent[v] == v:
            comps += 1
    return deaths[:nd], comps, positive


# ---------------------------------------------------------------------------- apparent pairs
@njit(cache=True)
def _apparent_block(lo, hi, k, cand_i, cand_d, n, indptr, nbr, length, D, dnbr, dlen, B, tau, sign, apparent):
    """:func:`_apparent` for the candidates ``lo .. hi − 1`` (each one independent of the others)."""
    verts = np.empty(k + 2, dtype=np.int64)
    cur = np.empty(k + 2, dtype=np.int64)
    od = np.empty(1, dtype=np.float64)
    oi = np.empty(1, dtype=np.int64)
    om = np.empty(1, dtype=np.int64)
    w = np.empty(k + 2, dtype=np.int64)
    pd = np.zeros((k + 2, k + 2), dtype=np.float64)
    for c in range(lo, hi):
        _vertices(cand_i[c], k, n, B, verts)
        t_c, m_c, j = _zero_pivot_cofacet(verts, k, cand_i[c], cand_d[c], indptr, nbr, length, D, dnbr, dlen,
                                          B, cur, od, oi, om)
        if t_c != -1:
            tau[c] = t_c
            sign[c] = 1 - 2 * (m_c & 1)
            if j >= 0:  # τ's vertices: σ's with j inserted at position m
                for r in range(k + 2):
                    w[r] = verts[r] if r < m_c else (j if r == m_c else verts[r - 1])
            f, _ = _zero_pivot_facet(t_c, k + 1, n, cand_d[c], indptr, nbr, length, D, B, w, pd, j >= 0)
            apparent[c] = f == cand_i[c]


@njit(cache=True, parallel=True)
def _apparent_parallel(k, cand_i, cand_d, n, indptr, nbr, length, D, dnbr, dlen, B, nblocks, tau, sign, apparent):
    m = cand_i.shape[0]
    size = (m + nblocks - 1) // nblocks
    for t in prange(nblocks):
        _apparent_block(t * size, min(m, (t + 1) * size), k, cand_i, cand_d, n, indptr, nbr, length, D, dnbr, dlen,
                        B, tau, sign, apparent)


#: below this many candidate columns the apparent pairs are found on one thread (starting the
#: thread pool costs more than it saves, and much more on a loaded machine)
PARALLEL_MIN = 50_000


def _apparent(k, cand_i, cand_d, n, indptr, nbr, length, D, dnbr, dlen, B):
    """For each candidate k-simplex: its earliest coface if that has the same diameter (else −1), its
    sign, and whether the two form a zero apparent pair.  The candidates are independent, so above
    ``PARALLEL_MIN`` they are split in blocks over every core (``numba.prange``)."""
    m = cand_i.shape[0]
    tau = np.full(m, -1, dtype=np.int64)
    sign = np.zeros(m, dtype=np.int64)
    apparent = np.zeros(m, dtype=np.bool_)
    args = (k, cand_i, cand_d, n, indptr, nbr, length, D, dnbr, dlen, B)
    threads = load_numba().get_num_threads()
    if m >= PARALLEL_MIN and threads > 1:
        _apparent_parallel(*args, np.int64(8 * threads), tau, sign, apparent)
    else:
        _apparent_block(0, m, *args, tau, sign, apparent)
    return tau, sign, apparent


# ---------------------------------------------------------------------------- lazy coboundary enumerators
# The working column is a heap of *enumerators*, one per added coboundary f · δs: each holds s's
# vertices and a few list positions, and yields the cofaces of s one at a time in filtration order,
# so the heap holds one head per added coboundary and nothing else (Ripser's heap holds every entry
# pushed and not yet popped: hundreds of millions at 1000 points per circle).  An enumerator's row
# of the int64 state table S (width 2k + 8):
#   S[r, 0:k+1] the vertices of s (decreasing); S[r, k+1:2k+2] list positions; S[r, AUX] the base
#   vertex (phase 0, 1) ; S[r, PHASE]; S[r, COEF] = f; S[r, SKIP] a coface index to leave out (the
#   pivot being cancelled) or −1; S[r, KEY], S[r, HEAD_C] the head's key (−index) and coefficient.
# and of the float table F: F[r, 0] the diameter of s, F[r, 1] the head's diameter.
# Phases: the cofaces of s's own diameter d come first (phase 0: a scan of the base vertex's
# neighbours by decreasing index, the base being the vertex with fewest neighbours within d; phase 1:
# the same set by selection from the base's distance-sorted prefix, when that prefix is short), then
# the rest (phase 2: a merge of the k + 1 distance-sorted lists beyond d by (distance, −neighbour);
# σ ∪ {j} is emitted from the list of the vertex farthest from j, the last list to reach j), so the
# keys come out increasing: (diameter up, index down).
@njit(cache=True)
def _coface_index(S, r, k, j, B):
    """Index of s ∪ {j} (s the vertices in row r of S) and m = #vertices of s above j."""
    idx = np.int64(0)
    m = 0
    for q in range(k + 1):
        v = S[r, q]
        if v > j:
            idx += B[v, k + 2 - q]
            m += 1
        else:
            idx += B[v, k + 1 - q]
    return idx + B[j, k + 2 - m], m


@njit(cache=True)
def _emit(S, F, r, k, j, d, B, p):
    """Make σ ∪ {j} (diameter d) the head of enumerator r; False when it is the one to skip."""
    idx, m = _coface_index(S, r, k, j, B)
    if idx == S[r, 2 * k + 5]:
        return False
    S[r, 2 * k + 6] = -idx
    f = S[r, 2 * k + 4]
    S[r, 2 * k + 7] = f if (m & 1) == 0 else p - f
    F[r, 1] = d
    return True


@njit(cache=True)
def _start_far(S, F, r, k, indptr, dlen):
    """Enter phase 2: each list position just past the neighbours within s's diameter."""
    d = F[r, 0]
    for q in range(k + 1):
        v = S[r, q]
        S[r, k + 1 + q] = _upper(dlen, indptr[v], indptr[v + 1], d)
    S[r, 2 * k + 3] = 2


@njit(cache=True)
def _advance(S, F, r, k, indptr, nbr, length, D, dnbr, dlen, B, p):
    """Move enumerator r to its next coface; False when it has none left."""
    P0 = k + 1
    AUX = 2 * k + 2
    PH = 2 * k + 3
    d = F[r, 0]
    while True:
        ph = S[r, PH]
        if ph == 0:  # cofaces of diameter d, by a scan of the base vertex's neighbours (j decreasing)
            b = S[r, AUX]
            e = S[r, P0 + b]
            end = indptr[S[r, b] + 1]
            while e < end:
                j = nbr[e]
                le = length[e]
                e += 1
                if le > d:
                    continue
                ok = True
                for q in range(k + 1):
                    if q != b and _dist(indptr, nbr, length, D, S[r, q], j) > d:
                        ok = False
                        break
                if ok and _emit(S, F, r, k, j, d, B, p):
                    S[r, P0 + b] = e
                    return True
            _start_far(S, F, r, k, indptr, dlen)
        elif ph == 1:  # the same set by selection: the largest j below the last one emitted
            b = S[r, AUX]
            vb = S[r, b]
            last = S[r, P0]
            hi = S[r, P0 + 1]
            best = np.int64(-1)
            for e in range(indptr[vb], hi):
                j = dnbr[e]
                if j >= last or j <= best:
                    continue
                ok = True
                for q in range(k + 1):
                    if q != b and _dist(indptr, nbr, length, D, S[r, q], j) > d:
                        ok = False
                        break
                if ok:
                    best = j
            if best == -1:
                _start_far(S, F, r, k, indptr, dlen)
                continue
            S[r, P0] = best
            if _emit(S, F, r, k, best, d, B, p):
                return True
        elif ph == 2:  # the far cofaces: merge the distance-sorted lists by (distance, −neighbour)
            while True:
                qi = -1
                bd = np.inf
                bj = np.int64(-1)
                for q in range(k + 1):
                    c = S[r, P0 + q]
                    if c < indptr[S[r, q] + 1]:
                        x = dlen[c]
                        if qi == -1 or x < bd or (x == bd and dnbr[c] > bj):
                            qi = q
                            bd = x
                            bj = dnbr[c]
                if qi == -1:
                    S[r, PH] = 3
                    return False
                S[r, P0 + qi] += 1
                ok = True
                for q in range(k + 1):
                    if q != qi:
                        x = _dist(indptr, nbr, length, D, S[r, q], bj)
                        if x > bd or (x == bd and q > qi):
                            ok = False
                            break
                if ok and _emit(S, F, r, k, bj, bd, B, p):
                    return True
        else:
            return False


@njit(cache=True)
def _open(S, F, r, s, f, skip, ds, k, n, indptr, nbr, length, D, dnbr, dlen, B, p):
    """Set up enumerator r for f · δs without the coface ``skip``; False when it yields nothing."""
    _vertices(s, k, n, B, S[r, : k + 1])
    F[r, 0] = ds
    S[r, 2 * k + 4] = f
    S[r, 2 * k + 5] = skip
    b = 0
    cb = np.int64(1) << 62
    for q in range(k + 1):  # the base: the vertex with the fewest neighbours within ds
        v = S[r, q]
        c = _upper(dlen, indptr[v], indptr[v + 1], ds) - indptr[v]
        if c < cb:
            cb = c
            b = q
    vb = S[r, b]
    S[r, 2 * k + 2] = b
    if cb == 0:
        _start_far(S, F, r, k, indptr, dlen)
    elif cb * cb <= indptr[vb + 1] - indptr[vb]:
        S[r, 2 * k + 3] = 1
        S[r, k + 1] = n  # last j emitted: none yet
        S[r, k + 2] = indptr[vb] + cb
    else:
        S[r, 2 * k + 3] = 0
        S[r, k + 1 + b] = indptr[vb]
    return _advance(S, F, r, k, indptr, nbr, length, D, dnbr, dlen, B, p)


@njit(cache=True)
def _add(S, F, nr, hv, hk, hr, hn, s, f, skip, ds, k, n, indptr, nbr, length, D, dnbr, dlen, B, p):
    """Add f · δs (without ``skip``) to the working column: a new enumerator, its head on the heap.
    Returns the (possibly grown) tables, the number of enumerators and the heap size."""
    if nr == S.shape[0]:
        S2 = np.empty((2 * nr, S.shape[1]), dtype=S.dtype)
        S2[:nr] = S
        F2 = np.empty((2 * nr, 2), dtype=F.dtype)
        F2[:nr] = F
        S, F = S2, F2
        hv, hk, hr = grow(hv, hk, hr, hn, 2 * nr)
    if _open(S, F, nr, s, f, skip, ds, k, n, indptr, nbr, length, D, dnbr, dlen, B, p):
        hn = heap_push(hv, hk, hr, hn, F[nr, 1], S[nr, 2 * k + 6], nr)
        nr += 1
    return S, F, nr, hv, hk, hr, hn


@njit(cache=True)
def _pop_pivot(S, F, hv, hk, hr, hn, k, indptr, nbr, length, D, dnbr, dlen, B, p):
    """The pivot of the working column (its earliest coface whose summed coefficient is non-zero),
    removed from it: returns (heap size, diameter, key, coefficient, entries read); coefficient 0
    when the column is zero."""
    read = 0
    while hn > 0:
        v, key = hv[0], hk[0]
        c = np.int64(0)
        while hn > 0 and hk[0] == key:
            r = hr[0]
            c += S[r, 2 * k + 7]
            read += 1
            if _advance(S, F, r, k, indptr, nbr, length, D, dnbr, dlen, B, p):
                heap_replace_top(hv, hk, hr, hn, F[r, 1], S[r, 2 * k + 6], r)
            else:
                hn = heap_pop(hv, hk, hr, hn)
        c %= p
        if c != 0:
            return hn, v, key, c, read
    return hn, np.inf, np.int64(0), np.int64(0), read


# ---------------------------------------------------------------------------- the reduction
@njit(cache=True)
def _record(wk, wc, wd, wn, s, c, d):
    """Append (simplex s, coefficient c, diameter d) to the working reduction chain V."""
    if wn == wk.shape[0]:
        wk, wc, wd = grow(wk, wc, wd, wn, wn + 1)
    wk[wn] = s
    wc[wn] = c
    wd[wn] = d
    return wk, wc, wd, wn + 1


@njit(cache=True)
def _reduce(k, col_i, col_d, col_tau, col_sign, app_keys, app_vals, n, indptr, nbr, length, D, dnbr, dlen, B, p):
    """Reduce the coboundary columns of the k-simplices ``col_i`` (latest first) over Z/p.

    The implicit kernel: the library's one reduction loop over coboundaries enumerated on the fly
    (the stored-matrix one is :func:`~thesis_lib.persistence.kernels.reduce_columns`).
    ``col_tau``/``col_sign``: each column's earliest coface when it has the column's diameter (else
    −1) and its sign; ``app_keys``/``app_vals``: the table τ → σ of the zero apparent pairs (σ, τ)
    of this dimension.  Returns (births, deaths, essential births, pivot table keys, number of
    emergent pairs, of columns reduced with at least one addition, of additions, of entries read,
    the largest number of enumerators a column needed).
    """
    ncol = col_i.shape[0]
    pkeys, pvals = _table(ncol)
    pcoef = np.zeros(ncol, dtype=np.int64)
    vstart = np.full(ncol, -1, dtype=np.int64)
    vlen = np.zeros(ncol, dtype=np.int64)
    pool_s = np.empty(1024, dtype=np.int64)
    pool_c = np.empty(1024, dtype=np.int64)
    pool_d = np.empty(1024, dtype=np.float64)
    used = 0
    emergent = 0
    births = np.empty(ncol, dtype=np.float64)
    deaths = np.empty(ncol, dtype=np.float64)
    npairs = 0
    ess = np.empty(ncol, dtype=np.float64)
    ness = 0
    verts = np.empty(k + 2, dtype=np.int64)
    w = np.empty(k + 2, dtype=np.int64)
    S = np.empty((64, 2 * k + 8), dtype=np.int64)  # the enumerators (see above)
    F = np.empty((64, 2), dtype=np.float64)
    hv = np.empty(64, dtype=np.float64)  # heap of their heads
    hk = np.empty(64, dtype=np.int64)
    hr = np.empty(64, dtype=np.int64)
    wk = np.empty(64, dtype=np.int64)
    wc = np.empty(64, dtype=np.int64)
    wd = np.empty(64, dtype=np.float64)
    worked = 0
    additions = 0
    read = 0
    most = 0
    for c in range(ncol):
        s = col_i[c]
        ds = col_d[c]
        t = col_tau[c]
        if t != -1:  # emergent pair: the earliest coface has σ's diameter and nobody owns it
            h = _slot(pkeys, t)
            if pkeys[h] == -1 and app_keys[_slot(app_keys, t)] == -1:
                pkeys[h] = t
                pvals[h] = c
                pcoef[c] = col_sign[c] % p
                emergent += 1
                continue
        S, F, nr, hv, hk, hr, hn = _add(S, F, 0, hv, hk, hr, 0, s, np.int64(1), np.int64(-1), ds, k, n, indptr, nbr,
                                        length, D, dnbr, dlen, B, p)
        wn = 0
        piv = np.int64(-1)
        while True:
            hn, pv, pk, pc, got = _pop_pivot(S, F, hv, hk, hr, hn, k, indptr, nbr, length, D, dnbr, dlen, B, p)
            read += got
            if pc == 0:  # the column is zero: σ creates an essential class
                piv = -1
                break
            piv = -pk
            h = _slot(pkeys, piv)
            if pkeys[h] != -1:  # add the column owning this pivot: factor · Σ_{s' in V_o} δ(s')
                o = pvals[h]
                factor = (p - pc * mod_inverse(pcoef[o], p) % p) % p
                ol = 1 if vstart[o] == -1 else vlen[o] + 1
                for q in range(ol):
                    if q == 0:
                        so, co = col_i[o], np.int64(1)
                        dso = col_d[o]
                    else:
                        so, co = pool_s[vstart[o] + q - 1], pool_c[vstart[o] + q - 1]
                        dso = pool_d[vstart[o] + q - 1]
                    f = factor * co % p
                    wk, wc, wd, wn = _record(wk, wc, wd, wn, so, f, dso)
                    S, F, nr, hv, hk, hr, hn = _add(S, F, nr, hv, hk, hr, hn, so, f, piv, dso, k, n, indptr, nbr,
                                                    length, D, dnbr, dlen, B, p)
                additions += 1
                continue
            ha = _slot(app_keys, piv)
            if app_keys[ha] != -1:  # pivot of a zero apparent pair (e, τ): add δe, the column of e
                e = app_vals[ha]
                de = pv  # the pair has equal diameters
                _vertices(piv, k + 1, n, B, w)
                _vertices(e, k, n, B, verts)
                r = 0
                while r <= k and w[r] == verts[r]:
                    r += 1
                se = 1 if (r & 1) == 0 else p - 1  # coefficient of τ in δe: (−1)^r
                factor = (p - pc * mod_inverse(se, p) % p) % p
                wk, wc, wd, wn = _record(wk, wc, wd, wn, e, factor, de)
                S, F, nr, hv, hk, hr, hn = _add(S, F, nr, hv, hk, hr, hn, e, factor, piv, de, k, n, indptr, nbr,
                                                length, D, dnbr, dlen, B, p)
                additions += 1
                continue
            # the pivot is free: (σ, τ) is a persistence pair
            if pv > ds:
                births[npairs] = ds
                deaths[npairs] = pv
                npairs += 1
            pkeys[h] = piv
            pvals[h] = c
            pcoef[c] = pc
            break
        most = max(most, nr)
        if wn > 0:
            worked += 1
        if piv == -1:
            ess[ness] = ds
            ness += 1
            continue
        if wn > 0:  # store V_c (merged, zeros dropped; σ itself is implicit) for later additions
            pos, sums = merge_entries(wk, wc, wn, p)
            if used + pos.shape[0] > pool_s.shape[0]:
                pool_s, pool_c, pool_d = grow(pool_s, pool_c, pool_d, used, used + pos.shape[0])
            vstart[c] = used
            for q in range(pos.shape[0]):
                pool_s[used + q] = wk[pos[q]]
                pool_c[used + q] = sums[q]
                pool_d[used + q] = wd[pos[q]]
            vlen[c] = pos.shape[0]
            used += pos.shape[0]
    return births[:npairs], deaths[:npairs], ess[:ness], pkeys, emergent, worked, additions, read, most


# ---------------------------------------------------------------------------- candidates of dimension k >= 2
@njit(cache=True)
def _next_simplices(k, prev_i, prev_d, n, indptr, nbr, length, B, maxdeg):
    """All (k)-simplices as cofaces of the (k−1)-simplices whose new vertex is the largest."""
    cap = max(16, prev_i.shape[0])
    out_i = np.empty(cap, dtype=np.int64)
    out_d = np.empty(cap, dtype=np.float64)
    cnt = 0
    verts = np.empty(k + 1, dtype=np.int64)
    cur = np.empty(k + 1, dtype=np.int64)
    od = np.empty(maxdeg + 1, dtype=np.float64)
    oi = np.empty(maxdeg + 1, dtype=np.int64)
    om = np.empty(maxdeg + 1, dtype=np.int64)
    for s in range(prev_i.shape[0]):
        _vertices(prev_i[s], k - 1, n, B, verts)
        c = _cofaces(verts, k - 1, prev_i[s], prev_d[s], indptr, nbr, length, B, cur, od, oi, om, False, True)
        if cnt + c > cap:
            while cap < cnt + c:
                cap *= 2
            oi2 = np.empty(cap, dtype=np.int64)
            od2 = np.empty(cap, dtype=np.float64)
            oi2[:cnt] = out_i[:cnt]
            od2[:cnt] = out_d[:cnt]
            out_i, out_d = oi2, od2
        out_i[cnt:cnt + c] = oi[:c]
        out_d[cnt:cnt + c] = od[:c]
        cnt += c
    return out_i[:cnt], out_d[:cnt]


@njit(cache=True)
def _not_in(keys_a, keys_b, cand_i):
    """Mask of the candidates found in neither hash table (the cleared simplices are dropped)."""
    out = np.ones(cand_i.shape[0], dtype=np.bool_)
    for c in range(cand_i.shape[0]):
        if keys_a[_slot(keys_a, cand_i[c])] != -1 or keys_b[_slot(keys_b, cand_i[c])] != -1:
            out[c] = False
    return out


@njit(cache=True)
def _apparent_table(cand_i, tau, apparent):
    keys, vals = _table(int(apparent.sum()))
    for c in range(cand_i.shape[0]):
        if apparent[c]:
            h = _slot(keys, tau[c])
            keys[h] = tau[c]
            vals[h] = cand_i[c]
    return keys, vals


# ---------------------------------------------------------------------------- driver
def rips_persistence(
    points: npt.ArrayLike | None = None, *, max_radius: float = np.inf, max_dim: int = 2, coefficients: int = 2,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = None,
    stats: dict[int, dict[str, int]] | None = None,
) -> Barcode:
    """Barcode of the Vietoris–Rips filtration of ``points`` without building it (implicit engine).

    Thesis: Definition 2.11 (Rips), Theorem 2.39 / Algorithm 2 (the pairs, computed by the dual
    reduction), Definitions 4.30–4.33 and Theorem 4.42 (apparent pairs as a discrete gradient).

    Parameters
    ----------
    points : array_like, shape (n, d), optional
        The point cloud; or give ``distance_matrix``.
    max_radius : float
        Scale ε: simplices of diameter ≤ 2ε (the values are ε = diameter / 2, as
        :func:`~thesis_lib.complexes.rips`).
    max_dim : int
        The largest simplex dimension of the complex (as :func:`~thesis_lib.complexes.rips`), ≥ 1;
        homology of dimensions 0 .. max_dim − 1 is computed, and it is complete (the top dimension
        of a truncated complex is not: its classes could only die in dimensions that are not built).
    coefficients : int
        A prime p: the field Z/p.
    distance_matrix : array_like, shape (n, n), or scipy.sparse matrix, optional
        A dense symmetric matrix, or a scipy.sparse matrix whose stored entries are the only edges
        (entries above 2ε dropped); keyword only, instead of ``points``.
    stats : dict, optional
        Filled per dimension with ``simplices`` (k-simplices not killing a (k−1)-class),
        ``apparent`` (zero apparent pairs σ < τ found), ``columns`` (columns left), ``emergent``
        (paired without enumerating their coboundary), ``reduced`` (columns that needed an addition)
        and ``additions``.

    Returns
    -------
    Barcode
        The same intervals as ``persistence(rips(points, max_radius, max_dim), coefficients)`` in
        dimensions 0 .. max_dim − 1 (zero-length intervals left out).

    Raises
    ------
    ValueError
        ``max_dim`` below 1 or above ``MAX_DIM`` (10⁴; dimensions above
        the number of points are computed as the empty homology they are), a non-prime
        ``coefficients``, or invalid points / distances.
    """
    max_dim = check_max_dim(max_dim, maximum=MAX_DIM)
    if max_dim < 1:
        raise ValueError("max_dim must be >= 1: the top dimension of the complex has no complete homology")
    p = resolve_coefficients(coefficients, None, default=2, field=True)
    n, indptr, nbr, length = rips_graph(points, max_radius=max_radius, distance_matrix=distance_matrix)
    asked, max_dim = max_dim, min(max_dim, n + 1)  # no simplex has more than n vertices: H_k = 0 for k >= n
    if math.comb(n, max_dim + 1) >= 2**62:
        raise ValueError(f"{n} points with max_dim={max_dim}: simplex indices would overflow 64 bits")
    B = _binomials(np.int64(n), np.int64(max_dim + 1))
    maxdeg = int(np.diff(indptr).max(initial=0))
    dnbr, dlen = _by_distance(indptr, nbr, length)
    D = _dense(np.int64(n), indptr, nbr, length) if n <= DENSE_MAX else np.empty((0, 0))
    intervals: dict[int, np.ndarray] = {}
    # ---- H0: union–find
    ed, ei = _edges(np.int64(n), indptr, nbr, length)
    order = np.argsort(ed)  # filtration order: diameter up, index down
    _ties_by_index(order, ed, ei)
    d0, comps, positive = _h0(np.int64(n), order, ed, ei, B)
    iv0 = np.empty((d0.shape[0] + comps, 2))
    iv0[: d0.shape[0], 0] = 0.0
    iv0[: d0.shape[0], 1] = d0
    iv0[d0.shape[0] :] = (0.0, np.inf)
    intervals[0] = iv0
    if stats is not None:
        stats[0] = {"simplices": n, "apparent": 0, "columns": n, "emergent": 0, "reduced": 0, "additions": 0}
    # ---- dimensions 1 .. max_dim - 1: cohomology with clearing, apparent and emergent pairs
    all_i, all_d = ei, ed  # every (k−1)-simplex, to generate the k-simplices
    cand_i, cand_d = ei[positive], ed[positive]
    for k in range(1, max_dim):
        tau, sign, apparent = _apparent(k, cand_i, cand_d, np.int64(n), indptr, nbr, length, D, dnbr, dlen, B)
        app_keys, app_vals = _apparent_table(cand_i, tau, apparent)
        keep = ~apparent
        cols = np.lexsort((cand_i[keep], -cand_d[keep]))  # latest first: diameter down, index up
        col_i, col_d = cand_i[keep][cols], cand_d[keep][cols]
        col_tau, col_sign = tau[keep][cols], sign[keep][cols]
        births, deaths, ess, pkeys, emergent, worked, adds, entries, most = _reduce(
            k, col_i, col_d, col_tau, col_sign, app_keys, app_vals, np.int64(n), indptr, nbr, length, D, dnbr, dlen,
            B, np.int64(p))
        iv = np.empty((births.shape[0] + ess.shape[0], 2))
        iv[: births.shape[0], 0] = births
        iv[: births.shape[0], 1] = deaths
        iv[births.shape[0] :, 0] = ess
        iv[births.shape[0] :, 1] = np.inf
        intervals[k] = iv
        if stats is not None:
            stats[k] = {"simplices": int(cand_i.shape[0]), "apparent": int(apparent.sum()),
                        "columns": int(col_i.shape[0]), "emergent": int(emergent),
                        "reduced": int(worked), "additions": int(adds),
                        "entries": int(entries), "enumerators": int(most)}
        if k + 1 < max_dim:
            all_i, all_d = _next_simplices(k + 1, all_i, all_d, np.int64(n), indptr, nbr, length, B, maxdeg)
            mask = _not_in(pkeys, app_keys, all_i)
            cand_i, cand_d = all_i[mask], all_d[mask]
    for d in intervals:
        intervals[d] = intervals[d] * 0.5  # diameters -> ε
    return Barcode(intervals, range(asked), p=p)

"""Acyclic matchings (discrete gradient vector fields) with few critical simplices (thesis §4.2.6).

Finding a gradient with the minimum number of critical simplices is NP-hard (Joswig & Pfetsch 2006,
thesis §4.2.6), so these are heuristics: greedy coreduction / collapse, and Robins, Wood &
Sheppard's ProcessLowerStars (2011) for lower-star filtrations of vertex values.
"""

from __future__ import annotations

import heapq
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from .._validate import check_complex_size, check_seed
from ._cells import CellComplex, ComplexLike, Pairs, Simplex, cell_complex, pairs_from_partner, partner_array
from ._kernels import greedy_partner

__all__ = ["morse_matching", "critical_counts"]


def _vertex_ranks(cx: CellComplex, values) -> np.ndarray:
    vals = np.asarray(values, dtype=np.float64)
    nv = int(cx.arrays[0][:, 0].max()) + 1
    if vals.ndim != 1:
        raise ValueError(f"vertex values must be a 1-D array, got shape {vals.shape}")
    if vals.shape[0] < nv:
        raise ValueError(f"vertex values cover {vals.shape[0]} vertices but the complex uses vertex {nv - 1}")
    if not np.all(np.isfinite(vals)):
        raise ValueError("vertex values must be finite (no NaN or inf)")
    order = np.lexsort((np.arange(vals.shape[0]), vals))  # ties broken by vertex index
    rank = np.empty(vals.shape[0], dtype=np.int64)
    rank[order] = np.arange(vals.shape[0])
    return rank


def _lower_star_partner(cx: CellComplex, values) -> np.ndarray:
    """ProcessLowerStars (Robins, Wood & Sheppard 2011) on the lower stars of the vertex order."""
    rank = _vertex_ranks(cx, values)
    keys: list[tuple[int, ...]] = []
    top = np.empty(cx.n, dtype=np.int64)  # vertex (global id of the 0-cell) whose lower star holds g
    vid = np.full(rank.shape[0], -1, dtype=np.int64)
    vid[cx.arrays[0][:, 0]] = np.arange(cx.counts[0])
    for d, a in enumerate(cx.arrays):
        r = rank[a]
        srt = -np.sort(-r, axis=1)
        keys.extend(map(tuple, srt.tolist()))
        top[cx.offsets[d] : cx.offsets[d + 1]] = vid[a[np.arange(a.shape[0]), np.argmax(r, axis=1)]]
    members = [[] for _ in range(cx.counts[0])]
    for g in np.argsort(top, kind="stable").tolist():
        members[top[g]].append(g)
    fptr, fidx = cx.D.indptr, cx.D.indices
    cptr, cidx = cx.cofaces.indptr, cx.cofaces.indices
    partner = np.full(cx.n, -1, dtype=np.int64)
    done = np.zeros(cx.n, dtype=bool)

    def lower_faces(g: int, v: int) -> list[int]:
        return [int(h) for h in fidx[fptr[g] : fptr[g + 1]] if top[h] == v]

    def lower_cofaces(g: int, v: int) -> list[int]:
        return [int(h) for h in cidx[cptr[g] : cptr[g + 1]] if top[h] == v]

    def unpaired_faces(g: int, v: int) -> list[int]:
        return [h for h in lower_faces(g, v) if not done[h]]

    def push_ones(cells: Sequence[int], v: int, pq_one: list[tuple[tuple[int, ...], int]]) -> None:
        for a in cells:
            for b in lower_cofaces(a, v):
                if not done[b] and len(unpaired_faces(b, v)) == 1:
                    heapq.heappush(pq_one, (keys[b], b))

    for v in range(cx.counts[0]):
        star = members[v]
        if len(star) == 1:
            done[v] = True
            continue
        edges = [g for g in star if cx.dim_of[g] == 1]
        delta = min(edges, key=lambda g: keys[g])
        partner[v], partner[delta] = delta, v
        done[v] = done[delta] = True
        pq_zero = [(keys[g], g) for g in edges if g != delta]
        heapq.heapify(pq_zero)
        pq_one: list[tuple[tuple[int, ...], int]] = []
        push_ones([delta], v, pq_one)
        while pq_one or pq_zero:
            while pq_one:
                _, a = heapq.heappop(pq_one)
                if done[a]:
                    continue
                free = unpaired_faces(a, v)
                if len(free) == 0:
                    heapq.heappush(pq_zero, (keys[a], a))
                elif len(free) == 1:
                    b = free[0]
                    partner[a], partner[b] = b, a
                    done[a] = done[b] = True
                    push_ones([a, b], v, pq_one)
            while pq_zero and done[pq_zero[0][1]]:
                heapq.heappop(pq_zero)
            if pq_zero:
                _, c = heapq.heappop(pq_zero)
                done[c] = True  # critical
                push_ones([c], v, pq_one)
    return partner


def morse_matching(
    simplices: ComplexLike, *, heuristic: str = "coreduction", values: npt.ArrayLike | None = None,
    seed: int | None = None,
) -> list[tuple[Simplex, Simplex]]:
    """An acyclic matching (gradient vector field) with few critical simplices.

    Thesis: §4.2.6 (minimising critical simplices is NP-hard [JP06]; acyclic by Theorem 4.44).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        The complex (all faces are added).
    heuristic : {"coreduction", "collapse", "lower-star"}, default "coreduction"
        ``"coreduction"``: greedy coreductions, a lowest-dimensional cell made critical when none
        is possible — one critical vertex per connected component.  ``"collapse"``: greedy
        elementary collapses from free faces, a top-dimensional cell made critical when stuck.
        ``"lower-star"``: ProcessLowerStars of Robins–Wood–Sheppard 2011 on the lower-star
        filtration of ``values``; every pair lies in one lower star.
    values : array_like, shape (n_vertices,), optional
        Finite vertex values (indexed by vertex number), required for ``"lower-star"`` and refused
        by the other heuristics; ties are broken by vertex index.
    seed : int, optional
        Random tie-breaking of the greedy heuristics (``None``: deterministic order).

    Returns
    -------
    list of (tuple, tuple)
        The pairs ``(sigma, tau)``, sigma a facet of tau, ordered by sigma (dimension, then
        lexicographically).  The optimum is NP-hard to reach; the result is only guaranteed to be
        acyclic.

    Raises
    ------
    ValueError
        An unknown heuristic, ``values`` missing for (or given to) a heuristic, or vertex values that are
        not finite, not 1-D or do not cover every vertex; a seed that is not a non-negative
        integer or None (``True``, ``[1, 2]``, ``numpy.array([1])``, ``1.5``, ``-1``).

    Examples
    --------
    On the 6-vertex RP² the coreduction heuristic leaves one critical simplex in each dimension, the
    fewest Z/2 allows (β = 1, 1, 1 over Z/2):

    >>> from thesis_lib.datasets import rp2
    >>> pairs = morse_matching(rp2())
    >>> len(pairs), critical_counts(rp2(), pairs)
    (14, [1, 1, 1])
    """
    if heuristic not in ("coreduction", "collapse", "lower-star"):
        raise ValueError(f"heuristic must be 'coreduction', 'collapse' or 'lower-star', got {heuristic!r}")
    seed = check_seed(seed, optional=True)
    cx = cell_complex(check_complex_size(simplices, "the complex"))
    if heuristic == "lower-star":
        if values is None:
            raise ValueError("heuristic 'lower-star' needs vertex values")
        partner = _lower_star_partner(cx, values)
    else:
        if values is not None:
            raise ValueError(f"heuristic {heuristic!r} takes no values")
        partner = greedy_partner(cx, heuristic, seed=seed)
    return pairs_from_partner(cx, partner)


def critical_counts(simplices: ComplexLike, pairs: Pairs) -> list[int]:
    """Number of critical simplices per dimension (Crit_k^d) of a vector field.

    Thesis: Theorem 4.27 (weak discrete Morse inequalities β_k ≤ Crit_k^d).

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and a vector field on it; a simplex in no pair is critical.

    Returns
    -------
    list of int
        ``out[k]`` the number of critical k-simplices, k = 0..dim K.

    Examples
    --------
    >>> from thesis_lib.datasets import torus
    >>> critical_counts(torus(), morse_matching(torus()))
    [1, 2, 1]
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    return np.bincount(cx.dim_of[partner < 0], minlength=cx.dimension + 1).astype(int).tolist()

"""The trimming step of the Crust (ABK98, step 5) for n-simplices in R^{n+1}, n = 1, 2, 3: one
implementation for the 3-D Crust (:func:`thesis_lib.reconstruction.extract_manifold`) and the Crust of
Chapter 5 (:func:`thesis_lib.reconstruction.crust_nd.extract_manifold_nd`).

An (n - 1)-face (a ridge) of an n-simplex in R^{n+1} has a two-dimensional normal plane, in which
every n-simplex through the ridge is a direction — exactly as the triangles about an edge in R³.
So both steps of the 3-D trimming hold in any dimension: remove simplices with a sharp ridge (in one
simplex only, or all its simplices within a wedge of angle < π/2), then walk from an outer simplex
across every ridge to the next simplex met when turning about the ridge through the outside,
orienting coherently; a simplex that would put a third simplex on a ridge is left out.  The walks
and the sharp-ridge test are compiled C++ (``src/crust_trimming.cpp``).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import crust_trimming as _trimming_core
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
    i64 = np.int64
    return (np.ascontiguousarray(ridges, dtype=i64), ridge_of, np.ascontiguousarray(start, dtype=i64),
            np.ascontiguousarray(tri_of, dtype=i64), np.ascontiguousarray(opp, dtype=i64))


def _prune_sharp(pts, simplices, ridges, ridge_of, start, tri_of, opp, max_rounds: int = 10000) -> np.ndarray:
    """Mask of the simplices left after removing those with a sharp ridge until none is left (each
    round re-examines only the ridges of the simplices just removed)."""
    alive = np.ones(len(simplices), dtype=bool)
    sharp = np.zeros(len(ridges), dtype=bool)
    todo = np.arange(len(ridges))
    for _ in range(max_rounds):
        _trimming_core.sharp_ridges(pts, ridges, alive, start, tri_of, opp, np.ascontiguousarray(todo, dtype=np.int64),
                                    sharp)
        kill = alive & sharp[ridge_of].any(axis=1)
        if not kill.any():
            break
        alive &= ~kill
        todo = np.unique(ridge_of[kill])
    return alive


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
    """The most open simplex and orientation near the samples' centroid: the largest smallest turning
    angle to another candidate over its ridges (about π on a sheet, small inside a pocket)."""
    alive = np.ones(len(s), dtype=bool)
    dist = np.linalg.norm(pts[s].mean(axis=1) - pts.mean(axis=0), axis=1)
    near = np.argsort(dist, kind="stable")[:_OPEN_SEEDS]
    ts = np.repeat(near.astype(np.int64), 2)
    flips = np.tile(np.array([False, True]), len(near))
    worst = _trimming_core.openness(pts, s, alive, _trimming_core.Ridges(*structure), ts, flips).tolist()
    best = max((worst[2 * i + j], -i, int(t), f) for i, t in enumerate(near) for j, f in enumerate((False, True)))
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
    pts = np.ascontiguousarray(pts, dtype=np.float64)
    simplices = np.ascontiguousarray(simplices, dtype=np.int64)
    structure = _ridge_structure(simplices, len(pts))
    alive = np.ones(len(simplices), dtype=bool)
    if prune:
        alive = _prune_sharp(pts, simplices, *structure)
        if not alive.any():
            raise ValueError("trimming removed every simplex: the sample is too sparse for the Crust")
    seed, flip = _outer_seed(pts, simplices, alive)
    ridges = _trimming_core.Ridges(*structure)
    return _kept(*_trimming_core.walk(pts, simplices, alive, ridges, seed, flip, False, np.pi), structure)


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
    pts = np.ascontiguousarray(pts, dtype=np.float64)
    simplices = np.ascontiguousarray(simplices, dtype=np.int64)
    structure = _ridge_structure(simplices, len(pts))
    alive = np.ones(len(simplices), dtype=bool)
    seed, flip = _open_seed(pts, simplices, structure)
    ridges = _trimming_core.Ridges(*structure)
    return _kept(*_trimming_core.walk(pts, simplices, alive, ridges, seed, flip, True, np.pi / 2), structure)


def _kept(orient, order, conflicts, structure) -> tuple[np.ndarray, int]:
    """The walked simplices, oriented, that the greedy manifold keeps (in visiting order, while each of
    their ridges has fewer than two kept ones), and the conflict count."""
    ridges, ridge_of = structure[0], structure[1]
    return orient[order[_trimming_core.greedy_manifold(ridge_of, order, len(ridges))]], int(conflicts)

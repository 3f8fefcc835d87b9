"""Internal: gradient paths of a discrete vector field on a :class:`~._cells.CellComplex`.

The V-path digraph and its topological order (acyclicity, Theorem 4.36), the modified Hasse
diagram (Theorem 4.44), closed V-paths named in errors, a depth-first walk over V-paths (no
recursion: paths of any length) and the Morse boundary on global cell ids (Theorem 4.42).  Shared by
:mod:`.vector_field`, :mod:`.functions`, :mod:`.morse_complex` and :mod:`.reduction`.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ._cells import CellComplex, Simplex
from ._kernels import morse_columns, topological_rank


def vpath_edges(cx: CellComplex, partner: np.ndarray) -> sp.csr_matrix:
    """Digraph on cells: σ → σ' when {σ < τ} ∈ V and σ' ≠ σ is a face of codimension one of τ."""
    ids = np.arange(cx.n)
    up = np.flatnonzero(partner > ids)
    tau = partner[up]
    ptr, idx = cx.D.indptr, cx.D.indices
    lens = ptr[tau + 1] - ptr[tau]
    src = np.repeat(up, lens)
    starts = np.repeat(ptr[tau] - np.concatenate([[0], np.cumsum(lens)[:-1]]), lens)
    dst = idx[starts + np.arange(lens.sum())] if lens.sum() else np.empty(0, np.int64)
    keep = dst != src
    g = sp.csr_matrix((np.ones(keep.sum(), dtype=np.int8), (src[keep], dst[keep])), shape=(cx.n, cx.n))
    g.sort_indices()
    return g


def vpath_ranks(cx: CellComplex, partner: np.ndarray) -> tuple[np.ndarray, sp.csr_matrix]:
    g = vpath_edges(cx, partner)
    return topological_rank(cx.n, g.indptr.astype(np.int64), g.indices.astype(np.int64)), g


def hasse_edges(cx: CellComplex, partner: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Edges (src, dst) of the modified Hasse diagram (Theorem 4.44), one per nonzero of the boundary
    matrix: τ → σ for a face σ of τ, reversed to σ → τ when σ and τ are paired."""
    coo = cx.D.tocoo()
    face, cell = coo.row.astype(np.int64), coo.col.astype(np.int64)
    flip = partner[face] == cell
    return np.where(flip, face, cell), np.where(flip, cell, face)


def closed_vpath(cx: CellComplex, partner: np.ndarray, rank: np.ndarray, g: sp.csr_matrix) -> list[Simplex]:
    alive = rank < 0
    # restricted to cells Kahn could not order, every cell has a predecessor: walk backwards
    gt = g.T.tocsr()
    start = int(np.flatnonzero(alive)[0])
    seen: dict[int, int] = {}
    walk = [start]
    v = start
    while v not in seen:
        seen[v] = len(walk) - 1
        preds = gt.indices[gt.indptr[v] : gt.indptr[v + 1]]
        preds = preds[alive[preds]]
        v = int(preds[0])
        walk.append(v)
    cycle = walk[seen[v] :][::-1]  # forwards, first == last
    out: list[Simplex] = []
    for s in cycle[:-1]:
        out.append(cx.simplex(s))
        out.append(cx.simplex(int(partner[s])))
    out.append(cx.simplex(cycle[-1]))
    return out


def cyclic_field_error(cx: CellComplex, partner: np.ndarray, rank: np.ndarray, g: sp.csr_matrix) -> ValueError:
    """The ValueError raised for a vector field with a closed V-path, naming one such path."""
    path = " > ".join(str(s) for s in closed_vpath(cx, partner, rank, g))
    return ValueError(
        f"the vector field has a non-trivial closed V-path {path}: it is not a gradient (Theorem 4.36)"
    )


def walk(cx: CellComplex, partner: np.ndarray, start: int, m0: int = 1):
    """Depth-first over the V-paths from ``start`` of an acyclic field, without recursion.

    Yields ``(path, m, maximal)`` at every cell reached: ``path`` = [σ_0, τ_0, σ_1, ...] (a list the
    caller copies to keep), ``m`` the multiplicity of Theorem 4.42 (``m0`` times the product of
    ``-<∂τ_i, σ_i><∂τ_i, σ_{i+1}>``) and ``maximal``: the last cell is paired with no coface.
    """
    path, mult = [start], [m0]
    frames: list[list] = []  # [τ, the other faces of τ, next face, index in path of the σ paired with τ]
    while True:
        s = path[-1]
        t = int(partner[s])
        maximal = t <= s
        yield path, mult[-1], maximal
        if not maximal:
            faces = cx.faces_of(t)
            frames.append([t, faces[faces != s], 0, len(path) - 1])
        while frames:
            frame = frames[-1]
            t, faces, i, base = frame
            if i < faces.size:
                frame[2] = i + 1
                s2 = int(faces[i])
                del path[base + 1:], mult[base + 1:]
                m = -mult[base] * cx.incidence(path[base], t) * cx.incidence(s2, t)
                path += [t, s2]
                mult += [0, m]
                break
            frames.pop()
        else:
            return


def morse_boundary_ids(cx: CellComplex, partner: np.ndarray, coefficients: int = 0):
    """Critical global ids per dimension and the Morse boundary matrices between them (Theorem 4.42)."""
    rank = acyclic_ranks(cx, partner)
    is_crit = partner < 0
    crit = np.flatnonzero(is_crit)
    sources = crit[cx.dim_of[crit] >= 1]
    rows, cols, vals, overflow = morse_columns(
        cx.n, cx.D.indptr.astype(np.int64), cx.D.indices.astype(np.int64), cx.D.data.astype(np.int64),
        partner, rank, is_crit, sources, int(coefficients),
    )
    if overflow:
        raise ValueError("Morse boundary coefficients exceed int64 over Z; use a prime p (coefficients=p)")
    local = np.full(cx.n, -1, dtype=np.int64)
    crit_by_dim = []
    for d in range(cx.dimension + 1):
        ids = crit[cx.dim_of[crit] == d]
        local[ids] = np.arange(ids.size)
        crit_by_dim.append(ids)
    mats = [sp.csc_matrix((0, crit_by_dim[0].size), dtype=np.int64)]
    cdim = cx.dim_of[cols] if cols.size else cols
    for d in range(1, cx.dimension + 1):
        m = cdim == d
        mat = sp.csc_matrix(
            (vals[m], (local[rows[m]], local[cols[m]])),
            shape=(crit_by_dim[d - 1].size, crit_by_dim[d].size), dtype=np.int64,
        )
        mat.sort_indices()
        mats.append(mat)
    return crit_by_dim, mats


def acyclic_ranks(cx: CellComplex, partner: np.ndarray) -> np.ndarray:
    """Topological ranks of the V-path digraph; ValueError naming a closed V-path if there is one."""
    rank, g = vpath_ranks(cx, partner)
    if not (rank >= 0).all():
        raise cyclic_field_error(cx, partner, rank, g)
    return rank

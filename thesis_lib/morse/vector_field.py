"""Discrete vector fields, V-paths and acyclicity (thesis §4.2.3 and §4.2.6).

A discrete vector field is given as an iterable of pairs ``(sigma, tau)`` of simplices with
``sigma`` a face of codimension one of ``tau`` (Definition 4.33).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components

from ._cells import CellComplex, Simplex, as_complex, pairs_from_partner, partner_array
from ._kernels import topological_rank

__all__ = [
    "check_vector_field",
    "critical_cells",
    "vpath_graph",
    "is_acyclic",
    "find_closed_vpath",
    "vpaths",
    "gradient_paths",
    "hasse_diagram",
]

Pairs = Iterable[tuple[Sequence[int], Sequence[int]]]


def check_vector_field(simplices, pairs: Pairs) -> list[tuple[Simplex, Simplex]]:
    """Validate a discrete vector field and return its pairs as sorted simplex tuples.

    Thesis: Definition 4.33 (pairs σ^(k) < τ^(k+1), each simplex in at most one pair).

    Raises
    ------
    ValueError
        If a pair is not a face of codimension one, a simplex is not in the complex, or a simplex
        lies in two pairs.
    """
    cx = as_complex(simplices)
    return pairs_from_partner(cx, partner_array(cx, pairs))


def critical_cells(simplices, pairs: Pairs) -> list[list[Simplex]]:
    """Simplices in no pair of the vector field, per dimension.

    Thesis: Proposition 4.32 (3): σ is critical iff σ ∉ im V and V(σ) = 0.
    """
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    out: list[list[Simplex]] = [[] for _ in range(cx.dimension + 1)]
    for g in np.flatnonzero(partner < 0):
        out[int(cx.dim_of[g])].append(cx.simplex(int(g)))
    return out


def _vpath_edges(cx: CellComplex, partner: np.ndarray) -> sp.csr_matrix:
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


def vpath_graph(simplices, pairs: Pairs) -> tuple[list[Simplex], sp.csr_matrix]:
    """The V-path digraph: an edge σ → σ' for each step σ < τ > σ' of a V-path.

    Thesis: Definition 4.34 (V-paths σ_0, τ_0, σ_1, ... with {σ_i < τ_i} ∈ V, σ_{i+1} ≠ σ_i).

    Returns the cells (global order: by dimension, then lexicographic) and the adjacency matrix.
    """
    cx = as_complex(simplices)
    return cx.simplices(), _vpath_edges(cx, partner_array(cx, pairs))


def _ranks(cx: CellComplex, partner: np.ndarray) -> tuple[np.ndarray, sp.csr_matrix]:
    g = _vpath_edges(cx, partner)
    return topological_rank(cx.n, g.indptr.astype(np.int64), g.indices.astype(np.int64)), g


def _hasse_edges(cx: CellComplex, partner: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Edges (src, dst) of the modified Hasse diagram (Theorem 4.44), one per nonzero of the boundary
    matrix: τ → σ for a face σ of τ, reversed to σ → τ when σ and τ are paired."""
    coo = cx.D.tocoo()
    face, cell = coo.row.astype(np.int64), coo.col.astype(np.int64)
    flip = partner[face] == cell
    return np.where(flip, face, cell), np.where(flip, cell, face)


def hasse_diagram(simplices, pairs: Pairs = ()) -> tuple[list[Simplex], sp.csr_matrix]:
    """The (modified) Hasse diagram: edge τ → σ for every face σ < τ of codimension one, reversed
    to σ → τ for the pairs of the vector field.

    Thesis: §4.2.6, Theorem 4.44 (Figures 4.7–4.8).
    """
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    src, dst = _hasse_edges(cx, partner)
    g = sp.csr_matrix((np.ones(src.size, dtype=np.int8), (src, dst)), shape=(cx.n, cx.n))
    return cx.simplices(), g


def is_acyclic(simplices, pairs: Pairs, method: str = "vpaths") -> bool:
    """True when the vector field has no non-trivial closed V-path.

    Thesis: Theorem 4.36 (then V is the gradient of a discrete Morse function) and Theorem 4.44.

    ``method="vpaths"`` topologically sorts the V-path digraph; ``method="hasse"`` looks for a
    strongly connected component with more than one cell in the modified Hasse diagram.
    """
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    if method == "vpaths":
        rank, _ = _ranks(cx, partner)
        return bool((rank >= 0).all())
    if method == "hasse":
        _, g = hasse_diagram(cx, pairs_from_partner(cx, partner))
        ncomp, labels = connected_components(g, directed=True, connection="strong")
        return ncomp == cx.n
    raise ValueError(f"method must be 'vpaths' or 'hasse', got {method!r}")


def _closed_vpath(cx: CellComplex, partner: np.ndarray, rank: np.ndarray, g: sp.csr_matrix) -> list[Simplex]:
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


def _cyclic_field_error(cx: CellComplex, partner: np.ndarray, rank: np.ndarray, g: sp.csr_matrix) -> ValueError:
    """The ValueError raised for a vector field with a closed V-path, naming one such path."""
    path = " > ".join(str(s) for s in _closed_vpath(cx, partner, rank, g))
    return ValueError(
        f"the vector field has a non-trivial closed V-path {path}: it is not a gradient (Theorem 4.36)"
    )


def find_closed_vpath(simplices, pairs: Pairs) -> list[Simplex] | None:
    """A non-trivial closed V-path σ_0, τ_0, σ_1, ..., τ_r, σ_0 if one exists, else ``None``.

    Thesis: Definition 4.34 (non-trivial closed V-path), Theorem 4.36.
    """
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    rank, g = _ranks(cx, partner)
    if (rank >= 0).all():
        return None
    return _closed_vpath(cx, partner, rank, g)


def vpaths(simplices, pairs: Pairs, start: Sequence[int], max_paths: int = 100_000) -> list[list[Simplex]]:
    """All maximal V-paths σ_0 = start, τ_0, σ_1, ..., σ_{r+1} (σ_{r+1} in no pair upwards).

    Thesis: Definition 4.34.  The trivial path ``[start]`` is returned when ``start`` is not paired
    with a coface.  Raises ValueError on a cyclic field (infinitely many paths) or when more than
    ``max_paths`` paths exist.
    """
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    rank, g = _ranks(cx, partner)
    if not (rank >= 0).all():
        raise _cyclic_field_error(cx, partner, rank, g)
    s0 = int(cx.ids([tuple(start)], "start simplex")[0])
    paths: list[list[int]] = []

    def extend(path: list[int]) -> None:
        s = path[-1]
        t = int(partner[s])
        if t <= s:  # not paired upwards
            paths.append(path)
            if len(paths) > max_paths:
                raise ValueError(f"more than {max_paths} V-paths start at {tuple(start)}")
            return
        for s2 in cx.faces_of(t):
            if s2 != s:
                extend(path + [t, int(s2)])

    extend([s0])
    return [[cx.simplex(c) for c in p] for p in paths]


def gradient_paths(simplices, pairs: Pairs, tau: Sequence[int], sigma: Sequence[int]) -> list[tuple[list[Simplex], int]]:
    """Gradient paths from a maximal face of ``tau`` to ``sigma`` with their multiplicities ±1.

    Thesis: Theorem 4.42 (Γ(τ, σ) and m(γ); orientation of τ induced along the path, Figure 4.5).

    Each entry is ``(path, m)`` where ``path = [tau, σ_0, τ_0, σ_1, ..., sigma]`` and
    m = <∂τ, σ_0> Π_i (-<∂τ_i, σ_i><∂τ_i, σ_{i+1}>).  Meant for small examples (enumerates paths).
    """
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    t0, s_end = (int(x) for x in cx.ids([tuple(tau), tuple(sigma)]))
    if cx.dim_of[t0] != cx.dim_of[s_end] + 1:
        raise ValueError("tau must have dimension one more than sigma")
    rank, g = _ranks(cx, partner)
    if not (rank >= 0).all():
        raise _cyclic_field_error(cx, partner, rank, g)
    out: list[tuple[list[Simplex], int]] = []

    def extend(path: list[int], m: int) -> None:
        s = path[-1]
        if s == s_end:
            out.append(([cx.simplex(c) for c in path], m))
        t = int(partner[s])
        if t <= s:
            return
        a = cx.incidence(s, t)
        for s2 in cx.faces_of(t):
            s2 = int(s2)
            if s2 != s:
                extend(path + [t, s2], -m * a * cx.incidence(s2, t))

    for s0 in cx.faces_of(t0):
        s0 = int(s0)
        if partner[s0] != t0:
            extend([t0, s0], cx.incidence(s0, t0))
    return out

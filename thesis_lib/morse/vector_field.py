"""Discrete vector fields, V-paths and acyclicity (thesis §4.2.3 and §4.2.6).

A discrete vector field is given as an iterable of pairs ``(sigma, tau)`` of simplices with
``sigma`` a face of codimension one of ``tau`` (Definition 4.33).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components

from ._cells import ComplexLike, Pairs, Simplex, cell_complex, pairs_from_partner, partner_array
from ._gradient import acyclic_ranks, closed_vpath, hasse_edges, vpath_edges, vpath_ranks, walk

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


def check_vector_field(simplices: ComplexLike, pairs: Pairs) -> list[tuple[Simplex, Simplex]]:
    """Validate a discrete vector field and return its pairs as sorted simplex tuples.

    Thesis: Definition 4.33 (pairs σ^(k) < τ^(k+1), each simplex in at most one pair).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        The complex, in any form :func:`~thesis_lib.homology.filtration.as_complex` accepts: all faces are
        added and a Filtration's values are ignored (so in every function of this module).
    pairs : iterable of (sigma, tau)
        The vector field: sigma a face of codimension one of tau, each simplex in at most one pair.

    Returns
    -------
    list of (tuple, tuple)
        The pairs ``(sigma, tau)`` with ascending vertices, ordered by sigma (dimension, then
        lexicographically).

    Raises
    ------
    ValueError
        If a pair is not a face of codimension one, a simplex is not in the complex, or a simplex
        lies in two pairs.

    Examples
    --------
    Pairs come back with sorted vertices, ordered by sigma:

    >>> check_vector_field([(0, 1), (0, 2), (1, 2)], [((2,), (2, 1)), ((1,), (1, 0))])
    [((1,), (0, 1)), ((2,), (1, 2))]
    """
    cx = cell_complex(simplices)
    return pairs_from_partner(cx, partner_array(cx, pairs))


def critical_cells(simplices: ComplexLike, pairs: Pairs) -> list[list[Simplex]]:
    """Simplices in no pair of the vector field, per dimension.

    Thesis: Proposition 4.32 (3): σ is critical iff σ ∉ im V and V(σ) = 0.

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and a vector field on it (as in :func:`check_vector_field`); the simplices
        in no pair are the critical ones.

    Returns
    -------
    list of list of tuple
        ``out[k]`` lists the critical k-simplices, lexicographically, for k = 0..dim K.

    Examples
    --------
    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> critical_cells(circle, pairs)
    [[(0,)], [(0, 2)]]
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    out: list[list[Simplex]] = [[] for _ in range(cx.dimension + 1)]
    for g in np.flatnonzero(partner < 0):
        out[int(cx.dim_of[g])].append(cx.simplex(int(g)))
    return out


def vpath_graph(simplices: ComplexLike, pairs: Pairs) -> tuple[list[Simplex], sp.csr_matrix]:
    """The V-path digraph: an edge σ → σ' for each step σ < τ > σ' of a V-path.

    Thesis: Definition 4.34 (V-paths σ_0, τ_0, σ_1, ... with {σ_i < τ_i} ∈ V, σ_{i+1} ≠ σ_i).

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex, whose cells are the nodes of the digraph, and the vector field, whose
        pairs give its edges (as in :func:`check_vector_field`).

    Returns
    -------
    cells : list of tuple
        All simplices in the global order: by dimension, then lexicographically.
    graph : scipy.sparse.csr_matrix, shape (n, n)
        The int8 adjacency matrix: ``graph[i, j] = 1`` for an edge ``cells[i] → cells[j]``.

    Examples
    --------
    The V-path steps on the circle: 1 → 0 (through 01) and 2 → 1 (through 12):

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> cells, graph = vpath_graph(circle, pairs)
    >>> [(cells[i], cells[j]) for i, j in zip(*graph.nonzero())]
    [((1,), (0,)), ((2,), (1,))]
    """
    cx = cell_complex(simplices)
    return cx.simplices(), vpath_edges(cx, partner_array(cx, pairs))


def hasse_diagram(simplices: ComplexLike, pairs: Pairs = ()) -> tuple[list[Simplex], sp.csr_matrix]:
    """The (modified) Hasse diagram: edge τ → σ for every face σ < τ of codimension one, reversed
    to σ → τ for the pairs of the vector field.

    Thesis: §4.2.6, Theorem 4.44 (Figures 4.7–4.8).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        The complex whose face relation gives the edges (as in :func:`check_vector_field`).
    pairs : iterable of (sigma, tau), default ()
        The pairs whose edges are reversed; empty gives the plain Hasse diagram.

    Returns
    -------
    cells, graph : list of tuple, scipy.sparse.csr_matrix
        As in :func:`vpath_graph`: the simplices in the global order and the (n × n) int8
        adjacency matrix, here of the modified Hasse diagram.

    Examples
    --------
    The edges of the modified Hasse diagram of the circle: each edge points to its vertices, except
    the paired ones, reversed (1 → 01, 2 → 12):

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> cells, graph = hasse_diagram(circle, pairs)
    >>> sorted((cells[i], cells[j]) for i, j in zip(*graph.nonzero()))
    [((0, 1), (0,)), ((0, 2), (0,)), ((0, 2), (2,)), ((1,), (0, 1)), ((1, 2), (1,)), ((2,), (1, 2))]
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    src, dst = hasse_edges(cx, partner)
    g = sp.csr_matrix((np.ones(src.size, dtype=np.int8), (src, dst)), shape=(cx.n, cx.n))
    return cx.simplices(), g


def is_acyclic(simplices: ComplexLike, pairs: Pairs, *, method: str = "vpaths") -> bool:
    """True when the vector field has no non-trivial closed V-path.

    Thesis: Theorem 4.36 (then V is the gradient of a discrete Morse function) and Theorem 4.44.

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The vector field to test, on its complex (as in :func:`check_vector_field`).
    method : {"vpaths", "hasse"}, default "vpaths"
        ``"vpaths"`` topologically sorts the V-path digraph; ``"hasse"`` looks for a strongly
        connected component with more than one cell in the modified Hasse diagram.

    Returns
    -------
    bool
        Whether the field is acyclic (both methods agree).

    Raises
    ------
    ValueError
        An invalid vector field or an unknown ``method``.

    Examples
    --------
    Pairing each vertex with the next edge round the circle makes a closed V-path:

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> cyclic = [((0,), (0, 1)), ((1,), (1, 2)), ((2,), (0, 2))]
    >>> is_acyclic(circle, pairs), is_acyclic(circle, cyclic)
    (True, False)
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    if method == "vpaths":
        rank, _ = vpath_ranks(cx, partner)
        return bool((rank >= 0).all())
    if method == "hasse":
        _, g = hasse_diagram(cx, pairs_from_partner(cx, partner))
        ncomp, labels = connected_components(g, directed=True, connection="strong")
        return ncomp == cx.n
    raise ValueError(f"method must be 'vpaths' or 'hasse', got {method!r}")


def find_closed_vpath(simplices: ComplexLike, pairs: Pairs) -> list[Simplex] | None:
    """A non-trivial closed V-path σ_0, τ_0, σ_1, ..., τ_r, σ_0 if one exists, else ``None``.

    Thesis: Definition 4.34 (non-trivial closed V-path), Theorem 4.36.

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and the vector field searched for a closed V-path (as in
        :func:`check_vector_field`).

    Returns
    -------
    list of tuple or None
        The simplices of one closed V-path, alternating k- and (k+1)-simplices and ending where it
        starts; None when the field is acyclic.

    Examples
    --------
    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> cyclic = [((0,), (0, 1)), ((1,), (1, 2)), ((2,), (0, 2))]
    >>> find_closed_vpath(circle, cyclic)
    [(0,), (0, 1), (1,), (1, 2), (2,), (0, 2), (0,)]
    >>> find_closed_vpath(circle, cyclic[:2]) is None
    True
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    rank, g = vpath_ranks(cx, partner)
    if (rank >= 0).all():
        return None
    return closed_vpath(cx, partner, rank, g)


def vpaths(simplices: ComplexLike, pairs: Pairs, start: Sequence[int],
           *, max_paths: int = 100_000) -> list[list[Simplex]]:
    """All maximal V-paths σ_0 = start, τ_0, σ_1, ..., σ_{r+1} (σ_{r+1} in no pair upwards).

    Thesis: Definition 4.34.

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and an acyclic vector field on it (as in :func:`check_vector_field`).
    start : sequence of int
        The first simplex σ_0 of every path; must be in the complex.
    max_paths : int, default 100_000
        Refuse (ValueError) when more paths than this start at ``start``.

    Returns
    -------
    list of list of tuple
        Each path as its simplices σ_0, τ_0, σ_1, ...; the trivial path ``[start]`` when ``start``
        is not paired with a coface.  Paths of any length (no recursion).

    Raises
    ------
    ValueError
        A cyclic field (infinitely many paths), ``start`` not in the complex, or more than
        ``max_paths`` paths.

    Examples
    --------
    From the vertex 2 the field of the circle flows down to the critical vertex 0:

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> vpaths(circle, pairs, (2,))
    [[(2,), (1, 2), (1,), (0, 1), (0,)]]
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    acyclic_ranks(cx, partner)
    s0 = int(cx.ids([tuple(start)], "start simplex")[0])
    paths: list[list[Simplex]] = []
    for path, _, maximal in walk(cx, partner, s0):
        if maximal:
            if len(paths) == max_paths:
                raise ValueError(f"more than {max_paths} V-paths start at {tuple(start)}")
            paths.append([cx.simplex(c) for c in path])
    return paths


def gradient_paths(simplices: ComplexLike, pairs: Pairs, tau: Sequence[int],
                   sigma: Sequence[int]) -> list[tuple[list[Simplex], int]]:
    """Gradient paths from a maximal face of ``tau`` to ``sigma`` with their multiplicities ±1.

    Thesis: Theorem 4.42 (Γ(τ, σ) and m(γ); orientation of τ induced along the path, Figure 4.5).

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and the acyclic vector field whose gradient paths are enumerated (as in
        :func:`check_vector_field`).
    tau : sequence of int
        A (k+1)-simplex of the complex, where the paths start (through a facet not paired with it).
    sigma : sequence of int
        A k-simplex of the complex, where the paths end.

    Returns
    -------
    list of (list of tuple, int)
        Each entry is ``(path, m)`` where ``path = [tau, σ_0, τ_0, σ_1, ..., sigma]`` and
        m = <∂τ, σ_0> Π_i (-<∂τ_i, σ_i><∂τ_i, σ_{i+1}>).  Meant for small examples (enumerates
        paths).

    Raises
    ------
    ValueError
        A cyclic field, a simplex not in the complex, or ``tau`` not one dimension above ``sigma``.

    Examples
    --------
    Two gradient paths run from the critical edge 02 to the critical vertex 0, with opposite signs: the
    Morse boundary of 02 is 0, so H_1 of the circle is Z:

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> gradient_paths(circle, pairs, (0, 2), (0,))
    [([(0, 2), (0,)], -1), ([(0, 2), (2,), (1, 2), (1,), (0, 1), (0,)], 1)]
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    t0, s_end = (int(x) for x in cx.ids([tuple(tau), tuple(sigma)]))
    if cx.dim_of[t0] != cx.dim_of[s_end] + 1:
        raise ValueError("tau must have dimension one more than sigma")
    acyclic_ranks(cx, partner)
    out: list[tuple[list[Simplex], int]] = []
    for s0 in cx.faces_of(t0):
        s0 = int(s0)
        if partner[s0] == t0:
            continue
        for path, m, _ in walk(cx, partner, s0, cx.incidence(s0, t0)):
            if path[-1] == s_end:
                out.append(([cx.simplex(t0)] + [cx.simplex(c) for c in path], m))
    return out

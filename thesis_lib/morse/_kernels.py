"""Internal kernels: topological order, greedy matchings (and their driver) and gradient-path propagation.

Thin casts around the compiled C++ module ``thesis_lib._core.discrete_gradient`` (``src/discrete_gradient.cpp``);
thesis chapter 4 (discrete Morse theory).
"""

from __future__ import annotations

import numpy as np

from .._core import discrete_gradient


def topological_rank(n: int, ptr: np.ndarray, idx: np.ndarray) -> np.ndarray:
    """Kahn's algorithm on the digraph (CSR ``ptr``/``idx``); rank[v] = position, -1 if on/after a cycle.

    Thesis: Theorem 4.36 (acyclic V-paths); compiled in ``src/discrete_gradient.cpp``.
    """
    return discrete_gradient.topological_rank(int(n), np.ascontiguousarray(ptr, dtype=np.int64),
                                              np.ascontiguousarray(idx, dtype=np.int64))


def greedy_matching(n: int, down_ptr: np.ndarray, down_idx: np.ndarray, up_ptr: np.ndarray, up_idx: np.ndarray,
                    vals: np.ndarray, order: np.ndarray) -> np.ndarray:
    """Greedy coreduction (down = faces) or collapse (down = cofaces) restricted to equal ``vals``.

    A cell whose single remaining ``down`` neighbour (of equal value) is σ is paired with σ and both
    are removed; when there is no such cell, the first remaining cell of ``order`` is made critical.
    Returns ``partner`` (-1 for critical cells).  Thesis: §4.3; compiled in ``src/discrete_gradient.cpp``.
    """
    i64 = np.int64
    return discrete_gradient.greedy_matching(
        int(n), np.ascontiguousarray(down_ptr, dtype=i64), np.ascontiguousarray(down_idx, dtype=i64),
        np.ascontiguousarray(up_ptr, dtype=i64), np.ascontiguousarray(up_idx, dtype=i64),
        np.ascontiguousarray(vals, dtype=np.float64), np.ascontiguousarray(order, dtype=i64))


def morse_columns(n: int, ptr: np.ndarray, idx: np.ndarray, data: np.ndarray, partner: np.ndarray, rank: np.ndarray,
                  is_crit: np.ndarray, sources: np.ndarray, p: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    """Theorem 4.42 for every critical cell in ``sources``: flow ∂τ along gradient paths.

    Up-paired k-cells are eliminated in topological order of the V-path graph; the coefficients
    left on critical cells are the sums of multiplicities ±1 over gradient paths (mod p if p > 0).
    Returns COO triples (rows, cols, vals) in global ids and an overflow flag (|entry| > 2^60 over Z).
    Compiled in ``src/discrete_gradient.cpp``.
    """
    i64 = np.int64
    return discrete_gradient.morse_columns(
        int(n), np.ascontiguousarray(ptr, dtype=i64), np.ascontiguousarray(idx, dtype=i64),
        np.ascontiguousarray(data, dtype=i64),
        discrete_gradient.Gradient(np.ascontiguousarray(partner, dtype=i64), np.ascontiguousarray(rank, dtype=i64),
                                   np.ascontiguousarray(is_crit, dtype=np.bool_)),
        np.ascontiguousarray(sources, dtype=i64), int(p))


def greedy_partner(cx, method: str, vals: np.ndarray | None = None, seed: int | None = None) -> np.ndarray:
    """Partners of the greedy ``"coreduction"`` or ``"collapse"`` matching on a CellComplex (see
    :func:`greedy_matching`), restricted to equal ``vals``; ``seed`` breaks ties at random."""
    faces = cx.D  # CSC: column g lists the faces of g
    cofaces = cx.cofaces  # CSR: row g lists the cofaces of g
    fptr, fidx = faces.indptr.astype(np.int64), faces.indices.astype(np.int64)
    cptr, cidx = cofaces.indptr.astype(np.int64), cofaces.indices.astype(np.int64)
    tie = np.arange(cx.n) if seed is None else np.random.default_rng(seed).permutation(cx.n)
    v = np.zeros(cx.n) if vals is None else np.asarray(vals, dtype=np.float64)
    if method == "coreduction":
        order = np.lexsort((tie, cx.dim_of)).astype(np.int64)  # lowest dimension first
        return greedy_matching(cx.n, fptr, fidx, cptr, cidx, v, order)
    order = np.lexsort((tie, -cx.dim_of)).astype(np.int64)  # top dimension first
    return greedy_matching(cx.n, cptr, cidx, fptr, fidx, v, order)

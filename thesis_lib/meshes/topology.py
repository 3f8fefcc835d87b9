"""Combinatorial checks of triangulated (hyper)surfaces: Euler characteristic, manifold edges."""

from __future__ import annotations

import itertools

import numpy as np

__all__ = ["faces_of", "euler_characteristic", "facet_degrees", "is_closed_pseudomanifold"]


def _simplices(simplices) -> np.ndarray:
    s = np.asarray(simplices)
    if s.ndim != 2 or s.shape[1] < 1 or s.shape[0] == 0:
        raise ValueError(f"simplices must be a non-empty (m, k) integer array, got shape {s.shape}")
    if not np.issubdtype(s.dtype, np.integer):
        raise ValueError("simplices must hold integer vertex indices")
    if s.min() < 0:
        raise ValueError("simplices hold negative vertex indices")
    return s


def faces_of(simplices, k: int) -> np.ndarray:
    """All distinct k-faces (k + 1 sorted vertices each) of the given simplices.

    Thesis: Definition 2.1 (faces of a simplex).
    """
    s = np.sort(_simplices(simplices), axis=1)
    if not 0 <= k < s.shape[1]:
        raise ValueError(f"k must be in [0, {s.shape[1] - 1}], got {k}")
    combos = list(itertools.combinations(range(s.shape[1]), k + 1))
    f = np.concatenate([s[:, c] for c in combos])
    return np.unique(f, axis=0)


def euler_characteristic(simplices) -> int:
    """χ = Σ_k (-1)^k #k-faces of the complex spanned by ``simplices`` (V - E + F for a surface).

    Thesis: Theorem 3.8 (χ in Gauss–Bonnet).
    """
    s = _simplices(simplices)
    return int(sum((-1) ** k * len(faces_of(s, k)) for k in range(s.shape[1])))


def facet_degrees(simplices) -> np.ndarray:
    """For each distinct (n-1)-face of the n-simplices, the number of n-simplices containing it.

    Thesis: §3.1.2 (every edge of a closed triangulated surface lies in exactly two triangles).
    """
    s = np.sort(_simplices(simplices), axis=1)
    n1 = s.shape[1]
    f = np.concatenate([np.delete(s, i, axis=1) for i in range(n1)])
    _, counts = np.unique(f, axis=0, return_counts=True)
    return counts


def is_closed_pseudomanifold(simplices) -> bool:
    """True when every (n-1)-face lies in exactly two of the n-simplices.

    Thesis: §3.1.2 (proof of Theorem 3.8: each edge belongs to exactly two triangles).
    """
    return bool(np.all(facet_degrees(simplices) == 2))

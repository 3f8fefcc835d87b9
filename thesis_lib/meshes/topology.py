"""Combinatorial checks of triangulated (hyper)surfaces: Euler characteristic, manifold edges."""

from __future__ import annotations

import itertools

import numpy as np
import numpy.typing as npt

from .._validate import check_int, check_simplices

__all__ = ["faces_of", "euler_characteristic", "facet_degrees", "is_closed_pseudomanifold"]


def _simplices(simplices) -> np.ndarray:
    return check_simplices(simplices)


def faces_of(simplices: npt.ArrayLike, *, k: int) -> np.ndarray:
    """All distinct k-faces (k + 1 sorted vertices each) of the given simplices.

    Thesis: Definition 2.1 (faces of a simplex).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        Vertex indices of the simplices (checked).
    k : int
        Face dimension, 0 <= k <= n.

    Returns
    -------
    ndarray, shape (f, k + 1)
        The distinct faces, rows ascending, in lexicographic order.
    """
    s = np.sort(_simplices(simplices), axis=1)
    k = check_int(k, "k", minimum=0, maximum=s.shape[1] - 1)
    combos = list(itertools.combinations(range(s.shape[1]), k + 1))
    f = np.concatenate([s[:, c] for c in combos])
    return np.unique(f, axis=0)


def euler_characteristic(simplices: npt.ArrayLike) -> int:
    """χ = Σ_k (-1)^k #k-faces of the complex spanned by ``simplices`` (V - E + F for a surface).

    Thesis: Theorem 3.8 (χ in Gauss–Bonnet).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        Vertex indices of the top simplices; the complex is all their faces.

    Returns
    -------
    int
        χ of that complex.
    """
    s = _simplices(simplices)
    return int(sum((-1) ** k * len(faces_of(s, k=k)) for k in range(s.shape[1])))


def facet_degrees(simplices: npt.ArrayLike) -> np.ndarray:
    """For each distinct (n-1)-face of the n-simplices, the number of n-simplices containing it.

    Thesis: §3.1.2 (every edge of a closed triangulated surface lies in exactly two triangles).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        The n-simplices' vertex indices, n >= 1 (checked).

    Returns
    -------
    ndarray of int
        One count per distinct (n - 1)-face, in lexicographic order of the faces.
    """
    s = np.sort(_simplices(simplices), axis=1)
    n1 = s.shape[1]
    if n1 < 2:
        raise ValueError("facet degrees need simplices of dimension >= 1")
    f = np.concatenate([np.delete(s, i, axis=1) for i in range(n1)])
    _, counts = np.unique(f, axis=0, return_counts=True)
    return counts


def is_closed_pseudomanifold(simplices: npt.ArrayLike) -> bool:
    """True when every (n-1)-face lies in exactly two of the n-simplices.

    Thesis: §3.1.2 (proof of Theorem 3.8: each edge belongs to exactly two triangles).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        Vertex indices of the n-simplices, n >= 1, as in :func:`facet_degrees`.

    Returns
    -------
    bool
        Whether every facet degree is 2 (orientation and vertex links are not checked).
    """
    return bool(np.all(facet_degrees(simplices) == 2))

"""Simplices as integer arrays: validation, closure, facet lookup and signed boundary matrices.

A set of ``k``-simplices is stored as an ``(m, k + 1)`` array of vertex indices, each row in
ascending order (the convention of DESIGN.md).  Everything in ``thesis_lib`` that needs faces,
boundaries or orientations goes through this module.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

import numpy as np

from .._validate import vertex_label

if TYPE_CHECKING:  # scipy.sparse loads when a boundary matrix is first built
    import scipy.sparse as sp

__all__ = [
    "as_simplex_array",
    "group_by_dimension",
    "closure",
    "facets",
    "row_keys",
    "find_rows",
    "boundary_matrix",
]


def as_simplex_array(rows: np.ndarray | Sequence[Sequence[int]], *, dim: int | None = None) -> np.ndarray:
    """Return ``rows`` as an ``(m, dim + 1)`` int64 array with every row sorted ascending.

    Thesis: Definition 2.1 (a p-simplex has p + 1 distinct vertices).

    Parameters
    ----------
    rows : array_like, shape (m, k + 1)
        Vertex indices, one simplex per row, in any order within a row; an empty sequence gives an
        empty array.
    dim : int, optional
        The dimension every row must have (``k``); ``None`` accepts any width.

    Returns
    -------
    numpy.ndarray of int64, shape (m, k + 1)
        The rows, each sorted ascending (a new array unless ``rows`` already was sorted int64).

    Raises
    ------
    ValueError
        If the rows are ragged, negative, not integral or have a repeated vertex.
    """
    arr = np.asarray(rows)
    if arr.ndim == 1 and arr.size == 0:
        width = 0 if dim is None else dim + 1
        return np.empty((0, width), dtype=np.int64)
    if arr.ndim != 2:
        raise ValueError(f"simplices must form a 2-D array of vertex indices, got shape {arr.shape}")
    if dim is not None and arr.shape[1] != dim + 1:
        raise ValueError(f"{dim}-simplices need {dim + 1} vertices each, got rows of length {arr.shape[1]}")
    if arr.size and not np.issubdtype(arr.dtype, np.integer):
        if not np.all(np.isfinite(arr)) or not np.all(arr == np.round(arr)):
            raise ValueError("vertex indices must be integers")
        if np.abs(arr).max() >= 2.0**63:
            raise ValueError(f"vertex label {np.abs(arr).max():g} does not fit in int64 (labels must be < 2^63)")
    arr = np.sort(arr.astype(np.int64, copy=False), axis=1)
    if arr.size and arr.min() < 0:
        raise ValueError("vertex indices must be non-negative")
    if arr.shape[1] > 1 and arr.shape[0]:
        repeated = np.any(arr[:, 1:] == arr[:, :-1], axis=1)
        if repeated.any():
            bad = tuple(int(v) for v in arr[np.argmax(repeated)])
            raise ValueError(f"simplex {bad} has a repeated vertex")
    return arr


def group_by_dimension(simplices: Iterable[Sequence[int]]) -> list[np.ndarray]:
    """Split an iterable of simplices of mixed dimension into one sorted-row array per dimension.

    Thesis: Definition 2.4 (abstract simplicial complex as a collection of vertex sets).

    Parameters
    ----------
    simplices : iterable of sequences of int
        Vertex tuples of any dimensions (non-negative integer labels, no empty simplex).

    Returns
    -------
    list of numpy.ndarray
        Entry ``d`` is an ``(m_d, d + 1)`` int64 array of the given ``d``-simplices, rows sorted
        ascending, in input order (empty where no simplex has that dimension); ``[]`` for no input.
        Duplicates are kept; see :func:`closure` for the complex they generate.

    Raises
    ------
    ValueError
        For an empty simplex, a vertex that is not a non-negative integer or a repeated vertex.
    """
    by_dim: dict[int, list[tuple[int, ...]]] = {}
    for s in simplices:
        t = tuple(vertex_label(v) for v in s)
        if not t:
            raise ValueError("the empty simplex is not allowed")
        by_dim.setdefault(len(t) - 1, []).append(t)
    if not by_dim:
        return []
    top = max(by_dim)
    return [as_simplex_array(by_dim.get(d, np.empty((0, d + 1), np.int64)), dim=d) for d in range(top + 1)]


def facets(arr: np.ndarray) -> np.ndarray:
    """Facets of each ``k``-simplex: array ``(m, k + 1, k)``; facet ``i`` omits vertex ``i``.

    Thesis: Definition 2.18 (the i-th term of the boundary omits x_i).

    Parameters
    ----------
    arr : numpy.ndarray, shape (m, k + 1)
        ``k``-simplices as sorted rows.

    Returns
    -------
    numpy.ndarray, shape (m, k + 1, k)
        ``out[r, i]`` is simplex ``r`` without its vertex ``i`` (rows stay sorted).
    """
    k1 = arr.shape[1]
    idx = np.array([[j for j in range(k1) if j != i] for i in range(k1)], dtype=np.int64).reshape(k1, k1 - 1)
    return arr[:, idx]


def row_keys(arr: np.ndarray, base: int) -> np.ndarray | None:
    """Encode sorted rows as int64 keys ``sum v_j base^(k-j)``; ``None`` if that could overflow.

    Parameters
    ----------
    arr : numpy.ndarray, shape (m, k)
        Integer rows with entries in ``[0, base)``.
    base : int
        One more than the largest entry.

    Returns
    -------
    numpy.ndarray of int64, shape (m,), or None
        One key per row (equal rows, equal keys; the order of keys is the lexicographic order of the
        rows), or ``None`` when ``k == 0`` or ``base ** k >= 2**62``.
    """
    width = arr.shape[1]
    if width == 0 or base ** width >= 2**62:
        return None
    keys = np.zeros(arr.shape[0], dtype=np.int64)
    for j in range(width):
        keys = keys * base + arr[:, j]
    return keys


def _void_view(arr: np.ndarray) -> np.ndarray:
    arr = np.ascontiguousarray(arr, dtype=np.int64)
    return arr.view(np.dtype((np.void, arr.dtype.itemsize * arr.shape[1]))).ravel()


def find_rows(haystack: np.ndarray, needles: np.ndarray, *, missing: str = "raise") -> np.ndarray:
    """Index in ``haystack`` of every row of ``needles`` (rows are sorted simplices).

    Thesis: Definition 2.3 (every face of a simplex of K is in K).

    Parameters
    ----------
    haystack : numpy.ndarray, shape (m, k)
        Integer rows, no duplicate rows.
    needles : numpy.ndarray, shape (n, k)
        Integer rows to look up.
    missing : {"raise", "mark"}
        ``"raise"``: a ValueError naming the first missing row; any other value: index -1 for it.

    Returns
    -------
    numpy.ndarray of int64, shape (n,)
        ``haystack[out[i]]`` equals ``needles[i]`` (or ``out[i] == -1`` for a missing row).

    Raises
    ------
    ValueError
        If ``missing == "raise"`` and a row of ``needles`` is not in ``haystack``.
    """
    if needles.shape[0] == 0:
        return np.empty(0, dtype=np.int64)
    if haystack.shape[0] == 0:
        if missing == "raise":
            raise ValueError(f"face {tuple(int(v) for v in needles[0])} is missing from the complex")
        return np.full(needles.shape[0], -1, dtype=np.int64)
    base = int(max(haystack.max(), needles.max())) + 1
    hk = row_keys(haystack, base)
    if hk is not None:
        nk = row_keys(needles, base)
    else:
        hk, nk = _void_view(haystack), _void_view(needles)
    order = np.argsort(hk, kind="stable")
    sorted_keys = hk[order]
    pos = np.searchsorted(sorted_keys, nk)
    pos_clipped = np.minimum(pos, len(sorted_keys) - 1)
    found = sorted_keys[pos_clipped] == nk
    out = np.where(found, order[pos_clipped], -1)
    if missing == "raise" and not found.all():
        bad = tuple(int(v) for v in needles[np.argmin(found)])
        raise ValueError(f"face {bad} is missing from the complex")
    return out


def _unique_rows(arr: np.ndarray) -> np.ndarray:
    if arr.shape[0] == 0:
        return arr
    keys = row_keys(arr, int(arr.max()) + 1)  # 1-D keys sort much faster than np.unique(axis=0)
    if keys is None:
        return np.unique(arr, axis=0)
    _, first = np.unique(keys, return_index=True)
    return arr[first]


def closure(simplices: Iterable[Sequence[int]] | list[np.ndarray]) -> list[np.ndarray]:
    """All faces of the given simplices: one lexicographically sorted, duplicate-free array per dimension.

    Thesis: Definition 2.3 / 2.4 (a complex contains every face of its simplices).

    Parameters
    ----------
    simplices : iterable of sequences of int, or list of numpy.ndarray
        Either vertex tuples of any dimensions, or a list of per-dimension arrays (entry ``d`` of
        shape ``(m_d, d + 1)``, as produced by :func:`group_by_dimension`).

    Returns
    -------
    list of numpy.ndarray
        Entry ``d`` is the ``(n_d, d + 1)`` int64 array of all ``d``-simplices of the complex they
        generate, rows sorted ascending, lexicographically sorted, without duplicates.

    Raises
    ------
    ValueError
        If there are no simplices, or a simplex is not valid (see :func:`as_simplex_array`).
    """
    if isinstance(simplices, list) and simplices and all(isinstance(a, np.ndarray) and a.ndim == 2 for a in simplices):
        groups = [as_simplex_array(a, dim=d) for d, a in enumerate(simplices)]
    else:
        groups = group_by_dimension(simplices)
    if not groups:
        raise ValueError("the complex is empty")
    out: list[np.ndarray] = [None] * len(groups)  # type: ignore[list-item]
    carry = np.empty((0, len(groups)), dtype=np.int64)
    for d in range(len(groups) - 1, -1, -1):
        rows = np.vstack([groups[d], carry]) if carry.shape[0] else groups[d]
        out[d] = _unique_rows(rows)
        if d > 0:
            carry = facets(out[d]).reshape(-1, d)
    return out


def boundary_matrix(lower: np.ndarray, upper: np.ndarray, *, coefficients: int = 0) -> sp.csc_matrix:
    """Signed boundary matrix of ``upper`` (k-simplices) in the basis ``lower`` ((k-1)-simplices).

    Thesis: Definition 2.18, ∂[x_0, ..., x_p] = Σ_i (-1)^i [x_0, ..., x̂_i, ..., x_p].

    Parameters
    ----------
    lower : numpy.ndarray, shape (n, k)
        The ``(k-1)``-simplices, sorted rows without duplicates: the row basis.
    upper : numpy.ndarray, shape (m, k + 1)
        The ``k``-simplices, sorted rows: the column basis.  Every facet must be a row of ``lower``.
    coefficients : int
        0 for Z (entries ±1); a prime p for Z/p (entries reduced mod p).

    Returns
    -------
    scipy.sparse.csc_matrix of int64, shape (n, m)
        Rows follow the order of ``lower``, columns that of ``upper``, indices sorted.

    Raises
    ------
    ValueError
        If a facet of ``upper`` is missing from ``lower``.
    """
    import scipy.sparse as sp

    m, width = upper.shape
    if width < 2:
        return sp.csc_matrix((lower.shape[0], m), dtype=np.int64)
    f = facets(upper)  # (m, k+1, k)
    rows = find_rows(lower, f.reshape(-1, width - 1)).reshape(m, width)
    signs = np.tile((-1) ** np.arange(width, dtype=np.int64), (m, 1))
    if coefficients:
        signs %= coefficients
    cols = np.repeat(np.arange(m, dtype=np.int64), width)
    mat = sp.csc_matrix((signs.ravel(), (rows.ravel(), cols)), shape=(lower.shape[0], m), dtype=np.int64)
    mat.sort_indices()
    return mat

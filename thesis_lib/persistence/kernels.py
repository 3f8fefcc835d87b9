"""The column reduction, field arithmetic and column heap shared by every persistence reduction.

Two reduction loops exist in the library, and only two:

* :func:`reduce_columns`, **the stored-matrix kernel**: the column reduction mod p, with clearing,
  of a matrix held in compressed columns.  It serves the explicit engine (:mod:`.engine`,
  coboundary columns: cohomology), the persistence of a general filtered chain complex
  (:mod:`.chains`, boundary columns, hence the Morse reduction of :mod:`thesis_lib.morse`) and the
  representative cycles (:mod:`.representatives`, which read R or V off its record).  Compiled
  C++: ``src/reduction.cpp`` (the module ``thesis_lib._core.reduction``); this function is its face.
* ``_reduce`` in :mod:`.implicit`, **the implicit kernel** of the Rips engine: its coboundaries are
  enumerated on the fly from the neighbour graph, never stored, so it cannot share a loop over
  stored columns; it is built from this module's primitives only (heap, pivot popping, chain
  merging, modular inverse).

The thesis's literal Algorithms 1–2 (:mod:`.algorithm`) stay readable Python on dicts and use
:func:`inverse`, the one modular inverse for Python integers (:func:`mod_inverse` inside compiled
code).  A working column of a reduction is a binary min-heap of entries ``(value, key, coefficient)``
ordered by ``(value, key)``: the *pivot* of the column is its least entry whose coefficients
(entries of the same key are summed lazily, as in Ripser) do not cancel mod p.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import reduction
from ..jit import njit

__all__ = ["inverse", "mod_inverse", "heap_push", "heap_pop", "heap_replace_top", "pop_pivot", "merge_entries", "grow",
           "reduce_columns", "KEEP_V", "KEEP_V_ALL", "KEEP_REDUCED"]


def inverse(a: int, p: int) -> int:
    """a⁻¹ in Z/p for a prime p (Python integers; Fermat: a^(p−2)).

    Thesis: Algorithm 1 (Reduce), the factor q⁻¹ of ``d = d − q⁻¹ T[i]``.

    Parameters
    ----------
    a : int
        The element to invert; any integer not divisible by ``p`` (reduced mod ``p`` first).
    p : int
        A prime: the field Z/p.

    Returns
    -------
    int
        The residue b in ``1 .. p − 1`` with ``a · b ≡ 1 (mod p)`` (0 when ``p`` divides ``a``, which
        has no inverse: callers never ask for it).
    """
    return pow(int(a) % p, p - 2, p)


@njit(cache=True)
def mod_inverse(a: np.int64, p: np.int64) -> np.int64:
    """a⁻¹ in Z/p (extended Euclid) inside compiled kernels; ``p < 2**31`` so products fit in int64."""
    t, newt, r, newr = np.int64(0), np.int64(1), np.int64(p), np.int64(a % p)
    while newr != 0:
        q = r // newr
        t, newt = newt, t - q * newt
        r, newr = newr, r - q * newr
    return t % p


@njit(cache=True, inline="always")
def _put(hv, hk, hc, i, v, k, c):
    """Write the entry ``(v, k, c)`` at position i of the heap (sift-up and sift-down move entries so)."""
    hv[i] = v
    hk[i] = k
    hc[i] = c


@njit(cache=True)
def heap_push(hv, hk, hc, n, v, k, c):
    """Push ``(value v, key k, coefficient c)`` on the heap of size ``n`` (arrays large enough); returns n + 1."""
    i = n
    while i > 0:
        par = (i - 1) >> 1
        if v < hv[par] or (v == hv[par] and k < hk[par]):
            _put(hv, hk, hc, i, hv[par], hk[par], hc[par])
            i = par
        else:
            break
    _put(hv, hk, hc, i, v, k, c)
    return n + 1


@njit(cache=True)
def heap_pop(hv, hk, hc, n):
    """Remove the top of the heap of size ``n`` (read it first); returns n − 1."""
    n -= 1
    if n > 0:
        heap_replace_top(hv, hk, hc, n, hv[n], hk[n], hc[n])
    return n


@njit(cache=True)
def heap_replace_top(hv, hk, hc, n, v, k, c):
    """Replace the top of the heap of size ``n`` by ``(v, k, c)`` and restore the order (one sift-down)."""
    i = 0
    while True:
        left = 2 * i + 1
        if left >= n:
            break
        m = left
        right = left + 1
        if right < n and (hv[right] < hv[left] or (hv[right] == hv[left] and hk[right] < hk[left])):
            m = right
        if hv[m] < v or (hv[m] == v and hk[m] < k):
            _put(hv, hk, hc, i, hv[m], hk[m], hc[m])
            i = m
        else:
            break
    _put(hv, hk, hc, i, v, k, c)


@njit(cache=True)
def pop_pivot(hv, hk, hc, n, p):
    """Pop entries until the least key whose summed coefficient is non-zero mod p.

    Returns ``(new size, value, key, coefficient)``; coefficient 0 (value ``inf``) when the column is zero.
    The pivot is removed from the heap: a caller that adds a column with the same pivot skips that
    column's pivot entries, which cancel exactly.
    """
    while n > 0:
        v, k = hv[0], hk[0]
        c = hc[0]
        n = heap_pop(hv, hk, hc, n)
        while n > 0 and hk[0] == k and hv[0] == v:
            c += hc[0]
            n = heap_pop(hv, hk, hc, n)
        c %= p
        if c != 0:
            return n, v, k, c
    return n, np.inf, np.int64(0), np.int64(0)


@njit(cache=True)
def merge_entries(keys, coefs, n, p):
    """The distinct keys of ``keys[:n]`` with their coefficients summed mod p, zeros dropped.

    Returns ``(positions, sums)``: for each surviving key (increasing) one position in ``keys``
    holding it (to read parallel arrays) and its summed coefficient.  Used to store a reduction
    chain V after a column was reduced.
    """
    order = np.argsort(keys[:n])
    pos = np.empty(n, dtype=np.int64)
    sums = np.empty(n, dtype=np.int64)
    q = 0
    i = 0
    while i < n:
        first = order[i]
        c = np.int64(0)
        while i < n and keys[order[i]] == keys[first]:
            c += coefs[order[i]]
            i += 1
        c %= p
        if c != 0:
            pos[q] = first
            sums[q] = c
            q += 1
    return pos[:q], sums[:q]


@njit(cache=True)
def grow(hv, hk, hc, n, need):
    """The heap arrays with room for ``need`` entries (the first ``n`` kept): doubled when too small."""
    if need <= hv.shape[0]:
        return hv, hk, hc
    cap = hv.shape[0]
    while cap < need:
        cap *= 2
    nv = np.empty(cap, dtype=hv.dtype)
    nk = np.empty(cap, dtype=hk.dtype)
    nc = np.empty(cap, dtype=hc.dtype)
    nv[:n] = hv[:n]
    nk[:n] = hk[:n]
    nc[:n] = hc[:n]
    return nv, nk, nc


#: what :func:`reduce_columns` keeps of a reduced column: its chain V (cohomology, as Ripser), V also
#: for the columns that reduce to zero (representative cycles), or the reduced column itself (homology)
KEEP_V, KEEP_V_ALL, KEEP_REDUCED = 0, 1, 2


def reduce_columns(
    indptr: npt.NDArray[np.int64], rows: npt.NDArray[np.integer], coefs: npt.NDArray[np.integer],
    row_value: npt.NDArray[np.float64], columns: npt.NDArray[np.int64], cleared: npt.NDArray[np.bool_],
    pivot: npt.NDArray[np.int64], pivot_coef: npt.NDArray[np.int64], p: np.int64, keep: int,
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.int64], int,
           npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.int64]]:
    """Reduce the columns of a compressed (CSC) matrix over Z/p, with clearing: the library's one
    stored-matrix column reduction.

    Thesis: Algorithm 1 (Reduce) inside Algorithm 2 (ComputeIntervals), §2.3.5: add earlier columns
    to a column until no earlier column has its pivot; with clearing (a column known to be paired is
    skipped) and on either side of the duality (boundary or coboundary columns).

    The rows are ordered by ``(row_value[r], r)`` and the *pivot* of a column is its least row: give
    ``row_value = −(position in the filtration)`` for boundary columns (pivot = latest face), the
    cofaces' values for coboundary columns (pivot = earliest coface).  A column whose pivot is still
    free is paired as it stands, without touching its entries (apparent and emergent pairs: the
    common case).  A colliding column is reduced lazily, as in Ripser (Bauer 2021): the working
    column is a heap of entries summed only when they reach the top, and only the entries up to the
    next free pivot are ever combined.  Compiled C++ (``src/reduction.cpp``).  A column added to
    another is either regenerated from its chain V of original columns (``KEEP_V``: cohomology, where
    reduced columns fill in) or read from its stored reduced column (``KEEP_REDUCED``: homology).

    Parameters
    ----------
    indptr : numpy.ndarray of int64, shape (m + 1,)
        Column ``c`` holds the entries ``indptr[c] .. indptr[c + 1] − 1``.
    rows : numpy.ndarray of int, shape (nnz,)
        The row of each entry; no row twice in one column.
    coefs : numpy.ndarray of int, shape (nnz,)
        The coefficient of each entry (integers taken mod p; none divisible by p).
    row_value : numpy.ndarray of float64, shape (number of rows,)
        The first key of the row order (the row index is the second).
    columns : numpy.ndarray of int64
        The columns to reduce, in the order of the reduction.
    cleared : numpy.ndarray of bool, shape (m,)
        Columns to skip (cleared: paired already, as a pivot row one dimension away).
    pivot : numpy.ndarray of int64, shape (m,)
        The least row of each column, −1 for an empty column.
    pivot_coef : numpy.ndarray of int64, shape (m,)
        The coefficient at that row.
    p : numpy.int64
        A prime below 2³¹ (a product of two residues fits in int64).
    keep : int
        ``KEEP_V``: keep the chain V_c of every paired column that needed additions (the columns a
        later column may add); ``KEEP_V_ALL``: also of the columns that reduce to zero (their V is a
        cycle: representatives); ``KEEP_REDUCED``: keep the reduced column of every paired column
        that needed additions, pivot entry first.

    Returns
    -------
    pair_columns, pair_rows : numpy.ndarray of int64
        The persistence pairs: column ``pair_columns[i]`` reduced to pivot ``pair_rows[i]``.
    zero_columns : numpy.ndarray of int64
        The columns that reduced to zero (empty ones included), in the order of ``columns``.
    additions : int
        The number of column additions.
    start, length : numpy.ndarray of int64, shape (m,)
        What is kept of column c is ``pool_keys[start[c]:start[c] + length[c]]`` with the
        coefficients ``pool_coefs`` at the same places: the columns of V_c (increasing; the reduced
        column is ``Σ_k V_c[k] · column k``) or the rows of the reduced column (pivot first).
        ``start[c] = −1``: column c was not added to (V_c = c, reduced column = column c).
    pool_keys, pool_coefs : numpy.ndarray of int64
        The kept chains or columns, coefficients in ``1 .. p − 1``.

    Raises
    ------
    ValueError
        Arrays of inconsistent lengths, a decreasing ``indptr``, a column, row or pivot index out of
        range, ``p`` outside ``2 .. 2³¹ − 1`` or an unknown ``keep``.
    """
    rows = np.asarray(rows)
    coefs = np.asarray(coefs)
    return reduction.reduce_columns(
        np.ascontiguousarray(indptr, dtype=np.int64),
        np.ascontiguousarray(rows, dtype=np.int32 if rows.dtype == np.int32 else np.int64),
        np.ascontiguousarray(coefs, dtype=np.int8 if coefs.dtype == np.int8 else np.int64),
        np.ascontiguousarray(row_value, dtype=np.float64), np.ascontiguousarray(columns, dtype=np.int64),
        np.ascontiguousarray(cleared, dtype=np.bool_), np.ascontiguousarray(pivot, dtype=np.int64),
        np.ascontiguousarray(pivot_coef, dtype=np.int64), int(p), int(keep),
    )

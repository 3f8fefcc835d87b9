"""The column reduction and field arithmetic shared by every persistence reduction.

Two reduction loops exist in the library, and only two:

* :func:`reduce_columns`, **the stored-matrix kernel**: the column reduction mod p, with clearing,
  of a matrix held in compressed columns.  It serves the explicit engine (:mod:`.engine`,
  coboundary columns: cohomology), the persistence of a general filtered chain complex
  (:mod:`.chains`, boundary columns, hence the Morse reduction of :mod:`thesis_lib.morse`) and the
  representative cycles (:mod:`.representatives`, which read R or V off its record).  Compiled
  C++: ``src/reduction.cpp`` (the module ``thesis_lib._core.reduction``); this function is its face.
* the reduction of :mod:`.implicit` (``src/implicit_rips.cpp``), **the implicit kernel** of the Rips
  engine: its coboundaries are
  enumerated on the fly from the neighbour graph, never stored, so it cannot share a loop over
  stored columns; both are built on the same primitives (``src/column_heap.hpp``: the heap, pivot
  popping, chain merging, the modular inverse).

The thesis's literal Algorithms 1–2 (:mod:`.algorithm`) stay readable Python on dicts and use
:func:`inverse`, the one modular inverse for Python integers (``mod_inverse`` of
``src/column_heap.hpp`` inside compiled code).  A working column of a reduction is a binary
min-heap of entries ``(value, key, coefficient)`` ordered by ``(value, key)``: the *pivot* of the
column is its least entry whose coefficients (entries of the same key are summed lazily, as in
Ripser) do not cancel mod p.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import reduction

__all__ = ["inverse", "reduce_columns", "KEEP_V", "KEEP_V_ALL", "KEEP_REDUCED"]


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
        np.ascontiguousarray(row_value, dtype=np.float64),
        reduction.ColumnState(np.ascontiguousarray(columns, dtype=np.int64),
                              np.ascontiguousarray(cleared, dtype=np.bool_),
                              np.ascontiguousarray(pivot, dtype=np.int64),
                              np.ascontiguousarray(pivot_coef, dtype=np.int64)),
        int(p), int(keep),
    )

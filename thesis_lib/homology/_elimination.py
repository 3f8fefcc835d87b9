"""Sparse Gaussian elimination with Markowitz pivoting, over Z (unit pivots) or over Z/p.

The first stage of :mod:`thesis_lib.homology.smith`.  A pivot is an entry ``v`` of the active matrix that is
a unit (``±1`` over Z, any nonzero residue over Z/p); eliminating it replaces the active matrix ``A``
by the Schur complement ``A' = A - a_{:,j} a_{i,:} / v`` on the other rows and columns, which over Z
is an exact unimodular step: ``A ~ (v) ⊕ A'``.  After ``t`` pivots,

    SNF(A) = diag(1, ..., 1) ⊕ SNF(core),

where the *core* is the active matrix left when no unit entry can be pivoted on (over Z/p the core
is empty and ``t`` is the rank).  The original rows and columns of the pivots form a ``t × t``
submatrix of determinant ``±1`` (the product of the pivots), which is what clearing needs
(:func:`thesis_lib.homology.homology`).

Pivots are chosen by the Markowitz rule: among the unit entries of the few rows and columns with
the fewest entries, the one with the least ``(r - 1)(c - 1)`` (``r``, ``c`` = entries in its row
and column), which bounds the fill-in of the step.  Over Z each step's new entries are checked
before they are stored: a step that would make an entry exceed ``lim`` (``|entries| ≤ 2³¹``, so
products fit in int64) is not taken and its column is set aside until it changes; such columns
end in the core, which the modular stage finishes exactly at any entry size.

Data layout (compiled C++, ``src/sparse_elimination.cpp``): rows are stored exactly, as sorted
``(column, value)`` runs in a pool (a row changed by a step is rewritten at the top of the pool);
columns keep only the list of rows that may hold an entry (stale rows are dropped when a column is
read) and an exact count.  Two lazy binary heaps, keyed by ``count · 2³² + index``, give the
shortest rows and columns.
"""

from __future__ import annotations

import numpy as np

from .._core import sparse_elimination

__all__ = ["markowitz_eliminate", "dense_kernel", "LIMIT"]

#: largest |entry| kept during elimination over Z: |a - f b| <= 2**31 + 2**62 < 2**63, exact in int64
LIMIT = 2**31


def dense_kernel(a: np.ndarray, p: int, lim: int) -> tuple[int, np.ndarray, np.ndarray]:
    """Unit-pivot elimination of a dense int64 matrix in place, column by column.

    The end of the sparse stage, and the unit part of the Smith form modulo M in
    :mod:`thesis_lib.homology._modular` (``p`` is then any modulus M < 2³¹, entries in [0, M)).  For each
    column a row with a unit entry (over Z the one with the smallest entries) is the pivot and every
    other live row is updated (Schur complement).  Over Z a step whose update could exceed ``lim``
    is skipped.  Passes repeat while they make progress (over a field the second finds nothing).
    Returns (pivots, pivot-row mask, eliminated-column mask).

    Parameters
    ----------
    a : numpy.ndarray of int64, shape (m, n), C-contiguous
        Overwritten.  Over Z ``|entries| <= lim``; modulo p entries in ``[0, p)``.
    p : int
        0 for Z, else the modulus (below 2³¹).
    lim : int
        Over Z the largest absolute entry a step may create (at most 2³¹).

    Returns
    -------
    tuple of (int, numpy.ndarray of bool, numpy.ndarray of bool)
        The number of pivots, the rows that carried one, the columns eliminated.
    """
    pivots, rows, cols = sparse_elimination.dense_unit_elimination(a, int(p), int(lim))
    return int(pivots), rows, cols


def markowitz_eliminate(indptr: np.ndarray, indices: np.ndarray, data: np.ndarray, n_rows: int,
                        skip: np.ndarray, p: int, *, search: int = 4, density: float = 0.2,
                        max_dense: int = 2 * 10**7,
                        finish: bool = True) -> tuple[int, np.ndarray, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Eliminate unit pivots of a CSC matrix (sorted indices, int64, |entries| <= LIMIT over Z).

    Sparse Markowitz steps while the active matrix is sparse; once it holds at least ``density``
    of its ``rows × columns`` (and that is at most ``max_dense`` entries) it is finished densely
    (``finish=False``: returned as it is then).
    Returns ``(rank, pivot_rows, core)``: the number of pivots, a boolean mask of the rows that
    carried one, and the core (over Z/p: empty) as a dense int64 array with its original row and
    column indices ``(core, rows, cols)``.  ``p`` = 0 for Z, a prime < 2³¹ for Z/p.
    """
    rank, pivot_rows, core_rows, core_ptr, core_cols, core_vals = sparse_elimination.markowitz(
        np.ascontiguousarray(indptr, dtype=np.int64), np.ascontiguousarray(indices, dtype=np.int64),
        np.ascontiguousarray(data, dtype=np.int64), int(n_rows), np.ascontiguousarray(skip, dtype=np.bool_),
        sparse_elimination.Options(int(p), LIMIT, int(search), float(density), int(max_dense)),
    )
    cols = np.unique(core_cols)
    dense = np.zeros((core_rows.size, cols.size), dtype=np.int64)
    dense[np.repeat(np.arange(core_rows.size), np.diff(core_ptr)), np.searchsorted(cols, core_cols)] = core_vals
    if dense.size and finish:
        more, piv, done = dense_kernel(dense, p, LIMIT)
        rank += more
        pivot_rows[core_rows[piv]] = True
        keep_r, keep_c = ~piv, ~done
        dense = dense[keep_r][:, keep_c]
        core_rows, cols = core_rows[keep_r], cols[keep_c]
        nz = dense != 0
        rows_nz, cols_nz = nz.any(axis=1), nz.any(axis=0)
        dense, core_rows, cols = dense[rows_nz][:, cols_nz], core_rows[rows_nz], cols[cols_nz]
    return int(rank), pivot_rows, (dense, core_rows, cols)

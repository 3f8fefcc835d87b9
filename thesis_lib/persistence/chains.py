"""Persistence of a general filtered chain complex (cells with values and boundary matrices).

Used for the Morse complex of a filtration (:mod:`thesis_lib.morse.reduction`), whose cells are the
critical simplices and whose boundary comes from gradient paths, not from vertices.  The reduction
is Algorithm 2's column reduction on the boundary side with the twist (clearing): higher dimensions
first, a column whose index is already a pivot is skipped.  The reduction loop is the library's one
stored-matrix kernel, :func:`~thesis_lib.persistence.kernels.reduce_columns`.
"""

from __future__ import annotations

import numpy as np

from .._validate import Field, parse_field
from .barcode import Barcode
from .kernels import KEEP_REDUCED, reduce_columns

__all__ = ["chain_persistence", "chain_barcode"]


def _reduce(mat, dims_pos: np.ndarray, p: int) -> np.ndarray:
    """low[col] (−1 for a zero column) of the boundary matrix ``mat`` (CSC, rows and columns the cells in
    filtration order, entries in 1 .. p − 1, sorted within each column) reduced mod p with the twist.

    One dimension at a time, the highest first, each by increasing position; the columns whose cell
    is already a pivot one dimension up are cleared.  Rows are ordered by −position, so the pivot of
    a column is its latest face.
    """
    n = mat.shape[0]
    indptr, rows, coefs = mat.indptr.astype(np.int64), mat.indices.astype(np.int64), mat.data.astype(np.int64)
    nonempty = indptr[1:] > indptr[:-1]
    pivot = np.where(nonempty, rows[np.maximum(indptr[1:] - 1, 0)] if rows.size else -1, -1)
    pivot_coef = np.where(nonempty, coefs[np.maximum(indptr[1:] - 1, 0)] if rows.size else 0, 0)
    row_value = -np.arange(n, dtype=np.float64)
    low = np.full(n, -1, dtype=np.int64)
    cleared = np.zeros(n, dtype=np.bool_)
    for d in range(int(dims_pos.max(initial=0)), 0, -1):
        cols, piv = reduce_columns(indptr, rows, coefs, row_value, np.flatnonzero(dims_pos == d), cleared, pivot,
                                   pivot_coef, np.int64(p), KEEP_REDUCED)[:2]
        low[cols] = piv
        cleared[piv] = True
    return low


def chain_persistence(values: list[np.ndarray], boundaries: list, *, coefficients: int = 2) -> Barcode:
    """Barcode of a filtered chain complex: cells with values per dimension, boundary matrices per dimension.

    Thesis: Algorithm 2, §2.3.5 (column reduction over Z/p; pairs give P-intervals, Definition 2.34).

    Parameters
    ----------
    values : ``values[d]`` the filtration values of the d-cells.
    boundaries : ``boundaries[d]`` the matrix (dense or scipy.sparse, integer) of ∂ from d-cells
        (columns) to (d−1)-cells (rows); ``boundaries[0]`` is ignored.  Every cell's boundary must
        consist of cells with value ≤ its own (ties: lower dimension first).
    coefficients : a prime p, the field Z/p.

    Returns
    -------
    Barcode

    Examples
    --------
    RP² as a CW complex: a vertex (value 0), a loop e (value 1, ∂e = 0) and a disc D glued along it
    twice (value 2, ∂D = 2e).  Over Z/2 the disc creates a 2-class; over Z/3 it kills the loop:

    >>> import numpy as np
    >>> values = [np.array([0.0]), np.array([1.0]), np.array([2.0])]
    >>> boundaries = [None, np.zeros((1, 1), dtype=int), np.array([[2]])]
    >>> chain_persistence(values, boundaries, coefficients=2).as_pairs()
    [(0, (0.0, inf)), (1, (1.0, inf)), (2, (2.0, inf))]
    >>> chain_persistence(values, boundaries, coefficients=3).as_pairs()
    [(0, (0.0, inf)), (1, (1.0, 2.0))]
    """
    field = parse_field(coefficients)
    if not field.is_field:
        raise ValueError("persistence needs a prime field Z/p, got 0")
    return chain_barcode(values, boundaries, field)


def chain_barcode(values: list[np.ndarray], boundaries: list, field: Field) -> Barcode:
    """:func:`chain_persistence` with the field parsed (a prime).

    Thesis: Algorithm 2, §2.3.5 (column reduction over Z/p).

    Parameters
    ----------
    values : list of numpy.ndarray
        As :func:`chain_persistence`.
    boundaries : list of matrices
        As :func:`chain_persistence`.
    field : Field
        The parsed prime field.

    Returns
    -------
    Barcode
        As :func:`chain_persistence`.

    Raises
    ------
    ValueError
        Mismatched shapes, NaN values, or a cell with a face of larger value.
    """
    import scipy.sparse as sp

    p = field.p
    counts = [len(v) for v in values]
    if len(boundaries) != len(values):
        raise ValueError("give one boundary matrix per dimension")
    offsets = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
    n = int(offsets[-1])
    dims = np.repeat(np.arange(len(counts)), counts)
    vals = np.concatenate([np.asarray(v, dtype=np.float64) for v in values]) if n else np.empty(0)
    if np.isnan(vals).any():
        raise ValueError("filtration values must not be NaN")
    order = np.lexsort((np.arange(n), dims, vals))
    pos = np.empty(n, dtype=np.int64)
    pos[order] = np.arange(n)
    blocks_r, blocks_c, blocks_v = [], [], []
    for d in range(1, len(counts)):
        b = sp.coo_matrix(boundaries[d])
        if b.shape != (counts[d - 1], counts[d]):
            raise ValueError(f"boundary {d} has shape {b.shape}, expected {(counts[d - 1], counts[d])}")
        r = pos[b.row + offsets[d - 1]]
        c = pos[b.col + offsets[d]]
        if b.nnz and np.any(r > c):
            raise ValueError(f"a {d}-cell has a face with a larger filtration value")
        blocks_r.append(r)
        blocks_c.append(c)
        blocks_v.append(np.asarray(b.data, dtype=np.int64) % p)
    if blocks_r:
        r, c, v = np.concatenate(blocks_r), np.concatenate(blocks_c), np.concatenate(blocks_v)
    else:
        r = c = v = np.empty(0, dtype=np.int64)
    mat = sp.csc_matrix((v, (r, c)), shape=(n, n), dtype=np.int64)
    mat.sum_duplicates()
    mat.data %= p
    mat.eliminate_zeros()
    mat.sort_indices()
    dims_pos = dims[order]
    low = _reduce(mat, dims_pos, p)
    vals_pos = vals[order]
    paired = np.zeros(n, dtype=bool)
    has = low >= 0
    cols = np.flatnonzero(has)
    rows = low[has]
    paired[cols] = True
    paired[rows] = True
    intervals: dict[int, list[tuple[float, float]]] = {d: [] for d in range(len(counts))}
    for rr, cc in zip(rows.tolist(), cols.tolist()):
        if vals_pos[cc] > vals_pos[rr]:
            intervals[int(dims_pos[rr])].append((float(vals_pos[rr]), float(vals_pos[cc])))
    for i in np.flatnonzero(~paired).tolist():
        intervals[int(dims_pos[i])].append((float(vals_pos[i]), np.inf))
    return Barcode(intervals, dimensions=range(len(counts)), coefficients=field)

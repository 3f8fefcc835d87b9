"""Smith normal form over Z and ranks over Z/p of sparse integer matrices.

The thesis (§2.2.1) reads homology off the Smith normal form of the boundary matrices: the number
of nonzero diagonal entries is the rank, entries ``>= 2`` are torsion.  Boundary matrices are huge
and sparse, and almost all of their elimination can be done with pivots ``±1``, so the engine works
in two stages, each exact:

1. **sparse elimination** (``thesis_lib.homology._elimination``, C++): Gaussian elimination on unit
   pivots (``±1`` over Z, any nonzero residue over Z/p) chosen by the Markowitz rule to limit
   fill-in, with every new entry checked to stay within int64.  Each step is unimodular, so
   ``SNF(A) = I ⊕ SNF(core)``; over Z/p the core is empty and the number of pivots is the rank;
2. **the dense core over Z** (``thesis_lib.homology._modular``): rank profile modulo a prime,
   determinants of two ``r × r`` minors by Chinese remaindering, and, only if their gcd ``M`` is not
   1, the Smith form modulo ``M`` — exact at any entry size, with no integer factored.

Over Z/p for a prime ``p >= 2³¹`` (beyond the word-size kernels) the rank is read off the Smith
form over Z of the symmetric residues: ``rank_p(A) = #{i : p ∤ s_i}``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

import numpy as np
import numpy.typing as npt
import scipy.sparse as sp

from .._validate import MAX_EXACT_PRIME, MAX_PRIME, Field, parse_field
from ._elimination import LIMIT, markowitz_eliminate
from ._modular import dense_invariants

__all__ = [
    "smith_normal_form",
    "rank_mod_p",
    "reduce_matrix",
    "reduce_checked",
    "Reduction",
    "dense_smith_diagonal",
    "diagonal_text",
]

#: largest dense matrix (entries) the modular stage accepts for a matrix with entries beyond 2³¹
MAX_DENSE_ENTRIES = 5 * 10**7


class Reduction(NamedTuple):
    """Outcome of :func:`reduce_matrix` for one matrix.

    Thesis: §2.2.1 (k_p = number of nonzero SNF entries; entries ≥ 2 give torsion).

    Attributes
    ----------
    rank : rank over Z (or over Z/p).
    invariants : invariant factors ``>= 2`` of the Smith normal form over Z (empty over Z/p),
        ascending, each dividing the next (Python ints).
    unit_pivot_rows : boolean mask over the rows that carry a pivot of the sparse stage; their
        rows and pivot columns form a submatrix of determinant ±1 (a unit mod p).  Used for clearing.
    core_shape : shape of the dense core left by the sparse stage (rows × columns).
    """

    rank: int
    invariants: list[int]
    unit_pivot_rows: np.ndarray
    core_shape: tuple[int, int]


# --------------------------------------------------------------------------------------------
# validation
# --------------------------------------------------------------------------------------------


def _is_int(x) -> bool:
    return isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_))


def _checked_entries(data: np.ndarray) -> np.ndarray:
    """The entries as int64, or as Python ints (object) when one does not fit; refuse non-integers."""
    dt = data.dtype
    if dt.kind == "O":  # object dtype (Python ints)
        if not all(_is_int(x) for x in data.flat):
            raise ValueError("matrix entries must be integers")
        out = np.array([int(x) for x in data.flat], dtype=object).reshape(data.shape)
        if out.size == 0 or max(abs(x) for x in out.flat) < 2**63:
            return out.astype(np.int64)
        return out
    if dt.kind == "b":
        return data.astype(np.int64)
    if np.issubdtype(dt, np.unsignedinteger):
        if data.size and int(data.max()) >= 2**63:  # uint64 beyond int64: keep exact Python ints
            return np.array([int(x) for x in data.flat], dtype=object).reshape(data.shape)
        return data.astype(np.int64)
    if np.issubdtype(dt, np.integer):
        if data.size and int(data.min()) == -(2**63):  # |x| does not fit: keep exact Python ints
            return data.astype(object)
        return data.astype(np.int64)
    if np.issubdtype(dt, np.floating):
        d = np.asarray(data, dtype=float)
        if not np.all(np.isfinite(d)):
            raise ValueError("matrix entries must be finite integers, got NaN or inf")
        if not np.all(d == np.round(d)):
            raise ValueError("matrix entries must be integers, got non-integral floats")
        if d.size and np.abs(d).max() >= 2**53:
            raise ValueError("float matrix entries too large to be exact integers; pass Python ints (dtype=object)")
        return d.astype(np.int64)
    raise ValueError(f"matrix entries must be integers, got dtype {dt}")


def _as_matrix(matrix) -> sp.csc_matrix | np.ndarray:
    """An int64 CSC matrix (sorted, no explicit zeros), or a dense object array if an entry exceeds int64."""
    if sp.issparse(matrix):
        if len(matrix.shape) != 2:
            raise ValueError("matrix must be 2-D")
        mat = sp.csc_matrix(matrix)
        data = _checked_entries(mat.data)
        if data.dtype == object:
            raise ValueError("sparse matrix entries must fit in int64; pass a dense object array of Python ints")
        mat = sp.csc_matrix((data, mat.indices, mat.indptr), shape=mat.shape)
    else:
        try:
            arr = np.asarray(matrix)
        except ValueError as err:
            raise ValueError(f"matrix must be a 2-D array of integers: {err}") from None
        if arr.ndim != 2:
            raise ValueError(f"matrix must be 2-D, got shape {arr.shape}")
        arr = _checked_entries(arr)
        if arr.dtype == object:
            return arr
        mat = sp.csc_matrix(arr)
    mat.sum_duplicates()
    mat.eliminate_zeros()
    mat.sort_indices()
    return mat


# --------------------------------------------------------------------------------------------
# drivers
# --------------------------------------------------------------------------------------------


def _dense_reduction(dense: np.ndarray, p: int) -> Reduction:
    """Exact path for a matrix with entries beyond the sparse kernels' range (no clearing mask)."""
    if dense.size > MAX_DENSE_ENTRIES:
        raise ValueError(f"a {dense.shape[0]} x {dense.shape[1]} matrix with entries beyond 2^31 is too large "
                         f"for the exact dense stage (limit {MAX_DENSE_ENTRIES:,} entries)")
    inv = dense_invariants(dense)
    return _result(0, inv, np.zeros(dense.shape[0], dtype=bool), dense.shape, p)


def _result(n_units: int, core_invariants: list[int], mask: np.ndarray, core_shape, p: int) -> Reduction:
    if p:  # rank over Z/p read off the Smith form over Z
        rank = n_units + sum(1 for s in core_invariants if s % p)
        return Reduction(rank, [], mask, tuple(core_shape))
    return Reduction(n_units + len(core_invariants), [s for s in core_invariants if s > 1], mask, tuple(core_shape))


def _symmetric(mat: sp.csc_matrix, p: int) -> sp.csc_matrix:
    """Entries reduced to (-p/2, p/2] (same rank over Z/p, small over Z)."""
    data = np.mod(mat.data, p)
    data = np.where(data > p // 2, data - p, data)
    out = sp.csc_matrix((data, mat.indices, mat.indptr), shape=mat.shape)
    out.eliminate_zeros()
    return out


def reduce_matrix(matrix: npt.ArrayLike | sp.spmatrix | sp.sparray, *, coefficients: int = 0,
                  skip_columns: npt.ArrayLike | None = None) -> Reduction:
    """Rank and torsion invariants of an integer matrix: sparse unit-pivot elimination, then an exact dense core.

    Thesis: §2.2.1 (Smith normal form of boundary matrices, torsion from diagonal entries ≥ 2).

    Parameters
    ----------
    matrix : array_like or scipy sparse matrix, shape (m, n)
        Integer entries (an object array of Python ints for entries beyond int64; a sparse matrix
        must fit in int64).
    coefficients : int
        0 for Z, a prime p for Z/p.
    skip_columns : array_like of bool, shape (n,), optional
        Columns to ignore (clearing: columns known to become zero after a unimodular change of
        basis); None keeps every column.

    Returns
    -------
    Reduction
        The rank over Z (or Z/p), the invariant factors ``>= 2`` (over Z only), the rows carrying a
        unit pivot of the sparse stage, and the shape of the dense core.

    Raises
    ------
    ValueError
        A matrix that is not 2-D or has non-integer entries, coefficients neither 0 nor a prime, or a
        ``skip_columns`` mask of the wrong length.
    """
    field = parse_field(coefficients, max_prime=MAX_EXACT_PRIME)
    mat = _as_matrix(matrix)
    if skip_columns is None:
        return reduce_checked(mat, field=field)
    skip = np.asarray(skip_columns, dtype=np.bool_)
    if skip.shape != (mat.shape[1],):
        raise ValueError(f"skip_columns must be a boolean mask of length {mat.shape[1]}, got shape {skip.shape}")
    return reduce_checked(mat, field=field, skip_columns=skip)


def reduce_checked(matrix: sp.csc_matrix | np.ndarray, *, field: Field,
                   skip_columns: np.ndarray | None = None) -> Reduction:
    """:func:`reduce_matrix` on checked input (a boundary matrix the library built, or one parsed by it).

    Thesis: §2.2.1 (Smith normal form of boundary matrices, torsion from diagonal entries ≥ 2).

    Parameters
    ----------
    matrix : scipy.sparse.csc_matrix of int64, or numpy.ndarray of Python ints
        Canonical CSC (sorted indices, no explicit zeros, no duplicates), or a dense object array
        when an entry exceeds int64.
    field : Field
        The parsed coefficients (0 for Z, a prime p < ``MAX_EXACT_PRIME`` for Z/p).
    skip_columns : numpy.ndarray of bool, shape (n,), optional
        Columns to ignore (clearing); None keeps every column.

    Returns
    -------
    Reduction
        As :func:`reduce_matrix`.
    """
    p = field.p
    skip = np.zeros(matrix.shape[1], dtype=np.bool_) if skip_columns is None else skip_columns
    if isinstance(matrix, np.ndarray):  # entries beyond int64
        dense = matrix[:, ~skip]
        if p:  # over Z/p the residues are small: back to the sparse kernels
            mat = sp.csc_matrix((dense % p).astype(np.int64))
            mat.sort_indices()
            return reduce_checked(mat, field=field)
        return _dense_reduction(dense, p)
    mat = matrix
    if p > MAX_PRIME:
        mat, kernel_p = _symmetric(mat, p), 0
    else:
        kernel_p = p
    if kernel_p == 0 and mat.nnz and np.abs(mat.data).max() > LIMIT:
        return _dense_reduction(mat[:, np.flatnonzero(~skip)].toarray().astype(object), p)
    rank, mask, (core, _, _) = markowitz_eliminate(mat.indptr, mat.indices, mat.data, mat.shape[0], skip, kernel_p)
    if kernel_p:
        return Reduction(rank, [], mask, (0, 0))
    return _result(rank, dense_invariants(core), mask, core.shape, p)


def smith_normal_form(matrix: npt.ArrayLike | sp.spmatrix | sp.sparray) -> np.ndarray:
    """Diagonal of the Smith normal form over Z: the nonzero invariant factors a_1 | a_2 | ... .

    Thesis: Theorem 2.20 and §2.2.1 (PAQ = diag(a_1, ..., a_k, 0, ..., 0) with a_i | a_{i+1}).

    Exact at any entry size: int64 inputs beyond 2³¹ and Python ints of any size (an object array)
    are handled by the modular stage, never wrapped around.

    Parameters
    ----------
    matrix : array_like or scipy sparse matrix, shape (m, n)
        Integer entries: numpy of any integer dtype, nested lists, an object array of Python ints,
        or scipy sparse.

    Returns
    -------
    numpy.ndarray, shape (rank,)
        The positive invariant factors, ascending by divisibility (int64, or object dtype if one
        exceeds int64).

    Raises
    ------
    ValueError
        If the matrix is not 2-D or has non-integer, NaN or infinite entries.

    Examples
    --------
    A classic 3 × 3 example, and the boundary ∂_2 of RP², whose one invariant factor 2 is the torsion
    Z/2 of H_1(RP²) (Example 2.21):

    >>> smith_normal_form([[2, 4, 4], [-6, 6, 12], [10, -4, -16]]).tolist()
    [2, 6, 12]
    >>> from thesis_lib.datasets import rp2
    >>> from thesis_lib.homology.filtration import as_complex
    >>> from thesis_lib.homology import boundary_matrices
    >>> smith_normal_form(boundary_matrices(as_complex(rp2()).simplices)[2]).tolist()
    [1, 1, 1, 1, 1, 1, 1, 1, 1, 2]
    """
    red = reduce_checked(_as_matrix(matrix), field=Field(0))
    values = [1] * (red.rank - len(red.invariants)) + list(red.invariants)
    if any(v >= 2**63 for v in values):
        return np.array(values, dtype=object)
    return np.array(values, dtype=np.int64)


def dense_smith_diagonal(matrix: npt.ArrayLike) -> list[int]:
    """Invariant factors (nonzero Smith normal form diagonal, ascending by divisibility) of a dense matrix.

    Thesis: Theorem 2.20 (Smith normal form by elementary row and column operations).

    The modular stage alone (no sparse elimination): rank profile mod p, determinants of two
    minors by Chinese remaindering, Smith form modulo their gcd.  Exact at any entry size.

    Parameters
    ----------
    matrix : array_like, shape (m, n)
        Integer entries (an object array of Python ints for entries beyond int64).

    Returns
    -------
    list of int
        The nonzero invariant factors as Python ints, each dividing the next.

    Raises
    ------
    ValueError
        If the matrix is not 2-D or has non-integer, NaN or infinite entries.
    """
    a = np.asarray(matrix)
    if a.ndim != 2:
        raise ValueError(f"matrix must be 2-D, got shape {a.shape}")
    return dense_invariants(_checked_entries(a))


def rank_mod_p(matrix: npt.ArrayLike | sp.spmatrix | sp.sparray, *, coefficients: int) -> int:
    """Rank of an integer matrix over the field Z/p (p prime) by sparse elimination mod p.

    Thesis: §2.2.1 (working over Z_p, where every nonzero pivot is invertible).

    Parameters
    ----------
    matrix : array_like or scipy sparse matrix, shape (m, n)
        Integer entries (as for :func:`reduce_matrix`).
    coefficients : int
        The prime p.

    Returns
    -------
    int
        The rank of ``matrix`` mod p.

    Raises
    ------
    ValueError
        If ``coefficients`` is not a prime, or the matrix is not a 2-D integer matrix.
    """
    field = parse_field(coefficients, max_prime=MAX_EXACT_PRIME)
    if not field.is_field:
        raise ValueError("rank_mod_p needs a prime p, got 0")
    return reduce_checked(_as_matrix(matrix), field=field).rank


def diagonal_text(diagonal: Sequence[int]) -> str:
    """A Smith diagonal written as the thesis reads it: ``1 (r times)`` followed by the other terms.

    Thesis: Example 2.21 (M̃_2 has nine 1s and one 2 on its diagonal).

    Parameters
    ----------
    diagonal : sequence of int
        The nonzero invariant factors, as :func:`smith_normal_form` returns them.

    Returns
    -------
    str
        ``"1 (r times)"``, then the factors other than 1, joined by ``", "``.

    Raises
    ------
    ValueError
        A factor below 1.

    Examples
    --------
    >>> diagonal_text(smith_normal_form([[2, 0, 0], [0, 1, 0], [0, 0, 1]]))
    '1 (2 times), 2'
    """
    values = [int(x) for x in diagonal]
    if any(x < 1 for x in values):
        raise ValueError(f"invariant factors are positive, got {values}")
    ones = sum(1 for x in values if x == 1)
    return ", ".join([f"1 ({ones} times)"] + [str(x) for x in values if x != 1])

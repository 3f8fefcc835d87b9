"""The Morse complex of an acyclic discrete vector field and its homology (thesis §4.2.4–4.2.5)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
import scipy.sparse as sp

from .._validate import MAX_EXACT_PRIME, Field, parse_field
from ..homology.smith import reduce_checked
from ._cells import ComplexLike, Pairs, Simplex, cell_complex, partner_array
from ._gradient import morse_boundary_ids

__all__ = ["morse_boundary", "morse_homology", "chain_complex_homology"]


def morse_boundary(simplices: ComplexLike, pairs: Pairs,
                   *, coefficients: int = 0) -> tuple[list[list[Simplex]], list[sp.csc_matrix]]:
    """Critical simplices per dimension and the Morse boundary ∂̃_k : M_k → M_{k-1} between them.

    Thesis: Theorem 4.42 (∂̃τ = Σ_σ σ · Σ_{γ ∈ Γ(τ, σ)} m(γ)), gradient paths of Definition 4.34.

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and an acyclic vector field on it, whose critical simplices span the Morse
        complex.
    coefficients : int, default 0
        0 for Z, a prime p for Z/p (entries reduced to 0..p-1).

    Returns
    -------
    critical : list of list of tuple
        ``critical[k]`` lists the critical k-simplices (lexicographic order).
    boundaries : list of scipy.sparse.csc_matrix
        ``boundaries[k]`` is the int64 sparse matrix of ∂̃_k (rows: critical (k-1)-simplices,
        columns: critical k-simplices); ``boundaries[0]`` has no rows.

    Raises
    ------
    ValueError
        A cyclic or invalid vector field, or coefficients neither 0 nor a prime.

    Notes
    -----
    Orientations are those of Definition 2.18 (vertices ascending).  Integer entries are exact in
    int64 (sums of ±1 over gradient paths).

    Examples
    --------
    The Morse complex of RP² from a matching with one critical simplex per dimension: Z ← Z ← Z with
    ∂̃_1 = 0 and ∂̃_2 = 2 (the two gradient paths from the triangle agree in sign):

    >>> from thesis_lib.datasets import rp2
    >>> from thesis_lib.morse import morse_matching
    >>> critical, boundaries = morse_boundary(rp2(), morse_matching(rp2()))
    >>> critical
    [[(0,)], [(1, 2)], [(3, 4, 5)]]
    >>> [b.toarray().tolist() for b in boundaries[1:]]
    [[[0]], [[2]]]
    """
    return _morse_boundary(simplices, pairs, parse_field(coefficients, max_prime=MAX_EXACT_PRIME))


def _morse_boundary(simplices: ComplexLike, pairs: Pairs,
                    field: Field) -> tuple[list[list[Simplex]], list[sp.csc_matrix]]:
    """:func:`morse_boundary` with the coefficients parsed."""
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    crit, mats = morse_boundary_ids(cx, partner, field.p)
    return [[cx.simplex(int(g)) for g in ids] for ids in crit], mats


def _integer_matrix(m, k: int) -> sp.csc_matrix:
    """Boundary ``k`` as an int64 CSC matrix; ValueError for entries that are not integers or exceed int64."""
    mat = sp.csc_matrix(m)
    data = mat.data
    if data.dtype == object or not (np.issubdtype(data.dtype, np.number) or data.dtype == bool):
        raise ValueError(f"boundary {k} must hold integers in int64, got dtype {data.dtype}")
    if data.size and not np.issubdtype(data.dtype, np.integer) and data.dtype != bool:
        if not np.all(np.isfinite(data)) or not np.all(data == np.round(data)) or np.abs(data).max() >= 2**53:
            raise ValueError(f"boundary {k} has entries that are not integers")
    if data.size and data.dtype == np.uint64 and data.max() >= 2**63:
        raise ValueError(f"boundary {k} has entries beyond int64")
    return mat.astype(np.int64)


def _first_nonzero_of_product(a: sp.csc_matrix, b: sp.csc_matrix, p: int) -> tuple[int, int] | None:
    """An entry (i, j) of a @ b that is nonzero (mod p if p), exactly; None if the product is zero."""
    big_a = int(np.abs(a.data).max()) if a.nnz else 0
    big_b = int(np.abs(b.data).max()) if b.nnz else 0
    if big_a * big_b * max(1, a.shape[1]) < 2**62:  # int64 is exact
        prod = (a @ b).tocoo()
        vals = prod.data % p if p else prod.data
        hit = np.flatnonzero(vals)
        return (int(prod.row[hit[0]]), int(prod.col[hit[0]])) if hit.size else None
    acc: dict[tuple[int, int], int] = {}
    ca, rb = a.tocsc(), b.tocsr()
    for k in range(a.shape[1]):  # exact Python integers, one inner index at a time
        for i, x in zip(ca.indices[ca.indptr[k]:ca.indptr[k + 1]], ca.data[ca.indptr[k]:ca.indptr[k + 1]]):
            for j, y in zip(rb.indices[rb.indptr[k]:rb.indptr[k + 1]], rb.data[rb.indptr[k]:rb.indptr[k + 1]]):
                acc[(int(i), int(j))] = acc.get((int(i), int(j)), 0) + int(x) * int(y)
    for key, v in acc.items():
        if (v % p if p else v):
            return key
    return None


def chain_complex_homology(boundaries: Sequence[npt.ArrayLike | sp.spmatrix],
                           *, coefficients: int = 0) -> list[tuple[int, list[int]]]:
    """Homology of a finite chain complex given by its boundary matrices ``boundaries[k]: C_k → C_{k-1}``.

    Thesis: Definition 2.19 / Theorem 2.20 (Betti numbers and torsion from Smith normal forms).

    Parameters
    ----------
    boundaries : sequence of array_like or scipy.sparse matrices
        ``boundaries[k]`` the integer matrix of ∂_k (rows: (k-1)-cells, columns: k-cells);
        ``boundaries[0]`` gives the number of 0-chains by its column count.  Consecutive shapes
        must match and ∂_{k-1}∂_k = 0 (exactly over Z, mod p over Z/p).
    coefficients : int, default 0
        0 for Z (Smith normal form, with torsion), a prime p for Z/p.

    Returns
    -------
    list of (int, list of int)
        Per dimension ``(betti, torsion)``, like :func:`thesis_lib.homology.homology`.

    Raises
    ------
    ValueError
        Not a sequence of 2-D integer matrices, mismatched shapes, ∂∂ ≠ 0 (an entry named), an
        empty complex, or coefficients neither 0 nor a prime.

    Examples
    --------
    The chain complex Z ← Z ← Z with ∂_1 = 0 and ∂_2 = 2, the Morse complex of RP²:

    >>> import numpy as np
    >>> boundaries = [np.zeros((0, 1), dtype=int), np.array([[0]]), np.array([[2]])]
    >>> chain_complex_homology(boundaries)
    [(1, []), (0, [2]), (0, [])]
    """
    field = parse_field(coefficients, max_prime=MAX_EXACT_PRIME)
    p = field.p
    if isinstance(boundaries, (str, bytes)) or not isinstance(boundaries, Sequence):
        raise ValueError("boundaries must be a sequence of matrices, boundaries[k]: C_k -> C_{k-1}")
    mats = []
    for k, b in enumerate(boundaries):
        try:
            m = b if sp.issparse(b) else np.asarray(b)
        except (TypeError, ValueError) as err:
            raise ValueError(f"boundary {k} is not a matrix: {err}") from None
        if m.ndim != 2:
            raise ValueError(f"boundary {k} must be a 2-D matrix, got shape {m.shape}")
        mats.append(m)
    if not mats:
        raise ValueError("the chain complex is empty")
    sizes = [m.shape[1] for m in mats]
    for k in range(1, len(mats)):
        if mats[k].shape[0] != sizes[k - 1]:
            raise ValueError(f"boundary {k} has {mats[k].shape[0]} rows but C_{k - 1} has {sizes[k - 1]} cells")
    mats = [_integer_matrix(m, k) for k, m in enumerate(mats)]
    for k in range(2, len(mats)):  # a chain complex: ∂_{k-1} ∂_k = 0 (exactly over Z, mod p over Z/p)
        hit = _first_nonzero_of_product(mats[k - 1], mats[k], p)
        if hit is not None:
            i, j = hit
            raise ValueError(f"not a chain complex: ∂_{k - 1} ∂_{k} != 0 (entry ({i}, {j})); "
                             "homology needs ∂∂ = 0 (§2.2.1)")
    return _chain_homology(mats, field)


def _chain_homology(mats: list[sp.csc_matrix], field: Field) -> list[tuple[int, list[int]]]:
    """:func:`chain_complex_homology` of checked int64 CSC boundaries (a chain complex), ``field`` parsed."""
    sizes = [m.shape[1] for m in mats]
    ranks, torsion = [0], [[]]
    for m in mats[1:]:
        m.sum_duplicates()
        m.eliminate_zeros()
        m.sort_indices()
        red = reduce_checked(m, field=field) if m.nnz else None
        ranks.append(red.rank if red else 0)
        torsion.append(sorted(int(x) for x in red.invariants) if red else [])
    ranks.append(0)
    torsion.append([])
    return [(int(sizes[k] - ranks[k] - ranks[k + 1]), torsion[k + 1]) for k in range(len(mats))]


def morse_homology(simplices: ComplexLike, pairs: Pairs, *, coefficients: int = 0) -> list[tuple[int, list[int]]]:
    """Homology from the critical simplices and the gradient paths between them.

    Thesis: Theorem 4.42 with Theorems 4.39 and 4.41 (H_k of the Morse complex ≅ H_k(K)).

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and an acyclic vector field on it, e.g. from
        :func:`~thesis_lib.morse.matching.morse_matching`; passed to :func:`morse_boundary`.
    coefficients : int, default 0
        0 for Z, a prime p for Z/p.

    Returns
    -------
    list of (int, list of int)
        Per dimension ``(betti, torsion)``, the format of :func:`thesis_lib.homology.homology`.

    Raises
    ------
    ValueError
        The vector field has a closed V-path or is invalid; coefficients neither 0 nor a prime.

    Examples
    --------
    Homology of RP² from three critical simplices (Theorem 4.42): Z, Z/2, 0 over Z; Z/2 in every
    dimension over Z/2:

    >>> from thesis_lib.datasets import rp2
    >>> from thesis_lib.morse import morse_matching
    >>> pairs = morse_matching(rp2())
    >>> morse_homology(rp2(), pairs)
    [(1, []), (0, [2]), (0, [])]
    >>> morse_homology(rp2(), pairs, coefficients=2)
    [(1, []), (1, []), (1, [])]
    """
    field = parse_field(coefficients, max_prime=MAX_EXACT_PRIME)
    return _chain_homology(_morse_boundary(simplices, pairs, field)[1], field)

"""Persistent Betti numbers straight from Definition 2.23, by ranks of boundary matrices.

An independent route to the numbers the barcode gives (Theorem 2.37): no reduction of the
filtration, no pairing, only ranks over Z/p of sub-matrices of the boundary matrices of the
complexes K^l and K^{l+k} of the filtration (``K^l`` = the simplices of value ≤ l).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from .._validate import resolve_coefficients
from ..filtration import Filtration, as_complex
from ..simplicial import boundary_matrix
from ..smith import rank_mod_p

__all__ = ["persistent_betti_by_definition"]


def _rank(matrix, p: int) -> int:
    return 0 if min(matrix.shape) == 0 or matrix.nnz == 0 else rank_mod_p(matrix, p)


def persistent_betti_by_definition(filtration: Filtration | Iterable[Any], l: float, k: float, dim: int, *,
                                   coefficients: int = 2) -> int:
    """Rank of H_p^{l,k} = Z_p^l / (B_p^{l+k} ∩ Z_p^l), computed from boundary matrices.

    Thesis: Definition 2.23 (the k-persistent p-th homology group of K^l).

    ``rank Z_p^l`` is the number of p-simplices of K^l minus the rank of ∂_p on them.
    ``B_p^{l+k} ∩ Z_p^l`` is the set of boundaries of K^{l+k} that lie in C_p(K^l); its dimension is
    ``rank ∂_{p+1} − rank P∂_{p+1}``, where ∂_{p+1} is taken on the (p + 1)-simplices of K^{l+k} and P
    keeps only the rows of p-simplices outside K^l (a boundary lies in C_p(K^l) iff P kills it).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        Anything :func:`~thesis_lib.filtration.as_complex` takes.
    l : float
        The filtration value of K^l.
    k : float
        The persistence, ≥ 0.
    dim : int
        The homology dimension p, ≥ 0.
    coefficients : int, default 2
        A prime: the field Z/p.

    Returns
    -------
    int
        β_p^{l,k}, the rank of H_p^{l,k} over Z/p.

    Raises
    ------
    ValueError
        ``k`` negative or NaN, ``dim`` negative, or ``coefficients`` not a prime.
    """
    K = as_complex(filtration)
    p = resolve_coefficients(coefficients, default=2, field=True)
    l, k = float(l), float(k)
    if np.isnan(l) or np.isnan(k) or k < 0:
        raise ValueError(f"l must be a number and k a non-negative number, got l = {l}, k = {k}")
    if int(dim) != dim or dim < 0:
        raise ValueError(f"dim must be a non-negative integer, got {dim}")
    dim = int(dim)
    if dim > K.dimension:
        return 0
    simplices, values = K.simplices[dim], K.values[dim]
    in_l = values <= l
    n_l = int(np.count_nonzero(in_l))
    if dim == 0:
        rank_z = n_l
    else:
        rank_z = n_l - _rank(boundary_matrix(K.simplices[dim - 1], simplices[in_l], coefficients=p), p)
    if dim + 1 > K.dimension:
        return rank_z
    upper = K.simplices[dim + 1][K.values[dim + 1] <= l + k]
    d = boundary_matrix(simplices, upper, coefficients=p).tocsr()
    rank_b_in_l = _rank(d, p) - _rank(d[np.flatnonzero(~in_l)], p)
    return rank_z - rank_b_in_l

"""Persistent Betti numbers straight from Definition 2.23, by ranks of boundary matrices.

An independent route to the numbers the barcode gives (Theorem 2.37): no reduction of the
filtration, no pairing, only ranks over Z/p of sub-matrices of the boundary matrices of the
complexes K^l and K^{l+k} of the filtration (``K^l`` = the simplices of value ≤ l).  Beside the
rank itself: grids of it over values of l and k, the same grids counted off a barcode, the count of
the cases where the two differ, and what the Betti numbers of the K^l alone show (§2.3.1).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validate import resolve_coefficients
from ..homology.filtration import Filtration, as_complex
from ..homology.simplicial import boundary_matrix
from ..homology.smith import rank_mod_p
from .algorithm import compute_intervals
from .barcode import Barcode

__all__ = [
    "persistent_betti_by_definition",
    "persistent_betti_grid",
    "barcode_betti_grid",
    "barcode_definition_mismatches",
    "definition_mismatches",
    "BettiVersusBarcode",
    "betti_versus_barcode",
]


def _rank(matrix, p: int) -> int:
    return 0 if min(matrix.shape) == 0 or matrix.nnz == 0 else rank_mod_p(matrix, coefficients=p)


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
        Anything :func:`~thesis_lib.homology.filtration.as_complex` takes.
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


def persistent_betti_grid(filtration: Filtration | Iterable[Any], *, ls: Iterable[float], ks: Iterable[float],
                          dim: int, coefficients: int = 2) -> list[list[int]]:
    """β_dim^{l,k} by Definition 2.23 for every l of ``ls`` (rows) and k of ``ks`` (columns).

    Thesis: Definition 2.23 (the k-persistent p-th Betti number of K^l).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        Anything :func:`~thesis_lib.homology.filtration.as_complex` takes.
    ls : iterable of float
        The filtration values l, one row each.
    ks : iterable of float
        The persistences k ≥ 0, one column each.
    dim : int
        The homology dimension p.
    coefficients : int, default 2
        A prime: the field Z/p.

    Returns
    -------
    list of list of int
        ``grid[i][j]`` = β_dim^{ls[i], ks[j]}, as :func:`persistent_betti_by_definition` computes it.

    Examples
    --------
    >>> from thesis_lib.datasets import module_filtration
    >>> persistent_betti_grid(module_filtration([(0, 2)]), ls=[0, 1, 2], ks=[0, 1, 2], dim=1)
    [[1, 1, 0], [1, 0, 0], [0, 0, 0]]
    """
    K = as_complex(filtration)
    columns = list(ks)
    return [[persistent_betti_by_definition(K, l, k, dim, coefficients=coefficients) for k in columns] for l in ls]


def barcode_betti_grid(barcode: Barcode, *, ls: Iterable[float], ks: Iterable[float], dim: int) -> list[list[int]]:
    """The number of bars of ``dim`` spanning [l, l + k] for every l of ``ls`` (rows) and k of ``ks`` (columns).

    Thesis: Theorem 2.37 (that number is the rank of H_p^{l,k}).

    Parameters
    ----------
    barcode : Barcode
        The barcode to count in.
    ls : iterable of float
        The filtration values l, one row each.
    ks : iterable of float
        The persistences k ≥ 0, one column each.
    dim : int
        The homology dimension.

    Returns
    -------
    list of list of int
        ``grid[i][j]`` = :meth:`Barcode.persistent_betti` ``(ls[i], ks[j], dim)``.

    Examples
    --------
    >>> barcode_betti_grid(Barcode({1: [(0.0, 2.0), (1.0, 3.0)]}), ls=[1.0, 2.0], ks=[0.0, 1.5], dim=1)
    [[2, 1], [1, 0]]
    """
    columns = list(ks)
    return [[barcode.persistent_betti(l, k, dim=dim) for k in columns] for l in ls]


def barcode_definition_mismatches(barcode: Barcode, filtration: Filtration | Iterable[Any], *, ls: Iterable[float],
                                  ks: Iterable[float], dims: Iterable[int],
                                  squared_values: bool = False) -> tuple[int, int]:
    """Cases (l, k, dim) where a barcode's count of bars differs from the rank of Definition 2.23.

    Thesis: Theorem 2.37 (the rank of H_p^{l,k} is the number of bars spanning [l, l + k]).

    Parameters
    ----------
    barcode : Barcode
        The barcode whose bars are counted; its field ``barcode.coefficients`` (Z/2 when unknown) is the field of
        the ranks.
    filtration : Filtration or iterable of (simplex, value) pairs
        The filtration whose ranks are computed.
    ls : iterable of float
        The filtration values l of the barcode.
    ks : iterable of float
        The persistences k ≥ 0 of the barcode.
    dims : iterable of int
        The homology dimensions.
    squared_values : bool, default False
        The filtration's values are the squares of the barcode's (an alpha filtration beside the
        barcode of the Čech filtration of the same points, Theorem 2.15): the rank is taken at
        (l², (l + k)² − l²).

    Returns
    -------
    cases : int
        The number of triples (l, k, dim) compared.
    mismatches : int
        How many of them differ.

    Examples
    --------
    >>> from thesis_lib.datasets import example_filtration
    >>> K = example_filtration()
    >>> barcode_definition_mismatches(compute_intervals(K), K, ls=range(5), ks=range(3), dims=(0, 1))
    (30, 0)
    """
    K = as_complex(filtration)
    p = barcode.coefficients or 2
    cases = [(float(l), float(k), int(d)) for l in ls for k in ks for d in dims]
    if squared_values:
        ranks = [persistent_betti_by_definition(K, l * l, (l + k) ** 2 - l * l, d, coefficients=p) for l, k, d in cases]
    else:
        ranks = [persistent_betti_by_definition(K, l, k, d, coefficients=p) for l, k, d in cases]
    bad = sum(barcode.persistent_betti(l, k, dim=d) != rank for (l, k, d), rank in zip(cases, ranks))
    return len(cases), int(bad)


def definition_mismatches(filtrations: Iterable[Filtration | Iterable[Any]], *, ls: Iterable[float],
                          ks: Iterable[float], dims: Iterable[int], fields: Iterable[int] = (2,)) -> tuple[int, int]:
    """Cases (filtration, field, l, k, dim) where the intervals of Algorithms 1–2 miscount the rank of Definition 2.23.

    Thesis: Theorems 2.37 and 2.39 (the intervals read off the pivots give the persistent Betti numbers).

    Parameters
    ----------
    filtrations : iterable of Filtration
        The filtrations (anything :func:`~thesis_lib.homology.filtration.as_complex` takes).
    ls : iterable of float
        The filtration values l.
    ks : iterable of float
        The persistences k ≥ 0.
    dims : iterable of int
        The homology dimensions.
    fields : iterable of int, default (2,)
        The primes p: each filtration is reduced by :func:`compute_intervals` over each Z/p.

    Returns
    -------
    cases : int
        The number of cases compared.
    mismatches : int
        How many of them differ.

    Examples
    --------
    >>> from thesis_lib.datasets import example_filtration
    >>> definition_mismatches([example_filtration()], ls=range(6), ks=range(6), dims=(0, 1), fields=(2, 3))
    (144, 0)
    """
    ls, ks, dims, fields = list(ls), list(ks), list(dims), list(fields)
    cases = bad = 0
    for filtration in filtrations:
        K = as_complex(filtration)
        for p in fields:
            n, b = barcode_definition_mismatches(compute_intervals(K, coefficients=p), K, ls=ls, ks=ks, dims=dims)
            cases, bad = cases + n, bad + b
    return cases, bad


@dataclass(frozen=True)
class BettiVersusBarcode:
    """What the Betti numbers of the complexes K^l show of a filtration, beside its barcode (§2.3.1).

    Attributes: ``betti`` (β_dim of K^l for each l asked for), ``n_bars`` (the bars of ``dim``) and
    ``persistent_betti`` (β_dim^{l,k} by Definition 2.23 at the l and k asked for).
    """

    betti: tuple[int, ...]
    n_bars: int
    persistent_betti: int


def betti_versus_barcode(filtration: Filtration | Iterable[Any], *, steps: Iterable[float], dim: int, l: float,
                         k: float, coefficients: int = 2) -> BettiVersusBarcode:
    """The Betti numbers of the K^l, the number of bars and one persistent Betti number of a filtration.

    Thesis: §2.3.1 (a cycle may die when another is born; β_p^l as a function of l does not show it).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        Anything :func:`~thesis_lib.homology.filtration.as_complex` takes.
    steps : iterable of float
        The values l at which β_dim of K^l is taken (β_dim^{l,0} of Definition 2.23).
    dim : int
        The homology dimension p.
    l : float
        Where the persistent Betti number is taken ...
    k : float
        ... and for which persistence.
    coefficients : int, default 2
        A prime: the field Z/p.

    Returns
    -------
    BettiVersusBarcode
        The Betti numbers, the number of bars of :func:`compute_intervals` and β_dim^{l,k}.

    Examples
    --------
    >>> from thesis_lib.datasets import module_filtration
    >>> betti_versus_barcode(module_filtration([(0, 2), (2, None)]), steps=range(4), dim=1, l=0, k=2)
    BettiVersusBarcode(betti=(1, 1, 1, 1), n_bars=2, persistent_betti=0)
    """
    K = as_complex(filtration)
    betti = tuple(persistent_betti_by_definition(K, value, 0, dim, coefficients=coefficients) for value in steps)
    n_bars = int(compute_intervals(K, coefficients=coefficients).intervals(dim).shape[0])
    return BettiVersusBarcode(betti, n_bars, persistent_betti_by_definition(K, l, k, dim, coefficients=coefficients))

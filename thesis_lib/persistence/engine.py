"""The fast persistence engine: union–find for H0, then cohomology column reduction with clearing.

Same barcode as :func:`~thesis_lib.persistence.algorithm.compute_intervals` on every input (the
pairs of the boundary and the coboundary reductions coincide, de Silva–Morozov–Vejdemo-Johansson
2011), but with

* the order of each dimension by one stable ``argsort`` (only the order *within* a dimension
  matters: a column of dimension d only ever meets rows of dimension d ± 1);
* facets found through a dense edge table (triangles; fused with the matrix assembly, so no facet
  array is stored) or a hash table (higher dimensions), and the coboundary matrix assembled as
  compressed sparse columns by a counting sort (two sequential passes over the cofaces, which also
  find each column's pivot);
* H0 by union–find with the elder rule (the pairs of Reduce on the edge columns);
* dimensions d ≥ 1 on the cohomology side, latest simplex first, pivot = earliest coface;
  columns of simplices already paired one dimension lower are cleared (skipped), columns whose
  pivot is still free (apparent/emergent pairs, the common case) are paired without any work,
  and only colliding columns are reduced, lazily as in Ripser (Bauer 2021): a heap of coface
  entries, added columns kept as combinations V of original coboundaries, in the library's one
  stored-matrix reduction loop (:func:`~thesis_lib.persistence.kernels.reduce_columns`).

The kernels (union–find, coboundary assembly, reduction) are compiled C++: ``src/explicit_cohomology.cpp``
and ``src/reduction.cpp``.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from .._core import explicit_cohomology
from .._validate import Field, check_min_persistence, parse_field
from ..homology.filtration import Filtration, as_complex
from .barcode import Barcode
from .kernels import KEEP_V, reduce_columns

__all__ = ["persistence", "filtration_barcode"]


# ---------------------------------------------------------------------------- coboundary columns
def _coboundary_matrix(K, d: int, up_values: np.ndarray):
    """(indptr, rows, signs, pivot, pivot_sign) of δ on the d-simplices of K (compiled:
    :func:`explicit_cohomology.coboundary`; edges through a dense edge table when it is small)."""
    m_d = K.simplices[d].shape[0]
    if d == 1:  # edges: the triangles' facets through a dense edge table, fused with the assembly
        lower, upper = K.simplices[1], K.simplices[2]
        n = int(max(lower.max(initial=0), upper.max(initial=0))) + 1
        if n * n <= max(1 << 22, 8 * lower.shape[0]):
            out = explicit_cohomology.coboundary_triangles(
                np.ascontiguousarray(lower, dtype=np.int64), np.ascontiguousarray(upper, dtype=np.int64), n, up_values
            )
            if out[5] >= 0:
                t = upper[out[5]]
                raise ValueError(f"an edge of the triangle {tuple(int(v) for v in t)} is missing from the filtration")
            return out[:5]
    return explicit_cohomology.coboundary(np.ascontiguousarray(K.facet_indices(d + 1), dtype=np.int64), up_values, m_d)


# ---------------------------------------------------------------------------- driver
def persistence(filtration: Filtration | Iterable[Any], *, coefficients: int | None = None,
                stats: dict[int, dict[str, int]] | None = None, min_persistence: float = 0.0) -> Barcode:
    """Barcode of a filtration over Z/p by the fast engine (same result as :func:`compute_intervals`).

    Thesis: Theorem 2.39 / Algorithm 2, §2.3.5 (the same pairs, computed by the dual reduction).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        A :class:`~thesis_lib.homology.filtration.Filtration` (e.g. from :func:`~thesis_lib.complexes.rips`),
        or anything :func:`~thesis_lib.homology.filtration.as_complex` takes.
    coefficients : int, optional
        A prime p: the field Z/p (default 2).
    stats : dict, optional
        Filled per dimension d < dim K with ``{"columns": ..., "additions": ...}`` (columns of the
        reduction after clearing, column additions).
    min_persistence : float
        Intervals with ``death − birth <= min_persistence`` are left out (default 0: only the
        zero-length ones); e.g. 1e-12 drops the bars of length ~1e-16 that tied distances give.

    Returns
    -------
    Barcode
        Dimensions 0 .. dim K with the creating and killing simplices of every interval (for
        :meth:`~Barcode.representative`); the top dimension is listed as complete unless the
        filtration is ``truncated``.

    Raises
    ------
    ValueError
        A complex :func:`~thesis_lib.homology.filtration.as_complex` refuses, ``coefficients`` not a prime, a
        triangle with a missing edge, or more than 2³¹ − 1 simplices in one dimension.

    Notes
    -----
    A filtration cut at ``max_dim`` (``filtration.truncated``, set by
    :func:`~thesis_lib.complexes.rips`) has an incomplete top dimension: the barcode marks it
    (``complete_dimensions``) and shows it only when asked.
    The top dimension's essential classes (a truncated Rips complex has millions) are listed lazily:
    they are sorted into ``intervals(dim K)`` only when first asked for.  Memory: the coboundary
    matrix of one dimension at a time (4 + 1 bytes per incidence) plus one int32 per coface.

    A filtration built by :func:`~thesis_lib.complexes.rips` is reduced here, not by the implicit
    engine of :func:`~thesis_lib.persistence.rips_persistence`: only this engine knows the simplex
    of every pair (:meth:`~Barcode.simplex_pairs`, :meth:`~Barcode.representative`) and the top
    dimension.  Both give the same intervals, to the last bit.

    Examples
    --------
    >>> from thesis_lib.complexes import rips
    >>> square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    >>> persistence(rips(square, max_dim=2)).intervals(1).tolist()
    [[0.5, 0.7071067811865476]]
    """
    K, field = as_complex(filtration), parse_field(coefficients, default=2, field=True)
    return filtration_barcode(K, field, stats=stats, min_persistence=check_min_persistence(min_persistence))


def filtration_barcode(K: Filtration, field: Field, *, stats: dict[int, dict[str, int]] | None = None,
                       min_persistence: float = 0.0) -> Barcode:
    """:func:`persistence` on parsed input: a non-empty :class:`~thesis_lib.homology.filtration.Filtration`
    and a parsed prime field (the loops that take many barcodes of one complex call this).

    Thesis: Theorem 2.39 / Algorithm 2, §2.3.5 (the same pairs, computed by the dual reduction).

    Parameters
    ----------
    K : Filtration
        The filtration (``as_complex`` already applied).
    field : Field
        The parsed coefficients, a prime.
    stats : dict, optional
        Filled as by :func:`persistence`.
    min_persistence : float
        The checked ``min_persistence`` of :func:`persistence`.

    Returns
    -------
    Barcode
        As :func:`persistence`.

    Raises
    ------
    ValueError
        A triangle with a missing edge, or more than 2³¹ − 1 simplices in one dimension.
    """
    p = field.p
    D = K.dimension
    # the order within each dimension (value, then index); the top dimension is never a column
    orders = [np.argsort(K.values[d], kind="stable") for d in range(D)]
    intervals: dict[int, np.ndarray] = {}
    pairs: dict[int, np.ndarray] = {}
    killers: dict[int, np.ndarray] = {}
    inf = np.inf

    def finish(d: int, born: np.ndarray, dies: np.ndarray, essential: np.ndarray) -> None:
        intervals[d] = np.empty((born.shape[0] + essential.shape[0], 2))
        if born.shape[0]:
            intervals[d][: born.shape[0], 0] = K.values[d][born]
            intervals[d][: born.shape[0], 1] = K.values[d + 1][dies]
        intervals[d][born.shape[0] :, 0] = K.values[d][essential]
        intervals[d][born.shape[0] :, 1] = inf
        pairs[d] = np.empty((born.shape[0] + essential.shape[0], 2), dtype=np.int64)
        pairs[d][: born.shape[0], 0] = born
        pairs[d][: born.shape[0], 1] = dies
        pairs[d][born.shape[0] :, 0] = essential
        pairs[d][born.shape[0] :, 1] = -1
        killers[d] = dies

    empty = np.empty(0, dtype=np.int64)
    if D == 0:
        finish(0, empty, empty, np.arange(K.simplices[0].shape[0]))
        return Barcode(intervals, dimensions=[0], coefficients=field, simplices=pairs, filtration=K, killers=killers,
                       min_persistence=min_persistence)
    # ---- H0 by union-find (the pairs Reduce finds on the edge columns)
    vrank = np.empty(K.simplices[0].shape[0], dtype=np.int64)
    vrank[orders[0]] = np.arange(orders[0].shape[0])
    order1 = orders[1] if D > 1 else np.argsort(K.values[1], kind="stable")
    pv, pe, cleared, ess = explicit_cohomology.h0(np.ascontiguousarray(K.facet_indices(1), dtype=np.int64), vrank,
                                                  np.ascontiguousarray(order1, dtype=np.int64))
    finish(0, pv, pe, ess)
    if stats is not None:
        stats[0] = {"columns": int(K.simplices[1].shape[0]), "additions": 0}
    # ---- dimensions 1 .. D-1 by cohomology with clearing
    for d in range(1, D):
        m_d = K.simplices[d].shape[0]
        if max(K.simplices[d + 1].shape[0], m_d) >= 2**31 - 1:
            raise ValueError("more than 2**31 simplices in one dimension are not supported")
        up_values = np.ascontiguousarray(K.values[d + 1])
        indptr, rows, signs, pivot, pivot_sign = _coboundary_matrix(K, d, up_values)
        # cohomology: latest d-simplex first, pivot = earliest coface (rows ordered by value, then index)
        born, dies, essential, adds, *_ = reduce_columns(
            indptr, rows, signs, up_values, np.ascontiguousarray(orders[d][::-1]), cleared, pivot, pivot_sign,
            np.int64(p), KEEP_V,
        )
        del indptr, rows, signs, pivot, pivot_sign
        finish(d, born, dies, essential)
        if stats is not None:
            stats[d] = {"columns": int(m_d - cleared.sum()), "additions": int(adds)}
        cleared = np.zeros(K.simplices[d + 1].shape[0], dtype=np.bool_)
        cleared[dies] = True
    # ---- top dimension: every simplex not killing a class creates an essential one (listed lazily:
    # often millions of classes of a truncated complex, which nobody reads)
    essential_top = {D: (K.values[D], ~cleared)}
    return Barcode(
        intervals, dimensions=range(D + 1), coefficients=field, simplices=pairs, filtration=K, killers=killers,
        essential=essential_top,
        complete=range(D if getattr(K, "truncated", False) else D + 1), min_persistence=min_persistence,
    )

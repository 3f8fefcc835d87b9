"""Apparent pairs of a filtration: the discrete gradient that the implicit Rips engine exploits.

A pair σ < τ (σ a facet of τ) is *apparent* when σ is the latest facet of τ and τ the earliest
coface of σ in the filtration order.  Every apparent pair is a persistence pair (the column of τ
reduces to σ at once in homology, the column of σ to τ in cohomology), the pairs are disjoint, and
along a V-path the filtration order strictly decreases, so they form an acyclic matching: a
discrete gradient vector field (thesis Definitions 4.30–4.33, Theorem 4.36).  Its critical cells
are what a reduction must look at; the barcode is that of the Morse complex on them (Theorem 4.42's
idea), which is how :func:`~thesis_lib.persistence.rips_persistence` skips most of a Rips complex.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from ..homology.filtration import Filtration, as_complex

__all__ = ["apparent_pairs", "apparent_summary"]


def _pairs_by_index(K) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """Per dimension d ≥ 1: (d, σ indices in dimension d − 1, τ indices in dimension d) of the apparent pairs."""
    out = []
    for d in range(1, K.dimension + 1):
        F = K.facet_indices(d)
        pos_lo, pos_up = K.positions[d - 1], K.positions[d]
        latest = F[np.arange(F.shape[0]), np.argmax(pos_lo[F], axis=1)]  # latest facet of each τ
        first = np.full(K.simplices[d - 1].shape[0], np.iinfo(np.int64).max, dtype=np.int64)
        np.minimum.at(first, F.ravel(), np.repeat(pos_up, d + 1))  # earliest coface position of each σ
        tau = np.arange(F.shape[0])
        ok = first[latest] == pos_up[tau]  # τ is also the earliest coface of its latest facet
        out.append((d, latest[ok], tau[ok]))
    return out


def apparent_pairs(filtration: Filtration | Iterable[Any], *,
                   zero: bool = False) -> list[tuple[tuple[int, ...], tuple[int, ...]]]:
    """The apparent pairs ``(σ, τ)`` of a filtration, in its order (``Filtration.order``).

    Thesis: Definitions 4.30–4.33 (the pairs are a discrete vector field, and an acyclic one:
    Theorem 4.36), used as in the Summary, "to reduce the size of simplicial complexes".

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        A :class:`~thesis_lib.homology.filtration.Filtration` (or anything
        :func:`~thesis_lib.homology.filtration.as_complex` takes).
    zero : bool
        Only the pairs whose two simplices have the same value (zero persistence: the ones the
        implicit engine never makes columns).

    Returns
    -------
    list of (tuple of int, tuple of int)
        The pairs ``(sigma, tau)`` as vertex tuples, σ a facet of τ, by increasing dimension of τ
        and, within one, by τ's index in ``filtration.simplices``.

    Examples
    --------
    The Rips filtration of the unit square: each vertex but the first is paired with an edge, and each
    diagonal with a triangle:

    >>> from thesis_lib.complexes import rips
    >>> square = rips([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], max_radius=1.0, max_dim=2)
    >>> pairs = apparent_pairs(square)
    >>> len(pairs), pairs[:4]
    (5, [((1,), (0, 1)), ((3,), (0, 3)), ((2,), (1, 2)), ((0, 2), (0, 1, 2))])
    """
    K = as_complex(filtration)
    pairs = []
    for d, lo, up in _pairs_by_index(K):
        if zero:
            keep = K.values[d - 1][lo] == K.values[d][up]
            lo, up = lo[keep], up[keep]
        S, T = K.simplices[d - 1], K.simplices[d]
        pairs += [(tuple(S[a].tolist()), tuple(T[b].tolist())) for a, b in zip(lo.tolist(), up.tolist())]
    return pairs


def apparent_summary(filtration: Filtration | Iterable[Any]) -> dict[str, Any]:
    """How much of a filtration its apparent pairs leave critical, per dimension and in all.

    Thesis: Definition 4.21 (critical cells) and Theorem 4.27 (Crit_k ≥ β_k), for the gradient of
    :func:`apparent_pairs`.

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        A :class:`~thesis_lib.homology.filtration.Filtration` (or anything
        :func:`~thesis_lib.homology.filtration.as_complex` takes).

    Returns
    -------
    dict
        With ``simplices``, ``critical`` and ``zero_critical`` (lists per dimension: all cells,
        those in no apparent pair, those in no zero-persistence apparent pair), the fractions
        ``critical_fraction`` and ``zero_critical_fraction`` of all cells, and the same fractions of the
        cells below the top dimension (``*_below_top``): those are the columns a cohomology reduction
        works on (a truncated complex's top simplices are only rows: their cofaces were never built).

    Examples
    --------
    The same square as in :func:`apparent_pairs`: one vertex, one edge and two triangles are left
    critical:

    >>> from thesis_lib.complexes import rips
    >>> square = rips([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], max_radius=1.0, max_dim=2)
    >>> summary = apparent_summary(square)
    >>> summary["simplices"], summary["critical"], round(summary["critical_fraction"], 6)
    ([4, 6, 4], [1, 1, 2], 0.285714)
    """
    K = as_complex(filtration)
    counts = K.counts()
    paired = [np.zeros(c, dtype=bool) for c in counts]
    zpaired = [np.zeros(c, dtype=bool) for c in counts]
    for d, lo, up in _pairs_by_index(K):
        zero = K.values[d - 1][lo] == K.values[d][up]
        paired[d - 1][lo] = paired[d][up] = True
        zpaired[d - 1][lo[zero]] = zpaired[d][up[zero]] = True
    critical = [int((~p).sum()) for p in paired]
    zcritical = [int((~p).sum()) for p in zpaired]
    total, below = sum(counts), max(sum(counts[:-1]), 1)
    return {"simplices": counts, "critical": critical, "zero_critical": zcritical,
            "critical_fraction": sum(critical) / total, "zero_critical_fraction": sum(zcritical) / total,
            "critical_fraction_below_top": sum(critical[:-1]) / below,
            "zero_critical_fraction_below_top": sum(zcritical[:-1]) / below}

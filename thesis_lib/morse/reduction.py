"""Morse reduction of a filtration before persistence (the "simplify large complexes" use of §4.2.6).

A filtration-compatible acyclic matching pairs σ < τ only when both have the same filtration value.
Every gradient path then runs downwards in value, so the Morse complex (Theorem 4.42) is a filtered
chain complex on the critical simplices, each keeping its value; its barcode equals the barcode of the
filtration (each sublevel set's Morse complex is the restriction, Theorems 4.39/4.41).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import scipy.sparse as sp

from .._validate import InvalidTypeError, parse_field, resolve_coefficients
from ..homology.filtration import Filtration, as_complex
from ..persistence.barcode import Barcode
from ..persistence.chains import chain_barcode, chain_persistence
from ._cells import CellComplex, ComplexLike, Pairs, Simplex, partner_array
from ._gradient import morse_boundary_ids
from ._kernels import greedy_partner

__all__ = ["MorseReduction", "lower_star_filtration", "filtration_matching", "morse_reduce", "reduced_persistence",
           "chain_persistence"]


def _cells_and_values(filt: Filtration) -> tuple[CellComplex, np.ndarray]:
    cx = CellComplex(filt)
    return cx, (cx.values if cx.values is not None else np.zeros(cx.n))


def lower_star_filtration(simplices: ComplexLike, vertex_values: npt.ArrayLike) -> Filtration:
    """The lower-star filtration: each simplex enters at the largest value of its vertices.

    Thesis: §4.2.6 context (discrete Morse functions from vertex values; ProcessLowerStars).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        Any complex (a ``Filtration``, whose values are replaced, or simplices; all faces are
        added).
    vertex_values : array_like, shape (n_vertices,)
        One finite value per vertex label 0..max label.

    Returns
    -------
    Filtration
        The same simplices, each with the largest value of its vertices.

    Raises
    ------
    ValueError
        NaN/inf values, values that are not 1-D, or values not covering every vertex.

    Examples
    --------
    Vertex values 0, 2, 1 on a triangle: each edge and the triangle enter with their highest vertex:

    >>> f = lower_star_filtration([(0, 1, 2)], [0.0, 2.0, 1.0])
    >>> f.simplices[1].tolist(), [v.tolist() for v in f.values]
    ([[0, 1], [0, 2], [1, 2]], [[0.0, 2.0, 1.0], [2.0, 1.0, 2.0], [2.0]])
    """
    arrays = as_complex(simplices).simplices
    vals = np.asarray(vertex_values, dtype=np.float64)
    if vals.ndim != 1:
        raise ValueError(f"vertex values must be a 1-D array, got shape {vals.shape}")
    if not np.all(np.isfinite(vals)):
        raise ValueError("vertex values must be finite (no NaN or inf)")
    if int(arrays[0].max()) >= vals.shape[0]:
        raise ValueError(f"vertex values cover {vals.shape[0]} vertices but the complex uses vertex "
                         f"{int(arrays[0].max())}")
    return Filtration(arrays, [vals[a].max(axis=1) for a in arrays], validate=False)


def filtration_matching(filtration: ComplexLike) -> list[tuple[Simplex, Simplex]]:
    """An acyclic matching of the filtration's complex that only pairs simplices of equal value.

    Thesis: §4.2.6 (greedy gradient; minimising critical cells is NP-hard) and Theorem 4.36.

    Greedy coreduction inside every level set {σ : f(σ) = t}: a simplex whose only face of the same
    value is σ is paired with σ.  Along a V-path values never increase, and inside a level the
    coreduction order strictly decreases, so the field is acyclic.

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        The filtered complex (without values every simplex has the same value 0).

    Returns
    -------
    list of (tuple, tuple)
        The pairs ``(sigma, tau)``, sigma a facet of tau of the same value, ordered by sigma
        (dimension, then lexicographically).

    Examples
    --------
    On the lower-star filtration above, only the vertex 0 stays critical: every other simplex is
    paired with one of the same value:

    >>> f = lower_star_filtration([(0, 1, 2)], [0.0, 2.0, 1.0])
    >>> filtration_matching(f)
    [((1,), (0, 1)), ((2,), (0, 2)), ((1, 2), (0, 1, 2))]
    """
    filt = as_complex(filtration)
    cx, vals = _cells_and_values(filt)
    partner = greedy_partner(cx, "coreduction", vals=vals)
    low = np.flatnonzero(partner > np.arange(cx.n))
    return [(cx.simplex(int(a)), cx.simplex(int(partner[a]))) for a in low]


@dataclass
class MorseReduction:
    """The Morse (reduced) filtered chain complex of a filtration.

    Thesis: Theorem 4.41 (the Morse complex M_k on the critical simplices).

    Attributes
    ----------
    critical : ``critical[d]`` the ``(m_d, d + 1)`` array of critical d-simplices.
    values : ``values[d]`` their filtration values.
    boundaries : ``boundaries[d]`` the Morse boundary ∂̃_d (sparse int64, rows critical (d-1)-cells,
        columns critical d-cells), reduced mod p when ``coefficients`` is a prime p.
    n_cells : simplices of the original filtration.
    coefficients : coefficients of the boundaries (0 = Z, a prime p = Z/p).

    Examples
    --------
    What :func:`morse_reduce` returns: the critical simplices per dimension with their values and the
    Morse boundaries between them.

    >>> from thesis_lib.datasets import example_filtration
    >>> from thesis_lib.morse import morse_reduce
    >>> reduction = morse_reduce(example_filtration(), coefficients=2)
    >>> [c.shape[0] for c in reduction.critical], reduction.values[2].tolist()
    ([4, 5, 1], [4.0])
    """

    critical: list[np.ndarray]
    values: list[np.ndarray]
    boundaries: list[sp.csc_matrix]
    n_cells: int
    coefficients: int

    @property
    def n_critical(self) -> int:
        """Number of critical simplices (cells of the Morse complex).

        Examples
        --------
        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.morse import morse_reduce
        >>> morse_reduce(example_filtration(), coefficients=2).n_critical
        10
        """
        return int(sum(c.shape[0] for c in self.critical))

    @property
    def critical_fraction(self) -> float:
        """``n_critical / n_cells``: the share of the filtration left after the reduction.

        Examples
        --------
        The Rips filtration of 20 points near a circle keeps 70 % of its simplices after the reduction:

        >>> from thesis_lib.complexes import rips
        >>> from thesis_lib.datasets import noisy_circle
        >>> from thesis_lib.morse import morse_reduce
        >>> reduction = morse_reduce(rips(noisy_circle(20, noise=0.1, seed=0), max_radius=1.0, max_dim=2))
        >>> reduction.n_critical, reduction.n_cells, round(reduction.critical_fraction, 6)
        (711, 1009, 0.704658)
        """
        return self.n_critical / self.n_cells


def morse_reduce(filtration: ComplexLike, *, coefficients: int | None = None,
                 pairs: Pairs | None = None) -> MorseReduction:
    """Reduce a filtration to its filtered Morse complex (critical simplices + Morse boundary).

    Thesis: Theorems 4.41–4.42 (Morse complex on critical cells, boundary by gradient paths).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        The filtered complex (without values every simplex has the same value 0).
    coefficients : int, optional
        A prime p for Z/p (default 2); 0 keeps integer boundaries (then take
        :func:`reduced_persistence` with a prime).
    pairs : iterable of (sigma, tau), optional
        An acyclic matching to use instead of :func:`filtration_matching`, e.g. the
        ``"lower-star"`` matching of a lower-star filtration; every pair must have equal values.

    Returns
    -------
    MorseReduction
        The critical simplices with their values and the Morse boundaries.

    Raises
    ------
    ValueError
        A pair joining different filtration values (the first one named), an invalid or cyclic
        matching, or coefficients neither 0 nor a prime.

    Examples
    --------
    Example 2.38's filtration reduces to 10 of its 12 simplices:

    >>> from thesis_lib.datasets import example_filtration
    >>> reduction = morse_reduce(example_filtration(), coefficients=2)
    >>> reduction.n_critical, reduction.n_cells
    (10, 12)
    """
    p = resolve_coefficients(coefficients, default=2)
    filt = as_complex(filtration)
    cx, vals = _cells_and_values(filt)
    if pairs is None:
        partner = greedy_partner(cx, "coreduction", vals=vals)
    else:
        partner = partner_array(cx, pairs)
        paired = np.flatnonzero(partner >= 0)
        bad = paired[vals[partner[paired]] != vals[paired]]
        if bad.size:
            g = int(bad.min())
            raise ValueError(
                f"pair {cx.simplex(g)} - {cx.simplex(int(partner[g]))} joins different filtration values "
                f"{vals[g]} and {vals[partner[g]]}: the reduced complex would change the barcode"
            )
    crit, mats = morse_boundary_ids(cx, partner, p)
    critical = [cx.arrays[d][ids - cx.offsets[d]] for d, ids in enumerate(crit)]
    values = [vals[ids] for ids in crit]
    return MorseReduction(critical, values, mats, cx.n, p)


def reduced_persistence(reduction: MorseReduction, *, coefficients: int | None = None) -> Barcode:
    """Barcode of the reduced (Morse) filtered complex; equals the filtration's barcode.

    Thesis: Theorems 4.39 and 4.41 applied to every sublevel complex; Algorithm 2 for the reduction.

    Parameters
    ----------
    reduction : MorseReduction
        The result of :func:`morse_reduce`.
    coefficients : int, optional
        The prime field of the persistence (default: the reduction's own, or 2 for a reduction over
        Z); a reduction mod p allows only p.

    Returns
    -------
    Barcode
        The persistence intervals of the filtration.

    Raises
    ------
    TypeError
        ``reduction`` is not a MorseReduction (an ``InvalidTypeError``, which is also a
        ValueError).
    ValueError
        Coefficients that are not a prime, or differ from a reduction's prime.

    Examples
    --------
    The reduced complex has the barcode of the filtration (Example 2.38):

    >>> from thesis_lib.datasets import example_filtration
    >>> from thesis_lib.persistence import persistence
    >>> barcode = reduced_persistence(morse_reduce(example_filtration(), coefficients=2))
    >>> barcode.intervals(1).tolist(), barcode.allclose(persistence(example_filtration()))
    ([[2.0, inf], [3.0, 4.0]], True)
    """
    if not isinstance(reduction, MorseReduction):
        raise InvalidTypeError(f"expected a MorseReduction (from morse_reduce), got {type(reduction).__name__}")
    field = parse_field(coefficients, default=reduction.coefficients or 2, field=True)
    if reduction.coefficients not in (0, field.p):
        raise ValueError(f"the reduction was computed mod {reduction.coefficients}, cannot take persistence mod "
                         f"{field.p}")
    return chain_barcode(reduction.values, reduction.boundaries, field)

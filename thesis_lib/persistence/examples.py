"""The worked examples of §2.3 computed and set against what the thesis prints.

Example 2.36 and Equations 2.5–2.6 (the P-intervals of a graded F[t]-module beside a computed
barcode), Example 2.40 (the matrix M_1 and the cycles z_1, z_2), Example 2.41 (the boundary matrix
over F[t], entry by entry) and the order of the rows of §2.3.4.  The thesis's printed inputs are in
:mod:`thesis_lib.datasets.filtrations`.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from ..datasets.filtrations import named_chain, simplex_labels
from ..homology.filtration import Filtration, as_complex
from ..homology.simplicial import boundary_matrix
from .barcode import Barcode

__all__ = [
    "intervals_text",
    "module_intervals",
    "module_mismatches",
    "IntervalSummary",
    "interval_summary",
    "MatrixAgreement",
    "matrix_agreement",
    "CycleCheck",
    "cycle_check",
    "cycle_table",
    "RowOrderCheck",
    "row_order_check",
    "row_order_table",
]

Summand = tuple[int, int | None]


def intervals_text(intervals: npt.ArrayLike) -> str:
    """P-intervals written as the thesis writes them: ``(0, ∞), (1, ∞), (2, 4)``.

    Thesis: Definition 2.34 (a P-interval is a pair (i, j), j possibly ∞).

    Parameters
    ----------
    intervals : array-like, shape (k, 2)
        ``(birth, death)`` rows, ``death = inf`` for an essential class.

    Returns
    -------
    str
        The intervals in their order, numbers written with ``:g``, comma-separated.

    Examples
    --------
    >>> intervals_text([(0.0, float("inf")), (2.0, 4.0)])
    '(0, ∞), (2, 4)'
    """
    rows = np.asarray(intervals, dtype=float).reshape(-1, 2)
    return ", ".join(f"({b:g}, {'∞' if math.isinf(d) else f'{d:g}'})" for b, d in rows)


def module_intervals(summands: Iterable[Summand]) -> list[tuple[float, float]]:
    """The P-intervals of ⊕ Σ^i F[t]/(t^n) ⊕ Σ^i F[t]: (i, i + n) for a torsion summand, (i, ∞) for a free one.

    Thesis: Definition 2.34 (Q(i, j) = Σ^i F[t]/(t^{j−i}), Q(i, ∞) = Σ^i F[t]) and Corollary 2.35.

    Parameters
    ----------
    summands : iterable of (int, int or None)
        ``(i, n)`` for Σ^i F[t]/(t^n), ``(i, None)`` for Σ^i F[t].

    Returns
    -------
    list of (float, float)
        The intervals, sorted.

    Examples
    --------
    >>> module_intervals([(2, 2), (0, None), (1, None)])
    [(0.0, inf), (1.0, inf), (2.0, 4.0)]
    """
    return sorted((float(i), math.inf if n is None else float(i + n)) for i, n in summands)


def module_mismatches(intervals: npt.ArrayLike, summands: Iterable[Summand]) -> int:
    """How many intervals a computed barcode and a printed module do not share (as multisets).

    Thesis: Equations 2.5 and 2.6 (the modules H_0 and H_1 of Example 2.40).

    Parameters
    ----------
    intervals : array-like, shape (k, 2)
        The computed ``(birth, death)`` rows of one dimension.
    summands : iterable of (int, int or None)
        The module as printed, as :func:`module_intervals` takes it.

    Returns
    -------
    int
        The size of the multiset symmetric difference of the two lists of intervals (0: the same).

    Examples
    --------
    >>> module_mismatches([(0.0, 1.0), (0.0, float("inf"))], [(0, None), (0, 1)])
    0
    >>> module_mismatches([(0.0, 1.0)], [(0, 1), (0, 1)])
    1
    """
    ours = Counter(tuple(map(float, row)) for row in np.asarray(intervals, dtype=float).reshape(-1, 2))
    printed = Counter(module_intervals(summands))
    return int(sum(((ours - printed) + (printed - ours)).values()))


@dataclass(frozen=True)
class IntervalSummary:
    """The intervals of one dimension in counts: how many, how many essential, their births, the finite ones.

    Attributes: ``n_intervals``, ``n_essential``, ``essential_births`` (in the intervals' order) and
    ``finite`` (the finite ``(birth, death)`` pairs, in order).
    """

    n_intervals: int
    n_essential: int
    essential_births: tuple[float, ...]
    finite: tuple[tuple[float, float], ...]


def interval_summary(intervals: npt.ArrayLike) -> IntervalSummary:
    """Count the intervals of one dimension: essential ones with their births, finite ones as pairs.

    Thesis: Theorem 2.39 (a pivot gives a finite P-interval, a zero column without pivot an infinite one).

    Parameters
    ----------
    intervals : array-like, shape (k, 2)
        ``(birth, death)`` rows (``Barcode.intervals(dim)``).

    Returns
    -------
    IntervalSummary
        Counts, births of the essential classes and the finite intervals, in the rows' order.

    Examples
    --------
    >>> interval_summary([(0.0, float("inf")), (2.0, 4.0)])
    IntervalSummary(n_intervals=2, n_essential=1, essential_births=(0.0,), finite=((2.0, 4.0),))
    """
    rows = np.asarray(intervals, dtype=float).reshape(-1, 2)
    essential = np.isinf(rows[:, 1])
    return IntervalSummary(
        n_intervals=int(rows.shape[0]),
        n_essential=int(essential.sum()),
        essential_births=tuple(float(b) for b in rows[essential, 0]),
        finite=tuple((float(b), float(d)) for b, d in rows[~essential]),
    )


@dataclass(frozen=True)
class MatrixAgreement:
    """A printed boundary matrix over F[t] against the one computed.

    Attributes: ``compared`` (entries of the printed matrix), ``ours_nonzero`` (nonzero entries of
    the computed one) and ``mismatches`` (printed entries whose coefficient or power of t differs).
    """

    compared: int
    ours_nonzero: int
    mismatches: int


def matrix_agreement(trace: list[dict[str, Any]], printed: Mapping[str, Mapping[str, tuple[int, int]]], *,
                     coefficients: int, names: str) -> MatrixAgreement:
    """Compare a boundary matrix over F[t] as printed, entry by entry, with a trace's boundary columns.

    Thesis: Example 2.41 (the m × m matrix of the filtration of Figure 2.11).

    The printed matrix names oriented simplices (``"da"``, ``"ced"``); an odd ordering of a column's or
    a row's vertices flips the sign of the entry (Definition 2.17) before it is compared mod p.  The
    power of t must be deg column − deg row.

    Parameters
    ----------
    trace : list of dict
        The whole list filled by ``compute_intervals(..., trace=[])``.
    printed : mapping of str to mapping of str to (int, int)
        Column name → {row name: (coefficient, power of t)}, the nonzero entries as printed
        (``EXAMPLE_2_41_MATRIX``).
    coefficients : int
        The prime the trace was computed over.
    names : str
        ``names[v]`` is the letter of vertex v.

    Returns
    -------
    MatrixAgreement
        The numbers of entries compared, of nonzero entries computed, and of disagreements.

    Raises
    ------
    ValueError
        A trace that is not the full list filled by ``compute_intervals``, or a printed simplex that is
        not in it.

    Examples
    --------
    >>> from thesis_lib.persistence import compute_intervals
    >>> trace = []
    >>> _ = compute_intervals([((0,), 0), ((1,), 0), ((0, 1), 1)], coefficients=3, trace=trace)
    >>> matrix_agreement(trace, {"ba": {"a": (1, 1), "b": (-1, 1)}}, coefficients=3, names="ab")
    MatrixAgreement(compared=2, ours_nonzero=2, mismatches=0)
    """
    if not trace or "order" not in trace[0]:
        raise ValueError("trace must be the full list filled by compute_intervals(..., trace=[])")
    index = {s: i for i, s in enumerate(trace[0]["order"])}
    deg = [r["value"] for r in trace]

    def position(name: str) -> tuple[int, int]:
        ((simplex, sign),) = named_chain({name: 1}, names=names).items()
        if simplex not in index:
            raise ValueError(f"{name!r} is not a simplex of the traced filtration")
        return index[simplex], sign

    compared = mismatches = 0
    for column, entries in printed.items():
        j, column_sign = position(column)
        for row, (coefficient, power) in entries.items():
            i, row_sign = position(row)
            compared += 1
            ours = trace[j]["boundary"].get(i, 0)
            mismatches += ours != (column_sign * row_sign * coefficient) % coefficients or deg[j] - deg[i] != power
    return MatrixAgreement(compared, sum(len(r["boundary"]) for r in trace), int(mismatches))


@dataclass(frozen=True)
class CycleCheck:
    """A printed cycle checked against a filtration and its barcode.

    Attributes: ``terms`` (as printed), ``boundary_terms`` (nonzero terms of its boundary; 0 for a
    cycle), ``degree`` (the latest entry time of its simplices), ``bar`` (the first interval born at
    that degree, or None) and ``matches_representative`` (it is a nonzero multiple of that bar's
    representative cycle, mod p).
    """

    terms: Mapping[str, int]
    boundary_terms: int
    degree: float
    bar: tuple[float, float] | None
    matches_representative: bool


def cycle_check(barcode: Barcode, terms: Mapping[str, int], *, names: str, dim: int = 1) -> CycleCheck:
    """Whether a printed chain is a cycle, where it is born, and whether it is the barcode's cycle born there.

    Thesis: Example 2.40 (the generators z_1 = da + t·cd + bc + t·ab and z_2 = ed + ce − t²·cd).

    Parameters
    ----------
    barcode : Barcode
        A barcode computed from a filtration (it knows its representatives); its field is the field
        of the comparison.
    terms : mapping of str to int
        Oriented simplices named by their vertices → integer coefficients, the powers of t left out
        (``EXAMPLE_2_40_CYCLES["z1"]``).
    names : str
        ``names[v]`` is the letter of vertex v.
    dim : int, default 1
        The dimension of the chain.

    Returns
    -------
    CycleCheck
        The boundary's nonzero terms, the degree, the bar born at the degree and the comparison of
        the chain with that bar's representative (:meth:`Barcode.representative`) up to a nonzero
        multiple.

    Raises
    ------
    ValueError
        A barcode not computed from a filtration, or a printed simplex not in it.

    Examples
    --------
    >>> from thesis_lib.persistence import compute_intervals
    >>> triangle = [((0,), 0), ((1,), 0), ((2,), 0), ((0, 1), 1), ((1, 2), 1), ((0, 2), 2)]
    >>> check = cycle_check(compute_intervals(triangle, coefficients=3), {"ab": 1, "bc": 1, "ca": 1}, names="abc")
    >>> check.boundary_terms, check.degree, check.bar, check.matches_representative
    (0, 2.0, (2.0, inf), True)
    """
    K = barcode.filtration
    if K is None:
        raise ValueError("the barcode must be computed from a filtration")
    p = barcode.coefficients or 2
    value_of = {tuple(map(int, s)): float(v) for s, v in zip(K.simplices[dim], K.values[dim])}
    z = named_chain(terms, names=names)
    if any(s not in value_of for s in z):
        raise ValueError(f"a simplex of {dict(terms)} is not in the filtration")
    simplices = sorted(z)
    boundary = boundary_matrix(K.simplices[dim - 1], np.array(simplices)) @ np.array([z[s] for s in simplices])
    degree = max(value_of[s] for s in z)
    bars = barcode.intervals(dim)
    born = np.flatnonzero(bars[:, 0] == degree)
    if born.size == 0:
        return CycleCheck(dict(terms), int(np.count_nonzero(boundary)), degree, None, False)
    i = int(born[0])
    theirs = dict(barcode.representative(dim, i))
    support = set(z) | set(theirs)
    same = any(all((lam * z.get(s, 0) - theirs.get(s, 0)) % p == 0 for s in support) for lam in range(1, p))
    return CycleCheck(dict(terms), int(np.count_nonzero(boundary)), degree, (float(bars[i, 0]), float(bars[i, 1])),
                      same)


def _printed(terms: Mapping[str, int]) -> str:
    text = " ".join(f"{'-' if c < 0 else '+'} {abs(c) if abs(c) != 1 else ''}{word}" for word, c in terms.items())
    return text.lstrip("+ ")


def cycle_table(checks: Mapping[str, CycleCheck]) -> list[list[str]]:
    """Table rows of printed cycles and their checks.

    Thesis: Example 2.40 (the cycles z_1 and z_2).

    Parameters
    ----------
    checks : mapping of str to CycleCheck
        Cycle name (a letter and an index, ``"z1"``) → its :func:`cycle_check`.

    Returns
    -------
    list of list of str
        The header, then per cycle: ``$z_1$``, the chain as printed, whether ∂z = 0, the degree, the
        bar born there and whether the engine's cycle is the same.

    Examples
    --------
    >>> cycle_table({"z1": CycleCheck({"ab": 1, "ba": -1}, 0, 1.0, (1.0, float("inf")), True)})[1]
    ['$z_1$', '$ab - ba$', 'yes', '1', '$[1, \\\\infty)$', 'the same']
    """
    rows = [["cycle", "as printed, without powers of $t$", "$\\partial z = 0$", "degree", "bar born there",
             "engine's cycle"]]
    for name, check in checks.items():
        bar = "none" if check.bar is None else f"$[{check.bar[0]:g}, {_end(check.bar[1])})$"
        rows.append([f"${name[0]}_{name[1:]}$", f"${_printed(check.terms)}$", "no" if check.boundary_terms else "yes",
                     f"{check.degree:g}", bar, "the same" if check.matches_representative else "different"])
    return rows


def _end(x: float) -> str:
    return "\\infty" if math.isinf(x) else f"{x:g}"


@dataclass(frozen=True)
class RowOrderCheck:
    """The columns of M_p whose powers of t do not decrease down a column, for two orders of the rows.

    Attributes: ``dim`` (p), ``n_columns``, ``increasing_rows`` and ``decreasing_rows`` (the
    (p − 1)-simplices top to bottom, by increasing and by decreasing degree), ``with_increasing_rows``
    and ``with_decreasing_rows`` (the number of such columns for each order).
    """

    dim: int
    n_columns: int
    increasing_rows: tuple[tuple[int, ...], ...]
    decreasing_rows: tuple[tuple[int, ...], ...]
    with_increasing_rows: int
    with_decreasing_rows: int


def _columns_not_decreasing(K: Filtration, dim: int, rows: list[int]) -> int:
    """Columns of M_dim whose powers deg(column) − deg(row) do not decrease from the top row down."""
    m = boundary_matrix(K.simplices[dim - 1], K.simplices[dim]).toarray()
    n = 0
    for j, value in enumerate(K.values[dim]):
        powers = [float(value - K.values[dim - 1][i]) for i in rows if m[i, j] != 0]
        n += all(a <= b for a, b in zip(powers, powers[1:]))
    return int(n)


def row_order_check(filtration: Filtration | Iterable[Any], *, dim: int = 1) -> RowOrderCheck:
    """Count the columns of M_p whose powers of t increase downward, rows by increasing and by decreasing degree.

    Thesis: §2.3.4 (the powers "have to be increasing as we move from the top row and down": they are
    when the rows are sorted by decreasing degree, the order Example 2.40 prints M_1 in).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        Anything :func:`~thesis_lib.homology.filtration.as_complex` takes.
    dim : int, default 1
        p ≥ 1: M_p has a row per (p − 1)-simplex and a column per p-simplex; entry t^k with
        k = deg(column) − deg(row).

    Returns
    -------
    RowOrderCheck
        The two row orders (increasing degree, ties in the filtration's order; and its reverse) and
        the counts of columns whose powers do not decrease from the top row down.

    Raises
    ------
    ValueError
        ``dim`` not between 1 and the filtration's dimension.

    Examples
    --------
    >>> from thesis_lib.datasets import example_filtration
    >>> check = row_order_check(example_filtration())
    >>> check.n_columns, check.with_increasing_rows, check.with_decreasing_rows
    (6, 2, 6)
    """
    K = as_complex(filtration)
    if not 1 <= dim <= K.dimension:
        raise ValueError(f"dim must be between 1 and {K.dimension}, got {dim}")
    increasing = [int(i) for i in np.argsort(K.values[dim - 1], kind="stable")]
    decreasing = increasing[::-1]
    rows = K.simplices[dim - 1]
    return RowOrderCheck(
        dim=dim,
        n_columns=int(K.simplices[dim].shape[0]),
        increasing_rows=tuple(tuple(map(int, rows[i])) for i in increasing),
        decreasing_rows=tuple(tuple(map(int, rows[i])) for i in decreasing),
        with_increasing_rows=_columns_not_decreasing(K, dim, increasing),
        with_decreasing_rows=_columns_not_decreasing(K, dim, decreasing),
    )


def row_order_table(check: RowOrderCheck, *, names: str | None = None) -> list[list[object]]:
    """Table rows of a :func:`row_order_check`: each order of the rows and its count of columns.

    Thesis: §2.3.4 (the order of the rows of the matrix M_p).

    Parameters
    ----------
    check : RowOrderCheck
        What :func:`row_order_check` returned.
    names : str, optional
        ``names[v]`` is the letter of vertex v; default: the numbers.

    Returns
    -------
    list of list
        The header, then the increasing and the decreasing order with their counts.

    Examples
    --------
    >>> from thesis_lib.datasets import example_filtration
    >>> row_order_table(row_order_check(example_filtration()), names="abcde")[2]
    ['by decreasing degree: $e$, $d$, $c$, $b$, $a$', 6]
    """
    def order(rows: tuple[tuple[int, ...], ...]) -> str:
        return ", ".join(f"${name}$" for name in simplex_labels(rows, names=names))

    return [
        [f"rows of $M_{check.dim}$, top to bottom",
         f"columns (of {check.n_columns}) whose powers of $t$ do not decrease downward"],
        ["by increasing degree: " + order(check.increasing_rows), check.with_increasing_rows],
        ["by decreasing degree: " + order(check.decreasing_rows), check.with_decreasing_rows],
    ]

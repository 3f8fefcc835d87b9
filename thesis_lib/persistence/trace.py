"""Reading a trace of :func:`~thesis_lib.persistence.algorithm.compute_intervals` (Algorithms 1–2).

``compute_intervals(K, trace=[])`` records every call of Reduce; the functions here write that record
out as Example 2.41 shows it: the boundary matrix over F[t] before and after the algorithm as table
rows, each call of Reduce as two lines of text, and the P-intervals read off the stored columns.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ..datasets.filtrations import simplex_labels
from .algorithm import trace_matrices

__all__ = [
    "trace_tables",
    "reduce_steps_text",
    "repeated_passes",
    "reduced_sizes",
    "ReadOffInterval",
    "read_off_intervals",
    "read_off_table",
]

Trace = list[dict[str, Any]]


def _check_trace(trace: Trace) -> None:
    if not trace or "order" not in trace[0]:
        raise ValueError("trace must be the full list filled by compute_intervals(..., trace=[])")


def _as_math(matrix: list[list[str]]) -> list[list[str]]:
    """Entries c·t^k of a trace table as math (``t^{k}`` inside ``$…$``); the corner cell left empty."""
    shown = [[re.sub(r"t\^(\d+)", r"t^{\1}", x) for x in row] for row in matrix]
    shown = [[f"${x}$" if i and j and x != "0" else x for j, x in enumerate(row)] for i, row in enumerate(shown)]
    shown[0][0] = ""
    return shown


def trace_tables(trace: Trace, *, coefficients: int, names: str | None = None) -> tuple[list[list[str]],
                                                                                        list[list[str]]]:
    """The two matrices of Example 2.41 as table rows, entries written as math.

    Thesis: Example 2.41 (the m × m boundary matrix over F[t], and the reduced columns with the
    unmarked rows removed).

    Parameters
    ----------
    trace : list of dict
        The whole list filled by ``compute_intervals(..., trace=[])``.
    coefficients : int
        The prime the trace was computed over; coefficients are shown as signed residues.
    names : str, optional
        ``names[v]`` is the letter of vertex v; default: the numbers.

    Returns
    -------
    before : list of list of str
        Header row (an empty corner, then every simplex), then one row per simplex: ``"0"`` or an
        entry such as ``"$-t^{2}$"`` (coefficient −1 at the power 2 = deg column − deg row).
    after : list of list of str
        The same for the reduced columns, restricted to the rows of marked simplices.

    Raises
    ------
    ValueError
        A trace that is not the full list filled by ``compute_intervals``.

    Examples
    --------
    >>> from thesis_lib.persistence import compute_intervals
    >>> trace = []
    >>> _ = compute_intervals([((0,), 0), ((1,), 0), ((0, 1), 2)], coefficients=3, trace=trace)
    >>> trace_tables(trace, coefficients=3, names="ab")[0]
    [['', 'a', 'b', 'ab'], ['a', '0', '0', '$-t^{2}$'], ['b', '0', '0', '$t^{2}$'], ['ab', '0', '0', '0']]
    """
    _check_trace(trace)
    before, after = trace_matrices(trace, coefficients=coefficients, names=names)
    return _as_math(before), _as_math(after)


def _coefficient(c: int, p: int) -> str:
    """A coefficient mod p in front of a name: nothing for 1, − for p − 1, else ``c·``."""
    return "" if c == 1 else ("−" if c == p - 1 else f"{c}·")


def _chain(d: dict[int, int], label: list[str], p: int) -> str:
    terms = [f"{_coefficient(c, p)}{label[i]}" for i, c in sorted(d.items())]
    return " + ".join(terms).replace("+ −", "− ") if terms else "0"


def _passes(steps: list[dict[str, Any]], label: list[str], p: int) -> str:
    """The subtractions of one call of Reduce; a pass repeated in a row is written once with its count."""
    passes: list[list[Any]] = []
    for s in steps:
        text = f"{_coefficient(s['factor'], p)}T[{label[s['i']]}]"
        if passes and passes[-1][0] == text:
            passes[-1][1] += 1
        else:
            passes.append([text, 1])
    return "; ".join(text + (f" ({n} passes)" if n > 1 else "") for text, n in passes)


def reduce_steps_text(trace: Trace, *, coefficients: int, names: str | None = None) -> list[str]:
    """Each call of Reduce on a simplex of dimension ≥ 1 as two lines: its boundary, then what it became.

    Thesis: Algorithm 1 (Reduce) and Example 2.41.

    The first line is ``Reduce(σ): ∂ = ...`` with the unmarked faces that were dropped; the second
    names the stored columns subtracted (``T[b] (2 passes)`` when one is subtracted twice in a row,
    which over Z/p with p > 2 the literal loop does for a coefficient other than 1), the reduced
    chain, and whether σ was marked (a cycle) or stored in ``T[i]``.

    Parameters
    ----------
    trace : list of dict
        The whole list filled by ``compute_intervals(..., trace=[])``.
    coefficients : int
        The prime the trace was computed over (``−`` is written for p − 1).
    names : str, optional
        ``names[v]`` is the letter of vertex v; default: the numbers.

    Returns
    -------
    list of str
        Two lines per simplex of dimension ≥ 1, in the algorithm's order.

    Raises
    ------
    ValueError
        A trace that is not the full list filled by ``compute_intervals``.

    Examples
    --------
    >>> from thesis_lib.persistence import compute_intervals
    >>> trace = []
    >>> _ = compute_intervals([((0,), 0), ((1,), 0), ((0, 1), 1)], coefficients=3, trace=trace)
    >>> reduce_steps_text(trace, coefficients=3, names="ab")
    ['Reduce(ab): ∂ = −a + b', '    ⇒ −a + b: stored in T[b]']
    """
    _check_trace(trace)
    label = simplex_labels(trace[0]["order"], names=names)
    p = coefficients
    lines = []
    for r in trace:
        if r["dim"] == 0:
            continue
        dropped = ", ".join(simplex_labels(r["removed"], names=names))
        outcome = "marked (a cycle)" if r["marked"] else f"stored in T[{label[r['pivot']]}]"
        passes = _passes(r["steps"], label, p)
        lines.append(f"Reduce({label[r['j']]}): ∂ = {_chain(r['boundary'], label, p)}"
                     + (f"; drop unmarked {dropped}" if dropped else ""))
        lines.append(f"    {'subtract ' + passes + ' ' if passes else ''}⇒ {_chain(r['result'], label, p)}: {outcome}")
    return lines


def repeated_passes(trace: Trace) -> int:
    """How many passes of Reduce's loop came back to a row it had already subtracted at.

    Thesis: Algorithm 1 (over Z/p the literal loop clears a coefficient c of σ^i in c passes).

    Parameters
    ----------
    trace : list of dict
        A list filled by ``compute_intervals(..., trace=[])``.

    Returns
    -------
    int
        Σ over the calls of Reduce of (passes − distinct rows subtracted at); 0 over Z/2.

    Examples
    --------
    >>> from thesis_lib.persistence import compute_intervals
    >>> trace = []
    >>> _ = compute_intervals([((0,), 0), ((1,), 0), ((0, 1), 1)], trace=trace)
    >>> repeated_passes(trace)
    0
    """
    return sum(len(r["steps"]) - len({s["i"] for s in r["steps"]}) for r in trace)


def reduced_sizes(trace: Trace, *, names: str | None = None) -> dict[str, int]:
    """The number of entries of each simplex's reduced column (0 for a marked simplex, a cycle).

    Thesis: Example 2.41 (the columns after the algorithm).

    Parameters
    ----------
    trace : list of dict
        The whole list filled by ``compute_intervals(..., trace=[])``.
    names : str, optional
        ``names[v]`` is the letter of vertex v; default: the numbers.

    Returns
    -------
    dict of str to int
        Simplex name → number of nonzero entries of its reduced column.

    Raises
    ------
    ValueError
        A trace that is not the full list filled by ``compute_intervals``.

    Examples
    --------
    >>> from thesis_lib.persistence import compute_intervals
    >>> trace = []
    >>> _ = compute_intervals([((0,), 0), ((1,), 0), ((0, 1), 1)], trace=trace)
    >>> reduced_sizes(trace, names="ab")
    {'a': 0, 'b': 0, 'ab': 2}
    """
    _check_trace(trace)
    label = simplex_labels(trace[0]["order"], names=names)
    return {label[r["j"]]: len(r["result"]) for r in trace}


@dataclass(frozen=True)
class ReadOffInterval:
    """A P-interval read off the stored columns: ``(deg creator, deg killer)``, or ``(deg creator, ∞)``.

    Attributes: ``creator`` and ``killer`` (vertex tuples; ``killer`` None for an essential class),
    ``birth`` and ``death``.
    """

    creator: tuple[int, ...]
    killer: tuple[int, ...] | None
    birth: float
    death: float


def read_off_intervals(trace: Trace) -> list[ReadOffInterval]:
    """Every P-interval Algorithm 2 reads off, zero-length ones included, in the order it reads them.

    Thesis: Theorem 2.39 and Algorithm 2 (T[i] holding column j gives (deg σ^i, deg σ^j); a marked
    σ^j with empty T[j] gives (deg σ^j, ∞)).

    Parameters
    ----------
    trace : list of dict
        The whole list filled by ``compute_intervals(..., trace=[])``.

    Returns
    -------
    list of ReadOffInterval
        First the finite pairs in the order their killing simplices were reduced, then the essential
        classes in the algorithm's order.

    Raises
    ------
    ValueError
        A trace that is not the full list filled by ``compute_intervals``.

    Examples
    --------
    >>> from thesis_lib.persistence import compute_intervals
    >>> trace = []
    >>> _ = compute_intervals([((0,), 0), ((1,), 0), ((0, 1), 1)], trace=trace)
    >>> [(i.birth, i.death) for i in read_off_intervals(trace)]
    [(0.0, 1.0), (0.0, inf)]
    """
    _check_trace(trace)
    order = trace[0]["order"]
    pivots = {r["pivot"] for r in trace if r["pivot"] is not None}
    finite = [ReadOffInterval(order[r["pivot"]], order[r["j"]], trace[r["pivot"]]["value"], r["value"])
              for r in trace if r["pivot"] is not None]
    essential = [ReadOffInterval(order[r["j"]], None, r["value"], math.inf)
                 for r in trace if r["marked"] and r["j"] not in pivots]
    return finite + essential


def _end(x: float) -> str:
    return "\\infty" if math.isinf(x) else f"{x:g}"


def read_off_table(intervals: Sequence[ReadOffInterval], *, names: str | None = None) -> list[list[str]]:
    """Table rows of the P-intervals read off: the pair, the interval, and a note on zero length.

    Thesis: Example 2.41 (the P-intervals read off as (deg a, ∞), (deg b, deg ab), ...).

    Parameters
    ----------
    intervals : sequence of ReadOffInterval
        As :func:`read_off_intervals` returns them.
    names : str, optional
        ``names[v]`` is the letter of vertex v; default: the numbers.

    Returns
    -------
    list of list of str
        The header ``["pair", "$\\mathcal{P}$-interval", ""]``, then per interval ``"$(b, ab)$"``,
        ``"$(0, 1)$"`` and ``"length zero: left out of the barcode"`` or ``""``.

    Examples
    --------
    >>> read_off_table([ReadOffInterval((1,), (0, 1), 0.0, 1.0)], names="ab")[1]
    ['$(b, ab)$', '$(0, 1)$', '']
    """
    rows = [["pair", "$\\mathcal{P}$-interval", ""]]
    for iv in intervals:
        creator = simplex_labels([iv.creator], names=names)[0]
        killer = "\\infty" if iv.killer is None else simplex_labels([iv.killer], names=names)[0]
        note = "length zero: left out of the barcode" if iv.birth == iv.death else ""
        rows.append([f"$({creator}, {killer})$", f"$({iv.birth:g}, {_end(iv.death)})$", note])
    return rows

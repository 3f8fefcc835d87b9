"""The thesis's persistence algorithm, literally: Reduce (Algorithm 1) and ComputeIntervals (Algorithm 2).

Readable pure Python on sparse chains ``{index: coefficient}``; meant for small complexes, the
notebook and as a reference for the fast engine in :mod:`thesis_lib.persistence.engine`.  The field
arithmetic is the library's one modular inverse, :func:`~thesis_lib.persistence.kernels.inverse`.

Reduce is the thesis's loop as printed: while the chain ``d`` is not empty, take its largest index
``i``; stop if ``T[i]`` is empty; otherwise ``d = d − q⁻¹T[i]`` with ``q`` the coefficient of σ^i in
``T[i]``.  Why it terminates over Z/p: the stored column ``T[i]`` has its largest index at ``i``, so
``q⁻¹T[i]`` is 1 at σ^i and touches only smaller indices besides.  One pass lowers the coefficient
``d_i`` of σ^i by one, as a residue in ``1 .. p − 1``, and leaves every larger index alone.  If
``d_i = 1`` the term σ^i is gone and the largest index drops; if ``d_i ≠ 1`` (possible only when
p > 2) the loop meets the same ``i`` again and subtracts ``q⁻¹T[i]`` once more, ``d_i`` times in
all, which is the single subtraction ``d − d_i q⁻¹T[i]`` done in unit steps.  So the pair (largest
index, its coefficient) decreases lexicographically and Reduce(σ^j) makes at most (p − 1)·j passes;
over Z/2 every coefficient is 1 and each pass lowers the largest index.  The reduced chains, hence
the intervals, are those of the one-step elimination used by the fast engine.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

import numpy as np

from .._validate import parse_field
from ..homology.filtration import Filtration, as_complex
from .barcode import Barcode
from .kernels import inverse

__all__ = ["compute_intervals", "trace_matrices"]


def compute_intervals(filtration: Filtration | Iterable[Any], *, coefficients: int | None = None,
                      trace: list[dict[str, Any]] | None = None) -> Barcode:
    """P-intervals of a filtered complex over Z/p by the thesis's Algorithms 1 (Reduce) and 2 (ComputeIntervals).

    Thesis: Algorithms 1–2, §2.3.5 (after Zomorodian and Carlsson), O(m³) in the number of simplices m.

    A separate implementation, on purpose: the thesis's pseudocode line by line in pure Python, for
    small complexes, the notebook's traces and as the reference the engines are tested against.
    The library's engines are :func:`~thesis_lib.persistence.persistence` (any filtration) and
    :func:`~thesis_lib.persistence.rips_persistence` (Rips, implicit); all three give the same
    intervals.

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        A :class:`~thesis_lib.homology.filtration.Filtration`, or anything
        :func:`~thesis_lib.homology.filtration.as_complex` takes: ``(simplex, value)`` pairs in filtration
        order (non-decreasing values, faces before cofaces), plain simplices (all values 0), ...
    coefficients : int, optional
        A prime p: the field Z/p (default 2).  0 (the integers) is refused: Reduce divides.
    trace : list of dict, optional
        If given, one dict per simplex σ^j is appended recording the steps of Reduce(σ^j): ``j``,
        ``simplex``, ``dim``, ``value``, ``boundary`` (∂σ^j as ``{i: coeff}``), ``removed`` (the
        unmarked terms dropped), ``steps`` (one ``{"i", "q", "factor", "T"}`` per pass of the loop,
        ``d = d − factor·T[i]`` with ``factor = q⁻¹``: a term of coefficient c takes c passes),
        ``result`` (the reduced ``d``), ``marked`` and ``pivot``.
        Indices ``i`` refer to the algorithm's order σ^0 < ... < σ^{m−1}; the first entry also holds
        ``order``, the list of all simplices in that order.

    Returns
    -------
    Barcode
        Intervals ``(deg σ^i, deg σ^j)`` and ``(deg σ^j, ∞)`` in dimensions 0 .. dim K, with the
        creating and killing simplices (:meth:`~Barcode.simplex_pairs`); zero-length intervals are
        left out.

    Raises
    ------
    ValueError
        A complex :func:`~thesis_lib.homology.filtration.as_complex` refuses, or ``coefficients`` not a prime.

    Examples
    --------
    Example 2.38 by the thesis's Algorithms 1 and 2, over Z/2:

    >>> from thesis_lib.datasets import example_filtration
    >>> barcode = compute_intervals(example_filtration(), coefficients=2)
    >>> barcode.intervals(0).tolist(), barcode.intervals(1).tolist()
    ([[0.0, 1.0], [0.0, inf], [1.0, 2.0], [2.0, 3.0]], [[2.0, inf], [3.0, 4.0]])
    """
    K = as_complex(filtration)
    field = parse_field(coefficients, default=2, field=True)
    p = field.p

    # "First, sort the simplices by dimension and then by degree.  The ordering between simplices
    #  with the same dimension and degree will be irrelevant."  We keep the filtration's own order
    #  among equal degrees (a stable sort), so the pairs match the fast engine's simplex for simplex.
    sigma: list[tuple[int, ...]] = []  # σ^0, ..., σ^{m-1}
    deg: list[float] = []  # deg σ^j (the filtration value at which σ^j enters)
    dim_of: list[int] = []
    source: list[int] = []  # index of σ^j in K.simplices[dim]
    for d in range(K.dimension + 1):
        for j in np.argsort(K.values[d], kind="stable").tolist():
            sigma.append(tuple(int(v) for v in K.simplices[d][j]))
            deg.append(float(K.values[d][j]))
            dim_of.append(d)
            source.append(j)
    m = len(sigma)
    index = {s: j for j, s in enumerate(sigma)}

    # "At the same time we also create an array T with one slot for each simplex."
    T: list[tuple[int, dict[int, int]] | None] = [None] * m
    marked = [False] * m

    def boundary(j: int) -> dict[int, int]:
        # d = ∂_p σ = Σ_k (-1)^k [x_0, ..., x̂_k, ..., x_p] (Definition 2.18), coefficients in Z/p.
        s = sigma[j]
        if len(s) == 1:
            return {}
        return {index[s[:k] + s[k + 1 :]]: (-1) ** k % p for k in range(len(s))}

    def reduce(j: int, record: dict | None) -> dict[int, int]:
        # Algorithm 1: Reduce.  Input: a simplex σ = σ^j.
        # p = dim σ;  d = ∂_p σ;
        d = boundary(j)
        if record is not None:
            record["boundary"] = dict(d)
        # Remove unmarked terms in d;   (unmarked faces are negative: their rows were deleted)
        removed = [i for i in d if not marked[i]]
        for i in removed:
            del d[i]
        if record is not None:
            record["removed"] = [sigma[i] for i in removed]
        # while d ≠ ∅ do
        while d:
            # i = maxindex d;
            i = max(d)
            # if T[i] is empty then break;
            if T[i] is None:
                break
            # Let q be the coefficient of σ^i in T[i];
            _, Ti = T[i]
            q = Ti[i]
            # d = d − q⁻¹T[i];
            # q⁻¹T[i] has coefficient 1 at σ^i, so this lowers the coefficient d_i of σ^i by one and
            # changes only terms of smaller index.  When d_i ≠ 1 the term σ^i survives and the loop
            # comes back to the same i: d_i subtractions in all clear it (see the module docstring).
            factor = inverse(q, p)
            for k, c in Ti.items():
                v = (d.get(k, 0) - factor * c) % p
                if v:
                    d[k] = v
                else:
                    d.pop(k, None)
            if record is not None:
                record["steps"].append({"i": i, "q": q, "factor": factor, "T": dict(Ti)})
        # end; return d;
        return d

    # Algorithm 2: ComputeIntervals.
    # for p = 0 to dim(K) do L_p = ∅;
    L: dict[int, list[tuple[float, float]]] = {q: [] for q in range(K.dimension + 1)}
    pairs: dict[int, list[tuple[int, int]]] = {q: [] for q in range(K.dimension + 1)}
    # for j = 0 to m − 1 do
    for j in range(m):
        record = None
        if trace is not None:
            record = {"j": j, "simplex": sigma[j], "dim": dim_of[j], "value": deg[j], "steps": []}
            if j == 0:
                record["order"] = list(sigma)
        # d = Reduce(σ^j);
        d = reduce(j, record)
        if not d:
            # if d = ∅ then Mark σ^j;
            marked[j] = True
            pivot = None
        else:
            # i = maxindex d;  p = dim σ^j;  Store j and d in T[i];
            i = max(d)
            q = dim_of[i]
            T[i] = (j, d)
            # L_p = L_p ∪ {(deg σ^i, deg σ^j)};   (σ^i is a (p−1)-simplex: the interval belongs to H_{p−1})
            L[q].append((deg[i], deg[j]))
            pairs[q].append((source[i], source[j]))
            pivot = i
        if record is not None:
            record.update(result=dict(d), marked=marked[j], pivot=pivot)
            trace.append(record)
    # for j = 0 to m − 1 do: if σ^j is marked and T[j] is empty then L_p = L_p ∪ {(deg σ^j, ∞)};
    for j in range(m):
        if marked[j] and T[j] is None:
            q = dim_of[j]
            L[q].append((deg[j], math.inf))
            pairs[q].append((source[j], -1))
    return Barcode(
        {q: np.array(v, dtype=np.float64).reshape(-1, 2) for q, v in L.items()},
        dimensions=range(K.dimension + 1),
        coefficients=field,
        simplices={q: np.array(v, dtype=np.int64).reshape(-1, 2) for q, v in pairs.items()},
        filtration=K,
        killers={q: np.array([t for _, t in v if t >= 0], dtype=np.int64) for q, v in pairs.items()},
    )


def _t_power(c: int, power: float, p: int) -> str:
    """An entry c·t^power of a boundary matrix over F[t], c shown as a signed residue mod p."""
    c = c - p if c > p // 2 else c
    k = int(power) if float(power).is_integer() else power
    mono = "1" if k == 0 else ("t" if k == 1 else f"t^{k}")
    if mono == "1":
        return str(c)
    return mono if c == 1 else ("-" + mono if c == -1 else f"{c}{mono}")


def trace_matrices(trace: list[dict[str, Any]], *, coefficients: int,
                   names: str | None = None) -> tuple[list[list[str]], list[list[str]]]:
    """The two m × m tables of Example 2.41 from a trace of :func:`compute_intervals`.

    Thesis: Example 2.41 (the boundary matrix over F[t] before and after ComputeIntervals, the
    latter with the unmarked rows removed).

    Parameters
    ----------
    trace : list of dict
        The whole list filled by ``compute_intervals(..., trace=[])`` (its first entry holds ``order``).
    coefficients : int
        The prime p the trace was computed over; entries are shown as signed residues mod p.
    names : str, optional
        Letters for the vertex numbers (``names[v]`` names vertex v, e.g. ``"abcde"``); default: the
        numbers, comma-separated.

    Returns
    -------
    before : list of list of str
        The boundary matrix over F[t], all m rows: header row and header column first; an entry
        c·t^k means coefficient c at the power k = deg σ^j − deg σ^i, ``"0"`` for none.
    after : list of list of str
        The reduced columns ``d`` of ComputeIntervals, restricted to the marked rows.

    Raises
    ------
    ValueError
        A trace that is not the full list filled by :func:`compute_intervals`.

    Examples
    --------
    The tables of Example 2.41.  Row a before the reduction: the edges ab and ad have a as a face,
    entering 1 and 2 steps after it.  The column of bc is reduced to zero (bc closes the loop abcd):

    >>> from thesis_lib.datasets import example_filtration
    >>> from thesis_lib.persistence import compute_intervals
    >>> trace = []
    >>> _ = compute_intervals(example_filtration(), coefficients=2, trace=trace)
    >>> before, after = trace_matrices(trace, coefficients=2, names="abcde")
    >>> before[0]
    ['*', 'a', 'b', 'c', 'd', 'e', 'ab', 'cd', 'ad', 'bc', 'de', 'ce', 'cde']
    >>> before[1]
    ['a', '0', '0', '0', '0', '0', 't', '0', 't^2', '0', '0', '0', '0']
    >>> [row[9] for row in before[1:4]], [row[9] for row in after[1:4]]
    (['0', 't^2', 't'], ['0', '0', '0'])
    """
    if not trace or "order" not in trace[0]:
        raise ValueError("trace must be the full list filled by compute_intervals(..., trace=[])")
    order = trace[0]["order"]
    deg = [r["value"] for r in trace]
    label = ["".join(names[v] for v in s) if names else ",".join(map(str, s)) for s in order]

    def table(rows: list[int], cols: list[dict[int, int]]) -> list[list[str]]:
        out = [["*"] + label]
        for i in rows:
            line = [label[i]]
            for j, col in enumerate(cols):
                c = col.get(i, 0)
                line.append(_t_power(c, deg[j] - deg[i], coefficients) if c else "0")
            out.append(line)
        return out

    before = table(list(range(len(order))), [r["boundary"] for r in trace])
    marked = [r["j"] for r in trace if r["marked"]]
    after = table(marked, [r["result"] for r in trace])
    return before, after

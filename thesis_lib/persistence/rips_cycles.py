"""Representative cycles of a Rips barcode, from the explicit engine on the complex the bars need.

The implicit engine (:func:`~thesis_lib.persistence.rips_persistence`) reduces coboundaries and keeps
no simplex of a pair, so it can hand out cocycles but not cycles.  The cycles of the bars of
dimension k are read off the explicit engine (:func:`~thesis_lib.persistence.engine.filtration_barcode`
and :meth:`~thesis_lib.persistence.barcode.Barcode.representative`, Theorem 2.39's z_i) on the Rips
filtration truncated to what those bars need: simplices of dimension <= k + 1 and value up to the
largest finite death of dimension k (all of ``max_radius`` when dimension k has an essential bar).
Below that radius the truncated filtration is the full one in dimensions <= k + 1, so every bar of
dimension k it must explain is one of its own bars, with the same birth and death to the last bit;
each bar asked for is matched to one of them (equal bars in turn).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import Edges, Field, Points
from ..complexes.rips import rips_filtration
from .barcode import Barcode
from .engine import filtration_barcode

__all__ = ["Cycles", "bar_cycles"]

#: representative cycles per homology dimension: ``cycles[k][i]`` belongs to ``barcode.intervals(k)[i]``
Cycles = dict[int, list[npt.NDArray[np.int64]]]


def bar_cycles(source: Points | np.ndarray | Edges, max_radius: float, field: Field, barcode: Barcode,
               dims: range) -> Cycles:
    """A representative cycle of every bar of ``barcode`` in the dimensions ``dims`` (each k >= 1).

    Thesis: Theorem 2.39 (the basis cycles z_i of the column-echelon form), Definition 2.23 (the bars).

    Parameters
    ----------
    source : Points, numpy.ndarray or Edges
        The parsed point cloud or distance matrix the barcode was computed from (``parse_rips_input``).
    max_radius : float
        The checked scale ε of that computation.
    field : Field
        The parsed coefficient field (a prime).
    barcode : Barcode
        The Rips barcode, e.g. the implicit engine's.
    dims : range
        The homology dimensions wanted (each >= 1 and complete in ``barcode``).

    Returns
    -------
    dict of int to list of numpy.ndarray
        ``cycles[k][i]`` for the bar ``barcode.intervals(k)[i]``: an int64 array of shape (m, k + 2), a
        row per simplex of the cycle, its k + 1 vertices (increasing) then its coefficient in
        1 .. p − 1, rows in filtration order (so the last row is the simplex that creates the bar).

    Raises
    ------
    RuntimeError
        A bar that the truncated filtration does not have (cannot happen for a Rips barcode of
        ``source`` at ``max_radius``).

    Examples
    --------
    >>> from thesis_lib._validate import parse_field, parse_points
    >>> from thesis_lib.persistence import rips_persistence
    >>> square = parse_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    >>> field = parse_field(2, field=True)
    >>> cycles = bar_cycles(square, np.inf, field, rips_persistence(square, max_dim=2), range(1, 2))
    >>> cycles[1][0].tolist()
    [[0, 1, 1], [0, 3, 1], [1, 2, 1], [2, 3, 1]]
    """
    out: Cycles = {}
    for k in dims:
        bars = barcode.intervals(k)
        if bars.shape[0] == 0:
            out[k] = []
            continue
        deaths = bars[:, 1]
        radius = max_radius if np.isinf(deaths).any() else float(deaths.max())
        truncated = filtration_barcode(rips_filtration(source, radius, k + 1), field)
        mine = truncated.intervals(k)
        free: dict[tuple[float, float], list[int]] = {}  # the truncated barcode's rows of each bar, in order
        for j, bar in enumerate(mine.tolist()):
            free.setdefault((bar[0], bar[1]), []).append(j)
        cycles = []
        for bar in bars.tolist():
            rows = free.get((bar[0], bar[1]))
            if not rows:
                raise RuntimeError(f"the Rips filtration at radius {radius} has no bar {bar} in dimension {k}")
            chain = truncated.representative(k, rows.pop(0))  # equal bars take equal bars in turn
            cycles.append(np.array([[*simplex, c] for simplex, c in chain], dtype=np.int64).reshape(-1, k + 2))
        out[k] = cycles
    return out

"""How the work of Algorithms 1–2 grows with the number of simplices (the O(m³) of Algorithm 2).

The work is counted exactly from a trace of :func:`~thesis_lib.persistence.algorithm.compute_intervals`:
every boundary entry Reduce reads and every entry of a stored column it subtracts.  A family of
growing filtrations gives the exponent a of work ∝ m^a by a least-squares fit in log-log scale.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from ..homology.filtration import Filtration
from .algorithm import compute_intervals

__all__ = ["algorithm_work", "WorkGrowth", "work_growth", "work_table"]


def algorithm_work(filtration: Filtration | Iterable[Any], *, coefficients: int = 2) -> int:
    """Boundary entries read plus stored-column entries subtracted by Algorithms 1–2 on a filtration.

    Thesis: Algorithms 1–2 (Reduce O(m²), ComputeIntervals O(m³) in the number m of simplices).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        Anything :func:`~thesis_lib.homology.filtration.as_complex` takes.
    coefficients : int, default 2
        A prime: the field Z/p of the reduction.

    Returns
    -------
    int
        Σ_j |∂σ^j| + Σ over the passes of Reduce of |T[i]|.

    Examples
    --------
    >>> triangle = [((0,), 0), ((1,), 0), ((2,), 0), ((0, 1), 1), ((1, 2), 1), ((0, 2), 1)]
    >>> algorithm_work(triangle)  # 6 boundary entries; the last edge subtracts two stored columns of 2
    10
    """
    trace: list[dict[str, Any]] = []
    compute_intervals(filtration, coefficients=coefficients, trace=trace)
    return sum(len(r["boundary"]) for r in trace) + sum(len(s["T"]) for r in trace for s in r["steps"])


@dataclass(frozen=True)
class WorkGrowth:
    """The work of Algorithms 1–2 on a family of filtrations and the fitted exponent.

    Attributes: ``simplices`` (m of each filtration), ``work`` (:func:`algorithm_work` of each) and
    ``exponent`` (the slope a of the least-squares line through (log m, log work)).
    """

    simplices: npt.NDArray[np.float64]
    work: npt.NDArray[np.float64]
    exponent: float


def work_growth(filtrations: Iterable[Filtration | Iterable[Any]], *, coefficients: int = 2) -> WorkGrowth:
    """Count the work on each filtration of a family and fit the exponent a of work ∝ m^a.

    Thesis: Algorithm 2 and the Summary (ComputeIntervals is O(m³)).

    Parameters
    ----------
    filtrations : iterable of Filtration
        The family, at least two filtrations of different sizes.
    coefficients : int, default 2
        A prime: the field Z/p of the reduction.

    Returns
    -------
    WorkGrowth
        The sizes, the work and the fitted exponent.

    Raises
    ------
    ValueError
        Fewer than two distinct sizes (no line to fit).

    Examples
    --------
    >>> paths = [[((v,), 0) for v in range(n)] + [((v, v + 1), 1) for v in range(n - 1)] for n in (10, 100)]
    >>> growth = work_growth(paths)
    >>> growth.work.tolist(), round(growth.exponent, 2)
    ([18.0, 198.0], 1.02)
    """
    family = list(filtrations)
    m = np.array([len(f) for f in family], dtype=float)
    if np.unique(m).size < 2:
        raise ValueError("the family needs filtrations of at least two different sizes")
    w = np.array([algorithm_work(f, coefficients=coefficients) for f in family], dtype=float)
    return WorkGrowth(m, w, float(np.polyfit(np.log(m), np.log(w), 1)[0]))


def work_table(growth: Mapping[str, WorkGrowth]) -> list[list[str]]:
    """Table rows of the fitted exponents: family, range of m, a to 2 significant digits.

    Thesis: Algorithm 2 and the Summary (the O(m³) bound beside the measured growth).

    Parameters
    ----------
    growth : mapping of str to WorkGrowth
        Family name → its :func:`work_growth`.

    Returns
    -------
    list of list of str
        The header, then one row per family.

    Examples
    --------
    >>> work_table({"paths": WorkGrowth(np.array([19.0, 199.0]), np.array([18.0, 198.0]), 1.0228)})[1]
    ['paths', '19–199', '1.0']
    """
    rows = [["family", "simplices $m$", "fitted $a$ in work $\\propto m^a$"]]
    for family, g in growth.items():
        rows.append([family, f"{int(g.simplices.min())}–{int(g.simplices.max())}", f"{g.exponent:.2}"])
    return rows

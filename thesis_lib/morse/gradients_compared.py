"""Two discrete gradients of one filtration compared by what they leave critical: the greedy Morse
matching (:func:`~thesis_lib.morse.morse_reduce`) and the apparent pairs."""

from __future__ import annotations

from ..homology.filtration import Filtration, as_complex
from ..persistence.apparent import apparent_summary
from ._cells import ComplexLike
from .reduction import morse_reduce

__all__ = ["critical_fractions"]


def critical_fractions(filtration: ComplexLike | Filtration) -> dict[str, float | int]:
    """The share of a filtration's simplices left critical by the greedy Morse matching and by the apparent pairs.

    Thesis: Definition 4.21 (critical cells), Theorem 4.27 (Crit_k ≥ β_k) and Definitions 4.30–4.33
    (the apparent pairs as a gradient).  "Below the top" leaves out the top dimension, whose
    simplices only kill classes of the dimension below (a truncated complex has many of them).

    Parameters
    ----------
    filtration : Filtration or anything :func:`~thesis_lib.homology.filtration.as_complex` takes
        The filtration.

    Returns
    -------
    dict
        ``simplices`` (all of them); ``greedy`` and ``apparent`` (critical fraction of all cells);
        ``greedy_below_top`` and ``apparent_below_top`` (of the cells below the top dimension); and
        ``zero_apparent_below_top`` (the same with only the apparent pairs of equal values).

    Examples
    --------
    >>> import numpy as np
    >>> from thesis_lib.complexes import rips
    >>> f = rips(np.random.default_rng(0).random((8, 2)), max_radius=0.5, max_dim=2)
    >>> r = critical_fractions(f)
    >>> r["simplices"] == len(f) and 0 < r["apparent_below_top"] <= r["apparent"] + 1
    True
    """
    K = as_complex(filtration)
    summary = apparent_summary(K)
    greedy = morse_reduce(K)
    below = sum(summary["simplices"][:-1])
    return {
        "simplices": int(sum(summary["simplices"])),
        "greedy": greedy.critical_fraction,
        "apparent": summary["critical_fraction"],
        "greedy_below_top": sum(c.shape[0] for c in greedy.critical[:-1]) / below,
        "apparent_below_top": summary["critical_fraction_below_top"],
        "zero_apparent_below_top": summary["zero_critical_fraction_below_top"],
    }

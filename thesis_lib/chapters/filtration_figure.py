"""The steps K^0 ⊆ K^1 ⊆ ... of a small planar filtration, listed and drawn one panel per step (Figure 2.11)."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from .._optional import require
from ..datasets.filtrations import simplex_labels
from ..homology.filtration import Filtration, as_complex

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["FIGURE_2_11_POSITIONS", "filtration_steps", "steps_text", "plot_filtration_steps"]

#: positions of a, b, c, d, e of ``datasets.example_filtration()`` in the plane (ours: the thesis's
#: figure gives none): the square abcd with e below cd
FIGURE_2_11_POSITIONS = ((0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0), (0.5, -0.8))

_SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def filtration_steps(filtration: Filtration | Iterable[Any]) -> list[tuple[float, list[tuple[int, ...]]]]:
    """The distinct values of a filtration in increasing order, each with the simplices entering there.

    Thesis: Definition 2.22 (a filtration ∅ = K^0 ⊆ K^1 ⊆ ... ⊆ K^m = K).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        Anything :func:`~thesis_lib.homology.filtration.as_complex` takes.

    Returns
    -------
    list of (float, list of tuple)
        ``(value, simplices)``: the simplices of that value, in the filtration's order.

    Examples
    --------
    >>> filtration_steps([((0,), 0), ((1,), 1), ((0, 1), 1)])
    [(0.0, [(0,)]), (1.0, [(1,), (0, 1)])]
    """
    K = as_complex(filtration)
    pairs = list(K)
    return [(value, [s for s, x in pairs if x == value]) for value in sorted({float(v) for _, v in pairs})]


def steps_text(filtration: Filtration | Iterable[Any], *, names: str | None = None) -> str:
    """One line per step of a filtration: ``K⁰: enters a, b``, the step numbered from 0.

    Thesis: Figure 2.11 and Example 2.38 (the simplices named where they first occur).

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        Anything :func:`~thesis_lib.homology.filtration.as_complex` takes.
    names : str, optional
        ``names[v]`` is the letter of vertex v; default: the numbers.

    Returns
    -------
    str
        The lines, joined by newlines.

    Examples
    --------
    >>> print(steps_text([((0,), 0), ((1,), 1), ((0, 1), 1)], names="ab"))
    K⁰: enters a
    K¹: enters b, ab
    """
    return "\n".join(f"K{str(i).translate(_SUPERSCRIPT)}: enters {', '.join(simplex_labels(entering, names=names))}"
                     for i, (_, entering) in enumerate(filtration_steps(filtration)))


def plot_filtration_steps(filtration: Filtration | Iterable[Any], positions: npt.ArrayLike, *,
                          names: str | None = None, panel_size: float = 1.4,
                          limits: Sequence[Sequence[float]] | None = None) -> Figure:
    """Draw a planar filtration one step per panel, the simplices entering at that step coloured.

    Thesis: Figure 2.11 (the filtration K^0 ⊆ ... ⊆ K^4 = K of Example 2.38).

    Panel i shows K^i: its triangles filled, its edges and its vertices (labelled with ``names``);
    what enters at step i is drawn in the book's first colour and thicker, the rest in grey.

    Parameters
    ----------
    filtration : Filtration or iterable of (simplex, value) pairs
        A filtration of dimension ≤ 2 (anything :func:`~thesis_lib.homology.filtration.as_complex` takes).
    positions : array-like, shape (n, 2)
        The position of each vertex (``FIGURE_2_11_POSITIONS`` for the example).
    names : str, optional
        ``names[v]`` labels vertex v; default: the vertex numbers.
    panel_size : float, default 1.4
        Width of one panel in inches.
    limits : ((float, float), (float, float)), optional
        The x and y ranges of every panel (default: the positions' bounding box with a margin, wider
        right and above for the labels).

    Returns
    -------
    matplotlib.figure.Figure
        One panel per step, titled ``$K^i$``.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        ``positions`` not of shape (n, 2) with a row for every vertex, or a simplex of dimension > 2.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.datasets import example_filtration
    >>> fig = plot_filtration_steps(example_filtration(), FIGURE_2_11_POSITIONS, names="abcde")
    >>> [ax.get_title() for ax in fig.axes]
    ['$K^{0}$', '$K^{1}$', '$K^{2}$', '$K^{3}$', '$K^{4}$']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing a filtration")
    from matplotlib.patches import Polygon

    from ..graphics.style import COLORS

    K = as_complex(filtration)
    pos = np.asarray(positions, dtype=float)
    n_vertices = int(K.simplices[0].max()) + 1 if K.simplices[0].size else 0
    if pos.ndim != 2 or pos.shape[1] != 2 or pos.shape[0] < n_vertices:
        raise ValueError(f"positions must have shape (n, 2) with a row for each of {n_vertices} vertices, "
                         f"got {pos.shape}")
    if K.dimension > 2:
        raise ValueError(f"only filtrations of dimension ≤ 2 are drawn, got dimension {K.dimension}")
    if limits is None:
        lo, hi = pos.min(axis=0), pos.max(axis=0)
        pad = 0.2 * float(max(hi - lo)) or 0.5
        limits = ((lo[0] - pad, hi[0] + 1.5 * pad), (lo[1] - pad, hi[1] + 1.5 * pad))
    label = dict(zip(K.simplices[0][:, 0].tolist(), simplex_labels(K.simplices[0], names=names)))
    steps = filtration_steps(K)
    fig, axes = plt.subplots(1, len(steps), figsize=(panel_size * len(steps), 1.9), squeeze=False)
    for i, (ax, (value, _)) in enumerate(zip(axes[0], steps)):
        for s, x in K:
            if x > value:
                continue
            new = x == value
            color = COLORS["first"] if new else "0.45"
            if len(s) == 3:
                ax.add_patch(Polygon(pos[list(s)], closed=True, fc=color, alpha=0.3, ec="none"))
            elif len(s) == 2:
                ax.plot(*pos[list(s)].T, color=color, lw=2.2 if new else 1.2)
            else:
                ax.plot(*pos[s[0]], "o", color=color, ms=5)
                ax.annotate(label[s[0]], pos[s[0]], xytext=(4, 3), textcoords="offset points", fontsize=10)
        ax.set_title(f"$K^{{{i}}}$")
        ax.set_xlim(*limits[0])
        ax.set_ylim(*limits[1])
        ax.set_aspect("equal")
        ax.axis("off")
    return fig

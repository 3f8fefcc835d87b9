"""Barcodes and persistence diagrams in the thesis's style (Figures 2.10 and 2.12), a long bar's cycle on its
points beside them (Figure 2.9), and the growth of the work of Algorithms 1–2, with matplotlib."""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from .._optional import require
from ._diagrams import parse_diagrams
from .barcode import Barcode

if TYPE_CHECKING:
    import numpy.typing as npt
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from .complexity import WorkGrowth

__all__ = ["plot_barcode", "plot_diagram", "plot_long_bar", "plot_work_growth"]


def _color(dim: int) -> str:
    """One colour per homology dimension, shared by barcodes and diagrams (the book's style)."""
    from ..graphics.style import COLORS

    dims = COLORS["dims"]
    return dims[dim % len(dims)]


#: plot_barcode refuses to draw more bars than this (one matplotlib artist each)
MAX_BARS = 5000


def _dims(barcode: Barcode, dims: Sequence[int] | None) -> list[int]:
    dims = list(barcode.complete_dimensions if dims is None else dims)
    if not dims:
        raise ValueError("no homology dimension to plot")
    return [int(d) for d in dims]


def _diagrams_to_draw(data: Barcode | npt.ArrayLike | Sequence[npt.ArrayLike],
                      dims: Sequence[int] | None) -> dict[int, np.ndarray]:
    """Homology dimension -> its ``(k, 2)`` intervals, for each dimension to draw, in order.

    A Barcode gives its intervals (default: its complete dimensions); a list of diagrams (ripser's
    ``dgms``) gives ``dgms[d]`` for each of ``dims`` (default: all); a single diagram is one
    dimension, ``dims[0]`` if given (default 0).  An empty array or list is one empty diagram.
    """
    if isinstance(data, Barcode):
        return {d: data.intervals(d) for d in _dims(data, dims)}
    diagrams, single = parse_diagrams(data, "diagram")
    if dims is not None:
        from .._validate import check_int

        dims = [check_int(d, "a dimension of dims", minimum=0) for d in dims]
        if not dims:
            raise ValueError("no homology dimension to plot")
    if single:
        if dims is not None and len(dims) != 1:
            raise ValueError(f"one diagram was given: dims names its one dimension, got {len(dims)} dimensions")
        return {dims[0] if dims else 0: diagrams[0]}
    if dims is None:
        return dict(enumerate(diagrams))
    missing = [d for d in dims if d >= len(diagrams)]
    if missing:
        raise ValueError(f"no diagram for dimension {missing[0]}: {len(diagrams)} diagrams given (0 .. "
                         f"{len(diagrams) - 1})")
    return {d: diagrams[d] for d in dims}


def _right_edge(diagrams: Mapping[int, np.ndarray], max_value: float | None) -> float:
    if max_value is not None:
        return float(max_value)
    finite = [v for iv in diagrams.values() for v in iv.ravel() if np.isfinite(v)]
    top = max(finite) if finite else 1.0
    return top + 0.15 * (top - min(finite + [0.0]) or 1.0)


def plot_barcode(
    barcode: Barcode | npt.ArrayLike | Sequence[npt.ArrayLike],
    *,
    dims: Sequence[int] | None = None,
    axes: Axes | Sequence[Axes] | None = None,
    max_value: float | None = None,
    min_length: float = 0.0,
    min_fraction: float = 0.01,
    max_bars: int = MAX_BARS,
    xlabel: str = "filtration value",
    title: str | None = None,
) -> Figure:
    """Draw a barcode: one panel per dimension, one horizontal bar per interval, arrows for ∞.

    Thesis: Figures 2.10 and 2.12 (barcodes; the vertical axis is an arbitrary ordering).

    Parameters
    ----------
    barcode : Barcode, array_like of shape (n, 2), or list of them
        The bars: a :class:`Barcode`; one persistence diagram, an ``(n, 2)`` array of
        ``(birth, death)`` (``death = inf`` for an essential class); or a list of diagrams, one per
        homology dimension (ripser.py's ``dgms``).  An empty array or an empty list is one empty
        diagram (a panel without bars).  Arrays are drawn as they are (no scale is applied).
    dims : sequence of int, optional
        Dimensions to draw, one panel each, top to bottom.  Default: a Barcode's complete
        dimensions, every diagram of a list; for a single diagram, ``dims=[k]`` names its
        dimension (default 0).
    axes : matplotlib Axes or sequence of Axes, optional
        One axes per dimension to draw into; a new figure otherwise.
    max_value : float, optional
        Right end of the axis; essential bars run to it and end in an arrow (default: a little past
        the largest finite value).
    min_length : float
        Leave out bars shorter than this (noise); ≥ 0.
    min_fraction : float
        Also leave out bars shorter than this fraction of the drawn range (default 1 %: bars thinner
        than a line width; 0 draws every bar).
    max_bars : int
        Refuse to draw more bars than this; raise ``min_length`` or ``min_fraction``, or choose
        ``dims``, to draw fewer.
    xlabel : str
        Label of the horizontal axis (under the bottom panel).
    title : str, optional
        Title over the top panel.

    Returns
    -------
    matplotlib.figure.Figure
        The figure holding the panels.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    TypeError
        ``barcode`` is neither a Barcode nor diagrams of numbers (a dict, a string, a list mixing
        rows and diagrams); a non-integer in ``dims``.
    ValueError
        No dimension to draw, a diagram that is not ``(n, 2)``, a NaN, an infinite birth, a death
        before its birth, a dimension of ``dims`` without a diagram (or more than one for a single
        diagram), a negative ``min_length`` or ``min_fraction``, more than ``max_bars`` bars, or a
        number of ``axes`` other than of ``dims``.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> dgms = [np.array([[0.0, 1.0], [0.0, np.inf]]), np.array([[0.4, 0.9]])]  # ripser.py's format
    >>> fig = plot_barcode(dgms, min_fraction=0)
    >>> [len(ax.collections) for ax in fig.axes]  # one horizontal bar each; the essential one ends in an arrow
    [2, 1]
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting barcodes")

    diagrams = _diagrams_to_draw(barcode, dims)
    dims = list(diagrams)
    for name, value in (("min_length", min_length), ("min_fraction", min_fraction)):
        if not value >= 0:
            raise ValueError(f"{name} must be >= 0, got {value}")
    right = _right_edge(diagrams, max_value)
    lowest = min([0.0] + [float(iv[:, 0].min()) for iv in diagrams.values() if iv.size])
    cut = max(float(min_length), float(min_fraction) * (right - lowest))
    bars = {}
    for d, iv in diagrams.items():
        bars[d] = iv[(iv[:, 1] - iv[:, 0]) >= cut] if cut > 0 else iv
    total = sum(b.shape[0] for b in bars.values())
    if total > max_bars:
        raise ValueError(f"{total} bars to draw (more than max_bars={max_bars}): raise min_length or min_fraction, "
                         "or choose dims")
    if axes is None:
        heights = [max(1, bars[d].shape[0]) for d in dims]
        ratios = [0.6 + min(h, 40) for h in heights]
        height = 0.9 + 0.22 * sum(min(h, 40) for h in heights) + 0.5 * len(dims)
        fig, axes = plt.subplots(
            len(dims), 1, sharex=True, squeeze=False, figsize=(6.4, height),
            gridspec_kw={"height_ratios": ratios},
        )
        axes = axes[:, 0]
    else:
        axes = list(np.atleast_1d(axes))
        if len(axes) != len(dims):
            raise ValueError(f"need {len(dims)} axes, got {len(axes)}")
        fig = axes[0].figure
    left = min([0.0] + [float(bars[d][:, 0].min()) for d in dims if bars[d].size])
    for ax, d in zip(axes, dims):
        iv = bars[d]
        # longest bars on top, as in the thesis's figures (births left to right)
        order = np.lexsort((-(np.minimum(iv[:, 1], right) - iv[:, 0]), iv[:, 0])) if iv.size else []
        lw = 3.0 if iv.shape[0] <= 40 else max(0.6, 120.0 / iv.shape[0])
        for y, k in enumerate(order):
            b, e = iv[k]
            if np.isfinite(e):
                ax.hlines(y, b, e, color=_color(d), lw=lw)
            else:
                ax.hlines(y, b, right, color=_color(d), lw=lw)
                ax.annotate(
                    "", xy=(right, y), xytext=(right - 0.02 * (right - left), y),
                    arrowprops={"arrowstyle": "-|>", "color": _color(d), "lw": lw, "mutation_scale": 12},
                    annotation_clip=False,
                )  # fmt: skip
        ax.set_ylim(-1, max(1, iv.shape[0]))
        ax.invert_yaxis()
        ax.set_yticks([])
        ax.set_ylabel(f"$H_{d}$", rotation=0, labelpad=14, va="center")
        for side in ("top", "right", "left"):
            ax.spines[side].set_visible(False)
        ax.set_xlim(left - 0.02 * (right - left), right * 1.0 + 0.03 * (right - left))
    axes[-1].set_xlabel(xlabel)
    if title:
        axes[0].set_title(title)
    return fig


def plot_diagram(
    barcode: Barcode | npt.ArrayLike | Sequence[npt.ArrayLike],
    *,
    dims: Sequence[int] | None = None,
    ax: Axes | None = None,
    max_value: float | None = None,
    title: str | None = None,
) -> Figure:
    """Persistence diagram: each interval as a point (birth, death); essential ones on a line marked ∞.

    Thesis: Theorem 2.37 (β^{l,k} counts the points up-left of (l, l + k)); §2.3 barcodes as points.

    Parameters
    ----------
    barcode : Barcode, array_like of shape (n, 2), or list of them
        Each interval becomes one point: a :class:`Barcode`; one persistence diagram, an
        ``(n, 2)`` array of ``(birth, death)`` (``death = inf`` for an essential class); or a list of
        diagrams, one per homology dimension (ripser.py's ``dgms``).  An empty array or an empty
        list is one empty diagram (no points).  Arrays are drawn as they are (no scale is applied).
    dims : sequence of int, optional
        The dimensions shown, one colour each, all in one panel.  Default: a Barcode's complete
        dimensions, every diagram of a list; for a single diagram, ``dims=[k]`` names its
        dimension (default 0).
    ax : matplotlib Axes, optional
        Where to draw; without it, in a new figure.
    max_value : float, optional
        Where the line of essential classes (∞) is drawn and the axes end (default: a little past
        the largest finite value), as persim draws them: the points of ``death = inf`` sit on a
        dashed line across the top.
    title : str, optional
        Title of the panel.

    Returns
    -------
    matplotlib.figure.Figure
        The figure holding the diagram.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    TypeError
        ``barcode`` is neither a Barcode nor diagrams of numbers (a dict, a string, a list mixing
        rows and diagrams); a non-integer in ``dims``.
    ValueError
        No dimension to draw, a diagram that is not ``(n, 2)``, a NaN, an infinite birth, a death
        before its birth, or a dimension of ``dims`` without a diagram (or more than one for a
        single diagram).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_diagram(np.array([[0.0, 1.0], [0.5, np.inf]]), max_value=2.0)
    >>> fig.axes[0].collections[0].get_offsets().tolist()  # the essential point on the line at the top
    [[0.0, 1.0], [0.5, 2.0]]
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting persistence diagrams")

    diagrams = _diagrams_to_draw(barcode, dims)
    right = _right_edge(diagrams, max_value)
    # negative values (an image's lower-star filtration) move the lower-left corner below 0
    low = min([0.0] + [float(iv[:, 0].min()) for iv in diagrams.values() if iv.size])
    span = right - low
    if ax is None:
        fig, ax = plt.subplots(figsize=(4.6, 4.6))
    else:
        fig = ax.figure
    ax.plot([low, right], [low, right], color="0.5", lw=0.8)
    ax.axhline(right, color="0.7", lw=0.8, ls="--")
    for d, iv in diagrams.items():
        death = np.where(np.isfinite(iv[:, 1]), iv[:, 1], right)
        ax.scatter(iv[:, 0], death, s=14, color=_color(d), label=f"$H_{d}$", zorder=3, edgecolor="none")
    ax.set_xlim(low - 0.02 * span, low + span * 1.04)
    ax.set_ylim(low - 0.02 * span, low + span * 1.06)
    ax.set_xlabel("birth")
    ax.set_ylabel("death")
    ax.text(low + 0.01 * span, low + span * 1.01, "∞", va="bottom")
    ax.legend(loc="lower right", frameon=False)
    ax.set_aspect("equal")
    if title:
        ax.set_title(title)
    return fig


def plot_long_bar(points: npt.ArrayLike, barcode: Barcode, *, index: int | None = None, dim: int = 1,
                  max_value: float | None = None, min_length: float = 0.0) -> Figure:
    """A bar's representative cycle drawn on the points, beside the barcode and the persistence diagram.

    Thesis: Figure 2.9 (points sampled with noise from a circle; the persistent cycle is the hole).

    Parameters
    ----------
    points : array-like, shape (n, 2)
        The vertex positions of the filtration the barcode was computed from.
    barcode : Barcode
        A barcode that knows its representatives (computed from a filtration).
    index : int, optional
        The row in ``barcode.intervals(dim)`` of the bar whose cycle is drawn (default: the longest).
    dim : int, default 1
        The dimension of the bar, and of the barcode panel; the diagram shows dimensions 0 .. dim.
    max_value : float, optional
        Right end of the barcode and diagram axes (as :func:`plot_barcode`).
    min_length : float, default 0
        The barcode and the diagram leave out bars no longer than this.

    Returns
    -------
    matplotlib.figure.Figure
        Three panels: the points with the cycle, the barcode of ``dim``, the persistence diagram.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        A barcode without representatives, or no bar ``index``.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.complexes import alpha
    >>> from thesis_lib.datasets import noisy_circle
    >>> from thesis_lib.persistence import persistence
    >>> points = noisy_circle(30, noise=0.05, seed=0)
    >>> fig = plot_long_bar(points, persistence(alpha(points)))
    >>> len(fig.axes)
    3
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting a representative cycle")
    from ..graphics.style import COLORS

    pts = np.asarray(points, dtype=float)
    i = int(barcode.longest(dim, n=1)[0]) if index is None else int(index)
    cycle = barcode.representative(dim, i)
    fig, axes = plt.subplots(1, 3, figsize=(7.2, 2.7), gridspec_kw={"width_ratios": [1, 1.2, 1]})
    ax = axes[0]
    ax.scatter(pts[:, 0], pts[:, 1], s=6, color=COLORS["points"])
    for simplex, _ in cycle:
        ax.plot(pts[list(simplex), 0], pts[list(simplex), 1], color=_color(dim), lw=1.4)
    ax.set_aspect("equal")
    ax.set_title(f"the long bar's cycle ({len(cycle)} edges)", fontsize=10)
    dims = list(range(dim + 1))
    shown = Barcode({d: barcode.intervals(d)[barcode.intervals(d)[:, 1] - barcode.intervals(d)[:, 0] > min_length]
                     for d in dims})
    plot_barcode(shown, dims=[dim], axes=[axes[1]], max_value=max_value, title=f"$H_{dim}$ barcode")
    plot_diagram(shown, dims=dims, ax=axes[2], max_value=max_value, title="persistence diagram")
    for a in axes:
        a.title.set_fontsize(10)
    axes[2].set_title("persistence diagram", fontsize=10, pad=14)
    fig.tight_layout()
    return fig


#: the reference slopes of :func:`plot_work_growth`: exponent, line style, name
_REFERENCE_SLOPES = ((1, ":", "m"), (2, "--", "m²"), (3, "-.", "m³"))


def plot_work_growth(growth: Mapping[str, WorkGrowth], *, reference: tuple[float, float] | None = None,
                     ylim: tuple[float, float] | None = None) -> Figure:
    """The work of Algorithms 1–2 against the number of simplices, log-log, with the slopes of m, m², m³.

    Thesis: Algorithm 2 and the Summary (ComputeIntervals is O(m³) in the number m of simplices).

    Parameters
    ----------
    growth : mapping of str to WorkGrowth
        Family name → its :func:`~thesis_lib.persistence.complexity.work_growth`; the legend shows
        the name up to its first ``:`` and the fitted exponent.
    reference : (float, float), optional
        The range of m of the reference lines (default: half the smallest m to twice the largest);
        each starts at twice its left end.
    ylim : (float, float), optional
        The range of the work axis (default: matplotlib's).

    Returns
    -------
    matplotlib.figure.Figure
        One panel, the legend right of it.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        No family to draw.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.persistence.complexity import WorkGrowth
    >>> fig = plot_work_growth({"paths": WorkGrowth(np.array([19.0, 199.0]), np.array([18.0, 198.0]), 1.02)})
    >>> [t.get_text() for t in fig.axes[0].get_legend().get_texts()][:2]
    ['paths (a ≈ 1.0)', 'slope of m']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting the work of Algorithms 1-2")
    from ..graphics.style import COLORS

    if not growth:
        raise ValueError("no family to draw")
    colors = itertools.cycle([COLORS["first"], COLORS["second"], COLORS["highlight"], COLORS["points"]])
    fig, ax = plt.subplots(figsize=(5.4, 3.4))
    for (family, g), color in zip(growth.items(), colors):
        ax.loglog(g.simplices, g.work, "o", color=color, ms=4, label=f"{family.split(':')[0]} (a ≈ {g.exponent:.2})")
    if reference is None:
        m = np.concatenate([g.simplices for g in growth.values()])
        reference = (float(m.min()) / 2, float(m.max()) * 2)
    m_ref = np.array(reference, dtype=float)
    for a, style, name in _REFERENCE_SLOPES:
        ax.loglog(m_ref, 2 * m_ref**a / m_ref[0] ** (a - 1), style, color="0.6", lw=1, label=f"slope of {name}")
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.set_xlabel("simplices m")
    ax.set_ylabel("work (entries touched)")
    ax.tick_params(labelsize=10.5)
    ax.legend(fontsize=9.5, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    return fig

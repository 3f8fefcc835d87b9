"""Barcodes and persistence diagrams in the thesis's style (Figures 2.10 and 2.12), with matplotlib."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from .._optional import require
from .barcode import Barcode

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["plot_barcode", "plot_diagram"]


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


def _right_edge(barcode: Barcode, dims: list[int], max_value: float | None) -> float:
    if max_value is not None:
        return float(max_value)
    finite = [v for d in dims for v in barcode.intervals(d).ravel() if np.isfinite(v)]
    top = max(finite) if finite else 1.0
    return top + 0.15 * (top - min(finite + [0.0]) or 1.0)


def plot_barcode(
    barcode: Barcode,
    dims: Sequence[int] | None = None,
    *,
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
    barcode : Barcode
        The barcode to draw.
    dims : sequence of int, optional
        Dimensions to draw (default: the complete ones), one panel each, top to bottom.
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
    ValueError
        No dimension to draw, a negative ``min_length`` or ``min_fraction``, more than ``max_bars``
        bars, or a number of ``axes`` other than of ``dims``.
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting barcodes")

    dims = _dims(barcode, dims)
    for name, value in (("min_length", min_length), ("min_fraction", min_fraction)):
        if not value >= 0:
            raise ValueError(f"{name} must be >= 0, got {value}")
    right = _right_edge(barcode, dims, max_value)
    lowest = min([0.0] + [float(barcode.intervals(d)[:, 0].min()) for d in dims if barcode.intervals(d).size])
    cut = max(float(min_length), float(min_fraction) * (right - lowest))
    bars = {}
    for d in dims:
        iv = barcode.intervals(d)
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
    barcode: Barcode,
    dims: Sequence[int] | None = None,
    *,
    ax: Axes | None = None,
    max_value: float | None = None,
    title: str | None = None,
) -> Figure:
    """Persistence diagram: each interval as a point (birth, death); essential ones on a line marked ∞.

    Thesis: Theorem 2.37 (β^{l,k} counts the points up-left of (l, l + k)); §2.3 barcodes as points.

    Parameters
    ----------
    barcode : Barcode
        Each of its intervals becomes one point.
    dims : sequence of int, optional
        The dimensions shown, one colour each, all in one panel (default: the complete ones).
    ax : matplotlib Axes, optional
        Where to draw; without it, in a new figure.
    max_value : float, optional
        Where the line of essential classes (∞) is drawn and the axes end (default: a little past
        the largest finite value).
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
    ValueError
        No dimension to draw.
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting persistence diagrams")

    dims = _dims(barcode, dims)
    right = _right_edge(barcode, dims, max_value)
    if ax is None:
        fig, ax = plt.subplots(figsize=(4.6, 4.6))
    else:
        fig = ax.figure
    ax.plot([0, right], [0, right], color="0.5", lw=0.8)
    ax.axhline(right, color="0.7", lw=0.8, ls="--")
    for d in dims:
        iv = barcode.intervals(d)
        death = np.where(np.isfinite(iv[:, 1]), iv[:, 1], right)
        ax.scatter(iv[:, 0], death, s=14, color=_color(d), label=f"$H_{d}$", zorder=3, edgecolor="none")
    ax.set_xlim(-0.02 * right, right * 1.04)
    ax.set_ylim(-0.02 * right, right * 1.06)
    ax.set_xlabel("birth")
    ax.set_ylabel("death")
    ax.text(0.01 * right, right * 1.01, "∞", va="bottom")
    ax.legend(loc="lower right", frameon=False)
    ax.set_aspect("equal")
    if title:
        ax.set_title(title)
    return fig

"""A point sample (two of its coordinates) beside its barcode: the figure of a reconstruction experiment."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy.typing as npt

from .._optional import require
from .._validate import as_points
from ..persistence.barcode import Barcode
from ..persistence.plotting import plot_barcode

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot_sample_and_barcode"]


def plot_sample_and_barcode(points: npt.ArrayLike, barcode: Barcode, *, dims: Sequence[int],
                            max_value: float | None = None, coordinates: tuple[int, int] = (0, 1),
                            title: str = "first two coordinates",
                            figsize: tuple[float, float] = (7.0, 3.6)) -> Figure:
    """Draw a sample (two coordinates) on the left and its barcode on the right, one panel per dimension.

    Thesis: Figures 2.14–2.16 (a sample of a space beside the barcode of its complex).

    Parameters
    ----------
    points : array_like, shape (n, d)
        The sample, d ≥ 2.
    barcode : Barcode
        Its barcode.
    dims : sequence of int
        The dimensions of the barcode to draw, one panel each, top to bottom.
    max_value : float, optional
        Right end of the barcode axis (as :func:`~thesis_lib.persistence.plot_barcode`).
    coordinates : (int, int), default (0, 1)
        The two coordinates of the points to draw.
    title : str, default "first two coordinates"
        Title of the sample's panel.
    figsize : (float, float), default (7.0, 3.6)
        The figure size in inches.

    Returns
    -------
    matplotlib.figure.Figure
        The sample's panel first, then one panel per dimension.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        Points with fewer coordinates than asked for, or no dimension to draw.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.datasets import noisy_circle
    >>> from thesis_lib.persistence import rips_persistence
    >>> X = noisy_circle(30, noise=0.05, seed=0)
    >>> fig = plot_sample_and_barcode(X, rips_persistence(X, max_radius=1.0), dims=[0, 1], max_value=1.0)
    >>> len(fig.axes)
    3
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing a sample and its barcode")
    from ..graphics.style import COLORS

    pts = as_points(points)
    i, j = coordinates
    if not (0 <= i < pts.shape[1] and 0 <= j < pts.shape[1]):
        raise ValueError(f"coordinates {coordinates} are not among the points' {pts.shape[1]} coordinates")
    dims = list(dims)
    if not dims:
        raise ValueError("dims must name at least one dimension of the barcode")
    fig = plt.figure(figsize=figsize)
    grid_spec = fig.add_gridspec(len(dims), 2, width_ratios=[1, 1.5])
    sample = fig.add_subplot(grid_spec[:, 0])
    sample.plot(pts[:, i], pts[:, j], ".", ms=1, color=COLORS["points"])
    sample.set_aspect("equal")
    sample.set_title(title)
    axes = [fig.add_subplot(grid_spec[k, 1]) for k in range(len(dims))]
    plot_barcode(barcode, dims=dims, axes=axes, max_value=max_value, min_length=0.0)
    fig.tight_layout()
    return fig

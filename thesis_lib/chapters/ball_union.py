"""The union of closed balls B(x, ε) around a planar point set, one panel per radius (the cover whose
nerve is the Čech complex)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import as_points

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot_ball_unions"]


def plot_ball_unions(points: npt.ArrayLike, radii: Sequence[float], *, limit: float | None = None,
                     figsize: tuple[float, float] = (7.0, 2.6)) -> Figure:
    """Draw the points and the union of the closed balls B(x, ε) around them, one panel per ε.

    Thesis: Definition 2.9 (the balls B(x, ε) whose nerve is the Čech complex C(X, ε)) and
    Theorem 2.8 (the nerve is homotopy equivalent to their union).

    Parameters
    ----------
    points : array_like, shape (n, 2)
        A planar point set.
    radii : sequence of float
        The radii ε, one panel each (each > 0).
    limit : float, optional
        Every panel shows [−limit, limit]²; default: the largest |coordinate| plus the largest radius.
    figsize : (float, float), default (7.0, 2.6)
        The figure size in inches.

    Returns
    -------
    matplotlib.figure.Figure
        One panel per radius, titled ``ε = …``, with equal axes shared by all panels.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        Points not of shape (n, 2), no radius, or a radius that is not positive and finite.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_ball_unions([[0.0, 0.0], [1.0, 0.0]], [0.25, 0.75])
    >>> [ax.get_title() for ax in fig.axes]
    ['ε = 0.25', 'ε = 0.75']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing unions of balls")
    from matplotlib.patches import Circle

    from ..graphics.style import COLORS

    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points must be planar, of shape (n, 2), got {pts.shape}")
    eps = np.asarray(radii, dtype=np.float64).ravel()
    if eps.size == 0 or not np.all(np.isfinite(eps) & (eps > 0)):
        raise ValueError(f"radii must be one or more positive finite numbers, got {list(radii)!r}")
    if limit is None:
        limit = float(np.abs(pts).max(initial=0.0) + eps.max())
    fig, axes = plt.subplots(1, eps.size, figsize=figsize, sharex=True, sharey=True, squeeze=False)
    for ax, r in zip(axes[0], eps):
        for p in pts:
            ax.add_patch(Circle(p, r, color=COLORS["second"], alpha=0.18, lw=0))
        ax.plot(*pts.T, ".", color="black", ms=3)
        ax.set_title(f"ε = {r:g}")
        ax.set_aspect("equal")
        ax.set_xlim(-limit, limit)
        ax.set_ylim(-limit, limit)
    return fig

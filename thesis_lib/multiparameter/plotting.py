"""Figures of two-parameter persistence: Hilbert-function heat maps, and fibered barcodes drawn on
their lines in the (ε, κ) plane."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from ..persistence.barcode import Barcode
from .bifiltration import Bifiltration
from .invariants import check_grid, fibered_barcode

if TYPE_CHECKING:  # matplotlib is imported only when drawing
    from matplotlib.axes import Axes
    from matplotlib.collections import QuadMesh
    from matplotlib.figure import Figure

__all__ = ["plot_hilbert", "plot_hilbert_functions", "line_fan", "plot_fibered_barcodes"]

SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def plot_hilbert(ax: Axes, values: npt.ArrayLike, radii: npt.ArrayLike, curvatures: npt.ArrayLike, *, label: str = "",
                 vmax: int | None = None, cmap: str = "viridis", xlabel: str = "ε", ylabel: str = "κ",
                 colorbar: bool = True) -> QuadMesh:
    """Heat map of one Hilbert function ``values[i, j]`` = dim H_k(K_{ε_i, κ_j}) on the grid.

    Each grid value is drawn as the cell up to the next one (K_{ε,κ} is constant there when the grid
    holds every grade).  The colour bar is discrete, labelled horizontally.

    Thesis: Chapter 5 (the homology for each pair (ε, κ)).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    values : array_like of int, shape (len(radii), len(curvatures))
        One Hilbert function, e.g. ``hilbert_function(...)[a]``.
    radii, curvatures : array_like
        The grid axes (strictly increasing); the last cell is as wide as the one before it.
    label : str, default ""
        Title of the colour bar (e.g. ``"β₁"``).
    vmax : int, optional
        Largest value of the colour scale (default ``values.max()``).
    cmap : str, default "viridis"
        A matplotlib colour map name.
    xlabel, ylabel : str
        Axis labels (default ``"ε"`` and ``"κ"``).
    colorbar : bool, default True
        Draw the colour bar beside ``ax``.

    Returns
    -------
    matplotlib.collections.QuadMesh
        The heat map.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        A bad grid, or ``values`` of the wrong shape.
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting Hilbert functions")
    from matplotlib.colors import BoundaryNorm

    radii, curvatures = check_grid(radii, name="radii"), check_grid(curvatures, name="curvatures")
    v = np.asarray(values)
    if v.shape != (radii.size, curvatures.size):
        raise ValueError(f"values must have shape {(radii.size, curvatures.size)}, got {v.shape}")
    top = int(v.max()) if vmax is None else int(vmax)
    edges_e = np.append(radii, radii[-1] + (radii[-1] - radii[-2] if radii.size > 1 else 1.0))
    edges_k = np.append(curvatures, curvatures[-1] + (curvatures[-1] - curvatures[-2] if curvatures.size > 1 else 1.0))
    norm = BoundaryNorm(np.arange(-0.5, top + 1.5), plt.get_cmap(cmap).N)
    mesh = ax.pcolormesh(edges_e, edges_k, v.T, cmap=cmap, norm=norm, shading="flat")
    ax.set(xlabel=xlabel, ylabel=ylabel)
    if colorbar:
        cb = ax.figure.colorbar(mesh, ax=ax, ticks=range(top + 1), fraction=0.05, pad=0.03)
        cb.ax.set_title(label, fontsize=9)
    return mesh


def plot_hilbert_functions(values: Sequence[npt.ArrayLike], radii: npt.ArrayLike, curvatures: npt.ArrayLike, *,
                           dims: Sequence[int] = (0, 1), vmax: int | None = None, rows: str = "bounds",
                           mark: float | None = None, ylabel: str = "", figsize: tuple[float, float] = (7.0, 3.0),
                           wspace: float = 0.55) -> Figure:
    """One heat map per homology dimension, side by side.

    Thesis: Chapter 5 (dim H_k(K_{ε,κ}) for each pair (ε, κ)).

    Parameters
    ----------
    values : sequence of array_like of int
        ``values[i]`` of shape (len(radii), len(curvatures)): the Hilbert function of H_{dims[i]}, as
        :func:`~thesis_lib.multiparameter.hilbert_function` returns them for ``dims``.
    radii, curvatures : array_like
        The grid axes (strictly increasing).
    dims : sequence of int, default (0, 1)
        The homology dimension of each entry of ``values``, one panel each (titled ``dim H_k``).
    vmax : int, optional
        Values above it are drawn as ``vmax`` (the colour scale ends there); default: no cap.
    rows : {"bounds", "values"}, default "bounds"
        ``"bounds"``: one even row per κ of the grid, labelled ``κ ≤ κ_j`` (for uneven grids such as
        0.5, 1, 5, 10); ``"values"``: the κ axis to scale.
    mark : float, optional
        A κ drawn as a dotted white line (e.g. 0, between negative and positive curvature).
    ylabel : str, default ""
        The κ axis label.
    figsize : (float, float), default (7.0, 3.0)
        The figure size in inches.
    wspace : float, default 0.55
        The space between the panels (a fraction of a panel's width).

    Returns
    -------
    matplotlib.figure.Figure
        The figure: the panels, then their colour bars.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        ``dims`` not one per entry of ``values``, an unknown ``rows``, a bad grid, or values of the
        wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> hf = [np.ones((3, 2), dtype=int), np.zeros((3, 2), dtype=int)]
    >>> fig = plot_hilbert_functions(hf, [0.0, 0.5, 1.0], [1.0, 5.0], vmax=2)
    >>> [ax.get_title() for ax in fig.axes[:2]]  # the panels, then their colour bars
    ['dim H₀', 'dim H₁']
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting Hilbert functions")
    curvatures = check_grid(curvatures, name="curvatures")
    if len(dims) != len(values):
        raise ValueError(f"dims must name the homology dimension of each of the {len(values)} Hilbert functions, "
                         f"got {list(dims)}")
    if rows not in ("bounds", "values"):
        raise ValueError(f"rows must be 'bounds' or 'values', got {rows!r}")
    even = np.arange(curvatures.size)
    fig, axes = plt.subplots(1, len(dims), figsize=figsize, gridspec_kw={"wspace": wspace}, squeeze=False)
    for ax, hf, d in zip(axes[0], values, dims):
        shown = np.asarray(hf) if vmax is None else np.minimum(hf, vmax)
        name = str(d).translate(SUBSCRIPTS)
        plot_hilbert(ax, shown, radii, even if rows == "bounds" else curvatures, label=f"β{name}", vmax=vmax,
                     ylabel=ylabel)
        if rows == "bounds":
            ax.set_yticks(even + 0.5, [f"κ ≤ {k:g}" for k in curvatures])
        if mark is not None:
            ax.axhline(mark, color="white", lw=0.8, ls=":")
        ax.set_title(f"dim H{name}")
    return fig


def line_fan(bounds: npt.ArrayLike, *, n_lines: int = 5, base: npt.ArrayLike | None = None,
             angles: tuple[float, float] = (15.0, 75.0)) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """``n_lines`` lines of positive slope through ``base`` (default the lower-left corner of
    ``bounds`` = ``[[ε_min, κ_min], [ε_max, κ_max]]``), at angles spread over ``angles`` (degrees)
    in the box's own scale, so that each line crosses the box.

    Thesis: Chapter 5 (one line of the (ε, κ) plane is one ordinary persistence problem).

    Parameters
    ----------
    bounds : array_like, shape (2, 2)
        The box ``[[ε_min, κ_min], [ε_max, κ_max]]`` with a positive span, e.g.
        :meth:`~thesis_lib.multiparameter.Bifiltration.bounds`.
    n_lines : int, default 5
        How many lines.
    base : array_like, shape (2,), optional
        The common point of the lines; default the lower-left corner.
    angles : (float, float), default (15.0, 75.0)
        The first and last angle in degrees, measured in the box scaled to a unit square.

    Returns
    -------
    base : ndarray of float64, shape (2,)
        The common point.
    directions : ndarray of float64, shape (n_lines, 2)
        One direction per line, scaled so that base + t·direction reaches the box's far side at
        t = 1.

    Raises
    ------
    ValueError
        ``bounds`` not a 2 × 2 box with a positive span.
    """
    b = np.asarray(bounds, dtype=np.float64)
    span = b[1] - b[0]
    if b.shape != (2, 2) or np.any(span <= 0):
        raise ValueError(f"bounds must be [[ε_min, κ_min], [ε_max, κ_max]] with a positive span, got {b.tolist()}")
    base = b[0] if base is None else np.asarray(base, dtype=np.float64)
    phi = np.radians(np.linspace(angles[0], angles[1], n_lines))
    unit = np.column_stack([np.cos(phi), np.sin(phi)])
    dirs = unit * span
    dirs /= np.max(dirs / np.maximum(b[1] - base, 1e-300), axis=1, keepdims=True)
    return base, dirs


def plot_fibered_barcodes(ax: Axes, bifiltration: Bifiltration, base: npt.ArrayLike, directions: npt.ArrayLike, *,
                          dim: int, min_length: float = 0.0, colors: Sequence[str] | None = None,
                          linewidth: float = 4.0, coefficients: int | None = None) -> list[Barcode]:
    """Draw each line base + t·direction and, on it, the bars of its fibered barcode in H_dim as
    thick segments (offset sideways a little so that overlapping bars stay visible).

    Thesis: Definition 2.34 (a barcode), along lines of the (ε, κ) plane (Chapter 5).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw, its limits already set (kept; they set the sideways offset).
    bifiltration : Bifiltration
        The one-critical bifiltration.
    base : array_like, shape (2,)
        The common point of the lines.
    directions : array_like, shape (n_lines, 2) or (2,)
        One direction per line, both components > 0 (e.g. from :func:`line_fan`).
    dim : int
        The homology dimension drawn.
    min_length : float, default 0.0
        Bars shorter than this (in t) are left out.
    colors : sequence of str, optional
        One colour per line, cycled (default matplotlib's colour cycle).
    linewidth : float, default 4.0
        Width of the bars.
    coefficients : int, optional
        A prime p, the field Z/p (default 2).

    Returns
    -------
    list of Barcode
        The fibered barcode of each line (all dimensions, every bar), in the order of
        ``directions``.  Bars are drawn up to t = 1.5.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        A direction that is not positive, or coefficients that are not a prime.
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="plotting fibered barcodes")

    base = np.asarray(base, dtype=np.float64)
    dirs = np.atleast_2d(np.asarray(directions, dtype=np.float64))
    colors = colors or plt.rcParams["axes.prop_cycle"].by_key()["color"]
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    scale = np.array([xlim[1] - xlim[0], ylim[1] - ylim[0]])
    out = []
    for i, d in enumerate(dirs):
        bc = fibered_barcode(bifiltration, base, d, coefficients=coefficients)
        out.append(bc)
        c = colors[i % len(colors)]
        ax.plot(*np.stack([base, base + 1.5 * d]).T, color=c, lw=0.8, ls="--")
        bars = bc.intervals(dim)
        bars = bars[bars[:, 1] - bars[:, 0] >= min_length]
        normal = np.array([-d[1] / scale[1], d[0] / scale[0]])
        normal = normal / np.linalg.norm(normal) * scale * 0.008
        for k, (t0, t1) in enumerate(bars):
            t1 = min(t1, 1.5)
            seg = np.stack([base + t0 * d, base + t1 * d]) + (k - (len(bars) - 1) / 2) * normal
            ax.plot(*seg.T, color=c, lw=linewidth, solid_capstyle="butt")
    ax.set_xlim(xlim)
    ax.set_ylim(ylim)
    return out

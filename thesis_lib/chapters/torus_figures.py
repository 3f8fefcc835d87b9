"""The figures of the torus experiment (thesis §3.4.1): curvature estimates drawn on the meshes
(Figures 3.4, 3.6, 3.8–3.10), the relative errors over the parameter square (Figures 3.5 and 3.7)
and the estimated |H| of the random samples against the exact profile (Figure 3.11)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require

if TYPE_CHECKING:
    from matplotlib.colorbar import Colorbar
    from matplotlib.figure import Figure

__all__ = [
    "TRIANGULATION_LABELS",
    "plot_estimate_on_mesh",
    "plot_gaussian_curvature_errors",
    "plot_mean_curvature_errors",
    "plot_mean_curvature_profile",
]

#: how the figures name the two triangulations of the chosen points
TRIANGULATION_LABELS = {"crust": "Crust of the chosen points", "fixed": "fixed-diagonal grid"}
#: the range of the relative errors' logarithmic colour scale
ERROR_RANGE = (1e-5, 1.0)


def plot_estimate_on_mesh(vertices: npt.ArrayLike, simplices: npt.ArrayLike, values: npt.ArrayLike, *,
                          clim: Sequence[float], titles: Sequence[str], label: str, cmap: str = "viridis") -> Figure:
    """The points of a mesh beside the mesh coloured by an estimate, with one colour bar labelled above.

    Thesis: Figures 3.4, 3.6 and 3.8–3.10 (point cloud, left; triangulation and estimate, right).

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
        The points.
    simplices : array_like of int, shape (m, 3)
        The triangles.
    values : array_like, shape (nv,)
        The estimate at each vertex (NaN drawn grey).
    clim : (float, float)
        The colour range.
    titles : (str, str)
        The titles of the two panels.
    label : str
        The colour bar's label, written above it.
    cmap : str, default "viridis"
        The colour map of the estimate.

    Returns
    -------
    matplotlib.figure.Figure
        The figure (not shown, not closed).

    Raises
    ------
    ImportError
        If pyvista or matplotlib is not installed (the ``[mesh]`` and ``[plot]`` extras).
    ValueError
        If ``vertices`` is not ``(nv, 3)`` or ``titles`` does not hold two titles.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.meshes import torus_chosen_points
    >>> V, grid, uv = torus_chosen_points(step=2 * np.pi / 12)
    >>> fig = plot_estimate_on_mesh(V, grid, uv[:, 1], clim=(0, 2 * np.pi), titles=["points", "v"], label="v")
    >>> fig.axes[-1].get_title()
    'v'
    >>> plt.close(fig)
    """
    from ..meshes.plotting import mesh_figure, render_mesh

    if len(titles) != 2:
        raise ValueError(f"titles must hold two titles (points, estimate), got {list(titles)!r}")
    fig = mesh_figure([render_mesh(vertices, simplices, None, points_only=True),
                       render_mesh(vertices, simplices, values, clim=clim, cmap=cmap)],
                      titles=list(titles), clim=clim, cmap=cmap)
    fig.axes[-1].set_title(label, fontsize=10, pad=8)  # the colour bar, labelled horizontally
    return fig


def _grid_errors(errors: Mapping[tuple[str, str], npt.ArrayLike], key: tuple[str, str], n_grid: int) -> np.ndarray:
    if key not in errors:
        raise ValueError(f"errors has no entry {key!r}; it has {sorted(errors)}")
    e = np.asarray(errors[key], dtype=np.float64)
    if e.shape != (n_grid * n_grid,):
        raise ValueError(f"errors[{key!r}] must hold n_grid² = {n_grid * n_grid} values, got shape {e.shape}")
    return e


def _error_image(ax, e: np.ndarray, n_grid: int, norm):
    """The errors over (u, v) ∈ [0, 2π]² (u along x), clipped below to the colour scale's least value."""
    shown = np.clip(e, ERROR_RANGE[0], None).reshape(n_grid, n_grid).T
    return ax.imshow(shown, origin="lower", extent=(0, 2 * np.pi, 0, 2 * np.pi), aspect="auto", cmap="magma", norm=norm)


def _error_colorbar(fig: Figure, im, axes, text: str) -> Colorbar:
    """A colour bar titled ``text`` whose logarithmic ticks read as plain decimals (0.001, not 10⁻³)."""
    from matplotlib.ticker import FuncFormatter, NullFormatter

    cbar = fig.colorbar(im, ax=axes, shrink=0.85)
    cbar.ax.set_title(text, fontsize=10, pad=10, loc="left")
    cbar.ax.yaxis.set_major_formatter(FuncFormatter(lambda x, _: np.format_float_positional(float(f"{x:.12g}"),
                                                                                            trim="-")))
    cbar.ax.yaxis.set_minor_formatter(NullFormatter())
    return cbar


def plot_mean_curvature_errors(errors: Mapping[tuple[str, str], npt.ArrayLike], *, n_grid: int) -> Figure:
    """The relative error of |H| over the parameter square: Crust and fixed grid (rows), Voronoi and
    barycentric areas (columns), on one logarithmic colour scale.

    Thesis: §3.4.1, Figure 3.5 (relative error of the mean curvature, ε = π/50).

    Parameters
    ----------
    errors : mapping of (str, str) to array_like
        ``errors[triangulation, area]``: the relative errors at the n_grid × n_grid chosen points, u
        major (``GridErrors.H`` of :func:`~thesis_lib.chapters.torus_study.grid_curvature_errors`), for
        the triangulations ``"crust"`` and ``"fixed"`` and the areas ``"voronoi"`` and ``"barycentric"``.
    n_grid : int
        Chosen points per circle.

    Returns
    -------
    matplotlib.figure.Figure
        The four maps (NaN, where H = 0, white) and the colour bar.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        If an entry is missing or does not hold n_grid² values.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> e = {(t, a): np.full(16, 1e-3) for t in ("crust", "fixed") for a in ("voronoi", "barycentric")}
    >>> fig = plot_mean_curvature_errors(e, n_grid=4)
    >>> fig.axes[1].get_title()
    'Crust of the chosen points\\nbarycentric area, largest 0.001'
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the torus's curvature errors")
    from matplotlib.colors import LogNorm

    from .._validate import check_int

    n_grid = check_int(n_grid, "n_grid", minimum=1)
    cases = [[_grid_errors(errors, (name, kind), n_grid) for kind in ("voronoi", "barycentric")]
             for name in ("crust", "fixed")]
    norm = LogNorm(*ERROR_RANGE)
    fig, axes = plt.subplots(2, 2, figsize=(7.2, 5.6), sharex=True, sharey=True, layout="constrained")
    for row, name in enumerate(("crust", "fixed")):
        for col, kind in enumerate(("voronoi", "barycentric")):
            ax = axes[row, col]
            im = _error_image(ax, cases[row][col], n_grid, norm)
            ax.set_title(f"{TRIANGULATION_LABELS[name]}\n{kind} area, largest {np.nanmax(cases[row][col]):.2g}",
                         fontsize=10)
            ax.set(xlabel="u" if row else None, ylabel="v" if not col else None)
    _error_colorbar(fig, im, axes, "relative\nerror of |H|")
    return fig


def plot_gaussian_curvature_errors(errors: Mapping[tuple[str, str], npt.ArrayLike], *, n_grid: int,
                                   area: str) -> Figure:
    """The relative error of K over the parameter square, on the Crust and on the fixed grid, with one vertex area.

    Thesis: §3.4.1, Figure 3.7 (relative error of the Gaussian curvature, ε = π/50).

    Parameters
    ----------
    errors : mapping of (str, str) to array_like
        ``errors[triangulation, area]`` (``GridErrors.K`` of
        :func:`~thesis_lib.chapters.torus_study.grid_curvature_errors`), for the triangulations
        ``"crust"`` and ``"fixed"``.
    n_grid : int
        Chosen points per circle.
    area : str
        The vertex area shown.

    Returns
    -------
    matplotlib.figure.Figure
        The two maps (NaN, where K = 0, white) and the colour bar.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        If an entry is missing or does not hold n_grid² values.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> e = {(t, "voronoi"): np.full(16, 2e-3) for t in ("crust", "fixed")}
    >>> fig = plot_gaussian_curvature_errors(e, n_grid=4, area="voronoi")
    >>> fig.axes[0].get_title()
    'Crust of the chosen points, voronoi area\\nlargest 0.002'
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the torus's curvature errors")
    from matplotlib.colors import LogNorm

    from .._validate import check_int

    n_grid = check_int(n_grid, "n_grid", minimum=1)
    cases = [_grid_errors(errors, (name, area), n_grid) for name in ("crust", "fixed")]
    norm = LogNorm(*ERROR_RANGE)
    fig, axes = plt.subplots(1, 2, figsize=(7.2, 3.3), sharey=True, layout="constrained")
    for ax, name, e in zip(axes, ("crust", "fixed"), cases):
        im = _error_image(ax, e, n_grid, norm)
        ax.set_title(f"{TRIANGULATION_LABELS[name]}, {area} area\nlargest {np.nanmax(e):.2g}", fontsize=10)
        ax.set_xlabel("u")
    axes[0].set_ylabel("v")
    _error_colorbar(fig, im, axes, "relative\nerror of K")
    return fig


def plot_mean_curvature_profile(v: npt.ArrayLike, values: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0,
                                title: str = "") -> Figure:
    """The estimated |H| at samples of the torus against the angle v around the tube, over the exact |H|.

    Thesis: §3.4.1, Figure 3.11 ("red points are estimated curvatures whereas the blue surface
    represents the exact absolute values").

    Parameters
    ----------
    v : array_like, shape (k,)
        The angle v of each sample.
    values : array_like, shape (k,)
        The estimated |H| at each sample (NaN not drawn).
    R, r : float, default 10 and 5
        The torus's radii.
    title : str, default ""
        The title of the axes.

    Returns
    -------
    matplotlib.figure.Figure
        The scatter (the estimates) and the curve (the exact |H|), up to 3 times the largest |H|.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        If ``v`` and ``values`` differ in shape, or on bad radii.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_mean_curvature_profile([0.0, np.pi], [0.13, 0.0], title="two samples")
    >>> round(float(fig.axes[0].get_ylim()[1]), 4)
    0.4
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the torus's curvature profile")
    from .._validate import check_torus_radii
    from ..graphics.style import COLORS
    from ..surfaces import torus_mean_curvature

    R, r = check_torus_radii(R, r)
    v = np.asarray(v, dtype=np.float64)
    values = np.asarray(values, dtype=np.float64)
    if v.shape != values.shape:
        raise ValueError(f"v {v.shape} and values {values.shape} differ in shape")
    h_max = (R + 2 * r) / (2 * r * (R + r))  # max |H|, on the outer equator v = 0
    vs = np.linspace(0, 2 * np.pi, 400)
    fig, ax = plt.subplots(figsize=(7, 3.8))
    ax.plot(v, values, ".", ms=1.5, color=COLORS["first"], alpha=0.5, label="estimated |H| at the samples")
    ax.plot(vs, np.abs(torus_mean_curvature(0.0, vs, R=R, r=r)), color=COLORS["second"], lw=2, label="exact |H|")
    ax.set(xlabel="v (angle around the tube)", ylabel="|H|", ylim=(0, 3 * h_max), title=title)
    ax.legend(loc="upper right")
    return fig

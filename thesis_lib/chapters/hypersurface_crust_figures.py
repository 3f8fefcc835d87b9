"""The figures of the Crust in R⁴ (experiment ``hypersurface-crust``, beyond the thesis): hyperplane
slices of a reconstructed 3-manifold coloured by the estimated |H|, and the errors of |H| against
the sample count."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import check_length

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["crop_to_drawing", "plot_hyperplane_slices", "plot_crust_error_curves"]


def crop_to_drawing(images: Sequence[npt.ArrayLike], *, margin: int = 8, background: int = 250) -> list[np.ndarray]:
    """Crop rendered images to the one box that holds what is drawn in any of them, plus a margin.

    Thesis: Figures 3.4–3.14 (curvature shown on rendered triangulations; the window is mostly background).

    Parameters
    ----------
    images : sequence of array_like, shape (h, w, 3)
        RGB images of one size (e.g. from :func:`~thesis_lib.meshes.render_mesh`), on a white background.
    margin : int, default 8
        Pixels of background kept around the box.
    background : int, default 250
        A pixel is drawn when a channel is below this value.

    Returns
    -------
    list of ndarray
        The cropped images, all of one size.

    Raises
    ------
    ValueError
        If ``images`` is empty, the images differ in size or are not RGB, or nothing is drawn.

    Examples
    --------
    >>> img = np.full((20, 30, 3), 255, dtype=np.uint8)
    >>> img[5:8, 10:12] = 0
    >>> crop_to_drawing([img], margin=2)[0].shape
    (7, 6, 3)
    """
    from .._validate import check_int

    margin = check_int(margin, "margin", minimum=0)
    images = [np.asarray(img) for img in images]
    if not images or any(img.ndim != 3 or img.shape[2] != 3 or img.shape != images[0].shape for img in images):
        raise ValueError("images must be one or more RGB images (h, w, 3) of one size")
    drawn = np.any([np.any(img < background, axis=2) for img in images], axis=0)
    if not drawn.any():
        raise ValueError("nothing is drawn in the images (every pixel is background)")
    rows, cols = np.flatnonzero(drawn.any(axis=1)), np.flatnonzero(drawn.any(axis=0))
    return [img[max(rows[0] - margin, 0):rows[-1] + margin + 1, max(cols[0] - margin, 0):cols[-1] + margin + 1]
            for img in images]


def plot_hyperplane_slices(vertices: npt.ArrayLike, simplices: npt.ArrayLike, values: npt.ArrayLike, *,
                           levels: Sequence[float], clim: Sequence[float], axis: int = 3) -> Figure:
    """Slices of a 3-manifold in R⁴ by hyperplanes x_axis = level, each rendered coloured by ``values``.

    Thesis: Theorem 3.18 on the Crust in R⁴, drawn as Figures 3.8–3.10 draw the torus (beyond the thesis).

    Parameters
    ----------
    vertices : array_like, shape (nv, 4)
        The vertices.
    simplices : array_like of int, shape (m, 4)
        The tetrahedra.
    values : array_like, shape (nv,)
        A value per vertex (the estimated |H|), interpolated along the cut edges.
    levels : sequence of float
        The hyperplanes, one panel each (titled ``w = level``).
    clim : (float, float)
        The colour range.
    axis : int, default 3
        The coordinate the hyperplanes fix.

    Returns
    -------
    matplotlib.figure.Figure
        The panels side by side, cropped to the slices, with one colour bar labelled |H|.

    Raises
    ------
    ImportError
        If pyvista or matplotlib is not installed (the ``[mesh]`` and ``[plot]`` extras).
    ValueError
        If ``levels`` is empty, or on an invalid mesh (``thesis_lib.meshes.slicing.hyperplane_slice``).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.meshes import freudenthal
    >>> from thesis_lib.meshes.grids import grid_parameters
    >>> g = np.linspace(-1, 1, 4)
    >>> V = np.column_stack([grid_parameters(g, g, g), np.zeros(64)])
    >>> V[:, 3] = V[:, 2]
    >>> fig = plot_hyperplane_slices(V, freudenthal((4, 4, 4)), V[:, 0], levels=[0.1], clim=(-1, 1))
    >>> fig.axes[0].get_title()
    'w = 0.1'
    >>> plt.close(fig)
    """
    from ..meshes.plotting import mesh_figure, render_mesh
    from ..meshes.slicing import hyperplane_slice

    check_length(levels, "levels", minimum=1)
    images, titles = [], []
    for level in levels:
        P, T, V = hyperplane_slice(vertices, simplices, values, axis=axis, level=level)
        images.append(render_mesh(P, T, V, clim=clim, elevation=20))
        titles.append(f"w = {level:g}".replace("-", "−"))
    fig = mesh_figure(crop_to_drawing(images), titles=titles, clim=clim, figsize=(7.0, 2.8))
    fig.axes[-1].set_title("|H|", fontsize=9)  # the colour bar, labelled horizontally
    return fig


def _curve_rows(rows: npt.ArrayLike, name: str) -> np.ndarray:
    c = np.asarray(rows, dtype=np.float64)
    if c.ndim != 2 or c.shape[1] < 5 or len(c) == 0:
        raise ValueError(f"{name} must be the rows of a CrustErrorCurve (k, 7), got shape {c.shape}")
    return c


def plot_crust_error_curves(sphere: npt.ArrayLike, catenoid: npt.ArrayLike) -> Figure:
    """The errors of |H| on Crust reconstructions against the sample count: the 3-sphere (left) and
    the 3-catenoid with its parameter-Delaunay control (right); bars span the seeds.

    Thesis: Theorem 3.18 on the Crust in R⁴, as Figures 3.8–3.10 grow the torus's sample (beyond the thesis).

    Parameters
    ----------
    sphere, catenoid : array_like, shape (k, 7)
        The rows of the two :class:`~thesis_lib.chapters.hypersurface_study.CrustErrorCurve` (sample
        count, median, 90th percentile, control median, control 90th percentile, ...).

    Returns
    -------
    matplotlib.figure.Figure
        The two panels (logarithmic sample axis) and one legend below them.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        If either table is not (k, 7) rows.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> rows = np.array([[100, 0.1, 0.2, 0.1, 0.3, 1, 1.0], [1000, 0.05, 0.1, 0.06, 0.2, 1, 1.0]])
    >>> fig = plot_crust_error_curves(rows, rows)
    >>> [t.get_text() for t in fig.legends[0].get_texts()][:2]
    ['Crust, median', 'Crust, 90th percentile']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the Crust's error curves")
    from ..graphics.style import COLORS

    curves = {"sphere": _curve_rows(sphere, "sphere"), "catenoid": _curve_rows(catenoid, "catenoid")}
    fig, axes = plt.subplots(1, 2, figsize=(7.0, 4.2), gridspec_kw={"wspace": 0.35})
    for ax, surf, ylabel in ((axes[0], "sphere", "relative error of |H|"), (axes[1], "catenoid", "|H| cosh² v")):
        c = curves[surf]
        ns = np.unique(c[:, 0])
        for col, label, colour, mark in ((1, "median", COLORS["first"], "o"),
                                         (2, "90th percentile", COLORS["second"], "s")):
            m = np.array([c[c[:, 0] == n, col].mean() for n in ns])
            lo = np.array([c[c[:, 0] == n, col].min() for n in ns])
            hi = np.array([c[c[:, 0] == n, col].max() for n in ns])
            ax.errorbar(ns, m, yerr=[m - lo, hi - m], marker=mark, color=colour, label=f"Crust, {label}", capsize=3)
        if surf == "catenoid":
            for col, label, mark in ((3, "median", "o"), (4, "90th percentile", "s")):
                m = np.array([c[c[:, 0] == n, col].mean() for n in ns])
                ax.plot(ns, m, ls="--", marker=mark, color=COLORS["highlight"], label=f"parameter Delaunay, {label}")
        ax.set_xscale("log")
        ax.set_ylim(0.0, None)
        ax.set(xlabel="samples", ylabel=ylabel, title="3-sphere, radius 2" if surf == "sphere" else "3-catenoid")
        ax.set_xticks(ns, [f"{int(n):,}" for n in ns])
        ax.minorticks_off()
    handles, labels = axes[1].get_legend_handles_labels()
    order = sorted(range(len(labels)), key=lambda i: (not labels[i].startswith("Crust"), "median" not in labels[i]))
    fig.legend([handles[i] for i in order], [labels[i] for i in order], loc="lower center", ncol=2, fontsize=9,
               frameon=False)
    fig.subplots_adjust(bottom=0.27)
    return fig

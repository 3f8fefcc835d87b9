"""Figures of triangulated surfaces: pyvista off-screen renders shown with matplotlib colour bars."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import check_length

if TYPE_CHECKING:  # matplotlib is imported on first use
    from matplotlib.figure import Figure

__all__ = ["render_mesh", "mesh_figure"]


def render_mesh(
    vertices: npt.ArrayLike,
    simplices: npt.ArrayLike,
    scalars: npt.ArrayLike | None = None,
    *,
    clim: Sequence[float] | None = None,
    cmap: str = "viridis",
    points_only: bool = False,
    window: Sequence[int] = (640, 480),
    elevation: float = 35.0,
    azimuth: float = 30.0,
    edges: bool = False,
    nan_color: str = "#bbbbbb",
) -> np.ndarray:
    """Render a triangle mesh (or its vertices) coloured by per-vertex ``scalars``; returns an RGB image.

    Off-screen through :func:`thesis_lib.graphics.render.pyvista_offscreen`; no scalar bar (the matplotlib
    figure of :func:`mesh_figure` draws it, so every figure shares one colour-bar style).
    Thesis: Figures 3.4–3.14 (curvature shown on the triangulations).

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
        The points.
    simplices : array_like of int, shape (m, 3)
        The triangles (unused with ``points_only``; not validated).
    scalars : array_like, shape (nv,), optional
        One value per vertex to colour by (NaN drawn in ``nan_color``); None: a plain grey mesh.
    clim : (low, high), optional
        The colour range; default the range of ``scalars``.
    cmap : str, default "viridis"
        A matplotlib colour-map name.
    points_only : bool, default False
        Draw the vertices as small spheres instead of the surface.
    window : (width, height), default (640, 480)
        Size of the image in pixels.
    elevation, azimuth : float, default 35.0 and 30.0
        Camera rotation in degrees from pyvista's isometric view.
    edges : bool, default False
        Draw the triangles' edges.
    nan_color : str, default "#bbbbbb"
        Colour of the vertices whose scalar is NaN.

    Returns
    -------
    ndarray of uint8, shape (height, width, 3)
        The rendered image.

    Raises
    ------
    ImportError
        If pyvista is not installed (the ``[mesh]`` extra).
    ValueError
        If ``vertices`` is not (nv, 3).
    """
    v = np.asarray(vertices, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"vertices must be (n, 3) to render, got shape {v.shape}")
    f = np.asarray(simplices, dtype=np.int64)
    from ..graphics.render import pyvista_offscreen

    pv = pyvista_offscreen()
    plotter = pv.Plotter(off_screen=True, window_size=list(window))
    plotter.set_background("white")
    kwargs = dict(cmap=cmap, show_scalar_bar=False, nan_color=nan_color)
    if clim is not None:
        kwargs["clim"] = list(clim)
    if points_only:
        cloud = pv.PolyData(v)
        if scalars is not None:
            cloud["s"] = np.asarray(scalars, dtype=np.float64)
            plotter.add_mesh(cloud, scalars="s", point_size=4, render_points_as_spheres=True, **kwargs)
        else:
            plotter.add_mesh(cloud, color="#555555", point_size=4, render_points_as_spheres=True)
    else:
        mesh = pv.PolyData(v, np.hstack([np.full((len(f), 1), 3), f]).ravel())
        if scalars is not None:
            mesh["s"] = np.asarray(scalars, dtype=np.float64)
            plotter.add_mesh(mesh, scalars="s", show_edges=edges, smooth_shading=False, **kwargs)
        else:
            plotter.add_mesh(mesh, color="#d0d0d0", show_edges=edges)
    plotter.camera_position = "iso"
    plotter.camera.elevation = elevation
    plotter.camera.azimuth = azimuth
    plotter.reset_camera()
    img = plotter.screenshot(return_img=True)
    plotter.close()
    return np.asarray(img)


def mesh_figure(images: Iterable[npt.ArrayLike], *, titles: Sequence[str] | None = None,
                clim: Sequence[float] | None = None, cmap: str = "viridis", label: str = "",
                figsize: tuple[float, float] | None = None) -> Figure:
    """A matplotlib figure showing rendered ``images`` side by side with one shared colour bar.

    Thesis: Figures 3.4–3.14.

    Parameters
    ----------
    images : iterable of array_like
        The images (e.g. from :func:`render_mesh`), at least one, left to right.
    titles : sequence of str, optional
        One title per image.
    clim : (low, high), optional
        The colour range the images were rendered with; draws the shared colour bar (none without it).
    cmap : str, default "viridis"
        The colour map the images were rendered with.
    label : str, default ""
        Label of the colour bar.
    figsize : (width, height), optional
        Figure size in inches; default 4.2 per image plus 0.8 wide, 3.6 high.

    Returns
    -------
    matplotlib.figure.Figure
        The figure (not shown, not closed).

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        If ``images`` is empty.
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="mesh figures")
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize

    images = check_length(list(images), "images", minimum=1)
    fig, axes = plt.subplots(1, len(images), figsize=figsize or (4.2 * len(images) + 0.8, 3.6))
    axes = np.atleast_1d(axes)
    for k, (ax, img) in enumerate(zip(axes, images)):
        ax.imshow(img)
        ax.set_axis_off()
        if titles is not None:
            ax.set_title(titles[k])
    if clim is not None:
        sm = ScalarMappable(norm=Normalize(*clim), cmap=cmap)
        fig.colorbar(sm, ax=list(axes), shrink=0.8, label=label)
    return fig

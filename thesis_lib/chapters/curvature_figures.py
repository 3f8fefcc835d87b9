"""The figures of chapter 3's theory: the exact curvatures of the torus, Figure 3.1 (exterior and
interior angles, the turning of a closed curve) and Figures 3.2–3.3 (Thales' circle and a vertex's
Voronoi region)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .._optional import require
from ..graphics import style

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot_exact_torus_curvature", "plot_exterior_angles", "plot_voronoi_regions"]


def plot_exact_torus_curvature(*, R: float = 10.0, r: float = 5.0, n: int = 80) -> tuple[Figure, Figure]:
    """The exact |H| and K of the torus drawn on its n × n grid, one figure each.

    Thesis: §3.4.1 (H = −(R + 2r cos v)/(2r(R + r cos v)), K = cos v/(r(R + r cos v))).

    Parameters
    ----------
    R, r : float
        The torus's radii.
    n : int
        The grid's size (:func:`thesis_lib.meshes.torus_grid`).

    Returns
    -------
    tuple of matplotlib.figure.Figure
        The |H| and the K figure (not shown, not closed).

    Raises
    ------
    ImportError
        If pyvista or matplotlib is not installed (the ``[mesh]`` and ``[plot]`` extras).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig_h, fig_k = plot_exact_torus_curvature(n=12)
    >>> fig_h.axes[-1].get_title(), fig_k.axes[-1].get_title()
    ('|H|', 'K')
    >>> plt.close("all")
    """
    from ..meshes import torus_grid
    from ..meshes.plotting import mesh_figure, render_mesh
    from ..surfaces import torus_gaussian_curvature, torus_mean_curvature

    vertices, faces = torus_grid(n, R=R, r=r)
    v = np.tile(2 * np.pi * np.arange(n) / n, n)
    H, K = np.abs(torus_mean_curvature(0.0, v, R=R, r=r)), torus_gaussian_curvature(0.0, v, R=R, r=r)
    kk = float(np.abs(K).max())
    fig_h = mesh_figure(
        [render_mesh(vertices, faces, H, clim=(0, H.max()))],
        titles=["exact |H|"],
        clim=(0, H.max()),
        figsize=(5.5, 3.4),
    )
    fig_h.axes[-1].set_title("|H|", fontsize=10, pad=8)
    fig_k = mesh_figure(
        [render_mesh(vertices, faces, K, clim=(-kk, kk), cmap="coolwarm")],
        titles=["exact K"],
        clim=(-kk, kk),
        cmap="coolwarm",
        figsize=(5.5, 3.4),
    )
    fig_k.axes[-1].set_title("K", fontsize=10, pad=8)
    return fig_h, fig_k


def plot_exterior_angles() -> Figure:
    """Figure 3.1 drawn: a closed curve turns by 2π, and a pentagon's exterior angles δ and interior angles α.

    Thesis: Figure 3.1, eq. (3.7) and Example 3.6.

    Returns
    -------
    matplotlib.figure.Figure
        The figure (not shown, not closed).

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_exterior_angles()
    >>> [ax.get_title() for ax in fig.axes]
    ['a closed curve turns by 2π', 'Σδ = 360°,  Σα = (n − 2)·180°']
    >>> plt.close(fig)
    """
    from ..curvature.checks import exterior_angles
    from .curvature_sections import flower_curve

    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing Figure 3.1")
    curve = flower_curve()
    turning = exterior_angles(curve).sum()
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7, 3.4), layout="constrained")
    ax0.plot(*np.vstack([curve, curve[:1]]).T, color=style.COLORS["second"])
    ax0.set_aspect("equal")
    ax0.set_axis_off()
    ax0.set_title(f"a closed curve turns by {turning / np.pi:.0f}π", fontsize=10)
    poly = np.array([[0.0, 0.0], [2.0, -0.3], [2.6, 1.2], [1.2, 2.0], [-0.2, 1.3]])
    ax1.fill(*poly.T, color="0.92")
    ax1.plot(*np.vstack([poly, poly[:1]]).T, color=style.COLORS["second"])
    delta = exterior_angles(poly)
    for i in range(len(poly)):
        a = poly[i]
        ext = a + 0.45 * (a - poly[i - 1]) / np.linalg.norm(a - poly[i - 1])
        ax1.plot(*np.array([a, ext]).T, ls=":", color="0.4")
        ax1.annotate(
            f"δ={np.degrees(delta[i]):.0f}°",
            ext,
            fontsize=9,
            color=style.COLORS["first"],
            ha="center",
            va="center",
            xytext=(0, 8),
            textcoords="offset points",
        )
        inward = (poly.mean(axis=0) - a) / np.linalg.norm(poly.mean(axis=0) - a)
        ax1.annotate(f"α={180 - np.degrees(delta[i]):.0f}°", a + 0.4 * inward, fontsize=9, ha="center", va="center")
    ax1.set_aspect("equal")
    ax1.set_axis_off()
    ax1.set_title(f"Σδ = {np.degrees(delta.sum()):.0f}°,  Σα = (n − 2)·180°", fontsize=10)
    return fig


def plot_voronoi_regions() -> Figure:
    """Figures 3.2 and 3.3 drawn: points inside the circle on pq₁ see it at an obtuse angle; a vertex's Voronoi region.

    Thesis: Figures 3.2 and 3.3 (§3.3.2).

    Left, 500 of the 4000 uniform points of :func:`thesis_lib.chapters.curvature_sections.chapter_of_voronoi_section`
    (seed 2), red where the angle at the point is obtuse; right, a vertex's one-ring of seven triangles
    and the part of each nearest to the vertex.

    Returns
    -------
    matplotlib.figure.Figure
        The figure (not shown, not closed).

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_voronoi_regions()
    >>> fig.axes[1].get_title()
    'Voronoi region of x (green)'
    >>> plt.close(fig)
    """
    from ..curvature.checks import thales_obtuse

    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing Figures 3.2 and 3.3")
    p_, q_ = np.array([-1.0, 0.0]), np.array([1.0, 0.0])
    cloud2 = np.random.default_rng(2).uniform(-1.6, 1.6, (4000, 2))
    obtuse_at_x = thales_obtuse(cloud2, p_, q_)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7, 3.3), layout="constrained")
    circle = np.linspace(0, 2 * np.pi, 200)
    ax0.plot(np.cos(circle), np.sin(circle), color="0.5", lw=0.8)
    ax0.scatter(*cloud2[::8].T, s=4, c=np.where(obtuse_at_x[::8], style.COLORS["first"], style.COLORS["second"]))
    ax0.plot(*np.array([p_, q_]).T, "ko-")
    ax0.annotate("p", p_, xytext=(-12, -4), textcoords="offset points")
    ax0.annotate("q₁", q_, xytext=(5, -4), textcoords="offset points")
    ax0.set_aspect("equal")
    ax0.set_axis_off()
    ax0.set_title("red: obtuse angle at the point", fontsize=10)
    ring_angles = 2 * np.pi * np.arange(7) / 7 + np.random.default_rng(4).uniform(-0.15, 0.15, 7)
    ring = np.column_stack([np.cos(ring_angles), np.sin(ring_angles)]) * np.random.default_rng(5).uniform(
        0.92, 1.08, (7, 1)
    )
    centre = np.zeros(2)
    for k in range(7):
        a, b = ring[k], ring[(k + 1) % 7]
        ax1.fill(*np.array([centre, a, b]).T, color="0.93", ec="0.5", lw=0.8)
        # the part nearest to the centre: bounded by the bisectors of its two edges, which meet at the
        # circumcentre (inside the triangle, as none of these triangles is obtuse)
        circ = np.linalg.solve(2 * np.array([a, b]), [a @ a, b @ b])
        ax1.fill(*np.array([centre, a / 2, circ, b / 2]).T, color=style.COLORS["highlight"], alpha=0.35, lw=0)
    ax1.plot(*centre, "ko")
    ax1.annotate("x", centre, xytext=(4, 4), textcoords="offset points")
    ax1.set_aspect("equal")
    ax1.set_axis_off()
    ax1.set_title("Voronoi region of x (green)", fontsize=10)
    return fig

"""The figures of §2.1–2.2: planar complexes drawn over their points (Figures 2.1, 2.2–2.3, 2.4,
2.5–2.6), alpha and witness complexes of a noisy circle, and the oriented triangulation of RP²
(Figure 2.7)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import as_points, check_real

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..homology.filtration import Filtration

__all__ = [
    "NOT_A_COMPLEX",
    "draw_complex",
    "plot_simplices",
    "plot_complex_examples",
    "plot_cech_rips",
    "plot_voronoi_delaunay",
    "plot_alpha_complexes",
    "plot_witness_complex",
    "plot_rp2_orientation",
]

#: the points of Figure 2.2 (b), the upper triangle 0, 1, 2 and the lower one 3, 4, 5, whose top
#: edge 3–4 lies inside the edge 0–1 of the upper one
NOT_A_COMPLEX = np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 1.2], [0.6, 0.0], [1.4, 0.0], [1.0, -1.0]])


def _planar(points: npt.ArrayLike) -> np.ndarray:
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points must be planar, of shape (n, 2), got {pts.shape}")
    return pts


def draw_complex(ax: Axes, points: npt.ArrayLike, simplices: Iterable[Sequence[int]], *, color: str | None = None,
                 alpha_fill: float = 0.25, vertex_size: float = 18) -> None:
    """Draw the vertices, edges and triangles of a planar complex on an axes (equal aspect, no frame).

    Thesis: Definition 2.3 (a simplicial complex), drawn as in Figures 2.1–2.6.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    points : array_like, shape (n, 2)
        The vertex positions.
    simplices : iterable of sequence of int
        The simplices; triangles are filled, edges drawn as segments, vertices and higher simplices
        add nothing beyond the points.
    color : str, optional
        The colour of edges and triangles; default the style's ``"second"`` colour.
    alpha_fill : float, default 0.25
        The opacity of the triangles.
    vertex_size : float, default 18
        The marker size of the points.

    Raises
    ------
    ValueError
        Points not of shape (n, 2).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> draw_complex(ax, [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], [(0, 1, 2), (0, 1)])
    >>> len(ax.patches), len(ax.lines)
    (1, 1)
    >>> plt.close(fig)
    """
    require("matplotlib.pyplot", extra="plot", purpose="drawing complexes")
    from matplotlib.patches import Polygon

    from ..graphics.style import COLORS

    pts = _planar(points)
    color = COLORS["second"] if color is None else color
    for s in simplices:
        if len(s) == 3:
            ax.add_patch(Polygon(pts[list(s)], closed=True, fc=color, ec="none", alpha=alpha_fill))
        elif len(s) == 2:
            ax.plot(*pts[list(s)].T, color=color, lw=1.2)
    ax.scatter(*pts.T, s=vertex_size, color="black", zorder=3)
    ax.set_aspect("equal")
    ax.axis("off")


def plot_simplices() -> Figure:
    """Figure 2.1: a p-simplex for p = 0, 1, 2, 3 (the tetrahedron's hidden edge dashed).

    Thesis: Definition 2.1 and Figure 2.1.

    Returns
    -------
    matplotlib.figure.Figure
        Four panels titled ``0-simplex`` to ``3-simplex``.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_simplices()
    >>> [ax.get_title() for ax in fig.axes]
    ['0-simplex', '1-simplex', '2-simplex', '3-simplex']
    >>> plt.close(fig)
    """
    import itertools

    from ..graphics.style import COLORS

    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing simplices")
    fig, axes = plt.subplots(1, 4, figsize=(7, 2.0))
    shapes = [np.array([[0.0, 0.0]]), np.array([[0.0, 0.0], [1.0, 0.3]]),
              np.array([[0.0, 0.0], [1.0, 0.0], [0.4, 0.8]]),
              np.array([[0.0, 0.0], [1.0, -0.1], [0.45, 0.85], [0.6, 0.3]])]
    for p, (ax, v) in enumerate(zip(axes, shapes)):
        draw_complex(ax, v, [s for k in range(1, min(p + 1, 3) + 1) for s in itertools.combinations(range(p + 1), k)])
        if p == 3:
            ax.plot(*v[[0, 3]].T, ls="--", color=COLORS["second"], lw=1)
        ax.set_title(f"{p}-simplex")
        ax.set_xlim(-0.2, 1.2)
        ax.set_ylim(-0.3, 1.0)
    return fig


def plot_complex_examples(glued: Sequence[Sequence[int]], circle: Sequence[Sequence[int]]) -> Figure:
    """Figures 2.2 and 2.3: (a) a glued complex, (b) two triangles that are not a complex, and a
    triangulated circle.

    Thesis: Definition 2.3, Figures 2.2 and 2.3 (drawn from their captions).

    Parameters
    ----------
    glued : sequence of sequence of int
        The facets of panel (a), on the six vertices of its drawing (vertices 0–5); their faces up
        to dimension 2 are drawn.
    circle : sequence of sequence of int
        The edges of the triangulated circle, on vertices 0, 1, 2.

    Returns
    -------
    matplotlib.figure.Figure
        Three panels; (b) draws :data:`NOT_A_COMPLEX` with the shared segment highlighted.

    Raises
    ------
    ValueError
        A vertex of ``glued`` beyond 5 or of ``circle`` beyond 2.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_complex_examples([(0, 1, 2, 3), (3, 4), (1, 2, 5)], [(0, 1), (1, 2), (0, 2)])
    >>> [ax.get_title() for ax in fig.axes]
    ['(a) a simplicial complex', '(b) not a complex', 'a triangulated circle']
    >>> plt.close(fig)
    """
    from matplotlib.patches import Circle

    from ..graphics.style import COLORS
    from ..homology.simplicial import closure

    if any(not 0 <= int(v) <= 5 for s in glued for v in s) or any(not 0 <= int(v) <= 2 for s in circle for v in s):
        raise ValueError("glued takes vertices 0-5 and circle vertices 0-2 (the vertices of the drawing)")
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing complexes")
    fig, axes = plt.subplots(1, 3, figsize=(7, 2.4))
    v = np.array([[0.0, 0.0], [1.2, -0.2], [0.6, 1.0], [0.8, 0.35], [1.8, 0.6], [1.4, 1.3]])
    draw_complex(axes[0], v, [tuple(r) for a in closure([tuple(s) for s in glued])[:3] for r in a])
    axes[0].set_title("(a) a simplicial complex")
    two = NOT_A_COMPLEX
    draw_complex(axes[1], two, [(0, 1, 2), (0, 1), (1, 2), (0, 2)], color=COLORS["first"])
    draw_complex(axes[1], two, [(3, 4, 5), (3, 4), (4, 5), (3, 5)], color=COLORS["second"])
    axes[1].plot(*two[[3, 4]].T, color=COLORS["highlight"], lw=3)
    axes[1].set_title("(b) not a complex")
    t = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 0.87]])
    draw_complex(axes[2], t, circle)
    axes[2].add_patch(Circle((0.5, 0.29), 0.58, fill=False, ls=":", color=COLORS["points"]))
    axes[2].set_title("a triangulated circle")
    return fig


def plot_cech_rips(points: npt.ArrayLike, cech_simplices: Iterable[Sequence[int]],
                   rips_simplices: Iterable[Sequence[int]], *, max_radius: float,
                   xlim: tuple[float, float] = (-0.7, 3.1), ylim: tuple[float, float] = (-0.7, 1.6)) -> Figure:
    """Figure 2.4: the balls B(x, ε) with the Čech complex (left) and the Vietoris–Rips complex (right).

    Thesis: Definitions 2.9 and 2.11, Figure 2.4.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The centres.
    cech_simplices, rips_simplices : iterable of sequence of int
        The two complexes at ε.
    max_radius : float
        The radius ε (> 0) of the balls and the complexes.
    xlim, ylim : (float, float), default (-0.7, 3.1) and (-0.7, 1.6)
        The range shown in both panels (the defaults fit the points of Figure 2.4).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels titled with the complex and ε.

    Raises
    ------
    ValueError
        Points not planar or ε not positive.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_cech_rips([[0.0, 0.0], [1.0, 0.0]], [(0, 1)], [(0, 1)], max_radius=0.6)
    >>> [ax.get_title() for ax in fig.axes]
    ['Čech complex, ε = 0.6', 'Vietoris–Rips complex, ε = 0.6']
    >>> plt.close(fig)
    """
    from matplotlib.patches import Circle

    from ..graphics.style import COLORS

    pts = _planar(points)
    eps = check_real(max_radius, "max_radius", positive=True)
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing complexes")
    fig, axes = plt.subplots(1, 2, figsize=(7, 2.6))
    for ax, cx, title, color in [(axes[0], cech_simplices, "Čech complex", COLORS["first"]),
                                 (axes[1], rips_simplices, "Vietoris–Rips complex", COLORS["second"])]:
        for p in pts:
            ax.add_patch(Circle(p, eps, color=COLORS["points"], alpha=0.18))
        draw_complex(ax, pts, cx, color=color)
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_title(f"{title}, ε = {eps}")
    return fig


def plot_voronoi_delaunay(points: npt.ArrayLike, simplices: Iterable[Sequence[int]]) -> Figure:
    """Figures 2.5 and 2.6: the Voronoi diagram (left) and the Delaunay triangulation over it (right).

    Thesis: Definition 2.13, Figures 2.5 and 2.6.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The sites, in the unit square (the panels show [−0.1, 1.1]²); at least 4, not all on a line.
    simplices : iterable of sequence of int
        The Delaunay complex of the points.

    Returns
    -------
    matplotlib.figure.Figure
        Two panels.

    Raises
    ------
    ValueError
        Points not planar.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.complexes import delaunay
    >>> pts = [[0.1, 0.1], [0.9, 0.2], [0.5, 0.9], [0.4, 0.4]]
    >>> fig = plot_voronoi_delaunay(pts, delaunay(pts))
    >>> [ax.get_title() for ax in fig.axes]
    ['Voronoi diagram', 'with the Delaunay triangulation']
    >>> plt.close(fig)
    """
    from scipy.spatial import Voronoi, voronoi_plot_2d

    from ..graphics.style import COLORS

    pts = _planar(points)
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing Voronoi diagrams")
    fig, axes = plt.subplots(1, 2, figsize=(7, 3.4))
    for ax in axes:
        voronoi_plot_2d(Voronoi(pts), ax=ax, show_vertices=False, line_colors=COLORS["points"], point_size=0)
        ax.set_xlim(-0.1, 1.1)
        ax.set_ylim(-0.1, 1.1)
    axes[0].scatter(*pts.T, s=18, color="black", zorder=3)
    axes[0].set_aspect("equal")
    axes[0].set_title("Voronoi diagram")
    draw_complex(axes[1], pts, simplices, alpha_fill=0.1)
    axes[1].set_title("with the Delaunay triangulation")
    return fig


def plot_alpha_complexes(points: npt.ArrayLike, filtration: Filtration, radii: Sequence[float], *,
                         limit: float = 1.8) -> Figure:
    """Alpha complexes at several radii over the union of the balls, titled with their Betti numbers over Z/2.

    Thesis: Definition 2.14 and Theorem 2.15 (the alpha complex has the homotopy type of the union).

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The points.
    filtration : Filtration
        Their alpha filtration (values ε², as :func:`~thesis_lib.complexes.alpha` returns them).
    radii : sequence of float
        The radii ε, one panel each (each > 0).
    limit : float, default 1.8
        Every panel shows [−limit, limit]².

    Returns
    -------
    matplotlib.figure.Figure
        One panel per radius, titled ``ε = …: β₀ = …, β₁ = …``.

    Raises
    ------
    ValueError
        Points not planar, or no radius, or a radius not positive.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.complexes import alpha
    >>> pts = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]
    >>> fig = plot_alpha_complexes(pts, alpha(pts), [0.5, 0.8])
    >>> [ax.get_title() for ax in fig.axes]
    ['ε = 0.5: β₀ = 4, β₁ = 0', 'ε = 0.8: β₀ = 1, β₁ = 1']
    >>> plt.close(fig)
    """
    from matplotlib.patches import Circle

    from ..graphics.style import COLORS
    from ..homology import betti_numbers

    pts = _planar(points)
    eps = [float(r) for r in radii]
    if not eps or not all(np.isfinite(r) and r > 0 for r in eps):
        raise ValueError(f"radii must be one or more positive numbers, got {list(radii)!r}")
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing alpha complexes")
    fig, axes = plt.subplots(1, len(eps), figsize=(7, 2.6), squeeze=False)
    for ax, eps_a in zip(axes[0], radii):
        sub = filtration.threshold(eps_a**2)
        for p in pts:
            ax.add_patch(Circle(p, eps_a, color=COLORS["points"], alpha=0.12))
        draw_complex(ax, pts, [s for s, _ in sub], vertex_size=6)
        b_title = betti_numbers([s for s, _ in sub], coefficients=2) + [0]
        ax.set_title(f"ε = {eps_a}: β₀ = {b_title[0]}, β₁ = {b_title[1]}", fontsize=10)
        ax.set_xlim(-limit, limit)
        ax.set_ylim(-limit, limit)
    return fig


def plot_witness_complex(points: npt.ArrayLike, landmarks: Sequence[int], simplices: Iterable[Sequence[int]], *,
                         max_radius: float) -> Figure:
    """A witness complex drawn on its landmarks over the whole point cloud.

    Thesis: Definition 2.16 (the witness complex W(X, L, ε)).

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The cloud X.
    landmarks : sequence of int
        The indices of the landmarks L in ``points``; the simplices' vertices index this list.
    simplices : iterable of sequence of int
        The witness complex.
    max_radius : float
        The ε of the complex (shown in the title).

    Returns
    -------
    matplotlib.figure.Figure
        One panel titled ``<number> maxmin landmarks, ε = …``.

    Raises
    ------
    ValueError
        Points not planar.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_witness_complex([[0.0, 0.0], [1.0, 0.0], [0.5, 0.5]], [0, 1], [(0, 1)], max_radius=0.1)
    >>> fig.axes[0].get_title()
    '2 maxmin landmarks, ε = 0.1'
    >>> plt.close(fig)
    """
    from ..graphics.style import COLORS

    pts = _planar(points)
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing witness complexes")
    fig, ax = plt.subplots(figsize=(3.6, 3.6))
    ax.scatter(*pts.T, s=3, color=COLORS["points"])
    draw_complex(ax, pts[np.asarray(landmarks)], simplices, color=COLORS["first"])
    ax.set_title(f"{len(landmarks)} maxmin landmarks, ε = {max_radius}")
    return fig


def plot_rp2_orientation(triangles: Sequence[Sequence[int]], chart: Mapping[tuple[int, ...], Sequence],
                         labels: Sequence[str]) -> Figure:
    """Figure 2.7: the disc picture of RP², each oriented triangle with an arrow from its first to its
    second vertex, the vertices named.

    Thesis: Example 2.21 and Figure 2.7 (the induced clockwise orientation).

    Parameters
    ----------
    triangles : sequence of sequence of int
        The oriented triangles (vertex order = orientation), as ``datasets.rp2(oriented=True)``.
    chart : mapping of tuple to sequence of (float, float)
        For each triangle (sorted vertices), its corners' plane positions in sorted vertex order, as
        :func:`~thesis_lib.morse.rp2_chart` returns them.
    labels : sequence of str
        The name of each vertex.

    Returns
    -------
    matplotlib.figure.Figure
        One panel in [−1.15, 1.15]².

    Raises
    ------
    ValueError
        A triangle missing from the chart.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.datasets import RP2_LABELS, rp2
    >>> from thesis_lib.morse import rp2_chart
    >>> fig = plot_rp2_orientation(rp2(oriented=True), rp2_chart(), RP2_LABELS)
    >>> len(fig.axes[0].patches), len(fig.axes[0].texts)
    (10, 19)
    >>> plt.close(fig)
    """
    from matplotlib.patches import Polygon

    from ..graphics.style import COLORS

    missing = [tuple(t) for t in triangles if tuple(sorted(t)) not in chart]
    if missing:
        raise ValueError(f"triangles missing from the chart: {missing}")
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing RP²")
    fig, ax = plt.subplots(figsize=(3.8, 3.8))
    for tri in triangles:
        corners = dict(zip(sorted(tri), chart[tuple(sorted(tri))]))
        a, b, c = (np.array(corners[v]) for v in tri)
        ax.add_patch(Polygon([a, b, c], closed=True, fc=COLORS["second"], ec="black", alpha=0.25, lw=1))
        centre = (a + b + c) / 3
        ax.annotate("", xy=centre + 0.6 * (b - centre), xytext=centre + 0.6 * (a - centre),
                    arrowprops={"arrowstyle": "->", "color": COLORS["first"], "lw": 1})
    drawn = {(labels[v], xy) for tri in triangles for v, xy in zip(sorted(tri), chart[tuple(sorted(tri))])}
    for name, (x, y) in sorted(drawn):
        ax.text(x, y, name, ha="center", va="center", fontsize=10, zorder=4,
                bbox={"boxstyle": "circle,pad=0.25", "fc": "white", "ec": "0.3"})
    ax.set_xlim(-1.15, 1.15)
    ax.set_ylim(-1.15, 1.15)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig

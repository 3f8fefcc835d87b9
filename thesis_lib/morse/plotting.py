"""Drawings of chapter 4: the torus's height (Figure 4.1), gradient fields as arrows (Figures 4.4, 4.6) and
modified Hasse diagrams (4.7–4.8)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from ._cells import ComplexLike, Pairs, cell_complex, partner_array
from .smooth import torus_height

if TYPE_CHECKING:  # matplotlib is imported only by whoever draws
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["draw_gradient_field", "draw_hasse_diagram", "hasse_figure", "spectral_layout", "torus_height_figure"]


def spectral_layout(simplices: ComplexLike) -> dict[int, tuple[float, float]]:
    """Plane positions of the vertices from two Laplacian eigenvectors of the 1-skeleton.

    Thesis: none (a drawing aid for Figures 4.4/4.6 when a complex has no natural picture).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        The complex; only its 1-skeleton (the graph) matters.

    Returns
    -------
    dict of int to (float, float)
        Vertex label → (x, y): the eigenvectors of the second and third smallest eigenvalues of
        the graph Laplacian (signs fixed so that each coordinate's entry of largest magnitude is
        positive); for fewer than three vertices, their order along the x-axis.

    Examples
    --------
    The square's cycle graph 0-1-2-3 is laid out with its four vertices on a circle:

    >>> import numpy as np
    >>> layout = spectral_layout([(0, 1), (1, 2), (2, 3), (0, 3)])
    >>> sorted(layout), {round(float(np.hypot(*p)), 6) for p in layout.values()}
    ([0, 1, 2, 3], {0.707107})
    """
    cx = cell_complex(simplices)
    verts = cx.arrays[0][:, 0]
    n = verts.size
    lap = np.zeros((n, n))
    if cx.dimension >= 1:
        idx = cx.facet_ids[1]  # global ids of the two vertices = local ids
        for a, b in idx:
            lap[a, b] = lap[b, a] = -1
    lap -= np.diag(lap.sum(axis=1))
    w, v = np.linalg.eigh(lap + 1e-9 * np.eye(n))
    xy = v[:, 1:3] if n >= 3 else np.column_stack([np.arange(n), np.zeros(n)])
    xy = xy * np.sign(xy[np.argmax(np.abs(xy), axis=0), [0, 1]]) if n >= 3 else xy
    return {int(u): (float(x), float(y)) for u, (x, y) in zip(verts, xy)}


def draw_gradient_field(
    ax: Axes,
    simplices: ComplexLike,
    pairs: Pairs,
    *,
    positions: Mapping[int, Sequence[float]] | None = None,
    chart: Mapping[tuple[int, ...], Sequence[Sequence[float]]] | None = None,
    labels: Mapping[int, str] | None = None,
) -> Axes:
    """Draw a 2-dimensional complex with its vector field: an arrow σ → τ for each pair, critical
    simplices in red (vertices as dots, edges thick, triangles shaded).

    Thesis: Figures 4.4 and 4.6 (arrows from σ to τ when f(τ) ≤ f(σ), Definition 4.30).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    simplices : Filtration or iterable of simplices
        A complex of dimension at most 2 (all faces are added).
    pairs : iterable of (sigma, tau)
        The discrete vector field, sigma a facet of tau.
    positions : mapping of int to (float, float), optional
        Vertex → (x, y); default :func:`spectral_layout`.  Ignored when ``chart`` is given.
    chart : mapping of tuple to sequence of (float, float), optional
        Triangle → positions of its corners, for complexes such as RP² drawn with identified
        boundary (see :func:`~thesis_lib.morse.examples.rp2_chart`); only the charted triangles
        and their faces are drawn.
    labels : mapping of int to str, optional
        Vertex names written beside the vertices (a vertex not in it is written as its number);
        no names when None.

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``, equal aspect and axes off.

    Raises
    ------
    ValueError
        A complex of dimension > 2, or an invalid vector field.

    Examples
    --------
    The triangle with a gradient field that leaves only the vertex 0 critical: one arrow per pair.

    >>> import matplotlib.pyplot as plt
    >>> from matplotlib.text import Annotation
    >>> pairs = [((1,), (0, 1)), ((2,), (0, 2)), ((1, 2), (0, 1, 2))]
    >>> fig, ax = plt.subplots()
    >>> ax = draw_gradient_field(ax, [(0, 1, 2)], pairs, positions={0: (0, 0), 1: (1, 0), 2: (0.5, 0.8)})
    >>> sum(isinstance(t, Annotation) for t in ax.texts)
    3
    >>> plt.close(fig)
    """
    cx = cell_complex(simplices)
    if cx.dimension > 2:
        raise ValueError("only complexes of dimension ≤ 2 can be drawn")
    partner = partner_array(cx, pairs)
    crit = set(int(g) for g in np.flatnonzero(partner < 0))
    # pieces: every drawn copy of a simplex with its corner coordinates
    copies: dict[tuple[int, ...], list[np.ndarray]] = {}

    def add(s, pts):
        lst = copies.setdefault(s, [])
        if not any(np.allclose(pts, q) for q in lst):
            lst.append(np.asarray(pts, dtype=float))

    if chart is not None:
        for t, corners in chart.items():
            t = tuple(t)
            corners = np.asarray(corners, dtype=float)
            add(t, corners)
            for i in range(3):
                for j in range(i + 1, 3):
                    add((t[i], t[j]), corners[[i, j]])
                add((t[i],), corners[[i]])
    else:
        pos = positions if positions is not None else spectral_layout(cx)
        for s in cx.simplices():
            add(s, np.array([pos[v] for v in s]))
    ids = {s: g for g, s in enumerate(cx.simplices())}
    for s, lst in copies.items():
        g = ids[s]
        for pts in lst:
            if len(s) == 3:
                ax.fill(pts[:, 0], pts[:, 1], color="#f4a3a3" if g in crit else "#dde6f2", lw=0, zorder=0)
            elif len(s) == 2:
                ax.plot(pts[:, 0], pts[:, 1], color="crimson" if g in crit else "0.35",
                        lw=3 if g in crit else 1, zorder=1)
            else:
                ax.plot(pts[0, 0], pts[0, 1], "o", color="crimson" if g in crit else "0.2",
                        ms=8 if g in crit else 4, zorder=3)
                if labels is not None:
                    ax.annotate(labels.get(s[0], str(s[0])), pts[0], textcoords="offset points", xytext=(4, 4))
    for low, high in zip(np.flatnonzero(partner > np.arange(cx.n)), partner[partner > np.arange(cx.n)]):
        s, t = cx.simplex(int(low)), cx.simplex(int(high))
        for tp in copies.get(t, []):
            centre_t = tp.mean(axis=0)
            # the copy of s that is a face of this copy of t
            for sp_ in copies.get(s, []):
                if all(any(np.allclose(p, q) for q in tp) for p in sp_):
                    c_s = sp_.mean(axis=0)
                    ax.annotate("", xy=c_s + 0.75 * (centre_t - c_s), xytext=c_s,
                                arrowprops=dict(arrowstyle="-|>", color="black", lw=1.2), zorder=4)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return ax


def draw_hasse_diagram(ax: Axes, simplices: ComplexLike, pairs: Pairs = (),
                       *, names: Mapping[tuple[int, ...], str] | None = None) -> Axes:
    """The (modified) Hasse diagram: one row per dimension, an edge τ → σ for each facet, reversed
    (red, upwards) for the pairs of the vector field; critical simplices boxed in red (only when
    a field is given).

    Thesis: §4.2.6, Figures 4.7–4.8 and Theorem 4.44.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    simplices : Filtration or iterable of simplices
        A small complex (all faces are added): every simplex is a labelled box.
    pairs : iterable of (sigma, tau), default ()
        The discrete vector field; empty draws the plain Hasse diagram.
    names : mapping of tuple to str, optional
        Simplex (ascending vertices) → label; default the concatenated vertex numbers.

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``, axes off.

    Raises
    ------
    ValueError
        The pairs are not a discrete vector field on the complex.

    Examples
    --------
    The triangle's Hasse diagram: its seven simplices and nine face relations (arrows).

    >>> import matplotlib.pyplot as plt
    >>> from matplotlib.text import Annotation
    >>> fig, ax = plt.subplots()
    >>> ax = draw_hasse_diagram(ax, [(0, 1, 2)], [((1,), (0, 1)), ((2,), (0, 2)), ((1, 2), (0, 1, 2))])
    >>> sorted(t.get_text() for t in ax.texts if t.get_text())
    ['0', '01', '012', '02', '1', '12', '2']
    >>> sum(isinstance(t, Annotation) for t in ax.texts)
    9
    >>> plt.close(fig)
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    pos = {}
    for d in range(cx.dimension + 1):
        m = int(cx.counts[d])
        xs = np.linspace(-(m - 1) / 2, (m - 1) / 2, m) if m > 1 else np.zeros(1)
        for k in range(m):
            pos[int(cx.offsets[d] + k)] = (float(xs[k]), float(d))
    coo = cx.D.tocoo()
    for face, cell in zip(coo.row.tolist(), coo.col.tolist()):
        flip = partner[face] == cell
        src, dst = (face, cell) if flip else (cell, face)
        ax.annotate("", xy=pos[dst], xytext=pos[src],
                    arrowprops=dict(arrowstyle="-|>", color="crimson" if flip else "0.5", lw=1.8 if flip else 0.8,
                                    shrinkA=9, shrinkB=9), zorder=1)
    for g, (x, y) in pos.items():
        s = cx.simplex(g)
        text = names.get(s) if names and s in names else "".join(str(v) for v in s)
        critical = bool(partner[g] < 0) and bool((partner >= 0).any())
        ax.text(x, y, text, ha="center", va="center", zorder=2,
                bbox=dict(boxstyle="round", fc="white", ec="crimson" if critical else "0.6", lw=2 if critical else 1))
    ax.set_xlim(min(p[0] for p in pos.values()) - 0.7, max(p[0] for p in pos.values()) + 0.7)
    ax.set_ylim(-0.5, cx.dimension + 0.5)
    ax.set_axis_off()
    return ax


def hasse_figure(simplices: ComplexLike, pairs: Pairs) -> Figure:
    """The Hasse diagram of a complex beside the modified diagram of a vector field on it.

    Thesis: §4.2.6, Figures 4.7–4.8 (the diagram, then its paired edges reversed).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        A small complex (all faces are added).
    pairs : iterable of (sigma, tau)
        The discrete vector field of the right panel.

    Returns
    -------
    matplotlib.figure.Figure
        Two panels, "Hasse diagram" and "modified" (:func:`draw_hasse_diagram`).

    Raises
    ------
    ValueError
        The pairs are not a discrete vector field on the complex.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = hasse_figure([(0, 1, 2)], [((1,), (0, 1))])
    >>> [ax.get_title() for ax in fig.axes]
    ['Hasse diagram', 'modified']
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt

    partner_array(cell_complex(simplices), pairs)  # a bad field fails before a figure is made
    fig, axs = plt.subplots(1, 2, figsize=(7, 3.2))
    draw_hasse_diagram(axs[0], simplices)
    draw_hasse_diagram(axs[1], simplices, pairs)
    axs[0].set_title("Hasse diagram")
    axs[1].set_title("modified")
    return fig


def torus_height_figure(critical: Sequence[Mapping], *, names: Sequence[str], R: float = 2.0,
                        r: float = 1.0) -> Figure:
    """The height of the upright torus over its parameter square, with its critical points and indices.

    Thesis: Example 4.2 and Figure 4.1 (the height function h(u, v) = cos u (R + r cos v)).

    Parameters
    ----------
    critical : sequence of mapping
        The critical points (``u``, ``v``, ``index``), :func:`~thesis_lib.morse.torus_critical_points`.
    names : sequence of str
        A label per critical point.
    R, r : float, default 2.0 and 1.0
        The torus's radii.

    Returns
    -------
    matplotlib.figure.Figure
        Filled contours of h on a 200 × 200 grid with a colour bar, each critical point marked and
        labelled "name (index k)".

    Raises
    ------
    ValueError
        If ``names`` has not one label per critical point.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.morse import torus_critical_points
    >>> fig = torus_height_figure(torus_critical_points(), names=["r", "q1", "q2", "p"])
    >>> [t.get_text() for t in fig.axes[0].texts]
    ['r (index 0)', 'q1 (index 1)', 'q2 (index 1)', 'p (index 2)']
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt

    if len(names) != len(critical):
        raise ValueError(f"names: one per critical point ({len(critical)}), got {len(names)}")
    uu, vv = np.meshgrid(np.linspace(0, 2 * np.pi, 200), np.linspace(0, 2 * np.pi, 200))
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    cs = ax.contourf(uu, vv, torus_height(uu, vv, R=R, r=r), levels=20, cmap="viridis")
    cbar = fig.colorbar(cs, ax=ax)
    cbar.ax.set_title("$h$", fontsize=11)
    for c, name in zip(critical, names):
        ax.plot(c["u"], c["v"], "o", color="crimson")
        ax.annotate(f"{name} (index {c['index']})", (c["u"], c["v"]), xytext=(5, 5), textcoords="offset points",
                    color="white", fontsize=10)
    ax.set_xlabel("$u$")
    ax.set_ylabel("$v$")
    return fig

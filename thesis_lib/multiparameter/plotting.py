"""Figures of two-parameter persistence: Hilbert-function heat maps, and fibered barcodes drawn on
their lines in the (ε, κ) plane."""

from __future__ import annotations

import numpy as np

from .bifiltration import Bifiltration
from .invariants import check_grid, fibered_barcode

__all__ = ["plot_hilbert", "line_fan", "plot_fibered_barcodes"]


def plot_hilbert(ax, values, eps, kappa, *, label: str = "", vmax: int | None = None, cmap: str = "viridis",
                 xlabel: str = "ε", ylabel: str = "κ", colorbar: bool = True):
    """Heat map of one Hilbert function ``values[i, j]`` = dim H_k(K_{ε_i, κ_j}) on the grid.

    Each grid value is drawn as the cell up to the next one (K_{ε,κ} is constant there when the grid
    holds every grade).  The colour bar is discrete, labelled horizontally.
    Thesis: Chapter 5 (the homology for each pair (ε, κ)).
    """
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm

    eps, kappa = check_grid(eps, "eps"), check_grid(kappa, "kappa")
    v = np.asarray(values)
    if v.shape != (eps.size, kappa.size):
        raise ValueError(f"values must have shape {(eps.size, kappa.size)}, got {v.shape}")
    top = int(v.max()) if vmax is None else int(vmax)
    edges_e = np.append(eps, eps[-1] + (eps[-1] - eps[-2] if eps.size > 1 else 1.0))
    edges_k = np.append(kappa, kappa[-1] + (kappa[-1] - kappa[-2] if kappa.size > 1 else 1.0))
    norm = BoundaryNorm(np.arange(-0.5, top + 1.5), plt.get_cmap(cmap).N)
    mesh = ax.pcolormesh(edges_e, edges_k, v.T, cmap=cmap, norm=norm, shading="flat")
    ax.set(xlabel=xlabel, ylabel=ylabel)
    if colorbar:
        cb = ax.figure.colorbar(mesh, ax=ax, ticks=range(top + 1), fraction=0.05, pad=0.03)
        cb.ax.set_title(label, fontsize=9)
    return mesh


def line_fan(bounds, n_lines: int = 5, *, base=None, angles=(15.0, 75.0)):
    """``n_lines`` lines of positive slope through ``base`` (default the lower-left corner of
    ``bounds`` = ``[[ε_min, κ_min], [ε_max, κ_max]]``), at angles spread over ``angles`` (degrees)
    in the box's own scale, so that each line crosses the box.  Returns ``(base, directions)``;
    each direction reaches the box's far side at t = 1.
    Thesis: Chapter 5 (one line of the (ε, κ) plane is one ordinary persistence problem).
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


def plot_fibered_barcodes(ax, bifiltration: Bifiltration, base, directions, *, dim: int, min_length: float = 0.0,
                          colors=None, linewidth: float = 4.0, coefficients: int | None = None):
    """Draw each line base + t·direction and, on it, the bars of its fibered barcode in H_dim as
    thick segments (offset sideways a little so that overlapping bars stay visible).

    Returns the list of barcodes (one per line).  Bars shorter than ``min_length`` (in t) are left out.
    Thesis: Definition 2.34 (a barcode), along lines of the (ε, κ) plane (Chapter 5).
    """
    import matplotlib.pyplot as plt

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

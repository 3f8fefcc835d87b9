"""The figures of the hypersurface experiment (thesis §3.4.2): mean curvature estimates on the
3-sphere (Figure 3.12) and on the 3-catenoid (Figure 3.13)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot_sphere_estimates", "plot_catenoid_estimates", "THESIS_CATENOID_RANGE"]

#: the range of the estimated |H| on the 3-catenoid that the thesis reports (§3.4.2, Figure 3.13)
THESIS_CATENOID_RANGE = (2e-5, 14e-5)


def plot_sphere_estimates(*, grid_values: npt.ArrayLike, grid_weight: int, freudenthal_values: npt.ArrayLike,
                          exact: float, n: int, radius: float, area: str,
                          grid_slice: npt.ArrayLike | None = None, step: float | None = None,
                          freudenthal_angles: npt.ArrayLike | None = None,
                          freudenthal_slice_values: npt.ArrayLike | None = None) -> Figure:
    """|H| on the n-sphere by the neighbour grid and on its Freudenthal triangulation: two maps at
    φ = 0 (for n = 3) above the histograms of both estimates against the exact 1/ρ.

    Thesis: §3.4.2, Figure 3.12 (the estimated mean curvature of the 3-sphere of radius 2).

    Parameters
    ----------
    grid_values : array_like
        The neighbour-grid estimates (one per grid point evaluated).
    grid_weight : int
        How many values of φ each grid estimate stands for (the estimate does not depend on φ).
    freudenthal_values : array_like
        The estimate at every vertex of the triangulation.
    exact : float
        The exact |H| (1/ρ up to the thesis's normalisation).
    n : int
        The dimension of the sphere.
    radius : float
        Its radius.
    area : str
        The vertex area of the Freudenthal estimate (for the legend).
    grid_slice : array_like, shape (m, m), optional
        For n = 3: the grid estimate at φ = 0 over (ψ, θ) ∈ [step, π − step]²; with ``step``.
    step : float, optional
        The grid step ε of ``grid_slice``.
    freudenthal_angles : array_like, shape (k, 2), optional
        For n = 3: (ψ, θ) of the Freudenthal vertices at φ = 0; with ``freudenthal_slice_values``.
    freudenthal_slice_values : array_like, shape (k,), optional
        Their estimates.

    Returns
    -------
    matplotlib.figure.Figure
        The two maps (empty axes without ``grid_slice``) and the histogram.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_sphere_estimates(grid_values=[0.49, 0.5, 0.51], grid_weight=2, freudenthal_values=[0.45, 0.52],
    ...                             exact=0.5, n=3, radius=2.0, area="voronoi")
    >>> fig.axes[2].get_title()
    '3-sphere of radius 2.0'
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the sphere's curvature")
    from matplotlib.ticker import NullFormatter, StrMethodFormatter

    from ..graphics.style import COLORS

    H_grid = np.asarray(grid_values, dtype=np.float64)
    H_fr = np.asarray(freudenthal_values, dtype=np.float64)
    fig = plt.figure(figsize=(7.2, 6.4), layout="constrained")
    grid_spec = fig.add_gridspec(2, 2)
    axes = [fig.add_subplot(grid_spec[0, 0]), fig.add_subplot(grid_spec[0, 1]), fig.add_subplot(grid_spec[1, :])]
    if grid_slice is not None:
        im = axes[0].imshow(np.asarray(grid_slice).T, origin="lower", extent=(step, np.pi - step, step, np.pi - step),
                            cmap="viridis")
        cb = fig.colorbar(im, ax=axes[0], format="%.4f")
        cb.ax.set_title("|H|", fontsize=10, pad=8)
        axes[0].set(xlabel="ψ", ylabel="θ")
        axes[0].set_title("neighbour grid (thesis), φ = 0", fontsize=10)
    if freudenthal_angles is not None:
        angles = np.asarray(freudenthal_angles, dtype=np.float64)
        sc = axes[1].scatter(angles[:, 0], angles[:, 1], c=freudenthal_slice_values, s=6, cmap="viridis")
        cb = fig.colorbar(sc, ax=axes[1])
        cb.ax.set_title("|H|", fontsize=10, pad=8)
        axes[1].set(xlabel="ψ", ylabel="θ")
        axes[1].set_title(f"Freudenthal, {area} area, φ = 0", fontsize=10)
    bins = np.linspace(0.0, 2 * exact, 81)
    axes[2].hist(H_grid, bins=bins, weights=np.full(len(H_grid), grid_weight), color=COLORS["first"],
                 alpha=0.7, label="neighbour grid (thesis)")  # each value stands for the φ it repeats
    axes[2].hist(H_fr, bins=bins, color=COLORS["second"], alpha=0.6, label=f"Freudenthal ({area})")
    axes[2].axvline(exact, color="k", lw=0.8, ls="--", label="exact 1/ρ")
    axes[2].set(xlabel="|H|", ylabel="vertices", yscale="log", title=f"{n}-sphere of radius {radius}")
    axes[2].yaxis.set_major_formatter(StrMethodFormatter("{x:.0f}"))  # 1, 10, 100: no superscripts
    axes[2].yaxis.set_minor_formatter(NullFormatter())
    axes[2].legend(fontsize=9)
    return fig


def plot_catenoid_estimates(image: npt.ArrayLike, *, clim: Sequence[float], v: npt.ArrayLike,
                            highest: npt.ArrayLike, lowest: npt.ArrayLike, n: int, step: float) -> Figure:
    """The rendered estimate of |H| on the n-catenoid above its profile along v against the thesis's range.

    Thesis: §3.4.2, Figure 3.13 (the estimated mean curvature of the 3-catenoid, which is minimal:
    the thesis reports values between 2·10⁻⁵ and 14·10⁻⁵).

    Parameters
    ----------
    image : array_like
        The rendered surface (:func:`~thesis_lib.meshes.render_mesh`), coloured with ``clim``.
    clim : (float, float)
        Its colour range.
    v : array_like
        The grid values of v.
    highest, lowest : array_like
        The largest and the least estimate at each v (over u and r).
    n : int
        The dimension of the catenoid.
    step : float
        The grid step ε.

    Returns
    -------
    matplotlib.figure.Figure
        The rendered surface with its colour bar, and the profile with the thesis's range
        (``THESIS_CATENOID_RANGE``) as a grey band.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_catenoid_estimates(np.zeros((4, 4, 3)), clim=(0.0, 1e-4), v=[-0.5, 0.0, 0.5],
    ...                               highest=[3e-5, 5e-5, 3e-5], lowest=[1e-5, 2e-5, 1e-5], n=3, step=0.05)
    >>> fig.axes[1].get_title()
    'neighbour grid, ε = 0.05'
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the catenoid's curvature")
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize

    from ..graphics.style import COLORS

    v = np.asarray(v, dtype=np.float64)
    fig, (ax0, ax1) = plt.subplots(2, 1, figsize=(7.2, 6.4), layout="constrained", height_ratios=[1.1, 1])
    ax0.imshow(image)
    ax0.set_axis_off()
    ax0.set_title(f"estimated |H| of the {n}-catenoid at r = 0")
    cb = fig.colorbar(ScalarMappable(Normalize(*clim), "viridis"), ax=ax0, shrink=0.8, format="%.1e")
    cb.ax.set_title("|H|", fontsize=10, pad=8)
    ax1.fill_between([v[0], v[-1]], *THESIS_CATENOID_RANGE, color="0.85", label="thesis: (2·10⁻⁵, 14·10⁻⁵)")
    ax1.plot(v, highest, ".-", color=COLORS["first"], label="estimate (max over u, r)")
    ax1.plot(v, lowest, ".", color=COLORS["second"], label="estimate (min over u, r)")
    ax1.set(xlabel="v", ylabel="estimated |H|", title=f"neighbour grid, ε = {step}")
    ax1.legend(fontsize=9)
    return fig

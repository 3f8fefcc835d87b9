"""The figures of the hypersurface experiment (chapters.hypersurface_figures)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thesis_lib.chapters.hypersurface_figures import (
    THESIS_CATENOID_RANGE,
    plot_catenoid_estimates,
    plot_sphere_estimates,
)


def test_the_sphere_histograms_weight_the_grid_by_the_values_of_phi_it_stands_for():
    rng = np.random.default_rng(0)
    grid, fr = 0.5 + 0.01 * rng.standard_normal(50), 0.5 + 0.05 * rng.standard_normal(400)
    fig = plot_sphere_estimates(grid_values=grid, grid_weight=10, freudenthal_values=fr, exact=0.5, n=3, radius=2.0,
                                area="voronoi", grid_slice=np.full((4, 4), 0.5), step=0.1,
                                freudenthal_angles=rng.random((5, 2)), freudenthal_slice_values=np.full(5, 0.5))
    hist = fig.axes[2]
    heights = [sum(p.get_height() for p in container) for container in hist.containers]
    assert heights == [10 * 50, 400]  # every estimate inside [0, 2·exact] counted, the grid's ten times
    assert hist.get_title() == "3-sphere of radius 2.0" and hist.get_yscale() == "log"
    assert fig.axes[0].get_title() == "neighbour grid (thesis), φ = 0" and len(fig.axes[1].collections) == 1
    bare = plot_sphere_estimates(grid_values=grid, grid_weight=1, freudenthal_values=fr, exact=0.5, n=4, radius=1.0,
                                 area="barycentric")
    assert not bare.axes[0].images and not bare.axes[1].collections  # no slice maps beyond n = 3
    plt.close("all")


def test_the_catenoid_profile_lies_beside_the_thesis_range():
    v = np.linspace(-1, 1, 9)
    fig = plot_catenoid_estimates(np.ones((5, 5, 3)), clim=(0.0, 1e-4), v=v, highest=np.full(9, 5e-5),
                                  lowest=np.full(9, 1e-5), n=3, step=0.05)
    profile = fig.axes[1]
    band = profile.collections[0].get_paths()[0].vertices
    assert band[:, 1].min() == THESIS_CATENOID_RANGE[0] and band[:, 1].max() == THESIS_CATENOID_RANGE[1]
    assert [np.array_equal(line.get_xdata(), v) for line in profile.lines] == [True, True]
    assert profile.get_title() == "neighbour grid, ε = 0.05"
    plt.close("all")

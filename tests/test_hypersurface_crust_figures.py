"""The figures of the Crust in R⁴ (chapters.hypersurface_crust_figures)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.chapters.hypersurface_crust_figures import (
    crop_to_drawing,
    plot_crust_error_curves,
    plot_hyperplane_slices,
)
from thesis_lib.chapters.hypersurface_study import crust_curvature_errors  # noqa: E402


def test_the_crop_is_the_box_of_every_drawing_plus_a_margin():
    a = np.full((40, 50, 3), 255, dtype=np.uint8)
    b = a.copy()
    a[10:12, 20:22] = 0
    b[30, 5] = (255, 100, 255)  # one channel below the background threshold is drawn
    out = crop_to_drawing([a, b], margin=3)
    assert [img.shape for img in out] == [(30 - 10 + 1 + 6, 21 - 5 + 1 + 6, 3)] * 2
    assert (out[0] < 250).any(axis=2).sum() == 4 and (out[1] < 250).any(axis=2).sum() == 1
    edge = crop_to_drawing([b], margin=100)[0]  # the margin stops at the image's edge
    assert edge.shape == (40, 50, 3)
    with pytest.raises(ValueError, match="nothing is drawn"):
        crop_to_drawing([np.full((4, 4, 3), 255)])
    with pytest.raises(ValueError, match="of one size"):
        crop_to_drawing([a, a[:-1]])
    with pytest.raises(ValueError, match="margin must be >= 0"):
        crop_to_drawing([a], margin=-1)


def test_the_error_curves_are_means_with_bars_over_the_seeds():
    sphere = np.array([[100, 0.1, 0.3, np.nan, np.nan, 1, 1.0], [100, 0.2, 0.5, np.nan, np.nan, 1, 1.0],
                       [1000, 0.05, 0.2, np.nan, np.nan, 1, 1.0], [1000, 0.07, 0.2, np.nan, np.nan, 1, 1.0]])
    catenoid = np.array([[100, 0.3, 0.6, 0.25, 0.5, 0, 0.2], [200, 0.2, 0.5, 0.2, 0.4, 0, 0.3]])
    fig = plot_crust_error_curves(sphere, catenoid)
    left, right = fig.axes
    median = left.containers[0]
    np.testing.assert_allclose(median.lines[0].get_ydata(), [0.15, 0.06])
    bars = median.lines[2][0].get_segments()  # the error bars span min to max over the seeds
    np.testing.assert_allclose([seg[:, 1] for seg in bars], [[0.1, 0.2], [0.05, 0.07]])
    assert [t.get_text() for t in left.get_xticklabels()] == ["100", "1,000"] and left.get_xscale() == "log"
    dashed = [line for line in right.lines if line.get_linestyle() == "--"]
    np.testing.assert_allclose(dashed[0].get_ydata(), [0.25, 0.2])
    assert (left.get_title(), right.get_title()) == ("3-sphere, radius 2", "3-catenoid")
    assert [t.get_text() for t in fig.legends[0].get_texts()] == [
        "Crust, median", "Crust, 90th percentile", "parameter Delaunay, median", "parameter Delaunay, 90th percentile"]
    with pytest.raises(ValueError, match="rows of a CrustErrorCurve"):
        plot_crust_error_curves(sphere[:, :3], catenoid)
    plt.close("all")


def test_the_slices_of_the_reconstructed_sphere():
    run = crust_curvature_errors("sphere", 500, seed=0)
    fig = plot_hyperplane_slices(run["points"], run["simplices"], run["H"], levels=[-1.0, 0.5], clim=(0.3, 0.7))
    assert [ax.get_title() for ax in fig.axes[:2]] == ["w = −1", "w = 0.5"] and fig.axes[-1].get_title() == "|H|"
    shapes = {ax.images[0].get_array().shape for ax in fig.axes[:2]}
    assert len(shapes) == 1 and next(iter(shapes))[0] < 480  # cropped alike, smaller than the window
    with pytest.raises(ValueError, match=r"^levels must hold at least 1 entry, got 0$"):
        plot_hyperplane_slices(run["points"], run["simplices"], run["H"], levels=[], clim=(0.3, 0.7))
    plt.close("all")

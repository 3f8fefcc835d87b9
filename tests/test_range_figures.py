"""The range-image experiment's analyses and figures (applications.range_images, range_figures)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import scipy.fft  # noqa: E402

from thesis_lib.applications.range_figures import plot_gradient_projection, plot_range_images  # noqa: E402
from thesis_lib.applications.range_images import dct_gradient_correlation, projection_summary  # noqa: E402


@pytest.mark.parametrize("size", range(2, 9))
def test_gradient_correlation_is_the_first_dct_coefficient_of_a_ramp(size):
    ramp = np.arange(size) - (size - 1) / 2
    expected = abs(scipy.fft.dct(ramp, norm="ortho")[1]) / np.linalg.norm(ramp)  # scipy's DCT-II, not ours
    assert dct_gradient_correlation(size=size) == pytest.approx(expected, rel=1e-12)
    assert dct_gradient_correlation(size=2) == pytest.approx(1.0)  # two pixels: the gradient is the ramp


def test_projection_summary_tells_a_circle_from_a_disc():
    rng = np.random.default_rng(5)
    t = rng.uniform(-np.pi, np.pi, 500)
    circle = projection_summary(0.8 * np.column_stack([np.cos(t), np.sin(t)]))
    assert circle == {"radius_median": pytest.approx(0.8), "sectors_held": 12, "angle_coverage": 1.0,
                      "inner_fraction": 0.0}
    disc = rng.uniform(-1, 1, size=(4000, 2))
    disc = disc[np.linalg.norm(disc, axis=1) <= 1]
    r = np.linalg.norm(disc, axis=1)
    summary = projection_summary(disc)
    assert summary["inner_fraction"] == np.mean(r < 0.5 * np.median(r))
    assert summary["inner_fraction"] == pytest.approx(0.125, abs=0.03)  # uniform disc: (1/2 · 1/√2)² of the area
    half = projection_summary(np.column_stack([np.cos(t[t > 0]), np.sin(t[t > 0])]), n_sectors=4)
    assert half["sectors_held"] == 2 and half["angle_coverage"] == 0.5


@pytest.mark.parametrize("coords, kwargs, match", [
    (np.zeros((3, 3)), {}, "shape"), (np.zeros((0, 2)), {}, "non-empty"), ([[np.nan, 0.0]], {}, "finite"),
    (np.ones((3, 2)), {"n_sectors": 0}, "n_sectors"),
])
def test_projection_summary_bad_input(coords, kwargs, match):
    with pytest.raises(ValueError, match=match):
        projection_summary(coords, **kwargs)


def test_range_images_are_drawn_with_out_of_range_black():
    images = [np.array([[1.0, np.nan], [2.0, 4.0]]), np.full((3, 3), 2.0), np.ones((2, 2))]
    fig = plot_range_images(images, n=2)
    assert len(fig.axes) == 2
    shown = fig.axes[0].images[0]
    assert np.array_equal(shown.get_array(), [[1.0, 0.0], [2.0, 4.0]]) and shown.get_clim() == (0.0, 4.0)
    with pytest.raises(ValueError, match="no image"):
        plot_range_images([])
    with pytest.raises(ValueError, match="2-D"):
        plot_range_images([np.full((2, 2), np.nan)])
    with pytest.raises(ValueError, match="n must"):
        plot_range_images(images, n=0)
    plt.close("all")


def test_gradient_projection_marks_the_landmarks():
    coords = np.random.default_rng(2).uniform(-1, 1, size=(20, 2))
    fig = plot_gradient_projection(coords, landmarks=[3, 7], size=4)
    points, stars = fig.axes[0].lines
    assert np.array_equal(np.column_stack(points.get_data()), coords)
    assert np.array_equal(np.column_stack(stars.get_data()), coords[[3, 7]])
    assert [ax.images[0].get_array().shape for ax in fig.axes[1:]] == [(4, 4), (4, 4)]
    assert len(plot_gradient_projection(coords).axes[0].lines) == 1
    with pytest.raises(ValueError, match="landmark"):
        plot_gradient_projection(coords, landmarks=[20])
    with pytest.raises(ValueError, match="coords"):
        plot_gradient_projection(np.zeros(4))
    plt.close("all")

"""plot_diagram and plot_barcode take plain diagram arrays (ripser.py's ``dgms``, one array, empty ones) as
well as Barcodes: the points and bars drawn, the line of essential classes, and the refusals."""

from __future__ import annotations

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest
import ripser

from thesis_lib.complexes import rips
from thesis_lib.datasets import noisy_circle
from thesis_lib.persistence import Barcode, persistence, plot_barcode, plot_diagram

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def points_by_label(fig) -> dict[str, np.ndarray]:
    ax = fig.axes[0]
    return {c.get_label(): np.asarray(c.get_offsets()) for c in ax.collections}


def bar_segments(ax) -> np.ndarray:
    """(k, 4) rows x0, y0, x1, y1 of the bars of a barcode panel, sorted."""
    rows = [np.ravel(seg) for c in ax.collections for seg in c.get_segments()]
    return np.array(sorted(map(tuple, rows))).reshape(-1, 4)


def test_ripser_dgms_are_drawn_point_for_point_with_essential_points_on_the_top_line():
    points = noisy_circle(30, noise=0.05, seed=1)
    dgms = ripser.ripser(points, maxdim=1)["dgms"]
    fig = plot_diagram(dgms, max_value=3.0)
    drawn = points_by_label(fig)
    assert set(drawn) == {"$H_0$", "$H_1$"}
    for d, label in enumerate(("$H_0$", "$H_1$")):
        expected = np.where(np.isinf(dgms[d]), 3.0, dgms[d])  # inf deaths on the line at max_value
        assert np.allclose(np.sort(drawn[label], axis=0), np.sort(expected, axis=0))
    assert len(drawn["$H_0$"]) == 30 and np.isclose(drawn["$H_0$"][:, 1], 3.0).sum() == 1
    dashed = [line for line in fig.axes[0].lines if line.get_linestyle() == "--"]
    assert len(dashed) == 1 and np.allclose(dashed[0].get_ydata(), 3.0)  # the line of ∞ across the top


def test_arrays_and_the_barcode_they_came_from_draw_the_same_points():
    bars = persistence(rips(noisy_circle(25, noise=0.05, seed=2), max_radius=1.0, max_dim=2))
    from_barcode = points_by_label(plot_diagram(bars, max_value=2.5))
    from_arrays = points_by_label(plot_diagram(bars.to_diagrams(), max_value=2.5))
    assert from_barcode.keys() == from_arrays.keys() == {"$H_0$", "$H_1$"}
    for key in from_barcode:
        assert np.array_equal(from_barcode[key], from_arrays[key])


def test_a_single_array_is_one_dimension_named_by_dims():
    dgm = np.array([[0.1, 0.5], [0.2, 0.9], [0.3, np.inf]])
    assert set(points_by_label(plot_diagram(dgm))) == {"$H_0$"}
    drawn = points_by_label(plot_diagram(dgm, dims=[1], max_value=1.5))
    assert list(drawn) == ["$H_1$"]
    assert drawn["$H_1$"].tolist() == [[0.1, 0.5], [0.2, 0.9], [0.3, 1.5]]
    # a list of (birth, death) rows is one diagram too
    assert points_by_label(plot_diagram(dgm[:2].tolist()))["$H_0$"].tolist() == [[0.1, 0.5], [0.2, 0.9]]


def test_the_list_dims_select_diagrams():
    dgms = [np.array([[0.0, 1.0]]), np.array([[0.2, 0.4], [0.3, 0.8]]), np.array([[0.5, 0.6]])]
    drawn = points_by_label(plot_diagram(dgms, dims=[2, 1]))
    assert list(drawn) == ["$H_2$", "$H_1$"]
    assert drawn["$H_1$"].tolist() == [[0.2, 0.4], [0.3, 0.8]]


@pytest.mark.parametrize("empty", [np.empty((0, 2)), np.array([]), [], [np.empty((0, 2)), np.empty((0, 2))]])
def test_empty_diagrams_draw_axes_without_points(empty):
    fig = plot_diagram(empty)
    drawn = points_by_label(fig)
    assert all(len(p) == 0 for p in drawn.values()) and len(drawn) == (2 if isinstance(empty, list) and empty
                                                                          else 1)
    ax = fig.axes[0]
    right = 1.15  # the default top of nothing: 1, and 15 % more
    assert ax.get_xlim() == pytest.approx((-0.02 * right, 1.04 * right))
    fig = plot_barcode(empty)
    assert all(len(ax.collections) == 0 for ax in fig.axes)


def test_negative_values_widen_the_diagram_to_hold_them():
    fig = plot_diagram(np.array([[-2.0, -1.0], [-1.5, np.inf]]), max_value=0.5)
    ax = fig.axes[0]
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    assert x0 < -2.0 and y0 < -2.0 and x1 > 0.5 and y1 > 0.5
    diagonal = ax.lines[0].get_xydata()
    assert diagonal.tolist() == [[-2.0, -2.0], [0.5, 0.5]]


def test_barcode_of_arrays_draws_one_segment_per_interval_with_infinite_ones_to_the_edge():
    dgms = [np.array([[0.0, 1.0], [0.0, np.inf], [0.2, 0.7]]), np.array([[0.4, 0.9]])]
    fig = plot_barcode(dgms, max_value=2.0, min_fraction=0)
    top, bottom = fig.axes
    segs = bar_segments(top)
    assert segs.shape == (3, 4)
    assert sorted((x0, x1) for x0, _, x1, _ in segs) == [(0.0, 1.0), (0.0, 2.0), (0.2, 0.7)]
    assert len(top.texts) == 1  # the arrow of the essential bar
    assert bar_segments(bottom)[:, [0, 2]].tolist() == [[0.4, 0.9]]
    assert top.get_ylabel() == "$H_0$" and bottom.get_ylabel() == "$H_1$"
    # the Barcode of the same intervals draws the same bars
    same = plot_barcode(Barcode.from_diagrams(dgms), max_value=2.0, min_fraction=0)
    for a, b in zip(fig.axes, same.axes):
        assert np.array_equal(bar_segments(a)[:, [0, 2]], bar_segments(b)[:, [0, 2]])


def test_barcode_of_a_single_array_and_min_length():
    dgm = np.array([[0.0, 0.05], [0.1, 1.0]])
    fig = plot_barcode(dgm, dims=[1], min_length=0.1, min_fraction=0)
    (ax,) = fig.axes
    assert ax.get_ylabel() == "$H_1$"
    assert bar_segments(ax)[:, [0, 2]].tolist() == [[0.1, 1.0]]


@pytest.mark.parametrize("plot", [plot_diagram, plot_barcode])
@pytest.mark.parametrize("bad, error, match", [
    ({"0": [[0, 1]]}, TypeError, "array"),
    ("dgm", TypeError, "array"),
    (None, TypeError, "array"),
    (np.array([[0.0, "a"]], dtype=object), TypeError, "numbers"),
    ([[0.0, 1.0], np.array([[0.0, 1.0]])], TypeError, "mixing"),
    (np.zeros((3, 3)), ValueError, "shape"),
    (np.zeros((2, 2, 2)), ValueError, "shape"),
    (np.array([0.0, 1.0]), ValueError, "shape"),
    (np.array([[0.0, np.nan]]), ValueError, "NaN"),
    ([np.array([[0.0, 1.0]]), np.array([[np.nan, 1.0]])], ValueError, r"diagram\[1\] has a NaN"),
    (np.array([[2.0, 1.0]]), ValueError, "dies before it is born"),
    (np.array([[np.inf, np.inf]]), ValueError, "births must be finite"),
    (np.array([[-np.inf, 1.0]]), ValueError, "births must be finite"),
])
def test_bad_diagrams_are_refused(plot, bad, error, match):
    with pytest.raises(error, match=match):
        plot(bad)


@pytest.mark.parametrize("plot", [plot_diagram, plot_barcode])
def test_bad_dims_for_arrays_are_refused(plot):
    dgms = [np.array([[0.0, 1.0]]), np.array([[0.5, 0.7]])]
    with pytest.raises(ValueError, match="no diagram for dimension 2"):
        plot(dgms, dims=[0, 2])
    with pytest.raises(ValueError, match="one diagram"):
        plot(dgms[0], dims=[0, 1])
    with pytest.raises(ValueError, match="no homology dimension"):
        plot(dgms, dims=[])
    with pytest.raises(TypeError, match="integer"):
        plot(dgms, dims=[0.5])
    with pytest.raises(ValueError, match=">= 0"):
        plot(dgms, dims=[-1])

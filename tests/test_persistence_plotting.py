"""The figures of §2.3 beyond the barcode itself: a long bar's cycle on its points (Figure 2.9) and the growth
of the work of Algorithms 1–2."""

from __future__ import annotations

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest

from thesis_lib.complexes import alpha
from thesis_lib.datasets import noisy_circle
from thesis_lib.graphics import style
from thesis_lib.persistence import Barcode, persistence
from thesis_lib.persistence.complexity import WorkGrowth
from thesis_lib.persistence.plotting import plot_long_bar, plot_work_growth

matplotlib.use("Agg")


def test_the_long_bar_figure_draws_its_cycle_and_the_positive_bars():
    points = noisy_circle(40, noise=0.05, seed=3)
    bars = persistence(alpha(points))
    fig = plot_long_bar(points, bars, min_length=1e-9)
    try:
        cycle_ax, barcode_ax, diagram_ax = fig.axes
        longest = int(bars.longest(1, n=1)[0])
        cycle = bars.representative(1, longest)
        assert len(cycle_ax.lines) == len(cycle)  # one segment per edge of the cycle
        assert cycle_ax.get_title() == f"the long bar's cycle ({len(cycle)} edges)"
        for line in cycle_ax.lines:  # each segment joins two of the points
            xy = line.get_xydata()
            assert all(np.isclose(points, p).all(axis=1).any() for p in xy)
        h1 = bars.intervals(1)
        positive = int(((h1[:, 1] - h1[:, 0]) > 1e-9).sum())
        # the diagram has a point per interval of positive length; the barcode draws those not thinner
        # than a line (plot_barcode's min_fraction), the long one among them
        h1_points = next(c for c in diagram_ax.collections if c.get_label() == "$H_1$").get_offsets()
        assert len(h1_points) == positive
        assert 1 <= sum(len(c.get_segments()) for c in barcode_ax.collections) <= positive
        assert barcode_ax.get_title() == "$H_1$ barcode" and diagram_ax.get_title() == "persistence diagram"
        assert style.smallest_text_px(fig, rendered_width_px=660) >= 9
    finally:
        plt.close(fig)


def test_the_long_bar_figure_needs_representatives():
    with pytest.raises(ValueError, match="representatives"):
        plot_long_bar(np.zeros((2, 2)), Barcode({0: [(0.0, 1.0)], 1: [(0.0, 1.0)]}))


def test_the_work_figure_shows_each_family_and_the_reference_slopes():
    growth = {"paths: n vertices": WorkGrowth(np.array([19.0, 199.0]), np.array([18.0, 198.0]), 1.0228),
              "dense": WorkGrowth(np.array([50.0, 500.0]), np.array([400.0, 40000.0]), 2.0)}
    fig = plot_work_growth(growth, reference=(10.0, 1000.0))
    try:
        ax = fig.axes[0]
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert labels == ["paths (a ≈ 1.0)", "dense (a ≈ 2.0)", "slope of m", "slope of m²", "slope of m³"]
        data = {line.get_label(): line.get_xydata() for line in ax.lines}
        assert np.array_equal(data["paths (a ≈ 1.0)"], np.c_[[19.0, 199.0], [18.0, 198.0]])
        for a, name in ((1, "m"), (2, "m²"), (3, "m³")):
            (x0, y0), (x1, y1) = data[f"slope of {name}"]
            assert (x0, x1, y0) == (10.0, 1000.0, 20.0)  # from twice the left end ...
            assert np.log(y1 / y0) / np.log(x1 / x0) == pytest.approx(a)  # ... with slope a
        assert ax.get_xscale() == ax.get_yscale() == "log"
    finally:
        plt.close(fig)
    with pytest.raises(ValueError, match="no family"):
        plot_work_growth({})

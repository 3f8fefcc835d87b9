"""The chapter 3 figures (thesis_lib.chapters.curvature_figures): what they draw against the
thesis's formulas and an independent Thales test."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.chapters import curvature_figures as cf  # noqa: E402
from thesis_lib.graphics import style  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.mark.parametrize(("R", "r"), [(10.0, 5.0), (3.0, 1.0)])
def test_exact_torus_colour_ranges_follow_section_3_4_1(R, r):
    n = 16
    fig_h, fig_k = cf.plot_exact_torus_curvature(R=R, r=r, n=n)
    v = 2 * np.pi * np.arange(n) / n
    H = np.abs((R + 2 * r * np.cos(v)) / (2 * r * (R + r * np.cos(v))))  # §3.4.1, by hand
    K = np.cos(v) / (r * (R + r * np.cos(v)))
    assert fig_h.axes[-1].get_ylim() == pytest.approx((0.0, H.max()))
    assert fig_k.axes[-1].get_ylim() == pytest.approx((-np.abs(K).max(), np.abs(K).max()))
    assert (fig_h.axes[-1].get_title(), fig_k.axes[-1].get_title()) == ("|H|", "K")


def test_exterior_angles_of_the_pentagon_add_up():
    fig = cf.plot_exterior_angles()
    texts = [t.get_text() for t in fig.axes[1].texts]
    delta = [float(t[2:-1]) for t in texts if t.startswith("δ=")]
    alpha = [float(t[2:-1]) for t in texts if t.startswith("α=")]
    assert len(delta) == len(alpha) == 5
    assert sum(delta) == pytest.approx(360, abs=3)  # rounded to whole degrees
    assert sum(alpha) == pytest.approx((5 - 2) * 180, abs=3)
    assert all(d + a == 180 for d, a in zip(delta, alpha, strict=True))
    assert fig.axes[0].get_title() == "a closed curve turns by 2π"


def test_voronoi_figure_colours_the_points_inside_thales_circle():
    fig = cf.plot_voronoi_regions()
    scatter = fig.axes[0].collections[0]
    xy = scatter.get_offsets()
    assert len(xy) == 500
    inside = np.linalg.norm(xy, axis=1) < 1  # Thales: the angle at x over the diameter pq₁ is obtuse
    colours = scatter.get_facecolors()
    first = matplotlib.colors.to_rgba(style.COLORS["first"])
    red = np.all(np.isclose(colours, first), axis=1)
    assert np.array_equal(red, inside)
    assert len(fig.axes[1].patches) == 14  # seven triangles and seven nearest parts

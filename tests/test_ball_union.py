"""The union-of-balls figure of the introduction (chapters.ball_union.plot_ball_unions)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.chapters.ball_union import plot_ball_unions  # noqa: E402


def test_one_ball_per_point_and_panel_at_each_radius():
    pts = np.random.default_rng(0).normal(size=(7, 2))
    fig = plot_ball_unions(pts, [0.1, 0.5, 1.5])
    assert [ax.get_title() for ax in fig.axes] == ["ε = 0.1", "ε = 0.5", "ε = 1.5"]
    for ax, r in zip(fig.axes, (0.1, 0.5, 1.5)):
        assert [tuple(p.center) for p in ax.patches] == [tuple(p) for p in pts]
        assert {p.radius for p in ax.patches} == {r}
    limit = np.abs(pts).max() + 1.5  # the default: every ball in view
    assert fig.axes[0].get_xlim() == pytest.approx((-limit, limit))
    assert plot_ball_unions(pts, [1.0], limit=3.0).axes[0].get_ylim() == (-3.0, 3.0)
    plt.close("all")


@pytest.mark.parametrize("points, radii, match", [
    (np.zeros((3, 3)), [1.0], "planar"),
    (np.zeros((3, 2)), [], "radii"),
    (np.zeros((3, 2)), [0.0], "radii"),
    (np.zeros((3, 2)), [np.nan], "radii"),
    ([[np.inf, 0.0]], [1.0], "finite"),
])
def test_bad_input_is_named(points, radii, match):
    with pytest.raises(ValueError, match=match):
        plot_ball_unions(points, radii)

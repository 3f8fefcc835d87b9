"""Figure 2.11 (thesis_lib.chapters.filtration_figure): the steps of the example filtration, listed and drawn."""

from __future__ import annotations

import doctest

import matplotlib
import matplotlib.pyplot as plt
import pytest
from matplotlib.colors import to_rgba
from matplotlib.patches import Polygon

from thesis_lib.chapters import filtration_figure
from thesis_lib.chapters.filtration_figure import (
    FIGURE_2_11_POSITIONS,
    filtration_steps,
    plot_filtration_steps,
    steps_text,
)
from thesis_lib.datasets import example_filtration, module_filtration
from thesis_lib.datasets.filtrations import EXAMPLE_NAMES
from thesis_lib.graphics import style

matplotlib.use("Agg")

#: Example 2.38 / Figure 2.11, from the entry times read off the thesis's matrices: a, b at 0; c, d,
#: ab, cd at 1; e, da, bc at 2; ed, ce at 3; ced at 4 (edges named with ascending vertices here)
ENTERING = [["a", "b"], ["c", "d", "ab", "cd"], ["e", "ad", "bc"], ["de", "ce"], ["cde"]]


def test_steps_of_the_example_filtration():
    steps = filtration_steps(example_filtration())
    assert [value for value, _ in steps] == [0.0, 1.0, 2.0, 3.0, 4.0]
    named = [["".join(EXAMPLE_NAMES[v] for v in s) for s in entering] for _, entering in steps]
    assert named == ENTERING
    assert steps_text(example_filtration(), names=EXAMPLE_NAMES).splitlines() == [
        f"K{sup}: enters {', '.join(names)}" for sup, names in zip("⁰¹²³⁴", ENTERING)]


def test_steps_are_numbered_not_valued():
    K = module_filtration([(0, 5)])  # values 0 and 5: two steps, K⁰ and K¹
    assert steps_text(K).splitlines()[1].startswith("K¹: enters 0,1,2")


def test_the_figure_draws_each_step():
    K = example_filtration()
    fig = plot_filtration_steps(K, FIGURE_2_11_POSITIONS, names=EXAMPLE_NAMES)
    try:
        assert len(fig.axes) == len(ENTERING)
        new = to_rgba(style.COLORS["first"])
        for i, ax in enumerate(fig.axes):
            present = [x for names in ENTERING[: i + 1] for x in names]
            edges = [x for x in present if len(x) == 2]
            vertices = [x for x in present if len(x) == 1]
            assert len(ax.lines) == len(edges) + len(vertices)
            assert sorted(t.get_text() for t in ax.texts) == sorted(vertices)
            triangles = [p for p in ax.patches if isinstance(p, Polygon)]
            assert len(triangles) == sum(len(x) == 3 for x in present)
            coloured = sum(to_rgba(line.get_color()) == new for line in ax.lines)
            assert coloured == sum(len(x) < 3 for x in ENTERING[i])  # what enters at step i is coloured
        assert style.smallest_text_px(fig, rendered_width_px=660) >= 9
    finally:
        plt.close(fig)


def test_bad_positions_and_dimensions_are_refused():
    with pytest.raises(ValueError, match="a row for each of 5 vertices"):
        plot_filtration_steps(example_filtration(), FIGURE_2_11_POSITIONS[:4])
    with pytest.raises(ValueError, match="dimension ≤ 2"):
        plot_filtration_steps(module_filtration([(0, 1)], dim=2), [(0, 0)] * 4)


def test_docstring_examples_run():
    result = doctest.testmod(filtration_figure)
    assert result.attempted > 3 and result.failed == 0

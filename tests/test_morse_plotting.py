"""Drawings and example inputs of chapter 4 (Figures 4.4, 4.6–4.8)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.homology import homology  # noqa: E402
from thesis_lib.morse import COMPLEX_NAMES, RP2_FACETS
from thesis_lib.morse.examples import example_4_45, experiment_complex, rp2_chart, rp2_gradient_field
from thesis_lib.morse.matching import morse_matching
from thesis_lib.morse.morse_complex import morse_homology
from thesis_lib.morse.plotting import draw_gradient_field, draw_hasse_diagram, spectral_layout
from thesis_lib.morse.vector_field import is_acyclic


def test_rp2_chart_is_a_disc_picture_of_rp2():
    chart = rp2_chart()
    assert sorted(chart) == sorted(RP2_FACETS)
    # every triangle has positive area and the triangles tile the hexagon (area 3√3/2)
    area = 0.0
    for corners in chart.values():
        (x0, y0), (x1, y1), (x2, y2) = corners
        a = abs((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)) / 2
        assert a > 1e-3
        area += a
    assert np.isclose(area, 3 * np.sqrt(3) / 2)


def test_draw_gradient_field_and_hasse():
    fig, axs = plt.subplots(1, 3)
    draw_gradient_field(axs[0], RP2_FACETS, rp2_gradient_field(), chart=rp2_chart(), labels=dict(enumerate("abcdef")))
    n_arrows = sum(1 for t in axs[0].texts if t.arrow_patch is not None)
    assert n_arrows >= len(rp2_gradient_field())  # boundary pairs are drawn once per copy
    small, pairs = example_4_45()
    draw_hasse_diagram(axs[1], small, pairs)
    n_cells = 4 + 5 + 1
    assert len([t for t in axs[1].texts if t.get_text()]) == n_cells
    draw_gradient_field(axs[2], small, pairs)  # spectral layout
    plt.close(fig)
    with pytest.raises(ValueError, match="dimension"):
        draw_gradient_field(axs[0], [(0, 1, 2, 3)], [])
    pos = spectral_layout(small)
    assert sorted(pos) == [1, 2, 3, 4]


@pytest.mark.parametrize("name", COMPLEX_NAMES)
def test_experiment_complexes(name):
    facets, positions, chart = experiment_complex(name, seed=1)
    pairs = morse_matching(facets)
    assert is_acyclic(facets, pairs)
    assert morse_homology(facets, pairs) == homology(facets)
    if positions is not None:
        assert all(v in positions for s in facets for v in s)
    with pytest.raises(ValueError, match="complex must be one of"):
        experiment_complex("moebius")

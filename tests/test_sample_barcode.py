"""The sample-beside-barcode figure of the reconstruction experiments (chapters.sample_barcode)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.chapters.sample_barcode import plot_sample_and_barcode  # noqa: E402
from thesis_lib.persistence import Barcode  # noqa: E402


def _barcode():
    return Barcode({0: [(0.0, 0.2), (0.0, np.inf)], 1: [(0.3, 0.9)], 2: []})


def test_the_sample_then_one_panel_per_dimension():
    X = np.random.default_rng(1).normal(size=(50, 4))
    fig = plot_sample_and_barcode(X, _barcode(), dims=[0, 1, 2], max_value=1.0, coordinates=(2, 3), title="t")
    sample, *panels = fig.axes
    assert sample.get_title() == "t" and len(panels) == 3
    x, y = sample.lines[0].get_data()
    assert np.array_equal(x, X[:, 2]) and np.array_equal(y, X[:, 3])
    assert [ax.get_xlim()[1] for ax in panels] == [pytest.approx(1.03)] * 3  # max_value and a 3 % margin
    plt.close("all")


@pytest.mark.parametrize("kwargs, match", [
    ({"dims": [0], "coordinates": (0, 5)}, "coordinates"),
    ({"dims": []}, "at least one dimension"),
])
def test_bad_options_are_named(kwargs, match):
    with pytest.raises(ValueError, match=match):
        plot_sample_and_barcode(np.zeros((4, 2)), _barcode(), **kwargs)

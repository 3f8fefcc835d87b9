"""The side-by-side Hilbert-function figure of Chapter 5 (multiparameter.plotting.plot_hilbert_functions)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.multiparameter.plotting import plot_hilbert_functions  # noqa: E402


def test_one_panel_per_dimension_capped_and_labelled_by_bound():
    rng = np.random.default_rng(3)
    hf = [rng.integers(0, 9, size=(5, 3)) for _ in range(3)]
    fig = plot_hilbert_functions(hf[::2], np.linspace(0, 1, 5), [0.5, 5.0, 10.0], dims=(0, 2), vmax=5)
    panels = fig.axes[:2]  # the panels, then their colour bars
    assert [ax.get_title() for ax in panels] == ["dim H₀", "dim H₂"]
    for ax, d in zip(panels, (0, 2)):
        mesh = ax.collections[0]
        assert np.array_equal(np.asarray(mesh.get_array()).reshape(3, 5), np.minimum(hf[d], 5).T)
        assert [t.get_text() for t in ax.get_yticklabels()] == ["κ ≤ 0.5", "κ ≤ 5", "κ ≤ 10"]
        assert np.allclose(ax.get_yticks(), [0.5, 1.5, 2.5])  # one even row per grid value
    uncapped = plot_hilbert_functions(hf[1:2], np.linspace(0, 1, 5), [0.5, 5.0, 10.0], dims=(1,))
    assert np.asarray(uncapped.axes[0].collections[0].get_array()).max() == hf[1].max()
    scaled = plot_hilbert_functions(hf[1:], np.linspace(0, 1, 5), [-1.0, 0.0, 4.0], dims=(1, 2), rows="values",
                                    mark=0.0, ylabel="κ")
    ax = scaled.axes[0]
    assert ax.get_ylabel() == "κ" and ax.get_ylim() == (-1.0, 8.0)  # to scale: the last row as tall as the one before
    assert [line.get_ydata()[0] for line in ax.lines] == [0.0]
    plt.close("all")


def test_a_dimension_not_computed_is_named():
    with pytest.raises(ValueError, match=r"dims must name the homology dimension of each of the 2"):
        plot_hilbert_functions([np.zeros((2, 2), dtype=int)] * 2, [0, 1], [0, 1], dims=(0,))
    with pytest.raises(ValueError, match="rows must be"):
        plot_hilbert_functions([np.zeros((2, 2), dtype=int)], [0, 1], [0, 1], dims=(0,), rows="even")
    with pytest.raises(ValueError, match="shape"):
        plot_hilbert_functions([np.zeros((3, 2), dtype=int)], [0, 1], [0, 1], dims=(0,))
    plt.close("all")

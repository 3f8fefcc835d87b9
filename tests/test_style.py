"""The size of a figure's smallest text, and the PNGs that carry it (graphics.style)."""

from __future__ import annotations

import base64
import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import nbformat  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.graphics import style  # noqa: E402
from thesis_lib.graphics.style import TEXT_PX_KEY, figure_png, png_text, smallest_text_px  # noqa: E402
from thesis_lib.lab.results import Recorder  # noqa: E402


def _px(points: float, dpi: float) -> float:
    return points * dpi / 72


@pytest.fixture
def fig():
    with plt.rc_context({"font.size": 12, "figure.dpi": 100}):
        fig, ax = plt.subplots(figsize=(5, 3))
        ax.plot([0, 1, 2], [1, 3, 2], label="a line")
        ax.set_xlabel("x", fontsize=14)
        ax.set_title("title", fontsize=16)
    yield fig
    plt.close(fig)


def test_smallest_text_is_the_smallest_font_drawn(fig):
    assert smallest_text_px(fig) == pytest.approx(_px(12, 100))  # tick labels at font.size
    fig.axes[0].legend(fontsize=9)
    assert smallest_text_px(fig) == pytest.approx(_px(9, 100))
    fig.axes[0].annotate("note", (1, 2), fontsize=7.5)
    assert smallest_text_px(fig) == pytest.approx(_px(7.5, 100))
    assert smallest_text_px(fig, dpi=144) == pytest.approx(_px(7.5, 144))


def test_texts_that_are_not_drawn_do_not_count(fig):
    ax = fig.axes[0]
    ax.text(0.5, 0.5, "hidden", fontsize=4, visible=False)
    ax.text(0.5, 0.5, "", fontsize=3)
    ax.text(0.5, 0.5, "   ", fontsize=3)
    assert smallest_text_px(fig) == pytest.approx(_px(12, 100))
    other = fig.add_axes([0.7, 0.7, 0.2, 0.2])
    other.tick_params(labelsize=5)
    assert smallest_text_px(fig) == pytest.approx(_px(5, 100))
    other.set_axis_off()  # its tick labels are no longer drawn
    assert smallest_text_px(fig) == pytest.approx(_px(12, 100))


def test_colour_bars_and_mathtext_scripts_count(fig):
    image = fig.axes[0].imshow(np.arange(6.0).reshape(2, 3))
    bar = fig.colorbar(image)
    bar.ax.tick_params(labelsize=8)
    assert smallest_text_px(fig) == pytest.approx(_px(8, 100))
    fig.axes[0].set_ylabel("$k_{p+1}$", fontsize=10)  # the subscript is drawn at 0.7 of 10 pt
    assert smallest_text_px(fig) == pytest.approx(_px(7, 100))


def test_figure_without_text_has_none():
    fig = plt.figure(figsize=(2, 2))
    fig.add_axes([0, 0, 1, 1]).set_axis_off()
    assert math.isinf(smallest_text_px(fig, bbox_inches=None))
    assert png_text(figure_png(fig, bbox_inches=None))[TEXT_PX_KEY] == "none"
    plt.close(fig)


def test_rendered_width_scales_by_the_png_width(fig):
    png = figure_png(fig)
    width = int.from_bytes(png[16:20], "big")
    natural = smallest_text_px(fig)
    assert smallest_text_px(fig, rendered_width_px=width / 2) == pytest.approx(natural / 2)
    assert smallest_text_px(fig, rendered_width_px=730) == pytest.approx(natural * 730 / width)
    with pytest.raises(ValueError):
        smallest_text_px(fig, rendered_width_px=0)


def test_png_carries_the_size_and_is_deterministic(fig):
    fig.axes[0].legend(fontsize=9)
    png = figure_png(fig, dpi=110)
    text = png_text(png)
    assert text == {TEXT_PX_KEY: f"{_px(9, 110):.2f}"}  # no Software, no time stamp
    assert figure_png(fig, dpi=110) == png
    plt.imread(__import__("io").BytesIO(png))  # still a valid PNG (chunk CRCs checked by the reader)


def test_recorder_savefig_writes_the_chunk(fig, tmp_path):
    fig.axes[0].tick_params(labelsize=8)
    path = Recorder("style-test", output_dir=tmp_path).savefig(fig, "figure")
    assert png_text(path.read_bytes()) == {TEXT_PX_KEY: f"{_px(8, 110):.2f}"}


def test_notebook_figures_carry_the_size(tmp_path):
    """In a kernel: glue(..., fig), display(fig) and a figure left open by a cell all carry the chunk."""
    from nbclient import NotebookClient

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(src) for src in [
        "import matplotlib.pyplot as plt\nfrom myst_nb import glue\nfrom thesis_lib.graphics import style\n"
        "style.apply()",
        "fig, ax = plt.subplots()\nax.plot([1, 2])\nax.tick_params(labelsize=6)\nglue('f', fig, display=False)\n"
        "plt.close(fig)",
        "fig, ax = plt.subplots()\nax.plot([1, 2])\nax.set_title('t', fontsize=7)\ndisplay(fig)\nplt.close(fig)",
        "fig, ax = plt.subplots()\nax.plot([1, 2])\nax.tick_params(labelsize=8)",
    ]]
    NotebookClient(nb, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}).execute()
    found = []
    for cell in nb.cells[1:]:
        (png,) = [base64.b64decode(v) for o in cell.outputs for k, v in o.get("data", {}).items() if "png" in k]
        found.append(png_text(png).get(TEXT_PX_KEY))
    assert found == [f"{_px(s, 100):.2f}" for s in (6, 7, 8)]


def test_apply_outside_ipython_only_sets_the_style():
    with plt.rc_context():
        style.apply()
        assert matplotlib.rcParams["savefig.dpi"] == 110

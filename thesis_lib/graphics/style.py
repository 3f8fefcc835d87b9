"""One matplotlib style for every figure of the book, and the size of a figure's smallest text.

Every PNG the book shows carries the height in pixels of its smallest text in a ``tEXt`` chunk
(key :data:`TEXT_PX_KEY`): :func:`apply` makes IPython turn figures into such PNGs (inline figures,
``display(fig)`` and ``glue(..., fig)`` alike), and :meth:`thesis_lib.lab.results.Recorder.savefig`
writes them. The book's browser test reads the chunk and scales it to the width the page shows the
image at, so that no text of a figure reads smaller than 9 px.
"""

from __future__ import annotations

import base64
import contextlib
import io
import math
import struct
import zlib
from collections.abc import Iterator
from typing import TYPE_CHECKING

from .._optional import require

if TYPE_CHECKING:  # matplotlib is imported by what draws ([plot] extra); COLORS and png_text need none
    from matplotlib.figure import Figure

__all__ = ["apply", "COLORS", "smallest_text_px", "figure_png", "png_text", "TEXT_PX_KEY"]

#: colours by role (data points, first method, second method, highlights, per homology dimension)
COLORS = {
    "points": "#9a9a9a",
    "first": "#c0392b",
    "second": "#2471a3",
    "highlight": "#1e8449",
    "dims": ["#c0392b", "#2471a3", "#1e8449", "#7d3c98"],
}

#: key of the PNG ``tEXt`` chunk holding the smallest text's height in pixels at the natural size
#: (``"none"`` for a figure without text)
TEXT_PX_KEY = "thesis-lab:smallest-text-px"


def apply() -> None:
    """Set the book's matplotlib defaults (sizes, fonts, no time stamps in saved files).

    In an IPython kernel, figures are also turned into PNGs by :func:`figure_png` from then on
    (inline figures, ``display(fig)``, ``myst_nb.glue``), so that each carries its smallest text's
    size.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    """
    mpl = require("matplotlib", extra="plot", purpose="the book's figure style")
    mpl.rcParams.update(
        {
            "figure.figsize": (7.0, 3.6),
            "figure.dpi": 100,
            "savefig.dpi": 110,
            "font.size": 10,
            "axes.titlesize": 11,
            "axes.spines.top": False,
            "axes.spines.right": False,
            "svg.hashsalt": "thesis-lab",
        }
    )
    _register_png_formatter(mpl)


# ---------------------------------------------------------------------------------------------------
# The smallest text of a figure

_recording: list[list[float]] = []  # the lists that drawn text sizes (px) are appended to


def _record(renderer, s: str, prop, ismath) -> None:
    if not _recording or not s or not str(s).strip():
        return
    points = prop.get_size_in_points()
    if ismath is True:  # mathtext: sub- and superscripts are drawn smaller than the text's size
        from matplotlib.mathtext import MathTextParser

        try:
            glyphs = MathTextParser("path").parse(s, 72, prop).glyphs
            points = min((g[1] for g in glyphs), default=points)
        except ValueError:  # not parseable (matplotlib would have failed to draw it)
            pass
    px = float(renderer.points_to_pixels(points))
    for sizes in _recording:
        sizes.append(px)


@contextlib.contextmanager
def _recording_text() -> Iterator[list[float]]:
    """Record the size in pixels of every non-empty text the Agg renderer draws inside the block."""
    from matplotlib.backends.backend_agg import RendererAgg

    sizes: list[float] = []
    draw_text, draw_tex = RendererAgg.draw_text, RendererAgg.draw_tex

    def recording_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        _record(self, s, prop, ismath)
        return draw_text(self, gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)

    def recording_tex(self, gc, x, y, s, prop, angle, *, mtext=None):
        _record(self, s, prop, "TeX")
        return draw_tex(self, gc, x, y, s, prop, angle, mtext=mtext)

    patched = RendererAgg.draw_text is draw_text and not _recording
    if patched:
        RendererAgg.draw_text, RendererAgg.draw_tex = recording_text, recording_tex
    _recording.append(sizes)
    try:
        yield sizes
    finally:
        _recording.remove(sizes)
        if patched:
            RendererAgg.draw_text, RendererAgg.draw_tex = draw_text, draw_tex


def _render(fig: Figure, dpi: float | None, bbox_inches: str | None, metadata: dict | None) -> tuple[bytes, float]:
    """The PNG of ``fig`` as saved with these options, and its smallest text's height in pixels."""
    buf = io.BytesIO()
    if fig.canvas is None:  # pragma: no cover - a Figure always has a canvas since matplotlib 3.6
        from matplotlib.backend_bases import FigureCanvasBase

        FigureCanvasBase(fig)
    with _recording_text() as sizes:
        fig.canvas.print_figure(
            buf, format="png", dpi=fig.dpi if dpi is None else dpi, bbox_inches=bbox_inches,
            facecolor=fig.get_facecolor(), edgecolor=fig.get_edgecolor(),
            metadata={"Software": None, **(metadata or {})},
        )
    return buf.getvalue(), min(sizes, default=math.inf)


def _png_size(png: bytes) -> tuple[int, int]:
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        raise ValueError("not a PNG image")
    return struct.unpack(">II", png[16:24])


def smallest_text_px(fig: Figure, *, rendered_width_px: float | None = None, dpi: float | None = None,
                     bbox_inches: str | None = "tight") -> float:
    """The height in pixels of the smallest visible, non-empty text of a matplotlib figure.

    Thesis: none (a rule of the book: every text of a figure renders at 9 px or more).

    The figure is rendered as its PNG would be saved, and every text the renderer draws is measured:
    tick labels, axis labels, titles, legends, colour bars, annotations, texts placed by hand. The
    height of a text is its font size in pixels (points × dpi / 72, what CSS calls ``font-size``);
    for mathtext (``$…$``) it is the size of its smallest glyph (a sub- or superscript is 0.7 of
    the text's size). Texts that are not drawn (invisible, empty, of an axis turned off) do not count.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    rendered_width_px : float, optional
        The width in CSS pixels the image is shown at; by default the PNG's natural width.
    dpi : float, optional
        The resolution of the PNG; by default ``fig.dpi`` (what a notebook shows).
    bbox_inches : str or None, default "tight"
        As for ``savefig`` (the notebook display and ``Recorder.savefig`` save tight).

    Returns
    -------
    float
        The smallest text's height in pixels at the PNG's natural size, or scaled by
        ``rendered_width_px`` / the PNG's width when ``rendered_width_px`` is given; ``inf`` when
        the figure draws no text.

    Raises
    ------
    ValueError
        If ``rendered_width_px`` is not positive.
    """
    if rendered_width_px is not None and not rendered_width_px > 0:
        raise ValueError(f"rendered_width_px must be positive, got {rendered_width_px!r}")
    png, px = _render(fig, dpi, bbox_inches, None)
    if rendered_width_px is not None:
        px *= rendered_width_px / _png_size(png)[0]
    return px


def _insert_text_chunk(png: bytes, key: str, value: str) -> bytes:
    """``png`` with a ``tEXt`` chunk ``key`` = ``value`` before its first IDAT chunk."""
    _png_size(png)
    body = key.encode("latin-1") + b"\0" + value.encode("latin-1")
    chunk = struct.pack(">I", len(body)) + b"tEXt" + body + struct.pack(">I", zlib.crc32(b"tEXt" + body))
    at = png.index(b"IDAT") - 4
    return png[:at] + chunk + png[at:]


def png_text(png: bytes) -> dict[str, str]:
    """The ``tEXt`` chunks of a PNG image.

    Thesis: none (reads back what :func:`figure_png` wrote).

    Parameters
    ----------
    png : bytes
        The PNG file's bytes.

    Returns
    -------
    dict of str to str
        Keyword → text of every ``tEXt`` chunk, in file order.

    Raises
    ------
    ValueError
        If ``png`` is not a PNG image.
    """
    _png_size(png)
    out, at = {}, 8
    while at + 8 <= len(png):
        length, kind = struct.unpack(">I4s", png[at:at + 8])
        if kind == b"tEXt":
            key, _, value = png[at + 8:at + 8 + length].partition(b"\0")
            out[key.decode("latin-1")] = value.decode("latin-1")
        if kind == b"IEND":
            break
        at += 12 + length
    return out


def figure_png(fig: Figure, *, dpi: float | None = None, bbox_inches: str | None = "tight") -> bytes:
    """The figure as PNG bytes that carry its smallest text's height (the book's figures).

    Thesis: none (how the book's figures are saved).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    dpi : float, optional
        Resolution; by default ``fig.dpi`` (what a notebook shows).
    bbox_inches : str or None, default "tight"
        As for ``savefig``.

    Returns
    -------
    bytes
        The PNG, with no time stamp and no software version (the same bytes on every run), and a
        ``tEXt`` chunk :data:`TEXT_PX_KEY` holding :func:`smallest_text_px` at the natural size to
        2 decimals (``"none"`` when the figure has no text).
    """
    png, px = _render(fig, dpi, bbox_inches, None)
    return _insert_text_chunk(png, TEXT_PX_KEY, "none" if math.isinf(px) else f"{px:.2f}")


def _png_formatter(fig: Figure) -> str | None:
    if not fig.axes and not fig.lines:  # as IPython: an empty figure shows nothing
        return None
    return base64.b64encode(figure_png(fig)).decode("ascii")


def _register_png_formatter(mpl) -> None:
    """In IPython, show figures through :func:`figure_png` (re-registered before every cell)."""
    try:
        from IPython import get_ipython
    except ImportError:  # pragma: no cover - IPython is a dependency of the book, not of the library
        return
    ip = get_ipython()
    if ip is None:
        return
    # load the inline backend first: matplotlib-inline registers its own PNG formatter when it is
    # imported (which pyplot does on the first figure)
    if "matplotlib_inline" in str(mpl.get_backend()):
        import importlib

        importlib.import_module("matplotlib_inline.backend_inline")

    def register(*_args) -> None:
        from matplotlib.figure import Figure

        ip.display_formatter.formatters["image/png"].for_type(Figure, _png_formatter)

    register()
    if not getattr(ip, "_thesis_lab_png", False):
        ip.events.register("pre_run_cell", register)
        ip._thesis_lab_png = True

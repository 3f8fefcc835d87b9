"""The one Markdown table writer of the project (sweep tables, the report, benchmark tables).

A cell is written as text: floats with a given number of significant digits, ``None`` as empty, and
``|`` escaped so that a note or a parameter value can never break the table.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

__all__ = ["cell", "header", "row", "markdown_table"]


def cell(value: object, digits: int = 6) -> str:
    """One cell's text: floats to ``digits`` significant digits (``:g``), ``None`` empty, ``|`` escaped.

    Parameters
    ----------
    value : object
        The cell's value; anything other than a float or None is written with ``str``.
    digits : int, default 6
        Significant digits of a float value.

    Returns
    -------
    str
        The text, with ``|`` escaped as ``\\|`` and newlines replaced by spaces.
    """
    if value is None:
        text = ""
    elif isinstance(value, float):
        text = f"{value:.{digits}g}"
    else:
        text = str(value)
    return text.replace("|", "\\|").replace("\n", " ")


def header(titles: Sequence[object]) -> str:
    """The two header lines of a Markdown table (no final newline).

    Parameters
    ----------
    titles : sequence of object
        The column titles, each written as a cell (default ``digits``).

    Returns
    -------
    str
        The title line and the ``|---|`` separator line, joined by a newline.
    """
    return "| " + " | ".join(cell(t) for t in titles) + " |\n|" + "---|" * len(titles)


def row(cells: Sequence[object], digits: int = 6) -> str:
    """One line of a Markdown table (no final newline); strings are taken as already formatted.

    Parameters
    ----------
    cells : sequence of object
        The cells of the line, each written by ``cell``.
    digits : int, default 6
        Significant digits of float cells.

    Returns
    -------
    str
        The line, ``| a | b | ... |``.
    """
    return "| " + " | ".join(cell(c, digits) for c in cells) + " |"


def markdown_table(titles: Sequence[object], rows: Iterable[Sequence[object]], digits: int = 6) -> str:
    """A whole Markdown table, ending with a newline.

    Parameters
    ----------
    titles : sequence of object
        The column titles.
    rows : iterable of sequence of object
        One sequence of cells per line, as many as ``titles``.
    digits : int, default 6
        Significant digits of float cells.

    Returns
    -------
    str
        The header lines, then one line per row, each ending with a newline.

    Raises
    ------
    ValueError
        If a row has not as many cells as there are titles.
    """
    lines = [header(titles)]
    for cells in rows:
        if len(cells) != len(titles):
            raise ValueError(f"a table row has {len(cells)} cells for {len(titles)} columns: {list(cells)!r}")
        lines.append(row(cells, digits))
    return "\n".join(lines) + "\n"

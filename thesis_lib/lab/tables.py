"""The one Markdown table writer of the project (sweep tables, the report, benchmark tables).

A cell is written as text: floats with a given number of significant digits, ``None`` as empty, and
``|`` escaped so that a note or a parameter value can never break the table.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

__all__ = ["cell", "header", "row", "markdown_table"]


def cell(value: object, digits: int = 6) -> str:
    """One cell's text: floats to ``digits`` significant digits (``:g``), ``None`` empty, ``|`` escaped."""
    if value is None:
        text = ""
    elif isinstance(value, float):
        text = f"{value:.{digits}g}"
    else:
        text = str(value)
    return text.replace("|", "\\|").replace("\n", " ")


def header(titles: Sequence[object]) -> str:
    """The two header lines of a Markdown table (no final newline)."""
    return "| " + " | ".join(cell(t) for t in titles) + " |\n|" + "---|" * len(titles)


def row(cells: Sequence[object], digits: int = 6) -> str:
    """One line of a Markdown table (no final newline); strings are taken as already formatted."""
    return "| " + " | ".join(cell(c, digits) for c in cells) + " |"


def markdown_table(titles: Sequence[object], rows: Iterable[Sequence[object]], digits: int = 6) -> str:
    """A whole Markdown table, ending with a newline.

    Parameters
    ----------
    titles : column titles.
    rows : one sequence of cells per line, as many as ``titles``.
    digits : significant digits of float cells.
    """
    lines = [header(titles)]
    for cells in rows:
        if len(cells) != len(titles):
            raise ValueError(f"a table row has {len(cells)} cells for {len(titles)} columns: {list(cells)!r}")
        lines.append(row(cells, digits))
    return "\n".join(lines) + "\n"

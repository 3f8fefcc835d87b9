"""The one Markdown table writer of the project (sweep tables, the report, benchmark tables, the
book's tables: :func:`show_table` displays one in a notebook).

A cell is written as text: floats with a given number of significant digits, ``None`` as empty, and
``|`` escaped so that a note or a parameter value can never break the table.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

__all__ = ["cell", "header", "row", "markdown_table", "labelled_grid", "show_table"]


def cell(value: object, *, digits: int = 6) -> str:
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


def row(cells: Sequence[object], *, digits: int = 6) -> str:
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
    return "| " + " | ".join(cell(c, digits=digits) for c in cells) + " |"


def markdown_table(titles: Sequence[object], rows: Iterable[Sequence[object]], *, digits: int = 6) -> str:
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
        lines.append(row(cells, digits=digits))
    return "\n".join(lines) + "\n"


def labelled_grid(values: Sequence[Sequence[object]], *, rows: Iterable[object], columns: Iterable[object],
                  row_label: str = "{}", column_label: str = "{}", corner: str = "") -> list[list[object]]:
    """A grid of values as table rows, each row headed by its key and each column by its key.

    Thesis: Definition 2.23 and Theorem 2.37 (the tables of β_p^{l,k} over a grid of l and k).

    Parameters
    ----------
    values : sequence of sequence of object
        ``values[i][j]`` belongs to the i-th row key and the j-th column key.
    rows : iterable of object
        The row keys, each written with ``row_label.format(key)``.
    columns : iterable of object
        The column keys, each written with ``column_label.format(key)``.
    row_label : str, default "{}"
        A ``str.format`` pattern with one field for a row key.
    column_label : str, default "{}"
        A ``str.format`` pattern with one field for a column key.
    corner : str, default ""
        The cell above the row keys.

    Returns
    -------
    list of list
        The header ``[corner, column labels...]``, then ``[row label, values[i]...]`` for each row.

    Raises
    ------
    ValueError
        If ``values`` has not one row per row key and one value per column key.

    Examples
    --------
    >>> labelled_grid([[1, 2], [3, 4]], rows=[0, 1], columns=[0.5, 1], row_label="l = {}", column_label="{:g}")
    [['', '0.5', '1'], ['l = 0', 1, 2], ['l = 1', 3, 4]]
    """
    row_keys, column_keys = list(rows), list(columns)
    grid = [list(line) for line in values]
    if len(grid) != len(row_keys) or any(len(line) != len(column_keys) for line in grid):
        raise ValueError(f"values must be {len(row_keys)} rows of {len(column_keys)} values, one per key")
    header: list[object] = [corner, *(column_label.format(key) for key in column_keys)]
    return [header] + [[row_label.format(key), *line] for key, line in zip(row_keys, grid)]


def show_table(rows: Sequence[Sequence[object]], *, digits: int = 6) -> None:
    """Display rows as a Markdown table in a notebook (the book renders it as MyST).

    Thesis: none (the book's tables; first row the header, as :func:`labelled_grid` and
    :func:`~thesis_lib.persistence.trace_matrices` return them).

    Parameters
    ----------
    rows : sequence of sequence of object
        The header first, then the lines; each cell is written by :func:`cell`.
    digits : int, default 6
        Significant digits of float cells.

    Raises
    ------
    ValueError
        If ``rows`` is empty or a line has not as many cells as the header.

    Examples
    --------
    >>> show_table([["n", "name"], [1, "a"]])  # in a notebook: the rendered table
    <IPython.core.display.Markdown object>
    """
    from IPython.display import Markdown, display

    if not rows:
        raise ValueError("a table needs at least its header row")
    display(Markdown(markdown_table(rows[0], rows[1:], digits=digits).rstrip("\n")))

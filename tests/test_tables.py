"""The book's tables (thesis_lib.lab.tables): a labelled grid as rows, and rows shown as a Markdown table."""

from __future__ import annotations

import doctest
import re

import pytest
from IPython.display import Markdown

from thesis_lib.lab import tables
from thesis_lib.lab.tables import labelled_grid, show_table


def shown(monkeypatch, rows, **kw):
    """The Markdown that show_table displays."""
    seen = []
    monkeypatch.setattr("IPython.display.display", lambda *objs: seen.extend(objs))
    show_table(rows, **kw)
    assert len(seen) == 1 and isinstance(seen[0], Markdown)
    return seen[0].data


def parse(markdown):
    """Cells of a Markdown table, split on unescaped pipes and unescaped back."""
    lines = markdown.split("\n")
    assert re.fullmatch(r"\|(---\|)+", lines[1])
    cells = [re.split(r"(?<!\\)\|", line)[1:-1] for line in lines[:1] + lines[2:]]
    return [[c.strip().replace("\\|", "|") for c in line] for line in cells]


def test_show_table_round_trips_the_cells(monkeypatch):
    rows = [["", "$k = 0$", "note"], ["$\\beta_1^{0,k}$", 3, "a | b"], ["x", 2.5, None]]
    text = shown(monkeypatch, rows)
    assert not text.endswith("\n")
    assert parse(text) == [["", "$k = 0$", "note"], ["$\\beta_1^{0,k}$", "3", "a | b"], ["x", "2.5", ""]]
    assert parse(shown(monkeypatch, [["v"], [1 / 3]], digits=2)) == [["v"], ["0.33"]]


def test_show_table_refuses_bad_rows(monkeypatch):
    with pytest.raises(ValueError, match="header"):
        shown(monkeypatch, [])
    with pytest.raises(ValueError, match="2 cells for 3 columns"):
        shown(monkeypatch, [["a", "b", "c"], [1, 2]])


def test_labelled_grid_places_each_value_under_its_keys():
    values = [[10 * i + j for j in range(3)] for i in range(2)]
    rows = labelled_grid(values, rows=[0.25, 0.5], columns=range(3), corner="$l$", row_label="{:.3f}",
                         column_label="$\\beta^{{l,{}}}$")
    assert rows[0] == ["$l$", "$\\beta^{l,0}$", "$\\beta^{l,1}$", "$\\beta^{l,2}$"]
    assert [r[0] for r in rows[1:]] == ["0.250", "0.500"]
    assert all(rows[i + 1][j + 1] == 10 * i + j for i in range(2) for j in range(3))


def test_labelled_grid_refuses_a_grid_of_another_shape():
    with pytest.raises(ValueError, match="2 rows of 3 values"):
        labelled_grid([[1, 2, 3]], rows=[0, 1], columns=[0, 1, 2])
    with pytest.raises(ValueError, match="1 rows of 2 values"):
        labelled_grid([[1, 2, 3]], rows=[0], columns=[0, 1])


def test_docstring_examples_run():
    result = doctest.testmod(tables)
    assert result.attempted >= 2 and result.failed == 0

"""A book page reads like the thesis: prose, one short call into thesis_lib, one figure.

The rule for the code cells of a notebook (CONVENTIONS.md, "Notebooks"): no ``def``, ``lambda`` or
``class``; no loop (``for``/``while`` statement or comprehension) longer than one line; a median of at
most :data:`MAX_MEDIAN_LINES` code lines per cell (not blank, not a comment, not part of an import);
no private import (``thesis_lib._x``, ``from ... import _name``).  Cells tagged ``parameters`` are
skipped, and IPython magics (``%...``, ``!...``) are not Python.  Every notebook of ``book/`` and
``experiments/`` keeps to it (:data:`NOTEBOOKS`), a new one included.
"""

from __future__ import annotations

import ast
import statistics
from pathlib import Path

import nbformat
import pytest

from thesis_lib.lab.paths import project_root

ROOT = project_root()
#: every notebook of the book and of the experiments
NOTEBOOKS = sorted(str(p.relative_to(ROOT)) for folder in ("book", "experiments")
                   for p in (ROOT / folder).glob("*.ipynb"))
#: the largest median number of code lines per code cell
MAX_MEDIAN_LINES = 7

DEFINITIONS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)
LOOPS = (ast.For, ast.AsyncFor, ast.While, ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


def _python(source: str) -> str:
    """The cell's source with IPython magic and shell lines blanked (line numbers kept)."""
    return "\n".join("" if line.lstrip().startswith(("%", "!")) else line for line in source.splitlines())


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def _import_lines(tree: ast.Module) -> set[int]:
    lines: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            lines.update(range(node.lineno, node.end_lineno + 1))
    return lines


def code_lines(source: str) -> int:
    """Lines of a cell that are code: not blank, not only a comment, not part of an import statement."""
    python = _python(source)
    imports = _import_lines(ast.parse(python))
    return sum(1 for number, line in enumerate(python.splitlines(), start=1)
               if line.strip() and not line.strip().startswith("#") and number not in imports)


def _cell_violations(tree: ast.Module, where: str) -> list[str]:
    found = []
    for node in ast.walk(tree):
        if isinstance(node, DEFINITIONS):
            kind = {ast.Lambda: "lambda", ast.ClassDef: "class"}.get(type(node), "def")
            found.append(f"{where}, line {node.lineno}: {kind} (a function belongs in thesis_lib)")
        elif isinstance(node, LOOPS) and node.end_lineno > node.lineno:
            found.append(f"{where}, line {node.lineno}: a loop of {node.end_lineno - node.lineno + 1} lines")
        elif isinstance(node, ast.Import):
            found += [f"{where}, line {node.lineno}: private import {a.name}" for a in node.names
                      if any(_private(part) for part in a.name.split("."))]
        elif isinstance(node, ast.ImportFrom):
            module = node.module or ""
            if any(_private(part) for part in module.split(".")):
                found.append(f"{where}, line {node.lineno}: private import from {module}")
            found += [f"{where}, line {node.lineno}: private import {a.name} from {module}" for a in node.names
                      if _private(a.name)]
    return found


def style_violations(path: str | Path) -> list[str]:
    """What in a notebook's code cells breaks the rule, one message each (empty: it keeps to it).

    Parameters
    ----------
    path : str or Path
        The notebook.

    Returns
    -------
    list of str
        ``"cell 7, line 2: def ..."``, ``"cell 9, line 1: a loop of 3 lines"``, ``"... private import ..."``,
        and ``"median of ... code lines per cell ..."`` (cells numbered as in the notebook, from 0).
    """
    nb = nbformat.read(path, as_version=4)
    found: list[str] = []
    counts: list[int] = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code" or "parameters" in cell.metadata.get("tags", []):
            continue
        source = _python(cell.source)
        try:
            tree = ast.parse(source)
        except SyntaxError as exc:
            found.append(f"cell {i}, line {exc.lineno}: not Python ({exc.msg})")
            continue
        found += _cell_violations(tree, f"cell {i}")
        counts.append(code_lines(cell.source))
    if counts and statistics.median(counts) > MAX_MEDIAN_LINES:
        found.append(f"median of {statistics.median(counts):g} code lines per cell (at most {MAX_MEDIAN_LINES}); "
                     f"cells have {counts}")
    return found


def test_every_notebook_is_found():
    assert "book/intro.ipynb" in NOTEBOOKS and "experiments/two-circles.ipynb" in NOTEBOOKS and len(NOTEBOOKS) >= 20


@pytest.mark.parametrize("name", NOTEBOOKS)
def test_notebook_keeps_to_the_rule(name):
    assert style_violations(ROOT / name) == []


def _notebook(tmp_path: Path, *sources: str, tags: dict[int, list[str]] | None = None) -> Path:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("# A page")]
    for k, source in enumerate(sources):
        cell = nbformat.v4.new_code_cell(source)
        cell.metadata["tags"] = (tags or {}).get(k, [])
        nb.cells.append(cell)
    path = tmp_path / "page.ipynb"
    nbformat.write(nb, path)
    return path


SHORT = "from thesis_lib import datasets\nK = datasets.example_filtration()\nprint(K)"


def test_a_conforming_notebook_passes(tmp_path):
    path = _notebook(tmp_path, SHORT, "%matplotlib inline\nx = [v for v in range(3)]  # one line\n", SHORT)
    assert style_violations(path) == []


@pytest.mark.parametrize("source, expected", [
    ("def f(x):\n    return x\n", "cell 1, line 1: def"),
    ("f = lambda x: x + 1\n", "cell 1, line 1: lambda"),
    ("class A:\n    pass\n", "cell 1, line 1: class"),
    ("for v in range(3):\n    print(v)\n", "cell 1, line 1: a loop of 2 lines"),
    ("while False:\n    pass\n", "cell 1, line 1: a loop of 2 lines"),
    ("x = [v\n     for v in range(3)]\n", "cell 1, line 1: a loop of 2 lines"),
    ("from thesis_lib._validate import check_int\n", "cell 1, line 1: private import from thesis_lib._validate"),
    ("import thesis_lib._core.flag\n", "cell 1, line 1: private import thesis_lib._core.flag"),
    ("from thesis_lib.persistence.trace import _passes\n", "cell 1, line 1: private import _passes"),
])
def test_each_kind_of_violation_is_reported(tmp_path, source, expected):
    found = style_violations(_notebook(tmp_path, source, SHORT, SHORT))
    assert len(found) == 1 and found[0].startswith(expected), found


def test_a_long_median_is_reported_and_imports_comments_and_blanks_do_not_count(tmp_path):
    long = "\n".join(f"x{k} = {k}" for k in range(8))
    padded = "import math\nfrom thesis_lib import (\n    datasets,\n)\n\n# a comment\n" + "\n".join(
        f"y{k} = {k}" for k in range(7))
    assert code_lines(padded) == 7
    assert style_violations(_notebook(tmp_path, padded, padded, long)) == []
    found = style_violations(_notebook(tmp_path, long, long, padded))
    assert len(found) == 1 and found[0].startswith("median of 8 code lines"), found


def test_parameters_cells_are_skipped(tmp_path):
    params = "def not_checked():\n    pass\n" + "\n".join(f"p{k} = {k}  # a parameter" for k in range(20))
    assert style_violations(_notebook(tmp_path, params, SHORT, tags={0: ["parameters"]})) == []
    assert style_violations(_notebook(tmp_path, params, SHORT)) != []

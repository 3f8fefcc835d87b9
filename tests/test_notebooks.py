"""Every notebook is stored executed with outputs, and every experiment has a valid parameters cell.

nbval (run by `make test`) re-executes the notebooks and compares outputs; it would pass a notebook
stored without outputs, so this file checks that they are there.
"""

from __future__ import annotations

import nbformat
import pytest
import yaml

from thesis_lib.lab import runner
from thesis_lib.lab.paths import project_root

ROOT = project_root()
NOTEBOOKS = sorted((ROOT / "book").glob("*.ipynb")) + sorted((ROOT / "experiments").glob("*.ipynb"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_is_stored_executed_with_outputs(path):
    nb = nbformat.read(path, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code" and c.source.strip()]
    assert code, "no code cells"
    unexecuted = [i for i, c in enumerate(code) if c.execution_count is None]
    assert not unexecuted, f"code cells {unexecuted} were never executed"
    counts = [c.execution_count for c in code]
    assert counts == list(range(1, len(code) + 1)), "cells were not executed once, top to bottom"
    assert any(c.outputs for c in code), "stored without outputs"
    errors = [o for c in code for o in c.outputs if o.get("output_type") == "error"]
    assert not errors, "stored with an error output"
    text = nbformat.writes(nb)
    assert str(ROOT) not in text, "outputs name this checkout's path (they would differ on a clean clone)"


@pytest.mark.parametrize("name", runner.list_experiments())
def test_experiment_parameters_cell(name):
    params = runner.experiment_parameters(name)
    assert params.get("output_dir") == "", "experiments take output_dir = '' (the stored default run)"
    nb = nbformat.read(ROOT / "experiments" / f"{name}.ipynb", as_version=4)
    cell = next(c for c in nb.cells if "parameters" in c.metadata.get("tags", []))
    for line in cell.source.splitlines():
        if "#" in line:
            assert "=" not in line.split("#", 1)[1], f"papermill cannot parse '=' in a comment: {line}"
        elif line.strip():
            pytest.fail(f"parameter without a comment saying what it is: {line}")


def test_every_book_notebook_is_in_the_toc():
    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text())
    listed = {toc["root"]}
    for part in toc.get("parts", []):
        for chapter in part.get("chapters", []):
            listed.add(chapter["file"])
            listed |= {s["file"] for s in chapter.get("sections", [])}
    for path in NOTEBOOKS:
        rel = path.relative_to(ROOT / "book" if path.parent.name == "book" else ROOT).with_suffix("")
        assert str(rel) in listed, f"{rel} is not in book/_toc.yml"

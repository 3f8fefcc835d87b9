"""The experiment runner: parameter validation, runs, sweeps (resume, failures, table), store."""

from __future__ import annotations

import csv
import json

import nbformat
import pytest

from thesis_lib.lab import cli, runner
from thesis_lib.lab.results import DEFAULT_RUN_ENV
from thesis_lib.lab.runner import ParameterError

TOY_PARAMETERS = """\
n = 3  # an int
x = 0.5  # a float
label = "a"  # a string
flag = False  # a bool
fail = False  # make the notebook raise
output_dir = ""  # set by the runner
"""

TOY_BODY = """\
from thesis_lib.lab.results import Recorder
rec = Recorder("toy", output_dir)
rec.record(square=n * n, x=x, flag=flag, label_length=len(label))
assert not fail, "asked to fail"
"""


@pytest.fixture
def root(tmp_path, monkeypatch):
    """A throw-away compendium root with one fast experiment, ``toy``."""
    monkeypatch.setenv("THESIS_LAB_ROOT", str(tmp_path))
    (tmp_path / "experiments").mkdir()
    nb = nbformat.v4.new_notebook()
    params = nbformat.v4.new_code_cell(TOY_PARAMETERS)
    params.metadata["tags"] = ["parameters"]
    nb.cells = [nbformat.v4.new_markdown_cell("# toy"), params, nbformat.v4.new_code_cell(TOY_BODY)]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, tmp_path / "experiments" / "toy.ipynb")
    return tmp_path


def test_parameters_are_read_from_the_tagged_cell(root):
    assert runner.experiment_parameters("toy") == {
        "n": 3, "x": 0.5, "label": "a", "flag": False, "fail": False, "output_dir": ""
    }


def test_strings_are_converted_to_the_default_type(root):
    params = runner.resolve_parameters("toy", {"n": "7", "x": "2", "label": "b", "flag": "true"})
    assert params == {"n": 7, "x": 2.0, "label": "b", "flag": True, "fail": False}


@pytest.mark.parametrize(
    "overrides, message",
    [
        ({"n": "1.5"}, "parameter 'n' expects int"),
        ({"x": "abc"}, "parameter 'x' expects float"),
        ({"flag": "maybe"}, "parameter 'flag' expects bool"),
        ({"n": 2.0}, "parameter 'n' expects int"),
        ({"label": 3}, "parameter 'label' expects str"),
        ({"nn": 1}, "has no parameter 'nn'; its parameters are: n, x, label, flag, fail"),
        ({"output_dir": "/tmp"}, "set by the runner"),
    ],
)
def test_bad_parameters_are_refused_with_a_clear_message(root, overrides, message):
    with pytest.raises(ParameterError, match=message.replace("(", r"\(")):
        runner.resolve_parameters("toy", overrides)


def test_unknown_experiment_names_the_known_ones(root):
    with pytest.raises(ParameterError, match="unknown experiment 'nope'; known experiments: toy"):
        runner.resolve_parameters("nope")


def test_bad_parameters_never_start_a_kernel(root, monkeypatch):
    import papermill

    monkeypatch.setattr(papermill, "execute_notebook", lambda *a, **k: pytest.fail("a kernel started"))
    with pytest.raises(ParameterError):
        runner.run("toy", {"n": "x"})
    with pytest.raises(ParameterError):
        runner.sweep("toy", {"n": ["1", "oops"]}, progress=False)


def test_cli_reports_bad_parameters_with_exit_code_2(root, capsys):
    assert cli.main(["run", "toy", "-p", "n", "1.5"]) == 2
    assert "expects int" in capsys.readouterr().err


def test_run_writes_results_into_a_folder_named_by_the_parameters(root):
    result = runner.run("toy", {"n": "4"})
    assert result.status == "ok"
    assert result.results == {"square": 16, "x": 0.5, "flag": 0, "label_length": 1}
    params = runner.resolve_parameters("toy", {"n": 4})
    assert result.path == root / "runs" / "toy" / runner.run_hash(params)
    assert json.loads((result.path / "params.json").read_text()) == params
    assert (result.path / "toy.ipynb").is_file() and (result.path / "complete.json").is_file()
    again = runner.run("toy", {"n": 4})
    assert again.status == "skipped" and again.results == result.results


def test_default_parameters_given_explicitly_hash_like_defaults(root):
    assert runner.run_hash(runner.resolve_parameters("toy", {"n": "3"})) == runner.run_hash(
        runner.resolve_parameters("toy")
    )


def test_sweep_resumes_keeps_going_past_failures_and_writes_a_table(root):
    runs, table = runner.sweep("toy", {"n": [1, 2], "fail": [False, True]}, progress=False)
    assert [r.status for r in runs] == ["ok", "failed", "ok", "failed"]
    assert "asked to fail" in runs[1].error
    rows = list(csv.DictReader(table.open()))
    assert [(r["n"], r["fail"], r["status"]) for r in rows] == [
        ("1", "False", "ok"), ("1", "True", "failed"), ("2", "False", "ok"), ("2", "True", "failed")
    ]
    assert rows[2]["square"] == "4"
    md = table.with_suffix(".md").read_text()
    assert md.startswith("`thesis-lab sweep toy -p n 1 2 -p fail False True`\n\n| n | fail | status |")
    assert runner.stored_sweeps("toy") == []
    runs2, _ = runner.sweep("toy", {"n": [1, 2], "fail": [False, True]}, progress=False)
    assert [r.status for r in runs2] == ["skipped", "failed", "skipped", "failed"]


def test_kept_sweeps_are_stored_with_the_default_run(root):
    runner.sweep("toy", {"n": [2]}, progress=False, keep=True)
    (table,) = runner.stored_sweeps("toy")
    assert "| 2 | ok |" in table
    (narrow,) = runner.stored_sweeps("toy", ["n", "square"])
    assert narrow.splitlines()[2:] == ["| n | square |", "|---|---|", "| 2 | 4 |"]
    with pytest.raises(ValueError, match="has no columns"):
        runner.stored_sweeps("toy", ["nothing"])


def test_sweep_in_parallel_gives_the_same_table(root):
    _, serial = runner.sweep("toy", {"n": [5, 6]}, progress=False)
    serial_text = serial.read_text()
    for path in (root / "runs" / "toy").glob("*/complete.json"):
        path.unlink()
    _, parallel = runner.sweep("toy", {"n": [5, 6]}, jobs=2, progress=False)
    assert parallel.read_text() == serial_text


def test_cli_sweep_exit_code_reports_failures(root, capsys):
    assert cli.main(["sweep", "toy", "-q", "-p", "fail", "true"]) == 1
    assert "failed" in capsys.readouterr().err


def test_store_executes_in_place_with_defaults(root, monkeypatch, tmp_path):
    monkeypatch.setenv(DEFAULT_RUN_ENV, str(tmp_path / "elsewhere"))  # storing is never redirected
    path = runner.store("toy")
    nb = nbformat.read(path, as_version=4)
    assert all(c.execution_count for c in nb.cells if c.cell_type == "code")
    assert json.loads((root / "experiments" / "results" / "toy" / "results.json").read_text())["square"] == 9

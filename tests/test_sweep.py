"""Sweeps on this machine: grid, resume, failures, tables, duplicates, shards and collect, list values,
self-contained runs on any executor (data by bytes, outputs bounded)."""

from __future__ import annotations

import concurrent.futures as cf
import csv

import pytest
from lab_helpers import (
    cli,
    root,  # noqa: F401 (the project fixture)
    table_rows,
)

from thesis_lib.lab import cli as lab_cli
from thesis_lib.lab import sweep as lab_sweep
from thesis_lib.lab.experiments import ParameterError
from thesis_lib.lab.sweep import collect, expand_grid, parse_shard, stored_sweeps, sweep


def test_sweep_resumes_keeps_going_past_failures_and_writes_a_table(root):
    runs, table = sweep("toy", {"n": [1, 2], "fail": [False, True]}, jobs=2, progress=False)
    assert [r.status for r in runs] == ["ok", "failed", "ok", "failed"]
    assert "asked to fail" in runs[1].error
    rows = list(csv.DictReader(table.open()))
    assert [(r["n"], r["fail"], r["status"]) for r in rows] == [
        ("1", "False", "ok"), ("1", "True", "failed"), ("2", "False", "ok"), ("2", "True", "failed")
    ]
    assert rows[2]["square"] == "4" and float(rows[2]["seconds"]) > 0 and rows[2]["worker"]
    assert list(rows[0]) == ["n", "fail", "status", "flag", "label_length", "sizes_sum", "square", "x",
                             "seconds", "worker", "run"]
    md = table.with_suffix(".md").read_text()
    assert md.startswith("`thesis-lab sweep toy -p n 1 2 -p fail False True`\n\n| n | fail | status |")
    assert stored_sweeps("toy") == []
    runs2, table2 = sweep("toy", {"n": [1, 2], "fail": [False, True]}, jobs=2, progress=False)
    assert [r.status for r in runs2] == ["skipped", "failed", "skipped", "failed"]
    assert table_rows(table2) == table_rows(table)  # a resumed sweep's table equals the one-shot table


def test_kept_sweeps_are_stored_with_the_default_run_without_times(root):
    sweep("toy", {"n": [2]}, progress=False, keep=True)
    (table,) = stored_sweeps("toy")
    assert "| 2 | ok |" in table and "seconds" not in table and "worker" not in table
    (narrow,) = stored_sweeps("toy", columns=["n", "square"])
    assert narrow.splitlines()[2:] == ["| n | square |", "|---|---|", "| 2 | 4 |"]
    with pytest.raises(ValueError, match="has no columns"):
        stored_sweeps("toy", columns=["nothing"])


def test_stored_sweeps_for_a_reader_titles_numbers_and_a_note(root):
    sweep("toy", {"n": [2000, 3], "x": [0.123456, 0.5], "fail": [False, True]}, progress=False, keep=True)
    (text,) = stored_sweeps("toy", columns=["n", "x", "square"], titles=["points", "$x$", "n²"], digits=2, note=True)
    lines = text.splitlines()
    assert lines[2:4] == ["| points | $x$ | n² |", "|---|---|---|"]
    assert "| 2,000 | 0.12 | 4,000,000 |" in lines and "| 3 | 0.5 | 9 |" in lines
    assert lines[-1] == "4 of the runs did not finish." and lines[-2] == ""  # fail=True: half of the 8 runs
    (raw,) = stored_sweeps("toy", columns=["n", "x"])
    assert "| 2000 | 0.123456 |" in raw and "did not finish" not in raw
    with pytest.raises(ValueError, match="give columns too"):
        stored_sweeps("toy", digits=2)
    with pytest.raises(ValueError, match="one title per column"):
        stored_sweeps("toy", columns=["n", "x"], titles=["points"])


def test_sweep_in_parallel_gives_the_same_table(root):
    _, serial = sweep("toy", {"n": [5, 6]}, progress=False)
    for path in (root / "runs" / "toy").glob("*/complete.json"):
        path.unlink()
    _, parallel = sweep("toy", {"n": [5, 6]}, jobs=2, progress=False)
    assert table_rows(parallel) == table_rows(serial)


def test_a_result_named_like_a_parameter_gets_its_own_column(root):
    runs, table = sweep("toy", {"x": ["2"]}, progress=False)
    header = table.read_text().splitlines()[0].split(",")
    assert header[:2] == ["x", "status"] and "x (result)" in header and header.count("x") == 1
    assert table_rows(table)[0]["x (result)"] == "2.0"


def test_duplicate_values_run_once(root):
    """Values that are equal after parsing run once (never two runs in the same folder at once)."""
    assert [p["n"] for p in expand_grid("toy", {"n": [1, "1", " 1", 2, 1]})] == [1, 2]
    runs, table = sweep("toy", {"n": ["1", "1", "01"]}, jobs=2, progress=False)
    assert len(runs) == 1 and len(table_rows(table)) == 1
    assert len([p for p in (root / "runs" / "toy").iterdir() if p.name != "sweeps"]) == 1


def test_sweeps_over_list_values(root):
    runs, table = sweep("toy", {"sizes": ["1,2", "[3, 4]", "[1, 2]"]}, progress=False)
    assert [r.params["sizes"] for r in runs] == [[1, 2], [3, 4]]
    assert [r.results["sizes_sum"] for r in runs] == [3, 7]
    assert [row["sizes"] for row in table_rows(table)] == ["1,2", "3,4"]
    with pytest.raises(ParameterError, match="item 'x' is not int"):
        sweep("toy", {"sizes": ["1,x"]}, progress=False)


@pytest.mark.parametrize("text, expected", [("1/2", (1, 2)), ("2/2", (2, 2)), (" 3 / 7 ", (3, 7)), (None, None)])
def test_parse_shard(text, expected):
    assert parse_shard(text) == expected


@pytest.mark.parametrize("text", ["3/2", "0/2", "1/0", "a/b", "1", "", "1/2/3", "-1/2"])
def test_bad_shards_are_refused(text):
    with pytest.raises(ParameterError, match="shard"):
        parse_shard(text)


def test_shards_and_collect_equal_the_one_shot_sweep(root, tmp_path):
    grid = {"n": [1, 2, 3], "x": [0.5]}
    _, whole = sweep("toy", grid, jobs=2, progress=False, root=tmp_path / "one-shot")
    shard_runs = [sweep("toy", grid, jobs=2, progress=False, shard=f"{i}/2")[0] for i in (1, 2)]
    assert [len(r) for r in shard_runs] == [2, 1]
    names = {r.path.name for runs in shard_runs for r in runs}
    assert len(names) == 3  # the shards partition the grid
    rows, table = collect("toy", grid)
    assert [r.status for r in rows] == ["ok"] * 3
    assert table_rows(table) == table_rows(whole)


def test_collect_reports_missing_runs(root, capsys):
    sweep("toy", {"n": [1]}, progress=False)
    rows, table = collect("toy", {"n": [1, 2]})
    assert [r.status for r in rows] == ["ok", "missing"]
    assert [r["status"] for r in table_rows(table)] == ["ok", "missing"]
    assert lab_cli.main(["collect", "toy", "-p", "n", "1", "2"]) == 1
    err = capsys.readouterr().err
    assert "missing: {" in err and "1 missing" in err


def test_self_contained_runs_on_any_executor_get_data_by_bytes(root, tmp_path, monkeypatch):
    """A run given to an executor carries its notebook and data; the worker needs no project."""
    monkeypatch.setenv("THESIS_LAB_SHARED", str(tmp_path / "nowhere"))
    with cf.ThreadPoolExecutor(1) as pool:
        runs, _ = sweep("toy", {"data_name": ["toy-data"]}, executor=pool, progress=False)
    assert runs[0].status == "ok", runs[0].error
    assert runs[0].results["data_bytes"] == len(b"ATOM      1  N   GLY A   1\n")
    bundle = lab_sweep.data_bundle()
    assert list(bundle["files"]) == ["x/toy.pdb"]


def test_a_run_output_over_the_limit_is_refused_clearly(root):
    with cf.ThreadPoolExecutor(1) as pool:
        runs, _ = sweep("toy", {"output_mb": [2.0]}, executor=pool, progress=False, max_output_mb=1.0)
    assert runs[0].status == "failed"
    assert "over the limit of 1 MB" in runs[0].error and "filler.bin" in runs[0].error
    assert (runs[0].path / "error.txt").read_text().startswith("the run's outputs are 2.0 MB")


def test_cli_sweep_exit_code_reports_failures(root):
    proc = cli(root, "sweep", "toy", "-q", "-p", "fail", "true")
    assert proc.returncode == 1 and "failed: {" in proc.stderr
    assert proc.stdout.startswith("`thesis-lab sweep toy -p fail True`")

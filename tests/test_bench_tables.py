"""The performance page's tables: readable headers with units (bench.header, bench.markdown)."""

from __future__ import annotations

import json

from thesis_lib.lab import bench


def test_headers_say_the_tool_and_the_unit():
    assert bench.header("ours_s") == "ours (s)"
    assert bench.header("ripser_s") == "ripser.py (s)"
    assert bench.header("ratio_ripser") == "ours ÷ ripser.py"
    assert bench.header("ratio_gph") == "ours ÷ giotto-ph"
    assert bench.header("gph_mb") == "giotto-ph peak (MB)"
    assert bench.header("ours_baseline_mb") == "ours baseline (MB)"
    assert bench.header("n_points") == "points"
    assert bench.header("ratio") == "ours ÷ reference"
    assert bench.header("held_out") == "held out"


def test_markdown_headers_are_opt_in(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    (tmp_path / "benchmarks" / "results").mkdir(parents=True)
    rows = [{"case": "a", "ours_s": 0.5, "ripser_s": 1.0, "ratio_ripser": 0.5, "ours_mb": 3.0}]
    (tmp_path / "benchmarks" / "results" / "x.json").write_text(json.dumps(rows))
    columns = ["case", "ours_s", "ripser_s", "ratio_ripser", "ours_mb"]
    header = "| case | ours_s | ripser_s | ratio_ripser | ours_mb |"
    assert bench.markdown("x", columns=columns).splitlines()[0] == header
    assert bench.markdown("x", columns=columns, headers=True).splitlines()[0] == (
        "| case | ours (s) | ripser.py (s) | ours ÷ ripser.py | ours peak (MB) |")
    assert bench.markdown("x", columns=columns, headers={"ours_mb": "memory (MB)"}).splitlines()[0].endswith(
        "| memory (MB) |")
    assert bench.markdown("x", columns=columns, headers=True).splitlines()[2] == "| a | 0.5 | 1 | 0.5 | 3 |"


def test_markdown_rows_by_values_and_digits(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    (tmp_path / "benchmarks" / "results").mkdir(parents=True)
    rows = [{"case": "a", "topic": "t1", "ours_s": 0.123456}, {"case": "b", "topic": "t2", "ours_s": 2.0},
            {"case": "c", "topic": "t1", "ours_s": 3.0}]
    (tmp_path / "benchmarks" / "results" / "x.json").write_text(json.dumps(rows))
    table = bench.markdown("x", columns=["case", "ours_s"], where={"topic": "t1"}).splitlines()
    assert table[2:] == ["| a | 0.123 |", "| c | 3 |"]
    by_predicate = bench.markdown("x", columns=["case", "ours_s"], where=lambda r: r["topic"] == "t1")
    assert by_predicate.splitlines() == table
    assert bench.markdown("x", columns=["case", "ours_s"], where={"topic": "t1", "case": "a"},
                          digits=2).splitlines()[2:] == ["| a | 0.12 |"]
    assert "No stored rows" in bench.markdown("x", where={"topic": "t3"})


def test_empty_rows_are_skipped_and_targets_may_add_keys(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    (tmp_path / "benchmarks" / "results").mkdir(parents=True)
    rows = [{"case": "a", "ours_mb": 10.0, "ours_baseline_mb": 30.0, "reference": "GUDHI", "kind": "alpha"},
            {"case": "b", "ours_mb": None, "reference": "GUDHI", "kind": "rips"}]
    (tmp_path / "benchmarks" / "results" / "x.json").write_text(json.dumps(rows))
    assert len(bench.markdown("x", columns=["case", "ours_mb"]).splitlines()) == 4
    assert bench.markdown("x", columns=["case", "ours_mb"], skip_empty=True).splitlines()[2:] == ["| a | 10 |"]
    spec = dict(label="memory", topic="x", cases=["a"], value=["ours_mb", "ours_baseline_mb"], bound=50, unit=" MB")
    assert "| 40 MB (a) | 50 MB | yes |" in bench.targets([spec])
    assert "| no |" in bench.targets([{**spec, "bound": 39}])
    assert bench.references("x", key="kind") == "- alpha: GUDHI\n- rips: GUDHI"
    assert bench.references("x") == "Reference: GUDHI."

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

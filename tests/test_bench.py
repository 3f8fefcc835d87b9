"""Stored benchmark results render as tables."""

from __future__ import annotations

import json

import pytest

from thesis_lib.lab import bench


def test_tables_from_rows(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_ROOT", str(tmp_path))
    (tmp_path / "benchmarks" / "results").mkdir(parents=True)
    rows = [{"case": "a", "ours_s": 0.5, "ref_s": 1.0, "ratio": 0.5}, {"case": "b", "ours_s": 2.0, "extra": 3}]
    (tmp_path / "benchmarks" / "results" / "x.json").write_text(json.dumps(rows))
    (tmp_path / "benchmarks" / "results" / "x_quick.json").write_text(json.dumps(rows))
    assert bench.topics() == ["x"]
    assert bench.markdown("x").splitlines() == [
        "| case | ours_s | ref_s | ratio | extra |",
        "|---|---|---|---|---|",
        "| a | 0.5 | 1 | 0.5 |  |",
        "| b | 2 |  |  | 3 |",
    ]
    assert bench.markdown("x", ["ratio", "case"]).splitlines()[2] == "| 0.5 | a |"
    with pytest.raises(ValueError, match="no columns"):
        bench.markdown("x", ["nothing"])
    with pytest.raises(FileNotFoundError, match="make bench"):
        bench.load("missing")


def test_every_stored_benchmark_is_readable():
    for topic in bench.topics():
        assert bench.load(topic), topic

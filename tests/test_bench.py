"""Stored benchmark results render as tables."""

from __future__ import annotations

import json

import pytest

from thesis_lib.lab import bench


def test_tables_from_rows(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
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
    assert bench.markdown("x", columns=["ratio", "case"]).splitlines()[2] == "| 0.5 | a |"
    with pytest.raises(ValueError, match="no columns"):
        bench.markdown("x", columns=["nothing"])
    with pytest.raises(FileNotFoundError, match="make bench"):
        bench.load("missing")


def test_targets_report_the_worst_case_and_what_is_missing(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    (tmp_path / "benchmarks" / "results").mkdir(parents=True)
    rows = [{"case": "a", "ratio_x": 0.5, "rounds": 5, "mb": 10.0, "base": 100.0},
            {"case": "b", "ratio_x": 1.2, "rounds": 15, "mb": 20.0, "base": 100.0}]
    (tmp_path / "benchmarks" / "results" / "t.json").write_text(json.dumps({"meta": {}, "rows": rows}))
    table = bench.targets([
        dict(label="fast", topic="t", cases=["a", "b"], value="ratio_x", bound=1.0, unit="×"),
        dict(label="fast a", topic="t", cases=["a"], value="ratio_x", bound=1.0),
        dict(label="memory", topic="t", cases=["b"], value=lambda r: r["mb"] + r["base"], bound=100, unit=" MB"),
        dict(label="later", topic="t", cases=["a", "z"], value="ratio_x", bound=1.0),
    ]).splitlines()
    assert table[2] == "| fast | a, b | 1.2× (b) | 1× | no | 15 |"
    assert table[3] == "| fast a | a | 0.5 (a) | 1 | yes | 5 |"
    assert table[4] == "| memory | b | 120 MB (b) | 100 MB | no | 15 |"
    assert table[5] == "| later | a, z |  | 1 | not measured (z) |  |"
    with pytest.raises(ValueError, match="lacks"):
        bench.targets([dict(label="x", topic="t")])


def test_every_stored_benchmark_is_readable():
    for topic in bench.topics():
        assert bench.load(topic), topic


# ----------------------------------------------------------------------------- the harness
def _harness():
    import importlib
    import sys

    from thesis_lib.lab.paths import project_root

    sys.path.insert(0, str(project_root() / "benchmarks"))
    try:
        return importlib.import_module("harness")
    finally:
        sys.path.pop(0)


def test_compare_interleaves_rounds_and_pairs_ratios():
    h = _harness()
    calls = []
    r = h.compare({"a": lambda: calls.append("a"), "b": lambda: calls.append("b")}, rounds=3)
    assert calls == ["a", "b"] * 4  # one warm-up each, then a, b, a, b, ...
    assert r["rounds"] == 3 and len(r["times_s"]["a"]) == 3
    fake = {"rounds": 3, "times_s": {"a": [1.0, 2.0, 10.0], "b": [2.0, 2.0, 2.0]}, "median_s": {"a": 2.0, "b": 2.0}}
    assert h.paired_ratio(fake, "a", "b") == 1.0  # median of 0.5, 1, 5
    row = h.ratio_fields(fake, "a")
    assert row == {"rounds": 3, "a_s": 2.0, "b_s": 2.0, "ratio_b": 1.0}
    assert h.default_rounds(0.05) == 15 and h.default_rounds(0.5) == 5
    seen = {}
    h.compare({"x": lambda: 1, "y": lambda: 2}, rounds=1, check=seen.update)
    assert seen == {"x": 1, "y": 2}
    with pytest.raises(ValueError):
        h.compare({})


def test_default_rounds_follow_the_first_timed_round_not_the_warm_up():
    """A contender whose warm-up is slow (compilation) but whose calls are fast gets 15 rounds."""
    import time

    h = _harness()
    calls = []

    def compiled_once():
        time.sleep(0.15 if not calls else 0.0)  # the first call "compiles"
        calls.append(1)

    r = h.compare({"a": compiled_once, "b": lambda: None})
    assert r["warmup_s"]["a"] >= 0.15
    assert r["rounds"] == h.FAST_ROUNDS and len(r["times_s"]["a"]) == h.FAST_ROUNDS == len(calls) - 1
    slow = h.compare({"a": lambda: time.sleep(0.11)})
    assert slow["rounds"] == h.MIN_ROUNDS and len(slow["times_s"]["a"]) == h.MIN_ROUNDS
    with pytest.raises(ValueError, match="rounds"):
        h.compare({"a": lambda: None}, rounds=0)


def test_results_carry_provenance_and_ratio_changes_are_caught(tmp_path):
    h = _harness()
    out = h.write_results("t", [{"case": "c", "ratio_ripser": 1.0}], output=str(tmp_path / "t.json"))
    meta, rows = h.read_results(out)
    assert rows == [{"case": "c", "ratio_ripser": 1.0}]
    assert meta["cores"] >= 1 and len(meta["load_average"]) == 3 and meta["date"].endswith("Z")
    assert "commit" in meta and "load_average_end" in meta
    stored = [{"case": "c", "ratio_ripser": 1.0, "ratio_gudhi": 0.5}]
    assert h.ratio_changes(stored, [{"case": "c", "ratio_ripser": 1.3, "ratio_gudhi": 0.4}]) == []
    moved = h.ratio_changes(stored, [{"case": "c", "ratio_ripser": 1.4}])
    assert len(moved) == 1 and "ratio_ripser moved +40%" in moved[0]
    assert "no stored result" in h.ratio_changes(stored, [{"case": "d", "ratio_ripser": 1.0}])[0]
    assert "no stored figure" in h.ratio_changes(stored, [{"case": "c", "ratio_new": 1.0}])[0]
    near_zero = [{"case": "c", "ratio_ripser": 0.04, "noise_floor": 0.05}]  # a difference at process noise
    assert h.ratio_changes(near_zero, [{"case": "c", "ratio_ripser": 0.08}]) == []
    assert h.ratio_changes([{"case": "c", "ratio_ripser": 0.04}], [{"case": "c", "ratio_ripser": 0.08,
                                                                     "noise_floor": 0.03}])[0].endswith("now 0.08)")
    assert h.ratio_changes(near_zero, [{"case": "c", "ratio_ripser": 0.1}])  # beyond the floor: a move
    assert h.ratio_moves(stored, [{"case": "c", "ratio_ripser": 1.4, "ratio_new": 2.0, "n": 3}]) == [
        ("c", "ratio_ripser", 1.0, 1.4)]


def test_update_replaces_one_row_and_keeps_both_provenances(tmp_path, monkeypatch):
    h = _harness()
    results = tmp_path / "benchmarks" / "results"
    results.mkdir(parents=True)
    monkeypatch.setattr(h, "RESULTS", results)
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    first = {"commit": "aaa", "date": "2026-01-01T00:00:00Z", "load_average": [0.1, 0.1, 0.1]}
    h.write_results("t", [{"case": "a", "ratio": 1.0}, {"case": "c", "ratio": 3.0}], meta=first)
    later = {"commit": "bbb", "date": "2026-02-01T00:00:00Z", "load_average": [0.2, 0.2, 0.2]}
    h.update_results("t", {"case": "b", "ratio": 2.0}, later, order=["a", "b", "c"])
    h.update_results("t", {"case": "c", "ratio": 4.0}, later, order=["a", "b", "c"])
    meta, rows = h.read_results(results / "t.json")
    assert [r["case"] for r in rows] == ["a", "b", "c"] and [r["ratio"] for r in rows] == [1.0, 2.0, 4.0]
    assert meta["commit"] == "aaa" and meta["updated"] == ["b", "c"]  # the file's run, and what came later
    assert "run" not in rows[0] and rows[2]["run"]["commit"] == "bbb" and len(rows[2]["run"]["load_average_end"]) == 3
    assert not list(results.glob("*.tmp"))
    text = bench.provenance("t")
    assert text.startswith("`t`: commit `aaa`") and "Row `c`: commit `bbb`, 2026-02-01" in text
    assert "Row `a`" not in text
    with pytest.raises(SystemExit, match="--update needs --cases"):
        h.run_cases("t", "doc", ["--update"], cases=["a"], quick=["a"], full=["a"], columns=[],
                    run_case=lambda name, rounds: {}, memory_child=lambda *a: None)


def test_memory_worker_subtracts_the_baseline():
    # in a fresh process, as the harness runs it: a long-lived test worker may serve the array from
    # pages it already holds, and then its resident set does not grow
    import subprocess
    import sys

    from thesis_lib.lab.paths import project_root

    code = ("import sys; sys.path.insert(0, 'benchmarks'); import numpy as np, harness; "
            "harness.memory_worker(lambda: None, lambda _: np.ones(40 * 2**20 // 8).sum())")
    proc = subprocess.run([sys.executable, "-c", code], cwd=project_root(), capture_output=True, text=True, check=True)
    res = json.loads(proc.stdout.strip().splitlines()[-1])
    assert res["peak_mb"] >= res["baseline_mb"] > 0
    if res["hwm_reset"]:
        assert res["delta_mb"] > 30  # the 40 MB array


def test_ratios_figures_and_exponents(tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    (tmp_path / "benchmarks" / "results").mkdir(parents=True)
    rows = [{"case": f"scaling-{n}", "n_per_circle": n, "rounds": 5, "ours_s": 0.001 * n**2, "ripser_s": 0.002 * n**3,
             "ours_mb": float(n), "ripser_mb": 2.0 * n, "ratio_ripser": 0.5 * n**-1} for n in (10, 20, 40)]
    (tmp_path / "benchmarks" / "results" / "p.json").write_text(
        json.dumps({"meta": {"commit": "abc", "date": "d", "cores": 2, "load_average": [1, 1, 1],
                             "load_average_end": [2, 2, 2]}, "rows": rows}))
    assert bench.ratios("p", cases=["scaling-10"]) == [("scaling-10", "ripser", 0.05, 5)]
    assert "No stored rows" in bench.markdown("p", columns=["case"], cases=["absent"])
    assert bench.meta("p")["commit"] == "abc" and "load average 1 at the start and 2" in bench.provenance("p")
    assert abs(bench.fit_exponent([1, 2, 4], [3, 12, 48]) - 2.0) < 1e-12
    with pytest.raises(ValueError):
        bench.fit_exponent([1], [1])
    fig = bench.ratio_figure("p")
    assert len(fig.axes[0].patches) == 3
    fig, exps = bench.scaling_figure("p", prefix="scaling-", tools={"ours": "ours", "ripser": "Ripser"})
    assert abs(exps["ours"][0] - 2) < 1e-9 and abs(exps["ripser"][0] - 3) < 1e-9 and abs(exps["ours"][1] - 1) < 1e-9
    with pytest.raises(ValueError, match="no cases"):
        bench.scaling_figure("p", prefix="nothing", tools={"ours": "ours"})

"""Recorder and load: flat numbers, deterministic figures."""

from __future__ import annotations

import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest

from thesis_lib.lab.results import DEFAULT_RUN_ENV, RESULT_DIGITS, Recorder, ResultsError, load, round_sig


def test_record_writes_flat_numbers(tmp_path):
    rec = Recorder("demo", output_dir=tmp_path)
    assert rec.record(a=1, b=np.float64(2.5), c=np.int64(3), ok=True) is None  # a cell ending in record() shows nothing
    assert rec.results == {"a": 1, "b": 2.5, "c": 3, "ok": 1}
    assert json.loads((tmp_path / "results.json").read_text()) == {"a": 1, "b": 2.5, "c": 3, "ok": 1}
    assert load("demo", output_dir=tmp_path) == {"a": 1, "b": 2.5, "c": 3, "ok": 1}


def test_a_new_recorder_clears_old_results(tmp_path):
    Recorder("demo", output_dir=tmp_path).record(old=1)
    Recorder("demo", output_dir=tmp_path).record(new=2)
    assert load("demo", output_dir=tmp_path) == {"new": 2}


@pytest.mark.parametrize("value", ["3", [1, 2], None, {"a": 1}])
def test_non_numbers_are_refused(tmp_path, value):
    with pytest.raises(ValueError, match="must be a number"):
        Recorder("demo", output_dir=tmp_path).record(x=value)


def test_bad_names_are_refused(tmp_path):
    with pytest.raises(ValueError, match="identifiers"):
        Recorder("demo", output_dir=tmp_path).record(**{"a b": 1})
    with pytest.raises(ValueError, match="invalid experiment name"):
        Recorder("a/b", output_dir=tmp_path)


def test_missing_results_say_how_to_make_them(tmp_path):
    with pytest.raises(FileNotFoundError, match="thesis-lab run nothing"):
        load("nothing", output_dir=tmp_path)


def test_figures_are_byte_identical_on_rerun(tmp_path):
    rec = Recorder("demo", output_dir=tmp_path)
    blobs = []
    for _ in range(2):
        fig, ax = plt.subplots()
        ax.plot([0, 1], [1, 0])
        blobs.append(rec.savefig(fig, "line").read_bytes())
        plt.close(fig)
    assert blobs[0] == blobs[1]


def test_stored_figures_are_found_or_explained(tmp_path, monkeypatch):
    from thesis_lib.lab.results import figure

    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    monkeypatch.delenv(DEFAULT_RUN_ENV, raising=False)
    rec = Recorder("demo", output_dir="")
    fig, ax = plt.subplots()
    rec.savefig(fig, "plot")
    plt.close(fig)
    assert figure("demo", "plot").filename.endswith("experiments/results/demo/plot.png")
    with pytest.raises(FileNotFoundError, match="make experiments"):
        figure("demo", "nothing")


def test_default_run_redirect_leaves_stored_results_alone(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path / "root"))
    monkeypatch.delenv(DEFAULT_RUN_ENV, raising=False)
    Recorder("demo", output_dir="").record(stored=1)
    monkeypatch.setenv(DEFAULT_RUN_ENV, str(tmp_path / "scratch"))
    Recorder("demo", output_dir="").record(rerun=2)
    assert load("demo") == {"stored": 1}
    assert load("demo", output_dir=tmp_path / "scratch" / "demo") == {"rerun": 2}


def test_reals_are_rounded_to_result_digits_and_counts_kept_exact(tmp_path):
    assert RESULT_DIGITS == 10
    rec = Recorder("demo", output_dir=tmp_path)
    rec.record(third=1 / 3, big=123456789012345.678, tiny=-2.718281828459045e-12, count=2**62 + 1,
               zero=0.0, nan=float("nan"))
    text = (tmp_path / "results.json").read_text()
    stored = json.loads(text)
    assert stored["third"] == 0.3333333333 and stored["big"] == 123456789000000.0
    assert stored["tiny"] == -2.718281828e-12 and stored["count"] == 2**62 + 1 and stored["zero"] == 0.0
    assert "NaN" in text
    # the last digits that BLAS or the CPU may change are not stored: perturbed values write the same bytes
    rec.record(third=1 / 3 * (1 + 1e-13))
    assert (tmp_path / "results.json").read_text() == text


@pytest.mark.parametrize("x, digits, expected", [(0.012345, 2, 0.012), (98765.0, 3, 98800.0), (-1.5e-300, 1, -2e-300),
                                                 (0.0, 3, 0.0), (float("inf"), 2, float("inf"))])
def test_round_sig(x, digits, expected):
    assert round_sig(x, digits) == expected


def test_results_are_written_atomically(tmp_path, monkeypatch):
    """A reader never sees a half-written results.json: it is replaced in one step."""
    rec = Recorder("demo", output_dir=tmp_path)
    rec.record(a=1)
    import os

    replaced = []
    real_replace = os.replace
    monkeypatch.setattr(os, "replace", lambda src, dst: (replaced.append((src, dst)), real_replace(src, dst)))
    rec.record(b=2)
    assert [str(dst) for _, dst in replaced] == [str(tmp_path / "results.json")]
    assert load("demo", output_dir=tmp_path) == {"a": 1, "b": 2}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results.json"]


@pytest.mark.parametrize("text", ['{"a": 1, "b":', "", "[1, 2]", '{"a": "x"}', '{"a": {"b": 1}}', "\udcff"])
def test_corrupt_results_give_a_clear_error(tmp_path, text):
    """A truncated or malformed results.json gives a ResultsError naming the file, not a raw JSONDecodeError."""
    (tmp_path / "results.json").write_text(text, errors="surrogateescape")
    with pytest.raises(ResultsError, match="results.json (is not valid JSON|must hold a flat JSON object).*restore it"):
        load("demo", output_dir=tmp_path)


@pytest.mark.parametrize("name", ["..", ".", "", "a/b", "../x", "a\\b", "a\x00b", 3, None])
def test_results_names_cannot_leave_the_results_folder(name):
    from thesis_lib.lab.results import results_dir

    with pytest.raises(ValueError, match="invalid experiment name"):
        results_dir(name)


def test_format_result_writes_counts_exactly_and_reals_to_their_digits():
    from thesis_lib.lab.results import format_result

    assert format_result(1333500) == "1,333,500" and format_result(0) == "0"
    assert format_result(0.50041283) == "0.5" and format_result(0.1167109) == "0.12"
    assert format_result(0.1167109, digits=3) == "0.117" and format_result(12345.678, digits=3) == "1.23e+04"
    assert format_result(float("nan")) == "nan"

"""Recorder and load: flat numbers, deterministic figures."""

from __future__ import annotations

import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest

from thesis_lib.lab.results import DEFAULT_RUN_ENV, Recorder, load


def test_record_writes_flat_numbers(tmp_path):
    rec = Recorder("demo", tmp_path)
    rec.record(a=1, b=np.float64(2.5), c=np.int64(3), ok=True)
    assert json.loads((tmp_path / "results.json").read_text()) == {"a": 1, "b": 2.5, "c": 3, "ok": 1}
    assert load("demo", tmp_path) == {"a": 1, "b": 2.5, "c": 3, "ok": 1}


def test_a_new_recorder_clears_old_results(tmp_path):
    Recorder("demo", tmp_path).record(old=1)
    Recorder("demo", tmp_path).record(new=2)
    assert load("demo", tmp_path) == {"new": 2}


@pytest.mark.parametrize("value", ["3", [1, 2], None, {"a": 1}])
def test_non_numbers_are_refused(tmp_path, value):
    with pytest.raises(ValueError, match="must be a number"):
        Recorder("demo", tmp_path).record(x=value)


def test_bad_names_are_refused(tmp_path):
    with pytest.raises(ValueError, match="identifiers"):
        Recorder("demo", tmp_path).record(**{"a b": 1})
    with pytest.raises(ValueError, match="invalid experiment name"):
        Recorder("a/b", tmp_path)


def test_missing_results_say_how_to_make_them(tmp_path):
    with pytest.raises(FileNotFoundError, match="thesis-lab run nothing"):
        load("nothing", tmp_path)


def test_figures_are_byte_identical_on_rerun(tmp_path):
    rec = Recorder("demo", tmp_path)
    blobs = []
    for _ in range(2):
        fig, ax = plt.subplots()
        ax.plot([0, 1], [1, 0])
        blobs.append(rec.savefig(fig, "line").read_bytes())
        plt.close(fig)
    assert blobs[0] == blobs[1]


def test_stored_figures_are_found_or_explained(tmp_path, monkeypatch):
    from thesis_lib.lab.results import figure

    monkeypatch.setenv("THESIS_LAB_ROOT", str(tmp_path))
    monkeypatch.delenv(DEFAULT_RUN_ENV, raising=False)
    rec = Recorder("demo", "")
    fig, ax = plt.subplots()
    rec.savefig(fig, "plot")
    plt.close(fig)
    assert figure("demo", "plot").filename.endswith("experiments/results/demo/plot.png")
    with pytest.raises(FileNotFoundError, match="make experiments"):
        figure("demo", "nothing")


def test_default_run_redirect_leaves_stored_results_alone(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_ROOT", str(tmp_path / "root"))
    monkeypatch.delenv(DEFAULT_RUN_ENV, raising=False)
    Recorder("demo", "").record(stored=1)
    monkeypatch.setenv(DEFAULT_RUN_ENV, str(tmp_path / "scratch"))
    Recorder("demo", "").record(rerun=2)
    assert load("demo") == {"stored": 1}
    assert load("demo", tmp_path / "scratch" / "demo") == {"rerun": 2}

"""The two-circles size study (applications.two_circles): Rips and witness runs, the 2-skeleton count."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thesis_lib.applications.two_circles import rips_2_skeleton_size, rips_run, witness_run, witness_table
from thesis_lib.complexes import rips
from thesis_lib.datasets import two_circles
from thesis_lib.persistence import long_bars, persistence


@pytest.mark.parametrize("seed", range(5))
def test_the_2_skeleton_count_equals_the_built_complex(seed):
    pts = np.random.default_rng(seed).random((30, 2))
    for eps in (0.05, 0.15, 0.3, 2.0):
        assert rips_2_skeleton_size(pts, max_radius=eps) == len(rips(pts, max_radius=eps, max_dim=2))


def test_a_rips_run_reads_its_long_bars_off_the_barcode():
    pts = two_circles(25, seed=3)
    run = rips_run(pts, n=25, max_radius=2.0, max_dim=2, min_bar_length=0.1)
    f = rips(pts, max_radius=2.0, max_dim=2)
    long = long_bars(persistence(f), dim=1, min_length=0.1)
    assert np.array_equal(run.long, long) and run.n_simplices == len(f)
    assert run.birth == long[:, 0].max() and run.death == long[:, 1].max()
    assert run.at_birth == len(f.threshold(run.birth)) < run.n_simplices
    assert run.complete == math.comb(50, 1) + math.comb(50, 2) + math.comb(50, 3)
    assert run.record[f"rips_simplices_at_birth_{25}"] == run.at_birth and run.seconds > 0
    assert "25 points per circle" in run.summary and f"{len(long)} long H₁ bars" in run.summary


def test_a_run_without_long_bars_says_nan_and_the_table_shows_each_run():
    pts = two_circles(15, seed=0)
    none = rips_run(pts, n=15, max_radius=0.05, max_dim=2, min_bar_length=0.5)
    assert len(none.long) == 0 and np.isnan(none.birth) and none.at_birth == 0
    ref = rips_run(pts, n=15, max_radius=2.0, max_dim=2, min_bar_length=0.1)
    w = witness_run(two_circles(60, seed=0), n=60, reference=ref, max_radius=1.0, landmark_method="maxmin",
                    n_landmarks=20, nu=1, seed=0, min_bar_length=0.1)
    assert w.rips_same_sample == rips_2_skeleton_size(two_circles(60, seed=0), max_radius=ref.death)
    assert w.record["witness_stop_size_ratio_60"] == w.at_birth / ref.at_birth
    lines = witness_table([w], reference=ref).splitlines()
    assert lines[2].startswith(f"| 60 | {w.n_simplices:,d} | {w.rips_same_sample:,d} | {len(w.long)} |")
    assert lines[3].startswith("| Rips, 15 |") and len(lines) == 4

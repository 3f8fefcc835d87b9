"""The pure parts of benchmarks/bench_ripser_data.py: Ripser's formats and the barcode comparison."""

from __future__ import annotations

import importlib
import sys

import numpy as np
import pytest

from thesis_lib.lab.paths import project_root


@pytest.fixture(scope="module")
def bench():
    sys.path.insert(0, str(project_root() / "benchmarks"))
    try:
        return importlib.import_module("bench_ripser_data")
    finally:
        sys.path.pop(0)


def _distances(n: int, seed: int) -> np.ndarray:
    x = np.random.default_rng(seed).random((n, 3))
    return np.sqrt(((x[:, None, :] - x[None, :, :]) ** 2).sum(-1))


@pytest.mark.parametrize("sep, end", [(",", ","), (" ", ""), ("\t", "\t")])
def test_lower_distance_reader_rebuilds_the_matrix(bench, tmp_path, sep, end):
    d = _distances(7, seed=1)
    lines = [sep.join(repr(float(v)) for v in d[i, :i]) + (end if i else "") for i in range(len(d))]
    path = tmp_path / "d.lower_distance_matrix"
    path.write_text("\n".join(lines) + "\n")
    assert lines[0] == ""
    got = bench.read_lower_distance(str(path))
    assert got.dtype == np.float64 and got.shape == d.shape
    np.testing.assert_array_equal(got, d * (1 - np.eye(len(d))))


def test_lower_distance_reader_rejects_a_ragged_count(bench, tmp_path):
    path = tmp_path / "bad.lower_distance_matrix"
    path.write_text("\n1\n2 3\n4\n")  # 4 values: no n with n (n - 1) / 2 = 4
    with pytest.raises(ValueError, match="lower triangle"):
        bench.read_lower_distance(str(path))


def _ripser_text(barcode: list[np.ndarray]) -> str:
    lines = ["value range: [0.1,2]", "distance matrix with 5 points, using threshold at enclosing radius 1.5"]
    for k, bars in enumerate(barcode):
        lines.append(f"persistence intervals in dim {k}:")
        lines += [f" [{b:g},{'' if np.isinf(d) else f'{d:g}'})".replace(",)", ", )") for b, d in bars]
    return "\n".join(lines) + "\n"


def test_ripser_output_parser(bench):
    barcode = [np.array([[0.0, 0.25], [0.0, 1.5], [0.0, np.inf]]), np.array([[0.75, 1.125]]), np.empty((0, 2)),
               np.array([[1.0, np.inf]])]
    got = bench.parse_ripser_output(_ripser_text(barcode))
    assert len(got) == len(barcode)
    for a, b in zip(got, barcode):
        np.testing.assert_array_equal(a, b)
    with pytest.raises(ValueError, match="before any dimension"):
        bench.parse_ripser_output(" [0,1)\npersistence intervals in dim 0:\n")
    with pytest.raises(ValueError, match="dimension 1 after 0"):
        bench.parse_ripser_output("persistence intervals in dim 1:\n")


def _barcode(seed: int) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    h0 = np.column_stack([np.zeros(6), np.append(rng.random(5) + 0.1, np.inf)])
    b = rng.random(4) + 0.2
    h1 = np.column_stack([b, b + rng.random(4) + 0.05])
    return [h0, h1]


def test_barcode_comparison_accepts_a_reordered_copy_within_tolerance(bench):
    ours = _barcode(3)
    theirs = [d[::-1] * (1 + 1e-6) for d in ours]
    assert bench.barcode_difference(ours, theirs) is None
    # zero-length bars are left out on either side
    padded = [theirs[0], np.vstack([theirs[1], [[0.5, 0.5]]])]
    assert bench.barcode_difference(ours, padded) is None


def test_barcode_comparison_fails_on_a_perturbed_barcode(bench):
    ours = _barcode(4)
    moved = [ours[0], ours[1].copy()]
    moved[1][2, 1] *= 1 + 1e-3
    assert "H1: deaths differ" in bench.barcode_difference(ours, moved)
    born = [ours[0].copy(), ours[1]]
    born[0][0, 0] = 1e-3
    assert "H0: births differ" in bench.barcode_difference(ours, born)
    fewer = [ours[0], ours[1][1:]]
    assert bench.barcode_difference(ours, fewer) == f"H1: {len(ours[1])} bars against {len(ours[1]) - 1}"
    finite = [ours[0].copy(), ours[1]]
    finite[0][-1, 1] = 9.0
    assert bench.barcode_difference(ours, finite) == "H0: 1 infinite deaths against 0"
    assert bench.barcode_difference(ours, ours[:1]) == "2 dimensions against 1"


def test_float32_view_drops_bars_that_collapse(bench):
    ours = [np.array([[0.0, 1.0], [0.0, 1.0 + 1e-12], [0.0, np.inf]]), np.array([[0.5, 0.5 + 1e-9], [0.5, 0.75]])]
    seen = bench.as_float32(ours)
    assert [len(d) for d in seen] == [3, 1]
    assert seen[1].tolist() == [[float(np.float32(0.5)), float(np.float32(0.75))]]
    assert bench.barcode_difference(ours, seen) == "H1: 2 bars against 1"

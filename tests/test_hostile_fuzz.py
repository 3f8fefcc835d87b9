"""Fuzz tests of hostile input: the families of tests/test_hostile_inputs.py.

Tolerances, dimensions, fields and seeds of every kind; weights and radii near and beyond the
float range; sizes that cannot fit (refused quickly, never allocated); complexes whose closure
cannot fit; the smallest enclosing ball at any power-of-two scale (checked exactly); corrupt
stored results and run folders.  Each call goes through ``helpers.fuzz_call`` (a value or a clear
ValueError/TypeError, never another exception or a hang), and the outcomes are tallied at the end
of the run under ``hostile-*``.  ``--fuzz-long`` runs 100 times more examples.
"""

from __future__ import annotations

import json
import math
import numbers
from fractions import Fraction

import numpy as np
import pytest
from helpers import fuzz_call, fuzz_settings
from hypothesis import given
from hypothesis import strategies as st

from thesis_lib import complexes as cx
from thesis_lib._validate import check_seed
from thesis_lib.homology import homology
from thesis_lib.morse.matching import morse_matching
from thesis_lib.persistence import Barcode
from thesis_lib.persistence.implicit import rips_persistence

MAXF = float(np.finfo(np.float64).max)
HOSTILE = [np.nan, np.inf, -np.inf, -1.0, -0.0, 0.0, 0.5, 1.5, 2.0, 3, 4, 0, 1, -1, True, False, None, "1", "01",
           b"1", [1, 2], (0,), np.array([1]), np.array(3), np.int64(2), np.float32(0.5), 1j, 10**12, 10**400,
           -(10**400), 2**63, MAXF, 1e300, 5e-324, {0: 1}]
hostile = st.sampled_from(HOSTILE)


def _is_index(v) -> bool:
    return isinstance(v, numbers.Integral) and not isinstance(v, bool) and v >= 0


# ----------------------------------------------------------------------------- barcodes and seeds
@fuzz_settings(150)
@given(atol=hostile, dim=hostile, coefficients=hostile, dims=st.one_of(hostile, st.lists(hostile, max_size=3)))
def test_barcode_arguments(atol, dim, coefficients, dims):
    a, b = Barcode({0: [[0, 1]], 1: [[0.5, 2]]}), Barcode({0: [[0, 1.2]], 1: [[0.5, 2]]})
    ok, value = fuzz_call("hostile-barcode", a.allclose, b, atol=atol)
    if ok:  # only a number >= 0 (inf included) is a tolerance, and it decides by it
        assert isinstance(atol, numbers.Real) and not isinstance(atol, bool) and atol >= 0
        assert value == (atol >= 0.2 - 1e-12)
    ok, _ = fuzz_call("hostile-barcode", Barcode.from_pairs, [(dim, (0.0, 1.0))])
    assert ok == _is_index(dim)
    ok, bc = fuzz_call("hostile-barcode", Barcode.from_diagrams, [[[0, 1]]], coefficients=coefficients)
    if ok:
        assert coefficients is None or (_is_index(coefficients) and coefficients in (2, 3))
    ok, dg = fuzz_call("hostile-barcode", a.to_diagrams, dims=dims)
    if ok:
        assert dims is None or all(_is_index(d) and d < 10_000 for d in dims)


@fuzz_settings(80)
@given(seed=hostile)
def test_seeds(seed):
    ok, _ = fuzz_call("hostile-seed", check_seed, seed)
    assert ok == _is_index(seed)
    ok, _ = fuzz_call("hostile-seed", morse_matching, [(0, 1, 2), (1, 2, 3)], seed=seed)
    assert ok == (_is_index(seed) or seed is None)


# ----------------------------------------------------------------------------- the float range
@fuzz_settings(60)
@given(scale=st.sampled_from([1e100, 1e140, 1e150, 1e200, 1e300, MAXF, 2.0**1000]),
       pattern=st.sampled_from(["equal", "random", "one", "two"]), d=st.sampled_from([2, 3]),
       seed=st.integers(0, 2**16))
def test_weights_near_the_float_range(scale, pattern, d, seed):
    rng = np.random.default_rng(seed)
    pts = rng.random((d + 5, d))
    w = {"equal": np.full(len(pts), scale), "random": rng.random(len(pts)) * scale,
         "one": np.r_[scale, np.zeros(len(pts) - 1)], "two": np.r_[scale, scale / 3, np.zeros(len(pts) - 2)]}[pattern]
    ok, f = fuzz_call("hostile-weights", cx.alpha, pts, weights=w)
    if ok:
        assert all(np.all(np.isfinite(v)) for v in f.values)
        if pattern == "equal":  # equal weights do not move the power diagram
            assert [s.tolist() for s in f.simplices] == [s.tolist() for s in cx.alpha(pts).simplices]
    fuzz_call("hostile-weights", cx.delaunay, pts, weights=w)


@fuzz_settings(60)
@given(radius=hostile, max_dim=hostile)
def test_radii_and_dimensions(radius, max_dim):
    pts = np.random.default_rng(0).random((6, 2))
    ok, f = fuzz_call("hostile-range", cx.rips, pts, max_radius=radius, max_dim=2)
    if ok:
        assert isinstance(radius, numbers.Real) and not isinstance(radius, bool) and radius >= 0
        assert abs(float(radius)) <= MAXF or radius == np.inf
    ok, _ = fuzz_call("hostile-range", rips_persistence, pts, max_dim=max_dim)
    assert ok == (_is_index(max_dim) and 1 <= max_dim <= 10_000)


# ----------------------------------------------------------------------------- sizes
@fuzz_settings(12)
@given(n=st.sampled_from([46_000, 60_000, 100_000]), d=st.sampled_from([2, 3]),
       radius=st.sampled_from([np.inf, 10.0, 2.0]), kind=st.sampled_from(["rips", "cech"]))
def test_edge_lists_that_cannot_fit_are_refused_quickly(n, d, radius, kind):
    pts = np.random.default_rng(n + d).random((n, d))
    fn = cx.rips if kind == "rips" else cx.cech
    ok, err = fuzz_call("hostile-size", fn, pts, max_radius=radius, max_dim=1, seconds=20)
    assert not ok and "edges" in str(err) and "more than the limit" in str(err)


@fuzz_settings(40)
@given(k=st.integers(22, 60), extra=st.integers(0, 3), kind=st.sampled_from(["homology", "morse"]))
def test_closures_that_cannot_fit_are_refused_quickly(k, extra, kind):
    simplices = [tuple(range(k))] + [(i, i + 1) for i in range(extra)]
    fn = homology if kind == "homology" else morse_matching
    ok, err = fuzz_call("hostile-size", fn, simplices, seconds=10)
    assert not ok and f"largest simplex has {k} vertices" in str(err)
    assert ("memory budget" in str(err)) == (24 * k * 2 ** (k - 1) > 8 * 2**30)


@fuzz_settings(20)
@given(n=st.integers(16, 24), d=st.sampled_from([2, 3]))
def test_cech_work_that_cannot_finish_is_refused(n, d):
    pts = np.random.default_rng(n).random((n, d))
    ok, err = fuzz_call("hostile-size", cx.cech, pts, max_radius=np.inf, max_dim=n - 1, seconds=20)
    assert not ok and "steps" in str(err) and "budget" in str(err)


# ----------------------------------------------------------------------------- miniball at any scale
@fuzz_settings(60)
@given(k=st.integers(-1070, 1020), n=st.integers(1, 9), d=st.sampled_from([1, 2, 3, 4]), seed=st.integers(0, 2**16),
       shape=st.sampled_from(["random", "duplicates", "segment"]))
def test_smallest_enclosing_ball_contains_every_point_at_any_scale(k, n, d, seed, shape):
    rng = np.random.default_rng(seed)
    unit = rng.random((n, d))
    if shape == "duplicates":
        unit = np.repeat(unit[:1], n, axis=0)
    elif shape == "segment":
        unit[:, 1:] = 0.0
    pts = np.ldexp(unit, k)
    ok, out = fuzz_call("hostile-miniball", cx.smallest_enclosing_ball, pts)
    assert ok, out
    centre, r = out
    assert math.isfinite(r) and r >= 0
    fc, fr = [Fraction(float(v)) for v in centre], Fraction(r)
    assert all(sum((Fraction(float(x)) - c) ** 2 for x, c in zip(p, fc)) <= fr * fr for p in pts)
    if np.all(pts == pts[0]):
        assert r == 0.0
    elif r >= 2.0**-1000:  # normal numbers: the power-of-two scaling is exact, so the radius scales
        _, r1 = cx.smallest_enclosing_ball(np.ldexp(pts, -k))
        assert abs(r - math.ldexp(r1, k)) <= 4e-15 * r


# ----------------------------------------------------------------------------- corrupt stored state
TEXTS = ['{"a": 1}', "[]", "[1, 2]", "{", "", "null", '"x"', '{"a": "x"}', '{"a": [1]}', '{"a": true}',
         '{"a": NaN}', '{"a": Infinity}', '{"a": ' + "9" * 5000 + "}", '{"a": 1' + "0" * 400 + "}",
         "[" * 100_000 + "]" * 100_000, '{"a": {"b": 1}}', "\x00\xff", '{"seconds": "x"}', '{"seconds": 1}',
         '{"seconds": null, "worker": 3}', '{"seconds": 1e999}']


@fuzz_settings(60)
@given(results=st.sampled_from(TEXTS + [None, "DIR"]), complete=st.sampled_from(TEXTS + ["DIR"]))
def test_corrupt_run_folders_and_results(tmp_path_factory, results, complete):
    from thesis_lib.lab import runner
    from thesis_lib.lab.results import ResultsError, load

    root = tmp_path_factory.mktemp("runs")
    params = {"n": 1}
    folder = root / "toy" / runner.run_hash(params)
    folder.mkdir(parents=True)
    for name, text in (("results.json", results), ("complete.json", complete)):
        if text == "DIR":
            (folder / name).mkdir()
        elif text is not None:
            (folder / name).write_text(text, errors="surrogateescape")
    ok, read = fuzz_call("hostile-lab", runner.read_run, "toy", params, root=root)
    assert ok and read.status in ("ok", "corrupt")
    if read.status == "ok":
        assert isinstance(json.loads((folder / "complete.json").read_text()), dict)
        assert all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in read.results.values())
    else:
        assert read.error and ("complete.json" in read.error or "results.json" in read.error)
    if results is None:
        return
    try:
        table = load("toy", output_dir=folder)
    except ResultsError as exc:
        assert "results.json" in str(exc) and "restore" in str(exc)
    else:
        assert isinstance(table, dict) and all(abs(v) <= MAXF or math.isnan(v) or math.isinf(v) for v in table.values())


@pytest.mark.parametrize("bad", [[[0, 1], [1]], {0: 1}, "abc", [[0, "a"], [1, 0]], None, 3.0, [[0, 1j], [1j, 0]],
                                 [[[0]]], [[0, -1], [-1, 0]], [[0, np.nan], [np.nan, 0]]])
def test_distance_matrices_of_every_wrong_kind(bad):
    ok, _ = fuzz_call("hostile-types", cx.rips, distance_matrix=bad)
    assert not ok
    ok, _ = fuzz_call("hostile-types", rips_persistence, distance_matrix=bad)
    assert not ok

"""Theorem 3.18 on the Crust in R⁴ (chapters.hypersurface_study): one run's records and text, the error curves."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from thesis_lib.chapters.hypersurface_study import (
    CrustErrorCurve,
    crust_curvature_errors,
    crust_error_curve,
    crust_run_results,
    describe_crust_run,
)


@pytest.fixture(scope="module")
def sphere_run():
    return crust_curvature_errors("sphere", 600, seed=2)


def test_the_records_of_a_run_are_its_report_and_errors(sphere_run):
    res = crust_run_results(sphere_run, prefix="main")
    rep = sphere_run["report"]
    assert res["main_closed_manifold"] == 1 and res["main_euler"] == 0 == rep.euler_characteristic  # χ(S³) = 0
    assert res["main_n_simplices"] == len(sphere_run["simplices"])
    errors = np.abs(sphere_run["H"][sphere_run["estimated"]] - 0.5) / 0.5  # |H − 1/r| r on the sphere of radius 2
    assert res["main_median_error"] == pytest.approx(np.median(errors)) and res["main_median_error"] < 0.15
    assert res["main_p90_error"] == pytest.approx(np.percentile(errors, 90))
    assert res["main_estimated_fraction"] == 1.0 and res["main_vertex_fraction"] == 1.0
    assert len(res) == 9 and all(k.startswith("main_") for k in res)


def test_the_description_is_filled_to_its_width(sphere_run):
    check = f"sphere, 600 samples: {sphere_run['report'].describe()}"
    errors = (f"|H| estimated at {sphere_run['estimated'].sum()} samples; error median {sphere_run['median']:.2g}, "
              f"90th percentile {sphere_run['p90']:.2g}")
    expected = textwrap.fill(check, 76) + "\n" + textwrap.fill(errors, 76)
    assert describe_crust_run(sphere_run, surface="sphere") == expected
    narrow = describe_crust_run(sphere_run, surface="sphere", width=40)
    assert max(len(line) for line in narrow.splitlines()) <= 40 and " ".join(narrow.split()) == f"{check} {errors}"


@pytest.mark.parametrize("call, message", [
    (lambda run: crust_run_results({"points": 1}, prefix="a"), "missing"),
    (lambda run: crust_run_results(run, prefix="2x"), "identifier"),
    (lambda run: describe_crust_run(run, surface="torus"), "surface must be one of"),
    (lambda run: describe_crust_run(run, surface="sphere", width=5), "width must be >= 20"),
    (lambda run: describe_crust_run([1, 2], surface="sphere"), "result of crust_curvature_errors"),
])
def test_bad_runs_and_options_are_refused(sphere_run, call, message):
    with pytest.raises(ValueError, match=message):
        call(sphere_run)


def test_an_error_curve_reuses_known_runs_and_averages_over_seeds(sphere_run):
    curve = crust_error_curve("sphere", [600, 300], repeats=2, seed=1, known={("sphere", 600, 2): sphere_run})
    assert curve.counts == (600, 300) and curve.rows.shape == (4, 7)
    np.testing.assert_array_equal(curve.rows[:, 0], [600, 600, 300, 300])
    assert curve.rows[1, 1] == sphere_run["median"]  # seed 1 + 1 = 2: the known run, not a new one
    again = crust_curvature_errors("sphere", 300, seed=1)
    assert curve.rows[2, 1] == again["median"] and curve.rows[2, 2] == again["p90"]
    assert np.isnan(curve.rows[:, 3:5]).all()  # no control on the sphere
    res = curve.results()
    at = curve.at(600)
    assert res["sphere_600_median_error"] == pytest.approx(at[:, 1].mean())
    assert res["sphere_600_median_error_spread"] == pytest.approx(abs(at[0, 1] - at[1, 1]))
    assert res["sphere_300_closed_runs"] == int(curve.at(300)[:, 5].sum()) and len(res) == 12
    lines = curve.describe().splitlines()
    assert lines[0].startswith("sphere     600: median ") and lines[0].endswith("estimated at 100%")


def test_the_catenoid_curve_carries_its_control():
    rows = np.array([[100, 0.2, 0.5, 0.25, 0.6, 0, 0.2], [100, 0.3, 0.7, 0.2, 0.5, 0, 0.4]])
    curve = CrustErrorCurve(surface="catenoid", counts=(100,), rows=rows)
    res = curve.results()
    assert res["catenoid_100_control_median_error"] == pytest.approx(0.225)
    assert res["catenoid_100_median_excess_over_control"] == pytest.approx(0.025)
    assert res["catenoid_100_estimated_fraction"] == pytest.approx(0.3) and res["catenoid_100_closed_runs"] == 0
    assert curve.describe() == "catenoid   100: median 0.25, p90 0.6, control median 0.23, estimated at 30%"
    with pytest.raises(ValueError, match="n_samples must be one of"):
        curve.at(200)


@pytest.mark.parametrize("kwargs, message", [
    (dict(surface="torus", counts=[100]), "surface must be one of"),
    (dict(surface="sphere", counts=[]), "distinct"),
    (dict(surface="sphere", counts=[100, 100]), "distinct"),
    (dict(surface="sphere", counts=[0]), "counts must be >= 1"),
    (dict(surface="sphere", counts=[100], repeats=0), "repeats must be >= 1"),
])
def test_bad_curves_are_refused(kwargs, message):
    surface, counts = kwargs.pop("surface"), kwargs.pop("counts")
    with pytest.raises(ValueError, match=message):
        crust_error_curve(surface, counts, **kwargs)

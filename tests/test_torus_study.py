"""The torus study of §3.4.1 (chapters.torus_study): chosen points, random samples, principal curvatures."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib.chapters.torus_study import (
    GridErrors,
    PrincipalCurvatureErrors,
    crust_grid_summary,
    grid_curvature_errors,
    principal_curvature_errors,
    random_runs_table,
    random_torus_run,
)
from thesis_lib.curvature import mean_curvature
from thesis_lib.meshes import euler_characteristic, sample_torus, torus_chosen_points
from thesis_lib.surfaces import torus_mean_curvature, torus_outer_inner_ratio

N_GRID = 20


@pytest.fixture(scope="module")
def grid():
    return torus_chosen_points(step=2 * np.pi / N_GRID)


def flipped(simplices):
    """The grid with the other diagonal in every quad: its faces are the (a, b, c) of each quad a b c d
    (in cyclic order), then the (a, c, d); the flip is (a, b, d), (b, c, d), oriented alike."""
    first, second = np.split(np.asarray(simplices), 2)
    a, b, c, d = first[:, 0], first[:, 1], first[:, 2], second[:, 2]
    assert np.array_equal(second[:, :2], np.stack([a, c], 1))
    return np.concatenate([np.stack([a, b, d], 1), np.stack([b, c, d], 1)])


def test_the_summary_of_a_triangulation_against_the_fixed_grid(grid):
    V, faces, _ = grid
    same = crust_grid_summary(V, faces, grid_simplices=faces)
    assert (same.n_faces, same.euler, same.closed, same.n_boundary_vertices) == (2 * N_GRID**2, 0, True, 0)
    assert (same.fixed_diagonal_fraction, same.valence_min, same.valence_max) == (1.0, 6, 6)
    other = flipped(faces)
    assert euler_characteristic(other) == 0
    s = crust_grid_summary(V, other, grid_simplices=faces)
    assert s.fixed_diagonal_fraction == 0.0 and s.closed
    assert (s.valence_min, s.valence_max) == (6, 6)  # every quad flipped: the other diagonal family
    holed = crust_grid_summary(V, np.delete(faces, [0, N_GRID**2], axis=0), grid_simplices=faces)  # a quad's hole
    assert (holed.closed, holed.n_boundary_vertices, holed.euler) == (False, 4, -1)
    assert holed.fixed_diagonal_fraction == (len(faces) - 2) / len(faces)
    res = holed.results()
    assert res["crust_grid_n_faces"] == len(faces) - 2 and res["crust_grid_valence_min"] == 4
    text = holed.describe()
    head = f"Crust of the {N_GRID**2} chosen points: {len(faces) - 2} faces, $\\chi$ = -1, closed: False"
    assert text.startswith(head)
    assert text.endswith("; 100% of its faces use the fixed grid's diagonal; valence 4–6 (fixed grid: 6).")  # 99.75%


@pytest.mark.parametrize("bad, message", [
    (dict(simplices=np.zeros((0, 3), int)), "non-empty"),
    (dict(simplices=np.array([[0, 1, 10**6]])), "outside"),
    (dict(grid_simplices=np.ones((3, 4), int)), "grid_simplices"),
])
def test_the_summary_refuses_bad_triangulations(grid, bad, message):
    V, faces, _ = grid
    args = dict(simplices=faces, grid_simplices=faces) | bad
    with pytest.raises(ValueError, match=message):
        crust_grid_summary(V, args["simplices"], grid_simplices=args["grid_simplices"])
    with pytest.raises(ValueError, match="vertices"):
        crust_grid_summary(V[:, :2], faces, grid_simplices=faces)


def test_grid_errors_are_the_relative_errors_and_leave_out_the_zeros(grid):
    V, faces, uv = grid
    errors = grid_curvature_errors(V, {"fixed": faces, "flipped": flipped(faces)}, uv)
    assert errors.triangulations == ("fixed", "flipped") and errors.areas == ("mixed", "voronoi", "barycentric")
    exact = np.abs(torus_mean_curvature(uv[:, 0], uv[:, 1]))
    est = mean_curvature(V, faces, area="voronoi")
    ok = exact > 1e-3 * exact.max()
    np.testing.assert_allclose(errors.H["fixed", "voronoi"][ok], np.abs(est - exact)[ok] / exact[ok],
                               rtol=1e-9, atol=1e-14)
    # H = 0 on the inner equator v = π (R = 2r): one circle of N_GRID points; K = 0 on v = ±π/2: two
    res = errors.results(area="voronoi")
    assert (res["grid_n_zeros_H"], res["grid_n_zeros_K"]) == (N_GRID, 2 * N_GRID)
    # co-circular quads: the Voronoi estimate does not depend on the diagonal (a cotangent weight of 0)
    np.testing.assert_allclose(errors.H["fixed", "voronoi"], errors.H["flipped", "voronoi"], rtol=1e-9)
    assert res["fixed_grid_max_rel_err_H_voronoi"] == pytest.approx(np.nanmax(errors.H["fixed", "voronoi"]), rel=1e-3)
    assert len(res) == 2 * 3 * 3 + 2
    lines = errors.table().splitlines()
    assert len(lines) == 1 + 6 and lines[1].split()[:2] == ["fixed", "mixed"]
    assert float(lines[2].split()[2]) == pytest.approx(np.nanmax(errors.H["fixed", "voronoi"]), rel=0.05)
    with pytest.raises(ValueError, match="area must be one of"):
        errors.results(area="cotangent")


def test_grid_errors_refuse_bad_input(grid):
    V, faces, uv = grid
    with pytest.raises(ValueError, match="non-empty mapping"):
        grid_curvature_errors(V, {}, uv)
    with pytest.raises(ValueError, match="uv must be"):
        grid_curvature_errors(V, {"fixed": faces}, uv[:-1])
    with pytest.raises(ValueError, match="zero_tol"):
        grid_curvature_errors(V, {"fixed": faces}, uv, zero_tol=1.5)


def test_a_random_run_measures_the_outer_inner_ratio():
    run = random_torus_run(3000, seed=3)
    pts, uv = sample_torus(3000, seed=3, return_uv=True)
    np.testing.assert_array_equal(run.points, pts)
    assert run.closed and run.euler == 0 and run.defects_over_2pi == 0.0  # Gauss–Bonnet: 2πχ
    ok = np.isfinite(run.H)
    assert run.n_estimated == ok.sum() == 3000
    hx = np.abs(torus_mean_curvature(uv[:, 0], uv[:, 1]))
    outer = np.cos(uv[:, 1]) > 0
    assert run.exact_ratio == pytest.approx(hx[outer].mean() / hx[~outer].mean(), rel=1e-12)
    # the exact ratio at the samples is the torus's 2.33 up to sampling noise of the stated size
    assert abs(run.exact_ratio - torus_outer_inner_ratio()) < 4 * run.exact_ratio_se
    # the delta-method standard error against a bootstrap of the same ratio
    rng = np.random.default_rng(0)
    boots = []
    for _ in range(300):
        i = rng.integers(0, 3000, 3000)
        o = outer[i]
        boots.append(run.H[i][o].mean() / run.H[i][~o].mean())
    assert run.ratio_se == pytest.approx(np.std(boots), rel=0.25)
    assert run.z == pytest.approx((run.ratio - 1) / run.ratio_se) and run.z > 5
    res = run.results(grid_median_error=run.median_error / 10)
    assert res["random_3000_over_grid_median_rel_err_H"] == 10.0
    assert res["random_3000_defects_over_2pi"] == 0.0 and res["random_3000_closed"] is True
    row = run.row()
    assert row.startswith("| 3000 | 0 | True | 3000 | ") and f"{run.ratio:.2f} ± " in row
    table = random_runs_table([run, run]).splitlines()
    assert len(table) == 4 and table[2] == table[3] == row


def test_an_open_reconstruction_has_no_angle_defect_sum():
    run = random_torus_run(100, seed=0)  # 100 points: the Crust leaves holes
    assert not run.closed and run.defects_over_2pi is None
    assert run.n_estimated == np.isfinite(run.H).sum() < 100
    assert "random_100_defects_over_2pi" not in run.results(grid_median_error=1e-3)


def test_random_runs_refuse_bad_input():
    with pytest.raises(ValueError, match="n_samples must be >= 4"):
        random_torus_run(3)
    with pytest.raises(ValueError, match="runs must hold"):
        random_runs_table([])
    run = random_torus_run(200)
    with pytest.raises(ValueError, match="grid_median_error must be positive"):
        run.results(grid_median_error=0.0)


def test_principal_curvatures_by_both_routes_on_the_grid(grid):
    V, faces, _ = grid
    fine = torus_chosen_points(step=2 * np.pi / 60)
    e = principal_curvature_errors({"coarse": (V, faces), "fine": fine[:2]})
    assert list(e.least_squares) == ["coarse", "fine"]
    for route in (e.least_squares, e.from_mean_and_gaussian):
        assert route["fine"] < route["coarse"] < 0.05  # both converge as the grid is refined
    res = e.results()
    assert res["fine_kappa_lsq_over_hk"] == pytest.approx(e.least_squares["fine"] / e.from_mean_and_gaussian["fine"],
                                                          rel=1e-3)
    lines = e.table().splitlines()
    assert lines[0].split()[0] == "mesh" and lines[2].split()[0] == "fine"
    with pytest.raises(ValueError, match="non-empty mapping"):
        principal_curvature_errors({})


def test_the_records_round_as_the_experiment_stores():
    e = GridErrors(H={("a", "voronoi"): np.array([0.123456, np.nan])}, K={("a", "voronoi"): np.array([0.5, 0.25])},
                   triangulations=("a",), areas=("voronoi",))
    assert e.results(area="voronoi") == {"a_grid_max_rel_err_H_voronoi": 0.1235,
                                         "a_grid_median_rel_err_H_voronoi": 0.1235,
                                         "a_grid_max_rel_err_K_voronoi": 0.5, "grid_n_zeros_H": 1, "grid_n_zeros_K": 0}
    p = PrincipalCurvatureErrors(least_squares={"m": 1 / 3}, from_mean_and_gaussian={"m": 1 / 7})
    assert p.results() == {"m_kappa_median_err_lsq": 0.3333, "m_kappa_median_err_hk": 0.1429,
                           "m_kappa_lsq_over_hk": 2.333}

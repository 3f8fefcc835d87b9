"""The figures of the torus experiment (chapters.torus_figures)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.chapters.torus_figures import (
    ERROR_RANGE,
    TRIANGULATION_LABELS,
    plot_estimate_on_mesh,
    plot_gaussian_curvature_errors,
    plot_mean_curvature_errors,
    plot_mean_curvature_profile,
)
from thesis_lib.meshes import torus_chosen_points  # noqa: E402
from thesis_lib.surfaces import torus_mean_curvature  # noqa: E402

N = 6


def error_table(kinds=("voronoi", "barycentric")):
    rng = np.random.default_rng(1)
    return {(t, k): 10 ** rng.uniform(-7, -1, N * N) for t in TRIANGULATION_LABELS for k in kinds}


def test_the_mean_curvature_maps_are_the_errors_over_the_parameter_square():
    errors = error_table()
    errors["crust", "voronoi"][3] = np.nan  # a zero of H: left white
    fig = plot_mean_curvature_errors(errors, n_grid=N)
    maps = fig.axes[:4]
    for ax, (t, k) in zip(maps, [("crust", "voronoi"), ("crust", "barycentric"), ("fixed", "voronoi"),
                                 ("fixed", "barycentric")]):
        shown = ax.images[0].get_array()
        expected = np.clip(errors[t, k], ERROR_RANGE[0], None).reshape(N, N).T  # u along x, v along y
        np.testing.assert_array_equal(np.ma.filled(shown, np.nan), expected)
        assert ax.get_title() == f"{TRIANGULATION_LABELS[t]}\n{k} area, largest {np.nanmax(errors[t, k]):.2g}"
        assert ax.images[0].get_extent() == [0, 2 * np.pi, 0, 2 * np.pi]
    assert [ax.get_xlabel() for ax in maps] == ["", "", "u", "u"]
    assert [ax.get_ylabel() for ax in maps] == ["v", "", "v", ""]
    bar = fig.axes[4]
    assert bar.get_title(loc="left") == "relative\nerror of |H|"
    formatter = bar.yaxis.get_major_formatter()
    assert [formatter(x, 0) for x in (1e-5, 1e-3, 1.0)] == ["0.00001", "0.001", "1"]  # plain decimals
    plt.close(fig)


def test_the_gaussian_curvature_maps_show_one_area():
    errors = error_table(("mixed",))
    fig = plot_gaussian_curvature_errors(errors, n_grid=N, area="mixed")
    largest = errors["crust", "mixed"].max()
    assert fig.axes[0].get_title() == f"Crust of the chosen points, mixed area\nlargest {largest:.2g}"
    assert fig.axes[1].get_title().startswith("fixed-diagonal grid, mixed area")
    assert fig.axes[2].get_title(loc="left") == "relative\nerror of K"
    plt.close(fig)


@pytest.mark.parametrize("plot, kwargs", [(plot_mean_curvature_errors, {}),
                                          (plot_gaussian_curvature_errors, {"area": "voronoi"})])
def test_the_error_maps_refuse_missing_or_misshapen_errors(plot, kwargs):
    errors = error_table()
    with pytest.raises(ValueError, match="must hold n_grid² = 49 values"):
        plot(errors, n_grid=7, **kwargs)
    del errors["fixed", "voronoi"]
    with pytest.raises(ValueError, match="no entry"):
        plot(errors, n_grid=N, **kwargs)
    with pytest.raises(ValueError, match="n_grid must be >= 1"):
        plot(error_table(), n_grid=0, **kwargs)


def test_the_profile_draws_the_estimates_over_the_exact_mean_curvature():
    v = np.linspace(0, 2 * np.pi, 50)
    est = np.abs(torus_mean_curvature(0.0, v)) * 1.1
    fig = plot_mean_curvature_profile(v, est, R=10.0, r=5.0, title="50 points")
    ax = fig.axes[0]
    dots, exact = ax.lines
    np.testing.assert_array_equal(dots.get_ydata(), est)
    np.testing.assert_allclose(exact.get_ydata(), np.abs(torus_mean_curvature(0.0, exact.get_xdata())))
    assert ax.get_ylim() == pytest.approx((0, 3 * exact.get_ydata().max()), rel=1e-6)  # max |H| on v = 0
    assert ax.get_title() == "50 points"
    with pytest.raises(ValueError, match="differ in shape"):
        plot_mean_curvature_profile(v, est[:-1])
    with pytest.raises(ValueError):
        plot_mean_curvature_profile(v, est, R=1.0, r=5.0)
    plt.close("all")


def test_the_estimate_on_the_mesh_has_its_colour_bar_labelled_above():
    V, faces, uv = torus_chosen_points(step=2 * np.pi / 10)
    values = uv[:, 1].copy()
    values[0] = np.nan
    fig = plot_estimate_on_mesh(V, faces, values, clim=(0.0, 2 * np.pi), titles=["points", "v"], label="v",
                                cmap="coolwarm")
    points, mesh, bar = fig.axes
    assert (points.get_title(), mesh.get_title(), bar.get_title()) == ("points", "v", "v")
    solids = [c for c in bar.collections if type(c).__name__ == "QuadMesh"]
    assert solids[0].cmap.name == "coolwarm" and bar.get_ylim() == (0.0, 2 * np.pi)
    assert not np.array_equal(points.images[0].get_array(), mesh.images[0].get_array())
    with pytest.raises(ValueError, match="two titles"):
        plot_estimate_on_mesh(V, faces, values, clim=(0, 1), titles=["one"], label="v")
    plt.close("all")

"""The figures of §2.1–2.2 (chapters.complex_figures): what each draws, counted against the complexes."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.patches import Circle, Polygon  # noqa: E402

from thesis_lib.chapters.complex_figures import (
    NOT_A_COMPLEX,
    draw_complex,
    plot_alpha_complexes,
    plot_cech_rips,
    plot_complex_examples,
    plot_rp2_orientation,
    plot_simplices,
    plot_voronoi_delaunay,
    plot_witness_complex,
)
from thesis_lib.complexes import alpha, cech, delaunay, rips  # noqa: E402
from thesis_lib.datasets import RP2_LABELS, rp2  # noqa: E402
from thesis_lib.homology import betti_numbers  # noqa: E402
from thesis_lib.morse.examples import rp2_chart  # noqa: E402

FIG22 = [(0, 1, 2, 3), (3, 4), (1, 2, 5)]
CIRCLE = [(0, 1), (1, 2), (0, 2)]


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def test_draw_complex_fills_triangles_and_draws_edges():
    pts = np.random.default_rng(0).random((12, 2))
    dt = delaunay(pts)
    fig, ax = plt.subplots()
    draw_complex(ax, pts, dt, color="red", alpha_fill=0.4, vertex_size=5)
    triangles = [s for s in dt if len(s) == 3]
    assert len(ax.patches) == len(triangles) and len(ax.lines) == sum(len(s) == 2 for s in dt)
    drawn = {tuple(map(tuple, p.get_xy()[:3])) for p in ax.patches}
    assert drawn == {tuple(map(tuple, pts[list(t)])) for t in triangles}
    assert all(p.get_alpha() == 0.4 for p in ax.patches)
    assert np.allclose(ax.collections[0].get_offsets(), pts) and ax.get_aspect() == 1.0
    with pytest.raises(ValueError, match="planar"):
        draw_complex(ax, np.zeros((3, 3)), [(0, 1)])


def test_plot_simplices_draws_the_faces_of_each_simplex():
    fig = plot_simplices()
    # triangles filled: 0, 0, 1, 4; edges: 0, 1, 3, 6 (+ the dashed hidden edge)
    assert [len(ax.patches) for ax in fig.axes] == [0, 0, 1, 4]
    assert [len(ax.lines) for ax in fig.axes] == [0, 1, 3, 7]
    assert fig.axes[3].lines[-1].get_linestyle() == "--"


def test_plot_complex_examples_draws_the_closure_of_the_glued_complex():
    fig = plot_complex_examples(FIG22, CIRCLE)
    a, b, c = fig.axes
    assert len(a.patches) == 5 and len(a.lines) == 9  # the triangles and edges of the closure
    assert len(b.patches) == 2 and len(b.lines) == 7  # two triangles, six edges and the shared segment
    assert np.allclose(b.lines[-1].get_xydata(), NOT_A_COMPLEX[[3, 4]])
    assert len(c.lines) == 3 and isinstance(c.patches[-1], Circle)
    with pytest.raises(ValueError, match="vertices"):
        plot_complex_examples([(0, 6)], CIRCLE)
    with pytest.raises(ValueError, match="vertices"):
        plot_complex_examples(FIG22, [(0, 3)])


def test_plot_cech_rips_one_ball_per_point_and_the_two_complexes():
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, np.sqrt(3) / 2], [1.9, 0.3], [2.4, 0.9]])
    c = [s for s, _ in cech(pts, max_radius=0.54, max_dim=2)]
    r = [s for s, _ in rips(pts, max_radius=0.54, max_dim=2)]
    fig = plot_cech_rips(pts, c, r, max_radius=0.54)
    left, right = fig.axes
    assert sum(isinstance(p, Circle) for p in left.patches) == 5
    assert sum(isinstance(p, Polygon) for p in left.patches) == 0  # the Čech complex has no triangle here
    assert sum(isinstance(p, Polygon) for p in right.patches) == 1  # the Rips complex fills the hole
    assert right.get_title() == "Vietoris–Rips complex, ε = 0.54"
    assert right.get_xlim() == (-0.7, 3.1)
    assert plot_cech_rips(pts, c, r, max_radius=0.54, xlim=(0.0, 1.0), ylim=(0.0, 2.0)).axes[0].get_ylim() == (0.0, 2.0)
    with pytest.raises(ValueError, match=r"^max_radius must be positive, got 0\.0$"):
        plot_cech_rips(pts, c, r, max_radius=0.0)


def test_plot_voronoi_delaunay_triangles_are_the_delaunay_triangles():
    pts = np.random.default_rng(3).random((14, 2))
    dt = delaunay(pts)
    fig = plot_voronoi_delaunay(pts, dt)
    assert len(fig.axes[1].patches) == sum(len(s) == 3 for s in dt)
    with pytest.raises(ValueError, match="planar"):
        plot_voronoi_delaunay(np.zeros((5, 3)), dt)


def test_plot_alpha_complexes_titles_carry_the_betti_numbers_over_z2():
    theta = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    pts = np.c_[np.cos(theta), np.sin(theta)]
    f = alpha(pts)
    fig = plot_alpha_complexes(pts, f, [0.1, 0.3, 1.5])
    for ax, eps in zip(fig.axes, (0.1, 0.3, 1.5)):
        b = betti_numbers([s for s, _ in f.threshold(eps**2)], coefficients=2) + [0]
        assert ax.get_title() == f"ε = {eps}: β₀ = {b[0]}, β₁ = {b[1]}"
    assert [ax.get_title().split(": ")[1] for ax in fig.axes] == ["β₀ = 16, β₁ = 0", "β₀ = 1, β₁ = 1", "β₀ = 1, β₁ = 0"]
    with pytest.raises(ValueError, match="radii"):
        plot_alpha_complexes(pts, f, [])
    with pytest.raises(ValueError, match="radii"):
        plot_alpha_complexes(pts, f, [-1.0])


def test_plot_witness_complex_draws_on_the_landmarks():
    pts = np.random.default_rng(1).random((30, 2))
    lm = [3, 7, 11]
    fig = plot_witness_complex(pts, lm, [(0, 1), (1, 2), (0, 1, 2)], max_radius=0.2)
    ax = fig.axes[0]
    assert np.allclose(ax.collections[1].get_offsets(), pts[lm]) and len(ax.patches) == 1
    assert ax.get_title() == "3 maxmin landmarks, ε = 0.2"


def test_plot_rp2_orientation_one_triangle_and_arrow_per_column():
    tris = rp2(oriented=True)
    fig = plot_rp2_orientation(tris, rp2_chart(), RP2_LABELS)
    ax = fig.axes[0]
    assert len(ax.patches) == 10
    labels = sorted(t.get_text() for t in ax.texts if t.get_text())
    assert labels == sorted("abcabcdef")  # a, b, c twice on the hexagon; d, e, f once inside
    with pytest.raises(ValueError, match="missing"):
        plot_rp2_orientation([(0, 1, 2)], rp2_chart(), RP2_LABELS)

"""Theorem 2.6's realization on the moment curve and the planar helpers of complexes.realization,
against exact arithmetic (sympy) and hand-made configurations."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import sympy

from thesis_lib.complexes.realization import (
    affine_dimension,
    barycentric_coordinates,
    clockwise_triangles,
    full_skeleton,
    moment_curve,
    realization_failures,
)
from thesis_lib.datasets import rp2
from thesis_lib.morse.examples import rp2_chart


@pytest.mark.parametrize("n, d", [(1, 0), (5, 1), (7, 2), (6, 5), (4, 9)])
def test_full_skeleton_counts_binomials_and_is_closed(n, d):
    cx = full_skeleton(n, max_dim=d)
    assert len(cx) == sum(math.comb(n, k) for k in range(1, d + 2))
    assert len(set(cx)) == len(cx) and all(list(s) == sorted(s) for s in cx)
    faces = {f for s in cx for k in range(1, len(s)) for f in itertools.combinations(s, k)}
    assert faces <= set(cx)


def test_full_skeleton_bad_counts():
    with pytest.raises(ValueError, match="n_vertices"):
        full_skeleton(0, max_dim=1)
    with pytest.raises(ValueError, match="max_dim"):
        full_skeleton(3, max_dim=-1)


def test_theorem_2_6_on_full_skeleta():
    for d in (1, 2):
        cx = full_skeleton(7, max_dim=d)
        assert realization_failures(cx, moment_curve(7, 2 * d + 1)) == 0
        assert realization_failures(cx, moment_curve(7, 2 * d)) > 0


@pytest.mark.parametrize("seed", range(6))
def test_affine_dimension_equals_the_exact_rank(seed):
    rng = np.random.default_rng(seed)
    n, ambient, k = int(rng.integers(1, 7)), 5, int(rng.integers(0, 5))
    basis = rng.integers(-3, 4, size=(k, ambient))
    pts = rng.integers(-2, 3, size=(n, k)) @ basis + rng.integers(-5, 5, size=ambient)  # inside a k-flat
    exact = sympy.Matrix((pts[1:] - pts[0]).tolist()).rank() if n > 1 else 0
    assert affine_dimension(pts.astype(float)) == exact <= k


def test_affine_dimension_of_random_sets_is_full_and_bad_input():
    rng = np.random.default_rng(21)
    assert [affine_dimension(rng.random((q + 1, 5))) for q in range(6)] == [0, 1, 2, 3, 4, 5]
    with pytest.raises(ValueError):
        affine_dimension(np.zeros((0, 2)))


def test_barycentric_coordinates_rebuild_the_points():
    rng = np.random.default_rng(2)
    for d in (1, 2, 3):
        simplex, pts = rng.random((d + 1, d)), rng.random((7, d))
        lam = barycentric_coordinates(simplex, pts)
        assert lam.shape == (7, d + 1)
        assert lam.sum(axis=1) == pytest.approx(np.ones(7))
        assert lam @ simplex == pytest.approx(pts)
    tri = np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 1.2]])  # Figure 2.2 (b): both points lie inside edge 0-1
    lam = barycentric_coordinates(tri, [[0.6, 0.0], [1.4, 0.0], [1.0, 0.4]])
    assert np.isclose(lam, 0).sum(axis=1).tolist() == [1, 1, 0]


@pytest.mark.parametrize("simplex, points, match", [
    ([[0.0, 0.0], [1.0, 0.0]], [[0.0, 0.0]], "d \\+ 1"),
    ([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], [[0.0, 0.0, 0.0]], "d \\+ 1"),
    ([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]], [[0.0, 0.0]], "degenerate"),
])
def test_barycentric_coordinates_bad_input(simplex, points, match):
    with pytest.raises(ValueError, match=match):
        barycentric_coordinates(simplex, points)


def test_clockwise_triangles_against_the_shoelace_area():
    chart = rp2_chart()
    tris = rp2(oriented=True)
    assert clockwise_triangles(tris, chart) == 10
    assert clockwise_triangles([t[::-1] for t in tris], chart) == 0
    rng = np.random.default_rng(4)
    pts = rng.random((6, 2))
    tris = [tuple(int(v) for v in rng.permutation(6)[:3]) for _ in range(30)]
    own = {tuple(sorted(t)): [tuple(pts[v]) for v in sorted(t)] for t in tris}
    def area(a, b, c):  # the shoelace formula: negative when a, b, c turn clockwise
        (x1, y1), (x2, y2), (x3, y3) = pts[a], pts[b], pts[c]
        return 0.5 * (x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2))

    assert clockwise_triangles(tris, own) == sum(area(*t) < 0 for t in tris)


def test_clockwise_triangles_bad_input():
    with pytest.raises(ValueError, match="not a triangle"):
        clockwise_triangles([(0, 1, 2)], {})
    with pytest.raises(ValueError, match="not a triangle"):
        clockwise_triangles([(0, 1)], {(0, 1): [(0.0, 0.0), (1.0, 0.0)]})

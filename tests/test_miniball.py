"""Smallest enclosing ball (Miniball, §2.1.2): exact cases, Jung's bound, independent cross-checks."""

import gudhi
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import minimize
from scipy.spatial.distance import pdist

from thesis_lib.complexes.miniball import circumball, meb_radius_small, smallest_enclosing_ball


def test_exact_cases():
    c, r = smallest_enclosing_ball([[0.0, 0.0], [2.0, 0.0]])
    np.testing.assert_allclose(c, [1, 0])
    assert r == pytest.approx(1.0)
    # equilateral triangle of side 1: circumradius 1/sqrt(3)
    tri = np.array([[0, 0], [1, 0], [0.5, np.sqrt(3) / 2]])
    assert smallest_enclosing_ball(tri)[1] == pytest.approx(1 / np.sqrt(3))
    # obtuse triangle: the ball on the longest edge
    obtuse = np.array([[0, 0], [4, 0], [2, 0.5]])
    c, r = smallest_enclosing_ball(obtuse)
    np.testing.assert_allclose(c, [2, 0], atol=1e-12)
    assert r == pytest.approx(2.0)
    # regular simplex in R^n (standard basis vectors of R^(n+1)): radius sqrt(n / (n + 1))
    for n in (2, 3, 5):
        assert smallest_enclosing_ball(np.eye(n + 1))[1] == pytest.approx(np.sqrt(n / (n + 1)))
        assert meb_radius_small(np.eye(n + 1)) == pytest.approx(np.sqrt(n / (n + 1)))
    # one point; repeated points
    assert smallest_enclosing_ball([[3.0, 4.0]])[1] == 0.0
    assert smallest_enclosing_ball([[1.0, 1.0]] * 5 + [[3.0, 1.0]])[1] == pytest.approx(1.0)
    assert meb_radius_small(np.array([[1.0, 1.0], [1.0, 1.0]])) == 0.0


def test_circumball():
    c, r2 = circumball(np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]]))
    np.testing.assert_allclose(c, [1, 1, 0])
    assert r2 == pytest.approx(2.0)


@pytest.mark.parametrize("bad", [[[0.0, np.nan]], [[np.inf, 0.0]], np.zeros((0, 2)), [1.0, 2.0]])
def test_bad_input(bad):
    with pytest.raises(ValueError):
        smallest_enclosing_ball(bad)


def _optimised_radius(pts):
    f = lambda c: np.max(np.sum((pts - c) ** 2, axis=1))  # noqa: E731
    best = np.inf
    for start in (pts.mean(axis=0), pts[0], (pts.max(0) + pts.min(0)) / 2):
        res = minimize(f, start, method="Nelder-Mead", options={"xatol": 1e-10, "fatol": 1e-14, "maxiter": 20000})
        best = min(best, res.fun)
    return np.sqrt(best)


@pytest.mark.parametrize("dim", [2, 3, 4])
def test_against_optimisation_and_subset_search(dim):
    rng = np.random.default_rng(dim)
    for _ in range(5):
        pts = rng.normal(size=(rng.integers(2, dim + 3), dim))
        c, r = smallest_enclosing_ball(pts)
        assert np.sqrt(((pts - c) ** 2).sum(1)).max() <= r * (1 + 1e-9)
        assert r == pytest.approx(_optimised_radius(pts), rel=1e-4)
        assert r == pytest.approx(meb_radius_small(pts), rel=1e-9)


def test_against_gudhi_delaunay_cech():
    # GUDHI's Delaunay–Čech values are squared minimal enclosing radii of Delaunay simplices
    pts = np.random.default_rng(7).random((40, 3))
    st_ = gudhi.DelaunayCechComplex(points=pts).create_simplex_tree()
    checked = 0
    for s, v in st_.get_simplices():
        if len(s) >= 2:
            assert smallest_enclosing_ball(pts[s])[1] == pytest.approx(np.sqrt(v), rel=1e-9)
            checked += 1
    assert checked > 100


@settings(deadline=None, max_examples=30)
@given(st.integers(0, 100_000), st.integers(1, 60), st.integers(1, 6))
def test_properties(seed, n, dim):
    rng = np.random.default_rng(seed)
    pts = rng.normal(size=(n, dim)) * rng.uniform(0.1, 10)
    c, r = smallest_enclosing_ball(pts, seed=seed)
    # encloses every point
    assert np.sqrt(((pts - c) ** 2).sum(1)).max() <= r * (1 + 1e-9) + 1e-12
    if n > 1:
        diam = pdist(pts).max()
        # Jung's theorem (Theorem 2.10) and the trivial lower bound diam / 2
        assert r <= diam * np.sqrt(dim / (2 * (dim + 1))) * (1 + 1e-9)
        assert r >= diam / 2 * (1 - 1e-9)
    # independent of the random order and of translations
    assert smallest_enclosing_ball(pts[::-1], seed=seed + 1)[1] == pytest.approx(r, rel=1e-9, abs=1e-12)
    shifted = smallest_enclosing_ball(pts + 3.0)
    assert shifted[1] == pytest.approx(r, rel=1e-9, abs=1e-12)
    np.testing.assert_allclose(shifted[0], c + 3.0, rtol=1e-7, atol=1e-7 * max(r, 1))

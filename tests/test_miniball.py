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


# ----------------------------------------------------------------------------- extreme scales
def _exact_radius(pts, digits=60):
    """The smallest enclosing radius of ``pts`` by subset search in mpmath (``digits`` digits)."""
    import itertools

    import mpmath

    mpmath.mp.dps = digits
    P = [[mpmath.mpf(float(v)) for v in row] for row in pts]
    n, d = len(P), len(P[0])
    best = None
    for k in range(1, d + 2):
        for sub in itertools.combinations(range(n), k):
            p0 = P[sub[0]]
            a = [[P[i][t] - p0[t] for t in range(d)] for i in sub[1:]]
            if a:
                gram = mpmath.matrix([[2 * sum(x * y for x, y in zip(u, v)) for v in a] for u in a])
                rhs = mpmath.matrix([sum(x * x for x in u) for u in a])
                try:
                    lam = mpmath.lu_solve(gram, rhs)
                except ZeroDivisionError:
                    continue
                c = [p0[t] + sum(lam[i] * a[i][t] for i in range(len(a))) for t in range(d)]
            else:
                c = list(p0)
            r2 = sum((c[t] - p0[t]) ** 2 for t in range(d))
            if all(sum((q[t] - c[t]) ** 2 for t in range(d)) <= r2 * (1 + mpmath.mpf(10) ** (-40)) for q in P):
                best = r2 if best is None else min(best, r2)
    return mpmath.sqrt(best)


@pytest.mark.parametrize("k", [1000, 600, 0, -600, -1000, -1040, -1060, -1068])
@pytest.mark.parametrize("dim", [2, 3])
def test_extreme_scales_contain_every_point_and_give_the_scaled_radius(dim, k):
    """At 1e300 the ball contains every point (no tolerance of the search lets a point 1e-12 outside);
    at tiny scales the radius is the exact one scaled by 2^k, up to the
    rounding of the centre among the subnormal numbers.  Checked exactly (fractions) and against a
    60-digit reference."""
    from fractions import Fraction

    import mpmath

    rng = np.random.default_rng(1000 * dim + k)
    for trial in range(3):
        unit = rng.random((7, dim))
        pts = np.ldexp(unit, k)
        if not np.array_equal(np.ldexp(pts, -k), unit):  # subnormal: the input itself is rounded
            unit = np.ldexp(pts, -k)
        centre, r = smallest_enclosing_ball(pts)
        fc, fr = [Fraction(float(v)) for v in centre], Fraction(r)
        for p in pts:  # the ball contains every point, exactly
            assert sum((Fraction(float(x)) - c) ** 2 for x, c in zip(p, fc)) <= fr * fr
        exact = _exact_radius(unit) * mpmath.mpf(2) ** k  # the radius scales with the points
        spacing = float(np.ldexp(1.0, -1074)) if r < 2.0**-1000 else 0.0  # subnormal numbers' spacing
        assert mpmath.mpf(r) >= exact * (1 - mpmath.mpf(2) ** -60)
        assert mpmath.mpf(r) - exact <= exact * 2e-15 + 2 * dim * spacing, (trial, r, exact)


def test_all_points_equal_at_tiny_scales_have_radius_zero():
    for v in (1e-300, 5e-324, 1e300, -2.0**-1060):
        assert smallest_enclosing_ball([[v, v]] * 4)[1] == 0.0
    assert smallest_enclosing_ball([[0.0, 0.0], [5e-324, 0.0]])[1] == 5e-324  # 2.5e-324 rounded up


def test_a_radius_beyond_the_float_range_is_refused():
    m = np.finfo(np.float64).max
    with pytest.raises(ValueError, match="radius of the smallest enclosing ball exceeds float64's range"):
        smallest_enclosing_ball([[m, m, m], [-m, -m, -m]])
    assert smallest_enclosing_ball([[m, 0.0], [-m, 0.0]])[1] == m  # the largest radius that fits

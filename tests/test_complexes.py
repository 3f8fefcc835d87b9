"""Complexes of §2.1.2: Rips, Čech, Delaunay, alpha, witness, nerve — values against GUDHI / brute force."""

import itertools

import gudhi
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.distance import pdist, squareform

from thesis_lib.complexes import (
    alpha,
    cech,
    delaunay,
    lazy_witness,
    maxmin_landmarks,
    nerve,
    random_landmarks,
    rips,
    witness,
    witness_offsets,
)
from thesis_lib.complexes.miniball import smallest_enclosing_ball
from thesis_lib.datasets import two_circles


def as_dict(f):
    return {s: v for s, v in f}


def gudhi_dict(st_):
    return {tuple(s): v for s, v in st_.get_simplices()}


def assert_valid(f):
    """Faces before cofaces, values non-decreasing along the order (DESIGN.md)."""
    seen, last = set(), -np.inf
    for s, v in f:
        assert v >= last
        assert all(s[:i] + s[i + 1 :] in seen for i in range(len(s))) if len(s) > 1 else True
        seen.add(s)
        last = v


# ----------------------------------------------------------------------------------------- Rips
@pytest.mark.parametrize("dim, eps, max_dim", [(2, 0.25, 2), (3, 0.3, 3), (5, 0.6, 2)])
def test_rips_equals_gudhi(dim, eps, max_dim):
    pts = np.random.default_rng(dim).random((50, dim))
    f = rips(pts, max_radius=eps, max_dim=max_dim)
    ref = gudhi_dict(gudhi.RipsComplex(points=pts, max_edge_length=2 * eps).create_simplex_tree(max_dimension=max_dim))
    ours = as_dict(f)
    assert set(ours) == set(ref)
    # GUDHI's values are diameters = 2 ε (Definition 2.11: diameter <= 2 ε)
    assert max(abs(2 * ours[s] - ref[s]) for s in ref) < 1e-12
    assert_valid(f)


def test_rips_kd_tree_path_equals_gudhi():
    # more than 2000 points in low dimension: edges come from a k-d tree instead of all pairs
    from thesis_lib._core import flag_complex
    from thesis_lib.complexes._flag import edges_within

    pts = np.random.default_rng(9).random((2500, 3))
    a, b = edges_within(pts, 0.06), flag_complex.pairwise_edges(pts, 0.06)  # k-d tree vs brute force
    np.testing.assert_array_equal(a[0], b[0])
    np.testing.assert_array_equal(a[1], b[1])
    f = rips(pts, max_radius=0.04, max_dim=3)
    ref = gudhi_dict(gudhi.RipsComplex(points=pts, max_edge_length=0.08).create_simplex_tree(max_dimension=3))
    ours = as_dict(f)
    assert set(ours) == set(ref)
    assert max(abs(2 * ours[s] - ref[s]) for s in ref) < 1e-12


def test_rips_distance_matrix_and_rows_sorted():
    pts = np.random.default_rng(1).random((30, 2))
    a = rips(pts, max_radius=0.3, max_dim=3)
    b = rips(distance_matrix=squareform(pdist(pts)), max_radius=0.3, max_dim=3)
    assert a.counts() == b.counts()
    for x, y in zip(a.simplices, b.simplices):
        np.testing.assert_array_equal(x, y)
        assert np.all(np.diff(x, axis=1) > 0)
        assert x.shape[0] < 2 or np.all(np.lexsort(x.T[::-1]) == np.arange(x.shape[0]))
    for x, y in zip(a.values, b.values):
        np.testing.assert_allclose(x, y, rtol=1e-14)


def test_rips_thesis_size_two_circles():
    # §2.4.1: 60 points per circle, ε <= 2, simplices up to dimension 2 -> 288,100 (every triple)
    f = rips(two_circles(60), max_radius=2.0, max_dim=2)
    assert len(f) == 288_100 and f.counts() == [120, 7140, 280840]
    assert len(rips(two_circles(60), max_radius=1.0, max_dim=2)) == 181_427  # diameter <= 2 (MEASUREMENTS.md)


def test_rips_small_cases():
    f = rips([[0.0, 0.0], [3.0, 4.0]], max_radius=10, max_dim=3)
    assert list(f) == [((0,), 0.0), ((1,), 0.0), ((0, 1), 2.5)]
    assert rips([[0.0], [1.0]], max_radius=0.4, max_dim=1).counts() == [2]
    assert rips([[0.0], [1.0]], max_radius=0.5, max_dim=0).counts() == [2]


# ----------------------------------------------------------------------------------------- Čech
def test_cech_values_and_gudhi_delaunay_cech():
    pts = np.random.default_rng(3).random((35, 2))
    f = cech(pts, max_radius=0.2, max_dim=3)
    assert_valid(f)
    ours = as_dict(f)
    for s, v in itertools.islice(ours.items(), 0, None, 7):
        assert v == pytest.approx(smallest_enclosing_ball(pts[list(s)])[1], rel=1e-9, abs=1e-15)
        assert v <= 0.2
    common = 0
    ref = gudhi.DelaunayCechComplex(points=pts).create_simplex_tree()  # keep alive while iterating
    for s, v in ref.get_simplices():
        s = tuple(s)
        if s in ours:
            assert ours[s] == pytest.approx(np.sqrt(v), rel=1e-9, abs=1e-15)
            common += 1
        else:
            assert np.sqrt(v) > 0.2 * (1 - 1e-12)
    assert common > 80


def test_cech_brute_force_membership():
    pts = np.random.default_rng(4).random((12, 3))
    f = as_dict(cech(pts, max_radius=0.3, max_dim=3))
    for k in range(1, 5):
        for s in itertools.combinations(range(12), k):
            r = smallest_enclosing_ball(pts[list(s)])[1]
            assert (s in f) == (r <= 0.3), s


@settings(deadline=None, max_examples=12)
@given(st.integers(0, 10_000), st.integers(4, 16), st.integers(2, 4), st.floats(0.1, 0.5))
def test_lemma_2_12_and_jung(seed, n, dim, eps):
    """R(X, ε) ⊆ C(X, √2 ε) ⊆ R(X, √2 ε) (Lemma 2.12); Čech radius <= Jung's bound (Theorem 2.10)."""
    pts = np.random.default_rng(seed).random((n, dim))
    r_small = set(as_dict(rips(pts, max_radius=eps, max_dim=3)))
    c = as_dict(cech(pts, max_radius=np.sqrt(2) * eps * (1 + 1e-12), max_dim=3))
    r_big = set(as_dict(rips(pts, max_radius=np.sqrt(2) * eps * (1 + 1e-12), max_dim=3)))
    assert r_small <= set(c) <= r_big
    rv = as_dict(rips(pts, max_radius=np.inf, max_dim=3))
    for s, v in c.items():
        # Jung: radius <= diam sqrt(n / (2 (n + 1))) with diam = 2 × Rips value; Čech >= Rips value
        assert v <= 2 * rv[s] * np.sqrt(dim / (2 * (dim + 1))) * (1 + 1e-9)
        assert v >= rv[s] * (1 - 1e-12)


# ------------------------------------------------------------------------------------- Delaunay
@pytest.mark.parametrize("dim", [2, 3])
def test_delaunay_equals_gudhi(dim):
    rng = np.random.default_rng(10 + dim)
    pts = rng.random((60, dim))
    ours = delaunay(pts)
    assert ours == sorted(ours, key=lambda s: (len(s), s))
    assert set(ours) == set(gudhi_dict(gudhi.DelaunayComplex(points=pts).create_simplex_tree()))
    w = rng.random(60) * 0.02
    ref = gudhi_dict(gudhi.AlphaComplex(points=pts, weights=w).create_simplex_tree())
    assert set(delaunay(pts, w)) == set(ref)


def test_delaunay_cospherical_is_the_nerve():
    # four co-circular points: the Voronoi cells meet in one vertex, so the nerve holds the 3-simplex
    square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    out = delaunay(square)
    assert (0, 1, 2, 3) in out and len(out) == 15
    grid = np.array([[i, j] for i in range(3) for j in range(3)], float)
    out = delaunay(grid)
    assert sum(len(s) == 4 for s in out) == 4  # one 3-simplex per unit square
    # a 3 × 3 × 3 grid: eight unit cubes, each with its 8 corners on one sphere -> eight 7-simplices
    cube = np.array(list(itertools.product(range(3), repeat=3)), float)
    out = delaunay(cube)
    tops = [s for s in out if len(s) == 8]
    assert len(tops) == 8 and max(len(s) for s in out) == 8
    assert all(np.ptp(cube[list(s)], axis=0).max() == 1 for s in tops)
    # the 36 integer points on the circle of radius 65 are exactly co-circular (floats on a circle
    # from cos and sin are not: co-sphericity is decided exactly)
    ring = np.array([(x, y) for x in range(-65, 66) for y in range(-65, 66) if x * x + y * y == 65 * 65], float)
    assert len(ring) == 36
    with pytest.raises(ValueError, match="36 points lie on one empty sphere"):
        delaunay(ring)


def test_weighted_delaunay_hides_points():
    pts = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [2.0, 2.0], [1.0, 1.0]])
    assert (4,) in delaunay(pts)
    # a tiny point at the centre under big balls at the corners has an empty power cell
    # (hidden iff its lifted point |x|² − w lies above the lower hull: 0 > 2 − w for the corners)
    out = delaunay(pts, [2.5, 2.5, 2.5, 2.5, 0.0])
    assert (4,) not in out and (0, 1) in out


# ---------------------------------------------------------------------------------------- alpha
@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("weighted", [False, True])
def test_alpha_equals_gudhi(dim, weighted):
    rng = np.random.default_rng(100 * dim + weighted)
    for _ in range(3):
        pts = rng.random((70, dim))
        w = rng.random(70) * 0.01 if weighted else None
        f = alpha(pts, w)
        ref = gudhi_dict(gudhi.AlphaComplex(points=pts, weights=w, precision="exact").create_simplex_tree())
        ours = as_dict(f)
        assert set(ours) == set(ref)
        got = np.array([ours[s] for s in ref])
        exp = np.array([ref[s] for s in ref])
        np.testing.assert_allclose(got, exp, rtol=1e-6, atol=1e-12)
        assert_valid(f)
        if weighted:
            # an unattached weighted vertex enters at -w (DESIGN.md)
            # (an attached one enters later, with an edge)
            own = -w[f.simplices[0][:, 0]]
            assert np.all(f.values[0] >= own - 1e-15)
            assert np.sum(np.isclose(f.values[0], own, rtol=1e-12, atol=0)) >= 0.5 * f.counts()[0]


def test_alpha_attached_edge():
    # obtuse triangle: the long edge's smallest circle contains the third vertex, so the edge is
    # attached and enters with the triangle (squared circumradius), not at (half its length)²
    pts = np.array([[0.0, 0.0], [4.0, 0.0], [2.0, 0.5]])
    f = as_dict(alpha(pts))
    c, r = smallest_enclosing_ball(pts)
    circum = ((4.0**2 / 4 + 0.5**2) / (2 * 0.5)) ** 2  # R = (a²/4 + h²) / (2h) for the isosceles triangle
    assert f[(0, 1, 2)] == pytest.approx(circum)
    assert f[(0, 1)] == pytest.approx(circum)
    assert f[(0, 2)] == pytest.approx((np.hypot(2, 0.5) / 2) ** 2)
    assert f[(0,)] == 0.0


# -------------------------------------------------------------------------------------- witness
def _brute_witness(D, eps, max_dim):
    out = {}
    for k in range(1, max_dim + 2):
        for s in itertools.combinations(range(D.shape[0]), k):
            v = max(0.0, D[list(s)].max(axis=0).min())
            if v <= eps:
                out[s] = v
    return out


@pytest.mark.parametrize("nu", [0, 1, 2])
def test_witness_brute_force(nu):
    rng = np.random.default_rng(nu)
    pts = rng.random((250, 2))
    lm = maxmin_landmarks(pts, n=11, seed=0)
    f = witness(pts, lm, max_radius=0.2, max_dim=3, nu=nu)
    D = witness_offsets(pts, lm, nu=nu)
    ref = _brute_witness(D, 0.2, 3)
    ours = as_dict(f)
    assert set(ours) == set(ref)
    assert max(abs(ours[s] - ref[s]) for s in ref) == 0.0
    assert_valid(f)
    # the thesis's rule: max_i |l_i - x| <= ε + m_k(x) for some x, m_k = (k+1)-th nearest, ν = k + 1
    dist = np.sqrt(((pts[lm][:, None, :] - pts[None]) ** 2).sum(-1))
    m = np.sort(dist, axis=0)[nu - 1] if nu else 0.0
    for s in list(ref)[::5]:
        assert np.any(dist[list(s)].max(axis=0) <= ours[s] + m + 1e-12)


def test_witness_full_complex_uses_shortcuts_correctly():
    # all simplices up to dimension 3 (ε = inf), values against brute force: exercises both the
    # lower-bound shortcut and the full scans
    pts = np.random.default_rng(5).random((400, 3))
    lm = random_landmarks(pts, n=14, seed=1)
    f = witness(pts, lm, max_radius=np.inf, max_dim=3)
    ref = _brute_witness(witness_offsets(pts, lm, nu=1), np.inf, 3)
    ours = as_dict(f)
    assert len(ours) == len(ref) == 14 + 91 + 364 + 1001
    assert max(abs(ours[s] - ref[s]) for s in ref) == 0.0


@settings(deadline=None, max_examples=15)
@given(st.integers(0, 10_000), st.integers(20, 150), st.integers(3, 9), st.integers(0, 2), st.floats(0.0, 0.6))
def test_witness_random_against_brute_force(seed, n, n_landmarks, nu, eps):
    pts = np.random.default_rng(seed).random((n, 3))
    lm = random_landmarks(pts, n=n_landmarks, seed=seed)
    ours = as_dict(witness(pts, lm, max_radius=eps, max_dim=3, nu=nu))
    ref = _brute_witness(witness_offsets(pts, lm, nu=nu), eps, 3)
    assert ours == ref


def test_witness_kernel_paths_agree():
    # the sorted-prefix scan, the gathered scan and the full scan give identical children and values
    from thesis_lib._core import witness_complex

    pts = np.random.default_rng(8).random((3000, 4))
    lm = maxmin_landmarks(pts, n=16, seed=0)
    D = np.ascontiguousarray(witness_offsets(pts, lm, nu=1))
    ev, arg = witness_complex.edge_values(D)
    order = np.argsort(D, axis=1, kind="stable")
    sorted_d = np.ascontiguousarray(np.take_along_axis(D, order, axis=1))
    tri = np.array(list(itertools.combinations(range(16), 3)))
    for eps in (np.inf, 0.3):
        a = witness_complex.witness_level(tri, D, ev, arg, eps, witness_complex.SortedDistances(order, sorted_d, True),
                                          n_threads=2)
        b = witness_complex.witness_level(tri, D, ev, arg, eps, witness_complex.SortedDistances(order, sorted_d, False),
                                          n_threads=1)
        np.testing.assert_array_equal(a[0], b[0])
        np.testing.assert_array_equal(a[1], b[1])


def test_witness_matches_gudhi_strong_witness_at_zero():
    # GUDHI's EuclideanStrongWitnessComplex uses squared distances, value min_x max_l (d² − m²); the
    # two rules agree on which simplices are witnessed at ε = 0 (max d <= m  <=>  max d² <= m²)
    rng = np.random.default_rng(11)
    pts = rng.random((300, 2))
    lm = maxmin_landmarks(pts, n=12, seed=3)
    ref = gudhi_dict(
        gudhi.EuclideanStrongWitnessComplex(landmarks=pts[lm], witnesses=pts).create_simplex_tree(
            max_alpha_square=0.05, limit_dimension=3
        )
    )
    ours = as_dict(witness(pts, lm, max_radius=np.inf, max_dim=3, nu=1))
    assert {s for s, v in ours.items() if v == 0} == {s for s, v in ref.items() if v <= 0}
    # the same values after squaring, brute force
    dist = np.sqrt(((pts[lm][:, None, :] - pts[None]) ** 2).sum(-1))
    m = dist.min(axis=0)
    for s, v in ref.items():
        assert v == pytest.approx(max(0.0, (dist[list(s)] ** 2 - m**2).max(axis=0).min()), abs=1e-12)


def test_lazy_witness_is_flag_and_contains_witness():
    pts = np.random.default_rng(2).random((300, 2))
    lm = maxmin_landmarks(pts, n=15, seed=0)
    lazy = as_dict(lazy_witness(pts, lm, max_radius=0.15, max_dim=3))
    strict = as_dict(witness(pts, lm, max_radius=0.15, max_dim=3))
    assert set(strict) <= set(lazy)
    for s, v in lazy.items():
        if len(s) == 2:
            assert v == strict[s]  # same rule on edges
        if len(s) > 2:
            assert v == max(lazy[e] for e in itertools.combinations(s, 2))  # flag complex
            if s in strict:
                assert v <= strict[s]


# ---------------------------------------------------------------------------------------- nerve
def test_nerve_examples():
    assert nerve([{1, 2}, {2, 3}, {3, 1}]) == [(0,), (1,), (2,), (0, 1), (0, 2), (1, 2)]  # a circle
    assert nerve([{1, 2}, {2}, {2, 5}]) == [(0,), (1,), (2,), (0, 1), (0, 2), (1, 2), (0, 1, 2)]
    assert nerve([{1}, set(), {1}], max_dim=0) == [(0,), (2,)]
    with pytest.raises(ValueError):
        nerve([{1}], max_dim=-1)
    with pytest.raises(ValueError):
        nerve([1, 2])


def test_nerve_of_balls_is_cech():
    # Definition 2.9: C(X, ε) is the nerve of the balls; sample the plane finely and compare
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 0.8], [2.2, 0.1]])
    eps = 0.56
    g = np.stack(np.meshgrid(np.linspace(-1, 3, 801), np.linspace(-1, 2, 601)), -1).reshape(-1, 2)
    cover = [set(np.flatnonzero(np.hypot(*(g - p).T) <= eps).tolist()) for p in pts]
    assert nerve(cover) == sorted(as_dict(cech(pts, max_radius=eps, max_dim=3)), key=lambda s: (len(s), s))


@settings(deadline=None, max_examples=25)
@given(st.lists(st.sets(st.integers(0, 8), max_size=5), min_size=1, max_size=7))
def test_nerve_brute_force(cover):
    expected = [
        s
        for k in range(1, len(cover) + 1)
        for s in itertools.combinations(range(len(cover)), k)
        if set.intersection(*(set(cover[i]) for i in s))
    ]
    assert nerve(cover) == expected


# ------------------------------------------------------------------------------ invariants
@settings(deadline=None, max_examples=10)
@given(st.integers(0, 10_000), st.integers(8, 30))
def test_relabelling_invariance(seed, n):
    rng = np.random.default_rng(seed)
    pts = rng.random((n, 2))
    perm = rng.permutation(n)
    for build in (lambda p: rips(p, max_radius=0.3, max_dim=2), lambda p: cech(p, max_radius=0.3, max_dim=2), alpha):
        a, b = build(pts), build(pts[perm])
        assert a.counts() == b.counts()
        np.testing.assert_allclose(np.sort(np.concatenate(a.values)), np.sort(np.concatenate(b.values)),
                                   rtol=1e-7, atol=1e-12)
        assert_valid(b)
    assert len(delaunay(pts)) == len(delaunay(pts[perm]))


# ------------------------------------------------------------------------------------ bad input
GOOD = np.random.default_rng(0).random((10, 2))


@pytest.mark.parametrize(
    "call, msg",
    [
        (lambda: rips([[0.0, np.nan], [1.0, 1.0]], max_radius=1.0, max_dim=2), "NaN"),
        (lambda: cech([[np.inf, 0.0]], max_radius=1.0, max_dim=2), "NaN or infinite"),
        (lambda: alpha([[0.0, np.nan], [1, 0], [0, 1]]), "NaN"),
        (lambda: rips(GOOD, max_radius=-1.0, max_dim=2), "non-negative"),
        (lambda: cech(GOOD, max_radius=float("nan"), max_dim=2), "NaN"),
        (lambda: witness(GOOD, [0, 1], max_radius=-0.5, max_dim=2), "non-negative"),
        (lambda: rips(GOOD, max_radius=1.0, max_dim=-1), "max_dim"),
        (lambda: cech(GOOD, max_radius=1.0, max_dim=1.5), "max_dim"),
        (lambda: lazy_witness(GOOD, [0, 1], max_radius=1.0, max_dim=-2), "max_dim"),
        (lambda: rips(), "exactly one"),
        (lambda: rips(distance_matrix=[[0, 1], [2, 0]]), "symmetric"),
        (lambda: rips(distance_matrix=[[0, -1], [-1, 0]]), "negative"),
        (lambda: delaunay([[0.0, 0.0], [1.0, 1.0]]), "at least 3 points"),
        (lambda: alpha([[0.0, 0.0, 0.0], [1, 0, 0], [0, 1, 0]]), "at least 4 points"),
        (lambda: delaunay([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]), "affinely dependent"),
        (lambda: alpha([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 0.0]]), "duplicate"),
        (lambda: delaunay(GOOD, -np.ones(10)), "squared radii"),
        (lambda: alpha(GOOD, np.ones(9)), "one weight per point"),
        (lambda: alpha(GOOD, np.full(10, np.nan)), "NaN"),
        (lambda: witness(GOOD, np.arange(11), max_radius=1.0, max_dim=2), "11 landmarks but only 10 points"),
        (lambda: witness(GOOD, [0, 0], max_radius=1.0, max_dim=2), "repeat"),
        (lambda: witness(GOOD, [0, 10], max_radius=1.0, max_dim=2), "indices"),
        (lambda: witness(GOOD, [0.5, 1.0], max_radius=1.0, max_dim=2), "integer"),
        (lambda: witness(GOOD, [0, 1], max_radius=1.0, max_dim=2, nu=3), "exceeds"),
        (lambda: lazy_witness(GOOD, [0, 1], max_radius=1.0, max_dim=2, nu=-1), "nu"),
        (lambda: maxmin_landmarks(GOOD, n=11, seed=0), "cannot choose"),
    ],
)
def test_bad_input(call, msg):
    with pytest.raises(ValueError, match=msg):
        call()


@settings(deadline=None, max_examples=10)
@given(st.integers(0, 10_000), st.integers(8, 60), st.sampled_from([2, 3]), st.booleans())
def test_alpha_random_against_gudhi(seed, n, dim, weighted):
    rng = np.random.default_rng(seed)
    pts = rng.random((n, dim))
    w = rng.random(n) * 0.01 if weighted else None
    ours = as_dict(alpha(pts, w))
    ref = gudhi_dict(gudhi.AlphaComplex(points=pts, weights=w, precision="exact").create_simplex_tree())
    assert set(ours) == set(ref)
    for s, v in ref.items():
        assert ours[s] == pytest.approx(v, rel=1e-6, abs=1e-12)


# ------------------------------------------------------------------------------------ landmarks
def test_landmarks():
    pts = np.random.default_rng(4).random((300, 2))
    lm = maxmin_landmarks(pts, n=25, seed=2)
    assert len(set(lm.tolist())) == 25
    np.testing.assert_array_equal(lm, maxmin_landmarks(pts, n=25, seed=2))
    d = np.sqrt(((pts[:, None, :] - pts[None]) ** 2).sum(-1))
    for i in range(1, 25):
        # the sequential maxmin rule (§2.1.2): the i-th landmark is farthest from the first i - 1
        nearest = d[:, lm[:i]].min(axis=1)
        assert nearest[lm[i]] == pytest.approx(nearest.max())
    rnd = random_landmarks(pts, n=25, seed=2)
    assert np.all(np.diff(rnd) > 0) and rnd.max() < 300
    from thesis_lib.complexes import covering_radius

    assert covering_radius(pts, lm) == pytest.approx(d[:, lm].min(axis=1).max())
    # maxmin covers better than random here, as the thesis observes (Figure 2.13)
    assert covering_radius(pts, lm) < covering_radius(pts, rnd)
    with pytest.raises(ValueError, match="number of landmarks must be >= 1"):
        random_landmarks(pts, n=0, seed=0)


def test_landmarks_on_duplicate_points():
    # maxmin returned a repeated index once the distinct points were exhausted
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [1.0, 0.0], [0.5, 3.0]])
    for seed in range(5):
        lm = maxmin_landmarks(pts, n=5, seed=seed)
        assert sorted(lm.tolist()) == [0, 1, 2, 3, 4]
        # the distinct points come first, then copies (at distance 0)
        assert len({tuple(pts[i]) for i in lm[:3]}) == 3


def test_covering_radius_checks_indices():
    from thesis_lib.complexes import covering_radius

    pts = np.random.default_rng(0).random((10, 2))
    # a negative index is refused (numpy would wrap it), an index too large too (not an IndexError)
    with pytest.raises(ValueError, match="indices in 0..9"):
        covering_radius(pts, [0, -1])
    with pytest.raises(ValueError, match="indices in 0..9"):
        covering_radius(pts, [0, 10])
    with pytest.raises(ValueError, match="empty"):
        covering_radius(pts, [])
    with pytest.raises(TypeError, match="integer"):
        covering_radius(pts, [0.5])
    assert covering_radius(pts, np.arange(10)) == 0.0


def test_nerve_refuses_explosions_and_deep_chains(monkeypatch):
    import importlib

    nerve_module = importlib.import_module("thesis_lib.complexes.nerve")

    # 64 sets sharing an element: C(64, 6) = 75 million simplices up to dimension 5, refused by the cap
    monkeypatch.setattr(nerve_module, "MAX_NERVE_SIMPLICES", 10_000)
    with pytest.raises(ValueError, match="more than 10,000 simplices"):
        nerve([{0, i} for i in range(64)], max_dim=5)
    # a chain of 3000 consecutive overlaps goes 2 deep only; the search must not recurse per set
    chain = [{i, i + 1} for i in range(3000)]
    out = nerve(chain)
    assert len(out) == 3000 + 2999 and max(len(s) for s in out) == 2
    # 1500 sets with one common element: the full simplex; the search must not recurse 1500 deep
    with pytest.raises(ValueError, match="more than 10,000"):
        nerve([{0}] * 1500)

"""The compiled exact-geometry kernels (src/predicate_filters.cpp, miniball.cpp, triangulation.cpp,
alpha_complex.cpp): bad shapes and out-of-range indices are refused with ValueError (never a crash),
and the filters' answers are right where they decide."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from thesis_lib._core import alpha_complex, miniball, predicate_filters, triangulation

PTS = np.random.default_rng(0).random((10, 3))
W = np.zeros(10)
S = np.array([[0, 1, 2, 3], [4, 5, 6, 7]], dtype=np.int64)
Y = np.array([8, 9], dtype=np.int64)


def exact_orient(pts, row):
    x = [[Fraction(float(v)) for v in pts[i]] for i in row]
    m = [[a - b for a, b in zip(xi, x[0])] for xi in x[1:]]

    def det(a):
        if len(a) == 1:
            return a[0][0]
        return sum((-1) ** j * a[0][j] * det([r[:j] + r[j + 1:] for r in a[1:]]) for j in range(len(a)))

    d = det(m)
    return (d > 0) - (d < 0)


def test_orient_filter_signs_are_exact_where_decided():
    rng = np.random.default_rng(1)
    for d in (2, 3, 4):
        pts = np.vstack([rng.random((20, d)), np.round(rng.random((20, d)) * 3)])  # grids: zero determinants
        simp = rng.integers(0, 40, (200, d + 1)).astype(np.int64)
        sign = predicate_filters.orient_filter(pts, simp)
        assert sign.dtype == np.int8
        decided = np.flatnonzero(sign)
        assert decided.size > 100
        for r in decided:
            assert sign[r] == exact_orient(pts, simp[r])
        for r in range(0, 200, 13):
            assert predicate_filters.orient_one(pts, simp[r]) == sign[r]


def test_insphere_one_equals_the_batch():
    rng = np.random.default_rng(2)
    pts, w = rng.random((15, 2)), rng.random(15) * 0.01
    simp = rng.integers(0, 15, (40, 3)).astype(np.int64)
    y = rng.integers(0, 15, 40).astype(np.int64)
    batch = predicate_filters.insphere_filter(pts, w, simp, y)
    assert [predicate_filters.insphere_one(pts, w, simp[r], int(y[r])) for r in range(40)] == batch.tolist()


def test_orthoball_of_a_triangle_is_its_circumcircle():
    pts = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])
    centre, r2, err, flag = predicate_filters.orthoball_float(pts, np.zeros(3), np.array([[0, 1, 2]]), 100.0)
    assert centre.tolist() == [[1.0, 1.0]] and r2.tolist() == [2.0] and flag.dtype == np.bool_ and not flag[0]
    assert err[0] >= 0
    # a point far outside: certain positive power; the centre's own vertex: power 0, undecided
    far = np.vstack([pts, [[10.0, 10.0]]])
    sign = predicate_filters.power_filter(far, np.zeros(4), centre, r2, err, np.array([[0, 1, 2]]),
                                          np.array([0, 0]), np.array([3, 0]))
    assert sign.tolist() == [1, 0]


def test_orthoball_flags_singular_rows():
    pts = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]])  # collinear: every system singular
    centre, r2, err, flag = predicate_filters.orthoball_float(pts, np.zeros(3), np.array([[0, 1, 2]]), 100.0)
    assert flag[0] and np.isnan(r2[0]) and np.isinf(err[0]) and centre[0].tolist() == [0.0, 0.0]


def test_meb_radius_small_and_meb_radii():
    tri = np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 0.1]])  # obtuse: the ball of the long edge
    assert miniball.meb_radius_small(tri) == 1.0
    assert miniball.meb_radius_small(np.zeros((3, 2))) == 0.0
    assert miniball.meb_radius_small(np.zeros((0, 2))) == 0.0
    radii = miniball.meb_radii(tri, np.array([[0, 1, 2], [0, 1, 1], [2, 2, 2]], dtype=np.int64))
    assert radii.tolist() == [1.0, 1.0, 0.0]


def test_hint_pairs_and_facet_ids():
    tri = np.array([[0, 1, 2], [1, 2, 3]], dtype=np.int64)
    nb = np.array([[1, -1, -1], [-1, -1, 0]], dtype=np.int64)
    s1, i1, s2, i2, ok = triangulation.hint_pairs(tri, nb)
    assert (s1.tolist(), i1.tolist(), s2.tolist(), i2.tolist(), ok.tolist()) == ([0], [0], [1], [2], [True])
    bad = np.array([[1, -1, -1], [0, -1, -1]], dtype=np.int64)  # the facets do not match
    assert triangulation.hint_pairs(tri, bad)[4].tolist() == [False]
    ids, rep_s, rep_i = alpha_complex.facet_ids(nb)
    assert ids.tolist() == [[0, 1, 2], [3, 4, 0]]
    assert rep_s.tolist() == [0, 0, 0, 1, 1] and rep_i.tolist() == [0, 1, 2, 0, 1]
    out = alpha_complex.coface_min(ids, np.array([0.5, 0.25]), 6)
    assert out.tolist() == [0.25, 0.5, 0.5, 0.25, 0.25, np.inf]


@pytest.mark.parametrize("call", [
    lambda: predicate_filters.orient_filter(PTS, np.array([[0, 1, 2]], dtype=np.int64)),  # too few columns
    lambda: predicate_filters.orient_filter(PTS, np.array([[0, 1, 2, 10]], dtype=np.int64)),
    lambda: predicate_filters.orient_filter(PTS, np.array([[0, 1, 2, -1]], dtype=np.int64)),
    lambda: predicate_filters.orient_filter(np.zeros((3, 0)), np.zeros((1, 1), dtype=np.int64)),
    lambda: predicate_filters.orient_filter(np.zeros((3, 40)), np.zeros((1, 41), dtype=np.int64)),
    lambda: predicate_filters.orient_one(PTS, np.array([0, 1, 2], dtype=np.int64)),
    lambda: predicate_filters.orient_one(PTS, np.array([0, 1, 2, 99], dtype=np.int64)),
    lambda: predicate_filters.insphere_filter(PTS, W[:5], S, Y),
    lambda: predicate_filters.insphere_filter(PTS, W, S, Y[:1]),
    lambda: predicate_filters.insphere_filter(PTS, W, S, np.array([8, 10], dtype=np.int64)),
    lambda: predicate_filters.insphere_filter(PTS, W, S + 3, Y),
    lambda: predicate_filters.insphere_one(PTS, W, S[0], 10),
    lambda: predicate_filters.insphere_one(PTS, W, S[0], -1),
    lambda: predicate_filters.orthoball_float(PTS, W, S + 7, 100.0),
    lambda: predicate_filters.orthoball_float(PTS, W[:3], S, 100.0),
    lambda: predicate_filters.orthoball_float(PTS, W, np.zeros((2, 0), dtype=np.int64), 100.0),
    lambda: predicate_filters.power_filter(PTS, W, np.zeros((2, 3)), np.zeros(2), np.zeros(2), S,
                                           np.array([2], dtype=np.int64), np.array([0], dtype=np.int64)),
    lambda: predicate_filters.power_filter(PTS, W, np.zeros((2, 3)), np.zeros(2), np.zeros(2), S,
                                           np.array([1], dtype=np.int64), np.array([10], dtype=np.int64)),
    lambda: predicate_filters.power_filter(PTS, W, np.zeros((2, 2)), np.zeros(2), np.zeros(2), S,
                                           np.array([1], dtype=np.int64), np.array([0], dtype=np.int64)),
    lambda: predicate_filters.power_filter(PTS, W, np.zeros((2, 3)), np.zeros(1), np.zeros(2), S,
                                           np.array([1], dtype=np.int64), np.array([0], dtype=np.int64)),
    lambda: predicate_filters.power_filter(PTS, W, np.zeros((2, 3)), np.zeros(2), np.zeros(2), S + 7,
                                           np.array([1], dtype=np.int64), np.array([0], dtype=np.int64)),
    lambda: predicate_filters.power_filter(PTS, W, np.zeros((2, 3)), np.zeros(2), np.zeros(2), S,
                                           np.array([1, 0], dtype=np.int64), np.array([0], dtype=np.int64)),
    lambda: miniball.meb_radius_small(np.zeros((63, 2))),
    lambda: miniball.meb_radii(PTS, np.array([[0, 10]], dtype=np.int64)),
    lambda: miniball.meb_radii(PTS, np.array([[0, -1]], dtype=np.int64)),
    lambda: triangulation.hint_pairs(S, np.array([[1, -1, -1, -1], [0, 2, -1, -1]], dtype=np.int64)),
    lambda: triangulation.hint_pairs(S, np.zeros((2, 3), dtype=np.int64)),
    lambda: triangulation.hint_pairs(S, np.zeros((1, 4), dtype=np.int64)),
    lambda: alpha_complex.facet_ids(np.array([[1, -1], [2, -1]], dtype=np.int64)),
    lambda: alpha_complex.coface_min(np.array([[0, 3]], dtype=np.int64), np.zeros(1), 3),
    lambda: alpha_complex.coface_min(np.array([[0, -1]], dtype=np.int64), np.zeros(1), 3),
    lambda: alpha_complex.coface_min(np.array([[0, 1]], dtype=np.int64), np.zeros(2), 3),
    lambda: alpha_complex.coface_min(np.zeros((0, 2), dtype=np.int64), np.zeros(0), -1),
])
def test_bad_shapes_and_indices_are_refused(call):
    with pytest.raises(ValueError):
        call()


def test_wrong_dimensions_are_refused_by_the_binding():
    with pytest.raises(TypeError):
        predicate_filters.orient_filter(PTS[0], S)
    with pytest.raises(TypeError):
        miniball.meb_radii(PTS, S.ravel())


def test_empty_inputs():
    assert predicate_filters.orient_filter(PTS, np.zeros((0, 4), dtype=np.int64)).shape == (0,)
    assert predicate_filters.insphere_filter(PTS, W, np.zeros((0, 4), dtype=np.int64),
                                             np.zeros(0, dtype=np.int64)).shape == (0,)
    c, r2, e, f = predicate_filters.orthoball_float(PTS, W, np.zeros((0, 3), dtype=np.int64), 100.0)
    assert c.shape == (0, 3) and r2.shape == e.shape == f.shape == (0,)
    assert [a.shape for a in triangulation.hint_pairs(np.zeros((0, 3), dtype=np.int64),
                                                      np.zeros((0, 3), dtype=np.int64))] == [(0,)] * 5
    ids, rs, ri = alpha_complex.facet_ids(np.zeros((0, 3), dtype=np.int64))
    assert ids.shape == (0, 3) and rs.shape == ri.shape == (0,)
    assert miniball.meb_radii(PTS, np.zeros((0, 3), dtype=np.int64)).shape == (0,)

"""Smooth Morse theory examples (thesis §4.1): Example 4.2, Theorems 4.6–4.7, Examples 4.17–4.19."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.morse.smooth import (
    morse_index,
    morse_inequalities,
    rp2_morse_complex,
    sphere_morse_complex,
    torus_critical_points,
    torus_height,
    torus_height_gradient,
    torus_height_hessian,
    torus_morse_complex,
)


def test_example_4_2_critical_points_and_indices():
    R, r = 2.0, 0.5
    crit = torus_critical_points(R=R, r=r)
    assert len(crit) == 4
    assert [c["index"] for c in crit] == [0, 1, 1, 2]  # r, q_1, q_2, p
    assert np.allclose([c["value"] for c in crit], [-(R + r), -(R - r), R - r, R + r])
    # points on the z-axis: p = (0, 0, R + r), q_2 = (0, 0, R - r), q_1 = (0, 0, -R + r), r = (0, 0, -R - r)
    assert np.allclose([c["point"] for c in crit], [(0, 0, -R - r), (0, 0, -R + r), (0, 0, R - r), (0, 0, R + r)],
                       atol=1e-9)
    uv = sorted((round(c["u"], 6), round(c["v"], 6)) for c in crit)
    assert np.allclose(uv, sorted([(0, 0), (0, np.pi), (np.pi, np.pi), (np.pi, 0)]), atol=1e-6)
    # the Hessians of the thesis
    assert np.allclose(torus_height_hessian(0, 0, R=R, r=r), np.diag([-(R + r), -r]))
    assert np.allclose(torus_height_hessian(0, np.pi, R=R, r=r), np.diag([-R + r, r]))
    assert np.allclose(torus_height_hessian(np.pi, np.pi, R=R, r=r), np.diag([R - r, -r]))
    assert np.allclose(torus_height_hessian(np.pi, 0, R=R, r=r), np.diag([R + r, r]))
    # β_k = Crit_k for the torus (§4.1.1): counts 1, 2, 1
    counts = np.bincount([c["index"] for c in crit], minlength=3).tolist()
    assert counts == [1, 2, 1]
    assert morse_inequalities(counts, [1, 2, 1]) == {"weak": True, "euler": True, "strong": True}


@settings(deadline=None, max_examples=20)
@given(st.floats(0.2, 5.0), st.floats(0.05, 0.95), st.floats(0, 2 * np.pi), st.floats(0, 2 * np.pi))
def test_height_derivatives_match_finite_differences(R, ratio, u, v):
    r = R * ratio
    h = 1e-6
    g = torus_height_gradient(u, v, R=R, r=r)
    fd = [(torus_height(u + h, v, R=R, r=r) - torus_height(u - h, v, R=R, r=r)) / (2 * h),
          (torus_height(u, v + h, R=R, r=r) - torus_height(u, v - h, R=R, r=r)) / (2 * h)]
    assert np.allclose(g, fd, atol=1e-5)
    H = torus_height_hessian(u, v, R=R, r=r)
    def grad(a, b):
        return torus_height_gradient(a, b, R=R, r=r)

    fdh = np.column_stack([(grad(u + h, v) - grad(u - h, v)) / (2 * h), (grad(u, v + h) - grad(u, v - h)) / (2 * h)])
    assert np.allclose(H, fdh, atol=1e-4)


@settings(deadline=None, max_examples=6)
@given(st.floats(1.0, 4.0), st.floats(0.1, 0.9))
def test_critical_points_for_any_radii(R, ratio):
    crit = torus_critical_points(R=R, r=R * ratio, grid=6)
    assert [c["index"] for c in crit] == [0, 1, 1, 2]


def test_morse_index_and_errors():
    assert morse_index(np.diag([-1.0, 2.0, -3.0])) == 2
    with pytest.raises(ValueError, match="degenerate"):
        morse_index(np.diag([1.0, 0.0]))
    with pytest.raises(ValueError, match="square"):
        morse_index(np.ones(3))
    with pytest.raises(ValueError, match="symmetric"):
        morse_index(np.array([[1.0, 2.0], [0.0, 1.0]]))
    with pytest.raises(ValueError, match="R > r > 0"):
        torus_critical_points(R=1.0, r=2.0)
    with pytest.raises(ValueError, match="R > r > 0"):
        torus_height(0.0, 0.0, R=np.nan, r=1.0)
    with pytest.raises(ValueError, match="grid"):
        torus_critical_points(grid=1)
    with pytest.raises(ValueError, match="non-negative"):
        morse_inequalities([1, -1], [1])


def test_morse_inequalities_detect_failures():
    assert morse_inequalities([1, 0, 1], [1, 2, 1])["weak"] is False  # too few index-1 points on a torus
    res = morse_inequalities([1, 3, 1], [1, 2, 1])
    assert res["weak"] and not res["euler"]
    # strong inequality at k = 1 fails: β_1 - β_0 = 0 > Crit_1 - Crit_0 = -1, while the weak ones hold
    assert morse_inequalities([2, 1], [1, 1]) == {"weak": True, "euler": False, "strong": False}


def test_example_4_18_sphere():
    names, mats, hom = sphere_morse_complex()
    assert names == [["r1", "r2"], ["q1", "q2"], ["p1", "p2"]]
    assert mats[2].toarray().tolist() == [[1, 1], [1, 1]]  # ∂p_i = q_1 + q_2
    assert mats[1].toarray().tolist() == [[1, -1], [-1, 1]]  # ∂q_1 = r_1 - r_2, ∂q_2 = r_2 - r_1
    assert not (mats[1] @ mats[2]).toarray().any()
    assert hom == [(1, []), (0, []), (1, [])]
    # ker ∂_2 = <(1, -1)>, im ∂_2 = <(1, 1)> (Example 4.18)
    assert not (mats[2] @ np.array([1, -1])).any()
    assert (mats[2] @ np.array([1, 0])).tolist() == [1, 1]


def test_examples_4_17_and_4_19_mod_2():
    names, mats, hom = rp2_morse_complex()
    assert [m.toarray().tolist() for m in mats[1:]] == [[[2]], [[2]]]  # two flow lines each
    assert hom == [(1, []), (1, []), (1, [])]
    names, mats, hom = torus_morse_complex()
    assert hom == [(1, []), (2, []), (1, [])]

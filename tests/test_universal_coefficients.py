"""The universal-coefficient prediction of Betti numbers (homology.universal_coefficient_betti) and the
displays of Example 2.21 (homology.group_latex, smith.diagonal_text), against direct computations."""

from __future__ import annotations

from functools import partial

import numpy as np
import pytest
import sympy
from sympy.matrices.normalforms import smith_normal_form as sympy_snf

from thesis_lib.datasets import dunce_hat, klein_bottle, rp2, sphere, torus
from thesis_lib.homology import betti_numbers, group_latex, homology, universal_coefficient_betti
from thesis_lib.homology.smith import diagonal_text, smith_normal_form


@pytest.mark.parametrize("make", [rp2, klein_bottle, torus, dunce_hat, partial(sphere, 2), partial(sphere, 3)])
@pytest.mark.parametrize("q", [2, 3, 5, 7])
def test_prediction_equals_the_homology_over_z_q(make, q):
    cx = make()
    assert universal_coefficient_betti(homology(cx), coefficients=q) == betti_numbers(cx, coefficients=q)


def test_prediction_with_odd_torsion_by_hand():
    # H = (Z, Z ⊕ Z/6, Z/9): over Z/3 both 6 and 9 count, over Z/2 only 6
    integral = [(1, []), (1, [6]), (0, [9])]
    assert universal_coefficient_betti(integral, coefficients=2) == [1, 2, 1]
    assert universal_coefficient_betti(integral, coefficients=3) == [1, 2, 2]
    assert universal_coefficient_betti(integral, coefficients=5) == [1, 1, 0]


@pytest.mark.parametrize("q", [0, 4, 1])
def test_prediction_needs_a_prime(q):
    with pytest.raises(ValueError):
        universal_coefficient_betti(homology(rp2()), coefficients=q)


def test_group_latex_of_rp2_and_by_hand():
    assert [group_latex(r, t) for r, t in homology(rp2())] == ["$\\mathbb{Z}$", "$\\mathbb{Z}/2$", "$0$"]
    klein = ["$\\mathbb{Z}$", "$\\mathbb{Z} \\oplus \\mathbb{Z}/2$", "$0$"]
    assert [group_latex(r, t) for r, t in homology(klein_bottle())] == klein
    assert group_latex(3, []) == "$\\mathbb{Z}^{3}$"
    with pytest.raises(ValueError, match="rank"):
        group_latex(-1, [])
    with pytest.raises(ValueError, match="torsion"):
        group_latex(1, [1])


@pytest.mark.parametrize("seed", range(5))
def test_diagonal_text_against_sympys_smith_form(seed):
    rng = np.random.default_rng(seed)
    a = rng.integers(-3, 4, size=(5, 4)) * rng.integers(1, 3, size=(1, 4))
    diag = [abs(int(x)) for x in sympy.Matrix(sympy_snf(sympy.Matrix(a.tolist()))).diagonal() if x != 0]
    ones = diag.count(1)
    assert diagonal_text(smith_normal_form(a)) == ", ".join([f"1 ({ones} times)"] + [str(x) for x in diag if x != 1])


def test_diagonal_text_of_example_2_21_and_bad_input():
    from thesis_lib.homology import boundary_matrices
    from thesis_lib.homology.simplicial import closure

    mats = boundary_matrices(closure(rp2()))
    assert diagonal_text(smith_normal_form(mats[2])) == "1 (9 times), 2"
    assert diagonal_text(smith_normal_form(mats[1])) == "1 (5 times)"
    with pytest.raises(ValueError, match="positive"):
        diagonal_text([1, 0])

"""The work of Algorithms 1–2 (thesis_lib.persistence.complexity), counted by hand and fitted."""

from __future__ import annotations

import doctest
import itertools

import numpy as np
import pytest

from thesis_lib.datasets import dense_filtration
from thesis_lib.persistence import complexity
from thesis_lib.persistence.complexity import WorkGrowth, algorithm_work, work_growth, work_table


def path(n):
    return [((v,), 0.0) for v in range(n)] + [((v, v + 1), 1.0) for v in range(n - 1)]


def test_work_counted_by_hand():
    # a path: each edge's boundary (2 entries) is stored at once, no subtraction
    assert algorithm_work(path(5)) == 2 * 4
    # a hollow triangle ab, bc, ca: ca = {a, c}; minus T[c] = bc (2 entries) gives {a, b}; minus
    # T[b] = ab (2 entries) gives 0, so 6 + 4
    hollow = [((0,), 0), ((1,), 0), ((2,), 0), ((0, 1), 1), ((1, 2), 1), ((0, 2), 1)]
    assert algorithm_work(hollow) == 10
    # the filled triangle adds its boundary (3 entries); ca is marked, so the unmarked ab and bc are
    # dropped and nothing is subtracted
    assert algorithm_work(hollow + [((0, 1, 2), 2)]) == 13


def test_work_is_bounded_below_by_the_boundaries_and_above_by_the_cubic_bound():
    for n, seed in itertools.product((6, 9), (0, 1)):
        K = dense_filtration(n, seed=seed)
        boundaries = sum((d + 1) * len(K.simplices[d]) for d in range(1, K.dimension + 1))
        assert boundaries <= algorithm_work(K) <= len(K) ** 3


def test_fit_recovers_a_known_exponent():
    # work = 2(n − 1) and m = 2n − 1 on paths: the slope of log work against log m tends to 1
    growth = work_growth([path(n) for n in (100, 400, 1600)])
    assert growth.simplices.tolist() == [199, 799, 3199]
    assert growth.work.tolist() == [198, 798, 3198]
    x, y = np.log(growth.simplices), np.log(growth.work)
    slope = np.sum((x - x.mean()) * (y - y.mean())) / np.sum((x - x.mean()) ** 2)  # least squares, by hand
    assert growth.exponent == pytest.approx(slope, rel=1e-12) and growth.exponent == pytest.approx(1.0, abs=0.01)
    # the dense family grows faster than linearly, slower than the cubic bound
    dense = work_growth([dense_filtration(n, seed=0) for n in (8, 12, 16)])
    assert 1.0 < dense.exponent < 3.0


def test_a_fit_needs_two_sizes():
    with pytest.raises(ValueError, match="two different sizes"):
        work_growth([path(5), path(5)])


def test_work_table_rows():
    rows = work_table({"paths: n": WorkGrowth(np.array([19.0, 199.0]), np.array([18.0, 198.0]), 1.0228),
                       "dense": WorkGrowth(np.array([175.0, 2951.0]), np.array([1.0, 2.0]), 1.664501813)})
    assert rows[0] == ["family", "simplices $m$", "fitted $a$ in work $\\propto m^a$"]
    assert rows[1:] == [["paths: n", "19–199", "1.0"], ["dense", "175–2951", "1.7"]]


def test_docstring_examples_run():
    result = doctest.testmod(complexity)
    assert result.attempted > 3 and result.failed == 0

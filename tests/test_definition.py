"""Persistent Betti numbers by Definition 2.23 over grids, and their comparison with barcodes (Theorem 2.37)."""

from __future__ import annotations

import doctest

import numpy as np
import pytest

from thesis_lib.complexes import alpha, cech, rips
from thesis_lib.datasets import example_filtration, module_filtration, noisy_circle
from thesis_lib.homology import homology
from thesis_lib.persistence import Barcode, compute_intervals, definition, persistence
from thesis_lib.persistence.definition import (
    barcode_betti_grid,
    barcode_definition_mismatches,
    betti_versus_barcode,
    definition_mismatches,
    persistent_betti_grid,
)

EX_2_36 = [(0, None), (1, None), (2, 2)]


def brute_force_count(intervals, l, k):
    """Bars [b, d) spanning [l, l + k], counted one by one."""
    return sum(1 for b, d in intervals if b <= l and d > l + k)


def test_the_grid_of_example_2_36():
    # the intervals (0, ∞), (1, ∞), (2, 4) of Example 2.36: β^{l,k} counts those spanning [l, l + k]
    grid = persistent_betti_grid(module_filtration(EX_2_36), ls=range(5), ks=range(4), dim=1)
    printed = [(0, np.inf), (1, np.inf), (2, 4)]
    assert grid == [[brute_force_count(printed, l, k) for k in range(4)] for l in range(5)]
    assert grid[2][1] == 3 and grid[2][2] == 2
    assert all(isinstance(x, int) for row in grid for x in row)


def test_barcode_grid_is_the_brute_force_count():
    bars = persistence(cech(noisy_circle(25, noise=0.1, seed=1), max_radius=1.0, max_dim=2))
    ls, ks = [0.1, 0.2, 0.5], [0.0, 0.05, 0.3]
    assert barcode_betti_grid(bars, ls=ls, ks=ks, dim=1) == [
        [brute_force_count(bars.intervals(1), l, k) for k in ks] for l in ls]


def test_no_mismatch_on_the_examples_and_a_planted_one_is_found():
    K = example_filtration()
    assert definition_mismatches([K, module_filtration(EX_2_36)], ls=range(6), ks=range(6), dims=(0, 1),
                                 fields=(2, 3)) == (2 * 2 * 6 * 6 * 2, 0)
    good = compute_intervals(K)
    assert barcode_definition_mismatches(good, K, ls=range(6), ks=range(6), dims=(0, 1)) == (72, 0)
    # a barcode that lost the H₁ bar (3, 4): β₁^{3,0} is 2 by the definition, 1 by the count
    h1 = good.intervals(1)
    wrong = Barcode({0: good.intervals(0), 1: h1[h1[:, 0] != 3]}, coefficients=2)
    cases, bad = barcode_definition_mismatches(wrong, K, ls=range(6), ks=range(6), dims=(1,))
    assert cases == 36 and bad == 1  # only (l, k) = (3, 0) spans [3, 3] and not [3, 4]


@pytest.mark.parametrize("seed", range(3))
def test_random_rips_filtrations_over_two_fields(seed):
    grid = np.round(np.linspace(0.0, 0.5, 6), 2)
    K = rips(np.random.default_rng(seed).random((8, 2)), max_radius=0.5, max_dim=2)
    assert definition_mismatches([K], ls=grid, ks=grid, dims=(0, 1), fields=(2, 3)) == (144, 0)


def test_squared_values_compare_cech_with_alpha():
    # the alpha filtration's values are squared radii; its ranks at (l², (l + k)² − l²) are the Čech counts
    points = noisy_circle(30, noise=0.08, seed=2)
    bars = persistence(cech(points, max_radius=1.0, max_dim=2))
    ls, ks = [0.15, 0.3, 0.6], [0.0, 0.1, 0.3]
    assert barcode_definition_mismatches(bars, alpha(points), ls=ls, ks=ks, dims=(0, 1), squared_values=True) == (18, 0)
    # without the squares they differ somewhere
    assert barcode_definition_mismatches(bars, alpha(points), ls=ls, ks=ks, dims=(1,))[1] > 0


def test_betti_numbers_of_sublevel_complexes_miss_what_the_barcode_shows():
    # §2.3.1: a circle born at 0 filled at 2, another born at 2
    swap = module_filtration([(0, 2), (2, None)])
    seen = betti_versus_barcode(swap, steps=range(5), dim=1, l=0, k=2)
    # β₁ of each K^l by homology of the complex itself
    assert seen.betti == tuple(homology(swap.threshold(l), coefficients=2)[1][0] for l in range(5)) == (1,) * 5
    assert seen.n_bars == 2 and seen.persistent_betti == 0


def test_docstring_examples_run():
    result = doctest.testmod(definition)
    assert result.attempted > 5 and result.failed == 0

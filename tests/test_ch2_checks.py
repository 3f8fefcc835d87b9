"""The independent checks of §2.1–2.3: union of discs on a pixel grid, moment-curve realizations,
persistent Betti numbers from Definition 2.23."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from thesis_lib.complexes import alpha, cech, rips
from thesis_lib.complexes.realization import moment_curve, realization_failures
from thesis_lib.complexes.union import union_of_discs_betti
from thesis_lib.datasets import example_filtration, module_filtration
from thesis_lib.homology import homology
from thesis_lib.persistence import Barcode
from thesis_lib.persistence.definition import persistent_betti_by_definition


# ---------------------------------------------------------------------------- union of discs
def test_union_of_discs_simple_shapes():
    assert union_of_discs_betti([[0.0, 0.0]], 0.3, pixel=0.01) == (1, 0)
    assert union_of_discs_betti([[0.0, 0.0], [2.0, 0.0]], 0.3, pixel=0.01) == (2, 0)
    angles = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    ring = np.c_[np.cos(angles), np.sin(angles)]
    assert union_of_discs_betti(ring, 0.2, pixel=0.005) == (1, 1)   # overlapping discs around a hole
    assert union_of_discs_betti(ring, 1.2, pixel=0.01) == (1, 0)    # the hole is covered
    assert union_of_discs_betti(ring, 0.1, pixel=0.005) == (24, 0)  # disjoint discs


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_union_of_discs_agrees_with_the_cech_complex_away_from_critical_radii(seed):
    pts = np.random.default_rng(seed).random((12, 2))
    f = cech(pts, max_radius=2.0, max_dim=2)
    values = np.unique(np.concatenate([np.asarray(v) for v in f.values]))
    gaps = np.diff(values)
    k = int(np.argmax(gaps))
    eps = float(values[k] + gaps[k] / 2)  # the middle of the widest gap between entry radii
    if gaps[k] < 0.02:
        pytest.skip("no radius far from every entry radius")
    b = [x for x, _ in homology([s for s, v in f if v <= eps], coefficients=2)] + [0]
    assert union_of_discs_betti(pts, eps, pixel=0.002) == (b[0], b[1])


def test_union_of_discs_refuses_bad_input():
    with pytest.raises(ValueError, match="planar"):
        union_of_discs_betti(np.zeros((3, 3)), 0.1, pixel=0.01)
    with pytest.raises(ValueError, match="positive"):
        union_of_discs_betti([[0.0, 0.0]], 0.0, pixel=0.01)
    with pytest.raises(ValueError, match="too large"):
        union_of_discs_betti([[0.0, 0.0], [100.0, 100.0]], 1.0, pixel=1e-3)


# ---------------------------------------------------------------------------- Theorem 2.6
def test_moment_curve_realizes_full_skeleta():
    for d, n in ((1, 6), (2, 6)):
        cx = [s for k in range(1, d + 2) for s in itertools.combinations(range(n), k)]
        assert realization_failures(cx, moment_curve(n, 2 * d + 1)) == 0
        # in R^{2d}, 2d + 2 points are always affinely dependent: every pair of disjoint d-simplices fails
        top = [s for s in cx if len(s) == d + 1]
        disjoint = sum(1 for a, b in itertools.combinations(top, 2) if not set(a) & set(b))
        assert realization_failures(cx, moment_curve(n, 2 * d)) >= disjoint > 0


def test_realization_failures_sees_a_degenerate_placement():
    points = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0)]  # vertices 0, 1, 2 on a line
    assert realization_failures([(0, 1, 2)], points) == 1
    assert realization_failures([(0, 1), (1, 3)], points) == 0
    with pytest.raises(ValueError):
        moment_curve(0, 3)


# ---------------------------------------------------------------------------- Definition 2.23
def gudhi_bars(f, p):
    pairs = f.to_simplex_tree().persistence(homology_coeff_field=p, min_persistence=0.0, persistence_dim_max=True)
    return Barcode.from_pairs(pairs, dimensions=range(f.dimension + 1))


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("p", [2, 3])
def test_definition_agrees_with_gudhi_barcodes(seed, p):
    f = rips(np.random.default_rng(seed).random((9, 2)), max_radius=0.5, max_dim=2)
    bars = gudhi_bars(f, p)
    for l, k in itertools.product(np.linspace(0, 0.5, 6), np.linspace(0, 0.4, 5)):
        for dim in (0, 1):
            assert persistent_betti_by_definition(f, l, k, dim, coefficients=p) == bars.persistent_betti(l, k, dim=dim)


def test_definition_on_the_thesis_examples():
    f = module_filtration([(0, None), (1, None), (2, 2)], dim=1)
    assert [persistent_betti_by_definition(f, 2, k, 1) for k in range(4)] == [3, 3, 2, 2]
    K = example_filtration()
    assert persistent_betti_by_definition(K, 2, 0, 1) == 1  # z₁ born at 2
    assert persistent_betti_by_definition(K, 3, 0, 1) == 2 and persistent_betti_by_definition(K, 3, 1, 1) == 1
    assert persistent_betti_by_definition(K, 4, 0, 0) == 1 and persistent_betti_by_definition(K, 0, 0, 0) == 2
    assert persistent_betti_by_definition(K, 4, 0, 3) == 0  # above the dimension of K


def test_definition_on_alpha_matches_the_squared_barcode():
    pts = np.random.default_rng(5).random((15, 2))
    a = alpha(pts)
    bars = gudhi_bars(a, 2)
    for l, k in ((0.002, 0.0), (0.01, 0.005), (0.02, 0.01)):
        assert persistent_betti_by_definition(a, l, k, 1) == bars.persistent_betti(l, k, dim=1)


def test_definition_refuses_bad_input():
    K = example_filtration()
    with pytest.raises(ValueError):
        persistent_betti_by_definition(K, 1, -1, 0)
    with pytest.raises(ValueError):
        persistent_betti_by_definition(K, math.nan, 1, 0)
    with pytest.raises(ValueError):
        persistent_betti_by_definition(K, 1, 1, -1)
    with pytest.raises(ValueError):
        persistent_betti_by_definition(K, 1, 1, 0, coefficients=4)

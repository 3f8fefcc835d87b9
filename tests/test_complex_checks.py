"""The numerical checks of §2.1.2 (chapters.complex_checks), each against an independent computation:
brute-force enclosing circles, gudhi's flag and alpha complexes, scipy's Delaunay triangulation."""

from __future__ import annotations

import itertools

import gudhi
import numpy as np
import pytest
from scipy.spatial import Delaunay

from thesis_lib.chapters.complex_checks import (
    JungCheck,
    alpha_not_in_cech,
    barcodes_differing,
    betti_text,
    cech_rips_ratios,
    cliques,
    jung_bound,
    jung_ratios,
    missing_simplices,
    voronoi_nerve,
    weighted_alpha_losses,
)
from thesis_lib.complexes import alpha, cech, delaunay, rips, witness
from thesis_lib.homology import betti_numbers
from thesis_lib.homology.filtration import Filtration
from thesis_lib.persistence import persistence


def circle_radius(points: np.ndarray) -> float:
    """The smallest enclosing circle by brute force: the best circle through 2 or 3 of the points."""
    best = np.inf
    for a, b in itertools.combinations(points, 2):
        centre, r = (a + b) / 2, np.linalg.norm(a - b) / 2
        if np.all(np.linalg.norm(points - centre, axis=1) <= r * (1 + 1e-12)):
            best = min(best, r)
    for a, b, c in itertools.combinations(points, 3):
        m = np.array([b - a, c - a])
        if abs(np.linalg.det(m)) < 1e-14:
            continue
        centre = a + np.linalg.solve(2 * m, [np.dot(b - a, b - a), np.dot(c - a, c - a)])
        r = np.linalg.norm(centre - a)
        if np.all(np.linalg.norm(points - centre, axis=1) <= r * (1 + 1e-12)):
            best = min(best, r)
    return float(best)


def test_jung_bound_is_the_circumradius_of_the_unit_regular_simplex():
    assert jung_bound(dim=1) == pytest.approx(0.5)
    assert jung_bound(dim=2) == pytest.approx(1 / np.sqrt(3))
    assert jung_bound(dim=3) == pytest.approx(np.sqrt(6) / 4)  # circumradius of the unit tetrahedron
    with pytest.raises(ValueError, match="dim"):
        jung_bound(dim=0)


def test_jung_ratios_match_brute_force_circles_on_the_same_draws():
    checks = jung_ratios(dims=(2,), n_sets=60, max_points=6, seed=3)
    assert checks == jung_ratios(dims=(2,), n_sets=60, max_points=6, seed=3)
    rng = np.random.default_rng(3)  # the same draws, enclosing circles found independently
    ratios = []
    for _ in range(60):
        sample = rng.random((int(rng.integers(2, 7)), 2))
        diam = max(np.linalg.norm(a - b) for a, b in itertools.combinations(sample, 2))
        ratios.append(circle_radius(sample) / diam)
    (check,) = checks
    assert isinstance(check, JungCheck) and check.dim == 2
    assert check.largest_ratio == pytest.approx(max(ratios), rel=1e-9)
    assert check.largest_ratio <= check.bound
    assert check.regular_ratio == pytest.approx(1.0, abs=1e-9)


def test_jung_ratios_in_space_stay_below_the_bound_and_the_simplex_attains_it():
    (check,) = jung_ratios(dims=(4,), n_sets=40, seed=1)
    assert check.bound == pytest.approx(np.sqrt(4 / 10))
    assert 0.5 <= check.largest_ratio <= check.bound  # at least half the diameter, at most Jung
    assert check.regular_ratio == pytest.approx(1.0, abs=1e-9)


@pytest.mark.parametrize("kwargs, match", [
    ({"dims": (0,)}, "dim"), ({"n_sets": 0}, "n_sets"), ({"max_points": 1}, "max_points"), ({"seed": -1}, "seed"),
])
def test_jung_ratios_bad_options(kwargs, match):
    with pytest.raises(ValueError, match=match):
        jung_ratios(**kwargs)
    with pytest.raises(TypeError, match="seed"):
        jung_ratios(seed=1.5)


def test_cech_rips_ratios_against_brute_force_circles():
    pts = np.random.default_rng(11).random((9, 2))
    ratios = cech_rips_ratios(pts, max_radius=2.0, max_dim=2)
    expected = []
    for k in (2, 3):
        for s in itertools.combinations(range(9), k):
            sub = pts[list(s)]
            diam = max(np.linalg.norm(a - b) for a, b in itertools.combinations(sub, 2))
            expected.append(circle_radius(sub) / (diam / 2))
    assert len(ratios) == len(expected) == 36 + 84
    assert np.sort(ratios) == pytest.approx(np.sort(expected), rel=1e-9)
    assert ratios.min() >= 1 - 1e-12 and ratios.max() <= 2 / np.sqrt(3) + 1e-12  # Lemma 2.12 and Jung


def test_cech_rips_ratios_needs_every_rips_simplex_in_the_cech_filtration():
    with pytest.raises(ValueError, match="max_radius"):
        cech_rips_ratios([[0.0, 0.0], [1.0, 0.0], [0.5, 0.8660254]], max_radius=0.55, max_dim=2)


def test_cliques_are_gudhis_flag_complex():
    pts = np.random.default_rng(4).random((25, 2))
    st = gudhi.RipsComplex(points=pts, max_edge_length=0.45).create_simplex_tree(max_dimension=3)
    flag = {tuple(s) for s, _ in st.get_simplices()}
    edges = [s for s in flag if len(s) == 2]
    assert cliques(edges, n_vertices=25, max_dim=3) == flag
    assert {c for c in cliques(edges, n_vertices=25, max_dim=1)} == {s for s in flag if len(s) <= 2}


def test_cliques_equal_our_rips_complex():
    pts = np.random.default_rng(8).random((20, 3))
    ours = {tuple(map(int, s)) for s, _ in rips(pts, max_radius=0.3, max_dim=3)}
    assert cliques([s for s in ours if len(s) == 2], n_vertices=20, max_dim=3) == ours


@pytest.mark.parametrize("edges, kwargs, match", [
    ([(0, 1)], {"n_vertices": 0, "max_dim": 1}, "n_vertices"),
    ([(0, 1)], {"n_vertices": 2, "max_dim": -1}, "max_dim"),
    ([(0, 2)], {"n_vertices": 2, "max_dim": 1}, "pairs"),
    ([(0, 1, 2)], {"n_vertices": 3, "max_dim": 1}, "pairs"),
    ([(1, 1)], {"n_vertices": 3, "max_dim": 1}, "pairs"),
])
def test_cliques_bad_input(edges, kwargs, match):
    with pytest.raises(ValueError, match=match):
        cliques(edges, **kwargs)


@pytest.mark.parametrize("dim, n, seed", [(2, 30, 0), (3, 25, 1)])
def test_voronoi_nerve_is_scipys_delaunay(dim, n, seed):
    pts = np.random.default_rng(seed).random((n, dim))
    top, meeting = voronoi_nerve(pts)
    assert top == {tuple(sorted(map(int, s))) for s in Delaunay(pts).simplices}
    assert meeting == dim + 1  # general position
    assert top == {s for s in delaunay(pts) if len(s) == dim + 1}


def test_voronoi_nerve_counts_four_cells_at_the_centre_of_a_square():
    square = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [3.0, 0.4]])
    assert voronoi_nerve(square)[1] == 4


@pytest.mark.parametrize("points", [np.zeros((5, 1)), np.random.default_rng(0).random((3, 2)), [[0.0, np.nan]] * 5])
def test_voronoi_nerve_bad_input(points):
    with pytest.raises(ValueError):
        voronoi_nerve(points)


def test_missing_simplices_on_lists_and_filtrations():
    assert missing_simplices([(0,), (1,), (1, 0), (2, 1)], [(0,), (1,), (0, 1)]) == 1
    pts = np.random.default_rng(2).random((12, 2))
    small, large = rips(pts, max_radius=0.2, max_dim=2), rips(pts, max_radius=0.3, max_dim=2)
    assert missing_simplices(small, large) == 0
    assert missing_simplices(large, small) == len(large) - len(small) > 0
    assert missing_simplices(alpha(pts), delaunay(pts)) == 0


def test_witness_complexes_are_nested():
    pts = np.random.default_rng(5).random((200, 2))
    lm = np.arange(12)
    small = witness(pts, lm, max_radius=0.02, max_dim=2)
    assert missing_simplices(small, witness(pts, lm, max_radius=0.05, max_dim=2)) == 0


def test_alpha_not_in_cech_is_zero_for_alpha_and_finds_a_planted_early_simplex():
    pts = np.random.default_rng(6).random((15, 2))
    f = alpha(pts)
    assert alpha_not_in_cech(pts, f) == 0
    # gudhi's alpha values: never below the squared enclosing radius either
    st = gudhi.AlphaComplex(points=pts).create_simplex_tree()  # kept alive while its filtration is read
    planted = [(tuple(s), v) for s, v in st.get_filtration()]
    assert alpha_not_in_cech(pts, Filtration.from_pairs(planted)) == 0
    edge = next(i for i, (s, _) in enumerate(planted) if len(s) == 2)
    planted[edge] = (planted[edge][0], 0.0)  # an edge entering at ε = 0
    assert alpha_not_in_cech(pts, Filtration.from_pairs(planted)) == 1
    with pytest.raises(ValueError):
        alpha_not_in_cech([[np.nan, 0.0]], f)


def test_barcodes_differing_alpha_against_cech_and_against_rips():
    pts = np.random.default_rng(9).random((14, 2))
    a = persistence(alpha(pts), coefficients=2)
    c = persistence(cech(pts, max_radius=2.0, max_dim=2), coefficients=2)
    r = persistence(rips(pts, max_radius=2.0, max_dim=2), coefficients=2)
    assert barcodes_differing(a, c, dims=(0, 1)) == 0
    # H0 of alpha and Rips agree (both: half the edge lengths of the minimum spanning tree), H1 need not
    assert barcodes_differing(a, r, dims=(0,)) == 0
    tri = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, np.sqrt(3) / 2]])
    a_tri = persistence(alpha(tri), coefficients=2)
    c_tri = persistence(cech(tri, max_radius=2.0, max_dim=2), coefficients=2)
    r_tri = persistence(rips(tri, max_radius=2.0, max_dim=2), coefficients=2)
    assert barcodes_differing(a_tri, c_tri, dims=(0, 1)) == 0
    assert barcodes_differing(a_tri, r_tri, dims=(0, 1)) == 1  # the Rips complex has no hole


def test_betti_text_is_the_homology_of_the_threshold_complex():
    pts = np.random.default_rng(10).random((20, 2))
    f = rips(pts, max_radius=1.0, max_dim=2)
    bars = persistence(f, coefficients=2)
    for value in (0.05, 0.1, 0.2):
        b = betti_numbers([s for s, _ in f.threshold(value)], coefficients=2) + [0]
        assert betti_text(bars, value) == f"{b[0]}, {b[1]}"
        assert betti_text(bars, value, dims=(0,)) == str(b[0])


def test_weighted_alpha_losses_against_gudhis_weighted_alpha():
    rng = np.random.default_rng(7)
    pts, r = rng.random((15, 2)), rng.uniform(0.02, 0.15, 15)
    grid = np.round(np.linspace(0.0, 0.3, 11), 2)
    thesis, naive = weighted_alpha_losses(pts, r, grid)
    assert thesis == 0
    before, lost = set(), 0  # the naive rule, from gudhi's weighted alpha complex
    for e in grid:
        st = gudhi.AlphaComplex(points=pts, weights=(r + e) ** 2).create_simplex_tree()
        now = {tuple(s) for s, v in st.get_filtration() if v <= 1e-12}
        lost += len(before - now)
        before = now
    assert naive == lost > 0


@pytest.mark.parametrize("radii, grid, match", [
    (np.full(4, 0.1), [0.0, 0.1], "one per point"),
    (np.full(5, -0.1), [0.0, 0.1], "nonnegative"),
    (np.full(5, 0.1), [0.1, 0.0], "increasing"),
])
def test_weighted_alpha_losses_bad_input(radii, grid, match):
    with pytest.raises(ValueError, match=match):
        weighted_alpha_losses(np.random.default_rng(0).random((5, 2)), radii, grid)

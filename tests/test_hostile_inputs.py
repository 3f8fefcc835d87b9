"""Refusals up front, by name, of what the library cannot compute: invalid seeds, values outside the
float range, type confusion and sizes that cannot fit.

Each test asserts the error and its message, or the value where the input is valid; the families
these cases stand for are fuzzed in ``tests/test_hostile_fuzz.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib._validate import InvalidTypeError, check_seed
from thesis_lib.applications.range_images import sample_patches, synthetic_range_image
from thesis_lib.complexes import build_filtration
from thesis_lib.curvature.checks import random_simplices
from thesis_lib.meshes.sampling import sample_n_catenoid
from thesis_lib.morse.examples import experiment_complex
from thesis_lib.morse.matching import morse_matching
from thesis_lib.persistence import RipsDiagrams

BAD_SEEDS = [True, False, [1, 2], np.array([1]), np.array(3), 1.5, 2.0, "1", -1, 1j, b"1"]


@pytest.mark.parametrize("seed", BAD_SEEDS, ids=repr)
def test_invalid_seeds_are_refused_by_name(seed):
    with pytest.raises((ValueError, TypeError), match="seed must be"):
        check_seed(seed)
    with pytest.raises((ValueError, TypeError), match="seed must be"):
        morse_matching([(0, 1, 2)], seed=seed)
    with pytest.raises((ValueError, TypeError), match="seed must be"):
        build_filtration(np.zeros((2, 2)), complex="rips", max_radius=1.0, max_dim=1, seed=seed)


SEEDED = {
    "sample_n_catenoid": lambda seed: sample_n_catenoid(10, seed=seed),
    "random_simplices": lambda seed: random_simplices(2, 3, seed=seed),
    "experiment_complex": lambda seed: experiment_complex("random-flag", seed=seed),
    "synthetic_range_image": lambda seed: synthetic_range_image(seed=seed, size=(8, 8)),
    "sample_patches": lambda seed: sample_patches([np.arange(64.0).reshape(8, 8) + 1], n=2, size=3, seed=seed),
}


@pytest.mark.parametrize("seed", [True, [1, 2], 1.5, -1], ids=repr)
@pytest.mark.parametrize("name", SEEDED)
def test_every_seeded_draw_checks_its_seed(name, seed):
    with pytest.raises((ValueError, TypeError), match="seed must be"):
        SEEDED[name](seed)
    SEEDED[name](3)  # a valid seed still draws


@pytest.mark.parametrize("X", [None, 3, "abc"], ids=repr)
def test_rips_diagrams_refuses_what_is_not_a_list_of_clouds(X):
    with pytest.raises(InvalidTypeError, match="X must be a list of point clouds"):
        RipsDiagrams().fit_transform(X)


def test_valid_seeds_are_kept():
    assert check_seed(np.int64(7)) == 7 and check_seed(2**80) == 2**80
    assert check_seed(None, optional=True) is None
    with pytest.raises(InvalidTypeError, match="seed must be a non-negative integer, got None"):
        check_seed(None)
    tri = [(0, 1, 2), (1, 2, 3), (2, 3, 4)]
    assert morse_matching(tri, seed=np.int64(3)) == morse_matching(tri, seed=3)
    assert morse_matching(tri, seed=None) == morse_matching(tri)


# ----------------------------------------------------------------------------- the float range
from thesis_lib import complexes as cx  # noqa: E402
from thesis_lib.applications.proteins import protein_filtration  # noqa: E402
from thesis_lib.homology import euler_characteristic, homology  # noqa: E402
from thesis_lib.persistence.implicit import rips_persistence  # noqa: E402

MAXF = np.finfo(np.float64).max
RNG = np.random.default_rng(21)
P2, P3 = RNG.random((8, 2)), RNG.random((10, 3))


@pytest.mark.filterwarnings("error::RuntimeWarning")  # a right answer, and no overflow on the way
@pytest.mark.parametrize("w", [1e140, 1e150, 1e300, MAXF], ids=repr)
@pytest.mark.parametrize("pts", [P2, P3], ids=["R2", "R3"])
def test_equal_huge_weights_give_the_unweighted_complex_shifted(pts, w):
    """Equal weights 1e140 and up give a complex, not an OverflowError in the predicates (the int64
    fast path's bound (2·big)^degree would overflow a float).  Equal weights do not move the power
    diagram: the same simplices, every value ε² − w."""
    plain, heavy = cx.alpha(pts), cx.alpha(pts, weights=np.full(len(pts), w))
    assert [s.tolist() for s in heavy.simplices] == [s.tolist() for s in plain.simplices]
    for v0, v in zip(plain.values, heavy.values):
        np.testing.assert_allclose(v, v0 - w, rtol=1e-15, atol=0)
    assert sorted(cx.delaunay(pts, weights=np.full(len(pts), w))) == sorted(cx.delaunay(pts))


@pytest.mark.filterwarnings("error::RuntimeWarning")  # a right answer, and no overflow on the way
@pytest.mark.parametrize("w", [np.r_[MAXF, np.zeros(7)], np.r_[1e300, 1e299, np.zeros(6)]], ids=["max", "1e300"])
def test_weights_whose_orthogonal_spheres_leave_the_float_range_are_refused_by_name(w):
    with pytest.raises(ValueError, match=r"beyond float64's range \(about 1.8e308\).*largest weight"):
        cx.alpha(P2, weights=w)
    tri = cx.delaunay(P2, weights=w)  # the complex needs signs only, no radius: it is computed
    assert (0,) in tri and all(len(s) <= 3 for s in tri)


def test_numbers_beyond_the_float_range_are_refused_by_name():
    """max_radius=10**400 is refused with a ValueError, not an OverflowError."""
    for fn in (lambda r: cx.rips(P2, max_radius=r), lambda r: cx.cech(P2, max_radius=r, max_dim=1),
               lambda r: cx.witness(P2, [0, 1, 2], max_radius=r, max_dim=1)):
        with pytest.raises(ValueError, match=r"max_radius is an integer of 1,329 bits, beyond float64's range.*inf"):
            fn(10**400)
        assert len(fn(10**300)) == len(fn(np.inf))  # a huge integer inside the range is a number
    with pytest.raises(ValueError, match=r"19,932 bits"):
        cx.rips(P2, max_radius=-(10**6000))


def test_rips_persistence_max_dim_is_bounded_and_dimensions_beyond_the_points_are_empty():
    """max_dim=10**9 and 10**30 are refused with a ValueError (not a MemoryError or an OverflowError)."""
    pts = RNG.random((6, 2))
    for bad in (10**9, 10**30, 10_001):
        with pytest.raises(ValueError, match="max_dim must be <= 10000"):
            rips_persistence(pts, max_dim=bad)
    with pytest.raises(TypeError, match="max_dim must be an integer"):
        rips_persistence(pts, max_dim=1e30)
    small, big = rips_persistence(pts, max_dim=7), rips_persistence(pts, max_dim=40)
    assert big.dimensions == tuple(range(40)) and big.allclose(small)
    assert all(big.intervals(d).shape == (0, 2) for d in range(1, 40))
    assert small == rips_persistence(pts, max_dim=6)  # max_dim = n: the unchanged path


@pytest.mark.parametrize("r_c, error, message", [
    (1e200, ValueError, r"r_c = 1e\+200 is too large: r_c² leaves float64's range"),
    ("0.5", TypeError, "r_c must be a number, got '0.5'"),
    (None, TypeError, "r_c must be a number, got None"),
    (float("nan"), ValueError, "r_c is NaN"),
    (-0.5, ValueError, "r_c must be >= 0.0"),
    (10**400, ValueError, "r_c is an integer of 1,329 bits"),
])
def test_protein_filtration_refuses_bad_r_c_by_name(r_c, error, message):
    with pytest.raises(error, match=message):
        protein_filtration(P3, np.ones(10), r_c=r_c)
    assert len(protein_filtration(P3, np.ones(10), r_c=np.float64(0.5))) == len(
        protein_filtration(P3, np.ones(10), r_c=0.5))


# ----------------------------------------------------------------------------- type confusion
@pytest.mark.filterwarnings("error::RuntimeWarning")  # a right answer, and no overflow on the way
def test_vertex_labels_objects_and_int64_overflow():
    """Object arrays of integer labels are accepted; a label 2⁶³ is refused as too large, not called negative."""
    tri = np.array([[0, 1, 2], [1, 2, 3]])
    assert euler_characteristic(tri.astype(object)) == euler_characteristic(tri) == 1
    assert homology(tri.astype(np.uint64)) == homology(tri)
    with pytest.raises(ValueError, match="vertex labels must be integers, got 'a'"):
        euler_characteristic(np.array([[0, 1], [1, "a"]], dtype=object))
    for bad in ([(0, 2**63)], [[2**63, 1, 2]], np.array([[0, 2**64 - 1]], dtype=np.uint64),
                np.array([[0, 2**63]], dtype=object)):
        with pytest.raises(ValueError, match=r"vertex label \d+ does not fit in int64 \(labels must be < 2\^63\)"):
            euler_characteristic(bad)
    assert euler_characteristic([(0, 2**63 - 1)]) == 1
    with pytest.raises(ValueError, match=r"vertex label 1e\+19 does not fit in int64"):  # a float label
        euler_characteristic(np.array([[0.0, 1e19]]))


@pytest.mark.parametrize("dm, message", [
    ([[0, 1], [1]], "its rows have different lengths"), ({0: 1}, "got a dict"), ("abc", "got a str"),
    ([[0, "a"], [1, 0]], "could not convert"), (np.array([[0, 1j], [1j, 0]]), "complex numbers are not distances"),
])
def test_distance_matrices_of_the_wrong_kind_are_refused_by_name(dm, message):
    for fn in (lambda: cx.rips(distance_matrix=dm), lambda: rips_persistence(distance_matrix=dm)):
        with pytest.raises(TypeError, match=f"distance_matrix must be an \\(n, n\\) array of numbers: {message}"):
            fn()


# ----------------------------------------------------------------------------- sizes that cannot fit
def test_edge_lists_beyond_the_limit_are_refused_before_allocating():
    """10⁵ points at ε = ∞ and 6·10⁴ in R³ at radius 10 are refused by size, before any MemoryError."""
    many = RNG.random((100_000, 2))
    for fn in (lambda: cx.rips(many, max_radius=np.inf, max_dim=1), lambda: cx.cech(many, max_radius=np.inf, max_dim=1),
               lambda: rips_persistence(many, max_dim=1)):
        with pytest.raises(ValueError,
                           match=r"would build 4,999,950,000 edges .* about 112 GiB.*limit of 1,000,000,000"):
            fn()
    with pytest.raises(ValueError, match=r"would build 1,799,970,000 edges \(60,000 points"):
        cx.rips(RNG.random((60_000, 3)), max_radius=10, max_dim=1)
    assert len(cx.rips(many[:2000], max_radius=np.inf, max_dim=1)) == 2000 + 1999 * 1000  # under it: built


def test_witness_distances_beyond_the_memory_budget_are_refused():
    pts = RNG.random((200_000, 2))
    for fn in (cx.witness, cx.lazy_witness):
        with pytest.raises(ValueError, match=r"about 186 GiB for the witness distances of 50,000 landmarks and "
                                             r"200,000 points, more than the memory budget of 8 GiB"):
            fn(pts, np.arange(50_000), max_radius=1.0, max_dim=1)
    with pytest.raises(ValueError, match="149 GiB"):
        cx.witness_offsets(pts, np.arange(50_000))


@pytest.mark.parametrize("k, gib", [(28, "84"), (40, "4.92e\\+05")])
def test_closures_beyond_the_memory_budget_are_refused(k, gib):
    """Homology of a 27- or 39-simplex and morse_matching of a 29-simplex are refused at once by the memory budget."""
    simplex = [tuple(range(k))]
    for fn in (homology, euler_characteristic):
        with pytest.raises(ValueError, match=rf"about {gib} GiB for the closure of the complex .*{k} vertices"):
            fn(simplex)
    with pytest.raises(ValueError, match="faces; its largest simplex has 30 vertices"):
        morse_matching([tuple(range(30))])
    with pytest.raises(ValueError, match="memory budget"):
        homology(iter(simplex))  # a generator is measured too
    assert homology(iter([tuple(range(12))])) == homology([tuple(range(12))]) == [(1, [])] + [(0, [])] * 11


def test_cech_work_beyond_the_budget_is_refused():
    with pytest.raises(ValueError, match=r"about 7.2e\+11 steps .* budget of 1e\+10"):
        cx.cech(RNG.random((18, 3)), max_radius=np.inf, max_dim=17)
    assert len(cx.cech(RNG.random((9, 3)), max_radius=np.inf, max_dim=8)) == 2**9 - 1  # 9 points: every subset, built


def test_delaunay_in_high_dimension_beyond_the_budget_is_refused():
    pts = RNG.random((400, 7))
    for fn in (cx.delaunay, cx.alpha, cx.regular_triangulation):
        with pytest.raises(ValueError, match=r"41,452,800 simplices \(estimated: 2,032,000 top simplices .* "
                                             r"400 points in R\^7\), more than the limit of 10,000,000"):
            fn(pts)
    assert len(cx.delaunay(pts[:12, :5])) > 0

"""One Rips computation behind every front door, and every input parsed once at the edge.

The doors: ``rips`` (the filtration), ``persistence(rips(...))`` (the explicit engine),
``rips_persistence`` (the implicit engine), ``RipsDiagrams`` (the implicit engine for many clouds)
and ``compute_intervals(rips(...))`` (the thesis's Algorithms 1–2, a separate implementation).
They share one parsed point cloud (``_validate.Points``, scaled by a power of two) and one edge
search, so they must give the same barcodes to the last bit, for coordinates near 1e160 and 1e-170
too, and a bad argument is reported once, by the public name.
"""

from __future__ import annotations

import itertools
import sys

import numpy as np
import pytest
import scipy.sparse as sp

import thesis_lib
from thesis_lib import _validate
from thesis_lib.complexes import rips
from thesis_lib.curvature import areas, gaussian_curvature, mean_curvature, vertex_areas
from thesis_lib.datasets import rp2
from thesis_lib.homology import homology
from thesis_lib.meshes.grids import torus_grid
from thesis_lib.morse.matching import morse_matching
from thesis_lib.morse.morse_complex import morse_homology
from thesis_lib.multiparameter import fibered_barcode, hilbert_function, radius_curvature_bifiltration, rank_invariant
from thesis_lib.persistence import RipsDiagrams, compute_intervals, persistence, rips_persistence
from thesis_lib.persistence.implicit import rips_graph


def cloud(seed: int, n: int, dim: int) -> np.ndarray:
    """Uniform points in the unit cube, or (odd seeds) distinct points of a small integer grid, where
    many distances tie and the engines' different tie-breaks are put to the test."""
    rng = np.random.default_rng(seed)
    if seed % 2:
        grid = np.unique(rng.integers(0, 4, size=(3 * n, dim)).astype(np.float64), axis=0)
        return grid[rng.permutation(grid.shape[0])[:n]]
    return rng.random((n, dim))


def radius(points: np.ndarray, kind: str) -> float:
    """ε = ∞, or half of a middle pairwise distance (an edge exactly at the threshold 2ε)."""
    if kind == "inf":
        return np.inf
    d = np.sqrt(((points[:, None] - points[None]) ** 2).sum(axis=2))[np.triu_indices(points.shape[0], 1)]
    return float(np.sort(d)[d.size // 3]) / 2


def door_bytes(points, eps: float, max_dim: int, p: int) -> dict[str, list[bytes]]:
    """The bytes of ``intervals(d)``, d < max_dim, by each front door that takes points."""
    out = {
        "rips_persistence": rips_persistence(points, max_radius=eps, max_dim=max_dim, coefficients=p),
        "persistence(rips)": persistence(rips(points, max_radius=eps, max_dim=max_dim), coefficients=p),
    }
    out = {k: [b.intervals(d).tobytes() for d in range(max_dim)] for k, b in out.items()}
    diagrams = RipsDiagrams(max_radius=eps, max_dim=max_dim, coefficients=p).transform([points])[0]
    out["RipsDiagrams"] = [np.ascontiguousarray(dg).tobytes() for dg in diagrams]
    return out


CASES = list(itertools.product((1, 2, 3, 4), (1, 2, 3), (2, 3), ("finite", "inf")))


@pytest.mark.parametrize("dim, max_dim, p, kind", CASES)
def test_the_doors_give_the_same_bytes(dim, max_dim, p, kind):
    for seed in (dim * 100 + max_dim * 10 + p, dim * 100 + max_dim * 10 + p + 1):
        points = cloud(seed, 17, dim)
        eps = radius(points, kind)
        got = door_bytes(points, eps, max_dim, p)
        reference = got["rips_persistence"]
        assert sum(len(b) for b in reference) > 0
        for door, value in got.items():
            assert value == reference, f"{door} differs (seed {seed})"


@pytest.mark.parametrize("power", [530, -560])
@pytest.mark.parametrize("dim, max_dim, p, kind", [c for c in CASES if c[1] >= 2 and c[2] == 2])
def test_extreme_scales_give_the_barcode_scaled_exactly(power, dim, max_dim, p, kind):
    # 2**530 ≈ 3.5e159: squared distances overflow float64; 2**-560 ≈ 2.6e-169: they underflow
    seed = 7 * dim + max_dim
    points = cloud(seed, 15, dim)
    eps = radius(points, kind)
    unit = door_bytes(points, eps, max_dim, p)["rips_persistence"]
    expected = [np.ldexp(np.frombuffer(b, dtype=np.float64), power).tobytes() for b in unit]
    got = door_bytes(np.ldexp(points, power), float(np.ldexp(eps, power)), max_dim, p)
    for door, value in got.items():
        assert value == expected, f"{door} at 2**{power} differs"


@pytest.mark.parametrize("power", [0, 530, -560])
def test_rips_and_the_implicit_graph_share_the_edges(power):
    points = np.ldexp(cloud(4, 30, 3), power)
    eps = float(np.ldexp(0.35, power))
    K = rips(points, max_radius=eps, max_dim=1)
    n, indptr, nbr, lengths = rips_graph(points, max_radius=eps)
    rows = np.repeat(np.arange(n), np.diff(indptr))
    upper = rows < nbr
    order = np.lexsort((nbr[upper], rows[upper]))
    np.testing.assert_array_equal(np.column_stack([rows[upper], nbr[upper]])[order], K.simplices[1])
    assert (lengths[upper][order] * 0.5).tobytes() == K.values[1].tobytes()
    assert np.all(np.isfinite(K.values[1])) and K.values[1].min() > 0


@pytest.mark.parametrize("max_dim, p, kind", list(itertools.product((1, 2, 3), (2, 3), ("finite", "inf"))))
def test_a_distance_matrix_gives_the_same_bytes_dense_or_sparse(max_dim, p, kind):
    points = cloud(40 + max_dim, 16, 3)
    dm = np.sqrt(((points[:, None] - points[None]) ** 2).sum(axis=2))
    eps = radius(points, kind)
    barcodes = [
        rips_persistence(distance_matrix=dm, max_radius=eps, max_dim=max_dim, coefficients=p),
        rips_persistence(distance_matrix=sp.coo_matrix(dm), max_radius=eps, max_dim=max_dim, coefficients=p),
        persistence(rips(distance_matrix=dm, max_radius=eps, max_dim=max_dim), coefficients=p),
    ]
    first = [barcodes[0].intervals(d).tobytes() for d in range(max_dim)]
    assert sum(len(b) for b in first) > 0
    for b in barcodes[1:]:
        assert [b.intervals(d).tobytes() for d in range(max_dim)] == first


@pytest.mark.parametrize("dim, max_dim, p, kind", [c for c in CASES if c[0] in (1, 2, 4)])
def test_the_thesis_algorithm_agrees_on_small_inputs(dim, max_dim, p, kind):
    points = cloud(dim + 10 * max_dim + p, 9, dim)
    eps = radius(points, kind)
    literal = compute_intervals(rips(points, max_radius=eps, max_dim=max_dim), coefficients=p)
    fast = rips_persistence(points, max_radius=eps, max_dim=max_dim, coefficients=p)
    for d in range(max_dim):
        assert literal.intervals(d).tobytes() == fast.intervals(d).tobytes()


# ---------------------------------------------------------------------------- parsed once
CHECKS = ("as_points", "check_radius", "check_max_dim", "check_coefficients", "check_area")


@pytest.fixture
def calls(monkeypatch):
    """Count the calls of the checkers, wherever a thesis_lib module holds them."""
    counts = dict.fromkeys(CHECKS, 0)
    originals = {name: getattr(_validate, name, None) or getattr(areas, name) for name in CHECKS}

    def counting(name):
        original = originals[name]

        def wrapper(*args, **kwargs):
            counts[name] += 1
            return original(*args, **kwargs)
        return wrapper

    wrappers = {name: counting(name) for name in CHECKS}
    for module in [m for name, m in sys.modules.items() if name.startswith(thesis_lib.__name__)]:
        for name in CHECKS:
            if getattr(module, name, None) is originals[name]:
                monkeypatch.setattr(module, name, wrappers[name])
    return counts


def test_the_rips_doors_check_each_argument_once(calls):
    points = cloud(2, 12, 2)
    rips_persistence(points, max_radius=0.4, max_dim=2, coefficients=3)
    assert calls == {"as_points": 1, "check_radius": 1, "check_max_dim": 1, "check_coefficients": 1, "check_area": 0}
    calls.update(dict.fromkeys(CHECKS, 0))
    persistence(rips(points, max_radius=0.4, max_dim=2), coefficients=3)
    assert calls == {"as_points": 1, "check_radius": 1, "check_max_dim": 1, "check_coefficients": 1, "check_area": 0}
    calls.update(dict.fromkeys(CHECKS, 0))
    RipsDiagrams(max_radius=0.4, max_dim=2, coefficients=3).transform([points, points + 1, points * 2])
    # the parameters once for all the clouds, each cloud once
    assert calls == {"as_points": 3, "check_radius": 1, "check_max_dim": 1, "check_coefficients": 1, "check_area": 0}


def test_the_bifiltration_and_its_invariants_check_once(calls):
    points = cloud(6, 10, 2)
    kappa = np.random.default_rng(6).normal(size=10)
    bif = radius_curvature_bifiltration(points, kappa, max_radius=0.6, max_dim=2)
    assert (calls["as_points"], calls["check_radius"], calls["check_max_dim"]) == (1, 1, 1)
    calls.update(dict.fromkeys(CHECKS, 0))
    eps, kappa = np.linspace(0.0, 0.6, 4), np.linspace(0.0, 2.0, 3)
    rank = rank_invariant(bif, eps, kappa, dim=0, coefficients=3)
    assert calls["check_coefficients"] == 1  # not once per barcode of the grid
    hilbert = hilbert_function(bif, eps, kappa, dims=0, coefficients=3)[0]
    np.testing.assert_array_equal(np.einsum("ijij->ij", rank), hilbert)
    assert hilbert.max() > 0
    calls.update(dict.fromkeys(CHECKS, 0))
    fibered_barcode(bif, [0.0, 0.0], [1.0, 1.0], coefficients=3)
    assert calls["check_coefficients"] == 1


def test_homology_and_the_morse_complex_check_the_coefficients_once(calls):
    assert homology(rp2(), coefficients=3) == [(1, []), (0, []), (0, [])]
    assert calls["check_coefficients"] == 1
    calls.update(dict.fromkeys(CHECKS, 0))
    facets = rp2()
    assert morse_homology(facets, morse_matching(facets), coefficients=0) == [(1, []), (0, [2]), (0, [])]
    assert calls["check_coefficients"] == 1


@pytest.mark.parametrize("function", [mean_curvature, gaussian_curvature, vertex_areas])
def test_the_curvature_functions_check_the_area_once(calls, function):
    vertices, faces = torus_grid(12)
    assert np.all(np.isfinite(function(vertices, faces, area="voronoi")))
    assert calls["check_area"] == 1


# ---------------------------------------------------------------------------- named once
POINTS = cloud(0, 8, 2)


@pytest.mark.parametrize("call, name", [
    (lambda: rips_persistence(POINTS, max_radius=-1), "max_radius"),
    (lambda: rips(POINTS, max_radius=-1), "max_radius"),
    (lambda: RipsDiagrams(max_radius=-1).transform([POINTS]), "max_radius"),
    (lambda: radius_curvature_bifiltration(POINTS, np.zeros(8), max_radius=-1), "max_radius"),
    (lambda: rips_persistence(POINTS, max_dim=1.5), "max_dim"),
    (lambda: rips(POINTS, max_dim=-1), "max_dim"),
    (lambda: rips_persistence(POINTS, coefficients=4), "coefficients"),
    (lambda: persistence(rips(POINTS), coefficients=4), "coefficients"),
    (lambda: RipsDiagrams(coefficients=0).transform([POINTS]), "coefficients"),
    (lambda: homology(rp2(), coefficients=6), "coefficients"),
    (lambda: rips_persistence(np.array([[0.0, np.nan], [1.0, 1.0]])), "points"),
    (lambda: rips(POINTS[:, :0]), "points"),
    (lambda: rips_persistence(POINTS, distance_matrix=np.zeros((8, 8))), "distance_matrix"),
    (lambda: rips_persistence(distance_matrix=sp.coo_matrix(([1.0, 2.0], ([0, 1], [1, 0])), shape=(2, 2))),
     "distance_matrix"),
    (lambda: mean_curvature(*torus_grid(6), area="circle"), "area"),
])
def test_a_bad_argument_is_reported_once_by_its_public_name(call, name):
    with pytest.raises(ValueError) as err:
        call()
    assert str(err.value).count(name) == 1, str(err.value)


# ---------------------------------------------------------------------------- doubtful input
def distance_matrix_of(points: np.ndarray) -> np.ndarray:
    return np.sqrt(((points[:, None] - points[None]) ** 2).sum(axis=2))


def cech_door(x):
    from thesis_lib.complexes import cech

    return cech(x, max_radius=np.inf, max_dim=2)


POINT_DOORS = {
    "rips": lambda x: rips(x, max_dim=2),
    "rips_persistence": lambda x: rips_persistence(x, max_dim=2),
    "rips_graph": lambda x: rips_graph(x),
    "RipsDiagrams": lambda x: RipsDiagrams(max_dim=2).transform([x]),
    "cech": cech_door,
}


def user_warnings(call) -> list:
    """The UserWarnings of one call, none filtered out (so a warning given twice shows twice)."""
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call()
    return [w for w in caught if issubclass(w.category, UserWarning)]


@pytest.mark.parametrize("door", sorted(POINT_DOORS))
def test_points_that_look_like_a_distance_matrix_warn_once_at_the_callers_line(door):
    dm = distance_matrix_of(cloud(3, 6, 2))
    caught = user_warnings(lambda: POINT_DOORS[door](dm))
    assert len(caught) == 1
    assert "read as 6 points in R^6" in str(caught[0].message) and "distance_matrix=" in str(caught[0].message)
    assert caught[0].filename == __file__
    # what is not a distance matrix is read as points without a word
    not_square, asymmetric, diagonal, negative = dm[:, :4], dm + np.triu(dm) * 0.1, dm + np.eye(6), dm.copy()
    negative[0, 1] = negative[1, 0] = -1.0
    for points in (not_square, asymmetric, diagonal, negative, cloud(3, 6, 6)):
        assert user_warnings(lambda p=points: POINT_DOORS[door](p)) == []


def test_a_distance_matrix_given_by_its_keyword_is_not_warned_about():
    dm = distance_matrix_of(cloud(4, 7, 3))
    assert user_warnings(lambda: rips_persistence(distance_matrix=dm, max_dim=2)) == []
    assert user_warnings(lambda: rips(distance_matrix=dm, max_dim=2)) == []


def test_the_warnings_of_every_rips_door_name_the_callers_line():
    d = np.array([[0.0, 1.0], [1.0, 2.0]])  # an entry below its vertex's birth (the diagonal)
    for call in (lambda: rips(distance_matrix=d), lambda: rips_persistence(distance_matrix=d),
                 lambda: rips_graph(distance_matrix=d)):
        caught = user_warnings(call)
        assert len(caught) == 1 and "below the diagonal entry" in str(caught[0].message)
        assert caught[0].filename == __file__


def test_the_alpha_complex_refuses_n_points_in_r_n():
    from thesis_lib.complexes import alpha

    with pytest.raises(ValueError, match="needs at least 7 points"):
        alpha(distance_matrix_of(cloud(5, 6, 3)))


@pytest.mark.parametrize("seed, dim, max_dim", [(0, 2, 2), (1, 3, 3), (2, 2, 3)])
def test_duplicate_points_are_allowed_and_the_four_doors_agree(seed, dim, max_dim):
    rng = np.random.default_rng(seed)
    distinct = cloud(seed, 12, dim)
    points = np.vstack([distinct, distinct[rng.integers(0, 12, size=5)]])[rng.permutation(17)]
    points = np.vstack([points, points[:1], points[:1]])  # a point three times over
    barcodes = {
        "rips_persistence": rips_persistence(points, max_dim=max_dim),
        "persistence(rips)": persistence(rips(points, max_dim=max_dim)),
        "compute_intervals(rips)": compute_intervals(rips(points, max_dim=max_dim)),
    }
    reference = [barcodes["rips_persistence"].intervals(d).tobytes() for d in range(max_dim)]
    for door, barcode in barcodes.items():
        assert [barcode.intervals(d).tobytes() for d in range(max_dim)] == reference, door
    diagrams = RipsDiagrams(max_dim=max_dim).transform([points])[0]
    assert [np.ascontiguousarray(dg).tobytes() for dg in diagrams] == reference
    # the copies only add zero-length H0 bars, left out: the barcode of the distinct points
    alone = rips_persistence(np.unique(points, axis=0), max_dim=max_dim)
    assert [alone.intervals(d).tobytes() for d in range(max_dim)] == reference
    assert len(np.unique(points, axis=0)) == 12 < len(points)


def rotated_grid(n: int, dim: int, angle: float) -> np.ndarray:
    """A cubic grid of n^dim points, step 0.1, turned by ``angle`` in its first plane and shifted:
    its many tied distances are computed with different roundings, and differ by about 1e-16."""
    grid = np.stack(np.meshgrid(*[np.arange(n)] * dim, indexing="ij"), axis=-1).reshape(-1, dim) * 0.1
    turn = np.eye(dim)
    turn[:2, :2] = [[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]
    return grid @ turn.T + 0.37


@pytest.mark.parametrize("angle", [0.3, 0.7])
def test_min_persistence_is_the_same_option_at_every_door(angle):
    points = rotated_grid(4, 3, angle)
    kept = {
        "rips_persistence": rips_persistence(points, max_dim=3, min_persistence=1e-12),
        "persistence(rips)": persistence(rips(points, max_dim=3), min_persistence=1e-12),
    }
    reference = [kept["rips_persistence"].intervals(d).tobytes() for d in range(3)]
    assert [kept["persistence(rips)"].intervals(d).tobytes() for d in range(3)] == reference
    diagrams = RipsDiagrams(max_dim=3, min_persistence=1e-12).transform([points])[0]
    assert [np.ascontiguousarray(dg).tobytes() for dg in diagrams] == reference
    everything = rips_persistence(points, max_dim=3)
    assert [everything.to_diagrams(min_persistence=1e-12)[d].tobytes() for d in range(3)] == reference
    # what was dropped: the bars of length at most 1e-12, and there were some
    full = everything.intervals(2)
    short = full[:, 1] - full[:, 0] <= 1e-12
    assert short.any() and kept["rips_persistence"].intervals(2).tobytes() == full[~short].tobytes()
    # ripser.py, on float32 distances, reports the bars that are left
    from ripser import ripser

    theirs = [len(d) for d in ripser(points, maxdim=2)["dgms"]]
    assert [len(kept["rips_persistence"].intervals(d)) for d in range(3)] == theirs
    assert [len(everything.intervals(d)) for d in range(3)] != theirs

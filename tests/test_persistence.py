"""Persistent homology: the thesis's Algorithms 1–2, the fast engine and GUDHI agree (§2.3)."""

from __future__ import annotations

import math

import gudhi
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import Filtration
from thesis_lib.datasets import example_filtration
from thesis_lib.homology.simplicial import boundary_matrix, closure
from thesis_lib.persistence import Barcode, compute_intervals, persistence

# ----------------------------------------------------------------------------- helpers


def gudhi_barcode(f: Filtration, p: int) -> Barcode:
    stree = f.to_simplex_tree()
    pairs = stree.persistence(homology_coeff_field=p, min_persistence=0.0, persistence_dim_max=True)
    return Barcode.from_pairs(pairs, dimensions=range(f.dimension + 1))


def rips_filtration(points: np.ndarray, max_edge: float, max_dim: int) -> Filtration:
    stree = gudhi.RipsComplex(points=points, max_edge_length=max_edge).create_simplex_tree(max_dimension=max_dim)
    return Filtration.from_simplex_tree(stree)


def alpha_filtration(points: np.ndarray) -> Filtration:
    return Filtration.from_simplex_tree(gudhi.AlphaComplex(points=points).create_simplex_tree())


def cech_filtration(points: np.ndarray) -> Filtration:
    return Filtration.from_simplex_tree(gudhi.DelaunayCechComplex(points=points).create_simplex_tree())


def random_filtration(seed: int, n: int = 7, n_top: int = 6, top_dim: int = 3) -> Filtration:
    """A random complex with many ties: value = max over facets + 0 or 1 (a general filtration)."""
    rng = np.random.default_rng(seed)
    tops = [tuple(sorted(rng.choice(n, size=int(rng.integers(2, top_dim + 2)), replace=False))) for _ in range(n_top)]
    groups = closure(tops)
    values = [rng.integers(0, 3, size=groups[0].shape[0]).astype(float)]
    for d in range(1, len(groups)):
        probe = Filtration(groups[: d + 1], values + [np.zeros(groups[d].shape[0])], validate=False)
        face_max = values[d - 1][probe.facet_indices(d)].max(axis=1)
        values.append(face_max + rng.integers(0, 2, size=groups[d].shape[0]))
    return Filtration(groups, values)


def _row_reduce_mod_p(a: np.ndarray, p: int) -> tuple[np.ndarray, list[int]]:
    """Reduced row echelon form of ``a`` over Z/p and its pivot columns (Gauss–Jordan)."""
    a = np.array(a, dtype=np.int64) % p
    rank, rows, cols = 0, a.shape[0], a.shape[1] if a.ndim == 2 else 0
    pivots = []
    for c in range(cols):
        piv = next((r for r in range(rank, rows) if a[r, c]), None)
        if piv is None:
            continue
        a[[rank, piv]] = a[[piv, rank]]
        a[rank] = a[rank] * pow(int(a[rank, c]), p - 2, p) % p
        for r in range(rows):
            if r != rank and a[r, c]:
                a[r] = (a[r] - a[r, c] * a[rank]) % p
        pivots.append(c)
        rank += 1
    return a, pivots


def rank_mod_p(a: np.ndarray, p: int) -> int:
    return len(_row_reduce_mod_p(a, p)[1])


def nullspace_mod_p(a: np.ndarray, p: int) -> np.ndarray:
    """Columns spanning {x : a x = 0} over Z/p."""
    a, pivots = _row_reduce_mod_p(a, p)
    cols = a.shape[1]
    free = [c for c in range(cols) if c not in pivots]
    basis = np.zeros((cols, len(free)), dtype=np.int64)
    for k, fcol in enumerate(free):
        basis[fcol, k] = 1
        for r, pc in enumerate(pivots):
            basis[pc, k] = (-a[r, fcol]) % p
    return basis


def dense_boundary(f: Filtration, d: int, p: int) -> np.ndarray:
    """∂_d as a dense matrix (rows: (d−1)-simplices, columns: d-simplices), or an empty one."""
    if d < 1 or d > f.dimension:
        rows = f.simplices[d - 1].shape[0] if 1 <= d <= f.dimension + 1 else 0
        cols = f.simplices[d].shape[0] if 0 <= d <= f.dimension else 0
        return np.zeros((rows, cols), dtype=np.int64)
    return boundary_matrix(f.simplices[d - 1], f.simplices[d], coefficients=p).toarray()


def persistent_betti_by_rank(f: Filtration, dim: int, l: float, k: float, p: int) -> int:
    """rank Z_dim^l / (B_dim^{l+k} ∩ Z_dim^l) by linear algebra over Z/p (Definition 2.23)."""
    n = f.simplices[dim].shape[0]
    in_l = f.values[dim] <= l
    if dim == 0:
        z = np.eye(n, dtype=np.int64)[:, in_l]
    else:
        dl = dense_boundary(f, dim, p)[:, in_l]
        z = np.zeros((n, 0), dtype=np.int64)
        if in_l.any():
            zl = nullspace_mod_p(dl, p)
            z = np.zeros((n, zl.shape[1]), dtype=np.int64)
            z[in_l] = zl
    if dim + 1 <= f.dimension:
        b = dense_boundary(f, dim + 1, p)[:, f.values[dim + 1] <= l + k]
    else:
        b = np.zeros((n, 0), dtype=np.int64)
    dim_z = rank_mod_p(z, p) if z.size else 0
    dim_b = rank_mod_p(b, p) if b.size else 0
    both = np.hstack([z, b])
    dim_sum = rank_mod_p(both, p) if both.size else 0
    return dim_z - (dim_b + dim_z - dim_sum)


# ----------------------------------------------------------------------------- the thesis's examples


def test_example_filtration_matches_figure_2_11():
    f = example_filtration()
    names = "abcde"
    entered = {"".join(names[v] for v in s): v for s, v in f}
    assert entered == {
        "a": 0, "b": 0, "c": 1, "d": 1, "ab": 1, "cd": 1, "e": 2, "ad": 2, "bc": 2,
        "de": 3, "ce": 3, "cde": 4,
    }  # fmt: skip
    assert f.counts() == [5, 6, 1]


@pytest.mark.parametrize("algorithm", [compute_intervals, persistence])
@pytest.mark.parametrize("p", [2, 3, 5])
def test_example_2_40_barcode(algorithm, p):
    b = algorithm(example_filtration(), coefficients=p)
    # Example 2.41: (a, ∞), (b, ab), (c, da), (e, ce), (bc, ∞), (ed, ced); (d, cd) = (1, 1) has length zero
    assert b.intervals(0).tolist() == [[0, 1], [0, math.inf], [1, 2], [2, 3]]
    assert b.intervals(1).tolist() == [[2, math.inf], [3, 4]]
    assert b.intervals(2).shape == (0, 2)
    assert b.dimensions == (0, 1, 2)


def test_example_2_41_trace():
    trace: list = []
    compute_intervals(example_filtration(), trace=trace)
    order = ["".join("abcde"[v] for v in s) for s in trace[0]["order"]]
    # "First, sort the simplices by dimension and then by degree": the order of Example 2.41
    assert order == ["a", "b", "c", "d", "e", "ab", "cd", "ad", "bc", "de", "ce", "cde"]
    marked = ["".join("abcde"[v] for v in r["simplex"]) for r in trace if r["marked"]]
    assert marked == ["a", "b", "c", "d", "e", "bc", "ce"]  # the cycles: vertices, (bc) and (ce) ~ z1, z2
    by_name = {"".join("abcde"[v] for v in r["simplex"]): r for r in trace}
    # Reduce(da) subtracts T[d] = ∂cd once; Reduce(bc) reduces to zero in two steps (column z1)
    assert [s["i"] for s in by_name["ad"]["steps"]] == [3]
    assert len(by_name["bc"]["steps"]) == 2 and by_name["bc"]["result"] == {}
    # Reduce(ced): unmarked terms cd, de removed, leaving (ce) — marked, so the pivot row is z2
    removed = {"".join("abcde"[v] for v in s) for s in by_name["cde"]["removed"]}
    assert removed == {"cd", "de"}
    assert by_name["cde"]["pivot"] == order.index("ce")


def test_example_2_36_persistent_betti():
    b = Barcode({0: [[0, math.inf], [1, math.inf], [2, 4]]})
    assert b.persistent_betti(0, 0, dim=0) == 1
    assert b.persistent_betti(2, 1, dim=0) == 3
    assert b.persistent_betti(2, 2, dim=0) == 2  # (2, 4) does not span [2, 4]
    assert b.betti(3.5, dim=0) == 3 and b.betti(4, dim=0) == 2


# ----------------------------------------------------------------------------- cross-checks with GUDHI

points_2d = st.integers(0, 10_000).map(lambda s: np.random.default_rng(s).random((int(6 + s % 9), 2)))


@settings(deadline=None, max_examples=15)
@given(points=points_2d, p=st.sampled_from([2, 3]), max_dim=st.sampled_from([2, 3]))
def test_rips_agrees_with_gudhi(points, p, max_dim):
    f = rips_filtration(points, 0.9, max_dim)
    ref = gudhi_barcode(f, p)
    fast = persistence(f, coefficients=p)
    assert fast.difference(ref) is None
    if len(f) <= 400:
        assert compute_intervals(f, coefficients=p).difference(ref) is None


@settings(deadline=None, max_examples=12)
@given(seed=st.integers(0, 10_000), p=st.sampled_from([2, 3]), dim=st.sampled_from([2, 3]))
def test_alpha_and_cech_agree_with_gudhi(seed, p, dim):
    pts = np.random.default_rng(seed).random((int(5 + seed % 10), dim))
    for f in (alpha_filtration(pts), cech_filtration(pts)):
        ref = gudhi_barcode(f, p)
        assert persistence(f, coefficients=p).difference(ref) is None
        assert compute_intervals(f, coefficients=p).difference(ref) is None


@settings(deadline=None, max_examples=25)
@given(seed=st.integers(0, 100_000), p=st.sampled_from([2, 3, 5]))
def test_random_general_filtrations_agree(seed, p):
    f = random_filtration(seed)
    ref = gudhi_barcode(f, p)
    assert persistence(f, coefficients=p).difference(ref) is None
    assert compute_intervals(f, coefficients=p).difference(ref) is None


def test_larger_rips_with_collisions_agrees_with_gudhi():
    pts = np.random.default_rng(7).random((40, 3))
    f = rips_filtration(pts, 0.7, 3)
    for p in (2, 3):
        stats: dict = {}
        assert persistence(f, coefficients=p, stats=stats).difference(gudhi_barcode(f, p)) is None
        assert stats[1]["additions"] > 0  # the merge path was exercised


def test_torsion_shows_over_z2_not_z3():
    # RP² (Example 2.21): H1 = Z/2, so over Z/2 one essential H1 and H2 class, over Z/3 none
    from thesis_lib.datasets import rp2

    groups = closure(rp2())
    f = Filtration(groups, [np.full(g.shape[0], float(d)) for d, g in enumerate(groups)])
    for p, expected in ((2, 1), (3, 0)):
        b = persistence(f, coefficients=p)
        assert b == compute_intervals(f, coefficients=p) == gudhi_barcode(f, p)
        essential = [int(np.isinf(b.intervals(d)[:, 1]).sum()) for d in (0, 1, 2)]
        assert essential == [1, expected, expected]
        assert (b.simplex_pairs(2)[:, 1] == -1).all()  # the lazily listed top dimension
    fundamental = persistence(f, coefficients=2).representative(2, 0)
    assert len(fundamental) == 10 and {c for _, c in fundamental} == {1}  # RP² is a Z/2-cycle


def test_pairs_input_and_vertices_only():
    pairs = [((0,), 0.0), ((1,), 0.5), ((0, 1), 1.0), ((2,), 2.0)]
    for algo in (compute_intervals, persistence):
        b = algo(pairs)
        assert b.intervals(0).tolist() == [[0, math.inf], [0.5, 1.0], [2.0, math.inf]]
        assert algo([((0,), 1.0), ((1,), 2.0)]).intervals(0).tolist() == [[1, math.inf], [2, math.inf]]


# ----------------------------------------------------------------------------- Theorem 2.37


@settings(deadline=None, max_examples=10)
@given(seed=st.integers(0, 10_000), p=st.sampled_from([2, 3]))
def test_persistent_betti_is_the_rank_of_the_persistent_group(seed, p):
    f = random_filtration(seed, n=6, n_top=4)
    b = persistence(f, coefficients=p)
    grid = np.unique(np.concatenate(f.values))
    for dim in range(f.dimension + 1):
        for l in grid:
            for k in (0.0, 1.0, 2.0):
                assert b.persistent_betti(l, k, dim=dim) == persistent_betti_by_rank(f, dim, l, k, p), (dim, l, k)


def test_persistent_betti_on_the_example():
    f = example_filtration()
    b = compute_intervals(f)
    for dim in (0, 1):
        for l in range(5):
            for k in range(4):
                assert b.persistent_betti(l, k, dim=dim) == persistent_betti_by_rank(f, dim, l, k, 2)


# ----------------------------------------------------------------------------- representatives


def _chain_vector(f: Filtration, dim: int, chain) -> np.ndarray:
    index = {tuple(s): i for i, s in enumerate(f.simplices[dim].tolist())}
    x = np.zeros(f.simplices[dim].shape[0], dtype=np.int64)
    for s, c in chain:
        x[index[s]] = c
    return x


@settings(deadline=None, max_examples=10)
@given(seed=st.integers(0, 10_000), p=st.sampled_from([2, 3]))
def test_representatives_are_cycles_born_and_dying_on_time(seed, p):
    f = random_filtration(seed, n=7, n_top=6)
    for b in (persistence(f, coefficients=p), compute_intervals(f, coefficients=p)):
        for dim in range(f.dimension + 1):
            for i, (birth, death) in enumerate(b.intervals(dim)):
                chain = b.representative(dim, i)
                x = _chain_vector(f, dim, chain)
                assert x.any()
                if dim > 0:
                    assert not (dense_boundary(f, dim, p) @ x % p).any()  # ∂c = 0
                else:
                    assert x.sum() % p == (0 if np.isfinite(death) else x.sum() % p)
                values = dict(zip(map(tuple, f.simplices[dim].tolist()), f.values[dim]))
                assert max(values[s] for s, _ in chain) == birth  # born at the birth
                if np.isfinite(death) and dim + 1 <= f.dimension:
                    bd = dense_boundary(f, dim + 1, p)
                    at = bd[:, f.values[dim + 1] <= death]
                    before = bd[:, f.values[dim + 1] < death]
                    assert rank_mod_p(np.column_stack([at, x]), p) == rank_mod_p(at, p)  # a boundary at death
                    r_before = rank_mod_p(before, p) if before.size else 0
                    assert rank_mod_p(np.column_stack([before, x]), p) == r_before + 1  # not before


def test_long_bar_representative_on_a_circle():
    theta = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    pts = np.column_stack([np.cos(theta), np.sin(theta)])
    f = rips_filtration(pts, 1.2, 2)
    b = persistence(f)
    (i,) = b.longest(1, n=1)
    cycle = b.representative(1, int(i))
    assert len(cycle) == 12  # the whole circle
    assert {v for s, _ in cycle for v in s} == set(range(12))


# ----------------------------------------------------------------------------- bad input


@pytest.mark.parametrize("algo", [compute_intervals, persistence])
def test_bad_input(algo):
    with pytest.raises(ValueError, match="face"):
        algo([((0, 1), 0.0), ((0,), 0.0), ((1,), 0.0)])
    with pytest.raises(ValueError, match="decrease"):
        algo([((0,), 1.0), ((1,), 0.0)])
    with pytest.raises(ValueError, match="NaN"):
        algo([((0,), float("nan"))])
    with pytest.raises(ValueError, match="empty"):
        algo([])
    for p in (4, 1, 0, -3, 2.5, True):
        with pytest.raises(ValueError, match="prime"):
            algo(example_filtration(), coefficients=p)
    with pytest.raises(ValueError, match="iterable"):
        algo(42)
    with pytest.raises(ValueError, match="face"):
        Filtration([np.array([[0], [1]]), np.array([[0, 1]])], [np.array([0.0, 0.0]), np.array([-1.0])])


@settings(deadline=None, max_examples=10)
@given(seed=st.integers(0, 10_000), p=st.sampled_from([2, 3]))
def test_unvalidated_filtrations_take_the_fused_path(seed, p):
    # thesis_lib's rips() skips validation, so the engine finds facets itself (fused dense lookup)
    from thesis_lib.complexes import rips

    pts = np.random.default_rng(seed).random((int(8 + seed % 12), 2))
    f = rips(pts, max_radius=0.45, max_dim=3)
    assert "_facet_cache" not in f.__dict__
    ref = gudhi_barcode(f, p)
    assert persistence(f, coefficients=p).difference(ref) is None
    g = random_filtration(seed)
    raw = Filtration(g.simplices, g.values, validate=False)
    assert persistence(raw, coefficients=p).difference(gudhi_barcode(g, p)) is None


def test_missing_edge_is_reported():
    tri = Filtration(
        [np.array([[0], [1], [2]]), np.array([[0, 1], [1, 2]]), np.array([[0, 1, 2]])],
        [np.zeros(3), np.zeros(2), np.zeros(1)],
        validate=False,
    )
    with pytest.raises(ValueError, match="missing"):
        persistence(tri)


def test_trace_matrices_of_example_2_41():
    from thesis_lib.persistence import trace_matrices

    trace: list = []
    compute_intervals(example_filtration(), coefficients=3, trace=trace)
    before, after = trace_matrices(trace, coefficients=3, names="abcde")
    header = before[0]
    assert header == ["*", "a", "b", "c", "d", "e", "ab", "cd", "ad", "bc", "de", "ce", "cde"]
    col = {row[0]: row[header.index("cde")] for row in before[1:]}
    # the thesis's column ced: cd −t³, ed t, ce t; we orient cde = −ced and de = −ed: same powers
    assert (col["cd"], col["de"], col["ce"]) == ("t^3", "t", "-t")
    assert {row[0] for row in after[1:]} == {"a", "b", "c", "d", "e", "bc", "ce"}  # marked rows only
    assert [row[header.index("ad")] for row in after[1:4]] == ["-t^2", "0", "t"]  # da reduced: a, c
    with pytest.raises(ValueError, match="trace"):
        trace_matrices([], coefficients=3)

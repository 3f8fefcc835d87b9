"""The compiled kernels of flag complexes, witness complexes and the facet lookup (src/flag_complex.cpp,
src/witness_complex.cpp, src/facet_lookup.cpp): their values, their refusal of bad input with an
exception instead of a crash, and the witness levels' independence of the thread count."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from thesis_lib._core import facet_lookup, flag_complex, witness_complex
from thesis_lib.complexes import maxmin_landmarks, witness_offsets

I64 = np.int64


def upper_csr(n, edges, values):
    counts = np.bincount(edges[:, 0], minlength=n)
    indptr = np.zeros(n + 1, dtype=I64)
    np.cumsum(counts, out=indptr[1:])
    return indptr, np.ascontiguousarray(edges[:, 1], dtype=I64), np.ascontiguousarray(values, dtype=np.float64)


def test_pairwise_and_matrix_edges_against_brute_force():
    pts = np.random.default_rng(0).random((40, 3))
    d = np.sqrt(((pts[:, None] - pts[None]) ** 2).sum(-1))
    want = [(i, j) for i in range(40) for j in range(i + 1, 40) if d[i, j] <= 0.4]
    e, v = flag_complex.pairwise_edges(pts, 0.4)
    assert e.dtype == I64 and e.shape == (len(want), 2)
    assert [tuple(r) for r in e.tolist()] == want
    np.testing.assert_allclose(v, [d[i, j] for i, j in want], rtol=1e-15)
    e2, v2 = flag_complex.matrix_edges(d, 0.4)
    assert [tuple(r) for r in e2.tolist()] == want
    np.testing.assert_array_equal(v2, [d[i, j] for i, j in want])
    e3, v3 = flag_complex.pairwise_edges(np.empty((0, 2)), 1.0)
    assert e3.shape == (0, 2) and v3.shape == (0,)


def test_expand_level_finds_exactly_the_cliques():
    rng = np.random.default_rng(1)
    n = 14
    w = rng.random((n, n))
    w = np.triu(w, 1) + np.triu(w, 1).T
    edges, vals = flag_complex.matrix_edges(w, 0.6)
    indptr, indices, ev = upper_csr(n, edges, vals)
    tri, tv = flag_complex.expand_level(edges, vals, indptr, indices, ev)
    want = [c for c in itertools.combinations(range(n), 3)
            if all(w[a, b] <= 0.6 for a, b in itertools.combinations(c, 2))]
    assert [tuple(r) for r in tri.tolist()] == want
    np.testing.assert_array_equal(tv, [max(w[a, b] for a, b in itertools.combinations(c, 2)) for c in want])
    tet, _ = flag_complex.expand_level(tri, tv, indptr, indices, ev)
    want4 = [c for c in itertools.combinations(range(n), 4)
             if all(w[a, b] <= 0.6 for a, b in itertools.combinations(c, 2))]
    assert [tuple(r) for r in tet.tolist()] == want4


def test_flag_kernels_refuse_bad_input():
    edges = np.array([[0, 1], [0, 2], [1, 2]], dtype=I64)
    vals = np.array([0.1, 0.2, 0.3])
    indptr, indices, ev = upper_csr(3, edges, vals)
    with pytest.raises(ValueError, match="out of range"):
        flag_complex.expand_level(np.array([[0, 7]], dtype=I64), np.zeros(1), indptr, indices, ev)
    with pytest.raises(ValueError, match="out of range"):
        flag_complex.expand_level(np.array([[-1, 1]], dtype=I64), np.zeros(1), indptr, indices, ev)
    with pytest.raises(ValueError, match="one value per parent"):
        flag_complex.expand_level(edges, np.zeros(2), indptr, indices, ev)
    with pytest.raises(ValueError, match="at least one column"):
        flag_complex.expand_level(np.empty((2, 0), dtype=I64), np.zeros(2), indptr, indices, ev)
    with pytest.raises(ValueError, match="past the end"):
        flag_complex.expand_level(edges, vals, np.array([0, 2, 9, 9], dtype=I64), indices, ev)
    with pytest.raises(ValueError, match="non-decreasing"):
        flag_complex.expand_level(edges, vals, np.array([0, 2, 1, 3], dtype=I64), indices, ev)
    with pytest.raises(ValueError, match="one value per entry"):
        flag_complex.expand_level(edges, vals, indptr, indices, ev[:2])
    with pytest.raises(ValueError, match="must not be empty"):
        flag_complex.expand_level(edges, vals, np.empty(0, dtype=I64), indices, ev)
    with pytest.raises(ValueError, match="fewer columns"):
        flag_complex.matrix_edges(np.zeros((4, 2)), 1.0)
    with pytest.raises(TypeError):  # wrong dimension or dtype: nanobind refuses the call
        flag_complex.pairwise_edges(np.zeros(4), 1.0)
    # read-only inputs of another integer type are converted, not misread
    a = flag_complex.expand_level(edges.astype(np.int32), vals, indptr, indices, ev)
    b = flag_complex.expand_level(edges, vals, indptr, indices, ev)
    assert a[0].tolist() == b[0].tolist() == [[0, 1, 2]] and a[1].tolist() == b[1].tolist() == [0.3]


def witness_input(n_points=400, n_landmarks=12, seed=3):
    pts = np.random.default_rng(seed).random((n_points, 3))
    lm = maxmin_landmarks(pts, n=n_landmarks, seed=0)
    D = np.ascontiguousarray(witness_offsets(pts, lm, nu=1))
    ev, arg = witness_complex.edge_values(D)
    order = np.argsort(D, axis=1, kind="stable")
    sorted_d = np.ascontiguousarray(np.take_along_axis(D, order, axis=1))
    return D, ev, arg, order, sorted_d


def test_edge_values_against_brute_force():
    D, ev, arg, _, _ = witness_input()
    want = np.maximum(D[:, None, :], D[None, :, :]).min(axis=-1)
    np.testing.assert_array_equal(ev, want)
    L = D.shape[0]
    for a in range(L):
        for b in range(L):
            assert max(D[a, arg[a, b]], D[b, arg[a, b]]) == ev[a, b]


@pytest.mark.parametrize("use_sorted", [True, False])
def test_witness_level_threads_give_identical_output(use_sorted):
    D, ev, arg, order, sorted_d = witness_input(n_points=600, n_landmarks=14)
    tri = np.array(list(itertools.combinations(range(14), 3)), dtype=I64)
    sorted_lists = witness_complex.SortedDistances(order, sorted_d, use_sorted)
    for eps in (np.inf, 0.25, 0.1):
        one = witness_complex.witness_level(tri, D, ev, arg, eps, sorted_lists, n_threads=1)
        for threads in (2, 3, 0):
            other = witness_complex.witness_level(tri, D, ev, arg, eps, sorted_lists, n_threads=threads)
            assert one[0].tobytes() == other[0].tobytes() and one[1].tobytes() == other[1].tobytes()
        # the children of all triangles are the tetrahedra of value min_x max_{l in σ} D[l, x] <= eps,
        # clamped at 0
        want = [(c, D[list(c)].max(axis=0).min()) for c in itertools.combinations(range(14), 4)]
        want = [(c, max(v, 0.0)) for c, v in want if v <= eps]
        assert [tuple(r) for r in one[0].tolist()] == [c for c, _ in want]
        np.testing.assert_array_equal(one[1], [v for _, v in want])


def test_witness_kernels_refuse_bad_input():
    D, ev, arg, order, sorted_d = witness_input(n_points=50, n_landmarks=5)
    tri = np.array([[0, 1, 2]], dtype=I64)
    level, lists = witness_complex.witness_level, witness_complex.SortedDistances
    used, unused = lists(order, sorted_d, True), lists(order, sorted_d, False)
    with pytest.raises(ValueError, match="parent vertex"):
        level(np.array([[0, 1, 5]], dtype=I64), D, ev, arg, 1.0, used)
    bad_arg = arg.copy()
    bad_arg[0, 1] = 50
    with pytest.raises(ValueError, match="witness in arg"):
        level(tri, D, ev, bad_arg, 1.0, used)
    with pytest.raises(ValueError, match="L x L"):
        level(tri, D, ev[:4], arg, 1.0, used)
    with pytest.raises(ValueError, match="shape of D"):
        level(tri, D, ev, arg, 1.0, lists(order[:, :10], sorted_d, True))
    bad_order = order.copy()
    bad_order[2, 3] = -1
    with pytest.raises(ValueError, match="point in order"):
        level(tri, D, ev, arg, 1.0, lists(bad_order, sorted_d, True))
    with pytest.raises(ValueError, match="no points"):
        level(tri, np.empty((5, 0)), ev, arg, 1.0, unused)
    with pytest.raises(ValueError, match="at least one column"):
        level(np.empty((1, 0), dtype=I64), D, ev, arg, 1.0, unused)
    # without the sorted lists, order and sorted_d are not read: placeholders are fine
    a = level(tri, D, ev, arg, 1.0, lists(np.zeros((1, 1), I64), np.zeros((1, 1)), False))
    b = level(tri, D, ev, arg, 1.0, used)
    assert a[0].tobytes() == b[0].tobytes() and a[1].tobytes() == b[1].tobytes()


def brute_facets(lower, upper):
    where = {tuple(r): i for i, r in enumerate(lower.tolist())}
    return np.array([[where.get(tuple(r[:i] + r[i + 1:]), -1) for i in range(len(r))] for r in upper.tolist()],
                    dtype=I64).reshape(upper.shape[0], upper.shape[1])


@pytest.mark.parametrize("d", [1, 2, 3])
def test_facet_kernels_against_brute_force(d):
    rng = np.random.default_rng(d)
    upper = np.unique(np.sort(np.array([rng.choice(30, size=d + 1, replace=False) for _ in range(80)]), axis=1),
                      axis=0).astype(I64)
    lower = np.unique(np.vstack([np.delete(upper, i, axis=1) for i in range(d + 1)]), axis=0).astype(I64)
    lower = np.ascontiguousarray(lower[1:])  # one facet missing: -1 where it is wanted
    want = brute_facets(lower, upper)
    assert (want < 0).any()
    np.testing.assert_array_equal(facet_lookup.hashed(lower, upper, 30), want)
    if d == 2:
        np.testing.assert_array_equal(facet_lookup.edge_table(lower, upper, 30), want)


def test_facet_kernels_refuse_bad_input():
    lower = np.array([[0, 1], [0, 2], [1, 2]], dtype=I64)
    upper = np.array([[0, 1, 2]], dtype=I64)
    with pytest.raises(ValueError, match="one column more"):
        facet_lookup.hashed(lower, np.array([[0, 1]], dtype=I64), 3)
    with pytest.raises(ValueError, match="triangle vertex"):
        facet_lookup.edge_table(lower, np.array([[0, 1, 3]], dtype=I64), 3)
    with pytest.raises(ValueError, match="edge vertex"):
        facet_lookup.edge_table(np.array([[0, -1]], dtype=I64), upper, 3)
    with pytest.raises(ValueError, match="overflows"):
        facet_lookup.edge_table(lower, upper, 1 << 40)
    with pytest.raises(TypeError):  # not (m, 2) and (m, 3)
        facet_lookup.edge_table(upper, lower, 3)
    assert facet_lookup.edge_table(lower, upper, 3).tolist() == [[2, 1, 0]]
    assert facet_lookup.hashed(lower, upper, 3).tolist() == [[2, 1, 0]]

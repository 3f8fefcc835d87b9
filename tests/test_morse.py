"""Discrete Morse theory (thesis §4.2): functions, vector fields, flows, Morse complex, matchings."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
import scipy.sparse as sp
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.matrices.normalforms import smith_normal_form as sympy_snf

from thesis_lib.complexes.rips import rips
from thesis_lib.datasets import dunce_hat, klein_bottle, rp2, sphere, torus
from thesis_lib.homology import homology
from thesis_lib.homology.filtration import Filtration
from thesis_lib.morse import RP2_FACETS
from thesis_lib.morse.examples import rp2_gradient_field
from thesis_lib.morse.flow import (
    boundary_operator,
    cells,
    gradient_flow,
    gradient_matrix,
    is_flow_invariant,
    stabilised_flow,
)
from thesis_lib.morse.functions import (
    check_discrete_morse_function,
    critical_simplices,
    discrete_morse_function,
    gradient_pairs,
    is_discrete_morse_function,
    sublevel_complex,
)
from thesis_lib.morse.matching import critical_counts, morse_matching
from thesis_lib.morse.morse_complex import chain_complex_homology, morse_boundary, morse_homology
from thesis_lib.morse.vector_field import (
    check_vector_field,
    critical_cells,
    find_closed_vpath,
    gradient_paths,
    hasse_diagram,
    is_acyclic,
    vpaths,
)

SETTINGS = settings(deadline=None, max_examples=25)
seeds = st.integers(0, 2**31 - 1)


# ---------------------------------------------------------------------------- helpers
def random_complex(seed: int, max_vertices: int = 8) -> list[tuple[int, ...]]:
    """A random simplicial complex: random triangles and tetrahedra plus some isolated vertices."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(4, max_vertices + 1))
    tris = [t for t in itertools.combinations(range(n), 3) if rng.random() < 0.35]
    tets = [t for t in itertools.combinations(range(n), 4) if rng.random() < 0.06]
    edges = [e for e in itertools.combinations(range(n), 2) if rng.random() < 0.15]
    verts = [(v,) for v in range(n) if rng.random() < 0.2]
    out = tris + tets + edges + verts
    return out if out else [(0, 1)]


def all_simplices(simplices) -> list[tuple[int, ...]]:
    out = set()
    for s in simplices:
        s = tuple(sorted(s))
        for k in range(1, len(s) + 1):
            out.update(itertools.combinations(s, k))
    return sorted(out, key=lambda t: (len(t), t))


def random_field(seed: int, simplices) -> list:
    """Pairs from one of the heuristics, chosen by the seed."""
    rng = np.random.default_rng(seed)
    kind = int(rng.integers(0, 4))
    if kind == 0:
        return morse_matching(simplices, heuristic="coreduction", seed=seed)
    if kind == 1:
        return morse_matching(simplices, heuristic="collapse", seed=seed)
    if kind == 2:
        nv = max(v for s in simplices for v in s) + 1
        return morse_matching(simplices, heuristic="lower-star", values=rng.random(nv))
    # a random discrete Morse function of a random field -> its gradient pairs
    f = discrete_morse_function(simplices, morse_matching(simplices, heuristic="coreduction", seed=seed))
    return gradient_pairs(f)


def random_any_matching(seed: int, simplices) -> list:
    """A random (possibly cyclic) discrete vector field: greedy on shuffled codimension-one incidences."""
    rng = np.random.default_rng(seed)
    incid = [(f, s) for s in all_simplices(simplices) if len(s) > 1 for f in itertools.combinations(s, len(s) - 1)]
    rng.shuffle(incid)
    used, pairs = set(), []
    for f, s in incid:
        if f not in used and s not in used and rng.random() < 0.7:
            used.update((f, s))
            pairs.append((f, s))
    return pairs


def z2_betti(simplices) -> list[int]:
    return [b for b, _ in homology(simplices, coefficients=2)]


COMPLEXES = {
    "rp2": rp2(),
    "torus": torus(),
    "klein": klein_bottle(),
    "dunce-hat": dunce_hat(),
    "s2": sphere(2),
    "s3": sphere(3),
}


# ---------------------------------------------------------------------------- Definition 4.20 / 4.21
TRIANGLE = [(0,), (1,), (2,), (0, 1), (0, 2), (1, 2), (0, 1, 2)]


def test_dimension_function_is_morse_with_everything_critical():
    f = {s: float(len(s) - 1) for s in TRIANGLE}  # f_d(σ^(k)) = k, §4.2.1
    assert is_discrete_morse_function(f)
    assert critical_simplices(f) == TRIANGLE
    assert gradient_pairs(f) == []


def test_example_4_23_functions_on_a_hollow_triangle():
    # right of Figure 4.3 (a hollow triangle, V = 0 on edges, §4.2.3): critical values 0 and 5
    good = {(0,): 0, (1,): 2, (2,): 3, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5}
    assert is_discrete_morse_function(good)
    assert critical_simplices(good) == [(0,), (0, 2)]
    assert [good[s] for s in critical_simplices(good)] == [0, 5]
    assert gradient_pairs(good) == [((1,), (0, 1)), ((2,), (1, 2))]
    # left of Figure 4.3: f^{-1}(0) is an edge below both its vertices, f^{-1}(5) a vertex above both edges
    bad = {(0,): 1, (1,): 2, (2,): 5, (0, 1): 0, (1, 2): 3, (0, 2): 4}
    assert not is_discrete_morse_function(bad)
    with pytest.raises(ValueError, match=r"simplex \(2,\) breaks condition 1 of Definition 4.20"):
        check_discrete_morse_function(bad)
    bad[(2,)] = 3.5  # only the edge problem is left
    with pytest.raises(ValueError, match=r"simplex \(0, 1\) breaks condition 2 of Definition 4.20"):
        check_discrete_morse_function(bad)
    with pytest.raises(ValueError, match="Definition 4.20"):
        critical_simplices(bad)
    with pytest.raises(ValueError, match="Definition 4.20"):
        gradient_pairs(bad)


@pytest.mark.parametrize(
    "values, message",
    [
        ({}, "non-empty"),
        ({(0, 1): 1.0, (0,): 0.0}, r"face \(1,\) has no value"),
        ({(0,): float("nan")}, "non-finite"),
        ({(0,): 0.0, (1,): 1.0, (0, 1): 0.5, (1, 0): 0.7}, "given twice"),
        ({(0, 0): 1.0}, "not a simplex"),
        ({(0,): "x"}, "non-numeric"),
    ],
)
def test_bad_function_input(values, message):
    with pytest.raises(ValueError, match=message):
        is_discrete_morse_function(values)


def _brute_conditions(f: dict) -> dict:
    """(4.4) and (4.5) for every simplex, straight from the definitions."""
    out = {}
    for s in f:
        cof = [t for t in f if len(t) == len(s) + 1 and set(s) <= set(t)]
        fac = [g for g in f if len(g) == len(s) - 1 and set(g) <= set(s)]
        out[s] = (any(f[t] <= f[s] for t in cof), any(f[g] >= f[s] for g in fac),
                  sum(f[t] <= f[s] for t in cof), sum(f[g] >= f[s] for g in fac))
    return out


@SETTINGS
@given(seeds)
def test_lemma_4_22_and_definition_4_21(seed):
    rng = np.random.default_rng(seed)
    cx = random_complex(seed, 6)
    if rng.random() < 0.5:
        f = discrete_morse_function(cx, random_field(seed, cx))
        f = {s: np.exp(v / 10) for s, v in f.items()}  # strictly monotone change keeps Definition 4.20
    else:  # random values near the dimension; keep only Morse functions
        f = {s: len(s) - 1 + 1.2 * rng.standard_normal() for s in all_simplices(cx)}
    brute = _brute_conditions(f)
    morse = all(c1 <= 1 and c2 <= 1 for _, _, c1, c2 in brute.values())
    assert is_discrete_morse_function(f) == morse
    if not morse:
        with pytest.raises(ValueError, match="Definition 4.20"):
            check_discrete_morse_function(f)
        return
    for s, (a, b, _, _) in brute.items():
        assert not (a and b), f"Lemma 4.22 fails at {s}"
    assert critical_simplices(f) == sorted((s for s, (a, b, _, _) in brute.items() if not a and not b),
                                           key=lambda t: (len(t), t))
    pairs = gradient_pairs(f)
    check_vector_field(cx, pairs)  # Definition 4.33 holds: each simplex in at most one pair
    assert is_acyclic(cx, pairs)  # Theorem 4.36, gradient fields have no closed V-path


@SETTINGS
@given(seeds)
def test_theorem_4_36_round_trip(seed):
    cx = random_complex(seed)
    pairs = random_field(seed, cx)
    f = discrete_morse_function(cx, pairs)
    assert is_discrete_morse_function(f)
    assert sorted(gradient_pairs(f)) == sorted(pairs)
    crit = [s for dim in critical_cells(cx, pairs) for s in dim]
    assert critical_simplices(f) == crit


def test_sublevel_complex_values():
    f = {(0,): 0, (1,): 1, (2,): 2, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5, (0, 1, 2): 4}
    assert sublevel_complex(f, -1) == []
    assert sublevel_complex(f, 0) == [(0,)]
    assert sublevel_complex(f, 1.5) == [(0,), (1,), (0, 1)]
    # the triangle enters at 4 and drags its faces (0, 2) along (K^a is a complex)
    assert sublevel_complex(f, 4) == TRIANGLE
    with pytest.raises(ValueError, match="NaN"):
        sublevel_complex(f, float("nan"))


@settings(deadline=None, max_examples=12)
@given(seeds)
def test_theorems_4_25_4_26_crossing_critical_values(seed):
    """Between consecutive values nothing changes unless the value is critical; crossing a critical
    k-simplex attaches a k-cell: β_k goes up by one or β_{k-1} down by one (Z/2 Betti numbers)."""
    cx = random_complex(seed, 6)
    f = discrete_morse_function(cx, random_field(seed, cx))  # injective values 1..n
    crit = {s: len(s) - 1 for s in critical_simplices(f)}
    by_value = {v: s for s, v in f.items()}
    levels = sorted(by_value)
    prev = None
    for v in levels:
        k_now = sublevel_complex(f, v)
        b_now = z2_betti(k_now) + [0] * 5
        s = by_value[v]
        if prev is not None:
            k_prev, b_prev = prev
            if s in crit:
                k = crit[s]
                diff = np.array(b_now[:5]) - np.array(b_prev[:5])
                up = np.zeros(5, int)
                up[k] = 1
                down = np.zeros(5, int)
                if k > 0:
                    down[k - 1] = -1
                assert np.array_equal(diff, up) or (k > 0 and np.array_equal(diff, down))
                assert set(k_now) - set(k_prev) == {s}  # exactly the cell σ is attached
            else:
                assert b_now[:5] == b_prev[:5]  # Theorem 4.25
        else:
            assert s in crit and len(s) == 1  # the minimum is a critical vertex
        prev = (k_now, b_now)


# ---------------------------------------------------------------------------- Definitions 4.30–4.31
@SETTINGS
@given(seeds)
def test_gradient_and_flow_properties(seed):
    cx = random_complex(seed, 6)
    pairs = random_field(seed, cx)
    basis = cells(cx)
    pos = {s: i for i, s in enumerate(basis)}
    d = boundary_operator(cx)
    v = gradient_matrix(cx, pairs)
    phi = gradient_flow(cx, pairs)
    assert v.dtype == np.int64 and phi.dtype == np.int64
    # Definition 4.30: V(σ) = -<∂τ, σ> τ
    for s, t in pairs:
        assert v[pos[t], pos[s]] == -d[pos[s], pos[t]]
    assert (v @ v).nnz == 0 or not (v @ v).toarray().any()  # Proposition 4.32 (1)
    hits = np.asarray((v != 0).sum(axis=1)).ravel()
    assert hits.max(initial=0) <= 1  # Proposition 4.32 (2)
    crit = set(s for dim in critical_cells(cx, pairs) for s in dim)
    in_image = hits > 0
    zero = np.asarray((v != 0).sum(axis=0)).ravel() == 0
    for s, i in pos.items():  # Proposition 4.32 (3)
        assert (s in crit) == (not in_image[i] and zero[i])
    # Definition 4.31 and Proposition 4.37
    ident = sp.identity(len(basis), dtype=np.int64)
    assert not (phi - (ident + d @ v + v @ d)).toarray().any()
    assert not (phi @ d - d @ phi).toarray().any()
    # Theorem 4.38: Φ^N = Φ^{N+1}; Φ^∞ chains are Φ-invariant
    inf, n = stabilised_flow(cx, pairs)
    assert not (phi @ inf - inf).toarray().any()
    col = inf[:, int(np.argmax(np.diff(inf.indptr)))].toarray().ravel()
    assert is_flow_invariant(cx, pairs, col)
    # Proposition 4.40 (2): <Φ^∞(σ), σ'> = δ on critical simplices
    ci = [pos[s] for s in sorted(crit, key=lambda t: (len(t), t))]
    assert np.array_equal(inf[ci][:, ci].toarray(), np.eye(len(ci), dtype=np.int64))
    # Theorems 4.41 / 4.42: ∂̃ = ∂Φ^∞ read on critical cells equals the gradient-path boundary
    crit_by_dim, mats = morse_boundary(cx, pairs)
    full = (d @ inf).tocsr()
    for k in range(1, len(mats)):
        rows = [pos[s] for s in crit_by_dim[k - 1]]
        cols = [pos[s] for s in crit_by_dim[k]]
        assert np.array_equal(full[rows][:, cols].toarray(), mats[k].toarray())


def test_flow_examples_and_errors():
    pairs = rp2_gradient_field()
    inf, n = stabilised_flow(RP2_FACETS, pairs)
    assert n >= 1
    phi = gradient_flow(RP2_FACETS, pairs)
    assert not (phi @ inf - inf).toarray().any()
    assert stabilised_flow(RP2_FACETS, [])[1] == 0  # V = 0 ⇒ Φ = id
    with pytest.raises(ValueError, match="coefficients"):
        is_flow_invariant(RP2_FACETS, pairs, np.zeros(3))
    cyc = [((0,), (0, 1)), ((1,), (1, 2)), ((2,), (0, 2))]
    with pytest.raises(ValueError, match="stabilise"):
        stabilised_flow([(0, 1), (1, 2), (0, 2)], cyc)


# ---------------------------------------------------------------------------- Definitions 4.33–4.34
CIRCLE = [(0, 1), (1, 2), (0, 2)]
CYCLIC = [((0,), (0, 1)), ((1,), (1, 2)), ((2,), (0, 2))]


@pytest.mark.parametrize(
    "pairs, message",
    [
        ([((0,), (1, 2))], "codimension one"),
        ([((0,), (0, 1, 2))], "codimension one"),
        ([((0,), (0, 1)), ((1,), (0, 1))], r"\(0, 1\) is in two pairs"),
        ([((0,), (0, 5))], r"\(0, 5\) is not in the complex"),
        ([((0,),)], "two simplices"),
    ],
)
def test_bad_vector_fields(pairs, message):
    with pytest.raises(ValueError, match=message):
        check_vector_field(TRIANGLE, pairs)
    with pytest.raises(ValueError, match=message):
        morse_homology(TRIANGLE, pairs)


def test_closed_vpath_detected_and_reported():
    assert not is_acyclic(CIRCLE, CYCLIC)
    assert not is_acyclic(CIRCLE, CYCLIC, method="hasse")
    path = find_closed_vpath(CIRCLE, CYCLIC)
    assert path[0] == path[-1] and len(path) == 7
    for i in range(0, len(path) - 2, 2):
        s, t, s2 = path[i], path[i + 1], path[i + 2]
        assert (s, t) in CYCLIC and set(s2) < set(t) and s2 != s  # Definition 4.34
    with pytest.raises(ValueError,
                       match=r"closed V-path \(0,\) > \(0, 1\) > \(1,\) > \(1, 2\) > \(2,\) > \(0, 2\) > \(0,\)"):
        morse_homology(CIRCLE, CYCLIC)
    with pytest.raises(ValueError, match="closed V-path"):
        morse_boundary(CIRCLE, CYCLIC)
    with pytest.raises(ValueError, match="closed V-path"):
        discrete_morse_function(CIRCLE, CYCLIC)
    with pytest.raises(ValueError, match="closed V-path"):
        vpaths(CIRCLE, CYCLIC, (0,))
    assert find_closed_vpath(CIRCLE, CYCLIC[:2]) is None
    with pytest.raises(ValueError, match="method"):
        is_acyclic(CIRCLE, [], method="dfs")


def test_closed_vpath_in_dimension_one():
    # the boundary of a tetrahedron's faces around vertex 0: edges to triangles in a cycle
    tet = list(itertools.combinations(range(4), 3))
    cyc = [((0, 1), (0, 1, 2)), ((0, 2), (0, 2, 3)), ((0, 3), (0, 1, 3))]
    path = find_closed_vpath(tet, cyc)
    assert path is not None and path[0] == path[-1] and len(path[0]) == 2
    assert not is_acyclic(tet, cyc, method="hasse")


@SETTINGS
@given(seeds)
def test_theorem_4_44_vpaths_vs_hasse(seed):
    cx = random_complex(seed, 6)
    pairs = random_any_matching(seed, cx)
    a = is_acyclic(cx, pairs)
    assert a == is_acyclic(cx, pairs, method="hasse")
    path = find_closed_vpath(cx, pairs)
    assert (path is None) == a
    if path is not None:
        assert path[0] == path[-1]
        for i in range(0, len(path) - 2, 2):
            assert (path[i], path[i + 1]) in set(pairs) and set(path[i + 2]) < set(path[i + 1])


def test_modified_hasse_diagram():
    # Figure 4.7–4.8 style: a circle of three edges; reversed edges are exactly the pairs
    pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    basis, g = hasse_diagram(CIRCLE, pairs)
    pos = {s: i for i, s in enumerate(basis)}
    assert g.nnz == 6
    assert g[pos[(1,)], pos[(0, 1)]] and not g[pos[(0, 1)], pos[(1,)]]
    assert g[pos[(0, 2)], pos[(0,)]] and g[pos[(0, 2)], pos[(2,)]]
    assert critical_cells(CIRCLE, pairs) == [[(0,)], [(0, 2)]]  # Example 4.45: two critical cells, a 1-sphere


# ---------------------------------------------------------------------------- Theorem 4.42 / Example 4.43
def test_example_4_43_rp2():
    assert sorted(RP2_FACETS) == sorted(rp2())
    pairs = rp2_gradient_field()
    assert is_acyclic(RP2_FACETS, pairs)
    crit, mats = morse_boundary(RP2_FACETS, pairs)
    assert crit == [[(0,)], [(0, 2)], [(0, 2, 4)]]  # a, σ = ac, τ = ace
    assert mats[1].toarray().tolist() == [[0]]
    assert mats[2].toarray().tolist() == [[2]]  # Z --2--> Z --0--> Z
    to_a = gradient_paths(RP2_FACETS, pairs, (0, 2), (0,))
    assert sorted(m for _, m in to_a) == [-1, 1]  # begin in a or in c: they cancel
    assert {p[1] for p, _ in to_a} == {(0,), (2,)}
    to_sigma = gradient_paths(RP2_FACETS, pairs, (0, 2, 4), (0, 2))
    assert [m for _, m in to_sigma] == [1, 1]  # two paths of multiplicity +1
    assert morse_homology(RP2_FACETS, pairs) == [(1, []), (0, [2]), (0, [])]
    assert morse_homology(RP2_FACETS, pairs, coefficients=2) == [(1, []), (1, []), (1, [])]
    assert morse_homology(RP2_FACETS, pairs, coefficients=3) == [(1, []), (0, []), (0, [])]
    # maximal V-paths from c end in a
    ends = {p[-1] for p in vpaths(RP2_FACETS, pairs, (2,))}
    assert ends == {(0,)}
    assert vpaths(RP2_FACETS, pairs, (0,)) == [[(0,)]]


@pytest.mark.parametrize("name", sorted(COMPLEXES))
@pytest.mark.parametrize("method", ["coreduction", "collapse", "lower-star"])
def test_morse_homology_on_triangulations(name, method):
    cx = COMPLEXES[name]
    nv = max(v for s in cx for v in s) + 1
    values = np.random.default_rng(1).random(nv) if method == "lower-star" else None
    pairs = morse_matching(cx, heuristic=method, values=values)
    assert is_acyclic(cx, pairs)
    for p in (0, 2, 3):
        assert morse_homology(cx, pairs, coefficients=p) == homology(cx, coefficients=p)
    counts = critical_counts(cx, pairs)
    betti = [b for b, _ in homology(cx, coefficients=2)]
    assert all(b <= c for b, c in zip(betti, counts))  # Theorem 4.27
    if method == "coreduction" and name in ("s2", "s3", "torus"):
        assert counts == betti  # perfect on these


@settings(deadline=None, max_examples=40)
@given(seeds)
def test_morse_homology_equals_homology_random(seed):
    cx = random_complex(seed)
    pairs = random_field(seed, cx)
    assert is_acyclic(cx, pairs)
    p = int(np.random.default_rng(seed).choice([0, 2, 3]))
    assert morse_homology(cx, pairs, coefficients=p) == homology(cx, coefficients=p)
    crit, mats = morse_boundary(cx, pairs, coefficients=p)
    for k in range(2, len(mats)):  # ∂̃∂̃ = 0
        prod = (mats[k - 1] @ mats[k]).toarray()
        assert not (prod % p if p else prod).any()


@settings(deadline=None, max_examples=10)
@given(seeds)
def test_morse_boundary_is_sum_over_gradient_paths(seed):
    """Theorem 4.42 literally: enumerate Γ(τ, σ) and add the multiplicities."""
    cx = random_complex(seed, 6)
    pairs = random_field(seed, cx)
    crit, mats = morse_boundary(cx, pairs)
    for k in range(1, len(mats)):
        for j, t in enumerate(crit[k]):
            for i, s in enumerate(crit[k - 1]):
                total = sum(m for _, m in gradient_paths(cx, pairs, t, s))
                assert mats[k][i, j] == total


def test_morse_boundary_torsion_vs_sympy_snf():
    cx = klein_bottle()
    pairs = morse_matching(cx, heuristic="collapse", seed=3)
    crit, mats = morse_boundary(cx, pairs)
    for k in range(1, len(mats)):
        m = mats[k].toarray()
        if m.size == 0:
            continue
        snf = sympy_snf(sympy.Matrix(m.tolist()), domain=sympy.ZZ)
        diag = sorted(abs(int(snf[i, i])) for i in range(min(snf.shape)) if snf[i, i] != 0)
        torsion = [x for x in diag if x > 1]
        assert torsion == morse_homology(cx, pairs)[k - 1][1]
    assert morse_homology(cx, pairs) == [(1, []), (1, [2]), (0, [])]


def test_chain_complex_homology_errors():
    with pytest.raises(ValueError, match="empty"):
        chain_complex_homology([])
    with pytest.raises(ValueError, match="rows"):
        chain_complex_homology([np.zeros((0, 2)), np.zeros((3, 1))])
    with pytest.raises(ValueError, match="prime"):
        morse_homology(TRIANGLE, [], coefficients=4)


# ---------------------------------------------------------------------------- §4.2.6 matchings
@settings(deadline=None, max_examples=30)
@given(seeds)
def test_weak_and_strong_morse_inequalities(seed):
    cx = random_complex(seed)
    pairs = random_field(seed, cx)
    counts = critical_counts(cx, pairs)
    for p in (0, 2):
        betti = [b for b, _ in homology(cx, coefficients=p)]
        assert all(b <= c for b, c in zip(betti, counts))  # Theorem 4.27
        assert sum((-1) ** k * b for k, b in enumerate(betti)) == sum((-1) ** k * c for k, c in enumerate(counts))
        for k in range(len(counts)):  # Theorem 4.28
            sb = sum((-1) ** (k - i) * betti[i] for i in range(k + 1))
            sc = sum((-1) ** (k - i) * counts[i] for i in range(k + 1))
            assert sb <= sc


@SETTINGS
@given(seeds)
def test_coreduction_one_critical_vertex_per_component(seed):
    cx = random_complex(seed)
    pairs = morse_matching(cx, heuristic="coreduction", seed=seed)
    assert critical_counts(cx, pairs)[0] == homology(cx)[0][0]


@SETTINGS
@given(seeds)
def test_lower_star_pairs_stay_in_lower_stars(seed):
    cx = random_complex(seed)
    nv = max(v for s in cx for v in s) + 1
    values = np.round(np.random.default_rng(seed).random(nv), 1)  # ties on purpose
    pairs = morse_matching(cx, heuristic="lower-star", values=values)
    rank = np.lexsort((np.arange(nv), values))
    order = np.empty(nv, int)
    order[rank] = np.arange(nv)
    for s, t in pairs:
        assert max(s, key=lambda v: order[v]) == max(t, key=lambda v: order[v])
    assert is_acyclic(cx, pairs)
    assert morse_homology(cx, pairs) == homology(cx)


def test_lower_star_height_on_sphere_is_perfect():
    cx = sphere(2)
    nv = max(v for s in cx for v in s) + 1
    pairs = morse_matching(cx, heuristic="lower-star", values=np.arange(nv, dtype=float))
    assert critical_counts(cx, pairs)[0] >= 1
    assert morse_homology(cx, pairs) == homology(cx)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(heuristic="greedy"), "heuristic must be"),
        (dict(heuristic="lower-star"), "needs vertex values"),
        (dict(heuristic="coreduction", values=[0.0, 1.0, 2.0]), "takes no values"),
        (dict(heuristic="lower-star", values=[0.0, 1.0]), "cover 2 vertices"),
        (dict(heuristic="lower-star", values=[0.0, np.nan, 1.0]), "finite"),
        (dict(heuristic="lower-star", values=[[0.0, 1.0, 2.0]]), "1-D"),
    ],
)
def test_matching_bad_input(kwargs, message):
    with pytest.raises(ValueError, match=message):
        morse_matching(TRIANGLE, **kwargs)


def test_matching_deterministic_and_seeded():
    cx = torus()
    assert morse_matching(cx) == morse_matching(cx)
    assert morse_matching(cx, seed=5) == morse_matching(cx, seed=5)
    assert critical_counts(cx, morse_matching(cx, heuristic="collapse", seed=2))[0] == 1


def test_public_contract_of_design_md():
    """The signatures DESIGN.md fixes for thesis_lib.morse."""
    import inspect

    import thesis_lib.morse as m

    def params(f):
        return list(inspect.signature(f).parameters)

    assert params(m.is_discrete_morse_function) == ["values"]
    assert params(m.critical_simplices) == ["values"]
    assert params(m.gradient_pairs) == ["values"]
    assert params(m.is_acyclic)[:2] == ["simplices", "pairs"]
    assert params(m.morse_matching)[0] == "simplices"
    assert params(m.morse_homology) == ["simplices", "pairs", "coefficients"]
    assert inspect.signature(m.morse_homology).parameters["coefficients"].default == 0
    pairs = m.morse_matching(rp2())
    assert m.is_acyclic(rp2(), pairs) and m.morse_homology(rp2(), pairs) == homology(rp2())


# ---------------------------------------------------------------------------- any complex: Filtration in, same answers
def _as_mapping(filt: Filtration) -> dict[tuple[int, ...], float]:
    return {tuple(int(x) for x in row): float(v) for s, vs in zip(filt.simplices, filt.values) for row, v in zip(s, vs)}


def test_filled_triangle_filtration_is_a_morse_function():
    # vertices at 0, edges at 1, 2, 3 and the triangle at 3: the triangle pairs with its last edge
    filt = Filtration.from_pairs([((0,), 0), ((1,), 0), ((2,), 0), ((0, 1), 1), ((0, 2), 2), ((1, 2), 3),
                                  ((0, 1, 2), 3)])
    assert is_discrete_morse_function(filt)
    assert critical_simplices(filt) == [(0,), (1,), (2,), (0, 1), (0, 2)]
    assert gradient_pairs(filt) == [((1, 2), (0, 1, 2))]
    assert sublevel_complex(filt, 1.5) == [(0,), (1,), (2,), (0, 1)]
    assert sublevel_complex(filt, -1) == []


def _random_filtration(seed: int) -> Filtration:
    """A random complex with monotone values that often tie (so Definition 4.20 holds or fails)."""
    rng = np.random.default_rng(seed)
    simplices = all_simplices(random_complex(seed, 6))
    vals: dict[tuple[int, ...], float] = {}
    for s in simplices:  # by dimension: faces first
        below = max((vals[f] for f in itertools.combinations(s, len(s) - 1)), default=0.0) if len(s) > 1 else 0.0
        vals[s] = below + float(rng.integers(1, 4)) * (rng.random() < 0.85)
    return Filtration.from_pairs(sorted(vals.items(), key=lambda kv: (kv[1], len(kv[0]), kv[0])))


@settings(deadline=None, max_examples=40)
@given(seeds)
def test_morse_function_given_a_filtration_equals_its_mapping(seed):
    filt = _random_filtration(seed)
    f = _as_mapping(filt)
    morse = is_discrete_morse_function(f)
    assert is_discrete_morse_function(filt) == morse
    if not morse:
        with pytest.raises(ValueError, match="Definition 4.20") as from_map:
            check_discrete_morse_function(f)
        with pytest.raises(ValueError, match="Definition 4.20") as from_filt:
            check_discrete_morse_function(filt)
        assert str(from_filt.value) == str(from_map.value)
        with pytest.raises(ValueError, match="Definition 4.20"):
            gradient_pairs(filt)
        return
    assert critical_simplices(filt) == critical_simplices(f)
    assert gradient_pairs(filt) == gradient_pairs(f)
    level = sorted(f.values())[len(f) // 2]
    assert sublevel_complex(filt, level) == sublevel_complex(f, level)
    # the gradient of a filtration pairs only simplices of equal value (faces never exceed cofaces)
    assert all(f[s] == f[t] for s, t in gradient_pairs(filt))


@SETTINGS
@given(seeds)
def test_vector_field_functions_given_a_filtration_equal_the_simplex_list(seed):
    simplices = random_complex(seed)
    filt = Filtration.from_simplices(simplices)
    pairs = random_field(seed, simplices)
    assert (morse_matching(filt, heuristic="coreduction", seed=seed)
            == morse_matching(simplices, heuristic="coreduction", seed=seed))
    assert critical_cells(filt, pairs) == critical_cells(simplices, pairs)
    assert morse_homology(filt, pairs) == morse_homology(simplices, pairs) == homology(simplices)
    assert discrete_morse_function(filt, pairs) == discrete_morse_function(simplices, pairs)
    assert cells(filt) == cells(simplices) == all_simplices(simplices)
    assert (boundary_operator(filt) != boundary_operator(simplices)).nnz == 0


def test_morse_homology_of_a_rips_filtration():
    points = np.random.default_rng(3).random((40, 2))
    filt = rips(points, max_radius=0.2, max_dim=2)
    pairs = morse_matching(filt)
    assert is_acyclic(filt, pairs)
    assert morse_homology(filt, pairs) == homology(filt) == homology(cells(filt))
    assert sum(critical_counts(filt, pairs)) < len(cells(filt))


def test_filtration_errors_for_morse_functions_and_fields():
    plain = Filtration.from_simplices([(0, 1, 2)])
    with pytest.raises(ValueError, match="needs values"):
        is_discrete_morse_function(plain)
    flat = Filtration(plain.simplices, [np.zeros(len(s)) for s in plain.simplices])  # every vertex ties two edges
    assert not is_discrete_morse_function(flat)
    with pytest.raises(ValueError, match=r"simplex \(0,\) breaks condition 1 of Definition 4.20: 2 cofaces"):
        critical_simplices(flat)
    circle = Filtration.from_simplices(CIRCLE)
    with pytest.raises(ValueError, match=r"closed V-path \(0,\) > \(0, 1\) > \(1,\)"):
        morse_homology(circle, CYCLIC)
    with pytest.raises(ValueError, match="closed V-path"):
        discrete_morse_function(circle, CYCLIC)
    with pytest.raises(ValueError, match="closed V-path"):
        gradient_paths(circle, CYCLIC, (0, 1), (0,))
    assert find_closed_vpath(circle, CYCLIC)[0] == (0,)
    with pytest.raises(ValueError, match="stabilise"):
        stabilised_flow(circle, CYCLIC)


@pytest.mark.parametrize(
    "values, message",
    [
        ({(0.5,): 0.0}, "vertex labels must be integers"),
        ({("a",): 0.0}, "vertex labels must be integers"),
        ({(-1,): 0.0}, "not a simplex"),
        ({5: 0.0}, "not a simplex"),
        ([((0,), 0.0)], "non-empty mapping"),
    ],
)
def test_bad_vertex_labels_in_a_morse_function(values, message):
    with pytest.raises(ValueError, match=message):
        is_discrete_morse_function(values)


@pytest.mark.parametrize(
    "pairs, message",
    [
        ("ab", "iterable of pairs"),
        (5, "iterable of pairs"),
        (["ab"], "two simplices"),
        ([((0,), "01")], "holds two simplices"),
        ([((0,), 1)], "holds two simplices"),
    ],
)
def test_malformed_vector_fields(pairs, message):
    with pytest.raises(ValueError, match=message):
        check_vector_field(TRIANGLE, pairs)
    with pytest.raises(ValueError, match=message):
        morse_boundary(Filtration.from_simplices(TRIANGLE), pairs)

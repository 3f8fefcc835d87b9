"""Tests for thesis_lib.homology and the triangulations of thesis_lib.datasets."""

import collections
import itertools

import gudhi
import numpy as np
import pytest
from helpers import THESIS_M2, sympy_invariants
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.datasets import RP2_LABELS, dunce_hat, klein_bottle, rp2, sphere, torus
from thesis_lib.homology import (
    betti_numbers,
    boundary_matrices,
    euler_characteristic,
    homology,
    simplex_counts,
)
from thesis_lib.homology._elimination import markowitz_eliminate
from thesis_lib.homology._modular import dense_invariants
from thesis_lib.homology.simplicial import closure
from thesis_lib.homology.smith import dense_smith_diagonal, reduce_matrix

# ------------------------------------------------------------------ random complexes


def random_flag_complex(seed: int, n: int = 9, max_dim: int = 3) -> list[tuple[int, ...]]:
    rng = np.random.default_rng(seed)
    prob = rng.uniform(0.3, 0.8)
    adj = np.triu(rng.random((n, n)) < prob, 1)
    adj = adj | adj.T
    out = [(v,) for v in range(n)]
    for k in range(2, max_dim + 2):
        for c in itertools.combinations(range(n), k):
            if all(adj[a, b] for a, b in itertools.combinations(c, 2)):
                out.append(c)
    return out


def random_subset_complex(seed: int, n: int = 7) -> list[tuple[int, ...]]:
    """Random simplices of the full simplex on n vertices (faces are added by closure)."""
    rng = np.random.default_rng(seed)
    out = []
    for k in range(1, 5):
        cand = list(itertools.combinations(range(n), k + 1))
        take = rng.random(len(cand)) < rng.uniform(0.05, 0.35) / k
        out += [c for c, t in zip(cand, take) if t]
    return out or [(0, 1)]


def random_complex(seed: int) -> list[tuple[int, ...]]:
    return random_flag_complex(seed) if seed % 2 else random_subset_complex(seed)


def gudhi_betti(simplices, p: int) -> list[int]:
    tree = gudhi.SimplexTree()
    for s in simplices:
        tree.insert(list(s), 0.0)
    tree.compute_persistence(homology_coeff_field=p, persistence_dim_max=True)
    b = tree.betti_numbers()
    return b + [0] * (tree.dimension() + 1 - len(b))


def sympy_homology(simplices) -> list[tuple[int, list[int]]]:
    """Reference: homology over Z from sympy's invariant factors of dense boundary matrices."""
    cx = closure(simplices)
    mats = boundary_matrices(cx, coefficients=0)
    ranks, tors = [0] * (len(cx) + 1), [[] for _ in range(len(cx) + 1)]
    for k in range(1, len(cx)):
        d = mats[k].toarray()
        inv = sympy_invariants(d)
        ranks[k], tors[k] = len(inv), sorted(x for x in inv if x > 1)
    return [(len(cx[k]) - ranks[k] - ranks[k + 1], tors[k + 1]) for k in range(len(cx))]


# ------------------------------------------------------------------ thesis values


def test_rp2_example_2_21():
    assert homology(rp2()) == [(1, []), (0, [2]), (0, [])]
    assert homology(rp2(), coefficients=2) == [(1, []), (1, []), (1, [])]
    assert homology(rp2(), coefficients=3) == [(1, []), (0, []), (0, [])]
    assert betti_numbers(rp2(), coefficients=2) == [1, 1, 1]
    assert simplex_counts(rp2()) == [6, 15, 10]


def test_rp2_matches_the_thesis_boundary_matrix():
    """Definition 2.18 on the thesis's oriented triangles gives M_2 of Example 2.21 entry by entry."""
    edges = [tuple(RP2_LABELS.index(c) for c in e) for e in
             ("ab ac ad ae af bc bd be bf cd ce cf de df ef".split())]
    m2 = np.zeros((15, 10), dtype=np.int64)
    for j, tri in enumerate(rp2(oriented=True)):
        for i in range(3):
            face = tri[:i] + tri[i + 1:]
            sign = (-1) ** i * (1 if face[0] < face[1] else -1)
            m2[edges.index(tuple(sorted(face))), j] += sign
    assert np.array_equal(m2, THESIS_M2)
    # and our sorted-orientation matrix differs only by column signs
    cx = closure(rp2())
    ours = boundary_matrices(cx, coefficients=0)[2].toarray()
    tris = [tuple(t) for t in cx[2].tolist()]
    order = [tris.index(tuple(sorted(t))) for t in rp2(oriented=True)]
    assert np.array_equal(np.abs(ours[:, order]), np.abs(THESIS_M2))
    red1 = reduce_matrix(boundary_matrices(closure(rp2()), coefficients=0)[1])
    assert (red1.rank, red1.invariants) == (5, [])  # thesis: M~_1 has five 1s


def test_surfaces_and_spheres():
    assert homology(torus()) == [(1, []), (2, []), (1, [])]
    assert homology(torus(), coefficients=2) == [(1, []), (2, []), (1, [])]
    assert simplex_counts(torus()) == [7, 21, 14]
    assert homology(klein_bottle()) == [(1, []), (1, [2]), (0, [])]
    assert homology(klein_bottle(n=3, m=5)) == [(1, []), (1, [2]), (0, [])]
    assert homology(klein_bottle(), coefficients=2) == [(1, []), (2, []), (1, [])]
    assert homology(klein_bottle(), coefficients=3) == [(1, []), (1, []), (0, [])]
    assert homology(sphere(0)) == [(2, [])]
    for n in range(1, 5):
        assert homology(sphere(n)) == [(1, [])] + [(0, [])] * (n - 1) + [(1, [])]


def test_dunce_hat_contractible_not_collapsible():
    faces = dunce_hat()
    assert len(faces) == 17 and len({v for f in faces for v in f}) == 8
    for p in (0, 2, 3):
        assert homology(faces, coefficients=p) == [(1, []), (0, []), (0, [])]
    deg = collections.Counter(e for f in faces for e in itertools.combinations(f, 2))
    assert min(deg.values()) >= 2  # no free edge: no elementary collapse is possible
    assert sorted(e for e, d in deg.items() if d == 3) == [(0, 1), (0, 2), (1, 2)]


@pytest.mark.parametrize("faces", [torus(), klein_bottle(), klein_bottle(n=3, m=3), rp2()])
def test_closed_surfaces_are_pseudomanifolds(faces):
    deg = collections.Counter(e for f in faces for e in itertools.combinations(f, 2))
    assert set(deg.values()) == {2} and len(set(faces)) == len(faces)


# ------------------------------------------------------------------ cross-checks


@settings(deadline=None, max_examples=25)
@given(st.integers(0, 2**32 - 1))
def test_matches_gudhi_over_z2_and_z3(seed):
    faces = random_complex(seed)
    for p in (2, 3):
        assert betti_numbers(faces, coefficients=p) == gudhi_betti(faces, p)


@settings(deadline=None, max_examples=12)
@given(st.integers(0, 2**32 - 1))
def test_matches_sympy_over_z(seed):
    faces = random_subset_complex(seed, n=6) if seed % 2 else random_flag_complex(seed, n=7, max_dim=2)
    assert homology(faces) == sympy_homology(faces)


def test_medium_rips_complex_matches_gudhi():
    pts = np.random.default_rng(3).random((120, 3))
    tree = gudhi.RipsComplex(points=pts, max_edge_length=0.3).create_simplex_tree(max_dimension=3)
    faces = [tuple(s) for s, _ in tree.get_simplices()]
    assert len(faces) > 2000
    hz = homology(faces)
    for p in (2, 3):
        assert betti_numbers(faces, coefficients=p) == gudhi_betti(faces, p)
        assert betti_numbers(faces, coefficients=p) == [b for b, _ in hz]  # no torsion here


def moore_space(k: int, offset: int = 0) -> list[tuple[int, ...]]:
    """A disc glued along its boundary by z -> z^k: H_1 = Z/k (cone over a 3k-cycle wound k times)."""
    n = 3 * k
    ring = [0, 1, 2] * k
    faces = []
    for i in range(n):
        a, b, r, s = ring[i], ring[(i + 1) % n], 3 + i, 3 + (i + 1) % n
        faces += [(a, b, r), (b, r, s), (r, s, 3 + n)]
    return [tuple(v + offset for v in f) for f in faces]


@pytest.mark.parametrize("k", [2, 3, 4, 6])
def test_torsion_of_moore_spaces(k):
    assert homology(moore_space(k)) == [(1, []), (0, [k]), (0, [])]
    for p in (2, 3, 5):
        b = 1 if k % p == 0 else 0
        assert homology(moore_space(k), coefficients=p) == [(1, []), (b, []), (b, [])]


def test_torsion_of_disjoint_moore_spaces():
    faces = moore_space(4) + moore_space(6, offset=100) + moore_space(2, offset=200)
    # torsion coefficients are the invariant factors 2 | 2 | 12 (Z/2 ⊕ Z/4 ⊕ Z/6 ≅ Z/2 ⊕ Z/2 ⊕ Z/12)
    assert homology(faces) == [(3, []), (0, [2, 2, 12]), (0, [])]
    d2 = boundary_matrices(closure(faces), coefficients=0)[2]
    assert reduce_matrix(d2).invariants == [2, 2, 12]


def test_sparse_and_dense_stages_agree_on_boundary_matrices():
    # the whole engine against each stage alone: the modular dense stage on the whole matrix, and
    # the sparse elimination switching to the dense kernel at once or never
    rng = np.random.default_rng(5)
    tris = [t for t in itertools.combinations(range(14), 3) if rng.random() < 0.25]
    for d in boundary_matrices(closure(tris), coefficients=0)[1:]:
        red = reduce_matrix(d)
        full = [1] * (red.rank - len(red.invariants)) + red.invariants
        assert dense_smith_diagonal(d.toarray()) == full
        for density in (0.0, 2.0):
            rank, _, (core, _, _) = markowitz_eliminate(d.indptr, d.indices, d.data, d.shape[0],
                                                        np.zeros(d.shape[1], bool), 0, density=density)
            assert sorted([1] * rank + dense_invariants(core)) == full


# ------------------------------------------------------------------ invariants


@settings(deadline=None, max_examples=20)
@given(st.integers(0, 2**32 - 1), st.sampled_from([0, 2, 3, 5]))
def test_boundary_of_boundary_is_zero(seed, p):
    mats = boundary_matrices(closure(random_complex(seed)), coefficients=p)
    for k in range(2, len(mats)):
        prod = (mats[k - 1] @ mats[k]).toarray()
        assert not np.any(prod % p if p else prod)


@settings(deadline=None, max_examples=20)
@given(st.integers(0, 2**32 - 1))
def test_euler_characteristic_and_universal_coefficients(seed):
    # a random complex, with a Moore space (torsion Z/k in H_1) attached to it by an edge
    k = 2 + seed % 5
    faces = random_complex(seed) + moore_space(k, offset=50) + [(0, 50)]
    hz = homology(faces)
    assert any(t % k == 0 for t in hz[1][1])
    chi = euler_characteristic(faces)
    assert chi == sum((-1) ** k * b for k, (b, _) in enumerate(hz))
    assert chi == sum((-1) ** k * m for k, m in enumerate(simplex_counts(faces)))
    for p in (2, 3, 5):
        hp = betti_numbers(faces, coefficients=p)
        assert sum((-1) ** k * b for k, b in enumerate(hp)) == chi
        for k, (b, tors) in enumerate(hz):
            below = hz[k - 1][1] if k else []
            expected = b + sum(t % p == 0 for t in tors) + sum(t % p == 0 for t in below)
            assert hp[k] == expected


@settings(deadline=None, max_examples=15)
@given(st.integers(0, 2**32 - 1), st.sampled_from([0, 2, 3]))
def test_relabelling_invariance(seed, p):
    faces = random_complex(seed) + moore_space(2 + seed % 4, offset=40)
    rng = np.random.default_rng(seed)
    n = 1 + max(v for f in faces for v in f)
    perm = rng.permutation(n) * 3 + 7  # also spread labels out
    relabelled = [tuple(int(perm[v]) for v in f) for f in faces]
    assert homology(relabelled, coefficients=p) == homology(faces, coefficients=p)
    # input order and duplicates do not matter either
    shuffled = [faces[i] for i in rng.permutation(len(faces))] + faces[:3]
    assert homology(shuffled, coefficients=p) == homology(faces, coefficients=p)


def test_clearing_does_not_change_ranks():
    faces = random_flag_complex(11, n=12, max_dim=3)
    cx = closure(faces)
    for p in (0, 2):
        mats = boundary_matrices(cx, coefficients=p)
        full = [0] + [reduce_matrix(d, coefficients=p).rank for d in mats[1:]] + [0]
        expected = [len(cx[k]) - full[k] - full[k + 1] for k in range(len(cx))]
        assert betti_numbers(faces, coefficients=p) == expected


def test_input_forms():
    assert homology([[0, 1], [1, 2], [0, 2]]) == [(1, []), (1, [])]
    assert homology(np.array([[0, 1], [1, 2], [2, 0]])) == [(1, []), (1, [])]
    assert homology(iter([(2, 1, 0)])) == [(1, []), (0, []), (0, [])]  # unsorted vertices are fine
    assert homology([(0,), (5,)]) == [(2, [])]
    assert homology([np.array([[0], [1]]), np.array([[0, 1]])]) == [(1, []), (0, [])]


# ------------------------------------------------------------------ bad input


@pytest.mark.parametrize("coefficients", [1, 4, 6, -3, 2.0, "2", None, True])
def test_bad_coefficients(coefficients):
    with pytest.raises(ValueError, match="prime"):
        homology(rp2(), coefficients=coefficients)


def test_bad_simplices():
    with pytest.raises(ValueError, match="repeated vertex"):
        homology([(0, 1, 1)])
    with pytest.raises(ValueError, match="empty"):
        homology([])
    with pytest.raises(ValueError, match="empty"):
        homology([()])
    with pytest.raises(ValueError, match="empty"):
        homology(np.empty((0, 3), dtype=np.int64))
    with pytest.raises(ValueError, match="non-negative"):
        homology([(-1, 2)])
    with pytest.raises(ValueError):
        homology("abc")
    with pytest.raises(ValueError, match="empty"):
        boundary_matrices([], coefficients=0)
    with pytest.raises(ValueError, match=">= 3"):
        klein_bottle(n=2, m=4)
    with pytest.raises(ValueError, match="^n must be >= 0, got -1$"):
        sphere(-1)

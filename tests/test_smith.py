"""Tests for thesis_lib.homology.smith: Smith normal form over Z and ranks over Z/p."""

import itertools

import numpy as np
import pytest
import scipy.sparse as sp
from helpers import THESIS_M2, pari_invariants, sympy_invariants
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.homology._elimination import markowitz_eliminate
from thesis_lib.homology._modular import dense_invariants
from thesis_lib.homology.simplicial import boundary_matrix, closure
from thesis_lib.homology.smith import dense_smith_diagonal, rank_mod_p, reduce_matrix, smith_normal_form


def staged_invariants(a, density: float) -> list[int]:
    """Sparse elimination switching to the dense kernel at ``density`` (0: at once; 2: never), then
    the modular stage on the core: the invariant factors, sorted."""
    m = sp.csc_matrix(np.asarray(a, dtype=np.int64))
    m.sort_indices()
    rank, _, (core, _, _) = markowitz_eliminate(m.indptr, m.indices, m.data, m.shape[0],
                                                np.zeros(m.shape[1], bool), 0, density=density)
    return sorted([1] * rank + dense_invariants(core))


def test_example_2_21_m2():
    # Thesis: diagonal (1, ..., 1, 2, 0, ...) with 10 nonzero terms, k_2 = 10.
    assert smith_normal_form(THESIS_M2).tolist() == [1] * 9 + [2]
    assert smith_normal_form(sp.csc_matrix(THESIS_M2)).tolist() == [1] * 9 + [2]
    assert rank_mod_p(THESIS_M2, coefficients=2) == 9
    assert rank_mod_p(THESIS_M2, coefficients=3) == 10


def test_known_small_cases():
    assert smith_normal_form([[2, 4], [6, -8]]).tolist() == [2, 20]
    assert smith_normal_form([[2, 0], [0, 3]]).tolist() == [1, 6]
    assert smith_normal_form([[4, 0], [0, 6]]).tolist() == [2, 12]
    assert smith_normal_form(np.zeros((3, 4), dtype=int)).tolist() == []
    assert smith_normal_form(np.zeros((0, 4), dtype=int)).tolist() == []
    assert smith_normal_form(np.eye(5, dtype=int)).tolist() == [1] * 5
    assert smith_normal_form([[1.0, 2.0], [3.0, 4.0]]).tolist() == [1, 2]  # integral floats are fine
    assert smith_normal_form(np.array([[True, True], [False, True]])).tolist() == [1, 1]


@settings(deadline=None, max_examples=60)
@given(
    st.integers(1, 7),
    st.integers(1, 7),
    st.integers(0, 2**32 - 1),
    st.sampled_from([1, 3, 9, 40]),
    st.floats(0.2, 1.0),
)
def test_matches_sympy_on_random_matrices(m, n, seed, bound, density):
    rng = np.random.default_rng(seed)
    a = rng.integers(-bound, bound + 1, (m, n)) * (rng.random((m, n)) < density)
    ref = sympy_invariants(a)
    assert smith_normal_form(a).tolist() == ref
    assert smith_normal_form(sp.csr_matrix(a)).tolist() == ref
    # each stage alone agrees: the dense modular stage, and sparse elimination switching to the
    # dense kernel at once, halfway or never
    assert dense_smith_diagonal(a) == ref
    for density in (0.0, 0.3, 2.0):
        assert staged_invariants(a, density) == ref
    # rank over Z/p = number of invariant factors prime to p
    for p in (2, 3, 5):
        assert rank_mod_p(a, coefficients=p) == sum(1 for x in ref if x % p)


@settings(deadline=None, max_examples=15)
@given(st.integers(0, 2**32 - 1))
def test_low_rank_products_match_sympy(seed):
    # products of random integer matrices have nontrivial invariant factors
    rng = np.random.default_rng(seed)
    a = rng.integers(-3, 4, (6, 3)) @ np.diag(rng.integers(1, 5, 3)) @ rng.integers(-3, 4, (3, 7))
    assert smith_normal_form(a).tolist() == sympy_invariants(a)


def test_big_integers_are_exact():
    big = 2**70
    a = np.array([[big, 0, 3], [0, 2 * big, 5], [7, 11, big + 1]], dtype=object)
    ours = smith_normal_form(a)
    assert ours.dtype == object
    assert [int(x) for x in ours] == sympy_invariants(a)
    d = np.array([[2**40, 0], [0, 3 * 2**40]], dtype=object)
    assert [int(x) for x in smith_normal_form(d)] == [2**40, 3 * 2**40]
    assert dense_smith_diagonal(d) == [2**40, 3 * 2**40]


def test_large_sparse_unit_matrix_and_skip():
    # a long path graph's incidence matrix: rank n - 1, all invariant factors 1
    n = 20000
    rows = np.r_[np.arange(n - 1), np.arange(1, n)]
    cols = np.r_[np.arange(n - 1), np.arange(n - 1)]
    vals = np.r_[-np.ones(n - 1, int), np.ones(n - 1, int)]
    a = sp.csc_matrix((vals, (rows, cols)), shape=(n, n - 1))
    red = reduce_matrix(a)
    assert red.rank == n - 1 and red.invariants == [] and red.unit_pivot_rows.sum() == n - 1
    skip = np.zeros(n - 1, bool)
    skip[::2] = True
    assert reduce_matrix(a, skip_columns=skip).rank == (n - 1) // 2
    assert reduce_matrix(a, coefficients=7, skip_columns=skip).rank == (n - 1) // 2


def test_large_prime_reads_the_rank_off_the_integer_smith_form():
    p = 2147483659  # the first prime above 2**31: too big for the word-size kernels
    assert rank_mod_p(THESIS_M2, coefficients=p) == 10
    assert rank_mod_p([[p, 0], [0, 1]], coefficients=p) == 1
    assert rank_mod_p([[p, 0], [0, 1]], coefficients=2**31 - 1) == 2


@pytest.mark.parametrize(
    "bad, message",
    [
        (np.zeros((2, 2, 2)), "2-D"),
        (np.zeros(3), "2-D"),
        ([[1.5, 0], [0, 1]], "integers"),
        ([[np.nan, 0], [0, 1]], "NaN"),
        ([[np.inf, 0], [0, 1]], "NaN or inf"),
        ([["a", "b"]], "integers"),
        (np.array([[1, None]], dtype=object), "integers"),
    ],
)
def test_bad_matrices(bad, message):
    with pytest.raises(ValueError, match=message):
        smith_normal_form(bad)


def test_uint64_entries_beyond_int64_are_exact():
    # uint64 entries >= 2**63 do not fit in int64: they must not wrap around to negative values
    big = 2**63 + 1  # divisible by 3
    a = np.array([[big, 0], [0, 3]], dtype=np.uint64)
    assert [int(x) for x in smith_normal_form(a)] == [3, big] == sympy_invariants(a.astype(object))
    b = np.array([[2**64 - 1, 2**63], [5, 7]], dtype=np.uint64)
    assert [int(x) for x in smith_normal_form(b)] == sympy_invariants(b.astype(object))
    c = np.array([[-(2**63), 0], [0, 2]], dtype=np.int64)  # |int64 min| does not fit in int64
    assert [int(x) for x in smith_normal_form(c)] == [2, 2**63]
    assert rank_mod_p(a, coefficients=3) == 0 and rank_mod_p(a, coefficients=5) == 2
    with pytest.raises(ValueError, match="int64"):
        smith_normal_form(sp.csc_matrix(np.array([[2**63]], dtype=np.uint64)))


@settings(deadline=None, max_examples=25)
@given(st.integers(1, 6), st.integers(1, 6), st.integers(0, 2**32 - 1), st.sampled_from([40, 70, 200]))
def test_huge_entries_match_sympy(m, n, seed, bits):
    rng = np.random.default_rng(seed)
    a = np.array([[int(x) * (1 << int(s)) + int(y) for x, s, y in zip(r1, r2, r3)]
                  for r1, r2, r3 in zip(rng.integers(-3, 4, (m, n)), rng.integers(0, bits, (m, n)),
                                        rng.integers(-9, 10, (m, n)))], dtype=object)
    a[rng.random((m, n)) < 0.3] = 0
    assert [int(x) for x in smith_normal_form(a)] == sympy_invariants(a)


@pytest.mark.parametrize("primes", [1, 2, 3])
@pytest.mark.parametrize("shape", [(1, 1), (2, 3), (4, 4)])
def test_entries_divisible_by_the_first_crt_primes(primes, shape):
    """Matrices whose entries are all divisible by the first CRT primes (zero modulo each, an empty rank
    profile there; e.g. [[2²⁶ − 5]] modulo the first) get sympy's invariants."""
    from thesis_lib.homology._modular import crt_primes

    q = int(np.prod([int(x) for x in crt_primes(primes)], dtype=object))
    rng = np.random.default_rng(primes)
    a = np.array(rng.integers(-5, 6, shape), dtype=object) * q
    a[0, 0] = q * 7  # never the zero matrix
    for matrix in (a, -a, a * (1 << 70)):
        assert [int(x) for x in smith_normal_form(matrix)] == sympy_invariants(matrix)
    if q < 2**62:
        assert [int(x) for x in smith_normal_form(a.astype(np.int64))] == sympy_invariants(a)


def known_smith_form(seed: int, m: int, n: int, diagonal: list[int]) -> np.ndarray:
    """U · diag · V with random unimodular U, V (products of elementary matrices): the Smith form is known."""
    rng = np.random.default_rng(seed)
    a = np.zeros((m, n), dtype=object)
    for i, d in enumerate(diagonal):
        a[i, i] = d
    for _ in range(3 * (m + n)):  # row and column additions with small multipliers
        i, j = rng.choice(m, 2, replace=False)
        a[i] += int(rng.integers(-3, 4)) * a[j]
        k, l = rng.choice(n, 2, replace=False)
        a[:, k] += int(rng.integers(-3, 4)) * a[:, l]
    return a[rng.permutation(m)][:, rng.permutation(n)]


@pytest.mark.parametrize("seed", range(3))
def test_large_matrices_with_large_elementary_divisors_match_pari(seed):
    # elementary divisors up to ~10^60, with shared prime factors, on 40 x 55 matrices of rank 30
    rng = np.random.default_rng(seed)
    q = [int(x) for x in rng.integers(2, 10**6, 4)]
    diagonal = [1] * 22 + [2, 2, 6, q[0], q[0] * q[1], q[0] * q[1] * 2**40, 10**30 * q[2], 10**60 * q[2] * q[3]]
    a = known_smith_form(seed, 40, 55, diagonal)
    expected = [int(x) for x in sympy_invariants(np.diag(np.array(diagonal, dtype=object)))]
    ours = [int(x) for x in smith_normal_form(a)]
    assert ours == expected == pari_invariants(a)
    assert dense_smith_diagonal(a) == expected


@pytest.mark.parametrize("density", [0.02, 0.05])
def test_dense_core_of_a_random_2_complex_matches_pari(density):
    # the dense part the sparse stage hands over on a Linial–Meshulam complex (n = 60)
    rng = np.random.default_rng(3)
    n = 60
    tris = np.array([t for t in itertools.combinations(range(n), 3) if rng.random() < 4 / n])
    cx = closure(tris)
    d2 = boundary_matrix(cx[1], cx[2], coefficients=0)
    rank, _, (core, _, _) = markowitz_eliminate(d2.indptr, d2.indices, d2.data, d2.shape[0],
                                                np.zeros(d2.shape[1], bool), 0, density=density, finish=False)
    assert core.shape[0] > 100
    ours = dense_invariants(core)
    assert ours == pari_invariants(core)
    assert reduce_matrix(d2).rank == rank + len(ours)


def test_bad_coefficients_and_masks():
    with pytest.raises(ValueError, match="prime"):
        rank_mod_p(THESIS_M2, coefficients=4)
    with pytest.raises(ValueError, match="prime"):
        rank_mod_p(THESIS_M2, coefficients=0)
    with pytest.raises(ValueError, match="prime"):
        reduce_matrix(THESIS_M2, coefficients=1)
    with pytest.raises(ValueError, match="skip_columns"):
        reduce_matrix(THESIS_M2, skip_columns=np.zeros(3, bool))
    with pytest.raises(ValueError, match="2-D"):
        dense_smith_diagonal(np.zeros(3))
    with pytest.raises(ValueError, match="integers"):
        dense_smith_diagonal(np.array([[0.5]]))
    with pytest.raises(ValueError, match="integers"):
        dense_smith_diagonal(np.array([[1, "x"]], dtype=object))
    assert dense_smith_diagonal(np.array([[6, 0], [0, 4]], dtype=object)) == [2, 12]


@settings(deadline=None, max_examples=6)
@given(st.integers(0, 2**32 - 1))
def test_sparse_matrices_with_postponed_rows_match_sympy(seed):
    # sparse entries in {-3..3}: many non-unit entries, so rows get postponed and a core remains
    rng = np.random.default_rng(seed)
    a = rng.integers(-3, 4, (18, 22)) * (rng.random((18, 22)) < 0.25)
    red = reduce_matrix(sp.csc_matrix(a))
    assert [1] * (red.rank - len(red.invariants)) + red.invariants == sympy_invariants(a)

"""Filtration container (Definition 2.22): construction, validation, order, GUDHI round trip."""

import gudhi
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import Filtration, rips


def small():
    return Filtration.from_pairs(
        [((0,), 0.0), ((1,), 0.0), ((2,), 0.5), ((0, 1), 1.0), ((1, 2), 1.0), ((0, 2), 2.0), ((0, 1, 2), 2.0)]
    )


def test_from_pairs_values_and_order():
    f = small()
    assert len(f) == 7 and f.dimension == 2 and f.counts() == [3, 3, 1]
    assert list(f) == [((0,), 0.0), ((1,), 0.0), ((2,), 0.5), ((0, 1), 1.0), ((1, 2), 1.0), ((0, 2), 2.0),
                       ((0, 1, 2), 2.0)]
    dims, index = f.order
    assert dims.tolist() == [0, 0, 0, 1, 1, 1, 2]
    # positions is the inverse permutation of order
    for d in range(3):
        for j, p in enumerate(f.positions[d]):
            assert dims[p] == d and index[p] == j
    np.testing.assert_array_equal(f.facet_indices(2), [[1, 2, 0]])  # edges stored (0,1), (1,2), (0,2)


@pytest.mark.parametrize(
    "pairs, msg",
    [
        ([((0,), 1.0), ((1,), 0.0)], "decrease"),
        ([((0,), 0.0), ((0, 1), 1.0)], "does not come before"),
        ([((0,), 0.0), ((0,), 0.0)], "twice"),
        ([((0,), float("nan"))], "NaN"),
        ([], "empty"),
    ],
)
def test_from_pairs_rejects(pairs, msg):
    with pytest.raises(ValueError, match=msg):
        Filtration.from_pairs(pairs)


def test_validation_of_arrays():
    with pytest.raises(ValueError, match="faces must come before"):
        Filtration([np.array([[0], [1]]), np.array([[0, 1]])], [np.array([0.0, 2.0]), np.array([1.0])])
    with pytest.raises(ValueError, match="missing"):
        Filtration([np.array([[0], [1]]), np.array([[0, 2]])], [np.zeros(2), np.ones(1)])
    with pytest.raises(ValueError, match="one array per dimension"):
        Filtration([np.array([[0]])], [])


def test_skeleton_and_threshold():
    f = small()
    assert f.skeleton(1).counts() == [3, 3]
    assert f.skeleton(5).counts() == [3, 3, 1]
    assert f.threshold(1.0).counts() == [3, 2]
    assert f.threshold(0.2).counts() == [2]
    with pytest.raises(ValueError):
        f.skeleton(-1)
    with pytest.raises(ValueError):
        f.threshold(-1.0)
    with pytest.raises(ValueError):
        f.threshold(float("nan"))


def test_simplex_tree_round_trip():
    pts = np.random.default_rng(0).random((25, 2))
    f = rips(pts, max_radius=0.3, max_dim=2)
    st_ = f.to_simplex_tree()
    assert st_.num_simplices() == len(f)
    g = Filtration.from_simplex_tree(st_)
    assert {s: v for s, v in g} == {s: v for s, v in f}
    ref = gudhi.RipsComplex(points=pts, max_edge_length=0.6).create_simplex_tree(max_dimension=2)
    assert {tuple(s): v for s, v in ref.get_filtration()} == pytest.approx({s: 2 * v for s, v in g})


@settings(deadline=None, max_examples=15)
@given(st.integers(0, 10_000), st.integers(3, 25), st.floats(0.05, 0.8))
def test_order_lists_faces_first(seed, n, eps):
    f = rips(np.random.default_rng(seed).random((n, 3)), max_radius=eps, max_dim=3)
    seen = set()
    last = -np.inf
    for s, v in f:
        assert v >= last
        last = v
        if len(s) > 1:
            assert all(s[:i] + s[i + 1 :] in seen for i in range(len(s)))
        seen.add(s)
    # the fast stable-argsort order equals the three-key lexsort of the definition
    dims = np.concatenate([np.full(c, d) for d, c in enumerate(f.counts())])
    index = np.concatenate([np.arange(c) for c in f.counts()])
    perm = np.lexsort((index, dims, np.concatenate(f.values)))
    np.testing.assert_array_equal(f.order[0], dims[perm])
    np.testing.assert_array_equal(f.order[1], index[perm])


def test_constructions_cut_at_max_dim_are_truncated():
    # Theorem 2.39: H_p is known only once the (p+1)-simplices are in; a complex cut at max_dim
    # reports its top dimension as incomplete, a complex that stops below the cut does not
    from thesis_lib import datasets
    from thesis_lib.complexes import cech, lazy_witness, rips, witness
    from thesis_lib.persistence import persistence

    pts = datasets.two_circles(12, seed=3)
    landmarks = np.arange(0, 24, 3)
    for f in (rips(pts, max_radius=2.0, max_dim=2), cech(pts, max_radius=1.0, max_dim=2),
              witness(pts, landmarks, max_radius=2.0, max_dim=2),
              lazy_witness(pts, landmarks, max_radius=2.0, max_dim=2)):
        assert f.truncated and f.dimension == 2
        assert persistence(f, coefficients=2).complete_dimensions == (0, 1)
    sparse = rips(pts, max_radius=0.01, max_dim=2)  # no edges at this scale: nothing was cut
    assert sparse.dimension == 0 and sparse.truncated is False
    full = rips(pts[:4], max_radius=10.0, max_dim=3)  # the whole 3-simplex: reaches the cut, so still marked
    assert full.truncated
    plain = Filtration.from_simplices([[0, 1, 2]])
    assert not plain.truncated and plain.skeleton(1).truncated and not plain.skeleton(2).truncated
    assert rips(pts, max_radius=2.0, max_dim=2).threshold(0.5).truncated

"""Barcode: intervals, Betti numbers, persistent Betti numbers, comparison and plots (§2.3)."""

from __future__ import annotations

import math

import matplotlib
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib.complexes import rips
from thesis_lib.datasets import example_filtration
from thesis_lib.persistence import Barcode, compute_intervals, persistence, plot_barcode, plot_diagram

matplotlib.use("Agg")

INF = math.inf


def test_intervals_sorted_zero_length_dropped():
    b = Barcode({0: [[2, 3], [0, INF], [1, 1], [0, 1]], 1: []}, dimensions=[0, 1, 2])
    assert b.intervals(0).tolist() == [[0, 1], [0, INF], [2, 3]]
    assert b.intervals(1).shape == (0, 2) and b.intervals(5).shape == (0, 2)
    assert b.dimensions == (0, 1, 2)
    assert len(b) == 3
    with pytest.raises(ValueError):
        b.intervals(0)[0, 0] = 5.0  # read-only


def test_from_pairs_equality_and_difference():
    a = Barcode.from_pairs([(0, (0.0, INF)), (1, (0.5, 2.0)), (0, (0.0, 1.0))])
    b = Barcode({0: [[0, 1], [0, INF]], 1: [[0.5, 2.0]], 2: []})
    assert a == b
    assert a.as_pairs() == [(0, (0.0, 1.0)), (0, (0.0, INF)), (1, (0.5, 2.0))]
    c = Barcode({0: [[0, 1], [0, INF]], 1: [[0.5, 2.0 + 1e-12]]})
    assert c != a and c.allclose(a, atol=1e-9)
    assert "H1" in a.difference(Barcode({0: [[0, 1], [0, INF]]}))
    assert "essential" in a.difference(Barcode({0: [[0, 1], [0, 5]], 1: [[0.5, 2.0]]}))


def test_betti_and_persistent_betti_example_2_36():
    # Example 2.36: F[t] ⊕ Σ¹F[t] ⊕ Σ²F[t]/(t²) has P-intervals (0, ∞), (1, ∞), (2, 4)
    b = Barcode({0: [[0, INF], [1, INF], [2, 4]]})
    assert [b.betti(v, dim=0) for v in (0, 0.5, 1, 2, 3.9, 4, 100)] == [1, 1, 2, 3, 3, 2, 2]
    assert b.persistent_betti(2, 1.99, dim=0) == 3 and b.persistent_betti(2, 2, dim=0) == 2
    assert b.persistent_betti(0, 1000, dim=0) == 1
    assert b.betti(1, dim=1) == 0


def test_example_barcode_betti_numbers():
    b = persistence(example_filtration())
    # K^l of Figure 2.11: β0 = 2, 2, 2, 1, 1 and β1 = 0, 0, 1, 2, 1 for l = 0..4
    assert [b.betti(l, dim=0) for l in range(5)] == [2, 2, 2, 1, 1]
    assert [b.betti(l, dim=1) for l in range(5)] == [0, 0, 1, 2, 1]
    assert b.longest(1, n=1).tolist() == [0]


intervals = st.lists(
    st.tuples(st.integers(0, 6), st.integers(0, 7) | st.just(INF)).map(lambda t: (t[0], max(t[0], t[1]))), max_size=12
)


@settings(deadline=None, max_examples=40)
@given(iv=intervals, l=st.integers(0, 8), k=st.integers(0, 4))
def test_persistent_betti_invariants(iv, l, k):
    b = Barcode({0: iv} if iv else {}, dimensions=[0])
    # monotone in k, bounded by β at l and at l + k, and k = 0 is the Betti number
    assert b.persistent_betti(l, k, dim=0) <= b.persistent_betti(l, 0, dim=0) == b.betti(l, dim=0)
    assert b.persistent_betti(l, k + 1, dim=0) <= b.persistent_betti(l, k, dim=0) <= b.betti(l + k, dim=0)
    assert b.persistent_betti(l, k, dim=0) == sum(1 for s, e in iv if s <= l and e > l + k)


def test_bad_barcodes():
    with pytest.raises(ValueError, match="dies before"):
        Barcode({0: [[2, 1]]})
    with pytest.raises(ValueError, match="NaN"):
        Barcode({0: [[float("nan"), 1]]})
    with pytest.raises(ValueError, match="outside"):
        Barcode({1: [[0, 1]]}, dimensions=[0])
    b = Barcode({0: [[0, 1]]})
    with pytest.raises(ValueError, match="non-negative"):
        b.persistent_betti(0, -1, dim=0)
    with pytest.raises(ValueError, match="NaN"):
        b.betti(float("nan"), dim=0)
    with pytest.raises(ValueError, match=">= 0"):
        b.intervals(-1)
    with pytest.raises(ValueError, match="filtration"):
        b.representative(0, 0)
    with pytest.raises(ValueError, match="no interval"):
        persistence(example_filtration()).representative(1, 5)


def test_simplex_pairs_of_the_example():
    f = example_filtration()
    for b in (compute_intervals(f), persistence(f)):
        sp = b.simplex_pairs(1)
        # (bc, ∞) and (ce, ced): with ed before ce (the order of Example 2.41's first matrix) ed kills
        # e and ce closes the cycle; the thesis's second matrix lists ce before ed and pairs the other
        # way round — the same intervals (2, 3) and (3, 4) either way
        assert [tuple(int(v) for v in f.simplices[1][i]) for i in sp[:, 0]] == [(1, 2), (2, 4)]
        assert sp[:, 1].tolist() == [-1, 0]


def test_plots():
    b = compute_intervals(example_filtration())
    fig = plot_barcode(b, dims=[0, 1], max_value=5, title="Figure 2.12")
    assert len(fig.axes) == 2
    assert len(fig.axes[0].collections) == 4 and len(fig.axes[1].collections) == 2
    fig2 = plot_diagram(b, dims=[0, 1], max_value=5)
    assert len(fig2.axes[0].collections) == 2
    with pytest.raises(ValueError, match="no homology"):
        plot_barcode(b, dims=[])
    with pytest.raises(ValueError, match="min_length"):
        plot_barcode(b, min_length=-1)
    import matplotlib.pyplot as plt

    plt.close("all")


def test_plot_defaults_complete_dims_short_bars_and_refuse_millions():
    import matplotlib.pyplot as plt

    rng = np.random.default_rng(0)
    births = rng.random(20000)
    noise = np.column_stack([births, births + 1e-4])  # 20,000 bars of 0.01 % of the range
    b = Barcode({0: np.vstack([noise, [[0, 1.0]]]), 1: [[0.2, 0.9]], 2: [[0.5, np.inf]] * 10**5}, complete=[0, 1])
    fig = plot_barcode(b)  # H2 (incomplete) left out, the short bars too
    assert len(fig.axes) == 2 and len(fig.axes[0].collections) == 1 and len(fig.axes[1].collections) == 1
    with pytest.raises(ValueError, match="20002 bars to draw"):
        plot_barcode(b, min_fraction=0)
    with pytest.raises(ValueError, match="100000 bars"):
        plot_barcode(b, dims=[2])
    plt.close("all")


def test_bad_dimensions_and_counts_get_clear_errors():
    b = Barcode({0: [[0, 1], [0, 2]], 1: [[0.5, 1]]})
    for bad in (1.5, "1", True, None):
        with pytest.raises((ValueError, TypeError), match="homology dimension"):
            b.intervals(bad)
    with pytest.raises(ValueError, match="n must be >= 0"):
        b.longest(0, n=-1)
    with pytest.raises(TypeError, match="n must be an integer"):
        b.longest(0, n=1.5)
    assert b.longest(0, n=0).tolist() == [] and b.longest(0, n=5).tolist() == [1, 0]
    with pytest.raises(ValueError, match="interval index"):
        persistence(example_filtration()).representative(1, 0.5)


def test_complete_dimensions_rule_repr_betti_diagrams_and_equality():
    iv = {0: [[0, 1], [0, np.inf]], 1: [[0.5, 2]], 2: [[1, np.inf]] * 3}
    b = Barcode(iv, complete=[0, 1])
    assert b.dimensions == (0, 1, 2) and b.complete_dimensions == (0, 1)
    assert repr(b) == ("Barcode(H0: 2 (1 essential), H1: 1 (0 essential); "
                       "H2 incomplete (top dimension of a truncated complex))")
    assert b.betti(0.7) == [2, 1] and b.betti(1.5, dim=2) == 3
    dg = b.to_diagrams()
    assert len(dg) == 2 and dg[0].tolist() == [[0, 1], [0, np.inf]] and dg[1].tolist() == [[0.5, 2]]
    assert Barcode.from_diagrams(dg) == b  # the incomplete dimension is left out of comparisons
    assert Barcode.from_diagrams(dg) != Barcode(iv)  # ... unless one side says it is complete
    assert len(b.to_diagrams(dims=[2])) == 3
    with pytest.raises(ValueError, match="not computed"):
        Barcode(iv, complete=[3])
    with pytest.raises(ValueError, match=r"\(m, 2\)"):
        Barcode.from_diagrams([np.zeros((2, 3))])
    with pytest.raises(TypeError):
        Barcode.from_diagrams(5)


def test_diagrams_round_trip_with_ripser():
    from ripser import ripser

    pts = np.random.default_rng(3).random((30, 2))
    f = rips(pts, max_radius=np.inf, max_dim=2)
    f.truncated = True  # the triangles' cofaces were not built: H2 is not complete
    ours = persistence(f)
    assert ours.complete_dimensions == (0, 1)
    dg = ripser(pts, maxdim=1)["dgms"]
    theirs = Barcode.from_diagrams([np.asarray(d, dtype=np.float64) / 2 for d in dg])  # ripser: diameters
    assert ours.allclose(theirs, atol=1e-6)  # ripser computes in float32
    again = Barcode.from_diagrams(ours.to_diagrams())
    assert again == ours and len(ours.to_diagrams()) == len(ours.complete_dimensions)


def test_hostile_tolerances_dimensions_and_fields_are_refused_by_name():
    """atol=NaN and atol=-1 are refused (they would call two different barcodes close, or a barcode
    different from itself), as are fractional or string dimensions and a non-prime field; a
    dimension of 10¹² is refused before to_diagrams would build 10¹² arrays."""
    a, b = Barcode({0: [[0, 1]]}), Barcode({0: [[0, 5]]})
    assert not a.allclose(b, atol=1.0) and a.allclose(b, atol=np.inf) and a.allclose(a, atol=0)
    with pytest.raises(ValueError, match="atol is NaN"):
        a.allclose(b, atol=float("nan"))
    with pytest.raises(ValueError, match="atol must be >= 0"):
        a.allclose(a, atol=-1)
    with pytest.raises(TypeError, match="atol must be a number"):
        a.difference(a, atol="0.1")
    with pytest.raises(TypeError, match="other must be a Barcode"):
        a.difference([[0, 1]])
    for bad in (1.5, "1", True):
        with pytest.raises(TypeError, match="homology dimension"):
            Barcode({bad: [[0, 1]]})
        with pytest.raises(TypeError, match="homology dimension"):
            Barcode({0: [[0, 1]]}, dimensions=[0, bad])
        with pytest.raises(TypeError, match="homology dimension"):
            Barcode.from_pairs([(bad, (0.0, 1.0))])
    with pytest.raises(ValueError, match="homology dimension must be >= 0"):
        Barcode({-1: [[0, 1]]})
    with pytest.raises(TypeError, match="dimensions must be an iterable"):
        Barcode({0: [[0, 1]]}, dimensions=1)
    with pytest.raises(TypeError, match="intervals must be a mapping"):
        Barcode([[0, 1]])
    for p in (4, 0, 1, -3, 2.0, "2", True):
        with pytest.raises(ValueError, match="coefficients"):
            Barcode.from_diagrams([[[0, 1]]], coefficients=p)
        with pytest.raises(ValueError, match="coefficients"):
            Barcode({0: [[0, 1]]}, coefficients=p)
    assert Barcode.from_diagrams([[[0, 1]]], coefficients=3).coefficients == 3
    assert Barcode({0: []}, coefficients=np.int64(5)).coefficients == 5
    with pytest.raises(TypeError, match="dims must be an iterable"):
        a.to_diagrams(dims="01")
    with pytest.raises(TypeError, match="dims must be an iterable"):
        a.to_diagrams(dims=3)
    with pytest.raises(TypeError, match="homology dimension"):
        a.to_diagrams(dims=[0.5])
    with pytest.raises(ValueError, match=r"1,000,000,000,001 diagrams.*limit of 10,000"):
        a.to_diagrams(dims=[10**12])
    assert [d.tolist() for d in a.to_diagrams(dims=[2])] == [[[0, 1]], [], []]


@pytest.mark.parametrize("seed", range(12))
def test_betti_at_infinity_counts_the_essential_classes_as_gudhi(seed):
    """At ∞ the complex is the whole filtration: β = the essential bars, GUDHI's betti_numbers()."""
    import gudhi

    rng = np.random.default_rng(seed)
    points = rng.random((int(rng.integers(8, 30)), 2))
    eps = [0.15, 0.3, np.inf][seed % 3]
    barcode = persistence(rips(points, max_radius=eps, max_dim=2))
    tree = gudhi.RipsComplex(points=points, max_edge_length=2 * eps).create_simplex_tree(max_dimension=2)
    tree.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
    expected = (tree.betti_numbers() + [0, 0])[:2]
    assert [barcode.betti(np.inf, dim=d) for d in (0, 1)] == expected
    assert [barcode.persistent_betti(np.inf, 0.0, dim=d) for d in (0, 1)] == expected
    born_at_0 = [barcode.intervals(d)[barcode.intervals(d)[:, 0] <= 0] for d in (0, 1)]
    essential_at_0 = [int(np.isinf(b[:, 1]).sum()) for b in born_at_0]
    assert [barcode.persistent_betti(0.0, np.inf, dim=d) for d in (0, 1)] == essential_at_0


# ---------------------------------------------------------------------------- the ecosystem's conventions
def sorted_rows(a) -> np.ndarray:
    a = np.asarray(a, dtype=np.float64).reshape(-1, 2)
    return a[np.lexsort(a.T[::-1])]


@pytest.mark.parametrize("seed, n, dim", [(0, 30, 2), (1, 40, 3), (2, 25, 4)])
def test_diameter_diagrams_are_ripsers_dgms(seed, n, dim):
    from ripser import ripser

    from thesis_lib.persistence import rips_persistence

    pts = np.random.default_rng(seed).random((n, dim))
    barcode = rips_persistence(pts, max_dim=3)
    theirs = ripser(pts, maxdim=2)["dgms"]
    ours = barcode.to_diagrams(scale="diameter")
    assert len(ours) == len(theirs) == 3
    for a, b in zip(ours, theirs):
        np.testing.assert_allclose(sorted_rows(a), sorted_rows(b), rtol=0, atol=1e-6)  # ripser: float32
    # "epsilon" (the default) and "radius" are the thesis's ε: exactly half
    for a, b, c in zip(ours, barcode.to_diagrams(), barcode.to_diagrams(scale="radius")):
        np.testing.assert_array_equal(a, 2 * b)
        np.testing.assert_array_equal(b, c)


def test_min_persistence_drops_the_bars_that_tied_distances_give_as_ripser_does():
    """Iris (sklearn's copy) has many tied distances, computed with different roundings: two H1
    bars of length ~2e-16 that ripser.py (on float32 distances) does not report."""
    from ripser import ripser
    from sklearn.datasets import load_iris

    from thesis_lib.persistence import rips_persistence

    X = load_iris().data
    theirs = [len(d) for d in ripser(X, maxdim=1)["dgms"]]
    everything = rips_persistence(X, max_dim=2)
    assert [len(everything.intervals(d)) for d in (0, 1)] != theirs
    tolerant = rips_persistence(X, max_dim=2, min_persistence=1e-12)
    assert [len(tolerant.intervals(d)) for d in (0, 1)] == theirs
    assert [len(d) for d in everything.to_diagrams(min_persistence=1e-12)] == theirs
    # the dropped bars are the ones no longer than 1e-12, nothing else
    h1 = everything.intervals(1)
    np.testing.assert_array_equal(tolerant.intervals(1), h1[h1[:, 1] - h1[:, 0] > 1e-12])


def test_min_persistence_and_scale_at_the_barcode():
    rows = np.array([[0.0, 1e-13], [0.0, 0.3], [0.1, 0.4000001], [0.2, INF], [0.5, 0.5]])
    for mp in (0.0, 1e-12, 0.3):
        kept = rows[(rows[:, 1] > rows[:, 0]) & (rows[:, 1] - rows[:, 0] > mp)]
        np.testing.assert_array_equal(Barcode({0: rows}, min_persistence=mp).intervals(0), sorted_rows(kept))
        np.testing.assert_array_equal(Barcode({0: rows}).to_diagrams(min_persistence=mp)[0], sorted_rows(kept))
    # after scale: 2 × 0.3 = 0.6 is not above 0.6, 2 × 0.3000001 is
    doubled = Barcode({0: rows}).to_diagrams(scale="diameter", min_persistence=0.6)[0]
    np.testing.assert_array_equal(doubled, [[0.2, 0.8000002], [0.4, INF]])
    for bad in (-1e-9, float("nan"), INF, "0"):
        with pytest.raises(ValueError, match="min_persistence"):
            Barcode({0: rows}, min_persistence=bad)
        with pytest.raises(ValueError, match="min_persistence"):
            Barcode({0: rows}).to_diagrams(min_persistence=bad)
    for bad in ("diam", "Diameter", 2, None):
        with pytest.raises(ValueError, match="scale"):
            Barcode({0: rows}).to_diagrams(scale=bad)
    with pytest.raises(ValueError, match="diameter does not fit"):
        Barcode({0: [[0.0, 1e308]]}).to_diagrams(scale="diameter")

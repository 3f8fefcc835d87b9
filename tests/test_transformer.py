"""RipsDiagrams: the scikit-learn-style transformer of point clouds into persistence diagrams."""

from __future__ import annotations

import gudhi
import numpy as np
import pytest
from sklearn.base import clone
from sklearn.model_selection import ParameterGrid
from sklearn.pipeline import Pipeline
from sklearn.preprocessing import FunctionTransformer

from thesis_lib.datasets import two_circles
from thesis_lib.persistence import RipsDiagrams


def clouds(seed: int, count: int = 3) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    return [rng.random((int(rng.integers(8, 25)), int(rng.integers(2, 4)))) for _ in range(count)]


def gudhi_diagram(points: np.ndarray, max_radius: float, max_dim: int, dim: int, p: int) -> np.ndarray:
    """GUDHI's Rips diagram of one dimension in ε (GUDHI's values are diameters 2ε), finite bars > 0."""
    st = gudhi.RipsComplex(points=points, max_edge_length=2 * max_radius).create_simplex_tree(max_dimension=max_dim)
    st.compute_persistence(homology_coeff_field=p)
    bars = np.array([[b / 2, d / 2] for b, d in st.persistence_intervals_in_dimension(dim)]).reshape(-1, 2)
    return bars[bars[:, 1] > bars[:, 0]]


def sorted_rows(a: np.ndarray) -> np.ndarray:
    return a[np.lexsort(a.T[::-1])] if len(a) else a.reshape(0, 2)


@pytest.mark.parametrize("seed, p", [(0, 2), (1, 3), (2, 2)])
def test_diagrams_match_gudhi_per_cloud(seed, p):
    data = clouds(seed)
    out = RipsDiagrams(max_radius=0.4, max_dim=2, coefficients=p).fit_transform(data)
    assert len(out) == len(data)
    for points, diagrams in zip(data, out):
        assert len(diagrams) == 2  # dimensions 0 and 1: the complete ones of a 2-skeleton
        for dim, dgm in enumerate(diagrams):
            assert dgm.shape[1:] == (2,)
            np.testing.assert_allclose(sorted_rows(dgm), sorted_rows(gudhi_diagram(points, 0.4, 2, dim, p)))


def test_two_circles_have_three_long_h1_classes():
    # Figure 2.13: two unit circles one apart bound three holes (β₁ = 3); with 40 points each the
    # three bars outlast every noise bar by far
    data = [two_circles(40, seed=s) for s in range(2)]
    for diagrams in RipsDiagrams(max_radius=2.0, max_dim=2).fit_transform(data):
        lengths = np.sort(diagrams[1][:, 1] - diagrams[1][:, 0])[::-1]
        assert len(lengths) >= 3 and lengths[2] > 0.15 and (len(lengths) == 3 or lengths[3] < 0.05)


def test_sklearn_clone_pipeline_and_parameter_grid():
    est = RipsDiagrams(max_radius=0.3, max_dim=2, coefficients=3)
    twin = clone(est)
    assert twin is not est and twin.get_params() == est.get_params()
    count_h1 = FunctionTransformer(lambda dgms: np.array([[len(d[1])] for d in dgms]))
    pipe = Pipeline([("diagrams", RipsDiagrams(max_dim=2)), ("count", count_h1)])
    data = clouds(5)
    for params in ParameterGrid({"diagrams__max_radius": [0.1, 0.5]}):
        pipe.set_params(**params)
        expected = [len(RipsDiagrams(max_radius=params["diagrams__max_radius"]).transform([c])[0][1]) for c in data]
        assert pipe.fit_transform(data)[:, 0].tolist() == expected
    assert repr(est) == ("RipsDiagrams(max_radius=0.3, max_dim=2, coefficients=3, homology_dimensions=None, "
                         "scale='epsilon', min_persistence=0.0, n_jobs=None, output='list', metric='euclidean')")


@pytest.mark.parametrize("params, match", [
    ({"max_dim": 0}, "max_dim"),
    ({"coefficients": 4}, "prime"),
    ({"max_radius": -1.0}, "max_radius"),
    ({"max_radius": float("nan")}, "max_radius"),
    ({"homology_dimensions": ()}, "homology_dimensions is empty"),
    ({"homology_dimensions": "01"}, "homology_dimensions"),
    ({"homology_dimensions": 1}, "homology_dimensions"),
    ({"homology_dimensions": (0, -1)}, "homology dimension"),
    ({"homology_dimensions": (0, 1.5)}, "homology dimension"),
    ({"homology_dimensions": (0, 1), "max_dim": 4}, "disagree"),
    ({"scale": "diam"}, "scale"),
    ({"min_persistence": -1e-9}, "min_persistence"),
    ({"min_persistence": float("inf")}, "min_persistence"),
])
def test_bad_parameters_are_refused_at_fit(params, match):
    with pytest.raises(ValueError, match=match):
        RipsDiagrams(**params).fit(clouds(0))


def test_bad_input_names_the_cloud():
    data = clouds(0) + [np.array([[0.0, np.nan], [1.0, 1.0]])]
    with pytest.raises(ValueError, match="point cloud 3"):
        RipsDiagrams().transform(data)
    with pytest.raises(ValueError, match="list of point clouds"):
        RipsDiagrams().transform(np.zeros((5, 2)))
    with pytest.raises(ValueError, match="unknown parameter"):
        RipsDiagrams().set_params(radius=1.0)


# ---------------------------------------------------------------------------- giotto-ph's and ripser's conventions
@pytest.mark.parametrize("dims", [(0, 1), (1,), (0, 2), (2, 1, 1)])
def test_homology_dimensions_choose_what_is_computed_and_returned(dims):
    data = clouds(7)
    chosen = RipsDiagrams(homology_dimensions=dims).fit_transform(data)
    wanted = sorted(set(dims))
    full = RipsDiagrams(max_dim=max(dims) + 1).fit_transform(data)  # max_dim = max(dims) + 1
    for ours, every in zip(chosen, full):
        assert len(ours) == len(wanted)
        for dgm, dim in zip(ours, wanted):
            np.testing.assert_array_equal(dgm, every[dim])
    # max_dim counts simplex dimensions: max_dim=1 (the 1-skeleton) gives H0 alone; H1 alone is asked by name
    assert [len(out) for out in RipsDiagrams(max_dim=1).fit_transform(data)] == [1] * len(data)
    h1 = RipsDiagrams(homology_dimensions=(1,), max_dim=2).fit_transform(data)
    for ours, every in zip(h1, full):
        np.testing.assert_array_equal(ours[0], every[1])


def finite(dgm: np.ndarray) -> np.ndarray:
    return dgm[np.isfinite(dgm[:, 1])]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_diameter_diagrams_are_ripsers_and_giotto_phs_up_to_a_bottleneck_of_zero(seed):
    import persim
    from gph import ripser_parallel
    from ripser import ripser

    data = clouds(seed)
    ours = RipsDiagrams(homology_dimensions=(0, 1, 2), scale="diameter").fit_transform(data)
    halves = RipsDiagrams(homology_dimensions=(0, 1, 2)).fit_transform(data)
    for points, diagrams, half in zip(data, ours, halves):
        for theirs in (ripser(points, maxdim=2)["dgms"], ripser_parallel(points, maxdim=2)["dgms"]):
            for dim in range(3):
                np.testing.assert_allclose(sorted_rows(diagrams[dim]), sorted_rows(theirs[dim]), rtol=0, atol=1e-6)
                assert np.isinf(diagrams[dim][:, 1]).sum() == np.isinf(theirs[dim][:, 1]).sum()
                if len(finite(theirs[dim])):
                    assert persim.bottleneck(finite(diagrams[dim]), finite(theirs[dim])) < 1e-6
                    # in ε (the default) the diagrams are ripser's halved: far from them
                    gap = persim.bottleneck(finite(half[dim]), finite(theirs[dim]))
                    assert gap > 1e-3 and np.isclose(gap, persim.bottleneck(finite(half[dim]), finite(diagrams[dim])))


def test_min_persistence_of_the_transformer_is_measured_in_the_values_returned():
    data = clouds(3)
    everything = RipsDiagrams(scale="diameter").fit_transform(data)
    for cut in (0.05, 0.2):
        kept = RipsDiagrams(scale="diameter", min_persistence=cut).fit_transform(data)
        for ours, every in zip(kept, everything):
            for dgm, full in zip(ours, every):
                np.testing.assert_array_equal(dgm, full[full[:, 1] - full[:, 0] > cut])
    assert sum(len(d) for e in everything for d in e) > sum(len(d) for k in kept for d in k)

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
    assert repr(est) == "RipsDiagrams(max_radius=0.3, max_dim=2, coefficients=3)"


@pytest.mark.parametrize("params, match", [
    ({"max_dim": 0}, "max_dim"),
    ({"coefficients": 4}, "prime"),
    ({"max_radius": -1.0}, "max_radius"),
    ({"max_radius": float("nan")}, "max_radius"),
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

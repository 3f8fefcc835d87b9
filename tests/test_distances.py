"""bottleneck_distance and wasserstein_distance: the numbers of GUDHI and persim on random diagrams, the two
backends agreeing (points at infinity included), the choice of backend, Barcodes and ripser's dgms as
input, and every refusal."""

from __future__ import annotations

import sys
import warnings

import gudhi
import gudhi.wasserstein
import numpy as np
import persim
import pytest
import ripser

from thesis_lib.complexes import rips
from thesis_lib.datasets import noisy_circle
from thesis_lib.persistence import Barcode, bottleneck_distance, persistence, wasserstein_distance
from thesis_lib.persistence.distances import BACKENDS

SEEDS = range(8)


def diagram(rng: np.random.Generator, n: int, n_infinite: int = 0) -> np.ndarray:
    births = rng.random(n + n_infinite)
    deaths = births + rng.exponential(0.3, n + n_infinite)
    deaths[n:] = np.inf
    return rng.permutation(np.c_[births, deaths])


def pair(seed: int, n_infinite: int = 0) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    return diagram(rng, int(rng.integers(0, 25)), n_infinite), diagram(rng, int(rng.integers(0, 25)), n_infinite)


@pytest.fixture
def no_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


# ------------------------------------------------------------------ against the libraries themselves
@pytest.mark.parametrize("seed", SEEDS)
def test_bottleneck_is_gudhis_and_persims(seed, no_warnings):
    x, y = pair(seed)
    ours = {backend: bottleneck_distance(x, y, backend=backend) for backend in BACKENDS}
    assert ours["gudhi"] == gudhi.bottleneck_distance(x, y, 0.0)
    assert ours["persim"] == pytest.approx(persim.bottleneck(x, y), abs=1e-12)
    assert ours["gudhi"] == pytest.approx(ours["persim"], abs=1e-12)
    assert bottleneck_distance(x, y) == ours["gudhi"]  # GUDHI first
    assert ours["gudhi"] > 0 or len(x) == len(y) == 0


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("order, internal_p", [(1.0, np.inf), (1.0, 2.0), (2.0, np.inf), (2.5, 1.0), (3.0, 2.0)])
def test_wasserstein_is_gudhis(seed, order, internal_p, no_warnings):
    x, y = pair(seed, n_infinite=seed % 3)
    ours = wasserstein_distance(x, y, order=order, internal_p=internal_p, backend="gudhi")
    assert ours == pytest.approx(gudhi.wasserstein.wasserstein_distance(x, y, order=order, internal_p=internal_p),
                                 rel=1e-12, abs=1e-12)
    assert wasserstein_distance(x, y, order=order, internal_p=internal_p) == ours


@pytest.mark.parametrize("seed", SEEDS)
def test_wasserstein_is_persims_for_order_1_and_the_euclidean_ground_metric(seed, no_warnings):
    x, y = pair(seed)
    ours = wasserstein_distance(x, y, internal_p=2.0, backend="persim")
    assert ours == pytest.approx(persim.wasserstein(x, y), rel=1e-12, abs=1e-12)
    assert ours == pytest.approx(wasserstein_distance(x, y, internal_p=2.0, backend="gudhi"), rel=1e-9, abs=1e-12)


@pytest.mark.parametrize("seed", SEEDS)
def test_the_backends_agree_on_points_at_infinity(seed, no_warnings):
    # persim alone drops them (with a warning); both backends here match them among themselves, as GUDHI
    x, y = pair(seed, n_infinite=1 + seed % 3)
    b = {backend: bottleneck_distance(x, y, backend=backend) for backend in BACKENDS}
    w = {backend: wasserstein_distance(x, y, internal_p=2.0, backend=backend) for backend in BACKENDS}
    assert b["gudhi"] == pytest.approx(b["persim"], abs=1e-12)
    assert w["gudhi"] == pytest.approx(w["persim"], rel=1e-9, abs=1e-12)
    # the essential part: the sorted births matched in order
    gaps = np.abs(np.sort(x[np.isinf(x[:, 1]), 0]) - np.sort(y[np.isinf(y[:, 1]), 0]))
    fx, fy = x[np.isfinite(x[:, 1])], y[np.isfinite(y[:, 1])]
    assert b["persim"] == pytest.approx(max(gaps.max(), gudhi.bottleneck_distance(fx, fy, 0.0)), abs=1e-12)
    assert w["persim"] == pytest.approx(gaps.sum() + persim.wasserstein(fx, fy), rel=1e-9)


@pytest.mark.parametrize("backend", BACKENDS)
def test_different_numbers_of_points_at_infinity_are_infinitely_far(backend, no_warnings):
    x = np.array([[0.0, 1.0], [0.0, np.inf]])
    y = np.array([[0.0, 1.0], [0.0, np.inf], [0.5, np.inf]])
    assert bottleneck_distance(x, y, backend=backend) == np.inf
    assert wasserstein_distance(x, y, internal_p=2.0, backend=backend) == np.inf
    assert wasserstein_distance(x, y[:2], internal_p=2.0, backend=backend) == 0.0
    # one point at infinity each: only their births count
    assert bottleneck_distance([[0.0, np.inf]], [[0.75, np.inf]], backend=backend) == 0.75


@pytest.mark.parametrize("backend", BACKENDS)
def test_empty_diagrams(backend, no_warnings):
    x = np.array([[0.0, 1.0], [0.25, 0.5]])
    for empty in (np.empty((0, 2)), [], np.array([])):
        assert bottleneck_distance(empty, empty, backend=backend) == 0.0
        assert bottleneck_distance(x, empty, backend=backend) == pytest.approx(0.5)  # (0, 1) to the diagonal
        assert wasserstein_distance(x, empty, internal_p=2.0, backend=backend) == pytest.approx(1.25 / np.sqrt(2))


# ------------------------------------------------------------------ Barcodes, dgms and the scale
def test_a_rips_barcode_at_diameter_scale_is_ripsers_dgms():
    points = noisy_circle(30, noise=0.05, seed=4)
    bars = persistence(rips(points, max_radius=1.5, max_dim=2))
    dgms = ripser.ripser(points, maxdim=1)["dgms"]
    for d in (0, 1):
        assert bottleneck_distance(bars, dgms, dim=d, scale="diameter") < 1e-6
        assert wasserstein_distance(bars, dgms, dim=d, scale="diameter") < 1e-5
        # at the thesis's ε every value is half of ripser's: the distance is not zero
        assert bottleneck_distance(bars, dgms, dim=d, scale="epsilon") > 0.01
    # ... but that of ripser's diagram and its half
    halved = gudhi.bottleneck_distance(dgms[1] / 2, dgms[1], 0.0)
    assert bottleneck_distance(bars, dgms, dim=1, scale="epsilon") == pytest.approx(halved, abs=1e-6)
    # two barcodes at one scale: scale applies to both
    assert bottleneck_distance(bars, bars, dim=1, scale="epsilon") == 0.0


def test_a_single_array_against_a_list_takes_the_list_at_dim():
    dgms = [np.array([[0.0, np.inf]]), np.array([[0.2, 0.6]])]
    assert bottleneck_distance(np.array([[0.2, 0.7]]), dgms, dim=1) == pytest.approx(0.1)
    assert bottleneck_distance(dgms, dgms, dim=0) == 0.0


def test_barcodes_and_lists_need_dim_and_barcodes_need_scale():
    bars = Barcode({0: [[0.0, 1.0]], 1: [[0.5, 0.75]]})
    dgms = bars.to_diagrams()
    with pytest.raises(ValueError, match="pass dim="):
        bottleneck_distance(bars, dgms[0], scale="epsilon")
    with pytest.raises(ValueError, match="pass scale="):
        bottleneck_distance(bars, dgms[0], dim=0)
    with pytest.raises(ValueError, match="pass dim="):
        wasserstein_distance(dgms, dgms[0])
    with pytest.raises(ValueError, match="no diagram of dimension 2"):
        wasserstein_distance(dgms, dgms[0], dim=2)
    with pytest.raises(ValueError, match="scale= applies to a Barcode"):
        bottleneck_distance(dgms[0], dgms[0], scale="diameter")
    with pytest.raises(ValueError, match="scale must be one of"):
        bottleneck_distance(bars, bars, dim=0, scale="radii")
    truncated = persistence(rips(noisy_circle(12, noise=0.0, seed=0), max_radius=2.0, max_dim=1))
    with pytest.raises(ValueError, match="no complete dimension 1"):
        bottleneck_distance(truncated, truncated, dim=1, scale="epsilon")


# ------------------------------------------------------------------ the backends
def spy(monkeypatch, module, name: str, *, calls: list | None = None) -> list:
    """Record in ``calls`` (a new list by default) each call of ``module.name``."""
    calls = [] if calls is None else calls
    original = getattr(module, name)

    def wrapper(*args, **kwargs):
        calls.append(name)
        return original(*args, **kwargs)

    monkeypatch.setattr(module, name, wrapper)
    return calls


def hide(monkeypatch, *modules: str) -> None:
    """Make ``import module`` fail as if it were not installed."""
    for name in modules:
        monkeypatch.setitem(sys.modules, name, None)


def test_backend_none_is_gudhi_when_installed_and_persim_otherwise(monkeypatch):
    x, y = pair(1, n_infinite=1)
    gudhi_calls = spy(monkeypatch, gudhi, "bottleneck_distance")
    wasserstein_calls = spy(monkeypatch, gudhi.wasserstein, "wasserstein_distance")
    persim_calls = spy(monkeypatch, persim, "bottleneck")
    spy(monkeypatch, persim, "wasserstein", calls=persim_calls)
    with_gudhi = bottleneck_distance(x, y), wasserstein_distance(x, y, internal_p=2.0)
    assert gudhi_calls == ["bottleneck_distance"] and wasserstein_calls == ["wasserstein_distance"]
    assert persim_calls == []
    hide(monkeypatch, "gudhi", "gudhi.wasserstein")
    without = bottleneck_distance(x, y), wasserstein_distance(x, y, internal_p=2.0)
    assert persim_calls == ["bottleneck", "wasserstein"]
    assert without == pytest.approx(with_gudhi, rel=1e-9)


def test_gudhis_wasserstein_needs_pot(monkeypatch):
    x, y = pair(2)
    hide(monkeypatch, "ot")
    expected = persim.wasserstein(x, y)
    calls = spy(monkeypatch, persim, "wasserstein")
    # order 1 with the Euclidean ground metric: persim computes it
    assert wasserstein_distance(x, y, internal_p=2.0) == pytest.approx(expected, rel=1e-12)
    assert calls == ["wasserstein"]
    with pytest.raises(ImportError, match="pip install gudhi pot"):
        wasserstein_distance(x, y)  # internal_p = inf: only GUDHI's
    with pytest.raises(ImportError, match="pip install gudhi pot"):
        wasserstein_distance(x, y, internal_p=2.0, backend="gudhi")


def test_no_backend_installed_names_both_install_commands(monkeypatch):
    x, y = pair(3)
    hide(monkeypatch, "gudhi", "gudhi.wasserstein", "persim")
    for call in (lambda: bottleneck_distance(x, y), lambda: wasserstein_distance(x, y, internal_p=2.0)):
        with pytest.raises(ImportError, match="pip install gudhi") as error:
            call()
        assert "pip install persim" in str(error.value)
    with pytest.raises(ImportError, match="backend='gudhi'.*pip install gudhi"):
        bottleneck_distance(x, y, backend="gudhi")


def test_gudhi_needs_no_persim(monkeypatch):
    x, y = pair(5)
    hide(monkeypatch, "persim")
    assert bottleneck_distance(x, y) == gudhi.bottleneck_distance(x, y, 0.0)  # GUDHI needs no persim
    with pytest.raises(ImportError, match="pip install gudhi"):
        bottleneck_distance(x, y, backend="persim")


# ------------------------------------------------------------------ refusals
@pytest.mark.parametrize("kwargs, error, match", [
    ({"backend": "hera"}, ValueError, "backend must be one of"),
    ({"dim": -1}, ValueError, "dim must be >= 0"),
    ({"dim": 1.5}, TypeError, "dim must be an integer"),
])
def test_bad_options_are_refused(kwargs, error, match):
    x = np.array([[0.0, 1.0]])
    for distance in (bottleneck_distance, wasserstein_distance):
        with pytest.raises(error, match=match):
            distance(x, x, **kwargs)


@pytest.mark.parametrize("kwargs, error, match", [
    ({"order": 0.5}, ValueError, "order must be >= 1"),
    ({"order": np.inf}, ValueError, "order must be finite"),
    ({"order": "1"}, TypeError, "order must be a number"),
    ({"internal_p": 0.5}, ValueError, "internal_p must be >= 1"),
    ({"internal_p": np.nan}, ValueError, "internal_p is NaN"),
    ({"order": 2.0, "internal_p": 2.0, "backend": "persim"}, ValueError, "persim.wasserstein computes order=1"),
    ({"backend": "persim"}, ValueError, "internal_p=2 only"),
])
def test_bad_wasserstein_parameters_are_refused(kwargs, error, match):
    x = np.array([[0.0, 1.0]])
    with pytest.raises(error, match=match):
        wasserstein_distance(x, x, **kwargs)


@pytest.mark.parametrize("bad, error, match", [
    (np.array([[0.0, np.nan]]), ValueError, "NaN"),
    (np.array([[1.0, 0.5]]), ValueError, "dies before it is born"),
    (np.array([[-np.inf, 0.5]]), ValueError, "births must be finite"),
    (np.zeros((2, 3)), ValueError, "shape"),
    ({"dgm": 1}, TypeError, "array"),
    ("dgm", TypeError, "array"),
    (None, TypeError, "array"),
    (np.array([[0.0, 1 + 1j]]), TypeError, "complex"),
    ([[0.0, 1.0], [0.5]], TypeError, "numbers"),
])
def test_bad_diagrams_are_refused(bad, error, match):
    good = np.array([[0.0, 1.0]])
    for distance in (bottleneck_distance, wasserstein_distance):
        with pytest.raises(error, match=match):
            distance(bad, good)
        with pytest.raises(error, match=r"^b|b "):
            distance(good, bad)

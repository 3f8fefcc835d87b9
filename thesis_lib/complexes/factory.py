"""Build any of the point-cloud filtrations of §2.1 by name (what the experiments' parameters choose)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import check_choice, check_seed, parse_points
from ..homology.filtration import Filtration
from .landmarks import maxmin_landmarks, random_landmarks
from .rips import rips
from .witness import lazy_witness, witness

__all__ = ["COMPLEXES", "LANDMARK_METHODS", "choose_landmarks", "build_filtration"]

COMPLEXES = ("rips", "witness", "lazy-witness")
LANDMARK_METHODS = {"maxmin": maxmin_landmarks, "random": random_landmarks}


def choose_landmarks(points: npt.ArrayLike, *, landmark_method: str, n: int, seed: int) -> np.ndarray:
    """Landmark indices by ``landmark_method`` (``"maxmin"`` or ``"random"``).

    Thesis: Definition 2.16 and §2.1.2 (the two standard ways of choosing landmarks).

    Parameters
    ----------
    points : (N, d) array.
    landmark_method : "maxmin" or "random".
    n : number of landmarks.
    seed : seed of the random choices.

    Returns
    -------
    ndarray of int64

    Examples
    --------
    >>> from thesis_lib.datasets import noisy_circle
    >>> points = noisy_circle(40, noise=0.0, seed=0)
    >>> choose_landmarks(points, landmark_method="maxmin", n=4, seed=0).tolist()
    [34, 20, 1, 4]
    >>> choose_landmarks(points, landmark_method="random", n=4, seed=0).tolist()
    [10, 19, 24, 31]
    """
    check_choice(landmark_method, sorted(LANDMARK_METHODS), "landmark_method")
    return LANDMARK_METHODS[landmark_method](points, n=n, seed=seed)


def build_filtration(
    points: npt.ArrayLike,
    *,
    complex: str,
    max_radius: float,
    max_dim: int,
    landmark_method: str = "maxmin",
    n_landmarks: int = 100,
    nu: int = 1,
    seed: int = 0,
) -> Filtration:
    """The filtration of ``points`` named by ``complex``: ``"rips"``, ``"witness"`` or ``"lazy-witness"``.

    Thesis: Definition 2.11 (Rips) and §2.1.2 (witness complexes on landmarks).

    Parameters
    ----------
    points : (N, d) array.
    complex : "rips", "witness" or "lazy-witness".
    max_radius : largest ε kept.
    max_dim : largest simplex dimension built.
    landmark_method, n_landmarks, nu, seed
        Witness complexes choose ``n_landmarks`` landmarks by ``landmark_method`` with ``seed``.

    Returns
    -------
    Filtration

    Examples
    --------
    The witness filtration on eight maxmin landmarks of a circle (see :func:`witness`):

    >>> from thesis_lib.datasets import noisy_circle
    >>> from thesis_lib.persistence import persistence
    >>> points = noisy_circle(40, noise=0.0, seed=0)
    >>> f = build_filtration(points, complex="witness", max_radius=1.0, max_dim=2, n_landmarks=8)
    >>> f.counts(), persistence(f).intervals(1).round(6).tolist()
    ([8, 22, 20], [[0.503326, inf]])
    """
    check_choice(complex, COMPLEXES, "complex")
    seed = check_seed(seed)  # checked for every complex, also where it is not used (a rips call)
    points = parse_points(points, warn_square=True)  # parsed once: each construction takes the record
    if complex == "rips":
        return rips(points, max_radius=max_radius, max_dim=max_dim)
    landmarks = choose_landmarks(points, landmark_method=landmark_method, n=n_landmarks, seed=seed)
    build = witness if complex == "witness" else lazy_witness
    return build(points, landmarks, max_radius=max_radius, max_dim=max_dim, nu=nu)

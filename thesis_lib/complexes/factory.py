"""Build any of the point-cloud filtrations of §2.1 by name (what the experiments' parameters choose)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import check_seed
from ..filtration import Filtration
from .landmarks import maxmin_landmarks, random_landmarks
from .rips import rips
from .witness import lazy_witness, witness

__all__ = ["COMPLEXES", "LANDMARK_METHODS", "choose_landmarks", "build_filtration"]

COMPLEXES = ("rips", "witness", "lazy-witness")
LANDMARK_METHODS = {"maxmin": maxmin_landmarks, "random": random_landmarks}


def choose_landmarks(points: npt.ArrayLike, method: str, n: int, seed: int) -> np.ndarray:
    """Landmark indices by ``method`` (``"maxmin"`` or ``"random"``).

    Thesis: Definition 2.16 and §2.1.2 (the two standard ways of choosing landmarks).

    Parameters
    ----------
    points : (N, d) array.
    method : "maxmin" or "random".
    n : number of landmarks.
    seed : seed of the random choices.

    Returns
    -------
    ndarray of int64
    """
    if not isinstance(method, str) or method not in LANDMARK_METHODS:
        raise ValueError(f"landmark method must be one of {sorted(LANDMARK_METHODS)}, got {method!r}")
    return LANDMARK_METHODS[method](points, n, seed=seed)


def build_filtration(
    kind: str,
    points: npt.ArrayLike,
    max_radius: float,
    max_dim: int,
    *,
    landmark_method: str = "maxmin",
    n_landmarks: int = 100,
    nu: int = 1,
    seed: int = 0,
) -> Filtration:
    """The ``kind`` filtration of ``points``: ``"rips"``, ``"witness"`` or ``"lazy-witness"``.

    Thesis: Definition 2.11 (Rips) and §2.1.2 (witness complexes on landmarks).

    Parameters
    ----------
    kind : "rips", "witness" or "lazy-witness".
    points : (N, d) array.
    max_radius : largest ε kept.
    max_dim : largest simplex dimension built.
    landmark_method, n_landmarks, nu, seed
        Witness complexes choose ``n_landmarks`` landmarks by ``landmark_method`` with ``seed``.

    Returns
    -------
    Filtration
    """
    if not isinstance(kind, str):
        raise ValueError(f"complex must be one of {COMPLEXES}, got {kind!r}")
    seed = check_seed(seed)  # checked for every kind, also where it is not used (a rips call)
    if kind == "rips":
        return rips(points, max_radius, max_dim)
    if kind in ("witness", "lazy-witness"):
        landmarks = choose_landmarks(points, landmark_method, n_landmarks, seed)
        build = witness if kind == "witness" else lazy_witness
        return build(points, landmarks, max_radius, max_dim, nu=nu)
    raise ValueError(f"complex must be one of {COMPLEXES}, got {kind!r}")

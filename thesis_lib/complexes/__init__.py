"""Simplicial complexes built from point clouds (thesis §2.1)."""

from .filtration import Filtration

__all__ = ["Filtration"]
from .landmarks import covering_radius, maxmin_landmarks, random_landmarks

__all__ += ["maxmin_landmarks", "random_landmarks", "covering_radius"]

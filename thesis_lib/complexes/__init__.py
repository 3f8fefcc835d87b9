"""Simplicial complexes built from point clouds (thesis §2.1)."""

from ..homology.filtration import Filtration, as_complex
from .alpha import alpha
from .cech import cech
from .delaunay import delaunay
from .factory import COMPLEXES, build_filtration, choose_landmarks
from .landmarks import covering_radius, maxmin_landmarks, random_landmarks
from .miniball import smallest_enclosing_ball
from .nerve import nerve
from .rips import rips
from .triangulation import regular_triangulation
from .witness import lazy_witness, witness, witness_offsets

__all__ = [
    "Filtration",
    "as_complex",
    "maxmin_landmarks",
    "random_landmarks",
    "covering_radius",
    "rips",
    "cech",
    "smallest_enclosing_ball",
    "delaunay",
    "regular_triangulation",
    "alpha",
    "witness",
    "lazy_witness",
    "witness_offsets",
    "nerve",
    "COMPLEXES",
    "build_filtration",
    "choose_landmarks",
]

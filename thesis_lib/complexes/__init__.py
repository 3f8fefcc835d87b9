"""Simplicial complexes built from point clouds (thesis §2.1)."""

from ..filtration import Filtration, as_complex

__all__ = ["Filtration", "as_complex"]
from .landmarks import covering_radius, maxmin_landmarks, random_landmarks

__all__ += ["maxmin_landmarks", "random_landmarks", "covering_radius"]
from .alpha import alpha
from .cech import cech
from .delaunay import delaunay, regular_triangulation
from .miniball import smallest_enclosing_ball
from .nerve import nerve
from .rips import rips
from .witness import lazy_witness, witness, witness_offsets

__all__ += ["rips", "cech", "smallest_enclosing_ball", "delaunay", "regular_triangulation", "alpha", "witness",
            "lazy_witness", "witness_offsets", "nerve"]
from .factory import COMPLEXES, build_filtration, choose_landmarks

__all__ += ["COMPLEXES", "build_filtration", "choose_landmarks"]

"""Data sets the thesis uses: triangulations, samplers and small example filtrations.

Each topic lives in its own module; the samplers of chapter 3's surfaces and the torus grid are
those of :mod:`thesis_lib.meshes`.
"""

from ..meshes import sample_catenoid, sample_sphere, sample_torus, torus_grid
from .filtrations import dense_filtration, example_filtration, module_filtration, named_chain
from .samplers import flat_torus, noisy_circle, two_circles, two_circles_intersections
from .triangulations import RP2_LABELS, dunce_hat, klein_bottle, rp2, sphere, torus

__all__ = [
    "RP2_LABELS",
    "dense_filtration",
    "dunce_hat",
    "example_filtration",
    "flat_torus",
    "klein_bottle",
    "module_filtration",
    "named_chain",
    "noisy_circle",
    "rp2",
    "sample_catenoid",
    "sample_sphere",
    "sample_torus",
    "sphere",
    "torus",
    "torus_grid",
    "two_circles",
    "two_circles_intersections",
]

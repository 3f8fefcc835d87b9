"""Data sets the thesis uses: triangulations, samplers and small example filtrations.

Each topic lives in its own module; this package re-exports their public functions.  The surfaces
of chapter 3 come from :mod:`thesis_lib.meshes` and are imported when first asked for, so that the
triangulations and samplers load without the mesh layer (and scipy.spatial).
"""

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

_SURFACES = ("sample_catenoid", "sample_sphere", "sample_torus", "torus_grid")


def __getattr__(name: str):
    if name in _SURFACES:
        from . import surfaces

        return getattr(surfaces, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_SURFACES))

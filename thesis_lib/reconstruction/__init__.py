"""Surfaces reconstructed from point samples (thesis §3.4): the Crust algorithm [ABK98] in R³ and,
the thesis's "natural next step" (Chapter 5), for hypersurfaces of R^{n+1}; ball pivoting for
comparison; one entry point choosing between them.
"""

from .crust import crust, crust_candidates, extract_manifold, poles
from .pivoting import ball_pivoting, estimate_normals
from .reconstruct import RECONSTRUCTIONS, reconstruct_surface

__all__ = [
    "RECONSTRUCTIONS",
    "ball_pivoting",
    "crust",
    "crust_candidates",
    "estimate_normals",
    "extract_manifold",
    "poles",
    "reconstruct_surface",
]

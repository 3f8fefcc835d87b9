"""Two-parameter persistence: radius × curvature (the thesis's Summary, Chapter 5).

A one-critical bifiltration (:class:`Bifiltration`: each simplex with its pair of grades (ε, κ)), its
construction from a point cloud and a curvature estimate (:func:`radius_curvature_bifiltration`),
and its invariants on a grid: the Hilbert function, the rank invariant and fibered barcodes along
lines of positive slope, each computed by the one-parameter persistence engine.
"""

from .bifiltration import COMPLEX_KINDS, Bifiltration, function_bifiltration, radius_curvature_bifiltration
from .invariants import (
    MAX_GRID_ENTRIES,
    check_grid,
    fibered_barcode,
    hilbert_function,
    line_filtration,
    rank_invariant,
)

__all__ = [
    "COMPLEX_KINDS",
    "MAX_GRID_ENTRIES",
    "Bifiltration",
    "check_grid",
    "fibered_barcode",
    "function_bifiltration",
    "hilbert_function",
    "line_filtration",
    "radius_curvature_bifiltration",
    "rank_invariant",
]

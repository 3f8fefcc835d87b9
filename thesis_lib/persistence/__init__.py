"""Persistent homology (thesis §2.3): the thesis's algorithm, a fast engine, barcodes and their plots."""

from .algorithm import compute_intervals, trace_matrices
from .apparent import apparent_pairs, apparent_summary
from .barcode import Barcode
from .chains import chain_persistence
from .distances import bottleneck_distance, wasserstein_distance
from .engine import persistence
from .implicit import rips_persistence
from .lower_star import image_filtration, lower_star_img
from .plotting import plot_barcode, plot_diagram
from .summaries import long_bars, long_betti
from .transformer import RipsDiagrams

__all__ = [
    "Barcode",
    "compute_intervals",
    "persistence",
    "rips_persistence",
    "trace_matrices",
    "plot_barcode",
    "plot_diagram",
    "long_bars",
    "long_betti",
    "apparent_pairs",
    "apparent_summary",
    "chain_persistence",
    "RipsDiagrams",
    "bottleneck_distance",
    "wasserstein_distance",
    "image_filtration",
    "lower_star_img",
]

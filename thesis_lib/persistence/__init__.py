"""Persistent homology (thesis §2.3): the thesis's algorithm, a fast engine, barcodes and their plots."""

from .algorithm import compute_intervals, trace_matrices
from .barcode import Barcode
from .engine import persistence
from .implicit import rips_persistence

__all__ = ["Barcode", "compute_intervals", "persistence", "rips_persistence", "trace_matrices"]
from .plotting import plot_barcode, plot_diagram

__all__ += ["plot_barcode", "plot_diagram"]
from .summaries import long_bars, long_betti

__all__ += ["long_bars", "long_betti"]
from .apparent import apparent_pairs, apparent_summary

__all__ += ["apparent_pairs", "apparent_summary"]
from .chains import chain_persistence

__all__ += ["chain_persistence"]

"""Reading a barcode: which bars are long enough to count as features."""

from __future__ import annotations

import numpy as np

from .barcode import Barcode

__all__ = ["long_bars", "long_betti"]


def long_bars(barcode: Barcode, dim: int, min_length: float) -> np.ndarray:
    """The intervals of ``dim`` whose length is at least ``min_length`` (infinite ones included).

    Thesis: §2.3 (a feature that persists for a significant filtration time is "real"; short
    bars are noise).  The threshold is the caller's explicit choice, never inferred.
    """
    if not np.isfinite(min_length) or min_length < 0:
        raise ValueError(f"min_length must be a finite non-negative number, got {min_length!r}")
    iv = barcode.intervals(dim)
    return iv[(iv[:, 1] - iv[:, 0]) >= min_length]


def long_betti(barcode: Barcode, min_length: float, dims=None) -> list[int]:
    """Number of long bars in each dimension (``dims`` default: all computed ones).

    Thesis: §2.4 (Betti numbers read off a barcode as its long bars, e.g. β = (1, 3) for two circles).
    """
    dims = barcode.dimensions if dims is None else dims
    return [int(long_bars(barcode, d, min_length).shape[0]) for d in dims]

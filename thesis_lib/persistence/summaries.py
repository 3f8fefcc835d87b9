"""Reading a barcode: which bars are long enough to count as features."""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from .barcode import Barcode

__all__ = ["long_bars", "long_betti"]


def long_bars(barcode: Barcode, *, dim: int, min_length: float) -> np.ndarray:
    """The intervals of ``dim`` whose length is at least ``min_length`` (infinite ones included).

    Thesis: §2.3 (a feature that persists for a significant filtration time is "real"; short
    bars are noise).  The threshold is the caller's explicit choice, never inferred.

    Parameters
    ----------
    barcode : Barcode
        The barcode to read.
    dim : int
        The homology dimension.
    min_length : float
        The least length death − birth of a long bar; finite, ≥ 0.

    Returns
    -------
    numpy.ndarray, shape (k, 2)
        The long intervals of ``barcode.intervals(dim)``, in its order.

    Raises
    ------
    ValueError
        ``min_length`` negative, infinite or NaN.

    Examples
    --------
    A noisy circle of 30 points has one H_1 bar longer than 0.2, the circle's:

    >>> from thesis_lib.complexes import rips
    >>> from thesis_lib.datasets import noisy_circle
    >>> from thesis_lib.persistence import persistence
    >>> barcode = persistence(rips(noisy_circle(30, noise=0.1, seed=0), max_radius=1.0, max_dim=2))
    >>> long_bars(barcode, dim=1, min_length=0.2).round(6).tolist()
    [[0.366976, 0.759903]]
    """
    if not np.isfinite(min_length) or min_length < 0:
        raise ValueError(f"min_length must be a finite non-negative number, got {min_length!r}")
    iv = barcode.intervals(dim)
    return iv[(iv[:, 1] - iv[:, 0]) >= min_length]


def long_betti(barcode: Barcode, *, min_length: float, dims: Iterable[int] | None = None) -> list[int]:
    """Number of long bars in each dimension (``dims`` default: all computed ones).

    Thesis: §2.4 (Betti numbers read off a barcode as its long bars, e.g. β = (1, 3) for two circles).

    Parameters
    ----------
    barcode : Barcode
        The barcode to read.
    min_length : float
        The least length of a long bar (as :func:`long_bars`).
    dims : iterable of int, optional
        The dimensions to count (default: ``barcode.dimensions``, complete or not).

    Returns
    -------
    list of int
        The number of long bars of each dimension of ``dims``, in that order.

    Examples
    --------
    The same noisy circle as in :func:`long_bars`: five long H_0 bars (the essential one among them,
    the others are gaps between the points), one long H_1 bar:

    >>> from thesis_lib.complexes import rips
    >>> from thesis_lib.datasets import noisy_circle
    >>> from thesis_lib.persistence import persistence
    >>> barcode = persistence(rips(noisy_circle(30, noise=0.1, seed=0), max_radius=1.0, max_dim=2))
    >>> long_betti(barcode, min_length=0.2, dims=(0, 1))
    [5, 1]
    """
    dims = barcode.dimensions if dims is None else dims
    return [int(long_bars(barcode, dim=d, min_length=min_length).shape[0]) for d in dims]

"""Argument checks shared by the constructions of §2.1.2 (each failure is a clear ValueError)."""

from __future__ import annotations

import numpy as np


def check_radius(max_radius, name: str = "max_radius") -> float:
    """A scale parameter ε: a non-negative number (``inf`` allowed: no bound)."""
    if isinstance(max_radius, bool):
        raise ValueError(f"{name} must be a number, got {max_radius!r}")
    try:
        r = float(max_radius)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, got {max_radius!r}") from None
    if np.isnan(r):
        raise ValueError(f"{name} is NaN")
    if r < 0:
        raise ValueError(f"{name} must be non-negative, got {r}")
    return r


def check_max_dim(max_dim, name: str = "max_dim") -> int:
    """A largest simplex dimension: an integer >= 0."""
    if isinstance(max_dim, bool) or not isinstance(max_dim, (int, np.integer)):
        raise ValueError(f"{name} must be an integer >= 0, got {max_dim!r}")
    if max_dim < 0:
        raise ValueError(f"{name} must be >= 0, got {max_dim}")
    return int(max_dim)


def check_weights(weights, n: int) -> np.ndarray:
    """Weights w_x >= 0 (squared radii of the weighted points, §2.1.2), one per point."""
    w = np.asarray(weights, dtype=np.float64)
    if w.ndim != 1 or w.shape[0] != n:
        raise ValueError(f"weights must be a 1-D array with one weight per point ({n}), got shape {w.shape}")
    if not np.all(np.isfinite(w)):
        raise ValueError(f"weight {int(np.argmax(~np.isfinite(w)))} is NaN or infinite")
    if np.any(w < 0):
        raise ValueError(f"weights are squared radii and must be >= 0; weight {int(np.argmax(w < 0))} is {w[w < 0][0]}")
    return w

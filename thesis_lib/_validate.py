"""Validation at the public edge: every public function checks its input here, in one call."""

from __future__ import annotations

import numpy as np

__all__ = ["as_points"]


def as_points(points, *, min_points: int = 1, allow_duplicates: bool = True) -> np.ndarray:
    """Return ``points`` as a finite ``(n, d)`` float64 array, or raise ``ValueError`` naming the problem.

    Thesis: §2.1.2 (a point set X in R^d).
    """
    arr = np.asarray(points, dtype=np.float64)
    if arr.ndim != 2:
        raise ValueError(f"points must be an (n, d) array, got shape {arr.shape}")
    if arr.shape[0] < min_points:
        raise ValueError(f"need at least {min_points} points, got {arr.shape[0]}")
    if arr.shape[1] == 0:
        raise ValueError("points must have at least one coordinate")
    if not np.all(np.isfinite(arr)):
        row = int(np.argmax(~np.all(np.isfinite(arr), axis=1)))
        raise ValueError(f"point {row} has a NaN or infinite coordinate")
    if not allow_duplicates and arr.shape[0] > 1:
        uniq, inverse, counts = np.unique(arr, axis=0, return_inverse=True, return_counts=True)
        if uniq.shape[0] != arr.shape[0]:
            dup = np.flatnonzero(counts[inverse.ravel()] > 1)[:2]
            raise ValueError(f"duplicate points: rows {int(dup[0])} and {int(dup[1])} are equal")
    return arr

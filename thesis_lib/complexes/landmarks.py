"""Landmark selection: random and sequential maxmin (thesis §2.1.2, Definition 2.16)."""

from __future__ import annotations

import numpy as np

from .._validate import as_points

__all__ = ["maxmin_landmarks", "random_landmarks", "covering_radius", "count_within"]


def _check_count(points: np.ndarray, n: int) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"the number of landmarks must be a positive integer, got {n!r}")
    if n > points.shape[0]:
        raise ValueError(f"cannot choose {n} landmarks from {points.shape[0]} points")
    return int(n)


def random_landmarks(points, n: int, seed: int) -> np.ndarray:
    """Indices of ``n`` landmarks drawn uniformly without replacement.

    Thesis: Definition 2.16 and §2.1.2 (the random method).
    """
    pts = as_points(points)
    n = _check_count(pts, n)
    return np.sort(np.random.default_rng(seed).choice(pts.shape[0], size=n, replace=False))


def maxmin_landmarks(points, n: int, seed: int) -> np.ndarray:
    """Indices of ``n`` landmarks chosen by the sequential maxmin method, in the order chosen.

    Thesis: §2.1.2: the i-th landmark maximises the distance to the first i - 1 landmarks;
    the first one is drawn at random with ``seed``.
    """
    pts = as_points(points)
    n = _check_count(pts, n)
    first = int(np.random.default_rng(seed).integers(pts.shape[0]))
    chosen = np.empty(n, dtype=np.int64)
    chosen[0] = first
    dist = np.linalg.norm(pts - pts[first], axis=1)
    for i in range(1, n):
        nxt = int(np.argmax(dist))
        chosen[i] = nxt
        np.minimum(dist, np.linalg.norm(pts - pts[nxt], axis=1), out=dist)
    return chosen


def covering_radius(points, landmarks: np.ndarray) -> float:
    """Largest distance from a point to its nearest landmark: how well ``landmarks`` cover the data.

    Thesis: §2.1.2 (maxmin minimises this greedily).
    """
    from scipy.spatial import cKDTree

    pts = as_points(points)
    d, _ = cKDTree(pts[np.asarray(landmarks)]).query(pts)
    return float(d.max())


def count_within(points, targets, radius: float) -> int:
    """Number of ``points`` within distance ``radius`` of at least one of ``targets``.

    Thesis: Figure 2.13 (landmarks near the intersection points of the two circles).
    """
    pts, tgt = as_points(points), as_points(targets)
    if pts.shape[1] != tgt.shape[1]:
        raise ValueError(f"points live in R^{pts.shape[1]} but targets in R^{tgt.shape[1]}")
    if not radius >= 0:
        raise ValueError(f"radius must be non-negative, got {radius!r}")
    d = np.linalg.norm(pts[:, None, :] - tgt[None, :, :], axis=2)
    return int(np.count_nonzero(d.min(axis=1) <= radius))

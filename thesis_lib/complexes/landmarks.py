"""Landmark selection: random and sequential maxmin (thesis §2.1.2, Definition 2.16)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_points, check_indices, check_int, check_real, check_seed
from .scaling import scaled

__all__ = ["maxmin_landmarks", "random_landmarks", "covering_radius", "count_within"]


def _check_count(points: np.ndarray, n) -> int:
    n = check_int(n, "the number of landmarks", minimum=1)
    if n > points.shape[0]:
        raise ValueError(f"cannot choose {n} landmarks from {points.shape[0]} points")
    return n


def random_landmarks(points: npt.ArrayLike, *, n: int, seed: int) -> np.ndarray:
    """Indices of ``n`` landmarks drawn uniformly without replacement.

    Thesis: Definition 2.16 and §2.1.2 (the random method).

    Parameters
    ----------
    points : (N, d) array.
    n : number of landmarks, 1 <= n <= N.
    seed : seed of the random draw.

    Returns
    -------
    ndarray of int64
        ``n`` distinct row indices of ``points``, ascending.

    Examples
    --------
    >>> from thesis_lib.datasets import noisy_circle
    >>> random_landmarks(noisy_circle(20, noise=0.0, seed=0), n=3, seed=0).tolist()
    [10, 12, 15]
    """
    pts = as_points(points)
    n = _check_count(pts, n)
    return np.sort(np.random.default_rng(check_seed(seed)).choice(pts.shape[0], size=n, replace=False))


def maxmin_landmarks(points: npt.ArrayLike, *, n: int, seed: int) -> np.ndarray:
    """Indices of ``n`` landmarks chosen by the sequential maxmin method, in the order chosen.

    Thesis: §2.1.2: the i-th landmark maximises the distance to the first i - 1 landmarks;
    the first one is drawn at random with ``seed``.

    Parameters
    ----------
    points : (N, d) array (repeated points allowed).
    n : number of landmarks, 1 <= n <= N.
    seed : seed of the first (random) landmark.

    Returns
    -------
    ndarray of int64
        ``n`` distinct row indices in the order chosen.  Once every distinct point is a landmark,
        the remaining ones are copies of chosen points (distance 0), lowest index first.

    Examples
    --------
    On the unit square, after the first (seeded) landmark the next one is the farthest point, the
    opposite corner:

    >>> square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    >>> maxmin_landmarks(square, n=2, seed=0).tolist()
    [3, 1]
    """
    pts = as_points(points)
    n = _check_count(pts, n)
    pts, _ = scaled(pts)  # distances near 1e200 would overflow when squared
    first = int(np.random.default_rng(check_seed(seed)).integers(pts.shape[0]))
    chosen = np.empty(n, dtype=np.int64)
    chosen[0] = first
    dist = np.linalg.norm(pts - pts[first], axis=1)
    dist[first] = -1.0  # a chosen index is never chosen again (duplicates sit at distance 0)
    for i in range(1, n):
        nxt = int(np.argmax(dist))
        chosen[i] = nxt
        np.minimum(dist, np.linalg.norm(pts - pts[nxt], axis=1), out=dist)
        dist[chosen[: i + 1]] = -1.0
    return chosen


def covering_radius(points: npt.ArrayLike, landmarks: npt.ArrayLike) -> float:
    """Largest distance from a point to its nearest landmark: how well ``landmarks`` cover the data.

    Thesis: §2.1.2 (maxmin minimises this greedily).

    Parameters
    ----------
    points : (N, d) array.
    landmarks : 1-D integer indices into ``points`` (0..N-1, at least one).

    Returns
    -------
    float
        max over the points of the distance to the nearest landmark.

    Examples
    --------
    Four maxmin landmarks of 20 points on the unit circle leave every point within 0.76 of one:

    >>> from thesis_lib.datasets import noisy_circle
    >>> points = noisy_circle(20, noise=0.0, seed=0)
    >>> round(covering_radius(points, maxmin_landmarks(points, n=4, seed=0)), 6)
    0.759885
    """
    from scipy.spatial import cKDTree

    pts, e = scaled(as_points(points))  # squared distances must not overflow
    lm = check_indices(landmarks, pts.shape[0], "landmarks")
    d, _ = cKDTree(pts[lm]).query(pts)
    return float(np.ldexp(d.max(), -e))


def count_within(points: npt.ArrayLike, targets: npt.ArrayLike, radius: float) -> int:
    """Number of ``points`` within distance ``radius`` of at least one of ``targets``.

    Thesis: Figure 2.13 (landmarks near the intersection points of the two circles).

    Parameters
    ----------
    points : (N, d) array.
    targets : (T, d) array.
    radius : distance >= 0.

    Returns
    -------
    int
    """
    pts, tgt = as_points(points), as_points(targets, name="targets")
    if pts.shape[1] != tgt.shape[1]:
        raise ValueError(f"points live in R^{pts.shape[1]} but targets in R^{tgt.shape[1]}")
    radius = check_real(radius, "radius", minimum=0.0, finite=False)
    from scipy.spatial import cKDTree

    both, e = scaled(np.vstack([pts, tgt]))  # squared distances must not overflow
    d, _ = cKDTree(both[len(pts):]).query(both[: len(pts)])
    return int(np.count_nonzero(np.ldexp(d, -e) <= radius))

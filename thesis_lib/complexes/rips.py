"""The Vietoris–Rips complex R(X, ε) as a filtration (thesis Definition 2.11)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import MAX_SIMPLICES, as_distance_matrix, as_points, check_max_dim, check_radius, check_size
from ..filtration import Filtration
from ._flag import edges_within, flag_levels, matrix_edges
from .scaling import scaled, unscale_values

__all__ = ["rips", "check_edges"]


def check_edges(n: int, threshold: float, *, points: np.ndarray | None = None,
                matrix: np.ndarray | None = None) -> None:
    """Refuse up front an edge list of more than ``MAX_SIMPLICES`` edges (24 bytes each, plus the
    search's own arrays): 10⁵ points at ε = ∞ are 5·10⁹ edges, 6·10⁴ points in a unit cube at
    radius 10 are 1.8·10⁹.

    Only when n(n − 1)/2 exceeds the limit are the pairs within ``threshold`` counted (a k-d tree
    count for points, a blocked count for a matrix), so ordinary inputs pay nothing.

    Thesis: Definition 2.11 (the edges of R(X, ε): pairs at distance ≤ 2ε).

    Parameters
    ----------
    n : int
        The number of points.
    threshold : float
        The largest edge length kept (2ε, in the units of ``points`` or ``matrix``).
    points : numpy.ndarray, shape (n, d), optional
        The points (give this or ``matrix``).
    matrix : numpy.ndarray, shape (n, n), optional
        The distance matrix.

    Raises
    ------
    ValueError
        More than ``MAX_SIMPLICES`` edges, with the count and its size in GiB.
    """
    pairs = n * (n - 1) // 2
    if pairs <= MAX_SIMPLICES:
        return
    count = pairs
    if np.isfinite(threshold):
        if points is not None:
            from scipy.spatial import cKDTree

            tree = cKDTree(points)
            count = (int(tree.count_neighbors(tree, threshold * (1 + 1e-12))) - n) // 2
        else:
            count = 0
            for start in range(0, n, 1024):
                block = matrix[start : start + 1024]
                count += int(np.count_nonzero(block <= threshold))
            count = (count - n) // 2
    check_size(count, f"edges ({n:,} points at this radius, about {24 * count / 2**30:,.3g} GiB)")


def rips(points: npt.ArrayLike | None = None, max_radius: float = np.inf, max_dim: int = 2, *,
         distance_matrix: npt.ArrayLike | None = None) -> Filtration:
    """Vietoris–Rips filtration: σ enters at ε = (largest distance between its vertices) / 2.

    Thesis: Definition 2.11, R(X, ε) = {σ ⊆ X : diam σ ≤ 2ε}; a flag complex (§2.1.2).

    Parameters
    ----------
    points : (n, d) array of points (or give ``distance_matrix`` instead).
    max_radius : largest ε kept (simplices of diameter ≤ 2 · max_radius); ``inf`` keeps all.
    max_dim : largest simplex dimension built (>= 0).
    distance_matrix : (n, n) symmetric array of pairwise distances (keyword only).

    Returns
    -------
    Filtration
        Values are ε = diameter / 2 (GUDHI's Rips values are the diameters, 2ε; ripser's
        ``thresh`` is 2ε).  Vertices enter at 0; ``simplices[d]`` is in lexicographic order.
        Points of any magnitude are scaled by a power of two first (exactly), so coordinates near
        1e160 or 1e-170 give correct values.
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    if (points is None) == (distance_matrix is None):
        raise ValueError("give exactly one of points and distance_matrix")
    none = (np.empty((0, 2), np.int64), np.empty(0))
    if distance_matrix is not None:
        dm = as_distance_matrix(distance_matrix)
        n = dm.shape[0]
        if max_dim >= 1:
            check_edges(n, 2.0 * eps, matrix=dm)
        edges, lengths = matrix_edges(dm, 2.0 * eps) if max_dim >= 1 else none
    else:
        # work on points scaled by a power of two (no overflow of squared distances near 1e160,
        # no underflow near 1e-170); lengths scale back exactly
        pts, e = scaled(as_points(points))
        n = pts.shape[0]
        with np.errstate(over="ignore"):
            threshold = float(np.ldexp(2.0 * eps, e))
        if max_dim >= 1:
            check_edges(n, threshold, points=pts)
        edges, lengths = edges_within(pts, threshold) if max_dim >= 1 else none
        lengths = unscale_values(lengths, -e, "edge lengths")
    simplices, values = flag_levels(n, edges, lengths * 0.5, max_dim)
    return Filtration(simplices, values, validate=False, truncated_at=max_dim)

"""The Vietoris–Rips complex R(X, ε) as a filtration (thesis Definition 2.11)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import (
    MAX_SIMPLICES,
    Edges,
    Points,
    check_max_dim,
    check_radius,
    check_size,
    parse_rips_input,
    warn_user,
)
from ..homology.filtration import Filtration
from ._flag import edges_within, flag_levels, matrix_edges
from .scaling import unscale_values

__all__ = ["rips", "check_edges", "rips_edges", "rips_filtration"]


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


def rips_edges(source: Points | np.ndarray | Edges,
               max_radius: float) -> tuple[int, np.ndarray, np.ndarray, np.ndarray | None]:
    """The edges of R(X, ε), pairs at distance ≤ 2ε, with their lengths, from parsed input.

    Thesis: Definition 2.11 (an edge when the distance is at most 2ε).

    The one edge search behind :func:`rips` and the implicit engine's
    :func:`~thesis_lib.persistence.implicit.rips_graph`.  For points the distances are computed on
    ``source.scaled`` (the threshold scaled by the same power of two) and scaled back exactly, so
    coordinates near 1e160 or 1e-170 neither overflow nor underflow.

    Parameters
    ----------
    source : Points, numpy.ndarray or Edges
        A parsed point cloud, a checked dense distance matrix (``as_distance_matrix``) or a parsed
        sparse one (``parse_sparse_distances``).
    max_radius : float
        The checked scale ε (``check_radius``).

    Returns
    -------
    n : int
        The number of vertices.
    edges : numpy.ndarray of int64, shape (m, 2)
        Pairs i < j in lexicographic order.
    lengths : numpy.ndarray of float64, shape (m,)
        Their values in the units of the input: the distance, or the larger of its two vertices'
        births when that is larger.
    births : numpy.ndarray of float64, shape (n,), or None
        The vertices' births, a distance matrix's diagonal (as ripser and giotto-ph read it), inf
        for a vertex born above 2ε (not in the complex, as in R(X, ε) for ε ≤ max_radius; ripser.py
        reports such a vertex as a class born above its threshold); None when every vertex is born
        at 0.

    Warns
    -----
    UserWarning
        An entry below one of its vertices' diagonal entries (read as that birth).

    Raises
    ------
    ValueError
        More than ``MAX_SIMPLICES`` edges (:func:`check_edges`), or lengths beyond float64's range
        once scaled back.
    """
    threshold = 2.0 * max_radius
    if isinstance(source, Points):
        with np.errstate(over="ignore"):
            scaled_threshold = float(np.ldexp(threshold, source.exponent))
        check_edges(source.n, scaled_threshold, points=source.scaled)
        edges, lengths = edges_within(source.scaled, scaled_threshold)
        return source.n, edges, unscale_values(lengths, -source.exponent, "edge lengths"), None
    if isinstance(source, Edges):
        n, edges, lengths, diagonal = source.n, source.edges, source.lengths, source.births
    else:
        n = int(source.shape[0])
        check_edges(n, threshold, matrix=source)
        (edges, lengths), diagonal = matrix_edges(source, threshold), np.diagonal(source)
    if not diagonal.any():
        keep = lengths <= threshold
        return n, edges[keep], lengths[keep], None
    ends = np.maximum(diagonal[edges[:, 0]], diagonal[edges[:, 1]])
    below = int(np.count_nonzero(lengths < ends))
    if below:
        warn_user(f"distance_matrix: {below} entries are below the diagonal entry (the birth) of one of their "
                  "vertices; an edge cannot enter before its vertices, so they are read as that birth "
                  "(ripser.py keeps them as they are and reports another barcode)")
    lengths = np.maximum(lengths, ends)
    keep = lengths <= threshold
    return n, edges[keep], lengths[keep], np.where(diagonal <= threshold, diagonal, np.inf)


def rips_filtration(source: Points | np.ndarray, max_radius: float, max_dim: int) -> Filtration:
    """:func:`rips` on parsed input: the Vietoris–Rips filtration, values ε = diameter / 2.

    Thesis: Definition 2.11, R(X, ε) = {σ ⊆ X : diam σ ≤ 2ε}; a flag complex (§2.1.2).

    Parameters
    ----------
    source : Points or numpy.ndarray
        A parsed point cloud or a checked distance matrix (``parse_rips_input``).
    max_radius : float
        The checked scale ε.
    max_dim : int
        The checked largest simplex dimension (>= 0).

    Returns
    -------
    Filtration
        As :func:`rips`.
    """
    n, edges, lengths, births = rips_edges(source, max_radius)
    if max_dim < 1:
        edges, lengths = edges[:0], lengths[:0]
    simplices, values = flag_levels(n, edges, lengths * 0.5, max_dim, None if births is None else births * 0.5)
    if births is not None and np.isinf(births).any():  # vertices born above 2ε are not in the complex
        present = np.isfinite(births)
        simplices[0], values[0] = simplices[0][present], values[0][present]
    return Filtration(simplices, values, validate=False, truncated_at=max_dim)


def rips(points: npt.ArrayLike | None = None, *, max_radius: float = np.inf, max_dim: int = 2,
         distance_matrix: npt.ArrayLike | None = None) -> Filtration:
    """Vietoris–Rips filtration: σ enters at ε = (largest distance between its vertices) / 2.

    Thesis: Definition 2.11, R(X, ε) = {σ ⊆ X : diam σ ≤ 2ε}; a flag complex (§2.1.2).

    Parameters
    ----------
    points : (n, d) array of points (or give ``distance_matrix`` instead).  Duplicate points are
        allowed: each row is a vertex, joined to its copies at ε = 0 (their H0 bars have length
        zero and are left out of barcodes).
    max_radius : largest ε kept (simplices of diameter ≤ 2 · max_radius); ``inf`` keeps all.
    max_dim : largest simplex dimension built (>= 0).
    distance_matrix : (n, n) symmetric array of pairwise distances (keyword only).  A non-zero
        diagonal gives the vertices' births, as ripser.py reads it (see
        :func:`~thesis_lib.persistence.rips_persistence`).

    Returns
    -------
    Filtration
        Values are ε = diameter / 2 (GUDHI's Rips values are the diameters, 2ε; ripser's
        ``thresh`` is 2ε).  Vertices enter at 0 (or their diagonal entry / 2); ``simplices[d]``
        is in lexicographic order.
        Points of any magnitude are scaled by a power of two first (exactly), so coordinates near
        1e160 or 1e-170 give correct values; the edges are those of ``rips_edges``, the same
        as the implicit engine's (:func:`~thesis_lib.persistence.rips_persistence`).

    Warns
    -----
    UserWarning
        ``points`` square, symmetric, with a zero diagonal and no negative entry: it looks like a
        distance matrix but is read as n points in R^n (ripser.py warns too); give a distance
        matrix as ``distance_matrix=``.

    Examples
    --------
    >>> K = rips([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], max_radius=1.0)
    >>> [len(s) for s in K.simplices]
    [3, 3, 1]
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    return rips_filtration(parse_rips_input(points, distance_matrix), eps, max_dim)

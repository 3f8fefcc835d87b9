"""Geometric realization of an abstract simplicial complex on the moment curve (Theorem 2.6).

Vertex i goes to m(tᵢ) = (tᵢ, tᵢ², …, tᵢ^{2d+1}) in R^{2d+1}.  Any 2d + 2 distinct points of the
moment curve are affinely independent (a Vandermonde determinant), so for two simplices σ, τ of
dimension ≤ d the points of σ ∪ τ span a simplex, and conv σ ∩ conv τ = conv(σ ∩ τ): the images
fit together as Definition 2.3 asks.  :func:`realization_failures` checks exactly that, with exact
integer arithmetic.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Mapping, Sequence
from fractions import Fraction

import numpy as np
import numpy.typing as npt

from .._validate import as_points

__all__ = [
    "moment_curve",
    "realization_failures",
    "full_skeleton",
    "affine_dimension",
    "barycentric_coordinates",
    "clockwise_triangles",
]


def moment_curve(n_vertices: int, dimension: int) -> list[tuple[int, ...]]:
    """Points m(t) = (t, t², …, t^dimension) for t = 1, …, n_vertices (exact integers).

    Thesis: Theorem 2.6 (a realization in R^{2d+1}: take dimension = 2d + 1).

    Parameters
    ----------
    n_vertices : int
        The number of vertices, ≥ 1.
    dimension : int
        The dimension of the ambient space, ≥ 1.

    Returns
    -------
    list of tuple of int
        One point per vertex.

    Raises
    ------
    ValueError
        A count below 1.
    """
    if int(n_vertices) < 1 or int(dimension) < 1:
        raise ValueError(f"need n_vertices ≥ 1 and dimension ≥ 1, got {n_vertices} and {dimension}")
    return [tuple(t**e for e in range(1, int(dimension) + 1)) for t in range(1, int(n_vertices) + 1)]


def _affine_rank(points: Sequence[Sequence[int]]) -> int:
    rows = [[Fraction(a - b) for a, b in zip(p, points[0])] for p in points[1:]]
    rank, col = 0, 0
    n_cols = len(points[0]) if points else 0
    while rank < len(rows) and col < n_cols:
        pivot = next((r for r in range(rank, len(rows)) if rows[r][col] != 0), None)
        if pivot is None:
            col += 1
            continue
        rows[rank], rows[pivot] = rows[pivot], rows[rank]
        for r in range(rank + 1, len(rows)):
            f = rows[r][col] / rows[rank][col]
            if f:
                rows[r] = [a - f * b for a, b in zip(rows[r], rows[rank])]
        rank, col = rank + 1, col + 1
    return rank


def realization_failures(simplices: Iterable[Sequence[int]], points: Sequence[Sequence[int]]) -> int:
    """Pairs of simplices whose vertices together are affinely dependent in the given placement.

    Thesis: Theorem 2.6 and Definition 2.3 (two simplices meet in a common face).

    When the vertices of σ ∪ τ are affinely independent they span one simplex of which σ and τ are
    faces, so conv σ ∩ conv τ = conv(σ ∩ τ); a placement with no failure is a geometric realization.
    The test is sufficient, not necessary: a failing pair need not cross.
    Each simplex is also checked on its own (σ = τ).

    Parameters
    ----------
    simplices : iterable of sequences of int
        The simplices (vertex numbers index ``points``).
    points : sequence of sequences of int
        The exact coordinates of the vertices.

    Returns
    -------
    int
        The number of unordered pairs {σ, τ} (σ = τ included) whose union is affinely dependent.
    """
    cells = sorted({tuple(sorted(int(v) for v in s)) for s in simplices})
    failures = 0
    for a, b in itertools.combinations_with_replacement(cells, 2):
        union = sorted(set(a) | set(b))
        if _affine_rank([points[v] for v in union]) != len(union) - 1:
            failures += 1
    return failures


def full_skeleton(n_vertices: int, *, max_dim: int) -> list[tuple[int, ...]]:
    """Every simplex of dimension 0, …, max_dim on the vertices 0, …, n_vertices − 1.

    Thesis: Theorem 2.6 (the complexes of dimension d tested on the moment curve).

    The max_dim-skeleton of the (n_vertices − 1)-simplex: for max_dim = 1 the complete graph.

    Parameters
    ----------
    n_vertices : int
        The number of vertices, ≥ 1.
    max_dim : int
        The largest simplex dimension, ≥ 0.

    Returns
    -------
    list of tuple of int
        The simplices by dimension, each dimension in lexicographic order.

    Raises
    ------
    ValueError
        A count below 1 or a negative dimension.

    Examples
    --------
    >>> full_skeleton(3, max_dim=1)
    [(0,), (1,), (2,), (0, 1), (0, 2), (1, 2)]
    >>> len(full_skeleton(7, max_dim=2))
    63
    """
    if int(n_vertices) < 1 or int(max_dim) < 0:
        raise ValueError(f"need n_vertices ≥ 1 and max_dim ≥ 0, got {n_vertices} and {max_dim}")
    return [s for k in range(1, int(max_dim) + 2) for s in itertools.combinations(range(int(n_vertices)), k)]


def affine_dimension(points: npt.ArrayLike) -> int:
    """The dimension of the affine hull of a point set (the rank of the differences x_i − x_0).

    Thesis: Definition 2.1 (x_1 − x_0, …, x_p − x_0 linearly independent: the hull is a p-simplex).

    Floating point: numpy's SVD rank with its default tolerance.

    Parameters
    ----------
    points : array_like, shape (n, d)
        At least one point.

    Returns
    -------
    int
        0 for one point; n − 1 exactly when the points are affinely independent.

    Raises
    ------
    ValueError
        An empty or non-finite point set.

    Examples
    --------
    >>> affine_dimension([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]])
    1
    >>> affine_dimension([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    2
    """
    pts = as_points(points)
    return int(np.linalg.matrix_rank(pts[1:] - pts[0])) if len(pts) > 1 else 0


def barycentric_coordinates(simplex: npt.ArrayLike, points: npt.ArrayLike) -> np.ndarray:
    """Barycentric coordinates of points with respect to a full-dimensional simplex of R^d.

    Thesis: Definition 2.1 (a point of a simplex is a convex combination of its vertices) and
    Definition 2.3 (where two simplices meet; Figure 2.2 (b)).

    Parameters
    ----------
    simplex : array_like, shape (d + 1, d)
        The vertices, affinely independent.
    points : array_like, shape (n, d)
        The points.

    Returns
    -------
    numpy.ndarray, shape (n, d + 1)
        Row i holds the weights λ of point i, Σλ = 1 and Σλ_j v_j = x_i; a zero weight puts the
        point on the hyperplane of the opposite facet.

    Raises
    ------
    ValueError
        Shapes that do not fit, or a degenerate simplex.

    Examples
    --------
    >>> barycentric_coordinates([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]], [[1.0, 0.0], [0.5, 0.5]]).round(3).tolist()
    [[0.5, 0.5, 0.0], [0.5, 0.25, 0.25]]
    """
    vertices, pts = as_points(simplex, name="simplex"), as_points(points)
    d = vertices.shape[1]
    if vertices.shape[0] != d + 1 or pts.shape[1] != d:
        raise ValueError(f"need d + 1 vertices in R^d and points in R^d, got shapes {vertices.shape} and {pts.shape}")
    if affine_dimension(vertices) != d:
        raise ValueError("the simplex is degenerate (its vertices are affinely dependent)")
    n = pts.shape[0]
    return np.linalg.solve(np.vstack([vertices.T, np.ones(d + 1)]), np.vstack([pts.T, np.ones(n)])).T


def clockwise_triangles(triangles: Iterable[Sequence[int]], chart: Mapping[tuple[int, ...], Sequence]) -> int:
    """How many oriented triangles run clockwise in a planar picture.

    Thesis: Example 2.21 and Figure 2.7 (the clockwise orientation of each triangle of RP²).

    Parameters
    ----------
    triangles : iterable of sequence of int
        Triangles whose vertex order is their orientation.
    chart : mapping of tuple to sequence of (float, float)
        For each triangle (its sorted vertices), the positions of its corners in sorted vertex
        order (a vertex may sit at different places in different triangles, as in a disc picture
        with glued sides), as :func:`~thesis_lib.morse.rp2_chart` returns them.

    Returns
    -------
    int
        The number of triangles whose vertices, in their order, turn clockwise.

    Raises
    ------
    ValueError
        A triangle that is not three vertices or is missing from the chart.

    Examples
    --------
    >>> chart = {(0, 1, 2): [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]}
    >>> clockwise_triangles([(0, 2, 1)], chart), clockwise_triangles([(0, 1, 2)], chart)
    (1, 0)
    """
    count = 0
    for tri in triangles:
        key = tuple(sorted(int(v) for v in tri))
        if len(key) != 3 or key not in chart:
            raise ValueError(f"{tuple(tri)} is not a triangle of the chart")
        corners = dict(zip(key, chart[key]))
        a, b, c = (np.array(corners[int(v)]) for v in tri)
        turn = (b - a)[0] * (c - a)[1] - (b - a)[1] * (c - a)[0]
        count += int(turn < 0)
    return count

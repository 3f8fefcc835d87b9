"""Geometric realization of an abstract simplicial complex on the moment curve (Theorem 2.6).

Vertex i goes to m(tᵢ) = (tᵢ, tᵢ², …, tᵢ^{2d+1}) in R^{2d+1}.  Any 2d + 2 distinct points of the
moment curve are affinely independent (a Vandermonde determinant), so for two simplices σ, τ of
dimension ≤ d the points of σ ∪ τ span a simplex, and conv σ ∩ conv τ = conv(σ ∩ τ): the images
fit together as Definition 2.3 asks.  :func:`realization_failures` checks exactly that, with exact
integer arithmetic.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Sequence
from fractions import Fraction

__all__ = ["moment_curve", "realization_failures"]


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

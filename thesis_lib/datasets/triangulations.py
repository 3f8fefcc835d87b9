"""Small triangulated spaces with known homology: RP², torus, Klein bottle, dunce hat, spheres.

Each function returns a list of facets (vertex tuples in ascending order, DESIGN.md convention),
except ``rp2(oriented=True)``, which keeps the thesis's vertex orders.
"""

from __future__ import annotations

import itertools

import numpy as np

from .._validate import check_int

__all__ = ["rp2", "RP2_LABELS", "torus", "klein_bottle", "dunce_hat", "sphere"]

#: Vertex names of Figure 2.7: vertex ``i`` of :func:`rp2` is ``RP2_LABELS[i]``.
RP2_LABELS = "abcdef"

# Columns of M_2 in Example 2.21, in the thesis's order; each name is the clockwise-oriented
# triangle [x0, x1, x2] of Figure 2.7 (e.g. ∂[a, f, c] = [f, c] − [a, c] + [a, f]).
_RP2_ORIENTED = ("abd", "adf", "afc", "bcd", "ced", "cae", "abe", "bfe", "bcf", "def")


def rp2(*, oriented: bool = False) -> list[tuple[int, ...]]:
    """The 6-vertex triangulation of the real projective plane (10 triangles), a..f = 0..5.

    Thesis: Example 2.21 / Figure 2.7 (columns abd, adf, afc, bcd, ced, cae, abe, bfe, bcf, def).

    Parameters
    ----------
    oriented : bool, default False
        Keep the thesis's vertex order in each triangle, i.e. the clockwise orientation of
        Figure 2.7 that produces the signs of M_2; otherwise the vertices are sorted.

    Returns
    -------
    list of tuple
        The 10 triangles in the order of the columns of M_2.
    """
    tris = [tuple(RP2_LABELS.index(c) for c in name) for name in _RP2_ORIENTED]
    return tris if oriented else [tuple(sorted(t)) for t in tris]


def torus() -> list[tuple[int, ...]]:
    """Möbius' 7-vertex torus (the Császár torus): triangles {i, i+1, i+3} and {i, i+2, i+3} mod 7.

    Thesis: §2.4 / Figure 2.16 (the torus has β = 1, 2, 1; here H_0 = Z, H_1 = Z², H_2 = Z).
    Every pair of the 7 vertices is an edge (21 edges, 14 triangles).

    Returns
    -------
    list of tuple
        The 14 triangles, sorted.
    """
    tris = [(i, (i + 1) % 7, (i + 3) % 7) for i in range(7)]
    tris += [(i, (i + 2) % 7, (i + 3) % 7) for i in range(7)]
    return sorted(tuple(sorted(t)) for t in tris)


def _grid_surface(n: int, m: int, twist: bool) -> list[tuple[int, ...]]:
    """n × m grid of squares, each split along a diagonal; sides glued to a torus or Klein bottle."""

    def vid(i: int, j: int) -> int:
        if i == n:  # right side glued to the left side, reversed for the Klein bottle
            i, j = 0, (-j if twist else j)
        return i * m + j % m

    tris = []
    for i in range(n):
        for j in range(m):
            a, b, c, d = vid(i, j), vid(i + 1, j), vid(i, j + 1), vid(i + 1, j + 1)
            tris += [tuple(sorted((a, b, d))), tuple(sorted((a, c, d)))]
    return sorted(tris)


def klein_bottle(*, n: int = 4, m: int = 4) -> list[tuple[int, ...]]:
    """A triangulated Klein bottle: an ``n × m`` grid of split squares with one side pair reversed.

    Thesis: §2.2.1, "Arbitrary Coefficients" (H_1 = Z ⊕ Z_2 has torsion; over Z_2, β = 1, 2, 1).

    Parameters
    ----------
    n, m : int, default 4
        Squares along the glued-with-a-twist direction and along the other; both at least 3, so
        that the complex is simplicial (``n * m`` vertices, ``2 n m`` triangles).

    Returns
    -------
    list of tuple
        The triangles, sorted.

    Raises
    ------
    ValueError
        ``n`` or ``m`` not an integer ≥ 3.
    """
    for name, v in (("n", n), ("m", m)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 3:
            raise ValueError(f"{name} must be an integer >= 3 for a simplicial Klein bottle, got {v!r}")
    return _grid_surface(int(n), int(m), twist=True)


def dunce_hat() -> list[tuple[int, ...]]:
    """An 8-vertex, 17-triangle dunce hat: contractible, yet no edge is free (not collapsible).

    Thesis: §4.2.2 / §4.2.6 (collapses and optimal discrete Morse functions; the dunce hat is the
    classic contractible complex that admits no collapse).  Vertices 0, 1, 2 lie on the glued edge
    0–1–2–0 (each of its 3 edges is in 3 triangles); every other edge is in exactly 2 triangles.
    Found by link-condition edge contractions of a subdivided triangle with sides a, a, a⁻¹ glued.

    Returns
    -------
    list of tuple
        The 17 triangles, sorted.
    """
    return [
        (0, 1, 3), (0, 1, 4), (0, 1, 7), (0, 2, 4), (0, 2, 5), (0, 2, 6), (0, 3, 7), (0, 5, 6),
        (1, 2, 3), (1, 2, 5), (1, 2, 6), (1, 4, 5), (1, 6, 7), (2, 3, 4), (3, 4, 7), (4, 5, 6),
        (4, 6, 7),
    ]


def sphere(n: int) -> list[tuple[int, ...]]:
    """The n-sphere as the boundary of the (n+1)-simplex on vertices 0..n+1 (n + 2 facets).

    Thesis: Definition 2.1 (a simplex and its faces); H_0 = H_n = Z, all else 0 (H_0 = Z² for n = 0).

    Parameters
    ----------
    n : int
        The dimension, n ≥ 0.

    Returns
    -------
    list of tuple
        The n + 2 facets, the n-faces of the simplex on 0..n+1, in lexicographic order.

    Raises
    ------
    ValueError
        ``n`` not a non-negative integer.
    """
    n = check_int(n, "n", minimum=0)
    return [tuple(c) for c in itertools.combinations(range(int(n) + 2), int(n) + 1)]

"""Geometry of the simplices of a triangulated hypersurface: hyperareas, aspects, the triangles'
edges and angles (one compiled pass), ridges and boundary vertices, and the exact integer arithmetic
that recomputes ill-conditioned simplices (thesis §3.3).

Conditioning.  The float formulas for hyperareas, corner dot products, cotangents and area
gradients lose about log10(aspect) to 2·log10(aspect) digits on a simplex of aspect
L^n / (n! · hyperarea) (L its longest edge; 2/√3 for the equilateral triangle).  Simplices of
aspect above :data:`thesis_lib.curvature.validate.ASPECT_BOUND` are recomputed from the exact values
of their coordinates (each float is an integer times a power of two: dot products, squared edges,
Gram determinants and adjugates in exact integer arithmetic, one rounding before each square root).
"""

from __future__ import annotations

from math import factorial, sqrt
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from .._core import triangle_geometry as _triangle_core

__all__ = [
    "DEGENERATE_RTOL",
    "TriangleGeometry",
    "boundary_mask",
    "boundary_vertices",
    "checked_triangle_geometry",
    "exact_edges",
    "exact_gram",
    "exact_hyperarea",
    "exact_triangle_geometry",
    "ridges",
    "simplex_aspects",
    "simplex_hyperareas",
    "triangle_geometry",
]


#: A simplex whose hyperarea is below ``DEGENERATE_RTOL * (longest edge) ** n`` counts as degenerate.
DEGENERATE_RTOL = 1e-10


class TriangleGeometry(NamedTuple):
    """Per-corner data of a triangle mesh, computed once during validation (n = 2).

    Corner k of a face is its k-th vertex; ``edge_sq[k]`` is the squared length of the edge
    opposite corner k and ``dot[k]`` the dot product of the two edge vectors leaving corner k.
    Arrays are ``(3, m)`` (corner-major) so that each row is contiguous.
    """

    dot: np.ndarray  #: (3, m)
    edge_sq: np.ndarray  #: (3, m)
    twice_area: np.ndarray  #: (m,)
    coords: np.ndarray  #: (3 corners, 3 coordinates, m) vertex coordinates
    edge_lo: np.ndarray  #: (m, 3) smaller vertex of the edge opposite corner k (raveled: ridge 3t + k)
    edge_hi: np.ndarray  #: (m, 3) larger vertex of that edge


def triangle_geometry(v: np.ndarray, s: np.ndarray) -> TriangleGeometry:
    """Corner dot products, squared opposite edge lengths and twice the areas of triangles in R^3.

    One compiled pass over the triangles (C++, ``src/triangle_geometry.cpp``); no validation.
    Thesis: Theorem 3.18 and §3.3.2 (the Gram matrices and corner cotangents of triangles).

    Parameters
    ----------
    v : ndarray of float64, shape (nv, 3)
        Vertex coordinates.
    s : ndarray of int64, shape (m, 3)
        Triangles, vertex indices in range (trusted).

    Returns
    -------
    TriangleGeometry
        ``dot`` and ``edge_sq`` (3, m), ``twice_area`` (m,), the corner ``coords`` (3, 3, m), and
        ``edge_lo``, ``edge_hi`` (m, 3), the ends of the edge opposite each corner.
    """
    return checked_triangle_geometry(v, s)[0]


def checked_triangle_geometry(v: np.ndarray, s: np.ndarray) -> tuple[TriangleGeometry, int, int, int, float]:
    """:func:`triangle_geometry` with what the kernel found on the way, for :func:`validate_mesh`.

    Thesis: §3.3.2 (the triangles' Gram matrices); no validation.

    Parameters
    ----------
    v : ndarray of float64, shape (nv, 3)
        Vertex coordinates.
    s : ndarray of int64, shape (m, 3)
        Triangles, vertex indices in range (trusted).

    Returns
    -------
    geometry : TriangleGeometry
        As :func:`triangle_geometry`.
    repeated, degenerate : int
        The first triangle with a repeated vertex and the first degenerate one (−1 if none).
    n_degenerate : int
        How many triangles are degenerate (twice the area below ``DEGENERATE_RTOL`` · L²).
    longest_sq : float
        The longest squared edge.
    """
    m = len(s)
    dot, sq = np.empty((3, m)), np.empty((3, m))
    twice, pts = np.empty(m), np.empty((3, 3, m))
    lo, hi = np.empty((m, 3), dtype=np.int64), np.empty((m, 3), dtype=np.int64)
    checks = _triangle_core.triangle_kernel(np.ascontiguousarray(v, dtype=np.float64),
                                            np.ascontiguousarray(s, dtype=np.int64),
                                            _triangle_core.Corners(dot, sq, twice, pts, lo, hi), DEGENERATE_RTOL)
    return (TriangleGeometry(dot, sq, twice, pts, lo, hi), *checks)


def simplex_hyperareas(vertices: np.ndarray, simplices: np.ndarray) -> np.ndarray:
    """Hyperarea of each simplex, ``sqrt(det G) / n!`` with ``G`` the Gram matrix of its edge vectors.

    Thesis: Theorem 3.18 (the Gram determinant G^2 = det(G-hat), G = n! A).
    No validation: use on arrays that passed :func:`validate_mesh`.

    Parameters
    ----------
    vertices : ndarray of float64, shape (nv, d)
        Vertex coordinates.
    simplices : ndarray of int, shape (m, n + 1)
        Simplices (vertex indices in range), d >= n.

    Returns
    -------
    ndarray of float64, shape (m,)
        The n-dimensional hyperarea of each simplex (1 for n = 0).

    Examples
    --------
    Each face of the octahedron is equilateral of side √2, of area √3/2:

    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> np.round(simplex_hyperareas(octahedron, faces), 6).tolist()
    [0.866025, 0.866025, 0.866025, 0.866025, 0.866025, 0.866025, 0.866025, 0.866025]
    """
    p = vertices[simplices]
    n = simplices.shape[1] - 1
    if n == 0:
        return np.ones(len(simplices))
    x = p[:, 1:, :] - p[:, :1, :]
    if n == 2 and p.shape[2] == 3:
        c = np.cross(x[:, 0], x[:, 1])
        return 0.5 * np.sqrt(np.einsum("ij,ij->i", c, c))
    gram = np.einsum("mia,mja->mij", x, x)
    return np.sqrt(np.clip(np.linalg.det(gram), 0.0, None)) / factorial(n)


def exact_edges(p: np.ndarray) -> tuple[list[list[int]], int]:
    """The edge vectors p_i − p_0 (i = 1..n) of one simplex, exactly, as integers times 2^-e.

    Thesis: Theorem 3.18 (the edge vectors x_i = p_i − q of the Gram matrix).
    Every float is an integer over a power of two; e is the largest such exponent among the
    coordinates, so the differences (and every polynomial in them) are exact Python integers.

    Parameters
    ----------
    p : ndarray of float64, shape (n + 1, d)
        The simplex's vertices.

    Returns
    -------
    x : list of n lists of d ints
        2^e (p_i − p_0), exactly.
    e : int
        The exponent.
    """
    ratios = [[float(x).as_integer_ratio() for x in row] for row in p]
    e = max(den.bit_length() - 1 for row in ratios for _, den in row)
    ints = [[num << (e - den.bit_length() + 1) for num, den in row] for row in ratios]
    return [[a - b for a, b in zip(row, ints[0])] for row in ints[1:]], e


def _int_det(m: list[list[int]]) -> int:
    """Determinant of a square integer matrix, exactly (Bareiss' fraction-free elimination)."""
    m = [row[:] for row in m]
    n, sign, prev = len(m), 1, 1
    for k in range(n - 1):
        if m[k][k] == 0:
            swap = next((r for r in range(k + 1, n) if m[r][k] != 0), None)
            if swap is None:
                return 0
            m[k], m[swap] = m[swap], m[k]
            sign = -sign
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                m[i][j] = (m[i][j] * m[k][k] - m[i][k] * m[k][j]) // prev
        prev = m[k][k]
    return sign * m[n - 1][n - 1] if n else 1


def exact_gram(x: list[list[int]]) -> tuple[list[list[int]], list[list[int]], int]:
    """Gram matrix G = XᵀX of integer edge vectors, its adjugate and its determinant, exactly.

    Thesis: Theorem 3.18 (G = XᵀX, ∇ sqrt(det G) = X adj(G) / sqrt(det G)).

    Parameters
    ----------
    x : list of n lists of d ints
        Edge vectors (as from :func:`exact_edges`).

    Returns
    -------
    g, adj : list of n lists of n ints
        G and its adjugate (cofactors; Bareiss elimination for n >= 3).
    det : int
        det G (positive for a non-degenerate simplex).
    """
    n = len(x)
    g = [[sum(a * b for a, b in zip(x[i], x[j])) for j in range(n)] for i in range(n)]
    if n == 1:
        return g, [[1]], g[0][0]
    if n == 2:
        a, b, c = g[0][0], g[0][1], g[1][1]
        return g, [[c, -b], [-b, a]], a * c - b * b
    adj = [[(-1) ** (i + j) * _int_det([[g[r][c] for c in range(n) if c != i] for r in range(n) if r != j])
            for j in range(n)] for i in range(n)]
    return g, adj, sum(g[0][k] * adj[k][0] for k in range(n))


def exact_hyperarea(p: np.ndarray) -> float:
    """Hyperarea sqrt(det G) / n! of one simplex, with det G in exact integer arithmetic, rounded once.

    Thesis: Theorem 3.18 (the hyperarea from the Gram determinant).

    Parameters
    ----------
    p : ndarray of float64, shape (n + 1, d)
        The simplex's vertices.

    Returns
    -------
    float
        Its n-dimensional hyperarea.
    """
    x, e = exact_edges(p)
    n = len(x)
    return sqrt(exact_gram(x)[2] / (1 << (2 * n * e))) / factorial(n)


def exact_triangle_geometry(tri: TriangleGeometry, t: int) -> None:
    """Overwrite triangle t's corner dots, squared edges and twice its area with their values computed
    from the exact coordinates (each correctly rounded; twice the area within an ulp).

    Thesis: §3.3.2 (corner cotangents of an ill-conditioned triangle, recomputed exactly).

    Parameters
    ----------
    tri : TriangleGeometry
        The triangles' geometry, changed in place.
    t : int
        The triangle to recompute.
    """
    (x1, x2), e = exact_edges(tri.coords[:, :, t])  # p1 − p0, p2 − p0
    x3 = [b - a for a, b in zip(x1, x2)]  # p2 − p1
    dot = lambda u, w: sum(a * b for a, b in zip(u, w))  # noqa: E731
    scale = 1 << (2 * e)
    sq = [dot(x3, x3), dot(x2, x2), dot(x1, x1)]  # opposite corners 0, 1, 2
    d0 = dot(x1, x2)
    dots = [d0, sq[2] - d0, sq[1] - d0]  # (p1 − p0)·(p2 − p0), (p2 − p1)·(p0 − p1), (p0 − p2)·(p1 − p2)
    for k in range(3):
        tri.edge_sq[k, t] = sq[k] / scale
        tri.dot[k, t] = dots[k] / scale
    tri.twice_area[t] = sqrt((sq[1] * sq[2] - d0 * d0) / (scale * scale))


def simplex_aspects(vertices: npt.ArrayLike, simplices: npt.ArrayLike) -> np.ndarray:
    """Aspect L^n / (n! · hyperarea) of each simplex (L its longest edge): how ill-conditioned it is.

    Thesis: §3.3 (the simplices of a triangulated hypersurface; the formulas of Theorem 3.18).
    The equilateral triangle has 2/√3, a needle or a cap about (longest edge) / (smallest height);
    above :data:`ASPECT_BOUND` the curvature functions switch to exact arithmetic (module
    docstring).  No validation: use on arrays that passed :func:`validate_mesh`.

    Parameters
    ----------
    vertices : array_like, shape (nv, d)
        Vertex coordinates.
    simplices : array_like of int, shape (m, n + 1)
        Non-degenerate simplices, n >= 1 (trusted).

    Returns
    -------
    ndarray of float64, shape (m,)
        The aspect of each simplex (1 for a segment).
    """
    v = np.asarray(vertices, dtype=np.float64)
    s = np.asarray(simplices, dtype=np.int64)
    n = s.shape[1] - 1
    p = v[s]
    longest = np.zeros(len(s))
    for i in range(1, n + 1):
        for j in range(i):
            e = p[:, i] - p[:, j]
            np.maximum(longest, np.einsum("ma,ma->m", e, e), out=longest)
    return np.sqrt(longest) ** n / (factorial(n) * simplex_hyperareas(v, s))


def _ridge_keys(simplices: np.ndarray, nv: int) -> tuple[np.ndarray, bool]:
    """One key per (simplex, omitted vertex) ridge; ``True`` if the keys are integers."""
    m, w = simplices.shape
    if w == 3:
        a, b, c = simplices[:, 0], simplices[:, 1], simplices[:, 2]
        lo = np.concatenate([np.minimum(b, c), np.minimum(a, c), np.minimum(a, b)])
        hi = np.concatenate([np.maximum(b, c), np.maximum(a, c), np.maximum(a, b)])
        if float(nv) ** 2 < 2.0**62:
            return lo * nv + hi, True
        allr = np.stack([lo, hi], axis=1)
    else:  # rows sorted once: dropping a column keeps them sorted
        ss = np.sort(simplices, axis=1)
        allr = np.concatenate([np.delete(ss, i, axis=1) for i in range(w)])
    if w == 1 or float(nv) ** (w - 1) < 2.0**62:
        key = allr[:, 0].astype(np.int64)
        for j in range(1, w - 1):
            key = key * nv + allr[:, j]
        return key, True
    allr = np.ascontiguousarray(allr)
    return allr.view(np.dtype((np.void, allr.dtype.itemsize * (w - 1)))).ravel(), False


def _decode(keys: np.ndarray, nv: int, width: int) -> np.ndarray:
    out = np.empty((len(keys), width), dtype=np.int64)
    k = keys.astype(np.int64)
    for j in range(width - 1, -1, -1):
        k, out[:, j] = np.divmod(k, nv)
    return out


def _ridge_counts(simplices: np.ndarray, nv: int) -> tuple[np.ndarray, np.ndarray, bool]:
    key, integral = _ridge_keys(simplices, nv)
    ks = np.sort(key)
    start = np.ones(len(ks), dtype=bool)
    start[1:] = ks[1:] != ks[:-1]
    first = np.flatnonzero(start)
    counts = np.diff(np.append(first, len(ks)))
    return ks[first], counts, integral


def _rows(keys: np.ndarray, nv: int, width: int, integral: bool) -> np.ndarray:
    if integral:
        return _decode(keys, nv, width)
    return np.frombuffer(np.ascontiguousarray(keys).tobytes(), dtype=np.int64).reshape(-1, width)


def ridges(simplices: npt.ArrayLike, nv: int) -> tuple[np.ndarray, np.ndarray]:
    """The ridges ((n-1)-faces) of the top simplices and how many top simplices hold each.

    Thesis: §3.3 (a triangulated hypersurface: every ridge in one or two top simplices).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        Top simplices, vertex indices in ``range(nv)`` (trusted).
    nv : int
        Number of vertices.

    Returns
    -------
    ridges : ndarray of int64, shape (r, n)
        The distinct ridges, rows sorted.
    counts : ndarray of int, shape (r,)
        How many top simplices hold each ridge.
    """
    simplices = np.asarray(simplices, dtype=np.int64)
    keys, counts, integral = _ridge_counts(simplices, nv)
    return _rows(keys, nv, simplices.shape[1] - 1, integral), counts


def boundary_vertices(simplices: npt.ArrayLike, n_vertices: int) -> np.ndarray:
    """Boolean mask of the vertices on a boundary ridge (a ridge lying in one top simplex).

    Thesis: §3.1.2 (Theorem 3.5: surfaces with boundary carry a boundary term).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        Top simplices of a validated mesh (trusted, as in ``ridges``).
    n_vertices : int
        Number of vertices: the length of the mask.

    Returns
    -------
    ndarray of bool, shape (n_vertices,)
        True at the vertices of the ridges that lie in exactly one top simplex.

    Examples
    --------
    A fan of four triangles around vertex 0: the rim is boundary, the centre is not:

    >>> import numpy as np
    >>> boundary_vertices(np.array([[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]), 5).tolist()
    [False, True, True, True, True]
    """
    r, counts = ridges(np.asarray(simplices, dtype=np.int64), n_vertices)
    mask = np.zeros(n_vertices, dtype=bool)
    mask[r[counts == 1].ravel()] = True
    return mask


def boundary_mask(s: np.ndarray, nv: int, tri: TriangleGeometry | None) -> np.ndarray:
    """Which vertices lie on a ridge of exactly one top simplex (the boundary of the hypersurface).

    Thesis: §3.3 (curvature is estimated at interior vertices only).

    Parameters
    ----------
    s : ndarray of int64, shape (m, n + 1)
        Top simplices (trusted).
    nv : int
        Number of vertices.
    tri : TriangleGeometry or None
        For triangles, the geometry whose edges are reused; None otherwise.

    Returns
    -------
    ndarray of bool, shape (nv,)
        True at boundary vertices.

    Raises
    ------
    ValueError
        On a ridge in three or more top simplices (not a manifold there).
    """
    n = s.shape[1] - 1
    if tri is not None and float(nv) ** 2 < 2.0**62:  # the edges from the compiled pass
        key, integral = (tri.edge_lo * nv + tri.edge_hi).ravel(), True
    else:
        key, integral = _ridge_keys(s, nv)
    ks = np.sort(key)
    eq = ks[1:] == ks[:-1]  # a ridge in k simplices gives a run of k equal keys
    triple = eq[1:] & eq[:-1]
    if triple.any():
        keys, counts, _ = _ridge_counts(s, nv)
        k = int(np.argmax(counts))
        ridge = _rows(keys[k : k + 1], nv, n, integral)[0]
        raise ValueError(
            f"non-manifold ridge {tuple(int(x) for x in ridge)}: it lies in {int(counts[k])} top simplices "
            f"(at most 2 allowed); {int((counts > 2).sum())} such ridges in all"
        )
    single = np.ones(len(ks), dtype=bool)
    single[1:] &= ~eq
    single[:-1] &= ~eq
    boundary = np.zeros(nv, dtype=bool)
    if single.any():
        boundary[_rows(ks[single], nv, n, integral).ravel()] = True
    return boundary

"""Validation of triangulated hypersurfaces, shared by every function of :mod:`thesis_lib.curvature`.

A triangulated n-dimensional hypersurface is given by ``vertices`` of shape ``(nv, n + 1)`` (points of
R^{n+1}) and top ``simplices`` of shape ``(m, n + 1)`` (vertex indices; the row order is the
orientation, so rows are *not* sorted).  Every curvature function calls :func:`validate_mesh` first,
which raises a ``ValueError`` naming the problem:

* wrong shapes: vertices not ``(nv, d)`` with ``d >= 2``, simplices not ``(m, d)`` (an n-simplex of a
  hypersurface in R^{n+1} has ``n + 1`` vertices, as many as the ambient dimension);
* NaN or infinite coordinates; empty inputs; non-integral, negative or out-of-range indices;
* a mesh whose extent is so large or so small that products of 2n lengths (Gram determinants,
  hyperareas squared) would overflow or underflow float64: beyond 2^±``SCALE_BITS``/(2n), for
  n = 2 about 10^±68 (rescale it: curvature scales as 1/s, hyperareas as s^n);
* a simplex with a repeated vertex, or a degenerate (zero-hyperarea) simplex;
* a non-manifold ridge: an (n-1)-face (an edge for surfaces) lying in more than two top simplices.

Conditioning.  The float formulas for hyperareas, corner dot products, cotangents and area
gradients lose about log10(aspect) to 2·log10(aspect) digits on a simplex of aspect
L^n / (n! · hyperarea) (L its longest edge; 2/√3 for the equilateral triangle): the law of cosines
cancels on a needle's base corners, and the gradient at a needle's tip, minus the sum of the two
long ones, cancels to a relative error of about 10⁻¹⁶ · aspect².  Simplices of aspect above
``ASPECT_BOUND`` (10³: below it the float formulas keep at least ten digits) are therefore
recomputed from the exact values of their coordinates (each float is an integer times a power of
two: dot products, squared edges, Gram determinants and adjugates in exact integer arithmetic, one
rounding before each square root), so
each per-simplex quantity is correct to a few units in the last place up to the degeneracy bound
(hyperarea > ``DEGENERATE_RTOL`` · L^n, i.e. aspect below about 10¹⁰ / n!), beyond which the
simplex is refused.  On simplices of aspect at most ``ASPECT_BOUND`` nothing changes: the float
formulas are kept, bit for bit.

Ridges in exactly one simplex form the boundary; their vertices are the *boundary vertices*, where
the curvature functions return NaN.
"""

from __future__ import annotations

from math import factorial, sqrt
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from .._core import triangle_geometry as _triangle_core

__all__ = [
    "Mesh",
    "TriangleGeometry",
    "triangle_geometry",
    "validate_mesh",
    "simplex_hyperareas",
    "ridges",
    "boundary_vertices",
    "check_orientation",
    "DEGENERATE_RTOL",
    "SCALE_BITS",
    "ASPECT_BOUND",
    "simplex_aspects",
]

#: A simplex whose hyperarea is below ``DEGENERATE_RTOL * (longest edge) ** n`` counts as degenerate.
DEGENERATE_RTOL = 1e-10

#: The extent e of a mesh (largest coordinate range) must have |log2 e| ≤ SCALE_BITS / (2n): the
#: formulas multiply up to 2n lengths, and float64 holds 2^±1022 (measured: wrong values past 2^±250
#: for n = 2, 2^±170 for n = 3, 2^±130 for n = 4).
SCALE_BITS = 900

#: Simplices of aspect L^n / (n! · hyperarea) above this bound (L the longest edge) are
#: ill-conditioned for the float formulas and are recomputed in exact rational arithmetic (see the
#: module docstring); at or below it the float formulas keep at least about ten digits.
ASPECT_BOUND = 1e3


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
    return _checked_triangle_geometry(v, s)[0]


def _checked_triangle_geometry(v: np.ndarray, s: np.ndarray) -> tuple[TriangleGeometry, int, int, int, float]:
    """:func:`triangle_geometry` and the kernel's (first repeated, first degenerate, count degenerate,
    longest squared edge)."""
    m = len(s)
    dot, sq = np.empty((3, m)), np.empty((3, m))
    twice, pts = np.empty(m), np.empty((3, 3, m))
    lo, hi = np.empty((m, 3), dtype=np.int64), np.empty((m, 3), dtype=np.int64)
    checks = _triangle_core.triangle_kernel(np.ascontiguousarray(v, dtype=np.float64),
                                            np.ascontiguousarray(s, dtype=np.int64),
                                            _triangle_core.Corners(dot, sq, twice, pts, lo, hi), DEGENERATE_RTOL)
    return (TriangleGeometry(dot, sq, twice, pts, lo, hi), *checks)


class Mesh(NamedTuple):
    """A validated triangulated hypersurface (see :func:`validate_mesh`)."""

    vertices: np.ndarray  #: ``(nv, n + 1)`` float64
    simplices: np.ndarray  #: ``(m, n + 1)`` int64, rows in the given (oriented) order
    areas: np.ndarray  #: ``(m,)`` hyperarea of each top simplex
    boundary: np.ndarray  #: ``(nv,)`` bool, vertex lies on a boundary ridge (None: not counted yet)
    isolated: np.ndarray  #: ``(nv,)`` bool, vertex lies in no simplex
    tri: TriangleGeometry | None = None  #: per-corner data when n = 2, else None
    pinched: np.ndarray | None = None  #: ``(nv,)`` bool, star not one fan (set by ``checked_mesh``)
    #: indices of the simplices of aspect above ``ASPECT_BOUND`` (their areas and, for n = 2, corner
    #: data were recomputed exactly); None: not computed (a Mesh built by hand)
    ill_conditioned: np.ndarray | None = None

    @property
    def n(self) -> int:
        """Dimension of the hypersurface."""
        return self.simplices.shape[1] - 1

    @property
    def no_estimate(self) -> np.ndarray:
        """``(nv,)`` bool: boundary, isolated or pinched vertices, where curvature is not estimated."""
        out = self.boundary | self.isolated
        return out if self.pinched is None else out | self.pinched


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


def _exact_hyperarea(p: np.ndarray) -> float:
    """Hyperarea sqrt(det G) / n! of one simplex ``p`` (n + 1, d): det G exact, rounded once."""
    x, e = exact_edges(p)
    n = len(x)
    return sqrt(exact_gram(x)[2] / (1 << (2 * n * e))) / factorial(n)


def _exact_triangle(tri: TriangleGeometry, t: int) -> None:
    """Overwrite triangle t's corner dots, squared edges and twice its area with their values computed
    from the exact coordinates (each correctly rounded; twice the area within an ulp)."""
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


def _check_scale(v: np.ndarray, longest_sq: float, n: int) -> None:
    """Refuse a mesh whose extent leaves 2^±(SCALE_BITS / 2n); the extent is computed only when the
    longest edge (squared, overflowed to inf or underflowed to 0 when far out) is outside that range."""
    limit = SCALE_BITS // (2 * n)
    if 2.0 ** (-2 * limit) <= longest_sq <= 2.0 ** (2 * limit):
        return
    extent = float((v.max(axis=0) - v.min(axis=0)).max())
    if extent > 0 and abs(np.log2(extent)) > limit:
        raise ValueError(
            f"the mesh extends over {extent:.3g}: its {n}-dimensional hyperareas and curvatures would "
            f"overflow or underflow float64 (extent must lie within 2^±{limit}); rescale the vertices "
            f"(curvature scales as 1/s, hyperareas as s^{n})"
        )


def validate_mesh(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, count_ridges: bool = True) -> Mesh:
    """Check a triangulated hypersurface and return it as a ``Mesh``.

    Thesis: Definition 3.13 (a triangulated hypersurface M of dimension n in R^{n+1}).

    Parameters
    ----------
    vertices : array_like, shape (nv, n + 1)
        Vertex coordinates.
    simplices : array_like of int, shape (m, n + 1)
        Top simplices (rows in orientation order).
    count_ridges : bool, default True
        Count the top simplices at each ridge: raise on a ridge in three or more and mark the
        boundary vertices.  ``False`` leaves ``boundary`` None, for a caller that counts them in its
        own pass (``checked_mesh``).

    Returns
    -------
    Mesh
        The vertices (float64) and simplices (int64, rows as given), the hyperarea of each simplex,
        the boundary (None without ``count_ridges``) and isolated vertex masks, and for n = 2 the
        per-corner ``TriangleGeometry``; ``pinched`` is left None (see
        ``checked_mesh``).

    Raises
    ------
    ValueError
        On any of the problems listed in the module docstring; the message names the offending
        simplex or ridge.

    Examples
    --------
    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> mesh = validate_mesh(octahedron, faces)
    >>> mesh.n, mesh.areas.shape, bool(mesh.boundary.any()), round(float(mesh.areas.sum()), 6)
    (2, (8,), False, 6.928203)
    """
    v = np.asarray(vertices)
    if v.ndim != 2 or v.shape[1] < 2:
        raise ValueError(f"vertices must be an (nv, n + 1) array with n >= 1, got shape {v.shape}")
    if v.shape[0] == 0:
        raise ValueError("vertices is empty")
    if not np.issubdtype(v.dtype, np.number) or np.iscomplexobj(v):
        raise ValueError(f"vertices must be real numbers, got dtype {v.dtype}")
    v = v.astype(np.float64, copy=False)
    if not np.isfinite(v).all():
        bad = int(np.flatnonzero(~np.all(np.isfinite(v), axis=1))[0])
        raise ValueError(f"vertex {bad} has a NaN or infinite coordinate: {v[bad].tolist()}")
    nv, d = v.shape
    s = np.asarray(simplices)
    if s.ndim != 2:
        raise ValueError(f"simplices must be a 2-D (m, n + 1) array, got shape {s.shape}")
    if s.shape[0] == 0:
        raise ValueError("simplices is empty")
    if s.shape[1] != d:
        raise ValueError(
            f"simplices have {s.shape[1]} vertices each, but a hypersurface in R^{d} is made of "
            f"{d - 1}-simplices with {d} vertices each"
        )
    if not np.issubdtype(s.dtype, np.integer):
        if s.dtype == bool or not np.issubdtype(s.dtype, np.number):
            raise ValueError(f"simplices must hold integer vertex indices, got dtype {s.dtype}")
        if not np.all(np.isfinite(s)) or not np.all(s == np.round(s)):
            raise ValueError("simplices must hold integer vertex indices")
    s = s.astype(np.int64, copy=False)
    lo, hi = int(s.min()), int(s.max())
    if lo < 0 or hi >= nv:
        bad = int(np.flatnonzero(np.any((s < 0) | (s >= nv), axis=1))[0])
        raise ValueError(f"simplex {bad} {s[bad].tolist()} has a vertex index outside 0..{nv - 1}")
    n = d - 1
    tri = None
    if n == 2:  # one compiled pass: geometry, repeated vertices, degenerate triangles
        tri, repeated, degenerate, n_degenerate, longest_sq = _checked_triangle_geometry(v, s)
        areas = 0.5 * tri.twice_area
    else:
        ss = np.sort(s, axis=1)
        rep = np.flatnonzero(np.any(ss[:, 1:] == ss[:, :-1], axis=1))
        repeated = int(rep[0]) if rep.size else -1
        with np.errstate(over="ignore", under="ignore", invalid="ignore"):  # far out: refused below
            areas = simplex_hyperareas(v, s)
            p = v[s]
            longest_sq = np.zeros(len(s))
            for i in range(1, d):
                for j in range(i):
                    e = p[:, i] - p[:, j]
                    np.maximum(longest_sq, np.einsum("ma,ma->m", e, e), out=longest_sq)
            flat = np.flatnonzero(areas <= DEGENERATE_RTOL * np.sqrt(longest_sq) ** n)
            ill = np.flatnonzero(np.sqrt(longest_sq) ** n > ASPECT_BOUND * factorial(n) * areas) if n > 1 else flat[:0]
        degenerate, n_degenerate = (int(flat[0]) if flat.size else -1), flat.size
        longest_sq = float(longest_sq.max())
    _check_scale(v, longest_sq, n)
    if repeated >= 0:
        raise ValueError(f"simplex {repeated} {s[repeated].tolist()} has a repeated vertex")
    if degenerate >= 0:
        raise ValueError(
            f"simplex {degenerate} {s[degenerate].tolist()} is degenerate (hyperarea {areas[degenerate]:.3g}); "
            f"{n_degenerate} degenerate simplices in all"
        )
    if tri is not None:
        ill = np.flatnonzero(tri.edge_sq.max(axis=0) > ASPECT_BOUND * tri.twice_area)
        for k in ill.tolist():
            _exact_triangle(tri, k)
        areas[ill] = 0.5 * tri.twice_area[ill]
    else:
        p = v[s[ill]]
        for r, k in enumerate(ill.tolist()):
            areas[k] = _exact_hyperarea(p[r])
    isolated = np.ones(nv, dtype=bool)
    isolated[s.ravel()] = False
    return Mesh(v, s, areas, _boundary(s, nv, tri) if count_ridges else None, isolated, tri, None, ill)


def _boundary(s: np.ndarray, nv: int, tri: TriangleGeometry | None) -> np.ndarray:
    """Boundary-vertex mask; raises ``ValueError`` on a ridge in three or more top simplices."""
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


def check_orientation(simplices: npt.ArrayLike) -> None:
    """Raise ``ValueError`` if neighbouring simplices are not coherently oriented.

    Thesis: §3.1.1 (the normal N = X_u ∧ X_v / W needs an orientation); for n = 2 two faces
    sharing an edge must traverse it in opposite directions.

    Parameters
    ----------
    simplices : array_like of int, shape (m, 3)
        Triangles with non-negative vertex indices, rows in orientation order.

    Raises
    ------
    ValueError
        If two faces traverse an edge in the same direction, or the simplices are not triangles.

    Examples
    --------
    Two triangles on the edge (0, 1) are coherent when they run through it in opposite directions:

    >>> import numpy as np
    >>> check_orientation(np.array([[0, 1, 2], [1, 0, 3]])) is None
    True
    >>> check_orientation(np.array([[0, 1, 2], [0, 1, 3]]))
    Traceback (most recent call last):
        ...
    ValueError: inconsistent orientation: faces 0 and 1 both traverse the edge (0, 1) in the same direction
    """
    s = np.asarray(simplices, dtype=np.int64)
    if s.shape[1] != 3:
        raise ValueError("orientation check is implemented for triangle meshes (n = 2) only")
    a = s.ravel()
    b = s[:, [1, 2, 0]].ravel()
    nv = int(s.max()) + 1
    key = a * nv + b
    order = np.argsort(key, kind="stable")
    ks = key[order]
    dup = np.flatnonzero(ks[1:] == ks[:-1])
    if dup.size:
        k = order[dup[0]]
        f1, f2 = k // 3, order[dup[0] + 1] // 3
        raise ValueError(
            f"inconsistent orientation: faces {int(f1)} and {int(f2)} both traverse the edge "
            f"({int(a[k])}, {int(b[k])}) in the same direction"
        )

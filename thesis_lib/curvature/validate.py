"""Validation of triangulated hypersurfaces, shared by every function of :mod:`thesis_lib.curvature`:
the one place where a mesh is parsed into a :class:`Mesh` record (its geometry is in :mod:`.geometry`).

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

from math import factorial
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from .geometry import (
    DEGENERATE_RTOL,
    TriangleGeometry,
    boundary_mask,
    checked_triangle_geometry,
    exact_hyperarea,
    exact_triangle_geometry,
    simplex_hyperareas,
)

__all__ = ["Mesh", "validate_mesh", "check_orientation", "SCALE_BITS", "ASPECT_BOUND"]


#: The extent e of a mesh (largest coordinate range) must have |log2 e| ≤ SCALE_BITS / (2n): the
#: formulas multiply up to 2n lengths, and float64 holds 2^±1022 (measured: wrong values past 2^±250
#: for n = 2, 2^±170 for n = 3, 2^±130 for n = 4).
SCALE_BITS = 900

#: Simplices of aspect L^n / (n! · hyperarea) above this bound (L the longest edge) are
#: ill-conditioned for the float formulas and are recomputed in exact rational arithmetic (see the
#: module docstring); at or below it the float formulas keep at least about ten digits.
ASPECT_BOUND = 1e3


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
        tri, repeated, degenerate, n_degenerate, longest_sq = checked_triangle_geometry(v, s)
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
            exact_triangle_geometry(tri, k)
        areas[ill] = 0.5 * tri.twice_area[ill]
    else:
        p = v[s[ill]]
        for r, k in enumerate(ill.tolist()):
            areas[k] = exact_hyperarea(p[r])
    isolated = np.ones(nv, dtype=bool)
    isolated[s.ravel()] = False
    return Mesh(v, s, areas, boundary_mask(s, nv, tri) if count_ridges else None, isolated, tri, None, ill)


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

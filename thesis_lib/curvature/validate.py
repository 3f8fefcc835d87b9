"""Validation of triangulated hypersurfaces, shared by every function of :mod:`thesis_lib.curvature`.

A triangulated n-dimensional hypersurface is given by ``vertices`` of shape ``(nv, n + 1)`` (points of
R^{n+1}) and top ``simplices`` of shape ``(m, n + 1)`` (vertex indices; the row order is the
orientation, so rows are *not* sorted).  Every curvature function calls :func:`validate_mesh` first,
which raises a ``ValueError`` naming the problem:

* wrong shapes: vertices not ``(nv, d)`` with ``d >= 2``, simplices not ``(m, d)`` (an n-simplex of a
  hypersurface in R^{n+1} has ``n + 1`` vertices, as many as the ambient dimension);
* NaN or infinite coordinates; empty inputs; non-integral, negative or out-of-range indices;
* a simplex with a repeated vertex, or a degenerate (zero-hyperarea) simplex;
* a non-manifold ridge: an (n-1)-face (an edge for surfaces) lying in more than two top simplices.

Ridges in exactly one simplex form the boundary; their vertices are the *boundary vertices*, where
the curvature functions return NaN.
"""

from __future__ import annotations

from math import factorial
from typing import NamedTuple

import numpy as np

__all__ = [
    "Mesh",
    "validate_mesh",
    "simplex_hyperareas",
    "ridges",
    "boundary_vertices",
    "check_orientation",
    "DEGENERATE_RTOL",
]

#: A simplex whose hyperarea is below ``DEGENERATE_RTOL * (longest edge) ** n`` counts as degenerate.
DEGENERATE_RTOL = 1e-10


class Mesh(NamedTuple):
    """A validated triangulated hypersurface (see :func:`validate_mesh`)."""

    vertices: np.ndarray  #: ``(nv, n + 1)`` float64
    simplices: np.ndarray  #: ``(m, n + 1)`` int64, rows in the given (oriented) order
    areas: np.ndarray  #: ``(m,)`` hyperarea of each top simplex
    boundary: np.ndarray  #: ``(nv,)`` bool, vertex lies on a boundary ridge
    isolated: np.ndarray  #: ``(nv,)`` bool, vertex lies in no simplex

    @property
    def n(self) -> int:
        """Dimension of the hypersurface."""
        return self.simplices.shape[1] - 1


def simplex_hyperareas(vertices: np.ndarray, simplices: np.ndarray) -> np.ndarray:
    """Hyperarea of each simplex, ``sqrt(det G) / n!`` with ``G`` the Gram matrix of its edge vectors.

    Thesis: Theorem 3.18 (the Gram determinant G^2 = det(G-hat), G = n! A).
    No validation: use on arrays that passed :func:`validate_mesh`.
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


def _rows_key(rows: np.ndarray, nv: int) -> np.ndarray:
    """One integer (or a void view) per sorted row, for counting equal rows."""
    rows = np.sort(rows, axis=1)
    w = rows.shape[1]
    if w == 1:
        return rows[:, 0].copy()
    if float(nv) ** w < 2.0**62:
        key = rows[:, 0].astype(np.int64)
        for j in range(1, w):
            key = key * nv + rows[:, j]
        return key
    rows = np.ascontiguousarray(rows)
    return rows.view(np.dtype((np.void, rows.dtype.itemsize * w))).ravel()


def ridges(simplices: np.ndarray, nv: int) -> tuple[np.ndarray, np.ndarray]:
    """The ridges ((n-1)-faces) of the top simplices and how many top simplices hold each.

    Thesis: §3.3 (a triangulated hypersurface: every ridge in one or two top simplices).

    Returns
    -------
    (ridges, counts)
        ``ridges`` is ``(r, n)`` with sorted rows, ``counts`` is ``(r,)``.
    """
    m, w = simplices.shape
    allr = np.concatenate([np.delete(simplices, i, axis=1) for i in range(w)])
    allr = np.sort(allr, axis=1)
    key = _rows_key(allr, nv)
    order = np.argsort(key, kind="stable")
    ks = key[order]
    start = np.ones(len(ks), dtype=bool)
    start[1:] = ks[1:] != ks[:-1]
    first = np.flatnonzero(start)
    counts = np.diff(np.append(first, len(ks)))
    return allr[order[first]], counts


def boundary_vertices(simplices: np.ndarray, nv: int) -> np.ndarray:
    """Boolean mask of the vertices on a boundary ridge (a ridge lying in one top simplex).

    Thesis: §3.1.2 (Theorem 3.5: surfaces with boundary carry a boundary term).
    """
    r, counts = ridges(np.asarray(simplices, dtype=np.int64), nv)
    mask = np.zeros(nv, dtype=bool)
    mask[r[counts == 1].ravel()] = True
    return mask


def validate_mesh(vertices, simplices) -> Mesh:
    """Check a triangulated hypersurface and return it as a :class:`Mesh`.

    Thesis: Definition 3.13 (a triangulated hypersurface M of dimension n in R^{n+1}).

    Parameters
    ----------
    vertices : array_like, shape (nv, n + 1)
        Vertex coordinates.
    simplices : array_like of int, shape (m, n + 1)
        Top simplices (rows in orientation order).

    Raises
    ------
    ValueError
        On any of the problems listed in the module docstring; the message names the offending
        simplex or ridge.
    """
    v = np.asarray(vertices)
    if v.ndim != 2 or v.shape[1] < 2:
        raise ValueError(f"vertices must be an (nv, n + 1) array with n >= 1, got shape {v.shape}")
    if v.shape[0] == 0:
        raise ValueError("vertices is empty")
    if not np.issubdtype(v.dtype, np.number) or np.iscomplexobj(v):
        raise ValueError(f"vertices must be real numbers, got dtype {v.dtype}")
    v = v.astype(np.float64, copy=False)
    if not np.all(np.isfinite(v)):
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
    ss = np.sort(s, axis=1)
    rep = np.any(ss[:, 1:] == ss[:, :-1], axis=1)
    if rep.any():
        bad = int(np.flatnonzero(rep)[0])
        raise ValueError(f"simplex {bad} {s[bad].tolist()} has a repeated vertex")
    n = d - 1
    areas = simplex_hyperareas(v, s)
    p = v[s]
    if n == 2:
        e = p[:, [1, 2, 0]] - p
        longest = np.sqrt(np.einsum("mia,mia->mi", e, e).max(axis=1))
    else:
        diff = p[:, :, None, :] - p[:, None, :, :]
        longest = np.sqrt(np.einsum("mija,mija->mij", diff, diff).max(axis=(1, 2)))
    degenerate = areas <= DEGENERATE_RTOL * longest**n
    if degenerate.any():
        bad = int(np.flatnonzero(degenerate)[0])
        raise ValueError(
            f"simplex {bad} {s[bad].tolist()} is degenerate (hyperarea {areas[bad]:.3g}); "
            f"{int(degenerate.sum())} degenerate simplices in all"
        )
    r, counts = ridges(s, nv)
    if counts.max() > 2:
        k = int(np.argmax(counts))
        raise ValueError(
            f"non-manifold ridge {tuple(int(x) for x in r[k])}: it lies in {int(counts[k])} top simplices "
            f"(at most 2 allowed); {int((counts > 2).sum())} such ridges in all"
        )
    boundary = np.zeros(nv, dtype=bool)
    boundary[r[counts == 1].ravel()] = True
    isolated = np.ones(nv, dtype=bool)
    isolated[s.ravel()] = False
    return Mesh(v, s, areas, boundary, isolated)


def check_orientation(simplices: np.ndarray) -> None:
    """Raise ``ValueError`` if neighbouring simplices are not coherently oriented.

    Thesis: §3.1.1 (the normal N = X_u ∧ X_v / W needs an orientation); for n = 2 two faces
    sharing an edge must traverse it in opposite directions.
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

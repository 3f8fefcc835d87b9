"""Simplicial pseudo-manifolds: the combinatorial condition the curvature estimates need (§3.3).

The discrete curvatures of §3.3 sum over the star of a vertex (the simplices around it, in one
fan) and over the two simplices at each ridge.  They are meaningful on a *simplicial
pseudo-manifold*: every ridge (codimension-1 face) lies in one or two top simplices, no top simplex
is repeated, and (for n >= 2) the link of every vertex is connected, so that its star is a single
fan.  A doubled triangle or two cones glued at their apex (a pinched vertex) are not; on them the
estimates return numbers without meaning, and the least-squares shape operator breaks down.

:func:`check_pseudomanifold` checks this in one compiled C++ pass (``src/pseudomanifold.cpp``: ridges
bucketed by their smallest vertex, then a union–find of the corners across shared ridges), cheap
enough to run on every call on meshes of 10⁵ vertices, and names the simplex or vertex that breaks it.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import pseudomanifold as _pseudomanifold_core
from .._validate import warn_user
from .validate import Mesh, validate_mesh

__all__ = ["check_pseudomanifold", "checked_mesh", "pinched_vertices"]


def _ridge_codes(s: np.ndarray, nv: int) -> tuple[np.ndarray, np.ndarray]:
    """For ridge r = (simplex r // k without vertex r % k): its smallest vertex and an injective
    int64 code of the other ones."""
    m, k = s.shape
    if k == 3:
        pairs = [s[:, [1, 2]], s[:, [0, 2]], s[:, [0, 1]]]  # ridge 3t + i omits corner i
        return (np.stack([p.min(axis=1) for p in pairs], axis=1).ravel(),
                np.stack([p.max(axis=1) for p in pairs], axis=1).ravel())
    ridges = np.sort(np.stack([np.delete(s, i, axis=1) for i in range(k)], axis=1).reshape(m * k, k - 1), axis=1)
    rest = ridges[:, 1:]
    if rest.shape[1] == 0:
        return ridges[:, 0], np.zeros(m * k, dtype=np.int64)
    if float(nv) ** rest.shape[1] < 2.0**62:
        code = np.zeros(m * k, dtype=np.int64)
        for j in range(rest.shape[1]):
            code = code * nv + rest[:, j]
        return ridges[:, 0], code
    _, code = np.unique(rest, axis=0, return_inverse=True)  # huge vertex counts: rank the rows instead
    return ridges[:, 0], code.ravel().astype(np.int64)


def _pseudomanifold(simplices: npt.NDArray[np.int64], n_vertices: int,
                    edges: tuple[np.ndarray, np.ndarray] | None = None) -> tuple:
    """The kernel's (code, a, b, c, pinched, boundary), raising on codes 1 and 2; ``edges`` the
    triangles' (lo, hi) ridge codes when already known (``TriangleGeometry.edge_lo/edge_hi``)."""
    s = np.ascontiguousarray(simplices, dtype=np.int64)
    lo, key = _ridge_codes(s, int(n_vertices)) if edges is None else (edges[0].ravel(), edges[1].ravel())
    code, a, b, c, pinched, boundary = _pseudomanifold_core.pseudomanifold_kernel(
        s, np.ascontiguousarray(lo, dtype=np.int64), np.ascontiguousarray(key, dtype=np.int64), int(n_vertices),
        s.shape[1] >= 3)
    if code == 1:
        raise ValueError(f"simplices {a} and {b} have the same vertices {sorted(s[a].tolist())}: a doubled "
                         "simplex is not a pseudo-manifold")
    if code == 2:
        ridge = sorted(np.delete(s[a], b).tolist())
        raise ValueError(f"the ridge {tuple(ridge)} of simplex {a} lies in three or more top simplices: "
                         "not a pseudo-manifold")
    return code, a, b, c, pinched, boundary


def check_pseudomanifold(simplices: npt.NDArray[np.int64], n_vertices: int) -> None:
    """Raise ``ValueError`` unless the top simplices form a simplicial pseudo-manifold.

    Thesis: §3.3 (the discrete curvatures sum over the star of a vertex and the two simplices at a
    ridge) and §3.1.2 (each edge of a closed surface lies in exactly two triangles).

    Parameters
    ----------
    simplices : ndarray of int64, shape (m, n + 1)
        Top simplices: vertex indices in 0..n_vertices-1, no repeated vertex in a row (trusted).
    n_vertices : int
        Number of vertices.

    Raises
    ------
    ValueError
        Naming a repeated simplex, a ridge in three or more simplices, or a pinched vertex (for
        n >= 2: a vertex whose link is disconnected, its star two fans meeting only there).

    Examples
    --------
    Three triangles on one edge are not a pseudo-manifold:

    >>> import numpy as np
    >>> check_pseudomanifold(np.array([[0, 1, 2], [0, 1, 3]]), 4) is None
    True
    >>> check_pseudomanifold(np.array([[0, 1, 2], [0, 1, 3], [0, 1, 4]]), 5)
    Traceback (most recent call last):
        ...
    ValueError: the ridge (0, 1) of simplex 0 lies in three or more top simplices: not a pseudo-manifold
    """
    code, a, b, c, _, _ = _pseudomanifold(simplices, n_vertices)
    if code == 3:
        raise ValueError(f"vertex {a} is pinched: its link is disconnected (simplices {b} and {c} meet "
                         "only through it), so it has no single fan; not a pseudo-manifold")


def pinched_vertices(simplices: npt.NDArray[np.int64], n_vertices: int) -> np.ndarray:
    """Mask of the pinched vertices (link disconnected: the star is two or more fans meeting there).

    Thesis: §3.3 (the estimates sum over the star of a vertex, one fan).  Reconstructions such as
    the Crust of random samples (§3.4.1) have a few; the curvature functions give no estimate (NaN)
    there, as on boundary vertices.

    Parameters
    ----------
    simplices : ndarray of int64, shape (m, n + 1)
        Top simplices with vertex indices in ``range(n_vertices)`` (trusted: validate first, e.g.
        with ``validate_mesh``).
    n_vertices : int
        Number of vertices nv.

    Returns
    -------
    ndarray of bool, shape (nv,)
        True at the pinched vertices; all False for curves (n = 1), whose vertex links are never
        checked.

    Raises
    ------
    ValueError
        On a repeated simplex or a ridge in three or more simplices (no formula applies there).

    Examples
    --------
    Two triangles meeting only at vertex 0 (a bow tie) pinch it:

    >>> import numpy as np
    >>> pinched_vertices(np.array([[0, 1, 2], [0, 3, 4]]), 5).tolist()
    [True, False, False, False, False]
    """
    return _pseudomanifold(simplices, n_vertices)[4]


def checked_mesh(vertices: npt.ArrayLike, simplices: npt.ArrayLike) -> Mesh:
    """``validate_mesh``, then the pseudo-manifold check with pinched vertices marked.

    Thesis: Definition 3.13 (a triangulated hypersurface) and §3.3.

    Parameters
    ----------
    vertices : array_like, shape (nv, n + 1)
        Vertex coordinates, as in ``validate_mesh``.
    simplices : array_like of int, shape (m, n + 1)
        Top simplices (rows in orientation order).

    Returns
    -------
    Mesh
        The validated mesh, its ``boundary`` counted; ``mesh.pinched`` marks the vertices whose star
        is not one fan.

    Warns
    -----
    UserWarning
        Boundary vertices at exactly the coordinates of another vertex (not merged: a triangle
        soup, or a mesh read from a textured OBJ file, split at its seams): the curvature is NaN
        there; ``thesis_lib.meshes.merge_coincident(vertices, simplices)`` merges them.

    Raises
    ------
    ValueError
        On an invalid mesh, a repeated simplex or a ridge in three or more simplices.
    """
    mesh = validate_mesh(vertices, simplices, count_ridges=False)  # ridges are counted below, once
    edges = None if mesh.tri is None else (mesh.tri.edge_lo, mesh.tri.edge_hi)
    try:
        _, _, _, _, pinched, boundary = _pseudomanifold(mesh.simplices, len(mesh.vertices), edges)
    except ValueError:
        validate_mesh(vertices, simplices)  # a ridge in three or more simplices: its own message first
        raise
    _warn_unmerged(mesh.vertices, boundary, ~mesh.isolated)
    return mesh._replace(boundary=boundary, pinched=pinched)


def _warn_unmerged(vertices: np.ndarray, boundary: np.ndarray, used: np.ndarray) -> None:
    """Warn when boundary vertices coincide (exactly) with other vertices of the simplices, found by
    one sort of the rows of the used vertices whose first coordinate is a boundary vertex's."""
    if not boundary.any():
        return
    candidates = np.flatnonzero(used & np.isin(vertices[:, 0], vertices[boundary, 0]))
    rows = vertices[candidates]
    order = np.lexsort(rows.T[::-1])
    same = np.all(rows[order[1:]] == rows[order[:-1]], axis=1)
    hit = np.zeros(len(rows), dtype=bool)
    hit[order[1:][same]] = hit[order[:-1][same]] = True
    count = int(np.count_nonzero(hit & boundary[candidates]))
    if count:
        warn_user(f"{count} boundary vertices lie at exactly the coordinates of another vertex, not shared by "
                  "the simplices (a triangle soup, or a mesh read from an OBJ file split at its texture seams): "
                  "the curvature is NaN on a boundary; merge them first with "
                  "vertices, simplices, _ = thesis_lib.meshes.merge_coincident(vertices, simplices)")

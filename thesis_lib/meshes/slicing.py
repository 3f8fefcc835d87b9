"""Slices of a triangulated 3-manifold of R⁴ by hyperplanes x_axis = level: triangle meshes of R³
to draw a hypersurface (and values on it) with the tools for surfaces."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["hyperplane_slice"]


def hyperplane_slice(
    vertices: npt.ArrayLike, simplices: npt.ArrayLike, values: npt.ArrayLike | None = None, *,
    axis: int = 3, level: float = 0.0,
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Intersect the tetrahedra of a 3-manifold in R⁴ with the hyperplane x_axis = level.

    Each tetrahedron crossing the hyperplane meets it in a triangle (one vertex on one side) or a
    quadrilateral (two and two; cut into two triangles).  Slice vertices are the points where edges
    cross, shared between neighbouring tetrahedra, so the slice of a closed 3-manifold is a closed
    surface (of a 3-sphere: a 2-sphere).  Values are interpolated linearly along the edges.
    Thesis: §3.4.2 (drawing the 3-sphere of Figure 3.12, which the thesis showed in coordinates).

    Parameters
    ----------
    vertices : array_like, shape (nv, 4)
        The points.
    simplices : array_like of int, shape (m, 4)
        The tetrahedra (indices not checked against ``vertices``).
    values : array_like, shape (nv,), optional
        Per-vertex values (NaN allowed) to carry onto the slice.
    axis : int, default 3
        The coordinate the hyperplane fixes, 0 to 3.
    level : float, default 0.0
        Its value: the hyperplane is x_axis = level (a vertex exactly on it counts as below).

    Returns
    -------
    points : ndarray of float64, shape (k, 3)
        The slice vertices, in the other three coordinates (in order).
    triangles : ndarray of int64, shape (t, 3)
        The slice's triangles (not coherently oriented).
    values : ndarray of float64, shape (k,), or None
        The interpolated values; None when ``values`` is None.

    Raises
    ------
    ValueError
        If ``vertices`` or ``simplices`` is not (·, 4), ``axis`` is not 0–3, or ``values`` does not
        have one entry per vertex.
    """
    v = np.asarray(vertices, dtype=np.float64)
    s = np.asarray(simplices, dtype=np.int64)
    if v.ndim != 2 or v.shape[1] != 4 or s.ndim != 2 or s.shape[1] != 4:
        raise ValueError(f"need (nv, 4) vertices and (m, 4) tetrahedra, got {v.shape} and {s.shape}")
    if not 0 <= axis < 4:
        raise ValueError(f"axis must be 0, 1, 2 or 3, got {axis}")
    side = v[:, axis] > level
    keep = [c for c in range(4) if c != axis]
    s = s[side[s].any(axis=1) & ~side[s].all(axis=1)]
    # crossing edges of each tetrahedron, in a fixed order; every crossing edge gets one slice vertex
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    a = np.stack([s[:, i] for i, _ in pairs], axis=1)
    b = np.stack([s[:, j] for _, j in pairs], axis=1)
    cross = side[a] != side[b]
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    key = lo * len(v) + hi
    uniq, inv = np.unique(key[cross], return_inverse=True)
    e0, e1 = uniq // len(v), uniq % len(v)
    t = (level - v[e0, axis]) / (v[e1, axis] - v[e0, axis])
    points = v[e0][:, keep] + t[:, None] * (v[e1][:, keep] - v[e0][:, keep])
    out_values = None
    if values is not None:
        f = np.asarray(values, dtype=np.float64)
        if f.shape != (len(v),):
            raise ValueError(f"values must have one entry per vertex ({len(v)}), got shape {f.shape}")
        out_values = f[e0] + t * (f[e1] - f[e0])
    ids = np.full(cross.shape, -1, dtype=np.int64)
    ids[cross] = inv.reshape(-1)
    tris = []
    n_cross = cross.sum(axis=1)
    for count in (3, 4):
        rows = ids[n_cross == count]
        corners = np.sort(rows, axis=1)[:, -count:]  # the crossing edges' slice vertices
        if count == 3:
            tris.append(corners)
        else:  # a quadrilateral: order its corners around their centroid, then split it in two
            p = points[corners]
            c = p.mean(axis=1, keepdims=True)
            nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
            u = p[:, 0] - c[:, 0]
            u /= np.linalg.norm(u, axis=1, keepdims=True) + 1e-300
            w = np.cross(nrm, u)
            w /= np.linalg.norm(w, axis=1, keepdims=True) + 1e-300
            rel = p - c
            ang = np.arctan2(np.einsum("mka,ma->mk", rel, w), np.einsum("mka,ma->mk", rel, u))
            ring = np.take_along_axis(corners, np.argsort(ang, axis=1), axis=1)
            tris.append(ring[:, [0, 1, 2]])
            tris.append(ring[:, [0, 2, 3]])
    triangles = np.concatenate(tris) if tris else np.empty((0, 3), dtype=np.int64)
    return points, triangles, out_values

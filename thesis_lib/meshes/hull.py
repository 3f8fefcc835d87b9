"""Convex-hull triangulations of spheres in any dimension (scipy / Qhull)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import ConvexHull

from .._validate import as_points
from .sampling import sample_sphere

__all__ = ["orient_outward", "convex_hull_surface", "sphere_hull"]


def orient_outward(vertices, simplices, centre=None) -> np.ndarray:
    """Reorder each facet so that det[v_1 - v_0, ..., v_n - v_0, v_0 - centre] > 0 (outward normal).

    Thesis: eq. (3.9) (orientation of N = X_{u_1} ∧ ... ∧ X_{u_n}/W).
    """
    v = np.asarray(vertices, dtype=np.float64)
    s = np.array(simplices, dtype=np.int64, copy=True)
    if s.ndim != 2 or v.ndim != 2 or s.shape[1] != v.shape[1]:
        raise ValueError("need (m, n+1) facets of (nv, n+1) vertices")
    c = v.mean(axis=0) if centre is None else np.asarray(centre, dtype=np.float64)
    p = v[s]
    mat = np.concatenate([p[:, 1:] - p[:, :1], (p[:, 0] - c)[:, None]], axis=1)
    flip = np.linalg.det(mat) < 0
    s[flip, 0], s[flip, 1] = s[flip, 1], s[flip, 0].copy()
    return s


def convex_hull_surface(points) -> np.ndarray:
    """Facets of the convex hull of ``points`` (n-simplices in R^{n+1}), oriented outward.

    Thesis: §3.4 (triangulating a convex hypersurface from a point cloud in any dimension).
    """
    pts = as_points(points, allow_duplicates=False)
    d = pts.shape[1]
    if d < 2 or len(pts) < d + 1:
        raise ValueError(f"need at least {d + 1} points in dimension >= 2")
    hull = ConvexHull(pts)
    return orient_outward(pts, hull.simplices, pts.mean(axis=0))


def sphere_hull(n_dims: int = 3, n_points: int = 1000, seed: int = 0, radius: float = 1.0):
    """Random uniform points on S^{n_dims-1}(radius) ⊂ R^{n_dims} and their convex-hull triangulation.

    Returns ``(vertices, simplices)``, simplices oriented outward.  Thesis: §3.4.2 (spheres in R^{n+1}).
    """
    pts = sample_sphere(n_points, n_dims, radius, seed)
    return pts, convex_hull_surface(pts)

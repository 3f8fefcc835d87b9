"""Convex-hull triangulations of spheres in any dimension (scipy / Qhull)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from scipy.spatial import ConvexHull, QhullError

from .._validate import as_points, check_int, check_simplices, power_of_two_scale
from ..complexes.scaling import scaled
from .sampling import sample_sphere

__all__ = ["orient_outward", "convex_hull_surface", "sphere_hull"]


def orient_outward(vertices: npt.ArrayLike, simplices: npt.ArrayLike,
                   *, centre: npt.ArrayLike | None = None) -> np.ndarray:
    """Reorder each facet so that det[v_1 - v_0, ..., v_n - v_0, v_0 - centre] > 0 (outward normal).

    Thesis: eq. (3.9) (orientation of N = X_{u_1} ∧ ... ∧ X_{u_n}/W).

    Parameters
    ----------
    vertices : array_like, shape (nv, n + 1)
        The points.
    simplices : array_like of int, shape (m, n + 1)
        Vertex indices of the facets.
    centre : array_like, shape (n + 1,), optional
        A point inside the surface (default: the mean of the vertices).

    Returns
    -------
    ndarray of int64, shape (m, n + 1)
        A copy of the facets, each with its first two vertices swapped where needed.

    Raises
    ------
    ValueError
        On invalid vertices or simplices, or a ``centre`` that is not one point of R^{n+1}.
    """
    v = as_points(vertices, name="vertices")
    s = check_simplices(simplices, len(v), width=v.shape[1]).copy()
    if centre is None:
        c = v.mean(axis=0)
    else:
        c = as_points(np.atleast_2d(centre), name="centre")
        if c.shape != (1, v.shape[1]):
            raise ValueError(f"centre must be one point of R^{v.shape[1]}, got shape {np.shape(centre)}")
        c = c[0]
    return outward_facets(v, s, c)


def outward_facets(v: np.ndarray, s: np.ndarray, c: np.ndarray) -> np.ndarray:
    """``s`` with the first two vertices of each facet swapped where it faces ``c`` (trusted input).

    Thesis: §3.3 (a coherent orientation, the normal by the right-hand rule of each facet).

    Parameters
    ----------
    v : ndarray of float64, shape (nv, n + 1)
        Vertices.
    s : ndarray of int64, shape (m, n + 1)
        Facets, a copy the function may change.
    c : ndarray of float64, shape (n + 1,)
        The point that every facet faces away from.

    Returns
    -------
    ndarray of int64, shape (m, n + 1)
        ``s``, each facet ordered so that its normal points away from ``c``.
    """
    # the sign of the determinant is unchanged by positive scalings: scale the points, then each
    # facet's matrix, by powers of two (exact: the computed determinant scales exactly), so that it
    # neither overflows nor underflows at any magnitude of coordinates
    e = power_of_two_scale(np.vstack([v, c[None]]))
    v, c = np.ldexp(v, e), np.ldexp(c, e)
    p = v[s]
    mat = np.concatenate([p[:, 1:] - p[:, :1], (p[:, 0] - c)[:, None]], axis=1)
    _, size = np.frexp(np.abs(mat).max(axis=(1, 2), keepdims=True))
    flip = np.linalg.det(np.ldexp(mat, -size)) < 0
    s[flip, 0], s[flip, 1] = s[flip, 1], s[flip, 0].copy()
    return s


def convex_hull_surface(points: npt.ArrayLike) -> np.ndarray:
    """Facets of the convex hull of ``points`` (n-simplices in R^{n+1}), oriented outward.

    Thesis: §3.4 (triangulating a convex hypersurface from a point cloud in any dimension).

    Parameters
    ----------
    points : array_like, shape (N, n + 1)
        At least n + 2 points, n + 1 >= 2, no duplicates, not all in a hyperplane.

    Returns
    -------
    ndarray of int64, shape (m, n + 1)
        Facets as vertex indices into ``points``, oriented outward (from the mean of the points).

    Raises
    ------
    ValueError
        On invalid or duplicate points, too few of them, or points all in a hyperplane.
    """
    pts = as_points(points, allow_duplicates=False)
    d = pts.shape[1]
    if d < 2 or len(pts) < d + 1:
        raise ValueError(f"need at least {d + 1} points in dimension >= 2, got {len(pts)} in dimension {d}")
    try:  # on points scaled by a power of two (Qhull crashes on coordinates near 1e150)
        hull = ConvexHull(scaled(pts)[0])
    except QhullError:
        raise ValueError(f"the points span less than R^{d} (all on a hyperplane), so their convex hull "
                         "is not a closed hypersurface") from None
    return outward_facets(pts, hull.simplices.astype(np.int64), pts.mean(axis=0))


def sphere_hull(*, n_dims: int = 3, n_points: int = 1000, seed: int = 0,
                radius: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Random uniform points on S^{n_dims-1}(radius) ⊂ R^{n_dims} and their convex-hull triangulation.

    Thesis: §3.4.2 (spheres in R^{n+1}).

    Parameters
    ----------
    n_dims : int, default 3
        Ambient dimension, at least 2.
    n_points : int, default 1000
        Number of points, at least n_dims + 1.
    seed : int, default 0
        Seed of the random points (:func:`~thesis_lib.meshes.sampling.sample_sphere`).
    radius : float, default 1.0
        Radius of the sphere, > 0.

    Returns
    -------
    vertices : ndarray of float64, shape (n_points, n_dims)
        The random points.
    simplices : ndarray of int64, shape (m, n_dims)
        Their outward-oriented hull facets.

    Raises
    ------
    ValueError
        On an invalid ``n_dims``, ``n_points``, ``seed`` or ``radius``.
    """
    n_dims = check_int(n_dims, "n_dims", minimum=2)
    n_points = check_int(n_points, "n_points", minimum=n_dims + 1)
    pts = sample_sphere(n_points, n_dims=n_dims, radius=radius, seed=seed)
    return pts, convex_hull_surface(pts)

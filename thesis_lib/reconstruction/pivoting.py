"""Ball-pivoting reconstruction (Bernardini et al. 1999) through pymeshlab, compared with the Crust."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import as_floats, as_points, check_int
from ..complexes.scaling import scaled

__all__ = ["estimate_normals", "ball_pivoting"]


def estimate_normals(points: npt.ArrayLike, *, k: int = 10) -> np.ndarray:
    """Unit normals from PCA of the ``k`` nearest neighbours, oriented away from the centroid.

    Thesis: §3.3.1 (there is no canonical normal for discrete data; here a local plane fit).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        The points, n >= 3.
    k : int, default 10
        Number of neighbours (the point itself among them), at least 3; at most n are used.

    Returns
    -------
    ndarray of float64, shape (n, 3)
        Unit normals, each with a non-negative dot product with (point − centroid).

    Raises
    ------
    ValueError
        On invalid points, fewer than 3, points not in R³, or ``k`` < 3.
    """
    from scipy.spatial import cKDTree

    pts = as_points(points, min_points=3, dimension=3)
    k = check_int(k, "k", minimum=3)
    pts, _ = scaled(pts)  # normals do not depend on the scale; distances must not overflow
    k = min(k, len(pts))
    _, nb = cKDTree(pts).query(pts, k)
    q = pts[nb] - pts[nb].mean(axis=1, keepdims=True)
    cov = np.einsum("nki,nkj->nij", q, q)
    _, vecs = np.linalg.eigh(cov)
    nrm = vecs[:, :, 0]
    flip = np.einsum("ij,ij->i", nrm, pts - pts.mean(axis=0)) < 0
    nrm[flip] *= -1
    return nrm


def ball_pivoting(points: npt.ArrayLike, normals: npt.ArrayLike | None = None,
                  *, radii: npt.ArrayLike | None = None) -> np.ndarray:
    """Triangulate ``points`` in R³ by pymeshlab's ball pivoting.

    Thesis: §3.4, "Triangulations" (an alternative to the Crust [ABK98]).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        The samples, n >= 4, no duplicates.
    normals : array_like, shape (n, 3), optional
        Normals at the samples; default :func:`estimate_normals`.
    radii : array_like of float, optional
        Ball radii pivoted in turn, each pass keeping the faces of the previous ones (default 2, 3,
        4 and 6 times the mean nearest-neighbour distance; a single radius leaves many holes in
        random samples).

    Returns
    -------
    ndarray of int64, shape (m, 3)
        Faces as indices into ``points``.

    Raises
    ------
    ValueError
        On invalid or duplicate points, fewer than 4, points not in R³, normals not of the points'
        shape, or radii that are not positive finite numbers.
    ImportError
        If pymeshlab is not installed (the ``[mesh]`` extra).
    """
    from scipy.spatial import cKDTree

    pymeshlab = require("pymeshlab", extra="mesh", purpose="ball pivoting")

    pts = as_points(points, min_points=4, allow_duplicates=False, dimension=3)
    nrm = estimate_normals(pts) if normals is None else as_floats(normals, "normals", shape=pts.shape)
    if radii is not None:
        try:
            radii = np.atleast_1d(np.asarray(radii, dtype=np.float64))
        except (TypeError, ValueError):
            raise ValueError(f"radii must be positive finite numbers, got {radii!r}") from None
        if radii.ndim != 1 or radii.size == 0 or not np.all(np.isfinite(radii)) or np.any(radii <= 0):
            raise ValueError(f"radii must be positive finite numbers, got {radii!r}")
    pts, e = scaled(pts)  # ball pivoting is scale-equivariant: run it near 1, radii scaled alike
    tree = cKDTree(pts)
    if radii is None:
        spacing = float(tree.query(pts, 2)[0][:, 1].mean())
        radii = np.array([f * spacing for f in (2.0, 3.0, 4.0, 6.0)])
    else:
        radii = np.ldexp(radii, e)
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=pts, v_normals_matrix=nrm))
    for rad in radii:
        ms.generate_surface_reconstruction_ball_pivoting(ballradius=pymeshlab.PureValue(float(rad)))
    m = ms.current_mesh()
    faces = np.asarray(m.face_matrix(), dtype=np.int64)
    out = np.asarray(m.vertex_matrix())
    if len(out) != len(pts) or not np.allclose(out, pts):  # map back to input order if reordered
        _, idx = tree.query(out)
        faces = idx[faces]
    return faces

"""Curvature at every point of a point cloud, by one of the thesis's estimators (the estimator is a
parameter): on a surface reconstructed by the Crust, Chapter 3's discrete mean or Gaussian
curvature; with no surface, the least-squares shape operator of §3.3.4 on k nearest neighbours.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_points, check_choice
from ..reconstruction.crust import crust
from ..reconstruction.crust_nd import crust_nd
from .gaussian import gaussian_curvature
from .mean import mean_curvature
from .pointcloud import knn_curvature

__all__ = ["point_curvature", "CURVATURE_ESTIMATORS"]

CURVATURE_ESTIMATORS = ("knn", "crust")


def point_curvature(points: npt.ArrayLike, *, estimator: str = "knn", curvature: str = "mean", k: int = 16,
                    area: str = "mixed") -> np.ndarray:
    """Estimated curvature at every point: |H| (``curvature="mean"``) or K (``"gaussian"``, surfaces in R³).

    Thesis: §3.3.1–§3.3.3 (mean curvature, Theorem 3.18; Gaussian curvature, Definition 3.21) on a
    Crust reconstruction (§3.4), or §3.3.4 (least-squares shape operator) on k-neighbourhoods.

    Parameters
    ----------
    points : array_like, shape (N, n + 1)
        Samples of a hypersurface (a curve in R², a surface in R³, a 3-manifold in R⁴), no
        duplicates.
    estimator : {"knn", "crust"}, default "knn"
        ``"crust"``: reconstruct with the Crust (:func:`~thesis_lib.reconstruction.crust` in R³,
        :func:`~thesis_lib.reconstruction.crust_nd.crust_nd` otherwise) and apply the discrete formulas of
        §3.3 at its vertices; ``"knn"``: the least-squares shape operator on the ``k`` nearest
        neighbours (no surface needed).
    curvature : {"mean", "gaussian"}, default "mean"
        ``"mean"`` (|H|, any n) or ``"gaussian"`` (signed K, n = 2).
    k : int, default 16
        Neighbours of the ``"knn"`` estimator.
    area : {"mixed", "voronoi", "barycentric"}, default "mixed"
        Vertex area of the ``"crust"`` estimator (``"mixed"`` needs n = 2; use ``"voronoi"`` or
        ``"barycentric"`` otherwise).

    Returns
    -------
    ndarray, shape (N,)
        NaN where the estimate is undefined (``"crust"``: samples that are not vertices of the
        reconstruction, boundary vertices); :func:`thesis_lib.multiparameter.radius_curvature_bifiltration`
        refuses NaN with a clear error.

    Raises
    ------
    ValueError
        On invalid or duplicate points, an unknown ``estimator`` or ``curvature``, ``"gaussian"`` off R³,
        ``area="mixed"`` with the Crust off R³; from the estimator (e.g. a Crust that fails to
        reconstruct, a ``k`` out of range).
    """
    pts = as_points(points, allow_duplicates=False)
    check_choice(estimator, CURVATURE_ESTIMATORS, "estimator")
    if curvature not in ("mean", "gaussian"):
        raise ValueError(f"curvature must be 'mean' or 'gaussian', got {curvature!r}")
    if estimator == "knn":
        return knn_curvature(pts, curvature=curvature, k=k)
    if curvature == "gaussian" and pts.shape[1] != 3:
        raise ValueError("the Gaussian curvature (Definition 3.21) is for surfaces in R³, "
                         f"got points in R^{pts.shape[1]}")
    if pts.shape[1] != 3 and area == "mixed":  # refused before the (costly) reconstruction
        raise ValueError("the mixed area is defined for surfaces in R³; use area='voronoi' or 'barycentric'")
    simplices = crust(pts) if pts.shape[1] == 3 else crust_nd(pts).simplices
    if curvature == "gaussian":
        return gaussian_curvature(pts, simplices, area=area)
    return mean_curvature(pts, simplices, area=area)

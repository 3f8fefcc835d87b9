"""Theorem 3.18 on Crust reconstructions of random samples of the 3-sphere and the 3-catenoid: the
3-D analogue of the thesis's Figures 3.8–3.11 (experiment ``hypersurface-crust``)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay

from ..curvature import mean_curvature
from .crust_nd import crust_nd, manifold_vertices
from .sampling import sample_n_catenoid, sample_sphere

__all__ = ["HYPERSURFACES", "sample_hypersurface", "crust_curvature_errors", "SPHERE_RADIUS"]

HYPERSURFACES = ("sphere", "catenoid")
#: the thesis's 3-sphere has radius 2, so |H| = 1/2 (§3.4.2)
SPHERE_RADIUS = 2.0


def sample_hypersurface(surface: str, n_samples: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray | None]:
    """Uniform random samples of the 3-sphere of radius 2 or of the 3-catenoid piece
    u ∈ [0, 2π), v, w ∈ [−1, 1] (the thesis's region), with their parameters (None for the sphere).

    Thesis: §3.4.2 and §3.4.3 (the same hypersurfaces, there on parameter grids).

    Parameters
    ----------
    surface : {"sphere", "catenoid"}
        Which hypersurface of R⁴.
    n_samples : int
        Number of samples, at least 1.
    seed : int, default 0
        Seed of the random draws.

    Returns
    -------
    points : ndarray of float64, shape (n_samples, 4)
        The samples.
    params : ndarray of float64, shape (n_samples, 3), or None
        The catenoid parameters (u, v, w) of each sample; None for the sphere.

    Raises
    ------
    ValueError
        On an unknown ``surface`` or an invalid ``n_samples`` (or ``seed``, for the sphere).
    """
    if surface == "sphere":
        return sample_sphere(n_samples, n_dims=4, radius=SPHERE_RADIUS, seed=seed), None
    if surface == "catenoid":
        return sample_n_catenoid(n_samples, dimension=3, seed=seed, return_params=True)
    raise ValueError(f"surface must be one of {HYPERSURFACES}, got {surface!r}")


def _errors(surface: str, H: np.ndarray, params, where: np.ndarray) -> np.ndarray:
    """Relative errors at the vertices ``where``: |H − 1/2| / (1/2) on the sphere; on the catenoid
    (H = 0, no relative error) |H| over the largest principal curvature 1/cosh² v."""
    if surface == "sphere":
        exact = 1.0 / SPHERE_RADIUS
        return np.abs(H[where] - exact) / exact
    return H[where] * np.cosh(params[where, 1]) ** 2


def crust_curvature_errors(surface: str, n_samples: int, *, seed: int = 0, area: str = "voronoi",
                           theta: float = np.pi / 4) -> dict:
    """Reconstruct ``n_samples`` random samples with :func:`crust_nd` and estimate |H| by Theorem 3.18.

    Thesis: Theorem 3.18 and §3.3.2 (areas) on the Crust of Chapter 5's "natural next step".

    Parameters
    ----------
    surface : {"sphere", "catenoid"}
        Which hypersurface of R⁴ (:func:`sample_hypersurface`); the sphere is reconstructed as a
        closed hypersurface, the catenoid piece as one with boundary.
    n_samples : int
        Number of random samples.
    seed : int, default 0
        Seed of the samples.
    area : {"voronoi", "barycentric"}, default "voronoi"
        The vertex region of :func:`~thesis_lib.curvature.mean_curvature` (``"mixed"`` needs n = 2
        and is refused here).
    theta : float, default π/4
        The Crust's normal-filter angle (:func:`~thesis_lib.meshes.crust_nd.crust_nd`).

    Returns
    -------
    dict
        ``simplices``, ``points``, ``params``, ``H`` (per sample, NaN where not estimated), ``report``
        (:class:`~thesis_lib.meshes.crust_nd.ManifoldReport`), ``pole_ratio``, ``estimated`` (mask
        of the samples with an estimate: vertices whose star is a manifold ball), ``errors`` (at those, see Notes),
        ``median``, ``p90``; for the catenoid also ``control_median``/``control_p90``: the same
        errors on the Delaunay triangulation of the samples' parameters (u, v, w) lifted to R⁴, a
        triangulation with no reconstruction error.

    Raises
    ------
    ValueError
        On an unknown ``surface`` or bad sampling parameters; ``ReconstructionError`` (a
        ValueError) when the Crust fails (see :func:`~thesis_lib.meshes.crust_nd.crust_nd`).

    Notes
    -----
    The error is |H − 1/2| / (1/2) on the sphere, and |H| cosh² v (|H| over the largest principal
    curvature) on the catenoid, whose H = 0 has no relative error.
    """
    pts, params = sample_hypersurface(surface, n_samples, seed)
    res = crust_nd(pts, theta=theta, closed=(surface == "sphere"))
    H = mean_curvature(pts, res.simplices, area=area)
    good = manifold_vertices(res.simplices, n_points=len(pts)) & np.isfinite(H)
    H = np.where(good, H, np.nan)
    err = _errors(surface, H, params, good)
    out = dict(points=pts, params=params, simplices=res.simplices, H=H, report=res.report,
               pole_ratio=res.pole_ratio, estimated=good, errors=err,
               median=float(np.median(err)), p90=float(np.percentile(err, 90)))
    if surface == "catenoid":
        tri = Delaunay(params)
        Hc = mean_curvature(pts, tri.simplices, area=area)
        # away from the seam u = 0 ≡ 2π, which the parameter triangulation does not close
        ok = np.isfinite(Hc) & (params[:, 0] > 0.5) & (params[:, 0] < 2 * np.pi - 0.5)
        ctrl = _errors(surface, Hc, params, ok)
        out.update(control_median=float(np.median(ctrl)), control_p90=float(np.percentile(ctrl, 90)))
    return out

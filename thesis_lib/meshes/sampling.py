"""Uniform random samples (with respect to area) of the surfaces of §3.4, by rejection sampling."""

from __future__ import annotations

import numpy as np

from .._validate import check_int, check_real, check_seed, check_size
from ..surfaces import catenoid_point, torus_point

__all__ = ["sample_torus", "sample_catenoid", "sample_sphere", "sample_n_catenoid"]


def _count(n, dim: int, name: str = "n") -> int:
    """A number of samples n >= 1, refused up front if the (n, dim) output would be too large."""
    n = check_int(n, name, minimum=1)
    check_size(n * dim, f"coordinates ({n:,} points in R^{dim})")
    return n


def _rejection(n: int, rng, draw, weight, wmax: float) -> np.ndarray:
    out, have = [], 0
    while have < n:
        m = max(64, int(2.6 * (n - have)))
        cand = draw(m)
        keep = rng.uniform(0.0, wmax, m) < weight(cand)
        out.append(cand[keep])
        have += int(keep.sum())
    return np.concatenate(out)[:n]


def sample_torus(n: int, *, R: float = 10.0, r: float = 5.0, seed: int = 0,
                 return_uv: bool = False) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """``n`` points uniform w.r.t. area on the torus: (u, v) uniform, accepted with prob. (R + r cos v)/(R + r).

    Thesis: §3.4.1, "Torus 2: random sampling" (rejection sampling).

    The area element of the torus is r (R + r cos v) du dv, so rejection on that density gives the
    uniform distribution on the surface.

    Parameters
    ----------
    n : int
        Number of samples, at least 1 (refused up front beyond 10⁹ coordinates).
    R, r : float
        The torus's radii, 0 < r < R (default 10 and 5, the thesis's torus).
    seed : int, default 0
        Seed of the rejection sampler's draws.
    return_uv : bool, default False
        Also return the parameters (u, v) of the samples.

    Returns
    -------
    points : ndarray of float64, shape (n, 3)
        The samples.
    uv : ndarray of float64, shape (n, 2)
        Their parameters, each in [0, 2π); only when ``return_uv``.

    Raises
    ------
    ValueError
        On an invalid ``n``, radii or ``seed``.
    """
    n = _count(n, 3)
    torus_point(0.0, 0.0, R=R, r=r)  # validates the radii
    rng = np.random.default_rng(check_seed(seed))
    uv = _rejection(
        n, rng, lambda m: rng.uniform(0.0, 2 * np.pi, (m, 2)),
        lambda c: R + r * np.cos(c[:, 1]), R + r,
    )
    pts = torus_point(uv[:, 0], uv[:, 1], R=R, r=r)
    return (pts, uv) if return_uv else pts


def sample_catenoid(n: int, *, v_range: tuple[float, float] = (-1.0, 1.0), seed: int = 0,
                    return_params: bool = False) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """``n`` points uniform w.r.t. area on the catenoid piece v ∈ v_range (area element cosh² v du dv).

    Thesis: §3.4.3, Figure 3.14 (point cloud on the 2-catenoid).

    Parameters
    ----------
    n : int
        How many points, at least 1.
    v_range : (low, high), default (-1.0, 1.0)
        The piece of the catenoid: low < high, within [-300, 300] (cosh² v overflows beyond).
    seed : int, default 0
        Seed of the draws (u, v and the acceptance test).
    return_params : bool, default False
        Also return the (u, v) parameters.

    Returns
    -------
    points : ndarray of float64, shape (n, 3)
        The samples, X(u, v) of :func:`~thesis_lib.surfaces.catenoid.catenoid_point`: uniform in
        area, so denser in (u, v) where cosh² v is larger.
    uv : ndarray of float64, shape (n, 2)
        Their parameters, u in [0, 2π); only when ``return_params``.

    Raises
    ------
    ValueError
        On an invalid ``n`` or ``seed``, or a ``v_range`` that is not such an interval.
    """
    n = _count(n, 3)
    try:
        lo, hi = v_range
    except (TypeError, ValueError):
        raise ValueError(f"v_range must be a pair (low, high), got {v_range!r}") from None
    lo, hi = check_real(lo, "v_range low"), check_real(hi, "v_range high")
    if hi <= lo or max(abs(lo), abs(hi)) > 300:
        raise ValueError(f"v_range must be an interval low < high within [-300, 300] (cosh² overflows beyond), "
                         f"got {v_range!r}")
    rng = np.random.default_rng(check_seed(seed))
    wmax = np.cosh(max(abs(lo), abs(hi))) ** 2
    uv = _rejection(
        n, rng,
        lambda m: np.column_stack([rng.uniform(0, 2 * np.pi, m), rng.uniform(lo, hi, m)]),
        lambda c: np.cosh(c[:, 1]) ** 2, wmax,
    )
    pts = catenoid_point(uv)
    return (pts, uv) if return_params else pts


def sample_sphere(n: int, *, n_dims: int = 3, radius: float = 1.0, seed: int = 0) -> np.ndarray:
    """``n`` points uniform on the sphere S^{n_dims - 1} of the given radius in R^{n_dims}.

    Thesis: §3.4.2 (spheres as test hypersurfaces).

    Parameters
    ----------
    n : int
        Number of points, at least 1.
    n_dims : int, default 3
        Ambient dimension, at least 2.
    radius : float, default 1.0
        Radius of the sphere, > 0.
    seed : int, default 0
        Seed of the normal draws that are projected onto the sphere.

    Returns
    -------
    ndarray of float64, shape (n, n_dims)
        The samples.

    Raises
    ------
    ValueError
        On an invalid ``n``, ``n_dims``, ``radius`` or ``seed``.
    """
    d = check_int(n_dims, "n_dims", minimum=2)
    n = _count(n, d)
    radius = check_real(radius, "radius", positive=True)
    g = np.random.default_rng(check_seed(seed)).normal(size=(n, d))
    return radius * g / np.linalg.norm(g, axis=1, keepdims=True)


def sample_n_catenoid(
    n_points: int, *, dimension: int = 3, v_range: tuple[float, float] = (-1.0, 1.0),
    w_range: tuple[float, float] = (-1.0, 1.0), seed: int = 0, return_params: bool = False,
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """``n_points`` uniform w.r.t. volume on the piece v ∈ v_range, every w_i ∈ w_range of the
    n-catenoid (catenoid × R^{n-2}) in R^{n+1}; volume element cosh² v du dv dw.

    Thesis: §3.4.3 (the 3-catenoid on u ∈ [−π, π], v, r ∈ [−1, 1]), sampled at random (Chapter 5).

    Parameters
    ----------
    n_points : int
        Number of samples, at least 1.
    dimension : int, default 3
        The dimension n >= 2 of the catenoid (points in R^{n+1}).
    v_range : (low, high), default (-1.0, 1.0)
        Finite range of v, low < high.
    w_range : (low, high), default (-1.0, 1.0)
        Finite range of each extra coordinate w_i, low < high (unused for n = 2).
    seed : int, default 0
        Seed of the random draws (``numpy.random.default_rng``).
    return_params : bool, default False
        Also return the parameters of the samples.

    Returns
    -------
    points : ndarray of float64, shape (n_points, n + 1)
        The samples.
    params : ndarray of float64, shape (n_points, n)
        Their parameters (u, v, w₁, ...), u in [0, 2π); only when ``return_params``.

    Raises
    ------
    ValueError
        On a ``dimension`` < 2, a ``n_points`` < 1 or too large, or a range that is not a finite
        interval low < high.
    """
    dimension = check_int(dimension, "dimension", minimum=2)
    n_points = _count(n_points, dimension + 1, "n_points")
    ranges = []
    for name, rng_ in (("v_range", v_range), ("w_range", w_range)):
        lo, hi = map(float, rng_)
        if not (np.isfinite(lo) and np.isfinite(hi)) or hi <= lo:
            raise ValueError(f"{name} must be a finite interval (low < high), got {rng_!r}")
        ranges.append((lo, hi))
    (vlo, vhi), (wlo, whi) = ranges
    rng = np.random.default_rng(check_seed(seed))
    wmax = np.cosh(max(abs(vlo), abs(vhi))) ** 2
    params = _rejection(
        n_points, rng,
        lambda m: np.column_stack([rng.uniform(0, 2 * np.pi, m), rng.uniform(vlo, vhi, m)]
                                  + [rng.uniform(wlo, whi, m) for _ in range(dimension - 2)]),
        lambda c: np.cosh(c[:, 1]) ** 2, wmax,
    )
    pts = catenoid_point(params)
    return (pts, params) if return_params else pts

"""Exact curvature of the smooth (hyper)surfaces of §3.4: torus, 3-sphere, n-catenoid.

Sign conventions follow the thesis: the normal is N = X_{u_1} ∧ ... ∧ X_{u_n} / W (eq. 3.9, for
n = 2 the cross product X_u × X_v), the shape operator is S = -N_* (Definition 3.1, eq. 3.10),
H = tr(S)/n and K = det(S) (Definitions 3.4 and 3.10).  The discrete estimates of
:mod:`thesis_lib.curvature` give |H| = ||∇area|| / (n · area), to be compared with ``abs`` of the
signed values returned here.
"""

from __future__ import annotations

from collections.abc import Callable
from math import factorial

import numpy as np
import numpy.typing as npt

__all__ = [
    "torus_point",
    "torus_uv",
    "torus_shape_operator",
    "torus_principal_curvatures",
    "torus_mean_curvature",
    "torus_gaussian_curvature",
    "torus_mean_curvature_at",
    "torus_gaussian_curvature_at",
    "torus_principal_curvatures_at",
    "hypersphere_point",
    "hypersphere_mean_curvature",
    "catenoid_point",
    "catenoid_principal_curvatures",
    "catenoid_mean_curvature",
    "hypersurface_normal",
    "fundamental_forms",
    "parametric_shape_operator",
    "normal_curvature_circle",
    "hypersphere_quadrature",
    "ellipsoid_point",
    "total_gauss_kronecker_curvature",
    "hypersphere_volume",
    "gauss_bonnet_chern_constant",
    "torus_outer_inner_ratio",
    "relative_error",
]


def check_torus_radii(R: float, r: float) -> tuple[float, float]:
    """``(R, r)`` as floats, or ValueError unless 0 < r < R (a torus of revolution without
    self-intersection).

    Shared by the torus of §3.4.1 and the upright torus of Example 4.2.
    Thesis: §3.4.1 (the torus with radii R > r).

    Parameters
    ----------
    R : float
        Distance from the centre of the tube to the axis of revolution.
    r : float
        Radius of the tube.

    Returns
    -------
    R, r : float
        The radii as Python floats.

    Raises
    ------
    ValueError
        Unless both are finite and 0 < r < R (also when either is not a number).
    """
    R, r = float(R), float(r)
    if not (np.isfinite(R) and np.isfinite(r)) or r <= 0 or R <= r:
        raise ValueError(f"torus radii need 0 < r < R (finite; R > r > 0), got R={R!r}, r={r!r}")
    return R, r


def _finite(name: str, x) -> np.ndarray:
    arr = np.asarray(x, dtype=np.float64)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} contains NaN or infinite values")
    return arr


# --------------------------------------------------------------------------------------- torus
def torus_point(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Points X(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) of the torus, shape (..., 3).

    Thesis: §3.4.1 (parametrisation of the torus in R³).

    Parameters
    ----------
    u : array_like
        Angle around the axis of revolution (the z-axis).
    v : array_like
        Angle around the tube, broadcast with ``u``.
    R : float, default 10.0
        Distance from the centre of the tube to the axis of revolution.
    r : float, default 5.0
        Radius of the tube, 0 < r < R.

    Returns
    -------
    ndarray of float64, shape (..., 3)
        X(u, v), over the broadcast shape of ``u`` and ``v``.

    Raises
    ------
    ValueError
        Unless 0 < r < R (finite), or if ``u``, ``v`` hold NaN or infinite values or do not
        broadcast.

    Examples
    --------
    The outer equator at u = v = 0 (distance R + r = 15 from the axis) and the top circle at v = π/2:

    >>> import numpy as np
    >>> torus_point(0.0, 0.0).tolist()
    [15.0, 0.0, 0.0]
    >>> np.round(torus_point(np.pi / 2, np.pi / 2), 6).tolist()
    [0.0, 10.0, 5.0]
    """
    R, r = check_torus_radii(R, r)
    u, v = np.broadcast_arrays(_finite("u", u), _finite("v", v))
    rho = R + r * np.cos(v)
    return np.stack([rho * np.cos(u), rho * np.sin(u), r * np.sin(v)], axis=-1)


def torus_uv(points: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> tuple[np.ndarray, np.ndarray]:
    """Parameters (u, v) in [0, 2π) of points on (or near) the torus: the nearest point's parameters.

    Thesis: §3.4.1 (inverse of the torus parametrisation, used to compare estimates at samples).

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Points on (or near) the torus of :func:`torus_point`.
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).
        Only R enters the formula; r is checked.

    Returns
    -------
    u, v : ndarray of float64, shape (...)
        The angle around the axis and the angle around the tube, each in [0, 2π).

    Raises
    ------
    ValueError
        Unless 0 < r < R (finite), or if ``points`` is not (..., 3) or holds NaN or infinite values.

    Examples
    --------
    The inverse of :func:`torus_point`:

    >>> import numpy as np
    >>> u, v = torus_uv([[15.0, 0.0, 0.0], [0.0, 10.0, 5.0]])
    >>> np.round(u, 6).tolist(), np.round(v, 6).tolist()
    ([0.0, 1.570796], [0.0, 1.570796])
    """
    check_torus_radii(R, r)
    p = _finite("points", points)
    if p.ndim < 1 or p.shape[-1] != 3:
        raise ValueError(f"points must have shape (..., 3), got {p.shape}")
    u = np.mod(np.arctan2(p[..., 1], p[..., 0]), 2 * np.pi)
    v = np.mod(np.arctan2(p[..., 2], np.hypot(p[..., 0], p[..., 1]) - R), 2 * np.pi)
    return u, v


def torus_shape_operator(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Shape operator in the basis (X_u, X_v): diag(-cos v / (R + r cos v), -1/r), shape (..., 2, 2).

    Thesis: §3.4.1 (S(X_u) = -cos v/(R + r cos v) X_u, S(X_v) = -X_v / r).

    Parameters
    ----------
    u : array_like
        Angle around the axis; S does not depend on it (it only sets the shape).
    v : array_like
        Angle around the tube, broadcast with ``u``.
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).

    Returns
    -------
    ndarray of float64, shape (..., 2, 2)
        The diagonal matrix of S at each parameter pair.

    Raises
    ------
    ValueError
        Unless 0 < r < R (finite); if ``u`` or ``v`` holds NaN or infinite values or they do not
        broadcast.

    Examples
    --------
    On the outer equator S = diag(−1/(R + r), −1/r) = diag(−1/15, −1/5); on the inner one the first
    entry changes sign, 1/(R − r) = 1/5:

    >>> import numpy as np
    >>> np.round(torus_shape_operator(0.0, 0.0), 6).tolist()
    [[-0.066667, 0.0], [0.0, -0.2]]
    >>> np.round(torus_shape_operator(0.0, np.pi), 6).tolist()
    [[0.2, 0.0], [0.0, -0.2]]
    """
    R, r = check_torus_radii(R, r)
    u, v = np.broadcast_arrays(_finite("u", u), _finite("v", v))
    out = np.zeros(v.shape + (2, 2))
    out[..., 0, 0] = -np.cos(v) / (R + r * np.cos(v))
    out[..., 1, 1] = -1.0 / r
    return out


def torus_principal_curvatures(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Principal curvatures κ₁ ≤ κ₂ (eigenvalues of S), shape (..., 2).

    Thesis: Definition 3.3 and §3.4.1.

    Parameters
    ----------
    u : array_like
        Angle around the axis (the curvatures do not depend on it).
    v : array_like
        Angle around the tube: κ = -cos v / (R + r cos v) along the parallel, -1/r along the meridian.
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).

    Returns
    -------
    ndarray of float64, shape (..., 2)
        κ₁ ≤ κ₂ along the last axis (signs for the outward normal).

    Raises
    ------
    ValueError
        As :func:`torus_shape_operator`.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(torus_principal_curvatures(0.0, [0.0, np.pi]), 6).tolist()
    [[-0.2, -0.066667], [-0.2, 0.2]]
    """
    S = torus_shape_operator(u, v, R=R, r=r)
    k = np.stack([S[..., 0, 0], S[..., 1, 1]], axis=-1)
    return np.sort(k, axis=-1)


def torus_mean_curvature(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Signed mean curvature H = -(R + 2r cos v) / (2r (R + r cos v)) (outward normal).

    Thesis: §3.4.1 (H = tr(S)/2, Definition 3.4).

    Parameters
    ----------
    u : array_like
        Angle around the axis (H does not depend on it; it is broadcast with ``v``).
    v : array_like
        Angle around the tube.
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).

    Returns
    -------
    ndarray of float64
        H over the broadcast shape of ``u`` and ``v``; zero on the circle cos v = -R/(2r).

    Raises
    ------
    ValueError
        As :func:`torus_shape_operator`.

    Examples
    --------
    H = −2/15 on the outer equator, −1/(2r) = −0.1 on the top circle:

    >>> import numpy as np
    >>> np.round(torus_mean_curvature(0.0, [0.0, np.pi / 2]), 6).tolist()
    [-0.133333, -0.1]
    """
    R, r = check_torus_radii(R, r)
    u, v = np.broadcast_arrays(_finite("u", u), _finite("v", v))
    c = np.cos(v)
    return -(R + 2 * r * c) / (2 * r * (R + r * c))


def torus_gaussian_curvature(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Gaussian curvature K = cos v / (r (R + r cos v)).

    Thesis: §3.4.1 (K = det S, Definition 3.4).

    Parameters
    ----------
    u : array_like
        Angle around the axis (K does not depend on it; it is broadcast with ``v``).
    v : array_like
        Angle around the tube: K > 0 on the outer half (cos v > 0), K < 0 on the inner half.
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).

    Returns
    -------
    ndarray of float64
        K over the broadcast shape of ``u`` and ``v``; zero on the circles v = ±π/2.

    Raises
    ------
    ValueError
        Unless 0 < r < R (finite), or if ``u`` and ``v`` are not finite or do not broadcast.

    Examples
    --------
    Positive outside (1/75), zero on the top circle, negative inside (−1/25):

    >>> import numpy as np
    >>> np.round(torus_gaussian_curvature(0.0, [0.0, np.pi / 2, np.pi]), 6).tolist()
    [0.013333, 0.0, -0.04]
    """
    R, r = check_torus_radii(R, r)
    u, v = np.broadcast_arrays(_finite("u", u), _finite("v", v))
    c = np.cos(v)
    return c / (r * (R + r * c))


def torus_mean_curvature_at(points: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Signed mean curvature of the torus at the parameters of ``points`` (see :func:`torus_uv`).

    Thesis: §3.4.1, Figure 3.11 (exact |H| at the sampled points).

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Sample points, e.g. the vertices of a reconstruction; each is read at the parameters of the
        nearest torus point.
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).

    Returns
    -------
    ndarray of float64, shape (...)
        H at each point (outward normal); compare ``abs`` of it with the discrete |H|.

    Raises
    ------
    ValueError
        As :func:`torus_uv`.

    Examples
    --------
    The outer equator and the top circle, as points:

    >>> import numpy as np
    >>> np.round(torus_mean_curvature_at([[15.0, 0.0, 0.0], [0.0, 10.0, 5.0]]), 6).tolist()
    [-0.133333, -0.1]
    """
    return torus_mean_curvature(*torus_uv(points, R=R, r=r), R=R, r=r)


def torus_principal_curvatures_at(points: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Principal curvatures κ₁ ≤ κ₂ of the torus at the parameters of ``points``, shape (..., 2).

    Thesis: Definition 3.3 and §3.4.1.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Points on (or near) the torus, read at their parameters (:func:`torus_uv`).
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).

    Returns
    -------
    ndarray of float64, shape (..., 2)
        κ₁ ≤ κ₂ at each point along the last axis.

    Raises
    ------
    ValueError
        If ``points`` is not (..., 3) or not finite, or the radii are invalid (:func:`torus_uv`).

    Examples
    --------
    >>> import numpy as np
    >>> np.round(torus_principal_curvatures_at([[15.0, 0.0, 0.0], [5.0, 0.0, 0.0]]), 6).tolist()
    [[-0.2, -0.066667], [-0.2, 0.2]]
    """
    return torus_principal_curvatures(*torus_uv(points, R=R, r=r), R=R, r=r)


def torus_gaussian_curvature_at(points: npt.ArrayLike, *, R: float = 10.0, r: float = 5.0) -> np.ndarray:
    """Gaussian curvature of the torus at the parameters of ``points`` (see :func:`torus_uv`).

    Thesis: §3.4.1, Figures 3.6–3.7.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Sample points; K is taken at the parameters of the nearest torus point.
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5; see :func:`torus_point`).

    Returns
    -------
    ndarray of float64, shape (...)
        K at each point.

    Raises
    ------
    ValueError
        As :func:`torus_uv`.

    Examples
    --------
    The outer and the inner equator, as points:

    >>> import numpy as np
    >>> np.round(torus_gaussian_curvature_at([[15.0, 0.0, 0.0], [5.0, 0.0, 0.0]]), 6).tolist()
    [0.013333, -0.04]
    """
    return torus_gaussian_curvature(*torus_uv(points, R=R, r=r), R=R, r=r)


# ---------------------------------------------------------------------------------- hypersphere
def hypersphere_point(angles: npt.ArrayLike, *, radius: float = 2.0) -> np.ndarray:
    """Hyperspherical coordinates: angles (..., n) = (ψ₁, ..., ψ_{n-1}, φ) to points (..., n+1) on S^n(ρ).

    x₁ = ρ cos ψ₁, x₂ = ρ sin ψ₁ cos ψ₂, ..., x_{n+1} = ρ sin ψ₁ ⋯ sin ψ_{n-1} sin φ; for n = 3 these are
    the coordinates (ψ, θ, φ) of the thesis.  Thesis: §3.4.2 (parametrisation of the 3-sphere).

    Parameters
    ----------
    angles : array_like, shape (..., n)
        The angles (ψ₁, ..., ψ_{n-1}, φ), n >= 1.
    radius : float, default 2.0
        The radius ρ > 0.

    Returns
    -------
    ndarray of float64, shape (..., n + 1)
        The points on S^n(ρ).

    Raises
    ------
    ValueError
        If ``radius`` is not a positive finite number, or ``angles`` is not (..., n) with n >= 1 or
        holds NaN or infinite values.

    Examples
    --------
    On the unit 2-sphere: ψ₁ = π/2, φ = 0 and φ = π/2 lie on the equator x₁ = 0; ψ₁ = 0 is the pole:

    >>> import numpy as np
    >>> np.round(hypersphere_point([[np.pi / 2, 0.0], [np.pi / 2, np.pi / 2], [0.0, 0.0]], radius=1.0), 6).tolist()
    [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]
    """
    radius = float(radius)
    if not np.isfinite(radius) or radius <= 0:
        raise ValueError(f"radius must be a positive finite number, got {radius!r}")
    a = _finite("angles", angles)
    if a.ndim < 1 or a.shape[-1] < 1:
        raise ValueError(f"angles must have shape (..., n) with n >= 1, got {a.shape}")
    n = a.shape[-1]
    out = np.empty(a.shape[:-1] + (n + 1,))
    s = np.ones(a.shape[:-1])
    for i in range(n):
        out[..., i] = s * np.cos(a[..., i])
        s = s * np.sin(a[..., i])
    out[..., n] = s
    return radius * out


def hypersphere_mean_curvature(*, radius: float = 2.0, n: int = 3) -> float:
    """|H| = 1/ρ of the n-sphere of radius ρ in R^{n+1} (every principal curvature is ±1/ρ).

    Thesis: §3.4.2 (mean curvature of the 3-sphere equals 1/r).

    Parameters
    ----------
    radius : float, default 2.0
        The radius ρ > 0.
    n : int, default 3
        Dimension of the sphere, n >= 1 (checked; |H| does not depend on it).

    Returns
    -------
    float
        1/ρ.

    Raises
    ------
    ValueError
        If ``radius`` is not a positive finite number or ``n`` not a positive integer.

    Examples
    --------
    >>> hypersphere_mean_curvature(radius=2.0, n=3)
    0.5
    """
    radius = float(radius)
    if not np.isfinite(radius) or radius <= 0:
        raise ValueError(f"radius must be a positive finite number, got {radius!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"n must be a positive integer, got {n!r}")
    return 1.0 / radius


# ------------------------------------------------------------------------------------ catenoid
def catenoid_point(params: npt.ArrayLike) -> np.ndarray:
    """The n-catenoid (catenoid × R^{n-2}): params (..., n) = (u, v, w₁, ...) to (..., n+1).

    X = (cosh v cos u, cosh v sin u, v, w₁, ..., w_{n-2}).  Thesis: §3.4.3 (the n-catenoid).

    Parameters
    ----------
    params : array_like, shape (..., n)
        The parameters (u, v, w₁, ..., w_{n-2}), n >= 2.

    Returns
    -------
    ndarray of float64, shape (..., n + 1)
        The points X(params).

    Raises
    ------
    ValueError
        If ``params`` is not (..., n) with n >= 2 or holds NaN or infinite values.

    Examples
    --------
    The waist circle v = 0 has radius cosh 0 = 1:

    >>> import numpy as np
    >>> np.round(catenoid_point([[0.0, 0.0], [np.pi / 2, 0.0]]), 6).tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    """
    p = _finite("params", params)
    if p.ndim < 1 or p.shape[-1] < 2:
        raise ValueError(f"params must have shape (..., n) with n >= 2, got {p.shape}")
    u, v = p[..., 0], p[..., 1]
    ch = np.cosh(v)
    return np.concatenate(
        [np.stack([ch * np.cos(u), ch * np.sin(u), v], axis=-1), p[..., 2:]], axis=-1
    )


def catenoid_principal_curvatures(params: npt.ArrayLike) -> np.ndarray:
    """Principal curvatures (-1/cosh² v, 1/cosh² v, 0, ..., 0) of the n-catenoid, shape (..., n).

    Signs for N = X_u × X_v (n = 2); for n > 2 the normal of eq. (3.9) may be the opposite one, which
    flips every sign.  Thesis: §3.4.3 (N_u = X_u / cosh² v, N_v = -X_v / cosh² v, flat in the extra
    directions).

    Parameters
    ----------
    params : array_like, shape (..., n)
        The parameters (u, v, w₁, ..., w_{n-2}), n >= 2, as in :func:`catenoid_point`; only v
        enters the curvatures.

    Returns
    -------
    ndarray of float64, shape (..., n)
        (-1/cosh² v, 1/cosh² v, 0, ..., 0) at each parameter.

    Raises
    ------
    ValueError
        As :func:`catenoid_point`.

    Examples
    --------
    ±1/cosh² v, here at v = 1:

    >>> import numpy as np
    >>> np.round(catenoid_principal_curvatures([0.0, 1.0]), 6).tolist()
    [-0.419974, 0.419974]
    """
    p = _finite("params", params)
    if p.ndim < 1 or p.shape[-1] < 2:
        raise ValueError(f"params must have shape (..., n) with n >= 2, got {p.shape}")
    k = 1.0 / np.cosh(p[..., 1]) ** 2
    out = np.zeros(p.shape)
    out[..., 0] = -k
    out[..., 1] = k
    return out


def catenoid_mean_curvature(params: npt.ArrayLike) -> np.ndarray:
    """H = 0 everywhere: the n-catenoid is a minimal hypersurface.

    Thesis: Definition 3.10 and §3.4.3.

    Parameters
    ----------
    params : array_like, shape (..., n)
        Where H is wanted: parameters (u, v, w₁, ..., w_{n-2}) of :func:`catenoid_point`, n >= 2.

    Returns
    -------
    ndarray of float64, shape (...)
        H = tr(S)/n, the mean of :func:`catenoid_principal_curvatures` (zero up to rounding).

    Raises
    ------
    ValueError
        As :func:`catenoid_point`.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(catenoid_mean_curvature([[0.0, 0.5], [1.0, 2.0]]), 12).tolist()
    [0.0, 0.0]
    """
    return catenoid_principal_curvatures(params).sum(axis=-1) / np.asarray(params).shape[-1]


# ------------------------------------------------------------------------ numerical reference
def hypersurface_normal(jacobian: npt.ArrayLike) -> np.ndarray:
    """Unit normal N = X_{u_1} ∧ ... ∧ X_{u_n} / W from Jacobians (..., n+1, n), with det[J | N] > 0.

    For n = 2 this is (X_u × X_v)/|X_u × X_v|.  Thesis: eq. (3.9).

    Parameters
    ----------
    jacobian : array_like, shape (..., n + 1, n)
        The columns X_{u_1}, ..., X_{u_n} at each point.

    Returns
    -------
    ndarray of float64, shape (..., n + 1)
        The unit normal N at each point.

    Raises
    ------
    ValueError
        If ``jacobian`` is not (..., n + 1, n), holds NaN or infinite values, or has rank < n
        somewhere (the parametrisation is not regular).

    Examples
    --------
    The plane spanned by X_u = (1, 0, 1) and X_v = (0, 1, 1) has the normal X_u × X_v / ‖·‖:

    >>> import numpy as np
    >>> np.round(hypersurface_normal([[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]), 6).tolist()
    [-0.57735, -0.57735, 0.57735]
    """
    J = _finite("jacobian", jacobian)
    if J.ndim < 2 or J.shape[-2] != J.shape[-1] + 1:
        raise ValueError(f"jacobian must have shape (..., n+1, n), got {J.shape}")
    n = J.shape[-1]
    comps = []
    for i in range(n + 1):
        minor = np.delete(J, i, axis=-2)
        comps.append((-1) ** (i + n) * np.linalg.det(minor))
    N = np.stack(comps, axis=-1)
    norm = np.linalg.norm(N, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("the parametrisation is not regular here (X_* has rank < n)")
    return N / norm


def _parameters(w) -> np.ndarray:
    w = _finite("w", w)
    if w.ndim < 1:
        raise ValueError("w must have shape (..., n)")
    return w


def _step(h: float) -> float:
    h = float(h)
    if not np.isfinite(h) or h <= 0:
        raise ValueError(f"step h must be positive, got {h!r}")
    return h


def fundamental_forms(
    X: Callable[[np.ndarray], np.ndarray], w: npt.ArrayLike, *, h: float = 1e-4
) -> tuple[np.ndarray, np.ndarray]:
    """First and second fundamental forms g_ij = <X_i, X_j>, B_ij = <N, X_ij> by central differences.

    A tangent vector with parameter components a has I(a) = aᵀ g a and II(a) = aᵀ B a, and its
    normal curvature is II(a)/I(a) (eq. 3.1).
    Thesis: Definitions 3.1–3.2 and eq. (3.9).

    Parameters
    ----------
    X : callable
        The parametrisation: maps parameters (..., n) to points (..., n + 1), vectorised.
    w : array_like, shape (..., n)
        The parameters at which to evaluate.
    h : float, default 1e-4
        The finite-difference step.

    Returns
    -------
    g, B : ndarray of float64, shape (..., n, n)
        The first and second fundamental forms in the basis (X_{u_1}, ..., X_{u_n}), with N the
        normal of eq. (3.9).

    Raises
    ------
    ValueError
        If ``w`` is not (..., n) or holds NaN or infinite values, ``h`` is not positive, ``X`` does
        not map (..., n) to (..., n + 1), or the parametrisation is not regular at ``w``.

    Examples
    --------
    On the sphere of radius 2 at a point of the equator, g = ρ² I and B = −ρ I:

    >>> import numpy as np
    >>> g, B = fundamental_forms(lambda w: hypersphere_point(w, radius=2.0), [np.pi / 2, 0.0])
    >>> np.round(g, 4).tolist(), np.round(B, 4).tolist()
    ([[4.0, 0.0], [0.0, 4.0]], [[-2.0, 0.0], [0.0, -2.0]])
    """
    w, h = _parameters(w), _step(h)
    n = w.shape[-1]
    eye = np.eye(n) * h
    X0 = np.asarray(X(w), dtype=np.float64)
    if X0.shape != w.shape[:-1] + (n + 1,):
        raise ValueError(f"X must map (..., {n}) to (..., {n + 1}), got {X0.shape}")
    first = np.stack([(X(w + eye[i]) - X(w - eye[i])) / (2 * h) for i in range(n)], axis=-1)
    second = np.empty(w.shape[:-1] + (n + 1, n, n))
    for i in range(n):
        for j in range(i, n):
            if i == j:
                d = (X(w + eye[i]) - 2 * X0 + X(w - eye[i])) / h**2
            else:
                d = (
                    X(w + eye[i] + eye[j]) - X(w + eye[i] - eye[j])
                    - X(w - eye[i] + eye[j]) + X(w - eye[i] - eye[j])
                ) / (4 * h * h)
            second[..., i, j] = second[..., j, i] = d
    N = hypersurface_normal(first)
    g = np.einsum("...ki,...kj->...ij", first, first)
    B = np.einsum("...k,...kij->...ij", N, second)
    return g, B


def parametric_shape_operator(X: Callable[[np.ndarray], np.ndarray], w: npt.ArrayLike,
                              *, h: float = 1e-4) -> np.ndarray:
    """Shape operator S = g⁻¹ B of a parametrisation X: (..., n) -> (..., n+1), by central differences.

    g_ij = <X_i, X_j> (first fundamental form), B_ij = <N, X_ij> = <S X_i, X_j> (second), so the
    matrix of S = -N_* in the basis (X_{u_1}, ..., X_{u_n}) is g⁻¹ B.
    Thesis: Definitions 3.1–3.2 and eq. (3.10).

    Parameters
    ----------
    X : callable
        Parametrisation (..., n) -> (..., n + 1) of the hypersurface, vectorised.
    w : array_like, shape (..., n)
        The parameters at which S is wanted.
    h : float, default 1e-4
        Step of the central differences of :func:`fundamental_forms`.

    Returns
    -------
    ndarray of float64, shape (..., n, n)
        The matrix of S at each parameter.

    Raises
    ------
    ValueError
        As :func:`fundamental_forms`.

    Examples
    --------
    From the parametrisation alone, S = g⁻¹B: −I/ρ on the sphere of radius 2, and the torus's
    diag(−1/15, −1/5) on its outer equator:

    >>> import numpy as np
    >>> np.round(parametric_shape_operator(lambda w: hypersphere_point(w, radius=2.0), [np.pi / 2, 0.0]), 4).tolist()
    [[-0.5, 0.0], [0.0, -0.5]]
    >>> torus = lambda w: torus_point(w[..., 0], w[..., 1])
    >>> np.round(parametric_shape_operator(torus, [0.0, 0.0]), 4).tolist()
    [[-0.0667, 0.0], [0.0, -0.2]]
    """
    g, B = fundamental_forms(X, w, h=h)
    return np.linalg.solve(g, B)


def normal_curvature_circle(X: Callable[[np.ndarray], np.ndarray], w: npt.ArrayLike, *, nodes: int = 64,
                            h: float = 1e-4) -> np.ndarray:
    """Normal curvature II(t)/I(t) of a surface (n = 2) at parameters w in the unit tangent directions
    t(θ_k) = cos θ_k e₁ + sin θ_k e₂, θ_k = 2πk/nodes, with (e₁, e₂) the orthonormal frame that
    Gram–Schmidt makes of (X_u, X_v).

    Definition 3.3 takes κ₁, κ₂ as the minimum and maximum over θ; eq. (3.23) integrates over θ
    (the trapezoid rule is exact here for nodes ≥ 3: κ_n is a trigonometric polynomial of degree 2).
    Thesis: eq. (3.1), Definition 3.3 and eq. (3.23).

    Parameters
    ----------
    X : callable
        The parametrisation of a surface: maps parameters (..., 2) to points (..., 3), vectorised.
    w : array_like, shape (..., 2)
        The parameters of the points at which the tangent direction turns.
    nodes : int, default 64
        How many directions θ_k, at least 3.
    h : float, default 1e-4
        Step of the central differences (see :func:`fundamental_forms`).

    Returns
    -------
    ndarray of float64, shape (..., nodes)
        The normal curvature in direction θ_k at each parameter.

    Raises
    ------
    ValueError
        As :func:`fundamental_forms`; also if n ≠ 2 or ``nodes`` is not an integer >= 3.

    Examples
    --------
    Four directions on the torus's outer equator: the normal curvature swings between its principal
    values −1/15 and −1/5 (Euler's formula):

    >>> import numpy as np
    >>> torus = lambda w: torus_point(w[..., 0], w[..., 1])
    >>> np.round(normal_curvature_circle(torus, [0.0, 0.0], nodes=4), 4).tolist()
    [-0.0667, -0.2, -0.0667, -0.2]
    """
    g, B = fundamental_forms(X, w, h=h)
    if g.shape[-1] != 2:
        raise ValueError(f"normal_curvature_circle needs a surface (n = 2), got n = {g.shape[-1]}")
    if isinstance(nodes, bool) or not isinstance(nodes, (int, np.integer)) or nodes < 3:
        raise ValueError(f"nodes must be an integer >= 3, got {nodes!r}")
    L = np.linalg.cholesky(g)  # g = L Lᵀ: parameter components of the orthonormal frame are L⁻ᵀ
    Linv = np.linalg.inv(L)
    S_orth = np.einsum("...ij,...jk,...lk->...il", Linv, B, Linv)  # L⁻¹ B L⁻ᵀ, symmetric
    theta = 2 * np.pi * np.arange(nodes) / nodes
    c = np.stack([np.cos(theta), np.sin(theta)])  # (2, nodes)
    return np.einsum("ik,...ij,jk->...k", c, S_orth, c)


def hypersphere_quadrature(n: int, *, nodes: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """Quadrature over the hyperspherical parameters (ψ₁, ..., ψ_{n−1}, φ) ∈ (0, π)^{n−1} × [0, 2π).

    Gauss–Legendre with ``nodes`` points in each ψ, the trapezoid rule with 2·nodes points in φ
    (periodic, so spectrally accurate).  Σ weights·f(params) approximates ∫ f dψ₁ ⋯ dψ_{n−1} dφ
    (the parameter measure; multiply f by a volume element).
    Thesis: §3.4.2 (the hyperspherical coordinates of the 3-sphere), Theorem 3.11.

    Parameters
    ----------
    n : int
        Dimension of the sphere (number of parameters), n >= 1.
    nodes : int, default 16
        Gauss–Legendre nodes per ψ (and half the trapezoid nodes in φ), at least 2.

    Returns
    -------
    params : ndarray of float64, shape (k, n)
        The quadrature nodes, k = nodes^{n−1} · 2·nodes.
    weights : ndarray of float64, shape (k,)
        Their weights.

    Raises
    ------
    ValueError
        If ``n`` is not a positive integer or ``nodes`` not an integer >= 2.

    Examples
    --------
    For n = 2: nodes × 2·nodes points whose weights sum to the area 2π² of the parameter box
    (0, π) × [0, 2π):

    >>> import numpy as np
    >>> params, weights = hypersphere_quadrature(2, nodes=8)
    >>> params.shape, round(float(weights.sum() / np.pi**2), 6)
    ((128, 2), 2.0)
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"n must be a positive integer, got {n!r}")
    if isinstance(nodes, bool) or not isinstance(nodes, (int, np.integer)) or nodes < 2:
        raise ValueError(f"nodes must be an integer >= 2, got {nodes!r}")
    x, wx = np.polynomial.legendre.leggauss(int(nodes))
    psi, wpsi = 0.5 * np.pi * (x + 1), 0.5 * np.pi * wx
    phi = 2 * np.pi * np.arange(2 * nodes) / (2 * nodes)
    wphi = np.full(2 * nodes, 2 * np.pi / (2 * nodes))
    axes, weights = [psi] * (n - 1) + [phi], [wpsi] * (n - 1) + [wphi]
    grids = np.meshgrid(*axes, indexing="ij")
    wgrid = np.meshgrid(*weights, indexing="ij")
    params = np.stack([gr.ravel() for gr in grids], axis=1)
    return params, np.prod(np.stack([wg.ravel() for wg in wgrid]), axis=0)


def ellipsoid_point(angles: npt.ArrayLike, axes: npt.ArrayLike) -> np.ndarray:
    """The ellipsoid Σ x_i²/a_i² = 1 in R^{n+1}: x = a ∘ y with y the unit-sphere point of ``angles``.

    Thesis: Theorem 3.11 (a closed hypersurface that is not a sphere).

    Parameters
    ----------
    angles : array_like, shape (..., n)
        Hyperspherical angles, as in :func:`hypersphere_point`.
    axes : array_like, shape (n + 1,)
        The positive semi-axes a_i.

    Returns
    -------
    ndarray of float64, shape (..., n + 1)
        The points on the ellipsoid.

    Raises
    ------
    ValueError
        If ``axes`` is not a 1-D array of positive finite numbers, does not have n + 1 entries, or
        ``angles`` is invalid (see :func:`hypersphere_point`).

    Examples
    --------
    >>> import numpy as np
    >>> np.round(ellipsoid_point([[0.0, 0.0], [np.pi / 2, 0.0]], [3.0, 2.0, 1.0]), 6).tolist()
    [[3.0, 0.0, 0.0], [0.0, 2.0, 0.0]]
    """
    a = _finite("axes", axes)
    if a.ndim != 1 or np.any(a <= 0):
        raise ValueError(f"axes must be a 1-D array of positive semi-axes, got {a!r}")
    y = hypersphere_point(angles, radius=1.0)
    if y.shape[-1] != len(a):
        raise ValueError(f"{len(a)} semi-axes for points in R^{y.shape[-1]}")
    return y * a


def total_gauss_kronecker_curvature(
    X: Callable[[np.ndarray], np.ndarray], params: npt.ArrayLike, weights: npt.ArrayLike, *, h: float = 1e-4
) -> float:
    """∫_X K dVol ≈ Σ weights · det S · sqrt(det g) over quadrature nodes ``params`` (k, n).

    K = det S (Definition 3.10) and dVol = sqrt(det g) du₁⋯du_n, from :func:`fundamental_forms`.
    For even n, K does not depend on the choice of normal.  Gauss–Bonnet (Theorem 3.8, n = 2) and
    Gauss–Bonnet–Chern (Theorem 3.11, n = 2m) say the result is (π^m 2^n m!/n!) χ.
    Thesis: eq. (3.14), Theorems 3.8 and 3.11.

    Parameters
    ----------
    X : callable
        Parametrisation (..., n) -> (..., n + 1) of a closed hypersurface, vectorised.
    params : array_like, shape (k, n)
        Quadrature nodes in parameter space (e.g. from :func:`hypersphere_quadrature`).
    weights : array_like, shape (k,)
        Quadrature weights of the nodes (not point weights).
    h : float, default 1e-4
        Step of the central differences for g and B.

    Returns
    -------
    float
        The quadrature sum.

    Raises
    ------
    ValueError
        As :func:`fundamental_forms`; also if ``weights`` holds NaN or infinite values or does not
        match ``params``.

    Examples
    --------
    Gauss–Bonnet on an ellipsoid with axes 3, 2, 1: ∫K dA = 2πχ = 4π:

    >>> import numpy as np
    >>> params, weights = hypersphere_quadrature(2, nodes=16)
    >>> ellipsoid = lambda w: ellipsoid_point(w, [3.0, 2.0, 1.0])
    >>> round(total_gauss_kronecker_curvature(ellipsoid, params, weights) / (4 * np.pi), 6)
    1.0
    """
    w = _finite("weights", weights)
    g, B = fundamental_forms(X, params, h=h)
    if w.shape != g.shape[:-2]:
        raise ValueError(f"weights {w.shape} do not match params {g.shape[:-2]}")
    return float(np.sum(w * np.linalg.det(B) / np.sqrt(np.linalg.det(g))))


def hypersphere_volume(n: int, *, nodes: int = 64) -> float:
    """Volume of the unit n-sphere, 2π ∏_{k=1}^{n−1} ∫_0^π sin^k ψ dψ, by Gauss–Legendre quadrature.

    Computed from the volume element of hyperspherical coordinates, independently of the closed
    form 2π^{(n+1)/2}/Γ((n+1)/2); Theorem 3.11's constant is half of it for even n.
    Thesis: Theorem 3.11 ("volume of S^n / 2 = π^m 2^n m!/n!").

    Parameters
    ----------
    n : int
        Dimension of the sphere, n >= 1.
    nodes : int, default 64
        Gauss–Legendre nodes per integral.

    Returns
    -------
    float
        The n-dimensional volume of the unit sphere S^n ⊂ R^{n+1}.

    Raises
    ------
    ValueError
        If ``n`` is not a positive integer.

    Examples
    --------
    4π for S², 2π² for S³:

    >>> import numpy as np
    >>> round(hypersphere_volume(2) / np.pi, 6), round(hypersphere_volume(3) / np.pi**2, 6)
    (4.0, 2.0)
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"n must be a positive integer, got {n!r}")
    x, wx = np.polynomial.legendre.leggauss(int(nodes))
    psi, wpsi = 0.5 * np.pi * (x + 1), 0.5 * np.pi * wx
    return float(2 * np.pi * np.prod([np.sum(wpsi * np.sin(psi) ** k) for k in range(1, n)]))


def gauss_bonnet_chern_constant(n: int) -> float:
    """The thesis's constant π^m 2^n m!/n! of Theorem 3.11 for even n = 2m.

    Thesis: Theorem 3.11.

    Parameters
    ----------
    n : int
        An even dimension n = 2m >= 2.

    Returns
    -------
    float
        π^m 2^n m!/n!.

    Raises
    ------
    ValueError
        If ``n`` is not an even integer >= 2.

    Examples
    --------
    2π for surfaces; for n = 4 the constant times χ(S⁴) = 2 is the volume of S⁴ (where K = 1):

    >>> import numpy as np
    >>> round(gauss_bonnet_chern_constant(2) / np.pi, 6)
    2.0
    >>> round(2 * gauss_bonnet_chern_constant(4), 6) == round(hypersphere_volume(4), 6)
    True
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2 or n % 2:
        raise ValueError(f"n must be an even integer >= 2, got {n!r}")
    m = n // 2
    return float(np.pi**m * 2**n * factorial(m) / factorial(n))


def torus_outer_inner_ratio(*, R: float = 10.0, r: float = 5.0) -> float:
    """Mean |H| over the outer half of the torus (cos v > 0) over that of the inner half, by area.

    With dA = r (R + r cos v) du dv and |H| = |R + 2r cos v| / (2r (R + r cos v)) the ratio is
    [∫ |R + 2r cos v| dv / ∫ (R + r cos v) dv]_outer / [same]_inner; for R = 2r it is
    (π + 2)(π − 1)/((π + 1)(π − 2)) ≈ 2.33.  What Figures 3.8–3.10's colour profile should show.
    Thesis: §3.4.1, Figures 3.8–3.10.

    Parameters
    ----------
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5, where R = 2r); the ratio depends only
        on R/r.

    Returns
    -------
    float
        The ratio of the area-weighted means of |H| (outer over inner).

    Raises
    ------
    ValueError
        Unless 0 < r < R (finite).

    Examples
    --------
    The outer half of the torus with R = 10, r = 5 is about 2.3 times as curved (in mean |H|) as the
    inner half:

    >>> round(torus_outer_inner_ratio(), 6)
    2.328928
    """
    R, r = check_torus_radii(R, r)
    from scipy.integrate import quad

    # H changes sign where cos v = -R/(2r): a kink of |H| for the quadrature to know about
    zeros = [np.arccos(-R / (2 * r)), 2 * np.pi - np.arccos(-R / (2 * r))] if R < 2 * r else []

    def mean_abs_h(a: float, b: float) -> float:
        kinks = [v for v in zeros if a < v < b]
        num = quad(lambda v: abs(R + 2 * r * np.cos(v)) / (2 * r), a, b, points=kinks or None)[0]
        return num / quad(lambda v: R + r * np.cos(v), a, b)[0]

    return mean_abs_h(-np.pi / 2, np.pi / 2) / mean_abs_h(np.pi / 2, 3 * np.pi / 2)


def relative_error(estimate: npt.ArrayLike, exact: npt.ArrayLike, *, zero_tol: float = 1e-3) -> np.ndarray:
    """|estimate - exact| / |exact| (pass |H| for H, signed K for K), NaN where |exact| < zero_tol · max|exact|.

    The thesis plots |real - estimate| / real (Figure 3.5); the real value vanishes on whole circles
    of the torus (H at cos v = -R/(2r), K at v = ±π/2), where the ratio is undefined: those points
    are left out (NaN) and should be reported separately as absolute errors.
    Thesis: §3.4.1, Figures 3.5 and 3.7.

    Parameters
    ----------
    estimate : array_like
        The estimated values.
    exact : array_like
        The exact values, same shape, finite.
    zero_tol : float, default 1e-3
        Fraction of max|exact| in [0, 1) at or below which |exact| counts as zero.

    Returns
    -------
    ndarray of float64
        The relative error, shape of ``exact``; NaN where |exact| <= zero_tol · max|exact|.

    Raises
    ------
    ValueError
        If the shapes differ, ``exact`` holds NaN or infinite values, or ``zero_tol`` is outside
        [0, 1).

    Examples
    --------
    NaN where the exact value is (near) zero:

    >>> import numpy as np
    >>> np.round(relative_error([0.51, 0.0, 2.2], [0.5, 0.0, 2.0]), 6).tolist()
    [0.02, nan, 0.1]
    """
    est = np.asarray(estimate, dtype=np.float64)
    ex = np.asarray(exact, dtype=np.float64)
    if est.shape != ex.shape:
        raise ValueError(f"estimate {est.shape} and exact {ex.shape} differ in shape")
    if not np.all(np.isfinite(ex)):
        raise ValueError("exact values contain NaN or infinite values")
    zero_tol = float(zero_tol)
    if not 0 <= zero_tol < 1:
        raise ValueError(f"zero_tol must lie in [0, 1), got {zero_tol!r}")
    scale = np.max(np.abs(ex)) if ex.size else 0.0
    out = np.full(ex.shape, np.nan)
    ok = np.abs(ex) > zero_tol * scale
    out[ok] = np.abs(est[ok] - ex[ok]) / np.abs(ex[ok])
    return out

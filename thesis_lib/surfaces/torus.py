"""The torus of revolution of §3.4.1 (radii R > r): its parametrisation and exact curvatures.

Sign conventions: those of :mod:`thesis_lib.surfaces`.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_floats, check_torus_radii

__all__ = [
    "torus_point",
    "torus_uv",
    "torus_shape_operator",
    "torus_principal_curvatures",
    "torus_mean_curvature",
    "torus_gaussian_curvature",
    "torus_mean_curvature_at",
    "torus_principal_curvatures_at",
    "torus_gaussian_curvature_at",
    "torus_outer_inner_ratio",
]


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
    u, v = np.broadcast_arrays(as_floats(u, "u"), as_floats(v, "v"))
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
    p = as_floats(points, "points", shape=(..., 3))
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
    u, v = np.broadcast_arrays(as_floats(u, "u"), as_floats(v, "v"))
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
    u, v = np.broadcast_arrays(as_floats(u, "u"), as_floats(v, "v"))
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
    u, v = np.broadcast_arrays(as_floats(u, "u"), as_floats(v, "v"))
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


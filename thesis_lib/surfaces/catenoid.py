"""The n-catenoid of §3.4.2 (the minimal hypersurface of revolution): parametrisation and exact curvatures.

Sign conventions: those of :mod:`thesis_lib.surfaces`.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_floats

__all__ = ["catenoid_point", "catenoid_principal_curvatures", "catenoid_mean_curvature"]


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
    p = as_floats(params, "params")
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
    p = as_floats(params, "params")
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


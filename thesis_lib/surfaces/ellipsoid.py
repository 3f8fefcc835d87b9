"""Ellipsoids with given semi-axes, the test surfaces of the Gauss–Bonnet–Chern theorem (§3.2).

Sign conventions: those of :mod:`thesis_lib.surfaces`.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_floats
from .hypersphere import hypersphere_point

__all__ = ["ellipsoid_point"]


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
    a = as_floats(axes, "axes")
    if a.ndim != 1 or np.any(a <= 0):
        raise ValueError(f"axes must be a 1-D array of positive semi-axes, got {a!r}")
    y = hypersphere_point(angles, radius=1.0)
    if y.shape[-1] != len(a):
        raise ValueError(f"{len(a)} semi-axes for points in R^{y.shape[-1]}")
    return y * a


"""Exact rescaling of point sets by a power of two (coordinates near 1e160 or 1e-170).

Every construction of §2.1.2 is scale-equivariant: scaling the points by s scales Rips, Čech and
witness values by s and alpha values (squared radii) by s².  Multiplying floats by a power of two
is exact (barring underflow), so the constructions run on points of magnitude about 1, where
squared distances neither overflow nor underflow, and the values are scaled back at the end; a
value that does not fit in float64 after scaling back is refused with a clear message.

The exponent and the exact scaling are part of parsing a point cloud (``_validate.parse_points``,
whose :class:`~thesis_lib._validate.Points` record carries both); this module scales back.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import power_of_two_scale, scale_points

__all__ = ["scaled", "unscale_values"]


def scaled(points: npt.NDArray[np.float64], name: str = "points") -> tuple[np.ndarray, int]:
    """``(points * 2**e, e)`` with the largest |coordinate| brought into [0.5, 1) (exactly).

    Parameters
    ----------
    points : float64 array (already validated).
    name : argument name for the error message.

    Returns
    -------
    The scaled points (C-contiguous) and the exponent e: results are scaled back by 2^(−e) (lengths)
    or 2^(−2e) (squared lengths).
    """
    e = power_of_two_scale(points)
    return np.ascontiguousarray(scale_points(points, e, name)), e


def unscale_values(values: npt.NDArray[np.float64], exponent: int, what: str) -> np.ndarray:
    """``values * 2**exponent`` (the inverse scaling of the results), refusing overflow or underflow.

    Parameters
    ----------
    values : float64 array computed on scaled points.
    exponent : power of two to multiply by.
    what : what the values are, for the error message (e.g. "squared radii").

    Returns
    -------
    The values in the units of the input points.

    Raises
    ------
    ValueError
        If a finite value becomes infinite, or a nonzero value falls below float64's normal range.
    """
    with np.errstate(over="ignore", under="ignore"):
        out = np.ldexp(values, exponent)
    finite = np.isfinite(values)
    if np.any(~np.isfinite(out) & finite):
        raise ValueError(f"the {what} exceed float64's range (about 1.8e308) at this scale; rescale the points")
    tiny = finite & (values != 0) & (np.abs(out) < np.finfo(np.float64).tiny)
    if np.any(tiny):
        raise ValueError(f"the {what} fall below float64's normal range (about 2.2e-308) at this scale; "
                         "rescale the points")
    return out

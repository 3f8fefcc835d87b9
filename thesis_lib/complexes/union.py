"""Betti numbers of a union of discs in the plane, read off a pixel grid (no complex involved).

An independent check of the nerve theorems of §2.1.2: the Čech and alpha complexes of the points
should have the homology of the union of the balls B(x, ε) (Theorems 2.8 and 2.15), while the
Vietoris–Rips complex need not (Figure 2.4).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from scipy import ndimage

from .._validate import as_points

__all__ = ["union_of_discs_betti"]


def union_of_discs_betti(points: npt.ArrayLike, radius: float, *, pixel: float) -> tuple[int, int]:
    """(β₀, β₁) of the union of closed discs B(x, radius) in the plane, on a grid of square pixels.

    Thesis: Theorem 2.8 (the union of the balls the nerve stands for), §2.1.2.

    A pixel belongs to the union when its centre does.  β₀ counts the 8-connected components of the
    union, β₁ the 4-connected components of the complement that do not reach the border (the holes);
    this pair of connectivities is the one for which the count is the homology of the pixel set.
    The answer is that of the union itself when ``pixel`` is small against the gaps and overlaps
    of the discs (no near-tangencies at this radius).

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The centres.
    radius : float
        The radius ε of every disc, > 0.
    pixel : float
        The side of a pixel, > 0.

    Returns
    -------
    tuple of int
        (β₀, β₁) of the pixel union.

    Raises
    ------
    ValueError
        Points not planar, NaN, a non-positive radius or pixel, or a grid over 4·10⁷ pixels.
    """
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points must be planar (shape (n, 2)), got shape {pts.shape}")
    radius, pixel = float(radius), float(pixel)
    if not (radius > 0 and pixel > 0) or not np.isfinite(radius + pixel):
        raise ValueError(f"radius and pixel must be positive numbers, got {radius} and {pixel}")
    lo, hi = pts.min(axis=0) - radius - 2 * pixel, pts.max(axis=0) + radius + 2 * pixel
    shape = np.ceil((hi - lo) / pixel).astype(int)
    if int(shape[0]) * int(shape[1]) > 4 * 10**7:
        raise ValueError(f"a grid of {shape[0]} × {shape[1]} pixels is too large; give a larger pixel")
    xs = lo[0] + pixel * (np.arange(shape[0]) + 0.5)
    ys = lo[1] + pixel * (np.arange(shape[1]) + 0.5)
    inside = np.zeros((shape[0], shape[1]), dtype=bool)
    r2 = radius * radius
    for x, y in pts:
        i = slice(max(0, int((x - radius - lo[0]) / pixel) - 1), int((x + radius - lo[0]) / pixel) + 2)
        j = slice(max(0, int((y - radius - lo[1]) / pixel) - 1), int((y + radius - lo[1]) / pixel) + 2)
        dx, dy = xs[i, None] - x, ys[None, j] - y
        inside[i, j] |= dx * dx + dy * dy <= r2
    _, b0 = ndimage.label(inside, structure=np.ones((3, 3), dtype=int))
    holes, n_out = ndimage.label(~inside)  # 4-connected (the default cross)
    border = set(np.unique(np.concatenate([holes[0], holes[-1], holes[:, 0], holes[:, -1]]))) - {0}
    return int(b0), int(n_out - len(border))

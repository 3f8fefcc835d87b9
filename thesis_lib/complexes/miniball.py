"""Smallest enclosing ball of a point set in any dimension (thesis §2.1.2, the Miniball Algorithm).

Two independent implementations:

* :func:`smallest_enclosing_ball` — Welzl's randomised algorithm in Gärtner's move-to-front form
  ([Gär99]); recursion only on the support set (depth <= d + 2) and a vectorised scan for the first
  point outside the current ball, so it runs on large point sets.
* :func:`meb_radius_small` (compiled C++, ``src/miniball.cpp``) — for the few vertices of one
  simplex: the smallest ball is the circumscribed ball, within the affine hull, of some subset of
  the points, so the radius is the smallest such circumradius whose ball contains every point.
  Used by the Čech complex.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import miniball
from .._validate import as_points, check_seed
from .scaling import scaled

__all__ = ["smallest_enclosing_ball", "circumball", "meb_radius_small"]


def circumball(support: npt.ArrayLike) -> tuple[np.ndarray, float]:
    """Centre and squared radius of the smallest ball with all of ``support`` on its boundary.

    Thesis: §2.1.2 (balls B(x, ε) of the Čech complex); the centre lies in the affine hull.

    Parameters
    ----------
    support : array_like, shape (k, d)
        One to d + 1 points; affinely dependent ones get the least-squares centre.

    Returns
    -------
    centre : numpy.ndarray of float64, shape (d,)
        The circumcentre in the affine hull of ``support``.
    r2 : float
        Its squared distance to the first point (the squared radius).
    """
    support = np.asarray(support, dtype=np.float64)
    p0 = support[0]
    if support.shape[0] == 1:
        return p0.copy(), 0.0
    a = support[1:] - p0
    gram = 2.0 * a @ a.T
    rhs = np.einsum("ij,ij->i", a, a)
    try:
        lam = np.linalg.solve(gram, rhs)
    except np.linalg.LinAlgError:
        lam = np.linalg.lstsq(gram, rhs, rcond=None)[0]
    centre = p0 + lam @ a
    return centre, float(np.sum((centre - p0) ** 2))


def _mtf(points: np.ndarray, end: int, support: list[np.ndarray], dim: int, tol: float):
    if support:
        centre, r2 = circumball(np.array(support))
    else:
        centre, r2 = points[0].copy(), -1.0
    if len(support) == dim + 1:
        return centre, r2
    i = 0
    while i < end:
        d2 = np.einsum("ij,ij->i", points[i:end] - centre, points[i:end] - centre)
        outside = np.flatnonzero(d2 > r2 + tol)
        if outside.size == 0:
            break
        j = i + int(outside[0])
        p = points[j].copy()
        centre, r2 = _mtf(points, j, support + [p], dim, tol)
        # move-to-front: the violating point goes first, the ones before it shift by one
        points[1 : j + 1] = points[0:j].copy()
        points[0] = p
        i = j + 1
    return centre, r2


def smallest_enclosing_ball(points: npt.ArrayLike, *, seed: int = 0) -> tuple[np.ndarray, float]:
    """Centre and radius of the smallest closed ball containing ``points`` (any dimension).

    Thesis: §2.1.2, the Miniball Algorithm [Gär99] deciding membership in C(X, ε) (Definition 2.9).

    Parameters
    ----------
    points : (n, d) array, n >= 1, finite.
    seed : seed of the random permutation (expected linear time); the ball does not depend on it.

    Returns
    -------
    centre : (d,) array.
    radius : float
        The largest distance from ``centre`` (as returned) to a point, rounded up: the closed ball
        contains every point exactly, at any scale (1e300, 1e-300, subnormal coordinates), and the
        radius exceeds the exact smallest one by a few units in the last place (at subnormal scales,
        by the spacing of the subnormal numbers, in which the centre is rounded).

    Raises
    ------
    ValueError
        Invalid points, or a radius beyond float64's range (points near ±1.8e308 in several axes).

    Examples
    --------
    The smallest disc around the unit square is centred at its middle, of radius √2/2:

    >>> import numpy as np
    >>> centre, radius = smallest_enclosing_ball([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    >>> np.round(centre, 6).tolist(), round(radius, 6)
    ([0.5, 0.5], 0.707107)
    """
    pts, e = scaled(as_points(points))  # power-of-two scaling: squared distances stay finite
    n, dim = pts.shape
    order = np.random.default_rng(check_seed(seed)).permutation(n)
    work = pts[order].copy()
    scale = float(np.max(np.abs(work - work[0]))) if n > 1 else 0.0
    tol = 1e-12 * max(scale, 1e-300) ** 2
    centre, _ = _mtf(work, n, [], dim, tol)
    with np.errstate(under="ignore"):
        out = np.ldexp(centre, -e)  # exact, except where it falls among the subnormal numbers
    return out, _radius_around(pts, np.ldexp(out, e), e)


def _radius_around(pts: np.ndarray, centre: np.ndarray, e: int) -> float:
    """The largest distance from ``centre`` to the (scaled) points, rounded up, scaled by 2^(−e).

    The search accepts points up to its tolerance outside its ball, so the radius is measured
    again: the differences, squares and sum carry a relative error below (d + 3)·u (no
    cancellation: all terms are non-negative), so the distance times 1 + 2(d + 4)·u is an upper
    bound; scaling back rounds upwards where the result is subnormal.
    """
    diff = pts - centre
    d = float(np.sqrt(np.max(np.einsum("ij,ij->i", diff, diff))))
    if d == 0.0:
        return 0.0
    up = d * (1.0 + 2.0 * (pts.shape[1] + 4) * 2.0**-53)
    with np.errstate(over="ignore", under="ignore"):
        r = float(np.ldexp(up, -e))
        if not np.isfinite(r) or r < np.finfo(np.float64).tiny:
            # at the ends of the float range (subnormal, or the bound of the error estimate past
            # 1.8e308): the smallest float that holds every point, decided exactly
            return _smallest_containing(pts, centre, e, float(np.ldexp(d, -e)))
    return r


def _smallest_containing(pts: np.ndarray, centre: np.ndarray, e: int, start: float) -> float:
    """The smallest float from ``start``'s predecessor up whose ball about ``centre`` (scaled by
    2^(−e)) holds every point, decided exactly with fractions (a few candidates; only at the ends
    of the float range)."""
    from fractions import Fraction

    c = [Fraction(float(v)) for v in centre]
    far = max(sum((Fraction(float(x)) - cv) ** 2 for x, cv in zip(p, c)) for p in pts) / Fraction(2) ** (2 * e)
    r = float(np.nextafter(start, 0.0))
    while np.isfinite(r) and Fraction(r) ** 2 < far:
        r = float(np.nextafter(r, np.inf))
    if not np.isfinite(r):
        raise ValueError("the radius of the smallest enclosing ball exceeds float64's range (about 1.8e308)")
    return r


def meb_radius_small(pts: npt.ArrayLike) -> float:
    """Radius of the smallest enclosing ball of a few points (rows of ``pts``), by subset search.

    Thesis: Definition 2.9 / Theorem 2.10 (the ball realising the Čech value of a simplex).

    Compiled C++ (``src/miniball.cpp``): the smallest ball is the circumscribed ball, within the
    affine hull, of some subset of the points, so the radius is the smallest such circumradius
    whose ball contains every point (2^k subsets, each a small Gaussian elimination).

    Parameters
    ----------
    pts : array_like of float, shape (k, d)
        The points (k at most 62).

    Returns
    -------
    float
        The radius (0 for one point or coincident points).
    """
    return miniball.meb_radius_small(np.ascontiguousarray(pts, dtype=np.float64))

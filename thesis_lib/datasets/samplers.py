"""Point samples used in chapter 2: circles, two intersecting circles, the flat torus."""

from __future__ import annotations

import numpy as np

from .._validate import check_int, check_real, check_seed, check_size

__all__ = ["noisy_circle", "two_circles", "two_circles_intersections", "flat_torus"]


def _count(name: str, n, points_per_unit: int, dim: int) -> int:
    """A positive count, refused up front if it would build more than 10⁹ coordinates."""
    n = check_int(n, name, minimum=1)
    check_size(n * points_per_unit * dim, f"coordinates ({n * points_per_unit:,} points in R^{dim})")
    return n


def _check_noise(noise) -> float:
    return check_real(noise, "noise", minimum=0.0)


def noisy_circle(n: int, *, noise: float = 0.1, seed: int = 0, radius: float = 1.0) -> np.ndarray:
    """``n`` points at uniform angles on a circle plus Gaussian noise of deviation ``noise``.

    Thesis: Figure 2.9 (point set sampled with noise from the unit circle).

    Parameters
    ----------
    n : number of points (>= 1).
    noise : standard deviation of the Gaussian noise (>= 0).
    seed : seed of the random draws.
    radius : radius of the circle (> 0).

    Returns
    -------
    ndarray, shape (n, 2)
    """
    n = _count("n", n, 1, 2)
    radius = check_real(radius, "radius", positive=True)
    rng = np.random.default_rng(check_seed(seed))
    theta = rng.uniform(0.0, 2 * np.pi, n)
    pts = radius * np.column_stack([np.cos(theta), np.sin(theta)])
    return pts + rng.normal(scale=_check_noise(noise), size=pts.shape)


def two_circles(n_per_circle: int, *, seed: int = 0, noise: float = 0.0, distance: float = 1.0) -> np.ndarray:
    """Uniform random points on two unit circles with centres ``(0, 0)`` and ``(distance, 0)``.

    Thesis: §2.4.1, Figure 2.13 (two circles meeting in exactly two points, β₀ = 1, β₁ = 3).
    The first ``n_per_circle`` rows lie on the left circle.

    Parameters
    ----------
    n_per_circle : points on each circle (>= 1).
    seed : seed of the random draws.
    noise : standard deviation of added Gaussian noise (>= 0).
    distance : distance between the centres, 0 < distance < 2.

    Returns
    -------
    ndarray, shape (2 n_per_circle, 2)
    """
    n = _count("n_per_circle", n_per_circle, 2, 2)
    distance = check_real(distance, "distance")
    if not 0 < distance < 2:
        raise ValueError(f"unit circles meet in two points only for 0 < distance < 2, got {distance}")
    rng = np.random.default_rng(check_seed(seed))
    theta = rng.uniform(0.0, 2 * np.pi, (2, n))
    left = np.column_stack([np.cos(theta[0]), np.sin(theta[0])])
    right = np.column_stack([distance + np.cos(theta[1]), np.sin(theta[1])])
    pts = np.vstack([left, right])
    return pts + rng.normal(scale=_check_noise(noise), size=pts.shape)


def two_circles_intersections(*, distance: float = 1.0) -> np.ndarray:
    """The two points where the circles of :func:`two_circles` meet (green in Figure 2.13).

    Thesis: §2.4.1, Figure 2.13.

    Parameters
    ----------
    distance : distance between the centres, 0 < distance < 2.

    Returns
    -------
    ndarray, shape (2, 2)
    """
    distance = check_real(distance, "distance")
    if not 0 < distance < 2:
        raise ValueError(f"unit circles meet in two points only for 0 < distance < 2, got {distance}")
    x = distance / 2
    y = np.sqrt(1 - x * x)
    return np.array([[x, y], [x, -y]])


def flat_torus(k: int, *, noise: float = 0.0, seed: int = 0) -> np.ndarray:
    """``k²`` points of a regular ``k × k`` grid on the flat torus S¹ × S¹ ⊂ R⁴, plus Gaussian noise.

    Thesis: §2.4.1, Figure 2.16 (100² points from the flat torus with noise).

    Parameters
    ----------
    k : grid points per circle (>= 1).
    noise : standard deviation of added Gaussian noise (>= 0).
    seed : seed of the random draws.

    Returns
    -------
    ndarray, shape (k², 4)
    """
    k = check_int(k, "k", minimum=1)
    check_size(k * k * 4, f"coordinates ({k * k:,} points in R^4)")
    noise = _check_noise(noise)
    t = 2 * np.pi * np.arange(k) / k
    u, v = np.meshgrid(t, t, indexing="ij")
    pts = np.column_stack([np.cos(u).ravel(), np.sin(u).ravel(), np.cos(v).ravel(), np.sin(v).ravel()])
    rng = np.random.default_rng(check_seed(seed))
    return pts + rng.normal(scale=noise, size=pts.shape)

"""Point samples used in chapter 2: circles, two intersecting circles, the flat torus."""

from __future__ import annotations

import numpy as np

__all__ = ["noisy_circle", "two_circles", "two_circles_intersections", "flat_torus"]


def _check_positive(name: str, n) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"{name} must be a positive integer, got {n!r}")
    return int(n)


def _check_noise(noise: float) -> float:
    noise = float(noise)
    if not np.isfinite(noise) or noise < 0:
        raise ValueError(f"noise must be a finite non-negative number, got {noise!r}")
    return noise


def noisy_circle(n: int, noise: float = 0.1, seed: int = 0, radius: float = 1.0) -> np.ndarray:
    """``n`` points at uniform angles on a circle plus Gaussian noise of deviation ``noise``.

    Thesis: Figure 2.9 (point set sampled with noise from the unit circle).
    """
    n = _check_positive("n", n)
    rng = np.random.default_rng(seed)
    theta = rng.uniform(0.0, 2 * np.pi, n)
    pts = radius * np.column_stack([np.cos(theta), np.sin(theta)])
    return pts + rng.normal(scale=_check_noise(noise), size=pts.shape)


def two_circles(n_per_circle: int, seed: int = 0, noise: float = 0.0, distance: float = 1.0) -> np.ndarray:
    """Uniform random points on two unit circles with centres ``(0, 0)`` and ``(distance, 0)``.

    Thesis: §2.4.1, Figure 2.13 (two circles meeting in exactly two points, β₀ = 1, β₁ = 3).
    The first ``n_per_circle`` rows lie on the left circle.
    """
    n = _check_positive("n_per_circle", n_per_circle)
    if not 0 < distance < 2:
        raise ValueError(f"unit circles meet in two points only for 0 < distance < 2, got {distance}")
    rng = np.random.default_rng(seed)
    theta = rng.uniform(0.0, 2 * np.pi, (2, n))
    left = np.column_stack([np.cos(theta[0]), np.sin(theta[0])])
    right = np.column_stack([distance + np.cos(theta[1]), np.sin(theta[1])])
    pts = np.vstack([left, right])
    return pts + rng.normal(scale=_check_noise(noise), size=pts.shape)


def two_circles_intersections(distance: float = 1.0) -> np.ndarray:
    """The two points where the circles of :func:`two_circles` meet (green in Figure 2.13)."""
    x = distance / 2
    y = np.sqrt(1 - x * x)
    return np.array([[x, y], [x, -y]])


def flat_torus(k: int, noise: float = 0.0, seed: int = 0) -> np.ndarray:
    """``k²`` points of a regular ``k × k`` grid on the flat torus S¹ × S¹ ⊂ R⁴, plus Gaussian noise.

    Thesis: §2.4.1, Figure 2.16 (100² points from the flat torus with noise).
    """
    k = _check_positive("k", k)
    t = 2 * np.pi * np.arange(k) / k
    u, v = np.meshgrid(t, t, indexing="ij")
    pts = np.column_stack([np.cos(u).ravel(), np.sin(u).ravel(), np.cos(v).ravel(), np.sin(v).ravel()])
    rng = np.random.default_rng(seed)
    return pts + rng.normal(scale=_check_noise(noise), size=pts.shape)

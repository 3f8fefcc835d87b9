"""The n-sphere of §3.4.2: its parametrisation by angles, exact mean curvature, volume and a quadrature on it.

Sign conventions: those of :mod:`thesis_lib.surfaces`.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_floats, check_int, check_real

__all__ = ["hypersphere_point", "hypersphere_mean_curvature", "hypersphere_quadrature", "hypersphere_volume"]


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
    radius = check_real(radius, "radius", positive=True)
    a = as_floats(angles, "angles")
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
    radius = check_real(radius, "radius", positive=True)
    n = check_int(n, "n", minimum=1)
    return 1.0 / radius



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
    n = check_int(n, "n", minimum=1)
    nodes = check_int(nodes, "nodes", minimum=2)
    x, wx = np.polynomial.legendre.leggauss(int(nodes))
    psi, wpsi = 0.5 * np.pi * (x + 1), 0.5 * np.pi * wx
    phi = 2 * np.pi * np.arange(2 * nodes) / (2 * nodes)
    wphi = np.full(2 * nodes, 2 * np.pi / (2 * nodes))
    axes, weights = [psi] * (n - 1) + [phi], [wpsi] * (n - 1) + [wphi]
    grids = np.meshgrid(*axes, indexing="ij")
    wgrid = np.meshgrid(*weights, indexing="ij")
    params = np.stack([gr.ravel() for gr in grids], axis=1)
    return params, np.prod(np.stack([wg.ravel() for wg in wgrid]), axis=0)



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
    n = check_int(n, "n", minimum=1)
    x, wx = np.polynomial.legendre.leggauss(int(nodes))
    psi, wpsi = 0.5 * np.pi * (x + 1), 0.5 * np.pi * wx
    return float(2 * np.pi * np.prod([np.sum(wpsi * np.sin(psi) ** k) for k in range(1, n)]))


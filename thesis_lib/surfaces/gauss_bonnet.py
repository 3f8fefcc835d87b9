"""The Gauss–Bonnet–Chern theorem for hypersurfaces (§3.2): total Gauss–Kronecker curvature and its constant.

Sign conventions: those of :mod:`thesis_lib.surfaces`.
"""

from __future__ import annotations

from collections.abc import Callable
from math import factorial

import numpy as np
import numpy.typing as npt

from .._validate import as_floats
from .parametric import fundamental_forms

__all__ = ["total_gauss_kronecker_curvature", "gauss_bonnet_chern_constant"]


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
    >>> from thesis_lib.surfaces import ellipsoid_point, hypersphere_quadrature
    >>> params, weights = hypersphere_quadrature(2, nodes=16)
    >>> ellipsoid = lambda w: ellipsoid_point(w, [3.0, 2.0, 1.0])
    >>> round(total_gauss_kronecker_curvature(ellipsoid, params, weights) / (4 * np.pi), 6)
    1.0
    """
    w = as_floats(weights, "weights")
    g, B = fundamental_forms(X, params, h=h)
    if w.shape != g.shape[:-2]:
        raise ValueError(f"weights {w.shape} do not match params {g.shape[:-2]}")
    return float(np.sum(w * np.linalg.det(B) / np.sqrt(np.linalg.det(g))))



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
    >>> from thesis_lib.surfaces import hypersphere_volume
    >>> round(2 * gauss_bonnet_chern_constant(4), 6) == round(hypersphere_volume(4), 6)
    True
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2 or n % 2:
        raise ValueError(f"n must be an even integer >= 2, got {n!r}")
    m = n // 2
    return float(np.pi**m * 2**n * factorial(m) / factorial(n))


"""Any parametrised hypersurface X: its normal, fundamental forms and shape operator by differentiation (§3.1).

Sign conventions: those of :mod:`thesis_lib.surfaces`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from .._validate import as_floats, check_int, check_real

__all__ = ["hypersurface_normal", "fundamental_forms", "parametric_shape_operator", "normal_curvature_circle"]


def hypersurface_normal(jacobian: npt.ArrayLike) -> np.ndarray:
    """Unit normal N = X_{u_1} ∧ ... ∧ X_{u_n} / W from Jacobians (..., n+1, n), with det[J | N] > 0.

    For n = 2 this is (X_u × X_v)/|X_u × X_v|.  Thesis: eq. (3.9).

    Parameters
    ----------
    jacobian : array_like, shape (..., n + 1, n)
        The columns X_{u_1}, ..., X_{u_n} at each point.

    Returns
    -------
    ndarray of float64, shape (..., n + 1)
        The unit normal N at each point.

    Raises
    ------
    ValueError
        If ``jacobian`` is not (..., n + 1, n), holds NaN or infinite values, or has rank < n
        somewhere (the parametrisation is not regular).

    Examples
    --------
    The plane spanned by X_u = (1, 0, 1) and X_v = (0, 1, 1) has the normal X_u × X_v / ‖·‖:

    >>> import numpy as np
    >>> np.round(hypersurface_normal([[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]), 6).tolist()
    [-0.57735, -0.57735, 0.57735]
    """
    J = as_floats(jacobian, "jacobian")
    if J.ndim < 2 or J.shape[-2] != J.shape[-1] + 1:
        raise ValueError(f"jacobian must have shape (..., n+1, n), got {J.shape}")
    n = J.shape[-1]
    comps = []
    for i in range(n + 1):
        minor = np.delete(J, i, axis=-2)
        comps.append((-1) ** (i + n) * np.linalg.det(minor))
    N = np.stack(comps, axis=-1)
    norm = np.linalg.norm(N, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("the parametrisation is not regular here (X_* has rank < n)")
    return N / norm



def _parameters(w) -> np.ndarray:
    w = as_floats(w, "w")
    if w.ndim < 1:
        raise ValueError("w must have shape (..., n)")
    return w



def _step(h: float) -> float:
    return check_real(h, "h", positive=True)



def fundamental_forms(
    X: Callable[[np.ndarray], np.ndarray], w: npt.ArrayLike, *, h: float = 1e-4
) -> tuple[np.ndarray, np.ndarray]:
    """First and second fundamental forms g_ij = <X_i, X_j>, B_ij = <N, X_ij> by central differences.

    A tangent vector with parameter components a has I(a) = aᵀ g a and II(a) = aᵀ B a, and its
    normal curvature is II(a)/I(a) (eq. 3.1).
    Thesis: Definitions 3.1–3.2 and eq. (3.9).

    Parameters
    ----------
    X : callable
        The parametrisation: maps parameters (..., n) to points (..., n + 1), vectorised.
    w : array_like, shape (..., n)
        The parameters at which to evaluate.
    h : float, default 1e-4
        The finite-difference step.

    Returns
    -------
    g, B : ndarray of float64, shape (..., n, n)
        The first and second fundamental forms in the basis (X_{u_1}, ..., X_{u_n}), with N the
        normal of eq. (3.9).

    Raises
    ------
    ValueError
        If ``w`` is not (..., n) or holds NaN or infinite values, ``h`` is not positive, ``X`` does
        not map (..., n) to (..., n + 1), or the parametrisation is not regular at ``w``.

    Examples
    --------
    On the sphere of radius 2 at a point of the equator, g = ρ² I and B = −ρ I:

    >>> import numpy as np
    >>> from thesis_lib.surfaces import hypersphere_point, torus_point
    >>> g, B = fundamental_forms(lambda w: hypersphere_point(w, radius=2.0), [np.pi / 2, 0.0])
    >>> np.round(g, 4).tolist(), np.round(B, 4).tolist()
    ([[4.0, 0.0], [0.0, 4.0]], [[-2.0, 0.0], [0.0, -2.0]])
    """
    w, h = _parameters(w), _step(h)
    n = w.shape[-1]
    eye = np.eye(n) * h
    X0 = np.asarray(X(w), dtype=np.float64)
    if X0.shape != w.shape[:-1] + (n + 1,):
        raise ValueError(f"X must map (..., {n}) to (..., {n + 1}), got {X0.shape}")
    first = np.stack([(X(w + eye[i]) - X(w - eye[i])) / (2 * h) for i in range(n)], axis=-1)
    second = np.empty(w.shape[:-1] + (n + 1, n, n))
    for i in range(n):
        for j in range(i, n):
            if i == j:
                d = (X(w + eye[i]) - 2 * X0 + X(w - eye[i])) / h**2
            else:
                d = (
                    X(w + eye[i] + eye[j]) - X(w + eye[i] - eye[j])
                    - X(w - eye[i] + eye[j]) + X(w - eye[i] - eye[j])
                ) / (4 * h * h)
            second[..., i, j] = second[..., j, i] = d
    N = hypersurface_normal(first)
    g = np.einsum("...ki,...kj->...ij", first, first)
    B = np.einsum("...k,...kij->...ij", N, second)
    return g, B



def parametric_shape_operator(X: Callable[[np.ndarray], np.ndarray], w: npt.ArrayLike,
                              *, h: float = 1e-4) -> np.ndarray:
    """Shape operator S = g⁻¹ B of a parametrisation X: (..., n) -> (..., n+1), by central differences.

    g_ij = <X_i, X_j> (first fundamental form), B_ij = <N, X_ij> = <S X_i, X_j> (second), so the
    matrix of S = -N_* in the basis (X_{u_1}, ..., X_{u_n}) is g⁻¹ B.
    Thesis: Definitions 3.1–3.2 and eq. (3.10).

    Parameters
    ----------
    X : callable
        Parametrisation (..., n) -> (..., n + 1) of the hypersurface, vectorised.
    w : array_like, shape (..., n)
        The parameters at which S is wanted.
    h : float, default 1e-4
        Step of the central differences of :func:`fundamental_forms`.

    Returns
    -------
    ndarray of float64, shape (..., n, n)
        The matrix of S at each parameter.

    Raises
    ------
    ValueError
        As :func:`fundamental_forms`.

    Examples
    --------
    From the parametrisation alone, S = g⁻¹B: −I/ρ on the sphere of radius 2, and the torus's
    diag(−1/15, −1/5) on its outer equator:

    >>> import numpy as np
    >>> from thesis_lib.surfaces import hypersphere_point, torus_point
    >>> np.round(parametric_shape_operator(lambda w: hypersphere_point(w, radius=2.0), [np.pi / 2, 0.0]), 4).tolist()
    [[-0.5, 0.0], [0.0, -0.5]]
    >>> torus = lambda w: torus_point(w[..., 0], w[..., 1])
    >>> np.round(parametric_shape_operator(torus, [0.0, 0.0]), 4).tolist()
    [[-0.0667, 0.0], [0.0, -0.2]]
    """
    g, B = fundamental_forms(X, w, h=h)
    return np.linalg.solve(g, B)



def normal_curvature_circle(X: Callable[[np.ndarray], np.ndarray], w: npt.ArrayLike, *, nodes: int = 64,
                            h: float = 1e-4) -> np.ndarray:
    """Normal curvature II(t)/I(t) of a surface (n = 2) at parameters w in the unit tangent directions
    t(θ_k) = cos θ_k e₁ + sin θ_k e₂, θ_k = 2πk/nodes, with (e₁, e₂) the orthonormal frame that
    Gram–Schmidt makes of (X_u, X_v).

    Definition 3.3 takes κ₁, κ₂ as the minimum and maximum over θ; eq. (3.23) integrates over θ
    (the trapezoid rule is exact here for nodes ≥ 3: κ_n is a trigonometric polynomial of degree 2).
    Thesis: eq. (3.1), Definition 3.3 and eq. (3.23).

    Parameters
    ----------
    X : callable
        The parametrisation of a surface: maps parameters (..., 2) to points (..., 3), vectorised.
    w : array_like, shape (..., 2)
        The parameters of the points at which the tangent direction turns.
    nodes : int, default 64
        How many directions θ_k, at least 3.
    h : float, default 1e-4
        Step of the central differences (see :func:`fundamental_forms`).

    Returns
    -------
    ndarray of float64, shape (..., nodes)
        The normal curvature in direction θ_k at each parameter.

    Raises
    ------
    ValueError
        As :func:`fundamental_forms`; also if n ≠ 2 or ``nodes`` is not an integer >= 3.

    Examples
    --------
    Four directions on the torus's outer equator: the normal curvature swings between its principal
    values −1/15 and −1/5 (Euler's formula):

    >>> import numpy as np
    >>> from thesis_lib.surfaces import torus_point
    >>> torus = lambda w: torus_point(w[..., 0], w[..., 1])
    >>> np.round(normal_curvature_circle(torus, [0.0, 0.0], nodes=4), 4).tolist()
    [-0.0667, -0.2, -0.0667, -0.2]
    """
    g, B = fundamental_forms(X, w, h=h)
    if g.shape[-1] != 2:
        raise ValueError(f"normal_curvature_circle needs a surface (n = 2), got n = {g.shape[-1]}")
    nodes = check_int(nodes, "nodes", minimum=3)
    L = np.linalg.cholesky(g)  # g = L Lᵀ: parameter components of the orthonormal frame are L⁻ᵀ
    Linv = np.linalg.inv(L)
    S_orth = np.einsum("...ij,...jk,...lk->...il", Linv, B, Linv)  # L⁻¹ B L⁻ᵀ, symmetric
    theta = 2 * np.pi * np.arange(nodes) / nodes
    c = np.stack([np.cos(theta), np.sin(theta)])  # (2, nodes)
    return np.einsum("ik,...ij,jk->...k", c, S_orth, c)


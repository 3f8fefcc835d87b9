"""Numerical evidence for the smooth and algebraic statements of chapter 3 (§3.1–§3.3).

Each function computes, from the thesis's own definitions, the number one of its statements
predicts, by a route that does not assume the statement: the Hodge dual of §3.1.1 from its defining
rule, the first variation of area (Theorems 3.9 and 3.12) as a finite difference of the area of a
varied surface, the area of the Gauss image (eq. 3.3), the geodesic curvature of a boundary curve
(Theorem 3.5), the pullback of the volume form (eq. 3.14), exterior products by their Plücker
coordinates (Proposition 3.17, the Gram determinant of Theorem 3.18), Jacobi's formula
(Theorem 3.16), Theorem 3.18's gradient as printed and the cotangent formula (3.18) and Example 3.20
on triangle meshes.  Two helpers read numbers off the thesis text for its numbering slips.  The
book's chapter 3 page calls them; ``tests/test_chapter3_checks.py`` pins them to closed forms.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from itertools import combinations
from math import factorial

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..surfaces import fundamental_forms, hypersurface_normal
from .checks import dihedral_cotangent_sum, hyperarea_gradient_fd
from .geometry import simplex_hyperareas

__all__ = [
    "hodge_dual",
    "wedge_coordinates",
    "proposition_3_17_residual",
    "jacobi_formula_residual",
    "theorem_3_18_printed_gradient",
    "printed_gram_determinant",
    "parametric_jacobian",
    "first_variation_of_area",
    "mean_curvature_integral",
    "gauss_map_area_ratio",
    "cap_boundary_geodesic_curvature",
    "gauss_map_pullback_ratio",
    "cotangent_formula_gradient",
    "example_3_20_gradient",
    "mesh_area_gradient_fd",
    "circumcentre_inside",
    "statement_containing",
    "chapter_of",
]

Param = Callable[[np.ndarray], np.ndarray]


def hodge_dual(u: ArrayLike, v: ArrayLike) -> NDArray[np.float64]:
    """*(u ∧ v) ∈ R³ by the rule of §3.1.1: ⟨*A, x⟩ e₁∧e₂∧e₃ = x ∧ A, so (*A)_k = det(e_k, u, v).

    Thesis: §3.1.1 (Remark on the Hodge dual).

    Parameters
    ----------
    u, v : array_like, shape (..., 3)
        The two vectors of the 2-vector u ∧ v.

    Returns
    -------
    ndarray of float64, shape (..., 3)
        The vector *(u ∧ v).

    Raises
    ------
    ValueError
        If ``u`` and ``v`` are not vectors of R³ of the same shape.
    """
    u, v = np.asarray(u, dtype=np.float64), np.asarray(v, dtype=np.float64)
    if u.shape != v.shape or u.shape[-1:] != (3,):
        raise ValueError(f"u and v must be vectors of R^3 of one shape, got {u.shape} and {v.shape}")
    eye = np.broadcast_to(np.eye(3), u.shape[:-1] + (3, 3))
    return np.stack([np.linalg.det(np.stack([eye[..., k, :], u, v], axis=-2)) for k in range(3)], axis=-1)


def wedge_coordinates(vectors: ArrayLike) -> NDArray[np.float64]:
    """Plücker coordinates of v₁ ∧ ⋯ ∧ v_k in R^d: the k × k minors on the rows i₁ < ⋯ < i_k.

    Two k-vectors are equal exactly when their coordinates are, and ‖v₁ ∧ ⋯ ∧ v_k‖² is the sum of
    their squares.  Thesis: Proposition 3.17 and Theorem 3.18 (exterior products).

    Parameters
    ----------
    vectors : array_like, shape (..., k, d)
        The k factors, 1 <= k <= d.

    Returns
    -------
    ndarray of float64, shape (..., C(d, k))
        The minors, the row sets in lexicographic order.

    Raises
    ------
    ValueError
        If ``vectors`` is not (..., k, d) with 1 <= k <= d.
    """
    a = np.asarray(vectors, dtype=np.float64)
    if a.ndim < 2 or not 1 <= a.shape[-2] <= a.shape[-1]:
        raise ValueError(f"vectors must have shape (..., k, d) with 1 <= k <= d, got {a.shape}")
    k, d = a.shape[-2:]
    return np.stack([np.linalg.det(a[..., list(rows)]) for rows in combinations(range(d), k)], axis=-1)


def proposition_3_17_residual(n: int, *, d: int | None = None, count: int = 50, seed: int = 0) -> float:
    """Largest relative difference between the two sides of Proposition 3.17 over random vectors.

    y_i = x_i − x_j; y₁ ∧ ⋯ ŷ_j ⋯ ∧ y_n against Σ_i (−1)^{i+j} x₁ ∧ ⋯ x̂_i ⋯ ∧ x_n, for every j,
    compared by their Plücker coordinates (:func:`wedge_coordinates`).
    Thesis: Proposition 3.17.

    Parameters
    ----------
    n : int
        Number of vectors x_i, n >= 2.
    d : int, optional
        Dimension of the space, at least n − 1 (default n + 1, the setting of Theorem 3.18).
    count : int, default 50
        How many random draws (standard normal vectors).
    seed : int, default 0
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    float
        max over draws and j of ‖lhs − rhs‖ / ‖lhs‖.

    Raises
    ------
    ValueError
        If ``n`` < 2, ``d`` < n − 1 or ``count`` < 1.
    """
    d = n + 1 if d is None else int(d)
    if n < 2 or d < n - 1 or count < 1:
        raise ValueError(f"need n >= 2, d >= n - 1 and count >= 1, got n={n}, d={d}, count={count}")
    x = np.random.default_rng(seed).normal(size=(count, n, d))
    worst = 0.0
    for j in range(n):
        y = np.delete(x - x[:, j : j + 1], j, axis=1)
        lhs = wedge_coordinates(y)
        rhs = sum((-1) ** (i + j) * wedge_coordinates(np.delete(x, i, axis=1)) for i in range(n))
        worst = max(worst, float(np.max(np.linalg.norm(lhs - rhs, axis=1) / np.linalg.norm(lhs, axis=1))))
    return worst


def jacobi_formula_residual(size: int, *, count: int = 50, h: float = 1e-6, seed: int = 0) -> float:
    """Largest relative difference of d(det A)[dA] (central difference) and tr(adj(A) dA).

    adj(A) is computed from cofactors (not as det(A) A⁻¹).  Thesis: Theorem 3.16.

    Parameters
    ----------
    size : int
        The matrices are size × size, size >= 1.
    count : int, default 50
        How many random pairs (A, dA) (standard normal entries).
    h : float, default 1e-6
        The finite-difference step.
    seed : int, default 0
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    float
        max |fd − formula| / |formula| over the pairs.

    Raises
    ------
    ValueError
        If ``size`` or ``count`` < 1.
    """
    if size < 1 or count < 1:
        raise ValueError(f"size and count must be >= 1, got {size}, {count}")
    rng = np.random.default_rng(seed)
    A, dA = rng.normal(size=(count, size, size)), rng.normal(size=(count, size, size))
    adj = np.empty_like(A)
    for i in range(size):
        for j in range(size):
            minor = np.delete(np.delete(A, j, axis=1), i, axis=2)  # adj_ij = (−1)^{i+j} M_ji
            adj[:, i, j] = (-1) ** (i + j) * (np.linalg.det(minor) if size > 1 else 1.0)
    formula = np.einsum("mij,mji->m", adj, dA)
    fd = (np.linalg.det(A + h * dA) - np.linalg.det(A - h * dA)) / (2 * h)
    return float(np.max(np.abs(fd - formula) / np.abs(formula)))


def theorem_3_18_printed_gradient(points: ArrayLike) -> NDArray[np.float64]:
    """Theorem 3.18's ∇_q A as printed, at q = ``points[:, 0]`` of each n-simplex, shape (m, d).

    ∇_q A = 1/((n!)² A) Σ_i −x_i ⟨x₁ ∧ ⋯ x̂_i ⋯ ∧ x_n, y_1i ∧ ⋯ ŷ_ii ⋯ ∧ y_ni⟩ with x_i = p_i − q,
    y_ki = x_k − x_i and ⟨a₁ ∧ ⋯, b₁ ∧ ⋯⟩ = det(⟨a_k, b_l⟩), term by term.
    Thesis: Theorem 3.18.

    Parameters
    ----------
    points : array_like, shape (m, n + 1, d)
        Vertex coordinates of m non-degenerate n-simplices (n >= 2, d >= n); vertex 0 is q.

    Returns
    -------
    ndarray of float64, shape (m, d)
        The printed gradient for each simplex.

    Raises
    ------
    ValueError
        If ``points`` is not (m, n + 1, d) with m >= 1, n >= 2 and d >= n, or is not finite.
    """
    p = np.asarray(points, dtype=np.float64)
    if p.ndim != 3 or p.shape[1] < 3 or p.shape[2] < p.shape[1] - 1 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError(f"points must be a finite (m, n + 1, d) array with n >= 2 and d >= n, got {p.shape}")
    m, w, d = p.shape
    n = w - 1
    x = p[:, 1:] - p[:, :1]  # (m, n, d)
    area = simplex_hyperareas(p.reshape(-1, d), np.arange(m * w).reshape(m, w))
    grad = np.zeros((m, d))
    for i in range(n):
        a = np.delete(x, i, axis=1)  # x_k, k ≠ i
        b = a - x[:, i : i + 1]  # y_ki = x_k − x_i, k ≠ i
        inner = np.linalg.det(np.einsum("mka,mla->mkl", a, b))
        grad -= x[:, i] * inner[:, None]
    return grad / (factorial(n) ** 2 * area)[:, None]


def printed_gram_determinant(x: ArrayLike) -> NDArray[np.float64]:
    """det Ĝ with Ĝ as printed in the proof of Theorem 3.18: the Gram matrix of x₁, …, x_n except
    that its entry (1, 1) reads ⟨x₁, x₂⟩.

    Thesis: Theorem 3.18 (its proof, the Gram determinant).

    Parameters
    ----------
    x : array_like, shape (m, n, d)
        m families of n >= 2 vectors.

    Returns
    -------
    ndarray of float64, shape (m,)
        The determinant of the printed matrix for each family.

    Raises
    ------
    ValueError
        If ``x`` is not (m, n, d) with n >= 2.
    """
    x = np.asarray(x, dtype=np.float64)
    if x.ndim != 3 or x.shape[1] < 2:
        raise ValueError(f"x must have shape (m, n, d) with n >= 2, got {x.shape}")
    G = np.einsum("mka,mla->mkl", x, x)
    G[:, 0, 0] = G[:, 0, 1]
    return np.linalg.det(G)


def parametric_jacobian(X: Param, w: ArrayLike, *, h: float = 1e-5) -> NDArray[np.float64]:
    """Central-difference Jacobian (X_{u_1}, …, X_{u_n}) of a parametrisation, shape (..., n + 1, n).

    Thesis: §3.1.1 (X_*) and eq. (3.8).

    Parameters
    ----------
    X : callable
        Parametrisation (..., n) -> (..., n + 1), vectorised.
    w : array_like, shape (..., n)
        The parameters.
    h : float, default 1e-5
        The step.

    Returns
    -------
    ndarray of float64, shape (..., n + 1, n)
        The columns X_{u_i}.

    Raises
    ------
    ValueError
        If ``h`` is not positive.
    """
    if not h > 0:
        raise ValueError(f"step h must be positive, got {h!r}")
    w = np.asarray(w, dtype=np.float64)
    eye = np.eye(w.shape[-1]) * h
    return np.stack([(X(w + e) - X(w - e)) / (2 * h) for e in eye], axis=-1)


def _area(X: Param, params: np.ndarray, weights: np.ndarray, h: float) -> float:
    J = parametric_jacobian(X, params, h=h)
    return float(np.sum(weights * np.sqrt(np.linalg.det(np.einsum("...ai,...aj->...ij", J, J)))))


def first_variation_of_area(X: Param, Y: Param, params: ArrayLike, weights: ArrayLike, *, eps: float = 1e-3,
                            h: float = 1e-5) -> float:
    """δA(X, Y) = d/dε A(X + εY) at ε = 0, by a four-point difference in ε of quadrature areas.

    A(Z) = Σ weights · ‖Z_{u_1} ∧ ⋯ ∧ Z_{u_n}‖ (Jacobians by central differences), so nothing of
    Theorems 3.9 and 3.12 enters the computation.  Thesis: §3.1.3 (δA_Ω(X, Y)), Theorems 3.9 and 3.12.

    Parameters
    ----------
    X : callable
        Parametrisation (..., n) -> (..., n + 1) of the hypersurface, vectorised.
    Y : callable
        The variation field (..., n) -> (..., n + 1), vectorised.
    params, weights : array_like, shapes (k, n) and (k,)
        Quadrature nodes in parameter space and their weights.
    eps : float, default 1e-3
        Step in ε.
    h : float, default 1e-5
        Step of the Jacobians.

    Returns
    -------
    float
        The first variation of the area.

    Raises
    ------
    ValueError
        If ``weights`` does not match ``params`` or a step is not positive.
    """
    params, weights = np.asarray(params, dtype=np.float64), np.asarray(weights, dtype=np.float64)
    if weights.shape != params.shape[:1] or not eps > 0:
        raise ValueError("weights must have one entry per node and eps must be positive")
    a = {k: _area(lambda w, k=k: X(w) + k * eps * Y(w), params, weights, h) for k in (-2, -1, 1, 2)}
    return (a[-2] - 8 * a[-1] + 8 * a[1] - a[2]) / (12 * eps)


def mean_curvature_integral(X: Param, normal: Param, lam: Param, params: ArrayLike, weights: ArrayLike, *,
                            h: float = 1e-4) -> float:
    """∫_X λ H dA with H = tr(S)/n and S = −N_* for the unit normal ``normal`` (Definition 3.10).

    The shape operator comes from the fundamental forms by central differences; its sign follows
    the given normal (H changes sign with N).  Thesis: Theorems 3.9 and 3.12 (their right-hand sides).

    Parameters
    ----------
    X : callable
        Parametrisation (..., n) -> (..., n + 1), vectorised.
    normal : callable
        The unit normal N (..., n) -> (..., n + 1) the variation λN uses.
    lam : callable
        The function λ (..., n) -> (...).
    params, weights : array_like, shapes (k, n) and (k,)
        Quadrature nodes in parameter space and their weights.
    h : float, default 1e-4
        Step of the fundamental forms.

    Returns
    -------
    float
        The integral.

    Raises
    ------
    ValueError
        As :func:`thesis_lib.surfaces.parametric.fundamental_forms`.
    """
    params, weights = np.asarray(params, dtype=np.float64), np.asarray(weights, dtype=np.float64)
    g, B = fundamental_forms(X, params, h=h)
    n = g.shape[-1]
    sign = np.sign(np.einsum("...a,...a->...", hypersurface_normal(parametric_jacobian(X, params)), normal(params)))
    H = sign * np.trace(np.linalg.solve(g, B), axis1=-2, axis2=-1) / n
    return float(np.sum(weights * lam(params) * H * np.sqrt(np.linalg.det(g))))


def gauss_map_area_ratio(X: Param, w0: ArrayLike, radius: float, *, nodes: int = 8, h: float = 1e-5) -> float:
    """A_Ω(N) / A_Ω(X) on the parameter disc of ``radius`` around w0, over |K(w0)| (eq. 3.3).

    N is the unit normal of eq. (3.9) from a central-difference Jacobian, its own Jacobian again by
    central differences; the areas by Gauss–Legendre quadrature in polar coordinates around w0.
    Thesis: eq. (3.3).

    Parameters
    ----------
    X : callable
        Parametrisation (..., 2) -> (..., 3) of a surface, vectorised.
    w0 : array_like, shape (2,)
        The centre.
    radius : float
        Radius of the parameter disc Ω_ε.
    nodes : int, default 8
        Gauss–Legendre nodes in the radius (4·nodes angles).
    h : float, default 1e-5
        Step of the Jacobians.

    Returns
    -------
    float
        The ratio of the two areas over |K(w0)|; 1 in the limit radius → 0 if eq. (3.3) holds.

    Raises
    ------
    ValueError
        If ``radius`` is not positive or X is not a surface in R³.
    """
    if not radius > 0:
        raise ValueError(f"radius must be positive, got {radius!r}")
    w0 = np.asarray(w0, dtype=np.float64)
    x, wx = np.polynomial.legendre.leggauss(nodes)
    rho, wrho = radius / 2 * (x + 1), radius / 2 * wx
    t = 2 * np.pi * np.arange(4 * nodes) / (4 * nodes)
    P, T = np.meshgrid(rho, t, indexing="ij")
    W = np.outer(wrho * rho, np.full(len(t), 2 * np.pi / len(t))).ravel()
    w = w0 + np.column_stack([(P * np.cos(T)).ravel(), (P * np.sin(T)).ravel()])

    def N(a: np.ndarray) -> np.ndarray:
        return hypersurface_normal(parametric_jacobian(X, a, h=h))

    JX, JN = parametric_jacobian(X, w, h=h), parametric_jacobian(N, w, h=1e3 * h)
    area_X = np.sum(W * np.linalg.norm(np.cross(JX[..., 0], JX[..., 1]), axis=-1))
    area_N = np.sum(W * np.linalg.norm(np.cross(JN[..., 0], JN[..., 1]), axis=-1))
    g, B = fundamental_forms(X, w0[None], h=1e-4)
    return float(area_N / area_X / abs(np.linalg.det(np.linalg.solve(g, B))[0]))


def cap_boundary_geodesic_curvature(X: Param, psi0: float, *, nodes: int = 256, h: float = 1e-4) -> float:
    """∫ κ_g ds along the boundary ψ = ψ0 of the cap {ψ < ψ0} of a surface X(ψ, φ), φ periodic.

    c(φ) = X(ψ0, φ); T = c'/|c'|, U = N of eq. (3.9), side normal 𝒮 = U ∧ T, κ_g = ⟨dT/ds, 𝒮⟩;
    the boundary is traversed so that 𝒮 points into the cap (positively oriented, as for eq. 3.6).
    The trapezoid rule in φ (spectrally accurate); derivatives by central differences.
    Thesis: Theorem 3.5, eq. (3.6).

    Parameters
    ----------
    X : callable
        Parametrisation (..., 2) -> (..., 3), with the cap at small ψ and φ ∈ [0, 2π) periodic.
    psi0 : float
        The boundary's ψ.
    nodes : int, default 256
        Trapezoid nodes in φ.
    h : float, default 1e-4
        Step of the derivatives.

    Returns
    -------
    float
        The total geodesic curvature of the boundary.

    Raises
    ------
    ValueError
        If ``nodes`` < 3 or ``h`` is not positive.
    """
    if nodes < 3 or not h > 0:
        raise ValueError("nodes must be >= 3 and h positive")
    phi = 2 * np.pi * np.arange(nodes) / nodes
    w = np.column_stack([np.full(nodes, float(psi0)), phi])
    e = np.array([0.0, h])
    c1 = (X(w + e) - X(w - e)) / (2 * h)
    c2 = (X(w + e) - 2 * X(w) + X(w - e)) / h**2
    speed = np.linalg.norm(c1, axis=1)
    T = c1 / speed[:, None]
    dT_ds = (c2 * speed[:, None] ** 2 - c1 * np.einsum("ka,ka->k", c1, c2)[:, None]) / speed[:, None] ** 4
    J = parametric_jacobian(X, w, h=h)
    side = np.cross(hypersurface_normal(J), T)
    orientation = -np.sign(np.einsum("ka,ka->k", side, J[..., 0]))  # 𝒮 into the cap: against X_ψ
    return float(np.sum(orientation * np.einsum("ka,ka->k", dT_ds, side) * speed) * 2 * np.pi / nodes)


def gauss_map_pullback_ratio(X: Param, w: ArrayLike, *, h: float = 1e-5) -> NDArray[np.float64]:
    """det(N, D N ξ₁, …, D N ξ_n) / (K · det(N, ξ₁, …, ξ_n)) with ξ_i = X_{u_i} (eq. 3.14's pullback).

    D N ξ_i = N_{u_i} by central differences of the normal of eq. (3.9); K = det S from the
    fundamental forms.  Since D N = −S the ratio is (−1)ⁿ: 1 in the even dimensions of Theorem 3.11.
    Thesis: eq. (3.14).

    Parameters
    ----------
    X : callable
        Parametrisation (..., n) -> (..., n + 1), vectorised.
    w : array_like, shape (k, n)
        The parameters.
    h : float, default 1e-5
        Step of the Jacobian of X (the normal's Jacobian uses 10³ h).

    Returns
    -------
    ndarray of float64, shape (k,)
        The ratio at each parameter.

    Raises
    ------
    ValueError
        As :func:`thesis_lib.surfaces.parametric.fundamental_forms`.
    """
    w = np.asarray(w, dtype=np.float64)

    def N(a: np.ndarray) -> np.ndarray:
        return hypersurface_normal(parametric_jacobian(X, a, h=h))

    n0 = N(w)
    JX, JN = parametric_jacobian(X, w, h=h), parametric_jacobian(N, w, h=1e3 * h)
    num = np.linalg.det(np.concatenate([n0[..., None], JN], axis=-1))
    den = np.linalg.det(np.concatenate([n0[..., None], JX], axis=-1))
    g, B = fundamental_forms(X, w, h=1e-4)
    return num / (den * np.linalg.det(np.linalg.solve(g, B)))


def _triangles(vertices: ArrayLike, faces: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    v, f = np.asarray(vertices, dtype=np.float64), np.asarray(faces)
    if v.ndim != 2 or f.ndim != 2 or f.shape[1] != 3 or len(f) == 0 or not np.isfinite(v).all():
        raise ValueError(f"need finite vertices (nv, d) and triangles (m, 3), got {v.shape} and {f.shape}")
    if f.min() < 0 or f.max() >= len(v):
        raise ValueError("faces refer to vertices that do not exist")
    return v, f


def cotangent_formula_gradient(vertices: ArrayLike, faces: ArrayLike) -> NDArray[np.float64]:
    """½ Σ_j (cot α_ij + cot β_ij)(p − q_j) at every vertex p, edge by edge (eq. 3.18 as printed).

    Each triangle adds ½ cot γ (p − q) at both ends p, q of each of its edges, γ the angle opposite
    that edge.  Thesis: eq. (3.18).

    Parameters
    ----------
    vertices : array_like, shape (nv, d)
        Vertex coordinates.
    faces : array_like of int, shape (m, 3)
        The triangles.

    Returns
    -------
    ndarray of float64, shape (nv, d)
        The formula's value at each vertex.

    Raises
    ------
    ValueError
        If the arrays are malformed or hold NaN.
    """
    v, f = _triangles(vertices, faces)
    out = np.zeros_like(v)
    for k in range(3):
        c, a, b = f[:, k], f[:, (k + 1) % 3], f[:, (k + 2) % 3]  # angle at c, opposite edge ab
        ea, eb = v[a] - v[c], v[b] - v[c]
        cot = np.einsum("ma,ma->m", ea, eb) / _cross_norm(ea, eb)
        d = 0.5 * cot[:, None] * (v[a] - v[b])
        np.add.at(out, a, d)
        np.add.at(out, b, -d)
    return out


def _cross_norm(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    aa, bb, ab = (np.einsum("ma,ma->m", s, t) for s, t in ((a, a), (b, b), (a, b)))
    return np.sqrt(np.clip(aa * bb - ab * ab, 0.0, None))


def example_3_20_gradient(vertices: ArrayLike, faces: ArrayLike) -> NDArray[np.float64]:
    """Example 3.20's ½ Σ_{i ∈ N(q)} −x_i (cot θ_i1 + cot θ_i2) at every vertex q.

    θ_ij is Theorem 3.18's angle θ in the j-th triangle at q and p_i (for n = 2 the angle at the
    triangle's third vertex), from :func:`thesis_lib.curvature.checks.dihedral_cotangent_sum`
    (A_G^i = 1), summed over the triangles at q and halved (1/n! with n = 2).
    Thesis: Example 3.20.

    Parameters
    ----------
    vertices : array_like, shape (nv, d)
        Vertex coordinates, d >= 2.
    faces : array_like of int, shape (m, 3)
        The triangles.

    Returns
    -------
    ndarray of float64, shape (nv, d)
        The value at each vertex.

    Raises
    ------
    ValueError
        If the arrays are malformed or hold NaN.
    """
    v, f = _triangles(vertices, faces)
    out = np.zeros_like(v)
    for k in range(3):
        rolled = np.roll(f, -k, axis=1)  # vertex q first
        np.add.at(out, rolled[:, 0], 0.5 * dihedral_cotangent_sum(v[rolled]))
    return out


def mesh_area_gradient_fd(vertices: ArrayLike, simplices: ArrayLike, *, h: float = 1e-6) -> NDArray[np.float64]:
    """∇_p (total hyperarea) at every vertex by central differences, simplex by simplex.

    Thesis: Definition 3.15 and eq. (3.16).

    Parameters
    ----------
    vertices : array_like, shape (nv, d)
        Vertex coordinates.
    simplices : array_like of int, shape (m, n + 1)
        The top simplices.
    h : float, default 1e-6
        The step.

    Returns
    -------
    ndarray of float64, shape (nv, d)
        The gradient at each vertex.

    Raises
    ------
    ValueError
        On malformed arrays (see :func:`thesis_lib.curvature.checks.hyperarea_gradient_fd`).
    """
    v, s = np.asarray(vertices, dtype=np.float64), np.asarray(simplices)
    out = np.zeros_like(v)
    for k in range(s.shape[1]):
        rolled = np.roll(s, -k, axis=1)
        np.add.at(out, rolled[:, 0], hyperarea_gradient_fd(v[rolled], h))
    return out


def circumcentre_inside(triangles: ArrayLike) -> NDArray[np.bool_]:
    """Whether each triangle's circumcentre lies in the closed triangle (barycentric coordinates ≥ 0).

    Thesis: §3.3.2 (the Voronoi region stays inside non-obtuse triangles; Figure 3.2).

    Parameters
    ----------
    triangles : array_like, shape (m, 3, d)
        The corners.

    Returns
    -------
    ndarray of bool, shape (m,)
        True where the circumcentre is inside.

    Raises
    ------
    ValueError
        If ``triangles`` is not (m, 3, d).
    """
    t = np.asarray(triangles, dtype=np.float64)
    if t.ndim != 3 or t.shape[1] != 3:
        raise ValueError(f"triangles must have shape (m, 3, d), got {t.shape}")
    sq = [np.einsum("ma,ma->m", t[:, (k + 1) % 3] - t[:, (k + 2) % 3], t[:, (k + 1) % 3] - t[:, (k + 2) % 3])
          for k in range(3)]  # squared length of the side opposite corner k
    a, b, c = sq
    bary = np.stack([a * (b + c - a), b * (c + a - b), c * (a + b - c)], axis=1)
    return np.all(bary >= 0, axis=1)


_STATEMENT = re.compile(r"^(Theorem|Definition|Proposition|Corollary|Example|Lemma) (\d+\.\d+)\.", re.M)
_CHAPTER = re.compile(r"^(\d)\s*$", re.M)


def statement_containing(text: str, marker: str) -> str:
    """The numbered statement (``"Theorem 3.5"``) in force where ``marker`` first occurs in ``text``.

    Thesis: used for the thesis's cross-references (e.g. "Theorem 3.4" in §3.1.2).

    Parameters
    ----------
    text : str
        The thesis text.
    marker : str
        A string that occurs in it (an equation tag, a phrase).

    Returns
    -------
    str
        Kind and number of the last statement heading before the marker.

    Raises
    ------
    ValueError
        If the marker does not occur or no statement precedes it.
    """
    at = text.find(marker)
    if at < 0:
        raise ValueError(f"{marker!r} does not occur in the text")
    heads = [m for m in _STATEMENT.finditer(text, 0, at)]
    if not heads:
        raise ValueError(f"no numbered statement precedes {marker!r}")
    return f"{heads[-1].group(1)} {heads[-1].group(2)}"


def chapter_of(text: str, marker: str) -> int:
    """Number of the chapter in which ``marker`` first occurs (chapter titles are a line with a digit).

    Thesis: used for the thesis's references to chapters (§3.3.2's "Chapter 1").

    Parameters
    ----------
    text : str
        The thesis text.
    marker : str
        A string that occurs in it.

    Returns
    -------
    int
        The chapter's number.

    Raises
    ------
    ValueError
        If the marker does not occur or no chapter title precedes it.
    """
    at = text.find(marker)
    if at < 0:
        raise ValueError(f"{marker!r} does not occur in the text")
    heads = list(_CHAPTER.finditer(text, 0, at))
    if not heads:
        raise ValueError(f"no chapter title precedes {marker!r}")
    return int(heads[-1].group(1))

"""Numerical evidence for statements of chapter 3 that the reproduction report checks.

Each function computes, from the thesis's own definitions, the number one of its statements
predicts: the exterior angles of a closed polygon (Figure 3.1, Example 3.6), the coefficient of
Corollary 3.19 (fitted to a finite-difference area gradient), the part of a simplex nearest each
vertex (§3.3.2 and §3.4.2), Thales's circle of Figure 3.2, the principal curvatures from H and K
(§3.3.4) and the gradient of §3.3.4's least-squares sum as printed.  The book's chapter 3 page
calls them; the tests pin them to closed forms.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial import ConvexHull, HalfspaceIntersection

from .._validate import check_real, check_seed
from .areas import vertex_areas
from .gaussian import gaussian_curvature
from .geometry import simplex_hyperareas
from .mean import mean_curvature_vector
from .shape import normal_curvatures, vertex_normals

__all__ = [
    "exterior_angles",
    "random_simplices",
    "barycentric_gradients",
    "dihedral_cotangent_sum",
    "hyperarea_gradient_fd",
    "corollary_3_19_coefficient",
    "nearest_vertex_volumes",
    "thales_obtuse",
    "principal_curvatures_from_mean_and_gaussian",
    "printed_sum_gradient",
]


def _simplices(points: ArrayLike) -> NDArray[np.float64]:
    p = np.asarray(points, dtype=np.float64)
    if p.ndim != 3 or p.shape[1] < 2 or p.shape[2] < p.shape[1] - 1:
        raise ValueError(f"points must have shape (m, n + 1, d) with m >= 1 and d >= n >= 1, got {p.shape}")
    if len(p) == 0:
        raise ValueError("points holds no simplex")
    if not np.isfinite(p).all():
        raise ValueError("points contain NaN or infinite values")
    return p


def exterior_angles(polygon: ArrayLike) -> NDArray[np.float64]:
    """Signed exterior angles δ_i ∈ (−π, π) at the corners of a closed plane polygon (k, 2).

    δ_i is the turn from edge i − 1 to edge i (positive to the left), π − α_i at a convex corner with
    interior angle α_i.  For a simple closed polygon traversed counter-clockwise they add up to 2π
    (the turning number is 1); a sampled smooth curve gives ∫ κ ds = ∫ dψ = 2π (Example 3.6).
    Thesis: Figure 3.1, eq. (3.7) and Example 3.6.

    Parameters
    ----------
    polygon : array_like, shape (k, 2)
        The corners in order, k >= 3; the last corner joins the first.

    Returns
    -------
    ndarray of float64, shape (k,)
        δ_i at corner i, in radians.

    Raises
    ------
    ValueError
        If ``polygon`` is not a (k, 2) array with k >= 3, holds NaN or infinite values, or repeats a
        corner consecutively.
    """
    p = np.asarray(polygon, dtype=np.float64)
    if p.ndim != 2 or p.shape[1] != 2 or len(p) < 3:
        raise ValueError(f"polygon must be a (k, 2) array of k >= 3 corners, got shape {p.shape}")
    if not np.isfinite(p).all():
        raise ValueError("polygon contains NaN or infinite values")
    e = np.roll(p, -1, axis=0) - p  # edge i from corner i to corner i + 1
    prev = np.roll(e, 1, axis=0)
    if np.any(np.einsum("ka,ka->k", e, e) == 0):
        raise ValueError("polygon has repeated consecutive corners")
    return np.arctan2(prev[:, 0] * e[:, 1] - prev[:, 1] * e[:, 0], np.einsum("ka,ka->k", prev, e))


def random_simplices(n: int, count: int, *, seed: int = 0) -> NDArray[np.float64]:
    """``count`` random n-simplices in R^{n+1} (vertices standard normal), shape (count, n + 1, n + 1).

    Thesis: Theorem 3.18 (an n-simplex of a triangulated hypersurface in R^{n+1}).

    Parameters
    ----------
    n : int
        Dimension of the simplices, n >= 1.
    count : int
        How many simplices, count >= 1.
    seed : int, default 0
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    ndarray of float64, shape (count, n + 1, n + 1)
        The vertex coordinates of each simplex.

    Raises
    ------
    ValueError
        If ``n`` or ``count`` is not an integer >= 1.
    """
    for name, value, low in (("n", n, 1), ("count", count, 1)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
            raise ValueError(f"{name} must be an integer >= {low}, got {value!r}")
    return np.random.default_rng(check_seed(seed)).normal(size=(int(count), int(n) + 1, int(n) + 1))


def barycentric_gradients(points: ArrayLike) -> NDArray[np.float64]:
    """Gradients ∇λ_k of the barycentric coordinates of each simplex, shape (m, n + 1, d).

    ∇λ_k lies in the simplex's affine hull, is normal to the facet opposite vertex k, points towards
    vertex k and has length 1/(the height of vertex k over that facet).  The interior dihedral angle
    θ_jk at the ridge opposite vertices j and k has cos θ_jk = −∇λ_j·∇λ_k / (|∇λ_j| |∇λ_k|).
    Thesis: Theorem 3.18 and the angle θ defined after it.

    Parameters
    ----------
    points : array_like, shape (m, n + 1, d)
        Vertex coordinates of m non-degenerate n-simplices, d >= n >= 1.

    Returns
    -------
    ndarray of float64, shape (m, n + 1, d)
        ``out[:, k]`` is ∇λ_k of each simplex.

    Raises
    ------
    ValueError
        If ``points`` is not an (m, n + 1, d) array with m >= 1 and d >= n >= 1, or holds NaN or
        infinite values.
    """
    p = _simplices(points)
    e = p[:, 1:] - p[:, :1]  # (m, n, d), rows e_k = v_k − v_0
    g = np.linalg.pinv(e)  # (m, d, n): e @ g = I, so column k of g is ∇λ_{k+1}
    grads = np.swapaxes(g, 1, 2)
    return np.concatenate([-grads.sum(axis=1, keepdims=True), grads], axis=1)


def dihedral_cotangent_sum(points: ArrayLike) -> NDArray[np.float64]:
    """Σ_i −x_i A_G^i cot θ_i for vertex q = ``points[:, 0]`` of each simplex, shape (m, d).

    x_i = p_i − q, A_G^i the hyperarea of the (n−2)-simplex of the p's other than p_i (1 for n = 2),
    θ_i the dihedral angle at it between the facets opposite q and opposite p_i: Corollary 3.19's sum
    without its coefficient (the thesis's A_G^i/n!, really A_G^i/(n(n−1))).
    Thesis: Corollary 3.19 and Example 3.20.

    Parameters
    ----------
    points : array_like, shape (m, n + 1, d)
        Vertex coordinates of m non-degenerate n-simplices, d >= n >= 2; vertex 0 is q.

    Returns
    -------
    ndarray of float64, shape (m, d)
        The sum for each simplex.

    Raises
    ------
    ValueError
        If ``points`` is not an (m, n + 1, d) array with m >= 1 and d >= n, holds NaN or infinite
        values, or n < 2.
    """
    p = _simplices(points)
    m, w, _ = p.shape
    n = w - 1
    if n < 2:
        raise ValueError(f"Corollary 3.19 needs n >= 2 (a dihedral angle), got n = {n}")
    grad = barycentric_gradients(p)
    norm = np.linalg.norm(grad, axis=2)
    out = np.zeros((m, p.shape[2]))
    for i in range(1, w):
        cos = -np.einsum("ma,ma->m", grad[:, 0], grad[:, i]) / (norm[:, 0] * norm[:, i])
        cot = cos / np.sqrt(np.clip(1.0 - cos * cos, 0.0, None))
        ridge = [k for k in range(1, w) if k != i]
        vol = simplex_hyperareas(p.reshape(-1, p.shape[2]), (np.arange(m)[:, None] * w + ridge)) if n > 2 else 1.0
        out -= (p[:, i] - p[:, 0]) * (vol * cot)[:, None]
    return out


def hyperarea_gradient_fd(points: ArrayLike, h: float = 1e-6) -> NDArray[np.float64]:
    """Central-difference gradient of each simplex's hyperarea with respect to its vertex 0, (m, d).

    Thesis: Definition 3.15 (∇_p area), Theorem 3.18.

    Parameters
    ----------
    points : array_like, shape (m, n + 1, d)
        Vertex coordinates of m n-simplices, d >= n >= 1.
    h : float, default 1e-6
        The finite-difference step.

    Returns
    -------
    ndarray of float64, shape (m, d)
        (A(p_0 + h e_a) − A(p_0 − h e_a)) / (2h) for each simplex and coordinate a.

    Raises
    ------
    ValueError
        If ``points`` is not an (m, n + 1, d) array with m >= 1 and d >= n >= 1, holds NaN or
        infinite values, or ``h`` is not a positive finite number.
    """
    p = _simplices(points)
    h = check_real(h, "h", positive=True)
    m, w, d = p.shape
    flat = np.arange(m * w).reshape(m, w)
    out = np.empty((m, d))
    for a in range(d):
        plus, minus = p.copy(), p.copy()
        plus[:, 0, a] += h
        minus[:, 0, a] -= h
        out[:, a] = (simplex_hyperareas(plus.reshape(-1, d), flat)
                     - simplex_hyperareas(minus.reshape(-1, d), flat)) / (2 * h)
    return out


def corollary_3_19_coefficient(n: int, count: int = 200, *, seed: int = 0) -> tuple[float, float]:
    """Least-squares coefficient c with ∇_q A ≈ c · Σ_i −x_i A_G^i cot θ_i over random n-simplices.

    The thesis's Corollary 3.19 has c = 1/n!; the gradient of the hyperarea gives c = 1/(n(n−1))
    (the two agree for n = 2, 3).
    Thesis: Corollary 3.19 and Example 3.20.

    Parameters
    ----------
    n : int
        Dimension of the simplices, n >= 2.
    count : int, default 200
        How many random simplices (:func:`random_simplices`) enter the fit.
    seed : int, default 0
        Seed of the random simplices.

    Returns
    -------
    c : float
        The fitted coefficient.
    residual : float
        ‖∇A − c Σ‖ / ‖∇A‖ over all simplices (about the finite-difference error when the form is
        right), ∇A from :func:`hyperarea_gradient_fd`.

    Raises
    ------
    ValueError
        If ``n`` or ``count`` is not an integer >= 1, or n < 2.
    """
    p = random_simplices(n, count, seed=seed)
    fd = hyperarea_gradient_fd(p).ravel()
    basis = dihedral_cotangent_sum(p).ravel()
    c = float(fd @ basis / (basis @ basis))
    return c, float(np.linalg.norm(fd - c * basis) / np.linalg.norm(fd))


def nearest_vertex_volumes(points: ArrayLike) -> NDArray[np.float64]:
    """Exact hyperarea of the part of each simplex nearer to each vertex than to the others, (m, n + 1).

    The Voronoi cell of vertex k clipped to the simplex: the simplex cut by the bisecting
    hyperplanes between k and the other vertices (scipy's half-space intersection in the simplex's
    own n-dimensional coordinates).  Rows sum to the simplex's hyperarea.  On a non-obtuse triangle
    this is the thesis's A_vor = 1/8 Σ (cot α + cot β) ‖x_i − x_j‖²; at the right corner of the
    3-simplex (0, e₁, e₂, e₃) it is 5/48.  Thesis: §3.3.2 (Voronoi regions) and §3.4.2.

    Parameters
    ----------
    points : array_like, shape (m, n + 1, d)
        The m simplices, by the coordinates of their n + 1 vertices (d >= n >= 1, none
        degenerate).

    Returns
    -------
    ndarray of float64, shape (m, n + 1)
        ``out[s, k]`` is the hyperarea of the part of simplex s nearest to its vertex k.

    Raises
    ------
    ValueError
        On the bad ``points`` that :func:`barycentric_gradients` refuses.
    """
    p = _simplices(points)
    m, w, _ = p.shape
    n = w - 1
    if n == 1:  # a segment: each end is nearest to its half
        return np.repeat(0.5 * np.linalg.norm(p[:, 1] - p[:, 0], axis=1)[:, None], 2, axis=1)
    out = np.empty((m, w))
    for s in range(m):
        q, _ = np.linalg.qr((p[s, 1:] - p[s, 0]).T)  # orthonormal basis of the affine hull
        x = (p[s] - p[s, 0]) @ q  # (w, n) intrinsic coordinates
        centroid = x.mean(axis=0)
        facets = []
        for k in range(w):  # the facet opposite vertex k: keep the side holding the centroid
            others = np.delete(x, k, axis=0)
            normal = np.linalg.svd(others[1:] - others[0])[2][-1]
            offset = -normal @ others[0]
            if normal @ centroid + offset > 0:
                normal, offset = -normal, -offset
            facets.append(np.append(normal, offset))
        for k in range(w):
            cuts = [np.append(x[j] - x[k], -0.5 * (x[j] @ x[j] - x[k] @ x[k])) for j in range(w) if j != k]
            inside = x[k] + 1e-3 * (centroid - x[k])  # strictly inside the simplex and nearest to k
            hs = HalfspaceIntersection(np.array(facets + cuts), inside)
            out[s, k] = ConvexHull(hs.intersections).volume
    return out


def thales_obtuse(points: ArrayLike, a: ArrayLike, b: ArrayLike) -> NDArray[np.bool_]:
    """Whether the triangle (a, b, x) is obtuse at x, for each point x of ``points`` (k, d).

    Figure 3.2: x lies inside the circle on the diameter ab exactly when the angle at x is obtuse
    (Thales: on the circle it is right), so a vertex inside it spoils a non-obtuse triangle.
    Thesis: Figure 3.2, §3.3.2.

    Parameters
    ----------
    points : array_like, shape (k, d)
        The points x.
    a, b : array_like, shape (d,)
        The ends of the diameter.

    Returns
    -------
    ndarray of bool, shape (k,)
        True where the angle at x is obtuse, i.e. x is strictly inside the circle (sphere) on ab.

    Raises
    ------
    ValueError
        If ``points`` is not (k, d) or ``a``, ``b`` are not points of dimension d.
    """
    x = np.asarray(points, dtype=np.float64)
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if x.ndim != 2 or a.shape != (x.shape[1],) or b.shape != a.shape:
        raise ValueError("points must be (k, d) and a, b points of dimension d")
    return np.einsum("kd,kd->k", a - x, b - x) < 0


def principal_curvatures_from_mean_and_gaussian(
    vertices: ArrayLike, faces: ArrayLike, area: str = "voronoi"
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """κ₁ ≤ κ₂ = H ∓ sqrt(max(H² − K, 0)) from the discrete H and K of a triangle mesh.

    The route that §3.3.4 (after [MDSB02]) prefers to the least-squares shape operator: the signed
    H = ⟨∇_p area, n⟩ / (2 · area(p)) (Definition 3.15, n the vertex normal) and the angle-defect K
    (Definition 3.21), over the vertex ``area``.  Signs as in :mod:`thesis_lib.curvature.shape`
    (faces coherently oriented; a sphere oriented outwards has κ = +1/R), so the result compares
    with :func:`thesis_lib.curvature.principal_curvatures`.
    Thesis: Definition 3.4 and §3.3.4 ("estimating K and H and use this to estimate κ₁ and κ₂").

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
        Vertex coordinates.
    faces : array_like of int, shape (m, 3)
        Coherently oriented triangles of a surface (checked).
    area : {"voronoi", "mixed", "barycentric"}, default "voronoi"
        The vertex region of H and K.

    Returns
    -------
    kappa1, kappa2 : ndarray of float64, shape (nv,)
        The smaller and the larger principal curvature at each vertex; equal (to H) where
        H² < K.

    Raises
    ------
    ValueError
        On an invalid mesh (see :func:`thesis_lib.curvature.vertex_areas`) or an unknown area.
    """
    vec = mean_curvature_vector(vertices, faces)
    H = np.einsum("ia,ia->i", vec, vertex_normals(vertices, faces)) / (2 * vertex_areas(vertices, faces, area=area))
    K = gaussian_curvature(vertices, faces, area=area)
    root = np.sqrt(np.clip(H * H - K, 0.0, None))
    return H - root, H + root


def printed_sum_gradient(vertices: ArrayLike, faces: ArrayLike) -> NDArray[np.float64]:
    """‖∇_S Σ_j (d_ijᵀ S d_ij − κ_ij)‖_F / deg(i) at every vertex i: the sum as §3.3.4 prints it.

    The printed sum (no square) is linear in S, with gradient Σ_j d_ij d_ijᵀ whatever the κ_ij, where
    d_ij is the unit projection of x_j − x_i onto the tangent plane at x_i (vertex normals of
    :func:`thesis_lib.curvature.vertex_normals`; weights 1, Voronoi weights change nothing here).
    Its trace is deg(i), so the ratio is at least 1/√2: the gradient never vanishes and the printed
    sum has no minimiser.  With the square it is the least-squares problem of
    :func:`thesis_lib.curvature.shape_operator`.
    Thesis: §3.3.4, "Estimating the Shape Operator".

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
        Vertex coordinates.
    faces : array_like of int, shape (m, 3)
        Triangles of a surface (checked).

    Returns
    -------
    ndarray of float64, shape (nv,)
        The ratio at each vertex; NaN at isolated vertices.

    Raises
    ------
    ValueError
        On an invalid mesh (see :func:`thesis_lib.curvature.normal_curvatures`).
    """
    edges, _ = normal_curvatures(vertices, faces)
    v = np.asarray(vertices, dtype=np.float64)
    nrm = vertex_normals(vertices, faces)
    i = edges[:, 0]
    d = v[edges[:, 1]] - v[i]
    d -= np.einsum("ea,ea->e", d, nrm[i])[:, None] * nrm[i]
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    grad = np.zeros((len(v), 3, 3))
    np.add.at(grad, i, np.einsum("ea,eb->eab", d, d))
    deg = np.bincount(i, minlength=len(v)).astype(np.float64)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.linalg.norm(grad, axis=(1, 2)) / deg

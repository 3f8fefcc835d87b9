"""Discrete mean curvature of triangulated hypersurfaces: the gradient of the total hyperarea.

The discrete mean curvature vector at a vertex p is ∇_p area M (Definition 3.15), an *integrated*
quantity.  By the first variation of area (Theorem 3.12, −δA(X, λN) = n ∫ λH dA) it approximates
−n·H·N times the area around p, so |H| ≈ ‖∇_p area M‖ / (n · area(p)).

Two independent implementations:

``method="gram"``
    Theorem 3.18: each simplex's hyperarea is A = sqrt(det G) / n! with G = XᵀX the Gram matrix of the
    edge vectors x_i = p_i − q; by Jacobi's formula (Theorem 3.16) ∇_X sqrt(det G) = X adj(G) / sqrt(det G),
    so ∇_{p_i} A is column i of X adj(G) / (n! sqrt(det G)) and ∇_q A is minus their sum.
``method="cot"``
    Corollary 3.19 (cot of dihedral angles): ∇_q A = Σ_i w_i (q − p_i) with
    w_i = vol_{n−2}(R_i) cot θ_i / (n (n − 1)), where R_i is the (n−2)-face opposite the edge q p_i
    and θ_i the dihedral angle of the simplex at R_i.  For n = 2, 3 this is the thesis's coefficient
    A_G^i / n!; for n ≥ 4 the thesis's n! should read n (n − 1) (it is off by the factor (n − 2)!,
    which the finite-difference tests in ``tests/test_curvature.py`` pin down).

Conditioning: on a simplex of aspect above ``ASPECT_BOUND`` (see :mod:`.validate`) both methods
use the same exact-arithmetic gradient instead (:func:`_exact_gradients`: the numerators X adj(G)
and their sum over the simplex in rational arithmetic, one rounding each, then one division by
n! sqrt(det G)), correct to a few ulps per component; the float formulas would lose up to
2·log10(aspect) digits there (at a needle's tip, minus the sum of two long gradients).  Elsewhere
the float formulas are kept bit for bit.

Both are orientation-independent: ∇ area does not depend on the order of a simplex's vertices, so
|H| needs no consistent orientation (only signed quantities do; see :mod:`.shape`).
"""

from __future__ import annotations

from itertools import combinations
from math import factorial, sqrt

import numpy as np
import numpy.typing as npt

from .areas import check_area, vertex_areas_of_mesh
from .geometry import exact_edges, exact_gram
from .manifold import checked_mesh
from .validate import Mesh

__all__ = ["mean_curvature_vector", "mean_curvature", "total_hyperarea"]


def _check_method(method) -> str:
    if not isinstance(method, str) or method not in ("gram", "cot"):
        raise ValueError(f"unknown method {method!r}: use 'gram' (Theorem 3.18) or 'cot' (Corollary 3.19)")
    return method


def _scatter(idx: np.ndarray, vals: np.ndarray, nv: int) -> np.ndarray:
    """Sum rows of ``vals`` (k, d) into ``nv`` bins given by ``idx`` (k,)."""
    return np.stack([np.bincount(idx, weights=vals[:, a], minlength=nv) for a in range(vals.shape[1])], axis=1)


def _exact_gradients(p: np.ndarray) -> np.ndarray:
    """∇ of one simplex's hyperarea at each of its vertices, shape (n + 1, d), from the exact
    coordinates: numerators X adj(G) (and minus their sum, for q = p_0) exact, each rounded once,
    divided by n! sqrt(det G) (det G exact, rounded once)."""
    x, e = exact_edges(p)
    n, d = len(x), len(x[0])
    _, adj, det = exact_gram(x)
    num = [[sum(x[i][a] * adj[i][j] for i in range(n)) for a in range(d)] for j in range(n)]
    q = [-sum(num[j][a] for j in range(n)) for a in range(d)]
    scale = 1 << ((2 * n - 1) * e)
    denom = factorial(n) * sqrt(det / (1 << (2 * n * e)))
    return np.array([[c / scale for c in row] for row in [q, *num]]) / denom


def _apply_exact(g: np.ndarray, p: np.ndarray, ill: np.ndarray | None) -> np.ndarray:
    """Overwrite the gradients ``g`` (m, n + 1, d) of the ill-conditioned simplices with exact ones."""
    if ill is not None:
        for k in ill.tolist():
            g[k] = _exact_gradients(p[k])
    return g


def _gradients_gram(v: np.ndarray, s: np.ndarray) -> np.ndarray:
    """∇ of each simplex's hyperarea with respect to each of its vertices, shape (m, n + 1, n + 1)."""
    n = s.shape[1] - 1
    p = v[s]
    x = p[:, 1:, :] - p[:, :1, :]  # (m, n, d): x_i = p_i - q
    if n == 2:
        a = np.einsum("ma,ma->m", x[:, 0], x[:, 0])
        b = np.einsum("ma,ma->m", x[:, 0], x[:, 1])
        c = np.einsum("ma,ma->m", x[:, 1], x[:, 1])
        root = np.sqrt(a * c - b * b)  # sqrt(det G) = n! A
        # X adj(G): adj [[a, b], [b, c]] = [[c, -b], [-b, a]]
        g1 = (x[:, 0] * c[:, None] - x[:, 1] * b[:, None]) / (2.0 * root[:, None])
        g2 = (x[:, 1] * a[:, None] - x[:, 0] * b[:, None]) / (2.0 * root[:, None])
        return np.stack([-(g1 + g2), g1, g2], axis=1)
    gram = np.einsum("mia,mja->mij", x, x)
    det = np.linalg.det(gram)
    adj = np.linalg.inv(gram) * det[:, None, None]  # adjugate of a symmetric positive-definite G
    g = np.einsum("mia,mij->mja", x, adj) / (factorial(n) * np.sqrt(det))[:, None, None]
    return np.concatenate([-g.sum(axis=1, keepdims=True), g], axis=1)


def _cot_weights(v: np.ndarray, s: np.ndarray) -> list[tuple[int, int, np.ndarray]]:
    """For each local vertex pair (i, j): the weight vol(R_ij) cot θ_ij / (n (n − 1)), shape (m,)."""
    n = s.shape[1] - 1
    p = v[s]
    out = []
    for i, j in combinations(range(n + 1), 2):
        rest = [k for k in range(n + 1) if k not in (i, j)]
        r0 = p[:, rest[0], :]
        yi = p[:, i, :] - r0
        yj = p[:, j, :] - r0
        if n == 2:
            ui, uj, vol = yi, yj, np.ones(len(s))
        else:
            e = p[:, rest[1:], :] - r0[:, None, :]  # (m, n - 2, d) edge vectors of the ridge R_ij
            ge = np.einsum("mka,mla->mkl", e, e)
            vol = np.sqrt(np.linalg.det(ge)) / factorial(n - 2)
            rhs = np.stack([np.einsum("mka,ma->mk", e, yi), np.einsum("mka,ma->mk", e, yj)], axis=2)
            coef = np.linalg.solve(ge, rhs)  # projections of p_i, p_j onto aff(R_ij)
            ui = yi - np.einsum("mka,mk->ma", e, coef[:, :, 0])
            uj = yj - np.einsum("mka,mk->ma", e, coef[:, :, 1])
        dot = np.einsum("ma,ma->m", ui, uj)
        sin_part = np.sqrt(np.clip(np.einsum("ma,ma->m", ui, ui) * np.einsum("ma,ma->m", uj, uj) - dot * dot, 0, None))
        cot = dot / sin_part
        out.append((i, j, vol * cot / (n * (n - 1))))
    return out


def _gram_triangles(mesh: Mesh) -> np.ndarray:
    """Theorem 3.18 for n = 2 on the validated corner data: gradients (3 corners, 3 coords, m)."""
    tri = mesh.tri
    pts = tri.coords
    x1, x2 = pts[1] - pts[0], pts[2] - pts[0]
    a, b, c = tri.edge_sq[2], tri.dot[0], tri.edge_sq[1]  # Gram matrix [[a, b], [b, c]]
    inv = 0.5 / tri.twice_area  # 1 / (n! * 2 sqrt(det G)) * 2
    # X adj(G) with adj = [[c, -b], [-b, a]]
    g1 = (x1 * c - x2 * b) * inv
    g2 = (x2 * a - x1 * b) * inv
    g = np.stack([-(g1 + g2), g1, g2])
    if mesh.ill_conditioned is not None:
        for k in mesh.ill_conditioned.tolist():
            g[:, :, k] = _exact_gradients(pts[:, :, k])
    return g


def _mean_curvature_vector(mesh: Mesh, method: str) -> np.ndarray:
    v, s = mesh.vertices, mesh.simplices
    nv, d = v.shape
    if method == "gram":
        if mesh.tri is not None:
            g = _gram_triangles(mesh)
            idx = s.T.ravel()
            return np.stack([np.bincount(idx, weights=g[:, a].ravel(), minlength=nv) for a in range(3)], axis=1)
        g = _apply_exact(_gradients_gram(v, s), v[s], mesh.ill_conditioned)
        return _scatter(s.ravel(), g.reshape(-1, d), nv)
    if method == "cot":
        if mesh.n < 2:
            raise ValueError("method 'cot' (dihedral angles, Corollary 3.19) needs n >= 2; use 'gram' for curves")
        ill = mesh.ill_conditioned if mesh.ill_conditioned is not None else np.zeros(0, dtype=np.int64)
        idx, vals = [], []
        with np.errstate(divide="ignore", invalid="ignore"):  # an ill-conditioned cot may be inf: replaced below
            weights = _cot_weights(v, s)
        for i, j, w in weights:
            w[ill] = 0.0
            diff = v[s[:, i]] - v[s[:, j]]
            idx += [s[:, i], s[:, j]]
            vals += [w[:, None] * diff, -w[:, None] * diff]
        if ill.size:  # the ill-conditioned simplices: the exact gradient (the same quantity, Corollary 3.19)
            idx.append(s[ill].ravel())
            vals.append(np.concatenate([_exact_gradients(p) for p in v[s[ill]]]))
        return _scatter(np.concatenate(idx), np.concatenate(vals), nv)
    raise AssertionError(method)  # pragma: no cover - checked by the callers


def mean_curvature_vector(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, method: str = "gram") -> np.ndarray:
    """Discrete mean curvature vector ∇_p (total hyperarea) at every vertex, integrated over its area.

    Thesis: Definition 3.15 (computed by Theorem 3.18 or Corollary 3.19).

    Parameters
    ----------
    vertices : array_like, shape (nv, n + 1)
        Vertex coordinates in R^{n+1}.
    simplices : array_like of int, shape (m, n + 1)
        Top n-simplices of the hypersurface (any orientation), a simplicial pseudo-manifold
        (checked: no doubled simplex, no ridge in three simplices, no pinched vertex).
    method : {"gram", "cot"}
        ``"gram"``: Gram-determinant gradient (Theorem 3.18), any n >= 1 (n = 1: closed or open
        polygons in the plane); ``"cot"``: cotangents of dihedral angles (Corollary 3.19, for n = 2 the
        cotangent formula (3.18)), n >= 2.

    Returns
    -------
    ndarray, shape (nv, n + 1)
        ∇_p area M, the direction in which moving p grows the area fastest: it points outwards on
        convex parts (≈ n H N · area(p) with N the outward unit normal; for n = 2 it equals libigl's
        −L V, L the cotangent Laplacian).  Defined at boundary vertices too (it is still the area
        gradient) and zero at isolated vertices.

    Raises
    ------
    ValueError
        On invalid meshes (see :func:`thesis_lib.curvature.validate_mesh`) or an unknown method.

    Examples
    --------
    At the vertex (1, 0, 0) of the octahedron the area gradient points straight outwards:

    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> np.round(mean_curvature_vector(octahedron, faces)[0], 6).tolist()
    [2.309401, 0.0, 0.0]
    """
    return _mean_curvature_vector(checked_mesh(vertices, simplices), _check_method(method))


def total_hyperarea(vertices: npt.ArrayLike, simplices: npt.ArrayLike) -> float:
    """Total hyperarea of a triangulated hypersurface, Σ sqrt(det G_T) / n!.

    Thesis: §3.3.1 (area M = Σ_T area T).

    Parameters
    ----------
    vertices : array_like, shape (nv, n + 1)
    simplices : array_like of int, shape (m, n + 1)

    Returns
    -------
    float

    Examples
    --------
    The octahedron's eight equilateral triangles of side √2 have area 4√3; 200 points on the sphere
    of radius 2 span 97 % of its area 16π:

    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> round(total_hyperarea(octahedron, faces), 6), round(4 * 3 ** 0.5, 6)
    (6.928203, 6.928203)
    >>> from thesis_lib.meshes import sphere_hull
    >>> vertices, triangles = sphere_hull(n_points=200, radius=2.0, seed=0)
    >>> round(total_hyperarea(vertices, triangles) / (16 * np.pi), 2)
    0.97
    """
    return float(checked_mesh(vertices, simplices).areas.sum())


def mean_curvature(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, area: str = "mixed",
                   method: str = "gram") -> np.ndarray:
    """Absolute mean curvature |H| = ‖∇_p area M‖ / (n · area(p)) at every vertex.

    Thesis: Definition 3.15 with Theorem 3.12 (the norm divided by n), averaged over the regions of §3.3.2.

    Parameters
    ----------
    vertices, simplices
        As in :func:`mean_curvature_vector`.
    area : {"mixed", "voronoi", "barycentric"}
        Vertex area (see :func:`thesis_lib.curvature.vertex_areas`); ``"mixed"`` needs n = 2.
    method : {"gram", "cot"}
        How to compute the mean curvature vector.

    Returns
    -------
    ndarray, shape (nv,)
        |H| ≥ 0 (orientation-independent).  NaN on boundary and pinched vertices (the area gradient there also
        measures the boundary's length variation, Theorem 3.9), on isolated vertices, and where the
        vertex area is not positive (possible with the signed ``"voronoi"`` area on badly shaped
        meshes).

    Warns
    -----
    UserWarning
        Boundary vertices at exactly the coordinates of other vertices: a triangle soup (a mesh
        read from a textured OBJ file is split at its seams), NaN there; merge them first with
        ``thesis_lib.meshes.merge_coincident(vertices, simplices)`` (``checked_mesh``).

    Examples
    --------
    On a triangulated sphere of radius 2 the discrete |H| is close to 1/r = 0.5; on the regular
    octahedron (circumradius 1) it is exactly 1:

    >>> import numpy as np
    >>> from thesis_lib.meshes import sphere_hull
    >>> vertices, triangles = sphere_hull(n_points=200, radius=2.0, seed=0)
    >>> round(float(np.median(mean_curvature(vertices, triangles))), 2)
    0.5
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> np.round(mean_curvature(octahedron, convex_hull_surface(octahedron)), 6).tolist()
    [1.0, 1.0, 1.0, 1.0, 1.0, 1.0]
    """
    area = check_area(area)
    method = _check_method(method)
    mesh = checked_mesh(vertices, simplices)
    vec = _mean_curvature_vector(mesh, method)
    a = vertex_areas_of_mesh(mesh, area)
    with np.errstate(divide="ignore", invalid="ignore"):
        h = np.sqrt(np.einsum("ia,ia->i", vec, vec)) / (mesh.n * a)
    h[mesh.no_estimate | ~(a > 0)] = np.nan
    return h

"""Normal curvature estimates and the weighted least-squares shape operator (§3.3.4), n = 2.

Sign convention.  Everything here depends on the orientation of the faces, so the faces must be
coherently oriented (checked; ``ValueError`` otherwise).  The vertex normal ``n`` is a weighted mean
of the face normals (right-hand rule on the face's vertex order; Max's weights by default).  Normal curvatures follow
equation (3.24): positive where the surface bends away from ``n``, so a sphere whose faces are
oriented outwards has κ = +1/R (Definition 3.1, S = −dN, gives the opposite sign for outward N).

Equation (3.24) as printed sets κ equal to the *radius* R = ‖x_i − x_j‖² / (2 (x_i − x_j)·n) of the
osculating circle; the curvature is its reciprocal, κ_ij = 2 (x_i − x_j)·n / ‖x_i − x_j‖², which is
what the thesis's next display (the Voronoi-weighted quadrature giving H) uses.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from .._validate import check_choice
from .manifold import checked_mesh
from .validate import Mesh, check_orientation

EDGE_WEIGHTS = ("voronoi", "uniform")
NORMALS = ("max", "area")

__all__ = [
    "vertex_normals",
    "normal_curvatures",
    "shape_operator",
    "principal_curvatures",
    "ShapeOperator",
    "PrincipalCurvatures",
]


class ShapeOperator(NamedTuple):
    """Per-vertex shape operator in a tangent basis.

    Examples
    --------
    What :func:`shape_operator` returns: a named tuple of per-vertex arrays.

    >>> import numpy as np
    >>> from thesis_lib.meshes import sphere_hull
    >>> vertices, triangles = sphere_hull(n_points=200, radius=2.0, seed=0)
    >>> s = shape_operator(vertices, triangles)
    >>> s.tensor.shape, s.basis.shape, s.normal.shape
    ((200, 2, 2), (200, 2, 3), (200, 3))
    """

    tensor: np.ndarray  #: (nv, 2, 2) symmetric matrix S in the basis below
    basis: np.ndarray  #: (nv, 2, 3) orthonormal tangent vectors t1, t2 (t1 × t2 = normal)
    normal: np.ndarray  #: (nv, 3) unit vertex normal


class PrincipalCurvatures(NamedTuple):
    """Principal curvatures κ1 ≤ κ2 (Definition 3.3) and their unit directions in R^3.

    Examples
    --------
    What :func:`principal_curvatures` returns: a named tuple of per-vertex arrays.

    >>> import numpy as np
    >>> from thesis_lib.meshes import sphere_hull
    >>> vertices, triangles = sphere_hull(n_points=200, radius=2.0, seed=0)
    >>> pc = principal_curvatures(vertices, triangles)
    >>> pc._fields, pc.k1.shape, pc.d1.shape
    (('k1', 'k2', 'd1', 'd2'), (200,), (200, 3))
    """

    k1: np.ndarray  #: (nv,) minimum normal curvature
    k2: np.ndarray  #: (nv,) maximum normal curvature
    d1: np.ndarray  #: (nv, 3) direction of k1
    d2: np.ndarray  #: (nv, 3) direction of k2


def _oriented_mesh(vertices, simplices) -> Mesh:
    mesh = checked_mesh(vertices, simplices)
    if mesh.n != 2:
        raise ValueError(f"the shape operator is implemented for triangle meshes in R^3 (n = 2), got n = {mesh.n}")
    check_orientation(mesh.simplices)
    return mesh


def _normals(mesh: Mesh, kind: str = "max") -> np.ndarray:
    v, s = mesh.vertices, mesh.simplices
    p = v[s]
    if kind == "area":
        c = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])  # twice the area times the unit normal
        idx, vals = s.ravel(), np.repeat(c, 3, axis=0)
    elif kind == "max":
        a = p[:, [1, 2, 0]] - p  # corner k: a = p_{k+1} - p_k, b = p_{k+2} - p_k
        b = p[:, [2, 0, 1]] - p
        c = np.cross(a, b) / (np.einsum("mka,mka->mk", a, a) * np.einsum("mka,mka->mk", b, b))[..., None]
        idx, vals = s.ravel(), c.reshape(-1, 3)
    else:  # pragma: no cover - checked by the callers
        raise AssertionError(kind)
    acc = np.stack([np.bincount(idx, weights=vals[:, a], minlength=len(v)) for a in range(3)], 1)
    norm = np.linalg.norm(acc, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return acc / norm[:, None]


def _check_normals(normals) -> str:
    return check_choice(normals, NORMALS, "normals")


def _check_edge_weights(edge_weights) -> str:
    return check_choice(edge_weights, EDGE_WEIGHTS, "edge_weights")


def vertex_normals(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, normals: str = "max") -> np.ndarray:
    """Unit vertex normals from the oriented face normals (Max's weights or area weights).

    Thesis: §3.3.4 (the normal n at x_i used in equation (3.24)).

    ``normals="max"`` weights each face's normal at a corner by 1 / (‖a‖² ‖b‖²), a and b the two edge
    vectors there (N. Max, 1999): exact for any triangulation inscribed in a sphere, and much better
    than area weights for the edge-based normal curvatures (3.24) on irregular meshes.
    ``normals="area"`` is the area-weighted mean.

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
    simplices : array_like of int, shape (m, 3), coherently oriented pseudo-manifold
    normals : {"max", "area"}

    Returns
    -------
    ndarray, shape (nv, 3)
        NaN at isolated vertices (and where the face normals cancel).

    Raises
    ------
    ValueError
        On an invalid or incoherently oriented mesh.

    Examples
    --------
    The octahedron's normals point out along the axes:

    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> np.round(vertex_normals(octahedron, faces)[:2], 6).tolist()
    [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    normals = _check_normals(normals)
    return _normals(_oriented_mesh(vertices, simplices), normals)


def _edges_with_weights(mesh: Mesh) -> tuple[np.ndarray, np.ndarray]:
    """Undirected edges (e, 2) and their Voronoi weights 1/8 Σ cot ‖x_i − x_j‖² (§3.3.2)."""
    v, s, tri = mesh.vertices, mesh.simplices, mesh.tri
    w = 0.125 * tri.dot / tri.twice_area * tri.edge_sq  # (3, m): corner k's share of the opposite edge
    a = s[:, [1, 2, 0]].T.ravel()
    b = s[:, [2, 0, 1]].T.ravel()
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    key = lo * len(v) + hi
    order = np.argsort(key, kind="stable")
    ks = key[order]
    start = np.flatnonzero(np.r_[True, ks[1:] != ks[:-1]])
    weights = np.add.reduceat(w.ravel()[order], start)
    edges = np.stack([lo[order[start]], hi[order[start]]], axis=1)
    return edges, weights


def normal_curvatures(vertices: npt.ArrayLike, simplices: npt.ArrayLike,
                      *, normals: str = "max") -> tuple[np.ndarray, np.ndarray]:
    """Normal curvature estimate κ_ij = 2 (x_i − x_j)·n_i / ‖x_i − x_j‖² along every directed edge.

    Thesis: Equation (3.24) (circle through x_i and x_j tangent to the plane ⊥ n_i; κ = 1/R).

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
    simplices : array_like of int, shape (m, 3), coherently oriented pseudo-manifold
    normals : {"max", "area"}
        Vertex normals, see :func:`vertex_normals`.

    Returns
    -------
    (edges, kappa)
        ``edges`` (2e, 2) directed edges (i, j), both directions of every edge; ``kappa`` (2e,) the
        estimate at vertex i in the direction of x_j.  Signs as in the module docstring.

    Examples
    --------
    On the octahedron (circumradius 1) every edge estimate is 2 (x_i − x_j)·n_i / ‖x_i − x_j‖² = 1:

    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> edges, kappa = normal_curvatures(octahedron, faces)
    >>> edges[:2].tolist(), np.unique(np.round(kappa, 6)).tolist()
    ([[0, 2], [0, 3]], [1.0])
    """
    normals = _check_normals(normals)
    mesh = _oriented_mesh(vertices, simplices)
    nrm = _normals(mesh, normals)
    und, _ = _edges_with_weights(mesh)
    edges = np.concatenate([und, und[:, ::-1]])
    d = mesh.vertices[edges[:, 0]] - mesh.vertices[edges[:, 1]]
    kappa = 2.0 * np.einsum("ea,ea->e", d, nrm[edges[:, 0]]) / np.einsum("ea,ea->e", d, d)
    return edges, kappa


def _tangent_basis(nrm: np.ndarray) -> np.ndarray:
    axis = np.zeros_like(nrm)
    safe = np.nan_to_num(nrm)
    axis[np.arange(len(nrm)), np.argmin(np.abs(safe), axis=1)] = 1.0
    t1 = np.cross(nrm, axis)
    t1 /= np.linalg.norm(t1, axis=1)[:, None]
    t2 = np.cross(nrm, t1)
    return np.stack([t1, t2], axis=1)


def shape_operator(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, edge_weights: str = "voronoi",
                   normals: str = "max") -> ShapeOperator:
    """Weighted least-squares shape operator at every vertex of a triangle mesh.

    Thesis: §3.3.4 "Estimating the Shape Operator" (minimise Σ_j w_ij (d_ijᵀ S d_ij − κ_ij)²).

    For each vertex i and neighbour j, d_ij is the unit projection of x_j − x_i onto the tangent plane
    ⊥ n_i, κ_ij the estimate (3.24) and w_ij = 1/8 (cot α_ij + cot β_ij) ‖x_i − x_j‖² the edge's share
    of the Voronoi area.  Weights that are negative (non-Delaunay edges) are set to zero so the fit
    stays a least-squares problem.  Where the weighted directions do not determine S (on a
    rectangular grid the diagonals' Voronoi weights vanish, leaving two directions for three unknowns)
    the minimum-Frobenius-norm least-squares solution is taken (pseudo-inverse), which adds no
    curvature in the undetermined "twist" d1 d2ᵀ + d2 d1ᵀ.

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
    simplices : array_like of int, shape (m, 3), coherently oriented pseudo-manifold
    edge_weights : {"voronoi", "uniform"}, default "voronoi"
        The thesis's Voronoi weights w_ij, or all w_ij = 1.
    normals : {"max", "area"}
        Vertex normals, see :func:`vertex_normals`.

    Returns
    -------
    ShapeOperator
        ``tensor`` (nv, 2, 2) in the tangent ``basis`` (nv, 2, 3), with the ``normal`` (nv, 3).  NaN at
        boundary, pinched and isolated vertices.

    Raises
    ------
    ValueError
        On an invalid mesh, n ≠ 2, incoherent orientation or unknown ``edge_weights``/``normals``.

    Examples
    --------
    On a sphere of radius 2 the shape operator is (1/r) times the identity:

    >>> import numpy as np
    >>> from thesis_lib.meshes import sphere_hull
    >>> vertices, triangles = sphere_hull(n_points=200, radius=2.0, seed=0)
    >>> s = shape_operator(vertices, triangles)
    >>> bool(np.allclose(np.median(s.tensor, axis=0), [[0.5, 0.0], [0.0, 0.5]], atol=1e-3))
    True
    """
    edge_weights = _check_edge_weights(edge_weights)
    normals = _check_normals(normals)
    mesh = _oriented_mesh(vertices, simplices)
    v = mesh.vertices
    nv = len(v)
    nrm = _normals(mesh, normals)
    basis = _tangent_basis(nrm)
    und, w = _edges_with_weights(mesh)
    w = np.clip(w, 0.0, None) if edge_weights == "voronoi" else np.ones_like(w)
    i = np.concatenate([und[:, 0], und[:, 1]])
    j = np.concatenate([und[:, 1], und[:, 0]])
    ww = np.concatenate([w, w])
    d = v[j] - v[i]
    ni = nrm[i]
    kappa = -2.0 * np.einsum("ea,ea->e", d, ni) / np.einsum("ea,ea->e", d, d)  # (x_i - x_j) = -d
    a = np.einsum("ea,ea->e", d, basis[i, 0])
    b = np.einsum("ea,ea->e", d, basis[i, 1])
    norm2 = a * a + b * b
    # unknowns (S11, sqrt2 S12, S22): d^T S d = phi . unknowns with an orthonormal (Frobenius) scaling,
    # so the minimum-norm solution below is the minimum-Frobenius-norm S (rotation invariant)
    phi = np.stack([a * a, np.sqrt(2.0) * a * b, b * b], axis=1) / norm2[:, None]
    mat = np.zeros((nv, 3, 3))
    rhs = np.zeros((nv, 3))
    for r in range(3):
        rhs[:, r] = np.bincount(i, weights=ww * kappa * phi[:, r], minlength=nv)
        for c in range(r, 3):
            mat[:, r, c] = mat[:, c, r] = np.bincount(i, weights=ww * phi[:, r] * phi[:, c], minlength=nv)
    ok = ~mesh.no_estimate
    sol = np.full((nv, 3), np.nan)
    if ok.any():
        sol[ok] = np.einsum("vij,vj->vi", np.linalg.pinv(mat[ok], rcond=1e-10), rhs[ok])
    sol[:, 1] /= np.sqrt(2.0)
    tensor = np.stack([sol[:, [0, 1]], sol[:, [1, 2]]], axis=1)
    return ShapeOperator(tensor, basis, nrm)


def principal_curvatures(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, edge_weights: str = "voronoi",
                         normals: str = "max") -> PrincipalCurvatures:
    """Principal curvatures κ1 ≤ κ2 and directions: eigenpairs of the least-squares shape operator.

    Thesis: Definition 3.3 and §3.3.4 (the principal curvatures are the eigenvalues of S).

    Parameters
    ----------
    vertices, simplices, edge_weights, normals
        As in :func:`shape_operator`.

    Returns
    -------
    PrincipalCurvatures
        ``k1``, ``k2`` (nv,) and unit directions ``d1``, ``d2`` (nv, 3) in the tangent plane; NaN where
        :func:`shape_operator` is NaN.  Signs as in the module docstring.

    Examples
    --------
    On a sphere of radius 2 both principal curvatures are 1/r = 0.5:

    >>> import numpy as np
    >>> from thesis_lib.meshes import sphere_hull
    >>> vertices, triangles = sphere_hull(n_points=200, radius=2.0, seed=0)
    >>> pc = principal_curvatures(vertices, triangles)
    >>> round(float(np.median(pc.k1)), 3), round(float(np.median(pc.k2)), 3)
    (0.5, 0.5)
    """
    so = shape_operator(vertices, simplices, edge_weights=edge_weights, normals=normals)
    nv = len(so.tensor)
    k = np.full((nv, 2), np.nan)
    vec = np.full((nv, 2, 2), np.nan)
    ok = np.all(np.isfinite(so.tensor), axis=(1, 2))
    if ok.any():
        k[ok], vec[ok] = np.linalg.eigh(so.tensor[ok])  # ascending eigenvalues
    dirs = np.einsum("vcj,vca->vja", vec, so.basis)  # (nv, 2 eigvecs, 3)
    return PrincipalCurvatures(k[:, 0], k[:, 1], dirs[:, 0], dirs[:, 1])

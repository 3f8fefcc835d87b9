"""Discrete Gaussian curvature of triangle meshes: angle defect over area (§3.3.3)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .areas import check_area, vertex_areas_of_mesh
from .manifold import checked_mesh
from .validate import Mesh

__all__ = ["angle_defects", "gaussian_curvature"]


def _angle_defects(mesh: Mesh) -> np.ndarray:
    if mesh.n != 2:
        raise ValueError(f"the angle defect is defined for triangle meshes (n = 2), got n = {mesh.n}")
    v, s, tri = mesh.vertices, mesh.simplices, mesh.tri
    angles = np.arctan2(np.broadcast_to(tri.twice_area, tri.dot.shape), tri.dot)  # (3 corners, m)
    defect = 2.0 * np.pi - np.bincount(s.T.ravel(), weights=angles.ravel(), minlength=len(v))
    defect[mesh.no_estimate] = np.nan
    return defect


def angle_defects(vertices: npt.ArrayLike, simplices: npt.ArrayLike) -> np.ndarray:
    """Angle defect 2π − Σ_j θ_j at every vertex: the integrated Gaussian curvature.

    Thesis: Equation (3.20) (∫_A K dA = 2π − Σ θ_j over a vertex's region).

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
    simplices : array_like of int, shape (m, 3)
        A simplicial pseudo-manifold (checked: no doubled face, no pinched vertex).

    Returns
    -------
    ndarray, shape (nv,)
        NaN on boundary and pinched vertices (there the defect would be π − Σ θ_j plus the boundary's turning)
        and on isolated vertices.  On a closed mesh the sum is 2πχ (Theorem 3.8).

    Examples
    --------
    At each vertex of the octahedron four angles π/3 meet: the defect is 2π/3, and the six defects
    sum to 2πχ = 4π (Theorem 3.8):

    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> np.round(angle_defects(octahedron, faces), 6).tolist()
    [2.094395, 2.094395, 2.094395, 2.094395, 2.094395, 2.094395]
    >>> round(float(angle_defects(octahedron, faces).sum() / (2 * np.pi)), 6)
    2.0
    """
    return _angle_defects(checked_mesh(vertices, simplices))


def gaussian_curvature(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, area: str = "mixed") -> np.ndarray:
    """Discrete Gaussian curvature K = (2π − Σ_j θ_j) / area at every vertex.

    Thesis: Definition 3.21 (Voronoi (3.21) or barycentric (3.22) region; "mixed" = Meyer et al.).

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
    simplices : array_like of int, shape (m, 3)
    area : {"mixed", "voronoi", "barycentric"}
        Vertex area, see :func:`thesis_lib.curvature.vertex_areas`.

    Returns
    -------
    ndarray, shape (nv,)
        NaN on boundary, pinched and isolated vertices and where the vertex area is not positive (possible
        with the signed ``"voronoi"`` area).  Independent of the triangles' orientation.

    Warns
    -----
    UserWarning
        Boundary vertices at exactly the coordinates of other vertices (a triangle soup): as
        :func:`~thesis_lib.curvature.mean_curvature`.

    Raises
    ------
    ValueError
        On an invalid mesh, an unknown area kind, or a hypersurface with n ≠ 2.

    Examples
    --------
    On a triangulated sphere of radius 2 the discrete K is close to 1/r² = 0.25:

    >>> import numpy as np
    >>> from thesis_lib.meshes import sphere_hull
    >>> vertices, triangles = sphere_hull(n_points=200, radius=2.0, seed=0)
    >>> round(float(np.median(gaussian_curvature(vertices, triangles))), 2)
    0.25
    """
    area = check_area(area)
    mesh = checked_mesh(vertices, simplices)
    defect = _angle_defects(mesh)
    a = vertex_areas_of_mesh(mesh, area)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = defect / a
    k[~(a > 0)] = np.nan
    return k

"""Discrete differential geometry of triangulated (hyper)surfaces: thesis chapter 3, §3.3.

Vertices are ``(nv, n + 1)`` points of R^{n+1}; top simplices ``(m, n + 1)`` vertex indices of the
n-simplices of the hypersurface (n = 2 is a triangle mesh).  Every function validates its input
through :func:`validate_mesh` (one module, ``curvature.validate``; the simplices' geometry is in
``curvature.geometry``).  The exact curvatures of the smooth surfaces they are measured against are
in :mod:`thesis_lib.surfaces`; estimates on point clouds in :mod:`.point_curvature` (a surface by
the Crust, or none) and ``curvature.pointcloud``.
"""

from .areas import AREA_KINDS, circumcentric_fractions, vertex_areas
from .gaussian import angle_defects, gaussian_curvature
from .geometry import boundary_vertices, simplex_hyperareas
from .manifold import check_pseudomanifold, pinched_vertices
from .mean import mean_curvature, mean_curvature_vector, total_hyperarea
from .shape import (
    PrincipalCurvatures,
    ShapeOperator,
    normal_curvatures,
    principal_curvatures,
    shape_operator,
    vertex_normals,
)
from .stencil import cross_stars, neighbour_grid_mean_curvature
from .validate import check_orientation, validate_mesh

__all__ = [
    "AREA_KINDS",
    "cross_stars",
    "neighbour_grid_mean_curvature",
    "PrincipalCurvatures",
    "ShapeOperator",
    "angle_defects",
    "boundary_vertices",
    "check_pseudomanifold",
    "check_orientation",
    "circumcentric_fractions",
    "gaussian_curvature",
    "mean_curvature",
    "mean_curvature_vector",
    "normal_curvatures",
    "pinched_vertices",
    "principal_curvatures",
    "shape_operator",
    "simplex_hyperareas",
    "total_hyperarea",
    "validate_mesh",
    "vertex_areas",
    "vertex_normals",
]

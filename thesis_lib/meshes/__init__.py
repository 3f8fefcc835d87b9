"""Triangulations for chapter 3: parameter grids (torus, Freudenthal subdivisions of the 3-sphere
and the n-catenoid), convex hulls of spheres, random surface samples, the Crust algorithm [ABK98]
and ball pivoting; plus the thesis's neighbour-grid stencil, topological checks, and mesh files and
pyvista meshes in and out (``meshes.io``).
"""

from .crust import crust, crust_candidates, extract_manifold, poles
from .grids import (
    catenoid_freudenthal,
    freudenthal,
    grid_parameters,
    hypersphere_freudenthal,
    merge_coincident,
    torus_chosen_points,
    torus_grid,
)
from .hull import convex_hull_surface, orient_outward, sphere_hull
from .io import from_pyvista, read_mesh, to_pyvista, write_mesh
from .pivoting import ball_pivoting, estimate_normals
from .plotting import mesh_figure, render_mesh
from .reconstruct import RECONSTRUCTIONS, reconstruct_surface
from .sampling import sample_catenoid, sample_sphere, sample_torus
from .stencil import cross_stars, neighbour_grid_mean_curvature
from .topology import euler_characteristic, faces_of, facet_degrees, is_closed_pseudomanifold

__all__ = [
    "RECONSTRUCTIONS",
    "ball_pivoting",
    "catenoid_freudenthal",
    "convex_hull_surface",
    "cross_stars",
    "crust",
    "crust_candidates",
    "estimate_normals",
    "euler_characteristic",
    "extract_manifold",
    "faces_of",
    "facet_degrees",
    "freudenthal",
    "from_pyvista",
    "grid_parameters",
    "hypersphere_freudenthal",
    "is_closed_pseudomanifold",
    "merge_coincident",
    "mesh_figure",
    "neighbour_grid_mean_curvature",
    "orient_outward",
    "poles",
    "read_mesh",
    "reconstruct_surface",
    "render_mesh",
    "sample_catenoid",
    "sample_sphere",
    "sample_torus",
    "sphere_hull",
    "to_pyvista",
    "torus_chosen_points",
    "torus_grid",
    "write_mesh",
]

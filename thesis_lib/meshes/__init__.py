"""Triangulations for chapter 3: parameter grids (torus, Freudenthal subdivisions of the 3-sphere
and the n-catenoid), convex hulls of spheres, random surface samples, topological checks, slices,
and mesh files and pyvista meshes in and out (``meshes.io``).  Reconstructions from samples are in
:mod:`thesis_lib.reconstruction`.
"""

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
from .plotting import mesh_figure, render_mesh
from .sampling import sample_catenoid, sample_sphere, sample_torus
from .topology import euler_characteristic, faces_of, facet_degrees, is_closed_pseudomanifold

__all__ = [
    "catenoid_freudenthal",
    "convex_hull_surface",
    "euler_characteristic",
    "faces_of",
    "facet_degrees",
    "freudenthal",
    "from_pyvista",
    "grid_parameters",
    "hypersphere_freudenthal",
    "is_closed_pseudomanifold",
    "merge_coincident",
    "mesh_figure",
    "orient_outward",
    "read_mesh",
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

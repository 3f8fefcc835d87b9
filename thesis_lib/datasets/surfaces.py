"""Surfaces of chapter 3 (re-exported from :mod:`thesis_lib.meshes`): the torus grid and samplers."""

from ..meshes import sample_catenoid, sample_sphere, sample_torus, torus_grid

__all__ = ["torus_grid", "sample_torus", "sample_catenoid", "sample_sphere"]

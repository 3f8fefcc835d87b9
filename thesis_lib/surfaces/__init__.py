"""The smooth (hyper)surfaces of chapter 3 and their exact curvatures: the references of §3.4.

One module per surface (the torus, the n-sphere, the n-catenoid, ellipsoids), one for any
parametrised hypersurface (normal, fundamental forms, shape operator by differentiation) and one for
the Gauss–Bonnet–Chern theorem.  The discrete estimates of :mod:`thesis_lib.curvature` are measured
against these.
"""

from .catenoid import catenoid_mean_curvature, catenoid_point, catenoid_principal_curvatures
from .ellipsoid import ellipsoid_point
from .gauss_bonnet import gauss_bonnet_chern_constant, total_gauss_kronecker_curvature
from .hypersphere import hypersphere_mean_curvature, hypersphere_point, hypersphere_quadrature, hypersphere_volume
from .parametric import fundamental_forms, hypersurface_normal, normal_curvature_circle, parametric_shape_operator
from .torus import (
    torus_gaussian_curvature,
    torus_gaussian_curvature_at,
    torus_mean_curvature,
    torus_mean_curvature_at,
    torus_outer_inner_ratio,
    torus_point,
    torus_principal_curvatures,
    torus_principal_curvatures_at,
    torus_shape_operator,
    torus_uv,
)

__all__ = [
    "catenoid_mean_curvature",
    "catenoid_point",
    "catenoid_principal_curvatures",
    "ellipsoid_point",
    "fundamental_forms",
    "gauss_bonnet_chern_constant",
    "hypersphere_mean_curvature",
    "hypersphere_point",
    "hypersphere_quadrature",
    "hypersphere_volume",
    "hypersurface_normal",
    "normal_curvature_circle",
    "parametric_shape_operator",
    "total_gauss_kronecker_curvature",
    "torus_gaussian_curvature",
    "torus_gaussian_curvature_at",
    "torus_mean_curvature",
    "torus_mean_curvature_at",
    "torus_outer_inner_ratio",
    "torus_point",
    "torus_principal_curvatures",
    "torus_principal_curvatures_at",
    "torus_shape_operator",
    "torus_uv",
]

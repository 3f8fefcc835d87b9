"""The smooth (hyper)surfaces of chapter 3 and their exact curvatures: the references of §3.4.

One module per surface (the torus, the n-sphere, the n-catenoid, ellipsoids), one for any
parametrised hypersurface (normal, fundamental forms, shape operator by differentiation) and one for
the Gauss–Bonnet–Chern theorem.  The discrete estimates of :mod:`thesis_lib.curvature` are measured
against these.

Sign conventions follow the thesis: the normal is N = X_{u_1} ∧ ... ∧ X_{u_n} / W (eq. 3.9, for
n = 2 the cross product X_u × X_v), the shape operator is S = -N_* (Definition 3.1, eq. 3.10),
H = tr(S)/n and K = det(S) (Definitions 3.4 and 3.10).  The discrete estimates of
:mod:`thesis_lib.curvature` give |H| = ||∇area|| / (n · area), to be compared with ``abs`` of the
signed values returned here.
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

"""The computed statements of chapter 3 (discrete differential geometry), one section each.

Each ``*_section`` function computes what one part of the chapter 3 page shows and records: a
:class:`~thesis_lib.chapters.morse_tables.Section` of Markdown ``texts``, flat ``results`` (for
:meth:`thesis_lib.lab.results.Recorder.record`) and ``glued`` values (for the prose).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from math import factorial

import numpy as np

from .._validate import check_int, check_real, check_seed
from ..curvature import (
    angle_defects,
    mean_curvature_vector,
    normal_curvatures,
    simplex_hyperareas,
    vertex_areas,
    vertex_normals,
)
from ..curvature import checks_theory as ct
from ..curvature.checks import (
    corollary_3_19_coefficient,
    exterior_angles,
    hyperarea_gradient_fd,
    nearest_vertex_volumes,
    printed_sum_gradient,
    random_simplices,
    thales_obtuse,
)
from ..lab.results import round_sig
from ..meshes import euler_characteristic, hypersphere_freudenthal, sphere_hull, torus_grid
from ..surfaces import (
    catenoid_point,
    catenoid_principal_curvatures,
    ellipsoid_point,
    gauss_bonnet_chern_constant,
    hypersphere_point,
    hypersphere_quadrature,
    hypersphere_volume,
    hypersurface_normal,
    normal_curvature_circle,
    parametric_shape_operator,
    torus_gaussian_curvature,
    torus_mean_curvature,
    torus_point,
    torus_shape_operator,
    total_gauss_kronecker_curvature,
)
from .morse_tables import Section

__all__ = [
    "area_variation_ratios",
    "catenoid_section",
    "chapter_of_voronoi_section",
    "corollary_height_section",
    "discrete_gauss_bonnet_section",
    "ellipsoid_parametrisation",
    "flower_curve",
    "gauss_bonnet_caps_section",
    "gauss_bonnet_chern_section",
    "gauss_image_section",
    "gauss_map_section",
    "hodge_dual_section",
    "hypersurface_experiment_glue",
    "mean_curvature_gradient_section",
    "octant_quadrature",
    "rounded_error",
    "shape_operator_section",
    "sphere_region_section",
    "theorem_3_12_section",
    "theorem_3_18_section",
    "torus_experiment_glue",
    "torus_shape_operator_section",
    "turning_and_octant_section",
    "variation_of_area_section",
    "vector_norm_section",
    "voronoi_area_section",
]

Surface = Callable[[np.ndarray], np.ndarray]
ELLIPSOID_2 = (1.0, 1.5, 2.0)
ELLIPSOID_3 = (1.0, 1.25, 1.5, 1.75)
ELLIPSOID_4 = (1.0, 1.25, 1.5, 1.75, 2.0)


def _radii(R: float, r: float) -> tuple[float, float]:
    R, r = check_real(R, "R", positive=True), check_real(r, "r", positive=True)
    if not r < R:
        raise ValueError(f"the torus needs r < R, got R={R}, r={r}")
    return R, r


def _dims(dims: Sequence[int], name: str, *, minimum: int, even: bool = False) -> list[int]:
    out = [check_int(n, name, minimum=minimum) for n in dims]
    if not out or (even and any(n % 2 for n in out)):
        raise ValueError(f"{name} must hold {'even ' if even else ''}dimensions >= {minimum}, got {list(dims)!r}")
    return out


def rounded_error(x: float, digits: int) -> tuple[float, str]:
    """A numerical error rounded to ``digits`` decimals, and as text ("below 10⁻ᵈ" when it rounds to 0).

    Thesis: §3.1–§3.3 (the numerical checks of the chapter's identities).

    Finite-difference and rounding noise below that accuracy depends on the machine.

    Parameters
    ----------
    x : float
        The error.
    digits : int
        Decimals kept.

    Returns
    -------
    tuple of (float, str)
        The rounded value (``-0.0`` made ``0.0``) and its text.

    Raises
    ------
    ValueError
        If ``digits`` is negative (TypeError if it is not an integer).

    Examples
    --------
    >>> rounded_error(3e-15, 12)
    (0.0, 'below $10^{-12}$')
    >>> rounded_error(0.0123, 3)
    (0.012, '0.012')
    """
    value = round(float(x), check_int(digits, "digits", minimum=0)) + 0.0
    return value, (f"below $10^{{-{digits}}}$" if value == 0 else f"{value:g}")


def ellipsoid_parametrisation(axes: Sequence[float]) -> tuple[Surface, Surface]:
    """The ellipsoid with these semi-axes and its outward unit normal, as functions of the angles.

    Thesis: §3.2 (hypersurfaces; the ellipsoid is our test surface for the chapter's theorems).

    Parameters
    ----------
    axes : sequence of float
        The n + 1 semi-axes.

    Returns
    -------
    tuple of callables
        ``X(w)`` and ``N(w)`` for angles ``w`` of shape ``(..., n)``.

    Raises
    ------
    ValueError
        If ``axes`` is not a list of at least two positive numbers.

    Examples
    --------
    >>> X, N = ellipsoid_parametrisation([1.0, 1.5, 2.0])
    >>> w = np.array([0.7, 0.4])
    >>> bool(np.isclose(np.linalg.norm(N(w)), 1.0)), bool(np.isclose(np.sum((X(w) / [1, 1.5, 2]) ** 2), 1.0))
    (True, True)
    """
    a = np.asarray(axes, dtype=float)
    if a.ndim != 1 or len(a) < 2 or np.any(a <= 0):
        raise ValueError(f"axes must be at least two positive semi-axes, got {axes!r}")

    def X(w: np.ndarray) -> np.ndarray:
        return ellipsoid_point(w, a)

    def N(w: np.ndarray) -> np.ndarray:
        y = ellipsoid_point(w, a) / a**2
        return y / np.linalg.norm(y, axis=-1, keepdims=True)

    return X, N


def _torus(R: float, r: float) -> Surface:
    return lambda w: torus_point(w[..., 0], w[..., 1], R=R, r=r)


def _vector_text(x: np.ndarray) -> str:
    return " ".join(f"{'-' if c < 0 else '+'} e_{k + 1}" for k, c in enumerate(np.rint(x).astype(int)) if c).lstrip(
        "+ "
    )


def hodge_dual_section() -> Section:
    """The Hodge dual of §3.1.1 on the basis bivectors and against the cross product.

    Thesis: §3.1.1 (the normal as the Hodge dual of X_u ∧ X_v).

    Returns
    -------
    Section
        One text, four results.

    Examples
    --------
    >>> sec = hodge_dual_section()
    >>> sec.results["hodge_e2e1_component_3"]
    -1.0
    """
    E = np.eye(3)
    duals = {"e2e3": ct.hodge_dual(E[1], E[2]), "e1e3": ct.hodge_dual(E[0], E[2]), "e2e1": ct.hodge_dual(E[1], E[0])}
    uh, vh = np.random.default_rng(6).normal(size=(2, 200, 3))
    cross_err = float(np.abs(ct.hodge_dual(uh, vh) - np.cross(uh, vh)).max())
    results = dict(
        hodge_e2e3_component_1=round(float(duals["e2e3"][0]), 9) + 0.0,
        hodge_e1e3_component_2=round(float(duals["e1e3"][1]), 9) + 0.0,
        hodge_e2e1_component_3=round(float(duals["e2e1"][2]), 9) + 0.0,
        hodge_cross_product_max_err=rounded_error(cross_err, 12)[0],
    )
    text = (
        f"By the rule: $*(e_2\\wedge e_3) = {_vector_text(duals['e2e3'])}$, $*(e_1\\wedge e_3) = "
        f"{_vector_text(duals['e1e3'])}$, $*(e_2\\wedge e_1) = {_vector_text(duals['e2e1'])}$; on 200 random pairs "
        f"$\\max|*(u\\wedge v) - u\\times v|$ = {rounded_error(cross_err, 12)[1]}."
    )
    return Section(texts=(text,), results=results)


def torus_shape_operator_section(*, R: float = 10.0, r: float = 5.0) -> Section:
    """The torus's shape operator, H, K and Gauss-map derivative by differences against §3.4.1's forms.

    Thesis: §3.1.2, Definition 3.1 and §3.4.1 (S = diag(−cos v/(R + r cos v), −1/r)).

    Also the self-adjointness of S, checked as ⟨N_{u_i}, X_{u_j}⟩ symmetric on ellipsoids in ℝ³ and ℝ⁴.

    Parameters
    ----------
    R, r : float
        The torus's radii.

    Returns
    -------
    Section
        One text, the disagreement counts at 200 random points and the largest asymmetries.

    Raises
    ------
    ValueError
        If ``R`` or ``r`` is not positive, or ``r >= R``.

    Examples
    --------
    >>> sec = torus_shape_operator_section()
    >>> sec.results["torus_S_disagreements"], sec.results["torus_gauss_map_derivative_disagreements"]
    (0, 0)
    """
    R, r = _radii(R, r)
    torus = _torus(R, r)
    uv = np.random.default_rng(0).uniform(0, 2 * np.pi, (200, 2))
    S_num = parametric_shape_operator(torus, uv)
    S_thesis = torus_shape_operator(uv[:, 0], uv[:, 1], R=R, r=r)
    H_num, K_num = np.trace(S_num, axis1=1, axis2=2) / 2, np.linalg.det(S_num)
    disagree = {
        "S": int(np.sum(np.abs(S_num - S_thesis).max(axis=(1, 2)) > 1e-6)),
        "H": int(np.sum(np.abs(H_num - torus_mean_curvature(uv[:, 0], uv[:, 1], R=R, r=r)) > 1e-6)),
        "K": int(np.sum(np.abs(K_num - torus_gaussian_curvature(uv[:, 0], uv[:, 1], R=R, r=r)) > 1e-6)),
    }
    JN = ct.parametric_jacobian(lambda w: hypersurface_normal(ct.parametric_jacobian(torus, w)), uv, h=1e-4)
    cu, su, cv, sv = np.cos(uv[:, 0]), np.sin(uv[:, 0]), np.cos(uv[:, 1]), np.sin(uv[:, 1])
    Nu_thesis = np.column_stack([-su * cv, cu * cv, 0 * cu])
    Nv_thesis = np.column_stack([-cu * sv, -su * sv, cv])
    n_disagree = int(
        np.sum(
            np.maximum(np.abs(JN[..., 0] - Nu_thesis).max(axis=1), np.abs(JN[..., 1] - Nv_thesis).max(axis=1)) > 1e-6
        )
    )
    asym = {}
    for n_dim, axes in ((2, list(ELLIPSOID_2)), (3, list(ELLIPSOID_3))):
        Xe, _ = ellipsoid_parametrisation(axes)
        we = np.random.default_rng(7).uniform(0.3, 1.3, (100, n_dim))
        Jx = ct.parametric_jacobian(Xe, we)
        Jn = ct.parametric_jacobian(lambda w, Xe=Xe: hypersurface_normal(ct.parametric_jacobian(Xe, w)), we, h=1e-4)
        M = np.einsum("kai,kaj->kij", Jn, Jx)  # ⟨N_{u_i}, X_{u_j}⟩ = −⟨S X_i, X_j⟩
        asym[n_dim] = float(np.max(np.abs(M - np.swapaxes(M, 1, 2)).max(axis=(1, 2)) / np.abs(M).max(axis=(1, 2))))
    results = {f"torus_{k}_disagreements": v for k, v in disagree.items()}
    results["torus_gauss_map_derivative_disagreements"] = n_disagree
    results |= {f"self_adjoint_n{k}_max_rel_asymmetry": rounded_error(v, 6)[0] for k, v in asym.items()}
    text = (
        f"Of the 200 points, those where the numerical value differs from the thesis's by more than "
        f"$10^{{-6}}$: {disagree['S']} for $S$, {disagree['H']} for $H$, {disagree['K']} for $K$, {n_disagree} for "
        f"$(N_u, N_v)$.  Largest relative asymmetry of $\\langle N_{{u_i}}, X_{{u_j}}\\rangle$: "
        f"{rounded_error(asym[2], 6)[1]} on the ellipsoid in $\\mathbb{{R}}^3$, {rounded_error(asym[3], 6)[1]} in "
        f"$\\mathbb{{R}}^4$ (the accuracy of the differences)."
    )
    return Section(texts=(text,), results=results)


def gauss_image_section(*, radii: Sequence[float] = (0.1, 0.01, 0.001)) -> Section:
    """The area of the Gauss image of shrinking discs over their area and |K| (eq. 3.3).

    Thesis: §3.1.2, eq. (3.3) (N_u ∧ N_v = K X_u ∧ X_v).

    On the ellipsoid with semi-axes 1, 1.5, 2 at w₀ = (0.7, 0.4).

    Parameters
    ----------
    radii : sequence of float
        The discs' radii ε; the results name 0.1, 0.01 and 0.001.

    Returns
    -------
    Section
        A table and the ratios.

    Raises
    ------
    ValueError
        If a radius is not positive.

    Examples
    --------
    >>> sec = gauss_image_section(radii=(0.1, 0.01, 0.001))
    >>> abs(sec.results["eq33_gauss_image_ratio_eps_1e_3"] - 1) < 1e-3
    True
    """
    eps = [check_real(e, "radii", positive=True) for e in radii]
    ell2, _ = ellipsoid_parametrisation(ELLIPSOID_2)
    gauss_image = {e: ct.gauss_map_area_ratio(ell2, [0.7, 0.4], e) for e in eps}
    results = {
        f"eq33_gauss_image_ratio_eps_1e_{round(-np.log10(e))}": round_sig(gauss_image[e], 5) for e in reversed(eps)
    }
    text = (
        "| $\\epsilon$ | $A_{\\Omega_\\epsilon}(N)/(A_{\\Omega_\\epsilon}(X)\\,\\lvert K(w_0)\\rvert)$ |\n|---:|---:|\n"
        + "\n".join(f"| {e:g} | {round_sig(q, 5):.5f} |" for e, q in gauss_image.items())
    )
    return Section(texts=(text,), results=results)


def _cap_quadrature(psi0: float, nodes: int = 24, n_phi: int = 48) -> tuple[np.ndarray, np.ndarray]:
    xg, wg = np.polynomial.legendre.leggauss(nodes)
    phi = 2 * np.pi * np.arange(n_phi) / n_phi
    params = np.stack(np.meshgrid(psi0 / 2 * (xg + 1), phi, indexing="ij"), -1).reshape(-1, 2)
    weights = np.outer(psi0 / 2 * wg, np.full(n_phi, 2 * np.pi / n_phi)).ravel()
    return params, weights


def gauss_bonnet_caps_section(thesis: str, *, psi0: Sequence[float] = (0.8, 1.3, 2.2)) -> Section:
    """Gauss–Bonnet for discs: ∫K dA + ∫κ_g ds over 2π on caps of the ellipsoid (Theorem 3.5).

    Thesis: Theorem 3.5, eq. (3.4) and eq. (3.6).

    Also which statement carries eq. (3.4) in the thesis's text (the text cites a "Theorem 3.4").

    Parameters
    ----------
    thesis : str
        The thesis's text (:func:`thesis_lib.lab.chapters.read_thesis`).
    psi0 : sequence of float
        The caps {ψ < ψ₀}.

    Returns
    -------
    Section
        A table and the ratios.

    Raises
    ------
    ValueError
        If a cap's ψ₀ is not positive, or the text lacks eq. (3.4).

    Examples
    --------
    >>> text = "Theorem 3.5. ... = 2\\\\pi \\\\quad (3.4) ..."
    >>> sec = gauss_bonnet_caps_section(text, psi0=(0.8,))
    >>> sec.results["thm35_cap_8_total_over_2pi"], sec.results["thm35_number_of_the_statement_with_eq_3_4"]
    (1.0, 3.5)
    """
    psi0 = [check_real(p, "psi0", positive=True) for p in psi0]
    ell2, _ = ellipsoid_parametrisation(ELLIPSOID_2)
    caps = {}
    for p in psi0:
        params, weights = _cap_quadrature(p)
        caps[p] = (total_gauss_kronecker_curvature(ell2, params, weights), ct.cap_boundary_geodesic_curvature(ell2, p))
    theorem_of_3_4 = ct.statement_containing(thesis, "= 2\\pi \\quad (3.4)")
    theorem_3_4_exists = "Theorem 3.4." in thesis
    results = {
        f"thm35_cap_{int(10 * p)}_total_over_2pi": round_sig((k + g) / (2 * np.pi), 8) for p, (k, g) in caps.items()
    }
    results |= dict(
        thm35_number_of_the_statement_with_eq_3_4=float(theorem_of_3_4.split()[1]),
        thm35_a_theorem_3_4_exists=theorem_3_4_exists,
    )
    text = (
        "| $\\psi_0$ | $\\int K\\,dA$ | $\\int\\kappa_g\\,ds$ | sum $/2\\pi$ |\n|---:|---:|---:|---:|\n"
        + "\n".join(f"| {p} | {k:.6f} | {g:.6f} | {(k + g) / (2 * np.pi):.8f} |" for p, (k, g) in caps.items())
        + f"\n\nEq. (3.4) belongs to {theorem_of_3_4}; a Theorem 3.4 exists in the text: {theorem_3_4_exists}."
    )
    return Section(texts=(text,), results=results)


def flower_curve(*, n: int = 2000) -> np.ndarray:
    """The non-convex closed plane curve ρ = 1 + 0.3 cos 3t, sampled at ``n`` angles.

    Thesis: Example 3.6 (the turning of a closed plane curve is 2π).

    Parameters
    ----------
    n : int
        Number of samples.

    Returns
    -------
    ndarray of shape (n, 2)

    Raises
    ------
    ValueError
        If ``n`` is below 3.

    Examples
    --------
    >>> curve = flower_curve(n=400)
    >>> round(float(exterior_angles(curve).sum() / (2 * np.pi)), 9)
    1.0
    """
    n = check_int(n, "n", minimum=3)
    t = 2 * np.pi * np.arange(n) / n
    rho = 1 + 0.3 * np.cos(3 * t)  # non-convex: its exterior angles change sign
    return np.column_stack([rho * np.cos(t), rho * np.sin(t)])


def octant_quadrature(*, nodes: int = 24) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights on the angles (ψ, φ) ∈ [0, π/2]² of the sphere's first octant.

    Thesis: eq. (3.7) and Example 3.7 (the octant, a triangle with three right angles).

    Parameters
    ----------
    nodes : int
        Nodes per angle.

    Returns
    -------
    tuple of ndarray
        Parameters of shape (nodes², 2) and weights of shape (nodes²,).

    Raises
    ------
    ValueError
        If ``nodes`` is below 1.

    Examples
    --------
    >>> params, weights = octant_quadrature(nodes=8)
    >>> params.shape, round(float(weights.sum() / (np.pi / 2) ** 2), 12)
    ((64, 2), 1.0)
    """
    x, w = np.polynomial.legendre.leggauss(check_int(nodes, "nodes", minimum=1))
    grid = np.pi / 4 * (x + 1)
    params = np.stack(np.meshgrid(grid, grid, indexing="ij"), -1).reshape(-1, 2)
    return params, np.outer(np.pi / 4 * w, np.pi / 4 * w).ravel()


def _unit_sphere(a: np.ndarray) -> np.ndarray:
    return hypersphere_point(a, radius=1.0)


def turning_and_octant_section() -> Section:
    """The turning of a closed curve (Example 3.6), the octant (eq. 3.7) and the hemisphere (Example 3.7).

    Thesis: Example 3.6, eq. (3.7) and Example 3.7.

    Returns
    -------
    Section
        One text, three results.

    Examples
    --------
    >>> sec = turning_and_octant_section()
    >>> float(sec.results["ex36_turning_over_2pi"]), sec.results["eq37_octant_integral_K_over_formula"]
    (1.0, 1.0)
    """
    curve = flower_curve()
    turning = exterior_angles(curve).sum()
    corners = np.eye(3)  # the octant: great-circle arcs between the coordinate axes
    alpha = [
        np.arccos(
            np.dot(
                np.cross(np.cross(corners[i], corners[j]), corners[i]),
                np.cross(np.cross(corners[i], corners[k]), corners[i]),
            )
        )
        for i, j, k in [(0, 1, 2), (1, 2, 0), (2, 0, 1)]
    ]
    octant, octant_weights = octant_quadrature()
    octant_K = total_gauss_kronecker_curvature(_unit_sphere, octant, octant_weights)
    x, w = np.polynomial.legendre.leggauss(24)
    hemi = np.stack(np.meshgrid(np.pi / 4 * (x + 1), 2 * np.pi * np.arange(48) / 48, indexing="ij"), -1).reshape(-1, 2)
    hemi_w = np.outer(np.pi / 4 * w, np.full(48, 2 * np.pi / 48)).ravel()  # ψ < π/2
    hemisphere_K = total_gauss_kronecker_curvature(_unit_sphere, hemi, hemi_w)
    results = dict(
        ex36_turning_over_2pi=round(turning / (2 * np.pi), 9) + 0.0,
        eq37_octant_integral_K_over_formula=round_sig(octant_K / ((2 - 3) * np.pi + sum(alpha)), 6),
        ex37_hemisphere_integral_K_over_2pi=round_sig(hemisphere_K / (2 * np.pi), 6),
    )
    text = (
        f"Turning of the sampled curve: {turning / np.pi:.6f}$\\pi$ (exterior angles from "
        f"{exterior_angles(curve).min():.2g} to {exterior_angles(curve).max():.2g}).  Octant: interior angles "
        f"{', '.join(f'{a:.4f}°' for a in np.degrees(alpha))}; $\\int K\\,dA$ = {octant_K / np.pi:.6f}$\\pi$ against "
        f"$(2 - 3)\\pi + \\sum\\alpha$ = {((2 - 3) * np.pi + sum(alpha)) / np.pi:.6f}$\\pi$.  Northern hemisphere: "
        f"$\\int K\\,dA$ = {hemisphere_K / np.pi:.6f}$\\pi$."
    )
    return Section(texts=(text,), results=results)


def discrete_gauss_bonnet_section(*, R: float = 10.0, r: float = 5.0, n: int = 80) -> Section:
    """Gauss–Bonnet for closed surfaces (Theorem 3.8): ∫K dA and the sum of angle defects over 2π.

    Thesis: Theorem 3.8 (∫K dA = 2πχ) and its discrete form Σ(2π − Σθ) = 2πχ.

    On the torus (quadrature, and an n × n grid), the ellipsoid (1, 1.5, 2) and the convex hull of
    500 points on S²; 3F − 2E = 0 for a closed surface.

    Parameters
    ----------
    R, r : float
        The torus's radii.
    n : int
        The torus grid's size.

    Returns
    -------
    Section
        One text with a table, six results.

    Raises
    ------
    ValueError
        If ``R`` or ``r`` is not positive, ``r >= R``, or ``n`` is below 3.

    Examples
    --------
    >>> sec = discrete_gauss_bonnet_section(n=20)
    >>> [float(sec.results[f"thm38_{m}_defects_over_2pi"]) for m in ("torus_grid", "sphere_hull")]
    [0.0, 2.0]
    """
    R, r = _radii(R, r)
    n = check_int(n, "n", minimum=3)
    grid_uv = np.stack(np.meshgrid(*[2 * np.pi * np.arange(120) / 120] * 2, indexing="ij"), -1).reshape(-1, 2)
    torus_K = total_gauss_kronecker_curvature(_torus(R, r), grid_uv, np.full(len(grid_uv), (2 * np.pi / 120) ** 2))
    ell2, _ = ellipsoid_parametrisation(ELLIPSOID_2)
    ellipsoid_K = total_gauss_kronecker_curvature(ell2, *hypersphere_quadrature(2, nodes=24))
    meshes = {
        f"torus grid {n} × {n}": torus_grid(n, R=R, r=r),
        "convex hull of 500 points on S²": sphere_hull(n_dims=3, n_points=500, seed=1),
    }
    counts = {}
    for name, (vv, ff) in meshes.items():
        edges = {tuple(sorted(e)) for f in ff.tolist() for e in ((f[0], f[1]), (f[1], f[2]), (f[0], f[2]))}
        counts[name] = (angle_defects(vv, ff).sum(), euler_characteristic(ff), 3 * len(ff) - 2 * len(edges))
    torus_c, hull_c = counts.values()
    results = dict(
        thm38_torus_integral_K_below_1e_6=bool(abs(torus_K) < 1e-6),
        thm38_ellipsoid_integral_K_over_2pi=round_sig(ellipsoid_K / (2 * np.pi), 6),
        thm38_torus_grid_defects_over_2pi=round(torus_c[0] / (2 * np.pi), 9) + 0.0,
        thm38_sphere_hull_defects_over_2pi=round(hull_c[0] / (2 * np.pi), 9) + 0.0,
        thm38_torus_grid_3F_minus_2E=torus_c[2],
        thm38_sphere_hull_3F_minus_2E=hull_c[2],
    )
    text = (
        f"Torus: $|\\int K\\,dA| < 10^{{-6}}$: {abs(torus_K) < 1e-6}; ellipsoid (1, 1.5, 2): $\\int K\\,dA$ = "
        f"{ellipsoid_K / np.pi:.6f}$\\pi$.\n\n| mesh | $\\sum$ angle defects | $\\chi$ | $3F - 2E$ |\n"
        f"|---|---:|---:|---:|\n"
        + "\n".join(
            f"| {name} | {round(total / np.pi, 6) + 0.0:.6f}$\\pi$ | {chi} | {d} |"
            for name, (total, chi, d) in counts.items()
        )
    )
    return Section(texts=(text,), results=results)


def area_variation_ratios(
    X: Surface, N: Surface, lam: Surface, params: np.ndarray, weights: np.ndarray, n: int
) -> tuple[float, float, float, float]:
    """−δA of the normal variation λN over n∫λ dA (as printed, no H) and over n∫λH dA (with H).

    Thesis: Theorem 3.9 and Theorem 3.12 (the first variation of area).

    Parameters
    ----------
    X, N, lam : callables
        The parametrisation, its unit normal and the variation's speed, of parameters ``(..., n)``.
    params, weights : ndarray
        A quadrature of the parameter domain.
    n : int
        The dimension of the hypersurface.

    Returns
    -------
    tuple of float
        −δA/(n∫λ dA), −δA/(n∫λH dA) (nan when ∫λH dA vanishes), −δA and n∫λ dA.

    Examples
    --------
    >>> X = lambda a: hypersphere_point(a, radius=2.0)
    >>> p, w = hypersphere_quadrature(2, nodes=12)
    >>> printed, with_h, _, _ = area_variation_ratios(X, _unit_sphere, lambda a: 1 + 0 * a[..., 0], p, w, 2)
    >>> round(float(printed), 6), round(float(with_h), 6)
    (-0.5, 1.0)
    """
    dA = ct.first_variation_of_area(X, lambda a: lam(a)[..., None] * N(a), params, weights)
    J = ct.parametric_jacobian(X, params)
    plain = np.sum(weights * lam(params) * np.sqrt(np.linalg.det(np.einsum("kai,kaj->kij", J, J))))
    with_h = ct.mean_curvature_integral(X, N, lam, params, weights)
    return -dA / (n * plain), (-dA / (n * with_h) if abs(with_h) > 1e-12 else np.nan), -dA, n * plain


def _disc(a: np.ndarray) -> np.ndarray:
    return np.stack([a[..., 0] * np.cos(a[..., 1]), a[..., 0] * np.sin(a[..., 1]), 0 * a[..., 0]], -1)


def _up(a: np.ndarray) -> np.ndarray:
    return np.stack([0 * a[..., 0], 0 * a[..., 0], 1 + 0 * a[..., 0]], -1)


def _bump(a: np.ndarray) -> np.ndarray:
    return (1 - a[..., 0] ** 2) ** 2


def _wave(a: np.ndarray) -> np.ndarray:
    return 1 + 0.5 * np.cos(a[..., 0])


def _sphere2(a: np.ndarray) -> np.ndarray:
    return hypersphere_point(a, radius=2.0)


def variation_of_area_section() -> Section:
    """Theorem 3.9 as printed (no H) and with H, on a flat disc, a sphere of radius 2 and an ellipsoid.

    Thesis: Theorem 3.9 (−δA_Ω(X, Y) printed without the mean curvature).

    Returns
    -------
    Section
        One table, four results.

    Examples
    --------
    >>> sec = variation_of_area_section()
    >>> sec.results["thm39_sphere_minus_dA_over_printed"], sec.results["thm39_sphere_minus_dA_over_with_H"]
    (-0.5, 1.0)
    """
    xr, wr = np.polynomial.legendre.leggauss(24)
    phi48 = 2 * np.pi * np.arange(48) / 48
    disc_params = np.stack(np.meshgrid((xr + 1) / 2, phi48, indexing="ij"), -1).reshape(-1, 2)  # (ρ, φ)
    disc_weights = np.outer(wr / 2, np.full(48, 2 * np.pi / 48)).ravel()
    params2, weights2 = hypersphere_quadrature(2, nodes=24)
    ell2, ell2_normal = ellipsoid_parametrisation(ELLIPSOID_2)
    disc, sphere, ellipsoid = (
        area_variation_ratios(_disc, _up, _bump, disc_params, disc_weights, 2),
        area_variation_ratios(_sphere2, _unit_sphere, _wave, params2, weights2, 2),
        area_variation_ratios(ell2, ell2_normal, _wave, params2, weights2, 2),
    )
    variation = {
        "flat disc, λ = (1 − ρ²)²": disc,
        "sphere of radius 2, λ = 1 + ½cos ψ": sphere,
        "ellipsoid (1, 1.5, 2), λ = 1 + ½cos ψ": ellipsoid,
    }
    results = dict(
        thm39_disc_minus_dA_over_printed=round(disc[0], 8) + 0.0,
        thm39_sphere_minus_dA_over_printed=round_sig(sphere[0], 6),
        thm39_sphere_minus_dA_over_with_H=round_sig(sphere[1], 6),
        thm39_ellipsoid_minus_dA_over_with_H=round_sig(ellipsoid[1], 6),
    )
    text = (
        "| surface | $-\\delta A$ | $2\\int\\lambda\\,dA$ | $-\\delta A/(2\\int\\lambda\\,dA)$ | "
        "$-\\delta A/(2\\int\\lambda H\\,dA)$ |\n|---|---:|---:|---:|---:|\n"
        + "\n".join(
            f"| {name} | {round(d, 8) + 0.0:.6g} | {p:.6g} | {round(a, 8) + 0.0:.6g} | "
            + ("—" if np.isnan(b) else f"{b:.6f}")
            + " |"
            for name, (a, b, d, p) in variation.items()
        )
    )
    return Section(texts=(text,), results=results)


def gauss_map_section() -> Section:
    """The Gauss map of a hypersurface goes to Sⁿ, and pulls back the volume form times K (eq. 3.14).

    Thesis: §3.2, eq. (3.14).

    Returns
    -------
    Section
        One text, five results.

    Examples
    --------
    >>> sec = gauss_map_section()
    >>> sec.results["sec32_gauss_map_sphere_dimension_n3"], sec.results["eq314_pullback_over_K_n3"]
    (3, -1.0)
    """
    ell2, _ = ellipsoid_parametrisation(ELLIPSOID_2)
    ell3, _ = ellipsoid_parametrisation(ELLIPSOID_3)
    ell4, _ = ellipsoid_parametrisation(ELLIPSOID_4)
    w3 = np.random.default_rng(8).uniform(0.3, 1.3, (100, 3))
    N3 = hypersurface_normal(ct.parametric_jacobian(ell3, w3))
    sphere_dimension = N3.shape[-1] - 1
    unit_err = float(np.abs(np.linalg.norm(N3, axis=1) - 1).max())
    pullback = {
        n_dim: float(
            np.median(ct.gauss_map_pullback_ratio(Xp, np.random.default_rng(9 + n_dim).uniform(0.3, 1.3, (50, n_dim))))
        )
        for n_dim, Xp in ((2, ell2), (3, ell3), (4, ell4))
    }
    results = dict(
        sec32_gauss_map_sphere_dimension_n3=sphere_dimension,
        sec32_gauss_map_unit_max_err=rounded_error(unit_err, 12)[0],
    )
    results |= {f"eq314_pullback_over_K_n{k}": round_sig(q, 3) for k, q in pullback.items()}
    text = (
        f"On the 3-dimensional ellipsoid in $\\mathbb{{R}}^4$ the normal has {N3.shape[-1]} components and "
        f"$\\max\\bigl|\\,\\|N\\| - 1\\bigr|$ {rounded_error(unit_err, 12)[1]}: the Gauss map goes to "
        f"$\\mathbb{{S}}^{{{sphere_dimension}}}$.  Median of $\\det(N, DN\\xi)/(K\\det(N, \\xi))$: "
        + ", ".join(f"{round_sig(q, 3):.3g} for $n = {k}$" for k, q in pullback.items())
        + "."
    )
    return Section(texts=(text,), results=results)


def gauss_bonnet_chern_section(*, dims: Sequence[int] = (2, 4, 6, 8)) -> Section:
    """The constant of Theorem 3.11 against vol Sⁿ/2, and ∫K dVol of a 4-ellipsoid against it.

    Thesis: Theorem 3.11 (Gauss–Bonnet–Chern, ∫K = (π^m 2^n m!/n!) χ for n = 2m).

    Parameters
    ----------
    dims : sequence of int
        Even dimensions n for the constant's table.

    Returns
    -------
    Section
        A table, one result per dimension and the ellipsoid's ratio.

    Raises
    ------
    ValueError
        If ``dims`` is empty or holds an odd dimension or one below 2.

    Examples
    --------
    >>> sec = gauss_bonnet_chern_section(dims=(2, 4))
    >>> sec.results["thm311_constant_ratio_n2"], round(sec.results["thm311_ellipsoid4_integral_K_over_formula"], 4)
    (1.0, 1.0)
    """
    dims = _dims(dims, "dims", minimum=2, even=True)
    ratios = {n: hypersphere_volume(n) / 2 / gauss_bonnet_chern_constant(n) for n in dims}
    axes4 = list(ELLIPSOID_4)
    params4, weights4 = hypersphere_quadrature(4, nodes=20)
    ellipsoid4_K = total_gauss_kronecker_curvature(ellipsoid_parametrisation(axes4)[0], params4, weights4)
    results = {f"thm311_constant_ratio_n{n}": round_sig(q, 10) for n, q in ratios.items()}
    results["thm311_ellipsoid4_integral_K_over_formula"] = round_sig(
        ellipsoid4_K / (gauss_bonnet_chern_constant(4) * 2), 6
    )
    text = (
        "| $n$ | $(\\operatorname{vol}\\mathbb{S}^n/2)/(\\pi^m 2^n m!/n!)$ |\n|---:|---:|\n"
        + "\n".join(f"| {n} | {q:.9f} |" for n, q in ratios.items())
        + f"\n\n4-ellipsoid with semi-axes {', '.join(f'{a:g}' for a in axes4)}: $\\int K\\,d\\mathrm{{Vol}}$ = "
        f"{ellipsoid4_K:.5f}, $(\\pi^2 2^4 2!/4!)\\,\\chi$ = {gauss_bonnet_chern_constant(4) * 2:.5f}."
    )
    return Section(texts=(text,), results=results)


def _freudenthal_sphere() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    V3, S3, _ = hypersphere_freudenthal(step=np.pi / 8, radius=2.0, n=3)
    return V3, S3, mean_curvature_vector(V3, S3)


def theorem_3_12_section() -> Section:
    """Theorem 3.12 on a 3-ellipsoid, and its discrete radial form on a triangulated 3-sphere (Euler's identity).

    Thesis: Theorem 3.12 (−δA = n∫λH dA for hypersurfaces).

    Returns
    -------
    Section
        One text, two results.

    Examples
    --------
    >>> sec = theorem_3_12_section()
    >>> sec.results["thm312_ellipsoid3_minus_dA_over_n_int_lambda_H"], sec.results["thm312_homogeneity_holds"]
    (1.0, True)
    """
    ell3, ell3_normal = ellipsoid_parametrisation(ELLIPSOID_3)
    thm312 = area_variation_ratios(ell3, ell3_normal, _wave, *hypersphere_quadrature(3, nodes=14), 3)
    V3, S3, grad3 = _freudenthal_sphere()
    area3 = float(vertex_areas(V3, S3, area="barycentric").sum())
    euler_identity = float(np.einsum("ij,ij->", grad3, V3))
    results = dict(
        thm312_ellipsoid3_minus_dA_over_n_int_lambda_H=round_sig(thm312[1], 6),
        thm312_homogeneity_holds=bool(abs(euler_identity - 3 * area3) < 1e-9 * area3),
    )
    text = (
        f"3-ellipsoid (1, 1.25, 1.5, 1.75), $\\lambda = 1 + \\tfrac12\\cos\\psi_1$: "
        f"$-\\delta A/(3\\int\\lambda H\\,dA)$ = {thm312[1]:.6f}.  The discrete form for the radial variation "
        f"$p \\mapsto (1 + t)p$ "
        f"of a triangulated 3-sphere, $\\sum_p\\langle\\nabla_p\\,\\mathrm{{area}}, p\\rangle/(3\\cdot"
        f"\\mathrm{{area}})$ = {euler_identity / (3 * area3):.9f}, "
        f"is Euler's identity for a function homogeneous of degree 3."
    )
    return Section(texts=(text,), results=results)


def _fit(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.sum(a * b) / np.sum(b * b))


def mean_curvature_gradient_section() -> Section:
    """Eq. (3.16), Theorem 3.16, Proposition 3.17, eq. (3.18) and Example 3.20 against finite differences.

    Thesis: eqs. (3.16)–(3.18), Theorem 3.16, Proposition 3.17 and Example 3.20.

    Returns
    -------
    Section
        One text, five results.

    Examples
    --------
    >>> sec = mean_curvature_gradient_section()
    >>> sec.results["eq316_fd_over_gradient_sum"], sec.results["eq318_coefficient"]
    (1.0, 1.0)
    """
    V3, S3, grad3 = _freudenthal_sphere()
    velocity = np.random.default_rng(10).normal(size=V3.shape)
    dt = 1e-6
    chain_fd = (
        float(simplex_hyperareas(V3 + dt * velocity, S3).sum())
        - float(simplex_hyperareas(V3 - dt * velocity, S3).sum())
    ) / (2 * dt)
    chain_sum = float(np.einsum("ij,ij->", velocity, grad3))
    jacobi = max(ct.jacobi_formula_residual(s, seed=s) for s in (2, 3, 5, 8))
    prop317 = max(ct.proposition_3_17_residual(n, seed=n) for n in range(2, 7))
    hull_pts, hull_faces = sphere_hull(n_dims=3, n_points=500, radius=2.0, seed=1)
    fd_hull = ct.mesh_area_gradient_fd(hull_pts, hull_faces)
    cot318 = _fit(fd_hull, ct.cotangent_formula_gradient(hull_pts, hull_faces))
    ex320 = _fit(fd_hull, ct.example_3_20_gradient(hull_pts, hull_faces))
    results = dict(
        eq316_fd_over_gradient_sum=round_sig(chain_fd / chain_sum, 6),
        thm316_jacobi_max_rel_err=rounded_error(jacobi, 6)[0],
        prop317_max_rel_err=rounded_error(prop317, 12)[0],
        eq318_coefficient=round_sig(cot318, 6),
        ex320_coefficient=round_sig(ex320, 6),
    )
    text = (
        f"Eq. (3.16) on a triangulated 3-sphere: finite difference over $\\sum_p\\langle v_p, "
        f"\\nabla_p\\,\\mathrm{{area}}"
        f"\\rangle$ = {chain_fd / chain_sum:.6f}.  Theorem 3.16: largest relative error {rounded_error(jacobi, 6)[1]} "
        f"(sizes 2, 3, 5, 8).  Proposition 3.17: largest relative difference {rounded_error(prop317, 12)[1]} "
        f"($n$ = 2 … 6).  "
        f"Coefficient of eq. (3.18) against the finite-difference gradient on the hull: {cot318:.6f}; "
        f"of Example 3.20: {ex320:.6f}."
    )
    return Section(texts=(text,), results=results)


def theorem_3_18_section(*, dims: Sequence[int] = (2, 3, 4, 5, 6)) -> Section:
    """Theorem 3.18 as printed and Corollary 3.19's coefficient against finite differences, and the proof's Gram matrix.

    Thesis: Theorem 3.18 and Corollary 3.19 (the gradient of a simplex's hyperarea).

    Parameters
    ----------
    dims : sequence of int
        The simplices' dimensions n (200 random simplices each).

    Returns
    -------
    Section
        One table, the coefficients per n and the Gram-matrix fractions.

    Raises
    ------
    ValueError
        If ``dims`` is empty or holds a dimension below 2.

    Examples
    --------
    >>> sec = theorem_3_18_section(dims=(2,))
    >>> sec.results["cor319_coefficient_times_nfact_n2"], sec.results["thm318_proof_gram_equal_fraction"]
    (1.0, 1.0)
    """
    dims = _dims(dims, "dims", minimum=2)
    thm318, cor319 = {}, {}
    for n in dims:
        simplices = random_simplices(n, 200, seed=n)
        thm318[n] = _fit(hyperarea_gradient_fd(simplices), ct.theorem_3_18_printed_gradient(simplices))
        cor319[n] = corollary_3_19_coefficient(n, 200, seed=n)
    gram_x = random_simplices(3, 200, seed=11)[:, 1:] - random_simplices(3, 200, seed=11)[:, :1]  # x_i = p_i − q, n = 3
    wedge_sq = np.sum(ct.wedge_coordinates(gram_x) ** 2, axis=1)
    printed_equal = float(np.mean(np.isclose(ct.printed_gram_determinant(gram_x), wedge_sq, rtol=1e-9)))
    gram_equal = float(
        np.mean(np.isclose(np.linalg.det(np.einsum("mka,mla->mkl", gram_x, gram_x)), wedge_sq, rtol=1e-9))
    )
    parallelotope_dim = int(np.min(np.linalg.matrix_rank(gram_x)))
    residual_small = bool(max(res for _, res in cor319.values()) < 1e-5)
    results = {f"thm318_coefficient_n{n}": round_sig(c, 6) for n, c in thm318.items()}
    results |= {f"cor319_coefficient_times_nfact_n{n}": round_sig(c * factorial(n), 6) for n, (c, _) in cor319.items()}
    results |= dict(
        cor319_residual_below_1e_5=residual_small,
        thm318_proof_printed_gram_equal_fraction=printed_equal,
        thm318_proof_gram_equal_fraction=gram_equal,
        thm318_proof_parallelotope_dimension_n3=parallelotope_dim,
    )
    text = (
        "| $n$ | Theorem 3.18 as printed: $c$ | "
        "Corollary 3.19: $c\\cdot n!$ | $c\\cdot n(n-1)$ | thesis: $c\\cdot n!$ |\n"
        "|---:|---:|---:|---:|---:|\n"
        + "\n".join(
            f"| {n} | {thm318[n]:.6f} | {c * factorial(n):.6f} | {c * n * (n - 1):.6f} | 1 |"
            for n, (c, _) in cor319.items()
        )
        + f"\n\nEvery fit's relative residual is below $10^{{-5}}$: {residual_small}.  "
        f"Of 200 random triples $x_1, x_2, x_3$ in $\\mathbb{{R}}^4$ the printed Gram matrix has determinant "
        f"$\\|x_1\\wedge x_2\\wedge x_3\\|^2$ for {printed_equal:.0%}, "
        f"the Gram matrix with $\\langle x_1, x_1\\rangle$ "
        f"for {gram_equal:.0%}; the vectors span a parallelotope of dimension {parallelotope_dim}."
    )
    return Section(texts=(text,), results=results)


def _height_ratio(n: int) -> float:
    p_h = random_simplices(n, 50, seed=20 + n)
    x_h = p_h[:, 1:] - p_h[:, :1]
    wedge_h = np.sqrt(np.sum(ct.wedge_coordinates(x_h[:, 1:]) ** 2, axis=1))  # omit x_1 (i = 1)
    base = p_h[:, 2:]  # the p's other than p_1
    k_b = base.shape[1]
    A_G = (
        simplex_hyperareas(base.reshape(-1, n + 1), np.arange(len(p_h) * k_b).reshape(len(p_h), k_b))
        if k_b > 1
        else np.ones(len(p_h))
    )  # the hyperarea of a point is 1
    d_h = p_h[:, 0] - base[:, 0]
    E_h = base[:, 1:] - base[:, :1]
    foot = (
        np.array([E_h[m].T @ np.linalg.lstsq(E_h[m].T, d_h[m], rcond=None)[0] for m in range(len(p_h))])
        if k_b > 1
        else 0.0
    )
    true_h = np.linalg.norm(d_h - foot, axis=1)
    return float(np.median(wedge_h / (factorial(n - 1) * A_G) / true_h))


def corollary_height_section(*, dims: Sequence[int] = (2, 3, 4, 5)) -> Section:
    """The height printed in the derivation of Corollary 3.19 over the true height of the simplex.

    Thesis: Corollary 3.19 (the area written A_G h sin θ / n).

    Parameters
    ----------
    dims : sequence of int
        The dimensions n (50 random simplices each).

    Returns
    -------
    Section
        A table and one median ratio per n.

    Raises
    ------
    ValueError
        If ``dims`` is empty or holds a dimension below 2.

    Examples
    --------
    >>> corollary_height_section(dims=(3,)).results
    {'cor319_printed_height_over_true_n3': 0.5}
    """
    height_ratio = {n: _height_ratio(n) for n in _dims(dims, "dims", minimum=2)}
    results = {f"cor319_printed_height_over_true_n{n}": round_sig(q, 6) for n, q in height_ratio.items()}
    text = "| $n$ | printed $h$ / true $h$ | $1/(n-1)$ |\n|---:|---:|---:|\n" + "\n".join(
        f"| {n} | {q:.6f} | {1 / (n - 1):.6f} |" for n, q in height_ratio.items()
    )
    return Section(texts=(text,), results=results)


def vector_norm_section(points: np.ndarray, simplices: np.ndarray, *, H: float = 0.5) -> Section:
    """The norm of the discrete mean curvature vector over n|H| and over n A(p)|H| (end of §3.3.1).

    Thesis: §3.3.1 ("the norm of the vector divided by n").

    Parameters
    ----------
    points, simplices : ndarray
        A triangulated sphere in ℝ³.
    H : float
        Its exact mean curvature (1/radius).

    Returns
    -------
    Section
        One text, two results.

    Raises
    ------
    ValueError
        If ``H`` is not positive.

    Examples
    --------
    >>> pts, simplices = sphere_hull(n_dims=3, n_points=400, radius=2.0, seed=0)
    >>> round(vector_norm_section(pts, simplices).results["sec331_norm_over_n_area_over_H"], 2)
    1.0
    """
    H = check_real(H, "H", positive=True)
    Hd = mean_curvature_vector(points, simplices)
    A_vor = vertex_areas(points, simplices, area="voronoi")
    norm_over_n = float(np.median(np.linalg.norm(Hd, axis=1) / 2 / H))
    norm_over_nA = float(np.median(np.linalg.norm(Hd, axis=1) / (2 * A_vor) / H))
    results = dict(
        sec331_norm_over_n_over_H=round_sig(norm_over_n, 4), sec331_norm_over_n_area_over_H=round_sig(norm_over_nA, 4)
    )
    text = (
        f"Median "
        f"of $\\|\\vec H_d\\|/(n|H|)$: {norm_over_n:.4f}; of $\\|\\vec H_d\\|/(n\\,A(p)\\,|H|)$: {norm_over_nA:.4f} "
        f"(the mean vertex area is {A_vor.mean():.4f})."
    )
    return Section(texts=(text,), results=results)


def chapter_of_voronoi_section(thesis: str) -> Section:
    """Voronoi regions: Thales' circle (Figure 3.2), circumcentres and the A_vor formula against exact regions.

    Thesis: §3.3.2, Figures 3.2 and 3.3 (the Voronoi area of Meyer et al.).

    Parameters
    ----------
    thesis : str
        The thesis's text, to find the chapter defining Voronoi regions.

    Returns
    -------
    Section
        One text, seven results.

    Examples
    --------
    >>> sec = chapter_of_voronoi_section("1\\nIntroduction\\nVoronoi Diagram and the Delaunay Complex")
    >>> sec.results["sec332_chapter_of_voronoi_regions"]
    1
    >>> sec.results["fig32_obtuse_inside_fraction"], sec.results["sec332_formula_exact_fraction_nonobtuse"]
    (1.0, 1.0)
    """
    voronoi_chapter = ct.chapter_of(thesis, "Voronoi Diagram and the Delaunay Complex")
    rng = np.random.default_rng(2)
    cloud2 = rng.uniform(-1.6, 1.6, (4000, 2))
    inside = np.einsum("ka,ka->k", cloud2, cloud2) < 1
    obtuse_at_x = thales_obtuse(cloud2, np.array([-1.0, 0.0]), np.array([1.0, 0.0]))
    triangles = rng.normal(size=(500, 3, 3))
    exact_regions = nearest_vertex_volumes(triangles)
    formula = vertex_areas(triangles.reshape(-1, 3), np.arange(1500).reshape(500, 3), area="voronoi").reshape(500, 3)
    ea, eb = triangles[:, [1, 2, 0]] - triangles, triangles[:, [2, 0, 1]] - triangles
    obtuse = (np.einsum("mka,mka->mk", ea, eb) < 0).any(axis=1)
    agree = np.all(np.abs(formula - exact_regions) <= 1e-9 * exact_regions.sum(axis=1, keepdims=True), axis=1)
    circ_inside = ct.circumcentre_inside(triangles)
    results = dict(
        sec332_chapter_of_voronoi_regions=voronoi_chapter,
        fig32_obtuse_inside_fraction=float(obtuse_at_x[inside].mean()),
        fig32_obtuse_outside_fraction=float(obtuse_at_x[~inside].mean()),
        sec332_circumcentre_inside_fraction_nonobtuse=float(circ_inside[~obtuse].mean()),
        sec332_circumcentre_inside_fraction_obtuse=float(circ_inside[obtuse].mean()),
        sec332_formula_exact_fraction_nonobtuse=float(agree[~obtuse].mean()),
        sec332_formula_exact_fraction_obtuse=float(agree[obtuse].mean()),
    )
    text = (
        f"Voronoi regions and the Delaunay complex are defined in Chapter {voronoi_chapter}.  Points inside the "
        f"circle with an obtuse angle at them: {obtuse_at_x[inside].mean():.0%}; "
        f"outside: {obtuse_at_x[~inside].mean():.0%}.  "
        f"Circumcentre inside the triangle: {circ_inside[~obtuse].mean():.0%} of the {int((~obtuse).sum())} non-obtuse "
        f"triangles, {circ_inside[obtuse].mean():.0%} of the {int(obtuse.sum())} obtuse ones.  "
        f"The $A_{{\\mathrm{{vor}}}}$ "
        f"formula equals the exact nearest-vertex area on {agree[~obtuse].mean():.0%} of the non-obtuse and "
        f"{agree[obtuse].mean():.0%} of the obtuse ones."
    )
    return Section(texts=(text,), results=results)


def voronoi_area_section(points: np.ndarray, simplices: np.ndarray) -> Section:
    """Eq. (3.19) on an ellipsoid's octant and the angle defect over the Voronoi area (eq. 3.20) on a sphere.

    Thesis: eqs. (3.19)–(3.20) (K ≈ (2π − Σθ_j)/A_vor).

    Parameters
    ----------
    points, simplices : ndarray
        A triangulated sphere of radius 2 in ℝ³.

    Returns
    -------
    Section
        One text, two results.

    Examples
    --------
    >>> pts, simplices = sphere_hull(n_dims=3, n_points=400, radius=2.0, seed=0)
    >>> voronoi_area_section(pts, simplices).results["eq319_ellipsoid_octant_integral_K_over_formula"]
    1.0
    """
    ell2, _ = ellipsoid_parametrisation(ELLIPSOID_2)
    ell_octant_K = total_gauss_kronecker_curvature(ell2, *octant_quadrature())
    defects = angle_defects(points, simplices)
    defect_over_area = float(np.median(defects / vertex_areas(points, simplices, area="voronoi")))
    results = dict(
        eq319_ellipsoid_octant_integral_K_over_formula=round_sig(ell_octant_K / (2 * np.pi - 3 * np.pi / 2), 6),
        eq320_defect_over_voronoi_area_sphere_r2=round_sig(defect_over_area, 4),
    )
    text = (
        f"Ellipsoid octant: $\\int K\\,dA$ = {ell_octant_K / np.pi:.6f}$\\pi$ against $2\\pi - 3\\pi/2 = 0.5\\pi$.  "
        f"Sphere of radius 2: median $(2\\pi - \\sum_j\\theta_j)/A_{{\\mathrm{{vor}}}}$ = {defect_over_area:.4f}."
    )
    return Section(texts=(text,), results=results)


def shape_operator_section(points: np.ndarray, simplices: np.ndarray, *, R: float = 10.0, r: float = 5.0) -> Section:
    """Mean curvature as a quadrature of normal curvatures (eq. 3.23), eq. (3.24), cotangent weights, the printed sum.

    Thesis: §3.3.4, Definition 3.3 and eqs. (3.23)–(3.24).

    Parameters
    ----------
    points, simplices : ndarray
        A triangulated sphere of radius 2 in ℝ³.
    R, r : float
        The torus's radii (normal curvatures at two points, and the 100 × 100 grid of the printed sum).

    Returns
    -------
    Section
        A table and text, eight results.

    Raises
    ------
    ValueError
        If ``R`` or ``r`` is not positive, or ``r >= R``.

    Examples
    --------
    >>> pts, simplices = sphere_hull(n_dims=3, n_points=400, radius=2.0, seed=0)
    >>> sec = shape_operator_section(pts, simplices)
    >>> sec.results["eq323_integral_over_k1_plus_k2"], sec.results["sec334_weights_sum_over_voronoi_area_max_err"]
    (3.14159, 0.0)
    """
    R, r = _radii(R, r)
    torus = _torus(R, r)
    kn = normal_curvature_circle(torus, np.array([[0.0, 0.0], [0.3, 1.2]]), nodes=64)
    S_at = torus_shape_operator(np.array([0.0, 0.3]), np.array([0.0, 1.2]), R=R, r=r)
    k_sum = np.trace(S_at, axis1=1, axis2=2)
    integral = 2 * np.pi * kn.mean(axis=1)  # the trapezoid rule, exact for this degree-2 trigonometric polynomial
    _, kappa = normal_curvatures(points, simplices)
    radius_formula = 1.0 / kappa  # eq. (3.24) as printed: ‖d‖² / (2 d·n)
    A_vor = vertex_areas(points, simplices, area="voronoi")
    quadrature = np.einsum("ia,ia->i", mean_curvature_vector(points, simplices), vertex_normals(points, simplices))
    quadrature /= 2 * A_vor  # = 1/(4A) Σ (cot α + cot β)(x_i − x_j)·n
    printed = printed_sum_gradient(*torus_grid(100, R=R, r=r))
    eig = np.linalg.eigvalsh(S_at)
    extremes_err = float(np.max(np.abs(np.column_stack([kn.min(axis=1), kn.max(axis=1)]) - eig)))
    edge_w = np.zeros(len(points))
    for k in range(3):  # w_ij = ⅛ cot γ ‖x_i − x_j‖² for the edge opposite the angle γ, to both ends
        c_, a_, b_ = simplices[:, k], simplices[:, (k + 1) % 3], simplices[:, (k + 2) % 3]
        da, db = points[a_] - points[c_], points[b_] - points[c_]
        cot = np.einsum("ma,ma->m", da, db) / np.linalg.norm(np.cross(da, db), axis=1)
        wgt = cot * np.einsum("ma,ma->m", points[a_] - points[b_], points[a_] - points[b_]) / 8
        np.add.at(edge_w, a_, wgt)
        np.add.at(edge_w, b_, wgt)
    results = dict(
        eq323_integral_over_k1_plus_k2=round_sig(float(np.mean(integral / k_sum)), 6),
        def33_max_abs_normal_curvature_torus_00=round_sig(float(np.abs(kn[0]).max()), 6),
        def33_extremes_minus_eigenvalues_max_err=rounded_error(extremes_err, 6)[0],
        eq324_formula_on_sphere_r2=round_sig(float(np.median(radius_formula)), 8),
        sec334_quadrature_on_sphere_r2=round_sig(float(np.median(quadrature)), 4),
        sec334_weights_sum_over_voronoi_area_max_err=rounded_error(np.max(np.abs(edge_w / A_vor - 1)), 12)[0],
        sec334_printed_sum_min_gradient=round_sig(float(np.nanmin(printed)), 6),
        sec334_printed_sum_has_minimiser=bool(np.nanmin(printed) < 1e-9),
    )
    rows = [
        f"| $({u0}, {v0})$ | {row.min():.6f} | {row.max():.6f} | {k1:.6f}, {k2:.6f} | "
        f"{2 * np.pi * row.mean() / (k1 + k2) / np.pi:.6f}$\\pi$ |"
        for (u0, v0), row, (k1, k2) in zip([(0.0, 0.0), (0.3, 1.2)], kn, eig)
    ]
    text = (
        "| $(u, v)$ | $\\min\\kappa_n$ | $\\max\\kappa_n$ | "
        "eigenvalues of $S$ | $\\int\\kappa_n\\,d\\theta/(\\kappa_1 + "
        "\\kappa_2)$ |\n|---|---:|---:|---:|---:|\n"
        + "\n".join(rows)
        + f"\n\nEq. (3.24) as printed on the sphere of radius 2: median {np.median(radius_formula):.6f}, from "
        f"{radius_formula.min():.6f} to {radius_formula.max():.6f} (the radius; the curvature is 0.5).  "
        f"$\\frac{{1}}{{4A}}\\sum(\\cot\\alpha + \\cot\\beta)(x_i - x_j)\\cdot\\mathbf{{n}}$ there: median "
        f"{np.median(quadrature):.4f} ($H = 0.5$, $K = 0.25$).  "
        f"Gradient of the printed sum over $\\deg(i)$, least over "
        f"the 10000 vertices of the torus grid: {np.nanmin(printed):.4f} ($\\geq 1/\\sqrt2$)."
    )
    return Section(texts=(text,), results=results)


_TC_G2 = (
    "crust_grid_max_rel_err_H_voronoi",
    "crust_grid_max_rel_err_H_barycentric",
    "crust_grid_median_rel_err_H_barycentric",
    "fixed_grid_max_rel_err_H_voronoi",
    "fixed_grid_max_rel_err_H_barycentric",
    "crust_grid_max_rel_err_K_voronoi",
    "random_100000_median_rel_err_H",
    "random_1000_kappa_lsq_over_hk",
    "random_100000_kappa_lsq_over_hk",
    "fixed_grid_kappa_lsq_over_hk",
    "crust_grid_median_rel_err_H_voronoi",
)
_TC_INT = (
    "crust_grid_n_boundary_vertices",
    "crust_grid_valence_min",
    "crust_grid_valence_max",
    "random_100_n_estimated",
)
_HS_4F = (
    "sphere_grid_H_min",
    "sphere_grid_H_max",
    "sphere_grid_exact_area_share",
    "sphere_grid_H_median_share_quarter",
    "sphere_grid_H_median_share_five_eighths",
)
_HS_2G = (
    "sphere_freudenthal_max_rel_err_away_from_poles",
    "sphere_freudenthal_max_rel_err",
    "sphere_freudenthal_median_rel_err",
    "catenoid_grid_H_min",
    "catenoid_grid_H_max",
    "catenoid_freudenthal_H_max",
    "cloud_H_median",
)


def _require_keys(results: Mapping[str, float], keys: Sequence[str], experiment: str) -> None:
    missing = [k for k in keys if k not in results]
    if missing:
        raise ValueError(f"the results of {experiment!r} lack {missing}")


def torus_experiment_glue(torus_curvature: Mapping[str, float]) -> Section:
    """The stored results of the experiment ``torus-curvature`` that the chapter's prose quotes, formatted.

    Thesis: §3.4.1 (Figures 3.4–3.11).

    Errors are given to 2 significant digits (CONVENTIONS.md); also the gain in z of the
    outer/inner ratio of Figure 3.10 from 100 to 1000 and to 100,000 points.

    Parameters
    ----------
    torus_curvature : mapping
        The experiment's ``results.json``.

    Returns
    -------
    Section
        ``glued`` (name → text, ``tc_*``) and two results.

    Raises
    ------
    ValueError
        If a result the prose quotes is missing.

    Examples
    --------
    >>> from thesis_lib.lab.results import load
    >>> sec = torus_experiment_glue(load("torus-curvature"))
    >>> sec.glued["tc_crust_grid_valence_min"], sorted(sec.results)
    ('4', ['fig310_z_gain_100000_over_1000', 'fig310_z_gain_1000_over_100'])
    """
    tc = torus_curvature
    ratio_keys = [f"random_{n}_outer_inner_{k}" for n in (100, 1000, 100000)
                  for k in ("ratio", "ratio_exact", "ratio_se", "ratio_est_se", "z")]
    _require_keys(tc, [*_TC_G2, *_TC_INT, *ratio_keys, "crust_grid_fixed_diagonal_fraction", "exact_outer_inner_ratio",
                       "random_100000_over_grid_median_rel_err_H"], "torus-curvature")
    glued = {f"tc_{k}": format(tc[k], ".2g") for k in _TC_G2}
    glued["tc_crust_grid_fixed_diagonal_fraction"] = format(100 * tc["crust_grid_fixed_diagonal_fraction"], ".0f")
    glued |= {f"tc_{k}": format(tc[k], "d") for k in _TC_INT}
    for n in (100, 1000, 100000):
        glued[f"tc_ratio_{n}"] = format(tc[f"random_{n}_outer_inner_ratio"], ".2f")
        glued[f"tc_ratio_exact_{n}"] = format(tc[f"random_{n}_outer_inner_ratio_exact"], ".2f")
        glued[f"tc_ratio_se_{n}"] = format(tc[f"random_{n}_outer_inner_ratio_se"], ".2g")
        glued[f"tc_ratio_est_se_{n}"] = format(tc[f"random_{n}_outer_inner_ratio_est_se"], ".2g")
        glued[f"tc_z_{n}"] = format(tc[f"random_{n}_outer_inner_z"], ".3g")
    glued["tc_exact_ratio"] = format(tc["exact_outer_inner_ratio"], ".2f")
    glued["tc_random_over_grid"] = format(tc["random_100000_over_grid_median_rel_err_H"], ".3g")
    z = {n: tc[f"random_{n}_outer_inner_z"] for n in (100, 1000, 100000)}
    results = dict(
        fig310_z_gain_1000_over_100=round_sig(z[1000] - z[100], 3),
        fig310_z_gain_100000_over_1000=round_sig(z[100000] - z[1000], 3),
    )
    return Section(results=results, glued=glued)


def hypersurface_experiment_glue(hypersurfaces: Mapping[str, float]) -> Section:
    """The stored results of the experiment ``hypersurfaces`` that the chapter's prose quotes, formatted.

    Thesis: §3.4.2–§3.4.3 (Figures 3.12–3.14).

    Parameters
    ----------
    hypersurfaces : mapping
        The experiment's ``results.json``.

    Returns
    -------
    Section
        ``glued`` (name → text, ``hs_*``; errors to 2 significant digits).

    Raises
    ------
    ValueError
        If a result the prose quotes is missing.

    Examples
    --------
    >>> sec = hypersurface_experiment_glue({k: 0.123456 for k in _HS_4F + _HS_2G})
    >>> sec.glued["hs_sphere_grid_H_min"], sec.glued["hs_cloud_H_median"]
    ('0.1235', '0.12')
    """
    hs = hypersurfaces
    _require_keys(hs, [*_HS_4F, *_HS_2G], "hypersurfaces")
    glued = {f"hs_{k}": format(hs[k], ".4f") for k in _HS_4F}
    glued |= {f"hs_{k}": format(hs[k], ".2g") for k in _HS_2G}
    return Section(glued=glued)


def sphere_region_section() -> Section:
    """The 3-sphere's mean curvature from its parametrisation, and the region of a corner simplex nearest to its corner.

    Thesis: §3.4.2 (Figure 3.12; "equals 1/12, which is half of the total volume").

    Returns
    -------
    Section
        One text, three results and the corner's volume in 48ths (glued ``corner_volume_48``).

    Examples
    --------
    >>> sec = sphere_region_section()
    >>> sec.results["sec342_corner_region_share"], sec.glued["corner_volume_48"]
    (0.625, '5')
    """
    w_s3 = np.random.default_rng(12).uniform([0.1, 0.1, 0.0], [np.pi - 0.1, np.pi - 0.1, 2 * np.pi], (200, 3))
    H_s3 = np.trace(parametric_shape_operator(_sphere2, w_s3), axis1=1, axis2=2) / 3
    corner = nearest_vertex_volumes(np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]], dtype=float))[0]
    results = dict(
        sec342_sphere_H_disagreements=int(np.sum(np.abs(np.abs(H_s3) - 0.5) > 1e-6)),
        sec342_corner_region_volume=round_sig(corner[0], 10),
        sec342_corner_region_share=round_sig(corner[0] / corner.sum(), 10),
    )
    text = (
        f"Points (of 200) where $|\\operatorname{{tr}}S/3|$ differs from $1/2$ by more than $10^{{-6}}$: "
        f"{int(np.sum(np.abs(np.abs(H_s3) - 0.5) > 1e-6))}.  Region nearest to the corner: {corner[0]:.7f} = "
        f"{corner[0] * 48:.4f}/48, a share {corner[0] / corner.sum():.4f} "
        f"of the volume $1/6$ ($1/12$ would be 0.0833333)."
    )
    return Section(texts=(text,), results=results, glued={"corner_volume_48": format(corner[0] * 48, ".0f")})


def catenoid_section(*, dims: Sequence[int] = (2, 3), seed: int = 3) -> Section:
    """The n-catenoid is minimal: its shape operator by differences at 200 random points.

    Thesis: §3.4.3 (N_u = X_u/cosh² v, N_v = −X_v/cosh² v, so H = 0).

    Parameters
    ----------
    dims : sequence of int
        The catenoids' dimensions n.
    seed : int
        Seed of the random points (one generator for all n, in turn).

    Returns
    -------
    Section
        A table and two counts per n.

    Raises
    ------
    ValueError
        If ``dims`` is empty or holds a dimension below 2.

    Examples
    --------
    >>> catenoid_section(dims=(2,)).results
    {'catenoid_n2_H_nonzero': 0, 'catenoid_n2_kappa_disagreements': 0}
    """
    dims = _dims(dims, "dims", minimum=2)
    cat_rng = np.random.default_rng(check_seed(seed))
    minimal = {}
    for n in dims:
        w_cat = np.column_stack([cat_rng.uniform(-np.pi, np.pi, 200), cat_rng.uniform(-1, 1, (200, n - 1))])
        S_cat = parametric_shape_operator(catenoid_point, w_cat)
        kappa_cat = np.sort(np.linalg.eigvals(S_cat).real, axis=1)
        exact_cat = np.sort(catenoid_principal_curvatures(w_cat), axis=1)
        minimal[n] = (
            int(np.sum(np.abs(np.trace(S_cat, axis1=1, axis2=2)) > 1e-6)),
            int(np.sum(np.abs(kappa_cat - exact_cat).max(axis=1) > 1e-6)),
        )
    results = {f"catenoid_n{n}_H_nonzero": h for n, (h, _) in minimal.items()}
    results |= {f"catenoid_n{n}_kappa_disagreements": k for n, (_, k) in minimal.items()}
    text = (
        "| $n$ | points with $\\lvert\\operatorname{tr}S\\rvert > 10^{-6}$ | principal curvatures off "
        "$(\\pm 1/\\cosh^2 v, 0, \\dots)$ by more than $10^{-6}$ |\n|---:|---:|---:|\n"
        + "\n".join(f"| {n} | {h} | {k} |" for n, (h, k) in minimal.items())
    )
    return Section(texts=(text,), results=results)

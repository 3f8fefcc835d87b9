"""The torus of §3.4.1 (R = 10, r = 5): chosen points and random samples, their triangulations and the
errors of the curvature estimates against the exact values (experiment ``torus-curvature``,
Figures 3.4–3.11, and §3.3.4's two routes to the principal curvatures).

Each analysis returns a record whose ``results()`` are the flat numbers the experiment stores and
whose ``describe()``/``table()``/``row()`` is the text it shows.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .._validate import check_int, check_real
from ..curvature import AREA_KINDS, angle_defects, boundary_vertices, gaussian_curvature, mean_curvature
from ..curvature import principal_curvatures as least_squares_principal_curvatures
from ..curvature.checks import principal_curvatures_from_mean_and_gaussian
from ..lab.results import round_sig
from ..meshes.sampling import sample_torus
from ..meshes.topology import euler_characteristic, is_closed_pseudomanifold
from ..reconstruction.reconstruct import reconstruct_surface
from ..surfaces import torus_gaussian_curvature, torus_mean_curvature, torus_principal_curvatures_at

__all__ = [
    "relative_error",
    "CrustGridSummary",
    "GridErrors",
    "PrincipalCurvatureErrors",
    "RandomTorusRun",
    "crust_grid_summary",
    "grid_curvature_errors",
    "principal_curvature_errors",
    "random_runs_table",
    "random_torus_run",
]


def relative_error(estimate: npt.ArrayLike, exact: npt.ArrayLike, *, zero_tol: float = 1e-3) -> np.ndarray:
    """|estimate - exact| / |exact| (pass |H| for H, signed K for K), NaN where |exact| < zero_tol · max|exact|.

    The thesis plots |real - estimate| / real (Figure 3.5); the real value vanishes on whole circles
    of the torus (H at cos v = -R/(2r), K at v = ±π/2), where the ratio is undefined: those points
    are left out (NaN) and should be reported separately as absolute errors.
    Thesis: §3.4.1, Figures 3.5 and 3.7.

    Parameters
    ----------
    estimate : array_like
        The estimated values.
    exact : array_like
        The exact values, same shape, finite.
    zero_tol : float, default 1e-3
        Fraction of max|exact| in [0, 1) at or below which |exact| counts as zero.

    Returns
    -------
    ndarray of float64
        The relative error, shape of ``exact``; NaN where |exact| <= zero_tol · max|exact|.

    Raises
    ------
    ValueError
        If the shapes differ, ``exact`` holds NaN or infinite values, or ``zero_tol`` is outside
        [0, 1).

    Examples
    --------
    NaN where the exact value is (near) zero:

    >>> import numpy as np
    >>> np.round(relative_error([0.51, 0.0, 2.2], [0.5, 0.0, 2.0]), 6).tolist()
    [0.02, nan, 0.1]
    """
    est = np.asarray(estimate, dtype=np.float64)
    ex = np.asarray(exact, dtype=np.float64)
    if est.shape != ex.shape:
        raise ValueError(f"estimate {est.shape} and exact {ex.shape} differ in shape")
    if not np.all(np.isfinite(ex)):
        raise ValueError("exact values contain NaN or infinite values")
    zero_tol = float(zero_tol)
    if not 0 <= zero_tol < 1:
        raise ValueError(f"zero_tol must lie in [0, 1), got {zero_tol!r}")
    scale = np.max(np.abs(ex)) if ex.size else 0.0
    out = np.full(ex.shape, np.nan)
    ok = np.abs(ex) > zero_tol * scale
    out[ok] = np.abs(est[ok] - ex[ok]) / np.abs(ex[ok])
    return out



def _check_mapping(meshes: Mapping, name: str) -> None:
    if not isinstance(meshes, Mapping) or not meshes:
        raise ValueError(f"{name} must be a non-empty mapping of names to triangulations, got {meshes!r}")


@dataclass(frozen=True, kw_only=True)
class CrustGridSummary:
    """The Crust of the chosen points beside the fixed-diagonal grid of the same points.

    Thesis: §3.4.1, Figure 3.4 (the Crust of the chosen points).

    Attributes: ``n_vertices``, ``n_faces``, ``euler`` (χ), ``closed`` (a closed pseudo-manifold),
    ``n_boundary_vertices``, ``fixed_diagonal_fraction`` (the share of the grid's triangles that the
    Crust also has), ``valence_min`` and ``valence_max`` (triangles at a vertex of the Crust).
    """

    n_vertices: int
    n_faces: int
    euler: int
    closed: bool
    n_boundary_vertices: int
    fixed_diagonal_fraction: float
    valence_min: int
    valence_max: int

    def results(self) -> dict[str, float]:
        """The stored numbers, named ``crust_grid_*``.

        Returns
        -------
        dict of str to number
            Faces, χ, closedness, boundary vertices, the fixed-diagonal fraction, least and largest valence.

        Examples
        --------
        >>> s = CrustGridSummary(n_vertices=4, n_faces=4, euler=2, closed=True, n_boundary_vertices=0,
        ...                      fixed_diagonal_fraction=0.5, valence_min=3, valence_max=3)
        >>> s.results()["crust_grid_fixed_diagonal_fraction"]
        0.5
        """
        return dict(
            crust_grid_n_faces=self.n_faces,
            crust_grid_euler=self.euler,
            crust_grid_closed=self.closed,
            crust_grid_n_boundary_vertices=self.n_boundary_vertices,
            crust_grid_fixed_diagonal_fraction=self.fixed_diagonal_fraction,
            crust_grid_valence_min=self.valence_min,
            crust_grid_valence_max=self.valence_max,
        )

    def describe(self) -> str:
        """One Markdown sentence for the reader.

        Returns
        -------
        str
            The counts, χ, closedness and the valences beside the fixed grid's 6.

        Examples
        --------
        >>> s = CrustGridSummary(n_vertices=4, n_faces=4, euler=2, closed=True, n_boundary_vertices=0,
        ...                      fixed_diagonal_fraction=0.5, valence_min=3, valence_max=3)
        >>> s.describe().split(";")[0]
        'Crust of the 4 chosen points: 4 faces, $\\\\chi$ = 2, closed: True, 0 boundary vertices'
        """
        return (f"Crust of the {self.n_vertices} chosen points: {self.n_faces} faces, $\\chi$ = "
                f"{self.euler}, closed: {self.closed}, "
                f"{self.n_boundary_vertices} boundary vertices; "
                f"{self.fixed_diagonal_fraction:.0%} of its faces use the fixed grid's diagonal; valence "
                f"{self.valence_min}–{self.valence_max} (fixed grid: 6).")


def crust_grid_summary(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *,
                       grid_simplices: npt.ArrayLike) -> CrustGridSummary:
    """Compare a triangulation of the chosen points (the Crust) with the fixed-diagonal grid.

    Thesis: §3.4.1, "Torus 1: chosen points" (triangulated by the Crust [ABK98], Figure 3.4).

    Every grid quad of the torus is an isosceles trapezoid, four co-circular points, so the Crust
    keeps whichever diagonal the Delaunay triangulation happens to contain; how often it is the fixed
    grid's is ``fixed_diagonal_fraction``.

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
        The chosen points.
    simplices : array_like of int, shape (m, 3)
        Their Crust (or any triangulation of them).
    grid_simplices : array_like of int, shape (k, 3)
        The fixed-diagonal grid (:func:`~thesis_lib.meshes.torus_chosen_points`).

    Returns
    -------
    CrustGridSummary
        Counts, topology, the shared diagonals and the valences.

    Raises
    ------
    ValueError
        If ``vertices`` is not ``(nv, 3)``, or a triangulation is not ``(m, 3)`` indices into it.

    Examples
    --------
    >>> from thesis_lib.meshes import torus_chosen_points
    >>> V, grid, uv = torus_chosen_points(step=2 * np.pi / 8)
    >>> s = crust_grid_summary(V, grid, grid_simplices=grid)
    >>> s.euler, s.closed, s.fixed_diagonal_fraction, s.valence_min, s.valence_max
    (0, True, 1.0, 6, 6)
    """
    points = np.asarray(vertices, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError(f"vertices must be (nv, 3), got shape {points.shape}")
    faces = np.asarray(simplices)
    grid = np.asarray(grid_simplices)
    for name, tri in (("simplices", faces), ("grid_simplices", grid)):
        if tri.ndim != 2 or tri.shape[1] != 3 or len(tri) == 0 or not np.issubdtype(tri.dtype, np.integer):
            raise ValueError(f"{name} must be a non-empty (m, 3) array of vertex indices, got shape {tri.shape}")
        if tri.min() < 0 or tri.max() >= len(points):
            raise ValueError(f"{name} index vertices outside 0..{len(points) - 1}")
    same_diagonal = {tuple(sorted(f)) for f in grid.tolist()} & {tuple(sorted(f)) for f in faces.tolist()}
    valence = np.bincount(faces.ravel(), minlength=len(points))
    return CrustGridSummary(
        n_vertices=len(points), n_faces=len(faces), euler=euler_characteristic(faces),
        closed=is_closed_pseudomanifold(faces),
        n_boundary_vertices=int(boundary_vertices(faces, len(points)).sum()),
        fixed_diagonal_fraction=len(same_diagonal) / len(grid),
        valence_min=int(valence.min()), valence_max=int(valence.max()),
    )


@dataclass(frozen=True, kw_only=True)
class GridErrors:
    """Relative errors of |H| and K at the chosen points, per triangulation and vertex area.

    Thesis: §3.4.1, Figures 3.5 and 3.7.

    ``H[name, area]`` and ``K[name, area]`` are arrays over the vertices (NaN where the exact value is
    zero, see :func:`~thesis_lib.chapters.torus_study.relative_error`); ``triangulations`` and ``areas``
    keep the order they were computed in.
    """

    H: dict[tuple[str, str], np.ndarray]
    K: dict[tuple[str, str], np.ndarray]
    triangulations: tuple[str, ...]
    areas: tuple[str, ...]

    def results(self, *, area: str) -> dict[str, float]:
        """The stored numbers: ``<name>_grid_max_rel_err_H_<area>``, ``..._median_...``,
        ``..._max_rel_err_K_...`` (4 significant digits) for every case, and ``grid_n_zeros_H`` /
        ``grid_n_zeros_K``, the points left out, counted on the first triangulation with ``area``.

        Parameters
        ----------
        area : str
            The vertex area whose left-out points are counted.

        Returns
        -------
        dict of str to number
            The results by name.

        Raises
        ------
        ValueError
            If ``area`` is not one of ``areas``.

        Examples
        --------
        >>> e = GridErrors(H={("crust", "voronoi"): np.array([0.1, np.nan])},
        ...                K={("crust", "voronoi"): np.array([0.2, 0.3])}, triangulations=("crust",),
        ...                areas=("voronoi",))
        >>> e.results(area="voronoi")["grid_n_zeros_H"], e.results(area="voronoi")["crust_grid_max_rel_err_K_voronoi"]
        (1, 0.3)
        """
        if area not in self.areas:
            raise ValueError(f"area must be one of {self.areas}, got {area!r}")
        out: dict[str, float] = {}
        for name, kind in self.H:
            eH, eK = self.H[name, kind], self.K[name, kind]
            out.update({
                f"{name}_grid_max_rel_err_H_{kind}": round_sig(np.nanmax(eH), 4),
                f"{name}_grid_median_rel_err_H_{kind}": round_sig(np.nanmedian(eH), 4),
                f"{name}_grid_max_rel_err_K_{kind}": round_sig(np.nanmax(eK), 4),
            })
        first = self.triangulations[0]
        out.update(grid_n_zeros_H=int(np.isnan(self.H[first, area]).sum()),
                   grid_n_zeros_K=int(np.isnan(self.K[first, area]).sum()))
        return out

    def table(self) -> str:
        """The errors as a fixed-width text table: largest and median relative error of |H|, largest of K.

        Returns
        -------
        str
            A header and one line per (triangulation, area), no final newline.

        Examples
        --------
        >>> e = GridErrors(H={("crust", "voronoi"): np.array([0.1, 0.3])},
        ...                K={("crust", "voronoi"): np.array([0.2, 0.3])}, triangulations=("crust",),
        ...                areas=("voronoi",))
        >>> print(e.table().splitlines()[1])
        crust          voronoi                    0.3      0.2             0.3
        """
        lines = [f"{'triangulation':14s} {'area':12s} {'max rel. err |H|':>17s} {'median':>8s} {'max rel. err K':>15s}"]
        lines += [f"{name:14s} {kind:12s} {np.nanmax(eH):17.2g} {np.nanmedian(eH):8.2g} "
                  f"{np.nanmax(self.K[name, kind]):15.2g}" for (name, kind), eH in self.H.items()]
        return "\n".join(lines)


def grid_curvature_errors(vertices: npt.ArrayLike, triangulations: Mapping[str, npt.ArrayLike], uv: npt.ArrayLike, *,
                          R: float = 10.0, r: float = 5.0, method: str = "cot",
                          zero_tol: float = 1e-3) -> GridErrors:
    """|real − estimate| / real of |H| and of K at the chosen points, for every triangulation and vertex area.

    Thesis: §3.4.1, Figures 3.5 and 3.7 ("less than 4·10⁻³ at every point" for |H|).

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
        The chosen points.
    triangulations : mapping of str to array_like of int, shape (m, 3)
        Named triangulations of them (e.g. ``{"crust": ..., "fixed": ...}``), in the order of the table.
    uv : array_like, shape (nv, 2)
        The parameters (u, v) of the points.
    R, r : float, default 10 and 5
        The torus's radii.
    method : {"cot", "gram"}, default "cot"
        How :func:`~thesis_lib.curvature.mean_curvature` computes the mean curvature vector.
    zero_tol : float, default 1e-3
        Points with |exact| at most ``zero_tol`` times the largest are left out (NaN).

    Returns
    -------
    GridErrors
        The errors with every vertex area of ``thesis_lib.curvature.AREA_KINDS``.

    Raises
    ------
    ValueError
        If ``triangulations`` is empty, ``uv`` is not ``(nv, 2)``, or on an invalid mesh, radii or ``zero_tol``.

    Examples
    --------
    On the fixed grid of 40 × 40 chosen points the Voronoi estimate of |H| is good to 1 %:

    >>> from thesis_lib.meshes import torus_chosen_points
    >>> V, grid, uv = torus_chosen_points(step=2 * np.pi / 40)
    >>> e = grid_curvature_errors(V, {"fixed": grid}, uv)
    >>> bool(np.nanmax(e.H["fixed", "voronoi"]) < 0.01), e.areas
    (True, ('mixed', 'voronoi', 'barycentric'))
    """
    _check_mapping(triangulations, "triangulations")
    params = np.asarray(uv, dtype=np.float64)
    if params.ndim != 2 or params.shape != (len(np.asarray(vertices)), 2):
        raise ValueError(f"uv must be (nv, 2) parameters of the vertices, got shape {params.shape}")
    U, V = params[:, 0], params[:, 1]
    H_exact = np.abs(torus_mean_curvature(U, V, R=R, r=r))
    K_exact = torus_gaussian_curvature(U, V, R=R, r=r)
    err_H, err_K = {}, {}
    for name, faces in triangulations.items():
        for kind in AREA_KINDS:
            err_H[name, kind] = relative_error(mean_curvature(vertices, faces, area=kind, method=method), H_exact,
                                               zero_tol=zero_tol)
            err_K[name, kind] = relative_error(gaussian_curvature(vertices, faces, area=kind), K_exact,
                                               zero_tol=zero_tol)
    return GridErrors(H=err_H, K=err_K, triangulations=tuple(triangulations), areas=tuple(AREA_KINDS))


def _ratio_se(values: np.ndarray, outer: np.ndarray, inner: np.ndarray, ratio: float) -> float:
    """Delta method: the standard error of the ratio of the means of ``values`` over ``outer`` and ``inner``."""
    return ratio * np.sqrt(values[outer].var() / (outer.sum() * values[outer].mean() ** 2)
                           + values[inner].var() / (inner.sum() * values[inner].mean() ** 2))


@dataclass(frozen=True, kw_only=True)
class RandomTorusRun:
    """One random sample of the torus, its reconstruction and the estimated |H|.

    Thesis: §3.4.1, "Torus 2: random sampling" (Figures 3.8–3.11).

    ``points``, ``uv``, ``simplices`` and ``H`` (NaN on boundary vertices) are the mesh;
    ``median_error`` the median relative error of |H| over the vertices with an estimate;
    ``ratio`` the mean estimated |H| on the outer half (cos v > 0) over that on the inner half,
    ``ratio_se`` its standard error (delta method), ``exact_ratio`` and ``exact_ratio_se`` the same of
    the exact |H| at the same vertices; ``defects_over_2pi`` the sum of the angle defects over 2π
    (χ by Gauss–Bonnet, Theorem 3.8), None unless the reconstruction is closed; ``seconds`` the
    reconstruction's wall-clock time.
    """

    n: int
    points: np.ndarray
    uv: np.ndarray
    simplices: np.ndarray
    H: np.ndarray
    euler: int
    closed: bool
    n_estimated: int
    median_error: float
    ratio: float
    ratio_se: float
    exact_ratio: float
    exact_ratio_se: float
    defects_over_2pi: float | None
    seconds: float

    @property
    def z(self) -> float:
        """How clearly the outer half is more curved, as (ratio − 1) / its standard error.

        Returns
        -------
        float
            The z-score of the estimated ratio against 1.

        Examples
        --------
        >>> run = random_torus_run(1000, seed=1)
        >>> bool(run.z == (run.ratio - 1) / run.ratio_se and run.z > 3)
        True
        """
        return (self.ratio - 1) / self.ratio_se

    def results(self, *, grid_median_error: float) -> dict[str, float]:
        """The stored numbers, named ``random_<n>_*``.

        Parameters
        ----------
        grid_median_error : float
            The median relative error of |H| on the chosen points, for ``random_<n>_over_grid_median_rel_err_H``.

        Returns
        -------
        dict of str to number
            Faces, χ, closedness, estimates, the median error, the outer/inner ratios with their
            standard errors and z, the error over the grid's, and (closed only) the angle defects over 2π.

        Raises
        ------
        ValueError
            If ``grid_median_error`` is not a positive number.

        Examples
        --------
        >>> run = random_torus_run(1000, seed=1)
        >>> res = run.results(grid_median_error=run.median_error / 20)
        >>> res["random_1000_over_grid_median_rel_err_H"], float(res["random_1000_defects_over_2pi"])
        (20.0, 0.0)
        """
        grid_median_error = check_real(grid_median_error, "grid_median_error", positive=True)
        p = f"random_{self.n}"
        out = {
            f"{p}_n_faces": len(self.simplices),
            f"{p}_euler": self.euler,
            f"{p}_closed": self.closed,
            f"{p}_n_estimated": self.n_estimated,
            f"{p}_median_rel_err_H": round_sig(self.median_error, 4),
            f"{p}_outer_inner_ratio": round_sig(self.ratio, 4),
            f"{p}_outer_inner_ratio_exact": round_sig(self.exact_ratio, 4),
            f"{p}_outer_inner_ratio_se": round_sig(self.exact_ratio_se, 2),
            f"{p}_outer_inner_ratio_est_se": round_sig(self.ratio_se, 2),
            f"{p}_outer_inner_z": round_sig(self.z, 3),
            f"{p}_over_grid_median_rel_err_H": round_sig(self.median_error / grid_median_error, 3),
        }
        if self.defects_over_2pi is not None:
            out[f"{p}_defects_over_2pi"] = self.defects_over_2pi
        return out

    def row(self) -> str:
        """The run as a row of :func:`random_runs_table`.

        Returns
        -------
        str
            ``| points | χ | closed | estimated | median error | outer/inner ± se | z | exact ± se |``.

        Examples
        --------
        >>> random_torus_run(1000, seed=1).row()[:22]
        '| 1000 | 0 | True | 10'
        """
        return (f"| {self.n} | {self.euler} | {self.closed} | {self.n_estimated} | {self.median_error:.2g} | "
                f"{self.ratio:.2f} ± {self.ratio_se:.1g} | {self.z:.3g} | "
                f"{self.exact_ratio:.2f} ± {self.exact_ratio_se:.1g} |")


def random_torus_run(n_samples: int, *, R: float = 10.0, r: float = 5.0, seed: int = 0, algorithm: str = "crust",
                     theta: float = np.pi / 4, area: str = "voronoi", method: str = "cot",
                     zero_tol: float = 1e-3) -> RandomTorusRun:
    """Sample the torus uniformly by area, reconstruct it and estimate |H| at every sample.

    Thesis: §3.4.1, "Torus 2: random sampling" (rejection sampling, the Crust, Figures 3.8–3.11;
    "more curvature at points further away from the centroid").

    Parameters
    ----------
    n_samples : int
        Number of samples, at least 4.
    R, r : float, default 10 and 5
        The torus's radii.
    seed : int, default 0
        Seed of the samples.
    algorithm : {"crust", "ball-pivoting"}, default "crust"
        The reconstruction (:func:`~thesis_lib.reconstruction.reconstruct_surface`).
    theta : float, default π/4
        The Crust's normal-filter angle, in radians.
    area : {"voronoi", "mixed", "barycentric"}, default "voronoi"
        The vertex area of the estimate.
    method : {"cot", "gram"}, default "cot"
        How the mean curvature vector is computed.
    zero_tol : float, default 1e-3
        Vertices with |exact H| at most ``zero_tol`` times the largest are left out of the errors.

    Returns
    -------
    RandomTorusRun
        The mesh, its estimate and the statistics of the estimate.

    Raises
    ------
    ValueError
        If ``n_samples`` is below 4, or on bad radii, seed, reconstruction or area.

    Examples
    --------
    >>> run = random_torus_run(1000, seed=1)
    >>> run.closed, run.euler, bool(run.ratio > 1.5)
    (True, 0, True)
    """
    n_samples = check_int(n_samples, "n_samples", minimum=4)
    pts, uv = sample_torus(n_samples, R=R, r=r, seed=seed, return_uv=True)
    start = time.perf_counter()
    tri = reconstruct_surface(pts, algorithm=algorithm, theta=theta)
    seconds = time.perf_counter() - start
    h = mean_curvature(pts, tri, area=area, method=method)
    hx = np.abs(torus_mean_curvature(uv[:, 0], uv[:, 1], R=R, r=r))
    ok = np.isfinite(h)
    e = relative_error(h, hx, zero_tol=zero_tol)
    outer, inner = ok & (np.cos(uv[:, 1]) > 0), ok & (np.cos(uv[:, 1]) <= 0)
    ratio, exact_ratio = h[outer].mean() / h[inner].mean(), hx[outer].mean() / hx[inner].mean()
    closed = is_closed_pseudomanifold(tri)
    defects = round(angle_defects(pts, tri).sum() / (2 * np.pi), 6) + 0.0 if closed else None
    return RandomTorusRun(
        n=n_samples, points=pts, uv=uv, simplices=tri, H=h, euler=euler_characteristic(tri), closed=closed,
        n_estimated=int(ok.sum()), median_error=np.nanmedian(e[ok]), ratio=ratio,
        ratio_se=_ratio_se(h, outer, inner, ratio), exact_ratio=exact_ratio,
        exact_ratio_se=_ratio_se(hx, outer, inner, exact_ratio), defects_over_2pi=defects, seconds=seconds,
    )


def random_runs_table(runs: Sequence[RandomTorusRun]) -> str:
    """The random runs as a Markdown table, one row each (:meth:`RandomTorusRun.row`).

    Thesis: §3.4.1, Figures 3.8–3.10.

    Parameters
    ----------
    runs : sequence of RandomTorusRun
        The runs, in the order of the rows.

    Returns
    -------
    str
        The table: points, χ, closed, estimated vertices, median error, outer/inner ± se, z, exact ± se.

    Raises
    ------
    ValueError
        If ``runs`` is empty.

    Examples
    --------
    >>> print(random_runs_table([random_torus_run(200)]).splitlines()[0])
    | points | $\\chi$ | closed | estimated | median error | outer/inner | $z$ | exact |
    """
    if not runs:
        raise ValueError("runs must hold at least one RandomTorusRun")
    return ("| points | $\\chi$ | closed | estimated | median error | outer/inner | $z$ | exact |\n"
            "|---:|---:|---|---:|---:|---:|---:|---:|\n" + "\n".join(run.row() for run in runs))


@dataclass(frozen=True, kw_only=True)
class PrincipalCurvatureErrors:
    """Median errors of the principal curvatures by least squares and from H and K, per mesh.

    Thesis: §3.3.4 (the least-squares shape operator, "generally worse" than κ from H and K [MDSB02]).

    ``least_squares[name]`` and ``from_mean_and_gaussian[name]``: the median over the vertices of
    max(|κ₁ − κ₁ᵉˣ|, |κ₂ − κ₂ᵉˣ|) / max|κᵉˣ|.
    """

    least_squares: dict[str, float]
    from_mean_and_gaussian: dict[str, float]

    def results(self) -> dict[str, float]:
        """The stored numbers: ``<name>_kappa_median_err_lsq``, ``..._hk`` and ``..._lsq_over_hk`` (4 digits).

        Returns
        -------
        dict of str to number
            The results by name.

        Examples
        --------
        >>> PrincipalCurvatureErrors(least_squares={"m": 0.2}, from_mean_and_gaussian={"m": 0.1}).results()
        {'m_kappa_median_err_lsq': 0.2, 'm_kappa_median_err_hk': 0.1, 'm_kappa_lsq_over_hk': 2.0}
        """
        out: dict[str, float] = {}
        for name, e_ls in self.least_squares.items():
            e_hk = self.from_mean_and_gaussian[name]
            out.update({f"{name}_kappa_median_err_lsq": round_sig(e_ls, 4),
                        f"{name}_kappa_median_err_hk": round_sig(e_hk, 4),
                        f"{name}_kappa_lsq_over_hk": round_sig(e_ls / e_hk, 4)})
        return out

    def table(self) -> str:
        """The errors as a fixed-width text table with their ratio.

        Returns
        -------
        str
            A header and one line per mesh, no final newline.

        Examples
        --------
        >>> e = PrincipalCurvatureErrors(least_squares={"m": 0.2}, from_mean_and_gaussian={"m": 0.1})
        >>> print(e.table().splitlines()[1])
        m                         0.2           0.1   2.00
        """
        lines = [f"{'mesh':14s} {'least squares':>14s} {'from H and K':>13s} {'ratio':>6s}"]
        lines += [f"{name:14s} {e_ls:14.2g} {self.from_mean_and_gaussian[name]:13.2g} "
                  f"{e_ls / self.from_mean_and_gaussian[name]:6.2f}" for name, e_ls in self.least_squares.items()]
        return "\n".join(lines)


def principal_curvature_errors(meshes: Mapping[str, tuple[npt.ArrayLike, npt.ArrayLike]], *, R: float = 10.0,
                               r: float = 5.0, area: str = "voronoi") -> PrincipalCurvatureErrors:
    """The principal curvatures of torus meshes by §3.3.4's two routes, against the exact ones.

    Thesis: §3.3.4, "Estimating the Shape Operator" (least squares, or κ₁, κ₂ from H and K).

    Parameters
    ----------
    meshes : mapping of str to (vertices, simplices)
        Named triangle meshes of the torus (coherently oriented), in the order of the table.
    R, r : float, default 10 and 5
        The torus's radii.
    area : {"voronoi", "mixed", "barycentric"}, default "voronoi"
        The vertex area of H and K.

    Returns
    -------
    PrincipalCurvatureErrors
        The median errors of both routes per mesh.

    Raises
    ------
    ValueError
        If ``meshes`` is empty, or on an invalid mesh, radii or area.

    Examples
    --------
    >>> from thesis_lib.meshes import torus_chosen_points
    >>> V, grid, uv = torus_chosen_points(step=2 * np.pi / 40)
    >>> e = principal_curvature_errors({"grid": (V, grid)})
    >>> bool(e.least_squares["grid"] < 0.01 and e.from_mean_and_gaussian["grid"] < 0.01)
    True
    """
    _check_mapping(meshes, "meshes")
    e_ls, e_hk = {}, {}
    for name, (pts, tri) in meshes.items():
        exact = np.sort(-torus_principal_curvatures_at(pts, R=R, r=r), axis=1)  # signs of curvature.shape
        scale = np.abs(exact).max(axis=1)
        ls = least_squares_principal_curvatures(pts, tri)
        hk = principal_curvatures_from_mean_and_gaussian(pts, tri, area)
        e_ls[name] = np.nanmedian(np.abs(np.stack([ls.k1, ls.k2], 1) - exact).max(axis=1) / scale)
        e_hk[name] = np.nanmedian(np.abs(np.stack(hk, 1) - exact).max(axis=1) / scale)
    return PrincipalCurvatureErrors(least_squares=e_ls, from_mean_and_gaussian=e_hk)

"""Theorem 3.18 on Crust reconstructions of random samples of the 3-sphere and the 3-catenoid: the
3-D analogue of the thesis's Figures 3.8–3.11 (experiment ``hypersurface-crust``).

:func:`crust_curvature_errors` is one reconstruction and its errors; :func:`crust_run_results` and
:func:`describe_crust_run` are what the experiment stores and shows of it; :func:`crust_error_curve`
repeats it over sample counts and seeds.
"""

from __future__ import annotations

import textwrap
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.spatial import Delaunay

from .._validate import check_choice, check_int
from ..curvature import mean_curvature
from ..lab.results import round_sig
from ..meshes.sampling import sample_n_catenoid, sample_sphere
from ..reconstruction.crust_nd import crust_nd, manifold_vertices

__all__ = ["HYPERSURFACES", "sample_hypersurface", "crust_curvature_errors", "SPHERE_RADIUS", "crust_run_results",
           "describe_crust_run", "CrustErrorCurve", "crust_error_curve"]

HYPERSURFACES = ("sphere", "catenoid")
#: the thesis's 3-sphere has radius 2, so |H| = 1/2 (§3.4.2)
SPHERE_RADIUS = 2.0


def sample_hypersurface(surface: str, n_samples: int, *, seed: int = 0) -> tuple[np.ndarray, np.ndarray | None]:
    """Uniform random samples of the 3-sphere of radius 2 or of the 3-catenoid piece
    u ∈ [0, 2π), v, w ∈ [−1, 1] (the thesis's region), with their parameters (None for the sphere).

    Thesis: §3.4.2 and §3.4.3 (the same hypersurfaces, there on parameter grids).

    Parameters
    ----------
    surface : {"sphere", "catenoid"}
        Which hypersurface of R⁴.
    n_samples : int
        Number of samples, at least 1.
    seed : int, default 0
        Seed of the random draws.

    Returns
    -------
    points : ndarray of float64, shape (n_samples, 4)
        The samples.
    params : ndarray of float64, shape (n_samples, 3), or None
        The catenoid parameters (u, v, w) of each sample; None for the sphere.

    Raises
    ------
    ValueError
        On an unknown ``surface`` or an invalid ``n_samples`` (or ``seed``, for the sphere).
    """
    if check_choice(surface, HYPERSURFACES, "surface") == "sphere":
        return sample_sphere(n_samples, n_dims=4, radius=SPHERE_RADIUS, seed=seed), None
    return sample_n_catenoid(n_samples, dimension=3, seed=seed, return_params=True)


def _errors(surface: str, H: np.ndarray, params, where: np.ndarray) -> np.ndarray:
    """Relative errors at the vertices ``where``: |H − 1/2| / (1/2) on the sphere; on the catenoid
    (H = 0, no relative error) |H| over the largest principal curvature 1/cosh² v."""
    if surface == "sphere":
        exact = 1.0 / SPHERE_RADIUS
        return np.abs(H[where] - exact) / exact
    return H[where] * np.cosh(params[where, 1]) ** 2


def crust_curvature_errors(surface: str, n_samples: int, *, seed: int = 0, area: str = "voronoi",
                           theta: float = np.pi / 4) -> dict:
    """Reconstruct ``n_samples`` random samples with the Crust and estimate |H| by Theorem 3.18.

    Thesis: Theorem 3.18 and §3.3.2 (areas) on the Crust of Chapter 5's "natural next step".

    Parameters
    ----------
    surface : {"sphere", "catenoid"}
        Which hypersurface of R⁴ (:func:`sample_hypersurface`); the sphere is reconstructed as a
        closed hypersurface, the catenoid piece as one with boundary.
    n_samples : int
        Number of random samples.
    seed : int, default 0
        Seed of the samples.
    area : {"voronoi", "barycentric"}, default "voronoi"
        The vertex region of :func:`~thesis_lib.curvature.mean_curvature` (``"mixed"`` needs n = 2
        and is refused here).
    theta : float, default π/4
        The Crust's normal-filter angle (:func:`~thesis_lib.reconstruction.crust_nd.crust_nd`).

    Returns
    -------
    dict
        ``simplices``, ``points``, ``params``, ``H`` (per sample, NaN where not estimated), ``report``
        (:class:`~thesis_lib.reconstruction.crust_nd.ManifoldReport`), ``pole_ratio``, ``estimated`` (mask
        of the samples with an estimate: vertices whose star is a manifold ball), ``errors`` (at those, see Notes),
        ``median``, ``p90``; for the catenoid also ``control_median``/``control_p90``: the same
        errors on the Delaunay triangulation of the samples' parameters (u, v, w) lifted to R⁴, a
        triangulation with no reconstruction error.

    Raises
    ------
    ValueError
        On an unknown ``surface`` or bad sampling parameters; ``ReconstructionError`` (a
        ValueError) when the Crust fails (see :func:`~thesis_lib.reconstruction.crust_nd.crust_nd`).

    Notes
    -----
    The error is |H − 1/2| / (1/2) on the sphere, and |H| cosh² v (|H| over the largest principal
    curvature) on the catenoid, whose H = 0 has no relative error.
    """
    pts, params = sample_hypersurface(surface, n_samples, seed=seed)
    res = crust_nd(pts, theta=theta, closed=(surface == "sphere"))
    H = mean_curvature(pts, res.simplices, area=area)
    good = manifold_vertices(res.simplices, n_points=len(pts)) & np.isfinite(H)
    H = np.where(good, H, np.nan)
    err = _errors(surface, H, params, good)
    out = dict(points=pts, params=params, simplices=res.simplices, H=H, report=res.report,
               pole_ratio=res.pole_ratio, estimated=good, errors=err,
               median=float(np.median(err)), p90=float(np.percentile(err, 90)))
    if surface == "catenoid":
        tri = Delaunay(params)
        Hc = mean_curvature(pts, tri.simplices, area=area)
        # away from the seam u = 0 ≡ 2π, which the parameter triangulation does not close
        ok = np.isfinite(Hc) & (params[:, 0] > 0.5) & (params[:, 0] < 2 * np.pi - 0.5)
        ctrl = _errors(surface, Hc, params, ok)
        out.update(control_median=float(np.median(ctrl)), control_p90=float(np.percentile(ctrl, 90)))
    return out


def _check_run(run: Mapping) -> None:
    missing = {"points", "report", "estimated", "median", "p90"} - set(run) if isinstance(run, Mapping) else None
    if missing is None or missing:
        raise ValueError(f"run must be a result of crust_curvature_errors; missing {sorted(missing or ['all'])}")


def crust_run_results(run: Mapping, *, prefix: str) -> dict[str, float]:
    """The numbers stored of one reconstruction: its manifold check and the errors of |H|.

    Thesis: Theorem 3.18 on the Crust of the Summary's "natural next step" (beyond the thesis).

    Parameters
    ----------
    run : mapping
        A result of :func:`crust_curvature_errors`.
    prefix : str
        The first part of every name (``"main"``: ``main_n_simplices``, ...).

    Returns
    -------
    dict of str to number
        ``<prefix>_n_simplices``, ``_closed_manifold`` (0 or 1), ``_vertex_fraction``,
        ``_boundary_components``, ``_bad_vertex_links``, ``_euler``, ``_estimated_fraction``,
        ``_median_error`` and ``_p90_error``.

    Raises
    ------
    ValueError
        If ``run`` is not a result of :func:`crust_curvature_errors`, or ``prefix`` is not an identifier.

    Examples
    --------
    >>> run = crust_curvature_errors("sphere", 500, seed=0)
    >>> res = crust_run_results(run, prefix="small")
    >>> res["small_closed_manifold"], res["small_euler"], bool(res["small_median_error"] < 0.2)
    (1, 0, True)
    """
    _check_run(run)
    if not prefix.isidentifier():
        raise ValueError(f"prefix must be an identifier, got {prefix!r}")
    rep = run["report"]
    return {
        f"{prefix}_n_simplices": rep.n_simplices,
        f"{prefix}_closed_manifold": int(rep.is_closed_manifold),
        f"{prefix}_vertex_fraction": rep.vertex_fraction,
        f"{prefix}_boundary_components": rep.boundary_components,
        f"{prefix}_bad_vertex_links": rep.bad_vertex_links,
        f"{prefix}_euler": rep.euler_characteristic,
        f"{prefix}_estimated_fraction": float(run["estimated"].mean()),
        f"{prefix}_median_error": run["median"],
        f"{prefix}_p90_error": run["p90"],
    }


def describe_crust_run(run: Mapping, *, surface: str, width: int = 76) -> str:
    """What the reconstruction is and how good its |H| is, in two paragraphs filled to ``width``.

    Thesis: Theorem 3.18 on the Crust of the Summary's "natural next step" (beyond the thesis).

    Parameters
    ----------
    run : mapping
        A result of :func:`crust_curvature_errors`.
    surface : {"sphere", "catenoid"}
        The hypersurface it reconstructs (named in the text).
    width : int, default 76
        The longest line.

    Returns
    -------
    str
        The manifold check (:meth:`~thesis_lib.reconstruction.crust_nd.ManifoldReport.describe`), then the
        number of estimates and the median and 90th percentile of the error to 2 digits.

    Raises
    ------
    ValueError
        If ``run`` is not a result of :func:`crust_curvature_errors`, ``surface`` is unknown or
        ``width`` is below 20.

    Examples
    --------
    >>> run = crust_curvature_errors("sphere", 500, seed=0)
    >>> print(describe_crust_run(run, surface="sphere").splitlines()[-1][:25])
    |H| estimated at 500 samp
    """
    _check_run(run)
    check_choice(surface, HYPERSURFACES, "surface")
    width = check_int(width, "width", minimum=20)
    check = textwrap.fill(f"{surface}, {len(run['points'])} samples: {run['report'].describe()}", width)
    errors = textwrap.fill(f"|H| estimated at {int(run['estimated'].sum())} samples; error median "
                           f"{round_sig(run['median'], 2):.2g}, 90th percentile {round_sig(run['p90'], 2):.2g}", width)
    return check + "\n" + errors


#: the columns of :attr:`CrustErrorCurve.rows`
CURVE_COLUMNS = ("n_samples", "median", "p90", "control_median", "control_p90", "closed_manifold", "estimated_fraction")


@dataclass(frozen=True, kw_only=True)
class CrustErrorCurve:
    """The errors of |H| on Crust reconstructions against the sample count, a few seeds per count.

    Thesis: Theorem 3.18, the 3-D analogue of Figures 3.8–3.10 (beyond the thesis).

    ``rows`` has one row per reconstruction with the columns of ``CURVE_COLUMNS``: the sample count,
    the median and 90th percentile of the error, the same on the parameter Delaunay control (NaN on
    the sphere), 1 if closed manifold, and the fraction of samples with an estimate.  ``counts`` are
    the sample counts in order.
    """

    surface: str
    counts: tuple[int, ...]
    rows: np.ndarray

    def at(self, n_samples: int) -> np.ndarray:
        """The rows of the reconstructions of ``n_samples`` samples.

        Parameters
        ----------
        n_samples : int
            One of ``counts``.

        Returns
        -------
        ndarray of float64, shape (repeats, 7)
            Their rows.

        Raises
        ------
        ValueError
            If ``n_samples`` is not one of ``counts``.

        Examples
        --------
        >>> rows = np.array([[100, 0.2, 0.5, 0.25, 0.6, 0, 0.2], [100, 0.3, 0.7, 0.2, 0.5, 0, 0.4]])
        >>> curve = CrustErrorCurve(surface="catenoid", counts=(100,), rows=rows)
        >>> curve.at(100)[:, 1].tolist()
        [0.2, 0.3]
        """
        if n_samples not in self.counts:
            raise ValueError(f"n_samples must be one of {self.counts}, got {n_samples!r}")
        return self.rows[self.rows[:, 0] == n_samples]

    def results(self) -> dict[str, float]:
        """The numbers stored per count: means over the seeds of the median and 90th-percentile errors
        with their spreads, closed runs, estimated fraction; on the catenoid also the control's.

        Returns
        -------
        dict of str to number
            Named ``<surface>_<n>_median_error``, ``..._median_error_spread``, ``..._p90_error``,
            ``..._p90_error_spread``, ``..._closed_runs``, ``..._estimated_fraction``; for the catenoid
            ``..._control_median_error``, ``..._control_p90_error``, ``..._median_excess_over_control``.

        Examples
        --------
        >>> rows = np.array([[100, 0.2, 0.5, 0.25, 0.6, 0, 0.2], [100, 0.3, 0.7, 0.2, 0.5, 0, 0.4]])
        >>> curve = CrustErrorCurve(surface="catenoid", counts=(100,), rows=rows)
        >>> res = curve.results()
        >>> [round(float(res[f"catenoid_100_{k}"]), 6) for k in ("median_error", "median_excess_over_control")]
        [0.25, 0.025]
        """
        out: dict[str, float] = {}
        for n in self.counts:
            sel = self.at(n)
            tag = f"{self.surface}_{n}"
            out.update({
                f"{tag}_median_error": sel[:, 1].mean(), f"{tag}_median_error_spread": np.ptp(sel[:, 1]),
                f"{tag}_p90_error": sel[:, 2].mean(), f"{tag}_p90_error_spread": np.ptp(sel[:, 2]),
                f"{tag}_closed_runs": int(sel[:, 5].sum()), f"{tag}_estimated_fraction": sel[:, 6].mean(),
            })
            if self.surface == "catenoid":
                out.update({f"{tag}_control_median_error": sel[:, 3].mean(),
                            f"{tag}_control_p90_error": sel[:, 4].mean(),
                            f"{tag}_median_excess_over_control": (sel[:, 1] - sel[:, 3]).mean()})
        return out

    def describe(self) -> str:
        """One line per count: the mean median and 90th-percentile errors (2 digits), the control's
        median on the catenoid, and the share of samples with an estimate.

        Returns
        -------
        str
            The lines, no final newline.

        Examples
        --------
        >>> rows = np.array([[100, 0.2, 0.5, 0.25, 0.6, 0, 0.2], [100, 0.3, 0.7, 0.2, 0.5, 0, 0.4]])
        >>> curve = CrustErrorCurve(surface="catenoid", counts=(100,), rows=rows)
        >>> print(curve.describe())
        catenoid   100: median 0.25, p90 0.6, control median 0.23, estimated at 30%
        """
        lines = []
        for n in self.counts:
            sel = self.at(n)
            control = f", control median {round_sig(sel[:, 3].mean(), 2):.2g}" if self.surface == "catenoid" else ""
            lines.append(f"{self.surface:8s} {n:5d}: median {round_sig(sel[:, 1].mean(), 2):.2g}, "
                         f"p90 {round_sig(sel[:, 2].mean(), 2):.2g}{control}, "
                         f"estimated at {100 * sel[:, 6].mean():.0f}%")
        return "\n".join(lines)


def crust_error_curve(surface: str, counts: Sequence[int], *, repeats: int = 2, seed: int = 0, area: str = "voronoi",
                      theta: float = np.pi / 4, known: Mapping[tuple[str, int, int], Mapping] | None = None
                      ) -> CrustErrorCurve:
    """Reconstruct ``repeats`` samples (seeds ``seed``, ``seed + 1``, ...) of every count and estimate |H|.

    Thesis: Theorem 3.18 on the Crust of the Summary's "natural next step", as Figures 3.8–3.10
    grow the sample of the torus (beyond the thesis).

    Parameters
    ----------
    surface : {"sphere", "catenoid"}
        The hypersurface (:func:`sample_hypersurface`).
    counts : sequence of int
        The sample counts, distinct, each at least 1.
    repeats : int, default 2
        Samples per count.
    seed : int, default 0
        The seed of the first sample of each count.
    area : {"voronoi", "barycentric"}, default "voronoi"
        The vertex region of Theorem 3.18.
    theta : float, default π/4
        The Crust's normal-filter angle.
    known : mapping, optional
        Results of :func:`crust_curvature_errors` already computed, by ``(surface, n_samples, seed)``:
        used instead of reconstructing again.

    Returns
    -------
    CrustErrorCurve
        One row per reconstruction, counts in order, seeds in order within a count.

    Raises
    ------
    ValueError
        On an unknown ``surface``, no or repeated ``counts``, ``repeats`` below 1, or a failed
        reconstruction (``ReconstructionError``).

    Examples
    --------
    >>> curve = crust_error_curve("sphere", [300, 600], repeats=1)
    >>> curve.rows.shape, curve.at(600)[0, 5]
    ((2, 7), np.float64(1.0))
    >>> print(curve.describe().splitlines()[0][:22])
    sphere     300: median
    """
    check_choice(surface, HYPERSURFACES, "surface")
    counts = tuple(check_int(n, "counts", minimum=1) for n in counts)
    if not counts or len(set(counts)) != len(counts):
        raise ValueError(f"counts must be distinct sample counts, at least one, got {list(counts)}")
    repeats = check_int(repeats, "repeats", minimum=1)
    known = known or {}
    rows = []
    for n in counts:
        for r in range(repeats):
            out = known.get((surface, n, seed + r))
            if out is None:
                out = crust_curvature_errors(surface, n, seed=seed + r, area=area, theta=theta)
            rows.append((n, out["median"], out["p90"], out.get("control_median", np.nan),
                         out.get("control_p90", np.nan), out["report"].is_closed_manifold,
                         float(out["estimated"].mean())))
    return CrustErrorCurve(surface=surface, counts=counts, rows=np.array(rows, dtype=float))

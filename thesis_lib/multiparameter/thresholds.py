"""Where classes appear in the (ε, κ) plane: the thresholds the radius–curvature experiment reads
off Hilbert functions (thesis, Summary: persistence in the radius and a curvature parameter).

:func:`torus_run` filters a torus sample by its estimated Gaussian curvature (the inner half,
K < 0, holds one of the two loops), :func:`circles_run` two circles by |κ| (their meeting points
are the most curved), and :func:`first_at_least` reads the first grade where a Betti number
reaches a level.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .._validate import as_points
from .bifiltration import Bifiltration, radius_curvature_bifiltration
from .invariants import check_grid, hilbert_function

__all__ = ["first_at_least", "TorusRun", "torus_run", "CirclesRun", "circles_run"]


def first_at_least(values: npt.ArrayLike, grid: npt.ArrayLike, level: float) -> float:
    """The first grid value where ``values`` reaches ``level`` (NaN if it never does).

    Thesis: Summary, Chapter 5 (the grade at which a class has appeared).

    Parameters
    ----------
    values : array_like, shape (m,)
        A Betti number along one row or column of a Hilbert function.
    grid : array_like, shape (m,)
        The grade of each entry.
    level : float
        The level to reach.

    Returns
    -------
    float
        ``grid[i]`` for the first ``i`` with ``values[i] >= level``, else NaN.

    Raises
    ------
    ValueError
        ``values`` and ``grid`` of different lengths.

    Examples
    --------
    >>> first_at_least([0, 1, 2, 2], [0.0, 0.5, 1.0, 1.5], 2)
    1.0
    >>> first_at_least([0, 1], [0.0, 0.5], 3)
    nan
    """
    v, g = np.asarray(values), np.asarray(grid)
    if v.shape != g.shape:
        raise ValueError(f"values and grid must have the same shape, got {v.shape} and {g.shape}")
    hit = np.flatnonzero(v >= level)
    return float(g[hit[0]]) if hit.size else float("nan")


@dataclass(frozen=True, kw_only=True)
class TorusRun:
    """One torus sample filtered by radius and estimated Gaussian curvature.

    Thesis: Summary (radius × curvature); the torus of §3.4.1 (K < 0 on the inner half).

    Attributes
    ----------
    bifiltration : the alpha bifiltration, κ the signed estimate.
    hilbert : ``[β₁, β₂]`` on the grid (``hilbert[0][i, j]`` at ε_i, κ_j).
    curvatures : the κ grid (from the least to the largest estimate).
    star : index of ε*, the middle of the ε band where the whole torus has β₁ = 2 and β₂ = 1.
    sign : the fraction of points whose estimate has the sign of the exact curvature.
    one, two : the first κ at ε* with β₁ ≥ 1, and the κ from which β₁ = 2 for good (NaN if never).
    inner : the most frequent β₁ at ε* on the inner half (κ ≤ 0).
    transient : the largest β₁ at ε* along κ.
    """

    bifiltration: Bifiltration
    hilbert: list[np.ndarray]
    curvatures: np.ndarray
    star: int
    sign: float
    one: float
    two: float
    inner: int
    transient: int


def torus_run(points: npt.ArrayLike, curvature: npt.ArrayLike, *, exact: npt.ArrayLike, radii: npt.ArrayLike,
              n_kappa: int) -> TorusRun:
    """Filter a torus sample by radius and its estimated Gaussian curvature and read off where its loops appear.

    Thesis: Summary (a filtration in ε and κ separates the inner loop, K < 0, from the outer one).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        The sample.
    curvature : array_like, shape (n,)
        The estimated Gaussian curvature at each point (signed).
    exact : array_like, shape (n,)
        The exact Gaussian curvature at each point (only its sign is used).
    radii : array_like
        The ε grid (strictly increasing); it must reach the band where the whole torus has β₁ = 2
        and β₂ = 1.
    n_kappa : int
        Grid points in κ, from the least to the largest estimate.

    Returns
    -------
    TorusRun
        The bifiltration, its Hilbert functions and the thresholds.

    Raises
    ------
    ValueError
        Mismatched lengths, a bad grid, or an ε grid that never shows the torus's β₁ = 2, β₂ = 1.

    Examples
    --------
    >>> from thesis_lib.surfaces import torus_gaussian_curvature_at
    >>> from thesis_lib.curvature.pointcloud import neighbour_mean
    >>> from thesis_lib.meshes import sample_torus
    >>> from thesis_lib.curvature.point_curvature import point_curvature
    >>> X = sample_torus(1000, R=10.0, r=5.0, seed=0)
    >>> K = neighbour_mean(X, point_curvature(X, estimator="crust", curvature="gaussian"), k=16)
    >>> run = torus_run(X, K, exact=torus_gaussian_curvature_at(X, R=10.0, r=5.0), radii=np.linspace(0, 8, 17),
    ...                 n_kappa=9)
    >>> int(run.hilbert[0][run.star, -1]), int(run.hilbert[1][run.star, -1]), run.inner  # the torus; its inner loop
    (2, 1, 1)
    """
    pts = as_points(points)
    K = np.asarray(curvature, dtype=np.float64)
    exact = np.asarray(exact, dtype=np.float64)
    if K.shape != (len(pts),) or exact.shape != (len(pts),):
        raise ValueError(f"curvature and exact need one value per point ({len(pts)}), got {K.shape} and {exact.shape}")
    eps = check_grid(radii, name="radii")
    kappa = np.linspace(K.min(), K.max(), n_kappa)
    bif = radius_curvature_bifiltration(pts, K, complex="alpha", absolute=False)
    hf = hilbert_function(bif, eps, kappa, dims=[1, 2])
    band = np.flatnonzero((hf[0][:, -1] == 2) & (hf[1][:, -1] == 1))
    if band.size == 0:
        raise ValueError("the ε grid never shows the torus (β₁ = 2 and β₂ = 1 with every point): extend radii")
    star = int(band[len(band) // 2])
    row = hf[0][star]
    settled = np.flatnonzero(row != 2)  # β₁ = 2 from just after the last κ where it is not 2
    two = kappa[settled[-1] + 1] if settled.size and settled[-1] + 1 < n_kappa else np.nan
    return TorusRun(bifiltration=bif, hilbert=hf, curvatures=kappa, star=star,
                    sign=np.mean(np.sign(K) == np.sign(exact)), one=first_at_least(row, kappa, 1), two=two,
                    inner=int(np.bincount(row[kappa <= 0]).argmax()), transient=int(row.max()))


@dataclass(frozen=True, kw_only=True)
class CirclesRun:
    """Two circles filtered by radius and |κ|, and where their three loops appear.

    Thesis: Summary (curvature as a second parameter); the two circles of §2.4.1.

    Attributes
    ----------
    bifiltration : the Rips bifiltration, κ = |estimated curvature|.
    hilbert : β₁ on the grid.
    radii, curvatures : the ε grid and the κ grid (quantiles of the estimates).
    junction, rest : the median |κ| near the circles' meeting points and elsewhere.
    eps3 : the smallest ε of the grid with β₁ = 3 at full κ.
    kappa3 : the smallest κ with β₁ = 3 at ``eps3``.
    kappa3_rank : the fraction of points with |κ| below ``kappa3``.
    """

    bifiltration: Bifiltration
    hilbert: np.ndarray
    radii: np.ndarray
    curvatures: np.ndarray
    junction: float
    rest: float
    eps3: float
    kappa3: float
    kappa3_rank: float


def circles_run(points: npt.ArrayLike, curvature: npt.ArrayLike, *, junctions: npt.ArrayLike, max_radius: float,
                n_eps: int, n_kappa: int, near: float = 0.05) -> CirclesRun:
    """Filter two circles by radius and |κ| and read off where their three loops appear.

    Thesis: Summary (the most curved points, where the circles meet, enter last).

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The sample.
    curvature : array_like, shape (n,)
        |κ| at each point (non-negative).
    junctions : array_like, shape (m, 2)
        The circles' meeting points.
    max_radius : float
        Largest Rips ε; the ε grid has ``n_eps`` points from 0.
    n_eps, n_kappa : int
        Grid points in ε and in κ (κ at quantiles of the estimates, repeated values merged).
    near : float, default 0.05
        A point within this distance of a junction is "near" it.

    Returns
    -------
    CirclesRun
        The bifiltration, its Hilbert function and the thresholds.

    Raises
    ------
    ValueError
        Mismatched lengths, or a grid on which β₁ never reaches 3.

    Examples
    --------
    >>> from thesis_lib.datasets import two_circles, two_circles_intersections
    >>> from thesis_lib.curvature.point_curvature import point_curvature
    >>> X = two_circles(60, seed=0)
    >>> run = circles_run(X, point_curvature(X, estimator="knn", k=10), junctions=two_circles_intersections(),
    ...                   max_radius=0.8, n_eps=21, n_kappa=21)
    >>> bool(run.junction > run.rest), int(run.hilbert.max())
    (True, 3)
    """
    pts = as_points(points)
    kap = np.asarray(curvature, dtype=np.float64)
    if kap.shape != (len(pts),):
        raise ValueError(f"curvature needs one value per point ({len(pts)}), got shape {kap.shape}")
    close = np.min(np.linalg.norm(pts[:, None] - np.asarray(junctions, dtype=np.float64)[None], axis=2), axis=1) < near
    bif = radius_curvature_bifiltration(pts, kap, complex="rips", max_radius=max_radius, max_dim=2)
    eps = np.linspace(0.0, max_radius, n_eps)
    kappa = np.unique(np.quantile(kap, np.linspace(0, 1, n_kappa)))
    hf = hilbert_function(bif, eps, kappa, dims=[1])[0]
    three = hf == 3
    full = np.flatnonzero(three[:, -1])
    if full.size == 0:
        raise ValueError("β₁ never reaches 3 on the ε grid: raise max_radius")
    e3 = int(full[0])  # the smallest ε with β₁ = 3 at full κ, then the smallest κ with β₁ = 3 there
    kappa3 = first_at_least(three[e3], kappa, 1)
    return CirclesRun(bifiltration=bif, hilbert=hf, radii=eps, curvatures=kappa, junction=np.median(kap[close]),
                      rest=np.median(kap[~close]), eps3=eps[e3], kappa3=kappa3, kappa3_rank=np.mean(kap < kappa3))

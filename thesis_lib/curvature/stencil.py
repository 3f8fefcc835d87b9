"""The thesis's neighbour-grid estimate of |H| on parametrised hypersurfaces (§3.4.2–3.4.3).

Without a triangulation in dimension ≥ 4, the thesis estimates the mean curvature at X(w) from the
2n neighbours X(w ± ε e_i): the star of X(w) is taken to be the 2^n simplices
[X(w), X(w + s_1 ε e_1), ..., X(w + s_n ε e_n)] (s ∈ {±1}^n, a cross-polytope star), the discrete
mean curvature vector is the gradient of the star's hyperarea (Definition 3.15), and the vertex's
area is half the star's hyperarea ("the volume of the 3-simplex divided by 2").  For this star the
half is exact to leading order in ε: |H| = ‖∇ area‖ / (n · area/2) → |tr S|/n for every n.
"""

from __future__ import annotations

import itertools
import warnings
from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from .._validate import InvalidTypeError, as_points, check_real, check_size
from .geometry import simplex_hyperareas
from .mean import mean_curvature_vector

__all__ = ["cross_stars", "neighbour_grid_mean_curvature"]


def cross_stars(X: Callable[[np.ndarray], np.ndarray], params: npt.ArrayLike,
                *, step: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Disjoint cross-polytope stars around the points X(w), w in ``params`` (k, n).

    Thesis: §3.4.2 (neighbouring vertices (ψ ± ε, θ ± ε, φ ± ε)).

    Parameters
    ----------
    X : callable
        Parametrisation mapping (m, n) parameters to (m, n + 1) points, vectorised.
    params : array_like, shape (k, n)
        The parameter points w, finite.
    step : float
        Grid step ε > 0.

    Returns
    -------
    vertices : ndarray of float64, shape (k(2n+1), n+1)
        Vertex ``centres[j]`` is X(w_j), followed by X(w_j + ε e_i) and X(w_j - ε e_i) for
        i = 0..n-1.
    simplices : ndarray of int, shape (k·2^n, n+1)
        The 2^n simplices of each star, centre first; star j is rows j·2^n to (j+1)·2^n − 1.
    centres : ndarray of int, shape (k,)
        Index of each centre X(w_j) among the vertices.

    Raises
    ------
    ValueError
        On invalid ``params``, a non-positive ``step``, stars too large to build, or an ``X``
        that does not map (m, n) to (m, n + 1) (``InvalidTypeError`` if it is not callable).

    Examples
    --------
    One star on the plane z = 0: the centre, its four neighbours at (±ε, 0) and (0, ±ε), four
    triangles:

    >>> import numpy as np
    >>> plane = lambda w: np.column_stack([w, np.zeros(len(w))])
    >>> vertices, simplices, centres = cross_stars(plane, [[0.0, 0.0]], step=0.1)
    >>> vertices.shape, simplices.tolist(), centres.tolist()
    ((5, 3), [[0, 1, 3], [0, 1, 4], [0, 2, 3], [0, 2, 4]], [0])
    """
    w = as_points(params, name="params")
    step = check_real(step, "step", positive=True)
    if not callable(X):
        raise InvalidTypeError(f"X must be a function of parameters, got {X!r}")
    k, n = w.shape
    check_size(k * 2**n * (n + 1), f"vertex entries ({k * 2**n:,} simplices of the stars)")
    shifts = [np.zeros(n)]
    for i in range(n):
        e = np.zeros(n)
        e[i] = step
        shifts += [e, -e]
    allw = (w[:, None, :] + np.array(shifts)[None]).reshape(-1, n)
    try:
        vertices = np.asarray(X(allw), dtype=np.float64)
    except (TypeError, ValueError) as err:
        raise ValueError(f"X must map (m, {n}) parameters to (m, {n + 1}) points: {err}") from None
    if vertices.shape != (len(allw), n + 1):
        raise ValueError(f"X must map (m, {n}) parameters to (m, {n + 1}) points, got {vertices.shape}")
    base = np.arange(k) * (2 * n + 1)
    local = []
    for signs in itertools.product((0, 1), repeat=n):
        local.append([0] + [1 + 2 * i + s for i, s in enumerate(signs)])
    local = np.array(local)  # (2^n, n+1)
    simplices = (base[:, None, None] + local[None]).reshape(-1, n + 1)
    return vertices, simplices, base


def neighbour_grid_mean_curvature(
    X: Callable[[np.ndarray], np.ndarray], params: npt.ArrayLike, *, step: float, method: str = "gram"
) -> np.ndarray:
    """|H| at X(w) for each w in ``params`` from its 2n grid neighbours (the thesis's approximation).

    Thesis: §3.4.2 (Figure 3.12) and §3.4.3 (Figure 3.13).

    |H| = ‖∇_p hyperarea(star)‖ / (n · hyperarea(star)/2), with the gradient from
    :func:`thesis_lib.curvature.mean_curvature_vector`.

    Parameters
    ----------
    X : callable
        Parametrisation (m, n) -> (m, n + 1), as in :func:`cross_stars`.
    params : array_like, shape (k, n)
        Where |H| is wanted.
    step : float
        The grid step ε of the neighbours X(w ± ε e_i).
    method : {"gram", "cot"}, default "gram"
        The gradient formula of :func:`thesis_lib.curvature.mean_curvature_vector`.

    Returns
    -------
    ndarray of float64, shape (k,)
        The estimated |H| at each X(w).

    Raises
    ------
    ValueError
        As :func:`cross_stars`, on an unknown ``method``, or when a star is not a valid mesh (e.g.
        degenerate simplices where the parametrisation is singular).

    Examples
    --------
    The sphere of radius 2 has |H| = 1/2 everywhere:

    >>> import numpy as np
    >>> from thesis_lib.surfaces import hypersphere_point
    >>> sphere = lambda w: hypersphere_point(w, radius=2.0)
    >>> np.round(neighbour_grid_mean_curvature(sphere, [[np.pi / 2, 0.0], [1.0, 2.0]], step=0.01), 4).tolist()
    [0.5, 0.5]
    """
    vertices, simplices, centres = cross_stars(X, params, step=step)
    n = simplices.shape[1] - 1
    with warnings.catch_warnings():  # the stars are disjoint copies by design: their rims coincide
        warnings.filterwarnings("ignore", message=".*boundary vertices lie at exactly", category=UserWarning)
        vec = mean_curvature_vector(vertices, simplices, method=method)[centres]
    vol = simplex_hyperareas(vertices, simplices).reshape(len(centres), -1).sum(axis=1)
    return np.linalg.norm(vec, axis=1) / (n * vol / 2)

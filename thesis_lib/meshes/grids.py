"""Triangulations of parameter grids: the torus grid and Freudenthal (Kuhn) subdivisions.

A parameter grid with ``shape = (m_1, ..., m_n)`` vertices is cut into n-simplices by the
Freudenthal–Kuhn rule: every grid cube with lower corner b gives the n! simplices
b, b + e_{π(1)}, b + e_{π(1)} + e_{π(2)}, ..., b + (1, ..., 1) for the permutations π.  Mapped
through a parametrisation X this triangulates the hypersurfaces of §3.4 in any dimension.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from .._validate import InvalidTypeError, as_points, check_int, check_real, check_simplices, check_size
from ..complexes.scaling import scaled
from ..surfaces import catenoid_point, hypersphere_point, torus_point

__all__ = [
    "freudenthal",
    "grid_parameters",
    "torus_grid",
    "torus_chosen_points",
    "merge_coincident",
    "hypersphere_freudenthal",
    "catenoid_freudenthal",
]

#: largest hypersurface dimension of the Freudenthal grids (each cube splits into n! simplices: the
#: size check refuses far smaller grids; the bound keeps absurd n from overflowing before it)
MAX_GRID_DIM = 32


def _check_grid(shape, periodic) -> tuple[tuple[int, ...], tuple[bool, ...]]:
    """Validated grid shape and periodicity; refuses up front a triangulation too large to build."""
    shape = tuple(shape) if np.ndim(shape) else (shape,)
    if len(shape) == 0:
        raise ValueError("shape must have at least one axis")
    n = len(shape)
    per = (bool(periodic),) * n if np.ndim(periodic) == 0 else tuple(bool(p) for p in periodic)
    if len(per) != n:
        raise ValueError(f"periodic has {len(per)} entries for {n} axes")
    shape = tuple(check_int(m, "grid size", minimum=3 if p else 2) for m, p in zip(shape, per))
    cells = math.prod(m if p else m - 1 for m, p in zip(shape, per))
    count = math.factorial(n) * cells
    check_size(count * (n + 1), f"vertex entries ({count:,} simplices of {n + 1} vertices)")
    return shape, per


def _permutation_sign(perm: tuple[int, ...]) -> int:
    perm = list(perm)
    sign = 1
    for i in range(len(perm)):
        while perm[i] != i:
            j = perm[i]
            perm[i], perm[j] = perm[j], perm[i]
            sign = -sign
    return sign


def freudenthal(shape: Sequence[int] | int, *, periodic: bool | Sequence[bool] = False) -> np.ndarray:
    """Freudenthal/Kuhn subdivision of an n-dimensional vertex grid into n-simplices.

    Thesis: §3.4.2–3.4.3 (triangulating hypersurfaces given by parametrised grids).

    Parameters
    ----------
    shape : int or sequence of int
        Number of grid vertices along each axis, ``(m_1, ..., m_n)``; vertex ``(i_1, ..., i_n)``
        has the C-order flat index ``np.ravel_multi_index(i, shape)``.
    periodic : bool or sequence of bool, default False
        One for all axes or one per axis; a periodic axis wraps (``m`` cells instead of ``m - 1``).

    Returns
    -------
    ndarray of int64, shape (n! · #cells, n + 1)
        The simplices, each positively oriented in parameter space
        (det[v_1 - v_0, ..., v_n - v_0] > 0 before wrapping).

    Raises
    ------
    ValueError
        On a bad shape, or when the triangulation would hold more than 10⁹ vertex entries (say
        ``(2,) * 12``: 12! = 479,001,600 simplices), before anything is built.
    """
    shape, per = _check_grid(shape, periodic)
    n = len(shape)
    cells = [m if p else m - 1 for m, p in zip(shape, per)]
    base = np.stack(np.meshgrid(*[np.arange(c) for c in cells], indexing="ij"), axis=-1).reshape(-1, n)
    out = []
    for perm in itertools.permutations(range(n)):
        path = [base.copy()]
        cur = base.copy()
        for axis in perm:
            cur = cur.copy()
            cur[:, axis] += 1
            path.append(cur)
        verts = np.stack(path, axis=1)  # (cells, n+1, n)
        if _permutation_sign(perm) < 0:  # orientation of the Kuhn simplex is sign(π)
            verts = verts[:, [1, 0] + list(range(2, n + 1))]
        for axis in range(n):
            if per[axis]:
                verts[..., axis] %= shape[axis]
        out.append(np.ravel_multi_index(tuple(np.moveaxis(verts, -1, 0)), shape))
    return np.concatenate(out, axis=0).astype(np.int64)


def grid_parameters(*axes: npt.ArrayLike) -> np.ndarray:
    """Parameters of the grid ``axes[0] × axes[1] × ...`` in the C order used by :func:`freudenthal`.

    Thesis: §3.4 (the parameter grids {0, ε, 2ε, ...}).

    Parameters
    ----------
    *axes : array_like
        One array of finite numbers per parameter, at least one, none empty (flattened).

    Returns
    -------
    ndarray of float64, shape (Π len(axes[i]), len(axes))
        Row ``ravel_multi_index(i, shape)`` holds ``(axes[0][i_0], axes[1][i_1], ...)``.

    Raises
    ------
    ValueError
        If there is no axis or an empty one, an axis holds NaN or infinite values or is not
        numeric (``InvalidTypeError``), or the grid would be too large.
    """
    try:
        arrs = [np.asarray(a, dtype=np.float64).ravel() for a in axes]
    except (TypeError, ValueError) as err:
        raise InvalidTypeError(f"grid axes must be arrays of numbers: {err}") from None
    if not arrs or any(a.size == 0 for a in arrs):
        raise ValueError("need at least one non-empty axis")
    if any(not np.all(np.isfinite(a)) for a in arrs):
        raise ValueError("grid axes contain NaN or infinite values")
    count = math.prod(a.size for a in arrs)
    check_size(count * len(arrs), f"coordinates ({count:,} grid points in R^{len(arrs)})")
    return np.stack(np.meshgrid(*arrs, indexing="ij"), axis=-1).reshape(-1, len(arrs))


def torus_grid(n: int, *, R: float = 10.0, r: float = 5.0) -> tuple[np.ndarray, np.ndarray]:
    """Periodic n × n grid on the torus, u_i = 2πi/n, v_j = 2πj/n, with one diagonal per square.

    Thesis: §3.4.1, "Torus 1: chosen points" (ε = 2π/n).

    Parameters
    ----------
    n : int
        Grid points per circle, at least 3.
    R, r : float
        The torus's radii, 0 < r < R (default 10 and 5).

    Returns
    -------
    vertices : ndarray of float64, shape (n², 3)
        Vertex ``i·n + j`` is X(u_i, v_j) (:func:`~thesis_lib.surfaces.torus.torus_point`).
    faces : ndarray of int64, shape (2n², 3)
        Every face oriented by X_u × X_v (outward).

    Raises
    ------
    ValueError
        On an ``n`` below 3 or too large, or invalid radii.
    """
    n = check_int(n, "n", minimum=3)
    check_size(2 * n * n, "faces")
    t = 2 * np.pi * np.arange(n) / n
    uv = grid_parameters(t, t)
    vertices = torus_point(uv[:, 0], uv[:, 1], R=R, r=r)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    a = (i * n + j).ravel()
    b = (((i + 1) % n) * n + j).ravel()
    c = (((i + 1) % n) * n + (j + 1) % n).ravel()
    d = (i * n + (j + 1) % n).ravel()
    faces = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    return vertices, faces


def torus_chosen_points(*, step: float = np.pi / 50, R: float = 10.0,
                        r: float = 5.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The thesis's "chosen points" (u, v) ∈ {0, ε, ..., 2π - ε}² on the torus, triangulated.

    Thesis: §3.4.1, Figures 3.4–3.7 (ε = π/50).

    Parameters
    ----------
    step : float, default π/50
        The grid step ε; 2π/ε must be an integer n >= 3 (up to a relative 1e-9).
    R, r : float
        Radii of the torus, 0 < r < R (default 10 and 5, as in the thesis).

    Returns
    -------
    vertices, faces : ndarray
        As :func:`torus_grid` with n = 2π/ε.
    uv : ndarray of float64, shape (n², 2)
        The parameters (u, v) of the vertices.

    Raises
    ------
    ValueError
        If ``step`` is not positive or 2π/ε not an integer >= 3, or on invalid radii.
    """
    step = check_real(step, "step", positive=True)
    m = _steps(2 * np.pi, step, "u")
    n = int(round(m))
    if abs(m - n) > 1e-9 * m or n < 3:
        raise ValueError(f"2π/step must be an integer >= 3, got {m!r}")
    check_size(2 * n * n, "faces")
    vertices, faces = torus_grid(n, R=R, r=r)
    t = 2 * np.pi * np.arange(n) / n
    return vertices, faces, grid_parameters(t, t)


def merge_coincident(vertices: npt.ArrayLike, simplices: npt.ArrayLike,
                     *, tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Identify vertices closer than ``tol``, then drop degenerate and repeated simplices.

    Thesis: §3.4.2 (grid points at the poles of hyperspherical coordinates coincide).

    Parameters
    ----------
    vertices : array_like, shape (nv, d)
        The points.
    simplices : array_like of int, shape (m, k)
        Vertex indices (may be empty).
    tol : float, default 1e-9
        Vertices at distance <= ``tol`` are identified (and so are chains of such pairs); >= 0.

    Returns
    -------
    vertices : ndarray of float64, shape (nv', d)
        The merged vertices: each class keeps its first representative's coordinates.
    simplices : ndarray of int64, shape (m', k)
        The simplices renumbered (vertex order, and so orientation, kept), without those that
        collapsed and without repeats (the first of each kept, in input order).
    kept : ndarray of int, shape (nv',)
        ``kept[i]`` is the original index of new vertex ``i`` (its first representative).

    Raises
    ------
    ValueError
        On invalid vertices or simplices, or a negative ``tol``.
    """
    v = as_points(vertices, name="vertices")
    s = check_simplices(simplices, len(v), allow_empty=True)
    tol = check_real(tol, "tol", minimum=0.0)
    vs, e = scaled(v)  # squared distances must not overflow
    with np.errstate(over="ignore"):
        pairs = cKDTree(vs).query_pairs(float(np.ldexp(tol, e)), output_type="ndarray")
    nv = len(v)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(nv, nv))
    _, label = connected_components(graph, directed=False)
    # representative = smallest original index of each class, numbered in order of appearance
    first = np.full(label.max() + 1, nv)
    np.minimum.at(first, label, np.arange(nv))
    order = np.argsort(first, kind="stable")
    new_id = np.empty_like(order)
    new_id[order] = np.arange(len(order))
    s2 = new_id[label[s]]
    ss = np.sort(s2, axis=1)
    nondeg = np.all(ss[:, 1:] != ss[:, :-1], axis=1)
    s2, ss = s2[nondeg], ss[nondeg]
    _, idx = np.unique(ss, axis=0, return_index=True)
    s2 = s2[np.sort(idx)]
    kept = first[order]
    return v[kept], s2, kept


def _steps(span: float, step: float, name: str) -> float:
    """span / step, refused when it is not finite or would build a grid of more than 10⁹ points."""
    steps = span / step
    if not np.isfinite(steps):
        raise ValueError(f"{name}: the grid step {step!r} is too small (the grid would be infinite)")
    check_size(steps, f"grid points on the {name} axis")
    return steps


def _pair(value, name: str) -> tuple:
    try:
        low, high = value
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair (low, high), got {value!r}") from None
    return low, high


def _grid_axis(name: str, low: float, high: float, step: float) -> np.ndarray:
    low, high = check_real(low, f"{name} low"), check_real(high, f"{name} high")
    steps = _steps(high - low, step, name)
    k = int(round(steps))
    if k < 1 or abs(steps - k) > 1e-6 * max(1.0, steps):
        raise ValueError(f"{name}: (high - low)/step must be a positive integer, got {steps!r}")
    return low + step * np.arange(k + 1)


def hypersphere_freudenthal(*, step: float = np.pi / 50, radius: float = 2.0,
                            n: int = 3) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Freudenthal triangulation of the n-sphere of radius ρ in R^{n+1} in hyperspherical coordinates.

    Thesis: §3.4.2 (3-sphere, hyperspherical coordinates, ε = π/50).

    Grid ψ_i ∈ {0, ε, ..., π} (i < n) and φ ∈ {0, ε, ..., 2π - ε} (periodic).  The grid points on
    the degenerate region (ψ_i ∈ {0, π} for some i < n, where the coordinates collapse) are
    identified, and the simplices that collapse there are dropped, which leaves a closed
    triangulation of the whole sphere.

    Parameters
    ----------
    step : float, default π/50
        The grid step ε; π/ε must be an integer >= 2.
    radius : float, default 2.0
        The radius ρ > 0 (the thesis's 3-sphere has ρ = 2).
    n : int, default 3
        Dimension of the sphere, 1 to the largest grid dimension.

    Returns
    -------
    vertices : ndarray of float64, shape (nv, n + 1)
        The merged grid points on the sphere.
    simplices : ndarray of int64, shape (m, n + 1)
        The Freudenthal n-simplices that survive the merge.
    params : ndarray of float64, shape (nv, n)
        The hyperspherical coordinates of each vertex's first grid representative.

    Raises
    ------
    ValueError
        If ``step`` or ``radius`` is not positive, π/ε is not an integer >= 2, ``n`` is out of
        range, or the grid would be too large.
    """
    step = check_real(step, "step", positive=True)
    radius = check_real(radius, "radius", positive=True)
    n = check_int(n, "n", minimum=1, maximum=MAX_GRID_DIM)
    m = _steps(np.pi, step, "ψ")
    if abs(m - round(m)) > 1e-9 * m or round(m) < 2:
        raise ValueError(f"π/step must be an integer >= 2, got {m!r}")
    k = int(round(m))
    _check_grid((k + 1,) * (n - 1) + (2 * k,), (False,) * (n - 1) + (True,))
    ang = np.pi * np.arange(k + 1) / k
    phi = np.pi * np.arange(2 * k) / k
    params = grid_parameters(*([ang] * (n - 1) + [phi]))
    simplices = freudenthal((k + 1,) * (n - 1) + (2 * k,), periodic=(False,) * (n - 1) + (True,))
    vertices = hypersphere_point(params, radius=radius)
    vertices, simplices, kept = merge_coincident(vertices, simplices, tol=1e-9 * radius)
    return vertices, simplices, params[kept]


def catenoid_freudenthal(
    *, step: float = 0.05, n: int = 3, v_range: tuple[float, float] = (-1.0, 1.0),
    w_range: tuple[float, float] = (-1.0, 1.0), n_u: int | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Freudenthal triangulation of a piece of the n-catenoid (catenoid × R^{n-2}) in R^{n+1}.

    Thesis: §3.4.3 (the 3-catenoid, ε = 0.05, v, r ∈ [-1, 1]).

    Parameters
    ----------
    step : float, default 0.05
        Grid step of v and w (the ranges must be whole multiples of it).
    n : int, default 3
        Dimension of the catenoid, n >= 2.
    v_range : (low, high), default (-1.0, 1.0)
        The range of v.
    w_range : (low, high), default (-1.0, 1.0)
        The range of each extra coordinate w (unused for n = 2).
    n_u : int or None, default None
        Steps of the periodic u, at least 3 (default ``round(2π/ε)``, so the u-step is 2π/n_u ≈ ε).

    Returns
    -------
    vertices : ndarray of float64, shape (nv, n + 1)
        The grid points on the catenoid (:func:`~thesis_lib.surfaces.catenoid.catenoid_point`).
    simplices : ndarray of int64, shape (m, n + 1)
        The Freudenthal n-simplices, closed up in u; the boundary is v = v_low, v_high (and
        w = w_low, w_high).
    params : ndarray of float64, shape (nv, n)
        The parameters (u, v, w₁, ...) of each vertex.

    Raises
    ------
    ValueError
        On a non-positive ``step``, ``n`` outside 2 to the largest grid dimension, a range that
        is not a pair or not a whole number of steps, fewer than 3 u-steps, or a grid too large.
    """
    step = check_real(step, "step", positive=True)
    n = check_int(n, "n", minimum=2, maximum=MAX_GRID_DIM)
    n_u = int(round(_steps(2 * np.pi, step, "u"))) if n_u is None else check_int(n_u, "n_u", minimum=3)
    if n_u < 3:
        raise ValueError(f"the u axis needs at least 3 steps (step <= 2π/3), got step = {step}")
    v_axis = _grid_axis("v_range", *_pair(v_range, "v_range"), step)
    w_axis = _grid_axis("w_range", *_pair(w_range, "w_range"), step) if n > 2 else np.zeros(0)
    _check_grid((n_u, len(v_axis)) + (len(w_axis),) * (n - 2), (True,) + (False,) * (n - 1))
    axes = [2 * np.pi * np.arange(n_u) / n_u, v_axis] + [w_axis] * (n - 2)
    params = grid_parameters(*axes)
    simplices = freudenthal(tuple(len(a) for a in axes), periodic=(True,) + (False,) * (n - 1))
    return catenoid_point(params), simplices, params

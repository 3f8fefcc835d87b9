"""Compiled floating-point filters for the predicates of :mod:`.predicates` (C++, any dimension).

The kernels are compiled C++ (``src/predicate_filters.cpp``); this module is their typed face.
Each filter computes, row by row, a determinant by Laplace expansion over subsets of rows together
with its permanent (the same expansion on absolute values), and returns the sign where the value
exceeds the proven rounding-error bound ``(e·k + (k² + 2k)·u)·1.01·permanent`` (e the entries' own
relative error), 0 where it does not: those rows go to exact arithmetic.  The orthoball kernel
solves the small linear system of the smallest orthogonal sphere from the best-conditioned vertex
and flags the rows whose error amplification is too large to trust.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import predicate_filters

__all__ = ["orient_filter", "insphere_filter", "orient_one", "insphere_one", "orthoball_float", "power_filter"]


def _f64(a: npt.ArrayLike) -> np.ndarray:
    return np.ascontiguousarray(a, dtype=np.float64)


def _i64(a: npt.ArrayLike) -> np.ndarray:
    return np.ascontiguousarray(a, dtype=np.int64)


def orient_filter(points: npt.ArrayLike, simplices: npt.ArrayLike) -> np.ndarray:
    """Certain signs of det[x_i − x_0] (0 where undecided) for the rows of ``simplices``.

    Thesis: §2.1.2 (the orientation predicate of the Delaunay triangulation, Definition 2.13).

    Parameters
    ----------
    points : array_like of float, shape (n, d)
        The points x.
    simplices : array_like of int, shape (m, d + 1)
        Point indices ``x_0, ..., x_d`` per row.

    Returns
    -------
    numpy.ndarray of int8, shape (m,)
        +1 or −1 where the float determinant exceeds its error bound, 0 where it does not.
    """
    return predicate_filters.orient_filter(_f64(points), _i64(simplices))


def insphere_filter(points: npt.ArrayLike, weights: npt.ArrayLike, simplices: npt.ArrayLike,
                    y: npt.ArrayLike) -> np.ndarray:
    """Certain signs (0: undecided) of det[[x_i − y, |x_i − y|² − (w_i − w_y)]] over the d + 1
    vertices of each full simplex: the power test of y against the simplex's orthogonal sphere.

    Thesis: §2.1.2 (power distance π_x, the weighted Delaunay complex of Definition 2.13).

    Parameters
    ----------
    points : array_like of float, shape (n, d)
        The points x.
    weights : array_like of float, shape (n,)
        Their weights w_x.
    simplices : array_like of int, shape (m, d + 1)
        Full simplices (point indices).
    y : array_like of int, shape (m,)
        One point index per simplex.

    Returns
    -------
    numpy.ndarray of int8, shape (m,)
        The determinant's sign where certain, else 0.
    """
    return predicate_filters.insphere_filter(_f64(points), _f64(weights), _i64(simplices), _i64(y))


def orient_one(points: npt.ArrayLike, v: npt.ArrayLike) -> int:
    """:func:`orient_filter` for one simplex ``v``.

    Thesis: §2.1.2 (the orientation predicate).

    Parameters
    ----------
    points : array_like of float, shape (n, d)
        The points x.
    v : array_like of int, shape (d + 1,)
        The point indices ``x_0, ..., x_d``.

    Returns
    -------
    int
        +1, −1, or 0 where the filter cannot decide.
    """
    return predicate_filters.orient_one(_f64(points), _i64(v))


def insphere_one(points: npt.ArrayLike, weights: npt.ArrayLike, v: npt.ArrayLike, y: int) -> int:
    """:func:`insphere_filter` for one full simplex ``v`` and point ``y``.

    Thesis: §2.1.2 (the power test).

    Parameters
    ----------
    points : array_like of float, shape (n, d)
        The points x.
    weights : array_like of float, shape (n,)
        Their weights w_x.
    v : array_like of int, shape (d + 1,)
        The simplex's point indices.
    y : int
        The point index tested.

    Returns
    -------
    int
        The determinant's sign where certain, else 0.
    """
    return predicate_filters.insphere_one(_f64(points), _f64(weights), _i64(v), int(y))


def orthoball_float(points: npt.ArrayLike, weights: npt.ArrayLike, simplices: npt.ArrayLike,
                    max_amplification: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Smallest orthogonal spheres of k-simplices (k >= 1) in floating point.

    Thesis: §2.1.2 and Definition 2.14 (the orthogonal sphere giving a simplex's alpha value).

    For each row the system is set up from every vertex in turn until one has Frobenius condition
    number κ <= 10 (else the best is kept): ``A off = rhs`` for k = d, the Gram system
    ``A Aᵀ λ = rhs``, off = Aᵀ λ, for k < d, with rows a_i = x_i − x_o and
    rhs_i = (|a_i|² − w_i + w_o) / 2.

    Parameters
    ----------
    points : array_like of float, shape (n, d)
        The points x.
    weights : array_like of float, shape (n,)
        Their weights w_x.
    simplices : array_like of int, shape (m, k + 1)
        The simplices (point indices).
    max_amplification : float
        Rows whose amplification κ·(1 + (|off|² + |w_o|)/|r²|) exceeds it are flagged.

    Returns
    -------
    centre : numpy.ndarray of float64, shape (m, d)
        The centres.
    r2 : numpy.ndarray of float64, shape (m,)
        The squared radii (NaN where every system was singular).
    err : numpy.ndarray of float64, shape (m,)
        An error estimate of the centre.
    flag : numpy.ndarray of bool, shape (m,)
        The rows whose values must be recomputed exactly.
    """
    return predicate_filters.orthoball_float(_f64(points), _f64(weights), _i64(simplices), float(max_amplification))


def power_filter(points: npt.ArrayLike, weights: npt.ArrayLike, centre: npt.ArrayLike, r2: npt.ArrayLike,
                 err: npt.ArrayLike, faces: npt.ArrayLike, face_idx: npt.ArrayLike, y: npt.ArrayLike) -> np.ndarray:
    """Certain signs (0: undecided) of π_y(c) − r² for the orthoballs (c, r²) of ``faces[face_idx]``.

    Thesis: §2.1.2 and Definition 2.14 (is a face attached by the vertex y of a coface?).

    Parameters
    ----------
    points : array_like of float, shape (n, d)
        The points x.
    weights : array_like of float, shape (n,)
        Their weights w_x.
    centre : array_like of float, shape (f, d)
        The faces' orthoball centres.
    r2 : array_like of float, shape (f,)
        Their squared radii.
    err : array_like of float, shape (f,)
        Error bounds of the centres.
    faces : array_like of int, shape (f, k + 1)
        The faces (point indices).
    face_idx : array_like of int, shape (q,)
        The faces tested.
    y : array_like of int, shape (q,)
        One point index per test.

    Returns
    -------
    numpy.ndarray of int8, shape (q,)
        The sign of π_y(c) − r² where certain, else 0.
    """
    return predicate_filters.power_filter(_f64(points), _f64(weights), _f64(centre), _f64(r2), _f64(err),
                                          _i64(faces), _i64(face_idx), _i64(y))

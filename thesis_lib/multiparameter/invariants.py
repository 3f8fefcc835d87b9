"""Invariants of a bifiltration on a grid: the Hilbert function, the rank invariant, fibered barcodes.

Every invariant is computed from one-parameter filtrations of the bifiltration, each by the
library's persistence engine (Algorithm 2 / Theorem 2.39):

* Hilbert function: HF_k(ε_i, κ_j) = dim H_k(K_{ε_i,κ_j}).  For each κ_j the complex K_{·,κ_j} is a
  filtration in ε, and its barcode gives dim H_k at every ε_i (bars with birth ≤ ε_i < death).
* Rank invariant: rk(a, b) = rank H_k(K_a) → H_k(K_b) for grid points a ≤ b.  Any monotone path from
  a to b gives the same map (the grid commutes), so one L-shaped path — up the column ε_i to κ_{j'},
  then right along κ_{j'} — is a one-parameter filtration through every a = (ε_i, κ_j) with j ≤ j'
  and, later, every b = (ε_{i'}, κ_{j'}) with i' ≥ i; rk(a, b) is the number of its bars alive at
  both (Definition 2.23: the persistent Betti number).  Every pair a ≤ b lies on the path
  (i_a, j_b), so a g × g grid needs g² barcodes.
* Fibered barcode: the filtration along a line ℓ(t) = base + t·direction of positive slope, where σ
  enters at t(σ) = max_c (grade_c(σ) − base_c) / direction_c.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from .._validate import check_int, check_size, parse_field
from ..homology.filtration import Filtration
from ..persistence.barcode import Barcode
from ..persistence.engine import filtration_barcode
from .bifiltration import Bifiltration

__all__ = ["hilbert_function", "rank_invariant", "fibered_barcode", "line_filtration", "check_grid",
           "MAX_GRID_ENTRIES"]

#: largest number of entries an invariant array may have (8 bytes each: 0.8 GB)
MAX_GRID_ENTRIES = 10**8


def check_grid(values: npt.ArrayLike, *, name: str) -> npt.NDArray[np.float64]:
    """A grid axis: a non-empty, finite, strictly increasing 1-D array.

    Thesis: Chapter 5 (the pairs (ε, κ) at which the invariants are evaluated).

    Parameters
    ----------
    values : array_like, shape (k,)
        The grid values.
    name : str
        The axis's name in error messages (``"radii"``, ``"curvatures"``).

    Returns
    -------
    ndarray of float64, shape (k,)
        The values as floats.

    Raises
    ------
    ValueError
        Values that are not numbers, not 1-D, empty, NaN or infinite, or not strictly increasing.
    """
    try:
        g = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError) as err:
        raise ValueError(f"{name} must be an array of numbers: {err}") from None
    if g.ndim != 1 or g.size == 0:
        raise ValueError(f"{name} must be a non-empty 1-D array, got shape {g.shape}")
    if not np.all(np.isfinite(g)):
        raise ValueError(f"{name} has a NaN or infinite value")
    if np.any(np.diff(g) <= 0):
        raise ValueError(f"{name} must be strictly increasing")
    return g


def _check_memory(n_entries: int, what: str) -> None:
    check_size(n_entries, f"{what} entries ({8 * n_entries / 2**30:.3g} GiB)", limit=MAX_GRID_ENTRIES)


def _dims(bif: Bifiltration, dims) -> list[int]:
    top = bif.max_homology_dim
    if dims is None:
        return list(range(top + 1))
    out = [check_int(d, "dims", minimum=0) for d in np.atleast_1d(dims).tolist()]
    for d in out:
        if d > top:
            raise ValueError(f"H_{d} is not determined by this bifiltration (its homology is known up to "
                             f"dimension {top}: build the complex with a larger max_dim)")
    return out


def _betti_at(arr: np.ndarray, at: np.ndarray) -> np.ndarray:
    """Number of bars [b, d) with b ≤ x < d, for each x in ``at``."""
    born = np.searchsorted(np.sort(arr[:, 0]), at, side="right")
    dead = np.searchsorted(np.sort(arr[:, 1]), at, side="right")
    return born - dead


def hilbert_function(bifiltration: Bifiltration, radii: npt.ArrayLike, curvatures: npt.ArrayLike, *,
                     dims: int | Sequence[int] | None = None,
                     coefficients: int | None = None) -> npt.NDArray[np.int64]:
    """dim H_k(K_{ε,κ}) at every point of the grid ``radii`` × ``curvatures``.

    Thesis: Chapter 5 (the homology at each pair (ε, κ)); Definition 2.23 along each row.

    Parameters
    ----------
    bifiltration : Bifiltration
        The one-critical bifiltration.
    radii, curvatures : array_like
        Strictly increasing grid axes (see :func:`check_grid`).
    dims : int or sequence of int, optional
        Homology dimensions (default all the bifiltration determines, 0..max_homology_dim).
    coefficients : int, optional
        A prime p, the field Z/p (default 2).

    Returns
    -------
    ndarray of int64, shape (len(dims), len(radii), len(curvatures))
        Entry ``[a, i, j]`` is dim H_{dims[a]}(K_{ε_i,κ_j}).

    Raises
    ------
    ValueError
        A bad grid, a grid too large for memory (refused with its size), or a dimension the
        bifiltration does not determine.
    """
    radii, curvatures = check_grid(radii, name="radii"), check_grid(curvatures, name="curvatures")
    dims = _dims(bifiltration, dims)
    field = parse_field(coefficients, default=2, field=True)
    _check_memory(len(dims) * radii.size * curvatures.size, "Hilbert-function")
    out = np.zeros((len(dims), radii.size, curvatures.size), dtype=np.int64)
    eps_grades = [g[:, 0] for g in bifiltration.grades]
    for j, k in enumerate(curvatures):
        keep = [g[:, 1] <= k for g in bifiltration.grades]
        if not keep[0].any():
            continue
        bc = filtration_barcode(bifiltration.filtration(eps_grades, keep=keep), field)
        for a, d in enumerate(dims):
            out[a, :, j] = _betti_at(bc.intervals(d), radii)
    return out


def _corner_path_values(te: list[np.ndarray], tk: list[np.ndarray], i: int, j2: int, n_eps: int):
    """Entry positions along the L-shaped path up the column ε_i (κ_0..κ_j2, position = κ index),
    then right along the row κ_j2 (ε_i..ε_last, position j2 + i' − i); a simplex enters at the first
    point of the path above its grades (grid indices ``te``, ``tk``), and is left out when none is."""
    values, keep = [], []
    for e, k in zip(te, tk):
        values.append(np.where(e <= i, k, j2 + e - i).astype(np.float64))
        keep.append((k <= j2) & (e < n_eps))
    return values, keep


def rank_invariant(bifiltration: Bifiltration, radii: npt.ArrayLike, curvatures: npt.ArrayLike, *, dim: int,
                   coefficients: int | None = None) -> npt.NDArray[np.int64]:
    """rank H_dim(K_a) → H_dim(K_b) for all grid points a ≤ b of ``radii`` × ``curvatures``.

    Thesis: Definition 2.23 (the persistent Betti numbers), for two parameters (Chapter 5).

    Parameters
    ----------
    bifiltration : Bifiltration
        The one-critical bifiltration.
    radii, curvatures : array_like
        Strictly increasing grid axes, as in :func:`hilbert_function`.
    dim : int
        The homology dimension; at most the bifiltration's ``max_homology_dim``.
    coefficients : int, optional
        A prime p, the field Z/p (default 2).

    Returns
    -------
    ndarray of int64, shape (len(radii), len(curvatures), len(radii), len(curvatures))
        Entry ``[i, j, i2, j2]`` is the rank from (ε_i, κ_j) to (ε_i2, κ_j2) when i ≤ i2 and
        j ≤ j2, else 0.  The diagonal ``[i, j, i, j]`` is the Hilbert function.

    Raises
    ------
    ValueError
        As :func:`hilbert_function`; the array has (len(radii) · len(curvatures))² entries, so the grid
        is refused sooner (at ``MAX_GRID_ENTRIES``).
    """
    radii, curvatures = check_grid(radii, name="radii"), check_grid(curvatures, name="curvatures")
    dim = _dims(bifiltration, [dim])[0]
    field = parse_field(coefficients, default=2, field=True)
    ne, nk = radii.size, curvatures.size
    _check_memory(ne * nk * ne * nk, "rank-invariant")
    out = np.zeros((ne, nk, ne, nk), dtype=np.int64)
    # grid index of each grade: the first grid value at or above it (len(grid) when above all)
    te = [np.searchsorted(radii, g[:, 0], side="left") for g in bifiltration.grades]
    tk = [np.searchsorted(curvatures, g[:, 1], side="left") for g in bifiltration.grades]
    # One barcode per L-shaped path (up the column ε_i to κ_j2, then right along κ_j2): it holds
    # every a = (ε_i, κ_j), j ≤ j2, before every b = (ε_i2, κ_j2), i2 ≥ i, so the rank from a to b
    # is the number of its bars alive at both (the rank is the same along any path through a and b).
    for i in range(ne):
        for j2 in range(nk):
            values, keep = _corner_path_values(te, tk, i, j2, ne)
            if not keep[0].any():
                continue
            arr = filtration_barcode(bifiltration.filtration(values, keep=keep), field).intervals(dim)
            later = j2 + np.arange(ne - i)  # the positions of b = (ε_i2, κ_j2), i2 = i .. ne − 1
            for j in range(j2 + 1):
                deaths = np.sort(arr[arr[:, 0] <= j, 1])  # bars alive at a = (ε_i, κ_j), position j
                out[i, j, i:, j2] = deaths.shape[0] - np.searchsorted(deaths, later, side="right")
    return out


def _check_line(base, direction) -> tuple[np.ndarray, np.ndarray]:
    b = np.asarray(base, dtype=np.float64)
    d = np.asarray(direction, dtype=np.float64)
    if b.shape != (2,) or d.shape != (2,):
        raise ValueError(f"base and direction must be pairs (ε, κ), got shapes {b.shape} and {d.shape}")
    if not (np.all(np.isfinite(b)) and np.all(np.isfinite(d))):
        raise ValueError("base and direction must be finite")
    if np.any(d <= 0):
        raise ValueError(f"the line must have positive slope: both direction components > 0, got {d.tolist()}")
    return b, d


def line_filtration(bifiltration: Bifiltration, base: npt.ArrayLike, direction: npt.ArrayLike) -> Filtration:
    """The bifiltration restricted to the line ℓ(t) = base + t·direction (positive slope): σ
    enters at t(σ) = max((ε(σ) − base_ε)/direction_ε, (κ(σ) − base_κ)/direction_κ).

    Thesis: Definition 2.22 (a one-parameter filtration), along a line of the (ε, κ) plane (Chapter 5).

    Parameters
    ----------
    bifiltration : Bifiltration
        The one-critical bifiltration.
    base : array_like, shape (2,)
        A point (ε, κ) of the line, finite.
    direction : array_like, shape (2,)
        Its direction; both components > 0 (positive slope).

    Returns
    -------
    Filtration
        Every simplex of the bifiltration, entering at its t(σ) (negative before ``base``).

    Raises
    ------
    ValueError
        ``base`` or ``direction`` not a finite pair, or a direction component ≤ 0.
    """
    b, d = _check_line(base, direction)
    values = [np.max((g - b) / d, axis=1) for g in bifiltration.grades]
    return bifiltration.filtration(values)


def fibered_barcode(bifiltration: Bifiltration, base: npt.ArrayLike, direction: npt.ArrayLike, *,
                    coefficients: int | None = None) -> Barcode:
    """Barcode of the bifiltration along the line base + t·direction (positive slope), in t.

    Thesis: Theorem 2.39 / Algorithm 2 on the filtration of :func:`line_filtration` (Chapter 5: one
    line of the (ε, κ) plane is an ordinary persistence problem).

    Parameters
    ----------
    bifiltration : Bifiltration
        The one-critical bifiltration.
    base, direction : array_like, shape (2,)
        The line, as in :func:`line_filtration`.
    coefficients : int, optional
        A prime p, the field Z/p (default 2).

    Returns
    -------
    Barcode
        Bars in t: a bar [t0, t1) is the segment from base + t0·direction to base + t1·direction of
        the plane.

    Raises
    ------
    ValueError
        A bad line (see :func:`line_filtration`) or coefficients that are not a prime.
    """
    field = parse_field(coefficients, default=2, field=True)
    return filtration_barcode(line_filtration(bifiltration, base, direction), field)

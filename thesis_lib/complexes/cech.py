"""The Čech complex C(X, ε) as a filtration (thesis Definition 2.9)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import miniball
from .._validate import MAX_WORK, check_max_dim, check_radius, parse_points
from ..homology.filtration import Filtration
from ..homology.simplicial import facets, find_rows
from ._flag import check_expansion, edges_within, expand_level, upper_csr
from .rips import check_edges
from .scaling import unscale_values

__all__ = ["cech"]


def _check_work(indptr: np.ndarray, max_dim: int) -> None:
    """Refuse up front a Čech complex whose exact enclosing balls would take more than ``MAX_WORK``.

    The enclosing radius of a simplex of k vertices tries its 2^k subsets, each a k × k solve
    (about 2^k·k³ steps); the candidates of dimension d number at most Σ_v C(deg⁺(v), d) (as in
    ``check_expansion``).  18 points at ε = ∞ with max_dim = 17 are 7·10¹¹ steps (hours), 13 points
    1.2·10⁹ (3 s).
    """
    from scipy.special import comb

    deg = np.diff(indptr)
    top = min(int(max_dim), int(deg.max(initial=0)))
    work = sum(float(np.sum(comb(deg, d, exact=False))) * 2.0 ** (d + 1) * (d + 1) ** 3 for d in range(2, top + 1))
    if work > MAX_WORK:
        raise ValueError(f"the exact enclosing balls of the simplices of dimension 2 to {max_dim} would take about "
                         f"{work:.2g} steps (each simplex of k vertices tries its 2^k subsets), more than the "
                         f"budget of {MAX_WORK:.0e} (about half a minute): lower max_radius or max_dim")


def cech(points: npt.ArrayLike, *, max_radius: float, max_dim: int) -> Filtration:
    """Čech filtration: σ enters at the radius of the smallest ball enclosing its vertices.

    Thesis: Definition 2.9, C(X, ε) = {σ : ∩_{x∈σ} B(x, ε) ≠ ∅}; the balls meet iff σ fits in a
    ball of radius ε (Theorem 2.10 and the Miniball Algorithm).

    Parameters
    ----------
    points : (n, d) array.
    max_radius : largest ε kept (``inf`` keeps every simplex up to ``max_dim``: 2^n of them!).
    max_dim : largest simplex dimension built (>= 0).

    Returns
    -------
    Filtration
        Values are the radii of the smallest enclosing balls (vertices 0, an edge half its
        length); points are scaled by a power of two first, so any magnitude works.

    Warns
    -----
    UserWarning
        ``points`` square, symmetric, with a zero diagonal and no negative entry (it looks like a
        distance matrix, but it is read as n points in R^n).

    Notes
    -----
    Candidates come from the Rips complex R(X, ε) ⊇ C(X, ε) (a set of diameter > 2ε fits in no
    ball of radius ε); each level is expanded from the Čech simplices of the level below and kept
    when its enclosing radius is <= ε.  Vertices enter at 0, an edge at half its length.

    Examples
    --------
    On an equilateral triangle of side 1 the triangle enters the Čech filtration at its circumradius
    1/√3, later than in the Rips filtration (half its diameter, 0.5):

    >>> import numpy as np
    >>> from thesis_lib.complexes import rips
    >>> triangle = [[0.0, 0.0], [1.0, 0.0], [0.5, np.sqrt(3) / 2]]
    >>> c = cech(triangle, max_radius=1.0, max_dim=2)
    >>> c.counts(), np.round(c.values[1], 6).tolist(), round(float(c.values[2][0]), 6)
    ([3, 3, 1], [0.5, 0.5, 0.5], 0.57735)
    >>> round(float(rips(triangle, max_radius=1.0, max_dim=2).values[2][0]), 6)
    0.5
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    cloud = parse_points(points, warn_square=True)  # scaled by a power of two: no overflow/underflow of squares
    pts, e = cloud.scaled, cloud.exponent
    with np.errstate(over="ignore"):
        eps = float(np.ldexp(eps, e))
    n = pts.shape[0]
    simplices = [np.arange(n, dtype=np.int64).reshape(n, 1)]
    values = [np.zeros(n)]
    if max_dim >= 1:
        check_edges(n, 2.0 * eps, points=pts)
        edges, lengths = edges_within(pts, 2.0 * eps)
        simplices.append(edges)
        values.append(lengths * 0.5)
        indptr, indices, vals = upper_csr(n, edges, lengths * 0.5)
        check_expansion(indptr, max_dim)
        _check_work(indptr, max_dim)
        for d in range(2, max_dim + 1):
            if simplices[-1].shape[0] == 0:
                break
            cand, cand_vals = expand_level(simplices[-1], values[-1], indptr, indices, vals)
            radii = np.maximum(miniball.meb_radii(pts, np.ascontiguousarray(cand, dtype=np.int64)), cand_vals)
            keep = radii <= eps
            cand, radii = cand[keep], radii[keep]
            if cand.shape[0]:
                # guard against rounding: a simplex never enters before one of its facets
                idx = find_rows(simplices[-1], facets(cand).reshape(-1, d)).reshape(cand.shape[0], d + 1)
                radii = np.maximum(radii, values[-1][idx].max(axis=1))
            simplices.append(cand)
            values.append(radii)
    values = [unscale_values(v, -e, "radii") for v in values]
    return Filtration(simplices, values, validate=False, truncated_at=max_dim)

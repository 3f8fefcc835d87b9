"""The Čech complex C(X, ε) as a filtration (thesis Definition 2.9)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._validate import as_points, check_max_dim, check_radius
from ..filtration import Filtration
from ..jit import njit
from ..simplicial import facets, find_rows
from ._flag import check_expansion, edges_within, expand_level, upper_csr
from .miniball import meb_radius_small
from .scaling import scaled, unscale_values

__all__ = ["cech"]


@njit(cache=True)
def _meb_radii(points, simplices):
    m, k = simplices.shape
    out = np.empty(m)
    buf = np.empty((k, points.shape[1]))
    for r in range(m):
        for i in range(k):
            buf[i] = points[simplices[r, i]]
        out[r] = meb_radius_small(buf)
    return out


def cech(points: npt.ArrayLike, max_radius: float, max_dim: int) -> Filtration:
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

    Notes
    -----
    Candidates come from the Rips complex R(X, ε) ⊇ C(X, ε) (a set of diameter > 2ε fits in no
    ball of radius ε); each level is expanded from the Čech simplices of the level below and kept
    when its enclosing radius is <= ε.  Vertices enter at 0, an edge at half its length.
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    pts, e = scaled(as_points(points))  # power-of-two scaling: no overflow/underflow of squares
    with np.errstate(over="ignore"):
        eps = float(np.ldexp(eps, e))
    n = pts.shape[0]
    simplices = [np.arange(n, dtype=np.int64).reshape(n, 1)]
    values = [np.zeros(n)]
    if max_dim >= 1:
        edges, lengths = edges_within(pts, 2.0 * eps)
        simplices.append(edges)
        values.append(lengths * 0.5)
        indptr, indices, vals = upper_csr(n, edges, lengths * 0.5)
        check_expansion(indptr, max_dim)
        for d in range(2, max_dim + 1):
            if simplices[-1].shape[0] == 0:
                break
            cand, cand_vals = expand_level(simplices[-1], values[-1], indptr, indices, vals)
            radii = np.maximum(_meb_radii(pts, cand), cand_vals)
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

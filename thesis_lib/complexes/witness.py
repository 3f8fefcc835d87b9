"""Witness complexes W(X, L, ε) (thesis §2.1.2, "The Witness Complex") and JavaPlex's lazy variant.

Notation.  ``m(x)`` is the distance from a point x to its ν-th closest landmark (``nu = ν``), with
``m(x) = 0`` for ν = 0.  The thesis writes m_k(x) for the distance to the (k + 1)-th closest landmark,
so **ν = k + 1**: the thesis's k = 0 is ``nu=1`` (the default), and this ν is JavaPlex's ν.

* :func:`witness` (the thesis's definition): a p-simplex {l_0, ..., l_p} is in W(X, L, ε) when all
  its faces are and some point x ∈ X has max_i |l_i − x| <= ε + m(x).  Its filtration value is
  max(0, min_x (max_i |l_i − x| − m(x))), which already grows with the simplex, so the "all faces"
  condition holds by itself.  One witness sees the whole simplex (a *strong* witness complex with
  plain, not squared, distances).
* :func:`lazy_witness` (JavaPlex ``LazyWitnessStream``): the rule is applied to edges only and the
  complex is the flag complex of those edges (a simplex's value is its largest edge value).

Vertices of both complexes are landmark positions ``0..L-1``: vertex ``i`` is the point
``points[landmarks[i]]``.  Every landmark is its own witness, so vertices enter at 0.  The edge values
and the levels of :func:`witness` are computed in compiled C++ (``src/witness_complex.cpp``).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .._core import witness_complex
from .._validate import as_points, check_indices, check_int, check_max_dim, check_memory, check_radius
from ..homology.filtration import Filtration
from ._flag import flag_levels, matrix_edges
from .scaling import scaled, unscale_values

__all__ = ["witness", "lazy_witness", "witness_offsets"]


def _check_landmarks(pts: np.ndarray, landmarks) -> np.ndarray:
    lm = np.asarray(landmarks)
    if lm.ndim == 1 and lm.size > pts.shape[0]:
        raise ValueError(f"{lm.size} landmarks but only {pts.shape[0]} points")
    return check_indices(lm, pts.shape[0], "landmarks", unique=True)


def _check_nu(nu, n_landmarks: int) -> int:
    nu = check_int(nu, "nu", minimum=0)
    if nu > n_landmarks:
        raise ValueError(f"nu = {nu} exceeds the number of landmarks ({n_landmarks})")
    return nu


def witness_offsets(points: npt.ArrayLike, landmarks: npt.ArrayLike, *, nu: int = 1) -> np.ndarray:
    """The matrix ``D[i, x] = |l_i − x| − m(x)`` (landmark i, point x) both complexes are built from.

    Thesis: §2.1.2, m_k(x) = distance to the (k + 1)-th closest landmark, with ν = k + 1.

    Parameters
    ----------
    points : (N, d) array, the witnesses.
    landmarks : 1-D distinct integer indices into ``points``.
    nu : ν >= 0 (``nu=0``: m(x) = 0).

    Returns
    -------
    ndarray, shape (L, N)

    Examples
    --------
    One row per landmark, one column per point; a landmark witnesses itself at offset 0 (ν = 1):

    >>> import numpy as np
    >>> from thesis_lib.complexes import maxmin_landmarks
    >>> from thesis_lib.datasets import noisy_circle
    >>> points = noisy_circle(40, noise=0.0, seed=0)
    >>> landmarks = maxmin_landmarks(points, n=8, seed=0)
    >>> D = witness_offsets(points, landmarks)
    >>> D.shape, np.round(D[:, landmarks[0]], 6).tolist()
    ((8, 40), [0.0, 1.999913, 1.438732, 1.57225, 0.881402, 0.831226, 1.88231, 1.876168])
    """
    return _offsets(points, landmarks, nu, 0)


def _offsets(points, landmarks, nu, per_pair: int) -> np.ndarray:
    """:func:`witness_offsets`, refused up front when its L × N matrix (twice: the distances and the
    partition finding m(x)), and ``per_pair`` bytes per pair of landmarks for the caller's L × L
    arrays, exceed the memory budget (5·10⁴ landmarks of 2·10⁵ points: 149 GiB)."""
    pts = as_points(points)
    lm = _check_landmarks(pts, landmarks)
    nu = _check_nu(nu, lm.size)
    n_l, n_x = lm.size, pts.shape[0]
    check_memory(16.0 * n_l * n_x + float(per_pair) * n_l * n_l,
                 f"the witness distances of {n_l:,} landmarks and {n_x:,} points")
    pts, e = scaled(pts)  # power-of-two scaling: squared distances neither overflow nor underflow
    lpts = pts[lm]
    # |l - x|² expanded is cheaper but loses accuracy near 0; chunked direct differences instead
    dist = np.empty((lm.size, pts.shape[0]))
    for start in range(0, lm.size, 64):
        block = lpts[start : start + 64]
        dist[start : start + block.shape[0]] = np.sqrt(((block[:, None, :] - pts[None, :, :]) ** 2).sum(-1))
    if nu > 0:
        dist -= np.partition(dist, nu - 1, axis=0)[nu - 1][None, :]
    return unscale_values(dist, -e, "distances")


_SORTED_LIMIT = 20_000_000  # largest L × N for which the per-landmark sorted witness lists are kept


def witness(points: npt.ArrayLike, landmarks: npt.ArrayLike, *, max_radius: float, max_dim: int,
            nu: int = 1) -> Filtration:
    """Witness filtration W(X, L, ε) with the thesis's (strong, un-squared) rule.

    Thesis: §2.1.2 "The Witness Complex" (Definition 2.16 for landmarks), with m_k and ν = k + 1.

    Parameters
    ----------
    points : (N, d) array, the witnesses X (landmarks included).
    landmarks : 1-D integer indices into ``points`` (e.g. from :func:`maxmin_landmarks`); at most N.
    max_radius : largest ε kept.
    max_dim : largest simplex dimension built (>= 0).
    nu : ν = k + 1 >= 0, the landmark rank defining m(x) (``nu=1``: nearest landmark, thesis k = 0).

    Returns
    -------
    Filtration
        On vertices ``0..L-1`` (landmark positions); the value of σ is
        max(0, min_x (max_{l∈σ} |l − x| − m(x))).

    Examples
    --------
    Eight maxmin landmarks on 40 points of the unit circle: the witness complex sees the circle's
    H_1 class from ε ≈ 0.5 on (no triangle at ε ≤ 1 fills it):

    >>> from thesis_lib.complexes import maxmin_landmarks
    >>> from thesis_lib.datasets import noisy_circle
    >>> from thesis_lib.persistence import persistence
    >>> points = noisy_circle(40, noise=0.0, seed=0)
    >>> landmarks = maxmin_landmarks(points, n=8, seed=0)
    >>> w = witness(points, landmarks, max_radius=1.0, max_dim=2)
    >>> w.counts(), persistence(w).intervals(1).round(6).tolist()
    ([8, 22, 20], [[0.503326, inf]])
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    D = np.ascontiguousarray(_offsets(points, landmarks, nu, 16))  # + the L × L edge values and witnesses
    n_l = D.shape[0]
    simplices = [np.arange(n_l, dtype=np.int64).reshape(n_l, 1)]
    values = [np.zeros(n_l)]
    if max_dim >= 1:
        ev, arg = witness_complex.edge_values(D)
        edges, vals = matrix_edges(np.maximum(ev, 0.0), eps)
        simplices.append(edges)
        values.append(vals)
        use_sorted = max_dim >= 2 and D.size <= _SORTED_LIMIT
        if use_sorted:
            order = np.argsort(D, axis=1, kind="stable")
            sorted_d = np.ascontiguousarray(np.take_along_axis(D, order, axis=1))
        else:
            order, sorted_d = np.zeros((1, 1), np.int64), np.zeros((1, 1))
        sorted_lists = witness_complex.SortedDistances(order, sorted_d, use_sorted)
        for _ in range(2, max_dim + 1):
            if simplices[-1].shape[0] == 0:
                break
            s, v = witness_complex.witness_level(np.ascontiguousarray(simplices[-1], dtype=np.int64), D, ev, arg,
                                                 eps, sorted_lists)
            simplices.append(s)
            values.append(v)
    return Filtration(simplices, values, validate=False, truncated_at=max_dim)


def lazy_witness(points: npt.ArrayLike, landmarks: npt.ArrayLike, *, max_radius: float, max_dim: int,
                 nu: int = 1) -> Filtration:
    """Lazy witness filtration (JavaPlex): the witness rule on edges, then the flag complex.

    Thesis: §2.1.2 "The Witness Complex" (edge rule with m_k, ν = k + 1) and the flag-complex
    construction of Definition 2.11's discussion; as JavaPlex's ``LazyWitnessStream`` used in §2.4.

    Parameters
    ----------
    points, landmarks, max_radius, max_dim, nu
        As in :func:`witness`.

    Returns
    -------
    Filtration
        Same vertex numbering as :func:`witness`; a simplex's value is its largest edge value, so
        the lazy complex contains the witness complex at every ε.

    Examples
    --------
    The same landmarks as in :func:`witness`: the lazy complex has the same edges but more triangles,
    which kill the circle's class at ε ≈ 0.86:

    >>> from thesis_lib.complexes import maxmin_landmarks
    >>> from thesis_lib.datasets import noisy_circle
    >>> from thesis_lib.persistence import persistence
    >>> points = noisy_circle(40, noise=0.0, seed=0)
    >>> landmarks = maxmin_landmarks(points, n=8, seed=0)
    >>> lw = lazy_witness(points, landmarks, max_radius=1.0, max_dim=2)
    >>> lw.counts(), persistence(lw).intervals(1).round(6).tolist()
    ([8, 22, 25], [[0.503326, 0.8644]])
    """
    eps = check_radius(max_radius)
    max_dim = check_max_dim(max_dim)
    D = np.ascontiguousarray(_offsets(points, landmarks, nu, 16))
    ev, _ = witness_complex.edge_values(D)
    edges, vals = matrix_edges(np.maximum(ev, 0.0), eps) if max_dim >= 1 else (np.empty((0, 2), np.int64), np.empty(0))
    simplices, values = flag_levels(D.shape[0], edges, vals, max_dim)
    return Filtration(simplices, values, validate=False, truncated_at=max_dim)

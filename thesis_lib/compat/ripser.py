"""ripser.py's ``ripser()`` on thesis_lib's implicit Rips engine: the same call, the same dictionary.

ripser.py (Tralie, Saul and Bar-On 2018) is the de-facto interface for Rips persistence in Python:
``ripser(X)["dgms"]`` feeds persim, scikit-tda and many pipelines.  :func:`ripser` takes the same
arguments in the same order and returns the same keys with the same conventions, computed by
:func:`thesis_lib.persistence.rips_persistence`:

* values are **diameters** (ripser's scale), i.e. twice the thesis's ε (Definition 2.11);
* distances are rounded to float32 first, as ripser.py does, so the diagrams hold the same float32
  values (returned as float64 arrays) and ties, hence the number of bars, agree;
* ``thresh=inf`` on a dense matrix uses the *enclosing radius* min_i max_j d(i, j) as ripser.py
  does: above it the complex is a cone, so the barcode is unchanged, and ``num_edges`` counts the
  edges up to it;
* ``n_perm`` subsamples by ripser.py's greedy permutation (farthest point sampling from point 0);
* ``do_cocycles=True`` gives ripser.py's representative cocycles: the reduction chain of the
  coboundary column that gave each bar, which the engine's reduction is (Ripser's, on the same
  float32 values), so the cocycles agree with ripser.py's wherever the two choose the same pairs.

ripser.py itself is never called here; the tests use it as the reference.
"""

from __future__ import annotations

import functools
import numbers
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt
import scipy.sparse
from scipy.spatial.distance import cdist

from .._validate import (
    MAX_PRIME,
    InvalidTypeError,
    as_distance_matrix,
    as_points,
    check_flag,
    check_int,
    is_prime,
    warn_user,
)
from ..persistence import rips_persistence

__all__ = ["ripser"]

#: scikit-learn's metric names (ripser.py's ``pairwise_distances``) that scipy spells differently
SKLEARN_ALIASES = {"manhattan": "cityblock", "l1": "cityblock", "l2": "euclidean"}

SUPPORTED_METRICS = ("'euclidean', 'precomputed' (X is a distance matrix), any metric name of "
                     "scipy.spatial.distance.cdist ('cityblock', 'chebyshev', 'cosine', 'minkowski', ...), "
                     "scikit-learn's 'manhattan', 'l1', 'l2', or a callable of two rows")


def ripser(
    X: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray,
    maxdim: int = 1,
    thresh: float = np.inf,
    coeff: int = 2,
    distance_matrix: bool = False,
    do_cocycles: bool = False,
    metric: str | Callable[[np.ndarray, np.ndarray], float] = "euclidean",
    n_perm: int | None = None,
) -> dict[str, Any]:
    """Persistence diagrams of the Rips filtration of ``X``, as ripser.py's ``ripser(X, ...)`` returns them.

    Thesis: Definition 2.11 (Rips), Algorithm 2.

    The signature mirrors ripser.py's on purpose, positional parameters included (unlike the rest of
    thesis_lib, whose options are keyword-only), so that ``from thesis_lib.compat import ripser``
    replaces ``from ripser import ripser`` without changing a call.

    Parameters
    ----------
    X : array_like, shape (n, d) or (n, n), or scipy.sparse matrix
        Points (one per row), or with ``distance_matrix=True`` a symmetric distance matrix: dense
        (a non-zero diagonal gives the vertices' births, as ripser.py reads it) or scipy.sparse
        (its stored off-diagonal entries are the only edges; an entry stored only below the diagonal
        is an edge here, ripser.py reads only the entries above it).  An off-diagonal 0 in a dense
        matrix with births is an edge of length 0 here; ripser.py, which stores such a matrix as a
        sparse one, drops it.  A vertex born above ``thresh`` is not in the complex here (ripser.py
        keeps its H0 class).
    maxdim : int
        Homology is computed in dimensions 0 .. ``maxdim`` (``thesis_lib``'s ``max_dim = maxdim + 1``).
    thresh : float
        Largest diameter: simplices of diameter ≤ ``thresh`` (rounded to float32, as ripser.py) are
        built; default ∞.  Non-negative.
    coeff : int
        A prime p: homology over the field Z/p.
    distance_matrix : bool
        Whether ``X`` is a distance matrix.
    do_cocycles : bool
        Also compute a representative cocycle of each bar of dimension >= 1 (``"cocycles"`` below).
    metric : str or callable
        How distances between the rows of points are computed (ignored for a distance matrix):
        ``"euclidean"`` (default), ``"precomputed"`` (``X`` is a distance matrix), a metric name of
        ``scipy.spatial.distance.cdist``, scikit-learn's ``"manhattan"``, ``"l1"``, ``"l2"``, or a
        callable of two rows.
    n_perm : int, optional
        Compute on a greedy permutation (farthest point sampling starting at row 0) of this many
        points; None or 0: all points.  Not for a sparse distance matrix.

    Returns
    -------
    dict
        ripser.py's dictionary:

        * ``"dgms"``: list of ``maxdim + 1`` float64 arrays of shape (k, 2), the (birth, death)
          diameters of dimension 0 .. maxdim (the essential H0 class as ``[0, inf]``); rows in
          ripser.py's order (H0 by death, higher dimensions by decreasing birth; rows with equal
          keys may be listed in another order).
        * ``"cocycles"``: ``maxdim + 1`` lists, empty without ``do_cocycles``; with it,
          ``cocycles[k][i]`` is a representative cocycle of the bar ``dgms[k][i]`` (k >= 1;
          ``cocycles[0]`` is empty, as in ripser.py): an int64 array of shape (m, k + 2), a row per
          simplex, its k + 1 vertices (decreasing; indices of the rows of ``X``, also with
          ``n_perm``, as ripser.py gives them) then its coefficient in 1 .. p − 1.  It is the
          reduction chain of the bar's coboundary column (``rips_persistence(..., cocycles=True)``):
          restricted to the simplices of diameter <= t it is a cocycle, not a coboundary, for every
          t from the birth to just before the death.
        * ``"num_edges"``: the number of edges {i, j} with distance ≤ the threshold, as ripser.py
          counts them (dense input with ``thresh=inf``: up to the enclosing radius; a pair stored
          twice in a sparse matrix counts once).
        * ``"dperm2all"``: the distances used: the full (n, n) matrix (``X`` itself for a distance
          matrix), or (n_perm, n) from the permutation's points to all points.
        * ``"idx_perm"``: int64 indices of the points used (``arange(n)`` without a permutation).
        * ``"r_cover"``: the permutation's covering radius (0.0 without one).

    Warns
    -----
    UserWarning
        Points in a square array (did you mean ``distance_matrix=True``?) or with more columns than
        rows (did you mean to transpose?), as ripser.py warns.

    Raises
    ------
    ValueError
        A negative, NaN or non-number ``maxdim``/``thresh``; ``coeff`` not a prime; an unknown
        ``metric``; ``n_perm`` negative, above the number of points, or given with a sparse matrix;
        a distance matrix that is not square, symmetric, or has NaN or negative entries; a sparse
        ``X`` without ``distance_matrix=True``; points that are not a finite (n, d) array;
        ``do_cocycles`` not True or False.

    Examples
    --------
    >>> import numpy as np
    >>> circle = np.column_stack([np.cos(np.arange(12) * np.pi / 6), np.sin(np.arange(12) * np.pi / 6)])
    >>> result = ripser(circle)
    >>> sorted(result)
    ['cocycles', 'dgms', 'dperm2all', 'idx_perm', 'num_edges', 'r_cover']
    >>> [d.shape for d in result["dgms"]]
    [(12, 2), (1, 2)]
    >>> bool(np.allclose(result["dgms"][1], [[0.5176381, 1.7320508]]))
    True
    >>> square = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    >>> ripser(square, do_cocycles=True)["cocycles"][1][0].tolist()  # the side from vertex 1 to vertex 0
    [[1, 0, 1]]
    """
    maxdim = check_int(maxdim, "maxdim", minimum=0)
    thresh = _float32_threshold(thresh)
    coeff = _check_coeff(coeff)
    do_cocycles = check_flag(do_cocycles, "do_cocycles")
    if n_perm is not None:
        n_perm = check_int(n_perm, "n_perm", minimum=0)
    if isinstance(metric, str) and metric == "precomputed":
        distance_matrix = True

    if scipy.sparse.issparse(X):
        if not distance_matrix:
            raise ValueError("X is a scipy.sparse matrix: only a distance matrix can be sparse; "
                             "pass distance_matrix=True")
        if n_perm:
            raise ValueError("the greedy permutation (n_perm) is not supported for sparse distance matrices "
                             "(as in ripser.py); pass a dense matrix or n_perm=None")
        if len(X.shape) != 2 or X.shape[0] != X.shape[1]:
            raise ValueError(f"distance_matrix must be a square (n, n) matrix, got shape {X.shape}")
        dm, dperm2all, rows = X, X, None
    elif distance_matrix:
        dm = as_distance_matrix(X)
        rows = dm.__getitem__
        dperm2all = X if isinstance(X, np.ndarray) else dm
    else:
        points = as_points(X)
        if points.shape[0] == points.shape[1]:
            warn_user("X is a square array but distance_matrix=False: its rows are read as points; "
                      "did you mean distance_matrix=True?")
        elif points.shape[0] < points.shape[1]:
            warn_user("X has more columns than rows: its rows are read as points; did you mean to transpose it?")
        distance = _metric(metric)
        rows = functools.partial(_row, points, metric=distance)
        dm = dperm2all = cdist(points, points, distance)
        np.fill_diagonal(dm, 0.0)  # a point is at distance 0 from itself (cosine's rounding aside), as ripser.py

    n = dm.shape[0]
    if n_perm and n_perm > n:
        raise ValueError(f"n_perm = {n_perm} is greater than the number of points ({n})")
    idx_perm, r_cover = np.arange(n), 0.0
    if n_perm and n_perm < n:
        idx_perm, r_cover, dperm2all = _greedy_permutation(rows, n_perm)
        dm = dperm2all[:, idx_perm]

    engine_input, threshold, num_edges = _float32_filtration(dm, thresh)
    result = rips_persistence(distance_matrix=engine_input, max_radius=threshold / 2, max_dim=maxdim + 1,
                              coefficients=coeff, cocycles=do_cocycles)
    barcode, reps = result if do_cocycles else (result, {})
    dgms, cocycles = [], []
    for k, dgm in enumerate(barcode.to_diagrams(scale="diameter")):
        order = _ripser_order(dgm, k)
        dgms.append(dgm[order])
        cocycles.append([_original_vertices(reps[k][i], idx_perm) for i in order] if k in reps else [])
    return {"dgms": dgms, "cocycles": cocycles, "num_edges": num_edges,
            "dperm2all": dperm2all, "idx_perm": idx_perm, "r_cover": r_cover}


def _float32_threshold(thresh) -> float:
    """ripser.py's ``thresh`` as the float32 value its C++ core compares with (inf stays inf)."""
    if isinstance(thresh, bool) or not isinstance(thresh, numbers.Real):
        raise InvalidTypeError(f"thresh must be a number (a diameter; inf for no bound), got {thresh!r}")
    t = float(thresh)
    if t != t:
        raise ValueError("thresh is NaN")
    if t < 0:
        raise ValueError(f"thresh is the largest diameter and must be >= 0, got {t}")
    with np.errstate(over="ignore"):
        return float(np.float32(t))


def _check_coeff(coeff) -> int:
    p = check_int(coeff, "coeff")
    if p > MAX_PRIME:
        raise ValueError(f"coeff = {p} is too large: a prime p <= {MAX_PRIME} is needed")
    if not is_prime(p):
        raise ValueError(f"coeff must be a prime p (homology over the field Z/p), got {p}")
    return p


def _metric(metric) -> str | Callable:
    """The metric for ``scipy.spatial.distance.cdist``, checked on two points."""
    if callable(metric):
        return metric
    if not isinstance(metric, str):
        raise InvalidTypeError(f"metric must be a string or a callable; supported: {SUPPORTED_METRICS}")
    name = SKLEARN_ALIASES.get(metric, metric)
    try:
        cdist(np.zeros((1, 1)), np.ones((1, 1)), name)
    except ValueError:
        raise ValueError(f"unknown metric {metric!r}; supported: {SUPPORTED_METRICS}") from None
    return name


def _row(points: np.ndarray, i: int, metric) -> np.ndarray:
    """Distances from point ``i`` to every point (0 at ``i`` itself), as ripser.py's ``dpoint2pointcloud``."""
    row = cdist(points[i : i + 1], points, metric)[0]
    row[i] = 0.0
    return row


def _greedy_permutation(rows: Callable[[int], np.ndarray], n_perm: int) -> tuple[np.ndarray, float, np.ndarray]:
    """ripser.py's ``get_greedy_perm``: farthest point sampling from point 0 on distance rows.

    Returns the chosen indices (int64), the covering radius (the largest distance from a point to
    the chosen ones) and the (n_perm, n) distances from the chosen points to all points.
    """
    idx_perm = np.zeros(n_perm, dtype=np.int64)
    ds = np.array(rows(0), dtype=np.float64)
    dperm2all = [ds]
    for i in range(1, n_perm):
        idx_perm[i] = int(np.argmax(ds))
        dperm2all.append(np.asarray(rows(idx_perm[i]), dtype=np.float64))
        ds = np.minimum(ds, dperm2all[-1])
    return idx_perm, float(np.max(ds)), np.array(dperm2all)


def _float32_filtration(dm, thresh: float):
    """The distances rounded to float32 (as ripser.py), the threshold its core uses and its edge count.

    A dense matrix with a zero diagonal and ``thresh = inf`` is cut at the enclosing radius
    min_i max_j d(i, j) (ripser.py's shortcut: from there on the complex is a cone, the barcode
    does not change).
    """
    with np.errstate(over="ignore"):
        if scipy.sparse.issparse(dm):
            coo = dm.tocoo()
            data = np.asarray(coo.data, dtype=np.float32).astype(np.float64)
            edge = (coo.row != coo.col) & (data <= thresh)
            low, high = np.minimum(coo.row, coo.col)[edge], np.maximum(coo.row, coo.col)[edge]
            pairs = np.unique(low.astype(np.int64) * coo.shape[0] + high)
            return scipy.sparse.coo_matrix((data, (coo.row, coo.col)), shape=coo.shape), thresh, int(pairs.size)
        d32 = np.asarray(dm, dtype=np.float32).astype(np.float64)
    if thresh == np.inf and not np.diagonal(dm).any():
        thresh = float(np.min(np.max(d32, axis=1)))
    return d32, thresh, int(np.count_nonzero(d32[np.triu_indices(d32.shape[0], 1)] <= thresh))


def _ripser_order(dgm: np.ndarray, dim: int) -> np.ndarray:
    """The order of the rows in ripser.py: H0 by death (the essential bars last), higher dimensions by
    decreasing birth (the order in which its reduction finds them)."""
    return np.argsort(dgm[:, 1], kind="stable") if dim == 0 else np.argsort(-dgm[:, 0], kind="stable")


def _original_vertices(cocycle: np.ndarray, idx_perm: np.ndarray) -> np.ndarray:
    """A cocycle on the subsample's vertices with the indices of the points they are (as ripser.py)."""
    out = cocycle.copy()
    out[:, :-1] = idx_perm[cocycle[:, :-1]]
    return out

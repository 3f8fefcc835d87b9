"""Curvature of a point cloud with no surface: the least-squares shape operator of §3.3.4 on the k
nearest neighbours of each point.

For a point x_i of a sample of a hypersurface of R^{n+1} (n = 1: a curve in the plane):

1. the normal n_i is the direction of least variance of its k nearest neighbours (the smallest
   principal axis; its sign is arbitrary), the tangent space the other n axes;
2. each neighbour x_j gives a normal-curvature estimate κ_ij = 2 (x_j − x_i)·n_i / ‖x_j − x_i‖²
   (equation (3.24): the circle through x_i and x_j tangent to the tangent space; its reciprocal
   radius, as in :mod:`.shape`) in the direction d_ij, the unit projection of x_j − x_i on the
   tangent space;
3. S is the symmetric n × n matrix minimising Σ_j w_ij (d_ijᵀ S d_ij − κ_ij)² (§3.3.4), with
   w_ij = 1 or a Gaussian of the distance.

Then H = tr S / n and, for n = 2, K = det S.  As the sign of n_i is arbitrary, |H| is meaningful at
every point and H only up to sign; K (n even) does not depend on the sign.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from scipy.spatial import cKDTree

from .._validate import as_points, check_choice, check_int
from .shape import ShapeOperator

__all__ = ["knn_shape_operator", "knn_curvature", "neighbour_mean", "KNN_WEIGHTS"]

KNN_WEIGHTS = ("uniform", "gaussian")


def knn_shape_operator(points: npt.ArrayLike, *, k: int = 16, neighbour_weights: str = "uniform") -> ShapeOperator:
    """Least-squares shape operator at every point from its ``k`` nearest neighbours.

    Thesis: §3.3.4 "Estimating the Shape Operator" (normal curvatures (3.24) fitted by least
    squares), on a k-neighbourhood instead of a mesh's 1-ring.

    Parameters
    ----------
    points : array_like, shape (N, n + 1)
        Samples of a hypersurface (n >= 1), at least 3, finite, no duplicates.
    k : int, default 16
        Number of neighbours: at least n (n + 1) / 2 + n (enough to determine S and the normal) and
        fewer than N.
    neighbour_weights : {"uniform", "gaussian"}, default "uniform"
        Weights w_ij of the neighbours in the least-squares fit: ``"gaussian"`` is
        exp(−‖x_j − x_i‖² / h²), h the distance to the k-th neighbour.

    Returns
    -------
    ShapeOperator
        ``tensor`` (N, n, n) symmetric S in the tangent ``basis`` (N, n, n + 1), and the unit
        ``normal`` (N, n + 1) (sign arbitrary: S changes sign with it).

    Raises
    ------
    ValueError
        On invalid or duplicate points, points in R^1, a ``k`` out of range or unknown
        ``neighbour_weights``.
    """
    pts = as_points(points, min_points=3, allow_duplicates=False)
    npts, d = pts.shape
    n = d - 1
    if n < 1:
        raise ValueError("points must lie in R^d with d >= 2 (a curve in the plane or a hypersurface)")
    need = n * (n + 1) // 2 + n
    k = check_int(k, "k", minimum=need)
    if k >= npts:
        raise ValueError(f"k = {k} neighbours need more than {k} points, got {npts}")
    check_choice(neighbour_weights, KNN_WEIGHTS, "neighbour_weights")
    dist, nb = cKDTree(pts).query(pts, k=k + 1)
    diff = pts[nb[:, 1:]] - pts[:, None, :]  # (N, k, d): x_j - x_i
    centred = pts[nb] - pts[nb].mean(axis=1, keepdims=True)
    _, vec = np.linalg.eigh(np.einsum("nka,nkb->nab", centred, centred))  # ascending eigenvalues
    normal = vec[:, :, 0]
    basis = np.transpose(vec[:, :, 1:], (0, 2, 1))  # (N, n, d)
    sq = np.einsum("nka,nka->nk", diff, diff)
    kappa = 2.0 * np.einsum("nka,na->nk", diff, normal) / sq
    coords = np.einsum("nka,nma->nkm", diff, basis)  # tangent coordinates of x_j - x_i
    coords /= np.linalg.norm(coords, axis=2, keepdims=True) + 1e-300
    # unknowns: S_aa, and sqrt(2) S_ab (a < b), so the minimum-norm solution is the minimum
    # Frobenius-norm S (as in .shape)
    iu = np.triu_indices(n)
    scale = np.where(iu[0] == iu[1], 1.0, np.sqrt(2.0))
    phi = coords[:, :, iu[0]] * coords[:, :, iu[1]] * scale  # (N, k, n(n+1)/2)
    if neighbour_weights == "gaussian":
        h2 = dist[:, -1:] ** 2
        w = np.exp(-dist[:, 1:] ** 2 / h2)
    else:
        w = np.ones_like(kappa)
    mat = np.einsum("nk,nka,nkb->nab", w, phi, phi)
    rhs = np.einsum("nk,nka,nk->na", w, phi, kappa)
    sol = np.einsum("nab,nb->na", np.linalg.pinv(mat, rcond=1e-10), rhs) / scale
    tensor = np.zeros((npts, n, n))
    tensor[:, iu[0], iu[1]] = sol
    tensor[:, iu[1], iu[0]] = sol
    return ShapeOperator(tensor, basis, normal)


def knn_curvature(points: npt.ArrayLike, *, curvature: str = "mean", k: int = 16,
                  neighbour_weights: str = "uniform") -> np.ndarray:
    """|H| = |tr S| / n (``curvature="mean"``) or K = det S (``"gaussian"``, n = 2) at every point, from
    :func:`knn_shape_operator`.

    Thesis: §3.3.4 (the shape operator's trace and determinant: H = tr S / n, K = det S).

    Parameters
    ----------
    points : array_like, shape (N, n + 1)
        Samples of a hypersurface (n >= 1), at least 3, finite, no duplicates.
    curvature : {"mean", "gaussian"}, default "mean"
        Which curvature; ``"gaussian"`` needs n = 2.
    k : int, default 16
        Number of neighbours, as in :func:`knn_shape_operator`.
    neighbour_weights : {"uniform", "gaussian"}, default "uniform"
        Weights of the neighbours in the fit, as in :func:`knn_shape_operator`.

    Returns
    -------
    ndarray of float64, shape (N,)
        |H| (unsigned, the normal's sign being arbitrary) or K at each point.

    Raises
    ------
    ValueError
        As :func:`knn_shape_operator`; also on an unknown ``curvature`` or ``"gaussian"`` with n ≠ 2.
    """
    so = knn_shape_operator(points, k=k, neighbour_weights=neighbour_weights)
    n = so.tensor.shape[1]
    if curvature == "mean":
        return np.abs(np.trace(so.tensor, axis1=1, axis2=2)) / n
    if curvature == "gaussian":
        if n != 2:
            raise ValueError(f"the Gaussian curvature det S is for surfaces in R^3 (n = 2), got n = {n}")
        return np.linalg.det(so.tensor)
    raise ValueError(f"curvature must be 'mean' or 'gaussian', got {curvature!r}")


def neighbour_mean(points: npt.ArrayLike, values: npt.ArrayLike, *, k: int = 16) -> np.ndarray:
    """The mean of ``values`` over each point and its ``k - 1`` nearest neighbours: a local average
    of a noisy per-point curvature estimate.

    Thesis: §3.3.1–§3.3.2 (an integrated curvature is turned into a value at p by averaging over a
    region around p).

    Parameters
    ----------
    points : array_like, shape (N, d)
        The points.
    values : array_like, shape (N,)
        One value per point.
    k : int, default 16
        Size of each neighbourhood, the point itself included; 1 <= k <= N.

    Returns
    -------
    ndarray of float64, shape (N,)
        The mean of ``values`` over each point's k nearest points (itself among them).

    Raises
    ------
    ValueError
        On invalid points, ``values`` not of shape (N,), or ``k`` out of range.
    """
    pts = as_points(points)
    v = np.asarray(values, dtype=np.float64)
    if v.shape != (pts.shape[0],):
        raise ValueError(f"values must have one entry per point ({pts.shape[0]}), got shape {v.shape}")
    k = check_int(k, "k", minimum=1)
    if k > pts.shape[0]:
        raise ValueError(f"k = {k} exceeds the number of points {pts.shape[0]}")
    nb = cKDTree(pts).query(pts, k=k)[1].reshape(len(pts), -1)
    return v[nb].mean(axis=1)

"""Compiled floating-point filters for the predicates of :mod:`.predicates` (numba, any dimension).

Each kernel computes, row by row, a determinant by Laplace expansion over subsets of rows together
with its permanent (the same expansion on absolute values), and returns the sign where the value
exceeds the proven rounding-error bound ``(e·k + (k² + 2k)·u)·1.01·permanent`` (e the entries' own
relative error), 0 where it does not: those rows go to exact arithmetic.  The orthoball kernel
solves the small linear system of the smallest orthogonal sphere from the best-conditioned vertex
and flags the rows whose error amplification is too large to trust.
"""

from __future__ import annotations

import numpy as np

from ..jit import njit
from ._pivot import pivot_row

__all__ = ["orient_filter", "insphere_filter", "orient_one", "insphere_one", "orthoball_float", "power_filter"]

_U = 2.0**-53
_TINY = 1e-290


@njit(cache=True)
def _popcount(x):
    c = 0
    while x:
        x &= x - 1
        c += 1
    return c


@njit(cache=True)
def _det_perm(mat, mag, k, dbuf, pbuf):
    """Determinant and permanent of the leading k × k block (subset dynamic programme)."""
    for mask in range(1, 1 << k):
        c = _popcount(mask)
        j = c - 1
        if c == 1:
            i = 0
            while not (mask >> i) & 1:
                i += 1
            dbuf[mask] = mat[i, 0]
            pbuf[mask] = mag[i, 0]
            continue
        acc = 0.0
        pacc = 0.0
        pos = 0
        for i in range(k):
            if (mask >> i) & 1:
                sub = mask & ~(1 << i)
                term = mat[i, j] * dbuf[sub]
                if (pos + j) % 2:
                    term = -term
                acc += term
                pacc += mag[i, j] * pbuf[sub]
                pos += 1
        dbuf[mask] = acc
        pbuf[mask] = pacc
    full = (1 << k) - 1
    return dbuf[full], pbuf[full]


@njit(cache=True)
def _signed(det, perm, k, entry_error):
    bound = (entry_error * k + (k * k + 2 * k) * _U) * 1.01 * perm + _TINY
    if det > bound:
        return 1
    if det < -bound:
        return -1
    return 0


@njit(cache=True)
def _workspace(m, k):
    """Zeroed signs for ``m`` rows, and the ``k × k`` matrices and buffers of :func:`_det_perm`."""
    return np.zeros(m, dtype=np.int8), np.empty((k, k)), np.empty((k, k)), np.empty(1 << k), np.empty(1 << k)


@njit(cache=True)
def orient_filter(points, simplices):
    """Certain signs of det[x_i − x_0] (0 where undecided) for rows of ``simplices`` (m, d + 1)."""
    m = simplices.shape[0]
    d = points.shape[1]
    out, mat, mag, dbuf, pbuf = _workspace(m, d)
    for r in range(m):
        o = simplices[r, 0]
        for i in range(d):
            v = simplices[r, i + 1]
            for t in range(d):
                x = points[v, t] - points[o, t]
                mat[i, t] = x
                mag[i, t] = abs(x)
        det, perm = _det_perm(mat, mag, d, dbuf, pbuf)
        out[r] = _signed(det, perm, d, _U)
    return out


@njit(cache=True)
def insphere_filter(points, weights, simplices, y):
    """Certain signs (0: undecided) of det[[x_i − y, |x_i − y|² − (w_i − w_y)]] over the d + 1
    vertices of each full simplex: the power test of y against the simplex's orthogonal sphere."""
    m = simplices.shape[0]
    d = points.shape[1]
    k = d + 1
    out, mat, mag, dbuf, pbuf = _workspace(m, k)
    for r in range(m):
        q = y[r]
        for i in range(k):
            v = simplices[r, i]
            sq = 0.0
            for t in range(d):
                x = points[v, t] - points[q, t]
                mat[i, t] = x
                mag[i, t] = abs(x)
                sq += x * x
            mat[i, d] = sq - (weights[v] - weights[q])
            mag[i, d] = sq + abs(weights[v]) + abs(weights[q])
        det, perm = _det_perm(mat, mag, k, dbuf, pbuf)
        out[r] = _signed(det, perm, k, (d + 4) * _U)
    return out


@njit(cache=True)
def orient_one(points, v):
    """:func:`orient_filter` for one simplex ``v`` (d + 1 point indices)."""
    return orient_filter(points, v.reshape(1, -1))[0]


@njit(cache=True)
def insphere_one(points, weights, v, y):
    """:func:`insphere_filter` for one full simplex ``v`` and point ``y``."""
    yy = np.empty(1, dtype=np.int64)
    yy[0] = y
    return insphere_filter(points, weights, v.reshape(1, -1), yy)[0]


@njit(cache=True)
def _invert(mat, k, inv, work):
    """Gauss–Jordan with partial pivoting; False if (numerically) singular."""
    for i in range(k):
        for j in range(k):
            work[i, j] = mat[i, j]
            inv[i, j] = 1.0 if i == j else 0.0
    for col in range(k):
        piv, best = pivot_row(work, col, k)
        if best == 0.0:
            return False
        if piv != col:
            for j in range(k):
                t = work[col, j]
                work[col, j] = work[piv, j]
                work[piv, j] = t
                t = inv[col, j]
                inv[col, j] = inv[piv, j]
                inv[piv, j] = t
        p = work[col, col]
        for j in range(k):
            work[col, j] /= p
            inv[col, j] /= p
        for r in range(k):
            if r != col:
                f = work[r, col]
                if f != 0.0:
                    for j in range(k):
                        work[r, j] -= f * work[col, j]
                        inv[r, j] -= f * inv[col, j]
    return True


@njit(cache=True)
def orthoball_float(points, weights, simplices, max_amplification):
    """Smallest orthogonal spheres of k-simplices (k >= 1) in floating point.

    For each row the system is set up from every vertex in turn until one has Frobenius condition
    number κ <= 10 (else the best is kept): ``A off = rhs`` for k = d, the Gram system
    ``A Aᵀ λ = rhs``, off = Aᵀ λ, for k < d, with rows a_i = x_i − x_o and
    rhs_i = (|a_i|² − w_i + w_o) / 2.  Returns centre (m, d), r² (m,), an error estimate of the
    centre (m,) and a flag (m,) for rows whose amplification κ·(1 + (|off|² + |w_o|)/|r²|)
    exceeds ``max_amplification`` (their values must be recomputed exactly).
    """
    m, w = simplices.shape
    d = points.shape[1]
    k = w - 1
    centre = np.empty((m, d))
    r2 = np.empty(m)
    err = np.empty(m)
    flag = np.zeros(m, dtype=np.bool_)
    a = np.empty((k, d))
    rhs = np.empty(k)
    mat = np.empty((k, k))
    inv = np.empty((k, k))
    work = np.empty((k, k))
    best_inv = np.empty((k, k))
    best_a = np.empty((k, d))
    best_rhs = np.empty(k)
    for r in range(m):
        best_kappa = np.inf
        best_o = 0
        for oi in range(w):
            o = simplices[r, oi]
            row = 0
            for i in range(w):
                if i == oi:
                    continue
                v = simplices[r, i]
                sq = 0.0
                for t in range(d):
                    x = points[v, t] - points[o, t]
                    a[row, t] = x
                    sq += x * x
                rhs[row] = 0.5 * (sq - weights[v] + weights[o])
                row += 1
            if k == d:
                for i in range(k):
                    for j in range(k):
                        mat[i, j] = a[i, j]
            else:
                for i in range(k):
                    for j in range(k):
                        s = 0.0
                        for t in range(d):
                            s += a[i, t] * a[j, t]
                        mat[i, j] = s
            if not _invert(mat, k, inv, work):
                continue
            n1 = 0.0
            n2 = 0.0
            for i in range(k):
                for j in range(k):
                    n1 += mat[i, j] * mat[i, j]
                    n2 += inv[i, j] * inv[i, j]
            kappa = np.sqrt(n1 * n2)
            if kappa < best_kappa:
                best_kappa = kappa
                best_o = o
                for i in range(k):
                    best_rhs[i] = rhs[i]
                    for j in range(k):
                        best_inv[i, j] = inv[i, j]
                    for t in range(d):
                        best_a[i, t] = a[i, t]
            if best_kappa <= 10.0:
                break
        if best_kappa == np.inf:
            flag[r] = True
            for t in range(d):
                centre[r, t] = points[simplices[r, 0], t]
            r2[r] = np.nan
            err[r] = np.inf
            continue
        off2 = 0.0
        asq = 0.0
        for t in range(d):
            c = 0.0
            for i in range(k):
                lam = 0.0
                for j in range(k):
                    lam += best_inv[i, j] * best_rhs[j]
                if k == d:
                    if i == t:
                        c = lam
                else:
                    c += lam * best_a[i, t]
            centre[r, t] = points[best_o, t] + c
            off2 += c * c
        for i in range(k):
            for t in range(d):
                asq += best_a[i, t] * best_a[i, t]
        w0 = weights[best_o]
        rr = off2 - w0
        r2[r] = rr
        amp = np.inf if rr == 0.0 else best_kappa * (1.0 + (off2 + abs(w0)) / abs(rr))
        flag[r] = not (amp <= max_amplification)
        err[r] = 16.0 * _U * best_kappa * np.sqrt(off2 + asq)
    return centre, r2, err, flag


@njit(cache=True)
def power_filter(points, weights, centre, r2, err, faces, face_idx, y):
    """Certain signs (0: undecided) of π_y(c) − r² for the orthoballs (c, r²) of ``faces[face_idx]``,
    given the centres' error bounds ``err``."""
    m = face_idx.shape[0]
    d = points.shape[1]
    out = np.zeros(m, dtype=np.int8)
    for r in range(m):
        f = face_idx[r]
        q = y[r]
        x0 = faces[f, 0]
        dist2 = 0.0
        off2 = 0.0
        for t in range(d):
            dc = centre[f, t] - points[q, t]
            dist2 += dc * dc
            do = centre[f, t] - points[x0, t]
            off2 += do * do
        power = dist2 - weights[q] - r2[f]
        e = err[f]
        scale = dist2 + abs(weights[q]) + abs(r2[f]) + off2
        bound = 4.0 * (np.sqrt(dist2) + np.sqrt(off2) + e) * e + 16.0 * _U * scale + _TINY
        if power > bound:
            out[r] = 1
        elif power < -bound:
            out[r] = -1
    return out

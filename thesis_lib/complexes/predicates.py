"""Robust geometric predicates for the Delaunay and alpha constructions (thesis §2.1.2).

Every decision of the (weighted) Delaunay triangulation and of the alpha values is a sign: the
orientation of d + 1 points, whether a point lies inside the orthogonal sphere of a simplex (the
power test), whether a face is attached.  Floating point gets these wrong when the answer is close
to zero (noisy grids, thin triangles, co-circular points).  This module follows CGAL, the library
behind GUDHI, in three layers:

1. **A floating-point filter with a proven error bound.**  Each determinant is computed by Laplace
   expansion together with its *permanent* (the same expansion on absolute values); the rounding
   error is at most ``c · u · permanent`` (u = 2⁻⁵³, c from the number of operations), so a value
   larger than that has a certain sign.  Vectorised over all simplices.
2. **Exact integer arithmetic** where the filter cannot decide.  A float is m·2^e exactly, so a few
   points' coordinates times a common power of two are Python integers; determinants of integers
   are exact, and a circumcentre or squared radius is a ratio of two such integers, rounded once
   (Python's integer division is correctly rounded).  Vectorised over object arrays.
3. **Symbolic perturbation** for exact ties (d + 2 points on one sphere): the lift |x|² − w_x of
   each point is raised by an infinitesimal that is larger for lexicographically larger points, as
   CGAL's ``perturbed_side_of_positive_sphere`` does, so the triangulation is the one GUDHI builds.

:class:`Geometry` holds the points (already scaled by a power of two, see :mod:`.scaling`), their
weights and their lexicographic ranks, and answers the predicates for arrays of simplices.
"""

from __future__ import annotations

import math
from itertools import combinations
from math import factorial

import numpy as np
import numpy.typing as npt

from .filters import insphere_filter, insphere_one, orient_filter, orient_one

__all__ = ["Geometry", "ScalarPredicates", "expand_det", "signs_of", "UNIT"]

#: unit roundoff of float64
UNIT = 2.0**-53

#: the refusal when an exact orthogonal sphere (a radius or a centre) leaves float64's range
_RANGE_MESSAGE = ("an orthogonal sphere of these weighted points has a squared radius or centre beyond "
                  "float64's range (about 1.8e308) at the points' scale (largest weight {biggest:.3g} after "
                  "scaling the largest coordinate to [0.5, 1)): the weights are too large for the spread of "
                  "the points; rescale the weights or the points")


# ------------------------------------------------------------------------------ determinants
def expand_det(mat: np.ndarray) -> np.ndarray:
    """Determinants of ``(m, k, k)`` matrices by Laplace expansion along columns over row subsets.

    k·2^(k−1) products; works on float arrays and on object arrays of Python integers (exact).

    Parameters
    ----------
    mat : numpy.ndarray, shape (m, k, k)
        Float or object (Python int) entries.

    Returns
    -------
    numpy.ndarray, shape (m,)
        The determinants, of the dtype of ``mat`` (ones for ``k = 0``).
    """
    m, k, _ = mat.shape
    if k == 0:
        return np.ones(m, dtype=mat.dtype)
    det = {(i,): mat[:, i, 0] for i in range(k)}
    for j in range(1, k):
        nd = {}
        for rows in combinations(range(k), j + 1):
            acc = None
            for pos, i in enumerate(rows):
                term = mat[:, i, j] * det[rows[:pos] + rows[pos + 1 :]]
                if (pos + j) % 2:
                    term = -term
                acc = term if acc is None else acc + term
            nd[rows] = acc
        det = nd
    return det[tuple(range(k))]


def _sign(x) -> int:
    return (x > 0) - (x < 0)


def _signs(values: np.ndarray) -> np.ndarray:
    """Signs of an object array of Python integers."""
    return np.array([_sign(v) for v in values.tolist()], dtype=np.int8)


def _dyadic(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each float as m · 2^(−e) exactly, m an odd int64 (or 0, with e = 0): (m, e).

    Odd mantissas keep the common scale of a batch small: integer coordinates stay themselves.
    """
    mant, ex = np.frexp(values)
    m = (mant * 2.0**53).astype(np.int64)
    e = np.where(m == 0, 0, 53 - ex.astype(np.int64))
    low = m & -m  # the lowest set bit: 2^(trailing zeros)
    zeros = np.where(m == 0, 0, np.frexp(low.astype(np.float64))[1] - 1)
    return m >> zeros, e - zeros


def signs_of(values: np.ndarray) -> np.ndarray:
    """Signs of exact integers (the determinants of :func:`expand_det`).

    Parameters
    ----------
    values : numpy.ndarray
        An int64 array, or an object array of Python integers.

    Returns
    -------
    numpy.ndarray
        The signs, −1, 0 or 1, as int8, in the shape of ``values``.
    """
    if values.dtype == object:
        return _signs(values)
    return np.sign(values).astype(np.int8)


def _det_perm_scalar(m: list[list[float]], a: list[list[float]]) -> tuple[float, float]:
    """Determinant and permanent (on the magnitudes ``a``) by expansion along the first column
    (explicit for k <= 4, the same operations as the compiled filters)."""
    k = len(m)
    if k == 1:
        return m[0][0], a[0][0]
    if k == 2:
        return m[0][0] * m[1][1] - m[1][0] * m[0][1], a[0][0] * a[1][1] + a[1][0] * a[0][1]
    if k == 3:
        (m0, m1, m2), (a0, a1, a2) = m, a
        d12 = m1[1] * m2[2] - m2[1] * m1[2]
        d02 = m0[1] * m2[2] - m2[1] * m0[2]
        d01 = m0[1] * m1[2] - m1[1] * m0[2]
        p12 = a1[1] * a2[2] + a2[1] * a1[2]
        p02 = a0[1] * a2[2] + a2[1] * a0[2]
        p01 = a0[1] * a1[2] + a1[1] * a0[2]
        return m0[0] * d12 - m1[0] * d02 + m2[0] * d01, a0[0] * p12 + a1[0] * p02 + a2[0] * p01
    if k == 4:
        (m0, m1, m2, m3), (a0, a1, a2, a3) = m, a
        # 2 x 2 minors of columns 2, 3, then 3 x 3 minors of columns 1..3, then column 0
        d = {}
        p = {}
        rows, arows = (m0, m1, m2, m3), (a0, a1, a2, a3)
        for i, j in ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)):
            d[i, j] = rows[i][2] * rows[j][3] - rows[j][2] * rows[i][3]
            p[i, j] = arows[i][2] * arows[j][3] + arows[j][2] * arows[i][3]
        det = per = 0.0
        for i in range(4):
            j, k2, l2 = [r for r in range(4) if r != i]
            minor = rows[j][1] * d[k2, l2] - rows[k2][1] * d[j, l2] + rows[l2][1] * d[j, k2]
            pminor = arows[j][1] * p[k2, l2] + arows[k2][1] * p[j, l2] + arows[l2][1] * p[j, k2]
            det += (-rows[i][0] if i % 2 else rows[i][0]) * minor
            per += arows[i][0] * pminor
        return det, per
    det = per = 0.0
    for i in range(k):
        sub = [row[1:] for j, row in enumerate(m) if j != i]
        suba = [row[1:] for j, row in enumerate(a) if j != i]
        dd, pp = _det_perm_scalar(sub, suba)
        det += (-m[i][0] if i % 2 else m[i][0]) * dd
        per += a[i][0] * pp
    return det, per


def _int_det(rows: list[list[int]]) -> int:
    """Exact determinant of a square integer matrix (Bareiss elimination)."""
    a = [list(r) for r in rows]
    n = len(a)
    sign, prev = 1, 1
    for k in range(n - 1):
        if a[k][k] == 0:
            for i in range(k + 1, n):
                if a[i][k] != 0:
                    a[k], a[i] = a[i], a[k]
                    sign = -sign
                    break
            else:
                return 0
        akk = a[k][k]
        for i in range(k + 1, n):
            aik = a[i][k]
            ri, rk = a[i], a[k]
            for j in range(k + 1, n):
                ri[j] = (ri[j] * akk - aik * rk[j]) // prev
        prev = akk
    return sign * a[n - 1][n - 1]


class ScalarPredicates:
    """Scalar robust predicates on a few points at a time (pure Python: no per-call numpy overhead).

    A float filter with the same proven bound as :mod:`.filters`; exact integers (the points of one
    predicate brought to a common power-of-two scale) where it cannot decide; CGAL's perturbation
    for ties.  Points are indices into the :class:`~.predicates.Geometry`.
    """

    def __init__(self, geo: Geometry):
        self.d = geo.d
        self.geo = geo
        self._x: dict[int, tuple[float, ...]] = {}
        self._w: dict[int, float] = {}
        self._dyadic: dict[int, tuple[list[int], list[int], int, int]] = {}

    def x(self, i: int) -> tuple[float, ...]:
        """The coordinates of point ``i`` as Python floats (cached).

        Parameters
        ----------
        i : int
            A point index of the geometry.

        Returns
        -------
        tuple of float
            Its ``d`` (scaled) coordinates.
        """
        got = self._x.get(i)
        if got is None:
            got = self._x[i] = tuple(self.geo.points[i].tolist())
            self._w[i] = float(self.geo.weights[i])
        return got

    def w(self, i: int) -> float:
        """The weight of point ``i`` as a Python float (cached with its coordinates, :meth:`x`).

        Parameters
        ----------
        i : int
            The point.

        Returns
        -------
        float
            Its weight, scaled by the square of the coordinates' power of two.
        """
        self.x(i)
        return self._w[i]

    def ints(self, ids: list[int]) -> tuple[list[list[int]], list[int]]:
        """Coordinates ×2^K and weights ×4^K of the points as Python integers (common K).

        Parameters
        ----------
        ids : list of int
            Point indices of the geometry.

        Returns
        -------
        x : list of list of int
            The coordinates of each point times 2^K.
        w : list of int
            The weight of each point times 4^K (K the smallest that makes every value an integer).
        """
        data = []
        k = 0
        for i in ids:
            got = self._dyadic.get(i)
            if got is None:
                geo = self.geo
                got = self._dyadic[i] = (geo.mantissas[i].tolist(), geo.exponents[i].tolist(),
                                         int(geo.weight_mantissas[i]), int(geo.weight_exponents[i]))
            data.append(got)
            k = max(k, max(got[1]), (got[3] + 1) // 2)
        x = [[m << (k - e) for m, e in zip(mr, er)] for mr, er, _, _ in data]
        w = [wm << (2 * k - we) for _, _, wm, we in data]
        return x, w

    def orient(self, v: list[int]) -> int:
        """Exact sign of det[x_i − x_0] over d + 1 points.

        Parameters
        ----------
        v : list of int
            The d + 1 point indices ``x_0, ..., x_d``, in this order.

        Returns
        -------
        int
            +1, 0 or −1 (float filter first, exact integers where it cannot decide).
        """
        if self.d > 3:  # the compiled filter beats Python's expansion of a 5 x 5 (or larger) determinant
            sign = int(orient_one(self.geo.points, np.array(v, dtype=np.int64)))
            return sign if sign else self.orient_exact(v)
        x0 = self.x(v[0])
        m = [[a - b for a, b in zip(self.x(u), x0)] for u in v[1:]]
        det, per = _det_perm_scalar(m, [[abs(t) for t in row] for row in m])
        k = self.d
        if abs(det) > (k + k * k + 2 * k) * UNIT * 1.01 * per + 1e-290:
            return 1 if det > 0 else -1
        return self.orient_exact(v)

    def orient_exact(self, v: list[int]) -> int:
        """:meth:`orient` in exact integer arithmetic alone.

        Parameters
        ----------
        v : list of int
            The d + 1 point indices.

        Returns
        -------
        int
            +1, 0 or −1.
        """
        x, _ = self.ints(list(v))
        return _sign(_int_det([[a - b for a, b in zip(xi, x[0])] for xi in x[1:]]))

    def outside(self, v: list[int], y: int) -> bool:
        """Is y outside the orthogonal sphere of the positively oriented full simplex v (perturbed)?

        Parameters
        ----------
        v : list of int
            The d + 1 point indices of a full simplex with :meth:`orient` ``+1``.
        y : int
            The point index tested.

        Returns
        -------
        bool
            True when π_y > r² of the orthogonal sphere of ``v``; exact ties are decided by CGAL's
            symbolic perturbation.
        """
        d = self.d
        cof_y = -1 if d % 2 == 0 else 1  # (−1)^(d+1) orient(v), orient(v) = +1
        if d > 3:
            sign = int(insphere_one(self.geo.points, self.geo.weights, np.array(v, dtype=np.int64), y))
            if sign:
                return sign == cof_y
            return self._outside_exact(v, y)
        xy, wy = self.x(y), self.w(y)
        m, a = [], []
        for u in v:
            diff = [s - t for s, t in zip(self.x(u), xy)]
            sq = sum(t * t for t in diff)
            wu = self.w(u)
            m.append(diff + [sq - (wu - wy)])
            a.append([abs(t) for t in diff] + [sq + abs(wu) + abs(wy)])
        det, per = _det_perm_scalar(m, a)
        k = d + 1
        if abs(det) > ((d + 4) * k + k * k + 2 * k) * UNIT * 1.01 * per + 1e-290:
            return (1 if det > 0 else -1) == cof_y
        return self._outside_exact(v, y)

    def _outside_exact(self, v: list[int], y: int) -> bool:
        d = self.d
        cof_y = -1 if d % 2 == 0 else 1
        pts = list(v) + [y]
        x, w = self.ints(pts)
        rows = []
        for xu, wu in zip(x[:-1], w[:-1]):
            diff = [s - t for s, t in zip(xu, x[-1])]
            rows.append(diff + [sum(t * t for t in diff) - (wu - w[-1])])
        p = _sign(_int_det(rows))
        if p != 0:
            return p == cof_y
        rank = self.geo.rank
        for j in sorted(range(d + 2), key=lambda t: -int(rank[pts[t]])):
            rest = x[:j] + x[j + 1 :]
            c = (-1) ** j * _sign(_int_det([[a - b for a, b in zip(xi, rest[0])] for xi in rest[1:]]))
            if c != 0:
                return c == cof_y
        raise AssertionError("the perturbation always decides")  # pragma: no cover


class Geometry:
    """Points (scaled by a power of two), weights and lexicographic ranks, with robust predicates.

    Thesis: §2.1.2 (weighted points, power distance π_x(u) = |u − x|² − w_x; the Delaunay complex
    of Definition 2.13 is decided by signs of such distances).

    Parameters
    ----------
    points : (n, d) float64 array.
    weights : (n,) float64 array (zeros for unweighted points).
    """

    def __init__(self, points: npt.NDArray[np.float64], weights: npt.NDArray[np.float64]):
        self.points = np.ascontiguousarray(points, dtype=np.float64)
        self.weights = np.ascontiguousarray(weights, dtype=np.float64)
        self.n, self.d = self.points.shape
        self.weighted = bool(np.any(self.weights != 0))
        order = np.lexsort(self.points.T[::-1])  # lexicographic: first coordinate first
        self.order = order
        self.rank = np.empty(self.n, dtype=np.int64)
        self.rank[order] = np.arange(self.n)
        self.mantissas, self.exponents = _dyadic(self.points)
        self.weight_mantissas, self.weight_exponents = _dyadic(self.weights)
        self.exact_rows = 0
        self.scalar = ScalarPredicates(self)

    # -------------------------------------------------------------------------- exact integers
    def _scale(self, idx: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
        """``(idx, pe, we, K)``: the indices as int64, their coordinate and weight exponents, and the
        one K that makes every coordinate ×2^K and weight ×4^K of the batch an integer."""
        idx = np.asarray(idx, dtype=np.int64)
        pe, we = self.exponents[idx], self.weight_exponents[idx]
        return idx, pe, we, int(max(pe.max(initial=0), (int(we.max(initial=0)) + 1) // 2))

    def ints(self, idx: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
        """Coordinates ×2^K and weights ×4^K of the points ``idx`` (any shape) as Python integers.

        Parameters
        ----------
        idx : numpy.ndarray of int
            Point indices, any shape.

        Returns
        -------
        x : numpy.ndarray of object, shape ``idx.shape + (d,)``
            Coordinates times 2^K (Python ints).
        w : numpy.ndarray of object, shape ``idx.shape``
            Weights times 4^K (Python ints).
        K : int
            One exponent for the whole batch (so every value is an integer).
        """
        idx, pe, we, k = self._scale(idx)
        x = self.mantissas[idx].astype(object) * np.power(2, (k - pe).astype(object))
        w = self.weight_mantissas[idx].astype(object) * np.power(2, (2 * k - we).astype(object))
        return x, w, k

    def small_ints(self, idx: np.ndarray, degree: int, terms: float) -> tuple[np.ndarray, np.ndarray] | None:
        """:meth:`ints` as int64 arrays when a polynomial of the coordinates (degree ``degree`` in
        coordinates and weights counted twice, at most ``terms`` terms of coefficient 1, each factor
        a difference of two values) is exact in int64; else None (use :meth:`ints`).

        Grids and other data on a coarse dyadic lattice take this path: their exact predicates run as
        vectorised integer arithmetic instead of Python integers.

        Parameters
        ----------
        idx : numpy.ndarray of int
            Point indices, any shape.
        degree : int
            Degree of the polynomial to be evaluated exactly.
        terms : float
            A bound on its number of terms.

        Returns
        -------
        tuple of numpy.ndarray or None
            ``(x, w)``: int64 coordinates ×2^K (shape ``idx.shape + (d,)``) and weights ×4^K (shape
            ``idx.shape``); None when K > 60 or the polynomial could overflow int64.
        """
        idx, pe, we, k = self._scale(idx)
        if k > 60:
            return None
        scale = 2.0**k
        big = max(float(np.abs(self.points[idx]).max(initial=0.0)) * scale,
                  float(np.sqrt(np.abs(self.weights[idx]).max(initial=0.0))) * scale, 1.0)
        # margin for the float estimate of the bound; in logarithms, so weights near the float range
        # (1e150 and up, raised to the degree) mean "not int64", never an OverflowError
        if math.log2(terms) + degree * math.log2(2.0 * big) >= 60.0:
            return None
        x = self.mantissas[idx] << (k - pe)
        w = self.weight_mantissas[idx] << (2 * k - we)
        return x, w

    # -------------------------------------------------------------------------- orientation
    def orientation(self, simplices: np.ndarray) -> np.ndarray:
        """Exact signs (+1, 0, −1) of det[x_i − x_0] for full simplices ``(m, d + 1)``.

        Parameters
        ----------
        simplices : numpy.ndarray of int, shape (m, d + 1)
            Full simplices (point indices).

        Returns
        -------
        numpy.ndarray of int8, shape (m,)
            The signs: the float filter, then exact integers for the rows it cannot decide.
        """
        sign = orient_filter(self.points, np.ascontiguousarray(simplices, dtype=np.int64))
        unsure = np.flatnonzero(sign == 0)
        if unsure.size:
            sign[unsure] = self.orientation_exact(simplices[unsure])
        return sign

    def orientation_exact(self, simplices: np.ndarray) -> np.ndarray:
        """:meth:`orientation` in exact integer arithmetic.

        Parameters
        ----------
        simplices : numpy.ndarray of int, shape (m, d + 1)
            As for :meth:`orientation`.

        Returns
        -------
        numpy.ndarray of int8
            One sign (+1, 0 or −1) per row, each decided exactly.
        """
        self.exact_rows += len(simplices)
        d = self.d
        small = self.small_ints(simplices, d, float(factorial(d)))
        x = self.ints(simplices)[0] if small is None else small[0]
        return signs_of(expand_det(x[:, 1:, :] - x[:, :1, :]))

    # -------------------------------------------------------------------------- power test
    def outside(self, simplices: np.ndarray, y: np.ndarray, orient: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """For each full simplex and point ``y``: is π_y > r² (y outside the orthogonal sphere, its
        lifted point above the simplex's lifted hyperplane), and was it an exact tie before the
        perturbation?  ``orient`` are the simplices' orientation signs (nonzero).

        Ties are broken by CGAL's symbolic perturbation (the lift of a lexicographically larger
        point is raised more), so the answer is always decided.

        Parameters
        ----------
        simplices : numpy.ndarray of int, shape (m, d + 1)
            Full simplices (point indices).
        y : numpy.ndarray of int, shape (m,)
            One point index per simplex.
        orient : numpy.ndarray of int, shape (m,)
            The simplices' orientation signs (nonzero).

        Returns
        -------
        outside : numpy.ndarray of bool, shape (m,)
            π_y > r² after the perturbation.
        tie : numpy.ndarray of bool, shape (m,)
            The rows that were exact ties (π_y = r²) before it.
        """
        sign = insphere_filter(self.points, self.weights, np.ascontiguousarray(simplices, dtype=np.int64),
                               np.ascontiguousarray(y, dtype=np.int64))
        # the homogeneous determinant grows with y's lift iff cof_y = (−1)^(d+1) orient(σ) > 0
        cof_y = np.where(self.d % 2, 1, -1) * orient.astype(np.int64)
        out = sign * cof_y > 0
        tie = np.zeros(len(y), dtype=bool)
        unsure = np.flatnonzero(sign == 0)
        if unsure.size:
            out[unsure], tie[unsure] = self.outside_exact(simplices[unsure], y[unsure], cof_y[unsure])
        return out, tie

    def outside_exact(self, simplices: np.ndarray, y: np.ndarray, cof_y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`outside` in exact integer arithmetic, with the symbolic perturbation for ties.

        Parameters
        ----------
        simplices, y : numpy.ndarray of int
            As for :meth:`outside`.
        cof_y : numpy.ndarray of int, shape (m,)
            ``(−1)^(d+1)`` times each simplex's orientation sign: the sign with which the
            determinant grows with y's lift.

        Returns
        -------
        outside, tie : numpy.ndarray of bool
            As for :meth:`outside`.
        """
        self.exact_rows += len(simplices)
        allp = np.column_stack([simplices, y])
        d = self.d
        # the lifted determinant: (d + 1)! terms of degree d + 2, the lift a sum of d + 2 squares
        small = self.small_ints(allp, d + 2, float(factorial(d + 1) * (d + 2)))
        x, w = self.ints(allp)[:2] if small is None else small
        diff = x[:, :-1, :] - x[:, -1:, :]
        lift = (diff * diff).sum(axis=2) - (w[:, :-1] - w[:, -1:])
        p = signs_of(expand_det(np.concatenate([diff, lift[..., None]], axis=2)))
        out = p * cof_y > 0
        tie = p == 0
        rows = np.flatnonzero(tie)
        if rows.size:
            # det M(δ) = det M + Σ_x δ_x cof_x; the largest δ belongs to the lexicographically
            # largest point, and cof_j = (−1)^j orient(the other d + 1 points, in order)
            xt = x[rows]
            cof = np.empty((len(rows), self.d + 2), dtype=np.int8)
            for j in range(self.d + 2):
                rest = np.delete(xt, j, axis=1)
                cof[:, j] = (-1) ** j * signs_of(expand_det(rest[:, 1:, :] - rest[:, :1, :]))
            by_rank = np.argsort(-self.rank[allp[rows]], axis=1)
            ordered = np.take_along_axis(cof, by_rank, axis=1)
            first = ordered[np.arange(len(rows)), np.argmax(ordered != 0, axis=1)]
            out[rows] = first * cof_y[rows] > 0
        return out, tie

    # -------------------------------------------------------------------------- orthoballs
    def _ball_numbers(self, x: np.ndarray, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Integers (num, g) with centre = x0 + num / (2g) and r² = |num|² / (4g²) − w0 for the
        smallest orthogonal spheres of the integer points ``x`` (m, j + 1, d) with weights ``w``."""
        a = x[:, 1:, :] - x[:, :1, :]  # (m, j, d)
        rhs2 = (a * a).sum(axis=2) - w[:, 1:] + w[:, :1]  # twice the right-hand side
        j = a.shape[1]
        if j == self.d:  # A off = rhs / 2: Cramer on A directly
            g = expand_det(a)
            num = np.empty((len(x), self.d), dtype=object)
            for c in range(self.d):
                mat = a.copy()
                mat[:, :, c] = rhs2
                num[:, c] = expand_det(mat)
            return num, g
        gram = (a[:, :, None, :] * a[:, None, :, :]).sum(axis=3)  # off = Σ λ_i a_i with G λ = rhs / 2
        g = expand_det(gram)
        num = np.zeros((len(x), self.d), dtype=object)
        for i in range(j):
            mat = gram.copy()
            mat[:, :, i] = rhs2
            num += expand_det(mat)[:, None] * a[:, i, :]
        return num, g

    def orthoballs_exact(self, simplices: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Centres and squared radii of the smallest orthogonal spheres, correctly rounded.

        Parameters
        ----------
        simplices : numpy.ndarray of int, shape (m, k + 1)
            ``k``-simplices (k <= d), affinely independent.

        Returns
        -------
        centre : numpy.ndarray of float64, shape (m, d)
            The centres (scaled coordinates).
        r2 : numpy.ndarray of float64, shape (m,)
            The squared radii (``−w`` for a vertex).
        """
        self.exact_rows += len(simplices)
        m = len(simplices)
        if simplices.shape[1] == 1:
            return self.points[simplices[:, 0]].copy(), -self.weights[simplices[:, 0]]
        x, w, k = self.ints(simplices)
        num, g = self._ball_numbers(x, w)
        x0, w0 = x[:, 0, :], w[:, 0]
        den = (4 * g * g).tolist()
        top = ((num * num).sum(axis=1) - 4 * g * g * w0).tolist()
        cnum = (2 * g[:, None] * x0 + num).tolist()
        cden = (2 * g).tolist()
        try:
            r2 = np.array([t / (dd << (2 * k)) for t, dd in zip(top, den)], dtype=np.float64)
            centre = np.array([[c / (dd << k) for c in row] for row, dd in zip(cnum, cden)], dtype=np.float64)
        except OverflowError:
            raise ValueError(_RANGE_MESSAGE.format(biggest=float(np.abs(self.weights).max(initial=0.0)))) from None
        return centre.reshape(m, self.d), r2

    def power_exact(self, faces: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Exact signs of π_y(c) − r² for the smallest orthogonal spheres (c, r²) of ``faces``.

        Parameters
        ----------
        faces : numpy.ndarray of int, shape (m, k + 1)
            ``k``-simplices (point indices), affinely independent.
        y : numpy.ndarray of int, shape (m,)
            One point index per face.

        Returns
        -------
        numpy.ndarray of int8, shape (m,)
            +1, 0 or −1 (negative: y attaches the face).
        """
        self.exact_rows += len(faces)
        allp = np.column_stack([faces, y])
        x, w, _ = self.ints(allp)
        if faces.shape[1] == 1:  # a vertex: c = x0, r² = −w0
            diff = x[:, 0, :] - x[:, 1, :]
            return _signs((diff * diff).sum(axis=1) - w[:, 1] + w[:, 0])
        num, g = self._ball_numbers(x[:, :-1], w[:, :-1])
        # (2g)² (π_y(c) − r²) = |2g (x0 − y) + num|² − 4g² w_y − (|num|² − 4g² w0)
        v = 2 * g[:, None] * (x[:, 0, :] - x[:, -1, :]) + num
        g4 = 4 * g * g
        return _signs((v * v).sum(axis=1) - g4 * w[:, -1] - (num * num).sum(axis=1) + g4 * w[:, 0])

"""An exact incremental (Bowyer–Watson) regular triangulation for small point sets, any dimension.

Used where Qhull's floating-point triangulation could not be certified (see :mod:`.triangulation`):
on the few points around a near-degenerate spot, or on all points when Qhull fails.  Every
decision goes through the robust predicates of :class:`~.predicates.Geometry` (filtered, exact,
symbolically perturbed), so the result is the unique regular triangulation of the perturbed
points: the one CGAL (and so GUDHI) builds.

The triangulation is stored as lists: ``verts[s]`` the d + 1 vertices of simplex ``s`` (−1 is the
point at infinity; finite simplices are positively oriented, an infinite simplex is oriented so
that putting a point beyond its hull facet in place of −1 gives a positive orientation) and
``nbrs[s][i]`` the simplex across the facet opposite ``verts[s][i]``.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .predicates import Geometry, ScalarPredicates

__all__ = ["exact_triangulation", "DegenerateInput"]


class DegenerateInput(ValueError):
    """The points lie in a hyperplane: they have no full-dimensional triangulation."""


class _Triangulation:
    def __init__(self, pred: ScalarPredicates):
        self.pred = pred
        self.d = pred.d
        self.verts: list[list[int]] = []
        self.nbrs: list[list[int]] = []
        self.alive: list[bool] = []
        self.last = 0

    # ------------------------------------------------------------------ predicates
    def orient(self, v: list[int]) -> int:
        return self.pred.orient(v)

    def conflict(self, s: int, p: int) -> bool:
        """Is point p in conflict with simplex s (inside its orthogonal sphere, or beyond its hull facet)?"""
        v = self.verts[s]
        if -1 not in v:
            return not self.pred.outside(v, p)
        i = v.index(-1)
        q = list(v)
        q[i] = p
        o = self.orient(q)
        if o != 0:
            return o > 0
        # p on the hyperplane of the hull facet: decided by the finite simplex behind it (as CGAL)
        return self.conflict(self.nbrs[s][i], p)

    # ------------------------------------------------------------------ construction
    def new(self, v: list[int]) -> int:
        self.verts.append(v)
        self.nbrs.append([-1] * (self.d + 1))
        self.alive.append(True)
        return len(self.verts) - 1

    def start(self, first: list[int]) -> None:
        """One positively oriented simplex and its d + 1 infinite neighbours."""
        v = list(first)
        if self.orient(v) < 0:
            v[0], v[1] = v[1], v[0]
        s = self.new(v)
        for i in range(self.d + 1):
            w = list(v)
            w[i] = -1
            # the outside of facet i is opposite v[i]: swapping two finite vertices makes it positive
            a, b = [j for j in range(self.d + 1) if j != i][:2]
            w[a], w[b] = w[b], w[a]
            t = self.new(w)
            self.nbrs[s][i] = t
            self.nbrs[t][w.index(-1)] = s
        # infinite simplices are glued to each other along facets through the point at infinity
        self.link([s + 1 + i for i in range(self.d + 1)])
        self.last = s

    def link(self, simplices: list[int]) -> None:
        """Set the neighbours of ``simplices`` across facets they share with one another."""
        seen: dict[tuple[int, ...], tuple[int, int]] = {}
        for s in simplices:
            v = self.verts[s]
            for i in range(self.d + 1):
                key = tuple(sorted(v[:i] + v[i + 1 :]))
                other = seen.pop(key, None)
                if other is None:
                    seen[key] = (s, i)
                else:
                    t, j = other
                    self.nbrs[s][i] = t
                    self.nbrs[t][j] = s

    def locate(self, p: int) -> int | None:
        """A simplex in conflict with p (None: p is hidden), by a visibility walk."""
        s = self.last if self.alive[self.last] else self.alive.index(True)
        for step in range(20 * len(self.verts) + 100):
            v = self.verts[s]
            if -1 in v:
                if self.conflict(s, p):
                    return s
                s = self.nbrs[s][v.index(-1)]
                continue
            moved = False
            for j in range(self.d + 1):
                i = (j + step) % (self.d + 1)  # rotate the first facet tried (the walk terminates
                q = list(v)  # on regular triangulations for any choice)
                q[i] = p
                if self.orient(q) < 0:  # p strictly beyond facet i
                    s = self.nbrs[s][i]
                    moved = True
                    break
            if not moved:
                return s if self.conflict(s, p) else None
        # the walk did not settle (it cannot in exact arithmetic): scan
        for s, ok in enumerate(self.alive):
            if ok and self.conflict(s, p):
                return s
        return None

    def insert(self, p: int) -> None:
        s0 = self.locate(p)
        if s0 is None:
            return  # hidden: its lifted point lies above the lower hull
        region = {s0}
        stack = [s0]
        tested: dict[int, bool] = {s0: True}
        boundary: list[tuple[int, int]] = []
        while stack:
            s = stack.pop()
            for i, t in enumerate(self.nbrs[s]):
                if t in region:
                    continue
                hit = tested.get(t)
                if hit is None:
                    hit = tested[t] = self.conflict(t, p)
                if hit:
                    region.add(t)
                    stack.append(t)
                else:
                    boundary.append((s, i))
        created = []
        for s, i in boundary:
            v = list(self.verts[s])
            v[i] = p
            n = self.new(v)
            t = self.nbrs[s][i]
            self.nbrs[n][i] = t
            self.nbrs[t][self.nbrs[t].index(s)] = n
            created.append(n)
        self.link(created)
        for s in region:
            self.alive[s] = False
        self.last = created[0]


def _first_simplex(geo: Geometry, ids: np.ndarray) -> list[int]:
    """d + 1 affinely independent points of ``ids`` (greedy on floats, checked exactly)."""
    pts = geo.points[ids]
    chosen = [0]
    basis = np.zeros((0, geo.d))
    for _ in range(geo.d):
        diff = pts - pts[chosen[0]]
        resid = diff - (diff @ basis.T) @ basis if basis.size else diff
        norms = np.linalg.norm(resid, axis=1)
        norms[chosen] = -1.0
        j = int(np.argmax(norms))
        if norms[j] <= 0:
            raise DegenerateInput("the points lie in a hyperplane")
        chosen.append(j)
        basis = np.vstack([basis, resid[j] / norms[j]])
    first = [int(ids[j]) for j in chosen]
    return first


def _line(geo: Geometry, ids: np.ndarray) -> np.ndarray:
    """The regular triangulation of points on a line: the lower hull of (x, x² − w), exactly."""
    order = ids[np.argsort(geo.points[ids, 0], kind="stable")]
    hull: list[int] = []
    for r in order.tolist():
        while len(hull) >= 2:
            a, b = hull[-2], hull[-1]
            out, _ = geo.outside(np.array([[a, r]]), np.array([b]), np.ones(1, dtype=np.int8))
            if out[0]:
                hull.pop()  # b lies above the segment a r: hidden
            else:
                break
        hull.append(r)
    if len(hull) < 2:
        raise DegenerateInput("need two points")
    arr = np.array(hull, dtype=np.int64)
    return np.sort(np.column_stack([arr[:-1], arr[1:]]), axis=1)


def exact_triangulation(geo: Geometry, ids: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """The regular triangulation of the points ``ids`` of ``geo``, decided exactly.

    Thesis: Definition 2.13 (Delaunay complex) for weighted points (§2.1.2).

    Parameters
    ----------
    geo : the points, weights and predicates.
    ids : indices of the points to triangulate (at least d + 1, not all in a hyperplane).

    Returns
    -------
    simplices : (m, d + 1) int64, each row ascending: the finite top simplices.
    neighbours : (m, d + 1) int64, row index of the simplex across the facet opposite each vertex
        of the *sorted* row (−1 on the convex hull).

    Raises
    ------
    DegenerateInput
        If the points lie in a hyperplane.
    """
    ids = np.asarray(ids, dtype=np.int64)
    if geo.d == 1:
        tri = _line(geo, ids)
        m = len(tri)
        nb = np.full((m, 2), -1, dtype=np.int64)
        nb[1:, 1] = np.arange(m - 1)  # across the left vertex lies the previous segment
        nb[:-1, 0] = np.arange(1, m)
        return tri, nb
    first = _first_simplex(geo, ids)
    pred = geo.scalar
    if pred.orient_exact(first) == 0:
        raise DegenerateInput("the points lie in a hyperplane")
    t = _Triangulation(pred)
    t.start(first)
    rest = [int(i) for i in ids if int(i) not in set(first)]
    # insert in a spatially coherent order (walks stay short)
    if rest:
        key = np.lexsort(np.round(geo.points[rest] * 64).T[::-1])
        rest = [rest[j] for j in key]
    for p in rest:
        t.insert(p)
    keep = [s for s, ok in enumerate(t.alive) if ok and -1 not in t.verts[s]]
    where = {s: r for r, s in enumerate(keep)}
    tri = np.array([t.verts[s] for s in keep], dtype=np.int64)
    order = np.argsort(tri, axis=1)
    nb_raw = np.array([[where.get(u, -1) for u in t.nbrs[s]] for s in keep], dtype=np.int64)
    return np.take_along_axis(tri, order, axis=1), np.take_along_axis(nb_raw, order, axis=1)

"""Exact Delaunay and alpha on near-degenerate input, checked in rational arithmetic.

Random near-degenerate sets in R² and R³ — near-duplicates (1e-13 … 1e-9 apart), points 1 to 4
ulps apart, jittered grids and (near-)co-spherical families — are triangulated and the result is
checked without trusting any of the library's predicates: every float coordinate is an exact
rational (``fractions.Fraction``), brought to integers by one power of two, and

* every top simplex is full-dimensional and its circumsphere has no point strictly inside
  (the empty-circumsphere condition, Thesis Definition 2.13);
* the simplices form a triangulation of the convex hull: each facet lies in one or two simplices,
  on opposite sides when two; each boundary facet has every point on its inner closed side (it
  lies on the hull); every point is a vertex; and the centroid of one simplex lies in exactly one
  simplex (so the covering degree, constant inside the hull, is 1);
* ``alpha`` equals GUDHI's ``AlphaComplex(precision="exact")``: the same simplices, values to
  1e-12 relative.

The suite runs ``N_SUITE`` inputs per family and dimension (deterministic seeds); ``--fuzz-long``
runs 100 times more.  The tally is printed with the other fuzz tests'.
"""

from __future__ import annotations

import itertools
from fractions import Fraction

import gudhi
import numpy as np
import pytest
from helpers import FUZZ_TALLY, fuzz_long
from scipy.spatial import ConvexHull

from thesis_lib.complexes import alpha, delaunay, regular_triangulation

MODULE = "delaunay exact (rational check)"
RTOL = 1e-12
N_SUITE = 12  # inputs per (family, dimension) in the suite


# ----------------------------------------------------------------------------- exact check
def _integers(points: np.ndarray) -> list[list[int]]:
    """The float coordinates as exact rationals, times one power of two that makes them integers."""
    fr = [[Fraction(float(c)) for c in row] for row in points]
    den = max((c.denominator for row in fr for c in row), default=1)
    return [[int(c * den) for c in row] for row in fr]


def _det(rows: list[list[int]]) -> int:
    """Exact integer determinant (fraction-free Bareiss elimination)."""
    a = [list(r) for r in rows]
    n = len(a)
    sign, prev = 1, 1
    for k in range(n - 1):
        if a[k][k] == 0:
            swap = next((i for i in range(k + 1, n) if a[i][k] != 0), None)
            if swap is None:
                return 0
            a[k], a[swap] = a[swap], a[k]
            sign = -sign
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                a[i][j] = (a[i][j] * a[k][k] - a[i][k] * a[k][j]) // prev
        prev = a[k][k]
    return sign * a[n - 1][n - 1]


def _orient(x: list[list[int]], v) -> int:
    d = _det([[a - b for a, b in zip(x[u], x[v[0]])] for u in v[1:]])
    return (d > 0) - (d < 0)


def _circumcentre(x: list[list[int]], v) -> tuple[list[int], int]:
    """Circumcentre of the full simplex v as (numerators, common denominator): Cramer's rule on
    2 (x_i − x_0) · c' = |x_i − x_0|², c = x_0 + c'."""
    a = [[2 * (p - q) for p, q in zip(x[u], x[v[0]])] for u in v[1:]]
    rhs = [sum((p - q) ** 2 for p, q in zip(x[u], x[v[0]])) for u in v[1:]]
    g = _det(a)
    num = []
    for c in range(len(a)):
        m = [row[:c] + [r] + row[c + 1 :] for row, r in zip(a, rhs)]
        num.append(_det(m) + g * x[v[0]][c])
    return num, g


def check_exact_delaunay(points: np.ndarray, tri: np.ndarray) -> None:
    """Assert, in exact rational arithmetic, that ``tri`` is a Delaunay triangulation of ``points``."""
    x = _integers(points)
    n, d = points.shape
    rows = [tuple(sorted(r)) for r in np.asarray(tri).tolist()]
    assert len(set(rows)) == len(rows), "a simplex twice"
    assert {v for r in rows for v in r} == set(range(n)), "a point is not a vertex"
    orient = [_orient(x, r) for r in rows]
    assert all(orient), f"flat simplices: {[r for r, o in zip(rows, orient) if not o][:4]}"
    # empty circumspheres: |D p − N|² ≤ |D x_0 − N|² for every point p
    for r in rows:
        num, g = _circumcentre(x, r)
        r2 = sum((g * c - t) ** 2 for c, t in zip(x[r[0]], num))
        for p in range(n):
            if p not in r:
                inside = sum((g * c - t) ** 2 for c, t in zip(x[p], num)) < r2
                assert not inside, f"point {p} lies strictly inside the circumsphere of {r}"
    # a triangulation of the hull: facets in one or two simplices, on opposite sides
    where: dict[tuple, list[tuple[int, int]]] = {}
    for s, r in enumerate(rows):
        for i in range(d + 1):
            where.setdefault(r[:i] + r[i + 1 :], []).append((s, r[i]))
    for f, occ in where.items():
        assert len(occ) <= 2, f"facet {f} in {len(occ)} simplices"
        sides = [_orient(x, list(f) + [apex]) for _, apex in occ]
        if len(occ) == 2:
            assert sides[0] == -sides[1] != 0, f"simplices on one side of facet {f}"
        else:  # a boundary facet: every point on the side of its simplex, or on it
            assert all(_orient(x, list(f) + [p]) * sides[0] >= 0 for p in range(n)), f"facet {f} not on the hull"
    # covering degree 1 (it is constant inside the hull once the boundary is on the hull)
    c = [sum(x[v][k] for v in rows[0]) for k in range(d)]  # (d + 1) × the centroid of simplex 0
    big = [[(d + 1) * t for t in row] for row in x]

    def contains(r) -> bool:
        o = _orient(big, r)
        for i in range(d + 1):
            q = [big[v] for v in r]
            q[i] = c
            if _det([[a - b for a, b in zip(qq, q[0])] for qq in q[1:]]) * o < 0:
                return False
        return True

    degree = sum(contains(r) for r in rows)
    assert degree == 1, f"the centroid of {rows[0]} lies in {degree} simplices"


def _min_ball(x: list[list[int]], v) -> tuple[list[Fraction], Fraction]:
    """Centre and squared radius of the smallest circumsphere of the simplex v (any dimension k):
    c = x_0 + Σ λ_i a_i with the Gram system G λ = |a_i|² / 2, in rationals."""
    a = [[Fraction(p - q) for p, q in zip(x[u], x[v[0]])] for u in v[1:]]
    k = len(a)
    m = [[sum(p * q for p, q in zip(a[i], a[j])) for j in range(k)] + [sum(p * p for p in a[i]) / 2]
         for i in range(k)]
    for col in range(k):  # Gauss–Jordan in rationals
        piv = next(r for r in range(col, k) if m[r][col] != 0)
        m[col], m[piv] = m[piv], m[col]
        for r in range(k):
            if r != col and m[r][col] != 0:
                f = m[r][col] / m[col][col]
                m[r] = [p - f * q for p, q in zip(m[r], m[col])]
    lam = [m[i][k] / m[i][i] for i in range(k)]
    off = [sum(lam[i] * a[i][c] for i in range(k)) for c in range(len(x[0]))]
    return [x[v[0]][c] + off[c] for c in range(len(off))], sum(t * t for t in off)


def check_alpha_equals_gudhi(points: np.ndarray) -> None:
    """Our alpha complex is GUDHI's exact one: the same simplices, values to 1e-12 relative.

    GUDHI's values are not always exact: where they differ, ours must be the correctly rounded
    squared radius of the simplex's smallest circumsphere (computed here in rationals) and that
    sphere must be empty (the simplex is Gabriel, so that radius is its value)."""
    ours = dict(alpha(points))
    tree = gudhi.AlphaComplex(points=points, precision="exact").create_simplex_tree()
    ref = {tuple(s): v for s, v in tree.get_simplices()}  # (the tree must outlive the iteration)
    assert set(ours) == set(ref), f"simplices differ: {sorted(set(ours) ^ set(ref))[:6]}"
    x = None
    for s, v in ref.items():
        if abs(ours[s] - v) <= RTOL * abs(v) + 1e-300:
            continue
        if x is None:
            fr = [[Fraction(float(c)) for c in row] for row in points]
            den = max(c.denominator for row in fr for c in row)
            x = [[int(c * den) for c in row] for row in fr]
        centre, r2 = _min_ball(x, s)
        empty = all(sum((Fraction(p) - c) ** 2 for p, c in zip(x[u], centre)) >= r2
                    for u in range(len(x)) if u not in s)
        exact = float(r2 / den**2)
        assert empty and ours[s] == exact, (f"alpha value of {s}: ours {ours[s]!r}, GUDHI {v!r}, exact smallest "
                                            f"circumsphere {exact!r} ({'empty' if empty else 'not empty'})")
        FUZZ_TALLY[MODULE]["GUDHI value inexact, ours exact"] += 1


def check(points) -> None:
    """Every check on one input; counted in the fuzz tally."""
    points = np.asarray(points, dtype=np.float64)
    tally = FUZZ_TALLY[MODULE]
    tally["tried"] += 1
    tri, _ = regular_triangulation(points)
    check_exact_delaunay(points, tri)
    ours = set(delaunay(points))
    assert {tuple(r) for r in tri.tolist()} <= ours
    check_alpha_equals_gudhi(points)
    tally["value"] += 1


# ----------------------------------------------------------------------------- families
def _distinct(p: np.ndarray) -> np.ndarray:
    _, first = np.unique(p, axis=0, return_index=True)
    return p[np.sort(first)]


def _ulps(p: np.ndarray, k: np.ndarray) -> np.ndarray:
    """p moved by k[i, j] ulps in each coordinate."""
    out = p.copy()
    for _ in range(int(np.abs(k).max(initial=0))):
        step = np.sign(k) * (np.abs(k) > 0)
        out = np.where(step != 0, np.nextafter(out, np.where(step > 0, np.inf, -np.inf)), out)
        k = k - step
    return out


def near_duplicates(rng, d: int) -> np.ndarray:
    n = int(rng.integers(d + 2, 14))
    p = np.round(rng.random((n, d)), int(rng.integers(2, 6)))
    k = int(rng.integers(1, max(2, n // 2)))
    src = p[rng.integers(0, n, k)]
    eps = 10.0 ** rng.uniform(-13, -9, (k, 1)) * rng.choice([-1.0, 1.0], (k, d))
    if rng.random() < 0.5:
        eps = np.abs(eps[:, :1]) * np.ones((1, d))  # displaced along the diagonal (as NEAR_DUPLICATE_2D)
    return _distinct(np.vstack([p, src + eps]))


def ulp_apart(rng, d: int) -> np.ndarray:
    n = int(rng.integers(d + 2, 14))
    p = rng.random((n, d)) * rng.choice([1.0, 1e-3, 1e3])
    k = int(rng.integers(1, n + 1))
    src = p[rng.integers(0, n, k)]
    return _distinct(np.vstack([p, _ulps(src, rng.integers(-4, 5, (k, d)))]))


def jittered_grid(rng, d: int) -> np.ndarray:
    side = int(rng.integers(2, 5 if d == 2 else 4))
    g = np.array(list(itertools.product(range(side), repeat=d)), dtype=np.float64)
    g = g * rng.choice([1.0, 0.1, 0.37]) + rng.choice([1.0, 0.5, 7.0])  # no zero: its ulp is subnormal
    if rng.random() < 0.5:
        g = g + rng.normal(0.0, 10.0 ** rng.uniform(-15, -8), g.shape) * (rng.random(g.shape) < 0.5)
    else:
        g = _ulps(g, rng.integers(-2, 3, g.shape))
    return _distinct(g)


def cospherical(rng, d: int) -> np.ndarray:
    n = int(rng.integers(d + 2, 14))
    if rng.random() < 0.4:  # exactly co-spherical: integer points on a lattice sphere, some jittered
        r2 = int(rng.choice([25, 50, 65, 169] if d == 2 else [9, 27, 41, 50]))
        m = int(np.sqrt(r2))
        pts = np.array([q for q in itertools.product(range(-m, m + 1), repeat=d) if sum(t * t for t in q) == r2],
                       dtype=np.float64)
        pts = pts[rng.permutation(len(pts))[: max(d + 2, n)]] + float(rng.integers(1, 9)) + 0.5  # exact, no zero
        jig = rng.random(len(pts)) < 0.3
        pts[jig] = _ulps(pts[jig], rng.integers(-2, 3, (int(jig.sum()), d)))
    else:  # rounded cos / sin: co-spherical to within an ulp or two
        v = rng.normal(size=(n, d))
        pts = v / np.linalg.norm(v, axis=1, keepdims=True) * rng.choice([1.0, 0.3, 1e3])
        pts = pts + 2.0 * np.abs(pts).max()  # off the axes (a coordinate of 1e-17 beside 1 is refused)
    if rng.random() < 0.5:
        pts = np.vstack([pts, rng.normal(0.0, 0.2, (int(rng.integers(1, 4)), d)) * np.abs(pts).max()])
    return _distinct(pts)


FAMILIES = {"near_duplicates": near_duplicates, "ulp_apart": ulp_apart, "jittered_grid": jittered_grid,
            "cospherical": cospherical}


def family_input(name: str, d: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng([21, d, seed, list(FAMILIES).index(name)])
    return FAMILIES[name](rng, d)


# ----------------------------------------------------------------------------- tests
NEAR_DUPLICATE_2D = [[0.04, 0.24], [0.04, 0.38], [0.01, 0.16], [0.03, 0.23], [0.5, 0.9], [0.04 + 1e-13, 0.24 + 1e-13]]


def test_near_duplicate_2d_triangles_cover_the_hull():
    """Two points 1e-13 apart: the triangles cover the hull (2n − 2 − h = 7)."""
    p = np.array(NEAR_DUPLICATE_2D)
    tri, _ = regular_triangulation(p)
    rows = {tuple(r) for r in tri.tolist()}
    hull = len(ConvexHull(p).vertices)  # no point on a hull edge here
    assert len(rows) == 2 * len(p) - 2 - hull
    assert {(0, 2, 3), (0, 2, 5)} <= rows and (2, 3, 5) not in rows
    assert len(alpha(p)) == 25
    check(p)


def test_certificate_rejects_an_overlapping_triangulation():
    """A wrong triangulation of these points (two triangles overlapping (2, 3, 5) by a sliver of
    area 1e-32, with a locally convex boundary of its own) fails the certificate."""
    from thesis_lib.complexes.triangulation import _certify, prepare_geometry

    geo, _ = prepare_geometry(NEAR_DUPLICATE_2D)
    wrong = np.array([[2, 4, 5], [1, 4, 5], [1, 2, 3], [2, 3, 5], [0, 1, 3], [0, 1, 5]])
    cert = _certify(geo, wrong)
    assert not cert.ok
    assert set(cert.bad.tolist()) == {3, 4, 5}
    with pytest.raises(AssertionError, match="lies in 2 simplices|inside the circumsphere"):
        check_exact_delaunay(np.array(NEAR_DUPLICATE_2D), wrong)


def test_alpha_attachment_of_an_edge_a_few_ulps_long():
    """Three points a few ulps apart near (911, 943): the third lies inside the diametral circle
    of the edge (12, 13), so the edge is attached and enters with the triangle (1.2142e-25), not
    at its own squared half-length (1.1955e-25)."""
    p = family_input("ulp_apart", 2, 10)
    assert np.abs(p[[12, 13]] - p[10]).max() < 1e-12
    a = dict(alpha(p))
    assert a[(12, 13)] == a[(10, 12, 13)]
    half = float(sum((Fraction(float(s)) - Fraction(float(t))) ** 2 for s, t in zip(p[12], p[13])) / 4)
    assert a[(12, 13)] > half
    check(p)


#: the near-duplicate seeds hardest to triangulate among those tried: a triangulation that is off there
#: has a point strictly inside a circumsphere
HARD_SEEDS = {3: [223], 2: [171, 235, 279, 296, 423, 427]}


@pytest.mark.parametrize("d", [2, 3])
def test_hard_near_duplicate_seeds(d):
    """Near-duplicates 1e-13 to 1e-9 apart, in R² and R³, on the hardest seeds found."""
    for seed in HARD_SEEDS[d]:
        check(family_input("near_duplicates", d, seed))


def test_boundary_winding_twice_is_rejected():
    """Points 1-4 ulps apart (seed 240): the triangulation the exact repair produced had a closed,
    connected, locally convex boundary that curled twice around a cluster (a boundary edge with
    points on both sides, a point inside a circumcircle); the certificate's winding test rejects it."""
    check(family_input("ulp_apart", 2, 240))


@pytest.mark.parametrize("d", [2, 3])
@pytest.mark.parametrize("family", list(FAMILIES))
def test_family(family, d):
    count = N_SUITE * (100 if fuzz_long() else 1)
    for seed in range(count):
        p = family_input(family, d, seed)
        if len(p) < d + 2:
            continue
        check(p)


def test_checker_catches_a_non_delaunay_triangulation():
    """The rational check can fail: the other diagonal of a convex quadrilateral is not Delaunay."""
    p = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.9]])
    tri, _ = regular_triangulation(p)
    check_exact_delaunay(p, tri)
    other = np.array([[0, 1, 3], [1, 2, 3]]) if {tuple(r) for r in tri.tolist()} != {(0, 1, 3), (1, 2, 3)} \
        else np.array([[0, 1, 2], [0, 2, 3]])
    with pytest.raises(AssertionError, match="inside the circumsphere"):
        check_exact_delaunay(p, other)


if __name__ == "__main__":  # a one-off long run: python tests/test_delaunay_exact_fuzz.py N
    import sys
    import traceback

    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    failed = []
    for d in (2, 3):
        for family in FAMILIES:
            for seed in range(n):
                p = family_input(family, d, seed)
                if len(p) < d + 2:
                    continue
                try:
                    check(p)
                except Exception as exc:  # noqa: BLE001 - a report of every failure
                    failed.append((family, d, seed, type(exc).__name__, str(exc)[:160]))
                    if len(failed) < 4:
                        traceback.print_exc()
    print(dict(FUZZ_TALLY[MODULE]), "failed:", len(failed))
    for f in failed[:40]:
        print(f)

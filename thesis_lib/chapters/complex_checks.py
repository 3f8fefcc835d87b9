"""Numerical checks of the statements of §2.1.2 on samples: Jung's bound (Theorem 2.10), the Čech/Rips
sandwich (Lemma 2.12), the Rips complex as a flag complex, the Delaunay complex as the nerve of the
Voronoi cells (Definition 2.13), the alpha complex inside the Čech complex (Definition 2.14) and the
nesting of weighted alpha and witness complexes."""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._validate import as_points, check_int, check_seed
from ..complexes.alpha import alpha
from ..complexes.cech import cech
from ..complexes.miniball import smallest_enclosing_ball
from ..complexes.rips import rips
from ..homology.filtration import Filtration

if TYPE_CHECKING:
    from ..persistence import Barcode

__all__ = [
    "JungCheck",
    "jung_bound",
    "jung_ratios",
    "cech_rips_ratios",
    "cliques",
    "voronoi_nerve",
    "missing_simplices",
    "alpha_not_in_cech",
    "barcodes_differing",
    "betti_text",
    "weighted_alpha_losses",
]


def _simplex_set(simplices: Filtration | Iterable[Sequence[int]]) -> list[tuple[int, ...]]:
    items = (s for s, _ in simplices) if isinstance(simplices, Filtration) else simplices
    return [tuple(sorted(int(v) for v in s)) for s in items]


def jung_bound(*, dim: int) -> float:
    """Jung's constant: a set of diameter d in R^n lies in a ball of radius d·√(n / (2(n + 1))).

    Thesis: Theorem 2.10 (Jung's theorem).

    Parameters
    ----------
    dim : int
        The dimension n, ≥ 1.

    Returns
    -------
    float
        √(n / (2(n + 1))), attained by the regular simplex.

    Raises
    ------
    ValueError
        A dimension below 1.

    Examples
    --------
    >>> round(jung_bound(dim=2), 6), round(1 / 3**0.5, 6)
    (0.57735, 0.57735)
    """
    n = check_int(dim, "dim", minimum=1)
    return float(np.sqrt(n / (2 * (n + 1))))


@dataclass(frozen=True, kw_only=True)
class JungCheck:
    """Jung's bound against random sets and the regular simplex in one dimension.

    Thesis: Theorem 2.10.

    Attributes
    ----------
    dim : int
        The dimension n.
    bound : float
        :func:`jung_bound` of n.
    largest_ratio : float
        The largest enclosing radius / diameter over the random sets.
    regular_ratio : float
        Enclosing radius / diameter of the regular n-simplex, divided by the bound (1 when attained).
    """

    dim: int
    bound: float
    largest_ratio: float
    regular_ratio: float


def jung_ratios(*, dims: Sequence[int] = (2, 3), n_sets: int = 1000, max_points: int = 8,
                seed: int = 0) -> list[JungCheck]:
    """Enclosing radius / diameter of random sets of 2 to ``max_points`` points of [0, 1]^n, against Jung's bound.

    Thesis: Theorem 2.10 (r ≤ d·√(n / (2(n + 1))), sharp for the regular simplex).

    One generator draws, dimension after dimension, for each set its size (uniform in
    2..max_points) and then its points.  The regular simplex is e_1, …, e_n and the point with all
    coordinates (1 − √(n + 1)) / n, all √2 apart.

    Parameters
    ----------
    dims : sequence of int, default (2, 3)
        The dimensions n, each ≥ 1.
    n_sets : int, default 1000
        Random sets per dimension, ≥ 1.
    max_points : int, default 8
        The largest set size, ≥ 2.
    seed : int, default 0
        The seed of ``numpy.random.default_rng``.

    Returns
    -------
    list of JungCheck
        One per dimension, in the order of ``dims``.

    Raises
    ------
    ValueError
        A dimension below 1, ``n_sets`` below 1, ``max_points`` below 2 or a negative seed.
    TypeError
        A seed that is not an integer.

    Examples
    --------
    >>> [(c.dim, c.largest_ratio <= c.bound, round(c.regular_ratio, 6)) for c in jung_ratios(n_sets=50)]
    [(2, True, 1.0), (3, True, 1.0)]
    """
    dims = [check_int(n, "dim", minimum=1) for n in dims]
    n_sets = check_int(n_sets, "n_sets", minimum=1)
    max_points = check_int(max_points, "max_points", minimum=2)
    rng = np.random.default_rng(check_seed(seed))
    out = []
    for n in dims:
        bound = np.sqrt(n / (2 * (n + 1)))
        ratios = []
        for _ in range(n_sets):
            sample = rng.random((int(rng.integers(2, max_points + 1)), n))
            diam = max(np.linalg.norm(a - b) for a, b in itertools.combinations(sample, 2))
            ratios.append(smallest_enclosing_ball(sample)[1] / diam)
        regular = np.vstack([np.eye(n), np.full((1, n), (1 - np.sqrt(n + 1)) / n)])
        attained = smallest_enclosing_ball(regular)[1] / np.sqrt(2) / bound
        out.append(JungCheck(dim=n, bound=float(bound), largest_ratio=float(max(ratios)),
                             regular_ratio=float(attained)))
    return out


def cech_rips_ratios(points: npt.ArrayLike, *, max_radius: float, max_dim: int) -> np.ndarray:
    """Čech value / Rips value of every simplex of dimension ≥ 1 of the Rips filtration.

    Thesis: Lemma 2.12 (R(X, ε) ⊆ C(X, √2 ε) ⊆ R(X, √2 ε): the ratio lies in [1, √2]).

    Parameters
    ----------
    points : array_like, shape (n, d)
        The points.
    max_radius : float
        The largest ε of both filtrations; take it above the point set's radius so that every Rips
        simplex is also a Čech simplex.
    max_dim : int
        The largest simplex dimension.

    Returns
    -------
    numpy.ndarray
        One ratio per simplex of dimension ≥ 1 of the Rips filtration, in its order.

    Raises
    ------
    ValueError
        As :func:`~thesis_lib.complexes.rips` and :func:`~thesis_lib.complexes.cech`, or a Rips
        simplex missing from the Čech filtration (``max_radius`` too small).

    Examples
    --------
    An equilateral triangle: its edges have ratio 1, the triangle 2/√3:

    >>> cech_rips_ratios([[0.0, 0.0], [1.0, 0.0], [0.5, 3**0.5 / 2]], max_radius=2.0, max_dim=2).round(4).tolist()
    [1.0, 1.0, 1.0, 1.1547]
    """
    r_val = dict(rips(points, max_radius=max_radius, max_dim=max_dim))
    c_val = dict(cech(points, max_radius=max_radius, max_dim=max_dim))
    edges_up = [s for s in r_val if len(s) > 1]
    if any(s not in c_val for s in edges_up):
        raise ValueError("a Rips simplex is not in the Čech filtration: raise max_radius")
    return np.array([c_val[s] / r_val[s] for s in edges_up])


def cliques(edges: Iterable[Sequence[int]], *, n_vertices: int, max_dim: int) -> set[tuple[int, ...]]:
    """Every set of at most max_dim + 1 vertices that are pairwise joined: the flag complex of a graph.

    Thesis: §2.1.2 (the Rips complex is the largest complex with its 1-skeleton, a flag complex).

    A brute-force search over all vertex sets, meant as an independent check of small complexes.

    Parameters
    ----------
    edges : iterable of sequence of int
        The edges (pairs of vertices in 0..n_vertices − 1).
    n_vertices : int
        The number of vertices, ≥ 1.
    max_dim : int
        The largest clique dimension, ≥ 0.

    Returns
    -------
    set of tuple of int
        The cliques as sorted tuples, the vertices included.

    Raises
    ------
    ValueError
        A count below 1, a negative dimension or an edge that is not two vertices in range.

    Examples
    --------
    >>> sorted(cliques([(0, 1), (1, 2), (0, 2), (2, 3)], n_vertices=4, max_dim=2), key=lambda c: (len(c), c))
    [(0,), (1,), (2,), (3,), (0, 1), (0, 2), (1, 2), (2, 3), (0, 1, 2)]
    """
    n = check_int(n_vertices, "n_vertices", minimum=1)
    top = check_int(max_dim, "max_dim", minimum=0)
    joined = {tuple(sorted(int(v) for v in e)) for e in edges}
    if any(len(e) != 2 or e[0] == e[1] or e[0] < 0 or e[1] >= n for e in joined):
        raise ValueError(f"edges must be pairs of distinct vertices in 0..{n - 1}")
    return {c for k in range(1, top + 2) for c in itertools.combinations(range(n), k)
            if all(e in joined for e in itertools.combinations(c, 2))}


def voronoi_nerve(points: npt.ArrayLike) -> tuple[set[tuple[int, ...]], int]:
    """The top simplices of the nerve of the Voronoi cells, read off the Voronoi vertices (scipy/Qhull).

    Thesis: Definition 2.13 (the Delaunay complex is the nerve of the Voronoi cells).

    Each Voronoi vertex is where d + 1 cells meet (in general position): its d + 1 nearest sites
    span a top simplex.  The second value counts the sites within a relative 10⁻⁹ of the nearest,
    among the d + 2 nearest, at the vertex where most do.

    Parameters
    ----------
    points : array_like, shape (n, d)
        The sites, d ≥ 2, at least d + 2 of them, not all on a hyperplane.

    Returns
    -------
    set of tuple of int
        The top simplices (sorted vertex tuples).
    int
        The largest number of cells meeting at one Voronoi vertex (d + 1 in general position).

    Raises
    ------
    ValueError
        Points of dimension below 2 or fewer than d + 2 of them.

    Examples
    --------
    >>> sorted(voronoi_nerve([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.1, 1.2]])[0])
    [(0, 1, 2), (1, 2, 3)]
    """
    from scipy.spatial import Voronoi, cKDTree

    pts = as_points(points)
    d = pts.shape[1]
    if d < 2 or pts.shape[0] < d + 2:
        raise ValueError(f"need at least d + 2 points in R^d, d ≥ 2, got shape {pts.shape}")
    vor = Voronoi(pts)
    dist, idx = cKDTree(pts).query(vor.vertices, k=d + 2)
    meeting = [int(np.sum(dd <= dd[0] * (1 + 1e-9))) for dd in dist]
    return {tuple(sorted(map(int, i[: d + 1]))) for i in idx}, max(meeting)


def missing_simplices(simplices: Filtration | Iterable[Sequence[int]],
                      other: Filtration | Iterable[Sequence[int]]) -> int:
    """How many simplices of one complex are not simplices of another.

    Thesis: §2.1.2 (the inclusions A(X, ε) ⊆ D(X) and W(X, L, ε) ⊆ W(X, L, ε') for ε ≤ ε').

    Parameters
    ----------
    simplices : Filtration or iterable of sequence of int
        The complex whose simplices are looked up (a filtration's values play no part).
    other : Filtration or iterable of sequence of int
        The complex they are looked up in.

    Returns
    -------
    int
        The number of simplices of ``simplices`` (with repetitions) missing from ``other``; vertex
        order plays no part.

    Examples
    --------
    >>> missing_simplices([(0,), (1,), (1, 0)], [(0,), (0, 1)])
    1
    """
    there = set(_simplex_set(other))
    return sum(1 for s in _simplex_set(simplices) if s not in there)


def alpha_not_in_cech(points: npt.ArrayLike, filtration: Filtration) -> int:
    """Simplices of an alpha filtration entering before their Čech radius (they should not).

    Thesis: Definition 2.14 (R(x, ε) ⊆ B(x, ε), so A(X, ε) ⊆ C(X, ε)).

    Parameters
    ----------
    points : array_like, shape (n, d)
        The points.
    filtration : Filtration
        Their (unweighted) alpha filtration, values ε².

    Returns
    -------
    int
        The simplices of dimension ≥ 1 whose value is below the square of their smallest enclosing
        ball's radius by more than a relative 10⁻⁹.

    Raises
    ------
    ValueError
        Points that are not an (n, d) array of finite numbers.

    Examples
    --------
    >>> from thesis_lib.complexes import alpha
    >>> pts = [[0.0, 0.0], [1.0, 0.0], [0.3, 0.8], [1.2, 1.0]]
    >>> alpha_not_in_cech(pts, alpha(pts))
    0
    """
    pts = as_points(points)
    return sum(1 for s, v in filtration
               if len(s) > 1 and v < smallest_enclosing_ball(pts[[int(x) for x in s]])[1] ** 2 * (1 - 1e-9))


def _positive_bars(barcode: Barcode, dim: int, squared: bool) -> np.ndarray:
    bars = barcode.intervals(dim)
    bars = np.sqrt(bars) if squared else bars
    return np.sort(bars[bars[:, 1] - bars[:, 0] > 1e-9], axis=0)


def barcodes_differing(squared_barcode: Barcode, barcode: Barcode, *, dims: Sequence[int] = (0, 1)) -> int:
    """In how many dimensions two barcodes differ, the first on a squared scale (alpha values ε²).

    Thesis: Theorem 2.15 (the alpha and Čech filtrations have the homotopy type of the same unions,
    hence the same barcodes in ε).

    Bars of length at most 10⁻⁹ are dropped; the others are compared sorted, with a relative
    tolerance of 10⁻⁹.

    Parameters
    ----------
    squared_barcode : Barcode
        A barcode whose values are squared radii (of an alpha filtration).
    barcode : Barcode
        A barcode in radii (of a Čech filtration).
    dims : sequence of int, default (0, 1)
        The dimensions compared.

    Returns
    -------
    int
        The number of dimensions in ``dims`` whose bars differ.

    Examples
    --------
    >>> from thesis_lib.complexes import alpha, cech
    >>> from thesis_lib.persistence import persistence
    >>> pts = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0], [0.7, 0.7]]
    >>> barcodes_differing(persistence(alpha(pts)), persistence(cech(pts, max_radius=2.0, max_dim=2)))
    0
    """
    differing = 0
    for d in dims:
        a, b = _positive_bars(squared_barcode, d, True), _positive_bars(barcode, d, False)
        differing += int(a.shape != b.shape or not np.allclose(a, b, rtol=1e-9))
    return differing


def betti_text(barcode: Barcode, value: float, *, dims: Sequence[int] = (0, 1)) -> str:
    """The Betti numbers of a barcode at one filtration value, written ``β₀, β₁, …``.

    Thesis: Definition 2.23 (β_p of the complex K^value), as the chapter's tables show them.

    Parameters
    ----------
    barcode : Barcode
        The barcode.
    value : float
        The filtration value.
    dims : sequence of int, default (0, 1)
        The dimensions, in order.

    Returns
    -------
    str
        The Betti numbers joined by ``", "``.

    Examples
    --------
    >>> from thesis_lib.complexes import rips
    >>> from thesis_lib.persistence import persistence
    >>> betti_text(persistence(rips([[0.0, 0.0], [1.0, 0.0], [5.0, 0.0]], max_radius=3.0)), 1.0)
    '2, 0'
    """
    return ", ".join(str(barcode.betti(value, dim=d)) for d in dims)


def weighted_alpha_losses(points: npt.ArrayLike, radii: npt.ArrayLike, eps_grid: Sequence[float]) -> tuple[int, int]:
    """Simplices lost by weighted alpha complexes as ε grows, under the thesis's rule and the naive one.

    Thesis: §2.1.2, weighted alpha complexes (balls of squared radius w_x + ε² keep the inclusions;
    radius √w_x + ε does not).

    The thesis's complex at ε is the alpha filtration of the weights r² cut at ε²; the naive one is
    the alpha complex (value ≤ 0) of the weights (r + ε)².  Along the grid, every simplex present at
    one value and absent at the next counts as lost.

    Parameters
    ----------
    points : array_like, shape (n, d)
        The centres.
    radii : array_like, shape (n,)
        The radii r_x (weights w_x = r_x²), ≥ 0.
    eps_grid : sequence of float
        The values of ε, increasing.

    Returns
    -------
    tuple of int
        (lost under w_x + ε², lost under (√w_x + ε)²).

    Raises
    ------
    ValueError
        Radii not one per point or negative, or a grid that does not increase.

    Examples
    --------
    >>> import numpy as np
    >>> rng = np.random.default_rng(1)
    >>> weighted_alpha_losses(rng.random((8, 2)), np.full(8, 0.05), [0.0, 0.1, 0.2])[0]
    0
    """
    pts = as_points(points)
    r = np.asarray(radii, dtype=np.float64)
    grid = np.asarray(eps_grid, dtype=np.float64)
    if r.shape != (pts.shape[0],) or not np.all(np.isfinite(r) & (r >= 0)):
        raise ValueError(f"radii must be {pts.shape[0]} nonnegative numbers, one per point")
    if grid.ndim != 1 or np.any(np.diff(grid) <= 0):
        raise ValueError("eps_grid must be an increasing sequence of numbers")
    alpha_w = alpha(pts, weights=r**2)
    lost_thesis = lost_naive = 0
    before_thesis: set = set()
    before_naive: set = set()
    for e in eps_grid:
        now_thesis = {tuple(map(int, s)) for s, v in alpha_w if v <= e**2}
        now_naive = {tuple(map(int, s)) for s, v in alpha(pts, weights=(r + e) ** 2) if v <= 0}
        lost_thesis += len(before_thesis - now_thesis)
        lost_naive += len(before_naive - now_naive)
        before_thesis, before_naive = now_thesis, now_naive
    return lost_thesis, lost_naive

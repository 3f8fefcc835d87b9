"""The implicit Rips engine: persistence of a Vietoris–Rips filtration without storing its simplices.

A Rips complex is a flag complex: every simplex is determined by its vertices, and its value by
the longest edge.  So nothing but the graph of edges (diameter ≤ 2ε) is stored, as neighbour lists
sorted by decreasing vertex; a k-simplex {v_k > … > v_0} is the integer

    idx = C(v_0, 1) + C(v_1, 2) + … + C(v_k, k + 1)         (the combinatorial number system),

its vertices are read back from idx by binary search in a table of binomials, and its coboundary
(the cofaces σ ∪ {j}) is enumerated on the fly by merging the neighbour lists of its vertices, j
decreasing, so that the coface indices come out decreasing.  The filtration order within a
dimension is (diameter ascending, index descending) — Ripser's reverse colexicographic tie-break,
which makes the first coface found with σ's own diameter the *earliest* coface of σ.

The reduction is Ripser's (Bauer 2021), on the cohomology side with clearing:

* **H₀ by union–find** over the edges in filtration order (elder rule); the edges that merge two
  components are the pivots of dimension 0 and are cleared from dimension 1.
* **Apparent pairs, a discrete gradient.**  A pair σ < τ is *apparent* when σ is the latest facet
  of τ and τ the earliest coface of σ.  Each such pair is a persistence pair of the filtration, and
  together they form an acyclic matching — a discrete gradient vector field in the sense of the
  thesis's Definitions 4.30–4.33 — whose critical cells are the only ones the reduction has to look
  at (the barcode is the Morse complex's, Theorem 4.42's idea).  Pairs of equal diameter
  ("zero apparent pairs") have zero persistence: σ is never made a column, and τ is known as the
  pivot of δσ when another column meets it (τ's latest facet is looked up then).  Deciding whether
  σ is in such a pair is local (one early-exit coboundary scan and one facet scan), so it runs in
  parallel while the columns are assembled (threads over blocks of the (k − 1)-simplices, on every
  core unless ``n_threads`` says otherwise; the blocks are independent and kept in order, so the
  barcode does not depend on the number of threads).
* **Emergent pairs**: a column whose earliest coface has σ's diameter and is not yet a pivot is
  paired at once, without enumerating the rest of its coboundary.
* **The rest is reduced lazily**: the working coboundary is a heap of *coboundary enumerators*,
  one per added coboundary f · δs, each yielding the cofaces of s one at a time in filtration order
  (the cofaces of s's own diameter by decreasing index, then the others by merging the vertices'
  distance-sorted neighbour lists); the heap holds each enumerator's head, equal entries are summed
  only when they reach the top, and an enumerator is advanced only when its head is popped.  So the
  column costs a few words per added coboundary, never its entries (Ripser's heap holds every entry
  pushed and not yet popped).  An added column is regenerated from its reduction chain V (the
  simplices whose coboundaries sum to it), never stored reduced.  This loop is sequential (each
  column depends on the pivots found before it), which is why it does not share the explicit
  engine's loop over stored columns: the field arithmetic, the heap and the chain merging are
  shared (``src/column_heap.hpp``), the coboundary enumeration cannot be.

The columns of each dimension are only the candidates that survive clearing and the apparent
pairs, and they are assembled in one pass over the cofaces of the (k − 1)-simplices (Ripser 1.2's
``assemble_columns_to_reduce``): whether a simplex is in a zero apparent pair is decided where it is
met.  A k-simplex τ = f ∪ {j} is met from the facet f that omits its top vertex j, which is τ's
latest facet when the two have one diameter; so the first such coface of f is the upper simplex of
the pair (f, τ), and only the pairs whose added vertex is not the top one are kept in a table to be
cleared from the next dimension.  The top dimension's facets, the longest list, are not stored: they
are met again as cofaces of the (k − 2)-simplices.  So memory holds the graph (with a dense distance
matrix for up to 2048 points, or a hash of the edges), the (k − 1)-simplices while dimension k < top
is assembled, one column record per column, the pivot table, the reduction chains of the columns
that needed work and, while a column is reduced, its enumerators.

With ``cocycles=True`` the reduction also keeps, for each bar of dimension k ≥ 1, the chain V_s of
the column that gave it (s and the simplices whose coboundaries were added to it) as the bar's
representative cocycle, as ripser.py's ``do_cocycles`` does; the bars of an emergent or a zero
apparent pair have length zero and are not reported, so the shortcuts never hide a chain that is
asked for.  Without it nothing more is kept than the barcode needs.  Representative *cycles*
(``cycles=True``) are not the implicit engine's: ``rips_cycles`` computes them by the explicit engine
on the Rips complex truncated to what the bars need.

Everything after the graph is compiled C++ (``src/implicit_rips.cpp``, with the graph and the
combinatorial number system in ``src/implicit_rips_graph.hpp``).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Literal, overload

import numpy as np
import numpy.typing as npt

from .._core import implicit_rips
from .._validate import (
    MAX_DIM,
    Edges,
    Field,
    Points,
    check_flag,
    check_int,
    check_max_dim,
    check_min_persistence,
    check_radius,
    parse_field,
    parse_rips_input,
)
from ..complexes.rips import rips_edges
from .barcode import Barcode, canonical_intervals
from .rips_cycles import Cycles, bar_cycles

if TYPE_CHECKING:
    import scipy.sparse

__all__ = ["rips_persistence", "rips_graph", "rips_barcode"]

#: up to DENSE_MAX points a dense distance matrix (8 n² bytes, 32 MB at the limit) is kept for
#: constant-time lookups, and up to DENSE_FULL_MAX (128 MB) when at least DENSE_FILL of the pairs are
#: edges; otherwise the lengths are looked up in a hash of the edges (16 to 32 bytes per edge), as fast
#: as a matrix too large for the cache and much smaller when the threshold leaves few edges
DENSE_MAX = 2048
DENSE_FULL_MAX = 4096
DENSE_FILL = 0.25


# ---------------------------------------------------------------------------- the graph
def rips_graph(
    points: npt.ArrayLike | None = None, *, max_radius: float = np.inf,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = None,
) -> tuple[int, npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.float64]]:
    """The neighbour graph of a Rips filtration: ``(n, indptr, neighbours, lengths)``.

    Thesis: Definition 2.11 (an edge when the distance is at most 2ε).

    Parameters
    ----------
    points : array_like, shape (n, d), optional
        The point cloud (Euclidean distances); give exactly one of ``points`` and ``distance_matrix``.
    max_radius : float
        Scale ε: an edge joins two vertices at distance at most 2ε (default ∞: every pair).
    distance_matrix : array_like, shape (n, n), or scipy.sparse matrix, optional
        A dense symmetric matrix of distances, or a scipy.sparse matrix whose stored entries are the
        only edges (as ripser's sparse input; entries above 2ε dropped).  A diagonal entry is the
        vertex's birth, as ripser reads it: the edges' lengths here are then at least their
        vertices' births (``thesis_lib.complexes.rips.rips_edges``).

    Returns
    -------
    n : int
        The number of vertices.
    indptr : numpy.ndarray of int64, shape (n + 1,)
        ``neighbours[indptr[v]:indptr[v + 1]]`` are the vertices adjacent to v.
    neighbours : numpy.ndarray of int64
        Each vertex's neighbours in decreasing order.
    lengths : numpy.ndarray of float64
        The distances, parallel to ``neighbours``.

    Warns
    -----
    UserWarning
        ``points`` that look like a distance matrix (as :func:`rips_persistence`).

    Raises
    ------
    ValueError
        Both or neither of ``points`` and ``distance_matrix``; a bad radius, point cloud or
        distance matrix (not square, NaN, negative or asymmetric entries); more edges than
        ``MAX_SIMPLICES`` (refused before they are listed, ``complexes.rips.check_edges``).

    Notes
    -----
    The edges are those of :func:`~thesis_lib.complexes.rips` (one search,
    ``thesis_lib.complexes.rips.rips_edges``): distances between points are computed on the
    points scaled by a power of two and scaled back exactly.
    """
    eps = check_radius(max_radius)
    return _graph(parse_rips_input(points, distance_matrix, sparse=True), eps)[0]


def _graph(source: Points | np.ndarray | Edges, eps: float):
    """:func:`rips_graph` on parsed input, and the vertices' births (zeros when none is given)."""
    n, edges, lengths, births = rips_edges(source, eps)
    graph = (n, *_csr(n, np.asarray(edges, np.int64).reshape(-1, 2), np.asarray(lengths, np.float64)))
    return graph, np.zeros(n) if births is None else births


def _csr(n: int, edges: np.ndarray, lengths: np.ndarray):
    """Symmetric neighbour lists, each sorted by decreasing neighbour."""
    return implicit_rips.neighbour_lists(int(n), np.ascontiguousarray(edges, dtype=np.int64),
                                         np.ascontiguousarray(lengths, dtype=np.float64))


#: below this many k-simplices to be met (the positive edges for H₁; above, the (k − 1)-simplices
#: times the mean degree over k + 1) the columns of a dimension are assembled on one thread
#: (starting the threads costs more than it saves, and much more on a loaded machine)
PARALLEL_MIN = 50_000


def _dense(n: int, neighbours: int) -> bool:
    """Whether the engine keeps a dense distance matrix for n vertices and that many list entries."""
    return n <= DENSE_MAX or (n <= DENSE_FULL_MAX and neighbours >= DENSE_FILL * n * n)


#: representative cocycles per homology dimension: ``cocycles[k][i]`` belongs to ``barcode.intervals(k)[i]``
Cocycles = dict[int, list[npt.NDArray[np.int64]]]


# ---------------------------------------------------------------------------- driver
@overload
def rips_persistence(
    points: npt.ArrayLike | None = None, *, max_radius: float = ..., max_dim: int = ..., coefficients: int = ...,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = ...,
    stats: dict[int, dict[str, int]] | None = ..., n_threads: int | None = ..., min_persistence: float = ...,
    cocycles: Literal[False] = ..., cycles: Literal[False] = ...,
) -> Barcode: ...
@overload
def rips_persistence(
    points: npt.ArrayLike | None = None, *, max_radius: float = ..., max_dim: int = ..., coefficients: int = ...,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = ...,
    stats: dict[int, dict[str, int]] | None = ..., n_threads: int | None = ..., min_persistence: float = ...,
    cocycles: Literal[True], cycles: Literal[False] = ...,
) -> tuple[Barcode, Cocycles]: ...
@overload
def rips_persistence(
    points: npt.ArrayLike | None = None, *, max_radius: float = ..., max_dim: int = ..., coefficients: int = ...,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = ...,
    stats: dict[int, dict[str, int]] | None = ..., n_threads: int | None = ..., min_persistence: float = ...,
    cocycles: Literal[False] = ..., cycles: Literal[True],
) -> tuple[Barcode, Cycles]: ...
@overload
def rips_persistence(
    points: npt.ArrayLike | None = None, *, max_radius: float = ..., max_dim: int = ..., coefficients: int = ...,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = ...,
    stats: dict[int, dict[str, int]] | None = ..., n_threads: int | None = ..., min_persistence: float = ...,
    cocycles: Literal[True], cycles: Literal[True],
) -> tuple[Barcode, Cocycles, Cycles]: ...
def rips_persistence(
    points: npt.ArrayLike | None = None, *, max_radius: float = np.inf, max_dim: int = 2, coefficients: int = 2,
    distance_matrix: npt.ArrayLike | scipy.sparse.spmatrix | scipy.sparse.sparray | None = None,
    stats: dict[int, dict[str, int]] | None = None, n_threads: int | None = None, min_persistence: float = 0.0,
    cocycles: bool = False, cycles: bool = False,
) -> Barcode | tuple[Barcode, Cocycles] | tuple[Barcode, Cycles] | tuple[Barcode, Cocycles, Cycles]:
    """Barcode of the Vietoris–Rips filtration of ``points`` without building it (implicit engine).

    Thesis: Definition 2.11 (Rips), Theorem 2.39 / Algorithm 2 (the pairs, computed by the dual
    reduction), Definitions 4.30–4.33 and Theorem 4.42 (apparent pairs as a discrete gradient).

    Parameters
    ----------
    points : array_like, shape (n, d), optional
        The point cloud; or give ``distance_matrix``.  Duplicate points are allowed (each row is a
        vertex, joined to its copies at 0: their H0 bars have length zero and are left out).
    max_radius : float
        Scale ε: simplices of diameter ≤ 2ε (the values are ε = diameter / 2, as
        :func:`~thesis_lib.complexes.rips`).
    max_dim : int
        The largest simplex dimension of the complex (as :func:`~thesis_lib.complexes.rips`), ≥ 1;
        homology of dimensions 0 .. max_dim − 1 is computed, and it is complete (the top dimension
        of a truncated complex is not: its classes could only die in dimensions that are not built).
    coefficients : int
        A prime p: the field Z/p.
    distance_matrix : array_like, shape (n, n), or scipy.sparse matrix, optional
        A dense symmetric matrix, or a scipy.sparse matrix whose stored entries are the only edges
        (entries above 2ε dropped); keyword only, instead of ``points``.  A non-zero diagonal gives
        the vertices' births, as ripser.py and giotto-ph read it: vertex i enters at
        ``D[i, i] / 2``, an edge at half the largest of its entry and its vertices' diagonal entries,
        and a vertex whose entry is above 2ε is left out.
    stats : dict, optional
        Filled per dimension with ``simplices`` (k-simplices not killing a (k−1)-class),
        ``apparent`` (zero apparent pairs σ < τ found), ``columns`` (columns left), ``emergent``
        (paired without enumerating their coboundary), ``reduced`` (columns that needed an addition)
        and ``additions``.
    n_threads : int, optional
        Threads for assembling the columns and finding the apparent pairs (used from about
        ``PARALLEL_MIN`` simplices of a dimension on); None: ``OMP_NUM_THREADS`` when set, else
        every core.  The barcode does not depend on it.
    min_persistence : float
        Intervals with ``death − birth <= min_persistence`` (in ε) are left out; default 0: only the
        zero-length ones.  Tied distances give bars of length ~1e-16 that ripser.py (on float32
        distances) does not report: 1e-12 drops them.
    cocycles : bool
        Also return a representative cocycle of every bar of dimension >= 1 (default False: the
        barcode alone, and the reduction keeps no more than it needs).  The cocycle of a bar born by
        the k-simplex s is the reduction chain V_s of s's coboundary column, as ripser.py's
        ``do_cocycles`` gives it (the columns of V with M_p V reduced, Theorem 2.39, on the
        coboundary side): s with coefficient 1 plus multiples of later simplices.  Restricted to the
        simplices of value <= t it is a cocycle of the complex at t whose class is not zero, for every
        t from the bar's birth to just before its death (every t from the birth on for an essential
        bar); it may hold simplices born after the birth (restrict it to see the class at a value).
    cycles : bool
        Also return a representative cycle of every bar of dimension >= 1 (default False).  Unlike the
        cocycles, which the implicit engine's own reduction gives at almost no cost, these do not come
        from the implicit engine, which keeps no simplex of a pair: the
        cycles of dimension k are :meth:`Barcode.representative`'s (Theorem 2.39's z_i) computed by
        the explicit engine on the Rips filtration of the same parsed input truncated to what the bars
        need, simplices of dimension <= k + 1 and value up to the largest finite death of dimension k
        (``max_radius`` when there is an essential bar), so they cost that complex's construction and
        reduction (``thesis_lib.persistence.rips_cycles``).  The cycle of a bar [b, d) is a cycle over
        Z/p of simplices of value <= b, one of them of value b; for a finite bar it is a boundary in
        the complex at d and not before.

    Returns
    -------
    Barcode
        The same intervals as ``persistence(rips(points, max_radius, max_dim), coefficients)`` in
        dimensions 0 .. max_dim − 1 (zero-length intervals left out), to the last bit: the edges
        are :func:`~thesis_lib.complexes.rips`'s (distances computed on the points scaled by a
        power of two and scaled back exactly, so coordinates near 1e160 or 1e-170 are fine).
        ``barcode.to_diagrams(scale="diameter")`` gives ripser.py's ``dgms`` (diameters 2ε).
    dict of int to list of numpy.ndarray
        Only with ``cocycles=True``, after the barcode: ``cocycles[k]`` for each dimension
        k = 1 .. max_dim − 1, one array per bar, ``cocycles[k][i]`` belonging to
        ``barcode.intervals(k)[i]`` (sorted by birth, then death).  Each is ripser.py's format: an
        int64 array of shape (m, k + 2), a row per simplex of the cocycle, its k + 1 vertices
        (decreasing) then its coefficient in 1 .. p − 1, rows in filtration order (value up).
    dict of int to list of numpy.ndarray
        Only with ``cycles=True``, last (after the cocycles when both are asked for: ``(barcode,
        cocycles, cycles)``): ``cycles[k][i]`` belongs to ``barcode.intervals(k)[i]`` for
        k = 1 .. max_dim − 1, the same layout as the cocycles but with the k + 1 vertices of each row
        *increasing* (the library's simplices; the cocycles keep ripser.py's decreasing order), rows
        in the filtration order of the explicit engine (the bar's creating simplex last).

    Warns
    -----
    UserWarning
        ``points`` square, symmetric, with a zero diagonal and no negative entry: it looks like a
        distance matrix but is read as n points in R^n (ripser.py warns too); give a distance
        matrix as ``distance_matrix=``.

    Raises
    ------
    ValueError
        ``max_dim`` below 1 or above ``MAX_DIM`` (10⁴; dimensions above
        the number of points are computed as the empty homology they are), a non-prime
        ``coefficients``, ``cocycles`` or ``cycles`` not True or False, ``n_threads`` below 1, a
        negative, infinite or NaN ``min_persistence``, or invalid points / distances.

    Examples
    --------
    >>> import numpy as np
    >>> circle = np.column_stack([np.cos(np.arange(12) * np.pi / 6), np.sin(np.arange(12) * np.pi / 6)])
    >>> rips_persistence(circle, max_dim=2).betti(0.4)
    [1, 1]

    A square of side 2: its loop is born with the sides (ε = 1) and dies with the diagonals; its
    cocycle is one side, the last of the four in the filtration (vertices 1 and 0, coefficient 1):

    >>> square = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    >>> barcode, cocycles = rips_persistence(square, max_dim=2, cocycles=True)
    >>> barcode.intervals(1).round(3).tolist(), cocycles[1][0].tolist()
    ([[1.0, 1.414]], [[1, 0, 1]])

    Its cycle is the four sides (the last, 2-3, creates the loop); over Z/3 the signs show:

    >>> barcode, cycles = rips_persistence(square, max_dim=2, coefficients=3, cycles=True)
    >>> cycles[1][0].tolist()
    [[0, 1, 1], [0, 3, 2], [1, 2, 1], [2, 3, 1]]
    """
    max_dim = check_max_dim(max_dim, maximum=MAX_DIM)
    if max_dim < 1:
        raise ValueError("max_dim must be >= 1: the top dimension of the complex has no complete homology")
    field = parse_field(coefficients, default=2, field=True)
    threads = 0 if n_threads is None else check_int(n_threads, "n_threads", minimum=1)
    eps = check_radius(max_radius)
    min_persistence = check_min_persistence(min_persistence)
    cocycles, cycles = check_flag(cocycles, "cocycles"), check_flag(cycles, "cycles")
    source = parse_rips_input(points, distance_matrix, sparse=True)
    out = rips_barcode(source, eps, max_dim, field, stats=stats, n_threads=threads, min_persistence=min_persistence,
                       cocycles=cocycles)
    if not cycles:
        return out
    barcode = out[0] if cocycles else out
    reps = bar_cycles(source, eps, field, barcode, range(1, max_dim))
    return (*out, reps) if cocycles else (barcode, reps)


def rips_barcode(source: Points | np.ndarray | Edges, max_radius: float, max_dim: int, field: Field, *,
                 stats: dict[int, dict[str, int]] | None = None, n_threads: int = 0,
                 min_persistence: float = 0.0, cocycles: bool = False) -> Barcode | tuple[Barcode, Cocycles]:
    """:func:`rips_persistence` on parsed input (the implicit engine's one entry point).

    Thesis: Definition 2.11 (Rips) and Theorem 2.39 (the pairs, by the dual reduction).

    Parameters
    ----------
    source : Points, numpy.ndarray or Edges
        The parsed point cloud or distance matrix (``parse_rips_input``).
    max_radius : float
        The checked scale ε.
    max_dim : int
        The checked largest simplex dimension, >= 1.
    field : Field
        The parsed coefficient field (a prime).
    stats : dict, optional
        Filled as by :func:`rips_persistence`.
    n_threads : int
        Threads for assembling the columns; 0: ``OMP_NUM_THREADS`` when set, else every core.
    min_persistence : float
        The checked ``min_persistence`` of :func:`rips_persistence`.
    cocycles : bool
        Also return the representative cocycles, as :func:`rips_persistence`.

    Returns
    -------
    Barcode
        As :func:`rips_persistence`.
    dict of int to list of numpy.ndarray
        Only with ``cocycles``: as :func:`rips_persistence`.

    Raises
    ------
    ValueError
        More edges than ``MAX_SIMPLICES``, or simplex indices that would overflow 64 bits.
    """
    (n, indptr, nbr, length), births = _graph(source, max_radius)
    asked, max_dim = max_dim, min(max_dim, n + 1)  # no simplex has more than n vertices: H_k = 0 for k >= n
    if math.comb(n, max_dim + 1) >= 2**62:
        raise ValueError(f"{n} points with max_dim={max_dim}: simplex indices would overflow 64 bits")
    options = implicit_rips.Options()
    options.max_dim, options.p, options.dense = max_dim, field.p, _dense(n, nbr.shape[0])
    options.n_threads, options.parallel_min, options.cocycles = n_threads, PARALLEL_MIN, cocycles
    dims = implicit_rips.rips_barcode(
        n, np.ascontiguousarray(indptr, dtype=np.int64), np.ascontiguousarray(nbr, dtype=np.int64),
        np.ascontiguousarray(length, dtype=np.float64), np.ascontiguousarray(births, dtype=np.float64), options)
    intervals: dict[int, np.ndarray] = {}
    reps: Cocycles = {k: [] for k in range(1, asked)}
    for k, (births, deaths, ess, counts, offsets, rows) in enumerate(dims):
        iv = np.empty((births.shape[0] + ess.shape[0], 2))
        iv[: births.shape[0], 0] = births
        iv[: births.shape[0], 1] = deaths
        iv[births.shape[0] :, 0] = ess
        iv[births.shape[0] :, 1] = np.inf
        intervals[k] = iv * 0.5  # diameters -> ε
        if cocycles and k > 0:
            reps[k] = _bar_cocycles(intervals[k], offsets, rows, min_persistence)
        if stats is None:
            continue
        if k == 0:
            stats[0] = {"simplices": n, "apparent": 0, "columns": n, "emergent": 0, "reduced": 0, "additions": 0}
        else:
            stats[k] = dict(zip(("simplices", "apparent", "columns", "emergent", "reduced", "additions", "entries",
                                 "enumerators"), (int(x) for x in counts)))
    barcode = Barcode(intervals, dimensions=range(asked), coefficients=field, min_persistence=min_persistence)
    return (barcode, reps) if cocycles else barcode


def _bar_cocycles(intervals: np.ndarray, offsets: np.ndarray, rows: np.ndarray,
                  min_persistence: float) -> list[np.ndarray]:
    """The engine's cocycles (one per row of ``intervals``: rows ``offsets[i] .. offsets[i + 1]``) in the
    order of the barcode's intervals (the same rows kept, sorted the same way)."""
    parts = np.split(rows, offsets[1:-1])
    _, order = canonical_intervals(intervals, np.arange(intervals.shape[0]), min_persistence)
    return [parts[i] for i in order]

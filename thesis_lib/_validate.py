"""Validation at the public edge: every public function checks its input here, in one call.

Each checker returns the value in the form the kernels expect (a float64 array, an int, ...) or
raises ``ValueError`` (a value that cannot be used) or :class:`InvalidTypeError` (a value of the wrong
kind; both a ``ValueError`` and a ``TypeError``), with a message that names the argument and the
problem.  Internal kernels trust what comes out.

Some inputs are parsed into small frozen records that the internal functions take instead of raw
values, so nothing is checked twice: :class:`Points` (the array and its exact power-of-two scaling,
shared by every Rips path), :class:`Edges` (a sparse distance matrix as an edge list) and
:class:`Field` (0 = Z or a prime p).  A public function parses each argument once, in one line, and
passes the records inward.

The names follow the project's vocabulary (DESIGN.md, ``book/api.md``): ``points``,
``max_radius`` (ε, diameter ≤ 2ε), ``max_dim``, ``weights`` (the points' squared radii),
``coefficients`` (0 = Z, a prime p = Z/p), ``seed``.
"""

from __future__ import annotations

import math
import numbers
import operator
import os
import sys
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

__all__ = [
    "as_distance_matrix",
    "InvalidTypeError",
    "as_points",
    "Points",
    "parse_points",
    "looks_like_distance_matrix",
    "warn_user",
    "power_of_two_scale",
    "scale_points",
    "Edges",
    "parse_sparse_distances",
    "parse_rips_input",
    "Field",
    "parse_field",
    "check_radius",
    "check_max_dim",
    "check_min_persistence",
    "SCALES",
    "check_scale",
    "check_weights",
    "check_int",
    "check_seed",
    "check_size",
    "check_coefficients",
    "resolve_coefficients",
    "vertex_label",
    "is_prime",
    "MAX_PRIME",
    "MAX_EXACT_PRIME",
    "MAX_SIMPLICES",
    "MAX_DIM",
    "MAX_BYTES",
    "MAX_WORK",
    "check_memory",
    "check_complex_size",
    "MAX_LABEL",
    "check_real",
    "check_indices",
    "check_simplices",
    "check_shape",
    "as_floats",
    "check_length",
]

#: the largest prime the int64 Z/p kernels accept: products of two residues must fit in an int64
MAX_PRIME = 2**31 - 1

#: the largest modulus whose primality the deterministic Miller–Rabin below decides exactly; the
#: exact (Python-integer) kernels of homology over Z/p accept primes up to here
MAX_EXACT_PRIME = 3_317_044_064_679_887_385_961_980

#: default cap on the number of simplices (or samples) a construction may build before it refuses;
#: about 16 bytes a simplex-vertex, 10^9 simplices is already tens of GB
MAX_SIMPLICES = 10**9


#: the largest homology dimension a function that lists every dimension up to ``max_dim`` accepts
#: (a barcode's dimensions, persistence diagrams): a simplex of dimension 10⁴ has 2^(10⁴+1) faces
MAX_DIM = 10_000

#: memory budget of one construction (bytes) for the refusals that estimate memory, not counts:
#: 8 GiB, a third of this project's 23 GiB build machine and what a laptop can hold
MAX_BYTES = 8 * 2**30

#: work budget (elementary steps of a compiled loop, about 4·10⁸ a second on one core) for the
#: constructions whose cost grows exponentially with the simplex size (the Čech complex's exact
#: enclosing balls): 10¹⁰ steps is about half a minute
MAX_WORK = 10**10


class InvalidTypeError(ValueError, TypeError):
    """An argument of the wrong kind (a string for a number, a float for a count, ...).

    It is both a ``TypeError`` and a ``ValueError`` (as scikit-learn's ``InvalidParameterError``),
    so ``except ValueError`` catches every input error of the library.
    """


# ---------------------------------------------------------------------------------------- numbers
def check_int(value, name: str, *, minimum: int | None = None, maximum: int | None = None) -> int:
    """``value`` as a Python int (bools and non-integral numbers refused), within the bounds."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InvalidTypeError(f"{name} must be an integer, got {value!r}")
    v = int(value)
    if minimum is not None and v < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {v}")
    if maximum is not None and v > maximum:
        raise ValueError(f"{name} must be <= {maximum}, got {v}")
    return v


def check_flag(value, name: str) -> bool:
    """A yes/no option: True or False (numpy's too, and the integers 0 and 1); anything else refused."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and int(value) in (0, 1):
        return bool(value)
    raise InvalidTypeError(f"{name} must be True or False, got {value!r}")


def check_seed(seed, *, optional: bool = False) -> int | None:
    """A random seed: a non-negative integer (every random draw of the library takes one).

    Bools, floats, strings, lists and arrays are refused by name (``numpy.random.default_rng``
    would take ``True`` or ``[1, 2]`` as a seed, or fail deep inside ``SeedSequence``);
    ``optional=True`` lets ``None`` through (a function whose default is a fixed order).
    """
    if seed is None and optional:
        return None
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral):
        raise InvalidTypeError(f"seed must be a non-negative integer{' or None' if optional else ''}, "
                               f"got {seed!r} ({type(seed).__name__})")
    return check_int(seed, "seed", minimum=0)


def check_size(count: int, what: str, *, limit: int = MAX_SIMPLICES) -> int:
    """Refuse up front a construction that would build ``count`` objects, more than ``limit``."""
    if count > limit:
        raise ValueError(f"this would build {count:,} {what}, more than the limit of {limit:,}; "
                         "reduce the input or the parameters")
    return int(count)


def _as_float(value: numbers.Real, name: str, *, hint: str = "") -> float:
    """``float(value)``; an integer (or fraction) beyond float64's range is refused by name."""
    try:
        return float(value)
    except OverflowError:
        size = f"an integer of {int(value).bit_length():,} bits" if isinstance(value, numbers.Integral) else "a number"
        raise ValueError(f"{name} is {size}, beyond float64's range (about 1.8e308){hint}") from None


def check_memory(nbytes: float, what: str, *, limit: int = MAX_BYTES) -> None:
    """Refuse up front a construction whose arrays would take ``nbytes``, more than ``limit``.

    The message gives the estimate in GiB and names what would be allocated (``what``), as
    :func:`check_size` does for counts.
    """
    if nbytes > limit:
        raise ValueError(f"this would allocate about {nbytes / 2**30:,.3g} GiB for {what}, more than the "
                         f"memory budget of {limit / 2**30:.3g} GiB; reduce the input or the parameters")


#: the largest vertex label: labels are stored as int64
MAX_LABEL = 2**63 - 1

#: bytes per vertex entry of a closed complex (an int64 in the per-dimension vertex arrays, and the
#: same face as a row index and a coefficient of a boundary matrix)
_BYTES_PER_ENTRY = 24

#: steps per vertex entry of a closure, to build it and reduce its boundary matrices (measured:
#: homology of a simplex of 20 vertices, 10⁷ entries, takes 9 s; morse_matching of 18, 2.4·10⁶, 2 s)
_STEPS_PER_ENTRY = 400


def check_complex_size(simplices, what: str = "the complex"):
    """Refuse up front a complex whose closure under faces cannot fit in :data:`MAX_BYTES`, or
    whose building and reduction would take more than :data:`MAX_WORK` steps.

    A simplex of k vertices has 2^k − 1 faces holding k·2^(k−1) vertex entries, so one 27-simplex
    is 2.7·10⁸ faces and 84 GiB; a 21-simplex (22 vertices, 4.6·10⁷ entries, about 45 s) is over
    the work budget.  The bound sums this over the given simplices (an upper bound: shared faces
    are counted once per simplex).  ``Filtration``-like objects (already built) and input that
    cannot be measured cheaply pass unchanged; the builder validates them.

    Returns
    -------
    The input, or a list of it when it was a one-shot iterator (a generator), so the caller can use
    it again.
    """
    if isinstance(simplices, np.ndarray):
        if simplices.ndim != 2 or simplices.size == 0:
            return simplices
        groups = [(int(simplices.shape[1]), int(simplices.shape[0]))]
    elif isinstance(simplices, (list, tuple)):
        if simplices and all(isinstance(a, np.ndarray) and a.ndim == 2 for a in simplices):
            groups = [(int(a.shape[1]), int(a.shape[0])) for a in simplices]
        else:
            try:
                lengths = np.fromiter((len(s) for s in simplices), dtype=np.int64, count=len(simplices))
            except TypeError:
                return simplices  # not a list of sequences: the builder says what is wrong
            counts = np.bincount(lengths) if lengths.size else np.zeros(0, np.int64)
            groups = [(k, int(c)) for k, c in enumerate(counts) if c and k]
    elif hasattr(simplices, "__iter__") and not hasattr(simplices, "__len__") and not hasattr(simplices, "simplices"):
        return check_complex_size(list(simplices), what)
    else:
        return simplices
    faces = sum(c * (2**k - 1) for k, c in groups)
    entries = sum(c * k * 2 ** (k - 1) for k, c in groups)
    top = max((k for k, _ in groups), default=0)
    where = f"the closure of {what} under faces (up to {faces:,} faces; its largest simplex has {top} vertices)"
    check_memory(entries * _BYTES_PER_ENTRY, where)
    if entries * _STEPS_PER_ENTRY > MAX_WORK:
        raise ValueError(f"{where[0].upper()}{where[1:]} would take about {entries * _STEPS_PER_ENTRY:.2g} steps to "
                         f"build and reduce, more than the work budget of {MAX_WORK:.0e} (about half a minute); "
                         "reduce the input")
    return simplices


def check_radius(max_radius, name: str = "max_radius") -> float:
    """A scale parameter ε: a non-negative number (``inf`` allowed: no bound).

    Thesis: Definition 2.11 (the Rips parameter ε; diameter ≤ 2ε).
    """
    if isinstance(max_radius, bool) or not isinstance(max_radius, numbers.Real):
        raise InvalidTypeError(f"{name} must be a number, got {max_radius!r}")
    r = _as_float(max_radius, name, hint="; use inf for no bound")
    if math.isnan(r):
        raise ValueError(f"{name} is NaN")
    if r < 0:
        raise ValueError(f"{name} must be non-negative, got {r}")
    return r


def check_min_persistence(min_persistence) -> float:
    """The ``min_persistence`` option of the barcodes: a finite number >= 0; bars with
    death − birth <= it are dropped (0: only the zero-length ones, as always).

    Thesis: §2.3 (short bars are noise; a bar of length 0 is no class at all).
    """
    return check_real(min_persistence, "min_persistence", minimum=0.0)


#: the choices of the ``scale`` option of the persistence diagrams and the factor each multiplies a
#: barcode's values by: ε (the thesis's Rips radius, Definition 2.11; "radius" is the same) or the
#: diameter 2ε (the values of ripser.py, giotto-ph and persim)
SCALES = {"epsilon": 1.0, "radius": 1.0, "diameter": 2.0}


def check_scale(scale) -> float:
    """The factor of a ``scale`` option (:data:`SCALES`), or a ``ValueError`` naming the choices.

    Thesis: Definition 2.11 (ε, with diameter ≤ 2ε).
    """
    check_choice(scale, SCALES, "scale")
    return SCALES[scale]


def check_max_dim(max_dim, name: str = "max_dim", *, maximum: int | None = None) -> int:
    """A largest simplex dimension: an integer >= 0 (and <= ``maximum`` when given, e.g.
    :data:`MAX_DIM` where every dimension up to it is allocated)."""
    return check_int(max_dim, name, minimum=0, maximum=maximum)


# ---------------------------------------------------------------------------------------- points
def float_array(value, *, kind: str, message: str) -> np.ndarray:
    """``value`` as a float64 array; :class:`InvalidTypeError` ``"<message>: <reason>"`` for complex
    numbers (``kind``: what they are not) or anything that is not numeric."""
    if isinstance(value, (str, bytes, dict, set, frozenset)) or value is None:
        raise InvalidTypeError(f"{message}: got {'None' if value is None else 'a ' + type(value).__name__}")
    try:
        if np.iscomplexobj(value):
            raise TypeError(f"complex numbers are not {kind}")
        return np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as err:
        why = "its rows have different lengths (a ragged list)" if "inhomogeneous" in str(err) else str(err)
        raise InvalidTypeError(f"{message}: {why}") from None


def as_points(points, *, min_points: int = 1, allow_duplicates: bool = True, name: str = "points",
              dimension: int | None = None) -> np.ndarray:
    """Return ``points`` as a finite ``(n, d)`` float64 array, or raise naming the problem.

    Thesis: §2.1.2 (a point set X in R^d).

    ``dimension`` fixes d (points in R^d only).  A :class:`Points` record is already parsed: its
    array is returned as it is, unless it may hold duplicates that ``allow_duplicates=False``
    refuses, has fewer than ``min_points`` rows or lives in another dimension.
    """
    if isinstance(points, Points) and points.satisfies(min_points=min_points, allow_duplicates=allow_duplicates,
                                                       dimension=dimension):
        return points.array
    if isinstance(points, Points):
        points = points.array
    arr = float_array(points, kind="coordinates", message=f"{name} must be an (n, d) array of numbers")
    if arr.ndim != 2:
        raise ValueError(f"{name} must be an (n, d) array, got shape {arr.shape}")
    if arr.shape[0] < min_points:
        raise ValueError(f"need at least {min_points} {name}, got {arr.shape[0]}")
    if arr.shape[1] == 0:
        raise ValueError(f"{name} must have at least one coordinate")
    if dimension is not None and arr.shape[1] != dimension:
        raise ValueError(f"{name} must lie in R^{dimension} (an (n, {dimension}) array), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        row = int(np.argmax(~np.all(np.isfinite(arr), axis=1)))
        raise ValueError(f"{name}: row {row} has a NaN or infinite coordinate")
    if not allow_duplicates and arr.shape[0] > 1:
        uniq, inverse, counts = np.unique(arr, axis=0, return_inverse=True, return_counts=True)
        if uniq.shape[0] != arr.shape[0]:
            dup = np.flatnonzero(counts[inverse.ravel()] > 1)[:2]
            raise ValueError(f"duplicate {name}: rows {int(dup[0])} and {int(dup[1])} are equal")
    return arr


def as_distance_matrix(distance_matrix) -> np.ndarray:
    """A dense distance matrix: a non-empty square, symmetric float64 array without NaN or negative
    entries (C-contiguous), or a ``ValueError`` saying what is wrong (an :class:`InvalidTypeError`
    for a string, a dict, a ragged list or anything that is not numbers)."""
    dm = float_array(distance_matrix, kind="distances", message="distance_matrix must be an (n, n) array of numbers")
    if dm.ndim != 2 or dm.shape[0] != dm.shape[1] or dm.shape[0] == 0:
        raise ValueError(f"distance_matrix must be a non-empty square (n, n) array, got shape {dm.shape}")
    if np.isnan(dm).any():
        raise ValueError("distance_matrix contains NaN")
    if np.any(dm < 0):
        raise ValueError("distance_matrix has a negative distance")
    if not np.allclose(dm, dm.T, rtol=1e-12, atol=0):
        raise ValueError("distance_matrix is not symmetric")
    return np.ascontiguousarray(dm)


# ---------------------------------------------------------------------------------------- parsed points
def power_of_two_scale(points: np.ndarray) -> int:
    """The exponent e such that ``points * 2**e`` has its largest |coordinate| in [0.5, 1).

    Thesis: §2.1.2 (the complexes depend on the points only up to similarity).  0 when every
    coordinate is 0 or there are none.
    """
    top = float(np.max(np.abs(points))) if points.size else 0.0
    if top == 0.0:
        return 0
    return -math.frexp(top)[1]


def scale_points(points: np.ndarray, exponent: int, name: str = "points") -> np.ndarray:
    """``points * 2**exponent`` (exact), refusing when that loses digits (coordinates spanning
    more than about 10³⁰⁰) or overflows; ``name`` is the argument named in the message."""
    with np.errstate(over="ignore", under="ignore"):
        out = np.ldexp(points, exponent)
    if exponent > 0 and not np.all(np.isfinite(out)):
        raise ValueError(f"{name} span too many orders of magnitude for float64 (rescaling overflows)")
    if exponent < 0 and not np.array_equal(np.ldexp(out, -exponent), points):
        raise ValueError(f"{name} span too many orders of magnitude for float64: the smallest nonzero "
                         "coordinates would lose digits when the largest are brought near 1")
    return out


@dataclass(frozen=True, eq=False)
class Points:
    """A point cloud parsed once (:func:`parse_points`); what the constructions on points take.

    ``array`` is the ``(n, d)`` float64 array (C-contiguous, finite), ``exponent`` the power of two
    e of :func:`power_of_two_scale` and ``scaled`` the exact copy ``array * 2**e``, whose largest
    |coordinate| is in [0.5, 1): squared distances on it neither overflow nor underflow, and
    lengths computed on it scale back by 2^(−e) exactly.  Every Rips path computes its distances on
    ``scaled``, so they all see the same numbers.
    """

    array: np.ndarray
    exponent: int
    scaled: np.ndarray
    distinct: bool = False  #: parsed with ``allow_duplicates=False``: no two rows are equal

    def satisfies(self, *, min_points: int, allow_duplicates: bool, dimension: int | None = None) -> bool:
        """Whether this record meets the options of :func:`as_points` without being checked again."""
        return ((allow_duplicates or self.distinct) and self.n >= min_points
                and (dimension is None or self.array.shape[1] == dimension))

    @property
    def n(self) -> int:
        """The number of points."""
        return int(self.array.shape[0])


#: the folder of the package: :func:`warn_user` names the first frame outside it
_PACKAGE_DIR = str(Path(__file__).resolve().parent) + os.sep


def warn_user(message: str, category: type[Warning] = UserWarning) -> None:
    """``warnings.warn(message, category)`` attributed to the first caller outside ``thesis_lib``.

    A public function warns through this whatever its depth of internal calls, so the warning
    names the user's line (and the default filter shows it once per such line).
    """
    frame, level = sys._getframe(0), 1
    while frame is not None and str(Path(frame.f_code.co_filename).resolve()).startswith(_PACKAGE_DIR):
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)


def looks_like_distance_matrix(arr: np.ndarray) -> bool:
    """Whether a checked ``(n, d)`` point array is also a distance matrix: n = d >= 2, symmetric,
    a zero diagonal and no negative entry (what a user meaning ``distance_matrix=`` would pass)."""
    n, d = arr.shape
    return bool(n == d >= 2 and not np.diagonal(arr).any() and np.all(arr >= 0)
                and np.allclose(arr, arr.T, rtol=1e-12, atol=0))


def parse_points(points, *, min_points: int = 1, allow_duplicates: bool = True, name: str = "points",
                 warn_square: bool = False) -> Points:
    """``points`` checked by :func:`as_points` and scaled by a power of two, as a :class:`Points`.

    Thesis: §2.1.2 (a point set X in R^d, up to similarity).

    ``warn_square=True`` (the front doors ``rips``, ``rips_persistence``, ``RipsDiagrams`` and
    ``cech``) warns, once, when the array :func:`looks_like_distance_matrix`: it is read as n points
    in R^n (as ripser.py reads it, with a warning too), and a distance matrix has its own keyword.
    A :class:`Points` record that satisfies the options is returned as it is.
    """
    if isinstance(points, Points) and points.satisfies(min_points=min_points, allow_duplicates=allow_duplicates):
        return points
    arr = np.ascontiguousarray(as_points(points, min_points=min_points, allow_duplicates=allow_duplicates, name=name))
    if warn_square and looks_like_distance_matrix(arr):
        n = arr.shape[0]
        warn_user(f"{name} is a square ({n}, {n}) array, symmetric with a zero diagonal: it is read as {n} points "
                  f"in R^{n}; a distance matrix goes to distance_matrix= (rips, rips_persistence)")
    e = power_of_two_scale(arr)
    return Points(arr, e, arr if e == 0 else np.ascontiguousarray(scale_points(arr, e, name)), not allow_duplicates)


@dataclass(frozen=True, eq=False)
class Edges:
    """A weighted graph on ``n`` vertices parsed once (a sparse distance matrix, :func:`parse_sparse_distances`):
    ``edges`` the ``(m, 2)`` int64 pairs i < j in lexicographic order, ``lengths`` their distances,
    ``births`` the diagonal (the vertices' filtration values, 0 where nothing is stored)."""

    n: int
    edges: np.ndarray
    lengths: np.ndarray
    births: np.ndarray


def parse_sparse_distances(matrix) -> Edges:
    """A scipy.sparse distance matrix as :class:`Edges`: its stored off-diagonal entries are the
    edges, its stored diagonal entries the vertices' births (as ripser reads them); a non-square
    shape, NaN, a negative entry, or (i, j) and (j, i) stored with different values are refused."""
    coo = matrix.tocoo()
    shape = coo.shape
    if len(shape) != 2 or shape[0] != shape[1] or shape[0] == 0:
        raise ValueError(f"distance_matrix must be a non-empty square (n, n) matrix, got shape {shape}")
    n = int(shape[0])
    r, c, v = np.asarray(coo.row, np.int64), np.asarray(coo.col, np.int64), np.asarray(coo.data, np.float64)
    if np.isnan(v).any():
        raise ValueError("distance_matrix contains NaN")
    if (v < 0).any():
        raise ValueError("distance_matrix has a negative distance")
    off = r != c
    births = np.zeros(n)
    np.maximum.at(births, r[~off], v[~off])
    r, c, v = r[off], c[off], v[off]
    key = np.minimum(r, c) * n + np.maximum(r, c)
    order = np.lexsort((v, key))
    key, v = key[order], v[order]
    first = np.ones(key.shape[0], dtype=bool)
    first[1:] = key[1:] != key[:-1]
    dup = np.flatnonzero(~first)
    if dup.size and not np.allclose(v[dup], v[dup - 1], rtol=1e-12, atol=0):
        raise ValueError("distance_matrix is not symmetric: an entry (i, j) differs from (j, i)")
    key, v = key[first], v[first]
    return Edges(n, np.column_stack([key // n, key % n]).astype(np.int64).reshape(-1, 2), np.ascontiguousarray(v),
                 births)


def parse_rips_input(points, distance_matrix, *, sparse: bool = False) -> Points | np.ndarray | Edges:
    """Exactly one of a point cloud (:func:`parse_points`) and a distance matrix: dense
    (:func:`as_distance_matrix`) or, with ``sparse``, a scipy.sparse one (:func:`parse_sparse_distances`).

    Thesis: Definition 2.11 (the Rips complex of a finite metric space).
    """
    if (points is None) == (distance_matrix is None):
        raise ValueError("give exactly one of points and distance_matrix")
    if distance_matrix is None:
        return parse_points(points, warn_square=True)
    if sparse and hasattr(distance_matrix, "tocoo"):
        return parse_sparse_distances(distance_matrix)
    return as_distance_matrix(distance_matrix)


def check_weights(weights, n: int) -> np.ndarray:
    """Weights w_x >= 0 (squared radii of the weighted points, §2.1.2), one per point."""
    w = float_array(weights, kind="weights", message="weights must be an array of numbers")
    if w.ndim != 1 or w.shape[0] != n:
        raise ValueError(f"weights must be a 1-D array with one weight per point ({n}), got shape {w.shape}")
    if not np.all(np.isfinite(w)):
        raise ValueError(f"weight {int(np.argmax(~np.isfinite(w)))} is NaN or infinite")
    if np.any(w < 0):
        raise ValueError(f"weights are squared radii and must be >= 0; weight {int(np.argmax(w < 0))} is {w[w < 0][0]}")
    return w


# ---------------------------------------------------------------------------------------- simplices
def vertex_label(v) -> int:
    """A vertex label as a Python int: integers (and integral floats) only, never truncated."""
    try:
        return operator.index(v)
    except TypeError:
        pass
    if isinstance(v, numbers.Real) and not isinstance(v, bool) and math.isfinite(v) and float(v).is_integer():
        return int(v)
    raise ValueError(f"vertex labels must be integers, got {v!r}")


# ---------------------------------------------------------------------------------------- coefficients
def is_prime(n: int) -> bool:
    """Deterministic Miller–Rabin: exact for n below :data:`MAX_EXACT_PRIME` (3.3·10²⁴)."""
    if n >= MAX_EXACT_PRIME:
        raise ValueError(f"cannot decide exactly whether {n} is prime (above {MAX_EXACT_PRIME})")
    if n < 2:
        return False
    small = (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41)
    for q in small:
        if n % q == 0:
            return n == q
    d, r = n - 1, 0
    while d % 2 == 0:
        d, r = d // 2, r + 1
    for a in small:
        x = pow(a, d, n)
        if x in (1, n - 1):
            continue
        for _ in range(r - 1):
            x = x * x % n
            if x == n - 1:
                break
        else:
            return False
    return True


def check_coefficients(coefficients, *, field: bool = False, max_prime: int = MAX_PRIME) -> int:
    """``0`` for the integers Z or a prime p < 2³¹ for the field Z/p (DESIGN.md conventions).

    Thesis: §2.2.1 (homology with coefficients in Z and Z_p).

    ``field=True`` refuses Z (persistence needs a field).  Primes are checked exactly; primes above
    ``max_prime`` are refused: :data:`MAX_PRIME` for the kernels that multiply two residues in
    64 bits, :data:`MAX_EXACT_PRIME` for those on Python integers.
    """
    if isinstance(coefficients, bool) or not isinstance(coefficients, numbers.Integral):
        raise InvalidTypeError(f"coefficients must be 0 (the integers) or a prime, got {coefficients!r}")
    c = int(coefficients)
    if c == 0:
        if field:
            raise ValueError("this computation needs a field: coefficients must be a prime, not 0 (the integers)")
        return 0
    if c < 0:
        raise ValueError(f"coefficients must be 0 (the integers) or a prime, got {c}")
    if c > max_prime:
        raise ValueError(f"coefficients = {c} is too large: this computation needs a prime p <= {max_prime}")
    if not is_prime(c):
        raise ValueError(f"coefficients must be 0 (the integers) or a prime, got {c}")
    return c


def resolve_coefficients(coefficients, *, default: int, field: bool = False, max_prime: int = MAX_PRIME) -> int:
    """The ``coefficients`` argument checked by :func:`check_coefficients`; ``default`` when it is None.

    Call as ``resolve_coefficients(coefficients, default=2)`` from a public function whose
    signature is ``(..., coefficients=None, ...)``.
    """
    return check_coefficients(default if coefficients is None else coefficients, field=field, max_prime=max_prime)


@dataclass(frozen=True)
class Field:
    """Coefficients parsed once (:func:`parse_field`): ``p`` is 0 for the integers Z or a prime for Z/p.

    Thesis: §2.2.1 (homology with coefficients in Z and Z_p).
    """

    p: int

    @property
    def is_field(self) -> bool:
        """Whether the coefficients form a field (Z/p), as persistence needs."""
        return self.p != 0


def parse_field(coefficients, *, default: int | None = None, field: bool = False, max_prime: int = MAX_PRIME) -> Field:
    """The ``coefficients`` argument (``default`` when it is None and a default is given) checked by
    :func:`check_coefficients`, as a :class:`Field`; ``field=True`` refuses Z."""
    value = default if coefficients is None and default is not None else coefficients
    return Field(check_coefficients(value, field=field, max_prime=max_prime))


# ---------------------------------------------------------------------------------------- geometry
# (numbers, index arrays and simplex arrays for the complexes, curvature and meshes)
def check_real(value, name: str, *, minimum: float | None = None, positive: bool = False,
               finite: bool = True) -> float:
    """A real number as a float: not a bool or a string, not NaN, finite unless ``finite=False``,
    ``> 0`` with ``positive``, ``>= minimum`` when given."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InvalidTypeError(f"{name} must be a number, got {value!r}")
    x = _as_float(value, name)
    if math.isnan(x):
        raise ValueError(f"{name} is NaN")
    if finite and math.isinf(x):
        raise ValueError(f"{name} must be finite, got {x}")
    if positive and not x > 0:
        raise ValueError(f"{name} must be positive, got {x}")
    if minimum is not None and x < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {x}")
    return x


def check_indices(indices, n: int, name: str, *, unique: bool = False, allow_empty: bool = False) -> np.ndarray:
    """A 1-D array of integer indices into ``n`` items (0..n-1; negative indices are refused)."""
    arr = np.asarray(indices)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array of indices, got shape {arr.shape}")
    if arr.size == 0:
        if allow_empty:
            return np.empty(0, dtype=np.int64)
        raise ValueError(f"{name} is empty")
    if arr.dtype == bool or not np.issubdtype(arr.dtype, np.integer):
        raise InvalidTypeError(f"{name} must be integer indices, got dtype {arr.dtype}")
    arr = arr.astype(np.int64)
    bad = (arr < 0) | (arr >= n)
    if bad.any():
        first = int(np.argmax(bad))
        raise ValueError(f"{name} must be indices in 0..{n - 1}; entry {first} is {int(arr[first])}")
    if unique and np.unique(arr).size != arr.size:
        raise ValueError(f"{name} repeat an index")
    return arr


def check_simplices(simplices, n_vertices: int | None = None, name: str = "simplices", *,
                    width: int | None = None, allow_empty: bool = False) -> np.ndarray:
    """An ``(m, k)`` int64 array of vertex indices (each row one simplex, in the given order).

    Integral floats are accepted; indices must be >= 0 and < ``n_vertices`` when given; ``width``
    fixes k; a row may not repeat a vertex.
    """
    try:
        arr = np.asarray(simplices)
    except (TypeError, ValueError) as err:
        raise InvalidTypeError(f"{name} must be an (m, k) array of vertex indices: {err}") from None
    if arr.ndim != 2 or arr.shape[1] == 0:
        raise ValueError(f"{name} must be an (m, k) array of vertex indices, got shape {arr.shape}")
    if width is not None and arr.shape[1] != width:
        raise ValueError(f"{name} must have {width} vertices per row, got {arr.shape[1]}")
    if arr.shape[0] == 0 and not allow_empty:
        raise ValueError(f"{name} is empty")
    if arr.dtype == bool or not (np.issubdtype(arr.dtype, np.integer) or np.issubdtype(arr.dtype, np.floating)):
        raise InvalidTypeError(f"{name} must hold integer vertex indices, got dtype {arr.dtype}")
    if not np.issubdtype(arr.dtype, np.integer):
        if not np.all(np.isfinite(arr)) or not np.all(arr == np.round(arr)):
            raise ValueError(f"{name} must hold integer vertex indices")
    arr = arr.astype(np.int64)
    if arr.size:
        bad = (arr < 0) if n_vertices is None else (arr < 0) | (arr >= n_vertices)
        if bad.any():
            row = int(np.flatnonzero(bad.any(axis=1))[0])
            where = "negative" if n_vertices is None else f"outside 0..{n_vertices - 1}"
            raise ValueError(f"{name}: row {row} {arr[row].tolist()} has a vertex index {where}")
        srt = np.sort(arr, axis=1)
        rep = np.any(srt[:, 1:] == srt[:, :-1], axis=1)
        if rep.any():
            row = int(np.argmax(rep))
            raise ValueError(f"{name}: row {row} {arr[row].tolist()} repeats a vertex")
    return arr


def check_torus_radii(R: float, r: float) -> tuple[float, float]:
    """``(R, r)`` as floats, or ValueError unless 0 < r < R (a torus of revolution without
    self-intersection).

    Shared by the torus of §3.4.1 and the upright torus of Example 4.2.
    Thesis: §3.4.1 (the torus with radii R > r).

    Parameters
    ----------
    R : float
        Distance from the centre of the tube to the axis of revolution.
    r : float
        Radius of the tube.

    Returns
    -------
    R, r : float
        The radii as Python floats.

    Raises
    ------
    ValueError
        Unless both are finite and 0 < r < R (also when either is not a number).
    """
    R, r = float(R), float(r)
    if not (np.isfinite(R) and np.isfinite(r)) or r <= 0 or R <= r:
        raise ValueError(f"torus radii need 0 < r < R (finite; R > r > 0), got R={R!r}, r={r!r}")
    return R, r


def _shape_text(shape) -> str:
    """A shape pattern as the messages print it: ``(..., 3)``, ``(n, 2)``, ``(m, n + 1, d)``."""
    return "(" + ", ".join("..." if a is Ellipsis else str(a) for a in shape) + ")"


def _matches(actual: tuple, shape: tuple) -> bool:
    if Ellipsis in shape:
        cut = shape.index(Ellipsis)
        head, tail = shape[:cut], shape[cut + 1:]
        if len(actual) < len(head) + len(tail):
            return False
        return _matches(actual[:len(head)], head) and _matches(actual[len(actual) - len(tail):], tail)
    return len(actual) == len(shape) and all(not isinstance(a, int) or a == b for a, b in zip(shape, actual))


def check_shape(array: np.ndarray, shape: tuple, name: str) -> np.ndarray:
    """``array`` if its shape fits the pattern ``shape``, else a ``ValueError`` naming both.

    An int fixes an axis, a string names a free axis (``"n"``, ``"n + 1"``: printed, not checked),
    ``...`` stands for any number of leading or trailing axes.

    Thesis: the arrays of the constructions (§2.1 points, §3.3 simplices and parameters).

    Parameters
    ----------
    array : numpy.ndarray
        The array to check.
    shape : tuple
        The pattern: ints, strings and at most one ``...``.
    name : str
        The argument's name, for the message.

    Returns
    -------
    numpy.ndarray
        ``array``.

    Examples
    --------
    >>> check_shape(np.zeros((4, 3)), ("n", 3), "points").shape
    (4, 3)
    >>> check_shape(np.zeros((4, 2)), (..., 3), "points")
    Traceback (most recent call last):
    ...
    ValueError: points must have shape (..., 3), got (4, 2)
    """
    if not _matches(tuple(array.shape), tuple(shape)):
        raise ValueError(f"{name} must have shape {_shape_text(shape)}, got {tuple(array.shape)}")
    return array


def as_floats(value, name: str, *, shape: tuple | None = None) -> np.ndarray:
    """``value`` as a finite float64 array of the pattern ``shape`` (:func:`check_shape`), refusing
    what is not numeric (:class:`InvalidTypeError`) and NaN or infinite values.

    Thesis: the arrays of numbers the constructions take (§2.1, §3.3, §4.1).

    Parameters
    ----------
    value : array_like
        What the caller passed.
    name : str
        The argument's name, for the messages.
    shape : tuple, optional
        The shape pattern; any shape when omitted.

    Returns
    -------
    numpy.ndarray
        A float64 array.

    Examples
    --------
    >>> as_floats([[0, 1], [2, 3]], "params", shape=(..., 2)).dtype
    dtype('float64')
    >>> as_floats([1.0, float("nan")], "weights")
    Traceback (most recent call last):
    ...
    ValueError: weights contains NaN or infinite values
    """
    arr = float_array(value, kind="numbers", message=f"{name} must be an array of numbers")
    if shape is not None:
        check_shape(arr, shape, name)
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} contains NaN or infinite values")
    return arr


def check_length(items, name: str, *, minimum: int):
    """``items`` if ``len(items)`` is at least ``minimum``, else a ``ValueError`` naming the argument;
    a value without a length is an :class:`InvalidTypeError`.

    Thesis: the lists the book's functions take (the panels of a figure, the hyperplanes of a
    slicing, the models of a structure).

    Parameters
    ----------
    items : sized
        A list, tuple, mapping or array.
    name : str
        The argument's name, for the message.
    minimum : int
        The least length allowed.

    Returns
    -------
    sized
        ``items``.

    Examples
    --------
    >>> check_length(["a", "b"], "names", minimum=1)
    ['a', 'b']
    >>> check_length([], "levels", minimum=1)
    Traceback (most recent call last):
    ...
    ValueError: levels must hold at least 1 entry, got 0
    """
    try:
        n = len(items)
    except TypeError:
        raise InvalidTypeError(f"{name} must be a sequence, got {type(items).__name__}") from None
    if n < minimum:
        raise ValueError(f"{name} must hold at least {minimum} entr{'y' if minimum == 1 else 'ies'}, got {n}")
    return items


def check_choice(value, choices, name: str) -> str:
    """``value`` if it is one of the names ``choices``; a ``ValueError`` naming the argument and the
    choices otherwise (also for a value that is not a string, such as an array).

    Thesis: the named options of the constructions and estimators (§2.1 complexes, §3.3 vertex areas
    and estimators, §3.4 reconstructions).

    Parameters
    ----------
    value : object
        What the caller passed.
    choices : sequence of str
        The names allowed.
    name : str
        The argument's name, for the message.

    Returns
    -------
    str
        ``value``.

    Examples
    --------
    >>> check_choice("mixed", ("mixed", "voronoi"), "area")
    'mixed'
    """
    if isinstance(value, str) and value in choices:
        return value
    raise ValueError(f"{name} must be one of {', '.join(map(repr, choices))}, got {value!r}")

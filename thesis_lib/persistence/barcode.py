"""Barcodes: the P-intervals of a filtered complex, one ``(k, 2)`` array per homology dimension."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from .._validate import check_min_persistence, check_scale

if TYPE_CHECKING:
    from .._validate import Field

__all__ = ["Barcode"]


def _as_interval_array(rows: Any) -> np.ndarray:
    arr = np.asarray(rows, dtype=np.float64)
    if arr.size == 0:
        return np.empty((0, 2), dtype=np.float64)
    arr = arr.reshape(-1, 2)
    if np.isnan(arr).any():
        raise ValueError("persistence intervals must not contain NaN")
    if (arr[:, 1] < arr[:, 0]).any():
        i = int(np.argmax(arr[:, 1] < arr[:, 0]))
        raise ValueError(f"interval ({arr[i, 0]}, {arr[i, 1]}) dies before it is born")
    return arr


def _long_enough(arr: np.ndarray, min_persistence: float) -> np.ndarray:
    """The rows whose length death − birth exceeds ``min_persistence`` (0: every non-zero length)."""
    keep = arr[:, 1] > arr[:, 0]
    if min_persistence > 0:
        keep &= arr[:, 1] - arr[:, 0] > min_persistence
    return keep


def canonical_intervals(arr: np.ndarray, extra: np.ndarray | None = None,
               min_persistence: float = 0.0) -> tuple[np.ndarray, np.ndarray | None]:
    """Drop the intervals of length at most ``min_persistence`` (zero-length ones always) and sort by
    (birth, death) (two stable sorts: faster than lexsort), the order of every barcode.

    Thesis: Definition 2.23 (the P-intervals; their order is ours).

    Parameters
    ----------
    arr : ndarray of float64, shape (k, 2)
        Intervals (birth, death).
    extra : ndarray or None
        Rows carried along (kept and reordered with the intervals), or None.
    min_persistence : float
        Intervals of length at most this are dropped.

    Returns
    -------
    intervals : ndarray of float64, shape (k', 2)
        The intervals kept, sorted.
    extra : ndarray or None
        ``extra`` kept and sorted alike.
    """
    keep = _long_enough(arr, min_persistence)
    if not keep.all():
        arr = arr[keep]
        extra = None if extra is None else extra[keep]
    b, d = arr[:, 0], arr[:, 1]
    if arr.shape[0] > 1 and not _is_sorted(b, d):
        if np.isinf(d).all():
            order = np.argsort(b, kind="stable")
        else:
            order = np.argsort(d, kind="stable")
            order = order[np.argsort(b[order], kind="stable")]
        arr = arr[order]
        extra = None if extra is None else extra[order]
    arr = np.ascontiguousarray(arr)
    if extra is not None:
        extra = np.ascontiguousarray(extra)
    return arr, extra


def _is_sorted(b: np.ndarray, d: np.ndarray) -> bool:
    db = b[1:] - b[:-1]
    return bool(np.all((b[1:] > b[:-1]) | ((b[1:] == b[:-1]) & (d[1:] >= d[:-1])))) if db.size else True


def _dimension(dim) -> int:
    """A homology dimension: a non-negative integer (``1.5``, ``'1'`` and ``True`` are refused)."""
    from .._validate import check_int

    return check_int(dim, "homology dimension", minimum=0)


def _dimension_list(dims, name: str) -> list[int]:
    """An iterable of homology dimensions (a string or a single number is refused, not iterated)."""
    from .._validate import InvalidTypeError

    if isinstance(dims, (str, bytes)) or not isinstance(dims, Iterable):
        raise InvalidTypeError(f"{name} must be an iterable of homology dimensions (integers), got {dims!r}")
    return [_dimension(d) for d in dims]


def _field(p) -> int | None:
    """The coefficient field of a barcode: ``None`` (unknown) or a prime (a parsed field is taken as it is)."""
    from .._validate import MAX_EXACT_PRIME, Field, check_coefficients

    if p is None:
        return None
    if isinstance(p, Field) and p.is_field:
        return p.p

    return check_coefficients(p, field=True, max_prime=MAX_EXACT_PRIME)


def _tolerance(atol) -> float:
    """An absolute tolerance: a number >= 0 (``inf`` allowed), not NaN."""
    from .._validate import check_real

    return check_real(atol, "atol", minimum=0.0, finite=False)


def _diagram(arr: np.ndarray, factor: float, min_persistence: float) -> np.ndarray:
    """A writable copy of the intervals ``arr`` times ``factor`` (exact: 1 or 2), without the rows
    of length at most ``min_persistence``; a finite value that doubles to inf is refused."""
    with np.errstate(over="ignore"):
        out = arr * factor
    if factor != 1.0 and np.isinf(out).sum() != np.isinf(arr).sum():
        raise ValueError("a value of the barcode is beyond half of float64's range: its diameter does not fit")
    return out[_long_enough(out, min_persistence)] if min_persistence > 0 else out


#: the most persistence diagrams :meth:`Barcode.to_diagrams` returns (dimensions 0 .. 9999): a
#: homology dimension above it would need a simplex of more than 10⁴ vertices (2^(10⁴) faces)
MAX_DIAGRAMS = 10_000


class Barcode:
    """The barcode of a filtered complex: finite and infinite P-intervals ``(birth, death)`` per dimension.

    Thesis: Definition 2.34 and Corollary 2.35 (P-intervals ↔ graded F[t]-modules; the barcode).

    Intervals are half-open ``[birth, death)``; ``death = inf`` marks an essential class; intervals of
    length zero are left out (DESIGN.md conventions).  Within a dimension the intervals are sorted by
    ``(birth, death)``, so two barcodes are equal exactly when their arrays are.

    Parameters
    ----------
    intervals : mapping ``dim -> (k, 2)`` array-like of ``(birth, death)``.
    dimensions : homology dimensions that were computed (default: the keys of ``intervals``);
        a computed dimension may have no intervals.
    coefficients : the coefficient field Z/p the barcode was computed over: a prime, a parsed ``Field``,
        or ``None`` if unknown.
    simplices : optional mapping ``dim -> (k, 2)`` int array, parallel to ``intervals``: the index
        (into ``filtration.simplices[dim]``) of the simplex creating each class and the index (into
        ``filtration.simplices[dim + 1]``) of the simplex killing it, ``-1`` for an essential class.
    filtration : the filtration the barcode was computed from (needed for :meth:`representative`).
    killers : optional mapping ``dim -> indices`` of every (dim+1)-simplex that kills a dim-class,
        zero-length pairs included (needed for :meth:`representative`).
    essential : optional mapping ``dim -> (values, mask)``: the dimension's intervals are all
        essential, born at ``values[mask]`` by the simplices where the boolean ``mask`` is true;
        the arrays are only built (sorted) when first asked for (a truncated complex can have
        millions of top-dimensional classes).  ``intervals`` must not also give that dimension.
    complete : the dimensions whose intervals are the whole truth (default: all of ``dimensions``).
        The top dimension of a complex cut at ``max_dim`` (a Rips complex) is not complete: its
        classes could only die by simplices that were never built, so they show as essential.
        ``repr``, :meth:`betti` without a dimension, :meth:`to_diagrams`, comparisons and the plots
        use the complete dimensions; :meth:`intervals` still returns any computed dimension.
    min_persistence : intervals with ``death − birth <= min_persistence`` are left out (default 0:
        only the zero-length ones).  A tolerance for the bars of length ~1e-16 that tied distances
        give in floating point (ripser drops them: its distances are float32).

    Examples
    --------
    The barcode of the filtration of Figure 2.11 (Example 2.38) over Z/2:

    >>> from thesis_lib.datasets import example_filtration
    >>> from thesis_lib.persistence import persistence
    >>> barcode = persistence(example_filtration(), coefficients=2)
    >>> barcode
    Barcode(H0: 4 (1 essential), H1: 2 (1 essential), H2: 0 (0 essential))
    >>> barcode.intervals(1).tolist()
    [[2.0, inf], [3.0, 4.0]]
    """

    def __init__(
        self,
        intervals: Mapping[int, Any],
        *,
        dimensions: Iterable[int] | None = None,
        coefficients: int | Field | None = None,
        simplices: Mapping[int, np.ndarray] | None = None,
        filtration: Any = None,
        killers: Mapping[int, np.ndarray] | None = None,
        essential: Mapping[int, tuple[np.ndarray, np.ndarray]] | None = None,
        complete: Iterable[int] | None = None,
        min_persistence: float = 0.0,
    ):
        if not isinstance(intervals, Mapping):
            raise TypeError(f"intervals must be a mapping dim -> (k, 2) array, got {type(intervals).__name__}")
        given = _dimension_list(intervals.keys(), "the keys of intervals")
        dims = sorted(set(given if dimensions is None else _dimension_list(dimensions, "dimensions")))
        done = dims if complete is None else sorted(set(_dimension_list(complete, "complete")))
        if set(done) - set(dims):
            raise ValueError(f"complete dimensions {sorted(set(done) - set(dims))} were not computed")
        self._complete = tuple(done)
        self._min_persistence = check_min_persistence(min_persistence)
        extra_dims = set(given) - set(dims)
        if extra_dims:
            raise ValueError(f"intervals given for dimensions {sorted(extra_dims)} outside {dims}")
        self._dims = tuple(dims)
        self.coefficients = _field(coefficients)
        self.filtration = filtration
        # raw (validated) arrays; each dimension is put in canonical form on first use
        self._raw: dict[int, tuple[np.ndarray, np.ndarray | None]] = {}
        self._done: dict[int, tuple[np.ndarray, np.ndarray | None]] = {}
        self._has_simplices = simplices is not None
        intervals = dict(zip(given, intervals.values()))
        for d in dims:
            arr = _as_interval_array(intervals.get(d, []))
            extra = None
            if simplices is not None:
                extra = np.asarray(simplices.get(d, np.empty((0, 2))), dtype=np.int64).reshape(-1, 2)
                if extra.shape[0] != arr.shape[0]:
                    raise ValueError(f"dimension {d}: {arr.shape[0]} intervals but {extra.shape[0]} simplex pairs")
            self._raw[d] = (arr, extra)
        self._lazy: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        self._lazy_pairs: dict[int, np.ndarray] = {}
        for d, (vals, mask) in (essential or {}).items():
            d = _dimension(d)
            if d in intervals or d not in dims:
                raise ValueError(f"dimension {d} is given both as intervals and as essential classes")
            vals, mask = np.asarray(vals, dtype=np.float64), np.asarray(mask, dtype=bool)
            if vals.shape != mask.shape:
                raise ValueError(f"dimension {d}: {vals.shape[0]} values but a mask of {mask.shape[0]}")
            self._raw.pop(d, None)
            self._lazy[d] = (vals, mask)
        self._killers = None if killers is None else {int(d): np.asarray(k, dtype=np.int64) for d, k in killers.items()}
        self._representatives: dict[int, Any] = {}

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_pairs(cls, pairs: Iterable[tuple[int, tuple[float, float]]], *,
                   dimensions: Iterable[int] | None = None) -> Barcode:
        """Build from ``(dim, (birth, death))`` pairs, the format of GUDHI's ``persistence()``.

        Thesis: Definition 2.34 (a set of P-intervals per dimension).

        Parameters
        ----------
        pairs : iterable of (int, (float, float))
            ``(dim, (birth, death))`` per interval, ``death = inf`` for an essential class.
        dimensions : iterable of int, optional
            The dimensions computed (default: those that occur in ``pairs``); a dimension with no
            pair has no intervals.

        Returns
        -------
        Barcode
            Without simplices or coefficients (``coefficients`` is None).

        Examples
        --------
        >>> import numpy as np
        >>> b = Barcode.from_pairs([(0, (0.0, np.inf)), (0, (0.0, 1.0)), (1, (1.0, 2.0))])
        >>> b
        Barcode(H0: 2 (1 essential), H1: 1 (0 essential))
        >>> b.betti(1.5)
        [1, 1]
        """
        by_dim: dict[int, list[tuple[float, float]]] = {}
        for dim, (b, d) in pairs:
            by_dim.setdefault(_dimension(dim), []).append((float(b), float(d)))
        return cls(by_dim, dimensions=dimensions)

    @classmethod
    def from_diagrams(cls, diagrams: Iterable[Any], *, coefficients: int | None = None) -> Barcode:
        """Build from persistence diagrams in the ripser/persim format: ``diagrams[k]`` is a ``(m, 2)``
        array of ``(birth, death)`` of dimension k (``inf`` for essential classes).

        Thesis: Definition 2.34 (a set of P-intervals per dimension).  Values are taken as they
        are: ripser's are diameters (2ε), so halve them to compare with :func:`~thesis_lib.complexes.rips` (ε).

        Parameters
        ----------
        diagrams : sequence of array_like, shape (m, 2)
            ``diagrams[k]`` the ``(birth, death)`` rows of dimension k (``inf`` for essential classes).
        coefficients : int, optional
            The coefficient field Z/p they were computed over (``None``: unknown).

        Returns
        -------
        Barcode
            Dimensions 0 .. ``len(diagrams) − 1``, all complete.

        Raises
        ------
        TypeError
            ``diagrams`` is not a list of arrays.
        ValueError
            A diagram that is not ``(m, 2)``, a NaN, or a death before its birth.

        Examples
        --------
        The diagrams of the unit square in ripser's layout (ε values):

        >>> import numpy as np
        >>> b = Barcode.from_diagrams([np.array([[0.0, np.inf], [0.0, 0.5]]), np.array([[0.5, 0.71]])])
        >>> b.dimensions, b.betti(0.6)
        ((0, 1), [1, 1])
        """
        if isinstance(diagrams, (str, bytes, dict)) or not hasattr(diagrams, "__iter__"):
            raise TypeError(f"diagrams must be a list of (m, 2) arrays, got {type(diagrams).__name__}")
        coefficients = _field(coefficients)
        by_dim = {}
        for d, dgm in enumerate(diagrams):
            arr = np.asarray(dgm, dtype=np.float64)
            if arr.size and (arr.ndim != 2 or arr.shape[1] != 2):
                raise ValueError(f"diagram {d} must be an (m, 2) array, got shape {arr.shape}")
            by_dim[d] = arr.reshape(-1, 2)
        return cls(by_dim, dimensions=range(len(by_dim)), coefficients=coefficients)

    def to_diagrams(self, *, dims: Iterable[int] | None = None, scale: str = "epsilon",
                    min_persistence: float = 0.0) -> list[np.ndarray]:
        """The barcode as persistence diagrams (ripser/persim format): a list of ``(m, 2)`` arrays, one
        per dimension 0, 1, ... up to the largest complete one (or the given ``dims``' maximum).

        Thesis: Definition 2.34 and Theorem 2.37 (P-intervals drawn as points).  The values are
        this barcode's (ε for :func:`~thesis_lib.complexes.rips`), or twice them with
        ``scale="diameter"``: the diameters 2ε that ripser.py, giotto-ph and persim report.

        Parameters
        ----------
        dims : iterable of int, optional
            Only its maximum matters: diagrams are returned for 0 .. max(dims) (default: the complete
            dimensions).
        scale : {"epsilon", "radius", "diameter"}
            ``"epsilon"`` (default; ``"radius"`` is the same): the barcode's values, the thesis's ε;
            ``"diameter"``: the values doubled, ripser's convention for a Rips barcode (2ε).
        min_persistence : float
            Rows with ``death − birth <= min_persistence`` are left out, measured in the returned
            values (after ``scale``); default 0 (the zero-length bars are never there).

        Returns
        -------
        list of numpy.ndarray, shape (m, 2)
            ``diagrams[k]``: a writable copy of :meth:`intervals` ``(k)``, scaled and filtered.

        Raises
        ------
        TypeError
            ``dims`` is a string or holds a non-integer.
        ValueError
            A negative dimension, more than ``MAX_DIAGRAMS`` diagrams asked for, an unknown ``scale``,
            a negative, infinite or NaN ``min_persistence``, or a finite value that doubles beyond
            float64's range.

        Examples
        --------
        >>> bars = Barcode({0: [[0.0, 0.5], [0.0, np.inf]], 1: [[0.5, 0.75]]})
        >>> [d.tolist() for d in bars.to_diagrams(scale="diameter", min_persistence=0.6)]
        [[[0.0, 1.0], [0.0, inf]], []]
        """
        factor = check_scale(scale)
        min_persistence = check_min_persistence(min_persistence)
        dims = self._complete if dims is None else tuple(_dimension_list(dims, "dims"))
        top = max(dims, default=-1)
        if top >= MAX_DIAGRAMS:
            raise ValueError(f"dims asks for {top + 1:,} diagrams (0 .. {top:,}), more than the limit of "
                             f"{MAX_DIAGRAMS:,} (this barcode's dimensions are {list(self._dims)})")
        return [_diagram(self.intervals(d), factor, min_persistence) for d in range(top + 1)]

    # ------------------------------------------------------------------ queries
    @property
    def complete_dimensions(self) -> tuple[int, ...]:
        """The dimensions whose intervals are complete (the top dimension of a truncated complex is not).

        Thesis: Theorem 2.39 (a class of H_p dies only by a (p+1)-simplex, so H_p is known only when
        the (p+1)-simplices are all built).

        Examples
        --------
        A Rips complex cut at ``max_dim = 2`` has complete H_0 and H_1 only:

        >>> from thesis_lib.complexes import rips
        >>> from thesis_lib.persistence import persistence
        >>> barcode = persistence(rips([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], max_radius=1.0, max_dim=2))
        >>> barcode.dimensions, barcode.complete_dimensions
        ((0, 1, 2), (0, 1))
        """
        return self._complete

    @property
    def dimensions(self) -> tuple[int, ...]:
        """The homology dimensions this barcode covers (0 .. dim K for a computed barcode).

        Thesis: Algorithm 2 (one list L_p of P-intervals for p = 0 .. dim K).

        Examples
        --------
        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> persistence(example_filtration()).dimensions
        (0, 1, 2)
        """
        return self._dims

    def _get(self, dim: int) -> tuple[np.ndarray, np.ndarray | None]:
        if dim in self._lazy:
            vals, mask = self._lazy.pop(dim)
            births = vals[mask]
            # all deaths are ∞: equal births are interchangeable intervals, so an unstable (faster)
            # sort still gives the canonical array; the simplices follow the same permutation
            order = np.argsort(births)
            arr = np.empty((births.shape[0], 2))
            arr[:, 0] = births[order]
            arr[:, 1] = np.inf
            del births
            self._lazy_pairs[dim] = np.flatnonzero(mask)[order]  # the creating simplices, sorted
            del order
            arr.setflags(write=False)
            self._done[dim] = (arr, None)
        if dim not in self._done:
            if dim not in self._raw:
                return np.empty((0, 2), dtype=np.float64), np.empty((0, 2), dtype=np.int64)
            arr, extra = canonical_intervals(*self._raw.pop(dim), self._min_persistence)
            arr.setflags(write=False)
            if extra is not None:
                extra.setflags(write=False)
            self._done[dim] = (arr, extra)
        return self._done[dim]

    def intervals(self, dim: int) -> np.ndarray:
        """``(k, 2)`` read-only array of ``(birth, death)`` in dimension ``dim``, sorted; ``death = inf`` if essential.

        Thesis: Theorem 2.39 (the intervals read off the column-echelon form).

        Parameters
        ----------
        dim : int
            A homology dimension (non-negative; a dimension not computed has no intervals).

        Returns
        -------
        numpy.ndarray, shape (k, 2)
            Read-only, sorted by ``(birth, death)``, zero-length intervals left out.

        Examples
        --------
        Example 2.38: the components of a and b merge at 1; c and d, born at 1 and joined at once by cd,
        join them at 2; e, born at 2, joins at 3:

        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> persistence(example_filtration()).intervals(0).tolist()
        [[0.0, 1.0], [0.0, inf], [1.0, 2.0], [2.0, 3.0]]
        """
        return self._get(_dimension(dim))[0]

    def betti(self, value: float, *, dim: int | None = None) -> int | list[int]:
        """Betti number of ``H_dim`` of the complex at filtration value ``value``: bars with birth ≤ value < death.
        Without ``dim``: the list of Betti numbers of the complete dimensions.

        Thesis: §2.3.1, β_p^l = rank H_p^l (the special case k = 0 of Definition 2.23).

        Parameters
        ----------
        value : float
            The filtration value l; ``np.inf`` means the whole complex, whose Betti numbers are
            the essential classes (bars ``[b, ∞)``, GUDHI's ``betti_numbers()``).
        dim : int, optional
            The homology dimension; default: every complete dimension.

        Returns
        -------
        int or list of int
            β_dim at ``value``; a list over :attr:`complete_dimensions` when ``dim`` is None.

        Examples
        --------
        At value 2.5 the complex of Figure 2.11 has two components and one loop:

        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> barcode = persistence(example_filtration())
        >>> barcode.betti(2.5), barcode.betti(3.5, dim=1)
        ([2, 1, 0], 2)
        """
        if dim is None:
            return [self.persistent_betti(value, 0.0, dim=d) for d in self._complete]
        return self.persistent_betti(value, 0.0, dim=dim)

    def persistent_betti(self, l: float, k: float, *, dim: int) -> int:
        """Rank of the k-persistent homology group H_dim^{l,k}: intervals spanning ``[l, l + k]``.

        Thesis: Definition 2.23 and Theorem 2.37 (the rank equals the number of intervals spanning
        [l, l + k]); an interval ``[b, d)`` spans it when ``b ≤ l`` and ``d > l + k``.

        Parameters
        ----------
        l : float
            The filtration value where the classes must exist.
        k : float
            The persistence, ≥ 0: the classes must still be alive at ``l + k``; when ``l + k`` is
            ∞ (the whole complex) the classes alive there are the essential ones, ``[b, ∞)``.
        dim : int
            The homology dimension.

        Returns
        -------
        int
            The number of intervals spanning ``[l, l + k]``.

        Raises
        ------
        ValueError
            ``l`` or ``k`` NaN, or ``k < 0``.

        Examples
        --------
        One H_0 class alive all through [1, 2] (the essential one; [1, 2) itself dies at 2):

        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> persistence(example_filtration()).persistent_betti(1, 1, dim=0)
        1
        """
        l, k = float(l), float(k)
        if np.isnan(l) or np.isnan(k):
            raise ValueError("l and k must not be NaN")
        if k < 0:
            raise ValueError(f"the persistence k must be non-negative, got {k}")
        arr = self.intervals(dim)
        end = l + k
        alive = arr[:, 1] > end if end != np.inf else arr[:, 1] == np.inf  # no bar is alive after ∞
        return int(np.count_nonzero((arr[:, 0] <= l) & alive))

    def __len__(self) -> int:
        return int(sum(self.intervals(d).shape[0] for d in self._dims))

    def as_pairs(self) -> list[tuple[int, tuple[float, float]]]:
        """All intervals as ``(dim, (birth, death))`` pairs (GUDHI's format), by dimension then birth.

        Thesis: Definition 2.34 (the P-intervals of every dimension).

        Returns
        -------
        list of (int, (float, float))
            Every computed dimension's intervals, complete or not.

        Examples
        --------
        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> persistence(example_filtration()).as_pairs()[-2:]
        [(1, (2.0, inf)), (1, (3.0, 4.0))]
        """
        return [(d, (float(b), float(e))) for d in self._dims for b, e in self.intervals(d).tolist()]

    def longest(self, dim: int, *, n: int = 1) -> np.ndarray:
        """Indices (into :meth:`intervals`) of the ``n`` longest intervals in ``dim``, longest first.

        Thesis: §2.3 (long bars are the persistent features, short ones noise).

        Parameters
        ----------
        dim : int
            The homology dimension.
        n : int
            How many (≥ 0); fewer when the dimension has fewer intervals.

        Returns
        -------
        numpy.ndarray of int
            Row indices into ``intervals(dim)``; essential intervals count as longest, ties by birth.

        Examples
        --------
        Rows of ``intervals(0)``: the essential class first, then the longest finite one (ties by birth):

        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> persistence(example_filtration()).longest(0, n=2).tolist()
        [1, 0]
        """
        from .._validate import check_int

        n = check_int(n, "n", minimum=0)
        arr = self.intervals(dim)
        order = np.lexsort((arr[:, 0], -(arr[:, 1] - arr[:, 0])))
        return order[: int(n)]

    # ------------------------------------------------------------------ comparison
    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Barcode):
            return NotImplemented
        return self.difference(other, atol=0.0) is None

    __hash__ = None  # compared by value

    def allclose(self, other: Barcode, *, atol: float = 1e-9) -> bool:
        """Same intervals in every dimension up to ``atol`` (dimensions without intervals are ignored).

        Thesis: Corollary 2.35 (a barcode determines the persistence module up to isomorphism).

        Parameters
        ----------
        other : Barcode
            The barcode to compare with (complete dimensions of either are compared).
        atol : float
            Absolute tolerance on each finite birth and death; ``inf`` must meet ``inf``.

        Returns
        -------
        bool
            True when :meth:`difference` finds none.

        Examples
        --------
        The thesis's Algorithm 2 and the fast engine agree on Example 2.38:

        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import compute_intervals, persistence
        >>> compute_intervals(example_filtration(), coefficients=2).allclose(persistence(example_filtration()))
        True
        """
        return self.difference(other, atol=atol) is None

    def difference(self, other: Barcode, *, atol: float = 0.0) -> str | None:
        """``None`` if both barcodes agree up to ``atol``, else a message naming the first difference.

        Thesis: Corollary 2.35 (equal barcodes ⇔ isomorphic persistence modules).

        Parameters
        ----------
        other : Barcode
            The barcode to compare with, over the union of both complete dimensions.
        atol : float
            Absolute tolerance on each finite birth and death; ``inf`` must meet ``inf``.

        Returns
        -------
        str or None
            ``None`` when they agree, else e.g. ``"H1: 3 intervals vs 2"``.

        Raises
        ------
        TypeError
            ``other`` is not a Barcode, or ``atol`` is not a number.
        ValueError
            ``atol`` is NaN or negative.

        Examples
        --------
        >>> import numpy as np
        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> other = Barcode.from_pairs([(0, (0.0, np.inf)), (0, (0.0, 1.0)), (1, (1.0, 2.0))])
        >>> persistence(example_filtration()).difference(other)
        'H0: 4 intervals vs 2'
        """
        if not isinstance(other, Barcode):
            raise TypeError(f"other must be a Barcode, got {type(other).__name__}")
        atol = _tolerance(atol)
        for d in sorted(set(self._complete) | set(other.complete_dimensions)):
            a, b = self.intervals(d), other.intervals(d)
            if a.shape != b.shape:
                return f"H{d}: {a.shape[0]} intervals vs {b.shape[0]}"
            if a.size == 0:
                continue
            inf_a, inf_b = np.isinf(a), np.isinf(b)
            if not np.array_equal(inf_a, inf_b):
                return f"H{d}: the essential intervals differ"
            fa, fb = np.where(inf_a, 0.0, a), np.where(inf_b, 0.0, b)
            bad = np.abs(fa - fb) > atol
            if bad.any():
                i = int(np.argmax(bad.any(axis=1)))
                return f"H{d}: interval {tuple(a[i])} vs {tuple(b[i])}"
        return None

    def __repr__(self) -> str:
        parts = ", ".join(
            f"H{d}: {self.intervals(d).shape[0]} ({int(np.isinf(self.intervals(d)[:, 1]).sum())} essential)"
            for d in self._complete
        )
        rest = [d for d in self._dims if d not in self._complete]
        if rest:
            parts += "; " + ", ".join(f"H{d}" for d in rest) + " incomplete (top dimension of a truncated complex)"
        return f"Barcode({parts})"

    # ------------------------------------------------------------------ representatives
    def simplex_pairs(self, dim: int) -> np.ndarray:
        """``(k, 2)`` indices of the creating simplex (in ``simplices[dim]``) and killing one (in
        ``simplices[dim + 1]``, ``-1`` if essential) of each interval of :meth:`intervals`.

        Thesis: Algorithm 2 (each interval is a pair (σ^i, σ^j) of simplices).

        Parameters
        ----------
        dim : int
            The homology dimension.

        Returns
        -------
        numpy.ndarray of int64, shape (k, 2)
            Read-only, row i belonging to row i of :meth:`intervals` ``(dim)``.

        Raises
        ------
        ValueError
            A barcode that does not know its simplices (not computed from a filtration).

        Examples
        --------
        In Example 2.38, H_1's essential class is created by the edge ``simplices[1][3]`` (bc) and the
        class [3, 4) by ``simplices[1][5]`` (ce), killed by the triangle ``simplices[2][0]`` (cde):

        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> persistence(example_filtration()).simplex_pairs(1).tolist()
        [[3, -1], [5, 0]]
        """
        if not self._has_simplices:
            raise ValueError("this barcode does not know its simplices (it was not computed from a filtration)")
        dim = _dimension(dim)
        arr, extra = self._get(dim)
        if extra is None:  # a lazily listed dimension of essential classes
            extra = np.empty((arr.shape[0], 2), dtype=np.int64)
            extra[:, 0] = self._lazy_pairs.pop(dim)
            extra[:, 1] = -1
            extra.setflags(write=False)
            self._done[dim] = (arr, extra)
        return extra

    def representative(self, dim: int, i: int) -> list[tuple[tuple[int, ...], int]]:
        """A cycle representing interval ``i`` of :meth:`intervals` ``(dim)``: ``[(simplex, coefficient), ...]``.

        Thesis: Theorem 2.39 (z_i: a cycle born at the interval's birth; for a finite interval it is
        the reduced boundary of the killing simplex, so it becomes a boundary at the death).

        Parameters
        ----------
        dim : int
            The homology dimension.
        i : int
            The row of the interval in :meth:`intervals` ``(dim)``.

        Returns
        -------
        list of (tuple of int, int)
            ``(simplex, coefficient)``: simplices as vertex tuples, listed in filtration order;
            coefficients in ``1 .. p − 1``.

        Raises
        ------
        ValueError
            A barcode not computed from a filtration, or no interval ``i`` in ``dim``.

        Examples
        --------
        The essential loop of Example 2.38 is the square a-b-c-d (vertices 0, 1, 2, 3):

        >>> from thesis_lib.datasets import example_filtration
        >>> from thesis_lib.persistence import persistence
        >>> persistence(example_filtration()).representative(1, 0)
        [((0, 1), 1), ((2, 3), 1), ((0, 3), 1), ((1, 2), 1)]
        """
        from .representatives import Representatives

        if self.filtration is None or not self._has_simplices or self._killers is None:
            raise ValueError("representatives need a barcode computed from a filtration")
        from .._validate import check_int

        dim, i = _dimension(dim), check_int(i, "interval index")
        arr = self.intervals(dim)
        if not 0 <= i < arr.shape[0]:
            raise ValueError(f"no interval {i} in dimension {dim} (there are {arr.shape[0]})")
        if dim not in self._representatives:
            empty = np.empty(0, dtype=np.int64)
            self._representatives[dim] = Representatives(
                self.filtration, dim, self.coefficients or 2, self._killers.get(dim, empty),
                self._killers.get(dim - 1, empty),
            )
        sigma, tau = self.simplex_pairs(dim)[i]
        return self._representatives[dim].cycle(int(sigma), int(tau))


"""A compact filtered simplicial complex: one vertex array and one value array per dimension."""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np

from .._validate import InvalidTypeError, vertex_label
from .simplicial import as_simplex_array, closure, group_by_dimension

if TYPE_CHECKING:
    import gudhi

__all__ = ["Filtration", "as_complex"]


class Filtration:
    """A filtered simplicial complex K^0 ⊆ K^1 ⊆ ... stored without a Python object per simplex.

    Thesis: Definition 2.22 (a filtration is a nested sequence of sub-complexes).

    ``simplices[d]`` is an ``(m_d, d + 1)`` int64 array of vertex indices (rows ascending) and
    ``values[d]`` the ``(m_d,)`` float64 filtration values.  The filtration order is the stable sort
    by ``(value, dimension, position in simplices[d])``: it lists every face before its cofaces
    whenever faces have values no larger than their cofaces, which is checked on construction.

    A plain simplicial complex is a ``Filtration`` without values (``values=None``, see
    :meth:`from_simplices`): every simplex gets the value 0, so the order is by dimension, and
    ``has_values`` is False.  Every function of the library that takes a complex accepts one
    (:func:`as_complex`).

    Parameters
    ----------
    simplices : sequence of ``(m_d, d + 1)`` int arrays, one per dimension 0..d.
    values : sequence of ``(m_d,)`` float arrays, one per dimension, or None for a plain complex.
    validate : check shapes, NaN, duplicates, missing faces and face values (default True).
        Constructions that are valid by design may pass ``False``.
    truncated_at : the dimension at which a construction stopped (Rips, Čech and witness complexes
        at ``max_dim``): when the complex reaches it, ``truncated`` is True, since its top simplices
        may have cofaces that were never built, and persistence reports that dimension as incomplete
        (Theorem 2.39).

    Examples
    --------
    Two vertices entering at 0 and the edge joining them at 1:

    >>> import numpy as np
    >>> f = Filtration([np.array([[0], [1]]), np.array([[0, 1]])], [np.array([0.0, 0.0]), np.array([1.0])])
    >>> f.counts(), f.dimension, f.has_values
    ([2, 1], 1, True)
    >>> f.threshold(0.5).counts()
    [2]
    """

    def __init__(self, simplices: Sequence[np.ndarray], values: Sequence[np.ndarray] | None = None, *,
                 validate: bool = True, truncated_at: int | None = None):
        self.has_values = values is not None
        if values is None:
            values = [np.zeros(len(s)) for s in simplices]
        if len(simplices) != len(values):
            raise ValueError("simplices and values must have one array per dimension each")
        if validate:
            self.simplices = [as_simplex_array(s, dim=d) for d, s in enumerate(simplices)]
        else:
            self.simplices = [np.asarray(s, dtype=np.int64) for s in simplices]
        self.values = [np.asarray(v, dtype=np.float64).reshape(-1) for v in values]
        while self.simplices and self.simplices[-1].shape[0] == 0:
            self.simplices.pop()
            self.values.pop()
        #: True when the top dimension was cut (see ``truncated_at``): its cofaces are missing
        self.truncated = truncated_at is not None and len(self.simplices) - 1 >= int(truncated_at)
        if validate:
            self._validate()

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_pairs(cls, pairs: Iterable[tuple[Sequence[int], float]]) -> Filtration:
        """Build from ``(simplex, value)`` pairs listed in filtration order.

        Thesis: Definition 2.22 (DESIGN.md conventions).

        Parameters
        ----------
        pairs : iterable of (sequence of int, float)
            ``(simplex, value)`` in filtration order: values non-decreasing, each face before its
            cofaces, no simplex twice.

        Returns
        -------
        Filtration
            The same simplices and values (with values, ``has_values`` True).

        Raises
        ------
        ValueError
            An entry that is not a pair, a NaN or decreasing value, a face listed after its coface
            (or missing), a simplex listed twice, or no entries at all.

        Examples
        --------
        >>> f = Filtration.from_pairs([((0,), 0.0), ((1,), 0.0), ((0, 1), 1.0)])
        >>> f.counts(), [v.tolist() for v in f.values]
        ([2, 1], [[0.0, 0.0], [1.0]])
        """
        seen: set[tuple[int, ...]] = set()
        last = -np.inf
        simplices: list[tuple[int, ...]] = []
        vals: list[float] = []
        for position, item in enumerate(pairs):
            try:
                s, v = item
                t = tuple(sorted(vertex_label(x) for x in s))
                v = float(v)
            except (TypeError, ValueError) as err:
                raise ValueError(f"entry {position} of the filtration is not a (simplex, value) pair: {err}") from None
            if np.isnan(v):
                raise ValueError(f"simplex {t} has a NaN filtration value")
            if v < last:
                raise ValueError(f"filtration values decrease at position {position}: {t} has {v} < {last}")
            if len(t) > 1:
                for i in range(len(t)):
                    face = t[:i] + t[i + 1 :]
                    if face not in seen:
                        raise ValueError(f"face {face} of {t} does not come before it in the filtration")
            if t in seen:
                raise ValueError(f"simplex {t} is listed twice")
            seen.add(t)
            last = v
            simplices.append(t)
            vals.append(v)
        if not simplices:
            raise ValueError("the filtration is empty")
        groups = group_by_dimension(simplices)
        dims = np.array([len(t) - 1 for t in simplices])
        vals_arr = np.array(vals)
        values = [vals_arr[dims == d] for d in range(len(groups))]
        return cls(groups, values)

    @classmethod
    def from_simplices(cls, simplices: Iterable[Sequence[int]] | np.ndarray | list[np.ndarray]) -> Filtration:
        """The plain simplicial complex generated by ``simplices`` (all faces added, no values).

        Thesis: Definition 2.4 (an abstract simplicial complex contains every face of its simplices).

        Parameters
        ----------
        simplices : iterable of sequences of int, numpy.ndarray or list of numpy.ndarray
            Vertex tuples of any dimensions, an ``(m, k + 1)`` integer array of ``k``-simplices, or a
            list of per-dimension arrays (entry ``d`` of shape ``(m_d, d + 1)``).

        Returns
        -------
        Filtration
            The closure of ``simplices``, without values (``has_values`` False, every value 0).

        Raises
        ------
        ValueError
            Empty input or an invalid simplex (see :func:`~thesis_lib.homology.simplicial.as_simplex_array`).

        Examples
        --------
        The triangle [0, 1, 2] with all its faces:

        >>> f = Filtration.from_simplices([(0, 1, 2)])
        >>> f.counts(), f.has_values
        ([3, 3, 1], False)
        >>> f.simplices[1].tolist()
        [[0, 1], [0, 2], [1, 2]]
        """
        if isinstance(simplices, np.ndarray) and simplices.ndim == 2:
            groups = {simplices.shape[1]: simplices}
        elif isinstance(simplices, list) and simplices and all(
                isinstance(a, np.ndarray) and a.ndim == 2 for a in simplices):
            return cls(closure(simplices), None, validate=False)  # per-dimension arrays
        else:
            groups = _group_by_length(simplices if isinstance(simplices, list) else list(simplices))
            if groups is None:  # unusual entries: the general path validates them one by one
                return cls(closure(simplices), None, validate=False)
        if not groups:
            raise ValueError("the complex is empty")
        top = max(groups) - 1
        cx = closure([groups.get(d + 1, np.empty((0, d + 1), np.int64)) for d in range(top + 1)])
        if cx[0].shape[0] == 0:
            raise ValueError("the complex is empty")
        return cls(cx, None, validate=False)

    @classmethod
    def from_simplex_tree(cls, simplex_tree: gudhi.SimplexTree) -> Filtration:
        """Convert a GUDHI ``SimplexTree`` (its filtration order is kept).

        Parameters
        ----------
        simplex_tree : gudhi.SimplexTree
            Any simplex tree; its ``get_filtration()`` order must list faces before cofaces.

        Returns
        -------
        Filtration
            The same simplices and filtration values.

        Examples
        --------
        >>> import gudhi
        >>> st = gudhi.SimplexTree()
        >>> st.insert([0, 1, 2], filtration=1.0)
        True
        >>> f = Filtration.from_simplex_tree(st)
        >>> f.counts(), f.values[2].tolist()
        ([3, 3, 1], [1.0])
        """
        return cls.from_pairs((s, v) for s, v in simplex_tree.get_filtration())

    def to_simplex_tree(self) -> gudhi.SimplexTree:
        """Convert to a GUDHI ``SimplexTree`` with the same simplices and values (needs gudhi).

        Returns
        -------
        gudhi.SimplexTree
            A new simplex tree holding every simplex with its value (0 for a plain complex).

        Examples
        --------
        >>> st = Filtration.from_pairs([((0,), 0.0), ((1,), 0.0), ((0, 1), 1.0)]).to_simplex_tree()
        >>> list(st.get_filtration())
        [([0], 0.0), ([1], 0.0), ([0, 1], 1.0)]
        """
        import gudhi

        st = gudhi.SimplexTree()
        for s, v in zip(self.simplices, self.values):
            if s.shape[0]:
                st.insert_batch(np.ascontiguousarray(s.T), v)
        return st

    # ------------------------------------------------------------------ validation
    def _validate(self) -> None:
        if not self.simplices:
            raise ValueError("the filtration is empty")
        for d, (s, v) in enumerate(zip(self.simplices, self.values)):
            if s.shape[0] != v.shape[0]:
                raise ValueError(f"dimension {d}: {s.shape[0]} simplices but {v.shape[0]} values")
            if np.isnan(v).any():
                bad = tuple(int(x) for x in s[np.argmax(np.isnan(v))])
                raise ValueError(f"simplex {bad} has a NaN filtration value")
            if s.shape[0] > 1:
                u = np.unique(s, axis=0)
                if u.shape[0] != s.shape[0]:
                    raise ValueError(f"dimension {d} lists a simplex twice")
        for d in range(1, self.dimension + 1):
            idx = self.facet_indices(d)  # raises on a missing face
            face_vals = self.values[d - 1][idx]
            bad = face_vals > self.values[d][:, None]
            if bad.any():
                i, j = np.argwhere(bad)[0]
                t = tuple(int(x) for x in self.simplices[d][i])
                f = tuple(int(x) for x in self.simplices[d - 1][idx[i, j]])
                raise ValueError(
                    f"face {f} has value {face_vals[i, j]} > {self.values[d][i]} of its coface {t}: "
                    "faces must come before cofaces"
                )

    # ------------------------------------------------------------------ queries
    @property
    def dimension(self) -> int:
        """Largest dimension of a simplex (-1 for an empty filtration).

        Examples
        --------
        >>> Filtration.from_simplices([(0, 1, 2), (2, 3)]).dimension
        2
        """
        return len(self.simplices) - 1

    def __len__(self) -> int:
        return int(sum(s.shape[0] for s in self.simplices))

    def counts(self) -> list[int]:
        """Number of simplices in each dimension.

        Returns
        -------
        list of int
            Entry ``d`` is the number of ``d``-simplices, for ``d = 0, ..., dimension``.

        Examples
        --------
        The filtration of Figure 2.11 has five vertices a, ..., e, six edges and one triangle:

        >>> from thesis_lib.datasets import example_filtration
        >>> example_filtration().counts()
        [5, 6, 1]
        """
        return [int(s.shape[0]) for s in self.simplices]

    def facet_indices(self, d: int) -> np.ndarray:
        """``(m_d, d + 1)`` indices into ``simplices[d - 1]``; column ``i`` is the facet omitting vertex ``i``.

        Thesis: Definition 2.18 (the faces entering the boundary of a simplex).

        Parameters
        ----------
        d : int
            A dimension ``1 <= d <= dimension``.

        Returns
        -------
        numpy.ndarray of int64, shape (m_d, d + 1)
            Computed once and cached: do not modify it.

        Raises
        ------
        ValueError
            If ``d`` is out of range, or a facet is missing from ``simplices[d - 1]``.

        Examples
        --------
        The facets of the triangle [0, 1, 2] omitting vertex 0, 1, 2 are the edges [1, 2], [0, 2], [0, 1]
        (rows 2, 1, 0 of ``simplices[1]``):

        >>> f = Filtration.from_simplices([(0, 1, 2)])
        >>> f.facet_indices(2).tolist()
        [[2, 1, 0]]
        >>> f.simplices[1][f.facet_indices(2)[0]].tolist()
        [[1, 2], [0, 2], [0, 1]]
        """
        if d < 1 or d > self.dimension:
            raise ValueError(f"no facets for dimension {d} in a filtration of dimension {self.dimension}")
        cache = self.__dict__.setdefault("_facet_cache", {})
        if d not in cache:
            from .facet_lookup import facet_indices  # compiled kernels: loaded when first needed

            cache[d] = facet_indices(self.simplices[d - 1], self.simplices[d])
        return cache[d]

    @cached_property
    def order(self) -> tuple[np.ndarray, np.ndarray]:
        """The filtration order as ``(dims, index)``: the i-th simplex is ``simplices[dims[i]][index[i]]``.

        Thesis: Definition 2.22 (simplices listed by value; ties by dimension, then position).
        """
        dims = np.concatenate([np.full(s.shape[0], d, dtype=np.int64) for d, s in enumerate(self.simplices)])
        index = np.concatenate([np.arange(s.shape[0], dtype=np.int64) for s in self.simplices])
        vals = np.concatenate(self.values)
        # the concatenation is already sorted by (dimension, index): a stable sort on the value alone
        # gives the (value, dimension, index) order, faster than a three-key lexsort.
        perm = np.argsort(vals, kind="stable")
        return dims[perm], index[perm]

    @cached_property
    def positions(self) -> list[np.ndarray]:
        """``positions[d][j]``: place of ``simplices[d][j]`` in the filtration order."""
        dims, index = self.order
        out = [np.empty(s.shape[0], dtype=np.int64) for s in self.simplices]
        where = np.arange(dims.shape[0], dtype=np.int64)
        for d in range(len(out)):
            mask = dims == d
            out[d][index[mask]] = where[mask]
        return out

    def skeleton(self, k: int) -> Filtration:
        """The k-skeleton K^(k): the simplices of dimension <= k with their values.

        Thesis: §2.1.1 (the j-skeleton of a complex).

        Parameters
        ----------
        k : int
            The largest dimension kept, ``k >= 0`` (above :attr:`dimension`: the whole complex).

        Returns
        -------
        Filtration
            The simplices of dimension at most ``k``, with their values; ``truncated`` when ``k`` cut
            the complex (or it was truncated already).

        Raises
        ------
        ValueError
            If ``k`` is not an integer >= 0.

        Examples
        --------
        The 1-skeleton of a triangle is its boundary circle, marked truncated:

        >>> f = Filtration.from_simplices([(0, 1, 2)]).skeleton(1)
        >>> f.counts(), f.truncated
        ([3, 3], True)
        """
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
            raise ValueError(f"skeleton dimension must be an integer >= 0, got {k!r}")
        k = min(int(k), self.dimension)
        return Filtration(self.simplices[: k + 1], self.values[: k + 1], validate=False,
                          truncated_at=k if self.truncated or k < self.dimension else None)

    def threshold(self, value: float) -> Filtration:
        """The sub-complex K^value of simplices with filtration value <= ``value``.

        Thesis: Definition 2.22 (each step of the filtration is a sub-complex).

        Parameters
        ----------
        value : float
            The filtration value to cut at.

        Returns
        -------
        Filtration
            The simplices with value at most ``value`` (a sub-complex, since faces come no later than
            their cofaces), with their values.

        Raises
        ------
        ValueError
            If ``value`` is NaN or no vertex has a value at most ``value``.

        Examples
        --------
        K^1 of the filtration of Figure 2.11: the vertices a, b, c, d and the edges ab, cd:

        >>> from thesis_lib.datasets import example_filtration
        >>> k1 = example_filtration().threshold(1)
        >>> k1.counts(), k1.simplices[1].tolist()
        ([4, 2], [[0, 1], [2, 3]])
        """
        value = float(value)
        if np.isnan(value):
            raise ValueError("threshold value is NaN")
        keep = [v <= value for v in self.values]
        if not keep or not keep[0].any():
            raise ValueError(f"no simplex has a value <= {value}")
        return Filtration([s[m] for s, m in zip(self.simplices, keep)], [v[m] for v, m in zip(self.values, keep)],
                          validate=False, truncated_at=self.dimension if self.truncated else None)

    def __iter__(self) -> Iterator[tuple[tuple[int, ...], float]]:
        dims, index = self.order
        for d, j in zip(dims.tolist(), index.tolist()):
            yield tuple(self.simplices[d][j].tolist()), float(self.values[d][j])

    def __repr__(self) -> str:
        kind = "Filtration" if self.has_values else "Filtration(no values"
        if not self.has_values:
            return f"{kind}, dimension={self.dimension}, counts={self.counts()})"
        return f"{kind}(dimension={self.dimension}, counts={self.counts()})"


def _group_by_length(items: list) -> dict[int, np.ndarray] | None:
    """Vertex tuples grouped by length into integer arrays with numpy (the fast path), or None."""
    try:
        lens = np.fromiter(map(len, items), dtype=np.int64, count=len(items))
    except TypeError:
        return None
    if lens.size == 0:
        return {}
    if lens.min() == 0:
        return None
    groups = {}
    for width in np.unique(lens):
        arr = np.array([items[i] for i in np.flatnonzero(lens == width)])
        if arr.ndim != 2 or arr.dtype.kind not in "iu":
            return None
        groups[int(width)] = arr
    return groups


def _looks_like_pair(item) -> bool:
    """``(simplex, value)``: a sequence of vertices followed by one number."""
    if isinstance(item, (str, bytes)) or not isinstance(item, (tuple, list)) or len(item) != 2:
        return False
    first, second = item
    return (isinstance(first, (tuple, list, np.ndarray)) and np.ndim(second) == 0
            and not isinstance(second, (str, bytes, bool)))


def as_complex(obj: Filtration | Iterable[Any] | np.ndarray) -> Filtration:
    """Any description of a (filtered) simplicial complex as a :class:`Filtration`.

    Thesis: Definitions 2.4 and 2.22 (a complex; a filtration of one).

    Parameters
    ----------
    obj : Filtration, iterable or numpy.ndarray
        A ``Filtration`` (returned as is), an iterable of ``(simplex, value)`` pairs in filtration
        order, an iterable of simplices (all faces added; no values), an ``(m, k + 1)`` integer array
        of k-simplices, or a list of per-dimension integer arrays.  A point cloud is not a complex:
        build one with ``rips(points, max_radius=..., max_dim=...)`` or ``alpha(points)``.

    Returns
    -------
    Filtration
        ``obj`` itself if it is one, else a new filtration (with values only from pairs).

    Raises
    ------
    ValueError
        Empty input, a repeated vertex, a negative or non-integer vertex label, a missing face or
        a face that enters after its coface, or a point cloud given where a complex is needed.
    TypeError
        An object that is not iterable.

    Examples
    --------
    Simplices give a plain complex (all faces added); ``(simplex, value)`` pairs a filtration:

    >>> as_complex([(0, 1), (1, 2)]).counts()
    [3, 2]
    >>> as_complex([((0,), 0.0), ((1,), 0.0), ((0, 1), 2.0)]).values[1].tolist()
    [2.0]
    """
    if isinstance(obj, Filtration):
        if len(obj) == 0:
            raise ValueError("the complex is empty")
        return obj
    if isinstance(obj, (str, bytes, dict)) or not hasattr(obj, "__iter__"):
        raise InvalidTypeError(f"expected a Filtration or an iterable of simplices or (simplex, value) pairs, "
                               f"got {type(obj).__name__}")
    if isinstance(obj, np.ndarray):
        if obj.ndim == 2 and obj.dtype.kind == "f" and not np.all(np.isfinite(obj) & (obj == np.round(obj))):
            raise ValueError(
                f"got a point cloud of shape {obj.shape}, not a complex: build a filtration first, "
                "e.g. rips(points, max_radius=..., max_dim=...) or alpha(points)")
        if obj.ndim != 2:
            raise ValueError(f"an array of simplices must be (m, k + 1), got shape {obj.shape}")
        if obj.shape[0] == 0:
            raise ValueError("the complex is empty")
        return Filtration.from_simplices(obj)
    items = obj if isinstance(obj, list) else list(obj)
    if not items:
        raise ValueError("the complex is empty")
    if all(isinstance(a, np.ndarray) and a.ndim == 2 for a in items):
        return Filtration.from_simplices(items)
    if _looks_like_pair(items[0]):
        return Filtration.from_pairs(items)
    return Filtration.from_simplices(items)

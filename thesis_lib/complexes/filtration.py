"""A compact filtered simplicial complex: one vertex array and one value array per dimension."""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from functools import cached_property

import numpy as np

from ..simplicial import as_simplex_array, find_rows, facets, group_by_dimension

__all__ = ["Filtration"]


class Filtration:
    """A filtered simplicial complex K^0 ⊆ K^1 ⊆ ... stored without a Python object per simplex.

    Thesis: Definition 2.22 (a filtration is a nested sequence of sub-complexes).

    ``simplices[d]`` is an ``(m_d, d + 1)`` int64 array of vertex indices (rows ascending) and
    ``values[d]`` the ``(m_d,)`` float64 filtration values.  The filtration order is the stable sort
    by ``(value, dimension, position in simplices[d])``: it lists every face before its cofaces
    whenever faces have values no larger than their cofaces, which is checked on construction.

    Parameters
    ----------
    simplices, values : sequences of arrays, one per dimension 0..d.
    validate : check shapes, NaN, duplicates, missing faces and face values (default True).
        Constructions that are valid by design may pass ``False``.
    """

    def __init__(self, simplices: Sequence[np.ndarray], values: Sequence[np.ndarray], *, validate: bool = True):
        if len(simplices) != len(values):
            raise ValueError("simplices and values must have one array per dimension each")
        if validate:
            self.simplices = [as_simplex_array(s, d) for d, s in enumerate(simplices)]
        else:
            self.simplices = [np.asarray(s, dtype=np.int64) for s in simplices]
        self.values = [np.asarray(v, dtype=np.float64).reshape(-1) for v in values]
        while self.simplices and self.simplices[-1].shape[0] == 0:
            self.simplices.pop()
            self.values.pop()
        if validate:
            self._validate()

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_pairs(cls, pairs: Iterable[tuple[Sequence[int], float]]) -> Filtration:
        """Build from ``(simplex, value)`` pairs listed in filtration order.

        Thesis: Definition 2.22; the list must have non-decreasing values and each face before
        its cofaces (DESIGN.md conventions), otherwise ``ValueError``.
        """
        seen: set[tuple[int, ...]] = set()
        last = -np.inf
        simplices: list[tuple[int, ...]] = []
        vals: list[float] = []
        for position, (s, v) in enumerate(pairs):
            t = tuple(sorted(int(x) for x in s))
            v = float(v)
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
    def from_simplex_tree(cls, simplex_tree) -> Filtration:
        """Convert a GUDHI ``SimplexTree`` (its filtration order is kept)."""
        return cls.from_pairs((s, v) for s, v in simplex_tree.get_filtration())

    def to_simplex_tree(self):
        """Convert to a GUDHI ``SimplexTree`` with the same simplices and values (needs gudhi)."""
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
        """Largest dimension of a simplex (-1 for an empty filtration)."""
        return len(self.simplices) - 1

    def __len__(self) -> int:
        return int(sum(s.shape[0] for s in self.simplices))

    def counts(self) -> list[int]:
        """Number of simplices in each dimension."""
        return [int(s.shape[0]) for s in self.simplices]

    def facet_indices(self, d: int) -> np.ndarray:
        """``(m_d, d + 1)`` indices into ``simplices[d - 1]``; column ``i`` is the facet omitting vertex ``i``.

        Thesis: Definition 2.18 (the faces entering the boundary of a simplex).
        """
        if d < 1 or d > self.dimension:
            raise ValueError(f"no facets for dimension {d} in a filtration of dimension {self.dimension}")
        cache = self.__dict__.setdefault("_facet_cache", {})
        if d not in cache:
            s = self.simplices[d]
            cache[d] = find_rows(self.simplices[d - 1], facets(s).reshape(-1, d)).reshape(s.shape[0], d + 1)
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
        """
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
            raise ValueError(f"skeleton dimension must be an integer >= 0, got {k!r}")
        k = min(int(k), self.dimension)
        return Filtration(self.simplices[: k + 1], self.values[: k + 1], validate=False)

    def threshold(self, value: float) -> Filtration:
        """The sub-complex K^value of simplices with filtration value <= ``value``.

        Thesis: Definition 2.22 (each step of the filtration is a sub-complex).
        """
        value = float(value)
        if np.isnan(value):
            raise ValueError("threshold value is NaN")
        keep = [v <= value for v in self.values]
        if not keep or not keep[0].any():
            raise ValueError(f"no simplex has a value <= {value}")
        return Filtration([s[m] for s, m in zip(self.simplices, keep)], [v[m] for v, m in zip(self.values, keep)],
                          validate=False)

    def __iter__(self) -> Iterator[tuple[tuple[int, ...], float]]:
        dims, index = self.order
        for d, j in zip(dims.tolist(), index.tolist()):
            yield tuple(self.simplices[d][j].tolist()), float(self.values[d][j])

    def __repr__(self) -> str:
        return f"Filtration(dimension={self.dimension}, counts={self.counts()})"

"""Internal: one global numbering of the cells of a complex, as a view of a :class:`Filtration`.

Every function of :mod:`thesis_lib.morse` takes a complex in any form the library accepts (a
``Filtration``, with or without values, an iterable of simplices, per-dimension arrays) and turns it
into a :class:`CellComplex` with :func:`cell_complex`.  Cells are numbered dimension by dimension
(0-simplices first), each dimension in lexicographic order; the algorithms work on these integer
ids, and tuples appear only at the public boundary.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np
import numpy.typing as npt
import scipy.sparse as sp

from ..homology.filtration import Filtration, as_complex
from ..homology.simplicial import as_simplex_array, facets, find_rows

Simplex = tuple[int, ...]

#: a complex in any form :func:`thesis_lib.homology.filtration.as_complex` accepts: a ``Filtration`` (values
#: optional), an iterable of simplices (vertex tuples; all faces are added), an ``(m, k + 1)``
#: integer array or a list of per-dimension integer arrays
ComplexLike = Filtration | Iterable[Sequence[int]] | npt.NDArray[np.integer] | Sequence[npt.NDArray[np.integer]]

#: a discrete vector field: pairs ``(sigma, tau)`` of simplices, sigma a facet of tau (Definition 4.33)
Pairs = Iterable[tuple[Sequence[int], Sequence[int]]]


class CellComplex:
    """A complex with global cell ids, facet lists and the signed boundary (Definition 2.18).

    Built from a :class:`~thesis_lib.homology.filtration.Filtration` (closed and validated); ``values`` holds
    the filtration value of every cell (global ids), or None for a complex without values.
    """

    def __init__(self, filtration: Filtration):
        self.arrays: list[np.ndarray] = []
        values = []
        for s, v in zip(filtration.simplices, filtration.values):
            order = np.lexsort(s.T[::-1]) if s.shape[0] else np.empty(0, dtype=np.int64)
            self.arrays.append(np.asarray(s, dtype=np.int64)[order])
            values.append(np.asarray(v, dtype=np.float64)[order])
        self.values: np.ndarray | None = np.concatenate(values) if filtration.has_values else None
        self.counts = np.array([a.shape[0] for a in self.arrays], dtype=np.int64)
        self.offsets = np.concatenate([[0], np.cumsum(self.counts)]).astype(np.int64)
        self.n = int(self.offsets[-1])
        self.dimension = len(self.arrays) - 1
        self.dim_of = np.repeat(np.arange(len(self.arrays), dtype=np.int64), self.counts)
        # facet_ids[d]: (n_d, d + 1) global ids; column i omits vertex i, sign (-1)^i
        self.facet_ids: list[np.ndarray] = [np.empty((self.counts[0], 0), dtype=np.int64)]
        for d in range(1, len(self.arrays)):
            a = self.arrays[d]
            idx = find_rows(self.arrays[d - 1], facets(a).reshape(-1, d)).reshape(a.shape[0], d + 1)
            self.facet_ids.append(idx + self.offsets[d - 1])
        if self.dimension:
            rows = np.concatenate([f.ravel() for f in self.facet_ids[1:]])
            cols = np.concatenate(
                [np.repeat(np.arange(self.offsets[d], self.offsets[d + 1]), d + 1) for d in range(1, len(self.arrays))])
            signs = np.concatenate(
                [np.tile((-1) ** np.arange(d + 1, dtype=np.int64), self.counts[d]) for d in range(1, len(self.arrays))])
        else:
            rows = cols = signs = np.empty(0, np.int64)
        #: global signed boundary matrix D (n x n), D[face, cell] = <∂ cell, face>
        self.D = sp.csc_matrix((signs, (rows, cols)), shape=(self.n, self.n), dtype=np.int64)
        self.D.sort_indices()
        cof = self.D.tocsr()
        cof.sort_indices()
        #: CSR of D: row g lists the cofaces of g
        self.cofaces = cof

    # ------------------------------------------------------------------ lookups
    def simplex(self, g: int) -> Simplex:
        d = int(self.dim_of[g])
        return tuple(int(v) for v in self.arrays[d][g - self.offsets[d]])

    def simplices(self) -> list[Simplex]:
        return [tuple(int(v) for v in row) for a in self.arrays for row in a]

    def ids(self, simplices: Sequence[Sequence[int]], what: str = "simplex") -> np.ndarray:
        """Global ids of the given simplices (ValueError naming one that is not in the complex)."""
        out = np.empty(len(simplices), dtype=np.int64)
        by_dim: dict[int, list[int]] = {}
        for i, s in enumerate(simplices):
            t = tuple(s)
            if len(t) == 0:
                raise ValueError(f"{what} {t} is empty")
            by_dim.setdefault(len(t) - 1, []).append(i)
        for d, where in by_dim.items():
            rows = as_simplex_array([tuple(simplices[i]) for i in where], dim=d)
            if d > self.dimension:
                raise ValueError(f"{what} {tuple(int(v) for v in rows[0])} is not in the complex")
            found = find_rows(self.arrays[d], rows, missing="mark")
            if (found < 0).any():
                bad = tuple(int(v) for v in rows[int(np.argmax(found < 0))])
                raise ValueError(f"{what} {bad} is not in the complex")
            out[np.asarray(where)] = found + self.offsets[d]
        return out

    def faces_of(self, g: int) -> np.ndarray:
        lo, hi = self.D.indptr[g], self.D.indptr[g + 1]
        return self.D.indices[lo:hi]

    def cofaces_of(self, g: int) -> np.ndarray:
        lo, hi = self.cofaces.indptr[g], self.cofaces.indptr[g + 1]
        return self.cofaces.indices[lo:hi]

    def incidence(self, face: int, cell: int) -> int:
        """<∂ cell, face> in {-1, 0, 1}."""
        return int(self.D[face, cell])


def cell_complex(obj) -> CellComplex:
    """Any complex the library accepts (:func:`thesis_lib.homology.filtration.as_complex`) as a :class:`CellComplex`."""
    return obj if isinstance(obj, CellComplex) else CellComplex(as_complex(obj))


def partner_array(cx: CellComplex, pairs: Iterable[tuple[Sequence[int], Sequence[int]]]) -> np.ndarray:
    """Validate a discrete vector field (Definition 4.33) and return ``partner[g]`` (-1 = unpaired).

    Raises ValueError when a pair is not (face, coface of codimension one) or a simplex is in two pairs.
    """
    if isinstance(pairs, (str, bytes)) or not isinstance(pairs, Iterable):
        raise ValueError(f"a discrete vector field is an iterable of pairs (sigma, tau), got {pairs!r}")
    pairs = list(pairs)
    partner = np.full(cx.n, -1, dtype=np.int64)
    if not pairs:
        return partner
    for p in pairs:
        if isinstance(p, (str, bytes)) or not isinstance(p, Sequence) or len(p) != 2:
            raise ValueError(f"a pair of a discrete vector field has two simplices, got {p!r}")
        for s in p:
            if isinstance(s, (str, bytes)) or not isinstance(s, (Sequence, np.ndarray)):
                raise ValueError(f"a pair of a discrete vector field holds two simplices, got {p!r}")
    lows = cx.ids([tuple(p[0]) for p in pairs], "paired simplex")
    highs = cx.ids([tuple(p[1]) for p in pairs], "paired simplex")
    for (s, t), a, b in zip(pairs, lows, highs):
        if cx.dim_of[b] != cx.dim_of[a] + 1 or cx.D[a, b] == 0:
            raise ValueError(
                f"pair {tuple(s)} < {tuple(t)} is not a face of codimension one (Definition 4.33)"
            )
    both = np.concatenate([lows, highs])
    uniq, cnt = np.unique(both, return_counts=True)
    if (cnt > 1).any():
        bad = cx.simplex(int(uniq[np.argmax(cnt > 1)]))
        raise ValueError(f"simplex {bad} is in two pairs of the vector field (Definition 4.33)")
    partner[lows] = highs
    partner[highs] = lows
    return partner


def pairs_from_partner(cx: CellComplex, partner: np.ndarray) -> list[tuple[Simplex, Simplex]]:
    lows = np.flatnonzero((partner >= 0) & (partner > np.arange(cx.n)))
    return [(cx.simplex(int(a)), cx.simplex(int(partner[a]))) for a in lows]

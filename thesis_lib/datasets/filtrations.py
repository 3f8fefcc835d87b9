"""Small filtrations from the thesis's worked examples, and families of filtrations that grow."""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Mapping, Sequence

import numpy as np

from .._validate import check_int, check_seed
from ..homology.filtration import Filtration

__all__ = [
    "example_filtration",
    "EXAMPLE_NAMES",
    "EXAMPLE_2_40_CYCLES",
    "EXAMPLE_2_41_MATRIX",
    "EQUATION_2_5",
    "EQUATION_2_6",
    "named_chain",
    "simplex_labels",
    "module_filtration",
    "dense_filtration",
]

#: vertex names of Figure 2.11: a, b, c, d, e = 0, 1, 2, 3, 4
EXAMPLE_NAMES = "abcde"

#: The cycles z₁ and z₂ of Example 2.40 as printed (oriented edges named by their vertices, with
#: their coefficients; the powers of t only shift degrees): z₁ = da + t·cd + bc + t·ab and
#: z₂ = ed + ce − t²·cd.
EXAMPLE_2_40_CYCLES = {
    "z1": {"da": 1, "cd": 1, "bc": 1, "ab": 1},
    "z2": {"ed": 1, "ce": 1, "cd": -1},
}

#: The first matrix of Example 2.41 as printed, with the thesis's orientations (da, ed, ced): column
#: → {row: (coefficient, power of t)}.
EXAMPLE_2_41_MATRIX = {
    "ab": {"a": (-1, 1), "b": (1, 1)},
    "cd": {"c": (-1, 0), "d": (1, 0)},
    "da": {"a": (1, 2), "d": (-1, 1)},
    "bc": {"b": (-1, 2), "c": (1, 1)},
    "ed": {"d": (1, 2), "e": (-1, 1)},
    "ce": {"c": (-1, 2), "e": (1, 1)},
    "ced": {"cd": (-1, 3), "ed": (1, 1), "ce": (1, 1)},
}

#: Equation 2.5 as printed, H₀ ≃ Σ²F[t]/(t) ⊕ Σ¹F[t]/(t) ⊕ F[t] ⊕ F[t]/(t), as summands (shift, n)
#: of Σ^shift F[t]/(t^n), n = None for a free summand.
EQUATION_2_5 = ((2, 1), (1, 1), (0, None), (0, 1))

#: Equation 2.6 as printed, H₁ ≃ Σ³F[t]/(t) ⊕ Σ²F[t], as summands (shift, n).
EQUATION_2_6 = ((3, 1), (2, None))


def example_filtration() -> Filtration:
    """The filtration K^0 ⊆ ... ⊆ K^4 of Figure 2.11 with vertices a, b, c, d, e = 0, 1, 2, 3, 4.

    Thesis: Figure 2.11, Examples 2.38, 2.40 and 2.41.

    The entry times are read off the powers of t in the boundary matrices of Examples 2.40/2.41
    (deg c_j = deg z_i + β_ij): a, b enter at 0; c, d, ab, cd at 1; e, da, bc at 2; ed, ce at 3;
    ced at 4.  Within a dimension the simplices are listed in the thesis's order
    (a, b, c, d, e; ab, cd, da, bc, ed, ce; ced).

    Returns
    -------
    Filtration
        The 12 simplices with their entry times 0..4, in the thesis's order.
    """
    a, b, c, d, e = range(5)
    pairs = [
        ((a,), 0), ((b,), 0),
        ((c,), 1), ((d,), 1), ((a, b), 1), ((c, d), 1),
        ((e,), 2), ((d, a), 2), ((b, c), 2),
        ((e, d), 3), ((c, e), 3),
        ((c, e, d), 4),
    ]  # fmt: skip
    return Filtration.from_pairs(pairs)


def _permutation_sign(order: Iterable[int]) -> int:
    """+1 for an even permutation of the sorted order, −1 for an odd one."""
    seq = list(order)
    inversions = sum(1 for i, j in itertools.combinations(range(len(seq)), 2) if seq[i] > seq[j])
    return -1 if inversions % 2 else 1


def named_chain(terms: Mapping[str, int], *, names: str = EXAMPLE_NAMES) -> dict[tuple[int, ...], int]:
    """A chain written with the thesis's vertex names, as ``{ascending simplex: integer coefficient}``.

    Thesis: Definition 2.17 ([x_0, ..., x_p] = −[x_τ(0), ..., x_τ(p)] for an odd permutation τ).

    Parameters
    ----------
    terms : mapping of str to int
        Oriented simplices named by their vertices (``"da"`` is the edge from d to a) to integer
        coefficients.
    names : str, default "abcde"
        ``names[i]`` is the one-letter name of vertex ``i`` (``EXAMPLE_NAMES``, Figure 2.11).

    Returns
    -------
    dict of tuple to int
        The chain on ascending simplices, the signs of odd orderings applied and terms that cancel
        dropped: ``named_chain({"da": 1})`` is ``{(0, 3): -1}`` since [d, a] = −[a, d].

    Raises
    ------
    ValueError
        A letter not in ``names``, or a repeated vertex.
    """
    chain: dict[tuple[int, ...], int] = {}
    for word, coefficient in terms.items():
        try:
            vertices = [names.index(ch) for ch in word]
        except ValueError:
            raise ValueError(f"{word!r} names a vertex not in {names!r}") from None
        if len(set(vertices)) != len(vertices):
            raise ValueError(f"{word!r} repeats a vertex")
        key = tuple(sorted(vertices))
        value = chain.get(key, 0) + _permutation_sign(vertices) * int(coefficient)
        if value:
            chain[key] = value
        else:
            chain.pop(key, None)
    return chain


def simplex_labels(simplices: Sequence[Sequence[int]], *, names: str | None = None) -> list[str]:
    """The name of each simplex: its vertices' letters (``names[v]``), or their numbers comma-separated.

    Thesis: Example 2.38 (simplices named by their vertices: ab, cd, ced, ...); the inverse of
    :func:`named_chain` on ascending simplices.

    Parameters
    ----------
    simplices : sequence of sequence of int
        Simplices as vertex tuples.
    names : str, optional
        ``names[v]`` is the letter of vertex v (``"abcde"``); default: the numbers.

    Returns
    -------
    list of str
        One name per simplex, in order.

    Examples
    --------
    >>> simplex_labels([(0,), (2, 3)], names="abcde"), simplex_labels([(2, 3)])
    (['a', 'cd'], ['2,3'])
    """
    return ["".join(names[v] for v in s) if names else ",".join(map(str, s)) for s in simplices]


def module_filtration(summands: Iterable[tuple[int, int | None]], *, dim: int = 1) -> Filtration:
    """A filtration whose dimension-``dim`` persistence module is ⊕ Σ^α F[t] ⊕ Σ^γ F[t]/(t^n).

    Thesis: Theorem 2.33 and Corollary 2.35 (finite sets of P-intervals and graded F[t]-modules
    correspond), Example 2.36.

    Parameters
    ----------
    summands : pairs ``(shift, n)``: ``(α, None)`` is the free summand Σ^α F[t] and ``(γ, n)`` the
        torsion summand Σ^γ F[t]/(t^n) (n ≥ 1).  Shifts are non-negative integers.
    dim : the homology dimension that carries the module (≥ 1).

    Returns
    -------
    Filtration
        One component per summand: the boundary of a (dim + 1)-simplex, all of it entering at the
        shift (a dim-sphere, one class born there), and for a torsion summand the (dim + 1)-simplex
        itself entering n steps later (the class dies).  Its dimension-``dim`` barcode is the set of
        P-intervals (α, ∞) and (γ, γ + n) of Definition 2.34.
    """
    dim = check_int(dim, "dim", minimum=1)
    pairs: list[tuple[tuple[int, ...], float]] = []
    fills: list[tuple[tuple[int, ...], float]] = []
    base = 0
    for item in summands:
        shift, n = item
        shift = check_int(shift, "shift", minimum=0)
        if n is not None:
            n = check_int(n, "torsion order n", minimum=1)
        top = tuple(range(base, base + dim + 2))
        base += dim + 2
        for k in range(1, dim + 2):
            pairs += [(face, float(shift)) for face in itertools.combinations(top, k)]
        if n is not None:
            fills.append((top, float(shift + n)))
    if not pairs:
        raise ValueError("the module needs at least one summand")
    ordered = sorted(pairs + fills, key=lambda sv: (sv[1], len(sv[0])))
    return Filtration.from_pairs(ordered)


def dense_filtration(n_vertices: int, *, seed: int) -> Filtration:
    """Every vertex, edge and triangle on ``n_vertices`` vertices; edges, then triangles, in random order.

    Thesis: Algorithm 2 / Summary (ComputeIntervals is O(m³) in the number m of simplices): a dense
    input for measuring how the work of the algorithm grows; m = n + C(n, 2) + C(n, 3).

    Parameters
    ----------
    n_vertices : int
        n ≥ 3.
    seed : int
        The random order of the edges and of the triangles.

    Returns
    -------
    Filtration
        Vertices at 0, then edges at 1, 2, ..., then triangles, one value each (every edge before
        every triangle, so faces always come first).
    """
    n = check_int(n_vertices, "n_vertices", minimum=3)
    rng = np.random.default_rng(check_seed(seed))
    edges = list(itertools.combinations(range(n), 2))
    triangles = list(itertools.combinations(range(n), 3))
    order_e = rng.permutation(len(edges))
    order_t = rng.permutation(len(triangles))
    pairs = [((v,), 0.0) for v in range(n)]
    pairs += [(edges[i], 1.0 + k) for k, i in enumerate(order_e)]
    pairs += [(triangles[i], 1.0 + len(edges) + k) for k, i in enumerate(order_t)]
    return Filtration.from_pairs(pairs)

"""Discrete Morse functions, their critical simplices, sublevel complexes and gradient pairs (§4.2.1–4.2.3)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from .._validate import vertex_label
from ..homology.filtration import Filtration
from ._cells import CellComplex, ComplexLike, Pairs, Simplex, cell_complex, partner_array
from ._gradient import acyclic_ranks, hasse_edges
from ._kernels import topological_rank

#: a discrete Morse function: simplex -> value over a whole complex, or a Filtration with values
Values = Mapping[Sequence[int], float] | Filtration

__all__ = [
    "is_discrete_morse_function",
    "check_discrete_morse_function",
    "critical_simplices",
    "gradient_pairs",
    "sublevel_complex",
    "discrete_morse_function",
]


def _prepare(values) -> tuple[CellComplex, np.ndarray]:
    """The complex and the function f on its cells (global ids) from ``values``: a mapping
    simplex -> value over every simplex of a complex, or a :class:`Filtration` with values."""
    if isinstance(values, Filtration):
        if not values.has_values:
            raise ValueError("a discrete Morse function needs values: this Filtration has none")
        cx = CellComplex(values)
        return cx, cx.values
    if not isinstance(values, Mapping) or not values:
        raise ValueError("values must be a non-empty mapping simplex -> float, or a Filtration with values")
    keys: list[Simplex] = []
    seen: set[Simplex] = set()
    vals: list[float] = []
    for s, v in values.items():
        try:
            t = tuple(sorted(vertex_label(x) for x in s))
        except TypeError:
            raise ValueError(f"{s!r} is not a simplex (a tuple of vertex labels)") from None
        if len(set(t)) != len(t) or not t or t[0] < 0:
            raise ValueError(f"{s!r} is not a simplex")
        if t in seen:
            raise ValueError(f"simplex {t} is given twice")
        seen.add(t)
        try:
            fv = float(v)
        except (TypeError, ValueError):
            raise ValueError(f"simplex {t} has a non-numeric value {v!r}") from None
        if not math.isfinite(fv):
            raise ValueError(f"simplex {t} has a non-finite value {v!r}")
        keys.append(t)
        vals.append(fv)
    cx = cell_complex(keys)
    if cx.n != len(keys):
        missing = next(s for s in cx.simplices() if s not in seen)
        raise ValueError(f"face {missing} has no value: values must cover every simplex of the complex")
    f = np.empty(cx.n)
    f[cx.ids(keys)] = vals
    return cx, f


def _violations(cx: CellComplex, f: np.ndarray):
    coo = cx.D.tocoo()
    face, cell = coo.row, coo.col
    bad = f[cell] <= f[face]  # coface not above its face
    n_up = np.bincount(face[bad], minlength=cx.n)  # condition 1 counts (per face)
    n_down = np.bincount(cell[bad], minlength=cx.n)  # condition 2 counts (per coface)
    return face[bad], cell[bad], n_up, n_down


def _checked(values) -> tuple[CellComplex, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(complex, f, the violating (face, coface) pairs, counts per cell); ValueError naming the
    simplex and the condition of Definition 4.20 that fails."""
    cx, f = _prepare(values)
    face, cell, n_up, n_down = _violations(cx, f)
    for counts, which, what in ((n_up, 1, "cofaces have a value <="), (n_down, 2, "faces have a value >=")):
        if (counts > 1).any():
            g = int(np.argmax(counts > 1))
            raise ValueError(f"simplex {cx.simplex(g)} breaks condition {which} of Definition 4.20: "
                             f"{int(counts[g])} {what} f{cx.simplex(g)} = {f[g]}")
    return cx, face, cell, n_up, n_down


def check_discrete_morse_function(values: Values) -> None:
    """Raise ValueError naming the simplex and the condition of Definition 4.20 that fails.

    Thesis: Definition 4.20 (#{τ > σ : f(τ) ≤ f(σ)} ≤ 1 and #{γ < σ : f(γ) ≥ f(σ)} ≤ 1).

    Parameters
    ----------
    values : mapping or Filtration
        The function to check, in a form :func:`is_discrete_morse_function` accepts.

    Raises
    ------
    ValueError
        A simplex breaks condition 1 or 2 of Definition 4.20 (named in the message), or ``values``
        is not a finite value for every simplex of a complex.

    Examples
    --------
    >>> f = {(0,): 0, (1,): 1, (2,): 2, (0, 1): 1, (0, 2): 3, (1, 2): 2}
    >>> check_discrete_morse_function(f) is None
    True
    >>> check_discrete_morse_function({**f, (0, 1): 0})
    Traceback (most recent call last):
        ...
    ValueError: simplex (0, 1) breaks condition 2 of Definition 4.20: 2 faces have a value >= f(0, 1) = 0.0
    """
    _checked(values)


def is_discrete_morse_function(values: Values) -> bool:
    """True when ``values`` is a discrete Morse function.

    Thesis: Definition 4.20.

    Parameters
    ----------
    values : mapping or Filtration
        The function: a mapping simplex -> value over every simplex of a complex, or a
        :class:`~thesis_lib.homology.filtration.Filtration` with values (its values are the function).

    Returns
    -------
    bool
        Whether both conditions of Definition 4.20 hold at every simplex.

    Raises
    ------
    ValueError
        Malformed input (missing faces, NaN, non-simplices, non-integer vertex labels) raises
        rather than returning False.

    Examples
    --------
    A discrete Morse function on the hollow triangle (a circle), and a change that breaks it (the
    edge 01 below both its vertices):

    >>> f = {(0,): 0, (1,): 1, (2,): 2, (0, 1): 1, (0, 2): 3, (1, 2): 2}
    >>> is_discrete_morse_function(f)
    True
    >>> is_discrete_morse_function({**f, (0, 1): 0})
    False
    """
    cx, f = _prepare(values)
    _, _, n_up, n_down = _violations(cx, f)
    return bool((n_up <= 1).all() and (n_down <= 1).all())


def critical_simplices(values: Values) -> list[Simplex]:
    """The critical simplices of a discrete Morse function, by dimension then lexicographically.

    Thesis: Definition 4.21 (no coface with f(τ) ≤ f(σ) and no face with f(γ) ≥ f(σ)).

    Parameters
    ----------
    values : mapping or Filtration
        A discrete Morse function (see :func:`is_discrete_morse_function` for the forms).

    Returns
    -------
    list of tuple
        The critical simplices (ascending vertices).

    Raises
    ------
    ValueError
        ``values`` is malformed or not a discrete Morse function.

    Examples
    --------
    The function of :func:`is_discrete_morse_function` on the circle has one critical vertex and one
    critical edge, the minimum number (β = 1, 1):

    >>> f = {(0,): 0, (1,): 1, (2,): 2, (0, 1): 1, (0, 2): 3, (1, 2): 2}
    >>> critical_simplices(f)
    [(0,), (0, 2)]
    """
    cx, _, _, n_up, n_down = _checked(values)
    return [cx.simplex(int(g)) for g in np.flatnonzero((n_up == 0) & (n_down == 0))]


def gradient_pairs(values: Values) -> list[tuple[Simplex, Simplex]]:
    """The pairs σ < τ of the gradient vector field V: τ > σ of codimension one with f(τ) ≤ f(σ).

    Thesis: Definition 4.30 (V(σ) = -<∂τ, σ>τ when f(τ) ≤ f(σ)); each simplex is in at most one
    pair by Lemma 4.22, so the pairs form a discrete vector field (Definition 4.33).

    Parameters
    ----------
    values : mapping or Filtration
        The discrete Morse function whose gradient is wanted (a mapping simplex -> value or a
        Filtration with values, as in :func:`is_discrete_morse_function`).

    Returns
    -------
    list of (tuple, tuple)
        The pairs ``(sigma, tau)``, ordered by sigma (dimension, then lexicographically), then tau.

    Raises
    ------
    ValueError
        As :func:`critical_simplices`.

    Examples
    --------
    >>> f = {(0,): 0, (1,): 1, (2,): 2, (0, 1): 1, (0, 2): 3, (1, 2): 2}
    >>> gradient_pairs(f)
    [((1,), (0, 1)), ((2,), (1, 2))]
    """
    cx, face, cell, _, _ = _checked(values)
    order = np.lexsort((cell, face))
    return [(cx.simplex(int(a)), cx.simplex(int(b))) for a, b in zip(face[order], cell[order])]


def sublevel_complex(values: Values, a: float) -> list[Simplex]:
    """K^a: the simplices with value ≤ a together with all their faces.

    Thesis: §4.2.2, K^a = ∪_{f(σ) ≤ a} ∪_{τ ≤ σ} τ (Theorems 4.25–4.26).

    Parameters
    ----------
    values : mapping or Filtration
        Any function on the simplices of a complex, in a form :func:`is_discrete_morse_function`
        accepts; it need not be a discrete Morse function.
    a : float
        The level.

    Returns
    -------
    list of tuple
        The simplices of K^a by dimension then lexicographically (empty list if none).

    Raises
    ------
    ValueError
        ``a`` is NaN, or ``values`` is malformed.

    Examples
    --------
    >>> f = {(0,): 0, (1,): 1, (2,): 2, (0, 1): 1, (0, 2): 3, (1, 2): 2}
    >>> sublevel_complex(f, 1.5)
    [(0,), (1,), (0, 1)]
    """
    a = float(a)
    if math.isnan(a):
        raise ValueError("the level a is NaN")
    cx, f = _prepare(values)
    keep = f <= a
    # add faces: propagate downwards dimension by dimension
    for d in range(cx.dimension, 0, -1):
        lo, hi = cx.offsets[d], cx.offsets[d + 1]
        sel = np.flatnonzero(keep[lo:hi])
        if sel.size:
            keep[cx.facet_ids[d][sel].ravel()] = True
    return [cx.simplex(int(g)) for g in np.flatnonzero(keep)]


def discrete_morse_function(simplices: ComplexLike, pairs: Pairs) -> dict[Simplex, float]:
    """A discrete Morse function whose gradient vector field is the given acyclic field.

    Thesis: Theorem 4.36 (acyclic fields are gradients), built from a topological order of the
    modified Hasse diagram of Theorem 4.44: every edge u → v gets f(u) > f(v).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        The complex (all faces are added).
    pairs : iterable of (sigma, tau)
        The acyclic discrete vector field, sigma a facet of tau (Definition 4.33).

    Returns
    -------
    dict of tuple to float
        f on every simplex of the complex; the values are the integers 1..n (as floats).

    Raises
    ------
    ValueError
        The field has a closed V-path (named), or is not a valid vector field.

    Examples
    --------
    Values 1..n for the field of the circle that pairs 1 with 01 and 2 with 12 (Theorem 4.36):

    >>> f = discrete_morse_function([(0, 1), (0, 2), (1, 2)], [((1,), (0, 1)), ((2,), (1, 2))])
    >>> f
    {(0,): 1.0, (1,): 3.0, (2,): 5.0, (0, 1): 2.0, (0, 2): 6.0, (1, 2): 4.0}
    >>> gradient_pairs(f)
    [((1,), (0, 1)), ((2,), (1, 2))]
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    acyclic_ranks(cx, partner)  # names a closed V-path if there is one
    src, dst = hasse_edges(cx, partner)
    order = np.argsort(src, kind="stable")
    ptr = np.concatenate([[0], np.cumsum(np.bincount(src, minlength=cx.n))]).astype(np.int64)
    rank = topological_rank(cx.n, ptr, dst[order])
    f = cx.n - rank
    return {cx.simplex(g): float(f[g]) for g in range(cx.n)}

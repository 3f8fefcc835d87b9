"""Discrete Morse functions, their critical simplices, sublevel complexes and gradient pairs (§4.2.1–4.2.3)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from ._cells import CellComplex, Simplex, as_complex, partner_array
from ._kernels import topological_rank
from .vector_field import _cyclic_field_error, _hasse_edges, _ranks

__all__ = [
    "is_discrete_morse_function",
    "check_discrete_morse_function",
    "critical_simplices",
    "gradient_pairs",
    "sublevel_complex",
    "discrete_morse_function",
]


def _prepare(values: Mapping[Sequence[int], float]) -> tuple[CellComplex, np.ndarray]:
    if not isinstance(values, Mapping) or not values:
        raise ValueError("values must be a non-empty mapping simplex -> float")
    keys: list[Simplex] = []
    seen: set[Simplex] = set()
    vals: list[float] = []
    for s, v in values.items():
        t = tuple(sorted(int(x) for x in s))
        if len(set(t)) != len(t) or not t:
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
    cx = CellComplex(keys)
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


def check_discrete_morse_function(values: Mapping[Sequence[int], float]) -> None:
    """Raise ValueError naming the simplex and the condition of Definition 4.20 that fails.

    Thesis: Definition 4.20 (#{τ > σ : f(τ) ≤ f(σ)} ≤ 1 and #{γ < σ : f(γ) ≥ f(σ)} ≤ 1).

    Also raises when ``values`` is not a finite value for every simplex of a complex.
    """
    cx, f = _prepare(values)
    _, _, n_up, n_down = _violations(cx, f)
    for g in range(cx.n):
        if n_up[g] > 1:
            raise ValueError(
                f"simplex {cx.simplex(g)} breaks condition 1 of Definition 4.20: "
                f"{int(n_up[g])} cofaces have a value <= f{cx.simplex(g)} = {f[g]}"
            )
        if n_down[g] > 1:
            raise ValueError(
                f"simplex {cx.simplex(g)} breaks condition 2 of Definition 4.20: "
                f"{int(n_down[g])} faces have a value >= f{cx.simplex(g)} = {f[g]}"
            )


def is_discrete_morse_function(values: Mapping[Sequence[int], float]) -> bool:
    """True when ``values`` (simplex → float over every simplex of a complex) is a discrete Morse function.

    Thesis: Definition 4.20.

    Malformed input (missing faces, NaN, non-simplices) raises ValueError rather than returning False.
    """
    cx, f = _prepare(values)
    _, _, n_up, n_down = _violations(cx, f)
    return bool((n_up <= 1).all() and (n_down <= 1).all())


def critical_simplices(values: Mapping[Sequence[int], float]) -> list[Simplex]:
    """The critical simplices of a discrete Morse function, by dimension then lexicographically.

    Thesis: Definition 4.21 (no coface with f(τ) ≤ f(σ) and no face with f(γ) ≥ f(σ)).
    """
    check_discrete_morse_function(values)
    cx, f = _prepare(values)
    _, _, n_up, n_down = _violations(cx, f)
    return [cx.simplex(int(g)) for g in np.flatnonzero((n_up == 0) & (n_down == 0))]


def gradient_pairs(values: Mapping[Sequence[int], float]) -> list[tuple[Simplex, Simplex]]:
    """The pairs σ < τ of the gradient vector field V: τ > σ of codimension one with f(τ) ≤ f(σ).

    Thesis: Definition 4.30 (V(σ) = -<∂τ, σ>τ when f(τ) ≤ f(σ)); each simplex is in at most one
    pair by Lemma 4.22, so the pairs form a discrete vector field (Definition 4.33).
    """
    check_discrete_morse_function(values)
    cx, f = _prepare(values)
    face, cell, _, _ = _violations(cx, f)
    order = np.lexsort((cell, face))
    return [(cx.simplex(int(a)), cx.simplex(int(b))) for a, b in zip(face[order], cell[order])]


def sublevel_complex(values: Mapping[Sequence[int], float], a: float) -> list[Simplex]:
    """K^a: the simplices with value ≤ a together with all their faces.

    Thesis: §4.2.2, K^a = ∪_{f(σ) ≤ a} ∪_{τ ≤ σ} τ (Theorems 4.25–4.26).

    Returns the simplices of K^a by dimension then lexicographically (empty list if none).
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


def discrete_morse_function(simplices, pairs) -> dict[Simplex, float]:
    """A discrete Morse function whose gradient vector field is the given acyclic field.

    Thesis: Theorem 4.36 (acyclic fields are gradients), built from a topological order of the
    modified Hasse diagram of Theorem 4.44: every edge u → v gets f(u) > f(v).

    Values are the integers 1..n.  Raises ValueError if the field has a closed V-path.
    """
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    src, dst = _hasse_edges(cx, partner)
    order = np.argsort(src, kind="stable")
    ptr = np.concatenate([[0], np.cumsum(np.bincount(src, minlength=cx.n))]).astype(np.int64)
    rank = topological_rank(cx.n, ptr, dst[order])
    if (rank < 0).any():
        vrank, g = _ranks(cx, partner)
        raise _cyclic_field_error(cx, partner, vrank, g)
    f = cx.n - rank
    return {cx.simplex(g): float(f[g]) for g in range(cx.n)}

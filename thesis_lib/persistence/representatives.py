"""Representative cycles of barcode intervals, by a homology column reduction that keeps track of V.

For an interval ``[deg σ, deg τ)`` the reduced boundary column ``R_τ = ∂(V_τ)`` is a cycle whose latest
simplex is σ: it is born with σ and is a boundary from τ on.  For an essential interval born at σ
the column ``V_σ`` (``∂ V_σ = 0``, latest simplex σ) is the cycle.  Only the columns that matter are
reduced (those killing a class, known from the engine's pairing), by the library's one column
reduction (:func:`~thesis_lib.persistence.kernels.reduce_columns`), which keeps R or V.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .kernels import KEEP_REDUCED, KEEP_V_ALL, reduce_columns

__all__ = ["Representatives"]


class Representatives:
    """Lazily computed representative cycles of one homology dimension of a filtration.

    Thesis: Theorem 2.39 (the basis elements z_i of Z_p read off the column-echelon form).

    Parameters
    ----------
    K : Filtration
        The filtration.
    dim : int
        The homology dimension.
    p : int
        A prime: the field Z/p.
    deaths_up : array_like of int
        Indices of all (dim+1)-simplices that kill a dim-class (zero-length pairs included).
    deaths_here : array_like of int
        Indices of all dim-simplices that kill a (dim−1)-class.
    """

    def __init__(self, K: Any, dim: int, p: int, deaths_up: np.ndarray, deaths_here: np.ndarray):
        self.K, self.dim, self.p = K, dim, p
        self.deaths_up = np.asarray(deaths_up, dtype=np.int64)
        self.deaths_here = np.asarray(deaths_here, dtype=np.int64)
        self._ranks: dict[int, np.ndarray] = {}
        self._finite: tuple[np.ndarray, ...] | None = None
        self._essential: dict[int, dict[int, int]] = {}

    def _rank(self, d: int) -> np.ndarray:
        if d not in self._ranks:
            order = np.argsort(self.K.values[d], kind="stable")
            rank = np.empty_like(order)
            rank[order] = np.arange(order.shape[0])
            self._ranks[d] = rank
        return self._ranks[d]

    def _reduce(self, d: int, columns: np.ndarray, keep: int) -> tuple:
        """Reduce the boundary columns ``columns`` (d-simplices, in filtration order) over the
        (d−1)-simplices, pivot = latest face: :func:`reduce_columns`' output and the facet array."""
        F = np.ascontiguousarray(self.K.facet_indices(d), dtype=np.int64)
        m, w = F.shape
        signs = 1 - 2 * (np.arange(w, dtype=np.int64) & 1)  # σ omitting vertex i has sign (−1)^i
        rank = self._rank(d - 1)
        latest = np.argmax(rank[F], axis=1)
        out = reduce_columns(
            np.arange(0, m * w + 1, w, dtype=np.int64), F.ravel(), np.tile(signs, m), -rank.astype(np.float64),
            np.ascontiguousarray(columns, dtype=np.int64), np.zeros(m, dtype=np.bool_), F[np.arange(m), latest],
            signs[latest], np.int64(self.p), keep,
        )
        return out, F, signs

    def _chain(self, j: int, start: np.ndarray, length: np.ndarray, keys: np.ndarray, coefs: np.ndarray,
               alone: dict[int, int]) -> dict[int, int]:
        """The kept chain of column j (``alone`` when the column was not added to)."""
        if start[j] == -1:
            return alone
        s = slice(start[j], start[j] + length[j])
        return dict(zip(keys[s].tolist(), coefs[s].tolist()))

    def finite(self, tau: int) -> dict[int, int]:
        """R_τ: the reduced boundary of the killing (dim+1)-simplex τ (a cycle of dim-simplices).

        Thesis: Theorem 2.39 (z_i for a finite interval: a boundary from deg τ on).

        Parameters
        ----------
        tau : int
            Index of τ in ``K.simplices[dim + 1]``; one of ``deaths_up``.

        Returns
        -------
        dict of int to int
            ``{index of a dim-simplex: coefficient in 1 .. p − 1}``; its latest simplex creates the class.

        Raises
        ------
        KeyError
            τ is not one of ``deaths_up``.
        """
        tau = int(tau)
        if self._finite is None:
            d = self.dim + 1
            cols = self.deaths_up[np.argsort(self._rank(d)[self.deaths_up], kind="stable")]
            (_, _, zero, _, start, length, keys, coefs), F, signs = self._reduce(d, cols, KEEP_REDUCED)
            if zero.shape[0]:  # cannot happen for a killing simplex
                raise RuntimeError(f"simplex {int(zero[0])} of dimension {d} does not kill a class")
            self._finite = (set(cols.tolist()), start, length, keys, coefs, F, signs)
        killing, start, length, keys, coefs, F, signs = self._finite
        if tau not in killing:
            raise KeyError(tau)
        boundary = {int(f): int(s) % self.p for f, s in zip(F[tau], signs)}
        return self._chain(tau, start, length, keys, coefs, boundary)

    def essential(self, sigma: int) -> dict[int, int]:
        """V_σ: a cycle ∂V_σ = 0 whose latest simplex is the dim-simplex σ (an essential class).

        Thesis: Theorem 2.39 (z_i for an infinite interval).

        Parameters
        ----------
        sigma : int
            Index of σ in ``K.simplices[dim]``; σ must create a class that never dies.

        Returns
        -------
        dict of int to int
            ``{index of a dim-simplex: coefficient in 1 .. p − 1}``, σ among them.

        Raises
        ------
        RuntimeError
            σ's boundary does not reduce to zero (σ does not create a class).
        """
        sigma, d = int(sigma), self.dim
        if d == 0:
            return {sigma: 1}
        if sigma not in self._essential:
            # the killing columns before σ (the only ones σ's column meets), then σ's own
            rank = self._rank(d)
            before = self.deaths_here[rank[self.deaths_here] < rank[sigma]]
            cols = np.append(before[np.argsort(rank[before], kind="stable")], sigma)
            (_, _, zero, _, start, length, keys, coefs), _, _ = self._reduce(d, cols, KEEP_V_ALL)
            if zero.shape[0] == 0 or zero[-1] != sigma:
                raise RuntimeError(f"simplex {sigma} of dimension {d} does not create an essential class")
            self._essential[sigma] = self._chain(sigma, start, length, keys, coefs, {sigma: 1})
        return self._essential[sigma]

    def cycle(self, sigma: int, tau: int) -> list[tuple[tuple[int, ...], int]]:
        """The representative of the interval created by σ and killed by τ (``-1``: essential).

        Thesis: Theorem 2.39 (the basis cycles z_i).

        Parameters
        ----------
        sigma : int
            Index of the creating simplex in ``K.simplices[dim]``.
        tau : int
            Index of the killing simplex in ``K.simplices[dim + 1]``, ``-1`` for an essential class.

        Returns
        -------
        list of (tuple of int, int)
            ``(simplex as a vertex tuple, coefficient in 1 .. p − 1)`` in filtration order.
        """
        chain = self.essential(sigma) if tau < 0 else self.finite(tau)
        rank = self._rank(self.dim)
        S = self.K.simplices[self.dim]
        return [(tuple(int(x) for x in S[s]), int(c)) for s, c in sorted(chain.items(), key=lambda sc: rank[sc[0]])]

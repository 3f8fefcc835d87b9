"""Representative cycles of barcode intervals, by a homology column reduction that keeps track of V.

For an interval ``[deg σ, deg τ)`` the reduced boundary column ``R_τ = ∂(V_τ)`` is a cycle whose latest
simplex is σ: it is born with σ and is a boundary from τ on.  For an essential interval born at σ
the column ``V_σ`` (``∂ V_σ = 0``, latest simplex σ) is the cycle.  Pure Python on sparse chains, only
the columns that matter are reduced (those killing a class, known from the engine's pairing).
"""

from __future__ import annotations

import numpy as np

__all__ = ["Representatives"]


def _signed_boundary(K, d: int, j: int, p: int) -> dict[int, int]:
    if d == 0:
        return {}
    f = K.facet_indices(d)[j]
    return {int(f[i]): (-1) ** i % p for i in range(d + 1)}


def _axpy(x: dict[int, int], a: int, y: dict[int, int], p: int) -> None:
    """x ← x + a·y over Z/p, in place."""
    for k, c in y.items():
        v = (x.get(k, 0) + a * c) % p
        if v:
            x[k] = v
        else:
            x.pop(k, None)


class Representatives:
    """Lazily computed representative cycles of one homology dimension of a filtration.

    Thesis: Theorem 2.39 (the basis elements z_i of Z_p read off the column-echelon form).

    Parameters
    ----------
    K : the Filtration.
    dim : homology dimension.
    p : prime.
    deaths_up : indices of all (dim+1)-simplices that kill a dim-class (zero-length pairs included).
    deaths_here : indices of all dim-simplices that kill a (dim−1)-class.
    """

    def __init__(self, K, dim: int, p: int, deaths_up: np.ndarray, deaths_here: np.ndarray):
        self.K, self.dim, self.p = K, dim, p
        self.deaths_up = np.asarray(deaths_up, dtype=np.int64)
        self.deaths_here = np.asarray(deaths_here, dtype=np.int64)
        self._finite: dict[int, dict[int, int]] | None = None
        self._vstate: tuple[dict, dict, dict] | None = None

    def _rank(self, d: int) -> np.ndarray:
        cache = self.__dict__.setdefault("_ranks", {})
        if d in cache:
            return cache[d]
        order = np.argsort(self.K.values[d], kind="stable")
        rank = np.empty_like(order)
        rank[order] = np.arange(order.shape[0])
        cache[d] = rank
        return rank

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
        if self._finite is None:
            K, d, p = self.K, self.dim, self.p
            rank_up, rank = self._rank(d + 1), self._rank(d)
            cols = self.deaths_up[np.argsort(rank_up[self.deaths_up], kind="stable")]
            owner: dict[int, dict[int, int]] = {}  # pivot (dim-simplex) -> reduced column
            out: dict[int, dict[int, int]] = {}
            for t in cols.tolist():
                r = _signed_boundary(K, d + 1, t, p)
                while r:
                    low = max(r, key=lambda s: rank[s])
                    if low not in owner:
                        break
                    o = owner[low]
                    _axpy(r, -r[low] * pow(o[low], p - 2, p) % p, o, p)
                if not r:  # cannot happen for a killing simplex
                    raise RuntimeError(f"simplex {t} of dimension {d + 1} does not kill a class")
                owner[max(r, key=lambda s: rank[s])] = r
                out[t] = r
            self._finite = out
        return self._finite[int(tau)]

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
        K, d, p = self.K, self.dim, self.p
        sigma = int(sigma)
        if self._vstate is not None:
            rank0, done0 = self._vstate[0], self._vstate[4]
            if done0 and rank0[done0[-1]] > rank0[sigma]:  # reduced past σ already: start again
                self._vstate = None
        if self._vstate is None:
            rank = self._rank(d)
            rank_low = self._rank(d - 1) if d > 0 else None
            cols = self.deaths_here[np.argsort(rank[self.deaths_here], kind="stable")]
            owner: dict[int, tuple[dict[int, int], dict[int, int]]] = {}
            done: list[int] = []
            self._vstate = (rank, rank_low, cols, owner, done)
        rank, rank_low, cols, owner, done = self._vstate

        def reduce(j: int) -> tuple[dict[int, int], dict[int, int]]:
            r = _signed_boundary(K, d, j, p)
            v = {j: 1}
            while r:
                low = max(r, key=lambda s: rank_low[s])
                if low not in owner:
                    break
                ro, vo = owner[low]
                a = -r[low] * pow(ro[low], p - 2, p) % p
                _axpy(r, a, ro, p)
                _axpy(v, a, vo, p)
            return r, v

        # reduce the killing columns that come before σ (those are the only ones σ's column meets)
        pos = len(done)
        while pos < cols.shape[0] and rank[cols[pos]] < rank[sigma]:
            j = int(cols[pos])
            r, v = reduce(j)
            owner[max(r, key=lambda s: rank_low[s])] = (r, v)
            done.append(j)
            pos += 1
        r, v = reduce(sigma) if d > 0 else ({}, {sigma: 1})
        if r:
            raise RuntimeError(f"simplex {sigma} of dimension {d} does not create an essential class")
        return v

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

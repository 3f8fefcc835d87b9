"""Partial pivoting, shared by the small dense solvers of the Čech and alpha constructions
(:mod:`.miniball`'s Gaussian elimination and :mod:`.filters`' Gauss–Jordan inverse)."""

from __future__ import annotations

from ..jit import njit


@njit(cache=True, inline="always")
def pivot_row(mat, col, k):
    """The row ``r`` in ``col..k-1`` with the largest ``|mat[r, col]|`` (the first on ties), and that
    magnitude.  Inlined: it runs once per column of every small elimination."""
    piv = col
    best = abs(mat[col, col])
    for r in range(col + 1, k):
        if abs(mat[r, col]) > best:
            best = abs(mat[r, col])
            piv = r
    return piv, best

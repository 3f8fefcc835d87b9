"""The field arithmetic and the column heap shared by every persistence reduction of the library.

One modular inverse and one heap serve the explicit engine (:mod:`.engine`), the implicit Rips
engine (:mod:`.implicit`), the reduction of a general filtered chain complex (:mod:`.chains`, used by
the Morse reduction) and the thesis's literal Algorithms 1–2 (:mod:`.algorithm`, through
:func:`inverse`).  A working column of a reduction is a binary min-heap of entries
``(value, key, coefficient)`` ordered by ``(value, key)``: the *pivot* of the column is its least entry
whose coefficients (entries of the same key are summed lazily, as in Ripser) do not cancel mod p.
"""

from __future__ import annotations

import numpy as np

from ..jit import njit

__all__ = ["inverse", "mod_inverse", "heap_push", "heap_pop", "heap_replace_top", "pop_pivot", "merge_entries", "grow"]


def inverse(a: int, p: int) -> int:
    """a⁻¹ in Z/p for a prime p (Python integers; Fermat: a^(p−2)).

    Thesis: Algorithm 1 (Reduce), the factor q⁻¹ of ``d = d − q⁻¹ T[i]``.

    Parameters
    ----------
    a : int
        The element to invert; any integer not divisible by ``p`` (reduced mod ``p`` first).
    p : int
        A prime: the field Z/p.

    Returns
    -------
    int
        The residue b in ``1 .. p − 1`` with ``a · b ≡ 1 (mod p)`` (0 when ``p`` divides ``a``, which
        has no inverse: callers never ask for it).
    """
    return pow(int(a) % p, p - 2, p)


@njit(cache=True)
def mod_inverse(a: np.int64, p: np.int64) -> np.int64:
    """a⁻¹ in Z/p (extended Euclid) inside compiled kernels; ``p < 2**31`` so products fit in int64."""
    t, newt, r, newr = np.int64(0), np.int64(1), np.int64(p), np.int64(a % p)
    while newr != 0:
        q = r // newr
        t, newt = newt, t - q * newt
        r, newr = newr, r - q * newr
    return t % p


@njit(cache=True)
def heap_push(hv, hk, hc, n, v, k, c):
    """Push ``(value v, key k, coefficient c)`` on the heap of size ``n`` (arrays large enough); returns n + 1."""
    i = n
    while i > 0:
        par = (i - 1) >> 1
        if v < hv[par] or (v == hv[par] and k < hk[par]):
            hv[i] = hv[par]
            hk[i] = hk[par]
            hc[i] = hc[par]
            i = par
        else:
            break
    hv[i] = v
    hk[i] = k
    hc[i] = c
    return n + 1


@njit(cache=True)
def heap_pop(hv, hk, hc, n):
    """Remove the top of the heap of size ``n`` (read it first); returns n − 1."""
    n -= 1
    if n > 0:
        heap_replace_top(hv, hk, hc, n, hv[n], hk[n], hc[n])
    return n


@njit(cache=True)
def heap_replace_top(hv, hk, hc, n, v, k, c):
    """Replace the top of the heap of size ``n`` by ``(v, k, c)`` and restore the order (one sift-down)."""
    i = 0
    while True:
        left = 2 * i + 1
        if left >= n:
            break
        m = left
        right = left + 1
        if right < n and (hv[right] < hv[left] or (hv[right] == hv[left] and hk[right] < hk[left])):
            m = right
        if hv[m] < v or (hv[m] == v and hk[m] < k):
            hv[i] = hv[m]
            hk[i] = hk[m]
            hc[i] = hc[m]
            i = m
        else:
            break
    hv[i] = v
    hk[i] = k
    hc[i] = c


@njit(cache=True)
def pop_pivot(hv, hk, hc, n, p):
    """Pop entries until the least key whose summed coefficient is non-zero mod p.

    Returns ``(new size, value, key, coefficient)``; coefficient 0 (value ``inf``) when the column is zero.
    The pivot is removed from the heap: a caller that adds a column with the same pivot skips that
    column's pivot entries, which cancel exactly.
    """
    while n > 0:
        v, k = hv[0], hk[0]
        c = hc[0]
        n = heap_pop(hv, hk, hc, n)
        while n > 0 and hk[0] == k and hv[0] == v:
            c += hc[0]
            n = heap_pop(hv, hk, hc, n)
        c %= p
        if c != 0:
            return n, v, k, c
    return n, np.inf, np.int64(0), np.int64(0)


@njit(cache=True)
def merge_entries(keys, coefs, n, p):
    """The distinct keys of ``keys[:n]`` with their coefficients summed mod p, zeros dropped.

    Returns ``(positions, sums)``: for each surviving key (increasing) one position in ``keys``
    holding it (to read parallel arrays) and its summed coefficient.  Used to store a reduction
    chain V after a column was reduced.
    """
    order = np.argsort(keys[:n])
    pos = np.empty(n, dtype=np.int64)
    sums = np.empty(n, dtype=np.int64)
    q = 0
    i = 0
    while i < n:
        first = order[i]
        c = np.int64(0)
        while i < n and keys[order[i]] == keys[first]:
            c += coefs[order[i]]
            i += 1
        c %= p
        if c != 0:
            pos[q] = first
            sums[q] = c
            q += 1
    return pos[:q], sums[:q]


@njit(cache=True)
def grow(hv, hk, hc, n, need):
    """The heap arrays with room for ``need`` entries (the first ``n`` kept): doubled when too small."""
    if need <= hv.shape[0]:
        return hv, hk, hc
    cap = hv.shape[0]
    while cap < need:
        cap *= 2
    nv = np.empty(cap, dtype=hv.dtype)
    nk = np.empty(cap, dtype=hk.dtype)
    nc = np.empty(cap, dtype=hc.dtype)
    nv[:n] = hv[:n]
    nk[:n] = hk[:n]
    nc[:n] = hc[:n]
    return nv, nk, nc

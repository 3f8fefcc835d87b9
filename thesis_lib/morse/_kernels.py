"""Internal numba kernels: topological order, greedy matchings (and their driver) and gradient-path propagation."""

from __future__ import annotations

import heapq

import numba
import numpy as np


@numba.njit(cache=True)
def topological_rank(n, ptr, idx):
    """Kahn's algorithm on the digraph (CSR ``ptr``/``idx``); rank[v] = position, -1 if on/after a cycle."""
    indeg = np.zeros(n, dtype=np.int64)
    for e in range(ptr[n]):
        indeg[idx[e]] += 1
    queue = np.empty(n, dtype=np.int64)
    head = 0
    tail = 0
    for v in range(n):
        if indeg[v] == 0:
            queue[tail] = v
            tail += 1
    rank = np.full(n, -1, dtype=np.int64)
    while head < tail:
        v = queue[head]
        rank[v] = head
        head += 1
        for e in range(ptr[v], ptr[v + 1]):
            w = idx[e]
            indeg[w] -= 1
            if indeg[w] == 0:
                queue[tail] = w
                tail += 1
    return rank


@numba.njit(cache=True)
def greedy_matching(n, down_ptr, down_idx, up_ptr, up_idx, vals, order):
    """Greedy coreduction (down = faces) or collapse (down = cofaces) restricted to equal ``vals``.

    A cell whose single remaining ``down`` neighbour (of equal value) is σ is paired with σ and both
    are removed; when there is no such cell, the first remaining cell of ``order`` is made critical.
    Returns ``partner`` (-1 for critical cells).
    """
    removed = np.zeros(n, dtype=np.bool_)
    cnt = np.zeros(n, dtype=np.int64)
    for g in range(n):
        c = 0
        for e in range(down_ptr[g], down_ptr[g + 1]):
            if vals[down_idx[e]] == vals[g]:
                c += 1
        cnt[g] = c
    queue = np.empty(2 * n + 1, dtype=np.int64)
    head = 0
    tail = 0
    for g in range(n):
        if cnt[g] == 1:
            queue[tail] = g
            tail += 1
    partner = np.full(n, -1, dtype=np.int64)
    pointer = 0
    done = 0
    gone = np.empty(2, dtype=np.int64)  # the cells removed in this step: a pair (σ, g), or one critical cell
    while done < n:
        if head < tail:
            g = queue[head]
            head += 1
            if removed[g] or cnt[g] != 1:
                continue
            s = -1
            for e in range(down_ptr[g], down_ptr[g + 1]):
                j = down_idx[e]
                if vals[j] == vals[g] and not removed[j]:
                    s = j
                    break
            partner[g] = s
            partner[s] = g
            gone[0], gone[1] = s, g
            n_gone = 2
        else:
            while removed[order[pointer]]:
                pointer += 1
            gone[0] = order[pointer]
            n_gone = 1
        for k in range(n_gone):
            c = gone[k]
            removed[c] = True
            done += 1
            for e in range(up_ptr[c], up_ptr[c + 1]):
                h = up_idx[e]
                if not removed[h] and vals[h] == vals[c]:
                    cnt[h] -= 1
                    if cnt[h] == 1:
                        queue[tail] = h
                        tail += 1
    return partner


@numba.njit(cache=True)
def morse_columns(n, ptr, idx, data, partner, rank, is_crit, sources, p):
    """Theorem 4.42 for every critical cell in ``sources``: flow ∂τ along gradient paths.

    Up-paired k-cells are eliminated in topological order of the V-path graph; the coefficients
    left on critical cells are the sums of multiplicities ±1 over gradient paths (mod p if p > 0).
    Returns COO triples (rows, cols, vals) in global ids and an overflow flag (|entry| > 2^60 over Z).
    """
    limit = np.int64(1) << 60
    overflow = False
    acc = np.zeros(n, dtype=np.int64)
    inheap = np.zeros(n, dtype=np.bool_)
    out_r = []
    out_c = []
    out_v = []
    touched = np.empty(n, dtype=np.int64)
    for t in sources:
        nt = 0
        heap = [(np.int64(0), np.int64(0))]
        heap.pop()
        for e in range(ptr[t], ptr[t + 1]):
            s = idx[e]
            acc[s] += data[e]
            if not inheap[s]:
                inheap[s] = True
                touched[nt] = s
                nt += 1
                if partner[s] > s:
                    heapq.heappush(heap, (rank[s], s))
        while len(heap) > 0:
            item = heapq.heappop(heap)
            s = item[1]
            a = acc[s]
            if p > 0:
                a = a % p
            if a == 0:
                continue
            tau = partner[s]
            sgn = 0
            for e in range(ptr[tau], ptr[tau + 1]):
                if idx[e] == s:
                    sgn = data[e]
            factor = -a * sgn
            for e in range(ptr[tau], ptr[tau + 1]):
                s2 = idx[e]
                acc[s2] += factor * data[e]
                if p > 0:
                    acc[s2] = acc[s2] % p
                elif acc[s2] > limit or acc[s2] < -limit:
                    overflow = True
                if not inheap[s2]:
                    inheap[s2] = True
                    touched[nt] = s2
                    nt += 1
                    if partner[s2] > s2:
                        heapq.heappush(heap, (rank[s2], s2))
        for i in range(nt):
            s = touched[i]
            a = acc[s]
            if p > 0:
                a = a % p
            if is_crit[s] and a != 0:
                out_r.append(s)
                out_c.append(t)
                out_v.append(a)
            acc[s] = 0
            inheap[s] = False
    return (
        np.array(out_r, dtype=np.int64), np.array(out_c, dtype=np.int64), np.array(out_v, dtype=np.int64), overflow
    )


def greedy_partner(cx, method: str, vals: np.ndarray | None = None, seed: int | None = None) -> np.ndarray:
    """Partners of the greedy ``"coreduction"`` or ``"collapse"`` matching on a CellComplex (see
    :func:`greedy_matching`), restricted to equal ``vals``; ``seed`` breaks ties at random."""
    faces = cx.D  # CSC: column g lists the faces of g
    cofaces = cx.cofaces  # CSR: row g lists the cofaces of g
    fptr, fidx = faces.indptr.astype(np.int64), faces.indices.astype(np.int64)
    cptr, cidx = cofaces.indptr.astype(np.int64), cofaces.indices.astype(np.int64)
    tie = np.arange(cx.n) if seed is None else np.random.default_rng(seed).permutation(cx.n)
    v = np.zeros(cx.n) if vals is None else np.asarray(vals, dtype=np.float64)
    if method == "coreduction":
        order = np.lexsort((tie, cx.dim_of)).astype(np.int64)  # lowest dimension first
        return greedy_matching(cx.n, fptr, fidx, cptr, cidx, v, order)
    order = np.lexsort((tie, -cx.dim_of)).astype(np.int64)  # top dimension first
    return greedy_matching(cx.n, cptr, cidx, fptr, fidx, v, order)

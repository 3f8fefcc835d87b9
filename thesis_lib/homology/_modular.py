"""Exact Smith normal form of a dense integer matrix by modular arithmetic.

The second stage of :mod:`thesis_lib.homology.smith`: the core left by sparse elimination is small but
dense, with entries of any size, and elimination over Z there makes the entries explode.  Here no
intermediate integer grows beyond a determinant, and no integer is factored.  For an ``m × n``
matrix ``A`` of rank ``r`` with invariant factors ``s_1 | s_2 | ... | s_r``:

1. **Rank profile modulo a prime** ``p`` (31 bits): rows ``I`` and columns ``J`` (``|I| = |J| = r_p``)
   with ``B = A[I, J]`` invertible mod ``p``, hence over Q: ``rank A ≥ r_p``.
2. **Determinant by Chinese remaindering**: ``det B`` and ``adj(B) y`` modulo as many 26-bit primes
   as it takes for their product to exceed twice Hadamard's bound (the product of the column
   norms); the symmetric residues are then the exact integers.
3. **Rank check** (Freivalds): ``rank A = r_p`` iff the Schur complement
   ``S = A[I', J'] − A[I', J] B⁻¹ A[I, J']`` (``I'``, ``J'`` the other rows and columns) is zero.  For
   two random vectors ``w`` with 62-bit entries the exact identity
   ``det(B) A[I', J'] w = A[I', J] adj(B) A[I, J'] w`` is checked; a nonzero ``S`` passes with
   probability at most ``2⁻⁶²`` per vector.  If it fails, ``p`` divided an ``(r_p + 1)``-minor: the
   next prime is tried.
4. **A multiple of the torsion**: ``d_r = s_1 ⋯ s_r`` divides every ``r × r`` minor, so
   ``M = gcd(det B, det B₂)`` (``B₂`` from the rank profile of ``A`` with shuffled rows and columns)
   is a multiple of ``d_r``, in practice a small one.  ``M = 1`` means every ``s_i = 1``.
5. Otherwise the **Smith form over Z/M**: every ``s_i`` divides ``M``, so reducing ``A`` modulo
   ``M`` and diagonalising by unimodular row and column operations (extended gcds, entries kept in
   ``[0, M)``) gives ``diag(s_1, ..., s_r, 0, ...)`` exactly.

Steps 1–3 cost ``O(m n r)`` word operations and ``O(r³)`` per prime; step 5 runs only when there
is torsion.  The word-size kernels (rank profile, determinant and adjugate modulo a prime, inverse
modulo a prime, p-adic digits) are compiled C++ (``src/modular_smith.cpp``).  (This is the
determinant-modulus idea of Kannan–Bachem and Hafner–McCurley with the modulus taken as a gcd of
minors instead of one determinant.)
"""

from __future__ import annotations

import math
import random

import numpy as np

from .._core import modular_smith
from .._validate import is_prime
from ._elimination import dense_kernel

__all__ = ["dense_invariants", "crt_primes"]

#: the CRT primes are the primes just below this bound (products of two residues are exact in float64)
_PRIME_BOUND = 2**26
#: entries below this bound are kept in int64 (products of two fit)
_WORD = 2**31
_PRIMES: list[int] = []
#: fixed seed of the random check vectors and shuffles: the result never depends on it (see step 3)
_SEED = 20110601


def crt_primes(count: int) -> list[int]:
    """The first ``count`` primes below 2²⁶, descending (cached)."""
    q = _PRIMES[-1] - 2 if _PRIMES else _PRIME_BOUND - 1
    while len(_PRIMES) < count:
        if is_prime(q):
            _PRIMES.append(q)
        q -= 2
    return _PRIMES[:count]


def _prime_stream():
    """The CRT primes one by one, as many as asked for."""
    i = 0
    while True:
        if i >= len(_PRIMES):
            crt_primes(len(_PRIMES) + 64)
        yield _PRIMES[i]
        i += 1


# --------------------------------------------------------------------------------------------
# exact integers from residues
# --------------------------------------------------------------------------------------------


def _residues(a: np.ndarray, p: int) -> np.ndarray:
    """``a mod p`` as float64 (``a`` int64 or an object array of Python ints; p < 2²⁶)."""
    if a.dtype == object:
        return (a % p).astype(np.float64)
    return np.mod(a, p).astype(np.float64)


def _column_norm_bound(a: np.ndarray) -> list[int]:
    """Upper bounds (integers) of the Euclidean norms of the columns of ``a``."""
    sq = (a.astype(object) ** 2).sum(axis=0) if a.size else np.zeros(a.shape[1], dtype=object)
    return [math.isqrt(int(s)) + 1 for s in sq]


def _crt(residues: list[np.ndarray], primes: list[int]) -> np.ndarray:
    """Symmetric CRT lift: the integers (object array) congruent to ``residues[i]`` mod ``primes[i]``."""
    modulus = math.prod(primes)
    basis = np.array([(modulus // q) * pow(modulus // q, -1, q) for q in primes], dtype=object)
    stack = np.stack([r.ravel() for r in residues]).astype(object)  # (K, V)
    x = basis.dot(stack) % modulus
    half = modulus // 2
    x = np.where(x > half, x - modulus, x)
    return x.reshape(residues[0].shape)


def _remainders(b: np.ndarray, y: np.ndarray, bound: int) -> tuple[list[int], list[np.ndarray], list[int]]:
    """det b and adj(b) y modulo 26-bit primes whose product exceeds ``2 · bound + 1``.

    Primes dividing det b are skipped (their adjugate is not reached by LU)."""
    r = b.shape[0]
    dets, zs, used = [], [], []
    product = 1
    for q in _prime_stream():
        if product > 2 * bound:
            break
        det, z, ok = modular_smith.det_adjugate(_residues(b, q), _residues(y, q) if y.size else np.zeros((r, 0)), q)
        if ok:
            dets.append(det)
            zs.append(z)
            used.append(q)
            product *= q
    return dets, zs, used


def _determinant(b: np.ndarray, y: np.ndarray) -> tuple[int, np.ndarray]:
    """``det b`` and ``adj(b) y`` exactly (``b`` nonsingular), by CRT to Hadamard's bound (Cramer's
    rule bounds ``|adj(b) y|`` by H(b)·‖y‖)."""
    hadamard = math.prod(_column_norm_bound(b))
    bound = hadamard * (max(_column_norm_bound(y)) if y.size else 1)
    dets, zs, used = _remainders(b, y, bound)
    det = int(_crt([np.array([d]) for d in dets], used)[0])
    return det, (_crt(zs, used) if y.size else np.zeros(y.shape, dtype=object))


def _horner(digits: np.ndarray, p: int) -> np.ndarray:
    """Σ_i digits[i] p^i (object array), by pairing digits level by level."""
    level = [d.astype(object) for d in digits]
    base = p
    while len(level) > 1:
        nxt = [level[i] + level[i + 1] * base for i in range(0, len(level) - 1, 2)]
        if len(level) % 2:
            nxt.append(level[-1])
        level, base = nxt, base * base
    return level[0]


def _rational(u: int, modulus: int, num_bound: int, den_bound: int) -> tuple[int, int] | None:
    """n/d ≡ u (mod modulus) with |n| <= num_bound, 0 < d <= den_bound (unique when 2·N·D < modulus)."""
    r0, r1 = modulus, u % modulus
    s0, s1 = 0, 1
    while r1 > num_bound:
        q = r0 // r1
        r0, r1 = r1, r0 - q * r1
        s0, s1 = s1, s0 - q * s1
    if s1 == 0 or abs(s1) > den_bound:
        return None
    return (r1, s1) if s1 > 0 else (-r1, -s1)


def _solve_dixon(b: np.ndarray, y: np.ndarray) -> tuple[int, np.ndarray] | None:
    """``(det b, adj(b) y)`` exactly by p-adic lifting (``b`` nonsingular, int64 entries below 2³¹,
    ``y`` int64 below 2⁶²); None when the entries are too large for a useful word-size prime.

    x = b⁻¹ y is lifted p-adically (Dixon), rebuilt as rationals with a common denominator δ as soon
    as the digits allow, and accepted only if ``b · (δ x) = δ y`` holds exactly (so the precision
    follows the size of the answer, not Hadamard's bound, which is far off for the ill-conditioned
    cores of elimination).  δ divides det b; the cofactor |det b| / δ ≤ H/δ comes from det b modulo
    primes.  Cost O(r³ + r²·K) instead of O(r³·K) for remaindering alone.
    """
    r, t = y.shape
    big = int(np.abs(b).max())
    p_max = min(2**31, (2**62) // (r * big + 1))
    if p_max < 2**10:
        return None
    hadamard = math.prod(_column_norm_bound(b))
    num_bound = hadamard * max(_column_norm_bound(y))
    q = p_max - 1
    while True:
        while not is_prime(q):
            q -= 1
        binv, ok = modular_smith.inverse_mod(b, q)
        if ok:
            break
        q -= 1
    most = 1  # with q**most > 2 N D the reconstruction is certain to exist
    while q**most <= 2 * num_bound * hadamard:
        most += 1
    res = np.array(y, dtype=np.int64, order="C")  # the residual, updated in place by the kernel
    u = np.zeros((r, t), dtype=object)
    steps, chunk = 0, 8
    b_obj = b.astype(object)
    while True:
        chunk = min(chunk, most - steps)
        u = u + _horner(modular_smith.dixon_digits(b, binv, res, q, chunk), q) * q**steps
        steps += chunk
        modulus = q**steps
        bound = math.isqrt((modulus - 1) // 2) if steps < most else None
        found = _reconstruct(u, modulus, bound, num_bound, hadamard)
        if found is not None:
            delta, numer = found
            if np.array_equal(b_obj.dot(numer), delta * y.astype(object)):
                break
        if steps >= most:  # pragma: no cover - the bounds make the last attempt succeed
            raise ArithmeticError("p-adic lifting did not converge")
        chunk *= 2
    # |det b| = delta · cofactor, the cofactor from det b modulo primes (its bound is H / delta)
    dets, _, used = _remainders(b, np.zeros((r, 0), dtype=np.int64), hadamard // delta + 1)
    cofactor = int(_crt([np.array([d * pow(delta, -1, q) % q]) for d, q in zip(dets, used)], used)[0])
    return delta * cofactor, numer * cofactor


def _reconstruct(u: np.ndarray, modulus: int, bound: int | None, num_bound: int, den_bound: int):
    """x ≡ u (mod modulus) as numer / delta (common denominator), or None.

    With ``bound`` None the rigorous bounds (2·num_bound·den_bound < modulus) are used and the
    answer is unique; otherwise numerators and denominators up to ``bound`` are tried (the caller
    checks the result exactly).
    """
    delta = 1
    numer = np.zeros(u.shape, dtype=object)
    for idx in np.ndindex(*u.shape):  # x = numer / delta, delta the least common denominator so far
        if bound is None:
            frac = _rational(delta * int(u[idx]), modulus, num_bound * delta, den_bound // delta)
        else:
            frac = _rational(delta * int(u[idx]), modulus, bound, bound // delta)
        if frac is None:
            return None
        n, d = frac
        if d > 1:
            numer *= d
            delta *= d
        numer[idx] = n
    return delta, numer


# --------------------------------------------------------------------------------------------
# Smith form over Z/M
# --------------------------------------------------------------------------------------------


def _egcd(a: int, b: int) -> tuple[int, int, int]:
    x0, y0, x1, y1 = 1, 0, 0, 1
    while b:
        q = a // b
        a, b = b, a - q * b
        x0, x1 = x1, x0 - q * x1
        y0, y1 = y1, y0 - q * y1
    return a, x0, y0


def _bezout(a: np.ndarray, k: int, i: int, x: int, y: int, modulus: int) -> None:
    """Rows k, i of ``a`` (x = a[k, 0] > 0, y = a[i, 0]) -> a unimodular combination with (gcd, 0) there.

    If x divides y it is one subtraction and the pivot stays x; otherwise the pivot becomes
    gcd(x, y) < x.
    """
    if y % x == 0:
        a[i] = (a[i] - (y // x) * a[k]) % modulus
        return
    d, s, t = _egcd(x, y)
    top = (s * a[k] + t * a[i]) % modulus
    a[i] = ((-(y // d)) * a[k] + (x // d) * a[i]) % modulus
    a[k] = top


def _smith_mod(a: np.ndarray, modulus: int) -> list[int]:
    """Diagonal of a Smith form of ``a`` over Z/modulus (``a`` reduced, int64 if modulus < 2³¹).

    Unit pivots first (the word-size kernel of the sparse stage, when the modulus allows), then
    extended-gcd steps on what is left."""
    a = a.copy()
    diag: list[int] = []
    if a.dtype != object and a.size:
        units, rows, cols = dense_kernel(a, modulus, 0)
        diag = [1] * int(units)
        a = a[~rows][:, ~cols]
    while a.size:
        nz = a != 0
        a = a[nz.any(axis=1)][:, nz.any(axis=0)]
        if a.size == 0:
            break
        g = np.gcd(a[:, 0], modulus)  # a unit of the first column, else the entry of least gcd with M
        i, j = int(np.argmin(g)), 0
        if g[i] != 1:
            g = np.gcd(a, modulus)
            i, j = np.unravel_index(int(np.argmin(g)), g.shape)
        a[[0, i]] = a[[i, 0]]
        a[:, [0, j]] = a[:, [j, 0]]
        while True:
            piv = int(a[0, 0])
            if math.gcd(piv, modulus) == 1:  # a unit: plain elimination; row 0 then clears by column ops
                f = (a[1:, 0] * pow(piv, -1, modulus)) % modulus
                a[1:, 1:] = (a[1:, 1:] - np.outer(f, a[0, 1:]).astype(a.dtype)) % modulus
                break
            for i in np.flatnonzero(a[1:, 0]) + 1:  # unimodular 2 × 2 row steps: (x, y) -> (gcd, 0)
                _bezout(a, 0, i, int(a[0, 0]), int(a[i, 0]), modulus)
            for j in np.flatnonzero(a[0, 1:]) + 1:  # the same with columns
                _bezout(a.T, 0, j, int(a[0, 0]), int(a[0, j]), modulus)
            if not a[1:, 0].any():  # the pivot only decreases, so this ends
                break
        diag.append(int(a[0, 0]))
        a = a[1:, 1:]
    return diag


def _chain(values: list[int], modulus: int, length: int) -> list[int]:
    """Divisors of ``modulus`` (0 read as ``modulus``) in divisibility order: diag(a, b) ~ diag(gcd, lcm)."""
    d = [math.gcd(v, modulus) for v in values] + [modulus] * max(0, length - len(values))
    for i in range(len(d)):
        for j in range(i + 1, len(d)):
            g = math.gcd(d[i], d[j])
            d[i], d[j] = g, d[i] // g * d[j]
    return d


# --------------------------------------------------------------------------------------------
# driver
# --------------------------------------------------------------------------------------------


def _as_exact(a: np.ndarray) -> np.ndarray:
    """int64 if every entry is below 2³¹ in absolute value (the kernels' range), else Python ints."""
    if a.dtype == object:
        if a.size == 0 or max(abs(int(x)) for x in a.flat) < _WORD:
            return a.astype(np.int64)
        return a
    if a.size and np.abs(a).max() >= _WORD:
        return a.astype(object)
    return a.astype(np.int64)


def _profile(a: np.ndarray, p: int, rows: np.ndarray, cols: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rank profile of ``a[rows][:, cols]`` mod p, as original row and column indices."""
    i, j = modular_smith.rank_profile(np.ascontiguousarray(_residues(a[rows][:, cols], p)), p)
    return rows[i], cols[j]


def _solve(b: np.ndarray, y: np.ndarray) -> tuple[int, np.ndarray]:
    """``(det b, adj(b) y)`` exactly: p-adic lifting when the entries allow, else remaindering."""
    if b.dtype != object and y.dtype != object:
        out = _solve_dixon(b, y)
        if out is not None:
            return out
    return _determinant(b, y)


def _check_vectors(a: np.ndarray, n: int, rng: random.Random) -> np.ndarray:
    """Random vectors w for the rank check: ``a @ w`` stays below 2⁶² for int64 ``a``, and the
    vectors together carry at least 64 random bits per coordinate."""
    if a.dtype == object:
        bits, count = 62, 2
    else:
        bits = max(1, 61 - int(np.abs(a).max()).bit_length() - max(1, n).bit_length())
        count = -(-64 // bits)
    dtype = object if a.dtype == object else np.int64
    return np.array([[rng.getrandbits(bits) for _ in range(count)] for _ in range(n)], dtype=dtype).reshape(n, count)


def _gcd_all(start: int, values: np.ndarray) -> int:
    g = abs(start)
    for v in values.flat:
        g = math.gcd(g, int(v))
        if g == 1:
            break
    return g


def dense_invariants(matrix: np.ndarray) -> list[int]:
    """The nonzero invariant factors ``s_1 | ... | s_r`` of an integer matrix, exactly (module docstring).

    ``matrix``: 2-D, int64 or an object array of Python ints.
    """
    a = _as_exact(np.asarray(matrix))
    nz = a != 0
    a = a[nz.any(axis=1)][:, nz.any(axis=0)]
    m, n = a.shape
    if a.size == 0:
        return []
    rng = random.Random(_SEED)
    all_rows, all_cols = np.arange(m), np.arange(n)
    for p in crt_primes(64):
        rows, cols = _profile(a, p, all_rows, all_cols)
        r = rows.size
        if r == 0:  # p divides every entry of a nonzero matrix: its rank mod p says nothing
            continue
        other_rows = np.setdiff1d(all_rows, rows)
        other_cols = np.setdiff1d(all_cols, cols)
        w = _check_vectors(a, other_cols.size, rng)
        y = a[np.ix_(rows, other_cols)].dot(w)
        det, z = _solve(a[np.ix_(rows, cols)], y)
        if not other_rows.size or not other_cols.size:
            break
        # Freivalds: det(B) A[I', J'] w = A[I', J] adj(B) A[I, J'] w exactly iff (w.h.p.) rank A = r
        left = det * a[np.ix_(other_rows, other_cols)].dot(w).astype(object)
        if np.array_equal(left, a[np.ix_(other_rows, cols)].astype(object).dot(z)):
            break
    else:  # pragma: no cover - 64 primes each dividing an (r+1)-minor
        raise ArithmeticError("rank of the dense core could not be certified")
    # every r x r minor of A is a multiple of d_r = s_1 ... s_r: det B, and each entry of adj(B) A[I, J'] w
    # (det B with one column replaced by A[I, J'] w, a combination of columns of A)
    modulus = _gcd_all(det, z)
    for _ in range(3):  # a large modulus: more minors, on shuffled rows and columns, may shrink it
        if modulus < _WORD or r == max(m, n):
            break
        rows2, _ = _profile(a, p, np.array(rng.sample(range(m), m), dtype=np.int64), cols)
        rows2, cols2 = _profile(a, p, rows2, np.array(rng.sample(range(n), n), dtype=np.int64))
        if rows2.size < r:
            continue
        rest = np.setdiff1d(all_cols, cols2)
        det2, z2 = _solve(a[np.ix_(rows2, cols2)], a[np.ix_(rows2, rest)].dot(_check_vectors(a, rest.size, rng)))
        modulus = _gcd_all(math.gcd(modulus, det2), z2)
    if modulus == 1:
        return [1] * r
    reduced = (a % modulus).astype(np.int64) if modulus < _WORD else a.astype(object) % modulus
    return _chain(_smith_mod(reduced, modulus), modulus, r)[:r]

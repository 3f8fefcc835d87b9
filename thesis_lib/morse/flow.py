"""The discrete gradient V, the discrete gradient flow Φ = 1 + ∂V + V∂ and its stabilisation Φ^∞.

All matrices act on the chain group of the whole complex, in the basis :func:`cells` (simplices by
dimension, then lexicographically, oriented by ascending vertices as in Definition 2.18).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
import scipy.sparse as sp

from ._cells import ComplexLike, Pairs, Simplex, cell_complex, partner_array

__all__ = ["cells", "boundary_operator", "gradient_matrix", "gradient_flow", "stabilised_flow", "is_flow_invariant"]


def cells(simplices: ComplexLike) -> list[Simplex]:
    """The basis used by :func:`gradient_matrix` and :func:`gradient_flow`: all simplices of the
    complex, by dimension then lexicographically.

    Thesis: §4.2.3 (C_k is the free Abelian group on the k-simplices, cells orthonormal).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        The complex whose simplices form the basis (all faces are added).

    Returns
    -------
    list of tuple
        The n simplices (ascending vertices) in basis order.

    Examples
    --------
    >>> cells([(0, 1), (0, 2), (1, 2)])
    [(0,), (1,), (2,), (0, 1), (0, 2), (1, 2)]
    """
    return cell_complex(simplices).simplices()


def boundary_operator(simplices: ComplexLike) -> sp.csc_matrix:
    """The boundary ∂ on the whole chain complex as one (n × n) integer matrix in the basis :func:`cells`.

    Thesis: Definition 2.18 (∂σ = Σ <∂σ, γ> γ, §4.2.3).

    Parameters
    ----------
    simplices : Filtration or iterable of simplices
        The complex, in any form :func:`cells` takes.

    Returns
    -------
    scipy.sparse.csc_matrix of int64, shape (n, n)
        ``D[face, cell] = <∂ cell, face>`` ∈ {−1, 0, 1}; a copy, free to modify.

    Examples
    --------
    The circle's ∂ in the basis :func:`cells`: column 01 is 1 − 0:

    >>> boundary_operator([(0, 1), (0, 2), (1, 2)]).toarray()[:3, 3:].tolist()
    [[-1, -1, 0], [1, 0, -1], [0, 1, 1]]
    """
    return cell_complex(simplices).D.copy()


def gradient_matrix(simplices: ComplexLike, pairs: Pairs) -> sp.csc_matrix:
    """The discrete gradient vector field V as an (n × n) integer matrix: V(σ) = -<∂τ, σ> τ for {σ < τ}.

    Thesis: Definition 4.30 (and Definition 4.33 for the pairs).

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and the vector field that V encodes, sigma a facet of tau (Definition 4.33).

    Returns
    -------
    scipy.sparse.csc_matrix of int64, shape (n, n)
        V in the basis :func:`cells`: column σ holds −<∂τ, σ> in row τ for each pair; zero columns
        for the other cells.

    Raises
    ------
    ValueError
        An invalid vector field (a pair that is not a facet of codimension one, a simplex in two
        pairs or not in the complex).

    Examples
    --------
    V sends the vertex 1 to −<∂(01), 1>·01 = −01 and 2 to −12:

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> V = gradient_matrix(circle, pairs).toarray()
    >>> V[:, 1].tolist(), V[:, 2].tolist()
    ([0, 0, 0, -1, 0, 0], [0, 0, 0, 0, 0, -1])
    """
    cx = cell_complex(simplices)
    partner = partner_array(cx, pairs)
    low = np.flatnonzero(partner > np.arange(cx.n))
    high = partner[low]
    signs = -np.asarray(cx.D[low, high]).ravel().astype(np.int64) if low.size else np.empty(0, np.int64)
    v = sp.csc_matrix((signs, (high, low)), shape=(cx.n, cx.n), dtype=np.int64)
    v.sort_indices()
    return v


def gradient_flow(simplices: ComplexLike, pairs: Pairs) -> sp.csc_matrix:
    """The discrete gradient flow Φ = id + ∂∘V + V∘∂ as an (n × n) integer matrix.

    Thesis: Definition 4.31.

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and the vector field; Φ is built from :func:`gradient_matrix` of them.

    Returns
    -------
    scipy.sparse.csc_matrix of int64, shape (n, n)
        Φ in the basis :func:`cells` (explicit zeros removed).

    Raises
    ------
    ValueError
        The pairs are not a vector field on the complex (see :func:`gradient_matrix`).

    Examples
    --------
    Φ = id + ∂V + V∂ moves the vertex 1 to 0 along the arrow 1 → 01 (column 1):

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> gradient_flow(circle, pairs).toarray()[:, 1].tolist()
    [1, 0, 0, 0, 0, 0]
    """
    cx = cell_complex(simplices)
    v = gradient_matrix(cx, pairs)
    phi = sp.identity(cx.n, dtype=np.int64, format="csc") + cx.D @ v + v @ cx.D
    phi = sp.csc_matrix(phi, dtype=np.int64)
    phi.eliminate_zeros()
    phi.sort_indices()
    return phi


def _equal(a: sp.spmatrix, b: sp.spmatrix) -> bool:
    return (a != b).nnz == 0


def stabilised_flow(simplices: ComplexLike, pairs: Pairs, *, max_iter: int | None = None) -> tuple[sp.csc_matrix, int]:
    """Φ^∞ = Φ^N for the first N with Φ^N = Φ^{N+1}, and that N.

    Thesis: Theorem 4.38 (Φ^N(c) = Φ^{N+1}(c) = ... = Φ^∞(c) for N large).

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and an acyclic vector field (a closed V-path keeps Φ^N from stabilising).
    max_iter : int, optional
        Largest power tried; default the number of cells + 1.

    Returns
    -------
    phi_infinity : scipy.sparse.csc_matrix of int64, shape (n, n)
        Φ^∞ in the basis :func:`cells`.
    n : int
        The first N with Φ^N = Φ^{N+1}.

    Raises
    ------
    ValueError
        Φ has not stabilised after ``max_iter`` steps, which happens for a vector field with a
        closed V-path; an invalid vector field.

    Examples
    --------
    Φ^∞ takes every vertex to the critical vertex 0 and the critical edge 02 to the cycle
    −01 + 02 − 12 around the circle; it stabilises after N = 2 steps:

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> phi, n = stabilised_flow(circle, pairs)
    >>> phi.toarray()[0, :3].tolist(), phi.toarray()[:, 4].tolist(), n
    ([1, 1, 1], [0, 0, 0, -1, 1, -1], 2)
    """
    cx = cell_complex(simplices)
    phi = gradient_flow(cx, pairs)
    limit = cx.n + 1 if max_iter is None else int(max_iter)
    power = sp.identity(cx.n, dtype=np.int64, format="csc")
    for n in range(limit + 1):
        nxt = sp.csc_matrix(phi @ power, dtype=np.int64)
        nxt.eliminate_zeros()
        if _equal(nxt, power):
            power.sort_indices()
            return power, n
        power = nxt
    raise ValueError(f"Φ^N did not stabilise within {limit} steps: is the vector field acyclic (Theorem 4.36)?")


def is_flow_invariant(simplices: ComplexLike, pairs: Pairs, chain: npt.ArrayLike) -> bool:
    """True when the chain (a length-n integer vector in the basis :func:`cells`) satisfies Φ(c) = c.

    Thesis: §4.2.4 (Φ-invariant chains form the Morse complex C^Φ).

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and the vector field that define Φ (see :func:`gradient_flow`).
    chain : array_like of int, shape (n,)
        Coefficients of the chain in the basis :func:`cells` (cast to int64).

    Returns
    -------
    bool
        Whether Φ(c) = c exactly.

    Raises
    ------
    ValueError
        A chain of the wrong length, or an invalid vector field.

    Examples
    --------
    The cycle −01 + 02 − 12 is Φ-invariant; the vertex 1 is not (it flows to 0):

    >>> circle = [(0, 1), (0, 2), (1, 2)]
    >>> pairs = [((1,), (0, 1)), ((2,), (1, 2))]
    >>> is_flow_invariant(circle, pairs, [0, 0, 0, -1, 1, -1]), is_flow_invariant(circle, pairs, [0, 1, 0, 0, 0, 0])
    (True, False)
    """
    cx = cell_complex(simplices)
    c = np.asarray(chain)
    if c.shape != (cx.n,):
        raise ValueError(f"a chain needs {cx.n} coefficients, got shape {c.shape}")
    phi = gradient_flow(cx, pairs)
    return bool(np.array_equal(phi @ c.astype(np.int64), c.astype(np.int64)))

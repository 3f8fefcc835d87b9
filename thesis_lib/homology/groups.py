"""Simplicial homology over Z and over Z/p (thesis §2.2.1).

``homology(simplices, coefficients=...)`` closes the input under faces, builds the signed boundary
matrices (Definition 2.18) and reads the groups off their Smith normal forms:
rank Z_p = m_p − k_p, rank B_p = k_{p+1}, β_p = m_p − k_p − k_{p+1}, and the diagonal entries ≥ 2
of ∂_{p+1} are the torsion coefficients of H_p.

The boundary matrices are reduced from the top dimension down with *clearing*: a p-simplex that
carries the pivot ±1 of a reduced column of ∂_{p+1} (a p-cycle) can be exchanged for that cycle by
a unimodular change of basis of C_p (the pivots form a triangular block with unit diagonal), and
∂_p kills the cycle; so its column of ∂_p is skipped without changing rank or torsion.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np
import scipy.sparse as sp

from .._validate import (
    MAX_EXACT_PRIME,
    MAX_LABEL,
    Field,
    check_coefficients,
    check_complex_size,
    parse_field,
    vertex_label,
)
from .filtration import Filtration, as_complex
from .simplicial import boundary_matrix
from .smith import reduce_checked

__all__ = [
    "homology",
    "boundary_matrices",
    "betti_numbers",
    "euler_characteristic",
    "simplex_counts",
    "universal_coefficient_betti",
    "group_latex",
]


def _complex(simplices: Filtration | Iterable[Sequence[int]] | np.ndarray) -> list[np.ndarray]:
    """The closed complex as one sorted vertex array per dimension (Definition 2.4).

    Refused up front: a closure beyond the memory budget (``check_complex_size``), an array of
    objects that are not integers, and vertex labels beyond int64 (>= 2⁶³).
    """
    simplices = _labels_fit(check_complex_size(simplices, "the complex"))
    try:
        return as_complex(simplices).simplices
    except (ValueError, TypeError, OverflowError):
        _labels_fit(simplices, scan=True)  # a clearer message when a label is the cause
        raise


def _labels_fit(simplices, *, scan: bool = False):
    """``simplices`` with object or unsigned arrays as int64, or a ValueError naming a label that
    is not an integer or does not fit in int64; ``scan``: also look through nested sequences."""
    if isinstance(simplices, np.ndarray):
        if simplices.dtype.kind == "u" and simplices.size and int(simplices.max()) > MAX_LABEL:
            raise ValueError(f"vertex label {int(simplices.max())} does not fit in int64 (labels must be < 2^63)")
        if simplices.dtype == object:
            flat = simplices.ravel().tolist()
            for v in flat:
                _one_label(v)
            return np.array(flat, dtype=np.int64).reshape(simplices.shape)
        return simplices
    if scan and isinstance(simplices, (list, tuple)):
        for s in simplices:
            if isinstance(s, np.ndarray):
                _labels_fit(s)
            elif isinstance(s, (list, tuple)):
                for v in s:
                    if not isinstance(v, (list, tuple, np.ndarray)):
                        _one_label(v)
    return simplices


def _one_label(v) -> int:
    label = vertex_label(v)
    if label > MAX_LABEL:
        raise ValueError(f"vertex label {label} does not fit in int64 (labels must be < 2^63)")
    return label


def boundary_matrices(complex_arrays: list[np.ndarray], *, coefficients: int = 0) -> list[sp.csc_matrix]:
    """Signed boundary matrices ∂_0, ..., ∂_top of a complex given as per-dimension sorted arrays.

    Thesis: Definition 2.18 (∂_p[x_0, ..., x_p] = Σ (−1)^i [x_0, ..., x̂_i, ..., x_p]).

    Parameters
    ----------
    complex_arrays : list of numpy.ndarray
        Entry ``k`` is the ``(m_k, k + 1)`` array of k-simplices of a closed complex, sorted rows (as
        from :func:`thesis_lib.homology.simplicial.closure` or ``Filtration.simplices``).
    coefficients : int
        0 for Z, or a prime p for Z/p (entries reduced mod p).

    Returns
    -------
    list of scipy.sparse.csc_matrix
        Entry ``k`` is ∂_k : C_k → C_{k−1} as an ``(m_{k−1}, m_k)`` int64 matrix; ∂_0 is ``(0, m_0)``.

    Raises
    ------
    ValueError
        No arrays, coefficients neither 0 nor a prime, or a face missing from the dimension below.

    Examples
    --------
    The boundary of the triangle [0, 1, 2]: ∂_1 sends each edge to its head minus its tail, and
    ∂_1 ∘ ∂_2 = 0.

    >>> from thesis_lib.homology.filtration import as_complex
    >>> d = boundary_matrices(as_complex([(0, 1, 2)]).simplices)
    >>> [m.shape for m in d]
    [(0, 3), (3, 3), (3, 1)]
    >>> d[1].toarray().tolist()
    [[-1, -1, 0], [1, 0, -1], [0, 1, 1]]
    >>> d[2].toarray().ravel().tolist()
    [1, -1, 1]
    >>> (d[1] @ d[2]).nnz
    0
    """
    p = check_coefficients(coefficients, max_prime=MAX_EXACT_PRIME)
    if not complex_arrays:
        raise ValueError("the complex is empty")
    out = [sp.csc_matrix((0, complex_arrays[0].shape[0]), dtype=np.int64)]
    for k in range(1, len(complex_arrays)):
        out.append(boundary_matrix(complex_arrays[k - 1], complex_arrays[k], coefficients=p))
    return out


def simplex_counts(simplices: Filtration | Iterable[Sequence[int]] | np.ndarray) -> list[int]:
    """Number m_k of k-simplices of the complex generated by ``simplices``, for k = 0..top.

    Thesis: §2.2.1 (m_p, the number of p-simplices, is the number of columns of M_p).

    Parameters
    ----------
    simplices : Filtration, iterable of sequences of int, or numpy.ndarray
        A complex (see :func:`homology`); all faces are added, values are ignored.

    Returns
    -------
    list of int
        Entry ``k`` is m_k, for k = 0, ..., the top dimension.

    Examples
    --------
    The 6-vertex RP² of Example 2.21 has 6 vertices, 15 edges and 10 triangles:

    >>> from thesis_lib.datasets import rp2
    >>> simplex_counts(rp2())
    [6, 15, 10]
    """
    return [int(a.shape[0]) for a in _complex(simplices)]


def euler_characteristic(simplices: Filtration | Iterable[Sequence[int]] | np.ndarray) -> int:
    """Σ_k (−1)^k m_k over the complex generated by ``simplices`` (equals Σ_k (−1)^k β_k).

    Thesis: §2.2.1 (β_p = m_p − k_p − k_{p+1}; the ranks cancel in the alternating sum).

    Parameters
    ----------
    simplices : Filtration, iterable of sequences of int, or numpy.ndarray
        The complex, in any form :func:`homology` accepts.

    Returns
    -------
    int
        The Euler characteristic χ.

    Examples
    --------
    χ(RP²) = 6 − 15 + 10 = 1 and χ(torus) = 0, as the alternating sum of Betti numbers says:

    >>> from thesis_lib.datasets import rp2, torus
    >>> euler_characteristic(rp2()), euler_characteristic(torus())
    (1, 0)
    """
    return int(sum((-1) ** k * m for k, m in enumerate(simplex_counts(simplices))))


def _homology_of_arrays(cx: list[np.ndarray], field: Field) -> list[tuple[int, list[int]]]:
    p = field.p
    top = len(cx) - 1
    ranks = [0] * (top + 2)
    invariants: list[list[int]] = [[] for _ in range(top + 2)]
    cleared = None
    for k in range(top, 0, -1):
        d = boundary_matrix(cx[k - 1], cx[k], coefficients=p)
        red = reduce_checked(d, field=field, skip_columns=cleared)
        ranks[k] = red.rank
        invariants[k] = red.invariants
        cleared = red.unit_pivot_rows
    out = []
    for k in range(top + 1):
        betti = int(cx[k].shape[0]) - ranks[k] - ranks[k + 1]
        torsion = sorted(int(t) for t in invariants[k + 1]) if p == 0 else []
        out.append((betti, torsion))
    return out


def homology(simplices: Filtration | Iterable[Sequence[int]] | np.ndarray,
             *, coefficients: int = 0) -> list[tuple[int, list[int]]]:
    """Homology groups H_0, ..., H_top of the simplicial complex generated by ``simplices``.

    Thesis: §2.2.1 and Example 2.21 (β_p = m_p − k_p − k_{p+1}; SNF entries ≥ 2 give torsion).

    Parameters
    ----------
    simplices : a complex: a ``Filtration`` (its values are ignored), an iterable of simplices
        (vertex tuples of any dimensions, an ``(m, k + 1)`` integer array, or a list of
        per-dimension arrays); all their faces are added.
    coefficients : 0 for the integers Z, or a prime p for the field Z/p.

    Returns
    -------
    list of ``(betti, torsion)`` indexed by dimension 0..top: ``H_k ≅ Z^betti ⊕ ⊕_t Z/t`` over Z,
    ``(Z/p)^betti`` over Z/p (``torsion`` is then empty).  ``torsion`` lists the torsion
    coefficients in the sense of the Smith normal form: the invariant factors ``> 1``, ascending,
    each dividing the next (Z/2 ⊕ Z/4 ⊕ Z/6 is reported as ``[2, 2, 12]``).

    Raises
    ------
    ValueError
        Empty input, a simplex with a repeated or negative vertex, or coefficients neither 0 nor
        a prime.

    Examples
    --------
    >>> from thesis_lib.datasets import rp2
    >>> homology(rp2())
    [(1, []), (0, [2]), (0, [])]
    """
    field = parse_field(coefficients, max_prime=MAX_EXACT_PRIME)
    return _homology_of_arrays(_complex(simplices), field)


def betti_numbers(simplices: Filtration | Iterable[Sequence[int]] | np.ndarray, *, coefficients: int = 0) -> list[int]:
    """Betti numbers β_0, ..., β_top (ranks of H_k over Z, or dimensions over Z/p).

    Thesis: Definition 2.19 (β_p = rank H_p = rank Z_p − rank B_p).

    Parameters
    ----------
    simplices : Filtration, iterable of sequences of int, or numpy.ndarray
        The complex (its faces are added; filtration values play no part).
    coefficients : int
        0 for the integers Z, or a prime p for the field Z/p.

    Returns
    -------
    list of int
        Entry ``k`` is β_k, for k = 0, ..., the top dimension.

    Raises
    ------
    ValueError
        As :func:`homology`.

    Examples
    --------
    The torus has β = (1, 2, 1); RP² has no free H_1 over Z but has H_1 = H_2 = Z/2 over Z/2:

    >>> from thesis_lib.datasets import rp2, torus
    >>> betti_numbers(torus())
    [1, 2, 1]
    >>> betti_numbers(rp2()), betti_numbers(rp2(), coefficients=2)
    ([1, 0, 0], [1, 1, 1])
    """
    return [b for b, _ in homology(simplices, coefficients=coefficients)]


def universal_coefficient_betti(integral: Sequence[tuple[int, Sequence[int]]], *, coefficients: int) -> list[int]:
    """The Betti numbers over Z/q predicted from the integral homology by the universal coefficient theorem.

    Thesis: §2.2.1 and Example 2.21 (torsion of H_p(Z) decides β_p over Z/2 against Z).

    β_p(Z/q) = rank H_p + #{torsion coefficients t of H_p with q | t} + #{those of H_{p−1}}:
    H_p ⊗ Z/q and Tor(H_{p−1}, Z/q) each contribute one Z/q per torsion coefficient divisible by q.

    Parameters
    ----------
    integral : sequence of (int, sequence of int)
        H_0, …, H_top over Z as :func:`homology` returns them (``(rank, torsion coefficients)``).
    coefficients : int
        The prime q.

    Returns
    -------
    list of int
        β_0, …, β_top over Z/q.

    Raises
    ------
    ValueError
        ``coefficients`` not a prime.

    Examples
    --------
    >>> from thesis_lib.datasets import rp2
    >>> h = homology(rp2())
    >>> universal_coefficient_betti(h, coefficients=2), universal_coefficient_betti(h, coefficients=3)
    ([1, 1, 1], [1, 0, 0])
    """
    q = parse_field(coefficients, field=True, max_prime=MAX_EXACT_PRIME).p
    groups = [(int(rank), [int(t) for t in torsion]) for rank, torsion in integral]
    return [rank + sum(t % q == 0 for t in torsion) + (sum(t % q == 0 for t in groups[p - 1][1]) if p else 0)
            for p, (rank, torsion) in enumerate(groups)]


def group_latex(rank: int, torsion: Sequence[int]) -> str:
    r"""An abelian group Z^rank ⊕ Z/t_1 ⊕ … written in LaTeX, as the chapter's tables show H_p.

    Thesis: Example 2.21 (H_0 = Z, H_1 = Z/2, H_2 = 0 for RP²).

    Parameters
    ----------
    rank : int
        The free rank, ≥ 0.
    torsion : sequence of int
        The torsion coefficients.

    Returns
    -------
    str
        ``$...$``: ``\\mathbb{Z}`` for rank 1, ``\\mathbb{Z}^{r}`` above, the torsion summands after it,
        ``$0$`` for the trivial group.

    Raises
    ------
    ValueError
        A negative rank or a torsion coefficient below 2.

    Examples
    --------
    >>> from thesis_lib.datasets import rp2
    >>> [group_latex(rank, torsion) for rank, torsion in homology(rp2())]
    ['$\\mathbb{Z}$', '$\\mathbb{Z}/2$', '$0$']
    >>> group_latex(2, [2, 4]), group_latex(0, [])
    ('$\\mathbb{Z}^{2} \\oplus \\mathbb{Z}/2 \\oplus \\mathbb{Z}/4$', '$0$')
    """
    if int(rank) < 0 or any(int(t) < 2 for t in torsion):
        raise ValueError(f"need a rank ≥ 0 and torsion coefficients ≥ 2, got {rank} and {list(torsion)}")
    parts = ([f"\\mathbb{{Z}}^{{{rank}}}" if rank > 1 else "\\mathbb{Z}"] if rank else [])
    parts += [f"\\mathbb{{Z}}/{t}" for t in torsion]
    return "$" + (" \\oplus ".join(parts) if parts else "0") + "$"

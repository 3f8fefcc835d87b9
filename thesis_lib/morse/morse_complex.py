"""The Morse complex of an acyclic discrete vector field and its homology (thesis §4.2.4–4.2.5)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import scipy.sparse as sp

from .._validate import MAX_EXACT_PRIME, check_coefficients
from ..smith import rank_mod_p, smith_normal_form
from ._cells import CellComplex, Simplex, as_complex, partner_array
from ._kernels import morse_columns
from .vector_field import Pairs, _ranks, _cyclic_field_error

__all__ = ["morse_boundary", "morse_homology", "chain_complex_homology"]


def _morse_boundary_ids(cx: CellComplex, partner: np.ndarray, coefficients: int = 0):
    """Critical global ids per dimension and Morse boundary matrices (internal, on global ids)."""
    rank, g = _ranks(cx, partner)
    if not (rank >= 0).all():
        raise _cyclic_field_error(cx, partner, rank, g)
    is_crit = partner < 0
    crit = np.flatnonzero(is_crit)
    sources = crit[cx.dim_of[crit] >= 1]
    rows, cols, vals, overflow = morse_columns(
        cx.n, cx.D.indptr.astype(np.int64), cx.D.indices.astype(np.int64), cx.D.data.astype(np.int64),
        partner, rank, is_crit, sources, int(coefficients),
    )
    if overflow:
        raise ValueError("Morse boundary coefficients exceed int64 over Z; use a prime p (coefficients=p)")
    local = np.full(cx.n, -1, dtype=np.int64)
    crit_by_dim = []
    for d in range(cx.dimension + 1):
        ids = crit[cx.dim_of[crit] == d]
        local[ids] = np.arange(ids.size)
        crit_by_dim.append(ids)
    mats = [sp.csc_matrix((0, crit_by_dim[0].size), dtype=np.int64)]
    cdim = cx.dim_of[cols] if cols.size else cols
    for d in range(1, cx.dimension + 1):
        m = cdim == d
        mat = sp.csc_matrix(
            (vals[m], (local[rows[m]], local[cols[m]])),
            shape=(crit_by_dim[d - 1].size, crit_by_dim[d].size), dtype=np.int64,
        )
        mat.sort_indices()
        mats.append(mat)
    return crit_by_dim, mats


def morse_boundary(simplices, pairs: Pairs, coefficients: int = 0) -> tuple[list[list[Simplex]], list[sp.csc_matrix]]:
    """Critical simplices per dimension and the Morse boundary ∂̃_k : M_k → M_{k-1} between them.

    Thesis: Theorem 4.42 (∂̃τ = Σ_σ σ · Σ_{γ ∈ Γ(τ, σ)} m(γ)), gradient paths of Definition 4.34.

    Parameters
    ----------
    simplices : the complex (all faces are added).
    pairs : the acyclic discrete vector field, pairs ``(sigma, tau)``.
    coefficients : 0 for Z, a prime p for Z/p (entries reduced to 0..p-1).

    Returns
    -------
    critical : ``critical[k]`` lists the critical k-simplices (lexicographic order).
    boundaries : ``boundaries[k]`` is the integer sparse matrix of ∂̃_k (rows: critical
        (k-1)-simplices, columns: critical k-simplices); ``boundaries[0]`` has no rows.

    Orientations are those of Definition 2.18 (vertices ascending).  Integer entries are exact in
    int64 (sums of ±1 over gradient paths).  Raises ValueError for a cyclic field.
    """
    p = check_coefficients(coefficients, max_prime=MAX_EXACT_PRIME)
    cx = as_complex(simplices)
    partner = partner_array(cx, pairs)
    crit, mats = _morse_boundary_ids(cx, partner, p)
    return [[cx.simplex(int(g)) for g in ids] for ids in crit], mats


def chain_complex_homology(boundaries: Sequence, coefficients: int = 0) -> list[tuple[int, list[int]]]:
    """Homology of a finite chain complex given by its boundary matrices ``boundaries[k]: C_k → C_{k-1}``.

    Thesis: Definition 2.19 / Theorem 2.20 (Betti numbers and torsion from Smith normal forms).

    ``boundaries[0]`` gives the number of 0-chains by its column count.  Returns, per dimension,
    ``(betti, torsion)`` like :func:`thesis_lib.homology.homology`.
    """
    p = check_coefficients(coefficients, max_prime=MAX_EXACT_PRIME)
    mats = [sp.csc_matrix(b) if not sp.issparse(b) else b for b in boundaries]
    if not mats:
        raise ValueError("the chain complex is empty")
    sizes = [m.shape[1] for m in mats]
    for k in range(1, len(mats)):
        if mats[k].shape[0] != sizes[k - 1]:
            raise ValueError(f"boundary {k} has {mats[k].shape[0]} rows but C_{k - 1} has {sizes[k - 1]} cells")
    ranks, divisors = [0], [[]]
    for k in range(1, len(mats)):
        if p:
            ranks.append(rank_mod_p(mats[k], p) if mats[k].nnz else 0)
            divisors.append([])
        else:
            d = [int(x) for x in smith_normal_form(mats[k])] if mats[k].nnz else []
            ranks.append(len(d))
            divisors.append(d)
    ranks.append(0)
    divisors.append([])
    out = []
    for k in range(len(mats)):
        betti = sizes[k] - ranks[k] - ranks[k + 1]
        torsion = sorted(x for x in divisors[k + 1] if x > 1)
        out.append((int(betti), torsion))
    return out


def morse_homology(simplices, pairs: Pairs, coefficients: int = 0) -> list[tuple[int, list[int]]]:
    """Homology from the critical simplices and the gradient paths between them.

    Thesis: Theorem 4.42 with Theorems 4.39 and 4.41 (H_k of the Morse complex ≅ H_k(K)).

    Same format as :func:`thesis_lib.homology.homology`: a list over dimensions of
    ``(betti, torsion)``.  Raises ValueError if the vector field has a closed V-path.
    """
    _, mats = morse_boundary(simplices, pairs, coefficients)
    return chain_complex_homology(mats, coefficients)

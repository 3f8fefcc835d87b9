"""Helpers shared by the tests (imported as ``from helpers import ...``; pytest puts tests/ on sys.path)."""

import numpy as np
from sympy import Matrix
from sympy.matrices.normalforms import invariant_factors

# M_2 of Example 2.21, rows ab ac ad ae af bc bd be bf cd ce cf de df ef,
# columns abd adf afc bcd ced cae abe bfe bcf def (copied from the thesis).
THESIS_M2 = np.array(
    [
        [1, 0, 0, 0, 0, 0, 1, 0, 0, 0],
        [0, 0, -1, 0, 0, -1, 0, 0, 0, 0],
        [-1, 1, 0, 0, 0, 0, 0, 0, 0, 0],
        [0, 0, 0, 0, 0, 1, -1, 0, 0, 0],
        [0, -1, 1, 0, 0, 0, 0, 0, 0, 0],
        [0, 0, 0, 1, 0, 0, 0, 0, 1, 0],
        [1, 0, 0, -1, 0, 0, 0, 0, 0, 0],
        [0, 0, 0, 0, 0, 0, 1, -1, 0, 0],
        [0, 0, 0, 0, 0, 0, 0, 1, -1, 0],
        [0, 0, 0, 1, -1, 0, 0, 0, 0, 0],
        [0, 0, 0, 0, 1, -1, 0, 0, 0, 0],
        [0, 0, -1, 0, 0, 0, 0, 0, 1, 0],
        [0, 0, 0, 0, -1, 0, 0, 0, 0, 1],
        [0, 1, 0, 0, 0, 0, 0, 0, 0, -1],
        [0, 0, 0, 0, 0, 0, 0, -1, 0, 1],
    ],
    dtype=np.int64,
)


def sympy_invariants(a) -> list[int]:
    """Reference: the nonzero invariant factors of an integer matrix (absolute values), from sympy."""
    a = np.asarray(a, dtype=object)
    if a.size == 0:
        return []
    return [abs(int(x)) for x in invariant_factors(Matrix(a.tolist())) if x != 0]


_PARI = []


def pari_invariants(a) -> list[int]:
    """Reference: the nonzero invariant factors (ascending) from PARI's ``matsnf`` (cypari2)."""
    if not _PARI:
        import cypari2

        pari = cypari2.Pari()
        pari.allocatemem(10**8, 2 * 10**9, silent=True)
        _PARI.append(pari)
    pari = _PARI[0]
    rows = np.asarray(a, dtype=object)
    if rows.size == 0:
        return []
    text = "[" + ";".join(",".join(str(int(x)) for x in row) for row in rows) + "]"
    return sorted(abs(int(x)) for x in pari.matsnf(pari(text)) if x != 0)

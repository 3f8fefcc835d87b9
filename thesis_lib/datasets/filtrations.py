"""Small filtrations from the thesis's worked examples."""

from __future__ import annotations

from ..filtration import Filtration

__all__ = ["example_filtration", "EXAMPLE_NAMES"]

#: vertex names of Figure 2.11: a, b, c, d, e = 0, 1, 2, 3, 4
EXAMPLE_NAMES = "abcde"


def example_filtration() -> Filtration:
    """The filtration K^0 ⊆ ... ⊆ K^4 of Figure 2.11 with vertices a, b, c, d, e = 0, 1, 2, 3, 4.

    Thesis: Figure 2.11, Examples 2.38, 2.40 and 2.41.

    The entry times are read off the powers of t in the boundary matrices of Examples 2.40/2.41
    (deg c_j = deg z_i + β_ij): a, b enter at 0; c, d, ab, cd at 1; e, da, bc at 2; ed, ce at 3;
    ced at 4.  Within a dimension the simplices are listed in the thesis's order
    (a, b, c, d, e; ab, cd, da, bc, ed, ce; ced).
    """
    a, b, c, d, e = range(5)
    pairs = [
        ((a,), 0), ((b,), 0),
        ((c,), 1), ((d,), 1), ((a, b), 1), ((c, d), 1),
        ((e,), 2), ((d, a), 2), ((b, c), 2),
        ((e, d), 3), ((c, e), 3),
        ((c, e, d), 4),
    ]  # fmt: skip
    return Filtration.from_pairs(pairs)

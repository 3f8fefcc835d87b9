"""The algebra core (thesis §2.2): simplices, filtered complexes, boundary matrices, their Smith normal
forms and ranks over Z and Z/p, and the simplicial homology groups read off them.

Modules, bottom up: :mod:`.simplicial` (simplices as integer arrays, closure, signed boundary
matrices), ``facet_lookup``, :mod:`.filtration` (the compact filtered complex), the sparse
elimination and modular arithmetic behind :mod:`.smith`, and ``groups`` (H_p over Z and Z/p).
"""

from .groups import (
    betti_numbers,
    boundary_matrices,
    euler_characteristic,
    group_latex,
    homology,
    simplex_counts,
    universal_coefficient_betti,
)
from .smith import smith_normal_form

__all__ = [
    "betti_numbers",
    "boundary_matrices",
    "euler_characteristic",
    "group_latex",
    "homology",
    "simplex_counts",
    "smith_normal_form",
    "universal_coefficient_betti",
]

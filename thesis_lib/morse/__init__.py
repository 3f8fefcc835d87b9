"""Smooth and discrete Morse theory (thesis chapter 4).

Modules: ``functions`` (discrete Morse functions, §4.2.1–4.2.2), ``vector_field`` (discrete
vector fields, V-paths, acyclicity, §4.2.3 and §4.2.6), ``flow`` (V, Φ, Φ^∞, §4.2.3–4.2.4),
``morse_complex`` (Morse boundary and homology, §4.2.5), ``matching`` (heuristic gradients,
§4.2.6), ``reduction`` (Morse reduction of filtrations for persistence) and ``smooth``
(the smooth examples of §4.1).
"""

from .examples import COMPLEX_NAMES, RP2_FACETS, example_4_45, experiment_complex, rp2_chart, rp2_gradient_field
from .flow import boundary_operator, cells, gradient_flow, gradient_matrix, is_flow_invariant, stabilised_flow
from .functions import (
    check_discrete_morse_function,
    critical_simplices,
    discrete_morse_function,
    gradient_pairs,
    is_discrete_morse_function,
    sublevel_complex,
)
from .matching import critical_counts, morse_matching
from .morse_complex import chain_complex_homology, morse_boundary, morse_homology
from .plotting import draw_gradient_field, draw_hasse_diagram, spectral_layout
from .reduction import (
    MorseReduction,
    chain_persistence,
    filtration_matching,
    lower_star_filtration,
    morse_reduce,
    reduced_persistence,
)
from .smooth import (
    morse_index,
    morse_inequalities,
    rp2_morse_complex,
    sphere_morse_complex,
    torus_critical_points,
    torus_height,
    torus_height_gradient,
    torus_height_hessian,
    torus_morse_complex,
)
from .vector_field import (
    check_vector_field,
    critical_cells,
    find_closed_vpath,
    gradient_paths,
    hasse_diagram,
    is_acyclic,
    vpath_graph,
    vpaths,
)

__all__ = [
    "RP2_FACETS",
    "rp2_gradient_field",
    "rp2_chart",
    "example_4_45",
    "experiment_complex",
    "COMPLEX_NAMES",
    "draw_gradient_field",
    "draw_hasse_diagram",
    "spectral_layout",
    "is_discrete_morse_function",
    "check_discrete_morse_function",
    "critical_simplices",
    "gradient_pairs",
    "sublevel_complex",
    "discrete_morse_function",
    "cells",
    "boundary_operator",
    "gradient_matrix",
    "gradient_flow",
    "stabilised_flow",
    "is_flow_invariant",
    "check_vector_field",
    "critical_cells",
    "vpath_graph",
    "is_acyclic",
    "find_closed_vpath",
    "vpaths",
    "gradient_paths",
    "hasse_diagram",
    "morse_matching",
    "critical_counts",
    "morse_boundary",
    "morse_homology",
    "chain_complex_homology",
    "MorseReduction",
    "filtration_matching",
    "lower_star_filtration",
    "morse_reduce",
    "reduced_persistence",
    "chain_persistence",
    "torus_height",
    "torus_height_gradient",
    "torus_height_hessian",
    "morse_index",
    "torus_critical_points",
    "morse_inequalities",
    "sphere_morse_complex",
    "rp2_morse_complex",
    "torus_morse_complex",
]

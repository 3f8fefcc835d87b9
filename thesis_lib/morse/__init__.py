"""Smooth and discrete Morse theory (thesis chapter 4).

Each module documents its own public names (its ``__all__``); this package re-exports them all:
``functions`` (discrete Morse functions, §4.2.1–4.2.2), ``vector_field`` (discrete vector fields,
V-paths, acyclicity, §4.2.3 and §4.2.6), ``flow`` (V, Φ, Φ^∞, §4.2.3–4.2.4), ``morse_complex``
(Morse boundary and homology, §4.2.5), ``matching`` (heuristic gradients, §4.2.6), ``reduction``
(Morse reduction of filtrations for persistence), ``gradients_compared`` (the greedy matching
against the apparent pairs), ``smooth`` (the smooth examples of §4.1),
``examples`` (the small complexes of chapter 4) and ``plotting`` (Figures 4.1, 4.4–4.8).  One module is
imported by name and not re-exported: ``checks`` (the statements of chapter 4 evaluated on inputs of our
choosing); the chapter 4 page's tables are in :mod:`thesis_lib.chapters.morse_tables`.
"""

from . import (
    examples,
    flow,
    functions,
    gradients_compared,
    matching,
    morse_complex,
    plotting,
    reduction,
    smooth,
    vector_field,
)
from .examples import *  # noqa: F403
from .flow import *  # noqa: F403
from .functions import *  # noqa: F403
from .gradients_compared import *  # noqa: F403
from .matching import *  # noqa: F403
from .morse_complex import *  # noqa: F403
from .plotting import *  # noqa: F403
from .reduction import *  # noqa: F403
from .smooth import *  # noqa: F403
from .vector_field import *  # noqa: F403

# one list per module, kept there; the forms below are those static checkers understand
__all__: list[str] = []
__all__ += examples.__all__
__all__ += plotting.__all__
__all__ += functions.__all__
__all__ += flow.__all__
__all__ += vector_field.__all__
__all__ += matching.__all__
__all__ += morse_complex.__all__
__all__ += reduction.__all__
__all__ += gradients_compared.__all__
__all__ += smooth.__all__

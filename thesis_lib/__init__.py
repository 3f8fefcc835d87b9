"""thesis_lib: the library behind the thesis-lab compendium of Botnan (2011),
*Three Approaches in Computational Geometry and Topology*.

Subpackages: :mod:`complexes`, :mod:`homology`, :mod:`persistence`, :mod:`curvature`,
:mod:`morse`, :mod:`datasets`; :mod:`results`, :mod:`data` and :mod:`report` serve the book.
"""

__version__ = "0.1.0"

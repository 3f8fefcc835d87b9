"""thesis_lib: the library behind the thesis-lab compendium of Botnan (2011),
*Three Approaches in Computational Geometry and Topology*.

Subpackages: :mod:`complexes`, :mod:`homology`, :mod:`persistence`, :mod:`curvature`,
:mod:`morse`, :mod:`datasets`, :mod:`meshes`; the applications of §2.4 in :mod:`applications`;
figure style and rendering in :mod:`graphics`; the laboratory (runner, results, report, data layer,
command line) in :mod:`lab`.
"""

__version__ = "0.1.0"

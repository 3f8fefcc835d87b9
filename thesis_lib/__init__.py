"""thesis_lib: the library behind the thesis-lab compendium of Botnan (2011),
*Three Approaches in Computational Geometry and Topology*.

Subpackages: :mod:`complexes`, :mod:`homology`, :mod:`persistence`, :mod:`curvature`,
:mod:`morse`, :mod:`datasets`, :mod:`meshes`; the applications of §2.4 in :mod:`applications`;
figure style and rendering in :mod:`graphics`; the laboratory (runner, results, report, data layer,
command line) in :mod:`lab`.

The library needs numpy and scipy only; each use adds an extra of the distribution: figures
``[plot]`` (matplotlib), mesh files, renders and ball pivoting ``[mesh]`` (pyvista, pymeshlab), the
PDB reader ``[proteins]`` (biotite), running experiments and the ``thesis-lab`` command ``[lab]``.
A function whose extra is missing raises an ImportError naming it, e.g. ``pip install "thesis-lab[plot]"``.
"""

__version__ = "0.1.0"

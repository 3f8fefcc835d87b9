"""Figure style (matplotlib) and off-screen 3-D rendering (pyvista) shared by every plotting function.

The layer imports nothing of the mathematics; the book's figures are built in
:mod:`thesis_lib.chapters` and the plotting functions of each subpackage.
"""

"""Figure style (matplotlib) and off-screen 3-D rendering (pyvista) shared by the plotting helpers."""

"""Off-screen 3-D rendering with pyvista (EGL, static Jupyter backend)."""

from __future__ import annotations

import os

__all__ = ["pyvista_offscreen"]


def pyvista_offscreen():
    """Return the ``pyvista`` module set up to render off-screen through EGL into static images."""
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    import pyvista as pv

    pv.OFF_SCREEN = True
    pv.set_jupyter_backend("static")
    pv.global_theme.window_size = [900, 700]
    return pv

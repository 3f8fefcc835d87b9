"""Off-screen 3-D rendering with pyvista (EGL, static Jupyter backend)."""

from __future__ import annotations

import os
import warnings
from types import ModuleType

from .._optional import require

__all__ = ["pyvista_offscreen"]


def pyvista_offscreen() -> ModuleType:
    """Return the ``pyvista`` module set up to render off-screen through EGL into static images.

    Sets ``VTK_DEFAULT_OPENGL_WINDOW`` (unless already set), ``pyvista.OFF_SCREEN``, the static
    Jupyter backend and a 900 × 700 window on the global theme: a side effect on the process.

    Returns
    -------
    types.ModuleType
        The imported ``pyvista`` module, configured.

    Raises
    ------
    ImportError
        If pyvista is not installed (the ``[mesh]`` extra).
    """
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    with warnings.catch_warnings():
        # pyvista imports tqdm.auto, which warns (with this machine's path) when ipywidgets is absent;
        # the warning would land in notebook stderr and make stored outputs machine-dependent.
        warnings.filterwarnings("ignore", message="IProgress not found")
        pv = require("pyvista", extra="mesh", purpose="rendering 3-D figures")

    pv.OFF_SCREEN = True
    pv.set_jupyter_backend("static")
    pv.global_theme.window_size = [900, 700]
    return pv

"""The optional dependencies: packages of the extras of pyproject.toml, imported where they are needed.

The library itself needs numpy and scipy only. Figures need the ``[plot]`` extra (matplotlib), mesh
files, renders and ball pivoting ``[mesh]`` (pyvista, pymeshlab), the PDB reader ``[proteins]``
(biotite), the laboratory and its ``thesis-lab`` command ``[lab]`` (papermill, nbformat, nbclient,
jupyter_client, pyzmq, traitlets, tqdm, dask, distributed). A module of thesis_lib never imports one
of these at its top: the function that needs it calls :func:`require`, whose ImportError names the
missing package and the command that installs it (tests/test_optional_dependencies.py checks both).
"""

from __future__ import annotations

import importlib
from types import ModuleType

__all__ = ["DISTRIBUTIONS", "EXTRAS", "MissingExtraError", "require"]

#: the extras of pyproject.toml that :func:`require` knows, each with the import names of its packages
EXTRAS: dict[str, tuple[str, ...]] = {
    "plot": ("matplotlib",),
    "mesh": ("pyvista", "pymeshlab"),
    "proteins": ("biotite",),
    "lab": ("papermill", "nbformat", "nbclient", "jupyter_client", "zmq", "traitlets", "tqdm", "dask",
            "distributed"),
}

#: the distribution (what pip installs) of an import name, where the two differ
DISTRIBUTIONS = {"zmq": "pyzmq"}


class MissingExtraError(ImportError):
    """An optional package is not installed; the message names it and the extra that installs it.

    ``extra`` is that extra (``"plot"``, ...); ``name`` the module that was asked for.
    """

    def __init__(self, message: str, *, name: str, extra: str):
        super().__init__(message, name=name)
        self.extra = extra


def require(module: str, *, extra: str, purpose: str) -> ModuleType:
    """Import and return an optional module, or say which extra of thesis-lab installs it.

    Thesis: none (packaging: the library needs numpy and scipy; each use adds its extra).

    Parameters
    ----------
    module : str
        The dotted name to import (``"matplotlib.pyplot"``); its top-level package must be one of
        the packages of ``extra`` (:data:`EXTRAS`).
    extra : str
        The extra of pyproject.toml that installs it: ``"plot"``, ``"mesh"``, ``"proteins"`` or
        ``"lab"``.
    purpose : str
        What the package is needed for, completing "... is needed for <purpose>".

    Returns
    -------
    types.ModuleType
        The imported module (``import a.b`` binds ``a``; this returns ``a.b`` itself).

    Raises
    ------
    MissingExtraError
        An ImportError, if the package is not installed: ``matplotlib is needed for plotting;
        install it with: pip install "thesis-lab[plot]"`` (the ModuleNotFoundError is its cause). An
        ImportError raised *inside* an installed package (one of its own dependencies missing or
        broken) propagates unchanged, since the extra would not fix it.
    ValueError
        If ``extra`` is not an extra of :data:`EXTRAS` or ``module`` is not one of its packages
        (a mistake in thesis_lib, not in the user's environment).

    Examples
    --------
    >>> try:  # doctest: +ELLIPSIS
    ...     pyplot = require("matplotlib.pyplot", extra="plot", purpose="plotting")
    ... except ImportError as error:  # without the [plot] extra
    ...     print(error)
    ... else:
    ...     print(pyplot.__name__)
    matplotlib...
    """
    if extra not in EXTRAS:
        raise ValueError(f"unknown extra {extra!r}; the extras are {sorted(EXTRAS)}")
    top = module.partition(".")[0]
    if top not in EXTRAS[extra]:
        raise ValueError(f"{top!r} is not a package of the [{extra}] extra ({', '.join(EXTRAS[extra])})")
    try:
        return importlib.import_module(module)
    except ModuleNotFoundError as error:
        # missing: the package itself or the submodule asked for, not something the package imports
        parts = module.split(".")
        if error.name not in {".".join(parts[:k]) for k in range(1, len(parts) + 1)}:
            raise
        package = DISTRIBUTIONS.get(top, top)
        message = f'{package} is needed for {purpose}; install it with: pip install "thesis-lab[{extra}]"'
        raise MissingExtraError(message, name=module, extra=extra) from error

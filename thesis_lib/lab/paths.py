"""Where the compendium keeps things: the project folder and the shared folder beside it.

The project is any folder that holds ``experiments/`` and ``data/manifest.toml`` (a git checkout, an
unpacked archive, a copy on a cluster node).  It is found, in this order, from

1. ``--project DIR`` on the command line (which sets ``THESIS_LAB_PROJECT``),
2. the environment variable ``THESIS_LAB_PROJECT``,
3. the current folder or the nearest folder above it that is a project,
4. the folder the package itself was installed from (an editable install inside a checkout).
"""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["PROJECT_ENV", "ProjectError", "is_project", "project_root", "shared_dir"]

#: environment variable naming the project folder (``thesis-lab --project DIR`` sets it)
PROJECT_ENV = "THESIS_LAB_PROJECT"


class ProjectError(ValueError):
    """No thesis-lab project folder could be found, or the one named is not a project."""


def is_project(folder: str | Path) -> bool:
    """Whether ``folder`` holds a thesis-lab project (``experiments/`` and ``data/manifest.toml``).

    Parameters
    ----------
    folder : str or pathlib.Path
        The folder to look at; it need not exist.

    Returns
    -------
    bool
        True when ``folder/experiments`` is a directory and ``folder/data/manifest.toml`` a file.
    """
    folder = Path(folder)
    return (folder / "experiments").is_dir() and (folder / "data" / "manifest.toml").is_file()


def project_root() -> Path:
    """The project folder this package works on (see the module docstring for the search order).

    Returns
    -------
    pathlib.Path
        The project folder, resolved.  A folder named by ``THESIS_LAB_PROJECT`` is returned as
        named, without checking that it holds a project.

    Raises
    ------
    ProjectError
        If the environment names a file, or no project is found.
    """
    named = os.environ.get(PROJECT_ENV)
    if named:
        folder = Path(named).expanduser().resolve()
        if folder.exists() and not folder.is_dir():
            raise ProjectError(f"{PROJECT_ENV}={named!r} is a file, not a project folder")
        return folder
    here = Path.cwd().resolve()
    for folder in (here, *here.parents):
        if is_project(folder):
            return folder
    installed = Path(__file__).resolve().parents[2]
    if is_project(installed):
        return installed
    raise ProjectError(
        f"no thesis-lab project found in {here} or above it, nor at {installed}: run from inside the "
        f"project folder, pass --project DIR, or set {PROJECT_ENV}=DIR"
    )


def shared_dir() -> Path:
    """The ``shared/`` folder beside the project (``THESIS_LAB_SHARED`` overrides it).

    Returns
    -------
    pathlib.Path
        ``THESIS_LAB_SHARED`` resolved when set, else ``project_root().parent / "shared"``; its
        existence is not checked.
    """
    env = os.environ.get("THESIS_LAB_SHARED")
    if env:
        return Path(env).resolve()
    return project_root().parent / "shared"

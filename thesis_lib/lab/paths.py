"""Where the compendium keeps things: the repository root and its folders."""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["repo_root", "shared_dir"]


def repo_root() -> Path:
    """The thesis-lab checkout this package runs from (``THESIS_LAB_ROOT`` overrides it)."""
    env = os.environ.get("THESIS_LAB_ROOT")
    if env:
        return Path(env).resolve()
    return Path(__file__).resolve().parents[2]


def shared_dir() -> Path:
    """The ``shared/`` folder beside the checkout (``THESIS_LAB_SHARED`` overrides it)."""
    env = os.environ.get("THESIS_LAB_SHARED")
    if env:
        return Path(env).resolve()
    return repo_root().parent / "shared"

"""Reading the project's TOML registries (the data manifest, the claims) with errors that name the file."""

from __future__ import annotations

import tomllib
from pathlib import Path

__all__ = ["read_tables"]


def read_tables(path: Path, key: str, error: type[Exception]) -> list:
    """The ``[[key]]`` tables of the TOML file ``path``; ``error`` (with the file named) when the file
    is missing, not UTF-8, not valid TOML, or ``key`` is not an array of tables."""
    try:
        with open(path, "rb") as fh:
            raw = tomllib.load(fh)
    except FileNotFoundError:
        raise error(f"no file {path}") from None
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path} is not valid TOML: {exc}") from None
    except UnicodeDecodeError as exc:
        raise error(f"{path} is not UTF-8 text: {exc}") from None
    items = raw.get(key, [])
    if not isinstance(items, list):
        raise error(f"{path}: '{key}' must be an array of tables ([[{key}]])")
    return items

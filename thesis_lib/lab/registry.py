"""Reading the project's TOML registries (the data manifest, the claims) with errors that name the file."""

from __future__ import annotations

import tomllib
from pathlib import Path

__all__ = ["read_tables"]


def read_tables(path: Path, *, key: str, error: type[Exception]) -> list:
    """The ``[[key]]`` tables of the TOML file ``path``.

    Parameters
    ----------
    path : pathlib.Path
        The TOML file to read.
    key : str
        The name of the array of tables (``[[key]]``).
    error : type of Exception
        The exception class raised, with the file named in its message, on any problem.

    Returns
    -------
    list
        The tables, as parsed by ``tomllib`` (an empty list when ``key`` is absent).  Their entries
        are not checked to be tables.

    Raises
    ------
    Exception
        An ``error`` (the class given) when the file is missing, not UTF-8, not valid TOML, or ``key``
        is not an array.
    """
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

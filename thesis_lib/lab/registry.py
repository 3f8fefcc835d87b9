"""Reading the project's TOML registries (the data manifest, the claims, the parameters' ranges) with errors
that name the file."""

from __future__ import annotations

import tomllib
from pathlib import Path

__all__ = ["read_tables", "read_mapping"]


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
    items = _load(path, error).get(key, [])
    if not isinstance(items, list):
        raise error(f"{path}: '{key}' must be an array of tables ([[{key}]])")
    return items


def read_mapping(path: Path, *, error: type[Exception]) -> dict:
    """The whole TOML file ``path`` as a mapping (``{}`` when the file does not exist).

    Parameters
    ----------
    path : pathlib.Path
        The TOML file to read; an optional registry, so a missing file reads as empty.
    error : type of Exception
        The exception class raised, with the file named in its message, on any problem.

    Returns
    -------
    dict
        The file's top-level tables and values, as parsed by ``tomllib`` (not checked further).

    Raises
    ------
    Exception
        An ``error`` (the class given) when the file is not UTF-8 or not valid TOML.
    """
    if not path.exists():
        return {}
    return _load(path, error)


def _load(path: Path, error: type[Exception]) -> dict:
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise error(f"no file {path}") from None
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path} is not valid TOML: {exc}") from None
    except UnicodeDecodeError as exc:
        raise error(f"{path} is not UTF-8 text: {exc}") from None

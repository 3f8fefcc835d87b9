"""Experiments and their parameters: names, the ``parameters`` cell, validation and run hashes.

An experiment is ``experiments/<name>.ipynb`` with one code cell tagged ``parameters`` that assigns
plain literals: an int, float, str or bool, or a non-empty list of one of those.  Only the names
:func:`list_experiments` shows are accepted (never a path), and every parameter value is checked
against its default's type, and against its allowed range when ``experiments/parameters.toml``
declares one, before any kernel starts.
"""

from __future__ import annotations

import ast
import difflib
import hashlib
import json
import math
from collections.abc import Mapping
from pathlib import Path

from .._optional import require
from .paths import project_root
from .registry import read_mapping

__all__ = [
    "OUTPUT_PARAMETER",
    "ParameterError",
    "experiments_dir",
    "list_experiments",
    "notebook_path",
    "experiment_parameters",
    "did_you_mean",
    "parameter_ranges",
    "ranges_path",
    "resolve_parameters",
    "run_hash",
]

#: set by the runner (the run's output folder); never a user parameter
OUTPUT_PARAMETER = "output_dir"


class ParameterError(ValueError):
    """An experiment name, parameter name or parameter value is not acceptable."""


def experiments_dir() -> Path:
    """Folder holding the experiment notebooks.

    Returns
    -------
    pathlib.Path
        ``experiments/`` of the project folder (``thesis_lib.lab.paths.project_root()``).
    """
    return project_root() / "experiments"


def list_experiments() -> list[str]:
    """Names of all experiments (notebooks in ``experiments/``).

    Returns
    -------
    list of str
        The notebooks' stems, sorted; hidden files are left out.
    """
    return sorted(p.stem for p in experiments_dir().glob("*.ipynb") if not p.name.startswith("."))


def notebook_path(name: object) -> Path:
    """The notebook of experiment ``name``; only names that :func:`list_experiments` shows are accepted.

    Parameters
    ----------
    name : object
        The experiment's name; anything else is refused.

    Returns
    -------
    pathlib.Path
        ``experiments/<name>.ipynb``, resolved.

    Raises
    ------
    ParameterError
        For anything else (a path, ``..``, an unknown name), naming the known experiments.
    """
    known = list_experiments()
    if not isinstance(name, str) or name not in known:
        shown = ", ".join(known) or "none"
        raise ParameterError(f"unknown experiment {name!r}; known experiments: {shown}{did_you_mean(name, known)}")
    folder = experiments_dir().resolve()
    path = (folder / f"{name}.ipynb").resolve()
    if path.parent != folder or not path.is_file():
        raise ParameterError(f"experiment {name!r} is not a notebook inside {folder}")
    return path


def did_you_mean(word: object, known: list[str]) -> str:
    """``"; did you mean 'x'?"`` naming the known words closest to ``word``, or ``""`` when none is close.

    Parameters
    ----------
    word : object
        What was given (anything but a string gets ``""``).
    known : list of str
        The accepted words.

    Returns
    -------
    str
        The text to end an "unknown ..." message with (``difflib.get_close_matches``, up to three).

    Examples
    --------
    >>> did_you_mean("two-circle", ["two-circles", "proteins"])
    "; did you mean 'two-circles'?"
    >>> did_you_mean("zzz", ["two-circles"])
    ''
    """
    close = difflib.get_close_matches(word, known, n=3) if isinstance(word, str) else []
    return f"; did you mean {' or '.join(map(repr, close))}?" if close else ""


def _parameters_cell(nb) -> str:
    cells = [c for c in nb.cells if c.cell_type == "code" and "parameters" in c.metadata.get("tags", [])]
    if len(cells) != 1:
        raise ParameterError(f"an experiment needs exactly one cell tagged 'parameters', found {len(cells)}")
    return cells[0].source


def _is_scalar(value: object) -> bool:
    return isinstance(value, (bool, int, float, str))


def _is_scalar_list(value: object) -> bool:
    """A non-empty list whose items share one scalar kind (ints may stand among floats)."""
    if not isinstance(value, list) or not value or not all(_is_scalar(v) for v in value):
        return False
    kinds = {type(v) for v in value}
    return len(kinds) == 1 or kinds == {int, float}


def experiment_parameters(name: str) -> dict[str, object]:
    """Default value of every parameter of experiment ``name``, read from its ``parameters`` cell.

    Parameters
    ----------
    name : str
        The experiment's name (a notebook stem that :func:`list_experiments` shows).

    Returns
    -------
    dict of str to object
        Each assigned name with its literal value (an int, float, str or bool, or a non-empty list of
        one of those), in the cell's order; ``output_dir`` included if the cell assigns it.

    Raises
    ------
    ParameterError
        If the experiment is unknown, it has not exactly one ``parameters`` cell, or that cell is not
        valid Python or does anything but assign such literals to names.
    """
    path = notebook_path(name)
    nb = require("nbformat", extra="lab", purpose="reading experiment notebooks").read(path, as_version=4)
    try:
        tree = ast.parse(_parameters_cell(nb))
    except SyntaxError as exc:
        raise ParameterError(f"{name}: the parameters cell is not valid Python ({exc.msg}, "
                             f"line {exc.lineno})") from None
    params: dict[str, object] = {}
    for node in tree.body:
        if not (isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name)):
            raise ParameterError(f"{name}: the parameters cell may only assign literals to names")
        try:
            value = ast.literal_eval(node.value)
        except ValueError:
            raise ParameterError(f"{name}: parameter {node.targets[0].id} is not a plain literal") from None
        if not _is_scalar(value) and not _is_scalar_list(value):
            raise ParameterError(f"{name}: parameter {node.targets[0].id} must be an int, float, str or bool, "
                                 "or a non-empty list of one of those")
        params[node.targets[0].id] = value
    return params


_TRUE = {"true", "yes", "1", "on"}
_FALSE = {"false", "no", "0", "off"}


def _kind(default: object) -> str:
    if isinstance(default, list):
        return f"a list of {type(default[0]).__name__}" if len({type(v) for v in default}) == 1 else "a list of float"
    return type(default).__name__


def _refuse(key: str, default: object, value: object, why: str = "") -> ParameterError:
    text = f"parameter {key!r} expects {_kind(default)} (like {default!r}), got {value!r}"
    return ParameterError(text + (f": {why}" if why else ""))


def _coerce_list(key: str, value: object, default: list) -> list:
    """A list parameter: a list, a JSON list (``[60, 100]``) or comma-separated text (``60,100``)."""
    original = value
    if isinstance(value, str):
        text = value.strip()
        if text.startswith("["):
            try:
                value = json.loads(text)
            except (json.JSONDecodeError, RecursionError):
                raise _refuse(key, default, value, "not a JSON list") from None
        else:
            value = text.split(",") if text else []
    if isinstance(value, tuple):
        value = list(value)
    if not isinstance(value, list) or not value:
        raise _refuse(key, default, value, "a non-empty list is needed")
    item_default = 0.0 if any(isinstance(v, float) for v in default) else default[0]
    items = []
    for item in value:
        try:
            items.append(_coerce(key, item, item_default))
        except ParameterError as exc:
            inner = str(exc).split(f"got {item!r}", 1)[-1].lstrip(": ")
            why = f"item {item!r} is not {_kind(item_default)}" + (f" ({inner})" if inner else "")
            raise _refuse(key, default, original, why) from None
    return items


def _coerce(key: str, value: object, default: object) -> object:
    if isinstance(default, list):
        return _coerce_list(key, value, default)
    if isinstance(value, str) and not isinstance(default, str):
        text = value.strip()
        try:
            if isinstance(default, bool):
                if text.lower() in _TRUE:
                    return True
                if text.lower() in _FALSE:
                    return False
                raise ValueError
            value = int(text) if isinstance(default, int) else float(text)
        except ValueError:
            raise _refuse(key, default, value) from None
    if isinstance(default, bool):
        ok = isinstance(value, bool)
    elif isinstance(default, int):
        ok = isinstance(value, int) and not isinstance(value, bool)
    elif isinstance(default, float):
        ok = isinstance(value, (int, float)) and not isinstance(value, bool)
        if ok:
            try:
                value = float(value)
            except OverflowError:
                raise _refuse(key, default, value, "too large for a float") from None
            if not math.isfinite(value):
                raise _refuse(key, default, value, "NaN and infinity are not parameter values")
    else:
        ok = isinstance(value, str)
    if not ok:
        raise _refuse(key, default, value)
    return value


def resolve_parameters(name: str, overrides: Mapping[str, object] | None = None) -> dict[str, object]:
    """Defaults of ``name`` updated with ``overrides`` (strings are converted to the default's type).

    Parameters
    ----------
    name : str
        The experiment's name (a notebook stem that :func:`list_experiments` shows).
    overrides : mapping of str to object, optional
        New values by parameter name.  A string is converted to the default's type (``"yes"`` /
        ``"no"`` and the like for a bool); a list parameter also takes a JSON list (``"[60, 100]"``),
        comma-separated text (``"60,100"``) or a tuple.  An int is accepted for a float.

    Returns
    -------
    dict of str to object
        Every parameter with its value, ``output_dir`` left out (the runner sets it).

    Raises
    ------
    ParameterError
        For an unknown experiment, an unknown parameter, ``output_dir``, a value of the wrong type
        (NaN and infinity included), or a value outside the range
        :func:`~thesis_lib.lab.experiments.parameter_ranges` declares.
    """
    defaults = experiment_parameters(name)
    if overrides is not None and not isinstance(overrides, Mapping):
        raise ParameterError(f"parameters must be a mapping of name to value, got {type(overrides).__name__}")
    params = dict(defaults)
    for key, value in (overrides or {}).items():
        if key == OUTPUT_PARAMETER:
            raise ParameterError(f"{OUTPUT_PARAMETER!r} is set by the runner; it is not a parameter to pass")
        if key not in defaults:
            names = [k for k in defaults if k != OUTPUT_PARAMETER]
            raise ParameterError(f"experiment {name!r} has no parameter {key!r}; its parameters are: "
                                 f"{', '.join(names)}{did_you_mean(key, names)}")
        params[key] = _coerce(key, value, defaults[key])
    params.pop(OUTPUT_PARAMETER, None)
    for key, bounds in parameter_ranges(name, defaults=defaults).items():
        _check_range(name, key, params[key], bounds)
    return params


#: the bounds a range may give: inclusive ``min`` / ``max``, strict ``above`` / ``below``
_BOUNDS = {"min": ">=", "max": "<=", "above": ">", "below": "<"}
#: the bound a list parameter may add: its least number of items
_MIN_ITEMS = "min_items"


def ranges_path() -> Path:
    """The registry of the parameters' allowed ranges.

    Returns
    -------
    pathlib.Path
        ``experiments/parameters.toml`` of the project (it need not exist: then no ranges are checked).
    """
    return experiments_dir() / "parameters.toml"


def parameter_ranges(name: str, *, defaults: Mapping[str, object] | None = None) -> dict[str, dict[str, float]]:
    """The allowed range of each numeric parameter of experiment ``name`` that declares one.

    ``experiments/parameters.toml`` has one table per experiment, and in it one inline table per
    parameter with any of ``min`` and ``max`` (inclusive) and ``above`` and ``below`` (strict), e.g.
    ``n_trials = { min = 1 }`` or ``top = { above = 0, max = 1 }``.  A list parameter's range holds
    for each of its items, and ``min_items`` bounds its length (``sizes = { min = 1, min_items = 1 }``).
    :func:`resolve_parameters` checks every value (the defaults included) against it before any
    kernel starts.

    Parameters
    ----------
    name : str
        The experiment's name (a notebook stem that :func:`list_experiments` shows).
    defaults : mapping of str to object, optional
        The experiment's defaults (:func:`experiment_parameters`), read when not given.

    Returns
    -------
    dict of str to dict
        Parameter name → its bounds (``{"min": 1}``); ``{}`` when the registry or the experiment's
        table is absent.

    Raises
    ------
    ParameterError
        If the registry is not valid TOML, or the experiment's table names a parameter that its
        ``parameters`` cell does not assign or that is not numeric, or a bound is unknown or not a
        number.
    """
    path = ranges_path()
    table = read_mapping(path, error=ParameterError).get(name, {})
    if not isinstance(table, dict):
        raise ParameterError(f"{path}: [{name}] must be a table of parameter = {{ min = ... }}")
    if table and defaults is None:
        defaults = experiment_parameters(name)
    out = {}
    for key, bounds in table.items():
        where = f"{path}: [{name}] {key}"
        if key not in defaults or key == OUTPUT_PARAMETER:
            raise ParameterError(f"{where}: the parameters cell of {name} assigns no parameter {key!r}")
        items = defaults[key] if isinstance(defaults[key], list) else [defaults[key]]
        if any(isinstance(v, (bool, str)) for v in items):
            raise ParameterError(f"{where}: a range needs a numeric parameter, its default is {defaults[key]!r}")
        allowed = [*_BOUNDS, _MIN_ITEMS] if isinstance(defaults[key], list) else list(_BOUNDS)
        if not isinstance(bounds, dict) or not bounds or set(bounds) - set(allowed):
            raise ParameterError(f"{where}: expected an inline table of {', '.join(allowed)}, got {bounds!r}")
        if any(isinstance(v, bool) or not isinstance(v, (int, float)) for v in bounds.values()):
            raise ParameterError(f"{where}: the bounds must be numbers, got {bounds!r}")
        out[key] = dict(bounds)
    return out


def _range_text(key: str, bounds: Mapping[str, float]) -> str:
    """A range as the user reads it: ``n_trials >= 1``, ``0 < top <= 1``."""
    low = [(k, v) for k, v in bounds.items() if k in ("min", "above")]
    high = [f"{_BOUNDS[k]} {v}" for k, v in bounds.items() if k in ("max", "below")]
    if len(low) == 1 and high:
        k, v = low[0]
        return f"{v} {_BOUNDS[k].replace('>', '<')} {key} " + " and ".join(high)
    return f"{key} " + " and ".join([f"{_BOUNDS[k]} {v}" for k, v in low] + high)


def _check_range(name: str, key: str, value: object, bounds: Mapping[str, float]) -> None:
    tests = {"min": lambda v, b: v >= b, "max": lambda v, b: v <= b,
             "above": lambda v, b: v > b, "below": lambda v, b: v < b}
    bounds = dict(bounds)
    least = bounds.pop(_MIN_ITEMS, None)
    if least is not None and len(value) < least:
        raise ParameterError(f"parameter {key!r} of {name} needs at least {least:g} item(s), got {value!r} "
                             f"(declared in {ranges_path()})")
    for item in value if isinstance(value, list) else [value]:
        if not all(tests[k](item, b) for k, b in bounds.items()):
            what = f"item {item!r} of {value!r}" if isinstance(value, list) else repr(value)
            raise ParameterError(f"parameter {key!r} of {name} is out of range: got {what}; allowed: "
                                 f"{_range_text(key, bounds)} (declared in {ranges_path()})")


def run_hash(params: Mapping[str, object]) -> str:
    """Short stable hash of resolved parameters: the run's folder name.

    Parameters
    ----------
    params : mapping of str to object
        Resolved parameters (:func:`resolve_parameters`); JSON-serialisable, finite.

    Returns
    -------
    str
        The first 10 hex digits of the sha256 of the parameters as JSON with sorted keys: the same
        parameters give the same hash in any order.
    """
    text = json.dumps(dict(params), sort_keys=True, allow_nan=False)
    return hashlib.sha256(text.encode()).hexdigest()[:10]

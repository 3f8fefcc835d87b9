"""Results of experiments: flat ``name -> number`` tables and figures written beside the run.

Every experiment and book chapter records what it measures through :class:`Recorder`; the book and
the reproduction report read the stored numbers back with :func:`load`.  Nothing is typed by hand.
"""

from __future__ import annotations

import json
import math
import numbers
import os
from pathlib import Path
from typing import TYPE_CHECKING

from . import atomic
from .paths import project_root

if TYPE_CHECKING:  # matplotlib and IPython are imported only where a figure is saved or shown
    from IPython.display import Image
    from matplotlib.figure import Figure

__all__ = [
    "Recorder",
    "ResultsError",
    "check_name",
    "format_result",
    "load",
    "read_json",
    "check_table",
    "figure",
    "results_dir",
    "round_sig",
    "RESULTS_FILE",
    "TIMINGS_FILE",
    "RESULT_DIGITS",
]

RESULTS_FILE = "results.json"
#: wall-clock times vary from run to run, so they are kept apart from the results and not committed
TIMINGS_FILE = "timings.json"
#: when set, a Recorder's stored default run is written under this folder instead (the test suite
#: sets it, so that re-executing the notebooks never rewrites committed results that others read)
DEFAULT_RUN_ENV = "THESIS_LAB_DEFAULT_RUN_DIR"


#: significant digits kept for every real number written to results.json, enough for any claim and
#: few enough that a re-run on another CPU, BLAS or thread count writes the same bytes
RESULT_DIGITS = 10


def round_sig(x: float, digits: int) -> float:
    """``x`` rounded to ``digits`` significant digits (0, NaN and ±inf unchanged).

    The book's rule (CONVENTIONS.md): counts exact; errors, tolerances and residuals to 2
    significant digits; other measured reals to the digits they are good for.

    Parameters
    ----------
    x : float
        The number (anything ``float`` accepts).
    digits : int
        Significant digits to keep.

    Returns
    -------
    float
        ``x`` rounded by Python's ``round`` at its ``digits``-th significant digit.
    """
    x = float(x)
    if x == 0 or not math.isfinite(x):
        return x
    return round(x, digits - 1 - math.floor(math.log10(abs(x))))


def format_result(value: float, *, digits: int = 2) -> str:
    """A stored result as the book writes it: a count exactly, with thousands separators; a real
    to ``digits`` significant digits (the book's rule, :func:`round_sig`).

    Parameters
    ----------
    value : int or float
        The result (a bool counts as a count).
    digits : int, default 2
        Significant digits of a real.

    Returns
    -------
    str
        The text.

    Examples
    --------
    >>> format_result(1333500), format_result(0.50041283), format_result(0.1167109, digits=3)
    ('1,333,500', '0.5', '0.117')
    """
    if isinstance(value, numbers.Integral):
        return f"{value:,}"
    return f"{round_sig(value, digits):.{digits}}"


class ResultsError(ValueError):
    """Stored results are unreadable (not JSON, not a flat table of numbers) or a name is not a name."""


def check_name(name: object) -> str:
    """``name`` if it can name a results folder: a non-empty name with no path separator, never ``..``.

    Parameters
    ----------
    name : object
        The name to check.

    Returns
    -------
    str
        ``name``, unchanged.

    Raises
    ------
    ResultsError
        If ``name`` is not a non-empty string, is ``.`` or ``..``, or holds ``/``, ``\\`` or NUL.
    """
    if not isinstance(name, str) or not name or name in (".", "..") or any(c in name for c in "/\\\x00"):
        raise ResultsError(f"invalid experiment name {name!r}: a results name has no path separator and is not '..'")
    return name


def results_dir(name: str) -> Path:
    """Folder of the stored default run of experiment ``name`` (committed with the repository).

    Parameters
    ----------
    name : str
        The experiment's name (checked by :func:`check_name`).

    Returns
    -------
    pathlib.Path
        ``experiments/results/<name>/`` of the project folder; its existence is not checked.
    """
    return project_root() / "experiments" / "results" / check_name(name)


def _as_number(key: str, value) -> float | int:
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        return round_sig(float(value), RESULT_DIGITS)
    raise ValueError(f"result {key!r} must be a number, got {type(value).__name__}: {value!r}")


class Recorder:
    """Write an experiment's numbers (``results.json``) and figures into its output folder.

    Parameters
    ----------
    name : str
        The experiment's name (``two-circles-landmarks``, ...; checked by :func:`check_name`).
    output_dir : str or pathlib.Path, optional
        Folder to write into (created); ``""`` or ``None`` means the stored default run
        ``experiments/results/<name>/`` (``$THESIS_LAB_DEFAULT_RUN_DIR/<name>/`` when that is set).
        Starting a recorder clears the previous ``results.json``.
    """

    def __init__(self, name: str, *, output_dir: str | Path | None = ""):
        self.name = check_name(name)
        redirect = os.environ.get(DEFAULT_RUN_ENV)
        default = Path(redirect) / name if redirect else results_dir(name)
        self.path = Path(output_dir) if output_dir else default
        self.path.mkdir(parents=True, exist_ok=True)
        self.results: dict[str, float | int] = {}
        self._write()

    def record(self, **values: float) -> None:
        """Add flat ``name=number`` results and rewrite ``results.json`` (atomically).

        Reals are rounded to ``RESULT_DIGITS`` significant digits.  Returns None, so that a notebook
        cell ending with a ``record`` call shows nothing; read values back from ``rec.results``.

        Parameters
        ----------
        **values : float
            Results by name (identifiers): integers (bools as 0 / 1) are kept exact, other reals
            rounded; a name recorded before is overwritten.

        Raises
        ------
        ValueError
            If a name is not an identifier or a value is not a real number (nothing is recorded).
        """
        checked = {}
        for key, value in values.items():
            if not key.replace("_", "").isalnum():
                raise ValueError(f"result names are identifiers, got {key!r}")
            checked[key] = _as_number(key, value)
        self.results.update(checked)
        self._write()

    def timing(self, **seconds: float) -> None:
        """Record wall-clock times (``timings.json``): shown to the reader, never compared.

        Parameters
        ----------
        **seconds : float
            Times in seconds by name, rounded to 4 decimals and merged into the file (atomically).
        """
        file = self.path / TIMINGS_FILE
        times = json.loads(file.read_text()) if file.exists() else {}
        times.update({k: round(float(v), 4) for k, v in seconds.items()})
        atomic.write_text(file, json.dumps(times, indent=1, sort_keys=True) + "\n")

    def savefig(self, fig: Figure, stem: str, *, dpi: int = 110) -> Path:
        """Save a matplotlib figure as ``<stem>.png`` with no time stamp (byte-identical on re-runs).

        Parameters
        ----------
        fig : matplotlib.figure.Figure
            The figure, saved with a tight bounding box.
        stem : str
            The file name without ``.png`` (checked by :func:`check_name`).
        dpi : int, default 110
            Resolution of the image.

        Returns
        -------
        pathlib.Path
            The written file, ``<output folder>/<stem>.png`` (replaced atomically); it carries the
            height of the figure's smallest text in a ``tEXt`` chunk (``graphics.style.figure_png``).
        """
        from ..graphics.style import figure_png

        out = self.path / f"{check_name(stem)}.png"
        atomic.write_bytes(out, figure_png(fig, dpi=dpi))
        return out

    def _write(self) -> None:
        text = json.dumps(self.results, indent=1, sort_keys=True, allow_nan=True)
        atomic.write_text(self.path / RESULTS_FILE, text + "\n")


#: the largest float; a stored integer beyond it cannot be compared with anything (report, tables)
_FLOAT_MAX = 1.7976931348623157e308


def read_json(path: str | Path) -> object:
    """The JSON value stored in ``path``, or a :class:`ResultsError` naming the file and what is wrong.

    Every stored file of the laboratory (``results.json``, a run's ``complete.json``) is read here,
    so that a corrupt one is reported by name, never as a traceback from inside the parser.

    Parameters
    ----------
    path : str or pathlib.Path
        The file (it must exist).

    Returns
    -------
    object
        The parsed value (``NaN`` and ``Infinity`` accepted, as :class:`Recorder` writes them).

    Raises
    ------
    ResultsError
        If ``path`` is a folder or unreadable, not UTF-8, not valid JSON, nested too deep for the
        parser, or holds an integer of more digits than Python converts (4300).
    """
    path = Path(path)
    if path.is_dir():
        raise ResultsError(f"{path} is a folder, not a file")
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise ResultsError(f"{path} is not valid JSON (not UTF-8 text: {exc}): it is corrupt") from None
    except OSError as exc:
        raise ResultsError(f"{path} cannot be read ({exc.strerror or exc})") from None
    return parse_json(text, path)


def parse_json(text: str, where: str | Path) -> object:
    """``json.loads(text)``, or a :class:`ResultsError` naming ``where`` (see :func:`read_json`).

    Parameters
    ----------
    text : str
        The file's text.
    where : str or pathlib.Path
        The file it came from (named in the message).

    Returns
    -------
    object
        The parsed value.

    Raises
    ------
    ResultsError
        Invalid JSON, nested too deeply, or an integer of more than 4300 digits.
    """
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise ResultsError(f"{where} is not valid JSON ({exc}): it is truncated or corrupt") from None
    except RecursionError:
        raise ResultsError(f"{where} is nested too deeply to be a table of results: it is corrupt") from None
    except ValueError as exc:  # an integer beyond int_max_str_digits
        raise ResultsError(f"{where} holds a number that cannot be read ({exc}): it is corrupt") from None


def check_table(data: object, path: str | Path) -> dict[str, float | int]:
    """``data`` if it is a flat table ``name -> number`` (finite ints within the float range, reals).

    Parameters
    ----------
    data : object
        What :func:`read_json` returned for ``path``.
    path : str or pathlib.Path
        The file it came from (named in the message).

    Returns
    -------
    dict of str to float or int
        ``data``, unchanged.

    Raises
    ------
    ResultsError
        If ``data`` is not a JSON object, or a value is not a number (a bool, a string, a list, an
        integer beyond the float range).
    """
    if not isinstance(data, dict):
        raise ResultsError(f"{path} must hold a flat JSON object of numbers, got a {type(data).__name__}")
    for key, value in data.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ResultsError(f"{path} must hold a flat JSON object of numbers; {key!r} is a "
                               f"{type(value).__name__}")
        if isinstance(value, int) and abs(value) > _FLOAT_MAX:
            raise ResultsError(f"{path}: {key!r} is an integer of {len(str(abs(value)))} digits, beyond the "
                               "float range; it is corrupt")
    return data


def load(name: str, *, output_dir: str | Path | None = None) -> dict[str, float | int]:
    """Read the results of experiment ``name`` (default: its stored default run).

    Parameters
    ----------
    name : str
        The experiment's name.
    output_dir : str or pathlib.Path, optional
        The run folder holding ``results.json``; by default the stored default run
        (:func:`results_dir`).

    Returns
    -------
    dict of str to float or int
        The stored results by name.

    Raises
    ------
    FileNotFoundError
        If there are no stored results (saying how to make them).
    ResultsError
        If ``results.json`` is a folder, not valid JSON (truncated, nested too deep, an integer of
        thousands of digits) or not a flat table of numbers, naming the file and how to restore it.
    """
    path = (Path(output_dir) if output_dir else results_dir(name)) / RESULTS_FILE
    if not path.exists():
        raise FileNotFoundError(
            f"no stored results for {name!r} at {path}; run `thesis-lab run {name}` or `make experiments`"
        )
    restore = f"re-run `thesis-lab store {name}` or restore it with `git checkout -- {path.name}` in its folder"
    try:
        return check_table(read_json(path), path)
    except ResultsError as exc:
        raise ResultsError(f"{exc}; {restore}") from None


def figure(name: str, stem: str, *, width: int = 640) -> Image:
    """A stored figure of experiment ``name``'s default run, for display in a notebook.

    Parameters
    ----------
    name : str
        The experiment's name.
    stem : str
        The figure's file name without ``.png``.
    width : int, default 640
        Display width in pixels.

    Returns
    -------
    IPython.display.Image
        The image of ``experiments/results/<name>/<stem>.png``.

    Raises
    ------
    FileNotFoundError
        If the figure is not stored.
    ResultsError
        If ``name`` or ``stem`` is not a valid name.
    """
    from IPython.display import Image

    path = results_dir(name) / f"{check_name(stem)}.png"
    if not path.exists():
        raise FileNotFoundError(f"no stored figure {stem!r} for {name!r} at {path}; run `make experiments`")
    return Image(filename=str(path), width=width)

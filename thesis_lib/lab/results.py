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

from .paths import repo_root

__all__ = ["Recorder", "load", "figure", "results_dir", "round_sig", "RESULTS_FILE", "TIMINGS_FILE", "RESULT_DIGITS"]

RESULTS_FILE = "results.json"
#: wall-clock times vary from run to run: kept apart from the results, and not committed
TIMINGS_FILE = "timings.json"
#: when set, a Recorder's stored default run is written under this folder instead (the test suite
#: sets it, so that re-executing the notebooks never rewrites committed results that others read)
DEFAULT_RUN_ENV = "THESIS_LAB_DEFAULT_RUN_DIR"


#: significant digits kept for every real number written to results.json: enough for any claim,
#: few enough that a re-run on another CPU, BLAS or thread count writes the same bytes
RESULT_DIGITS = 10


def round_sig(x: float, digits: int) -> float:
    """``x`` rounded to ``digits`` significant digits (0, NaN and ±inf unchanged).

    The book's rule (CONVENTIONS.md): counts exact; errors, tolerances and residuals to 2
    significant digits; other measured reals to the digits they are good for.
    """
    x = float(x)
    if x == 0 or not math.isfinite(x):
        return x
    return round(x, digits - 1 - math.floor(math.log10(abs(x))))


def results_dir(name: str) -> Path:
    """Folder of the stored default run of experiment ``name`` (committed with the repository)."""
    return repo_root() / "experiments" / "results" / name


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
    name : experiment name (``two-circles-landmarks``, ...).
    output_dir : folder to write into; ``""`` or ``None`` means the stored default run
        ``experiments/results/<name>/`` (``$THESIS_LAB_DEFAULT_RUN_DIR/<name>/`` when that is set).
        Starting a recorder clears the previous ``results.json``.
    """

    def __init__(self, name: str, output_dir: str | Path | None = ""):
        if not name or "/" in name:
            raise ValueError(f"invalid experiment name {name!r}")
        self.name = name
        redirect = os.environ.get(DEFAULT_RUN_ENV)
        default = Path(redirect) / name if redirect else results_dir(name)
        self.path = Path(output_dir) if output_dir else default
        self.path.mkdir(parents=True, exist_ok=True)
        self.results: dict[str, float | int] = {}
        self._write()

    def record(self, **values) -> dict[str, float | int]:
        """Add flat ``name=number`` results and rewrite ``results.json``; returns what was recorded."""
        for key, value in values.items():
            if not key.replace("_", "").isalnum():
                raise ValueError(f"result names are identifiers, got {key!r}")
            self.results[key] = _as_number(key, value)
        self._write()
        return {k: self.results[k] for k in values}

    def timing(self, **seconds) -> None:
        """Record wall-clock times (``timings.json``): shown to the reader, never compared."""
        file = self.path / TIMINGS_FILE
        times = json.loads(file.read_text()) if file.exists() else {}
        times.update({k: round(float(v), 4) for k, v in seconds.items()})
        file.write_text(json.dumps(times, indent=1, sort_keys=True) + "\n")

    def savefig(self, fig, stem: str, dpi: int = 110) -> Path:
        """Save a matplotlib figure as ``<stem>.png`` with no time stamp (byte-identical on re-runs)."""
        out = self.path / f"{stem}.png"
        fig.savefig(out, dpi=dpi, bbox_inches="tight", metadata={"Software": None})
        return out

    def _write(self) -> None:
        text = json.dumps(self.results, indent=1, sort_keys=True, allow_nan=True)
        (self.path / RESULTS_FILE).write_text(text + "\n")


def load(name: str, output_dir: str | Path | None = None) -> dict[str, float | int]:
    """Read the results of experiment ``name`` (default: its stored default run)."""
    path = (Path(output_dir) if output_dir else results_dir(name)) / RESULTS_FILE
    if not path.exists():
        raise FileNotFoundError(
            f"no stored results for {name!r} at {path}; run `thesis-lab run {name}` or `make experiments`"
        )
    data = json.loads(path.read_text())
    return {k: (v if not isinstance(v, float) or not math.isnan(v) else math.nan) for k, v in data.items()}


def figure(name: str, stem: str, width: int = 640):
    """A stored figure of experiment ``name``'s default run, for display in a notebook."""
    from IPython.display import Image

    path = results_dir(name) / f"{stem}.png"
    if not path.exists():
        raise FileNotFoundError(f"no stored figure {stem!r} for {name!r} at {path}; run `make experiments`")
    return Image(filename=str(path), width=width)

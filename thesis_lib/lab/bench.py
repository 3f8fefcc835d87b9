"""Stored benchmark results (``benchmarks/results/<topic>.json``) as tables and figures for the book.

The files are written by the harness (``benchmarks/harness.py``): ``{"meta": ..., "rows": [...]}``
with the commit, date, load average and cores of the run; every time ratio is a row key starting
with ``ratio_`` (the median over interleaved rounds of ours / peer, below 1 = we are faster) and the
number of rounds is ``rounds``.  A file that is a bare list of rows has no provenance.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from .._optional import require
from .paths import project_root
from .tables import markdown_table

if TYPE_CHECKING:  # matplotlib is imported only when a figure is drawn
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["topics", "load", "meta", "markdown", "header", "ratios", "fit_exponent", "ratio_figure",
           "scaling_figure", "provenance", "targets", "show", "references"]

#: the peers' display names (row keys ratio_<key>, <key>_s, <key>_mb)
PEERS = {"ripser": "ripser.py", "gph": "giotto-ph", "gudhi": "GUDHI", "explicit": "explicit engine", "ref": "reference",
         "libigl": "libigl", "pari": "PARI", "sympy": "sympy", "ball_pivoting": "ball pivoting",
         "ripser12_whole": "Ripser 1.2, whole process", "ripser12_warm": "Ripser 1.2 (our warm call)",
         "ripserpy_whole": "ripser.py, whole process", "ripserpy_warm": "ripser.py, warm",
         "giotto_1t_whole": "giotto-ph 1 thread, whole process", "giotto_1t_warm": "giotto-ph 1 thread, warm",
         "giotto_2t_whole": "giotto-ph 2 threads, whole process", "giotto_2t_warm": "giotto-ph 2 threads, warm"}


#: other row-key stems as headers say them (``<stem>_s``, ``<stem>_mb``, ``ratio_<stem>``)
NAMES = {"ours": "ours", "ours_z": "ours over Z", "ours_core": "ours, core", "pari_core": "PARI, core",
         "engine": "explicit engine", "delaunay": "Delaunay", "multipers": "multipers"}

#: counts and parameters as headers say them
COLUMN_HEADERS = {"n_points": "points", "n_per_circle": "per circle", "n_simplices": "simplices",
                  "n_vertices": "vertices", "n_faces": "faces", "n_cells": "cells", "n_critical": "critical",
                  "n_samples": "samples", "max_dim": "max dim", "max_radius": "ε max", "wall_s": "wall (s)",
                  "per_run_s": "per run (s)", "overhead_per_run_s": "Dask overhead per run (s)",
                  "cluster_start_s": "cluster start (s)", "max_abs_diff": "max difference"}


def header(column: str) -> str:
    """The header of a stored column, with its unit: ``ours_s`` → ``ours (s)``, ``ratio_ripser`` →
    ``ours ÷ Ripser``, ``gph_mb`` → ``giotto-ph peak (MB)``.

    Thesis: none (the performance page's tables).

    Parameters
    ----------
    column : str
        A row key of the stored results.

    Returns
    -------
    str
        Times ``<tool>_s`` as ``<tool> (s)``, ratios ``ratio_<peer>`` as ``ours ÷ <peer>`` (``ratio``:
        ``ours ÷ reference``), peak memory ``<tool>_mb`` as ``<tool> peak (MB)`` and
        ``<tool>_baseline_mb`` as ``<tool> baseline (MB)``, counts without their ``n_``; other keys
        with spaces for underscores.
    """
    def name(stem: str) -> str:
        return PEERS.get(stem) or NAMES.get(stem) or stem.replace("_", " ")

    if column in COLUMN_HEADERS:
        return COLUMN_HEADERS[column]
    if column == "ratio":
        return "ours ÷ reference"
    if column.startswith("ratio_"):
        return f"{NAMES['ours_z']} ÷ reference" if column == "ratio_z" else f"ours ÷ {name(column[6:])}"
    if column.endswith("_baseline_mb"):
        return f"{name(column[:-12])} baseline (MB)"
    if column.endswith("_mb"):
        return f"{name(column[:-3])} peak (MB)"
    if column.endswith("_s"):
        return f"{name(column[:-2])} (s)"
    return column.replace("_", " ")


def _dir() -> Path:
    return project_root() / "benchmarks" / "results"


def topics() -> list[str]:
    """Benchmarks with stored full results (``--quick`` smoke runs and partial runs are left out).

    Returns
    -------
    list of str
        The topics (file stems of ``benchmarks/results/*.json``), sorted.
    """
    return sorted(p.stem for p in _dir().glob("*.json")
                  if not p.stem.replace("-", "_").endswith(("_quick", "_partial")))


def _read(topic: str):
    path = _dir() / f"{topic}.json"
    if not path.exists():
        raise FileNotFoundError(f"no stored benchmark {topic!r} at {path}; run `make bench`")
    return path, json.loads(path.read_text())


def load(topic: str) -> list[dict]:
    """Rows of one benchmark (a list of flat dicts), as ``make bench`` stored them.

    Parameters
    ----------
    topic : str
        The benchmark's name (``benchmarks/results/<topic>.json``).

    Returns
    -------
    list of dict
        The stored rows, in stored order.

    Raises
    ------
    FileNotFoundError
        If no results of ``topic`` are stored.
    ValueError
        If the file does not hold a list of dicts.
    """
    path, data = _read(topic)
    rows = data["rows"] if isinstance(data, dict) else data
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise ValueError(f"{path} must hold a list of rows (dicts)")
    return rows


def meta(topic: str) -> dict:
    """Where and when the stored run was made (commit, date, load average, cores).

    Parameters
    ----------
    topic : str
        Whose stored run to describe.

    Returns
    -------
    dict
        The file's ``meta`` table; ``{}`` for a file that is a bare list of rows.

    Raises
    ------
    FileNotFoundError
        If no results of ``topic`` are stored.
    """
    _, data = _read(topic)
    return data.get("meta", {}) if isinstance(data, dict) else {}


def provenance(topic: str) -> str:
    """One sentence saying where the stored figures of ``topic`` come from.

    Parameters
    ----------
    topic : str
        The stored benchmark to describe in one sentence.

    Returns
    -------
    str
        Commit, date, cores and the load average at the start and end of the run, in Markdown (and
        the same for each row re-run later, which carries its own run); for a file without
        provenance, a sentence saying so.
    """
    m = meta(topic)
    if not m:
        return f"`{topic}`: stored without provenance: re-run `make bench`."
    load_avg = m.get("load_average", [None])[0]
    end = m.get("load_average_end", [None])[0]
    text = (f"`{topic}`: commit `{str(m.get('commit'))[:10]}`, {m.get('date')}, {m.get('cores')} cores, "
            f"load average {load_avg} at the start and {end} at the end of the run.")
    for row in load(topic):
        run = row.get("run")
        if isinstance(run, dict):  # a row re-run later (harness --update) carries its own run
            text += (f" Row `{row.get('case')}`: commit `{str(run.get('commit'))[:10]}`, {run.get('date')}, "
                     f"load average {(run.get('load_average') or [None])[0]} at the start and "
                     f"{(run.get('load_average_end') or [None])[0]} at the end.")
    return text


def markdown(topic: str, *, columns: list[str] | None = None, cases: list[str] | None = None,
             where: Callable[[dict], bool] | Mapping[str, object] | None = None,
             headers: bool | Mapping[str, str] = False, digits: int = 3, skip_empty: bool = False) -> str:
    """One benchmark as a Markdown table.

    Parameters
    ----------
    topic : str
        The stored benchmark to show (as in ``load``).
    columns : list of str, optional
        The columns, in order; by default every scalar (not list or dict) column, in first-seen order.
    cases : list of str, optional
        Only the rows whose ``case`` is one of these (those stored); by default every row.
    where : callable or mapping, optional
        A predicate on a row (a dict): only the rows it accepts; or a mapping of columns to values:
        only the rows that hold these values.
    headers : bool or mapping, default False
        False: the row keys are the headers; True: :func:`header` of each key; a mapping: its
        headers for the keys it names and :func:`header` for the others.
    digits : int, default 3
        Significant digits of float cells.
    skip_empty : bool, default False
        Leave out the rows that hold none of the columns after the first (the case).

    Returns
    -------
    str
        The Markdown table (floats to ``digits`` significant digits, missing cells empty), ending
        with a newline; an italic line saying so when no row is left.

    Raises
    ------
    ValueError
        If a named column is in none of the rows.
    FileNotFoundError
        If no results of ``topic`` are stored.
    """
    def kept(row: dict) -> bool:
        if isinstance(where, Mapping):
            return all(row.get(k) == v for k, v in where.items())
        return where is None or where(row)

    rows = [r for r in load(topic) if (cases is None or r.get("case") in cases) and kept(r)]
    if skip_empty and columns is not None:
        rows = [r for r in rows if any(r.get(c) is not None for c in columns[1:])]
    if not rows:
        return f"*No stored rows of `{topic}` for the cases {', '.join(cases or [])}: run `make bench`.*\n"
    if columns is None:
        columns = []
        for row in rows:
            columns += [k for k in row if k not in columns and not isinstance(row[k], (list, dict))]
    else:
        missing = [c for c in columns if all(c not in r for r in rows)]
        if missing:
            raise ValueError(f"benchmark {topic!r} has no columns {missing}")
    names = columns
    if headers is not False:
        given = headers if isinstance(headers, Mapping) else {}
        names = [given.get(c) or header(c) for c in columns]
    return markdown_table(names, ([r.get(c) for c in columns] for r in rows), digits=digits)


def show(topic: str, *tables: list[str], headers: bool | Mapping[str, str] | None = None) -> None:
    """Display one benchmark in a notebook: its ratio bars, then one table per list of columns, each
    with only the rows that hold one of its values.

    Thesis: none (the performance page).

    Parameters
    ----------
    topic : str
        The stored benchmark.
    *tables : list of str
        The columns of each table (the case first).
    headers : bool or mapping, optional
        As :func:`markdown`; default True (readable headers with units).

    Examples
    --------
    >>> show("no-such-benchmark", ["case"])  # in a notebook: the rendered tables
    <IPython.core.display.Markdown object>
    """
    from IPython.display import Markdown, display

    if topic not in topics():
        return display(Markdown(f"*No stored results for `{topic}` yet: run `make bench`.*"))
    if meta(topic) and ratios(topic):  # figures only from runs of the current harness
        plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the benchmark's ratios")
        fig = ratio_figure(topic)
        display(fig)
        plt.close(fig)
    for columns in tables:
        display(Markdown(markdown(topic, columns=columns, headers=True if headers is None else headers,
                                  skip_empty=True)))
    return None


def references(topic: str, *, key: str | None = None) -> str:
    """What the cases of a benchmark were compared with, as Markdown: one line per value of ``key``.

    Thesis: none (the performance page).

    Parameters
    ----------
    topic : str
        The stored benchmark.
    key : str, optional
        A row key naming the kind of case (e.g. ``"kind"``); without it, one sentence.

    Returns
    -------
    str
        ``- <kind>: <reference>`` lines, or ``Reference: <reference>.``, each reference once.

    Examples
    --------
    >>> references("complexes", key="kind").startswith("- ")
    True
    """
    pairs = dict.fromkeys((r.get(key) if key else None, r.get("reference")) for r in load(topic))
    return "\n".join(f"- {k}: {ref}" if k else f"Reference: {ref}." for k, ref in pairs)


def targets(specs: Sequence[Mapping[str, Any]]) -> str:
    """The performance targets beside the stored figures, as a Markdown table.

    Parameters
    ----------
    specs : sequence of mapping
        One per target: ``label`` (str), ``topic`` (str), ``cases`` (list of case names; a missing
        one is reported as not measured), ``value`` (a row key, or a callable of the row giving the
        number, or a list of row keys whose values are added), ``bound`` (float) and optionally
        ``unit`` (str, shown after the numbers).  A
        target is met when the largest value over its cases is at most ``bound``.

    Returns
    -------
    str
        Columns: target, cases, worst value, bound, met (``yes``/``no``/``not measured``), and the
        round counts of the worst case; every value read from ``benchmarks/results``.

    Raises
    ------
    ValueError
        On a spec without one of the required keys.
    """
    lines = []
    for spec in specs:
        missing = [k for k in ("label", "topic", "cases", "value", "bound") if k not in spec]
        if missing:
            raise ValueError(f"target spec {spec!r} lacks {missing}")
        rows = {r.get("case"): r for r in load(spec["topic"])}
        keys = spec["value"] if isinstance(spec["value"], (list, tuple)) else [spec["value"]]
        value = spec["value"] if callable(spec["value"]) else (lambda row, keys=keys: sum(row[k] for k in keys))
        unit = spec.get("unit", "")
        found = [(float(value(rows[c])), c) for c in spec["cases"] if c in rows]
        if len(found) < len(spec["cases"]):
            absent = [c for c in spec["cases"] if c not in rows]
            lines.append([spec["label"], ", ".join(spec["cases"]), "", f"{spec['bound']:g}{unit}",
                          f"not measured ({', '.join(absent)})", ""])
            continue
        worst, case = max(found)
        met = "yes" if worst <= spec["bound"] else "no"
        lines.append([spec["label"], ", ".join(spec["cases"]), f"{worst:.3g}{unit} ({case})",
                      f"{spec['bound']:g}{unit}", met, rows[case].get("rounds", "")])
    return markdown_table(["target", "cases", "worst", "bound", "met", "rounds"], lines, digits=3)


def ratios(topic: str, *, cases: list[str] | None = None) -> list[tuple[str, str, float, int]]:
    """``(case, peer, ratio, rounds)`` for every ``ratio_<peer>`` of the stored rows (or of ``cases``).

    Parameters
    ----------
    topic : str
        The stored benchmark whose ratios are read.
    cases : list of str, optional
        Only the rows whose ``case`` is one of these; by default every row.

    Returns
    -------
    list of tuple (str, str, float, int)
        One entry per numeric ``ratio_<peer>`` key, in row order: the case, the peer key, the ratio
        (ours / peer) and the row's ``rounds`` (0 when not stored).
    """
    out = []
    for row in load(topic):
        if cases is not None and row.get("case") not in cases:
            continue
        for key, value in row.items():
            if key.startswith("ratio_") and isinstance(value, (int, float)) and not isinstance(value, bool):
                out.append((str(row.get("case")), key[len("ratio_"):], float(value), int(row.get("rounds", 0))))
    return out


def fit_exponent(x: npt.ArrayLike, y: npt.ArrayLike) -> float:
    """The exponent a of y ≈ c · x^a, by least squares on log y against log x.

    Parameters
    ----------
    x, y : array_like, shape (n,)
        The sizes and the measurements; positive, ``n >= 2``, the same shape.

    Returns
    -------
    float
        The slope of the least-squares line through ``(log x, log y)``.

    Raises
    ------
    ValueError
        If the shapes differ, there are fewer than two points, or a value is not positive.
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if x.shape != y.shape or x.size < 2 or (x <= 0).any() or (y <= 0).any():
        raise ValueError("need at least two positive (x, y) points of the same length")
    return float(np.polyfit(np.log(x), np.log(y), 1)[0])


def ratio_figure(topic: str, *, cases: list[str] | None = None, peers: list[str] | None = None,
                 ax: Axes | None = None) -> Figure:
    """Horizontal bars of ours / peer per workload (log scale, 1 marked): one group per case.

    The ratios are the stored medians of paired ratios; each label names the peer and the rounds.

    Parameters
    ----------
    topic : str
        The stored benchmark to draw.
    cases : list of str, optional
        Only these cases; by default every stored case.
    peers : list of str, optional
        Only the ratios against these peer keys (``"ripser"``, ``"gudhi"``, ...); by default all.
    ax : matplotlib.axes.Axes, optional
        The axes to draw on; by default a new figure sized to the number of bars.

    Returns
    -------
    matplotlib.figure.Figure
        The figure of ``ax``.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        If no ratio is left to draw.
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="benchmark figures")

    from ..graphics.style import COLORS

    data = [r for r in ratios(topic, cases=cases) if peers is None or r[1] in peers]
    if not data:
        raise ValueError(f"benchmark {topic!r} has no ratio_* figures to draw")
    names = list(dict.fromkeys(r[0] for r in data))
    kinds = list(dict.fromkeys(r[1] for r in data))
    palette = COLORS.get("dims", ["C0", "C1", "C2", "C3", "C4"])
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 0.5 + 0.28 * len(data) + 0.15 * len(names)))
    y, ticks, labels = 0.0, [], []
    for name in names:
        for case, peer, value, rounds in data:
            if case != name:
                continue
            ax.barh(y, value, color=palette[kinds.index(peer) % len(palette)], height=0.8)
            ax.text(value * 1.05, y, f"{value:.2g}", va="center", fontsize=9)
            ticks.append(y)
            labels.append(f"{case} / {PEERS.get(peer, peer)} ({rounds} rounds)")
            y += 1
        y += 0.6
    ax.axvline(1.0, color="0.3", lw=1)
    ax.set_xscale("log")
    # plain numbers (0.1, 1, 10), not 10⁻¹ in mathtext, whose exponents are drawn at 0.7 of the size
    from matplotlib.ticker import FuncFormatter, NullFormatter

    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_yticks(ticks)
    ax.set_yticklabels(labels, fontsize=9)
    ax.invert_yaxis()
    ax.set_xlabel("time ours ÷ peer (median of paired ratios; below 1 we are faster)")
    return ax.figure


def scaling_figure(topic: str, *, prefix: str, tools: dict[str, str],
                   x_key: str = "n_per_circle") -> tuple[Figure, dict[str, tuple[float, float]]]:
    """Time and memory against ``x_key`` for the rows whose case starts with ``prefix``, log–log,
    one line per tool (one legend below the panels; the fitted exponents are returned).

    Parameters
    ----------
    topic : str
        The stored benchmark to draw (its rows with sizes, times and memory).
    prefix : str
        Only the rows whose ``case`` starts with this.
    tools : dict of str to str
        ``{row key: label}``: the tool's columns are ``<key>_s`` (time) and ``<key>_mb`` (memory; a
        missing or smaller value is drawn as 0.1 MB so the log scale holds it).
    x_key : str, default "n_per_circle"
        The row key of the size on the horizontal axis.

    Returns
    -------
    figure : matplotlib.figure.Figure
        Two log–log panels, time and peak memory.
    exponents : dict of str to tuple (float, float)
        ``{tool: (time exponent, memory exponent)}`` for the tools with at least two timed rows.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        If no case starts with ``prefix``.
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="benchmark figures")

    rows = [r for r in load(topic) if str(r.get("case", "")).startswith(prefix)]
    if not rows:
        raise ValueError(f"benchmark {topic!r} has no cases starting with {prefix!r}")
    fig, (ax_t, ax_m) = plt.subplots(1, 2, figsize=(7.0, 3.6))
    exponents = {}
    for key, label in tools.items():
        pts = [(r[x_key], r.get(f"{key}_s"), r.get(f"{key}_mb")) for r in rows if r.get(f"{key}_s") is not None]
        if len(pts) < 2:
            continue
        x = np.array([p[0] for p in pts], float)
        t = np.array([p[1] for p in pts], float)
        m = np.array([max(p[2] or 0.0, 0.1) for p in pts], float)
        et, em = fit_exponent(x, t), fit_exponent(x, m)
        exponents[key] = (et, em)
        ax_t.loglog(x, t, "o-", label=label)
        ax_m.loglog(x, m, "o-", label=label)
    from matplotlib.ticker import FuncFormatter, NullFormatter

    for ax, what in ((ax_t, "time (s, median)"), (ax_m, "peak memory above baseline (MB)")):
        for axis in (ax.xaxis, ax.yaxis):  # plain numbers, not mathtext powers of ten (small exponents)
            axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
            axis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("points per circle")
        ax.set_ylabel(what)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    # one legend for both panels, below them (inside a panel it hid points)
    fig.legend(*ax_t.get_legend_handles_labels(), loc="lower center", ncol=5, fontsize=9, frameon=False,
               handlelength=1.5, columnspacing=1.0)
    return fig, exponents

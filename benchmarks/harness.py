"""Scaffolding shared by the ``benchmarks/bench_<topic>.py`` scripts.

Imported as ``import harness`` (running ``python benchmarks/bench_x.py`` puts this folder on
``sys.path``).  What lives here: the command line (``--quick``, ``--repeat``, the hidden
``--worker``), best-of-N timing, peak memory (RSS high-water mark of a fresh subprocess, or
``tracemalloc``), running a worker subprocess, the Markdown table, and writing
``benchmarks/results/<topic>.json`` (``<topic>_quick.json`` with ``--quick``: a smoke run never
overwrites the stored full results the book shows).
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
import tracemalloc
from pathlib import Path
from typing import Callable, Sequence

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"

# A table column is a row key (the title; floats shown with 3 significant digits) or a pair
# (title, spec): spec a format string over the row's keys ("{ours_s:.4f}") or a function of the row.


# ---------------------------------------------------------------------------- command line
def main_per_case(
    topic: str,
    doc: str,
    argv: list[str] | None,
    *,
    worker: Callable[[str, str, int], dict],
    make_row: Callable[[str, int], dict],
    columns: Sequence,
    cases: tuple[Sequence[str], Sequence[str]],
    repeat: tuple[int, int],
) -> list[dict]:
    """The ``main`` of a benchmark whose tools each run a case in their own subprocess.

    ``--worker TOOL CASE`` (the subprocess): print ``worker(tool, case, repeat)`` as JSON.  Otherwise
    ``make_row(case, repeat)`` (which calls :func:`run_worker`) for ``cases`` = (quick, full), streamed
    as a table, then :func:`write_rows`.  ``repeat`` = (quick, full) defaults of ``--repeat``.
    """
    args = arguments(doc, argv, repeat=None, worker=("TOOL", "CASE"))
    n = args.repeat or (repeat[0] if args.quick else repeat[1])
    if args.worker:
        print(json.dumps(worker(args.worker[0], args.worker[1], n)))
        return []
    rows = stream_table(columns, cases[0] if args.quick else cases[1], lambda name: make_row(name, n))
    write_rows(topic, rows, args.quick)
    return rows


def arguments(
    doc: str,
    argv: list[str] | None = None,
    *,
    quick_help: str = "small cases only (smoke test)",
    repeat: int | None | bool = False,
    worker: Sequence[str] | None = None,
    output: bool = False,
) -> argparse.Namespace:
    """Parse the common options: ``--quick``; ``--repeat N`` (default ``repeat``; omitted when False);
    ``--worker`` with the metavars ``worker`` (hidden, for the subprocesses); ``--output FILE`` (default
    None: :func:`write_rows` picks the file)."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help=quick_help)
    if repeat is not False:
        ap.add_argument("--repeat", type=int, default=repeat, help="timed runs per case (best is kept)")
    if worker:
        ap.add_argument("--worker", nargs=len(worker), metavar=tuple(worker), help=argparse.SUPPRESS)
    if output:
        ap.add_argument("--output", default=None, help="JSON file for the rows (default: benchmarks/results)")
    return ap.parse_args(argv)


# ---------------------------------------------------------------------------- time and memory
def best_of(run: Callable[[], object], repeat: int, summary: Callable[[object], object] | None = None):
    """Best wall time of ``repeat`` calls of ``run()`` and the last result.

    With ``summary``, each result is replaced by ``summary(result)`` and dropped before the next call
    (so at most one result is alive); without it the last result is returned as is.
    """
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = run()
        best = min(best, time.perf_counter() - t0)
        if summary is not None:
            out = summary(out)
    return best, out


def best_times(fns: Sequence[Callable], args: tuple, repeat: int) -> list[float]:
    """Best wall time of each ``fn(*args)`` after one warm-up call each; the calls are interleaved
    (fn0, fn1, fn0, ...) so that machine load hits all alike."""
    for fn in fns:
        fn(*args)  # warm-up
    best = [float("inf")] * len(fns)
    for _ in range(repeat):
        for i, fn in enumerate(fns):
            t0 = time.perf_counter()
            fn(*args)
            best[i] = min(best[i], time.perf_counter() - t0)
    return best


def rss_mb() -> float:
    """This process's resident-set high-water mark (``getrusage``), MB."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def status_mb(field: str) -> float:
    """A field of ``/proc/self/status`` (``VmRSS``, ``VmHWM``, ...), MB."""
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024  # kB
    raise RuntimeError(f"{field} not in /proc/self/status")


def measure_rss(run: Callable[[], object], repeat: int, summary: Callable[[object], object] | None = None):
    """Time ``run`` (:func:`best_of`) between two reads of the RSS high-water mark.

    Returns ``({"time_s", "base_mb", "peak_mb", "work_mb"}, last result)``; ``work_mb = peak - base``
    is what the timed calls added to what the process held before.
    """
    base = rss_mb()
    best, out = best_of(run, repeat, summary)
    peak = rss_mb()
    return {"time_s": best, "base_mb": base, "peak_mb": peak, "work_mb": peak - base}, out


def peak_growth_mb(call: Callable[[], object]) -> float:
    """Peak RSS growth (MB) of one ``call()``: the high-water mark is reset first (``clear_refs``),
    or, where that is not possible, the lifetime peak is used."""
    try:  # reset the high-water mark (VmHWM) so imports and loading do not count
        with open("/proc/self/clear_refs", "w") as fh:
            fh.write("5")
        before = status_mb("VmRSS")
        call()
        peak = status_mb("VmHWM")
    except OSError:  # no clear_refs: fall back to the lifetime peak
        before = status_mb("VmRSS")
        call()
        peak = rss_mb()
    return max(peak - before, 0.0)


def tracemalloc_timed(fn: Callable[[], object], repeat: int):
    """``(best time, last result, peak MB)``: :func:`best_of`, then one more call under ``tracemalloc``
    (Python-side allocations only)."""
    best, out = best_of(fn, repeat)
    tracemalloc.start()
    fn()
    peak = tracemalloc.get_traced_memory()[1] / 2**20
    tracemalloc.stop()
    return best, out, peak


def run_worker(script: str, *args: object):
    """Run ``python script --worker args...`` in a fresh process; the JSON of its last output line."""
    cmd = [sys.executable, str(Path(script).resolve()), "--worker", *map(str, args)]
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        raise RuntimeError(f"worker {' '.join(map(str, args))} failed:\n{proc.stderr}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


# ---------------------------------------------------------------------------- output
def _cell(value) -> str:
    return f"{value:.3g}" if isinstance(value, float) else str(value)


def _columns(columns: Sequence) -> list[tuple[str, object]]:
    return [(c, None) if isinstance(c, str) else c for c in columns]


def table_header(columns: Sequence) -> str:
    """The two header lines of a Markdown table (columns as described above)."""
    from thesis_lib.lab.tables import header

    return header([t for t, _ in _columns(columns)])


def table_row(columns: Sequence, row: dict) -> str:
    """One Markdown table line of ``row`` (the project's one table writer, ``thesis_lib.lab.tables``)."""
    from thesis_lib.lab.tables import row as table_line

    cells = []
    for title, spec in _columns(columns):
        if spec is None:
            cells.append(_cell(row[title]))
        elif callable(spec):
            cells.append(spec(row))
        else:
            cells.append(spec.format(**row))
    return table_line(cells)


def print_table(columns: Sequence, rows: Sequence[dict]) -> None:
    """Print a Markdown table of ``rows``."""
    print(table_header(columns))
    for row in rows:
        print(table_row(columns, row))


def stream_table(columns: Sequence, names: Sequence[str], make_row: Callable[[str], dict]) -> list[dict]:
    """Print the table header, then ``make_row(name)`` for each name, each row printed once it is made
    (long runs show progress).  Returns the rows."""
    print(table_header(columns), flush=True)
    rows = []
    for name in names:
        rows.append(make_row(name))
        print(table_row(columns, rows[-1]), flush=True)
    return rows


def write_rows(topic: str, rows: list[dict], quick: bool, output: str | None = None, indent: int = 1) -> Path:
    """Write the rows as JSON to ``output``, or to ``results/<topic>.json`` (``<topic>_quick.json``
    when ``quick``: a smoke run never overwrites the stored full results).  Prints and returns the path."""
    out = Path(output) if output else RESULTS / (f"{topic}_quick.json" if quick else f"{topic}.json")
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(rows, indent=indent) + "\n")
    print(f"wrote {out}")
    return out

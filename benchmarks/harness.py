"""The benchmark harness shared by every ``benchmarks/bench_<topic>.py`` script.

Imported as ``import harness`` (running ``python benchmarks/bench_x.py`` puts this folder on
``sys.path``).  A published ratio must survive a re-run on a noisy shared machine, so every
benchmark follows these rules, and this module gives one function for each:

**Time: interleaved rounds, medians, paired ratios** — :func:`compare`.
    ``compare({"ours": f, "ripser": g}, rounds=None)`` calls each contender once to warm it up
    (imports, caches; the warm-up time is kept as ``warmup_s``), then runs *rounds*
    rounds A, B, A, B, ... so that a burst of load hits every contender alike.  The default
    number of rounds is :func:`default_rounds`: at least 5, and 15 when the slowest contender's
    first timed round took under 0.1 s (not its warm-up, which includes first-use costs).  The result
    holds every time, the median per contender and, from :func:`paired_ratio`, the median over
    rounds of the ratio of the two times of one round (the figure to publish: ``ratio_<peer>``).
    Compare **whole pipelines** (points → barcode for every tool); a step-only figure is named as
    such (``step_ratio_<peer>``, ``<step>_s``).

**Peak memory: separate processes, import baseline subtracted** — :func:`memory` (parent) and
    :func:`memory_worker` (child).  The parent runs ``python SCRIPT --memory ARGS...`` in a fresh
    process; the script calls ``memory_worker(setup, run)``: ``setup()`` imports, builds the input
    and warms up; the resident set size then is the *baseline* (``baseline_mb``); the high-water
    mark is reset and ``run(state)`` runs once; ``peak_mb`` is the new high-water mark and
    ``delta_mb = peak_mb - baseline_mb`` what the run itself added.  Both are stored, so a reader
    sees what was subtracted.

**Provenance** — :func:`environment`: commit (``-dirty`` when the tree has changes), UTC date,
    load average (1, 5, 15 min) at the start and the end of the run, cores seen and usable, Python
    and library versions.  :func:`write_results` stores ``{"meta": environment(), "rows": rows}``
    atomically in ``benchmarks/results/<topic>.json`` (``<topic>_quick.json`` for ``--quick``, so a
    smoke run never overwrites the stored full results).

**Staleness** — ``make bench-check`` (``benchmarks/check.py``) re-runs every benchmark's quick
    cases and fails when a stored ratio moved by more than ``TOLERANCE`` (±35 % on this noisy
    2-core machine).  Contract for a benchmark script, so that it can be checked: it accepts
    ``--quick`` and ``--output FILE``; its quick cases are also full cases (same ``case`` name);
    every time ratio it stores is a key starting with ``ratio`` (median of paired ratios, ours /
    peer; below 1 means we are faster).  A row may add ``noise_floor``: the smallest move of its
    ratios that its timings can resolve (in the ratio's units, e.g. fresh-process noise over the
    peer's time); a move within the larger of the two rows' floors is not a move.

**One timed call per fresh process** — :func:`run_worker` (parent) and :func:`measure_rss` (child),
    for tools that must not share a process (``bench_homology``: PARI, GUDHI and ours, each in
    its own interpreter, interleaved by the parent).
"""

from __future__ import annotations

import argparse
import datetime
import gc
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from importlib import metadata
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"
MIN_ROUNDS = 5  # rounds of interleaved timing, at least
FAST_ROUNDS = 15  # rounds when a case takes under FAST_BELOW seconds
FAST_BELOW = 0.1
TOLERANCE = 0.35  # make bench-check: largest relative move of a stored ratio
LIBRARIES = ("numpy", "scipy", "gudhi", "ripser", "giotto-ph", "libigl", "pymeshlab")


# ---------------------------------------------------------------------------- interleaved timing
def default_rounds(seconds: float) -> int:
    """Rounds for a case whose single run takes ``seconds``: 15 under 0.1 s, else 5."""
    return FAST_ROUNDS if seconds < FAST_BELOW else MIN_ROUNDS


def compare(contenders: Mapping[str, Callable[[], object]], *, rounds: int | None = None,
            check: Callable[[Mapping[str, object]], None] | None = None) -> dict:
    """Time contenders in interleaved rounds (A, B, A, B, ...) after one warm-up call each.

    Parameters
    ----------
    contenders : name -> zero-argument callable running one whole pipeline.
    rounds : timed rounds; default :func:`default_rounds` of the slowest contender's first timed
        round (5, or 15 when every contender took under 0.1 s; the warm-up is not used, as it
        includes compilation).
    check : optional; called once with ``{name: warm-up result}`` (e.g. to assert that every tool
        computed the same barcode) before the results are dropped.

    Returns
    -------
    dict with ``rounds``, ``warmup_s`` {name: s}, ``times_s`` {name: [s per round]} and
    ``median_s`` {name: s}.  Results are dropped at once (at most one alive at a time).
    """
    if not contenders:
        raise ValueError("no contenders to compare")
    warm, results = {}, {}
    for name, fn in contenders.items():
        t0 = time.perf_counter()
        out = fn()
        warm[name] = time.perf_counter() - t0
        if check is not None:
            results[name] = out
        del out
    if check is not None:
        check(results)
    results.clear()
    n = int(rounds) if rounds is not None else None
    if n is not None and n < 1:
        raise ValueError(f"rounds must be >= 1, got {n}")
    times: dict[str, list[float]] = {name: [] for name in contenders}
    done = 0
    while n is None or done < n:
        for name, fn in contenders.items():
            gc.collect()
            t0 = time.perf_counter()
            out = fn()
            times[name].append(time.perf_counter() - t0)
            del out
        done += 1
        if n is None:  # the first timed round, compiled code warm, sets the count
            n = default_rounds(max(t[0] for t in times.values()))
    return {"rounds": n, "warmup_s": warm, "times_s": times,
            "median_s": {name: statistics.median(t) for name, t in times.items()}}


def paired_ratio(result: Mapping, a: str, b: str) -> float:
    """Median over the rounds of ``time(a) / time(b)`` measured in the same round (of :func:`compare`)."""
    ta, tb = result["times_s"][a], result["times_s"][b]
    return statistics.median(x / y for x, y in zip(ta, tb))


def ratio_fields(result: Mapping, ours: str = "ours") -> dict:
    """The flat row fields of a :func:`compare` result: ``<name>_s`` (median) for every contender,
    ``ratio_<peer>`` (:func:`paired_ratio` of ``ours`` over each peer) and ``rounds``."""
    row: dict = {"rounds": result["rounds"]}
    for name, t in result["median_s"].items():
        row[f"{_key(name)}_s"] = t
    for name in result["median_s"]:
        if name != ours:
            row[f"ratio_{_key(name)}"] = paired_ratio(result, ours, name)
    return row


def _key(name: str) -> str:
    return name.replace("-", "_").replace(" ", "_")


# ---------------------------------------------------------------------------- memory in a fresh process
def _status_kb(field: str) -> int | None:
    try:
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith(field + ":"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


def memory_worker(setup: Callable[[], object], run: Callable[[object], object]) -> dict:
    """In the child process: ``state = setup()`` (imports, input, warm-up), read the resident set
    (the baseline), reset the high-water mark, ``run(state)`` once, read the high-water mark.

    Prints and returns ``{"baseline_mb", "peak_mb", "delta_mb", "hwm_reset"}``; ``hwm_reset`` is False
    where ``/proc/self/clear_refs`` cannot be written, and then ``peak_mb`` is the lifetime peak.
    """
    state = setup()
    gc.collect()
    base_kb = _status_kb("VmRSS") or 0
    try:
        with open("/proc/self/clear_refs", "w") as fh:
            fh.write("5")
        reset = True
    except OSError:
        reset = False
    out = run(state)
    del out
    peak_kb = (_status_kb("VmHWM") if reset else None) or resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    res = {"baseline_mb": base_kb / 1024, "peak_mb": peak_kb / 1024,
           "delta_mb": max(peak_kb - base_kb, 0) / 1024, "hwm_reset": reset}
    print(json.dumps(res), flush=True)
    return res


def memory(script: str, *args: object) -> dict:
    """Run ``python SCRIPT --memory ARGS...`` in a fresh process and return what its
    :func:`memory_worker` printed (``baseline_mb``, ``peak_mb``, ``delta_mb``)."""
    cmd = [sys.executable, str(Path(script).resolve()), "--memory", *map(str, args)]
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        raise RuntimeError(f"memory run {' '.join(map(str, args))} failed:\n{proc.stderr[-4000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def memory_fields(script: str, key: str, *args: object) -> dict:
    """``{key}_mb`` (peak above the baseline) and ``{key}_baseline_mb`` of :func:`memory`'s fresh run."""
    mem = memory(script, *args)
    return {f"{key}_mb": mem["delta_mb"], f"{key}_baseline_mb": mem["baseline_mb"]}


# ---------------------------------------------------------------------------- provenance
def _git(*args: str) -> str | None:
    try:
        out = subprocess.run(["git", *args], cwd=HERE, capture_output=True, text=True, timeout=20)
    except (OSError, subprocess.SubprocessError):
        return None
    return out.stdout.strip() if out.returncode == 0 else None


def environment() -> dict:
    """Where and when a benchmark ran: commit, UTC date, load average, cores, versions."""
    commit = _git("rev-parse", "HEAD")
    if commit and _git("status", "--porcelain", "--untracked-files=no"):
        commit += "-dirty"
    versions = {}
    for lib in LIBRARIES:
        try:
            versions[lib] = metadata.version(lib)
        except metadata.PackageNotFoundError:
            pass
    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:
        usable = os.cpu_count()
    return {
        "commit": commit,
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "load_average": [round(x, 2) for x in os.getloadavg()],
        "cores": os.cpu_count(),
        "usable_cores": usable,
        "machine": platform.machine(),
        "python": platform.python_version(),
        "versions": versions,
    }


def write_results(topic: str, rows: list[dict], quick: bool = False, output: str | None = None,
                  meta: Mapping | None = None) -> Path:
    """Store ``{"meta": ..., "rows": rows}`` atomically in ``results/<topic>.json`` (``<topic>_quick.json``
    when ``quick``) or ``output``.  ``meta`` is the :func:`environment` taken when the run started
    (default: now); the load average at the end is added as ``load_average_end``."""
    info = dict(meta) if meta is not None else environment()
    info["load_average_end"] = [round(x, 2) for x in os.getloadavg()]
    info["topic"] = topic
    info["quick"] = bool(quick)
    out = Path(output) if output else RESULTS / (f"{topic}_quick.json" if quick else f"{topic}.json")
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(out.name + ".tmp")
    tmp.write_text(json.dumps({"meta": info, "rows": rows}, indent=1) + "\n")
    os.replace(tmp, out)
    print(f"wrote {out}")
    return out


def update_results(topic: str, row: Mapping, meta: Mapping, order: Sequence[str] = ()) -> Path:
    """Replace (or add) the row of ``row["case"]`` in the stored ``results/<topic>.json``, atomically.

    The file's ``meta`` stays that of the run that stored the other rows; the new row carries its own
    run's provenance under ``"run"`` (commit, date, load at start and end) and is listed in
    ``meta["updated"]``.  Rows are kept in the order of ``order`` (the benchmark's full case list).
    """
    path = RESULTS / f"{topic}.json"
    stored_meta, rows = read_results(path) if path.exists() else (environment(), [])
    new = dict(row)
    new["run"] = {k: meta.get(k) for k in ("commit", "date", "load_average")}
    new["run"]["load_average_end"] = [round(x, 2) for x in os.getloadavg()]
    rows = [r for r in rows if r.get("case") != new["case"]] + [new]
    rank = {name: i for i, name in enumerate(order)}
    rows.sort(key=lambda r: rank.get(r.get("case"), len(rank)))
    info = dict(stored_meta)
    info["updated"] = sorted({*info.get("updated", []), str(new["case"])}, key=lambda c: rank.get(c, len(rank)))
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps({"meta": info, "rows": rows}, indent=1) + "\n")
    os.replace(tmp, path)
    print(f"updated {path} ({new['case']})")
    return path


def read_results(path: str | Path) -> tuple[dict, list[dict]]:
    """``(meta, rows)`` of a stored result file (a bare list of rows has empty meta)."""
    data = json.loads(Path(path).read_text())
    if isinstance(data, list):
        return {}, data
    return data.get("meta", {}), data["rows"]


def _ratio_pairs(stored: Sequence[Mapping], fresh: Sequence[Mapping]):
    """``(case, key, fresh value, stored value or None)`` for every ``ratio*`` number of each fresh
    row whose case is stored (None: no positive stored figure under that key)."""
    by_case = {r.get("case"): r for r in stored}
    for row in fresh:
        old = by_case.get(row.get("case"))
        if old is None:
            continue
        for key, value in row.items():
            if key.startswith("ratio") and isinstance(value, (int, float)) and not isinstance(value, bool):
                ref = old.get(key)
                yield row["case"], key, value, ref if isinstance(ref, (int, float)) and ref > 0 else None


def ratio_moves(stored: Sequence[Mapping], fresh: Sequence[Mapping]) -> list[tuple[str, str, float, float]]:
    """``(case, key, stored, fresh)`` for every ``ratio*`` value of a fresh row whose case has a
    stored positive figure under the same key."""
    return [(case, key, ref, value) for case, key, value, ref in _ratio_pairs(stored, fresh) if ref is not None]


def ratio_changes(stored: Sequence[Mapping], fresh: Sequence[Mapping], tolerance: float = TOLERANCE) -> list[str]:
    """Problems found by ``make bench-check``: every ``ratio*`` value of each fresh row against the
    stored row of the same ``case``; a move beyond ``tolerance`` (relative), a fresh case without a
    stored row, or a stored ratio missing from the fresh row.  A move within the rows' ``noise_floor``
    (absolute, the larger of the stored and the fresh one) is not counted."""
    cases = {r.get("case") for r in stored}
    problems = [f"{row.get('case')}: no stored result for this quick case" for row in fresh
                if row.get("case") not in cases]
    floors = {r.get("case"): r.get("noise_floor", 0.0) for r in stored}
    for row in fresh:
        floors[row.get("case")] = max(floors.get(row.get("case"), 0.0), row.get("noise_floor", 0.0))
    for case, key, value, ref in _ratio_pairs(stored, fresh):
        if ref is None:
            problems.append(f"{case}: {key} = {value:.3g} has no stored figure")
        elif abs(value / ref - 1.0) > tolerance and abs(value - ref) > floors[case]:
            problems.append(f"{case}: {key} moved {value / ref - 1.0:+.0%} (stored {ref:.3g}, now {value:.3g})")
    return problems

# A table column is a row key (the title; floats shown with 3 significant digits) or a pair
# (title, spec): spec a format string over the row's keys ("{ours_s:.4f}") or a function of the row.


# ---------------------------------------------------------------------------- command line
def arguments(
    doc: str,
    argv: list[str] | None = None,
    *,
    quick_help: str = "small cases only (smoke test)",
    repeat: int | None | bool = False,
    output: bool = False,
    memory: Sequence[str] | None = None,
    cases: Sequence[str] | None = None,
) -> argparse.Namespace:
    """Parse the common options: ``--quick``; ``--repeat N`` (default ``repeat``; omitted when False);
    ``--memory`` with the
    metavars ``memory`` (hidden, for :func:`memory`); ``--output FILE`` (default None:
    :func:`write_results` picks the file); ``--rounds N`` (default None: :func:`default_rounds`);
    with ``cases`` (the known case names) ``--cases NAME ...`` to run only some (``args.cases``, None
    for all) — a partial run is written to ``--output`` or ``<topic>_partial.json`` by the caller."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help=quick_help)
    if repeat is not False:
        ap.add_argument("--repeat", type=int, default=repeat, help="timed runs per case (best is kept)")
    if memory:
        ap.add_argument("--memory", nargs=len(memory), metavar=tuple(memory), help=argparse.SUPPRESS)
        ap.add_argument("--rounds", type=int, default=None,
                        help="interleaved timing rounds (default 5, or 15 under 0.1 s)")
    if cases:
        ap.add_argument("--cases", nargs="+", choices=list(cases), default=None, metavar="CASE",
                        help="run only these cases: " + ", ".join(cases))
    if output:
        ap.add_argument("--output", default=None, help="JSON file for the rows (default: benchmarks/results)")
    if cases and output:
        ap.add_argument("--update", action="store_true",
                        help="with --cases: replace (or add) those rows in the stored results, each with "
                             "its own run's provenance under 'run'")
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


def rss_mb() -> float:
    """This process's resident-set high-water mark (``getrusage``), MB."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def measure_rss(run: Callable[[], object], repeat: int, summary: Callable[[object], object] | None = None,
                *, short_s: float | None = None):
    """Time ``run`` (:func:`best_of` of ``repeat`` calls) between two reads of the RSS high-water mark.

    With ``short_s``, the calls after the first are made only when it took under ``short_s`` seconds
    (a single cold call of a few milliseconds is noisy; a long one is not, and is not repeated).
    Returns ``({"time_s", "base_mb", "peak_mb", "work_mb"}, last result)``; ``work_mb = peak - base``
    is what the timed calls added to what the process held before.
    """
    base = rss_mb()
    best, out = best_of(run, 1, summary)
    if repeat > 1 and (short_s is None or best < short_s):
        more, out = best_of(run, repeat - 1, summary)
        best = min(best, more)
    peak = rss_mb()
    return {"time_s": best, "base_mb": base, "peak_mb": peak, "work_mb": peak - base}, out


def run_worker(script: str, *args: object, timeout: float | None = None):
    """Run ``python script --worker args...`` in a fresh process; the JSON of its last output line.
    A run longer than ``timeout`` seconds is stopped (``subprocess.TimeoutExpired``)."""
    cmd = [sys.executable, str(Path(script).resolve()), "--worker", *map(str, args)]
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False, timeout=timeout)
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


def run_cases(topic: str, doc: str, argv: list[str] | None, *, cases: Sequence[str], quick: Sequence[str],
              full: Sequence[str], columns: Sequence, run_case: Callable[[str, int | None], dict],
              memory_child: Callable[..., object], memory: Sequence[str] = ("TOOL", "CASE"),
              quick_help: str = "small cases only (make bench-check)") -> list[dict]:
    """The ``main`` of a case-by-case benchmark: parse the common options (:func:`arguments`); in a
    ``--memory`` child call ``memory_child(*args)``; else run ``run_case(name, rounds)`` for the
    chosen cases (``--cases``, else ``quick`` or ``full``), printing each row as it is made and
    storing the rows after each case (an interrupted long run keeps the finished ones; a partial
    run goes to ``--output`` or ``<topic>_partial.json``)."""
    args = arguments(doc, argv, quick_help=quick_help, output=True, memory=memory, cases=list(cases))
    if args.update and (not args.cases or args.quick or args.output):
        raise SystemExit("--update needs --cases (and neither --quick nor --output)")
    if args.memory:
        memory_child(*args.memory)
        return []
    meta = environment()
    names = args.cases or list(quick if args.quick else full)
    output = args.output or (str(RESULTS / f"{topic}_partial.json") if args.cases else None)
    rows: list[dict] = []

    def row(name: str) -> dict:
        rows.append(run_case(name, args.rounds))
        if args.update:
            update_results(topic, rows[-1], meta, order=list(full))
        else:
            write_results(topic, rows, args.quick, output, meta)
        return rows[-1]

    stream_table(columns, names, row)
    return rows

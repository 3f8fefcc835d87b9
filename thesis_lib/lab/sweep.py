"""Sweeps: an experiment run on every point of a parameter grid, locally or on a Dask cluster.

``sweep(name, grid)`` expands the Cartesian grid (values checked before any kernel starts, equal
points run once), skips points whose run is complete, runs the rest on an executor and writes one
table (CSV and Markdown) of parameters, status, results, wall time and worker.

Executors: by default a pool of ``jobs`` threads, each driving a kernel on this machine; a
``distributed.Client`` (or its ``get_executor()``) runs each point on a Dask worker with no shared
file system (the notebook and input data travel as bytes, the outputs come back as bytes); any other
``concurrent.futures.Executor`` works the same way.  A worker that dies mid-run has its run retried
on another worker (Dask's ``allowed-failures``), then the run is reported failed.  Ctrl-C or SIGTERM
cancels what is pending and kills the running kernels; nothing half-written is ever marked complete,
and the next invocation resumes.  ``shard=(i, n)`` runs the i-th of n deterministic slices (for a job
array); :func:`collect` builds the table from whatever run folders exist.
"""

from __future__ import annotations

import builtins
import concurrent.futures as cf
import contextlib
import csv
import io
import itertools
import logging
import types
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from .._optional import require
from . import atomic
from .execute import DEFAULT_MAX_OUTPUT_MB, RunOutput, cancel_runs, execute, kill_kernels, missing_on_worker
from .experiments import ParameterError, resolve_parameters, run_hash
from .results import results_dir, round_sig
from .runner import RunResult, check_paths, local_spec, read_run, report_corrupt, runs_dir, write_run
from .tables import markdown_table

if TYPE_CHECKING:  # distributed is imported only when a Dask sweep is asked for
    from distributed import Client

__all__ = [
    "ClusterError",
    "expand_grid",
    "parse_shard",
    "data_bundle",
    "dask_client",
    "sweep",
    "collect",
    "stored_sweeps",
]

#: columns that differ from run to run (kept out of the table stored with the default run)
VOLATILE = ("seconds", "worker")


class ClusterError(OSError):
    """The Dask cluster cannot be reached, or its workers cannot run experiments."""


def expand_grid(name: str, grid: dict[str, list[object]]) -> list[dict[str, object]]:
    """The grid's points as resolved parameters, in grid order, each point once.

    Every value is checked (``ParameterError``) before anything runs; values that resolve to the
    same parameters (``1`` and ``"1"``, a value given twice) give one point.

    Parameters
    ----------
    name : str
        The experiment whose parameters the values are checked against.
    grid : dict of str to list
        The sweep's grid, as for :func:`sweep`.

    Returns
    -------
    list of dict
        One dict of resolved parameters (every parameter of the experiment) per distinct point of
        the Cartesian product, the last parameter varying fastest.

    Raises
    ------
    ParameterError
        If the grid is empty, a parameter has no values, or a name or value is not acceptable.
    """
    if not isinstance(grid, dict) or not grid:
        raise ParameterError("a sweep needs at least one parameter with values")
    for key, values in grid.items():
        if not isinstance(values, (list, tuple)) or not values:
            raise ParameterError(f"parameter {key!r} of the sweep has no values")
    points, seen = [], set()
    for values in itertools.product(*grid.values()):
        params = resolve_parameters(name, dict(zip(grid, values)))
        key = run_hash(params)
        if key not in seen:
            seen.add(key)
            points.append(params)
    return points


def parse_shard(text: str | tuple[int, int] | None) -> tuple[int, int] | None:
    """``"I/N"`` (or ``(I, N)``) as ``(I, N)`` with 1 ≤ I ≤ N; None stays None.

    Parameters
    ----------
    text : str or tuple of (int, int) or None
        The shard, as given to ``--shard`` (``"2/4"``) or as a pair.

    Returns
    -------
    tuple of (int, int) or None
        ``(I, N)``, or None for None.

    Raises
    ------
    ParameterError
        If the text is not ``I/N`` with digits, or not 1 ≤ I ≤ N.
    """
    if text is None:
        return None
    if isinstance(text, str):
        head, sep, tail = text.partition("/")
        if not sep or not head.strip().isdigit() or not tail.strip().isdigit():
            raise ParameterError(f"--shard takes I/N (like 1/4), got {text!r}")
        text = (int(head), int(tail))
    i, n = text
    if not (isinstance(i, int) and isinstance(n, int)) or n < 1 or not 1 <= i <= n:
        raise ParameterError(f"--shard I/N needs 1 <= I <= N, got {i}/{n}")
    return i, n


def _check_jobs(jobs: object) -> int:
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise ParameterError(f"jobs must be a positive integer (the number of runs at a time), got {jobs!r}")
    return jobs


def data_bundle() -> dict[str, object]:
    """The manifest and every data file found locally (sha256-checked), to ship to remote workers.

    Returns
    -------
    dict
        ``{"manifest": bytes, "files": {file below data/: bytes}}``.  Files that are missing or do
        not match their sha256 are left out (a run that needs one fails with the data layer's
        message); without a readable manifest, ``{"manifest": b"", "files": {}}``.
    """
    from . import data

    try:
        manifest_file = data.manifest_path()
        entries = data.manifest(manifest_file)
    except (data.DataError, OSError):
        return {"manifest": b"", "files": {}}
    files = {}
    for name, entry in entries.items():
        try:
            files[entry.file] = data.path(name).read_bytes()
        except data.DataError:
            continue  # missing here: a run that needs it fails with the data layer's message
    return {"manifest": manifest_file.read_bytes(), "files": files}


def _by_value(fn: Callable) -> Callable:
    """A copy of ``fn`` that cloudpickle sends by value (so it runs where thesis_lib is missing)."""
    clone = types.FunctionType(fn.__code__, {"__builtins__": builtins}, fn.__name__, fn.__defaults__)
    clone.__kwdefaults__ = fn.__kwdefaults__  # the defaults of keyword-only parameters are kept apart
    clone.__module__ = "__main__"
    return clone


@contextlib.contextmanager
def dask_client(
    *,
    scheduler: str | None = None,
    jobs: int = 2,
    retries: int = 2,
    timeout: float = 10.0,
    log: Callable[[str], None] | None = None,
) -> Iterator[Client]:
    """A ``distributed.Client`` for a sweep, checked, and closed (with its cluster) on exit.

    Parameters
    ----------
    scheduler : str, optional
        The address of a running scheduler (``tcp://host:8786``); None starts a ``LocalCluster`` of
        ``jobs`` single-threaded worker processes (closed on exit, whatever happens).
    jobs : int, default 2
        Worker processes of the local cluster (ignored with ``scheduler``).
    retries : int, default 2
        How many times a run is retried when its worker dies (the scheduler's
        ``allowed-failures``, set while the client is made).
    timeout : float, default 10.0
        Seconds to reach the scheduler; the first worker may take up to ``max(timeout, 60)``.
    log : callable, optional
        Called with a line of text to show (the dashboard's address); by default nothing is shown.

    Yields
    ------
    distributed.Client
        A client with at least one worker, each able to import thesis_lib, papermill, ipykernel and
        nbformat and to start a ``python3`` kernel.

    Raises
    ------
    ClusterError
        If the scheduler cannot be reached within ``timeout`` seconds (nothing is started), or a
        worker lacks a package the runs need (named).
    """
    dask = require("dask", extra="lab", purpose="sweeps on Dask")
    distributed = require("distributed", extra="lab", purpose="sweeps on Dask")
    Client, LocalCluster = distributed.Client, distributed.LocalCluster

    say = log or (lambda text: None)
    cluster = None
    with dask.config.set({"distributed.scheduler.allowed-failures": retries,
                          "distributed.comm.timeouts.connect": f"{timeout}s"}):
        try:
            if scheduler:
                client = Client(scheduler, timeout=f"{timeout}s")
            else:
                cluster = LocalCluster(n_workers=_check_jobs(jobs), threads_per_worker=1, processes=True,
                                       dashboard_address=":0", silence_logs=logging.ERROR)
                client = Client(cluster)
        except (OSError, TimeoutError, ValueError, RuntimeError) as exc:
            if cluster is not None:
                cluster.close()
            if scheduler:
                raise ClusterError(f"could not reach the Dask scheduler at {scheduler!r} within {timeout:g} s: "
                                   f"{exc}") from None
            raise ClusterError(f"could not start a local Dask cluster of {jobs} workers: {exc}") from None
        try:
            try:
                client.wait_for_workers(1, timeout=max(timeout, 60.0))
            except TimeoutError:
                raise ClusterError(f"no Dask worker joined the scheduler at {client.scheduler.address} "
                                   f"within {max(timeout, 60.0):g} s") from None
            missing = {w: m for w, m in client.run(_by_value(missing_on_worker)).items() if m}
            if missing:
                worker, names = next(iter(missing.items()))
                raise ClusterError(
                    f"{len(missing)} Dask worker(s) cannot run experiments: {worker} is missing "
                    f"{', '.join(names)}; install the project there (pip install \"thesis-lab[lab]\")"
                )
            if "dashboard" in client.scheduler_info().get("services", {}):
                say(f"Dask dashboard: {client.dashboard_link}")
            yield client
        finally:
            client.close()
            if cluster is not None:
                cluster.close()


class _Progress:
    """The sweep's progress bar: completed / failed / skipped / running."""

    def __init__(self, total: int, desc: str, enabled: bool):
        tqdm = require("tqdm.auto", extra="lab", purpose="the progress bar of sweeps").tqdm

        self.counts = {"ok": 0, "failed": 0, "skipped": 0, "running": 0}
        self.bar = tqdm(total=total, desc=desc, disable=not enabled, unit="run")

    def done(self, status: str) -> None:
        self.counts[status] += 1
        self.bar.update()
        self._show()

    def running(self, n: int) -> None:
        if n != self.counts["running"]:
            self.counts["running"] = n
            self._show()

    def _show(self) -> None:
        self.bar.set_postfix(self.counts, refresh=True)

    def close(self) -> None:
        self.bar.close()


def _client_of(executor) -> object | None:
    if executor is None:
        return None
    if type(executor).__module__.startswith("distributed") and hasattr(executor, "get_executor"):
        return executor
    return getattr(executor, "_client", None)


def _outcome(future: cf.Future) -> RunOutput:
    try:
        return future.result()
    except Exception as exc:  # the task itself failed: its worker died too often, or it could not run
        kind = type(exc).__name__
        why = ("its worker died on every attempt (killed or out of memory)" if kind == "KilledWorker"
               else "it could not run")
        return RunOutput("failed", error=f"{kind}: {why}: {exc}")


def _running(pending: dict, client) -> int:
    if client is not None:
        try:
            return sum(len(v) for v in client.processing().values())
        except Exception:  # noqa: BLE001 (progress only)
            return 0
    return sum(1 for f in pending if f.running())


def _table(rows: list[RunResult], keys: list[str], volatile: bool) -> tuple[str, str]:
    result_keys = sorted({k for r in rows for k in r.results})
    extra = list(VOLATILE) if volatile else []
    named = [f"{k} (result)" if k in keys or k in ("status", "run", *VOLATILE) else k for k in result_keys]
    header = keys + ["status"] + named + extra + ["run"]
    lines = []
    for r in rows:
        status = "ok" if r.status == "skipped" else r.status
        times = [round(r.seconds, 1), r.worker] if volatile else []
        lines.append([_shown(r.params[k]) for k in keys] + [status] + [r.results.get(k, "") for k in result_keys]
                     + times + [r.path.name if r.status != "missing" else ""])
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    writer.writerows(lines)
    return buf.getvalue(), markdown_table(header, lines)


def _shown(value: object) -> object:
    return ",".join(map(str, value)) if isinstance(value, list) else value


def _write_tables(name: str, keys: list[str], points: list[dict], rows: list[RunResult], base: Path,
                  keep: bool, suffix: str = "") -> Path:
    grid = {k: list(dict.fromkeys(_shown(p[k]) for p in points)) for k in keys}
    stem = run_hash({"grid": grid}) + suffix
    command = f"thesis-lab sweep {name}" + "".join(f" -p {k} " + " ".join(map(str, v)) for k, v in grid.items())
    table_dir = base / name / "sweeps"
    targets = [(table_dir, True)] + ([(results_dir(name) / "sweeps", False)] if keep else [])
    for folder, volatile in targets:
        csv_text, md_text = _table(rows, keys, volatile)
        atomic.write_text(folder / f"{stem}.csv", csv_text)
        atomic.write_text(folder / f"{stem}.md", f"`{command}`\n\n" + md_text)
    return table_dir / f"{stem}.csv"


def sweep(
    name: str,
    grid: dict[str, list[object]],
    *,
    jobs: int = 1,
    executor: cf.Executor | Client | None = None,
    root: Path | None = None,
    progress: bool = True,
    timeout: int = 3600,
    keep: bool = False,
    shard: str | tuple[int, int] | None = None,
    retries: int = 2,
    max_output_mb: float = DEFAULT_MAX_OUTPUT_MB,
) -> tuple[list[RunResult], Path]:
    """Run experiment ``name`` on the Cartesian product of ``grid`` and write one results table.

    Parameters
    ----------
    name : str
        An experiment that ``thesis-lab list`` shows.
    grid : dict of str to list
        Parameter name → values (a list or tuple, non-empty); strings are converted to the default's
        type.
    jobs : int, default 1
        Runs at a time on this machine (the default executor: a pool of threads driving kernels).
    executor : concurrent.futures.Executor or distributed.Client, optional
        A ``distributed.Client``, ``client.get_executor()`` or any ``concurrent.futures`` executor;
        runs then need no shared file system (the data travel with them, :func:`data_bundle`).
    root : pathlib.Path, optional
        Folder of the run folders (default ``runs/``).
    progress : bool, default True
        Show the progress bar (completed / failed / skipped / running).
    timeout : int, default 3600
        Seconds a cell may run.
    keep : bool, default False
        Also store the table (without wall times and workers) with the default run,
        ``experiments/results/<name>/sweeps/``, where the book reads it (not for a shard).
    shard : str or tuple of (int, int), optional
        ``"I/N"``: run only the I-th of N deterministic slices of the grid (a job array);
        the table then covers the slice; :func:`collect` builds the whole one.
    retries : int, default 2
        Dask only: how many times a run is retried when its worker dies.
    max_output_mb : float, default 64.0
        Largest total size of one run's outputs that may travel back from a worker.

    Returns
    -------
    runs : list of RunResult
        The runs in grid order (``status`` ``"ok"``, ``"failed"`` or ``"skipped"``).
    table : pathlib.Path
        The CSV table in ``<root>/<name>/sweeps/`` (a Markdown twin beside it).

    Raises
    ------
    ParameterError
        If the experiment, the grid, ``jobs`` or ``shard`` is not acceptable (before any run).
    KeyboardInterrupt
        When cancelled: nothing pending starts and running kernels are killed.
    """
    points = expand_grid(name, grid)
    for point in points:
        check_paths(point)
    _check_jobs(jobs)
    part = parse_shard(shard)
    if part is not None:
        points = points[part[0] - 1 :: part[1]]
    base = root or runs_dir()
    (base / name).mkdir(parents=True, exist_ok=True)
    atomic.clean_stale(base / name)
    results: list[RunResult | None] = [read_run(name, p, root=base) for p in points]
    bar = _Progress(len(points), f"sweep {name}", progress)
    todo = []
    for i, r in enumerate(results):
        if r.status == "ok":
            r.status = "skipped"
            bar.done("skipped")
        else:
            if r.status == "corrupt":
                report_corrupt(r)
            results[i] = None
            todo.append(i)
    client = _client_of(executor)
    owned = executor is None
    pool = cf.ThreadPoolExecutor(max_workers=jobs, thread_name_prefix="thesis-lab-run") if owned else executor
    if client is not None and executor is client:
        pool = client.get_executor(pure=False, retries=retries)
    bundle = None
    if not owned:
        bundle = data_bundle()
        if client is not None:
            # One future under a fresh key: a dict would be scattered value by value under its own keys
            # ("files"), which a previous sweep's release of the same keys can delete under this one.
            [bundle] = client.scatter([bundle], broadcast=True, hash=False)
    pending: dict[cf.Future, int] = {}
    try:
        for i in todo:
            spec = local_spec(name, points[i], timeout=timeout, max_output_mb=max_output_mb, self_contained=not owned)
            pending[pool.submit(execute, spec, bundle=bundle)] = i
        while pending:
            finished, _ = cf.wait(pending, timeout=0.5, return_when=cf.FIRST_COMPLETED)
            for fut in finished:
                i = pending.pop(fut)
                results[i] = write_run(name, points[i], _outcome(fut), root=base)
                bar.done(results[i].status)
            bar.running(_running(pending, client))
    except BaseException:
        _cancel(pending, pool if owned else None)
        raise
    finally:
        bar.close()
        if owned:
            pool.shutdown(wait=True, cancel_futures=True)
    done = [r for r in results if r is not None]
    suffix = f"-shard-{part[0]}-of-{part[1]}" if part else ""
    return done, _write_tables(name, list(grid), points, done, base, keep and not part, suffix)


def _cancel(pending: dict, pool: cf.Executor | None) -> None:
    """Cancel a sweep: nothing pending starts, running kernels are killed, threads are joined."""
    cancel_runs(cancelled=True)
    try:
        for fut in pending:
            fut.cancel()
        kill_kernels()
        if pool is not None:
            pool.shutdown(wait=True, cancel_futures=True)
        kill_kernels()
    finally:
        cancel_runs(cancelled=False)


def collect(name: str, grid: dict[str, list[object]], *, root: Path | None = None,
            keep: bool = False) -> tuple[list[RunResult], Path]:
    """The sweep table of ``grid`` built from the run folders that exist (after ``--shard`` runs).

    Points without a run folder are rows with status ``missing``; nothing is executed.

    Parameters
    ----------
    name, grid, root, keep
        As for :func:`sweep`; the grid is the whole one the shards were cut from.

    Returns
    -------
    runs : list of RunResult
        One per point of the grid, in grid order: ``"ok"``, ``"failed"``, ``"corrupt"`` (a run folder
        that cannot be read, reported on stderr) or ``"missing"``.
    table : pathlib.Path
        The CSV table in ``<root>/<name>/sweeps/`` (a Markdown twin beside it).

    Raises
    ------
    ParameterError
        If the experiment or the grid is not acceptable.
    """
    points = expand_grid(name, grid)
    base = root or runs_dir()
    rows = [read_run(name, p, root=base) for p in points]
    for r in rows:
        if r.status == "corrupt":
            report_corrupt(r, "its row is marked corrupt (run the sweep again to replace it)")
    return rows, _write_tables(name, list(grid), points, rows, base, keep)


def stored_sweeps(name: str, *, columns: list[str] | None = None, titles: list[str] | None = None,
                  digits: int | None = None, note: bool = False) -> list[str]:
    """Markdown tables of the sweeps stored with experiment ``name`` (``sweep(..., keep=True)``).

    Parameters
    ----------
    name : str
        The experiment's name.
    columns : list of str, optional
        Keep only these columns (in that order) of each table, read from its CSV twin; the command
        line stays on top.  By default the stored Markdown as it is.
    titles : list of str, optional
        The headers of ``columns`` (one each); by default the column names.
    digits : int, optional
        Write numbers for a reader: whole numbers with thousands separators, others to ``digits``
        significant digits; by default the stored text.
    note : bool, default False
        End each table with a line saying whether every run finished (from the ``status`` column).

    Returns
    -------
    list of str
        One Markdown text per stored sweep (the command line, a blank line, the table, and the note),
        by file name; empty when none is stored.

    Raises
    ------
    ValueError
        If a stored sweep lacks one of ``columns``, or ``titles``, ``digits`` or ``note`` is given
        without ``columns``, or ``titles`` has not one title per column.

    Examples
    --------
    >>> stored_sweeps("an-experiment-without-sweeps")
    []
    """
    if columns is None and (titles is not None or digits is not None or note):
        raise ValueError("titles, digits and note shape the chosen columns: give columns too")
    if titles is not None and len(titles) != len(columns):
        raise ValueError(f"titles must have one title per column ({len(columns)}), got {len(titles)}")
    tables = []
    for md in sorted((results_dir(name) / "sweeps").glob("*.md")):
        if columns is None:
            tables.append(md.read_text())
            continue
        with md.with_suffix(".csv").open(newline="") as fh:
            rows = list(csv.DictReader(fh))
        missing = [c for c in [*columns, *(["status"] if note else [])] if rows and c not in rows[0]]
        if missing:
            raise ValueError(f"the stored sweep {md.name} of {name!r} has no columns {missing}")
        command = md.read_text().split("\n", 1)[0]
        cells = [[_readable(r[c], digits) if digits is not None else r[c] for c in columns] for r in rows]
        text = f"{command}\n\n" + markdown_table(titles or columns, cells)
        if note:
            failed = sum(r["status"].strip() != "ok" for r in rows)
            text += "\n" + (f"{failed} of the runs did not finish." if failed else "Every run finished.")
        tables.append(text)
    return tables


def _readable(text: str, digits: int) -> str:
    """A stored cell for a reader: whole numbers with thousands separators, others to ``digits`` digits."""
    try:
        number = float(text)
    except ValueError:
        return text
    return f"{int(number):,}" if number.is_integer() else f"{round_sig(number, digits):g}"

"""Run experiment notebooks with papermill: one run, or the stored default run (``store``).

A run with parameters P goes to ``runs/<name>/<hash(P)>/``: the executed notebook, ``params.json``,
the experiment's ``results.json`` and figures, and ``complete.json`` once it succeeded (a sweep
skips such runs; a failed run has ``error.txt`` and ``failed.json`` instead).  The run executes in a
scratch folder (``thesis_lib.lab.execute``) and its folder appears in one step when it is done:
an interrupted run leaves nothing, and nothing is ever marked complete without its results.
``store`` re-executes a notebook in place and replaces its committed results folder only on success.
Sweeps over grids of parameters are in :mod:`thesis_lib.lab.sweep`.
"""

from __future__ import annotations

import atexit
import dataclasses
import json
import math
import os
import shutil
import sys
import tempfile
from dataclasses import KW_ONLY, dataclass, field
from pathlib import Path

from .._optional import require
from . import atomic
from .execute import DEFAULT_MAX_OUTPUT_MB, LabKernelManager, RunOutput, RunSpec, cancellable, execute, kernel_config
from .experiments import (
    OUTPUT_PARAMETER,
    ParameterError,
    experiment_parameters,
    experiments_dir,
    list_experiments,
    notebook_path,
    resolve_parameters,
    run_hash,
)
from .paths import PROJECT_ENV, project_root
from .results import DEFAULT_RUN_ENV, RESULTS_FILE, ResultsError, check_table, parse_json, read_json, results_dir

__all__ = [
    "ParameterError",
    "OUTPUT_PARAMETER",
    "COMPLETE_FILE",
    "experiments_dir",
    "runs_dir",
    "list_experiments",
    "experiment_parameters",
    "resolve_parameters",
    "run_hash",
    "run",
    "read_run",
    "write_run",
    "store",
    "RunResult",
]

COMPLETE_FILE = "complete.json"
FAILED_FILE = "failed.json"
ERROR_FILE = "error.txt"


def runs_dir() -> Path:
    """Folder where ``thesis-lab run`` and ``sweep`` write (not committed).

    Returns
    -------
    pathlib.Path
        ``runs/`` of the project folder; its existence is not checked.
    """
    return project_root() / "runs"


@dataclass
class RunResult:
    """Outcome of one experiment run."""

    name: str
    params: dict[str, object]
    path: Path
    status: str  # "ok", "skipped" (already complete), "failed", "corrupt" or "missing" (no run folder)
    _: KW_ONLY
    results: dict[str, float] = field(default_factory=dict)
    error: str = ""
    seconds: float = 0.0
    worker: str = ""


def _json(value: object) -> str:
    return json.dumps(value, indent=1, sort_keys=True, allow_nan=False) + "\n"


def read_run(name: str, params: dict[str, object], *, root: Path | None = None) -> RunResult:
    """What ``runs/<name>/<hash>/`` holds for these resolved parameters: ok, failed, corrupt or missing.

    An interrupted replacement of the folder is undone first (``atomic.recover``).  A folder whose
    ``complete.json`` / ``failed.json`` or ``results.json`` cannot be read as the runner wrote it
    (garbage, not a JSON object, a non-numeric ``seconds``, a folder in place of a file, a table
    that is not flat numbers) is ``"corrupt"``, with the reason naming the file: ``run`` and
    ``sweep`` run it again, ``collect`` reports it.

    Parameters
    ----------
    name : str
        The experiment's name.
    params : dict of str to object
        Resolved parameters (:func:`resolve_parameters`); their :func:`run_hash` names the run folder.
    root : pathlib.Path, optional
        The runs folder; by default ``runs/`` of the project (:func:`runs_dir`).

    Returns
    -------
    RunResult
        ``status`` ``"ok"`` (``complete.json``), ``"failed"`` (``failed.json``, with its error),
        ``"corrupt"`` (``error`` says which file and why) or ``"missing"``; the stored time, worker
        and ``results.json`` when there are any.
    """
    path = (root or runs_dir()) / name / run_hash(params)
    atomic.recover(path)
    result = RunResult(name, params, path, "missing")
    if (path / COMPLETE_FILE).exists():
        status, marker = "ok", path / COMPLETE_FILE
    elif (path / FAILED_FILE).exists():
        status, marker = "failed", path / FAILED_FILE
    else:
        return result
    try:
        info = read_json(marker)
        if not isinstance(info, dict):
            raise ResultsError(f"{marker} must hold a JSON object, got a {type(info).__name__}")
        seconds, worker, error = info.get("seconds", 0.0), info.get("worker", ""), info.get("error", "")
        if isinstance(seconds, bool) or not isinstance(seconds, (int, float)) or not math.isfinite(seconds):
            raise ResultsError(f"{marker}: 'seconds' must be a number, got {seconds!r}"[:300])
        if not isinstance(worker, str) or not isinstance(error, str):
            raise ResultsError(f"{marker}: 'worker' and 'error' must be strings")
        results = {}
        if (path / RESULTS_FILE).exists():
            try:
                results = check_table(read_json(path / RESULTS_FILE), path / RESULTS_FILE)
            except ResultsError:
                if status == "ok":  # a failed run's partial results are shown when readable, never used
                    raise
    except ResultsError as exc:
        result.status, result.error = "corrupt", str(exc)
        return result
    result.status, result.seconds, result.worker, result.results = status, float(seconds), worker, results
    if status == "failed":
        result.error = error
    return result


def report_corrupt(result: RunResult, action: str = "running it again") -> None:
    """Say on stderr that a run folder is corrupt (by name, with the reason) and what is done.

    Parameters
    ----------
    result : RunResult
        A run read by :func:`read_run` with status ``"corrupt"``.
    action : str
        What happens to it, e.g. ``"running it again"``.
    """
    print(f"corrupt run folder {result.path}: {result.error}; {action}", file=sys.stderr, flush=True)


def _relative_file(rel: str) -> str:
    parts = Path(rel).parts
    if not rel or Path(rel).is_absolute() or ".." in parts:
        raise ValueError(f"a run output named {rel!r} would be written outside its run folder")
    return rel


def write_run(name: str, params: dict[str, object], output: RunOutput, *, root: Path | None = None) -> RunResult:
    """Write a run's outputs into ``runs/<name>/<hash>/`` in one step (see the module docstring).

    A failed run never replaces a complete one: its outputs go to ``runs/<name>/<hash>.failed/``.

    Parameters
    ----------
    name : str
        The experiment's name.
    params : dict of str to object
        Resolved parameters (:func:`resolve_parameters`); their :func:`run_hash` names the run
        folder.  Written as ``params.json``.
    output : RunOutput
        What ``thesis_lib.lab.execute.execute`` returned; its files are written below the run
        folder, with ``complete.json`` when ``status`` is ``"ok"``, else ``failed.json`` and
        ``error.txt``.
    root : pathlib.Path, optional
        The runs folder; by default ``runs/`` of the project (:func:`runs_dir`).

    Returns
    -------
    RunResult
        The run as written: its folder, ``output``'s status, error, time and worker, and the
        results of a complete run.

    Raises
    ------
    ValueError
        If an output file's name leads outside the run folder (absolute or with ``..``).
    """
    folder = (root or runs_dir()) / name
    folder.mkdir(parents=True, exist_ok=True)
    atomic.clean_stale(folder)
    dest = folder / run_hash(params)
    results = _written_results(output)
    if isinstance(results, str):  # the notebook wrote a results.json that no reader could use
        output = dataclasses.replace(output, status="failed", error=results)
    if output.status != "ok" and (dest / COMPLETE_FILE).is_file():
        dest = folder / f"{dest.name}.failed"
    info = {"seconds": round(output.seconds, 3), "worker": output.worker}
    with atomic.staging(dest) as tmp:
        for rel, payload in output.files.items():
            target = tmp / _relative_file(rel)
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(payload)
        (tmp / "params.json").write_text(_json(params))
        if output.status == "ok":
            (tmp / COMPLETE_FILE).write_text(_json(info))
        else:
            if not (tmp / ERROR_FILE).exists():
                (tmp / ERROR_FILE).write_text(output.error + "\n")
            (tmp / FAILED_FILE).write_text(_json({**info, "error": output.error}))
    result = RunResult(name, params, dest, output.status, error=output.error, seconds=output.seconds,
                       worker=output.worker)
    if output.status == "ok":
        result.results = results
    return result


def _written_results(output: RunOutput) -> dict[str, float | int] | str:
    """The table in a run's ``results.json`` (empty when there is none), or why it is unusable."""
    payload = output.files.get(RESULTS_FILE)
    if payload is None or output.status != "ok":
        return {}
    try:
        return check_table(parse_json(payload.decode("utf-8", errors="replace"), RESULTS_FILE), RESULTS_FILE)
    except ResultsError as exc:
        return f"the notebook wrote an unusable {exc}"


def check_paths(params: dict[str, object]) -> None:
    """Refuse a parameter naming a file outside the project that the manifest does not list.

    The kernel runs in the project's ``experiments/`` folder, so a relative path is read from there.
    See :func:`thesis_lib.lab.data.check_parameter_paths`.

    Parameters
    ----------
    params : dict of str to object
        Resolved parameters.

    Raises
    ------
    DataError
        If a parameter names a file outside the project whose sha256 no manifest entry has.
    """
    from .data import check_parameter_paths

    check_parameter_paths(params, base=experiments_dir())


def local_spec(name: str, params: dict[str, object], *, timeout: int = 3600,
               max_output_mb: float = DEFAULT_MAX_OUTPUT_MB, self_contained: bool = False) -> RunSpec:
    """The :class:`RunSpec` of a run of ``name`` with resolved ``params``.

    Parameters
    ----------
    name : str
        The experiment's name.
    params : dict of str to object
        Resolved parameters (:func:`resolve_parameters`), copied into the spec.
    timeout : int, default 3600
        Seconds a cell may run.
    max_output_mb : float, default 64.0
        Largest total size of the run's outputs, MB.
    self_contained : bool, default False
        False: the kernel uses this project in place.  True: a scratch project (then the data must
        travel with it, see ``sweep.data_bundle``).

    Returns
    -------
    RunSpec
        The spec, with the notebook's bytes read now.

    Raises
    ------
    ParameterError
        If ``name`` is not a known experiment.
    """
    return RunSpec(
        name=name,
        params=dict(params),
        notebook=notebook_path(name).read_bytes(),
        timeout=timeout,
        max_output_mb=max_output_mb,
        project=None if self_contained else str(project_root()),
    )


def run(
    name: str,
    overrides: dict[str, object] | None = None,
    *,
    root: Path | None = None,
    force: bool = False,
    timeout: int = 3600,
    progress: bool | None = None,
) -> RunResult:
    """Execute experiment ``name`` with papermill into ``runs/<name>/<hash>/``.

    A run that completed before with the same resolved parameters is not repeated unless ``force``.
    Failures of the notebook are returned with ``status="failed"`` and the error text; invalid
    parameters raise ``ParameterError`` before any kernel starts.

    Parameters
    ----------
    name : str
        The experiment's name.
    overrides : dict of str to object, optional
        Parameter values that differ from the notebook's defaults (see :func:`resolve_parameters`).
    root : pathlib.Path, optional
        The runs folder; by default ``runs/`` of the project (:func:`runs_dir`).
    force : bool, default False
        Run again even if a complete run exists.
    timeout : int, default 3600
        Seconds a cell may run.
    progress : bool, optional
        Show which cell runs and the elapsed time; by default when stderr is a terminal.

    Returns
    -------
    RunResult
        ``status`` ``"ok"``, ``"failed"`` or ``"skipped"`` (the complete earlier run, as read).

    Raises
    ------
    ParameterError
        For an unknown experiment or parameter, or a value of the wrong type.
    DataError
        For a parameter naming a file outside the project that the manifest does not list.
    KeyboardInterrupt
        When cancelled (Ctrl-C): running kernels are killed and nothing is written.
    """
    params = resolve_parameters(name, overrides)
    check_paths(params)
    atomic.clean_stale((root or runs_dir()) / name)
    previous = read_run(name, params, root=root)
    if previous.status == "ok" and not force:
        previous.status = "skipped"
        return previous
    if previous.status == "corrupt":
        report_corrupt(previous)
    if progress is None:
        progress = sys.stderr.isatty()
    output = cancellable(execute, local_spec(name, params, timeout=timeout), progress=progress)
    return write_run(name, params, output, root=root)


def _store_target(target: str | Path) -> Path:
    """An experiment name that ``list`` shows, or a notebook inside the project's book/ or experiments/."""
    text = str(target)
    if not text.endswith(".ipynb"):
        return notebook_path(text)
    root = project_root().resolve()
    path = Path(text) if Path(text).is_absolute() else Path.cwd() / text
    path = path.resolve()
    allowed = [root / "book", root / "experiments"]
    if not path.is_file() or not any(path.parent == folder.resolve() for folder in allowed):
        raise ParameterError(
            f"{text!r} is not a notebook of this project: give an experiment name "
            f"({', '.join(list_experiments())}) or a notebook in {root / 'book'} or {root / 'experiments'}"
        )
    return path


def store(path: str | Path, *, timeout: int = 3600) -> Path:
    """Execute a notebook in place with its own defaults (the stored default run), outputs kept.

    ``path`` is an experiment name or a notebook path (book chapters).  Cells run in the notebook's
    folder; no parameters are injected, so the stored notebook stays as authored.  The results the
    notebook records go to a temporary folder and replace ``experiments/results/<name>/`` in one step
    only once every cell has run (its stored ``sweeps/`` are kept): a failing or interrupted store
    leaves the committed results byte-identical.

    Parameters
    ----------
    path : str or pathlib.Path
        An experiment name that ``thesis-lab list`` shows, or a notebook (``.ipynb``) directly inside
        the project's ``book/`` or ``experiments/`` (relative to the current folder).
    timeout : int, default 3600
        Seconds a cell may run.

    Returns
    -------
    pathlib.Path
        The notebook, rewritten with its new outputs.

    Raises
    ------
    ParameterError
        If ``path`` is neither a known experiment nor a notebook of the project.

    Notes
    -----
    A failing cell raises nbclient's ``CellExecutionError``; nothing is rewritten.
    """
    nb_path = _store_target(path)
    NotebookClient = require("nbclient", extra="lab", purpose="storing executed notebooks").NotebookClient
    nbformat = require("nbformat", extra="lab", purpose="storing executed notebooks")
    nb = nbformat.read(nb_path, as_version=4)
    results_root = project_root() / "experiments" / "results"
    results_root.mkdir(parents=True, exist_ok=True)
    atomic.clean_stale(results_root)
    staging_root = Path(tempfile.mkdtemp(prefix=f".store.tmp-{os.getpid()}-", dir=results_root))
    try:
        env = {DEFAULT_RUN_ENV: str(staging_root), PROJECT_ENV: str(project_root())}
        client = NotebookClient(
            nb,
            timeout=timeout,
            kernel_name="python3",
            resources={"metadata": {"path": str(nb_path.parent)}},
            kernel_manager_class=LabKernelManager,
            config=kernel_config(extra_env=env, log=staging_root / "kernel.log"),
        )
        try:
            cancellable(client.execute)
        finally:  # nbclient leaves its exit-time kernel clean-up registered when a run is cancelled
            atexit.unregister(client._cleanup_kernel)
        for cell in nb.cells:
            cell.metadata.pop("execution", None)
        with atomic.replacing(nb_path) as tmp_nb:
            nbformat.write(nb, tmp_nb)
            for new in sorted(p for p in staging_root.iterdir() if p.is_dir()):
                dest = results_dir(new.name)
                kept = dest / "sweeps"
                if kept.is_dir() and not (new / "sweeps").exists():
                    shutil.copytree(kept, new / "sweeps")
                atomic.recover(dest)
                atomic.replace_dir(new, dest)
    finally:
        shutil.rmtree(staging_root, ignore_errors=True)
    return nb_path

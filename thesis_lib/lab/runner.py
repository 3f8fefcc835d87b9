"""Run experiment notebooks with papermill: one run, a sweep over a grid, or the stored default run.

An experiment is ``experiments/<name>.ipynb`` with one code cell tagged ``parameters`` that assigns
plain literals (int, float, str, bool).  Parameters are validated against those literals before any
kernel starts.  A run with parameters P goes to ``runs/<name>/<hash(P)>/``: the executed notebook,
``params.json``, the experiment's ``results.json`` and figures, and ``complete.json`` once it
succeeded (a sweep skips such runs).
"""

from __future__ import annotations

import ast
import csv
import hashlib
import io
import itertools
import json
import os
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path

import nbformat

from .paths import repo_root
from .results import DEFAULT_RUN_ENV, RESULTS_FILE, results_dir

__all__ = [
    "ParameterError",
    "experiments_dir",
    "list_experiments",
    "experiment_parameters",
    "resolve_parameters",
    "run_hash",
    "run",
    "sweep",
    "store",
    "stored_sweeps",
    "RunResult",
]

OUTPUT_PARAMETER = "output_dir"
COMPLETE_FILE = "complete.json"


class ParameterError(ValueError):
    """An experiment name, parameter name or parameter value is not acceptable."""


def experiments_dir() -> Path:
    """Folder holding the experiment notebooks."""
    return repo_root() / "experiments"


def runs_dir() -> Path:
    """Folder where ``thesis-lab run`` and ``sweep`` write (not committed)."""
    return repo_root() / "runs"


def list_experiments() -> list[str]:
    """Names of all experiments (notebooks in ``experiments/``)."""
    return sorted(p.stem for p in experiments_dir().glob("*.ipynb"))


def _notebook_path(name: str) -> Path:
    path = experiments_dir() / f"{name}.ipynb"
    if not path.is_file():
        known = ", ".join(list_experiments()) or "none"
        raise ParameterError(f"unknown experiment {name!r}; known experiments: {known}")
    return path


def _parameters_cell(nb) -> str:
    cells = [c for c in nb.cells if c.cell_type == "code" and "parameters" in c.metadata.get("tags", [])]
    if len(cells) != 1:
        raise ParameterError(f"an experiment needs exactly one cell tagged 'parameters', found {len(cells)}")
    return cells[0].source


def experiment_parameters(name: str) -> dict[str, object]:
    """Default value of every parameter of experiment ``name``, read from its ``parameters`` cell."""
    nb = nbformat.read(_notebook_path(name), as_version=4)
    tree = ast.parse(_parameters_cell(nb))
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


def _is_scalar(value: object) -> bool:
    return isinstance(value, (bool, int, float, str))


def _is_scalar_list(value: object) -> bool:
    """A non-empty list whose items share one scalar kind (ints may stand among floats)."""
    if not isinstance(value, list) or not value or not all(_is_scalar(v) for v in value):
        return False
    kinds = {type(v) for v in value}
    return len(kinds) == 1 or kinds == {int, float}


def _coerce_list(key: str, value: object, default: list) -> list:
    """A list parameter: a list, a JSON list (``[60, 100]``) or comma-separated text (``60,100``)."""
    if isinstance(value, str):
        text = value.strip()
        if text.startswith("["):
            try:
                value = json.loads(text)
            except json.JSONDecodeError:
                raise ParameterError(f"parameter {key!r} expects a list (like {default!r}), got {value!r}") from None
        else:
            value = [v for v in text.split(",")] if text else []
    if not isinstance(value, list) or not value:
        raise ParameterError(f"parameter {key!r} expects a non-empty list (like {default!r}), got {value!r}")
    item_default = default[0] if not any(isinstance(v, float) for v in default) else 0.0
    return [_coerce(key, v, item_default) for v in value]


def _coerce(key: str, value: object, default: object) -> object:
    if isinstance(default, list):
        return _coerce_list(key, value, default)
    kind = type(default).__name__
    if isinstance(value, str) and not isinstance(default, str):
        text = value.strip()
        try:
            if isinstance(default, bool):
                if text.lower() in _TRUE:
                    return True
                if text.lower() in _FALSE:
                    return False
                raise ValueError
            if isinstance(default, int):
                return int(text)
            return float(text)
        except ValueError:
            raise ParameterError(f"parameter {key!r} expects {kind} (like {default!r}), got {value!r}") from None
    if isinstance(default, bool):
        ok = isinstance(value, bool)
    elif isinstance(default, int):
        ok = isinstance(value, int) and not isinstance(value, bool)
    elif isinstance(default, float):
        ok = isinstance(value, (int, float)) and not isinstance(value, bool)
        value = float(value) if ok else value
    else:
        ok = isinstance(value, str)
    if not ok:
        raise ParameterError(f"parameter {key!r} expects {kind} (like {default!r}), got {value!r}")
    return value


def resolve_parameters(name: str, overrides: dict[str, object] | None = None) -> dict[str, object]:
    """Defaults of ``name`` updated with ``overrides`` (strings are converted to the default's type).

    Raises ``ParameterError`` for an unknown experiment, an unknown parameter or a value of the
    wrong type; ``output_dir`` is set by the runner and cannot be overridden.
    """
    defaults = experiment_parameters(name)
    params = dict(defaults)
    for key, value in (overrides or {}).items():
        if key == OUTPUT_PARAMETER:
            raise ParameterError(f"{OUTPUT_PARAMETER!r} is set by the runner; it is not a parameter to pass")
        if key not in defaults:
            known = ", ".join(k for k in defaults if k != OUTPUT_PARAMETER)
            raise ParameterError(f"experiment {name!r} has no parameter {key!r}; its parameters are: {known}")
        params[key] = _coerce(key, value, defaults[key])
    params.pop(OUTPUT_PARAMETER, None)
    return params


def run_hash(params: dict[str, object]) -> str:
    """Short stable hash of resolved parameters: the run's folder name."""
    text = json.dumps(params, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:10]


@dataclass
class RunResult:
    """Outcome of one experiment run."""

    name: str
    params: dict[str, object]
    path: Path
    status: str  # "ok", "skipped" (already complete) or "failed"
    results: dict[str, float] = field(default_factory=dict)
    error: str = ""
    seconds: float = 0.0


def _read_results(path: Path) -> dict[str, float]:
    file = path / RESULTS_FILE
    return json.loads(file.read_text()) if file.exists() else {}


def run(
    name: str,
    overrides: dict[str, object] | None = None,
    *,
    root: Path | None = None,
    force: bool = False,
    timeout: int = 3600,
) -> RunResult:
    """Execute experiment ``name`` with papermill into ``runs/<name>/<hash>/``.

    A run that completed before with the same resolved parameters is not repeated unless ``force``.
    Failures of the notebook are returned with ``status="failed"`` and the error text; invalid
    parameters raise ``ParameterError`` before any kernel starts.
    """
    params = resolve_parameters(name, overrides)
    out = (root or runs_dir()) / name / run_hash(params)
    result = RunResult(name, params, out, "ok")
    if (out / COMPLETE_FILE).exists() and not force:
        result.status = "skipped"
        result.results = _read_results(out)
        return result
    out.mkdir(parents=True, exist_ok=True)
    (out / COMPLETE_FILE).unlink(missing_ok=True)
    (out / "params.json").write_text(json.dumps(params, indent=1, sort_keys=True) + "\n")
    import papermill as pm

    start = time.perf_counter()
    try:
        pm.execute_notebook(
            str(_notebook_path(name)),
            str(out / f"{name}.ipynb"),
            parameters={**params, OUTPUT_PARAMETER: str(out)},
            cwd=str(experiments_dir()),
            kernel_name="python3",
            progress_bar=False,
            execution_timeout=timeout,
        )
    except Exception as exc:  # papermill re-raises the notebook's error; keep its message
        result.status = "failed"
        result.error = f"{type(exc).__name__}: {str(exc).strip().splitlines()[-1] if str(exc).strip() else ''}"
        (out / "error.txt").write_text(str(exc))
    result.seconds = time.perf_counter() - start
    result.results = _read_results(out)
    if result.status == "ok":
        (out / COMPLETE_FILE).write_text(json.dumps({"seconds": round(result.seconds, 3)}) + "\n")
    return result


def _grid(name: str, grid: dict[str, list[object]]) -> list[dict[str, object]]:
    if not grid:
        raise ParameterError("a sweep needs at least one parameter with values")
    for key, values in grid.items():
        if not values:
            raise ParameterError(f"parameter {key!r} of the sweep has no values")
    combos = [dict(zip(grid, values)) for values in itertools.product(*grid.values())]
    for combo in combos:  # validate every point before any kernel starts
        resolve_parameters(name, combo)
    return combos


def _markdown(header: list[str], lines: list[list[object]]) -> str:
    def cell(v: object) -> str:
        return f"{v:.6g}" if isinstance(v, float) else str(v)

    md = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    md += ["| " + " | ".join(cell(v) for v in line) + " |" for line in lines]
    return "\n".join(md) + "\n"


def _table(rows: list[RunResult], keys: list[str]) -> tuple[str, str]:
    result_keys = sorted({k for r in rows for k in r.results})
    header = keys + ["status"] + result_keys + ["run"]
    lines = []
    for r in rows:
        lines.append(
            [r.params[k] for k in keys] + [r.status] + [r.results.get(k, "") for k in result_keys] + [r.path.name]
        )
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    writer.writerows(lines)
    return buf.getvalue(), _markdown(header, lines)


def _run_one(args) -> RunResult:
    name, combo, root, timeout = args
    return run(name, combo, root=root, timeout=timeout)


def sweep(
    name: str,
    grid: dict[str, list[object]],
    *,
    jobs: int = 1,
    root: Path | None = None,
    progress: bool = True,
    timeout: int = 3600,
    keep: bool = False,
) -> tuple[list[RunResult], Path]:
    """Run experiment ``name`` on the Cartesian product of ``grid`` and write one results table.

    Completed runs are skipped, failing runs are reported and the sweep goes on.  Returns the runs
    (in grid order) and the path of the CSV table (a Markdown twin sits beside it).  With ``keep``
    the table is also stored with the default run, ``experiments/results/<name>/sweeps/``, where
    the book reads it.
    """
    combos = _grid(name, grid)
    base = root or runs_dir()
    tasks = [(name, combo, base, timeout) for combo in combos]
    results: list[RunResult | None] = [None] * len(tasks)
    from tqdm.auto import tqdm

    bar = tqdm(total=len(tasks), desc=f"sweep {name}", disable=not progress, unit="run")
    if jobs > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            futures = {pool.submit(_run_one, t): i for i, t in enumerate(tasks)}
            for fut in as_completed(futures):
                results[futures[fut]] = fut.result()
                bar.update()
    else:
        for i, t in enumerate(tasks):
            results[i] = _run_one(t)
            bar.update()
    bar.close()
    done = [r for r in results if r is not None]
    csv_text, md_text = _table(done, list(grid))
    table_dir = base / name / "sweeps"
    table_dir.mkdir(parents=True, exist_ok=True)
    stem = run_hash({k: [str(v) for v in vals] for k, vals in grid.items()})
    command = "thesis-lab sweep " + name + "".join(f" -p {k} " + " ".join(map(str, v)) for k, v in grid.items())
    md_text = f"`{command}`\n\n" + md_text
    folders = [table_dir] + ([results_dir(name) / "sweeps"] if keep else [])
    for folder in folders:
        folder.mkdir(parents=True, exist_ok=True)
        (folder / f"{stem}.csv").write_text(csv_text)
        (folder / f"{stem}.md").write_text(md_text)
    return done, table_dir / f"{stem}.csv"


def stored_sweeps(name: str, columns: list[str] | None = None) -> list[str]:
    """Markdown tables of the sweeps stored with experiment ``name`` (``sweep(..., keep=True)``).

    ``columns`` keeps only those columns (in that order) of each table; its command line stays on top.
    """
    tables = []
    for md in sorted((results_dir(name) / "sweeps").glob("*.md")):
        if columns is None:
            tables.append(md.read_text())
            continue
        rows = list(csv.DictReader(md.with_suffix(".csv").open()))
        missing = [c for c in columns if rows and c not in rows[0]]
        if missing:
            raise ValueError(f"the stored sweep {md.name} of {name!r} has no columns {missing}")
        command = md.read_text().split("\n", 1)[0]
        tables.append(f"{command}\n\n" + _markdown(columns, [[r[c] for c in columns] for r in rows]))
    return tables


def store(path: str | Path, timeout: int = 3600) -> Path:
    """Execute a notebook in place with its own defaults (the stored default run), outputs kept.

    ``path`` is an experiment name or a notebook path (book chapters).  Cells run in the notebook's
    folder; no parameters are injected, so the stored notebook stays as authored.
    """
    from nbclient import NotebookClient

    nb_path = Path(path)
    if nb_path.suffix != ".ipynb":
        nb_path = _notebook_path(str(path))
    nb = nbformat.read(nb_path, as_version=4)
    # the stored default run is the point of storing: never redirected (see results.DEFAULT_RUN_ENV)
    env = {k: v for k, v in os.environ.items() if k != DEFAULT_RUN_ENV}
    client = NotebookClient(nb, timeout=timeout, kernel_name="python3", resources={"metadata": {"path": str(nb_path.parent)}})
    client.execute(env=env)
    for cell in nb.cells:
        cell.metadata.pop("execution", None)
    nbformat.write(nb, nb_path)
    return nb_path

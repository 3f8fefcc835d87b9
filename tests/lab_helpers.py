"""Helpers of the laboratory's tests: a throw-away project with the fast ``toy`` experiment, a data
set, and the tools to find the processes a command left behind."""

from __future__ import annotations

import csv
import hashlib
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import nbformat
import pytest

FIXTURES = Path(__file__).resolve().parent / "fixtures"
PAYLOAD = b"ATOM      1  N   GLY A   1\n"
TAG_ENV = "THESIS_LAB_TEST_TAG"
#: every result key the toy records with its defaults
TOY_RESULTS = {"square": 9, "x": 0.5, "flag": 0, "label_length": 1, "sizes_sum": 160}


def make_project(root: Path, experiments: tuple[str, ...] = ("toy",)) -> Path:
    """A project at ``root``: ``experiments/toy.ipynb`` (and copies under other names), a manifest
    with one data set ``toy-data`` (``data/x/toy.pdb``), and ``../shared`` beside it."""
    (root / "experiments").mkdir(parents=True)
    for name in experiments:
        shutil.copy(FIXTURES / "experiments" / "toy.ipynb", root / "experiments" / f"{name}.ipynb")
    (root / "data" / "x").mkdir(parents=True)
    (root / "data" / "x" / "toy.pdb").write_bytes(PAYLOAD)
    digest = hashlib.sha256(PAYLOAD).hexdigest()
    (root / "data" / "manifest.toml").write_text(
        f'[[file]]\nname = "toy-data"\nfile = "x/toy.pdb"\nsha256 = "{digest}"\nsize = {len(PAYLOAD)}\n'
        f'url = "file:///nonexistent"\norigin = "test"\nlicence = "CC0"\n'
    )
    (root.parent / "shared" / "data").mkdir(parents=True, exist_ok=True)
    return root


@pytest.fixture
def root(tmp_path, monkeypatch):
    """A throw-away project with the fast experiment ``toy`` (import this fixture into a test file)."""
    project = make_project(tmp_path / "project")
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(project))
    monkeypatch.setenv("THESIS_LAB_SHARED", str(tmp_path / "shared"))
    return project


def commit_fake_results(root: Path) -> Path:
    """A committed default run of ``toy`` that no run could write: results, a figure, a kept sweep."""
    folder = root / "experiments" / "results" / "toy"
    (folder / "sweeps").mkdir(parents=True)
    (folder / "results.json").write_text('{"square": -1}\n')
    (folder / "old.png").write_bytes(b"\x89PNG old")
    (folder / "sweeps" / "kept.md").write_text("| n |\n|---|\n| 1 |\n")
    return folder


def set_default(root: Path, name: str, key: str, value: str) -> None:
    """Change a default in the parameters cell of ``experiments/<name>.ipynb``."""
    path = root / "experiments" / f"{name}.ipynb"
    nb = nbformat.read(path, as_version=4)
    cell = next(c for c in nb.cells if "parameters" in c.metadata.get("tags", []))
    lines = [f"{key} = {value}  # changed by a test" if line.startswith(f"{key} =") else line
             for line in cell.source.splitlines()]
    cell.source = "\n".join(lines)
    nbformat.write(nb, path)


def cli(root: Path, *args: str, tag: str = "", timeout: float = 600, **kw) -> subprocess.CompletedProcess:
    """Run ``thesis-lab ARGS`` in a fresh process on the project ``root`` (outputs captured)."""
    return subprocess.run(popen_args(root, *args), env=cli_env(root, tag), capture_output=True, text=True,
                          timeout=timeout, **kw)


def popen_args(root: Path, *args: str) -> list[str]:
    return [sys.executable, "-m", "thesis_lib.lab.cli", "--project", str(root), *args]


def cli_env(root: Path, tag: str = "") -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("THESIS_LAB_")}
    env["THESIS_LAB_SHARED"] = str(root.parent / "shared")
    if tag:
        env[TAG_ENV] = tag
    return env


def tagged_processes(tag: str) -> list[int]:
    """Process ids whose environment carries ``THESIS_LAB_TEST_TAG=tag`` (kernels and workers inherit it)."""
    needle = f"{TAG_ENV}={tag}".encode() + b"\0"
    pids = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit() or int(entry.name) == os.getpid():
            continue
        try:
            if needle in (entry / "environ").read_bytes() + b"\0":
                pids.append(int(entry.name))
        except OSError:
            continue
    return pids


def wait_until(predicate, timeout: float, interval: float = 0.2, what: str = "condition"):
    """Poll ``predicate()`` until it is true (returns its value) or fail after ``timeout`` seconds."""
    end = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > end:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(interval)


def table_rows(path: Path, drop: tuple[str, ...] = ("seconds", "worker")) -> list[dict[str, str]]:
    """A sweep table's rows without the columns that vary from run to run."""
    with open(path, newline="") as fh:
        return [{k: v for k, v in row.items() if k not in drop} for row in csv.DictReader(fh)]


def tree_bytes(folder: Path) -> dict[str, bytes]:
    """Every file below ``folder`` by relative path (to compare folders byte for byte)."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def complete_runs_are_whole(runs: Path) -> list[str]:
    """Problems with run folders below ``runs``: a folder marked complete without its results,
    notebook or valid params, or a failed one whose params are not JSON."""
    problems = []
    folders = (p for p in runs.glob("*/*") if p.is_dir() and not p.name.startswith(".") and p.name != "sweeps")
    for folder in sorted(folders):
        files = {p.name for p in folder.iterdir()}
        if "complete.json" in files:
            missing = {"results.json", "params.json", f"{folder.parent.name}.ipynb"} - files
            if missing:
                problems.append(f"{folder} is complete without {sorted(missing)}")
        if "params.json" in files:
            try:
                json.loads((folder / "params.json").read_text(), parse_constant=_no_constant)
            except ValueError as exc:
                problems.append(f"{folder}/params.json: {exc}")
    return problems


def _no_constant(name: str):
    raise ValueError(f"{name} is not JSON")

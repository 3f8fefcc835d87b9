"""Stored outputs and results do not depend on the machine that made them.

Every notebook (book chapters and experiments) is re-executed once more under perturbed numerics —
one BLAS thread and one thread of the compiled core, another OpenBLAS kernel family
(``OPENBLAS_CORETYPE``), numpy's code for an older CPU — and its outputs are compared with the stored ones by nbval,
with the same sanitising rules as the ordinary nbval run of ``make test`` (which re-executes them
with this machine's defaults); the ``results.json`` and figures each notebook writes must equal the
committed ones byte for byte. The experiments' default runs go to a scratch folder, never to
``experiments/results``.

The re-execution is a second nbval session (two workers) in a subprocess, started once for this
module; it takes as long as the notebooks' part of ``make test``.

The compiled core (``src/*.cpp``) has no code for another CPU to select: it is compiled once for the
baseline instruction set of its target (no ``-march``, no fast-math, ``-ffp-contract=off``), so the
same machine code runs on every CPU of that architecture and no run-time setting can change it.
"""

from __future__ import annotations

import functools
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from thesis_lib.lab.paths import project_root
from thesis_lib.lab.results import DEFAULT_RUN_ENV, RESULTS_FILE

ROOT = project_root()
NOTEBOOKS = sorted((ROOT / "book").glob("*.ipynb")) + sorted((ROOT / "experiments").glob("*.ipynb"))
COMMITTED = ROOT / "experiments" / "results"
SANITIZE = ROOT / "tests" / "nbval_sanitize.cfg"

#: OpenBLAS kernel families to try, in order of preference: Sandybridge has no FMA, so its dot
#: products round differently from the Haswell/Zen/SkylakeX kernels of current machines
CORETYPES = ("Sandybridge", "Haswell", "Nehalem")


def _probe(env: dict[str, str], code: str) -> str:
    """Run ``code`` in a fresh interpreter with ``env`` and return what it prints."""
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120)
    proc.check_returncode()
    return proc.stdout.strip()


_BLAS_ARCH = (
    "import numpy, scipy.linalg, threadpoolctl; "
    "print(sorted({i['architecture'] for i in threadpoolctl.threadpool_info() if i['internal_api'] == 'openblas'}))"
)
_NUMPY_DISPATCH = (
    "from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__; "
    "print(' '.join(f for f in __cpu_dispatch__ if __cpu_features__.get(f)))"
)


@functools.lru_cache(maxsize=1)
def perturbed_environment() -> tuple[dict[str, str], dict[str, str]]:
    """The environment of the re-execution, and what each perturbation amounts to on this machine."""
    base = {k: v for k, v in os.environ.items() if not k.startswith(("PYTEST_", "OPENBLAS_CORETYPE"))}
    changes = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    found = {"threads": "OpenBLAS 1 thread, the compiled core's parallel kernels on 1 thread"}
    default_arch = _probe(base, _BLAS_ARCH)
    for core in CORETYPES:
        arch = _probe(base | {"OPENBLAS_CORETYPE": core}, _BLAS_ARCH)
        if arch != default_arch:
            changes["OPENBLAS_CORETYPE"] = core
            found["openblas"] = f"OpenBLAS kernels {arch} instead of {default_arch}"
            break
    else:
        found["openblas"] = f"OpenBLAS kernels unchanged ({default_arch}): this machine accepts no other core type"
    dispatched = _probe(base, _NUMPY_DISPATCH)
    if dispatched:
        changes["NPY_DISABLE_CPU_FEATURES"] = dispatched
        found["numpy"] = f"numpy without its {dispatched} loops"
    else:
        found["numpy"] = "numpy has only its baseline loops on this machine"
    return base | changes, found


def _failures(junit: Path) -> dict[str, list[str]]:
    """Failed or erroring cells per notebook (path relative to the checkout) from nbval's JUnit report."""
    out: dict[str, list[str]] = {}
    for case in ET.parse(junit).getroot().iter("testcase"):
        for bad in list(case.iter("failure")) + list(case.iter("error")):
            notebook = case.get("file", "")
            out.setdefault(notebook, []).append(f"{case.get('name')}:\n{bad.text or bad.get('message', '')}")
    return out


@pytest.fixture(scope="module")
def perturbed_run(tmp_path_factory) -> dict[str, object]:
    """Re-execute every notebook under perturbed numerics with nbval; keep its default runs."""
    scratch = tmp_path_factory.mktemp("perturbed")
    env, found = perturbed_environment()
    env = env | {DEFAULT_RUN_ENV: str(scratch / "runs")}
    junit = scratch / "nbval.xml"
    cmd = [
        sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "-n", "2", "--dist", "loadfile",
        "--nbval", "--nbval-current-env", "--nbval-sanitize-with", str(SANITIZE),
        f"--junitxml={junit}", "-o", "junit_family=xunit1",
        *[str(p.relative_to(ROOT)) for p in NOTEBOOKS],
    ]
    proc = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=3600)
    assert junit.is_file(), proc.stdout[-3000:] + proc.stderr[-3000:]
    return {"failures": _failures(junit), "runs": scratch / "runs", "found": found, "log": proc.stdout}


_BLAS_THREADS = (
    "import numpy, scipy.linalg, threadpoolctl; "
    "print(sorted({i['num_threads'] for i in threadpoolctl.threadpool_info() if i['user_api'] == 'blas'}))"
)


def test_the_perturbed_environment_does_what_it_says():
    env, found = perturbed_environment()
    assert _probe(env, _BLAS_THREADS) in ("[1]", "[]"), "BLAS does not run on one thread"
    assert _probe(env, "from thesis_lib._core import threads; print(threads.thread_count())") == "1"
    if "OPENBLAS_CORETYPE" in env:
        base = {k: v for k, v in env.items() if k != "OPENBLAS_CORETYPE"}
        assert _probe(env, _BLAS_ARCH) != _probe(base, _BLAS_ARCH), found["openblas"]
    assert _probe(env, _NUMPY_DISPATCH) == "", "numpy still uses loops beyond its baseline"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_outputs_do_not_depend_on_numerics(perturbed_run, path):
    rel = str(path.relative_to(ROOT))
    failures = perturbed_run["failures"].get(rel, [])
    assert not failures, (
        f"{rel} re-executed with {perturbed_run['found']} gives other outputs than stored "
        "(round the value to the digits that mean something, CONVENTIONS.md):\n\n" + "\n\n".join(failures)
    )


def _committed_runs() -> list[str]:
    return sorted(p.parent.name for p in COMMITTED.glob(f"*/{RESULTS_FILE}"))


@pytest.mark.parametrize("name", _committed_runs())
def test_results_json_bytes_do_not_depend_on_numerics(perturbed_run, name):
    rerun = perturbed_run["runs"] / name / RESULTS_FILE
    assert rerun.is_file(), f"no notebook wrote the default run {name!r} when re-executed"
    stored, fresh = (COMMITTED / name / RESULTS_FILE).read_bytes(), rerun.read_bytes()
    if stored != fresh:
        old, new = json.loads(stored), json.loads(fresh)
        moved = {k: (old.get(k), new.get(k)) for k in sorted(set(old) | set(new)) if old.get(k) != new.get(k)}
        pytest.fail(f"{name}/results.json differs under {perturbed_run['found']}: (stored, re-run) = {moved}")


def _committed_figures() -> list[str]:
    return sorted(str(p.relative_to(COMMITTED)) for p in COMMITTED.glob("*/*.png"))


@pytest.mark.parametrize("figure", _committed_figures())
def test_stored_figures_do_not_depend_on_numerics(perturbed_run, figure):
    rerun = perturbed_run["runs"] / figure
    assert rerun.is_file(), f"no notebook wrote {figure} when re-executed"
    assert rerun.read_bytes() == (COMMITTED / figure).read_bytes(), f"{figure} differs under {perturbed_run['found']}"


def test_every_default_run_comes_from_a_notebook(perturbed_run):
    written = sorted(p.parent.name for p in Path(perturbed_run["runs"]).glob(f"*/{RESULTS_FILE}"))
    assert written == _committed_runs()

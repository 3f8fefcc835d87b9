"""The distributions: the sdist and the wheel built from this checkout, and the installed package.

One build per test session (the module fixture ``dist``): ``python -m build`` of the checkout, which
makes the sdist and then the wheel *from that sdist* in isolated environments (so a file the sdist
forgot fails the wheel build here, not on a user's machine), compiling every ``src/*.cpp``.  It runs
in a scratch folder (``python -m build`` started inside the checkout would import the CMake folder
``build/`` as the ``build`` package) and writes nothing into the checkout.

``test_installed_package_computes`` needs neither the checkout nor the build: it is the test
``.github/workflows/wheels.yml`` runs on every wheel cibuildwheel makes
(``pytest --noconftest tests/test_distribution.py -k installed``); this file therefore imports only the
standard library and pytest at module level.
"""

from __future__ import annotations

import email.parser
import importlib
import importlib.machinery
import pkgutil
import re
import subprocess
import sys
import tarfile
import tomllib
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: the extras pyproject.toml promises (README, environment.yml and the book rely on them)
EXTRAS = {"plot", "mesh", "proteins", "lab", "book", "dev"}
#: what the library itself needs; everything else comes with an extra
RUNTIME = {"numpy", "scipy"}
#: the wheel and the sdist are built within this many seconds (every src/*.cpp compiled, 2 cores)
BUILD_TIMEOUT_S = 1800


def _run(cmd: list[str], cwd: Path, timeout: float) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout, check=False)


def _tool(module: str) -> None:
    """Fail (not skip: the [dev] extra installs them) when ``python -m <module>`` is unavailable."""
    proc = _run([sys.executable, "-m", module, "--version"], cwd=Path(sys.prefix), timeout=120)
    if proc.returncode != 0:
        pytest.fail(f"`{sys.executable} -m {module}` is not available (it is in the [dev] extra: "
                    f"pip install -e '.[dev]'): {proc.stderr.strip()[-500:]}")


@pytest.fixture(scope="module")
def dist(tmp_path_factory) -> dict:
    """Build the sdist, and the wheel from the sdist, of this checkout: ``{"sdist": path, "wheel": path}``."""
    _tool("build")
    out = tmp_path_factory.mktemp("dist")
    proc = _run([sys.executable, "-m", "build", "--outdir", str(out), str(ROOT)], cwd=out, timeout=BUILD_TIMEOUT_S)
    if proc.returncode != 0:
        pytest.fail(f"python -m build failed (exit {proc.returncode}):\n{proc.stdout[-6000:]}\n{proc.stderr[-6000:]}")
    sdists, wheels = sorted(out.glob("*.tar.gz")), sorted(out.glob("*.whl"))
    assert len(sdists) == 1 and len(wheels) == 1, (sdists, wheels, proc.stdout[-3000:])
    return {"sdist": sdists[0], "wheel": wheels[0], "log": proc.stdout}


def _wheel_names(dist: dict) -> list[str]:
    with zipfile.ZipFile(dist["wheel"]) as zf:
        return zf.namelist()


def _sdist_names(dist: dict) -> list[str]:
    """The sdist's members without their top folder (``thesis_lab-0.1.0/``)."""
    with tarfile.open(dist["sdist"]) as tf:
        names = [m.name for m in tf.getmembers() if m.isfile() or m.issym()]
    top = {n.split("/", 1)[0] for n in names}
    assert len(top) == 1, f"the sdist has more than one top folder: {sorted(top)}"
    return [n.split("/", 1)[1] for n in names if "/" in n]


def _wheel_metadata(dist: dict):
    names = _wheel_names(dist)
    [meta] = [n for n in names if re.fullmatch(r"[^/]+\.dist-info/METADATA", n)]
    with zipfile.ZipFile(dist["wheel"]) as zf:
        return email.parser.Parser().parsestr(zf.read(meta).decode())


def _tracked(folder: str) -> list[str]:
    """Files of ``folder`` that git tracks (relative to the checkout)."""
    proc = _run(["git", "ls-files", "--", folder], cwd=ROOT, timeout=60)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout.split()


def _kernels() -> list[str]:
    """The compiled modules the checkout defines: one per ``src/<name>.cpp``."""
    return sorted(p.stem for p in (ROOT / "src").glob("*.cpp"))


def _citation_version() -> str:
    m = re.search(r"^version:\s*['\"]?([^'\"\s]+)", (ROOT / "CITATION.cff").read_text(), re.M)
    assert m, "CITATION.cff has no version"
    return m.group(1)


def _source_version() -> str:
    m = re.search(r"^__version__\s*=\s*['\"]([^'\"]+)['\"]", (ROOT / "thesis_lib" / "__init__.py").read_text(), re.M)
    assert m, "thesis_lib/__init__.py sets no __version__"
    return m.group(1)


# ---------------------------------------------------------------------------- the built distributions
def test_twine_check_passes(dist):
    _tool("twine")
    proc = _run([sys.executable, "-m", "twine", "check", "--strict", str(dist["sdist"]), str(dist["wheel"])],
                cwd=dist["wheel"].parent, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.count("PASSED") == 2, proc.stdout


def test_wheel_holds_the_compiled_core_and_the_package_data(dist):
    names = set(_wheel_names(dist))
    tag = dist["wheel"].name.split("-")[2]  # the interpreter tag, e.g. cp311
    assert tag.startswith("cp"), dist["wheel"].name
    core = {n for n in names if n.startswith("thesis_lib/_core/") and not n.endswith(".py")}
    built = {n.split("/")[-1].split(".", 1)[0] for n in core}
    assert built == set(_kernels()), f"compiled modules {sorted(built)} != src/*.cpp {_kernels()}"
    suffixes = importlib.machinery.EXTENSION_SUFFIXES
    for name in core:
        assert any(name.endswith(s) for s in suffixes), f"{name}: not an extension module of this interpreter"
    # every file git tracks in the package (py.typed, *.toml or other data, every module) is in the wheel
    missing = [f for f in _tracked("thesis_lib") if f not in names]
    assert not missing, f"tracked package files missing from the wheel: {missing}"
    assert "thesis_lib/py.typed" in names


def test_wheel_holds_nothing_but_the_package(dist):
    names = _wheel_names(dist)
    info = {n.split("/", 1)[0] for n in names if ".dist-info/" in n}
    assert len(info) == 1
    stray = [n for n in names if not n.startswith(("thesis_lib/", *info))]
    assert not stray, f"files outside the package in the wheel: {stray[:20]}"
    for bad in ("__pycache__/", ".pyc", ".nbi", ".nbc", ".o", ".a"):
        assert not [n for n in names if bad in n or n.endswith(bad)], bad
    for folder in ("tests/", "book/", "src/", "experiments/", "benchmarks/", "data/"):
        assert not [n for n in names if n.startswith(folder) or f"/{folder}" in n], folder


def test_sdist_holds_the_sources_of_the_compiled_core(dist):
    names = set(_sdist_names(dist))
    for f in ("CMakeLists.txt", "pyproject.toml", "LICENSE", "README.md", "CITATION.cff", "PKG-INFO"):
        assert f in names, f
    sources = {p.relative_to(ROOT).as_posix() for p in (ROOT / "src").iterdir() if p.suffix in (".cpp", ".hpp")}
    assert any(s.endswith(".hpp") for s in sources) and any(s.endswith(".cpp") for s in sources)
    assert sources <= names, f"sources missing from the sdist: {sorted(sources - names)}"
    assert {n for n in names if n.startswith("src/")} == sources, "the sdist's src/ differs from the checkout's"
    for f in _tracked("thesis_lib"):
        assert f in names, f
    for bad in (".venv/", "build/", "__pycache__/", ".egg-info/", "book/_build/", ".jupyter_cache/"):
        assert not [n for n in names if n.startswith(bad) or f"/{bad}" in n], bad
    assert not [n for n in names if n.endswith((".so", ".pyd", ".dylib", ".pyc"))], "compiled files in the sdist"


def test_metadata_version_is_the_citation_and_package_version(dist):
    meta = _wheel_metadata(dist)
    assert meta["Name"] == "thesis-lab"
    assert meta["Version"] == _citation_version() == _source_version()
    assert dist["sdist"].name == f"thesis_lab-{meta['Version']}.tar.gz"
    assert dist["wheel"].name.startswith(f"thesis_lab-{meta['Version']}-")
    with zipfile.ZipFile(dist["wheel"]) as zf:
        text = zf.read("thesis_lib/__init__.py").decode()
    assert re.search(rf"^__version__\s*=\s*['\"]{re.escape(meta['Version'])}['\"]", text, re.M)
    import thesis_lib

    assert thesis_lib.__version__ == meta["Version"]


def test_metadata_dependencies_are_numpy_and_scipy_and_the_extras_exist(dist):
    meta = _wheel_metadata(dist)
    requires = meta.get_all("Requires-Dist") or []
    plain = {re.match(r"[A-Za-z0-9_.\-]+", r).group(0).lower() for r in requires if ";" not in r}
    assert plain == RUNTIME, f"Requires-Dist without an extra marker: {sorted(plain)}"
    extras = set(meta.get_all("Provides-Extra") or [])
    assert EXTRAS <= extras, f"missing extras: {sorted(EXTRAS - extras)}"
    for extra in EXTRAS:
        assert any(f'extra == "{extra}"' in r for r in requires), f"the extra {extra} requires nothing"
    assert meta["Requires-Python"] == ">=3.11"
    assert meta["License-Expression"] == "MIT"
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert set(project["optional-dependencies"]) == extras


# ---------------------------------------------------------------------------- the wheel workflow
def test_wheel_workflow_builds_tests_and_publishes_only_tags():
    yaml = pytest.importorskip("yaml")
    workflow = yaml.safe_load((ROOT / ".github" / "workflows" / "wheels.yml").read_text())
    env = workflow["env"]
    assert env["CIBW_BUILD"].split() == ["cp311-*", "cp312-*", "cp313-*"]
    # the test command runs this file's installed-package test, which must exist
    m = re.search(r"tests/test_distribution\.py -k (\w+)", env["CIBW_TEST_COMMAND"])
    assert m and any(name.startswith("test_") and m.group(1) in name for name in globals()), env["CIBW_TEST_COMMAND"]
    assert "--noconftest" in env["CIBW_TEST_COMMAND"] and "pytest" in env["CIBW_TEST_REQUIRES"].split()
    jobs = workflow["jobs"]
    publish = [j for j in jobs.values() if any(s.get("uses", "").startswith("pypa/gh-action-pypi-publish@")
                                               for s in j.get("steps", []))]
    assert len(publish) == 1
    assert "refs/tags/" in publish[0]["if"] and publish[0]["permissions"]["id-token"] == "write"
    assert not any("password" in s.get("with", {}) for s in publish[0]["steps"])  # trusted publishing
    needs = set(publish[0]["needs"])
    assert needs <= set(jobs) and len(needs) >= 2
    steps = [s for j in jobs.values() for s in j.get("steps", [])]
    assert any("build --sdist" in s.get("run", "") for s in steps)
    assert any(s.get("uses", "").startswith("pypa/cibuildwheel@") for s in steps)


# ---------------------------------------------------------------------------- the installed package
def test_installed_package_computes():
    """Run by cibuildwheel on each wheel (no checkout, no conftest): the compiled modules load and a
    tiny Rips barcode and a mean curvature come out right."""
    import numpy as np

    import thesis_lib
    import thesis_lib._core as core
    from thesis_lib.curvature import mean_curvature
    from thesis_lib.datasets import torus_grid
    from thesis_lib.persistence import rips_persistence
    from thesis_lib.surfaces import torus_mean_curvature_at

    assert re.fullmatch(r"\d+\.\d+\.\d+\S*", thesis_lib.__version__)
    modules = sorted({m.name for m in pkgutil.iter_modules(core.__path__)})
    assert modules, f"no compiled module in {core.__path__}"
    for name in modules:
        importlib.import_module(f"thesis_lib._core.{name}")
    # the unit square: three finite H0 bars at 0.5 (edge 1, values are half-diameters), one H1 bar [0.5, √2/2)
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    barcode = rips_persistence(square, max_dim=2)
    assert np.allclose(barcode.intervals(1), [[0.5, np.sqrt(0.5)]])
    h0 = barcode.intervals(0)
    assert len(h0) == 4 and np.isinf(h0[:, 1]).sum() == 1 and np.allclose(np.sort(h0[:, 1])[:3], 0.5)
    V, F = torus_grid(20)
    H = mean_curvature(V, F)
    assert H.shape == (400,) and np.isfinite(H).all()
    assert np.abs(H - np.abs(torus_mean_curvature_at(V))).max() < 2e-3  # 1.4e-3 at n = 20


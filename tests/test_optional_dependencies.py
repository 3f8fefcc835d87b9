"""The library needs numpy and scipy only; each use adds its extra.

Three checks:

* in a fresh interpreter where every package but the standard library, numpy and scipy is made
  unimportable, ``import thesis_lib`` and every module outside the laboratory's core imports, and
  persistence, homology, curvature, meshes, Morse theory and two-parameter persistence compute;
* there, a plotting function, a mesh function, the PDB reader and the ``thesis-lab`` command raise
  (or print) the ImportError of :func:`thesis_lib._optional.require`, naming the package and the
  extra that installs it;
* statically, no module of thesis_lib imports a package beyond the standard library, numpy and
  scipy when it is imported (not in a function, not under ``TYPE_CHECKING``); optional packages come
  through ``require`` or a lazy import inside the function that needs them.
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
import textwrap
import tomllib
from pathlib import Path

import pytest

import thesis_lib
from thesis_lib._optional import DISTRIBUTIONS, EXTRAS, MissingExtraError, require

PACKAGE = Path(thesis_lib.__file__).parent
ROOT = PACKAGE.parent
SOURCES = sorted(PACKAGE.rglob("*.py"))
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())

#: what a module of thesis_lib may import when it is imported, besides the standard library
LIBRARY = {"numpy", "scipy", "thesis_lib"}
#: the modules that need the [lab] extra to import at all: the laboratory's core (the kernel manager
#: subclasses jupyter_client's); the rest of thesis_lib.lab (results, report, data, ...) needs none
LAB_CORE = {"thesis_lib.lab.execute", "thesis_lib.lab.runner", "thesis_lib.lab.sweep"}


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _eager_statements(body: list[ast.stmt]) -> list[ast.stmt]:
    """The statements run when a module is imported: not in functions, not under ``if TYPE_CHECKING``."""
    out: list[ast.stmt] = []
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        if isinstance(node, ast.If):
            out += _eager_statements(node.orelse if _is_type_checking(node.test) else node.body + node.orelse)
        elif isinstance(node, ast.Try):
            out += _eager_statements(node.body + [s for h in node.handlers for s in h.body] + node.orelse
                                     + node.finalbody)
        elif isinstance(node, (ast.With, ast.For, ast.While)):
            out += _eager_statements(node.body + getattr(node, "orelse", []))
        elif isinstance(node, ast.ClassDef):  # a class body runs at import
            out.append(node)
            out += _eager_statements(node.body)
        else:
            out.append(node)
    return out


def _imported(node: ast.stmt) -> list[str]:
    if isinstance(node, ast.Import):
        return [alias.name for alias in node.names]
    if isinstance(node, ast.ImportFrom) and node.level == 0:
        return [node.module or ""]
    return []


def _requires(tree: ast.AST) -> list[ast.Call]:
    return [node for node in ast.walk(tree) if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
            and node.func.id == "require"]


def eager_imports(path: Path, text: str | None = None, allowed: set[str] = LIBRARY) -> list[str]:
    """``line: module`` for each package beyond the standard library and ``allowed`` that ``path`` (or
    ``text``, read as that file) imports when it is imported, and ``line: require(module)`` for each
    module-level :func:`require` outside the laboratory's core."""
    tree = ast.parse(path.read_text(encoding="utf-8") if text is None else text)
    name = ".".join(path.relative_to(ROOT).with_suffix("").parts)
    found = []
    for node in _eager_statements(tree.body):
        for module in _imported(node):
            top = module.partition(".")[0]
            if top not in sys.stdlib_module_names and top not in allowed:
                found.append(f"{node.lineno}: {module}")
        if not isinstance(node, ast.ClassDef) and name not in LAB_CORE:
            found += [f"{call.lineno}: require({ast.unparse(call.args[0])})" for call in _requires(node)]
    return found


# ---------------------------------------------------------------------------------------------------
# require


def test_extras_of_require_are_those_of_pyproject():
    extras = PYPROJECT["project"]["optional-dependencies"]
    for extra, modules in EXTRAS.items():
        declared = {spec.split(">")[0].split("=")[0].split("<")[0].strip().lower() for spec in extras[extra]}
        assert {DISTRIBUTIONS.get(m, m).lower() for m in modules} == declared, extra


def test_require_returns_the_module():
    pytest.importorskip("matplotlib")
    pyplot = require("matplotlib.pyplot", extra="plot", purpose="plotting")
    assert pyplot.__name__ == "matplotlib.pyplot"
    assert callable(pyplot.subplots)


def test_require_names_the_package_and_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "zmq", None)  # as if pyzmq were not installed
    with pytest.raises(ImportError) as info:
        require("zmq", extra="lab", purpose="encrypted kernel connections")
    assert str(info.value) == ('pyzmq is needed for encrypted kernel connections; install it with: '
                               'pip install "thesis-lab[lab]"')
    assert isinstance(info.value, MissingExtraError) and info.value.extra == "lab" and info.value.name == "zmq"
    assert isinstance(info.value.__cause__, ModuleNotFoundError)


def test_require_of_a_missing_submodule(monkeypatch):
    monkeypatch.setitem(sys.modules, "biotite", None)
    with pytest.raises(MissingExtraError, match=r'^biotite is needed for reading PDB files; install it with: '
                                                r'pip install "thesis-lab\[proteins\]"$'):
        require("biotite.structure.io.pdb", extra="proteins", purpose="reading PDB files")


def test_a_broken_installed_package_is_not_called_missing(monkeypatch, tmp_path):
    # the package is there but one of its own dependencies is not: the extra would not help, so the
    # original error comes through unchanged
    (tmp_path / "tqdm").mkdir()
    (tmp_path / "tqdm" / "__init__.py").write_text("import thesis_lab_no_such_dependency\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    for name in [m for m in sys.modules if m == "tqdm" or m.startswith("tqdm.")]:
        monkeypatch.delitem(sys.modules, name)
    with pytest.raises(ModuleNotFoundError) as info:
        require("tqdm", extra="lab", purpose="progress bars")
    assert not isinstance(info.value, MissingExtraError)
    assert info.value.name == "thesis_lab_no_such_dependency"


def test_require_refuses_a_package_of_another_extra():
    with pytest.raises(ValueError, match="not a package of the \\[plot\\] extra"):
        require("pyvista", extra="plot", purpose="rendering")
    with pytest.raises(ValueError, match="unknown extra 'plots'"):
        require("matplotlib", extra="plots", purpose="plotting")


# ---------------------------------------------------------------------------------------------------
# A fresh interpreter with numpy and scipy only

BLOCKER = """
import importlib.abc, json, sys
ALLOWED = set(sys.stdlib_module_names) | set({allowed!r})
OPTIONAL = set({optional!r})
# what site and .pth files loaded before this (the editable install's finder, ...) stays, but no
# package of an extra
for _name in [m for m in sys.modules if m.partition(".")[0] in OPTIONAL]:
    del sys.modules[_name]
ALLOWED |= {{m.partition(".")[0] for m in sys.modules}}


class _OnlyNumpyAndScipy(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        top = name.partition(".")[0]
        if top not in ALLOWED and not top.startswith("_sysconfigdata_"):  # (the standard library's own)
            raise ModuleNotFoundError(f"No module named {{name!r}} (not installed in this test)", name=name)
        return None


sys.meta_path.insert(0, _OnlyNumpyAndScipy())
"""


def run_bare(code: str) -> subprocess.CompletedProcess:
    """Run ``code`` in a new interpreter in which only the standard library, numpy and scipy import."""
    optional = sorted({m for modules in EXTRAS.values() for m in modules} | {"IPython", "yaml", "gudhi"})
    prelude = BLOCKER.format(allowed=sorted(LIBRARY), optional=optional)
    return subprocess.run([sys.executable, "-c", prelude + textwrap.dedent(code)], cwd=ROOT, capture_output=True,
                          text=True, timeout=900)


def run_bare_json(code: str) -> dict:
    proc = run_bare(code)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return json.loads(proc.stdout.strip().splitlines()[-1])


def test_the_bare_interpreter_has_only_numpy_and_scipy():
    # the harness itself: were the blocker ineffective, every test below would pass for nothing
    out = run_bare_json("""
        import importlib
        status = {}
        for name in ["matplotlib", "pyvista", "pymeshlab", "biotite", "nbformat", "zmq", "dask", "yaml",
                     "IPython", "numpy", "scipy.sparse", "json"]:
            try:
                importlib.import_module(name)
                status[name] = "ok"
            except ModuleNotFoundError:
                status[name] = "missing"
        print(json.dumps(status))
    """)
    assert out == {"matplotlib": "missing", "pyvista": "missing", "pymeshlab": "missing", "biotite": "missing",
                   "nbformat": "missing", "zmq": "missing", "dask": "missing", "yaml": "missing",
                   "IPython": "missing", "numpy": "ok", "scipy.sparse": "ok", "json": "ok"}


def test_every_module_but_the_lab_core_imports_without_extras():
    out = run_bare_json("""
        import importlib, pkgutil
        import thesis_lib
        failed = {}
        names = sorted(m.name for m in pkgutil.walk_packages(thesis_lib.__path__, "thesis_lib."))
        for name in names:
            try:
                importlib.import_module(name)
            except ImportError as error:
                failed[name] = str(error)
        print(json.dumps({"count": len(names), "failed": failed}))
    """)
    assert out["count"] > 80
    lab = 'jupyter_client is needed for running experiments; install it with: pip install "thesis-lab[lab]"'
    assert out["failed"] == dict.fromkeys(sorted(LAB_CORE), lab)


def test_the_mathematics_computes_without_extras():
    out = run_bare_json("""
        import numpy as np
        from thesis_lib.complexes import rips
        from thesis_lib.curvature import angle_defects, mean_curvature
        from thesis_lib.datasets import example_filtration, rp2
        from thesis_lib.homology import homology
        from thesis_lib.meshes import euler_characteristic, sphere_hull, torus_grid
        from thesis_lib.persistence import compute_intervals, persistence, rips_persistence

        square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
        thesis = compute_intervals(example_filtration())
        implicit = rips_persistence(square, max_dim=2)
        explicit = persistence(rips(square, max_dim=2))
        v, f = sphere_hull(n_dims=3, n_points=300, seed=0)
        tv, tf = torus_grid(12)
        print(json.dumps({
            "thesis": [thesis.intervals(d).tolist() for d in (0, 1)],
            "implicit": [implicit.intervals(d).tolist() for d in (0, 1)],
            "explicit_h1": explicit.intervals(1).tolist(),
            "homology_rp2": homology(rp2()),
            "sphere_defects_over_pi": float(angle_defects(v, f).sum() / np.pi),
            "sphere_median_mean_curvature": float(np.median(mean_curvature(v, f))),
            "torus_euler": int(euler_characteristic(tf)),
        }).replace("Infinity", '"inf"'))
    """)
    inf = "inf"
    assert out["thesis"] == [[[0.0, 1.0], [0.0, inf], [1.0, 2.0], [2.0, 3.0]], [[2.0, inf], [3.0, 4.0]]]
    assert out["implicit"] == [[[0.0, 0.5], [0.0, 0.5], [0.0, 0.5], [0.0, inf]], [[0.5, 0.5 ** 0.5]]]
    assert out["explicit_h1"] == [[0.5, 0.5 ** 0.5]]
    assert out["homology_rp2"] == [[1, []], [0, [2]], [0, []]]
    assert out["sphere_defects_over_pi"] == pytest.approx(4.0, abs=1e-9)  # Gauss–Bonnet: 2πχ(S²)
    assert out["sphere_median_mean_curvature"] == pytest.approx(1.0, abs=0.01)  # the unit sphere
    assert out["torus_euler"] == 0


def test_using_an_extra_says_which_to_install():
    out = run_bare_json("""
        import numpy as np
        from thesis_lib.applications import proteins
        from thesis_lib.graphics import style
        from thesis_lib.meshes import sphere_hull, to_pyvista
        from thesis_lib.reconstruction import ball_pivoting
        from thesis_lib.persistence import Barcode, plot_barcode, rips_persistence

        barcode = rips_persistence(np.array([[0.0, 0.0], [1.0, 0.0]]), max_dim=1)
        v, f = sphere_hull(n_dims=3, n_points=60, seed=0)
        calls = {
            "plot_barcode": lambda: plot_barcode(barcode),
            "style.apply": style.apply,
            "to_pyvista": lambda: to_pyvista(v, f),
            "ball_pivoting": lambda: ball_pivoting(v),
            "read_pdb": lambda: proteins.read_pdb("1abc.pdb"),
            "lab.runner": lambda: __import__("thesis_lib.lab.runner"),
        }
        messages = {}
        for name, call in calls.items():
            try:
                call()
                messages[name] = None
            except ImportError as error:
                messages[name] = str(error)
        print(json.dumps({"messages": messages, "colors": style.COLORS["first"], "bars": len(barcode.intervals(0))}))
    """)
    install = ' install it with: pip install "thesis-lab[{}]"'
    assert out["messages"] == {
        "plot_barcode": "matplotlib is needed for plotting barcodes;" + install.format("plot"),
        "style.apply": "matplotlib is needed for the book's figure style;" + install.format("plot"),
        "to_pyvista": "pyvista is needed for mesh files and pyvista meshes;" + install.format("mesh"),
        "ball_pivoting": "pymeshlab is needed for ball pivoting;" + install.format("mesh"),
        "read_pdb": "biotite is needed for reading PDB files;" + install.format("proteins"),
        "lab.runner": "jupyter_client is needed for running experiments;" + install.format("lab"),
    }
    assert out["colors"] == "#c0392b"  # the style's colours need no matplotlib
    assert out["bars"] == 2


def test_a_python_that_has_only_numpy_and_scipy(tmp_path):
    # no blocker: the base interpreter without site-packages (-S), whose path holds numpy, scipy and
    # thesis_lib alone, as after `pip install thesis-lab` into an empty environment
    import numpy
    import scipy

    for module in [numpy, scipy]:
        folder = Path(module.__file__).parent
        for entry in [folder, folder.with_name(folder.name + ".libs")]:  # wheels keep shared libraries beside
            if entry.exists():
                (tmp_path / entry.name).symlink_to(entry)
    # the package's sources, and its compiled core wherever the install put it (an editable install
    # keeps the extension modules in site-packages, beside no source)
    import thesis_lib._core as core

    (tmp_path / "thesis_lib").mkdir()
    for entry in PACKAGE.iterdir():
        if entry.name not in ("_core", "__pycache__"):
            (tmp_path / "thesis_lib" / entry.name).symlink_to(entry)
    (tmp_path / "thesis_lib" / "_core").mkdir()
    for folder in map(Path, core.__path__):
        for entry in folder.iterdir():
            target = tmp_path / "thesis_lib" / "_core" / entry.name
            if entry.suffix in (".py", ".so", ".pyd") and not target.exists():
                target.symlink_to(entry)
    code = textwrap.dedent("""
        import importlib, json, pkgutil, sys
        import numpy as np
        import thesis_lib
        from thesis_lib.persistence import plot_barcode, rips_persistence

        failed = {}
        for name in sorted(m.name for m in pkgutil.walk_packages(thesis_lib.__path__, "thesis_lib.")):
            try:
                importlib.import_module(name)
            except ImportError as error:
                failed[name] = str(error)
        barcode = rips_persistence(np.array([[0.0, 0.0], [3.0, 4.0]]), max_dim=1)
        try:
            plot_barcode(barcode)
            plotted = "plotted"
        except ImportError as error:
            plotted = str(error)
        outside = {m.partition(".")[0] for m in sys.modules} - set(sys.stdlib_module_names)
        print(json.dumps({"failed": failed, "h0": barcode.intervals(0).tolist(), "plot": plotted,
                          "packages": sorted(p for p in outside if not p.startswith("_"))}))
    """)
    env = {"PYTHONPATH": str(tmp_path), "PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "MPLBACKEND": "Agg"}
    proc = subprocess.run([getattr(sys, "_base_executable", sys.executable), "-S", "-c", code], cwd=tmp_path,
                          env=env, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-3000:]
    out = json.loads(proc.stdout.strip().splitlines()[-1].replace("Infinity", '"inf"'))
    lab = 'jupyter_client is needed for running experiments; install it with: pip install "thesis-lab[lab]"'
    assert out["failed"] == dict.fromkeys(sorted(LAB_CORE), lab)
    assert out["h0"] == [[0.0, 2.5], [0.0, "inf"]]
    assert out["plot"] == 'matplotlib is needed for plotting barcodes; install it with: pip install "thesis-lab[plot]"'
    assert set(out["packages"]) <= LIBRARY | {"cython_runtime"}
    assert {"numpy", "scipy", "thesis_lib"} <= set(out["packages"])


@pytest.mark.parametrize("argv, missing", [
    (["run", "torus-curvature"], "jupyter_client is needed for running experiments"),
    (["sweep", "torus-curvature", "-p", "n", "8"], "jupyter_client is needed for running experiments"),
    (["list"], "nbformat is needed for reading experiment notebooks"),
])
def test_the_command_without_the_lab_extra_prints_one_line(argv, missing):
    proc = run_bare(f"""
        from thesis_lib.lab.cli import main
        sys.exit(main({argv!r}))
    """)
    assert proc.returncode == 1
    assert proc.stdout == ""
    assert proc.stderr == f'error: {missing}; install it with: pip install "thesis-lab[lab]"\n'


# ---------------------------------------------------------------------------------------------------
# Statically: what each module imports when it is imported


def test_the_walk_sees_the_package():
    assert len(SOURCES) > 80


@pytest.mark.parametrize("path", SOURCES, ids=[str(p.relative_to(PACKAGE)) for p in SOURCES])
def test_no_optional_package_is_imported_with_the_module(path):
    assert eager_imports(path, allowed=LIBRARY) == []


def test_the_check_catches_a_planted_top_level_import():
    # the rule itself can fail: a real module with `import matplotlib` at its top is reported, as are
    # imports in a class body or a try block and a module-level require; a lazy import inside a
    # function and one under TYPE_CHECKING are not
    path = PACKAGE / "persistence" / "barcode.py"
    real = path.read_text(encoding="utf-8")
    assert eager_imports(path, real) == []
    planted = real.replace("import numpy as np\n", "import matplotlib\nimport numpy as np\n", 1)
    line = planted.splitlines().index("import matplotlib") + 1
    assert eager_imports(path, planted) == [f"{line}: matplotlib"]
    text = textwrap.dedent("""\
        import os
        from typing import TYPE_CHECKING

        import scipy.sparse

        if TYPE_CHECKING:
            import pyvista


        def lazy():
            import biotite


        class Eager:
            from tqdm import tqdm


        try:
            import yaml
        except ImportError:
            pass
        pyplot = require("matplotlib.pyplot", extra="plot", purpose="plotting")
    """)
    assert eager_imports(path, text) == ["15: tqdm", "19: yaml", '22: require(\'matplotlib.pyplot\')']
    assert eager_imports(PACKAGE / "lab" / "execute.py", text) == ["15: tqdm", "19: yaml"]


def test_every_require_names_a_package_of_its_extra():
    calls = 0
    for path in SOURCES:
        for call in _requires(ast.parse(path.read_text(encoding="utf-8"))):
            if path.name == "_optional.py":
                continue
            module = ast.literal_eval(call.args[0])
            keywords = {k.arg: ast.literal_eval(k.value) for k in call.keywords}
            assert set(keywords) == {"extra", "purpose"}, f"{path}:{call.lineno}"
            assert module.partition(".")[0] in EXTRAS[keywords["extra"]], f"{path}:{call.lineno}"
            calls += 1
    assert calls >= 20

"""The compiled core: one extension module per C++ concept, no JIT left, each kernel with its citation.

Every ``src/<name>.cpp`` is built (CMakeLists.txt) into ``thesis_lib._core.<name>``; numba is gone
from the package and its dependencies; each bound kernel's C++ source cites the thesis.
"""

from __future__ import annotations

import ast
import importlib
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

import thesis_lib

ROOT = Path(__file__).resolve().parents[1]
SOURCES = sorted((ROOT / "src").glob("*.cpp"))
PACKAGE = Path(thesis_lib.__file__).parent
JIT_NAMES = {"numba", "llvmlite"}


def test_there_is_a_compiled_core():
    assert len(SOURCES) >= 10


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.stem)
def test_every_source_is_a_module_of_that_name(source):
    module = importlib.import_module(f"thesis_lib._core.{source.stem}")
    assert module.__doc__, f"{source.name}: the module has no docstring (m.doc())"
    text = source.read_text(encoding="utf-8")
    assert f"NB_MODULE({source.stem}," in text
    bound = re.findall(r'\bm\.def\(\s*"(\w+)"', text)
    assert bound, f"{source.name} binds no function"
    for name in bound:
        assert callable(getattr(module, name)), name


def _uncited_kernels(text: str) -> list[str]:
    """The bound kernels (``m.def("name", &thesis::fn, ...)``) whose definition has no ``Thesis:``
    line in the comment block directly above it (helpers such as input checks need none)."""
    lines = text.splitlines()
    missing = []
    for fn in re.findall(r'\bm\.def\(\s*"\w+",\s*&(?:[\w:]+::)?(\w+)', text):
        starts = [i for i, line in enumerate(lines)
                  if re.match(rf"^(?!\s)(?!//)(?:[^;=]*[\s*&])?{fn}\(", line)]
        cited = False
        for i in starts:
            j = i - 1
            while j >= 0 and i - j <= 3 and lines[j] and not lines[j].startswith(("//", "}", "#")) \
                    and not lines[j].endswith((";", "{")):
                j -= 1  # the return type on lines of its own
            while j >= 0 and (lines[j].startswith("//") or lines[j].startswith("template")):
                cited = cited or "Thesis:" in lines[j]
                j -= 1
        if not cited:
            missing.append(fn)
    return missing


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.stem)
def test_every_kernel_cites_the_thesis(source):
    text = source.read_text(encoding="utf-8")
    if source.stem == "threads":  # infrastructure, not a construction of the thesis
        return
    assert "Thesis:" in text, f"{source.name} cites no thesis place"
    assert _uncited_kernels(text) == [], f"{source.name}: bound kernels without a thesis citation"


def test_the_citation_check_can_fail():
    text = ("// The area.\n// Thesis: §3.3.2.\ndouble area(int n) {\n}\n\n// A helper.\nint helper(int k) {\n}\n"
            'NB_MODULE(x, m) {\n    m.def("area", &thesis::area);\n    m.def("helper", &helper);\n}\n')
    assert _uncited_kernels(text) == ["helper"]


def _top_imports(path: Path) -> set[str]:
    names = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            names.add(node.module.split(".")[0])
    return names


def test_no_module_uses_a_jit():
    users = sorted(str(p.relative_to(PACKAGE)) for p in PACKAGE.rglob("*.py") if _top_imports(p) & JIT_NAMES)
    assert users == []
    assert not (PACKAGE / "jit.py").exists()


def test_no_dependency_is_a_jit():
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    everything = meta["dependencies"] + [r for extra in meta["optional-dependencies"].values() for r in extra]
    assert not [r for r in everything if re.split(r"[<>=!~\[ ;]", r)[0].lower() in JIT_NAMES]
    env = (ROOT / "environment.yml").read_text(encoding="utf-8")
    assert not re.search(r"^\s*-\s*(numba|llvmlite)\b", env, re.M)


def test_a_first_call_loads_no_jit_and_no_plotting():
    code = ("import sys, numpy as np; from thesis_lib.persistence import rips_persistence; "
            "bars = rips_persistence(np.random.default_rng(0).normal(size=(30, 2)), max_dim=2); "
            "print(sorted(m for m in ('numba', 'llvmlite', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.strip() == "[]"


def test_the_build_keeps_the_same_bytes_everywhere():
    # the flags that make the compiled numbers independent of the machine (and none that would not)
    text = "\n".join(line.split("#")[0] for line in (ROOT / "CMakeLists.txt").read_text(encoding="utf-8").splitlines())
    assert "-ffp-contract=off" in text and "/fp:precise" in text
    assert not re.search(r"-march=native|-ffast-math|-Ofast|/fp:fast", text)

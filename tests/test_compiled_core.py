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


# --- no kernel function takes more than eight parameters ----------------------------------------------

MAX_PARAMETERS = 8
HEADERS_AND_SOURCES = sorted((ROOT / "src").glob("*.[ch]pp"))
_NOT_FUNCTIONS = {"if", "for", "while", "switch", "return", "catch", "sizeof", "decltype", "alignof", "alignas",
                  "static_assert", "noexcept", "throw", "new", "delete"}
# what may stand between a parameter list and the body or the end of a declaration
_QUALIFIERS = re.compile(r"(?:\s*(?:const|noexcept|override|final|mutable|constexpr|&&|&"
                         r"|->\s*[\w:<>,*& ]+?(?=\s*[{;=])))*\s*")


def _blank(text: str) -> str:
    """The C++ source with its comments, string and character literals and preprocessor lines blanked
    (lines kept, so that positions and line numbers stay)."""
    def spaces(m: re.Match) -> str:
        return re.sub(r"[^\n]", " ", m.group(0))
    text = re.sub(r'//[^\n]*|/\*.*?\*/|R"(\w*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', spaces, text,
                  flags=re.S)
    return re.sub(r"^[ \t]*#[^\n]*(?:\\\n[^\n]*)*", spaces, text, flags=re.M)


def _group_end(text: str, start: int) -> int:
    """The position just past the bracket group that opens at text[start]."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] in "([{":
            depth += 1
        elif text[i] in ")]}":
            depth -= 1
            if depth == 0:
                return i + 1
    return len(text)


def _parameter_count(params: str) -> int:
    """The parameters of a parameter list: its top-level commas plus one (template arguments, default
    values in brackets and function types nest)."""
    if params.strip() in ("", "void"):
        return 0
    depth, count = 0, 1
    for ch in params:
        if ch in "([{<":
            depth += 1
        elif ch in ")]}>":
            depth -= 1
        elif ch == "," and depth == 0:
            count += 1
    return count


def _declaration_scope(text: str) -> list[bool]:
    """For each character of the blanked source, whether it stands at file, namespace or class scope
    (where functions are declared) rather than in a function body or an initializer."""
    scope, stack, head = [], [True], 0
    for i, ch in enumerate(text):
        scope.append(stack[-1])
        if ch == "{":
            before = text[head:i]
            stack.append(bool(re.search(r"\b(namespace|struct|class|union)\b[^()]*$", before))
                         or (stack[-1] and bool(re.search(r"\bextern\s*$", before))))
        elif ch == "}" and len(stack) > 1:
            stack.pop()
        if ch in "{};":
            head = i + 1
    return scope


def _functions(text: str) -> list[tuple[str, int, int]]:
    """(name, line, number of parameters) of every function the C++ source declares or defines (free
    functions, member functions, constructors, operators, and lambdas, named "lambda"): a name at file,
    namespace or class scope, or the ] of a lambda's captures, then a parameter list followed (after
    qualifiers) by a body, ; , = or a constructor's initializers."""
    text = _blank(text)
    scope = _declaration_scope(text)
    found = []
    for m in re.finditer(r"(\boperator\s*(?:\(\s*\)|[^\s(]+)|~?\b[A-Za-z_]\w*|\])\s*\(", text):
        name = m.group(1)
        if name in _NOT_FUNCTIONS:
            continue
        start = m.end() - 1
        end = _group_end(text, start)
        after = text[_QUALIFIERS.match(text, end).end():][:2]
        if name == "]":
            if not after.startswith("{"):
                continue  # a call through a subscript, or new T[n]()
            name = "lambda"
        elif not scope[m.start()] or not after or after[0] not in "{;:=" or after == "::":
            continue  # a call in a body, or an expression
        elif re.search(r"(?<!:)[=,(:]\s*$", text[:m.start()]):
            continue  # an initializer: x = f(...), a member's or base's : m(...), n(...)
        found.append((name, text.count("\n", 0, m.start()) + 1, _parameter_count(text[start + 1:end - 1])))
    return found


def _long_parameter_lists(text: str, limit: int = MAX_PARAMETERS) -> list[str]:
    return [f"{name} ({n} parameters), line {line}" for name, line, n in _functions(text) if n > limit]


@pytest.mark.parametrize("source", HEADERS_AND_SOURCES, ids=lambda p: p.name)
def test_no_function_takes_more_than_eight_parameters(source):
    # parameters that travel together are one struct (the graph's arrays, the options, the output buffers)
    assert _long_parameter_lists(source.read_text(encoding="utf-8")) == []


def test_the_parameter_check_reads_the_real_tree():
    seen = {(path.name, name): n for path in HEADERS_AND_SOURCES
            for name, _, n in _functions(path.read_text(encoding="utf-8"))}
    assert seen[("implicit_rips.cpp", "rips_barcode")] == 6  # In<i64, nb::ndim<1>>: one parameter each
    assert seen[("implicit_rips_graph.hpp", "cofaces")] == 8
    assert seen[("implicit_rips.cpp", "NB_MODULE")] == 2
    assert seen[("implicit_rips_graph.hpp", "binom")] == 2  # a member function
    assert ("implicit_rips.cpp", "lambda") in seen
    assert len(seen) > 100


def test_the_parameter_check_can_fail():
    nine = ", ".join(f"int a{i}" for i in range(9))
    eight = ", ".join(f"In<std::int64_t, nb::ndim<{i}>> a{i}" for i in range(8))
    text = (f"namespace x {{\n// f(a, b, c, d, e, f, g, h, i)\nvoid free_fn({nine}) {{\n"
            f"    g(1, 2, 3, 4, 5, 6, 7, 8, 9);\n    auto l = [&]({nine}) -> int {{ return 0; }};\n"
            f'    const char* s = "h(1, 2, 3, 4, 5, 6, 7, 8, 9) {{";\n}}\n'
            f"int declared({nine});\nstruct S {{\n    explicit S(int k) : v(k, 1, 2, 3, 4, 5, 6, 7, 8) {{}}\n"
            f"    double member({nine}) const;\n    Table t{{0}};\n}};\n"
            f"std::tuple<int, int> fine({eight}) {{\n    return {{}};\n}}\n}}  // namespace x\n")
    assert _long_parameter_lists(text) == ["free_fn (9 parameters), line 3", "lambda (9 parameters), line 5",
                                           "declared (9 parameters), line 8", "member (9 parameters), line 11"]
    assert _long_parameter_lists(text, limit=9) == []


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

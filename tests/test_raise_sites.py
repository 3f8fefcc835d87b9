"""Where the package raises: argument checks live in ``_validate``; elsewhere a ``raise`` is a kernel's
own invariant, the environment (a missing package or file), a condition found while computing (a named
error class such as ``DegenerateInput``), or a re-raise.

Every ``raise`` of the package is sorted into one of these kinds by its exception class.  A plain
``ValueError`` / ``TypeError`` / ``InvalidTypeError`` outside ``_validate`` is an argument check that
has not moved into the validation layer yet: their number, room by room, is written below and the
test fails when it changes, so the count in this file is the count in the code.
"""

from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "thesis_lib"

#: the validation layer: every argument check of the package, one checker per kind of argument
VALIDATION = {"_validate"}

#: a state the code's own logic rules out, or a lookup protocol (a mapping's KeyError)
INVARIANTS = {"AssertionError", "RuntimeError", "ArithmeticError", "KeyError", "NotImplementedError"}

#: the environment: a missing optional package, file or folder, the operating system, the command line
ENVIRONMENT = {"ImportError", "MissingExtraError", "FileNotFoundError", "OSError", "ArgumentTypeError",
               "UsageError", "ClusterError", "Terminated"}

#: argument checks outside the validation layer, room by room (plain ValueError / TypeError)
ARGUMENT_CHECKS_OUTSIDE = {
    "_optional": 2,
    "applications": 51,
    "chapters": 56,
    "compat": 11,
    "complexes": 26,
    "curvature": 67,
    "datasets": 6,
    "graphics": 2,
    "homology": 53,
    "lab": 36,
    "meshes": 29,
    "morse": 58,
    "multiparameter": 26,
    "persistence": 80,
    "reconstruction": 17,
    "surfaces": 12,
}


def named_conditions(sources: dict[str, str]) -> set[str]:
    """The package's own exception classes: subclasses (through any chain) of ValueError."""
    bases = {}
    for text in sources.values():
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.ClassDef):
                bases[node.name] = {ast.unparse(b).rpartition(".")[2] for b in node.bases}
    found, grew = set(), True
    while grew:
        grew = False
        for name, parents in bases.items():
            if name not in found and parents & (found | {"ValueError"}):
                found.add(name)
                grew = True
    return found - {"InvalidTypeError"}


def raised_class(node: ast.Raise) -> str | None:
    """The class a ``raise`` names (``None`` for a bare re-raise; a lowercase name is a re-raise of
    a caught or built exception object)."""
    if node.exc is None:
        return None
    target = node.exc.func if isinstance(node.exc, ast.Call) else node.exc
    name = ast.unparse(target).rpartition(".")[2]
    if not isinstance(node.exc, ast.Call) and name[:1].islower():
        return None
    return name


def kind(room: str, cls: str | None, conditions: set[str]) -> str:
    """One of: validation, invariant, environment, condition, re-raise, argument check."""
    if room in VALIDATION:
        return "validation"
    if cls is None:
        return "re-raise"
    if cls in INVARIANTS:
        return "invariant"
    if cls in ENVIRONMENT:
        return "environment"
    if cls in conditions:
        return "condition"
    return "argument check"


def census(sources: dict[str, str]) -> dict[str, Counter]:
    """``{kind: Counter(room)}`` over every ``raise`` of the modules ``{relative path: source}``."""
    conditions = named_conditions(sources)
    out: dict[str, Counter] = {}
    for rel, text in sources.items():
        room = Path(rel).parts[0].removesuffix(".py")
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Raise):
                out.setdefault(kind(room, raised_class(node), conditions), Counter())[room] += 1
    return out


def package_sources() -> dict[str, str]:
    return {str(p.relative_to(PACKAGE)): p.read_text(encoding="utf-8") for p in sorted(PACKAGE.rglob("*.py"))}


def test_argument_checks_outside_the_validation_layer_are_counted():
    found = census(package_sources()).get("argument check", Counter())
    assert {room: n for room, n in sorted(found.items())} == ARGUMENT_CHECKS_OUTSIDE


def test_the_census_sorts_each_kind():
    sources = {
        "_validate.py": "def check(x):\n    raise ValueError('x')\n",
        "curvature/mean.py": (
            "class NotAManifold(ValueError):\n    pass\n"
            "def f(x):\n"
            "    if x: raise ValueError('an argument check')\n"
            "    if x: raise NotAManifold('found while computing')\n"
            "    if x: raise AssertionError('an invariant')\n"
            "    if x: raise ImportError('a package is missing')\n"
            "    try:\n        pass\n    except KeyError as err:\n        raise err\n"
            "    raise\n"),
    }
    kinds = {k: dict(c) for k, c in census(sources).items()}
    assert kinds == {"validation": {"_validate": 1}, "argument check": {"curvature": 1},
                     "condition": {"curvature": 1}, "invariant": {"curvature": 1},
                     "environment": {"curvature": 1}, "re-raise": {"curvature": 2}}

"""No module of thesis_lib reaches into another module's private names.

What two modules share is promoted to a public name (of an internal module, ``_kernels``,
``_validate``, ... if it is not for users): ``from .x import _name`` and ``x._name`` on another
thesis_lib module are refused.  Attributes of other libraries (``mesh._replace`` of a NamedTuple)
are not concerned.
"""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import pytest

import thesis_lib

PACKAGE = Path(thesis_lib.__file__).parent
SOURCES = sorted(PACKAGE.rglob("*.py"))


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def is_module(name: str) -> bool:
    parent, _, _ = name.rpartition(".")
    spec = importlib.util.find_spec(parent)
    return bool(spec and spec.submodule_search_locations) and importlib.util.find_spec(name) is not None


def reach_ins(path: Path, text: str | None = None) -> list[str]:
    """``line: what`` for every private name of another thesis_lib module used in ``path`` (or in
    ``text``, read as if it were that file)."""
    here = module_name(path)
    package = here if path.name == "__init__.py" else here.rpartition(".")[0]
    tree = ast.parse(path.read_text(encoding="utf-8") if text is None else text)
    modules: set[str] = set()  # local names bound to thesis_lib modules
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            source = importlib.util.resolve_name("." * node.level + (node.module or ""), package) if node.level \
                else node.module or ""
            if not source.startswith("thesis_lib"):
                continue
            for alias in node.names:
                if private(alias.name):
                    found.append(f"{node.lineno}: from {source} import {alias.name}")
                elif is_module(f"{source}.{alias.name}"):
                    modules.add(alias.asname or alias.name)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("thesis_lib") and alias.asname:
                    modules.add(alias.asname)
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and private(node.attr) and isinstance(node.value, ast.Name) \
                and node.value.id in modules:
            found.append(f"{node.lineno}: {node.value.id}.{node.attr}")
    return found


def test_the_walk_sees_the_package():
    assert len(SOURCES) > 80


@pytest.mark.parametrize("path", SOURCES, ids=[str(p.relative_to(PACKAGE)) for p in SOURCES])
def test_no_private_reach_in(path):
    assert reach_ins(path) == []


def test_the_check_catches_a_reach_in():
    # the rule itself can fail: a module importing another's private helper is reported
    text = "from ..complexes.rips import _as_distance_matrix\nfrom ..lab import data\nx = data._manifest\n"
    found = reach_ins(PACKAGE / "persistence" / "probe.py", text)
    assert found == ["1: from thesis_lib.complexes.rips import _as_distance_matrix", "3: data._manifest"]

"""The package's layers: every import of a ``thesis_lib`` module goes down a floor or stays in its room,
and no chain of imports comes back to where it started.

The floors are those that ``CONVENTIONS.md`` draws; imports inside functions count as much as those at
the top of a module (a lazy import is still a dependency).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "thesis_lib"

#: bottom up; a room may import its own modules and the rooms of every floor below its own
FLOORS = (
    ("_core", "_optional", "_validate"),
    ("graphics", "homology"),
    ("complexes", "surfaces"),
    ("meshes",),
    ("datasets", "reconstruction"),
    ("persistence", "curvature"),
    ("morse", "multiparameter", "applications", "compat"),
    ("lab",),
    ("chapters",),
)
FLOOR = {room: level for level, rooms in enumerate(FLOORS) for room in rooms}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def imports(path: Path) -> set[str]:
    """The ``thesis_lib`` modules (or packages) that the file at ``path`` imports, anywhere in it."""
    name = module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                source = ".".join(base + ([node.module] if node.module else []))
            else:
                source = node.module or ""
            for alias in node.names:  # ``from . import x`` imports the module x
                candidate = f"{source}.{alias.name}"
                is_module = (PACKAGE.parent / candidate.replace(".", "/")).with_suffix(".py").is_file() or (
                    PACKAGE.parent / candidate.replace(".", "/") / "__init__.py").is_file()
                found.add(candidate if is_module else source)
        elif isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
    return {m for m in found if m == "thesis_lib" or m.startswith("thesis_lib.")}


GRAPH = {module_name(p): imports(p) for p in sorted(PACKAGE.rglob("*.py"))}


def room(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else None


def test_every_room_has_a_floor():
    rooms = {p.stem if p.is_file() else p.name for p in PACKAGE.iterdir()
             if (p.suffix == ".py" and p.name != "__init__.py") or (p / "__init__.py").is_file()}
    assert rooms == set(FLOOR), f"without a floor: {sorted(rooms - set(FLOOR))}; gone: {sorted(set(FLOOR) - rooms)}"


def upward(graph: dict[str, set[str]], module: str) -> list[str]:
    """The imports of ``module`` that leave its room without going down a floor."""
    own = room(module)
    return sorted(target for target in graph[module]
                  if room(target) is None or (room(target) != own and FLOOR[room(target)] >= FLOOR[own]))


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Tarjan's strongly connected components of more than one module (or a module importing itself)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1 or v in graph.get(v, ()):
                found.append(sorted(component))

    for v in list(graph):
        if v not in index:
            visit(v)
    return found


@pytest.mark.parametrize("module", [m for m in GRAPH if room(m) is not None])
def test_imports_go_down(module):
    assert upward(GRAPH, module) == [], f"{module} (floor {FLOOR[room(module)]}) imports upwards"


def test_no_import_cycle():
    assert cycles(GRAPH) == []


def test_the_checks_see_an_upward_and_a_circular_import():
    """Both checks fail where they should: the figure style importing the mathematics, and a cycle."""
    graph = {m: set(targets) for m, targets in GRAPH.items()}
    graph["thesis_lib.graphics.style"].add("thesis_lib.persistence.barcode")
    assert upward(graph, "thesis_lib.graphics.style") == ["thesis_lib.persistence.barcode"]
    assert "thesis_lib.homology.simplicial" in GRAPH["thesis_lib.homology.groups"]
    graph["thesis_lib.homology.simplicial"].add("thesis_lib.homology.groups")
    assert any({"thesis_lib.homology.groups", "thesis_lib.homology.simplicial"} <= set(c) for c in cycles(graph))

"""Every public function and method of ``thesis_lib`` documents itself the numpy way.

Public: a name without a leading underscore, in a module whose dotted path has none, defined in that
module (re-exports are checked where they are defined).  Each must have

* type hints on every parameter and on the return value;
* a numpydoc ``Parameters`` section naming every parameter (``name : type``), when it takes any;
* a ``Returns`` (or ``Yields``) section, unless it returns ``None``.

The API page (book/api.md) renders these sections through Sphinx's napoleon.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import re

import pytest

import thesis_lib


def public_modules() -> list:
    names = [thesis_lib.__name__] + [
        m.name for m in pkgutil.walk_packages(thesis_lib.__path__, thesis_lib.__name__ + ".")
        if not any(part.startswith("_") for part in m.name.split(".")[1:])
    ]
    return [importlib.import_module(name) for name in sorted(names)]


def public_callables() -> list[tuple[str, object]]:
    """(qualified name, function) for every public function and public method of a public class."""
    out = []
    for module in public_modules():
        for name, obj in vars(module).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != module.__name__:
                continue
            if inspect.isfunction(obj):
                out.append((f"{module.__name__}.{name}", obj))
            elif inspect.isclass(obj):
                for attr, member in vars(obj).items():
                    if attr.startswith("_"):
                        continue
                    if isinstance(member, (staticmethod, classmethod)):
                        member = member.__func__
                    if inspect.isfunction(member):
                        out.append((f"{module.__name__}.{name}.{attr}", member))
    return out


CALLABLES = public_callables()


def section(doc: str, title: str) -> str | None:
    """The body of a numpydoc section (``title`` underlined with dashes), or None."""
    match = re.search(rf"^{title}\n-{{{len(title)}}}\n(.*?)(?=^\S[^\n]*\n-{{3,}}\n|\Z)", doc, re.S | re.M)
    return match.group(1) if match else None


def documented_names(body: str) -> set[str]:
    """Parameter names of a Parameters section: lines ``name : type`` or ``a, b : type`` at the left."""
    names: set[str] = set()
    for line in body.splitlines():
        if line and not line[0].isspace():
            head = line.split(" : ")[0].strip() if " : " in line else line.strip()
            names.update(part.strip().lstrip("*") for part in head.split(","))
    return names


def test_the_public_surface_is_large_enough_to_mean_something():
    # a walk that silently found nothing would pass every test below
    assert len(CALLABLES) > 300


@pytest.mark.parametrize("qualname, func", CALLABLES, ids=[q for q, _ in CALLABLES])
def test_public_callable_is_documented_and_typed(qualname, func):
    doc = inspect.getdoc(func) or ""
    signature = inspect.signature(func)
    params = [p for p in list(signature.parameters.values()) if p.name not in ("self", "cls")]
    problems = []
    missing_hints = [p.name for p in params if p.annotation is inspect.Parameter.empty]
    if missing_hints:
        problems.append(f"parameters without type hints: {missing_hints}")
    if signature.return_annotation is inspect.Signature.empty:
        problems.append("no return type hint")
    if params:
        body = section(doc, "Parameters")
        if body is None:
            problems.append("no Parameters section")
        else:
            undocumented = [p.name for p in params if p.name not in documented_names(body)]
            if undocumented:
                problems.append(f"Parameters section misses {undocumented}")
    returns_none = signature.return_annotation in (None, "None")
    if not returns_none and section(doc, "Returns") is None and section(doc, "Yields") is None:
        problems.append("no Returns section")
    assert not problems, f"{qualname}: " + "; ".join(problems)

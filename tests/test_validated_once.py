"""Every public function parses each of its arguments once: the documented examples of the public API
run with every checker of the validation layer counting what it is handed.

The checkers are the parsers of ``thesis_lib._validate`` and the mesh parser of the curvature
functions (``curvature.validate.validate_mesh``).  Within one call of a public function (nested
public calls included) a checker may see a given array, list or other non-scalar argument once; a
second look at the same object means an inner function
validated again what the outer one had already parsed.  The examples are those of the doctests
(every public name of the main subpackages has one, ``tests/test_doctests.py``); scalars are left
out, since Python shares small numbers and strings between unrelated arguments, and so are the
records of the validation layer (a :class:`~thesis_lib._validate.Points` is parsed: a checker hands
its array back unchecked).
"""

from __future__ import annotations

import doctest
import functools
import importlib
import inspect
import os
import pkgutil
import sys
from pathlib import Path

import numpy as np
import pytest

import thesis_lib
from thesis_lib import _validate
from thesis_lib.curvature.validate import validate_mesh

PACKAGES = ("complexes", "persistence", "homology", "curvature", "surfaces", "morse", "multiparameter",
            "meshes", "reconstruction", "datasets")
CHECKERS = sorted(name for name, f in vars(_validate).items()
                  if inspect.isfunction(f) and f.__module__ == _validate.__name__
                  and name.startswith(("check_", "as_", "parse_")))
PACKAGE_DIR = str(Path(thesis_lib.__file__).resolve().parent) + os.sep
SCALARS = (int, float, complex, str, bytes, bool, type(None), np.generic)


def modules_of(package: str) -> list[str]:
    root = importlib.import_module(f"thesis_lib.{package}")
    names = [root.__name__]
    if hasattr(root, "__path__"):
        names += [m.name for m in pkgutil.walk_packages(root.__path__, root.__name__ + ".")]
    return names


MODULES = [m for p in PACKAGES for m in modules_of(p)
           if not m.rsplit(".", 1)[-1].startswith("_") and not m.endswith("plotting")]


class Ledger:
    """What each checker saw during the outermost public call under way."""

    def __init__(self) -> None:
        self.depth = 0
        self.seen: list[tuple[str, object]] = []
        self.repeats: list[str] = []
        self.call = ""
        self.home: tuple[str, ...] = (PACKAGE_DIR,)  #: the files whose calls belong to the call under way

    def public(self, name: str, function):
        @functools.wraps(function)
        def wrapper(*args, **kwargs):
            # a call from outside the package (the outermost one, or one made by a function the user
            # passed in, such as a parametrisation) is a public call of its own
            outside = not sys._getframe(1).f_code.co_filename.startswith(self.home)
            saved = (self.seen, self.call)
            if self.depth == 0 or outside:
                self.seen, self.call = [], name
            self.depth += 1
            try:
                return function(*args, **kwargs)
            finally:
                self.depth -= 1
                if outside:
                    self.seen, self.call = saved
        return wrapper

    def checker(self, name: str, function):
        @functools.wraps(function)
        def wrapper(*args, **kwargs):
            if self.depth and args and not isinstance(args[0], (*SCALARS, _validate.Points)):
                if any(c == name and obj is args[0] for c, obj in self.seen):
                    self.repeats.append(f"{self.call}: {name} twice on one {type(args[0]).__name__}")
                self.seen.append((name, args[0]))  # kept alive, so its id is not reused
            return function(*args, **kwargs)
        return wrapper


def public_functions() -> dict[int, tuple[str, object]]:
    out = {}
    for package in PACKAGES:
        module = importlib.import_module(f"thesis_lib.{package}")
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name)
            if inspect.isfunction(obj):
                out[id(obj)] = (f"{package}.{name}", obj)
    return out


@pytest.fixture
def ledger(monkeypatch):
    book = Ledger()
    checkers = {id(getattr(_validate, n)): (n, getattr(_validate, n)) for n in CHECKERS}
    checkers[id(validate_mesh)] = ("validate_mesh", validate_mesh)
    public = public_functions()
    for name, module in list(sys.modules.items()):
        if not name.startswith(thesis_lib.__name__ + ".") or module is None:
            continue
        for attr, value in list(vars(module).items()):
            if id(value) in checkers and checkers[id(value)][1] is value:
                monkeypatch.setattr(module, attr, book.checker(*checkers[id(value)]))
            elif id(value) in public and public[id(value)][1] is value:
                monkeypatch.setattr(module, attr, book.public(*public[id(value)]))
    return book


@pytest.mark.parametrize("name", MODULES)
def test_examples_parse_each_argument_once(name, ledger):
    import matplotlib

    matplotlib.use("Agg")
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in finder.find(module, globs=dict(vars(module))):
        runner.run(test, out=lambda _: None)
    assert ledger.repeats == [], sorted(set(ledger.repeats))


def test_the_ledger_sees_a_second_parse(ledger):
    """The check fails where it should: a public function that checks its points and hands the same
    raw array to another public function, which parses it again; handing on the parsed record passes."""
    from thesis_lib.complexes import rips

    def outer(points, *, record: bool):
        if record:
            return rips(_validate.parse_points(points), max_radius=1.0, max_dim=1)
        _validate.as_points(points)
        return rips(points, max_radius=1.0, max_dim=1)

    ledger.home += (__file__,)  # outer stands for a function of the package
    points = np.random.default_rng(0).random((5, 2))
    ledger.public("outer", outer)(points, record=False)
    assert ledger.repeats == ["outer: as_points twice on one ndarray"]
    ledger.repeats.clear()
    ledger.public("outer", outer)(points, record=True)
    assert ledger.repeats == []

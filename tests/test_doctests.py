"""The ``Examples`` of the core subpackages run, and every public name of them has one.

Scope: the public names (each ``__all__``, and the public methods and properties of the classes it
exports) of ``thesis_lib.complexes``, ``thesis_lib.persistence``, ``thesis_lib.homology``,
``thesis_lib.curvature``, ``thesis_lib.surfaces`` (its exact references) and ``thesis_lib.morse``.
Each module that defines one of them, and every other module of those subpackages, has its
doctests run (one test per module, so a failure names its module), and each such name must show
at least one ``>>>`` example.  Plotting examples run on matplotlib's Agg backend.
"""

from __future__ import annotations

import doctest
import importlib
import inspect
import pkgutil

import pytest

PACKAGES = (
    "thesis_lib.complexes",
    "thesis_lib.persistence",
    "thesis_lib.homology",
    "thesis_lib.curvature",
    "thesis_lib.surfaces",
    "thesis_lib.morse",
)


def exported_names(package: str) -> list[str]:
    module = importlib.import_module(package)
    return list(module.__all__)


def public_targets(package: str) -> dict[str, object]:
    """Qualified name -> function, class, method or property getter, for every public name of ``package``."""
    out: dict[str, object] = {}
    module = importlib.import_module(package)
    for name in exported_names(package):
        obj = getattr(module, name)
        if not (inspect.isfunction(obj) or inspect.isclass(obj)):
            continue  # constants (COMPLEXES, AREA_KINDS) are documented where they are defined
        qualname = f"{obj.__module__}.{obj.__qualname__}"
        out[qualname] = obj
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if attr.startswith("_"):
                    continue
                if isinstance(member, (staticmethod, classmethod)):
                    member = member.__func__
                elif isinstance(member, property):
                    member = member.fget
                if inspect.isfunction(member):
                    out[f"{qualname}.{attr}"] = member
    return out


def doctest_modules() -> list[str]:
    """Every module of the five subpackages, and the modules outside them that define a re-export."""
    names = set()
    for package in PACKAGES:
        module = importlib.import_module(package)
        names.add(package)
        if hasattr(module, "__path__"):
            names.update(m.name for m in pkgutil.walk_packages(module.__path__, package + "."))
    names.update(obj.__module__ for obj in TARGETS.values())
    return sorted(names)


PER_PACKAGE = {package: public_targets(package) for package in PACKAGES}
TARGETS = {q: obj for targets in PER_PACKAGE.values() for q, obj in targets.items()}
MODULES = doctest_modules()


def test_the_scope_is_large_enough_to_mean_something():
    # a walk that silently found nothing would pass every test below
    assert len(TARGETS) > 150 and len(MODULES) > 50


@pytest.mark.parametrize("package", PACKAGES)
def test_every_public_name_has_an_example(package):
    missing = sorted(
        q for q, obj in PER_PACKAGE[package].items()
        if ">>>" not in (inspect.getdoc(obj) or "")
    )
    assert not missing, f"{package}: public names without a >>> example: {missing}"


@pytest.mark.parametrize("name", MODULES)
def test_module_examples_run(name):
    try:
        import matplotlib
    except ImportError:  # the plot extra is missing: only the plotting modules need it
        if name.endswith("plotting"):
            pytest.skip("matplotlib is not installed")
        plt = None
    else:
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    module = importlib.import_module(name)
    before = set(plt.get_fignums()) if plt else set()
    result = doctest.testmod(module, verbose=False)
    assert result.failed == 0, f"{name}: {result.failed} of {result.attempted} examples failed (output above)"
    if plt:
        left_open = set(plt.get_fignums()) - before
        plt.close("all")
        assert not left_open, f"{name}: its examples leave {len(left_open)} figure(s) open (plt.close(fig) them)"

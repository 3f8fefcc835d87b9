"""One name per meaning, keyword-only options: the signatures of the public API of ``thesis_lib``.

Public: the names in a package's ``__all__`` and the members of the modules book/api.md documents
(``automodule``), with their public methods.  In each, the data arguments (the inputs the callable is
about: points, vertices and simplices, a filtration, a barcode, a matrix) may be positional; every
parameter after them is keyword-only.

Which parameters are data: by rule, the leading parameters without a default whose name is not an
option word of the vocabulary (``OPTION_WORDS``); ``DATA_ARGUMENTS`` lists the callables where that
rule is wrong, with optional data (``alpha(points, weights=None)``) or a required option that is not
a vocabulary word (``faces_of(simplices, *, k)``), so that making such an option positional again
fails here too.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import pytest

import thesis_lib

ROOT = Path(__file__).resolve().parents[1]

#: options wherever they occur: a parameter so named is never a data argument (records excepted)
OPTION_WORDS = frozenset({
    "max_radius", "max_dim", "coefficients", "seed", "area", "method", "heuristic", "algorithm",
    "landmark_method", "complex", "estimator", "step", "normals", "edge_weights", "neighbour_weights",
    "dim", "dims", "min_length",
})

#: the data arguments where the rule above does not find them (qualified names without "thesis_lib.")
DATA_ARGUMENTS = {
    "applications.proteins.discretise_intervals": ("intervals",),
    "applications.proteins.invisible_bars": ("intervals",),
    "applications.proteins.sample_barcode": ("intervals",),
    "applications.range_images.density_filter": ("X",),
    "applications.range_images.kth_neighbour_distance": ("X",),
    "applications.range_images.range_patch_space": ("images",),
    "applications.range_images.sample_patches": ("images",),
    "complexes.alpha.alpha": ("points", "weights"),
    "complexes.delaunay.delaunay": ("points", "weights"),
    "complexes.factory.choose_landmarks": ("points",),
    "complexes.landmarks.maxmin_landmarks": ("points",),
    "complexes.landmarks.random_landmarks": ("points",),
    "complexes.rips.rips": ("points",),
    "complexes.triangulation.regular_triangulation": ("points", "weights"),
    "datasets.filtrations.module_filtration": ("summands",),
    "datasets.filtrations.named_chain": ("terms",),
    "homology.filtration.Filtration": ("simplices", "values"),
    "lab.bench.scaling_figure": ("topic",),
    "lab.chapters.read_thesis": ("path",),
    "lab.cli.main": ("argv",),
    "lab.data.check_parameter_paths": ("params",),
    "lab.data.manifest": ("manifest_file",),
    "lab.data.verify": ("manifest_file",),
    "lab.experiments.resolve_parameters": ("name", "overrides"),
    "lab.registry.read_tables": ("path",),
    "lab.report.errata_markdown": ("rows",),
    "lab.report.findings": ("rows",),
    "lab.report.headline": ("rows",),
    "lab.report.load_claims": ("directory",),
    "lab.report.markdown": ("rows",),
    "lab.report.report": ("directory",),
    "lab.report.summary": ("rows",),
    "lab.report.summary_markdown": ("rows",),
    "lab.report.to_json": ("rows",),
    "lab.runner.run": ("name", "overrides"),
    "lab.tables.cell": ("value",),
    "lab.tables.labelled_grid": ("values",),
    "lab.tables.markdown_table": ("titles", "rows"),
    "lab.tables.row": ("cells",),
    "reconstruction.pivoting.ball_pivoting": ("points", "normals"),
    "meshes.plotting.render_mesh": ("vertices", "simplices", "scalars"),
    "meshes.topology.faces_of": ("simplices",),
    "morse.plotting.draw_hasse_diagram": ("ax", "simplices", "pairs"),
    "morse.reduction.MorseReduction": ("critical", "values", "boundaries", "n_cells", "coefficients"),
    "morse.vector_field.hasse_diagram": ("simplices", "pairs"),
    "multiparameter.invariants.check_grid": ("values",),
    "persistence.barcode.Barcode.intervals": ("dim",),
    "persistence.barcode.Barcode.longest": ("dim",),
    "persistence.barcode.Barcode.representative": ("dim", "i"),
    "persistence.barcode.Barcode.simplex_pairs": ("dim",),
    "persistence.implicit.rips_persistence": ("points",),
    "persistence.plotting.plot_barcode": ("barcode",),
    "persistence.plotting.plot_diagram": ("barcode",),
    "homology.smith.reduce_checked": ("matrix",),
}

#: callables whose signature another library fixes: scikit-learn's estimator API, jupyter_client's
#: kernel manager, and the drop-in for ripser.py's ``ripser(X, maxdim, thresh, coeff, ...)`` (positional
#: on purpose: existing calls must run unchanged)
PROTOCOL = frozenset(
    [f"persistence.transformer.RipsDiagrams.{m}" for m in ("fit", "transform", "fit_transform", "get_params",
                                                            "set_params")]
    + [f"lab.execute.LabKernelManager.{m}" for m in ("start_kernel", "cleanup_resources")]
    + ["compat.ripser.ripser"]
)

#: names the redesign removed from every public signature: ``kind`` (now ``complex``, ``curvature``,
#: ``area``), ``faces`` (``simplices``), ``eps``/``epsilon`` (``max_radius``, ``step``, ``radii``,
#: ``radius``), ``p`` (``coefficients``, ``corners``), ``nv`` (``n_vertices``)
REMOVED_NAMES = frozenset({"kind", "faces", "eps", "epsilon", "kappa", "p", "nv"})

#: ``method`` says *how* a value is computed, where the ways agree; nowhere else
METHOD_USERS = frozenset({
    "curvature.mean.mean_curvature",
    "curvature.mean.mean_curvature_vector",
    "curvature.stencil.neighbour_grid_mean_curvature",
    "chapters.torus_study.grid_curvature_errors",
    "chapters.torus_study.random_torus_run",
    "morse.vector_field.is_acyclic",
})


def public_modules() -> list[str]:
    """book/api.md's automodules and every package that has an ``__all__``."""
    names = set(re.findall(r"automodule:: (\S+)", (ROOT / "book" / "api.md").read_text(encoding="utf-8")))
    for info in pkgutil.walk_packages(thesis_lib.__path__, "thesis_lib."):
        if info.ispkg and hasattr(importlib.import_module(info.name), "__all__"):
            names.add(info.name)
    return sorted(names)


def has_signature(obj) -> bool:
    try:
        inspect.signature(obj)
    except ValueError:
        return False
    return True


def public_callables() -> dict[str, object]:
    """Qualified name (without ``thesis_lib.``) -> function, class or method, each once."""
    out: dict[str, object] = {}
    for name in public_modules():
        module = importlib.import_module(name)
        names = getattr(module, "__all__", None)
        if names is None:
            names = [n for n, o in vars(module).items() if getattr(o, "__module__", None) == name]
        for attr in names:
            obj = getattr(module, attr)
            if attr.startswith("_") or not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            qualname = f"{obj.__module__}.{obj.__qualname__}".removeprefix("thesis_lib.")
            if has_signature(obj):  # not an exception class that keeps ``Exception(*args)``
                out[qualname] = obj
            if inspect.isclass(obj):
                for method, member in vars(obj).items():
                    if isinstance(member, (staticmethod, classmethod)):
                        member = member.__func__
                    if not method.startswith("_") and inspect.isfunction(member):
                        out[f"{qualname}.{method}"] = member
    return {q: f for q, f in sorted(out.items()) if q not in PROTOCOL}


CALLABLES = public_callables()
POSITIONAL = (inspect.Parameter.POSITIONAL_ONLY, inspect.Parameter.POSITIONAL_OR_KEYWORD)


def parameters(obj) -> list[inspect.Parameter]:
    return [p for p in inspect.signature(obj).parameters.values() if p.name not in ("self", "cls")]


def data_arguments(qualname: str, params: list[inspect.Parameter]) -> tuple[str, ...]:
    """The table's entry, else the leading parameters without a default that are not option words."""
    if qualname in DATA_ARGUMENTS:
        return DATA_ARGUMENTS[qualname]
    data = []
    for p in params:
        if p.kind not in POSITIONAL or p.default is not p.empty or p.name in OPTION_WORDS:
            break
        data.append(p.name)
    return tuple(data)


def positional_options(qualname: str, params: list[inspect.Parameter]) -> list[str]:
    """The parameters after the data arguments that can still be given by position."""
    data = set(data_arguments(qualname, params))
    return [p.name for p in params if p.kind in POSITIONAL and p.name not in data]


def test_the_walk_finds_the_public_api():
    # a walk that found nothing would pass every test below; these are the ones the redesign is about
    assert len(CALLABLES) > 300
    for name in ("complexes.rips.rips", "complexes.cech.cech", "persistence.engine.persistence",
                 "curvature.mean.mean_curvature", "persistence.barcode.Barcode", "lab.results.Recorder"):
        assert name in CALLABLES


@pytest.mark.parametrize("qualname", sorted(DATA_ARGUMENTS))
def test_table_entries_are_leading_parameters_of_a_public_callable(qualname):
    assert qualname in CALLABLES, f"{qualname} is not public (stale entry)"
    names = [p.name for p in parameters(CALLABLES[qualname])]
    data = DATA_ARGUMENTS[qualname]
    assert tuple(names[: len(data)]) == data, f"{qualname}{inspect.signature(CALLABLES[qualname])}"


@pytest.mark.parametrize("qualname", list(CALLABLES))
def test_options_after_the_data_are_keyword_only(qualname):
    params = parameters(CALLABLES[qualname])
    assert positional_options(qualname, params) == [], f"{qualname}{inspect.signature(CALLABLES[qualname])}"


def test_the_check_finds_options_planted_positionally():
    def cech(points, max_radius, max_dim): ...  # the vocabulary words are options
    def faces_of(simplices, k): ...  # a required option the table names
    def sampler(n, radius=1.0, *, seed=0): ...  # a default makes an option
    def alpha(points, weights=None, seed=0): ...  # optional data, then an option
    def rips(points=None, *, max_radius, max_dim=2): ...  # as it should be

    found = {name: positional_options(q, parameters(f)) for name, q, f in [
        ("cech", "complexes.cech.cech", cech), ("faces_of", "meshes.topology.faces_of", faces_of),
        ("sampler", "new.sampler", sampler), ("alpha", "complexes.alpha.alpha", alpha),
        ("rips", "complexes.rips.rips", rips)]}
    assert found == {"cech": ["max_radius", "max_dim"], "faces_of": ["k"], "sampler": ["radius"],
                     "alpha": ["seed"], "rips": []}


@pytest.mark.parametrize("qualname", list(CALLABLES))
def test_no_public_parameter_keeps_a_removed_name(qualname):
    names = {p.name for p in parameters(CALLABLES[qualname])}
    assert not names & REMOVED_NAMES, f"{qualname}{inspect.signature(CALLABLES[qualname])}"


def test_method_names_only_how_a_value_is_computed():
    users = {q for q, f in CALLABLES.items() if "method" in {p.name for p in parameters(f)}}
    assert users == METHOD_USERS


def test_barcode_names_its_field_coefficients():
    from thesis_lib.persistence import Barcode

    bars = Barcode({0: [[0.0, 1.0]]}, coefficients=3)
    assert bars.coefficients == 3 and not hasattr(bars, "p")
    with pytest.raises(TypeError):
        Barcode({0: [[0.0, 1.0]]}, p=3)

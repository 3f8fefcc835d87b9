"""§2.4's claims (the five chapter 2 experiments) name their thesis place, say what their input is
(the notebook's first cell agrees), read results that the stored runs hold, and are what their
status says: the counts that the parameters fix are identities, JPlex's time-out is not compared,
and the notebooks' Markdown typesets its formulas."""

from __future__ import annotations

import json
import math
import re

import nbformat
import pytest
from helpers import claims_of

from thesis_lib.lab import report
from thesis_lib.lab.paths import project_root, shared_dir

#: experiment -> the provenance of its input (the thesis's description rebuilt, its data, a stand-in)
INPUT = {
    "two-circles-landmarks": "reconstructed input",
    "two-circles": "reconstructed input",
    "flat-torus": "reconstructed input",
    "proteins": "thesis data",
    "range-patches": "substitute input",
}
#: the words of the first Markdown cell that say so
INPUT_SENTENCE = {
    "reconstructed input": "**Input: reconstructed.**",
    "thesis data": "**Input: the thesis's data.**",
    "substitute input": "**Input: a substitute.**",
}
PLACE = re.compile(r"^(Figure|Example|Theorem|Lemma|Definition|Eq\.) \d+\.\d+|^§\d+(\.\d+)+")


def thesis_text() -> str:
    return (shared_dir() / "thesis" / report.THESIS_TEXT).read_text()


def stored(name: str) -> dict:
    return json.loads((project_root() / "experiments" / "results" / name / "results.json").read_text())


def notebook(path: str):
    return nbformat.read(project_root() / path, as_version=4)


@pytest.mark.parametrize("name", INPUT)
def test_claims_name_a_thesis_place_that_exists(name):
    text = thesis_text()
    for claim in claims_of(name):
        m = PLACE.match(claim["where"])
        assert m, f"{claim['id']}: place {claim['where']!r} is not numbered as the thesis numbers it"
        place = m.group(0)
        if place.startswith("§"):
            assert re.search(rf"^{re.escape(place[1:])} [A-Z]", text, re.M), f"{claim['id']}: no heading {place}"
        else:
            assert re.search(rf"^\s*{re.escape(place)}[.:]", text, re.M), f"{claim['id']}: {place} not in the thesis"


@pytest.mark.parametrize("name", INPUT)
def test_provenance_agrees_with_the_notebook(name):
    first = notebook(f"experiments/{name}.ipynb").cells[0]
    assert first.cell_type == "markdown"
    assert INPUT_SENTENCE[INPUT[name]] in first.source, f"{name}: the first cell does not say what its input is"
    for claim in claims_of(name):
        if claim["provenance"] != INPUT[name]:
            # a general fact checked on an input of our own (the torus, two circles, the DCT), never counted
            assert claim["provenance"] == "computed", claim["id"]
            assert "by_construction" in claim or claim.get("own_tolerance") is True, claim["id"]


@pytest.mark.parametrize("name", INPUT)
def test_every_result_is_stored_and_no_timing_is(name):
    results = stored(name)
    timings = [k for k in results if re.search(r"seconds|_time|elapsed|timing", k)]
    assert not timings, f"{name}: a timing in results.json: {timings}"
    for claim in claims_of(name):
        refs = claim.get("result", [])
        for ref in refs if isinstance(refs, list) else [refs]:
            experiment, key = ref.split(":", 1)
            assert key in stored(experiment), f"{claim['id']}: {ref} is not in the stored run"


def test_the_substitute_and_the_time_out_are_never_counted():
    for claim in claims_of("range-patches"):
        if claim["provenance"] == "substitute input":
            assert claim["not_reproducible"] is True, claim["id"]
    timed_out = {c["id"]: c for c in claims_of("two-circles")}["fig-2.14-100-timed-out"]
    assert timed_out.get("not_comparable") is True


def test_complete_rips_counts_are_identities():
    """At ε = 2 the stored Rips counts are the complete 2-skeleta: the claims must say so."""
    results = stored("two-circles")
    claims = {c["id"]: c for c in claims_of("two-circles")}
    for n, cid in ((60, "fig-2.14-simplices-60"), (100, "fig-2.14-simplices-100")):
        complete = math.comb(2 * n, 1) + math.comb(2 * n, 2) + math.comb(2 * n, 3)
        assert results[f"n_simplices_{n}"] == complete
        assert "by_construction" in claims[cid] and f"{complete:,}" in claims[cid]["by_construction"]
    # read as JPlex reads R (the diameter), the count depends on the sample and is smaller
    assert results["n_simplices_60_diameter_max_radius"] < results["n_simplices_60"]


def test_witness_comparisons_are_in_one_unit():
    """'Stop earlier' and 'denser sampling' compare simplex counts, never a witness value with a Rips one."""
    results = stored("two-circles")
    for n in (200, 2000):
        assert results[f"witness_stop_size_ratio_{n}"] == pytest.approx(
            results[f"witness_simplices_at_birth_{n}"] / results["rips_simplices_at_birth_60"], rel=1e-9)
        assert results[f"witness_size_ratio_{n}"] == pytest.approx(
            results[f"witness_simplices_{n}"] / results[f"rips_simplices_same_sample_{n}"], rel=1e-9)
    claim = {c["id"]: c for c in claims_of("two-circles")}["fig-2.15-witness-stops-earlier"]
    assert all("stop_size_ratio" in ref for ref in claim["result"])


def test_the_evaluated_statuses():
    rows = {r["id"]: r for r in report.report()}
    mine = [c["id"] for name in INPUT for c in claims_of(name)]
    assert rows["fig-2.14-simplices-60"]["status"] == "identity"
    assert rows["fig-2.14-100-timed-out"]["status"] == "not-comparable"
    for cid in mine:
        row = rows[cid]
        if row["status"] == "reproduced":
            assert not row["by_construction"] and not row["own_tolerance"], cid
        if row["provenance"] == "substitute input":
            assert row["status"] == "not-reproducible", cid


_MATH = re.compile(r"\$[^$]+\$")
_CODE = re.compile(r"`[^`]*`")


@pytest.mark.parametrize("path", ["book/ch2-experiments.ipynb"] + [f"experiments/{n}.ipynb" for n in INPUT])
def test_markdown_typesets_its_formulas(path):
    for cell in notebook(path).cells:
        if cell.cell_type != "markdown":
            continue
        prose = _CODE.sub("", _MATH.sub("", cell.source))
        for raw in ("_{", "^{", "\\"):
            assert raw not in prose, f"{path}: raw {raw!r} outside math in {cell.source[:80]!r}"
        for unicode_math in ("β₀", "β₁", "β₂", "R⁴", "r_c²", "ε²"):
            assert unicode_math not in prose, f"{path}: {unicode_math!r} is not typeset with $…$"


#: the width of the book's text column in CSS pixels (a 1280 px wide window; tests/test_book.py)
COLUMN_PX = 676


def test_figures_on_the_page_have_legible_text():
    """Each stored figure §2.4's page shows: its smallest text (the PNG's tEXt chunk) at the width the
    page shows it (its natural width, at most the column) is at least 9 px."""
    import struct

    from thesis_lib.graphics.style import TEXT_PX_KEY, png_text

    text = "\n".join(c.source for c in notebook("book/ch2-experiments.ipynb").cells if c.cell_type == "markdown")
    paths = re.findall(r"^```\{figure\} (\S+)$", text, re.M)
    assert len(paths) >= 12
    for path in paths:
        png = (project_root() / "book" / path).read_bytes()
        width = struct.unpack(">I", png[16:20])[0]
        assert ":width:" not in text.split(path, 1)[1].split("```", 1)[0], f"{path}: shown at a fixed width"
        px = png_text(png)[TEXT_PX_KEY]
        if px != "none":
            assert float(px) * min(width, COLUMN_PX) / width >= 9.0, f"{path}: text {px} px at {width} px wide"

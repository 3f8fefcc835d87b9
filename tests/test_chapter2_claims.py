"""Chapter 2's claims (experiments/claims/ch2-*.toml and the chapter 2 experiments) carry provenance and a
link to a label that exists on the linked book page; no claim compares an input parameter; the errata
carry their correction and evaluate as errata on the stored results."""

from __future__ import annotations

import pytest
from helpers import claims_of as _claims
from helpers import page_labels

from thesis_lib.lab import report, runner

FILES = ["ch2-complexes", "ch2-persistence", "two-circles-landmarks", "two-circles", "flat-torus", "proteins",
         "range-patches"]
#: the errata of the §2.1–2.3 pages, each with a decisive computed check on its page
PAGE_ERRATA = {"sec-2.1.1-q-vertices-erratum", "ex-2.21-m1-erratum", "sec-2.3.3-alive-erratum",
               "ex-2.40-m1-erratum", "ex-2.41-ce-ed-erratum", "sec-2.3.4-row-order-erratum"}


@pytest.mark.parametrize("name", FILES)
def test_claims_have_provenance_links_and_no_input_parameter(name):
    params = set(runner.experiment_parameters(name)) if name in runner.list_experiments() else set()
    for claim in _claims(name):
        assert claim.get("provenance") in report.PROVENANCES, claim["id"]  # the report's five provenances
        page, _, label = claim["link"].partition("#")
        assert label in page_labels(page), f"{claim['id']}: no label {label!r} on book/{page}.ipynb"
        results = claim.get("result", [])
        for ref in results if isinstance(results, list) else [results]:
            experiment, key = ref.split(":", 1)
            assert experiment != name or key not in params, f"{claim['id']} compares the parameter {key!r} of {name}"


def test_errata_carry_their_correction():
    errata = [c for name in FILES for c in _claims(name) if "correct" in c]
    assert PAGE_ERRATA <= {c["id"] for c in errata}
    for claim in errata:
        assert claim["compare"] == "eq" and claim.get("note", "").startswith("Erratum")
        assert claim.get("corrected", "").strip() and claim.get("check", "").strip(), claim["id"]


def _rows(names):
    ids = {c["id"] for name in names for c in _claims(name)}
    return {row["id"]: row for row in report.report() if row["id"] in ids}


def test_page_claims_evaluate_as_registered():
    rows = _rows(["ch2-complexes", "ch2-persistence"])
    # every erratum of the two pages fails the thesis's value and passes the corrected one
    assert {i for i, r in rows.items() if r["status"] == "erratum"} == PAGE_ERRATA
    # nothing that holds by construction or on a tolerance of ours is counted as reproduced
    for name in ("ch2-complexes", "ch2-persistence"):
        for claim in _claims(name):
            status = rows[claim["id"]]["status"]
            if "by_construction" in claim:
                assert status == "identity", claim["id"]
            elif claim.get("own_tolerance"):
                assert status == "consistent", claim["id"]
            elif claim.get("not_reproducible"):
                assert status == "not-reproducible", claim["id"]
            elif claim["compare"] != "none":
                assert status in ("reproduced", "erratum"), (claim["id"], status)

"""Chapter 2's claims (experiments/claims/ch2-*.toml and the chapter 2 experiments) carry provenance and a
link to a label that exists on the linked book page; no claim compares an input parameter."""

from __future__ import annotations

import pytest
from helpers import check_claim_file
from helpers import claims_of as _claims

FILES = ["ch2-complexes", "ch2-persistence", "two-circles-landmarks", "two-circles", "flat-torus", "proteins",
         "range-patches"]


@pytest.mark.parametrize("name", FILES)
def test_claims_have_provenance_links_and_no_input_parameter(name):
    check_claim_file(name)


def test_errata_carry_their_correction():
    errata = [c for name in FILES for c in _claims(name) if "correct" in c]
    assert {c["id"] for c in errata} == {"ex-2.21-m1-erratum", "ex-2.41-ce-ed-erratum"}
    for claim in errata:
        assert claim["compare"] == "eq" and claim.get("note", "").startswith("Erratum")

"""Chapter 2's claims (experiments/claims/ch2-*.toml and the chapter 2 experiments) carry provenance and a
link to a label that exists on the linked book page; no claim compares an input parameter."""

from __future__ import annotations

import re
import tomllib

import nbformat
import pytest

from thesis_lib.lab import runner
from thesis_lib.lab.paths import repo_root

ROOT = repo_root()
FILES = ["ch2-complexes", "ch2-persistence", "two-circles-landmarks", "two-circles", "flat-torus", "proteins",
         "range-patches"]
PROVENANCE = {"computed", "reconstructed input", "transcribed"}


def _claims(name):
    with open(ROOT / "experiments" / "claims" / f"{name}.toml", "rb") as fh:
        return tomllib.load(fh)["claim"]


def _labels(page: str) -> set[str]:
    nb = nbformat.read(ROOT / "book" / f"{page}.ipynb", as_version=4)
    text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
    return set(re.findall(r"^\(([\w-]+)\)=\s*$", text, re.M)) | set(re.findall(r"^:name:\s*([\w-]+)\s*$", text, re.M))


@pytest.mark.parametrize("name", FILES)
def test_claims_have_provenance_and_resolving_links(name):
    for claim in _claims(name):
        assert claim.get("provenance") in PROVENANCE, claim["id"]
        page, _, label = claim["link"].partition("#")
        assert label in _labels(page), f"{claim['id']}: no label {label!r} on book/{page}.ipynb"


@pytest.mark.parametrize("name", [n for n in FILES if n in runner.list_experiments()])
def test_no_claim_reads_an_input_parameter(name):
    params = set(runner.experiment_parameters(name))
    for claim in _claims(name):
        results = claim["result"] if isinstance(claim["result"], list) else [claim["result"]]
        for ref in results:
            experiment, key = ref.split(":", 1)
            assert key not in params, f"{claim['id']} compares the parameter {key!r} of {experiment}"


def test_errata_carry_their_correction():
    errata = [c for name in FILES for c in _claims(name) if "correct" in c]
    assert {c["id"] for c in errata} == {"ex-2.21-m1-erratum", "ex-2.41-ce-ed-erratum"}
    for claim in errata:
        assert claim["compare"] == "eq" and claim.get("note", "").startswith("Erratum")

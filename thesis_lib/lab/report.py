"""The reproduction report: each numeric claim of the thesis beside what the stored runs measured.

Claims live in ``experiments/claims/*.toml`` as ``[[claim]]`` tables with the keys

``id``, ``where`` (thesis place), ``thesis`` (the thesis's value, as stated), ``result``
(``"<results name>:<key>"`` or a list of them), ``compare`` (``eq``, ``rel``, ``abs``, ``le``, ``ge``,
``between``), its tolerances (``rtol``, ``atol``, ``low``, ``high``), optionally ``value`` (the number
to compare with when ``thesis`` is prose), ``note`` (required unless reproduced) and
``not_reproducible`` (the thesis's input or set-up cannot be had).

The report reads only stored results (``experiments/results/<name>/results.json``), so it works in a
fresh clone without running anything.
"""

from __future__ import annotations

import json
import math
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path

from .paths import repo_root
from .results import load

__all__ = ["Claim", "ClaimError", "load_claims", "evaluate", "report", "markdown"]

STATUSES = ("reproduced", "differs", "erratum", "not-reproducible", "figure-only", "new")
COMPARISONS = ("eq", "rel", "abs", "le", "ge", "between", "none")
PROVENANCES = ("computed", "reconstructed input", "transcribed")
SECTIONS = ("thesis", "beyond")


class ClaimError(ValueError):
    """A claim in the registry is malformed."""


@dataclass(frozen=True)
class Claim:
    """One thesis claim and how our stored result is compared with it."""

    id: str
    where: str
    thesis: object
    result: tuple[str, ...]
    compare: str
    source: str
    value: object = None
    rtol: float = 0.0
    atol: float = 0.0
    low: float | None = None
    high: float | None = None
    note: str = ""
    not_reproducible: bool = False
    provenance: str | None = None
    correct: object = None
    section: str = "thesis"
    link: str | None = None

    def reference(self, ref: object = None) -> list[float]:
        """The numbers the comparison uses, one per result key (``ref``: another reference, e.g. the
        erratum's ``correct``)."""
        if ref is None:
            ref = self.thesis if self.value is None else self.value
        values = ref if isinstance(ref, list) else [ref] * len(self.result)
        if len(values) != len(self.result):
            raise ClaimError(f"claim {self.id}: {len(values)} reference values for {len(self.result)} results")
        return [float(v) for v in values]


def claims_dir() -> Path:
    """Folder of the claim registry."""
    return repo_root() / "experiments" / "claims"


_KEYS = {
    "id", "where", "thesis", "result", "compare", "value", "rtol", "atol", "low", "high", "note",
    "not_reproducible", "provenance", "correct", "section", "link",
}


def _parse(item: dict, source: str) -> Claim:
    unknown = set(item) - _KEYS
    missing = {"id", "where", "thesis", "result", "compare"} - set(item)
    if unknown or missing:
        raise ClaimError(f"{source}: claim {item.get('id', '?')}: unknown keys {sorted(unknown)}, missing {sorted(missing)}")
    result = item["result"]
    result = tuple(result) if isinstance(result, list) else (result,)
    for key in result:
        if ":" not in key:
            raise ClaimError(f"{source}: claim {item['id']}: result {key!r} is not '<results name>:<key>'")
    if item["compare"] not in COMPARISONS:
        raise ClaimError(f"{source}: claim {item['id']}: compare must be one of {COMPARISONS}")
    if item["compare"] == "between" and ("low" not in item or "high" not in item):
        raise ClaimError(f"{source}: claim {item['id']}: 'between' needs low and high")
    if item.get("provenance", PROVENANCES[0]) not in PROVENANCES:
        raise ClaimError(f"{source}: claim {item['id']}: provenance must be one of {PROVENANCES}")
    if item.get("section", "thesis") not in SECTIONS:
        raise ClaimError(f"{source}: claim {item['id']}: section must be one of {SECTIONS}")
    if "correct" in item and item["compare"] in ("between", "none"):
        raise ClaimError(f"{source}: claim {item['id']}: an erratum's 'correct' needs a comparison with a value")
    fields = {k: v for k, v in item.items() if k != "result"}
    return Claim(result=result, source=source, **fields)


def _place(claim: Claim) -> tuple[int, ...]:
    """Sort key: the first thesis number in ``where`` (``Figure 2.14`` → (2, 14); ``§2.2.2`` → (2, 2, 2))."""
    m = re.search(r"\d+(?:\.\d+)*", claim.where)
    return tuple(int(x) for x in m.group(0).split(".")) if m else (99,)


def load_claims(directory: Path | None = None) -> list[Claim]:
    """Every claim of the registry, ordered by thesis place (stable); ids must be unique."""
    claims: list[Claim] = []
    for file in sorted((directory or claims_dir()).glob("*.toml")):
        with open(file, "rb") as fh:
            raw = tomllib.load(fh)
        claims += [_parse(item, file.name) for item in raw.get("claim", [])]
    ids = [c.id for c in claims]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise ClaimError(f"claim ids must be unique; repeated: {sorted(dup)}")
    return sorted(claims, key=_place)


def _ours(claim: Claim, cache: dict[str, dict]) -> list[float] | None:
    values = []
    for ref in claim.result:
        name, key = ref.split(":", 1)
        if name not in cache:
            try:
                cache[name] = load(name)
            except FileNotFoundError:
                cache[name] = {}
        if key not in cache[name]:
            return None
        values.append(float(cache[name][key]))
    return values


def _holds(claim: Claim, ours: list[float], ref: object = None) -> bool:
    if claim.compare == "between":
        return all(claim.low <= o <= claim.high for o in ours)
    checks = []
    for o, t in zip(ours, claim.reference(ref)):
        if math.isnan(o):
            checks.append(False)
        elif claim.compare == "eq":
            checks.append(o == t)
        elif claim.compare == "rel":
            checks.append(abs(o - t) <= claim.rtol * abs(t))
        elif claim.compare == "abs":
            checks.append(abs(o - t) <= claim.atol)
        elif claim.compare == "le":
            checks.append(o <= t)
        else:  # ge
            checks.append(o >= t)
    return all(checks)


def evaluate(claim: Claim, cache: dict[str, dict] | None = None) -> dict[str, object]:
    """The report row of one claim: id, where, thesis, ours, status, note."""
    ours = _ours(claim, {} if cache is None else cache)
    if claim.not_reproducible or ours is None:
        status = "not-reproducible"
    elif claim.section == "beyond":
        status = "new"
    elif claim.compare == "none":
        status = "figure-only"
    elif _holds(claim, ours):
        status = "reproduced"
    elif claim.correct is not None and _holds(claim, ours, claim.correct):
        status = "erratum"
    else:
        status = "differs"
    note = claim.note
    if ours is None and not claim.not_reproducible:
        note = f"no stored result for {', '.join(claim.result)}: run `make experiments`"
    if status != "reproduced" and not note:
        raise ClaimError(f"claim {claim.id} is {status} but has no note saying why")
    shown = None if ours is None else (ours[0] if len(ours) == 1 else ours)
    if isinstance(shown, float) and shown.is_integer():
        shown = int(shown)
    elif isinstance(shown, list):
        shown = [int(v) if float(v).is_integer() else v for v in shown]
    return {"id": claim.id, "where": claim.where, "thesis": claim.thesis, "ours": shown, "status": status, "note": note}


def report(directory: Path | None = None) -> list[dict[str, object]]:
    """Rows of the whole report, one per claim."""
    cache: dict[str, dict] = {}
    return [evaluate(c, cache) for c in load_claims(directory)]


def _fmt(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, list):
        return "(" + ", ".join(_fmt(v) for v in value) + ")"
    return "—" if value is None else str(value)


def markdown(rows: list[dict[str, object]] | None = None) -> str:
    """The report as a Markdown table (what the book's report page shows)."""
    rows = report() if rows is None else rows
    lines = ["| claim | thesis place | thesis | ours | status | note |", "|---|---|---|---|---|---|"]
    for r in rows:
        cells = [r["id"], r["where"], _fmt(r["thesis"]), _fmt(r["ours"]), f"**{r['status']}**", r["note"]]
        lines.append("| " + " | ".join(str(c).replace("|", "\\|") for c in cells) + " |")
    counts = {s: sum(r["status"] == s for r in rows) for s in STATUSES}
    summary = ", ".join(f"{n} {s}" for s, n in counts.items())
    return "\n".join(lines) + f"\n\n{len(rows)} claims: {summary}.\n"


def to_json(rows: list[dict[str, object]] | None = None) -> str:
    """The report as JSON (``thesis-lab report --json``)."""
    return json.dumps(report() if rows is None else rows, indent=1, ensure_ascii=False)

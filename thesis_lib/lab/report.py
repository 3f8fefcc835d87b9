"""The reproduction report: each claim of the thesis beside what the stored runs measured.

Claims live in ``experiments/claims/*.toml`` as ``[[claim]]`` tables (schema in CONVENTIONS.md):
``id``, ``where`` (thesis place), ``thesis`` (the thesis's text or value, as printed), ``result``
(``"<results name>:<key>"`` or a list of them; optional with ``compare = "none"``), ``compare``
(``eq``, ``rel``, ``abs``, ``le``, ``ge``, ``between``, ``none``), its tolerances (``rtol``, ``atol``,
``low``, ``high``), optionally ``value`` (the number compared with when ``thesis`` is prose),
``provenance`` of the input (one of :data:`PROVENANCES`), ``section`` (``thesis`` or ``beyond``),
``link`` (``<book page>#<label>``), ``note`` (required unless reproduced), and for the kinds of
claim that are shown apart ``by_construction`` (why it holds by construction), ``own_tolerance``
(the tolerance is ours), ``not_comparable`` (about another program's run), ``not_reproducible``;
errata have ``correct`` (the corrected value) with ``corrected`` (the corrected statement) and
``check`` (the decisive check).

Statuses are computed, never typed: of claims that could have failed, ``reproduced``, ``erratum``
(fails with the thesis's value, passes with ``correct``) and ``differs``; shown apart, ``identity``
(``by_construction`` and it holds), ``consistent`` (``own_tolerance`` and it holds),
``not-comparable``, ``figure-only`` (``compare = "none"``), ``not-reproducible`` and ``new``
(``section = "beyond"``, reported in its own section).  The report follows the thesis's order: each
claim sits where its place (caption, statement or heading) stands in the thesis text.  It reads
only stored results, so it works in a fresh clone without running anything.
"""

from __future__ import annotations

import functools
import json
import math
import re
from collections import Counter
from collections.abc import Callable
from dataclasses import KW_ONLY, dataclass
from pathlib import Path

from .paths import project_root, shared_dir
from .registry import read_tables
from .results import ResultsError, check_name, load
from .tables import header, markdown_table

__all__ = ["BADGES", "COULD_FAIL", "PROVENANCES", "PROVENANCE_LEGEND", "STATUS_LEGEND", "findings", "Claim",
           "ClaimError", "STATUSES", "compared_as", "errata_markdown", "headline", "load_claims", "evaluate",
           "math_text", "number_text", "report", "summary", "summary_markdown", "markdown", "table_cell", "to_json",
           "place_line", "why", "chapter_tally", "provenance_text"]

#: every status a claim can have, in the report's order (computed, never typed in)
STATUSES = ("reproduced", "erratum", "differs", "identity", "consistent", "not-comparable", "figure-only",
            "not-reproducible", "new")
#: the statuses of claims that could have failed (the report's headline counts these)
COULD_FAIL = ("reproduced", "erratum", "differs")
COMPARISONS = ("eq", "rel", "abs", "le", "ge", "between", "none")
#: the five provenances of a claim's input; PROVENANCE_LEGEND says what each means
PROVENANCES = ("transcribed", "thesis data", "reconstructed input", "substitute input", "computed")
SECTIONS = ("thesis", "beyond")
THESIS_TEXT = "botnan-2011-three-approaches.txt"


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
    _: KW_ONLY
    value: object = None
    correct: object = None
    rtol: float = 0.0
    atol: float = 0.0
    low: float | None = None
    high: float | None = None
    note: str = ""
    not_reproducible: bool = False
    provenance: str | None = None
    section: str = "thesis"
    link: str | None = None
    by_construction: str | None = None
    own_tolerance: bool = False
    not_comparable: bool = False
    corrected: str | None = None
    check: str | None = None

    def reference(self, *, which: str = "thesis") -> list[float]:
        """The numbers the comparison uses, one per result key.

        Parameters
        ----------
        which : str, default "thesis"
            ``"correct"``: the corrected value of an erratum (``correct``); anything else: the
            thesis's value (``value`` when the thesis is prose, else ``thesis``).

        Returns
        -------
        list of float
            One number per result key: the list as given, or the one value repeated.

        Raises
        ------
        ClaimError
            If a list has not one value per result key, or a value is not a number.
        """
        ref = self.correct if which == "correct" else (self.thesis if self.value is None else self.value)
        values = ref if isinstance(ref, list) else [ref] * len(self.result)
        if len(values) != len(self.result):
            raise ClaimError(f"claim {self.id}: {len(values)} reference values for {len(self.result)} results")
        try:
            return [float(v) for v in values]
        except (TypeError, ValueError):
            raise ClaimError(f"claim {self.id}: {which} value {ref!r} is not a number; give `value`") from None


def claims_dir() -> Path:
    """Folder of the claim registry.

    Returns
    -------
    pathlib.Path
        ``experiments/claims/`` of the project folder.
    """
    return project_root() / "experiments" / "claims"


_KEYS = {"id", "where", "thesis", "result", "compare", "value", "correct", "rtol", "atol", "low", "high", "note",
         "not_reproducible", "provenance", "section", "link", "by_construction", "own_tolerance", "not_comparable",
         "corrected", "check"}
_LINK = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_./-]*#[A-Za-z0-9_][A-Za-z0-9_.-]*")


def _check_kind(item: dict, where: str) -> None:
    """The keys that say what kind of claim this is (identity, own tolerance, not comparable, erratum)."""
    if not isinstance(item.get("note", ""), str):
        raise ClaimError(f"{where}: note must be a string, got {item['note']!r}")
    for key in ("by_construction", "corrected", "check"):
        if key in item and (not isinstance(item[key], str) or not item[key].strip()):
            raise ClaimError(f"{where}: {key} must be a non-empty string (one sentence), got {item[key]!r}")
    for key in ("own_tolerance", "not_comparable", "not_reproducible"):
        if key in item and not isinstance(item[key], bool):
            raise ClaimError(f"{where}: {key} must be true or false, got {item[key]!r}")
    compare = item["compare"]
    if item.get("not_comparable"):
        clash = [k for k in ("by_construction", "own_tolerance", "correct", "not_reproducible")
                 if item.get(k) not in (None, False)]
        if clash:
            raise ClaimError(f"{where}: not_comparable (a statement about another program's run) cannot be combined "
                             f"with {', '.join(clash)}")
        if not item.get("note"):
            raise ClaimError(f"{where}: not_comparable needs a note saying what was run and why it is not compared")
    if item.get("own_tolerance"):
        if compare == "none":
            raise ClaimError(f"{where}: own_tolerance needs a comparison with a tolerance or a value, not 'none'")
        need = {"rel": "rtol", "abs": "atol"}.get(compare)
        if need and not item.get(need):
            raise ClaimError(f"{where}: own_tolerance with compare = {compare!r} needs a nonzero {need} (the tolerance "
                             f"of ours)")
    if "by_construction" in item and "correct" in item:
        raise ClaimError(f"{where}: by_construction cannot be an erratum (correct): an erratum needs a computation "
                         f"that could have given the thesis's value")
    if "correct" not in item:
        extra = [k for k in ("corrected", "check") if k in item]
        if extra:
            raise ClaimError(f"{where}: {' and '.join(extra)} only go with an erratum (a claim with correct)")
    else:
        missing = [k for k in ("corrected", "check") if k not in item]
        if missing:
            raise ClaimError(f"{where}: an erratum (correct) needs {' and '.join(missing)}: the corrected statement "
                             f"and the decisive check, one sentence each")


def _parse(item: object, source: str) -> Claim:
    if not isinstance(item, dict):
        raise ClaimError(f"{source}: a [[claim]] must be a table, got {item!r}")
    cid = item.get("id", "?")
    where = f"{source}: claim {cid}"
    unknown = set(item) - _KEYS
    required = {"id", "where", "thesis", "compare"} | ({"result"} if item.get("compare") != "none" else set())
    missing = required - set(item)
    if unknown or missing:
        raise ClaimError(f"{where}: unknown keys {sorted(unknown)}, missing {sorted(missing)}")
    for key in ("id", "where"):
        if not isinstance(item[key], str) or not item[key].strip():
            raise ClaimError(f"{where}: {key} must be a non-empty string")
    result = item.get("result", ())
    result = tuple(result) if isinstance(result, list) else (result,) if result != () else ()
    for key in result:
        if not isinstance(key, str) or ":" not in key:
            raise ClaimError(f"{where}: result {key!r} is not '<results name>:<key>'")
        try:
            check_name(key.split(":", 1)[0])
        except ResultsError as exc:
            raise ClaimError(f"{where}: result {key!r}: {exc}") from None
    if item["compare"] not in COMPARISONS:
        raise ClaimError(f"{where}: compare must be one of {COMPARISONS}")
    if item["compare"] == "between" and ("low" not in item or "high" not in item):
        raise ClaimError(f"{where}: 'between' needs low and high")
    if "correct" in item and item["compare"] in ("between", "none"):
        raise ClaimError(f"{where}: 'correct' needs a comparison with a value (not {item['compare']!r})")
    if item.get("provenance") not in PROVENANCES:
        raise ClaimError(f"{where}: provenance must be one of {PROVENANCES}, got {item.get('provenance')!r} (required)")
    if item.get("section", "thesis") not in SECTIONS:
        raise ClaimError(f"{where}: section must be one of {SECTIONS}, got {item['section']!r}")
    link = item.get("link")
    if "link" in item and (not isinstance(link, str) or not _LINK.fullmatch(link) or ".." in link):
        raise ClaimError(f"{where}: link must be '<book page>#<label>' (like 'ch3-curvature#fig-3-5'), got {link!r}")
    for key in ("rtol", "atol", "low", "high"):
        if key in item and (isinstance(item[key], bool) or not isinstance(item[key], (int, float))):
            raise ClaimError(f"{where}: {key} must be a number, got {item[key]!r}")
    _check_kind(item, where)
    fields = {k: v for k, v in item.items() if k != "result"}
    return Claim(result=result, source=source, **fields)


def load_claims(directory: Path | None = None) -> list[Claim]:
    """Every claim of the registry in the thesis's order (stable); ids must be unique.

    Parameters
    ----------
    directory : pathlib.Path, optional
        Folder of the ``*.toml`` claim files; by default ``experiments/claims/`` (``claims_dir()``).

    Returns
    -------
    list of Claim
        The claims of every file (files by name), sorted stably by :func:`place_line`.

    Raises
    ------
    ClaimError
        If a file is not valid TOML, a claim is malformed (schema in CONVENTIONS.md), or an id repeats.
    """
    claims: list[Claim] = []
    for file in sorted((directory or claims_dir()).glob("*.toml")):
        items = read_tables(file, key="claim", error=ClaimError)
        claims += [_parse(item, file.name) for item in items]
    ids = [c.id for c in claims]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise ClaimError(f"claim ids must be unique; repeated: {sorted(dup)}")
    index = _thesis_index()
    return sorted(claims, key=lambda c: place_line(c.where, index=index))


# ---------------------------------------------------------------------------- thesis order
_DEFINED = re.compile(r"(Figure|Table) (\d+(?:\.\d+)+):|"
                      r"(Example|Theorem|Corollary|Lemma|Definition|Proposition|Remark|Algorithm) (\d+(?:\.\d+)*)[.:]")
_HEADING = re.compile(r"(\d+(?:\.\d+)+) [A-Z]")
_EQUATION = re.compile(r"\((\d+\.\d+)\)\$*\s*$")
_REF = re.compile(r"(Figure|Fig\.|Table|Example|Theorem|Corollary|Lemma|Definition|Proposition|Remark|Algorithm|"
                  r"Eq\.|Equation|§)\s*\(?(\d+(?:\.\d+)*)\)?")
_KINDS = {"Fig.": "Figure", "Eq.": "Eq", "Equation": "Eq"}


#: the thesis's unnumbered parts, each indexed at its heading line
_UNNUMBERED = ("Preface", "Introduction", "Summary")


def _index_text(text: str) -> dict[tuple[str, str], int]:
    """Line of each place defined in the thesis text: captions, statements, headings, equation tags."""
    index: dict[tuple[str, str], int] = {}
    for number, line in enumerate(text.splitlines()):
        line = line.lstrip()  # the text indents some statements and headings by a space
        m = _DEFINED.match(line)
        if m:
            kind, num = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
            index.setdefault((kind, num), number)
        m = _HEADING.match(line)
        if m:
            index.setdefault(("§", m.group(1)), number)
        m = _EQUATION.search(line)
        if m:
            index.setdefault(("Eq", m.group(1)), number)
        if line.strip() in _UNNUMBERED:
            index.setdefault((line.strip(), ""), number)
    return index


@functools.lru_cache(maxsize=4)
def _index_file(path: str, mtime: float) -> dict[tuple[str, str], int]:
    return _index_text(Path(path).read_text(encoding="utf-8", errors="replace"))


def _thesis_index() -> dict[tuple[str, str], int]:
    path = shared_dir() / "thesis" / THESIS_TEXT
    try:
        return _index_file(str(path), path.stat().st_mtime)
    except OSError:
        return {}


def place_line(where: str, *, index: dict[tuple[str, str], int] | None = None) -> tuple[float, ...]:
    """Sort key of a thesis place: the line where its first reference is defined in the thesis text
    (``Figure 3.5`` → its caption, ``Example 2.36`` → its statement, ``§3.4.2`` → its heading), else
    the heading of its section (``Figure 9.1`` → ``9.1``), else its numbers; places with none go last.

    Parameters
    ----------
    where : str
        A claim's thesis place, e.g. ``"Figure 3.5"`` or ``"Example 2.36, §2.4"``.
    index : dict of (str, str) to int, optional
        Line of each defined place, keyed ``(kind, number)``; by default read from the thesis text
        in the shared folder (empty when it is missing).

    Returns
    -------
    tuple of float
        ``(line, 0.0)`` for a place defined in the text, ``(line, 0.5)`` for one placed after the
        nearest place of its kind or at its section's heading, ``(inf, numbers...)`` for a place
        found nowhere, ``(inf, inf)`` for text with no reference.
    """
    index = _thesis_index() if index is None else index
    refs = [(_KINDS.get(k, k), n) for k, n in _REF.findall(where)]
    refs += [(name, "") for name in _UNNUMBERED if name in where]
    for ref in refs:
        if ref in index:
            return (index[ref], 0.0)
    for kind, num in refs:  # not in the text: after the nearest place of its kind before it, or its section
        if not num:
            continue
        key = _numbers(num)
        before = [line for (k, n), line in index.items() if k == kind and n and key[0] == _numbers(n)[0]
                  and _numbers(n) < key]
        if before:
            return (max(before), 0.5)
        parts = num.split(".")
        for k in range(len(parts), 0, -1):
            head = ("§", ".".join(parts[:k]) if k > 1 else f"{parts[0]}.1")
            if head in index:
                return (index[head], 0.5)
    if refs and refs[0][1]:
        return (float("inf"),) + tuple(float(x) for x in refs[0][1].split("."))
    return (float("inf"), float("inf"))


def _numbers(num: str) -> tuple[int, ...]:
    return tuple(int(x) for x in num.split("."))


def _chapter(where: str) -> str:
    m = re.search(r"\d+", where)
    if m:
        return m.group(0)
    if "Summary" in where:
        return "5"
    return "front" if re.match(r"(Preface|Introduction)\b", where) else "other"


# ---------------------------------------------------------------------------- evaluation
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
    return values or None


def _holds(claim: Claim, ours: list[float], reference: list[float] | None) -> bool:
    if claim.compare == "between":
        return all(claim.low <= o <= claim.high for o in ours)
    checks = []
    for o, t in zip(ours, reference):
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


def _status(claim: Claim, ours: list[float] | None) -> str:
    if claim.section == "beyond":
        return "new"
    if claim.not_comparable:
        return "not-comparable"
    if claim.not_reproducible or (ours is None and claim.compare != "none"):
        return "not-reproducible"
    if claim.compare == "none":
        return "figure-only"
    reference = None if claim.compare == "between" else claim.reference()
    if _holds(claim, ours, reference):
        return "identity" if claim.by_construction else "consistent" if claim.own_tolerance else "reproduced"
    if claim.correct is not None and _holds(claim, ours, claim.reference(which="correct")):
        return "erratum"
    return "differs"


# ---------------------------------------------------------------------------- "compared as"
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number_text(x: object) -> str:
    """A number written compactly: integers in full (below 10⁶), four significant digits, and powers
    of ten with Unicode superscripts (``0.004`` → ``4·10⁻³``, ``1e-5`` → ``10⁻⁵``); minus as ``−``.

    Thesis: none (how the report writes numbers).

    Parameters
    ----------
    x : object
        A number (int, float, bool) or anything else, written with ``str``.

    Returns
    -------
    str
        The text: ``nan``, ``∞`` and ``−∞`` for non-finite floats.
    """
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        return str(x)
    x = float(x)
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "∞" if x > 0 else "−∞"
    if x == 0:
        return "0"
    exp = math.floor(math.log10(abs(x)))
    if x.is_integer() and abs(x) < 1e6:
        text = str(int(x))
    elif -3 < exp < 4:
        text = f"{x:.4g}"
    elif 4 <= exp < 6:
        text = str(round(x))
    else:
        mant = f"{x / 10.0 ** exp:.4g}"
        if mant.lstrip("-") == "10":
            mant, exp = mant.replace("10", "1"), exp + 1
        power = "10" + str(exp).translate(_SUPERSCRIPT)
        text = power if mant == "1" else "-" + power if mant == "-1" else f"{mant}·{power}"
    return text.replace("-", "−")


def _values_text(values: list[float]) -> str:
    if len(set(values)) == 1:
        return number_text(values[0])
    return "(" + ", ".join(number_text(v) for v in values) + ")"


def _condition(claim: Claim, values: list[float], *, tolerance: bool = True) -> str:
    v = _values_text(values)
    if claim.compare == "le":
        return f"≤ {v}"
    if claim.compare == "ge":
        return f"≥ {v}"
    if claim.compare == "rel" and tolerance and claim.rtol:
        pct = claim.rtol * 100
        return f"= {v} ± {number_text(pct)} %" if claim.rtol >= 1e-3 else f"= {v} (rel. {number_text(claim.rtol)})"
    if claim.compare == "abs" and tolerance and claim.atol:
        if set(values) == {0.0}:
            return f"within {number_text(claim.atol)} of 0"
        return f"= {v} ± {number_text(claim.atol)}"
    return f"= {v}"


def compared_as(claim: Claim) -> str:
    """How the stored result is compared, as a short formula: ``= 3``, ``≤ 0``, ``≥ 1``,
    ``= 2.329 ± 21 %``, ``within 4·10⁻³ of 0``, ``= 3.142 (rel. 10⁻⁵)``, ``in [a, b]``, ``—`` (nothing).

    Thesis: none (the report's "compared as" column, for the claims of every chapter).

    Parameters
    ----------
    claim : Claim
        The claim.

    Returns
    -------
    str
        The formula.  ``(ours)`` is added when the tolerance or constant is ours (``own_tolerance``);
        an erratum shows both sides, ``= <thesis>; corrected = <correct>`` (the tolerance on the
        corrected side); ``—`` for ``compare = "none"``, for a statement about another program
        (``not_comparable``) and when the claim gives no number.
    """
    if claim.compare == "none" or claim.not_comparable:
        return "—"
    if claim.compare == "between":
        text = f"in [{number_text(claim.low)}, {number_text(claim.high)}]"
    else:
        try:
            thesis = claim.reference()
            if claim.correct is None:
                text = _condition(claim, thesis)
            else:
                corrected = _condition(claim, claim.reference(which="correct"))
                text = f"{_condition(claim, thesis, tolerance=False)}; corrected {corrected}"
        except ClaimError:
            return "—"
    return text + " (ours)" if claim.own_tolerance else text


# ---------------------------------------------------------------------------- rows
def evaluate(claim: Claim, *, cache: dict[str, dict] | None = None) -> dict[str, object]:
    """The report row of one claim.

    Parameters
    ----------
    claim : Claim
        The claim to evaluate.
    cache : dict of str to dict, optional
        Loaded results by results name, filled as results are read (a missing file is stored as
        ``{}``); pass one dict to share it between claims.

    Returns
    -------
    dict of str to object
        The row, with the fields listed in :func:`to_json`.  ``ours`` is the stored value (a list for
        several result keys; integral floats as ints) or None; ``status`` one of ``STATUSES``;
        ``note`` says what to run when no result is stored.

    Raises
    ------
    ClaimError
        If the status is not ``reproduced`` and the claim has no note (an identity's
        ``by_construction`` counts as its note), or a reference value is not a number.
    """
    ours = _ours(claim, {} if cache is None else cache)
    status = _status(claim, ours)
    note = claim.note
    if ours is None and claim.result and not claim.not_reproducible and not claim.not_comparable:
        note = f"no stored result for {', '.join(claim.result)}: run `make experiments`"
    if status not in ("reproduced", "identity") and not note:
        raise ClaimError(f"claim {claim.id} is {status} but has no note saying why")
    shown = None if ours is None else (ours[0] if len(ours) == 1 else ours)
    if isinstance(shown, float) and shown.is_integer():
        shown = int(shown)
    elif isinstance(shown, list):
        shown = [int(v) if float(v).is_integer() else v for v in shown]
    return {"id": claim.id, "where": claim.where, "thesis": claim.thesis, "ours": shown, "status": status,
            "compared_as": compared_as(claim), "note": note, "provenance": claim.provenance,
            "section": claim.section, "link": claim.link, "correct": claim.correct, "corrected": claim.corrected,
            "check": claim.check, "by_construction": claim.by_construction, "own_tolerance": claim.own_tolerance,
            "not_comparable": claim.not_comparable}


def report(directory: Path | None = None) -> list[dict[str, object]]:
    """Rows of the whole report, one per claim, in the thesis's order.

    Parameters
    ----------
    directory : pathlib.Path, optional
        The claim registry to report on, as in :func:`load_claims`.

    Returns
    -------
    list of dict
        One :func:`evaluate` row per claim.

    Raises
    ------
    ClaimError
        If the registry is malformed or a claim that is not reproduced has no note.
    """
    cache: dict[str, dict] = {}
    return [evaluate(c, cache=cache) for c in load_claims(directory)]


# ---------------------------------------------------------------------------- counts
def summary(rows: list[dict[str, object]] | None = None) -> dict[str, object]:
    """Counts of the report.

    Parameters
    ----------
    rows : list of dict, optional
        Report rows (:func:`report`); by default the whole report, from the stored results.

    Returns
    -------
    dict of str to object
        ``total``, ``thesis`` (claims of the thesis), ``could_fail`` (those of them with a status in
        :data:`COULD_FAIL`), ``by_status`` (every status, zeros included), ``thesis_by_status`` (the
        same for the thesis's claims only), ``by_chapter`` (chapter → status → count, thesis section
        only, chapters in numeric order), ``by_provenance`` and ``beyond`` (new work).
    """
    rows = report() if rows is None else rows
    thesis = [r for r in rows if r.get("section", "thesis") == "thesis"]
    by_chapter: dict[str, dict[str, int]] = {}
    for r in thesis:
        counts = by_chapter.setdefault(_chapter(str(r["where"])), {})
        counts[r["status"]] = counts.get(r["status"], 0) + 1
    return {
        "total": len(rows),
        "thesis": len(thesis),
        "could_fail": sum(r["status"] in COULD_FAIL for r in thesis),
        "by_status": {s: sum(r["status"] == s for r in rows) for s in STATUSES},
        "thesis_by_status": {s: sum(r["status"] == s for r in thesis) for s in STATUSES},
        "by_chapter": dict(sorted(by_chapter.items(), key=lambda kv: (kv[0] != "front", not kv[0].isdigit(),
                                                                      kv[0].zfill(3)))),
        "by_provenance": dict(Counter(r["provenance"] for r in rows)),
        "beyond": len(rows) - len(thesis),
    }


def chapter_tally(counts: dict[str, object], chapter: str) -> tuple[int, str]:
    """How many of a chapter's claims the report holds, and their statuses in words.

    Thesis: the checkable statements of the chapter (the reproduction report).

    Parameters
    ----------
    counts : dict
        :func:`summary` of the report.
    chapter : str
        The chapter (``"2"``, ``"3"``, ``"4"``, ``"5"`` or ``"front"``).

    Returns
    -------
    (int, str)
        The number of claims, and ``"n status, m status, ..."`` in the order of :data:`STATUSES`
        (statuses with no claim left out).

    Examples
    --------
    >>> chapter_tally({"by_chapter": {"2": {"reproduced": 3, "differs": 1}}}, "2")
    (4, '3 reproduced, 1 differs')
    >>> chapter_tally({"by_chapter": {}}, "4")
    (0, '')
    """
    n = counts["by_chapter"].get(chapter, {})
    return sum(n.values()), ", ".join(f"{n[s]} {s}" for s in STATUSES if n.get(s))


def _count(n: int, one: str, many: str) -> str:
    return f"{n} {one if n == 1 else many}"


def headline(rows: list[dict[str, object]] | None = None) -> str:
    """The report's headline: the thesis's claims that could have failed, and how they came out,
    then those shown apart (identities, tolerances of ours, other programs' runs, figures, claims
    that cannot be reproduced) and the new work.

    Thesis: none (the reproduction report's headline).

    Parameters
    ----------
    rows : list of dict, optional
        The rows to count, as for :func:`summary`.

    Returns
    -------
    str
        ``"Of N claims of the thesis, K could have failed: R reproduced, E errata, D differ. Shown
        apart: I identities, C consistent within a tolerance of ours, X not comparable, F
        figure-only, U not reproducible."``, plus ``" Beyond the thesis: B new results."`` when
        there is new work.
    """
    s = summary(rows)
    n = s["thesis_by_status"]
    text = (f"Of {_count(s['thesis'], 'claim', 'claims')} of the thesis, {s['could_fail']} could have failed: "
            f"{n['reproduced']} reproduced, {_count(n['erratum'], 'erratum', 'errata')}, "
            f"{n['differs']} {'differs' if n['differs'] == 1 else 'differ'}. "
            f"Shown apart: {_count(n['identity'], 'identity', 'identities')}, {n['consistent']} consistent within a "
            f"tolerance of ours, {n['not-comparable']} not comparable, {n['figure-only']} figure-only, "
            f"{n['not-reproducible']} not reproducible.")
    if s["beyond"]:
        text += f" Beyond the thesis: {_count(s['beyond'], 'new result', 'new results')}."
    return text


def summary_markdown(rows: list[dict[str, object]] | None = None) -> str:
    """The summary as Markdown: the headline, the inputs' provenance, then claims per chapter by status.

    Parameters
    ----------
    rows : list of dict, optional
        The rows to count, as for :func:`summary`.

    Returns
    -------
    str
        The :func:`headline`, a sentence of provenance counts, then (when a chapter has claims) a
        table with one column per status present and the total, ending with a newline.
    """
    rows = report() if rows is None else rows
    s = summary(rows)
    lines = [headline(rows), "", f"Inputs: {provenance_text(s)}."]
    shown = [st for st in STATUSES if st != "new" and any(st in c for c in s["by_chapter"].values())]
    if shown:
        table = [[f"Chapter {ch}" if ch.isdigit() else "Preface, Introduction" if ch == "front" else ch]
                 + [c.get(st, 0) for st in shown] + [sum(c.values())]
                 for ch, c in s["by_chapter"].items()]
        lines += ["", markdown_table(["chapter"] + shown + ["claims"], table).rstrip("\n")]
    return "\n".join(lines) + "\n"


def provenance_text(counts: dict[str, object]) -> str:
    """The claims' inputs counted, in the order of ``PROVENANCES`` (any other after them): ``"40 computed, …"``.

    Thesis: none (the report's page).

    Parameters
    ----------
    counts : dict
        :func:`~thesis_lib.lab.report.summary` of the report.

    Returns
    -------
    str
        The counts of the provenances present, comma-separated.

    Examples
    --------
    >>> provenance_text({"by_provenance": {PROVENANCES[0]: 3}}) == f"3 {PROVENANCES[0]}"
    True
    """
    by = counts["by_provenance"]
    return ", ".join(f"{by[p]} {p}" for p in sorted(by, key=_prov_order) if by[p])


def _prov_order(p: object) -> int:
    return PROVENANCES.index(p) if p in PROVENANCES else len(PROVENANCES)


# ---------------------------------------------------------------------------- Markdown
def _fmt(value: object) -> str:
    if isinstance(value, float):
        return number_text(value)
    if isinstance(value, list):
        return "(" + ", ".join(_fmt(v) for v in value) + ")"
    return "—" if value is None else str(value)


_BRACED = re.compile(r"[_^]\{")


def math_text(text: str) -> str:
    r"""Text with every TeX fragment (a word holding ``_{…}``, ``^{…}`` or a backslash) put in ``$…$``,
    so that rendered Markdown shows no raw ``_{``, ``^{`` or ``\``.

    Thesis: none (a rule of the book: no raw TeX outside math).

    Parameters
    ----------
    text : str
        Prose with formulas in Unicode, perhaps with TeX sub- and superscripts (``Σ_{i ∈ N(q)}``).

    Returns
    -------
    str
        The text, each such fragment wrapped (``$Σ_{i ∈ N(q)}$``); text already holding ``$`` is
        returned unchanged.
    """
    if "$" in text or not (_BRACED.search(text) or "\\" in text):
        return text
    out, i = [], 0
    stop = set(" \t\n([,;:")
    while i < len(text):
        m = _BRACED.search(text, i)
        b = text.find("\\", i)
        start = min(x for x in (m.start() if m else -1, b) if x >= 0) if (m or b >= 0) else -1
        if start < 0:
            out.append(text[i:])
            break
        left = start
        while left > i and text[left - 1] not in stop:
            left -= 1
        right, depth = start, 0
        while right < len(text):  # to the end of the word, braces balanced
            ch = text[right]
            depth += ch == "{"
            depth -= ch == "}"
            if depth <= 0 and (ch in stop or ch in ").") and ch != "}":
                break
            right += 1
        while right > start and text[right - 1] in ",.;:":
            right -= 1
        out += [text[i:left], "$", text[left:right], "$"]
        i = right
    return "".join(out)


def table_cell(value: object) -> str:
    """A report value as the text of one Markdown table cell: numbers as :func:`number_text` writes them,
    lists in parentheses, None as ``—``, TeX fragments in ``$…$`` (:func:`math_text`), ``|`` escaped.
    (A long result key or module name in a note breaks in the book through its style sheet, which
    lets table cells wrap anywhere, so the text itself is left as it reads.)

    Thesis: none (the report's tables).

    Parameters
    ----------
    value : object
        A row's value (thesis, ours, note, ...).

    Returns
    -------
    str
        The cell's text, on one line.
    """
    return math_text(_fmt(value)).replace("|", "\\|").replace("\n", " ")


def why(row: dict[str, object]) -> str:
    """The reason shown with a row: ``By construction: …`` for an identity, the note, and for an
    erratum the corrected statement and the decisive check.

    Thesis: none (the report's tables).

    Parameters
    ----------
    row : dict
        A report row (:func:`evaluate`).

    Returns
    -------
    str
        The sentences, joined by spaces.
    """
    parts = []
    if row.get("by_construction"):
        parts.append(f"By construction: {str(row['by_construction']).rstrip('.')}.")
    if row.get("note"):
        parts.append(str(row["note"]))
    if row.get("status") == "erratum":
        parts += [f"Corrected: {row.get('corrected')}", f"Decisive check: {row.get('check')}"]
    return " ".join(parts)


def _place(row: dict[str, object], link_suffix: str) -> str:
    link = row.get("link")
    if not link:
        return str(row["where"])
    page, label = str(link).split("#", 1)
    return f"[{row['where']}]({page}{link_suffix}#{label})"


def errata_markdown(rows: list[dict[str, object]] | None = None, *,
                    place: Callable[[dict[str, object]], str] | None = None) -> str:
    """The errata as a Markdown table: thesis place, as printed, corrected, decisive check, ours.

    Thesis: the errata of every chapter, each beside its correction.

    Parameters
    ----------
    rows : list of dict, optional
        The rows, as for :func:`summary`; only those with status ``erratum`` are shown.
    place : callable, optional
        Writes a row's thesis place (e.g. as a link); by default its ``where``.

    Returns
    -------
    str
        The table ending with a newline, or ``""`` when there is no erratum.
    """
    rows = report() if rows is None else rows
    place = place or (lambda r: table_cell(r["where"]))
    errata = [r for r in rows if r["status"] == "erratum"]
    if not errata:
        return ""
    lines = ["| thesis place | as printed | corrected | decisive check | ours |", "|---|---|---|---|---|"]
    lines += [f"| {place(r)} | {table_cell(r['thesis'])} | {table_cell(r['corrected'])} | {table_cell(r['check'])} "
              f"| {table_cell(r['ours'])} |" for r in errata]
    return "\n".join(lines) + "\n"


def markdown(rows: list[dict[str, object]] | None = None, *, with_summary: bool = False,
             link_suffix: str = ".html") -> str:
    """The report as Markdown: the thesis's claims in its order, the errata, then new work.

    Parameters
    ----------
    rows : list of dict, optional
        The rows to show, as for :func:`summary`.
    with_summary : bool, default False
        Put :func:`summary_markdown` first.
    link_suffix : str, default ".html"
        Added to a claim's page name: its thesis place links to ``<page><link_suffix>#<label>``.

    Returns
    -------
    str
        The Markdown: the summary when asked, the table of the thesis's claims (columns claim,
        thesis place, thesis, compared as, ours, status, input (provenance), why), a section
        ``Errata`` (table ``tbl-report-errata``) when there are errata, a legend of the inputs'
        provenances, then a section ``Beyond the thesis`` when there is new work.
    """
    rows = report() if rows is None else rows
    titles = ["claim", "thesis place", "thesis", "compared as", "ours", "status", "input", "why"]

    def table(part):
        return "\n".join([header(titles)] + [f"| {r['id']} | {_place(r, link_suffix)} | {table_cell(r['thesis'])} "
                            f"| {table_cell(r.get('compared_as'))} | {table_cell(r['ours'])} | **{r['status']}** "
                            f"| {table_cell(r.get('provenance') or '')} | {table_cell(why(r))} |" for r in part]) + "\n"

    thesis = [r for r in rows if r.get("section", "thesis") == "thesis"]
    beyond = [r for r in rows if r.get("section") == "beyond"]
    parts = [summary_markdown(rows)] if with_summary else []
    parts.append(table(thesis))
    errata = errata_markdown(thesis, place=lambda r: _place(r, link_suffix))
    if errata:
        parts.append("### Errata\n\n(tbl-report-errata)=\n" + errata)
    parts.append("Inputs: " + "; ".join(f"`{p}`: {PROVENANCE_LEGEND[p]}" for p in PROVENANCES) + ".\n")
    if beyond:
        parts.append("### Beyond the thesis\n\n" + table(beyond))
    return "\n".join(parts)


#: the sphinx-design badge of each status (the report page's and the summary page's tables; ``-line``: outlined,
#: for the statuses shown apart)
BADGES = {"reproduced": "success", "erratum": "warning", "differs": "danger", "identity": "success-line",
          "consistent": "primary-line", "not-comparable": "muted-line", "figure-only": "light",
          "not-reproducible": "muted", "new": "primary"}

#: what each status means, one line each (the legend of the report page)
STATUS_LEGEND = {
    "reproduced": "our stored result, from a computation that could have given another answer, passes the "
                  "comparison with the thesis's value",
    "erratum": "the thesis's statement fails and the corrected one passes; the book shows the computation",
    "differs": "our result fails the comparison; the note says why",
    "identity": "the statement holds by construction or by an identity; the comparison is shown, not counted",
    "consistent": "the comparison holds, but its tolerance or constant is ours, not the thesis's",
    "not-comparable": "a statement about another program's run, not about the mathematics",
    "figure-only": "the book draws the figure; nothing is compared",
    "not-reproducible": "the thesis's input or set-up cannot be had",
    "new": "new work beyond the thesis, in its own section, never counted as reproduced",
}

#: what each provenance of a claim's input means (the legend of the report)
PROVENANCE_LEGEND = {
    "transcribed": "the thesis's own example input, typed in from its text",
    "thesis data": "the thesis's own data set (e.g. the PDB structures)",
    "reconstructed input": "an input the thesis describes but does not give, rebuilt from its description",
    "substitute input": "a stand-in for data we cannot have",
    "computed": "a general statement, checked on inputs of our own choosing",
}


def findings(rows: list[dict[str, object]] | None, *, chapter: str) -> str:
    """The thesis's claims of one chapter that are not simply reproduced, as a Markdown table.

    Parameters
    ----------
    rows : list of dict or None
        The evaluated claims (:func:`report`); None evaluates them.
    chapter : str
        The chapter number, ``"2"`` .. ``"4"`` (``"5"`` for the Summary), as the claims' places say.

    Returns
    -------
    str
        Columns thesis place, thesis (as printed, then the test it is compared as), ours, status (a
        badge, :data:`BADGES`) and why
        (:func:`why`: the note, and for an erratum the corrected statement and the decisive check);
        a sentence instead when every claim of the chapter is reproduced.
    """
    rows = report() if rows is None else rows
    shown = [r for r in rows if r.get("section", "thesis") == "thesis" and _chapter(str(r["where"])) == chapter
             and r["status"] != "reproduced"]
    if not shown:
        return "Every claim of this chapter is reproduced."
    lines = ["| thesis place | thesis — compared as | ours | status | why |", "|---|---|---|---|---|"]
    for r in shown:
        test = r.get("compared_as") or "—"
        thesis = table_cell(r["thesis"]) + ("" if test == "—" else f" — *compared as* {table_cell(test)}")
        lines.append(f"| {table_cell(r['where'])} | {thesis} | {table_cell(r['ours'])} "
                     f"| {{bdg-{BADGES[str(r['status'])]}}}`{r['status']}` | {table_cell(why(r))} |")
    return "\n".join(lines) + "\n"


def _finite(value: object) -> object:
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else "inf" if value > 0 else "-inf"
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


def to_json(rows: list[dict[str, object]] | None = None) -> str:
    """The report as JSON (``thesis-lab report --json``), always valid JSON.

    Each row has the fields ``id``, ``where`` (thesis place), ``thesis`` (as printed: number, list
    or text), ``ours`` (the stored result: number, list or null), ``status`` (one of
    :data:`STATUSES`), ``compared_as`` (:func:`compared_as`), ``note``, ``provenance`` (one of
    :data:`PROVENANCES`), ``section`` (``thesis`` or ``beyond``), ``link`` (``<page>#<label>`` or
    null), ``correct`` (an erratum's corrected value, else null), ``corrected`` and ``check`` (an
    erratum's corrected statement and decisive check, else null), ``by_construction`` (why the
    statement holds by construction, else null), ``own_tolerance`` and ``not_comparable`` (true or
    false).

    Parameters
    ----------
    rows : list of dict, optional
        What to write; by default the whole report, from the stored results.

    Returns
    -------
    str
        The rows as a JSON list (indent 1, non-ASCII characters kept).  A non-finite float (a NaN
        result, an infinite tolerance) is written as the string ``"nan"``, ``"inf"`` or ``"-inf"``:
        JSON has no such numbers, and ``NaN`` or ``Infinity`` would make the file unreadable by
        strict parsers.
    """
    return json.dumps(_finite(report() if rows is None else rows), indent=1, ensure_ascii=False, allow_nan=False)

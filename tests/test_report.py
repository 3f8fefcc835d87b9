"""The reproduction report: registry format, comparisons, statuses and notes, JSON output."""

from __future__ import annotations

import json

import pytest

from thesis_lib.lab import cli, report
from thesis_lib.lab.paths import shared_dir
from thesis_lib.lab.report import ClaimError

ROW_FIELDS = {"id", "where", "thesis", "ours", "status", "compared_as", "note", "provenance", "section", "link",
              "correct", "corrected", "check", "by_construction", "own_tolerance", "not_comparable"}


def strict_json(text: str):
    """json.loads that refuses NaN and Infinity (which Python's json accepts by default)."""
    return json.loads(text, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))


def test_registry_is_well_formed_and_complete():
    rows = report.report()
    assert rows, "the registry has no claims"
    for row in rows:
        assert set(row) == ROW_FIELDS
        assert row["status"] in report.STATUSES
        assert row["provenance"] in report.PROVENANCES
        if row["status"] not in ("reproduced", "identity"):
            assert row["note"], row
        if row["status"] == "erratum":
            assert row["corrected"] and row["check"] and "; corrected " in row["compared_as"], row
        if row["ours"] is None:
            # nothing measured, or a figure to compare by eye
            assert row["status"] in ("not-reproducible", "figure-only")
            assert not row["note"].startswith("no stored result"), f"claim {row['id']} has no stored result"


def test_cli_json_matches_the_library(capsys):
    assert cli.main(["report", "--json"]) == 0
    out = capsys.readouterr().out
    assert strict_json(out) == strict_json(report.to_json(report.report()))
    assert [r["id"] for r in strict_json(out)] == [r["id"] for r in report.report()]
    assert '"where": "§' in out  # thesis places stay readable (no \\u escapes)


def test_cli_prints_the_summary_first_then_the_table(capsys):
    assert cli.main(["report"]) == 0
    out = capsys.readouterr().out
    thesis = [r for r in report.report() if r["section"] == "thesis"]
    assert out.startswith(f"Of {len(thesis)} claims of the thesis, ")
    assert "\n| claim | thesis place | thesis | compared as | ours | status | input | why |\n" in out


@pytest.fixture
def registry(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_SHARED", str(shared_dir()))  # the thesis text orders the report
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    (tmp_path / "experiments" / "claims").mkdir(parents=True)
    res = tmp_path / "experiments" / "results" / "exp"
    res.mkdir(parents=True)
    (res / "results.json").write_text(json.dumps({"count": 288100, "err": 0.003, "b1": 3, "b2": 1, "coef": 0.1041667}))

    def write(text: str):
        (tmp_path / "experiments" / "claims" / "t.toml").write_text(text)
        return report.report()

    return write


ERRATUM = {"corrected": "the coefficient is 5/48", "check": "the volume of the cut simplex is 1/8 − 1/48"}


def _claim(**kw) -> str:
    base = {"id": "c", "where": "Figure 2.14", "thesis": 290000, "result": "exp:count", "compare": "rel",
            "provenance": "computed"}
    base.update(kw)
    return "[[claim]]\n" + "\n".join(f"{k} = {json.dumps(v)}" for k, v in base.items()) + "\n"


@pytest.mark.parametrize(
    "kw, status",
    [
        ({"rtol": 0.01}, "reproduced"),
        ({"rtol": 0.001, "note": "exact count is 288100"}, "differs"),
        ({"compare": "eq", "thesis": 288100}, "reproduced"),
        ({"compare": "le", "thesis": 0.004, "result": "exp:err"}, "reproduced"),
        ({"compare": "ge", "thesis": 0.004, "result": "exp:err", "note": "too small"}, "differs"),
        ({"compare": "abs", "thesis": 0.0, "atol": 0.01, "result": "exp:err"}, "reproduced"),
        ({"compare": "between", "thesis": "(2e-5, 1.4e-4)", "low": 2e-5, "high": 1.4e-4, "result": "exp:err",
          "note": "n"}, "differs"),
        ({"compare": "eq", "thesis": [3, 1], "result": ["exp:b1", "exp:b2"]}, "reproduced"),
        ({"compare": "eq", "thesis": "β = (3, 2)", "value": [3, 2], "result": ["exp:b1", "exp:b2"], "note": "β₂"},
         "differs"),
        ({"not_reproducible": True, "note": "data unavailable"}, "not-reproducible"),
        # errata: passes with `correct`, fails with the thesis's value
        ({"compare": "abs", "atol": 1e-6, "thesis": 1 / 12, "correct": 5 / 48, "result": "exp:coef", "note": "5/48",
          **ERRATUM}, "erratum"),
        # passes with the thesis's value: reproduced, even with a `correct`
        ({"compare": "abs", "atol": 0.1, "thesis": 1 / 12, "correct": 5 / 48, "result": "exp:coef", **ERRATUM},
         "reproduced"),
        # passes with neither: differs
        ({"compare": "abs", "atol": 1e-6, "thesis": 1 / 12, "correct": 0.5, "result": "exp:coef", "note": "n",
          **ERRATUM}, "differs"),
        ({"compare": "eq", "thesis": "β = (3, 2)", "value": [3, 2], "correct": [3, 1], "result": ["exp:b1", "exp:b2"],
          "note": "β₂ = 1", **ERRATUM}, "erratum"),
        # by construction: identity when it holds, differs when not; never reproduced
        ({"compare": "eq", "thesis": 288100, "by_construction": "the count is fixed by the parameters"}, "identity"),
        ({"compare": "eq", "thesis": 290000, "by_construction": "fixed by the parameters", "note": "off"}, "differs"),
        # a tolerance of ours: consistent when it holds, differs when not
        ({"compare": "abs", "thesis": 0.0, "atol": 0.004, "result": "exp:err", "own_tolerance": True,
          "note": "the thesis gives no number"}, "consistent"),
        ({"compare": "abs", "thesis": 0.0, "atol": 0.001, "result": "exp:err", "own_tolerance": True,
          "note": "the thesis gives no number"}, "differs"),
        # another program's run: not comparable, whatever the numbers say
        ({"rtol": 0.01, "not_comparable": True, "note": "jPlex ran out of time in 2011"}, "not-comparable"),
        ({"compare": "none", "not_comparable": True, "note": "jPlex ran out of time"}, "not-comparable"),
        ({"section": "beyond", "rtol": 0.01, "by_construction": "x", "note": "new work"}, "new"),
        ({"compare": "none", "thesis": "the figure", "note": "shown in the book"}, "figure-only"),
        ({"compare": "none", "thesis": "the figure", "result": "exp:count", "note": "shown"}, "figure-only"),
        ({"section": "beyond", "rtol": 0.01, "note": "new work"}, "new"),
        ({"section": "beyond", "rtol": 0.0, "note": "new work, never reproduced"}, "new"),
    ],
)
def test_comparisons_give_the_right_status(registry, kw, status):
    assert registry(_claim(**kw))[0]["status"] == status


def test_a_claim_that_is_not_reproduced_needs_a_note(registry):
    with pytest.raises(ClaimError, match="has no note"):
        registry(_claim(rtol=0.0001))


def test_missing_results_are_reported_not_hidden(registry):
    row = registry(_claim(result="exp:nothing", rtol=0.1))[0]
    assert row["status"] == "not-reproducible" and "no stored result" in row["note"]


@pytest.mark.parametrize(
    "text, message",
    [
        (_claim(compare="approx"), "compare must be one of"),
        (_claim(result="count"), "is not '<results name>:<key>'"),
        (_claim(colour="red"), "unknown keys"),
        (_claim(compare="between"), "needs low and high"),
        (_claim(rtol=0.1) + _claim(rtol=0.1), "repeated"),
        (_claim(provenance="guessed"), "provenance must be one of"),
        (_claim(section="elsewhere"), "section must be one of"),
        (_claim(link="https://x.org/page"), "link must be"),
        (_claim(link="../ch2#x"), "link must be"),
        (_claim(compare="between", low=0, high=1, correct=0.5, **ERRATUM), "'correct' needs a comparison"),
        (_claim(result="../../etc:passwd"), "invalid experiment name"),
        (_claim(rtol="big"), "rtol must be a number"),
        ("[[claim]\nid = 'x'", "is not valid TOML"),
        ("claim = 3", "must be an array of tables"),
        (_claim(compare="eq", thesis="prose", note="n"), "is not a number; give `value`"),
    ],
)
def test_malformed_claims_are_refused(registry, text, message):
    with pytest.raises(ClaimError, match=message):
        registry(text)


def test_report_is_ordered_by_thesis_place(registry):
    text = _claim(id="late", where="Figure 3.5", rtol=0.1) + _claim(id="early", where="§2.2.2", rtol=0.1)
    text += _claim(id="mid", where="Example 2.21", rtol=0.1)
    assert [r["id"] for r in registry(text)] == ["mid", "early", "late"]  # Example 2.21 stands in §2.2.1


def test_examples_and_figures_interleave_as_in_the_thesis(registry):
    """Figure 2.10's caption stands before Example 2.36's statement in the text, Theorem 3.18 before
    Corollary 3.19, Figure 3.5 (§3.4.1) before §3.4.2; a figure missing from the text falls back to its section."""
    places = ["Corollary 3.19", "Example 2.36", "§3.4.2", "Figure 2.10", "Theorem 3.18", "Figure 3.5, §3.4.1",
              "Eq. 3.24", "Summary", "Figure 3.99"]
    text = "".join(_claim(id=f"c{i}", where=w, rtol=0.1) for i, w in enumerate(places))
    order = [r["where"] for r in registry(text)]
    assert order == ["Figure 2.10", "Example 2.36", "Theorem 3.18", "Corollary 3.19", "Eq. 3.24", "Figure 3.5, §3.4.1",
                     "§3.4.2", "Figure 3.99", "Summary"]
    lines = report._thesis_index()
    assert lines[("Figure", "3.5")] < lines[("§", "3.4.2")] < lines[("Summary", "")]


def test_preface_and_introduction_stand_before_chapter_2(registry):
    """The unnumbered parts sort at their headings: Preface, Introduction, then the chapters, Summary last."""
    places = ["Summary", "Example 2.21", "Introduction", "Preface"]
    text = "".join(_claim(id=f"c{i}", where=w, rtol=0.1) for i, w in enumerate(places))
    assert [r["where"] for r in registry(text)] == ["Preface", "Introduction", "Example 2.21", "Summary"]


def test_order_falls_back_to_numbers_without_the_thesis_text(registry, monkeypatch, tmp_path):
    monkeypatch.setenv("THESIS_LAB_SHARED", str(tmp_path / "no-shared"))
    text = _claim(id="b", where="Figure 3.5", rtol=0.1) + _claim(id="a", where="Example 2.36", rtol=0.1)
    text += _claim(id="c", where="somewhere", rtol=0.1)
    assert [r["id"] for r in registry(text)] == ["a", "b", "c"]


def test_rows_carry_provenance_section_link_and_correct(registry):
    rows = registry(_claim(rtol=0.1, provenance="computed", link="ch2-experiments#fig-2-14")
                    + _claim(id="n", section="beyond", rtol=0.1, note="new", provenance="reconstructed input"))
    assert rows[0]["provenance"] == "computed" and rows[0]["link"] == "ch2-experiments#fig-2-14"
    assert rows[1]["section"] == "beyond" and rows[0]["correct"] is None
    md = report.markdown(rows)
    assert "[Figure 2.14](ch2-experiments.html#fig-2-14)" in md
    thesis_part, beyond_part = md.split("### Beyond the thesis")
    assert "| c |" in thesis_part and "| n |" in beyond_part and "**new**" in beyond_part


def test_summary_counts_by_status_chapter_and_provenance(registry):
    text = (_claim(id="a", rtol=0.1, provenance="computed")
            + _claim(id="b", where="Figure 3.5", rtol=0, note="x", provenance="reconstructed input")
            + _claim(id="c", where="Example 4.43", compare="none", note="fig", provenance="transcribed")
            + _claim(id="d", section="beyond", rtol=0.1, note="new", provenance="reconstructed input"))
    s = report.summary(registry(text))
    assert s["total"] == 4 and s["beyond"] == 1
    assert s["by_status"] == {"reproduced": 1, "erratum": 0, "differs": 1, "identity": 0, "consistent": 0,
                              "not-comparable": 0, "figure-only": 1, "not-reproducible": 0, "new": 1}
    assert s["by_chapter"] == {"2": {"reproduced": 1}, "3": {"differs": 1}, "4": {"figure-only": 1}}
    assert s["by_provenance"] == {"computed": 1, "reconstructed input": 2, "transcribed": 1}
    assert report.summary_markdown(registry(text)).startswith(
        "Of 3 claims of the thesis, 2 could have failed: 1 reproduced, 0 errata, 1 differs. Shown apart: 0 identities, "
        "0 consistent within a tolerance of ours, 0 not comparable, 1 figure-only, 0 not reproducible. "
        "Beyond the thesis: 1 new result.\n\n"
        "Inputs: 1 transcribed, 2 reconstructed input, 1 computed.\n")


def test_corrupt_results_and_claims_give_clear_errors(registry, tmp_path, capsys):
    """A truncated results.json gives `report` a ResultsError naming the file, not a raw JSONDecodeError."""
    (tmp_path / "experiments" / "results" / "exp" / "results.json").write_text('{"count": 2881')
    from thesis_lib.lab.results import ResultsError

    with pytest.raises(ResultsError, match="is not valid JSON"):
        registry(_claim(rtol=0.1))
    assert cli.main(["report"]) == 2
    assert "is not valid JSON" in capsys.readouterr().err
    (tmp_path / "experiments" / "claims" / "t.toml").write_text("[[claim]\n")
    assert cli.main(["report", "--json"]) == 2
    assert "t.toml is not valid TOML" in capsys.readouterr().err


def test_findings_list_what_is_not_reproduced_with_badges():
    from thesis_lib.lab.report import findings

    rows = [
        {"section": "thesis", "where": "Example 2.36", "status": "differs", "thesis": 1.0, "ours": [2.0, 3.5],
         "note": "a | b\nc"},
        {"section": "thesis", "where": "Figure 2.13", "status": "reproduced", "thesis": 3, "ours": 3, "note": ""},
        {"section": "beyond", "where": "§2.4", "status": "new", "thesis": None, "ours": 1, "note": ""},
        {"section": "thesis", "where": "Figure 3.5", "status": "reproduced", "thesis": 1, "ours": 1, "note": ""},
    ]
    rows[0]["compared_as"] = "= 1"
    lines = findings(rows, chapter="2").splitlines()
    assert lines[:2] == ["| thesis place | thesis — compared as | ours | status | why |", "|---|---|---|---|---|"]
    assert lines[2:] == ["| Example 2.36 | 1 — *compared as* = 1 | (2, 3.5) | {bdg-danger}`differs` | a \\| b c |"]
    assert findings(rows, chapter="3") == "Every claim of this chapter is reproduced."


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"correct": 0.5, "note": "n"}, "an erratum \\(correct\\) needs corrected and check"),
        ({"correct": 0.5, "note": "n", "corrected": "0.5"}, "needs check"),
        ({"correct": 0.5, "note": "n", "check": "a counterexample"}, "needs corrected"),
        ({"corrected": "x"}, "corrected only go with an erratum"),
        ({"check": "x", "corrected": "y"}, "corrected and check only go with an erratum"),
        ({"correct": 0.5, "corrected": "", "check": "c", "note": "n"}, "corrected must be a non-empty string"),
        ({"correct": 0.5, "corrected": 3, "check": "c", "note": "n"}, "corrected must be a non-empty string"),
        ({"by_construction": True}, "by_construction must be a non-empty string"),
        ({"own_tolerance": "yes"}, "own_tolerance must be true or false"),
        ({"not_comparable": 1, "note": "n"}, "not_comparable must be true or false"),
        ({"not_comparable": True}, "not_comparable needs a note"),
        ({"not_comparable": True, "by_construction": "x", "note": "n"}, "cannot be combined with by_construction"),
        ({"not_comparable": True, "own_tolerance": True, "rtol": 0.1, "note": "n"},
         "cannot be combined with own_tolerance"),
        ({"not_comparable": True, "not_reproducible": True, "note": "n"}, "cannot be combined with not_reproducible"),
        ({"own_tolerance": True, "compare": "none", "note": "n"}, "own_tolerance needs a comparison"),
        ({"own_tolerance": True}, "needs a nonzero rtol"),
        ({"own_tolerance": True, "compare": "abs"}, "needs a nonzero atol"),
        ({"by_construction": "x", "correct": 1, "note": "n", **ERRATUM}, "by_construction cannot be an erratum"),
        ({"provenance": "thesis"}, "provenance must be one of"),
        ({"note": 3}, "note must be a string"),
    ],
)
def test_new_schema_keys_are_checked(registry, kw, message):
    with pytest.raises(ClaimError, match=message):
        registry(_claim(**kw))


@pytest.mark.parametrize("provenance", ["transcribed", "thesis data", "reconstructed input", "substitute input",
                                        "computed"])
def test_the_five_provenances_are_accepted_and_carried(registry, provenance):
    row = registry(_claim(rtol=0.01, provenance=provenance))[0]
    assert row["provenance"] == provenance and row["status"] == "reproduced"
    assert f"| {provenance} |" in report.markdown([row])
    assert f"`{provenance}`: {report.PROVENANCE_LEGEND[provenance]}" in report.markdown([row])


@pytest.mark.parametrize(
    "kw, text",
    [
        ({"compare": "eq", "thesis": 3}, "= 3"),
        ({"compare": "le", "thesis": 0}, "≤ 0"),
        ({"compare": "ge", "thesis": 1}, "≥ 1"),
        ({"compare": "rel", "thesis": 2.329, "rtol": 0.21}, "= 2.329 ± 21 %"),
        ({"compare": "rel", "thesis": 290000, "rtol": 0.05}, "= 290000 ± 5 %"),
        ({"compare": "rel", "thesis": 3.141592654, "rtol": 1e-5}, "= 3.142 (rel. 10⁻⁵)"),
        ({"compare": "abs", "thesis": 0.0, "atol": 0.004}, "within 4·10⁻³ of 0"),
        ({"compare": "abs", "thesis": 0.5, "atol": 2.5e-7}, "= 0.5 ± 2.5·10⁻⁷"),
        ({"compare": "between", "thesis": "small", "low": 2e-5, "high": 1.4e-4}, "in [2·10⁻⁵, 1.4·10⁻⁴]"),
        ({"compare": "none", "thesis": "a figure"}, "—"),
        ({"compare": "eq", "thesis": "β", "value": [3, 2], "result": ["exp:b1", "exp:b2"]}, "= (3, 2)"),
        ({"compare": "ge", "thesis": "grows", "value": -0.001}, "≥ −10⁻³"),
        ({"compare": "abs", "thesis": 0.0, "atol": 0.004, "own_tolerance": True}, "within 4·10⁻³ of 0 (ours)"),
        ({"compare": "eq", "thesis": 6, "correct": 15, **ERRATUM}, "= 6; corrected = 15"),
        ({"compare": "rel", "thesis": 1 / 12, "correct": 5 / 48, "rtol": 1e-8, **ERRATUM},
         "= 0.08333; corrected = 0.1042 (rel. 10⁻⁸)"),
        ({"compare": "eq", "thesis": 1, "not_comparable": True, "note": "n"}, "—"),
    ],
)
def test_compared_as(kw, text, tmp_path):
    (tmp_path / "t.toml").write_text(_claim(**kw))
    claim = report.load_claims(tmp_path)[0]
    assert report.compared_as(claim) == text


@pytest.mark.parametrize("x, text", [(0.004, "4·10⁻³"), (1e-5, "10⁻⁵"), (-2.5e-7, "−2.5·10⁻⁷"), (288100, "288100"),
                                     (1e6, "10⁶"), (3.7e8, "3.7·10⁸"), (0.1041666667, "0.1042"), (12345.6, "12346"),
                                     (0, "0"), (float("nan"), "nan"), (float("inf"), "∞"), (9.9996e-4, "10⁻³")])
def test_numbers_are_written_compactly(x, text):
    assert report.number_text(x) == text


def test_headline_counts_only_what_could_have_failed(registry):
    text = (_claim(id="r", rtol=0.01)
            + _claim(id="i", compare="eq", thesis=288100, by_construction="the count is the parameter")
            + _claim(id="k", compare="abs", thesis=0.0, atol=0.004, result="exp:err", own_tolerance=True, note="ours")
            + _claim(id="x", not_comparable=True, rtol=0.01, note="jPlex timed out")
            + _claim(id="e", compare="abs", atol=1e-6, thesis=1 / 12, correct=5 / 48, result="exp:coef", note="n",
                     **ERRATUM)
            + _claim(id="d", rtol=0.0001, note="off")
            + _claim(id="d2", where="Figure 3.5", rtol=0.0001, note="off")
            + _claim(id="f", compare="none", note="fig")
            + _claim(id="u", not_reproducible=True, note="data")
            + _claim(id="n", section="beyond", rtol=0.01, note="new"))
    rows = registry(text)
    assert report.headline(rows) == (
        "Of 9 claims of the thesis, 4 could have failed: 1 reproduced, 1 erratum, 2 differ. Shown apart: "
        "1 identity, 1 consistent within a tolerance of ours, 1 not comparable, 1 figure-only, 1 not reproducible. "
        "Beyond the thesis: 1 new result.")
    s = report.summary(rows)
    assert s["thesis"] == 9 and s["could_fail"] == 4 and s["beyond"] == 1
    assert s["thesis_by_status"]["identity"] == 1 and s["by_status"]["new"] == 1
    assert report.summary_markdown(rows).startswith(report.headline(rows) + "\n")
    # without the identity and the tolerance of ours, fewer are shown apart; plural forms follow the counts
    rows = [r for r in rows if r["id"] not in ("i", "k", "e", "n", "d")]
    assert report.headline(rows) == (
        "Of 5 claims of the thesis, 2 could have failed: 1 reproduced, 0 errata, 1 differs. Shown apart: "
        "0 identities, 0 consistent within a tolerance of ours, 1 not comparable, 1 figure-only, 1 not reproducible.")


def test_an_identity_gives_its_reason_and_is_never_reproduced(registry):
    row = registry(_claim(compare="eq", thesis=288100, by_construction="the count is fixed by the parameters"))[0]
    assert row["status"] == "identity" and row["note"] == "" and row["compared_as"] == "= 288100"
    assert report.why(row) == "By construction: the count is fixed by the parameters."
    assert "{bdg-success-line}`identity`" in report.findings([row], chapter="2")


def test_errata_show_the_text_as_printed_the_correction_and_the_check(registry):
    rows = registry(_claim(id="e", where="§3.4.2", thesis="the region has volume 1/12", value=1 / 12,
                           compare="rel", rtol=1e-6, correct=5 / 48, result="exp:coef", note="Computed.",
                           link="ch3-curvature#sec-3-4-2", **ERRATUM)
                    + _claim(id="r", rtol=0.01))
    e = rows[0] if rows[0]["id"] == "e" else rows[1]
    assert e["status"] == "erratum" and e["corrected"] == ERRATUM["corrected"] and e["check"] == ERRATUM["check"]
    assert report.why(e) == ("Computed. Corrected: the coefficient is 5/48 "
                             "Decisive check: the volume of the cut simplex is 1/8 − 1/48")
    table = report.errata_markdown(rows).splitlines()
    assert table == ["| thesis place | as printed | corrected | decisive check | ours |", "|---|---|---|---|---|",
                     "| §3.4.2 | the region has volume 1/12 | the coefficient is 5/48 "
                     "| the volume of the cut simplex is 1/8 − 1/48 | 0.1042 |"]
    md = report.markdown(rows)
    errata_part = md.split("### Errata")[1]
    assert "(tbl-report-errata)=" in errata_part
    assert "[§3.4.2](ch3-curvature.html#sec-3-4-2)" in errata_part and "| r |" not in errata_part
    assert report.errata_markdown([r for r in rows if r["id"] == "r"]) == ""
    assert "### Errata" not in report.markdown([r for r in rows if r["id"] == "r"])


def test_json_is_strict_with_nan_and_infinity(registry, tmp_path):
    res = tmp_path / "experiments" / "results" / "exp" / "results.json"
    res.write_text('{"count": NaN, "err": Infinity, "b1": -Infinity, "b2": 1, "coef": 0.5}')
    rows = registry(_claim(id="a", rtol=0.01, note="nan") + _claim(id="b", compare="le", thesis=1, result="exp:err",
                                                                      note="inf")
                    + _claim(id="c", compare="eq", thesis=float("inf"), value=1, result=["exp:b1", "exp:b2"],
                             note="-inf").replace("Infinity", "inf"))
    assert [r["status"] for r in rows] == ["differs", "differs", "differs"]
    text = report.to_json(rows)
    with pytest.raises(ValueError):
        strict_json(json.dumps(rows))  # what json.dumps writes by default is not JSON
    data = strict_json(text)
    assert [d["ours"] for d in data] == ["nan", "inf", ["-inf", 1]]
    assert data[2]["thesis"] == "inf"
    assert set(data[0]) == ROW_FIELDS


def test_math_in_table_text_is_typeset():
    assert report.math_text("H_d = Σ_{i ∈ N(q)} −x_i") == "H_d = $Σ_{i ∈ N(q)}$ −x_i"
    assert report.math_text("points in R^{n+1}, n = 2…6.") == "points in $R^{n+1}$, n = 2…6."
    assert report.math_text("(1/2π) ∫₀^{2π} κ_n") == "(1/2π) $∫₀^{2π}$ κ_n"
    assert report.math_text("already $x_{1}$") == "already $x_{1}$"
    assert report.table_cell("a | b_{i}\nc") == "a \\| $b_{i}$ c"


def test_front_matter_and_summary_have_their_own_columns(registry):
    text = (_claim(id="p", where="Preface", rtol=0.1) + _claim(id="i", where="Introduction", rtol=0.1)
            + _claim(id="s", where="Summary", rtol=0.1) + _claim(id="c", where="Figure 3.5", rtol=0.1)
            + _claim(id="o", where="somewhere", rtol=0.1))
    assert list(report.summary(registry(text))["by_chapter"]) == ["front", "3", "5", "other"]
    assert "| Preface, Introduction | 2 | 2 |" in report.summary_markdown(registry(text))

"""The reproduction report: registry format, comparisons, statuses and notes, JSON output."""

from __future__ import annotations

import json

import pytest

from thesis_lib.lab import cli, report
from thesis_lib.lab.paths import shared_dir
from thesis_lib.lab.report import ClaimError


def test_registry_is_well_formed_and_complete():
    rows = report.report()
    assert rows, "the registry has no claims"
    for row in rows:
        assert set(row) == {"id", "where", "thesis", "ours", "status", "note", "provenance", "section", "link",
                            "correct"}
        assert row["status"] in report.STATUSES
        if row["status"] != "reproduced":
            assert row["note"], row
        if row["ours"] is None:
            # nothing measured, or a figure to compare by eye
            assert row["status"] in ("not-reproducible", "figure-only")
            assert not row["note"].startswith("no stored result"), f"claim {row['id']} has no stored result"


def test_cli_json_matches_the_library(capsys):
    assert cli.main(["report", "--json"]) == 0
    out = capsys.readouterr().out
    assert json.loads(out) == json.loads(json.dumps(report.report()))
    assert '"where": "§' in out  # thesis places stay readable (no \\u escapes)


def test_cli_prints_the_summary_first_then_the_table(capsys):
    assert cli.main(["report"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"{len(report.report())} claims: ")
    assert "\n| claim | thesis place | thesis | ours | status | provenance | note |\n" in out


@pytest.fixture
def registry(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_SHARED", str(shared_dir()))  # the thesis text orders the report
    monkeypatch.setenv("THESIS_LAB_ROOT", str(tmp_path))
    (tmp_path / "experiments" / "claims").mkdir(parents=True)
    res = tmp_path / "experiments" / "results" / "exp"
    res.mkdir(parents=True)
    (res / "results.json").write_text(json.dumps({"count": 288100, "err": 0.003, "b1": 3, "b2": 1, "coef": 0.1041667}))

    def write(text: str):
        (tmp_path / "experiments" / "claims" / "t.toml").write_text(text)
        return report.report()

    return write


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
        ({"compare": "abs", "atol": 1e-6, "thesis": 1 / 12, "correct": 5 / 48, "result": "exp:coef", "note": "5/48"},
         "erratum"),
        # passes with the thesis's value: reproduced, even with a `correct`
        ({"compare": "abs", "atol": 0.1, "thesis": 1 / 12, "correct": 5 / 48, "result": "exp:coef"}, "reproduced"),
        # passes with neither: differs
        ({"compare": "abs", "atol": 1e-6, "thesis": 1 / 12, "correct": 0.5, "result": "exp:coef", "note": "n"},
         "differs"),
        ({"compare": "eq", "thesis": "β = (3, 2)", "value": [3, 2], "correct": [3, 1], "result": ["exp:b1", "exp:b2"],
          "note": "β₂ = 1"}, "erratum"),
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
        (_claim(compare="between", low=0, high=1, correct=0.5), "'correct' needs a comparison"),
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
    assert s["by_status"] == {"reproduced": 1, "erratum": 0, "differs": 1, "not-reproducible": 0, "figure-only": 1,
                              "new": 1}
    assert s["by_chapter"] == {"2": {"reproduced": 1}, "3": {"differs": 1}, "4": {"figure-only": 1}}
    assert s["by_provenance"] == {"computed": 1, "reconstructed input": 2, "transcribed": 1}
    assert report.summary_markdown(registry(text)).startswith(
        "4 claims: 1 reproduced, 1 differs, 1 figure-only, 1 new. "
        "Provenance: 1 computed, 2 reconstructed input, 1 transcribed.")


def test_corrupt_results_and_claims_give_clear_errors(registry, tmp_path, capsys):
    """Regression (issue 11): a truncated results.json raised a raw JSONDecodeError in `report`."""
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
    lines = findings(rows, "2").splitlines()
    assert lines[:2] == ["| thesis place | thesis | ours | status | why |", "|---|---|---|---|---|"]
    assert lines[2:] == ["| Example 2.36 | 1 | (2, 3.5) | {bdg-danger}`differs` | a \\| b c |"]
    assert findings(rows, "3") == "Every claim of this chapter is reproduced."

"""The reproduction report: registry format, comparisons, statuses and notes, JSON output."""

from __future__ import annotations

import json

import pytest

from thesis_lib.lab import cli, report
from thesis_lib.lab.report import ClaimError


def test_registry_is_well_formed_and_complete():
    rows = report.report()
    assert rows, "the registry has no claims"
    for row in rows:
        assert set(row) == {"id", "where", "thesis", "ours", "status", "note"}
        assert row["status"] in report.STATUSES
        if row["status"] != "reproduced":
            assert row["note"], row
        if row["ours"] is None:
            assert row["status"] == "not-reproducible"
            assert not row["note"].startswith("no stored result"), f"claim {row['id']} has no stored result"


def test_cli_json_matches_the_library(capsys):
    assert cli.main(["report", "--json"]) == 0
    out = capsys.readouterr().out
    assert json.loads(out) == json.loads(json.dumps(report.report()))
    assert '"where": "§' in out  # thesis places stay readable (no \\u escapes)


def test_cli_markdown_table(capsys):
    assert cli.main(["report"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("| claim | thesis place | thesis | ours | status | note |")
    assert f"{len(report.report())} claims:" in out


@pytest.fixture
def registry(tmp_path, monkeypatch):
    monkeypatch.setenv("THESIS_LAB_ROOT", str(tmp_path))
    (tmp_path / "experiments" / "claims").mkdir(parents=True)
    res = tmp_path / "experiments" / "results" / "exp"
    res.mkdir(parents=True)
    (res / "results.json").write_text(json.dumps({"count": 288100, "err": 0.003, "b1": 3, "b2": 1}))

    def write(text: str):
        (tmp_path / "experiments" / "claims" / "t.toml").write_text(text)
        return report.report()

    return write


def _claim(**kw) -> str:
    base = {"id": "c", "where": "Figure 2.14", "thesis": 290000, "result": "exp:count", "compare": "rel"}
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
        ({"compare": "between", "thesis": "(2e-5, 1.4e-4)", "low": 2e-5, "high": 1.4e-4, "result": "exp:err", "note": "n"}, "differs"),
        ({"compare": "eq", "thesis": [3, 1], "result": ["exp:b1", "exp:b2"]}, "reproduced"),
        ({"compare": "eq", "thesis": "β = (3, 2)", "value": [3, 2], "result": ["exp:b1", "exp:b2"], "note": "β₂"}, "differs"),
        ({"not_reproducible": True, "note": "data unavailable"}, "not-reproducible"),
        ({"rtol": 0.01, "thesis": 1000, "correct": 288100, "note": "typo"}, "erratum"),
        ({"rtol": 0.01, "correct": 1000}, "reproduced"),
        ({"rtol": 0.01, "thesis": 1000, "correct": 2000, "note": "neither"}, "differs"),
        ({"compare": "none", "thesis": "a picture", "note": "drawn only", "provenance": "computed"}, "figure-only"),
        ({"rtol": 0.01, "section": "beyond", "note": "new work"}, "new"),
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
        (_claim(rtol=0.1, provenance="guessed"), "provenance must be one of"),
        (_claim(rtol=0.1, section="appendix"), "section must be one of"),
        (_claim(compare="none", correct=1.0), "needs a comparison"),
        (_claim(rtol=0.1) + _claim(rtol=0.1), "repeated"),
    ],
)
def test_malformed_claims_are_refused(registry, text, message):
    with pytest.raises(ClaimError, match=message):
        registry(text)


def test_report_is_ordered_by_thesis_place(registry):
    text = _claim(id="late", where="Figure 3.5", rtol=0.1) + _claim(id="early", where="§2.2.2", rtol=0.1)
    text += _claim(id="mid", where="Example 2.21", rtol=0.1)
    assert [r["id"] for r in registry(text)] == ["early", "mid", "late"]

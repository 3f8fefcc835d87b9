"""thesis_lib.lab.chapters: chapter headings of the thesis text and the chapter numbers it refers to."""

from __future__ import annotations

import re

import pytest

from thesis_lib.lab import chapters as ch
from thesis_lib.lab.paths import shared_dir

# a small document laid out like the thesis text: front matter, numbered chapter headings, sections,
# a caption, a running head, and references by number (one right, one wrong)
DOC = """Title page

Preface

The method of Chapter 3 was the hardest. Thanks to all.

 1

Introduction

Balls are studied in Chapter 2. Chapter 2 ends with pictures of balls.

2

Balls

2.1 Round Things

Text.

Figure 2.1: a ball

3

Cubes

3.1 Square Things

CHAPTER 3. CUBES

4

Summary

In Chapter 3 we studied cubes.
"""


def test_chapters_are_read_from_the_headings():
    got = ch.chapters(DOC)
    assert [(c.number, c.title) for c in got] == [(1, "Introduction"), (2, "Balls"), (3, "Cubes"), (4, "Summary")]
    lines = DOC.splitlines()
    for c in got:
        assert lines[c.start].strip() == str(c.number)
        assert c.start < c.end
    assert [c.end for c in got[:-1]] == [c.start for c in got[1:]] and got[-1].end == len(lines)


def test_chapter_at_and_parts():
    chaps = ch.chapters(DOC)
    lines = DOC.splitlines()
    assert ch.chapter_at(chaps, lines.index("2.1 Round Things")).title == "Balls"
    assert ch.chapter_at(chaps, lines.index("Preface")) is None
    assert [lines[i] for i in ch.part_lines(DOC, "Preface")][0] == "Preface"
    assert lines.index(" 1") == ch.part_lines(DOC, "Preface").stop
    assert "In Chapter 3 we studied cubes." in [lines[i] for i in ch.part_lines(DOC, "Summary")]
    with pytest.raises(ValueError, match="no part titled"):
        ch.part_lines(DOC, "Appendix")
    with pytest.raises(ValueError, match="no Preface"):
        ch.part_lines(DOC.replace("Preface\n", "Foreword\n"), "Preface")


def test_references_and_their_sentences():
    refs = ch.chapter_references(DOC, "Introduction")
    assert [r.number for r in refs] == [2, 2]
    assert [r.sentence for r in refs] == ["Balls are studied in Chapter 2.", "Chapter 2 ends with pictures of balls."]
    assert [r.number for r in ch.chapter_references(DOC, "Preface")] == [3]
    # the running head "CHAPTER 3." is no reference
    assert [r.number for r in ch.chapter_references(DOC, "Cubes")] == []


def test_section_chapter_reads_the_heading_not_the_section_number():
    assert ch.section_chapter(DOC, "Round Things") == 2
    # a section misnumbered 7.1 under the heading 3 still belongs to chapter 3
    assert ch.section_chapter(DOC.replace("3.1 Square", "7.1 Square"), "Square Things") == 3
    with pytest.raises(ValueError, match="need exactly one"):
        ch.section_chapter(DOC, "Triangles")
    twice = DOC.replace("3.1 Square Things", "3.1 Round Things")
    with pytest.raises(ValueError, match=r"chapters \[2, 3\]"):
        ch.section_chapter(twice, "Round Things")


def test_section_at_is_the_innermost_numbered_heading_above():
    lines = DOC.splitlines()
    assert ch.section_at(DOC, lines.index("Figure 2.1: a ball")) == "2.1"
    assert ch.section_at(DOC, lines.index("CHAPTER 3. CUBES")) == "3.1"
    assert ch.section_at(DOC, lines.index("Cubes")) == ""  # the chapter heading, before its sections
    assert ch.section_at(DOC, lines.index("In Chapter 3 we studied cubes.")) == ""
    assert ch.section_at(DOC, lines.index("Preface")) == ""


def test_numbering_disagreements_find_misnumbered_lines():
    assert ch.numbering_disagreements(DOC) == []
    lines = DOC.splitlines()
    bad = DOC.replace("Figure 2.1:", "Figure 5.1:").replace("CHAPTER 3. CUBES", "CHAPTER 2. CUBES")
    got = ch.numbering_disagreements(bad)
    assert got == [(lines.index("Figure 2.1: a ball"), 5, 2), (lines.index("CHAPTER 3. CUBES"), 2, 3)]


def test_headings_out_of_order_are_refused():
    with pytest.raises(ValueError, match="not numbered 1, 2"):
        ch.chapters(DOC.replace("\n3\n\nCubes", "\n5\n\nCubes"))
    with pytest.raises(ValueError, match="not numbered"):
        ch.chapters("no headings here\n")


def test_resolve_on_a_table_of_references(monkeypatch):
    monkeypatch.setattr(ch, "REFERENCES", (
        ("balls", "Introduction", "Balls are studied", "Round Things"),
        ("cubes", "Summary", "we studied cubes", "Square Things"),
        ("method", "Preface", "The method of", "Square Things"),
    ))
    got = ch.resolve(DOC)
    assert list(got) == ["balls", "cubes", "method"]
    assert [(r.printed, r.chapter.number) for r in got.values()] == [(2, 2), (3, 3), (3, 3)]
    assert got["balls"].section == "2.1 Round Things" and got["cubes"].chapter.title == "Cubes"
    wrong = DOC.replace("In Chapter 3 we studied", "In Chapter 2 we studied")
    assert ch.resolve(wrong)["cubes"].printed == 2
    monkeypatch.setattr(ch, "REFERENCES", (("x", "Introduction", "pictures", "Round Things"),
                                           ("y", "Introduction", "Chapter", "Round Things")))
    with pytest.raises(ValueError, match="y: 2 sentences"):
        ch.resolve(DOC)


THESIS = shared_dir() / "thesis" / ch.THESIS_TEXT


@pytest.mark.skipif(not THESIS.is_file(), reason="the thesis text is not in the shared folder")
def test_the_thesis_text():
    text = ch.read_thesis()
    assert [c.title for c in ch.chapters(text)] == ["Introduction", "Persistent Homology",
                                                      "Discrete Differential Geometry", "Discrete Morse Theory",
                                                      "Summary"]
    assert ch.numbering_disagreements(text) == []
    got = ch.resolve(text)
    # every "Chapter N" of the three parts is one of the table's references, so none is left unchecked
    for part in [c.title for c in ch.chapters(text)] + ["Preface"]:
        refs = ch.chapter_references(text, part)
        mine = [r for r in got.values() if r.part == part]
        assert sorted(r.sentence for r in refs) == sorted(r.sentence for r in mine)
    for r in got.values():
        # the number printed is the one in the sentence, and the section's own number agrees with
        # the heading it stands under
        assert f"Chapter {r.printed}" in r.sentence
        assert int(re.match(r"\d+", r.section).group()) == r.chapter.number
        if r.part in ch.FRONT_AND_SUMMARY:
            assert r.where == r.part
        else:  # the sentence stands in a numbered section of its own chapter
            own = next(c.number for c in ch.chapters(text) if c.title == r.part)
            assert r.where.split(".")[0] == str(own)


@pytest.mark.skipif(not THESIS.is_file(), reason="the thesis text is not in the shared folder")
def test_the_stored_numbers_are_the_texts():
    """The summary page's stored run (what the report's errata read) matches the thesis text."""
    from thesis_lib.lab.report import report
    from thesis_lib.lab.results import load

    stored = load("ch5-summary")
    for key, r in ch.resolve(ch.read_thesis()).items():
        assert (stored[f"{key}_printed"], stored[f"{key}_chapter"]) == (r.printed, r.chapter.number), key
    rows = {row["id"]: row for row in report()}
    for cid in ("preface-mean-curvature-chapter", "introduction-chapter-1-is-2", "introduction-chapter-2-is-3",
                "summary-chapter-1-is-2", "summary-chapter-2-is-3"):
        assert rows[cid]["status"] == "erratum", rows[cid]


def test_the_numbering_record_reads_every_reference_and_the_headings():
    from thesis_lib.lab.chapters import (
        REFERENCES,
        chapters,
        numbering_disagreements,
        numbering_record,
        read_thesis,
        reference_table,
        resolve,
        slips_text,
    )

    text = read_thesis()
    record, refs = numbering_record(text), resolve(text)
    assert len(record) == 2 * len(REFERENCES) + 3
    for key, r in refs.items():
        assert (record[f"{key}_printed"], record[f"{key}_chapter"]) == (r.printed, r.chapter.number)
    assert record["numbering_disagreements"] == len(numbering_disagreements(text))
    heads = chapters(text)
    assert "Morse" in heads[record["morse_approach_position"]].title  # position among the chapters 2..4
    slipped = [r for r in refs.values() if r.printed != r.chapter.number]
    assert slipped and slips_text(refs.values()).count("; ") == len(slipped) - 1
    assert slips_text([r for r in refs.values() if r.printed == r.chapter.number]) == ""
    table = reference_table(refs.values(), words=3).splitlines()
    assert len(table) == 2 + len(refs) and all(line.count(" | ") == 4 for line in table[2:])


def test_chapter_tally_counts_statuses_in_their_order():
    from thesis_lib.lab.report import STATUSES, chapter_tally

    counts = {"by_chapter": {"3": {"differs": 2, "reproduced": 5, "new": 0}}}
    assert chapter_tally(counts, "3") == (7, "5 reproduced, 2 differs")
    assert STATUSES.index("reproduced") < STATUSES.index("differs")
    assert chapter_tally(counts, "2") == (0, "")

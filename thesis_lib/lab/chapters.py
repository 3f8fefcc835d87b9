"""The thesis text's own chapter headings, and the chapters that its Preface, Introduction and
Summary refer to by number.

The thesis heads each chapter with its number on a line of its own and the title below it
("2", "Persistent Homology"); its section headings ("2.3 Persistent Homology"), captions ("Figure
1.1: ...") and running heads ("CHAPTER 5. SUMMARY") carry the same number.  The Preface, the
Introduction and the Summary refer to chapters as "Chapter N".  :data:`REFERENCES` names, for each
such reference, the section that holds the subject it speaks of; :func:`resolve` reads the number
printed in the sentence and the number of the chapter whose heading stands above that section, so
the two can be set side by side.  Only the thesis text is read; nothing is typed in but the
sentences' words and the sections' titles.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from .paths import shared_dir

__all__ = ["Chapter", "Reference", "Resolved", "REFERENCES", "FRONT_AND_SUMMARY", "THESIS_TEXT", "read_thesis",
           "chapters", "chapter_at", "part_lines", "numbering_disagreements",
           "chapter_references", "section_chapter", "section_at", "resolve", "numbering_record", "reference_table",
           "slips_text"]

THESIS_TEXT = "botnan-2011-three-approaches.txt"

#: (key, part, words of the sentence that holds its "Chapter N", title of the section its subject is in)
REFERENCES = (
    ("preface_mean_curvature", "Preface", "the generalisation of mean curvature discussed in",
     "Discrete Mean Curvature"),
    ("intro_complexes", "Introduction", "Various methods to obtain such complexes are described in", "Complexes"),
    ("intro_persistent_homology", "Introduction", "which is discussed in", "Persistent Homology"),
    ("intro_applications", "Introduction", "range image analysis", "Experiments"),
    ("intro_differential_geometry", "Introduction", "we use ideas from differential geometry", "Discrete Versions"),
    ("intro_familiar_manifolds", "Introduction", "ends with calculations on some familiar manifolds",
     "Experimental Results"),
    ("intro_discrete_versions", "Introduction", "where we develop the discrete theory as discrete versions",
     "Discrete Versions"),
    ("summary_persistent_homology", "Summary", "we defined persistent homology", "Persistent Homology"),
    ("summary_curvature", "Summary", "we defined the necessary tools needed to define discrete curvature",
     "Discrete Versions"),
    # the body of the thesis refers back to its first chapter of mathematics three times
    ("body_voronoi", "Discrete Differential Geometry", "We discussed Voronoi regions in",
     "Constructing Simplicial Complexes"),
    ("body_simplicial_homology", "Discrete Morse Theory", "as when we used simplicial homology in",
     "Simplicial Homology"),
    ("body_boundary_operator", "Discrete Morse Theory", "the standard boundary operator on a simplicial complex from",
     "Simplicial Homology"),
)
#: the parts that are not chapters of mathematics (the rest of :data:`REFERENCES` is in the body)
FRONT_AND_SUMMARY = ("Preface", "Introduction", "Summary")

_NUMBER = re.compile(r"\s*(\d+)\s*")
_SECTION = re.compile(r"(\d+)\.\d+(?:\.\d+)* [A-Z]")
_CAPTION = re.compile(r"(?:Figure|Table) (\d+)\.\d+:")
_RUNNING_HEAD = re.compile(r"CHAPTER (\d+)\. ")
_CHAPTER_REF = re.compile(r"Chapter (\d+)")
_SENTENCE_END = re.compile(r"\.\s+")


@dataclass(frozen=True)
class Chapter:
    """A chapter of the thesis text: its number and title as headed, and its lines ``[start, end)``."""

    number: int
    title: str
    start: int
    end: int


@dataclass(frozen=True)
class Reference:
    """A "Chapter N" in the text: the number printed, its line, and the sentence it stands in."""

    number: int
    line: int
    sentence: str


def read_thesis(path: str | Path | None = None) -> str:
    """The thesis text.

    Thesis: the whole text (its headings, §1–§5).

    Parameters
    ----------
    path : str or pathlib.Path, optional
        The text file; by default ``thesis/botnan-2011-three-approaches.txt`` in the shared folder.

    Returns
    -------
    str
        The text.
    """
    path = Path(path) if path is not None else shared_dir() / "thesis" / THESIS_TEXT
    return path.read_text(encoding="utf-8")


def chapters(text: str) -> list[Chapter]:
    """The chapters as the text heads them: a line holding only a number, then the title.

    Thesis: the chapter headings 1 Introduction … 5 Summary.

    Parameters
    ----------
    text : str
        The thesis text (:func:`read_thesis`).

    Returns
    -------
    list of Chapter
        In the text's order; each runs to the next heading (the last to the end of the text).

    Raises
    ------
    ValueError
        If the headings are not numbered 1, 2, 3, ... in order, or there are none.
    """
    lines = text.splitlines()
    heads = []
    for i, line in enumerate(lines):
        m = _NUMBER.fullmatch(line)
        if not m:
            continue
        title = next((t.strip() for t in lines[i + 1:i + 4] if t.strip()), "")
        if title and title[0].isupper() and not title.endswith(".") and len(title) < 60:
            heads.append((int(m.group(1)), title, i))
    numbers = [h[0] for h in heads]
    if not heads or numbers != list(range(1, len(heads) + 1)):
        raise ValueError(f"the chapter headings are not numbered 1, 2, ... in order: {numbers}")
    ends = [h[2] for h in heads[1:]] + [len(lines)]
    return [Chapter(n, title, start, end) for (n, title, start), end in zip(heads, ends)]


def chapter_at(chapter_list: list[Chapter], line: int) -> Chapter | None:
    """The chapter whose lines hold ``line`` (None before the first heading: the front matter).

    Thesis: the chapter headings.

    Parameters
    ----------
    chapter_list : list of Chapter
        The chapters (:func:`chapters`).
    line : int
        A line number of the text (0-based).

    Returns
    -------
    Chapter or None
        The chapter, or None for a line before the first chapter heading.
    """
    return next((c for c in chapter_list if c.start <= line < c.end), None)


def part_lines(text: str, part: str) -> range:
    """The lines of a named part: ``"Preface"`` (its heading to the first chapter heading), or a
    chapter by its title (``"Introduction"``, ``"Summary"``).

    Thesis: the Preface, the Introduction (Chapter 1) and the Summary (Chapter 5).

    Parameters
    ----------
    text : str
        The thesis text.
    part : str
        ``"Preface"`` or the title of a chapter.

    Returns
    -------
    range
        Its line numbers.

    Raises
    ------
    ValueError
        If there is no such part.
    """
    chaps = chapters(text)
    if part == "Preface":
        lines = text.splitlines()
        start = next((i for i, line in enumerate(lines) if line.strip() == "Preface"), None)
        if start is None or start >= chaps[0].start:
            raise ValueError("the text has no Preface before its first chapter")
        return range(start, chaps[0].start)
    for c in chaps:
        if c.title == part:
            return range(c.start, c.end)
    raise ValueError(f"no part titled {part!r}; chapters are {[c.title for c in chaps]}")


def numbering_disagreements(text: str) -> list[tuple[int, int, int]]:
    """Section headings, captions and running heads whose chapter number is not that of the
    chapter heading above them.

    Thesis: the numbering of §2.1–§4.2, Figures 1.1–4.8 and the running heads.

    Parameters
    ----------
    text : str
        The thesis text.

    Returns
    -------
    list of (int, int, int)
        ``(line, number printed, number of the chapter it stands in)``; empty when all agree.
    """
    chaps = chapters(text)
    out = []
    for i, line in enumerate(text.splitlines()):
        m = _SECTION.match(line) or _CAPTION.match(line) or _RUNNING_HEAD.match(line)
        chap = chapter_at(chaps, i)
        if m and chap is not None and int(m.group(1)) != chap.number:
            out.append((i, int(m.group(1)), chap.number))
    return out


def chapter_references(text: str, part: str) -> list[Reference]:
    """Every "Chapter N" in a part of the text.

    Thesis: the chapter references of the Preface, the Introduction and the Summary.

    Parameters
    ----------
    text : str
        The thesis text.
    part : str
        As for :func:`part_lines`.

    Returns
    -------
    list of Reference
        In the text's order.
    """
    lines = text.splitlines()
    out = []
    for i in part_lines(text, part):
        for m in _CHAPTER_REF.finditer(lines[i]):
            start = max((b.end() for b in _SENTENCE_END.finditer(lines[i], 0, m.start())), default=0)
            end = next((e.start() + 1 for e in _SENTENCE_END.finditer(lines[i], m.end())), len(lines[i]))
            out.append(Reference(int(m.group(1)), i, lines[i][start:end].strip()))
    return out


def section_chapter(text: str, title: str) -> int:
    """The number of the chapter whose heading stands above the section titled ``title``.

    Thesis: the section headings §2.1–§4.2.

    Parameters
    ----------
    text : str
        The thesis text.
    title : str
        A section's title as headed, without its number (``"Persistent Homology"`` for §2.3).

    Returns
    -------
    int
        The chapter heading's number (read from the heading, not from the section's number).

    Raises
    ------
    ValueError
        If no section has that title, or sections in different chapters have it.
    """
    return _section(text, title)[1].number


def section_at(text: str, line: int) -> str:
    """The number of the innermost numbered section whose heading stands at or above ``line`` within
    its chapter, e.g. ``"3.3.2"``.

    Thesis: the section headings §2.1–§4.2.

    Parameters
    ----------
    text : str
        The thesis text.
    line : int
        A line number of the text (0-based).

    Returns
    -------
    str
        The section number as printed, or ``""`` when no numbered heading of the line's chapter
        comes before it (the front matter, the Introduction, the Summary).
    """
    chap = chapter_at(chapters(text), line)
    if chap is None:
        return ""
    lines = text.splitlines()
    for i in range(line, chap.start - 1, -1):
        m = re.match(r"(\d+\.\d+(?:\.\d+)*) [A-Z]", lines[i])
        if m:
            return m.group(1)
    return ""


def _section(text: str, title: str) -> tuple[str, Chapter]:
    """The first section heading titled ``title`` (as printed) and the chapter it stands in."""
    chaps = chapters(text)
    heading = re.compile(r"\d+\.\d+(?:\.\d+)* " + re.escape(title))
    found = [(line.strip(), chapter_at(chaps, i)) for i, line in enumerate(text.splitlines())
             if heading.fullmatch(line.strip())]
    numbers = sorted({c.number for _, c in found})
    if len(numbers) != 1:
        raise ValueError(f"sections titled {title!r} in chapters {numbers}: need exactly one")
    return found[0]


@dataclass(frozen=True, kw_only=True)
class Resolved:
    """One reference of :data:`REFERENCES` read from the text."""

    key: str
    part: str
    sentence: str
    printed: int
    section: str
    chapter: Chapter
    where: str = ""


def resolve(text: str) -> dict[str, Resolved]:
    """For each reference of :data:`REFERENCES`: the number printed and the chapter that holds its
    subject.

    Thesis: the Preface, the Introduction and the Summary (their "Chapter N").

    Parameters
    ----------
    text : str
        The thesis text.

    Returns
    -------
    dict of str to Resolved
        ``key ->`` the sentence, the number printed in it, the subject's section heading as printed,
        the chapter (number and title as headed) that section stands in, and the number of the
        section the sentence itself stands in (``""`` outside numbered sections: the part's name), in
        the order of :data:`REFERENCES`.

    Raises
    ------
    ValueError
        If a reference's words are not in exactly one sentence with a "Chapter N" of its part, or its
        section is not found.
    """
    out = {}
    for key, part, words, title in REFERENCES:
        hits = [r for r in chapter_references(text, part) if words in r.sentence]
        if len(hits) != 1:
            raise ValueError(f"{key}: {len(hits)} sentences of the {part} with a chapter number and {words!r}")
        heading, chap = _section(text, title)
        out[key] = Resolved(key=key, part=part, sentence=hits[0].sentence, printed=hits[0].number, section=heading,
                            chapter=chap, where=section_at(text, hits[0].line) or part)
    return out


def numbering_record(text: str) -> dict[str, int]:
    """What the book records about the thesis's chapter numbers: each reference's printed number and
    its subject's chapter, the headings that disagree, and where the Morse chapter stands.

    Thesis: the Preface, the Introduction and the Summary (their "Chapter N"), and the chapter headings.

    Parameters
    ----------
    text : str
        The thesis text.

    Returns
    -------
    dict of str to int
        ``<key>_printed`` and ``<key>_chapter`` for each reference of :data:`REFERENCES`,
        ``numbering_disagreements`` (:func:`numbering_disagreements`), ``approach_chapters`` (the
        chapters between the Introduction and the Summary) and ``morse_approach_position`` (the
        Morse chapter's place among them, from 1).

    Raises
    ------
    ValueError
        As :func:`resolve`, or when no chapter between the Introduction and the Summary is on Morse theory.

    Examples
    --------
    >>> record = numbering_record(read_thesis())
    >>> record["approach_chapters"], record["morse_approach_position"], record["summary_curvature_printed"]
    (3, 3, 2)
    """
    out: dict[str, int] = {}
    for key, r in resolve(text).items():
        out[f"{key}_printed"] = r.printed
        out[f"{key}_chapter"] = r.chapter.number
    approaches = chapters(text)[1:-1]  # the chapters between the Introduction and the Summary
    morse = [i for i, c in enumerate(approaches) if "Morse" in c.title]
    if not morse:
        raise ValueError("no chapter between the Introduction and the Summary is on Morse theory")
    out["numbering_disagreements"] = len(numbering_disagreements(text))
    out["approach_chapters"] = len(approaches)
    out["morse_approach_position"] = 1 + morse[0]
    return out


def reference_table(refs: Iterable[Resolved], *, words: int = 12) -> str:
    """The references as a Markdown table: part, the sentence's first words, the number printed, the
    section of the subject and the chapter heading it stands under.

    Thesis: the Preface, the Introduction and the Summary (their "Chapter N").

    Parameters
    ----------
    refs : iterable of Resolved
        The references (:func:`resolve`'s values).
    words : int, default 12
        Words of each sentence shown (the rest as "…"); Markdown bold marks are dropped.

    Returns
    -------
    str
        The table (no final newline).

    Examples
    --------
    >>> refs = resolve(read_thesis())
    >>> print(reference_table([refs["summary_curvature"]], words=4).splitlines()[-1])
    | Summary | In Chapter 2 we … | 2 | §3.3 Discrete Versions | 3 Discrete Differential Geometry |
    """
    def shown(sentence: str) -> str:
        w = sentence.replace("**", "").split()
        return " ".join(w[:words]) + (" …" if len(w) > words else "")

    lines = ["| part | sentence | printed | subject in | chapter heading |", "|---|---|---|---|---|"]
    lines += [f"| {r.part} | {shown(r.sentence)} | {r.printed} | §{r.section} | {r.chapter.number} {r.chapter.title} |"
              for r in refs]
    return "\n".join(lines)


def slips_text(refs: Iterable[Resolved]) -> str:
    """The references whose printed number is not their subject's chapter, each as a phrase: where it
    stands, what it says, and where its subject is.

    Thesis: the body's references back to its chapters (§3, §4: "Chapter 1" for Chapter 2).

    Parameters
    ----------
    refs : iterable of Resolved
        The references (:func:`resolve`'s values).

    Returns
    -------
    str
        The phrases joined by "; " (empty when every number is right).

    Examples
    --------
    >>> refs = resolve(read_thesis())
    >>> slips_text([refs["body_voronoi"]]).startswith("§3.")
    True
    """
    return "; ".join(f"§{r.where}: “{r.sentence.split('Chapter')[0].strip()} Chapter {r.printed}”, "
                     f"where §{r.section.split()[0]} is in Chapter {r.chapter.number}"
                     for r in refs if r.printed != r.chapter.number)

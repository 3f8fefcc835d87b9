"""What §2.3 of the thesis prints, parsed from its text (imported by the tests as ``from thesis_text import ...``).

The tests compare the library's transcriptions and computations with these, so that a typo in a
transcription is caught by the text itself.
"""

from __future__ import annotations

import re

import pytest

from thesis_lib.lab import chapters
from thesis_lib.lab.paths import shared_dir

THESIS = shared_dir() / "thesis" / chapters.THESIS_TEXT
needs_thesis = pytest.mark.skipif(not THESIS.is_file(), reason="the thesis text is not in the shared folder")

Entry = tuple[int, int]  # (coefficient, power of t)


def _entry(text: str) -> Entry | None:
    """``$-t^2$`` → (−1, 2), ``t`` → (1, 1), ``-1`` → (−1, 0), ``0`` → None."""
    text = text.strip().strip("$")
    if text == "0":
        return None
    sign = -1 if text.startswith("-") else 1
    body = text.lstrip("-")
    if body == "1":
        return sign, 0
    match = re.fullmatch(r"t(?:\^(\d+))?", body)
    assert match, f"unexpected matrix entry {text!r}"
    return sign, int(match.group(1) or 1)


def _label(text: str) -> str:
    return re.sub(r"</?i>", "", text).strip()


def example_2_41_tables() -> list[dict[str, dict[str, Entry]]]:
    """The two matrices of Example 2.41 as printed: column label → {row label: entry}, nonzero entries only.

    Labels keep the thesis's parentheses (``(bc)``, ``(ed)``: "a homogeneous basis element with the
    same degree as σ").
    """
    text = chapters.read_thesis(THESIS)
    start = text.index("Example 2.41.")
    lines = text[start:].splitlines()
    tables = []
    k = 0
    while len(tables) < 2:
        while not lines[k].startswith("*\t"):
            k += 1
        columns = [_label(c) for c in lines[k].split("\t")[1:]]
        table: dict[str, dict[str, Entry]] = {c: {} for c in columns}
        k += 1
        while lines[k].strip():
            cells = lines[k].split("\t")
            row = _label(cells[0])
            for column, cell in zip(columns, cells[1:]):
                entry = _entry(cell)
                if entry is not None:
                    table[column][row] = entry
            k += 1
        tables.append(table)
    return tables


def printed_module(equation: str) -> list[tuple[int, int | None]]:
    """The summands ``(shift, n)`` of Σ^shift F[t]/(t^n) (n None for F[t]) of Equation ``equation`` ("2.5")."""
    text = chapters.read_thesis(THESIS)
    line = next(line for line in text.splitlines() if f"\\quad ({equation})" in line)
    formula = line.split("\\simeq", 1)[1].split("\\quad", 1)[0]
    summands = []
    for term in formula.split("\\oplus"):
        match = re.search(r"(?:\\Sigma\^(\d+)\s*)?\\mathbb\{F\}\[t\](?:/\(t(?:\^(\d+))?\))?", term)
        assert match, f"unexpected summand {term!r}"
        shift = int(match.group(1) or 0)
        torsion = "/(" in term
        summands.append((shift, (int(match.group(2) or 1)) if torsion else None))
    return summands

"""Reading a trace of compute_intervals (thesis_lib.persistence.trace) against Example 2.41 as printed."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from thesis_text import example_2_41_tables, needs_thesis

from thesis_lib.datasets import dense_filtration, example_filtration, named_chain
from thesis_lib.datasets.filtrations import EXAMPLE_NAMES
from thesis_lib.persistence import compute_intervals, trace
from thesis_lib.persistence.trace import (
    ReadOffInterval,
    read_off_intervals,
    read_off_table,
    reduce_steps_text,
    reduced_sizes,
    repeated_passes,
    trace_tables,
)


def traced(filtration, p):
    steps = []
    compute_intervals(filtration, coefficients=p, trace=steps)
    return steps


def simplex(name):
    """The ascending simplex a thesis name stands for and the sign of the thesis's orientation."""
    ((s, sign),) = named_chain({name.strip("()"): 1}, names=EXAMPLE_NAMES).items()
    return s, sign


def as_cell(coefficient, power):
    """A table entry written independently of the library: ±1, ±t, ±t^{k}."""
    mono = "1" if power == 0 else ("t" if power == 1 else f"t^{{{power}}}")
    if mono == "1":
        return f"${coefficient}$"
    return f"${'-' if coefficient < 0 else ''}{mono}$"


def expected_table(printed, rows, columns):
    """The printed matrix in our orientations (ascending simplices), rows and columns named as ours."""
    name = {s: "".join(EXAMPLE_NAMES[v] for v in s) for s in (simplex(c)[0] for c in printed)}
    cells = {}
    for column, entries in printed.items():
        c, c_sign = simplex(column)
        for row, (coefficient, power) in entries.items():
            r, r_sign = simplex(row)
            cells[name.get(r, row), name[c]] = as_cell(c_sign * r_sign * coefficient, power)
    return [[""] + columns] + [[row] + [cells.get((row, column), "0") for column in columns] for row in rows]


ORDER = ["a", "b", "c", "d", "e", "ab", "cd", "ad", "bc", "de", "ce", "cde"]


@needs_thesis
def test_the_boundary_matrix_is_the_first_matrix_of_example_2_41():
    before, _ = trace_tables(traced(example_filtration(), 3), coefficients=3, names=EXAMPLE_NAMES)
    printed, _ = example_2_41_tables()
    assert before == expected_table(printed, ORDER, ORDER)


@needs_thesis
def test_the_reduced_matrix_is_the_second_with_the_labels_ce_and_ed_swapped():
    _, after = trace_tables(traced(example_filtration(), 3), coefficients=3, names=EXAMPLE_NAMES)
    _, printed = example_2_41_tables()
    # the erratum of Example 2.41: the column printed as ce is ed's, the one printed as (ed) is ce's,
    # and so is the marked row printed as (ed)
    swapped = {{"ce": "ed", "(ed)": "ce"}.get(c, c): {{"(ed)": "ce"}.get(r, r): e for r, e in entries.items()}
               for c, entries in printed.items()}
    marked = ["a", "b", "c", "d", "e", "bc", "ce"]
    assert after == expected_table(swapped, marked, ORDER)


def test_tables_over_z2_have_no_signs():
    before, after = trace_tables(traced(example_filtration(), 2), coefficients=2, names=EXAMPLE_NAMES)
    cells = [x for row in before[1:] + after[1:] for x in row[1:]]
    assert not any("-" in x for x in cells)
    assert sum(x != "0" for row in before[1:] for x in row[1:]) == 6 * 2 + 3  # two faces per edge, three for cde


def test_reduce_steps_name_the_thesis_pairs_and_cycles():
    lines = reduce_steps_text(traced(example_filtration(), 3), coefficients=3, names=EXAMPLE_NAMES)
    assert len(lines) == 2 * 7  # two lines per edge and triangle
    outcome = {head.split("(")[1].split(")")[0]: tail.rsplit(": ", 1)[1] for head, tail in zip(lines[::2], lines[1::2])}
    # Example 2.41 reads off (b, ab), (d, cd), (c, da), (e, ed), (ce, ced) and the cycles bc, ce (z_1, z_2)
    assert outcome == {"ab": "stored in T[b]", "cd": "stored in T[d]", "ad": "stored in T[c]", "de": "stored in T[e]",
                       "cde": "stored in T[ce]", "bc": "marked (a cycle)", "ce": "marked (a cycle)"}
    # ∂(cde) = de − ce + cd; its faces de and cd are unmarked (they kill classes) and are dropped
    assert lines[12] == "Reduce(cde): ∂ = cd + de − ce; drop unmarked de, cd"


def test_repeated_passes_of_the_literal_loop():
    # Reduce(bc) over Z/3: ∂bc = 2b + c; minus T[c] = 2a + c leaves 2b + a; minus T[b] = 2a + b twice
    # clears b (coefficient 2 needs two passes): one repeat.  Every other call subtracts each row once.
    K = example_filtration()
    assert repeated_passes(traced(K, 3)) == 1
    assert "subtract T[c]; T[b] (2 passes) ⇒ 0: marked (a cycle)" in reduce_steps_text(traced(K, 3), coefficients=3,
                                                                                      names=EXAMPLE_NAMES)[7]
    # over Z/2 every coefficient is 1, so each pass lowers the largest index
    for seed in range(3):
        assert repeated_passes(traced(dense_filtration(7, seed=seed), 2)) == 0


def test_reduced_sizes_are_zero_exactly_for_cycles():
    steps = traced(example_filtration(), 3)
    sizes = reduced_sizes(steps, names=EXAMPLE_NAMES)
    # the erratum of Example 2.41: ce is a cycle (empty column), ed = de is stored with two entries
    assert sizes["ce"] == 0 and sizes["de"] == 2
    assert {name for name, n in sizes.items() if n == 0} == {"a", "b", "c", "d", "e", "bc", "ce"}


def test_read_off_intervals_are_the_thesis_list():
    K = example_filtration()
    read = read_off_intervals(traced(K, 3))
    degree = {tuple(map(int, s)): float(v) for d in range(3) for s, v in zip(K.simplices[d], K.values[d])}
    # Example 2.41, with ce and ed swapped (the erratum): (a, ∞), (b, ab), (d, cd), (c, da), (e, ed),
    # (bc, ∞), (ce, ced)
    printed = [("a", None), ("b", "ab"), ("d", "cd"), ("c", "da"), ("e", "ed"), ("bc", None), ("ce", "ced")]
    expected = {(simplex(c)[0], None if k is None else simplex(k)[0]) for c, k in printed}
    assert {(iv.creator, iv.killer) for iv in read} == expected
    for iv in read:
        assert iv.birth == degree[iv.creator] and iv.death == (math.inf if iv.killer is None else degree[iv.killer])
    # every simplex is in exactly one pair (Algorithm 2 pairs or marks each)
    used = [iv.creator for iv in read] + [iv.killer for iv in read if iv.killer is not None]
    assert sorted(used) == sorted(degree)


def test_read_off_table_marks_zero_length():
    read = read_off_intervals(traced(example_filtration(), 3))
    rows = read_off_table(read, names=EXAMPLE_NAMES)
    assert len(rows) == 1 + len(read) == 8
    notes = [r[0] for r in rows[1:] if r[2]]
    assert notes == ["$(d, cd)$"]  # (deg d, deg cd) = (1, 1)
    assert rows[-1][1] == "$(2, \\infty)$"
    assert read_off_table([ReadOffInterval((0,), None, 0.5, math.inf)])[1] == ["$(0, \\infty)$", "$(0.5, \\infty)$",
                                                                               ""]


def test_bad_traces_are_refused():
    for bad in ([], [{"j": 0}]):
        with pytest.raises(ValueError, match="full list"):
            trace_tables(bad, coefficients=2)
        with pytest.raises(ValueError, match="full list"):
            read_off_intervals(bad)


def test_random_traces_read_off_the_barcode():
    # the intervals read off the trace, zero-length ones left out, are compute_intervals' barcode
    for seed in range(3):
        K = dense_filtration(6, seed=seed)
        bars = compute_intervals(K, coefficients=2)
        read = read_off_intervals(traced(K, 2))
        for d in range(3):
            ours = sorted((iv.birth, iv.death) for iv in read if len(iv.creator) == d + 1 and iv.birth != iv.death)
            assert np.array_equal(np.array(ours).reshape(-1, 2), bars.intervals(d))


def test_docstring_examples_run():
    result = doctest.testmod(trace)
    assert result.attempted > 5 and result.failed == 0

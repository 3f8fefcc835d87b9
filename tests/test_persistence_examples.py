"""The worked examples of §2.3 (thesis_lib.persistence.examples) against what the thesis prints."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from thesis_text import example_2_41_tables, needs_thesis, printed_module

from thesis_lib.datasets import example_filtration, module_filtration
from thesis_lib.datasets.filtrations import (
    EQUATION_2_5,
    EQUATION_2_6,
    EXAMPLE_2_40_CYCLES,
    EXAMPLE_2_41_MATRIX,
    EXAMPLE_NAMES,
    simplex_labels,
)
from thesis_lib.homology.filtration import Filtration
from thesis_lib.persistence import Barcode, compute_intervals, examples, persistence
from thesis_lib.persistence.examples import (
    CycleCheck,
    cycle_check,
    cycle_table,
    interval_summary,
    intervals_text,
    matrix_agreement,
    module_intervals,
    module_mismatches,
    row_order_check,
    row_order_table,
)

INF = math.inf


def traced(filtration, p):
    steps = []
    compute_intervals(filtration, coefficients=p, trace=steps)
    return steps


# ------------------------------------------------------------------ transcriptions
@needs_thesis
def test_the_transcriptions_are_the_printed_ones():
    printed, _ = example_2_41_tables()
    assert EXAMPLE_2_41_MATRIX == {c: e for c, e in printed.items() if e}
    assert sorted(EQUATION_2_5, key=str) == sorted(printed_module("2.5"), key=str)
    assert sorted(EQUATION_2_6, key=str) == sorted(printed_module("2.6"), key=str)


def test_simplex_labels_invert_named_chain():
    from thesis_lib.datasets import named_chain

    for word in ("ab", "cde", "e"):
        ((s, _),) = named_chain({word: 1}).items()
        assert simplex_labels([s], names=EXAMPLE_NAMES) == [word]
    assert simplex_labels([(10, 2)]) == ["10,2"]


# ------------------------------------------------------------------ Example 2.36, Equations 2.5–2.6
def test_module_intervals_of_example_2_36():
    # Example 2.36: F[t] ⊕ Σ¹F[t] ⊕ Σ²F[t]/(t²) has S = {(0, ∞), (1, ∞), (2, 4)}
    assert module_intervals([(0, None), (1, None), (2, 2)]) == [(0.0, INF), (1.0, INF), (2.0, 4.0)]
    assert module_intervals([]) == []


def test_computed_barcodes_are_the_modules_they_realise():
    for summands in ([(0, None), (1, None), (2, 2)], [(3, 1), (0, 5), (0, 5)], [(1, None)]):
        bars = compute_intervals(module_filtration(summands, dim=1))
        assert module_mismatches(bars.intervals(1), summands) == 0
        assert module_mismatches(bars.intervals(1), summands[1:]) == 1


def test_example_2_40_is_equations_2_5_and_2_6():
    bars = compute_intervals(example_filtration(), coefficients=3)
    assert module_mismatches(bars.intervals(0), EQUATION_2_5) == 0
    assert module_mismatches(bars.intervals(1), EQUATION_2_6) == 0
    assert module_mismatches(bars.intervals(1), EQUATION_2_5) == 6  # two vs four intervals, none shared


def test_module_mismatches_counts_multisets():
    assert module_mismatches([(0, 1), (0, 1)], [(0, 1)]) == 1
    assert module_mismatches(np.empty((0, 2)), [(0, None), (2, 1)]) == 2


def test_interval_summary_and_text():
    iv = [(0.0, 1.0), (0.0, INF), (1.0, 2.0), (2.0, INF)]
    s = interval_summary(iv)
    assert (s.n_intervals, s.n_essential, s.essential_births, s.finite) == (4, 2, (0.0, 2.0), ((0.0, 1.0), (1.0, 2.0)))
    text = intervals_text(iv)
    assert text == "(0, 1), (0, ∞), (1, 2), (2, ∞)"
    back = [tuple(INF if x == "∞" else float(x) for x in pair.strip("()").split(", ")) for pair in text.split("), (")]
    assert back == iv
    assert intervals_text(np.empty((0, 2))) == "" and interval_summary([]).n_intervals == 0


# ------------------------------------------------------------------ Example 2.41
def test_matrix_agreement_with_the_printed_matrix():
    steps = traced(example_filtration(), 3)
    agreement = matrix_agreement(steps, EXAMPLE_2_41_MATRIX, coefficients=3, names=EXAMPLE_NAMES)
    # 15 printed entries = two faces per edge (6 edges) and three for the triangle
    assert (agreement.compared, agreement.ours_nonzero, agreement.mismatches) == (15, 6 * 2 + 3, 0)
    # a sign, a power and a misplaced entry are each found
    for column, row, entry in (("da", "a", (-1, 2)), ("ab", "b", (1, 2)), ("cd", "a", (1, 0))):
        wrong = {c: dict(e) for c, e in EXAMPLE_2_41_MATRIX.items()}
        wrong[column][row] = entry
        assert matrix_agreement(steps, wrong, coefficients=3, names=EXAMPLE_NAMES).mismatches == 1, (column, row)
    with pytest.raises(ValueError, match="not a simplex"):
        matrix_agreement(steps, {"ae": {"a": (1, 1)}}, coefficients=3, names=EXAMPLE_NAMES)


# ------------------------------------------------------------------ Example 2.40
def test_the_cycles_of_example_2_40():
    fast = persistence(example_filtration(), coefficients=3)
    z1 = cycle_check(fast, EXAMPLE_2_40_CYCLES["z1"], names=EXAMPLE_NAMES)
    z2 = cycle_check(fast, EXAMPLE_2_40_CYCLES["z2"], names=EXAMPLE_NAMES)
    # Equation 2.6 and the text: z_1 (the square abcd) is born at 2 and never dies, z_2 is born at 3
    # and bounds ced from 4 on
    assert (z1.boundary_terms, z1.degree, z1.bar, z1.matches_representative) == (0, 2.0, (2.0, INF), True)
    assert (z2.boundary_terms, z2.degree, z2.bar, z2.matches_representative) == (0, 3.0, (3.0, 4.0), True)


def test_cycle_check_sees_non_cycles_and_multiples():
    fast = persistence(example_filtration(), coefficients=3)
    twice = {word: 2 * c for word, c in EXAMPLE_2_40_CYCLES["z1"].items()}
    assert cycle_check(fast, twice, names=EXAMPLE_NAMES).matches_representative  # 2·z_1 is a multiple
    flipped = dict(EXAMPLE_2_40_CYCLES["z1"], ab=-1)
    check = cycle_check(fast, flipped, names=EXAMPLE_NAMES)
    assert check.boundary_terms == 2 and not check.matches_representative  # ∂ab counted twice: 2a − 2b ≠ 0
    path = cycle_check(fast, {"ab": 1}, names=EXAMPLE_NAMES)  # born at 1, where no H₁ bar is born
    assert (path.boundary_terms, path.bar, path.matches_representative) == (2, None, False)
    # z_1 + z_2 is a cycle born at 3, but not the representative of the bar born there
    summed = cycle_check(fast, {**EXAMPLE_2_40_CYCLES["z1"], "ed": 1, "ce": 1, "cd": 0}, names=EXAMPLE_NAMES)
    assert summed.boundary_terms == 0 and summed.degree == 3.0 and not summed.matches_representative
    with pytest.raises(ValueError, match="not in the filtration"):
        cycle_check(fast, {"ae": 1}, names=EXAMPLE_NAMES)
    with pytest.raises(ValueError, match="from a filtration"):
        cycle_check(Barcode({1: [(0.0, 1.0)]}), {"ab": 1}, names=EXAMPLE_NAMES)


def test_cycle_table_rows():
    checks = {"z1": CycleCheck({"da": 1, "cd": 1}, 0, 2.0, (2.0, INF), True),
              "z12": CycleCheck({"ed": 1, "cd": -1}, 3, 3.0, None, False)}
    rows = cycle_table(checks)
    assert [r[0] for r in rows[1:]] == ["$z_1$", "$z_12$"]
    assert rows[1][1:] == ["$da + cd$", "yes", "2", "$[2, \\infty)$", "the same"]
    assert rows[2][1:] == ["$ed - cd$", "no", "3", "none", "different"]
    assert all(len(r) == len(rows[0]) for r in rows)


# ------------------------------------------------------------------ §2.3.4
def brute_force_row_order(K, increasing):
    """Columns of M_1 whose powers deg(edge) − deg(row) do not decrease down the rows, from the degrees alone."""
    deg = {int(s[0]): float(v) for s, v in zip(K.simplices[0], K.values[0])}
    rows = sorted(deg, key=lambda v: deg[v])  # a stable sort by degree: ties in the filtration's order
    rows = rows if increasing else rows[::-1]
    n = 0
    for edge, value in zip(K.simplices[1], K.values[1]):
        powers = [value - deg[v] for v in rows if v in edge]
        n += powers[0] <= powers[1]
    return n


def test_row_order_of_example_2_40():
    check = row_order_check(example_filtration())
    # the erratum of §2.3.4: rows by increasing degree keep the order only in ab and cd (both vertices
    # enter together); by decreasing degree, the order Example 2.40 prints (e, d, c, b, a), in all six
    assert (check.n_columns, check.with_increasing_rows, check.with_decreasing_rows) == (6, 2, 6)
    assert simplex_labels(check.decreasing_rows, names=EXAMPLE_NAMES) == list("edcba")
    rows = row_order_table(check, names=EXAMPLE_NAMES)
    assert rows[1] == ["by increasing degree: $a$, $b$, $c$, $d$, $e$", 2]
    assert rows[0][1] == "columns (of 6) whose powers of $t$ do not decrease downward"


@pytest.mark.parametrize("seed", range(4))
def test_row_order_on_random_filtrations(seed):
    rng = np.random.default_rng(seed)
    vertices = [((v,), float(rng.integers(0, 3))) for v in range(6)]
    entry = dict((s[0], t) for s, t in vertices)
    edges = [((u, v), max(entry[u], entry[v]) + float(rng.integers(0, 2))) for u in range(6) for v in range(u + 1, 6)
             if rng.random() < 0.6]
    K = Filtration.from_pairs(sorted(vertices + edges, key=lambda p: (p[1], len(p[0]))))
    if K.dimension < 1:
        pytest.skip("no edge drawn")
    check = row_order_check(K)
    assert check.with_increasing_rows == brute_force_row_order(K, True)
    assert check.with_decreasing_rows == brute_force_row_order(K, False) == check.n_columns
    # with increasing rows a column keeps the order exactly when its two vertices enter together
    assert check.with_increasing_rows == sum(entry[u] == entry[v] for (u, v), _ in edges)


def test_row_order_refuses_a_dimension_without_matrix():
    with pytest.raises(ValueError, match="dim must be between 1"):
        row_order_check(example_filtration(), dim=3)


def test_docstring_examples_run():
    result = doctest.testmod(examples)
    assert result.attempted > 10 and result.failed == 0

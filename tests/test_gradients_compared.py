"""Critical fractions of the greedy Morse matching and of the apparent pairs (morse.critical_fractions)."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib.complexes import rips
from thesis_lib.homology import betti_numbers
from thesis_lib.morse.gradients_compared import critical_fractions
from thesis_lib.morse.reduction import morse_reduce
from thesis_lib.persistence import apparent_pairs


@pytest.mark.parametrize("seed", range(6))
def test_fractions_count_the_unpaired_cells(seed):
    f = rips(np.random.default_rng(seed).random((9, 2)), max_radius=0.45, max_dim=2)
    r = critical_fractions(f)
    n = len(f)
    paired = {tuple(s) for pair in apparent_pairs(f) for s in pair}
    assert r["simplices"] == n
    assert r["apparent"] == pytest.approx((n - len(paired)) / n)
    top = f.simplices[-1].shape[0]
    paired_below = sum(1 for s in paired if len(s) < 3)
    assert r["apparent_below_top"] == pytest.approx((n - top - paired_below) / (n - top))
    greedy = morse_reduce(f)
    assert r["greedy"] == pytest.approx(greedy.n_critical / n)
    # weak Morse inequalities (Theorem 4.27): at least β_k critical k-cells, so the fractions are bounded below
    beta = betti_numbers(f)
    assert greedy.n_critical >= sum(beta)
    assert r["apparent"] * n >= sum(beta)
    assert 0 <= r["zero_apparent_below_top"] <= 1

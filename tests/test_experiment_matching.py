"""The gradient of the rp2-morse experiment (morse.experiment_matching)."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib import morse
from thesis_lib.homology import betti_numbers


@pytest.mark.parametrize("name", morse.COMPLEX_NAMES)
@pytest.mark.parametrize("heuristic", ["coreduction", "collapse", "lower-star"])
def test_every_experiment_gradient_is_acyclic_and_bounds_the_betti_numbers(name, heuristic):
    facets, positions, _ = morse.experiment_complex(name, seed=1)
    pairs = morse.experiment_matching(facets, heuristic=heuristic, positions=positions, seed=1)
    assert morse.is_acyclic(facets, pairs)
    counts = morse.critical_counts(facets, pairs)
    assert all(c >= b for c, b in zip(counts, betti_numbers(facets, coefficients=2)))  # Theorem 4.27


def test_lower_star_reads_the_x_coordinates_or_draws_with_the_seed():
    facets, positions, _ = morse.experiment_complex("random-flag", seed=0)
    x = np.array([positions[v][0] for v in range(len(positions))])
    expected = morse.morse_matching(facets, heuristic="lower-star", values=x)
    assert morse.experiment_matching(facets, heuristic="lower-star", positions=positions) == expected
    drawn = np.random.default_rng(4).random(6)
    assert morse.experiment_matching(list(morse.RP2_FACETS), heuristic="lower-star", seed=4) == morse.morse_matching(
        morse.RP2_FACETS, heuristic="lower-star", values=drawn)
    with pytest.raises(ValueError, match="no entry for vertices"):
        morse.experiment_matching(facets, heuristic="lower-star", positions={0: (0.0, 0.0)})
    with pytest.raises(ValueError):
        morse.experiment_matching(facets, heuristic="steepest", seed=0)

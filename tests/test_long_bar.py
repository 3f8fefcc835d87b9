"""One long bar among short ones (thesis_lib.persistence.long_bar): Figure 2.9's reading of a barcode."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest

from thesis_lib.complexes import alpha
from thesis_lib.datasets import noisy_circle
from thesis_lib.persistence import Barcode, long_bar, persistence
from thesis_lib.persistence.long_bar import busiest_birth, long_bar_summary, winding_parity


def polygon_cycle(n):
    return [((k, (k + 1) % n) if k + 1 < n else (0, n - 1), 1) for k in range(n)]


@pytest.mark.parametrize("n", [3, 4, 7])
def test_winding_parity_of_regular_polygons(n):
    angles = 2 * np.pi * (np.arange(n) + 0.3) / n
    ring = np.c_[np.cos(angles), np.sin(angles)]
    cycle = polygon_cycle(n)
    assert winding_parity(cycle, ring) == 1  # around its centre
    assert winding_parity(cycle, ring, centre=(5.0, 0.0)) == 0  # a point outside
    assert winding_parity(cycle, ring + 3.0, centre=(3.0, 3.0)) == 1  # moved with its centre
    # two copies of the polygon wind twice: an even number of crossings
    twice = cycle + [((a + n, b + n), c) for (a, b), c in cycle]
    assert winding_parity(twice, np.vstack([ring, ring])) == 0


def test_winding_parity_refuses_bad_input():
    with pytest.raises(ValueError, match="shape"):
        winding_parity([((0, 1), 1)], np.zeros((3, 3)))
    with pytest.raises(ValueError, match="cycle of edges"):
        winding_parity([((0, 1, 2), 1)], np.zeros((3, 2)))


def test_summary_of_a_hand_made_barcode():
    bars = Barcode({1: [(0.1, 0.9), (0.0, 0.05), (0.2, 0.3), (0.25, 0.25 + 1e-12)]})
    s = long_bar_summary(bars, min_length=1e-9)
    iv = bars.intervals(1)
    assert tuple(iv[s.index]) == (0.1, 0.9) and (s.birth, s.death) == (0.1, 0.9)
    assert s.n_bars == 3  # the bar of length 1e-12 is left out
    assert s.second_length == pytest.approx(0.1) and s.ratio == pytest.approx(0.8 / 0.1)
    assert s.last_noise_death == 0.3
    assert s.betti_once_noise_dies == 1  # at 0.3 only the long bar is alive
    assert s.n_enclosing is s.encloses is s.short_enclosing is None
    alone = long_bar_summary(Barcode({1: [(0.0, 1.0)]}))
    assert (alone.second_length, alone.ratio, alone.last_noise_death) == (0.0, math.inf, -math.inf)
    with pytest.raises(ValueError, match="longer than min_length"):
        long_bar_summary(Barcode({1: [(0.0, 1e-12)]}), min_length=1e-9)
    with pytest.raises(ValueError, match="longer than min_length"):
        long_bar_summary(Barcode({1: []}))


def test_on_a_noisy_circle_only_the_long_cycle_goes_around_the_centre():
    points = noisy_circle(40, noise=0.05, seed=3)
    bars = persistence(alpha(points))
    s = long_bar_summary(bars, points=points, min_length=1e-9)
    iv = bars.intervals(1)
    lengths = iv[:, 1] - iv[:, 0]
    assert s.index == int(np.argmax(lengths)) and s.n_bars == int((lengths > 1e-9).sum())
    assert s.encloses and s.n_enclosing == 1 and s.short_enclosing == 0
    assert s.ratio > 5
    # the centre moved off the hole: no cycle goes around it
    off = long_bar_summary(bars, points=points, min_length=1e-9, centre=(3.0, 0.0))
    assert off.n_enclosing == 0 and off.encloses is False


def test_busiest_birth_counts_bars_alive():
    bars = Barcode({1: [(0.0, 1.0), (0.5, 0.6), (0.55, 0.7), (0.8, 0.9)]})
    alive = {b: sum(1 for c, d in bars.intervals(1) if c <= b < d) for b in bars.intervals(1)[:, 0]}
    assert busiest_birth(bars) == max(alive, key=alive.get) == 0.55
    with pytest.raises(ValueError, match="no interval"):
        busiest_birth(Barcode({1: []}))


def test_docstring_examples_run():
    result = doctest.testmod(long_bar)
    assert result.attempted > 3 and result.failed == 0

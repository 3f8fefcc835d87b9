"""Refusals up front, by name, of what the library cannot compute (issue 21, the second hostile-input
round): invalid seeds, values outside the float range, type confusion and sizes that cannot fit.

Each test asserts the error and its message, or the value where the input is valid; the families
these cases stand for are fuzzed in ``tests/test_hostile_fuzz.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib._validate import InvalidTypeError, check_seed
from thesis_lib.complexes import build_filtration
from thesis_lib.morse import morse_matching

BAD_SEEDS = [True, False, [1, 2], np.array([1]), np.array(3), 1.5, 2.0, "1", -1, 1j, b"1"]


@pytest.mark.parametrize("seed", BAD_SEEDS, ids=repr)
def test_invalid_seeds_are_refused_by_name(seed):
    with pytest.raises((ValueError, TypeError), match="seed must be"):
        check_seed(seed)
    with pytest.raises((ValueError, TypeError), match="seed must be"):
        morse_matching([(0, 1, 2)], seed=seed)
    with pytest.raises((ValueError, TypeError), match="seed must be"):
        build_filtration("rips", np.zeros((2, 2)), 1.0, 1, seed=seed)


def test_valid_seeds_are_kept():
    assert check_seed(np.int64(7)) == 7 and check_seed(2**80) == 2**80
    assert check_seed(None, optional=True) is None
    with pytest.raises(InvalidTypeError, match="seed must be a non-negative integer, got None"):
        check_seed(None)
    tri = [(0, 1, 2), (1, 2, 3), (2, 3, 4)]
    assert morse_matching(tri, seed=np.int64(3)) == morse_matching(tri, seed=3)
    assert morse_matching(tri, seed=None) == morse_matching(tri)

"""Algorithm 1 (Reduce) as printed in §2.3.5: ``d = d − q⁻¹T[i]`` inside the while loop.

The literal loop subtracts ``q⁻¹T[i]`` once per pass, so a term σ^i of coefficient c > 1 is met c
times; the tests check that this is what the trace shows, that it ends within (p − 1)·j passes, and
that the reduced chains are those of the one-step elimination ``d − d_i q⁻¹T[i]`` (written out here
as an independent reference), so the intervals equal the fast engine's and GUDHI's.
"""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib.complexes import Filtration, rips
from thesis_lib.datasets import dense_filtration, example_filtration
from thesis_lib.persistence import Barcode, compute_intervals, persistence


def one_step_reduction(f: Filtration, p: int) -> list[dict[int, int]]:
    """Reference: the reduced chain of every simplex, each pivot cleared in one subtraction."""
    order = [(d, j) for d in range(f.dimension + 1) for j in np.argsort(f.values[d], kind="stable")]
    sigma = [tuple(int(v) for v in f.simplices[d][j]) for d, j in order]
    index = {s: i for i, s in enumerate(sigma)}
    stored: dict[int, dict[int, int]] = {}
    marked: set[int] = set()
    out = []
    for j, s in enumerate(sigma):
        d = {} if len(s) == 1 else {index[s[:k] + s[k + 1:]]: (-1) ** k % p for k in range(len(s))}
        d = {i: c for i, c in d.items() if i in marked}
        while d and max(d) in stored:
            i = max(d)
            col = stored[i]
            factor = d[i] * pow(col[i], p - 2, p) % p
            for k, c in col.items():
                v = (d.get(k, 0) - factor * c) % p
                d.pop(k, None) if v == 0 else d.__setitem__(k, v)
        if d:
            stored[max(d)] = d
        else:
            marked.add(j)
        out.append(dict(d))
    return out


def gudhi_barcode(f: Filtration, p: int) -> Barcode:
    pairs = f.to_simplex_tree().persistence(homology_coeff_field=p, min_persistence=0.0, persistence_dim_max=True)
    return Barcode.from_pairs(pairs, dimensions=range(f.dimension + 1))


FILTRATIONS = {
    "example-2.40": example_filtration,
    "rips-12": lambda: rips(np.random.default_rng(4).random((12, 2)), max_radius=0.6, max_dim=3),
    "dense-9": lambda: dense_filtration(9, seed=2),
}


@pytest.mark.parametrize("name", sorted(FILTRATIONS))
@pytest.mark.parametrize("p", [2, 3, 5, 7])
def test_literal_reduce_equals_one_step_elimination(name, p):
    f = FILTRATIONS[name]()
    trace: list = []
    bars = compute_intervals(f, coefficients=p, trace=trace)
    assert [r["result"] for r in trace] == one_step_reduction(f, p)
    assert bars == persistence(f, coefficients=p)
    assert bars.difference(gudhi_barcode(f, p)) is None


@pytest.mark.parametrize("p", [3, 5, 7])
def test_each_pass_subtracts_q_inverse_times_the_stored_column(p):
    f = dense_filtration(9, seed=0)
    trace: list = []
    compute_intervals(f, coefficients=p, trace=trace)
    repeated = 0
    for r in trace:
        removed = {trace[0]["order"].index(s) for s in r["removed"]}
        d = {i: c for i, c in r["boundary"].items() if i not in removed}
        for step in r["steps"]:
            # the loop's pivot is the largest index of the current chain, and the factor is q⁻¹ itself
            assert step["i"] == max(d) and step["q"] == step["T"][step["i"]]
            assert step["factor"] * step["q"] % p == 1
            before = d[step["i"]]
            for k, c in step["T"].items():
                v = (d.get(k, 0) - step["factor"] * c) % p
                d.pop(k, None) if v == 0 else d.__setitem__(k, v)
            # one pass lowers the pivot's coefficient by exactly one (it vanishes when it was 1)
            assert d.get(step["i"], 0) == before - 1
            repeated += before > 1
        assert d == r["result"]
        assert len(r["steps"]) <= (p - 1) * r["j"]  # the termination bound of the module docstring
    assert repeated > 0  # over Z/p, p > 2, some coefficient ≠ 1 does come back to the same row


def test_over_z2_every_pass_lowers_the_largest_index():
    trace: list = []
    compute_intervals(dense_filtration(9, seed=1), coefficients=2, trace=trace)
    for r in trace:
        pivots = [s["i"] for s in r["steps"]]
        assert pivots == sorted(set(pivots), reverse=True)
        assert len(pivots) <= r["j"]

"""Morse reduction before persistence (thesis §4.2.6: "simplify simplicial complexes that are too large").

Usage: ``python benchmarks/bench_morse.py [--quick] [--rounds N] [--output FILE]``; writes
``benchmarks/results/morse.json`` (``morse_quick.json`` with ``--quick``).

A **step-only** comparison: every contender starts from the same stored filtration (built before
timing), so the figures are the persistence step, named as such.  Contenders, interleaved over
rounds by the harness (medians, median of paired ratios):

* ``ours``: ``reduced_persistence(morse_reduce(f))`` — equal-value greedy coreductions, the Morse
  boundary by gradient paths (Theorem 4.42), then the column reduction of the Morse complex;
* ``engine``: ``persistence(f)``, the explicit engine on the whole filtration;
* ``gudhi``: GUDHI's ``compute_persistence`` on a ``SimplexTree`` built from the same filtration.

``critical_fraction`` is the Morse reduction's critical cells over all cells;
``apparent_critical_below_top`` the fraction of cells below the top dimension in no apparent pair
(:func:`thesis_lib.persistence.apparent_summary`), the ones the implicit Rips engine reduces.  Every
run checks that the three barcodes are equal.  Peak memory: each contender once more in a fresh
process, above its baseline after imports and input.
"""

from __future__ import annotations

import sys

import harness
import numpy as np

CASES = ["two-circles-20", "two-circles-40", "two-circles-60", "flat-torus-20",
         "lower-star-grid-100", "lower-star-grid-300"]
# make bench-check's cases: the engine's 0.7 ms on two-circles-20 made its ratio move by 25 % between runs
QUICK = ["two-circles-40", "lower-star-grid-100"]


def grid_triangles(n: int) -> np.ndarray:
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a = (i * n + j).ravel()
    b, c, d = a + 1, a + n, a + n + 1
    return np.vstack([np.column_stack([a, b, d]), np.column_stack([a, c, d])])


def build(case: str):
    from thesis_lib.complexes.rips import rips
    from thesis_lib.datasets import flat_torus, two_circles
    from thesis_lib.morse import lower_star_filtration

    kind, n = case.rsplit("-", 1)
    n = int(n)
    if kind == "two-circles":
        return rips(two_circles(n, seed=0), max_radius=2.0, max_dim=2)
    if kind == "flat-torus":
        return rips(flat_torus(n, noise=0.02, seed=0), max_radius=0.5, max_dim=3)
    if kind == "lower-star-grid":
        vals = np.random.default_rng(0).random(n * n)
        return lower_star_filtration([tuple(t) for t in grid_triangles(n).tolist()], vals)
    raise ValueError(case)


def contenders(f) -> dict:
    from thesis_lib.morse import morse_reduce, reduced_persistence
    from thesis_lib.persistence import Barcode, persistence

    st = f.to_simplex_tree()

    def gudhi():
        st.compute_persistence(homology_coeff_field=2, min_persistence=0, persistence_dim_max=True)
        return Barcode.from_pairs(st.persistence(homology_coeff_field=2, min_persistence=0,
                                                 persistence_dim_max=True), dimensions=range(f.dimension + 1))

    return {"ours": lambda: reduced_persistence(morse_reduce(f, coefficients=2)),
            "engine": lambda: persistence(f, coefficients=2), "gudhi": gudhi}


def check(results: dict) -> None:
    ref = results["engine"]
    for name, bc in results.items():
        diff = ref.difference(bc, atol=1e-9)
        if diff is not None:
            raise AssertionError(f"{name}: {diff}")


def memory_child(tool: str, case: str) -> None:
    def setup():
        contenders(build("two-circles-6"))[tool]()  # imports and compiled code (the baseline)
        return contenders(build(case))[tool]

    harness.memory_worker(setup, lambda run: run())


def run_case(case: str, rounds: int | None) -> dict:
    from thesis_lib.morse import morse_reduce
    from thesis_lib.persistence import apparent_summary

    f = build(case)
    res = harness.compare(contenders(f), rounds=rounds, check=check)
    red = morse_reduce(f, coefficients=2)
    row = {"case": case, "n_cells": len(f), "n_critical": red.n_critical, "critical_fraction": red.critical_fraction,
           "critical_per_dim": [int(c.shape[0]) for c in red.critical],
           "apparent_critical_below_top": apparent_summary(f)["critical_fraction_below_top"],
           "same_barcode": True, "step_only": True}
    row.update(harness.ratio_fields(res, "ours"))
    for tool in ("ours", "engine", "gudhi"):
        row.update(harness.memory_fields(__file__, tool, tool, case))
    return row


COLUMNS = [("case", "{case}"), ("cells", "{n_cells}"), ("critical", "{critical_fraction:.3f}"),
           ("apparent, below top", "{apparent_critical_below_top:.3f}"), ("rounds", "{rounds}"),
           ("ours s", "{ours_s:.3g}"), ("ours/engine", "{ratio_engine:.2f}"), ("ours/GUDHI", "{ratio_gudhi:.2f}")]


def main(argv: list[str] | None = None) -> list[dict]:
    return harness.run_cases(
        "morse", __doc__, argv, cases=CASES, quick=QUICK, full=CASES, columns=COLUMNS, run_case=run_case,
        memory_child=memory_child, quick_help="one small case (make bench-check)"
    )


if __name__ == "__main__":
    main(sys.argv[1:])

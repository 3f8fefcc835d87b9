"""Morse reduction before persistence (thesis §4.2.6: "simplify simplicial complexes that are too large").

Usage: ``python benchmarks/bench_morse.py [--quick] [--repeat N] [--output FILE]`` (``--quick``
writes ``benchmarks/results/morse_quick.json`` unless ``--output`` is given).

For each case the filtration is built first (not timed).  Then, best of ``--repeat`` runs:

* ``reduce_s``: ``thesis_lib.morse.morse_reduce(f, 2)``: equal-value greedy coreduction matching
  plus the Morse boundary over Z/2 by gradient paths (Theorem 4.42);
* ``reduced_pers_s``: ``reduced_persistence`` of the Morse complex (our column reduction with clearing);
* ``ours_s = reduce_s + reduced_pers_s``;
* ``direct_column_s``: the same column reduction on the unreduced complex;
* ``engine_s``: ``thesis_lib.persistence.persistence(f, 2)`` (the project's fast engine);
* ``ref_s``: GUDHI ``SimplexTree`` from the same filtration (not timed) then ``compute_persistence``.

Peak memory is ``tracemalloc`` (Python-side allocations; numba-internal buffers are not seen).
Every run checks that the reduced barcode equals the engine's.  Cases: two circles
(``two_circles(n, seed=0)``, Rips ε ≤ 2, dim ≤ 2, the Figure 2.14 setting), a Rips complex of the
flat torus in R⁴ with dim ≤ 3, and a lower-star filtration of random vertex values on an n × n grid.
"""

from __future__ import annotations

import harness
import numpy as np


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
        return rips(two_circles(n, seed=0), 2.0, 2)
    if kind == "flat-torus":
        return rips(flat_torus(n, noise=0.02, seed=0), 0.5, 3)
    if kind == "lower-star-grid":
        vals = np.random.default_rng(0).random(n * n)
        return lower_star_filtration([tuple(t) for t in grid_triangles(n).tolist()], vals)
    raise ValueError(case)


def run_case(case: str, repeat: int) -> dict:
    from thesis_lib.morse import chain_persistence, morse_reduce, reduced_persistence
    from thesis_lib.persistence import persistence
    from thesis_lib.simplicial import boundary_matrix

    f = build(case)
    reduce_s, red, reduce_mb = harness.tracemalloc_timed(lambda: morse_reduce(f, 2), repeat)
    pers_s, bar, pers_mb = harness.tracemalloc_timed(lambda: reduced_persistence(red), repeat)
    engine_s, ref_bar, engine_mb = harness.tracemalloc_timed(lambda: persistence(f, 2), repeat)
    assert bar == ref_bar, bar.difference(ref_bar)
    bds = [np.zeros((0, f.simplices[0].shape[0]))]
    bds += [boundary_matrix(f.simplices[d - 1], f.simplices[d]) for d in range(1, f.dimension + 1)]
    direct_s, direct_bar, direct_mb = harness.tracemalloc_timed(
        lambda: chain_persistence(f.values, bds, 2), max(1, repeat - 1)
    )
    assert direct_bar == ref_bar
    st = f.to_simplex_tree()
    ref_s, _, ref_mb = harness.tracemalloc_timed(
        lambda: st.compute_persistence(homology_coeff_field=2, min_persistence=0, persistence_dim_max=True), repeat
    )
    ours = reduce_s + pers_s
    return {
        "case": case,
        "n_cells": len(f),
        "n_critical": red.n_critical,
        "critical_fraction": red.critical_fraction,
        "critical_per_dim": [int(c.shape[0]) for c in red.critical],
        "reduce_s": reduce_s,
        "reduced_pers_s": pers_s,
        "ours_s": ours,
        "direct_column_s": direct_s,
        "engine_s": engine_s,
        "ref_s": ref_s,
        "ratio": ours / ref_s,
        "ours_mb": max(reduce_mb, pers_mb),
        "direct_column_mb": direct_mb,
        "engine_mb": engine_mb,
        "ref_mb": ref_mb,
        "same_barcode": True,
    }


COLUMNS = [
    ("case", "{case}"),
    ("cells", "{n_cells}"),
    ("critical", "{n_critical}"),
    ("fraction", "{critical_fraction:.3f}"),
    ("reduce s", "{reduce_s:.3f}"),
    ("reduced pers s", "{reduced_pers_s:.3f}"),
    ("ours s", "{ours_s:.3f}"),
    ("direct column s", "{direct_column_s:.3f}"),
    ("engine s", "{engine_s:.3f}"),
    ("GUDHI s", "{ref_s:.3f}"),
    ("ours/GUDHI", "{ratio:.2f}"),
]


def main() -> None:
    args = harness.arguments(__doc__, quick_help="one small case (smoke test)", repeat=3, output=True)
    from thesis_lib.morse import morse_reduce, reduced_persistence
    from thesis_lib.persistence import persistence

    warm = build("two-circles-6")  # warm-up: numba compilation excluded
    reduced_persistence(morse_reduce(warm, 2))
    persistence(warm, 2)
    cases = ["two-circles-20"] if args.quick else [
        "two-circles-20", "two-circles-40", "two-circles-60", "flat-torus-20", "lower-star-grid-100", "lower-star-grid-300"
    ]
    rows = [run_case(c, 1 if args.quick else args.repeat) for c in cases]
    harness.print_table(COLUMNS, rows)
    harness.write_rows("morse", rows, args.quick, args.output)  # --quick: morse_quick.json


if __name__ == "__main__":
    main()

"""Construction of the complexes of §2.1.2: thesis_lib against GUDHI, time and peak memory as ratios.

Usage: ``python benchmarks/bench_complexes.py [--quick] [--rounds N] [--cases NAME ...] [--output FILE]``.

Time: both tools build the same complex from the same points in one process, interleaved
(ours, GUDHI, ours, ...) after a warm-up, for 5 rounds (15 under 0.1 s); the table gives the
medians and ``ratio_gudhi``, the median of the per-round ratios (``harness.compare``).  Whole
constructions are timed: points in, complex out (GUDHI's simplex tree, our ``Filtration``), the
clock stopping while the complex is still alive (neither tool's destructor is timed), and the
warm-up checks that both built the same number of simplices.  Memory: each tool builds the
case once in a fresh process; ``delta_mb`` is the peak resident set above the baseline after
imports, input and warm-up (``harness.memory``).

Pairs compared:

* rips — ``rips(points, max_radius=ε, max_dim=2)`` vs ``RipsComplex(max_edge_length=2ε).create_simplex_tree(2)``;
  the thesis case is two circles with 100 points each, ε <= 2 (1,333,500 simplices).
* alpha — ``alpha(points)`` vs ``AlphaComplex(points).create_simplex_tree()`` (GUDHI's default,
  ``precision="safe"``; ours is exact where it matters, see ``thesis_lib.complexes.predicates``),
  uniform random points; ``alpha-grid`` is an exact 2-D grid (every unit square co-circular: the
  exact predicates' worst case) against GUDHI with ``precision="exact"``.
* alpha-weighted — the same with random weights in [0, 1e-5).
* witness — ``witness(points, landmarks, max_radius=ε, max_dim=3)`` (thesis rule, un-squared offsets) vs
  ``EuclideanStrongWitnessComplex(...).create_simplex_tree(α², 3)`` (squared rule): the complexes
  differ, so read the ratio with the simplex counts.
* cech — GUDHI's Python API has no Čech complex; the reference is its Delaunay–Čech complex on the
  same points (a different, smaller complex with the same miniball values): context only.
"""

from __future__ import annotations

import harness

CASES = {
    "rips-two-circles-20": {"kind": "rips", "data": ("two_circles", 20), "eps": 2.0, "max_dim": 2},
    "rips-two-circles-60": {"kind": "rips", "data": ("two_circles", 60), "eps": 2.0, "max_dim": 2},
    "rips-two-circles-100": {"kind": "rips", "data": ("two_circles", 100), "eps": 2.0, "max_dim": 2},
    "alpha-2d-10000": {"kind": "alpha", "data": ("uniform", 10_000, 2)},
    "alpha-2d-100000": {"kind": "alpha", "data": ("uniform", 100_000, 2)},
    "alpha-3d-2000": {"kind": "alpha", "data": ("uniform", 2_000, 3)},
    "alpha-3d-20000": {"kind": "alpha", "data": ("uniform", 20_000, 3)},
    "alpha-weighted-2d-10000": {"kind": "alpha-weighted", "data": ("uniform", 10_000, 2)},
    "alpha-weighted-2d-100000": {"kind": "alpha-weighted", "data": ("uniform", 100_000, 2)},
    "alpha-grid-2d-100": {"kind": "alpha-grid", "data": ("grid", 100, 2)},
    "witness-torus-20-30": {"kind": "witness", "data": ("flat_torus", 20), "landmarks": 30, "max_dim": 3,
                            "eps": 0.5, "alpha2": 0.5},
    "witness-torus-50-50": {"kind": "witness", "data": ("flat_torus", 50), "landmarks": 50, "max_dim": 3,
                            "eps": 1.0, "alpha2": 2.0},
    "cech-two-circles-20": {"kind": "cech", "data": ("two_circles", 20), "eps": 0.3, "max_dim": 2},
    "cech-two-circles-100": {"kind": "cech", "data": ("two_circles", 100), "eps": 0.3, "max_dim": 2},
}
FULL = ["rips-two-circles-20", "alpha-2d-10000", "alpha-3d-2000", "alpha-weighted-2d-10000",
        "witness-torus-20-30", "cech-two-circles-20", "rips-two-circles-60", "rips-two-circles-100",
        "alpha-2d-100000", "alpha-3d-20000", "alpha-weighted-2d-100000", "alpha-grid-2d-100",
        "witness-torus-50-50", "cech-two-circles-100"]
# make bench-check's cases: none of a millisecond or two (rips-two-circles-20 at 1.2 ms against
# GUDHI's 0.45 ms moved by 30 % between runs; cech and witness at 20 points alike)
QUICK = ["rips-two-circles-60", "alpha-2d-10000", "alpha-3d-2000", "alpha-weighted-2d-10000",
         "witness-torus-50-50", "cech-two-circles-100"]
REFERENCE = {
    "rips": "gudhi RipsComplex (same complex)",
    "alpha": "gudhi AlphaComplex precision=safe (same complex)",
    "alpha-weighted": "gudhi AlphaComplex precision=safe (same complex)",
    "alpha-grid": "gudhi AlphaComplex precision=exact (same complex)",
    "witness": "gudhi EuclideanStrongWitnessComplex (squared rule: a different complex)",
    "cech": "gudhi DelaunayCechComplex (a different complex)",
}


def _input(name: str):
    """(points, weights) of a case."""
    import numpy as np

    from thesis_lib.datasets import flat_torus, two_circles

    case = CASES[name]
    kind = case["data"][0]
    if kind == "two_circles":
        pts = two_circles(case["data"][1], seed=0)
    elif kind == "flat_torus":
        pts = flat_torus(case["data"][1], noise=0.02, seed=0)
    elif kind == "grid":
        side, dim = case["data"][1:]
        pts = np.stack(np.meshgrid(*[np.arange(side)] * dim, indexing="ij"), -1).reshape(-1, dim).astype(float)
    else:
        _, n, dim = case["data"]
        pts = np.random.default_rng(0).random((n, dim))
    weights = np.random.default_rng(1).random(len(pts)) * 1e-5 if case["kind"] == "alpha-weighted" else None
    return pts, weights


def builders(name: str):
    """``{"ours": f, "gudhi": g}``: zero-argument callables building the case, each returning what it
    built (our ``Filtration``, GUDHI's simplex tree), so that the clock stops before it is destroyed."""
    import gudhi

    from thesis_lib import complexes as cx

    case = CASES[name]
    kind = case["kind"]
    pts, weights = _input(name)
    if kind == "rips":
        return {"ours": lambda: cx.rips(pts, max_radius=case["eps"], max_dim=case["max_dim"]),
                "gudhi": lambda: gudhi.RipsComplex(points=pts, max_edge_length=2 * case["eps"])
                .create_simplex_tree(max_dimension=case["max_dim"])}
    if kind == "cech":
        return {"ours": lambda: cx.cech(pts, max_radius=case["eps"], max_dim=case["max_dim"]),
                "gudhi": lambda: gudhi.DelaunayCechComplex(points=pts)
                .create_simplex_tree(max_alpha_square=case["eps"] ** 2)}
    if kind.startswith("alpha"):
        precision = "exact" if kind == "alpha-grid" else "safe"
        return {"ours": lambda: cx.alpha(pts, weights),
                "gudhi": lambda: gudhi.AlphaComplex(points=pts, weights=weights, precision=precision)
                .create_simplex_tree()}
    if kind == "witness":
        lm = cx.maxmin_landmarks(pts, n=case["landmarks"], seed=0)
        return {"ours": lambda: cx.witness(pts, lm, max_radius=case["eps"], max_dim=case["max_dim"]),
                "gudhi": lambda: gudhi.EuclideanStrongWitnessComplex(landmarks=pts[lm], witnesses=pts)
                .create_simplex_tree(max_alpha_square=case["alpha2"], limit_dimension=case["max_dim"])}
    raise ValueError(f"unknown case kind {kind!r}")


def memory_run(name: str, tool: str) -> dict:
    """In a fresh process: peak memory of one construction above the post-warm-up baseline."""

    def setup():
        build = builders(name)[tool]
        build()  # warm-up: caches
        return build

    return harness.memory_worker(setup, lambda build: build())


COLUMNS = [
    ("case", "{case}"),
    ("simplices (ours / GUDHI)", "{ours_simplices} / {gudhi_simplices}"),
    ("ours s", "{ours_s:.4f}"),
    ("GUDHI s", "{gudhi_s:.4f}"),
    ("ratio (median of rounds)", "{ratio_gudhi:.2f}"),
    ("rounds", "{rounds}"),
    ("ours MB", "{ours_mb:.1f}"),
    ("GUDHI MB", "{gudhi_mb:.1f}"),
]


def make_row(name: str, rounds: int | None) -> dict:
    counts = {}

    def check(results):
        counts["ours"], counts["gudhi"] = len(results["ours"]), results["gudhi"].num_simplices()

    result = harness.compare(builders(name), rounds=rounds, check=check)
    row = {"case": name, "kind": CASES[name]["kind"], **harness.ratio_fields(result)}
    row["ours_simplices"], row["gudhi_simplices"] = counts["ours"], counts["gudhi"]
    if CASES[name]["kind"] in ("rips", "alpha", "alpha-weighted", "alpha-grid") and counts["ours"] != counts["gudhi"]:
        raise AssertionError(f"{name}: ours built {counts['ours']} simplices, GUDHI {counts['gudhi']}")
    for tool in ("ours", "gudhi"):
        row.update(harness.memory_fields(__file__, tool, name, tool))
    row["reference"] = REFERENCE[CASES[name]["kind"]]
    return row


def main(argv: list[str] | None = None) -> list[dict]:
    return harness.run_cases(
        "complexes", __doc__, argv, cases=list(CASES), quick=QUICK, full=FULL, columns=COLUMNS, run_case=make_row,
        memory_child=memory_run, memory=("CASE", "TOOL")
    )


if __name__ == "__main__":
    main()

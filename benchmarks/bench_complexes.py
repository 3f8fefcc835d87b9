"""Construction of the complexes of §2.1.2: thesis_lib against GUDHI, time and peak memory as ratios.

Usage: ``python benchmarks/bench_complexes.py [--quick] [--repeat N]``.

Every (case, tool) runs in its own subprocess so that the resident-set high-water mark
(``resource.getrusage``) belongs to that tool alone: build the input, warm up on a small input
(numba compilation excluded), read the RSS mark (``base_mb``), time the construction (best of
``--repeat``), read the mark again; ``work_mb = peak - base`` is what the construction added.

Pairs compared (same input for both tools):

* rips — ``rips(points, ε, 2)`` vs ``RipsComplex(max_edge_length=2ε).create_simplex_tree(2)``; the
  thesis case is two circles with 100 points each, ε <= 2 (1,333,500 simplices).
* alpha — ``alpha(points)`` vs ``AlphaComplex(points).create_simplex_tree()`` (default precision).
* alpha-weighted — the same with weights.
* witness — ``witness(points, landmarks, ε, 3)`` (thesis rule, un-squared offsets) vs
  ``EuclideanStrongWitnessComplex(...).create_simplex_tree(α², 3)`` (GUDHI's strong witness rule with
  squared distances).  The rules differ (see ``thesis_lib.complexes.witness``), so the complexes
  differ too: compare the simplex counts in the table with the times.  (GUDHI's construction with
  α² = inf did not finish in 4 minutes on 400 witnesses and 30 landmarks, so thresholds are finite.)
* cech — GUDHI's Python API has no Čech complex; the reference is its Delaunay–Čech complex on the
  same points (a different, smaller complex with the same miniball values).  Read that ratio as
  context, not as a like-for-like comparison.
"""

from __future__ import annotations

import harness

CASES = {
    "rips-two-circles-20": {"kind": "rips", "data": ("two_circles", 20), "eps": 2.0, "max_dim": 2},
    "rips-two-circles-60": {"kind": "rips", "data": ("two_circles", 60), "eps": 2.0, "max_dim": 2},
    "rips-two-circles-100": {"kind": "rips", "data": ("two_circles", 100), "eps": 2.0, "max_dim": 2},
    "alpha-2d-1000": {"kind": "alpha", "data": ("uniform", 1000, 2)},
    "alpha-2d-100000": {"kind": "alpha", "data": ("uniform", 100_000, 2)},
    "alpha-3d-20000": {"kind": "alpha", "data": ("uniform", 20_000, 3)},
    "alpha-weighted-2d-100000": {"kind": "alpha-weighted", "data": ("uniform", 100_000, 2)},
    "witness-torus-20-30": {"kind": "witness", "data": ("flat_torus", 20), "landmarks": 30, "max_dim": 3,
                            "eps": 0.5, "alpha2": 0.5},
    "witness-torus-50-50": {"kind": "witness", "data": ("flat_torus", 50), "landmarks": 50, "max_dim": 3,
                            "eps": 1.0, "alpha2": 2.0},
    "cech-two-circles-20": {"kind": "cech", "data": ("two_circles", 20), "eps": 0.3, "max_dim": 2},
    "cech-two-circles-100": {"kind": "cech", "data": ("two_circles", 100), "eps": 0.3, "max_dim": 2},
}
FULL = [
    "rips-two-circles-60",
    "rips-two-circles-100",
    "alpha-2d-100000",
    "alpha-3d-20000",
    "alpha-weighted-2d-100000",
    "witness-torus-50-50",
    "cech-two-circles-100",
]
QUICK = ["rips-two-circles-20", "alpha-2d-1000", "witness-torus-20-30", "cech-two-circles-20"]


def _points(case: dict):
    import numpy as np

    from thesis_lib.datasets import flat_torus, two_circles

    kind = case["data"][0]
    if kind == "two_circles":
        return two_circles(case["data"][1], seed=0)
    if kind == "flat_torus":
        return flat_torus(case["data"][1], noise=0.02, seed=0)
    _, n, dim = case["data"]
    return np.random.default_rng(0).random((n, dim))


def worker(tool: str, name: str, repeat: int) -> dict:
    import numpy as np

    case = CASES[name]
    pts = _points(case)
    kind = case["kind"]
    weights = np.random.default_rng(1).random(pts.shape[0]) * 1e-5 if kind == "alpha-weighted" else None
    small = pts[: min(40, pts.shape[0])]
    if tool == "ours":
        from thesis_lib import complexes as cx

        if kind == "rips":
            build = lambda p: cx.rips(p, case["eps"], case["max_dim"])  # noqa: E731
        elif kind == "cech":
            build = lambda p: cx.cech(p, case["eps"], case["max_dim"])  # noqa: E731
        elif kind.startswith("alpha"):
            build = lambda p: cx.alpha(p, None if weights is None else weights[: p.shape[0]])  # noqa: E731
        elif kind == "witness":
            lm_all = cx.maxmin_landmarks(pts, case["landmarks"], seed=0)

            def build(p):
                lm = lm_all if p is pts else np.arange(5)
                return cx.witness(p, lm, case["eps"], case["max_dim"])
        build(small)  # warm-up (numba compilation, cached on disk anyway)
        run = lambda: build(pts)  # noqa: E731
        count = lambda f: len(f)  # noqa: E731
    elif tool == "gudhi":
        import gudhi

        if kind == "rips":
            run = lambda: gudhi.RipsComplex(points=pts, max_edge_length=2 * case["eps"]).create_simplex_tree(  # noqa: E731
                max_dimension=case["max_dim"]
            )
        elif kind == "cech":
            run = lambda: gudhi.DelaunayCechComplex(points=pts).create_simplex_tree(  # noqa: E731
                max_alpha_square=case["eps"] ** 2
            )
        elif kind.startswith("alpha"):
            run = lambda: gudhi.AlphaComplex(points=pts, weights=weights).create_simplex_tree()  # noqa: E731
        elif kind == "witness":
            from thesis_lib.complexes import maxmin_landmarks

            lm = maxmin_landmarks(pts, case["landmarks"], seed=0)
            run = lambda: gudhi.EuclideanStrongWitnessComplex(  # noqa: E731
                landmarks=pts[lm], witnesses=pts
            ).create_simplex_tree(max_alpha_square=case["alpha2"], limit_dimension=case["max_dim"])
        count = lambda s: s.num_simplices()  # noqa: E731
    else:
        raise ValueError(f"unknown tool {tool!r}")
    stats, n = harness.measure_rss(run, repeat, summary=count)  # each output counted, then dropped
    return {**stats, "n_simplices": n}


def run_case(tool: str, name: str, repeat: int) -> dict:
    return harness.run_worker(__file__, tool, name, "--repeat", repeat)


COLUMNS = [
    ("case", "{case}"),
    ("simplices (ours / GUDHI)", "{ours_simplices} / {ref_simplices}"),
    ("ours s", "{ours_s:.4f}"),
    ("GUDHI s", "{ref_s:.4f}"),
    ("time ratio", "{ratio:.2f}"),
    ("ours MB", "{ours_mb:.1f}"),
    ("GUDHI MB", "{ref_mb:.1f}"),
    ("memory ratio", lambda r: "n/a" if r["mem_ratio"] is None else f"{r['mem_ratio']:.2f}"),
]


def make_row(name: str, repeat: int) -> dict:
    """One table row: every tool on case ``name`` (each in its own subprocess)."""
    ours = run_case("ours", name, repeat)
    ref = run_case("gudhi", name, repeat)
    return {
        "case": name,
        "kind": CASES[name]["kind"],
        "ours_s": ours["time_s"],
        "ref_s": ref["time_s"],
        "ratio": ours["time_s"] / ref["time_s"],
        "ours_mb": ours["work_mb"],
        "ref_mb": ref["work_mb"],
        "mem_ratio": ours["work_mb"] / ref["work_mb"] if ref["work_mb"] > 0 else None,
        "ours_peak_mb": ours["peak_mb"],
        "ref_peak_mb": ref["peak_mb"],
        "ours_simplices": ours["n_simplices"],
        "ref_simplices": ref["n_simplices"],
        "reference": "gudhi " + ("DelaunayCechComplex (different complex)" if CASES[name]["kind"] == "cech" else
                                 "EuclideanStrongWitnessComplex (squared rule)" if CASES[name]["kind"] == "witness"
                                 else "same complex"),
        "repeat": repeat,
    }


def main(argv: list[str] | None = None) -> list[dict]:
    return harness.main_per_case("complexes", __doc__, argv, worker=worker, make_row=make_row, columns=COLUMNS,
                                 cases=(QUICK, FULL), repeat=(2, 5))


if __name__ == "__main__":
    main()

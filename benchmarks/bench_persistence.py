"""Persistent homology: thesis_lib's engine against GUDHI and Ripser (thesis §2.3, §2.4.1).

Usage: ``python benchmarks/bench_persistence.py [--quick] [--repeat N] [--output FILE]``; writes
``benchmarks/results/persistence.json`` (``persistence_quick.json`` with ``--quick``).

Every (case, tool) runs in its own subprocess, so that the peak resident set size
(``resource.getrusage``, the high-water mark) belongs to that tool alone.  Inside a worker:
build the input, warm up (numba compilation excluded), record the RSS high-water mark
(``base_mb``), then time the persistence computation (best of ``--repeat``) and read the peak
again (``peak_mb``; ``work_mb = peak - base`` is what the computation itself added).  The base
includes the libraries: numba's runtime (≈ 50 MB) is a fixed cost GUDHI and Ripser do not pay, and
ours holds the input as thesis_lib's Filtration (int64 vertex arrays) where GUDHI holds its tree.

* ours: ``thesis_lib.complexes.rips`` builds the Filtration (not timed), then
  ``thesis_lib.persistence.persistence(f, coefficients=2)`` and reading the intervals of dimensions
  0 .. max_dim − 1, the ones GUDHI and Ripser report (``ours_s``); ``ours_all_dims_s`` also sorts
  the top dimension's essential classes (listed lazily; GUDHI skips that dimension).
* GUDHI: ``RipsComplex(...).create_simplex_tree`` (not timed), then
  ``SimplexTree.compute_persistence(homology_coeff_field=2)`` (timed).  GUDHI skips the top
  dimension by default (``persistence_dim_max=False``); ours also lists its essential classes.
* Ripser: ``ripser(points, maxdim=max_dim - 1, thresh=2 ε)``: builds its complex implicitly, so its
  time includes what the other two get for free (it never stores the simplices).

Cases: two circles (``two_circles(n, seed=0)``, Rips ε ≤ 2 ⇒ every pair is an edge, dim ≤ 2: the
thesis's Figure 2.14 setting) and the flat torus of §2.4.1 (``flat_torus(k, noise=0.02, seed=0)``
in R⁴, Rips ε ≤ 0.5, dim ≤ 3 so that H₂ appears; the thesis's 100² points would need a far smaller
threshold to stay tractable).
"""

from __future__ import annotations

import json
import sys

import harness

CASES = {
    "two-circles-20": {"data": ("two_circles", 20), "eps": 2.0, "max_dim": 2},
    "two-circles-60": {"data": ("two_circles", 60), "eps": 2.0, "max_dim": 2},
    "two-circles-100": {"data": ("two_circles", 100), "eps": 2.0, "max_dim": 2},
    "two-circles-200": {"data": ("two_circles", 200), "eps": 2.0, "max_dim": 2},
    "flat-torus-20": {"data": ("flat_torus", 20), "eps": 0.5, "max_dim": 3},
}
FULL = ["two-circles-60", "two-circles-100", "two-circles-200", "flat-torus-20"]
QUICK = ["two-circles-20"]


def _points(case: dict):
    from thesis_lib.datasets import flat_torus, two_circles

    kind, n = case["data"]
    return two_circles(n, seed=0) if kind == "two_circles" else flat_torus(n, noise=0.02, seed=0)


def _summary(pairs_by_dim: dict[int, list[tuple[float, float]]], scale: float) -> dict:
    """Count and total length of the finite bars, number of essential bars, per dimension (in ε units)."""
    out = {}
    for d, pairs in pairs_by_dim.items():
        fin = [(b * scale, e * scale) for b, e in pairs if e != float("inf") and e > b]
        out[str(d)] = {
            "finite": len(fin),
            "total": sum(e - b for b, e in fin),
            "essential": sum(1 for _, e in pairs if e == float("inf")),
        }
    return out


def worker(tool: str, name: str, repeat: int) -> dict:
    import numpy as np

    case = CASES[name]
    pts = _points(case)
    eps, max_dim = case["eps"], case["max_dim"]
    homology_dims = range(max_dim)  # the dimensions all three tools report
    if tool == "ours":
        from thesis_lib.complexes.rips import rips
        from thesis_lib.persistence import persistence

        persistence(rips(pts[:12], eps, max_dim))  # warm-up: numba compilation (cached on disk anyway)
        f = rips(pts, eps, max_dim)
        n_simplices = len(f)

        def run():
            b = persistence(f, coefficients=2)
            for d in homology_dims:  # the dimensions GUDHI and Ripser report
                b.intervals(d)
            return b

        def run_all():  # also sort the top dimension's essential classes (GUDHI skips that dimension)
            b = persistence(f, coefficients=2)
            for d in b.dimensions:
                b.intervals(d)
            return b

        def result(b):
            return {d: [tuple(r) for r in b.intervals(d).tolist()] for d in homology_dims}, 1.0

    elif tool == "gudhi":
        import gudhi

        stree = gudhi.RipsComplex(points=pts, max_edge_length=2 * eps).create_simplex_tree(max_dimension=max_dim)
        n_simplices = stree.num_simplices()

        def run():
            stree.compute_persistence(homology_coeff_field=2)
            return stree

        def result(s):
            return {d: [tuple(x) for x in s.persistence_intervals_in_dimension(d).tolist()] for d in homology_dims}, 0.5

    elif tool == "ripser":
        from ripser import ripser

        ripser(pts[:12], maxdim=max_dim - 1, thresh=2 * eps)
        n_simplices = None

        def run():
            return ripser(pts, maxdim=max_dim - 1, thresh=2 * eps)

        def result(r):
            return {d: [tuple(x) for x in np.asarray(r["dgms"][d]).tolist()] for d in homology_dims}, 0.5

    else:
        raise ValueError(f"unknown tool {tool!r}")
    stats, out = harness.measure_rss(run, repeat)
    all_s = peak_all = None
    if tool == "ours":
        all_s, _ = harness.best_of(run_all, repeat, summary=lambda b: None)  # results dropped at once
        peak_all = harness.rss_mb()
    pairs, scale = result(out)
    return {
        "time_s": stats["time_s"],
        "all_dims_s": all_s,
        "peak_all_mb": peak_all,
        "base_mb": stats["base_mb"],
        "peak_mb": stats["peak_mb"],
        "work_mb": stats["work_mb"],
        "n_simplices": n_simplices,
        "summary": _summary(pairs, scale),
    }


def run_case(tool: str, name: str, repeat: int) -> dict:
    return harness.run_worker(__file__, tool, name, "--repeat", repeat)


def _agree(a: dict, b: dict) -> bool:
    for d, s in a.items():
        t = b.get(d)
        if t is None or s["finite"] != t["finite"] or s["essential"] != t["essential"]:
            return False
        if abs(s["total"] - t["total"]) > 1e-6 * max(1.0, s["total"]):
            return False
    return True


def main(argv: list[str] | None = None) -> list[dict]:
    args = harness.arguments(__doc__, argv, quick_help="one small case (smoke test)", repeat=3,
                             worker=("TOOL", "CASE"), output=True)
    if args.worker:
        print(json.dumps(worker(args.worker[0], args.worker[1], args.repeat)))
        return []
    rows = []
    for name in QUICK if args.quick else FULL:
        res = {tool: run_case(tool, name, args.repeat) for tool in ("ours", "gudhi", "ripser")}
        o, g, r = res["ours"], res["gudhi"], res["ripser"]
        case = CASES[name]
        rows.append(
            {
                "case": name,
                "n_points": int(case["data"][1] ** 2 if case["data"][0] == "flat_torus" else 2 * case["data"][1]),
                "max_radius": case["eps"],
                "max_dim": case["max_dim"],
                "n_simplices": o["n_simplices"],
                "ours_s": o["time_s"],
                "ref_s": g["time_s"],
                "ratio": o["time_s"] / g["time_s"],
                "ours_all_dims_s": o["all_dims_s"],
                "ripser_s": r["time_s"],
                "ratio_ripser": o["time_s"] / r["time_s"],
                "ours_mb": o["peak_mb"],
                "ref_mb": g["peak_mb"],
                "mem_ratio": o["peak_mb"] / g["peak_mb"],
                "ripser_mb": r["peak_mb"],
                "mem_ratio_ripser": o["peak_mb"] / r["peak_mb"],
                "ours_all_dims_mb": o["peak_all_mb"],
                "ours_work_mb": o["work_mb"],
                "ref_work_mb": g["work_mb"],
                "ripser_work_mb": r["work_mb"],
                "same_barcode": _agree(o["summary"], g["summary"]) and _agree(o["summary"], r["summary"]),
                "reference": "GUDHI SimplexTree.compute_persistence (Z/2)",
            }
        )
        print(f"done {name}", file=sys.stderr, flush=True)
    cols = ["case", "n_simplices", "ours_s", "ours_all_dims_s", "ref_s", "ratio", "ripser_s", "ratio_ripser", "ours_mb", "ref_mb",
            "mem_ratio", "ripser_mb", "same_barcode"]  # fmt: skip
    harness.print_table(cols, rows)
    harness.write_rows("persistence", rows, args.quick, args.output)
    return rows


if __name__ == "__main__":
    main()

"""Persistent homology of Rips filtrations: thesis_lib against Ripser, giotto-ph and GUDHI (§2.3, §2.4.1).

Usage: ``python benchmarks/bench_persistence.py [--quick] [--rounds N] [--cases NAME ...] [--output FILE]``;
writes ``benchmarks/results/persistence.json`` (``persistence_quick.json`` with ``--quick``).

Every figure is a **whole pipeline, points → barcode**, for every tool (the harness's rules,
``benchmarks/harness.py``):

* ``ours``: ``rips_persistence(points, max_radius=ε, max_dim=D)`` — the implicit engine (nothing stored
  but the neighbour graph; apparent and emergent pairs; H0 by union–find);
* ``explicit``: ``persistence(rips(points, max_radius=ε, max_dim=D))`` — the Filtration is built, then reduced (the
  engine of the thesis's pages; only where its simplices fit in memory);
* ``ripser``: ``ripser(points, maxdim=D − 1, thresh=2ε)`` (ripser.py, one thread);
* ``gph``: giotto-ph ``ripser_parallel(points, maxdim=D − 1, thresh=2ε, n_threads=2)`` (both cores);
* ``gudhi``: ``RipsComplex(points, max_edge_length=2ε).create_simplex_tree(D)`` then
  ``compute_persistence(homology_coeff_field=2)`` (only where its tree fits in memory).

Times: the contenders run interleaved (ours, explicit, ripser, gph, gudhi, ours, ...) after one
warm-up each, for 5 rounds (15 when a case takes under 0.1 s); ``<tool>_s`` is the median and
``ratio_<tool>`` the median over rounds of ours / tool measured in the same round.  Before timing,
every tool's barcode (dimensions 0 .. D − 1, in ε) must equal ours to 1e-5 (Ripser and giotto-ph
compute in float32).  Memory: each tool runs once more in a fresh process; ``<tool>_mb`` is the peak
resident set *above the baseline* of that process after its imports and input (``baseline_mb``,
stored), so libraries' import costs are not counted.  Coefficients Z/2 throughout.

Cases: two circles (``two_circles(n, seed=0)``: unit circles with centres 1 apart) with ε ≤ 2
(diameter ≤ 4: every pair is an edge, the thesis's Figure 2.14 setting) and max_dim 2 (H0, H1), or
max_dim 3 (H0–H2); ε ≤ 1 for the scaling series and the held-out sizes (all three H1 bars die at
ε ≈ 1: the features survive the cut); 400 uniform points in the unit cube, full range, H0–H1.
"""

from __future__ import annotations

import sys

import harness
import numpy as np

# name: (data, n, ε, max_dim, tools)
ALL = ("ours", "explicit", "ripser", "gph", "gudhi")
IMPLICIT = ("ours", "ripser", "gph")
CASES = {
    "two-circles-20": ("circles", 20, 2.0, 2, ALL),
    "two-circles-60": ("circles", 60, 2.0, 2, ALL),
    "two-circles-100": ("circles", 100, 2.0, 2, ALL),
    "two-circles-200": ("circles", 200, 2.0, 2, ALL),
    "two-circles-60-h2": ("circles", 60, 2.0, 3, ALL),
    "cube-400": ("cube", 400, np.inf, 2, ALL),
    "cube-100-quick": ("cube", 100, np.inf, 2, ALL),
    # scaling series, ε ≤ 1 (GUDHI and the explicit engine while their complexes fit in memory)
    "scaling-100": ("circles", 100, 1.0, 2, ALL),
    "scaling-200": ("circles", 200, 1.0, 2, ALL),
    "scaling-300": ("circles", 300, 1.0, 2, IMPLICIT + ("explicit",)),
    "scaling-400": ("circles", 400, 1.0, 2, IMPLICIT),
    "scaling-500": ("circles", 500, 1.0, 2, IMPLICIT),
    "scaling-1000": ("circles", 1000, 1.0, 2, IMPLICIT),
}
QUICK = ["two-circles-20", "cube-100-quick"]
FULL = ["two-circles-20", "cube-100-quick", "two-circles-60", "two-circles-100", "two-circles-200",
        "two-circles-60-h2", "cube-400", "scaling-100", "scaling-200", "scaling-300", "scaling-400",
        "scaling-500", "scaling-1000"]
HELD_OUT = ["scaling-500", "two-circles-60-h2", "cube-400", "scaling-1000"]  # the re-measurement's workloads


def points(name: str) -> np.ndarray:
    from thesis_lib.datasets import two_circles

    kind, n = CASES[name][:2]
    return two_circles(n, seed=0) if kind == "circles" else np.random.default_rng(0).random((n, 3))


def pipeline(tool: str, pts: np.ndarray, eps: float, max_dim: int):
    """The whole pipeline of one tool; returns its barcode as a list of (m, 2) arrays in ε."""
    thresh = 2 * eps
    if tool == "ours":
        from thesis_lib.persistence import rips_persistence

        return lambda: rips_persistence(pts, max_radius=eps, max_dim=max_dim).to_diagrams()
    if tool == "explicit":
        from thesis_lib.complexes import rips
        from thesis_lib.persistence import persistence

        return lambda: [persistence(rips(pts, max_radius=eps, max_dim=max_dim)).intervals(d) for d in range(max_dim)]
    if tool == "ripser":
        from ripser import ripser

        return lambda: [d / 2 for d in ripser(pts, maxdim=max_dim - 1, thresh=thresh)["dgms"]]
    if tool == "gph":
        from gph import ripser_parallel

        return lambda: [d / 2 for d in ripser_parallel(pts, maxdim=max_dim - 1, thresh=thresh, n_threads=2)["dgms"]]
    if tool == "gudhi":
        import gudhi

        def run():
            st = gudhi.RipsComplex(points=pts, max_edge_length=thresh).create_simplex_tree(max_dimension=max_dim)
            st.compute_persistence(homology_coeff_field=2, min_persistence=0)
            return [st.persistence_intervals_in_dimension(d) / 2 for d in range(max_dim)]

        return run
    raise ValueError(f"unknown tool {tool!r}")


def _same(a: list, b: list, atol: float = 1e-5) -> str | None:
    from thesis_lib.persistence import Barcode

    x = Barcode.from_diagrams([np.asarray(d, np.float64) for d in a])
    y = Barcode.from_diagrams([np.asarray(d, np.float64) for d in b])
    return x.difference(y, atol=atol)


def check_same(results: dict) -> None:
    ref = results["ours"]
    for tool, out in results.items():
        diff = _same(ref, out)
        if diff is not None:
            raise AssertionError(f"{tool} computed a different barcode: {diff}")


def memory_child(tool: str, name: str) -> None:
    _, _, eps, max_dim, _ = CASES[name]

    def setup():
        pts = points(name)
        pipeline(tool, pts[:12], eps, max_dim)()  # imports and compiled code loaded (the baseline)
        return pipeline(tool, pts, eps, max_dim)

    harness.memory_worker(setup, lambda run: run())


def run_case(name: str, rounds: int | None) -> dict:
    kind, n, eps, max_dim, tools = CASES[name]
    pts = points(name)
    contenders = {tool: pipeline(tool, pts, eps, max_dim) for tool in tools}
    res = harness.compare(contenders, rounds=rounds, check=check_same)
    row = {"case": name, "data": kind, "n_points": int(pts.shape[0]), "n_per_circle": n if kind == "circles" else None,
           "max_radius": eps if np.isfinite(eps) else None, "max_dim": max_dim, "same_barcode": True,
           "held_out": name in HELD_OUT}
    row.update(harness.ratio_fields(res, "ours"))
    for tool in tools:
        row.update(harness.memory_fields(__file__, tool, tool, name))
    stats: dict = {}
    from thesis_lib.persistence import rips_persistence

    rips_persistence(pts, max_radius=eps, max_dim=max_dim, stats=stats)
    top = stats[max_dim - 1]
    row["columns"] = top["columns"]
    row["apparent"] = top["apparent"]
    row["candidates"] = top["simplices"]
    return row


COLUMNS = [("case", "{case}"), ("rounds", "{rounds}"), ("ours s", "{ours_s:.3g}"),
           ("ours/ripser", "{ratio_ripser:.2f}"), ("ours/giotto-ph", "{ratio_gph:.2f}"),
           ("ours/GUDHI", lambda r: f"{r['ratio_gudhi']:.2f}" if "ratio_gudhi" in r else "–"),
           ("ours MB", "{ours_mb:.0f}"), ("ripser MB", "{ripser_mb:.0f}"), ("giotto-ph MB", "{gph_mb:.0f}")]


def main(argv: list[str] | None = None) -> list[dict]:
    return harness.run_cases(
        "persistence", __doc__, argv, cases=list(CASES), quick=QUICK, full=FULL, columns=COLUMNS, run_case=run_case,
        memory_child=memory_child
    )


if __name__ == "__main__":
    main(sys.argv[1:])

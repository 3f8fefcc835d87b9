"""Crust [ABK98] against pymeshlab's ball pivoting on uniform torus samples (R = 10, r = 5, §3.4.1).

Usage: ``python benchmarks/bench_crust.py [--quick] [--rounds N] [--cases NAME ...] [--output FILE]``.

Time: both reconstructions run on the same samples in one process, interleaved (Crust, ball
pivoting, Crust, ...) after a warm-up, 5 rounds; medians and ``ratio_ball_pivoting``, the median
of the per-round ratios (``harness.compare``).  Each output is checked for a closed surface of
genus 1 (every edge in two faces, χ = 0).  Memory: each method reconstructs once in a fresh
process; ``delta_mb`` is the peak resident set above the baseline after imports, samples and
warm-up (``harness.memory``).  A third process measures Qhull's Delaunay triangulation of the same
samples alone (``scipy.spatial.Delaunay``: the tetrahedra, their neighbours and Qhull's own peak),
the first step of the Crust and what bounds its peak from below: the Crust cannot use less.
"""

from __future__ import annotations

import harness
import numpy as np

QUICK = [2000]
FULL = [2000, 10000, 30000, 100000]
TOOLS = ("crust", "ball_pivoting", "delaunay")

COLUMNS = [
    ("samples", "{n_samples}"),
    ("Crust (s)", "{ours_s:.2f}"),
    ("ball pivoting (s)", "{ball_pivoting_s:.2f}"),
    ("ratio", "{ratio_ball_pivoting:.2f}"),
    ("rounds", "{rounds}"),
    ("Crust (MB)", "{ours_mb:.0f}"),
    ("ball pivoting (MB)", "{ball_pivoting_mb:.0f}"),
    ("Qhull Delaunay alone (MB)", "{delaunay_mb:.0f}"),
    ("Crust closed genus 1", "{ours_closed_genus1}"),
    ("ball pivoting closed genus 1", "{ball_pivoting_closed_genus1}"),
]


def _case(n: int) -> str:
    return f"torus {n} samples"


def _run(tool: str, pts: np.ndarray):
    from scipy.spatial import Delaunay

    from thesis_lib.reconstruction import ball_pivoting, crust

    if tool == "crust":
        return crust(pts)
    if tool == "ball_pivoting":
        return ball_pivoting(pts)
    tri = Delaunay(pts)
    return tri.simplices, tri.neighbors


def memory_run(n: str, tool: str) -> dict:
    """In a fresh process: peak memory of one reconstruction above the post-warm-up baseline."""
    from thesis_lib.meshes import sample_torus

    def setup():
        _run(tool, sample_torus(500, seed=1))  # warm-up: pymeshlab's plugins
        return sample_torus(int(n), seed=0)

    return harness.memory_worker(setup, lambda pts: _run(tool, pts))


def closed_genus1(faces: np.ndarray) -> bool:
    from thesis_lib.meshes import euler_characteristic, facet_degrees

    return bool(np.all(facet_degrees(faces) == 2) and euler_characteristic(faces) == 0)


def make_row(n: int, rounds: int | None) -> dict:
    from thesis_lib.meshes import sample_torus

    pts = sample_torus(n, seed=0)
    closed = {}

    def check(results):
        closed.update({name: closed_genus1(faces) for name, faces in results.items()})

    result = harness.compare({"ours": lambda: _run("crust", pts), "ball_pivoting": lambda: _run("ball_pivoting", pts)},
                             rounds=rounds, check=check)
    row = {"case": _case(n), "n_samples": n, **harness.ratio_fields(result)}
    row["ours_closed_genus1"] = closed["ours"]
    row["ball_pivoting_closed_genus1"] = closed["ball_pivoting"]
    for tool, key in zip(TOOLS, ("ours", "ball_pivoting", "delaunay")):
        row.update(harness.memory_fields(__file__, key, n, tool))
    return row


def main(argv: list[str] | None = None) -> list[dict]:
    return harness.run_cases(
        "crust", __doc__, argv, cases=[str(n) for n in FULL], quick=QUICK, full=[str(n) for n in FULL],
        columns=COLUMNS, run_case=lambda name, rounds: make_row(int(name), rounds), memory_child=memory_run,
        memory=("N", "TOOL")
    )


if __name__ == "__main__":
    main()

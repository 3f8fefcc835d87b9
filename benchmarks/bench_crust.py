"""Crust [ABK98] against pymeshlab's ball pivoting on uniform torus samples (R = 10, r = 5, §3.4.1).

Usage: ``python benchmarks/bench_crust.py [--quick]``.  Prints a Markdown table and writes
``benchmarks/results/crust.json`` (``crust_quick.json`` with ``--quick``): case, ours_s, ref_s,
ratio, ours_mb, ref_mb, and whether each surface came out closed with χ = 0 (the issue's target:
10⁵ samples in under a minute, closed genus 1).  Time is the best of a few runs after a warm-up
(numba compilation excluded); memory is the peak RSS of a fresh subprocess.
"""

from __future__ import annotations

import json

import harness
import numpy as np

QUICK, FULL = [2000], [2000, 10000, 30000, 100000]

COLUMNS = [
    ("case", "{case}"),
    ("Crust (s)", "{ours_s:.2f}"),
    ("ball pivoting (s)", "{ref_s:.2f}"),
    ("ratio", "{ratio:.2f}"),
    ("Crust (MB)", "{ours_mb:.0f}"),
    ("ball pivoting (MB)", "{ref_mb:.0f}"),
    ("Crust closed genus 1", "{ours_closed_genus1}"),
    ("ball pivoting closed genus 1", "{ref_closed_genus1}"),
]


def _method(which: str):
    from thesis_lib.meshes import ball_pivoting, crust

    return crust if which == "crust" else ball_pivoting


def worker(which: str, n: int) -> None:
    """Reconstruct once in this fresh process; print the peak RSS (MB) as JSON."""
    from thesis_lib.meshes import sample_torus

    _method(which)(sample_torus(n, seed=0))
    print(json.dumps(harness.status_mb("VmHWM")))


def closed_genus1(faces: np.ndarray) -> bool:
    from thesis_lib.meshes import euler_characteristic, facet_degrees

    return bool(np.all(facet_degrees(faces) == 2) and euler_characteristic(faces) == 0)


def make_row(n: int, repeat: int) -> dict:
    from thesis_lib.meshes import sample_torus

    pts = sample_torus(n, seed=0)
    ours_s, ours = harness.best_of(lambda: _method("crust")(pts), repeat)
    ref_s, ref = harness.best_of(lambda: _method("ball")(pts), repeat)
    return {
        "case": f"torus {n} samples",
        "n_samples": n,
        "ours_s": ours_s,
        "ref_s": ref_s,
        "ratio": ours_s / ref_s,
        "ours_mb": float(harness.run_worker(__file__, "crust", n)),
        "ref_mb": float(harness.run_worker(__file__, "ball", n)),
        "ours_closed_genus1": closed_genus1(ours),
        "ref_closed_genus1": closed_genus1(ref),
    }


def main() -> None:
    args = harness.arguments(__doc__, worker=("METHOD", "N"))
    if args.worker:
        worker(args.worker[0], int(args.worker[1]))
        return
    from thesis_lib.meshes import sample_torus

    _method("crust")(sample_torus(500, seed=1))  # warm-up: numba compilation
    sizes = QUICK if args.quick else FULL
    rows = harness.stream_table(COLUMNS, sizes, lambda n: make_row(n, 1 if args.quick or n > 10000 else 3))
    harness.write_rows("crust", rows, args.quick)


if __name__ == "__main__":
    main()

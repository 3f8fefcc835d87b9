"""Benchmark thesis_lib.curvature against libigl on a torus grid (thesis §3.4.1, 10^5 vertices).

Cases (ours vs libigl, measured in the same run):

* ``mean_curvature_vector``: ∇ area at every vertex vs ``-(igl.cotmatrix(V, F) @ V)``;
* ``mixed_area``: Meyer's mixed area vs ``igl.massmatrix(V, F, MASSMATRIX_TYPE_VORONOI)``;
* ``gaussian_curvature``: angle defect / mixed area vs ``igl.gaussian_curvature / massmatrix``;
* ``mean_curvature``: |H| = ‖∇ area‖ / (2 · mixed area) vs the same from cotmatrix + massmatrix;
* ``all_three``: the first three together (what an experiment computes per mesh).

Ours includes input validation (manifoldness, degeneracy, NaN, ...) in every call.
Time is the best of several interleaved runs (ours, libigl, ours, ...) after a warm-up; memory is the peak RSS growth of one call in a
fresh subprocess (mesh loaded from disk first, libraries imported), which also sees libigl's C++
allocations.  Usage: ``python benchmarks/bench_curvature.py [--quick]``; writes
``benchmarks/results/curvature.json`` (``curvature_quick.json`` with ``--quick``) and prints a
Markdown table.
"""

from __future__ import annotations

import importlib.metadata
import json
import tempfile
from pathlib import Path

import harness
import numpy as np

from thesis_lib.datasets import torus_grid  # n x n grid, R = 10, r = 5 as in the thesis


def operations():
    """case -> (ours, libigl) callables of (V, F)."""
    import igl

    from thesis_lib.curvature import gaussian_curvature, mean_curvature, mean_curvature_vector, vertex_areas

    voronoi = igl.MASSMATRIX_TYPE_VORONOI

    def igl_vec(V, F):
        return -(igl.cotmatrix(V, F) @ V)

    def igl_area(V, F):
        return igl.massmatrix(V, F, voronoi).diagonal()

    def igl_gauss(V, F):
        return igl.gaussian_curvature(V, F) / igl_area(V, F)

    def igl_mean(V, F):
        return np.linalg.norm(igl_vec(V, F), axis=1) / (2 * igl_area(V, F))

    def ours_all(V, F):
        return mean_curvature_vector(V, F), vertex_areas(V, F, "mixed"), gaussian_curvature(V, F)

    def igl_all(V, F):
        return igl_vec(V, F), igl_area(V, F), igl_gauss(V, F)

    return {
        "mean_curvature_vector": (mean_curvature_vector, igl_vec),
        "mixed_area": (lambda V, F: vertex_areas(V, F, "mixed"), igl_area),
        "gaussian_curvature": (gaussian_curvature, igl_gauss),
        "mean_curvature": (mean_curvature, igl_mean),
        "all_three": (ours_all, igl_all),
    }


def worker(case: str, side: int, path: str) -> None:
    """Run one call in this fresh process and print its peak RSS growth (MB)."""
    ops = operations()
    data = np.load(path)
    V, F = np.array(data["V"]), np.array(data["F"])
    ops[case][side](*torus_grid(8))  # warm-up on a tiny mesh: numba compilation/caching excluded
    print(json.dumps(harness.peak_growth_mb(lambda: ops[case][side](V, F))))


def peak_mb(case: str, side: int, path: str) -> float:
    return float(harness.run_worker(__file__, case, side, path))


def max_abs_diff(a, b) -> float:
    if isinstance(a, tuple):
        return max(max_abs_diff(x, y) for x, y in zip(a, b))
    return float(np.nanmax(np.abs(np.asarray(a) - np.asarray(b))))


COLUMNS = [
    ("case", "{case}"),
    ("vertices", "{n_vertices}"),
    ("ours (s)", "{ours_s:.4f}"),
    ("libigl (s)", "{ref_s:.4f}"),
    ("ratio", "{ratio:.2f}"),
    ("ours (MB)", "{ours_mb:.1f}"),
    ("libigl (MB)", "{ref_mb:.1f}"),
    ("max abs diff", "{max_abs_diff:.2e}"),
]


def main() -> None:
    args = harness.arguments(__doc__, quick_help="small mesh (60 x 60), for smoke tests",
                             worker=("CASE", "SIDE", "PATH"))
    if args.worker:
        worker(args.worker[0], int(args.worker[1]), args.worker[2])
        return
    k, repeats = (60, 3) if args.quick else (317, 15)
    V, F = torus_grid(k)
    ops = operations()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        path = str(Path(tmp) / "mesh.npz")
        np.savez(path, V=V, F=F)
        for case, (ours, ref) in ops.items():
            ours_s, ref_s = harness.best_times([ours, ref], (V, F), repeats)
            rows.append(
                {
                    "case": case,
                    "mesh": f"torus grid {k}x{k}",
                    "n_vertices": int(len(V)),
                    "n_faces": int(len(F)),
                    "ours_s": round(ours_s, 5),
                    "ref_s": round(ref_s, 5),
                    "ratio": round(ours_s / ref_s, 3),
                    "ours_mb": round(peak_mb(case, 0, path), 1),
                    "ref_mb": round(peak_mb(case, 1, path), 1),
                    "reference": "libigl " + importlib.metadata.version("libigl"),
                    "max_abs_diff": max_abs_diff(ours(V, F), ref(V, F)),
                }
            )
    harness.print_table(COLUMNS, rows)
    harness.write_rows("curvature", rows, args.quick, indent=2)


if __name__ == "__main__":
    main()

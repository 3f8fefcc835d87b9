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

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results" / "curvature.json"
RESULTS_QUICK = RESULTS.with_name("curvature_quick.json")  # --quick never overwrites the full results


def torus_grid(nu: int, nv: int, R: float = 10.0, r: float = 5.0) -> tuple[np.ndarray, np.ndarray]:
    """Grid triangulation of the torus (R = 10, r = 5, as in the thesis), nu * nv vertices."""
    u = 2 * np.pi * np.arange(nu) / nu
    v = 2 * np.pi * np.arange(nv) / nv
    U, V = np.meshgrid(u, v, indexing="ij")
    P = np.stack([(R + r * np.cos(V)) * np.cos(U), (R + r * np.cos(V)) * np.sin(U), r * np.sin(V)], -1)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    a, b = i * nv + j, ((i + 1) % nu) * nv + j
    c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    return P.reshape(-1, 3), F


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


def best_times(fns, V, F, repeats: int) -> list[float]:
    """Best wall time of each callable; calls are interleaved so machine load hits all alike."""
    for fn in fns:
        fn(V, F)  # warm-up
    best = [float("inf")] * len(fns)
    for _ in range(repeats):
        for i, fn in enumerate(fns):
            t0 = time.perf_counter()
            fn(V, F)
            best[i] = min(best[i], time.perf_counter() - t0)
    return best


def _status_mb(field: str) -> float:
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024  # kB
    raise RuntimeError(f"{field} not in /proc/self/status")


def worker(case: str, side: int, path: str) -> None:
    """Run one call in this fresh process and print its peak RSS growth (MB)."""
    ops = operations()
    data = np.load(path)
    V, F = np.array(data["V"]), np.array(data["F"])
    try:  # reset the high-water mark (VmHWM) so imports and loading do not count
        with open("/proc/self/clear_refs", "w") as fh:
            fh.write("5")
        before = _status_mb("VmRSS")
        ops[case][side](V, F)
        peak = _status_mb("VmHWM")
    except OSError:  # no clear_refs: fall back to the lifetime peak
        before = _status_mb("VmRSS")
        ops[case][side](V, F)
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(json.dumps(max(peak - before, 0.0)))


def peak_mb(case: str, side: int, path: str) -> float:
    out = subprocess.run(
        [sys.executable, __file__, "--worker", case, str(side), path], capture_output=True, text=True, check=True
    )
    return float(out.stdout.strip().splitlines()[-1])


def max_abs_diff(a, b) -> float:
    if isinstance(a, tuple):
        return max(max_abs_diff(x, y) for x, y in zip(a, b))
    return float(np.nanmax(np.abs(np.asarray(a) - np.asarray(b))))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small mesh (60 x 60), for smoke tests")
    parser.add_argument("--worker", nargs=3, metavar=("CASE", "SIDE", "PATH"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args.worker[0], int(args.worker[1]), args.worker[2])
        return
    k, repeats = (60, 3) if args.quick else (317, 15)
    V, F = torus_grid(k, k)
    ops = operations()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        path = str(Path(tmp) / "mesh.npz")
        np.savez(path, V=V, F=F)
        for case, (ours, ref) in ops.items():
            ours_s, ref_s = best_times([ours, ref], V, F, repeats)
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
                    "reference": "libigl " + getattr(__import__("igl"), "__version__", ""),
                    "max_abs_diff": max_abs_diff(ours(V, F), ref(V, F)),
                }
            )
    out = RESULTS_QUICK if args.quick else RESULTS
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(rows, indent=2) + "\n")
    print("| case | vertices | ours (s) | libigl (s) | ratio | ours (MB) | libigl (MB) | max abs diff |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(
            f"| {r['case']} | {r['n_vertices']} | {r['ours_s']:.4f} | {r['ref_s']:.4f} | {r['ratio']:.2f} | "
            f"{r['ours_mb']:.1f} | {r['ref_mb']:.1f} | {r['max_abs_diff']:.2e} |"
        )
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

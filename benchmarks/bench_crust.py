"""Crust [ABK98] against pymeshlab's ball pivoting on uniform torus samples (R = 10, r = 5).

Usage: python benchmarks/bench_crust.py [--quick]
Prints a Markdown table and writes benchmarks/results/crust.json (case, ours_s, ref_s, ratio,
ours_mb, ref_mb, plus whether each surface came out closed with χ = 0).  Time is the best of a few
runs after a warm-up (numba compilation excluded); memory is the peak RSS of a fresh subprocess.
"""

from __future__ import annotations

import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent

# peak RSS from VmHWM (ru_maxrss can carry over the parent's high-water mark through fork + exec)
WORKER = r"""
import sys, numpy as np
from thesis_lib.meshes import sample_torus, crust, ball_pivoting
n, which = int(sys.argv[1]), sys.argv[2]
pts = sample_torus(n, seed=0)
(crust if which == "crust" else ball_pivoting)(pts)
hwm = [l for l in open("/proc/self/status") if l.startswith("VmHWM")][0]
print(int(hwm.split()[1]) / 1024)
"""


def _rss(n: int, which: str) -> float:
    out = subprocess.run([sys.executable, "-c", WORKER, str(n), which], capture_output=True, text=True, check=True)
    return float(out.stdout.strip().splitlines()[-1])


def _best(fn, repeat: int) -> tuple[float, object]:
    best, result = np.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    return best, result


def main(quick: bool) -> list[dict]:
    from thesis_lib.meshes import ball_pivoting, crust, euler_characteristic, facet_degrees, sample_torus

    crust(sample_torus(500, seed=1))  # warm-up: numba compilation
    sizes = [2000] if quick else [2000, 10000, 30000]
    rows = []
    for n in sizes:
        pts = sample_torus(n, seed=0)
        repeat = 1 if quick or n > 10000 else 3
        t_ours, f_ours = _best(lambda: crust(pts), repeat)
        t_ref, f_ref = _best(lambda: ball_pivoting(pts), repeat)
        rows.append({
            "case": f"torus {n} samples",
            "ours_s": t_ours,
            "ref_s": t_ref,
            "ratio": t_ours / t_ref,
            "ours_mb": _rss(n, "crust"),
            "ref_mb": _rss(n, "ball"),
            "ours_closed_genus1": bool(np.all(facet_degrees(f_ours) == 2) and euler_characteristic(f_ours) == 0),
            "ref_closed_genus1": bool(np.all(facet_degrees(f_ref) == 2) and euler_characteristic(f_ref) == 0),
        })
    print("| case | Crust s | ball pivoting s | ratio | Crust MB | BP MB | Crust closed | BP closed |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['case']} | {r['ours_s']:.2f} | {r['ref_s']:.2f} | {r['ratio']:.1f} | {r['ours_mb']:.0f} | "
              f"{r['ref_mb']:.0f} | {r['ours_closed_genus1']} | {r['ref_closed_genus1']} |")
    (HERE / "results").mkdir(exist_ok=True)
    (HERE / "results" / "crust.json").write_text(json.dumps(rows, indent=1) + "\n")
    return rows


if __name__ == "__main__":
    main("--quick" in sys.argv)

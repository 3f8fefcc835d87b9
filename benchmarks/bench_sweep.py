"""Sweeps: the local executor against Dask with 1 and 2 workers, and what a kernel start costs.

A sweep of 8 runs of a CPU-bound experiment of about 5 s (the test fixture ``toy`` with ``work``
million loop steps, calibrated on this machine) runs with the local executor (1 and 2 at a time) and
on a Dask LocalCluster of 1 and 2 worker processes (started before the clock, its start-up timed
apart).  Rounds are interleaved (local-1, dask-1, local-2, dask-2, ...) and the median is kept.
Reported: wall time, time per run, Dask's scheduling overhead per run beyond the local executor
(``(dask-1 − local-1) / runs``: papermill's own start-up is in both), the speed-up from 1 to 2
workers, and the cost of a kernel start (a run of the same notebook with no work).
"""

from __future__ import annotations

import os
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

import harness

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from lab_helpers import make_project  # noqa: E402

COLUMNS = [
    "case",
    "runs",
    ("wall_s", "{wall_s:.1f}"),
    ("per_run_s", "{per_run_s:.2f}"),
    ("speedup", lambda r: f"{r['speedup']:.2f}" if r.get("speedup") else ""),
    ("overhead_per_run_s",
     lambda r: f"{r['overhead_per_run_s']:.2f}" if r.get("overhead_per_run_s") is not None else ""),
]


def _calibrate(target_s: float) -> int:
    """Millions of loop steps that take about ``target_s`` seconds here (at least 1)."""
    t0 = time.perf_counter()
    steps = 0
    for _ in range(2_000_000):
        steps += 1
    per_million = (time.perf_counter() - t0) / 2
    return max(1, round(target_s / per_million))


def _sweep_once(project: Path, runs: int, work: int, jobs: int, client=None) -> float:
    from thesis_lib.lab.sweep import sweep

    root = Path(tempfile.mkdtemp(prefix="bench-sweep-", dir=project))
    try:
        t0 = time.perf_counter()
        results, _ = sweep("toy", {"n": [str(i) for i in range(runs)], "work": [str(work)]}, jobs=jobs,
                           executor=client, root=root, progress=False)
        wall = time.perf_counter() - t0
        failed = [r.error for r in results if r.status != "ok"]
        if failed:
            raise RuntimeError(f"benchmark runs failed: {failed[:2]}")
        return wall
    finally:
        shutil.rmtree(root, ignore_errors=True)


def main(argv: list[str] | None = None) -> list[dict]:
    args = harness.arguments(__doc__, argv, repeat=None, quick_help="4 runs of about 1 s, one round")
    runs, target, rounds = (4, 1.0, 1) if args.quick else (8, 5.0, args.repeat or 3)
    from thesis_lib.lab.execute import execute
    from thesis_lib.lab.runner import local_spec
    from thesis_lib.lab.sweep import dask_client

    tmp = Path(tempfile.mkdtemp(prefix="bench-sweep-"))
    project = make_project(tmp / "project")
    os.environ["THESIS_LAB_PROJECT"] = str(project)
    os.environ["THESIS_LAB_SHARED"] = str(tmp / "shared")
    try:
        work = _calibrate(target)
        starts = []
        for _ in range(3):
            out = execute(local_spec("toy", {**_defaults(), "n": 1}))
            starts.append(out.seconds)
        kernel_s = statistics.median(starts)
        times: dict[str, list[float]] = {"local-1": [], "local-2": [], "dask-1": [], "dask-2": []}
        cluster_s = {}
        for workers in (1, 2):
            t0 = time.perf_counter()
            with dask_client(scheduler=None, jobs=workers) as client:
                cluster_s[workers] = time.perf_counter() - t0
                for _ in range(rounds):
                    times[f"local-{workers}"].append(_sweep_once(project, runs, work, workers))
                    times[f"dask-{workers}"].append(_sweep_once(project, runs, work, 1, client))
        wall = {k: statistics.median(v) for k, v in times.items()}
        rows = [{"case": "kernel start (one run, no work)", "runs": 1, "wall_s": kernel_s, "per_run_s": kernel_s}]
        for case in ("local-1", "dask-1", "local-2", "dask-2"):
            workers = int(case[-1])
            row = {"case": case.replace("-", ", ") + (" job" if workers == 1 else " jobs"), "runs": runs,
                   "wall_s": wall[case], "per_run_s": wall[case] / runs, "work_millions": work,
                   "rounds": rounds, "load": round(os.getloadavg()[0], 2)}
            if case == "dask-1":
                row["overhead_per_run_s"] = (wall["dask-1"] - wall["local-1"]) / runs
            if workers == 2:
                row["speedup"] = wall[case.replace("2", "1")] / wall[case]
            if case.startswith("dask"):
                row["cluster_start_s"] = cluster_s[workers]
            rows.append(row)
        harness.print_table(COLUMNS, rows)
        print(f"kernel start ~{kernel_s:.1f} s per run; Dask cluster start {cluster_s[1]:.1f} s (1 worker), "
              f"{cluster_s[2]:.1f} s (2 workers); 1-minute load average {os.getloadavg()[0]:.1f}")
        harness.write_results("sweep", rows, args.quick)
        return rows
    finally:
        os.environ.pop("THESIS_LAB_PROJECT", None)
        shutil.rmtree(tmp, ignore_errors=True)


def _defaults() -> dict:
    from thesis_lib.lab.experiments import resolve_parameters

    return resolve_parameters("toy")


if __name__ == "__main__":
    main()

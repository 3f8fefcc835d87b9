"""``make bench-check``: re-run every benchmark's quick cases and fail when a stored ratio moved.

Usage: ``python benchmarks/check.py [--tolerance 0.35] [TOPIC ...]`` (default: every
``bench_<topic>.py``).  Each script runs with ``--quick`` (writing ``results/<topic>_quick.json``,
never the stored full results); every ``ratio*`` of each quick row is compared with the row of the
same case in ``results/<topic>.json`` (:func:`harness.ratio_changes`).  A move of more than the
tolerance (±35 % by default: a shared 2-core machine is noisy), a quick case without a stored row,
or a stored file without provenance (``meta``: commit, date, load) fails the check, so a stale
published figure cannot stand: re-run ``make bench`` and commit the new results.
"""

from __future__ import annotations

import argparse
import subprocess
import sys

import harness


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("topics", nargs="*", help="benchmarks to check (default: all)")
    ap.add_argument("--tolerance", type=float, default=harness.TOLERANCE, help="largest relative move of a ratio")
    args = ap.parse_args(argv)
    topics = args.topics or sorted(p.stem[len("bench_"):] for p in harness.HERE.glob("bench_*.py"))
    failures: list[str] = []
    for topic in topics:
        script = harness.HERE / f"bench_{topic}.py"
        stored = harness.RESULTS / f"{topic}.json"
        if not script.exists():
            failures.append(f"{topic}: no benchmarks/bench_{topic}.py")
            continue
        if not stored.exists():
            failures.append(f"{topic}: no stored results {stored.name} (run make bench)")
            continue
        meta, rows = harness.read_results(stored)
        if not meta.get("commit"):
            failures.append(f"{topic}: {stored.name} was stored without provenance (commit, date, load): re-run it")
            continue
        print(f"== {topic} (stored {meta.get('date')} at {str(meta.get('commit'))[:12]}, "
              f"load {meta.get('load_average')})", flush=True)
        proc = subprocess.run([sys.executable, str(script), "--quick"], cwd=harness.HERE.parent)
        if proc.returncode != 0:
            failures.append(f"{topic}: the quick run failed (exit {proc.returncode})")
            continue
        _, fresh = harness.read_results(harness.RESULTS / f"{topic}_quick.json")
        problems = harness.ratio_changes(rows, fresh, args.tolerance)
        failures += [f"{topic}: {p}" for p in problems]
        moves = harness.ratio_moves(rows, fresh)
        if moves:
            case, key, ref, value = max(moves, key=lambda m: abs(m[3] / m[2] - 1.0))
            print(f"largest move: {case} {key} {value / ref - 1.0:+.0%} (stored {ref:.3g}, now {value:.3g})")
        print("ok" if not problems else "\n".join(problems), flush=True)
    if failures:
        print(f"\nbench-check FAILED (tolerance ±{args.tolerance:.0%}):", *failures, sep="\n  ")
        return 1
    print(f"\nbench-check passed: every quick ratio within ±{args.tolerance:.0%} of the stored one")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Simplicial homology (§2.2.1) over Z and Z/2 against GUDHI (Z/2) and PARI's matsnf (Z).

Usage: ``python benchmarks/bench_homology.py [--quick] [--repeat N] [--case NAME ...]``.

Every timing runs in a fresh subprocess (``--worker TOOL CASE``): build the input (not timed), warm
up on a small complex (imports excluded), read the resident-set high-water
mark, time one call, read the mark again (``work_mb`` = what the calls added).  When that first call
takes under ``SHORT_S`` (0.5 s), the worker reports the best of ``SHORT_REPEAT`` (5) calls on the same
input, for every tool alike: a single cold call of a few tens of milliseconds moved by ±25 % from one
process to the next (page faults, first-touch allocation), for GUDHI and for us.  The tools of a case
take turns, round after round (A, B, C, A, B, C, ...: load hits all alike); a row reports each
tool's median over ``--repeat`` rounds (default 5, 15 for cases under 0.1 s) and the median of the
per-round ratios.

Tools, all starting from the same per-dimension arrays of simplices:

* ``ours-z`` — ``homology(arrays, coefficients=0)``: boundary matrices, sparse unit-pivot elimination with
  clearing, then the modular Smith form of the dense core; Betti numbers and torsion over Z.
* ``ours-z2`` — ``homology(arrays, coefficients=2)``.
* ``gudhi`` — ``SimplexTree.insert_batch`` per dimension (constant filtration),
  ``compute_persistence(homology_coeff_field=2, persistence_dim_max=True)``, ``betti_numbers()``:
  the whole pipeline over Z/2 (GUDHI has no homology over Z).
* ``pari-core`` / ``ours-core`` — step only: PARI's ``matsnf`` and our modular stage
  (``dense_invariants``) on the same dense core that the sparse stage of ∂₂ hands over (the core is
  computed outside the timing).  PARI on the whole boundary matrix is out of reach here: for the
  Linial–Meshulam complex with n = 100 (∂₂ 4950 × 6323, dense) it grew past 6 GB and was stopped.

Cases: Vietoris–Rips complexes of uniform random points, grid-triangulated torus and Klein bottle
(torsion Z/2), Linial–Meshulam random 2-complexes (every edge, each triangle with probability c/n:
the hard case for elimination, a dense core with entries up to ~10⁸), and random 2-dimensional
hypertrees (triangles kept in random order while they raise the rank: Q-acyclic, with a huge
cyclic torsion group H₁, 10²⁶ and more at n = 75 — elementary divisors of any size).
"""

from __future__ import annotations

import argparse
import itertools
import json
import statistics

import harness

CASES = {
    "rips-2d-300": {"kind": "rips", "n": 300, "dim": 2, "r": 0.09, "max_dim": 2},
    "rips-2d-3000": {"kind": "rips", "n": 3000, "dim": 2, "r": 0.04, "max_dim": 2},
    "rips-3d-2500": {"kind": "rips", "n": 2500, "dim": 3, "r": 0.12, "max_dim": 3},
    "torus-grid-20": {"kind": "torus", "n": 20},
    "torus-grid-180": {"kind": "torus", "n": 180},
    "klein-grid-180": {"kind": "klein", "n": 180},
    "linial-meshulam-40": {"kind": "lm", "n": 40, "c": 4.0},
    "linial-meshulam-100": {"kind": "lm", "n": 100, "c": 4.0},
    "linial-meshulam-150": {"kind": "lm", "n": 150, "c": 4.0},
    "linial-meshulam-200": {"kind": "lm", "n": 200, "c": 4.0},
    "hypertree-30": {"kind": "hypertree", "n": 30},
    "hypertree-60": {"kind": "hypertree", "n": 60},
    "hypertree-90": {"kind": "hypertree", "n": 90},
}
FULL = ["rips-2d-3000", "rips-3d-2500", "torus-grid-180", "klein-grid-180", "linial-meshulam-100",
        "linial-meshulam-150", "linial-meshulam-200", "hypertree-60", "hypertree-90"]
# make bench-check's cases: large enough for stable timings (GUDHI's time on the millisecond cases
# rips-2d-300 ... hypertree-30 moved by up to 2× between runs minutes apart, ours did not)
QUICK = ["rips-2d-3000", "torus-grid-180", "linial-meshulam-100", "hypertree-60"]
#: cases with a dense core worth the step-only comparison with PARI
CORE_CASES = {"linial-meshulam-40", "linial-meshulam-100", "linial-meshulam-150", "linial-meshulam-200",
              "hypertree-30", "hypertree-60", "hypertree-90"}
#: a worker whose first call takes less than SHORT_S seconds reports the best of SHORT_REPEAT calls
SHORT_S, SHORT_REPEAT = 0.5, 5
#: a PARI call longer than this is stopped and reported as "> limit"
PARI_LIMIT_S = 900


def _hypertree(n: int, seed: int = 0):
    """A random 2-dimensional hypertree on n vertices: all edges, and the triangles that raise the
    rank of ∂₂ when taken in a random order (the deaths of H₁ classes in the filtration that adds
    the triangles in that order; GUDHI over Z/46337 finds them, only to build the input).  Q-acyclic."""
    import gudhi
    import numpy as np

    tris = np.array(list(itertools.combinations(range(n), 3)), dtype=np.int64)
    order = np.random.default_rng(seed).permutation(len(tris))
    st = gudhi.SimplexTree()
    for e in itertools.combinations(range(n), 2):
        st.insert(list(e), 0.0)
    st.insert_batch(np.ascontiguousarray(tris[order].T), np.arange(1, len(tris) + 1, dtype=float))
    st.compute_persistence(homology_coeff_field=46337, min_persistence=-1)
    kept = sorted(tuple(sorted(d)) for b, d in st.persistence_pairs() if len(b) == 2 and len(d) == 3)
    assert len(kept) == (n - 1) * (n - 2) // 2
    return np.array(kept, dtype=np.int64)


def complex_arrays(name: str) -> list:
    """The case's complex as a list of per-dimension (m_k, k+1) int64 arrays (all simplices)."""
    import numpy as np

    from thesis_lib.datasets import klein_bottle
    from thesis_lib.homology.simplicial import closure
    from thesis_lib.meshes import freudenthal

    case = CASES[name]
    if case["kind"] == "rips":
        import gudhi  # only to generate the input

        pts = np.random.default_rng(0).random((case["n"], case["dim"]))
        st = gudhi.RipsComplex(points=pts, max_edge_length=case["r"]).create_simplex_tree(
            max_dimension=case["max_dim"]
        )
        by_dim: dict[int, list] = {}
        for s, _ in st.get_simplices():
            by_dim.setdefault(len(s) - 1, []).append(s)
        return [np.array(sorted(by_dim[d]), dtype=np.int64) for d in range(max(by_dim) + 1)]
    if case["kind"] == "torus":
        return closure(freudenthal((case["n"], case["n"]), periodic=True))
    if case["kind"] == "klein":
        return closure(klein_bottle(n=case["n"], m=case["n"]))
    n = case["n"]
    edges = np.array(list(itertools.combinations(range(n), 2)), dtype=np.int64)
    if case["kind"] == "hypertree":
        return [np.arange(n, dtype=np.int64)[:, None], edges, _hypertree(n)]
    rng = np.random.default_rng(0)
    tris = np.array(list(itertools.combinations(range(n), 3)), dtype=np.int64)
    tris = tris[rng.random(len(tris)) < case["c"] / n]
    return [np.arange(n, dtype=np.int64)[:, None], edges, tris]


def dense_core(arrays: list):
    """The dense core the sparse stage leaves on ∂₂ (what the modular stage receives)."""
    import numpy as np

    from thesis_lib.homology._elimination import markowitz_eliminate
    from thesis_lib.homology.simplicial import boundary_matrix

    d2 = boundary_matrix(arrays[1], arrays[2], coefficients=0)
    _, _, (core, _, _) = markowitz_eliminate(d2.indptr, d2.indices, d2.data, d2.shape[0],
                                             np.zeros(d2.shape[1], bool), 0)
    return core


def _big(x: int) -> int | str:
    return x if x < 10**15 else f"~1e{len(str(x)) - 1}"


def worker(tool: str, name: str) -> dict:
    import numpy as np

    arrays = complex_arrays(name)
    n_simplices = int(sum(a.shape[0] for a in arrays))
    out: dict = {"n_simplices": n_simplices}
    if tool in ("ours-z", "ours-z2"):
        from thesis_lib.homology import homology

        p = 0 if tool == "ours-z" else 2
        homology([(0, 1, 2), (1, 3)], coefficients=p)  # warm-up: imports and caches
        homology(complex_arrays("linial-meshulam-40"), coefficients=p)
        run = lambda: homology(arrays, coefficients=p)  # noqa: E731
        summary = lambda h: {"betti": [b for b, _ in h], "torsion": [[_big(t) for t in ts] for _, ts in h]}  # noqa: E731
    elif tool == "gudhi":
        import gudhi

        def run():
            st = gudhi.SimplexTree()
            for a in arrays:
                st.insert_batch(np.ascontiguousarray(a.T), np.zeros(a.shape[0]))
            st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
            b = st.betti_numbers()
            return b + [0] * (len(arrays) - len(b))

        warm = gudhi.SimplexTree()
        warm.insert([0, 1, 2])
        warm.compute_persistence()
        summary = lambda b: {"betti": b}  # noqa: E731
    elif tool in ("ours-core", "pari-core"):
        core = dense_core(arrays)
        out["core_shape"] = list(core.shape)
        out["core_max"] = int(np.abs(core).max()) if core.size else 0
        if tool == "ours-core":
            from thesis_lib.homology._modular import dense_invariants

            dense_invariants(np.array([[2, 4], [6, 9]]))
            run = lambda: dense_invariants(core)  # noqa: E731
        else:
            import cypari2

            pari = cypari2.Pari()
            pari.allocatemem(10**8, 8 * 10**9, silent=True)
            matrix = pari("[" + ";".join(",".join(map(str, row)) for row in core.tolist()) + "]") if core.size else None
            run = lambda: [int(x) for x in pari.matsnf(matrix) if x != 0] if core.size else []  # noqa: E731
        summary = lambda inv: {"core_rank": len(inv), "core_invariants": [_big(x) for x in inv if x != 1]}  # noqa: E731
    else:
        raise ValueError(f"unknown tool {tool!r}")
    stats, result = harness.measure_rss(run, SHORT_REPEAT, summary, short_s=SHORT_S)
    return {**out, **stats, **result}


def _run(tool: str, name: str) -> dict | None:
    """One worker in a fresh process (:func:`harness.run_worker`); None when PARI exceeds its limit."""
    import subprocess

    try:
        return harness.run_worker(__file__, tool, name, timeout=PARI_LIMIT_S if tool == "pari-core" else None)
    except subprocess.TimeoutExpired:
        return None


def make_row(name: str, rounds: int | None) -> dict:
    """One table row: the tools of case ``name`` interleaved over rounds, medians and paired ratios."""
    tools = ["ours-z", "ours-z2", "gudhi"] + (["ours-core", "pari-core"] if name in CORE_CASES else [])
    runs: dict[str, list] = {t: [] for t in tools}
    first = {t: _run(t, name) for t in tools}
    n = rounds or (15 if first["ours-z"]["time_s"] < 0.1 else 5)
    for t in tools:
        runs[t].append(first[t])
    for _ in range(n - 1):
        for t in tools:
            if t == "pari-core" and runs[t][-1] is None:
                runs[t].append(None)  # stopped once at the limit: do not try again
                continue
            runs[t].append(_run(t, name))
    med = {t: statistics.median(r["time_s"] for r in runs[t]) if None not in runs[t] else None for t in tools}
    mb = {t: statistics.median(r["work_mb"] for r in runs[t]) if None not in runs[t] else None for t in tools}
    last = {t: runs[t][-1] for t in tools}
    if last["ours-z2"]["betti"] != last["gudhi"]["betti"]:
        raise AssertionError(f"{name}: Betti numbers over Z/2 differ: ours {last['ours-z2']['betti']}, "
                             f"GUDHI {last['gudhi']['betti']}")

    def paired(a: str, b: str):
        if med[a] is None or med[b] is None:
            return None
        return statistics.median(x["time_s"] / y["time_s"] for x, y in zip(runs[a], runs[b]))

    row = {
        "case": name,
        "n_simplices": last["ours-z"]["n_simplices"],
        "betti_z2": last["gudhi"]["betti"],
        "betti_z": last["ours-z"]["betti"],
        "torsion_z": last["ours-z"]["torsion"],
        "ours_z_s": med["ours-z"],
        "ours_s": med["ours-z2"],
        "ref_s": med["gudhi"],
        "ratio": paired("ours-z2", "gudhi"),
        "ratio_z": paired("ours-z", "gudhi"),
        "ours_z_mb": mb["ours-z"],
        "ours_mb": mb["ours-z2"],
        "ref_mb": mb["gudhi"],
        "reference": "gudhi SimplexTree.compute_persistence(homology_coeff_field=2) + betti_numbers",
        "rounds": n,
    }
    if name in CORE_CASES:
        core = last["ours-core"]
        if last["pari-core"] is not None and last["pari-core"]["core_invariants"] != core["core_invariants"]:
            raise AssertionError(f"{name}: invariants of the dense core differ from PARI's")
        row.update({
            "core_shape": core["core_shape"], "core_max": core["core_max"], "core_rank": core["core_rank"],
            "ours_core_s": med["ours-core"], "pari_core_s": med["pari-core"],
            "pari_core": "PARI matsnf on the dense core (step only)" if med["pari-core"] is not None
            else f"PARI matsnf on the dense core stopped at {PARI_LIMIT_S} s",
            "ratio_core": paired("ours-core", "pari-core"),
        })
    return row


def _fmt(x, spec: str) -> str:
    return "—" if x is None else format(x, spec)


def _torsion_text(torsion: list) -> str:
    parts = [f"H{k}: " + "+".join(f"Z/{t}" for t in ts) for k, ts in enumerate(torsion) if ts]
    return ", ".join(parts) or "none"


COLUMNS = [
    ("case", "{case}"),
    ("simplices", "{n_simplices}"),
    ("Betti (Z/2)", "{betti_z2}"),
    ("torsion over Z", lambda r: _torsion_text(r["torsion_z"])),
    ("ours Z s", lambda r: _fmt(r["ours_z_s"], ".3g")),
    ("ours Z/2 s", lambda r: _fmt(r["ours_s"], ".3g")),
    ("GUDHI Z/2 s", lambda r: _fmt(r["ref_s"], ".3g")),
    ("ratio Z/2", lambda r: _fmt(r["ratio"], ".2g")),
    ("ratio Z", lambda r: _fmt(r["ratio_z"], ".2g")),
    ("core", lambda r: "×".join(map(str, r["core_shape"])) if r.get("core_shape") else "—"),
    ("ours core s", lambda r: _fmt(r.get("ours_core_s"), ".3g")),
    ("PARI core s", lambda r: _fmt(r.get("pari_core_s"), ".3g") if r.get("core_shape") else "—"),
    ("ours Z MB", lambda r: _fmt(r["ours_z_mb"], ".0f")),
    ("GUDHI MB", lambda r: _fmt(r["ref_mb"], ".0f")),
    ("rounds", "{rounds}"),
]


def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small cases only (smoke test)")
    ap.add_argument("--repeat", type=int, default=None, help="rounds (default 5, 15 under 0.1 s)")
    ap.add_argument("--case", nargs="+", default=None,
                    help="only these cases, updated in the stored results with their own provenance")
    ap.add_argument("--worker", nargs=2, metavar=("TOOL", "CASE"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.worker:
        print(json.dumps(worker(*args.worker)))
        return []
    names = args.case or (QUICK if args.quick else FULL)
    meta = harness.environment()
    rows = harness.stream_table(COLUMNS, names, lambda name: make_row(name, args.repeat))
    if args.case and not args.quick:  # refresh some rows of the stored results, each with its own run
        for row in rows:
            harness.update_results("homology", row, meta, order=FULL)
    else:
        harness.write_results("homology", rows, args.quick, meta=meta)
    return rows


if __name__ == "__main__":
    main()

"""Beyond the thesis: two-parameter invariants against multipers, and the Crust in R⁴.

Usage: ``python benchmarks/bench_beyond.py [--quick]``.  Prints Markdown tables and writes
``benchmarks/results/beyond.json`` (``beyond_quick.json`` with ``--quick``), one row per case:

* ``hilbert``/``rank``/``lines``: ours (``thesis_lib.multiparameter``) against multipers 2.3.2 on the
  same bifiltration (the same simplices and grades; grades rounded up to the grid for the grid
  invariants, which is what an invariant on the grid sees).  Whole pipeline against whole pipeline:
  ours from the :class:`Bifiltration`, multipers from inserting the simplices into its simplex tree
  to the invariant on the grid (the Hilbert function integrated from its signed measure).  multipers
  runs with ``n_jobs=1`` (ours is single-threaded too).  The outputs are compared for equality.
* ``crust4d``: the Crust of 3-sphere samples in R⁴ (radius 2), interleaved with Qhull's 4-D Delaunay
  of the samples alone (its first step, for scale), the peak memory of a fresh process above its
  import baseline, and whether the result is a closed 3-manifold.  No reference library
  reconstructs hypersurfaces of R⁴; the 3-D case is compared with ball pivoting in bench_crust.

Every case interleaves its contenders (harness.compare: a warm-up each, then at least 5 rounds,
15 under 0.1 s; medians and the median of paired ratios); memory from fresh processes
(harness.memory_fields).
"""

from __future__ import annotations

import importlib.metadata
import sys
import warnings

import harness
import numpy as np


def _bifiltration(case: str):
    from thesis_lib.curvature.point_curvature import point_curvature
    from thesis_lib.datasets import two_circles
    from thesis_lib.meshes import sample_torus
    from thesis_lib.multiparameter import radius_curvature_bifiltration

    kind, n = case.split("-")
    if kind == "torus":
        pts = sample_torus(int(n), seed=0)
        return radius_curvature_bifiltration(pts, point_curvature(pts, estimator="knn", curvature="gaussian", k=24),
                                             complex="alpha", absolute=False)
    pts = two_circles(int(n), seed=0)
    return radius_curvature_bifiltration(pts, point_curvature(pts, estimator="knn", k=10), complex="rips",
                                         max_radius=0.5, max_dim=2)


def _grid(bif, n_eps, n_kappa):
    lo, hi = bif.bounds()
    return np.linspace(lo[0], hi[0], n_eps), np.linspace(lo[1], hi[1], n_kappa)


def _tree(bif, eps=None, kappa=None):
    from multipers.simplex_tree_multi import SimplexTreeMulti

    t = SimplexTreeMulti(num_parameters=2)
    for s, g in zip(bif.simplices, bif.grades):
        if eps is not None:
            ie, ik = np.searchsorted(eps, g[:, 0]), np.searchsorted(kappa, g[:, 1])
            keep = (ie < len(eps)) & (ik < len(kappa))
            s, g = s[keep], np.column_stack([eps[ie[keep]], kappa[ik[keep]]])
        t.insert_batch(np.ascontiguousarray(s.T), np.ascontiguousarray(g))
    return t


def _mp_hilbert(bif, eps, kappa, dims):
    import multipers as mp

    tree = _tree(bif, eps, kappa)
    out = np.zeros((len(dims), len(eps), len(kappa)), dtype=np.int64)
    for a, d in enumerate(dims):
        locs, w = mp.signed_measure(tree, degree=d, invariant="hilbert", n_jobs=1)[0]
        x, y = np.searchsorted(eps, locs[:, 0]), np.searchsorted(kappa, locs[:, 1])
        dense = np.zeros((len(eps) + 1, len(kappa) + 1), dtype=np.int64)
        np.add.at(dense, (x, y), w.astype(np.int64))
        out[a] = dense.cumsum(0).cumsum(1)[: len(eps), : len(kappa)]
    return out


def _mp_rank(bif, eps, kappa, dim):
    import multipers as mp

    locs, w = mp.signed_measure(_tree(bif, eps, kappa), degree=dim, invariant="rank", n_jobs=1)[0]
    idx = [np.searchsorted(g, locs[:, c]) for c, g in enumerate((eps, kappa, eps, kappa))]
    ne, nk = len(eps), len(kappa)
    out = np.zeros((ne, nk, ne, nk), dtype=np.int64)
    for i, j, i2, j2 in np.ndindex(out.shape):
        if i <= i2 and j <= j2:
            out[i, j, i2, j2] = w[(idx[0] <= i) & (idx[1] <= j) & (idx[2] > i2) & (idx[3] > j2)].sum()
    return out


def _lines(bif, n_lines):
    from thesis_lib.multiparameter.plotting import line_fan

    return line_fan(bif.bounds(), n_lines=n_lines)


def _ours_lines(bif, base, dirs):
    from thesis_lib.multiparameter import fibered_barcode

    return [fibered_barcode(bif, base, d) for d in dirs]


def _mp_lines(bif, base, dirs):
    import multipers as mp

    return mp.Slicer(_tree(bif)).persistence_on_lines([base] * len(dirs), list(dirs))


def _same_lines(ours, theirs, dims) -> bool:
    for bc, th in zip(ours, theirs):
        for d in dims:
            m = np.asarray(th[d]).reshape(-1, 2)
            m = m[m[:, 1] > m[:, 0]]
            if not np.allclose(bc.intervals(d), m[np.lexsort((m[:, 1], m[:, 0]))]):
                return False
    return True


INVARIANTS = {"hilbert": ("Hilbert function", "40 × 40"), "rank": ("rank invariant (H₁)", "8 × 8"),
              "lines": ("fibered barcodes", "32 lines")}


def _invariant_contenders(data: str, invariant: str) -> tuple[object, dict]:
    """(bifiltration, {"ours": ..., "multipers": ...}) for one invariant of one data set."""
    from thesis_lib.multiparameter import hilbert_function, rank_invariant

    bif = _bifiltration(data)
    dims = list(range(bif.max_homology_dim + 1))
    if invariant == "hilbert":
        eps, kappa = _grid(bif, 40, 40)
        return bif, {"ours": lambda: hilbert_function(bif, eps, kappa, dims=dims),
                     "multipers": lambda: _mp_hilbert(bif, eps, kappa, dims)}
    if invariant == "rank":
        eps, kappa = _grid(bif, 8, 8)
        return bif, {"ours": lambda: rank_invariant(bif, eps, kappa, dim=1),
                     "multipers": lambda: _mp_rank(bif, eps, kappa, 1)}
    base, dirs = _lines(bif, 32)
    return bif, {"ours": lambda: _ours_lines(bif, base, dirs), "multipers": lambda: _mp_lines(bif, base, dirs)}


def invariant_row(case: str, rounds: int | None) -> dict:
    data, invariant = case.split("/")
    bif, contenders = _invariant_contenders(data, invariant)
    dims = list(range(bif.max_homology_dim + 1))
    same = {}

    def check(results):
        ours, ref = results["ours"], results["multipers"]
        same["equal"] = _same_lines(ours, ref, dims) if invariant == "lines" else bool(np.array_equal(ours, ref))

    res = harness.compare(contenders, rounds=rounds, check=check)
    name, grid = INVARIANTS[invariant]
    row = {"topic": "multiparameter", "case": case, "invariant": name, "grid": grid, "n_simplices": len(bif),
           "rounds": res["rounds"], "ours_s": res["median_s"]["ours"], "ref_s": res["median_s"]["multipers"],
           "ratio": harness.paired_ratio(res, "ours", "multipers"), "equal": same["equal"],
           "reference": "multipers " + importlib.metadata.version("multipers") + " (n_jobs=1)"}
    for tool in ("ours", "multipers"):
        row.update(harness.memory_fields(__file__, tool, case, tool))
    return row


def _sphere(n: int):
    from thesis_lib.meshes import sample_sphere

    return sample_sphere(n, n_dims=4, radius=2.0, seed=0)


def crust_row(case: str, rounds: int | None) -> dict:
    """The Crust of S³ samples, interleaved with Qhull's 4-D Delaunay of the same points (its first step)."""
    from scipy.spatial import Delaunay

    from thesis_lib.reconstruction.crust_nd import crust_nd

    n = int(case.split("-")[1])
    pts = _sphere(n)
    report = {}

    def check(results):
        report["r"] = results["crust"].report

    res = harness.compare({"crust": lambda: crust_nd(pts), "delaunay": lambda: Delaunay(pts, qhull_options="QJ")},
                          rounds=rounds, check=check)
    r = report["r"]
    row = {"topic": "crust4d", "case": case, "n_samples": n, "rounds": res["rounds"],
           "ours_s": res["median_s"]["crust"], "delaunay_s": res["median_s"]["delaunay"],
           "n_simplices": int(r.n_simplices), "closed": bool(r.is_closed_manifold),
           "vertex_fraction": float(r.vertex_fraction)}
    row.update(harness.memory_fields(__file__, "ours", case, "ours"))
    return row


def memory_child(case: str, tool: str) -> None:
    if case.startswith("crust4d"):
        from thesis_lib.reconstruction.crust_nd import crust_nd

        def setup():
            crust_nd(_sphere(300))  # imports and compiled code (the baseline)
            return _sphere(int(case.split("-")[1]))

        harness.memory_worker(setup, crust_nd)
        return

    def setup():
        data, invariant = case.split("/")
        _invariant_contenders("torus-100", invariant)[1][tool]()  # imports and compiled code
        return _invariant_contenders(data, invariant)[1][tool]

    harness.memory_worker(setup, lambda run: run())


def run_case(case: str, rounds: int | None) -> dict:
    return crust_row(case, rounds) if case.startswith("crust4d") else invariant_row(case, rounds)


QUICK = [f"torus-300/{inv}" for inv in INVARIANTS] + ["crust4d-1000"]
FULL = QUICK + [f"{data}/{inv}" for data in ("torus-1000", "circles-100") for inv in INVARIANTS] + \
    ["crust4d-3000", "crust4d-10000"]
COLUMNS = [("case", "{case}"), ("simplices", "{n_simplices}"), ("rounds", "{rounds}"), ("ours (s)", "{ours_s:.3f}"),
           ("peer (s)", lambda r: f"{r['ref_s']:.3f}" if "ref_s" in r else f"{r['delaunay_s']:.3f} (Delaunay)"),
           ("ratio", lambda r: f"{r['ratio']:.2f}" if "ratio" in r else "—"),
           ("ours (MB)", "{ours_mb:.0f}"), ("equal / closed", lambda r: str(r.get("equal", r.get("closed"))))]


def main(argv: list[str] | None = None) -> list[dict]:
    warnings.filterwarnings("ignore")
    try:
        import multipers  # noqa: F401
    except ImportError:
        print("multipers is not installed (pip install multipers==2.3.2): bench_beyond needs it", file=sys.stderr)
        return []
    return harness.run_cases("beyond", __doc__, argv, cases=FULL, quick=QUICK, full=FULL, columns=COLUMNS,
                             run_case=run_case, memory_child=memory_child, memory=("CASE", "TOOL"),
                             quick_help="the small torus and the smallest Crust (make bench-check)")


if __name__ == "__main__":
    main(sys.argv[1:])

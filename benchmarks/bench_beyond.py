"""Beyond the thesis: two-parameter invariants against multipers, and the Crust in R⁴.

Usage: ``python benchmarks/bench_beyond.py [--quick]``.  Prints Markdown tables and writes
``benchmarks/results/beyond.json`` (``beyond_quick.json`` with ``--quick``), one row per case:

* ``hilbert``/``rank``/``lines``: ours (``thesis_lib.multiparameter``) against multipers 2.3.2 on the
  same bifiltration (the same simplices and grades; grades rounded up to the grid for the grid
  invariants, which is what an invariant on the grid sees).  Whole pipeline against whole pipeline:
  ours from the :class:`Bifiltration`, multipers from inserting the simplices into its simplex tree
  to the invariant on the grid (the Hilbert function integrated from its signed measure).  multipers
  runs with ``n_jobs=1`` (ours is single-threaded too).  The outputs are compared for equality.
* ``crust4d``: the Crust of 3-sphere samples in R⁴ (radius 2), with Qhull's 4-D Delaunay alone, the
  peak RSS of a fresh process, and whether the result is a closed 3-manifold.  No reference library
  reconstructs hypersurfaces of R⁴; the 3-D case is compared with ``thesis_lib.meshes.crust``.

Times are the best of a few runs after a warm-up (numba compilation excluded).
"""

from __future__ import annotations

import json
import sys
import time
import warnings

import harness
import numpy as np

QUICK = {"invariants": ["torus-300"], "crust": [1000]}
FULL = {"invariants": ["torus-1000", "circles-100"], "crust": [1000, 10000, 30000]}

INV_COLUMNS = [("case", "{case}"), ("invariant", "{invariant}"), ("grid", "{grid}"), ("simplices", "{n_simplices}"),
               ("ours (s)", "{ours_s:.3f}"), ("multipers (s)", "{ref_s:.3f}"), ("ratio", "{ratio:.2f}"),
               ("equal", "{equal}")]
CRUST_COLUMNS = [("case", "{case}"), ("Crust (s)", "{ours_s:.1f}"), ("Qhull 4-D Delaunay (s)", "{delaunay_s:.1f}"),
                 ("peak RSS (MB)", "{ours_mb:.0f}"), ("tetrahedra", "{n_simplices}"),
                 ("closed 3-manifold", "{closed}"), ("samples used", "{vertex_fraction:.3f}")]


def _bifiltration(case: str):
    from thesis_lib.datasets import two_circles
    from thesis_lib.meshes import sample_torus
    from thesis_lib.meshes.point_curvature import point_curvature
    from thesis_lib.multiparameter import radius_curvature_bifiltration

    kind, n = case.split("-")
    if kind == "torus":
        pts = sample_torus(int(n), seed=0)
        return radius_curvature_bifiltration(pts, point_curvature(pts, estimator="knn", kind="gaussian", k=24),
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

    return line_fan(bif.bounds(), n_lines)


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


def invariant_rows(case: str, repeat: int) -> list[dict]:
    from thesis_lib.multiparameter import hilbert_function, rank_invariant

    bif = _bifiltration(case)
    dims = list(range(bif.max_homology_dim + 1))
    rows = []
    eps, kappa = _grid(bif, 40, 40)
    ours_s, ours = harness.best_of(lambda: hilbert_function(bif, eps, kappa, dims=dims), repeat)
    ref_s, ref = harness.best_of(lambda: _mp_hilbert(bif, eps, kappa, dims), repeat)
    rows.append(dict(invariant="Hilbert function", grid="40 × 40", ours_s=ours_s, ref_s=ref_s,
                     equal=bool(np.array_equal(ours, ref))))
    eps, kappa = _grid(bif, 8, 8)
    ours_s, ours = harness.best_of(lambda: rank_invariant(bif, eps, kappa, dim=1), repeat)
    ref_s, ref = harness.best_of(lambda: _mp_rank(bif, eps, kappa, 1), repeat)
    rows.append(dict(invariant="rank invariant (H₁)", grid="8 × 8", ours_s=ours_s, ref_s=ref_s,
                     equal=bool(np.array_equal(ours, ref))))
    base, dirs = _lines(bif, 32)
    ours_s, ours = harness.best_of(lambda: _ours_lines(bif, base, dirs), repeat)
    ref_s, ref = harness.best_of(lambda: _mp_lines(bif, base, dirs), repeat)
    rows.append(dict(invariant="fibered barcodes", grid="32 lines", ours_s=ours_s, ref_s=ref_s,
                     equal=_same_lines(ours, ref, dims)))
    for row in rows:
        row.update(topic="multiparameter", case=case, n_simplices=len(bif), ratio=row["ours_s"] / row["ref_s"])
    return rows


def crust_worker(n: int) -> dict:
    """One S³ reconstruction in this fresh process: times, peak RSS, the manifold check."""
    from thesis_lib.meshes import sample_sphere
    from thesis_lib.meshes.crust_nd import _delaunay, crust_nd

    crust_nd(sample_sphere(300, 4, 2.0, seed=1))  # numba compilation
    pts = sample_sphere(n, 4, 2.0, seed=0)
    t0 = time.perf_counter()
    _delaunay(pts)
    delaunay_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    res = crust_nd(pts)
    return dict(ours_s=time.perf_counter() - t0, delaunay_s=delaunay_s, ours_mb=harness.status_mb("VmHWM"),
                n_simplices=int(res.report.n_simplices), closed=bool(res.report.is_closed_manifold),
                vertex_fraction=float(res.report.vertex_fraction))


def crust_row(n: int) -> dict:
    row = harness.run_worker(__file__, "crust", n)
    row.update(topic="crust4d", case=f"S³ (radius 2), {n} samples", n_samples=n)
    return row


def main(argv=None) -> None:
    args = harness.arguments(__doc__, argv, worker=("TOOL", "CASE"))
    if args.worker:
        print(json.dumps(crust_worker(int(args.worker[1]))))
        return
    warnings.filterwarnings("ignore")
    cases = QUICK if args.quick else FULL
    repeat = 1 if args.quick else 3
    rows = []
    try:
        import multipers  # noqa: F401
    except ImportError:
        print("multipers is not installed (pip install 'multipers>=2.3.2,<2.4'): invariants not compared",
              file=sys.stderr)
    else:
        invariant_rows(cases["invariants"][0], 1)  # warm-up: numba compilation
        print(harness.table_header(INV_COLUMNS), flush=True)
        for case in cases["invariants"]:
            for row in invariant_rows(case, repeat):
                print(harness.table_row(INV_COLUMNS, row), flush=True)
                rows.append(row)
    print()
    rows += harness.stream_table(CRUST_COLUMNS, cases["crust"], crust_row)
    harness.write_rows("beyond", rows, args.quick)


if __name__ == "__main__":
    main()

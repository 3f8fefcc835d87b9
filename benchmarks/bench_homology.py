"""Simplicial homology (§2.2.1): thesis_lib over Z and Z/2 against GUDHI's Betti numbers (Z/2).

Usage: ``python benchmarks/bench_homology.py [--quick] [--repeat N]``.

Every (case, tool) runs in its own subprocess so that the resident-set high-water mark
(``resource.getrusage``) belongs to that tool alone: build the input (not timed), warm up on a
small complex (numba compilation excluded), read the RSS mark (``base_mb``), time the computation
(best of ``--repeat``), read the mark again; ``work_mb = peak - base``.

Tools, all starting from the same per-dimension arrays of simplices:

* ``ours-z`` — ``homology(arrays, 0)``: closure, boundary matrices, unit-pivot elimination with
  clearing, dense Smith normal form of the small core; Betti numbers and torsion over Z.
* ``ours-z2`` — ``homology(arrays, 2)``.
* ``gudhi`` — ``SimplexTree.insert_batch`` per dimension (constant filtration),
  ``compute_persistence(homology_coeff_field=2, persistence_dim_max=True)``, ``betti_numbers()``.

``ratio`` is ours over Z/2 / GUDHI, ``ratio_z`` ours over Z / GUDHI (GUDHI has no Z homology).
Cases: Vietoris–Rips complexes of uniform random points (2-D up to triangles, 3-D up to
tetrahedra), grid-triangulated torus and Klein bottle (torsion Z/2 at 10⁵ simplices), and a
Linial–Meshulam random 2-complex, the hard case for elimination over Z (large dense core).
"""

from __future__ import annotations

import itertools

import harness

CASES = {
    "rips-2d-300": {"kind": "rips", "n": 300, "dim": 2, "r": 0.09, "max_dim": 2},
    "rips-2d-3000": {"kind": "rips", "n": 3000, "dim": 2, "r": 0.04, "max_dim": 2},
    "rips-3d-2500": {"kind": "rips", "n": 2500, "dim": 3, "r": 0.12, "max_dim": 3},
    "torus-grid-20": {"kind": "grid", "n": 20, "twist": False},
    "torus-grid-180": {"kind": "grid", "n": 180, "twist": False},
    "klein-grid-180": {"kind": "grid", "n": 180, "twist": True},
    "linial-meshulam-40": {"kind": "lm", "n": 40, "c": 4.0},
    "linial-meshulam-100": {"kind": "lm", "n": 100, "c": 4.0},
}
FULL = ["rips-2d-3000", "rips-3d-2500", "torus-grid-180", "klein-grid-180", "linial-meshulam-100"]
QUICK = ["rips-2d-300", "torus-grid-20", "linial-meshulam-40"]


def complex_arrays(name: str) -> list:
    """The case's complex as a list of per-dimension (m_k, k+1) int64 arrays (all simplices)."""
    import numpy as np

    from thesis_lib.datasets.triangulations import _grid_surface
    from thesis_lib.simplicial import closure

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
    if case["kind"] == "grid":
        return closure(_grid_surface(case["n"], case["n"], case["twist"]))
    n = case["n"]
    rng = np.random.default_rng(0)
    tris = np.array(list(itertools.combinations(range(n), 3)), dtype=np.int64)
    tris = tris[rng.random(len(tris)) < case["c"] / n]
    edges = np.array(list(itertools.combinations(range(n), 2)), dtype=np.int64)
    return [np.arange(n, dtype=np.int64)[:, None], edges, tris]


def worker(tool: str, name: str, repeat: int) -> dict:
    import numpy as np

    arrays = complex_arrays(name)
    n_simplices = int(sum(a.shape[0] for a in arrays))
    if tool in ("ours-z", "ours-z2"):
        from thesis_lib.homology import homology

        p = 0 if tool == "ours-z" else 2
        homology([(0, 1, 2), (1, 3)], p)  # warm-up: load the numba kernels
        run = lambda: homology(arrays, p)  # noqa: E731
        summary = lambda h: {"betti": [b for b, _ in h], "torsion": [t for _, t in h]}  # noqa: E731
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
        summary = lambda b: {"betti": b, "torsion": None}  # noqa: E731
    else:
        raise ValueError(f"unknown tool {tool!r}")
    stats, out = harness.measure_rss(run, repeat)
    return {**stats, "n_simplices": n_simplices, **summary(out)}


def run_case(tool: str, name: str, repeat: int) -> dict:
    return harness.run_worker(__file__, tool, name, "--repeat", repeat)


def _torsion_text(torsion: list) -> str:
    parts = [f"H{k}: " + "+".join(f"Z/{t}" for t in ts) for k, ts in enumerate(torsion) if ts]
    return ", ".join(parts) or "none"


COLUMNS = [
    ("case", "{case}"),
    ("simplices", "{n_simplices}"),
    ("Betti (Z/2)", "{betti_z2}"),
    ("torsion over Z", lambda r: _torsion_text(r["torsion_z"])),
    ("ours Z s", "{ours_z_s:.3f}"),
    ("ours Z/2 s", "{ours_s:.3f}"),
    ("GUDHI Z/2 s", "{ref_s:.3f}"),
    ("ratio Z/2", "{ratio:.2f}"),
    ("ratio Z", "{ratio_z:.2f}"),
    ("ours Z MB", "{ours_z_mb:.1f}"),
    ("ours Z/2 MB", "{ours_mb:.1f}"),
    ("GUDHI MB", "{ref_mb:.1f}"),
]


def make_row(name: str, repeat: int) -> dict:
    """One table row: every tool on case ``name`` (each in its own subprocess)."""
    oz = run_case("ours-z", name, repeat)
    o2 = run_case("ours-z2", name, repeat)
    ref = run_case("gudhi", name, repeat)
    if o2["betti"] != ref["betti"]:
        raise AssertionError(f"{name}: Betti numbers over Z/2 differ: ours {o2['betti']}, GUDHI {ref['betti']}")
    return {
        "case": name,
        "n_simplices": oz["n_simplices"],
        "betti_z2": ref["betti"],
        "betti_z": oz["betti"],
        "torsion_z": oz["torsion"],
        "ours_s": o2["time_s"],
        "ours_z_s": oz["time_s"],
        "ref_s": ref["time_s"],
        "ratio": o2["time_s"] / ref["time_s"],
        "ratio_z": oz["time_s"] / ref["time_s"],
        "ours_mb": o2["work_mb"],
        "ours_z_mb": oz["work_mb"],
        "ref_mb": ref["work_mb"],
        "reference": "gudhi SimplexTree.compute_persistence(homology_coeff_field=2) + betti_numbers",
        "repeat": repeat,
    }


def main(argv: list[str] | None = None) -> list[dict]:
    return harness.main_per_case("homology", __doc__, argv, worker=worker, make_row=make_row, columns=COLUMNS,
                                 cases=(QUICK, FULL), repeat=(2, 3))


if __name__ == "__main__":
    main()

"""Discrete curvature of thesis_lib against libigl on torus grids (thesis §3.4.1).

Usage: ``python benchmarks/bench_curvature.py [--quick] [--rounds N] [--cases NAME ...] [--output FILE]``.

Cases (ours vs libigl on the same mesh, whole calls from arrays to per-vertex arrays):

* ``mean_curvature_vector``: ∇ area at every vertex vs ``-(igl.cotmatrix(V, F) @ V)``;
* ``mixed_area``: Meyer's mixed area vs ``igl.massmatrix(V, F, MASSMATRIX_TYPE_VORONOI)``;
* ``gaussian_curvature``: angle defect / mixed area vs ``igl.gaussian_curvature / massmatrix``;
* ``mean_curvature``: |H| = ‖∇ area‖ / (2 · mixed area) vs the same from cotmatrix + massmatrix;
* ``all_three``: the first three together (what an experiment computes per mesh).

Ours includes its input checks in every call (shapes, NaN, degenerate triangles, the simplicial
pseudo-manifold check: no doubled face, no pinched vertex); libigl checks nothing.  Time: ours and
libigl interleaved in one process after a warm-up, 15 rounds under 0.1 s (else 5); medians and
``ratio_libigl``, the median of the per-round ratios (``harness.compare``).  Memory: each call once
in a fresh process, the peak resident set above the post-warm-up baseline (``harness.memory``).
Meshes: the periodic n × n torus grid (R = 10, r = 5) for n = 60 (quick), 317 (10⁵ vertices) and
448 (2·10⁵ vertices).
"""

from __future__ import annotations

import importlib.metadata

import harness
import numpy as np

OPS = ("mean_curvature_vector", "mixed_area", "gaussian_curvature", "mean_curvature", "all_three")
QUICK = [f"{op}-60" for op in OPS]
FULL = QUICK + [f"{op}-{k}" for k in (317, 448) for op in OPS]


def operations():
    """case operation -> (ours, libigl) callables of (V, F)."""
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
        return mean_curvature_vector(V, F), vertex_areas(V, F, area="mixed"), gaussian_curvature(V, F)

    def igl_all(V, F):
        return igl_vec(V, F), igl_area(V, F), igl_gauss(V, F)

    return {
        "mean_curvature_vector": (mean_curvature_vector, igl_vec),
        "mixed_area": (lambda V, F: vertex_areas(V, F, area="mixed"), igl_area),
        "gaussian_curvature": (gaussian_curvature, igl_gauss),
        "mean_curvature": (mean_curvature, igl_mean),
        "all_three": (ours_all, igl_all),
    }


def _mesh(name: str):
    from thesis_lib.datasets import torus_grid

    op, k = name.rsplit("-", 1)
    return op, int(k), *torus_grid(int(k))


def max_abs_diff(a, b) -> float:
    if isinstance(a, tuple):
        return max(max_abs_diff(x, y) for x, y in zip(a, b))
    return float(np.nanmax(np.abs(np.asarray(a) - np.asarray(b))))


def memory_run(name: str, tool: str) -> dict:
    def setup():
        op, _, V, F = _mesh(name)
        fn = operations()[op][0 if tool == "ours" else 1]
        fn(*_mesh(f"{op}-8")[2:])  # warm-up on a tiny mesh: imports and caches
        return fn, V, F

    return harness.memory_worker(setup, lambda state: state[0](state[1], state[2]))


COLUMNS = [
    ("case", "{case}"),
    ("vertices", "{n_vertices}"),
    ("ours (s)", "{ours_s:.4f}"),
    ("libigl (s)", "{libigl_s:.4f}"),
    ("ratio", "{ratio_libigl:.2f}"),
    ("rounds", "{rounds}"),
    ("ours (MB)", "{ours_mb:.1f}"),
    ("libigl (MB)", "{libigl_mb:.1f}"),
    ("max abs diff", "{max_abs_diff:.2e}"),
]


def make_row(name: str, rounds: int | None) -> dict:
    op, k, V, F = _mesh(name)
    ours, ref = operations()[op]
    diff = {}

    def check(results):
        diff["value"] = max_abs_diff(results["ours"], results["libigl"])

    result = harness.compare({"ours": lambda: ours(V, F), "libigl": lambda: ref(V, F)}, rounds=rounds, check=check)
    row = {"case": name, "operation": op, "mesh": f"torus grid {k}x{k}", "n_vertices": int(len(V)),
           "n_faces": int(len(F)), **harness.ratio_fields(result), "max_abs_diff": diff["value"],
           "reference": "libigl " + importlib.metadata.version("libigl")}
    for tool in ("ours", "libigl"):
        row.update(harness.memory_fields(__file__, tool, name, tool))
    return row


def main(argv: list[str] | None = None) -> list[dict]:
    return harness.run_cases(
        "curvature", __doc__, argv, cases=FULL, quick=QUICK, full=FULL, columns=COLUMNS, run_case=make_row,
        memory_child=memory_run, memory=("CASE", "TOOL")
    )


if __name__ == "__main__":
    main()

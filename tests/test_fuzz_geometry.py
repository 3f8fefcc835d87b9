"""Fuzz tests for complexes, curvature and meshes.

Hostile inputs (NaN and inf, duplicates, wrong shapes and types, empty input, huge and tiny
coordinates, degenerate sets, non-manifold and mutated meshes) go to every public function; each
call must return a value or raise ValueError/TypeError with a message: never another exception,
never a hang (``fuzz_call``'s deadline).  The calls that reach a C++ library which could crash the
interpreter (pymeshlab's ball pivoting) run in a subprocess.  ``--fuzz-long`` runs 100 times more
examples (``fuzz_settings``).
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pytest
from helpers import fuzz_call, fuzz_settings
from hypothesis import given
from hypothesis import strategies as st

from thesis_lib import complexes as cx
from thesis_lib import curvature as cv
from thesis_lib import meshes as ms
from thesis_lib import reconstruction as rc
from thesis_lib.datasets import flat_torus, noisy_circle, two_circles, two_circles_intersections

# ----------------------------------------------------------------------------- hostile values
SPECIAL = [np.nan, np.inf, -np.inf, 0.0, -0.0, 1e300, -1e300, 1e160, 1e-170, 5e-324, 1.0]
scalars = st.one_of(
    st.integers(-3, 6),
    st.sampled_from(SPECIAL),
    st.floats(-10, 10),
    st.sampled_from([None, "1", True, False, 2**70, -(2**70), 10**9, [1], np.int64(2), np.float32(0.5), 1j]),
)
garbage = st.sampled_from([None, "points", 3.0, [], [[]], [[1.0, 2.0], [3.0]], {"a": 1}, [None, None],
                           np.zeros((2, 2, 2)), np.array([["a", "b"]]), np.ones((3, 2), dtype=complex),
                           np.ones((3, 2), dtype=bool), np.array([1.0, 2.0, 3.0])])


@st.composite
def point_sets(draw, max_n: int = 14, dims=(1, 2, 3, 4)):
    """A point set that is often hostile: special values, duplicates, degenerate or garbage."""
    kind = draw(st.sampled_from(["random", "special", "duplicate", "flat", "scaled", "grid", "garbage", "empty"]))
    if kind == "garbage":
        return draw(garbage)
    d = draw(st.sampled_from(dims))
    n = draw(st.integers(0, max_n))
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    pts = rng.random((n, d))
    if kind == "empty":
        return np.zeros((0, d))
    if kind == "special" and n:
        pts[rng.integers(n), rng.integers(d)] = draw(st.sampled_from(SPECIAL))
    elif kind == "duplicate" and n:
        pts = np.vstack([pts, pts[: draw(st.integers(1, n))]])
    elif kind == "flat" and n and d > 1:
        pts[:, -1] = pts[:, 0] * draw(st.sampled_from([0.0, 1.0, 1e-12]))
    elif kind == "scaled":
        pts = pts * draw(st.sampled_from([1e160, 1e-170, 1e300, 1e-300, 2.0**500]))
    elif kind == "grid":  # exact ties everywhere (side 3 in R^4 already takes seconds, as in GUDHI)
        d = min(d, 3)
        side = draw(st.integers(2, 4))
        pts = np.stack(np.meshgrid(*[np.arange(side)] * d, indexing="ij"), -1).reshape(-1, d).astype(float)
        pts = pts + draw(st.sampled_from([0.0, 1e-14, 1e-9])) * rng.normal(size=pts.shape)
    return pts


def small_mesh(d: int):
    """A closed triangulated hypersurface in R^d (boundary of a simplex) and one with boundary."""
    x = np.vstack([np.zeros(d), np.eye(d)])
    faces = np.array([[j for j in range(d + 1) if j != i] for i in range(d + 1)])
    return x, faces


@st.composite
def meshes(draw):
    """(vertices, simplices): a valid small mesh, mutated in a hostile way most of the time."""
    d = draw(st.sampled_from([2, 3, 4]))
    if d == 3 and draw(st.booleans()):
        x, f = ms.torus_grid(draw(st.integers(3, 6)))
    else:
        x, f = small_mesh(d)
    x, f = x.astype(float).copy(), f.copy()
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    kind = draw(st.sampled_from(["valid", "index", "negative", "float", "double", "pinch", "drop", "flip",
                                 "collapse", "special", "width", "garbage", "empty", "scaled"]))
    if kind == "index":
        f[rng.integers(len(f)), 0] = len(x) + rng.integers(0, 3)
    elif kind == "negative":
        f[rng.integers(len(f)), 0] = -1
    elif kind == "float":
        f = f + draw(st.sampled_from([0.0, 0.5]))
    elif kind == "double":
        f = np.vstack([f, f[rng.integers(len(f))][None]])
    elif kind == "pinch":
        f = np.vstack([f, np.where(f == f[0, 0], f[0, 0], f + len(x))])
        x = np.vstack([x, x + 3.0])
    elif kind == "drop" and len(f) > 1:
        f = np.delete(f, rng.integers(len(f)), axis=0)
    elif kind == "flip":
        f[0] = f[0, ::-1]
    elif kind == "collapse":
        x[f[0, 1]] = x[f[0, 0]]
    elif kind == "special":
        x[rng.integers(len(x)), rng.integers(x.shape[1])] = draw(st.sampled_from(SPECIAL))
    elif kind == "width":
        f = f[:, :-1]
    elif kind == "garbage":
        return draw(garbage), draw(st.one_of(garbage, st.just(f)))
    elif kind == "empty":
        f = f[:0]
    elif kind == "scaled":
        x = x * draw(st.sampled_from([1e160, 1e-170]))
    return x, f


# ----------------------------------------------------------------------------- targets
COMPLEX_CALLS = {
    "rips": lambda p, a, b: cx.rips(p, max_radius=a, max_dim=b),
    "rips_matrix": lambda p, a, b: cx.rips(distance_matrix=p, max_radius=a, max_dim=b),
    "cech": lambda p, a, b: cx.cech(p, max_radius=a, max_dim=b),
    "alpha": lambda p, a, b: cx.alpha(p),
    "alpha_weighted": lambda p, a, b: cx.alpha(p, np.full(len(p), a) if hasattr(p, "__len__") and
                                               not isinstance(p, (str, dict)) else a),
    "delaunay": lambda p, a, b: cx.delaunay(p),
    "regular_triangulation": lambda p, a, b: cx.regular_triangulation(p, a),
    "witness": lambda p, a, b: cx.witness(p, [0, 1], max_radius=a, max_dim=b),
    "lazy_witness": lambda p, a, b: cx.lazy_witness(p, b, max_radius=a, max_dim=2),
    "witness_offsets": lambda p, a, b: cx.witness_offsets(p, [0], nu=b),
    "maxmin_landmarks": lambda p, a, b: cx.maxmin_landmarks(p, n=b, seed=0),
    "random_landmarks": lambda p, a, b: cx.random_landmarks(p, n=b, seed=a),
    "covering_radius": lambda p, a, b: cx.covering_radius(p, [b]),
    "count_within": lambda p, a, b: cx.landmarks.count_within(p, p, a),
    "smallest_enclosing_ball": lambda p, a, b: cx.smallest_enclosing_ball(p, seed=b),
    "build_filtration": lambda p, a, b: cx.build_filtration(p, complex="witness", max_radius=a, max_dim=b,
                                                            n_landmarks=2),
    "nerve": lambda p, a, b: cx.nerve(p, max_dim=b),
}


def _check_complex_value(name, value):
    """Light checks of a returned value (the property tests check them against references)."""
    if isinstance(value, cx.Filtration):
        for arr in value.values:
            assert not np.isnan(arr).any(), f"{name} returned NaN values"


@fuzz_settings(30)
@given(point_sets(), scalars, scalars, st.sampled_from(sorted(COMPLEX_CALLS)))
def test_fuzz_complexes(points, a, b, name):
    ok, value = fuzz_call("complexes", COMPLEX_CALLS[name], points, a, b, seconds=30.0)
    if ok:
        _check_complex_value(name, value)


CURVATURE_CALLS = {
    "vertex_areas": lambda v, f: cv.vertex_areas(v, f, area="mixed"),
    "vertex_areas_voronoi": lambda v, f: cv.vertex_areas(v, f, area="voronoi"),
    "mean_curvature": lambda v, f: cv.mean_curvature(v, f, area="barycentric"),
    "mean_curvature_mixed": lambda v, f: cv.mean_curvature(v, f),
    "mean_curvature_vector_cot": lambda v, f: cv.mean_curvature_vector(v, f, method="cot"),
    "gaussian_curvature": lambda v, f: cv.gaussian_curvature(v, f),
    "angle_defects": lambda v, f: cv.angle_defects(v, f),
    "shape_operator": lambda v, f: cv.shape_operator(v, f),
    "principal_curvatures": lambda v, f: cv.principal_curvatures(v, f, edge_weights="uniform"),
    "vertex_normals": lambda v, f: cv.vertex_normals(v, f),
    "normal_curvatures": lambda v, f: cv.normal_curvatures(v, f),
    "total_hyperarea": lambda v, f: cv.total_hyperarea(v, f),
    "circumcentric_fractions": lambda v, f: cv.circumcentric_fractions(_corners(v, f)),
}


def _corners(v, f):
    """``v[f]`` when that indexes, else ``v`` itself (then the function sees the raw garbage)."""
    try:
        return np.asarray(v, dtype=float)[np.asarray(f)]
    except (TypeError, ValueError, IndexError):
        return v


@fuzz_settings(30)
@given(meshes(), st.sampled_from(sorted(CURVATURE_CALLS)))
def test_fuzz_curvature(mesh, name):
    v, f = mesh
    fuzz_call("curvature", CURVATURE_CALLS[name], v, f, seconds=30.0)


MESH_CALLS = {
    "orient_outward": lambda v, f, a: ms.orient_outward(v, f),
    "orient_outward_centre": lambda v, f, a: ms.orient_outward(v, f, centre=[a, a, a]),
    "convex_hull_surface": lambda v, f, a: ms.convex_hull_surface(v),
    "merge_coincident": lambda v, f, a: ms.merge_coincident(v, f, tol=a),
    "euler_characteristic": lambda v, f, a: ms.euler_characteristic(f),
    "facet_degrees": lambda v, f, a: ms.facet_degrees(f),
    "is_closed_pseudomanifold": lambda v, f, a: ms.is_closed_pseudomanifold(f),
    "faces_of": lambda v, f, a: ms.faces_of(f, k=a),
    "crust": lambda v, f, a: rc.crust(v),
    "crust_theta": lambda v, f, a: rc.crust(v, theta=a),
    "extract_manifold": lambda v, f, a: rc.extract_manifold(v, f),
    "poles": lambda v, f, a: rc.poles(v, far=a),
    "estimate_normals": lambda v, f, a: rc.estimate_normals(v, k=a),
}
GRID_CALLS = {
    "freudenthal": lambda a, b: ms.freudenthal((a, b)),
    "freudenthal_many": lambda a, b: ms.freudenthal((2,) * (min(abs(b), 30) if isinstance(b, int) else 3)),
    "freudenthal_periodic": lambda a, b: ms.freudenthal(a, periodic=b),
    "grid_parameters": lambda a, b: ms.grid_parameters([a, b], [1.0, 2.0]),
    "torus_grid": lambda a, b: ms.torus_grid(a),
    "torus_chosen_points": lambda a, b: ms.torus_chosen_points(step=a),
    "hypersphere_freudenthal": lambda a, b: ms.hypersphere_freudenthal(step=a, n=b),
    "catenoid_freudenthal": lambda a, b: ms.catenoid_freudenthal(step=a, n=b),
    "sample_torus": lambda a, b: ms.sample_torus(a, seed=b),
    "sample_sphere": lambda a, b: ms.sample_sphere(a, n_dims=b),
    "sample_catenoid": lambda a, b: ms.sample_catenoid(a, v_range=(b, 1.0)),
    "sphere_hull": lambda a, b: ms.sphere_hull(n_dims=b, n_points=a),
    "cross_stars": lambda a, b: cv.cross_stars(lambda w: np.column_stack([w, w[:, :1]]), [[0.0, a]], step=b),
    "noisy_circle": lambda a, b: noisy_circle(a, noise=b),
    "two_circles": lambda a, b: two_circles(a, distance=b),
    "two_circles_intersections": lambda a, b: two_circles_intersections(distance=a),
    "flat_torus": lambda a, b: flat_torus(a, noise=b),
}


@fuzz_settings(30)
@given(point_sets(max_n=30, dims=(2, 3)), meshes(), scalars, st.sampled_from(sorted(MESH_CALLS)))
def test_fuzz_meshes(points, mesh, a, name):
    v, f = (points, mesh[1]) if name in ("crust", "crust_theta", "poles", "convex_hull_surface",
                                         "estimate_normals") else mesh
    fuzz_call("meshes", MESH_CALLS[name], v, f, a, seconds=30.0)


@fuzz_settings(30)
@given(scalars, scalars, st.sampled_from(sorted(GRID_CALLS)))
def test_fuzz_grids_and_samplers(a, b, name):
    fuzz_call("meshes", GRID_CALLS[name], a, b, seconds=30.0)


def test_ball_pivoting_hostile_input_in_subprocess():
    # pymeshlab is C++: a crash there would take the test process down, so it runs on its own
    code = textwrap.dedent("""
        import numpy as np
        from thesis_lib.reconstruction import ball_pivoting
        for case in ["nan", "flat", "duplicates", "two", "huge", "normals"]:
            rng = np.random.default_rng(0)
            pts = rng.normal(size=(40, 3))
            pts /= np.linalg.norm(pts, axis=1)[:, None]
            normals = None
            if case == "nan":
                pts[3, 1] = np.nan
            elif case == "flat":
                pts[:, 2] = 0.0
            elif case == "duplicates":
                pts = np.vstack([pts, pts[:5]])
            elif case == "two":
                pts = pts[:2]
            elif case == "huge":
                pts = pts * 1e160
            elif case == "normals":
                normals = np.zeros_like(pts)
            try:
                ball_pivoting(pts, normals)
                print(case, "value")
            except (ValueError, TypeError) as exc:
                assert str(exc).strip()
                print(case, "error")
    """)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    outcome = dict(line.split() for line in proc.stdout.strip().splitlines())
    assert outcome == {"nan": "error", "flat": outcome["flat"], "duplicates": "error", "two": "error",
                       "huge": "value", "normals": outcome["normals"]}


def test_qhull_never_sees_huge_coordinates():
    # Qhull can crash the interpreter (SIGSEGV) on samples near 3e150; the Crust and the hull run on
    # points scaled by a power of two.  In a subprocess, so that a crash cannot kill pytest.
    code = textwrap.dedent("""
        import numpy as np
        from thesis_lib.meshes import convex_hull_surface, sample_sphere
        from thesis_lib.reconstruction import crust, poles
        pts = sample_sphere(60, seed=0) * 2.0**500
        faces = crust(pts)
        assert len(faces) and faces.max() < len(pts)
        p_plus, _ = poles(pts)
        assert np.all(np.isfinite(p_plus)) and np.abs(p_plus).max() > 1e149
        hull = convex_hull_surface(pts)
        assert np.array_equal(np.sort(hull, axis=1), np.sort(convex_hull_surface(pts / 2.0**500), axis=1))
        print("ok")
    """)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.strip().endswith("ok")


def test_absurd_grid_dimensions_and_complex_corners_are_refused():
    """n = 2**70 is refused by the size check before it could overflow a shape; complex corner
    coordinates are refused, not cast to real."""
    import numpy as np

    from thesis_lib.curvature import circumcentric_fractions
    from thesis_lib.meshes.grids import MAX_GRID_DIM, catenoid_freudenthal, hypersphere_freudenthal

    with pytest.raises(ValueError, match=f"n must be <= {MAX_GRID_DIM}"):
        catenoid_freudenthal(step=1, n=2**70)
    with pytest.raises(ValueError, match=f"n must be <= {MAX_GRID_DIM}"):
        hypersphere_freudenthal(step=np.pi / 4, radius=2.0, n=2**70)
    with pytest.raises(ValueError, match="complex numbers are not coordinates"):
        circumcentric_fractions(np.zeros((1, 3, 2)) + 1j)


def test_dense_expansions_to_a_huge_dimension_are_refused_up_front():
    """Čech and Rips of a 4 × 4 × 4 grid at ε = 2 with max_dim = 2**70: the clique bound Σ C(deg⁺, d)
    refuses them at once, before any expansion."""
    import numpy as np

    from thesis_lib.complexes import cech, rips

    grid = np.array([[i, j, k] for i in range(4) for j in range(4) for k in range(4)], dtype=float)
    for build in (cech, rips):
        with pytest.raises(ValueError, match="could number up to"):
            build(grid, max_radius=2.0, max_dim=2**70)
        assert len(build(grid, max_radius=0.6, max_dim=3)) == 208  # the unit-spaced grid's 64 vertices and 144 edges

"""Triangulations of chapter 3: torus grid, Freudenthal subdivisions, convex hulls, samplers, stencil."""

from math import factorial

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thesis_lib import datasets
from thesis_lib.curvature import cross_stars, neighbour_grid_mean_curvature, simplex_hyperareas
from thesis_lib.meshes import (
    catenoid_freudenthal,
    convex_hull_surface,
    euler_characteristic,
    facet_degrees,
    freudenthal,
    grid_parameters,
    hypersphere_freudenthal,
    is_closed_pseudomanifold,
    merge_coincident,
    sample_catenoid,
    sample_sphere,
    sample_torus,
    sphere_hull,
    torus_chosen_points,
    torus_grid,
)
from thesis_lib.surfaces import catenoid_point, hypersphere_point, torus_uv


def _signed_volumes(params, simplices):
    p = params[simplices]
    return np.linalg.det(p[:, 1:] - p[:, :1])


def test_torus_grid_is_closed_genus_one_and_outward():
    v, f = torus_grid(20, R=10.0, r=5.0)
    assert v.shape == (400, 3) and f.shape == (800, 3)
    assert euler_characteristic(f) == 0 and is_closed_pseudomanifold(f)
    assert np.allclose(v[0], [15, 0, 0]) and np.allclose(v[1], [10 + 5 * np.cos(np.pi / 10), 0, 5 * np.sin(np.pi / 10)])
    p = v[f]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    c = p.mean(axis=1)
    ring = c.copy()
    ring[:, 2] = 0
    ring *= 10 / np.linalg.norm(ring, axis=1, keepdims=True)  # centre of the tube
    assert np.all(np.einsum("ij,ij->i", nrm, c - ring) > 0)
    assert datasets.torus_grid is torus_grid


def test_chosen_points_step():
    v, f, uv = torus_chosen_points(step=np.pi / 50)
    assert len(v) == 100 * 100 and np.isclose(uv[1, 1], np.pi / 50)
    with pytest.raises(ValueError, match="integer"):
        torus_chosen_points(step=0.3)


@pytest.mark.parametrize("shape,periodic", [((3, 4), False), ((4, 3, 3), False), ((5, 3), (True, False)),
                                            ((3, 3, 3, 3), False), ((4, 5, 3), (False, True, False))])
def test_freudenthal_tiles_the_box(shape, periodic):
    s = freudenthal(shape, periodic=periodic)
    n = len(shape)
    per = (periodic,) * n if isinstance(periodic, bool) else periodic
    cells = np.prod([m if p else m - 1 for m, p in zip(shape, per)])
    assert s.shape == (factorial(n) * cells, n + 1)
    assert len(np.unique(np.sort(s, axis=1), axis=0)) == len(s)
    if not any(per):
        params = grid_parameters(*[np.arange(m, dtype=float) for m in shape])
        vol = _signed_volumes(params, s)
        assert np.all(vol > 0)  # positively oriented
        assert np.isclose(vol.sum() / factorial(n), np.prod([m - 1 for m in shape]))  # tiles the box
        deg = facet_degrees(s)
        assert set(np.unique(deg)) <= {1, 2}


@settings(deadline=None, max_examples=10)
@given(st.lists(st.integers(3, 5), min_size=2, max_size=3))
def test_freudenthal_periodic_torus_is_closed(shape):
    s = freudenthal(tuple(shape), periodic=True)
    assert is_closed_pseudomanifold(s)
    assert euler_characteristic(s) == 0  # the n-torus


@pytest.mark.parametrize("n,k", [(2, 12), (3, 8)])
def test_hypersphere_freudenthal_is_a_closed_sphere(n, k):
    v, s, params = hypersphere_freudenthal(step=np.pi / k, radius=2.0, n=n)
    assert is_closed_pseudomanifold(s)
    assert euler_characteristic(s) == 1 + (-1) ** n
    assert np.allclose(np.linalg.norm(v, axis=1), 2.0)
    assert np.allclose(hypersphere_point(params, radius=2.0), v)
    vol = simplex_hyperareas(v, s).sum()
    exact = {2: 4 * np.pi * 4, 3: 2 * np.pi**2 * 8}[n]
    assert 0.9 * exact < vol < exact
    assert _coherently_oriented(s)


def _coherently_oriented(s):
    """Each ridge must appear with opposite induced orientations in its two simplices."""
    keys, signs = [], []
    n1 = s.shape[1]
    for i in range(n1):
        r = np.delete(s, i, axis=1)
        inv = sum((r[:, a] > r[:, b]).astype(int) for a in range(n1 - 1) for b in range(a + 1, n1 - 1))
        keys.append(np.sort(r, axis=1))
        signs.append((-1) ** i * (-1) ** inv)
    keys = np.concatenate(keys)
    signs = np.concatenate(signs)
    _, inverse = np.unique(keys, axis=0, return_inverse=True)
    return bool(np.all(np.bincount(inverse.ravel(), weights=signs) == 0))


def test_orientation_helper():
    v, f = torus_grid(6)
    assert _coherently_oriented(f)
    f2 = f.copy()
    f2[0, [0, 1]] = f2[0, [1, 0]]
    assert not _coherently_oriented(f2)


def test_catenoid_freudenthal_piece():
    v, s, params = catenoid_freudenthal(step=0.1, n=3, v_range=(-1, 1), w_range=(-1, 1))
    assert v.shape[1] == 4 and s.shape[1] == 4
    assert euler_characteristic(s) == 0  # annulus × interval
    assert np.allclose(catenoid_point(params), v)
    assert set(np.unique(facet_degrees(s))) == {1, 2}
    with pytest.raises(ValueError, match="integer"):
        catenoid_freudenthal(step=0.3, v_range=(-1, 1))


def test_merge_coincident_drops_degenerate():
    v = np.array([[0.0, 0], [1, 0], [1, 1e-12], [0, 1]])
    s = np.array([[0, 1, 3], [0, 2, 3], [0, 1, 2]])
    v2, s2, kept = merge_coincident(v, s, tol=1e-9)
    assert len(v2) == 3 and list(kept) == [0, 1, 3]
    assert s2.tolist() == [[0, 1, 2]]


@pytest.mark.parametrize("d", [3, 4, 5])
def test_sphere_hull(d):
    pts, s = sphere_hull(n_dims=d, n_points=200, seed=d)
    assert np.allclose(np.linalg.norm(pts, axis=1), 1)
    assert is_closed_pseudomanifold(s)
    assert euler_characteristic(s) == 1 + (-1) ** (d - 1)
    assert _coherently_oriented(s)
    p = pts[s]
    mat = np.concatenate([p[:, 1:] - p[:, :1], p[:, :1]], axis=1)
    assert np.all(np.linalg.det(mat) > 0)  # outward


def test_samplers_are_uniform_in_area():
    pts, uv = sample_torus(20000, R=10.0, r=5.0, seed=3, return_uv=True)
    assert pts.shape == (20000, 3)
    assert np.allclose(np.hypot(np.hypot(pts[:, 0], pts[:, 1]) - 10, pts[:, 2]), 5)
    # density of v is (R + r cos v) / (2π R): P(cos v > 0) = 1/2 + r/(πR)
    frac = np.mean(np.cos(uv[:, 1]) > 0)
    assert abs(frac - (0.5 + 5 / (10 * np.pi))) < 0.015
    u, v = torus_uv(pts)
    assert np.allclose(np.cos(v), np.cos(uv[:, 1]))
    assert np.array_equal(sample_torus(50, seed=1), sample_torus(50, seed=1))
    c = sample_catenoid(5000, v_range=(-1, 1), seed=0)
    assert np.allclose(np.hypot(c[:, 0], c[:, 1]), np.cosh(c[:, 2]))
    s = sample_sphere(100, n_dims=4, radius=2.0, seed=0)
    assert np.allclose(np.linalg.norm(s, axis=1), 2.0)


def test_cross_star_stencil():
    w = np.array([[0.5, 0.7, 1.0]])
    v, s, c = cross_stars(lambda a: hypersphere_point(a, radius=2.0), w, step=0.1)
    assert v.shape == (7, 4) and s.shape == (8, 4) and c.tolist() == [0]
    eps = np.pi / 50
    P = grid_parameters(eps * np.arange(5, 45, 10), eps * np.arange(5, 45, 10), eps * np.arange(0, 100, 25))
    H = neighbour_grid_mean_curvature(lambda a: hypersphere_point(a, radius=2.0), P, step=eps)
    assert np.allclose(H, 0.5, rtol=3e-3)
    Hc = neighbour_grid_mean_curvature(catenoid_point, np.array([[0.0, 0.0, 0.0], [1.0, -0.9, 0.5]]), step=0.05)
    assert np.all(Hc < 2e-4)
    # the surface case: |H| of the torus from the 4-neighbour star
    from thesis_lib.surfaces import torus_mean_curvature, torus_point

    uv = np.array([[0.3, 0.4], [1.0, 2.0]])
    Ht = neighbour_grid_mean_curvature(lambda a: torus_point(a[:, 0], a[:, 1]), uv, step=0.01)
    assert np.allclose(Ht, np.abs(torus_mean_curvature(uv[:, 0], uv[:, 1])), rtol=1e-3)


def test_bad_input():
    with pytest.raises(ValueError, match="n must be"):
        torus_grid(2)
    with pytest.raises(ValueError, match="grid size"):
        freudenthal((1, 4))
    with pytest.raises(ValueError, match="periodic"):
        freudenthal((3, 3), periodic=(True,))
    with pytest.raises(ValueError, match="n must be >= 1"):
        sample_torus(0)
    with pytest.raises(ValueError, match="0 < r < R"):
        sample_torus(10, R=1, r=2)
    with pytest.raises(ValueError, match="step"):
        hypersphere_freudenthal(step=-1.0)
    with pytest.raises(ValueError, match="π/step"):
        hypersphere_freudenthal(step=0.3)
    with pytest.raises(ValueError, match="duplicate"):
        convex_hull_surface(np.vstack([np.eye(3), np.eye(3)[:1], [[0, 0, 0]]]))
    with pytest.raises(ValueError, match="step"):
        cross_stars(lambda a: a, np.zeros((2, 2)), step=0.0)
    with pytest.raises(ValueError, match="interval"):
        sample_catenoid(10, v_range=(1, -1))


def test_hangs_are_refused_up_front():
    # freudenthal((2,) * 12) would build 12! = 479,001,600 simplices of 13 vertices
    with pytest.raises(ValueError, match=r"479,001,600 simplices"):
        freudenthal((2,) * 12)
    # 10^9 samples: refused with the size, before anything is drawn
    for call in (lambda: sample_torus(10**9), lambda: sample_sphere(10**9), lambda: sample_catenoid(10**9)):
        with pytest.raises(ValueError, match=r"1,000,000,000 points"):
            call()
    with pytest.raises(ValueError, match="this would build"):
        hypersphere_freudenthal(step=1e-300)
    with pytest.raises(ValueError, match="this would build"):
        torus_grid(10**6)


def test_raw_errors_become_clear_errors():
    from thesis_lib.meshes import orient_outward
    from thesis_lib.reconstruction import crust, extract_manifold

    x = np.eye(3)
    # out-of-range and negative indices were IndexError (or silently wrapped)
    with pytest.raises(ValueError, match="vertex index outside"):
        orient_outward(x, [[0, 1, 5]])
    with pytest.raises(ValueError, match="vertex index outside"):
        orient_outward(x, [[0, 1, -1]])
    with pytest.raises(ValueError, match="3 vertices per row"):
        orient_outward(x, [[0, 1]])
    with pytest.raises(ValueError, match="centre"):
        orient_outward(x, [[0, 1, 2]], centre=[0.0, 1.0])
    # coplanar points: QhullError before
    flat = np.column_stack([np.random.default_rng(0).random((20, 2)), np.zeros(20)])
    with pytest.raises(ValueError, match="hyperplane"):
        convex_hull_surface(flat)
    with pytest.raises(ValueError, match="lie in a plane"):
        crust(flat)
    with pytest.raises(ValueError, match=r"^points must lie in R\^3 \(an \(n, 3\) array\), got shape \(20, 2\)$"):
        crust(np.random.default_rng(0).random((20, 2)))
    with pytest.raises(ValueError, match="theta"):
        crust(np.random.default_rng(0).random((20, 3)), theta=2.0)
    with pytest.raises(ValueError, match="vertex index outside"):
        extract_manifold(np.random.default_rng(0).random((5, 3)), [[0, 1, 9]])


def test_plotting_bad_input():
    from thesis_lib.meshes import mesh_figure, render_mesh

    with pytest.raises(ValueError, match=r"^images must hold at least 1 entry, got 0$"):
        mesh_figure([])
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        render_mesh(np.zeros((4, 2)), np.array([[0, 1, 2]]))


# ------------------------------------------------------------------------- mesh files and pyvista
@pytest.mark.parametrize("suffix, exact", [(".vtk", True), (".vtp", True), (".ply", False), (".stl", False),
                                           (".obj", False)])
def test_mesh_files_round_trip(tmp_path, suffix, exact):
    from thesis_lib.curvature import mean_curvature
    from thesis_lib.meshes import read_mesh, write_mesh

    V, F = torus_grid(12)
    path = write_mesh(tmp_path / f"torus{suffix}", V, F)
    assert path.exists() and not list(tmp_path.glob(".torus-*"))  # no temporary file left behind
    V2, F2 = read_mesh(path)
    if exact:
        np.testing.assert_array_equal(V2, V)
        np.testing.assert_array_equal(F2, F)
    else:  # float32 formats; STL and OBJ may renumber the vertices: compare the faces' corners
        assert len(F2) == len(F)
        np.testing.assert_allclose(np.sort(V2[F2].reshape(len(F2), -1), axis=0),
                                   np.sort(V[F].reshape(len(F), -1), axis=0), rtol=1e-6, atol=1e-5)
    # what comes back is usable as is: the same mean curvature (up to the float32 rounding)
    h, h2 = mean_curvature(V, F), mean_curvature(V2, F2)
    np.testing.assert_allclose(np.sort(h2), np.sort(h), rtol=1e-4, atol=1e-4 * h.max())


def test_pyvista_round_trip_and_triangulation():
    pv = pytest.importorskip("pyvista")
    from thesis_lib.meshes import from_pyvista, to_pyvista

    V, F = torus_grid(8)
    mesh = to_pyvista(V, F)
    assert isinstance(mesh, pv.PolyData) and mesh.n_points == len(V) and mesh.n_cells == len(F)
    V2, F2 = from_pyvista(mesh)
    np.testing.assert_array_equal(V2, V)
    np.testing.assert_array_equal(F2, F)  # orientation (row order) kept
    # a user's mesh with quadrilaterals and a volume grid: triangulated / surface taken
    V3, F3 = from_pyvista(pv.Plane(i_resolution=3, j_resolution=2))
    assert F3.shape == (12, 3) and V3.shape == (12, 3)
    V4, F4 = from_pyvista(pv.Cube().triangulate().delaunay_3d())
    assert F4.shape[1] == 3 and len(F4) >= 12


def test_mesh_io_bad_input(tmp_path):
    from thesis_lib.meshes import from_pyvista, read_mesh, to_pyvista, write_mesh

    V, F = torus_grid(5)
    with pytest.raises(FileNotFoundError, match="no mesh file"):
        read_mesh(tmp_path / "missing.vtk")
    (tmp_path / "broken.vtk").write_text("not a mesh")
    with pytest.raises(ValueError):
        read_mesh(tmp_path / "broken.vtk")
    with pytest.raises(ValueError, match="suffix"):
        write_mesh(tmp_path / "torus", V, F)
    with pytest.raises(FileNotFoundError, match="no folder"):
        write_mesh(tmp_path / "nowhere" / "t.vtk", V, F)
    with pytest.raises(ValueError, match="R³"):
        to_pyvista(V[:, :2], F)
    with pytest.raises(ValueError, match="vertex index outside"):
        to_pyvista(V, F + len(V))
    with pytest.raises(TypeError, match="pyvista mesh"):
        from_pyvista((V, F))


@pytest.mark.parametrize("scale", [1e159, 2.0**500, 1e-159, 2.0**-500])
def test_orientation_is_the_same_at_any_magnitude(scale):
    """orient_outward's determinants overflowed (coordinates near 1e159: a RuntimeWarning and a sign
    read from inf/nan) or underflowed to 0 (tiny coordinates: no facet flipped); the orientation of
    a scaled surface must be that of the surface."""
    import warnings

    from thesis_lib.meshes import convex_hull_surface, orient_outward, sample_sphere

    for dim in (2, 3, 4):
        pts = sample_sphere(40, n_dims=dim, seed=dim)
        faces = convex_hull_surface(pts)
        shuffled = faces[:, ::-1].copy()  # every facet reversed: half of them need a flip
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            assert np.array_equal(orient_outward(pts * scale, shuffled), orient_outward(pts, shuffled))
            assert np.array_equal(convex_hull_surface(pts * scale), faces)

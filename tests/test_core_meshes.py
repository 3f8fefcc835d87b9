"""The compiled kernels of meshes, curvature and discrete Morse theory refuse what would read or write
outside their arrays (a ValueError, never a crash), and compute what their Python callers expect.

Modules: ``vertex_areas``, ``triangle_geometry``, ``pseudomanifold`` (§3.3), ``crust_trimming`` (§3.4),
``discrete_gradient`` (chapter 4).
"""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib._core import crust_trimming, discrete_gradient, pseudomanifold, triangle_geometry, vertex_areas
from thesis_lib.meshes import sample_sphere, torus_grid
from thesis_lib.reconstruction import crust
from thesis_lib.reconstruction.crust import crust_candidates
from thesis_lib.reconstruction.crust_trimming import _ridge_structure

I64 = np.int64


def tri_arrays(m: int):
    return (np.zeros((3, m)), np.zeros((3, m)), np.zeros(m), np.zeros((3, 3, m)),
            np.zeros((m, 3), dtype=I64), np.zeros((m, 3), dtype=I64))


# --- vertex areas and triangle corner data (§3.3.2) ---------------------------------------------

def test_triangle_areas_values():
    s = np.array([[0, 1, 2]], dtype=I64)
    dot = np.array([[0.0], [1.0], [1.0]])  # right angle at corner 0 of the triangle (0,0), (1,0), (0,1)
    sq = np.array([[2.0], [1.0], [1.0]])
    out = vertex_areas.triangle_areas(s, dot, sq, np.array([1.0]), 4, False)
    assert out.tolist() == [0.25, 0.125, 0.125, 0.0]


@pytest.mark.parametrize("bad", ["shape", "negative", "large", "dot", "twice"])
def test_triangle_areas_refuses(bad):
    s = np.array([[0, 1, 2]], dtype=I64)
    dot, sq, tw = np.ones((3, 1)), np.ones((3, 1)), np.ones(1)
    if bad == "shape":
        s = np.array([[0, 1]], dtype=I64)
    elif bad == "negative":
        s = np.array([[0, -1, 2]], dtype=I64)
    elif bad == "large":
        s = np.array([[0, 1, 3]], dtype=I64)
    elif bad == "dot":
        dot = np.ones((3, 2))
    else:
        tw = np.ones(2)
    with pytest.raises(ValueError):
        vertex_areas.triangle_areas(s, dot, sq, tw, 3, True)


def test_triangle_kernel_values():
    v = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    arrays = tri_arrays(1)
    checks = triangle_geometry.triangle_kernel(v, np.array([[0, 1, 2]], dtype=I64), triangle_geometry.Corners(*arrays),
                                                1e-10)
    dot, sq, twice, pts, lo, hi = arrays
    assert checks == (-1, -1, 0, 2.0)
    assert dot[:, 0].tolist() == [0.0, 1.0, 1.0] and sq[:, 0].tolist() == [2.0, 1.0, 1.0] and twice[0] == 1.0
    assert lo.tolist() == [[1, 0, 0]] and hi.tolist() == [[2, 2, 1]]
    assert pts[:, :, 0].tolist() == v.tolist()
    # repeated vertex and degenerate triangle are reported, not refused
    arrays = tri_arrays(2)
    checks = triangle_geometry.triangle_kernel(v, np.array([[0, 1, 2], [0, 0, 1]], dtype=I64),
                                                triangle_geometry.Corners(*arrays), 1e-10)
    assert checks[:3] == (1, 1, 1)


@pytest.mark.parametrize("bad", ["v", "s", "index", "negative", "out"])
def test_triangle_kernel_refuses(bad):
    v = np.zeros((3, 3))
    s = np.array([[0, 1, 2]], dtype=I64)
    arrays = list(tri_arrays(1))
    if bad == "v":
        v = np.zeros((3, 2))
    elif bad == "s":
        s = np.array([[0, 1, 2, 0]], dtype=I64)
    elif bad == "index":
        s = np.array([[0, 1, 3]], dtype=I64)
    elif bad == "negative":
        s = np.array([[0, -3, 1]], dtype=I64)
    else:
        arrays[3] = np.zeros((3, 3, 2))
    with pytest.raises(ValueError):
        triangle_geometry.triangle_kernel(v, s, triangle_geometry.Corners(*arrays), 1e-10)


# --- pseudo-manifolds (§3.3) ----------------------------------------------------------------------

def ridge_codes(s: np.ndarray):
    pairs = [s[:, [1, 2]], s[:, [0, 2]], s[:, [0, 1]]]
    return (np.stack([p.min(axis=1) for p in pairs], axis=1).ravel(),
            np.stack([p.max(axis=1) for p in pairs], axis=1).ravel())


def run_pm(s, nv):
    s = np.asarray(s, dtype=I64)
    lo, key = ridge_codes(s)
    return pseudomanifold.pseudomanifold_kernel(s, lo, key, nv, True)


def test_pseudomanifold_codes():
    _, f = torus_grid(6)
    code, *_, pinched, boundary = run_pm(f, int(f.max()) + 1)
    assert code == 0 and not pinched.any() and not boundary.any()
    assert run_pm([[0, 1, 2], [2, 1, 0]], 3)[:3] == (1, 0, 1)
    assert run_pm([[0, 1, 2], [0, 1, 3], [1, 0, 4]], 5)[:3] == (2, 0, 2)
    cones = [[0, 1, 2], [0, 2, 3], [0, 3, 1], [0, 4, 5], [0, 5, 6], [0, 6, 4]]
    code, a, b, c, pinched, boundary = run_pm(cones, 7)
    assert (code, a, b, c) == (3, 0, 0, 3) and pinched.tolist() == [True] + [False] * 6
    assert boundary.tolist() == [False] + [True] * 6


def test_pseudomanifold_large_bucket():
    """A fan of 40 triangles about vertex 0 (a bucket sorted by the stable sort, not insertion)."""
    k = 40
    fan = [[0, 1 + i, 1 + (i + 1) % k] for i in range(k)]
    code, _, _, _, pinched, boundary = run_pm(fan, k + 1)
    assert code == 0 and not pinched.any()
    assert boundary.tolist() == [False] + [True] * k
    assert run_pm(fan + [[0, 7, 6]], k + 1)[:3] == (2, 4, 1)  # the ridge (0, 6) in three triangles


@pytest.mark.parametrize("bad", ["length", "index", "lo", "nv"])
def test_pseudomanifold_refuses(bad):
    s = np.array([[0, 1, 2]], dtype=I64)
    lo, key = ridge_codes(s)
    nv = 3
    if bad == "length":
        lo = lo[:2]
    elif bad == "index":
        s = np.array([[0, 1, 5]], dtype=I64)
    elif bad == "lo":
        lo = np.array([0, 0, 7], dtype=I64)
    else:
        nv = -1
    with pytest.raises(ValueError):
        pseudomanifold.pseudomanifold_kernel(s, lo, key, nv, True)


# --- crust trimming (§3.4) --------------------------------------------------------------------------

@pytest.fixture(scope="module")
def candidates():
    pts = sample_sphere(120, seed=3)
    cand = crust_candidates(pts).astype(I64)
    return pts, cand, _ridge_structure(cand, len(pts))


def test_walk_and_greedy_manifold(candidates):
    pts, cand, structure = candidates
    alive = np.ones(len(cand), dtype=bool)
    orient, order, conflicts = crust_trimming.walk(pts, cand, alive, crust_trimming.Ridges(*structure), 0, False, False,
                                                   np.pi)
    assert orient.shape == cand.shape and len(np.unique(order)) == len(order) and order[0] == 0
    assert (np.sort(orient[order], axis=1) == np.sort(cand[order], axis=1)).all()
    keep = crust_trimming.greedy_manifold(structure[1], order, len(structure[0]))
    assert keep.dtype == bool and keep.shape == order.shape and keep[0]
    used = np.bincount(structure[1][order[keep]].ravel(), minlength=len(structure[0]))
    assert used.max() <= 2
    assert isinstance(conflicts, int)


def test_crust_of_sphere_is_closed():
    tris = crust(sample_sphere(200, seed=1))
    edges = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert (counts == 2).all()
    v = len(np.unique(tris))
    assert v - len(counts) + len(tris) == 2  # Euler characteristic of the sphere


def test_sharp_ridges_and_openness(candidates):
    pts, cand, structure = candidates
    ridges, ridge_of, start, tri_of, opp = structure
    alive = np.ones(len(cand), dtype=bool)
    sharp = np.zeros(len(ridges), dtype=bool)
    crust_trimming.sharp_ridges(pts, ridges, alive, start, tri_of, opp, np.arange(len(ridges), dtype=I64), sharp)
    single = np.diff(start) == 1
    assert sharp[single].all()
    ts = np.array([0, 0, 1], dtype=I64)
    worst = crust_trimming.openness(pts, cand, alive, crust_trimming.Ridges(*structure), ts,
                                    np.array([False, True, False]))
    assert worst.shape == (3,) and ((worst >= 0) & (worst <= 2 * np.pi)).all()


@pytest.mark.parametrize("bad", ["seed", "ridge_of", "pts", "start", "tri_of", "alive", "opp"])
def test_walk_refuses(candidates, bad):
    pts, cand, structure = candidates
    ridges, ridge_of, start, tri_of, opp = (a.copy() for a in structure)
    alive = np.ones(len(cand), dtype=bool)
    seed = 0
    if bad == "seed":
        seed = len(cand)
    elif bad == "ridge_of":
        ridge_of[3, 1] = len(ridges)
    elif bad == "pts":
        pts = np.c_[pts, pts[:, :1]]
    elif bad == "start":
        start[-1] = len(tri_of) + 1
    elif bad == "tri_of":
        tri_of[0] = -1
    elif bad == "alive":
        alive = alive[:-1]
    else:
        opp[4] = len(pts)
    with pytest.raises(ValueError):
        crust_trimming.walk(pts, cand, alive, crust_trimming.Ridges(ridges, ridge_of, start, tri_of, opp), seed,
                            False, False, np.pi)


def test_trimming_kernels_refuse(candidates):
    pts, cand, structure = candidates
    ridges, ridge_of, start, tri_of, opp = structure
    ridge_arrays = crust_trimming.Ridges(*structure)
    alive = np.ones(len(cand), dtype=bool)
    sharp = np.zeros(len(ridges), dtype=bool)
    with pytest.raises(ValueError):
        crust_trimming.sharp_ridges(pts, ridges, alive, start, tri_of, opp, np.array([len(ridges)], dtype=I64), sharp)
    with pytest.raises(ValueError):
        crust_trimming.sharp_ridges(pts, ridges, alive, start, tri_of, opp, np.array([0], dtype=I64), sharp[:-1])
    with pytest.raises(ValueError):
        crust_trimming.greedy_manifold(ridge_of, np.array([len(cand)], dtype=I64), len(ridges))
    with pytest.raises(ValueError):
        crust_trimming.greedy_manifold(ridge_of, np.array([0], dtype=I64), 1)
    with pytest.raises(ValueError):
        crust_trimming.openness(pts, cand, alive, ridge_arrays, np.array([-1], dtype=I64), np.array([False]))
    with pytest.raises(ValueError):
        crust_trimming.openness(pts, cand, alive, ridge_arrays, np.array([0], dtype=I64), np.array([False, True]))
    bad = pts.copy()
    bad[cand[0, 0]] = np.nan  # numba's det refused non-finite matrices: so does the port
    with pytest.raises(ValueError, match="infs or NaNs"):
        crust_trimming.walk(bad, cand, alive, ridge_arrays, 0, False, False, np.pi)


# --- discrete gradients (chapter 4) -----------------------------------------------------------------

def csr(n, edges):
    src = np.array([e[0] for e in edges], dtype=I64)
    dst = np.array([e[1] for e in edges], dtype=I64)
    order = np.argsort(src, kind="stable")
    ptr = np.concatenate([[0], np.cumsum(np.bincount(src, minlength=n))]).astype(I64)
    return ptr, dst[order]


def test_topological_rank():
    ptr, idx = csr(4, [(0, 1), (1, 2), (0, 2)])
    assert discrete_gradient.topological_rank(4, ptr, idx).tolist() == [0, 2, 3, 1]
    ptr, idx = csr(3, [(0, 1), (1, 0), (1, 2)])  # a cycle: nothing on or after it is ranked
    assert discrete_gradient.topological_rank(3, ptr, idx).tolist() == [-1, -1, -1]


@pytest.mark.parametrize("bad", ["ptr-length", "ptr-order", "idx", "ptr-end"])
def test_topological_rank_refuses(bad):
    ptr, idx = csr(3, [(0, 1), (1, 2)])
    if bad == "ptr-length":
        ptr = ptr[:-1]
    elif bad == "ptr-order":
        ptr = np.array([0, 2, 1, 2], dtype=I64)
    elif bad == "idx":
        idx = np.array([1, 3], dtype=I64)
    else:
        ptr = np.array([0, 1, 2, 5], dtype=I64)
    with pytest.raises(ValueError):
        discrete_gradient.topological_rank(3, ptr, idx)


def edge_complex():
    """The edge [0, 1] as cells 0, 1 (vertices) and 2 (the edge): faces and cofaces in CSR."""
    fptr, fidx = np.array([0, 0, 0, 2], dtype=I64), np.array([0, 1], dtype=I64)
    cptr, cidx = np.array([0, 1, 2, 2], dtype=I64), np.array([2, 2], dtype=I64)
    return fptr, fidx, cptr, cidx


def test_greedy_matching():
    fptr, fidx, cptr, cidx = edge_complex()
    vals, order = np.zeros(3), np.array([0, 1, 2], dtype=I64)
    partner = discrete_gradient.greedy_matching(3, fptr, fidx, cptr, cidx, vals, order)  # coreduction
    assert partner.tolist() == [-1, 2, 1]
    empty = np.zeros(4, dtype=I64), np.zeros(0, dtype=I64)  # three isolated cells: order used thrice
    assert discrete_gradient.greedy_matching(3, *empty, *empty, vals, order).tolist() == [-1, -1, -1]
    with pytest.raises(ValueError, match="permutation"):
        discrete_gradient.greedy_matching(3, *empty, *empty, vals, np.array([0, 0, 0], dtype=I64))
    with pytest.raises(ValueError):
        discrete_gradient.greedy_matching(3, fptr, fidx, cptr, cidx, vals, np.array([0, 1, 3], dtype=I64))
    with pytest.raises(ValueError):
        discrete_gradient.greedy_matching(3, fptr, fidx, cptr, cidx, vals[:2], order)


def test_morse_columns():
    # the edge [0, 1] with vertex 1 paired to it: ∂[0, 1] = -[0] + [1] flows to 0 (the pair cancels)
    fptr, fidx, _, _ = edge_complex()
    data = np.array([-1, 1], dtype=I64)
    partner = np.array([-1, 2, 1], dtype=I64)
    rank = np.array([0, 1, 2], dtype=I64)
    crit = np.array([True, False, False])
    rows, cols, vals, overflow = discrete_gradient.morse_columns(3, fptr, fidx, data,
                                                                 discrete_gradient.Gradient(partner, rank, crit),
                                                                 np.array([2], dtype=I64), 0)
    assert rows.tolist() == [] and not overflow
    partner = np.array([-1, -1, -1], dtype=I64)
    every = discrete_gradient.Gradient(partner, rank, np.ones(3, dtype=bool))
    rows, cols, vals, _ = discrete_gradient.morse_columns(3, fptr, fidx, data, every, np.array([2], dtype=I64), 3)
    assert rows.tolist() == [0, 1] and cols.tolist() == [2, 2] and vals.tolist() == [2, 1]  # -1 mod 3 = 2
    with pytest.raises(ValueError):
        discrete_gradient.morse_columns(3, fptr, fidx, data,
                                        discrete_gradient.Gradient(np.array([-1, 3, 1], dtype=I64), rank, crit),
                                        np.array([2], dtype=I64), 0)
    with pytest.raises(ValueError):
        discrete_gradient.morse_columns(3, fptr, fidx, data, discrete_gradient.Gradient(partner, rank, crit),
                                        np.array([3], dtype=I64), 0)
    with pytest.raises(ValueError):
        discrete_gradient.morse_columns(3, fptr, fidx, data[:1], discrete_gradient.Gradient(partner, rank, crit),
                                        np.array([2], dtype=I64), 0)

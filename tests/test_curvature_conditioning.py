"""Curvature on ill-conditioned simplices (needles, spikes, slivers) against 60-digit references.

The float formulas of :mod:`thesis_lib.curvature` lose up to 2·log10(aspect) digits on a simplex of
large aspect (the law of cosines at a needle's base, the gradient at a needle's tip as minus the sum
of two long ones); above ``ASPECT_BOUND`` the library recomputes such simplices exactly.  Here every
estimate is compared with a reference evaluated at 60 significant digits (mpmath) from the same
floats, on random closed meshes with one family of bad simplices each, in R³ and in R⁴; and on
well-conditioned meshes the values are compared bit for bit with the library as it was before the
exact path (its sources taken from git), so that stored results elsewhere do not move.

Tolerances: each per-simplex quantity on the exact path is correct to a few ulps, but the simplices
of aspect up to ASPECT_BOUND keep the float formulas (error up to about 10⁻¹⁶ · aspect², i.e. 10⁻¹⁰
relative at the bound, more in the cotangent form whose terms cot·edge cancel), and the sums over a
vertex's star round.  So a vertex value is held to TOL times the *condition scale* of its sum (the
sum of the absolute values of its terms, from the reference), not to its own size.
"""

from __future__ import annotations

import io
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

import mpmath
import numpy as np
import pytest

from thesis_lib.curvature import (
    angle_defects,
    circumcentric_fractions,
    gaussian_curvature,
    mean_curvature,
    mean_curvature_vector,
    validate_mesh,
    vertex_areas,
)
from thesis_lib.curvature.geometry import simplex_aspects
from thesis_lib.curvature.validate import ASPECT_BOUND

DPS = 60
TOL = 1e-9  # relative to the condition scale (module docstring)
TOL_COT = 1e-8  # the cotangent form below ASPECT_BOUND: its terms cot·edge are up to aspect times larger
#: the library before the exact path (thesis_lib/curvature as of this commit), for the bit-identity test
OLD_COMMIT = "509d13b1c08fe3eb967c5d6e07c53ccfa98f761d"
ROOT = Path(__file__).resolve().parents[1]


# ----------------------------------------------------------------------------- mesh families
def bipyramid(rng: np.random.Generator, family: str) -> tuple[np.ndarray, np.ndarray]:
    """A closed triangle mesh in R³ (a ring of k vertices, two apices) with one family of bad triangles.

    ``needle``: ring vertex 1 within ε = 10^-U(3, 8.5) of ring vertex 0 (needles of aspect ~1/ε with
    their tips at the apices); ``spike``: the top apex at height 10^U(3, 9.4) (needles of aspect up
    to 5·10⁹ meeting at a spike vertex); ``sliver``: the top apex 10^-U(3, 9) above the midpoint of
    ring edge (0, 1) (a cap, its angle near π); ``plain``: none.  Rows are rotated at random so that
    the bad corner is any of the three.
    """
    k = int(rng.integers(4, 9))
    ang = np.linspace(0, 2 * np.pi, k, endpoint=False) + rng.uniform(-0.3, 0.3, k) * (2 * np.pi / k)
    rad = rng.uniform(0.7, 1.3, k)
    ring = np.stack([rad * np.cos(ang), rad * np.sin(ang), rng.uniform(-0.1, 0.1, k)], axis=1)
    top = np.array([*rng.uniform(-0.2, 0.2, 2), rng.uniform(0.5, 2.0)])
    bot = np.array([*rng.uniform(-0.2, 0.2, 2), -rng.uniform(0.5, 2.0)])
    if family == "needle":
        eps = 10.0 ** -rng.uniform(3, 8.5)
        d = rng.normal(size=3)
        ring[1] = ring[0] + eps * d / np.linalg.norm(d)
    elif family == "spike":
        top = np.array([*rng.uniform(-1, 1, 2), 10.0 ** rng.uniform(3, 9.4)])
    elif family == "sliver":
        delta = 10.0 ** -rng.uniform(3, 9)
        mid = 0.5 * (ring[0] + ring[1])
        top = mid * (1 - 1e-3) + np.array([0, 0, delta * np.linalg.norm(ring[1] - ring[0])])
    v = np.concatenate([ring, [top, bot]])
    f = np.array([[i, (i + 1) % k, k] for i in range(k)] + [[(i + 1) % k, i, k + 1] for i in range(k)])
    f = np.array([np.roll(r, t) for r, t in zip(f, rng.integers(0, 3, len(f)))])
    return v + rng.uniform(-1, 1, 3), f


def suspension(rng: np.random.Generator, family: str) -> tuple[np.ndarray, np.ndarray]:
    """A closed 3-manifold in R⁴: the suspension of a perturbed octahedron over two apices (16 tetrahedra).

    ``needle``: two octahedron vertices 10^-U(2, 5) apart; ``spike``: the top apex at height
    10^U(2, 4.5); ``sliver``: the top apex 10^-U(3, 8) off the hyperplane of a face; ``plain``: none.
    """
    base = np.concatenate([np.eye(3), -np.eye(3)]) * rng.uniform(0.7, 1.3, (6, 1))
    base = np.concatenate([base + rng.uniform(-0.1, 0.1, base.shape), rng.uniform(-0.05, 0.05, (6, 1))], axis=1)
    faces = [(a, b, c) for a in (0, 3) for b in (1, 4) for c in (2, 5)]
    top = np.array([*rng.uniform(-0.1, 0.1, 3), rng.uniform(0.5, 2)])
    bot = np.array([*rng.uniform(-0.1, 0.1, 3), -rng.uniform(0.5, 2)])
    if family == "needle":
        d = rng.normal(size=4)
        base[0] = base[1] + 10.0 ** -rng.uniform(2, 5) * d / np.linalg.norm(d)
    elif family == "spike":
        top = np.array([*rng.uniform(-0.5, 0.5, 3), 10.0 ** rng.uniform(2, 4.5)])
    elif family == "sliver":
        c = base[list(faces[0])].mean(axis=0)
        top = c * (1 - 1e-3) + np.array([0, 0, 0, 10.0 ** -rng.uniform(3, 8)])
    v = np.concatenate([base, [top, bot]])
    s = np.array([[*fc, 6] for fc in faces] + [[*fc, 7] for fc in faces])
    s = np.array([np.roll(r, t) for r, t in zip(s, rng.integers(0, 4, len(s)))])
    return v + rng.uniform(-1, 1, 4), s


# ----------------------------------------------------------------------------- 60-digit reference
def _adjugate_column(g: list[list], j: int) -> list:
    """Column j of the adjugate of a symmetric 2×2 or 3×3 matrix g (cofactors)."""
    n = len(g)
    if n == 2:
        return [g[1][1], -g[1][0]] if j == 0 else [-g[0][1], g[0][0]]
    col = []
    for i in range(3):  # adj[i][j] = (-1)^(i+j) minor(j, i)
        r = [a for a in range(3) if a != j]
        c = [b for b in range(3) if b != i]
        minor = g[r[0]][c[0]] * g[r[1]][c[1]] - g[r[0]][c[1]] * g[r[1]][c[0]]
        col.append(minor if (i + j) % 2 == 0 else -minor)
    return col


def reference(v: np.ndarray, s: np.ndarray) -> dict[str, np.ndarray]:
    """The estimates at 60 digits from the exact values of the floats ``v``.

    The gradient of each simplex's hyperarea at its vertex i is the Gram formula (Theorem 3.18)
    based at the *next* vertex of the row (not at row[0], as the library does), with the adjugate by
    cofactors; ``size`` is Σ_T |∇_p A_T| at each vertex (the condition scale of the vertex sum),
    ``voronoi_size`` Σ_T of the absolute Voronoi terms.
    """
    with mpmath.workdps(DPS):
        nv, d = v.shape
        n = s.shape[1] - 1
        V = [[mpmath.mpf(float(x)) for x in p] for p in v]
        zero = mpmath.mpf(0)
        vec = [[zero] * d for _ in range(nv)]
        size, bary, mixed, vor, vsize, angle = ([zero] * nv for _ in range(6))
        fact = mpmath.factorial(n)
        hyper = []
        for row in s:
            row = [int(x) for x in row]
            area = None
            for c, i in enumerate(row):
                q = row[(c + 1) % (n + 1)]
                others = [row[(c + 1 + t) % (n + 1)] for t in range(1, n + 1)]  # others[-1] == i
                x = [[V[o][a] - V[q][a] for a in range(d)] for o in others]
                g = [[sum(x[a][t] * x[b][t] for t in range(d)) for b in range(n)] for a in range(n)]
                adj = _adjugate_column(g, n - 1)
                det = sum(g[n - 1][t] * adj[t] for t in range(n))
                root = mpmath.sqrt(det)
                area = root / fact
                grad = [sum(x[t][a] * adj[t] for t in range(n)) / (fact * root) for a in range(d)]
                for a in range(d):
                    vec[i][a] += grad[a]
                size[i] += mpmath.sqrt(sum(t * t for t in grad))
            hyper.append(area)
            for i in row:
                bary[i] += area / (n + 1)
            if n == 2:
                dots, sq = [], []
                for c in range(3):
                    p, a, b = V[row[c]], V[row[(c + 1) % 3]], V[row[(c + 2) % 3]]
                    dots.append(sum((a[t] - p[t]) * (b[t] - p[t]) for t in range(3)))
                    sq.append(sum((b[t] - a[t]) ** 2 for t in range(3)))
                tw = 2 * area
                w = [dots[c] / tw * sq[c] for c in range(3)]
                for c in range(3):
                    angle[row[c]] += mpmath.atan2(tw, dots[c])
                    share = (w[(c + 1) % 3] + w[(c + 2) % 3]) / 8
                    vor[row[c]] += share
                    vsize[row[c]] += (abs(w[(c + 1) % 3]) + abs(w[(c + 2) % 3])) / 8
                    if min(dots) < 0:
                        mixed[row[c]] += tw / 4 if dots[c] < 0 else tw / 8
                    else:
                        mixed[row[c]] += share
        norm = [mpmath.sqrt(sum(t * t for t in r)) for r in vec]
        f = lambda xs: np.array([float(t) for t in xs])  # noqa: E731
        out = {"vector": np.array([[float(t) for t in r] for r in vec]), "size": f(size), "norm": f(norm),
               "areas": f(hyper),
               "barycentric": f(bary), "H_barycentric": f(norm[i] / (n * bary[i]) for i in range(nv))}
        if n == 2:
            out.update(mixed=f(mixed), voronoi=f(vor), voronoi_size=f(vsize),
                       defect=f(2 * mpmath.pi - a for a in angle),
                       H_mixed=f(norm[i] / (n * mixed[i]) for i in range(nv)),
                       K_mixed=f((2 * mpmath.pi - angle[i]) / mixed[i] for i in range(nv)))
        return out


def check_mesh(v: np.ndarray, s: np.ndarray) -> dict[str, float]:
    """Every estimate on one closed mesh against the reference: the worst ratio error / allowed."""
    r = reference(v, s)
    n = s.shape[1] - 1
    worst = {}

    def ratio(name, err, allowed):
        worst[name] = float(np.max(err / allowed))

    for method, tol in (("gram", TOL), ("cot", TOL_COT)):
        vec = mean_curvature_vector(v, s, method=method)
        ratio(f"vector-{method}", np.abs(vec - r["vector"]).max(axis=1), tol * r["size"])
    a = vertex_areas(v, s, area="barycentric")
    ratio("barycentric", np.abs(a - r["barycentric"]), 1e-12 * r["barycentric"])
    h = mean_curvature(v, s, area="barycentric")
    ratio("H-barycentric", np.abs(h - r["H_barycentric"]),
          TOL * r["size"] / (n * r["barycentric"]) + 1e-12 * r["H_barycentric"])
    if n == 2:
        for kind in ("mixed", "voronoi"):
            a = vertex_areas(v, s, area=kind)
            scale = r["barycentric"] if kind == "mixed" else r["voronoi_size"]
            ratio(kind, np.abs(a - r[kind]), (1e-13 if kind == "mixed" else TOL) * scale)
        h = mean_curvature(v, s, area="mixed")
        ratio("H-mixed", np.abs(h - r["H_mixed"]), TOL * r["size"] / (n * r["mixed"]) + 1e-12 * r["H_mixed"])
        ratio("defect", np.abs(angle_defects(v, s) - r["defect"]), np.full(len(v), TOL))
        k = gaussian_curvature(v, s, area="mixed")
        ratio("K-mixed", np.abs(k - r["K_mixed"]), TOL / r["mixed"] + 1e-12 * np.abs(r["K_mixed"]))
    return worst


CASES = {("R3", "needle"): 200, ("R3", "spike"): 200, ("R3", "sliver"): 200,
         ("R4", "needle"): 80, ("R4", "spike"): 80, ("R4", "sliver"): 80}


@pytest.mark.parametrize("space,family", list(CASES))
def test_bad_simplices_against_60_digit_reference(space, family):
    gen = bipyramid if space == "R3" else suspension
    worst: dict[str, float] = {}
    ill_meshes = 0
    for seed in range(CASES[space, family]):
        rng = np.random.default_rng([21, seed, list(CASES).index((space, family))])
        v, s = gen(rng, family)
        ill_meshes += bool(validate_mesh(v, s).ill_conditioned.size)
        for name, x in check_mesh(v, s).items():
            worst[name] = max(worst.get(name, 0.0), x)
    print(f"{space} {family}: {CASES[space, family]} meshes, {ill_meshes} with a simplex of aspect > "
          f"{ASPECT_BOUND:g}; worst error / allowed: " + ", ".join(f"{k} {x:.2g}" for k, x in worst.items()))
    assert ill_meshes >= CASES[space, family] // 2  # the family does exercise the exact path
    assert all(x <= 1.0 for x in worst.values()), worst


def test_spike_vertex_of_aspect_5e9():
    """A spike: |H| at the apex of needles of aspect 5·10⁹ against the 60-digit value."""
    ring = np.array([[1.2, 0.1, 0.0], [-0.1, 1.1, 0.05], [-1.3, 0.0, -0.02], [0.05, -1.2, 0.0]])
    v = np.concatenate([ring, [[0.1, -0.2, 5e9], [0.0, 0.1, -1.0]]])  # the spike's apex at height 5·10⁹
    s = np.array([[i, (i + 1) % 4, 4] for i in range(4)] + [[(i + 1) % 4, i, 5] for i in range(4)])
    assert simplex_aspects(v, s).max() > 1e9
    r = reference(v, s)
    h = mean_curvature(v, s, area="mixed")
    apex = len(v) - 2
    assert h[apex] == pytest.approx(r["H_mixed"][apex], rel=1e-9)


def test_exact_path_only_above_the_bound():
    """A needle just above ASPECT_BOUND is recomputed, a triangle just below it is not."""
    for aspect, expect in ((2.0 * ASPECT_BOUND, True), (0.5 * ASPECT_BOUND, False)):
        h = 1.0 / aspect  # the triangle (0,0,0), (1,0,0), (1/2, h, 0) has aspect 1 / h
        v = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, h, 0.0], [0.4, 0.3, 1.0]])
        s = np.array([[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]])
        mesh = validate_mesh(v, s)
        assert (0 in mesh.ill_conditioned.tolist()) is expect
        assert simplex_aspects(v, s)[0] == pytest.approx(aspect, rel=1e-6)


# ----------------------------------------------------------------------------- bit identity
#: the old commit's thesis_lib.jit replaced by the identity: its kernels run as plain Python and numpy
_PLAIN_JIT = """
def njit(fn=None, **options):
    return (lambda f: f) if fn is None else fn


prange = range
"""

#: the old formulas, and the new ones in R^{n+1} for n >= 3 (Gram determinants and adjugates), are
#: numpy code whose BLAS and SIMD kernels are chosen for the CPU: an AVX-512 kernel can round a last
#: bit that the AVX2 one does not.  Old and new therefore run in two processes with the same kernels
#: fixed (OpenBLAS's Haswell ones, numpy's SIMD dispatch at AVX2, one thread).
FIXED_KERNELS = {"OPENBLAS_CORETYPE": "Haswell", "OPENBLAS_NUM_THREADS": "1",
                 "NPY_DISABLE_CPU_FEATURES": "AVX512F AVX512CD AVX512_SKX AVX512_CLX AVX512_CNL AVX512_ICL AVX512_SPR"}

#: run first by the old sources: an editable install's import hook would hand out the checkout's
#: thesis_lib whatever PYTHONPATH says
_OLD_PRELUDE = r"""
import os, sys
sys.meta_path[:] = [f for f in sys.meta_path if not type(f).__module__.startswith("_editable")]
import thesis_lib
assert thesis_lib.__file__.startswith(os.environ["PYTHONPATH"]), thesis_lib.__file__
"""

#: the formulas of one library on the meshes of argv[1], written to argv[2]
_FORMULAS = r"""
import sys
import numpy as np
from thesis_lib import curvature as c
data = np.load(sys.argv[1], allow_pickle=False)
out = {}
for key in sorted({k.split(':')[0] for k in data.files}):
    v, s = data[key + ':v'], data[key + ':s']
    n = s.shape[1] - 1
    out[key + ':gram'] = c.mean_curvature_vector(v, s, method='gram')
    out[key + ':cot'] = c.mean_curvature_vector(v, s, method='cot')
    out[key + ':bary'] = c.vertex_areas(v, s, area='barycentric')
    out[key + ':vor'] = c.vertex_areas(v, s, area='voronoi')
    out[key + ':Hb'] = c.mean_curvature(v, s, area='barycentric')
    if n == 2:
        out[key + ':mixed'] = c.vertex_areas(v, s, area='mixed')
        out[key + ':Hm'] = c.mean_curvature(v, s, area='mixed')
        out[key + ':K'] = c.gaussian_curvature(v, s, area='mixed')
        out[key + ':defect'] = c.angle_defects(v, s)
        out[key + ':hyper'] = c.simplex_hyperareas(v, s)
np.savez(sys.argv[2], **out)
"""


def _well_conditioned_meshes() -> dict[str, np.ndarray]:
    from scipy.spatial import ConvexHull

    meshes = {}
    for seed in range(6):
        rng = np.random.default_rng([21, 2, seed])
        for dim in (3, 4):
            p = rng.normal(size=(40 + 10 * seed, dim)) * rng.uniform(0.5, 2.0, dim) + rng.uniform(-3, 3, dim)
            meshes[f"hull{dim}-{seed}"] = (p, ConvexHull(p).simplices)
        meshes[f"bipyramid-{seed}"] = bipyramid(rng, "plain")
        meshes[f"suspension-{seed}"] = suspension(rng, "plain")
    return {f"{k}:{x}": a for k, (v, s) in meshes.items() for x, a in (("v", v), ("s", s))}


def test_well_conditioned_meshes_bit_identical_to_the_float_formulas(tmp_path):
    """On meshes with every simplex of aspect at most ASPECT_BOUND nothing changes by a single bit:
    the library's sources before the exact path (git) run in a subprocess on the same meshes."""
    old_src = Path(tempfile.gettempdir()) / f"thesis-lab-curvature-{OLD_COMMIT[:12]}-python"
    if not (old_src / "thesis_lib" / "curvature" / "validate.py").exists():
        try:
            blob = subprocess.run(["git", "-C", str(ROOT), "archive", OLD_COMMIT, "thesis_lib"],
                                  capture_output=True, check=True).stdout
        except (OSError, subprocess.CalledProcessError):
            pytest.skip(f"git history with commit {OLD_COMMIT[:10]} not available (shallow clone?)")
        with tarfile.open(fileobj=io.BytesIO(blob)) as tar:
            tar.extractall(tmp_path / "extract", filter="data")
        old_src.mkdir(parents=True, exist_ok=True)
        if not (old_src / "thesis_lib").exists():
            # numba is not installed: that commit's kernels run as the plain Python they are written in
            (tmp_path / "extract" / "thesis_lib" / "jit.py").write_text(_PLAIN_JIT, encoding="utf-8")
            (tmp_path / "extract" / "thesis_lib").rename(old_src / "thesis_lib")
    data = _well_conditioned_meshes()
    np.savez(tmp_path / "meshes.npz", **data)
    meshes = str(tmp_path / "meshes.npz")
    subprocess.run([sys.executable, "-c", _OLD_PRELUDE + _FORMULAS, meshes, str(tmp_path / "old.npz")],
                   check=True, cwd=tmp_path, env={"PYTHONPATH": str(old_src), "PATH": "/usr/bin:/bin", **FIXED_KERNELS})
    # the checkout's library, as installed (its compiled core is not in the source tree)
    subprocess.run([sys.executable, "-c", _FORMULAS, meshes, str(tmp_path / "new.npz")],
                   check=True, cwd=tmp_path, env={"PATH": "/usr/bin:/bin", **FIXED_KERNELS})
    old, computed = np.load(tmp_path / "old.npz"), np.load(tmp_path / "new.npz")
    assert sorted(computed.files) == sorted(old.files)
    keys = sorted({k.split(":")[0] for k in data})
    compared = 0
    for key in keys:
        v, s = data[key + ":v"], data[key + ":s"]
        assert simplex_aspects(v, s).max() <= ASPECT_BOUND
        assert validate_mesh(v, s).ill_conditioned.size == 0
        for name in (f for f in old.files if f.startswith(key + ":")):
            value, ref = computed[name], old[name]
            assert value.shape == ref.shape and value.tobytes() == ref.tobytes(), name
            compared += 1
    assert compared == len(old.files)


def circumcentric_reference(p: np.ndarray) -> np.ndarray:
    """The circumcentric fractions of one simplex ``p`` (n + 1, d) at 60 digits (the recursion of
    :func:`thesis_lib.curvature.circumcentric_fractions`, each face's circumcentre by mpmath's solve)."""
    with mpmath.workdps(DPS):
        w = len(p)
        P = [[mpmath.mpf(float(x)) for x in row] for row in p]
        frac = {1 << i: [mpmath.mpf(1)] * w for i in range(w)}
        for mask in sorted(range(1, 1 << w), key=lambda m: bin(m).count("1")):
            members = [i for i in range(w) if mask >> i & 1]
            if len(members) < 2:
                continue
            x = [[a - b for a, b in zip(P[i], P[members[0]])] for i in members[1:]]
            g = mpmath.matrix([[sum(a * b for a, b in zip(u, z)) for z in x] for u in x])
            a = mpmath.lu_solve(g, mpmath.matrix([g[i, i] / 2 for i in range(len(x))]))
            lam = [1 - sum(a)] + [a[i] for i in range(len(x))]
            f = [mpmath.mpf(0)] * w
            for i in members:
                for kk, k in enumerate(members):
                    if k != i:
                        f[i] += lam[kk] * frac[mask & ~(1 << k)][i]
            frac[mask] = f
        return np.array([float(t) for t in frac[(1 << w) - 1]])


CIRCUMCENTRIC_CASES = 20


@pytest.mark.parametrize("family", ["needle", "spike", "sliver"])
def test_circumcentric_fractions_on_bad_tetrahedra_against_60_digit_reference(family):
    """The signed Voronoi shares of n = 3 simplices (exact circumcentres above ASPECT_BOUND)."""
    worst, ill = 0.0, 0
    for seed in range(CIRCUMCENTRIC_CASES):
        v, s = suspension(np.random.default_rng([21, 3, seed]), family)
        p = v[s]
        ref = np.array([circumcentric_reference(q) for q in p])
        ill += int((simplex_aspects(v, s) > ASPECT_BOUND).sum())
        worst = max(worst, float(np.max(np.abs(circumcentric_fractions(p) - ref)) / np.abs(ref).max()))
        areas = reference(v, s)["areas"][:, None]  # the 60-digit hyperareas
        exact = np.bincount(s.ravel(), weights=(ref * areas).ravel(), minlength=len(v))
        scale = np.bincount(s.ravel(), weights=(np.abs(ref) * areas).ravel(), minlength=len(v))
        assert np.all(np.abs(vertex_areas(v, s, area="voronoi") - exact) <= TOL * scale)
    print(f"R4 {family}: {CIRCUMCENTRIC_CASES} meshes, {ill} tetrahedra of aspect > {ASPECT_BOUND:g}, "
          f"worst error {worst:.2g}")
    assert ill >= CIRCUMCENTRIC_CASES
    assert worst <= TOL

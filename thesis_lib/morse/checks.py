"""Computations that check the statements of thesis chapter 4 on inputs of our own choosing.

Two halves.  The smooth half (§4.1) works on closed surfaces ``{g = 0}`` in R³ (the torus of
Example 4.2 and the unit sphere of Example 4.18) with a function F of R³ restricted to them: the
critical points are found by Newton's method on the Lagrange system, classified by the Riemannian
Hessian, and the negative gradient flow of the induced metric is integrated, so that flow lines
between critical points — and with them the Morse complex of §4.1.2 — are computed, not typed in.
The discrete half (§4.2) draws random complexes and random vector fields and evaluates the
statements of §4.2.1–4.2.5 on them (Lemma 4.22, Theorems 4.25–4.28, Proposition 4.32, Theorems
4.36–4.44).  This module is imported as ``thesis_lib.morse.checks``.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import scipy.integrate
import scipy.optimize
import scipy.sparse as sp

from .._validate import check_int, check_torus_radii
from ..homology import homology
from ..homology.smith import rank_mod_p
from ._cells import ComplexLike, Pairs, Simplex
from .flow import boundary_operator, cells, gradient_matrix, stabilised_flow
from .functions import critical_simplices, gradient_pairs, sublevel_complex
from .matching import critical_counts, morse_matching
from .smooth import morse_index, morse_inequalities

__all__ = [
    "Surface",
    "AmbientFunction",
    "torus_surface",
    "sphere_surface",
    "linear_function",
    "quadratic_function",
    "random_quadratic_function",
    "surface_critical_points",
    "flow_end",
    "flow_limit_fractions",
    "saddle_branches",
    "surface_morse_complex",
    "antipodal_quotient_counts",
    "random_complex",
    "random_vector_field",
    "gradient_samples",
    "morse_inequality_survey",
    "lemma_4_22_count",
    "proposition_4_32_violations",
    "flow_invariant_homology",
    "sublevel_changes",
    "chapter_of_heading",
    "two_critical_survey",
    "finite_difference_hessian",
    "torus_grid",
    "sublevel_level_changes",
]

Vector = npt.NDArray[np.float64]


# ---------------------------------------------------------------------------------------- smooth
@dataclass(frozen=True)
class Surface:
    """A closed surface ``{x ∈ R³ : g(x) = 0}`` with ∇g ≠ 0 on it; ∇g/|∇g| is its orientation.

    Attributes: ``g``, ``grad`` and ``hess`` (callables of a point), ``project`` (a point near the
    surface to the surface), ``sample`` (``sample(n, seed)``: n points on it) and ``euler``.
    """

    name: str
    g: Callable[[Vector], float]
    grad: Callable[[Vector], Vector]
    hess: Callable[[Vector], Vector]
    project: Callable[[Vector], Vector]
    sample: Callable[[int, int], Vector]
    euler: int


@dataclass(frozen=True)
class AmbientFunction:
    """A smooth function F on R³ with its gradient and Hessian (callables of a point)."""

    name: str
    value: Callable[[Vector], float]
    grad: Callable[[Vector], Vector]
    hess: Callable[[Vector], Vector]


def torus_surface(*, R: float = 2.0, r: float = 1.0) -> Surface:
    """The upright torus φ(u, v) = (sin u (R + r cos v), r sin v, cos u (R + r cos v)) as ``{g = 0}``.

    Thesis: Example 4.2 / Figure 4.1 (axis along y, so the height z has four critical points).

    Parameters
    ----------
    R, r : float
        Distance from the centre of the tube to the axis and radius of the tube, 0 < r < R.

    Returns
    -------
    Surface
        g(x) = (ρ − R)² + y² − r² with ρ = √(x² + z²); χ = 0.

    Raises
    ------
    ValueError
        Unless 0 < r < R.
    """
    R, r = check_torus_radii(R, r)

    def g(p):
        rho = np.hypot(p[0], p[2])
        return (rho - R) ** 2 + p[1] ** 2 - r * r

    def grad(p):
        rho = np.hypot(p[0], p[2])
        return np.array([2 * p[0] * (1 - R / rho), 2 * p[1], 2 * p[2] * (1 - R / rho)])

    def hess(p):
        rho = np.hypot(p[0], p[2])
        w = np.array([p[0], p[2]])
        block = 2 * np.eye(2) - 2 * R * (np.eye(2) / rho - np.outer(w, w) / rho**3)
        h = np.zeros((3, 3))
        h[np.ix_([0, 2], [0, 2])] = block
        h[1, 1] = 2.0
        return h

    def project(p):
        rho = np.hypot(p[0], p[2])
        c = np.array([R * p[0] / rho, 0.0, R * p[2] / rho])
        d = p - c
        return c + r * d / np.linalg.norm(d)

    def sample(n, seed):
        u, v = np.random.default_rng(seed).uniform(0, 2 * np.pi, (2, int(n)))
        return np.stack([np.sin(u) * (R + r * np.cos(v)), r * np.sin(v), np.cos(u) * (R + r * np.cos(v))], axis=1)

    return Surface(f"torus(R={R:g}, r={r:g})", g, grad, hess, project, sample, 0)


def sphere_surface() -> Surface:
    """The unit sphere S² = ``{|x|² − 1 = 0}`` with the metric induced from R³.

    Thesis: Example 4.18.

    Returns
    -------
    Surface
        χ = 2.
    """

    def sample(n, seed):
        x = np.random.default_rng(seed).normal(size=(int(n), 3))
        return x / np.linalg.norm(x, axis=1, keepdims=True)

    return Surface("S²", lambda p: float(p @ p - 1.0), lambda p: 2 * p, lambda p: 2 * np.eye(3),
                   lambda p: p / np.linalg.norm(p), sample, 2)


def linear_function(a: Sequence[float], *, name: str = "") -> AmbientFunction:
    """F(x) = a·x, e.g. the height z (a = (0, 0, 1)) or a tilted height.

    Thesis: Example 4.2 (the height), Example 4.12 (a small tilt).

    Parameters
    ----------
    a : sequence of 3 floats
        The direction.
    name : str, optional
        A label.

    Returns
    -------
    AmbientFunction
    """
    a = np.asarray(a, dtype=float)
    return AmbientFunction(name or f"{a.tolist()}·x", lambda p: float(a @ p), lambda p: a.copy(),
                           lambda p: np.zeros((3, 3)))


def quadratic_function(A: npt.ArrayLike, *, b: Sequence[float] = (0.0, 0.0, 0.0), name: str = "") -> AmbientFunction:
    """F(x) = xᵀAx + b·x (A symmetrised).

    Thesis: Example 4.18 (h = c₁u² + c₂v² + c₃w² is A = diag(c), b = 0).

    Parameters
    ----------
    A : array_like, shape (3, 3)
        The quadratic form.
    b : sequence of 3 floats, default 0
        The linear part.
    name : str, optional
        A label.

    Returns
    -------
    AmbientFunction
    """
    A = np.asarray(A, dtype=float)
    A = (A + A.T) / 2
    b = np.asarray(b, dtype=float)
    return AmbientFunction(name or "quadratic", lambda p: float(p @ A @ p + b @ p), lambda p: 2 * A @ p + b,
                           lambda p: 2 * A)


def random_quadratic_function(*, seed: int) -> AmbientFunction:
    """A random F(x) = xᵀAx + b·x (standard normal entries): generically a Morse function on a surface.

    Thesis: Theorems 4.6–4.7 (inputs of our choosing for the Morse inequalities).

    Parameters
    ----------
    seed : int
        The draw.

    Returns
    -------
    AmbientFunction
    """
    rng = np.random.default_rng(seed)
    return quadratic_function(rng.normal(size=(3, 3)), b=rng.normal(size=3), name=f"random quadratic {seed}")


def _tangent_basis(n: Vector) -> Vector:
    a = np.eye(3)[int(np.argmin(np.abs(n)))]
    e1 = np.cross(n, a)
    e1 /= np.linalg.norm(e1)
    return np.stack([e1, np.cross(n, e1)], axis=1)


def _riemannian_hessian(surface: Surface, F: AmbientFunction, x: Vector) -> tuple[Vector, Vector]:
    dg = surface.grad(x)
    lam = float(F.grad(x) @ dg / (dg @ dg))
    n = dg / np.linalg.norm(dg)
    T = _tangent_basis(n)
    H = T.T @ (F.hess(x) - lam * surface.hess(x)) @ T
    return (H + H.T) / 2, T


def surface_critical_points(surface: Surface, F: AmbientFunction, *, n_starts: int = 300,
                            seed: int = 0) -> list[dict]:
    """Critical points of F restricted to a surface, with their Morse indices, sorted by value.

    Thesis: §4.1.1 (critical points, Hessian, Morse index; Definition 4.1).

    Newton's method (``scipy.optimize.root`` with the exact Jacobian) on the Lagrange system
    ∇F = λ∇g, g = 0 from ``n_starts`` random points of the surface; the roots are merged and
    classified by the Hessian of F|surface, P(∇²F − λ∇²g)P on the tangent plane.

    Parameters
    ----------
    surface : Surface
        The surface.
    F : AmbientFunction
        The function.
    n_starts : int, default 300
        Number of starting points.
    seed : int, default 0
        Their draw.

    Returns
    -------
    list of dict
        ``point`` (ndarray (3,)), ``value``, ``index``, ``hessian`` (2 × 2 in an orthonormal
        tangent basis ``tangent`` (3 × 2) with (t₁, t₂, n) positively oriented).

    Raises
    ------
    ValueError
        A degenerate critical point (F is not a Morse function there).
    """

    def system(z):
        x, lam = z[:3], z[3]
        return np.concatenate([F.grad(x) - lam * surface.grad(x), [surface.g(x)]])

    def jac(z):
        x, lam = z[:3], z[3]
        J = np.zeros((4, 4))
        J[:3, :3] = F.hess(x) - lam * surface.hess(x)
        J[:3, 3] = -surface.grad(x)
        J[3, :3] = surface.grad(x)
        return J

    found: list[Vector] = []
    for x0 in surface.sample(n_starts, seed):
        dg = surface.grad(x0)
        z0 = np.concatenate([x0, [F.grad(x0) @ dg / (dg @ dg)]])
        sol = scipy.optimize.root(system, z0, jac=jac, method="hybr", options={"xtol": 1e-13})
        if not sol.success or np.linalg.norm(system(sol.x)) > 1e-9:
            continue
        x = sol.x[:3]
        if not any(np.linalg.norm(x - y) < 1e-6 for y in found):
            found.append(x)
    out = []
    for x in found:
        H, T = _riemannian_hessian(surface, F, x)
        out.append(dict(point=x, value=F.value(x), index=morse_index(H), hessian=H, tangent=T))
    return sorted(out, key=lambda c: (c["value"], tuple(np.round(c["point"], 9))))


def _velocity(surface: Surface, F: AmbientFunction, sign: float) -> Callable[[float, Vector], Vector]:
    def f(_t, x):
        dg = surface.grad(x)
        nn = dg @ dg
        dF = F.grad(x)
        tangential = dF - (dF @ dg) / nn * dg
        return -sign * tangential - surface.g(x) / nn * dg  # second term: stay on the surface

    return f


def flow_end(surface: Surface, F: AmbientFunction, x0: npt.ArrayLike, targets: Sequence[npt.ArrayLike], *,
             backward: bool = False, skip: int | None = None, tol: float = 1e-6, t_max: float = 2000.0) -> int:
    """Which critical point the negative gradient flow from x0 reaches (in forward or backward time).

    Thesis: §4.1.2 (∂φ/∂t = −∇f(φ); initial and final points of a flow line).

    The flow of the metric induced from R³ is integrated (``solve_ivp``, DOP853, rtol 1e-10)
    until it comes within ``tol`` of one of the ``targets``.

    Parameters
    ----------
    surface, F : Surface, AmbientFunction
        The surface and the function.
    x0 : array_like, shape (3,)
        The start, on the surface.
    targets : sequence of array_like
        The critical points.
    backward : bool, default False
        Follow +∇f (backward time) instead of −∇f.
    skip : int, optional
        A target not to stop at (the critical point a branch starts from).
    tol : float, default 1e-6
        Distance at which a target counts as reached.
    t_max : float, default 2000
        Longest time integrated.

    Returns
    -------
    int
        The index of the target reached, or -1 if none is reached by ``t_max``.
    """
    targets = [np.asarray(t, dtype=float) for t in targets]
    events = []
    for i, c in enumerate(targets):
        if i == skip:
            continue

        def ev(_t, x, c=c):
            return np.linalg.norm(x - c) - tol

        ev.terminal = True
        events.append((i, ev))
    sol = scipy.integrate.solve_ivp(_velocity(surface, F, -1.0 if backward else 1.0), (0.0, t_max),
                                    np.asarray(x0, dtype=float), method="DOP853", rtol=1e-10, atol=1e-12,
                                    events=[e for _, e in events])
    for (i, _), hits in zip(events, sol.t_events):
        if len(hits):
            return i
    return -1


def flow_limit_fractions(surface: Surface, F: AmbientFunction, critical: Sequence[dict], *, n: int = 100,
                         seed: int = 0) -> tuple[Vector, Vector]:
    """For each critical point p, the fraction of random points x with lim φ(x, t) = p as t → +∞ and as t → −∞.

    Thesis: Definition 4.9 and Theorem 4.10 (the sets of points flowing to p in forward and in
    backward time, and their dimensions n − k and k): a set of dimension 2 on a surface is open and
    holds a positive fraction of random points; one of dimension < 2 holds none.

    Parameters
    ----------
    surface, F : Surface, AmbientFunction
        The surface and the function.
    critical : sequence of dict
        Its critical points (:func:`surface_critical_points`).
    n : int, default 100
        Number of random points.
    seed : int, default 0
        Their draw.

    Returns
    -------
    forward, backward : ndarray, shape (len(critical),)
        Fractions (multiples of 1/n) of the points whose forward (backward) limit is each critical point.
    """
    pts = [c["point"] for c in critical]
    fwd = np.zeros(len(pts))
    bwd = np.zeros(len(pts))
    for x in surface.sample(n, seed):
        for out, backward in ((fwd, False), (bwd, True)):
            i = flow_end(surface, F, x, pts, backward=backward, tol=1e-5)
            if i >= 0:
                out[i] += 1
    return fwd / n, bwd / n


def saddle_branches(surface: Surface, F: AmbientFunction, critical: Sequence[dict], *,
                    delta: float = 1e-4) -> list[dict]:
    """The two unstable and the two stable branches of every index-1 critical point, followed to their ends.

    Thesis: §4.1.2 (flow lines between critical points; on a surface every flow line from an index-2
    to an index-1 point is a stable branch of the latter, every one from index 1 to 0 an unstable one).

    Parameters
    ----------
    surface, F : Surface, AmbientFunction
        The surface and the function.
    critical : sequence of dict
        The critical points (:func:`surface_critical_points`).
    delta : float, default 1e-4
        Distance from the saddle at which a branch is started, along an eigenvector of the Hessian.

    Returns
    -------
    list of dict
        One per branch: ``saddle`` (index into ``critical``), ``kind`` (``"unstable"``: followed
        forward; ``"stable"``: followed backward), ``direction`` (unit tangent vector the branch
        leaves the saddle along), ``end`` (index of the critical point reached, -1 if none).
    """
    pts = [c["point"] for c in critical]
    out = []
    for i, c in enumerate(critical):
        if c["index"] != 1:
            continue
        ev, vec = np.linalg.eigh(c["hessian"])
        for kind, col in (("unstable", 0), ("stable", 1)):  # eigh sorts ascending: col 0 is negative
            e = c["tangent"] @ vec[:, col]
            for s in (1.0, -1.0):
                x0 = surface.project(c["point"] + s * delta * e)
                end = flow_end(surface, F, x0, pts, backward=(kind == "stable"), skip=i)
                out.append(dict(saddle=i, kind=kind, direction=s * e, end=end))
    return out


def _orient_unstable(e: Vector) -> Vector:
    k = int(np.flatnonzero(np.abs(e) > 1e-9)[0])
    return e if e[k] > 0 else -e


def surface_morse_complex(surface: Surface, F: AmbientFunction, critical: Sequence[dict], *,
                          branches: Sequence[dict] | None = None) -> dict:
    """The Morse complex over Z of a function on an oriented surface, from its computed flow lines.

    Thesis: §4.1.2 (the Morse complex; orientations of the moduli spaces by (4.3), Example 4.18).

    Orientations: the unstable manifold of an index-2 point carries the surface's orientation
    (outward normal); that of a saddle the unstable eigenvector whose first nonzero coordinate is
    positive; index-0 points +.  A flow line from a maximum into a saddle q counts
    sign det[n, γ̇, e_q]; one from q to a minimum counts +1 if it leaves q along e_q, else −1.

    Parameters
    ----------
    surface, F : Surface, AmbientFunction
        The surface and the function.
    critical : sequence of dict
        The critical points (:func:`surface_critical_points`).
    branches : sequence of dict, optional
        :func:`saddle_branches` (computed when not given).

    Returns
    -------
    dict
        ``names`` (indices into ``critical`` per Morse index 0, 1, 2), ``counts`` and ``signed``
        (lists of int64 arrays: ``[k]`` has rows the index-(k−1) points, columns the index-k points,
        k = 1, 2; ``counts`` the numbers of flow lines, ``signed`` the sums of their signs),
        ``saddle_connection_branches`` (saddle branches that end at a saddle: 0 for a Morse–Smale
        function) and ``saddle_connections`` (flow lines from a saddle to a saddle, each seen as an
        unstable branch of one saddle and a stable branch of the other: half the branches).
    """
    if branches is None:
        branches = saddle_branches(surface, F, critical)
    names = [[i for i, c in enumerate(critical) if c["index"] == k] for k in range(3)]
    pos = {i: j for level in names for j, i in enumerate(level)}
    counts = [None, np.zeros((len(names[0]), len(names[1])), np.int64),
              np.zeros((len(names[1]), len(names[2])), np.int64)]
    signed = [None, counts[1].copy(), counts[2].copy()]
    connections = 0
    for b in branches:
        q = b["saddle"]
        if b["end"] < 0:
            continue
        end_index = critical[b["end"]]["index"]
        eq = _orient_unstable(critical[q]["tangent"] @ np.linalg.eigh(critical[q]["hessian"])[1][:, 0])
        if b["kind"] == "unstable" and end_index == 0:
            counts[1][pos[b["end"]], pos[q]] += 1
            signed[1][pos[b["end"]], pos[q]] += 1 if b["direction"] @ eq > 0 else -1
        elif b["kind"] == "stable" and end_index == 2:
            n = surface.grad(critical[q]["point"])
            arriving = -b["direction"]  # the flow line comes into q against the branch's direction
            counts[2][pos[q], pos[b["end"]]] += 1
            signed[2][pos[q], pos[b["end"]]] += 1 if np.linalg.det(np.stack([n, arriving, eq])) > 0 else -1
        elif end_index == 1:
            connections += 1
    return dict(names=names, counts=counts, signed=signed, saddle_connections=connections // 2,
                saddle_connection_branches=connections)


def antipodal_quotient_counts(critical: Sequence[dict], complex_: dict) -> list[Vector]:
    """Flow-line counts of the quotient RP² = S²/(x ~ −x) of an even function on S².

    Thesis: Example 4.19 (the Morse–Smale function of S² on RP²: p, q, r with two flow lines
    p → q and two q → r).

    A flow line of RP² from [a] lifts to exactly one flow line of S² from each of a and −a, so
    the count from [a] to [b] is #M(a, b) + #M(a, −b) on S².

    Parameters
    ----------
    critical : sequence of dict
        The critical points on S² (closed under x → −x).
    complex_ : dict
        :func:`surface_morse_complex` of the function on S².

    Returns
    -------
    list of ndarray
        ``[k]`` for k = 1, 2: rows the classes of index k − 1, columns those of index k (the first
        point of each antipodal pair represents it); ``[0]`` is None.

    Raises
    ------
    ValueError
        The critical points are not closed under x → −x.
    """
    names = complex_["names"]
    out: list = [None]
    for k in (1, 2):
        lower, upper = names[k - 1], names[k]

        def classes(level):
            reps, cls = [], {}
            for i in level:
                partner = [j for j in level if np.linalg.norm(critical[j]["point"] + critical[i]["point"]) < 1e-6]
                if not partner:
                    raise ValueError("the critical points are not closed under x -> -x")
                key = min(i, partner[0])
                if key not in reps:
                    reps.append(key)
                cls[i] = reps.index(key)
            return reps, cls

        up_reps, _ = classes(upper)
        low_reps, low_cls = classes(lower)
        m = np.zeros((len(low_reps), len(up_reps)), np.int64)
        for col, a in enumerate(up_reps):
            for row_pos, b in enumerate(lower):
                m[low_cls[b], col] += complex_["counts"][k][row_pos, upper.index(a)]
        out.append(m)
    return out


def torus_grid(n: int, *, R: float = 2.0, r: float = 1.0) -> tuple[list[Simplex], Vector]:
    """A triangulation of the torus by an n × n grid of the parameters (u, v), and its vertices' φ(u, v).

    Thesis: Example 4.2 (the parametrisation φ of the upright torus), for the sublevel sets M^a of
    Theorems 4.4–4.5.

    Parameters
    ----------
    n : int
        Grid points per angle (at least 3); vertex i·n + j sits at u = 2πi/n, v = 2πj/n.
    R, r : float
        The radii, 0 < r < R.

    Returns
    -------
    triangles : list of tuple
        2n² triangles (sorted vertices).
    points : ndarray, shape (n², 3)
        φ at the vertices.

    Raises
    ------
    ValueError
        n < 3 or radii without 0 < r < R.
    """
    n = check_int(n, "n", minimum=3)
    R, r = check_torus_radii(R, r)
    idx = lambda i, j: (i % n) * n + (j % n)  # noqa: E731
    tris = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i, j + 1), idx(i + 1, j + 1)
            tris += [tuple(sorted((a, b, d))), tuple(sorted((a, c, d)))]
    u, v = np.meshgrid(2 * np.pi * np.arange(n) / n, 2 * np.pi * np.arange(n) / n, indexing="ij")
    u, v = u.ravel(), v.ravel()
    pts = np.stack([np.sin(u) * (R + r * np.cos(v)), r * np.sin(v), np.cos(u) * (R + r * np.cos(v))], axis=1)
    return tris, pts


def sublevel_level_changes(triangles: Sequence[Simplex], values: npt.ArrayLike, levels: Sequence[float],
                           critical: Sequence[tuple[float, int]], *, coefficients: int = 2) -> dict[str, object]:
    """Betti numbers of the sublevel sets M^a of a vertex function on a triangulated surface, level by
    level, and whether they change only across critical values and then as attaching one cell does.

    Thesis: Theorem 4.4 (no critical point in f⁻¹[a, b]: M^a ≃ M^b) and Theorem 4.5 (one critical
    point of index k: M^b is M^a with a k-cell attached, up to homotopy).

    M^a is taken as the subcomplex spanned by the vertices with value ≤ a (the lower-star
    filtration of the piecewise-linear interpolation).

    Parameters
    ----------
    triangles : sequence of tuple
        The surface.
    values : array_like, shape (n_vertices,)
        The function at the vertices.
    levels : sequence of float
        Increasing levels a, none of them a critical value.
    critical : sequence of (float, int)
        The critical values with their indices.
    coefficients : int, default 2
        Betti numbers over Z/p.

    Returns
    -------
    dict
        ``betti`` (list per level), ``steps_without`` / ``changes_without`` (consecutive levels with
        no critical value between them, and among those the ones whose Betti numbers differ),
        ``steps_with_one`` / ``one_cell`` (consecutive levels with one critical value between them,
        and among those the ones where exactly β_k rises by one or β_(k−1) falls by one).

    Raises
    ------
    ValueError
        A level equal to a critical value.
    """
    f = np.asarray(values, dtype=float)
    if any(abs(a - c) <= 1e-12 * max(1.0, abs(c)) for a in levels for c, _ in critical):
        raise ValueError("a level equals a critical value; choose levels between them")
    tris = np.asarray(triangles, dtype=np.int64)
    edges = np.unique(np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [0, 2]], tris[:, [1, 2]]]), axis=1), axis=0)
    betti = []
    for a in levels:
        keep_v = np.flatnonzero(f <= a)
        simplices = [(int(v),) for v in keep_v]
        simplices += [tuple(map(int, e)) for e in edges[(f[edges] <= a).all(axis=1)]]
        simplices += [tuple(map(int, t)) for t in tris[(f[tris] <= a).all(axis=1)]]
        b = [x for x, _ in homology(simplices, coefficients=coefficients)] if simplices else []
        betti.append((b + [0, 0, 0])[:3])
    out = dict(betti=betti, steps_without=0, changes_without=0, steps_with_one=0, one_cell=0)
    for lo, hi, b0, b1 in zip(levels[:-1], levels[1:], betti[:-1], betti[1:]):
        between = [k for c, k in critical if lo < c < hi]
        diff = np.array(b1) - np.array(b0)
        if not between:
            out["steps_without"] += 1
            out["changes_without"] += bool(diff.any())
        elif len(between) == 1:
            k = between[0]
            out["steps_with_one"] += 1
            single = np.count_nonzero(diff) == 1
            out["one_cell"] += bool(single and (diff[k] == 1 or (k > 0 and diff[k - 1] == -1)))
    return out


# -------------------------------------------------------------------------------------- discrete
def random_complex(*, n_vertices: int = 8, dim: int = 2, density: float = 0.3, seed: int) -> list[Simplex]:
    """A random pure complex: each dim-simplex on ``n_vertices`` vertices kept with probability ``density``.

    Thesis: §4.2 (inputs of our choosing for the statements about any simplicial complex).

    Parameters
    ----------
    n_vertices : int, default 8
        Number of vertices.
    dim : int, default 2
        Dimension of the facets.
    density : float, default 0.3
        Probability of each facet.
    seed : int
        The draw.

    Returns
    -------
    list of tuple
        The facets (at least one).
    """
    rng = np.random.default_rng(seed)
    facets = [s for s in itertools.combinations(range(n_vertices), dim + 1) if rng.random() < density]
    return facets or [tuple(range(dim + 1))]


def random_vector_field(simplices: ComplexLike, *, seed: int, fraction: float = 1.0) -> list[tuple[Simplex, Simplex]]:
    """A random discrete vector field (Definition 4.33): random face–coface pairs, each simplex in at most one.

    Thesis: Definition 4.33 (such a field may have closed V-paths, Definition 4.34).

    Parameters
    ----------
    simplices : complex
        The complex.
    seed : int
        The draw.
    fraction : float, default 1.0
        Probability with which each admissible pair met in random order is taken.

    Returns
    -------
    list of (tuple, tuple)
        The pairs (sigma, tau).
    """
    rng = np.random.default_rng(seed)
    basis = cells(simplices)
    incid = [(s, t) for t in basis for s in itertools.combinations(t, len(t) - 1) if len(t) > 1]
    used: set[Simplex] = set()
    out = []
    for j in rng.permutation(len(incid)):
        s, t = incid[j]
        if s not in used and t not in used and rng.random() < fraction:
            used.update((s, t))
            out.append((s, t))
    return out


def gradient_samples(n: int, *, seed: int) -> list[tuple[str, list[Simplex], list[tuple[Simplex, Simplex]]]]:
    """``n`` pairs (complex, acyclic gradient field): random 2- and 3-complexes and the triangulations
    of §2.2.1 with greedy gradients of random tie-breaking.

    Thesis: §4.2.6 (heuristic gradients), for the statements of §4.2 on inputs of our choosing.

    Parameters
    ----------
    n : int
        Number of samples.
    seed : int
        The draw (sample i uses seed + i).

    Returns
    -------
    list of (str, list of tuple, list of pairs)
        A label, the complex's facets and the gradient field.
    """
    from ..datasets import dunce_hat, klein_bottle, rp2, sphere, torus

    named = [("torus", torus()), ("RP²", rp2()), ("Klein bottle", klein_bottle()), ("dunce hat", dunce_hat()),
             ("S²", sphere(2)), ("S³", sphere(3))]
    out = []
    for i in range(int(n)):
        s = seed + i
        kind = i % 4
        if kind == 0:
            name, cx = f"random 2-complex {s}", random_complex(n_vertices=8, dim=2, density=0.3, seed=s)
        elif kind == 1:
            name, cx = f"random 3-complex {s}", random_complex(n_vertices=7, dim=3, density=0.25, seed=s)
        else:
            name, cx = named[(i // 4 + kind) % len(named)]
        method = "coreduction" if (i // 2) % 2 == 0 else "collapse"
        out.append((f"{name}, {method}", cx, morse_matching(cx, heuristic=method, seed=s)))
    return out


def morse_inequality_survey(samples: Sequence[tuple[str, list[Simplex], Pairs]]) -> dict[str, int]:
    """Weak, Euler and strong discrete Morse inequalities over gradient samples.

    Thesis: Theorems 4.27 and 4.28 (β_k ≤ Crit_k^d, the alternating sums, the strong inequalities).

    β_k is the rank of H_k(K; Z) (computed by the Smith normal form), Crit_k^d the number of
    critical k-simplices of the field.

    Parameters
    ----------
    samples : sequence of (label, complex, pairs)
        As :func:`gradient_samples` returns.

    Returns
    -------
    dict of str to int
        ``n``; ``weak``, ``euler_le``, ``euler_equal``, ``strong``: the samples where each holds;
        ``weak_strict``, ``strong_strict``: those where it is strict in some k;
        ``euler_strict``: those with Σ(−1)^k β_k < Σ(−1)^k Crit_k^d.
    """
    keys = ("n", "weak", "euler_le", "euler_equal", "euler_strict", "strong", "weak_strict", "strong_strict")
    out = dict.fromkeys(keys, 0)
    for _, cx, pairs in samples:
        crit = np.array(critical_counts(cx, pairs), dtype=np.int64)
        betti = np.array([b for b, _ in homology(cx)], dtype=np.int64)
        m = max(crit.size, betti.size)
        crit, betti = np.pad(crit, (0, m - crit.size)), np.pad(betti, (0, m - betti.size))
        checks = morse_inequalities(crit, betti)
        signs = (-1) ** np.arange(m)
        a_b, a_c = int(signs @ betti), int(signs @ crit)
        partial = [int(np.sum(signs[: k + 1][::-1] * (crit[: k + 1] - betti[: k + 1]))) for k in range(m)]
        out["n"] += 1
        out["weak"] += checks["weak"]
        out["strong"] += checks["strong"]
        out["euler_le"] += a_b <= a_c
        out["euler_equal"] += a_b == a_c
        out["euler_strict"] += a_b < a_c
        out["weak_strict"] += bool(np.any(betti < crit))
        out["strong_strict"] += any(d > 0 for d in partial)
    return out


def lemma_4_22_count(values: dict[Simplex, float]) -> tuple[int, int, bool]:
    """Simplices at which (4.4) and (4.5) both hold, and whether the minimum is at a vertex.

    Thesis: Lemma 4.22 ((4.4) and (4.5) cannot both hold) and the remark after it (the minimum
    of f_d occurs at a vertex).

    Parameters
    ----------
    values : dict of tuple to float
        A discrete Morse function on every simplex of a complex.

    Returns
    -------
    (int, int, bool)
        Number of simplices checked, number where both conditions hold, whether a minimiser is a vertex.
    """
    keys = list(values)
    faces = {s: [g for g in itertools.combinations(s, len(s) - 1) if g] for s in keys}
    cofaces: dict[Simplex, list[Simplex]] = {s: [] for s in keys}
    for s in keys:
        for g in faces[s]:
            cofaces[g].append(s)
    both = sum(1 for s in keys if any(values[t] <= values[s] for t in cofaces[s])
               and any(values[g] >= values[s] for g in faces[s]))
    low = min(values.values())
    return len(keys), both, any(len(s) == 1 and values[s] == low for s in keys)


def proposition_4_32_violations(values: dict[Simplex, float]) -> dict[str, int]:
    """Counts of failures of the three parts of Proposition 4.32 for the gradient V of a discrete Morse function.

    Thesis: Proposition 4.32 (V∘V = 0; #{γ : V(γ) = ±σ} ≤ 1; σ critical ⇔ σ ∉ im V and V(σ) = 0).

    The pairs of V are read from the values by Definition 4.30 (σ < τ with f(τ) ≤ f(σ)), the
    critical simplices by Definition 4.21, both from the values alone.

    Parameters
    ----------
    values : dict of tuple to float
        A discrete Morse function on every simplex of a complex.

    Returns
    -------
    dict of str to int
        ``not_a_field`` (1 if a simplex lies in two pairs, so that V(γ) = ±σ for two γ or
        V(σ) ≠ 0 for σ ∈ im V; the other counts are then 0), ``vv_nonzero`` (nonzero entries of
        V∘V), ``critical_mismatch`` (simplices where Definition 4.21 and "σ ∉ im V and V(σ) = 0"
        disagree), ``n`` (simplices).
    """
    simplices = list(values)
    pairs = gradient_pairs(values)
    basis = cells(simplices)
    try:
        V = sp.csc_matrix(gradient_matrix(simplices, pairs))
    except ValueError:
        return dict(not_a_field=1, vv_nonzero=0, critical_mismatch=0, n=len(basis))
    vv = (V @ V).tocoo()
    in_image = np.bincount(V.tocoo().row, minlength=len(basis)) > 0
    nonzero_image = np.diff(V.indptr) > 0
    crit = set(critical_simplices(values))
    mismatch = sum(1 for i, s in enumerate(basis) if (s in crit) != (not in_image[i] and not nonzero_image[i]))
    return dict(not_a_field=0, vv_nonzero=int(np.count_nonzero(vv.data)), critical_mismatch=int(mismatch),
                n=len(basis))


def flow_invariant_homology(simplices: ComplexLike, pairs: Pairs, *, coefficients: int = 2) -> dict[str, list[int]]:
    """Betti numbers over Z/p of the complex C^Φ of Φ-invariant chains, and the ranks of C^Φ_k.

    Thesis: Theorem 4.39 (H_k(C^Φ) ≅ H_k(K)) and Theorem 4.41 (C^Φ_k ≅ M_k, the critical k-simplices).

    C^Φ_k is the image of Φ^∞ on k-chains (Theorem 4.38): β_k(C^Φ) = rank Φ^∞_k − rank ∂Φ^∞_k −
    rank ∂Φ^∞_{k+1}, ranks taken mod p.

    Parameters
    ----------
    simplices, pairs : complex, iterable of (sigma, tau)
        The complex and an acyclic field.
    coefficients : int, default 2
        The prime p.

    Returns
    -------
    dict
        ``rank`` (rank C^Φ_k), ``betti`` (of C^Φ), ``n_steps`` ([N] of Theorem 4.38).
    """
    p = int(coefficients)
    basis = cells(simplices)
    dims = np.array([len(s) - 1 for s in basis])
    inf, steps = stabilised_flow(simplices, pairs)
    inf = sp.csc_matrix(inf)
    D = sp.csc_matrix(boundary_operator(simplices))
    top = int(dims.max())
    rank, drank = [], []
    for k in range(top + 1):
        cols = np.flatnonzero(dims == k)
        block = inf[:, cols]
        rank.append(rank_mod_p(block, coefficients=p) if block.nnz else 0)
        img = sp.csc_matrix(D @ block)
        img.eliminate_zeros()
        drank.append(rank_mod_p(img, coefficients=p) if img.nnz else 0)
    betti = [rank[k] - drank[k] - (drank[k + 1] if k < top else 0) for k in range(top + 1)]
    return dict(rank=rank, betti=betti, n_steps=[steps])


def sublevel_changes(values: dict[Simplex, float], *, coefficients: int = 2) -> dict[str, int]:
    """How the Betti numbers of the sublevel complexes K^a change as a passes the values of f.

    Thesis: Theorems 4.25 (no critical value in [a, b]: K^a ≃ K^b) and 4.26 (one critical
    k-simplex: a k-cell is attached, so β_k rises by one or β_{k−1} falls by one).

    Parameters
    ----------
    values : dict of tuple to float
        An injective discrete Morse function.
    coefficients : int, default 2
        Betti numbers over Z/p.

    Returns
    -------
    dict of str to int
        ``regular`` and ``critical`` (values passed of each kind), ``regular_changes`` (regular
        values where the Betti numbers change), ``one_cell`` (critical values where exactly one
        Betti number changes, by one, as attaching a k-cell does).
    """
    crit = set(critical_simplices(values))
    order = sorted(values.items(), key=lambda kv: kv[1])
    top = max(len(s) for s in values) - 1
    prev = [0] * (top + 1)
    out = dict(regular=0, critical=0, regular_changes=0, one_cell=0)
    for s, a in order:
        sub = sublevel_complex(values, a)
        betti = [b for b, _ in homology(sub, coefficients=coefficients)] if sub else []
        betti += [0] * (top + 1 - len(betti))
        diff = np.array(betti) - np.array(prev)
        if s in crit:
            k = len(s) - 1
            out["critical"] += 1
            up = diff[k] == 1 and np.count_nonzero(diff) == 1
            down = k > 0 and diff[k - 1] == -1 and np.count_nonzero(diff) == 1
            out["one_cell"] += bool(up or down)
        else:
            out["regular"] += 1
            out["regular_changes"] += bool(np.any(diff))
        prev = betti
    return out


def two_critical_survey(samples: Sequence[tuple[str, list[Simplex], Pairs]]) -> dict[str, int]:
    """The samples whose field has exactly two critical simplices: is one a vertex, is K a homology sphere?

    Thesis: Example 4.29 (two critical simplices: one is a vertex, and K ≃ S^k for the k of the other).

    Parameters
    ----------
    samples : sequence of (label, complex, pairs)
        As :func:`gradient_samples` returns.

    Returns
    -------
    dict of str to int
        ``n`` (samples with two critical simplices), ``with_vertex`` (of those, one critical
        simplex a vertex), ``sphere_homology`` (H_*(K; Z) that of S^k, k the other's dimension).
    """
    out = dict(n=0, with_vertex=0, sphere_homology=0)
    for _, cx, pairs in samples:
        crit = critical_counts(cx, pairs)
        if sum(crit) != 2:
            continue
        out["n"] += 1
        out["with_vertex"] += crit[0] >= 1
        k = max(d for d, c in enumerate(crit) if c) if crit[0] == 1 else 0
        want = [0] * len(crit)
        want[0] += 1
        want[k] += 1
        hom = homology(cx)
        got = [b for b, _ in hom] + [0] * (len(crit) - len(hom))
        out["sphere_homology"] += got == want and not any(t for _, t in hom)
    return out


def finite_difference_hessian(f: Callable[[float, float], float], u: float, v: float, *,
                              step: float = 1e-4) -> Vector:
    """The Hessian of a function of two variables by central differences.

    Thesis: Example 4.2 (the Hessian matrices of the height at its critical points).

    Parameters
    ----------
    f : callable (u, v) -> float
        The function.
    u, v : float
        The point.
    step : float, default 1e-4
        The difference step (error of order step²).

    Returns
    -------
    ndarray, shape (2, 2)
    """
    h = float(step)
    fuu = (f(u + h, v) - 2 * f(u, v) + f(u - h, v)) / h**2
    fvv = (f(u, v + h) - 2 * f(u, v) + f(u, v - h)) / h**2
    fuv = (f(u + h, v + h) - f(u + h, v - h) - f(u - h, v + h) + f(u - h, v - h)) / (4 * h * h)
    return np.array([[fuu, fuv], [fuv, fvv]])


_CHAPTER_LINE = re.compile(r"^\s*(\d+)\s*$")
_SECTION_LINE = re.compile(r"^(\d+)\.(\d+)(?:\.\d+)* (.+?)\s*$")


def chapter_of_heading(text: str, title: str) -> dict[str, int]:
    """The chapter that holds a section heading, read from the thesis text's own headings.

    Thesis: Example 4.19 and §4.2.3 ("simplicial homology in Chapter 1").

    A chapter opens with a line holding only its number, then its title; a section heading is
    "<chapter>.<section>[.<sub>] Title".  Both numberings are read and must agree.

    Parameters
    ----------
    text : str
        The thesis text.
    title : str
        The heading's title, e.g. ``"Simplicial Homology"``.

    Returns
    -------
    dict of str to int
        ``by_section_number``: the chapter number in the heading's own number; ``by_chapter_line``:
        the number of the last chapter line before it.

    Raises
    ------
    ValueError
        No heading with that title.
    """
    chapter = 0
    lines = text.splitlines()
    for i, line in enumerate(lines):
        m = _CHAPTER_LINE.match(line)
        if m and i + 2 < len(lines) and not lines[i + 1].strip() and lines[i + 2].strip()[:1].isupper():
            chapter = int(m.group(1))
        m = _SECTION_LINE.match(line)
        if m and m.group(3) == title:
            return dict(by_section_number=int(m.group(1)), by_chapter_line=chapter)
    raise ValueError(f"no heading {title!r} in the text")

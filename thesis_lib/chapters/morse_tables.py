"""The tables and checks of the chapter 4 page: each statement of the chapter evaluated and written up.

Every function takes what a section of the page computed (critical points, Morse complexes, random
samples of :mod:`thesis_lib.morse.checks`) and returns a :class:`Section`: the Markdown texts the page
shows, the flat results it records (the names of ``experiments/results/ch4-morse/results.json``) and
the values it glues into its prose.  This module is imported as ``thesis_lib.chapters.morse_tables``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from .._validate import check_torus_radii
from ..homology import betti_numbers, homology
from ..morse._cells import Pairs, Simplex
from ..morse.checks import (
    AmbientFunction,
    Surface,
    antipodal_quotient_counts,
    finite_difference_hessian,
    flow_invariant_homology,
    flow_limit_fractions,
    lemma_4_22_count,
    linear_function,
    morse_inequality_survey,
    proposition_4_32_violations,
    random_quadratic_function,
    random_vector_field,
    sublevel_changes,
    sublevel_level_changes,
    surface_critical_points,
    surface_morse_complex,
    two_critical_survey,
)
from ..morse.flow import boundary_operator, cells, gradient_flow, gradient_matrix, stabilised_flow
from ..morse.functions import (
    check_discrete_morse_function,
    critical_simplices,
    discrete_morse_function,
    gradient_pairs,
    is_discrete_morse_function,
    sublevel_complex,
)
from ..morse.matching import critical_counts, morse_matching
from ..morse.morse_complex import chain_complex_homology, morse_boundary, morse_homology
from ..morse.smooth import morse_inequalities, torus_height
from ..morse.vector_field import critical_cells, gradient_paths, is_acyclic

__all__ = [
    "Section",
    "simplex_name",
    "critical_point_table",
    "hessian_section",
    "sublevel_section",
    "smooth_inequalities_section",
    "flow_limits_section",
    "tilted_morse_complexes",
    "saddle_connection_section",
    "flow_line_counts",
    "tilted_torus_section",
    "sphere_morse_section",
    "rp2_quotient_section",
    "example_4_23_section",
    "lemma_4_22_section",
    "discrete_sublevel_section",
    "discrete_inequalities_section",
    "flow_matrices_section",
    "vector_field_section",
    "rp2_stabilisation_section",
    "stabilisation_section",
    "gradient_path_table",
    "rp2_morse_complex_section",
    "heuristic_table",
    "reduction_benchmark_section",
]

_EMPTY = np.zeros((0, 1), np.int64)


@dataclass(frozen=True, kw_only=True)
class Section:
    """What a section of a chapter page shows, records and glues.

    Attributes: ``texts`` (Markdown, shown in turn), ``results`` (flat name → number, for
    :meth:`thesis_lib.lab.results.Recorder.record`) and ``glued`` (name → value for the prose).
    """

    texts: tuple[str, ...] = ()
    results: dict[str, float | int] = field(default_factory=dict)
    glued: dict[str, object] = field(default_factory=dict)


def _betti(hom: Sequence[tuple[int, list[int]]]) -> list[int]:
    return [b for b, _ in hom]


def _table(header: str, rows: Sequence[str]) -> str:
    return header + "\n" + "\n".join(rows)


_WORDS = dict(enumerate(("no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")))
_WORDS |= {20: "twenty", 30: "thirty", 40: "forty", 50: "fifty"}


def _samples(n: int) -> str:
    return f"On the {_WORDS.get(n, str(n))} samples"


def simplex_name(simplex: Sequence[int], *, letters: str = "abcdef") -> str:
    """A simplex written with letters for its vertices, as the thesis names those of ℝP² (``ace``).

    Thesis: Example 4.43 (the simplices a, σ = ac, τ = ace of ℝP²).

    Parameters
    ----------
    simplex : sequence of int
        Vertex labels, each below ``len(letters)``.
    letters : str, default "abcdef"
        The letter of vertex 0, 1, ...

    Returns
    -------
    str
        The letters of the vertices, in order.

    Raises
    ------
    ValueError
        If a vertex has no letter.

    Examples
    --------
    >>> simplex_name((0, 2, 4))
    'ace'
    """
    if any(not 0 <= v < len(letters) for v in simplex):
        raise ValueError(f"simplex {tuple(simplex)} has a vertex without a letter among {letters!r}")
    return "".join(letters[v] for v in simplex)


# ------------------------------------------------------------------------------------------ §4.1
def critical_point_table(critical: Sequence[Mapping], *, names: Sequence[str]) -> str:
    """The critical points of the torus's height: parameters, point, value and index (Example 4.2).

    Thesis: Example 4.2 (the critical points r, q₁, q₂, p of the height function).

    Parameters
    ----------
    critical : sequence of mapping
        :func:`thesis_lib.morse.torus_critical_points` (``u``, ``v``, ``point``, ``value``, ``index``).
    names : sequence of str
        A TeX name per point, in the same order.

    Returns
    -------
    str
        A Markdown table, one row per point.

    Raises
    ------
    ValueError
        If ``names`` has not one name per point.

    Examples
    --------
    >>> from thesis_lib.morse import torus_critical_points
    >>> print(critical_point_table(torus_critical_points(), names=["r", "q_1", "q_2", "p"]).splitlines()[2])
    | $r$ | (3.1416, 0.0000) | (0.0, 0.0, -3.0) | -3.000 | 0 |
    """
    if len(names) != len(critical):
        raise ValueError(f"names: one per critical point ({len(critical)}), got {len(names)}")
    rows = [f"| ${name}$ | ({c['u']:.4f}, {c['v']:.4f}) | {tuple(float(x) for x in np.round(c['point'], 6) + 0.0)} "
            f"| {c['value']:+.3f} | {c['index']} |" for c, name in zip(critical, names)]
    return _table("| point | $(u, v)$ | $\\phi(u, v)$ | $h$ | index |\n|---|---|---|---|---|", rows)


def hessian_section(*, R: float = 3.0, r: float = 1.0) -> Section:
    """The Hessians of the torus's height at its four critical points, computed and as printed.

    Thesis: Example 4.2 (diag(−(R+r), −r), diag(−R+r, r), diag(R−r, −r), diag(R+r, r)).

    Parameters
    ----------
    R, r : float, default 3.0 and 1.0
        The torus's radii (with R = 3, r = 1 no two printed entries coincide).

    Returns
    -------
    Section
        A table (central differences beside the printed matrices) and the results
        ``ex42_hessian_<i>``: the entries (0, 0), (1, 1), (0, 1) of each Hessian in turn.

    Raises
    ------
    ValueError
        If ``r`` is not below ``R`` or not positive.

    Examples
    --------
    >>> s = hessian_section()
    >>> [s.results[f"ex42_hessian_{i}"] for i in range(3)]
    [-4.0, -1.0, 0.0]
    """
    R, r = check_torus_radii(R, r)
    points = [(0.0, 0.0), (0.0, np.pi), (np.pi, np.pi), (np.pi, 0.0)]
    printed = [np.diag([-(R + r), -r]), np.diag([-R + r, r]), np.diag([R - r, -r]), np.diag([R + r, r])]
    fd = [finite_difference_hessian(lambda u, v: float(torus_height(u, v, R=R, r=r)), u, v) for u, v in points]
    entries = [round(float(x), 4) + 0.0 for H in fd for x in (H[0, 0], H[1, 1], H[0, 1])]
    rows = [f"| {where} | {(np.round(H, 4) + 0.0).tolist()} | {P.tolist()} |"
            for where, H, P in zip(["$(0, 0)$", "$(0, \\pi)$", "$(\\pi, \\pi)$", "$(\\pi, 0)$"], fd, printed)]
    text = _table("| $(u, v)$ | computed Hessian | printed in the thesis |\n|---|---|---|", rows)
    return Section(texts=(text,), results={f"ex42_hessian_{i}": e for i, e in enumerate(entries)})


def sublevel_section(triangles: Sequence[Simplex], values: Sequence[float], levels: Sequence[float],
                     critical_values: Sequence[tuple[float, int]]) -> Section:
    """The Betti numbers of the sublevel sets Mᵃ of a triangulated surface, level by level.

    Thesis: Theorems 4.4–4.5 (Mᵃ keeps its homotopy type between critical values and gains a
    k-cell at one of index k).

    Parameters
    ----------
    triangles, values, levels, critical_values
        As :func:`thesis_lib.morse.checks.sublevel_level_changes`: the triangles, a value per
        vertex, the increasing levels a and the (value, index) of each critical point.

    Returns
    -------
    Section
        The table of the levels where the Betti numbers change, a sentence on the steps with and
        without a critical value, and the results ``thm44_*``, ``thm45_*``.

    Examples
    --------
    The height on a 12 × 12 grid torus:

    >>> from thesis_lib.morse import checks, torus_critical_points
    >>> tris, pts = checks.torus_grid(12)
    >>> crit = [(c["value"], c["index"]) for c in torus_critical_points()]
    >>> s = sublevel_section(tris, pts[:, 2], np.linspace(-3.5, 3.5, 36), crit)
    >>> s.results["thm44_changes_without_critical"], s.results["thm45_not_one_cell"]
    (0, 0)
    """
    steps = sublevel_level_changes(triangles, values, levels, critical_values)
    rows, prev = [], None
    for a, b in zip(levels, steps["betti"]):
        if b != prev:
            rows.append(f"| {a:+.1f} | {b} |")
        prev = b
    table = _table("| first level $a$ | Betti numbers of $M^a$ |\n|---|---|", rows)
    sentence = (f"{steps['steps_without']} steps between levels pass no critical value: the Betti numbers change at "
                f"{steps['changes_without']}. {steps['steps_with_one']} steps pass one: at {steps['one_cell']} the "
                "change is that of attaching a cell of the critical point's index.")
    return Section(texts=(table, sentence), results=dict(
        thm44_changes_without_critical=steps["changes_without"], thm44_steps=steps["steps_without"],
        thm45_not_one_cell=steps["steps_with_one"] - steps["one_cell"], thm45_steps=steps["steps_with_one"]))


def smooth_inequalities_section(surfaces: Sequence[tuple[Surface, Sequence[int], str]], *,
                                n_functions: int = 10) -> Section:
    """The Morse inequalities for random quadratic functions restricted to surfaces.

    Thesis: Theorems 4.6–4.7 (weak and strong Morse inequalities, the alternating sum).

    Parameters
    ----------
    surfaces : sequence of (Surface, betti, str)
        Each surface with its Betti numbers and a label.
    n_functions : int, default 10
        Functions per surface, :func:`~thesis_lib.morse.checks.random_quadratic_function` of seeds
        0, 1, ...

    Returns
    -------
    Section
        A table of the critical points' counts per surface, the results ``thm46_*``,
        ``thm47_strong_failures`` and the glued ``ch4_thm46_n`` (functions) and ``ch4_thm46_fail``
        (inequalities broken).

    Raises
    ------
    ValueError
        If ``n_functions`` is below 1.

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> s = smooth_inequalities_section([(checks.sphere_surface(), [1, 0, 1], "sphere")], n_functions=1)
    >>> s.results["thm46_functions"], s.glued["ch4_thm46_fail"]
    (1, 0)
    """
    if n_functions < 1:
        raise ValueError(f"n_functions must be at least 1, got {n_functions}")
    failures = {"weak": 0, "euler": 0, "strong": 0}
    rows = []
    for surface, betti, label in surfaces:
        seen: dict[tuple[int, ...], int] = {}
        for seed in range(n_functions):
            f = random_quadratic_function(seed=seed)
            counts = np.bincount([c["index"] for c in surface_critical_points(surface, f, seed=seed)], minlength=3)
            for key, holds in morse_inequalities(counts, betti).items():
                failures[key] += not holds
            seen[tuple(counts.tolist())] = seen.get(tuple(counts.tolist()), 0) + 1
        crit = "; ".join(f"{list(k)} ({v}×)" for k, v in sorted(seen.items()))
        rows.append(f"| {label} | {betti} | {crit} |")
    text = _table("| surface | $\\beta_0, \\beta_1, \\beta_2$ | $\\mathrm{Crit}_0, \\mathrm{Crit}_1, \\mathrm{Crit}_2$ "
                  "(how many functions) |\n|---|---|---|", rows)
    n = len(surfaces) * n_functions
    return Section(texts=(text,), results=dict(
        thm46_functions=n, thm46_weak_failures=failures["weak"], thm46_euler_failures=failures["euler"],
        thm47_strong_failures=failures["strong"]), glued={"ch4_thm46_n": n, "ch4_thm46_fail": sum(failures.values())})


def flow_limits_section(surface: Surface, function: AmbientFunction, critical: Sequence[Mapping], *,
                        names: Sequence[str], n: int = 50, seed: int = 0) -> Section:
    """Where random points flow in forward and backward time: the open stable and unstable sets.

    Thesis: Definition 4.9 and Theorem 4.10 (stable and unstable manifolds, their dimensions).

    Parameters
    ----------
    surface, function : Surface, AmbientFunction
        The surface and the function whose negative gradient flows.
    critical : sequence of mapping
        Its critical points (:func:`~thesis_lib.morse.checks.surface_critical_points`).
    names : sequence of str
        A TeX name per critical point.
    n : int, default 50
        Random starting points.
    seed : int, default 0
        Seed of the starting points.

    Returns
    -------
    Section
        A table of the shares per critical point and the results ``def49_open_*`` (1 when the set
        of the maximum or the minimum holds random points).

    Raises
    ------
    ValueError
        If ``names`` has not one name per critical point.

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> torus, height = checks.torus_surface(), checks.linear_function([0.0, 0.0, 1.0], name="z")
    >>> crit = checks.surface_critical_points(torus, height)
    >>> s = flow_limits_section(torus, height, crit, names=["r", "q_1", "q_2", "p"], n=4)
    >>> s.results["def49_open_backward_max"], s.results["def49_open_forward_max"]
    (1, 0)
    """
    if len(names) != len(critical):
        raise ValueError(f"names: one per critical point ({len(critical)}), got {len(names)}")
    forward, backward = flow_limit_fractions(surface, function, critical, n=n, seed=seed)
    rows = [f"| ${lab}$ | {c['index']} | {fw:.2f} | {bw:.2f} |"
            for lab, c, fw, bw in zip(names, critical, forward, backward)]
    text = _table("| $p$ | index $k$ | share with $\\lim_{t\\to\\infty}\\phi = p$ | share with "
                  "$\\lim_{t\\to-\\infty}\\phi = p$ |\n|---|---|---|---|", rows)
    values = [c["value"] for c in critical]
    i_max, i_min = int(np.argmax(values)), int(np.argmin(values))
    return Section(texts=(text,), results=dict(
        def49_open_backward_max=int(backward[i_max] > 0), def49_open_forward_max=int(forward[i_max] > 0),
        def49_open_backward_min=int(backward[i_min] > 0), def49_open_forward_min=int(forward[i_min] > 0)))


def tilted_morse_complexes(surface: Surface, *, tilts: Sequence[float]) -> dict[float, tuple[list[dict], dict]]:
    """The critical points and Morse complex of the height tilted by each angle about the x-axis.

    Thesis: Example 4.12 (the upright torus is not Morse–Smale; a tilt makes it so).

    Parameters
    ----------
    surface : Surface
        The surface (the torus of Example 4.2).
    tilts : sequence of float
        Angles α: the height becomes cos α z + sin α y.

    Returns
    -------
    dict of float to (list of dict, dict)
        α → (:func:`~thesis_lib.morse.checks.surface_critical_points`,
        :func:`~thesis_lib.morse.checks.surface_morse_complex`).

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> crit, mc = tilted_morse_complexes(checks.torus_surface(), tilts=[0.1])[0.1]
    >>> len(crit), mc["saddle_connection_branches"]
    (4, 0)
    """
    out = {}
    for alpha in tilts:
        f = linear_function([0.0, np.sin(alpha), np.cos(alpha)])
        crit = surface_critical_points(surface, f)
        out[alpha] = (crit, surface_morse_complex(surface, f, crit))
    return out


def saddle_connection_section(upright: Mapping, tilted: Mapping[float, tuple[list[dict], dict]]) -> Section:
    """The saddle branches that end at a saddle, upright and tilted.

    Thesis: Example 4.12 (the unstable manifold of q₂ is the stable manifold of q₁).

    Parameters
    ----------
    upright : mapping
        The Morse complex of the upright height (``saddle_connection_branches``).
    tilted : mapping
        :func:`tilted_morse_complexes`.

    Returns
    -------
    Section
        A table per tilt and the results ``ex412_upright_saddle_branches`` and
        ``ex412_tilted_saddle_branches`` (the most over the tilts).

    Raises
    ------
    ValueError
        If ``tilted`` is empty.

    Examples
    --------
    >>> s = saddle_connection_section({"saddle_connection_branches": 4},
    ...                               {0.1: ([], {"saddle_connection_branches": 0})})
    >>> print(s.texts[0])
    | tilt $\\alpha$ | branches from a saddle to a saddle |
    |---|---|
    | 0 | 4 |
    | 0.1 | 0 |
    """
    if not tilted:
        raise ValueError("tilted: at least one tilt")
    text = ("| tilt $\\alpha$ | branches from a saddle to a saddle |\n|---|---|\n"
            + "\n".join(f"| {a:g} | {m['saddle_connection_branches']} |" for a, m in [(0.0, upright)]
                        + [(a, t[1]) for a, t in tilted.items()]))
    return Section(texts=(text,), results=dict(
        ex412_upright_saddle_branches=upright["saddle_connection_branches"],
        ex412_tilted_saddle_branches=max(t[1]["saddle_connection_branches"] for t in tilted.values())))


def flow_line_counts(critical: Sequence[Mapping], complex_: Mapping) -> list[int]:
    """#M(p, q₁), #M(p, q₂), #M(q₁, r), #M(q₂, r) of a torus function; q₁ is the lower saddle.

    Thesis: Example 4.17 (two flow lines join each pair of consecutive critical points).

    Parameters
    ----------
    critical : sequence of mapping
        The critical points (one of index 0, two of index 1, one of index 2).
    complex_ : mapping
        Their :func:`~thesis_lib.morse.checks.surface_morse_complex`.

    Returns
    -------
    list of int
        The four numbers of flow lines.

    Raises
    ------
    ValueError
        If the critical points are not one minimum, two saddles and one maximum.

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> flow_line_counts(*tilted_morse_complexes(checks.torus_surface(), tilts=[0.1])[0.1])
    [2, 2, 2, 2]
    """
    if [len(level) for level in complex_["names"]] != [1, 2, 1]:
        raise ValueError("the torus's counts need one minimum, two saddles and one maximum")
    q = sorted(range(2), key=lambda j: critical[complex_["names"][1][j]]["value"])
    return [int(complex_["counts"][2][q[0], 0]), int(complex_["counts"][2][q[1], 0]),
            int(complex_["counts"][1][0, q[0]]), int(complex_["counts"][1][0, q[1]])]


def tilted_torus_section(tilted: Mapping[float, tuple[list[dict], dict]], *, alpha: float = 0.1) -> Section:
    """The Morse complex of the tilted torus: flow lines and homology over Z₂ and, with signs, Z.

    Thesis: Example 4.17 (∂p = 2q₂ + 2q₁ = 0, ∂qᵢ = 2r = 0; Betti numbers 1, 2, 1 over Z₂).

    Parameters
    ----------
    tilted : mapping
        :func:`tilted_morse_complexes`, with the tilt ``alpha``.
    alpha : float, default 0.1
        The tilt shown; the others are compared with it.

    Returns
    -------
    Section
        The counts and Betti numbers as text and the results ``ex417_*``.

    Raises
    ------
    ValueError
        If ``alpha`` is not one of the tilts.

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> s = tilted_torus_section(tilted_morse_complexes(checks.torus_surface(), tilts=[0.1]))
    >>> [s.results[f"ex417_betti_{k}"] for k in range(3)]
    [1, 2, 1]
    """
    if alpha not in tilted:
        raise ValueError(f"alpha {alpha} is not one of the tilts {list(tilted)}")
    crit, mc = tilted[alpha]
    lines = flow_line_counts(crit, mc)
    z2 = chain_complex_homology([_EMPTY, mc["counts"][1], mc["counts"][2]], coefficients=2)
    zz = chain_complex_homology([_EMPTY, mc["signed"][1], mc["signed"][2]], coefficients=0)
    same = sum(flow_line_counts(*tilted[a]) == lines for a in tilted if a != alpha)
    text = (f"flow lines: $\\#\\mathcal{{M}}(p, q_1)$ = {lines[0]}, $\\#\\mathcal{{M}}(p, q_2)$ = {lines[1]}, "
            f"$\\#\\mathcal{{M}}(q_1, r)$ = {lines[2]}, $\\#\\mathcal{{M}}(q_2, r)$ = {lines[3]} "
            f"(the same for {same} of the other {len(tilted) - 1} tilts)\n\n"
            f"Betti numbers over $\\mathbb{{Z}}_2$: {_betti(z2)}; over $\\mathbb{{Z}}$, with signs: {_betti(zz)}")
    results = {**{f"ex417_flow_lines_{i}": n for i, n in enumerate(lines)}, "ex417_other_tilts_same": same,
               **{f"ex417_betti_{k}": b for k, b in enumerate(_betti(z2))}}
    return Section(texts=(text,), results=results)


def sphere_morse_section(critical: Sequence[Mapping], complex_: Mapping) -> Section:
    """The Morse complex over Z of a function on the sphere: its critical points, ∂ and homology.

    Thesis: Example 4.18 (h = c₁u² + c₂v² + c₃w² on S²: H₂ ≅ Z, H₁ = 0, H₀ ≅ Z).

    Parameters
    ----------
    critical : sequence of mapping
        The critical points (``point``).
    complex_ : mapping
        Their :func:`~thesis_lib.morse.checks.surface_morse_complex` (two points of each index).

    Returns
    -------
    Section
        The critical points per index, the boundaries and the homology, and the results ``ex418_*``.

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> sphere, h = checks.sphere_surface(), checks.quadratic_function(np.diag([1.0, 2.0, 3.0]))
    >>> crit = checks.surface_critical_points(sphere, h)
    >>> s = sphere_morse_section(crit, checks.surface_morse_complex(sphere, h, crit))
    >>> [s.results[f"ex418_betti_{k}"] for k in range(3)], s.results["ex418_flow_lines"]
    ([1, 0, 1], 8)
    """
    ms = complex_
    pt = {i: "(" + ", ".join(f"{x:g}" for x in np.round(c["point"], 6) + 0.0) + ")" for i, c in enumerate(critical)}
    points = ("| index | critical points |\n|---|---|\n"
              + "\n".join(f"| {k} | {', '.join(pt[i] for i in ms['names'][k])} |" for k in range(3)))
    d1, d2 = ms["signed"][1], ms["signed"][2]
    hom = chain_complex_homology([np.zeros((0, d1.shape[0]), np.int64), d1, d2], coefficients=0)
    text = (f"$\\partial_2$ = {d2.tolist()}, $\\partial_1$ = {d1.tolist()}, $\\partial_1\\partial_2$ = "
            f"{(d1 @ d2).tolist()}\n\n$H_k$ over $\\mathbb{{Z}}$: Betti numbers {_betti(hom)}, torsion "
            f"{[t for _, t in hom]}")
    results = {**{f"ex418_crit_{k}": len(ms["names"][k]) for k in range(3)},
               "ex418_flow_lines": int(ms["counts"][1].sum() + ms["counts"][2].sum()),
               "ex418_max_lines_per_pair": int(max(ms["counts"][1].max(), ms["counts"][2].max())),
               "ex418_dd_nonzero": int(np.count_nonzero(d1 @ d2)),
               "ex418_dd_mod2_nonzero": int(np.count_nonzero((ms["counts"][1] @ ms["counts"][2]) % 2)),
               **{f"ex418_betti_{k}": b for k, b in enumerate(_betti(hom))},
               "ex418_torsion_count": sum(len(t) for _, t in hom)}
    return Section(texts=(points, text), results=results)


def rp2_quotient_section(critical: Sequence[Mapping], complex_: Mapping, *, facets: Sequence[Simplex]) -> Section:
    """The Morse complex of ℝP² over Z₂ from the sphere's flow lines (antipodal points identified).

    Thesis: Example 4.19 (two flow lines p → q and q → r; ℝP²'s homology over Z₂).

    Parameters
    ----------
    critical, complex_
        The sphere's critical points and Morse complex (:func:`sphere_morse_section`'s input).
    facets : sequence of simplex
        A triangulation of ℝP², for its simplicial homology.

    Returns
    -------
    Section
        The counts and Betti numbers, and the results ``ex419_lines_*``, ``ex419_betti_*``.

    Examples
    --------
    >>> from thesis_lib.morse import RP2_FACETS, checks
    >>> sphere, h = checks.sphere_surface(), checks.quadratic_function(np.diag([1.0, 2.0, 3.0]))
    >>> crit = checks.surface_critical_points(sphere, h)
    >>> s = rp2_quotient_section(crit, checks.surface_morse_complex(sphere, h, crit), facets=RP2_FACETS)
    >>> s.results["ex419_lines_p_q"], [s.results[f"ex419_betti_{k}"] for k in range(3)]
    (2, [1, 1, 1])
    """
    counts = antipodal_quotient_counts(critical, complex_)
    hom = chain_complex_homology([_EMPTY, counts[1], counts[2]], coefficients=2)
    text = (f"flow lines $p \\to q$: {int(counts[2][0, 0])}, $q \\to r$: {int(counts[1][0, 0])}; "
            f"Betti numbers over $\\mathbb{{Z}}_2$: {_betti(hom)} "
            f"(simplicial, over $\\mathbb{{Z}}_2$: {betti_numbers(facets, coefficients=2)})")
    results = {"ex419_lines_p_q": int(counts[2][0, 0]), "ex419_lines_q_r": int(counts[1][0, 0]),
               **{f"ex419_betti_{k}": b for k, b in enumerate(_betti(hom))}}
    return Section(texts=(text,), results=results)


# ------------------------------------------------------------------------------------------ §4.2
def example_4_23_section(good: Mapping[Simplex, float], bad: Mapping[Simplex, float]) -> Section:
    """A discrete Morse function and a function that breaks both conditions, on one complex.

    Thesis: Definitions 4.20–4.21 and Example 4.23 (Figure 4.3).

    Parameters
    ----------
    good : mapping of simplex to float
        A discrete Morse function (the right of Figure 4.3).
    bad : mapping of simplex to float
        A function that is not one (the left).

    Returns
    -------
    Section
        A sentence on each and the results ``ex423_*`` (the critical values of ``good``).

    Raises
    ------
    ValueError
        If ``good`` is not a discrete Morse function or ``bad`` is one.

    Examples
    --------
    >>> good = {(0,): 0, (1,): 2, (2,): 3, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5}
    >>> bad = {(0,): 1, (1,): 2, (2,): 5, (0, 1): 0, (1, 2): 3, (0, 2): 4}
    >>> example_4_23_section(good, bad).results["ex423_right_n_critical"]
    2
    """
    check_discrete_morse_function(good)
    if is_discrete_morse_function(bad):
        raise ValueError("bad: expected a function that is not a discrete Morse function")
    right = (f"right: discrete Morse function: {is_discrete_morse_function(good)}; critical: "
             + ", ".join(f"{s} with value {good[s]:g}" for s in critical_simplices(good))
             + f"; gradient pairs: {gradient_pairs(good)}")
    try:
        check_discrete_morse_function(bad)
    except ValueError as err:
        left = f"left: discrete Morse function: {is_discrete_morse_function(bad)}. {err}."
    values = sorted(good[s] for s in critical_simplices(good))
    return Section(texts=(right, left), results={
        "ex423_left_is_morse": int(is_discrete_morse_function(bad)), "ex423_right_n_critical": len(values),
        **{f"ex423_right_critical_value_{i}": v for i, v in enumerate(values)}})


def lemma_4_22_section(functions: Sequence[Mapping[Simplex, float]]) -> Section:
    """Conditions (4.4) and (4.5) at every simplex of discrete Morse functions, and where the minimum is.

    Thesis: Lemma 4.22 ((4.4) and (4.5) exclude each other) and §4.2.1 (the minimum is at a vertex).

    Parameters
    ----------
    functions : sequence of mapping
        Discrete Morse functions.

    Returns
    -------
    Section
        A sentence and the results ``lem422_*`` and ``sec421_min_not_at_vertex``.

    Examples
    --------
    >>> s = lemma_4_22_section([{(0,): 0, (1,): 2, (2,): 3, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5}])
    >>> s.results
    {'lem422_both': 0, 'lem422_simplices': 6, 'sec421_min_not_at_vertex': 0}
    """
    lemma = [lemma_4_22_count(dict(f)) for f in functions]
    n_checked, n_both = sum(n for n, _, _ in lemma), sum(b for _, b, _ in lemma)
    n_min_vertex = sum(v for _, _, v in lemma)
    text = (f"{n_checked} simplices of {len(functions)} functions: {n_both} satisfy both (4.4) and (4.5); "
            f"the minimum is at a vertex for {n_min_vertex} of the {len(functions)} functions")
    return Section(texts=(text,), results=dict(lem422_both=n_both, lem422_simplices=n_checked,
                                               sec421_min_not_at_vertex=len(functions) - n_min_vertex))


def discrete_sublevel_section(values: Mapping[Simplex, float],
                              functions: Sequence[Mapping[Simplex, float]]) -> Section:
    """The sublevel complexes Kᵃ of a discrete Morse function, and their changes over many.

    Thesis: Theorems 4.25–4.26 (Kᵃ changes only at critical values, as attaching one cell does).

    Parameters
    ----------
    values : mapping of simplex to float
        The function tabulated value by value (at each critical value and each change).
    functions : sequence of mapping
        The functions counted over (:func:`~thesis_lib.morse.checks.sublevel_changes`).

    Returns
    -------
    Section
        The table of ``values``, a sentence on ``functions`` and the results ``thm425_*``, ``thm426_*``.

    Examples
    --------
    >>> good = {(0,): 0, (1,): 2, (2,): 3, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5}
    >>> s = discrete_sublevel_section(good, [good])
    >>> s.results["thm426_critical"], s.results["thm425_regular_changes"]
    (2, 0)
    """
    critical = set(critical_simplices(values))
    prev, rows = None, []
    for s, a in sorted(values.items(), key=lambda kv: kv[1]):
        betti = betti_numbers(sublevel_complex(values, a), coefficients=2)
        betti += [0] * (3 - len(betti))
        if s in critical or betti != prev:
            kind = "critical" if s in critical else "regular"
            rows.append(f"| {a:.0f} | ${simplex_name(s)}$ | {kind} | {betti} |")
        prev = betti
    table = _table("| $a$ | simplex | kind | Betti numbers of $K^a$ over $\\mathbb{Z}_2$ |\n|---|---|---|---|", rows)
    changes = {"regular": 0, "critical": 0, "regular_changes": 0, "one_cell": 0}
    for f in functions:
        for key, value in sublevel_changes(dict(f)).items():
            changes[key] += value
    sentence = (f"{_samples(len(functions))}: {changes['regular']} regular values, at {changes['regular_changes']} of "
                f"which the Betti numbers change; {changes['critical']} critical values, at {changes['one_cell']} "
                "of which exactly one Betti number moves by one.")
    return Section(texts=(table, sentence), results=dict(
        thm425_regular_changes=changes["regular_changes"], thm425_regular=changes["regular"],
        thm426_not_one_cell=changes["critical"] - changes["one_cell"], thm426_critical=changes["critical"]))


def discrete_inequalities_section(samples: Sequence[tuple[str, list[Simplex], Pairs]]) -> Section:
    """The discrete Morse inequalities over gradient samples, and the samples with two critical simplices.

    Thesis: Theorems 4.27–4.28 and Example 4.29.

    Parameters
    ----------
    samples : sequence of (str, complex, pairs)
        :func:`~thesis_lib.morse.checks.gradient_samples`.

    Returns
    -------
    Section
        A table (holds on, strict on), the results ``thm427_*``, ``thm428_*``, ``ex429_*`` and the
        glued ``ch4_two_n``, ``ch4_two_sphere``.

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> s = discrete_inequalities_section(checks.gradient_samples(4, seed=0))
    >>> s.results["thm427_weak_failures"], s.results["thm427_euler_strict"]
    (0, 0)
    """
    survey = morse_inequality_survey(samples)
    n = survey["n"]
    text = (f"| statement | holds on | strict on |\n|---|---|---|\n"
            f"| $\\beta_k \\le \\mathrm{{Crit}}^d_k$ for all $k$ | {survey['weak']} of {n} "
            f"| {survey['weak_strict']} |\n"
            f"| $\\sum_k (-1)^k\\beta_k \\le \\sum_k (-1)^k\\mathrm{{Crit}}^d_k$ | {survey['euler_le']} of {n} "
            f"| {survey['euler_strict']} |\n"
            f"| strong inequalities (Theorem 4.28) | {survey['strong']} of {n} | {survey['strong_strict']} |")
    two = two_critical_survey(samples)
    return Section(texts=(text,), results=dict(
        thm427_weak_failures=n - survey["weak"], thm427_euler_strict=survey["euler_strict"],
        thm427_euler_failures=n - survey["euler_le"], thm428_strong_failures=n - survey["strong"],
        thm427_weak_strict=survey["weak_strict"], thm428_strong_strict=survey["strong_strict"],
        ex429_two_critical=two["n"], ex429_no_vertex=two["n"] - two["with_vertex"],
        ex429_not_sphere=two["n"] - two["sphere_homology"]),
        glued={"ch4_two_n": two["n"], "ch4_two_sphere": two["sphere_homology"]})


def flow_matrices_section(values: Mapping[Simplex, float]) -> Section:
    """The matrices of V and Φ = 1 + ∂V + V∂ of a discrete Morse function, and two of their identities.

    Thesis: Definitions 4.30–4.31 and Proposition 4.37 (V∘V = 0, Φ∂ = ∂Φ).

    Parameters
    ----------
    values : mapping of simplex to float
        A discrete Morse function on a complex with at most six vertices (named a, b, ...).

    Returns
    -------
    Section
        The tables of V and Φ (column j the image of the j-th simplex) and a line on the identities.

    Examples
    --------
    >>> good = {(0,): 0, (1,): 2, (2,): 3, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5}
    >>> print(flow_matrices_section(good).texts[2])
    $V\\circ V = 0$: True; $\\Phi\\partial = \\partial\\Phi$ (Proposition 4.37): True
    """
    simplices = list(values)
    pairs = gradient_pairs(values)
    V = gradient_matrix(simplices, pairs).toarray()
    Phi = gradient_flow(simplices, pairs).toarray()
    names = [simplex_name(s) for s in cells(simplices)]
    head = "| | " + " | ".join(f"${n}$" for n in names) + " |\n|---|" + "---|" * len(names) + "\n"
    texts = tuple(f"{title}, column $j$ the image of the $j$-th simplex:\n\n" + head
                  + "\n".join(f"| ${n}$ | " + " | ".join(str(int(x)) for x in row) + " |" for n, row in zip(names, M))
                  for title, M in (("V", V), ("Φ", Phi)))
    D = boundary_operator(simplices).toarray()
    identities = (f"$V\\circ V = 0$: {not (V @ V).any()}; $\\Phi\\partial = \\partial\\Phi$ (Proposition 4.37): "
                  f"{np.array_equal(Phi @ D, D @ Phi)}")
    return Section(texts=(*texts, identities))


def vector_field_section(functions: Sequence[Mapping[Simplex, float]],
                         samples: Sequence[tuple[str, list[Simplex], Pairs]], *, fields_per_sample: int = 3,
                         fraction: float = 0.7) -> Section:
    """Proposition 4.32 on discrete Morse functions; the two acyclicity tests on random vector fields.

    Thesis: Proposition 4.32, Theorems 4.36 and 4.44 (closed V-paths and the modified Hasse diagram).

    Parameters
    ----------
    functions : sequence of mapping
        Discrete Morse functions (:func:`~thesis_lib.morse.checks.proposition_4_32_violations`).
    samples : sequence of (str, complex, pairs)
        Complexes to draw random vector fields on.
    fields_per_sample : int, default 3
        Fields per complex; field ``s`` of sample ``i`` has seed ``100 i + s``.
    fraction : float, default 0.7
        :func:`~thesis_lib.morse.checks.random_vector_field`'s share of paired simplices.

    Returns
    -------
    Section
        Two paragraphs and the results ``prop432_*``, ``thm444_*``, ``thm436_not_gradient``.

    Raises
    ------
    ValueError
        If ``fields_per_sample`` is below 1.

    Examples
    --------
    >>> from thesis_lib.morse import checks, discrete_morse_function
    >>> samples = checks.gradient_samples(2, seed=0)
    >>> functions = [discrete_morse_function(cx, pairs) for _, cx, pairs in samples]
    >>> s = vector_field_section(functions, samples)
    >>> s.results["prop432_violations"], s.results["thm444_disagreements"], s.results["thm444_fields"]
    (0, 0, 6)
    """
    if fields_per_sample < 1:
        raise ValueError(f"fields_per_sample must be at least 1, got {fields_per_sample}")
    viol = {"not_a_field": 0, "vv_nonzero": 0, "critical_mismatch": 0, "n": 0}
    for f in functions:
        for key, value in proposition_4_32_violations(dict(f)).items():
            viol[key] += value
    n_fields = n_cyclic = n_disagree = n_not_gradient = 0
    for i, (_, cx, _) in enumerate(samples):
        for s in range(fields_per_sample):
            vf = random_vector_field(cx, seed=100 * i + s, fraction=fraction)
            acyclic = is_acyclic(cx, vf)
            n_fields += 1
            n_cyclic += not acyclic
            n_disagree += acyclic != is_acyclic(cx, vf, method="hasse")
            if acyclic:
                n_not_gradient += sorted(gradient_pairs(discrete_morse_function(cx, vf))) != sorted(vf)
    text = (f"Proposition 4.32 over {viol['n']} simplices, $V$ read off the functions' values: {viol['not_a_field']} "
            f"functions whose pairs put a simplex in two, {viol['vv_nonzero']} nonzero entries of $V\\circ V$, "
            f"{viol['critical_mismatch']} mismatches of the critical simplices.\n\n"
            f"{n_fields} random vector fields, {n_cyclic} with a closed V-path: the two tests disagree on "
            f"{n_disagree}; {n_not_gradient} acyclic fields are not the gradient of the function built from them.")
    return Section(texts=(text,), results=dict(
        prop432_violations=viol["not_a_field"] + viol["vv_nonzero"] + viol["critical_mismatch"],
        prop432_simplices=viol["n"], thm444_disagreements=n_disagree, thm444_fields=n_fields,
        thm444_cyclic=n_cyclic, thm436_not_gradient=n_not_gradient))


def _critical_ids(simplices, pairs) -> list[int]:
    basis = cells(simplices)
    return [basis.index(s) for dim in critical_cells(simplices, pairs) for s in dim]


def rp2_stabilisation_section(facets: Sequence[Simplex], pairs: Pairs) -> Section:
    """When Φᴺ stops changing on a complex, and Φ^∞ on its critical simplices.

    Thesis: Theorems 4.38–4.41 and Proposition 4.40 (Φ^∞ is the identity on the critical simplices).

    Parameters
    ----------
    facets : sequence of simplex
        The complex (ℝP² on the page), faces named a, b, ...
    pairs : iterable of (sigma, tau)
        An acyclic gradient field on it.

    Returns
    -------
    Section
        A sentence and the glued ``ch4_stabilisation_N``.

    Examples
    --------
    >>> from thesis_lib.morse import RP2_FACETS, rp2_gradient_field
    >>> rp2_stabilisation_section(RP2_FACETS, rp2_gradient_field()).glued
    {'ch4_stabilisation_N': 7}
    """
    inf, N = stabilised_flow(facets, pairs)
    phi = gradient_flow(facets, pairs)
    crit_cells = [s for dim in critical_cells(facets, pairs) for s in dim]
    idx = _critical_ids(facets, pairs)
    block = inf[idx][:, idx].toarray()
    text = (f"$\\Phi^N = \\Phi^{{N+1}}$ from $N$ = {N}; $\\Phi\\Phi^\\infty = \\Phi^\\infty$: "
            f"{not (phi @ inf - inf).toarray().any()}; "
            f"$\\langle\\Phi^\\infty(\\sigma), \\sigma'\\rangle$ on the critical simplices "
            f"{', '.join('$' + simplex_name(s) + '$' for s in crit_cells)} (Proposition 4.40): {block.tolist()}")
    return Section(texts=(text,), glued={"ch4_stabilisation_N": N})


def stabilisation_section(samples: Sequence[tuple[str, list[Simplex], Pairs]]) -> Section:
    """Stabilisation of Φ, Φ^∞ on the critical simplices and the homology of C^Φ over gradient samples.

    Thesis: Theorems 4.38–4.42, Propositions 4.37 and 4.40.

    Parameters
    ----------
    samples : sequence of (str, complex, pairs)
        :func:`~thesis_lib.morse.checks.gradient_samples`.

    Returns
    -------
    Section
        A sentence and the results ``thm438_*``, ``thm439_*``, ``thm441_*``, ``thm442_*``,
        ``prop437_nonzero`` and ``prop440_not_identity``.

    Raises
    ------
    ValueError
        If Φ stabilises on none of the samples.

    Examples
    --------
    >>> from thesis_lib.morse import checks
    >>> s = stabilisation_section(checks.gradient_samples(2, seed=0))
    >>> s.results["thm442_homology_mismatches"], s.results["prop437_nonzero"]
    (0, 0)
    """
    mismatch_rank = mismatch_betti = mismatch_morse = not_stabilised = not_identity = commutator = 0
    steps: list[int] = []
    for _, cx, pairs in samples:
        try:
            inv = flow_invariant_homology(cx, pairs, coefficients=2)
        except ValueError:
            not_stabilised += 1
            continue
        steps += inv["n_steps"]
        inf_s, _ = stabilised_flow(cx, pairs)
        idx = _critical_ids(cx, pairs)
        not_identity += not np.array_equal(inf_s[idx][:, idx].toarray(), np.eye(len(idx)))
        phi_s, d_s = gradient_flow(cx, pairs), boundary_operator(cx)
        commutator += int(np.count_nonzero((phi_s @ d_s - d_s @ phi_s).toarray()))
        mismatch_rank += inv["rank"] != critical_counts(cx, pairs)
        mismatch_betti += inv["betti"] != betti_numbers(cx, coefficients=2)
        mismatch_morse += morse_homology(cx, pairs) != homology(cx)
    if not steps:
        raise ValueError("the flow stabilises on none of the samples")
    text = (f"{_samples(len(samples))} $\\Phi$ stabilises after {min(steps)} to {max(steps)} steps "
            f"(it fails to on {not_stabilised}); $\\Phi\\partial - \\partial\\Phi$ has {commutator} nonzero entries; "
            f"$\\Phi^\\infty$ is not the identity on the critical simplices on {not_identity}; "
            f"$\\operatorname{{rank}} C^\\Phi_k \\ne \\mathrm{{Crit}}_k$ on {mismatch_rank}, "
            f"$H_*(C^\\Phi; \\mathbb{{Z}}_2) \\ne H_*(K; \\mathbb{{Z}}_2)$ on {mismatch_betti}, and the Morse complex "
            f"of gradient paths (Theorem 4.42) has another integer homology than $K$ on {mismatch_morse}.")
    return Section(texts=(text,), results=dict(
        thm438_max_steps=max(steps), thm438_not_stabilised=not_stabilised, thm441_rank_mismatches=mismatch_rank,
        thm439_homology_mismatches=mismatch_betti, thm442_homology_mismatches=mismatch_morse,
        prop440_not_identity=not_identity, prop437_nonzero=commutator))


def gradient_path_table(facets: Sequence[Simplex], pairs: Pairs,
                        ends: Sequence[tuple[Simplex, Simplex]]) -> str:
    """The gradient paths between critical simplices, with their multiplicities.

    Thesis: Example 4.43 (the paths from σ = ac to a cancel; those from τ = ace to σ add up).

    Parameters
    ----------
    facets : sequence of simplex
        The complex, vertices named a, b, ...
    pairs : iterable of (sigma, tau)
        The gradient field.
    ends : sequence of (tau, sigma)
        The critical simplices the paths run from and to.

    Returns
    -------
    str
        A Markdown table, one row per path.

    Examples
    --------
    >>> from thesis_lib.morse import RP2_FACETS, rp2_gradient_field
    >>> print(gradient_path_table(RP2_FACETS, rp2_gradient_field(), [((0, 2), (0,))]).splitlines()[2])
    | $ac \\to a$ | $ac$ $a$ | -1 |
    """
    rows = [f"| ${simplex_name(tau)} \\to {simplex_name(sigma)}$ "
            f"| {' '.join('$' + simplex_name(s) + '$' for s in path)} | {m:+d} |"
            for tau, sigma in ends for path, m in gradient_paths(facets, pairs, tau, sigma)]
    return _table("| from, to | gradient path | multiplicity |\n|---|---|---|", rows)


def rp2_morse_complex_section(facets: Sequence[Simplex], pairs: Pairs) -> Section:
    """The Morse complex of a gradient field: its boundary matrices and homology beside the simplicial one.

    Thesis: Example 4.43 and Theorem 4.42 (Z →2 Z →0 Z, H₁(ℝP²) = Z/2).

    Parameters
    ----------
    facets : sequence of simplex
        The complex (ℝP² on the page).
    pairs : iterable of (sigma, tau)
        An acyclic gradient field on it with one critical simplex in each of dimensions 0, 1, 2.

    Returns
    -------
    Section
        A sentence and the glued ``ch4_rp2_torsion`` (the torsion coefficient of H₁).

    Raises
    ------
    ValueError
        If H₁ of the Morse complex has no torsion.

    Examples
    --------
    >>> from thesis_lib.morse import RP2_FACETS, rp2_gradient_field
    >>> rp2_morse_complex_section(RP2_FACETS, rp2_gradient_field()).glued
    {'ch4_rp2_torsion': 2}
    """
    _, mats = morse_boundary(facets, pairs)
    hom = morse_homology(facets, pairs)
    if len(hom) < 2 or not hom[1][1]:
        raise ValueError("H_1 of the Morse complex has no torsion")
    text = (f"Morse complex: $\\tilde\\partial_2$ = {mats[2].toarray().tolist()}, "
            f"$\\tilde\\partial_1$ = {mats[1].toarray().tolist()}; $H_k$ over $\\mathbb{{Z}}$: {hom}; "
            f"simplicial homology: {homology(facets)}")
    return Section(texts=(text,), glued={"ch4_rp2_torsion": hom[1][1][0]})


def heuristic_table(complexes: Sequence[tuple[str, Sequence[Simplex]]], *,
                    heuristics: Sequence[str] = ("coreduction", "collapse")) -> str:
    """The critical simplices the greedy heuristics leave on named complexes, with their homology.

    Thesis: §4.2.6 (finding a field with the fewest critical simplices is NP-hard; heuristics).

    Parameters
    ----------
    complexes : sequence of (str, complex)
        A name (Markdown) and the facets.
    heuristics : sequence of str, default ("coreduction", "collapse")
        :func:`~thesis_lib.morse.morse_matching`'s heuristics to compare.

    Returns
    -------
    str
        A Markdown table: simplices, critical per dimension, Betti numbers over Z₂ and whether the
        Morse homology over Z is the simplicial one.

    Examples
    --------
    >>> from thesis_lib import datasets
    >>> print(heuristic_table([("torus", datasets.torus())], heuristics=["collapse"]).splitlines()[2])
    | torus | collapse | 42 | [1, 2, 1] | [1, 2, 1] | True |
    """
    rows = []
    for name, cx in complexes:
        betti = betti_numbers(cx, coefficients=2)
        for method in heuristics:
            p = morse_matching(cx, heuristic=method)
            same = morse_homology(cx, p) == homology(cx)
            rows.append(f"| {name} | {method} | {sum(critical_counts(cx, []))} | {critical_counts(cx, p)} "
                        f"| {betti} | {same} |")
    return _table("| complex | heuristic | simplices | critical per dimension | Betti over $\\mathbb{Z}_2$ "
                  "| Morse = simplicial over $\\mathbb{Z}$ |\n|---|---|---|---|---|---|", rows)


def reduction_benchmark_section(rows: Sequence[Mapping]) -> Section:
    """The stored Morse-reduction benchmark: cells, the share left critical and the barcode check.

    Thesis: §4.2.6 and the Summary (reducing complexes too large to be stored).

    Parameters
    ----------
    rows : sequence of mapping
        The benchmark's rows (``case``, ``n_cells``, ``critical_fraction``, ``same_barcode``),
        with ``two-circles`` and ``lower-star`` cases.

    Returns
    -------
    Section
        The table and the glued ``ch4_rips_critical_pct`` (the fewest critical on the Rips cases)
        and ``ch4_star_critical_pct`` (the most on the lower-star cases), as whole percents.

    Raises
    ------
    ValueError
        If there is no ``two-circles`` or no ``lower-star`` case.

    Examples
    --------
    >>> rows = [dict(case="two-circles-a", n_cells=10, critical_fraction=0.5, same_barcode=True),
    ...         dict(case="lower-star-b", n_cells=20, critical_fraction=0.1, same_barcode=True)]
    >>> reduction_benchmark_section(rows).glued
    {'ch4_rips_critical_pct': '50', 'ch4_star_critical_pct': '10'}
    """
    rips = [100 * r["critical_fraction"] for r in rows if r["case"].startswith("two-circles")]
    star = [100 * r["critical_fraction"] for r in rows if r["case"].startswith("lower-star")]
    if not rips or not star:
        raise ValueError("the benchmark needs two-circles and lower-star cases")
    text = ("| case | cells | critical | same barcode |\n|---|---|---|---|\n"
            + "\n".join(f"| {r['case']} | {r['n_cells']} | {100 * r['critical_fraction']:.1f} % | {r['same_barcode']} |"
                        for r in rows))
    return Section(texts=(text,), glued={"ch4_rips_critical_pct": f"{min(rips):.0f}",
                                         "ch4_star_critical_pct": f"{max(star):.0f}"})

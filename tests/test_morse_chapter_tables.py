"""The tables and checks of the chapter 4 page (thesis_lib.chapters.morse_tables) and its two new figures."""

from __future__ import annotations

import itertools
import re

import matplotlib

matplotlib.use("Agg")
import gudhi  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import networkx as nx  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.text import Annotation  # noqa: E402

from thesis_lib import datasets  # noqa: E402
from thesis_lib.chapters import morse_tables as tables  # noqa: E402
from thesis_lib.homology import homology  # noqa: E402
from thesis_lib.morse import RP2_FACETS, checks
from thesis_lib.morse.examples import example_4_45, rp2_gradient_field
from thesis_lib.morse.flow import cells, gradient_flow
from thesis_lib.morse.functions import critical_simplices, discrete_morse_function, sublevel_complex
from thesis_lib.morse.matching import critical_counts, morse_matching
from thesis_lib.morse.morse_complex import morse_boundary
from thesis_lib.morse.plotting import hasse_figure, torus_height_figure
from thesis_lib.morse.smooth import torus_critical_points, torus_height_hessian

GOOD = {(0,): 0, (1,): 2, (2,): 3, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5}
BAD = {(0,): 1, (1,): 2, (2,): 5, (0, 1): 0, (1, 2): 3, (0, 2): 4}


def gudhi_betti(simplices, *, top: int = 2, field: int = 2) -> list[int]:
    """Betti numbers over Z/field from GUDHI (an independent engine), padded to dimension ``top``."""
    st = gudhi.SimplexTree()
    for s in simplices:
        st.insert(list(s))
    st.compute_persistence(homology_coeff_field=field, persistence_dim_max=True)
    b = list(st.betti_numbers())
    return (b + [0] * (top + 1))[: top + 1]


def table_rows(text: str) -> list[list[str]]:
    """The body cells of a Markdown table (header and rule dropped)."""
    lines = [line for line in text.splitlines() if line.startswith("|")]
    return [[c.strip() for c in line.strip("|").split("|")] for line in lines[2:]]


@pytest.fixture(scope="module")
def samples():
    return checks.gradient_samples(6, seed=3)


@pytest.fixture(scope="module")
def functions(samples):
    return [discrete_morse_function(cx, pairs) for _, cx, pairs in samples]


@pytest.fixture(scope="module")
def sphere_complex():
    sphere, h = checks.sphere_surface(), checks.quadratic_function(np.diag([1.0, 2.0, 3.0]))
    crit = checks.surface_critical_points(sphere, h)
    return crit, checks.surface_morse_complex(sphere, h, crit)


@pytest.fixture(scope="module")
def tilted():
    return tables.tilted_morse_complexes(checks.torus_surface(), tilts=[0.1, 0.2])


def test_simplex_name():
    assert tables.simplex_name((0, 2, 4)) == "ace"
    assert tables.simplex_name((1, 2), letters="xyz") == "yz"
    with pytest.raises(ValueError, match="without a letter"):
        tables.simplex_name((0, 6))


def test_critical_point_table_has_the_heights_and_indices_of_the_torus():
    crit = torus_critical_points(R=2.0, r=1.0)
    rows = table_rows(tables.critical_point_table(crit, names=["r", "q_1", "q_2", "p"]))
    assert [row[0] for row in rows] == ["$r$", "$q_1$", "$q_2$", "$p$"]
    # h = cos u (R + r cos v) at the critical points: -(R + r), -(R - r), R - r, R + r
    assert [float(row[3]) for row in rows] == [-3.0, -1.0, 1.0, 3.0]
    assert [int(row[4]) for row in rows] == [0, 1, 1, 2]
    with pytest.raises(ValueError, match="one per critical point"):
        tables.critical_point_table(crit, names=["r"])


def test_hessian_section_matches_the_analytic_hessian_and_the_printed_one():
    R, r = 3.0, 1.0
    s = tables.hessian_section(R=R, r=r)
    points = [(0.0, 0.0), (0.0, np.pi), (np.pi, np.pi), (np.pi, 0.0)]
    printed = [(-(R + r), -r), (-R + r, r), (R - r, -r), (R + r, r)]
    for i, ((u, v), diag) in enumerate(zip(points, printed)):
        exact = np.asarray(torus_height_hessian(u, v, R=R, r=r)).reshape(2, 2)
        got = [s.results[f"ex42_hessian_{3 * i + j}"] for j in range(3)]
        assert np.allclose(got, [exact[0, 0], exact[1, 1], exact[0, 1]], atol=1e-3)
        assert np.allclose(got[:2], diag, atol=1e-3)
    assert len(s.results) == 12 and len(table_rows(s.texts[0])) == 4
    with pytest.raises(ValueError, match="0 < r < R"):
        tables.hessian_section(R=1.0, r=2.0)


def test_sublevel_section_rows_agree_with_gudhi():
    tris, pts = checks.torus_grid(10)
    crit = [(c["value"], c["index"]) for c in torus_critical_points()]
    levels = np.linspace(-3.5, 3.5, 36)
    s = tables.sublevel_section(tris, pts[:, 2], levels, crit)
    rows = table_rows(s.texts[0])
    assert rows[0][0] == "-3.5" and rows[-1][1] == "[1, 2, 1]"
    faces = {f for t in tris for k in (1, 2, 3) for f in itertools.combinations(t, k)}
    for a, betti in rows:
        level = levels[np.argmin(np.abs(levels - float(a)))]
        assert gudhi_betti([f for f in faces if max(pts[list(f), 2]) <= level]) == eval(betti)
    assert s.results["thm44_changes_without_critical"] == 0 and s.results["thm45_not_one_cell"] == 0
    assert s.results["thm44_steps"] + s.results["thm45_steps"] <= len(levels) - 1


def test_smooth_inequalities_section_on_the_sphere():
    s = tables.smooth_inequalities_section([(checks.sphere_surface(), [1, 0, 1], "sphere")], n_functions=3)
    assert s.results == dict(thm46_functions=3, thm46_weak_failures=0, thm46_euler_failures=0,
                             thm47_strong_failures=0)
    assert s.glued == {"ch4_thm46_n": 3, "ch4_thm46_fail": 0}
    (row,) = table_rows(s.texts[0])
    counts = re.findall(r"\[(\d+), (\d+), (\d+)\] \((\d+)×\)", row[2])
    assert sum(int(n) for *_, n in counts) == 3
    assert all(int(c0) - int(c1) + int(c2) == 2 for c0, c1, c2, _ in counts)  # χ(S²)
    with pytest.raises(ValueError, match="at least 1"):
        tables.smooth_inequalities_section([], n_functions=0)


def test_flow_limits_section_every_point_flows_to_the_extremes():
    torus, height = checks.torus_surface(), checks.linear_function([0.0, 0.0, 1.0], name="z")
    crit = checks.surface_critical_points(torus, height)
    s = tables.flow_limits_section(torus, height, crit, names=["r", "q_1", "q_2", "p"], n=6, seed=1)
    rows = table_rows(s.texts[0])
    assert [row[2] for row in rows] == ["1.00", "0.00", "0.00", "0.00"]  # forward: all to the minimum r
    assert [row[3] for row in rows] == ["0.00", "0.00", "0.00", "1.00"]  # backward: all to the maximum p
    assert s.results == dict(def49_open_backward_max=1, def49_open_forward_max=0, def49_open_backward_min=0,
                             def49_open_forward_min=1)
    with pytest.raises(ValueError, match="one per critical point"):
        tables.flow_limits_section(torus, height, crit, names=["r"])


def test_saddle_connections_upright_and_tilted(tilted):
    torus, height = checks.torus_surface(), checks.linear_function([0.0, 0.0, 1.0], name="z")
    upright = checks.surface_morse_complex(torus, height, checks.surface_critical_points(torus, height))
    s = tables.saddle_connection_section(upright, tilted)
    assert table_rows(s.texts[0]) == [["0", "4"], ["0.1", "0"], ["0.2", "0"]]
    assert s.results == dict(ex412_upright_saddle_branches=4, ex412_tilted_saddle_branches=0)
    with pytest.raises(ValueError, match="at least one tilt"):
        tables.saddle_connection_section(upright, {})


def test_flow_line_counts_order_the_saddles_by_value():
    crit = [dict(value=-3.0), dict(value=1.0), dict(value=-1.0), dict(value=3.0)]
    mc = dict(names=[[0], [1, 2], [3]], counts=[None, np.array([[5, 7]]), np.array([[11], [13]])])
    # q_1 is critical point 2 (the lower saddle), the second column and row
    assert tables.flow_line_counts(crit, mc) == [13, 11, 7, 5]
    with pytest.raises(ValueError, match="two saddles"):
        tables.flow_line_counts(crit, dict(mc, names=[[0], [1], [3]]))


def test_tilted_torus_section_has_the_torus_homology(tilted):
    s = tables.tilted_torus_section(tilted, alpha=0.1)
    assert [s.results[f"ex417_flow_lines_{i}"] for i in range(4)] == [2, 2, 2, 2]
    assert s.results["ex417_other_tilts_same"] == 1
    assert [s.results[f"ex417_betti_{k}"] for k in range(3)] == gudhi_betti(datasets.torus())
    assert "with signs: [1, 2, 1]" in s.texts[0]
    with pytest.raises(ValueError, match="not one of the tilts"):
        tables.tilted_torus_section(tilted, alpha=0.3)


def test_sphere_morse_section_has_the_sphere_homology(sphere_complex):
    s = tables.sphere_morse_section(*sphere_complex)
    assert [s.results[f"ex418_crit_{k}"] for k in range(3)] == [2, 2, 2]
    assert [s.results[f"ex418_betti_{k}"] for k in range(3)] == gudhi_betti(datasets.sphere(2))
    assert s.results["ex418_dd_nonzero"] == 0 and s.results["ex418_flow_lines"] == 8
    assert s.results["ex418_max_lines_per_pair"] == 1 and s.results["ex418_torsion_count"] == 0
    points = table_rows(s.texts[0])
    assert [row[0] for row in points] == ["0", "1", "2"]
    # h = u² + 2v² + 3w²: minima ±e_1, saddles ±e_2, maxima ±e_3
    assert all(row[1].count("(") == 2 for row in points)
    assert "(1, 0, 0)" in points[0][1] and "(0, 0, 1)" in points[2][1]


def test_rp2_quotient_section_has_the_rp2_homology_mod_2(sphere_complex):
    s = tables.rp2_quotient_section(*sphere_complex, facets=RP2_FACETS)
    assert (s.results["ex419_lines_p_q"], s.results["ex419_lines_q_r"]) == (2, 2)
    assert [s.results[f"ex419_betti_{k}"] for k in range(3)] == gudhi_betti(RP2_FACETS) == [1, 1, 1]


def test_example_4_23_section():
    s = tables.example_4_23_section(GOOD, BAD)
    assert s.results == dict(ex423_left_is_morse=0, ex423_right_n_critical=2, ex423_right_critical_value_0=0,
                             ex423_right_critical_value_1=5)
    assert s.texts[0].startswith("right: discrete Morse function: True; critical: (0,) with value 0")
    assert s.texts[1].startswith("left: discrete Morse function: False. ")
    with pytest.raises(ValueError):
        tables.example_4_23_section(BAD, BAD)
    with pytest.raises(ValueError, match="not a discrete Morse function"):
        tables.example_4_23_section(GOOD, GOOD)


def test_lemma_4_22_section_counts_every_simplex(functions):
    s = tables.lemma_4_22_section(functions)
    assert s.results == dict(lem422_both=0, lem422_simplices=sum(len(f) for f in functions),
                             sec421_min_not_at_vertex=0)
    assert s.texts[0].endswith(f"for {len(functions)} of the {len(functions)} functions")


def test_discrete_sublevel_section_rows_agree_with_gudhi(functions):
    f = discrete_morse_function(RP2_FACETS, rp2_gradient_field())
    s = tables.discrete_sublevel_section(f, functions)
    rows = table_rows(s.texts[0])
    assert [row[2] for row in rows].count("critical") == 3
    for a, _, _, betti in rows:
        assert gudhi_betti(sublevel_complex(f, float(a))) == eval(betti)
    assert rows[-1][3] == "[1, 1, 1]"
    assert s.results["thm425_regular_changes"] == 0 and s.results["thm426_not_one_cell"] == 0
    assert s.results["thm426_critical"] == sum(len(critical_simplices(g)) for g in functions)
    assert s.texts[1].startswith("On the six samples: ")


def test_discrete_inequalities_section(samples):
    s = tables.discrete_inequalities_section(samples)
    r = s.results
    assert r["thm427_weak_failures"] == r["thm427_euler_failures"] == r["thm428_strong_failures"] == 0
    assert r["thm427_euler_strict"] == 0  # both sums are the Euler characteristic
    two = [cx for _, cx, p in samples if sum(critical_counts(cx, p)) == 2]
    assert r["ex429_two_critical"] == s.glued["ch4_two_n"] == len(two)
    # β_k over Z: the ranks over Z/3 (no sample has 3-torsion; RP² and the Klein bottle have 2-torsion)
    weak_strict = sum(any(b < c for b, c in zip(gudhi_betti(cx, top=3, field=3), critical_counts(cx, p) + [0]))
                      for _, cx, p in samples)
    assert r["thm427_weak_strict"] == weak_strict
    assert f"| {len(samples)} of {len(samples)} |" in s.texts[0]


def test_flow_matrices_section_writes_v_and_phi():
    texts = tables.flow_matrices_section(GOOD).texts
    names = ["a", "b", "c", "ab", "ac", "bc"]
    V = np.array([[int(x) for x in row[1:]] for row in table_rows(texts[0].split("\n\n", 1)[1])])
    Phi = np.array([[int(x) for x in row[1:]] for row in table_rows(texts[1].split("\n\n", 1)[1])])
    assert V.shape == Phi.shape == (6, 6)
    # V(b) = -<∂(ab), b> ab = -ab and V(c) = -<∂(bc), c> bc = -bc (∂(xy) = y - x)
    expected = np.zeros((6, 6), int)
    expected[names.index("ab"), names.index("b")] = -1
    expected[names.index("bc"), names.index("c")] = -1
    assert np.array_equal(V, expected)
    assert np.array_equal(Phi, gradient_flow(list(GOOD), [((1,), (0, 1)), ((2,), (1, 2))]).toarray())
    assert texts[2] == "$V\\circ V = 0$: True; $\\Phi\\partial = \\partial\\Phi$ (Proposition 4.37): True"


def _has_closed_vpath(cx, pairs) -> bool:
    """Independent test: a directed cycle in the modified Hasse diagram, found by networkx."""
    g = nx.DiGraph()
    paired = set(map(tuple, pairs))
    for tau in cells(cx):
        for i in range(len(tau) if len(tau) > 1 else 0):
            sigma = tau[:i] + tau[i + 1:]
            g.add_edge(sigma, tau) if (sigma, tau) in paired else g.add_edge(tau, sigma)
    return not nx.is_directed_acyclic_graph(g)


def test_vector_field_section_against_networkx(samples, functions):
    s = tables.vector_field_section(functions, samples, fields_per_sample=2, fraction=0.7)
    cyclic = sum(_has_closed_vpath(cx, checks.random_vector_field(cx, seed=100 * i + k, fraction=0.7))
                 for i, (_, cx, _) in enumerate(samples) for k in range(2))
    assert s.results["thm444_fields"] == 2 * len(samples)
    assert s.results["thm444_cyclic"] == cyclic > 0
    assert s.results["thm444_disagreements"] == s.results["thm436_not_gradient"] == 0
    assert s.results["prop432_violations"] == 0
    assert s.results["prop432_simplices"] == sum(len(f) for f in functions)
    with pytest.raises(ValueError, match="at least 1"):
        tables.vector_field_section(functions, samples, fields_per_sample=0)


def test_rp2_stabilisation_section_against_dense_powers():
    field = rp2_gradient_field()
    s = tables.rp2_stabilisation_section(RP2_FACETS, field)
    phi = gradient_flow(RP2_FACETS, field).toarray()
    power, n = phi.copy(), 1
    while not np.array_equal(power @ phi, power):
        power, n = power @ phi, n + 1
    assert s.glued == {"ch4_stabilisation_N": n}
    assert s.texts[0].endswith("on the critical simplices $a$, $ac$, $ace$ (Proposition 4.40): "
                               "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]")


def test_stabilisation_section(samples):
    s = tables.stabilisation_section(samples)
    assert s.results["thm438_not_stabilised"] == 0 and s.results["thm438_max_steps"] >= 1
    for key in ("thm441_rank_mismatches", "thm439_homology_mismatches", "thm442_homology_mismatches",
                "prop440_not_identity", "prop437_nonzero"):
        assert s.results[key] == 0, key
    with pytest.raises(ValueError, match="none of the samples"):
        tables.stabilisation_section([])


def test_gradient_path_table_sums_to_the_morse_boundary():
    field = rp2_gradient_field()
    text = tables.gradient_path_table(RP2_FACETS, field, [((0, 2), (0,)), ((0, 2, 4), (0, 2))])
    rows = table_rows(text)
    totals = {}
    for ends, _, m in rows:
        totals[ends] = totals.get(ends, 0) + int(m)
    _, mats = morse_boundary(RP2_FACETS, field)
    assert totals == {"$ac \\to a$": int(mats[1].toarray()[0, 0]), "$ace \\to ac$": int(mats[2].toarray()[0, 0])}
    assert abs(totals["$ace \\to ac$"]) == 2 and totals["$ac \\to a$"] == 0


def test_rp2_morse_complex_section():
    s = tables.rp2_morse_complex_section(RP2_FACETS, rp2_gradient_field())
    assert s.glued == {"ch4_rp2_torsion": 2}
    assert s.texts[0].endswith(f"simplicial homology: {homology(RP2_FACETS)}")
    torus = datasets.torus()
    with pytest.raises(ValueError, match="no torsion"):
        tables.rp2_morse_complex_section(torus, morse_matching(torus))


def test_heuristic_table_against_gudhi():
    complexes = [("torus", datasets.torus()), ("Klein bottle", datasets.klein_bottle())]
    rows = table_rows(tables.heuristic_table(complexes))
    assert [row[:2] for row in rows] == [["torus", "coreduction"], ["torus", "collapse"],
                                         ["Klein bottle", "coreduction"], ["Klein bottle", "collapse"]]
    for (_, cx), row in zip([c for c in complexes for _ in range(2)], rows):
        st = gudhi.SimplexTree()
        for s in cx:
            st.insert(list(s))
        assert int(row[2]) == st.num_simplices()
        betti = gudhi_betti(cx)
        assert eval(row[4]) == betti
        assert all(c >= b for c, b in zip(eval(row[3]), betti))
        assert row[5] == "True"


def test_reduction_benchmark_section():
    rows = [dict(case="two-circles-a", n_cells=10, critical_fraction=0.62, same_barcode=True),
            dict(case="two-circles-b", n_cells=12, critical_fraction=0.58, same_barcode=True),
            dict(case="lower-star-c", n_cells=20, critical_fraction=0.031, same_barcode=False)]
    s = tables.reduction_benchmark_section(rows)
    assert s.glued == {"ch4_rips_critical_pct": "58", "ch4_star_critical_pct": "3"}
    assert table_rows(s.texts[0])[2] == ["lower-star-c", "20", "3.1 %", "False"]
    with pytest.raises(ValueError, match="two-circles and lower-star"):
        tables.reduction_benchmark_section(rows[:2])


def test_torus_height_figure():
    crit = torus_critical_points()
    fig = torus_height_figure(crit, names=["r", "q1", "q2", "p"])
    ax = fig.axes[0]
    assert [t.get_text() for t in ax.texts] == ["r (index 0)", "q1 (index 1)", "q2 (index 1)", "p (index 2)"]
    marks = np.array([line.get_xydata()[0] for line in ax.lines])
    assert np.allclose(marks, [(c["u"], c["v"]) for c in crit])
    assert fig.axes[1].get_title() == "$h$"
    plt.close(fig)
    with pytest.raises(ValueError, match="one per critical point"):
        torus_height_figure(crit, names=["r"])


def test_hasse_figure():
    small, pairs = example_4_45()
    fig = hasse_figure(small, pairs)
    assert [ax.get_title() for ax in fig.axes] == ["Hasse diagram", "modified"]
    red = [t for t in fig.axes[1].texts if isinstance(t, Annotation) and t.arrow_patch.get_edgecolor()[0] > 0.8]
    assert len(red) == len(pairs)
    plt.close(fig)
    with pytest.raises(ValueError):
        hasse_figure(small, [((1,), (1, 2)), ((2,), (1, 2))])

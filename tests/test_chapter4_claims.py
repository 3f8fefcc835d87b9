"""Chapter 4's claims (experiments/claims/ch4-morse.toml) carry provenance and a link to a label of
the book page; the errata are computed as errata, the identities shown as such; and the checks of
thesis_lib.morse.checks give the values that independent reasoning predicts."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from helpers import check_claim_file
from helpers import claims_of as _claims

from thesis_lib import morse
from thesis_lib.datasets import rp2, sphere, torus
from thesis_lib.homology import homology
from thesis_lib.lab import report
from thesis_lib.lab.paths import shared_dir
from thesis_lib.morse import checks
from thesis_lib.morse.morse_complex import chain_complex_homology

ERRATA = {"def-4.9-stable-unstable-swapped", "ex-4.19-chapter-number", "sec-4.2.3-chapter-number",
          "ex-4.17-exact-sequence", "ex-4.43-exact-sequence"}
IDENTITIES = {"thm-4.27-alternating-sum", "prop-4.37-flow-commutes"}
NOT_REPRODUCIBLE = {"ex-4.23-figure-4.3", "ex-4.35-four-vpaths", "ex-4.43-three-critical-simplices",
                    "ex-4.43-morse-complex", "ex-4.45-two-critical-simplices"}


def _rows():
    ids = {c["id"] for c in _claims("ch4-morse")}
    return {r["id"]: r for r in report.report() if r["id"] in ids}


def test_claims_have_provenance_links_and_no_input_parameter():
    check_claim_file("ch4-morse")


def test_statuses_of_the_chapter_4_rows():
    rows = _rows()
    assert {i for i, r in rows.items() if r["status"] == "erratum"} == ERRATA
    assert {i for i, r in rows.items() if r["status"] == "identity"} == IDENTITIES
    assert {i for i, r in rows.items() if r["status"] == "not-reproducible"} == NOT_REPRODUCIBLE
    others = set(rows) - ERRATA - IDENTITIES - NOT_REPRODUCIBLE
    assert {rows[i]["status"] for i in others} == {"reproduced"}
    for claim in _claims("ch4-morse"):
        if claim["id"] in ERRATA:
            assert claim["corrected"].strip() and claim["check"].strip(), claim["id"]
        # the Morse complexes of §4.1 are computed from flow lines, not read from typed-in matrices
        if claim["where"].startswith(("Example 4.17", "Example 4.18", "Example 4.19")):
            assert all(ref.startswith("ch4-morse:") for ref in claim["result"]), claim["id"]


# ------------------------------------------------------------------------------------ smooth checks
@pytest.mark.parametrize("R, r", [(2.0, 1.0), (3.0, 0.5)])
def test_torus_height_critical_points_are_the_four_on_the_z_axis(R, r):
    crit = checks.surface_critical_points(checks.torus_surface(R=R, r=r), checks.linear_function([0, 0, 1]))
    assert [c["index"] for c in crit] == [0, 1, 1, 2]
    heights = [-(R + r), -(R - r), R - r, R + r]
    for c, z in zip(crit, heights):
        np.testing.assert_allclose(c["point"], [0, 0, z], atol=1e-9)


@pytest.mark.parametrize("c", list(itertools.permutations([1.0, 2.0, 3.0])))
def test_sphere_quadratic_critical_points_indices_and_homology(c):
    S2 = checks.sphere_surface()
    f = checks.quadratic_function(np.diag(c))
    crit = checks.surface_critical_points(S2, f)
    assert len(crit) == 6
    for p in crit:  # at ±e_i the Hessian of h on S² is diag(2(c_j − c_i)), j ≠ i
        i = int(np.argmax(np.abs(p["point"])))
        assert p["index"] == sum(cj < c[i] for cj in c)
    mc = checks.surface_morse_complex(S2, f, crit)
    d1, d2 = mc["signed"][1], mc["signed"][2]
    assert not (d1 @ d2).any()
    assert mc["counts"][1].tolist() == [[1, 1], [1, 1]] and mc["counts"][2].tolist() == [[1, 1], [1, 1]]
    hom = chain_complex_homology([np.zeros((0, 2), np.int64), d1, d2], coefficients=0)
    assert hom == [(1, []), (0, []), (1, [])]
    q = checks.antipodal_quotient_counts(crit, mc)
    assert q[1].tolist() == [[2]] and q[2].tolist() == [[2]]


def test_upright_torus_has_saddle_connections_and_a_tilt_removes_them():
    T = checks.torus_surface(R=2.0, r=1.0)
    up = checks.surface_morse_complex(T, checks.linear_function([0, 0, 1]),
                                      checks.surface_critical_points(T, checks.linear_function([0, 0, 1])))
    assert up["saddle_connection_branches"] == 4
    f = checks.linear_function([0, np.sin(0.15), np.cos(0.15)])
    tilted = checks.surface_morse_complex(T, f, checks.surface_critical_points(T, f))
    assert tilted["saddle_connection_branches"] == 0
    assert tilted["counts"][1].tolist() == [[2, 2]] and tilted["counts"][2].tolist() == [[2], [2]]
    assert not tilted["signed"][1].any() and not tilted["signed"][2].any()  # the torus over Z: ∂ = 0


def test_flow_limits_of_the_torus_height():
    T, h = checks.torus_surface(R=2.0, r=1.0), checks.linear_function([0, 0, 1])
    crit = checks.surface_critical_points(T, h)
    forward, backward = checks.flow_limit_fractions(T, h, crit, n=8, seed=3)
    assert forward.tolist() == [1, 0, 0, 0] and backward.tolist() == [0, 0, 0, 1]


def test_finite_difference_hessian_of_a_quadratic():
    H = checks.finite_difference_hessian(lambda u, v: 3 * u * u - 2 * u * v + 0.5 * v * v, 0.3, -0.7)
    np.testing.assert_allclose(H, [[6, -2], [-2, 1]], atol=1e-6)


# ---------------------------------------------------------------------------------- discrete checks
def test_flow_invariant_homology_of_rp2_depends_on_the_field_of_coefficients():
    field = morse.rp2_gradient_field()
    z2 = checks.flow_invariant_homology(morse.RP2_FACETS, field, coefficients=2)
    z3 = checks.flow_invariant_homology(morse.RP2_FACETS, field, coefficients=3)
    assert z2["rank"] == [1, 1, 1] == z3["rank"]
    assert z2["betti"] == [1, 1, 1] and z3["betti"] == [1, 0, 0]


@pytest.mark.parametrize("seed", range(4))
def test_flow_invariant_homology_equals_simplicial_on_random_complexes(seed):
    cx = checks.random_complex(n_vertices=7, dim=2, density=0.35, seed=seed)
    pairs = morse.morse_matching(cx, heuristic="collapse", seed=seed)
    out = checks.flow_invariant_homology(cx, pairs, coefficients=2)
    assert out["betti"] == [b for b, _ in homology(cx, coefficients=2)]
    assert out["rank"] == morse.critical_counts(cx, pairs)


def test_morse_inequality_survey_sees_strictness_and_equal_alternating_sums():
    tor = torus()
    samples = [("all critical", tor, []), ("greedy", tor, morse.morse_matching(tor, heuristic="coreduction"))]
    out = checks.morse_inequality_survey(samples)
    assert out["n"] == 2 and out["weak"] == 2 and out["strong"] == 2 and out["euler_equal"] == 2
    assert out["weak_strict"] >= 1 and out["euler_strict"] == 0


def test_lemma_4_22_counter_finds_a_simplex_breaking_both_conditions():
    f = {(0,): 2, (1,): 0, (2,): 0.1, (0, 1): 1, (0, 2): 3, (1, 2): 4, (0, 1, 2): 0.5}
    n, both, at_vertex = checks.lemma_4_22_count(f)
    assert n == 7 and both == 1 and at_vertex
    g = morse.discrete_morse_function(rp2(), morse.morse_matching(rp2(), heuristic="collapse", seed=1))
    assert checks.lemma_4_22_count(g)[1] == 0


def test_sublevel_changes_count_one_cell_per_critical_simplex():
    cx = sphere(2)
    f = morse.discrete_morse_function(cx, morse.morse_matching(cx, heuristic="collapse", seed=0))
    out = checks.sublevel_changes(f)
    assert out["regular_changes"] == 0 and out["one_cell"] == out["critical"] == len(morse.critical_simplices(f))


def test_random_vector_fields_are_vector_fields_and_some_have_closed_paths():
    cx = torus()
    fields = [checks.random_vector_field(cx, seed=s) for s in range(6)]
    for vf in fields:
        used = [x for pair in vf for x in pair]
        assert len(used) == len(set(used))
        assert morse.check_vector_field(cx, vf)
    assert not all(morse.is_acyclic(cx, vf) for vf in fields)


def test_proposition_4_32_counts_are_zero_for_a_discrete_morse_function():
    f = morse.discrete_morse_function(rp2(), morse.rp2_gradient_field())
    assert checks.proposition_4_32_violations(f) == dict(not_a_field=0, vv_nonzero=0, critical_mismatch=0, n=31)
    # Figure 4.3's right function: two critical simplices, the others paired
    good = {(0,): 0, (1,): 2, (2,): 3, (0, 1): 1.5, (1, 2): 2.5, (0, 2): 5}
    assert checks.proposition_4_32_violations(good)["critical_mismatch"] == 0


def test_two_critical_survey_on_spheres():
    samples = [(f"S{d}", sphere(d), morse.morse_matching(sphere(d), heuristic="collapse", seed=0)) for d in (2, 3)]
    out = checks.two_critical_survey(samples)
    assert out["n"] == out["with_vertex"] == out["sphere_homology"]


def test_chapter_of_heading_reads_both_numberings():
    text = "\n".join(["1", "", "Introduction", "x", "2", "", "Persistent Homology", "2.1 Complexes",
                      "2.2.1 Simplicial Homology", "3", "", "Curvature"])
    assert checks.chapter_of_heading(text, "Simplicial Homology") == dict(by_section_number=2, by_chapter_line=2)
    with pytest.raises(ValueError):
        checks.chapter_of_heading(text, "Morse Homology")
    path = shared_dir() / "thesis" / "botnan-2011-three-approaches.txt"
    if path.exists():
        text = path.read_text(encoding="utf-8")
        assert checks.chapter_of_heading(text, "Simplicial Homology") == dict(by_section_number=2, by_chapter_line=2)
        assert checks.chapter_of_heading(text, "Morse Homology") == dict(by_section_number=4, by_chapter_line=4)


def test_torus_grid_sublevels_change_only_at_critical_values():
    tris, pts = checks.torus_grid(12)
    assert homology(tris, coefficients=2) == [(1, []), (2, []), (1, [])]
    assert len(tris) == 2 * 12 * 12
    levels = np.linspace(-3.5, 3.5, 14)  # no level at a critical value
    crit = [(-3.0, 0), (-1.0, 1), (1.0, 1), (3.0, 2)]
    out = checks.sublevel_level_changes(tris, pts[:, 2], levels, crit)
    assert out["betti"][0] == [0, 0, 0] and out["betti"][-1] == [1, 2, 1]
    assert out["changes_without"] == 0 and out["one_cell"] == out["steps_with_one"] == 4
    # told of a wrong critical value, the count of changes without one is no longer zero
    wrong = checks.sublevel_level_changes(tris, pts[:, 2], levels, [(-3.0, 0), (1.0, 1), (3.0, 2)])
    assert wrong["changes_without"] == 1
    with pytest.raises(ValueError, match="critical value"):
        checks.sublevel_level_changes(tris, pts[:, 2], [-3.0, 0.0], crit)

"""thesis_lib.chapters.protein_study: rings and voids of the thesis's proteins (§2.2.2, §2.4.2,
Examples 2.42 and 2.43), cross-checked against GUDHI's weighted alpha complex and direct counts."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thesis_lib.applications.proteins import read_pdb, vdw_radii, void_count_readings  # noqa: E402
from thesis_lib.chapters.protein_study import (
    THESIS_1ECA_VOIDS,
    VoidSurvey,
    load_structure,
    model_rings,
    plot_space_filling,
    plot_void_barcodes,
    plot_window_barcode,
    plot_window_sensitivity,
    rings_at_radii,
    rings_in_window,
    void_readings,
    void_survey,
)
from thesis_lib.lab.data import resolve_structure
from thesis_lib.lab.paths import shared_dir  # noqa: E402

PDB = shared_dir() / "data" / "pdb"
pytestmark = pytest.mark.skipif(not (PDB / "1grm.pdb").is_file(), reason="shared PDB files not present")
WINDOW = (0.0, 0.5)
SAMPLING = dict(window=WINDOW, increment=0.02, increment_fine=0.005, increment_coarse=0.05, min_length=0.03)


@pytest.fixture(scope="module")
def grm():
    return load_structure("1grm")


@pytest.fixture(scope="module")
def bondi():
    return load_structure("1grm", radii_set="bondi")


@pytest.fixture(scope="module")
def at_radii(grm, bondi):
    return rings_at_radii(grm, compare=bondi)


@pytest.fixture(scope="module")
def rings(grm, bondi, at_radii):
    return rings_in_window(grm, compare=bondi, at_radii=at_radii, r_c=0.5, window=WINDOW, vicinity=0.02)


def _alive(intervals, value):
    return int(np.sum((intervals[:, 0] <= value) & (intervals[:, 1] > value)))


def test_a_structure_is_read_pdb_with_vdw_radii(grm):
    atoms = read_pdb(resolve_structure("1grm"))
    radii, fallback = vdw_radii(atoms, set="protor", return_fallback=True)
    np.testing.assert_array_equal(grm.atoms.coords, atoms.coords)
    np.testing.assert_array_equal(grm.radii, radii)
    np.testing.assert_array_equal(grm.fallback, fallback)
    assert (grm.label, grm.model, grm.radii_set) == ("1GRM", 1, "protor")
    assert load_structure("1grm", model=3).model == 3


def test_betti_numbers_at_the_radii_agree_with_gudhi(grm, bondi, at_radii):
    gudhi = pytest.importorskip("gudhi")
    for structure, betti in ((grm, at_radii.betti), (bondi, (None, at_radii.betti1_compare, None))):
        tree = gudhi.AlphaComplex(points=structure.atoms.coords, weights=structure.radii**2).create_simplex_tree()
        tree.compute_persistence()
        for k, ours in enumerate(betti):
            if ours is not None:
                assert _alive(tree.persistence_intervals_in_dimension(k).reshape(-1, 2), 0.0) == ours
    assert at_radii.record["grm_atoms"] == len(grm.atoms) == at_radii.table[1][1]
    assert at_radii.table[0][-1] == "β₁ with bondi radii"


def test_the_window_shifts_every_bar_by_r_c_squared(at_radii, rings):
    """Every weight moves by r_c², so the filtration with r_c is the one at the radii shifted by r_c²."""
    for k in range(3):
        shifted = np.sort(at_radii.barcode.intervals(k) + 0.25, axis=0)
        np.testing.assert_allclose(np.sort(rings.barcode.intervals(k), axis=0), shifted, atol=1e-9)
    assert rings.shift_mismatch == 0


def test_window_counts_against_the_bars(rings, bondi):
    h1 = rings.barcode.intervals(1)
    c = rings.counts
    assert c["grm_h1_spanning_window"] == int(np.sum((h1[:, 0] <= 0.0) & (h1[:, 1] > 0.5)))
    assert c["grm_h1_at_radii"] == _alive(h1, 0.25) == 28
    assert c["grm_h1_at_window_start"] == _alive(h1, 0.0)
    assert c["grm_h1_at_window_end"] == _alive(h1, 0.5)
    assert c["grm_h1_bars_in_window"] == int(np.sum((h1[:, 0] < 0.5) & (h1[:, 1] > 0.0)))
    assert c["grm_h1_ends_near_radii"] == int(np.sum(np.abs(h1 - 0.25) <= 0.02))
    assert (c["grm_h1_below_radii"], c["grm_h1_above_radii"]) == (_alive(h1, 0.23), _alive(h1, 0.27))
    h1_bondi = bondi.barcode(r_c=0.5).intervals(1)
    assert c["grm_h1_spanning_window_compare_radii"] == int(np.sum((h1_bondi[:, 0] <= 0) & (h1_bondi[:, 1] > 0.5)))
    assert rings.record == {**c, "grm_radii_shift_mismatch": 0}
    assert [row[1] for row in rings.table[1:]] == list(c.values())


def test_model_rings_per_model(at_radii, rings):
    models = model_rings("1grm", models=[1, 2], r_c=0.5, window=WINDOW)
    assert models.betti1[0] == at_radii.betti[1]
    assert models.spanning[0] == rings.counts["grm_h1_spanning_window"]
    assert models.at_start[0] == rings.counts["grm_h1_at_window_start"]
    assert models.record["grm_betti1_model2"] == load_structure("1grm", model=2).barcode(r_c=0.0).betti(0.0, dim=1)
    assert models.matching(models.betti1[1]) in ("2", "1, 2")
    assert models.matching(-1) == "none"
    assert models.table[0] == ["NMR model", "1", "2"] and models.table[2][0] == "rings spanning ε² ∈ [0, 0.5]"


def test_void_survey_counts_against_the_bars(grm):
    survey = void_survey([grm], r_c=0.5, **SAMPLING)
    h2 = grm.barcode(r_c=0.5).intervals(2)
    np.testing.assert_array_equal(survey.bars["1grm"], h2)
    c = survey.counts["1grm"]
    met = (h2[:, 0] < 0.5) & (h2[:, 1] > 0.0)
    assert c["exact"] == int(met.sum()) and c["at_radii"] == _alive(h2, 0.25)
    # sampled at ε² = 0, Δ, 2Δ, ...: a bar is seen when a sample falls in [b, d)
    for key, step in (("", 0.02), ("fine", 0.005), ("coarse", 0.05)):
        grid = np.arange(0.0, 0.5, step)
        seen = [np.any((grid >= b) & (grid < d)) for b, d in h2]
        assert c[key] == int(np.sum(seen)), key
    assert c["fine"] >= c[""] - c["invisible_at_step"]
    assert survey.record["voids_1grm"] == c[""] and "voids_5mbn_minus_3rn3" not in survey.record
    assert survey.exact_table[1][0] == "1GRM" and len(survey.sampled_table[0]) == 8


def test_the_difference_of_5mbn_and_3rn3_is_recorded_when_both_are_surveyed():
    keys = ("atoms", "radius_fallbacks", "at_radii", "exact", "exact_long", "", "fine", "distinct",
            "distinct_fine", "invisible_at_step", "coarse", "coarse_long")
    counts = {name: dict.fromkeys(keys, n) for name, n in (("3rn3", 5), ("5mbn", 23))}
    survey = VoidSurvey(bars={}, counts=counts, **SAMPLING)
    assert survey.record["voids_5mbn_minus_3rn3"] == 18 and survey.record["voids_5mbn_minus_3rn3_exact"] == 18
    assert survey.record["voids_3rn3_coarse_long"] == 5


def test_void_readings_against_the_rows_it_reads(grm):
    ends = [0.3, 0.5]
    readings = void_readings("1grm", window_ends=ends, increments=(0.02, 0.005, 0.05), min_length=0.03,
                             radii_sets=["protor"], waters=[False], r_c_values=[0.0, 0.5])
    rows = [row for r_c in (0.0, 0.5)
            for row in void_count_readings(grm.barcode(r_c=r_c).intervals(2), np.array(ends), min_length=0.03)]
    assert readings.tried == len(rows) == 2 * 2 * 2 * len(ends)
    t = THESIS_1ECA_VOIDS
    assert readings.match_16_9 == sum(r["n_0.05"] == t["coarse"] and r["long"] == t["long"] for r in rows)
    assert readings.thresholded == sum(r["long"] < r["n_0.05"] for r in rows)
    assert readings.record["voids_1grm_readings_tried"] == readings.tried
    assert readings.table[0][1:3] == ["16 at 0.05 and 9 long", "12 at 0.02 and 16 at 0.05"]


def test_the_figures(grm, rings):
    fig = plot_space_filling(grm, title=None, scales=[0.5])
    assert len(fig.axes) == 1 and fig.axes[0].get_title() == "" and fig.axes[0].images[0].get_array().ndim == 3
    plt.close(fig)
    fig = plot_window_barcode(rings)
    assert fig.axes[0].lines[-1].get_xdata()[0] == pytest.approx(0.25)  # the radii, ε² = r_c²
    plt.close(fig)
    survey = void_survey([grm], r_c=0.5, **SAMPLING)
    fig = plot_void_barcodes(survey, [("1grm", 0.05)], figsize=(6, 2))
    assert fig.axes[0].get_title() == "1GRM, dimension 2, increments 0.05"
    plt.close(fig)
    fig = plot_window_sensitivity(survey, rings, ends=[0.25, 0.5], window_end=0.5)
    ys = fig.axes[1].lines[0].get_ydata()
    assert list(ys) == [rings.barcode.persistent_betti(0.0, t, dim=1) for t in (0.25, 0.5)]
    plt.close(fig)
    with pytest.raises(ValueError, match="not \\['1eca'\\]"):
        plot_void_barcodes(survey, [("1eca", 0.02)], figsize=(6, 2))
    with pytest.raises(ValueError, match=r"^panels must hold at least 1 entry, got 0$"):
        plot_void_barcodes(survey, [], figsize=(6, 2))


@pytest.mark.parametrize("call, match", [
    (lambda g, b: load_structure("no-such-file.pdb", radii_set="vdw"), "radius sets are"),
    (lambda g, b: load_structure("9zzz"), "unknown structure"),
    (lambda g, b: rings_at_radii(g, compare=load_structure("1eca")), "same atoms"),
    (lambda g, b: model_rings("1grm", models=[], r_c=0.5, window=WINDOW), r"^models must hold at least 1 entry"),
    (lambda g, b: model_rings("1grm", models=[1], r_c=0.5, window=(0.5, 0.5)), "window"),
    (lambda g, b: rings_in_window(g, compare=b, at_radii=None, r_c=0.5, window=WINDOW, vicinity=-1.0), "vicinity"),
    (lambda g, b: rings_in_window(g, compare=b, at_radii=None, r_c=0.5, window=(0.0, np.inf), vicinity=0.0),
     "window"),
    (lambda g, b: void_survey([g], r_c=5.0, **SAMPLING), "exceeds the smallest radius"),
    (lambda g, b: void_survey([g], r_c=0.5, **{**SAMPLING, "increment": 0.0}), "increment"),
])
def test_bad_inputs_are_refused(grm, bondi, call, match):
    with pytest.raises(ValueError, match=match):
        call(grm, bondi)

"""Tests of thesis_lib.applications.proteins: PDB parsing traps (SOURCES.md), radii and weights
(thesis §2.2.2, §2.4.2)."""

from __future__ import annotations

import numpy as np
import pytest

from thesis_lib.applications.proteins import Atoms, discretise_intervals, read_pdb, vdw_radii, weighted_points
from thesis_lib.lab.data import resolve_structure
from thesis_lib.lab.paths import shared_dir

PDB = shared_dir() / "data" / "pdb"
pytestmark = pytest.mark.skipif(not (PDB / "1eca.pdb").is_file(), reason="shared PDB files not present")


def _counts(atoms: Atoms) -> tuple[int, int]:
    return int((~atoms.hetero).sum()), int(atoms.hetero.sum())


# ----------------------------------------------------------------------------- counts of SOURCES.md
def test_1eca_all_records_match_master_count():
    atoms = read_pdb(PDB / "1eca.pdb", waters=True, altloc="all")
    assert _counts(atoms) == (1049, 138)


def test_1eca_first_altloc_drops_the_five_b_atoms():
    atoms = read_pdb(PDB / "1eca.pdb", waters=True)
    assert len(atoms) == 1187 - 5
    no_water = read_pdb(PDB / "1eca.pdb")
    assert _counts(no_water) == (1044, 44)  # HEM stays, 94 waters go
    assert not np.any(no_water.res_names == "HOH")


def test_1eca_elements_have_no_digits_and_come_from_names():
    atoms = read_pdb(PDB / "1eca.pdb", waters=True, altloc="all")
    assert all(e.isalpha() for e in atoms.elements)
    els, counts = np.unique(atoms.elements, return_counts=True)
    assert dict(zip(els.tolist(), counts.tolist())) == {"C": 709, "FE": 1, "N": 177, "O": 295, "S": 5}
    assert atoms.elements[(atoms.res_names == "HEM") & (atoms.atom_names == "FE")].tolist() == ["FE"]
    # The alpha carbons are carbon, not calcium.
    assert set(atoms.elements[atoms.atom_names == "CA"]) == {"C"}


def test_1eca_old_amide_names_renamed():
    atoms = read_pdb(PDB / "1eca.pdb")
    names = set(atoms.atom_names.tolist())
    assert not names & {"AD1", "AD2", "AE1", "AE2"}
    asn = atoms.res_names == "ASN"
    gln = atoms.res_names == "GLN"
    assert int(np.sum(asn & (atoms.atom_names == "OD1"))) == 5
    assert int(np.sum(asn & (atoms.atom_names == "ND2"))) == 5
    assert int(np.sum(gln & (atoms.atom_names == "OE1"))) == 4
    assert int(np.sum(gln & (atoms.atom_names == "NE2"))) == 4
    assert set(atoms.elements[asn & (atoms.atom_names == "OD1")]) == {"O"}
    assert set(atoms.elements[asn & (atoms.atom_names == "ND2")]) == {"N"}
    # Old HEM names with a blank inside ("N A") become the dictionary names.
    hem = atoms.atom_names[atoms.res_names == "HEM"]
    assert {"NA", "NB", "NC", "ND"} <= set(hem.tolist())


def test_1eca_altloc_occupancy_and_coordinates():
    first = read_pdb(PDB / "1eca.pdb")
    # ATOM 1 N LEU 1 -15.159 11.595 27.068
    np.testing.assert_allclose(first.coords[0], [-15.159, 11.595, 27.068])
    # SER 106 OG altloc A at (-.276, 22.689, 10.437) is kept with altloc="first".
    og = (first.res_ids == 106) & (first.atom_names == "OG")
    np.testing.assert_allclose(first.coords[og][0], [-0.276, 22.689, 10.437])


def test_1grm_five_models_of_272_heavy_atoms_with_d_amino_acids():
    counts = [len(read_pdb(PDB / "1grm.pdb", model=m)) for m in range(1, 6)]
    assert counts == [272] * 5
    atoms = read_pdb(PDB / "1grm.pdb")
    assert set(atoms.elements.tolist()) == {"C", "N", "O"}
    res = set(atoms.res_names.tolist())
    assert {"DLE", "DVA", "FVA", "ETA"} <= res
    # hetero=False keeps the amino-acid HETATM residues (the whole peptide).
    assert len(read_pdb(PDB / "1grm.pdb", hetero=False)) == 272
    # Models differ in coordinates only.
    m2 = read_pdb(PDB / "1grm.pdb", model=2)
    assert np.array_equal(m2.atom_names, atoms.atom_names)
    assert not np.allclose(m2.coords, atoms.coords)


def test_hetero_false_drops_ligands():
    het = read_pdb(PDB / "5mbn.pdb", waters=True)
    assert _counts(het) == (1217, 164)
    nohet = read_pdb(PDB / "5mbn.pdb", hetero=False)
    assert _counts(nohet) == (1217, 0)
    rn = read_pdb(PDB / "3rn3.pdb", waters=True, altloc="all")
    assert _counts(rn) == (957, 112)
    assert len(read_pdb(PDB / "3rn3.pdb", waters=True)) == 1069 - 6


def test_name_resolution():
    path = resolve_structure("1grm")
    assert path.name.lower().endswith("1grm.pdb")
    assert len(read_pdb(path)) == 272
    with pytest.raises(ValueError, match="unknown structure"):
        resolve_structure("9zzz")


# ----------------------------------------------------------------------------- corrupt input
def _write(tmp_path, text: str):
    p = tmp_path / "bad.pdb"
    p.write_text(text)
    return p


def test_truncated_file_raises(tmp_path):
    text = (PDB / "1grm.pdb").read_text()
    cut = text[: text.index("HETATM    5") + 40]
    with pytest.raises(ValueError, match="truncated"):
        read_pdb(_write(tmp_path, cut))


def test_garbled_coordinates_raise(tmp_path):
    lines = (PDB / "1eca.pdb").read_text().splitlines()
    i = next(k for k, l in enumerate(lines) if l.startswith("ATOM"))
    lines[i] = lines[i][:30] + "  12.x4#" + lines[i][38:]
    with pytest.raises(ValueError, match="not numbers"):
        read_pdb(_write(tmp_path, "\n".join(lines)))


def test_no_atoms_binary_missing_and_bad_arguments(tmp_path):
    with pytest.raises(ValueError, match="no ATOM/HETATM"):
        read_pdb(_write(tmp_path, "HEADER    NOTHING HERE\nEND\n"))
    p = tmp_path / "bin.pdb"
    p.write_bytes(bytes(range(256)) * 4)
    with pytest.raises(ValueError, match="not a text PDB"):
        read_pdb(p)
    with pytest.raises(ValueError, match="no PDB file"):
        read_pdb(tmp_path / "missing.pdb")
    with pytest.raises(ValueError, match=r"no PDB file at 1grm \(a PDB id is found by thesis_lib.lab.data.resolve_"):
        read_pdb("1grm")
    with pytest.raises(ValueError, match="model"):
        read_pdb(PDB / "1grm.pdb", model=6)
    with pytest.raises(ValueError, match="model"):
        read_pdb(PDB / "1grm.pdb", model=0)
    with pytest.raises(ValueError, match="altloc"):
        read_pdb(PDB / "1grm.pdb", altloc="last")


# ----------------------------------------------------------------------------- radii and weights
def test_protor_radii_cover_nearly_all_protein_atoms():
    for name, max_fallback in [("1grm", 2), ("1eca", 4), ("3rn3", 1), ("5mbn", 4)]:
        atoms = read_pdb(PDB / f"{name}.pdb")
        radii, fallback = vdw_radii(atoms, return_fallback=True)
        assert radii.shape == (len(atoms),)
        assert np.all(np.isfinite(radii)) and np.all((radii > 1.0) & (radii < 2.5))
        assert int(fallback.sum()) <= max_fallback, name
        assert not np.any(fallback & ~atoms.hetero), name  # every standard residue atom has ProtOr
    atoms = read_pdb(PDB / "1grm.pdb")
    r = vdw_radii(atoms)
    # ProtOr (Tsai et al. 1999): backbone N 1.64, carbonyl O 1.42, CH3 1.88, C 1.61.
    ile = atoms.res_names == "DLE"
    assert set(r[ile & (atoms.atom_names == "N")]) == {1.64}
    assert set(r[ile & (atoms.atom_names == "O")]) == {1.42}
    assert set(r[ile & (atoms.atom_names == "CD1")]) == {1.88}
    assert set(r[ile & (atoms.atom_names == "C")]) == {1.61}


def test_single_radii_and_water_fallback():
    atoms = read_pdb(PDB / "3rn3.pdb", waters=True)
    single = vdw_radii(atoms, set="single")
    expected = {"C": 1.70, "N": 1.55, "O": 1.52, "S": 1.80}
    for el, r in expected.items():
        np.testing.assert_allclose(single[atoms.elements == el], r)
    protor, fallback = vdw_radii(atoms, return_fallback=True)
    water = atoms.res_names == "HOH"
    assert np.all(fallback[water]) and np.allclose(protor[water], 1.52)
    with pytest.raises(ValueError, match="radius set"):
        vdw_radii(atoms, set="vdw")
    with pytest.raises(ValueError, match="Atoms"):
        vdw_radii(atoms.coords)


def test_weighted_points():
    atoms = read_pdb(PDB / "1grm.pdb")
    r = vdw_radii(atoms)
    pts, w = weighted_points(atoms, r)
    np.testing.assert_allclose(w, r**2)
    assert pts.shape == (272, 3)
    pts, w = weighted_points(atoms, r, r_c=0.5)
    np.testing.assert_allclose(w, r**2 - 0.25)
    np.testing.assert_allclose(pts, atoms.coords)
    # An array of centres is accepted too.
    _, w2 = weighted_points(np.zeros((2, 3)), [1.0, 2.0], r_c=1.0)
    np.testing.assert_allclose(w2, [0.0, 3.0])
    with pytest.raises(ValueError, match="one radius per atom"):
        weighted_points(atoms, r[:-1])
    with pytest.raises(ValueError, match="positive"):
        weighted_points(np.zeros((1, 3)), [-1.0])
    with pytest.raises(ValueError, match="r_c"):
        weighted_points(np.zeros((1, 3)), [1.0], r_c=-0.1)
    with pytest.raises(ValueError, match="finite"):
        weighted_points(np.zeros((1, 3)), [np.nan])
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        weighted_points(np.zeros((2, 2)), [1.0, 1.0])


# ----------------------------------------------------------------------------- filtrations and bars
def test_discretise_intervals_on_a_grid():
    from thesis_lib.applications.proteins import discretise_intervals

    iv = np.array([[0.01, 0.015], [0.01, 0.05], [-0.3, 0.07], [0.12, np.inf], [0.6, 0.9], [0.2, 0.61]])
    out = discretise_intervals(iv, increment=0.02, window=(0.0, 0.5))
    # [0.01, 0.015) falls between samples 0.00 and 0.02: gone.  [-0.3, 0.07) is clipped to [0, 0.08).
    np.testing.assert_allclose(out, [[0.02, 0.06], [0.0, 0.08], [0.12, 0.5], [0.2, 0.5]])
    unbounded = discretise_intervals(iv, increment=0.05)
    assert np.isinf(unbounded).sum() == 1
    np.testing.assert_allclose(unbounded, [[0.0, 0.1], [0.15, np.inf], [0.6, 0.9], [0.2, 0.65]])
    with pytest.raises(ValueError, match="increment"):
        discretise_intervals(iv, increment=0.0)
    with pytest.raises(ValueError, match="window"):
        discretise_intervals(iv, increment=0.1, window=(1.0, 0.5))
    with pytest.raises(ValueError, match="birth <= death"):
        discretise_intervals([[1.0, 0.5]], increment=0.1)


def test_bondi_radii_equal_mantina_for_protein_elements_and_fall_back_for_iron():
    from thesis_lib.applications.proteins import BONDI_RADII

    atoms = read_pdb(PDB / "1eca.pdb", waters=True)
    bondi, fallback = vdw_radii(atoms, set="bondi", return_fallback=True)
    single = vdw_radii(atoms, set="single")
    # Bondi (1964): C 1.70, N 1.55, O 1.52, S 1.80; Mantina et al. (2009) kept these values.
    for el, r in {"C": 1.70, "N": 1.55, "O": 1.52, "S": 1.80}.items():
        np.testing.assert_allclose(bondi[atoms.elements == el], r)
    assert fallback.tolist() == (atoms.elements == "FE").tolist()  # Bondi lists no iron
    np.testing.assert_array_equal(bondi, single)
    assert BONDI_RADII["H"] == 1.20  # where the two tables differ (Mantina: 1.10)


def test_sampled_barcodes_invisible_bars_and_readings():
    from thesis_lib.applications.proteins import invisible_bars, sample_barcode, void_count_readings

    iv = np.array([[0.01, 0.015], [0.021, 0.039], [0.011, 0.05], [0.3, np.inf]])
    # On the 0.02 grid only [0.011, 0.05) and [0.3, ...) hold a sample; on the 0.005 grid all four do.
    assert invisible_bars(iv, increment=0.02, finer=0.005, window=(0.0, 0.5)) == 2
    assert invisible_bars(iv[2:], increment=0.02, finer=0.005, window=(0.0, 0.5)) == 0
    assert invisible_bars(iv, increment=0.02, finer=0.02, window=(0.0, 0.5)) == 0
    with pytest.raises(ValueError, match="increment"):
        invisible_bars(iv, increment=0.02, finer=0.0, window=(0.0, 0.5))
    # Radius grid: steps of 0.1 in ε = sqrt(ε²); [0.01, 0.04) in ε² is [0.1, 0.2) in ε.
    np.testing.assert_allclose(sample_barcode([[0.01, 0.04]], increment=0.1, window=(0.0, 1.0), grid="radius"),
                               [[0.01, 0.04]])
    assert len(sample_barcode([[0.012, 0.015]], increment=0.1, window=(0.0, 1.0), grid="radius")) == 0
    np.testing.assert_array_equal(sample_barcode(iv, increment=0.02, window=(0.0, 0.5)),
                                  discretise_intervals(iv, increment=0.02, window=(0.0, 0.5)))
    with pytest.raises(ValueError, match="grid"):
        sample_barcode(iv, increment=0.02, window=(0.0, 0.5), grid="log")
    rows = void_count_readings(iv, [0.5, 1.0], increments=(0.02, 0.005, 0.05), min_length=0.03)
    assert len(rows) == 2 * 2 * 2
    first = rows[0]
    assert (first["grid"], first["length"], first["window_end"]) == ("squared", "squared", 0.5)
    assert (first["n_0.02"], first["n_0.005"], first["n_0.05"]) == (2, 4, 1)  # 0.05 falls just past [0.011, 0.05)
    # On a 0.05 grid every bar is at least 0.05 long: a 0.03 threshold removes nothing.
    assert first["long"] == first["n_0.05"]


def test_protein_filtration_of_gramicidin_is_connected_at_vdw_radii():
    from thesis_lib.applications.proteins import protein_filtration
    from thesis_lib.persistence import persistence

    atoms = read_pdb(PDB / "1grm.pdb")
    r = vdw_radii(atoms)
    f = protein_filtration(atoms, r, r_c=0.5)
    # Every weighted vertex enters at -w = r_c^2 - r^2.
    np.testing.assert_allclose(np.sort(f.values[0]), np.sort(0.25 - r**2))
    bars = persistence(f)
    assert bars.betti(0.25, dim=0) == 1  # the union of the van der Waals balls is connected
    assert bars.betti(0.25, dim=1) > 10  # many rings (the thesis reports 30 with its radii)
    with pytest.raises(ValueError, match="negative weights"):
        protein_filtration(atoms, r, r_c=2.0)


def test_unknown_element_has_no_radius_and_select():
    atoms = read_pdb(PDB / "1grm.pdb")
    first = atoms.select(np.arange(len(atoms)) < 3)
    assert len(first) == 3 and first.atom_names.tolist() == atoms.atom_names[:3].tolist()
    odd = Atoms(first.coords, np.array(["C", "XX", "N"]), first.res_names, first.atom_names,
                first.res_ids, first.chain_ids, first.hetero)
    with pytest.raises(ValueError, match="element"):
        vdw_radii(odd, set="single")
    with pytest.raises(ValueError, match="mask"):
        atoms.select(np.ones(3, dtype=bool))


def test_element_from_remediated_columns_and_hydrogens(tmp_path):
    lines = [
        "ATOM      1  N   ALA A   1      11.104   6.134  -6.504  1.00  0.00           N  ",
        "ATOM      2  CA  ALA A   1      11.639   6.071  -5.147  1.00  0.00           C  ",
        "HETATM    3 ZN    ZN A   2       1.000   2.000   3.000  1.00  0.00          ZN  ",
        "ATOM      4 HB11 ALA A   1      12.000   6.000  -5.000  1.00  0.00           H  ",
        "END",
    ]
    path = _write(tmp_path, "\n".join(lines) + "\n")
    atoms = read_pdb(path)
    assert atoms.elements.tolist() == ["N", "C", "ZN"]
    assert read_pdb(path, hydrogens=True).elements.tolist() == ["N", "C", "ZN", "H"]
    assert read_pdb(path, hetero=False).elements.tolist() == ["N", "C"]
    # Without element columns the element comes from the name columns 13-14.
    path = _write(tmp_path, "\n".join(l[:66] for l in lines) + "\n")
    assert read_pdb(path, hydrogens=True).elements.tolist() == ["N", "C", "ZN", "H"]

"""Proteins as weighted point sets: PDB atoms, van der Waals radii and alpha-complex weights.

Thesis §2.2.2 (space-filling diagrams) and §2.4.2 (weights w = r² − r_c²).

The PDB files of the thesis's proteins come in two formats (see ``../shared/data/pdb/SOURCES.md``):
the old pre-remediation format of 1ECA, where columns 73–80 hold the entry id and a line number
(so the element columns 77–78 contain digits) and the ASN/GLN amide atoms carry the ambiguous names
AD1/AD2 and AE1/AE2, and the remediated format of 1GRM, 3RN3 and 5MBN.  :func:`read_pdb` normalises
every coordinate record before biotite parses it:

* ATOM/HETATM lines are cut to 72 columns; the element is kept from columns 77–78 only when they hold
  a real element symbol, otherwise it is worked out from the atom-name columns 13–14 (PDB rule:
  the element symbol is right-justified in columns 13–14);
* ASN AD1/AD2 → OD1/ND2 and GLN AE1/AE2 → OE1/NE2 (the reading fixed by SOURCES.md);
* spaces inside atom names of the old format (HEM ``N A``) are removed (``NA``, the CCD name);
* HETATM residues that are amino acids in the Chemical Component Dictionary (1GRM's DLE, DVA, FVA,
  ETA) are kept even when ``hetero=False``, which drops only the other hetero groups.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import check_int
from ..homology.filtration import Filtration

__all__ = [
    "Atoms",
    "read_pdb",
    "vdw_radii",
    "weighted_points",
    "protein_filtration",
    "discretise_intervals",
    "sample_barcode",
    "invisible_bars",
    "void_count_readings",
    "BONDI_RADII",
    "space_filling_image",
    "WATER_NAMES",
    "ELEMENT_COLORS",
]

WATER_NAMES = frozenset({"HOH", "WAT", "DOD", "H2O", "SOL"})

# Element symbols (Z = 1..103), upper case as in PDB files.
_ELEMENTS = frozenset(
    """H HE LI BE B C N O F NE NA MG AL SI P S CL AR K CA SC TI V CR MN FE CO NI CU ZN GA GE AS SE BR
    KR RB SR Y ZR NB MO TC RU RH PD AG CD IN SN SB TE I XE CS BA LA CE PR ND PM SM EU GD TB DY HO ER
    TM YB LU HF TA W RE OS IR PT AU HG TL PB BI PO AT RN FR RA AC TH PA U NP PU AM CM BK CF ES FM MD
    NO LR D""".split()
)

# Old ambiguous amide names -> remediated names (SOURCES.md).
_OLD_NAMES = {
    ("ASN", "AD1"): "OD1",
    ("ASN", "AD2"): "ND2",
    ("GLN", "AE1"): "OE1",
    ("GLN", "AE2"): "NE2",
}



@dataclass(frozen=True)
class Atoms:
    """The atoms of one model of a PDB entry, one row per atom.

    ``coords`` (n, 3) in Å; ``elements``, ``res_names``, ``atom_names``, ``chain_ids`` string arrays
    (upper case); ``res_ids`` int array; ``hetero`` bool array (HETATM record).
    """

    coords: np.ndarray
    elements: np.ndarray
    res_names: np.ndarray
    atom_names: np.ndarray
    res_ids: np.ndarray
    chain_ids: np.ndarray
    hetero: np.ndarray

    def __len__(self) -> int:
        return int(self.coords.shape[0])

    def select(self, mask: np.ndarray) -> Atoms:
        """The atoms where boolean ``mask`` is true.

        Parameters
        ----------
        mask : array_like of bool, shape (n,)
            One entry per atom.

        Returns
        -------
        Atoms
            A new record with the selected rows of every field, in order.

        Raises
        ------
        ValueError
            If ``mask`` does not have one entry per atom.
        """
        mask = np.asarray(mask, dtype=bool)
        if mask.shape != (len(self),):
            raise ValueError(f"mask must have shape ({len(self)},), got {mask.shape}")
        return Atoms(*(getattr(self, f)[mask] for f in self.__dataclass_fields__))


# --------------------------------------------------------------------------- reading
def _element_from_name(field: str) -> str:
    """Element of an atom from its 4-column name field (PDB columns 13–16)."""
    c13, c14 = field[0], field[1]
    if c13 in " 0123456789":
        return c14.upper()
    two = (c13 + c14).upper()
    if c13.upper() == "H" and len(field.strip()) == 4:  # 4-character hydrogen names (HD11, HG12)
        return "H"
    if two in _ELEMENTS and c14.isalpha():
        return two
    return c13.upper()


def _normalise(text: str, source: str) -> tuple[str, int]:
    """Coordinate records rewritten as clean 80-column lines; also the number of MODEL records."""
    out: list[str] = []
    n_atoms = 0
    n_models = 0
    for number, raw in enumerate(text.splitlines(), start=1):
        record = raw[:6]
        if record in ("ATOM  ", "HETATM"):
            line = raw.rstrip("\n\r")
            if len(line.rstrip()) < 54:
                raise ValueError(f"{source}, line {number}: truncated {record.strip()} record ({len(line)} columns)")
            try:
                xyz = [float(line[30:38]), float(line[38:46]), float(line[46:54])]
            except ValueError:
                raise ValueError(
                    f"{source}, line {number}: coordinates {line[30:54]!r} are not numbers"
                ) from None
            if not np.all(np.isfinite(xyz)):
                raise ValueError(f"{source}, line {number}: coordinates are not finite")
            core = line[:72].ljust(72)
            name_field = core[12:16]
            res_name = core[17:20].strip().upper()
            new_name = _OLD_NAMES.get((res_name, name_field.strip().upper()))
            if new_name is not None:
                name_field = " " + new_name
            elif " " in name_field.strip():  # old HEM names "N A" -> "NA"
                name_field = (" " + name_field.strip().replace(" ", "")).ljust(4)[:4]
            column_element = line[76:78].strip().upper() if len(line) >= 78 else ""
            if column_element.isalpha() and column_element in _ELEMENTS:
                element = column_element
            else:
                element = _element_from_name(core[12:16] if new_name is None else name_field)
            if element not in _ELEMENTS:
                element = "X"
            core = core[:12] + name_field + core[16:]
            out.append(core + "    " + element.rjust(2) + "  ")
            n_atoms += 1
        elif record == "MODEL ":
            out.append("MODEL     " + raw[10:14].rjust(4))
            n_models += 1
        elif record in ("ENDMDL", "TER   ", "TER"):
            out.append(record.strip())
    if n_atoms == 0:
        raise ValueError(f"{source}: no ATOM/HETATM records; not a PDB coordinate file")
    return "\n".join(out) + "\nEND\n", n_models


def read_pdb(
    path: str | Path,
    *,
    model: int = 1,
    hetero: bool = True,
    waters: bool = False,
    altloc: str = "first",
    hydrogens: bool = False,
) -> Atoms:
    """Read the atoms of one model of a PDB file, with the traps of old PDB formats handled.

    Thesis: §2.2.2 (atoms of a protein from the Protein Data Bank, space-filling model).

    Parameters
    ----------
    path : a PDB file (a PDB id such as ``"1grm"`` is found by :func:`thesis_lib.lab.data.resolve_structure`).
    model : 1-based model number (NMR entries such as 1GRM hold several).
    hetero : keep HETATM groups (ligands such as HEM, SO4).  HETATM residues that are amino acids
        (D-amino acids, formyl-Val, ethanolamine of 1GRM) are kept either way.
    waters : keep water molecules (HOH, WAT, DOD, ...).
    altloc : ``"first"``, ``"occupancy"`` or ``"all"`` alternate locations (as biotite).
    hydrogens : keep hydrogen/deuterium atoms (none of the thesis's entries has any).

    Returns
    -------
    Atoms
        One row per atom kept, in file order.

    Raises
    ------
    ValueError
        Missing file, no coordinate records, truncated or garbled records, unknown model.
    ImportError
        If biotite is not installed (the ``[proteins]`` extra).
    """
    info = require("biotite.structure.info", extra="proteins", purpose="reading PDB files")
    PDBFile = require("biotite.structure.io.pdb", extra="proteins", purpose="reading PDB files").PDBFile

    model = check_int(model, "model", minimum=1)
    if altloc not in ("first", "occupancy", "all"):
        raise ValueError(f"altloc must be 'first', 'occupancy' or 'all', got {altloc!r}")
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"no PDB file at {path} (a PDB id is found by thesis_lib.lab.data.resolve_structure)")
    try:
        text = path.read_text(encoding="ascii", errors="strict")
    except UnicodeDecodeError as exc:
        raise ValueError(f"{path}: not a text PDB file ({exc.reason} at byte {exc.start})") from None
    clean, n_model_records = _normalise(text, str(path))
    try:
        pdb_file = PDBFile.read(io.StringIO(clean))
        n_models = pdb_file.get_model_count()
    except Exception as exc:  # biotite's InvalidFileError and friends
        raise ValueError(f"{path}: cannot parse coordinate records ({type(exc).__name__}: {exc})") from None
    if model > n_models:
        raise ValueError(f"{path} has {n_models} model(s), asked for model {model}")
    try:
        array = pdb_file.get_structure(model=int(model), altloc=altloc)
    except Exception as exc:
        raise ValueError(f"{path}: cannot parse coordinate records ({type(exc).__name__}: {exc})") from None
    if array.array_length() == 0:
        raise ValueError(f"{path}: model {model} has no atoms")

    res_names = np.char.upper(array.res_name.astype(str))
    elements = np.char.upper(array.element.astype(str))
    is_het = np.asarray(array.hetero, dtype=bool)
    keep = np.ones(array.array_length(), dtype=bool)
    is_water = np.isin(res_names, list(WATER_NAMES))
    if not waters:
        keep &= ~is_water
    if not hetero:
        amino = np.isin(res_names, list(info.amino_acid_names()))
        keep &= ~is_het | amino | (is_water & waters)
    if not hydrogens:
        keep &= ~np.isin(elements, ["H", "D"])
    return Atoms(
        coords=np.asarray(array.coord[keep], dtype=np.float64),
        elements=elements[keep],
        res_names=res_names[keep],
        atom_names=np.char.upper(array.atom_name.astype(str))[keep],
        res_ids=np.asarray(array.res_id[keep], dtype=np.int64),
        chain_ids=array.chain_id.astype(str)[keep],
        hetero=is_het[keep],
    )


# --------------------------------------------------------------------------- radii and weights
#: Van der Waals radii (Å) of A. Bondi, "van der Waals Volumes and Radii", J. Phys. Chem. 68 (1964)
#: 441–451, Table I (the elements it lists that occur in proteins and their ligands).  biotite's
#: single-element table (``set="single"``) is Mantina et al. (2009), which keeps Bondi's values for
#: C, N, O, P and S and differs for H (1.10) and for elements Bondi does not list (Fe).
BONDI_RADII = {
    "H": 1.20, "C": 1.70, "N": 1.55, "O": 1.52, "F": 1.47, "P": 1.80, "S": 1.80, "CL": 1.75,
    "SE": 1.90, "BR": 1.85, "I": 1.98,
}  # fmt: skip

RADII_SETS = ("protor", "bondi", "single")


def _element_radii(elements: np.ndarray, table) -> np.ndarray:
    """Radius of every element from ``table`` (a dict or a function of the symbol); NaN where absent."""
    symbols, inverse = np.unique(elements, return_inverse=True)
    lookup = table.get if isinstance(table, dict) else table
    values = [lookup(str(e)) for e in symbols]
    return np.array([np.nan if r is None else r for r in values], dtype=np.float64)[np.asarray(inverse).reshape(-1)]


def vdw_radii(
    atoms: Atoms, *, set: str = "protor", return_fallback: bool = False
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """Van der Waals radius (Å) of every atom.

    Thesis: §2.2.2 (the radius of an atom depends on its chemical environment; the thesis took its
    radii from ESBTL, whose default classifier loads the table of Tsai et al. 1999, i.e. ProtOr).

    Parameters
    ----------
    atoms : an :class:`Atoms` record from :func:`read_pdb`.
    set : the radius table.  ``"protor"``: the ProtOr united-atom radii of Tsai et al. (1999)
        (heavy atom plus its bonded hydrogens, from the residue's entry in the Chemical Component
        Dictionary, ``biotite.structure.info.vdw_radius_protor``), the table ESBTL loads by
        default.  ``"bondi"``: Bondi's (1964) element radii, :data:`BONDI_RADII`.  ``"single"``:
        biotite's single-element radii (Mantina et al. 2009).
    return_fallback : also return the boolean mask of the atoms whose radius came from the
        single-element table because the chosen table has none (ProtOr: waters, metal ions,
        sulfate, atom names unknown to the dictionary; Bondi: iron).

    Returns
    -------
    numpy.ndarray
        ``(n,)`` radii, and the ``(n,)`` fallback mask if ``return_fallback``.

    Raises
    ------
    ValueError
        Unknown radius set, or an element without any tabulated radius.
    ImportError
        If biotite is not installed (the ``[proteins]`` extra).
    """
    info = require("biotite.structure.info", extra="proteins", purpose="atomic radii")

    if set not in RADII_SETS:
        raise ValueError(f"radius set must be one of {', '.join(RADII_SETS)}, got {set!r}")
    if not isinstance(atoms, Atoms):
        raise ValueError(f"atoms must be an Atoms record from read_pdb, got {type(atoms).__name__}")
    n = len(atoms)
    if set == "protor":
        pairs, inverse = np.unique(
            np.stack([atoms.res_names, atoms.atom_names], axis=1), axis=0, return_inverse=True
        )
        table = np.full(len(pairs), np.nan)
        for i, (res, name) in enumerate(pairs):
            try:
                r = info.vdw_radius_protor(str(res), str(name))
            except (KeyError, ValueError):
                r = None
            if r is not None:
                table[i] = r
        radii = table[np.asarray(inverse).reshape(-1)]
    elif set == "bondi":
        radii = _element_radii(atoms.elements, BONDI_RADII)
    else:
        radii = np.full(n, np.nan)
    fallback = np.isnan(radii)
    single = _element_radii(atoms.elements, info.vdw_radius_single)
    missing = fallback & np.isnan(single)
    if np.any(missing):
        bad = sorted({str(e) for e in atoms.elements[missing]})
        raise ValueError(f"no van der Waals radius for element(s) {', '.join(bad)}")
    radii = np.where(fallback, single, radii)
    return (radii, fallback) if return_fallback else radii


def weighted_points(atoms: Atoms | npt.ArrayLike, radii: npt.ArrayLike,
                    *, r_c: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Centres and alpha-complex weights w = r² − r_c² of the atoms' balls.

    Thesis: §2.4.2 (w = r² − r_c², so the filtration value ε² = r_c² gives every atom its radius r;
    r_c = 0 gives the weights of §2.2.2, the squared van der Waals radii).

    Parameters
    ----------
    atoms : Atoms or array_like, shape (n, 3)
        An :class:`Atoms` record or the atoms' centres (Å).
    radii : array_like, shape (n,)
        Positive radii (Å), one per atom (e.g. :func:`vdw_radii`).
    r_c : float
        The radius offset r_c >= 0 (Å).

    Returns
    -------
    points : numpy.ndarray of float64, shape (n, 3)
        A copy of the centres.
    weights : numpy.ndarray of float64, shape (n,)
        r² − r_c² (negative where r < r_c).

    Raises
    ------
    ValueError
        Centres not ``(n, 3)``, not one radius per atom, a non-finite or non-positive radius, or
        a negative or non-finite ``r_c``.
    """
    coords = atoms.coords if isinstance(atoms, Atoms) else np.asarray(atoms, dtype=np.float64)
    if coords.ndim != 2 or coords.shape[1] != 3:
        raise ValueError(f"atom centres must be an (n, 3) array, got shape {coords.shape}")
    r = np.asarray(radii, dtype=np.float64)
    if r.shape != (coords.shape[0],):
        raise ValueError(f"need one radius per atom: {coords.shape[0]} atoms, radii of shape {r.shape}")
    if not (np.all(np.isfinite(r)) and np.all(np.isfinite(coords))):
        raise ValueError("radii and centres must be finite")
    if np.any(r <= 0):
        raise ValueError("radii must be positive")
    if not np.isfinite(r_c) or r_c < 0:
        raise ValueError(f"r_c must be a finite non-negative number, got {r_c!r}")
    return coords.copy(), r**2 - float(r_c) ** 2


# --------------------------------------------------------------------------- filtrations and bars
def protein_filtration(atoms: Atoms | npt.ArrayLike, radii: npt.ArrayLike, *, r_c: float = 0.0) -> Filtration:
    """Weighted alpha filtration of the atoms' balls with weights w = r² − r_c² (values ε²).

    Thesis: §2.2.2 and §2.4.2 (the union of the balls B(x, sqrt(w + ε²)) is homotopy equivalent to
    the weighted alpha complex; at ε² = r_c² every atom has its van der Waals radius).

    Parameters
    ----------
    atoms : Atoms or array_like, shape (n, 3)
        The atoms, or their centres (Å).
    radii : array_like, shape (n,)
        Positive radii (Å), one per atom.
    r_c : float
        The radius offset, at most the smallest radius (so every weight is >= 0).

    Returns
    -------
    Filtration
        The weighted alpha filtration (:func:`~thesis_lib.complexes.alpha`), values ε² in Å².

    Raises
    ------
    ValueError
        As :func:`weighted_points`, or ``r_c`` larger than the smallest radius (or so large that
        r_c² overflows); ``r_c`` not a number (a string, None: an ``InvalidTypeError``), NaN,
        infinite or negative.
    """
    from .._validate import check_real
    from ..complexes.alpha import alpha

    r_c = check_real(r_c, "r_c", minimum=0.0)  # '0.5', None, NaN, inf and negatives refused by name
    if r_c * r_c == np.inf:
        raise ValueError(f"r_c = {r_c:.3g} is too large: r_c² leaves float64's range (about 1.8e308); "
                         "r_c must be at most the smallest radius")
    points, weights = weighted_points(atoms, radii, r_c=r_c)
    if np.any(weights < 0):
        raise ValueError(f"r_c = {r_c} exceeds the smallest radius {float(np.min(radii)):.3f}: negative weights")
    return alpha(points, weights)


def _snap(intervals: np.ndarray, increment: float, window: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Each interval snapped to the grid ``lo + j·increment`` and clipped to the window, and the mask
    of those a sample falls in (the others vanish on the grid)."""
    iv = np.asarray(intervals, dtype=np.float64).reshape(-1, 2)
    if not (np.isfinite(increment) and increment > 0):
        raise ValueError(f"increment must be a positive number, got {increment!r}")
    lo, hi = (float(window[0]), float(window[1]))
    if not (np.isfinite(lo) and hi > lo):
        raise ValueError(f"window must be (lo, hi) with a finite lo < hi, got {window!r}")
    if np.any(np.isnan(iv)) or np.any(iv[:, 1] < iv[:, 0]):
        raise ValueError("intervals must be (birth, death) pairs with birth <= death and no NaN")
    meets = (iv[:, 0] < hi) & (iv[:, 1] > lo)
    clipped = np.clip(iv, lo, hi)
    with np.errstate(invalid="ignore"):
        steps = np.ceil(np.round((clipped - lo) / increment, 9))
    snapped = np.where(np.isinf(clipped), clipped, lo + steps * increment)
    return snapped, meets & (snapped[:, 1] > snapped[:, 0])


def discretise_intervals(
    intervals: np.ndarray, *, increment: float, window: tuple[float, float] = (0.0, np.inf)
) -> np.ndarray:
    """Intervals of the filtration sampled at ``lo, lo + increment, lo + 2·increment, ...`` within a window.

    Thesis: §2.4.2, Example 2.43 ("filtration increments" of 0.02, 0.005 and 0.05).

    A complex computed only at the values ``lo + j·increment`` sees a class born at b from the first
    sample ≥ b until the first sample ≥ d, so each interval ``[b, d)`` becomes ``[⌈b⌉, ⌈d⌉)`` on the
    grid; classes born and dead between two samples vanish.  Only intervals meeting the window
    ``[lo, hi)`` are kept, clipped to it (a class alive at ``hi`` ends there, like a finite stream).
    Since persistence pairs do not change under a monotone re-indexing of a filtration, this is the
    barcode of the sampled filtration.

    Parameters
    ----------
    intervals : numpy.ndarray, shape (k, 2)
        ``(birth, death)`` rows, birth <= death, no NaN (death may be ``inf``).
    increment : float
        The sampling step, > 0.
    window : tuple of float
        ``(lo, hi)``, finite ``lo < hi`` (``hi`` may be ``inf``).

    Returns
    -------
    numpy.ndarray of float64, shape (j, 2)
        The intervals seen on the grid, snapped and clipped, in input order.

    Raises
    ------
    ValueError
        A non-positive increment, a bad window or bad intervals.
    """
    snapped, seen = _snap(intervals, increment, window)
    return snapped[seen]


def sample_barcode(
    intervals: np.ndarray, *, increment: float, window: tuple[float, float], grid: str = "squared"
) -> np.ndarray:
    """Bars of an alpha filtration (values ε²) sampled every ``increment`` of ε² or of ε, in ε² units.

    Thesis: §2.4.2, Example 2.43 (filtration increments).

    ``grid="squared"`` samples at ε² = lo, lo + Δ, ... (:func:`discretise_intervals`);
    ``grid="radius"`` samples at ε = sqrt(lo), sqrt(lo) + Δ, ... (the thesis does not say which of the
    two its increments step), then maps the sample values back to ε².  Values below 0 are clipped
    to 0 under the radius grid (ε² < 0 has no radius).

    Parameters
    ----------
    intervals : numpy.ndarray, shape (k, 2)
        ``(birth, death)`` rows, birth <= death, values ε².
    increment : float
        The sampling step Δ (of ε² or of ε), > 0.
    window : tuple of float
        ``(lo, hi)`` in ε² units.
    grid : {"squared", "radius"}
        What the increments step.

    Returns
    -------
    numpy.ndarray of float64, shape (j, 2)
        The sampled bars, in ε² units.

    Raises
    ------
    ValueError
        An unknown ``grid``, or as :func:`discretise_intervals`.
    """
    if grid == "squared":
        return discretise_intervals(intervals, increment=increment, window=window)
    if grid != "radius":
        raise ValueError(f"grid must be 'squared' or 'radius', got {grid!r}")
    iv = np.asarray(intervals, dtype=np.float64).reshape(-1, 2)
    lo, hi = float(window[0]), float(window[1])
    root = np.sqrt(np.clip(iv, 0.0, None))
    sampled = discretise_intervals(root, increment=increment, window=(np.sqrt(max(lo, 0.0)), np.sqrt(max(hi, 0.0))))
    return sampled**2


def invisible_bars(
    intervals: np.ndarray, *, increment: float, finer: float, window: tuple[float, float]
) -> int:
    """Number of bars seen when sampling every ``finer`` but not when sampling every ``increment``.

    Thesis: §2.4.2, Example 2.43 ("by refining the increments we detect new holes").

    A bar [b, d) is seen on a grid when a sample falls in it (:func:`discretise_intervals`); a bar
    seen on the finer grid but born and dead between two samples of the coarser one is a hole that
    only the finer increments detect.  The count is 0 when refining detects nothing new (and when
    the two increments are equal).

    Parameters
    ----------
    intervals : numpy.ndarray, shape (k, 2)
        ``(birth, death)`` rows, birth <= death, no NaN (death may be ``inf``).
    increment : float
        The coarse sampling step, > 0.
    finer : float
        The fine sampling step, > 0.
    window : tuple of float
        ``(lo, hi)``, finite ``lo < hi``.

    Returns
    -------
    int
        The number of such bars.
    """
    _, seen_fine = _snap(intervals, finer, window)
    _, seen_coarse = _snap(intervals, increment, window)
    return int(np.count_nonzero(seen_fine & ~seen_coarse))


def void_count_readings(
    intervals: np.ndarray,
    window_ends: np.ndarray,
    *,
    increments: tuple[float, float, float] = (0.02, 0.005, 0.05),
    min_length: float = 0.03,
    lo: float = 0.0,
) -> list[dict[str, float | int | str]]:
    """Dimension-2 bar counts under every reading of Example 2.43's procedure, one row per reading.

    Thesis: §2.4.2, Example 2.43 (12 generators at increments 0.02, more at 0.005, 16 at 0.05 of
    which 9 are at least 0.03 long).

    A reading is a sampling grid (``"squared"``: steps of ε²; ``"radius"``: steps of ε, see
    :func:`sample_barcode`), a unit in which bar lengths are compared with ``min_length``
    (``"squared"`` or ``"radius"``) and a window ``[lo, t]`` for each ``t`` in ``window_ends``.  Each
    row holds the reading and the counts ``n_<increment>`` of bars at each increment and
    ``long`` (bars at the last increment at least ``min_length`` long, by
    :func:`thesis_lib.persistence.long_bars`).

    Parameters
    ----------
    intervals : numpy.ndarray, shape (k, 2)
        The dimension-2 bars of the alpha filtration, values ε².
    window_ends : numpy.ndarray of float
        The ends ``t`` of the windows ``[lo, t]``.
    increments : tuple of float
        The three sampling steps; the last one's bars are also counted by length.
    min_length : float
        The length a bar must reach to count as ``long``.
    lo : float
        The start of every window.

    Returns
    -------
    list of dict
        One row per (grid, length unit, window end): keys ``grid``, ``length``, ``window_end``,
        ``n_<increment>`` for each increment, and ``long``.
    """
    from ..persistence import Barcode, long_bars

    rows = []
    for grid in ("squared", "radius"):
        for unit in ("squared", "radius"):
            for t in np.asarray(window_ends, dtype=np.float64):
                row: dict[str, float | int | str] = {"grid": grid, "length": unit, "window_end": float(t)}
                sampled = {inc: sample_barcode(intervals, increment=inc, window=(lo, float(t)), grid=grid)
                           for inc in increments}
                for inc in increments:
                    row[f"n_{inc:g}"] = len(sampled[inc])
                last = sampled[increments[-1]]
                shown = last if unit == "squared" else np.sqrt(np.clip(last, 0.0, None))
                row["long"] = int(len(long_bars(Barcode({2: shown}), dim=2, min_length=min_length)))
                rows.append(row)
    return rows


# --------------------------------------------------------------------------- rendering
#: CPK-like colours of the elements in the space-filling pictures.
ELEMENT_COLORS = {"C": "#8c8c8c", "N": "#3050f8", "O": "#ff0d0d", "S": "#e6c619", "FE": "#e06633"}


def space_filling_image(
    atoms: Atoms,
    radii: np.ndarray,
    *,
    scale: float = 1.0,
    window_size: tuple[int, int] = (600, 600),
    resolution: int = 16,
) -> np.ndarray:
    """RGB picture (h, w, 3) of the atoms as balls of radius ``scale × radius`` rendered off-screen.

    Thesis: §2.2.2 and Figure 2.18 (space-filling diagram; 1ECA with 15 % and 100 % of the radii).

    Parameters
    ----------
    atoms : Atoms
        The atoms, coloured by element (:data:`ELEMENT_COLORS`).
    radii : numpy.ndarray, shape (n,)
        One radius per atom (Å).
    scale : float
        The factor applied to every radius, > 0.
    window_size : tuple of int
        ``(width, height)`` of the picture in pixels.
    resolution : int
        Angular resolution of each sphere.

    Returns
    -------
    numpy.ndarray of uint8, shape (height, width, 3)
        The rendered picture, viewed along z.

    Raises
    ------
    ValueError
        Not an Atoms record with one radius per atom, or a non-positive scale.
    ImportError
        If pyvista (the ``[mesh]`` extra) or matplotlib (``[plot]``) is not installed.
    """
    from ..graphics.render import pyvista_offscreen

    r = np.asarray(radii, dtype=np.float64)
    if not isinstance(atoms, Atoms) or r.shape != (len(atoms),):
        raise ValueError("need an Atoms record and one radius per atom")
    if not (np.isfinite(scale) and scale > 0):
        raise ValueError(f"scale must be positive, got {scale!r}")
    pv = pyvista_offscreen()
    to_rgb = require("matplotlib.colors", extra="plot", purpose="colouring atoms").to_rgb

    colors = np.array([to_rgb(ELEMENT_COLORS.get(e, "#ff69b4")) for e in atoms.elements])
    cloud = pv.PolyData(atoms.coords - atoms.coords.mean(axis=0))
    cloud["radius"] = scale * r
    cloud["rgb"] = (255 * colors).astype(np.uint8)
    ball = pv.Sphere(radius=1.0, theta_resolution=resolution, phi_resolution=resolution)
    glyphs = cloud.glyph(scale="radius", geom=ball, orient=False)
    plotter = pv.Plotter(off_screen=True, window_size=list(window_size))
    plotter.set_background("white")
    plotter.add_mesh(glyphs, scalars="rgb", rgb=True, smooth_shading=True)
    plotter.camera_position = "xy"
    plotter.reset_camera()
    plotter.camera.zoom(1.4)
    image = plotter.screenshot(return_img=True)
    plotter.close()
    return np.asarray(image)

"""The rings and voids of the thesis's proteins (thesis §2.2.2 and §2.4.2, Examples 2.42 and 2.43).

Each step of the proteins experiment is one call here; :mod:`thesis_lib.applications.proteins`
reads the structures and builds the filtrations.

* :func:`load_structure`: one model of a PDB entry with its van der Waals radii (a :class:`Structure`);
* :func:`rings_at_radii` and :func:`model_rings`: β₀, β₁, β₂ of gramicidin A's space-filling model
  (§2.2.2), for the chosen model and for every NMR model;
* :func:`rings_in_window`: the rings that persist through the window ε² ∈ [lo, hi] around the radii,
  reached at ε² = r_c² (Example 2.42, Figure 2.17: :func:`plot_window_barcode`);
* :func:`void_survey`: the dimension-2 bars of 1ECA, 3RN3 and 5MBN sampled at the thesis's
  increments (Example 2.43, Figures 2.19 and 2.20: :func:`plot_void_barcodes`;
  :func:`plot_window_sensitivity` shows how the counts depend on the end of the window);
* :func:`void_readings`: every reading of Example 2.43's procedure tried against the thesis's counts
  12, 16 and 9 for 1ECA.

:func:`plot_space_filling` draws Figures 2.8 and 2.18.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import check_length, check_real
from ..applications.proteins import (
    RADII_SETS,
    Atoms,
    discretise_intervals,
    invisible_bars,
    protein_filtration,
    read_pdb,
    space_filling_image,
    vdw_radii,
    void_count_readings,
)
from ..graphics.style import COLORS
from ..homology.filtration import Filtration
from ..lab.data import resolve_structure
from ..persistence import Barcode, long_bars, persistence, plot_barcode

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "THESIS_1ECA_VOIDS",
    "Structure",
    "RadiiRings",
    "ModelRings",
    "WindowRings",
    "VoidSurvey",
    "VoidReadings",
    "load_structure",
    "rings_at_radii",
    "model_rings",
    "rings_in_window",
    "void_survey",
    "void_readings",
    "plot_space_filling",
    "plot_window_barcode",
    "plot_void_barcodes",
    "plot_window_sensitivity",
]

#: the thesis's counts of dimension-2 generators of 1ECA in Example 2.43, at increments 0.02
#: (``step``), at 0.05 (``coarse``), and at 0.05 ignoring bars shorter than 0.03 (``long``)
THESIS_1ECA_VOIDS = {"step": 12, "coarse": 16, "long": 9}


@dataclass(frozen=True, kw_only=True)
class Structure:
    """One model of a PDB entry, its atoms and their van der Waals radii.

    Thesis: §2.2.2 (every atom a ball of its van der Waals radius).

    Attributes
    ----------
    name : the entry as given (a PDB id such as ``"1grm"``, or a path).
    model : the 1-based model number.
    radii_set : the radius table (``thesis_lib.applications.proteins.RADII_SETS``).
    atoms : the atoms (:func:`~thesis_lib.applications.proteins.read_pdb`).
    radii : one radius per atom (Å).
    fallback : the atoms whose radius came from the single-element table.
    """

    name: str
    model: int
    radii_set: str
    atoms: Atoms
    radii: np.ndarray
    fallback: np.ndarray

    @property
    def label(self) -> str:
        """The entry's id in capitals (``"1GRM"``)."""
        return Path(self.name).stem.upper()

    def filtration(self, *, r_c: float) -> Filtration:
        """The weighted alpha filtration with weights r² − r_c² (values ε²).

        Parameters
        ----------
        r_c : float
            The radius offset (:func:`~thesis_lib.applications.proteins.protein_filtration`).

        Returns
        -------
        Filtration
            The filtration; at ε² = r_c² every atom has its radius.
        """
        return protein_filtration(self.atoms, self.radii, r_c=r_c)

    def barcode(self, *, r_c: float) -> Barcode:
        """The barcode over Z/2 of :meth:`filtration`.

        Parameters
        ----------
        r_c : float
            The radius offset.

        Returns
        -------
        Barcode
            Its bars in dimensions 0, 1 and 2.
        """
        return persistence(self.filtration(r_c=r_c))


def load_structure(name: str | Path, *, model: int = 1, radii_set: str = "protor", hetero: bool = True,
                   waters: bool = False) -> Structure:
    """Read one model of a PDB entry and give each atom its van der Waals radius.

    Thesis: §2.2.2 (the atoms of a protein from the Protein Data Bank, radii from ESBTL's table).

    Parameters
    ----------
    name : str or pathlib.Path
        A PDB id (``"1grm"``) or a file (:func:`~thesis_lib.lab.data.resolve_structure`).
    model : int, default 1
        The 1-based model (1GRM, an NMR entry, has 5).
    radii_set : str, default "protor"
        ``"protor"``, ``"bondi"`` or ``"single"`` (:func:`~thesis_lib.applications.proteins.vdw_radii`).
    hetero : bool, default True
        Keep hetero groups (the haem of 1ECA and 5MBN).
    waters : bool, default False
        Keep crystallographic waters.

    Returns
    -------
    Structure
        The atoms, their radii and which of those fell back to single-element radii.

    Raises
    ------
    ValueError
        An unknown radius set (before any file is read), or as
        :func:`~thesis_lib.applications.proteins.read_pdb`.

    Examples
    --------
    >>> grm = load_structure("1grm")
    >>> grm.label, len(grm.atoms), int(grm.fallback.sum())
    ('1GRM', 272, 2)
    """
    if radii_set not in RADII_SETS:
        raise ValueError(f"radius sets are {RADII_SETS}, got {radii_set!r}")
    atoms = read_pdb(resolve_structure(name), model=model, hetero=hetero, waters=waters)
    radii, fallback = vdw_radii(atoms, set=radii_set, return_fallback=True)
    return Structure(name=str(name), model=int(model), radii_set=radii_set, atoms=atoms, radii=radii,
                     fallback=fallback)


def _spanning(barcode: Barcode, window: tuple[float, float]) -> int:
    """The dimension-1 bars spanning the whole window (β₁^{lo, hi − lo}, Definition 2.23)."""
    return barcode.persistent_betti(window[0], window[1] - window[0], dim=1)


def _check_window(window: tuple[float, float]) -> tuple[float, float]:
    lo, hi = (float(v) for v in window)
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
        raise ValueError(f"window must be (lo, hi) with finite lo < hi, got {window!r}")
    return lo, hi


@dataclass(frozen=True, kw_only=True)
class RadiiRings:
    """Betti numbers of a protein's space-filling model, with a second radius table beside it.

    Thesis: §2.2.2 (gramicidin A: β₀ = 1, β₁ = 30, β₂ = 0).

    Attributes
    ----------
    structure : the protein.
    barcode : the barcode of its filtration with r_c = 0 (ε² = 0 is the space-filling model).
    betti : β₀, β₁, β₂ at ε² = 0.
    compare_radii_set : the second radius table.
    betti1_compare : β₁ at ε² = 0 with the second table's radii.
    """

    structure: Structure
    barcode: Barcode
    betti: tuple[int, int, int]
    compare_radii_set: str
    betti1_compare: int

    @property
    def record(self) -> dict[str, int]:
        """The experiment's recorded values (``grm_...``: gramicidin A), by their names in ``results.json``."""
        return {"grm_atoms": len(self.structure.atoms), "grm_radius_fallbacks": int(self.structure.fallback.sum()),
                "grm_betti0": self.betti[0], "grm_betti1": self.betti[1], "grm_betti2": self.betti[2],
                "grm_betti1_compare_radii": self.betti1_compare}

    @property
    def table(self) -> list[list[object]]:
        """A header and one line of atoms, fallbacks, the Betti numbers, β₁ with the second table."""
        s = self.structure
        return [["", "heavy atoms", "radius fallbacks", "β₀", "β₁", "β₂", f"β₁ with {self.compare_radii_set} radii"],
                [f"{s.label} model {s.model} ({s.radii_set})", len(s.atoms), int(s.fallback.sum()), *self.betti,
                 self.betti1_compare]]


def rings_at_radii(structure: Structure, *, compare: Structure) -> RadiiRings:
    """β₀, β₁, β₂ of the union of the atoms' balls at their radii, and β₁ with another radius table.

    Thesis: §2.2.2 (the union of balls is homotopy equivalent to the weighted alpha complex with
    weights r²; the thesis reports β₀ = 1, β₁ = 30, β₂ = 0 for gramicidin A).

    Parameters
    ----------
    structure : Structure
        The protein with its radii (:func:`load_structure`).
    compare : Structure
        The same protein with a second radius table.

    Returns
    -------
    RadiiRings
        The barcode with r_c = 0 and the Betti numbers at ε² = 0.

    Raises
    ------
    ValueError
        If ``compare`` is not the same atoms.

    Examples
    --------
    >>> rings = rings_at_radii(load_structure("1grm"), compare=load_structure("1grm", radii_set="bondi"))
    >>> rings.betti, rings.betti1_compare
    ((1, 28, 0), 18)
    """
    if not np.array_equal(structure.atoms.coords, compare.atoms.coords):
        raise ValueError("compare must hold the same atoms as structure (another radius table)")
    barcode = structure.barcode(r_c=0.0)
    betti = (barcode.betti(0.0, dim=0), barcode.betti(0.0, dim=1), barcode.betti(0.0, dim=2))
    return RadiiRings(structure=structure, barcode=barcode, betti=betti, compare_radii_set=compare.radii_set,
                      betti1_compare=compare.barcode(r_c=0.0).betti(0.0, dim=1))


@dataclass(frozen=True, kw_only=True)
class ModelRings:
    """The rings of every model of an NMR entry, at the radii and through the window.

    Thesis: §2.2.2 and Example 2.42 (1GRM is an NMR entry with five models; the thesis does not say
    which it used).

    Attributes
    ----------
    models : the model numbers.
    betti1 : β₁ at the radii (r_c = 0), per model.
    spanning : the dimension-1 bars spanning the window (weights r² − r_c²), per model.
    at_start : β₁ at the start of the window, per model.
    window : the window (lo, hi) in ε².
    """

    models: tuple[int, ...]
    betti1: tuple[int, ...]
    spanning: tuple[int, ...]
    at_start: tuple[int, ...]
    window: tuple[float, float]

    @property
    def record(self) -> dict[str, int]:
        """The experiment's recorded values, by their names in ``results.json``."""
        out = {}
        for m, b, s, a in zip(self.models, self.betti1, self.spanning, self.at_start):
            out.update({f"grm_betti1_model{m}": b, f"grm_h1_spanning_window_model{m}": s,
                        f"grm_h1_at_window_start_model{m}": a})
        return out

    @property
    def table(self) -> list[list[object]]:
        """A header of the models, then β₁ at the radii, the bars spanning the window, β₁ at its start."""
        lo, hi = self.window
        return [["NMR model", *(str(m) for m in self.models)], ["β₁ at the radii", *self.betti1],
                [f"rings spanning ε² ∈ [{lo:g}, {hi:g}]", *self.spanning],
                [f"rings alive at ε² = {lo:g}", *self.at_start]]

    def matching(self, betti1: int) -> str:
        """The models with ``betti1`` rings at the radii, as text (``"5"``, ``"2, 4"``, or ``"none"``).

        Parameters
        ----------
        betti1 : int
            The number of rings looked for (the thesis's 30 for gramicidin A).

        Returns
        -------
        str
            The model numbers joined by commas.
        """
        return ", ".join(str(m) for m, b in zip(self.models, self.betti1) if b == betti1) or "none"


def model_rings(name: str | Path, *, models: Sequence[int], r_c: float, window: tuple[float, float],
                radii_set: str = "protor", hetero: bool = True, waters: bool = False) -> ModelRings:
    """β₁ at the radii, and the rings spanning the window around them, of each model of an NMR entry.

    Thesis: §2.2.2 (β₁ = 30 for gramicidin A) and Example 2.42 (rings that persist through the
    filtration with weights r² − r_c²).

    Parameters
    ----------
    name : str or pathlib.Path
        The entry (:func:`load_structure`).
    models : sequence of int
        The models to read (1GRM's are 1 to 5).
    r_c : float
        The radius offset of the window's filtration.
    window : tuple of float
        ``(lo, hi)`` in ε², finite, lo < hi.
    radii_set, hetero, waters
        As :func:`load_structure`.

    Returns
    -------
    ModelRings
        The counts per model.

    Raises
    ------
    ValueError
        No model, a bad window, or as :func:`load_structure`.

    Examples
    --------
    >>> rings = model_rings("1grm", models=[1, 5], r_c=0.5, window=(0.0, 0.5))
    >>> rings.betti1, rings.matching(30)
    ((28, 30), '5')
    """
    window = _check_window(window)
    models = check_length(tuple(int(m) for m in models), "models", minimum=1)
    betti1, spanning, at_start = [], [], []
    for m in models:
        structure = load_structure(name, model=m, radii_set=radii_set, hetero=hetero, waters=waters)
        around = structure.barcode(r_c=r_c)
        betti1.append(structure.barcode(r_c=0.0).betti(0.0, dim=1))
        spanning.append(_spanning(around, window))
        at_start.append(around.betti(window[0], dim=1))
    return ModelRings(models=models, betti1=tuple(betti1), spanning=tuple(spanning), at_start=tuple(at_start),
                      window=window)


@dataclass(frozen=True, kw_only=True)
class WindowRings:
    """The dimension-1 bars of a protein in the window around its radii.

    Thesis: Example 2.42 (16 generators persisted through the whole filtration; fixed radii "would
    give different results even in the immediate vicinity of the radii").

    Attributes
    ----------
    structure : the protein.
    barcode : the barcode of its filtration with weights r² − r_c².
    r_c : the radius offset (the radii are reached at ε² = r_c²).
    window : (lo, hi) in ε².
    vicinity : the half-width of the vicinity of the radii, in ε².
    compare_radii_set : the second radius table.
    counts : the recorded counts by their names in ``results.json``.
    shift_mismatch : how far the Betti numbers at ε² = r_c² are from those at the radii (0: equal).
    """

    structure: Structure
    barcode: Barcode
    r_c: float
    window: tuple[float, float]
    vicinity: float
    compare_radii_set: str
    counts: dict[str, int]
    shift_mismatch: int

    @property
    def record(self) -> dict[str, int]:
        """The experiment's recorded values, by their names in ``results.json``."""
        return {**self.counts, "grm_radii_shift_mismatch": self.shift_mismatch}

    @property
    def table(self) -> list[list[object]]:
        """A header, then one line per count with what it counts."""
        v, hi = self.vicinity, self.window[1]
        labels = {
            "grm_h1_spanning_window": f"rings spanning the window [{self.window[0]:g}, {hi:g}]",
            "grm_h1_at_radii": "rings at the radii ($\\varepsilon^2 = r_c^2$)",
            "grm_h1_at_window_start": "rings at the start of the window",
            "grm_h1_at_window_end": "rings at its end",
            "grm_h1_bars_in_window": "dimension-1 bars met by the window",
            "grm_h1_spanning_window_compare_radii": f"rings spanning the window, {self.compare_radii_set} radii",
            "grm_h1_ends_near_radii": f"bar ends within {v:g} of the radii",
            "grm_h1_below_radii": f"rings at $\\varepsilon^2 = r_c^2 - {v:g}$",
            "grm_h1_above_radii": f"rings at $\\varepsilon^2 = r_c^2 + {v:g}$",
        }
        head = [f"{self.structure.label}, model {self.structure.model}", "count"]
        return [head] + [[labels[key], value] for key, value in self.counts.items()]


def rings_in_window(structure: Structure, *, compare: Structure, at_radii: RadiiRings, r_c: float,
                    window: tuple[float, float], vicinity: float) -> WindowRings:
    """The rings of the filtration with weights r² − r_c² in the window around the radii (ε² = r_c²).

    Thesis: §2.4.2 (w = r² − r_c²: at ε² = r_c² every atom has its van der Waals radius) and
    Example 2.42 (the bars spanning the whole filtration; the bars that end near the radii).

    The counts: the bars spanning the window (β₁^{lo, hi − lo}, Definition 2.23), also with the second
    radius table; β₁ at the radii, at the window's ends and at r_c² ∓ ``vicinity``; the bars met by the
    window; the bar ends within ``vicinity`` of r_c².  Every weight moves by r_c², so the complex at
    ε² = r_c² is that of ``at_radii`` at ε² = 0: ``shift_mismatch`` adds up how far their Betti numbers differ.

    Parameters
    ----------
    structure : Structure
        The protein (:func:`load_structure`).
    compare : Structure
        The same atoms with a second radius table.
    at_radii : RadiiRings
        The protein at its radii (:func:`rings_at_radii`).
    r_c : float
        The radius offset, at most the smallest radius.
    window : tuple of float
        ``(lo, hi)`` in ε², finite, lo < hi.
    vicinity : float
        The half-width of the vicinity of the radii, >= 0.

    Returns
    -------
    WindowRings
        The barcode and its counts.

    Raises
    ------
    ValueError
        A bad window or vicinity, or as :func:`~thesis_lib.applications.proteins.protein_filtration`.

    Examples
    --------
    >>> grm, bondi = load_structure("1grm"), load_structure("1grm", radii_set="bondi")
    >>> rings = rings_in_window(grm, compare=bondi, at_radii=rings_at_radii(grm, compare=bondi), r_c=0.5,
    ...                         window=(0.0, 0.5), vicinity=0.02)
    >>> rings.counts["grm_h1_spanning_window"], rings.counts["grm_h1_at_radii"], rings.shift_mismatch
    (12, 28, 0)
    """
    window = _check_window(window)
    check_real(vicinity, "vicinity", minimum=0.0)
    bars = structure.barcode(r_c=r_c)
    h1 = bars.intervals(1)
    radii_value = r_c**2
    counts = {
        "grm_h1_spanning_window": _spanning(bars, window),
        "grm_h1_at_radii": bars.betti(radii_value, dim=1),
        "grm_h1_at_window_start": bars.betti(window[0], dim=1),
        "grm_h1_at_window_end": bars.betti(window[1], dim=1),
        "grm_h1_bars_in_window": len(discretise_intervals(h1, increment=1e-9, window=window)),
        "grm_h1_spanning_window_compare_radii": _spanning(compare.barcode(r_c=r_c), window),
        "grm_h1_ends_near_radii": int(np.sum(np.abs(h1 - radii_value) <= vicinity)),
        "grm_h1_below_radii": bars.betti(radii_value - vicinity, dim=1),
        "grm_h1_above_radii": bars.betti(radii_value + vicinity, dim=1),
    }
    mismatch = sum(abs(bars.betti(radii_value, dim=d) - at_radii.barcode.betti(0.0, dim=d)) for d in range(3))
    return WindowRings(structure=structure, barcode=bars, r_c=r_c, window=window, vicinity=vicinity,
                       compare_radii_set=compare.radii_set, counts=counts, shift_mismatch=mismatch)


@dataclass(frozen=True, kw_only=True)
class VoidSurvey:
    """The dimension-2 bars of several proteins, exact and sampled at three increments.

    Thesis: Example 2.43 (voids of 1ECA, 3RN3 and 5MBN; increments 0.02, 0.005 and 0.05).

    Attributes
    ----------
    bars : entry → its dimension-2 intervals (weights r² − r_c², values ε²).
    counts : entry → its counts (atoms, radius fallbacks, bars alive at the radii, exact counts,
        counts at each increment, distinct bars, bars only the finer increment sees, long bars).
    window : (lo, hi) in ε².
    increment, increment_fine, increment_coarse : the sampling steps.
    min_length : the length of a long bar.
    """

    bars: dict[str, np.ndarray]
    counts: dict[str, dict[str, int]]
    window: tuple[float, float]
    increment: float
    increment_fine: float
    increment_coarse: float
    min_length: float

    @property
    def record(self) -> dict[str, int]:
        """``voids_<entry>_<count>`` (``voids_<entry>`` for the count at ``increment``) for every entry, and
        ``voids_5mbn_minus_3rn3`` (also ``_exact``) when both are surveyed."""
        out = {f"voids_{name}_{key}" if key else f"voids_{name}": value
               for name, counts in self.counts.items() for key, value in counts.items()}
        if "3rn3" in self.counts and "5mbn" in self.counts:
            out["voids_5mbn_minus_3rn3"] = out["voids_5mbn"] - out["voids_3rn3"]
            out["voids_5mbn_minus_3rn3_exact"] = out["voids_5mbn_exact"] - out["voids_3rn3_exact"]
        return out

    def _table(self, head: list[str], keys: tuple[str, ...]) -> list[list[object]]:
        return [head] + [[name.upper(), *(c[k] for k in keys)] for name, c in self.counts.items()]

    @property
    def exact_table(self) -> list[list[object]]:
        """Per entry the atoms, radius fallbacks, bars alive at the radii, exact bars in the window, long ones."""
        return self._table(["entry", "atoms", "radius fallbacks", "alive at the radii", "exact",
                            f"exact, ≥ {self.min_length:g}"],
                           ("atoms", "radius_fallbacks", "at_radii", "exact", "exact_long"))

    @property
    def sampled_table(self) -> list[list[object]]:
        """Per entry the bars at each increment (and how many distinct), those only the finer one sees,
        the long bars at the coarse one."""
        fine, coarse = self.increment_fine, self.increment_coarse
        return self._table(["entry", f"step {self.increment:g}", "distinct", f"step {fine:g}", "distinct",
                            f"only at {fine:g}", f"step {coarse:g}", f"≥ {self.min_length:g}"],
                           ("", "distinct", "fine", "distinct_fine", "invisible_at_step", "coarse", "coarse_long"))


def _void_counts(structure: Structure, h2: np.ndarray, *, radii_value: float, window: tuple[float, float],
                 increment: float, increment_fine: float, increment_coarse: float,
                 min_length: float) -> dict[str, int]:
    def sampled(step: float) -> np.ndarray:
        return discretise_intervals(h2, increment=step, window=window)

    coarse, exact = Barcode({2: sampled(increment_coarse)}), Barcode({2: sampled(1e-9)})
    return {
        "atoms": len(structure.atoms),
        "radius_fallbacks": int(structure.fallback.sum()),
        "at_radii": int(np.sum((h2[:, 0] <= radii_value) & (h2[:, 1] > radii_value))),
        "exact": len(exact.intervals(2)),
        "exact_long": len(long_bars(exact, dim=2, min_length=min_length)),
        "": len(sampled(increment)),
        "fine": len(sampled(increment_fine)),
        "distinct": len({tuple(bar) for bar in sampled(increment).tolist()}),
        "distinct_fine": len({tuple(bar) for bar in sampled(increment_fine).tolist()}),
        "invisible_at_step": invisible_bars(h2, increment=increment, finer=increment_fine, window=window),
        "coarse": len(coarse.intervals(2)),
        "coarse_long": len(long_bars(coarse, dim=2, min_length=min_length)),
    }


def void_survey(structures: Sequence[Structure], *, r_c: float, window: tuple[float, float], increment: float,
                increment_fine: float, increment_coarse: float, min_length: float) -> VoidSurvey:
    """The dimension-2 bars of each protein in the window, exact and sampled at three increments.

    Thesis: Example 2.43 (12 generators of 1ECA at increments 0.02, new holes at 0.005, 16 at 0.05
    of which 9 are at least 0.03 long; Rashin et al. found 9, 5 and 23 cavities in 1ECA, 3RN3, 5MBN).

    A sampled count reads the filtration at ε² = lo, lo + Δ, ...
    (:func:`~thesis_lib.applications.proteins.discretise_intervals`); the exact count samples every
    1e-9.  Long bars are those at least ``min_length`` long
    (:func:`~thesis_lib.persistence.long_bars`).

    Parameters
    ----------
    structures : sequence of Structure
        The proteins (:func:`load_structure`), named by their ``name``.
    r_c : float
        The radius offset (the radii are reached at ε² = r_c²).
    window : tuple of float
        ``(lo, hi)`` in ε², finite, lo < hi.
    increment, increment_fine, increment_coarse : float
        The sampling steps (> 0) of Figures 2.19 (top) and 2.20, of Figure 2.19 (bottom), and of the
        count of 16.
    min_length : float
        The length of a long bar, >= 0.

    Returns
    -------
    VoidSurvey
        The bars and their counts per protein.

    Raises
    ------
    ValueError
        A bad window, a non-positive increment, or as
        :func:`~thesis_lib.applications.proteins.protein_filtration`.

    Examples
    --------
    >>> survey = void_survey([load_structure("1grm")], r_c=0.5, window=(0.0, 0.5), increment=0.02,
    ...                      increment_fine=0.005, increment_coarse=0.05, min_length=0.03)
    >>> survey.counts["1grm"]["exact"] >= survey.counts["1grm"]["fine"] >= survey.counts["1grm"][""]
    True
    """
    window = _check_window(window)
    options = dict(window=window, increment=increment, increment_fine=increment_fine,
                   increment_coarse=increment_coarse, min_length=min_length)
    bars, counts = {}, {}
    for structure in structures:
        h2 = structure.barcode(r_c=r_c).intervals(2)
        bars[structure.name] = h2
        counts[structure.name] = _void_counts(structure, h2, radii_value=r_c**2, **options)
    return VoidSurvey(bars=bars, counts=counts, **options)


@dataclass(frozen=True, kw_only=True)
class VoidReadings:
    """How many readings of Example 2.43's procedure give the thesis's counts for one protein.

    Thesis: Example 2.43 (1ECA: 12 generators at increments 0.02, 16 at 0.05, 9 of them at least
    0.03 long).

    Attributes
    ----------
    name : the entry.
    increments : the three steps (``step``, fine, ``coarse``).
    tried : the readings tried.
    match_16_9 : readings with 16 bars at the coarse step and 9 long ones.
    match_12_16 : readings with 12 bars at the step and 16 at the coarse one.
    thresholded : readings where the length threshold removes a bar.
    """

    name: str
    increments: tuple[float, float, float]
    tried: int
    match_16_9: int
    match_12_16: int
    thresholded: int

    @property
    def record(self) -> dict[str, int]:
        """The experiment's recorded values, by their names in ``results.json``."""
        key = f"voids_{self.name}_readings"
        return {f"{key}_tried": self.tried, f"{key}_16_and_9": self.match_16_9, f"{key}_12_and_16": self.match_12_16,
                f"{key}_threshold_removes": self.thresholded}

    @property
    def table(self) -> list[list[object]]:
        """A header and one line of the four counts."""
        step, _, coarse = self.increments
        t = THESIS_1ECA_VOIDS
        return [["readings tried", f"{t['coarse']} at {coarse:g} and {t['long']} long",
                 f"{t['step']} at {step:g} and {t['coarse']} at {coarse:g}", "threshold removes a bar"],
                [self.tried, self.match_16_9, self.match_12_16, self.thresholded]]


def void_readings(name: str | Path, *, window_ends: npt.ArrayLike, increments: tuple[float, float, float],
                  min_length: float, hetero: bool = True, radii_sets: Sequence[str] = ("protor", "bondi"),
                  waters: Sequence[bool] = (False, True), r_c_values: Sequence[float] = (0.0, 0.5)) -> VoidReadings:
    """Every combination of radii, waters, r_c and :func:`~thesis_lib.applications.proteins.void_count_readings`'
    grids, length units and windows, checked against the thesis's counts for 1ECA.

    Thesis: Example 2.43 (:data:`THESIS_1ECA_VOIDS`: 12 at increments 0.02, 16 at 0.05, 9 of them at
    least 0.03 long).

    Parameters
    ----------
    name : str or pathlib.Path
        The entry (:func:`load_structure`).
    window_ends : array_like of float
        The ends t of the windows [0, t].
    increments : tuple of float
        The step, the fine step and the coarse step.
    min_length : float
        The length of a long bar.
    hetero : bool, default True
        Keep hetero groups.
    radii_sets : sequence of str, default ("protor", "bondi")
        The radius tables tried.
    waters : sequence of bool, default (False, True)
        Without and with waters.
    r_c_values : sequence of float, default (0.0, 0.5)
        The radius offsets r_c tried.

    Returns
    -------
    VoidReadings
        The readings tried and how many give each of the thesis's counts.

    Raises
    ------
    ValueError
        As :func:`load_structure` and :func:`~thesis_lib.applications.proteins.void_count_readings`.

    Examples
    --------
    >>> readings = void_readings("1grm", window_ends=[0.5, 1.0], increments=(0.02, 0.005, 0.05), min_length=0.03,
    ...                          radii_sets=["protor"], waters=[False], r_c_values=[0.5])
    >>> readings.tried  # 2 grids, 2 length units, 2 windows
    8
    """
    step, _, coarse = increments
    t = THESIS_1ECA_VOIDS
    tried = match_16_9 = match_12_16 = thresholded = 0
    for radii_set in radii_sets:
        for with_waters in waters:
            structure = load_structure(name, radii_set=radii_set, hetero=hetero, waters=with_waters)
            for r_c in r_c_values:
                h2 = structure.barcode(r_c=r_c).intervals(2)
                for row in void_count_readings(h2, np.asarray(window_ends, dtype=np.float64), increments=increments,
                                               min_length=min_length):
                    tried += 1
                    n_step, n_coarse = row[f"n_{step:g}"], row[f"n_{coarse:g}"]
                    match_16_9 += int(n_coarse == t["coarse"] and row["long"] == t["long"])
                    match_12_16 += int(n_step == t["step"] and n_coarse == t["coarse"])
                    thresholded += int(row["long"] < n_coarse)
    return VoidReadings(name=str(name), increments=tuple(increments), tried=tried, match_16_9=match_16_9,
                        match_12_16=match_12_16, thresholded=thresholded)


def plot_space_filling(structure: Structure, *, scales: Sequence[float] = (1.0,),
                       figsize: tuple[float, float] = (4.5, 4.5),
                       title: str | None = "{name}, {percent} % of the radii") -> Figure:
    """The protein as a space-filling diagram, one panel per scale of the radii, rendered off-screen.

    Thesis: §2.2.2, Figure 2.8 (gramicidin A) and Figure 2.18 (1ECA with 15 % and 100 % of the radii).

    Parameters
    ----------
    structure : Structure
        The protein (:func:`load_structure`), coloured by element.
    scales : sequence of float, default (1.0,)
        The factors applied to the radii, one panel each, left to right.
    figsize : tuple of float, default (4.5, 4.5)
        The figure size in inches.
    title : str or None
        Each panel's title, a ``str.format`` pattern with the fields ``name`` (the entry in capitals)
        and ``percent``; None for none.

    Returns
    -------
    matplotlib.figure.Figure
        The panels, axes off.

    Raises
    ------
    ImportError
        If pyvista or matplotlib is not installed.
    ValueError
        As :func:`~thesis_lib.applications.proteins.space_filling_image`.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_space_filling(load_structure("1grm"), scales=[0.15, 1.0], figsize=(7, 3.6))
    >>> [ax.get_title() for ax in fig.axes]
    ['1GRM, 15 % of the radii', '1GRM, 100 % of the radii']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing proteins")
    fig, axes = plt.subplots(1, len(scales), figsize=figsize, squeeze=False)
    for ax, scale in zip(axes[0], scales):
        ax.imshow(space_filling_image(structure.atoms, structure.radii, scale=scale))
        if title is not None:
            ax.set_title(title.format(name=structure.label, percent=int(round(100 * scale))))
        ax.axis("off")
    return fig


def plot_window_barcode(rings: WindowRings) -> Figure:
    """Figure 2.17: the dimension-1 barcode in the window, a dotted line at the radii (ε² = r_c²).

    Thesis: Example 2.42, Figure 2.17 (the dimension-1 barcode of gramicidin A, r_c = 0.5).

    Parameters
    ----------
    rings : WindowRings
        The bars (:func:`rings_in_window`); those met by the window are drawn, clipped to it.

    Returns
    -------
    matplotlib.figure.Figure
        One panel, values ε².

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> grm, bondi = load_structure("1grm"), load_structure("1grm", radii_set="bondi")
    >>> rings = rings_in_window(grm, compare=bondi, at_radii=rings_at_radii(grm, compare=bondi), r_c=0.5,
    ...                         window=(0.0, 0.5), vicinity=0.02)
    >>> plot_window_barcode(rings).axes[0].get_title()
    '1GRM: dimension 1, $r_c = 0.5$'
    >>> plt.close("all")
    """
    h1 = discretise_intervals(rings.barcode.intervals(1), increment=1e-9, window=rings.window)
    fig = plot_barcode(Barcode({1: h1}), dims=[1], max_value=rings.window[1],
                       xlabel="$\\varepsilon^2$ (radii reached at $r_c^2$)",
                       title=f"{rings.structure.label}: dimension 1, $r_c = {rings.r_c:g}$")
    fig.axes[0].axvline(rings.r_c**2, color="0.5", ls=":", lw=1)
    return fig


def plot_void_barcodes(survey: VoidSurvey, panels: Sequence[tuple[str, float]], *,
                       figsize: tuple[float, float]) -> Figure:
    """Dimension-2 barcodes sampled at increments, one panel per (entry, increment), top to bottom.

    Thesis: Example 2.43, Figures 2.19 (1ECA at 0.02 and 0.005) and 2.20 (3RN3 and 5MBN at 0.02).

    Parameters
    ----------
    survey : VoidSurvey
        The bars (:func:`void_survey`); drawn in its window.
    panels : sequence of (str, float)
        The entry and the increment of each panel.
    figsize : tuple of float
        The figure size in inches.

    Returns
    -------
    matplotlib.figure.Figure
        The panels, sharing their ε² axis.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        No panel, or an entry the survey does not hold.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> survey = void_survey([load_structure("1grm")], r_c=0.5, window=(0.0, 0.5), increment=0.02,
    ...                      increment_fine=0.005, increment_coarse=0.05, min_length=0.03)
    >>> fig = plot_void_barcodes(survey, [("1grm", 0.02), ("1grm", 0.005)], figsize=(6.4, 4.5))
    >>> [ax.get_title() for ax in fig.axes]
    ['1GRM, dimension 2, increments 0.02', '1GRM, dimension 2, increments 0.005']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing barcodes")
    check_length(panels, "panels", minimum=1)
    unknown = sorted({name for name, _ in panels} - set(survey.bars))
    if unknown:
        raise ValueError(f"the survey holds {sorted(survey.bars)}, not {unknown}")
    fig, axes = plt.subplots(len(panels), 1, figsize=figsize, sharex=True, squeeze=False)
    for ax, (name, step) in zip(axes[:, 0], panels):
        bars = Barcode({2: discretise_intervals(survey.bars[name], increment=step, window=survey.window)})
        plot_barcode(bars, dims=[2], axes=[ax], max_value=survey.window[1], xlabel="ε²",
                     title=f"{Path(name).stem.upper()}, dimension 2, increments {step:g}")
    fig.tight_layout()
    return fig


def plot_window_sensitivity(survey: VoidSurvey, rings: WindowRings, *, ends: npt.ArrayLike,
                            window_end: float) -> Figure:
    """How the counts depend on the end t of the window [lo, t]: each protein's dimension-2 bars
    sampled at the survey's increment (left), the rings spanning [lo, t] (right).

    Thesis: Example 2.43 (the thesis does not state its window; beyond the radii the growing balls
    close off surface pockets, each a new void).

    Parameters
    ----------
    survey : VoidSurvey
        The voids (:func:`void_survey`), one line per entry.
    rings : WindowRings
        The rings (:func:`rings_in_window`).
    ends : array_like of float
        The window ends t.
    window_end : float
        The window used, marked by a dotted line.

    Returns
    -------
    matplotlib.figure.Figure
        Two panels.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> grm, bondi = load_structure("1grm"), load_structure("1grm", radii_set="bondi")
    >>> rings = rings_in_window(grm, compare=bondi, at_radii=rings_at_radii(grm, compare=bondi), r_c=0.5,
    ...                         window=(0.0, 0.5), vicinity=0.02)
    >>> survey = void_survey([grm], r_c=0.5, window=(0.0, 0.5), increment=0.02, increment_fine=0.005,
    ...                      increment_coarse=0.05, min_length=0.03)
    >>> fig = plot_window_sensitivity(survey, rings, ends=[0.25, 0.5, 1.0], window_end=0.5)
    >>> fig.axes[1].get_ylabel()
    '1GRM rings spanning [0, t]'
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the window's effect")
    ends = np.asarray(ends, dtype=np.float64)
    lo = survey.window[0]
    fig, (ax_v, ax_r) = plt.subplots(1, 2, figsize=(7, 3.2))
    for name, h2 in survey.bars.items():
        counts = [len(discretise_intervals(h2, increment=survey.increment, window=(lo, t))) for t in ends]
        ax_v.plot(ends, counts, "o-", ms=3, label=Path(name).stem.upper())
    ax_v.axvline(window_end, color="0.5", ls=":", lw=1)
    ax_v.set_xlabel("window end t (ε²)")
    ax_v.set_ylabel("dimension-2 bars")
    ax_v.legend()
    spanning = [rings.barcode.persistent_betti(lo, t - lo, dim=1) for t in ends]
    ax_r.plot(ends, spanning, "o-", ms=3, color=COLORS["first"])
    ax_r.axvline(window_end, color="0.5", ls=":", lw=1)
    ax_r.set_xlabel("window end t (ε²)")
    ax_r.set_ylabel(f"{rings.structure.label} rings spanning [{lo:g}, t]")
    fig.tight_layout()
    return fig

"""How large the complexes of the two-circles example are when its loops are born (thesis §2.4.1,
Figures 2.14 and 2.15): Rips complexes of the whole sample against witness complexes on landmarks.

For each sample size, :func:`rips_run` and :func:`witness_run` build the complex, compute its
barcode over Z/2 and read off the long H₁ bars: when the last of them is born (the smallest
ε at which every loop is there) and how many simplices the complex has at that ε, the quantity
that decides whether a computation fits in memory.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .._validate import as_points
from ..complexes import build_filtration, rips
from ..homology.filtration import Filtration
from ..persistence import Barcode, long_bars, persistence

__all__ = ["RipsRun", "WitnessRun", "rips_run", "witness_run", "witness_table", "rips_2_skeleton_size"]


@dataclass(frozen=True, kw_only=True)
class RipsRun:
    """The Rips complex of one sample of the two-circles experiment and its long H₁ bars.

    Thesis: §2.4.1, Figure 2.14.

    Attributes
    ----------
    n : points per circle.
    n_simplices : simplices of the Rips complex up to ``max_radius``.
    complete : simplices of the complete complex on the same points (every subset up to ``max_dim``).
    within_diameter : simplices of diameter at most ``max_radius`` (ε ≤ max_radius / 2).
    long : the long H₁ bars (k, 2).
    birth, death : the largest birth and death of a long H₁ bar (NaN without one).
    at_birth : simplices of the complex at ``birth`` (0 without a long bar).
    seconds : wall time of building the complex and its barcode (a measurement: shown, never compared).
    """

    n: int
    n_simplices: int
    complete: int
    within_diameter: int
    long: np.ndarray
    birth: float
    death: float
    at_birth: int
    seconds: float
    max_radius: float

    @property
    def record(self) -> dict[str, float | int]:
        """The experiment's recorded values of this run, by their names in ``results.json``."""
        n = self.n
        return {f"n_simplices_{n}": self.n_simplices, f"n_simplices_{n}_complete": self.complete,
                f"n_simplices_{n}_diameter_max_radius": self.within_diameter,
                f"betti1_long_rips_{n}": len(self.long), f"rips_h1_long_birth_max_{n}": self.birth,
                f"rips_simplices_at_birth_{n}": self.at_birth}

    @property
    def summary(self) -> str:
        """The complex's size against the complete one, and its long H₁ bars, on two lines."""
        return (f"{self.n:4d} points per circle: {self.n_simplices:>9,d} simplices (complete 2-skeleton "
                f"{self.complete:,d})\n     {self.within_diameter:,d} of diameter at most {self.max_radius:g}; "
                f"{len(self.long)} long H₁ bars")


@dataclass(frozen=True, kw_only=True)
class WitnessRun:
    """The witness complex of one sample and its long H₁ bars, beside the Rips complex of the same points.

    Thesis: §2.4.1, Figure 2.15.

    Attributes
    ----------
    n : points per circle.
    barcode : its barcode over Z/2.
    n_simplices : simplices of the witness complex up to its ``max_radius``.
    long : the long H₁ bars (k, 2).
    birth : the largest birth of a long H₁ bar (NaN without one).
    at_birth : simplices of the witness complex at ``birth`` (all of them without a long bar).
    rips_same_sample : simplices of the 2-skeleton of the Rips complex of the same points at the
        scale where the reference Rips run's loops die.
    rips_at_birth : simplices of the reference Rips run at the birth of its loops.
    """

    n: int
    barcode: Barcode
    n_simplices: int
    long: np.ndarray
    birth: float
    at_birth: int
    rips_same_sample: int
    rips_at_birth: int

    @property
    def record(self) -> dict[str, float | int]:
        """The experiment's recorded values of this run, by their names in ``results.json``."""
        n = self.n
        return {f"witness_betti1_long_{n}": len(self.long), f"witness_simplices_{n}": self.n_simplices,
                f"witness_h1_long_birth_max_{n}": self.birth, f"witness_simplices_at_birth_{n}": self.at_birth,
                f"witness_stop_size_ratio_{n}": self.at_birth / self.rips_at_birth,
                f"rips_simplices_same_sample_{n}": self.rips_same_sample,
                f"witness_size_ratio_{n}": self.n_simplices / self.rips_same_sample}



def _long_h1(filtration: Filtration, barcode: Barcode, min_length: float, *, empty: int) -> tuple:
    long = long_bars(barcode, dim=1, min_length=min_length)
    if not len(long):
        return long, float("nan"), float("nan"), empty
    birth = float(long[:, 0].max())
    return long, birth, float(long[:, 1].max()), len(filtration.threshold(birth))


def rips_run(points: npt.ArrayLike, *, n: int, max_radius: float, max_dim: int, min_bar_length: float) -> RipsRun:
    """Build the Rips complex of ``points``, its barcode over Z/2, and read off its long H₁ bars.

    Thesis: §2.4.1, Figure 2.14 (the Rips complex of the two circles; its size grows as the
    number of points to the power max_dim + 1).

    Parameters
    ----------
    points : array_like, shape (2n, d)
        The sample (:func:`~thesis_lib.datasets.two_circles`).
    n : int
        Points per circle (the run's label).
    max_radius : float
        Largest ε of the complex (diameter at most 2ε).
    max_dim : int
        Largest simplex dimension.
    min_bar_length : float
        Least length of a long bar.

    Returns
    -------
    RipsRun
        The sizes, the long bars and the time it took.

    Examples
    --------
    >>> from thesis_lib.datasets import two_circles
    >>> run = rips_run(two_circles(20, seed=0), n=20, max_radius=2.0, max_dim=2, min_bar_length=0.1)
    >>> len(run.long), run.n_simplices, run.complete  # 40 points: the complete 2-skeleton
    (2, 10700, 10700)
    """
    pts = as_points(points)
    start = time.perf_counter()
    filtration = rips(pts, max_radius=max_radius, max_dim=max_dim)
    barcode = persistence(filtration, coefficients=2)
    seconds = time.perf_counter() - start
    long, birth, death, at_birth = _long_h1(filtration, barcode, min_bar_length, empty=0)
    complete = sum(math.comb(len(pts), k + 1) for k in range(max_dim + 1))
    return RipsRun(n=n, n_simplices=len(filtration), complete=complete,
                   within_diameter=len(filtration.threshold(max_radius / 2)), long=long, birth=birth, death=death,
                   at_birth=at_birth, seconds=seconds, max_radius=max_radius)


def witness_run(points: npt.ArrayLike, *, n: int, reference: RipsRun, max_radius: float, landmark_method: str,
                n_landmarks: int, nu: int, seed: int, min_bar_length: float) -> WitnessRun:
    """Build the witness complex of ``points``, its barcode over Z/2, its long H₁ bars, and the
    size of the Rips complex of the same points at the scale where ``reference``'s loops die.

    Thesis: §2.4.1, Figure 2.15 (witness complexes find the two loops with far fewer simplices).

    Parameters
    ----------
    points : array_like, shape (2n, d)
        The sample.
    n : int
        Points per circle (the run's label).
    reference : RipsRun
        The Rips run the witness complex is compared with.
    max_radius : float
        Largest ε of the witness filtration.
    landmark_method, n_landmarks, nu, seed
        As :func:`~thesis_lib.complexes.build_filtration` with ``complex="witness"``.
    min_bar_length : float
        Least length of a long bar.

    Returns
    -------
    WitnessRun
        The sizes and the long bars.

    Examples
    --------
    >>> from thesis_lib.datasets import two_circles
    >>> ref = rips_run(two_circles(20, seed=0), n=20, max_radius=2.0, max_dim=2, min_bar_length=0.1)
    >>> w = witness_run(two_circles(100, seed=0), n=100, reference=ref, max_radius=1.0, landmark_method="maxmin",
    ...                 n_landmarks=30, nu=1, seed=0, min_bar_length=0.1)
    >>> len(w.long), w.n_simplices, w.rips_same_sample  # three loops from 30 landmarks
    (3, 3100, 106463)
    """
    pts = as_points(points)
    filtration = build_filtration(pts, complex="witness", max_radius=max_radius, max_dim=2,
                                  landmark_method=landmark_method, n_landmarks=n_landmarks, nu=nu, seed=seed)
    barcode = persistence(filtration, coefficients=2)
    long, birth, _, at_birth = _long_h1(filtration, barcode, min_bar_length, empty=len(filtration))
    return WitnessRun(n=n, barcode=barcode, n_simplices=len(filtration), long=long, birth=birth, at_birth=at_birth,
                      rips_same_sample=rips_2_skeleton_size(pts, max_radius=reference.death),
                      rips_at_birth=reference.at_birth)


def witness_table(runs: list[WitnessRun], *, reference: RipsRun) -> str:
    """The experiment's table (Markdown): per witness run its size, the Rips complex's on the same
    points, its long bars, its size when they are born and that birth; then the Rips reference.

    Thesis: §2.4.1, Figure 2.15.

    Parameters
    ----------
    runs : list of WitnessRun
        The witness runs, one line each.
    reference : RipsRun
        The Rips run of the last line.

    Returns
    -------
    str
        The table, numbers right-aligned.

    Examples
    --------
    >>> from thesis_lib.datasets import two_circles
    >>> ref = rips_run(two_circles(20, seed=0), n=20, max_radius=2.0, max_dim=2, min_bar_length=0.1)
    >>> print(witness_table([], reference=ref).splitlines()[-1])
    | Rips, 20 | | | 2 | 595 | 0.377 |
    """
    lines = ["| points per circle | witness simplices | Rips, same points | long $H_1$ bars | built when born "
             "| born by $\\varepsilon$ |", "|---:|---:|---:|---:|---:|---:|"]
    lines += [f"| {r.n} | {r.n_simplices:,d} | {r.rips_same_sample:,d} | {len(r.long)} | {r.at_birth:,d} "
              f"| {r.birth:.3f} |" for r in runs]
    lines.append(f"| Rips, {reference.n} | | | {len(reference.long)} | {reference.at_birth:,d} "
                 f"| {reference.birth:.3f} |")
    return "\n".join(lines)


def rips_2_skeleton_size(points: npt.ArrayLike, *, max_radius: float) -> int:
    """Simplices of dimension ≤ 2 of the Rips complex at ``max_radius``, counted without building it.

    Thesis: Definition 2.11 (an edge when two points are at most 2ε apart; a triangle when its three
    edges are): vertices + edges + triangles, the triangles as trace(A³) / 6 of the adjacency matrix.

    Parameters
    ----------
    points : array_like, shape (n, d)
        The points.
    max_radius : float
        The scale ε.

    Returns
    -------
    int
        The number of simplices.

    Examples
    --------
    >>> rips_2_skeleton_size([[0, 0], [1, 0], [0, 1]], max_radius=0.75)
    7
    """
    from scipy.spatial.distance import pdist, squareform

    pts = as_points(points)
    adjacency = (squareform(pdist(pts)) <= 2 * max_radius).astype(np.float32)
    np.fill_diagonal(adjacency, 0.0)
    edges = int(adjacency.sum()) // 2
    triangles = int(((adjacency @ adjacency) * adjacency).astype(np.int64).sum()) // 6  # exact: small integers
    return len(pts) + edges + triangles

"""Maxmin against random landmarks on the two circles (thesis §2.1.2 and §2.4.1, Figure 2.13).

The thesis shows both methods' landmarks on 2000 points from each of two circles meeting in two
points and remarks that maxmin's are "more uniformly distributed and therefore more appropriate for
this case. Though for a point set with several outliers a random approach may be better".  Three
measurements over samples with seeds ``seed, seed + 1, ...`` test the remark:

* :func:`cover_study`: each method's covering radius (the largest distance from a data point to its
  nearest landmark) and its landmarks near the intersection points;
* :func:`loop_study`: how clearly a witness complex on each method's landmarks shows the three loops
  (the length of its third-longest H₁ bar);
* :func:`outlier_study`: with uniform outliers added, the landmarks each method spends on them and
  how well the others still cover the circles.

:func:`plot_landmarks` draws Figure 2.13 and :func:`plot_outliers` the landmarks among outliers.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .._optional import require
from .._validate import check_int, check_real, check_seed
from ..complexes import build_filtration, choose_landmarks, covering_radius
from ..complexes.landmarks import count_within
from ..datasets import two_circles, two_circles_intersections
from ..graphics.style import COLORS
from ..persistence import long_bars, persistence

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["METHODS", "LandmarkSample", "CoverStudy", "LoopStudy", "OutlierStudy", "landmark_sample",
           "cover_study", "loop_study", "outlier_study", "outlier_table", "plot_landmarks", "plot_outliers"]

#: the two landmark methods of §2.1.2, in the order they are reported
METHODS = ("maxmin", "random")


@dataclass(frozen=True, kw_only=True)
class LandmarkSample:
    """One sample of the two circles and each method's landmarks on it.

    Thesis: §2.4.1, Figure 2.13.

    Attributes
    ----------
    points : the sample, shape (2 n_per_circle, 2).
    landmarks : method → landmark indices into ``points``.
    """

    points: np.ndarray
    landmarks: dict[str, np.ndarray]


def _check_sampling(n_per_circle: int, n_landmarks: int, seed: int, noise: float, n_trials: int = 1) -> None:
    check_int(n_per_circle, "n_per_circle", minimum=1)
    check_int(n_landmarks, "n_landmarks", minimum=1)
    check_seed(seed)
    check_real(noise, "noise", minimum=0.0)
    check_int(n_trials, "n_trials", minimum=1)


def _sample(n_per_circle: int, n_landmarks: int, seed: int, noise: float) -> LandmarkSample:
    points = two_circles(n_per_circle, seed=seed, noise=noise)
    return LandmarkSample(points=points, landmarks={m: choose_landmarks(points, landmark_method=m, n=n_landmarks,
                                                                         seed=seed) for m in METHODS})


def _trials(n_per_circle: int, n_landmarks: int, seed: int, noise: float, n_trials: int) -> Iterator[LandmarkSample]:
    return (_sample(n_per_circle, n_landmarks, seed + trial, noise) for trial in range(n_trials))


def landmark_sample(*, n_per_circle: int, n_landmarks: int, seed: int, noise: float = 0.0) -> LandmarkSample:
    """A sample of the two circles with ``n_landmarks`` landmarks of each method, all drawn with ``seed``.

    Thesis: §2.1.2 (Definition 2.16; the random and the sequential maxmin methods) and §2.4.1,
    Figure 2.13.

    Parameters
    ----------
    n_per_circle : int
        Points per circle (:func:`~thesis_lib.datasets.two_circles`).
    n_landmarks : int
        Landmarks per method, at most ``2 n_per_circle``.
    seed : int
        Seed of the sample and of both methods.
    noise : float, default 0.0
        Standard deviation of the Gaussian noise on the points.

    Returns
    -------
    LandmarkSample
        The points and the landmark indices of :data:`METHODS`.

    Raises
    ------
    ValueError
        A count below 1, more landmarks than points, a negative seed or noise.

    Examples
    --------
    >>> sample = landmark_sample(n_per_circle=100, n_landmarks=10, seed=0)
    >>> sample.points.shape, {m: len(idx) for m, idx in sample.landmarks.items()}
    ((200, 2), {'maxmin': 10, 'random': 10})
    """
    _check_sampling(n_per_circle, n_landmarks, seed, noise)
    return _sample(n_per_circle, n_landmarks, seed, noise)


@dataclass(frozen=True, kw_only=True)
class CoverStudy:
    """Covering radii and landmarks near the intersection points, per method and sample.

    Thesis: §2.1.2 (maxmin chooses the landmarks greedily to cover the data) and §2.4.1.

    Attributes
    ----------
    cover : method → covering radius on each sample (the first sample is the one drawn with ``seed``).
    near : method → landmarks within ``near_radius`` of an intersection point on each sample.
    near_radius : the distance of "near".
    """

    cover: dict[str, np.ndarray]
    near: dict[str, np.ndarray]
    near_radius: float

    @property
    def ratios(self) -> np.ndarray:
        """Random's covering radius over maxmin's, per sample."""
        return self.cover["random"] / self.cover["maxmin"]

    @property
    def record(self) -> dict[str, float | int]:
        """The experiment's recorded values, by their names in ``results.json``."""
        first = {m: float(self.cover[m][0]) for m in METHODS}
        return {
            "covering_radius_maxmin": first["maxmin"],
            "covering_radius_random": first["random"],
            "covering_radius_ratio": first["random"] / first["maxmin"],
            "covering_radius_ratio_min": float(np.min(self.ratios)),
            "covering_radius_ratio_median": float(np.median(self.ratios)),
            "near_intersections_maxmin": int(self.near["maxmin"][0]),
            "near_intersections_random": int(self.near["random"][0]),
            "near_intersections_mean_maxmin": float(np.mean(self.near["maxmin"])),
            "near_intersections_mean_random": float(np.mean(self.near["random"])),
        }

    @property
    def summary(self) -> str:
        """The covering radii of the first sample, their ratio over all, the near landmarks (four lines)."""
        r, n = self.record, len(self.ratios)
        return (f"covering radius: maxmin {r['covering_radius_maxmin']:.3f}, random {r['covering_radius_random']:.3f}"
                f" (ratio {r['covering_radius_ratio']:.2f})\n"
                f"ratio random/maxmin over {n} samples: smallest {r['covering_radius_ratio_min']:.2f}, "
                f"median {r['covering_radius_ratio_median']:.2f}\n"
                f"landmarks within {self.near_radius} of the two intersection points (mean of {n} samples):\n"
                f"  maxmin {r['near_intersections_mean_maxmin']:.2f}, random {r['near_intersections_mean_random']:.2f}")

    @property
    def texts(self) -> dict[str, str]:
        """The numbers the prose quotes, as text (``ratio``, ``ratio_min``, ``near_maxmin``, ``near_random``)."""
        r = self.record
        return {"ratio": f"{r['covering_radius_ratio']:.2f}", "ratio_min": f"{r['covering_radius_ratio_min']:.2f}",
                "near_maxmin": f"{r['near_intersections_mean_maxmin']:.2f}",
                "near_random": f"{r['near_intersections_mean_random']:.2f}"}


def cover_study(*, n_per_circle: int, n_landmarks: int, seed: int, noise: float = 0.0, near_radius: float,
                n_trials: int) -> CoverStudy:
    """Each method's covering radius and landmarks near the intersection points, on ``n_trials`` samples.

    Thesis: §2.1.2 and §2.4.1, Figure 2.13 (maxmin's landmarks are "more uniformly distributed").

    Sample ``t`` is :func:`landmark_sample` with seed ``seed + t``.  Maxmin's covering radius is at
    most twice the least any ``n_landmarks`` points reach, so random can beat it by that factor at most.

    Parameters
    ----------
    n_per_circle, n_landmarks, seed, noise
        As :func:`landmark_sample`.
    near_radius : float
        A landmark within this distance of an intersection point is near it (>= 0).
    n_trials : int
        The number of samples (>= 1).

    Returns
    -------
    CoverStudy
        The covering radii and near counts per method and sample.

    Raises
    ------
    ValueError
        As :func:`landmark_sample`, a negative ``near_radius`` or ``n_trials`` below 1.

    Examples
    --------
    >>> study = cover_study(n_per_circle=200, n_landmarks=20, seed=0, near_radius=0.1, n_trials=3)
    >>> bool(study.ratios.min() > 1)  # maxmin covers more tightly on every sample
    True
    >>> sorted(study.texts)
    ['near_maxmin', 'near_random', 'ratio', 'ratio_min']
    """
    _check_sampling(n_per_circle, n_landmarks, seed, noise, n_trials)
    near_radius = check_real(near_radius, "near_radius", minimum=0.0)
    crossings = two_circles_intersections()
    cover: dict[str, list[float]] = {m: [] for m in METHODS}
    near: dict[str, list[int]] = {m: [] for m in METHODS}
    for sample in _trials(n_per_circle, n_landmarks, seed, noise, n_trials):
        for method, idx in sample.landmarks.items():
            cover[method].append(covering_radius(sample.points, idx))
            near[method].append(count_within(sample.points[idx], crossings, near_radius))
    return CoverStudy(cover={m: np.array(v) for m, v in cover.items()},
                      near={m: np.array(v) for m, v in near.items()}, near_radius=near_radius)


@dataclass(frozen=True, kw_only=True)
class LoopStudy:
    """How clearly the witness complex on each method's landmarks shows the three loops, per sample.

    Thesis: §2.1.2 (landmarks serve the witness complex) and §2.4.1 (β₁ = 3).

    Attributes
    ----------
    third : method → the length of the third-longest H₁ bar on each sample (bars alive at the end
        cut at ``max_radius``; 0 with fewer than three bars).
    loops : method → the H₁ bars at least ``min_bar_length`` long on each sample.
    min_bar_length : the least length of a loop's bar.
    """

    third: dict[str, np.ndarray]
    loops: dict[str, np.ndarray]
    min_bar_length: float

    @property
    def ratios(self) -> np.ndarray:
        """Maxmin's third bar over random's, per sample (random's at least 1e-12)."""
        return self.third["maxmin"] / np.maximum(self.third["random"], 1e-12)

    @property
    def record(self) -> dict[str, float | int]:
        """The experiment's recorded values, by their names in ``results.json``."""
        return {
            "witness_third_bar_median_maxmin": float(np.median(self.third["maxmin"])),
            "witness_third_bar_median_random": float(np.median(self.third["random"])),
            "witness_third_bar_ratio_median": float(np.median(self.ratios)),
            "witness_third_bar_maxmin_longer_trials": int(np.sum(self.ratios > 1)),
            "witness_three_loops_trials_maxmin": int(np.sum(self.loops["maxmin"] == 3)),
            "witness_three_loops_trials_random": int(np.sum(self.loops["random"] == 3)),
        }

    @property
    def summary(self) -> str:
        """One line per method (its median third bar, the samples with three loops), then their comparison."""
        n = len(self.ratios)
        lines = [f"{m:6s}: third-longest H₁ bar {np.median(self.third[m]):.2f} (median);"
                 f" 3 bars ≥ {self.min_bar_length} in {int(np.sum(self.loops[m] == 3))} of {n}" for m in METHODS]
        lines.append(f"maxmin's third bar longer in {int(np.sum(self.ratios > 1))} of {n} samples;"
                     f" median ratio {np.median(self.ratios):.2f}")
        return "\n".join(lines)


def loop_study(*, n_per_circle: int, n_landmarks: int, seed: int, noise: float = 0.0, n_trials: int,
               max_radius: float, nu: int, min_bar_length: float) -> LoopStudy:
    """The H₁ barcode over Z/2 of the witness filtration on each method's landmarks, on ``n_trials`` samples.

    Thesis: §2.1.2 (the witness complex W(X, L, ε) on landmarks L) and §2.4.1 (the two circles
    have β₁ = 3; maxmin is "more appropriate for this case").

    Parameters
    ----------
    n_per_circle, n_landmarks, seed, noise, n_trials
        As :func:`cover_study` (sample ``t`` and its landmarks drawn with seed ``seed + t``).
    max_radius : float
        Largest ε of the witness filtrations (> 0).
    nu : int
        Witness rank ν (>= 1).
    min_bar_length : float
        An H₁ bar at least this long is a loop (>= 0).

    Returns
    -------
    LoopStudy
        The third-longest H₁ bar and the loops per method and sample.

    Raises
    ------
    ValueError
        As :func:`cover_study`, or a bad ``max_radius``, ``nu`` or ``min_bar_length``.

    Examples
    --------
    >>> study = loop_study(n_per_circle=100, n_landmarks=30, seed=0, n_trials=2, max_radius=1.0, nu=1,
    ...                    min_bar_length=0.1)
    >>> study.loops["maxmin"].tolist()  # the three loops on both samples
    [3, 3]
    """
    _check_sampling(n_per_circle, n_landmarks, seed, noise, n_trials)
    max_radius = check_real(max_radius, "max_radius", positive=True)
    min_bar_length = check_real(min_bar_length, "min_bar_length", minimum=0.0)
    third: dict[str, list[float]] = {m: [] for m in METHODS}
    loops: dict[str, list[int]] = {m: [] for m in METHODS}
    for trial in range(n_trials):
        points = two_circles(n_per_circle, seed=seed + trial, noise=noise)
        for method in METHODS:
            bars = persistence(build_filtration(points, complex="witness", max_radius=max_radius, max_dim=2,
                                                landmark_method=method, n_landmarks=n_landmarks, nu=nu,
                                                seed=seed + trial), coefficients=2)
            h1 = bars.intervals(1)
            lengths = np.sort(np.minimum(h1[:, 1], max_radius) - h1[:, 0])[::-1]
            third[method].append(float(lengths[2]) if len(lengths) > 2 else 0.0)
            loops[method].append(len(long_bars(bars, dim=1, min_length=min_bar_length)))
    return LoopStudy(third={m: np.array(v) for m, v in third.items()},
                     loops={m: np.array(v) for m, v in loops.items()}, min_bar_length=min_bar_length)


@dataclass(frozen=True, kw_only=True)
class OutlierStudy:
    """The two methods on the circles with outliers added, per sample.

    Thesis: §2.1.2 (maxmin "tends to pick out extremal points") and §2.4.1 ("for a point set with
    several outliers a random approach may be better").

    Attributes
    ----------
    n_outliers : the outliers added to each sample.
    cover : method → the covering radius of the circle points by the method's landmarks that are not
        outliers, per sample (inf when every landmark is an outlier).
    wasted : method → the landmarks that are outliers, per sample.
    circles : the circle points of the last sample.
    cloud : the last sample, circle points first and then the outliers.
    landmarks : method → its landmark indices into ``cloud``.
    """

    n_outliers: int
    cover: dict[str, np.ndarray]
    wasted: dict[str, np.ndarray]
    circles: np.ndarray
    cloud: np.ndarray
    landmarks: dict[str, np.ndarray]

    @property
    def ratios(self) -> np.ndarray:
        """Maxmin's covering radius over random's, per sample (above 1 where random covers better)."""
        return self.cover["maxmin"] / self.cover["random"]

    @property
    def record(self) -> dict[str, float | int]:
        """The experiment's recorded values, by their names in ``results.json``."""
        return {
            "outlier_landmarks_mean_maxmin": float(np.mean(self.wasted["maxmin"])),
            "outlier_landmarks_mean_random": float(np.mean(self.wasted["random"])),
            "outlier_cover_median_maxmin": float(np.median(self.cover["maxmin"])),
            "outlier_cover_median_random": float(np.median(self.cover["random"])),
            "outlier_cover_ratio": float(np.median(self.ratios)),
            "outlier_random_better_trials": int(np.sum(self.ratios > 1)),
        }

    @property
    def count_record(self) -> dict[str, float | int]:
        """The median ratio and the samples where random is better, named by the number of outliers."""
        return {f"outlier_cover_ratio_{self.n_outliers}": float(np.median(self.ratios)),
                f"outlier_random_better_trials_{self.n_outliers}": int(np.sum(self.ratios > 1))}

    @property
    def summary(self) -> str:
        """The setting, one line per method (landmarks on outliers, covering radius), then their comparison."""
        n = len(self.ratios)
        n_landmarks = len(self.landmarks["maxmin"])
        lines = [f"{self.n_outliers} outliers among {len(self.circles)} circle points, {n_landmarks} landmarks, "
                 f"{n} samples:"]
        lines += [f"  {m:6s}: {np.mean(self.wasted[m]):5.1f} landmarks on outliers (mean);"
                  f" circles covered within {np.median(self.cover[m]):.3f}" for m in METHODS]
        lines.append(f"  random covers better in {int(np.sum(self.ratios > 1))} of {n} samples;"
                     f" median ratio {np.median(self.ratios):.2f}")
        return "\n".join(lines)


def outlier_study(*, n_per_circle: int, n_landmarks: int, seed: int, noise: float = 0.0, n_trials: int,
                  n_outliers: int, margin: float) -> OutlierStudy:
    """Both methods' landmarks on the circles with ``n_outliers`` uniform outliers, on ``n_trials`` samples.

    Thesis: §2.1.2 (maxmin "tends to pick out extremal points") and §2.4.1 ("for a point set with
    several outliers a random approach may be better").

    Sample ``t``: the circles with seed ``seed + t``, then ``n_outliers`` points uniform in their
    bounding box grown by ``margin`` on each side (``numpy.random.default_rng(seed + t)``); each
    method chooses ``n_landmarks`` landmarks on the whole set with seed ``seed + t``.

    Parameters
    ----------
    n_per_circle, n_landmarks, seed, noise, n_trials
        As :func:`cover_study`.
    n_outliers : int
        Outliers per sample (>= 1).
    margin : float
        How far the outliers' box reaches beyond the circles' on each side (>= 0).

    Returns
    -------
    OutlierStudy
        The wasted landmarks and covering radii per method and sample, and the last sample.

    Raises
    ------
    ValueError
        As :func:`cover_study`, ``n_outliers`` below 1 or a negative ``margin``.

    Examples
    --------
    >>> study = outlier_study(n_per_circle=200, n_landmarks=20, seed=0, n_trials=3, n_outliers=20, margin=1.5)
    >>> bool(study.wasted["maxmin"].mean() > study.wasted["random"].mean())  # maxmin picks the extremes
    True
    >>> study.cloud.shape
    (420, 2)
    """
    _check_sampling(n_per_circle, n_landmarks, seed, noise, n_trials)
    n_outliers = check_int(n_outliers, "n_outliers", minimum=1)
    margin = check_real(margin, "margin", minimum=0.0)
    cover: dict[str, list[float]] = {m: [] for m in METHODS}
    wasted: dict[str, list[int]] = {m: [] for m in METHODS}
    for trial in range(n_trials):
        circles = two_circles(n_per_circle, seed=seed + trial, noise=noise)
        rng = np.random.default_rng(seed + trial)
        low, high = circles.min(axis=0) - margin, circles.max(axis=0) + margin
        cloud = np.vstack([circles, rng.uniform(low, high, size=(n_outliers, 2))])
        chosen = {m: choose_landmarks(cloud, landmark_method=m, n=n_landmarks, seed=seed + trial) for m in METHODS}
        for method, idx in chosen.items():
            inliers = idx[idx < len(circles)]
            wasted[method].append(len(idx) - len(inliers))
            cover[method].append(covering_radius(circles, inliers) if len(inliers) else np.inf)
    return OutlierStudy(n_outliers=n_outliers, cover={m: np.array(v) for m, v in cover.items()},
                        wasted={m: np.array(v) for m, v in wasted.items()}, circles=circles, cloud=cloud,
                        landmarks=chosen)


def outlier_table(studies: Sequence[OutlierStudy]) -> str:
    """A Markdown table, one line per number of outliers: maxmin's landmarks on them, the median ratio of
    maxmin's covering radius to random's, and the samples where random covers better.

    Thesis: §2.4.1 ("for a point set with several outliers a random approach may be better").

    Parameters
    ----------
    studies : sequence of OutlierStudy
        One study per number of outliers (:func:`outlier_study`).

    Returns
    -------
    str
        The table, numbers right-aligned (no final newline).

    Examples
    --------
    >>> study = outlier_study(n_per_circle=100, n_landmarks=10, seed=0, n_trials=2, n_outliers=5, margin=1.5)
    >>> print(outlier_table([study]).splitlines()[1])
    |---:|---:|---:|---:|
    """
    rows = [f"| {s.n_outliers} | {np.mean(s.wasted['maxmin']):.1f} | {np.median(s.ratios):.2f} |"
            f" {int(np.sum(s.ratios > 1))} of {len(s.ratios)} |" for s in studies]
    return "\n".join(["| outliers | maxmin landmarks on them | maxmin / random | random better |",
                      "|---:|---:|---:|---:|", *rows])


def plot_landmarks(sample: LandmarkSample) -> Figure:
    """Figure 2.13: maxmin (∗) and random (+) landmarks (left) and the points (right), the two
    intersection points in green.

    Thesis: §2.4.1, Figure 2.13.

    Parameters
    ----------
    sample : LandmarkSample
        The points and both methods' landmarks (:func:`landmark_sample`).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels with shared axes, equal aspect.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_landmarks(landmark_sample(n_per_circle=50, n_landmarks=8, seed=0))
    >>> [ax.get_title() for ax in fig.axes]
    ['8 landmarks per method', '100 points']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing landmarks")
    points, maxmin, rand = sample.points, sample.landmarks["maxmin"], sample.landmarks["random"]
    crossings = two_circles_intersections()
    fig, (ax_l, ax_r) = plt.subplots(1, 2, figsize=(6.6, 3.3), sharex=True, sharey=True)
    ax_l.plot(*points[maxmin].T, "*", color=COLORS["first"], ms=8, label="maxmin")
    ax_l.plot(*points[rand].T, "+", color=COLORS["second"], ms=8, mew=1.5, label="random")
    ax_r.plot(*points.T, ".", color=COLORS["points"], ms=1.5)
    for ax in (ax_l, ax_r):
        ax.plot(*crossings.T, "o", color=COLORS["highlight"], ms=7)
        ax.set_aspect("equal")
    ax_l.legend(loc="lower left")
    ax_l.set_title(f"{len(maxmin)} landmarks per method")
    ax_r.set_title(f"{len(points)} points")
    return fig


def plot_outliers(study: OutlierStudy) -> Figure:
    """The last sample of :func:`outlier_study`: outliers, circle points, and both methods' landmarks.

    Thesis: §2.1.2 (maxmin "tends to pick out extremal points").

    Parameters
    ----------
    study : OutlierStudy
        The study whose last sample is drawn.

    Returns
    -------
    matplotlib.figure.Figure
        One panel, maxmin (∗) and random (+), the legend outside on the right.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> study = outlier_study(n_per_circle=50, n_landmarks=8, seed=0, n_trials=1, n_outliers=10, margin=1.5)
    >>> fig = plot_outliers(study)
    >>> [text.get_text() for text in fig.axes[0].get_legend().get_texts()]
    ['outliers', 'maxmin', 'random']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing landmarks")
    circles, cloud = study.circles, study.cloud
    fig, ax = plt.subplots(figsize=(4.8, 3.6))
    ax.plot(*cloud[len(circles):].T, ".", color=COLORS["points"], ms=3, label="outliers")
    ax.plot(*circles.T, ".", color="0.8", ms=1)
    for method, marker, color in (("maxmin", "*", COLORS["first"]), ("random", "+", COLORS["second"])):
        ax.plot(*cloud[study.landmarks[method]].T, marker, color=color, ms=7, label=method)
    ax.set_aspect("equal")
    ax.legend(loc="upper left", bbox_to_anchor=(1.0, 1.0))
    return fig

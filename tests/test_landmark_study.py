"""thesis_lib.applications.landmark_study: maxmin against random landmarks (thesis §2.1.2, §2.4.1)."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from scipy.spatial.distance import cdist  # noqa: E402

from thesis_lib.applications.landmark_study import (  # noqa: E402
    METHODS,
    cover_study,
    landmark_sample,
    loop_study,
    outlier_study,
    outlier_table,
    plot_landmarks,
    plot_outliers,
)
from thesis_lib.datasets import two_circles, two_circles_intersections  # noqa: E402
from thesis_lib.lab.experiments import ParameterError, resolve_parameters  # noqa: E402


def _cover(points, idx):
    """Covering radius by brute force: the largest distance to the nearest landmark."""
    return float(cdist(points, points[idx]).min(axis=1).max())


def test_a_sample_holds_both_methods_landmarks_drawn_with_its_seed():
    sample = landmark_sample(n_per_circle=60, n_landmarks=12, seed=3, noise=0.01)
    np.testing.assert_array_equal(sample.points, two_circles(60, seed=3, noise=0.01))
    assert list(sample.landmarks) == list(METHODS)
    for idx in sample.landmarks.values():
        assert len(idx) == 12 and len(set(idx.tolist())) == 12
    # the maxmin landmarks: each the farthest point from those before it
    lm = sample.landmarks["maxmin"]
    for i in range(1, len(lm)):
        d = cdist(sample.points, sample.points[lm[:i]]).min(axis=1)
        assert d[lm[i]] == pytest.approx(d.max())


@pytest.mark.parametrize("seed", [0, 7])
def test_cover_study_against_brute_force(seed):
    study = cover_study(n_per_circle=150, n_landmarks=15, seed=seed, near_radius=0.2, n_trials=3)
    crossings = two_circles_intersections()
    for t in range(3):
        sample = landmark_sample(n_per_circle=150, n_landmarks=15, seed=seed + t)
        for m in METHODS:
            idx = sample.landmarks[m]
            assert study.cover[m][t] == pytest.approx(_cover(sample.points, idx), rel=1e-12)
            near = int((cdist(sample.points[idx], crossings).min(axis=1) <= 0.2).sum())
            assert study.near[m][t] == near
    rec = study.record
    assert rec["covering_radius_maxmin"] == study.cover["maxmin"][0]
    assert rec["covering_radius_ratio"] == pytest.approx(study.cover["random"][0] / study.cover["maxmin"][0])
    assert rec["covering_radius_ratio_min"] == pytest.approx(min(study.ratios))
    # maxmin is a 2-approximation of the best covering, so random can beat it by a factor 2 at most
    assert np.all(study.ratios >= 0.5)
    assert study.summary.splitlines()[0].startswith(f"covering radius: maxmin {rec['covering_radius_maxmin']:.3f}")
    assert study.texts["ratio"] == f"{rec['covering_radius_ratio']:.2f}"


def test_loop_study_finds_the_three_loops_and_its_record_follows_its_bars():
    study = loop_study(n_per_circle=150, n_landmarks=30, seed=0, n_trials=3, max_radius=1.0, nu=1,
                       min_bar_length=0.1)
    for m in METHODS:
        assert study.loops[m].tolist() == [3, 3, 3]  # β₁ = 3 of the two circles
        assert np.all((study.third[m] > 0.1) & (study.third[m] <= 1.0))
    rec = study.record
    assert rec["witness_three_loops_trials_maxmin"] == 3
    ratios = study.third["maxmin"] / study.third["random"]
    assert rec["witness_third_bar_ratio_median"] == pytest.approx(np.median(ratios))
    assert rec["witness_third_bar_maxmin_longer_trials"] == int(np.sum(study.third["maxmin"] > study.third["random"]))
    assert len(study.summary.splitlines()) == 3


def test_outlier_study_against_an_independent_count():
    study = outlier_study(n_per_circle=100, n_landmarks=20, seed=1, n_trials=2, n_outliers=30, margin=1.0)
    circles = two_circles(100, seed=2)  # the last sample
    np.testing.assert_array_equal(study.circles, circles)
    outliers = study.cloud[len(circles):]
    assert outliers.shape == (30, 2)
    assert np.all(outliers >= circles.min(axis=0) - 1.0) and np.all(outliers <= circles.max(axis=0) + 1.0)
    for m in METHODS:
        idx = study.landmarks[m]
        inliers = idx[idx < len(circles)]
        assert study.wasted[m][-1] == len(idx) - len(inliers)
        assert study.cover[m][-1] == pytest.approx(_cover(circles, inliers), rel=1e-12)
    assert study.wasted["maxmin"].mean() > study.wasted["random"].mean()  # maxmin picks out extremal points
    assert study.count_record == {"outlier_cover_ratio_30": float(np.median(study.ratios)),
                                  "outlier_random_better_trials_30": int(np.sum(study.ratios > 1))}
    assert study.record["outlier_cover_ratio"] == study.count_record["outlier_cover_ratio_30"]
    assert study.summary.splitlines()[0] == "30 outliers among 200 circle points, 20 landmarks, 2 samples:"


def test_landmarks_all_on_outliers_leave_the_circles_uncovered():
    study = outlier_study(n_per_circle=5, n_landmarks=2, seed=0, n_trials=4, n_outliers=500, margin=50.0)
    all_out = study.wasted["maxmin"] == 2
    assert all_out.any()
    assert np.all(np.isinf(study.cover["maxmin"][all_out]))
    assert np.all(np.isfinite(study.cover["maxmin"][~all_out]))


def test_outlier_table_has_a_line_per_study():
    studies = [outlier_study(n_per_circle=80, n_landmarks=10, seed=0, n_trials=2, n_outliers=n, margin=1.5)
               for n in (5, 20)]
    lines = outlier_table(studies).splitlines()
    assert lines[:2] == ["| outliers | maxmin landmarks on them | maxmin / random | random better |",
                         "|---:|---:|---:|---:|"]
    s = studies[1]
    assert lines[3] == (f"| 20 | {s.wasted['maxmin'].mean():.1f} | {np.median(s.ratios):.2f} | "
                        f"{int((s.ratios > 1).sum())} of 2 |")


def test_the_figures_draw_the_landmarks():
    sample = landmark_sample(n_per_circle=40, n_landmarks=6, seed=0)
    fig = plot_landmarks(sample)
    left, right = fig.axes
    np.testing.assert_array_equal(left.lines[0].get_xydata(), sample.points[sample.landmarks["maxmin"]])
    np.testing.assert_array_equal(right.lines[0].get_xydata(), sample.points)
    plt.close(fig)
    study = outlier_study(n_per_circle=40, n_landmarks=6, seed=0, n_trials=1, n_outliers=8, margin=1.0)
    fig = plot_outliers(study)
    np.testing.assert_array_equal(fig.axes[0].lines[0].get_xydata(), study.cloud[80:])
    np.testing.assert_array_equal(fig.axes[0].lines[3].get_xydata(), study.cloud[study.landmarks["random"]])
    plt.close(fig)


@pytest.mark.parametrize("call, match", [
    (lambda: cover_study(n_per_circle=20, n_landmarks=5, seed=0, near_radius=0.1, n_trials=0), "n_trials"),
    (lambda: cover_study(n_per_circle=20, n_landmarks=5, seed=0, near_radius=-0.1, n_trials=1), "near_radius"),
    (lambda: cover_study(n_per_circle=20, n_landmarks=50, seed=0, near_radius=0.1, n_trials=1), "50 landmarks"),
    (lambda: landmark_sample(n_per_circle=20, n_landmarks=0, seed=0), "n_landmarks"),
    (lambda: landmark_sample(n_per_circle=20, n_landmarks=3, seed=-1), "seed"),
    (lambda: landmark_sample(n_per_circle=20, n_landmarks=3, seed=0, noise=-1.0), "noise"),
    (lambda: loop_study(n_per_circle=20, n_landmarks=5, seed=0, n_trials=1, max_radius=0.0, nu=1,
                        min_bar_length=0.1), "max_radius"),
    (lambda: loop_study(n_per_circle=20, n_landmarks=5, seed=0, n_trials=1, max_radius=1.0, nu=1,
                        min_bar_length=-1.0), "min_bar_length"),
    (lambda: outlier_study(n_per_circle=20, n_landmarks=5, seed=0, n_trials=1, n_outliers=0, margin=1.0),
     "n_outliers"),
    (lambda: outlier_study(n_per_circle=20, n_landmarks=5, seed=0, n_trials=1, n_outliers=3, margin=-1.0),
     "margin"),
])
def test_bad_inputs_are_refused_by_name(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize("key, value", [("outlier_counts", "[5, 0]"), ("n_trials", 0), ("n_outliers", 0),
                                        ("near_radius", -0.5)])
def test_the_experiments_ranges_are_checked_before_a_kernel_starts(key, value):
    with pytest.raises(ParameterError, match=key):
        resolve_parameters("two-circles-landmarks", {key: value})

"""lower_star_img and image_filtration: the lower-star filtration of a grayscale image, cross-checked against
ripser.lower_star_img (H0, 8 neighbours) and GUDHI's cubical complexes (H0 and H1, both connectivities) on
seeded random images, the complex itself, and the refusals."""

from __future__ import annotations

import gudhi
import numpy as np
import pytest
import ripser

from thesis_lib.persistence import Barcode, lower_star_img
from thesis_lib.persistence.lower_star import image_filtration

SHAPES = [(1, 1), (1, 7), (6, 1), (2, 2), (5, 8), (13, 9), (20, 20)]


def random_image(seed: int, shape: tuple[int, int]) -> np.ndarray:
    rng = np.random.default_rng(seed)
    if seed % 2:  # few levels: many ties
        return rng.integers(-3, 4, size=shape).astype(float)
    return rng.normal(size=shape).astype(np.float32).astype(float)  # exact in ripser.py's float32


def sorted_rows(dgm: np.ndarray) -> np.ndarray:
    dgm = np.asarray(dgm, dtype=float).reshape(-1, 2)
    dgm = dgm[dgm[:, 1] > dgm[:, 0]]
    return dgm[np.lexsort((dgm[:, 1], dgm[:, 0]))]


def gudhi_cubical(image: np.ndarray, connectivity: int) -> list[np.ndarray]:
    cells = {"top_dimensional_cells": image} if connectivity == 8 else {"vertices": image}
    cc = gudhi.CubicalComplex(**cells)
    cc.compute_persistence()
    return [sorted_rows(cc.persistence_intervals_in_dimension(d)) for d in (0, 1)]


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("shape", SHAPES)
def test_h0_is_ripsers_lower_star_img(seed, shape):
    image = random_image(seed, shape)
    ours = lower_star_img(image)
    assert np.array_equal(ours.intervals(0), sorted_rows(ripser.lower_star_img(image)))
    assert np.isinf(ours.intervals(0)[:, 1]).sum() == 1 and ours.intervals(0)[0, 0] == image.min()


@pytest.mark.parametrize("connectivity", [8, 4])
@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("shape", SHAPES)
def test_h0_and_h1_are_gudhis_cubical_complex(connectivity, seed, shape):
    image = random_image(seed + 10, shape)
    ours = lower_star_img(image, connectivity=connectivity)
    h0, h1 = gudhi_cubical(image, connectivity)
    assert np.array_equal(ours.intervals(0), h0)
    assert np.array_equal(ours.intervals(1), h1)
    assert ours.complete_dimensions == (0, 1)


def test_connectivity_decides_whether_diagonal_pixels_touch():
    checkerboard = np.array([[0.0, 3.0, 1.0], [3.0, 2.0, 3.0], [1.0, 3.0, 0.5]])
    eight = lower_star_img(checkerboard)
    four = lower_star_img(checkerboard, connectivity=4)
    # 8 neighbours: the corners meet the centre diagonally as soon as it enters at 2
    assert eight.intervals(0).tolist() == [[0.0, np.inf], [0.5, 2.0], [1.0, 2.0], [1.0, 2.0]]
    # 4 neighbours: everything waits for the 3s; the centre 2 is a minimum of its own
    assert four.intervals(0).tolist() == [[0.0, np.inf], [0.5, 3.0], [1.0, 3.0], [1.0, 3.0], [2.0, 3.0]]
    assert eight.intervals(1).size == four.intervals(1).size == 0


def test_a_ring_of_low_pixels_is_a_hole_until_the_middle_fills():
    image = np.full((5, 5), 1.0)
    image[1:4, 1:4] = 4.0
    image[2, 2] = 7.0
    for connectivity in (8, 4):
        bars = lower_star_img(image, connectivity=connectivity)
        assert bars.intervals(0).tolist() == [[1.0, np.inf]]
        # one hole: born when the ring of 1s closes, it shrinks to the 7 as the 4s come, and dies with it
        assert bars.intervals(1).tolist() == [[1.0, 7.0]]


def test_constant_and_integer_and_boolean_images():
    assert lower_star_img(np.full((3, 4), 2.5)).intervals(0).tolist() == [[2.5, np.inf]]
    mask = np.array([[True, False], [False, True]])
    assert lower_star_img(mask).intervals(0).tolist() == [[0.0, np.inf]]
    assert lower_star_img(mask, connectivity=4).intervals(0).tolist() == [[0.0, 1.0], [0.0, np.inf]]
    assert lower_star_img([[3, 1, 2]]).intervals(0).tolist() == [[1.0, np.inf]]


def test_the_barcode_is_a_barcode_and_its_diagrams_plot_and_compare():
    image = random_image(0, (8, 8))
    bars = lower_star_img(image)
    assert isinstance(bars, Barcode)
    assert len(bars.to_diagrams()) == 2
    np.testing.assert_array_equal(bars.to_diagrams()[0], bars.intervals(0))


@pytest.mark.parametrize("connectivity", [8, 4])
def test_the_filtration_is_the_lower_star_of_the_pixels(connectivity):
    image = random_image(3, (4, 5))
    m, n = image.shape
    filt = image_filtration(image, connectivity=connectivity)
    counts = [len(s) for s in filt.simplices]
    blocks = (m - 1) * (n - 1)
    if connectivity == 8:
        assert counts == [m * n, m * (n - 1) + (m - 1) * n + 2 * blocks, 4 * blocks, blocks]
    else:
        assert counts == [m * n + blocks, m * (n - 1) + (m - 1) * n + 4 * blocks, 4 * blocks]
    vertex_value = np.r_[image.ravel(), [image[i:i + 2, j:j + 2].max() for i in range(m - 1) for j in range(n - 1)]]
    for simplices, values in zip(filt.simplices, filt.values):
        assert np.array_equal(values, vertex_value[simplices].max(axis=1))
    pixels = np.arange(m * n).reshape(m, n)
    edges = {tuple(e) for e in filt.simplices[1].tolist()}
    grid_neighbours = {(int(pixels[i, j]), int(pixels[i + di, j + dj])) for i in range(m) for j in range(n)
                       for di, dj in ((0, 1), (1, 0), (1, 1), (1, -1))
                       if 0 <= i + di < m and 0 <= j + dj < n and (connectivity == 8 or di * dj == 0)}
    assert {tuple(sorted(e)) for e in grid_neighbours} == {e for e in edges if max(e) < m * n}


@pytest.mark.parametrize("bad, error, match", [
    (np.zeros(5), ValueError, "2-D"),
    (np.zeros((2, 2, 3)), ValueError, "2-D"),
    (np.zeros((0, 4)), ValueError, "empty"),
    ([], ValueError, "2-D"),
    (np.array([[0.0, np.nan]]), ValueError, r"pixel \(0, 1\) is nan"),
    (np.array([[0.0], [np.inf]]), ValueError, "must be finite"),
    ("image", TypeError, "2-D array of pixel values"),
    (None, TypeError, "2-D array of pixel values"),
    (np.array([[1 + 2j]]), TypeError, "complex"),
    ([[0.0, 1.0], [2.0]], TypeError, "numbers"),
    ([["a", "b"]], TypeError, "numbers"),
])
def test_bad_images_are_refused(bad, error, match):
    for call in (lower_star_img, image_filtration):
        with pytest.raises(error, match=match):
            call(bad)


@pytest.mark.parametrize("connectivity, error", [(6, ValueError), (0, ValueError), (8.0, TypeError),
                                                 ("8", TypeError), (True, TypeError)])
def test_bad_connectivity_is_refused(connectivity, error):
    with pytest.raises(error, match="connectivity"):
        lower_star_img(np.zeros((2, 2)), connectivity=connectivity)

"""The lower-star filtration of a grayscale image: its pixels as vertices, the sublevel sets of their values.

A pixel enters at its value and a simplex of the pixel grid at the largest value of its pixels (the
rule of :func:`~thesis_lib.morse.reduction.lower_star_filtration`, on this one complex; persistence does
not import from morse), so the complex at value t is the set of pixels ≤ t, joined as the
``connectivity`` says:

* ``connectivity=8`` (the default, as ``ripser.lower_star_img``): the flag complex of the 8-neighbour
  graph, i.e. in every 2×2 block of pixels all 6 edges, 4 triangles and the tetrahedron.  It is the
  nerve of the closed pixel squares, so its sublevel sets have the homotopy type of the union of the
  pixels ≤ t; its barcode is that of ``gudhi.CubicalComplex(top_dimensional_cells=image)``.
* ``connectivity=4``: the grid graph with each 2×2 block's square filled once its four pixels are in
  (the square is coned off from a vertex at its centre, entering at the largest of the four values);
  its barcode is that of ``gudhi.CubicalComplex(vertices=image)``.

The barcode is computed by :func:`~thesis_lib.persistence.persistence`, not by ripser or GUDHI.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .._validate import InvalidTypeError, check_int, check_size
from ..homology.filtration import Filtration
from .barcode import Barcode
from .engine import persistence

if TYPE_CHECKING:
    import numpy.typing as npt

__all__ = ["image_filtration", "lower_star_img"]

#: the neighbourhoods of a pixel that :func:`image_filtration` joins it to
CONNECTIVITIES = (4, 8)


def _image(image) -> np.ndarray:
    """The image as a finite, non-empty 2-D float64 array, or a clear TypeError/ValueError."""
    if isinstance(image, (str, bytes, dict, set, frozenset)) or image is None:
        raise InvalidTypeError(f"image must be a 2-D array of pixel values, got {type(image).__name__}")
    try:
        if np.iscomplexobj(image):
            raise TypeError(f"got complex numbers ({np.asarray(image).dtype})")
        arr = np.asarray(image, dtype=np.float64)
    except (TypeError, ValueError) as err:
        raise InvalidTypeError(f"image must be a 2-D array of pixel values (numbers): {err}") from None
    if arr.ndim != 2:
        raise ValueError(f"image must be a 2-D array (one grayscale channel), got shape {arr.shape}")
    if arr.size == 0:
        raise ValueError(f"image is empty (shape {arr.shape})")
    if not np.isfinite(arr).all():
        i, j = np.argwhere(~np.isfinite(arr))[0]
        raise ValueError(f"image: pixel ({i}, {j}) is {arr[i, j]}; pixel values must be finite")
    return arr


def _connectivity(connectivity) -> int:
    c = check_int(connectivity, "connectivity")
    if c not in CONNECTIVITIES:
        raise ValueError(f"connectivity must be 4 or 8 (the neighbours a pixel is joined to), got {c}")
    return c


def _grid_complex(m: int, n: int, connectivity: int) -> list[np.ndarray]:
    """The simplices of the complex on an m × n pixel grid (pixel (i, j) is vertex i·n + j; for
    connectivity 4 the centre of block (i, j) is vertex m·n + i·(n − 1) + j), one array per dimension."""
    ids = np.arange(m * n, dtype=np.int64).reshape(m, n)
    a, b = ids[:-1, :-1].ravel(), ids[:-1, 1:].ravel()  # each 2×2 block: a b
    c, d = ids[1:, :-1].ravel(), ids[1:, 1:].ravel()  # .................. c d
    horizontal = np.c_[ids[:, :-1].ravel(), ids[:, 1:].ravel()]
    vertical = np.c_[ids[:-1, :].ravel(), ids[1:, :].ravel()]
    if connectivity == 8:
        edges = np.r_[horizontal, vertical, np.c_[a, d], np.c_[b, c]]
        triangles = np.r_[np.c_[a, b, c], np.c_[a, b, d], np.c_[a, c, d], np.c_[b, c, d]]
        tops = [np.c_[a, b, c, d]]
        vertices = m * n
    else:
        centre = m * n + np.arange(a.size, dtype=np.int64)
        edges = np.r_[horizontal, vertical, np.c_[a, centre], np.c_[b, centre], np.c_[c, centre], np.c_[d, centre]]
        triangles = np.r_[np.c_[a, b, centre], np.c_[a, c, centre], np.c_[b, d, centre], np.c_[c, d, centre]]
        tops = []
        vertices = m * n + a.size
    arrays = [np.arange(vertices, dtype=np.int64).reshape(-1, 1), edges, triangles, *tops]
    return [np.sort(s, axis=1) if s.shape[1] > 1 else s for s in arrays]


def image_filtration(image: npt.ArrayLike, *, connectivity: int = 8) -> Filtration:
    """The lower-star filtration of a grayscale image: pixels are vertices, each simplex enters at the
    largest value of its pixels.

    Thesis: Definition 2.22 (a filtration: here the sublevel sets {pixels ≤ t} of the image).

    Parameters
    ----------
    image : array_like, shape (m, n)
        The pixel values (finite numbers; integers, floats or booleans).
    connectivity : {8, 4}
        The pixels a pixel is joined to: its 8 neighbours (default, as ``ripser.lower_star_img``;
        each 2×2 block spans a tetrahedron) or its 4 neighbours (each 2×2 block's square is filled
        when all four pixels are in, coned off from an extra vertex at its centre).

    Returns
    -------
    Filtration
        Vertex ``i·n + j`` is pixel ``(i, j)``; with ``connectivity=4`` the vertices from ``m·n`` on
        are the centres of the 2×2 blocks, row by row.

    Raises
    ------
    TypeError
        ``image`` is not numbers, or ``connectivity`` is not an integer.
    ValueError
        ``image`` is not 2-D, is empty or has a NaN or infinite pixel; ``connectivity`` is not 4 or
        8; the complex would have more than ``MAX_SIMPLICES`` simplices.

    Examples
    --------
    >>> filt = image_filtration([[0, 2], [2, 1]])
    >>> [len(s) for s in filt.simplices]  # 4 pixels, 6 edges, 4 triangles, 1 tetrahedron
    [4, 6, 4, 1]
    >>> filt.values[1].tolist()  # the diagonal edges (0, 3) and (1, 2) enter at 1 and 2
    [2.0, 2.0, 2.0, 2.0, 1.0, 2.0]
    """
    pixels = _image(image)
    connectivity = _connectivity(connectivity)
    m, n = pixels.shape
    blocks = (m - 1) * (n - 1)
    extra = 3 * blocks if connectivity == 8 else 5 * blocks  # per block: 2 diagonals, a tetrahedron / a centre, 4 edges
    check_size(m * n + m * (n - 1) + (m - 1) * n + 4 * blocks + extra, "simplices of the image's complex")
    arrays = _grid_complex(m, n, connectivity)
    values = pixels.ravel()
    if connectivity == 4:  # a block's centre enters with its square: at the largest of its four pixels
        corners = np.stack([pixels[:-1, :-1], pixels[:-1, 1:], pixels[1:, :-1], pixels[1:, 1:]])
        values = np.r_[values, corners.max(axis=0).ravel()]
    return Filtration(arrays, [values[s].max(axis=1) for s in arrays], validate=False)


def lower_star_img(image: npt.ArrayLike, *, connectivity: int = 8) -> Barcode:
    """The barcode (H0 and H1) of the lower-star filtration of a grayscale image.

    Thesis: Definition 2.22 (the sublevel sets of the image as a filtration) and Theorem 2.39.

    ``lower_star_img(image).intervals(0)`` is the diagram of ``ripser.lower_star_img(image)`` (a
    component is born at a local minimum and dies when it meets an older one); ``intervals(1)`` holds
    the holes, the regions of high values enclosed by lower ones.  Computed on the complex of
    :func:`image_filtration` by :func:`~thesis_lib.persistence.persistence` over Z/2.

    Parameters
    ----------
    image : array_like, shape (m, n)
        The pixel values (finite numbers; integers, floats or booleans).
    connectivity : {8, 4}
        Which pixels touch: 8 neighbours (default, as ripser.py; GUDHI's
        ``CubicalComplex(top_dimensional_cells=image)``) or 4 (``CubicalComplex(vertices=image)``).

    Returns
    -------
    Barcode
        Dimensions 0 and 1, in the image's values; one essential H0 bar, born at the smallest
        pixel.

    Raises
    ------
    TypeError
        ``image`` is not numbers, or ``connectivity`` is not an integer.
    ValueError
        ``image`` is not 2-D, is empty or has a NaN or infinite pixel; ``connectivity`` is not 4 or 8.

    Examples
    --------
    >>> image = [[0, 2], [2, 1]]
    >>> lower_star_img(image).intervals(0).tolist()  # the 1 touches the 0 diagonally, at value 1
    [[0.0, inf]]
    >>> lower_star_img(image, connectivity=4).intervals(0).tolist()  # it waits for a 2
    [[0.0, inf], [1.0, 2.0]]
    >>> lower_star_img([[0, 0, 0], [0, 5, 0], [0, 0, 0]]).intervals(1).tolist()  # a hole until 5
    [[0.0, 5.0]]
    """
    bars = persistence(image_filtration(image, connectivity=connectivity))
    return Barcode({0: bars.intervals(0), 1: bars.intervals(1)}, coefficients=bars.coefficients)

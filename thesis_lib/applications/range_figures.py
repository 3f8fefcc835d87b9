"""Figures of the range-image experiment (thesis §2.4.3): range images, and patches projected onto
the two gradient vectors of the DCT basis."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import check_int
from .range_images import dct_basis

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot_range_images", "plot_gradient_projection"]


def plot_range_images(images: Sequence[npt.ArrayLike], *, n: int = 3,
                      figsize: tuple[float, float] = (10.0, 2.6)) -> Figure:
    """The first ``n`` range images in grey (near is dark), out-of-range pixels black.

    Thesis: §2.4.3, Figure 2.21 (range images of the Brown database; here synthetic scenes).

    Parameters
    ----------
    images : sequence of array_like, each of shape (h, w)
        Range images, NaN where out of range.
    n : int, default 3
        How many to show (fewer if there are fewer).
    figsize : (float, float), default (10.0, 2.6)
        The figure size in inches.

    Returns
    -------
    matplotlib.figure.Figure
        One panel per image, axes off.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        No image, ``n`` below 1, an image that is not 2-D or holds no value in range.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from thesis_lib.applications.range_images import synthetic_range_image
    >>> fig = plot_range_images([synthetic_range_image(seed=0)], n=1)
    >>> len(fig.axes)
    1
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing range images")
    n = check_int(n, "n", minimum=1)
    shown = [np.asarray(img, dtype=np.float64) for img in list(images)[: int(n)]]
    if not shown:
        raise ValueError("no image to show")
    for i, img in enumerate(shown):
        if img.ndim != 2 or not np.any(np.isfinite(img)):
            raise ValueError(f"image {i} must be a 2-D array with a value in range, got shape {img.shape}")
    fig, axes = plt.subplots(1, len(shown), figsize=figsize, squeeze=False)
    for ax, img in zip(axes[0], shown):
        ax.imshow(np.where(np.isnan(img), 0.0, img), cmap="gray", vmin=0.0, vmax=np.nanmax(img))
        ax.axis("off")
    return fig


def plot_gradient_projection(coords: npt.ArrayLike, *, landmarks: npt.ArrayLike | None = None, size: int = 5,
                             figsize: tuple[float, float] = (7.0, 3.5)) -> Figure:
    """Patches projected onto the horizontal and vertical DCT gradients, beside the two basis patches.

    Thesis: §2.4.3, Figure 2.23 (the projection of X(300, 30) onto the two gradients: a circle).

    Parameters
    ----------
    coords : array_like, shape (n, 2)
        The projected patches (:func:`~thesis_lib.applications.range_images.gradient_projection`).
    landmarks : array_like of int, optional
        Indices of landmark patches, drawn as stars.
    size : int, default 5
        The patch side (for the two basis patches shown).
    figsize : (float, float), default (7.0, 3.5)
        The figure size in inches.

    Returns
    -------
    matplotlib.figure.Figure
        The projection (axes ``[-1.05, 1.05]²``), then the horizontal and the vertical basis patch.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).
    ValueError
        ``coords`` not an (n, 2) array, a landmark index out of range, or a bad ``size``.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_gradient_projection([[0.5, 0.5], [-0.7, 0.1]], landmarks=[1])
    >>> [ax.get_title() for ax in fig.axes]
    ['', 'horizontal', 'vertical']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the gradient projection")
    from ..graphics.style import COLORS

    c = np.asarray(coords, dtype=np.float64)
    if c.ndim != 2 or c.shape[1] != 2:
        raise ValueError(f"coords must be an (n, 2) array, got shape {c.shape}")
    basis = dct_basis(size=size)
    fig = plt.figure(figsize=figsize)
    ax = fig.add_axes([0.05, 0.1, 0.5, 0.8])
    ax.plot(*c.T, ".", ms=2, color=COLORS["points"])
    if landmarks is not None:
        idx = np.asarray(landmarks, dtype=np.int64)
        if idx.size and (idx.min() < 0 or idx.max() >= c.shape[0]):
            raise ValueError(f"landmark indices must lie in 0 .. {c.shape[0] - 1}")
        ax.plot(*c[idx].T, "*", ms=7, color=COLORS["first"], label="landmarks")
        ax.legend(loc="lower left")
    ax.set_aspect("equal")
    ax.set_xlim(-1.05, 1.05)
    ax.set_ylim(-1.05, 1.05)
    ax.set_xlabel("horizontal gradient")
    ax.set_ylabel("vertical gradient")
    for i, (row, label) in enumerate(((1, "horizontal"), (size, "vertical"))):
        sub = fig.add_axes([0.62, 0.55 - 0.45 * i, 0.3, 0.35])
        sub.imshow(basis[row].reshape(size, size), cmap="gray")
        sub.set_title(label)
        sub.axis("off")
    return fig

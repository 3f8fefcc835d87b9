"""One long bar among short ones: how far it stands out, and whether its cycle goes around the hole.

The situation of Figure 2.9: points sampled with noise from a circle, whose Čech filtration has many
short-lived cycles and one that persists.  The long bar is compared with the others, and each bar's
representative cycle is tested for winding around a point (the centre of the circle) by the parity
of its crossings of a ray.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .barcode import Barcode

__all__ = ["winding_parity", "LongBar", "long_bar_summary", "busiest_birth"]


def winding_parity(cycle: Sequence[tuple[tuple[int, ...], int]], points: npt.ArrayLike, *,
                   centre: tuple[float, float] = (0.0, 0.0)) -> int:
    """Whether a mod-2 cycle of edges in the plane winds around a point: its crossings of a ray, mod 2.

    Thesis: Figure 2.9 (the persistent cycle is the one of the "real" hole).

    The ray leaves ``centre`` along the positive x-axis; an edge crosses it when its ends lie on
    opposite sides of the line y = 0 (one with y > 0) and it meets the line right of the centre.

    Parameters
    ----------
    cycle : sequence of ((int, int), int)
        The edges of the cycle as ``(edge, coefficient)`` (:meth:`Barcode.representative`);
        coefficients are ignored (mod 2).
    points : array-like, shape (n, 2)
        The positions of the vertices.
    centre : (float, float), default (0, 0)
        The point the cycle may wind around.

    Returns
    -------
    int
        1 if the cycle winds an odd number of times around ``centre``, else 0.

    Raises
    ------
    ValueError
        ``points`` not of shape (n, 2), or a simplex of the cycle that is not an edge.

    Examples
    --------
    >>> square = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)]
    >>> cycle = [((0, 1), 1), ((1, 2), 1), ((2, 3), 1), ((0, 3), 1)]
    >>> winding_parity(cycle, square), winding_parity(cycle, square, centre=(3.0, 0.0))
    (1, 0)
    """
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise ValueError(f"points must have shape (n, 2), got {pts.shape}")
    pts = pts - np.asarray(centre, dtype=float)
    crossings = 0
    for edge, _ in cycle:
        if len(edge) != 2:
            raise ValueError(f"a cycle of edges was expected, got the simplex {tuple(edge)}")
        (x0, y0), (x1, y1) = pts[edge[0]], pts[edge[1]]
        if (y0 > 0) != (y1 > 0) and x0 - y0 * (x1 - x0) / (y1 - y0) > 0:
            crossings += 1
    return crossings % 2


@dataclass(frozen=True)
class LongBar:
    """The longest bar of a dimension beside the other bars of positive length.

    Attributes: ``index`` (its row in ``barcode.intervals(dim)``), ``birth``, ``death``, ``n_bars``
    (bars longer than ``min_length``, the long one included), ``second_length`` (the next longest
    length, 0 if none), ``ratio`` (longest length / second, ∞ if there is no second),
    ``last_noise_death`` (the latest death among the other bars, −∞ if none), ``betti_once_noise_dies``
    (β_dim at the later of that death and the long bar's birth), and, when points were given,
    ``n_enclosing`` (bars whose cycle winds around the centre), ``encloses`` (the long bar's does) and
    ``short_enclosing`` (the other bars whose cycle does); else None.
    """

    index: int
    birth: float
    death: float
    n_bars: int
    second_length: float
    ratio: float
    last_noise_death: float
    betti_once_noise_dies: int
    n_enclosing: int | None
    encloses: bool | None
    short_enclosing: int | None


def long_bar_summary(barcode: Barcode, *, dim: int = 1, min_length: float = 0.0, points: npt.ArrayLike | None = None,
                     centre: tuple[float, float] = (0.0, 0.0)) -> LongBar:
    """The longest bar of ``dim`` against the other bars longer than ``min_length``.

    Thesis: §2.3 and Figure 2.9 (one cycle persists for a significant filtration time, the others
    are noise).

    Parameters
    ----------
    barcode : Barcode
        The barcode; with ``points`` it must know its representatives (computed from a filtration).
    dim : int, default 1
        The homology dimension.
    min_length : float, default 0
        Bars no longer than this are left out (a triangle entering with its longest edge up to
        rounding gives a bar of length ~1e-16).
    points : array-like, shape (n, 2), optional
        The vertex positions: each bar's representative cycle is tested with :func:`winding_parity`.
    centre : (float, float), default (0, 0)
        The point the cycles may wind around.

    Returns
    -------
    LongBar
        The long bar, how it compares with the rest, and which cycles go around ``centre``.

    Raises
    ------
    ValueError
        No bar of ``dim`` longer than ``min_length``.

    Examples
    --------
    >>> bars = Barcode({1: [(0.0, 1.0), (0.2, 0.3), (0.25, 0.26)]})
    >>> s = long_bar_summary(bars)
    >>> s.index, s.n_bars, round(s.ratio, 6), s.last_noise_death, s.betti_once_noise_dies
    (0, 3, 10.0, 0.3, 1)
    """
    iv = barcode.intervals(dim)
    positive = np.flatnonzero(iv[:, 1] - iv[:, 0] > min_length)
    long_i = int(barcode.longest(dim, n=1)[0]) if iv.shape[0] else -1
    if long_i not in positive:
        raise ValueError(f"no bar of dimension {dim} is longer than min_length = {min_length}")
    lengths = iv[positive, 1] - iv[positive, 0]
    second = float(np.sort(lengths)[-2]) if len(lengths) > 1 else 0.0
    others = [float(iv[i, 1]) for i in positive if i != long_i]
    last_noise_death = max(others) if others else -math.inf
    birth = float(iv[long_i, 0])
    enclosing = None
    if points is not None:
        enclosing = {int(i): winding_parity(barcode.representative(dim, int(i)), points, centre=centre)
                     for i in positive}
    return LongBar(
        index=long_i,
        birth=birth,
        death=float(iv[long_i, 1]),
        n_bars=int(len(positive)),
        second_length=second,
        ratio=float(lengths.max() / second) if second else math.inf,
        last_noise_death=last_noise_death,
        betti_once_noise_dies=barcode.betti(max(last_noise_death, birth), dim=dim),
        n_enclosing=None if enclosing is None else sum(enclosing.values()),
        encloses=None if enclosing is None else bool(enclosing[long_i]),
        short_enclosing=None if enclosing is None else sum(v for i, v in enclosing.items() if i != long_i),
    )


def busiest_birth(barcode: Barcode, *, dim: int = 1) -> float:
    """The birth time at which the most bars of ``dim`` are alive at once (the first such, by birth).

    Thesis: §2.3 (many small cycles of a noisy sample alive together).

    Parameters
    ----------
    barcode : Barcode
        The barcode.
    dim : int, default 1
        The homology dimension.

    Returns
    -------
    float
        The birth b of an interval maximising β_dim(b).

    Raises
    ------
    ValueError
        No interval in ``dim``.

    Examples
    --------
    >>> busiest_birth(Barcode({1: [(0.0, 1.0), (0.5, 0.6), (0.55, 0.7), (0.8, 0.9)]}))
    0.55
    """
    iv = barcode.intervals(dim)
    if iv.shape[0] == 0:
        raise ValueError(f"no interval in dimension {dim}")
    alive = [barcode.betti(b, dim=dim) for b in iv[:, 0]]
    return float(iv[int(np.argmax(alive)), 0])

"""One entry point for the surface reconstructions of §3.4: the Crust or ball pivoting."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .crust import crust
from .pivoting import ball_pivoting

__all__ = ["RECONSTRUCTIONS", "reconstruct_surface"]

#: the algorithms :func:`reconstruct_surface` knows
RECONSTRUCTIONS = ("crust", "ball-pivoting")


def reconstruct_surface(
    points: ArrayLike, *, algorithm: str = "crust", theta: float = np.pi / 4, closed: bool = True
) -> NDArray[np.int64]:
    """Triangulate a point cloud sampled from a surface in R³; returns ``(m, 3)`` faces into ``points``.

    Thesis: §3.4, "Triangulations" (the Crust, used for Figures 3.8–3.11 and 3.14).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        The samples.
    algorithm : {"crust", "ball-pivoting"}, default "crust"
        The Crust algorithm [ABK98] (the thesis's choice) or ball pivoting (pymeshlab).
    theta : float, default π/4
        The Crust's normal-filter angle (ignored by ball pivoting).
    closed : bool, default True
        Whether the surface is closed: the Crust's trimming removes triangles with a free edge, which
        would eat a surface with boundary from its border, so it is switched off when False.

    Returns
    -------
    ndarray of int, shape (m, 3)
        Faces, consistently oriented by the Crust (outward for a closed surface).

    Raises
    ------
    ValueError
        On an unknown ``algorithm``, or from the reconstruction (:func:`~thesis_lib.reconstruction.crust`,
        :func:`~thesis_lib.reconstruction.pivoting.ball_pivoting`).
    """
    if algorithm == "crust":
        return crust(points, theta=theta, prune=bool(closed))
    if algorithm == "ball-pivoting":
        return ball_pivoting(points)
    raise ValueError(f"unknown reconstruction {algorithm!r}: use one of {RECONSTRUCTIONS}")

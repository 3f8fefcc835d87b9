"""Bottleneck and Wasserstein distances between persistence diagrams, computed by GUDHI or persim.

The thesis compares barcodes by eye (long bars against short ones, §2.3); these are the metrics that
make the comparison a number (Cohen-Steiner, Edelsbrunner & Harer 2007; Mileyko, Mukherjee & Harer
2011).  The optimal matchings are not computed here: :func:`bottleneck_distance` calls
``gudhi.bottleneck_distance`` or ``persim.bottleneck``, :func:`wasserstein_distance` calls
``gudhi.wasserstein.wasserstein_distance`` (which needs POT) or ``persim.wasserstein``, whichever is
installed (``backend=`` chooses).  Neither library is a dependency of thesis-lab.

Points at infinity (``death = inf``, the essential classes) are handled the same way by every
backend, as GUDHI does: they are matched only among themselves, by birth, so the distance is ``inf``
when the two diagrams have different numbers of them, and otherwise the optimal matching on the line
of births (the k-th smallest birth with the k-th smallest) adds its cost.  persim itself drops such
points with a warning; here its backend is given the finite points only and the essential ones are
matched by sorting their births, so both backends return the same number.
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence
from types import ModuleType
from typing import TYPE_CHECKING

import numpy as np

from .._validate import check_int, check_real, check_scale
from ._diagrams import parse_diagram, parse_diagrams
from .barcode import Barcode

if TYPE_CHECKING:
    import numpy.typing as npt

__all__ = ["BACKENDS", "bottleneck_distance", "wasserstein_distance"]

#: the libraries the distances delegate to, in the order ``backend=None`` tries them
BACKENDS = ("gudhi", "persim")


def _import(module: str) -> ModuleType | None:
    """The module, or None when it (or a package it needs) cannot be imported."""
    try:
        return importlib.import_module(module)
    except ImportError:
        return None


def _check_backend(backend) -> str | None:
    if backend is not None and backend not in BACKENDS:
        raise ValueError(f"backend must be one of {', '.join(map(repr, BACKENDS))} or None (the first installed), "
                         f"got {backend!r}")
    return backend


def _one_diagram(data, name: str, dim: int | None, scale: str | None) -> np.ndarray:
    """The ``(n, 2)`` diagram of ``data`` in dimension ``dim`` (a Barcode scaled by ``scale``)."""
    if isinstance(data, Barcode):
        if dim is None:
            raise ValueError(f"{name} is a Barcode: pass dim=, the homology dimension to compare")
        if scale is None:
            raise ValueError(f"{name} is a Barcode: pass scale='epsilon' (its own values, the thesis's ε) or "
                             "scale='diameter' (twice them: the values ripser.py, giotto-ph and persim give a "
                             "Rips complex)")
        if dim not in data.complete_dimensions:
            raise ValueError(f"{name} has no complete dimension {dim} (complete: "
                             f"{list(data.complete_dimensions)}; the top dimension of a truncated complex is not)")
        return parse_diagram(data.to_diagrams(dims=[dim], scale=scale)[dim], name)
    diagrams, single = parse_diagrams(data, name)
    if single:
        return diagrams[0]
    if dim is None:
        raise ValueError(f"{name} is a list of {len(diagrams)} diagrams (one per homology dimension): pass dim=")
    if dim >= len(diagrams):
        raise ValueError(f"{name} has no diagram of dimension {dim}: {len(diagrams)} diagrams given")
    return diagrams[dim]


def _diagram_pair(a, b, dim, scale) -> tuple[np.ndarray, np.ndarray]:
    """Both diagrams, checked once: ``dim`` an integer >= 0 or None, ``scale`` only for a Barcode."""
    dim = None if dim is None else check_int(dim, "dim", minimum=0)
    if scale is not None:
        check_scale(scale)
        if not isinstance(a, Barcode) and not isinstance(b, Barcode):
            raise ValueError("scale= applies to a Barcode; diagrams given as arrays are compared as they are")
    return _one_diagram(a, "a", dim, scale), _one_diagram(b, "b", dim, scale)


def _essential_births(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """The sorted births of the points at infinity of each diagram, or None if their numbers differ."""
    bx, by = np.sort(x[np.isinf(x[:, 1]), 0]), np.sort(y[np.isinf(y[:, 1]), 0])
    return (bx, by) if bx.shape == by.shape else None


def _finite(x: np.ndarray) -> np.ndarray:
    return x[np.isfinite(x[:, 1])]


def bottleneck_distance(a: Barcode | npt.ArrayLike | Sequence[npt.ArrayLike],
                        b: Barcode | npt.ArrayLike | Sequence[npt.ArrayLike], *, dim: int | None = None,
                        scale: str | None = None, backend: str | None = None) -> float:
    """The bottleneck distance: the least, over matchings of the points (or with the diagonal), of the
    largest L∞ distance of a matched pair.

    Thesis: §2.3, Theorem 2.37 (a barcode as the points of a diagram); the distance is beyond the thesis.

    Parameters
    ----------
    a, b : Barcode, array_like of shape (n, 2), or list of them
        The two diagrams: an ``(n, 2)`` array of ``(birth, death)`` (``death = inf`` for an
        essential class), a list of them, one per homology dimension (ripser.py's ``dgms``; ``dim``
        picks one), or a :class:`Barcode` (``dim`` and ``scale`` say which diagram).
    dim : int, optional
        The homology dimension to compare, needed for a Barcode or a list of diagrams.
    scale : {"epsilon", "radius", "diameter"}, optional
        Needed when ``a`` or ``b`` is a Barcode, and only then: its intervals are converted by
        :meth:`Barcode.to_diagrams` with this scale (``"epsilon"``: the barcode's own values, the
        thesis's ε; ``"diameter"``: twice them, as ripser.py reports a Rips complex).  Arrays are
        taken as they are.
    backend : {"gudhi", "persim"}, optional
        The library that computes the distance (default: GUDHI if installed, else persim); both
        compute it exactly (GUDHI with ``e=0``, not its default approximation).

    Returns
    -------
    float
        The distance; ``inf`` when the diagrams have different numbers of points at infinity (these
        are matched only among themselves, by birth: see the module's note).

    Raises
    ------
    ImportError
        Neither GUDHI nor persim is installed (or not the ``backend`` asked for); the message says
        ``pip install gudhi`` or ``pip install persim``.
    TypeError
        A diagram that is not numbers, or a ``dim`` that is not an integer.
    ValueError
        A diagram that is not ``(n, 2)``, a NaN, an infinite birth, a death before its birth; a
        Barcode without ``dim`` or ``scale``, or without that complete dimension; a list without
        ``dim`` or shorter than it; ``scale`` without a Barcode, an unknown ``scale`` or ``backend``.

    Examples
    --------
    >>> bottleneck_distance(np.array([[0.0, 1.0], [0.0, np.inf]]), np.array([[0.0, 1.25], [0.5, np.inf]]))
    0.5
    >>> bars = Barcode({0: [[0.0, 0.5], [0.0, np.inf]]})
    >>> bottleneck_distance(bars, [np.array([[0.0, 1.0], [0.0, np.inf]])], dim=0, scale="diameter")
    0.0
    """
    x, y = _diagram_pair(a, b, dim, scale)
    backend = _check_backend(backend)
    if backend in (None, "gudhi"):
        gudhi = _import("gudhi")
        if gudhi is not None:
            # e=0: the exact distance (GUDHI's default approximation gives 2.2e-308 for equal diagrams)
            return float(gudhi.bottleneck_distance(x, y, 0.0))  # GUDHI matches the points at infinity itself
        if backend == "gudhi":
            raise ImportError("bottleneck_distance(backend='gudhi') needs GUDHI; install it with: pip install gudhi")
    persim = _import("persim")
    if persim is None:
        raise ImportError("bottleneck_distance needs GUDHI or persim; install one with: pip install gudhi "
                          "(or: pip install persim)")
    births = _essential_births(x, y)
    if births is None:
        return float("inf")
    essential = float(np.abs(births[0] - births[1]).max(initial=0.0))
    return max(float(persim.bottleneck(_finite(x), _finite(y))), essential)


def wasserstein_distance(a: Barcode | npt.ArrayLike | Sequence[npt.ArrayLike],
                         b: Barcode | npt.ArrayLike | Sequence[npt.ArrayLike], *, order: float = 1.0,
                         internal_p: float = np.inf, dim: int | None = None, scale: str | None = None,
                         backend: str | None = None) -> float:
    """The q-Wasserstein distance: the least, over matchings of the points (or with the diagonal), of
    (Σ ‖x − y‖_p^q)^(1/q), with q = ``order`` and the L^p ground metric p = ``internal_p``.

    Thesis: §2.3, Theorem 2.37 (a barcode as the points of a diagram); the distance is beyond the thesis.

    Parameters
    ----------
    a, b : Barcode, array_like of shape (n, 2), or list of them
        The two diagrams, as for :func:`bottleneck_distance`.
    order : float
        The exponent q ≥ 1 (default 1).
    internal_p : float
        The ground metric's p ≥ 1, ``inf`` allowed (default ``inf``, GUDHI's: a point's distance to
        the diagonal is half its length).  persim computes ``order=1``, ``internal_p=2`` only.
    dim : int, optional
        The homology dimension to compare, needed for a Barcode or a list of diagrams.
    scale : {"epsilon", "radius", "diameter"}, optional
        Needed when ``a`` or ``b`` is a Barcode, and only then (see :func:`bottleneck_distance`).
    backend : {"gudhi", "persim"}, optional
        The library that computes the distance (default: GUDHI with POT if installed, else persim
        when it can compute this ``order`` and ``internal_p``).

    Returns
    -------
    float
        The distance; ``inf`` when the diagrams have different numbers of points at infinity (these
        are matched only among themselves, by birth, at cost |b − b'|^q: see the module's note).

    Raises
    ------
    ImportError
        No installed backend can compute it: the message says ``pip install gudhi pot`` (GUDHI's
        needs POT) or ``pip install persim``.
    TypeError
        A diagram that is not numbers, a ``dim`` that is not an integer, ``order`` or ``internal_p``
        not a number.
    ValueError
        As :func:`bottleneck_distance`; ``order`` below 1 or infinite, ``internal_p`` below 1; and
        ``backend="persim"`` with an ``order`` other than 1 or an ``internal_p`` other than 2.

    Examples
    --------
    >>> x, y = np.array([[0.0, 1.0], [0.0, np.inf]]), np.array([[0.0, 1.5], [0.5, np.inf]])
    >>> float(round(wasserstein_distance(x, y), 12))  # 0.5 to move (0, 1) up, 0.5 for the births at infinity
    1.0
    >>> float(round(wasserstein_distance(x, y, order=2.0), 12))  # sqrt(0.5² + 0.5²)
    0.707106781187
    """
    order = check_real(order, "order", minimum=1.0)
    internal_p = check_real(internal_p, "internal_p", minimum=1.0, finite=False)
    x, y = _diagram_pair(a, b, dim, scale)
    backend = _check_backend(backend)
    persim_can = order == 1.0 and internal_p == 2.0
    if backend == "persim" and not persim_can:
        raise ValueError(f"persim.wasserstein computes order=1 with internal_p=2 only, got order={order}, "
                         f"internal_p={internal_p}; use backend='gudhi' (pip install gudhi pot)")
    births = _essential_births(x, y)
    if births is None:
        return float("inf")
    if backend in (None, "gudhi"):
        gudhi_wasserstein = _import("gudhi.wasserstein") if _import("ot") is not None else None
        if gudhi_wasserstein is not None:  # GUDHI matches the points at infinity itself
            return float(gudhi_wasserstein.wasserstein_distance(x, y, order=order, internal_p=internal_p))
        if backend == "gudhi" or not persim_can:
            raise ImportError(f"wasserstein_distance with order={order}, internal_p={internal_p} needs GUDHI's, "
                              "which needs POT; install them with: pip install gudhi pot (persim computes "
                              "order=1, internal_p=2 only: pip install persim)")
    persim = _import("persim")
    if persim is None:
        raise ImportError("wasserstein_distance needs GUDHI with POT, or persim; install them with: "
                          "pip install gudhi pot (or: pip install persim)")
    return float(persim.wasserstein(_finite(x), _finite(y))) + float(np.abs(births[0] - births[1]).sum())

"""Persistence diagrams given as arrays (the ripser/persim formats), parsed once at the public edge.

A *diagram* is an ``(n, 2)`` array of ``(birth, death)`` rows, ``death = inf`` for an essential class
(an empty one may have any shape of size 0); ripser's ``dgms`` is a list of them, one per homology
dimension.  :func:`parse_diagrams` tells the two apart and checks each diagram: numbers, the shape,
no NaN, finite births, no death before its birth.  Used by the plots and the distances.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .._validate import InvalidTypeError, float_array

__all__ = ["parse_diagram", "parse_diagrams"]


def parse_diagram(value, what: str) -> np.ndarray:
    """One diagram as a float64 ``(n, 2)`` array (a new one: writable); ``what`` names it in errors.

    Raises InvalidTypeError (not numbers) or ValueError (a shape other than ``(n, 2)``, a NaN, an
    infinite birth, a death before its birth).
    """
    arr = float_array(value, kind="(birth, death) values",
                      message=f"{what} must be an (n, 2) array of (birth, death) numbers")
    if arr.size == 0:
        return np.empty((0, 2), dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ValueError(f"{what} must be an (n, 2) array of (birth, death), got shape {arr.shape}")
    if np.isnan(arr).any():
        raise ValueError(f"{what} has a NaN in row {int(np.argmax(np.isnan(arr).any(axis=1)))}")
    if not np.isfinite(arr[:, 0]).all():
        raise ValueError(f"{what}: births must be finite, row {int(np.argmax(~np.isfinite(arr[:, 0])))} is "
                         f"{tuple(arr[int(np.argmax(~np.isfinite(arr[:, 0])))])}")
    if (arr[:, 1] < arr[:, 0]).any():
        i = int(np.argmax(arr[:, 1] < arr[:, 0]))
        raise ValueError(f"{what}: row {i} ({arr[i, 0]}, {arr[i, 1]}) dies before it is born")
    return np.array(arr, dtype=np.float64)


def _is_diagram_like(item) -> bool:
    """An item of a list that is a diagram (2-D, or empty) rather than a (birth, death) row."""
    return np.ndim(item) == 2 or np.size(item) == 0


def parse_diagrams(value, what: str) -> tuple[list[np.ndarray], bool]:
    """``(diagrams, single)``: a list of checked diagrams and whether ``value`` was one diagram.

    ``value`` is one diagram (an ``(n, 2)`` array or a list of ``(birth, death)`` rows) or a list of
    diagrams (ripser's ``dgms``); an empty array or an empty list is one empty diagram.  Anything
    else (a dict, a string, a 3-D array, a list mixing rows and diagrams) is refused.
    """
    if isinstance(value, np.ndarray) or not isinstance(value, Sequence) or isinstance(value, (str, bytes)):
        return [parse_diagram(value, what)], True
    if len(value) == 0:
        return [np.empty((0, 2), dtype=np.float64)], True
    try:
        kinds = {_is_diagram_like(item) for item in value}
    except (TypeError, ValueError):  # ragged items: np.ndim cannot tell
        kinds = {True, False}
    if kinds == {True}:
        return [parse_diagram(item, f"{what}[{k}]") for k, item in enumerate(value)], False
    if kinds == {False}:
        return [parse_diagram(value, what)], True
    raise InvalidTypeError(f"{what} must be one (n, 2) diagram or a list of them (one per homology dimension), "
                           "got a list mixing (birth, death) rows and diagrams")

"""One matplotlib style for every figure of the book."""

from __future__ import annotations

import matplotlib as mpl

__all__ = ["apply", "COLORS"]

#: colours by role (data points, first method, second method, highlights, per homology dimension)
COLORS = {
    "points": "#9a9a9a",
    "first": "#c0392b",
    "second": "#2471a3",
    "highlight": "#1e8449",
    "dims": ["#c0392b", "#2471a3", "#1e8449", "#7d3c98"],
}


def apply() -> None:
    """Set the book's matplotlib defaults (sizes, fonts, no time stamps in saved files)."""
    mpl.rcParams.update(
        {
            "figure.figsize": (7.0, 3.6),
            "figure.dpi": 100,
            "savefig.dpi": 110,
            "font.size": 10,
            "axes.titlesize": 11,
            "axes.spines.top": False,
            "axes.spines.right": False,
            "svg.hashsalt": "thesis-lab",
        }
    )

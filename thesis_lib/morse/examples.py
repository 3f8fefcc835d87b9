"""Small inputs of chapter 4: the RP² triangulation with the gradient field of Example 4.43."""

from __future__ import annotations

from .._validate import check_seed
from ._cells import Simplex

__all__ = [
    "RP2_FACETS", "rp2_gradient_field", "rp2_chart", "example_4_45", "experiment_complex", "experiment_matching",
    "COMPLEX_NAMES",
]

#: The 6-vertex RP² of Example 2.21 / Figure 2.7 with a, b, c, d, e, f = 0, ..., 5
#: (abd, adf, afc, bcd, ced, cae, abe, bfe, bcf, def).
RP2_FACETS: list[Simplex] = [
    (0, 1, 3), (0, 3, 5), (0, 2, 5), (1, 2, 3), (2, 3, 4),
    (0, 2, 4), (0, 1, 4), (1, 4, 5), (1, 2, 5), (3, 4, 5),
]


def rp2_gradient_field() -> list[tuple[Simplex, Simplex]]:
    """An acyclic gradient field on ``RP2_FACETS`` with the critical cells of Example 4.43.

    Thesis: Example 4.43 / Figure 4.6 (critical a, σ = ac and one triangle τ; two gradient paths
    σ → a of multiplicities ±1, two paths τ → σ of multiplicity +1, so ∂̃τ = 2σ and ∂̃σ = 0).

    The figure itself is not in the text; this field is one that matches every statement the text
    makes about it (τ = ace, vertices flowing to a along a spanning tree).

    Returns
    -------
    list of (tuple, tuple)
        The 14 pairs ``(sigma, tau)`` of the field, sigma a facet of tau.

    Examples
    --------
    >>> from thesis_lib.morse import critical_cells, is_acyclic
    >>> field = rp2_gradient_field()
    >>> critical_cells(RP2_FACETS, field), is_acyclic(RP2_FACETS, field)  # a, σ = ac and τ = ace
    ([[(0,)], [(0, 2)], [(0, 2, 4)]], True)
    """
    return [
        ((0, 3), (0, 3, 5)), ((0, 4), (0, 1, 4)), ((0, 5), (0, 2, 5)), ((1,), (0, 1)),
        ((1, 3), (0, 1, 3)), ((1, 5), (1, 4, 5)), ((2,), (1, 2)), ((2, 3), (1, 2, 3)),
        ((2, 4), (2, 3, 4)), ((2, 5), (1, 2, 5)), ((3,), (3, 4)), ((3, 5), (3, 4, 5)),
        ((4,), (1, 4)), ((5,), (4, 5)),
    ]


def rp2_chart() -> dict[Simplex, list[tuple[float, float]]]:
    """Plane coordinates of the corners of every triangle of ``RP2_FACETS`` in the disc picture
    of RP² (Figure 2.7): inner triangle d, e, f; outer hexagon a, b, c, a, b, c with antipodal
    points identified.  Maps each triangle (sorted vertices) to the positions of its vertices.

    Thesis: Figure 2.7 (triangulation of RP²), used to draw Figure 4.6.

    Returns
    -------
    dict of tuple to list of (float, float)
        For each triangle of ``RP2_FACETS``, the (x, y) positions of its three vertices, in the
        triangle's vertex order; the chart argument of
        :func:`~thesis_lib.morse.plotting.draw_gradient_field`.

    Examples
    --------
    >>> chart = rp2_chart()
    >>> len(chart), [tuple(round(x, 3) for x in corner) for corner in chart[(0, 1, 3)]]
    (10, [(0.0, 1.0), (0.866, 0.5), (0.39, 0.225)])
    """
    import numpy as np

    ang = np.pi / 2 - np.arange(6) * np.pi / 3  # hexagon P0..P5 clockwise from the top
    hexagon = [(float(np.cos(t)), float(np.sin(t))) for t in ang]  # a, b, c, a, b, c
    inner = {v: (0.45 * float(np.cos(ang[k])), 0.45 * float(np.sin(ang[k]))) for v, k in ((3, 1), (4, 3), (5, 5))}
    corner_copy = {  # which hexagon copy of a, b, c each triangle uses
        (0, 1, 3): {0: 0, 1: 1}, (1, 2, 3): {1: 1, 2: 2}, (0, 2, 4): {2: 2, 0: 3}, (0, 1, 4): {0: 3, 1: 4},
        (1, 2, 5): {1: 4, 2: 5}, (0, 2, 5): {2: 5, 0: 0}, (2, 3, 4): {2: 2}, (0, 3, 5): {0: 0},
        (1, 4, 5): {1: 4}, (3, 4, 5): {},
    }
    out = {}
    for t in RP2_FACETS:
        pos = corner_copy[t]
        out[t] = [hexagon[pos[v]] if v in pos else inner[v] for v in t]
    return out


def example_4_45() -> tuple[list[Simplex], list[tuple[Simplex, Simplex]]]:
    """A small complex and an acyclic modified Hasse diagram with critical v_2 and e_23.

    Thesis: Example 4.45 / Figures 4.7–4.8 (two critical simplices, so K ≃ S¹ by Example 4.29).
    The complex of Figure 4.7 is not in the text; this one (a filled triangle 123 with a path
    2–4–3) has the stated critical simplices.

    Returns
    -------
    simplices : list of tuple
        The facets (123, 24, 34).
    pairs : list of (tuple, tuple)
        The acyclic vector field, pairs ``(sigma, tau)``.

    Examples
    --------
    >>> from thesis_lib.morse import critical_cells
    >>> simplices, pairs = example_4_45()
    >>> critical_cells(simplices, pairs)  # v_2 and e_23
    [[(2,)], [(2, 3)], []]
    """
    simplices = [(1, 2, 3), (2, 4), (3, 4)]
    pairs = [((1,), (1, 2)), ((1, 3), (1, 2, 3)), ((3,), (3, 4)), ((4,), (2, 4))]
    return simplices, pairs


COMPLEX_NAMES = ("rp2", "torus", "klein", "dunce-hat", "random-flag", "rips")


def experiment_complex(name: str, *, seed: int = 0) -> tuple[
    list[Simplex], dict[int, tuple[float, float]] | None, dict[Simplex, list[tuple[float, float]]] | None
]:
    """The complexes of the ``rp2-morse`` experiment: ``(facets, positions, chart)``.

    Thesis: §4.2 (RP² of Example 4.43; other triangulations of §2.2.1; small flag and Rips complexes).

    Parameters
    ----------
    name : str
        One of ``COMPLEX_NAMES``: ``"rp2"``, ``"torus"``, ``"klein"``, ``"dunce-hat"``,
        ``"random-flag"`` (the flag complex of 14 uniform points in the unit square at ε = 0.2,
        edges of length ≤ 0.4) or ``"rips"`` (the Rips complex of ``two_circles(30, seed=seed)`` at
        ε = 0.3), both up to dimension 2.
    seed : int, default 0
        The random draw of the point-cloud complexes (ignored by the triangulations).

    Returns
    -------
    facets : list of tuple
        The simplices (for the point-cloud complexes every simplex, in filtration order).
    positions : dict of int to (float, float) or None
        Vertex → plane position for the point-cloud complexes, else None.
    chart : dict or None
        The disc picture of RP² (:func:`rp2_chart`) for ``"rp2"``, else None.

    Raises
    ------
    ValueError
        An unknown name.

    Examples
    --------
    >>> facets, positions, chart = experiment_complex("random-flag", seed=0)
    >>> len(facets), len(positions), chart is None
    (62, 14, True)
    """
    from ..complexes.rips import rips
    from ..datasets import dunce_hat, klein_bottle, torus, two_circles

    if name == "rp2":
        return list(RP2_FACETS), None, rp2_chart()
    if name == "torus":
        return torus(), None, None
    if name == "klein":
        return klein_bottle(), None, None
    if name == "dunce-hat":
        return dunce_hat(), None, None
    if name in ("random-flag", "rips"):
        import numpy as np

        if name == "random-flag":
            pts = np.random.default_rng(check_seed(seed)).random((14, 2))
            filt = rips(pts, max_radius=0.2, max_dim=2)
        else:
            pts = two_circles(30, seed=seed)
            filt = rips(pts, max_radius=0.3, max_dim=2)
        facets = [s for s, _ in filt]
        return facets, {i: (float(x), float(y)) for i, (x, y) in enumerate(pts)}, None
    raise ValueError(f"complex must be one of {', '.join(COMPLEX_NAMES)}, got {name!r}")


def experiment_matching(facets: list[Simplex], *, heuristic: str,
                        positions: dict[int, tuple[float, float]] | None = None,
                        seed: int = 0) -> list[tuple[Simplex, Simplex]]:
    """The gradient of the ``rp2-morse`` experiment: :func:`~thesis_lib.morse.morse_matching` by ``heuristic``.

    Thesis: §4.2.6 (heuristic acyclic matchings).  For ``"lower-star"`` the vertex values are the
    x-coordinates of ``positions`` when the complex is drawn in the plane, else uniform random
    numbers drawn with ``seed``; the greedy heuristics break ties at random with ``seed``.

    Parameters
    ----------
    facets : list of tuple
        The complex (as :func:`experiment_complex` returns it).
    heuristic : {"coreduction", "collapse", "lower-star"}
        As :func:`~thesis_lib.morse.morse_matching`.
    positions : dict of int to (float, float), optional
        Vertex → plane position (:func:`experiment_complex`'s second value).
    seed : int, default 0
        Seed of the random vertex values or of the tie-breaking.

    Returns
    -------
    list of (tuple, tuple)
        The pairs ``(sigma, tau)``, as :func:`~thesis_lib.morse.morse_matching`.

    Raises
    ------
    ValueError
        An unknown heuristic, an invalid seed, or positions missing a vertex.

    Examples
    --------
    >>> from thesis_lib.morse import critical_counts
    >>> critical_counts(RP2_FACETS, experiment_matching(list(RP2_FACETS), heuristic="lower-star", seed=0))
    [1, 1, 1]
    """
    import numpy as np

    from .matching import morse_matching

    if heuristic != "lower-star":
        return morse_matching(facets, heuristic=heuristic, seed=seed)
    n_vertices = max(v for s in facets for v in s) + 1
    if positions:
        missing = [v for v in range(n_vertices) if v not in positions]
        if missing:
            raise ValueError(f"positions has no entry for vertices {missing[:5]}")
        values = np.array([positions[v][0] for v in range(n_vertices)])
    else:
        values = np.random.default_rng(check_seed(seed)).random(n_vertices)
    return morse_matching(facets, heuristic="lower-star", values=values)

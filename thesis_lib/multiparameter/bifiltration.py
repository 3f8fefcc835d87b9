"""A one-critical bifiltration: every simplex with its pair of grades (ε, κ).

The thesis's Summary (Chapter 5): "a filtration varying with both the familiar radius ε and a
curvature parameter κ.  With ordinary persistent homology we must fix either ε or κ".  Here K_{ε,κ}
is the subcomplex of the simplices σ with ε(σ) ≤ ε and κ(σ) ≤ κ, where ε(σ) is the simplex's value
in a Rips or alpha filtration (Definitions 2.11 and 2.14) and κ(σ) the largest value of a vertex
function on its vertices (sublevel sets of |κ| or κ, the curvature estimated at each point).  Both
grades are monotone on faces, so K_{ε,κ} ⊆ K_{ε',κ'} whenever ε ≤ ε' and κ ≤ κ'.

Stored compactly, as :class:`~thesis_lib.homology.filtration.Filtration`: one vertex array and one
``(m_d, 2)`` grade array per dimension.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from .._validate import check_choice, check_max_dim, check_radius, parse_points
from ..complexes import alpha
from ..complexes.rips import rips_filtration
from ..homology.filtration import Filtration, as_complex

__all__ = ["Bifiltration", "function_bifiltration", "radius_curvature_bifiltration", "COMPLEX_KINDS"]

COMPLEX_KINDS = ("rips", "alpha")


class Bifiltration:
    """A one-critical bifiltration K_{ε,κ}: simplices with two grades each.

    Thesis: Chapter 5 (a filtration in the radius ε and a curvature parameter κ); each grade
    alone is a filtration in the sense of Definition 2.22.

    Parameters
    ----------
    simplices : sequence of ``(m_d, d + 1)`` int arrays, one per dimension (rows ascending).
    grades : sequence of ``(m_d, 2)`` float arrays: column 0 the ε-grade, column 1 the κ-grade.
    max_homology_dim : the largest homology dimension the complex determines (the top dimension
        of a Rips complex truncated at ``max_dim`` is incomplete: ``max_dim - 1``); default the
        complex's dimension.
    validate : check shapes, NaN grades and that faces have grades no larger than their cofaces.
    """

    def __init__(self, simplices: Sequence[np.ndarray], grades: Sequence[np.ndarray], *,
                 max_homology_dim: int | None = None, validate: bool = True):
        if len(simplices) != len(grades) or len(simplices) == 0:
            raise ValueError("simplices and grades must have one (non-empty list of) array per dimension each")
        self.grades = [np.asarray(g, dtype=np.float64).reshape(-1, 2) for g in grades]
        if validate and any(np.isnan(g).any() for g in self.grades):
            d = next(d for d, g in enumerate(self.grades) if np.isnan(g).any())
            raise ValueError(f"dimension {d} has a NaN grade")
        # a Filtration on the ε-grade holds the simplices and checks faces (validated once)
        self._eps = Filtration(simplices, [g[:, 0] for g in self.grades], validate=validate)
        self.simplices = self._eps.simplices
        if validate:
            self._validate()
        top = self._eps.dimension
        self.max_homology_dim = top if max_homology_dim is None else min(int(max_homology_dim), top)

    def _validate(self) -> None:
        for d, (s, g) in enumerate(zip(self.simplices, self.grades)):
            if s.shape[0] != g.shape[0]:
                raise ValueError(f"dimension {d}: {s.shape[0]} simplices but {g.shape[0]} grade pairs")
        for d in range(1, self.dimension + 1):
            faces = self._eps.facet_indices(d)
            if np.any(self.grades[d - 1][faces, 1] > self.grades[d][:, None, 1]):
                raise ValueError(f"a face of a {d}-simplex has a larger κ-grade than the simplex")

    # ------------------------------------------------------------------ queries
    @property
    def dimension(self) -> int:
        """Largest simplex dimension."""
        return self._eps.dimension

    def __len__(self) -> int:
        return len(self._eps)

    def counts(self) -> list[int]:
        """Number of simplices in each dimension.

        Returns
        -------
        list of int
            ``m_d`` for d = 0..dimension."""
        return self._eps.counts()

    def bounds(self) -> np.ndarray:
        """The box of the grades: ``[[ε_min, κ_min], [ε_max, κ_max]]`` over all simplices.

        Returns
        -------
        ndarray of float64, shape (2, 2)
            Row 0 the smallest grades, row 1 the largest."""
        allg = np.concatenate(self.grades)
        return np.stack([allg.min(axis=0), allg.max(axis=0)])

    def facet_indices(self, d: int) -> np.ndarray:
        """The facets of the d-simplices, as :meth:`thesis_lib.homology.filtration.Filtration.facet_indices`.

        Parameters
        ----------
        d : int
            A dimension, 1 ≤ d ≤ :attr:`dimension`.

        Returns
        -------
        ndarray of int, shape (m_d, d + 1)
            Indices into ``simplices[d - 1]``; column ``i`` is the facet omitting vertex ``i``."""
        return self._eps.facet_indices(d)

    def filtration(self, values: Sequence[np.ndarray], *, keep: Sequence[np.ndarray] | None = None) -> Filtration:
        """The one-parameter filtration of the simplices ``keep`` (masks) with ``values`` (per dimension).

        Parameters
        ----------
        values : sequence of ndarray
            ``values[d]`` one value per d-simplex; must be monotone on faces (as every line or path
            through the grades is).  Not checked.
        keep : sequence of bool ndarray, optional
            ``keep[d]`` selects the d-simplices kept; they must form a subcomplex (not checked).
            Default all.

        Returns
        -------
        Filtration
            The kept simplices with their values, empty top dimensions dropped.
        """
        if keep is None:
            return Filtration(self.simplices, values, validate=False)
        simp = [s[k] for s, k in zip(self.simplices, keep)]
        vals = [v[k] for v, k in zip(values, keep)]
        while simp and simp[-1].shape[0] == 0:
            simp.pop()
            vals.pop()
        return Filtration(simp, vals, validate=False)

    def subcomplex(self, radius: float, curvature: float) -> Filtration | None:
        """K_{ε,κ} as a filtration by ε (None when empty).

        Thesis: Chapter 5 (the complex at one value of both parameters).

        Parameters
        ----------
        radius : float
            The radius grade ε: simplices with ε(σ) ≤ radius.
        curvature : float
            The curvature grade κ: simplices with κ(σ) ≤ curvature.

        Returns
        -------
        Filtration or None
            K_{ε,κ}, filtered by the ε-grades; None when no vertex is in it.
        """
        keep = [(g[:, 0] <= radius) & (g[:, 1] <= curvature) for g in self.grades]
        if not keep[0].any():
            return None
        return self.filtration([g[:, 0] for g in self.grades], keep=keep)

    def __repr__(self) -> str:
        return (f"Bifiltration(dimension={self.dimension}, counts={self.counts()}, "
                f"max_homology_dim={self.max_homology_dim})")


def _vertex_values(values, labels: np.ndarray, name: str) -> np.ndarray:
    try:
        v = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError) as err:
        raise ValueError(f"{name} must be an array of numbers, one per point: {err}") from None
    if v.ndim != 1:
        raise ValueError(f"{name} must be one number per point, got shape {v.shape}")
    if labels.size and labels.max() >= v.shape[0]:
        raise ValueError(f"{name} has {v.shape[0]} values but the complex has a vertex {int(labels.max())}")
    bad = ~np.isfinite(v[labels])
    if bad.any():
        rows = labels[bad]
        raise ValueError(
            f"{name} is NaN or infinite at {rows.size} of {labels.size} points (rows {rows[:5].tolist()}"
            f"{', ...' if rows.size > 5 else ''}): a curvature estimate can be undefined at a boundary "
            "vertex or a degenerate neighbourhood; drop those points or give them a value")
    return v


def function_bifiltration(filtration: Filtration, vertex_values: npt.ArrayLike, *,
                          max_homology_dim: int | None = None, name: str = "vertex_values") -> Bifiltration:
    """The bifiltration (filtration value, largest vertex value): σ ∈ K_{ε,κ} iff its value is ≤ ε
    and f(v) ≤ κ at each of its vertices (the sublevel sets of f on the filtered complex).

    Thesis: Chapter 5 (ε and a second parameter κ on the same complex).

    Parameters
    ----------
    filtration : Filtration
        Its values are the ε-grades (anything :func:`~thesis_lib.homology.filtration.as_complex` turns into
        a Filtration with values).
    vertex_values : array_like, shape (n_points,)
        f, one number per point (indexed by vertex label); finite at every vertex of the complex.
    max_homology_dim : int, optional
        The largest homology dimension the complex determines (see :class:`Bifiltration`).
    name : str, default "vertex_values"
        What the values are called in error messages.

    Returns
    -------
    Bifiltration
        Grades (value of σ, max of f on the vertices of σ) for every simplex.

    Raises
    ------
    ValueError
        Vertex values that are not 1-D numbers, do not reach the largest vertex label, or are NaN or
        infinite at a vertex (the rows named).
    """
    K = as_complex(filtration)
    labels = K.simplices[0][:, 0]
    f = _vertex_values(vertex_values, labels, name)
    grades = [np.column_stack([K.values[d], f[s].max(axis=1)]) for d, s in enumerate(K.simplices)]
    return Bifiltration(K.simplices, grades, max_homology_dim=max_homology_dim, validate=False)


def radius_curvature_bifiltration(points: npt.ArrayLike, curvature: npt.ArrayLike, *, complex: str = "rips",
                                  max_radius: float = np.inf, max_dim: int = 2,
                                  absolute: bool = True) -> Bifiltration:
    """The radius × curvature bifiltration of a point cloud: Rips or alpha in ε, sublevel sets of
    |κ| (or κ) in the second parameter.

    Thesis: Chapter 5 ("a filtration varying with both the familiar radius ε and a curvature
    parameter κ"), with the complexes of Definitions 2.11 and 2.14.

    Parameters
    ----------
    points : array_like, shape (n, d)
        The point cloud.
    curvature : array_like, shape (n,)
        Curvature estimate at each point, finite (e.g.
        :func:`thesis_lib.curvature.point_curvature.point_curvature`).
    complex : {"rips", "alpha"}, default "rips"
        ``"rips"``: ε with diameter ≤ 2ε, truncated at ``max_dim``; ``"alpha"``: the alpha complex,
        its values ε² square-rooted so that both complexes are graded by ε.
    max_radius : float, default inf
        Largest ε kept (Rips only).
    max_dim : int, default 2
        Largest simplex dimension (Rips only; homology up to ``max_dim - 1`` is determined).
    absolute : bool, default True
        Grade by |κ| (curvature magnitude) rather than by signed κ.

    Returns
    -------
    Bifiltration
        ε-grade from the complex, κ-grade the largest |κ| (or κ) on the simplex's vertices, and
        ``max_homology_dim`` the dimensions the complex determines.

    Raises
    ------
    ValueError
        Bad points, a curvature array of the wrong length or with NaN/inf entries (named), an
        unknown complex.
    """
    pts = parse_points(points)
    check_choice(complex, COMPLEX_KINDS, "complex")
    k = np.asarray(curvature, dtype=np.float64) if not isinstance(curvature, str) else curvature
    if np.ndim(k) != 1 or np.shape(k)[0] != pts.n:
        raise ValueError(f"curvature must have one value per point ({pts.n}), got shape {np.shape(k)}")
    _vertex_values(k, np.arange(pts.n), "curvature")
    if absolute:
        k = np.abs(k)
    if complex == "rips":
        eps, max_dim = check_radius(max_radius), check_max_dim(max_dim)
        K = rips_filtration(pts, eps, max_dim)
        top = K.dimension - 1 if K.dimension == max_dim else K.dimension
    else:
        K = alpha(pts)
        K = Filtration(K.simplices, [np.sqrt(np.maximum(v, 0.0)) for v in K.values], validate=False)
        top = K.dimension
    return function_bifiltration(K, k, max_homology_dim=max(top, 0), name="curvature")

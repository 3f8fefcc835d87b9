"""The Crust for hypersurfaces of R^{n+1}, n = 1, 2, 3: the thesis's "natural next step" (Chapter 5).

The steps of :func:`~thesis_lib.reconstruction.crust` (ABK98) carry over to any dimension d = n + 1
word for word, because a hypersurface has codimension one:

1. Delaunay triangulation of the samples S (Qhull; in R⁴ with the joggle option ``QJ``: samples of
   the 3-sphere are co-spherical, a degenerate input on which Qhull's default merging takes minutes
   at 10⁴ points, while the joggled triangulation takes seconds and equals the Delaunay
   triangulation whenever it is unique).
2. Poles: p⁺ the farthest Voronoi vertex of each sample's cell, p⁻ the farthest on the other side.
   The Voronoi cell of a sample of a hypersurface is long and thin along the normal in any
   dimension, so p⁺ - s estimates the normal line.
3. Voronoi filtering: the n-simplices of Del(S ∪ P) with sample vertices.  An n-simplex of R^{n+1}
   is dual to a Voronoi *edge* (codimension one), so the one-dimensional linear program of
   :func:`~thesis_lib.reconstruction.crust` decides it without triangulating S ∪ P, in any dimension.
4. Normal filter: the simplex's normal within θ of the pole vector at the vertex opposite its
   largest facet (for a triangle: the largest-angle vertex), within 3θ/2 at the others.
5. Trimming.  An (n - 1)-face (a ridge) of an n-simplex in R^{n+1} has a two-dimensional normal
   plane, in which every n-simplex through the ridge is a direction — exactly as the triangles about
   an edge in R³.  So the two steps of the 3-D trimming generalise: remove simplices with a sharp
   ridge (in one simplex only, or all its simplices within a wedge of angle < π/2), then walk from
   an outer simplex, across every ridge to the next simplex met when turning about the ridge
   through the outside, orienting coherently; a simplex that would put a third simplex on a ridge
   is left out.

Steps 1–4 are ``thesis_lib.reconstruction.crust_geometry``, step 5
``thesis_lib.reconstruction.crust_trimming``: the code the 3-D Crust runs.
The result is checked (:func:`manifold_report`): every ridge in two simplices, every link of an
(n - 2)-face a single circle, every vertex link a sphere (n = 3: connected with Euler
characteristic 2), coherent orientation.  :func:`crust_nd` refuses (``ReconstructionError``, with
the report) rather than return something that is not a closed manifold when ``closed=True``.

For n = 2 this is the computation of :func:`~thesis_lib.reconstruction.crust` but for the joggled triangulation
and the 3-D Crust's resolution of flat tetrahedra (a test compares them).
Cocone (Amenta, Choi, Dey, Leekha 2002) would replace step 3 by a test of the Voronoi edge against
each vertex's cocone; the Voronoi filter of the Crust already runs without triangulating S ∪ P, and
on the 3-sphere and 3-catenoid it closes the surface (see ``experiments/hypersurface-crust``), so
the Crust is kept.
"""

from __future__ import annotations

import math
from itertools import combinations
from typing import NamedTuple

import numpy as np
import numpy.typing as npt
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import Delaunay, QhullError, cKDTree

from .._validate import as_points
from ..meshes.topology import euler_characteristic
from .crust_geometry import check_theta, filtered_faces
from .crust_trimming import open_walk, outer_walk, unique_rows

__all__ = ["crust_nd", "crust_nd_candidates", "extract_manifold_nd", "manifold_report", "manifold_vertices",
           "ManifoldReport", "CrustResult", "ReconstructionError", "MAX_AMBIENT_DIM"]

#: the largest ambient dimension d = n + 1 the Crust accepts (a 3-manifold in R⁴)
MAX_AMBIENT_DIM = 4


class ManifoldReport(NamedTuple):
    """What a reconstructed n-dimensional simplicial complex is (:func:`manifold_report`)."""

    n: int  #: dimension of the simplices
    n_simplices: int
    n_vertices: int  #: samples that are vertices of some simplex
    vertex_fraction: float  #: n_vertices / number of samples
    boundary_ridges: int  #: (n-1)-faces in one simplex (holes)
    singular_ridges: int  #: (n-1)-faces in three or more simplices
    boundary_components: int  #: connected pieces of the boundary (holes), 0 if closed
    bad_ridge_links: int  #: (n-2)-faces whose link is not one circle or one path (n >= 2)
    bad_vertex_links: int  #: vertices whose link is not a sphere or a disc (n = 3)
    orientation_conflicts: int  #: ridges whose two simplices induce the same orientation
    euler_characteristic: int

    @property
    def is_manifold(self) -> bool:
        """A combinatorial n-manifold (possibly with boundary), coherently oriented."""
        return (self.singular_ridges == 0 and self.bad_ridge_links == 0 and self.bad_vertex_links == 0
                and self.orientation_conflicts == 0 and self.n_simplices > 0)

    @property
    def is_closed_manifold(self) -> bool:
        """A closed, coherently oriented combinatorial n-manifold (every ridge in exactly two simplices)."""
        return self.is_manifold and self.boundary_ridges == 0

    def describe(self) -> str:
        """One line: what is wrong (or that nothing is).

        Returns
        -------
        str
            The counts of simplices and vertices, χ, then each defect found, or "a closed oriented
            combinatorial manifold" when there is none.
        """
        bad = []
        if self.n_simplices == 0:
            bad.append("no simplex")
        if self.boundary_ridges:
            bad.append(f"{self.boundary_ridges} ridges in one simplex ({self.boundary_components} holes)")
        if self.singular_ridges:
            bad.append(f"{self.singular_ridges} ridges in three or more simplices")
        if self.bad_ridge_links:
            bad.append(f"{self.bad_ridge_links} {self.n - 2}-faces whose link is not one circle")
        if self.bad_vertex_links:
            bad.append(f"{self.bad_vertex_links} vertices whose link is not a {self.n - 1}-sphere")
        if self.orientation_conflicts:
            bad.append(f"{self.orientation_conflicts} orientation conflicts")
        head = (f"{self.n_simplices} {self.n}-simplices on {self.n_vertices} vertices "
                f"({100 * self.vertex_fraction:.1f}% of the samples), χ = {self.euler_characteristic}")
        return head + (": " + "; ".join(bad) if bad else ": a closed oriented combinatorial manifold")


class CrustResult(NamedTuple):
    """The reconstruction and its check."""

    simplices: np.ndarray  #: (m, n + 1) coherently oriented n-simplices (outward for a closed surface)
    report: ManifoldReport
    pole_ratio: float  #: median over samples of (inner pole distance) / (nearest-sample distance)


class ReconstructionError(ValueError):
    """The Crust did not produce a closed manifold; ``report`` says what failed."""

    def __init__(self, message: str, *, report: ManifoldReport | None = None, pole_ratio: float | None = None):
        super().__init__(message)
        self.report = report
        self.pole_ratio = pole_ratio


# ---------------------------------------------------------------------------- input
def _samples_nd(points) -> np.ndarray:
    pts = as_points(points, allow_duplicates=False)
    n_pts, d = pts.shape
    if d < 2:
        raise ValueError(f"the Crust reconstructs hypersurfaces of R^d with d >= 2, got points in R^{d}")
    if d > MAX_AMBIENT_DIM:
        bound = float(n_pts) ** math.ceil(d / 2)
        raise ValueError(
            f"points in R^{d} (hypersurfaces of dimension {d - 1}) are refused: the Crust would build the "
            f"Delaunay triangulation of {n_pts:,} points in R^{d}, up to n^⌈d/2⌉ ≈ {bound:.2g} simplices "
            f"(R⁴ samples already give 13–53 simplices a point); the limit is d = {MAX_AMBIENT_DIM}")
    if n_pts < d + 3:
        raise ValueError(f"too few samples: {n_pts} points in R^{d}; the Crust needs at least {d + 3} "
                         "(and many more to close a hypersurface)")
    centred = pts - pts.mean(axis=0)
    sv = np.linalg.svd(centred, compute_uv=False)
    if sv[-1] <= 1e-10 * sv[0]:
        raise ValueError(f"the points lie in an affine subspace of dimension < {d}: they sample no hypersurface "
                         f"of R^{d} (drop a coordinate)")
    return pts


def _delaunay(pts: np.ndarray) -> Delaunay:
    try:
        return Delaunay(pts, qhull_options="QJ")
    except QhullError as err:  # pragma: no cover - Qhull refuses only degenerate inputs caught above
        raise ValueError(f"Qhull could not triangulate the samples: {str(err).splitlines()[0]}") from None


def _far(pts: np.ndarray, far) -> float:
    """Distance of the poles at infinity: ``far``, or half the diagonal of the bounding box."""
    if far is None:
        return 0.5 * float(np.linalg.norm(pts.max(axis=0) - pts.min(axis=0)))
    f = float(far)
    if not np.isfinite(f) or f <= 0:
        raise ValueError(f"far must be a positive distance, got {far!r}")
    return f


def crust_nd_candidates(points: npt.ArrayLike, *, theta: float = np.pi / 4, far: float | None = None) -> np.ndarray:
    """Steps 1–4 of the Crust in R^{n+1}: the n-simplices of Del(S ∪ P) with sample vertices that
    pass the normal filter.

    Thesis: Chapter 5 (a higher-dimensional analogue of the Crust used in §3.4).

    Parameters
    ----------
    points : array_like, shape (N, n + 1)
        Samples without duplicates, 2 <= n + 1 <= 4, at least n + 4 of them, not in an affine
        subspace.
    theta : float, default π/4
        Normal-filter angle θ in (0, π/2): θ at the vertex opposite the largest facet, 3θ/2 at the
        others.
    far : float or None, default None
        Distance of the poles at infinity (default half the bounding-box diagonal).

    Returns
    -------
    ndarray of int, shape (m, n + 1)
        The candidate simplices, each row sorted, rows in lexicographic order (Qhull's index type).

    Raises
    ------
    ValueError
        On invalid or too few samples, points in R^d with d > 4 or in a lower-dimensional subspace,
        ``theta`` outside (0, π/2), or a ``far`` that is not a positive distance.
    """
    theta = check_theta(theta)
    pts = _samples_nd(points)
    return filtered_faces(pts, _delaunay(pts), theta, _far(pts, far))[0]


# ---------------------------------------------------------------------------- trimming
def extract_manifold_nd(
    points: npt.ArrayLike, simplices: npt.ArrayLike, *, closed: bool = True
) -> tuple[np.ndarray, int]:
    """Trimming step of the Crust in R^{n+1}: from candidate n-simplices to an oriented manifold.

    ``closed`` (a closed hypersurface): remove simplices with sharp ridges until none is left, then
    walk depth first from an outer simplex (at the extreme-x sample), as the 3-D Crust does.
    Otherwise (a piece with boundary, which erosion would eat from its border and which has no
    outside): walk breadth first from the most open simplex near the centroid, stop where the
    next simplex folds by more than π/2 (the boundary).  The result may have defects along the
    boundary and where slivers confused the walk: :func:`manifold_vertices` tells the vertices
    whose star is a manifold ball.

    Thesis: Chapter 5 (higher-dimensional Crust; the trimming of [ABK98] used in §3.4).

    Parameters
    ----------
    points : array_like, shape (N, n + 1)
        The samples, at least 2.
    simplices : array_like of int, shape (m, n + 1)
        Candidate n-simplices (e.g. :func:`crust_nd_candidates`), m >= 1, indices into ``points``.
    closed : bool, default True
        The samples come from a closed hypersurface (erosion of sharp ridges, then the outer walk);
        ``False`` for a piece with boundary (the open walk).

    Returns
    -------
    simplices : ndarray of int64, shape (k, n + 1)
        Coherently oriented n-simplices (outward for a closed hypersurface; every ridge in one or
        two of them).
    conflicts : int
        The orientation conflicts met by the walk.

    Raises
    ------
    ValueError
        On invalid points, ``simplices`` not a non-empty (m, n + 1) integer array, or an index
        outside ``points``; with ``closed=True``, when trimming removes every simplex.
    """
    pts = as_points(points, min_points=2)
    s = np.asarray(simplices)
    if s.ndim != 2 or s.shape[1] != pts.shape[1] or len(s) == 0 or not np.issubdtype(s.dtype, np.integer):
        raise ValueError(f"simplices must be a non-empty (m, {pts.shape[1]}) integer array for points in "
                         f"R^{pts.shape[1]}, got shape {s.shape}")
    s = s.astype(np.int64)
    if s.min() < 0 or s.max() >= len(pts):
        raise ValueError("simplices refer to points that do not exist")
    return outer_walk(pts, s) if closed else open_walk(pts, s)


# ---------------------------------------------------------------------------- checks
def _sorted_parity(rows: np.ndarray) -> np.ndarray:
    """Sign (+1/-1) of the permutation sorting each row."""
    inv = np.zeros(len(rows), dtype=np.int64)
    for i in range(rows.shape[1]):
        for j in range(i + 1, rows.shape[1]):
            inv += rows[:, i] > rows[:, j]
    return 1 - 2 * (inv % 2)


def _components_per_group(group: np.ndarray, a: np.ndarray, b: np.ndarray, n_groups: int) -> np.ndarray:
    """Number of connected components of the graph on nodes (group, vertex) with edges a–b, per group."""
    node_key = np.concatenate([np.stack([group, a], 1), np.stack([group, b], 1)])
    uniq, inv = unique_rows(node_key)
    k = len(group)
    graph = coo_matrix((np.ones(k), (inv[:k], inv[k:])), shape=(len(uniq), len(uniq)))
    _, label = connected_components(graph, directed=False)
    comp_group = np.zeros(label.max() + 1, dtype=np.int64)
    comp_group[label] = uniq[:, 0]
    return np.bincount(comp_group, minlength=n_groups)


def _faces_with_index(s: np.ndarray, k: int):
    """Distinct k-faces of the rows of ``s`` and, for each (row, combination), the face's index."""
    combos = list(combinations(range(s.shape[1]), k + 1))
    f = np.concatenate([s[:, c] for c in combos])
    uniq, inv = unique_rows(f)
    return uniq, inv.reshape(len(combos), len(s)).T, combos


def _link_components(ss: np.ndarray, k: int, n_groups: int | None = None):
    """For every k-face of the sorted n-simplices ``ss`` (k = n - 2 or, with three vertices left, a
    vertex of a tetrahedron's link triangles): the faces and the number of connected components of
    the graph whose edges are the remaining vertex pairs."""
    faces, fidx, combos = _faces_with_index(ss, k)
    group, a_, b_ = [], [], []
    for c, comb in enumerate(combos):
        rest = [i for i in range(ss.shape[1]) if i not in comb]
        group.append(fidx[:, c])
        a_.append(ss[:, rest[0]])
        b_.append(ss[:, rest[1]])
    n = len(faces) if n_groups is None else n_groups
    return faces, _components_per_group(np.concatenate(group), np.concatenate(a_), np.concatenate(b_), n)


def _defects(s: np.ndarray, npts: int) -> tuple[dict, np.ndarray, np.ndarray]:
    """Counts for :class:`ManifoldReport`, the mask of vertices at a defect (a singular ridge, a
    ridge with an orientation conflict, an (n-2)-face whose link is not one path or circle, a vertex
    whose link is not a sphere or disc) and the mask of vertices on a boundary ridge."""
    m, k1 = s.shape
    n = k1 - 1
    ss = np.sort(s, axis=1)
    bad = np.zeros(npts, dtype=bool)
    ridge_rows = np.concatenate([np.delete(s, k, axis=1) for k in range(k1)])
    sign = np.repeat((-1) ** np.arange(k1), m) * _sorted_parity(ridge_rows)
    ridges, rinv, rcount = unique_rows(np.sort(ridge_rows, axis=1), return_counts=True)
    boundary = rcount == 1
    sign_sum = np.bincount(rinv, weights=sign, minlength=len(ridges))
    conflict = (rcount == 2) & (sign_sum != 0)
    bad[ridges[(rcount > 2) | conflict].ravel()] = True
    b = ridges[boundary]
    on_boundary = np.zeros(npts, dtype=bool)
    on_boundary[b.ravel()] = True
    holes = 0
    if len(b):
        if n == 1:
            holes = max(len(b) // 2, 1)  # the ends of paths, two per path
        else:
            sub, sub_idx, _ = _faces_with_index(b, n - 2)
            ridge_id = np.repeat(np.arange(len(b)), sub_idx.shape[1])
            graph = coo_matrix((np.ones(ridge_id.size), (ridge_id, len(b) + sub_idx.ravel())),
                               shape=(len(b) + len(sub), len(b) + len(sub)))
            holes = len(np.unique(connected_components(graph, directed=False)[1][: len(b)]))
    bad_ridge_links = 0
    if n >= 2:
        faces, comps = _link_components(ss, n - 2)
        bad[faces[comps != 1].ravel()] = True
        bad_ridge_links = int(np.count_nonzero(comps != 1))
    bad_vertex_links = 0
    if n == 3:  # link of v: connected, χ = #edges - #triangles + #tetrahedra through v, 2 or 1 (disc)
        edges, _, _ = _faces_with_index(ss, 1)
        tris, _, _ = _faces_with_index(ss, 2)
        chi = (np.bincount(edges.ravel(), minlength=npts) - np.bincount(tris.ravel(), minlength=npts)
               + np.bincount(ss.ravel(), minlength=npts))
        _, comps = _link_components(tris, 0, npts)
        used = np.zeros(npts, dtype=bool)
        used[ss.ravel()] = True
        wrong = used & ((comps != 1) | (chi != np.where(on_boundary, 1, 2)))
        bad |= wrong
        bad_vertex_links = int(np.count_nonzero(wrong))
    counts = dict(boundary_ridges=int(boundary.sum()), singular_ridges=int(np.count_nonzero(rcount > 2)),
                  boundary_components=int(holes), bad_ridge_links=bad_ridge_links,
                  bad_vertex_links=bad_vertex_links, orientation_conflicts=int(conflict.sum()))
    return counts, bad, on_boundary


def manifold_vertices(simplices: npt.ArrayLike, *, n_points: int | None = None) -> np.ndarray:
    """Mask of the vertices whose star is a manifold n-ball: interior (on no boundary ridge) and at
    no defect (:func:`manifold_report`).  Curvature estimated there uses a complete, clean star.
    Thesis: Definition 3.15 (the discrete mean curvature at p uses the simplices around p).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        Oriented vertex rows, m >= 1 (not validated: use :func:`manifold_report` for bad input).
    n_points : int or None, default None
        Number of samples (default and at least: largest vertex index + 1).

    Returns
    -------
    ndarray of bool, shape (n_points,)
        True at the vertices used by some simplex, on no boundary ridge and at no defect.
    """
    s = np.asarray(simplices, dtype=np.int64)
    npts = int(s.max()) + 1 if n_points is None else max(int(n_points), int(s.max()) + 1)
    _, bad, on_boundary = _defects(s, npts)
    used = np.zeros(npts, dtype=bool)
    used[s.ravel()] = True
    return used & ~bad & ~on_boundary


def manifold_report(simplices: npt.ArrayLike, *, n_points: int | None = None) -> ManifoldReport:
    """Check that n-simplices form a (closed) coherently oriented combinatorial n-manifold.

    Ridges ((n-1)-faces) in one simplex are boundary (holes), in three or more singular; the link of
    every (n-2)-face must be one circle (or one path at the boundary); for n = 3 every vertex link
    must be a 2-sphere (connected, χ = 2) or a disc (connected, χ = 1); two simplices sharing a ridge
    must induce opposite orientations on it.
    Thesis: §3.1.2 (every edge of a closed surface in two triangles), generalised (Chapter 5).

    Parameters
    ----------
    simplices : array_like of int, shape (m, n + 1)
        Oriented vertex rows, n >= 1 (m = 0 gives an empty report).
    n_points : int or None, default None
        Number of samples, for ``vertex_fraction`` (default and at least: largest vertex index + 1).

    Returns
    -------
    ManifoldReport
        The counts of simplices, vertices and each kind of defect, and the Euler characteristic;
        ``is_manifold`` and ``is_closed_manifold`` sum them up.

    Raises
    ------
    ValueError
        If ``simplices`` is not an (m, n + 1) array of non-negative integers with n >= 1.
    """
    s = np.asarray(simplices)
    if s.ndim != 2 or s.shape[1] < 2 or not np.issubdtype(s.dtype, np.integer) or (len(s) and s.min() < 0):
        raise ValueError(f"simplices must be an (m, n + 1) array of vertex indices with n >= 1, got shape {s.shape}")
    s = s.astype(np.int64)
    n = s.shape[1] - 1
    if len(s) == 0:
        return ManifoldReport(n, 0, 0, 0.0, 0, 0, 0, 0, 0, 0, 0)
    npts = int(s.max()) + 1 if n_points is None else max(int(n_points), int(s.max()) + 1)
    counts, _, _ = _defects(s, npts)
    nverts = len(np.unique(s))
    return ManifoldReport(n=n, n_simplices=len(s), n_vertices=nverts, vertex_fraction=nverts / npts,
                          euler_characteristic=euler_characteristic(np.sort(s, axis=1)), **counts)


def _pole_ratio(pts: np.ndarray, p_plus: np.ndarray, p_minus: np.ndarray) -> float:
    """Median over samples of min(|p⁺ - s|, |p⁻ - s|) / (distance to the nearest other sample).

    Large (≳ 3) for a sample of a hypersurface (long thin Voronoi cells), about 1 for points that
    fill a volume (round cells)."""
    near = cKDTree(pts).query(pts, k=2)[0][:, 1]
    h = np.minimum(np.linalg.norm(p_plus - pts, axis=1), np.linalg.norm(p_minus - pts, axis=1))
    return float(np.median(h / near))


def crust_nd(
    points: npt.ArrayLike, *, theta: float = np.pi / 4, closed: bool = True, far: float | None = None
) -> CrustResult:
    """Reconstruct a hypersurface of R^{n+1} (n = 1, 2, 3) from samples with the Crust [ABK98].

    Thesis: Chapter 5 ("a natural next step ... higher dimensional analogues of the Crust Algorithm");
    the 3-D Crust is the one of §3.4.

    Parameters
    ----------
    points : array_like, shape (N, n + 1)
        Samples without duplicates, 2 <= n + 1 <= 4.
    theta : float, default π/4
        Normal-filter angle θ in (0, π/2): θ at the vertex opposite the largest facet, 3θ/2 at the
        others.
    closed : bool, default True
        The samples come from a closed hypersurface (trimming by sharp ridges and the outer walk,
        as in 3-D); refuse unless the result is a closed oriented combinatorial manifold.
        ``False``: a piece with boundary (see :func:`extract_manifold_nd`); the report counts its
        defects and :func:`manifold_vertices` tells the vertices with a clean manifold star.
    far : float or None, default None
        Distance of the poles at infinity (default half the bounding-box diagonal).

    Returns
    -------
    CrustResult
        ``simplices`` (m, n + 1) coherently oriented (outward when closed), the
        :class:`ManifoldReport` and the pole ratio (median inner-pole distance over nearest-sample
        distance: about 1 when the points fill a volume).

    Raises
    ------
    ValueError
        Points in R^d with d > 4 (refused with the size that would be built), too few samples,
        points in a lower-dimensional subspace, θ outside (0, π/2).
    ReconstructionError
        (a ValueError) The result is not a closed manifold (``closed=True``), or nothing of it is a
        manifold; the message says what failed and whether the points look like a sample of a
        hypersurface at all.
    """
    theta = check_theta(theta)
    pts = _samples_nd(points)
    faces, p_plus, p_minus = filtered_faces(pts, _delaunay(pts), theta, _far(pts, far))
    ratio = _pole_ratio(pts, p_plus, p_minus)
    hint = (f"the median pole distance is {ratio:.2g} nearest-sample distances: the points fill a volume "
            "rather than sample a hypersurface" if ratio < 2.5 else
            f"the median pole distance is {ratio:.2g} nearest-sample distances (a hypersurface-like sample): "
            "the sample may be too sparse or too noisy for its curvature")
    if len(faces) == 0:
        raise ReconstructionError(f"no {pts.shape[1] - 1}-simplex survived the Crust's filtering; {hint}",
                                  report=None, pole_ratio=ratio)
    try:
        out, _ = extract_manifold_nd(pts, faces, closed=closed)
    except ValueError as err:
        raise ReconstructionError(f"{err}; {hint}", report=None, pole_ratio=ratio) from None
    report = manifold_report(out, n_points=len(pts))
    if not closed and not manifold_vertices(out, n_points=len(pts)).any():
        raise ReconstructionError(f"no vertex of the reconstruction has a manifold star: {report.describe()}; {hint}",
                                  report=report, pole_ratio=ratio)
    if closed and not report.is_closed_manifold:
        raise ReconstructionError(f"the Crust did not produce a closed manifold: {report.describe()}; {hint}",
                                  report=report, pole_ratio=ratio)
    return CrustResult(out, report, ratio)

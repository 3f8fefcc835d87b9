"""Vertex areas: the regions over which integrated curvatures are averaged (§3.3.2).

``"barycentric"``
    Each simplex gives 1/(n + 1) of its hyperarea to each of its vertices (any n).
``"voronoi"``
    Circumcentric (signed) decomposition, any n: simplex T gives vertex i the signed hyperarea of
    the cells c_{σ_0} c_{σ_1} … c_{σ_n} over the flags i = σ_0 ⊂ σ_1 ⊂ … ⊂ σ_n = T (c_σ the
    circumcentre of σ).  Recursively, with λ^T the barycentric coordinates of T's circumcentre,
    f_i(T) = Σ_{k ≠ i} λ^T_k f_i(T \\ k), f_i({i}) = 1, and the share is f_i(T)·area(T).  Whenever
    every circumcentre lies in its simplex this is exactly the part of T closest to vertex i; for
    n = 2 it is the thesis's A_vor = 1/8 Σ (cot α_ij + cot β_ij) ‖x_i − x_j‖², which equals libigl's
    Voronoi mass on non-obtuse triangles but is signed (a piece can be negative) on obtuse ones.
    On a simplex of aspect above ``ASPECT_BOUND`` (:mod:`.validate`) the circumcentres are solved
    for in exact rational arithmetic (the float solve loses up to 2·log10(aspect) digits there);
    below it the float computation is kept bit for bit.
``"mixed"``
    Meyer, Desbrun, Schröder & Barr (2002), n = 2: Voronoi shares on non-obtuse triangles; on an
    obtuse triangle the obtuse vertex gets half its area and the other two a quarter each.  This is
    what libigl's ``massmatrix(..., MASSMATRIX_TYPE_VORONOI)`` computes.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import numpy.typing as npt

from .._core import vertex_areas as _vertex_areas_core
from .._validate import InvalidTypeError, check_choice
from .manifold import checked_mesh
from .validate import ASPECT_BOUND, Mesh

__all__ = ["vertex_areas", "vertex_areas_of_mesh", "circumcentric_fractions", "AREA_KINDS", "check_area"]

AREA_KINDS = ("mixed", "voronoi", "barycentric")


def check_area(area: object) -> str:
    """The vertex-region name ``area``: one of :data:`AREA_KINDS`.

    Thesis: §3.3.2 (Voronoi and barycentric regions).

    Parameters
    ----------
    area : object
        The name to check: ``"mixed"``, ``"voronoi"`` or ``"barycentric"``.

    Returns
    -------
    str
        ``area`` itself.

    Raises
    ------
    ValueError
        If ``area`` is not one of :data:`AREA_KINDS` (including a non-string).
    """
    return check_choice(area, AREA_KINDS, "area")


def circumcentric_fractions(corners: npt.ArrayLike) -> np.ndarray:
    """Signed fraction of each simplex's hyperarea in each vertex's circumcentric cell.

    Thesis: §3.3.2 (Voronoi regions; the 3-simplex corner remark of §3.4.2).

    Parameters
    ----------
    corners : ndarray, shape (m, n + 1, d)
        Vertex coordinates of m non-degenerate n-simplices.

    Returns
    -------
    ndarray, shape (m, n + 1)
        Rows sum to 1.  Example: at the right corner of the tetrahedron (0, e1, e2, e3) the share is
        3/4 (volume 1/8), while the part of it closest to the corner has volume 5/48; §3.4.2 of the
        thesis uses 1/12 (half the volume) as its Voronoi estimate.

    Raises
    ------
    ValueError
        If ``corners`` is not an (m, n + 1, d) array of finite numbers with d >= n.

    Examples
    --------
    Each vertex of an equilateral triangle has a third of it; the right angle of a right triangle has
    half.  An obtuse triangle gives signed shares, negative at its acute corners:

    >>> import numpy as np
    >>> right = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
    >>> obtuse = [[0.0, 0.0], [4.0, 0.0], [2.0, 0.5]]
    >>> np.round(circumcentric_fractions([right, obtuse]), 6).tolist()
    [[0.5, 0.25, 0.25], [-1.625, -1.625, 4.25]]
    """
    if np.iscomplexobj(corners):
        raise InvalidTypeError("complex numbers are not coordinates")
    try:
        corners = np.asarray(corners, dtype=np.float64)
    except (TypeError, ValueError) as err:
        raise ValueError(f"corners must be an (m, n + 1, d) array of numbers: {err}") from None
    if corners.ndim != 3 or corners.shape[1] < 1 or corners.shape[2] < corners.shape[1] - 1:
        raise ValueError(f"corners must have shape (m, n + 1, d) with d >= n, got {corners.shape}")
    if not np.isfinite(corners).all():
        raise ValueError("corners have a NaN or infinite coordinate")
    m, w, _ = corners.shape
    full = (1 << w) - 1
    ill = _ill_rows(corners)
    frac: dict[int, np.ndarray] = {1 << i: np.ones((m, w)) for i in range(w)}
    masks = sorted(range(1, full + 1), key=lambda s: bin(s).count("1"))
    for mask in masks:
        members = [i for i in range(w) if mask >> i & 1]
        if len(members) < 2:
            continue
        q = corners[:, members, :]
        x = q[:, 1:, :] - q[:, :1, :]
        g = np.einsum("mia,mja->mij", x, x)
        a = np.linalg.solve(g, 0.5 * np.einsum("mii->mi", g)[..., None])[..., 0]
        lam = np.concatenate([1.0 - a.sum(axis=1, keepdims=True), a], axis=1)  # circumcentre of face
        f = np.zeros((m, w))
        for i in members:
            for kk, k in enumerate(members):
                if k != i:
                    f[:, i] += lam[:, kk] * frac[mask & ~(1 << k)][:, i]
        frac[mask] = f
    out = frac[full]
    for k in ill.tolist():
        try:
            out[k] = _exact_circumcentric_fractions(corners[k])
        except ZeroDivisionError:
            raise ValueError(f"simplex {k} is degenerate: its vertices are affinely dependent") from None
    return out


def _ill_rows(p: np.ndarray) -> np.ndarray:
    """Rows of ``p`` (m, n + 1, d) whose simplex has aspect L^n / (n! hyperarea) above ASPECT_BOUND."""
    m, w, _ = p.shape
    n = w - 1
    if n < 2:
        return np.zeros(0, dtype=np.int64)
    x = p[:, 1:, :] - p[:, :1, :]
    with np.errstate(all="ignore"):
        vol = np.sqrt(np.clip(np.linalg.det(np.einsum("mia,mja->mij", x, x)), 0.0, None))  # n! hyperarea
        longest = np.zeros(m)
        for i in range(1, w):
            for j in range(i):
                e = p[:, i] - p[:, j]
                np.maximum(longest, np.einsum("ma,ma->m", e, e), out=longest)
        return np.flatnonzero(~(np.sqrt(longest) ** n <= ASPECT_BOUND * vol))


def _exact_circumcentric_fractions(p: np.ndarray) -> np.ndarray:
    """:func:`circumcentric_fractions` of one simplex ``p`` (n + 1, d) in exact rational arithmetic
    (each face's circumcentre solved for exactly), rounded once at the end."""
    w = len(p)
    pts = [[Fraction(float(c)) for c in row] for row in p]
    frac: dict[int, list[Fraction]] = {1 << i: [Fraction(1)] * w for i in range(w)}
    for mask in sorted(range(1, 1 << w), key=lambda s: bin(s).count("1")):
        members = [i for i in range(w) if mask >> i & 1]
        if len(members) < 2:
            continue
        x = [[a - b for a, b in zip(pts[i], pts[members[0]])] for i in members[1:]]
        k = len(x)
        aug = [[sum((a * b for a, b in zip(x[i], x[j])), Fraction(0)) for j in range(k)] for i in range(k)]
        for i in range(k):
            aug[i].append(aug[i][i] / 2)
        for col in range(k):  # Gauss–Jordan on the positive-definite Gram matrix: no pivoting needed
            piv = aug[col][col]
            aug[col] = [c / piv for c in aug[col]]
            for r in range(k):
                if r != col and aug[r][col] != 0:
                    fac = aug[r][col]
                    aug[r] = [c - fac * d for c, d in zip(aug[r], aug[col])]
        a = [aug[i][k] for i in range(k)]
        lam = [1 - sum(a, Fraction(0)), *a]
        f = [Fraction(0)] * w
        for i in members:
            for kk, kv in enumerate(members):
                if kv != i:
                    f[i] += lam[kk] * frac[mask & ~(1 << kv)][i]
        frac[mask] = f
    return np.array([float(c) for c in frac[(1 << w) - 1]])


def vertex_areas_of_mesh(mesh: Mesh, area: str = "mixed") -> np.ndarray:
    """:func:`vertex_areas` on checked input: a validated :class:`~.validate.Mesh` and an area name
    already checked by :func:`check_area` (the public functions check both once, then call this).

    Thesis: §3.3.2 (Voronoi and barycentric regions).

    Parameters
    ----------
    mesh : Mesh
        A validated mesh (from ``checked_mesh``).
    area : {"mixed", "voronoi", "barycentric"}, default "mixed"
        The vertex region, checked (:func:`check_area`); ``"mixed"`` needs n = 2.

    Returns
    -------
    ndarray, shape (nv,)
        The area of each vertex's region; zero at isolated vertices.

    Raises
    ------
    ValueError
        ``"mixed"`` on a mesh with n ≠ 2.
    """
    v, s, areas = mesh.vertices, mesh.simplices, mesh.areas
    nv, n = len(v), mesh.n
    if area == "barycentric":
        return np.bincount(s.ravel(), weights=np.repeat(areas / (n + 1), n + 1), minlength=nv)
    if area == "mixed" and n != 2:
        raise ValueError(f"the mixed area (Meyer et al. 2002) is defined for n = 2, got n = {n}; "
                         "use 'voronoi' or 'barycentric'")
    if n == 2:
        tri = mesh.tri
        return _vertex_areas_core.triangle_areas(
            np.ascontiguousarray(s, dtype=np.int64), np.ascontiguousarray(tri.dot, dtype=np.float64),
            np.ascontiguousarray(tri.edge_sq, dtype=np.float64), np.ascontiguousarray(tri.twice_area, dtype=np.float64),
            nv, area == "mixed")
    share = circumcentric_fractions(v[s]) * areas[:, None]
    return np.bincount(s.ravel(), weights=share.ravel(), minlength=nv)


def vertex_areas(vertices: npt.ArrayLike, simplices: npt.ArrayLike, *, area: str = "mixed") -> np.ndarray:
    """Area (hyperarea) of each vertex's region: mixed, Voronoi (circumcentric) or barycentric.

    Thesis: §3.3.2 (Voronoi and barycentric regions, the formula for A_vor).

    Parameters
    ----------
    vertices : array_like, shape (nv, n + 1)
    simplices : array_like of int, shape (m, n + 1)
        Top simplices of a simplicial pseudo-manifold (checked).
    area : {"mixed", "voronoi", "barycentric"}, default "mixed"
        See the module docstring; ``"mixed"`` needs n = 2.

    Returns
    -------
    ndarray, shape (nv,)
        Sums to the total hyperarea (for every region).  Zero at isolated vertices.  The signed
        ``"voronoi"`` area can be negative at a vertex surrounded by badly obtuse simplices.

    Raises
    ------
    ValueError
        On an invalid mesh (not a pseudo-manifold, degenerate simplices, ...), an unknown area, or
        ``"mixed"`` with n ≠ 2.

    Examples
    --------
    On the regular octahedron every vertex gets a sixth of the area 4√3:

    >>> import numpy as np
    >>> from thesis_lib.meshes import convex_hull_surface
    >>> octahedron = np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    >>> faces = convex_hull_surface(octahedron)
    >>> np.round(vertex_areas(octahedron, faces), 6).tolist()
    [1.154701, 1.154701, 1.154701, 1.154701, 1.154701, 1.154701]
    """
    area = check_area(area)
    return vertex_areas_of_mesh(checked_mesh(vertices, simplices), area)

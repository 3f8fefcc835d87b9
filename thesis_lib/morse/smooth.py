"""Smooth Morse theory examples of thesis §4.1: the upright torus, Morse inequalities, Morse complexes."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
import scipy.optimize
import scipy.sparse as sp

from .._validate import check_torus_radii
from .morse_complex import chain_complex_homology

__all__ = [
    "torus_height",
    "torus_height_gradient",
    "torus_height_hessian",
    "morse_index",
    "torus_critical_points",
    "morse_inequalities",
    "sphere_morse_complex",
    "rp2_morse_complex",
    "torus_morse_complex",
]


def torus_height(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 2.0,
                 r: float = 1.0) -> npt.NDArray[np.float64] | float:
    """Height h(u, v) = cos(u)(R + r cos v) on the torus φ(u, v) of Example 4.2.

    Thesis: Example 4.2.

    Parameters
    ----------
    u, v : array_like
        The angles of φ(u, v): around the axis and around the tube (scalars or arrays that
        broadcast together).
    R : float, default 2.0
        Distance from the centre of the tube to the axis; 0 < r < R.
    r : float, default 1.0
        Radius of the tube.

    Returns
    -------
    float or ndarray
        h at each (u, v) (a numpy float for scalar input, else the broadcast shape of u and v).

    Raises
    ------
    ValueError
        Radii without 0 < r < R.

    Examples
    --------
    The top of the torus of Example 4.2 (R = 2, r = 1), at u = v = 0, has height R + r = 3:

    >>> float(torus_height(0.0, 0.0))
    3.0
    """
    R, r = check_torus_radii(R, r)
    return np.cos(u) * (R + r * np.cos(v))


def torus_height_gradient(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 2.0,
                          r: float = 1.0) -> npt.NDArray[np.float64]:
    """h_*(u, v) = (-sin(u)(R + r cos v), -r cos(u) sin v).

    Thesis: Example 4.2.

    Parameters
    ----------
    u, v : array_like
        The angles, as in :func:`torus_height`.
    R, r : float
        The radii (default 2 and 1), as in :func:`torus_height`.

    Returns
    -------
    ndarray, shape (2,) or (2, *shape)
        (∂h/∂u, ∂h/∂v), the components first.

    Raises
    ------
    ValueError
        Unless 0 < r < R.

    Examples
    --------
    The gradient vanishes at the maximum u = v = 0; at u = π/2, v = 0 it is (−(R + r), 0):

    >>> import numpy as np
    >>> torus_height_gradient(0.0, 0.0).tolist() == [0.0, 0.0]
    True
    >>> bool(np.allclose(torus_height_gradient(np.pi / 2, 0.0), [-3.0, 0.0]))
    True
    """
    R, r = check_torus_radii(R, r)
    return np.array([-np.sin(u) * (R + r * np.cos(v)), -r * np.cos(u) * np.sin(v)])


def torus_height_hessian(u: npt.ArrayLike, v: npt.ArrayLike, *, R: float = 2.0,
                         r: float = 1.0) -> npt.NDArray[np.float64]:
    """The Hessian of h in the coordinates (u, v).

    Thesis: Example 4.2 (e.g. diag(-(R + r), -r) at (0, 0)).

    Parameters
    ----------
    u, v, R, r : array_like, array_like, float, float
        The point (u, v) and the radii of :func:`torus_height` (defaults R = 2, r = 1).

    Returns
    -------
    ndarray, shape (2, 2) or (2, 2, *shape)
        The symmetric matrix of second derivatives, the two matrix indices first.

    Raises
    ------
    ValueError
        Radii that are not 0 < r < R (finite).

    Examples
    --------
    Negative definite at the maximum, positive definite at the minimum u = π, v = 0:

    >>> import numpy as np
    >>> torus_height_hessian(0.0, 0.0).tolist(), torus_height_hessian(np.pi, 0.0).tolist()
    ([[-3.0, 0.0], [0.0, -1.0]], [[3.0, 0.0], [0.0, 1.0]])
    """
    R, r = check_torus_radii(R, r)
    return np.array(
        [
            [-np.cos(u) * (R + r * np.cos(v)), r * np.sin(u) * np.sin(v)],
            [r * np.sin(u) * np.sin(v), -r * np.cos(u) * np.cos(v)],
        ]
    )


def morse_index(hessian: npt.ArrayLike, *, tol: float = 1e-9) -> int:
    """Number of negative eigenvalues of a non-degenerate Hessian (the Morse index).

    Thesis: §4.1.1 (index of a non-degenerate critical point), Definition 4.1.

    Parameters
    ----------
    hessian : array_like, shape (n, n)
        A finite symmetric matrix (symmetric to 1e-9).
    tol : float, default 1e-9
        The Hessian is degenerate when its smallest |eigenvalue| is at most ``tol`` times
        max(1, its largest |eigenvalue|).

    Returns
    -------
    int
        The number of negative eigenvalues.

    Raises
    ------
    ValueError
        The Hessian is not a finite symmetric square matrix, or is degenerate.

    Examples
    --------
    Index 2 at the maximum, 0 at the minimum and 1 at the saddle u = 0, v = π:

    >>> import numpy as np
    >>> [morse_index(torus_height_hessian(u, v)) for u, v in [(0.0, 0.0), (np.pi, 0.0), (0.0, np.pi)]]
    [2, 0, 1]
    """
    h = np.asarray(hessian, dtype=float)
    if h.ndim != 2 or h.shape[0] != h.shape[1] or not np.all(np.isfinite(h)):
        raise ValueError(f"a Hessian is a finite square matrix, got shape {h.shape}")
    if not np.allclose(h, h.T, atol=1e-9):
        raise ValueError("the Hessian is not symmetric")
    ev = np.linalg.eigvalsh(h)
    if np.min(np.abs(ev)) <= tol * max(1.0, np.max(np.abs(ev))):
        raise ValueError("the critical point is degenerate (det H = 0): not a Morse function")
    return int(np.sum(ev < 0))


def torus_critical_points(*, R: float = 2.0, r: float = 1.0, grid: int = 8) -> list[dict]:
    """Critical points of the height on the upright torus, found numerically from a grid of starts.

    Thesis: Example 4.2 / Figure 4.1 (r, q_1, q_2, p of indices 0, 1, 1, 2).

    Newton iterations (``scipy.optimize.root`` with the analytic Hessian as Jacobian) from a
    ``grid × grid`` lattice of (u, v); the roots are reduced to [0, 2π)², merged, and classified
    by the Hessian.

    Parameters
    ----------
    R : float, default 2.0
        Distance from the centre of the tube to the axis; 0 < r < R.
    r : float, default 1.0
        Radius of the tube.
    grid : int, default 8
        Starts per angle (at least 2).

    Returns
    -------
    list of dict
        One dict per critical point with keys ``u``, ``v`` (angles in [0, 2π)), ``point`` (x, y, z),
        ``value`` (the height) and ``index`` (the Morse index), sorted by value.

    Raises
    ------
    ValueError
        Radii without 0 < r < R, or ``grid`` < 2.

    Examples
    --------
    The four critical points of the height: a minimum, two saddles and a maximum (Example 4.2):

    >>> [(round(p["value"], 6), p["index"]) for p in torus_critical_points()]
    [(-3.0, 0), (-1.0, 1), (1.0, 1), (3.0, 2)]
    """
    R, r = check_torus_radii(R, r)
    if int(grid) < 2:
        raise ValueError(f"grid must be at least 2, got {grid}")
    two_pi = 2 * np.pi
    found: list[np.ndarray] = []
    starts = np.linspace(0, two_pi, int(grid), endpoint=False) + 0.1
    for u0 in starts:
        for v0 in starts:
            sol = scipy.optimize.root(
                lambda x: torus_height_gradient(x[0], x[1], R=R, r=r),
                np.array([u0, v0]),
                jac=lambda x: torus_height_hessian(x[0], x[1], R=R, r=r),
                method="hybr",
            )
            if not sol.success or np.linalg.norm(torus_height_gradient(*sol.x, R=R, r=r)) > 1e-10:
                continue
            x = np.mod(sol.x, two_pi)
            x[np.isclose(x, two_pi, atol=1e-8)] = 0.0
            if not any(np.allclose(np.mod(x - y + np.pi, two_pi) - np.pi, 0, atol=1e-6) for y in found):
                found.append(x)
    out = []
    for u, v in found:
        point = (np.sin(u) * (R + r * np.cos(v)), r * np.sin(v), np.cos(u) * (R + r * np.cos(v)))
        out.append(
            dict(
                u=float(u), v=float(v), point=tuple(float(c) for c in point),
                value=float(torus_height(u, v, R=R, r=r)), index=morse_index(torus_height_hessian(u, v, R=R, r=r)),
            )
        )
    return sorted(out, key=lambda d: d["value"])


def morse_inequalities(critical_counts: Sequence[int], betti: Sequence[int]) -> dict[str, bool]:
    """Check β_k ≤ Crit_k, Σ(-1)^k β_k = Σ(-1)^k Crit_k and the strong inequalities.

    Thesis: Theorems 4.6 and 4.7 (and their discrete versions, Theorems 4.27–4.28).

    Parameters
    ----------
    critical_counts : sequence of int
        Crit_k, the number of critical points (or simplices) of index k, k = 0, 1, ...
    betti : sequence of int
        β_k; the shorter list is padded with zeros.

    Returns
    -------
    dict of str to bool
        ``{"weak": ..., "euler": ..., "strong": ...}``: whether each form holds.

    Raises
    ------
    ValueError
        Lists that are not 1-D or hold negative numbers.

    Examples
    --------
    The torus's height function is perfect (Crit = β); critical counts 2, 1, 1 cannot be those of a
    Morse function on RP² (β = 1, 0, 0 over Z): the Euler equation fails:

    >>> morse_inequalities([1, 2, 1], [1, 2, 1])
    {'weak': True, 'euler': True, 'strong': True}
    >>> morse_inequalities([2, 1, 1], [1, 0, 0])["euler"]
    False
    """
    c = np.asarray(critical_counts, dtype=np.int64)
    b = np.asarray(betti, dtype=np.int64)
    if c.ndim != 1 or b.ndim != 1 or (c < 0).any() or (b < 0).any():
        raise ValueError("critical counts and Betti numbers are 1-D lists of non-negative integers")
    n = max(c.size, b.size)
    c = np.pad(c, (0, n - c.size))
    b = np.pad(b, (0, n - b.size))
    signs = (-1) ** np.arange(n)
    strong = all(
        int(np.sum(signs[: k + 1][::-1] * b[: k + 1])) <= int(np.sum(signs[: k + 1][::-1] * c[: k + 1]))
        for k in range(n)
    )
    return {
        "weak": bool(np.all(b <= c)),
        "euler": bool(np.sum(signs * b) == np.sum(signs * c)),
        "strong": bool(strong),
    }


def _complex(mats: list[list[list[int]]], sizes: list[int]) -> list[sp.csc_matrix]:
    out = [sp.csc_matrix((0, sizes[0]), dtype=np.int64)]
    out += [sp.csc_matrix(np.array(m, dtype=np.int64).reshape(sizes[k], sizes[k + 1])) for k, m in enumerate(mats)]
    return out


def sphere_morse_complex() -> tuple[list[list[str]], list[sp.csc_matrix], list[tuple[int, list[int]]]]:
    """The integer Morse complex of h = c_1u² + c_2v² + c_3w² on S² and its homology.

    Thesis: Example 4.18 (∂p_i = q_1 + q_2, ∂q_1 = r_1 - r_2, ∂q_2 = r_2 - r_1).

    Returns
    -------
    names : list of list of str
        The critical points per index 0, 1, 2.
    boundaries : list of scipy.sparse.csc_matrix
        ``boundaries[k]`` the int64 Morse boundary from index-k to index-(k-1) points
        (``boundaries[0]`` has no rows).
    homology : list of (int, list of int)
        Its homology over Z, as :func:`~thesis_lib.morse.morse_complex.chain_complex_homology`.

    Examples
    --------
    >>> names, boundaries, homology = sphere_morse_complex()
    >>> names
    [['r1', 'r2'], ['q1', 'q2'], ['p1', 'p2']]
    >>> [b.toarray().tolist() for b in boundaries[1:]], homology
    ([[[1, -1], [-1, 1]], [[1, 1], [1, 1]]], [(1, []), (0, []), (1, [])])
    """
    names = [["r1", "r2"], ["q1", "q2"], ["p1", "p2"]]
    mats = _complex([[[1, -1], [-1, 1]], [[1, 1], [1, 1]]], [2, 2, 2])
    return names, mats, chain_complex_homology(mats, coefficients=0)


def rp2_morse_complex() -> tuple[list[list[str]], list[sp.csc_matrix], list[tuple[int, list[int]]]]:
    """The Morse complex of RP² over Z/2: two flow lines p → q and two q → r.

    Thesis: Example 4.19 (Z_2 → Z_2 → Z_2 with zero maps).

    Returns
    -------
    names, boundaries, homology : list, list, list
        As in :func:`sphere_morse_complex`: the critical points r, q, p; the boundaries, which hold
        the numbers of flow lines (2) and so vanish mod 2; the homology over Z/2 (β = 1, 1, 1).

    Examples
    --------
    Two flow lines between consecutive critical points: the boundaries are 2, zero mod 2, so every
    point survives in Z/2-homology:

    >>> names, boundaries, homology = rp2_morse_complex()
    >>> names, [b.toarray().tolist() for b in boundaries[1:]], homology
    ([['r'], ['q'], ['p']], [[[2]], [[2]]], [(1, []), (1, []), (1, [])])
    """
    names = [["r"], ["q"], ["p"]]
    mats = _complex([[[2]], [[2]]], [1, 1, 1])
    return names, mats, chain_complex_homology(mats, coefficients=2)


def torus_morse_complex() -> tuple[list[list[str]], list[sp.csc_matrix], list[tuple[int, list[int]]]]:
    """The Morse complex of the tilted upright torus over Z/2.

    Thesis: Example 4.17 (∂p = 2q_2 + 2q_1 = 0, ∂q_i = 2r = 0).

    Returns
    -------
    names, boundaries, homology : list, list, list
        As in :func:`sphere_morse_complex`: the critical points r; q1, q2; p, boundary entries 2
        (the flow-line counts) and the homology over Z/2, β = 1, 2, 1.

    Examples
    --------
    >>> names, boundaries, homology = torus_morse_complex()
    >>> names, homology
    ([['r'], ['q1', 'q2'], ['p']], [(1, []), (2, []), (1, [])])
    """
    names = [["r"], ["q1", "q2"], ["p"]]
    mats = _complex([[[2, 2]], [[2], [2]]], [1, 2, 1])
    return names, mats, chain_complex_homology(mats, coefficients=2)

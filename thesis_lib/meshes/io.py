"""Triangle meshes in and out: files (VTK, VTP, PLY, STL, OBJ, ...) and pyvista ``PolyData``.

So that users can bring their own surfaces to the curvature estimates of chapter 3 (and take ours
to ParaView or any VTK tool), meshes convert to and from pyvista, whose readers and writers cover
the common formats; the library's own form is the pair ``(vertices (nv, 3), simplices (m, 3))``.
pyvista (the ``[mesh]`` extra) is imported on first use (it is slow to import).
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from .._optional import require
from .._validate import InvalidTypeError, as_points, check_simplices

if TYPE_CHECKING:  # pyvista is slow to import: loaded on first use (_pyvista)
    import pyvista

__all__ = ["read_mesh", "write_mesh", "to_pyvista", "from_pyvista"]


def _pyvista():
    import warnings

    with warnings.catch_warnings():  # pyvista's tqdm import warns with this machine's path
        warnings.filterwarnings("ignore", message="IProgress not found")
        return require("pyvista", extra="mesh", purpose="mesh files and pyvista meshes")


def to_pyvista(vertices: npt.ArrayLike, simplices: npt.ArrayLike) -> pyvista.PolyData:
    """A pyvista ``PolyData`` of a triangle mesh.

    Thesis: §3.4 (the triangulated surfaces of the experiments).

    Parameters
    ----------
    vertices : array_like, shape (nv, 3)
        The points, finite (float64 is kept).
    simplices : array_like of int, shape (m, 3)
        Vertex indices of the triangles (the row order is the orientation, kept).

    Returns
    -------
    pyvista.PolyData
        A copy of the vertices as its points, the triangles as its faces.

    Raises
    ------
    ImportError
        If pyvista is not installed (the ``[mesh]`` extra).
    ValueError
        On invalid vertices, vertices not in R³, or simplices that are not (m, 3) indices of vertices.
    """
    v = as_points(vertices, name="vertices")
    if v.shape[1] != 3:
        raise ValueError(f"pyvista meshes live in R³; vertices have {v.shape[1]} coordinates")
    f = check_simplices(simplices, len(v), "simplices", width=3)
    pv = _pyvista()
    cells = np.column_stack([np.full(len(f), 3, dtype=np.int64), f]).ravel()
    return pv.PolyData(v.copy(), cells)


def from_pyvista(mesh: pyvista.DataSet) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, simplices)`` of a pyvista mesh; polygons and other cells are triangulated first.

    Thesis: §3.4 (the triangulated surfaces of the experiments).

    Parameters
    ----------
    mesh : pyvista.DataSet
        ``PolyData``, ``UnstructuredGrid``, ...: its surface is used.

    Returns
    -------
    vertices : ndarray of float64, shape (nv, 3)
        The mesh's points.
    simplices : ndarray of int64, shape (m, 3)
        The triangles, in the mesh's vertex order (lines and points are dropped).

    Raises
    ------
    ImportError
        If pyvista is not installed (the ``[mesh]`` extra).
    TypeError
        If ``mesh`` is not a pyvista data set (``InvalidTypeError``, also a ``ValueError``).
    ValueError
        If it has no faces, or its faces could not be triangulated.
    """
    pv = _pyvista()
    if not isinstance(mesh, pv.DataSet):
        raise InvalidTypeError(f"expected a pyvista mesh (PolyData, UnstructuredGrid, ...), got {type(mesh).__name__}")
    if isinstance(mesh, pv.PolyData):
        surface = mesh
    else:
        import warnings

        with warnings.catch_warnings():  # pyvista announces a change of the default algorithm
            warnings.simplefilter("ignore", FutureWarning)
            # pyvista 0.49 warns with PyVistaFutureWarning, a Warning but not a FutureWarning
            warnings.filterwarnings("ignore", message="The default value of `algorithm`")
            surface = mesh.extract_surface()
    if np.asarray(surface.faces).size == 0:
        raise ValueError("the mesh has no faces (only points or lines)")
    if not surface.is_all_triangles:
        surface = surface.triangulate()
    faces = np.asarray(surface.faces, dtype=np.int64).reshape(-1, 4)
    if faces.size and not np.all(faces[:, 0] == 3):
        raise ValueError("the mesh's faces could not be triangulated")
    return np.asarray(surface.points, dtype=np.float64), np.ascontiguousarray(faces[:, 1:])


def read_mesh(path: str | os.PathLike) -> tuple[np.ndarray, np.ndarray]:
    """Read a triangle mesh from any file pyvista reads (``.vtk``, ``.vtp``, ``.ply``, ``.stl``, ``.obj``, ...).

    Thesis: §3.4 (surfaces to estimate curvature on).

    Parameters
    ----------
    path : str or os.PathLike
        The file; its suffix tells pyvista the format.

    Returns
    -------
    vertices : ndarray of float64, shape (nv, 3)
        The points of the file's surface.
    simplices : ndarray of int64, shape (m, 3)
        Its triangles (polygons triangulated), as :func:`from_pyvista` gives them.

    Raises
    ------
    ImportError
        If pyvista is not installed (the ``[mesh]`` extra).
    FileNotFoundError
        If there is no such file.
    ValueError
        If pyvista cannot read it or it holds no faces.
    """
    p = Path(path)
    if not p.is_file():
        raise FileNotFoundError(f"no mesh file {p}")
    pv = _pyvista()
    try:
        mesh = pv.read(str(p))
    except Exception as err:  # pyvista/VTK raise various errors for unknown or broken files
        raise ValueError(f"cannot read {p.name} as a mesh: {err}") from None
    if isinstance(mesh, pv.MultiBlock):
        mesh = mesh.combine()
    return from_pyvista(mesh)


def write_mesh(path: str | os.PathLike, vertices: npt.ArrayLike, simplices: npt.ArrayLike, *,
               binary: bool = True) -> Path:
    """Write a triangle mesh; the format follows the suffix (``.vtk``, ``.vtp``, ``.ply``, ``.stl``, ...).

    Thesis: §3.4 (the reconstructed surfaces, for viewing in other tools).

    Written to a temporary file beside ``path`` first and renamed on success, so an interrupted
    write never leaves a half-written mesh.  ``.vtk``/``.vtp`` keep float64 coordinates; ``.ply``
    and ``.stl`` store float32, and STL stores each face's corners (vertices shared by triangles are
    merged again when read).

    Parameters
    ----------
    path : str or os.PathLike
        Destination file, with a suffix naming the format (its folder must exist).
    vertices : array_like, shape (nv, 3)
        The points, as in :func:`to_pyvista`.
    simplices : array_like of int, shape (m, 3)
        The triangles, as in :func:`to_pyvista`.
    binary : bool, default True
        Binary rather than ASCII where the format allows both.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    ImportError
        If pyvista is not installed (the ``[mesh]`` extra).
    ValueError
        On a path without suffix, an invalid mesh, or a format pyvista cannot write.
    FileNotFoundError
        If the folder of ``path`` does not exist.
    """
    p = Path(path)
    if not p.suffix:
        raise ValueError(f"give the file a suffix naming its format (.vtk, .vtp, .ply, .stl, ...): {p}")
    if not p.parent.is_dir():
        raise FileNotFoundError(f"no folder {p.parent} to write {p.name} into")
    mesh = to_pyvista(vertices, simplices)
    fd, tmp = tempfile.mkstemp(prefix=f".{p.stem}-", suffix=p.suffix, dir=p.parent)
    os.close(fd)
    try:
        try:
            mesh.save(tmp, binary=binary)
        except ValueError as err:
            raise ValueError(f"cannot write {p.name}: {err}") from None
        os.replace(tmp, p)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    return p

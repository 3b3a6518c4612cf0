"""Meshes on disk: read and written through meshio (the files in ``meshes/``).

The package builds its own grids from a scene's parameters; a file lets a user (or a
study) fix one exactly and inspect it in ParaView. Files hold dimensionless coordinates
in the units the scene's ``[mesh]`` ranges use (Hertz semi-axes for elastic contacts,
hydrodynamic lengths sqrt(2 r h0) for rigid ones, the strip half-width for the
Korovchinsky patch), so one file serves every load. ``meshes/make_meshes.py`` writes
the shipped ones from their parameters.

* :func:`read_mesh` / :func:`write_mesh` - any meshio format (``.vtu``, ``.msh``,
  ``.xdmf``, ...) to and from scikit-fem meshes (line, triangle, quad cells);
* :func:`tensor_axes` - the node coordinates x, y of a quad mesh on a tensor grid
  (the grids of point contacts); :func:`line_nodes` - the nodes of a 1D mesh;
* :func:`outlet_graded_nodes` - line-contact nodes refined around the outlet spike.

meshio is imported inside the functions that use it.
"""
from __future__ import annotations

import contextlib
import functools
import io
import os
import secrets
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["read_mesh", "write_mesh", "tensor_axes", "line_nodes", "tensor_mesh",
           "grid_axes", "every_other", "outlet_graded_nodes"]

#: meshio cell types and the scikit-fem meshes they become.
_CELLS = {"line": "MeshLine", "triangle": "MeshTri", "quad": "MeshQuad"}


def read_mesh(path: str | os.PathLike) -> Any:
    """Read a mesh file into a scikit-fem mesh (``MeshLine``, ``MeshTri`` or ``MeshQuad``).

    Parameters
    ----------
    path : str or Path
        Any format meshio reads. It must hold one kind of cell (line, triangle or quad)
        in 1 or 2 dimensions (a zero z coordinate is dropped).

    Returns
    -------
    skfem.Mesh

    Raises
    ------
    ValueError
        Unreadable file, no supported cells, or several kinds of cells (the message names
        the file).
    """
    import meshio
    import skfem

    path = Path(path)
    if not path.is_file():
        raise ValueError(f"mesh file {str(path)!r} does not exist")
    try:  # meshio's readers may print, and even call sys.exit, on a bad file
        with contextlib.redirect_stdout(io.StringIO()), \
                contextlib.redirect_stderr(io.StringIO()):
            m = meshio.read(path)
    except (Exception, SystemExit) as exc:
        raise ValueError(f"mesh file {str(path)!r} cannot be read by meshio: "
                         f"{type(exc).__name__} {exc}") from None
    kinds = [c for c in m.cells if c.type in _CELLS and len(c.data)]
    if len({c.type for c in kinds}) != 1:
        found = sorted({c.type for c in m.cells})
        raise ValueError(f"mesh file {str(path)!r} must hold one kind of cell among "
                         f"{', '.join(_CELLS)}; found {found}")
    ctype = kinds[0].type
    cells = np.vstack([c.data for c in kinds]).T
    pts = np.asarray(m.points, dtype=float)
    dim = 1 if ctype == "line" else 2
    if pts.shape[1] > dim and np.any(pts[:, dim:] != 0.0):
        raise ValueError(f"mesh file {str(path)!r}: {ctype} cells need a {dim}D mesh, the "
                         "points have non-zero further coordinates")
    if ctype == "line":
        order = np.argsort(pts[:, 0])
        return skfem.MeshLine(pts[order, 0])
    mesh_class = getattr(skfem, _CELLS[ctype])
    return mesh_class(np.ascontiguousarray(pts[:, :2].T), np.ascontiguousarray(cells))


def write_mesh(mesh: Any, path: str | os.PathLike) -> Path:
    """Write a scikit-fem mesh (line, triangle or quad) with meshio, atomically.

    The file is written under a temporary name in the target folder and moved into
    place, so an interrupted write never leaves a half-written mesh.
    """
    import meshio

    path = Path(path)
    kind = _kind(mesh)
    if kind is None:
        raise ValueError(f"write_mesh writes MeshLine, MeshTri or MeshQuad, got "
                         f"{type(mesh).__name__}")
    p = np.asarray(mesh.p, dtype=float)
    pts = np.zeros((p.shape[1], 3))
    pts[:, :p.shape[0]] = p.T
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp{path.suffix}")
    try:
        meshio.write(str(tmp), meshio.Mesh(pts, [(kind, np.asarray(mesh.t).T)]))
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()
    return path


def _kind(mesh: Any) -> str | None:
    """The meshio cell type of a scikit-fem mesh (None if unsupported)."""
    import skfem

    for ctype, name in _CELLS.items():
        if isinstance(mesh, getattr(skfem, name)):
            return ctype
    return None


def tensor_mesh(x: np.ndarray, y: np.ndarray) -> Any:
    """A ``MeshQuad`` on the tensor grid of node coordinates x (nx,), y (ny,)."""
    import skfem

    return skfem.MeshQuad.init_tensor(np.asarray(x, float), np.asarray(y, float))


def tensor_axes(mesh: Any) -> tuple[np.ndarray, np.ndarray]:
    """Node coordinates x (nx,), y (ny,) of a quad mesh that is a tensor-product grid.

    Raises
    ------
    ValueError
        If the mesh is not quads on a tensor grid (every (x_i, y_j) a node, nothing else).
    """
    if _kind(mesh) != "quad":
        raise ValueError(f"a contact grid is a quad mesh on a tensor grid, got "
                         f"{type(mesh).__name__}")
    x = np.unique(mesh.p[0])
    y = np.unique(mesh.p[1])
    if x.size * y.size != mesh.p.shape[1] or x.size < 3 or y.size < 3:
        raise ValueError(f"the quad mesh is not a tensor grid: {mesh.p.shape[1]} nodes on "
                         f"{x.size} x values and {y.size} y values")
    return x, y


def line_nodes(mesh: Any) -> np.ndarray:
    """Sorted node coordinates of a 1D mesh (``MeshLine``)."""
    if _kind(mesh) != "line":
        raise ValueError(f"a line-contact grid is a 1D mesh, got {type(mesh).__name__}")
    return np.sort(np.asarray(mesh.p[0], dtype=float))


@functools.lru_cache(maxsize=32)
def _axes(path: str, mtime: float) -> tuple[tuple[float, ...], tuple[float, ...] | None]:
    mesh = read_mesh(path)
    kind = _kind(mesh)
    if kind == "line":
        return tuple(line_nodes(mesh)), None
    if kind == "quad":
        x, y = tensor_axes(mesh)
        return tuple(x), tuple(y)
    raise ValueError(f"mesh file {path!r} holds triangles: a contact grid is a line mesh "
                     "(line contact) or quads on a tensor grid (point contact)")


def grid_axes(path: str | os.PathLike) -> tuple[np.ndarray, np.ndarray | None]:
    """Node coordinates of a contact grid file: x (and y for a quad tensor grid; None for
    a 1D mesh), dimensionless, as stored. Cached per file and modification time."""
    p = Path(path)
    if not p.is_file():
        raise ValueError(f"mesh file {str(p)!r} does not exist")
    x, y = _axes(str(p.resolve()), p.stat().st_mtime)
    return np.array(x), (None if y is None else np.array(y))


def every_other(axis: np.ndarray, nodes: int) -> np.ndarray:
    """The nodes of ``axis`` taken with the stride that leaves ``nodes`` of them (the
    coarser grids of grid sequencing); ValueError unless the stride is a whole number."""
    n = axis.size
    if nodes == n:
        return axis
    if nodes < 2 or (n - 1) % (nodes - 1):
        raise ValueError(f"a grid of {n} nodes has no nested coarser grid of {nodes} nodes")
    return axis[::(n - 1) // (nodes - 1)]


def outlet_graded_nodes(nodes: int, x_range: tuple[float, float] = (-4.5, 1.5),
                        centre: float = 0.95, width: float = 0.1,
                        ratio: float = 9.0) -> np.ndarray:
    """Line-contact nodes refined around the outlet pressure spike, in Hertz half-widths.

    The node density is ``1 + (ratio - 1) exp(-((x - centre)/width)^2)``: the spacing at
    ``centre`` is about ``ratio`` times finer than far from it. The defaults put the
    refinement where an elastic piezo-viscous line contact has its spike and its minimum
    film (0.93-0.97 b at Moes M = 65-500; docs/line_contact.md, "Graded grids"). Written
    to a file (:func:`write_mesh` of ``skfem.MeshLine(x)``), it is a scene's
    ``mesh.file``; with ``nodes - 1`` divisible by 4 its every-other-node subsets are the
    coarser levels of the grid sequence and of the error estimate.

    Parameters
    ----------
    nodes : int
        Number of nodes (>= 3).
    x_range : (float, float)
        Ends of the grid, Hertz half-widths b.
    centre, width : float
        Centre and width of the refinement, Hertz half-widths b.
    ratio : float
        Largest over smallest node density (>= 1).

    Returns
    -------
    numpy.ndarray
        Increasing node coordinates x/b, shape (nodes,), the ends exactly ``x_range``.
    """
    if isinstance(nodes, bool) or not isinstance(nodes, (int, np.integer)) or nodes < 3:
        raise ValueError(f"nodes must be an integer >= 3, got {nodes!r}")
    x0, x1 = (float(v) for v in x_range)
    if not (np.isfinite(x0) and np.isfinite(x1) and x0 < x1):
        raise ValueError(f"x_range must be two finite increasing values (Hertz half-widths), "
                         f"got {x_range!r}")
    if not (np.isfinite(width) and width > 0.0):
        raise ValueError(f"width must be > 0 (Hertz half-widths), got {width!r}")
    if not (np.isfinite(ratio) and ratio >= 1.0):
        raise ValueError(f"ratio must be >= 1 (dimensionless), got {ratio!r}")
    s = np.linspace(x0, x1, 200 * int(nodes) + 1)
    density = 1.0 + (ratio - 1.0) * np.exp(-((s - centre) / width) ** 2)
    cdf = np.concatenate(([0.0], np.cumsum(0.5 * (density[1:] + density[:-1]) * np.diff(s))))
    x = np.interp(np.linspace(0.0, cdf[-1], int(nodes)), cdf, s)
    x[0], x[-1] = x0, x1
    return x

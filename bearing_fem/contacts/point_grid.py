"""Tensor grids of point contacts and the sparse-LU ordering of their free nodes.

* :class:`PointGrid` - a tensor-product grid meshed by bilinear quads (scikit-fem
  ``ElementQuad1``), node numbering ``j*nx + i`` (x fastest), with its quadrature
  operators; optionally the half y >= 0 of a y-symmetric domain.
* :func:`graded_coordinates` - sinh-graded nodes (fine at the centre) for rigid scenes.
* :func:`nested_dissection` and :class:`FreePattern` - the fill-reducing order and the
  cached sparsity pattern of the preconditioner's sparse LU.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from skfem import CellBasis, ElementQuad1, MeshQuad

from ..numerics.fe import QuadratureOperators, quadrature_operators

#: SuperLU threshold partial pivoting of the preconditioner LU: the diagonal is kept as
#: pivot unless it is below this fraction of the largest entry of its column (the fill-
#: reducing nested-dissection order survives; 1.0 would be classical partial pivoting).
LU_PIVOT_THRESHOLD = 0.1
#: Nested dissection: blocks of at most this many nodes per side are not split further
#: (measured on the 255 x 255 free nodes of 257^2: 4 -> fill 5.2e6, factor 0.21 s,
#: solve 6 ms; COLAMD: fill 9.0e6, 0.67 s, 15 ms; MMD on A^T + A: 5.5e6, 0.28 s, 8 ms).
ND_LEAF_NODES = 4


# ---------------------------------------------------------------------------------------
# grid
# ---------------------------------------------------------------------------------------
@dataclass
class PointGrid:
    """Tensor grid of bilinear quads with node numbering ``j*nx + i``.

    Attributes
    ----------
    x, y : ndarray
        Node coordinates [m], strictly increasing.
    mirror_y : bool
        True for the half y >= 0 of a y-symmetric domain (row 0 is the symmetry line).
    mesh : skfem.MeshQuad
    basis : skfem.CellBasis
    ops : QuadratureOperators
    """

    x: np.ndarray
    y: np.ndarray
    mesh: MeshQuad
    basis: CellBasis
    ops: QuadratureOperators
    mirror_y: bool = False

    @classmethod
    def tensor(cls, x: np.ndarray, y: np.ndarray, intorder: int | None = None,
               mirror_y: bool = False) -> "PointGrid":
        """Build the grid from node coordinates x (nx,), y (ny,) [m].

        ``mirror_y``: the grid is the half y >= 0 (``y[0] = 0``) of a domain symmetric in
        y; its first row is the symmetry line (free nodes, natural condition).
        """
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        for name, v in (("x", x), ("y", y)):
            if v.ndim != 1 or v.size < 3 or np.any(np.diff(v) <= 0):
                raise ValueError(f"grid {name} must be >= 3 strictly increasing coordinates "
                                 f"in m, got shape {v.shape}")
        nx, ny = x.size, y.size
        xx, yy = np.meshgrid(x, y)  # (ny, nx): flat index j*nx + i
        p = np.vstack([xx.ravel(), yy.ravel()])
        i, j = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1))
        n00 = (j * nx + i).ravel()
        # same local orientation as MeshQuad.init_tensor: (i,j), (i,j+1), (i+1,j+1), (i+1,j)
        t = np.vstack([n00, n00 + nx, n00 + nx + 1, n00 + 1])
        mesh = MeshQuad(p, t)
        kw = {} if intorder is None else {"intorder": intorder}
        basis = CellBasis(mesh, ElementQuad1(), **kw)
        if mirror_y and y[0] != 0.0:
            raise ValueError(f"a mirrored grid starts at y = 0 m, got y[0] = {y[0]!r} m")
        return cls(x=x, y=y, mesh=mesh, basis=basis, ops=quadrature_operators(basis),
                   mirror_y=mirror_y)

    @property
    def shape(self) -> tuple[int, int]:
        """(ny, nx)."""
        return self.y.size, self.x.size

    @property
    def size(self) -> int:
        return self.x.size * self.y.size

    def node_coordinates(self) -> tuple[np.ndarray, np.ndarray]:
        """Flat node coordinates (X, Y) [m], index j*nx + i."""
        xx, yy = np.meshgrid(self.x, self.y)
        return xx.ravel(), yy.ravel()

    def boundary_mask(self) -> np.ndarray:
        """Flat boolean mask of the boundary nodes."""
        m = np.zeros(self.shape, dtype=bool)
        m[0, :] = m[-1, :] = m[:, 0] = m[:, -1] = True
        if self.mirror_y:
            m[0, 1:-1] = False  # symmetry line
        return m.ravel()

    def interpolate(self, field: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Bilinear interpolation of a nodal field to points (x, y) [m] (flattened)."""
        from scipy.interpolate import RegularGridInterpolator

        f = RegularGridInterpolator((self.y, self.x), np.asarray(field).reshape(self.shape),
                                    bounds_error=False, fill_value=None)
        return f(np.column_stack([np.ravel(y), np.ravel(x)]))


def graded_coordinates(lo: float, hi: float, nodes: int, unit: float,
                       stretch: float = 1.0) -> np.ndarray:
    """Nodes on [lo, hi] * unit [m], dense near 0: x = unit stretch sinh(s), s uniform.

    Parameters
    ----------
    lo, hi : float
        Range in units of ``unit`` [-], lo < 0 < hi.
    nodes : int
        Node count.
    unit : float
        Length unit [m].
    stretch : float
        Length [in ``unit``] below which the spacing is nearly uniform [-].
    """
    s = np.linspace(math.asinh(lo / stretch), math.asinh(hi / stretch), nodes)
    return unit * stretch * np.sinh(s)


# ---------------------------------------------------------------------------------------
# preconditioner pattern
# ---------------------------------------------------------------------------------------
def nested_dissection(nx: int, ny: int, leaf: int = ND_LEAF_NODES) -> np.ndarray:
    """Nested-dissection order of an nx x ny tensor grid (flat index j*nx + i).

    The grid is split recursively across its longer side by one grid line (a separator
    for the 9-point stencil of bilinear quads); both halves are ordered first, the
    separator last. Blocks of at most ``leaf`` nodes per side keep their natural order.

    Parameters
    ----------
    nx, ny : int
        Nodes along x and y [-].
    leaf : int
        Largest block side [nodes] that is not split further.

    Returns
    -------
    perm : ndarray of int, shape (nx * ny,)
        ``perm[k]`` is the flat index of the node eliminated k-th.
    """
    out: list[np.ndarray] = []
    stack = [(0, nx, 0, ny, False)]
    while stack:  # explicit stack: (i0, i1, j0, j1, emit) with emit = separator line
        i0, i1, j0, j1, emit = stack.pop()
        if emit:
            out.append(np.add.outer(np.arange(j0, j1) * nx, np.arange(i0, i1)).ravel())
            continue
        ni, nj = i1 - i0, j1 - j0
        if ni <= 0 or nj <= 0:
            continue
        if ni <= leaf and nj <= leaf:
            out.append(np.add.outer(np.arange(j0, j1) * nx, np.arange(i0, i1)).ravel())
            continue
        # pushed in reverse: first half, second half, then the separator
        if ni >= nj:
            c = (i0 + i1) // 2
            stack += [(c, c + 1, j0, j1, True), (c + 1, i1, j0, j1, False),
                      (i0, c, j0, j1, False)]
        else:
            c = (j0 + j1) // 2
            stack += [(i0, i1, c, c + 1, True), (i0, i1, c + 1, j1, False),
                      (i0, i1, j0, c, False)]
    return np.concatenate(out)


class FreePattern:
    """Free-node block of a grid's assembler pattern, permuted for a sparse LU (internal).

    ``factor(m, scale, diag)`` forms diag(scale) M[free, free] + diag(diag) (M given by
    its values on the assembler pattern) in nested-dissection order as a csc matrix
    and factors it; ``perm``/``inverse`` map free-node vectors to that order and back.
    """

    def __init__(self, grid: PointGrid, free: np.ndarray) -> None:
        ny, nx = grid.shape
        interior = np.zeros(grid.size, dtype=bool)
        interior.reshape(ny, nx)[1:-1, 1:-1] = True
        self.dissected = bool(np.array_equal(np.nonzero(interior)[0], free))
        if self.dissected:
            self.perm = nested_dissection(nx - 2, ny - 2)
        else:  # not the interior block of the grid: SuperLU orders it (MMD on A^T + A)
            self.perm = np.arange(free.size)
        self.inverse = np.empty_like(self.perm)
        self.inverse[self.perm] = np.arange(self.perm.size)
        asm = grid.ops.assembler
        n = grid.size
        where = np.full(n, -1, dtype=np.int64)  # node -> position in the permuted order
        where[free[self.perm]] = np.arange(free.size)
        rows = np.repeat(np.arange(n), np.diff(asm.indptr))
        r, c = where[rows], where[asm.indices]
        keep = np.nonzero((r >= 0) & (c >= 0))[0]
        r, c = r[keep], c[keep]
        order = np.lexsort((r, c))  # csc: by column, then row
        self._select = keep[order]
        self._row = r[order]
        self.indices = r[order].astype(np.int32)
        self.indptr = np.searchsorted(c[order], np.arange(free.size + 1)).astype(np.int32)
        diag_entries = np.nonzero(self._row == c[order])[0]
        if diag_entries.size != free.size:
            raise ValueError("assembler pattern lacks a diagonal entry at a free node")
        self._diag = diag_entries[np.argsort(self._row[diag_entries])]
        self.size = free.size

    def factor(self, m: np.ndarray, scale: np.ndarray, diag: np.ndarray) -> spla.SuperLU:
        """splu of diag(scale) M[free, free] + diag(diag) in the permuted order.

        ``scale`` and ``diag`` are free-node vectors in the original (free) order.
        """
        data = m[self._select] * np.asarray(scale)[self.perm][self._row]
        data[self._diag] += np.asarray(diag)[self.perm]
        a = sp.csc_matrix((data, self.indices, self.indptr), shape=(self.size, self.size))
        return spla.splu(a, permc_spec="NATURAL" if self.dissected else "MMD_AT_PLUS_A",
                         diag_pivot_thresh=LU_PIVOT_THRESHOLD, options={"SymmetricMode": True})



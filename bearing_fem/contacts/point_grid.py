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
from functools import cached_property

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from skfem import CellBasis, ElementQuad1, MeshQuad
from skfem.quadrature import get_quadrature_line

from ..numerics.fe import pattern_values

#: SuperLU threshold partial pivoting of the preconditioner LU: the diagonal is kept as
#: pivot unless it is below this fraction of the largest entry of its column (the fill-
#: reducing nested-dissection order survives; 1.0 would be classical partial pivoting).
LU_PIVOT_THRESHOLD = 0.1
#: Fill cap of the incomplete factors (``FreePattern.factor(drop_tol > 0)``): at most
#: this many times the matrix's nonzeros (never reached at the drop tolerance used).
ILU_FILL_FACTOR = 20.0
#: Nested dissection: blocks of at most this many nodes per side are not split further
#: (measured on the 255 x 255 free nodes of 257^2: 4 -> fill 5.2e6, factor 0.21 s,
#: solve 6 ms; COLAMD: fill 9.0e6, 0.67 s, 15 ms; MMD on A^T + A: 5.5e6, 0.28 s, 8 ms).
ND_LEAF_NODES = 4


# ---------------------------------------------------------------------------------------
# quadrature operators of a tensor grid
# ---------------------------------------------------------------------------------------
def _reference_rule(intorder: int | None) -> tuple[np.ndarray, np.ndarray]:
    """1D Gauss rule on [0, 1] of the quads' tensor rule: points (n,), weights (n,).

    The same rule as scikit-fem's ``CellBasis(mesh, ElementQuad1(), intorder)`` (default
    intorder 4, the 3 x 3 Gauss rule), so the operators equal the scikit-fem ones.
    """
    points, weights = get_quadrature_line(4 if intorder is None else int(intorder))
    return np.asarray(points, dtype=float).ravel(), np.asarray(weights, dtype=float)


class TensorMap:
    """Nodal field -> values at the quadrature points of a tensor grid (value, d/dx or
    d/dy of the bilinear interpolant), applied without a stored matrix.

    Behaves like the csr matrix ``(n_elements * n_quad, n_nodes)`` of
    :class:`~bearing_fem.numerics.fe.QuadratureOperators` for the products the solvers
    use: ``M @ u`` and ``M.T @ f`` with 1-D arrays take the structured path (four shifted
    slices and one small dense product per call); anything else (2-D or sparse operands,
    ``tocsr``) builds the csr matrix once and keeps it.

    Element ``e = j (nx - 1) + i`` (cell [x_i, x_i+1] x [y_j, y_j+1]) has the local nodes
    ``(j + b, i + a)``, ``k = 2 b + a``; its quadrature point ``q = qy n + qx``. Row
    ``e n_quad + q`` of the map is ``sum_k table[q, k] scale[e] u[node_k]``.

    Parameters
    ----------
    grid_shape : (ny, nx)
    table : ndarray (n_quad, 4)
        Reference values of the four local basis functions (or of their derivative in
        the reference coordinate) at the quadrature points.
    scale : ndarray (ny - 1, nx - 1) or None
        Per-element factor (1/hx or 1/hy [1/m] for derivatives; None: 1).
    """

    ndim = 2
    dtype = np.dtype(float)
    __array_ufunc__ = None  # numpy defers ``array @ map`` to __rmatmul__

    def __init__(self, grid_shape: tuple[int, int], table: np.ndarray,
                 scale: np.ndarray | None, *, transposed: bool = False,
                 _base: "TensorMap | None" = None) -> None:
        self.grid_shape = grid_shape
        self.table = table
        self.scale = scale
        self.transposed = transposed
        self._base = _base
        ny, nx = grid_shape
        rows = (ny - 1) * (nx - 1) * table.shape[0]
        self.shape = (nx * ny, rows) if transposed else (rows, nx * ny)
        self._csr: sp.csr_matrix | None = None

    @property
    def T(self) -> "TensorMap":
        base = self._base if self.transposed else self
        if self.transposed:
            return base
        return TensorMap(self.grid_shape, self.table, self.scale, transposed=True,
                         _base=self)

    # -- structured products ---------------------------------------------------------
    def rows(self, u2: np.ndarray, j0: int, j1: int) -> np.ndarray:
        """The map applied to the nodal field ``u2`` (ny, nx), for the cells of rows
        j0 <= j < j1 only: values at their quadrature points, flat in row order."""
        nx = self.grid_shape[1]
        loc = np.empty(((j1 - j0) * (nx - 1), 4), dtype=np.result_type(u2, float))
        for k, (b, a) in enumerate(_LOCAL):
            loc[:, k] = u2[j0 + b:j1 + b, a:nx - 1 + a].ravel()
        if self.scale is not None:
            loc *= self.scale[j0:j1].reshape(-1, 1)
        return (loc @ self.table.T).ravel()

    def add_rows(self, f: np.ndarray, out2: np.ndarray, j0: int, j1: int) -> None:
        """``out2 += M.T f`` for values ``f`` at the quadrature points of the cells of rows
        j0 <= j < j1 (``out2`` nodal, (ny, nx), updated in place)."""
        nx = self.grid_shape[1]
        loc = np.reshape(f, (-1, self.table.shape[0])) @ self.table
        if self.scale is not None:
            loc *= self.scale[j0:j1].reshape(-1, 1)
        for k, (b, a) in enumerate(_LOCAL):
            out2[j0 + b:j1 + b, a:nx - 1 + a] += loc[:, k].reshape(j1 - j0, nx - 1)

    def _forward(self, u: np.ndarray) -> np.ndarray:
        return self.rows(u.reshape(self.grid_shape), 0, self.grid_shape[0] - 1)

    def _backward(self, f: np.ndarray) -> np.ndarray:
        out = np.zeros(self.grid_shape, dtype=np.result_type(f, float))
        self.add_rows(f, out, 0, self.grid_shape[0] - 1)
        return out.ravel()

    def __matmul__(self, other):
        if isinstance(other, np.ndarray) and other.ndim == 1 and not sp.issparse(other):
            if other.shape[0] != self.shape[1]:
                raise ValueError(f"dimension mismatch: {self.shape} @ {other.shape}")
            return self._backward(other) if self.transposed else self._forward(other)
        return self.tocsr() @ other

    def __rmatmul__(self, other):
        return other @ self.tocsr()

    def dot(self, other):
        return self @ other

    # -- csr fallback ----------------------------------------------------------------
    def tocsr(self) -> sp.csr_matrix:
        """The map as a csr matrix (built once, then kept)."""
        if self.transposed:
            return self._base.tocsr().T.tocsr()
        if self._csr is None:
            ny, nx = self.grid_shape
            nq = self.table.shape[0]
            ne = (ny - 1) * (nx - 1)
            j, i = np.divmod(np.arange(ne), nx - 1)
            n00 = j * nx + i
            cols = np.stack([n00, n00 + 1, n00 + nx, n00 + nx + 1], axis=1)  # sorted
            vals = np.broadcast_to(self.table[None], (ne, nq, 4))
            if self.scale is not None:
                vals = vals * self.scale.reshape(-1, 1, 1)
            idx = np.int32 if nx * ny < 2**31 - 1 and ne * nq * 4 < 2**31 - 1 else np.int64
            indices = np.repeat(cols[:, None, :], nq, axis=1).ravel().astype(idx)
            indptr = (np.arange(ne * nq + 1, dtype=np.int64) * 4).astype(idx)
            self._csr = sp.csr_matrix((np.ascontiguousarray(vals).ravel(), indices, indptr),
                                      shape=self.shape)
        return self._csr

    def toarray(self) -> np.ndarray:
        return self.tocsr().toarray()

    def __getattr__(self, name: str):
        # csr attributes (data, indices, indptr, nnz, ...) of the fallback matrix
        if name.startswith("_") or name in ("grid_shape", "table", "scale", "transposed",
                                            "shape"):
            raise AttributeError(name)
        return getattr(self.tocsr(), name)


#: Local nodes of a cell, k = 2 b + a: (b, a) = (y offset, x offset).
_LOCAL = ((0, 0), (0, 1), (1, 0), (1, 1))


class TensorOperators:
    """:class:`~bearing_fem.numerics.fe.QuadratureOperators` of a tensor grid of bilinear
    quads, without stored matrices (the interface the contact solvers use).

    ``value`` and ``grad`` are :class:`TensorMap` objects; ``weights``, ``points`` and
    ``element_size`` are computed on first use; ``assembler`` is a
    :class:`TensorAssembler` (the element assembler of this grid). Same values as the
    scikit-fem operators of ``CellBasis(mesh, ElementQuad1(), intorder)`` to rounding,
    with a fraction of their memory: on 513 x 257 nodes the three csr maps take 170 MB.

    Parameters
    ----------
    x, y : ndarray
        Node coordinates [m], strictly increasing.
    intorder : int or None
        Integration order of the tensor Gauss rule (None: 4, 3 x 3 points).
    """

    def __init__(self, x: np.ndarray, y: np.ndarray, intorder: int | None = None) -> None:
        self.x, self.y = x, y
        s, w = _reference_rule(intorder)
        n = s.size
        self.n_quad = n * n
        self._s, self._w = s, w
        sx = np.tile(s, n)          # q = qy n + qx
        sy = np.repeat(s, n)
        lx = (1.0 - sx, sx)
        ly = (1.0 - sy, sy)
        one = np.ones_like(sx)
        dx = (-one, one)
        value = np.stack([ly[b] * lx[a] for b, a in _LOCAL], axis=1)
        gx = np.stack([ly[b] * dx[a] for b, a in _LOCAL], axis=1)
        gy = np.stack([dx[b] * lx[a] for b, a in _LOCAL], axis=1)
        self._tables = (value, gx, gy)
        self._quad_weights = np.repeat(w, n) * np.tile(w, n)
        self.hx, self.hy = np.diff(x), np.diff(y)
        shape = (y.size, x.size)
        self.grid_shape = shape
        ones = np.ones((y.size - 1, 1))
        self._inv_hx = ones * (1.0 / self.hx)[None, :]
        self._inv_hy = (1.0 / self.hy)[:, None] * np.ones((1, x.size - 1))
        self.value = TensorMap(shape, value, None)
        self.grad = (TensorMap(shape, gx, self._inv_hx), TensorMap(shape, gy, self._inv_hy))

    # -- pointwise data (computed on first use) ----------------------------------------
    def _broadcast(self, fx: np.ndarray | None, fy: np.ndarray | None) -> np.ndarray:
        """fx (nx - 1, n_quad) and fy (ny - 1, n_quad) combined per quadrature point
        (product; a missing factor is 1), flattened in the row order of the maps."""
        ny1, nx1 = self.y.size - 1, self.x.size - 1
        out = np.ones((ny1, nx1, self.n_quad))
        if fx is not None:
            out *= fx[None, :, :]
        if fy is not None:
            out *= fy[:, None, :]
        return out.ravel()

    @cached_property
    def weights(self) -> np.ndarray:
        """Quadrature weights times the cell area [m^2], per quadrature point."""
        return self._broadcast(self.hx[:, None] * np.ones(self.n_quad),
                               self.hy[:, None] * self._quad_weights[None, :])

    @cached_property
    def points(self) -> np.ndarray:
        """Physical coordinates (2, n_elements n_quad) of the quadrature points [m]."""
        n = self._s.size
        sx, sy = np.tile(self._s, n), np.repeat(self._s, n)
        xq = self.x[:-1, None] + self.hx[:, None] * sx[None, :]
        yq = self.y[:-1, None] + self.hy[:, None] * sy[None, :]
        return np.stack([self._broadcast(xq, None), self._broadcast(None, yq)])

    @cached_property
    def element_size(self) -> np.ndarray:
        """Cell size along x at each quadrature point [m] (stabilisation)."""
        return self._broadcast(self.hx[:, None] * np.ones(self.n_quad), None)

    def coordinate_x(self) -> tuple[np.ndarray, np.ndarray]:
        """x of the quadrature points per (cell column, point): (nx - 1, n_quad) [m] and
        its broadcast to all points is ``points[0]``; kept small for separable fields."""
        n = self._s.size
        return self.x[:-1, None] + self.hx[:, None] * np.tile(self._s, n)[None, :]

    def coordinate_y(self) -> np.ndarray:
        """y of the quadrature points per (cell row, point): (ny - 1, n_quad) [m]."""
        n = self._s.size
        return self.y[:-1, None] + self.hy[:, None] * np.repeat(self._s, n)[None, :]

    def separable(self, fx: np.ndarray | None, fy: np.ndarray | None) -> np.ndarray:
        """A field f(x) + g(y) at every quadrature point from its per-column part
        fx (nx - 1, n_quad) and per-row part fy (ny - 1, n_quad) (None: 0)."""
        ny1, nx1 = self.y.size - 1, self.x.size - 1
        out = np.zeros((ny1, nx1, self.n_quad))
        if fx is not None:
            out += fx[None, :, :]
        if fy is not None:
            out += fy[:, None, :]
        return out.ravel()

    # -- cell rows (bounded temporaries) -------------------------------------------------
    def chunks(self, points: int) -> list[tuple[int, int]]:
        """Ranges [j0, j1) of cell rows with about ``points`` quadrature points each,
        covering the grid."""
        ny1 = self.y.size - 1
        step = max(1, int(points) // ((self.x.size - 1) * self.n_quad))
        return [(j, min(j + step, ny1)) for j in range(0, ny1, step)]

    def weights_rows(self, j0: int, j1: int) -> np.ndarray:
        """:attr:`weights` of the cells of rows j0 <= j < j1."""
        w = (self.hy[j0:j1, None, None] * self.hx[None, :, None]) * self._quad_weights
        return w.ravel()

    def element_size_rows(self, j0: int, j1: int) -> np.ndarray:
        """:attr:`element_size` of the cells of rows j0 <= j < j1."""
        return np.broadcast_to(self.hx[None, :, None],
                               (j1 - j0, self.x.size - 1, self.n_quad)).ravel()

    def separable_rows(self, fx: np.ndarray | None, fy: np.ndarray | None, j0: int,
                       j1: int) -> np.ndarray:
        """:meth:`separable` for the cells of rows j0 <= j < j1 only."""
        out = np.zeros((j1 - j0, self.x.size - 1, self.n_quad))
        if fx is not None:
            out += fx[None, :, :]
        if fy is not None:
            out += fy[j0:j1, None, :]
        return out.ravel()

    # -- QuadratureOperators interface ----------------------------------------------------
    @property
    def mass(self) -> np.ndarray:
        """Integrals of the basis functions int phi_i [m^2] (the load row)."""
        out = np.zeros(self.grid_shape)
        for j0, j1 in self.chunks(2**16):
            self.value.add_rows(self.weights_rows(j0, j1), out, j0, j1)
        return out.ravel()

    def integrate(self, f_q: np.ndarray) -> float:
        """Integral of a field given at the quadrature points."""
        return float(np.dot(self.weights, f_q))

    def weak_divergence(self, *flux: np.ndarray) -> np.ndarray:
        """Nodal vector int F . grad(phi_i) for a flux F given at the quadrature points."""
        w = self.weights
        out = self.grad[0].T @ (w * flux[0])
        for g, f in zip(self.grad[1:], flux[1:]):
            out = out + g.T @ (w * f)
        return out

    def flux_jacobian(self, d: int, coeff_value: np.ndarray,
                      coeff_grad: tuple[np.ndarray, ...]) -> sp.csr_matrix:
        """Matrix of int (a phi_j + sum_k b_k d_k phi_j) d_d phi_i (sparse products)."""
        gt = self.grad[d].tocsr().T
        out = gt @ sp.diags(self.weights * coeff_value) @ self.value.tocsr()
        for k, b in enumerate(coeff_grad):
            out = out + gt @ sp.diags(self.weights * b) @ self.grad[k].tocsr()
        return out.tocsr()

    @cached_property
    def assembler(self) -> "TensorAssembler":
        """Element assembler of the grid's forms on the 9-point pattern (cached)."""
        return TensorAssembler(self)


class TensorAssembler:
    """Sums of :meth:`TensorOperators.flux_jacobian` terms on a tensor grid, on one fixed
    csr pattern (the 9-point stencil: all node pairs sharing a cell, sorted columns).

    The local matrices of all cells are products of the coefficient arrays with constant
    reference tables (one dense (n_cells, n_quad) x (n_quad, 16) product per nonzero
    coefficient), scattered into the nine stencil diagonals by shifted slices and gathered
    into the csr order by one precomputed index. Same interface as
    :class:`~bearing_fem.numerics.fe.ElementAssembler` (``flux_jacobian_sum``,
    ``pattern_data``, ``matrix``, ``indices``, ``indptr``, ``nnz``, ``n_dofs``).

    Parameters
    ----------
    ops : TensorOperators
    """

    def __init__(self, ops: TensorOperators) -> None:
        ny, nx = ops.grid_shape
        self.grid_shape = (ny, nx)
        self.n_dofs = n = nx * ny
        self._ops = ops
        value, gx, gy = ops._tables
        w = ops._quad_weights[:, None, None]
        # T[d][c][q, alpha, beta] = w_q D_d phi_alpha(q) B_c phi_beta(q)
        tests = (gx, gy)
        trials = (value, gx, gy)
        self._tables = [[(w * tests[d][:, :, None] * trials[c][:, None, :]).reshape(-1, 16)
                         for c in range(3)] for d in range(2)]
        hx = np.diff(ops.x)[None, :] * np.ones((ny - 1, 1))
        hy = np.diff(ops.y)[:, None] * np.ones((1, nx - 1))
        area = hx * hy
        # factor of each (test derivative d, trial part c): area / (h_d h_c), h_value = 1
        hs = (hx, hy)
        self._factors = [[(area / hs[d] / (1.0 if c == 0 else hs[c - 1])).ravel()
                          for c in range(3)] for d in range(2)]
        # csr pattern of the 9-point stencil, columns sorted (offset order below)
        jj, ii = np.divmod(np.arange(n), nx)
        offsets = [(dy, dx) for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
        valid = np.stack([(jj + dy >= 0) & (jj + dy < ny) & (ii + dx >= 0) & (ii + dx < nx)
                          for dy, dx in offsets], axis=1)                   # (n, 9)
        col = np.stack([np.arange(n) + dy * nx + dx for dy, dx in offsets], axis=1)
        idx = np.int32 if 9 * n < 2**31 - 1 else np.int64
        self.indptr = np.concatenate([[0], np.cumsum(valid.sum(axis=1))]).astype(idx)
        self.indices = col[valid].astype(idx)
        self.nnz = int(self.indices.size)
        rows = np.repeat(np.arange(n), 9).reshape(n, 9)
        slot = np.broadcast_to(np.arange(9), (n, 9))
        self._gather = (slot[valid].astype(np.int64) * n + rows[valid])   # into (9, n)
        self._keys = rows[valid].astype(np.int64) * n + col[valid]
        # stencil slot of local pair (alpha, beta): (b_beta - b_alpha + 1) 3 + (a_beta - ...)
        self._pairs = [(al, be, (_LOCAL[be][0] - _LOCAL[al][0] + 1) * 3
                        + (_LOCAL[be][1] - _LOCAL[al][1] + 1)) for al in range(4)
                       for be in range(4)]

    def matrix(self, data: np.ndarray) -> sp.csr_matrix:
        """csr matrix on the assembler's pattern with the given ``data`` (not copied)."""
        return sp.csr_matrix((data, self.indices, self.indptr), shape=(self.n_dofs,) * 2)

    def _local(self, d: int, a, b, j0: int, j1: int) -> np.ndarray | None:
        """Local matrices (n_cells, 16) of one term on the cells of rows j0 <= j < j1, or
        None if all its coefficients are 0."""
        nq = self._ops.n_quad
        c0, c1 = j0 * (self.grid_shape[1] - 1), j1 * (self.grid_shape[1] - 1)
        out = None
        for c, coeff in enumerate((a,) + tuple(b)):
            if coeff is None or not np.any(coeff):
                continue
            part = np.reshape(coeff, (-1, nq)) @ self._tables[d][c]
            part *= self._factors[d][c][c0:c1, None]
            out = part if out is None else out + part
        return out

    def _scatter(self, local: np.ndarray, stencil: np.ndarray, j0: int, j1: int,
                 column_scale: np.ndarray | None = None) -> None:
        ny, nx = self.grid_shape
        s2 = None if column_scale is None else np.reshape(column_scale, (ny, nx))
        for al, be, slot in self._pairs:
            ba, aa = _LOCAL[al]
            vals = local[:, 4 * al + be].reshape(j1 - j0, nx - 1)
            if s2 is not None:
                bb, ab = _LOCAL[be]
                vals = vals * s2[j0 + bb:j1 + bb, ab:nx - 1 + ab]
            stencil[slot, j0 + ba:j1 + ba, aa:nx - 1 + aa] += vals

    def stencil(self) -> np.ndarray:
        """Zero stencil array (9, ny, nx) for :meth:`add` and :meth:`csr`."""
        return np.zeros((9,) + self.grid_shape)

    def add(self, stencil: np.ndarray, terms, j0: int = 0, j1: int | None = None) -> None:
        """Add the terms of :meth:`flux_jacobian_sum` with coefficients given on the cells
        of rows j0 <= j < j1 (default all) to ``stencil`` (in place)."""
        j1 = self.grid_shape[0] - 1 if j1 is None else j1
        plain = None
        for term in terms:
            d, a, b = term[:3]
            scale = term[3] if len(term) > 3 else None
            local = self._local(d, a, b, j0, j1)
            if local is None:
                continue
            if scale is not None:
                self._scatter(local, stencil, j0, j1, scale)
            else:
                plain = local if plain is None else plain + local
        if plain is not None:
            self._scatter(plain, stencil, j0, j1)

    def csr(self, stencil: np.ndarray) -> sp.csr_matrix:
        """The csr matrix (on the pattern) of a stencil array."""
        return self.matrix(stencil.reshape(-1)[self._gather])

    def flux_jacobian_sum(self, terms) -> sp.csr_matrix:
        """Sum over ``terms`` of ``flux_jacobian(d, a, (b_0, b_1))``, on the fixed pattern.

        Parameters
        ----------
        terms : iterable of (d, a, b) or (d, a, b, s)
            As :meth:`bearing_fem.numerics.fe.ElementAssembler.flux_jacobian_sum`: d the
            test-function derivative, a and b = (b_x, b_y) the coefficients of the trial
            function value and gradient at the quadrature points, s an optional nodal
            column scaling.

        Returns
        -------
        scipy.sparse.csr_matrix, shape (n_dofs, n_dofs)
        """
        stencil = self.stencil()
        self.add(stencil, terms)
        return self.csr(stencil)

    def pattern_data(self, mat: sp.spmatrix) -> np.ndarray | None:
        """Values of ``mat`` at the pattern positions (zeros elsewhere), or None if ``mat``
        has an entry outside the pattern."""
        return pattern_values(mat, self.indptr, self.indices, self._keys)


# ---------------------------------------------------------------------------------------
# grid
# ---------------------------------------------------------------------------------------
class PointGrid:
    """Tensor grid of bilinear quads with node numbering ``j*nx + i``.

    Attributes
    ----------
    x, y : ndarray
        Node coordinates [m], strictly increasing.
    mirror_y : bool
        True for the half y >= 0 of a y-symmetric domain (row 0 is the symmetry line).
    ops : TensorOperators
        Quadrature operators (built on first use).
    assembler : TensorAssembler
        Element assembler on the 9-point pattern (``ops.assembler``).
    mesh : skfem.MeshQuad
    basis : skfem.CellBasis
        The scikit-fem mesh and basis of the same grid, built only when asked for (the
        solvers use ``ops``).
    """

    def __init__(self, x: np.ndarray, y: np.ndarray, intorder: int | None = None,
                 mirror_y: bool = False) -> None:
        self.x, self.y = x, y
        self.intorder = intorder
        self.mirror_y = mirror_y

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
        if mirror_y and y[0] != 0.0:
            raise ValueError(f"a mirrored grid starts at y = 0 m, got y[0] = {y[0]!r} m")
        return cls(x, y, intorder, mirror_y)

    @cached_property
    def ops(self) -> TensorOperators:
        return TensorOperators(self.x, self.y, self.intorder)

    @property
    def assembler(self) -> TensorAssembler:
        return self.ops.assembler

    def release(self) -> None:
        """Drop the cached LU patterns (rebuilt on demand)."""
        self.__dict__.pop("_free_patterns", None)

    def free_pattern(self, free: np.ndarray) -> "FreePattern":
        """The :class:`FreePattern` of the free nodes ``free`` (cached per grid: every
        problem on the grid with the same free nodes shares it)."""
        cache = self.__dict__.setdefault("_free_patterns", {})
        key = (free.size, int(free[0]) if free.size else -1, int(free[-1]) if free.size else -1)
        pat = cache.get(key)
        if pat is None or not np.array_equal(pat.free, free):
            pat = cache[key] = FreePattern(self, free)
        return pat

    @cached_property
    def mesh(self) -> MeshQuad:
        nx, ny = self.x.size, self.y.size
        xx, yy = np.meshgrid(self.x, self.y)  # (ny, nx): flat index j*nx + i
        p = np.vstack([xx.ravel(), yy.ravel()])
        i, j = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1))
        n00 = (j * nx + i).ravel()
        # same local orientation as MeshQuad.init_tensor: (i,j), (i,j+1), (i+1,j+1), (i+1,j)
        t = np.vstack([n00, n00 + nx, n00 + nx + 1, n00 + 1])
        return MeshQuad(p, t)

    @cached_property
    def basis(self) -> CellBasis:
        kw = {} if self.intorder is None else {"intorder": self.intorder}
        return CellBasis(self.mesh, ElementQuad1(), **kw)

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

    @property
    def whole_y_range(self) -> tuple[float, float]:
        """(y0, y1) [m] of the whole domain: a half grid y >= 0 stands for
        [-y[-1], y[-1]]."""
        y0 = -self.y[-1] if self.mirror_y else self.y[0]
        return float(y0), float(self.y[-1])

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
def require_finite_factor_data(data: np.ndarray) -> None:
    """Raise RuntimeError if a matrix about to be factored has a non-finite entry.

    SuperLU does not check its input: a NaN or inf entry (an iterate whose viscosity
    overflowed in the Jacobian while its residual stayed finite) crashed the process
    (segmentation fault in ``splu``) instead of failing the Newton step, which the
    Newton loop answers with a regularised retry.
    """
    bad = int(np.count_nonzero(~np.isfinite(data)))
    if bad:
        raise RuntimeError(f"the Jacobian to factor has {bad} non-finite entries")


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
        free = np.asarray(free)
        self.free = free
        # a rectangular block of nodes (the interior; on a mirrored half grid the interior
        # plus the symmetry row) in its natural order: nested dissection of that block
        jj, ii = np.divmod(free, nx)
        self.dissected = False
        if free.size:
            j0, i0 = int(jj.min()), int(ii.min())
            nj, ni = int(jj.max()) + 1 - j0, int(ii.max()) + 1 - i0
            block = (np.arange(j0, j0 + nj)[:, None] * nx + np.arange(i0, i0 + ni)).ravel()
            self.dissected = bool(np.array_equal(block, free))
        if self.dissected:
            self.perm = nested_dissection(ni, nj)
        else:  # not a rectangular block: SuperLU orders it (MMD on A^T + A)
            self.perm = np.arange(free.size)
        self.inverse = np.empty_like(self.perm)
        self.inverse[self.perm] = np.arange(self.perm.size)
        # the free-free block of the pattern, rows and columns in that order, as csc
        # (columns ascending, rows ascending within each): a matrix whose values are the
        # pattern positions (+ 1, so that none is an explicit zero), sliced by scipy
        asm = grid.assembler
        n = grid.size
        where = sp.csr_matrix((np.arange(1, asm.nnz + 1, dtype=float), asm.indices,
                               asm.indptr), shape=(n, n))
        chosen = free[self.perm]
        sub = where[chosen][:, chosen].tocsc()
        sub.sort_indices()
        idx = np.int32 if asm.nnz < 2**31 - 1 else np.int64
        self._select = (sub.data.astype(np.int64) - 1).astype(idx)
        self._row = sub.indices.astype(idx)
        self.indices = sub.indices.astype(np.int32)
        self.indptr = sub.indptr.astype(np.int32)
        col = np.repeat(np.arange(free.size), np.diff(self.indptr))
        diag_entries = np.nonzero(self._row == col)[0]
        if diag_entries.size != free.size:
            raise ValueError("assembler pattern lacks a diagonal entry at a free node")
        self._diag = diag_entries[np.argsort(self._row[diag_entries])]
        self.size = free.size

    def factor(self, m: np.ndarray, scale: np.ndarray, diag: np.ndarray, *,
               single: bool = False, drop_tol: float = 0.0) -> spla.SuperLU:
        """splu of diag(scale) M[free, free] + diag(diag) in the permuted order.

        ``scale`` and ``diag`` are free-node vectors in the original (free) order.
        ``single``: factor in single precision (half the memory; solve float32 vectors).
        ``drop_tol`` > 0: incomplete factors (SuperLU's ILU, entries below ``drop_tol``
        times their column's norm dropped).
        """
        data = m[self._select] * np.asarray(scale)[self.perm][self._row]
        data[self._diag] += np.asarray(diag)[self.perm]
        require_finite_factor_data(data)
        if single:
            data = data.astype(np.float32)
        a = sp.csc_matrix((data, self.indices, self.indptr), shape=(self.size, self.size))
        order = "NATURAL" if self.dissected else "MMD_AT_PLUS_A"
        if drop_tol > 0.0:
            return spla.spilu(a, drop_tol=drop_tol, fill_factor=ILU_FILL_FACTOR,
                              permc_spec=order, diag_pivot_thresh=LU_PIVOT_THRESHOLD,
                              options={"SymmetricMode": True})
        return spla.splu(a, permc_spec=order, diag_pivot_thresh=LU_PIVOT_THRESHOLD,
                         options={"SymmetricMode": True})



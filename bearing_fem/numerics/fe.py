"""Finite-element operators built once from a scikit-fem basis.

For a Lagrange basis {phi_i} and the basis' quadrature points q (weights dx_q), this
module precomputes the sparse maps

* ``value``:  nodal vector -> values at quadrature points  (u_q = sum_i u_i phi_i(x_q)),
* ``grad[d]``: nodal vector -> d-th derivative at quadrature points,

so that every weak form the Reynolds solver needs is a sparse product:

* residual of the flux form  R_i = int F . grad(phi_i)   ->  sum_d grad[d].T @ (w * F_d),
* Jacobian term int (a phi_j + b . grad phi_j) grad_d phi_i  ->  grad[d].T diag(w a) value + ...

This keeps all element geometry and quadrature in scikit-fem while each Newton step
costs a few sparse products, with no Python loop over elements.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from skfem import CellBasis


def pattern_values(mat: sp.spmatrix, indptr: np.ndarray, indices: np.ndarray,
                   keys: np.ndarray) -> np.ndarray | None:
    """Values of the square matrix ``mat`` at the positions of a fixed CSR pattern
    (``indptr``, ``indices``; ``keys`` = row * n + column of each entry, ascending), zeros
    where ``mat`` has none, or None if ``mat`` has an entry outside the pattern or another
    shape. Shared by the fixed-pattern assemblers (:class:`ElementAssembler` and the
    tensor-grid assembler of point contacts)."""
    n_dofs = indptr.size - 1
    nnz = indices.size
    mat = sp.csr_matrix(mat)
    if mat.shape != (n_dofs, n_dofs):
        return None
    if mat.indptr.size == indptr.size and mat.nnz == nnz and np.array_equal(
            mat.indptr, indptr) and np.array_equal(mat.indices, indices):
        return np.asarray(mat.data, dtype=float)
    mat = mat.copy()
    mat.sum_duplicates()
    rows = np.repeat(np.arange(n_dofs, dtype=np.int64), np.diff(mat.indptr))
    key = rows * n_dofs + mat.indices
    pos = np.searchsorted(keys, key)
    pos = np.minimum(pos, nnz - 1)
    if not np.all(keys[pos] == key):
        return None
    out = np.zeros(nnz)
    out[pos] = mat.data
    return out


@dataclass(frozen=True)
class QuadratureOperators:
    """Sparse interpolation/derivative maps of a scikit-fem basis (see module docstring).

    Attributes
    ----------
    value : scipy.sparse.csr_matrix, shape (n_elements * n_quad, n_dofs)
    grad : tuple of csr_matrix, one per space dimension, same shape as ``value``
    weights : ndarray, shape (n_elements * n_quad,)
        Quadrature weights times the Jacobian determinant [m^dim].
    points : ndarray, shape (dim, n_elements * n_quad)
        Physical coordinates of the quadrature points [m].
    element_size : ndarray, shape (n_elements * n_quad,)
        Element size along x at each quadrature point [m] (for stabilisation).
    n_quad : int
        Quadrature points per element.
    """

    value: sp.csr_matrix
    grad: tuple[sp.csr_matrix, ...]
    weights: np.ndarray
    points: np.ndarray
    element_size: np.ndarray
    n_quad: int

    @property
    def mass(self) -> np.ndarray:
        """Integrals of the basis functions int phi_i [m^dim] (the load row)."""
        return np.asarray(self.value.T @ self.weights).ravel()

    def integrate(self, f_q: np.ndarray) -> float:
        """Integral of a field given at the quadrature points."""
        return float(np.dot(self.weights, f_q))

    def weak_divergence(self, *flux: np.ndarray) -> np.ndarray:
        """Nodal vector int F . grad(phi_i) for a flux F given at the quadrature points."""
        out = self.grad[0].T @ (self.weights * flux[0])
        for g, f in zip(self.grad[1:], flux[1:]):
            out = out + g.T @ (self.weights * f)
        return out

    def flux_jacobian(self, d: int, coeff_value: np.ndarray,
                      coeff_grad: tuple[np.ndarray, ...]) -> sp.csr_matrix:
        """Matrix of int (a phi_j + sum_k b_k d_k phi_j) d_d phi_i for pointwise a, b_k."""
        gt = self.grad[d].T
        out = gt @ sp.diags(self.weights * coeff_value) @ self.value
        for k, b in enumerate(coeff_grad):
            out = out + gt @ sp.diags(self.weights * b) @ self.grad[k]
        return out.tocsr()

    @cached_property
    def assembler(self) -> "ElementAssembler":
        """Element-wise assembler of the same forms on a fixed sparsity pattern (cached)."""
        return ElementAssembler(self)


class ElementAssembler:
    """Assemble sums of :meth:`QuadratureOperators.flux_jacobian` terms element by element.

    ``flux_jacobian`` forms each term as a product of sparse matrices (and a new sparsity
    pattern) per call. Here the local matrices

        K_e[i, j] = sum_q w_q d_d phi_i(x_q) (a_q phi_j(x_q) + sum_k b_kq d_k phi_j(x_q))

    are computed for all elements at once (batched small products) and scattered into
    one fixed CSR pattern (all node pairs sharing an element) by a precomputed position
    map, so the matrices of successive Newton iterations share ``indptr``/``indices``.
    Same values as ``flux_jacobian`` up to the order of summation (rounding).

    The element-local basis values are views of the ``value``/``grad`` data: it needs
    every row of those maps (one quadrature point) to store the same number of entries,
    the element's nodes in the same (sorted) order, which ``quadrature_operators`` gives.

    Parameters
    ----------
    ops : QuadratureOperators
    """

    def __init__(self, ops: QuadratureOperators) -> None:
        nrow, ndof = ops.value.shape
        nq = ops.n_quad
        nel = nrow // nq
        nl = ops.value.nnz // nrow
        ok = nl * nrow == ops.value.nnz and np.array_equal(
            ops.value.indptr, np.arange(nrow + 1) * nl)
        for g in ops.grad:
            ok = ok and np.array_equal(g.indptr, ops.value.indptr) and np.array_equal(
                g.indices, ops.value.indices)
        if not ok:
            raise ValueError("ElementAssembler needs the same node set per quadrature row in "
                             "value and grad (as built by quadrature_operators)")
        cols = ops.value.indices.reshape(nel, nq, nl)
        if not np.all(cols == cols[:, :1, :]):
            raise ValueError("ElementAssembler: quadrature points of one element must share "
                             "the element's nodes")
        self.n_dofs = ndof
        self.shape = (nel, nq, nl)
        self._value = ops.value.data.reshape(nel, nq, nl)
        self._grad = tuple(g.data.reshape(nel, nq, nl) for g in ops.grad)
        self._weights = ops.weights.reshape(nel, nq)
        dofs = cols[:, 0, :]                                         # (nel, nl)
        self._dofs = dofs
        rows = np.repeat(dofs[:, :, None], nl, axis=2).ravel()      # K_e[i, j] -> (dof_i, dof_j)
        colj = np.repeat(dofs[:, None, :], nl, axis=1).ravel()
        key = rows.astype(np.int64) * ndof + colj
        uniq, pos = np.unique(key, return_inverse=True)
        idx_dtype = np.int32 if uniq.size < 2**31 - 1 and ndof < 2**31 - 1 else np.int64
        self.indices = (uniq % ndof).astype(idx_dtype)
        self.indptr = np.searchsorted(uniq, np.arange(ndof + 1, dtype=np.int64) * ndof
                                      ).astype(idx_dtype)
        self.nnz = uniq.size
        self._pos = pos.astype(idx_dtype).reshape(nel, nl, nl)
        self._keys = uniq

    def matrix(self, data: np.ndarray) -> sp.csr_matrix:
        """csr matrix on the assembler's pattern with the given ``data`` (not copied)."""
        return sp.csr_matrix((data, self.indices, self.indptr), shape=(self.n_dofs,) * 2)

    def flux_jacobian_sum(self, terms) -> sp.csr_matrix:
        """Sum over ``terms`` of ``flux_jacobian(d, a, (b_0, b_1, ...))``, on the fixed pattern.

        Parameters
        ----------
        terms : iterable of (d, a, b) or (d, a, b, s)
            d : int, derivative direction of the test function; a : ndarray
            (n_elements * n_quad,); b : tuple of such arrays (one per dimension), the
            coefficients of the trial function value and gradient (units of the form);
            s : optional nodal array (n_dofs,) scaling the trial functions, i.e. the
            columns of the term (``flux_jacobian(d, a, b) @ diag(s)``).

        Returns
        -------
        scipy.sparse.csr_matrix, shape (n_dofs, n_dofs)
        """
        nel, nq, nl = self.shape
        local = np.zeros((nel, nl, nl))
        for term in terms:
            d, a, b = term[:3]
            scale = term[3] if len(term) > 3 else None
            t = None
            for phi, c in zip((self._value,) + self._grad, (a,) + tuple(b)):
                if not np.any(c):  # structurally zero coefficient (common): skip
                    continue
                part = phi * np.reshape(c, (nel, nq, 1))
                t = part if t is None else t + part
            if t is None:
                continue
            t *= self._weights[:, :, None]
            if scale is not None:
                t *= np.asarray(scale)[self._dofs][:, None, :]
            local += np.matmul(self._grad[d].transpose(0, 2, 1), t)
        data = np.bincount(self._pos.ravel(), weights=local.ravel(), minlength=self.nnz)
        return self.matrix(data)

    def pattern_data(self, mat: sp.spmatrix) -> np.ndarray | None:
        """Values of ``mat`` at the pattern positions (zeros elsewhere), or None if ``mat``
        has an entry outside the pattern."""
        return pattern_values(mat, self.indptr, self.indices, self._keys)


def quadrature_operators(basis: CellBasis) -> QuadratureOperators:
    """Build :class:`QuadratureOperators` from a scikit-fem ``CellBasis``."""
    nel = basis.mesh.nelements
    dofs = basis.element_dofs  # (n_local, nel)
    nq = basis.dx.shape[1]
    nl = dofs.shape[0]
    dim = basis.mesh.dim()
    vals, grads = [], [[] for _ in range(dim)]
    for k in range(nl):
        phi = basis.basis[k][0]
        vals.append(np.asarray(phi).reshape(nel, nq))  # DiscreteField is array-like
        for d in range(dim):
            grads[d].append(np.asarray(phi.grad[d]).reshape(nel, nq))
    shape = (nel * nq, basis.N)
    # CSR built directly: row (e, q) holds the element's nl nodes in increasing order
    # (what a COO -> CSR conversion with sorted indices gives; no duplicates to sum)
    order = np.argsort(dofs, axis=0, kind="stable").T                      # (nel, nl)
    idx = np.int32 if max(basis.N, nel * nq * nl) < 2**31 - 1 else np.int64
    indices = np.repeat(np.take_along_axis(dofs.T, order, axis=1)[:, None, :], nq,
                        axis=1).ravel().astype(idx)
    indptr = (np.arange(nel * nq + 1, dtype=np.int64) * nl).astype(idx)

    def build(data: list[np.ndarray]) -> sp.csr_matrix:
        values = np.take_along_axis(np.stack(data, axis=-1), order[:, None, :], axis=2)
        return sp.csr_matrix((values.ravel(), indices, indptr), shape=shape)

    points = np.asarray(basis.mapping.F(basis.X)).reshape(dim, -1)
    # element extent along x (the streamline direction of the Reynolds equation)
    px = basis.mesh.p[0][basis.mesh.t]
    size = np.repeat(px.max(axis=0) - px.min(axis=0), nq)
    return QuadratureOperators(value=build(vals), grad=tuple(build(g) for g in grads),
                               weights=np.asarray(basis.dx).ravel(), points=points,
                               element_size=size, n_quad=nq)

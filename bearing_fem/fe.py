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

import numpy as np
import scipy.sparse as sp
from skfem import CellBasis


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


def quadrature_operators(basis: CellBasis) -> QuadratureOperators:
    """Build :class:`QuadratureOperators` from a scikit-fem ``CellBasis``."""
    nel = basis.mesh.nelements
    dofs = basis.element_dofs  # (n_local, nel)
    nq = basis.dx.shape[1]
    rows = np.arange(nel * nq).reshape(nel, nq)
    dim = basis.mesh.dim()
    vals, grads = [], [[] for _ in range(dim)]
    rr, cc = [], []
    for k in range(dofs.shape[0]):
        phi = basis.basis[k][0]
        rr.append(rows.ravel())
        cc.append(np.repeat(dofs[k], nq))
        vals.append(np.asarray(phi).ravel())  # DiscreteField is array-like (its values)
        for d in range(dim):
            grads[d].append(np.asarray(phi.grad[d]).ravel())
    rr = np.concatenate(rr)
    cc = np.concatenate(cc)
    shape = (nel * nq, basis.N)

    def build(data: list[np.ndarray]) -> sp.csr_matrix:
        return sp.csr_matrix((np.concatenate(data), (rr, cc)), shape=shape)

    points = np.asarray(basis.mapping.F(basis.X)).reshape(dim, -1)
    # element extent along x (the streamline direction of the Reynolds equation)
    px = basis.mesh.p[0][basis.mesh.t]
    size = np.repeat(px.max(axis=0) - px.min(axis=0), nq)
    return QuadratureOperators(value=build(vals), grad=tuple(build(g) for g in grads),
                               weights=np.asarray(basis.dx).ravel(), points=points,
                               element_size=size, n_quad=nq)

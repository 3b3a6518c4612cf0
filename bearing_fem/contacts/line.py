"""Line contact: 1D finite elements (scikit-fem, P1) for the Reynolds-elasticity system.

Unknowns: nodal pressures p_i at the free nodes (the two end nodes carry Dirichlet
data, 0 by default) and, under load balance, the rigid offset h0.

Equations (all scaled to O(1)):

* Reynolds rows: the weak flux-form residual R_i = int F dphi_i/dx (see
  :mod:`bearing_fem.physics.reynolds`), scaled to a pressure as r_i = R_i dx / (2 eps0_i p_ref)
  with eps0_i the isoviscous flow coefficient at node i. With ``cavitation = "none"``
  the row is r_i = 0; with ``"reynolds"`` it is the Fischer-Burmeister function
  phi(p_i/p_ref, r_i) = a + b - sqrt(a^2 + b^2) of the complementarity problem
  p >= 0, R >= 0, p R = 0 (semismooth Newton).
* Load row: (int p dx - w) / w = 0, partner of h0.

Film: h(x) = h0 + x^2/(2R) + v(x), the geometry evaluated exactly at the quadrature
points and the elastic displacement v = C p interpolated from the nodes.

Jacobian: dR/dp = A_p + A_h C and dR/dh0 = A_h 1, with A_p, A_h the sparse
derivative matrices of the flux form (exact, complex-step pointwise derivatives) and C
the compliance (dense Toeplitz for the half-space, diagonal for Kodnir's local model).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from skfem import CellBasis, ElementLineP1, MeshLine

from ..numerics.fe import QuadratureOperators, quadrature_operators
from ..numerics.newton import gmres_right
from ..physics.reynolds import FluxModel


@dataclass
class LineDiscretisation:
    """Mesh, basis and precomputed operators of a uniform 1D grid."""

    x: np.ndarray            # node coordinates [m]
    mesh: MeshLine
    basis: CellBasis
    ops: QuadratureOperators

    @classmethod
    def uniform(cls, x_min: float, x_max: float, nodes: int, intorder: int = 4) -> "LineDiscretisation":
        x = np.linspace(x_min, x_max, nodes)
        mesh = MeshLine(x)
        basis = CellBasis(mesh, ElementLineP1(), intorder=intorder)
        return cls(x=x, mesh=mesh, basis=basis, ops=quadrature_operators(basis))

    @property
    def spacing(self) -> float:
        return float(self.x[1] - self.x[0])


#: Smoothing of the Fischer-Burmeister function (scaled units). A degenerate node with
#: p = R = 0 (the discrete free boundary) makes the plain FB Jacobian singular and lets
#: the semismooth Newton cycle between two active sets; with mu > 0 the function is
#: smooth and its root satisfies p >= 0, R >= 0, p R = mu^2 / 2, i.e. complementarity
#: to 5e-21 in scaled units (p/p_ref times the scaled residual).
FB_SMOOTHING = 1e-10

#: Dense (half-space) Newton steps: GMRES preconditioned by the last LU factors is
#: accepted when it reaches this relative residual within this many iterations; else the
#: Jacobian is factorised afresh. Near convergence the Jacobian changes little and GMRES
#: needs a few iterations of O(n^2) each instead of an O(n^3) factorisation.
REUSE_GMRES_RTOL = 1e-10
REUSE_GMRES_ITERATIONS = 12


def fischer_burmeister(a: np.ndarray, b: np.ndarray,
                       mu: float = FB_SMOOTHING) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Smoothed FB function phi = a + b - sqrt(a^2 + b^2 + 2 mu^2) and its derivatives."""
    r = np.sqrt(a * a + b * b + 2.0 * mu * mu)
    phi = a + b - r
    zero = r < 1e-300
    rs = np.where(zero, 1.0, r)
    da = np.where(zero, 1.0 - 1.0 / np.sqrt(2.0), 1.0 - a / rs)
    db = np.where(zero, 1.0 - 1.0 / np.sqrt(2.0), 1.0 - b / rs)
    return phi, da, db


class ScaledResidual:
    """Parts shared by the line and point problems: the scaled residual (Reynolds rows, or
    their Fischer-Burmeister functions, at the free nodes, then the load row) and the
    admissibility test (finite unknowns, positive film at every quadrature point), and
    the reduced-pressure gradient of the Poiseuille term. Needs ``unpack``, ``fields_q``,
    ``reynolds_residual``, ``free``, ``_row_scale``, ``cavitation``, ``p_ref``,
    ``has_h0``, ``mass``, ``load``, ``flux`` and ``ops`` (the quadrature operators)."""

    @property
    def _reduced(self) -> bool:
        """True if the Poiseuille term is rho h^3/(12 eta0) grad q_h (reduced pressure)."""
        return getattr(self.flux, "reduced_alpha", None) is not None

    def _grad_reduced(self, p: np.ndarray) -> tuple[np.ndarray, ...]:
        """Gradient of the interpolant q_h of the nodal reduced pressure q(p) at the
        quadrature points [Pa/m], one array per dimension
        (:meth:`~bearing_fem.physics.reynolds.UpwindFluxModel.reduced`)."""
        q = self.flux.reduced(p)
        return tuple(g @ q for g in self.ops.grad)

    def admissible(self, z: np.ndarray) -> bool:
        if not np.all(np.isfinite(z)):
            return False
        p, h0 = self.unpack(z)
        _, h, _, _ = self.fields_q(p, h0)
        return bool(np.min(h) > 0.0)

    def nodal_residual(self, z: np.ndarray) -> tuple[np.ndarray, float, np.ndarray]:
        """p [Pa], h0 [m] and the unscaled nodal Reynolds residual of ``z``.

        The last evaluation is kept: Newton asks for the residual of the same iterate
        up to three times (line search, after the row scaling is updated, and in the
        step), and only the row scaling differs. A problem's data never change after
        construction, so the unknowns alone identify the evaluation.
        """
        cached = getattr(self, "_nodal_cache", None)
        if cached is not None and np.array_equal(cached[0], z):
            return cached[1], cached[2], cached[3]
        p, h0 = self.unpack(z)
        r = self.reynolds_residual(p, h0)
        self._nodal_cache = (np.array(z, dtype=float, copy=True), p, h0, r)
        return p, h0, r

    def residual(self, z: np.ndarray) -> np.ndarray:
        p, h0, r = self.nodal_residual(z)
        r = r[self.free] * self._row_scale
        if self.cavitation == "reynolds":
            r, _, _ = fischer_burmeister(p[self.free] / self.p_ref, r)
        if self.has_h0:
            r = np.append(r, (self.mass @ p - self.load) / self.load)
        return r


class LineProblem(ScaledResidual):
    """Scaled nonlinear system of one line-contact scene (implements NonlinearProblem).

    Parameters
    ----------
    disc : LineDiscretisation
    flux : FluxModel
    radius : float
        Reduced radius R [m].
    compliance : object with ``matrix()``/``apply()``/``is_zero``/``is_local``
        From :mod:`bearing_fem.physics.elasticity`.
    cavitation : {"reynolds", "none"}
    load : float or None
        Load per length w [N/m]; None means the offset is prescribed.
    gap : float or None
        Prescribed h0 [m] (when ``load`` is None).
    p_ref, h_ref : float
        Pressure [Pa] and film [m] scales of the unknowns.
    boundary_pressure : (float, float)
        Dirichlet pressures at the two end nodes [Pa].
    viscosity0 : float
        eta0 [Pa s], for the row scaling.
    """

    def __init__(self, disc: LineDiscretisation, flux: FluxModel, radius: float, compliance,
                 cavitation: str, load: float | None, gap: float | None, p_ref: float,
                 h_ref: float, viscosity0: float,
                 boundary_pressure: tuple[float, float] = (0.0, 0.0)) -> None:
        self.disc, self.flux, self.radius = disc, flux, radius
        self.ops = disc.ops
        self.compliance = compliance
        self.cavitation = cavitation
        self.load, self.gap = load, gap
        self.p_ref, self.h_ref = p_ref, h_ref
        self.eta0 = viscosity0
        x = disc.x
        n = x.size
        self.free = np.arange(1, n - 1)
        self.p_bc = np.zeros(n)
        self.p_bc[0], self.p_bc[-1] = boundary_pressure
        ops = disc.ops
        xq = ops.points[0]
        self.g_q = xq**2 / (2 * radius)
        self.gx_q = xq / radius
        self.g_nodes = x**2 / (2 * radius)
        self.mass = ops.mass
        self.has_h0 = load is not None
        self.n_unknowns = self.free.size + (1 if self.has_h0 else 0)
        if compliance.is_zero:
            self._cmat = None
        elif compliance.is_local:
            self._cmat = sp.diags(compliance.diagonal(n))
        else:
            self._cmat = compliance.matrix(n)
        self._row_scale = None
        self._lu = None  # dense LU factors kept for reuse as a preconditioner
        self.factorisations = 0
        self.krylov_iterations = 0

    # -- unknown <-> fields --------------------------------------------------------------
    def unpack(self, z: np.ndarray) -> tuple[np.ndarray, float]:
        p = self.p_bc.copy()
        p[self.free] = z[: self.free.size] * self.p_ref
        h0 = z[-1] * self.h_ref if self.has_h0 else self.gap
        return p, h0

    def pack(self, p: np.ndarray, h0: float) -> np.ndarray:
        z = p[self.free] / self.p_ref
        return np.append(z, h0 / self.h_ref) if self.has_h0 else z

    def displacement(self, p: np.ndarray) -> np.ndarray:
        if self._cmat is None:
            return np.zeros_like(p)
        return self._cmat @ p

    def film_nodes(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Film at the nodes [m]."""
        return h0 + self.g_nodes + self.displacement(p)

    def fields_q(self, p: np.ndarray, h0: float):
        """p, h, dp/dx, dh/dx at the quadrature points."""
        ops = self.disc.ops
        v = self.displacement(p)
        h = h0 + self.g_q + ops.value @ v
        hx = self.gx_q + ops.grad[0] @ v
        return ops.value @ p, h, ops.grad[0] @ p, hx

    # -- NonlinearProblem ---------------------------------------------------------------------
    def prepare(self, z: np.ndarray) -> None:
        p, h0 = self.unpack(z)
        h = np.maximum(self.film_nodes(p, h0), 1e-3 * self.h_ref)
        eps0 = h**3 / (12.0 * self.eta0)
        self._row_scale = (self.disc.spacing / (2.0 * eps0 * self.p_ref))[self.free]

    def reynolds_residual(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Nodal weak residual R_i [m^2/s] (all nodes)."""
        pq, h, px, hx = self.fields_q(p, h0)
        dx = self.disc.ops.element_size
        if self._reduced:
            (fx,) = self.flux.flux(pq, h, (px,), (hx,), dx, gq=self._grad_reduced(p))
        else:
            (fx,) = self.flux.flux(pq, h, (px,), (hx,), dx)
        return self.disc.ops.weak_divergence(fx)

    def _blocks(self, z: np.ndarray):
        """Pieces of the scaled Jacobian at z.

        Returns
        -------
        a_p, a_h : csr_matrix
            dR/dp and dR/dh at fixed h and p (interior rows, all nodes as columns).
        scale : ndarray
            Row factor times p_ref of the pressure columns.
        da : ndarray or None
            Fischer-Burmeister diagonal (Reynolds cavitation).
        dr_dh0, load_row : ndarray or None
            The h0 column and the load row (load balance).
        """
        p, h0 = self.unpack(z)
        ops = self.disc.ops
        pq, h, px, hx = self.fields_q(p, h0)
        inner = slice(1, p.size - 1)  # the free (interior) nodes
        if self._reduced:
            (fx,), dp, dh, dgp, dgh, dgq = self.flux.flux_and_derivatives_reduced(
                pq, h, (px,), (hx,), ops.element_size, self._grad_reduced(p))
            # d(dq_h/dx)/dp_j = q'(p_j) dphi_j/dx: the dq/dx column term, column-scaled
            a_q = ops.flux_jacobian(0, np.zeros_like(pq), (dgq[0][0],)) \
                @ sp.diags(self.flux.fluidity(p))
        else:
            (fx,), dp, dh, dgp, dgh = self.flux.flux_and_derivatives(pq, h, (px,), (hx,),
                                                                   ops.element_size)
            a_q = None
        a_p = ops.flux_jacobian(0, dp[0], (dgp[0][0],))
        a_p = (a_p if a_q is None else a_p + a_q).tocsr()[inner]
        a_h = ops.flux_jacobian(0, dh[0], (dgh[0][0],)).tocsr()[inner]
        rows = self.free
        res = ops.weak_divergence(fx)[rows]
        s = self._row_scale
        da = None
        if self.cavitation == "reynolds":
            _, da, db = fischer_burmeister(p[rows] / self.p_ref, res * s)
            row_factor = db * s
        else:
            row_factor = s
        dr_dh0 = load_row = None
        if self.has_h0:
            dr_dh0 = (ops.grad[0].T @ (ops.weights * dh[0]))[rows] * row_factor * self.h_ref
            load_row = self.mass[rows] * self.p_ref / self.load
        return a_p, a_h, row_factor * self.p_ref, da, dr_dh0, load_row

    def jacobian(self, z: np.ndarray):
        """Scaled Jacobian dF/dz (dense ndarray for the half-space, sparse otherwise)."""
        return self._jacobian_from_blocks(*self._blocks(z))

    def _jacobian_from_blocks(self, a_p, a_h, scale, da, dr_dh0, load_row):
        inner = slice(1, a_p.shape[1] - 1)
        if self._cmat is None:
            j = a_p[:, inner]
        elif sp.issparse(self._cmat):
            j = (a_p + a_h @ self._cmat).tocsr()[:, inner]
        else:  # dense: A_h is tridiagonal, so A_h C costs 3 n^2
            j = np.asarray(a_h @ self._cmat[:, inner])
            a_pi = a_p[:, inner].tocoo()
            np.add.at(j, (a_pi.row, a_pi.col), a_pi.data)
        if sp.issparse(j):
            j = sp.diags(scale) @ j
            if da is not None:
                j = j + sp.diags(da)
        else:
            j *= scale[:, None]
            if da is not None:
                j[np.diag_indices_from(j)] += da
        if not self.has_h0:
            return j
        if sp.issparse(j):
            return sp.bmat([[j, dr_dh0[:, None]], [load_row[None, :], None]], format="csc")
        out = np.zeros((j.shape[0] + 1, j.shape[1] + 1))
        out[:-1, :-1] = j
        out[:-1, -1] = dr_dh0
        out[-1, :-1] = load_row
        return out

    def newton_step(self, z: np.ndarray, shift: float = 0.0) -> np.ndarray:
        """Solve (J + shift D) dz = -F, D = identity on the pressure unknowns.

        Sparse J (rigid, local): sparse LU. Dense J (half-space): GMRES on the exact
        Jacobian (matrix-vector products with the blocks), preconditioned by the dense LU
        factors of an earlier iterate's Jacobian, when it converges within
        ``REUSE_GMRES_ITERATIONS``; otherwise J is formed and factorised afresh and the
        factors are kept. Both give the Newton step to rounding or to a relative residual
        of ``REUSE_GMRES_RTOL``.
        """
        f = self.residual(z)
        npf = self.free.size
        blocks = self._blocks(z)
        if self._cmat is not None and not sp.issparse(self._cmat) and self._lu is not None:
            dz = self._reuse_step(blocks, f, shift)
            if dz is not None:
                return dz
        j = self._jacobian_from_blocks(*blocks)
        if sp.issparse(j):
            if shift:
                d = np.zeros(j.shape[0])
                d[:npf] = shift
                j = j + sp.diags(d)
            return spla.spsolve(j.tocsc(), -f)
        if shift:
            j[np.arange(npf), np.arange(npf)] += shift
        lu = sla.lu_factor(j, overwrite_a=True, check_finite=False)
        self._lu = lu
        self.factorisations += 1
        return sla.lu_solve(lu, -f, check_finite=False)

    def _reuse_step(self, blocks: tuple, f: np.ndarray, shift: float) -> np.ndarray | None:
        a_p, a_h, scale, da, dr_dh0, load_row = blocks
        n = self.disc.x.size
        npf = self.free.size
        diag = (da if da is not None else 0.0) + shift
        cmat = self._cmat
        lu = self._lu

        def matvec(u: np.ndarray) -> np.ndarray:
            full = np.zeros(n)
            full[1:-1] = u[:npf]
            out = scale * (a_p @ full + a_h @ (cmat @ full)) + diag * u[:npf]
            if self.has_h0:
                out = out + dr_dh0 * u[npf]
                return np.append(out, load_row @ u[:npf])
            return out

        def precond(r: np.ndarray) -> np.ndarray:
            return sla.lu_solve(lu, r, check_finite=False)

        dz, its, rel = gmres_right(matvec, precond, -f, rtol=REUSE_GMRES_RTOL,
                                   max_iterations=REUSE_GMRES_ITERATIONS)
        self.krylov_iterations += its
        if rel > REUSE_GMRES_RTOL or not np.all(np.isfinite(dz)):
            return None
        return dz

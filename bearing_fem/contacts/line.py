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

import math
import time
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from skfem import CellBasis, ElementLineP1, MeshLine

from .. import units
from ..errors import SceneError
from ..formulas import line_central_film_moes
from ..mesh import every_other, outlet_graded_nodes
from ..numerics.fe import QuadratureOperators, quadrature_operators
from ..numerics.newton import BUDGET_STATUSES, ForcingTerm, gmres_right
from ..physics.elasticity import (UNIFORMITY_TOLERANCE, GradedHalfSpaceLine, HalfSpaceLine,
                                  LocalCompliance, RigidCompliance, kodnir_local_coefficient,
                                  line_displacement_at, spacing_deviation)
from ..physics.reynolds import FluxModel, UpwindFluxModel
from ..post import (FilmDissipation, film_numbers, friction_and_heat,
                    full_film_indicator_line, outlet_position_line, reported_viscosity)
from ..result import Result
from ..scene import Scene
from .driver import (DriverSettings, Progress, Solution, overload_result,
                     solve_linear_model, solve_newton_model)
from .linear import (active_set_solve, is_linear_scene, is_rigid_barus_load,
                     pressure_from_reduced, reduced_law)
from .problem import ScaledResidual, fischer_burmeister, row_smoothing


@dataclass
class LineDiscretisation:
    """Mesh, basis and precomputed operators of a 1D grid (uniform, or graded from a grid
    file)."""

    x: np.ndarray            # node coordinates [m]
    mesh: MeshLine
    basis: CellBasis
    ops: QuadratureOperators

    @classmethod
    def uniform(cls, x_min: float, x_max: float, nodes: int, intorder: int = 4) -> "LineDiscretisation":
        return cls.from_nodes(np.linspace(x_min, x_max, nodes), intorder)

    @classmethod
    def from_nodes(cls, x: np.ndarray, intorder: int = 4) -> "LineDiscretisation":
        """The P1 discretisation on the increasing node coordinates x [m]."""
        x = np.asarray(x, dtype=float)
        mesh = MeshLine(x)
        basis = CellBasis(mesh, ElementLineP1(), intorder=intorder)
        return cls(x=x, mesh=mesh, basis=basis, ops=quadrature_operators(basis))

    @property
    def spacing(self) -> float:
        """Node spacing [m]: the first one (uniform grids), the smallest on a graded grid."""
        return float(np.min(np.diff(self.x))) if not self.is_uniform else \
            float(self.x[1] - self.x[0])

    @cached_property
    def is_uniform(self) -> bool:
        """True if every spacing equals the mean to UNIFORMITY_TOLERANCE."""
        return spacing_deviation(self.x) <= UNIFORMITY_TOLERANCE

    @cached_property
    def node_spacing(self) -> np.ndarray | float:
        """Spacing at each node [m]: the grid spacing (uniform), else half the distance
        between the neighbours (one-sided at the ends)."""
        return self.spacing if self.is_uniform else np.gradient(self.x)


#: Dense (half-space) Newton steps: GMRES preconditioned by the last LU factors is
#: accepted when it reaches this relative residual within this many iterations; else the
#: Jacobian is factorised afresh. Near convergence the Jacobian changes little and GMRES
#: needs a few iterations of O(n^2) each instead of an O(n^3) factorisation.
REUSE_GMRES_RTOL = 1e-10
REUSE_GMRES_ITERATIONS = 12
REUSE_GMRES_FORCING = True
REUSE_GMRES_FORCING_MAX = 1e-2
DENSE_LU_SINGLE = True
#: Entries per row block of the dense Jacobian's product A_h C (a buffer that stays in
#: cache: at 1801 nodes 4 ms instead of 14 ms for n^2 temporaries).
DENSE_JACOBIAN_BLOCK_ENTRIES = 2**17


#: The film between the nodes (:meth:`LineProblem.film_near_minimum`): each element cut
#: into this many parts ...
FILM_MINIMUM_SAMPLES = 16
#: ... over this many elements on either side of the nodal minimum.
FILM_MINIMUM_ELEMENTS = 2


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
        self._fb_mu = None
        self._cmat_columns = {}  # dtype -> C[:, interior] in that dtype (dense C)
        self._lu = None  # dense LU factors kept for reuse as a preconditioner
        self._displacement_cache = None
        self._forcing = None  # ForcingTerm of the GMRES steps
        self._lu_transposed = False  # self._lu holds the factors of J^T
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
        """Nodal elastic displacement v = C p [m]. A dense compliance is applied by the
        half-space operator (FFT from ``LINE_FFT_APPLY_MIN`` nodes: at 2001 nodes ~40 us
        instead of ~0.9 ms for the dense product, equal to rounding), and the last product
        is kept (:meth:`~bearing_fem.contacts.problem.ScaledResidual.compliance_product`).
        The returned array is shared with the cache and must not be modified."""
        if self._cmat is None:
            return np.zeros_like(p)
        if sp.issparse(self._cmat):
            return self._cmat @ p
        return self.compliance_product(p)

    def film_nodes(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Film at the nodes [m]."""
        return h0 + self.g_nodes + self.displacement(p)

    @property
    def rigid(self) -> bool:
        """No deformation: the film is h0 + x^2/(2R)."""
        return getattr(self.compliance, "kind", "rigid") == "rigid"

    def film_central(self, p: np.ndarray, h0: float) -> float:
        """Film at x = 0 [m]: h0 itself for rigid bodies (the interpolant of the nodal
        parabola put a rigid cylinder's h_central up to 7 % above h0 on a grid without a
        node at x = 0); for deformable bodies the interpolant of the nodal film, which is
        flat in the Hertz zone (the default elastic grids have a node at x = 0)."""
        if self.rigid:
            return float(h0)
        return float(np.interp(0.0, self.disc.x, self.film_nodes(p, h0)))

    def film_near_minimum(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Film [m] between the nodes around the nodal minimum of a half-space line
        contact: at the points cutting each of the :data:`FILM_MINIMUM_ELEMENTS` elements
        on either side of it into :data:`FILM_MINIMUM_SAMPLES` parts; empty for rigid and
        local (Kodnir) compliances, whose film between the nodes is the interpolant's, and
        for a non-finite pressure or film.

        There the film is the interpolant of the nodal film plus what the interpolant
        leaves out: the bow of the geometry x^2/(2R) and of the deflection of the
        piecewise-linear pressure between the nodes
        (:func:`~bearing_fem.physics.elasticity.line_displacement_at`). The outlet
        constriction is a few elements wide, and the nodal minimum jumps with the grid as
        the constriction falls on or between the nodes (measured at M = 100, L = 5 on
        401 .. 6401 nodes: nodal minima 2.6975, 2.7374, 2.7337, 2.7368, 2.7377e-8 m), so
        that the error estimate could not read its changes.
        """
        comp = self.compliance
        x = self.disc.x
        if getattr(comp, "kind", None) != "half-space" or x.size < 3:
            return np.zeros(0)
        h = self.film_nodes(p, h0)
        if not (np.all(np.isfinite(p)) and np.all(np.isfinite(h))):
            return np.zeros(0)  # no film to refine (the nodal one says what it is)
        k = int(np.argmin(h))
        lo = max(k - FILM_MINIMUM_ELEMENTS, 0)
        hi = min(k + FILM_MINIMUM_ELEMENTS, x.size - 1)
        t = np.linspace(0.0, 1.0, FILM_MINIMUM_SAMPLES + 1)[1:-1]
        e = np.repeat(np.arange(lo, hi), t.size)  # the element of each point
        w = np.tile(t, hi - lo)  # its position in the element
        pts = x[e] + w * (x[e + 1] - x[e])
        near = x[lo:hi + 1]
        v = line_displacement_at(x, p, comp.e_prime, np.concatenate((pts, near)))
        v_pts, v_near = v[:pts.size], v[pts.size:]
        g_pts, g_near = pts**2 / (2.0 * self.radius), near**2 / (2.0 * self.radius)

        def interpolated(nodal: np.ndarray) -> np.ndarray:
            return (1.0 - w) * nodal[e - lo] + w * nodal[e - lo + 1]

        return (interpolated(h[lo:hi + 1]) + (g_pts - interpolated(g_near))
                + (v_pts - interpolated(v_near)))

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
        self._row_scale = (self.disc.node_spacing / (2.0 * eps0 * self.p_ref))[self.free]
        self._fb_mu = row_smoothing(self._row_scale)

    def reynolds_residual(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Nodal weak residual R_i [m^2/s] (all nodes)."""
        pq, h, px, hx = self.fields_q(p, h0)
        dx = self.disc.ops.element_size
        if self.uses_reduced:
            (fx,) = self.flux.flux(pq, h, (px,), (hx,), dx, gq=self.grad_reduced(p))
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
        if self.uses_reduced:
            (fx,), dp, dh, dgp, dgh, dgq = self.flux.flux_and_derivatives_reduced(
                pq, h, (px,), (hx,), ops.element_size, self.grad_reduced(p))
            # d(dq_h/dx)/dp_j = q'(p_j) dphi_j/dx: the dq/dx column term, column-scaled
            extra = [(0, np.zeros_like(pq), (dgq[0][0],), self.flux.fluidity(p))]
        else:
            (fx,), dp, dh, dgp, dgh = self.flux.flux_and_derivatives(pq, h, (px,), (hx,),
                                                                   ops.element_size)
            extra = []
        asm = ops.assembler  # element-wise assembly on one fixed pattern
        a_p = asm.flux_jacobian_sum([(0, dp[0], (dgp[0][0],))] + extra)[inner]
        a_h = asm.flux_jacobian_sum([(0, dh[0], (dgh[0][0],))])[inner]
        rows = self.free
        res = ops.weak_divergence(fx)[rows]
        s = self._row_scale
        da = None
        if self.cavitation == "reynolds":
            _, da, db = fischer_burmeister(p[rows] / self.p_ref, res * s, self._fb_mu)
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
        dense = self._cmat is not None and not sp.issparse(self._cmat)
        if dense and DENSE_LU_SINGLE:
            # single-precision factors as the preconditioner of a GMRES step on the exact
            # Jacobian (half the factorisation time); double if that does not converge
            j = self._dense_jacobian(blocks, shift, np.float32)
            if j is not None:
                # factor J^T (J's C-order memory is J^T in Fortran order: no copy) and
                # solve with the transpose
                self._lu = sla.lu_factor(j.T, overwrite_a=True, check_finite=False)
                self._lu_transposed = True
                self.factorisations += 1
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
        self._lu_transposed = False
        self.factorisations += 1
        return sla.lu_solve(lu, -f, check_finite=False)

    def _dense_jacobian(self, blocks: tuple, shift: float, dtype) -> np.ndarray | None:
        """The scaled, shifted, bordered dense Jacobian in ``dtype``, C order (so that its
        transpose is the Fortran-ordered array LAPACK factors in place), from the
        tridiagonal A_p, A_h and the dense C: row r of A_h C combines rows r, r + 1, r + 2
        of C (the interior node r + 1 and its neighbours), written row-wise in ``dtype``.
        None if A_h is not tridiagonal."""
        a_p, a_h, scale, da, dr_dh0, load_row = blocks
        npf = self.free.size
        rows = np.repeat(np.arange(npf), np.diff(a_h.indptr))
        if np.any((a_h.indices < rows) | (a_h.indices > rows + 2)):
            return None
        c = self._interior_columns(dtype)
        m = npf + (1 if self.has_h0 else 0)
        out = np.empty((m, m), dtype=dtype)
        j = out[:npf, :npf]
        bands = [(a_h.diagonal(k) * scale).astype(dtype)[:, None] for k in range(3)]
        # by blocks of rows, the product of each band in a small buffer (no n^2 temporary)
        block = max(1, DENSE_JACOBIAN_BLOCK_ENTRIES // max(npf, 1))
        buf = np.empty((min(block, npf), npf), dtype=dtype)
        for r0 in range(0, npf, block):
            r1 = min(npf, r0 + block)
            rows_j, tmp = j[r0:r1], buf[:r1 - r0]
            np.multiply(c[r0:r1], bands[0][r0:r1], out=rows_j)
            for k in (1, 2):  # (scale A_h)[r, r + k] * C[r + k, interior]
                np.multiply(c[r0 + k:r1 + k], bands[k][r0:r1], out=tmp)
                rows_j += tmp
        ap = sp.coo_matrix(a_p)
        keep = (ap.col >= 1) & (ap.col <= npf)
        np.add.at(j, (ap.row[keep], ap.col[keep] - 1),
                  (scale[ap.row[keep]] * ap.data[keep]).astype(dtype))
        diag = (da if da is not None else 0.0) + shift
        j[np.arange(npf), np.arange(npf)] += np.broadcast_to(diag, (npf,)).astype(dtype)
        if self.has_h0:
            out[:npf, -1] = dr_dh0
            out[-1, :npf] = load_row
            out[-1, -1] = 0.0
        return out

    def _interior_columns(self, dtype) -> np.ndarray:
        """C[:, interior] of the dense compliance in ``dtype`` (C-contiguous; kept)."""
        key = np.dtype(dtype)
        if key not in self._cmat_columns:
            self._cmat_columns[key] = np.ascontiguousarray(self._cmat[:, 1:-1], dtype=key)
        return self._cmat_columns[key]

    def _reuse_step(self, blocks: tuple, f: np.ndarray, shift: float) -> np.ndarray | None:
        a_p, a_h, scale, da, dr_dh0, load_row = blocks
        n = self.disc.x.size
        npf = self.free.size
        diag = (da if da is not None else 0.0) + shift
        comp = self.compliance  # the product C x, by FFT on large grids
        lu = self._lu

        def matvec(u: np.ndarray) -> np.ndarray:
            full = np.zeros(n)
            full[1:-1] = u[:npf]
            out = scale * (a_p @ full + a_h @ comp.apply(full)) + diag * u[:npf]
            if self.has_h0:
                out = out + dr_dh0 * u[npf]
                return np.append(out, load_row @ u[:npf])
            return out

        trans = 1 if self._lu_transposed else 0

        def precond(r: np.ndarray) -> np.ndarray:
            return sla.lu_solve(lu, r.astype(lu[0].dtype), trans=trans,
                                check_finite=False).astype(float)

        rtol = REUSE_GMRES_RTOL
        if REUSE_GMRES_FORCING:  # inexact Newton: Eisenstat-Walker tolerance
            if self._forcing is None:
                self._forcing = ForcingTerm(REUSE_GMRES_FORCING_MAX)
            rtol = max(rtol, self._forcing(float(np.linalg.norm(f))))
        dz, its, rel = gmres_right(matvec, precond, -f, rtol=rtol,
                                   max_iterations=REUSE_GMRES_ITERATIONS)
        self.krylov_iterations += its
        if not math.isfinite(rel):
            # the factors or the product overflowed: a failed linear solve (Newton takes a
            # shifted step next), as singular factors are
            raise np.linalg.LinAlgError("gmres: the LU preconditioner or the Jacobian "
                                        "product gave non-finite values")
        if rel > rtol or not np.all(np.isfinite(dz)):
            return None
        return dz


# =======================================================================================
# The line-contact model: scales, default grid, levels, problems, post-processing
# =======================================================================================
#: h*/h0 of Martin's rigid isoviscous cylinder (sec^2 of the outlet angle, ~1.2255);
#: used only to estimate a starting offset for rigid loaded scenes, never as an oracle.
MARTIN_HSTAR_APPROX = 1.2255
#: Default grid density of elastic line contacts at Moes M = 100 [nodes per Hertz
#: half-width b]: 801 nodes on the default domain [-4.5, 1.5] b. The fastest setting
#: that reaches 1 % in h_central and h_min at M = 100, L = 10 is 801 uniform nodes
#: (``studies/work_precision.py``: h_min 0.72 %, h_central 0.05 %).
NODES_PER_HALF_WIDTH = 800.0 / 6.0
#: The default density grows as (M / 100)^DENSITY_MOES_EXPONENT: the outlet constriction
#: and spike narrow with load. At a fixed density the h_min error grows about as M^1.4
#: between M = 100 and 500, and falls about as the density^-1.9 (measured at 300 and
#: 424 nodes per b, L = 5 .. 20), so M^0.75 keeps it about constant: M = 500 gets
#: 446 per b (h_min 0.86 % at 424 per b, 1.6 to 1.9 % at 284 per b).
DENSITY_MOES_EXPONENT = 0.75
#: Kodnir's local compliance (``model.elasticity = "local"``) converges more slowly on
#: uniform grids than the half-space (measured against 12801 nodes at M = 100, L = 10:
#: h_central 1.8 % off on 801 nodes, 0.46 % on 1601, 0.21 % on 2401): its default density
#: is at least LOCAL_NODES_PER_HALF_WIDTH nodes per Hertz half-width, growing as
#: sqrt(M / DENSE_MESH_MOES_M) above that M (1801 nodes at M = 100).
LOCAL_NODES_PER_HALF_WIDTH = 300.0
#: Isoviscous (alpha = 0) half-space scenes take this multiple of the default density:
#: their outlet constriction is sharper than the piezo-viscous one at the same M
#: (``studies/line_graded_grid.py``: h_min 1.1, 1.5 and 1.9 % off at M = 100, 500 and
#: 1000 on the plain density, where piezo-viscous scenes stay within 0.8 %).
ISOVISCOUS_DENSITY_FACTOR = 1.5
#: Above this Moes load parameter M the grid sequence keeps at most MAX_COARSENINGS
#: coarser levels (their outlet spike must still be resolved).
DENSE_MESH_MOES_M = 250.0
#: Cap on default elastic line grids (dense compliance: memory and LU time grow as N^2, N^3).
MAX_DEFAULT_ELASTIC_NODES = 4001
#: Default domain of isoviscous elastic line scenes whose default grid reaches
#: MAX_DEFAULT_ELASTIC_NODES (Moes M above ~500): [-ISOVISCOUS_CAPPED_INLET,
#: ISOVISCOUS_CAPPED_OUTLET] Hertz half-widths (the inlet end at least 15 hydrodynamic
#: lengths sqrt(2 R h) beyond the Hertz edge) instead of [-4.5, 1.5], so that the capped
#: grid keeps the density the film needs. Without piezo-viscosity the inlet pressure
#: builds up within a few hydrodynamic lengths of the Hertz edge, which are a few
#: thousandths of b there. Measured (``studies/stability_atlas.py``), L = 0: on
#: [-4.5, 1.5] M = 4329 and 1e4 never converged (budget spent, or stalled, from 667 nodes
#: per half-width); on [-1.5, 1.2] both converge (M = 4329: 3373 nodes, 41 Newton
#: iterations; M = 1e4: 4001 nodes, 45), and M = 4329 gives h_central 2.4010e-10 m, against
#: 2.4031e-10 m on the same domain with 4001 nodes, 2.4010e-10 m on [-1.5, 1.5] (3749
#: nodes) and 2.4044e-10 m on [-1.2, 1.2] (4001 nodes): the inlet end does not set the
#: film. At M = 1874 (2217 instead of 4001 nodes) h_central agrees with
#: the wide domain's to 0.09 %. Piezo-viscous scenes keep [-4.5, 1.5]: at M = 1e4,
#: L = 3.57 the narrow domain stalled on its coarsest level where the wide one converges.
ISOVISCOUS_CAPPED_INLET = 1.5
ISOVISCOUS_CAPPED_OUTLET = 1.2
#: Outlet end of the default elastic line domain at light load, in hydrodynamic lengths
#: sqrt(2 R h) of the estimated central film: Martin's rigid outlet lies at
#: 0.475 sqrt(2 R h0) = 0.43 sqrt(2 R h*), so one length keeps the outlet inside the domain
#: where it lies beyond the 1.5 b of an EHL contact (Moes M below ~1; at 300 N/m on a
#: 10 mm steel roller the outlet at 1.5 b cut the pressure zone and h_central came out
#: 17 % thin).
OUTLET_HYDRO_LENGTHS = 1.0
#: Default rigid-scene grid: nodes per sqrt(2 R h0).
NODES_PER_RIGID_LENGTH = 40
#: Stabilisation of half-space line contacts: "upwind" (first-order upwinded wedge term,
#: :class:`~bearing_fem.physics.reynolds.UpwindFluxModel`) or "supg" (SUPG on the whole
#: strong residual). Kodnir's local model always uses SUPG.
#: ``studies/line_stabilisation.py`` compares the two.
HALF_SPACE_STABILISATION = "upwind"
#: Poiseuille term of half-space line contacts with Barus viscosity (as
#: :data:`bearing_fem.contacts.point.REDUCED_POISEUILLE`): rho h^3/(12 eta0) dq_h/dx, q_h
#: the P1 interpolant of the nodal reduced pressure q = (1 - exp(-alpha p))/alpha, instead
#: of eps(p) dp/dx at the quadrature points. Over an element it is the exact integral of
#: eps(p) dp/dx for linear p, monotone in the nodal pressures whatever the jump; the
#: 3-point quadrature of exp(-alpha p) is not once alpha dp >> 1. Measured at the outlet
#: spike of M = 5, L = 15 on 8001 nodes (p from 3.1 to 0.5 p_h across one element,
#: alpha dp = 35): the quadrature flux peaks at a spike-side pressure of 1.0 p_h and falls
#: by 4x up to 3.1 p_h, and Newton stalled at |F| = 5e-7 on that falling branch (exact
#: Jacobian, exact linear solves, plain Newton steps growing to 1e2-1e3 p_h as it
#: approached the fold); with the reduced term it converges in 5 iterations on 8001
#: nodes. Same grid limit, smaller grid error: h_central 3601 -> 7201 nodes changes
#: 0.27 % -> 0.029 % at M = 1000, L = 2 and 0.0047 % -> 0.0019 % at M = 100, L = 10
#: (docs/line_contact.md).
REDUCED_POISEUILLE_LINE = True
#: Grid sequencing: coarsest grid of the line Newton solve (nodes). Finer grids are
#: solved coarse-to-fine, halving the spacing each level, each level started from the
#: interpolated solution of the one below (measured at M = 100, L = 10, 2001 nodes:
#: 10 + 7 + 5 iterations on 501, 1001, 2001 nodes, against 34 iterations directly on
#: 2001 nodes; the upwinded wedge flux is what lets the fine levels converge). The
#: Newton iterations from the Hertzian guess are cheapest on the coarsest level: from 201
#: nodes (was 501) a 1801-node solve at M = 100, L = 10 takes 6 + 5 + 7 + 4
#: iterations on 226 .. 1801 nodes instead of 18 + 4 on 901 and 1801; over the line
#: map of ``studies/stability_atlas.py`` (384 solves) 12 % fewer Newton iterations and
#: 113 instead of 170 continuation steps, with the same films but in one under-resolved
#: Roelands case (docs/stability.md, "The line grid sequence from 201 nodes").
COARSEST_NODES = 201
#: Grid sequencing above Moes M = DENSE_MESH_MOES_M: at most this many halvings of the
#: spacing below the solve's grid. A coarse level must still resolve the outlet spike,
#: which narrows with load: the default
#: grid grows with M up to MAX_DEFAULT_ELASTIC_NODES, and below the cap the levels
#: stop at a quarter of it anyway (e.g. 670, 1339, 2677 at M = 500); capped at 4001
#: nodes (M > ~860), four levels went down to 501 nodes (83 per Hertz half-width), where
#: Newton and every continuation step stalled at M = 1874, L = 0 .. 3.6 and M = 4329 and
#: 1e4, L = 3.6 .. 10.7 (``studies/stability_atlas.py``); from 1001 nodes they converge in
#: 14-28 iterations. Below that M the full sequence from COARSEST_NODES stays (an explicit
#: 8001-node grid at M = 5, L = 15 converges from 501 nodes without continuation, but
#: needed continuation when started on 2001).
MAX_COARSENINGS = 2
#: Newton iterations allowed to the direct attempt and to each continuation step before
#: backing off (fail fast: a stalled attempt costs more than a smaller step).
ATTEMPT_ITERATIONS = 40
#: Isoviscous continuation starts at this multiple of the entrainment speed (Moes M
#: 10x lower), where the film is thick compared with the elastic deflection.
CONTINUATION_SPEED_FACTOR = 100.0
#: How the shared driver attacks line contacts: every attempt capped at
#: ATTEMPT_ITERATIONS; a monotone line search from an interpolated coarse solution
#: (close enough that a non-monotone search only wanders), non-monotone (window 5) from
#: the Hertzian guess; one BLAS thread (measured at 2001 nodes, M = 100, L = 10: 0.59 s
#: wall with the default two threads on an idle 2-core machine, 0.31-0.35 s CPU with one).
LINE_DRIVER = DriverSettings(direct_iterations=ATTEMPT_ITERATIONS,
                             transfer_iterations=ATTEMPT_ITERATIONS,
                             continuation_iterations=ATTEMPT_ITERATIONS,
                             start_memory=5, transfer_memory=1,
                             blas_threads=1)


@dataclass
class LineSetup:
    """Scales, grid and operators of a line scene on one grid (a driver level).

    Attributes
    ----------
    disc : LineDiscretisation
    compliance : Compliance
        From :mod:`bearing_fem.physics.elasticity`.
    p_ref, h_ref : float
        Pressure [Pa] and film [m] scales of the unknowns.
    x_unit : float
        Length unit of the mesh range [m] (Hertz half-width b, or sqrt(2 R h0)).
    h_estimate : float
        Estimated central film [m] (Moes for elastic scenes).
    stab_compliance : float
        Compliance of the stabilisation [m/Pa] (0 when rigid).
    """

    disc: LineDiscretisation
    compliance: object
    p_ref: float
    h_ref: float
    x_unit: float
    h_estimate: float
    stab_compliance: float

    @property
    def label(self) -> str:
        return f"{self.disc.x.size} nodes"


def kodnir_coefficient(scene) -> float:
    """A'/E of Kodnir's local compliance of a line scene [m/Pa]."""
    # Kodnir's 1.52 contains nu = 0.3 for two equal bodies: E = E' (1 - 0.3^2).
    e = scene.e_prime * (1.0 - 0.3**2)
    return kodnir_local_coefficient(scene.load.force, scene.contact.rx, e)


def _moes_m(scene: Scene) -> float:
    """Moes load parameter M [-] of a loaded line scene."""
    lub = scene.lubricant
    return units.moes_line(scene.load.force, scene.contact.rx, scene.e_prime, lub.viscosity,
                           scene.kinematics.mean_speed, lub.effective_piezo)["M"]


def _nested_count(intervals: float) -> int:
    """The node count with at least ``intervals`` intervals and N - 1 divisible by 4, so
    that the grid and its two coarser grids (every other node) nest."""
    return 4 * math.ceil(intervals / 4) + 1


def _elastic_density(scene: Scene) -> float:
    """Default grid density of a loaded elastic line scene [nodes per Hertz half-width]:
    :data:`NODES_PER_HALF_WIDTH` (M / 100)^:data:`DENSITY_MOES_EXPONENT`, M the Moes load
    parameter, times :data:`ISOVISCOUS_DENSITY_FACTOR` for isoviscous half-space scenes;
    with the local compliance at least :data:`LOCAL_NODES_PER_HALF_WIDTH`
    sqrt(max(1, M / :data:`DENSE_MESH_MOES_M`)) (the node count is then kept between 801
    and :data:`MAX_DEFAULT_ELASTIC_NODES`)."""
    moes_m = _moes_m(scene)
    density = NODES_PER_HALF_WIDTH * (moes_m / 100.0) ** DENSITY_MOES_EXPONENT
    if scene.lubricant.effective_piezo == 0.0 and scene.model.elasticity == "half-space":
        density *= ISOVISCOUS_DENSITY_FACTOR
    if scene.model.elasticity == "local":
        density = max(density, LOCAL_NODES_PER_HALF_WIDTH
                      * math.sqrt(max(1.0, moes_m / DENSE_MESH_MOES_M)))
    return density


def default_x_range(scene: Scene) -> tuple[float, float]:
    """The default domain of a loaded elastic line scene, the one :func:`line_setup` takes
    when ``scene.mesh`` gives no ``x_range``.

    Parameters
    ----------
    scene : Scene
        A line scene with ``load.force`` [N/m] and an elastic model.

    Returns
    -------
    (float, float)
        In Hertz half-widths b [-]: the fully flooded inlet, 4.5 b or 15 hydrodynamic
        lengths sqrt(2 R h) at low load, to the outlet at 1.5 b or, at low load,
        :data:`OUTLET_HYDRO_LENGTHS` hydrodynamic lengths; an isoviscous half-space
        scene whose default grid would exceed :data:`MAX_DEFAULT_ELASTIC_NODES` takes the
        shorter [-max(:data:`ISOVISCOUS_CAPPED_INLET`, 1 + 15 sqrt(2 R h)/b),
        :data:`ISOVISCOUS_CAPPED_OUTLET`].
    """
    R, w, lub = scene.contact.rx, scene.load.force, scene.lubricant
    b, _ = units.hertz_line(w, R, scene.e_prime)
    h_est = line_central_film_moes(w, R, scene.e_prime, lub.viscosity,
                                   scene.kinematics.mean_speed, lub.effective_piezo)
    # fully flooded inlet: 4.5 b, or 15 hydrodynamic lengths sqrt(2 R h) at low load;
    # the outlet at 1.5 b, or beyond the rigid (Martin) outlet at low load
    length = math.sqrt(2 * R * h_est) / b
    hydro = 15.0 * length
    x_range = (-max(4.5, hydro), max(1.5, OUTLET_HYDRO_LENGTHS * length))
    capped = (x_range[1] - x_range[0]) * _elastic_density(scene) > MAX_DEFAULT_ELASTIC_NODES - 1
    if capped and lub.effective_piezo == 0.0 and scene.model.elasticity == "half-space":
        x_range = (-max(ISOVISCOUS_CAPPED_INLET, 1.0 + hydro), ISOVISCOUS_CAPPED_OUTLET)
    return x_range


def line_setup(scene: Scene, nodes: int | None = None,
               x_nodes: np.ndarray | None = None) -> LineSetup:
    """Reference scales, default mesh and compliance operator of a line scene.

    Parameters
    ----------
    scene : Scene
        A line scene.
    nodes : int, optional
        Overrides the node count (grid sequencing) on the same interval.
    x_nodes : ndarray, optional
        Increasing nodes in units of the length unit (Hertz half-widths when elastic and
        loaded, else sqrt(2 R h0)) that replace the grid as a ``mesh.file`` would (every
        other node of it for coarser levels).

    Returns
    -------
    LineSetup
    """
    R = scene.contact.rx
    lub, kin, model = scene.lubricant, scene.kinematics, scene.model
    u_m = kin.mean_speed
    elastic = model.elasticity != "rigid"
    if scene.load.force is not None and elastic:
        w = scene.load.force
        b, p_h = units.hertz_line(w, R, scene.e_prime)
        h_est = line_central_film_moes(w, R, scene.e_prime, lub.viscosity, u_m,
                                       lub.effective_piezo)
        x_unit, p_ref, h_ref = b, p_h, h_est
        x_range = scene.mesh.x_range or default_x_range(scene)
        density = _elastic_density(scene)
    else:
        if scene.load.gap is not None:
            h0 = scene.load.gap
        else:  # rigid under load: Martin's isoviscous estimate of the offset
            h0 = 6 * lub.viscosity * u_m * R / (MARTIN_HSTAR_APPROX * scene.load.force)
        x_unit = math.sqrt(2 * R * h0)
        h_est, h_ref = h0, h0
        p_ref = lub.viscosity * u_m * x_unit / h0**2
        if model.cavitation == "none":
            x_range = scene.mesh.x_range or (-100.0, 100.0)
        else:
            x_range = scene.mesh.x_range or (-100.0, 5.0)
        density = NODES_PER_RIGID_LENGTH
    width = x_range[1] - x_range[0]
    cap = 20001 if model.elasticity == "rigid" else MAX_DEFAULT_ELASTIC_NODES
    axes = (np.asarray(x_nodes, dtype=float), None) if x_nodes is not None else scene.mesh.axes()
    if axes is not None:  # a grid file (or given nodes), in units of x_unit
        x_file = axes[0]
        repeated = np.flatnonzero(np.diff(x_file) <= 0.0)
        if repeated.size:
            raise SceneError(f"mesh.file {scene.mesh.file!r}: the nodes must be distinct; "
                             f"x = {float(x_file[repeated[0]])!r} (in the units of mesh.x_range) "
                             f"appears {int(np.sum(x_file == x_file[repeated[0]]))} times")
        xs = every_other(x_file, nodes or x_file.size) * x_unit
        disc = LineDiscretisation.from_nodes(xs)  # graded nodes allowed (any model)
    else:
        if nodes is None:
            # nested levels for the grid sequence and the error estimate (rounded to 1e-6
            # first: 6 b at 800/6 per b is 800 intervals, not 800 + 1e-13)
            auto = _nested_count(round(min(max(width * density, 800), cap - 1), 6))
            nodes = scene.mesh.nodes or auto
        disc = LineDiscretisation.uniform(x_range[0] * x_unit, x_range[1] * x_unit, nodes)
    if model.elasticity == "rigid":
        comp = RigidCompliance()
        c_stab = 0.0
    elif model.elasticity == "local":
        coef = kodnir_coefficient(scene)
        comp = LocalCompliance(coef)
        c_stab = coef
    else:
        comp, c_stab = _half_space(disc, scene.e_prime)
    return LineSetup(disc, comp, p_ref, h_ref, x_unit, h_est, c_stab)


def _half_space(disc: LineDiscretisation, e_prime: float):
    """The half-space compliance of a grid (Toeplitz on uniform nodes, dense cell
    integrals on graded ones) and the compliance c of the upwind Peclet fade-out [m/Pa].

    c is that of a pressure change over one element (~ its self-influence), of the
    smallest element on a graded grid: a contact-width compliance would over-stabilise
    and wash out the outlet constriction and spike (checked: h_min/h_c 0.99 instead of
    0.75 at M = 100, L = 10).
    """
    comp = (HalfSpaceLine(disc.x, e_prime, method="dense") if disc.is_uniform
            else GradedHalfSpaceLine(disc.x, e_prime))
    return comp, 4.0 * disc.spacing / (math.pi * e_prime)


def is_linear(scene) -> bool:
    """True if a scene is solved by linear solves of the reduced pressure
    (:func:`bearing_fem.contacts.linear.is_linear_scene`: rigid, incompressible,
    prescribed gap; constant or Barus viscosity, or Roelands with Reynolds cavitation)."""
    return is_linear_scene(scene)


def _limited_coarsening(scene: Scene) -> bool:
    """True for a loaded half-space scene above Moes M = DENSE_MESH_MOES_M, whose grid
    sequence keeps at most MAX_COARSENINGS coarser levels."""
    if scene.load.force is None or scene.model.elasticity != "half-space":
        return False
    return _moes_m(scene) > DENSE_MESH_MOES_M


def line_levels(nodes: int, coarsest: int = COARSEST_NODES,
                max_coarsenings: int | None = None) -> list[int]:
    """Grid sequence n_0 < n_1 < ... < nodes, halving the spacing each level.

    No level below ``coarsest`` nodes, and at most ``max_coarsenings`` halvings below
    ``nodes`` (None: no such limit).
    """
    if max_coarsenings is not None:
        coarsest = max(coarsest, (nodes - 1) // 2**max_coarsenings + 1)
    levels = [nodes]
    while (levels[-1] - 1) % 2 == 0 and (levels[-1] - 1) // 2 + 1 >= coarsest:
        levels.append((levels[-1] - 1) // 2 + 1)
    return levels[::-1]


def reduced_isoviscous_solve(problem: LineProblem, h0: float, q_bc: np.ndarray,
                             mean_speed: float, eta0: float, cavitation: str,
                             active: np.ndarray | None = None):
    """Solve the rigid isoviscous Reynolds problem for the reduced pressure q [Pa].

    One sparse solve for full-Sommerfeld; a primal-dual active-set sequence of sparse
    solves for Reynolds cavitation (q >= 0, A q - f >= 0, q (A q - f) = 0).

    Returns
    -------
    q : ndarray (nodal, Pa), linear_solves : int, active : bool ndarray (cavitated nodes)
    """
    ops = problem.disc.ops
    h = h0 + problem.g_q
    a = ops.flux_jacobian(0, np.zeros_like(h), (h**3 / (12.0 * eta0),)).tocsr()
    f = ops.weak_divergence(mean_speed * h)
    return active_set_solve(a, f, q_bc, problem.free, cavitation, active=active)


class LineModel:
    """A line-contact scene as a :class:`~bearing_fem.contacts.driver.ContactModel`.

    Parameters
    ----------
    scene : Scene
        ``contact.kind == "line"``.
    boundary_pressure : (float, float)
        Dirichlet pressures at the inlet and outlet ends [Pa].
    x_nodes : ndarray, optional
        The grid's nodes in units of the length unit (see :func:`line_setup`); None: the
        scene's own grid.
    """

    settings = LINE_DRIVER

    def __init__(self, scene: Scene, boundary_pressure: tuple[float, float] = (0.0, 0.0),
                 x_nodes: np.ndarray | None = None) -> None:
        self.scene = scene
        self.bp = tuple(float(v) for v in boundary_pressure)
        self.x_nodes = x_nodes
        #: (x [m], p [Pa], central film [m]) of a solution on another grid to start
        #: from instead of the Hertzian guess (the outlet-grading spike locator's)
        self.start: tuple[np.ndarray, np.ndarray, float] | None = None
        self.setup = line_setup(scene, x_nodes=x_nodes)
        piezo = scene.lubricant.effective_piezo > 0.0
        self.continuation_parameter = "alpha" if piezo else "speed"
        self._setups = {self.setup.disc.x.size: self.setup}

    # -- levels ----------------------------------------------------------------------------
    def level(self, nodes: int) -> LineSetup:
        """The scene on a grid of ``nodes`` nodes over the same interval (uniform, or every
        other node of a grid file; cached: the driver recognises a level by identity)."""
        if nodes not in self._setups:
            if self.scene.mesh.file is not None or self.x_nodes is not None:
                self._setups[nodes] = line_setup(self.scene, nodes, x_nodes=self.x_nodes)
            else:
                x = self.setup.disc.x
                self._setups[nodes] = _regridded(self.scene, self.setup, float(x[0]),
                                                 float(x[-1]), nodes)
        return self._setups[nodes]

    def levels(self) -> list[LineSetup]:
        # started from a solution on another grid (``start``): no level coarser than it
        coarsest = max(COARSEST_NODES, self.start[0].size if self.start is not None else 0)
        return [self.level(n) for n in line_levels(self.setup.disc.x.size, coarsest,
                                                   max_coarsenings=self._max_coarsenings())]

    def _max_coarsenings(self) -> int | None:
        """MAX_COARSENINGS for loaded half-space scenes above DENSE_MESH_MOES_M (where
        the outlet spike narrows with load), else None."""
        return MAX_COARSENINGS if _limited_coarsening(self.scene) else None

    def coarsen(self, level: LineSetup) -> LineSetup | None:
        """The level with half the spacing's inverse (every other node), or None."""
        n = level.disc.x.size
        if (n - 1) % 2 or (n - 1) // 2 < 8:
            return None
        return self.level((n - 1) // 2 + 1)

    # -- problems --------------------------------------------------------------------------
    def problem(self, level: LineSetup, s: float = 1.0,
                tolerance: float | None = None) -> LineProblem:
        """The problem on ``level``; s scales alpha (or the speed, from 100x, when
        isoviscous) for continuation."""
        if self.continuation_parameter == "alpha":
            return self._problem(level, piezo_scale=s)
        return self._problem(level, speed_scale=CONTINUATION_SPEED_FACTOR ** (1.0 - s))

    def _problem(self, level: LineSetup, piezo_scale: float = 1.0,
                 speed_scale: float = 1.0) -> LineProblem:
        scene = self.scene
        lub = scene.lubricant
        u_m = scene.kinematics.mean_speed * speed_scale
        if scene.model.elasticity == "half-space" and HALF_SPACE_STABILISATION == "upwind":
            reduced = None
            if REDUCED_POISEUILLE_LINE and lub.viscosity_law == "barus" \
                    and lub.effective_piezo > 0:
                reduced = lub.effective_piezo * piezo_scale
            flux = UpwindFluxModel.elastic(lub, u_m, level.stab_compliance,
                                           piezo_scale=piezo_scale, reduced_alpha=reduced)
        else:
            flux = FluxModel.from_lubricant(lub, u_m, compliance=level.stab_compliance,
                                            piezo_scale=piezo_scale)
        return LineProblem(level.disc, flux, scene.contact.rx, level.compliance,
                           scene.model.cavitation, scene.load.force, scene.load.gap,
                           level.p_ref, level.h_ref, lub.viscosity, self.bp)

    def initial_guess(self, level: LineSetup, problem: LineProblem,
                      s: float = 1.0) -> np.ndarray:
        """Hertzian (elastic, loaded), local-dry (Kodnir) or rigid linear initial guess.

        For the isoviscous speed continuation the film estimate is that of the start
        speed 100^(1-s) u_m (thicker than the target's)."""
        scene = self.scene
        x = level.disc.x
        if self.start is not None and s == 1.0:
            return self._from_start(level, problem)
        R = scene.contact.rx
        lub = scene.lubricant
        if scene.load.force is not None and scene.model.elasticity != "rigid":
            w = scene.load.force
            # at very light loads the dry contact may fall between the nodes of the
            # (hydrodynamically long) default grid: the guess spans at least 1.5 cells,
            # or its integral would be 0 and the load scaling NaN (M = 0.01 on 501 nodes;
            # a local-compliance roller at 100 N/m on 801 nodes)
            min_half_width = 1.5 * float(np.max(np.diff(x)))
            if scene.model.elasticity == "local":
                c = level.stab_compliance
                a = (1.5 * R * c * w) ** (1.0 / 3.0)  # dry local contact: p = (a^2-x^2)/(2Rc)
                a = max(a, min_half_width)
                p = np.maximum(a**2 - x**2, 0.0) / (2 * R * c)
            else:
                b = max(level.x_unit, min_half_width)
                p = level.p_ref * np.sqrt(np.maximum(1.0 - (x / b) ** 2, 0.0))
            p = p * w / (problem.mass @ p)
            v0 = float(np.interp(0.0, x, problem.displacement(p)))
            h_est = level.h_estimate
            if self.continuation_parameter == "speed" and s != 1.0:
                h_est = line_central_film_moes(
                    w, R, scene.e_prime, lub.viscosity,
                    scene.kinematics.mean_speed * CONTINUATION_SPEED_FACTOR ** (1.0 - s),
                    lub.effective_piezo)
            return problem.pack(p, h_est - v0)
        # rigid or prescribed gap: isoviscous rigid solution at the (estimated) offset
        h0 = scene.load.gap if scene.load.gap is not None else level.h_ref
        q, _, _ = reduced_isoviscous_solve(problem, h0, problem.p_bc.copy(),
                                           scene.kinematics.mean_speed, lub.viscosity,
                                           scene.model.cavitation)
        return problem.pack(q, h0)

    def _from_start(self, level: LineSetup, problem: LineProblem) -> np.ndarray:
        """Unknowns interpolated from ``start`` = (x [m], p [Pa], central film [m]), a
        solution of the same scene on another grid (the spike locator's)."""
        xs, ps, hc = self.start
        return _interpolated(problem, xs, ps, hc)

    def transfer(self, z: np.ndarray, coarse: LineProblem, fine: LineProblem) -> np.ndarray:
        """Interpolate a solution to another grid of the same interval (same film at
        x = 0)."""
        p_c, h0_c = coarse.unpack(z)
        xc = coarse.disc.x
        hc = float(np.interp(0.0, xc, coarse.film_nodes(p_c, h0_c)))
        return _interpolated(fine, xc, p_c, hc)

    def whole(self, problem: LineProblem, z: np.ndarray) -> tuple[LineProblem, np.ndarray]:
        """The problem and unknowns the result is reported on (the same for lines)."""
        return problem, z

    # -- solutions -------------------------------------------------------------------------
    def solution(self, problem: LineProblem, z: np.ndarray | None = None, *,
                 field: np.ndarray | None = None, h0: float | None = None,
                 post: bool = True, cavitated: np.ndarray | None = None) -> Solution:
        """Fields and post-processed numbers of unknowns ``z`` (or of a nodal pressure
        ``field`` at the offset ``h0``, for the linear path)."""
        scene = self.scene
        if z is not None:
            p, h0 = problem.unpack(z)
            if scene.model.cavitation == "reynolds":
                p = np.maximum(p, 0.0)  # the FB solution is >= 0 up to the tolerance
        else:
            p = field
        disc = problem.disc
        ops = disc.ops
        h_nodes = problem.film_nodes(p, h0)
        out = Solution(x=disc.x, y=None, pressure=p, film=h_nodes, h0=float(h0))
        if not post:
            return out
        pq, h_q, px, _ = problem.fields_q(p, h0)
        load = float(problem.mass @ p)
        q = out.quantities
        nums, notes = film_numbers(h_nodes, h_q, problem.film_central(p, h0), p, load, disc.x,
                                   h_near=problem.film_near_minimum(p, h0),
                                   constriction=(None if problem.rigid
                                                 else "the outlet constriction"))
        q.update(nums)
        outlet = outlet_position_line(disc.x, p, scene.model.cavitation)
        ind = full_film_indicator_line(ops.points[0], outlet)
        numbers, more, d = self._friction_and_heat(problem, p, h0, ind, load)
        q.update(numbers)
        out.traction_model = d.shear["model"]
        out.warnings += notes + more
        if outlet is not None:
            q["outlet_position"] = outlet
            q["h_outlet"] = float(np.interp(outlet, disc.x, h_nodes))
        out.extra_fields["viscosity_Pa_s"], more = reported_viscosity(
            problem.flux.viscosity(p), law=scene.lubricant.viscosity_law,
            reduced=problem.uses_reduced)
        out.warnings += more
        return out

    def _friction_and_heat(self, problem: LineProblem, p: np.ndarray, h0: float,
                           indicator: np.ndarray, load: float):
        """:func:`bearing_fem.post.friction_and_heat` of a solution on ``problem``."""
        pq, h_q, px, hx = problem.fields_q(p, h0)
        gq = problem.grad_reduced(p) if problem.uses_reduced else None
        ops = problem.disc.ops
        kin = self.scene.kinematics
        return friction_and_heat(
            ops, h_q, (px,), problem.flux.viscosity(pq), pq,
            mean_speed=kin.mean_speed, sliding_speed=kin.sliding_speed, indicator_q=indicator,
            load=load, gross_load=float(problem.mass @ np.abs(p)), traction=self.scene.traction,
            reduced=None if gq is None else (gq, problem.flux.viscosity0),
            stabilisation=problem.flux.stabilisation_flux(pq, h_q, (px,), (hx,),
                                                          ops.element_size, gq))

    def heat_flux(self, pressure: np.ndarray, h0: float) -> tuple[np.ndarray, FilmDissipation]:
        """Heat generated in the film per element [W/m^2] (element means of the Couette
        and conservative Poiseuille densities, :class:`bearing_fem.post.FilmDissipation`)
        of a solution on the model's own grid (``setup.disc.x``), and the dissipation."""
        problem = self.problem(self.setup)
        ops = self.setup.disc.ops
        outlet = outlet_position_line(self.setup.disc.x, pressure, self.scene.model.cavitation)
        ind = full_film_indicator_line(ops.points[0], outlet)
        _, _, d = self._friction_and_heat(problem, pressure, h0, ind,
                                          float(problem.mass @ pressure))
        per_element = (ops.weights * (d.couette_density + d.poiseuille_density)).reshape(
            -1, ops.n_quad).sum(axis=1) / np.diff(self.setup.disc.x)
        return per_element, d

    def linear(self, level: LineSetup, start: Solution | None = None
               ) -> tuple[str, Solution, str, int]:
        """Linear (reduced-pressure) solve on ``level``: status, solution, message and
        the number of linear solves. ``start``: a solution on another grid whose
        cavitated nodes (p <= 0) make the first guess of the cavitated set."""
        scene = self.scene
        lub = scene.lubricant
        law = reduced_law(lub)
        problem = self.problem(level)
        h0 = scene.load.gap
        q_bc = np.zeros(level.disc.x.size)
        q_bc[0], q_bc[-1] = law.to_reduced(np.array(self.bp, dtype=float))
        active = None
        if start is not None:
            dry = (np.asarray(start.pressure) <= 0.0).astype(float)
            active = np.interp(level.disc.x, start.x, dry) > 0.5
        q, solves, _ = reduced_isoviscous_solve(problem, h0, q_bc, scene.kinematics.mean_speed,
                                                lub.viscosity, scene.model.cavitation,
                                                active=active)
        status, field, msg = pressure_from_reduced(q, law, solves)
        return status, self.solution(problem, field=field, h0=h0,
                                     post=status == "linear"), msg, solves


def _interpolated(problem: LineProblem, xs: np.ndarray, ps: np.ndarray,
                  hc: float) -> np.ndarray:
    """Unknowns of ``problem`` from nodal pressures ``ps`` [Pa] at ``xs`` [m] of another grid
    (linear interpolation, the problem's end pressures kept) with the central film
    ``hc`` [m] (the offset that gives it on this grid; a prescribed gap has no offset
    unknown)."""
    x = problem.disc.x
    p = np.interp(x, xs, ps)
    p[[0, -1]] = problem.p_bc[[0, -1]]
    h0 = 0.0
    if problem.has_h0:
        h0 = hc - problem.film_central(p, 0.0)
    return problem.pack(p, h0)


def _regridded(scene, setup: LineSetup, x0: float, x1: float, nodes: int) -> LineSetup:
    """The same scene on another uniform grid over [x0, x1] [m] (the half-space
    compliance and its stabilisation scale follow the grid spacing)."""
    disc = LineDiscretisation.uniform(x0, x1, nodes)
    comp = setup.compliance
    c_stab = setup.stab_compliance
    if scene.model.elasticity == "half-space":
        comp, c_stab = _half_space(disc, scene.e_prime)
    return replace(setup, disc=disc, compliance=comp, stab_compliance=c_stab)


def solve_line(scene: Scene, *, boundary_pressure: tuple[float, float] | None = None,
               progress: Progress | None = None) -> Result:
    """Solve a line-contact scene (the linear path or damped Newton by the shared
    driver, :mod:`bearing_fem.contacts.driver`).

    Parameters
    ----------
    scene : Scene
        ``contact.kind == "line"``.
    boundary_pressure : (float, float), optional
        Dirichlet pressures at the inlet and outlet ends of the domain [Pa] (default
        0, 0); the analytic-oracle tests impose exact data this way.
    progress : callable, optional
        Progress callback (:func:`bearing_fem.contacts.driver.solve_levels`).

    Returns
    -------
    Result
        Never raises for non-convergence or non-existence: see ``result.status``.
    """
    t0 = time.perf_counter()
    bp = (0.0, 0.0) if boundary_pressure is None else boundary_pressure
    over = _rigid_barus_overload(scene) if bp == (0.0, 0.0) else None
    if over is not None:
        return _overload_result(scene, *over, t0)
    if scene.mesh.grading == "outlet":
        return _solve_outlet_graded(scene, bp, t0, progress)
    model = LineModel(scene, bp)
    if is_linear(scene):
        return solve_linear_model(model, scene, t0)
    return rigid_barus_beyond_limit(solve_newton_model(model, scene, t0, progress=progress))


#: ``mesh.grading = "outlet"``: the uniform grid whose solution locates the outlet spike
#: has a spacing of at most SPIKE_LOCATOR_SPACING Hertz half-widths (a quarter of the
#: refinement width), with SPIKE_LOCATOR_NODES to SPIKE_LOCATOR_MAX_NODES nodes (401 on
#: the default [-4.5, 1.5] b: 0.015 b; the cap makes it coarser on domains longer than
#: 50 b, the long inlets of light loads); the
#: refinement of :func:`bearing_fem.mesh.outlet_graded_nodes`: density ratio and width [b]
#: (the study of docs/line_contact.md, "Graded grids").
SPIKE_LOCATOR_SPACING = 0.025
SPIKE_LOCATOR_NODES = 401
SPIKE_LOCATOR_MAX_NODES = 2001
OUTLET_GRADING_RATIO = 9.0
OUTLET_GRADING_WIDTH = 0.1


def locator_nodes(scene: Scene, setup: LineSetup | None = None) -> int:
    """Node count of the uniform spike-locator grid of a scene.

    Parameters
    ----------
    scene : Scene
        An elastic line scene under load.
    setup : LineSetup, optional
        ``line_setup(scene)``, if the caller has it.

    Returns
    -------
    int
        4k + 1 nodes giving a spacing of at most :data:`SPIKE_LOCATOR_SPACING` Hertz
        half-widths over the scene's domain, between :data:`SPIKE_LOCATOR_NODES` and
        :data:`SPIKE_LOCATOR_MAX_NODES` (on domains longer than 50 b the cap makes the
        spacing coarser); above Moes M = :data:`DENSE_MESH_MOES_M` (half-space) at least
        the scene's own node count, up to the same cap.
    """
    setup = setup or line_setup(scene)
    width = float(setup.disc.x[-1] - setup.disc.x[0]) / setup.x_unit
    n = _nested_count(width / SPIKE_LOCATOR_SPACING)
    if _limited_coarsening(scene):
        # above DENSE_MESH_MOES_M the outlet spike is narrow: locate it on the scene's own
        # grid (capped), whose sequence keeps its coarsest level fine enough to converge
        # (on 401 nodes over the short isoviscous domain, M = 1000 spent the budget)
        # (rounded up to 4k + 1: a mesh.nodes count such as 1000 has no coarser levels)
        n = max(n, _nested_count(setup.disc.x.size - 1))
    return int(min(max(n, SPIKE_LOCATOR_NODES), SPIKE_LOCATOR_MAX_NODES))


def locate_outlet_spike(scene: Scene,
                        boundary_pressure: tuple[float, float] = (0.0, 0.0),
                        setup: LineSetup | None = None) -> tuple[float | None, Result]:
    """Where the outlet constriction of an elastic line scene lies.

    Parameters
    ----------
    scene : Scene
        An elastic line scene under load.
    boundary_pressure : (float, float)
        End pressures [Pa] of the scene's solve (the locator solves the same problem).
    setup : LineSetup, optional
        ``line_setup(scene)``, if the caller has it.

    Returns
    -------
    centre : float or None
        x of the smallest film [Hertz half-widths] of a solve on a uniform grid of
        :func:`locator_nodes` nodes over the scene's domain; None if that solve failed.
    result : Result
        That solve.
    """
    setup = setup or line_setup(scene)
    mesh = replace(scene.mesh, grading=None, nodes=locator_nodes(scene, setup))
    coarse = solve_line(replace(scene, mesh=mesh), boundary_pressure=boundary_pressure)
    if not coarse.success:
        return None, coarse
    b = setup.x_unit
    return float(coarse.x[int(np.argmin(coarse.film))] / b), coarse


def outlet_graded_grid(scene: Scene, centre: float,
                       setup: LineSetup | None = None) -> np.ndarray:
    """The nodes of ``scene``'s grid refined around its outlet spike.

    Parameters
    ----------
    scene : Scene
        An elastic line scene under load (its default or ``mesh.nodes`` node count and
        its domain).
    centre : float
        x of the refinement [Hertz half-widths] (clipped to the domain).
    setup : LineSetup, optional
        ``line_setup(scene)``, if the caller has it.

    Returns
    -------
    numpy.ndarray
        Increasing nodes [Hertz half-widths], the node count rounded up to 4k + 1 so that
        the two coarser levels nest (:func:`bearing_fem.mesh.outlet_graded_nodes`, ratio
        :data:`OUTLET_GRADING_RATIO`, width :data:`OUTLET_GRADING_WIDTH`).
    """
    setup = setup or line_setup(scene)
    x = setup.disc.x / setup.x_unit
    n = _nested_count(x.size - 1)
    lo, hi = float(x[0]), float(x[-1])
    return outlet_graded_nodes(n, (lo, hi), centre=min(max(centre, lo), hi),
                               width=OUTLET_GRADING_WIDTH, ratio=OUTLET_GRADING_RATIO)


def _spent(solver, iterations: int, seconds: float) -> str | None:
    """``"budget_exhausted"`` or ``"time_limit"`` if ``iterations`` Newton iterations and
    ``seconds`` [s] spend a ``[solver]`` section's budget, else None."""
    if iterations >= solver.iteration_budget:
        return "budget_exhausted"
    if solver.time_limit is not None and seconds >= solver.time_limit:
        return "time_limit"
    return None


def _remaining(solver, iterations: int, seconds: float):
    """The ``[solver]`` section with what ``iterations`` and ``seconds`` [s] left of its
    budget (see :func:`_spent`)."""
    left = {"iteration_budget": solver.iteration_budget - iterations}
    if solver.time_limit is not None:
        left["time_limit"] = solver.time_limit - seconds
    return replace(solver, **left)


def _solve_outlet_graded(scene: Scene, bp, t0: float, progress) -> Result:
    """``mesh.grading = "outlet"``: locate the spike on a coarse uniform grid, then solve on
    the grid refined there, started from the locator's solution; if the graded grid
    fails, the uniform grid (with a warning). The locator's iterations and time count in
    the result and against ``solver.iteration_budget`` and ``time_limit``."""
    setup = line_setup(scene)  # the scene's own grid: domain and node count, built once
    centre, coarse = locate_outlet_spike(scene, bp, setup)
    n_loc = coarse.x.size
    if centre is None:
        message = (f"mesh.grading = 'outlet': the solve on a uniform grid of {n_loc} nodes "
                   f"that locates the outlet spike ended with {coarse.status}: "
                   f"{coarse.message}")
        return replace(coarse, scene=scene, message=message,
                       wall_time_s=time.perf_counter() - t0)
    solver = scene.solver
    spent, spent_s = coarse.newton_iterations, time.perf_counter() - t0
    limits = (f"{solver.iteration_budget} Newton iterations"
              + (f", time limit {solver.time_limit:g} s" if solver.time_limit else ""))
    located = (f"the outlet spike was located at x = {centre:.4g} b in {spent} Newton "
               f"iterations and {spent_s:.3g} s on {n_loc} uniform nodes")
    status = _spent(solver, spent, spent_s)
    if status is not None:
        return replace(coarse, scene=scene, success=False, status=status,
                       error_estimate=None, wall_time_s=spent_s,
                       message=f"{status}: {located}, which spent the scene's budget "
                               f"({limits}) before the graded grid was solved")
    graded = replace(scene, solver=_remaining(solver, spent, spent_s))
    model = LineModel(graded, bp, x_nodes=outlet_graded_grid(scene, centre, setup))
    model.start = (coarse.x, coarse.pressure, float(np.interp(0.0, coarse.x, coarse.film)))
    res = solve_newton_model(model, graded, t0, progress=progress,
                             prefix=f"grid refined at the outlet spike; {located}; ")
    history = list(coarse.history) + list(res.history)
    steps = ([(s_, f"{st} (spike locator)", its) for s_, st, its in coarse.continuation]
             + list(res.continuation))
    total = spent + res.newton_iterations
    if not res.success and res.status not in BUDGET_STATUSES:
        spent += res.newton_iterations
        spent_s = time.perf_counter() - t0
        note = (f"mesh.grading = 'outlet': the graded grid failed ({res.status}: "
                f"{res.message})")
        status = _spent(solver, spent, spent_s)
        if status is not None:
            res = replace(res, status=status,
                          message=f"{status}: {note}, which spent the scene's budget "
                                  f"({limits}) before the uniform grid could be tried")
        else:
            uniform = replace(scene, mesh=replace(scene.mesh, grading=None),
                              solver=_remaining(solver, spent, spent_s))
            fallback = solve_line(uniform, boundary_pressure=bp, progress=progress)
            res = replace(fallback, warnings=[note + "; the result is on the uniform grid"]
                          + fallback.warnings,
                          message=f"{located}; the graded grid failed ({res.status}), the "
                                  f"result is on the uniform grid: {fallback.message}")
            total += fallback.newton_iterations
            history += list(fallback.history)
            steps += [(s_, f"{st} (uniform fallback)", its)
                      for s_, st, its in fallback.continuation]
    elif res.status in BUDGET_STATUSES:
        res = replace(res, message=f"{res.message} (the graded solve's share; the scene's "
                                   f"budget is {limits}, and {located})")
    return replace(res, scene=scene, newton_iterations=total,
                   wall_time_s=time.perf_counter() - t0, history=history,
                   continuation=steps)


#: alpha p beyond which the reduced pressure q = (1 - exp(-alpha p))/alpha equals 1/alpha
#: to double precision (exp(-36) = 2e-16): a rigid Barus solution there sits at Kapitsa's
#: existence limit alpha q_max = 1, its pressure set by rounding, not by the equations.
RIGID_BARUS_RESOLVABLE_ALPHA_P = 36.0
#: A rigid Barus load above this multiple of the largest load the contact can carry
#: (:func:`bearing_fem.analytic.martin_barus_load_limit`, exact in closed form on an
#: infinite inlet; a finite domain carries less) has no solution, and the solve ends so
#: before any Newton iteration. Above the limit a load-driven Newton solve can still
#: converge on a grid, the excess carried by a one-element pressure spike: 1.3 times the
#: limit on 201..801 nodes at alpha p_max = 9..24, and on the default grid 1.02 and 1.05
#: times it at alpha p_max = 16 and 21 when this factor was 1.1. So it is 1.
RIGID_BARUS_LOAD_MARGIN = 1.0


def _rigid_barus_overload(scene: Scene) -> tuple[float, float] | None:
    """(W*, h0*) of :func:`bearing_fem.analytic.martin_barus_load_limit` when ``scene``
    (rigid, incompressible, Barus, Reynolds cavitation, under load) asks for more than
    :data:`RIGID_BARUS_LOAD_MARGIN` W* [N/m], else None."""
    from ..analytic import martin_barus_load_limit

    if not is_rigid_barus_load(scene):
        return None
    lub = scene.lubricant
    limit, h_limit = martin_barus_load_limit(scene.contact.rx, lub.viscosity,
                                             scene.kinematics.mean_speed, lub.effective_piezo)
    return (limit, h_limit) if scene.load.force > RIGID_BARUS_LOAD_MARGIN * limit else None


def _overload_message(force: float, why: str) -> str:
    """The ``no_solution`` message of a rigid Barus roller loaded beyond its limit."""
    return (f"no_solution: load.force = {force:.4g} N/m exceeds what the rigid Barus "
            f"contact can carry: {why}: Kapitsa's existence limit alpha q_max < 1 "
            "(docs/theory.md). Lower the load, give the gap (load.gap) instead, or model the "
            "elasticity.")


def _overload_result(scene: Scene, limit: float, h_limit: float, t0: float) -> Result:
    """``no_solution`` for a rigid Barus load above :data:`RIGID_BARUS_LOAD_MARGIN` times
    its limit, without Newton iterations: the fields are the reduced pressure q at a gap
    5 % below h0* (one isoviscous linear solve on the scene's grid for that gap; alpha
    q_max exceeds 1 there on the default domain)."""
    gap = 0.95 * h_limit
    why = (f"the largest load of the rigid Barus cylinder is {limit:.4g} N/m, at the gap "
           f"h0 = {h_limit:.4g} m where alpha q_max = 1 (Martin's film with the Reynolds "
           "outlet; the reduced pressure grows as h0^(-3/2) as the gap closes)")
    message = (_overload_message(scene.load.force, why) + " The pressure field holds the "
               f"reduced pressure q at the gap {gap:.4g} m; no Newton iteration was run.")
    return overload_result(LineModel, scene, gap, message, t0)


def rigid_barus_beyond_limit(result: Result) -> Result:
    """A converged rigid Barus solve of a load (not a gap) whose pressure peak lies
    beyond :data:`RIGID_BARUS_RESOLVABLE_ALPHA_P` is no solution (a one-node spike set by
    rounding, Kapitsa: alpha q_max < 1), with the reduced pressure q in its fields; other
    results are returned unchanged. (Loads above :data:`RIGID_BARUS_LOAD_MARGIN` times the
    limit of an incompressible Reynolds-outlet roller end before any Newton iteration,
    :func:`solve_line`.)
    """
    scene = result.scene
    lub = scene.lubricant
    if not (scene.model.elasticity == "rigid" and scene.load.force is not None
            and lub.viscosity_law == "barus" and lub.effective_piezo > 0.0
            and result.success):
        return result
    alpha = lub.effective_piezo
    alpha_p = alpha * float(np.max(result.pressure))
    if alpha_p <= RIGID_BARUS_RESOLVABLE_ALPHA_P:
        return result
    why = (f"the converged discrete pressure peaks at alpha p = {alpha_p:.4g} (> "
           f"{RIGID_BARUS_RESOLVABLE_ALPHA_P:g}), where the reduced pressure "
           "q = (1 - exp(-alpha p))/alpha equals 1/alpha to double precision")
    message = (_overload_message(scene.load.force, why) + " The pressure field holds the "
               "reduced pressure q of the last iterate instead.")
    reduced = -np.expm1(-alpha * np.maximum(result.pressure, 0.0)) / alpha
    return replace(result, success=False, status="no_solution", message=message,
                   pressure=reduced, quantities={}, error_estimate=None,
                   traction_model=None)

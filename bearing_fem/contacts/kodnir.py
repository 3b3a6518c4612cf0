"""Kodnir's dimensionless EHL boundary problem (Yachikov & Vostrikov 2015), solved by finite elements.

Yachikov & Vostrikov (2015, heat power of the SKF NNCF 5040 CV roller bearing, eqs 4-6)
write the isothermal, Newtonian, Barus,
locally compliant line contact as

    dk/dz = (1 - H)/H^3 exp(B alpha k),     H = 1 - z_a^2 + z^2 + C k,           (4), (5)
    k(z_a) = 0, H(z_a) = 1 at the outlet z_a < 0;  k(z_b) = 0 at the inlet z_b > 0, (6)

and solves it by shooting on z_a. Here the same problem is solved by P1 finite elements
(scikit-fem), semismooth Newton and continuation, with no shooting.

Symbols (all DIMENSIONLESS; docs/theory.md section 13, "Kodnir variables"):

=========  =====================================================================
z          x/B1, x AGAINST the motion (inlet at z_b = +20, outlet z_a < 0)
k          p/B, dimensionless pressure
H          h/h*, film over the film h* where dp/dx = 0 at the outlet
C          A' B/(E h*), local compliance (elastic deflection C k)
b_alpha    B alpha, piezo-viscous parameter (viscosity exp(b_alpha k))
H_off      1 - z_a^2, offset of the film (an unknown of the discretisation)
eps        H^3 exp(-b_alpha k), flow coefficient
F          eps dk/dz + H, mass flux (in units of the Couette flux of the film h*)
=========  =====================================================================

Formulation. Eq (4) is the once-integrated Reynolds equation
F = H^3 exp(-b_alpha k) dk/dz + H = 1. Differentiating, -dF/dz = 0: the Reynolds equation
in divergence form, d/dz(eps dk/dz) = -dH/dz (the fluid moves towards -z), whose
weak form on a fixed domain z in [z_min, z_b] is

    R_i = int F dphi_i/dz dz = 0       (phi_i the P1 hat functions).

Cavitation (Reynolds / Swift-Stieber) is the complementarity problem k_i >= 0, R_i >= 0,
k_i R_i = 0 at every free node, written as a Fischer-Burmeister row. In the cavitated
zone z < z_a, k = 0 and R_i ~ -dH/dz dz > 0 (diverging gap). The free boundary gets
k = dk/dz = 0 automatically, so there the flux is F = H(z_a).

The flux condition. With P1 elements, R_i = Fbar(e_left) - Fbar(e_right) (element means
of F), so the Galerkin equations make the element-mean flux the same constant Q in every
pressurised element (discrete mass conservation), and Q is the reaction (weak residual)
at the Dirichlet inlet node z_b. The extra scalar equation that determines the extra
unknown H_off is Q = R_N = 1: the film at the outlet, where dk/dz = 0, equals h*
(H = 1) -- exactly the paper's condition H(z_a) = 1 of eq (6). Then z_a = -sqrt(1 - H_off)
by eq (5): the outlet position is a continuous function of the unknowns (sub-grid).
The free-boundary position (where k drops to 0) is reported separately, from a linear
extrapolation of sqrt(k) (k ~ (z - z_a)^2 near a Reynolds outlet) through the two first
pressurised nodes; both converge to the same point and their difference is a
discretisation-error indicator.

Stabilisation. Where exp(b_alpha k) is large, eps -> 0 and the equation degenerates to
the advection of k through the elastic film term C k (Galerkin P1 then gives odd-even
oscillations). The flux is stabilised by streamline-upwind Petrov-Galerkin exactly as
in :mod:`bearing_fem.physics.reynolds` (test function v + tau beta dv/dz, advection speed
beta = -C, tau beta = -(dz/2)(coth Pe - 1/Pe), Pe = C dz / (2 eps), multiplying the
element strong residual S = -d(eps)/dz dk/dz - dH/dz); consistent (S = 0 for the exact
solution) and absent when C = 0. The derivatives of the pointwise flux are taken by the
complex-step method.

Post-processing (Yachikov & Vostrikov 2015, eqs 8-9): I = int_{z_a}^{z_b} (1 - H) dk/dz dz and
J = int_{z_a}^{z_b} exp(b_alpha k)/H dz; dimensional friction and heat by
:func:`kodnir_friction_heat`.
"""
from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.optimize import brentq
from skfem import CellBasis, ElementLineP1, MeshLine

from ..numerics.fe import QuadratureOperators, quadrature_operators
from .problem import fischer_burmeister
from ..numerics.newton import NewtonOutcome, damped_newton
from ..post import parabola_vertex
from ..physics.reynolds import upwind_factor
from ..validation import require_finite, require_int, require_nonnegative, require_positive

log = logging.getLogger(__name__)

__all__ = ["KodnirResult", "KodnirScales", "KodnirFrictionHeat", "solve", "kodnir_scales",
           "kodnir_friction_heat", "to_dimensional", "graded_grid"]

_STEP = 1e-20  # complex step


# ----------------------------------------------------------------------------------------
# Grid
# ----------------------------------------------------------------------------------------
#: Layer bands of the final grid (dimensionless z), for stiff local compliance: at the
#: outlet from z_a - OUTLET_BAND_BEHIND - 2 % of |z_a| to z_a + w, at the inlet z_in -+ w
#: (z_in: last node of the coarse solution with k > 1 % of k_max), w =
#: max(OUTLET_BAND_AHEAD, OUTLET_BAND_LAYERS / C). Their spacing is a fixed ratio of the
#: zone spacing, chosen so that the layer width 1/C gets OUTLET_LAYER_CELLS intervals on a
#: BAND_REFERENCE_NODES-node grid (ratio between MIN_BAND_RATIO and 1; it is 1, no band,
#: unless C is of order 20 or more). docs/kodnir.md.
OUTLET_BAND_BEHIND = 0.1
OUTLET_BAND_AHEAD = 0.5
OUTLET_BAND_LAYERS = 20.0
OUTLET_LAYER_CELLS = 10.0
BAND_REFERENCE_NODES = 2001
MIN_BAND_RATIO = 0.125


def graded_grid(z_min: float, z_fine: float, z_b: float, nodes: int,
                fine_fraction: float = 0.8,
                bands: tuple[tuple[float, float], ...] = (),
                band_ratio: float = 1.0) -> np.ndarray:
    """Node coordinates: uniform on [z_min, z_fine], geometric growth up to z_b.

    ``fine_fraction`` of the intervals lie in [z_min, z_fine] (spacing dz); the rest grow
    geometrically from dz so that they end exactly at z_b (dimensionless z).

    ``bands``: disjoint, increasing intervals (z_lo, z_hi) inside [z_min, z_fine] whose
    spacing is ``band_ratio`` (< 1) times the spacing of the rest of the zone (used for the
    outlet and inlet layers of stiff contacts). The ratio does not depend on ``nodes``, so
    doubling the nodes halves every spacing (a proper grid refinement).
    """
    if not z_min < z_fine < z_b:
        raise ValueError(f"need z_min < z_fine < z_b, got {z_min}, {z_fine}, {z_b}")
    n_int = nodes - 1
    n_f = max(2, int(round(fine_fraction * n_int)))
    n_c = n_int - n_f
    fine = np.linspace(z_min, z_fine, n_f + 1)
    cuts = [(max(lo, z_min), min(hi, z_fine)) for lo, hi in bands]
    cuts = [(lo, hi) for lo, hi in cuts if hi > lo]
    if cuts and band_ratio < 1.0:
        edges, dense = [z_min], []
        for lo, hi in cuts:
            if lo > edges[-1]:
                edges.append(lo)
                dense.append(False)
            edges.append(hi)
            dense.append(True)
        if edges[-1] < z_fine:
            edges.append(z_fine)
            dense.append(False)
        weight = np.diff(edges) / np.where(dense, band_ratio, 1.0)
        counts = np.maximum(1, np.round(n_f * weight / weight.sum()).astype(int))
        counts[int(np.argmax(counts))] += n_f - counts.sum()
        fine = np.concatenate([np.linspace(a, b, c + 1)[:-1] for a, b, c
                               in zip(edges[:-1], edges[1:], counts)] + [[z_fine]])
    dz = fine[-1] - fine[-2]
    length = z_b - z_fine
    if n_c <= 0:
        return np.append(fine[:-1], np.linspace(z_fine, z_b, 2))
    if length <= n_c * dz:  # no growth needed
        return np.append(fine, np.linspace(z_fine, z_b, n_c + 1)[1:])
    r_hi = min(10.0, math.exp(600.0 / n_c))
    ratio = brentq(lambda r: dz * np.expm1(n_c * np.log(r)) / (r - 1.0) - length,
                   1.0 + 1e-12, r_hi)
    steps = dz * ratio ** np.arange(1, n_c + 1)
    coarse = z_fine + np.cumsum(steps)
    coarse[-1] = z_b
    return np.append(fine, coarse)


@dataclass
class _Grid:
    z: np.ndarray
    ops: QuadratureOperators
    #: refined bands (outlet, inlet critical point) of a continuation grid and the C
    #: whose outlet layer 1/C they resolve
    bands: tuple[tuple[float, float], ...] = ()
    layer_c: float = 0.0

    @classmethod
    def from_nodes(cls, z: np.ndarray, intorder: int = 4,
                   bands: tuple[tuple[float, float], ...] = (),
                   layer_c: float = 0.0) -> "_Grid":
        basis = CellBasis(MeshLine(np.asarray(z, dtype=float)), ElementLineP1(), intorder=intorder)
        return cls(z=np.asarray(z, dtype=float), ops=quadrature_operators(basis),
                   bands=bands, layer_c=layer_c)


#: Continuation grids for stiff local compliance (docs/kodnir.md): from C >= REGRID_MIN_C
#: on, the continuation grid gets a band of half-width max(OUTLET_BAND_AHEAD,
#: COARSE_BAND_LAYERS / C) around the outlet z_a and one of half-width 1 around the inlet
#: critical point z* = 2C/27 (H = 3/2, where dk/dz = (1 - H)/H^3 reaches its bound -4/27),
#: spaced so that the outlet layer 1/C_d gets COARSE_LAYER_CELLS intervals (C_d =
#: REGRID_C_GROWTH times the current C, at most the target), on top of the nodes of the
#: base grid; it is rebuilt around the current solution when z_a or z* leaves the middle
#: half of its band or C exceeds C_d.
REGRID_MIN_C = 60.0
#: First break point of the march in C (then doubling): below it, one straight segment.
PATH_BREAK = 200.0
COARSE_BAND_LAYERS = 60.0
COARSE_LAYER_CELLS = 3.0
REGRID_C_GROWTH = 1.25


def _outlet_position(h_off: float) -> float:
    """Outlet (free boundary) z_a = -sqrt(1 - H_off) of the film H = H_off + z^2 + C k,
    where k = 0 and H = 1 (dimensionless; 0 when H_off >= 1)."""
    return -math.sqrt(max(1.0 - h_off, 0.0))


def _inlet_layer(z: np.ndarray, k: np.ndarray) -> float:
    """Inlet layer of a stiff contact: the middle of the element where k falls fastest
    downstream of its maximum (dimensionless z)."""
    i = int(np.argmax(k))
    slope = np.diff(k[i:]) / np.diff(z[i:])
    j = i + int(np.argmin(slope))
    return float(0.5 * (z[j] + z[j + 1]))


def _continuation_grid(z_a: float, z_in: float, C: float, C_target: float, z_b: float,
                       base_nodes: int) -> _Grid:
    """Continuation grid with bands around the outlet z_a and the inlet critical point
    2C/27 for the local compliance C (see REGRID_MIN_C); the uniform zone [z_lo, z_fine]
    reaches past the inlet layer z_in (:func:`_inlet_layer`) and keeps the spacing of a
    ``base_nodes`` grid outside the bands (dimensionless z)."""
    c_d = min(C_target, REGRID_C_GROWTH * C)
    w = max(OUTLET_BAND_AHEAD, COARSE_BAND_LAYERS / C)
    z_lo = z_a - 0.5 - max(1.0, 0.3 * abs(z_a))
    z_fine = min(0.98 * z_b, max(0.5 * z_b, z_in + 2.0 + 0.1 * abs(z_in), 2.0 * C / 27.0 + 2.0))
    z_crit = 2.0 * C / 27.0
    bands = [(max(z_a - w, z_lo), min(z_a + w, z_fine))]
    if z_crit + 1.0 < z_fine:
        bands.append((max(z_crit - 1.0, bands[0][1]), min(z_crit + 1.0, z_fine)))
    h_rest = (z_fine - z_lo) / (0.8 * (base_nodes - 1))
    h_band = min(h_rest, 1.0 / (COARSE_LAYER_CELLS * c_d))
    width = sum(hi - lo for lo, hi in bands)
    n_f = (z_fine - z_lo - width) / h_rest + width / h_band
    nodes = int(math.ceil(n_f / 0.8)) + 1
    z = graded_grid(z_lo, z_fine, z_b, nodes, bands=tuple(bands), band_ratio=h_band / h_rest)
    return _Grid.from_nodes(z, bands=tuple(bands), layer_c=c_d)


def _needs_regrid(grid: _Grid, prob: "KodnirProblem", u: np.ndarray) -> bool:
    """True if the continuation grid no longer fits the solution u at prob.C."""
    if prob.C < REGRID_MIN_C:
        return False
    if not grid.bands or prob.C > grid.layer_c:
        return True
    def in_middle(band: tuple[float, float], z: float) -> bool:  # its middle half
        lo, hi = band
        return lo + 0.25 * (hi - lo) <= z <= hi - 0.25 * (hi - lo)

    _, h_off = prob.unpack(u)
    if not in_middle(grid.bands[0], _outlet_position(h_off)):
        return True
    return len(grid.bands) > 1 and not in_middle(grid.bands[1], 2.0 * prob.C / 27.0)


# ----------------------------------------------------------------------------------------
# Pointwise flux
# ----------------------------------------------------------------------------------------
def _flux(k, H, kp, Hp, dz, b_alpha: float, C: float):
    """Stabilised flux F = eps k' + H + tau beta S at quadrature points (dimensionless)."""
    eps = H**3 * np.exp(-b_alpha * k)
    f = eps * kp + H
    if C > 0.0:
        strong = -eps * (3.0 * Hp / H - b_alpha * kp) * kp - Hp
        pe = C * dz / (2.0 * eps)
        f = f - 0.5 * dz * upwind_factor(pe) * strong
    return f


def _flux_derivatives(k, H, kp, Hp, dz, b_alpha, C):
    """Flux and its partial derivatives w.r.t. (k, H, k', H') by complex step."""
    base = _flux(k, H, kp, Hp, dz, b_alpha, C)
    args = [k, H, kp, Hp]
    out = []
    for j in range(4):
        v = args[j]
        scale = float(np.max(np.abs(v))) if v.size else 1.0
        step = _STEP * (scale if scale > 0 else 1.0)
        a = list(args)
        a[j] = v + 1j * step
        out.append(np.imag(_flux(*a, dz, b_alpha, C)) / step)
    return base, out


# ----------------------------------------------------------------------------------------
# Nonlinear problem (implements newton.NonlinearProblem)
# ----------------------------------------------------------------------------------------
class KodnirProblem:
    """Discrete system of the Kodnir problem on a fixed grid.

    Unknowns: k at the interior nodes (k = 0 at z_min and z_b) and H_off.
    Rows: Fischer-Burmeister(k_i, R_i s_i) at interior nodes, s_i a frozen row scale
    (1/|dR_i/dk_i|, so the residual is in units of k); last row (Q - 1)/(1 + z_b^2),
    Q = R_N.
    """

    def __init__(self, grid: _Grid, C: float, b_alpha: float) -> None:
        self.grid, self.C, self.b_alpha = grid, float(C), float(b_alpha)
        ops = grid.ops
        self.zq = ops.points[0]
        n = grid.z.size
        self.n = n
        self.free = np.arange(1, n - 1)
        self.n_unknowns = self.free.size + 1
        self._scale: np.ndarray | None = None
        # the inlet flux sums terms of size H(z_b) ~ z_b^2 that cancel to 1: the flux row is
        # divided by that size so that its rounding noise stays below the Newton tolerance
        self._flux_scale = 1.0 / (1.0 + grid.z[-1] ** 2)

    # fields -----------------------------------------------------------------------------
    def unpack(self, u: np.ndarray) -> tuple[np.ndarray, float]:
        k = np.zeros(self.n, dtype=u.dtype)
        k[self.free] = u[:-1]
        return k, u[-1]

    def pack(self, k: np.ndarray, h_off: float) -> np.ndarray:
        return np.append(k[self.free], h_off)

    def film_nodes(self, k: np.ndarray, h_off: float) -> np.ndarray:
        return h_off + self.grid.z**2 + self.C * k

    def fields_q(self, k: np.ndarray, h_off: float):
        ops = self.grid.ops
        kq = ops.value @ k
        kp = ops.grad[0] @ k
        H = h_off + self.zq**2 + self.C * kq
        Hp = 2.0 * self.zq + self.C * kp
        return kq, H, kp, Hp

    def nodal_residual(self, k: np.ndarray, h_off: float) -> np.ndarray:
        """R_i = int F dphi_i/dz at all nodes (R at z_b is the flux Q)."""
        kq, H, kp, Hp = self.fields_q(k, h_off)
        f = _flux(kq, H, kp, Hp, self.grid.ops.element_size, self.b_alpha, self.C)
        return self.grid.ops.weak_divergence(f)

    # NonlinearProblem -------------------------------------------------------------------
    def prepare(self, u: np.ndarray) -> None:
        # the row scale is frozen at the first iterate (the previous continuation
        # solution) so that the Newton merit |F|^2 is the same function all along
        if self._scale is not None:
            return
        k, h_off = self.unpack(u)
        ops = self.grid.ops
        kq, H, kp, Hp = self.fields_q(k, h_off)
        _, d = _flux_derivatives(kq, H, kp, Hp, ops.element_size, self.b_alpha, self.C)
        a = ops.flux_jacobian(0, d[0] + self.C * d[1], (d[2] + self.C * d[3],))
        diag = np.abs(a.diagonal())[self.free]
        self._scale = 1.0 / np.maximum(diag, 1e-300)

    def admissible(self, u: np.ndarray) -> bool:
        if not np.all(np.isfinite(u)):
            return False
        k, h_off = self.unpack(u)
        _, H, _, _ = self.fields_q(k, h_off)
        if not (np.min(H) > 0.0 and np.min(self.film_nodes(k, h_off)) > 0.0):
            return False
        with np.errstate(over="ignore"):
            return bool(np.all(np.isfinite(np.exp(self.b_alpha * np.abs(k)))))

    def residual(self, u: np.ndarray) -> np.ndarray:
        k, h_off = self.unpack(u)
        with np.errstate(over="ignore", invalid="ignore"):
            r = self.nodal_residual(k, h_off)
        phi, _, _ = fischer_burmeister(k[self.free], r[self.free] * self._scale, mu=0.0)
        return np.append(phi, (r[-1] - 1.0) * self._flux_scale)

    def jacobian(self, u: np.ndarray) -> sp.csc_matrix:
        k, h_off = self.unpack(u)
        ops = self.grid.ops
        kq, H, kp, Hp = self.fields_q(k, h_off)
        f, d = _flux_derivatives(kq, H, kp, Hp, ops.element_size, self.b_alpha, self.C)
        r = ops.weak_divergence(f)
        a = ops.flux_jacobian(0, d[0] + self.C * d[1], (d[2] + self.C * d[3],)).tocsr()
        col_h = np.asarray(ops.grad[0].T @ (ops.weights * d[1])).ravel()
        fr = self.free
        s = self._scale
        _, da, db = fischer_burmeister(k[fr], r[fr] * s, mu=0.0)
        jk = sp.diags(db * s) @ a[fr][:, fr] + sp.diags(da)
        jh = (db * s * col_h[fr])[:, None]
        last_k = a[self.n - 1][:, fr] * self._flux_scale
        last_h = np.array([[col_h[self.n - 1] * self._flux_scale]])
        return sp.bmat([[jk, sp.csr_matrix(jh)], [last_k, sp.csr_matrix(last_h)]], format="csc")

    def newton_step(self, u: np.ndarray, shift: float = 0.0) -> np.ndarray:
        j = self.jacobian(u)
        f = self.residual(u)
        if shift:
            d = np.full(j.shape[0], shift)
            d[-1] = 0.0
            j = j + sp.diags(d)
        return spla.spsolve(j.tocsc(), -f)


# ----------------------------------------------------------------------------------------
# Result
# ----------------------------------------------------------------------------------------
@dataclass
class KodnirResult:
    """Solution of the Kodnir problem (4)-(6). Everything is dimensionless.

    Attributes
    ----------
    success : bool
    status : str
        ``converged`` or the reason of failure: ``no_convergence``, ``no_solution``
        (C = 0 with B alpha q_max >= 1: no rigid piezo-viscous solution exists) or
        ``outlet_outside_domain``.
    message : str
    C, b_alpha, z_b : float
        Parameters.
    z_a : float
        Outlet position -sqrt(1 - H_off) (the paper's z_a, eq 5); NaN only when unsuccessful.
    z_a_free_boundary : float
        Where k drops to 0, from sqrt(k) extrapolation (agrees with z_a to discretisation
        accuracy).
    k_max : float
        Maximum of k (sub-grid parabola through the three nodes around the largest nodal k).
    z_k_max : float
        Its position.
    h_min : float
        Minimum of H over [z_a, z_b] (sub-grid parabola), and ``z_h_min`` its position.
    h_offset : float
        H_off = 1 - z_a^2.
    friction_integral : float
        I = int_{z_a}^{z_b} (1 - H) dk/dz dz (Yachikov & Vostrikov 2015, eq 8).
    couette_integral : float
        J = int_{z_a}^{z_b} exp(b_alpha k)/H dz (Yachikov & Vostrikov 2015, eq 9).
    flux : float
        Discrete mass flux Q (1 when converged).
    z, k, H : ndarray
        Nodes, nodal k, nodal H of the final grid.
    iterations : int
        Total Newton iterations (all continuation steps and grids).
    continuation : list of (C, b_alpha, status, iterations)
    """

    success: bool
    status: str
    message: str
    C: float
    b_alpha: float
    z_b: float
    z_a: float = math.nan
    z_a_free_boundary: float = math.nan
    k_max: float = math.nan
    z_k_max: float = math.nan
    h_min: float = math.nan
    z_h_min: float = math.nan
    h_offset: float = math.nan
    friction_integral: float = math.nan
    couette_integral: float = math.nan
    flux: float = math.nan
    z: np.ndarray = field(default_factory=lambda: np.zeros(0))
    k: np.ndarray = field(default_factory=lambda: np.zeros(0))
    H: np.ndarray = field(default_factory=lambda: np.zeros(0))
    iterations: int = 0
    continuation: list = field(default_factory=list)

    def __repr__(self) -> str:
        return (f"KodnirResult(message={self.message!r}, success={self.success}, "
                f"status={self.status!r}, C={self.C}, b_alpha={self.b_alpha}, "
                f"z_a={self.z_a:.6g}, k_max={self.k_max:.6g}, h_min={self.h_min:.6g}, "
                f"I={self.friction_integral:.6g}, J={self.couette_integral:.6g}, "
                f"z: shape {self.z.shape})")

    def summary(self) -> dict:
        """Flat dict of the scalar outputs."""
        keys = ["success", "status", "message", "C", "b_alpha", "z_b", "z_a",
                "z_a_free_boundary", "k_max", "z_k_max", "h_min", "z_h_min", "h_offset",
                "friction_integral", "couette_integral", "flux", "iterations"]
        out = {k: getattr(self, k) for k in keys}
        out["nodes"] = int(self.z.size)
        return out


# ----------------------------------------------------------------------------------------
# Post-processing of a discrete solution
# ----------------------------------------------------------------------------------------
#: Relative level below which a nodal k counts as zero (cavitated) in post-processing.
PRESSURISED_FLOOR = 1e-12


def _free_boundary(z: np.ndarray, k: np.ndarray) -> float:
    """Outlet where k drops to 0: sqrt(k) extrapolated linearly from the two first
    pressurised nodes (k ~ (z - z_a)^2 at a Reynolds boundary). Nodes with
    k <= PRESSURISED_FLOOR * max k (rounding noise of the complementarity solution in the
    cavitated zone) count as unpressurised."""
    pos = np.nonzero(k > PRESSURISED_FLOOR * np.max(k))[0]
    if pos.size < 3:
        return math.nan
    i = pos[0]
    # the first pressurised node lies within one cell of the free boundary, where the
    # complementarity solution is least accurate: use nodes i+1 and i+2
    s1, s2 = math.sqrt(max(k[i + 1], 0.0)), math.sqrt(max(k[i + 2], 0.0))
    if s2 <= s1:
        return float(z[i])
    return float(z[i + 1] - s1 * (z[i + 2] - z[i + 1]) / (s2 - s1))


def _gauss_on(a: float, b: float, n: int = 8) -> tuple[np.ndarray, np.ndarray]:
    t, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * t + 0.5 * (a + b), 0.5 * (b - a) * w


def _integrals(prob: KodnirProblem, k: np.ndarray, h_off: float, z_a: float) -> tuple[float, float]:
    """I and J over [z_a, z_b]: scikit-fem quadrature on the elements right of z_a and a
    Gauss rule on the part of the element cut by z_a."""
    grid, ops = prob.grid, prob.grid.ops
    kq, H, kp, _ = prob.fields_q(k, h_off)
    nq = ops.n_quad
    z = grid.z
    left = np.repeat(z[:-1], nq)
    full = left >= z_a
    w = ops.weights * full
    with np.errstate(over="ignore"):
        i_val = float(w @ ((1.0 - H) * kp))
        j_val = float(w @ (np.exp(prob.b_alpha * kq) / H))
    e = int(np.searchsorted(z, z_a) - 1)
    if 0 <= e < z.size - 1:
        zg, wg = _gauss_on(z_a, z[e + 1])
        kg = np.interp(zg, z, k)
        slope = (k[e + 1] - k[e]) / (z[e + 1] - z[e])
        Hg = h_off + zg**2 + prob.C * kg
        i_val += float(wg @ ((1.0 - Hg) * slope))
        j_val += float(wg @ (np.exp(prob.b_alpha * kg) / Hg))
    return i_val, j_val


def _finish(res: KodnirResult, prob: KodnirProblem, u: np.ndarray) -> KodnirResult:
    k, h_off = prob.unpack(u)
    z = prob.grid.z
    H = prob.film_nodes(k, h_off)
    res.z, res.k, res.H = z.copy(), k.copy(), H.copy()
    res.h_offset = float(h_off)
    res.flux = float(prob.nodal_residual(k, h_off)[-1])
    res.z_a = _outlet_position(h_off)
    res.z_a_free_boundary = _free_boundary(z, k)
    res.z_k_max, res.k_max = parabola_vertex(z, k, int(np.argmax(k)))
    inside = z >= res.z_a
    idx = np.nonzero(inside)[0]
    i_min = int(idx[np.argmin(H[idx])])
    res.z_h_min, res.h_min = parabola_vertex(z, H, i_min)
    res.friction_integral, res.couette_integral = _integrals(prob, k, h_off, res.z_a)
    return res


# ----------------------------------------------------------------------------------------
# Driver
# ----------------------------------------------------------------------------------------
def _check(C: float, b_alpha: float, z_b: float, nodes: int, coarse_nodes: int = 401,
           tol: float = 1e-10, max_iterations: int = 60,
           z_min: float | None = None) -> None:
    for name, val in (("C", C), ("b_alpha", b_alpha), ("z_b", z_b)):
        if not isinstance(val, (int, float, np.floating, np.integer)) or not math.isfinite(val):
            raise ValueError(f"{name} must be a finite number (dimensionless), got {val!r}")
    if C < 0:
        raise ValueError(f"C (dimensionless compliance) must be >= 0, got {C}")
    if b_alpha < 0:
        raise ValueError(f"b_alpha (dimensionless B alpha) must be >= 0, got {b_alpha}")
    if z_b <= 0:
        raise ValueError(f"z_b (dimensionless inlet position) must be > 0, got {z_b}")
    require_int("nodes", nodes, 50, what="nodes")
    require_int("coarse_nodes", coarse_nodes, 50, what="nodes")
    require_int("max_iterations", max_iterations, 1, what="Newton iterations")
    require_positive("tol (Newton tolerance)", tol, "(units of k)")
    if z_min is not None and require_finite("z_min", z_min, "(dimensionless)") > -1.0:
        raise ValueError(f"z_min (dimensionless left end of the grid) must be <= -1 (the "
                         f"contact lies in |z| < 1), got {z_min!r}")


def _initial_guess(prob: KodnirProblem) -> np.ndarray:
    """Rigid isoviscous solution (C = 0, b_alpha = 0) as initial guess.

    With H = H_off + z^2 the flux form of eq (4) integrates from the inlet,
    k(z) = int_z^{z_b} (H - 1)/H^3 dz, clipped at 0 downstream of its first zero, and
    H_off is chosen so that this k vanishes again at z_a = -sqrt(1 - H_off)
    (Martin's outlet when z_b -> infinity).
    """
    from scipy.integrate import cumulative_trapezoid

    z = prob.grid.z
    zz = np.unique(np.concatenate([z, np.linspace(z[0], z[-1], 4001)]))

    def profile(h_off: float) -> np.ndarray:
        H = h_off + zz**2
        f = (H - 1.0) / H**3
        c = cumulative_trapezoid(f, zz, initial=0.0)
        return c[-1] - c

    def k_at_outlet(h_off: float) -> float:
        za = -math.sqrt(1.0 - h_off)
        return float(np.interp(za, zz, profile(h_off)))

    try:
        h_off = brentq(k_at_outlet, 0.3, 0.99, xtol=1e-12)
    except ValueError:
        h_off = 0.8
    kk = profile(h_off)
    za = -math.sqrt(1.0 - h_off)
    kk = np.where(zz > za, np.maximum(kk, 0.0), 0.0)
    k = np.interp(z, zz, kk)
    k[0] = k[-1] = 0.0
    return prob.pack(k, h_off)


def _transfer(u: np.ndarray, old: KodnirProblem, new: KodnirProblem) -> np.ndarray:
    k, h_off = old.unpack(u)
    kn = np.interp(new.grid.z, old.grid.z, k, left=0.0, right=0.0)
    return new.pack(kn, h_off)


def _moving_secant(prob: KodnirProblem, u: np.ndarray, c_u: float, u_prev: np.ndarray,
                   c_prev: float, r: float) -> np.ndarray:
    """Secant predictor u + r (u - u_prev) that moves with the contact (stiff local
    compliance, C >= REGRID_MIN_C).

    u and u_prev are solutions at the compliances c_u and c_prev. The outlet z_a is
    extrapolated; on the outlet side (z < 0) the film H is extrapolated at the same
    relative position z/z_a and k follows from eq (5), k = (H - H_off - z^2)/C, so that
    the free boundary starts where it will be instead of moving one node per Newton
    iteration. For z >= 0 the nodal secant in a frame that moves with the inlet critical
    point 2C/27 (piecewise linear, fixed at 0 and z_b).
    """
    z = prob.grid.z
    k, h = prob.unpack(u)
    kp, hp = prob.unpack(u_prev)
    za, zap = _outlet_position(h), _outlet_position(hp)
    za_n = za + r * (za - zap)
    h_n = 1.0 - za_n**2
    Hc = np.interp(z * za / za_n, z, h + z**2 + c_u * k)
    Hp = np.interp(z * zap / za_n, z, hp + z**2 + c_prev * kp)
    km = np.maximum((Hc + r * (Hc - Hp) - h_n - z**2) / prob.C, 0.0)
    z_b = z[-1]
    zc_u, zc_p, zc_n = (2.0 * c / 27.0 for c in (c_u, c_prev, prob.C))
    if max(zc_u, zc_p, zc_n) < 0.95 * z_b:
        # inlet critical point z* = 2 C/27 (H = 3/2, where the Couette-Poiseuille flux
        # (H - 1)/H^3 is largest): the secant in a frame that moves with it
        def frame(zc: float) -> np.ndarray:
            return np.interp(z, [0.0, zc_n, z_b], [0.0, zc, z_b])
        k_u = np.interp(frame(zc_u), z, k)
        k_p = np.interp(frame(zc_p), z, kp)
        ks = np.maximum(k_u + r * (k_u - k_p), 0.0)
    else:
        ks = np.maximum(k + r * (k - kp), 0.0)
    kn = np.where(z <= za_n, 0.0, np.where(z < 0.0, km, ks))
    kn[0] = kn[-1] = 0.0
    return prob.pack(kn, h_n)


def _march(grid: _Grid, u0: np.ndarray, path: list[tuple[float, float]],
           record: list, tol: float, max_iterations: int,
           min_increment: float = 1e-3, base_nodes: int = 0
           ) -> tuple[np.ndarray | None, int, str, _Grid]:
    """Follow the straight segments of a (C, b_alpha) path with adaptive steps.

    With ``base_nodes`` > 0 the grid is rebuilt around the solution (layer bands,
    :func:`_continuation_grid`) whenever :func:`_needs_regrid` says so; the grid of the
    last solution is returned with it."""
    u = u0
    total = 0
    start = path[0]
    prob = KodnirProblem(grid, *start)
    out = damped_newton(prob, u, tol=tol, max_iterations=max_iterations, memory=1)
    total += out.iterations
    record.append((start[0], start[1], out.status, out.iterations))
    if not out.converged:
        return (None, total, f"no convergence at C={start[0]:.4g}, b_alpha={start[1]:.4g}",
                grid)
    u = out.z
    c_target = max(p[0] for p in path)
    grid0 = grid
    for a, b in zip(path[:-1], path[1:]):
        s, ds = 0.0, 1.0 if a == start else 0.5
        if a[0] == b[0] and a[1] != b[1] and grid.bands:
            # the march in b_alpha runs on the base grid (on the banded grids it stalled
            # at b_alpha ~ 0.02 for C = 80 and 100, where the base grid converges)
            prob, prob0 = KodnirProblem(grid, *a), KodnirProblem(grid0, *a)
            out = damped_newton(prob0, _transfer(u, prob, prob0), tol=tol,
                                max_iterations=max_iterations, memory=1)
            total += out.iterations
            record.append((a[0], a[1], f"{out.status} (base grid)", out.iterations))
            if not out.converged:
                return (None, total, f"no convergence at C={a[0]:.4g}, b_alpha={a[1]:.4g} "
                        f"on the base grid ({out.status}, |F| = {out.residual_norm:.2e})",
                        grid)
            grid, u = grid0, out.z
        prev: tuple[float, np.ndarray] | None = None   # last converged (s, u): secant
        while s < 1.0:
            st = min(1.0, s + ds)
            pc = (a[0] + st * (b[0] - a[0]), a[1] + st * (b[1] - a[1]))
            prob = KodnirProblem(grid, *pc)
            guess = u
            if prev is not None and s > prev[0]:
                if pc[0] >= REGRID_MIN_C and a[0] != b[0]:
                    c_u = a[0] + s * (b[0] - a[0])
                    c_p = a[0] + prev[0] * (b[0] - a[0])
                    cand = _moving_secant(prob, u, c_u, prev[1], c_p,
                                          (st - s) / (s - prev[0]))
                else:
                    cand = u + (st - s) / (s - prev[0]) * (u - prev[1])
                if prob.admissible(cand):
                    guess = cand
            out = damped_newton(prob, guess, tol=tol, max_iterations=max_iterations,
                                   memory=1)
            total += out.iterations
            record.append((pc[0], pc[1], out.status, out.iterations))
            if out.converged:
                prev = (s, u)
                s, u = st, out.z
                ds = min(1.0 - s if s < 1.0 else 1.0, 1.5 * ds) if out.iterations < 12 else ds
                ds = max(ds, min_increment)
                if base_nodes and a[0] != b[0] and _needs_regrid(grid, prob, u):
                    k, h_off = prob.unpack(u)
                    new = _continuation_grid(_outlet_position(h_off),
                                             _inlet_layer(grid.z, k), pc[0], c_target,
                                             grid.z[-1], base_nodes)
                    prob_new = KodnirProblem(new, *pc)
                    out = damped_newton(prob_new, _transfer(u, prob, prob_new), tol=tol,
                                        max_iterations=max_iterations, memory=1)
                    total += out.iterations
                    record.append((pc[0], pc[1], f"{out.status} (new grid, {new.z.size} "
                                   f"nodes)", out.iterations))
                    if out.converged:
                        k_p, h_p = prob.unpack(prev[1])
                        prev = (prev[0], prob_new.pack(np.interp(new.z, grid.z, k_p), h_p))
                        grid, u = new, out.z
            else:
                ds *= 0.5
                if ds < min_increment:
                    return None, total, (f"continuation stalled at C={pc[0]:.4g}, "
                                         f"b_alpha={pc[1]:.4g} ({out.status}, "
                                         f"|F| = {out.residual_norm:.2e})"), grid
    return u, total, "ok", grid


def solve(C: float, b_alpha: float, z_b: float = 20.0, *, nodes: int = 2001,
          coarse_nodes: int = 401, z_min: float | None = None, tol: float = 1e-10,
          max_iterations: int = 60) -> KodnirResult:
    """Solve the dimensionless Kodnir problem (4)-(6) by P1 finite elements.

    Parameters
    ----------
    C : float
        Dimensionless local compliance C = A' B/(E h*), >= 0.
    b_alpha : float
        Dimensionless piezo-viscous parameter B alpha, >= 0.
    z_b : float
        Dimensionless inlet position (> 0); k(z_b) = 0.
    nodes : int
        Nodes of the final grid (80 % of them over the contact and the outlet zone
        [z_min, z_fine], uniform except for refined outlet and inlet bands when C is
        large, the rest graded geometrically up to z_b). The default 2001 solves all 20
        cases of the table of Yachikov & Vostrikov (2015) with z_a and k_max within 0.05 % of a 4001-node solve
        (docs/kodnir.md).
    coarse_nodes : int
        Nodes of the first (continuation) grid.
    z_min : float or None
        Left end of the first grid, <= -1 (default -(2 + 0.1 C + 0.2 b_alpha), moved
        left automatically if the outlet comes close to it).
    tol : float
        Newton tolerance on the max-norm of the scaled residual (units of k).
    max_iterations : int
        Newton iterations per continuation step.

    Returns
    -------
    KodnirResult
        Never raises for non-convergence: ``success=False`` with a message and NaN-free
        arrays of the last grid (empty when nothing converged).

    Raises
    ------
    ValueError
        For C < 0, b_alpha < 0, z_b <= 0, non-integer or too small node counts and
        iteration caps, tol <= 0, z_min > -1 (the message names the argument).

    Notes
    -----
    Strategy: on a coarse grid solve the isoviscous problem (C, 0) directly (if that
    fails, march in C from the rigid problem), then march in b_alpha with adaptive steps;
    then build the final grid around the outlet found, interpolate, and finish with Newton
    at the target (marching again on the fine grid only if the direct step fails).
    """
    _check(C, b_alpha, z_b, nodes, coarse_nodes, tol, max_iterations, z_min)
    C, b_alpha, z_b = float(C), float(b_alpha), float(z_b)
    res = KodnirResult(success=False, status="no_convergence", message="", C=C,
                       b_alpha=b_alpha, z_b=z_b)
    record: list = []
    total = 0
    if C == 0.0 and b_alpha > 0.0:
        # rigid piezo-viscous: by the Barus (Kapitsa) transform the reduced pressure
        # q = (1 - exp(-b_alpha k))/b_alpha is the isoviscous solution (same outlet), so a
        # solution exists only while b_alpha q_max < 1 (docs/theory.md section 14.1)
        iso = solve(0.0, 0.0, z_b, nodes=coarse_nodes, coarse_nodes=coarse_nodes,
                    z_min=z_min, tol=tol, max_iterations=max_iterations)
        if iso.success and b_alpha * iso.k_max >= 1.0:
            res.status = "no_solution"
            res.iterations = iso.iterations
            res.message = (f"no solution: rigid (C = 0) piezo-viscous problem needs "
                           f"b_alpha * q_max < 1, here {b_alpha} * {iso.k_max:.6g} = "
                           f"{b_alpha * iso.k_max:.4g} (Kapitsa transform, docs/theory.md section 14.1)")
            return res
    # heuristic first left end (widened below if the outlet comes close to it)
    # (the outlet lies right of -sqrt(1 + z_b^2), where the film at the inlet would vanish)
    zlo = (max(-(2.0 + 0.1 * C + 0.2 * b_alpha), -1.25 * math.sqrt(1.0 + z_b**2) - 1.0)
           if z_min is None else float(z_min))
    u = None
    msg = ""
    # large C: the march in C doubles from PATH_BREAK on, so that its smallest step
    # (a fraction of a segment) stays a fraction of the current C
    breaks = [(PATH_BREAK * 2.0**j, 0.0) for j in range(64) if PATH_BREAK * 2.0**j < C]
    path = ([(0.0, 0.0)] + breaks + [(C, 0.0), (C, b_alpha)] if C > 0
            else [(0.0, 0.0), (0.0, b_alpha)])
    for _attempt in range(4):
        zf = min(0.5 * z_b, max(2.0, -zlo))
        grid = _Grid.from_nodes(graded_grid(zlo, zf, z_b, coarse_nodes))
        coarse = KodnirProblem(grid, C, b_alpha)
        u, it, msg, grid = _march(grid, _initial_guess(coarse), path, record, tol,
                                  max_iterations, base_nodes=coarse_nodes)
        total += it
        if u is None:
            break
        zlo = float(grid.z[0])
        coarse = KodnirProblem(grid, C, b_alpha)
        k, h_off = coarse.unpack(u)
        za = _outlet_position(h_off)
        pos = np.nonzero(k > 0)[0]
        if pos.size and pos[0] > 3 and za - zlo > 0.2 * max(1.0, abs(za)):
            break
        zlo = 1.5 * min(za, zlo) - 1.0   # outlet too close to the left end: widen
        u = None
        msg = "outlet outside the grid"
    res.iterations = total
    res.continuation = record
    if u is None:
        res.message = f"coarse grid: {msg}"
        return res
    # final grid: uniform over [z_a - margin, z_fine], graded to z_b
    margin = 0.25 + 0.15 * abs(za)
    zf = min(0.5 * z_b, abs(za) + 1.5 + 0.25 * abs(za))
    bands: tuple[tuple[float, float], ...] = ()
    ratio = 1.0
    if C > 0.0:
        # stiff local compliance: the film changes over a length of about eps/C at the
        # outlet and at the inlet (eps = H^3 exp(-b_alpha k) ~ 1 there); refine bands
        # around both so that the layer gets OUTLET_LAYER_CELLS intervals at 2001 nodes
        layer = 1.0 / C
        width = max(OUTLET_BAND_AHEAD, OUTLET_BAND_LAYERS * layer)
        kc = coarse.unpack(u)[0]
        z_in = float(grid.z[np.nonzero(kc > 0.01 * kc.max())[0][-1]])
        bands = ((za - OUTLET_BAND_BEHIND - 0.02 * abs(za), za + width),
                 (z_in - width, z_in + width))
        if bands[1][0] <= bands[0][1]:
            bands = ((bands[0][0], bands[1][1]),)
        dz_ref = (zf - za + margin) / (0.8 * (BAND_REFERENCE_NODES - 1))
        ratio = min(1.0, max(MIN_BAND_RATIO, layer / OUTLET_LAYER_CELLS / dz_ref))

    def newton_on(prob_n: KodnirProblem, u0: np.ndarray, label: str) -> NewtonOutcome:
        nonlocal total
        o = damped_newton(prob_n, u0, tol=tol, max_iterations=max_iterations, memory=1)
        total += o.iterations
        record.append((C, b_alpha, f"{o.status} ({label}, |F| = {o.residual_norm:.1e})",
                       o.iterations))
        return o

    def refine(n: int) -> tuple[KodnirProblem, np.ndarray | None, np.ndarray, str]:
        """Solve on the n-node final-type grid: Newton from the coarse solution; if that
        fails, Newton from the solution on the grid with half as many intervals (grid
        sequencing, recursively); if that fails too, march along ``path`` on this grid.
        Returns (problem, solution or None, last iterate, message)."""
        nonlocal total
        prob_n = KodnirProblem(_Grid.from_nodes(graded_grid(
            za - margin, zf, z_b, n, bands=bands, band_ratio=ratio)), C, b_alpha)
        out_n = newton_on(prob_n, _transfer(u, coarse, prob_n), f"{n}-node grid")
        half = (n - 1) // 2 + 1
        if not out_n.converged and half >= 2 * coarse_nodes:
            prob_h, u_h, _, _ = refine(half)
            if u_h is not None:
                out_n = newton_on(prob_n, _transfer(u_h, prob_h, prob_n),
                                  f"{n}-node grid from {half}")
        if out_n.converged:
            return prob_n, out_n.z, out_n.z, "ok"
        u_n, it, msg_n, _ = _march(prob_n.grid, _initial_guess(prob_n), path, record, tol,
                                   max_iterations)
        total += it
        return prob_n, u_n, out_n.z, msg_n

    prob, ufin, last, msg = refine(nodes)
    res.iterations = total
    if ufin is None:
        res.message = f"final grid: {msg}"
        _finish(res, prob, last)   # last finite iterate, for diagnosis
        res.success = False
        return res
    _finish(res, prob, ufin)
    k = res.k
    pos = np.nonzero(k > PRESSURISED_FLOOR * np.max(k))[0]
    if pos.size == 0 or pos[0] < 2:
        res.status = "outlet_outside_domain"
        res.message = "pressurised zone reaches the left end of the grid"
        return res
    res.success, res.status = True, "converged"
    res.message = (f"converged: {total} Newton iterations, {len(record)} solves, "
                   f"flux {res.flux:.12f}")
    return res


# ----------------------------------------------------------------------------------------
# Dimensional conversions (Yachikov & Vostrikov 2015)
# ----------------------------------------------------------------------------------------
@dataclass(frozen=True)
class KodnirScales:
    """Scales of the Kodnir problem. SI where stated.

    Attributes
    ----------
    h_star : film at the outlet where dp/dx = 0 [m]
    B1 : sqrt(2 h* R), length scale of z [m]
    B : 6 eta0 U_sum B1 / h*^2, pressure scale of k [Pa]
    C : A' B / (E h*), dimensionless compliance [-]
    b_alpha : B alpha [-]
    compliance : A'/E [m/Pa]
    """

    h_star: float
    B1: float
    B: float
    C: float
    b_alpha: float
    compliance: float


def kodnir_scales(h_star: float, radius: float, viscosity: float, sum_speed: float,
                  youngs_modulus: float, load_per_length: float, piezo: float) -> KodnirScales:
    """Scales and parameters of the Kodnir problem from a dimensional line contact.

    Parameters
    ----------
    h_star : film h* where dp/dx = 0 [m] (the paper's h0)
    radius : reduced radius R (the paper's rho_pr) [m]
    viscosity : eta0 [Pa s]
    sum_speed : U_sum = U1 + U2 [m/s]
    youngs_modulus : E of the two equal bodies [Pa] (not E')
    load_per_length : q_H [N/m]
    piezo : Barus alpha [1/Pa]

    Returns
    -------
    KodnirScales
        B1 = sqrt(2 h* R), B = 6 eta0 U_sum B1/h*^2, C = A' B/(E h*) with
        A' = 2.54 b_H, b_H = 1.52 sqrt(q_H R/E), and B alpha.
    """
    from ..physics.elasticity import kodnir_local_coefficient

    h_star = require_positive("h_star", h_star, "m")
    radius = require_positive("radius", radius, "m")
    viscosity = require_positive("viscosity", viscosity, "Pa s")
    sum_speed = require_positive("sum_speed", sum_speed, "m/s")
    piezo = require_nonnegative("piezo", piezo, "1/Pa")
    c = kodnir_local_coefficient(load_per_length, radius, youngs_modulus)
    b1 = math.sqrt(2.0 * h_star * radius)
    b = 6.0 * viscosity * sum_speed * b1 / h_star**2
    return KodnirScales(h_star=h_star, B1=b1, B=b, C=c * b / h_star, b_alpha=b * piezo,
                        compliance=c)


def to_dimensional(result: KodnirResult, scales: KodnirScales) -> dict[str, np.ndarray]:
    """Fields in SI and in the package convention (x along the motion: x = -B1 z).

    Returns ``x`` [m] (ascending), ``pressure`` p = B k [Pa], ``film`` h = h* H [m].
    """
    x = -scales.B1 * result.z[::-1]
    return {"x": x, "pressure": scales.B * result.k[::-1], "film": scales.h_star * result.H[::-1]}


@dataclass(frozen=True)
class KodnirFrictionHeat:
    """Yachikov & Vostrikov (2015) eqs 7-9: rolling_force w_k [N/m], friction_coefficient f [-],
    heat_power Q [W/m] and its two parts [W/m]."""

    rolling_force: float
    friction_coefficient: float
    heat_power: float
    heat_power_rolling: float
    heat_power_sliding: float


def kodnir_friction_heat(result: KodnirResult, h_star: float, B: float, q_H: float,
                         sum_speed: float, sliding_speed: float) -> KodnirFrictionHeat:
    """Friction coefficient and heat power per length in Kodnir form (Yachikov & Vostrikov 2015, eqs 7-9).

    w_k = (B h*/2) I,  f = 2 w_k / q_H,  Q = U_sum (w_k + (U_s/U_sum)^2 (B h*/6) J).

    Parameters
    ----------
    result : successful KodnirResult
    h_star : [m]; B : pressure scale [Pa]; q_H : load per length [N/m];
    sum_speed : U_sum = U1 + U2 [m/s]; sliding_speed : U_s = U1 - U2 [m/s]
    """
    if not result.success:
        raise ValueError(f"result is not a converged solution: {result.message}")
    h_star = require_positive("h_star", h_star, "m")
    B = require_positive("B", B, "Pa")
    q_H = require_positive("q_H", q_H, "N/m")
    sum_speed = require_positive("sum_speed", sum_speed, "m/s")
    sliding_speed = require_finite("sliding_speed", sliding_speed, "m/s")
    wk = 0.5 * B * h_star * result.friction_integral
    q_roll = sum_speed * wk
    q_slide = sum_speed * (sliding_speed / sum_speed) ** 2 * B * h_star / 6.0 * result.couette_integral
    return KodnirFrictionHeat(rolling_force=wk, friction_coefficient=2.0 * wk / q_H,
                              heat_power=q_roll + q_slide, heat_power_rolling=q_roll,
                              heat_power_sliding=q_slide)

"""Point and elliptical contacts: 2D finite elements (scikit-fem, bilinear quads).

Symbols and units: x rolling direction, y across it [m]; p pressure [Pa]; q Kapitsa
reduced pressure [Pa]; h film [m]; h0 rigid offset [m]; a = 1/(2 rx), b = 1/(2 ry)
gap curvatures [1/m]; eta0 [Pa s]; alpha Barus coefficient [1/Pa]; u_m mean speed
[m/s]; dh0/dt approach rate [m/s] (``squeeze_velocity``); F load [N]; E' [Pa].

Grid: a tensor-product grid x (nx,), y (ny,) meshed by ``ElementQuad1`` cells, node
numbering ``j*nx + i`` (x fastest), the layout of
:class:`~bearing_fem.physics.elasticity.HalfSpacePoint`. Fields in the :class:`Result` are
``(ny, nx)`` arrays, ``pressure[j, i]`` at ``(x[i], y[j])``.

Film: h = h0 + x^2/(2 rx) + y^2/(2 ry) + v(x, y) (geometry exact at the quadrature
points, v interpolated from the nodes).

Reynolds (PHYSICS.md 2): div(eps grad p) = u_m d(rho h)/dx + rho dh0/dt. Weak form,
for every test function phi vanishing on the boundary,

    R(phi) = int F . grad phi + int rho (dh0/dt) phi = 0,   F = eps grad p - u_m rho h e_x

(+ an upwinded wedge term in F for elastic scenes, :class:`UpwindFluxModel`).

Two paths (a scene pays only for what it needs):

* **linear** - rigid, incompressible, constant or Barus viscosity, prescribed gap: the
  Kapitsa reduced pressure q = (1 - exp(-alpha p))/alpha obeys the isoviscous equation
  A q = f - s  (A stiffness with h^3/(12 eta0), f = int u_m h dphi/dx, s = int dh0/dt phi),
  one sparse solve (full-Sommerfeld) or a primal-dual active set of sparse solves
  (Reynolds cavitation q >= 0). p = -ln(1 - alpha q)/alpha exists only while
  alpha max q < 1; otherwise status ``no_solution`` and the fields hold q.
  Default rigid grid: sinh-graded (fine at the centre), since no FFT is needed.
* **Newton** - everything else: damped Newton (:func:`bearing_fem.numerics.newton.damped_newton`)
  on the scaled unknowns (p at interior nodes, h0 under load balance) with
  Fischer-Burmeister cavitation rows and a load row, as :mod:`bearing_fem.contacts.line`. The
  Jacobian dR/dp = A_p + A_h C couples the sparse Reynolds blocks with the dense
  half-space compliance C (FFT apply); each Newton step is solved by GMRES with the
  matrix-free Jacobian, preconditioned by a sparse LU of A_p + A_h C_near
  (C truncated to a near-field stencil; nested-dissection order), to an inexact-Newton
  forcing tolerance. Elastic scenes with Barus viscosity take the Poiseuille term from
  the interpolated nodal reduced pressure (``REDUCED_POISEUILLE``). Grid sequencing
  (coarse solve, bilinear interpolation, few fine steps) and continuation in alpha as
  :mod:`bearing_fem.contacts.solver`, warm-started from the interpolated solution on finer grids.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass
from typing import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from skfem import CellBasis, ElementQuad1, MeshQuad

from ..errors import SceneError
from ..numerics.fe import QuadratureOperators, quadrature_operators
from .line import ScaledResidual, fischer_burmeister
from ..numerics.newton import continuation, damped_newton, gmres_right, outcome_message
from ..result import Result
from ..physics.reynolds import FluxModel, UpwindFluxModel

log = logging.getLogger(__name__)

#: Default rigid-scene domain, in units of sqrt(2 rx h0) (x) and sqrt(2 ry h0) (y).
#: PHYSICS.md 5.2: a free inlet needs X <= -30 in 2D for the load within ~0.3%.
RIGID_RANGE_FS = ((-30.0, 30.0), (-30.0, 30.0))
RIGID_RANGE_REYNOLDS = ((-30.0, 8.0), (-30.0, 30.0))
#: Default rigid grid (sinh-graded, nodes per direction).
RIGID_NODES = 161
#: Default elastic grid (uniform, nodes per direction) and domain in Hertz semi-axes.
ELASTIC_NODES = 129
ELASTIC_RANGE = ((-4.5, 1.5), (-3.0, 3.0))
#: Grid sequencing: coarsest grid (nodes per direction) of the elastic Newton solve.
COARSEST_NODES = 65
#: Elastic loaded scenes with zero boundary pressure, a domain symmetric in y and an odd
#: node count across it are solved on the half grid y >= 0 (the rolling contact is
#: symmetric about y = 0; the y = 0 row is a symmetry line, not a boundary) and the
#: result is mirrored to the whole grid, where the residual of the whole discrete system
#: is evaluated and reported. Same equations, half the unknowns. False: whole grid.
Y_SYMMETRY = True
#: Near-field radius (cells) of the compliance block in the preconditioner.
NEAR_FIELD_CELLS = 0
#: Upwinding of the wedge term fades as xi(Pe) = coth(Pe) - 1/Pe with
#: Pe = u_m c dx/(2 eps), c = factor * C_00, C_00 the self-compliance of a grid node
#: (``HalfSpacePoint.kernel()[0, 0]``, ~2.2 dx/E'), so Pe ~ dx^2 and the added diffusion
#: vanishes faster than dx wherever Pe < 1 (0: full first-order upwind everywhere).
#: The Hertz-scale c = 4 a_x/(pi E') used before kept first-order upwinding across the
#: inlet: h_c changed by 3.1% from 129^2 to 257^2 at M = 500, L = 5 (0.6% with C_00).
UPWIND_COMPLIANCE_FACTOR = 1.0
#: Poiseuille term of elastic scenes with Barus (or constant) viscosity:
#: rho h^3/(12 eta0) grad q_h, q_h the bilinear interpolant of the nodal reduced pressure
#: q = (1 - exp(-alpha p))/alpha, instead of eps(p) grad p at the quadrature points. Along
#: an element edge this is the exact integral of eps(p) dp/dx for linear p, whatever the
#: pressure jump; the quadrature of exp(-alpha p) is not once alpha dp >> 1 (the outlet
#: spike: alpha p from ~60 to ~1 across one cell at L = 20), where its flux is not even
#: monotone in the spike pressure and Newton cycled.
REDUCED_POISEUILLE = True
#: Initial Newton regularisation sigma (``damped_newton(initial_shift=...)``) of elastic
#: solves, from the Hertzian start of the coarsest grid and from a solution interpolated
#: to a finer grid. Measured (M, L) = (100, 20) with the pointwise Poiseuille term: with
#: 0 the direct attempt stalled on 65^2 (30 iterations, then 38 of alpha continuation)
#: and again on 129^2 from the 65^2 solution (30 + 59); with 1e-2 it converged directly
#: in 19 and 16. Easy cases: +-1. With REDUCED_POISEUILLE it makes no difference on
#: 257^2 at (100, 10), (20, 20), (100, 20) (+-2 iterations).
START_SHIFT = 1e-2
TRANSFER_SHIFT = 1e-2
#: Finer levels of the grid sequence: the direct Newton attempt from the interpolated
#: solution gets at most this many iterations; if it fails, alpha continuation starts from
#: that same interpolated solution at s = WARM_START_ALPHA (then s -> 1), before the
#: continuation from scratch. Measured with the pointwise Poiseuille term (before
#: REDUCED_POISEUILLE), 65^2 -> 129^2: direct attempts at (M, L) = (20, 20) and (100, 20)
#: cycled at |F| ~ 3e-4 (spike and outlet nodes); s = 0.8 -> 1 converged in 6 + 11 and
#: 13 + 13 iterations, where the continuation from scratch took 56 and 62 after 30 failed
#: direct iterations. With the reduced-pressure Poiseuille term the direct attempts of
#: the circular map need 6-12 iterations per finer level.
TRANSFER_DIRECT_ITERATIONS = 20
WARM_START_ALPHA = 0.8
#: Newton tolerance of the coarser levels of the grid sequence (the finest level uses
#: ``solver.tolerance``). Measured M = 100, L = 10: the first residual on 129^2 / 257^2
#: after interpolation is 1.3e-2 / 5.1e-3 when the coarser level stops at 1e-5 and
#: 1.3e-2 / 4.5e-3 when it stops at 1e-8.
COARSE_TOLERANCE = 1e-5
#: GMRES relative tolerance (floor) and iteration cap of the elastic Newton steps.
GMRES_RTOL = 1e-9
GMRES_MAX_ITERATIONS = 150
#: Inexact Newton (Dembo, Eisenstat & Steihaug 1982): GMRES stops at the relative
#: residual eta_k = min(GMRES_FORCING_MAX, max(GMRES_RTOL, |F_k|_inf)). eta_k = O(|F_k|)
#: keeps the local quadratic convergence, and the Newton stopping test (|F| <= tol) is
#: untouched. GMRES gains about one decade per 5 iterations here, so the early steps
#: save ~25 of ~40 iterations. Measured M = 100, L = 10, 257^2: Newton iterations 25 ->
#: 25, GMRES 701 -> 302, h_c/h_min equal to 11 digits, p_max to 10. 0 disables.
GMRES_FORCING_MAX = 1e-3
#: The linear solve need not be more accurate than the Newton test can see: eta_k is also
#: allowed up to GMRES_TOLERANCE_FRACTION tol / |F_k|_2, so the linear residual left in the
#: step (<= eta_k |F_k|_2, which bounds its max norm) stays below this fraction of the
#: Newton tolerance. Only the last one or two steps are affected (where |F_k| is within a
#: few decades of tol); there GMRES stops after ~10 instead of 30-40 iterations.
GMRES_TOLERANCE_FRACTION = 0.1
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
# setup
# ---------------------------------------------------------------------------------------
@dataclass
class PointSetup:
    """Scales, grid and compliance of a point scene (internal).

    Attributes
    ----------
    grid : PointGrid
    compliance : HalfSpacePoint or None (rigid)
    p_ref, h_ref : float
        Pressure [Pa] and film [m] scales of the unknowns.
    x_unit, y_unit : float
        Length units of the mesh ranges [m].
    h_estimate : float
        Estimated central film [m] (Nijenbanning-Venner-Moes for elastic scenes).
    stab_compliance : float
        Effective compliance of the stabilisation [m/Pa]: the grid-node self-compliance
        C_00 for elastic scenes, 0 when rigid.
    hertz : HertzPoint or None
    """

    grid: PointGrid
    compliance: object
    p_ref: float
    h_ref: float
    x_unit: float
    y_unit: float
    h_estimate: float
    stab_compliance: float
    hertz: object = None


def _nodes(scene, default: int) -> tuple[int, int]:
    n = scene.mesh.nodes
    if n is None:
        return default, default
    return int(n[0]), int(n[1])


def _mirrorable(y_range: tuple[float, float], ny: int) -> bool:
    """True if a uniform grid of ``ny`` nodes on ``y_range`` has a node row at y = 0 and
    is symmetric about it."""
    return y_range[0] == -y_range[1] and ny % 2 == 1


def point_setup(scene, nodes: tuple[int, int] | None = None,
                symmetric: bool = False) -> PointSetup:
    """Reference scales, default grid and compliance of a point scene.

    Rigid scenes: lengths in sqrt(2 rx h0) (x) and sqrt(2 ry h0) (y), sinh-graded grid.
    Elastic scenes: lengths in the Hertz semi-axes a_x, a_y, uniform grid (FFT compliance).
    ``nodes`` overrides ``scene.mesh.nodes`` (grid sequencing). ``symmetric`` (elastic
    scenes under load with a y-symmetric grid, see :func:`_symmetric`): the half grid
    y >= 0 with :class:`~bearing_fem.physics.elasticity.MirroredHalfSpacePoint`; ``nodes`` still
    counts the whole grid.
    """
    from .. import units
    from ..physics.elasticity import HalfSpacePoint, MirroredHalfSpacePoint
    from ..formulas import point_central_film_nvm

    rx, ry = scene.contact.rx, scene.contact.ry
    lub, kin, model = scene.lubricant, scene.kinematics, scene.model
    u_m = kin.mean_speed
    elastic = model.elasticity != "rigid"
    if model.elasticity == "local":
        raise SceneError("model.elasticity = 'local' is defined for line contacts only")
    if elastic and scene.load.force is not None:
        F = scene.load.force
        hz = units.hertz_point(F, rx, ry, scene.e_prime)
        h_est = point_central_film_nvm(F, rx, ry, scene.e_prime, lub.viscosity, u_m,
                                       lub.effective_piezo)
        x_unit, y_unit = hz.a_x, hz.a_y
        p_ref, h_ref = hz.p_h, h_est
        # fully flooded inlet: 4.5 a, or 8 hydrodynamic lengths sqrt(2 rx h) at low load
        inlet = max(4.5, 8.0 * math.sqrt(2 * rx * h_est) / hz.a_x)
        side = max(3.0, 0.5 * inlet)
        xr = scene.mesh.x_range or (-inlet, 1.5)
        yr = scene.mesh.y_range or (-side, side)
        nxy = nodes or _nodes(scene, ELASTIC_NODES)
        x = np.linspace(xr[0] * x_unit, xr[1] * x_unit, nxy[0])
        if _mirrorable(yr, nxy[1]):  # rows mirror each other exactly about y = 0
            y_half = np.linspace(0.0, yr[1] * y_unit, (nxy[1] + 1) // 2)
            y = np.concatenate([-y_half[:0:-1], y_half])
        elif symmetric:
            raise ValueError(f"a symmetric point setup needs mesh.y_range symmetric about 0 "
                             f"and an odd node count across, got {yr} and {nxy[1]}")
        else:
            y = np.linspace(yr[0] * y_unit, yr[1] * y_unit, nxy[1])
        if symmetric:
            grid = PointGrid.tensor(x, y_half, mirror_y=True)
            comp = MirroredHalfSpacePoint(x, y_half, scene.e_prime)
        else:
            grid = PointGrid.tensor(x, y)
            comp = HalfSpacePoint(grid.x, grid.y, scene.e_prime)
        # grid-scale compliance: the displacement of a node per unit pressure on its own
        # cell, C_00 = (2/(pi E')) K(0, 0) ~ 2.2 dx/E' (the line solver's analogue is
        # 4 dx/(pi E')); see UPWIND_COMPLIANCE_FACTOR
        c_stab = float(comp.kernel()[0, 0])
        return PointSetup(grid, comp, p_ref, h_ref, x_unit, y_unit, h_est, c_stab, hz)
    if scene.load.gap is not None:
        h0 = scene.load.gap
    else:
        # rigid under load (start only): pressure scale eta0 u_m Lx/h0^2 on an area
        # Lx Ly, Lx = sqrt(2 rx h0), Ly = sqrt(2 ry h0)  ->  F ~ 2 sqrt(2) eta0 u_m rx
        # sqrt(ry) / sqrt(h0)
        k = 2.0 * math.sqrt(2.0) * lub.viscosity * u_m * rx * math.sqrt(ry)
        h0 = (k / scene.load.force) ** 2
    x_unit, y_unit = math.sqrt(2 * rx * h0), math.sqrt(2 * ry * h0)
    p_ref = lub.viscosity * u_m * x_unit / h0**2
    rng = RIGID_RANGE_FS if model.cavitation == "none" else RIGID_RANGE_REYNOLDS
    xr = scene.mesh.x_range or rng[0]
    yr = scene.mesh.y_range or rng[1]
    nxy = nodes or _nodes(scene, RIGID_NODES)
    uniform = scene.mesh.x_range is not None or scene.mesh.y_range is not None
    if uniform:  # an explicit range asks for a uniform grid (convergence studies)
        gx = np.linspace(xr[0] * x_unit, xr[1] * x_unit, nxy[0])
        gy = np.linspace(yr[0] * y_unit, yr[1] * y_unit, nxy[1])
    else:
        gx = graded_coordinates(xr[0], xr[1], nxy[0], x_unit, stretch=1.5)
        gy = graded_coordinates(yr[0], yr[1], nxy[1], y_unit, stretch=1.5)
    grid = PointGrid.tensor(gx, gy)
    return PointSetup(grid, None, p_ref, h0, x_unit, y_unit, h0, 0.0, None)


def _is_linear(scene) -> bool:
    m, lub = scene.model, scene.lubricant
    return (m.elasticity == "rigid" and lub.density == "incompressible"
            and lub.viscosity_law in ("constant", "barus") and scene.load.gap is not None)


def _boundary_values(grid: PointGrid, boundary_pressure) -> np.ndarray:
    """Flat nodal Dirichlet pressure [Pa] (zero off the boundary)."""
    out = np.zeros(grid.size)
    if boundary_pressure is None:
        return out
    mask = grid.boundary_mask()
    if callable(boundary_pressure):
        X, Y = grid.node_coordinates()
        vals = np.asarray(boundary_pressure(X[mask], Y[mask]), dtype=float)
        out[mask] = np.broadcast_to(vals, (int(mask.sum()),))
    else:
        arr = np.asarray(boundary_pressure, dtype=float)
        if arr.size != grid.size:
            raise ValueError(f"boundary_pressure must be a callable (x [m], y [m]) -> p [Pa] "
                             f"or nodal values of shape {grid.shape}, got shape {arr.shape}")
        out[mask] = arr.ravel()[mask]
    if not np.all(np.isfinite(out)):
        raise ValueError("boundary_pressure must be finite (Pa) on the boundary nodes")
    return out


# ---------------------------------------------------------------------------------------
# linear rigid path
# ---------------------------------------------------------------------------------------
def reduced_pressure_solve(grid: PointGrid, h0: float, rx: float, ry: float,
                           mean_speed: float, viscosity: float, q_bc: np.ndarray,
                           cavitation: str, squeeze_velocity: float = 0.0
                           ) -> tuple[np.ndarray, int, np.ndarray]:
    """Rigid isoviscous Reynolds problem for the reduced pressure q [Pa].

    Solves int h^3/(12 eta0) grad q . grad phi = int u_m h dphi/dx - int (dh0/dt) phi
    with q = q_bc on the boundary: one sparse solve (``cavitation = "none"``) or a
    primal-dual active-set sequence (``"reynolds"``: q >= 0, A q - f >= 0, complementary).

    Parameters
    ----------
    grid : PointGrid
    h0 : float
        Central gap [m].
    rx, ry : float
        Reduced radii [m].
    mean_speed : float
        u_m [m/s].
    viscosity : float
        eta0 [Pa s].
    q_bc : ndarray
        Flat nodal Dirichlet data [Pa] (only boundary entries are used).
    cavitation : {"none", "reynolds"}
    squeeze_velocity : float
        dh0/dt [m/s] (< 0: approach, positive squeeze pressure).

    Returns
    -------
    q : ndarray (flat, Pa); linear_solves : int; active : bool ndarray (cavitated nodes)
    """
    ops = grid.ops
    xq, yq = ops.points
    h = h0 + xq**2 / (2 * rx) + yq**2 / (2 * ry)
    eps = h**3 / (12.0 * viscosity)
    zero = np.zeros_like(h)
    a = (ops.flux_jacobian(0, zero, (eps, zero)) + ops.flux_jacobian(1, zero, (zero, eps))).tocsr()
    f = ops.weak_divergence(mean_speed * h, zero)
    if squeeze_velocity:
        f = f - ops.value.T @ (ops.weights * squeeze_velocity)
    from .solver import active_set_solve

    free = np.nonzero(~grid.boundary_mask())[0]
    return active_set_solve(a, f, np.where(grid.boundary_mask(), q_bc, 0.0), free,
                            cavitation)


def _solve_linear(scene, setup: PointSetup, p_bc: np.ndarray, squeeze_velocity: float,
                  t0: float) -> Result:
    from ..analytic import reduced_from_barus

    lub = scene.lubricant
    alpha = lub.effective_piezo
    h0 = scene.load.gap
    grid = setup.grid
    q_bc = reduced_from_barus(p_bc, alpha) if alpha > 0 else p_bc
    q, solves, active = reduced_pressure_solve(
        grid, h0, scene.contact.rx, scene.contact.ry, scene.kinematics.mean_speed,
        lub.viscosity, q_bc, scene.model.cavitation, squeeze_velocity)
    from .solver import pressure_from_reduced

    problem = PointProblem(grid, _flux(scene, setup), scene.contact.rx, scene.contact.ry,
                           None, scene.model.cavitation, None, h0, setup.p_ref, setup.h_ref,
                           lub.viscosity, p_bc, squeeze_velocity)
    status, field, msg = pressure_from_reduced(q, alpha, solves,
                                               f", {grid.x.size} x {grid.y.size} nodes")
    return _finish(scene, setup, problem, field, h0, status, msg, t0, linear_solves=solves,
                   post=status == "linear", cavitated=active)


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


class _FreePattern:
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


# ---------------------------------------------------------------------------------------
# nonlinear problem
# ---------------------------------------------------------------------------------------
class PointProblem(ScaledResidual):
    """Scaled nonlinear system of one point-contact scene (a NonlinearProblem).

    Unknowns z: p/p_ref at the interior nodes, then h0/h_ref under load balance.
    Rows: Reynolds rows r_i = R_i / (d_i eps0_i p_ref) (d_i eps0_i the isoviscous
    stiffness diagonal), wrapped by Fischer-Burmeister for Reynolds cavitation; load row
    (int p - F)/F.

    Parameters
    ----------
    grid : PointGrid
    flux : FluxModel
    rx, ry : float
        Reduced radii [m].
    compliance : HalfSpacePoint or None
        None: rigid.
    cavitation : {"reynolds", "none"}
    load : float or None
        F [N]; None: h0 prescribed (``gap``).
    gap : float or None
        h0 [m].
    p_ref, h_ref : float
        Scales [Pa], [m].
    viscosity0 : float
        eta0 [Pa s] (row scaling).
    p_bc : ndarray
        Flat Dirichlet pressures [Pa].
    squeeze_velocity : float
        dh0/dt [m/s].
    near_field_cells : int
        Compliance stencil radius of the preconditioner.
    tolerance : float or None
        Newton tolerance on max|F| the problem is solved to (scaled, -); bounds the GMRES
        accuracy asked for (see ``GMRES_TOLERANCE_FRACTION``). None: no such bound.
    """

    def __init__(self, grid: PointGrid, flux: FluxModel, rx: float, ry: float, compliance,
                 cavitation: str, load: float | None, gap: float | None, p_ref: float,
                 h_ref: float, viscosity0: float, p_bc: np.ndarray | None = None,
                 squeeze_velocity: float = 0.0,
                 near_field_cells: int = NEAR_FIELD_CELLS,
                 tolerance: float | None = None) -> None:
        self.grid, self.flux = grid, flux
        self.ops = grid.ops
        self.tolerance = tolerance
        self.rx, self.ry = rx, ry
        self.compliance = compliance
        self.cavitation = cavitation
        self.load, self.gap = load, gap
        self.p_ref, self.h_ref = p_ref, h_ref
        self.eta0 = viscosity0
        self.squeeze = float(squeeze_velocity)
        n = grid.size
        self.free = np.nonzero(~grid.boundary_mask())[0]
        self.p_bc = np.zeros(n) if p_bc is None else np.asarray(p_bc, dtype=float).ravel()
        ops = grid.ops
        xq, yq = ops.points
        self.g_q = xq**2 / (2 * rx) + yq**2 / (2 * ry)
        self.gx_q = xq / rx
        self.gy_q = yq / ry
        X, Y = grid.node_coordinates()
        self.g_nodes = X**2 / (2 * rx) + Y**2 / (2 * ry)
        # a mirrored half grid stands for the whole one: the load integral counts both
        # halves, and a symmetry-line row (half a test function) is weighted by 2 so that
        # every scaled row equals the whole grid's row of the same node
        self.mass = ops.mass * (2.0 if grid.mirror_y else 1.0)
        weight = np.ones(n)
        if grid.mirror_y:
            weight[:grid.x.size] = 2.0
        self._row_weight = weight[self.free]
        self.has_h0 = load is not None
        self.n_unknowns = self.free.size + (1 if self.has_h0 else 0)
        # Q1 stiffness diagonal / eps on the local cell (Laplacian): (4/3)(hy/hx + hx/hy)
        hx = np.gradient(grid.x)
        hy = np.gradient(grid.y)
        hxx, hyy = np.meshgrid(hx, hy)
        self._stiff_diag = ((4.0 / 3.0) * (hyy / hxx + hxx / hyy)).ravel()
        self.near_field_cells = near_field_cells
        self._row_scale = None
        self._pattern = None
        self._fields_cache = None
        self.linear_iterations = 0

    # -- unknowns <-> fields -------------------------------------------------------------
    def unpack(self, z: np.ndarray) -> tuple[np.ndarray, float]:
        p = self.p_bc.copy()
        p[self.free] = z[: self.free.size] * self.p_ref
        h0 = z[-1] * self.h_ref if self.has_h0 else self.gap
        return p, float(h0)

    def pack(self, p: np.ndarray, h0: float) -> np.ndarray:
        z = np.ravel(p)[self.free] / self.p_ref
        return np.append(z, h0 / self.h_ref) if self.has_h0 else z

    def displacement(self, p: np.ndarray) -> np.ndarray:
        if self.compliance is None:
            return np.zeros_like(p)
        return self.compliance.apply(p)

    def film_nodes(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Nodal film [m] (flat)."""
        return h0 + self.g_nodes + self.displacement(p)

    def fields_q(self, p: np.ndarray, h0: float, v: np.ndarray | None = None):
        """p, h, (px, py), (hx, hy) at the quadrature points.

        Without ``v`` the fields of the last (p, h0) are kept: a Newton iteration asks for
        the same iterate's fields in the admissibility test, the residual and the
        Jacobian (each costs an FFT product and five sparse interpolations). The
        returned arrays are shared with the cache and must not be modified.
        """
        cached = self._fields_cache if v is None else None
        if cached is not None and cached[1] == h0 and np.array_equal(cached[0], p):
            return cached[2]
        ops = self.grid.ops
        displacement = self.displacement(p) if v is None else v
        h = h0 + self.g_q + ops.value @ displacement
        gh = (self.gx_q + ops.grad[0] @ displacement, self.gy_q + ops.grad[1] @ displacement)
        gp = (ops.grad[0] @ p, ops.grad[1] @ p)
        out = (ops.value @ p, h, gp, gh)
        if v is None:
            self._fields_cache = (np.array(p, dtype=float, copy=True), float(h0), out)
        return out

    # -- NonlinearProblem ------------------------------------------------------------------
    def prepare(self, z: np.ndarray) -> None:
        p, h0 = self.unpack(z)
        h = np.maximum(self.film_nodes(p, h0), 1e-3 * self.h_ref)
        eps0 = h**3 / (12.0 * self.eta0)
        self._row_scale = (1.0 / (self._stiff_diag * eps0 * self.p_ref))[self.free] \
            * self._row_weight

    def reynolds_residual(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Nodal weak residual R_i [m^3/s] (all nodes)."""
        pq, h, gp, gh = self.fields_q(p, h0)
        ops = self.grid.ops
        if self._reduced:
            fl = self.flux.flux(pq, h, gp, gh, ops.element_size, gq=self._grad_reduced(p))
        else:
            fl = self.flux.flux(pq, h, gp, gh, ops.element_size)
        r = ops.weak_divergence(*fl)
        if self.squeeze:
            rho = self.flux.density(pq)
            r = r + ops.value.T @ (ops.weights * rho * self.squeeze)
        return r

    def _blocks(self, z: np.ndarray):
        """Sparse A_p, A_h (all nodes), dR/dh0 (all nodes), residual, row factors."""
        p, h0 = self.unpack(z)
        ops = self.grid.ops
        pq, h, gp, gh = self.fields_q(p, h0)
        asm = ops.assembler  # element-wise assembly on one fixed pattern
        if self._reduced:
            fl, dp, dh, dgp, dgh, dgq = self.flux.flux_and_derivatives_reduced(
                pq, h, gp, gh, ops.element_size, self._grad_reduced(p))
            zero = np.zeros_like(pq)
            fluidity = self.flux.fluidity(p)  # d grad q_h / d p_j = q'(p_j) grad phi_j
            extra = [(d, zero, (dgq[0][d], dgq[1][d]), fluidity) for d in range(2)]
        else:
            fl, dp, dh, dgp, dgh = self.flux.flux_and_derivatives(pq, h, gp, gh,
                                                                ops.element_size)
            extra = []
        a_p = asm.flux_jacobian_sum([(d, dp[d], (dgp[0][d], dgp[1][d])) for d in range(2)]
                                    + extra)
        a_h = asm.flux_jacobian_sum([(d, dh[d], (dgh[0][d], dgh[1][d])) for d in range(2)])
        res = ops.weak_divergence(*fl)
        drdh0 = ops.grad[0].T @ (ops.weights * dh[0]) + ops.grad[1].T @ (ops.weights * dh[1])
        if self.squeeze:
            res = res + ops.value.T @ (ops.weights * self.flux.density(pq) * self.squeeze)
            if self.flux.density(np.array([1e8]))[0] != 1.0:  # compressible: d rho/dp term
                dp_rho = np.imag(self.flux.density(pq + 1j * 1e-20 * max(self.p_ref, 1.0))) \
                    / (1e-20 * max(self.p_ref, 1.0))
                a_p = a_p + ops.value.T @ sp.diags(ops.weights * dp_rho * self.squeeze) \
                    @ ops.value
        rows = self.free
        s = self._row_scale
        if self.cavitation == "reynolds":
            _, da, db = fischer_burmeister(p[rows] / self.p_ref, res[rows] * s)
            row_factor = db * s
        else:
            da = None
            row_factor = s
        return a_p.tocsr(), a_h.tocsr(), drdh0, row_factor, da

    def jacobian_sparse(self, z: np.ndarray, near: bool = True) -> sp.csc_matrix:
        """Scaled sparse Jacobian (rigid: exact) or its near-field approximation."""
        a_p, a_h, drdh0, row_factor, da = self._blocks(z)
        return self._assemble(a_p, a_h, drdh0, row_factor, da, near)

    def _assemble(self, a_p, a_h, drdh0, row_factor, da, near: bool) -> sp.csc_matrix:
        rows = self.free
        m = a_p
        if self.compliance is not None and near:
            m = (a_p + a_h @ self.compliance.near_field(self.near_field_cells)).tocsr()
        j = sp.diags(row_factor * self.p_ref) @ m[rows][:, rows]
        if da is not None:
            j = j + sp.diags(da)
        if not self.has_h0:
            return j.tocsc()
        col = (drdh0[rows] * row_factor * self.h_ref)[:, None]
        load_row = (self.mass[rows] * self.p_ref / self.load)[None, :]
        return sp.bmat([[j, sp.csr_matrix(col)], [sp.csr_matrix(load_row), None]],
                       format="csc")

    def _free_pattern(self) -> _FreePattern:
        """Free-node block of the assembler pattern in nested-dissection order (cached)."""
        if self._pattern is None:
            self._pattern = _FreePattern(self.grid, self.free)
        return self._pattern

    def _preconditioner_lu(self, a_p: sp.spmatrix, a_h: sp.spmatrix, scale: np.ndarray,
                           diag: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
        """Sparse LU of diag(scale) (A_p + A_h C_near)[free, free] + diag(diag).

        Returns the solve, a function of free-node vectors. A_p, A_h on the assembler's
        pattern and C_near = near_field(0) (diagonal) take the fast path: the scaled
        free-free block is gathered by a cached index map in nested-dissection order
        (SuperLU, no column reordering). Anything else (a subclass adding terms off the
        pattern, a wider near field) is assembled by sparse products and reordered by
        SuperLU's MMD on A^T + A.
        """
        asm = self.grid.ops.assembler
        fast = self.compliance is None or self.near_field_cells == 0
        ap = asm.pattern_data(a_p) if fast else None
        ah = asm.pattern_data(a_h) if fast and self.compliance is not None else None
        if ap is not None and (self.compliance is None or ah is not None):
            m = ap if self.compliance is None else ap + self.compliance.kernel()[0, 0] * ah
            pat = self._free_pattern()
            lu = pat.factor(m, scale, diag)
            perm, inv = pat.perm, pat.inverse

            def solve(r: np.ndarray) -> np.ndarray:
                return lu.solve(np.ascontiguousarray(r[perm]))[inv]

            return solve
        return self._preconditioner_lu_general(a_p, a_h, scale, diag)

    def _preconditioner_lu_general(self, a_p: sp.spmatrix, a_h: sp.spmatrix,
                                   scale: np.ndarray, diag: np.ndarray
                                   ) -> Callable[[np.ndarray], np.ndarray]:
        """:meth:`_preconditioner_lu` by sparse products, any patterns and near field."""
        rows = self.free
        m = a_p
        if self.compliance is not None:
            m = a_p + a_h @ self.compliance.near_field(self.near_field_cells)
        jpp = sp.diags(scale) @ sp.csr_matrix(m)[rows][:, rows]
        jpp = (jpp + sp.diags(diag)).tocsc()
        return spla.splu(jpp, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=LU_PIVOT_THRESHOLD,
                         options={"SymmetricMode": True}).solve

    def newton_step(self, z: np.ndarray, shift: float = 0.0) -> np.ndarray:
        """Solve (J + shift D) dz = -F; D = identity on the pressure unknowns.

        Rigid: sparse direct. Elastic: GMRES on the matrix-free Jacobian (sparse blocks
        plus A_h (C x) by FFT), preconditioned by a sparse LU of the near-field Jacobian,
        to the relative residual eta = min(GMRES_FORCING_MAX, max(GMRES_RTOL, |F|_inf,
        GMRES_TOLERANCE_FRACTION tol / |F|_2)) (inexact Newton).
        """
        f = self.residual(z)
        npf = self.free.size
        a_p, a_h, drdh0, row_factor, da = self._blocks(z)
        rows = self.free
        scale = row_factor * self.p_ref
        col = drdh0[rows] * row_factor * self.h_ref
        load_row = self.mass[rows] * self.p_ref / self.load if self.has_h0 else None
        diag = (da if da is not None else 0.0) + shift
        lu_solve = self._preconditioner_lu(a_p, a_h, scale, np.broadcast_to(diag, (npf,)))
        if self.has_h0:  # bordered system by the Schur complement of the (h0, load) pair
            w = lu_solve(col)
            schur = float(load_row @ w)

        def precond(r: np.ndarray) -> np.ndarray:
            r = np.ravel(r)
            y = lu_solve(r[:npf])
            if not self.has_h0:
                return y
            xh = (float(load_row @ y) - r[npf]) / schur
            return np.append(y - w * xh, xh)

        if self.compliance is None:
            return precond(-f)
        n = self.grid.size
        comp = self.compliance

        def matvec(u: np.ndarray) -> np.ndarray:
            u = np.ravel(u)
            full = np.zeros(n)
            full[rows] = u[:npf]
            v = a_p @ full + a_h @ comp.apply(full)
            out = scale * v[rows] + diag * u[:npf]
            if self.has_h0:
                out = out + col * u[npf]
                return np.append(out, load_row @ u[:npf])
            return out

        rtol = GMRES_RTOL
        if GMRES_FORCING_MAX > GMRES_RTOL:  # inexact Newton, see GMRES_FORCING_MAX
            floor = max(GMRES_RTOL, float(np.max(np.abs(f))))
            if self.tolerance is not None:
                floor = max(floor, GMRES_TOLERANCE_FRACTION * self.tolerance
                            / max(float(np.linalg.norm(f)), 1e-300))
            rtol = min(GMRES_FORCING_MAX, floor)
        dz, its, rel = gmres_right(matvec, precond, -f, rtol=rtol,
                                   max_iterations=GMRES_MAX_ITERATIONS)
        self.linear_iterations += its
        log.debug("gmres: %d iterations, relative residual %.2e", its, rel)
        if not np.all(np.isfinite(dz)):
            raise RuntimeError("gmres produced non-finite values")
        return dz


def _flux(scene, setup: PointSetup, piezo_scale: float = 1.0) -> FluxModel:
    if setup.compliance is not None:
        lub = scene.lubricant
        reduced = None
        if REDUCED_POISEUILLE and (lub.viscosity_law == "barus" or lub.effective_piezo == 0.0):
            reduced = lub.effective_piezo * piezo_scale
        return UpwindFluxModel.elastic(lub, scene.kinematics.mean_speed,
                                       UPWIND_COMPLIANCE_FACTOR * setup.stab_compliance,
                                       piezo_scale=piezo_scale, reduced_alpha=reduced)
    return FluxModel.from_lubricant(scene.lubricant, scene.kinematics.mean_speed,
                                    compliance=setup.stab_compliance, piezo_scale=piezo_scale)


def _make_problem(scene, setup: PointSetup, p_bc, squeeze_velocity: float,
                  piezo_scale: float = 1.0, tolerance: float | None = None) -> PointProblem:
    return PointProblem(setup.grid, _flux(scene, setup, piezo_scale), scene.contact.rx,
                        scene.contact.ry, setup.compliance, scene.model.cavitation,
                        scene.load.force, scene.load.gap, setup.p_ref, setup.h_ref,
                        scene.lubricant.viscosity, p_bc, squeeze_velocity,
                        tolerance=tolerance)


def _initial_guess(scene, setup: PointSetup, problem: PointProblem) -> np.ndarray:
    """Hertzian pressure (elastic, loaded) or the rigid isoviscous solution."""
    grid = setup.grid
    X, Y = grid.node_coordinates()
    if scene.load.force is not None and setup.compliance is not None:
        hz = setup.hertz
        p = hz.p_h * np.sqrt(np.maximum(1.0 - (X / hz.a_x) ** 2 - (Y / hz.a_y) ** 2, 0.0))
        p = p * scene.load.force / (problem.mass @ p)
        v0 = float(grid.interpolate(problem.displacement(p), np.array([0.0]),
                                    np.array([0.0]))[0])
        return problem.pack(p, setup.h_estimate - v0)
    return _rigid_start(scene, setup, problem,
                       scene.load.gap if scene.load.gap is not None else setup.h_ref)


def _rigid_start(scene, setup: PointSetup, problem: PointProblem, h0: float) -> np.ndarray:
    """Isoviscous rigid (Kapitsa-type) solution at the offset h0 [m], with the
    problem's Dirichlet data and squeeze velocity, as packed unknowns of ``problem``."""
    q, _, _ = reduced_pressure_solve(setup.grid, h0, scene.contact.rx, scene.contact.ry,
                                     scene.kinematics.mean_speed, scene.lubricant.viscosity,
                                     problem.p_bc, scene.model.cavitation, problem.squeeze)
    if scene.model.cavitation == "reynolds":
        q = np.maximum(q, 0.0)
    return problem.pack(q, h0)


def _attempt(scene, setup, p_bc, squeeze, z0, max_iterations, initial_shift: float = 0.0,
             tol: float | None = None, transferred: bool = False):
    """Damped Newton on one grid, with alpha continuation as the fallback.

    1. Direct Newton from ``z0`` (at most ``TRANSFER_DIRECT_ITERATIONS`` iterations when
       ``z0`` was interpolated from a coarser grid).
    2. Only for an interpolated ``z0``: warm continuation in alpha, s = WARM_START_ALPHA
       -> 1, starting from ``z0`` itself.
    3. Continuation in alpha from the Hertzian (or rigid) initial guess at s = 0.

    ``tol`` (default ``scene.solver.tolerance``) is the Newton tolerance of this level;
    intermediate continuation steps stop at max(tol, COARSE_TOLERANCE).

    Returns
    -------
    z, status, iterations, history, steps [(s, status, iterations)], problem (s = 1),
    linear (GMRES) iterations of all solves
    """
    sol = scene.solver
    tol = sol.tolerance if tol is None else tol
    problems = []

    def make(s: float = 1.0) -> PointProblem:
        problems.append(_make_problem(scene, setup, p_bc, squeeze, piezo_scale=s,
                                      tolerance=tol))
        return problems[-1]

    def linear() -> int:
        return sum(p.linear_iterations for p in problems)

    problem = make()
    direct_cap = min(max_iterations, TRANSFER_DIRECT_ITERATIONS) if transferred \
        else max_iterations
    out = damped_newton(problem, z0, tol=tol, max_iterations=direct_cap,
                        initial_shift=initial_shift)
    history = list(out.history)
    steps = [(1.0, out.status, out.iterations)]
    iterations = out.iterations
    if out.converged or not sol.continuation or scene.lubricant.effective_piezo == 0.0:
        return out.z, out.status, iterations, history, steps, problem, linear()
    starts = [(WARM_START_ALPHA, z0)] if transferred else []
    starts.append((0.0, None))
    for s_start, z_start in starts:
        log.info("Newton %s after %d iterations; continuing in alpha from s = %g",
                 out.status, iterations, s_start)
        if z_start is None:
            z_start = _initial_guess(scene, setup, problem)
        cont = continuation(make, z_start, s_start=s_start,
                            first_step=0.25 if s_start == 0.0 else 1.0 - s_start,
                            tol=tol, intermediate_tol=max(tol, COARSE_TOLERANCE),
                            max_iterations=max_iterations, initial_shift=initial_shift)
        iterations += cont.iterations
        steps += cont.steps
        history += list(cont.last.history)
        if cont.parameter >= 1.0 and cont.status == "converged":
            return cont.z, "converged", iterations, history, steps, problem, linear()
    return out.z, out.status, iterations, history, steps, problem, linear()


def _levels(n: tuple[int, int]) -> list[tuple[int, int]]:
    """Grid sequence halving the spacing each level, coarsest >= COARSEST_NODES."""
    levels = [n]
    while all((m - 1) % 2 == 0 and (m - 1) // 2 + 1 >= COARSEST_NODES for m in levels[-1]):
        levels.append(tuple((m - 1) // 2 + 1 for m in levels[-1]))
    return levels[::-1]


def _transfer(z: np.ndarray, coarse: PointProblem, fine: PointProblem) -> np.ndarray:
    """Bilinear interpolation of a coarse solution to a finer grid (same central film)."""
    p_c, h0_c = coarse.unpack(z)
    X, Y = fine.grid.node_coordinates()
    p_f = coarse.grid.interpolate(p_c, X, Y)
    p_f[~np.isin(np.arange(p_f.size), fine.free)] = fine.p_bc[
        ~np.isin(np.arange(p_f.size), fine.free)]
    o = np.array([0.0])
    hc = float(coarse.grid.interpolate(coarse.film_nodes(p_c, h0_c), o, o)[0])
    if fine.has_h0:
        h0_f = hc - float(fine.grid.interpolate(fine.g_nodes + fine.displacement(p_f), o, o)[0])
    else:
        h0_f = h0_c
    return fine.pack(p_f, h0_f)


def _symmetric(scene, setup: PointSetup, boundary_pressure) -> bool:
    """True if the elastic Newton solve may run on the half grid y >= 0 (``Y_SYMMETRY``):
    a loaded elastic scene with zero boundary pressure on a grid whose rows mirror each
    other about y = 0. The contact geometry (x^2/(2 rx) + y^2/(2 ry)), rolling along x and
    the half-space kernel are even in y, so the discrete problem maps even pressures to
    even residuals."""
    y = setup.grid.y
    return (Y_SYMMETRY and setup.compliance is not None and scene.load.force is not None
            and boundary_pressure is None and y.size % 2 == 1
            and np.array_equal(y, -y[::-1]))


def _solve_newton(scene, setup: PointSetup, p_bc_fn, squeeze: float, t0: float,
                  max_iterations: int | None) -> Result:
    sol = scene.solver
    maxit = max_iterations or sol.max_iterations
    n_fine = (setup.grid.x.size, setup.grid.y.size)
    levels = _levels(n_fine) if setup.compliance is not None else [n_fine]
    symmetric = _symmetric(scene, setup, p_bc_fn)
    # the setup the Newton iterations run on at the finest level (whole or half grid)
    work = point_setup(scene, nodes=n_fine, symmetric=True) if symmetric else setup
    iterations, history, steps = 0, [], []
    z, prev, status = None, None, "max_iterations"
    linear_its = 0
    problem = None
    for n in levels:
        lvl = work if n == n_fine else point_setup(scene, nodes=n, symmetric=symmetric)
        p_bc = _boundary_values(lvl.grid, p_bc_fn)
        problem = _make_problem(scene, lvl, p_bc, squeeze)
        if z is None:
            z0, shift = _initial_guess(scene, lvl, problem), START_SHIFT
        else:
            z0, shift = _transfer(z, prev, problem), TRANSFER_SHIFT
        if setup.compliance is None:
            shift = 0.0  # rigid Newton scenes: plain Newton as validated
        # coarse levels only provide a start: the interpolation to the next grid leaves a
        # residual ~1e-3..1e-2 there, so converging them below COARSE_TOLERANCE buys
        # nothing; the finest level converges to the scene's tolerance
        tol = sol.tolerance if n == n_fine else max(sol.tolerance, COARSE_TOLERANCE)
        z, status, it, hist, st, problem, lin = _attempt(
            scene, lvl, p_bc, squeeze, z0, maxit, initial_shift=shift, tol=tol,
            transferred=prev is not None)
        linear_its += lin
        iterations += it
        history += hist
        steps += [(s, f"{stat} ({n[0]}x{n[1]} nodes)", i) for s, stat, i in st]
        prev = problem
        if status != "converged":
            break
    if status != "converged" and len(levels) > 1 and problem.grid.size != work.grid.size:
        p_bc = _boundary_values(work.grid, p_bc_fn)
        problem = _make_problem(scene, work, p_bc, squeeze)
        z, status, it, hist, st, problem, lin = _attempt(
            scene, work, p_bc, squeeze, _initial_guess(scene, work, problem), maxit,
            initial_shift=START_SHIFT if work.compliance is not None else 0.0)
        linear_its += lin
        iterations += it
        history += hist
        steps += [(s, f"{stat} ({n_fine[0]}x{n_fine[1]} nodes)", i) for s, stat, i in st]
    if symmetric:  # mirror to the whole grid; the residual below is the whole system's
        p_half, h0 = problem.unpack(z)
        whole = _make_problem(scene, setup, _boundary_values(setup.grid, p_bc_fn), squeeze)
        z = whole.pack(problem.compliance.mirror(p_half).ravel(), h0)
        problem = whole
    p, h0 = problem.unpack(z)
    problem.prepare(z)
    resid = float(np.max(np.abs(problem.residual(z))))
    n_cont = sum(1 for s in steps if s[0] < 1.0)
    note = f", continuation in alpha ({n_cont} steps)" if n_cont else ""
    half = ", each solved on its half y >= 0 by symmetry" if symmetric else ""
    msg = outcome_message(status, iterations, resid, sol.tolerance,
                          detail=f" (grids {[f'{a}x{b}' for a, b in levels]}{half}{note})",
                          cap=maxit)
    if scene.model.cavitation == "reynolds":
        p = np.maximum(p, 0.0)
    res = _finish(scene, setup, problem, p, h0, status, msg, t0, iterations=iterations,
                  history=history, continuation_steps=steps)
    res.extra_fields = dict(res.extra_fields)
    res.quantities["gmres_iterations"] = float(linear_its)
    return res


# ---------------------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------------------
def solve_point(scene, *, boundary_pressure: Callable | np.ndarray | None = None,
                squeeze_velocity: float = 0.0, max_iterations: int | None = None) -> Result:
    """Solve a point/elliptical contact scene.

    Parameters
    ----------
    scene : Scene
        ``contact.kind == "point"``.
    boundary_pressure : callable or ndarray, optional
        Dirichlet pressure on the domain boundary [Pa]: a callable ``(x [m], y [m]) -> p``
        on flat arrays, or nodal values of shape (ny, nx) (only boundary nodes are used).
        Default 0. The analytic-oracle tests impose the exact Kapitsa solution this way.
    squeeze_velocity : float
        Approach rate dh0/dt [m/s] (negative: the surfaces approach, positive squeeze
        pressure). A scene has no key for it yet (proposed: ``[kinematics] squeeze``).
    max_iterations : int, optional
        Overrides ``scene.solver.max_iterations`` (Newton iterations per attempt).

    Returns
    -------
    Result
        ``x`` (nx,), ``y`` (ny,) [m]; ``pressure`` [Pa] and ``film`` [m] as (ny, nx)
        arrays. Never raises for non-convergence or non-existence (see ``status``).
    """
    from ..scene import Scene

    if not isinstance(scene, Scene):
        raise SceneError(f"solve_point() needs a Scene, got {type(scene).__name__}")
    if scene.contact.kind != "point":
        raise SceneError(f"solve_point() needs contact.kind = 'point', got "
                         f"{scene.contact.kind!r}")
    sq = float(squeeze_velocity)
    if not math.isfinite(sq):
        raise ValueError(f"squeeze_velocity must be finite (m/s), got {squeeze_velocity!r}")
    if scene.model.elasticity == "half-space" and scene.load.gap is not None:
        # elastic with a prescribed rigid offset: no load balance, grid in sqrt(2 r h0)
        from .transient import solve_elastic_gap

        return solve_elastic_gap(scene, squeeze_velocity=sq,
                                 boundary_pressure=boundary_pressure,
                                 max_iterations=max_iterations)
    t0 = time.perf_counter()
    setup = point_setup(scene)
    if _is_linear(scene):
        return _solve_linear(scene, setup, _boundary_values(setup.grid, boundary_pressure),
                             sq, t0)
    return _solve_newton(scene, setup, boundary_pressure, sq, t0, max_iterations)


@dataclass
class SqueezeSeries:
    """Rigid transient squeeze series h0(t) = h0 (1 + eps cos(omega t)) (PHYSICS.md 2, 5.1).

    Attributes
    ----------
    times : ndarray
        t [s].
    gap : ndarray
        h0(t) [m].
    squeeze_velocity : ndarray
        dh0/dt = -h0 eps omega sin(omega t) [m/s].
    p_max : ndarray
        Maximum pressure of each step [Pa] (``inf`` for a step without solution).
    results : list of Result
        One quasi-steady solve per step, all on the same grid.
    """

    times: np.ndarray
    gap: np.ndarray
    squeeze_velocity: np.ndarray
    p_max: np.ndarray
    results: list

    @property
    def statuses(self) -> list[str]:
        return [r.status for r in self.results]

    def export(self, directory, name: str = "squeeze") -> dict[str, str]:
        """Write the series as VTU files + a PVD index and as one XDMF/HDF5 time series.

        Fields per node: ``pressure_Pa``, ``film_m``. Returns the written paths
        (``pvd``, ``xdmf``). Uses meshio (imported here only).
        """
        import os
        from pathlib import Path

        import meshio

        out = Path(directory)
        out.mkdir(parents=True, exist_ok=True)
        r0 = self.results[0]
        grid = PointGrid.tensor(r0.x, r0.y)
        X, Y = grid.node_coordinates()
        points = np.column_stack([X, Y, np.zeros_like(X)])
        cells = [("quad", np.ascontiguousarray(grid.mesh.t.T))]
        entries = []
        for k, (t, r) in enumerate(zip(self.times, self.results)):
            fname = f"{name}_{k:04d}.vtu"
            meshio.write(out / fname, meshio.Mesh(points, cells, point_data={
                "pressure_Pa": r.pressure.ravel(), "film_m": r.film.ravel()}))
            entries.append(f'    <DataSet timestep="{t:.9g}" part="0" file="{fname}"/>')
        pvd = out / f"{name}.pvd"
        pvd.write_text('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                       "  <Collection>\n" + "\n".join(entries) + "\n  </Collection>\n"
                       "</VTKFile>\n", encoding="utf-8")
        xdmf = out / f"{name}.xdmf"
        cwd = os.getcwd()
        try:  # meshio writes the .h5 next to the .xdmf with a relative reference
            os.chdir(out)
            with meshio.xdmf.TimeSeriesWriter(xdmf.name) as w:
                w.write_points_cells(points, cells)
                for t, r in zip(self.times, self.results):
                    w.write_data(float(t), point_data={"pressure_Pa": r.pressure.ravel(),
                                                       "film_m": r.film.ravel()})
        finally:
            os.chdir(cwd)
        return {"pvd": str(pvd), "xdmf": str(xdmf)}


def solve_squeeze_series(scene, eps: float = 0.3, omega: float | None = None,
                         times: np.ndarray | None = None, n_steps: int = 16, *,
                         boundary_pressure: Callable | None = None) -> SqueezeSeries:
    """Quasi-steady rigid series for h0(t) = h0 (1 + eps cos(omega t)).

    Each step solves the rigid wedge + squeeze problem with the gap h0(t) and the
    squeeze source dh0/dt = -h0 eps omega sin(omega t) (the film has no memory in the
    rigid incompressible Reynolds equation, so the steps are independent). All steps use
    the grid of the mean gap h0, so the series exports on one mesh.

    Parameters
    ----------
    scene : Scene
        Rigid point scene with a prescribed gap (``load.gap`` = h0, the mean) and a
        linear lubricant law (constant or Barus, incompressible).
    eps : float
        Relative amplitude [-], 0 <= eps < 1.
    omega : float, optional
        Angular frequency [rad/s]; default u_m / sqrt(2 rx h0) (one hydrodynamic length
        per period/(2 pi)).
    times : array, optional
        Instants [s]; default ``n_steps`` instants over one period.
    n_steps : int
        Used when ``times`` is None.
    boundary_pressure : callable, optional
        ``(x, y, t) -> p`` Dirichlet data [Pa] (default 0).

    Returns
    -------
    SqueezeSeries
    """
    from dataclasses import replace as dc_replace

    if scene.contact.kind != "point":
        raise SceneError(f"solve_squeeze_series needs contact.kind = 'point', got "
                         f"{scene.contact.kind!r}")
    if not _is_linear(scene):
        raise SceneError("solve_squeeze_series needs a rigid, incompressible scene with "
                         "load.gap (m) and a constant or Barus viscosity law")
    eps = float(eps)
    if not 0.0 <= eps < 1.0:
        raise ValueError(f"eps must lie in [0, 1) (dimensionless), got {eps!r}")
    h0 = scene.load.gap
    if omega is None:
        omega = scene.kinematics.mean_speed / math.sqrt(2 * scene.contact.rx * h0)
    omega = float(omega)
    if not (math.isfinite(omega) and omega > 0.0):
        raise ValueError(f"omega must be > 0 rad/s, got {omega!r}")
    if times is None:
        if not isinstance(n_steps, int) or n_steps < 1:
            raise ValueError(f"n_steps must be a positive integer, got {n_steps!r}")
        times = np.arange(n_steps) * (2 * math.pi / omega) / n_steps
    times = np.asarray(times, dtype=float).ravel()
    setup = point_setup(scene)
    gaps = h0 * (1.0 + eps * np.cos(omega * times))
    rates = -h0 * eps * omega * np.sin(omega * times)
    results = []
    for t, g, r in zip(times, gaps, rates):
        sc = dc_replace(scene, load=dc_replace(scene.load, gap=float(g)))
        bp = None if boundary_pressure is None else (
            lambda x, y, _t=t: boundary_pressure(x, y, _t))
        t0 = time.perf_counter()
        res = _solve_linear(sc, dc_replace(setup, h_ref=float(g)),
                            _boundary_values(setup.grid, bp), float(r), t0)
        results.append(res)
    p_max = np.array([r.quantities.get("p_max", np.inf) if r.success else np.inf
                      for r in results])
    return SqueezeSeries(times, gaps, rates, p_max, results)


def _finish(scene, setup: PointSetup, problem: PointProblem, p: np.ndarray, h0: float,
            status: str, message: str, t0: float, *, iterations: int = 0,
            linear_solves: int = 0, history=None, continuation_steps=None, post: bool = True,
            cavitated: np.ndarray | None = None) -> Result:
    from .. import post as pp

    grid = problem.grid
    ops = grid.ops
    h_nodes = problem.film_nodes(p, h0)
    quantities: dict[str, float] = {}
    extra: dict[str, np.ndarray] = {}
    if post:
        pq, h_q, gp, _ = problem.fields_q(p, h0)
        o = np.array([0.0])
        v = problem.displacement(p)
        load = float(problem.mass @ p)
        quantities.update({
            "h_min": float(min(np.min(h_nodes), np.min(h_q))),
            "h_central": float(h0 + grid.interpolate(v, o, o)[0]),
            "p_max": float(np.max(p)),
            "load": load,
        })
        if scene.model.cavitation == "reynolds":
            full = ~cavitated if cavitated is not None else p > 1e-12 * problem.p_ref
            full = full | grid.boundary_mask()
            ind = (ops.value @ full.astype(float) >= 0.5).astype(float)
        else:
            ind = np.ones_like(h_q)
        with np.errstate(all="ignore"):  # unconverged iterates may overflow exp(alpha p)
            eta_q = problem.flux.viscosity(pq)
            quantities.update(pp.friction_and_heat(ops, h_q, gp, eta_q,
                                                   scene.kinematics.sliding_speed, ind, load))
            extra["viscosity_Pa_s"] = problem.flux.viscosity(p).reshape(grid.shape)
    success = status in ("converged", "linear")
    return Result(success=success, status=status, message=message, scene=scene, x=grid.x,
                  y=grid.y, pressure=np.asarray(p).reshape(grid.shape),
                  film=np.asarray(h_nodes).reshape(grid.shape), h0=float(h0),
                  quantities=quantities, history=list(history or []),
                  newton_iterations=iterations, linear_solves=linear_solves,
                  wall_time_s=time.perf_counter() - t0,
                  continuation=list(continuation_steps or []), extra_fields=extra)

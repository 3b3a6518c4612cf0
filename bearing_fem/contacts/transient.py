"""Elastic transient squeeze of a point contact with a prescribed rigid-body approach h0(t).

Symbols and units: x rolling direction, y across it [m]; t time [s]; p pressure [Pa];
h film [m]; h0(t) prescribed rigid offset [m]; g = x^2/(2 rx) + y^2/(2 ry) gap of the
undeformed bodies [m]; v = C p elastic displacement [m] (Boussinesq half-space, FFT);
rho density relative to ambient [-]; eta viscosity [Pa s]; u_m mean speed [m/s];
eps vibration amplitude [-]; omega angular frequency [rad/s]; dt time step [s].

Problem (``docs/theory.md``; the vibrating 209 bearing of Kadochnikova 2018): the gap oscillates as h0(t) = h0 (1 + eps cos(omega t))
(``load.gap`` = h0, the mean) and the film is

    h(x, y, t) = h0(t) + g(x, y) + v[p(t)](x, y),

so the time derivative d(rho h)/dt of the Reynolds equation

    div(rho h^3/(12 eta) grad p) = u_m d(rho h)/dx + d(rho h)/dt

contains dh0/dt, the elastic deformation rate dv/dt = C dp/dt and the density change:
the pressure has memory, the steps are coupled in time.

Weak form and time discretisation (conservative, the time derivative acts on the mass
rho h itself). With the steady residual of :class:`bearing_fem.contacts.point.PointProblem`,
R_steady(phi) = int F . grad phi, F = rho h^3/(12 eta) grad p - u_m rho h e_x (+ the
upwinding of the elastic path), step n solves for p^n

    R_steady(p^n; h0^n)(phi) + int (1/dt) sum_k c_k (rho h)^(n-k) phi = 0,

with the backward differentiation formulas (c_0, c_1, c_2) = (1, -1) (backward Euler,
first order) or (3/2, -2, 1/2) (BDF2, second order). Both are L-stable: the rigid part
of the problem is algebraic (no dp/dt when v = 0), and an L-stable scheme damps the
start-up error instead of carrying it; the trapezoidal rule (Crank-Nicolson) is not: on
the algebraic part it gives S(p^n) = -S(p^(n-1)) + ..., so an error of the start flips
sign every step and never decays. It is not offered.

Newton on step n (:func:`bearing_fem.numerics.newton.damped_newton`, the GMRES machinery of
:meth:`PointProblem.newton_step`): the time term adds to the sparse blocks

    A_p += (c_0/dt) M[rho'(p) h],     A_h += (c_0/dt) M[rho],

M[w] the weighted mass matrix int w phi_j phi_i; A_h multiplies the nodal displacement,
so the dense part (c_0/dt) M[rho] C goes through the same matrix-free FFT path as the
wedge term A_h C, and its near-field part into the preconditioner.

Start: step 0 at t0 is the steady elastic solution at h0(t0) with the squeeze source
rho dh0/dt(t0) (the exact prescribed rate; zero at t0 = 0 for the cosine) and no dv/dt
(the bodies are assumed at rest relative to the deformed shape). The history before t0
that BDF2 needs is taken in the same spirit: (rho h)(t0 - dt) = rho^0 (h0(t0 - dt) + g +
v^0), i.e. the gap follows its prescribed law and the deformation stands still, so the
rigid limit is second order from the first step (a backward-Euler first step would put
an O(dt) error of the approach rate into step 1). The memory of that start decays at
the elastic relaxation rate of the film; studies run two periods.

Grid of a gap-controlled elastic scene: uniform (FFT compliance), lengths in
L_x = sqrt(2 rx h0), L_y = sqrt(2 ry h0) (the hydrodynamic lengths of the mean gap, as for
rigid scenes with a gap; there is no Hertz radius without a load); default
``ELASTIC_GAP_NODES`` per direction on ``ELASTIC_GAP_RANGE_FS`` (full-Sommerfeld) or
``ELASTIC_GAP_RANGE_REYNOLDS`` (Reynolds cavitation). All steps share the grid of the
mean gap.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from dataclasses import replace as dc_replace
from typing import Callable

import numpy as np
import scipy.sparse as sp

from ..errors import SceneError
from ..numerics.newton import BUDGET_STATUSES, Budget, damped_newton, outcome_message
from ..physics.elasticity import HalfSpacePoint
from ..result import Result
from ..scene import Scene
from .driver import (DriverSettings, Progress, finish, solve_levels, solve_newton_model)
from .point import (RIGID_RANGE_REYNOLDS, PointLevel, PointModel, PointProblem, PointSetup,
                    boundary_values, flux_model, rigid_domain_load_share, rigid_start)
from .point_grid import PointGrid
from .problem import fischer_burmeister
from .series import SqueezeSeries

log = logging.getLogger(__name__)

#: Default nodes per direction of the uniform grid of a gap-controlled elastic scene.
ELASTIC_GAP_NODES = 97
#: Default domains in units of sqrt(2 rx h0) (x) and sqrt(2 ry h0) (y). The rigid Kapitsa
#: wedge pressure at 10 lengths is 0.3% of its peak (p ~ x/(1 + x^2)^2); the elastic
#: deformation flattens and widens the pressure zone only mildly at the gaps of interest.
ELASTIC_GAP_RANGE_FS = ((-10.0, 10.0), (-10.0, 10.0))
ELASTIC_GAP_RANGE_REYNOLDS = ((-10.0, 5.0), (-10.0, 10.0))
#: Backward differentiation formulas: coefficients c_k of (rho h)^(n-k), k = 0, 1, ...
BDF_COEFFICIENTS = {"euler": (1.0, -1.0), "bdf2": (1.5, -2.0, 0.5)}
SCHEMES = ("bdf2", "euler", "quasi-steady")


# ---------------------------------------------------------------------------------------
# setup of a gap-controlled elastic scene
# ---------------------------------------------------------------------------------------
def elastic_gap_setup(scene, nodes: tuple[int, int] | None = None,
                      pressure_scale: float | None = None) -> PointSetup:
    """Uniform grid, half-space compliance and scales of an elastic point scene with a gap.

    Parameters
    ----------
    scene : Scene
        ``contact.kind = "point"``, ``model.elasticity = "half-space"``, ``load.gap`` = h0
        [m]. ``mesh.x_range``/``y_range`` are read in units of sqrt(2 rx h0) and
        sqrt(2 ry h0); ``mesh.nodes`` as (nx, ny).
    nodes : (int, int), optional
        Overrides ``scene.mesh.nodes``.
    pressure_scale : float, optional
        p_ref [Pa] of the Newton unknowns; default eta0 u_m L_x/h0^2 (the rigid wedge
        pressure scale, L_x = sqrt(2 rx h0)).

    Returns
    -------
    PointSetup
        ``compliance`` is a :class:`~bearing_fem.physics.elasticity.HalfSpacePoint`;
        ``stab_compliance`` = C_00, the self-compliance of a grid node (the upwinding
        scale of load-controlled scenes, :data:`bearing_fem.contacts.point.
        UPWIND_COMPLIANCE_FACTOR`); ``hertz`` is None.
    """
    h0 = scene.load.gap
    rx, ry = scene.contact.rx, scene.contact.ry
    lx, ly = math.sqrt(2.0 * rx * h0), math.sqrt(2.0 * ry * h0)
    rng = ELASTIC_GAP_RANGE_FS if scene.model.cavitation == "none" \
        else ELASTIC_GAP_RANGE_REYNOLDS
    xr = scene.mesh.x_range or rng[0]
    yr = scene.mesh.y_range or rng[1]
    if nodes is None:
        n = scene.mesh.nodes
        nodes = (ELASTIC_GAP_NODES, ELASTIC_GAP_NODES) if n is None else (int(n[0]), int(n[1]))
    grid = PointGrid.tensor(np.linspace(xr[0] * lx, xr[1] * lx, nodes[0]),
                            np.linspace(yr[0] * ly, yr[1] * ly, nodes[1]))
    comp = HalfSpacePoint(grid.x, grid.y, scene.e_prime)
    if pressure_scale is None:
        pressure_scale = scene.lubricant.viscosity * scene.kinematics.mean_speed * lx / h0**2
    # the grid-scale compliance of every elastic point scene (point.point_setup): a
    # contact-scale one (4 L_x/(pi E')) keeps first-order upwinding across the inlet
    c_stab = float(comp.kernel()[0, 0])
    return PointSetup(grid, comp, float(pressure_scale), h0, lx, ly, h0, c_stab, None)


# ---------------------------------------------------------------------------------------
# the time-discrete problem
# ---------------------------------------------------------------------------------------
class TransientPointProblem(PointProblem):
    """One time step of the transient Reynolds-elasticity system (a NonlinearProblem).

    The residual is that of :class:`~bearing_fem.contacts.point.PointProblem` plus the BDF mass
    term int (1/dt) sum_k c_k (rho h)^(n-k) phi (module docstring); the film of the
    earlier levels enters only through ``history``. With ``time_step=None`` the problem
    is the steady one (optionally with the squeeze source of the base class).

    Parameters
    ----------
    *args, **kwargs
        As :class:`~bearing_fem.contacts.point.PointProblem` (``gap`` = h0^n [m]).
    time_step : float or None
        dt [s]; None: steady (no time term).
    coefficients : sequence of float
        BDF coefficients (c_0, c_1, ...) [-], ``len(history) + 1`` of them.
    history : sequence of ndarray
        (rho h)^(n-1), (rho h)^(n-2), ... at the quadrature points [m] (relative density
        times film).
    """

    def __init__(self, *args, time_step: float | None = None,
                 coefficients: tuple[float, ...] = (), history=(), **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.time_step = time_step
        self.coefficients = tuple(coefficients)
        if time_step is not None:
            if not (math.isfinite(time_step) and time_step > 0.0):
                raise ValueError(f"time_step must be > 0 s, got {time_step!r}")
            if len(self.coefficients) != len(history) + 1:
                raise ValueError(f"{len(self.coefficients)} BDF coefficients need "
                                 f"{len(self.coefficients) - 1} history levels, got "
                                 f"{len(history)}")
            ops = self.grid.ops
            old = np.zeros(ops.weights.size)
            for c, mass in zip(self.coefficients[1:], history):
                old = old + c * np.asarray(mass, dtype=float)
            #: sum_{k>=1} c_k (rho h)^(n-k) / dt at the quadrature points [m/s]
            self._old_rate = old / time_step

    # -- time term -----------------------------------------------------------------------
    def mass_q(self, p: np.ndarray, h0: float) -> np.ndarray:
        """rho h at the quadrature points [m] (relative density times film)."""
        pq, h, _, _ = self.fields_q(p, h0)
        return self.flux.density(pq) * h

    def mass_rate_q(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Discrete d(rho h)/dt at the quadrature points [m/s] (0 when steady)."""
        if self.time_step is None:
            return np.zeros(self.grid.ops.weights.size)
        return self.coefficients[0] * self.mass_q(p, h0) / self.time_step + self._old_rate

    def reynolds_residual(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Nodal weak residual R_i [m^3/s] (all nodes), steady part + BDF mass term."""
        r = super().reynolds_residual(p, h0)
        if self.time_step is None:
            return r
        ops = self.grid.ops
        return r + ops.value.T @ (ops.weights * self.mass_rate_q(p, h0))

    def _blocks(self, z: np.ndarray):
        a_p, a_h, drdh0, row_factor, da = super()._blocks(z)
        if self.time_step is None:
            return a_p, a_h, drdh0, row_factor, da
        p, h0 = self.unpack(z)
        ops = self.grid.ops
        pq, h, _, _ = self.fields_q(p, h0)
        rho = np.real(self.flux.density(pq))
        w = ops.weights * self.coefficients[0] / self.time_step
        # d/dv: rho (c_0/dt) int phi_j phi_i  (multiplies C dp in the matrix-free product)
        a_h = (a_h + ops.value.T @ sp.diags(w * rho) @ ops.value).tocsr()
        drdh0 = drdh0 + ops.value.T @ (w * rho)
        step = 1e-20 * max(self.p_ref, 1.0)
        drho = np.imag(self.flux.density(pq + 1j * step)) / step
        if np.any(drho != 0.0):  # compressible: rho'(p) h (c_0/dt) int phi_j phi_i
            a_p = (a_p + ops.value.T @ sp.diags(w * drho * h) @ ops.value).tocsr()
        if self.cavitation == "reynolds":
            # the base class linearised Fischer-Burmeister about the steady residual;
            # redo it about the full (steady + time) residual
            rows = self.free
            res = self.reynolds_residual(p, h0)
            _, da, db = fischer_burmeister(p[rows] / self.p_ref, res[rows] * self._row_scale,
                                           self._fb_mu)
            row_factor = db * self._row_scale
        return a_p, a_h, drdh0, row_factor, da


# ---------------------------------------------------------------------------------------
# series container
# ---------------------------------------------------------------------------------------
@dataclass
class ElasticSqueezeSeries(SqueezeSeries):
    """Elastic transient squeeze series (a :class:`~bearing_fem.contacts.point.SqueezeSeries`).

    Step 0 is the steady start at t0; steps 1.. are the time steps. The arrays cover the
    solved steps only: a failed step stops the series, its Result is ``failure`` and
    ``status``/``message`` say which step failed and why (never NaN in the arrays).

    Attributes
    ----------
    times, gap, squeeze_velocity, p_max, results
        As :class:`SqueezeSeries`: t [s], h0(t) [m], the prescribed dh0/dt [m/s] (exact
        derivative of h0(t)), maximum pressure [Pa], one Result per step (all on one grid).
    h_min, h_central : ndarray
        Minimum film and film at x = y = 0 [m].
    load : ndarray
        Film force int p dA [N].
    newton_iterations : ndarray of int
        Newton iterations per step.
    wall_time_s : ndarray
        Wall time per step [s].
    status : str
        ``"converged"`` if every planned step converged, else the failed step's status.
    message : str
    scheme : str
        ``"bdf2"``, ``"euler"`` or ``"quasi-steady"``.
    time_step : float
        dt [s].
    eps, omega : float
        Amplitude [-] and angular frequency [rad/s] of h0(t).
    n_planned : int
        Steps planned, including the start (``len(times)`` when complete).
    failure : Result or None
        The failed step (last admissible iterate), if any.
    failure_time, failure_gap : float or None
        t [s] and h0(t) [m] of the failed step, if any.
    """

    h_min: np.ndarray = field(default_factory=lambda: np.zeros(0))
    h_central: np.ndarray = field(default_factory=lambda: np.zeros(0))
    load: np.ndarray = field(default_factory=lambda: np.zeros(0))
    newton_iterations: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    wall_time_s: np.ndarray = field(default_factory=lambda: np.zeros(0))
    status: str = "converged"
    message: str = ""
    scheme: str = "bdf2"
    time_step: float = 0.0
    eps: float = 0.0
    omega: float = 0.0
    n_planned: int = 0
    failure: Result | None = None
    failure_time: float | None = None
    failure_gap: float | None = None

    ESTIMATE_NOTE = ("no error estimate: the instants of an elastic series are solved on one "
                     "grid, so their discretisation error is unknown; compare with a series "
                     "on a finer mesh (mesh.nodes)")

    @property
    def success(self) -> bool:
        return self.status == "converged"

    def summary(self) -> dict:
        """As :meth:`SqueezeSeries.summary`, with ``failed_step``: None, or the failed
        step's number (0 = the start), ``time`` [s], ``gap`` [m] and ``status`` (its
        fields, the last admissible iterate, are exported apart from the solved steps:
        :func:`bearing_fem.io.export_series`)."""
        out = super().summary()
        out["failed_step"] = None if self.failure is None else {
            "step": len(self.results), "time": self.failure_time, "gap": self.failure_gap,
            "status": self.failure.status}
        return out


# ---------------------------------------------------------------------------------------
# driver
# ---------------------------------------------------------------------------------------
def _check_scene(scene, who: str) -> None:
    if not isinstance(scene, Scene):
        raise SceneError(f"{who} needs a Scene, got {type(scene).__name__}")
    if scene.contact.kind != "point":
        raise SceneError(f"{who} needs contact.kind = 'point', got {scene.contact.kind!r}")
    if scene.model.elasticity != "half-space":
        raise SceneError(f"{who} needs model.elasticity = 'half-space' (an elastic scene), "
                         f"got {scene.model.elasticity!r}; rigid scenes have no memory: use "
                         f"bearing_fem.contacts.series.solve_squeeze_series")
    if scene.load.gap is None:
        raise SceneError(f"{who} needs a prescribed gap load.gap (m), the mean rigid offset "
                         f"h0 of h0(t) = h0 (1 + eps cos(omega t)); got load.force = "
                         f"{scene.load.force!r} N (a prescribed load F(t) needs the rolling "
                         f"element's equation of motion, not implemented)")
    if scene.model.thermal != "none":
        raise SceneError(f"{who} is isothermal: model.thermal must be 'none', got "
                         f"{scene.model.thermal!r}")


def _make_step_problem(scene, setup: PointSetup, gap: float, p_bc: np.ndarray, *,
                       squeeze: float = 0.0, time_step: float | None = None,
                       coefficients=(), history=(), compliance_scale: float = 1.0,
                       tolerance: float | None = None) -> TransientPointProblem:
    comp = setup.compliance
    if compliance_scale != 1.0:
        comp = None if compliance_scale == 0.0 else HalfSpacePoint(
            setup.grid.x, setup.grid.y, scene.e_prime / compliance_scale)
    return TransientPointProblem(
        setup.grid, flux_model(scene, setup), scene.contact.rx, scene.contact.ry, comp,
        scene.model.cavitation, None, gap, setup.p_ref, setup.h_ref,
        scene.lubricant.viscosity, p_bc, squeeze, time_step=time_step,
        coefficients=coefficients, history=history, tolerance=tolerance)


class ElasticGapModel(PointModel):
    """The steady elastic point contact at a prescribed gap as a driver model.

    One grid (uniform, in units of sqrt(2 r h0), :func:`elastic_gap_setup`); the direct
    attempt starts from the rigid isoviscous solution at the gap, and the fallback is
    continuation in the compliance 1/E' from the rigid problem (s = 0) to the elastic
    one (s = 1). Post-processing, transfer and the coarser grids of the error estimate
    as :class:`~bearing_fem.contacts.point.PointModel`.

    Parameters
    ----------
    scene : Scene
        Elastic point scene with ``load.gap`` = h0 [m].
    setup : PointSetup
        Its grid (shared by every step of a series).
    gap : float
        The rigid offset of this solve [m] (h0(t) of a series step).
    p_bc_fn : callable or ndarray or None
        Dirichlet pressure (as :func:`~bearing_fem.contacts.point.solve_point`).
    squeeze : float
        dh0/dt [m/s] (the source rho dh0/dt; no dv/dt).
    """

    settings = DriverSettings()
    continuation_parameter = "compliance"
    grid_note = ""

    def __init__(self, scene, setup: PointSetup, gap: float, p_bc_fn=None,
                 squeeze: float = 0.0) -> None:
        self.scene = scene
        self.boundary_pressure = p_bc_fn
        self.squeeze = float(squeeze)
        self.gap = float(gap)
        self.setup = setup
        self.fine_nodes = (setup.grid.x.size, setup.grid.y.size)
        self.elastic = True
        self.symmetric = False
        self._levels = {}
        self._problems = []

    def level(self, nodes: tuple[int, int], half: bool | None = None) -> PointLevel:
        key = (tuple(nodes), False)
        if key not in self._levels:
            setup = self.setup if tuple(nodes) == self.fine_nodes else \
                elastic_gap_setup(self.scene, tuple(nodes), self.setup.p_ref)
            self._levels[key] = PointLevel(setup, tuple(nodes),
                                           boundary_values(setup.grid, self.boundary_pressure))
        return self._levels[key]

    def levels(self) -> list[PointLevel]:
        return [self.level(self.fine_nodes)]

    def problem(self, level: PointLevel, s: float = 1.0,
                tolerance: float | None = None) -> TransientPointProblem:
        problem = _make_step_problem(self.scene, level.setup, self.gap, level.p_bc,
                                     squeeze=self.squeeze, compliance_scale=s,
                                     tolerance=tolerance)
        self._problems.append(problem)
        return problem

    def initial_guess(self, level: PointLevel, problem: PointProblem,
                      s: float = 1.0) -> np.ndarray:
        return rigid_start(self.scene, level.setup, problem, self.gap)


def solve_elastic_gap(scene: Scene, *, squeeze_velocity: float = 0.0,
                      boundary_pressure: Callable | np.ndarray | None = None,
                      max_iterations: int | None = None,
                      progress: Progress | None = None) -> Result:
    """Steady elastic point contact with a prescribed rigid offset h0 = ``load.gap``.

    The film is h = h0 + g + v[p] (half-space compliance) and the steady Reynolds equation
    carries the squeeze source rho dh0/dt (no dv/dt): the start of
    :func:`solve_elastic_squeeze_series` and its quasi-steady comparison.
    :func:`bearing_fem.contacts.point.solve_point` handles elastic scenes under a load;
    this is the gap-controlled counterpart (no load balance, uniform grid in
    sqrt(2 rx h0) units), solved by the shared driver (:class:`ElasticGapModel`).

    Parameters
    ----------
    scene : Scene
        Point contact, ``model.elasticity = "half-space"``, ``load.gap`` = h0 [m].
    squeeze_velocity : float
        dh0/dt [m/s] (< 0: approach, positive squeeze pressure).
    boundary_pressure : callable or ndarray, optional
        Dirichlet pressure [Pa]: ``(x [m], y [m]) -> p`` or nodal values (ny, nx). Default 0.
    max_iterations : int, optional
        Newton iterations per attempt (default ``scene.solver.max_iterations``).
    progress : callable, optional
        Progress callback (:func:`bearing_fem.contacts.driver.solve_levels`).

    Returns
    -------
    Result
        As :func:`~bearing_fem.contacts.point.solve_point`; never raises for
        non-convergence.
    """
    _check_scene(scene, "solve_elastic_gap")
    sq = float(squeeze_velocity)
    if not math.isfinite(sq):
        raise ValueError(f"squeeze_velocity must be finite (m/s), got {squeeze_velocity!r}")
    if max_iterations is not None:
        scene = dc_replace(scene, solver=dc_replace(scene.solver,
                                                    max_iterations=int(max_iterations)))
    t0 = time.perf_counter()
    setup = elastic_gap_setup(scene, pressure_scale=_pressure_scale(scene, abs(sq)))
    model = ElasticGapModel(scene, setup, scene.load.gap, boundary_pressure, sq)
    result = solve_newton_model(model, scene, t0, progress=progress,
                                prefix="steady elastic: ")
    result.warnings += domain_load_warnings(scene)
    return result


#: A gap-controlled elastic scene on its default domain is warned when a rigid film at
#: the same gap carries less than this share of its load there (against the default rigid
#: domain, :func:`bearing_fem.contacts.point.rigid_domain_load_share`).
DOMAIN_LOAD_SHARE_WARNING = 0.99


def domain_load_warnings(scene: Scene) -> list[str]:
    """The warning of a gap-controlled elastic scene with the Reynolds outlet whose default
    domain (:data:`ELASTIC_GAP_RANGE_REYNOLDS`, taken where ``mesh.x_range`` or
    ``mesh.y_range`` is not given) cuts off part of the pressure field: the pressure of a
    fully flooded film decays only as r^-3, and the film's load with it (measured:
    rx = ry = 5 mm, E' = 2.2e11 Pa, 1 m/s, 0.01 Pa s, isoviscous, h0 = 1.4e-7 m: 0.0926 N
    on the default domain and 97^2 grid, 0.1044 N on [-30, 8] x [-30, 30] with 193 x 257
    nodes: the default domain carries 11.3 % less; the rigid share says 10 %). Empty
    otherwise."""
    mesh = scene.mesh
    if (scene.model.cavitation != "reynolds" or mesh.file is not None
            or (mesh.x_range is not None and mesh.y_range is not None)):
        return []
    xr = mesh.x_range or ELASTIC_GAP_RANGE_REYNOLDS[0]
    yr = mesh.y_range or ELASTIC_GAP_RANGE_REYNOLDS[1]
    share = rigid_domain_load_share(scene.contact.ry / scene.contact.rx, tuple(xr), tuple(yr))
    if share >= DOMAIN_LOAD_SHARE_WARNING:
        return []
    big = RIGID_RANGE_REYNOLDS
    return [f"load (and friction) cut by the domain: a rigid film at this gap carries "
            f"{100 * (1 - share):.2g}% less load on x in [{xr[0]:g}, {xr[1]:g}], y in "
            f"[{yr[0]:g}, {yr[1]:g}] (lengths sqrt(2 rx h0), sqrt(2 ry h0)) than on "
            f"[{big[0][0]:g}, {big[0][1]:g}] x [{big[1][0]:g}, {big[1][1]:g}], itself a few "
            "percent short of an unbounded flooded film (its pressure decays as r^-3); give "
            "mesh.x_range and mesh.y_range wider, with more mesh.nodes, where the load "
            "matters"]


def _pressure_scale(scene, rate: float) -> float:
    """eta0 (u_m L_x + |dh0/dt| L_x^2/h0)/h0^2 [Pa]: wedge plus squeeze pressure scales."""
    h0 = scene.load.gap
    lx = math.sqrt(2.0 * scene.contact.rx * h0)
    return scene.lubricant.viscosity * (scene.kinematics.mean_speed * lx
                                        + rate * lx**2 / h0) / h0**2


def _step_result(scene, model: ElasticGapModel, problem: TransientPointProblem,
                 z: np.ndarray, status: str, iterations: int, t0: float, history,
                 what: str) -> Result:
    """Result of one step of a series (no error estimate: the steps share one grid)."""
    problem.prepare(z)
    resid = float(np.max(np.abs(problem.residual(z))))
    msg = outcome_message(status, iterations, resid, scene.solver.tolerance,
                          prefix=f"{what}: ",
                          admissible=status == "converged" or problem.admissible(z))
    res = finish(scene, model.solution(problem, z), status=status, message=msg, t0=t0,
                 iterations=iterations, history=history, estimate=False, residual=resid)
    res.quantities["gmres_iterations"] = float(problem.linear_iterations)
    return res


def solve_elastic_squeeze_series(scene: Scene, eps: float = 0.3, omega: float | None = None,
                                 n_steps: int = 32, periods: int = 1, *,
                                 scheme: str = "bdf2", t0: float = 0.0,
                                 boundary_pressure: Callable | None = None,
                                 max_iterations: int | None = None
                                 ) -> ElasticSqueezeSeries:
    """Elastic transient squeeze: h0(t) = h0 (1 + eps cos(omega t)) with d(rho h)/dt.

    Each time step solves the coupled Reynolds-elasticity problem with the BDF time term
    (module docstring) by damped Newton-GMRES, starting from the previous step
    (linearly extrapolated). Step 0 is the steady elastic solution at t0 with the
    squeeze source dh0/dt(t0) (zero at t0 = 0) and no dv/dt.

    Parameters
    ----------
    scene : Scene
        Point contact with ``model.elasticity = "half-space"``, a prescribed gap
        ``load.gap`` = h0 [m] (the mean of h0(t)), ``model.thermal = "none"``. Grid:
        ``mesh.nodes`` (default 97 x 97) and ``mesh.x_range``/``y_range`` in units of
        sqrt(2 rx h0), sqrt(2 ry h0) (defaults in :data:`ELASTIC_GAP_RANGE_FS`).
    eps : float
        Relative amplitude [-], 0 <= eps < 1.
    omega : float, optional
        Angular frequency [rad/s], > 0; default u_m / sqrt(2 rx h0) (as
        :func:`~bearing_fem.contacts.point.solve_squeeze_series`).
    n_steps : int
        Time steps per period (>= 2); dt = 2 pi/(omega n_steps) [s].
    periods : int
        Number of periods (>= 1).
    scheme : {"bdf2", "euler", "quasi-steady"}
        BDF2 (default, second order), backward Euler (first order), or the quasi-steady
        elastic comparison: each instant solved as a steady elastic problem with the
        squeeze source rho dh0/dt (exact rate) and no dv/dt, d(rho)/dt (no memory).
    t0 : float
        Start time [s].
    boundary_pressure : callable, optional
        ``(x [m], y [m], t [s]) -> p [Pa]`` Dirichlet data on the domain boundary
        (default 0).
    max_iterations : int, optional
        Newton iterations per step (default ``scene.solver.max_iterations``).

    Returns
    -------
    ElasticSqueezeSeries
        ``n_steps * periods + 1`` instants when every step converges. Never raises for a
        failed step: the series stops there with an explicit ``status``.

    Raises
    ------
    SceneError
        Not a point contact, not elastic, a load instead of a gap, a thermal scene.
    ValueError
        eps outside [0, 1), omega <= 0 (rad/s), n_steps < 2, periods < 1, unknown scheme,
        non-finite t0 (s), non-callable ``boundary_pressure``.
    """
    who = "solve_elastic_squeeze_series"
    _check_scene(scene, who)
    eps = float(eps)
    if not (math.isfinite(eps) and 0.0 <= eps < 1.0):
        raise ValueError(f"eps must lie in [0, 1) (dimensionless amplitude of h0(t)), got "
                         f"{eps!r}")
    h0m = scene.load.gap
    if omega is None:  # one hydrodynamic length per radian of the vibration
        omega = scene.kinematics.mean_speed / math.sqrt(2.0 * scene.contact.rx * h0m)
    omega = float(omega)
    if not (math.isfinite(omega) and omega > 0.0):
        raise ValueError(f"omega must be a finite angular frequency > 0 rad/s, got {omega!r}")
    if isinstance(n_steps, bool) or not isinstance(n_steps, (int, np.integer)) or n_steps < 2:
        raise ValueError(f"n_steps must be an integer >= 2 (time steps per period), got "
                         f"{n_steps!r}")
    if isinstance(periods, bool) or not isinstance(periods, (int, np.integer)) or periods < 1:
        raise ValueError(f"periods must be an integer >= 1, got {periods!r}")
    if scheme not in SCHEMES:
        raise ValueError(f"scheme must be one of {SCHEMES}, got {scheme!r}")
    t0 = float(t0)
    if not math.isfinite(t0):
        raise ValueError(f"t0 must be finite (s), got {t0!r}")
    if boundary_pressure is not None and not callable(boundary_pressure):
        raise ValueError("boundary_pressure must be a callable (x [m], y [m], t [s]) -> p "
                         f"[Pa], got {type(boundary_pressure).__name__}")

    dt = 2.0 * math.pi / (omega * n_steps)
    n_total = int(n_steps) * int(periods)
    times = t0 + dt * np.arange(n_total + 1)
    gaps = h0m * (1.0 + eps * np.cos(omega * times))
    rates = -h0m * eps * omega * np.sin(omega * times)
    if max_iterations is not None:
        scene = dc_replace(scene, solver=dc_replace(scene.solver,
                                                    max_iterations=int(max_iterations)))
    setup = elastic_gap_setup(scene, pressure_scale=_pressure_scale(scene, h0m * eps * omega))
    maxit = scene.solver.max_iterations
    tol = scene.solver.tolerance

    def p_bc_at(t: float):
        if boundary_pressure is None:
            return None
        return lambda x, y: boundary_pressure(x, y, t)

    def step_scene(g: float):
        return dc_replace(scene, load=dc_replace(scene.load, gap=float(g)))

    # solver.iteration_budget applies to each instant (each is one solve),
    # solver.time_limit to the whole series (a wall clock)
    series_start = time.perf_counter()
    results: list[Result] = []
    masses: list[np.ndarray] = []   # (rho h) at the quadrature points, latest first
    zs: list[np.ndarray] = []
    failure, failed_at = None, (None, None)
    status, message = "converged", ""
    for n, (t, g, rate) in enumerate(zip(times, gaps, rates)):
        clock = time.perf_counter()
        what = f"step {n} (t = {t:.6g} s)"
        limit = scene.solver.time_limit
        budget = Budget(iterations=scene.solver.iteration_budget,
                        seconds=None if limit is None else limit - (clock - series_start))
        sc = step_scene(g)
        model = ElasticGapModel(sc, setup, float(g), p_bc_at(t), float(rate))
        level = model.levels()[0]
        steps: list = []
        if n == 0:
            out = solve_levels(model, sc.solver, budget=budget)
            z, st, its, problem, hist, steps = (out.z, out.status, out.iterations,
                                                out.problem, out.history, out.steps)
        elif scheme == "quasi-steady":
            problem = model.problem(level, 1.0, tol)
            res_n = damped_newton(problem, _guess(problem, zs), tol=tol, max_iterations=maxit,
                                  budget=budget)
            z, st, its, hist = res_n.z, res_n.status, res_n.iterations, res_n.history
        else:
            coeffs = BDF_COEFFICIENTS[scheme]
            problem = _make_step_problem(sc, setup, float(g), level.p_bc, time_step=dt,
                                         coefficients=coeffs,
                                         history=masses[:len(coeffs) - 1], tolerance=tol)
            z, st, its, hist = _step_newton(problem, zs, tol, maxit, budget)
        res = _step_result(sc, model, problem, z, st, its, clock, hist, what)
        res.continuation = list(steps)
        if n == 0:  # the series' domain: said once, with its start
            res.warnings += domain_load_warnings(scene)
        if not res.success:
            failure, failed_at = res, (float(t), float(g))
            status = st
            spent = (f"; this instant spent {budget.describe()}; solver.iteration_budget "
                     "applies to each instant, solver.time_limit to the whole series"
                     if st in BUDGET_STATUSES else "")
            message = (f"{what} {st}: series stopped after {n} of {n_total + 1} instants "
                       f"({res.message}{spent})")
            break
        p, _ = problem.unpack(z)
        masses.insert(0, problem.mass_q(p, float(g)))
        if n == 0:  # history before t0: h0 follows its law, the deformation stands still
            ghost = h0m * (1.0 + eps * math.cos(omega * (t - dt)))
            masses.append(problem.mass_q(p, ghost))
        del masses[2:]
        zs.insert(0, z)
        del zs[2:]
        results.append(res)
    if failure is None:
        message = (f"{n_total} {scheme} steps of dt = {dt:.4g} s converged "
                   f"({int(sum(r.newton_iterations for r in results))} Newton iterations)")
    k = len(results)
    q = [r.quantities for r in results]
    return ElasticSqueezeSeries(
        times=times[:k], gap=gaps[:k], squeeze_velocity=rates[:k],
        p_max=np.array([d["p_max"] for d in q]), results=results,
        h_min=np.array([d["h_min"] for d in q]),
        h_central=np.array([d["h_central"] for d in q]),
        load=np.array([d["load"] for d in q]),
        newton_iterations=np.array([r.newton_iterations for r in results], dtype=int),
        wall_time_s=np.array([r.wall_time_s for r in results]),
        status=status, message=message, scheme=scheme, time_step=dt, eps=eps,
        omega=omega, n_planned=n_total + 1, failure=failure, failure_time=failed_at[0],
        failure_gap=failed_at[1], scene=scene)


def _guess(problem: TransientPointProblem, zs: list[np.ndarray]) -> np.ndarray:
    """Linear extrapolation of the last two steps if admissible, else the last step."""
    if len(zs) >= 2:
        z = 2.0 * zs[0] - zs[1]
        if problem.admissible(z):
            return z
    return zs[0]


def _step_newton(problem: TransientPointProblem, zs: list[np.ndarray], tol: float,
                 maxit: int, budget=None):
    """Newton from the extrapolated start; one retry from the previous step."""
    z0 = _guess(problem, zs)
    out = damped_newton(problem, z0, tol=tol, max_iterations=maxit, budget=budget)
    its, history = out.iterations, list(out.history)
    if not out.converged and z0 is not zs[0] and out.status not in BUDGET_STATUSES:
        log.info("time step: Newton %s from the extrapolated start; retrying from the "
                 "previous step", out.status)
        out = damped_newton(problem, zs[0], tol=tol, max_iterations=maxit, budget=budget)
        its += out.iterations
        history += list(out.history)
    return out.z, out.status, its, history

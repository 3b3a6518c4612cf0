"""``solve(scene)``: pick the cheapest correct path for a scene and run it.

Paths (a scene pays only for what it needs):

* rigid, incompressible, constant or Barus viscosity, prescribed gap: **linear**.
  Kapitsa's transform q = (1 - exp(-alpha p))/alpha turns the Reynolds equation into
  the isoviscous one, solved by one sparse linear solve (full-Sommerfeld) or by a
  primal-dual active-set sequence of linear solves (Reynolds cavitation, an obstacle
  problem); then p = -ln(1 - alpha q)/alpha, which exists only while alpha max q < 1
  (PHYSICS.md 5.1): otherwise the status is ``no_solution``.
* everything else: **damped Newton** on (p, h0) (:mod:`bearing_fem.contacts.line`), from a
  Hertzian (elastic) or rigid (linear) initial guess, with automatic continuation in the
  pressure-viscosity coefficient when the direct attempt does not converge.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import SceneError
from .line import LineDiscretisation, LineProblem
from ..numerics.newton import continuation, damped_newton, outcome_message
from ..result import Result
from ..physics.reynolds import FluxModel, UpwindFluxModel
from ..scene import Scene

log = logging.getLogger(__name__)

#: h*/h0 of Martin's rigid isoviscous cylinder (sec^2 of the outlet angle, ~1.2255);
#: used only to estimate a starting offset for rigid loaded scenes, never as an oracle.
_MARTIN_HSTAR_APPROX = 1.2255
#: Default grid density of elastic line contacts: nodes per Hertz half-width.
NODES_PER_HALF_WIDTH = 300
#: Above this Moes load parameter M the default density grows as sqrt(M / this): the
#: outlet constriction and spike narrow with load (measured at 300 nodes per b against
#: twice as fine: h_central changes 0.08 % at M = 200 but 0.82 % at M = 1000, L = 2).
DENSE_MESH_MOES_M = 250.0
#: Cap on default elastic line grids (dense compliance: memory and LU time grow as N^2, N^3).
MAX_DEFAULT_ELASTIC_NODES = 4001
#: Default rigid-scene grid: nodes per sqrt(2 R h0).
NODES_PER_RIGID_LENGTH = 40
#: Stabilisation of half-space line contacts: "upwind" (first-order upwinded wedge term,
#: :class:`~bearing_fem.physics.reynolds.UpwindFluxModel`) or "supg" (SUPG on the whole strong
#: residual). Kodnir's local model always uses SUPG. ``studies/line_stabilisation.py``
#: compares the two.
HALF_SPACE_STABILISATION = "upwind"
#: Poiseuille term of half-space line contacts with Barus viscosity (as in
#: :data:`bearing_fem.contacts.point.REDUCED_POISEUILLE`): rho h^3/(12 eta0) dq_h/dx, q_h the P1
#: interpolant of the nodal reduced pressure q = (1 - exp(-alpha p))/alpha, instead of
#: eps(p) dp/dx at the quadrature points. Over an element it is the exact integral of
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


def solve(scene: Scene, *, boundary_pressure: tuple[float, float] | None = None) -> Result:
    """Solve a contact scene.

    Parameters
    ----------
    scene : Scene
    boundary_pressure : (float, float), optional
        Dirichlet pressures at the inlet and outlet ends of a line domain [Pa]
        (default 0, 0). Used by the analytic-oracle tests to impose exact data.

    Returns
    -------
    Result
        Never raises for non-convergence or non-existence: see ``result.status``.
    """
    if not isinstance(scene, Scene):
        raise SceneError(f"solve() needs a Scene, got {type(scene).__name__}")
    if scene.model.thermal == "patch":
        from .coupling import solve_thermal  # only thermal scenes import the patch

        return solve_thermal(scene)
    if scene.contact.kind == "point":
        from .point import solve_point

        return solve_point(scene)
    return solve_line(scene, boundary_pressure=boundary_pressure)


# ---------------------------------------------------------------------------------------
@dataclass
class LineSetup:
    """Scales, grid and operators of a line scene (internal)."""

    disc: LineDiscretisation
    compliance: object
    p_ref: float
    h_ref: float
    x_unit: float
    h_estimate: float
    stab_compliance: float


def _kodnir_coefficient(scene: Scene) -> float:
    from ..physics.elasticity import kodnir_local_coefficient

    # Kodnir's 1.52 contains nu = 0.3 for two equal bodies: E = E' (1 - 0.3^2).
    e = scene.e_prime * (1.0 - 0.3**2)
    return kodnir_local_coefficient(scene.load.force, scene.contact.rx, e)


def line_setup(scene: Scene) -> LineSetup:
    """Reference scales, default mesh and compliance operator of a line scene."""
    from ..physics import elasticity
    from .. import units
    from ..formulas import line_central_film_moes

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
        # fully flooded inlet: 4.5 b, or 15 hydrodynamic lengths sqrt(2 R h) at low load
        inlet = max(4.5, 15.0 * math.sqrt(2 * R * h_est) / b)
        x_range = scene.mesh.x_range or (-inlet, 1.5)
        moes_m = units.moes_line(w, R, scene.e_prime, lub.viscosity, u_m,
                                 lub.effective_piezo)["M"]
        density = NODES_PER_HALF_WIDTH * math.sqrt(max(1.0, moes_m / DENSE_MESH_MOES_M))
    else:
        if scene.load.gap is not None:
            h0 = scene.load.gap
        else:  # rigid under load: Martin's isoviscous estimate of the offset
            h0 = 6 * lub.viscosity * u_m * R / (_MARTIN_HSTAR_APPROX * scene.load.force)
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
    nodes = scene.mesh.nodes or int(min(max(width * density, 801), cap)) | 1
    disc = LineDiscretisation.uniform(x_range[0] * x_unit, x_range[1] * x_unit, nodes)
    if model.elasticity == "rigid":
        comp = elasticity.RigidCompliance()
        c_stab = 0.0
    elif model.elasticity == "local":
        coef = _kodnir_coefficient(scene)
        comp = elasticity.LocalCompliance(coef)
        c_stab = coef
    else:
        comp = elasticity.HalfSpaceLine(disc.x, scene.e_prime, method="dense")
        # compliance of a pressure change over one element (~ its self-influence): a
        # contact-width compliance would over-stabilise and wash out the outlet
        # constriction and spike (checked: h_min/h_c 0.99 instead of 0.75 at M=100, L=10)
        c_stab = 4.0 * disc.spacing / (math.pi * scene.e_prime)
    return LineSetup(disc, comp, p_ref, h_ref, x_unit, h_est, c_stab)


def _is_linear(scene: Scene) -> bool:
    m, lub = scene.model, scene.lubricant
    return (m.elasticity == "rigid" and lub.density == "incompressible"
            and lub.viscosity_law in ("constant", "barus") and scene.load.gap is not None)


def solve_line(scene: Scene, *, boundary_pressure: tuple[float, float] | None = None) -> Result:
    """Line-contact solve (see module docstring)."""
    t0 = time.perf_counter()
    setup = line_setup(scene)
    bp = (0.0, 0.0) if boundary_pressure is None else tuple(map(float, boundary_pressure))
    if _is_linear(scene):
        return _solve_line_linear(scene, setup, bp, t0)
    return _solve_line_newton(scene, setup, bp, t0)


def _make_problem(scene: Scene, setup: LineSetup, bp, piezo_scale: float = 1.0,
                  speed_scale: float = 1.0) -> LineProblem:
    u_m = scene.kinematics.mean_speed * speed_scale
    if scene.model.elasticity == "half-space" and HALF_SPACE_STABILISATION == "upwind":
        lub = scene.lubricant
        reduced = None
        if REDUCED_POISEUILLE_LINE and lub.viscosity_law == "barus" and lub.effective_piezo > 0:
            reduced = lub.effective_piezo * piezo_scale
        flux = UpwindFluxModel.elastic(lub, u_m, setup.stab_compliance,
                                       piezo_scale=piezo_scale, reduced_alpha=reduced)
    else:
        flux = FluxModel.from_lubricant(scene.lubricant, u_m,
                                        compliance=setup.stab_compliance,
                                        piezo_scale=piezo_scale)
    return LineProblem(setup.disc, flux, scene.contact.rx, setup.compliance,
                       scene.model.cavitation, scene.load.force, scene.load.gap,
                       setup.p_ref, setup.h_ref, scene.lubricant.viscosity, bp)


# ---------------------------------------------------------------------------------------
def reduced_isoviscous_solve(problem: LineProblem, h0: float, q_bc: np.ndarray,
                             mean_speed: float, eta0: float, cavitation: str):
    """Solve the rigid isoviscous Reynolds problem for the reduced pressure q [Pa].

    One sparse solve for full-Sommerfeld; a primal-dual active-set sequence of sparse
    solves for Reynolds cavitation (q >= 0, A q - f >= 0, q (A q - f) = 0).

    Returns
    -------
    q : ndarray (nodal, Pa), linear_solves : int
    """
    ops = problem.disc.ops
    h = h0 + problem.g_q
    a = ops.flux_jacobian(0, np.zeros_like(h), (h**3 / (12.0 * eta0),)).tocsr()
    f = ops.weak_divergence(mean_speed * h)
    q, solves, _ = active_set_solve(a, f, q_bc, problem.free, cavitation)
    return q, solves


def active_set_solve(a: sp.spmatrix, f: np.ndarray, q_bc: np.ndarray, free: np.ndarray,
                     cavitation: str, max_sweeps: int = 200
                     ) -> tuple[np.ndarray, int, np.ndarray]:
    """Linear Reynolds problem A q = f with Dirichlet data, optionally with q >= 0.

    Full-Sommerfeld (``cavitation != "reynolds"``): one sparse solve on the free nodes.
    Reynolds: primal-dual active set for q >= 0, A q - f >= 0, q (A q - f) = 0 (a node
    is cavitated when its scaled multiplier (A q - f)_i / A_ii exceeds q_i); stops when
    the active set repeats, after at most ``max_sweeps`` solves.

    Parameters
    ----------
    a : sparse matrix
        Assembled Reynolds operator (nodes x nodes).
    f : ndarray
        Load vector.
    q_bc : ndarray
        Nodal vector whose entries at the non-free nodes are the Dirichlet data [Pa].
    free : ndarray of int
        Indices of the unknown nodes.
    cavitation : {"none", "reynolds"}
    max_sweeps : int

    Returns
    -------
    q : ndarray (nodal, Pa); linear_solves : int; active : bool ndarray (cavitated nodes)
    """
    n = q_bc.size
    rhs = f - a @ q_bc
    active = np.zeros(n, dtype=bool)
    diag = a.diagonal()
    q, solves = q_bc.copy(), 0
    for _ in range(max_sweeps):
        inactive = free[~active[free]]
        q = q_bc.copy()
        q[active] = 0.0
        if inactive.size:
            q[inactive] = spla.spsolve(a[inactive][:, inactive].tocsc(), rhs[inactive])
        solves += 1
        if cavitation != "reynolds":
            break
        lam = a @ q - f
        new_active = np.zeros(n, dtype=bool)
        new_active[free] = lam[free] / diag[free] > q[free]
        if np.array_equal(new_active, active):
            break
        active = new_active
    return q, solves, active


def no_solution_message(alpha: float, q_max: float) -> str:
    """Status message of a rigid Barus scene beyond Kapitsa's existence limit."""
    return (f"no solution: rigid piezo-viscous (Barus) pressure does not exist since "
            f"alpha*q_max = {alpha * q_max:.4g} >= 1 (Kapitsa transform, PHYSICS.md 5.1; "
            f"alpha = {alpha:.3g} 1/Pa, q_max = {q_max:.4g} Pa). The pressure field "
            "holds the isoviscous reduced pressure q instead.")


def pressure_from_reduced(q: np.ndarray, alpha: float, solves: int,
                          detail: str = "") -> tuple[str, np.ndarray, str]:
    """Status, nodal field and message of the linear (reduced-pressure) path.

    ``linear`` with p = -ln(1 - alpha q)/alpha while alpha q_max < 1, else
    ``no_solution`` with q itself as the (finite) field. ``detail`` is appended to the
    description of the solve in the message.
    """
    q_max = float(np.max(q))
    if alpha * q_max >= 1.0:
        return "no_solution", q, no_solution_message(alpha, q_max)
    from ..analytic import barus_from_reduced

    p = barus_from_reduced(q, alpha) if alpha > 0 else q
    return "linear", p, (f"solved by {solves} linear solve(s) (rigid, reduced pressure"
                         f"{detail}); alpha*q_max = {alpha * q_max:.3g} < 1")


def _solve_line_linear(scene: Scene, setup: LineSetup, bp, t0: float) -> Result:
    from ..analytic import reduced_from_barus

    lub = scene.lubricant
    alpha = lub.effective_piezo
    problem = _make_problem(scene, setup, bp)
    h0 = scene.load.gap
    q_bc = np.zeros(setup.disc.x.size)
    q_bc[0], q_bc[-1] = (reduced_from_barus(np.array(bp), alpha) if alpha > 0 else bp)
    q, solves = reduced_isoviscous_solve(problem, h0, q_bc, scene.kinematics.mean_speed,
                                         lub.viscosity, scene.model.cavitation)
    status, field, msg = pressure_from_reduced(q, alpha, solves)
    return _finish(scene, setup, problem, field, h0, status, msg, t0, linear_solves=solves,
                   post=status == "linear")


def _initial_guess(scene: Scene, setup: LineSetup, problem: LineProblem,
                   speed_scale: float = 1.0) -> np.ndarray:
    """Hertzian (elastic, loaded), local-dry (Kodnir) or rigid linear initial guess.

    ``speed_scale`` multiplies the entrainment speed of the film estimate (the start of
    a continuation in speed, whose film is thicker than the target's)."""
    x = setup.disc.x
    R = scene.contact.rx
    lub = scene.lubricant
    if scene.load.force is not None and scene.model.elasticity != "rigid":
        w = scene.load.force
        if scene.model.elasticity == "local":
            c = setup.stab_compliance
            a = (1.5 * R * c * w) ** (1.0 / 3.0)  # dry local contact: p = (a^2 - x^2)/(2Rc)
            p = np.maximum(a**2 - x**2, 0.0) / (2 * R * c)
        else:
            b = setup.x_unit
            p = setup.p_ref * np.sqrt(np.maximum(1.0 - (x / b) ** 2, 0.0))
        p = p * w / (problem.mass @ p)
        v0 = float(np.interp(0.0, x, problem.displacement(p)))
        h_est = setup.h_estimate
        if speed_scale != 1.0:
            from ..formulas import line_central_film_moes

            h_est = line_central_film_moes(w, R, scene.e_prime, lub.viscosity,
                                           scene.kinematics.mean_speed * speed_scale,
                                           lub.effective_piezo)
        h0 = h_est - v0
        return problem.pack(p, h0)
    # rigid or prescribed gap: isoviscous rigid solution at the (estimated) offset
    h0 = scene.load.gap if scene.load.gap is not None else setup.h_ref
    q, _ = reduced_isoviscous_solve(problem, h0, problem.p_bc.copy(),
                                    scene.kinematics.mean_speed, lub.viscosity,
                                    scene.model.cavitation)
    return problem.pack(q, h0)


#: Grid sequencing: coarsest grid of the line Newton solve (nodes). Finer grids are
#: solved coarse-to-fine, halving the spacing each level, each level started from the
#: interpolated solution of the one below (measured at M = 100, L = 10, 2001 nodes:
#: 10 + 7 + 5 iterations on 501, 1001, 2001 nodes, against 34 iterations directly on
#: 2001 nodes; the upwinded wedge flux is what lets the fine levels converge).
COARSEST_NODES = 501
#: Newton iterations allowed to the direct attempt and to each continuation step before
#: backing off (fail fast: a stalled attempt costs more than a smaller step).
ATTEMPT_ITERATIONS = 40
#: Isoviscous continuation starts at this multiple of the entrainment speed (Moes M
#: 10x lower), where the film is thick compared with the elastic deflection.
CONTINUATION_SPEED_FACTOR = 100.0


def _attempt(scene: Scene, setup: LineSetup, bp, z0: np.ndarray, max_iterations: int,
             memory: int = 5):
    """Direct damped Newton, then continuation (alpha, or speed if isoviscous) on failure.

    ``memory`` is the non-monotone line-search window of the direct attempt: 5 from a
    Hertzian guess, 1 (monotone) from a converged coarse-grid solution, which is close
    enough that a monotone search does not wander.

    Returns (z, status, iterations, history, steps, problem)."""
    sol = scene.solver
    problem = _make_problem(scene, setup, bp)
    out = damped_newton(problem, z0, tol=sol.tolerance, memory=memory,
                        max_iterations=min(max_iterations, ATTEMPT_ITERATIONS))
    history = list(out.history)
    steps = [(1.0, out.status, out.iterations)]
    if out.converged or not sol.continuation:
        return out.z, out.status, out.iterations, history, steps, problem
    piezo = scene.lubricant.effective_piezo > 0.0
    z_start = _initial_guess(scene, setup, problem,
                             speed_scale=1.0 if piezo else CONTINUATION_SPEED_FACTOR)
    if piezo:
        log.info("direct Newton %s after %d iterations; continuing in alpha", out.status,
                 out.iterations)

        def family(s: float) -> LineProblem:
            return _make_problem(scene, setup, bp, piezo_scale=s)
    else:
        # isoviscous: continue in the entrainment speed from 100x faster (thicker film,
        # lower Moes M) down to the target
        log.info("direct Newton %s after %d iterations; continuing in speed", out.status,
                 out.iterations)

        def family(s: float) -> LineProblem:
            return _make_problem(scene, setup, bp,
                                 speed_scale=CONTINUATION_SPEED_FACTOR ** (1.0 - s))
    cont = continuation(family, z_start,
                        tol=sol.tolerance,
                        max_iterations=min(max_iterations, ATTEMPT_ITERATIONS))
    iterations = out.iterations + cont.iterations
    steps += cont.steps
    history += list(cont.last.history)
    if cont.parameter >= 1.0 and cont.status == "converged":
        return cont.z, "converged", iterations, history, steps, problem
    problem.prepare(out.z)
    r_direct = np.max(np.abs(problem.residual(out.z)))
    problem.prepare(cont.z)
    r_cont = np.max(np.abs(problem.residual(cont.z))) if cont.parameter >= 1.0 else np.inf
    z = cont.z if r_cont < r_direct else out.z
    return z, cont.status if cont.status != "converged" else out.status, iterations, history, \
        steps, problem


def _line_levels(nodes: int) -> list[int]:
    """Grid sequence n_0 < n_1 < ... < nodes, halving the spacing each level."""
    levels = [nodes]
    while (levels[-1] - 1) % 2 == 0 and (levels[-1] - 1) // 2 + 1 >= COARSEST_NODES:
        levels.append((levels[-1] - 1) // 2 + 1)
    return levels[::-1]


def _transfer(z: np.ndarray, coarse: LineProblem, fine: LineProblem) -> np.ndarray:
    """Interpolate a converged coarse solution to a finer grid (same film at x = 0)."""
    p_c, h0_c = coarse.unpack(z)
    xc, xf = coarse.disc.x, fine.disc.x
    p_f = np.interp(xf, xc, p_c)
    hc = float(np.interp(0.0, xc, coarse.film_nodes(p_c, h0_c)))
    if fine.has_h0:
        h0_f = hc - float(np.interp(0.0, xf, fine.g_nodes + fine.displacement(p_f)))
    else:
        h0_f = h0_c
    return fine.pack(p_f, h0_f)


def _solve_line_newton(scene: Scene, setup: LineSetup, bp, t0: float) -> Result:
    """Damped Newton with grid sequencing (coarse solve, interpolate, few fine steps)."""
    sol = scene.solver
    levels = _line_levels(setup.disc.x.size)
    iterations, history, steps = 0, [], []
    z = None
    prev_problem = None
    status = "max_iterations"
    for level, n in enumerate(levels):
        lvl_setup = setup if n == setup.disc.x.size else _coarsened(scene, setup, n)
        problem = _make_problem(scene, lvl_setup, bp)
        z0 = _initial_guess(scene, lvl_setup, problem) if z is None else \
            _transfer(z, prev_problem, problem)
        z, status, it, hist, st, problem = _attempt(scene, lvl_setup, bp, z0,
                                                    sol.max_iterations,
                                                    memory=5 if level == 0 else 1)
        iterations += it
        history += hist
        steps += [(s, f"{stat} ({n} nodes)", i) for s, stat, i in st]
        prev_problem = problem
        if status != "converged":
            break
    if status != "converged" or len(levels) == 0 or prev_problem.disc.x.size != setup.disc.x.size:
        # fall back to the fine grid alone when a coarse level failed
        if status != "converged" and len(levels) > 1:
            problem = _make_problem(scene, setup, bp)
            z0 = _initial_guess(scene, setup, problem)
            z, status, it, hist, st, problem = _attempt(scene, setup, bp, z0, sol.max_iterations)
            iterations += it
            history += hist
            steps += [(s, f"{stat} ({setup.disc.x.size} nodes)", i) for s, stat, i in st]
    p, h0 = problem.unpack(z)
    problem.prepare(z)
    resid = float(np.max(np.abs(problem.residual(z))))
    n_cont = sum(1 for s in steps if s[0] < 1.0)
    what = "alpha" if scene.lubricant.effective_piezo > 0 else "speed"
    cont_note = f", continuation in {what} ({n_cont} steps)" if n_cont else ""
    msg = outcome_message(status, iterations, resid, sol.tolerance,
                          detail=f" (grids {levels}{cont_note})", cap=sol.max_iterations)
    if scene.model.cavitation == "reynolds":
        p = np.maximum(p, 0.0)  # the FB solution is >= 0 up to the tolerance
    return _finish(scene, setup, problem, p, h0, status, msg, t0, iterations=iterations,
                   history=history, continuation_steps=steps)


def _coarsened(scene: Scene, setup: LineSetup, nodes: int) -> LineSetup:
    """The same scene on a coarser uniform grid over the same interval."""
    from dataclasses import replace as dc_replace

    from ..physics import elasticity

    x = setup.disc.x
    disc = LineDiscretisation.uniform(float(x[0]), float(x[-1]), nodes)
    comp = setup.compliance
    if scene.model.elasticity == "half-space":
        comp = elasticity.HalfSpaceLine(disc.x, scene.e_prime, method="dense")
    return dc_replace(setup, disc=disc, compliance=comp)


def _finish(scene: Scene, setup: LineSetup, problem: LineProblem, p: np.ndarray, h0: float,
            status: str, message: str, t0: float, *, iterations: int = 0, linear_solves: int = 0,
            history=None, continuation_steps=None, post: bool = True) -> Result:
    from .. import post as pp

    disc = setup.disc
    ops = disc.ops
    h_nodes = problem.film_nodes(p, h0)
    pq, h_q, px, _ = problem.fields_q(p, h0)
    quantities: dict[str, float] = {}
    extra: dict[str, np.ndarray] = {}
    if post:
        quantities.update(pp.film_quantities(disc.x, p, h_nodes, ops, h_q))
        outlet = pp.outlet_position_line(disc.x, p, scene.model.cavitation)
        ind = pp.full_film_indicator_line(ops.points[0], outlet)
        eta_q = problem.flux.viscosity(pq)
        quantities.update(pp.friction_and_heat(ops, h_q, (px,), eta_q,
                                               scene.kinematics.sliding_speed, ind,
                                               quantities["load"]))
        if outlet is not None:
            quantities["outlet_position"] = outlet
            quantities["h_outlet"] = float(np.interp(outlet, disc.x, h_nodes))
        nodes_eta = problem.flux.viscosity(p)
        extra["viscosity_Pa_s"] = nodes_eta
        if scene.traction.model != "newtonian":
            _non_newtonian_couette(scene, disc.x, p, h_nodes, nodes_eta, outlet, quantities)
    success = status in ("converged", "linear")
    return Result(success=success, status=status, message=message, scene=scene, x=disc.x,
                  pressure=p, film=h_nodes, h0=float(h0), quantities=quantities,
                  history=list(history or []), newton_iterations=iterations,
                  linear_solves=linear_solves, wall_time_s=time.perf_counter() - t0,
                  continuation=list(continuation_steps or []), extra_fields=extra)


def _non_newtonian_couette(scene: Scene, x: np.ndarray, p: np.ndarray, h: np.ndarray,
                           eta: np.ndarray, outlet: float | None, q: dict) -> None:
    """Replace the Newtonian Couette friction and heat by the scene's traction model
    (Eyring or limiting shear stress, :mod:`bearing_fem.physics.traction`); the Poiseuille parts
    stay as computed."""
    from ..physics.traction import _model_kwargs, couette_line

    xm = 0.5 * (x[1:] + x[:-1])
    ind = np.ones_like(xm) if outlet is None else (xm <= outlet).astype(float)
    f_c, q_c = couette_line(x, p, h, eta, scene.kinematics.sliding_speed, indicator=ind,
                            **_model_kwargs(scene.traction))
    f_p = q["rolling_resistance"]
    q.update(sliding_friction=f_c, friction_force=f_p + f_c, friction_force_surface2=f_p - f_c,
             friction_coefficient=(f_p + f_c) / q["load"] if q["load"] > 0 else 0.0,
             heat_power_couette=q_c, heat_power=q_c + q["heat_power_poiseuille"])

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

Reynolds (docs/theory.md section 11): div(eps grad p) = u_m d(rho h)/dx + rho dh0/dt. Weak form,
for every test function phi vanishing on the boundary,

    R(phi) = int F . grad phi + int rho (dh0/dt) phi = 0,   F = eps grad p - u_m rho h e_x

(+ an upwinded wedge term in F for elastic scenes, :class:`UpwindFluxModel`).

Two paths (a scene pays only for what it needs):

* **linear** - rigid, incompressible, prescribed gap, constant or Barus viscosity (or
  Roelands with Reynolds cavitation, whose reduced pressure is bounded by q_inf): the
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
  (coarse solve, bilinear interpolation, few fine steps) and continuation in alpha by
  the shared driver (:mod:`bearing_fem.contacts.driver`), warm-started from the
  interpolated solution on finer grids (:data:`POINT_DRIVER`).
"""
from __future__ import annotations

import functools
import logging
import math
import time
import weakref
from dataclasses import dataclass, replace
from typing import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from .. import units
from ..analytic import kapitsa_point_exterior_load, kapitsa_point_pressure
from ..errors import SceneError
from ..formulas import point_central_film_nvm
from ..mesh import every_other
from ..numerics.newton import ForcingTerm, blas_threads, gmres_right
from ..physics.elasticity import HalfSpacePoint, MirroredHalfSpacePoint
from ..physics.reynolds import FluxModel, UpwindFluxModel
from ..post import film_numbers, friction_and_heat, reported_viscosity
from ..result import Result
from ..validation import require_finite, require_int, require_positive
from ..scene import Scene
from .driver import (DriverSettings, Progress, Solution, overload_result,
                     solve_linear_model, solve_newton_model)
from .linear import (active_set_solve, is_linear_scene, is_rigid_barus_load,
                     pressure_from_reduced, reduced_law)
from .point_grid import (LU_PIVOT_THRESHOLD, FreePattern, PointGrid, graded_coordinates,
                         require_finite_factor_data)
from .problem import FB_SMOOTHING, ScaledResidual, fischer_burmeister

log = logging.getLogger(__name__)

#: Default rigid-scene domain, in units of sqrt(2 rx h0) (x) and sqrt(2 ry h0) (y).
#: docs/theory.md section 14.2: a free inlet needs X <= -30 in 2D for the load within ~0.3%.
RIGID_RANGE_FS = ((-30.0, 30.0), (-30.0, 30.0))
RIGID_RANGE_REYNOLDS = ((-30.0, 8.0), (-30.0, 30.0))
#: Default rigid grid (sinh-graded, nodes per direction).
RIGID_NODES = 161
#: Default elastic grid (uniform, nodes per direction) and domain in Hertz semi-axes.
ELASTIC_NODES = 129
ELASTIC_RANGE = ((-4.5, 1.5), (-3.0, 3.0))
#: Grid sequencing: coarsest grid (nodes per direction) of the elastic Newton solve.
COARSEST_NODES = 65
#: Largest grid (nodes per direction) the driver solves first when the requested grid
#: fails alone (``PointModel.refine``): requested grids up to 129^2 (257^2 costs ~2 s).
REFINE_MAX_NODES = 257
#: Outlet end of the default elastic point domain at light load, in hydrodynamic lengths
#: sqrt(2 rx h) of the estimated central film (the line contacts' rule,
#: :data:`bearing_fem.contacts.line.OUTLET_HYDRO_LENGTHS`): where the film's pressure zone
#: reaches beyond the 1.5 a_x of an EHL contact, the domain keeps the part of it that
#: carries the load (a rigid ball's side lobes reach 4.6 lengths downstream but carry
#: 1.6e-4 of the load beyond one length; 12.7 mm steel ball at 0.3 N, 2 m/s, 0.05 Pa s:
#: the outlet at 1.5 a_x cut the pressure zone, h_central 2.405e-6 m against 2.558e-6 m
#: with the outlet at 1, 2 or 4 lengths).
OUTLET_HYDRO_LENGTHS = 1.0
#: Moes M below which a loaded elastic scene solved on the default domain without
#: Kapitsa's far field on its edges (full-Sommerfeld; :data:`FAR_FIELD_MOES_M`) is warned
#: that the domain truncates its pressure field: the film of a lightly loaded contact
#: spreads its pressure over tens of hydrodynamic lengths (a rigid film needs an inlet of
#: 30 of them, docs/theory.md section 14.2), beyond the default inlet of 8 and sides of 4.
#: Measured, 10 mm ball, 1 m/s, 0.01 Pa s, h_central on the default domain against the
#: domain 4 times longer at the inlet and 4 times wider (257^2), both with p = 0 on the
#: edges: Reynolds outlet, isoviscous -28.2 %, -24.5 %, -5.7 %, -2.1 %, -1.4 % at
#: M = 0.87, 2.6, 5.2, 8.7, 17.4 (which the far field now removes); full-Sommerfeld
#: -69 %, -23 %, -2.1 % at M = 0.52, 2.6, 8.7 (129^2 against 257^2). Between this M and
#: FAR_FIELD_MOES_M full-Sommerfeld balls go unwarned: -2.1 %, -1.5 %, -1.4 % at M = 8.7,
#: 12.2, 14.8 (tests/test_point_far_field.py), below the 5 % at which a quantity's error
#: is warned and like the Reynolds-outlet balls above FAR_FIELD_MOES_M.
LIGHT_LOAD_MOES_M = 8.0
#: Moes M below which a loaded elastic scene on the default domain (with the Reynolds
#: outlet) takes Kapitsa's far field on its edges and adds that film's load beyond them,
#: as rigid scenes do (:func:`far_field_data`): lighter contacts spread their pressure
#: far beyond the default domain. Measured (10 mm ball, 1 m/s, 0.01 Pa s;
#: tests/test_point_far_field.py): h_central of the default domain against a domain 4
#: times longer at the inlet and 4 times wider, both with the far field, -2.3 %, -2.1 %,
#: -0.6 %, -0.2 % isoviscous at M = 0.52, 2.6, 5.2, 8.7 (Barus, 2e-8 1/Pa: -2.3 %,
#: -1.8 %, +0.4 %, -0.9 %), where p = 0 on both domains' edges gave up to -28 %, and the
#: default domain with p = 0 against the wide one with the far field -32 % at M = 2.6.
#: 15 % of the load lies beyond the default domain at M = 2.6, 8 % at M = 8.7. From
#: M = 15 on, the default domain keeps p = 0 on its edges, as the multigrid references of
#: the maps (M = 20 and more) do: against a domain 4 times longer and wider (p = 0 too)
#: its h_central differs by -1.4 %, -1.3 %, -0.6 %, -0.5 % at M = 17.4, 20, 30, 60
#: isoviscous (Barus: -0.6 %, -0.7 %, -0.9 % at M = 17.4, 20, 30), an error the error
#: estimate does not contain; h_central steps by -1.3 % isoviscous (Barus -0.2 %) from
#: M = 14.999 to 15.001.
FAR_FIELD_MOES_M = 15.0
#: Moes M above which isoviscous scenes take a narrower default domain (below).
HIGH_LOAD_MOES_M = 1000.0
#: Default domain of isoviscous elastic scenes above HIGH_LOAD_MOES_M, in Hertz
#: semi-axes: [-ISOVISCOUS_HIGH_LOAD_INLET, ISOVISCOUS_HIGH_LOAD_OUTLET] x [-side, side]
#: with side = ISOVISCOUS_HIGH_LOAD_SIDE (the inlet end at least 8 hydrodynamic lengths
#: sqrt(2 rx h) beyond the Hertz edge), instead of ELASTIC_RANGE: without
#: piezo-viscosity the inlet pressure builds up within a few hydrodynamic lengths of the
#: contact, and the narrow domain puts 2.2 times the nodes per Hertz radius on the same
#: grid. Measured: M = 2000, L = 0 stalled on ELASTIC_RANGE at 97^2 (atlas) and 129^2
#: (from 65^2 or 129^2); on the narrow domain it converges on 97^2, 129^2 and 257^2, as
#: M = 1160 does. At M = 500, L = 0 the two domains agree to 0.4 % in h_central
#: (narrow 129^2 against ELASTIC_RANGE 257^2, about the same spacing). Piezo-viscous
#: scenes keep ELASTIC_RANGE: at M = 500, L = 10.7 and 17.9 the narrow inlet lowers
#: h_central by 5-7 % (starved).
ISOVISCOUS_HIGH_LOAD_INLET = 1.5
ISOVISCOUS_HIGH_LOAD_OUTLET = 1.2
ISOVISCOUS_HIGH_LOAD_SIDE = 1.5
#: Largest Moes M of the circular map on which the default elastic set-up (domain, grid
#: sequence, continuation) is checked (``studies/stability_atlas.py``: 100 % up to
#: M = 2000). Above it a piezo-viscous scene may stall on the default domain, whose inlet
#: then holds the narrow pressure build-up in a few cells; such a failure is followed by
#: one more solve on HIGH_LOAD_RANGES with HIGH_LOAD_NODES (:func:`solve_point`), said in
#: the message and the warnings. Measured, every default 129^2 solve stalled (and the
#: finer-grid fallback with it), HIGH_LOAD_RANGES on 257^2 converged: 100 N steel balls
#: (rx = ry = 10 mm, eta0 = 0.01 Pa s, alpha = 2e-8 1/Pa) at u_m = 0.05 and 0.02 m/s
#: (M = 8.2e3, 1.6e4; at 0.1 m/s, M = 4.9e3, the 257^2 default grid converges and is
#: returned); 1000 N at 0.5 m/s (M = 1.5e4); a 5 mm ball, 50 N, 0.05 m/s (M = 9.8e3); an
#: ellipse ry/rx = 4, 300 N, at 0.1 and 0.03 m/s (M = 1.5e4, 3.6e4). Neither converged
#: for the 100 N ball at 0.01 and 0.005 m/s (M = 2.7e4, 4.6e4) nor for 1000 N at 0.2 m/s
#: (M = 2.9e4).
CHECKED_MOES_M = 2000.0
#: The narrower domain [Hertz semi-axes] and the grid of that second solve. The short
#: inlet starves a strongly piezo-viscous contact a little (measured h_central on 257^2:
#: -0.35 % against [-3.5, 1.2] at M = 2000, L = 10.7; -0.9 % against the default domain
#: at M = 500, L = 17.9), an error the grid error estimate does not contain: the result
#: says so in its warnings.
HIGH_LOAD_RANGES = ((-2.5, 1.2), (-1.5, 1.5))
HIGH_LOAD_NODES = 257
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
#: Line search on finer levels (from an interpolated solution): monotone (window 1), as
#: for line contacts. Measured on 257^2 (Newton iterations of the whole sequence, window 5
#: -> 1): (M, L) = (100, 10) 27 -> 26, (50, 20) 43 -> 39, (100, 20) 46 -> 39, (500, 10)
#: 24 -> 23, (20, 20), (1000, 10), (200, 5) unchanged; on 513^2: (100, 10) 36 -> 33,
#: (50, 20) 58 -> 52, (20, 20) 50 -> 51.
TRANSFER_MEMORY = 1
WARM_START_ALPHA = 0.8
#: Isoviscous elastic continuation starts at this multiple of the entrainment speed
#: (Moes M 30x lower), where the film is thick compared with the elastic deflection
#: (as for line contacts). Measured: M = 1160 and 2000, L = 0 on 97^2 stalled from the
#: Hertzian start with no continuation (``studies/stability_atlas.py``).
CONTINUATION_SPEED_FACTOR = 100.0
#: Newton tolerance of the coarser levels of the grid sequence (the finest level uses
#: ``solver.tolerance``). Measured M = 100, L = 10: the first residual on 129^2 / 257^2
#: after interpolation is 1.3e-2 / 5.1e-3 when the coarser level stops at 1e-5 and
#: 1.3e-2 / 4.5e-3 when it stops at 1e-8: the interpolation error dominates. With
#: 1e-4 the first residual on 513^2 is the same (6.6e-4 after the first step, with
#: the coarser level stopped at 1e-4 or 1e-5), the 257^2 level of a 513^2 solve takes
#: 5 instead of 6 iterations (0.4 s less) and the finest films agree to 1e-7.
COARSE_TOLERANCE = 1e-4
#: Newton tolerance of intermediate continuation steps (s < 1): they only provide the
#: start of the next step.
INTERMEDIATE_TOLERANCE = 1e-5
#: GMRES relative tolerance (floor) and iteration cap of the elastic Newton steps.
GMRES_RTOL = 1e-9
GMRES_MAX_ITERATIONS = 150
#: Residual and Jacobian are evaluated on blocks of cell rows of about this many
#: quadrature points (the same sums as on whole arrays): the temporaries of the flux and
#: its derivatives (some 40 arrays) stay small, e.g. ~25 MB instead of ~500 MB on the
#: 513 x 257 half grid, and fit the processor caches.
CHUNK_POINTS = 2**16
#: The near-field LU of elastic problems (a GMRES preconditioner) in single precision:
#: measured on the 513 x 257 half grid (M = 100, L = 10, a mid-level Newton iterate,
#: GMRES to 1e-6): 34 GMRES iterations with the float64 and with the float32 factors,
#: factorisation 0.38 -> 0.28 s, solve 22 -> 16 ms, factors 134 -> 82 MB. The
#: preconditioner's error is dominated by the truncated compliance (near field C_00
#: only), not by the factorisation: an incomplete LU with half the fill (drop 1e-3)
#: also needed 34 iterations. GMRES stores the Krylov basis and forms M^-1 (V y) in
#: float64; the Newton residual is always evaluated in float64.
PRECONDITIONER_SINGLE = True
#: ... and incomplete: entries below this fraction of their column's norm are dropped
#: (SuperLU ILU; 0: complete LU). Measured on the same iterate: 35 GMRES iterations with
#: the complete and the incomplete float32 factors (drop 1e-3: 5.8e6 instead of 1.02e7
#: nonzeros, solve 11.5 instead of 18 ms, peak memory of the step 366 instead of 454 MB);
#: drop 1e-2 needed 52.
PRECONDITIONER_DROP_TOL = 1e-3
#: Inexact Newton: GMRES stops at the relative residual eta_k = min(GMRES_FORCING_MAX,
#: max(GMRES_RTOL, f_k)) (and the GMRES_TOLERANCE_FRACTION floor below), f_k the forcing
#: term of GMRES_FORCING: Eisenstat & Walker (1996), choice 2 (the default), else |F_k|_inf
#: (Dembo, Eisenstat & Steihaug 1982). Either keeps the local quadratic convergence, and
#: the Newton stopping test (|F| <= tol) is untouched. GMRES gains about one decade per 5
#: iterations here, so the early steps save ~25 of ~40 iterations. Measured M = 100,
#: L = 10, 257^2, when |F_k|_inf with the cap 1e-3 was introduced: Newton iterations
#: 25 -> 25, GMRES 701 -> 302, h_c/h_min equal to 11 digits, p_max to 10; with
#: Eisenstat-Walker and the cap 0.1: 24 Newton and 173 GMRES iterations (with
#: |F_k|_inf capped at 1e-3: 25 and 276). 0 disables.
GMRES_FORCING_MAX = 1e-1
#: The near-field factors of a Newton step are kept for the next steps of the same
#: problem while GMRES needed at most this many iterations with them.
PRECONDITIONER_KEEP_ITERATIONS = 6
#: ... and at most PRECONDITIONER_KEEP_ITERATIONS_LARGE on grids of at least
#: PRECONDITIONER_LARGE_UNKNOWNS free nodes, where a factorisation costs many GMRES
#: iterations (on the 513 x 257 half grid ~0.33 s against ~25 ms; its cost grows faster
#: than a GMRES iteration's). Measured M = 100, L = 10 at 513^2: 12 instead of 6 keeps 4
#: instead of 6 fine-grid factorisations for 245 instead of 196 GMRES iterations, 3-4%
#: less CPU time, same Newton iterations; 20 (3 factorisations, 308 iterations) gained
#: nothing more. On every grid (65^2 included) 12 changed the inexact Newton path of
#: the coarsest level at M = 1000, L = 10 (+8 iterations of the sequence at 257^2),
#: where a factorisation costs milliseconds.
PRECONDITIONER_KEEP_ITERATIONS_LARGE = 12
PRECONDITIONER_LARGE_UNKNOWNS = 30_000
#: Forcing term of the inexact Newton steps (GMRES_FORCING_MAX): "eisenstat-walker"
#: (:class:`~bearing_fem.numerics.newton.ForcingTerm`), anything else |F_k|_inf.
GMRES_FORCING = "eisenstat-walker"
#: The linear solve need not be more accurate than the Newton test can see: eta_k is also
#: allowed up to GMRES_TOLERANCE_FRACTION tol / |F_k|_2, so the linear residual left in the
#: step (<= eta_k |F_k|_2, which bounds its max norm) stays below this fraction of the
#: Newton tolerance. Only the last one or two steps are affected (where |F_k| is within a
#: few decades of tol); there GMRES stops after ~10 instead of 30-40 iterations.
GMRES_TOLERANCE_FRACTION = 0.1

#: BLAS threads inside a point solve (restored afterwards). Its dense work is small
#: (vectors of one grid, (cells x 9) by (9 x 16) products), where the threads' start-up
#: and synchronisation cost more than they save, and far more on a busy machine: measured
#: on 2 cores with two other jobs, (131072 x 4) @ (4 x 9) took 57 ms with the default
#: threads and 0.85 ms with one. None: leave the process setting alone.
BLAS_THREADS = 1

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


def _moes_point_m(scene) -> float:
    """Moes load parameter M of a loaded point scene [-]."""
    c, lub = scene.contact, scene.lubricant
    return units.moes_point(scene.load.force, c.rx, c.ry, scene.e_prime, lub.viscosity,
                            scene.kinematics.mean_speed, lub.effective_piezo)["M"]


def _mirrorable(y_range: tuple[float, float], ny: int) -> bool:
    """True if a uniform grid of ``ny`` nodes on ``y_range`` has a node row at y = 0 and
    is symmetric about it."""
    return y_range[0] == -y_range[1] and ny % 2 == 1


def _light_load_pressure_scale(force: float, rx: float, ry: float, p_h: float,
                              h_est: float) -> float:
    """Pressure scale [Pa] of a loaded elastic point scene: the Hertz pressure p_h, or,
    where smaller, the load over 2 pi times the hydrodynamic area sqrt(2 rx h)
    sqrt(2 ry h) / 2 of the estimated central film h.

    At light load (Moes M below ~1) the film carries its load far outside the Hertz
    ellipse, its pressures are orders of magnitude below p_h, and a scale of p_h made the
    scaled Newton residual and the cavitation complementarity blind to them: at M = 0.01
    (p_max ~ 1e-7 p_h) a ball's h_central came out 10 times its rigid value with an error
    estimate of 59 %; with this scale it is 0.967 times the rigid value at M = 0.01 to 1,
    as the self-similar film must be (tests/test_point_far_field.py). For the rigid
    isoviscous ball the scale is about 1.3 p_max; from Moes M ~ 2 on, results are the
    same as with p_h to 1e-8."""
    return min(p_h, force / (2.0 * math.pi * math.sqrt(rx * ry) * h_est))


def default_ranges(scene) -> tuple[tuple[float, float], tuple[float, float]]:
    """The default domain of a loaded elastic point scene, the one :func:`point_setup`
    takes when ``scene.mesh`` gives no ``x_range`` or ``y_range``.

    Parameters
    ----------
    scene : Scene
        A point scene with ``load.force`` [N] and an elastic model.

    Returns
    -------
    x_range, y_range : (float, float)
        In Hertz semi-axes a_x, a_y [-]: the fully flooded inlet, 4.5 a_x or 8
        hydrodynamic lengths sqrt(2 rx h) at low load, to the outlet at 1.5 a_x or, at
        low load, :data:`OUTLET_HYDRO_LENGTHS` hydrodynamic lengths, and
        y in +-max(3, inlet/2); an isoviscous scene above :data:`HIGH_LOAD_MOES_M` takes
        the shorter inlet max(:data:`ISOVISCOUS_HIGH_LOAD_INLET`, 1 + 8 sqrt(2 rx h)/a_x),
        the outlet :data:`ISOVISCOUS_HIGH_LOAD_OUTLET` and y in
        +-:data:`ISOVISCOUS_HIGH_LOAD_SIDE`.
    """
    rx, ry, lub = scene.contact.rx, scene.contact.ry, scene.lubricant
    F = scene.load.force
    hz = units.hertz_point(F, rx, ry, scene.e_prime)
    h_est = point_central_film_nvm(F, rx, ry, scene.e_prime, lub.viscosity,
                                   scene.kinematics.mean_speed, lub.effective_piezo)
    # fully flooded inlet: 4.5 a, or 8 hydrodynamic lengths sqrt(2 rx h) at low load
    length = math.sqrt(2 * rx * h_est) / hz.a_x
    hydro = 8.0 * length
    inlet = max(4.5, hydro)
    side = max(3.0, 0.5 * inlet)
    # the outlet at 1.5 a_x, or beyond the rigid (Kapitsa) outlet at low load
    outlet = max(1.5, OUTLET_HYDRO_LENGTHS * length)
    if lub.effective_piezo == 0.0 and _moes_point_m(scene) > HIGH_LOAD_MOES_M:
        inlet = max(ISOVISCOUS_HIGH_LOAD_INLET, 1.0 + hydro)
        outlet, side = ISOVISCOUS_HIGH_LOAD_OUTLET, ISOVISCOUS_HIGH_LOAD_SIDE
    return (-inlet, outlet), (-side, side)


def point_setup(scene, nodes: tuple[int, int] | None = None,
                symmetric: bool = False) -> PointSetup:
    """Reference scales, default grid and compliance of a point scene.

    Rigid scenes: lengths in sqrt(2 rx h0) (x) and sqrt(2 ry h0) (y), sinh-graded grid.
    Elastic scenes: lengths in the Hertz semi-axes a_x, a_y, uniform grid (FFT compliance).
    ``nodes`` overrides ``scene.mesh.nodes`` (grid sequencing). ``symmetric`` (elastic
    scenes under load with a y-symmetric grid, see :meth:`PointModel._symmetric`): the half grid
    y >= 0 with :class:`~bearing_fem.physics.elasticity.MirroredHalfSpacePoint`; ``nodes`` still
    counts the whole grid.
    """
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
        p_ref, h_ref = _light_load_pressure_scale(F, rx, ry, hz.p_h, h_est), h_est
        default_x, default_y = default_ranges(scene)
        xr = scene.mesh.x_range or default_x
        yr = scene.mesh.y_range or default_y
        axes = _file_axes(scene, nodes, x_unit, y_unit)
        if axes is not None:
            x, y = axes
            for name, v in (("x", x), ("y", y)):
                if np.ptp(np.diff(v)) > 1e-6 * np.mean(np.diff(v)):
                    raise SceneError(f"mesh.file {scene.mesh.file!r}: an elastic point contact "
                                     f"needs uniformly spaced {name} nodes (the FFT "
                                     "half-space compliance)")
            mirrored = bool(y.size % 2 == 1 and np.allclose(y, -y[::-1], rtol=0,
                                                            atol=1e-12 * np.ptp(y)))
            if mirrored:
                y = 0.5 * (y - y[::-1])  # exactly symmetric
            y_half = y[y.size // 2:]
            if symmetric and not mirrored:
                raise ValueError("a symmetric point setup needs a grid symmetric about y = 0 "
                                 "with an odd node count across")
        else:
            nxy = nodes or _nodes(scene, ELASTIC_NODES)
            x = np.linspace(xr[0] * x_unit, xr[1] * x_unit, nxy[0])
            if _mirrorable(yr, nxy[1]):  # rows mirror each other exactly about y = 0
                y_half = np.linspace(0.0, yr[1] * y_unit, (nxy[1] + 1) // 2)
                y = np.concatenate([-y_half[:0:-1], y_half])
            elif symmetric:
                raise ValueError(f"a symmetric point setup needs mesh.y_range symmetric "
                                 f"about 0 and an odd node count across, got {yr} and "
                                 f"{nxy[1]}")
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
        # rigid under load: pressure scale eta0 u_m Lx/h0^2 on an area Lx Ly,
        # Lx = sqrt(2 rx h0), Ly = sqrt(2 ry h0)  ->  F = 2 sqrt(2) eta0 u_m rx sqrt(ry)
        # I / sqrt(h0), I the isoviscous load integral (Reynolds outlet); this h0 sets the
        # domain, so it has to be the film's own gap, not only its order of magnitude
        k = 2.0 * math.sqrt(2.0) * lub.viscosity * u_m * rx * math.sqrt(ry)
        if model.cavitation == "reynolds":
            k *= rigid_isoviscous_load_integral(ry / rx)
        h0 = (k / scene.load.force) ** 2
    x_unit, y_unit = math.sqrt(2 * rx * h0), math.sqrt(2 * ry * h0)
    p_ref = lub.viscosity * u_m * x_unit / h0**2
    rng = RIGID_RANGE_FS if model.cavitation == "none" else RIGID_RANGE_REYNOLDS
    xr = scene.mesh.x_range or rng[0]
    yr = scene.mesh.y_range or rng[1]
    nxy = nodes or _nodes(scene, RIGID_NODES)
    uniform = scene.mesh.x_range is not None or scene.mesh.y_range is not None
    axes = _file_axes(scene, nodes, x_unit, y_unit)
    if axes is not None:  # a grid file
        gx, gy = axes
    elif uniform:  # an explicit range asks for a uniform grid (convergence studies)
        gx = np.linspace(xr[0] * x_unit, xr[1] * x_unit, nxy[0])
        gy = np.linspace(yr[0] * y_unit, yr[1] * y_unit, nxy[1])
    else:
        gx = graded_coordinates(xr[0], xr[1], nxy[0], x_unit, stretch=1.5)
        gy = graded_coordinates(yr[0], yr[1], nxy[1], y_unit, stretch=1.5)
    grid = PointGrid.tensor(gx, gy)
    return PointSetup(grid, None, p_ref, h0, x_unit, y_unit, h0, 0.0, None)


def _file_axes(scene, nodes: tuple[int, int] | None, x_unit: float,
               y_unit: float) -> tuple[np.ndarray, np.ndarray] | None:
    """The grid of ``mesh.file`` in metres (every other node for a coarser level of
    ``nodes``), or None without a file."""
    axes = scene.mesh.axes()
    if axes is None:
        return None
    xf, yf = axes
    n = nodes or (xf.size, yf.size)
    return every_other(xf, n[0]) * x_unit, every_other(yf, n[1]) * y_unit


def is_linear(scene) -> bool:
    """True if a point scene is solved by linear solves of the reduced pressure
    (:func:`bearing_fem.contacts.linear.is_linear_scene`)."""
    return is_linear_scene(scene)


def boundary_values(grid: PointGrid, boundary_pressure) -> np.ndarray:
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


def far_field_applies(scene: Scene, grid: PointGrid) -> bool:
    """True for a rigid point scene, or an elastic one under a load below
    :data:`FAR_FIELD_MOES_M`, with the Reynolds outlet and a rolling speed on its
    default domain (no ``mesh.x_range``, ``mesh.y_range`` or ``mesh.file``), which
    contains the contact centre (x0 < 0 < x1, y0 < 0 < y1; a half grid y >= 0 stands for
    the whole): the scenes whose film is fully flooded, its far field Kapitsa's inlet
    film (:func:`far_field_data`). A given domain keeps p = 0 on its edges: an inlet
    meniscus there, or a convergence study."""
    mesh = scene.mesh
    y0, y1 = grid.whole_y_range
    return (_far_field_model(scene) and scene.model.cavitation == "reynolds"
            and scene.kinematics.mean_speed > 0.0 and mesh.x_range is None
            and mesh.y_range is None and mesh.file is None
            and grid.x[0] < 0.0 < grid.x[-1] and y0 < 0.0 < y1)


def _far_field_model(scene: Scene) -> bool:
    """Rigid, or elastic under a load below :data:`FAR_FIELD_MOES_M`."""
    if scene.model.elasticity == "rigid":
        return True
    return (scene.model.elasticity == "half-space" and scene.load.force is not None
            and _moes_point_m(scene) < FAR_FIELD_MOES_M)


def far_field_data(scene: Scene, grid: PointGrid, h0: float,
                   from_reduced: Callable[[np.ndarray], np.ndarray]
                   ) -> tuple[np.ndarray, float]:
    """Edge data and the load beyond the domain of a rigid point film with the Reynolds
    outlet (:func:`far_field_applies`).

    Far from the contact the reduced pressure of the rigid film is Kapitsa's
    full-Sommerfeld one on the inlet side, q = A x/h^2 ~ x/r^4, and zero (cavitated)
    downstream. It decays so slowly that p = 0 on the edges of the default domain
    [-30, 8] x [-30, 30] sqrt(2 rx h0), sqrt(2 ry h0) cost a ball 5 % of its load. So the
    edges take max(q, 0) of Kapitsa's film, and the load of that film beyond the edges
    (:func:`bearing_fem.analytic.kapitsa_point_exterior_load`, with the viscosity law's
    p(q)) is added to the load. On the edges of a domain many film lengths long the gap
    is x^2/(2 rx) + y^2/(2 ry) to within h0/(that): the data of a scene under a load,
    whose gap is unknown, are taken at the gap that scaled its domain, which on the
    default domain (h = 900 h_ref and more on the inlet and side edges) moves the edge
    values by 0.1 to 0.2 % (q ~ 1/h^2) and the load beyond the domain by 0.06 % per
    factor 2 in h0 (tests/test_point_rigid_barus.py).

    A lightly loaded elastic scene (:data:`FAR_FIELD_MOES_M`) takes the same data at its
    central-film estimate (``PointSetup.h_ref``): its edges lie only 4 to 8 hydrodynamic
    lengths out, where the rigid gap is 17 h0 and more and the elastic deflection is
    left out; measured on a 10 mm ball at M = 0.52 and 2.6 a factor 2 in that gap moves
    h_central by 1.3 to 1.5 % (0.1 % at M = 8.7), and the default domain's h_central
    lies within 2.3 % of a domain 4 times longer and wider
    (tests/test_point_far_field.py).

    Parameters
    ----------
    scene : Scene
        Rigid, or elastic and lightly loaded.
    grid : PointGrid
    h0 : float
        Central gap of the film [m] (the scene's gap, or the scale of its domain).
    from_reduced : callable
        The viscosity law's p(q) [Pa] (``linear.reduced_law(...).from_reduced``).

    Returns
    -------
    q_bc : ndarray
        Flat nodal reduced pressure [Pa] on the boundary nodes (zero elsewhere).
    exterior : float
        The film's load beyond the domain [N].
    """
    c, lub = scene.contact, scene.lubricant
    u_m = scene.kinematics.mean_speed
    q_bc = _kapitsa_edges(grid, h0, c.rx, c.ry, lub.viscosity, u_m)
    exterior = kapitsa_point_exterior_load((float(grid.x[0]), float(grid.x[-1])),
                                           grid.whole_y_range, h0,
                                           0.5 / c.rx, 0.5 / c.ry, lub.viscosity, u_m,
                                           from_reduced=from_reduced)
    return q_bc, exterior


def _kapitsa_edges(grid: PointGrid, h0: float, rx: float, ry: float, viscosity: float,
                   mean_speed: float) -> np.ndarray:
    """Flat nodal max(q, 0) of Kapitsa's isoviscous full-Sommerfeld film [Pa] on the
    boundary nodes of ``grid`` (zero elsewhere)."""
    q_bc = np.zeros(grid.size)
    mask = grid.boundary_mask()
    X, Y = grid.node_coordinates()
    q_bc[mask] = np.maximum(kapitsa_point_pressure(X[mask], Y[mask], h0, 0.5 / rx,
                                                   0.5 / ry, viscosity, mean_speed), 0.0)
    return q_bc


# ---------------------------------------------------------------------------------------
# linear rigid path
# ---------------------------------------------------------------------------------------
def reduced_pressure_solve(grid: PointGrid, h0: float, rx: float, ry: float,
                           mean_speed: float, viscosity: float, q_bc: np.ndarray,
                           cavitation: str, squeeze_velocity: float = 0.0,
                           active: np.ndarray | None = None
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
    active : bool ndarray, optional
        First guess of the cavitated nodes (flat), e.g. from a coarser grid.

    Returns
    -------
    q : ndarray (flat, Pa); linear_solves : int; active : bool ndarray (cavitated nodes)
    """
    ops = grid.ops
    xq, yq = ops.coordinate_x(), ops.coordinate_y()
    h = h0 + ops.separable(xq**2 / (2 * rx), yq**2 / (2 * ry))
    eps = h**3 / (12.0 * viscosity)
    zero = np.zeros_like(h)
    a = ops.assembler.flux_jacobian_sum([(0, zero, (eps, zero)), (1, zero, (zero, eps))])
    f = ops.weak_divergence(mean_speed * h, zero)
    if squeeze_velocity:
        f = f - ops.value.T @ (ops.weights * squeeze_velocity)
    free = np.nonzero(~grid.boundary_mask())[0]
    return active_set_solve(a, f, np.where(grid.boundary_mask(), q_bc, 0.0), free,
                            cavitation, active=active)


#: A rigid Barus point scene with Reynolds cavitation is refused before any Newton
#: iteration (status ``no_solution``) when its load exceeds this multiple of
#: :func:`rigid_barus_point_load_limit` (the margin covers that limit's grid error on its
#: default 161^2 grid, 0.12 % below its 321^2 value for a ball). With 1.1 and an 81^2
#: limit, 1.02 times that limit (0.7 % above the 161^2 one) converged on a pressure spike
#: (alpha p_max = 15) and 1.05 times it ran its 400 Newton iterations out in 60 s.
RIGID_BARUS_POINT_LOAD_MARGIN = 1.005


def rigid_barus_point_load_limit(rx: float, ry: float, viscosity: float,
                                 mean_speed: float, piezo: float,
                                 nodes: int = 161) -> tuple[float, float]:
    """Largest load a rigid Barus point contact with the Reynolds outlet carries, and the
    gap at which it does.

    The Barus pressure p = -ln(1 - alpha q)/alpha of the isoviscous reduced pressure q
    exists while alpha q_max < 1 (Kapitsa). On the paraboloid gap h = h0 + x^2/(2 rx)
    + y^2/(2 ry) the isoviscous problem is self-similar in X = x/sqrt(2 rx h0),
    Y = y/sqrt(2 ry h0): q = eta0 u_m sqrt(2 rx h0)/h0^2 Q(X, Y), Q set by ry/rx alone. So
    q_max grows as h0^(-3/2) as the gap closes, the load grows to its limit at the gap
    h0* where alpha q_max = 1, and there W* = 2 sqrt(rx ry) h0* int -ln(1 - Q/Q_max)/alpha
    dX dY (a logarithmic, integrable singularity at the peak). No load above W* has a
    solution. Q comes from one reduced-pressure solve on a sinh-graded grid of ``nodes``
    per direction over the default rigid domain (:data:`RIGID_RANGE_REYNOLDS`) with
    Kapitsa's inlet film on its edges, as a scene with a gap is solved
    (:func:`far_field_data`); the integral is taken at the quadrature points, where
    Q < Q_max, and the film's load beyond the domain is added. The shape Q is that of every
    contact with the same ry/rx, so its numbers are cached by ry/rx and ``nodes`` (the
    161^2 solve takes about 1.6 s once). Measured for a ball: 0.5239 N on 81^2, 0.5305 N on
    161^2, 0.5311 N on 321^2 (with p = 0 on the edges it was 0.5028, 0.5093 and
    0.5099 N). The line-contact counterpart in closed form is
    :func:`bearing_fem.analytic.martin_barus_load_limit`.

    Parameters
    ----------
    rx, ry : float
        Reduced radii [m].
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s], > 0.
    piezo : float
        alpha [1/Pa], > 0.
    nodes : int
        Grid nodes per direction of the reduced-pressure solve.

    Returns
    -------
    (float, float)
        W* [N] and h0* [m].
    """
    rx, ry = require_positive("rx", rx, "m"), require_positive("ry", ry, "m")
    viscosity = require_positive("viscosity", viscosity, "Pa s")
    mean_speed = require_positive("mean_speed", mean_speed, "m/s")
    piezo = require_positive("piezo", piezo, "1/Pa")
    nodes = require_int("nodes", nodes, 9, what="grid nodes per direction")
    q_max, integral = _barus_limit_shape(ry / rx, nodes)
    # q(h0) = eta0 u_m sqrt(rx) h0^(-3/2) Q, Q that of rx = h0 = eta0 = u_m = 1 m: alpha
    # q_max(h0*) = 1; lengths scale with sqrt(h0 rx), sqrt(h0 ry), areas with h0 rx
    h_star = (piezo * viscosity * mean_speed * math.sqrt(rx) * q_max) ** (2.0 / 3.0)
    return h_star * rx * integral / piezo, h_star


@functools.lru_cache(maxsize=64)
def _barus_limit_shape(ratio: float, nodes: int) -> tuple[float, float]:
    """(Q_max, int -ln(1 - Q/Q_max) dA) of the flooded rigid isoviscous film at
    rx = h0 = eta0 = u_m = 1, ry = ``ratio`` (SI units): Q from one reduced-pressure solve
    on the default rigid domain with Kapitsa's film on its edges, the integral at the
    quadrature points (where Q < Q_max) plus Kapitsa's film beyond the edges (cached: the
    shape is that of every rigid Barus point contact with this ry/rx)."""
    grid, q = _unit_flooded_film(ratio, nodes)
    q_max = float(np.max(q))
    ops = grid.ops
    share = np.minimum(ops.value @ (q / q_max), 1.0 - 1e-16)
    inside = float(ops.weights @ -np.log1p(-share))
    beyond = _unit_film_beyond(
        ratio, lambda v: -np.log1p(-np.minimum(v / q_max, 1.0 - 1e-16)))
    return q_max, inside + beyond


@functools.lru_cache(maxsize=8)
def _unit_flooded_film(ratio: float, nodes: int) -> tuple[PointGrid, np.ndarray]:
    """The grid and nodal reduced pressure of the flooded rigid isoviscous film at
    rx = h0 = eta0 = u_m = 1, ry = ``ratio`` (SI units) on the default rigid domain with
    Kapitsa's film on its edges (cached: the self-similar shape of every rigid point film
    with this ry/rx, :func:`_rigid_reduced_pressure`)."""
    return _rigid_reduced_pressure(1.0, ratio, 1.0, 1.0, 1.0, nodes, far_field=True)


def _unit_film_beyond(ratio: float, from_reduced=None) -> float:
    """Load of Kapitsa's film beyond the default rigid domain of :func:`_unit_flooded_film`
    (:func:`bearing_fem.analytic.kapitsa_point_exterior_load`; ``from_reduced`` p(q))."""
    (x0, x1), (y0, y1) = RIGID_RANGE_REYNOLDS
    xu, yu = math.sqrt(2.0), math.sqrt(2.0 * ratio)
    return kapitsa_point_exterior_load((x0 * xu, x1 * xu), (y0 * yu, y1 * yu), 1.0, 0.5,
                                       0.5 / ratio, 1.0, 1.0, from_reduced=from_reduced)


def _rigid_reduced_pressure(rx: float, ry: float, h0: float, mean_speed: float,
                            viscosity: float, nodes: int, ranges=RIGID_RANGE_REYNOLDS,
                            far_field: bool = False) -> tuple[PointGrid, np.ndarray]:
    """The isoviscous reduced pressure q >= 0 [Pa] of a rigid point contact with the
    Reynolds outlet at the gap ``h0`` [m], on a sinh-graded grid of ``nodes`` per
    direction over ``ranges`` (default :data:`RIGID_RANGE_REYNOLDS`; in units of
    sqrt(2 rx h0), sqrt(2 ry h0)), with q = 0 on the edges or (``far_field``) Kapitsa's
    inlet film there (:func:`far_field_data`): the self-similar solution behind
    :func:`rigid_barus_point_load_limit` and :func:`rigid_isoviscous_load_integral`.
    Returns the grid and the nodal q."""
    xu, yu = math.sqrt(2.0 * rx * h0), math.sqrt(2.0 * ry * h0)
    (x0, x1), (y0, y1) = ranges
    grid = PointGrid.tensor(graded_coordinates(x0, x1, nodes, xu, stretch=1.5),
                            graded_coordinates(y0, y1, nodes, yu, stretch=1.5))
    q_bc = (_kapitsa_edges(grid, h0, rx, ry, viscosity, mean_speed) if far_field
            else np.zeros(grid.size))
    q, _, _ = reduced_pressure_solve(grid, h0, rx, ry, mean_speed, viscosity, q_bc,
                                     "reynolds")
    return grid, np.maximum(q, 0.0)


#: Nodes per direction of the reduced-pressure solve of
#: :func:`rigid_isoviscous_load_integral` (for a ball its integral is 4.115 on 41^2 and
#: 4.196 on 161^2: the rigid domain's length unit, proportional to it, is 2 % short).
LOAD_INTEGRAL_NODES = 41


#: Nodes per direction of the reduced-pressure solves of :func:`rigid_domain_load_share`
#: (for a ball on [-10, 5] x [-10, 10]: 0.897 on 41^2, 0.890 on 81^2, 0.888 on 161^2, in
#: 0.05, 0.4 and 3.4 s).
LOAD_SHARE_NODES = 41


def rigid_domain_load_share(ratio: float, x_range: tuple[float, float],
                            y_range: tuple[float, float],
                            nodes: int = LOAD_SHARE_NODES) -> float:
    """Load a rigid isoviscous film with the Reynolds outlet carries on a domain, as a
    share of its load on the default rigid domain :data:`RIGID_RANGE_REYNOLDS` [-].

    The reduced pressure is self-similar (:func:`rigid_barus_point_load_limit`), so the
    share depends on ry/rx and on the domain in units of sqrt(2 rx h0), sqrt(2 ry h0)
    alone: one solve on each domain with p = 0 on its edges, sinh-graded, ``nodes`` per
    direction. Far from the contact the pressure of a fully flooded film decays as r^-3
    (Kapitsa's q ~ x/h^2), so the load a domain misses falls only as 1/(its size):
    measured for a ball, 0.888 on [-10, 5] x [-10, 10] (161^2), and the default rigid
    domain carries 0.964 of the load on [-90, 8] x [-90, 90] (241^2). An
    estimate for warnings: on its default 41^2 grids it is within 1 % of the 161^2 value.

    Parameters
    ----------
    ratio : float
        ry/rx [-].
    x_range, y_range : (float, float)
        The domain in units of sqrt(2 rx h0) and sqrt(2 ry h0).
    nodes : int
        Grid nodes per direction.

    Returns
    -------
    float
        Load on the domain / load on the default rigid domain [-].

    Raises
    ------
    ValueError
        ratio not finite and > 0, a range not two finite numbers low < high, nodes not an
        integer >= 3.
    """
    ratio = require_positive("ratio", ratio, "(ry/rx, dimensionless)")
    ranges = []
    for name, rng in (("x_range", x_range), ("y_range", y_range)):
        vals = np.atleast_1d(require_finite(name, rng,
                                            "in lengths sqrt(2 rx h0), sqrt(2 ry h0)"))
        if vals.size != 2 or not vals[0] < vals[1]:
            raise ValueError(f"{name} must be (low, high) with low < high (lengths "
                             f"sqrt(2 rx h0), sqrt(2 ry h0)), got {rng!r}")
        ranges.append((float(vals[0]), float(vals[1])))
    nodes = require_int("nodes", nodes, 3, what="grid nodes per direction")
    ranges = (ranges[0], ranges[1])
    return _rigid_load(ratio, ranges, nodes) / _rigid_load(ratio, RIGID_RANGE_REYNOLDS, nodes)


@functools.lru_cache(maxsize=128)
def _rigid_load(ratio: float, ranges: tuple[tuple[float, float], tuple[float, float]],
                nodes: int) -> float:
    """Load [N] of the rigid isoviscous film with the Reynolds outlet on ``ranges`` at
    rx = h0 = 1 m, ry = ``ratio`` m, eta0 u_m = 1 Pa m (the self-similar solution of
    :func:`_rigid_reduced_pressure`; cached: its solves are shared by
    :func:`rigid_domain_load_share` and :func:`rigid_isoviscous_load_integral`)."""
    grid, q = _rigid_reduced_pressure(1.0, ratio, 1.0, 1.0, 1.0, nodes, ranges)
    return float(grid.ops.weights @ (grid.ops.value @ q))


def rigid_isoviscous_load_integral(ratio: float, nodes: int = LOAD_INTEGRAL_NODES) -> float:
    """Dimensionless load I of the rigid isoviscous point contact with the Reynolds
    outlet: F = 2 sqrt(2) eta0 u_m rx sqrt(ry) I / sqrt(h0).

    The reduced (isoviscous) pressure is self-similar in X = x/sqrt(2 rx h0),
    Y = y/sqrt(2 ry h0) (see :func:`rigid_barus_point_load_limit`): q = eta0 u_m
    sqrt(2 rx h0)/h0^2 Q(X, Y), so the load is the expression above with I = int Q dX dY,
    set by ry/rx alone. One solve on the default rigid domain (:data:`RIGID_RANGE_REYNOLDS`,
    sinh-graded, ``nodes`` per direction) with Kapitsa's inlet film on its edges plus that
    film's load beyond them, as the film is solved (:func:`far_field_data`). Measured:
    4.115, 4.180, 4.196 for a ball and 6.210, 6.309, 6.336 for ry/rx = 4 on 41^2, 81^2,
    161^2 (with p = 0 on the edges it was 3.90, 3.96, 3.98 and 5.88, 5.98, 6.01).

    Parameters
    ----------
    ratio : float
        ry/rx [-].
    nodes : int
        Grid nodes per direction.

    Returns
    -------
    float
        I [-].
    """
    ratio = float(ratio)  # the load at rx = h0 = 1 m, ry = ratio m: F = 2 sqrt(2 ratio) I
    return _flooded_load(ratio, int(nodes)) / (2.0 * math.sqrt(2.0 * ratio))


@functools.lru_cache(maxsize=128)
def _flooded_load(ratio: float, nodes: int) -> float:
    """Load [N] of the fully flooded rigid isoviscous film with the Reynolds outlet at
    rx = h0 = 1 m, ry = ``ratio`` m, eta0 = u_m = 1: the default domain with Kapitsa's
    inlet film on its edges plus that film's load beyond them (:func:`far_field_data`;
    cached)."""
    grid, q = _unit_flooded_film(ratio, nodes)
    return float(grid.ops.weights @ (grid.ops.value @ q)) + _unit_film_beyond(ratio)


def _rigid_barus_overload(scene: Scene) -> tuple[float, float] | None:
    """(W*, h0*) of :func:`rigid_barus_point_load_limit` when ``scene`` (rigid,
    incompressible, Barus, Reynolds cavitation, under load) asks for more than
    :data:`RIGID_BARUS_POINT_LOAD_MARGIN` W*, else None."""
    if not is_rigid_barus_load(scene):
        return None
    lub = scene.lubricant
    limit, h_star = rigid_barus_point_load_limit(
        scene.contact.rx, scene.contact.ry, lub.viscosity, scene.kinematics.mean_speed,
        lub.effective_piezo)
    return (limit, h_star) if scene.load.force > RIGID_BARUS_POINT_LOAD_MARGIN * limit \
        else None


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

    #: Load of the film beyond the domain [N] (set by ``PointModel.problem`` from its
    #: level; None: p = 0 beyond the edges, nothing added).
    exterior_load: float | None = None

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
        # the gap geometry at the quadrature points is separable, g = gx(x) + gy(y): kept
        # per cell column / row ((nx - 1, n_quad), (ny - 1, n_quad)), never as full arrays
        xq, yq = ops.coordinate_x(), ops.coordinate_y()
        self._geometry = ((xq**2 / (2 * rx), yq**2 / (2 * ry)), xq / rx, yq / ry)
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
        # one smoothing for every row: the cavitation boundary of a point contact wraps
        # round its sides, at films well above h_min, where a smoothing shrunk with the
        # row scale (as a line contact's, :func:`row_smoothing`) lets the semismooth
        # Newton cycle on coarse grids (the 33^2 estimate level of the circular map's
        # M = 500, L = 10 no longer converged); the circular map's energy balance
        # closes to 2.5e-8 with it
        self._fb_mu = FB_SMOOTHING
        self._pattern = None
        self._displacement_cache = None
        self._forcing_term = None
        self._kept = None
        self.factorizations = 0
        self.linear_iterations = 0
        #: optional one-element list that also receives the GMRES iteration counts (a
        #: model's total over all its problems, without keeping the problems alive)
        self.iteration_sink: list[int] | None = None

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
        """Nodal elastic displacement v = C p [m] (0 when rigid), the last product kept
        (:meth:`~bearing_fem.contacts.problem.ScaledResidual.compliance_product`). The
        returned array is shared with the cache and must not be modified."""
        if self.compliance is None:
            return np.zeros_like(p)
        return self.compliance_product(p)

    # gap geometry at the quadrature points (whole arrays, built on each access)
    @property
    def g_q(self) -> np.ndarray:
        """x^2/(2 rx) + y^2/(2 ry) at the quadrature points [m]."""
        return self.ops.separable(*self._geometry[0])

    @property
    def gx_q(self) -> np.ndarray:
        """x/rx at the quadrature points [-]."""
        return self.ops.separable(self._geometry[1], None)

    @property
    def gy_q(self) -> np.ndarray:
        """y/ry at the quadrature points [-]."""
        return self.ops.separable(None, self._geometry[2])

    def _rows_fields(self, p2: np.ndarray, v2: np.ndarray, h0: float, j0: int, j1: int):
        """p, h, (px, py), (hx, hy) at the quadrature points of the cell rows
        j0 <= j < j1 (nodal p2, v2 of shape (ny, nx))."""
        ops = self.ops
        (gx2, gy2), gx1, gy1 = self._geometry
        value, (dx, dy) = ops.value, ops.grad
        h = ops.separable_rows(gx2, gy2, j0, j1)
        h += h0
        h += value.rows(v2, j0, j1)
        gh = (ops.separable_rows(gx1, None, j0, j1) + dx.rows(v2, j0, j1),
              ops.separable_rows(None, gy1, j0, j1) + dy.rows(v2, j0, j1))
        gp = (dx.rows(p2, j0, j1), dy.rows(p2, j0, j1))
        return value.rows(p2, j0, j1), h, gp, gh

    def post_fields(self, p: np.ndarray, h0: float):
        """Fields at the quadrature points that post-processing integrates: p, h,
        (px, py), eta, the reduced-pressure gradient (None without the reduced Poiseuille
        term) and the stabilisation flux (whole arrays, filled cell row block by block so
        that only they are held, not the temporaries of the flux)."""
        ops = self.ops
        shape = self.grid.shape
        p = np.asarray(p, dtype=float)
        p2 = p.reshape(shape)
        v2 = self.displacement(p).reshape(shape)
        q2 = self.flux.reduced(p).reshape(shape) if self.uses_reduced else None
        dx, dy = ops.grad
        size = ops.n_quad * (shape[1] - 1) * (shape[0] - 1)
        out = {k: np.empty(size) for k in ("p", "h", "px", "py", "eta", "sx", "sy")}
        if q2 is not None:
            out["qx"], out["qy"] = np.empty(size), np.empty(size)
        per_row = ops.n_quad * (shape[1] - 1)
        for j0, j1 in self._chunks():
            sl = slice(j0 * per_row, j1 * per_row)
            pq, h, gp, gh = self._rows_fields(p2, v2, h0, j0, j1)
            gq = None if q2 is None else (dx.rows(q2, j0, j1), dy.rows(q2, j0, j1))
            stab = self.flux.stabilisation_flux(pq, h, gp, gh, ops.element_size_rows(j0, j1),
                                                gq)
            out["p"][sl], out["h"][sl] = pq, h
            out["px"][sl], out["py"][sl] = gp
            out["eta"][sl] = self.flux.viscosity(pq)
            out["sx"][sl], out["sy"][sl] = stab
            if gq is not None:
                out["qx"][sl], out["qy"][sl] = gq
        gq_all = (out["qx"], out["qy"]) if q2 is not None else None
        return (out["p"], out["h"], (out["px"], out["py"]), out["eta"], gq_all,
                (out["sx"], out["sy"]))

    def _chunks(self) -> list[tuple[int, int]]:
        return self.ops.chunks(CHUNK_POINTS)

    def film_nodes(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Nodal film [m] (flat)."""
        return h0 + self.g_nodes + self.displacement(p)

    def fields_q(self, p: np.ndarray, h0: float, v: np.ndarray | None = None):
        """p, h, (px, py), (hx, hy) at the quadrature points (whole arrays; ``v`` the nodal
        displacement, default C p). The Newton iteration itself works on cell row blocks
        (:meth:`reynolds_residual`); this is for post-processing and subclasses."""
        ops = self.ops
        displacement = self.displacement(p) if v is None else v
        h = h0 + self.g_q + ops.value @ displacement
        gh = (self.gx_q + ops.grad[0] @ displacement, self.gy_q + ops.grad[1] @ displacement)
        gp = (ops.grad[0] @ p, ops.grad[1] @ p)
        return ops.value @ p, h, gp, gh

    # -- NonlinearProblem ------------------------------------------------------------------
    def prepare(self, z: np.ndarray) -> None:
        p, h0 = self.unpack(z)
        h = np.maximum(self.film_nodes(p, h0), 1e-3 * self.h_ref)
        eps0 = h**3 / (12.0 * self.eta0)
        self._row_scale = (1.0 / (self._stiff_diag * eps0 * self.p_ref))[self.free] \
            * self._row_weight

    def admissible(self, z: np.ndarray) -> bool:
        """Finite unknowns and a positive film at every quadrature point."""
        if not np.all(np.isfinite(z)):
            return False
        p, h0 = self.unpack(z)
        shape = self.grid.shape
        v2 = self.displacement(p).reshape(shape)
        ops = self.ops
        (gx2, gy2), _, _ = self._geometry
        for j0, j1 in self._chunks():
            h = ops.separable_rows(gx2, gy2, j0, j1) + ops.value.rows(v2, j0, j1)
            if not np.min(h) + h0 > 0.0:
                return False
        return True

    def reynolds_residual(self, p: np.ndarray, h0: float) -> np.ndarray:
        """Nodal weak residual R_i [m^3/s] (all nodes), evaluated cell row block by
        block (``CHUNK_POINTS``): the same sums as on whole arrays, with bounded
        temporaries."""
        shape = self.grid.shape
        p = np.asarray(p, dtype=float)
        p2 = p.reshape(shape)
        v2 = self.displacement(p).reshape(shape)
        q2 = self.flux.reduced(p).reshape(shape) if self.uses_reduced else None
        ops = self.ops
        dx, dy = ops.grad
        r2 = np.zeros(shape)
        for j0, j1 in self._chunks():
            pq, h, gp, gh = self._rows_fields(p2, v2, h0, j0, j1)
            size = ops.element_size_rows(j0, j1)
            if q2 is not None:
                gq = (dx.rows(q2, j0, j1), dy.rows(q2, j0, j1))
                fl = self.flux.flux(pq, h, gp, gh, size, gq=gq)
            else:
                fl = self.flux.flux(pq, h, gp, gh, size)
            w = ops.weights_rows(j0, j1)
            dx.add_rows(w * fl[0], r2, j0, j1)
            dy.add_rows(w * fl[1], r2, j0, j1)
            if self.squeeze:
                ops.value.add_rows(w * self.flux.density(pq) * self.squeeze, r2, j0, j1)
        return r2.ravel()

    def _blocks(self, z: np.ndarray):
        """Sparse A_p, A_h (all nodes), dR/dh0 (all nodes), residual, row factors."""
        p, h0 = self.unpack(z)
        ops = self.ops
        asm = ops.assembler  # element-wise assembly on one fixed pattern
        shape = self.grid.shape
        p2 = p.reshape(shape)
        v2 = self.displacement(p).reshape(shape)
        q2 = self.flux.reduced(p).reshape(shape) if self.uses_reduced else None
        fluidity = self.flux.fluidity(p) if self.uses_reduced else None
        dx, dy = ops.grad
        stencil_p, stencil_h = asm.stencil(), asm.stencil()
        res2, drdh0_2 = np.zeros(shape), np.zeros(shape)
        compressible = bool(self.squeeze) and self.flux.density(np.array([1e8]))[0] != 1.0
        dp_rho_terms = []
        for j0, j1 in self._chunks():  # cell row blocks: bounded temporaries
            pq, h, gp, gh = self._rows_fields(p2, v2, h0, j0, j1)
            size = ops.element_size_rows(j0, j1)
            if q2 is not None:
                gq = (dx.rows(q2, j0, j1), dy.rows(q2, j0, j1))
                fl, dp, dh, dgp, dgh, dgq = self.flux.flux_and_derivatives_reduced(
                    pq, h, gp, gh, size, gq)
                zero = np.zeros_like(pq)
                # d grad q_h / d p_j = q'(p_j) grad phi_j: columns scaled by the fluidity
                extra = [(d, zero, (dgq[0][d], dgq[1][d]), fluidity) for d in range(2)]
            else:
                fl, dp, dh, dgp, dgh = self.flux.flux_and_derivatives(pq, h, gp, gh, size)
                extra = []
            asm.add(stencil_p, [(d, dp[d], (dgp[0][d], dgp[1][d])) for d in range(2)]
                    + extra, j0, j1)
            asm.add(stencil_h, [(d, dh[d], (dgh[0][d], dgh[1][d])) for d in range(2)],
                    j0, j1)
            w = ops.weights_rows(j0, j1)
            dx.add_rows(w * fl[0], res2, j0, j1)
            dy.add_rows(w * fl[1], res2, j0, j1)
            dx.add_rows(w * dh[0], drdh0_2, j0, j1)
            dy.add_rows(w * dh[1], drdh0_2, j0, j1)
            if self.squeeze:
                ops.value.add_rows(w * self.flux.density(pq) * self.squeeze, res2, j0, j1)
                if compressible:  # d rho/dp term, assembled below on whole arrays
                    step = 1e-20 * max(self.p_ref, 1.0)
                    dp_rho_terms.append(np.imag(self.flux.density(pq + 1j * step)) / step)
        a_p, a_h = asm.csr(stencil_p), asm.csr(stencil_h)
        res, drdh0 = res2.ravel(), drdh0_2.ravel()
        if dp_rho_terms:
            dp_rho = np.concatenate(dp_rho_terms)
            a_p = a_p + ops.value.T @ sp.diags(ops.weights * dp_rho * self.squeeze) \
                @ ops.value
        rows = self.free
        s = self._row_scale
        if self.cavitation == "reynolds":
            _, da, db = fischer_burmeister(p[rows] / self.p_ref, res[rows] * s, self._fb_mu)
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

    def _free_pattern(self) -> FreePattern:
        """Free-node block of the assembler pattern in nested-dissection order (cached)."""
        if self._pattern is None:
            self._pattern = self.grid.free_pattern(self.free)
        return self._pattern

    def release(self) -> None:
        """Drop what only further Newton steps need (the kept LU, cached products); the
        problem stays usable (they are rebuilt on demand)."""
        self._pattern = None
        self._kept = None
        self._displacement_cache = None
        self._nodal_cache = None

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
            # a preconditioner (elastic) in single precision; a direct solve (rigid) not
            elastic = self.compliance is not None
            single = elastic and PRECONDITIONER_SINGLE
            drop = PRECONDITIONER_DROP_TOL if elastic else 0.0
            try:
                lu = pat.factor(m, scale, diag, single=single, drop_tol=drop)
            except RuntimeError:  # singular incomplete or single-precision factors
                if not (single or drop):
                    raise
                single = False
                lu = pat.factor(m, scale, diag)
            perm, inv = pat.perm, pat.inverse
            dtype = np.float32 if single else float

            def solve(r: np.ndarray) -> np.ndarray:
                return lu.solve(np.ascontiguousarray(r[perm], dtype=dtype))[inv].astype(float)

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
        require_finite_factor_data(jpp.data)
        return spla.splu(jpp, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=LU_PIVOT_THRESHOLD,
                         options={"SymmetricMode": True}).solve

    def _preconditioner(self, a_p: sp.spmatrix, a_h: sp.spmatrix, scale: np.ndarray,
                        diag: np.ndarray, shift: float) -> Callable[[np.ndarray], np.ndarray]:
        """The near-field LU solve of this Newton step: the factorization of an earlier
        step of this problem while GMRES needed at most ``PRECONDITIONER_KEEP_ITERATIONS``
        (``PRECONDITIONER_KEEP_ITERATIONS_LARGE`` on large grids) iterations with it and the Newton shift has not grown, else a fresh one (rigid
        problems, solved directly, always factor afresh)."""
        kept = self._kept
        keep = (PRECONDITIONER_KEEP_ITERATIONS_LARGE
                if self.free.size >= PRECONDITIONER_LARGE_UNKNOWNS
                else PRECONDITIONER_KEEP_ITERATIONS)
        if (self.compliance is not None and kept is not None and kept["its"] <= keep
                and shift <= 2.0 * kept["shift"] + 1e-300):
            return kept["solve"]
        self._kept = kept = None  # free the old factors before the new ones are made
        solve = self._preconditioner_lu(a_p, a_h, scale, diag)
        self.factorizations += 1
        if self.compliance is not None and PRECONDITIONER_KEEP_ITERATIONS > 0:
            self._kept = {"solve": solve, "shift": shift, "its": 0}
        return solve

    def _forcing(self, f: np.ndarray) -> float:
        """Relative GMRES tolerance of a Newton step with residual ``f`` (inexact Newton,
        see ``GMRES_FORCING``)."""
        if GMRES_FORCING_MAX <= GMRES_RTOL:
            return GMRES_RTOL
        norm2 = float(np.linalg.norm(f))
        if GMRES_FORCING == "eisenstat-walker":
            if self._forcing_term is None:
                self._forcing_term = ForcingTerm(GMRES_FORCING_MAX)
            eta = self._forcing_term(norm2)
        else:
            eta = float(np.max(np.abs(f)))
        floor = max(GMRES_RTOL, eta)
        if self.tolerance is not None:
            floor = max(floor, GMRES_TOLERANCE_FRACTION * self.tolerance / max(norm2, 1e-300))
        return min(GMRES_FORCING_MAX, floor)

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
        lu_solve = self._preconditioner(a_p, a_h, scale, np.broadcast_to(diag, (npf,)),
                                        shift)
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

        rtol = self._forcing(f)
        dz, its, rel = gmres_right(matvec, precond, -f, rtol=rtol,
                                   max_iterations=GMRES_MAX_ITERATIONS)
        if self._kept is not None:
            self._kept["its"] = its if rel <= rtol else GMRES_MAX_ITERATIONS
        self.linear_iterations += its
        if self.iteration_sink is not None:
            self.iteration_sink[0] += its
        log.debug("gmres: %d iterations, relative residual %.2e", its, rel)
        if not math.isfinite(rel) or not np.all(np.isfinite(dz)):
            raise RuntimeError("gmres: the preconditioner or the Jacobian product gave "
                               "non-finite values")
        return dz


def flux_model(scene, setup: PointSetup, piezo_scale: float = 1.0,
               speed_scale: float = 1.0) -> FluxModel:
    """The Reynolds flux of a point scene on a setup: upwinded with the reduced-pressure
    Poiseuille term for elastic scenes, plain for rigid ones; ``piezo_scale`` scales
    alpha and ``speed_scale`` the entrainment speed (continuation)."""
    u_m = scene.kinematics.mean_speed * speed_scale
    if setup.compliance is not None:
        lub = scene.lubricant
        reduced = None
        if REDUCED_POISEUILLE and (lub.viscosity_law == "barus" or lub.effective_piezo == 0.0):
            reduced = lub.effective_piezo * piezo_scale
        return UpwindFluxModel.elastic(lub, u_m,
                                       UPWIND_COMPLIANCE_FACTOR * setup.stab_compliance,
                                       piezo_scale=piezo_scale, reduced_alpha=reduced)
    return FluxModel.from_lubricant(scene.lubricant, u_m,
                                    compliance=setup.stab_compliance, piezo_scale=piezo_scale)


def rigid_start(scene, setup: PointSetup, problem: PointProblem, h0: float) -> np.ndarray:
    """Isoviscous rigid (Kapitsa-type) solution at the offset h0 [m], with the
    problem's Dirichlet data and squeeze velocity, as packed unknowns of ``problem``."""
    q, _, _ = reduced_pressure_solve(setup.grid, h0, scene.contact.rx, scene.contact.ry,
                                     scene.kinematics.mean_speed, scene.lubricant.viscosity,
                                     problem.p_bc, scene.model.cavitation, problem.squeeze)
    if scene.model.cavitation == "reynolds":
        q = np.maximum(q, 0.0)
    return problem.pack(q, h0)


#: How the shared driver attacks elastic point contacts (measured reasons at the
#: constants above): a small decaying Newton shift from the Hertzian start and from an
#: interpolated solution; at most TRANSFER_DIRECT_ITERATIONS direct iterations on a finer
#: level, then warm alpha continuation from s = WARM_START_ALPHA; coarse levels stop at
#: COARSE_TOLERANCE, intermediate continuation steps at INTERMEDIATE_TOLERANCE.
POINT_DRIVER = DriverSettings(transfer_iterations=TRANSFER_DIRECT_ITERATIONS,
                              start_shift=START_SHIFT, transfer_shift=TRANSFER_SHIFT,
                              coarse_tolerance=COARSE_TOLERANCE,
                              intermediate_tolerance=INTERMEDIATE_TOLERANCE,
                              warm_start=WARM_START_ALPHA, transfer_memory=TRANSFER_MEMORY,
                              blas_threads=BLAS_THREADS)
#: Rigid Newton scenes (loaded, or non-Barus laws): plain Newton as validated.
RIGID_POINT_DRIVER = replace(POINT_DRIVER, start_shift=0.0, transfer_shift=0.0)


@dataclass
class PointLevel:
    """One grid of a point scene's sequence (a driver level).

    Attributes
    ----------
    setup : PointSetup
        The grid the Newton iterations run on (the half grid of a symmetric solve).
    nodes : (int, int)
        Whole-grid node counts (nx, ny).
    p_bc : ndarray
        Flat Dirichlet pressures of ``setup.grid`` [Pa].
    exterior_load : float or None
        Load of the film beyond the domain [N] where the edges carry Kapitsa's far field
        (:func:`far_field_data`), else None.
    """

    setup: PointSetup
    nodes: tuple[int, int]
    p_bc: np.ndarray
    exterior_load: float | None = None

    @property
    def label(self) -> str:
        return f"{self.nodes[0]}x{self.nodes[1]} nodes"


class _Weighted:
    """Quadrature operators whose weights (and integrals) are scaled by ``factor`` (a half
    grid standing for the whole symmetric one); everything else is ``ops``'s."""

    def __init__(self, ops, factor: float) -> None:
        self._ops = ops
        self.factor = float(factor)

    @property
    def weights(self) -> np.ndarray:
        w = self._ops.weights
        return w if self.factor == 1.0 else self.factor * w

    def integrate(self, f_q: np.ndarray) -> float:
        return self.factor * self._ops.integrate(f_q)

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self._ops, name)


class PointModel:
    """A point-contact scene as a :class:`~bearing_fem.contacts.driver.ContactModel`.

    Elastic loaded scenes are solved by grid sequencing (coarsest grid
    ``COARSEST_NODES`` per direction); y-symmetric ones on the half grid y >= 0
    (``Y_SYMMETRY``), mirrored to the whole grid for the result. Rigid scenes are one
    level (linear path or Newton).

    Parameters
    ----------
    scene : Scene
    boundary_pressure : callable or ndarray or None
        Dirichlet pressure on the boundary [Pa] (see :func:`solve_point`).
    squeeze_velocity : float
        dh0/dt [m/s].
    grid_scene : Scene, optional
        The scene whose scales set the grids (default ``scene``); a rigid squeeze series
        solves every instant on the grid of its mean gap.
    far_field : bool
        Rigid scenes with the Reynolds outlet (a gap or a load), and elastic ones under a
        load below :data:`FAR_FIELD_MOES_M`: impose Kapitsa's inlet
        film on the domain's edges and add its load beyond them (:func:`far_field_data`)
        instead of p = 0 on the edges; ignored where :func:`far_field_applies` is False,
        where the film's pressure on the edges or its load beyond them is not finite
        (reduced pressure at the viscosity law's limit there) and where a load does not
        exceed twice the load beyond the domain.
    """

    def __init__(self, scene, boundary_pressure=None, squeeze_velocity: float = 0.0, *,
                 grid_scene=None, far_field: bool = False) -> None:
        self.scene = scene
        self.boundary_pressure = boundary_pressure
        self.far_field = bool(far_field)
        self.squeeze = float(squeeze_velocity)
        self.grid_scene = scene if grid_scene is None else grid_scene
        self.setup = point_setup(self.grid_scene)
        grid = self.setup.grid
        self.fine_nodes = (grid.x.size, grid.y.size)
        self.elastic = self.setup.compliance is not None
        self.symmetric = self._symmetric()
        self.settings = POINT_DRIVER if self.elastic else RIGID_POINT_DRIVER
        piezo = scene.lubricant.effective_piezo > 0.0
        # isoviscous elastic scenes under load continue in the entrainment speed (from
        # CONTINUATION_SPEED_FACTOR times it), as line contacts do
        speed = self.elastic and scene.load.force is not None
        self.continuation_parameter = "alpha" if piezo else ("speed" if speed else None)
        self.grid_note = ", each solved on its half y >= 0 by symmetry" if self.symmetric \
            else ""
        self._levels: dict[tuple[tuple[int, int], bool], PointLevel] = {}
        self._linear_iterations = [0]  # GMRES iterations of all problems of the model
        self._live: weakref.WeakSet[PointProblem] = weakref.WeakSet()

    def _symmetric(self) -> bool:
        """True if the elastic Newton solve may run on the half grid y >= 0
        (``Y_SYMMETRY``): a loaded elastic scene with zero boundary pressure on a grid
        whose rows mirror each other about y = 0. The contact geometry
        (x^2/(2 rx) + y^2/(2 ry)), rolling along x and the half-space kernel are even in
        y, so the discrete problem maps even pressures to even residuals."""
        y = self.setup.grid.y
        return (Y_SYMMETRY and self.elastic and self.scene.load.force is not None
                and self.boundary_pressure is None and y.size % 2 == 1
                and bool(np.array_equal(y, -y[::-1])))

    # -- levels ----------------------------------------------------------------------------
    def level(self, nodes: tuple[int, int], half: bool | None = None) -> PointLevel:
        """The scene on the grid of ``nodes`` (whole-grid counts), on its half y >= 0 when
        ``half`` (default: as the model's solve). Cached: the driver recognises a level
        by identity."""
        half = self.symmetric if half is None else half
        key = (tuple(nodes), half)
        if key not in self._levels:
            if tuple(nodes) == self.fine_nodes and not half:
                setup = self.setup
            else:
                setup = point_setup(self.grid_scene, nodes=tuple(nodes), symmetric=half)
            far = self.far_field and far_field_applies(self.scene, setup.grid)
            if far:
                law = reduced_law(self.scene.lubricant)
                gap = self.scene.load.gap
                q_bc, beyond = far_field_data(self.scene, setup.grid,
                                              setup.h_ref if gap is None else gap,
                                              law.from_reduced)
                p_edges = law.from_reduced(q_bc)
                # a load must exceed the film's load beyond the domain (not so on a domain
                # far wider than the film: then p = 0 on its edges is right anyway); where
                # the edges' reduced pressure reaches the law's limit (a gap far below the
                # film's existence limit) no pressure exists there (inf): p = 0 edges, and
                # the solve says no_solution as it did before the far field
                force = self.scene.load.force
                far = (math.isfinite(beyond) and bool(np.all(np.isfinite(p_edges)))
                       and (force is None or beyond < 0.5 * force))
            if far:
                self._levels[key] = PointLevel(setup, tuple(nodes), p_edges, beyond)
            else:
                self._levels[key] = PointLevel(
                    setup, tuple(nodes), boundary_values(setup.grid, self.boundary_pressure))
        return self._levels[key]

    def levels(self) -> list[PointLevel]:
        if not self.elastic:
            return [self.level(self.fine_nodes)]
        seq = [self.fine_nodes]
        while all((m - 1) % 2 == 0 and (m - 1) // 2 + 1 >= COARSEST_NODES for m in seq[-1]):
            seq.append(tuple((m - 1) // 2 + 1 for m in seq[-1]))
        return [self.level(n) for n in seq[::-1]]

    def refine(self, level: PointLevel) -> PointLevel | None:
        """The level with half the spacing (2 n - 1 nodes per direction) for the driver's
        last resort when ``level`` fails, or None for rigid scenes and above
        REFINE_MAX_NODES nodes per direction."""
        nodes = tuple(2 * m - 1 for m in level.nodes)
        if not self.elastic or max(nodes) > REFINE_MAX_NODES:
            return None
        return self.level(nodes)

    def coarsen(self, level: PointLevel) -> PointLevel | None:
        """The level with every other node in each direction, or None."""
        nodes = level.nodes
        if any((m - 1) % 2 or (m - 1) // 2 < 8 for m in nodes):
            return None
        coarse = tuple((m - 1) // 2 + 1 for m in nodes)
        if self.symmetric and coarse[1] % 2 == 0:
            return None
        return self.level(coarse)

    # -- problems --------------------------------------------------------------------------
    def problem(self, level: PointLevel, s: float = 1.0,
                tolerance: float | None = None) -> PointProblem:
        scene = self.scene
        setup = level.setup
        if self.continuation_parameter == "speed":
            flux = flux_model(scene, setup, speed_scale=CONTINUATION_SPEED_FACTOR ** (1.0 - s))
        else:
            flux = flux_model(scene, setup, s)
        force = scene.load.force
        if force is not None and level.exterior_load is not None:
            force = force - level.exterior_load  # the domain carries the rest
        problem = PointProblem(setup.grid, flux, scene.contact.rx,
                               scene.contact.ry, setup.compliance, scene.model.cavitation,
                               force, scene.load.gap, setup.p_ref, setup.h_ref,
                               scene.lubricant.viscosity, level.p_bc, self.squeeze,
                               tolerance=tolerance)
        problem.iteration_sink = self._linear_iterations
        problem.exterior_load = level.exterior_load
        # a new problem means the earlier ones are done with their Newton iterations
        # (the driver moves on to a new level, continuation step or the finish): drop their
        # LU and cached products (they are rebuilt if an earlier problem is used again)
        for old in self._live:
            old.release()
        self._live.add(problem)
        return problem

    def initial_guess(self, level: PointLevel, problem: PointProblem,
                      s: float = 1.0) -> np.ndarray:
        """Hertzian pressure (elastic, loaded) or the rigid isoviscous solution."""
        scene = self.scene
        setup = level.setup
        grid = setup.grid
        if scene.load.force is not None and setup.compliance is not None:
            X, Y = grid.node_coordinates()
            hz = setup.hertz
            # at very light loads the Hertz ellipse may fall between the nodes of the
            # (hydrodynamically long) default grid: the guess spans at least 1.5 cells,
            # or its integral would be 0 and the load scaling NaN (M = 0.3 on 97^2)
            a_x = max(hz.a_x, 1.5 * float(np.max(np.diff(grid.x))))
            a_y = max(hz.a_y, 1.5 * float(np.max(np.diff(grid.y))))
            p = hz.p_h * np.sqrt(np.maximum(1.0 - (X / a_x) ** 2 - (Y / a_y) ** 2, 0.0))
            p = p * scene.load.force / (problem.mass @ p)
            v0 = float(grid.interpolate(problem.displacement(p), np.array([0.0]),
                                        np.array([0.0]))[0])
            h_est = setup.h_estimate
            if self.continuation_parameter == "speed" and s != 1.0:
                c, lub = scene.contact, scene.lubricant   # the start speed's thicker film
                h_est = point_central_film_nvm(
                    scene.load.force, c.rx, c.ry, scene.e_prime, lub.viscosity,
                    scene.kinematics.mean_speed * CONTINUATION_SPEED_FACTOR ** (1.0 - s),
                    lub.effective_piezo)
            return problem.pack(p, h_est - v0)
        return rigid_start(scene, setup, problem,
                           scene.load.gap if scene.load.gap is not None else setup.h_ref)

    def transfer(self, z: np.ndarray, coarse: PointProblem, fine: PointProblem) -> np.ndarray:
        """Bilinear interpolation of a solution to another grid of the same domain (same
        central film); boundary nodes take the fine problem's Dirichlet data."""
        p_c, h0_c = coarse.unpack(z)
        X, Y = fine.grid.node_coordinates()
        p_f = coarse.grid.interpolate(p_c, X, Y)
        fixed = np.ones(p_f.size, dtype=bool)
        fixed[fine.free] = False
        p_f[fixed] = fine.p_bc[fixed]
        o = np.array([0.0])
        hc = float(coarse.grid.interpolate(coarse.film_nodes(p_c, h0_c), o, o)[0])
        if fine.has_h0:
            h0_f = hc - float(fine.grid.interpolate(fine.g_nodes + fine.displacement(p_f),
                                                    o, o)[0])
        else:
            h0_f = h0_c
        return fine.pack(p_f, h0_f)

    def whole(self, problem: PointProblem, z: np.ndarray) -> tuple[PointProblem, np.ndarray]:
        """A half-grid solution mirrored to the whole grid (there the residual of the
        whole discrete system is evaluated and reported); others as they are."""
        if not problem.grid.mirror_y:
            return problem, z
        p_half, h0 = problem.unpack(z)
        nodes = (problem.grid.x.size, 2 * problem.grid.y.size - 1)
        whole = self.problem(self.level(nodes, half=False), 1.0, problem.tolerance)
        for level in self._levels.values():  # the Newton iterations are over
            level.setup.grid.release()
        # the solution's integrals over the quadrature points are twice those of the half
        # grid (every cell lies in one half); :meth:`solution` takes them from there
        whole.mirror_half = (problem, np.array(z, copy=True))
        return whole, whole.pack(problem.compliance.mirror(p_half).ravel(), h0)

    # -- solutions -------------------------------------------------------------------------
    def solution(self, problem: PointProblem, z: np.ndarray | None = None, *,
                 field: np.ndarray | None = None, h0: float | None = None,
                 post: bool = True, cavitated: np.ndarray | None = None) -> Solution:
        """Fields and post-processed numbers of unknowns ``z`` (or of a nodal pressure
        ``field`` at the offset ``h0``, for the linear path; ``cavitated`` marks the
        nodes of its active set). The film's load beyond the domain of a level with
        Kapitsa's far field on its edges (``PointLevel.exterior_load``) is added to the
        load and reported as ``load_beyond_domain`` [N]."""
        scene = self.scene
        grid = problem.grid
        ops = grid.ops
        if z is not None:
            p, h0 = problem.unpack(z)
            if scene.model.cavitation == "reynolds":
                p = np.maximum(p, 0.0)
        else:
            p = np.asarray(field, dtype=float).ravel()
        h_nodes = problem.film_nodes(p, h0)
        out = Solution(x=grid.x, y=grid.y, pressure=np.asarray(p).reshape(grid.shape),
                       film=np.asarray(h_nodes).reshape(grid.shape), h0=float(h0))
        if not post:
            return out
        q = out.quantities
        o = np.array([0.0])
        v = problem.displacement(p)
        exterior_load = problem.exterior_load
        beyond = 0.0 if exterior_load is None else float(exterior_load)
        load = float(problem.mass @ p) + beyond
        gross = float(problem.mass @ np.abs(p)) + beyond
        h_c = float(h0 + grid.interpolate(v, o, o)[0])
        # integrals over the quadrature points: on the half grid a whole-grid solution
        # mirrors (``whole``; every cell lies in one half, so twice its integrals, and the
        # same extrema), with half the temporaries; otherwise on the problem's own grid
        qp, qpress, qcav, weight = problem, p, cavitated, 1.0
        half = getattr(problem, "mirror_half", None) if z is not None else None
        if half is not None:
            qp, weight = half[0], 2.0
            qpress = qp.unpack(half[1])[0]
            if scene.model.cavitation == "reynolds":
                qpress = np.maximum(qpress, 0.0)
        del v
        qgrid = qp.grid
        qops = qgrid.ops
        pq, h_q, gp, eta_q, gq, stab = qp.post_fields(qpress, h0)
        nums, notes = film_numbers(
            h_nodes, h_q, h_c, p, load, grid.x, grid.y,
            constriction=(None if scene.model.elasticity == "rigid"
                          else "the outlet constriction"))
        q.update(nums)
        if exterior_load is not None:
            q["load_beyond_domain"] = beyond
        if scene.model.cavitation == "reynolds":
            full = ~qcav if qcav is not None else qpress > 1e-12 * qp.p_ref
            full = full | qgrid.boundary_mask()
            ind = (qops.value @ full.astype(float) >= 0.5).astype(float)
        else:
            ind = np.ones_like(h_q)
        kin = scene.kinematics
        numbers, more, d = friction_and_heat(
            _Weighted(qops, weight), h_q, gp, eta_q, pq, mean_speed=kin.mean_speed,
            sliding_speed=kin.sliding_speed, indicator_q=ind, load=load,
            gross_load=gross, traction=scene.traction,
            reduced=None if gq is None else (gq, qp.flux.viscosity0), stabilisation=stab)
        q.update(numbers)
        out.traction_model = d.shear["model"]
        out.warnings += notes + more
        eta, more = reported_viscosity(problem.flux.viscosity(p).reshape(grid.shape),
                                       law=scene.lubricant.viscosity_law,
                                       reduced=problem.uses_reduced)
        out.extra_fields["viscosity_Pa_s"] = eta
        out.warnings += more
        if self.elastic:
            q["gmres_iterations"] = float(self.linear_iterations())
        return out

    def linear_iterations(self) -> int:
        """GMRES iterations of all problems of the model so far (a subclass that keeps its
        problems in ``_problems`` instead of giving them the shared counter: their sum)."""
        sink = getattr(self, "_linear_iterations", None)
        if sink is not None:
            return int(sink[0])
        return int(sum(pr.linear_iterations for pr in getattr(self, "_problems", ())))

    def linear(self, level: PointLevel, start: Solution | None = None
               ) -> tuple[str, Solution, str, int]:
        """Linear (reduced-pressure) solve on ``level``: status, solution, message and the
        number of linear solves. ``start``: a solution on another grid whose cavitated
        nodes (p <= 0) make the first guess of the cavitated set."""
        scene = self.scene
        lub = scene.lubricant
        law = reduced_law(lub)
        h0 = scene.load.gap
        grid = level.setup.grid
        q_bc = law.to_reduced(level.p_bc)
        guess = None
        if start is not None and start.y is not None:
            from scipy.interpolate import RegularGridInterpolator

            dry = RegularGridInterpolator(
                (start.y, start.x), (np.asarray(start.pressure) <= 0.0).astype(float),
                bounds_error=False, fill_value=0.0)
            yy, xx = np.meshgrid(grid.y, grid.x, indexing="ij")
            guess = dry(np.column_stack((yy.ravel(), xx.ravel()))) > 0.5
        q, solves, active = reduced_pressure_solve(
            grid, h0, scene.contact.rx, scene.contact.ry, scene.kinematics.mean_speed,
            lub.viscosity, q_bc, scene.model.cavitation, self.squeeze, active=guess)
        status, field, msg = pressure_from_reduced(q, law, solves,
                                                   f", {grid.x.size} x {grid.y.size} nodes")
        problem = self.problem(level)
        return status, self.solution(problem, field=field, h0=h0, post=status == "linear",
                                     cavitated=active), msg, solves


# ---------------------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------------------
def solve_point(scene: Scene, *, boundary_pressure: Callable | np.ndarray | None = None,
                squeeze_velocity: float = 0.0, max_iterations: int | None = None,
                progress: Progress | None = None) -> Result:
    """Solve a point/elliptical contact scene under a load, or a rigid one with a gap.

    Parameters
    ----------
    scene : Scene
        ``contact.kind == "point"``. (Elastic scenes with a prescribed gap are solved by
        :func:`bearing_fem.contacts.transient.solve_elastic_gap`; ``bearing_fem.solve``
        routes every scene.)
    boundary_pressure : callable or ndarray, optional
        Dirichlet pressure on the domain boundary [Pa]: a callable ``(x [m], y [m]) -> p``
        on flat arrays, or nodal values of shape (ny, nx) (only boundary nodes are used).
        Default 0. The analytic-oracle tests impose the exact Kapitsa solution this way.
    squeeze_velocity : float
        Approach rate dh0/dt [m/s] (negative: the surfaces approach, positive squeeze
        pressure).
    max_iterations : int, optional
        Overrides ``scene.solver.max_iterations`` (Newton iterations per attempt).
    progress : callable, optional
        Progress callback (:func:`bearing_fem.contacts.driver.solve_levels`).

    Returns
    -------
    Result
        ``x`` (nx,), ``y`` (ny,) [m]; ``pressure`` [Pa] and ``film`` [m] as (ny, nx)
        arrays. Never raises for non-convergence or non-existence (see ``status``).
        When the default set-up fails above :data:`CHECKED_MOES_M`, the scene is solved
        once more on :func:`high_load_scene`; a success there is returned with that scene
        (``result.scene``), its message and a warning.
    """
    if not isinstance(scene, Scene):
        raise SceneError(f"solve_point() needs a Scene, got {type(scene).__name__}")
    if scene.contact.kind != "point":
        raise SceneError(f"solve_point() needs contact.kind = 'point', got "
                         f"{scene.contact.kind!r}")
    if scene.model.elasticity == "half-space" and scene.load.gap is not None:
        raise SceneError("solve_point() solves loaded or rigid point scenes; an elastic "
                         "scene with load.gap (m) is solved by bearing_fem.solve (or "
                         "bearing_fem.contacts.transient.solve_elastic_gap)")
    sq = float(squeeze_velocity)
    if not math.isfinite(sq):
        raise ValueError(f"squeeze_velocity must be finite (m/s), got {squeeze_velocity!r}")
    if max_iterations is not None:
        max_iterations = require_int("max_iterations", max_iterations, 1,
                                     what="Newton iterations per attempt")
        scene = replace(scene, solver=replace(scene.solver, max_iterations=max_iterations))
    t0 = time.perf_counter()
    with blas_threads(BLAS_THREADS):
        plain = boundary_pressure is None and sq == 0.0   # no Dirichlet data, no squeeze
        model = PointModel(scene, boundary_pressure, sq, far_field=plain)
        if is_linear(scene):
            return solve_linear_model(model, scene, t0)
        over = _rigid_barus_overload(scene) if plain else None
        if over is not None:
            return _overload_result(scene, *over, t0)
        result = solve_newton_model(model, scene, t0, progress=progress)
        if not plain:
            return result
        if "load_beyond_domain" not in result.quantities:  # else the far field holds it
            result.warnings += light_load_warning(scene)
        if result.success:
            return result
        narrow = high_load_scene(scene, result.newton_iterations, time.perf_counter() - t0)
        if narrow is None:
            return result
        return _high_load_outcome(scene, result, narrow, solve_newton_model(
            PointModel(narrow), narrow, t0, progress=progress))


def light_load_warning(scene: Scene) -> list[str]:
    """A warning for a loaded elastic scene on the default domain below
    :data:`LIGHT_LOAD_MOES_M`, whose film the domain's truncation of the pressure field
    makes wrong by tens of percent (an error the grid error estimate does not contain).
    :func:`solve_point` adds it only where the edges carry no far field
    (:func:`far_field_applies`: full-Sommerfeld scenes).

    Parameters
    ----------
    scene : Scene
        A point scene.

    Returns
    -------
    list of str
        One sentence, or empty where it does not apply (rigid, prescribed gap, a given
        ``mesh.x_range``, ``mesh.y_range`` or ``mesh.file``, or M >= the threshold).
    """
    mesh = scene.mesh
    if not (scene.model.elasticity == "half-space" and scene.load.force is not None
            and mesh.file is None and mesh.x_range is None and mesh.y_range is None):
        return []
    m = _moes_point_m(scene)
    if m >= LIGHT_LOAD_MOES_M:
        return []
    (x0, x1), (y0, y1) = default_ranges(scene)
    return [f"light load (Moes M = {m:.3g} < {LIGHT_LOAD_MOES_M:g}): the film's pressure "
            f"reaches beyond the default domain x in [{x0:.3g}, {x1:.3g}] a_x, y in "
            f"[{y0:.3g}, {y1:.3g}] a_y, whose truncation moved h_central by tens of "
            "percent at such loads (an error not contained in error_estimate); give "
            "mesh.x_range and mesh.y_range several times longer and wider and compare "
            "(docs/point.md)"]


def _overload_result(scene: Scene, limit: float, h_star: float, t0: float) -> Result:
    """``no_solution`` for a rigid Barus load above its limit, without Newton iterations:
    the fields are the reduced pressure q at a gap 5 % below h0* (the isoviscous linear
    solve on the scene's grid, so q whatever its domain; on the default one alpha q_max
    exceeds 1 there), the message names the load and the limit."""
    gap = 0.95 * h_star
    message = (f"no_solution: load.force = {scene.load.force:.4g} N exceeds what the rigid "
               f"Barus point contact can carry: its largest load is {limit:.4g} N, at the "
               f"gap h0 = {h_star:.4g} m where alpha q_max = 1 (Kapitsa's existence limit "
               "alpha q_max < 1, docs/theory.md; the isoviscous reduced pressure grows as "
               "h0^(-3/2) as the gap closes). Lower the load, give the gap (load.gap) "
               "instead, or model the elasticity. The pressure field holds the reduced "
               f"pressure q at the gap {gap:.4g} m, no Newton iteration was run.")
    # the isoviscous solve of the same gap is q itself (a Barus solve returns p where
    # alpha q_max < 1, as on a domain narrower than the default one)
    return overload_result(lambda sc: PointModel(sc, far_field=True), scene, gap, message,
                           t0)


def high_load_scene(scene: Scene, spent_iterations: int = 0,
                    spent_seconds: float = 0.0) -> Scene | None:
    """The scene on :data:`HIGH_LOAD_RANGES` and :data:`HIGH_LOAD_NODES`, solved when the
    default set-up of a loaded, elastic, piezo-viscous scene above
    :data:`CHECKED_MOES_M` (default domain) fails; its solver budget is what the first
    solve left (``spent_iterations`` Newton iterations, ``spent_seconds`` s). None where
    it does not apply or nothing is left.
    """
    if not (scene.model.elasticity == "half-space" and scene.load.force is not None
            and scene.lubricant.effective_piezo > 0.0 and scene.mesh.file is None
            and scene.mesh.x_range is None and scene.mesh.y_range is None
            and _moes_point_m(scene) > CHECKED_MOES_M):
        return None
    solver = scene.solver
    left = solver.iteration_budget - int(spent_iterations)
    seconds = None if solver.time_limit is None else solver.time_limit - spent_seconds
    if left < 1 or (seconds is not None and seconds <= 0.0):
        return None
    (x0, x1), (y0, y1) = HIGH_LOAD_RANGES
    n = max((HIGH_LOAD_NODES, *_nodes(scene, ELASTIC_NODES)))
    n += 1 - n % 2  # odd: the y-symmetric half grid
    return replace(scene, mesh=replace(scene.mesh, nodes=(n, n), x_range=(x0, x1),
                                       y_range=(y0, y1)),
                   solver=replace(solver, iteration_budget=left, time_limit=seconds))


def _high_load_outcome(scene: Scene, first: Result, narrow: Scene, second: Result) -> Result:
    """The result of the high-load second solve (:func:`high_load_scene`) when it
    succeeded, else the first, each saying what was tried."""
    (x0, x1), (y0, y1) = HIGH_LOAD_RANGES
    n = narrow.mesh.nodes[0]
    where = (f"x in [{x0:g}, {x1:g}] a_x, y in [{y0:g}, {y1:g}] a_y on {n}x{n} nodes")
    m = _moes_point_m(scene)
    if not second.success:
        first.newton_iterations += second.newton_iterations
        first.message += (f" At Moes M = {m:.4g}, above the checked M <= {CHECKED_MOES_M:g}, "
                          f"the narrower domain {where} was tried too: {second.status} "
                          f"after {second.newton_iterations} Newton iterations "
                          f"({first.newton_iterations} in all).")
        first.wall_time_s = second.wall_time_s
        return first
    second.newton_iterations += first.newton_iterations
    second.message += (f"; the default domain failed first ({first.status} after "
                       f"{first.newton_iterations} Newton iterations; "
                       f"{second.newton_iterations} in all) and this result is on {where}")
    second.warnings.insert(0, (
        f"solved on the narrower domain {where}: at Moes M = {m:.4g}, above the "
        f"checked M <= {CHECKED_MOES_M:g}, the default domain failed ({first.status}); a "
        "short inlet can starve a strongly piezo-viscous contact (h_central -0.3 to -0.9 % "
        "measured at M = 500-2000), an error not contained in error_estimate"))
    return second

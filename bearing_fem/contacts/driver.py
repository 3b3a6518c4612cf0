"""One driver for every contact kind: grid levels, attempts, continuation, finish.

A contact kind (line, point, the elastic start of a transient series) describes itself
by a small protocol, :class:`ContactModel`; this module knows nothing of its physics and
imports none of the contact modules.

Strategy of :func:`solve_levels` (measured reasons in ``docs/theory.md``, "Solver"):

1. **Grid sequencing.** The grids of ``model.levels()`` are solved coarse to fine; each
   finer level starts from the interpolated solution of the one below
   (``model.transfer``), so it needs only a few Newton iterations.
2. **Attempts.** On each level a direct damped Newton attempt
   (:func:`bearing_fem.numerics.newton.damped_newton`); if it fails and the scene allows
   continuation, natural-parameter continuation in the model's parameter (the
   pressure-viscosity coefficient alpha, the entrainment speed, or the compliance),
   first warm (from the interpolated solution at s = ``warm_start``) where the model
   asks for it, then from the initial guess at s = 0.
3. **Fallback.** If a level fails after a coarser one succeeded, the finest grid is
   tried once more from the initial guess alone.
4. **Budget.** Every Newton iteration of every attempt is charged to one
   :class:`~bearing_fem.numerics.newton.Budget` (``solver.iteration_budget``,
   ``solver.time_limit``); once it is spent the solve ends with the status
   ``budget_exhausted`` or ``time_limit``.

:func:`finish` turns the outcome into a :class:`~bearing_fem.result.Result`: the
model post-processes the finest solution and every converged coarser level, and the
level-to-level changes give the error estimate (:func:`bearing_fem.post.error_estimate`).
"""
from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Protocol, Sequence

import numpy as np

from .. import post
from ..numerics.newton import (BUDGET_STATUSES, Budget, NonlinearProblem, blas_threads,
                               continuation, damped_newton, outcome_message)
from ..result import SUCCESS_STATUSES, Result

log = logging.getLogger(__name__)

#: Progress callback of a solve: called with one dict per event (see :func:`solve_levels`).
Progress = Callable[[dict[str, Any]], None]


@dataclass(frozen=True)
class DriverSettings:
    """How the driver attacks one contact kind (line and point are tuned differently).

    Attributes
    ----------
    direct_iterations : int or None
        Cap on the direct attempt from the initial guess (None: ``solver.max_iterations``).
    transfer_iterations : int or None
        Cap on the direct attempt from a solution interpolated from a coarser level.
    continuation_iterations : int or None
        Cap on the Newton iterations of each continuation step.
    start_shift, transfer_shift : float
        Initial Newton regularisation sigma from the initial guess / an interpolated
        solution (``damped_newton(initial_shift=...)``).
    start_memory, transfer_memory : int
        Non-monotone line-search window from the initial guess / an interpolated solution.
    coarse_tolerance : float or None
        Newton tolerance of the coarser levels (they only provide a start); None: the
        scene's tolerance on every level.
    intermediate_tolerance : float or None
        Newton tolerance of continuation steps with s < 1 (None: the level's tolerance).
    warm_start : float or None
        Continuation parameter from which a failed transferred attempt restarts with the
        interpolated solution itself, before the continuation from scratch (None: no
        warm start).
    first_step : float
        First continuation increment from s = 0.
    blas_threads : int or None
        BLAS threads of numpy/scipy during the solve (restored afterwards): 1 for solvers
        whose dense work is small vectors and products, where threads cost more than they
        save (more so on a busy machine); None: the process setting.
    """

    direct_iterations: int | None = None
    transfer_iterations: int | None = None
    continuation_iterations: int | None = None
    start_shift: float = 0.0
    transfer_shift: float = 0.0
    start_memory: int = 5
    transfer_memory: int = 5
    coarse_tolerance: float | None = None
    intermediate_tolerance: float | None = None
    warm_start: float | None = None
    first_step: float = 0.25
    blas_threads: int | None = None


class Level(Protocol):
    """One grid of a sequence: ``label`` names it in messages (``"1001 nodes"``,
    ``"129x129 nodes"``)."""

    label: str


class ContactModel(Protocol):
    """What the driver needs from a contact kind.

    Attributes
    ----------
    settings : DriverSettings
    continuation_parameter : str or None
        What the continuation parameter s in [0, 1] scales (``"alpha"``, ``"speed"``,
        ``"compliance"``), named in messages; None: no continuation.

    A kind may also provide ``refine(level) -> Level | None``, the grid with half the
    spacing of ``level`` (None: none allowed), for the driver's last resort when the
    finest grid fails on its own (:func:`solve_levels`).
    """

    settings: DriverSettings
    continuation_parameter: str | None

    def levels(self) -> Sequence[Level]:
        """Grid sequence, coarse to fine (at least one level)."""

    def problem(self, level: Level, s: float = 1.0,
                tolerance: float | None = None) -> NonlinearProblem:
        """The discrete problem on ``level`` at continuation parameter ``s`` (1: target)."""

    def initial_guess(self, level: Level, problem: NonlinearProblem,
                      s: float = 1.0) -> np.ndarray:
        """Start of a solve at parameter ``s`` without a coarser solution."""

    def transfer(self, z: np.ndarray, coarse: NonlinearProblem,
                 fine: NonlinearProblem) -> np.ndarray:
        """Interpolate a converged coarse solution to a finer problem."""


@dataclass
class LevelSolution:
    """A converged level of the sequence (kept for the error estimate)."""

    level: Any
    problem: Any
    z: np.ndarray


@dataclass
class DriverOutcome:
    """Result of :func:`solve_levels` (scaled unknowns of the finest problem tried).

    ``steps`` lists every attempt and continuation step as
    ``(parameter, "status (grid label)", iterations)``; ``levels`` the converged levels
    coarse to fine (the finest last when the solve converged).
    """

    z: np.ndarray
    problem: Any
    status: str
    iterations: int = 0
    history: list[float] = field(default_factory=list)
    steps: list[tuple[float, str, int]] = field(default_factory=list)
    levels: list[LevelSolution] = field(default_factory=list)
    labels: list[str] = field(default_factory=list)
    continuation_steps: int = 0
    #: labels of first levels that failed, after which the sequence started one finer
    restarts: list[str] = field(default_factory=list)
    #: the finer grid tried when the finest failed (see ``refine``): its label and
    #: whether it converged
    refined: tuple[str, bool] | None = None
    #: label of the requested (finest) grid when the result is the converged solution of
    #: the finer grid instead, because the requested grid failed even from it
    requested: str | None = None

    @property
    def converged(self) -> bool:
        return self.status == "converged"


def make_budget(solver: Any) -> Budget:
    """The :class:`Budget` of a scene's ``[solver]`` section."""
    return Budget(iterations=solver.iteration_budget, seconds=solver.time_limit)


def _level_callback(progress: Progress | None, index: int
                    ) -> Callable[[int, float], None] | None:
    if progress is None:
        return None

    def callback(iteration: int, residual: float) -> None:
        progress({"event": "newton", "level": index, "iteration": int(iteration),
                  "residual": float(residual)})

    return callback


def attempt(model: ContactModel, level: Level, problem: NonlinearProblem, z0: np.ndarray,
            *, solver: Any, tolerance: float, transferred: bool, budget: Budget,
            callback: Callable[[int, float], None] | None = None) -> DriverOutcome:
    """Direct damped Newton on one level, then continuation as the fallback.

    Parameters
    ----------
    model : ContactModel
    level : Level
    problem : NonlinearProblem
        The level's target problem (s = 1).
    z0 : ndarray
        Start (initial guess, or a solution interpolated from a coarser level).
    solver : SolverSpec
        The scene's ``[solver]`` section (``max_iterations``, ``continuation``).
    tolerance : float
        Newton tolerance of this level (scaled residual, max norm).
    transferred : bool
        True if ``z0`` was interpolated from a coarser level.
    budget : Budget
    callback : callable, optional
        ``callback(iteration, residual)`` after each accepted Newton step.

    Returns
    -------
    DriverOutcome
        ``z`` the converged solution, or the better of the failed iterates.
    """
    st = model.settings
    cap = st.transfer_iterations if transferred else st.direct_iterations
    maxit = solver.max_iterations if cap is None else min(cap, solver.max_iterations)
    shift = st.transfer_shift if transferred else st.start_shift
    memory = st.transfer_memory if transferred else st.start_memory
    out = damped_newton(problem, z0, tol=tolerance, max_iterations=maxit, memory=memory,
                        initial_shift=shift, callback=callback, budget=budget)
    result = DriverOutcome(out.z, problem, out.status, out.iterations, list(out.history),
                           [(1.0, out.status, out.iterations)])
    if (out.converged or not solver.continuation or model.continuation_parameter is None
            or out.status in BUDGET_STATUSES):
        return result
    cont_cap = st.continuation_iterations
    cont_maxit = solver.max_iterations if cont_cap is None else min(cont_cap,
                                                                    solver.max_iterations)
    starts: list[tuple[float, np.ndarray | None]] = []
    if transferred and st.warm_start is not None:
        starts.append((st.warm_start, z0))
    starts.append((0.0, None))
    cont = None
    for s_start, z_start in starts:
        log.info("Newton %s after %d iterations; continuing in %s from s = %g",
                 out.status, result.iterations, model.continuation_parameter, s_start)
        if z_start is None:
            z_start = model.initial_guess(level, problem, s=0.0)
        cont = continuation(
            lambda s: model.problem(level, s, tolerance), z_start, s_start=s_start,
            first_step=st.first_step if s_start == 0.0 else 1.0 - s_start, tol=tolerance,
            intermediate_tol=st.intermediate_tolerance, max_iterations=cont_maxit,
            initial_shift=shift, callback=callback, budget=budget)
        result.iterations += cont.iterations
        result.steps += cont.steps
        result.history += list(cont.last.history)
        result.continuation_steps += sum(1 for s in cont.steps if s[0] < 1.0)
        if cont.parameter >= 1.0 and cont.status == "converged":
            result.z, result.status = cont.z, "converged"
            return result
        if cont.status in BUDGET_STATUSES:
            result.status = cont.status
            break
    if cont is not None and cont.parameter >= 1.0:
        # both failed at the target: keep the iterate with the smaller residual
        problem.prepare(out.z)
        r_direct = float(np.max(np.abs(problem.residual(out.z))))
        problem.prepare(cont.z)
        if float(np.max(np.abs(problem.residual(cont.z)))) < r_direct:
            result.z = cont.z
    return result


def solve_levels(model: ContactModel, solver: Any, *, budget: Budget,
                 progress: Progress | None = None) -> DriverOutcome:
    """Solve a contact model by grid sequencing, attempts and continuation.

    The levels are solved coarse to fine, each from the interpolated solution of the one
    below. Fallbacks, in this order, while the budget lasts: a first level that fails
    from the initial guess is dropped and the sequence starts again one level finer; a
    finer level that fails after a coarser one converged sends the finest grid alone
    from the initial guess; if the finest grid still fails and the model has ``refine``,
    the grid with half its spacing is solved and the finest grid started from that
    solution; if the finest grid fails even from it, the outcome is the finer grid's
    converged solution (``DriverOutcome.requested`` names the grid asked for).

    Parameters
    ----------
    model : ContactModel
    solver : SolverSpec
        The scene's ``[solver]`` section.
    budget : Budget
        Iterations and time of the whole solve (:func:`make_budget`).
    progress : callable, optional
        Called with ``{"event": "level", "level": i, "levels": n, "grid": label}`` when
        a level starts and ``{"event": "newton", "level": i, "iteration": k,
        "residual": r}`` after each accepted Newton step.

    Returns
    -------
    DriverOutcome
    """
    levels = list(model.levels())
    labels = [lv.label for lv in levels]
    total = DriverOutcome(np.zeros(0), None, "max_iterations", labels=labels)
    start = 0
    while True:
        failed = _sequence(model, levels, start, solver, budget, progress, total)
        if (failed is None or total.status in BUDGET_STATUSES or total.levels
                or failed >= len(levels) - 1):
            break
        # the first level of the sequence failed from the initial guess: its grid is too
        # coarse for the contact (measured: circular M = 2000, L = 3.57 stalled on 65^2
        # and converges on 129^2 from the Hertzian start); start again one level finer
        total.restarts.append(levels[failed].label)
        start = failed + 1
    if (not total.converged and total.status not in BUDGET_STATUSES and len(levels) > 1
            and total.levels):
        # a level failed after a coarser one converged: the finest grid alone, from the
        # initial guess
        level = levels[-1]
        if progress is not None:
            progress({"event": "level", "level": len(levels) - 1, "levels": len(levels),
                      "grid": level.label})
        problem = model.problem(level, 1.0, solver.tolerance)
        out = attempt(model, level, problem, model.initial_guess(level, problem),
                      solver=solver, tolerance=solver.tolerance, transferred=False,
                      budget=budget, callback=_level_callback(progress, len(levels) - 1))
        _accumulate(total, out, level.label)
        if out.converged:
            total.levels = [LevelSolution(level, problem, out.z)]
    if not total.converged and total.status not in BUDGET_STATUSES:
        _from_finer_grid(model, levels, solver, budget, progress, total)
    return total


def _from_finer_grid(model: ContactModel, levels: list, solver: Any, budget: Budget,
                     progress: Progress | None, total: DriverOutcome) -> None:
    """Last resort when the finest grid failed: solve the grid with half its spacing
    (``model.refine``, if the model has one and allows it) from the initial guess, and
    start the finest grid from that solution restricted to it; if that fails, the outcome
    is the finer grid's converged solution (``total.requested`` set). For grids too coarse for
    the contact to converge from the initial guess (measured: circular M = 2000,
    L = 3.57 on 97^2 stalled from the Hertzian start; 193^2 converges in 18 iterations,
    and 97^2 from its solution in 12)."""
    refine = getattr(model, "refine", None)
    level = levels[-1]
    finer = refine(level) if refine is not None else None
    if finer is None:
        return
    n = len(levels)
    if progress is not None:
        progress({"event": "level", "level": n - 1, "levels": n, "grid": finer.label})
    fine_problem = model.problem(finer, 1.0, solver.tolerance)
    kept = (total.z, total.problem, total.status)
    out = attempt(model, finer, fine_problem, model.initial_guess(finer, fine_problem),
                  solver=solver, tolerance=solver.tolerance, transferred=False,
                  budget=budget, callback=_level_callback(progress, n - 1))
    _accumulate(total, out, finer.label)
    total.refined = (finer.label, out.converged)
    fine = out
    if not out.converged:
        # the result stays on the requested grid: its last iterate, and its status
        # unless the budget ran out on the finer grid
        total.z, total.problem = kept[0], kept[1]
        if out.status not in BUDGET_STATUSES:
            total.status = kept[2]
        return
    problem = model.problem(level, 1.0, solver.tolerance)
    if progress is not None:
        progress({"event": "level", "level": n - 1, "levels": n, "grid": level.label})
    out = attempt(model, level, problem, model.transfer(out.z, fine_problem, problem),
                  solver=solver, tolerance=solver.tolerance, transferred=True,
                  budget=budget, callback=_level_callback(progress, n - 1))
    _accumulate(total, out, level.label)
    if out.converged:
        total.levels = [LevelSolution(level, problem, out.z)]
    elif out.status not in BUDGET_STATUSES:
        # the requested grid has no converged solution even from the finer one (measured:
        # a 100 N ball at 0.1 m/s, M = 4.9e3, L = 4.3, on the default 129^2 grid): the
        # result is the finer grid's converged solution, and says so
        total.z, total.problem, total.status = fine.z, fine_problem, fine.status
        total.levels = [LevelSolution(finer, fine_problem, fine.z)]
        total.requested = level.label


def _sequence(model: ContactModel, levels: list, start: int, solver: Any, budget: Budget,
              progress: Progress | None, total: DriverOutcome) -> int | None:
    """Solve ``levels[start:]`` coarse to fine into ``total`` (the first from the
    initial guess, each further one from the interpolated solution of the one below);
    return the index of the level that failed, or None."""
    st = model.settings
    prev: LevelSolution | None = None
    for i in range(start, len(levels)):
        level = levels[i]
        if progress is not None:
            progress({"event": "level", "level": i, "levels": len(levels),
                      "grid": level.label})
        finest = i == len(levels) - 1
        tol = solver.tolerance
        if not finest and st.coarse_tolerance is not None:
            tol = max(tol, st.coarse_tolerance)
        problem = model.problem(level, 1.0, tol)
        if prev is None:
            z0 = model.initial_guess(level, problem)
        else:
            z0 = model.transfer(prev.z, prev.problem, problem)
        out = attempt(model, level, problem, z0, solver=solver, tolerance=tol,
                      transferred=prev is not None, budget=budget,
                      callback=_level_callback(progress, i))
        _accumulate(total, out, level.label)
        if not out.converged:
            return i
        prev = LevelSolution(level, problem, out.z)
        total.levels.append(prev)
    return None


def _accumulate(total: DriverOutcome, out: DriverOutcome, label: str) -> None:
    total.z, total.problem, total.status = out.z, out.problem, out.status
    total.iterations += out.iterations
    total.history += out.history
    total.steps += [(s, f"{status} ({label})", its) for s, status, its in out.steps]
    total.continuation_steps += out.continuation_steps


# ---------------------------------------------------------------------------------------
# finish: outcome -> Result
# ---------------------------------------------------------------------------------------
@dataclass
class Solution:
    """Fields and numbers of one solution, as a contact model post-processes it.

    Attributes
    ----------
    x, y : ndarray
        Node coordinates [m] (``y`` None for line contacts).
    pressure, film : ndarray
        Nodal fields [Pa], [m] (shape (nx,) or (ny, nx)).
    h0 : float
        Rigid offset [m].
    quantities : dict
        Post-processed numbers (``bearing_fem.post``); empty when not post-processed.
    extra_fields : dict
        Further nodal fields (names carry units).
    warnings : list of str
        Model-specific warnings about this solution.
    traction_model : str or None
        Shear-stress model of the sliding friction (None when not post-processed).
    """

    x: np.ndarray
    y: np.ndarray | None
    pressure: np.ndarray
    film: np.ndarray
    h0: float
    quantities: dict[str, Any] = field(default_factory=dict)
    extra_fields: dict[str, np.ndarray] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    traction_model: str | None = None


def finish(scene: Any, solution: Solution, *, status: str, message: str, t0: float,
           iterations: int = 0, linear_solves: int = 0, history: Sequence[float] = (),
           continuation_steps: Sequence[tuple[float, str, int]] = (),
           coarse: Sequence[Solution] = (), estimate_note: str = "",
           warnings: Sequence[str] = (), estimate: bool = True,
           residual: float | None = None) -> Result:
    """Assemble the :class:`~bearing_fem.result.Result` of a solve.

    Parameters
    ----------
    scene : Scene
    solution : Solution
        The finest solution (post-processed when the solve succeeded).
    status, message : str
    t0 : float
        ``time.perf_counter()`` at the start of the solve [s].
    iterations, linear_solves : int
    history : sequence of float
        Scaled residual after each Newton iteration.
    continuation_steps : sequence
        ``(parameter, status, iterations)`` of every attempt and continuation step.
    coarse : sequence of Solution
        Post-processed solutions of the coarser levels, coarse to fine, all on grids with
        half the spacing of the next (for the error estimate).
    estimate_note : str
        Appended to the error estimate's ``method`` (e.g. which levels were used).
    warnings : sequence of str
        Warnings to report besides those of the solution and the estimate.
    estimate : bool
        False when the solve makes no error estimate by design (the instants of an
        elastic series share one grid): no estimate, and no warning that one is missing.
    residual : float or None
        Scaled residual (max norm) of the returned fields on the scene's own problem.
    """
    success = status in SUCCESS_STATUSES
    notes = list(warnings) + list(solution.warnings)
    error_estimate = None
    if estimate and success and solution.quantities:
        error_estimate = post.error_estimate(
            [c.quantities for c in coarse] + [solution.quantities], note=estimate_note)
        notes += post.estimate_warnings(error_estimate)
    return Result(success=success, status=status, message=message, scene=scene,
                  x=solution.x, y=solution.y, pressure=solution.pressure,
                  film=solution.film, h0=float(solution.h0),
                  quantities=dict(solution.quantities), history=list(history),
                  newton_iterations=int(iterations), linear_solves=int(linear_solves),
                  wall_time_s=time.perf_counter() - t0,
                  continuation=list(continuation_steps),
                  extra_fields=dict(solution.extra_fields),
                  warnings=_unique(notes), error_estimate=error_estimate,
                  traction_model=solution.traction_model,
                  residual=None if residual is None else float(residual))


def _unique(items: Sequence[str]) -> list[str]:
    seen: list[str] = []
    for s in items:
        if s not in seen:
            seen.append(s)
    return seen


def outcome_text(outcome: DriverOutcome, residual: float, solver: Any, budget: Budget,
                 *, parameter: str | None = None, prefix: str = "",
                 grid_note: str = "", admissible: bool = True) -> str:
    """Status message of a Newton solve: iterations, grids, continuation (in
    ``parameter``), residual, and what was spent when the budget ran out; ``admissible``
    False says that the returned iterate is not admissible
    (:func:`~bearing_fem.numerics.newton.outcome_message`)."""
    note = ""
    if outcome.continuation_steps:
        n = outcome.continuation_steps
        note = f", continuation in {parameter} ({n} step{'' if n == 1 else 's'})"
    grids = "[" + ", ".join(lb.removesuffix(" nodes") for lb in outcome.labels) + "]"
    for lb in outcome.restarts:
        note += f"; {lb} failed, the sequence started again one grid finer"
    if outcome.refined is not None:
        label, converged = outcome.refined
        if outcome.requested is not None:
            note += (f"; the requested grid failed alone, and again when started from the "
                     f"converged solution on {label} (half the spacing): the result is that "
                     f"solution on {label}, not one on the requested {outcome.requested}")
        else:
            note += (f"; the finest grid failed alone and was started from the solution on "
                     f"{label}" if converged else
                     f"; the finest grid failed alone, and so did {label} (half the spacing)")
    detail = f" (grids {grids}{grid_note}{note})" if outcome.labels else note
    msg = outcome_message(outcome.status, outcome.iterations, residual, solver.tolerance,
                          prefix=prefix, detail=detail, cap=solver.max_iterations,
                          admissible=admissible)
    if outcome.status in BUDGET_STATUSES:
        msg += f" Spent {budget.describe()}."
    return msg


# ---------------------------------------------------------------------------------------
# whole solves of a model
# ---------------------------------------------------------------------------------------
#: Coarser levels solved for the error estimate below the finest grid (two give the
#: observed order of convergence, :func:`bearing_fem.post.error_estimate`).
ESTIMATE_LEVELS = 2


def estimate_levels(model: Any, outcome: DriverOutcome, solver: Any,
                    budget: Budget) -> list[LevelSolution]:
    """The converged solutions on the ``ESTIMATE_LEVELS`` grids below the finest, coarse
    to fine (each with twice the spacing of the next).

    Levels the sequence already solved are reused; a missing one is solved from the
    finer solution restricted to it (a start so close that a few Newton iterations
    do). A level that does not converge, or a spent budget, ends the list.
    """
    out: list[LevelSolution] = []
    finer = outcome.levels[-1]
    st = model.settings
    for _ in range(ESTIMATE_LEVELS):
        level = model.coarsen(finer.level)
        if level is None or budget.exhausted():
            break
        found = next((s for s in outcome.levels if s.level is level), None)
        if found is None:
            problem = model.problem(level, 1.0, solver.tolerance)
            z0 = model.transfer(finer.z, finer.problem, problem)
            cap = st.transfer_iterations or solver.max_iterations
            res = damped_newton(problem, z0, tol=solver.tolerance,
                                max_iterations=min(cap, solver.max_iterations),
                                memory=st.transfer_memory, initial_shift=st.transfer_shift,
                                budget=budget)
            if not res.converged:
                log.debug("error-estimate level %s: %s", level.label, res.status)
                break
            found = LevelSolution(level, problem, res.z)
        out.insert(0, found)
        finer = found
    return out


def solve_newton_model(model: Any, scene: Any, t0: float, *,
                       progress: Progress | None = None, prefix: str = "") -> Result:
    """Newton solve of a model by :func:`solve_levels`, finished into a Result with an
    error estimate from the coarser levels (BLAS threads as ``model.settings``)."""
    with blas_threads(getattr(model.settings, "blas_threads", None)):
        return _solve_newton_model(model, scene, t0, progress=progress, prefix=prefix)


def _solve_newton_model(model: Any, scene: Any, t0: float, *,
                        progress: Progress | None = None, prefix: str = "") -> Result:
    budget = make_budget(scene.solver)
    outcome = solve_levels(model, scene.solver, budget=budget, progress=progress)
    problem, z = model.whole(outcome.problem, outcome.z)
    problem.prepare(z)
    residual = float(np.max(np.abs(problem.residual(z))))
    message = outcome_text(outcome, residual, scene.solver, budget,
                           parameter=model.continuation_parameter, prefix=prefix,
                           grid_note=getattr(model, "grid_note", ""),
                           admissible=outcome.converged or problem.admissible(z))
    solution = model.solution(problem, z)
    coarse: list[Solution] = []
    if outcome.converged:
        for lv in estimate_levels(model, outcome, scene.solver, budget):
            coarse.append(model.solution(*model.whole(lv.problem, lv.z)))
    notes = []
    if outcome.requested is not None:  # set together with ``refined``
        notes.append(f"the requested grid ({outcome.requested}) has no converged solution; "
                     f"the result is on {outcome.refined[0]} (half the spacing)")
    return finish(scene, solution, status=outcome.status, message=message, t0=t0,
                  iterations=outcome.iterations, history=outcome.history,
                  continuation_steps=outcome.steps, coarse=coarse,
                  estimate_note=_levels_note(coarse, solution), warnings=notes,
                  residual=residual)


def solve_linear_model(model: Any, scene: Any, t0: float) -> Result:
    """Linear (reduced-pressure) solve of a model's finest level, with the error
    estimate from the same solve on ``ESTIMATE_LEVELS`` coarser grids.

    The grids are solved coarse to fine, each cavitated set starting from the coarser
    solution's (``model.linear(level, start=...)``); the estimate uses the coarser
    solutions down to the first that failed."""
    chain = [model.levels()[-1]]
    for _ in range(ESTIMATE_LEVELS):
        level = model.coarsen(chain[0])
        if level is None:
            break
        chain.insert(0, level)
    start = None
    solved: list[tuple[str, Solution]] = []
    for level in chain[:-1]:
        st, start, _, _ = model.linear(level, start=start)
        solved.append((st, start))
    status, solution, message, solves = model.linear(chain[-1], start=start)
    coarse: list[Solution] = []
    if status in SUCCESS_STATUSES:
        for st, sol in reversed(solved):
            if st not in SUCCESS_STATUSES:
                break
            coarse.insert(0, sol)
    return finish(scene, solution, status=status, message=message, t0=t0,
                  linear_solves=solves, coarse=coarse,
                  estimate_note=_levels_note(coarse, solution))


def overload_result(model_class: Any, scene: Any, gap: float, message: str,
                    t0: float) -> Result:
    """``no_solution`` of a rigid Barus scene loaded beyond what it can carry, without
    Newton iterations: its fields are the reduced pressure q at ``gap`` [m] (the
    isoviscous solve of that gap is q itself: one linear solve on the scene's finest
    grid, no error estimate), ``message`` its message. ``model_class(scene)`` builds the
    contact model (``LineModel``, ``PointModel``)."""
    linear = replace(scene, load=replace(scene.load, force=None, gap=gap),
                     lubricant=replace(scene.lubricant, viscosity_law="constant"))
    model = model_class(linear)
    _, solution, _, solves = model.linear(model.levels()[-1])
    return finish(scene, replace(solution, quantities={}, traction_model=None),
                  status="no_solution", message=message, t0=t0, linear_solves=solves)


def _levels_note(coarse: Sequence[Solution], fine: Solution) -> str:
    def size(s: Solution) -> str:
        return str(s.x.size) if s.y is None else f"{s.x.size}x{s.y.size}"
    return "grids " + ", ".join(size(s) for s in list(coarse) + [fine])

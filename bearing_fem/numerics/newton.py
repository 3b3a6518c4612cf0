"""Damped Newton with a residual line search, and a continuation driver.

The nonlinear problems of the package (line and point contacts) expose a small
interface, :class:`NonlinearProblem`; this module knows nothing of the physics.

* Newton step  J dz = -F  (dense LU, sparse LU or a Krylov solver chosen by the problem).
* Line search: backtracking lam = 1, 1/2, ... on the merit f = |F|^2 / 2 with the
  Armijo condition f(z + lam dz) <= (1 - 2 c lam) f(z), c = 1e-4, accepting only
  admissible iterates (positive film, finite values).
* Status strings follow scipy's contract: ``converged``, ``max_iterations``,
  ``stalled`` (no admissible decrease along the Newton direction), ``diverged``
  (non-finite values), and ``budget_exhausted`` / ``time_limit`` when the
  :class:`Budget` of the whole solve is spent.
"""
from __future__ import annotations

import contextlib
import logging
import math
import time
from dataclasses import dataclass, field
from typing import Callable, Iterator, Protocol

import numpy as np
from threadpoolctl import threadpool_limits

log = logging.getLogger(__name__)


class NonlinearProblem(Protocol):
    """What :func:`damped_newton` needs from a discretised problem."""

    def prepare(self, z: np.ndarray) -> None:
        """Freeze iteration-level scalings at the current iterate."""

    def residual(self, z: np.ndarray) -> np.ndarray:
        """Scaled residual F(z) (dimensionless)."""

    def newton_step(self, z: np.ndarray, shift: float = 0.0) -> np.ndarray:
        """Solve (J(z) + shift D) dz = -F(z) and return dz (D: identity on field unknowns)."""

    def admissible(self, z: np.ndarray) -> bool:
        """True if z is a physically admissible iterate (e.g. positive film)."""


@contextlib.contextmanager
def blas_threads(limit: int | None) -> Iterator[None]:
    """Limit the BLAS threads of numpy/scipy to ``limit`` inside the block and restore
    the previous setting on exit (None: no change). For solves whose dense work is small
    vectors and small products, where thread start-up costs more than it saves."""
    if limit is None:
        yield
        return
    with threadpool_limits(limits=int(limit), user_api="blas"):
        yield


#: Statuses that end a whole solve (not just one attempt): the budget is spent.
BUDGET_STATUSES = ("budget_exhausted", "time_limit")


class Budget:
    """Newton iterations and wall time allowed to a whole solve (all grids, attempts and
    continuation steps together).

    Parameters
    ----------
    iterations : int or None
        Newton iterations allowed (None: no limit).
    seconds : float or None
        Wall-clock time allowed [s] (None: no limit), counted from construction.
    """

    def __init__(self, iterations: int | None = None, seconds: float | None = None) -> None:
        self.iterations = iterations
        self.seconds = seconds
        self.used = 0
        self._start = time.perf_counter()

    @property
    def elapsed(self) -> float:
        """Wall time since construction [s]."""
        return time.perf_counter() - self._start

    def charge(self, iterations: int = 1) -> None:
        """Count Newton iterations against the budget."""
        self.used += int(iterations)

    def exhausted(self) -> str | None:
        """``"budget_exhausted"`` or ``"time_limit"`` once spent, else None."""
        if self.iterations is not None and self.used >= self.iterations:
            return "budget_exhausted"
        if self.seconds is not None and self.elapsed >= self.seconds:
            return "time_limit"
        return None

    def describe(self) -> str:
        """What was spent, for messages."""
        its = f"{self.used} Newton iterations" + (
            f" of a budget of {self.iterations}" if self.iterations is not None else "")
        t = f"{self.elapsed:.3g} s" + (f" of a time limit of {self.seconds:.3g} s"
                                       if self.seconds is not None else "")
        return f"{its}, {t}"


@dataclass
class NewtonOutcome:
    """Result of :func:`damped_newton` (scaled unknowns)."""

    z: np.ndarray
    status: str
    iterations: int
    residual_norm: float
    history: list[float] = field(default_factory=list)
    step_lengths: list[float] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def converged(self) -> bool:
        return self.status == "converged"


def damped_newton(problem: NonlinearProblem, z0: np.ndarray, *, tol: float = 1e-8,
                  max_iterations: int = 50, min_step: float = 2.0**-8,
                  memory: int = 5, initial_shift: float = 0.0,
                  callback: Callable[[int, float], None] | None = None,
                  budget: Budget | None = None) -> NewtonOutcome:
    """Damped, diagonally regularised Newton iteration on ``problem`` from ``z0``.

    Each iteration solves (J + sigma D) dz = -F, D = identity on the field unknowns
    (pseudo-transient / Levenberg-Marquardt regularisation), then backtracks
    lam = 1, 1/2, ... >= ``min_step`` on the merit |F|^2/2 with a non-monotone Armijo
    rule (Grippo, Lampariello & Lucidi 1986): the reference is the largest merit of the
    last ``memory`` iterates. Allowing a temporary increase lets full steps through the
    strongly nonlinear outlet region of EHL contacts (measured: M=100, L=10 on 901 nodes
    converged in 18 iterations with memory 5, stalled after 28 with the monotone rule;
    isoviscous M=500 and M=10 stalled monotone, converged in 8 and 10). If no step is
    accepted, sigma grows (x10, from 1e-2; stall above 1) and the iteration is repeated; after an
    accepted step sigma shrinks (/4) and is dropped below 1e-8, so the final iterations
    are plain Newton with quadratic convergence. Far from the solution the
    regularisation keeps nodes whose linearisation is poor (e.g. where
    exp(alpha p) varies by orders of magnitude) from derailing the whole step.

    Parameters
    ----------
    problem : NonlinearProblem
    z0 : ndarray
        Initial (scaled) unknowns, admissible for the iteration to move (a step is
        accepted only to an admissible iterate; an inadmissible start is returned
        as it is when no step is accepted).
    tol : float
        Convergence when max|F| <= tol.
    max_iterations : int
        Cap on linear solves (Newton iterations, accepted or rejected).
    min_step : float
        Smallest line-search factor tried before the regularisation is increased.
    memory : int
        Window of the non-monotone line search (1 = monotone).
    initial_shift : float
        sigma of the first iteration (0: plain Newton from the start). A start that is
        close in most of the domain but not near a sharp feature (a solution
        interpolated from a coarser grid) converges more reliably with a small shift
        that decays (/4 per accepted step) before plain Newton takes over.
    callback : callable, optional
        ``callback(iteration, residual_norm)`` after every accepted step.
    budget : Budget, optional
        Iterations and time of the whole solve; every iteration is charged to it and
        the iteration stops with its status (``budget_exhausted``, ``time_limit``)
        once it is spent.

    Returns
    -------
    NewtonOutcome
        The last accepted iterate (admissible, never NaNs), or the starting guess where
        no step was accepted (not tested for admissibility: it may have a negative film).
    """
    t0 = time.perf_counter()
    z = np.array(z0, dtype=float)
    problem.prepare(z)
    f = problem.residual(z)
    if not np.all(np.isfinite(f)):
        return NewtonOutcome(z, "diverged", 0, float("inf"), seconds=time.perf_counter() - t0)
    norm = float(np.max(np.abs(f))) if f.size else 0.0
    history = [norm]
    steps: list[float] = []
    status = "max_iterations"
    it = 0
    sigma = float(initial_shift)
    merits = [float(f @ f)]
    while True:
        if norm <= tol:
            status = "converged"
            break
        if it >= max_iterations:
            status = "max_iterations"
            break
        if sigma > 1.0:  # three regularised retries failed: give up on this attempt
            status = "stalled"
            break
        spent = budget.exhausted() if budget is not None else None
        if spent:
            status = spent
            break
        it += 1
        if budget is not None:
            budget.charge()
        try:
            dz = problem.newton_step(z, shift=sigma)
        except (np.linalg.LinAlgError, RuntimeError) as exc:
            log.debug("linear solve failed: %s", exc)
            sigma = max(4.0 * sigma, 1e-3)
            continue
        if not np.all(np.isfinite(dz)):
            sigma = max(4.0 * sigma, 1e-3)
            continue
        merit = 0.5 * float(f @ f)
        # non-monotone reference (Grippo-Lampariello-Lucidi): the largest of the last
        # ``memory`` merits; memory = 1 is the classical monotone Armijo rule
        ref = max([merit] + [0.5 * h for h in merits[-memory:]]) if memory > 1 else merit
        lam = 1.0
        accepted = False
        with np.errstate(all="ignore"):
            while lam >= min_step:
                zt = z + lam * dz
                if problem.admissible(zt):
                    ft = problem.residual(zt)
                    if np.all(np.isfinite(ft)) and 0.5 * float(ft @ ft) <= (1 - 2e-4 * lam) * ref:
                        accepted = True
                        break
                lam *= 0.5
        if not accepted:
            sigma = max(10.0 * sigma, 1e-2)
            log.debug("newton %d: step rejected, sigma -> %.2e", it, sigma)
            continue
        z, steps = zt, steps + [lam]
        sigma = sigma / 4.0 if sigma > 1e-8 else 0.0
        problem.prepare(z)
        f = problem.residual(z)
        norm = float(np.max(np.abs(f)))
        history.append(norm)
        merits.append(float(f @ f))
        if callback is not None:
            callback(it, norm)
        log.debug("newton %d: |F| = %.3e, step %.3g, sigma %.2e", it, norm, lam, sigma)
    return NewtonOutcome(z, status, it, norm, history, steps, time.perf_counter() - t0)


@dataclass
class ContinuationOutcome:
    """Result of :func:`continuation`."""

    z: np.ndarray
    status: str
    iterations: int
    steps: list[tuple[float, str, int]]
    last: NewtonOutcome
    parameter: float


def continuation(make_problem: Callable[[float], NonlinearProblem], z_start: np.ndarray,
                 *, s_start: float = 0.0, first_step: float = 0.25, tol: float = 1e-8,
                 max_iterations: int = 50, max_steps: int = 40,
                 min_increment: float = 1e-3, intermediate_tol: float | None = None,
                 initial_shift: float = 0.0, memory: int = 5,
                 callback: Callable[[int, float], None] | None = None,
                 budget: Budget | None = None) -> ContinuationOutcome:
    """Natural-parameter continuation s: s_start -> 1 with adaptive steps.

    ``make_problem(s)`` returns the problem at parameter s (s = 1 is the target). Each
    step starts Newton from the last converged solution; a failed step is retried with
    half the increment, a successful one grows it by 1.5. Steps with s < 1 stop at
    ``intermediate_tol`` (default ``tol``: they only provide starting points); the final
    step at s = 1 always converges to ``tol``. ``initial_shift``, ``memory``, ``callback``
    and ``budget`` are passed to every :func:`damped_newton`; a spent budget ends the
    continuation with its status.
    """
    tol_mid = tol if intermediate_tol is None else max(tol, intermediate_tol)
    z = np.array(z_start, dtype=float)
    s = s_start
    ds = first_step
    total = 0
    record: list[tuple[float, str, int]] = []
    last = None
    # converge at the starting parameter first
    newton = dict(max_iterations=max_iterations, initial_shift=initial_shift, memory=memory,
                  callback=callback, budget=budget)
    out = damped_newton(make_problem(s), z, tol=tol if s >= 1.0 else tol_mid, **newton)
    total += out.iterations
    record.append((s, out.status, out.iterations))
    last = out
    if not out.converged:
        return ContinuationOutcome(out.z, out.status, total, record, out, s)
    z = out.z
    for _ in range(max_steps):
        if s >= 1.0:
            break
        s_try = min(1.0, s + ds)
        out = damped_newton(make_problem(s_try), z, tol=tol if s_try >= 1.0 else tol_mid,
                            **newton)
        total += out.iterations
        record.append((s_try, out.status, out.iterations))
        last = out
        if out.converged:
            s, z = s_try, out.z
            ds *= 1.5
        elif out.status in BUDGET_STATUSES:
            break
        else:
            ds *= 0.5
            if ds < min_increment:
                break
    status = "converged" if s >= 1.0 else (last.status if last and not last.converged
                                            else "max_iterations")
    if budget is not None and s < 1.0 and budget.exhausted():
        status = budget.exhausted()
    return ContinuationOutcome(z, status, total, record, last, s)


def outcome_message(status: str, iterations: int, residual: float, tol: float, *,
                    prefix: str = "", detail: str = "", cap: int | None = None,
                    admissible: bool = True) -> str:
    """One-line status message of a damped-Newton solve (line, point, transient).

    Parameters
    ----------
    status : str
        ``converged`` or the failure status.
    iterations : int
        Newton iterations (every linear solve).
    residual, tol : float
        Final max|F| and the tolerance (scaled, dimensionless).
    prefix : str
        Text before the message (e.g. ``"steady elastic: "``).
    detail : str
        Appended after the iteration count of a converged solve (grids, continuation);
        in a failure message, the last sentence ("Tried ...").
    cap : int, optional
        Iteration cap per attempt, quoted in a failure message.
    admissible : bool
        False when the returned iterate is not admissible (a starting guess from which
        no step was accepted: negative film somewhere); a failure message then says so
        instead of promising the last admissible iterate.
    """
    if status == "converged":
        return (f"{prefix}converged in {iterations} Newton iterations{detail}; residual "
                f"{residual:.2e} <= tol {tol:.1e}")
    limit = f" (max_iterations={cap} per attempt)" if cap is not None else ""
    tried = detail.strip().removeprefix("(").removesuffix(")").strip()
    resid = (f"residual {residual:.2e} > tol {tol:.1e}" if math.isfinite(residual) else
             "the residual of the last iterate is not finite")
    fields = ("Fields hold the last admissible iterate." if admissible else
              "Fields hold a starting guess from which no step was accepted; it is not "
              "admissible (its film is negative somewhere), so its numbers describe no film.")
    return (f"{prefix}{status}: no converged solution after {iterations} Newton "
            f"iterations{limit}; {resid}. {fields}" + (f" Tried: {tried}." if tried else ""))


class ForcingTerm:
    """Relative tolerance of the linear solves of an inexact Newton iteration:
    Eisenstat & Walker (1996), choice 2.

    eta_k = gamma (|F_k| / |F_k-1|)^alpha, safeguarded by gamma eta_k-1^alpha when that
    exceeds 0.1, capped at ``eta_max``; the first step gets ``eta_max``. Where Newton
    converges slowly (far from the solution, |F| falling by small factors) the linear
    solves stay loose; in the quadratic phase they tighten with |F|^2. A step whose
    residual did not fall (a repeated attempt at the same iterate) keeps the last eta.
    One instance per sequence of Newton steps (per problem).

    Parameters
    ----------
    eta_max : float
        Upper bound of eta (and its first value) [-].
    gamma, alpha : float
        Eisenstat-Walker parameters [-] (0.9 and 2 as recommended there).
    """

    def __init__(self, eta_max: float = 0.1, gamma: float = 0.9, alpha: float = 2.0) -> None:
        self.eta_max, self.gamma, self.alpha = float(eta_max), float(gamma), float(alpha)
        self._last: tuple[float, float] | None = None

    def __call__(self, norm: float) -> float:
        """eta for a Newton step at residual norm ``norm`` (2-norm, any scale)."""
        last = self._last
        if last is None:
            eta = self.eta_max
        elif norm >= last[0]:
            eta = last[1]
        else:
            eta = self.gamma * (norm / last[0]) ** self.alpha
            guard = self.gamma * last[1] ** self.alpha
            if guard > 0.1:
                eta = max(eta, guard)
        eta = min(eta, self.eta_max)
        self._last = (float(norm), eta)
        return eta


def gmres_right(matvec: Callable[[np.ndarray], np.ndarray],
                precond: Callable[[np.ndarray], np.ndarray], b: np.ndarray, *,
                rtol: float = 1e-9, max_iterations: int = 150,
                restart: int | None = None) -> tuple[np.ndarray, int, float]:
    """Right-preconditioned GMRES from x0 = M^-1 b.

    Arnoldi with classical Gram-Schmidt applied twice (numpy matrix products), the small
    least-squares problem solved each iteration. Stops when the true-residual estimate
    |b - A x| <= rtol |b| or after ``max_iterations`` in all. The preconditioner must be
    a fixed linear map: the update M^-1 (V y) is formed once per cycle from the Krylov
    basis V (one more preconditioner solve) instead of storing M^-1 V, which halves the
    memory (one vector of b's length per iteration). ``restart``: the basis is restarted
    from the current iterate after that many iterations (None: no restart), capping the
    memory at restart + 1 vectors.

    Returns
    -------
    x : ndarray; iterations : int; relative residual estimate : float (inf when the
    preconditioner or the product gave a non-finite vector: no usable step)
    """
    bnorm = float(np.linalg.norm(b))
    if bnorm == 0.0:
        return np.zeros_like(b), 0, 0.0
    x = precond(b)
    if not np.all(np.isfinite(x)):
        return np.zeros_like(b), 0, math.inf
    total = 0
    rel = 1.0
    while True:
        r0 = b - matvec(x)
        beta = float(np.linalg.norm(r0))
        rel = beta / bnorm
        if rel <= rtol or total >= max_iterations:
            return x, total, rel
        m = max_iterations - total
        if restart is not None:
            m = min(m, max(int(restart), 1))
        V = np.zeros((m + 1, b.size))
        H = np.zeros((m + 1, m))
        V[0] = r0 / beta
        e1 = np.zeros(m + 1)
        e1[0] = beta
        y = np.zeros(0)
        k = 0
        for k in range(m):
            w = matvec(precond(V[k]))
            for _ in range(2):  # CGS2
                h = V[:k + 1] @ w
                w = w - V[:k + 1].T @ h
                H[:k + 1, k] += h
            H[k + 1, k] = np.linalg.norm(w)
            if not np.all(np.isfinite(H[:k + 2, k])):
                # a preconditioner or product that overflowed (e.g. singular
                # single-precision factors): no usable step from this basis; report it as
                # a failed solve instead of handing NaN to LAPACK (which prints to stderr)
                return x, total + k + 1, math.inf
            if H[k + 1, k] > 0.0:
                V[k + 1] = w / H[k + 1, k]
            y, *_ = np.linalg.lstsq(H[:k + 2, :k + 1], e1[:k + 2], rcond=None)
            rel = float(np.linalg.norm(e1[:k + 2] - H[:k + 2, :k + 1] @ y)) / bnorm
            if rel <= rtol or H[k + 1, k] == 0.0:
                break
        x = x + precond(V[:k + 1].T @ y)
        total += k + 1
        del V
        if rel <= rtol or H[k + 1, k] == 0.0 or total >= max_iterations:
            return x, total, rel

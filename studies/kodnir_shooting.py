"""Shooting solver for the Kodnir problem, the comparison baseline of ``shooting_vs_fe.py``.

This is NOT part of the package: it reproduces the method of Yachikov & Vostrikov (2015),
who integrate the once-integrated Reynolds equation of the locally compliant line contact
(Kodnir's form, docs/kodnir.md, docs/theory.md)

    dk/dz = (1 - H)/H^3 exp(B alpha k),   H = 1 - z_a^2 + z^2 + C k,

from the outlet z_a (k = 0, H = 1) towards the inlet z_b = 20 with a Runge-Kutta method
and adjust the single unknown z_a until k(z_b) = 0. Here the initial-value problem is
integrated by ``scipy.integrate.solve_ivp`` (the explicit RK45, like the authors'
Runge-Kutta, or the stiff/non-stiff switching LSODA), and z_a is found by a scan for a
sign change of k(z_b) followed by Brent's method (``scipy.optimize.brentq``). The work
of every integration is capped by a count of right-hand-side evaluations (no wall-time
limits), so a failure is reproducible.

All quantities are dimensionless (z = x/B1 against the motion, k = p/B, H = h/h*).
"""
from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp, trapezoid
from scipy.optimize import brentq

Z_B = 20.0
#: z_a candidates of the bracketing scan (outlet positions, dimensionless)
SCAN = -np.geomspace(0.05, 12.0, 18)
#: terminal events: the exponent B alpha k beyond which exp overflows the sense of the
#: problem, and the film thickness below which the gap is taken as closed
BA_K_CAP = 700.0
K_CAP_ISOVISCOUS = 1.0e6
H_FLOOR = 1.0e-6


class _Budget(Exception):
    """Raised inside the right-hand side when the evaluation budget is spent."""


@dataclass
class Trajectory:
    """One integration from a trial outlet z_a.

    status: "ok" (reached z_b; ``k_end`` = k(z_b)), "blow_up" (B alpha k or k exceeded
    its cap: far too much pressure), "film_closed" (H fell to ``H_FLOOR``), "budget"
    (more than the allowed right-hand-side evaluations: too stiff for the method) or
    "solver" (solve_ivp reported a failure).
    """

    status: str
    z_a: float
    k_end: float = math.nan
    n_rhs: int = 0
    z: np.ndarray | None = None
    k: np.ndarray | None = None
    H: np.ndarray | None = None


def integrate(z_a: float, C: float, b_alpha: float, method: str = "RK45",
              rtol: float = 1e-9, atol: float = 1e-12, max_rhs: int = 40_000,
              dense: bool = False) -> Trajectory:
    """Integrate dk/dz from the trial outlet z_a (k = 0, H = 1) to z_b = 20."""
    h_off = 1.0 - z_a * z_a
    count = [0]

    def rhs(z, y):
        count[0] += 1
        if count[0] > max_rhs:
            raise _Budget
        H = h_off + z * z + C * y[0]
        return [(1.0 - H) / H**3 * math.exp(min(b_alpha * y[0], 700.0))]

    def jac(z, y):
        H = h_off + z * z + C * y[0]
        e = math.exp(min(b_alpha * y[0], 700.0))
        return [[e * (-C / H**3 - 3.0 * (1.0 - H) * C / H**4 + b_alpha * (1.0 - H) / H**3)]]

    def film(z, y):
        return h_off + z * z + C * y[0] - H_FLOOR
    film.terminal = True

    def pressure(z, y):
        return b_alpha * y[0] - BA_K_CAP if b_alpha > 0 else y[0] - K_CAP_ISOVISCOUS
    pressure.terminal = True

    kw = {} if method in ("RK45", "RK23", "DOP853") else {"jac": jac}
    try:
        # a failed integration is reported through its status: keep scipy's and numpy's
        # warnings (LSODA convergence failures, overflow) off the terminal
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sol = solve_ivp(rhs, (z_a, Z_B), [0.0], method=method, rtol=rtol, atol=atol,
                            events=[film, pressure], dense_output=dense, **kw)
    except (_Budget, OverflowError, ZeroDivisionError):
        return Trajectory("budget" if count[0] > max_rhs else "solver", z_a, n_rhs=count[0])
    if sol.status == 1:
        st = "film_closed" if len(sol.t_events[0]) else "blow_up"
        return Trajectory(st, z_a, n_rhs=count[0])
    if sol.status != 0 or not np.isfinite(sol.y[0, -1]):
        return Trajectory("solver", z_a, n_rhs=count[0])
    out = Trajectory("ok", z_a, k_end=float(sol.y[0, -1]), n_rhs=count[0])
    if dense:
        zz = np.unique(np.concatenate([np.linspace(z_a, 5.0, 20001),
                                       np.linspace(5.0, Z_B, 1501)]))
        kk = sol.sol(zz)[0]
        out.z, out.k, out.H = zz, kk, h_off + zz * zz + C * kk
    return out


@dataclass
class ShootingResult:
    """Outcome of :func:`shoot` (dimensionless; ``seconds`` is the wall time)."""

    success: bool
    status: str
    message: str
    C: float
    b_alpha: float
    method: str
    z_a: float = math.nan
    k_max: float = math.nan
    h_min: float = math.nan
    k_end: float = math.nan
    friction_integral: float = math.nan
    integrations: int = 0
    n_rhs: int = 0
    seconds: float = 0.0


def shoot(C: float, b_alpha: float, method: str = "RK45", *, max_rhs: int = 40_000,
          max_total_rhs: int = 600_000, rtol: float = 1e-9, atol: float = 1e-12,
          tol_k: float = 1e-6) -> ShootingResult:
    """Find z_a with k(z_b) = 0 by a sign-change scan over ``SCAN`` and Brent's method.

    Success requires: a bracket (a trial outlet giving k(z_b) < 0 next to one giving
    k(z_b) > 0 or a pressure blow-up), Brent converged, the final integration reached
    z_b with |k(z_b)| <= tol_k max(1, k_max), and k >= -tol_k max(1, k_max) all along
    (a physical pressure). Every integration is capped at ``max_rhs`` right-hand-side
    evaluations and the whole case at ``max_total_rhs``.
    """
    t0 = time.perf_counter()
    res = ShootingResult(False, "no_bracket", "", float(C), float(b_alpha), method)
    used = [0, 0]

    def run(z_a: float, dense: bool = False) -> Trajectory:
        if used[1] >= max_total_rhs:
            raise _Budget
        tr = integrate(z_a, C, b_alpha, method, rtol, atol, max_rhs, dense)
        used[0] += 1
        used[1] += tr.n_rhs
        return tr

    def signed(tr: Trajectory) -> float | None:
        if tr.status == "ok":
            return tr.k_end
        if tr.status == "blow_up":
            return 1.0e3          # far too much pressure: the positive side
        return None               # unknown side: integration failed

    def finish(status: str, message: str) -> ShootingResult:
        res.status, res.message = status, message
        res.integrations, res.n_rhs = used
        res.seconds = time.perf_counter() - t0
        return res

    try:
        prev, bracket, failures = None, None, []
        for z_a in SCAN:
            tr = run(float(z_a))
            s = signed(tr)
            if s is None:
                failures.append(tr.status)
                prev = None
                continue
            if prev is not None and prev[1] < 0.0 <= s:
                bracket = (prev[0], float(z_a))
                break
            prev = (float(z_a), s)
        if bracket is None:
            why = (f"integration failures at {len(failures)} of the trial outlets "
                   f"({', '.join(sorted(set(failures)))})" if failures else "k(z_b) never "
                   "changes sign")
            return finish("no_bracket", f"no sign change of k(z_b) over z_a in "
                          f"[{SCAN[-1]:.3g}, {SCAN[0]:.3g}]: {why}")

        def f(z_a: float) -> float:
            s = signed(run(z_a))
            if s is None:
                raise _Budget
            return s

        z_a = brentq(f, bracket[1], bracket[0], xtol=1e-13, rtol=1e-12, maxiter=200)
        tr = run(z_a, dense=True)
    except _Budget:
        return finish("budget", f"work budget exhausted ({used[1]} right-hand-side "
                      f"evaluations in {used[0]} integrations; per integration "
                      f"{max_rhs}): too stiff for {method}")
    except (RuntimeError, ValueError) as exc:
        return finish("root_finder", f"Brent's method failed: {exc}")
    if tr.status != "ok":
        return finish("final_integration", f"the integration at the root ended with "
                      f"{tr.status}")
    k_max = float(np.max(tr.k))
    scale = max(1.0, k_max)
    res.z_a, res.k_end = float(z_a), tr.k_end
    res.k_max, res.h_min = k_max, float(np.min(tr.H))
    # I = int (1 - H) dk/dz dz with dk/dz from the equation itself (Yachikov & Vostrikov 2015, eq 8)
    with np.errstate(over="ignore"):
        dk = (1.0 - tr.H) / tr.H**3 * np.exp(np.minimum(b_alpha * tr.k, 700.0))
    res.friction_integral = float(trapezoid((1.0 - tr.H) * dk, tr.z))
    if abs(tr.k_end) > tol_k * scale:
        return finish("not_converged", f"|k(z_b)| = {abs(tr.k_end):.3g} at the root: the "
                      "root is a discontinuity of the shooting function")
    if np.min(tr.k) < -tol_k * scale:
        return finish("unphysical", f"negative pressure k = {np.min(tr.k):.3g} on the "
                      "trajectory")
    res.success = True
    return finish("converged", f"z_a = {z_a:.10f} after {used[0]} integrations")

"""Thermal coupling of a line EHL contact: contact temperature <-> viscosity fixed point.

Loop (``model.thermal = "patch"``, see ``docs/coupling.md``)::

    T = t_oil                                      contact temperature [deg C]
    repeat:
        eta0 = eta_ref (t_ref / T)^n                Prokofiev law, T in deg C
        alpha = alpha(T)                            optional ln-linear table
        isothermal EHL solve (line.LineModel, shared driver) with eta0, alpha
        q(x) = Couette tau u_s + Poiseuille u_m p' (h - h*)  [W/m^2]  (LineModel.heat_flux)
        q_i = f_i q, f_i from Blok's partition (thermal.heat_partition)
        flash temperature of each body in the ROLLING plane (moving source, body i moving
            at its surface speed u_i under the fixed source q_i)
        dT = pressure-weighted mean (or max) surface temperature rise, averaged over bodies
        G(T) = t_oil + dT;  stop when |G(T) - T| < tol;  T <- T + omega (G(T) - T)
        (from the second iteration a safeguarded secant step on G(T) - T replaces it)

Why the rolling plane and not Korovchinsky's: the Korovchinsky strip (thermal.strip_source)
is the steady conduction field across the track, where the source is stationary relative
to the body; in a rolling bearing every surface point crosses the contact in b/u ~ 1e-4 s,
the Peclet number u b/(2 kappa) is tens to hundreds (docs/coupling.md), and the surface
temperature is set by the moving source (Jaeger/Blok), whose rise does not depend on a
far-field datum. The
Korovchinsky patch gives only temperature differences in 2D (its constant C needs a datum).

Flash temperature (``thermal.source_model``): ``"jaeger"`` the high-Pe closed form
T(x) = (pi lambda rho c V)^(-1/2) int_{-inf}^{x} q(s) (x - s)^(-1/2) ds, integrated exactly
for the piecewise-constant element flux; ``"fe"`` the FE moving source
(:func:`bearing_fem.physics.thermal.moving_source`) on the band covering the heated zone.
"""
from __future__ import annotations

import math
import time
from dataclasses import replace

import numpy as np

from ..errors import SceneError
from ..numerics.newton import BUDGET_STATUSES
from ..physics import thermal
from ..physics.rheology import prokofiev
from ..physics.traction import shear_parameters
from ..result import Result
from ..scene import Scene
from .driver import finish, solve_newton_model
from .line import LineModel

__all__ = ["solve_thermal", "contact_viscosity", "contact_piezo", "piezo_table_warning",
           "jaeger_surface_temperature",
           "flash_temperature", "heated_half_length"]

#: Share of the film's heat inside the band whose half-length enters the Peclet number
#: (the rest, beyond the band's ends, is split equally between them).
HEATED_SHARE = 0.98
#: Below this Peclet number the high-Peclet (Jaeger) flash temperature is not trusted.
PECLET_MIN_JAEGER = 5.0
#: Relative difference of the two surfaces' contact temperature rises above which the
#: result says that Blok's partition (equal flash temperatures) does not hold.
PARTITION_MISMATCH = 0.1


def contact_viscosity(scene: Scene, temperature: float) -> float:
    """eta0 [Pa s] at ``temperature`` [deg C] by the scene's temperature law."""
    th = scene.thermal
    eta_ref = th.reference_viscosity if th.reference_viscosity is not None \
        else scene.lubricant.viscosity
    return float(prokofiev(temperature, eta_ref, th.reference_temperature, th.exponent))


def contact_piezo(scene: Scene, temperature: float) -> float:
    """alpha [1/Pa] at ``temperature`` [deg C]: ln(alpha) linear in t through the
    ``thermal.piezo_temperatures`` / ``piezo_values`` table (linear extrapolation of
    ln alpha outside it); ``lubricant.piezo`` without a table."""
    th = scene.thermal
    if th.piezo_temperatures is None:
        return float(scene.lubricant.piezo)
    return _table_piezo(th.piezo_temperatures, th.piezo_values, temperature)


def _table_piezo(temperatures, values, temperature: float) -> float:
    """alpha [1/Pa] at ``temperature`` [deg C] from a piezo_temperatures [deg C] /
    piezo_values [1/Pa] table: ln alpha linear in t, extrapolated linearly outside it (a
    single entry: its value)."""
    ts = np.asarray(temperatures, dtype=float)
    la = np.log(np.asarray(values, dtype=float))
    if ts.size == 1:
        return float(np.exp(la[0]))
    t = float(temperature)
    i = int(np.clip(np.searchsorted(ts, t) - 1, 0, ts.size - 2))
    s = (la[i + 1] - la[i]) / (ts[i + 1] - ts[i])
    return float(np.exp(la[i] + s * (t - ts[i])))


#: A temperature more than this [K] outside the range of a ``piezo_temperatures`` table
#: is named in the result's warnings: alpha is extrapolated there (ln alpha linear), and
#: a short table can put it far off (a table over [40, 41] deg C gave 2e-14 1/Pa at
#: 60 deg C).
PIEZO_TABLE_EXTRAPOLATION_K = 10.0


def piezo_table_warning(thermal, temperature: float, what: str = "the contact temperature"
                        ) -> str | None:
    """The warning sentence when ``temperature`` [deg C] lies more than
    :data:`PIEZO_TABLE_EXTRAPOLATION_K` outside a ``[thermal]`` (or bearing
    ``[lubricant]``) section's ``piezo_temperatures`` table, else None.

    Parameters
    ----------
    thermal : Thermal
        The section with ``piezo_temperatures`` [deg C] and ``piezo_values`` [1/Pa].
    temperature : float
        Where alpha is evaluated [deg C].
    what : str
        What that temperature is, for the sentence.
    """
    ts = getattr(thermal, "piezo_temperatures", None)
    if ts is None or len(ts) == 0:
        return None
    lo, hi = float(min(ts)), float(max(ts))
    t = float(temperature)
    if lo - PIEZO_TABLE_EXTRAPOLATION_K <= t <= hi + PIEZO_TABLE_EXTRAPOLATION_K:
        return None
    alpha = _table_piezo(ts, thermal.piezo_values, t)
    how = ("the table's single value is used" if len(ts) == 1
           else "ln alpha is extrapolated linearly")
    return (f"{what} {t:.4g} deg C lies outside the piezo_temperatures table "
            f"[{lo:g}, {hi:g}] deg C by more than {PIEZO_TABLE_EXTRAPOLATION_K:g} K: {how}, "
            f"giving alpha = {alpha:.3g} 1/Pa; extend the table to that temperature")


def jaeger_surface_temperature(x_nodes: np.ndarray, q_elements: np.ndarray,
                               x_eval: np.ndarray, conductivity: float, density: float,
                               heat_capacity: float, speed: float) -> np.ndarray:
    """High-Peclet surface temperature rise [K] of a body moving at ``speed`` along +x.

    T(x) = (pi lambda rho c V)^(-1/2) int_{-inf}^{x} q(s) (x - s)^(-1/2) ds, exact for a
    flux q_j [W/m^2] constant on each element [x_j, x_{j+1}] of ``x_nodes`` [m]:
    int = sum_j q_j 2 (sqrt(max(x - x_j, 0)) - sqrt(max(x - x_{j+1}, 0))).
    lambda [W/(m K)], rho [kg/m^3], c [J/(kg K)], V [m/s] > 0.
    """
    for name, v, unit in (("conductivity", conductivity, "W/(m K)"),
                          ("density", density, "kg/m^3"),
                          ("heat_capacity", heat_capacity, "J/(kg K)"),
                          ("speed", speed, "m/s")):
        if not (np.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be > 0 {unit} for the moving-source (Jaeger) "
                             f"temperature, got {v!r}")
    xn = np.asarray(x_nodes, dtype=float)
    q = np.asarray(q_elements, dtype=float)
    xe = np.asarray(x_eval, dtype=float)
    d0 = np.sqrt(np.maximum(xe[:, None] - xn[None, :-1], 0.0))
    d1 = np.sqrt(np.maximum(xe[:, None] - xn[None, 1:], 0.0))
    integral = 2.0 * ((d0 - d1) @ q)
    return integral / math.sqrt(math.pi * conductivity * density * heat_capacity * speed)


def flash_temperature(x_nodes: np.ndarray, q_elements: np.ndarray, x_eval: np.ndarray,
                      conductivity: float, density: float, heat_capacity: float,
                      speed: float, *, source_model: str = "jaeger") -> np.ndarray:
    """Surface temperature rise [K] at ``x_eval`` [m] of a body moving at ``speed`` [m/s]
    under the element flux ``q_elements`` [W/m^2] (``"jaeger"`` closed form or ``"fe"``).

    ``speed`` is the body's surface velocity along x: a body moving along -x (negative
    speed, e.g. a surface running against the entrainment) carries its heat towards -x,
    so its field is that of the mirrored problem (x -> -x) at the speed's magnitude.
    ``x_nodes`` [m] ascend; ``q_elements`` has one value per element between them.
    """
    if speed < 0.0:
        xn = np.asarray(x_nodes, dtype=float)
        return flash_temperature(-xn[::-1], np.asarray(q_elements, dtype=float)[::-1],
                                 -np.asarray(x_eval, dtype=float), conductivity, density,
                                 heat_capacity, -speed, source_model=source_model)
    if source_model == "jaeger":
        return jaeger_surface_temperature(x_nodes, q_elements, x_eval, conductivity, density,
                                          heat_capacity, speed)
    if source_model != "fe":
        raise ValueError(f"source_model must be 'jaeger' or 'fe', got {source_model!r}")
    xn = np.asarray(x_nodes, dtype=float)
    q = np.asarray(q_elements, dtype=float)
    nz = np.nonzero(q != 0.0)[0]
    if nz.size == 0:
        return np.zeros_like(np.asarray(x_eval, dtype=float))
    lo, hi = xn[nz[0]], xn[nz[-1] + 1]
    centre, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    xm = 0.5 * (xn[1:] + xn[:-1])
    samples = np.column_stack([xm - centre, q])
    qmax = float(np.max(np.abs(q)))
    ms = thermal.moving_source(half, qmax, conductivity, density, heat_capacity, speed,
                               flux=samples, n_source=max(160, min(nz.size, 400)))
    return np.interp(np.asarray(x_eval, dtype=float) - centre, ms.x, ms.surface_temperature)


def heated_half_length(x_nodes: np.ndarray, q_elements: np.ndarray,
                       share: float = HEATED_SHARE) -> float:
    """Half-length [m] of the band that holds the central ``share`` of the heat.

    The ends are where the cumulative heat int |q| dx reaches (1 - share)/2 and
    (1 + share)/2 of its total, so the thin tails of the Couette and Poiseuille heat in
    the inlet and outlet (which reach the ends of any mesh domain) do not set the
    length: the result does not depend on how far the domain extends.

    Parameters
    ----------
    x_nodes : ndarray
        Ascending nodes [m].
    q_elements : ndarray
        Heat flux [W/m^2] on each element between them.
    share : float
        Share of the heat inside the band [-], in (0, 1].

    Returns
    -------
    float
        Half-length [m]; half the domain when the flux is zero everywhere.
    """
    xn = np.asarray(x_nodes, dtype=float)
    w = np.abs(np.asarray(q_elements, dtype=float)) * np.diff(xn)
    total = float(w.sum())
    if not total > 0.0:
        return 0.5 * float(xn[-1] - xn[0])
    cum = np.concatenate([[0.0], np.cumsum(w)]) / total
    lo, hi = np.interp([0.5 * (1.0 - share), 0.5 * (1.0 + share)], cum, xn)
    return 0.5 * float(hi - lo)


def _isothermal_state(temperature: float, t_oil: float, eta0: float, alpha: float,
                      iteration: int) -> dict[str, float | int]:
    """Thermal numbers of a loop that stopped after an isothermal solve, before its flash
    temperatures: the contact temperature [deg C] that solve used, its rise over the oil
    [K], the viscosity [Pa s] and pressure-viscosity coefficient [1/Pa] there, and the
    iteration."""
    return {"contact_temperature": float(temperature),
            "contact_temperature_rise": float(temperature - t_oil),
            "contact_viscosity": eta0, "contact_piezo": alpha,
            "thermal_iterations": int(iteration)}


def solve_thermal(scene: Scene) -> Result:
    """Thermally coupled steady line-contact solve (see module docstring).

    Returns
    -------
    Result
        status ``converged`` (EHL and temperature fixed point converged), ``max_iterations``
        (temperature loop exhausted: fields of the last iterate) or the EHL solver's status
        when an isothermal solve fails. Quantities (per metre of length) add
        ``contact_temperature`` [deg C], ``contact_temperature_rise`` [K],
        ``contact_temperature_rise_max`` [K], ``heat_flux_body1``/``body2`` [W/m],
        ``heat_fraction_body1`` [-], ``contact_viscosity`` [Pa s], ``contact_piezo`` [1/Pa],
        ``peclet_min`` [-], ``thermal_iterations``, ``thermal_residual`` |G(T) - T| [K];
        friction and heat power as every line solve (:mod:`bearing_fem.post`), at the
        final contact temperature. ``history`` is the Newton history of the last
        isothermal solve; ``error_estimate`` and ``warnings`` are its own.
    """
    t0 = time.perf_counter()
    if scene.thermal is None:
        raise SceneError("model.thermal = 'patch' needs a [thermal] section")
    if scene.contact.kind != "line":
        raise SceneError(f"model.thermal = 'patch' is implemented for line contacts only, got "
                         f"contact.kind = {scene.contact.kind!r}")
    th = scene.thermal
    kin = scene.kinematics
    velocities = (kin.u1, kin.u2)     # signed: a surface may run along -x
    speeds = (abs(kin.u1), abs(kin.u2))
    if min(speeds) <= 0.0:
        raise SceneError(f"model.thermal = 'patch' (moving-source flash temperature) needs both "
                         f"surface speeds non-zero (m/s), got u1={kin.u1!r}, u2={kin.u2!r}")
    lam = (th.conductivity, th.conductivity2 or th.conductivity)
    rho = (th.density, th.density2 or th.density)
    cap = (th.heat_capacity, th.heat_capacity2 or th.heat_capacity)
    part = thermal.heat_partition(lam, rho, cap, speeds, rule="blok")
    fractions = (part.fraction_1, part.fraction_2)
    shear = shear_parameters(scene.traction)
    model_name = shear["model"]

    t_oil = th.oil_temperature
    T = t_oil
    iso_model = replace(scene.model, thermal="none")
    history: list[float] = []
    newton_its = 0
    res = None
    status, converged = "max_iterations", False
    info: dict[str, float | int] = {}
    notes: list[str] = []
    temps: list[np.ndarray] = []
    q_e = np.zeros(0)
    prev: tuple[float, float] | None = None     # (T, G(T) - T) of the previous iteration
    body_rises = [0.0, 0.0]
    sol = scene.solver
    last_step = 0.0  # duration of the previous thermal iteration [s]
    for it in range(1, th.max_iterations + 1):
        left_its = sol.iteration_budget - newton_its
        elapsed = time.perf_counter() - t0
        # an iteration is not started when the previous one, taken again, would end past
        # the time limit (the limit is checked between iterations, and one iteration with
        # source_model = "fe" costs a patch solve per body)
        if left_its <= 0 or (sol.time_limit is not None
                             and elapsed + last_step >= sol.time_limit):
            status = "budget_exhausted" if left_its <= 0 else "time_limit"
            ahead = (f"; the previous iteration took {last_step:.3g} s"
                     if status == "time_limit" and elapsed < sol.time_limit else "")
            msg = (f"{status}: the thermal loop stopped before iteration {it} after "
                   f"{newton_its} Newton iterations (budget {sol.iteration_budget}) and "
                   f"{elapsed:.3g} s" + (f" (time limit {sol.time_limit:.3g} s{ahead})"
                                         if sol.time_limit is not None else ""))
            break
        step_start = time.perf_counter()
        eta0 = contact_viscosity(scene, T)
        alpha = contact_piezo(scene, T)
        inner = replace(sol, iteration_budget=left_its, time_limit=None if sol.time_limit
                        is None else sol.time_limit - elapsed)
        try:
            lub = replace(scene.lubricant, viscosity=eta0, piezo=alpha)
            iso = replace(scene, model=iso_model, lubricant=lub, thermal=None, solver=inner)
        except SceneError as exc:
            # the oil's laws leave the range of the viscosity law at this temperature:
            # say so in the user's terms (not as the value of lubricant.viscosity)
            src = (f"thermal.reference_viscosity = {th.reference_viscosity:.4g} Pa s"
                   if th.reference_viscosity is not None else
                   f"lubricant.viscosity = {scene.lubricant.viscosity:.4g} Pa s")
            where = (f"at {T:.4g} deg C the oil has eta0 = {eta0:.4g} Pa s and alpha = "
                     f"{alpha:.4g} 1/Pa ({src} at {th.reference_temperature:.4g} deg C), "
                     f"refused as the isothermal scene's: {exc}")
            if it == 1:   # already at the oil temperature: the input is out of range
                raise SceneError(f"thermal.oil_temperature = {t_oil:.4g} deg C: {where}") \
                    from None
            status = "diverged"
            msg = (f"diverged: thermal iteration {it}: {where}; the last isothermal solve "
                   "is kept")
            break
        model = LineModel(iso)
        res = solve_newton_model(model, iso, time.perf_counter())
        newton_its += res.newton_iterations
        if not res.success:
            status = res.status
            msg = (f"{res.status}: the isothermal EHL solve failed at thermal iteration {it} "
                   f"(contact temperature {T:.4g} deg C, eta0 = {eta0:.4g} Pa s, alpha = "
                   f"{alpha:.4g} 1/Pa): {res.message}")
            # the returned fields are this solve's: describe it, not the previous
            # iteration (whose flash temperatures and heat fluxes belong to other fields)
            info, temps = _isothermal_state(T, t_oil, eta0, alpha, it), []
            break
        elapsed = time.perf_counter() - t0
        if sol.time_limit is not None and elapsed >= sol.time_limit:
            # the flash temperatures (with source_model = "fe" a patch solve per body,
            # larger than the isothermal solve) would overrun the limit by a whole step:
            # stop with this isothermal solve, described as such
            status = "time_limit"
            msg = (f"time_limit: the thermal loop stopped after the isothermal solve of "
                   f"iteration {it} (contact temperature {T:.4g} deg C), before its flash "
                   f"temperatures, after {newton_its} Newton iterations (budget "
                   f"{sol.iteration_budget}) and {elapsed:.3g} s (time limit "
                   f"{sol.time_limit:.3g} s)")
            info, temps = _isothermal_state(T, t_oil, eta0, alpha, it), []
            break
        q_e, _ = model.heat_flux(res.pressure, res.h0)
        xn = res.x
        temps = [flash_temperature(xn, fractions[i] * q_e, xn, lam[i], rho[i], cap[i],
                                   velocities[i], source_model=th.source_model)
                 for i in range(2)]
        p_pos = np.maximum(res.pressure, 0.0)
        wts = np.gradient(xn) * p_pos
        body_means = [float(wts @ T_i / wts.sum()) for T_i in temps]
        body_maxima = [float(np.max(T_i)) for T_i in temps]
        mean_rise = float(np.mean(body_means))
        max_rise = float(np.mean(body_maxima))
        rise = mean_rise if th.contact_temperature == "mean" else max_rise
        body_rises = body_means if th.contact_temperature == "mean" else body_maxima
        G = t_oil + rise
        delta = G - T
        history.append(abs(delta))
        band = heated_half_length(xn, q_e)
        peclet = min(speeds[i] * band * rho[i] * cap[i] / (2 * lam[i]) for i in range(2))
        total = float(np.diff(xn) @ q_e)
        info = {
            "contact_temperature": float(T),
            "contact_temperature_rise": float(T - t_oil),
            "contact_temperature_rise_computed": rise,
            "contact_temperature_rise_mean": mean_rise,
            "contact_temperature_rise_max": max_rise,
            "heat_flux_body1": float(fractions[0] * total),
            "heat_flux_body2": float(fractions[1] * total),
            "heat_fraction_body1": fractions[0],
            "contact_viscosity": eta0,
            "contact_piezo": alpha,
            "peclet_min": float(peclet),
            "thermal_iterations": int(it),
            "thermal_residual": float(abs(delta)),
        }
        heat = res.quantities["heat_power"]
        if rise > th.max_temperature_rise:
            status = "diverged"
            msg = (f"diverged: computed contact temperature rise {rise:.4g} K exceeds "
                   f"thermal.max_temperature_rise = {th.max_temperature_rise:.4g} K at thermal "
                   f"iteration {it} (heat power {heat:.4g} W/m, of which Couette "
                   f"{res.quantities['heat_power_couette']:.4g} W/m, traction model "
                   f"{model_name!r}); no fixed point below that limit (raise "
                   "thermal.max_temperature_rise if such a rise is expected)"
                   + (" - Newtonian Barus traction is unphysical under sliding, use "
                      "traction.model = 'eyring-limiting'" if model_name == "newtonian"
                      else ""))
            break
        if abs(delta) < th.tolerance:
            status, converged = "converged", True
            break
        step = th.relaxation * delta
        if prev is not None and delta != prev[1]:
            # secant on the residual d(T) = G(T) - T, safeguarded: used only when it points
            # the same way as the relaxed step and is at most 3x longer
            secant = -delta * (T - prev[0]) / (delta - prev[1])
            if secant * delta > 0 and abs(secant) <= 3.0 * abs(delta):
                step = secant
        prev = (T, delta)
        T = T + step
        if T <= 0.0:  # keep the Prokofiev law defined (t > 0 deg C)
            T = 0.5 * t_oil
        last_step = time.perf_counter() - step_start
    if res is None:
        # the budget was spent before the first isothermal solve: report the oil state
        lub = replace(scene.lubricant, viscosity=contact_viscosity(scene, T),
                      piezo=contact_piezo(scene, T))
        iso = replace(scene, model=iso_model, lubricant=lub, thermal=None)
        model = LineModel(iso)
        problem = model.problem(model.setup)
        z0 = model.initial_guess(model.setup, problem)
        res = finish(iso, model.solution(problem, z0, post=False), status=status,
                     message=msg, t0=t0)
    if res.success and status not in ("diverged",) + BUDGET_STATUSES:
        if converged:
            msg = (f"converged: contact temperature {T:.4g} deg C (rise {T - t_oil:.4g} K over "
                   f"oil {t_oil:.4g} deg C) after {len(history)} thermal iteration(s), "
                   f"|G(T) - T| = {history[-1]:.2e} K < tol {th.tolerance:.2e} K; heat power "
                   f"{res.quantities['heat_power']:.4g} W/m; {res.message}")
        else:
            msg = (f"max_iterations: contact temperature not converged after {len(history)} "
                   f"thermal iterations (|G(T) - T| = {history[-1]:.3g} K > tol "
                   f"{th.tolerance:.2e} K, relaxation {th.relaxation}); fields of the last "
                   "iterate")
        if info.get("peclet_min", np.inf) < PECLET_MIN_JAEGER and th.source_model == "jaeger":
            notes.append(f"Peclet number {info['peclet_min']:.3g} < {PECLET_MIN_JAEGER:g}: "
                         "the high-Peclet Jaeger formula is inaccurate here (it overestimates "
                         "the maximum flash temperature and misses the heat conducted "
                         "upstream of the source); use thermal.source_model = 'fe'")
        hi, lo = max(body_rises), min(body_rises)
        if hi - lo > PARTITION_MISMATCH * hi and hi - lo > th.tolerance:
            notes.append(f"the surfaces' contact temperature rises differ ({body_rises[0]:.4g} K "
                         f"body 1, {body_rises[1]:.4g} K body 2): Blok's heat partition "
                         "assumes equal flash temperatures (both Peclet numbers >~ 5, minimum "
                         f"here {info['peclet_min']:.3g}); the contact temperature is their "
                         "mean and is uncertain by about half their difference")
    table_note = piezo_table_warning(th, T)
    if table_note is not None:
        notes.append(table_note)
    quantities = {k: v for k, v in res.quantities.items()}
    quantities.update({"contact_temperature": float(T),
                       "contact_temperature_rise": float(T - t_oil),
                       "contact_viscosity": contact_viscosity(scene, T),
                       "contact_piezo": contact_piezo(scene, T),
                       "thermal_iterations": int(len(history) or 1)})
    quantities.update({k: (v if k == "thermal_iterations" else float(v))
                       for k, v in info.items() if np.isfinite(v)})
    extra = dict(res.extra_fields)
    if info and res.success and temps:
        extra["surface_temperature_rise_body1_K"] = temps[0]
        extra["surface_temperature_rise_body2_K"] = temps[1]
        extra["heat_flux_W_m2"] = np.interp(res.x, 0.5 * (res.x[1:] + res.x[:-1]), q_e)
    success = converged and res.success
    return Result(success=success, status=status, message=msg, scene=scene,
                  x=res.x, pressure=res.pressure, film=res.film, h0=res.h0,
                  quantities=quantities, history=list(res.history), newton_iterations=newton_its,
                  linear_solves=res.linear_solves, wall_time_s=time.perf_counter() - t0,
                  continuation=res.continuation, extra_fields=extra,
                  warnings=list(res.warnings) + notes,
                  error_estimate=res.error_estimate if success else None,
                  traction_model=res.traction_model, residual=res.residual)

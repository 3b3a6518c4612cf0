"""Bearing totals from the contact results: friction torque, heat power, films, pressures.

Friction torque from forces and moment arms (derivation in docs/bearing.md, "Friction
torque"). In each contact the contact solver reports the Poiseuille (rolling) shear force
F_P = int (h/2) dp/dx dA on each surface and the Couette force F_C (0 in pure rolling).
The x-force of the film on body k is its shear force plus the pressure acting on its
curved surface, -(1/R_k) int p x dA = 2 (R_x/R_k) F_P (the elastic part vanishes for
half-space bodies: int p v' dx = 0); the moment about body k's own axis is R_k times
its shear force. Each element then needs a traction that balances its spin and, with no
cage force, its circumferential force; the ring torques that follow are

    M_j = r_i [F_P,i (2 - R_x,i/r) + F_P,o R_x,o/r],   r = D_w/2,

i.e. M_j = (d_m/2)(1 - gamma^2)(F_P,i + F_P,o) at equal contact angles, and the same
torque acts on the outer ring. The bearing torque is sum_j M_j. The energy balance
M omega_i = sum Q then holds exactly when every contact's heat power satisfies the
steady Reynolds identity Q = 2 u_m F_P (+ u_s F_C): it is a check of the contact
solutions, not a definition.

Only numpy here.
"""
from __future__ import annotations

import math
from typing import Any, Mapping, Sequence

import numpy as np

from .. import formulas
from .contacts import ContactSpec
from .description import Bearing

__all__ = ["contact_summary", "bearing_totals", "element_torque", "slice_label",
           "LAST_ITERATE_NOTE"]

#: Keys of a per-contact summary that are totals over the contact (N, W).
_EXTENSIVE = ("load", "rolling_resistance", "sliding_friction", "friction_force", "heat_power")
#: Result quantities of a contact summary: None when a scene of the contact failed (its
#: last iterate is no result; the contact's Result keeps it).
_RESULT_KEYS = ("load_solved", "h_min", "h_central", "p_max", "rolling_resistance",
                "sliding_friction", "friction_force", "heat_power", "film_parameter",
                "heat_power_poiseuille_direct", "heat_power_stabilisation", "error_estimate")
#: Prefix of the warnings of an unsuccessful scene: they are about its last iterate.
LAST_ITERATE_NOTE = "unsuccessful solve, about its last iterate (no result)"


def slice_label(spec: ContactSpec, i: int, n_slices: int) -> str:
    """``"slice k of n"`` for the ``i``-th scene of a profiled roller's contact (k counted
    from one roller end), ``""`` for a contact of one scene."""
    if not spec.slice_numbers:
        return ""
    return f"slice {spec.slice_numbers[i]} of {n_slices}"


def _val(summary: dict[str, Any], key: str) -> float | None:
    v = summary.get(key)
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def contact_summary(bearing: Bearing, spec: ContactSpec, results: dict[str, Any]) -> dict[str, Any]:
    """One contact's numbers as totals over the contact (N, W, m, Pa).

    Line contacts: the per-metre results of each scene times its length (slice width),
    summed; films are minima and pressures maxima over the slices. Point contacts: the
    scene's summary. Excluded contacts: status ``excluded`` with the reason. Unsuccessful
    contacts (a scene not successful): the status and message of the failed scene, and
    every result quantity None (``load_solved``, films, ``p_max``, the forces, heat
    powers, ``film_parameter`` and ``error_estimate``; the last iterate stays in the
    contact's :class:`~bearing_fem.result.Result`); the failed scenes' warnings are
    marked as about the last iterate (:data:`LAST_ITERATE_NOTE`). The warnings of a
    profiled roller's slices name the slice ("slice 2 of 5: ...").

    Returns
    -------
    dict
        ``status``, ``success``, ``message``, ``load`` [N] (applied), ``load_solved`` [N]
        (integral of the computed pressure), ``contact_angle_deg``,
        ``entrainment_speed`` [m/s], ``slide_to_roll`` [-], ``rx``, ``ry`` [m],
        ``h_min``, ``h_central`` [m], ``p_max`` [Pa], ``rolling_resistance``,
        ``sliding_friction``, ``friction_force`` [N], ``heat_power`` [W],
        ``film_parameter`` (lambda, or None), ``h_central_formula`` [m] and its name,
        ``heat_power_poiseuille_direct`` and ``heat_power_stabilisation`` [W] (the contact
        solver's split of the rolling heat: direct dissipation integral and numerical
        dissipation of the stabilisation; None if not reported), ``newton_iterations``,
        ``wall_time_s``, ``warnings``, ``slices``.
    """
    out: dict[str, Any] = {
        "raceway": spec.raceway, "load": spec.load,
        "contact_angle_deg": math.degrees(spec.contact_angle),
        "entrainment_speed": spec.entrainment_speed, "slide_to_roll": 0.0,
        "rx": spec.rx, "ry": spec.ry,
    }
    if spec.excluded is not None:
        out.update(status="excluded", success=True, message=spec.excluded,
                   load_solved=None, h_min=None, h_central=None, p_max=None,
                   rolling_resistance=0.0, sliding_friction=0.0, friction_force=0.0,
                   heat_power=0.0, film_parameter=None, h_central_formula=None,
                   h_central_formula_name=None, newton_iterations=0, wall_time_s=0.0,
                   warnings=[], slices=0, heat_power_poiseuille_direct=0.0,
                   heat_power_stabilisation=0.0, error_estimate=None)
        return out
    sums = [results[k].summary() for k in spec.keys]
    kind = "point" if spec.ry is not None else "line"
    widths = [1.0] if kind == "point" else list(spec.widths)
    failed = [s for s in sums if not s["success"]]
    tot = {key: 0.0 for key in _EXTENSIVE}
    complete = {key: True for key in _EXTENSIVE}
    for s, w in zip(sums, widths):
        for key in _EXTENSIVE:
            v = _val(s, key)
            if v is None:
                complete[key] = False
            else:
                tot[key] += v * w
    # the contact solver's split of the rolling heat: the direct dissipation integral and
    # the stabilisation's numerical dissipation (their sum is heat_power); None if absent
    extra = {}
    for key in ("heat_power_poiseuille_direct", "heat_power_stabilisation"):
        vals = [_val(s, key) for s in sums]
        extra[key] = None if any(v is None for v in vals) else \
            float(sum(v * w for v, w in zip(vals, widths)))
    films = [_val(s, "h_min") for s in sums]
    pmax = [_val(s, "p_max") for s in sums]
    # central film of the most loaded scene (the middle slice of a symmetric roller)
    imax = int(np.argmax([float(sc.load.force) for sc in spec.scenes]))
    scene = spec.scenes[imax]
    lub = scene.lubricant
    if kind == "point":
        name = "Nijenbanning-Venner-Moes"
        h_formula = formulas.point_central_film_nvm(scene.load.force, spec.rx, spec.ry,
                                                    scene.e_prime, lub.viscosity,
                                                    spec.entrainment_speed,
                                                    lub.effective_piezo)
    else:
        name = "Moes"
        h_formula = formulas.line_central_film_moes(scene.load.force, spec.rx, scene.e_prime,
                                                    lub.viscosity, spec.entrainment_speed,
                                                    lub.effective_piezo)
    h_min = None if any(f is None for f in films) else min(films)
    sigma = bearing.model.roughness
    warnings: list[str] = []
    for i, s in enumerate(sums):
        label = slice_label(spec, i, bearing.geometry.n_slices)
        if not s["success"]:
            label = f"{label}, {LAST_ITERATE_NOTE}" if label else LAST_ITERATE_NOTE
        for w in s.get("warnings", []):
            text = f"{label}: {w}" if label else w
            if text not in warnings:
                warnings.append(text)
    if failed:
        status, success = failed[0]["status"], False
        message = f"{len(failed)} of {len(sums)} scene(s) unsuccessful: {failed[0]['message']}"
    else:
        status, success = sums[0]["status"], True
        message = sums[0]["message"] if len(sums) == 1 else \
            f"{len(sums)} slices solved ({sums[imax]['message']})"
    h_central = _val(sums[imax], "h_central")
    p_top = None if any(p is None for p in pmax) else max(pmax)
    out.update(
        status=status, success=success, message=message,
        load_solved=tot["load"] if complete["load"] else None,
        h_min=h_min, h_central=h_central, p_max=p_top,
        rolling_resistance=tot["rolling_resistance"] if complete["rolling_resistance"] else None,
        sliding_friction=tot["sliding_friction"] if complete["sliding_friction"] else None,
        friction_force=tot["friction_force"] if complete["friction_force"] else None,
        heat_power=tot["heat_power"] if complete["heat_power"] else None,
        film_parameter=(h_min / sigma) if (sigma and h_min is not None) else None,
        h_central_formula=float(h_formula), h_central_formula_name=name,
        newton_iterations=int(sum(int(s.get("newton_iterations") or 0) for s in sums)),
        wall_time_s=float(sum(float(s.get("wall_time_s") or 0.0) for s in sums)),
        warnings=warnings, slices=len(sums), **extra)
    out["error_estimate"] = None if failed else _contact_estimate(sums, widths, imax)
    if failed:  # an unsuccessful solve's last iterate is no result (Result keeps it)
        out.update({key: None for key in _RESULT_KEYS})
    if kind == "point":
        out.pop("slices")
    return out


#: Quantities of the contact and bearing error estimates.
_ESTIMATED_EXTENSIVE = ("friction_force", "heat_power")


def _relative(estimate: Mapping[str, Any] | None, key: str) -> float | None:
    v = (estimate or {}).get(key)
    return float(v) if isinstance(v, (int, float)) and math.isfinite(v) else None


def weighted_relative_error(values: Sequence[float | None],
                            errors: Sequence[float | None]) -> float | None:
    """Relative error of a sum of parts, assuming that the parts' errors add (one
    discretisation, errors of one sign): sum |v_k| e_k / |sum v_k|.

    Parameters
    ----------
    values : sequence of float or None
        The parts v_k (any one unit: N m, W, N).
    errors : sequence of float or None
        Their relative errors e_k [-].

    Returns
    -------
    float or None
        The relative error of the sum [-]; None if a part or its error is unknown or the
        sum is 0.
    """
    if any(v is None for v in values) or any(e is None for e in errors):
        return None
    total = float(sum(values))
    if total == 0.0:
        return None
    return float(sum(abs(v) * e for v, e in zip(values, errors)) / abs(total))


def _contact_estimate(sums: list[dict[str, Any]], widths: list[float],
                      imax: int) -> dict[str, float | None]:
    """Relative discretisation errors of a contact's numbers from its scenes' estimates:
    films and p_max those of the scene that sets them, friction and heat power
    :func:`weighted_relative_error` over the slices."""
    ests = [s.get("error_estimate") for s in sums]
    out: dict[str, float | None] = {}
    for key in _ESTIMATED_EXTENSIVE:
        vals = [(_val(s, key) * w if _val(s, key) is not None else None)
                for s, w in zip(sums, widths)]
        out[key] = weighted_relative_error(vals, [_relative(e, key) for e in ests])
    films = [_val(s, "h_min") for s in sums]
    pmax = [_val(s, "p_max") for s in sums]
    out["h_min"] = (None if any(f is None for f in films)
                    else _relative(ests[int(np.argmin(films))], "h_min"))
    out["p_max"] = (None if any(p is None for p in pmax)
                    else _relative(ests[int(np.argmax(pmax))], "p_max"))
    out["h_central"] = _relative(ests[imax], "h_central")
    return out


def element_torque(race_radius_inner: float, rx_inner: float, rx_outer: float,
                   element_radius: float, rolling_inner: float,
                   rolling_outer: float) -> tuple[float, float]:
    """Ring torque of one element's two contacts [N m], split by contact.

    M = r_i [F_P,i (2 - R_x,i/r) + F_P,o R_x,o/r] (see the module docstring): returns
    (r_i F_P,i (2 - R_x,i/r), r_i F_P,o R_x,o/r).

    Parameters
    ----------
    race_radius_inner : r_i [m]; rx_inner, rx_outer : R_x [m]; element_radius : r = D_w/2
    [m]; rolling_inner, rolling_outer : F_P of the inner and outer contact [N].
    """
    r = float(element_radius)
    ri = float(race_radius_inner)
    return (ri * rolling_inner * (2.0 - rx_inner / r), ri * rolling_outer * rx_outer / r)


def bearing_totals(bearing: Bearing, azimuth: np.ndarray, race_radius_inner: np.ndarray,
                   rows: list[dict[str, Any]]) -> dict[str, Any]:
    """Bearing totals from the per-element contact summaries.

    Parameters
    ----------
    bearing : Bearing
    azimuth : ndarray
        psi_j [rad].
    race_radius_inner : ndarray
        r_i of each element [m].
    rows : list of dict
        Per element: ``inner`` and ``outer`` (from :func:`contact_summary`).

    Returns
    -------
    dict
        ``friction_torque``, ``friction_torque_inner``, ``friction_torque_outer`` [N m]
        (None if a contact failed), ``heat_power``, ``heat_power_inner``,
        ``heat_power_outer`` [W], ``energy_balance`` {torque x omega_i [W], heat power [W],
        relative difference, the fraction of the heat that is the contact solver's
        numerical (stabilisation) dissipation}, ``h_min`` [m] and ``h_min_location``,
        ``p_max`` [Pa] and ``p_max_location``, ``film_parameter_min`` [-] (each None when a
        contact failed), ``complete`` (bool).
    """
    r = 0.5 * bearing.geometry.element_diameter
    omega = bearing.operation.inner_speed
    m_in = m_out = q_in = q_out = q_stab = 0.0
    stab_known = True
    complete = True
    h_best = p_best = None
    for j, row in enumerate(rows):
        ci, co = row["inner"], row["outer"]
        fpi, fpo = ci["rolling_resistance"], co["rolling_resistance"]
        if (fpi is None or fpo is None or ci["heat_power"] is None or co["heat_power"] is None
                or not ci["success"] or not co["success"]):
            complete = False  # a failed contact's last iterate is no result
            continue
        a, b = element_torque(race_radius_inner[j], ci["rx"], co["rx"], r, fpi, fpo)
        row["torque"] = a + b
        row["heat_power"] = ci["heat_power"] + co["heat_power"]
        m_in += a
        m_out += b
        q_in += ci["heat_power"]
        q_out += co["heat_power"]
        for c in (ci, co):
            if c.get("heat_power_stabilisation") is None:
                stab_known = False
            else:
                q_stab += c["heat_power_stabilisation"]
        for c in (ci, co):
            loc = {"element": j, "raceway": c["raceway"],
                   "azimuth_deg": math.degrees(float(azimuth[j]))}
            if c["h_min"] is not None and (h_best is None or c["h_min"] < h_best[0]):
                h_best = (c["h_min"], loc)
            if c["p_max"] is not None and (p_best is None or c["p_max"] > p_best[0]):
                p_best = (c["p_max"], loc)
    torque = m_in + m_out
    heat = q_in + q_out
    estimate = _bearing_estimate(rows, race_radius_inner, r, complete, h_best, p_best)
    power = torque * omega
    rel = (power - heat) / heat if heat > 0.0 else None
    sigma = bearing.model.roughness
    return {
        "friction_torque": torque if complete else None,
        "friction_torque_inner": m_in if complete else None,
        "friction_torque_outer": m_out if complete else None,
        "heat_power": heat if complete else None,
        "heat_power_inner": q_in if complete else None,
        "heat_power_outer": q_out if complete else None,
        "energy_balance": {"torque_times_speed": power if complete else None,
                           "heat_power": heat if complete else None,
                           "relative_difference": rel if complete else None,
                           "stabilisation_fraction": (q_stab / heat if complete and stab_known
                                                      and heat > 0.0 else None)},
        # the extremes over all loaded contacts, or None when a contact failed
        "h_min": h_best[0] if complete and h_best else None,
        "h_min_location": h_best[1] if complete and h_best else None,
        "p_max": p_best[0] if complete and p_best else None,
        "p_max_location": p_best[1] if complete and p_best else None,
        "film_parameter_min": (h_best[0] / sigma) if (sigma and complete and h_best) else None,
        "error_estimate": estimate,
        "complete": complete,
    }


def _bearing_estimate(rows: list[dict[str, Any]], race_radius_inner: np.ndarray,
                      element_radius: float, complete: bool, h_best, p_best
                      ) -> dict[str, float | None] | None:
    """Relative discretisation errors of the bearing's friction torque, heat power, h_min
    and p_max from the contacts' estimates (:func:`weighted_relative_error` over the
    element torques and contact heat powers; the films and p_max of the contact that sets
    them); None when a contact failed."""
    if not complete:
        return None
    torques: list[float | None] = []
    torque_errors: list[float | None] = []
    heats: list[float | None] = []
    heat_errors: list[float | None] = []
    by_loc: dict[tuple[int, str], dict[str, Any]] = {}
    for j, row in enumerate(rows):
        ci, co = row["inner"], row["outer"]
        a, b = element_torque(race_radius_inner[j], ci["rx"], co["rx"], element_radius,
                              ci["rolling_resistance"], co["rolling_resistance"])
        for part, c in ((a, ci), (b, co)):
            by_loc[(j, c["raceway"])] = c
            if c["status"] == "excluded":
                continue
            est = c.get("error_estimate")
            torques.append(part)
            torque_errors.append(_relative(est, "friction_force"))
            heats.append(c["heat_power"])
            heat_errors.append(_relative(est, "heat_power"))

    def at(best, key):
        if not best:
            return None
        loc = best[1]
        return _relative(by_loc[(loc["element"], loc["raceway"])].get("error_estimate"), key)

    return {"friction_torque": weighted_relative_error(torques, torque_errors),
            "heat_power": weighted_relative_error(heats, heat_errors),
            "h_min": at(h_best, "h_min"), "p_max": at(p_best, "p_max")}

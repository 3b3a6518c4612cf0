"""``solve_bearing(bearing)``: load distribution, kinematics, EHL at every loaded contact,
totals and the empirical models side by side.

Steps (docs/bearing.md):

1. internal load distribution with rigid rings (:mod:`~bearing_fem.bearing.loads`);
2. pure-rolling kinematics at the loaded contact angles (:mod:`~bearing_fem.bearing.kinematics`);
3. one EHL scene per loaded contact (per slice of a profiled roller), identical scenes
   solved once (:mod:`~bearing_fem.bearing.contacts`, :func:`bearing_fem.solve`);
4. per-contact totals, the bearing friction torque from forces and moment arms, heat
   power, films and pressures (:mod:`~bearing_fem.bearing.totals`);
5. the empirical models (:mod:`~bearing_fem.bearing.empirical`).

Never raises for an unsuccessful contact solve: the status says so. Raises
:class:`~bearing_fem.errors.SceneError` for input it cannot accept.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from ..errors import SceneError
from ..formulas import point_films_hamrock_dowson
from ..post import ERROR_WARNING_THRESHOLD, parse_estimate_warning
from ..contacts.refine import (TARGET_ERROR_MAX_LINE_NODES, TARGET_ERROR_MAX_POINT_NODES,
                               TARGET_ERROR_QUANTITIES, finer_grid, grid_label, grid_nodes,
                               misses_target, target_errors, target_grid_cap)
from ..result import json_safe
from ..scene import Scene
from .contacts import ContactSpec, contact_specs, solve_unique
from .description import Bearing, input_warnings, kelvin_like_temperatures
from .empirical import FIT_MIN_MATERIALS_PARAMETER, empirical_models, film_formulas
from .kinematics import ElementKinematics, element_kinematics
from .loads import LoadDistribution, centrifugal_force, distribute_loads, row_axial_force
from .totals import bearing_totals, contact_summary, slice_label

__all__ = ["BearingResult", "solve_bearing", "thin_film_refinement",
           "target_error_refinement", "BEARING_UNITS", "TARGET_ERROR_QUANTITIES",
           "FILM_FIT_WARNING_RATIO", "THIN_FILM_ESTIMATE", "THIN_FILM_REFINE_MAX_NODES",
           "ISO76_BALL_PRESSURE", "ISO76_ROLLER_PRESSURE"]

log = logging.getLogger(__name__)

#: Relative tolerance of the reported energy balance check (torque x omega vs heat).
ENERGY_BALANCE_RTOL = 1e-3
#: Hertz pressure at which ISO 76 sets the basic static load rating C0 of ball bearings
#: (self-aligning ones excepted) and of roller bearings [Pa]: the load at which the most
#: loaded contact deforms the raceway permanently by 1e-4 of the element diameter. A
#: contact above it is named in the bearing's warnings (the contacts themselves warn
#: only above :data:`bearing_fem.checks.HERTZ_PRESSURE_HIGH`, 5 GPa).
ISO76_BALL_PRESSURE = 4.2e9
ISO76_ROLLER_PRESSURE = 4.0e9
#: A ball contact whose solved h_min falls below this fraction of Hamrock-Dowson's minimum
#: film is solved again on the grid of half the spacing (:func:`thin_film_refinement`), and
#: named in the bearing's warnings if it stays below. The FE films lie up to 38 % below
#: that fit where they are grid-converged (docs/point.md, the circular map), so a factor 2
#: marks a film the grid does not resolve: 6209 at 500 rpm, the most loaded inner contact
#: (ry/rx = 32, Moes M = 2.4e4) had h_min 3.6e-8 m on the default 129^2 against
#: 1.05e-7 m on 257^2 and 1.02e-7 m by Hamrock-Dowson, with no error estimate (its 65^2
#: level failed; tests/test_bearing_solve.py).
FILM_FIT_WARNING_RATIO = 0.5
#: A ball contact's h_min below Hamrock-Dowson's with an estimated error above this (or
#: none) is solved again too (:func:`thin_film_refinement`): the 6209 at 500 rpm had
#: films of 0.55 and 0.78 times the fit on 129^2, one without an estimate and one with
#: a level difference of 79 % (6.7e-8 and 8.2e-8 m; 1.19e-7 and 1.10e-7 m on 257^2), and
#: set the bearing's h_min and film parameter (0.45 instead of 0.70); at 1000 rpm the two
#: contacts of the most loaded ball had 0.88 and 0.92 times the fit with estimates of
#: 59 and 44 %. A grid-converged film lies within about 40 % of the fit (docs/point.md).
THIN_FILM_ESTIMATE = 0.2
#: Largest node count per direction of that second solve (257^2 costs about 2-6 s per
#: contact; a finer grid than that is left to ``[mesh] point_nodes``).
THIN_FILM_REFINE_MAX_NODES = 257
#: With ``model.centrifugal`` off, the bearing's warnings name an element centrifugal force
#: above this fraction of the largest element load (the outer contacts' extra load).
CENTRIFUGAL_WARNING_FRACTION = 0.1

#: Units of the dimensional keys of :meth:`BearingResult.summary`.
BEARING_UNITS = {
    "friction_torque": "N m", "friction_torque_inner": "N m", "friction_torque_outer": "N m",
    "heat_power": "W", "heat_power_inner": "W", "heat_power_outer": "W", "h_min": "m",
    "p_max": "Pa", "radial_load": "N", "axial_load": "N", "inner_rpm": "1/min",
    "film_parameter_min": "1", "wall_time_s": "s",
    "elements.azimuth_deg": "deg", "elements.load": "N", "elements.load_outer": "N",
    "elements.contact_angle_deg": "deg", "elements.torque": "N m",
    "elements.heat_power": "W", "elements.inner/outer.h_min": "m",
    "elements.inner/outer.p_max": "Pa", "elements.inner/outer.rolling_resistance": "N",
    "elements.inner/outer.heat_power": "W", "elements.inner/outer.entrainment_speed": "m/s",
    "load_distribution.radial_displacement": "m", "load_distribution.axial_displacement": "m",
    "kinematics.cage_rpm": "1/min", "kinematics.entrainment_speed": "m/s",
    "kinematics.element_rpm": "1/min", "kinematics.slide_to_roll": "1",
    "load_distribution.load_zone_half_angle_deg": "deg",
    "load_distribution.max_element_load": "N", "load_distribution.centrifugal_force": "N",
    "load_distribution.radial_clearance": "m", "load_distribution.load_exponent": "1",
    "load_balance.radial_sum": "N", "load_balance.axial_sum": "N",
    "load_balance.row_axial_force": "N",
    "load_balance.radial_relative_error": "1", "load_balance.axial_relative_error": "1",
    "energy_balance.torque_times_speed": "W", "energy_balance.heat_power": "W",
    "energy_balance.relative_difference": "1", "energy_balance.stabilisation_fraction": "1",
    "h_min_location.azimuth_deg": "deg", "p_max_location.azimuth_deg": "deg",
    "empirical.*.torque": "N m", "empirical.*.heat_power": "W",
    # relative discretisation errors (the run store's error_estimate.* columns)
    "error_estimate.friction_torque": "1", "error_estimate.heat_power": "1",
    "error_estimate.h_min": "1", "error_estimate.p_max": "1",
    "elements.inner/outer.error_estimate.*": "1",
    # the rest of the per-element and per-contact numbers (counts are "1")
    "elements.index": "1", "elements.row": "1", "elements.approach": "m",
    "elements.contact_angle_outer_deg": "deg",
    "elements.inner/outer.load": "N", "elements.inner/outer.load_solved": "N",
    "elements.inner/outer.contact_angle_deg": "deg",
    "elements.inner/outer.slide_to_roll": "1", "elements.inner/outer.rx": "m",
    "elements.inner/outer.ry": "m", "elements.inner/outer.h_central": "m",
    "elements.inner/outer.h_central_formula": "m",
    "elements.inner/outer.sliding_friction": "N",
    "elements.inner/outer.friction_force": "N", "elements.inner/outer.film_parameter": "1",
    "elements.inner/outer.heat_power_poiseuille_direct": "W",
    "elements.inner/outer.heat_power_stabilisation": "W",
    "elements.inner/outer.newton_iterations": "1", "elements.inner/outer.slices": "1",
    "elements.inner/outer.wall_time_s": "s",
    "h_min_location.element": "1", "p_max_location.element": "1",
    "load_distribution.elements_loaded": "1", "contact_solves.scenes": "1",
    "contact_solves.distinct_solved": "1", "contact_solves.reused": "1",
    "contact_solves.solved_again": "1",
    # the empirical models' parts and parameters
    "empirical.*.torque_viscous": "N m", "empirical.*.torque_load": "N m",
    "empirical.*.torque_rolling": "N m", "empirical.*.torque_sliding": "N m",
    "empirical.*.torque_seal": "N m", "empirical.*.torque_drag": "N m",
    "empirical.*.friction_heat_power": "W", "empirical.*.churning_heat_power": "W",
    "empirical.*.friction_coefficient": "1",
    "empirical.*.parameters.f0": "1", "empirical.*.parameters.f1": "1",
    "empirical.*.parameters.f_pr": "1", "empirical.*.parameters.P1_N": "N",
    "empirical.*.parameters.kinematic_viscosity_mm2_s": "mm^2/s",
    "empirical.*.parameters.R1": "SKF catalogue units (d_m in mm, loads in N, N mm)",
    "empirical.*.parameters.R2": "SKF catalogue units (d_m in mm, loads in N, N mm)",
    "empirical.*.parameters.S1": "SKF catalogue units (d_m in mm, loads in N, N mm)",
    "empirical.*.parameters.S2": "SKF catalogue units (d_m in mm, loads in N, N mm)",
    "empirical.*.parameters.phi_ish": "1", "empirical.*.parameters.phi_rs": "1",
    "empirical.*.parameters.mu_sl": "1", "empirical.*.parameters.flow_ratio": "1",
    "empirical.*.parameters.Re": "1", "empirical.*.parameters.Pr": "1",
    "empirical.*.parameters.Eu": "1", "empirical.*.parameters.cage_speed_m_s": "m/s",
    "film_formulas.element": "1", "film_formulas.inner/outer.*.h_min": "m",
    "film_formulas.inner/outer.*.h_central": "m",
}


@dataclass
class BearingResult:
    """Outcome of :func:`solve_bearing`.

    Attributes
    ----------
    bearing : Bearing
    success : bool
        Every loaded contact solved and the loads balanced.
    status : str
        ``converged``, ``contacts_failed`` (some contact solve unsuccessful: the totals
        are None, the per-contact statuses say which) or ``load_distribution_failed``.
    message : str
    distribution : LoadDistribution or None
    kinematics : ElementKinematics or None
    specs : list of ContactSpec
        Two per element (inner, outer), with their scenes.
    contacts : dict
        Scene key -> :class:`~bearing_fem.result.Result` of every distinct scene solved.
    elements : list of dict
        Per element: ``index``, ``row``, ``azimuth_deg``, ``load`` (inner contact),
        ``load_outer``, ``contact_angle_deg``, ``contact_angle_outer_deg``,
        ``in_load_zone``, ``approach``, ``torque`` [N m], ``heat_power`` [W] and the
        ``inner`` and ``outer`` contact summaries
        (:func:`~bearing_fem.bearing.totals.contact_summary`).
    totals : dict
        :func:`~bearing_fem.bearing.totals.bearing_totals`.
    empirical : dict
        :func:`~bearing_fem.bearing.empirical.empirical_models`.
    films : dict
        Film formulas at the most loaded element's inner and outer contacts.
    warnings : list of str
    refined : dict
        Scene key -> ``{"nodes": (n,) or (nx, ny), "h_min": [m]}`` of its first grid, for
        each contact solved again on a grid of half the spacing: a ball contact whose film
        lay far below Hamrock-Dowson's (:func:`thin_film_refinement`), or one above
        ``mesh.target_error`` (:func:`target_error_refinement`); ``contacts`` holds the
        finer result.
    wall_time_s : float
    """

    bearing: Bearing
    success: bool
    status: str
    message: str
    distribution: LoadDistribution | None = None
    kinematics: ElementKinematics | None = None
    specs: list[ContactSpec] = field(default_factory=list)
    contacts: dict[str, Any] = field(default_factory=dict)
    elements: list[dict[str, Any]] = field(default_factory=list)
    totals: dict[str, Any] = field(default_factory=dict)
    empirical: dict[str, Any] = field(default_factory=dict)
    films: dict[str, Any] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    refined: dict[str, dict[str, Any]] = field(default_factory=dict)
    wall_time_s: float = 0.0

    def __repr__(self) -> str:
        return (f"BearingResult(message={self.message!r}, success={self.success}, "
                f"status={self.status!r}, elements={len(self.elements)}, "
                f"friction_torque={self.totals.get('friction_torque')!r})")

    # ------------------------------------------------------------------------------
    def most_loaded_element(self) -> int:
        """Index of the element with the largest inner-contact load."""
        return int(np.argmax(self.distribution.load_inner))

    def contact_results(self, element: int, raceway: str) -> list[Any]:
        """The contact solver's results of one contact (one per slice; [] if excluded)."""
        for spec in self.specs:
            if spec.element == element and spec.raceway == raceway:
                return [self.contacts[k] for k in spec.keys if k in self.contacts]
        raise KeyError(f"no contact ({element}, {raceway!r})")

    def contact_spec(self, element: int, raceway: str) -> ContactSpec:
        """The :class:`ContactSpec` of one contact."""
        for spec in self.specs:
            if spec.element == element and spec.raceway == raceway:
                return spec
        raise KeyError(f"no contact ({element}, {raceway!r})")

    def element_table(self) -> list[dict[str, Any]]:
        """One flat row per element (the columns of ``elements.csv``; SI, unit in names)."""
        rows = []
        for e in self.elements:
            row = {"element": e["index"], "row": e["row"], "azimuth_deg": e["azimuth_deg"],
                   "load_N": e["load"], "load_outer_N": e["load_outer"],
                   "contact_angle_deg": e["contact_angle_deg"],
                   "contact_angle_outer_deg": e["contact_angle_outer_deg"],
                   "in_load_zone": e["in_load_zone"], "approach_m": e["approach"],
                   "torque_N_m": e.get("torque"), "heat_power_W": e.get("heat_power")}
            for race in ("inner", "outer"):
                c = e[race]
                est = c.get("error_estimate") or {}
                row.update({
                    f"{race}_status": c["status"], f"{race}_h_min_m": c["h_min"],
                    f"{race}_h_central_m": c["h_central"], f"{race}_p_max_Pa": c["p_max"],
                    f"{race}_rolling_resistance_N": c["rolling_resistance"],
                    f"{race}_heat_power_W": c["heat_power"],
                    f"{race}_entrainment_speed_m_s": c["entrainment_speed"],
                    f"{race}_film_parameter": c["film_parameter"],
                    f"{race}_newton_iterations": c["newton_iterations"]})
                # relative discretisation errors of the contact's numbers (error bars)
                row.update({f"{race}_{k}_rel_error": est.get(k)
                            for k in ("h_min", "h_central", "p_max", "friction_force",
                                      "heat_power")})
            rows.append(row)
        return rows

    def summary(self) -> dict[str, Any]:
        """The result as a JSON-able dict (SI; ``units`` names every unit).

        Keys: ``status``, ``success``, ``message``, ``warnings``, ``wall_time_s``,
        ``friction_torque`` [N m], ``heat_power`` [W], ``h_min`` [m], ``p_max`` [Pa],
        ``radial_load``, ``axial_load`` [N], ``inner_rpm``, ``elements`` (per element:
        ``azimuth_deg``, ``load`` [N], ``contact_angle_deg``, ``inner``/``outer`` contact
        summaries ...), ``empirical`` (models' ``torque`` and ``heat_power``),
        ``error_estimate`` (relative discretisation errors of ``friction_torque``,
        ``heat_power``, ``h_min`` and ``p_max`` from the contacts' estimates; None when
        the totals are not formed), and the per-raceway totals, the energy balance, the locations of h_min and p_max, the
        load balance, the load distribution, the kinematics, the film formulas at the
        most loaded element, ``units``, ``version`` and ``bearing``.
        """
        from .. import __version__

        op = self.bearing.operation
        t = self.totals
        d = self.distribution
        out: dict[str, Any] = {
            "status": self.status, "success": bool(self.success), "message": self.message,
            "warnings": list(self.warnings), "wall_time_s": float(self.wall_time_s),
            "friction_torque": t.get("friction_torque"), "heat_power": t.get("heat_power"),
            "h_min": t.get("h_min"), "p_max": t.get("p_max"),
            "radial_load": float(op.radial_load), "axial_load": float(op.axial_load),
            "inner_rpm": float(op.inner_rpm),
            "friction_torque_inner": t.get("friction_torque_inner"),
            "friction_torque_outer": t.get("friction_torque_outer"),
            "heat_power_inner": t.get("heat_power_inner"),
            "heat_power_outer": t.get("heat_power_outer"),
            "energy_balance": t.get("energy_balance"),
            "h_min_location": t.get("h_min_location"),
            "p_max_location": t.get("p_max_location"),
            "film_parameter_min": t.get("film_parameter_min"),
            "error_estimate": t.get("error_estimate"),
            "elements": self.elements, "empirical": self.empirical,
            "film_formulas": self.films,
        }
        if d is not None:
            fr, fa = float(op.radial_load), float(op.axial_load)
            out["load_balance"] = {
                "radial_sum": d.radial_sum, "axial_sum": d.axial_sum,
                "row_axial_force": row_axial_force(d),
                "radial_relative_error": (d.radial_sum - fr) / fr if fr > 0 else None,
                "axial_relative_error": (d.axial_sum - fa) / fa if fa > 0 else None}
            out["load_distribution"] = {
                "radial_displacement": d.radial_displacement,
                "axial_displacement": d.axial_displacement,
                "load_zone_half_angle_deg": math.degrees(d.load_zone_half_angle),
                "max_element_load": d.max_load, "centrifugal_force": d.centrifugal_force,
                "radial_clearance": d.clearance, "load_exponent": d.exponent,
                "elements_loaded": int(np.count_nonzero(d.in_load_zone))}
        if self.kinematics is not None and d is not None:
            j = self.most_loaded_element()
            k = self.kinematics
            out["kinematics"] = {
                "cage_rpm": float(k.cage_speed[j]) * 60.0 / (2.0 * math.pi),
                "element_rpm": float(k.element_speed[j]) * 60.0 / (2.0 * math.pi),
                "entrainment_speed": float(k.entrainment_speed[j]),
                "slide_to_roll": 0.0,
                "note": "pure rolling; values of the most loaded element"}
        n_scenes = sum(len(s.keys) for s in self.specs)
        out["contact_solves"] = {"scenes": n_scenes, "distinct_solved": len(self.contacts),
                                 "reused": n_scenes - len(self.contacts),
                                 "solved_again": len(self.refined)}
        out["units"] = dict(BEARING_UNITS)
        out["version"] = __version__
        out["bearing"] = self.bearing.to_dict()
        return json_safe(out)


def _drawn_back_warning(bearing: Bearing, dist: LoadDistribution) -> str:
    """The warning of a single angular-contact ball bearing whose axial load is below the
    axial force its radial load induces: the inner ring is drawn back from the nominal
    contact position and every loaded ball runs below the nominal contact angle, towards
    the deep-groove state of a radial load alone (refused at 0 N)."""
    op, g = bearing.operation, bearing.geometry
    a = np.degrees(dist.alpha_inner[dist.in_load_zone])
    return (f"operation.axial_load = {float(op.axial_load):g} N is below the axial force "
            f"that operation.radial_load = {float(op.radial_load):g} N induces at the "
            f"nominal contact angle: the inner ring is drawn back "
            f"{-1e3 * dist.axial_displacement:.3g} mm from the nominal contact position and "
            f"the loaded balls run at {float(a.min()):.3g} to {float(a.max()):.3g} deg "
            f"instead of {g.contact_angle:g} deg, as in a deep-groove bearing with "
            "clearance; a single angular-contact bearing is mounted against an opposed one: "
            "give its net axial load, the external load plus the opposed bearing's reaction")


def _energy_balance_warning(difference: float, elements: list[dict[str, Any]],
                            dist: LoadDistribution) -> str:
    """The warning of an open energy balance (torque x omega vs the contacts' heat), naming
    its cause: contacts whose heat power departs from Q = 2 u_m F_P, or, when every contact
    satisfies it, the unequal inner and outer contact angles of the balls (centrifugal
    force), for which the element torque's moment arms do not hold (docs/bearing.md 5.1)."""
    head = (f"friction torque x omega differs from the contacts' heat power by "
            f"{100 * difference:+.2f} % (> {100 * ENERGY_BALANCE_RTOL:g} %): ")
    worst = 0.0
    for e in elements:
        for race in ("inner", "outer"):
            c = e[race]
            if c["status"] == "excluded" or not c["heat_power"]:
                continue
            rolling = 2.0 * c["entrainment_speed"] * c["rolling_resistance"]
            worst = max(worst, abs(c["heat_power"] - rolling) / abs(c["heat_power"]))
    split = dist.alpha_inner[dist.in_load_zone] - dist.alpha_outer[dist.in_load_zone]
    split = float(np.max(np.abs(split))) if split.size else 0.0
    if worst > 0.1 * ENERGY_BALANCE_RTOL or split == 0.0:
        return head + ("the contact heat powers do not satisfy Q = 2 u_m F_P (contact "
                       f"solver's heat form; up to {100 * worst:.2g} % off)")
    return head + ("every contact's heat power satisfies Q = 2 u_m F_P, but the inner and "
                   f"outer contact angles of the balls differ by up to "
                   f"{math.degrees(split):.3g} deg (centrifugal force) and the element "
                   "torque's moment arms hold for equal angles (ball spin and gyroscopic "
                   "motion are not modelled): the friction torque is uncertain by about "
                   "this difference")


def solve_bearing(bearing: Bearing, *,
                  progress: Callable[[int, int, str], None] | None = None,
                  blas_threads: int | None = 1) -> BearingResult:
    """Solve a bearing: load distribution, kinematics, EHL at every loaded contact, totals.

    Parameters
    ----------
    bearing : Bearing
    progress : callable, optional
        ``progress(done, total, title)`` after each contact solve.
    blas_threads : int or None
        BLAS threads during the contact solves (default 1; None: unchanged); see
        :func:`~bearing_fem.bearing.contacts.solve_unique`.

    Returns
    -------
    BearingResult
        Never raises for an unsuccessful solve: see ``status`` and ``message``.

    Raises
    ------
    SceneError
        ``bearing`` is not a Bearing, or a contact scene built from it is refused (the
        message names the bearing's field: ``operation.inner_rpm``, the loads, ...).
    """
    if not isinstance(bearing, Bearing):
        raise SceneError(f"solve_bearing() needs a Bearing, got {type(bearing).__name__}")
    t0 = time.perf_counter()
    g, op = bearing.geometry, bearing.operation
    warnings: list[str] = input_warnings(bearing)
    try:
        dist = distribute_loads(bearing)
    except (RuntimeError, ValueError) as exc:
        return BearingResult(bearing=bearing, success=False, status="load_distribution_failed",
                             message=f"no ring displacement balances the loads: {exc}",
                             warnings=warnings, wall_time_s=time.perf_counter() - t0)
    flipped = np.flatnonzero(np.maximum(np.abs(dist.alpha_inner), np.abs(dist.alpha_outer))
                             >= 0.5 * math.pi)
    if flipped.size:
        j = int(flipped[0])
        angle = max(abs(float(dist.alpha_inner[j])), abs(float(dist.alpha_outer[j])))
        if dist.centrifugal_force > 0.0:
            raise SceneError(
                f"model.centrifugal: at operation.inner_rpm = {float(op.inner_rpm)!r} 1/min "
                f"the elements' centrifugal force {dist.centrifugal_force:.4g} N pushes them "
                f"out so far, against operation.radial_load = {float(op.radial_load)!r} N and "
                f"operation.axial_load = {float(op.axial_load)!r} N, that element {j}'s "
                f"contact angle is {math.degrees(angle):.4g} deg (>= 90 deg): the inner "
                "contact runs off its raceway; give a larger axial load (preload) or a "
                "lower speed")
        raise SceneError(
            f"operation.radial_load = {float(op.radial_load)!r} N and operation.axial_load = "
            f"{float(op.axial_load)!r} N displace the rings so far that element {j}'s contact "
            f"angle is {math.degrees(angle):.4g} deg (>= 90 deg): no "
            "rolling bearing carries that load; check the loads' unit (N)")
    if not bearing.model.centrifugal:
        fc = centrifugal_force(bearing, modelled=False)
        if fc > CENTRIFUGAL_WARNING_FRACTION * dist.max_load:
            warnings.append(
                f"model.centrifugal is off, but at operation.inner_rpm = "
                f"{float(op.inner_rpm):g} 1/min each element's centrifugal force "
                f"m (d_m/2) omega_c^2 = {fc:.4g} N is {100 * fc / dist.max_load:.3g} % of the "
                f"largest element load {dist.max_load:.4g} N (above "
                f"{100 * CENTRIFUGAL_WARNING_FRACTION:g} %): the outer contacts would carry "
                "up to F_c more than the inner ones"
                + (" and the balls' contact angles would split" if g.is_ball
                   and op.axial_load > 0.0 else "")
                + ("; model.centrifugal is not modelled for profiled rollers"
                   if not g.is_ball and g.profile != "straight"
                   else "; set model.centrifugal = true"))
    if (g.type == "angular-contact-ball" and op.radial_load > 0.0
            and np.any(dist.in_load_zone) and dist.axial_displacement < 0.0
            and np.max(dist.alpha_inner[dist.in_load_zone]) < math.radians(g.contact_angle)):
        warnings.append(_drawn_back_warning(bearing, dist))
    kin = element_kinematics(op.inner_speed, g.mean_diameter, g.element_diameter,
                             dist.alpha_inner, dist.alpha_outer)
    specs = contact_specs(bearing, dist, kin)
    warnings.extend(_truncated_domain_warnings(bearing, specs))
    warnings.extend(_static_capacity_warning(bearing, specs))
    refined: dict[str, dict[str, Any]] = {}
    results = solve_unique(specs, progress=progress, blas_threads=blas_threads,
                           refine=_refinement(bearing), refined=refined)
    by_element: dict[int, dict[str, Any]] = {}
    for spec in specs:
        by_element.setdefault(spec.element, {})[spec.raceway] = contact_summary(
            bearing, spec, results)
    elements = []
    for j in range(dist.azimuth.size):
        elements.append({
            "index": j, "row": int(dist.row[j]),
            "azimuth_deg": math.degrees(float(dist.azimuth[j])),
            "load": float(dist.load_inner[j]), "load_outer": float(dist.load_outer[j]),
            "contact_angle_deg": math.degrees(float(dist.alpha_inner[j])),
            "contact_angle_outer_deg": math.degrees(float(dist.alpha_outer[j])),
            "in_load_zone": bool(dist.in_load_zone[j]), "approach": float(dist.approach[j]),
            "torque": None, "heat_power": None,
            "inner": by_element[j]["inner"], "outer": by_element[j]["outer"]})
    totals = bearing_totals(bearing, dist.azimuth, kin.race_radius_inner, elements)
    loaded = dist.in_load_zone
    mean_alpha = math.degrees(float(np.average(dist.alpha_inner[loaded],
                                               weights=dist.load_inner[loaded])))
    emp = empirical_models(bearing, mean_alpha)
    if not g.is_ball and op.axial_load > 0.0 and "palmgren" in emp:
        warnings.append(
            f"Palmgren's load term of roller bearings takes P1 = Fr = "
            f"{float(op.radial_load):.4g} N (operation.radial_load): the axial load "
            f"operation.axial_load = {float(op.axial_load):.4g} N is left out of its torque "
            "(M1 = f1 P1 d_m), so its comparison with the EHL torque leaves that load out")
    films = _films_at_most_loaded(bearing, specs, dist)
    warnings.extend(_thin_film_warnings(bearing, films, elements))
    failed = [(s.element, s.raceway) for s in specs
              if s.excluded is None and not all(results[k].success for k in s.keys)]
    excluded = [s for s in specs if s.excluded is not None and s.load > 0.0]
    if excluded:
        warnings.append(f"{len(excluded)} lightly loaded contact(s) below "
                        f"model.min_load_fraction = {bearing.model.min_load_fraction:g} were "
                        "not solved (see their messages)")
    est = totals.get("error_estimate") or {}
    unknown = [k for k, v in est.items() if v is None]
    if unknown:
        warnings.append(_missing_estimate_warning(bearing, specs, results, elements, unknown))
    loose = {k: v for k, v in est.items() if v is not None and v > ERROR_WARNING_THRESHOLD}
    if loose:
        warnings.append("estimated discretisation error above "
                        f"{100 * ERROR_WARNING_THRESHOLD:g} %: "
                        + ", ".join(f"{k} {100 * v:.2g} %" for k, v in loose.items())
                        + f" (finer contact grids: [mesh] {_nodes_key(bearing)})")
    eb = totals["energy_balance"]["relative_difference"]
    if eb is not None and abs(eb) > ENERGY_BALANCE_RTOL:
        warnings.append(_energy_balance_warning(eb, elements, dist))
    warnings.extend(_target_error_warning(bearing, specs, results))
    warnings.extend(_contact_warnings(bearing, specs, results,
                                      drop_missing_estimate=bool(unknown)))
    n_solved = len(results)
    n_scenes = sum(len(s.keys) for s in specs)
    if failed:
        status, success = "contacts_failed", False
        message = (f"{len(failed)} contact(s) unsuccessful, e.g. element {failed[0][0]} "
                   f"{failed[0][1]}; totals not formed ({n_solved} distinct contact scenes "
                   f"attempted, {sum(not r.success for r in results.values())} of them "
                   "unsuccessful)")
    else:
        status, success = "converged", True
        m = totals["friction_torque"]
        message = (f"{int(np.count_nonzero(loaded))} of {dist.azimuth.size} elements loaded; "
                   f"{n_solved} distinct contact scenes solved ({n_scenes - n_solved} reused by "
                   f"symmetry{_solved_again_note(refined)}); friction torque {m:.4g} N m, "
                   f"heat power {totals['heat_power']:.4g} W")
    return BearingResult(bearing=bearing, success=success, status=status, message=message,
                         distribution=dist, kinematics=kin, specs=specs, contacts=results,
                         elements=elements, totals=totals, empirical=emp, films=films,
                         warnings=warnings, refined=refined,
                         wall_time_s=time.perf_counter() - t0)


def _nodes_key(bearing: Bearing) -> str:
    """The ``[mesh]`` key of the contact grids of this bearing's type."""
    return "point_nodes" if bearing.geometry.is_ball else "line_nodes"


#: Longest failure message of a contact quoted in the bearing's warnings [characters].
FAILURE_MESSAGE_CHARS = 240


def _short(text: str, limit: int = FAILURE_MESSAGE_CHARS) -> str:
    """``text`` cut after ``limit`` characters (at a word) with an ellipsis."""
    text = " ".join(str(text).split())
    if len(text) <= limit:
        return text
    return text[:limit].rsplit(" ", 1)[0] + " ..."


def _bearing_terms(bearing: Bearing, text: str) -> str:
    """A contact scene's warning in the bearing file's terms: scene fields that come from
    a bearing field are named by that field (``mesh.nodes`` -> ``[mesh] point_nodes`` or
    ``line_nodes``, ``thermal.oil_temperature`` -> ``operation.oil_temperature``, the
    temperature law's fields -> ``lubricant.*``), a viscosity warning about a viscosity
    the temperature law computed says so instead of naming ``lubricant.viscosity``, and a
    light line load is named as such, without the scene's hint on giving a force per
    metre (the bearing computed the line load itself)."""
    key = _nodes_key(bearing)
    text = text.replace("(mesh.nodes)", f"([mesh] {key})").replace("mesh.nodes",
                                                                      f"mesh.{key}")
    for name in ("reference_temperature", "reference_viscosity", "exponent",
                 "piezo_temperatures", "piezo_values"):
        text = text.replace(f"thermal.{name}", f"lubricant.{name}")
    text = text.replace("thermal.oil_temperature", "operation.oil_temperature")
    if text.startswith("load.force = ") and "; a line load is per metre of length" in text:
        # the bearing computed the line load itself: the scene's unit hint does not apply
        load, _, rest = text[len("load.force = "):].partition(" gives ")
        text = (f"a light load: the line load {load} (from the bearing's loads) gives "
                + rest.split("; a line load is per metre")[0] + "; a nearly rigid film")
    lub, t = bearing.lubricant, bearing.operation.oil_temperature
    if lub.temperature_law == "prokofiev" and text.startswith("lubricant.viscosity = "):
        value, _, rest = text[len("lubricant.viscosity = "):].partition(" Pa s ")
        rest = rest.split("; did you")[0]
        text = (f"the temperature law (lubricant.temperature_law = 'prokofiev') gives "
                f"{float(value):.3g} Pa s at {t:g} deg C (operation.oil_temperature), which "
                f"{rest}; check lubricant.reference_viscosity (Pa s at "
                "lubricant.reference_temperature, deg C), lubricant.exponent and the oil "
                "temperature")
    return text


def _contact_warnings(bearing: Bearing, specs: list[ContactSpec], results: dict[str, Any], *,
                      drop_missing_estimate: bool = False) -> list[str]:
    """The contact solver's warnings for the bearing's ``warnings``: each text once, in the
    bearing file's terms (:func:`_bearing_terms`), naming the contacts (and the slices of a
    profiled roller) it applies to, or "all n solved contacts". The warnings of an
    unsuccessful scene are about its last iterate and are dropped; its failure message
    (shortened) is given instead. With ``drop_missing_estimate`` (the bearing's own
    warning lists the contacts without error estimates) a contact's "no error estimate"
    warning is dropped too. A warning about a temperature that the bearing's input
    warnings already call kelvin-like (a hot oil; :func:`kelvin_like_temperatures` of
    :mod:`bearing_fem.bearing.description`) is dropped: theirs says it, and more."""
    covered = tuple(f"{name} = " for name, _ in kelvin_like_temperatures(bearing))
    users: dict[str, list[str]] = {}
    for spec in specs:
        for i, key in enumerate(spec.keys):
            label = slice_label(spec, i, bearing.geometry.n_slices)
            name = f"{spec.element} {spec.raceway}" + (f", {label}" if label else "")
            if name not in users.setdefault(key, []):
                users[key].append(name)
    texts: dict[str, list[str]] = {}
    failures: dict[str, list[str]] = {}
    n_ok = 0
    for key, names in users.items():
        res = results[key]
        if not res.success:
            why = (f"unsuccessful (status {res.status}): "
                   f"{_short(_bearing_terms(bearing, res.message))}")
            failures.setdefault(why, []).extend(names)
            continue
        n_ok += len(names)
        for w in res.warnings:
            if drop_missing_estimate and w.startswith("no error estimate"):
                continue
            text = _bearing_terms(bearing, w)
            if covered and text.startswith(covered):
                continue
            texts.setdefault(text, []).extend(names)

    texts = _merge_estimate_warnings(texts)

    def who(names: list[str]) -> str:
        sep = "; " if any("," in n for n in names) else ", "
        return (f"contact{'s' if len(names) > 1 else ''} " + sep.join(names[:4])
                + (f" (+{len(names) - 4} more)" if len(names) > 4 else ""))

    out = [f"{who(names)} {why}" for why, names in failures.items()]
    for text, names in texts.items():
        if len(names) == n_ok and n_ok > 1:
            what = "contact slices" if bearing.geometry.n_slices > 1 else "contacts"
            out.append(f"all {n_ok} solved {what}: {text}")
        else:
            out.append(f"{who(names)}: {text}")
    return out


def _merge_estimate_warnings(texts: dict[str, list[str]]) -> dict[str, list[str]]:
    """Contacts' warnings that one quantity is not mesh-converged as one sentence with
    the range of their estimated errors, naming the grids when all contacts share them
    (text -> contact names, in the order of first appearance); other warnings
    unchanged."""
    parsed = {text: parse_estimate_warning(text) for text in texts}
    groups: dict[tuple[str, str], list[str]] = {}
    for text, parts in parsed.items():
        if parts is not None:
            groups.setdefault((parts["key"], parts["tail"]), []).append(text)
    merged: dict[str, list[str]] = {}
    for text, names in texts.items():
        parts = parsed[text]
        members = groups.get((parts["key"], parts["tail"])) if parts else None
        if not members or len(members) < 2:
            merged.setdefault(text, []).extend(names)
            continue
        if text != members[0]:
            continue  # folded into the first member's sentence
        found = [parsed[t] for t in members]
        errors = [float(f["error"]) for f in found]
        hows = " or ".join(sorted({f["how"] for f in found}, reverse=True))
        grids = {f["grids"] for f in found}
        where = grids.pop() if len(grids) == 1 else _coarser_grids(grids)
        lo, hi = f"{min(errors):.3g}", f"{max(errors):.3g}"
        span = lo if lo == hi else f"{lo} to {hi}"
        sentence = (f"{parts['key']} is not mesh-converged: estimated discretisation error "
                    f"{span}% ({hows}, {where}); {parts['tail']}")
        merged[sentence] = [n for t in members for n in texts[t]]
    return merged


def _coarser_grids(notes: set[str]) -> str:
    """Words for the estimates' grids when the contacts' grids differ: each contact's
    grid and how many coarser ones (the grids notes "grids a, b, c" of
    :func:`bearing_fem.post.estimate_warnings`, finest last)."""
    counts = sorted({n.count(",") for n in notes if n.startswith("grids ")})
    if not counts:
        return "each contact's own grids"
    words = {1: "one", 2: "two", 3: "three"}
    lo, hi = (words.get(k, str(k)) for k in (counts[0], counts[-1]))
    return f"each contact's grid and {lo if lo == hi else f'{lo} to {hi}'} coarser"

def _default_domain(scene: Any) -> tuple[float, float]:
    """(inlet, side) of the default domain of a loaded elastic contact scene [Hertz
    half-widths]: where the default x range starts upstream, -x_range[0], and the
    half-width of a point contact's default y range (0 for a line contact), from the same
    functions the contact setups take them from (``default_x_range`` of
    :mod:`bearing_fem.contacts.line`, ``default_ranges`` of
    :mod:`bearing_fem.contacts.point`; an isoviscous heavily loaded contact has a shorter
    inlet)."""
    if scene.contact.kind == "line":
        from ..contacts.line import default_x_range

        return -default_x_range(scene)[0], 0.0
    from ..contacts.point import default_ranges

    xr, yr = default_ranges(scene)
    return -xr[0], yr[1]


def _truncated_domain_warnings(bearing: Bearing, specs: list[ContactSpec]) -> list[str]:
    """Warnings for a user ``[mesh] x_range`` that starts downstream of the default inlet
    of some solved contact (or a ``y_range`` of a ball bearing narrower than the default):
    the inlet is truncated, which lowers the rolling resistance and the friction torque
    (measured: an x_range of [-3, 1.2] put a roller bearing's torque 17..19 % low), and the
    error estimates (grid discretisation only) do not include it."""
    mesh = bearing.mesh
    if mesh.x_range is None and mesh.y_range is None:
        return []
    inlet, side = 0.0, 0.0
    for spec in specs:
        if spec.excluded is not None:
            continue
        for sc in spec.scenes:
            i, s = _default_domain(sc)
            inlet, side = max(inlet, i), max(side, s)
    out = []
    tail = ("the rolling resistance and the friction torque may be underestimated (the "
            "inlet builds the film and carries the rolling resistance), and the error "
            "estimates are grid discretisation errors that do not include this domain "
            "truncation; remove it or start it at or before the default")
    if mesh.x_range is not None and inlet and mesh.x_range[0] > -inlet:
        out.append(f"mesh.x_range starts at {mesh.x_range[0]:g} Hertz half-widths, downstream "
                   f"of the contacts' default inlet at {-inlet:.3g}: the inlet is truncated; "
                   + tail)
    if mesh.y_range is not None and side and min(-mesh.y_range[0], mesh.y_range[1]) < side:
        out.append(f"mesh.y_range = [{mesh.y_range[0]:g}, {mesh.y_range[1]:g}] Hertz "
                   f"half-widths is narrower than the contacts' default [{-side:.3g}, "
                   f"{side:.3g}]: the inlet's side flow is truncated; " + tail)
    return out


def _grid_text(nx: int, ny: int | None) -> str:
    """A grid of ``nx`` (by ``ny``) nodes: ``"65x65"`` (point) or ``"401 nodes"`` (line)."""
    return f"{nx} nodes" if ny is None else f"{nx}x{ny}"


def _grid(res: Any) -> str:
    """A contact result's grid (:func:`_grid_text`)."""
    return _grid_text(res.x.size, None if res.y is None else res.y.size)


def _missing_estimate_warning(bearing: Bearing, specs: list[ContactSpec],
                              results: dict[str, Any], elements: list[dict[str, Any]],
                              unknown: list[str]) -> str:
    """The warning for bearing error bars that are missing (``unknown``): which contacts
    (and slices) have no estimate, on which grids, and why.

    A contact's estimate (:func:`bearing_fem.post.error_estimate`) compares its solution
    with the same solve on the grids of every other node (twice and four times the
    spacing, ``contacts.driver.estimate_levels``). It is missing when the grid of twice
    the spacing does not converge from the restricted fine solution (coarse grids of
    heavily loaded contacts: 33x33 below 65x65, 9x9 below 17x17), when the grid cannot be
    halved (the contact models' ``coarsen``: an even node count, or fewer than 17 nodes per
    direction) or when a quantity is zero or undefined on the finest grid.
    """
    items = []
    example = ""
    for e in elements:
        for c in (e["inner"], e["outer"]):
            ce = c.get("error_estimate")
            if c["status"] == "excluded" or (ce is not None and all(
                    v is not None for v in ce.values())):
                continue
            spec = next(s for s in specs if s.element == e["index"]
                        and s.raceway == c["raceway"])
            grids = []
            for i, key in enumerate(spec.keys):
                res = results[key]
                est = res.error_estimate or {}
                if est.get("levels", 0) >= 2:
                    continue
                label = slice_label(spec, i, bearing.geometry.n_slices)
                grids.append(f"{label + ' ' if label else ''}{_grid(res)}")
                n = res.x.size
                if not example and n % 2 == 1:
                    half_y = None if res.y is None else (res.y.size - 1) // 2 + 1
                    example = (f" (here e.g. {_grid_text((n - 1) // 2 + 1, half_y)} below "
                               f"{_grid(res)})")
            name = f"{e['index']} {c['raceway']}"
            items.append(f"{name} ({', '.join(dict.fromkeys(grids))})" if grids else name)
    key = _nodes_key(bearing)
    return (f"no error estimate for {', '.join(unknown)}: contact(s) "
            f"{'; '.join(items[:4])}{' ...' if len(items) > 4 else ''} have none. A contact's "
            "estimate compares its solution with the same solve on the grids of every other "
            "node (twice and four times the spacing); it is missing when the grid of twice "
            f"the spacing did not converge{example}, when the grid cannot be halved (an even "
            "node count, or fewer than 17 nodes per direction) or when a quantity is zero "
            f"on the finest grid; finer contact grids ([mesh] {key}) give estimates")


def thin_film_refinement(scene: Scene, result: Any) -> tuple[Scene, str] | None:
    """The scene to solve again when a ball contact's film is far below the fit, or below
    it without an error estimate; or None.

    A successful point contact whose h_min lies below :data:`FILM_FIT_WARNING_RATIO` times
    Hamrock-Dowson's minimum film, or below that film with no error estimate of h_min
    (piezo-viscous oils only: the fit is one in G = alpha E'), is returned on the grid of
    half the spacing (2 n - 1 nodes per direction), unless that grid exceeds
    :data:`THIN_FILM_REFINE_MAX_NODES` per direction. The second rule catches a film the
    grid does not resolve that the first misses: the 6209 at 500 rpm, outer contact of
    the most loaded ball, h_min 0.55 times the fit on 129^2 (6.7e-8 m, no estimate) and
    1.19e-7 m on 257^2; it set the bearing's h_min and film parameter.

    Parameters
    ----------
    scene : Scene
        A bearing contact's scene.
    result : Result
        Its solution.

    Returns
    -------
    (Scene, str) or None
        The finer scene and why (for
        :func:`~bearing_fem.bearing.contacts.solve_unique`), or None.
    """
    c, lub = scene.contact, scene.lubricant
    if (c.kind != "point" or not result.success
            or lub.effective_piezo * scene.e_prime < FIT_MIN_MATERIALS_PARAMETER):
        return None
    fit, _ = point_films_hamrock_dowson(scene.load.force, c.rx, c.ry, scene.e_prime,
                                        lub.viscosity, scene.kinematics.mean_speed,
                                        lub.effective_piezo)
    h_min = result.quantities.get("h_min")
    finer, nodes = finer_grid(scene, result)
    if h_min is None or max(nodes) > THIN_FILM_REFINE_MAX_NODES:
        return None
    grid = grid_label(grid_nodes(result))
    if h_min < FILM_FIT_WARNING_RATIO * fit:
        return finer, (f"on {grid} its h_min {h_min:.3g} m was below "
                       f"{FILM_FIT_WARNING_RATIO:g} times Hamrock-Dowson's minimum film "
                       f"{fit:.3g} m (a film the grid does not resolve)")
    estimate = (result.error_estimate or {}).get("h_min")
    if h_min < fit and (estimate is None or estimate > THIN_FILM_ESTIMATE):
        told = ("had no error estimate" if estimate is None
                else f"an estimated error of {100 * estimate:.2g} %")
        return finer, (f"on {grid} its h_min {h_min:.3g} m was below Hamrock-Dowson's "
                       f"minimum film {fit:.3g} m and {told}")
    return None


def target_error_refinement(scene: Scene, result: Any,
                            target: float) -> tuple[Scene, None] | None:
    """The scene on the grid of half the spacing when a contact's estimated error exceeds
    ``target``, or None.

    A successful contact whose largest ``error_estimate`` over
    :data:`TARGET_ERROR_QUANTITIES` exceeds ``target`` (or that has no estimate for one of
    them) is returned on 2 n - 1 nodes (per direction), unless that grid exceeds
    :data:`~bearing_fem.contacts.refine.TARGET_ERROR_MAX_POINT_NODES` per direction
    (points) or :data:`~bearing_fem.contacts.refine.TARGET_ERROR_MAX_LINE_NODES`
    (lines).

    Parameters
    ----------
    scene : Scene
    result : Result
    target : float
        ``mesh.target_error`` [-].

    Returns
    -------
    (Scene, None) or None
        The finer scene (no warning: the user asked for it), or None.
    """
    if not result.success or not misses_target(result, target):
        return None
    finer, nodes = finer_grid(scene, result)
    return None if max(np.atleast_1d(nodes)) > target_grid_cap(result) else (finer, None)


def _refinement(bearing: Bearing) -> Callable[[Scene, Any], Any] | None:
    """The ``refine`` of :func:`~bearing_fem.bearing.contacts.solve_unique` for a bearing:
    :func:`thin_film_refinement` for ball contacts (unless ``mesh.refine_thin_films`` is
    false), then :func:`target_error_refinement` when ``mesh.target_error`` is given."""
    ball = bearing.geometry.is_ball and bearing.mesh.refine_thin_films
    target = bearing.mesh.target_error
    if not ball and target is None:
        return None

    def refine(scene: Scene, result: Any):
        again = thin_film_refinement(scene, result) if ball else None
        if again is None and target is not None:
            again = target_error_refinement(scene, result, target)
        return again

    return refine


def _target_error_warning(bearing: Bearing, specs: list[ContactSpec],
                          results: dict[str, Any]) -> list[str]:
    """One warning naming the successful contacts whose estimated errors stay above
    ``mesh.target_error`` on the finest grid they reached."""
    target = bearing.mesh.target_error
    if target is None:
        return []
    above = []
    for spec in specs:
        for key in spec.keys:
            res = results.get(key)
            if res is None or not res.success:
                continue
            if misses_target(res, target):
                worst = max((e for e in target_errors(res) if e is not None), default=None)
                above.append((spec, res, worst))
                break
    if not above:
        return []
    names = ", ".join(f"{s.element} {s.raceway} ({grid_label(grid_nodes(r))}"
                      + (f", {100 * w:.2g} %)" if w is not None else ", no estimate)")
                      for s, r, w in above[:6])
    more = f" (+{len(above) - 6} more)" if len(above) > 6 else ""
    return [f"mesh.target_error = {target:g} is not met by contact(s) {names}{more}: their "
            "largest estimated error of friction_force, heat_power, h_min and h_central "
            "stays above it on the finest grid reached (a grid of half the spacing failed, "
            f"or would exceed {TARGET_ERROR_MAX_POINT_NODES}^2 nodes for points, "
            f"{TARGET_ERROR_MAX_LINE_NODES} for lines)"]


def _solved_again_note(refined: dict[str, dict[str, Any]]) -> str:
    """", n solved again on finer grids" for the bearing's message, or ""."""
    return f", {len(refined)} solved again on finer grids" if refined else ""


def _static_capacity_warning(bearing: Bearing, specs: list[ContactSpec]) -> list[str]:
    """One warning when the largest Hertz pressure of the solved contacts (of their most
    loaded slice, for rollers) exceeds the ISO 76 limit of the bearing's kind
    (:data:`ISO76_BALL_PRESSURE`, :data:`ISO76_ROLLER_PRESSURE`): the loads exceed the
    bearing's basic static load rating C0."""
    ball = bearing.geometry.is_ball
    limit = ISO76_BALL_PRESSURE if ball else ISO76_ROLLER_PRESSURE
    worst = None
    for spec in specs:
        if spec.excluded is not None:
            continue
        for sc in spec.scenes:
            hertz = sc.hertz_scales()
            if hertz is not None and (worst is None or hertz["p_h"] > worst[0]):
                worst = (hertz["p_h"], spec)
    if worst is None or worst[0] <= limit:
        return []
    p_h, spec = worst
    return [f"element {spec.element} {spec.raceway}: the Hertz pressure {p_h / 1e9:.3g} GPa is "
            f"above the {limit / 1e9:g} GPa at which ISO 76 sets the basic static load "
            f"rating C0 of {'ball' if ball else 'roller'} bearings (a permanent raceway "
            "deformation of 1e-4 of the element diameter): the loads exceed the bearing's "
            "static capacity; check operation.radial_load and operation.axial_load (N)"]


def _thin_film_warnings(bearing: Bearing, films: dict[str, Any],
                        elements: list[dict[str, Any]]) -> list[str]:
    """A warning for each ball contact of the most loaded element whose solved h_min lies
    below :data:`FILM_FIT_WARNING_RATIO` times Hamrock-Dowson's minimum film (the fit of
    ``films``, :func:`_films_at_most_loaded`): a sign of a grid too coarse for the
    contact, which the error estimate may not show."""
    if not bearing.geometry.is_ball:
        return []
    out = []
    j = films["element"]
    for raceway in ("inner", "outer"):
        fit = ((films.get(raceway) or {}).get("Hamrock-Dowson") or {}).get("h_min")
        contact = elements[j][raceway]
        if not fit or not contact.get("success"):
            continue
        h_min = contact.get("h_min")
        if h_min is not None and h_min < FILM_FIT_WARNING_RATIO * fit:
            out.append(f"element {j} {raceway}: h_min {h_min:.3g} m is {h_min / fit:.2f} "
                       f"times Hamrock-Dowson's {fit:.3g} m (the solved films lie within "
                       "about 40 % of it where the grid resolves them): the contact grid "
                       f"may not resolve this film; compare with finer [mesh] "
                       f"{_nodes_key(bearing)}")
    return out


def _films_at_most_loaded(bearing: Bearing, specs: list[ContactSpec],
                          dist: LoadDistribution) -> dict[str, Any]:
    """Film formulas at the most loaded element's contacts (the most loaded slice)."""
    j = int(np.argmax(dist.load_inner))
    out: dict[str, Any] = {"element": j}
    for spec in specs:
        if spec.element != j or spec.excluded is not None:
            continue
        k = int(np.argmax([s.load.force for s in spec.scenes]))
        sc = spec.scenes[k]
        kind = "point" if spec.ry is not None else "line"
        out[spec.raceway] = film_formulas(kind, sc.load.force, spec.rx, sc.e_prime,
                                          sc.lubricant.viscosity, spec.entrainment_speed,
                                          sc.lubricant.effective_piezo, ry=spec.ry)
    return out

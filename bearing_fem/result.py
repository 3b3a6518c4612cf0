"""The result of a solve: scipy-style status plus fields and post-processed numbers."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Mapping

import numpy as np

from .errors import SolveError
from .version import VERSION

if TYPE_CHECKING:
    from .scene import Scene


def json_safe(value: Any) -> Any:
    """Plain-Python copy of ``value`` for strict JSON: mappings, lists and numpy arrays
    become dicts and lists, numpy scalars become bool/int/float, and non-finite floats
    become ``None`` (the summaries of contacts, series and bearings are written this way).
    """
    if isinstance(value, Mapping):
        return {str(k): json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(v) for v in value]
    if isinstance(value, np.ndarray):
        return json_safe(value.tolist())
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        v = float(value)
        return v if math.isfinite(v) else None
    return value

#: Units of every dimensional summary key (line-contact values are per metre of length;
#: the scene decides, see :func:`summary_units`).
_UNITS_POINT = {
    "h_min": "m", "h_central": "m", "p_max": "Pa", "h0": "m", "load": "N",
    "load_beyond_domain": "N",
    "friction_force": "N", "friction_force_surface2": "N", "rolling_resistance": "N",
    "sliding_friction": "N", "friction_coefficient": "1", "heat_power": "W",
    "heat_power_couette": "W", "heat_power_poiseuille": "W",
    "heat_power_poiseuille_direct": "W", "heat_power_stabilisation": "W",
    "outlet_position": "m",
    "h_outlet": "m",
    # thermal coupling (bearing_fem.contacts.coupling)
    "contact_temperature": "degC", "contact_temperature_rise": "K",
    "contact_temperature_rise_computed": "K", "contact_temperature_rise_mean": "K",
    "contact_temperature_rise_max": "K", "heat_power_direct": "W",
    "heat_power_direct_poiseuille": "W", "heat_flux_body1": "W", "heat_flux_body2": "W",
    "heat_fraction_body1": "1", "peclet_min": "1", "thermal_iterations": "1",
    "thermal_residual": "K",
    "contact_viscosity": "Pa s", "contact_piezo": "1/Pa", "gmres_iterations": "1",
    "wall_time_s": "s",
    # counts: unit 1, as every dimensionless number
    "newton_iterations": "1", "linear_solves": "1", "dofs": "1",
}
#: Per-metre summary keys of a line contact and the totals over ``contact.length`` that
#: :meth:`Result.summary` adds when the length is given (key, total key, total unit).
LINE_TOTALS = (("load", "load_total", "N"), ("friction_force", "friction_force_total", "N"),
               ("heat_power", "heat_power_total", "W"))


def summary_units(kind: str) -> dict[str, str]:
    """Units of the summary keys of a contact.

    Parameters
    ----------
    kind : {"line", "point"}
        The contact kind (``scene.contact.kind``); line-contact forces and powers are per
        metre of length (N/m, W/m).

    Returns
    -------
    dict
        Summary key -> unit.

    Raises
    ------
    ValueError
        ``kind`` is neither ``"line"`` nor ``"point"`` (it used to give the line units).
    """
    if kind not in ("line", "point"):
        raise ValueError(f"summary_units: kind must be 'line' or 'point', got {kind!r}")
    if kind == "point":
        return dict(_UNITS_POINT)
    per_m = {"N": "N/m", "W": "W/m"}
    units = {k: per_m.get(u, u) for k, u in _UNITS_POINT.items()}
    units.update({total: unit for _, total, unit in LINE_TOTALS})
    return units


def line_totals(summary: Mapping[str, Any], length: float) -> dict[str, float | None]:
    """Totals of a line contact over its length: the per-metre load, friction force and
    heat power times ``length``.

    Parameters
    ----------
    summary : mapping
        Per-metre values [N/m, W/m] under the keys of :data:`LINE_TOTALS` (absent or None
        where undefined).
    length : float
        ``contact.length`` [m].

    Returns
    -------
    dict
        ``load_total`` [N], ``friction_force_total`` [N], ``heat_power_total`` [W] for
        each per-metre key present; None where its value is None.
    """
    return {total: (None if summary[key] is None else float(summary[key]) * length)
            for key, total, _ in LINE_TOTALS if key in summary}


def error_estimate_units(estimate: Mapping[str, Any], prefix: str = "error_estimate"
                         ) -> dict[str, str]:
    """Units of the relative errors of an ``error_estimate`` table: ``"1"`` (a
    dimensionless ratio, as ``friction_coefficient``; so is ``levels``, a count, as every
    count of a summary) for each of its entries that is a number or None, named
    ``prefix.key`` (the run store's column names); the text and table entries have no
    unit."""
    return {f"{prefix}.{k}": "1" for k, v in estimate.items()
            if v is None or (isinstance(v, (int, float)) and not isinstance(v, bool))}


#: Status strings, in the spirit of scipy.optimize.
SUCCESS_STATUSES = ("converged", "linear")


@dataclass
class Result:
    """Outcome of :func:`bearing_fem.solve`. Never raises for non-convergence.

    Attributes
    ----------
    success : bool
    status : str
        ``converged`` (Newton), ``linear`` (solved by linear solves, no Newton),
        ``no_solution`` (proved not to exist), ``max_iterations``, ``stalled``, ``diverged``,
        ``budget_exhausted`` (``solver.iteration_budget`` spent), ``time_limit``.
    message : str
        Human-readable, with numbers.
    scene : Scene
    x, y : ndarray
        Node coordinates [m] (``y`` is None for line contacts).
    pressure : ndarray
        Nodal pressure [Pa] (the last finite iterate when unsuccessful).
    film : ndarray
        Nodal film thickness [m].
    h0 : float
        Rigid offset [m].
    quantities : dict
        Post-processed numbers (see :meth:`summary`).
    history : list of float
        Scaled residual norm after each Newton iteration (all continuation steps).
    newton_iterations : int
    wall_time_s : float
    extra_fields : dict
        Further nodal fields written to the exports, name -> array (names carry units).
    warnings : list of str
        Short sentences on anything the user should know about the numbers (generic
        model defaults, inputs outside the usual physical range, quantities whose
        estimated discretisation error is large); empty when all is well.
    error_estimate : dict or None
        Estimated relative discretisation error of the main quantities (see
        :meth:`summary` and ``docs/accuracy.md``); None where no estimate was made.
    traction_model : str or None
        The shear-stress model of the sliding friction (``eyring-limiting``, ``eyring``,
        ``limiting``, ``newtonian``), None where friction was not computed.
    residual : float or None
        Scaled Newton residual (max norm, dimensionless) of the returned fields on the
        scene's own problem (of a thermal scene: its last isothermal solve, at the contact
        temperature's viscosity); None where the solve does not record it. After a failed
        continuation it differs from ``history[-1]``, the residual of the last step's
        (easier) problem.
    refinement : dict or None
        With ``mesh.target_error``: ``target_error`` [-], ``grids`` (the grids solved,
        coarse to fine, e.g. ``["129x129", "257x257"]``; the result is on the last one
        that succeeded), ``met`` (every estimate within the target), ``newton_iterations``
        and ``wall_time_s`` [s] of all the solves
        (:func:`bearing_fem.contacts.refine.hold_target_error`); None otherwise.
    """

    success: bool
    status: str
    message: str
    scene: Any
    x: np.ndarray
    pressure: np.ndarray
    film: np.ndarray
    h0: float
    y: np.ndarray | None = None
    quantities: dict[str, float] = field(default_factory=dict)
    history: list[float] = field(default_factory=list)
    newton_iterations: int = 0
    linear_solves: int = 0
    wall_time_s: float = 0.0
    continuation: list[tuple[float, str, int]] = field(default_factory=list)
    extra_fields: dict[str, np.ndarray] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    error_estimate: dict[str, Any] | None = None
    traction_model: str | None = None
    residual: float | None = None
    refinement: dict[str, Any] | None = None

    def __repr__(self) -> str:
        return (f"Result(message={self.message!r}, success={self.success}, "
                f"status={self.status!r}, pressure=<array {self.pressure.shape}>, "
                f"film=<array {self.film.shape}>, newton_iterations={self.newton_iterations})")

    @property
    def dofs(self) -> int:
        return int(self.pressure.size)

    def raise_for_status(self) -> "Result":
        """Raise :class:`~bearing_fem.errors.SolveError` unless the solve succeeded."""
        if not self.success:
            raise SolveError(f"{self.status}: {self.message}")
        return self

    def summary(self) -> dict[str, Any]:
        """The result as a flat dict of SI numbers (``docs/api.md`` lists every key).

        A line contact with ``contact.length`` also has the totals over that length
        (:func:`line_totals`). Besides the numbers: ``status``, ``success``, ``message``,
        ``warnings`` (list of str), ``error_estimate`` (dict or None), ``units`` (unit of
        every dimensional key), ``dimensionless`` (Moes/Hamrock groups), ``version`` and
        ``scene``.
        A quantity that is undefined (e.g. a friction coefficient without a positive
        load) is ``None``, never NaN.
        """
        kind = self.scene.contact.kind
        out: dict[str, Any] = {
            "status": self.status,
            "success": bool(self.success),
            "message": self.message,
        }
        out.update({k: number_or_none(v) for k, v in self.quantities.items()})
        if "friction_force" in self.quantities:
            out.setdefault("friction_coefficient", None)
        length = getattr(self.scene.contact, "length", None)
        if kind == "line" and length is not None:
            out.update(line_totals(out, length))
        out["traction_model"] = self.traction_model
        out["h0"] = float(self.h0)
        out["newton_iterations"] = int(self.newton_iterations)
        out["linear_solves"] = int(self.linear_solves)
        out["wall_time_s"] = float(self.wall_time_s)
        out["dofs"] = self.dofs
        out["warnings"] = [str(w) for w in self.warnings]
        out["error_estimate"] = None if self.error_estimate is None else dict(self.error_estimate)
        if self.refinement is not None:
            out["refinement"] = dict(self.refinement)
        out["units"] = {k: u for k, u in summary_units(kind).items() if k in out}
        if out["error_estimate"] is not None:
            out["units"].update(error_estimate_units(out["error_estimate"]))
        if self.refinement is not None:
            out["units"].update({"refinement.target_error": "1",
                                 "refinement.wall_time_s": "s"})
        out["dimensionless"] = dimensionless_groups(
            self.scene, viscosity=self.quantities.get("contact_viscosity"),
            piezo=self.quantities.get("contact_piezo"))
        out["units"].update({f"dimensionless.{k}": "1" for k in out["dimensionless"]})
        out["version"] = VERSION
        out["scene"] = self.scene.to_dict()
        return out


def number_or_none(value: Any) -> Any:
    """A float (an integer count stays an int), a string label as it is, or None for a
    missing or non-finite number."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        return int(value)
    v = float(value)
    return v if np.isfinite(v) else None


def dimensionless_groups(scene: Scene, *, viscosity: float | None = None,
                         piezo: float | None = None) -> dict[str, float]:
    """Moes/Hamrock groups of a loaded elastic scene (empty where not defined).

    Parameters
    ----------
    scene : Scene
    viscosity : float, optional
        eta0 [Pa s] of the groups; default ``lubricant.viscosity``. A thermal scene's
        result passes its ``contact_viscosity`` (the eta0 it was solved with at the
        contact temperature): its ``lubricant.viscosity`` is the value at the reference
        temperature, or unused when ``thermal.reference_viscosity`` is given.
    piezo : float, optional
        alpha [1/Pa] of the groups; default the scene's effective alpha (a thermal
        result passes its ``contact_piezo``); 0 for the ``constant`` law either way.

    Returns
    -------
    dict
        The dimensionless groups [-] that :func:`bearing_fem.units.moes_line` (line) or
        :func:`bearing_fem.units.moes_point` (point) define among Moes ``M``, ``L`` and
        the Hamrock-Dowson ``W``, ``U``, ``G``. Empty without a load or an elastic
        modulus (rigid scenes, a prescribed gap).
    """
    from . import units

    if scene.load.force is None or scene.e_prime is None:
        return {}
    lub, kin = scene.lubricant, scene.kinematics
    eta0 = lub.viscosity if viscosity is None else float(viscosity)
    alpha = (lub.effective_piezo if piezo is None or lub.viscosity_law == "constant"
             else float(piezo))
    if scene.contact.kind == "line":
        g = units.moes_line(scene.load.force, scene.contact.rx, scene.e_prime,
                            eta0, kin.mean_speed, alpha)
    else:
        g = units.moes_point(scene.load.force, scene.contact.rx, scene.contact.ry,
                             scene.e_prime, eta0, kin.mean_speed, alpha)
    return {k: float(g[k]) for k in ("M", "L", "W", "U", "G") if k in g}

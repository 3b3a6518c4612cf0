"""``solve(scene)``: route a scene to the cheapest correct path and run it.

Paths (a scene pays only for what it needs):

* rigid, incompressible, prescribed gap, constant or Barus viscosity (or Roelands with
  Reynolds cavitation): the **linear** path (:mod:`bearing_fem.contacts.linear`): the
  reduced pressure (Kapitsa's for Barus), one sparse solve or an active-set sequence,
  and the explicit status ``no_solution`` beyond the existence limit (alpha q_max < 1
  for Barus, q_max < q_inf for Roelands);
* everything else: **damped Newton** by the shared driver
  (:mod:`bearing_fem.contacts.driver`) on the line (:mod:`~bearing_fem.contacts.line`)
  or point (:mod:`~bearing_fem.contacts.point`) discretisation, elastic point scenes
  with a prescribed gap by :mod:`~bearing_fem.contacts.transient`;
* ``model.thermal = "patch"``: the thermal fixed point of
  :mod:`bearing_fem.contacts.coupling` around isothermal line solves. Only thermal
  scenes import it.

Floating-point warnings of intermediate iterates never reach the user: they are
silenced during the solve and logged at debug level; a failure is a status and a
message, never a warning. Inputs outside the range the package knows to be plausible
(:func:`bearing_fem.checks.input_warnings`) head the result's ``warnings``.
"""
from __future__ import annotations

import logging
import warnings
from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from ..checks import input_warnings, thick_film_warning
from ..errors import SceneError
from ..result import Result
from ..scene import Scene
from ..validation import require_finite, shown

if TYPE_CHECKING:  # the series modules are imported by the series path only
    from .series import SqueezeSeries

log = logging.getLogger(__name__)


def solve(scene: Scene, *, boundary_pressure: tuple[float, float] | None = None,
          progress: Callable[[dict[str, Any]], None] | None = None) -> Result:
    """Solve a contact scene.

    Parameters
    ----------
    scene : Scene
    boundary_pressure : (float, float), optional
        Dirichlet pressures at the inlet and outlet ends of a line domain [Pa]
        (default 0, 0). Used by the analytic-oracle tests to impose exact data.
    progress : callable, optional
        Called with one dict per event of a Newton solve: ``{"event": "level",
        "level": i, "levels": n, "grid": "257x257"}`` when a grid level starts and
        ``{"event": "newton", "level": i, "iteration": k, "residual": r}`` after each
        Newton iteration (``bearing_fem.contacts.driver.solve_levels``).

    Returns
    -------
    Result
        Never raises for non-convergence or non-existence: see ``result.status``.

    Raises
    ------
    SceneError
        ``scene`` is not a Scene, or asks for something the package does not solve
        (e.g. Dirichlet end pressures of a point contact), or has a ``[transient]``
        section (a squeeze series: :func:`solve_series`).
    """
    if not isinstance(scene, Scene):
        raise SceneError(f"solve() needs a Scene, got {type(scene).__name__}")
    if scene.transient is not None:
        raise SceneError("the scene has a [transient] section (a squeeze series): solve it "
                         "with bearing_fem.solve_series(scene), or remove the section "
                         "(transient=None) for the steady solve at the mean gap load.gap")
    if boundary_pressure is not None and (scene.contact.kind != "line"
                                          or scene.model.thermal != "none"):
        raise SceneError("boundary_pressure (Pa) applies to isothermal line contacts only")
    if boundary_pressure is not None:
        boundary_pressure = _end_pressures(boundary_pressure, scene.model.cavitation)
    with np.errstate(all="ignore"), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = _route(scene, boundary_pressure, progress)
        if scene.mesh.target_error is not None:
            from .refine import hold_target_error

            result = hold_target_error(
                scene, result, lambda finer: _route(finer, boundary_pressure, progress))
    for w in caught:
        log.debug("suppressed during the solve: %s: %s", w.category.__name__, w.message)
    notes = input_warnings(scene)
    if result.success:
        thick = thick_film_warning(scene, result.quantities.get("h_central"))
        notes += [thick] if thick else []
    if notes:
        result.warnings = notes + [w for w in result.warnings if w not in notes]
    return result


def _end_pressures(value: Any, cavitation: str) -> tuple[float, float]:
    """``boundary_pressure`` as two finite floats [Pa] (>= 0 with Reynolds cavitation,
    whose pressure is never below the cavity's, 0), or SceneError naming it."""
    if (not isinstance(value, (tuple, list, np.ndarray)) or len(value) != 2
            or any(isinstance(v, (bool, np.bool_, str, bytes)) for v in value)):
        raise SceneError(f"boundary_pressure must be two pressures (inlet, outlet) in Pa, "
                         f"got {shown(value)}")
    values = require_finite("boundary_pressure", value, "Pa", error=SceneError)
    if np.ndim(values) != 1:
        raise SceneError(f"boundary_pressure must be two pressures (inlet, outlet) in Pa, "
                         f"got {shown(value)}")
    if cavitation == "reynolds" and np.any(values < 0.0):
        raise SceneError(f"boundary_pressure must be >= 0 Pa with model.cavitation = "
                         f"'reynolds' (the cavity pressure is 0), got {shown(value)}")
    return float(values[0]), float(values[1])


def _route(scene: Scene, boundary_pressure, progress) -> Result:
    if scene.model.thermal == "patch":
        from .coupling import solve_thermal  # only thermal scenes import the patch

        return solve_thermal(scene)
    if scene.contact.kind == "point":
        if scene.model.elasticity == "half-space" and scene.load.gap is not None:
            from .transient import solve_elastic_gap

            return solve_elastic_gap(scene, progress=progress)
        from .point import solve_point

        return solve_point(scene, progress=progress)
    from .line import solve_line

    return solve_line(scene, boundary_pressure=boundary_pressure, progress=progress)


def solve_series(scene: Scene, *, progress: Callable[[dict[str, Any]], None] | None = None
                 ) -> SqueezeSeries:
    """Solve the squeeze series of a scene with a ``[transient]`` section.

    h0(t) = h0 (1 + amplitude cos(omega t)) with ``load.gap`` = h0: ``transient.steps``
    steps per period over ``transient.periods`` periods. Rigid scenes are solved instant
    by instant on the linear path (:func:`bearing_fem.contacts.series.solve_squeeze_series`:
    the rigid film has no memory); elastic ones with the time derivative of the film
    (:func:`bearing_fem.contacts.transient.solve_elastic_squeeze_series`, scheme
    ``transient.scheme``).

    Parameters
    ----------
    scene : Scene
        With a ``[transient]`` section (point contact, ``load.gap``).
    progress : callable, optional
        Called with ``{"event": "step", "step": k, "steps": n}`` before each instant is
        reported (elastic series report after the whole series).

    Returns
    -------
    SqueezeSeries or ElasticSqueezeSeries
        ``status``, ``success``, ``message``, ``summary()`` and one Result per instant;
        never raises for a failed instant (the series stops there, with its status).

    Raises
    ------
    SceneError
        The scene has no ``[transient]`` section.
    """
    if not isinstance(scene, Scene):
        raise SceneError(f"solve_series() needs a Scene, got {type(scene).__name__}")
    tr = scene.transient
    if tr is None:
        raise SceneError("solve_series() needs a [transient] section (a squeeze series of a "
                         "point contact with load.gap)")
    with np.errstate(all="ignore"), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        if scene.model.elasticity == "rigid":
            import math

            from .series import solve_squeeze_series

            h0 = scene.load.gap
            omega = tr.angular_frequency or (scene.kinematics.mean_speed
                                             / math.sqrt(2.0 * scene.contact.rx * h0))
            times = np.arange(tr.steps * tr.periods + 1) * (2.0 * math.pi / (omega * tr.steps))
            series = solve_squeeze_series(scene, eps=tr.amplitude, omega=omega, times=times)
        else:
            from .transient import solve_elastic_squeeze_series

            series = solve_elastic_squeeze_series(
                scene, eps=tr.amplitude, omega=tr.angular_frequency, n_steps=tr.steps,
                periods=tr.periods, scheme=tr.scheme)
    for w in caught:
        log.debug("suppressed during the series: %s: %s", w.category.__name__, w.message)
    if progress is not None:
        for k in range(len(series.results)):
            progress({"event": "step", "step": k, "steps": len(series.results)})
    return series

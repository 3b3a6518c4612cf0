"""Per-contact EHL scenes of a bearing and their solution through ``bearing_fem.solve``.

Every loaded element has an inner and an outer contact. A ball contact is one elliptical
point scene (reduced radii from the pitch diameter and the groove conformity, the load
Q in N); a straight roller contact is one line scene per unit length (q = Q / l_we, the
totals multiplied by l_we); a profiled roller contact is one line scene per loaded
slice (q_k = Q_k / w_k, totals multiplied by the slice width w_k). Body 1 is the ring,
body 2 the element; both surfaces move at the entrainment speed (pure rolling).

Scenes that are identical (elements at +psi and -psi of the symmetric load zone, equal
rows, symmetric slices) are solved once: the scene's TOML layout with every number
rounded to 10 significant digits is the key. The public solver API has no initial
guess, so no warm start from a neighbouring element is made.

This module uses only the public API of the contact solver (:class:`bearing_fem.scene.Scene`,
:func:`bearing_fem.solve`) and the temperature laws of :mod:`bearing_fem.contacts.coupling`.
"""
from __future__ import annotations

import json
import logging
import math
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from ..contacts.refine import finer_grid, grid_label, grid_nodes
from ..errors import SceneError
from ..scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec, Model, Scene,
                     Thermal)
from .description import Bearing
from .geometry import contact_geometry
from .kinematics import ElementKinematics
from .loads import LoadDistribution

__all__ = ["ContactSpec", "contact_specs", "lubricant_at_oil_temperature", "scene_key",
           "solve_unique", "KEY_DIGITS"]

log = logging.getLogger(__name__)

#: Significant digits of the numbers in a scene key (identical contacts by symmetry
#: differ by rounding only, ~1e-15 relative).
KEY_DIGITS = 10


@dataclass
class ContactSpec:
    """One contact of one element: its scenes (one, or one per slice) and why not.

    Attributes
    ----------
    element : int
        Element index (all rows: row * Z + j).
    raceway : {"inner", "outer"}
    load : float
        Normal contact load [N].
    contact_angle : float
        [rad].
    entrainment_speed : float
        u_m [m/s].
    rx, ry : float
        Reduced radii [m] (ry None for line contacts).
    race_radius : float
        Raceway radius at the contact, from the bearing axis [m].
    scenes : list of Scene
        Line contacts: one per loaded slice (or one); point: one.
    widths : list of float
        Line contacts: length [m] each scene's per-metre results are multiplied by.
    positions : list of float
        Line contacts: axial position of each scene's slice from the roller middle [m].
    slice_numbers : list of int
        Profiled rollers: the number of each scene's slice, 1 .. ``geometry.n_slices``
        from one roller end (unloaded slices have no scene); [] otherwise.
    keys : list of str
        :func:`scene_key` of each scene.
    excluded : str or None
        Why the contact is not solved (no load, below ``model.min_load_fraction``).
    """

    element: int
    raceway: str
    load: float
    contact_angle: float
    entrainment_speed: float
    rx: float
    ry: float | None
    race_radius: float
    scenes: list[Scene] = field(default_factory=list)
    widths: list[float] = field(default_factory=list)
    positions: list[float] = field(default_factory=list)
    slice_numbers: list[int] = field(default_factory=list)
    keys: list[str] = field(default_factory=list)
    excluded: str | None = None


def _helper_scene(bearing: Bearing) -> Scene:
    """A minimal line scene carrying the bearing's temperature law (for its evaluation)."""
    lub = bearing.lubricant
    t = bearing.operation.oil_temperature
    return Scene(contact=Contact(kind="line", rx=0.01),
                 materials=Materials(reduced_modulus=2.0e11),
                 lubricant=Lubricant(viscosity=lub.reference_viscosity, piezo=lub.piezo),
                 kinematics=Kinematics(u1=1.0, u2=1.0), load=Load(force=1.0e5),
                 model=Model(thermal="patch"), thermal=_thermal_section(bearing, t))


def _thermal_section(bearing: Bearing, t_oil: float) -> Thermal:
    lub, th = bearing.lubricant, bearing.thermal
    return Thermal(oil_temperature=t_oil, exponent=lub.exponent,
                   reference_temperature=lub.reference_temperature,
                   reference_viscosity=lub.reference_viscosity,
                   piezo_temperatures=lub.piezo_temperatures, piezo_values=lub.piezo_values,
                   conductivity=th.conductivity, density=th.density,
                   heat_capacity=th.heat_capacity, source_model=th.source_model,
                   contact_temperature=th.contact_temperature,
                   max_iterations=th.max_iterations, tolerance=th.tolerance,
                   relaxation=th.relaxation)


def lubricant_at_oil_temperature(bearing: Bearing) -> tuple[float, float]:
    """(eta0 [Pa s], alpha [1/Pa]) at ``operation.oil_temperature``.

    ``temperature_law = "none"``: ``lubricant.viscosity`` and ``lubricant.piezo``. Else
    the Prokofiev law and the ln-linear alpha(t) table, evaluated by
    :func:`bearing_fem.contacts.coupling.contact_viscosity` and
    :func:`~bearing_fem.contacts.coupling.contact_piezo` (the thermal scenes use the same laws).
    """
    lub = bearing.lubricant
    if lub.temperature_law == "none":
        return float(lub.viscosity), float(lub.piezo)
    from ..contacts.coupling import contact_piezo, contact_viscosity

    scene = _helper_scene(bearing)
    t = bearing.operation.oil_temperature
    return contact_viscosity(scene, t), contact_piezo(scene, t)


def scene_key(scene: Scene) -> str:
    """Canonical text of a scene (numbers to :data:`KEY_DIGITS` digits): equal keys,
    equal solves."""
    def canon(v: Any) -> Any:
        if isinstance(v, dict):
            return {k: canon(x) for k, x in sorted(v.items()) if k != "title"}
        if isinstance(v, (list, tuple)):
            return [canon(x) for x in v]
        if isinstance(v, float):
            return float(f"{v:.{KEY_DIGITS}g}")
        return v

    return json.dumps(canon(scene.to_dict()), sort_keys=True)


def _scene(bearing: Bearing, kind: str, rx: float, ry: float | None, length: float | None,
           force: float, speed: float, eta: float, alpha: float, title: str) -> Scene:
    b = bearing
    e1, nu1 = b.materials.ring
    e2, nu2 = b.materials.element
    mesh = b.mesh
    nodes = mesh.point_nodes if kind == "point" else mesh.line_nodes
    thermal = None
    if b.model.thermal == "patch":
        thermal = _thermal_section(b, b.operation.oil_temperature)
    return Scene(title=title,
                 contact=Contact(kind=kind, rx=rx, ry=ry, length=length),
                 materials=Materials(e1=e1, nu1=nu1, e2=e2, nu2=nu2),
                 lubricant=Lubricant(viscosity=eta, piezo=alpha,
                                     viscosity_law=b.lubricant.viscosity_law,
                                     density=b.lubricant.compressibility),
                 kinematics=Kinematics(u1=speed, u2=speed), load=Load(force=force),
                 model=Model(elasticity=b.model.elasticity, cavitation="reynolds",
                             thermal=b.model.thermal),
                 mesh=MeshSpec(nodes=nodes, x_range=mesh.x_range,
                               y_range=mesh.y_range if kind == "point" else None,
                               grading=mesh.line_grading if kind == "line" else None),
                 solver=b.solver, thermal=thermal, traction=b.traction)


def _add_scenes(spec: ContactSpec, bearing: Bearing, dist: LoadDistribution, j: int,
                q: float, rx: float, ry: float | None, u: float, eta: float, alpha: float,
                title: str, threshold: float) -> None:
    """The contact scenes of one loaded element and raceway (a ball: one point contact;
    a straight roller: one line contact; a profiled roller: one per loaded slice)."""
    g = bearing.geometry
    if g.is_ball:
        spec.scenes = [_scene(bearing, "point", rx, ry, None, q, u, eta, alpha, title)]
    elif dist.slice_loads is None:
        lw = g.effective_length
        spec.scenes = [_scene(bearing, "line", rx, None, lw, q / lw, u, eta, alpha, title)]
        spec.widths, spec.positions = [lw], [0.0]
    else:
        loads = dist.slice_loads[j] * (q / max(float(dist.load_inner[j]), 1e-300))
        for k, (qk, wk, yk) in enumerate(zip(loads, dist.slice_widths, dist.slice_positions)):
            if qk <= threshold / g.n_slices:
                continue
            spec.scenes.append(_scene(bearing, "line", rx, None, float(wk), float(qk / wk),
                                      u, eta, alpha, f"{title}, slice {k + 1} of {g.n_slices}"))
            spec.widths.append(float(wk))
            spec.positions.append(float(yk))
            spec.slice_numbers.append(k + 1)


def _in_bearing_terms(bearing: Bearing, spec: ContactSpec, exc: SceneError) -> str:
    """A contact scene's refusal restated with the bearing-file fields that caused it:
    the contact scene's fields (kinematics.u1, load.force, ...) are not in the user's
    file."""
    op = bearing.operation
    where = f"element {spec.element}'s {spec.raceway} contact"
    text = str(exc)
    if text.startswith("kinematics"):
        cause = (f"operation.inner_rpm = {op.inner_rpm!r} 1/min gives {where} an "
                 f"entrainment speed of {spec.entrainment_speed:.4g} m/s")
    elif text.startswith("load"):
        cause = (f"operation.radial_load = {op.radial_load!r} N and operation.axial_load = "
                 f"{op.axial_load!r} N give {where} a load of {spec.load:.4g} N")
    else:
        cause = f"the bearing file gives {where} (load {spec.load:.4g} N)"
    return f"{cause}, which its contact model refuses: {text}"


def contact_specs(bearing: Bearing, dist: LoadDistribution,
                  kin: ElementKinematics) -> list[ContactSpec]:
    """The inner and outer contact of every element, with their scenes (or exclusion).

    Parameters
    ----------
    bearing : Bearing
    dist : LoadDistribution
    kin : ElementKinematics
        At the contact angles of ``dist``.

    Returns
    -------
    list of ContactSpec
        Two per element, inner first.
    """
    g = bearing.geometry
    eta, alpha = lubricant_at_oil_temperature(bearing)
    cg = contact_geometry(bearing, dist.alpha_inner, dist.alpha_outer)
    q_ref = max(float(np.max(dist.load_inner)), float(np.max(dist.load_outer)))
    threshold = bearing.model.min_load_fraction * q_ref
    specs: list[ContactSpec] = []
    for j in range(dist.azimuth.size):
        for race in ("inner", "outer"):
            q = float(dist.load_inner[j] if race == "inner" else dist.load_outer[j])
            a = float(dist.alpha_inner[j] if race == "inner" else dist.alpha_outer[j])
            rx = float((cg.rx_inner if race == "inner" else cg.rx_outer)[j])
            ry = cg.ry_inner if race == "inner" else cg.ry_outer
            rr = float((cg.race_radius_inner if race == "inner" else cg.race_radius_outer)[j])
            u = float(kin.entrainment_speed[j])
            spec = ContactSpec(element=j, raceway=race, load=q, contact_angle=a,
                               entrainment_speed=u, rx=rx, ry=ry, race_radius=rr)
            psi = math.degrees(float(dist.azimuth[j]))
            title = f"element {j} {race} (psi = {psi:.1f} deg)"
            if q <= 0.0:
                spec.excluded = ("no load: outside the load zone (element approach "
                                 f"{float(dist.approach[j]):.3e} m <= 0); the drag of an "
                                 "unloaded element is not modelled")
            elif q < threshold:
                spec.excluded = (f"load {q:.4g} N below model.min_load_fraction x Q_max = "
                                 f"{threshold:.4g} N (edge of the load zone; its contribution "
                                 "is below that fraction)")
            else:
                try:
                    _add_scenes(spec, bearing, dist, j, q, rx, ry, u, eta, alpha, title,
                                threshold)
                except SceneError as exc:
                    raise SceneError(_in_bearing_terms(bearing, spec, exc)) from None
            spec.keys = [scene_key(s) for s in spec.scenes]
            specs.append(spec)
    return specs


def solve_unique(specs: list[ContactSpec],
                 progress: Callable[[int, int, str], None] | None = None,
                 blas_threads: int | None = 1,
                 refine: Callable[[Scene, Any], tuple[Scene, str | None] | None] | None = None,
                 refined: dict[str, dict[str, Any]] | None = None) -> dict[str, Any]:
    """Solve every distinct scene of ``specs`` once with :func:`bearing_fem.solve`.

    Parameters
    ----------
    specs : list of ContactSpec
    progress : callable, optional
        ``progress(done, total, title)`` after each solve.
    refine : callable, optional
        ``refine(scene, result)`` after each solve: None, or a scene to solve instead (a
        finer grid) and why, a clause such as "its h_min ... was below ..." for the
        result's warnings (None: no warning). Its result replaces the last when it
        succeeds, and ``refine`` is asked again about it; a failed solve ends the
        refinement with a warning on the last result.
    refined : dict, optional
        Filled with scene key -> ``{"nodes": the first grid's nodes (:func:`grid_nodes`),
        "h_min": its h_min [m]}`` for each scene solved again successfully.
    blas_threads : int or None
        BLAS threads during the contact solves (threadpoolctl); None: leave as is. One
        thread by default: the dense line-contact Jacobians are small, and on a shared
        2-core machine multi-threaded BLAS made an 801-node solve 10-20x slower
        (measured: 7-15 s vs 0.6-1.3 s per contact of the NNCF 5040 example).

    Returns
    -------
    dict
        scene key -> :class:`~bearing_fem.result.Result`.
    """
    from contextlib import nullcontext

    from threadpoolctl import threadpool_limits

    from .. import solve

    unique: dict[str, Scene] = {}
    for spec in specs:
        for key, scene in zip(spec.keys, spec.scenes):
            unique.setdefault(key, scene)
    # most loaded first: the contact that matters most is solved even if a run is cut short
    order = sorted(unique, key=lambda k: -unique[k].load.force)
    results: dict[str, Any] = {}
    limit = nullcontext() if blas_threads is None else \
        threadpool_limits(limits=int(blas_threads), user_api="blas")
    with limit:
        for i, key in enumerate(order):
            scene = unique[key]
            res = solve(scene)
            first = res
            again = refine(scene, res) if refine is not None else None
            while again is not None:
                finer, why = again
                res, solved = _solved_again(solve, finer, why, res)
                if not solved:  # the finer grid failed: the last success stays
                    break
                again = refine(finer, res)
            if res is not first and refined is not None:
                refined[key] = {"nodes": grid_nodes(first),
                                "h_min": first.quantities.get("h_min")}
            results[key] = res
            log.info("contact %d/%d (%s): %s in %.2f s", i + 1, len(order), scene.title,
                     res.status, res.wall_time_s)
            if progress is not None:
                progress(i + 1, len(order), scene.title)
    return results


def _solved_again(solve: Callable[[Scene], Any], finer: Scene, why: str | None,
                  last: Any) -> tuple[Any, bool]:
    """(the solution of ``finer``, True), with a warning that says why it was solved (none
    when ``why`` is None), or (``last``, False) with a warning that the solve failed."""
    nodes = grid_label(finer.mesh.nodes)
    res = solve(finer)
    if res.success:
        if why is not None:
            res.warnings.append(f"solved again on {nodes} nodes: {why}; the results are "
                                f"those on {nodes} (h_min {res.quantities['h_min']:.3g} m)")
        return res, True
    last.warnings.append(f"{why or 'a finer grid was asked for'}, and a solve on {nodes} "
                         f"nodes did not succeed ({res.status}); the results are those on "
                         f"{grid_label(grid_nodes(last))}")
    return last, False

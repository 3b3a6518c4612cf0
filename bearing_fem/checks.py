"""Plausibility of a scene's inputs: short warnings for values outside the physical range.

:func:`input_warnings` looks at a validated :class:`~bearing_fem.scene.Scene` and returns
one short sentence per input that lies outside the range the package knows of for
rolling-bearing contacts: values that can be computed (validation rejects those that
cannot) but are most likely a unit slip or outside the models' assumptions. The solve
puts the sentences into ``Result.warnings``. Every threshold is a module constant,
documented with its reason in ``docs/scenes.md`` ("Plausibility warnings").

Pure: no I/O, no logging; the Hertz scales come from :meth:`Scene.hertz_scales`.
"""
from __future__ import annotations

from typing import Callable

from .physics.traction import GENERIC_MINERAL_OIL
from .scene import Scene

__all__ = ["input_warnings", "VISCOSITY_HIGH", "VISCOSITY_LOW", "E_PRIME_LOW",
           "ALPHA_PH_HIGH", "HERTZ_PRESSURE_HIGH", "LINE_PRESSURE_LOW", "HARD_E_PRIME",
           "HERTZ_RATIO_HIGH", "GAP_RATIO_HIGH", "OIL_TEMPERATURE_HIGH", "OIL_DENSITY",
           "HYDRODYNAMIC_RANGE_LOW", "TRACTION_PARAMETERS", "thick_film_warning"]

#: Viscosity above which no lubricating oil runs at its working temperature [Pa s]
#: (an ISO VG 1500 gear oil at 40 deg C is about 1.3 Pa s).
VISCOSITY_HIGH = 5.0
#: Viscosity below which no liquid lubricant lies [Pa s] (water is 1e-3 Pa s at 20 deg C,
#: light kerosene about 1e-3; 1e-4 Pa s is a light gas-like fluid).
VISCOSITY_LOW = 1e-4
#: Reduced modulus below which the bodies are not bearing materials [Pa] (steel on steel
#: 2.3e11, silicon nitride on steel 2.9e11, engineering polymers a few 1e9).
E_PRIME_LOW = 1e9
#: alpha p_h above which the pressure-viscosity response lies beyond any measured
#: lubricant [-] (mineral oils in bearings: 10..60; exp(100) = 2.7e43).
ALPHA_PH_HIGH = 100.0
#: Hertz pressure above which bearing steel yields [Pa] (ISO 76 static ratings allow
#: 4.0 GPa for roller and 4.2 GPa for ball bearings).
HERTZ_PRESSURE_HIGH = 5e9
#: Hertz pressure of a line contact between hard bodies below which the line load looks
#: like a force in N rather than N per metre of length [Pa] (loaded roller contacts run
#: at 0.5..2.5 GPa; 1e4 N/m on a 10 mm steel radius gives 0.19 GPa, 1200 N/m 66 MPa).
LINE_PRESSURE_LOW = 1e8
#: Reduced modulus from which the bodies count as hard (metals, ceramics) [Pa].
HARD_E_PRIME = 5e10
#: Hertz semi-axis over its reduced radius above which Hertz theory (a contact small
#: against the radii) is strained [-]; validation rejects 0.5.
HERTZ_RATIO_HIGH = 0.1
#: Prescribed gap over rx above which the film is not thin against the radius [-]
#: (the Reynolds equation assumes h << rx).
GAP_RATIO_HIGH = 1e-2
#: Width of a domain in hydrodynamic lengths sqrt(2 r h0) (the unit of ``mesh.x_range``
#: and ``y_range`` in rigid and prescribed-gap scenes) below which it cannot hold the
#: film's pressure, which builds over several (default [-100, 5]) [-]: mostly a range
#: given in metres ([-0.001, 0.0005] on a 10 mm roller at 1 um carried 5e-9 N/m).
HYDRODYNAMIC_RANGE_LOW = 1.0
#: The ``[traction]`` parameters each model uses (the others it ignores).
TRACTION_PARAMETERS = {
    "eyring-limiting": ("eyring_stress", "limiting_shear_stress", "limiting_slope"),
    "eyring": ("eyring_stress",), "limiting": ("limiting_shear_stress", "limiting_slope"),
    "newtonian": ()}
_TRACTION_UNITS = {"eyring_stress": " Pa", "limiting_shear_stress": " Pa", "limiting_slope": ""}
#: Oil temperature above which mineral oils oxidise and degrade quickly [deg C].
OIL_TEMPERATURE_HIGH = 150.0
#: Density of a mineral oil [kg/m^3], used only to suggest a dynamic viscosity when a
#: kinematic one seems to have been given.
OIL_DENSITY = 870.0


def input_warnings(scene: Scene) -> list[str]:
    """Short sentences on inputs outside the physical range the package knows of.

    Parameters
    ----------
    scene : Scene
        A validated scene.

    Returns
    -------
    list of str
        One sentence per finding, in a fixed order (viscosity, moduli, Hertz pressure,
        pressure-viscosity, contact size, gap, elastic line gap, domain, traction,
        temperature); empty when all is well.
    """
    hertz = scene.hertz_scales()
    checks: list[Callable[[], str | None]] = [
        lambda: (None if scene.thermal is not None
                 and scene.thermal.reference_viscosity is not None   # then unused
                 else _viscosity("lubricant.viscosity", scene.lubricant.viscosity)),
        lambda: (None if scene.thermal is None or scene.thermal.reference_viscosity is None
                 else _viscosity("thermal.reference_viscosity",
                                 scene.thermal.reference_viscosity)),
        lambda: _soft_bodies(scene),
        lambda: _high_pressure(hertz),
        lambda: _light_line_load(scene, hertz),
        lambda: _piezo_viscous(scene, hertz),
        lambda: _large_contact(hertz),
        lambda: _thick_gap(scene),
        lambda: _elastic_line_gap(scene),
        lambda: _narrow_hydrodynamic_range(scene),
        lambda: _unused_traction(scene),
        lambda: _hot_oil(scene),
    ]
    return [text for text in (check() for check in checks) if text]


# ---------------------------------------------------------------------------------------
def _viscosity(field: str, eta: float) -> str | None:
    if eta > VISCOSITY_HIGH:
        text = (f"{field} = {eta:.4g} Pa s is above {VISCOSITY_HIGH:g} Pa s, thicker than "
                "lubricating oils at their working temperature")
        if VISCOSITY_LOW <= eta / 1000.0 <= VISCOSITY_HIGH:
            text += f"; did you mean {eta / 1000.0:.4g} Pa s (cP given as Pa s)?"
        return text
    if eta < VISCOSITY_LOW:
        text = (f"{field} = {eta:.4g} Pa s is below {VISCOSITY_LOW:g} Pa s, thinner than "
                "any liquid lubricant (water has 1e-3 Pa s)")
        if eta * 1e6 >= 1.0:  # at least 1 cSt if read as m^2/s
            text += (f"; did you give a kinematic viscosity ({eta:.4g} m^2/s = "
                     f"{eta * 1e6:.4g} cSt)? "
                     f"The dynamic viscosity is that times the density, e.g. "
                     f"{eta * OIL_DENSITY:.4g} Pa s at {OIL_DENSITY:g} kg/m^3")
        return text
    return None


def _soft_bodies(scene: Scene) -> str | None:
    e_prime = scene.e_prime
    if e_prime is None or e_prime >= E_PRIME_LOW:
        return None
    return (f"the reduced modulus E' = {e_prime:.4g} Pa is below {E_PRIME_LOW:g} Pa, softer "
            "than bearing materials (steel on steel 2.3e11 Pa): a soft contact, or moduli "
            "given in MPa or GPa as Pa?")


def _high_pressure(hertz: dict | None) -> str | None:
    if hertz is None or hertz["p_h"] <= HERTZ_PRESSURE_HIGH:
        return None
    return (f"the Hertz pressure {hertz['p_h']:.4g} Pa is above {HERTZ_PRESSURE_HIGH:g} Pa, "
            "beyond the static capacity of bearing steel (ISO 76: 4.0-4.2 GPa): the bodies "
            "would yield; check the load and its unit")


def _light_line_load(scene: Scene, hertz: dict | None) -> str | None:
    if (hertz is None or scene.contact.kind != "line" or scene.e_prime < HARD_E_PRIME
            or hertz["p_h"] >= LINE_PRESSURE_LOW):
        return None
    w, length = scene.load.force, scene.contact.length
    hint = (f"if {w:.4g} N is the force on the roller, give {w / length:.4g} N/m "
            f"(force / contact.length)" if length else
            "if it is the force on the roller in N, divide it by the contact length in m")
    return (f"load.force = {w:.4g} N/m gives a Hertz pressure of only {hertz['p_h']:.3g} Pa "
            f"(< {LINE_PRESSURE_LOW:g} Pa) between hard bodies; a line load is per metre of "
            f"length: {hint}")


def _piezo_viscous(scene: Scene, hertz: dict | None) -> str | None:
    lub = scene.lubricant
    if hertz is None or lub.effective_piezo == 0.0:
        return None
    exponent = lub.effective_piezo * hertz["p_h"]
    if exponent <= ALPHA_PH_HIGH:
        return None
    return (f"alpha p_h = {exponent:.4g} is above {ALPHA_PH_HIGH:g} (lubricant.piezo = "
            f"{lub.piezo:.4g} 1/Pa at the Hertz pressure {hertz['p_h']:.4g} Pa): a "
            "pressure-viscosity response beyond any measured lubricant; check the piezo "
            "coefficient and the load")


def _large_contact(hertz: dict | None) -> str | None:
    if hertz is None:
        return None
    for what, width, radius_name, radius in hertz["widths"]:
        if width > HERTZ_RATIO_HIGH * radius:
            return (f"the {what} = {width:.4g} m is {width / radius:.3g} x {radius_name}: "
                    f"Hertz theory and the half-space model assume a contact small against "
                    f"the radii (below {HERTZ_RATIO_HIGH:g})")
    return None


def _thick_gap(scene: Scene) -> str | None:
    gap, rx = scene.load.gap, scene.contact.rx
    if gap is None or gap <= GAP_RATIO_HIGH * rx:
        return None
    return (f"load.gap = {gap:.4g} m is {gap / rx:.3g} x contact.rx: the Reynolds equation "
            f"assumes a film much thinner than the radius (below {GAP_RATIO_HIGH:g})")


def thick_film_warning(scene: Scene, h_central: float | None) -> str | None:
    """The solved counterpart of the thick-gap check: a sentence when the central film of
    a solve under a load exceeds :data:`GAP_RATIO_HIGH` times ``contact.rx`` (the Reynolds
    equation and the parabolic gap assume a film much thinner than the radius), else None.

    Parameters
    ----------
    scene : Scene
        The solved scene (a prescribed gap is left to :func:`input_warnings`).
    h_central : float or None
        The solved central film [m].

    Returns
    -------
    str or None
    """
    rx = scene.contact.rx
    if scene.load.force is None or h_central is None or not h_central > GAP_RATIO_HIGH * rx:
        return None
    return (f"the central film {h_central:.4g} m is {h_central / rx:.3g} x contact.rx: the "
            "Reynolds equation and the parabolic gap assume a film much thinner than the "
            f"radius (below {GAP_RATIO_HIGH:g}); check the viscosity, speed and load and "
            "their units")


def _elastic_line_gap(scene: Scene) -> str | None:
    gap = scene.load.gap
    if gap is None or scene.contact.kind != "line" or scene.model.elasticity != "half-space":
        return None
    return (f"load.gap = {gap:.4g} m on an elastic (half-space) line contact: the "
            "plane-strain displacement has no absolute datum (ln|x - s| with x in metres), "
            "so the film at a given gap depends on that convention and h_central - gap is "
            "no physical approach; give load.force for a physical solve")


def _narrow_hydrodynamic_range(scene: Scene) -> str | None:
    mesh = scene.mesh
    if scene.load.gap is None and scene.model.elasticity != "rigid":
        return None   # elastic under load: ranges in Hertz half-widths, checked when built
    for name, r, radius in (("x_range", mesh.x_range, "rx"), ("y_range", mesh.y_range, "ry")):
        if r is not None and r[1] - r[0] < HYDRODYNAMIC_RANGE_LOW:
            return (f"mesh.{name} = [{r[0]:g}, {r[1]:g}] spans {r[1] - r[0]:.3g} hydrodynamic "
                    f"lengths sqrt(2 {radius} h0), the unit of ranges in rigid and "
                    f"prescribed-gap scenes: too narrow for the film's pressure, which "
                    f"builds over several (default x in [-100, 5]); was it given in metres?")
    return None


def _unused_traction(scene: Scene) -> str | None:
    tr = scene.traction
    if tr is None:
        return None
    unused = [f"traction.{name} = {getattr(tr, name):g}{_TRACTION_UNITS[name]}"
              for name in _TRACTION_UNITS if name not in TRACTION_PARAMETERS[tr.model]
              and getattr(tr, name) != GENERIC_MINERAL_OIL[name]]
    if not unused:
        return None
    used = ", ".join(TRACTION_PARAMETERS[tr.model]) or "none of the parameters"
    verb = "is" if len(unused) == 1 else "are"
    return (f"{', '.join(unused)} {verb} not used by traction.model = {tr.model!r} (it uses "
            f"{used}); for an Eyring or limiting stress choose a model that has it")


def _hot_oil(scene: Scene) -> str | None:
    th = scene.thermal
    if th is None or th.oil_temperature <= OIL_TEMPERATURE_HIGH:
        return None
    return (f"thermal.oil_temperature = {th.oil_temperature:.4g} deg C is above "
            f"{OIL_TEMPERATURE_HIGH:g} deg C, where mineral oils oxidise and degrade")

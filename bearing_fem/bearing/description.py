"""Bearing descriptions: frozen, keyword-only, SI dataclasses, validated when built.

A bearing file is TOML with a top-level ``[bearing]`` table (the internal geometry; a
contact scene file has ``[contact]`` instead) and the sections ``[materials]``,
``[lubricant]``, ``[operation]`` (required), ``[model]``, ``[mesh]``, ``[solver]``,
``[traction]``, ``[thermal]`` and ``[empirical]`` (optional). Every key, its unit and
its default are listed in ``docs/bearing.md``. Every invalid value raises
:class:`~bearing_fem.errors.SceneError` naming the field, the value and the unit; an
unknown key lists the known ones.

Units: lengths in m, forces in N, moduli in Pa, viscosity in Pa s, speeds in 1/min
(``inner_rpm``), angles in degrees (``contact_angle``, ``first_element_azimuth``) and
temperatures in deg C (the Prokofiev law of Yachikov & Vostrikov 2015 is written in them).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Literal, Mapping

from ..errors import SceneError
from ..scene import (FORCE_RANGE, GRADINGS, TEMPERATURE_RANGE, VISCOSITY_RANGE, SolverSpec,
                     Traction, field_bool, field_bounded, field_choice, field_integer,
                     field_name_prefix, field_nonnegative, field_number, field_piezo,
                     field_piezo_table, field_poisson, field_positive, field_range,
                     field_target_error, parse_toml, read_text_file, sections_from_dict,
                     sections_to_dict)

__all__ = ["Bearing", "Geometry", "BearingMaterials", "BearingLubricant", "Operation",
           "BearingModel", "BearingMesh", "BearingThermal", "EmpiricalOptions",
           "BEARING_TYPES", "MATERIAL_PRESETS", "load_example", "example_names",
           "input_warnings", "kelvin_like_temperatures", "iso76_static_load_rating"]

#: Bearing types: radial deep-groove and angular-contact ball bearings (one row),
#: cylindrical roller bearings (any number of rows) and tapered roller bearings
#: (simplified: both raceways at one contact angle, rib contact neglected).
BEARING_TYPES = ("deep-groove-ball", "angular-contact-ball", "cylindrical-roller",
                 "tapered-roller")
BALL_TYPES = ("deep-groove-ball", "angular-contact-ball")
ROLLER_TYPES = ("cylindrical-roller", "tapered-roller")
#: Types with a nominal contact angle (``bearing.contact_angle``, required).
ANGULAR_TYPES = ("angular-contact-ball", "tapered-roller")

#: Accepted oil properties of ``[lubricant]`` (the empirical models' kinematic viscosity
#: and Nikitin's criteria): density [kg/m^3] (oils 700..2000: mineral about 870,
#: perfluoropolyethers 1900), thermal conductivity [W/(m K)] (0.1..0.2) and specific heat
#: [J/(kg K)] (1700..2500), with margins for water-based fluids; outside them a value is a
#: unit slip (g/cm^3, kJ/(kg K)) and is refused, naming the field.
OIL_DENSITY_RANGE = (100.0, 5000.0)
OIL_CONDUCTIVITY_RANGE = (0.01, 10.0)
OIL_SPECIFIC_HEAT_RANGE = (100.0, 1e4)
#: Material presets: name -> (Young's modulus [Pa], Poisson ratio [-], density [kg/m^3]).
#: Bearing steel (AISI 52100) and hot-isostatically pressed silicon nitride (Si3N4).
MATERIAL_PRESETS: dict[str, tuple[float, float, float]] = {
    "steel": (2.08e11, 0.30, 7850.0),
    "si3n4": (3.10e11, 0.26, 3200.0),
}

#: Geometry constants (R1, R2, S1, S2) of the SKF model for deep groove ball bearing
#: series, transcribed from the SKF catalogue's table of geometry constants for rolling
#: and sliding frictional moments. Series not listed (e.g. full-complement cylindrical
#: and angular-contact spindle bearings) need their constants from the catalogue
#: (``[empirical] skf_r1 ...``). Used by :mod:`~bearing_fem.bearing.empirical`; here
#: because :class:`Bearing` checks ``empirical.skf_series`` against it.
#: Fields of the SKF geometry constants given directly (``[empirical]``).
SKF_CONSTANT_FIELDS = ("skf_r1", "skf_r2", "skf_s1", "skf_s2")
#: The SKF geometry constants each type's model uses (the catalogue lists R1, S1, S2 for
#: cylindrical roller bearings: G_rr = R1 d_m^2.41 Fr^0.31, G_sl = S1 d_m^0.9 Fa +
#: S2 d_m Fr); types not listed have no SKF model here.
SKF_CONSTANTS_USED: dict[str, tuple[str, ...]] = {
    "deep-groove-ball": SKF_CONSTANT_FIELDS,
    "cylindrical-roller": ("skf_r1", "skf_s1", "skf_s2"),
}
SKF_GEOMETRY_CONSTANTS: dict[tuple[str, str], tuple[float, float, float, float]] = {
    ("deep-groove-ball", "60"): (4.1e-7, 1.7, 3.73e-3, 14.6),
    ("deep-groove-ball", "62"): (3.9e-7, 1.7, 3.23e-3, 36.5),
    ("deep-groove-ball", "63"): (3.7e-7, 1.7, 2.84e-3, 92.8),
    ("deep-groove-ball", "64"): (3.6e-7, 1.7, 2.43e-3, 198.0),
}

# ---------------------------------------------------------------------------------------
# validation helpers (besides the scene's field validators, bearing_fem.scene)
# ---------------------------------------------------------------------------------------
def _optional_positive(obj: Any, name: str, unit: str) -> None:
    if getattr(obj, name) is not None:
        field_positive(obj, name, unit)


#: Largest crown drop of a crowned roller as a fraction of its diameter: real drops are
#: micrometres to tens of micrometres (a few 1e-4 D_w); beyond this the value is a unit
#: slip (millimetres, or micrometres given as millimetres).
MAX_CROWN_DROP_FRACTION = 0.01
#: Plausible bearing dimensions [m] (bore, outside, pitch and element diameters, widths
#: and roller lengths): from miniature bearings (0.6 mm bores, 0.3 mm balls) to slewing
#: and tunnel-boring bearings of several metres. Beyond it the value is almost surely in
#: millimetres (a 45 mm bore given as 45).
BEARING_LENGTH_RANGE = (1e-4, 10.0)
#: Largest rolling-element diameter [m]: the balls and rollers of the largest slewing and
#: tunnel-boring bearings are about 0.1-0.2 m; beyond 0.5 m the bearing's dimensions are
#: almost surely millimetres that happen to lie in :data:`BEARING_LENGTH_RANGE` (a
#: miniature 623 bearing given as bore 3, D 10, D_w 1.5875).
MAX_ELEMENT_DIAMETER = 0.5
#: Longest effective roller length as a multiple of the roller diameter [-]: needle
#: rollers reach about 10 D_w (ISO 3096); beyond twice that the length is a unit slip (a
#: 10 mm roller given as 10.0 m).
MAX_ROLLER_LENGTH_RATIO = 20.0
#: Young's moduli of rings and rolling elements [Pa]: from bearing polymers (PEEK, about
#: 4e9 Pa; nothing softer carries a rolling contact) to beyond diamond (1.05e12 Pa).
#: Below it the value is almost surely in GPa (208 for 208 GPa).
BEARING_MODULUS_RANGE = (1e9, 2e12)
#: Largest composite rms roughness sigma [m]: the finished surfaces of rolling bearings
#: have 0.05..0.5 um, rough machined ones a few micrometres; beyond 10 um the film
#: parameter h_min/sigma of any EHL film is far below 0.01 and meaningless, and the value
#: is a unit slip (0.2 for 0.2 um).
MAX_ROUGHNESS = 1e-5
#: Composite rms roughness [m] that a unit hint of a refused roughness may suggest: from
#: the finest finished bearing surfaces (0.05 um) to :data:`MAX_ROUGHNESS`.
ROUGHNESS_HINT_RANGE = (5e-8, MAX_ROUGHNESS)
#: Oil temperature [deg C] above which a bearing's warnings say that it looks like
#: kelvin: mineral oils oxidise quickly above about 150 deg C and few synthetic oils run
#: above 200 deg C, while 273..473 are common temperatures in kelvin.
KELVIN_WARNING_TEMPERATURE = 200.0

#: Smallest nominal contact angle [deg] of an angular-contact ball or tapered roller
#: bearing: real ones have 10..40 deg; below 2 deg the value is almost surely in radians
#: (0.26 for 15 deg) and is refused.
MIN_NOMINAL_CONTACT_ANGLE = 2.0
#: Largest nominal contact angle [deg], included: the axial angular-contact ball bearings
#: that support ball screws have exactly 60 deg. The load distribution and the kinematics
#: hold for any angle below 90 deg (the loaded angles stay below it, else the loads are
#: refused); beyond 60 deg the bearing is a thrust bearing, which is not modelled.
MAX_NOMINAL_CONTACT_ANGLE = 60.0

#: Smallest non-zero ``operation.radial_load`` or ``axial_load`` [N]: the smallest contact
#: load the contact scenes accept (``scene.FORCE_RANGE``); no element carries more than the
#: bearing's load, and a smaller one underflows in the load distribution.
MIN_BEARING_LOAD = FORCE_RANGE[0]

#: Largest ``operation.radial_load`` or ``axial_load`` [N]: the largest contact load the
#: contact scenes accept (``scene.FORCE_RANGE``; the largest bearings carry about 1e8 N).
MAX_BEARING_LOAD = FORCE_RANGE[1]

#: ``bearing.first_element_azimuth`` range [deg]: one turn either way (beyond it the
#: element azimuths psi_0 + 2 pi j/Z lose their digits).
FIRST_ELEMENT_AZIMUTH_RANGE = (-360.0, 360.0)

#: ``bearing.static_load_rating`` C0 range [N]: miniature bearings (tens of N) to slewing
#: bearings (1e7..1e8 N); outside it Palmgren's f1 = z (P0/C0)^y overflows or the value is
#: a unit slip.
STATIC_LOAD_RATING_RANGE = (10.0, 1e9)
#: ``bearing.static_load_rating`` below this fraction of the geometry's ISO 76 static load
#: rating (:func:`iso76_static_load_rating`) is refused as a unit slip: a catalogue C0
#: written in kN (21.6 for the 6209's 21600 N) is 1/1000 of it, while real ratings lie
#: within a few tens of per cent of it.
MIN_STATIC_LOAD_RATING_FRACTION = 0.01
#: ISO 76 factor f0 of C0 = f0 i Z D_w^2 cos(alpha) for radial ball bearings, taken at the
#: low end of its tabulated values (about 12 to 16 for deep groove and angular-contact
#: bearings of usual proportions; the 6209's catalogue 21600 N gives 14.9).
ISO76_BALL_FACTOR = 12.0

#: ``materials.element_density`` range [kg/m^3]: polymer balls (about 900..1400) to
#: tungsten carbide (15600); 7.85 is g/cm^3.
ELEMENT_DENSITY_RANGE = (500.0, 25000.0)
#: Oil temperatures [deg C] accepted by ``operation.oil_temperature``: cold starts down to
#: -60 deg C (low-temperature synthetic oils), up to 500 deg C (oils decompose long before;
#: above it the value is kelvin), the top of :data:`bearing_fem.scene.TEMPERATURE_RANGE`.
#: The Prokofiev law and the thermal model need t > 0 deg C (checked by :class:`Bearing`
#: where they use it).
OIL_TEMPERATURE_RANGE = (-60.0, TEMPERATURE_RANGE[1])
#: Fewest slices along a profiled roller that docs/bearing.md ("Slicing error")
#: recommends (the default count): with fewer, a bearing's warnings say that the error
#: bars exclude the slicing error (measured: 5 slices put the torque 8 % off).
MIN_RECOMMENDED_SLICES = 11

def _kelvin(t: float) -> str:
    """The kelvin reading of a temperature given in deg C, for unit hints:
    ``"300 K is 26.85 deg C"``."""
    return f"{t:g} K is {t - 273.15:g} deg C"


def _refuse_above_oil_range(field: str, t: float, t_hi: float) -> None:
    """SceneError for a temperature ``t`` [deg C] of ``field`` above ``t_hi`` [deg C],
    which no oil reaches: read as kelvin."""
    if t > t_hi:
        raise SceneError(f"{field} = {t:g} deg C lies above {t_hi:g} deg C: that is no oil "
                         "temperature (oils decompose long before); temperatures are in deg "
                         f"C, and this looks like kelvin ({_kelvin(t)})")


#: Words of the length fields in the hints of their messages.
_LENGTH_WORDS = {"bore": "bore", "outside_diameter": "outside diameter",
                 "element_diameter": "element diameter", "pitch_diameter": "pitch diameter",
                 "width": "width", "effective_length": "effective length"}


def _an(word: str) -> str:
    """``word`` with its indefinite article ("an angular-contact-ball", "a tapered-roller")."""
    return f"{'an' if str(word)[:1].lower() in 'aeiou' else 'a'} {word}"


def _metres_hint(name: str, value: float) -> str:
    """The hint of a bearing length field's message, with the field's own value: read as
    millimetres when it is large (``pitch_diameter = 65`` -> "a pitch diameter of 65 mm
    is 0.065"), else a reminder of the unit."""
    what = _LENGTH_WORDS.get(name, name.replace("_", " "))
    if value >= 1.0:
        return f"dimensions are in metres ({_an(what)} of {value:g} mm is {value * 1e-3:g})"
    if value < BEARING_LENGTH_RANGE[0]:
        return (f"dimensions are in metres, and {_an(what)} below "
                f"{BEARING_LENGTH_RANGE[0] * 1e3:g} mm is no bearing dimension")
    return "dimensions are in metres"


def _length(obj: Any, name: str) -> float:
    """Field ``name`` as a length in :data:`BEARING_LENGTH_RANGE` [m], else SceneError
    naming it, its value and the unit (a millimetre value given as metres, mostly)."""
    value = field_positive(obj, name, "m")
    lo, hi = BEARING_LENGTH_RANGE
    if not lo <= value <= hi:
        raise SceneError(f"bearing.{name} = {value!r} m lies outside the plausible "
                         f"[{lo:g}, {hi:g}] m; {_metres_hint(name, value)}")
    return value


def _modulus_hint(value: float) -> str:
    """The unit hint of a refused modulus [Pa]: the value read as GPa (208 for 208 GPa) or
    MPa (208000), whichever lands in :data:`BEARING_MODULUS_RANGE`, else an example."""
    reading = _unit_reading(value, (("GPa", 1e9), ("MPa", 1e6)), BEARING_MODULUS_RANGE)
    return f" ({reading})" if reading else " (e.g. 208 GPa is 2.08e+11)"


def _unit_reading(value: float, units: tuple[tuple[str, float], ...],
                  accepted: tuple[float, float]) -> str | None:
    """``"<value> <unit> is <SI value>"`` for the first unit (name, factor to SI) whose
    reading of ``value`` lies in ``accepted`` (SI), else None: a hint that names a unit
    only when the value read in it is a valid input."""
    for unit, factor in units:
        if accepted[0] <= value * factor <= accepted[1]:
            return f"{value:g} {unit} is {value * factor:g}"
    return None


def _modulus(obj: Any, name: str) -> None:
    """Optional Young's modulus ``name`` [Pa] in :data:`BEARING_MODULUS_RANGE`, else
    SceneError naming the field, the value and the unit (GPa given as Pa, mostly)."""
    if getattr(obj, name) is None:
        return
    value = field_positive(obj, name, "Pa")
    lo, hi = BEARING_MODULUS_RANGE
    if not lo <= value <= hi:
        raise SceneError(f"{field_name_prefix(obj)}.{name} = {value!r} Pa lies outside the "
                         f"plausible [{lo:g}, {hi:g}] Pa of bearing materials; moduli are "
                         f"in Pa{_modulus_hint(value)}")


#: Largest free contact angle of a deep-groove ball bearing [deg] that its radial
#: clearance may give (cos a0 = 1 - c_r / A): the 6209 example's clearance gives 9.9 deg;
#: 60 deg leaves room for large clearance classes with close conformities, while
#: micrometres given as millimetres put c_r far beyond 2 A, where cos a0 = 1 - c_r / A has
#: no solution (the load distribution failed with a math domain error).
MAX_FREE_CONTACT_ANGLE = 60.0
#: Largest radial clearance of a roller bearing as a fraction of the roller diameter [-]:
#: the largest catalogue clearances (C5) of cylindrical roller bearings are about 1 % of it.
MAX_ROLLER_CLEARANCE_FRACTION = 0.05


# ---------------------------------------------------------------------------------------
# sections
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class Geometry:
    """Internal geometry of the bearing (the ``[bearing]`` table).

    Parameters
    ----------
    type : {"deep-groove-ball", "angular-contact-ball", "cylindrical-roller", "tapered-roller"}
    bore, outside_diameter : float
        d and D [m] (catalogue dimensions; used by the empirical models).
    element_diameter : float
        Ball or roller diameter D_w [m] (tapered: the mean roller diameter).
    elements : int
        Rolling elements per row Z.
    pitch_diameter : float or None
        d_m [m]; None: (d + D)/2.
    rows : int
        Rows of rolling elements (ball bearings: 1). The rows share the radial load
        equally (rigid rings, no tilt).
    width : float or None
        Bearing width B [m]; when given, the rows of rollers must fit in it
        (rows l_we cos(beta) <= B), and a ball bearing is at least as wide as its balls.
    contact_angle : float or None
        Nominal (unloaded) contact angle [deg]: required for angular-contact ball and
        tapered roller bearings, in [:data:`MIN_NOMINAL_CONTACT_ANGLE`,
        :data:`MAX_NOMINAL_CONTACT_ANGLE`] deg (a smaller
        one is taken for radians and refused); 0 or none for deep-groove (its free angle
        follows from the clearance) and cylindrical roller bearings (stored as 0).
    radial_clearance : float
        Radial internal clearance c_r [m] (half the diametral clearance P_d), >= 0.
        Angular-contact ball bearings take it from the contact angle instead.
    inner_conformity, outer_conformity : float or None
        Groove radius over ball diameter f = r/D_w [-], in (0.5, 0.6]; balls only,
        default 0.52 and 0.53.
    effective_length : float or None
        Effective roller length l_we [m]; rollers only (required), at most
        :data:`MAX_ROLLER_LENGTH_RATIO` D_w and, with ``width``, within the width.
    profile : {"straight", "crowned", "logarithmic"}
        Roller profile; a profiled roller is cut into ``slices`` along its length.
    crown_drop : float or None
        Crown drop at the roller ends [m] (profile "crowned").
    flat_length : float
        Straight middle part of a crowned roller [m] (default 0: fully crowned).
    design_load : float or None
        Design roller load Q_d [N] of a logarithmic (Johns-Gohar) profile.
    slices : int or None
        Slices along a profiled roller (default 11; 1 for a straight roller).
    first_element_azimuth : float
        Azimuth of element 0 [deg] from the direction of the radial load, in [-360, 360]
        (:data:`FIRST_ELEMENT_AZIMUTH_RANGE`).
    static_load_rating : float or None
        C0 [N] (SKF model of a deep-groove bearing under axial load; Palmgren's f1), in
        :data:`STATIC_LOAD_RATING_RANGE` and at least
        :data:`MIN_STATIC_LOAD_RATING_FRACTION` of :func:`iso76_static_load_rating`.
    """

    _section = "bearing"
    type: Literal["deep-groove-ball", "angular-contact-ball", "cylindrical-roller",
                  "tapered-roller"]
    bore: float
    outside_diameter: float
    element_diameter: float
    elements: int
    pitch_diameter: float | None = None
    rows: int = 1
    width: float | None = None
    contact_angle: float | None = None
    radial_clearance: float = 0.0
    inner_conformity: float | None = None
    outer_conformity: float | None = None
    effective_length: float | None = None
    profile: Literal["straight", "crowned", "logarithmic"] = "straight"
    crown_drop: float | None = None
    flat_length: float = 0.0
    design_load: float | None = None
    slices: int | None = None
    first_element_azimuth: float = 0.0
    static_load_rating: float | None = None

    def __post_init__(self) -> None:
        field_choice(self, "type", BEARING_TYPES)
        d = _length(self, "bore")
        big_d = _length(self, "outside_diameter")
        if big_d <= d:
            raise SceneError(f"bearing.outside_diameter = {big_d!r} m must exceed "
                             f"bearing.bore = {d!r} m")
        dw = _length(self, "element_diameter")
        if dw > MAX_ELEMENT_DIAMETER:
            raise SceneError(f"bearing.element_diameter = {dw:g} m exceeds "
                             f"{MAX_ELEMENT_DIAMETER:g} m (the balls and rollers of the largest "
                             f"bearings are 0.1-0.2 m); {_metres_hint('element_diameter', dw)}"
                             f"; check the bore ({d:g} m) and the outside diameter "
                             f"({big_d:g} m) too")
        field_integer(self, "elements", 3, 500, "rolling elements per row")
        field_integer(self, "rows", 1, 8, "rows")
        if self.pitch_diameter is not None:
            dm = _length(self, "pitch_diameter")
            if not d < dm < big_d:
                raise SceneError(f"bearing.pitch_diameter = {dm!r} m must lie between the "
                                 f"bore {d!r} m and the outside diameter {big_d!r} m")
        dm = self.mean_diameter
        if dw >= 0.5 * (big_d - d) or dw >= dm:
            raise SceneError(f"bearing.element_diameter = {dw:g} m does not fit between the "
                             f"rings (D - d)/2 = {0.5 * (big_d - d):.4g} m; "
                             f"{_metres_hint('element_diameter', dw)}")
        z = self.elements
        if z * dw > math.pi * dm * (1.0 + 1e-9):
            raise SceneError(f"bearing.elements = {z} elements of {dw:g} m do not fit on "
                             f"the pitch circle pi d_m = {math.pi * dm:.4g} m; give the "
                             "elements per row (and the diameters in metres)")
        if self.width is not None:
            _length(self, "width")
        alpha = self._contact_angle()
        self._check_raceways_in_rings(d, big_d, dm, dw, alpha)
        c_r = field_number(self, "radial_clearance", "m")
        if c_r < 0.0:
            raise SceneError(f"bearing.radial_clearance must be >= 0 m, got {c_r:g} m: a "
                             "negative clearance (preload) is not modelled; give 0 for a "
                             "bearing without clearance")
        field_bounded(self, "first_element_azimuth", "deg", *FIRST_ELEMENT_AZIMUTH_RANGE,
                      why="the azimuth of element 0 from the radial load, within one turn")
        if self.static_load_rating is not None:
            field_bounded(self, "static_load_rating", "N", *STATIC_LOAD_RATING_RANGE,
                          why="catalogue C0 values; a rating in kN is 1000 times larger")
        if self.type in BALL_TYPES:
            self._check_ball()
        else:
            self._check_roller()
        if self.static_load_rating is not None:
            self._check_static_load_rating()

    def _check_static_load_rating(self) -> None:
        """C0 against the ISO 76 rating of the geometry: below
        :data:`MIN_STATIC_LOAD_RATING_FRACTION` of it the value is a unit slip (kN)."""
        c0 = float(self.static_load_rating)
        iso = iso76_static_load_rating(self)
        if c0 < MIN_STATIC_LOAD_RATING_FRACTION * iso:
            raise SceneError(
                f"bearing.static_load_rating = {c0!r} N is below "
                f"{MIN_STATIC_LOAD_RATING_FRACTION:.0%} of the static load rating of this "
                f"geometry, about {iso:.3g} N by ISO 76; C0 is in N, not kN "
                f"({c0:g} kN is {c0 * 1e3:g} N)")

    def _check_raceways_in_rings(self, d: float, big_d: float, dm: float, dw: float,
                                 alpha: float) -> None:
        """The raceway diameters d_m -+ D_w cos(alpha) (section 3 of docs/bearing.md) lie
        between the bore and the outside diameter. Without a pitch diameter (d_m = (d + D)/2)
        the element check above implies it; a given pitch diameter off the middle of the
        section can put a raceway inside the bore or beyond the outer ring."""
        reach = dw * math.cos(math.radians(alpha))
        inner, outer = dm - reach, dm + reach
        if inner > d and outer < big_d:
            return
        name = "pitch_diameter" if self.pitch_diameter is not None else "element_diameter"
        side = (f"the inner raceway d_m - D_w cos(alpha) = {inner:.4g} m lies inside the bore "
                f"{d:g} m" if inner <= d else
                f"the outer raceway d_m + D_w cos(alpha) = {outer:.4g} m lies beyond the "
                f"outside diameter {big_d:g} m")
        raise SceneError(f"bearing.{name} = {getattr(self, name):g} m puts the elements "
                         f"(D_w = {dw:g} m) outside the rings: {side}; the raceways must lie "
                         f"between the bore and the outside diameter (d_m = {dm:g} m; "
                         "dimensions are in metres)")

    def _contact_angle(self) -> float:
        """The nominal contact angle [deg]: required (and at least
        :data:`MIN_NOMINAL_CONTACT_ANGLE`) for angular-contact ball and tapered roller
        bearings, 0 (given or not) for the others."""
        angular = self.type in ANGULAR_TYPES
        if self.contact_angle is None:
            if angular:
                raise SceneError(f"bearing.contact_angle (deg) is required for "
                                 f"{_an(self.type)} bearing: its nominal contact angle, in "
                                 f"[{MIN_NOMINAL_CONTACT_ANGLE:g}, "
                                 f"{MAX_NOMINAL_CONTACT_ANGLE:g}] deg")
            object.__setattr__(self, "contact_angle", 0.0)
        alpha = field_number(self, "contact_angle", "deg")
        if not angular:
            if alpha != 0.0:
                raise SceneError(f"bearing.contact_angle applies to angular-contact ball and "
                                 f"tapered roller bearings, got {alpha!r} deg for "
                                 f"{self.type!r}")
            return alpha
        if 0.0 < alpha < MIN_NOMINAL_CONTACT_ANGLE:
            raise SceneError(f"bearing.contact_angle = {alpha!r} deg is below "
                             f"{MIN_NOMINAL_CONTACT_ANGLE:g} deg for {_an(self.type)} bearing: "
                             f"the angle is in degrees, and {alpha!r} looks like radians "
                             f"({alpha!r} rad is {math.degrees(alpha):.4g} deg)")
        if not 0.0 < alpha <= MAX_NOMINAL_CONTACT_ANGLE:
            raise SceneError(f"bearing.contact_angle = {alpha!r} deg must lie in "
                             f"[{MIN_NOMINAL_CONTACT_ANGLE:g}, {MAX_NOMINAL_CONTACT_ANGLE:g}] "
                             f"deg for {_an(self.type)} bearing (nominal contact angles are "
                             "10..40 deg, 60 deg for ball-screw support bearings)")
        return alpha

    def _check_ball(self) -> None:
        if self.rows != 1:
            raise SceneError(f"bearing.rows must be 1 for a ball bearing, got {self.rows!r}")
        for name, default in (("inner_conformity", 0.52), ("outer_conformity", 0.53)):
            if getattr(self, name) is None:
                object.__setattr__(self, name, default)
            f = field_number(self, name, "(dimensionless)")
            if not 0.5 < f <= 0.6:
                raise SceneError(f"bearing.{name} = r/D_w must lie in (0.5, 0.6] "
                                 f"(dimensionless), got {f!r}")
        for name in ("effective_length", "crown_drop", "design_load", "slices"):
            if getattr(self, name) is not None:
                raise SceneError(f"bearing.{name} applies to roller bearings only, got "
                                 f"{getattr(self, name)!r} for {self.type!r}")
        if self.profile != "straight" or self.flat_length != 0.0:
            raise SceneError("bearing.profile and bearing.flat_length apply to roller "
                             f"bearings only, got {self.profile!r}, {self.flat_length!r} m")
        if self.width is not None and self.element_diameter > self.width * (1.0 + 1e-9):
            raise SceneError(f"bearing.width = {self.width!r} m is narrower than the balls "
                             f"(bearing.element_diameter = {self.element_diameter!r} m): a ball "
                             "bearing is at least as wide as its balls; "
                             f"{_metres_hint('width', self.width)}")
        if self.type == "angular-contact-ball" and self.radial_clearance != 0.0:
            raise SceneError("bearing.radial_clearance of an angular-contact ball bearing "
                             "follows from bearing.contact_angle (deg); give only the angle, "
                             f"got {self.radial_clearance!r} m")
        # free contact angle cos a0 = 1 - c_r / A, A = (f_i + f_o - 1) D_w
        a_dist = (self.inner_conformity + self.outer_conformity - 1.0) * self.element_diameter
        limit = a_dist * (1.0 - math.cos(math.radians(MAX_FREE_CONTACT_ANGLE)))
        if self.radial_clearance > limit:
            raise SceneError(f"bearing.radial_clearance = {self.radial_clearance!r} m exceeds "
                             f"{limit:.3g} m, the clearance of a free contact angle of "
                             f"{MAX_FREE_CONTACT_ANGLE:g} deg with these grooves; radial "
                             "clearances are micrometres to tens of micrometres, in metres "
                             "(e.g. 7.5e-6 for 7.5 um)")

    def _check_roller(self) -> None:
        for name in ("inner_conformity", "outer_conformity"):
            if getattr(self, name) is not None:
                raise SceneError(f"bearing.{name} applies to ball bearings only, got "
                                 f"{getattr(self, name)!r} for {self.type!r}")
        if self.effective_length is None:
            raise SceneError(f"bearing.effective_length (m) is required for {_an(self.type)} "
                             "bearing")
        lw = _length(self, "effective_length")
        dw = self.element_diameter
        if lw > MAX_ROLLER_LENGTH_RATIO * dw:
            raise SceneError(f"bearing.effective_length = {lw!r} m exceeds "
                             f"{MAX_ROLLER_LENGTH_RATIO:g} roller diameters "
                             f"({MAX_ROLLER_LENGTH_RATIO * dw:.4g} m; needle rollers reach "
                             f"about 10); {_metres_hint('effective_length', lw)}")
        if self.width is not None:
            extent = self.rows * lw * math.cos(math.radians(self.contact_angle))
            if extent > self.width * (1.0 + 1e-9):
                raise SceneError(f"bearing.effective_length = {lw!r} m does not fit in "
                                 f"bearing.width = {self.width!r} m: {self.rows} row(s) of "
                                 f"rollers that long span {extent:.4g} m axially (rows l_we "
                                 f"cos(contact_angle)); {_metres_hint('effective_length', lw)}")
        limit = MAX_ROLLER_CLEARANCE_FRACTION * self.element_diameter
        if self.radial_clearance > limit:
            raise SceneError(f"bearing.radial_clearance = {self.radial_clearance!r} m exceeds "
                             f"{limit:.3g} m ({MAX_ROLLER_CLEARANCE_FRACTION:g} of the roller "
                             "diameter); radial clearances are micrometres to a few tenths of "
                             "a millimetre, in metres (e.g. 4e-5 for 40 um)")
        field_choice(self, "profile", ("straight", "crowned", "logarithmic"))
        flat = field_nonnegative(self, "flat_length", "m")
        if flat >= lw and self.profile == "crowned":
            raise SceneError(f"bearing.flat_length = {flat!r} m must be shorter than "
                             f"bearing.effective_length = {lw!r} m")
        if self.profile == "crowned":
            if self.crown_drop is None:
                raise SceneError("bearing.crown_drop (m) is required for profile = 'crowned'")
            drop = field_positive(self, "crown_drop", "m")
            limit = MAX_CROWN_DROP_FRACTION * self.element_diameter
            if drop > limit:
                raise SceneError(f"bearing.crown_drop = {drop!r} m exceeds {limit:.3g} m "
                                 f"({MAX_CROWN_DROP_FRACTION:g} of the roller diameter); "
                                 "crown drops are micrometres to tens of micrometres, in "
                                 "metres (e.g. 1.5e-5 for 15 um)")
        elif self.crown_drop is not None:
            raise SceneError(f"bearing.crown_drop applies to profile = 'crowned', got "
                             f"{self.crown_drop!r} m with profile {self.profile!r}")
        if self.profile == "logarithmic":
            if self.design_load is None:
                raise SceneError("bearing.design_load (N) is required for profile = "
                                 "'logarithmic' (Johns-Gohar)")
            field_positive(self, "design_load", "N")
        elif self.design_load is not None:
            raise SceneError(f"bearing.design_load applies to profile = 'logarithmic', got "
                             f"{self.design_load!r} N")
        if self.profile != "straight" and flat != 0.0 and self.profile != "crowned":
            raise SceneError("bearing.flat_length applies to profile = 'crowned'")
        if self.slices is None:
            return
        n = field_integer(self, "slices", 1, 101, "slices along the roller")
        if self.profile == "straight" and n != 1:
            raise SceneError(f"bearing.slices = {n} needs a roller profile ('crowned' or "
                             "'logarithmic'); a straight roller is one line contact")

    @property
    def mean_diameter(self) -> float:
        """Pitch diameter d_m [m] (given, or (d + D)/2)."""
        if self.pitch_diameter is not None:
            return float(self.pitch_diameter)
        return 0.5 * (float(self.bore) + float(self.outside_diameter))

    @property
    def n_slices(self) -> int:
        """Slices along a roller: ``slices``, or 1 (straight) / 11 (profiled) by default."""
        if self.slices is not None:
            return int(self.slices)
        return 1 if self.profile == "straight" else 11

    @property
    def is_ball(self) -> bool:
        """True for ball bearings (point contacts)."""
        return self.type in BALL_TYPES


@dataclass(frozen=True, kw_only=True)
class BearingMaterials:
    """Rings and rolling elements: a preset name and optional overrides.

    Parameters
    ----------
    rings, elements : {"steel", "si3n4"}
        Material presets (:data:`MATERIAL_PRESETS`).
    ring_modulus, element_modulus : float or None
        Young's moduli [Pa], in :data:`BEARING_MODULUS_RANGE`; None: from the preset.
    ring_poisson, element_poisson : float or None
        Poisson ratios [-]; None: from the preset.
    element_density : float or None
        Density of the rolling elements [kg/m^3] (centrifugal load), in
        :data:`ELEMENT_DENSITY_RANGE`; None: preset.
    """

    _section = "materials"
    rings: Literal["steel", "si3n4"] = "steel"
    elements: Literal["steel", "si3n4"] = "steel"
    ring_modulus: float | None = None
    ring_poisson: float | None = None
    element_modulus: float | None = None
    element_poisson: float | None = None
    element_density: float | None = None

    def __post_init__(self) -> None:
        field_choice(self, "rings", tuple(MATERIAL_PRESETS))
        field_choice(self, "elements", tuple(MATERIAL_PRESETS))
        for name in ("ring_modulus", "element_modulus"):
            _modulus(self, name)
        if self.element_density is not None:
            field_bounded(self, "element_density", "kg/m^3", *ELEMENT_DENSITY_RANGE,
                          why="polymer to tungsten carbide balls; 7.85 is g/cm^3")
        for name in ("ring_poisson", "element_poisson"):
            if getattr(self, name) is not None:
                field_poisson(self, name)

    @property
    def ring(self) -> tuple[float, float]:
        """(E [Pa], nu [-]) of the rings."""
        e, nu, _ = MATERIAL_PRESETS[self.rings]
        return (self.ring_modulus if self.ring_modulus is not None else e,
                self.ring_poisson if self.ring_poisson is not None else nu)

    @property
    def element(self) -> tuple[float, float]:
        """(E [Pa], nu [-]) of the rolling elements."""
        e, nu, _ = MATERIAL_PRESETS[self.elements]
        return (self.element_modulus if self.element_modulus is not None else e,
                self.element_poisson if self.element_poisson is not None else nu)

    @property
    def density(self) -> float:
        """Density of the rolling elements [kg/m^3]."""
        if self.element_density is not None:
            return float(self.element_density)
        return MATERIAL_PRESETS[self.elements][2]


@dataclass(frozen=True, kw_only=True)
class BearingLubricant:
    """Oil, with its viscosity at the oil temperature or a Prokofiev temperature law.

    Parameters
    ----------
    viscosity : float or None
        eta0 [Pa s] at the oil temperature (``temperature_law = "none"``).
    piezo : float
        Barus alpha [1/Pa] (``temperature_law = "none"`` or no alpha table).
    viscosity_law : {"barus", "roelands", "constant"}
    compressibility : {"incompressible", "dowson-higginson"}
        Density-pressure law of the contact scenes.
    density : float
        Oil density at ambient pressure [kg/m^3] (kinematic viscosity of the empirical
        models, Nikitin's criteria).
    temperature_law : {"none", "prokofiev"}
        ``prokofiev``: eta0(t) = reference_viscosity (reference_temperature/t)^exponent,
        t in deg C (Yachikov & Vostrikov 2015).
    reference_viscosity : float or None
        eta_ref [Pa s] at ``reference_temperature``.
    reference_temperature : float
        t_ref [deg C].
    exponent : float or None
        Prokofiev exponent n [-].
    piezo_temperatures, piezo_values : list of float or None
        alpha(t) table [deg C], [1/Pa]: ln(alpha) linear in t.
    thermal_conductivity : float
        Oil conductivity [W/(m K)] (Nikitin's Prandtl number).
    specific_heat : float
        Oil specific heat [J/(kg K)] (Nikitin's Prandtl number).
    """

    _section = "lubricant"
    viscosity: float | None = None
    piezo: float = 0.0
    viscosity_law: Literal["barus", "roelands", "constant"] = "barus"
    compressibility: Literal["incompressible", "dowson-higginson"] = "incompressible"
    density: float = 870.0
    temperature_law: Literal["none", "prokofiev"] = "none"
    reference_viscosity: float | None = None
    reference_temperature: float = 40.0
    exponent: float | None = None
    piezo_temperatures: tuple[float, ...] | None = None
    piezo_values: tuple[float, ...] | None = None
    thermal_conductivity: float = 0.13
    specific_heat: float = 2000.0

    def __post_init__(self) -> None:
        field_piezo(self)
        field_choice(self, "viscosity_law", ("barus", "roelands", "constant"))
        field_choice(self, "compressibility", ("incompressible", "dowson-higginson"))
        field_bounded(self, "density", "kg/m^3", *OIL_DENSITY_RANGE,
                      why="oils have 700..2000 kg/m^3")
        field_choice(self, "temperature_law", ("none", "prokofiev"))
        t_ref = field_number(self, "reference_temperature", "deg C")
        _refuse_above_oil_range("lubricant.reference_temperature", t_ref, TEMPERATURE_RANGE[1])
        if t_ref <= 0.0:
            raise SceneError(f"lubricant.reference_temperature = {t_ref:g} deg C must be > 0 "
                             "deg C: the Prokofiev law eta0(t) = reference_viscosity "
                             "(reference_temperature/t)^exponent is written in deg C; give the "
                             "temperature of reference_viscosity (e.g. 40 deg C)")
        field_bounded(self, "thermal_conductivity", "W/(m K)", *OIL_CONDUCTIVITY_RANGE,
                      why="oils have 0.1..0.2 W/(m K)")
        field_bounded(self, "specific_heat", "J/(kg K)", *OIL_SPECIFIC_HEAT_RANGE,
                      why="oils have 1700..2500 J/(kg K)")
        if self.temperature_law == "none":
            if self.viscosity is None:
                raise SceneError("lubricant.viscosity (Pa s at the oil temperature) is "
                                 "required unless lubricant.temperature_law = 'prokofiev'")
            field_bounded(self, "viscosity", "Pa s", *VISCOSITY_RANGE,
                          why="the contact scenes' range: gases to bitumen")
            for name in ("reference_viscosity", "exponent", "piezo_temperatures"):
                if getattr(self, name) is not None:
                    raise SceneError(f"lubricant.{name} needs lubricant.temperature_law = "
                                     "'prokofiev'")
        else:
            if self.viscosity is not None:
                raise SceneError("lubricant.viscosity is set by the temperature law: give "
                                 "lubricant.reference_viscosity (Pa s) instead")
            for name, unit in (("reference_viscosity", "Pa s"), ("exponent", "(dimensionless)")):
                if getattr(self, name) is None:
                    raise SceneError(f"lubricant.{name} ({unit}) is required for "
                                     "temperature_law = 'prokofiev'")
                field_positive(self, name, unit)
            field_bounded(self, "reference_viscosity", "Pa s", *VISCOSITY_RANGE,
                          why="the contact scenes' range: gases to bitumen")
        field_piezo_table(self)


@dataclass(frozen=True, kw_only=True)
class Operation:
    """Operating point: inner ring rotating, outer ring fixed.

    Parameters
    ----------
    inner_rpm : float
        Inner-ring speed n [1/min], > 0.
    radial_load, axial_load : float
        Fr, Fa [N], >= 0, not both zero; each 0 or in [:data:`MIN_BEARING_LOAD`,
        :data:`MAX_BEARING_LOAD`] (1e-6..1e12 N). The radial load acts along azimuth 0.
    oil_temperature : float or None
        Oil (and bearing) temperature [deg C], in [-60, 500] deg C
        (:data:`OIL_TEMPERATURE_RANGE`: cold starts allowed); required by a temperature law
        and by the thermal model, which need it > 0 deg C. Without a temperature law it
        changes no result: ``lubricant.viscosity`` and ``piezo`` are taken as given. Above
        :data:`KELVIN_WARNING_TEMPERATURE` the bearing's warnings say it looks like kelvin
        (:func:`input_warnings`).
    """

    _section = "operation"
    inner_rpm: float
    radial_load: float = 0.0
    axial_load: float = 0.0
    oil_temperature: float | None = None

    def __post_init__(self) -> None:
        field_positive(self, "inner_rpm", "1/min")
        fr = field_nonnegative(self, "radial_load", "N")
        fa = field_nonnegative(self, "axial_load", "N")
        if fr == 0.0 and fa == 0.0:
            raise SceneError("operation: radial_load and axial_load are both 0 N; give a "
                             "load (an unloaded bearing has no EHL contacts)")
        for name, value in (("radial_load", fr), ("axial_load", fa)):
            if 0.0 < value < MIN_BEARING_LOAD:
                raise SceneError(f"operation.{name} = {value:g} N is below {MIN_BEARING_LOAD:g} "
                                 "N, the smallest contact load the contact model accepts, so "
                                 "no element could carry it; give 0 for none (loads are in N)")
            if value > MAX_BEARING_LOAD:
                raise SceneError(f"operation.{name} = {value:g} N exceeds {MAX_BEARING_LOAD:g} "
                                 "N, the largest contact load the contact model accepts (the "
                                 "largest bearings carry about 1e8 N); loads are in N")
        if self.oil_temperature is not None:
            t = field_number(self, "oil_temperature", "deg C")
            t_lo, t_hi = OIL_TEMPERATURE_RANGE
            _refuse_above_oil_range("operation.oil_temperature", t, t_hi)
            if t < t_lo:
                raise SceneError(f"operation.oil_temperature = {t:g} deg C lies below "
                                 f"{t_lo:g} deg C, colder than any oil flows; give the oil "
                                 "temperature in deg C")

    @property
    def inner_speed(self) -> float:
        """Inner-ring angular speed omega_i [rad/s]."""
        return 2.0 * math.pi * float(self.inner_rpm) / 60.0


@dataclass(frozen=True, kw_only=True)
class BearingModel:
    """Model options of the bearing solve.

    Parameters
    ----------
    centrifugal : bool
        Add the centrifugal force of the rolling elements (orbiting with the cage) to the
        load distribution (outer contacts then carry more than inner ones).
    thermal : {"none", "patch"}
        ``patch``: thermally coupled contact solves (line contacts only; needs the
        Prokofiev law in ``[lubricant]`` and ``operation.oil_temperature``).
    elasticity : {"half-space", "local"}
        Elastic model of every contact scene (``local``: Kodnir's compliance, line
        contacts only).
    roughness : float or None
        Composite rms roughness sigma = sqrt(Rq1^2 + Rq2^2) [m] for the film parameter
        lambda = h_min / sigma, at most :data:`MAX_ROUGHNESS`; None: lambda not reported.
    min_load_fraction : float
        Elements whose load is below this fraction of the largest element load are not
        solved (reported as excluded, with the reason) [-]. 0: solve every element
        with a load.
    """

    _section = "model"
    centrifugal: bool = False
    thermal: Literal["none", "patch"] = "none"
    elasticity: Literal["half-space", "local"] = "half-space"
    roughness: float | None = None
    min_load_fraction: float = 1e-3

    def __post_init__(self) -> None:
        field_bool(self, "centrifugal")
        field_choice(self, "thermal", ("none", "patch"))
        field_choice(self, "elasticity", ("half-space", "local"))
        _optional_positive(self, "roughness", "m")
        if self.roughness is not None and self.roughness > MAX_ROUGHNESS:
            raise SceneError(f"model.roughness = {self.roughness!r} m exceeds {MAX_ROUGHNESS:g} m "
                             "(10 um rms, beyond any lubricated rolling surface); the "
                             f"roughness is in metres ({_roughness_hint(self.roughness)})")
        v = field_nonnegative(self, "min_load_fraction", "(dimensionless)")
        if v >= 1.0:
            raise SceneError(f"model.min_load_fraction must be < 1 (dimensionless), got {v!r}")


def _roughness_hint(value: float) -> str:
    """The unit hint of a refused roughness [m]: the value read as micrometres (0.2 for
    0.2 um) or millimetres (0.0002), whichever lands in :data:`ROUGHNESS_HINT_RANGE`, else
    an example (2e-05 is 20 um in metres, too rough, and no 2e-05 mm)."""
    reading = _unit_reading(value, (("um", 1e-6), ("mm", 1e-3)), ROUGHNESS_HINT_RANGE)
    return reading or "e.g. 0.2 um is 2e-07"




@dataclass(frozen=True, kw_only=True)
class BearingMesh:
    """Mesh of every contact scene (defaults: the contact solver's own).

    Parameters
    ----------
    line_nodes : int or None
        Nodes of each line-contact scene.
    point_nodes : (int, int) or None
        (nx, ny) of each point-contact scene.
    x_range, y_range : (float, float) or None
        Domain in Hertz half-widths (``y_range``: point contacts); must contain the Hertz
        zone [-1, 1] (:func:`bearing_fem.scene.require_hertz_zone`).
    line_grading : {"uniform", "outlet"} or None
        Node spacing of each line-contact scene (``mesh.grading`` of a scene: "outlet"
        refines the grid at the outlet spike, docs/line_contact.md "Automatic grading");
        half-space, isothermal roller bearings only. None: uniform.
    target_error : float or None
        Largest estimated relative discretisation error [-] of each contact's
        friction force, heat power, h_min and h_central, in [1e-3, 0.5]: a contact above
        it, or without an estimate, is solved again on the grid of half the spacing,
        until it meets it or the grid reaches :data:`~bearing_fem.contacts.refine.TARGET_ERROR_MAX_POINT_NODES`
        per direction (points) or
        :data:`~bearing_fem.contacts.refine.TARGET_ERROR_MAX_LINE_NODES` (lines). None (the
        default): each contact is solved once on its grid (but see
        ``refine_thin_films``).
    refine_thin_films : bool
        Ball contacts whose h_min lies below half of Hamrock-Dowson's are solved again on
        the grid of half the spacing, up to 257^2 (default true;
        :func:`bearing_fem.bearing.solve.thin_film_refinement`). false keeps every contact
        on its grid (work-precision studies of a fixed grid); such films are then only
        warned.
    """

    _section = "mesh"
    line_nodes: int | None = None
    point_nodes: tuple[int, int] | None = None
    x_range: tuple[float, float] | None = None
    y_range: tuple[float, float] | None = None
    line_grading: str | None = None
    target_error: float | None = None
    refine_thin_films: bool = True

    def __post_init__(self) -> None:
        field_bool(self, "refine_thin_films")
        if self.target_error is not None:
            field_target_error(self)
        if self.line_grading is not None:
            field_choice(self, "line_grading", GRADINGS)
            if self.line_grading == "uniform":
                object.__setattr__(self, "line_grading", None)
        if self.line_nodes is not None:
            field_integer(self, "line_nodes", 9, 20001, "nodes")
        n = self.point_nodes
        if n is not None:
            if (not isinstance(n, (list, tuple)) or len(n) != 2
                    or any(isinstance(v, bool) or not isinstance(v, int) or not 9 <= v <= 2049
                           for v in n)):
                raise SceneError(f"mesh.point_nodes must be two integers [nx, ny] in "
                                 f"[9, 2049], got {n!r}")
            object.__setattr__(self, "point_nodes", (int(n[0]), int(n[1])))
        field_range(self, "x_range", hertz_zone=True)  # every bearing contact is elastic
        field_range(self, "y_range", hertz_zone=True)  # and loaded: Hertz units


@dataclass(frozen=True, kw_only=True)
class BearingThermal:
    """Options of the thermal patch (``model.thermal = "patch"``; see docs/coupling.md).

    Parameters
    ----------
    conductivity, density, heat_capacity : float
        Body lambda [W/(m K)], rho [kg/m^3], c [J/(kg K)] (bearing steel defaults).
    source_model : {"jaeger", "fe"}
    contact_temperature : {"mean", "max"}
    max_iterations : int
    tolerance : float
        [K].
    relaxation : float
        [-], in (0, 1].
    """

    _section = "thermal"
    conductivity: float = 46.0
    density: float = 7850.0
    heat_capacity: float = 470.0
    source_model: Literal["jaeger", "fe"] = "jaeger"
    contact_temperature: Literal["mean", "max"] = "mean"
    max_iterations: int = 30
    tolerance: float = 0.05
    relaxation: float = 0.7

    def __post_init__(self) -> None:
        field_positive(self, "conductivity", "W/(m K)")
        field_positive(self, "density", "kg/m^3")
        field_positive(self, "heat_capacity", "J/(kg K)")
        field_choice(self, "source_model", ("jaeger", "fe"))
        field_choice(self, "contact_temperature", ("mean", "max"))
        field_integer(self, "max_iterations", 1, 1000, "thermal iterations")
        field_positive(self, "tolerance", "K")
        r = field_positive(self, "relaxation", "(dimensionless)")
        if r > 1.0:
            raise SceneError(f"thermal.relaxation must lie in (0, 1] (dimensionless), got {r!r}")


@dataclass(frozen=True, kw_only=True)
class EmpiricalOptions:
    """Coefficients of the empirical torque models (see docs/bearing.md).

    Parameters
    ----------
    palmgren_f0 : float or None
        Palmgren's lubrication factor f0 [-]; None: the typical value for the type and
        an oil bath (:data:`bearing_fem.bearing.empirical.PALMGREN_F0`).
    palmgren_f1 : float or None
        Palmgren's load factor f1 [-]; None: from the type
        (:func:`bearing_fem.bearing.empirical.palmgren_f1`).
    friction_coefficient : float or None
        Reduced friction coefficient f_pr [-] of the bore-based form M1 = f_pr P d/2
        (Yachikov & Vostrikov 2015), in (0, 1]; None: that model is not evaluated.
    skf_series : str or None
        Bearing series for the SKF four-component model's geometry constants: one listed
        for the bearing's type in
        :data:`bearing_fem.bearing.empirical.SKF_GEOMETRY_CONSTANTS` (checked by
        :class:`Bearing`; another series is an error).
    skf_r1, skf_r2, skf_s1, skf_s2 : float or None
        Geometry constants given directly (they override the series): exactly those the
        SKF model of the bearing's type uses (:data:`SKF_CONSTANTS_USED`, checked by
        :class:`Bearing`): all four for deep groove ball bearings, R1, S1, S2 for
        cylindrical roller bearings; none for types without an SKF model.
    lubrication : {"oil-bath", "oil-jet", "oil-air", "grease"}
        Lubrication method (SKF replenishment constant).
    nikitin_flow_ratio : float or None
        q/q_nom [-] of Nikitin's (2011) criterial loss model (ball bearings); None: not
        evaluated.
    nikitin_set : {"steel", "ceramic", "joint"}
        Nikitin's coefficient set.
    """

    _section = "empirical"
    palmgren_f0: float | None = None
    palmgren_f1: float | None = None
    friction_coefficient: float | None = None
    skf_series: str | None = None
    skf_r1: float | None = None
    skf_r2: float | None = None
    skf_s1: float | None = None
    skf_s2: float | None = None
    lubrication: Literal["oil-bath", "oil-jet", "oil-air", "grease"] = "oil-bath"
    nikitin_flow_ratio: float | None = None
    nikitin_set: Literal["steel", "ceramic", "joint"] = "joint"

    def __post_init__(self) -> None:
        for name in ("palmgren_f0", "palmgren_f1", "friction_coefficient",
                     "nikitin_flow_ratio"):
            _optional_positive(self, name, "(dimensionless)")
        if self.friction_coefficient is not None:
            field_bounded(self, "friction_coefficient", "(dimensionless)", 0.0, 1.0,
                          open_low=True, why="a friction coefficient; bearings have "
                          "0.001..0.005")
        for name in SKF_CONSTANT_FIELDS:  # which are needed and > 0: Bearing (by type)
            if getattr(self, name) is not None:
                field_number(self, name, "(catalogue units)")
        if self.skf_series is not None and not isinstance(self.skf_series, str):
            hint = (f'; write "{self.skf_series}" (a string)'
                    if isinstance(self.skf_series, int) and not isinstance(self.skf_series, bool)
                    else "")
            raise SceneError(f"empirical.skf_series must be a string (a series designation "
                             f"such as \"62\", no unit), got {self.skf_series!r}{hint}")
        field_choice(self, "lubrication", ("oil-bath", "oil-jet", "oil-air", "grease"))
        field_choice(self, "nikitin_set", ("steel", "ceramic", "joint"))


# ---------------------------------------------------------------------------------------
# the bearing
# ---------------------------------------------------------------------------------------
#: TOML table name -> (attribute of Bearing, section class). ``[bearing]`` is the geometry.
_SECTIONS: dict[str, tuple[str, type]] = {
    "bearing": ("geometry", Geometry),
    "materials": ("materials", BearingMaterials),
    "lubricant": ("lubricant", BearingLubricant),
    "operation": ("operation", Operation),
    "model": ("model", BearingModel),
    "mesh": ("mesh", BearingMesh),
    "solver": ("solver", SolverSpec),
    "traction": ("traction", Traction),
    "thermal": ("thermal", BearingThermal),
    "empirical": ("empirical", EmpiricalOptions),
}
_REQUIRED = ("bearing", "lubricant", "operation")


@dataclass(frozen=True, kw_only=True)
class Bearing:
    """A complete, validated bearing with its operating point (SI; see docs/bearing.md).

    Attributes
    ----------
    title : str
    geometry : Geometry
        The ``[bearing]`` table.
    materials, lubricant, operation, model, mesh, solver, traction, thermal, empirical
        The sections of the same names (``solver`` and ``traction`` are the contact
        scene's :class:`~bearing_fem.scene.SolverSpec` and
        :class:`~bearing_fem.scene.Traction`, applied to every contact).
    """

    title: str = ""
    geometry: Geometry
    materials: BearingMaterials = field(default_factory=BearingMaterials)
    lubricant: BearingLubricant
    operation: Operation
    model: BearingModel = field(default_factory=BearingModel)
    mesh: BearingMesh = field(default_factory=BearingMesh)
    solver: SolverSpec = field(default_factory=SolverSpec)
    traction: Traction = field(default_factory=Traction)
    thermal: BearingThermal = field(default_factory=BearingThermal)
    empirical: EmpiricalOptions = field(default_factory=EmpiricalOptions)

    def __post_init__(self) -> None:
        if not isinstance(self.title, str):
            raise SceneError(f"title must be a string, got {self.title!r}")
        g, op, lub, model = self.geometry, self.operation, self.lubricant, self.model
        if op.axial_load > 0.0 and g.type == "cylindrical-roller":
            raise SceneError(f"operation.axial_load = {op.axial_load!r} N: axial loads of "
                             f"{g.type} bearings (carried by the ribs) are not modelled; "
                             "give 0 N")
        if op.axial_load > 0.0 and g.type == "tapered-roller" and g.rows % 2 and g.rows > 1:
            raise SceneError(f"operation.axial_load = {op.axial_load!r} N with bearing.rows = "
                             f"{g.rows}: an axially loaded tapered-roller bearing is modelled "
                             "with one row, or with rows in opposed pairs (an even number); "
                             "give rows = 1 or an even number, or axial_load = 0 N")
        if g.type == "angular-contact-ball" and op.axial_load <= 0.0:
            raise SceneError("operation.axial_load must be > 0 N for a single-row "
                             "angular-contact ball bearing (it cannot carry a radial load "
                             "without an axial reaction), got 0 N")
        if (g.type == "tapered-roller" and g.rows == 1 and op.axial_load > 0.0
                and op.radial_load > 0.0):
            fa_min = single_row_min_axial_load(g, op.radial_load)
            if op.axial_load <= fa_min * (1.0 + 1e-9):
                from ..analytic import harris_axial_integral, harris_radial_integral

                half = (harris_axial_integral(0.5, 10.0 / 9.0)
                        / harris_radial_integral(0.5, 10.0 / 9.0))
                tb = math.tan(math.radians(g.contact_angle))
                psi_j = math.degrees(math.acos(min(1.0, op.radial_load * tb / fa_min)))
                raise SceneError(
                    f"operation.axial_load = {op.axial_load:g} N is too small for "
                    f"operation.radial_load = {op.radial_load:g} N on one row of tapered "
                    f"rollers at {g.contact_angle:g} deg: a single row needs more than "
                    f"{fa_min:.4g} N = F_r tan(beta)/cos(psi_j), psi_j = {psi_j:.4g} deg the "
                    "azimuth of the roller nearest the load line (that roller alone loaded), "
                    f"and {half:.3g} F_r tan(beta) = {half * op.radial_load * tb:.4g} N to "
                    "load half its rollers; give the bearing's net axial load (including "
                    "the force its opposed bearing exerts), or rows = 2 for an opposed pair")
        if g.type in ROLLER_TYPES and op.radial_load <= 0.0 and not (
                g.type == "tapered-roller" and op.axial_load > 0.0):
            raise SceneError(f"operation.radial_load must be > 0 N for a {g.type} bearing"
                             + (" without axial load" if g.type == "tapered-roller" else "")
                             + ", got 0 N")
        if lub.temperature_law == "prokofiev" and op.oil_temperature is None:
            raise SceneError("operation.oil_temperature (deg C) is required by "
                             "lubricant.temperature_law = 'prokofiev'")
        if model.thermal == "patch":
            if g.is_ball:
                raise SceneError("model.thermal = 'patch' is available for line contacts "
                                 f"(roller bearings) only, got {g.type!r}")
            if lub.temperature_law != "prokofiev":
                raise SceneError("model.thermal = 'patch' needs lubricant.temperature_law "
                                 "= 'prokofiev' (reference_viscosity, exponent)")
        if (lub.temperature_law == "prokofiev" and op.oil_temperature is not None
                and op.oil_temperature <= 0.0):
            patch = model.thermal == "patch"
            raise SceneError(f"operation.oil_temperature = {op.oil_temperature:g} deg C must be "
                             "> 0 deg C with lubricant.temperature_law = 'prokofiev'"
                             + (" (and model.thermal = 'patch', which needs it)" if patch
                                else "")
                             + ": the Prokofiev law eta0(t) = reference_viscosity "
                             "(reference_temperature/t)^exponent is written in deg C and has "
                             "no value at t <= 0; for a cold start give "
                             + ("model.thermal = 'none' and " if patch else "")
                             + "lubricant.temperature_law = 'none' with lubricant.viscosity "
                             "(Pa s) at that temperature")
        if (lub.temperature_law == "prokofiev" and op.oil_temperature is not None
                and op.oil_temperature > 0.0):
            self._check_law_viscosity()
        if model.elasticity == "local" and g.is_ball:
            raise SceneError("model.elasticity = 'local' (Kodnir) is defined for line "
                             f"contacts only, got {g.type!r}")
        if model.centrifugal and g.type in ROLLER_TYPES and g.profile != "straight":
            raise SceneError("model.centrifugal with a profiled roller is not modelled; "
                             "use bearing.profile = 'straight' or model.centrifugal = false")
        self._check_skf_constants()
        self._check_skf_series()
        if self.mesh.point_nodes is not None and not g.is_ball:
            raise SceneError("mesh.point_nodes applies to ball bearings; use mesh.line_nodes")
        if self.mesh.line_nodes is not None and g.is_ball:
            raise SceneError("mesh.line_nodes applies to roller bearings; use mesh.point_nodes")
        if self.mesh.y_range is not None and not g.is_ball:
            raise SceneError("mesh.y_range applies to point contacts (ball bearings) only")
        if self.mesh.line_grading == "outlet" and (
                g.is_ball or model.elasticity != "half-space" or model.thermal != "none"):
            raise SceneError("mesh.line_grading = 'outlet' applies to the line contacts of "
                             "roller bearings with model.elasticity = 'half-space' and "
                             f"model.thermal = 'none'; got {g.type!r}, model.elasticity = "
                             f"{model.elasticity!r}, model.thermal = {model.thermal!r}")

    def _check_law_viscosity(self) -> None:
        """The Prokofiev law's viscosity at the oil temperature within the contact scenes'
        :data:`~bearing_fem.scene.VISCOSITY_RANGE` [Pa s], else a SceneError naming the
        law's fields (the contact scenes would refuse a ``lubricant.viscosity`` the bearing
        file does not contain)."""
        from ..physics.rheology import prokofiev

        lub, t = self.lubricant, float(self.operation.oil_temperature)
        eta = float(prokofiev(t, lub.reference_viscosity, lub.reference_temperature,
                              lub.exponent))
        lo, hi = VISCOSITY_RANGE
        if not lo <= eta <= hi:
            raise SceneError(
                f"lubricant.temperature_law = 'prokofiev' gives {eta:.4g} Pa s at "
                f"operation.oil_temperature = {t:g} deg C (reference_viscosity "
                f"{lub.reference_viscosity:g} Pa s at reference_temperature "
                f"{lub.reference_temperature:g} deg C, exponent {lub.exponent:g}), outside "
                f"[{lo:g}, {hi:g}] Pa s; check lubricant.reference_viscosity (Pa s at "
                "lubricant.reference_temperature, deg C), lubricant.exponent and the oil "
                "temperature")

    def _check_skf_constants(self) -> None:
        """``empirical.skf_r1 ...``: exactly the constants the SKF model of this type uses
        (:data:`SKF_CONSTANTS_USED`), each > 0; none for a type without an SKF model."""
        emp, kind = self.empirical, self.geometry.type
        given = [n for n in SKF_CONSTANT_FIELDS if getattr(emp, n) is not None]
        if not given:
            return
        used = SKF_CONSTANTS_USED.get(kind)
        if used is None:
            raise SceneError(f"empirical.{', '.join(given)}: the SKF model is implemented for "
                             f"{' and '.join(SKF_CONSTANTS_USED)} bearings only, not for "
                             f"{kind} bearings; remove the SKF constants (the Palmgren models "
                             "are evaluated for every type)")
        extra = [n for n in given if n not in used]
        if extra:
            raise SceneError(f"empirical.{extra[0]} = {getattr(emp, extra[0])!r} is not used by "
                             f"the SKF model of {kind} bearings, which takes "
                             f"{', '.join(used)} (catalogue units); remove it")
        missing = [n for n in used if n not in given]
        if missing:
            raise SceneError(f"empirical: the SKF model of {kind} bearings needs "
                             f"{', '.join('empirical.' + n for n in used)} (catalogue units); "
                             f"got only {', '.join(given)}, missing {', '.join(missing)}")
        for name in used:
            field_positive(emp, name, "(catalogue units)")

    def _check_skf_series(self) -> None:
        """``empirical.skf_series``: one listed for this type in SKF_GEOMETRY_CONSTANTS."""
        series = self.empirical.skf_series
        if series is None:
            return
        kind = self.geometry.type
        listed = sorted(s for t, s in SKF_GEOMETRY_CONSTANTS if t == kind)
        if series in listed:
            return
        have = (f"listed for {kind} bearings: {', '.join(map(repr, listed))}" if listed else
                f"no series is listed for {kind} bearings")
        hint = ""
        if listed and len(series) > 2 and series[:2] in listed:
            hint = (f"; {series!r} looks like a bearing designation: its series is "
                    f"{series[:2]!r} (skf_series = \"{series[:2]}\")")
        used = SKF_CONSTANTS_USED.get(kind)
        other = (f"; for another series give {', '.join('empirical.' + n for n in used)} from "
                 "the SKF catalogue" if used else
                 f"; the SKF model is not implemented for {kind} bearings: remove "
                 "empirical.skf_series")
        raise SceneError(f"empirical.skf_series = {series!r} (a series designation, no unit) "
                         f"is not a series with SKF geometry constants here; {have} "
                         f"(SKF_GEOMETRY_CONSTANTS){hint}{other}")

    # ------------------------------------------------------------------------------
    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> "Bearing":
        """Build a bearing from a nested mapping with the TOML layout (docs/bearing.md)."""
        hint = (" (this looks like a contact scene file: solve it with `bearing-fem solve`, "
                "or read it with Scene.from_toml)"
                if isinstance(data, Mapping) and "contact" in data else "")
        return cls(**sections_from_dict(data, _SECTIONS, _REQUIRED, "bearing", hint))

    @classmethod
    def from_toml(cls, path: str | Path) -> "Bearing":
        """Read and validate a TOML bearing file."""
        return cls.from_toml_string(read_text_file(path, "bearing file"), source=str(path))

    @classmethod
    def from_toml_string(cls, text: str, source: str = "<string>") -> "Bearing":
        """Parse and validate a bearing given as TOML text."""
        return cls.from_dict(parse_toml(text, source, "a bearing file"))

    def to_dict(self) -> dict[str, Any]:
        """Nested dict with the TOML layout (None entries omitted); round-trips via from_dict."""
        return sections_to_dict(self, _SECTIONS)

    def replace(self, **sections: Any) -> "Bearing":
        """Copy with whole sections replaced (``dataclasses.replace``)."""
        return replace(self, **sections)


def kelvin_like_temperatures(bearing: Bearing) -> list[tuple[str, float]]:
    """The temperatures of a bearing that look like kelvin: ``operation.oil_temperature``
    and, when the Prokofiev law uses it, ``lubricant.reference_temperature``, above
    :data:`KELVIN_WARNING_TEMPERATURE`.

    Parameters
    ----------
    bearing : Bearing

    Returns
    -------
    list of (str, float)
        The field's name and its value [deg C], for :func:`input_warnings` (and the bearing
        solve, which leaves out the contacts' own warnings about these fields).
    """
    temps = [("operation.oil_temperature", bearing.operation.oil_temperature)]
    if bearing.lubricant.temperature_law == "prokofiev":
        temps.append(("lubricant.reference_temperature",
                      bearing.lubricant.reference_temperature))
    return [(name, float(t)) for name, t in temps
            if t is not None and t > KELVIN_WARNING_TEMPERATURE]


def input_warnings(bearing: Bearing) -> list[str]:
    """Warnings about accepted values that look like a unit slip or limit the accuracy
    (:func:`~bearing_fem.bearing.solve_bearing` puts them first in the bearing's
    ``warnings``).

    * ``operation.oil_temperature``, or ``lubricant.reference_temperature`` of the
      Prokofiev law, above :data:`KELVIN_WARNING_TEMPERATURE` [deg C]: it looks like kelvin
      (:func:`kelvin_like_temperatures`; the bearing's warnings then leave out the contacts'
      own warning about a hot oil);
    * a profiled roller with fewer than :data:`MIN_RECOMMENDED_SLICES` slices: the error
      bars exclude the slicing error, which is then of several per cent;
    * ``operation.oil_temperature`` more than
      :data:`bearing_fem.contacts.coupling.PIEZO_TABLE_EXTRAPOLATION_K` outside the
      ``piezo_temperatures`` table: alpha is extrapolated there;
    * ``lubricant.piezo`` = 0 (its default) without a ``piezo_values`` table and with a
      Barus or Roelands law: the contacts are isoviscous (``viscosity_law = "constant"``
      says that this is meant);
    * a tapered roller bearing with an odd number of rows and no axial load: the model
      takes its rows in opposed pairs (docs/bearing.md 2.3), so a single row is treated as
      one row of such a pair, its induced axial force reacted by the opposed bearing.

    Returns
    -------
    list of str
    """
    out = []
    for name, t in kelvin_like_temperatures(bearing):
        out.append(f"{name} = {t:g} deg C is above {KELVIN_WARNING_TEMPERATURE:g} deg C, "
                   "hotter than lubricating oils run (mineral oils oxidise and degrade above "
                   "about 150 deg C): temperatures are in deg C, and this looks like kelvin "
                   f"({_kelvin(t)})")
    g = bearing.geometry
    if not g.is_ball and g.profile != "straight" and g.n_slices < MIN_RECOMMENDED_SLICES:
        out.append(f"bearing.slices = {g.n_slices}, below the recommended minimum of "
                   f"{MIN_RECOMMENDED_SLICES} for a {g.profile} roller: the error estimates "
                   "are the grid discretisation errors of each slice's contact and exclude "
                   "the slicing error along the roller, which with so few slices is several "
                   "per cent (docs/bearing.md, \"Slicing error\")")
    lub = bearing.lubricant
    if lub.piezo == 0.0 and lub.piezo_values is None and lub.viscosity_law != "constant":
        out.append("lubricant.piezo = 0 1/Pa (its default when left out): every contact is "
                   "isoviscous, with films several times thinner than those of a "
                   "piezo-viscous oil (mineral oils have 1e-8..3e-8 1/Pa); give the oil's "
                   "pressure-viscosity coefficient in 1/Pa, or lubricant.viscosity_law = "
                   "\"constant\" for an isoviscous lubricant")
    if lub.temperature_law != "none":
        from ..contacts.coupling import piezo_table_warning

        note = piezo_table_warning(lub, bearing.operation.oil_temperature,
                                   "operation.oil_temperature =")
        if note is not None:
            out.append(note)
    if g.type == "tapered-roller" and g.rows % 2 and bearing.operation.axial_load == 0.0:
        out.append(f"bearing.rows = {g.rows} for a tapered-roller bearing without axial load: "
                   "each row is taken as one row of an opposed pair (face-to-face or "
                   "back-to-back) whose other bearing reacts its induced axial force "
                   "(docs/bearing.md 2.3); for a single row under a combined load give "
                   "operation.axial_load (N), the bearing's net axial load")
    return out


def iso76_static_load_rating(geometry: Geometry) -> float:
    """Basic static radial load rating C0 [N] of the geometry by ISO 76.

    Ball bearings: C0 = f0 i Z D_w^2 cos(alpha) with f0 = :data:`ISO76_BALL_FACTOR`;
    roller bearings: C0 = 44 (1 - D_w cos(alpha)/d_m) i Z l_we D_w cos(alpha)
    (i rows, Z elements per row, lengths in mm, C0 in N). An order of magnitude for
    checking ``bearing.static_load_rating``, not a rating.

    Parameters
    ----------
    geometry : Geometry

    Returns
    -------
    float
        C0 [N].
    """
    g = geometry
    cos_a = math.cos(math.radians(g.contact_angle or 0.0))
    dw_mm = 1e3 * g.element_diameter
    if g.is_ball:
        return ISO76_BALL_FACTOR * g.rows * g.elements * dw_mm**2 * cos_a
    gamma = g.element_diameter * cos_a / g.mean_diameter
    return 44.0 * (1.0 - gamma) * g.rows * g.elements * 1e3 * g.effective_length \
        * dw_mm * cos_a


def single_row_min_axial_load(geometry: Geometry, radial_load: float) -> float:
    """Smallest axial load [N] that one row of angled elements balances with a radial load.

    The limit of a row whose axial displacement draws back until only the element nearest
    the load line (azimuth psi_j closest to 0) carries: F_a -> F_r tan(beta) / cos(psi_j).
    Below it no ring position balances the two loads (the rest of the induced axial force
    must come from an opposed bearing).

    Parameters
    ----------
    geometry : Geometry
        ``contact_angle`` beta [deg], ``elements`` and ``first_element_azimuth`` [deg].
    radial_load : float
        F_r [N], >= 0.

    Returns
    -------
    float
        F_a limit [N] (inf if no element lies within 90 deg of the load line).
    """
    z = geometry.elements
    psi0 = math.radians(geometry.first_element_azimuth)
    cos_max = max(math.cos(psi0 + 2.0 * math.pi * j / z) for j in range(z))
    if cos_max <= 0.0:
        return math.inf
    return float(radial_load) * math.tan(math.radians(geometry.contact_angle)) / cos_max


def example_names() -> list[str]:
    """Names of the example bearings shipped in ``bearing_fem/bearings/``."""
    from importlib import resources

    files = resources.files("bearing_fem") / "bearings"
    return sorted(p.name[:-5] for p in files.iterdir() if p.name.endswith(".toml"))


def load_example(name: str) -> Bearing:
    """Load an example bearing shipped with the package (e.g. ``"6209"``)."""
    from importlib import resources

    available = example_names()
    if name not in available:
        raise SceneError(f"unknown example bearing {name!r}; available: "
                         f"{', '.join(available)}")
    text = (resources.files("bearing_fem") / "bearings" / f"{name}.toml").read_text(
        encoding="utf-8")
    return Bearing.from_toml_string(text, source=f"example bearing {name!r}")

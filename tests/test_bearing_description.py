"""Bearing files: examples, round trips, validation messages, the top-level API."""
from __future__ import annotations

import copy
import math

import pytest

import bearing_fem as bf
from bearing_fem.bearing import Bearing, example_names, load_example
from bearing_fem.bearing.description import input_warnings
from bearing_fem.errors import SceneError

EXAMPLES = ("6209", "7010-steel", "7010-hybrid", "nncf5040", "30205")


def test_examples_shipped_and_round_trip():
    assert set(EXAMPLES) <= set(example_names()), "the example bearings are package data"
    for name in EXAMPLES:
        b = load_example(name)
        again = Bearing.from_dict(b.to_dict())
        assert again == b, f"{name}: to_dict/from_dict must round-trip"
        assert b.to_dict()["bearing"]["type"] == b.geometry.type, "[bearing] is the geometry"
    hybrid, steel = load_example("7010-hybrid"), load_example("7010-steel")
    assert hybrid.materials.element == (3.10e11, 0.26), "Si3N4 preset: E = 310 GPa, nu = 0.26"
    assert steel.materials.element == steel.materials.ring, "all-steel bearing"


def test_top_level_lazy_names():
    assert bf.Bearing is Bearing
    assert bf.solve_bearing is bf.bearing.solve_bearing


def test_from_toml_file(tmp_path):
    text = (
        'title = "t"\n[bearing]\ntype = "deep-groove-ball"\nbore = 0.045\n'
        'outside_diameter = 0.085\nelement_diameter = 0.0127\nelements = 9\n'
        '[lubricant]\nviscosity = 0.03\npiezo = 2e-8\n[operation]\ninner_rpm = 1000\n'
        'radial_load = 1000\n')
    path = tmp_path / "b.toml"
    path.write_text(text)
    b = Bearing.from_toml(path)
    assert b.geometry.mean_diameter == pytest.approx(0.065), "d_m defaults to (d + D)/2"
    assert (b.geometry.inner_conformity, b.geometry.outer_conformity) == (0.52, 0.53), \
        "documented conformity defaults"
    with pytest.raises(SceneError, match="cannot read bearing file"):
        Bearing.from_toml(tmp_path / "missing.toml")
    path.write_text("[bearing\n")
    with pytest.raises(SceneError, match="not valid TOML"):
        Bearing.from_toml(path)
    path.write_bytes(b"title = '\xff'\n")
    with pytest.raises(SceneError, match=r"bearing file .*b\.toml' is not UTF-8 text"):
        Bearing.from_toml(path)


def _base() -> dict:
    return copy.deepcopy(load_example("6209").to_dict())


@pytest.mark.parametrize("section, key, value, pattern", [
    ("bearing", "bore", -0.045, r"bearing\.bore must be > 0 m, got -0\.045"),
    # millimetres given as metres
    ("bearing", "bore", 45, r"bearing\.bore = 45\.0 m lies outside the plausible "
                            r"\[0\.0001, 10\] m; dimensions are in metres"),
    ("bearing", "element_diameter", 12.7, r"bearing\.element_diameter = 12\.7 m lies outside"),
    ("bearing", "outside_diameter", 0.04, r"outside_diameter = 0\.04 m must exceed"),
    ("bearing", "elements", 40, r"elements = 40 elements of 0\.0127 m do not fit"),
    ("bearing", "elements", 2.5, r"bearing\.elements must be an integer"),
    ("bearing", "inner_conformity", 0.49, r"inner_conformity = r/D_w must lie in \(0\.5, 0\.6\]"),
    ("bearing", "radial_clearance", -1e-6, r"radial_clearance must be >= 0 m"),
    # micrometres given as millimetres: the free contact angle would pass 60 deg
    ("bearing", "radial_clearance", 7.5e-3, r"radial_clearance = 0\.0075 m exceeds .* m, "
                                            r"the clearance of a free contact angle of 60"),
    ("bearing", "contact_angle", 15.0, r"contact_angle applies to angular-contact"),
    ("bearing", "type", "spherical", r"bearing\.type must be one of"),
    ("bearing", "effective_length", 0.01, r"effective_length applies to roller bearings"),
    ("lubricant", "viscosity", 0.0, r"lubricant\.viscosity must lie in \[1e-06, 1e\+06\] Pa s, got 0\.0"),
    ("lubricant", "piezo", 1e-5, r"lubricant\.piezo must be <= 1e-6 1/Pa"),
    ("operation", "inner_rpm", -5, r"operation\.inner_rpm must be > 0 1/min"),
    ("operation", "radial_load", "4 kN", r"operation\.radial_load must be a number in N"),
    ("model", "roughness", 0.0, r"model\.roughness must be > 0 m"),
    ("mesh", "point_nodes", [65], r"mesh\.point_nodes must be two integers"),
    ("solver", "tolerance", 0.5, r"solver\.tolerance must be < 0\.1"),
    ("materials", "elements", "glass", r"materials\.elements must be one of 'steel', 'si3n4'"),
    ("materials", "ring_poisson", 0.6, r"materials\.ring_poisson must lie in \(-1, 0\.5\]"),
    ("mesh", "x_range", [-2.0e3, 2.0], r"mesh\.x_range must lie within \[-1000, 1000\]"),
    ("mesh", "x_range", [1.0, 2.0], r"mesh\.x_range must satisfy start < 0 < end"),
    # metres given for Hertz half-widths: the domain missed the contact
    ("mesh", "x_range", [-0.0005, 0.0003],
     r"mesh\.x_range = \[-0\.0005, 0\.0003\] \(in Hertz half-widths\) does not contain the "
     r"Hertz zone \[-1, 1\]: the range is in units of the Hertz half-width, not in metres"),
    ("mesh", "y_range", [-3.0, 0.5], r"mesh\.y_range = \[-3, 0\.5\] \(in Hertz half-widths\) "
                                     r"does not contain the Hertz zone"),
    ("lubricant", "piezo_values", [2e-8],
     r"give both lubricant\.piezo_temperatures .* and lubricant\.piezo_values"),
])
def test_invalid_values_name_field_value_unit(section, key, value, pattern):
    d = _base()
    d.setdefault(section, {})[key] = value
    with pytest.raises(SceneError, match=pattern):
        Bearing.from_dict(d)


def test_unknown_and_missing_keys():
    d = _base()
    d["bearing"]["diameter"] = 1.0
    with pytest.raises(SceneError, match=r"unknown key\(s\) bearing\.diameter; known keys of "
                                         r"\[bearing\]: type, bore"):
        Bearing.from_dict(d)
    d = _base()
    d["contact"] = {"kind": "line"}
    with pytest.raises(SceneError, match="looks like a contact scene file: solve it with "
                                         "`bearing-fem solve`"):
        Bearing.from_dict(d)
    d = _base()
    del d["operation"]
    with pytest.raises(SceneError, match=r"missing bearing section \[operation\]"):
        Bearing.from_dict(d)
    d = _base()
    del d["bearing"]["elements"]
    with pytest.raises(SceneError, match=r"missing key\(s\) bearing\.elements"):
        Bearing.from_dict(d)


def test_cross_section_rules():
    d = copy.deepcopy(load_example("7010-steel").to_dict())
    d["operation"]["axial_load"] = 0.0
    with pytest.raises(SceneError, match="axial_load must be > 0 N for a single-row "
                                         "angular-contact"):
        Bearing.from_dict(d)
    d = copy.deepcopy(load_example("nncf5040").to_dict())
    d["operation"]["axial_load"] = 100.0
    with pytest.raises(SceneError, match="axial loads of cylindrical-roller bearings"):
        Bearing.from_dict(d)
    d = copy.deepcopy(load_example("nncf5040").to_dict())
    d["bearing"]["profile"] = "crowned"
    with pytest.raises(SceneError, match=r"bearing\.crown_drop \(m\) is required"):
        Bearing.from_dict(d)
    d["bearing"]["crown_drop"] = 1e-5
    assert Bearing.from_dict(d).geometry.n_slices == 11, "profiled rollers default to 11 slices"
    d["bearing"]["crown_drop"] = 0.02  # 20 um given as mm: accepted before, a 1-slice contact
    with pytest.raises(SceneError, match=r"bearing\.crown_drop = 0\.02 m exceeds .* \(0\.01 "
                                         r"of the roller diameter\)"):
        Bearing.from_dict(d)
    d = copy.deepcopy(load_example("nncf5040").to_dict())
    del d["operation"]["oil_temperature"]
    with pytest.raises(SceneError, match="oil_temperature .* is required"):
        Bearing.from_dict(d)
    d = _base()
    d["model"]["thermal"] = "patch"
    with pytest.raises(SceneError, match="line contacts .* only"):
        Bearing.from_dict(d)


def test_roller_clearance_in_the_wrong_unit_is_refused():
    d = copy.deepcopy(load_example("nncf5040").to_dict())
    d["bearing"]["radial_clearance"] = 0.1  # 100 um meant, given as mm
    with pytest.raises(SceneError, match=r"bearing\.radial_clearance = 0\.1 m exceeds .* m "
                                         r"\(0\.05 of the roller diameter\)"):
        Bearing.from_dict(d)


@pytest.mark.parametrize("key, value, pattern", [
    ("inner_rpm", 1e7, r"operation\.inner_rpm = 10000000\.0 1/min gives element 0's inner "
                       r"contact an entrainment speed of .* m/s, which its contact model "
                       r"refuses: kinematics\.u1 must lie in"),
    # the load distribution turns the opposite balls' contact angles past 90 deg (from
    # ~3e5 N on this 6209; it ended in the contact model's refusal of load.force before)
    ("radial_load", 1e9, r"operation\.radial_load = 1000000000\.0 N and operation\.axial_load "
                         r"= 0\.0 N displace the rings so far that element 3's contact angle "
                         r"is 180 deg"),
])
def test_contact_refusals_name_the_bearing_fields(key, value, pattern):
    """The contact scenes' fields (kinematics.u1, load.force) are not in a bearing file:
    a refusal names the operation field that caused it."""
    d = _base()
    d["operation"][key] = value
    with pytest.raises(SceneError, match=pattern):
        bf.solve_bearing(Bearing.from_dict(d))


def _roller() -> dict:
    return copy.deepcopy(load_example("nncf5040").to_dict())


def _angular() -> dict:
    return copy.deepcopy(load_example("7010-steel").to_dict())


@pytest.mark.parametrize("value, without_width, pattern", [
    # 10 mm given as 10.0 m: inside BEARING_LENGTH_RANGE, accepted and solved before
    (10.0, True, r"bearing\.effective_length = 10\.0 m exceeds 20 roller diameters \(0\.55 m"
                 r"; needle rollers reach about 10\); dimensions are in metres \(an "
                 r"effective length of 10 mm is 0\.01\)"),
    # plausible alone, but two rows of them do not fit in the 150 mm width
    (0.1, False, r"bearing\.effective_length = 0\.1 m does not fit in bearing\.width = 0\.15 "
                 r"m: 2 row\(s\) of rollers that long span 0\.2 m axially"),
    (0.2, True, None),  # without a width only the diameter ratio applies
])
def test_roller_length_in_the_wrong_unit_or_beyond_the_width_is_refused(value, without_width,
                                                                        pattern):
    d = _roller()
    d["bearing"]["effective_length"] = value
    if without_width:
        del d["bearing"]["width"]
    if pattern is None:
        assert Bearing.from_dict(d).geometry.effective_length == value
        return
    with pytest.raises(SceneError, match=pattern):
        Bearing.from_dict(d)


@pytest.mark.parametrize("name, value, hint", [
    ("pitch_diameter", 65, "a pitch diameter of 65 mm is 0.065"),
    ("outside_diameter", 85.0, "an outside diameter of 85 mm is 0.085"),
    ("bore", 45, "a bore of 45 mm is 0.045"),
    ("width", 1e-5, "a width below 0.1 mm is no bearing dimension"),
])
def test_length_hint_uses_the_fields_own_value(name, value, hint):
    """The hint was "(a 45 mm bore is 0.045)" for every length field."""
    d = _base()
    d["bearing"][name] = value
    with pytest.raises(SceneError) as err:
        Bearing.from_dict(d)
    assert f"bearing.{name} = {float(value)!r} m" in str(err.value), str(err.value)
    assert hint in str(err.value), str(err.value)
    if name != "bore":
        assert "45 mm bore" not in str(err.value), str(err.value)


@pytest.mark.parametrize("name", ["element_modulus", "ring_modulus"])
@pytest.mark.parametrize("value", [208, 208.0e15, float("inf")])
def test_moduli_in_gpa_are_refused_where_read(name, value):
    """208 (GPa meant) ended in a load-distribution refusal that blamed the loads."""
    d = _base()
    d["materials"][name] = value
    with pytest.raises(SceneError, match=rf"materials\.{name}") as err:
        Bearing.from_dict(d)
    text = str(err.value)
    assert "Pa" in text and "load" not in text, text
    if math.isfinite(value):
        assert (f"materials.{name} = {float(value)!r} Pa lies outside the plausible "
                "[1e+09, 2e+12] Pa of bearing materials; moduli are in Pa ("
                + ("208 GPa is 2.08e+11" if value < 1e4 else "e.g. 208 GPa is 2.08e+11")
                + ")") in text, text
    d["materials"][name] = 3.1e11
    assert getattr(Bearing.from_dict(d).materials, name) == 3.1e11, "Si3N4 is accepted"


@pytest.mark.parametrize("value, hint", [
    (208.0, "(208 GPa is 2.08e+11)"), (208000.0, "(208000 MPa is 2.08e+11)"),
    (0.2, "(e.g. 208 GPa is 2.08e+11)"),  # 0.2 GPa = 2e8 Pa: still outside the range
])
def test_modulus_hint_names_a_unit_only_when_its_reading_is_accepted(value, hint):
    d = _base()
    d["materials"]["element_modulus"] = value
    with pytest.raises(SceneError) as err:
        Bearing.from_dict(d)
    assert str(err.value).endswith("moduli are in Pa " + hint), str(err.value)


@pytest.mark.parametrize("value, hint", [
    (0.2, "(0.2 um is 2e-07)"), (0.0002, "(0.0002 mm is 2e-07)"),
    (2e-5, "(e.g. 0.2 um is 2e-07)"),  # 20 um in metres: too rough, not 2e-05 mm = 20 nm
    (50.0, "(e.g. 0.2 um is 2e-07)"),  # 50 um: too rough in any unit
])
def test_roughness_hint_names_a_unit_only_when_its_reading_is_accepted(value, hint):
    d = _base()
    d["model"]["roughness"] = value
    with pytest.raises(SceneError) as err:
        Bearing.from_dict(d)
    assert str(err.value).endswith("the roughness is in metres " + hint), str(err.value)


def test_roughness_in_micrometres_is_refused():
    d = _base()
    d["model"]["roughness"] = 0.2
    with pytest.raises(SceneError, match=r"model\.roughness = 0\.2 m exceeds 1e-05 m .*the "
                                         r"roughness is in metres \(0\.2 um is 2e-07\)"):
        Bearing.from_dict(d)
    d["model"]["roughness"] = 2e-7
    assert Bearing.from_dict(d).model.roughness == 2e-7


def test_oil_temperature_in_kelvin_warns_and_beyond_500_is_refused():
    """docs/bearing.md: temperatures in deg C; 353 (K meant) was accepted silently."""
    d = _base()
    assert input_warnings(Bearing.from_dict(d)) == [], "60 deg C is ordinary"
    d["operation"]["oil_temperature"] = 353.0
    (w,) = input_warnings(Bearing.from_dict(d))
    assert w.startswith("operation.oil_temperature = 353 deg C is above 200 deg C"), w
    assert "looks like kelvin (353 K is 79.85 deg C)" in w, w
    d["operation"]["oil_temperature"] = 600.0
    with pytest.raises(SceneError, match=r"operation\.oil_temperature = 600 deg C lies above "
                                         r"500 deg C: that is no oil temperature .*this looks "
                                         r"like kelvin \(600 K is 326\.85 deg C\)"):
        Bearing.from_dict(d)


def test_contact_angle_in_radians_or_missing():
    """0.26 (rad meant) was taken as 0.26 deg; a missing angle was reported as 0.0 deg."""
    d = _angular()
    d["bearing"]["contact_angle"] = 0.26
    with pytest.raises(SceneError, match=r"bearing\.contact_angle = 0\.26 deg is below 2 deg "
                                         r"for an angular-contact-ball bearing: the angle is "
                                         r"in degrees, and 0\.26 looks like radians \(0\.26 "
                                         r"rad is 14\.9 deg\)"):
        Bearing.from_dict(d)
    del d["bearing"]["contact_angle"]
    with pytest.raises(SceneError) as err:
        Bearing.from_dict(d)
    assert str(err.value).startswith("bearing.contact_angle (deg) is required for an "
                                     "angular-contact-ball bearing"), str(err.value)
    assert "0.0 deg" not in str(err.value), str(err.value)
    d["bearing"]["contact_angle"] = 75.0
    with pytest.raises(SceneError, match=r"contact_angle = 75\.0 deg must lie in \[2, 60\] "
                                         r"deg for an angular-contact-ball bearing"):
        Bearing.from_dict(d)
    g = Bearing.from_dict(_base()).geometry
    assert g.contact_angle == 0.0, "deep-groove: none given is 0 deg (documented default)"


def test_unlisted_skf_series_is_an_error():
    """empirical.skf_series = "6" made the SKF model 'unavailable' in the results only."""
    d = _base()
    d["empirical"]["skf_series"] = "6"
    with pytest.raises(SceneError, match=r"empirical\.skf_series = '6' \(a series designation, "
                                         r"no unit\) is not a series with SKF geometry "
                                         r"constants here; listed for deep-groove-ball "
                                         r"bearings: '60', '62', '63', '64'"):
        Bearing.from_dict(d)
    d = _roller()
    d.setdefault("empirical", {})["skf_series"] = "62"
    with pytest.raises(SceneError, match=r"no series is listed for cylindrical-roller "
                                         r"bearings .* give empirical\.skf_r1"):
        Bearing.from_dict(d)
    d["empirical"] = {"skf_r1": 1e-6, "skf_s1": 1e-3}
    with pytest.raises(SceneError, match=r"the SKF model of cylindrical-roller bearings needs "
                                         r"empirical\.skf_r1, empirical\.skf_s1, "
                                         r"empirical\.skf_s2 .* got only skf_r1, skf_s1, "
                                         r"missing skf_s2"):
        Bearing.from_dict(d)


@pytest.mark.parametrize("field, value, unit", [
    ("density", 0.87, "kg/m\\^3"), ("density", 1e-300, "kg/m\\^3"),
    ("specific_heat", 2.0, "J/\\(kg K\\)"), ("thermal_conductivity", 130.0, "W/\\(m K\\)"),
    ("viscosity", 1e-300, "Pa s")])
def test_oil_properties_outside_any_oil_are_refused(field, value, unit):
    """Oil density, conductivity and specific heat in g/cm^3, mW or kJ (or absurd values)
    are refused naming the field, the value and the unit (they overflowed Nikitin's
    criteria); the viscosity takes the contact scenes' range."""
    d = copy.deepcopy(load_example("7010-steel").to_dict())
    d["lubricant"][field] = value
    with pytest.raises(SceneError, match=rf"lubricant\.{field} must lie in .* {unit}, got "):
        Bearing.from_dict(d)


def test_nikitin_overflow_is_reported_not_raised():
    """Accepted extremes that still overflow Nikitin's criteria (Re = u d_b / nu with a gas
    viscosity and a light fluid at high speed) give an unavailable model, never an
    exception or a non-finite number."""
    import json

    from bearing_fem.bearing.empirical import _nikitin_entry

    b = load_example("7010-steel")
    entry = _nikitin_entry(b, 1e300, 1e-9, 500.0, 2000.0, 1.0)
    assert entry["available"] is False and "overflow" in entry["reason"], entry
    ok = _nikitin_entry(b, 10000.0, 1e-5, 500.0, 2000.0, 1047.2)
    assert ok["heat_power"] > 0.0
    json.dumps([entry, ok], allow_nan=False)


@pytest.mark.parametrize("t_ref", [5e-324, 1e-3])
def test_prokofiev_viscosity_outside_the_scenes_range_names_the_law(t_ref):
    """A reference temperature near 0 deg C drives the Prokofiev viscosity at the oil
    temperature to ~0 Pa s: refused naming the law's fields, not a lubricant.viscosity
    the bearing file does not contain."""
    d = copy.deepcopy(load_example("nncf5040").to_dict())
    d["lubricant"]["reference_temperature"] = t_ref
    with pytest.raises(SceneError, match=r"lubricant\.temperature_law = 'prokofiev' gives "
                                         r".* Pa s at operation\.oil_temperature = 40 deg C"):
        Bearing.from_dict(d)


def test_oil_temperature_far_outside_the_piezo_table_warns():
    """The NNCF 5040 table spans [30, 150] deg C: 40 deg C is inside, 10 deg C is more
    than 10 K below it (ln alpha extrapolated) and is named with the alpha it gives."""
    d = load_example("nncf5040").to_dict()
    assert not any("piezo_temperatures" in w for w in input_warnings(Bearing.from_dict(d)))
    d["operation"]["oil_temperature"] = 10.0
    notes = [w for w in input_warnings(Bearing.from_dict(d)) if "piezo_temperatures" in w]
    assert len(notes) == 1 and notes[0].startswith("operation.oil_temperature = 10 deg C "
                                                   "lies outside the piezo_temperatures "
                                                   "table [30, 150] deg C"), notes


def test_ball_bearing_narrower_than_its_balls_is_refused():
    """A width of 0.001 m for the 6209 (D_w = 12.7 mm, B = 19 mm) was accepted unused."""
    d = load_example("6209").to_dict()
    d["bearing"]["width"] = 0.019
    assert Bearing.from_dict(d).geometry.width == 0.019
    d["bearing"]["width"] = 0.001
    with pytest.raises(SceneError, match=r"bearing\.width = 0\.001 m is narrower than the "
                                         r"balls \(bearing\.element_diameter = 0\.0127"):
        Bearing.from_dict(d)


@pytest.mark.parametrize("example, dm, side", [
    ("6209", 0.055, "inner raceway d_m - D_w cos(alpha) = 0.0423 m lies inside the bore"),
    ("6209", 0.075, "outer raceway d_m + D_w cos(alpha) = 0.0877 m lies beyond the outside"),
    # tapered rollers at 13.9 deg: 46 + 6.75 cos(13.9 deg) = 52.55 mm beyond the 52 mm ring
    ("30205", 0.046, "outer raceway d_m + D_w cos(alpha) = 0.05255 m lies beyond the outside"),
])
def test_pitch_diameter_that_puts_the_raceways_outside_the_rings_is_refused(example, dm,
                                                                            side):
    """A pitch diameter between d and D but off-centre (0.030 m for a 6205, d = 25 mm,
    D_w = 7.94 mm) was accepted: its inner raceway, d_m - D_w = 22 mm, lay inside the bore,
    and the bearing was solved on that geometry."""
    d = load_example(example).to_dict()
    g = load_example(example).geometry
    d["bearing"]["pitch_diameter"] = g.mean_diameter
    assert Bearing.from_dict(d).geometry.mean_diameter == g.mean_diameter, \
        "the example's own pitch diameter stays valid"
    d["bearing"]["pitch_diameter"] = dm
    with pytest.raises(SceneError, match=rf"bearing\.pitch_diameter = {dm:g} m puts the "
                                         r"elements \(D_w = .* m\) outside the rings") as err:
        Bearing.from_dict(d)
    assert side in str(err.value), str(err.value)


def test_left_out_piezo_coefficient_warns_that_the_contacts_are_isoviscous():
    """lubricant.piezo defaults to 0: a bearing file without it was solved isoviscous with
    no word (a 6205 at 6000 rpm: h_min 0.054 um instead of 0.33 um with 2.1e-8 1/Pa).
    The warning names the field and the unit; an isoviscous oil says so with
    viscosity_law = "constant", and a piezo table (Prokofiev law) needs no piezo."""
    for name in EXAMPLES:
        assert not any("lubricant.piezo" in w for w in input_warnings(load_example(name))), \
            f"{name}: the shipped examples give a pressure-viscosity coefficient"
    d = load_example("6209").to_dict()
    del d["lubricant"]["piezo"]
    notes = [w for w in input_warnings(Bearing.from_dict(d)) if "lubricant.piezo" in w]
    assert len(notes) == 1 and notes[0].startswith(
        "lubricant.piezo = 0 1/Pa (its default when left out): every contact is isoviscous"), \
        notes
    d["lubricant"]["viscosity_law"] = "constant"
    assert not any("lubricant.piezo" in w for w in input_warnings(Bearing.from_dict(d))), \
        "an isoviscous oil given as such"
    d = load_example("nncf5040").to_dict()
    assert d["lubricant"].get("piezo", 0.0) == 0.0 and d["lubricant"]["piezo_values"], \
        "the NNCF 5040 takes alpha from its table"
    del d["lubricant"]["piezo_temperatures"], d["lubricant"]["piezo_values"]
    assert any(w.startswith("lubricant.piezo = 0 1/Pa")
               for w in input_warnings(Bearing.from_dict(d))), "no table and no piezo"

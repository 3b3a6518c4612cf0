"""Bearing files: examples, round trips, validation messages, the top-level API."""
from __future__ import annotations

import copy

import pytest

import bearing_fem as bf
from bearing_fem.bearing import Bearing, example_names, load_example
from bearing_fem.errors import SceneError

EXAMPLES = ("6209", "7010-steel", "7010-hybrid", "nncf5040")


def test_examples_shipped_and_round_trip():
    assert set(EXAMPLES) <= set(example_names()), "the four example bearings are package data"
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
    ("lubricant", "viscosity", 0.0, r"lubricant\.viscosity must be > 0 Pa s"),
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

"""Bearing files: accepted edge values (cold oil, 60 deg, the SKF constants of a type),
the bearing's warnings (once, in the bearing file's terms, failures by their reason), a
truncated inlet, and the files and figures of failed contacts."""
from __future__ import annotations

import copy
import json
import re

import numpy as np
import pytest

from bearing_fem import cli, io
from bearing_fem.bearing import Bearing, load_example, solve_bearing
from bearing_fem.bearing.description import input_warnings, iso76_static_load_rating
from bearing_fem.bearing.contacts import contact_specs
from bearing_fem.bearing.empirical import empirical_models
from bearing_fem.bearing.kinematics import element_kinematics
from bearing_fem.bearing.loads import distribute_loads
from bearing_fem.errors import SceneError

from test_bearing_solve import small_roller  # noqa: E402  (tests/ is on sys.path)


def _example(name: str) -> dict:
    return copy.deepcopy(load_example(name).to_dict())


def _specs(b: Bearing):
    dist = distribute_loads(b)
    kin = element_kinematics(b.operation.inner_speed, b.geometry.mean_diameter,
                             b.geometry.element_diameter, dist.alpha_inner, dist.alpha_outer)
    return contact_specs(b, dist, kin)


# ---------------------------------------------------------------------------------------
# accepted and refused values
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("t", [-20.0, 0.0, -60.0])
def test_cold_oil_is_accepted_without_a_temperature_law(t):
    d = _example("6209")
    d["operation"]["oil_temperature"] = t
    assert Bearing.from_dict(d).operation.oil_temperature == t, "a cold start is valid input"


def test_oil_temperatures_refused_where_they_are_used():
    d = small_roller().to_dict()
    d["lubricant"] = {"temperature_law": "prokofiev", "reference_viscosity": 0.06,
                      "exponent": 2.9, "piezo": 2e-8}
    d["operation"]["oil_temperature"] = -20.0
    with pytest.raises(SceneError, match=r"operation\.oil_temperature = -20 deg C must be > 0 "
                                         r"deg C with lubricant\.temperature_law = 'prokofiev'"):
        Bearing.from_dict(d)
    d["operation"]["oil_temperature"] = 600.0
    with pytest.raises(SceneError, match=r"operation\.oil_temperature = 600 deg C lies above 500 "
                                         r"deg C: .*oils decompose long before.*600 K is "
                                         r"326\.85 deg C"):
        Bearing.from_dict(d)
    d["operation"]["oil_temperature"] = -80.0
    with pytest.raises(SceneError, match=r"operation\.oil_temperature = -80 deg C lies below "
                                         r"-60 deg C"):
        Bearing.from_dict(d)
    d["operation"]["oil_temperature"] = 60.0
    d["lubricant"]["reference_temperature"] = 600.0
    with pytest.raises(SceneError, match=r"^lubricant\.reference_temperature = 600 deg C lies "
                                         r"above 500 deg C: .*600 K is 326\.85 deg C"):
        Bearing.from_dict(d)


def test_cold_oil_with_the_thermal_patch_names_the_patch_first():
    """model.thermal = 'patch' without the Prokofiev law is refused for that, whatever the
    oil temperature; with it, a cold oil's hint also names model.thermal = 'none'."""
    with pytest.raises(SceneError, match=r"model\.thermal = 'patch' needs "
                                         r"lubricant\.temperature_law = 'prokofiev'"):
        small_roller(operation={"oil_temperature": -10}, model={"thermal": "patch"})
    with pytest.raises(SceneError) as err:
        small_roller(operation={"oil_temperature": -10}, model={"thermal": "patch"},
                     lubricant={"temperature_law": "prokofiev", "viscosity": None,
                                "reference_viscosity": 0.06, "exponent": 2.9})
    text = str(err.value)
    assert text.startswith("operation.oil_temperature = -10 deg C must be > 0 deg C"), text
    assert "give model.thermal = 'none' and lubricant.temperature_law = 'none'" in text, text


def test_contact_angle_of_60_deg_is_accepted():
    d = _example("7010-steel")
    d["bearing"]["contact_angle"] = 60.0
    b = Bearing.from_dict(d)
    assert b.geometry.contact_angle == 60.0, "ball-screw support bearings have 60 deg"
    dist = distribute_loads(b)  # the load distribution holds at 60 deg
    assert dist.load_inner.max() > 0.0, dist.load_inner
    d["bearing"]["contact_angle"] = 60.5
    with pytest.raises(SceneError, match=r"contact_angle = 60\.5 deg must lie in \[2, 60\] deg"):
        Bearing.from_dict(d)


def test_skf_constants_are_those_of_the_type():
    d = small_roller().to_dict()
    d["empirical"] = {"skf_r1": 1.12e-6, "skf_s1": 0.17, "skf_s2": 0.0048}
    b = Bearing.from_dict(d)
    skf = empirical_models(b)["skf"]
    assert skf.get("torque", 0.0) > 0.0, skf
    d["empirical"]["skf_r2"] = 0.0
    with pytest.raises(SceneError, match=r"empirical\.skf_r2 = 0\.0 is not used by the SKF "
                                         r"model of cylindrical-roller bearings"):
        Bearing.from_dict(d)
    a = _example("7010-steel")
    a["empirical"] = {"skf_r1": 4e-7, "skf_r2": 1.7, "skf_s1": 3e-3, "skf_s2": 40.0}
    with pytest.raises(SceneError, match=r"empirical\.skf_r1, skf_r2, skf_s1, skf_s2: the SKF "
                                         r"model is implemented for deep-groove-ball and "
                                         r"cylindrical-roller bearings only"):
        Bearing.from_dict(a)
    e = _example("6209")
    e["empirical"] = {"skf_series": "6205"}
    with pytest.raises(SceneError, match=r"its series is '62'"):
        Bearing.from_dict(e)
    e["empirical"] = {"skf_series": 62}
    with pytest.raises(SceneError, match=r'write "62" \(a string\)'):
        Bearing.from_dict(e)


@pytest.mark.parametrize("section, key, value, pattern", [
    ("bearing", "element_diameter", {"bore": 0.025, "outside_diameter": 0.052,
                                     "pitch_diameter": 0.0385, "element_diameter": 0.014},
     r"element_diameter = 0\.014 m does not fit between the rings \(D - d\)/2 = 0\.0135 m; "
     r"dimensions are in metres$"),
    ("bearing", "radial_clearance", -2e-6, r"radial_clearance must be >= 0 m, got -2e-06 m: a "
                                           r"negative clearance \(preload\) is not modelled"),
    ("model", "roughness", 0.0001, r"\(0\.0001 mm is 1e-07\)"),
    ("model", "roughness", 0.2, r"\(0\.2 um is 2e-07\)"),
    ("materials", "ring_modulus", 208000.0, r"\(208000 MPa is 2\.08e\+11\)"),
    ("materials", "element_modulus", 310.0, r"\(310 GPa is 3\.1e\+11\)"),
    ("mesh", "y_range", [-0.5, 0.5], r"mesh\.y_range .* \(e\.g\. \[-3, 3\]\)"),
])
def test_unit_hints_read_the_value(section, key, value, pattern):
    d = _example("6209")
    if isinstance(value, dict):
        d[section].update(value)
    else:
        d.setdefault(section, {})[key] = value
    with pytest.raises(SceneError) as err:
        Bearing.from_dict(d)
    assert re.search(pattern, str(err.value)), str(err.value)
    assert "99999" not in str(err.value), "no float noise"


def test_solve_on_a_bearing_file_says_so(tmp_path, capsys):
    path = tmp_path / "b.toml"
    path.write_text((io.Path(__file__).parent.parent / "bearing_fem" / "bearings"
                     / "6209.toml").read_text())
    assert cli.main(["solve", str(path), "--out", str(tmp_path / "o")]) == cli.EXIT_INVALID
    assert "this looks like a bearing file: run `bearing-fem bearing FILE`" in \
        capsys.readouterr().err


# ---------------------------------------------------------------------------------------
# warnings
# ---------------------------------------------------------------------------------------
def test_truncated_inlet_warns():
    from bearing_fem.bearing.solve import _truncated_domain_warnings

    b = load_example("6209")
    d = b.to_dict()
    d["mesh"] = {"x_range": [-3.0, 1.5]}
    w = _truncated_domain_warnings(Bearing.from_dict(d), _specs(Bearing.from_dict(d)))
    assert len(w) == 1 and w[0].startswith("mesh.x_range starts at -3 Hertz half-widths, "
                                           "downstream of the contacts' default inlet"), w
    assert "underestimated" in w[0] and "do not include this domain truncation" in w[0], w
    d["mesh"] = {"x_range": [-30.0, 1.5], "y_range": [-2.0, 2.0]}
    w = _truncated_domain_warnings(Bearing.from_dict(d), _specs(Bearing.from_dict(d)))
    assert len(w) == 1 and w[0].startswith("mesh.y_range = [-2, 2] Hertz half-widths is "
                                           "narrower"), w
    assert _truncated_domain_warnings(b, _specs(b)) == [], "the default domain: no warning"
    r = solve_bearing(small_roller(mesh={"line_nodes": 101, "x_range": [-3.0, 1.2]}))
    assert any(x.startswith("mesh.x_range starts at -3 ") for x in r.warnings), r.warnings



def test_hot_oil_gets_one_warning_under_the_thermal_patch():
    """Oil at 250 deg C with model.thermal = 'patch': the bearing's input warning (looks
    like kelvin, oils oxidise) is the only warning about operation.oil_temperature; the
    contacts' own hot-oil warning is left out."""
    b = small_roller(operation={"oil_temperature": 250.0}, model={"thermal": "patch"},
                     mesh={"line_nodes": 101},
                     lubricant={"temperature_law": "prokofiev", "viscosity": None,
                                "reference_viscosity": 0.06, "exponent": 2.9})
    r = solve_bearing(b)
    about = [w for w in r.warnings if "oil_temperature" in w]
    assert len(about) == 1, about
    assert about[0].startswith("operation.oil_temperature = 250 deg C is above 200 deg C"), about
    assert "oxidise" in about[0] and "looks like kelvin (250 K is -23.15 deg C)" in about[0], \
        about


def test_reference_temperature_warns_only_under_the_prokofiev_law():
    d = small_roller().to_dict()
    d["lubricant"]["reference_temperature"] = 313.0
    assert input_warnings(Bearing.from_dict(d)) == [], \
        "lubricant.reference_temperature is unused without the Prokofiev law"
    d["lubricant"] = {"temperature_law": "prokofiev", "reference_viscosity": 0.06,
                      "exponent": 2.9, "piezo": 2e-8, "reference_temperature": 313.0}
    d["operation"]["oil_temperature"] = 60.0
    (w,) = input_warnings(Bearing.from_dict(d))
    assert w.startswith("lubricant.reference_temperature = 313 deg C is above 200"), w


def test_load_distribution_failure_keeps_the_input_warnings(monkeypatch):
    from bearing_fem.bearing import solve as bearing_solve

    def fail(bearing):
        raise RuntimeError("no balance")

    monkeypatch.setattr(bearing_solve, "distribute_loads", fail)
    r = solve_bearing(small_roller(operation={"oil_temperature": 353.0}))
    assert r.status == "load_distribution_failed", r.status
    assert len(r.warnings) == 1 and r.warnings[0].startswith(
        "operation.oil_temperature = 353 deg C is above 200 deg C"), r.warnings


def test_kelvin_hints_share_one_helper(monkeypatch):
    """Operation, BearingLubricant and input_warnings read a kelvin-like value with one
    helper, and the oil range ends where the scenes' temperature range does."""
    from bearing_fem.bearing import description
    from bearing_fem.scene import TEMPERATURE_RANGE

    assert description.OIL_TEMPERATURE_RANGE[1] is TEMPERATURE_RANGE[1], \
        "one constant for the hottest accepted temperature"
    monkeypatch.setattr(description, "_kelvin", lambda t: f"<{t:g} K>")
    d = small_roller().to_dict()
    d["operation"]["oil_temperature"] = 600.0
    with pytest.raises(SceneError, match=r"looks like kelvin \(<600 K>\)"):
        Bearing.from_dict(d)
    d["operation"]["oil_temperature"] = 353.0
    assert "(<353 K>)" in input_warnings(Bearing.from_dict(d))[0], "input_warnings"
    d["lubricant"]["reference_temperature"] = 600.0
    with pytest.raises(SceneError, match=r"^lubricant\.reference_temperature .*\(<600 K>\)"):
        Bearing.from_dict(d)


def test_skf_types_come_from_one_table(monkeypatch):
    """SKF_CONSTANTS_USED lists the types with an SKF model: empirical_models and
    skf_friction_torque follow it."""
    from bearing_fem.bearing import empirical
    from bearing_fem.bearing.description import SKF_CONSTANTS_USED

    b = small_roller(empirical={"skf_r1": 1.09e-6, "skf_s1": 0.16, "skf_s2": 0.0015})
    assert "torque" in empirical_models(b, 0.0)["skf"], "the SKF model of a listed type"
    monkeypatch.delitem(SKF_CONSTANTS_USED, "cylindrical-roller")
    assert empirical_models(b, 0.0)["skf"]["available"] is False, \
        "a type left out of SKF_CONSTANTS_USED has no SKF model"
    with pytest.raises(ValueError, match="SKF model implemented for deep-groove-ball bearings, "
                                         "got 'cylindrical-roller'"):
        empirical.skf_friction_torque("cylindrical-roller", 30, 62, 1500.0, 30.0, 2000.0,
                                      r1=1.09e-6, r2=0.0, s1=0.16, s2=0.0015)


def test_missing_estimate_warning_names_the_bearings_mesh_key(monkeypatch):
    from bearing_fem.bearing import solve as bearing_solve

    monkeypatch.setattr(bearing_solve, "_nodes_key", lambda bearing: "<key>")
    b = small_roller()
    text = bearing_solve._missing_estimate_warning(b, [], {}, [], ["torque"])
    assert text.endswith("finer contact grids ([mesh] <key>) give estimates"), text


def test_isoviscous_heavily_loaded_default_domain_is_not_called_truncated():
    """A ball bearing with lubricant.piezo = 0 at 50 rpm: its contacts are isoviscous
    above Moes M = 1000, whose default domain is x from -1.5, y in +-1.5 (point_setup);
    that domain given as mesh ranges is no truncation, a shorter one is."""
    from bearing_fem.bearing.solve import _default_domain, _truncated_domain_warnings
    from bearing_fem.contacts.point import default_ranges, point_setup

    d = load_example("6209").to_dict()
    d["lubricant"]["piezo"] = 0.0
    d["operation"]["inner_rpm"] = 50.0
    b = Bearing.from_dict(d)
    scene = next(s for spec in _specs(b) if spec.excluded is None for s in spec.scenes)
    setup = point_setup(scene, nodes=(17, 17))
    xr, yr = default_ranges(scene)
    assert xr == (-1.5, 1.2) and yr == (-1.5, 1.5), (xr, yr, "isoviscous high-load domain")
    assert setup.grid.x.min() == pytest.approx(xr[0] * setup.x_unit, rel=1e-12), \
        "the setup takes its x range from default_ranges"
    assert _default_domain(scene) == (1.5, 1.5), "the warning's default: the setup's one"
    d["mesh"] = {"x_range": [-1.5, 1.2], "y_range": [-1.5, 1.5]}
    b = Bearing.from_dict(d)
    assert _truncated_domain_warnings(b, _specs(b)) == [], \
        "the solver's own default domain is not truncated"
    d["mesh"] = {"x_range": [-1.2, 1.2], "y_range": [-1.2, 1.2]}
    b = Bearing.from_dict(d)
    w = _truncated_domain_warnings(b, _specs(b))
    assert len(w) == 2 and "default inlet at -1.5" in w[0] and "[-1.5, 1.5]" in w[1], w


def test_line_default_range_is_the_setups_for_a_capped_isoviscous_contact():
    """An isoviscous line contact whose default grid reaches the node cap takes the short
    inlet; default_x_range and line_setup agree (and the wide range otherwise)."""
    from bearing_fem.contacts.line import default_x_range, line_setup
    from bearing_fem.scene import Scene

    e, r, eta, u_sum = 2.2e11, 0.01, 0.01, 1e-11
    for m, short in ((1500.0, True), (100.0, False)):
        u = u_sum * e * r / (2 * eta)
        scene = Scene.from_dict({
            "contact": {"kind": "line", "rx": r}, "materials": {"reduced_modulus": e},
            "lubricant": {"viscosity": eta, "piezo": 0.0},
            "kinematics": {"u1": u, "u2": u}, "load": {"force": m * u_sum ** 0.5 * e * r},
            "mesh": {"nodes": 101}})
        xr = default_x_range(scene)
        setup = line_setup(scene)
        assert (xr[1] == 1.2) == short, (m, xr, "short isoviscous inlet above the cap")
        np.testing.assert_allclose(setup.disc.x[[0, -1]], np.array(xr) * setup.x_unit,
                                   rtol=1e-12, err_msg=f"M = {m}: setup and default agree")

def test_warnings_once_in_bearing_terms():
    from bearing_fem.bearing.solve import _bearing_terms

    r = solve_bearing(small_roller(lubricant={"viscosity": 15.0}, mesh={"line_nodes": 101}))
    visc = [w for w in r.warnings if "lubricant.viscosity = 15 Pa s" in w]
    assert len(visc) == 1 and visc[0].startswith("all "), r.warnings
    assert not any("mesh.nodes" in w or "point_nodes" in w for w in r.warnings), r.warnings
    b = small_roller(lubricant={"viscosity": None, "temperature_law": "prokofiev",
                                "reference_viscosity": 0.06, "exponent": 2.93},
                     operation={"oil_temperature": 5.0}, model={"thermal": "patch"})
    text = _bearing_terms(b, "lubricant.viscosity = 26.57 Pa s is above 5 Pa s, thicker than "
                            "lubricating oils at their working temperature; did you mean "
                            "0.02657 Pa s (cP given as Pa s)?")
    assert text.startswith("the temperature law (lubricant.temperature_law = 'prokofiev') "
                           "gives 26.6 Pa s at 5 deg C"), text
    assert "did you mean" not in text, text
    assert _bearing_terms(b, "thermal.oil_temperature = 180 deg C is above 150 deg C").startswith(
        "operation.oil_temperature = 180"), "a bearing file's key"
    assert _bearing_terms(b, "refine the mesh (mesh.nodes)") == \
        "refine the mesh ([mesh] line_nodes)"


@pytest.fixture(scope="module")
def failed():
    b = small_roller(solver={"max_iterations": 1, "continuation": False,
                             "iteration_budget": 1}, mesh={"line_nodes": 101})
    r = solve_bearing(b)
    assert not r.success and r.status == "contacts_failed", r.status
    return r


def test_failed_contacts_warn_with_their_reason(failed):
    assert "distinct contact scenes attempted" in failed.message, failed.message
    assert "scenes solved" not in failed.message, failed.message
    carried = [w for w in failed.warnings if w.startswith("contact")]
    assert carried and all(" unsuccessful (status " in w for w in carried), carried
    assert not any("last iterate" in w or "between the nodes" in w for w in failed.warnings), \
        failed.warnings


def test_failed_contact_files_and_figure(failed, tmp_path):
    from bearing_fem.plot_bearing import films_figure

    files = io.export_bearing(failed, tmp_path)
    folders = [k for k in files if k.startswith("contact_")]
    assert folders, files
    s = json.loads((files[folders[0]] / "summary.json").read_text())
    assert s["status"] in ("budget_exhausted", "max_iterations") and not s["success"], s
    assert s["message"], "the failure message stays"
    for key in ("h_min", "p_max", "friction_force", "heat_power", "load"):
        assert key in s, f"the failed contact's summary keeps {key!r} (as null)"
        assert s[key] is None, (key, s[key], "a failed contact's quantity is null")
    vtm = (tmp_path / "contacts.vtm").read_text()
    assert "<DataSet" not in vtm, "failed contacts are no blocks"
    fig = films_figure(failed)
    try:
        texts = [t.get_text() for ax in fig.axes for t in ax.texts]
        title = fig.axes[0].get_title()
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)
    assert re.search(r"EHL: (\d+) of \1 contacts failed", title), title
    assert texts and all("no EHL result" in t for t in texts), texts


def test_slice_folders_are_numbered_from_one(tmp_path):
    r = solve_bearing(small_roller(bearing={"profile": "crowned", "crown_drop": 4e-6,
                                            "slices": 3}, mesh={"line_nodes": 101}))
    files = io.export_bearing(r, tmp_path)
    names = sorted(k for k in files if "_slice" in k)
    assert names and all(re.search(r"_slice0[1-3]$", n) for n in names), names
    assert any(n.endswith("_slice03") for n in names), names
    vtk = sorted(p.name for p in (tmp_path / "contacts_vtk").iterdir())
    assert not any("_slice00" in n for n in vtk), vtk


def test_miniature_bearing_in_millimetres_is_refused_up_front():
    # a 623 (bore 3 mm, D 10 mm, balls 1/16 in) written in millimetres: every length lies
    # in the accepted [1e-4, 10] m, but a 1.59 m ball is no rolling element
    import bearing_fem.bearing.description as desc

    with pytest.raises(SceneError) as info:
        desc.Geometry(type="deep-groove-ball", bore=3.0, outside_diameter=10.0,
                      element_diameter=1.5875, elements=7)
    msg = str(info.value)
    assert "bearing.element_diameter = 1.5875 m" in msg and "0.0015875" in msg, msg
    assert "bore (3 m)" in msg, msg
    # the same bearing in metres is accepted
    desc.Geometry(type="deep-groove-ball", bore=0.003, outside_diameter=0.010,
                  element_diameter=0.0015875, elements=7)


def test_single_row_tapered_bearing_says_how_it_is_modelled():
    from bearing_fem.bearing.description import input_warnings

    d = load_example("nncf5040").to_dict()
    d["bearing"].update(type="tapered-roller", contact_angle=15.0, rows=1)
    d["bearing"].pop("radial_clearance", None)
    one = Bearing.from_dict(d)
    notes = [w for w in input_warnings(one) if "opposed pair" in w]
    assert len(notes) == 1 and "bearing.rows = 1" in notes[0], input_warnings(one)
    # under a combined load the single row is modelled as it is: no such warning
    d["operation"]["axial_load"] = 0.5 * d["operation"]["radial_load"]
    assert not [w for w in input_warnings(Bearing.from_dict(d)) if "opposed pair" in w]
    d["operation"]["axial_load"] = 0.0
    d["bearing"]["rows"] = 2
    assert not [w for w in input_warnings(Bearing.from_dict(d)) if "opposed pair" in w]


@pytest.mark.parametrize("name, key", [("6209", "radial_load"), ("nncf5040", "radial_load"),
                                       ("30205", "radial_load"), ("7010-steel", "axial_load")])
@pytest.mark.parametrize("load", [1e-20, 1e-300, 5e-324])
def test_load_below_the_smallest_contact_load_is_refused_naming_it(name, key, load):
    """A load that no contact can carry (it underflowed in the load distribution: a
    ZeroDivisionError of the loaded-angle average, or Brent's 'f(a) and f(b) must have
    different signs' as a failed load distribution) is refused up front."""
    data = _example(name)
    data["operation"][key] = load
    with pytest.raises(SceneError, match=rf"operation\.{key} = {load:g} N .*1e-06 N.*give 0"):
        Bearing.from_dict(data)


def test_tiny_radial_load_exits_2_without_a_traceback(tmp_path, capsys):
    data = _example("6209")
    data["operation"]["radial_load"] = 1e-300
    path = tmp_path / "b.toml"
    path.write_text(io.scene_to_toml(data), encoding="utf-8")
    assert cli.main(["bearing", str(path), "--out", str(tmp_path / "out"),
                     "--no-figures"]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and "operation.radial_load" in err


@pytest.mark.parametrize("psi0", [1e20, -1e300, 361.0])
def test_first_element_azimuth_out_of_a_turn_is_refused_naming_it(psi0):
    """1e20 deg was accepted and then reported as the loads turning a contact angle
    beyond 90 deg (the element azimuths lose every digit)."""
    data = _example("6209")
    data["bearing"]["first_element_azimuth"] = psi0
    with pytest.raises(SceneError, match=r"bearing\.first_element_azimuth must lie in "
                                         r"\[-360, 360\] deg"):
        Bearing.from_dict(data)


def test_first_element_azimuth_within_a_turn_is_accepted():
    data = _example("6209")
    for psi0 in (-360.0, 20.0, 360.0):
        data["bearing"]["first_element_azimuth"] = psi0
        assert Bearing.from_dict(data).geometry.first_element_azimuth == psi0


@pytest.mark.parametrize("c0", [5e-324, 1e-300, 1.0, 1e300])
def test_static_load_rating_outside_its_range_is_refused_naming_it(c0):
    """5e-324 N was accepted and overflowed Palmgren's f1 = z (P0/C0)^y: a ValueError
    traceback of 'bearing-fem bearing' after the contact solves."""
    data = _example("6209")
    data["bearing"]["static_load_rating"] = c0
    with pytest.raises(SceneError, match=r"bearing\.static_load_rating must lie in "
                                         r"\[10, 1e\+09\] N"):
        Bearing.from_dict(data)


def test_tiny_static_load_rating_exits_2_without_a_traceback(tmp_path, capsys):
    data = _example("6209")
    data["bearing"]["static_load_rating"] = 5e-324
    data["mesh"] = {"point_nodes": [17, 17]}
    path = tmp_path / "b.toml"
    path.write_text(io.scene_to_toml(data), encoding="utf-8")
    assert cli.main(["bearing", str(path), "--out", str(tmp_path / "out"),
                     "--no-figures"]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and "bearing.static_load_rating" in err


@pytest.mark.parametrize("rho", [5e-324, 7.85, 1e300])
def test_element_density_outside_its_range_is_refused_naming_it(rho):
    """1e300 kg/m^3 with the centrifugal model was reported as the loads turning a
    contact angle beyond 90 deg, naming operation.radial_load."""
    data = _example("7010-steel")
    data["materials"]["element_density"] = rho
    data.setdefault("model", {})["centrifugal"] = True
    with pytest.raises(SceneError, match=r"materials\.element_density must lie in "
                                         r"\[500, 25000\] kg/m\^3"):
        Bearing.from_dict(data)


@pytest.mark.parametrize("f", [1.5, 1e300])
def test_bore_form_friction_coefficient_above_one_is_refused(f):
    data = _example("nncf5040")
    data["empirical"]["friction_coefficient"] = f
    with pytest.raises(SceneError, match=r"empirical\.friction_coefficient must lie in "
                                         r"\(0, 1\]"):
        Bearing.from_dict(data)


@pytest.mark.parametrize("name, key", [("30205", "axial_load"), ("6209", "radial_load")])
def test_load_above_the_largest_contact_load_is_refused_naming_it(name, key):
    """An axial load of 1e20 N on the tapered row failed in Brent's bracket of the load
    distribution ('f(a) and f(b) must have different signs', exit 3) instead of being
    refused as input."""
    data = _example(name)
    data["operation"][key] = 1e20
    with pytest.raises(SceneError, match=rf"operation\.{key} = 1e\+20 N exceeds 1e\+12 N"):
        Bearing.from_dict(data)


@pytest.mark.parametrize("name, c0", [("6209", 21.6), ("30205", 33.5), ("nncf5040", 3900.0)])
def test_static_load_rating_in_kn_is_refused_against_the_iso76_rating(name, c0):
    """A catalogue C0 written in kN (21.6 for the 6209's 21600 N) lay inside [10, 1e9] N
    and was accepted: Palmgren's f1 = z (P0/C0)^y then put the 6209's torque at 2.41 N m
    instead of 0.161 N m, with no warning."""
    data = _example(name)
    data["bearing"]["static_load_rating"] = c0
    with pytest.raises(SceneError, match=r"bearing\.static_load_rating = .* N is below 1% "
                                         r"of the static load rating .* ISO 76.* kN is "):
        Bearing.from_dict(data)


@pytest.mark.parametrize("name, c0", [("6209", 21600.0), ("7010-steel", 16000.0),
                                      ("30205", 33500.0), ("nncf5040", 3.9e6)])
def test_static_load_ratings_in_n_are_accepted(name, c0):
    """Ratings of the examples' sizes in N (the 6209 file's catalogue 21600 N, the others
    of their catalogue sizes' order) lie within 30% of the ISO 76 estimate and pass
    (6209: 21600 N against 17400 N)."""
    data = _example(name)
    data["bearing"]["static_load_rating"] = c0
    geometry = Bearing.from_dict(data).geometry
    assert geometry.static_load_rating == c0
    ratio = c0 / iso76_static_load_rating(geometry)
    assert 0.7 < ratio < 1.3, f"{name}: C0/ISO 76 = {ratio} (a C0 in N is of its order)"

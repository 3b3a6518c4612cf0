"""bearing_fem.checks.input_warnings: one sentence per implausible input, none otherwise."""
from __future__ import annotations

import copy

import pytest

from bearing_fem import checks, units
from bearing_fem.checks import input_warnings
from bearing_fem.scene import Scene, load_embedded

#: The README's ball scene (steel ball on flat, mineral oil): a plausible point contact.
BALL = {
    "title": "Ball on flat",
    "contact": {"kind": "point", "rx": 0.0127, "ry": 0.0127},
    "materials": {"reduced_modulus": 2.3e11},
    "lubricant": {"viscosity": 0.04, "piezo": 2.2e-8},
    "kinematics": {"u1": 1.0, "u2": 1.0},
    "load": {"force": 30.0},
}
#: A steel roller contact at 1 GPa (per metre of length), plausible.
ROLLER = {
    "contact": {"kind": "line", "rx": 0.01, "length": 0.02},
    "materials": {"e1": 2.1e11, "nu1": 0.3, "e2": 2.1e11, "nu2": 0.3},
    "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"force": 2e5},
}


def _scene(base: dict, **changes) -> Scene:
    data = copy.deepcopy(base)
    for path, value in changes.items():
        section, key = path.split("__")
        if value is None:
            data[section].pop(key)
        else:
            data.setdefault(section, {})[key] = value
    return Scene.from_dict(data)


def _one(scene: Scene) -> str:
    found = input_warnings(scene)
    assert len(found) == 1, f"expected exactly one warning, got {found}"
    return found[0]


@pytest.mark.parametrize("scene", [
    Scene.from_dict(BALL), Scene.from_dict(ROLLER), load_embedded("roller"),
    _scene(ROLLER, load__force=None, load__gap=1e-6, model__elasticity="rigid"),
], ids=["ball", "roller", "embedded-roller", "rigid-gap"])
def test_plausible_scenes_have_no_warning(scene):
    """Positive control: the package's own example scenes are all plausible."""
    assert input_warnings(scene) == []


def test_viscosity_in_centipoise():
    text = _one(_scene(BALL, lubricant__viscosity=40.0))
    assert "lubricant.viscosity = 40 Pa s" in text and "above 5 Pa s" in text
    assert "did you mean 0.04 Pa s" in text and "cP" in text


def test_viscosity_high_without_unit_hint():
    """6000 Pa s read as cP is still 6 Pa s, above the range: no cP suggestion."""
    text = _one(_scene(BALL, lubricant__viscosity=6000.0))
    assert "above 5 Pa s" in text and "did you mean" not in text


def test_viscosity_kinematic_given():
    text = _one(_scene(BALL, lubricant__viscosity=4e-5))
    assert "below 0.0001 Pa s" in text and "kinematic" in text and "40 cSt" in text
    assert f"{4e-5 * checks.OIL_DENSITY:.4g} Pa s" in text


def test_viscosity_just_inside_range_is_quiet():
    """The thresholds are exclusive: 5 Pa s and 1e-4 Pa s themselves do not warn."""
    assert input_warnings(_scene(BALL, lubricant__viscosity=checks.VISCOSITY_HIGH)) == []
    assert input_warnings(_scene(BALL, lubricant__viscosity=checks.VISCOSITY_LOW)) == []


def test_thermal_reference_viscosity_checked():
    data = copy.deepcopy(ROLLER)
    data["model"] = {"thermal": "patch"}
    data["thermal"] = {"oil_temperature": 60.0, "exponent": 2.9, "reference_viscosity": 30.0}
    text = _one(Scene.from_dict(data))
    assert text.startswith("thermal.reference_viscosity = 30 Pa s")
    # beside thermal.reference_viscosity, lubricant.viscosity is not used: no warning on it
    data["lubricant"]["viscosity"] = 1e-5
    data["thermal"]["reference_viscosity"] = 0.05
    assert input_warnings(Scene.from_dict(data)) == []


def test_soft_bodies():
    """E' = 2.3e8 Pa (MPa-scale moduli): warned; the ball's contact also grows past
    a/rx = 0.1, which is a second, separate warning."""
    found = input_warnings(_scene(BALL, materials__reduced_modulus=2.3e8))
    assert any("E' = 2.3e+08 Pa" in t and "below 1e+09 Pa" in t for t in found), found
    assert any("a_x" in t and "contact.rx" in t for t in found), found
    assert len(found) == 2, found


def test_hertz_pressure_above_5_gpa():
    # p_h = sqrt(w E'/(2 pi R)) > 5 GPa for w = 8e6 N/m on R = 0.01 m, steel
    scene = _scene(ROLLER, load__force=8e6, lubricant__piezo=1e-8)
    p_h = units.hertz_line(8e6, 0.01, scene.e_prime)[1]
    assert p_h > 5e9, "test scene must exceed 5 GPa"
    text = _one(scene)
    assert "Hertz pressure" in text and "above 5e+09 Pa" in text


def test_alpha_ph_above_100():
    scene = _scene(ROLLER, lubricant__piezo=1e-7, load__force=1e6)
    p_h = units.hertz_line(1e6, 0.01, scene.e_prime)[1]
    assert 100 < 1e-7 * p_h and p_h < 5e9
    text = _one(scene)
    assert "alpha p_h" in text and "above 100" in text
    # a constant-viscosity law has no pressure-viscosity response: no warning
    assert input_warnings(_scene(ROLLER, lubricant__piezo=1e-7, load__force=1e6,
                                 lubricant__viscosity_law="constant")) == []


def test_line_load_given_in_newton():
    text = _one(_scene(ROLLER, load__force=1200.0))
    assert "load.force = 1200 N/m" in text and "per metre of length" in text
    assert "6e+04 N/m" in text, "suggests force / contact.length with length 0.02 m"
    text = _one(_scene(ROLLER, load__force=1200.0, contact__length=None))
    assert "divide it by the contact length" in text


def test_light_line_load_on_soft_bodies_is_not_a_unit_slip():
    """The N-for-N/m hint is for hard bodies only: a polymer pair at low pressure is fine."""
    scene = _scene(ROLLER, load__force=1200.0, materials__e1=None, materials__nu1=None,
                   materials__e2=None, materials__nu2=None, materials__reduced_modulus=5e9)
    assert input_warnings(scene) == []


def test_point_load_in_newton_not_flagged_as_line_load():
    assert input_warnings(_scene(BALL, load__force=1.0)) == []


def test_large_contact():
    # b/R = 4 p_h/E' > 0.1 for a soft line contact at 2 MPa on E' = 5e7
    scene = _scene(ROLLER, materials__e1=None, materials__nu1=None, materials__e2=None,
                   materials__nu2=None, materials__reduced_modulus=5e7, load__force=3e4,
                   lubricant__piezo=0.0)
    found = input_warnings(scene)
    assert any("Hertz half-width b" in t and "contact.rx" in t for t in found), found


def test_thick_gap():
    text = _one(_scene(ROLLER, load__force=None, load__gap=5e-4, model__elasticity="rigid"))
    assert "load.gap = 0.0005 m" in text and "0.05 x contact.rx" in text


@pytest.mark.parametrize("base, changes, ratio", [
    (BALL, {"lubricant__viscosity": 40.0}, "0.0392"),
    (ROLLER, {"lubricant__viscosity": 4.0, "kinematics__u1": 20.0, "kinematics__u2": 20.0,
              "load__force": 1e4}, "0.0393"),
], ids=["ball-40-Pa-s", "roller-fast-light"])
def test_thick_solved_film(base, changes, ratio):
    """A film solved under a load that is not thin against the radius (a ball at 40 Pa s:
    0.5 mm, 3.9 % of rx) is named after the solve, as a prescribed thick gap is before it."""
    import bearing_fem as bf

    r = bf.solve(_scene(base, **changes))
    assert r.success, r.message
    notes = [w for w in r.warnings if w.startswith("the central film")]
    assert len(notes) == 1 and f"is {ratio} x contact.rx" in notes[0], r.warnings
    assert checks.thick_film_warning(r.scene, 0.99 * checks.GAP_RATIO_HIGH
                                     * r.scene.contact.rx) is None, "quiet below the limit"


def test_plausible_solved_film_is_not_thick():
    import bearing_fem as bf

    r = bf.solve(Scene.from_dict(BALL))
    assert r.success and not any("central film" in w for w in r.warnings), r.warnings


def test_gap_on_an_elastic_line_contact():
    """The plane-strain displacement is defined up to a constant (that of ln|x - s| in
    metres): a prescribed gap on a half-space line contact gives a film that depends on
    the length unit, which the result must say (gap 0.1 um gave h_central 0.92 um)."""
    text = _one(_scene(ROLLER, load__force=None, load__gap=1e-7))
    assert "load.gap = 1e-07 m" in text and "no absolute datum" in text, text
    assert "load.force" in text, "the way out is named"
    for quiet in (_scene(ROLLER, load__force=None, load__gap=1e-6, model__elasticity="rigid"),
                  _scene(BALL, load__force=None, load__gap=1e-7)):
        assert input_warnings(quiet) == [], "rigid lines and elastic points have a datum"


def test_range_in_metres_on_a_rigid_scene():
    """Rigid and prescribed-gap ranges are in hydrodynamic lengths sqrt(2 r h0): a range
    given in metres spans a sliver of the film (5e-9 N/m carried), said in a warning."""
    text = _one(_scene(ROLLER, load__force=None, load__gap=1e-6, model__elasticity="rigid",
                       mesh__x_range=[-0.001, 0.0005]))
    assert "mesh.x_range = [-0.001, 0.0005]" in text and "sqrt(2 rx h0)" in text, text
    assert "metres" in text, text
    ball = _scene(BALL, load__force=None, load__gap=5e-7, mesh__x_range=[-4.0, 2.0],
                  mesh__y_range=[-0.002, 0.002])
    assert "mesh.y_range" in _one(ball), "elastic point with a gap: same unit"
    for quiet in (_scene(ROLLER, load__force=None, load__gap=1e-6, model__elasticity="rigid",
                         mesh__x_range=[-0.5, 5.0]),   # a starved inlet is physics
                  _scene(ROLLER, mesh__x_range=[-4.5, 1.5])):
        assert input_warnings(quiet) == [], input_warnings(quiet)


def test_traction_parameter_the_model_does_not_use():
    """An Eyring stress given with the Newtonian or limiting model (or a limiting stress with
    the Eyring model) was silently ignored; the generic defaults are not flagged."""
    text = _one(_scene(ROLLER, traction__model="newtonian", traction__eyring_stress=3e6))
    assert "traction.eyring_stress = 3e+06 Pa is not used by traction.model = 'newtonian'" \
        in text, text
    text = _one(_scene(ROLLER, traction__model="eyring", traction__limiting_slope=0.05,
                       traction__limiting_shear_stress=1e6))
    assert "limiting_shear_stress = 1e+06 Pa, traction.limiting_slope = 0.05 are not " \
           "used by traction.model = 'eyring' (it uses eyring_stress)" in text, text
    for quiet in (_scene(ROLLER, traction__model="eyring", traction__eyring_stress=3e6),
                  _scene(ROLLER, traction__model="limiting"),
                  _scene(ROLLER, traction__model="eyring-limiting",
                         traction__eyring_stress=8e6, traction__limiting_slope=0.06)):
        assert input_warnings(quiet) == [], input_warnings(quiet)


def test_hot_oil():
    data = copy.deepcopy(ROLLER)
    data["model"] = {"thermal": "patch"}
    data["thermal"] = {"oil_temperature": 180.0, "exponent": 2.9}
    text = _one(Scene.from_dict(data))
    assert "thermal.oil_temperature = 180 deg C" in text


def test_warnings_are_short_sentences():
    """Each warning is one line of bounded length (it goes into summaries and terminals)."""
    scene = _scene(ROLLER, lubricant__viscosity=40.0, load__force=1200.0)
    found = input_warnings(scene)
    assert len(found) == 2
    assert all("\n" not in t and len(t) < 300 for t in found), found

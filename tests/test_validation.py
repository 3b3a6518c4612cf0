"""Argument checks of the Python functions (bearing_fem.validation and its users)."""
from __future__ import annotations

import pytest

from bearing_fem import analytic, units
from bearing_fem.validation import require_finite, require_positive


@pytest.mark.parametrize("value", ["1e8", b"1", True, None, [1.0, "x"]])
def test_numbers_only(value):
    """A string that parses as a number is refused too: it is a unit slip or a typo."""
    with pytest.raises(ValueError, match=r"force must be (a number in N|finite \(N\)), got "):
        require_positive("force", value, "N")


def test_helpers_name_the_argument_of_a_string():
    with pytest.raises(ValueError, match=r"force must be a number in N, got '100'"):
        units.hertz_point("100", 0.01, 0.01, 2.2e11)
    with pytest.raises(ValueError, match=r"p must be a number in Pa, got '1e8'"):
        analytic.reduced_from_barus("1e8", 1e-8)
    assert require_finite("x", 2, "m") == 2.0


@pytest.mark.parametrize("value, match", [
    ((float("nan"), 0.0), r"boundary_pressure must be finite \(Pa\), got \(nan, 0.0\)"),
    ((float("inf"), 0.0), r"boundary_pressure must be finite"),
    (("a", 0.0), r"boundary_pressure must be two pressures \(inlet, outlet\) in Pa"),
    (("1e5", 0.0), r"boundary_pressure must be two pressures"),
    ((True, False), r"boundary_pressure must be two pressures"),
    ((1e6,), r"boundary_pressure must be two pressures \(inlet, outlet\) in Pa"),
    ((-1e6, 0.0), r"boundary_pressure must be >= 0 Pa with model.cavitation = 'reynolds'"),
])
def test_solve_checks_its_end_pressures(value, match):
    """A NaN end pressure gave a 'linear' success with NaN pressures, inf a false
    no_solution verdict, a string or one value a bare ValueError."""
    import bearing_fem as bf
    from bearing_fem.errors import SceneError

    scene = bf.Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                                "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
                                "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": 1e-6},
                                "model": {"elasticity": "rigid"}})
    with pytest.raises(SceneError, match=match):
        bf.solve(scene, boundary_pressure=value)
    assert bf.solve(scene, boundary_pressure=(1e5, 0.0)).status == "linear"


@pytest.mark.parametrize("call, match", [
    (lambda: __import__("bearing_fem.bearing.kinematics", fromlist=["x"]).element_kinematics(
        100.0, 0.01, 0.02, 0.0, 0.0), r"element_diameter must be smaller than pitch_diameter"),
    (lambda: __import__("bearing_fem.bearing.kinematics", fromlist=["x"]).element_kinematics(
        float("nan"), 0.065, 0.0127, 0.0, 0.0), r"inner_speed must be finite \(rad/s\)"),
    (lambda: __import__("bearing_fem.bearing.geometry", fromlist=["x"]).contact_radii(
        0.065, 0.0127, float("inf"), 0.0), r"alpha_inner must be finite \(rad\)"),
    (lambda: __import__("bearing_fem.bearing.kinematics", fromlist=["x"]).element_kinematics(
        314.0, 0.065, 0.0127, 40.0, 40.0), r"alpha_inner must lie in \(-pi/2, pi/2\) rad"),
    (lambda: __import__("bearing_fem.bearing.geometry", fromlist=["x"]).contact_radii(
        0.065, 0.0127, [0.1, 0.2], [0.1]), r"alpha_inner and alpha_outer must have one shape"),
    (lambda: __import__("bearing_fem.bearing.geometry", fromlist=["x"]).contact_radii(
        [0.065, 0.07], 0.0127, 0.1, 0.1), r"pitch_diameter must be one number in m"),
    (lambda: __import__("bearing_fem.bearing.empirical", fromlist=["x"]).torque_to_heat_power(
        float("nan"), 3000.0), r"torque_nmm must be finite \(N mm\)"),
    (lambda: __import__("bearing_fem.physics.rheology", fromlist=["x"]).prokofiev(
        50.0, 0.05, 40.0, float("nan")), r"exponent must be finite"),
    (lambda: __import__("bearing_fem.physics.rheology", fromlist=["x"]).prokofiev(
        50.0, -0.05, 40.0, 2.9), r"viscosity_ref must be > 0 Pa s"),
])
def test_bearing_and_rheology_helpers_refuse_what_they_cannot_compute(call, match):
    """An element larger than the pitch circle gave negative radii and speeds; NaN inputs
    gave NaN speeds, heat powers and viscosities."""
    with pytest.raises(ValueError, match=match):
        call()

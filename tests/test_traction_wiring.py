"""The scene's [traction] model reaches the line-contact summary."""
from __future__ import annotations

import numpy as np

import bearing_fem as bf
from bearing_fem.scene import Scene


def _scene(model: str, **extra) -> Scene:
    return Scene.from_dict({
        "contact": {"kind": "line", "rx": 0.01},
        "materials": {"reduced_modulus": 2.2e11},
        "lubricant": {"viscosity": 0.05, "piezo": 1e-8},
        "kinematics": {"u1": 2.2, "u2": 1.8},
        "load": {"force": 1e5},
        "mesh": {"nodes": 401},
        "traction": {"model": model, **extra},
    })


def test_eyring_traction_below_newtonian_and_energy_consistent():
    newt = bf.solve(_scene("newtonian"))
    eyr = bf.solve(_scene("eyring", eyring_stress=5e6))
    assert newt.success and eyr.success, (newt.message, eyr.message)
    qn, qe = newt.quantities, eyr.quantities
    np.testing.assert_allclose(qe["rolling_resistance"], qn["rolling_resistance"], rtol=1e-12,
                               err_msg="the traction model changes only the Couette part")
    assert 0 < qe["sliding_friction"] < qn["sliding_friction"], (
        "Eyring stress tau0 asinh(eta gamma/tau0) <= eta gamma: less sliding friction")
    np.testing.assert_allclose(qe["heat_power_couette"], qe["sliding_friction"] * 0.4,
                               rtol=1e-12, err_msg="Couette heat = force x sliding speed")
    np.testing.assert_allclose(qe["heat_power"],
                               qe["heat_power_couette"] + qe["heat_power_poiseuille"],
                               rtol=1e-12, err_msg="heat power is the sum of its parts")

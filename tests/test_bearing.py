"""Empirical bearing formulas (seed 000) and roller kinematics."""
from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_fem import bearing


def test_palmgren_branches_and_units():
    kw = dict(mean_diameter_mm=255.0, bore_mm=200.0, radial_load=5e5, f0=5.0, f_pr=0.003)
    hi = bearing.palmgren_friction_torque(20.0, 537.0, **kw)        # nu n = 10740 >= 2000
    np.testing.assert_allclose(hi["M0"], 1e-7 * 5 * (20 * 537) ** (2 / 3) * 255**3, rtol=1e-14,
                               err_msg="viscous branch nu n >= 2000")
    lo = bearing.palmgren_friction_torque(1.0, 537.0, **kw)         # nu n = 537 < 2000
    np.testing.assert_allclose(lo["M0"], 160e-7 * 5 * 255**3, rtol=1e-14,
                               err_msg="low-viscosity branch")
    np.testing.assert_allclose(hi["M1"], 0.003 * 5e5 * 200 / 2, rtol=1e-14,
                               err_msg="load torque M1 = f_pr P d/2 (N mm)")
    q = bearing.palmgren_heat_power(20.0, 537.0, **kw)
    np.testing.assert_allclose(q, hi["M"] * 1e-3 * 537 * 2 * math.pi / 60, rtol=1e-3,
                               err_msg="1.047e-4 = 2 pi/60/1000 (N mm rpm -> W)")
    with pytest.raises(ValueError, match="kinematic_viscosity_mm2s.*mm\\^2/s"):
        bearing.palmgren_friction_torque(-1.0, 537.0, **kw)


def test_roller_kinematics_pure_rolling():
    c = bearing.cylindrical_roller_contacts(0.255, 0.028, 537.0)
    omega = 537 * 2 * math.pi / 60
    # inner-ring surface speed relative to the cage = roller surface speed = u_m
    u_inner = (omega - c.cage_speed) * (0.255 - 0.028) / 2
    np.testing.assert_allclose(c.mean_speed, u_inner, rtol=1e-12,
                               err_msg="pure rolling: inner surface speed in the cage frame")
    u_outer = c.cage_speed * (0.255 + 0.028) / 2
    np.testing.assert_allclose(c.mean_speed, u_outer, rtol=1e-12,
                               err_msg="same entrainment speed at the outer raceway")
    assert c.rx_outer > 0.014 > c.rx_inner, "concave outer race enlarges the reduced radius"
    np.testing.assert_allclose(bearing.max_line_load(5e5, 56, 0.06), 4.6 * 5e5 / (56 * 0.06),
                               rtol=1e-14, err_msg="q_H = K Fr/(z l_w)")
    with pytest.raises(ValueError, match="roller_diameter"):
        bearing.cylindrical_roller_contacts(0.02, 0.03, 100.0)

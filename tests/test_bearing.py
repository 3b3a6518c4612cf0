"""Empirical bearing formulas (Palmgren, SKF, Nikitin, film fits) and roller kinematics."""
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
    np.testing.assert_allclose(q, hi["M"] * 1e-3 * 537 * 2 * math.pi / 60, rtol=1e-13,
                               err_msg="Q = M omega exactly (the paper's 1.047e-4 is "
                                       "2 pi/60/1000 rounded)")
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


# ---------------------------------------------------------------------------------------
# empirical models (bearing_fem.bearing.empirical)
# ---------------------------------------------------------------------------------------
def test_palmgren_harris_form():
    from bearing_fem.bearing.empirical import palmgren_equivalent_load, palmgren_f1, palmgren_torque

    m = palmgren_torque(30.0, 3000.0, 65.0, 4000.0, f0=2.0, f1=2e-4)
    np.testing.assert_allclose(m["M0"], 1e-7 * 2.0 * (30 * 3000) ** (2 / 3) * 65**3, rtol=1e-14,
                               err_msg="viscous term 1e-7 f0 (nu n)^(2/3) d_m^3 [N mm]")
    np.testing.assert_allclose(m["M1"], 2e-4 * 4000 * 65, rtol=1e-14, err_msg="f1 P1 d_m")
    assert palmgren_equivalent_load("deep-groove-ball", 1000.0, 0.0) == 1000.0
    assert palmgren_equivalent_load("angular-contact-ball", 500.0, 2000.0) == 1950.0, \
        "angular contact: max(Fa - 0.1 Fr, Fr)"
    assert palmgren_f1("cylindrical-roller", full_complement=True) == 0.00055
    np.testing.assert_allclose(palmgren_f1("deep-groove-ball", 1000.0, 8000.0),
                               0.0005 * 0.125**0.55, rtol=1e-14)


def test_skf_model_limits():
    from bearing_fem.bearing.empirical import SKF_GEOMETRY_CONSTANTS, skf_friction_torque

    r1, r2, s1, s2 = SKF_GEOMETRY_CONSTANTS[("deep-groove-ball", "62")]
    slow = skf_friction_torque("deep-groove-ball", 45, 85, 1.0, 30.0, 4000.0, r1=r1, r2=r2,
                               s1=s1, s2=s2)
    assert slow["phi_ish"] == pytest.approx(1.0, abs=1e-4), "no inlet shear heating at 1 rpm"
    assert slow["mu_sl"] == pytest.approx(0.12, abs=1e-4), "boundary friction at n nu -> 0"
    fast = skf_friction_torque("deep-groove-ball", 45, 85, 3000.0, 30.0, 4000.0, r1=r1, r2=r2,
                               s1=s1, s2=s2)
    np.testing.assert_allclose(fast["G_rr"], r1 * 65**1.96 * 4000**0.54, rtol=1e-14)
    np.testing.assert_allclose(fast["M_rr"], fast["phi_ish"] * fast["phi_rs"] * fast["G_rr"]
                               * (30 * 3000) ** 0.6, rtol=1e-14)
    assert fast["mu_sl"] < 0.06, "full film: mu_sl -> mu_EHL = 0.05"
    with pytest.raises(ValueError, match="static_load_rating"):
        skf_friction_torque("deep-groove-ball", 45, 85, 3000.0, 30.0, 4000.0, 500.0, r1=r1,
                            r2=r2, s1=s1, s2=s2)


def test_nikitin_model_structure():
    """Q = phi m rho d^2 u^3 with the paper's constants; the friction/churning split and the
    reduced friction coefficient land in the paper's reported range for its conditions."""
    from bearing_fem.bearing import load_example
    from bearing_fem.bearing.empirical import NIKITIN_TOTAL, empirical_models, nikitin_power_loss

    args = (10000.0, 0.05, 0.08, 0.008731, 15.0, 20, 8e-6, 850.0, 8.7e-8, 500.0, 2000.0)
    q = nikitin_power_loss(*args, flow_ratio=1.0, coefficient_set="joint")
    k, b, x, y, z = NIKITIN_TOTAL["joint"]
    u = math.pi * (0.065 - 0.008731 * math.cos(math.radians(15))) * 10000 / 120
    np.testing.assert_allclose(q["u"], u, rtol=1e-14,
                               err_msg="cage speed pi (d_cg - d cos g) n/120")
    phi = k * q["Re"] ** x * q["Pr"] ** y * q["Eu"] ** z
    np.testing.assert_allclose(q["heat_power"], phi * 20 * 850 * 0.008731**2 * u**3, rtol=1e-12)
    half = nikitin_power_loss(*args, flow_ratio=0.5, coefficient_set="joint")["heat_power"]
    np.testing.assert_allclose(q["heat_power"] / half, 2.0**b, rtol=1e-12,
                               err_msg="flow-rate term (q/q_nom)^b")
    e = empirical_models(load_example("7010-steel"), 19.3)["nikitin"]
    assert e["churning_heat_power"] > e["friction_heat_power"] > 0, \
        "jet lubrication at 10000 rpm: churning dominates (Nikitin's conclusion)"
    assert 0.0016 <= e["friction_coefficient"] <= 0.0083, \
        "steel balls: reduced friction coefficient in Nikitin's reported 0.0016..0.0083"


def test_film_formulas_table():
    from bearing_fem import formulas
    from bearing_fem.bearing.empirical import film_formulas

    f = film_formulas("line", 5e5, 0.012, 2.3e11, 0.1, 3.0, 2e-8)
    np.testing.assert_allclose(f["Dowson (Zhirkin et al.)"]["h_min"],
                               f["Dowson-Higginson"]["h_min"], rtol=1e-12,
                               err_msg="Zhirkin's 'Dowson' set is Dowson-Higginson")
    assert len([k for k in f if "Zhirkin" in k]) == len(formulas.ZHIRKIN_FITS)
    p = film_formulas("point", 2000.0, 0.005, 2.3e11, 0.03, 5.0, 2e-8, ry=0.16)
    assert set(p) == {"Nijenbanning-Venner-Moes", "Hamrock-Dowson"}


@pytest.mark.parametrize("piezo", [1e-300, 1e-12])
def test_film_formulas_leave_out_the_piezoviscous_fits_for_a_vanishing_alpha(piezo):
    """alpha = 1e-300 1/Pa (G = alpha E' ~ 1e-289) gave Hamrock-Dowson films of 1e-150 m
    with h_min > h_central; such a contact is isoviscous for the fits: only the Moes-type
    fits are evaluated, as for alpha = 0."""
    from bearing_fem.bearing.empirical import FIT_MIN_MATERIALS_PARAMETER, film_formulas

    assert 2.3e11 * piezo < FIT_MIN_MATERIALS_PARAMETER
    p = film_formulas("point", 300.0, 0.004, 2.3e11, 0.007, 15.0, piezo, ry=0.1)
    assert set(p) == {"Nijenbanning-Venner-Moes"}
    f = film_formulas("line", 5e5, 0.012, 2.3e11, 0.1, 3.0, piezo)
    assert set(f) == {"Moes"}
    assert f["Moes"]["h_central"] > 0.0 and p["Nijenbanning-Venner-Moes"]["h_central"] > 0.0

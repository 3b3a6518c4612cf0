"""Traction models, Couette friction/heat and the conservative heat-flux distribution."""
from __future__ import annotations

import numpy as np
import pytest

from bearing_fem.physics import traction


def test_eyring_tends_to_newtonian_as_tau0_grows():
    eta = np.array([0.01, 1.0, 100.0])
    gd = np.array([1e3, 1e5, 1e6])
    newt = traction.newtonian_stress(eta, gd)
    # asinh(z) = z (1 - z^2/6 + ...): relative error ~ (tau_N/tau0)^2/6
    for tau0 in (1e10, 1e12):
        err = np.max(np.abs(traction.eyring_stress(eta, gd, tau0) / newt - 1.0))
        bound = (newt.max() / tau0) ** 2 / 6 * 1.01 + 1e-15
        assert err <= bound, f"Eyring must approach Newtonian as tau0 -> inf (tau0={tau0})"


def test_eyring_is_logarithmic_at_high_stress():
    tau0 = 5e6
    tau = traction.eyring_stress(1e4, 1e6, tau0)      # eta gd / tau0 = 2000
    np.testing.assert_allclose(tau, tau0 * np.log(2 * 2000.0), rtol=1e-6,
                               err_msg="asinh(z) ~ ln(2z) for large z")


def test_limiting_stress_caps_and_keeps_sign():
    p = np.array([0.0, 1e9, 2e9])
    tau_l0, lam = 2e6, 0.075
    cap = tau_l0 + lam * p
    for sign in (1.0, -1.0):
        tau = traction.limiting_stress(1e6, sign * 1e6, p, tau_l0, lam)
        np.testing.assert_allclose(tau, sign * cap, rtol=1e-14,
                                   err_msg="a huge Newtonian stress is capped at tau_L0 + Lambda p")
    low = traction.limiting_stress(1e-3, 1e3, p, tau_l0, lam)
    np.testing.assert_allclose(low, 1.0, rtol=1e-14, err_msg="below the cap: Newtonian")
    smooth = traction.limiting_stress(1e6, 1e6, p, tau_l0, lam, smooth=True)
    assert np.all(smooth <= cap) and np.all(smooth > 0.99 * cap), \
        "smooth limit stays below and close to the cap far beyond it"


def test_bad_parameters_name_field_and_unit():
    with pytest.raises(ValueError, match="tau0.*Pa"):
        traction.eyring_stress(1.0, 1.0, -1.0)
    with pytest.raises(ValueError, match="Lambda"):
        traction.limiting_stress(1.0, 1.0, 0.0, 1e6, -0.1)
    with pytest.raises(ValueError, match="traction model"):
        traction.shear_stress(1.0, 1.0, model="bingham")


def _film(n=401):
    x = np.linspace(-2e-4, 2e-4, n)
    p = 1e9 * np.sqrt(np.clip(1 - (x / 1.5e-4) ** 2, 0, None))
    h = 2e-7 + x**2 / (2 * 0.01)
    eta = 0.05 * np.exp(2e-8 * p)
    return x, p, h, eta


@pytest.mark.parametrize("model", ["newtonian", "eyring", "limiting"])
def test_couette_heat_equals_force_times_sliding_speed(model):
    x, p, h, eta = _film()
    u_s = 0.3
    force, heat = traction.couette_line(x, p, h, eta, u_s, model=model)
    np.testing.assert_allclose(heat, force * u_s, rtol=1e-13,
                               err_msg="Couette heat = traction x sliding speed (energy)")
    hf = traction.heat_flux_line(x, p, h, eta, 2.0, u_s, cavitation="none", model=model)
    np.testing.assert_allclose(hf.heat_power_couette, heat, rtol=1e-12,
                               err_msg="heat_flux_line Couette part = couette_line")
    np.testing.assert_allclose(hf.sliding_friction * u_s, hf.heat_power_couette, rtol=1e-12,
                               err_msg="per-element energy balance")


def test_non_newtonian_traction_is_below_newtonian():
    x, p, h, eta = _film()
    f_n, _ = traction.couette_line(x, p, h, eta, 0.3)
    f_e, _ = traction.couette_line(x, p, h, eta, 0.3, model="eyring", eyring_stress_pa=5e6)
    f_l, _ = traction.couette_line(x, p, h, eta, 0.3, model="limiting")
    assert 0 < f_e < f_n and 0 < f_l < f_n, "Barus Newtonian traction is the upper bound"
    # at GPa the Eyring stress is tau0 ln(2 tau_N/tau0): a friction coefficient ~ 0.02-0.1
    assert f_e / (np.trapezoid(p, x)) < 0.1, "Eyring traction coefficient is realistic"


def test_couette_2d_matches_line_for_uniform_y():
    x, p, h, eta = _film(201)
    y = np.linspace(0.0, 1e-3, 11)
    P, H, E = (np.repeat(a[:, None], y.size, axis=1) for a in (p, h, eta))
    f2, q2 = traction.couette_2d(x, y, P, H, E, 0.2, model="eyring")
    # trapezoid in x vs midpoint in the line routine: compare with the trapezoid rule
    tau = traction.eyring_stress(eta, 0.2 / h, 5e6)
    np.testing.assert_allclose(f2, np.trapezoid(tau, x) * 1e-3, rtol=1e-12,
                               err_msg="2D Couette force = line force x width for y-uniform data")
    np.testing.assert_allclose(q2, f2 * 0.2, rtol=1e-13, err_msg="2D energy")


def test_poiseuille_conservative_form_on_exact_rigid_film():
    """Rigid isoviscous full-Sommerfeld cylinder: p = -4 eta u_m x / h^2 is exact, so the
    conservative Poiseuille flux u_m p'(h - h*) equals the direct h^3 p'^2/(12 eta)."""
    eta0, u_m, R, h0 = 0.1, 1.0, 0.01, 1e-6
    L = np.sqrt(2 * R * h0)
    x = np.linspace(-60 * L, 60 * L, 20001)
    h = h0 + x**2 / (2 * R)
    p = -4 * eta0 * u_m * x / h**2
    hf = traction.heat_flux_line(x, p, h, np.full_like(x, eta0), u_m, 0.0, cavitation="none")
    np.testing.assert_allclose(hf.h_star, 4 * h0 / 3, rtol=1e-3,
                               err_msg="h* = 4 h0/3 for full-Sommerfeld (PHYSICS.md 5.2)")
    np.testing.assert_allclose(hf.heat_power_poiseuille, hf.heat_power_direct_poiseuille,
                               rtol=2e-3, err_msg="both Poiseuille forms agree on an exact film")
    # int u_m p'(h - h*) = 2 u_m F_P - u_m h* (p_end - p_start), exactly (truncated domain)
    expected = 2 * u_m * hf.rolling_resistance - u_m * hf.h_star * (p[-1] - p[0])
    np.testing.assert_allclose(hf.heat_power_poiseuille, expected, rtol=1e-10,
                               err_msg="identity Q_P = 2 u_m F_P (+ end term) holds exactly")


def test_drop_in_matches_post_keys_on_a_solved_film():
    """friction_and_heat_line has post.friction_and_heat's keys and agrees with it on a
    resolved (local-compliance) Newtonian film with sliding."""
    import bearing_fem as bf
    from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec,
                                   Model, Scene, Traction)

    s = Scene(contact=Contact(kind="line", rx=0.01), lubricant=Lubricant(viscosity=0.05,
              piezo=1e-8), materials=Materials(reduced_modulus=2.3e11),
              kinematics=Kinematics(u1=2.1, u2=1.9), load=Load(force=1e5),
              model=Model(elasticity="local"), mesh=MeshSpec(nodes=801))
    r = bf.solve(s)
    assert r.success, r.message
    d = traction.friction_and_heat_line(r.x, r.pressure, r.film, r.extra_fields["viscosity_Pa_s"],
                                        2.0, 0.2, r.quantities["load"])
    for key in ("rolling_resistance", "sliding_friction", "friction_force", "heat_power"):
        np.testing.assert_allclose(d[key], r.quantities[key], rtol=2e-2,
                                   err_msg=f"{key}: nodal midpoint rule vs post's quadrature")
    e = traction.friction_and_heat_line(r.x, r.pressure, r.film, r.extra_fields["viscosity_Pa_s"],
                                        2.0, 0.2, r.quantities["load"],
                                        traction=Traction(model="eyring"))
    assert e["sliding_friction"] < d["sliding_friction"], "Eyring routed through the section"

"""Traction models, Couette friction/heat and the conservative heat-flux distribution."""
from __future__ import annotations

import numpy as np
import pytest

from bearing_fem import post
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


def _film(n=401, y=None):
    """A Hertz-like pressure on a parabolic film, Barus viscosity, at the quadrature points
    of a P1 line grid (or of a y-uniform tensor grid of the nodes ``y``)."""
    from bearing_fem.contacts.line import LineDiscretisation
    from bearing_fem.contacts.point_grid import PointGrid

    x = np.linspace(-2e-4, 2e-4, n)
    ops = LineDiscretisation.uniform(x[0], x[-1], n).ops if y is None else \
        PointGrid.tensor(x, y).ops
    xq = ops.points[0]
    p = 1e9 * np.sqrt(np.clip(1 - (xq / 1.5e-4) ** 2, 0, None))
    px = np.gradient(p, xq) if y is None else np.zeros_like(p)
    h = 2e-7 + xq**2 / (2 * 0.01)
    eta = 0.05 * np.exp(2e-8 * p)
    return ops, p, px, h, eta


def _dissipation(model, u_s=0.3, y=None, **params):
    ops, p, px, h, eta = _film(y=y)
    grad = (px,) if y is None else (px, np.zeros_like(px))
    return post.film_dissipation(ops, h, grad, eta, p, mean_speed=2.0, sliding_speed=u_s,
                                 indicator_q=np.ones_like(p),
                                 shear={"model": model, **params})


@pytest.mark.parametrize("model", ["newtonian", "eyring", "limiting", "eyring-limiting"])
def test_couette_heat_equals_force_times_sliding_speed(model):
    d = _dissipation(model)
    np.testing.assert_allclose(d.heat_power_couette, d.sliding_friction * 0.3, rtol=1e-13,
                               err_msg="Couette heat = traction x sliding speed (energy)")
    ops = _film()[0]
    np.testing.assert_allclose(ops.integrate(d.couette_density), d.heat_power_couette,
                               rtol=1e-12, err_msg="the density integrates to the total")


def test_non_newtonian_traction_is_below_newtonian():
    f_n = _dissipation("newtonian").sliding_friction
    f_e = _dissipation("eyring", eyring_stress=5e6).sliding_friction
    f_l = _dissipation("limiting").sliding_friction
    f_el = _dissipation("eyring-limiting").sliding_friction
    assert 0 < f_e < f_n and 0 < f_l < f_n, "Barus Newtonian traction is the upper bound"
    assert 0 < f_el <= min(f_e, f_l) * (1 + 1e-12), "the combination is below both"
    load = 1e9 * np.pi * 1.5e-4 / 2   # int of the semi-elliptic pressure [N/m]
    # at GPa the Eyring stress is tau0 ln(2 tau_N/tau0): a friction coefficient ~ 0.02-0.1
    assert 0.01 < f_el / load < 0.1, "generic traction gives a realistic friction coefficient"


def test_couette_2d_matches_line_for_uniform_y():
    y = np.linspace(0.0, 1e-3, 11)
    line = _dissipation("eyring")
    plane = _dissipation("eyring", y=y)
    np.testing.assert_allclose(plane.sliding_friction, line.sliding_friction * 1e-3, rtol=1e-10,
                               err_msg="2D Couette force = line force x width for y-uniform data")


def test_poiseuille_conservative_form_on_exact_rigid_film():
    """Rigid isoviscous full-Sommerfeld cylinder: p = -4 eta u_m x / h^2 is exact, so the
    conservative Poiseuille heat u_m int h p' equals the direct int h^3 p'^2/(12 eta)."""
    from bearing_fem.contacts.line import LineDiscretisation

    eta0, u_m, R, h0 = 0.1, 1.0, 0.01, 1e-6
    L = np.sqrt(2 * R * h0)
    ops = LineDiscretisation.uniform(-60 * L, 60 * L, 20001).ops
    x = ops.points[0]
    h = h0 + x**2 / (2 * R)
    p = -4 * eta0 * u_m * x / h**2
    px = -4 * eta0 * u_m * (1 / h**2 - 2 * x * (x / R) / h**3)
    d = post.film_dissipation(ops, h, (px,), np.full_like(x, eta0), p, mean_speed=u_m,
                              sliding_speed=0.0, indicator_q=np.ones_like(x),
                              shear={"model": "newtonian"})
    np.testing.assert_allclose(d.h_star, 4 * h0 / 3, rtol=1e-3,
                               err_msg="h* = 4 h0/3 for full-Sommerfeld (docs/analytic.md)")
    np.testing.assert_allclose(d.heat_power_poiseuille, d.heat_power_poiseuille_direct,
                               rtol=2e-3, err_msg="both Poiseuille forms agree on an exact film "
                                                  "(truncation at +-60 lengths)")
    np.testing.assert_allclose(d.heat_power_poiseuille, 2 * u_m * d.rolling_resistance,
                               rtol=1e-12, err_msg="Q_P = 2 u_m F_P, by definition")
    np.testing.assert_allclose(ops.integrate(d.poiseuille_density), d.heat_power_poiseuille,
                               rtol=1e-3, atol=1e-9 * d.heat_power_poiseuille,
                               err_msg="the h*-shifted density integrates to Q_P (int p' ~ 0)")


def test_film_of_a_few_molecular_layers_is_flagged():
    from bearing_fem.post import MOLECULAR_FILM, film_numbers

    x = np.linspace(-1e-3, 1e-3, 5)
    p = np.array([0.0, 1e8, 2e8, 1e8, 0.0])
    for h_min, flagged in ((0.5 * MOLECULAR_FILM, True), (2.0 * MOLECULAR_FILM, False)):
        h = np.full(5, 4.0 * MOLECULAR_FILM)
        h[3] = h_min
        nums, notes = film_numbers(h, h.copy(), 4.0 * MOLECULAR_FILM, p, 1.0, x)
        assert nums["h_min"] == h_min
        assert any("molecular" in n for n in notes) == flagged, (h_min, notes)


def test_viscosity_overflow_warning_names_the_law_and_its_effect():
    """The clipped-viscosity warning says which law overflowed and whether the solve used
    that viscosity: a rigid Roelands film (Newton on the pointwise viscosity) is not
    'Barus ... in the reduced pressure, not affected'."""
    import bearing_fem as bf

    eta = np.array([1.0, np.inf])
    clipped, barus = post.reported_viscosity(eta, law="barus", reduced=True)
    assert clipped[1] == np.finfo(float).max and len(barus) == 1
    assert "Barus at alpha p > 709.8" in barus[0] and "not affected" in barus[0], barus
    _, roe = post.reported_viscosity(eta, law="roelands", reduced=False)
    assert "Roelands law" in roe[0] and "Barus" not in roe[0], roe
    assert "not affected" not in roe[0] and "solved with this viscosity" in roe[0], roe
    assert post.reported_viscosity(np.ones(3), law="roelands", reduced=False)[1] == []
    # end to end: a rigid Roelands gap too narrow for a solution (0.2 s), full-Sommerfeld
    # so that Newton solves it (with Reynolds cavitation the linear path refuses it at once)
    scene = bf.Scene.from_dict({
        "contact": {"kind": "line", "rx": 0.008},
        "lubricant": {"viscosity": 0.04, "piezo": 2e-8, "viscosity_law": "roelands"},
        "kinematics": {"u1": 5.0, "u2": 5.0}, "load": {"gap": 3e-7},
        "model": {"elasticity": "rigid", "cavitation": "none"},
        "solver": {"iteration_budget": 100}})
    r = bf.solve(scene)
    over = [w for w in r.warnings if "overflows double precision" in w]
    assert not r.success and over, (r.status, r.warnings)
    assert "Roelands law" in over[0] and "not affected" not in over[0], over

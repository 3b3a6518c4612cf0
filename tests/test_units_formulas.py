"""Scalings (bearing_fem.units) and film fits (bearing_fem.formulas), docs/theory.md sections 1, 13, 16.

Every check compares against an independent route (a different formula of docs/theory.md,
quadrature, an analytic oracle, a round trip), never against pasted numbers.
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad

from bearing_fem import analytic, formulas, units

STEEL_E = 2.1e11
STEEL_NU = 0.3


# --------------------------------------------------------------------------- materials
def test_reduced_modulus_equal_bodies_and_rigid_limit():
    e_prime = units.reduced_modulus(STEEL_E, STEEL_NU, STEEL_E, STEEL_NU)
    assert_allclose(e_prime, STEEL_E / (1 - STEEL_NU**2), rtol=1e-14,
                    err_msg="two equal bodies: E' = E/(1-nu^2) up to round-off")
    rigid = units.reduced_modulus(STEEL_E, STEEL_NU, np.inf, 0.3)
    assert_allclose(rigid, 2 * STEEL_E / (1 - STEEL_NU**2), rtol=1e-14,
                    err_msg="rigid second body: E' = 2E1/(1-nu1^2) up to round-off")


@pytest.mark.parametrize("args, name", [((-1.0, 0.3, 2e11, 0.3), "e1"),
                                        ((2e11, 0.7, 2e11, 0.3), "nu1"),
                                        ((2e11, 0.3, 0.0, 0.3), "e2")])
def test_reduced_modulus_rejects_bad_input(args, name):
    with pytest.raises(ValueError, match=name):
        units.reduced_modulus(*args)


def test_reduced_radius_concave_and_errors():
    assert_allclose(units.reduced_radius(0.01, -0.0105), 1 / (1 / 0.01 - 1 / 0.0105),
                    rtol=1e-14, err_msg="concave race enters with a negative radius")
    assert_allclose(units.reduced_radius(0.01, np.inf), 0.01, rtol=0,
                    err_msg="flat counter-surface leaves the radius unchanged exactly")
    with pytest.raises(ValueError, match=r"1/r1 \+ 1/r2.*1/m"):
        units.reduced_radius(0.01, -0.009)
    with pytest.raises(ValueError, match="r1"):
        units.reduced_radius(0.0, 0.01)


def test_negative_radius_message_names_argument_value_and_unit():
    with pytest.raises(ValueError, match=r"radius must be > 0 m.*-0\.01"):
        units.hertz_line(1e5, -0.01, 2.2e11)


# --------------------------------------------------------------------------- Hertz
def test_hertz_line_two_forms_and_load_integral():
    w, radius, e_prime = 2.0e5, 0.012, 2.2e11
    b, p_h = units.hertz_line(w, radius, e_prime)
    assert_allclose(p_h, e_prime * b / (4 * radius), rtol=1e-13,
                    err_msg="docs/theory.md section 13 gives p_h both as 2w/(pi b) and E' b/(4R)")
    load, _ = quad(lambda x: analytic.hertz_line_pressure(x, b, p_h), -b, b,
                   epsabs=0, epsrel=1e-12)
    assert_allclose(load, w, rtol=1e-9, err_msg="quadrature of the semi-ellipse, 1e-12 asked")


def test_hertz_point_circular_exact_forms():
    force, radius, e_prime = 50.0, 0.008, 2.3e11
    hp = units.hertz_point(force, radius, radius, e_prime)
    assert hp.k == 1.0 and hp.a_x == hp.a_y
    assert_allclose(hp.a_x**3, 1.5 * force * radius / e_prime, rtol=1e-13,
                    err_msg="circular Hertz radius, round-off only")
    assert_allclose(hp.p_h, hp.a_x * e_prime / (np.pi * radius), rtol=1e-13,
                    err_msg="docs/theory.md section 13: p_h = 3F/(2 pi a^2) = a E'/(pi R)")
    assert_allclose(hp.delta, hp.a_x**2 / radius, rtol=1e-13,
                    err_msg="docs/theory.md section 13: delta = a^2/R; delta comes from the elliptic "
                            "branch formula 2 p_h a K(0)/E', so this cross-checks it")


@pytest.mark.parametrize("eps", [1e-9, 1e-7, 1e-5, 1e-3])
def test_hertz_point_continuous_at_the_circle(eps):
    """The series branch (tiny m) and the brentq branch join the exact circle smoothly."""
    circ = units.hertz_point(40.0, 0.01, 0.01, 2.2e11)
    ell = units.hertz_point(40.0, 0.01, 0.01 * (1 + eps), 2.2e11)
    # first-order sensitivity of a, p_h, delta to ry/rx is O(1): allow 2 eps
    for name in ("a_x", "a_y", "p_h", "delta"):
        assert_allclose(getattr(ell, name), getattr(circ, name), rtol=2 * eps + 1e-12,
                        err_msg=f"{name}: O(eps) change for ry/rx = 1 + {eps}")


def test_hertz_point_axis_swap_and_hamrock_k():
    f, e_prime = 30.0, 2.2e11
    for ratio in (1.5, 3.0, 10.0, 30.0):
        one = units.hertz_point(f, 0.01, 0.01 * ratio, e_prime)
        two = units.hertz_point(f, 0.01 * ratio, 0.01, e_prime)
        assert_allclose([one.a_x, one.a_y, one.p_h], [two.a_y, two.a_x, two.p_h],
                        rtol=1e-12, err_msg="swapping rx, ry swaps the semi-axes")
        assert one.k > 1.0
        assert_allclose(one.k, units.hamrock_ellipticity(0.01, 0.01 * ratio), rtol=0.03,
                        err_msg="Hamrock-Brewe k = 1.03 (ry/rx)^0.64 is a ~3% fit on 1..30")
        assert_allclose(2 * np.pi * one.a_x * one.a_y * one.p_h / 3, f, rtol=1e-13,
                        err_msg="ellipsoidal pressure volume equals the load")


# --------------------------------------------------------------------------- Moes groups
def _raw_line_groups(w, radius, e_prime, eta, u_m, alpha):
    """Moes groups written out from docs/theory.md section 13 (independent of units.moes_line)."""
    u_sum = 2 * eta * u_m / (e_prime * radius)
    return w / (e_prime * radius) / np.sqrt(u_sum), alpha * e_prime * u_sum**0.25, u_sum


def test_moes_line_groups_and_alpha_ph():
    args = (1.5e5, 0.01, 2.2e11, 0.03, 2.0, 2.1e-8)
    g = units.moes_line(*args)
    m_ref, l_ref, u_sum = _raw_line_groups(*args)
    assert_allclose([g["M"], g["L"], g["U_sum"]], [m_ref, l_ref, u_sum], rtol=1e-13,
                    err_msg="same definitions, round-off only")
    assert_allclose(g["alpha_ph"], g["L"] * np.sqrt(g["M"] / (2 * np.pi)), rtol=1e-12,
                    err_msg="docs/theory.md section 13 identity alpha p_h = L sqrt(M/(2 pi))")


def test_venner_moes_line_conversion_from_a_film():
    args = (1.5e5, 0.01, 2.2e11, 0.03, 2.0, 2.1e-8)
    g = units.moes_line(*args)
    h = 3.3e-7
    h_venner = h * args[1] / g["b"] ** 2
    h_moes = h / args[1] / np.sqrt(g["U_sum"])
    assert_allclose(units.venner_to_moes_line(h_venner, g["M"]), h_moes, rtol=1e-12,
                    err_msg="both films built from the same h: round-off only")
    assert_allclose(units.moes_to_venner_line(h_moes, g["M"]), h_venner, rtol=1e-12,
                    err_msg="inverse conversion, round-off only")


def test_venner_moes_point_conversion_from_a_film():
    args = (25.0, 0.0095, 0.0095, 2.2e11, 0.05, 1.5, 2.0e-8)
    g = units.moes_point(*args)
    h = 2.1e-7
    h_venner = h * args[1] / g["a"] ** 2
    h_moes = h / args[1] / np.sqrt(g["U_sum"])
    assert_allclose(units.venner_to_moes_point(h_venner, g["M"]), h_moes, rtol=1e-12,
                    err_msg="circular Moes/Venner conversion from one h, round-off only")
    assert_allclose(units.moes_to_venner_point(h_moes, g["M"]), h_venner, rtol=1e-12,
                    err_msg="inverse conversion, round-off only")
    assert_allclose(g["alpha_ph"], g["L"] / np.pi * (1.5 * g["M"]) ** (1 / 3), rtol=1e-12,
                    err_msg="docs/theory.md section 13 identity alpha p_h = (L/pi)(3M/2)^(1/3)")


@pytest.mark.parametrize("fix", [{}, {"viscosity": 0.08}, {"mean_speed": 3.0}])
def test_line_scene_from_moes_round_trip(fix):
    m_in, l_in = 20.0, 10.0
    s = units.line_scene_from_moes(m_in, l_in, radius=0.015, e_prime=2.3e11, piezo=1.8e-8,
                                   **fix)
    g = units.moes_line(s["load_per_length"], s["radius"], s["e_prime"], s["viscosity"],
                        s["mean_speed"], s["piezo"])
    assert_allclose([g["M"], g["L"]], [m_in, l_in], rtol=1e-12,
                    err_msg="inverse map then forward map: round-off only")
    for key, val in fix.items():
        assert s[key] == val


def test_point_scene_from_moes_round_trip():
    s = units.point_scene_parameters_from_moes(200.0, 10.0, rx=0.01, ry=0.03,
                                               mean_speed=1.0)
    g = units.moes_point(s["force"], s["rx"], s["ry"], s["e_prime"], s["viscosity"],
                         s["mean_speed"], s["piezo"])
    assert_allclose([g["M"], g["L"]], [200.0, 10.0], rtol=1e-12,
                    err_msg="inverse map then forward map: round-off only")
    with pytest.raises(ValueError, match="not both"):
        units.point_scene_parameters_from_moes(1.0, 1.0, viscosity=0.1, mean_speed=1.0)


# --------------------------------------------------------------------------- film fits
@pytest.mark.parametrize("m", [1e-4, 1e-3])
def test_moes_line_rigid_isoviscous_is_martin(m):
    """H_RI = 3/M is Martin's exact load written with the outlet film h* (not h0).

    Build a Martin scene, compute M from its closed-form load and H_Moes from h*; the
    product is exactly 3; and moes_line_central(M, L=0) tends to it as M -> 0.
    """
    radius, e_prime, eta, u_m, h0 = 0.01, 2.2e11, 0.04, 1.3, 2e-7
    w = float(analytic.martin_load(h0, radius, eta, u_m))
    g = units.moes_line(w, radius, e_prime, eta, u_m, 0.0)
    h_star = float(analytic.martin_hstar(h0))
    assert_allclose(h_star / radius / np.sqrt(g["U_sum"]) * g["M"], 3.0, rtol=1e-12,
                    err_msg="exact identity w h* = 6 eta0 u_m R, round-off only")
    # the fit at small M: blending corrections are O(M^(28/15)) relative (H_EI/H_RI)^(7/3)
    assert_allclose(formulas.moes_line_central(m, 0.0), 3.0 / m, rtol=10 * m ** (28 / 15),
                    err_msg="rigid-isoviscous limit; tolerance = size of the H_EI term")


def test_moes_line_rigid_piezoviscous_is_martin_barus_blow_up():
    """H_RP = 1.287 L^(2/3): the film h* at which Martin's Barus solution ceases to exist.

    martin_existence_ratio scales as h0^(-3/2), so the critical h0 follows in closed form.
    """
    radius, e_prime, eta, u_m, alpha = 0.01, 2.2e11, 0.04, 1.3, 2.0e-8
    h_try = 1e-6
    ratio = float(analytic.martin_existence_ratio(h_try, radius, eta, u_m, piezo=alpha))
    h0_crit = h_try * ratio ** (2 / 3)
    assert_allclose(analytic.martin_existence_ratio(h0_crit, radius, eta, u_m, piezo=alpha),
                    1.0, rtol=1e-12, err_msg="h0^(-3/2) scaling, round-off")
    g = units.moes_line(1.0, radius, e_prime, eta, u_m, alpha)
    h_moes = float(analytic.martin_hstar(h0_crit)) / radius / np.sqrt(g["U_sum"])
    h_rp = formulas.moes_line_asymptotes(1.0, g["L"])["H_RP"]
    assert_allclose(h_moes, h_rp, rtol=5e-4,
                    err_msg="Moes' 1.287 is this closed form rounded to 4 digits")


@pytest.mark.parametrize("fit, asym", [(formulas.moes_line_central, formulas.moes_line_asymptotes),
                                       (formulas.nijenbanning_central,
                                        formulas.nijenbanning_asymptotes)])
def test_film_fits_reach_their_asymptotes(fit, asym):
    cases = [  # (M, L, asymptote, rtol and why)
        (1e-4, 0.0, "H_RI", 1e-5),   # H_EI/H_RI ~ 1e-3..1e-6 -> corrections << 1e-5
        (1e7, 0.0, "H_EI", 1e-5),    # H_RI/H_EI ~ 1e-6
        (1.0, 1e12, "H_RP", 1e-3),   # H_RP/H_EP ~ 0.1 and H_RI/H_RP ~ 1e-6
        (1e12, 1e4, "H_EP", 3e-3),   # H_EP/H_RP ~ 0.05 (line); NVM: 0.1, exponent -8
    ]
    for m, l, name, rtol in cases:
        assert_allclose(fit(m, l), asym(m, l)[name], rtol=rtol,
                        err_msg=f"{fit.__name__}({m}, {l}) -> {name}: blending leftovers")


def test_nijenbanning_elliptic_reduces_and_is_vectorised():
    m = np.array([10.0, 100.0, 1000.0])
    assert_allclose(formulas.nijenbanning_central(m, 10.0, 1.0),
                    [formulas.nijenbanning_central(v, 10.0) for v in m], rtol=1e-14,
                    err_msg="array call equals scalar calls")
    # an elongated contact (ry > rx, lambda < 1) has less side leakage: thicker film
    assert np.all(formulas.nijenbanning_central(m, 10.0, 0.2)
                  > formulas.nijenbanning_central(m, 10.0, 1.0))


def test_zhirkin_fits():
    u, g, w = 1e-11, 4500.0, 5e-5
    assert_allclose(formulas.power_law_film(u, g, w, formulas.ZHIRKIN_FITS["Dowson"]),
                    formulas.dowson_higginson_line_min(u, g, w), rtol=1e-14,
                    err_msg="the Dowson row of Zhirkin et al. is the Dowson-Higginson formula")
    k, a, b, c = formulas.ZHIRKIN_FITS["Ertel-Grubin"]
    assert_allclose([a, b, c], [8 / 11, 8 / 11, -1 / 11], atol=5e-4,
                    err_msg="Grubin's exponents 8/11, -1/11 printed to 3 decimals")
    assert set(formulas.ZHIRKIN_FITS) == set(formulas.ZHIRKIN_CONVENTIONS)
    with pytest.raises(ValueError, match="coeffs"):
        formulas.power_law_film(u, g, w, (1.0, 2.0))


def test_line_fits_agree_within_their_bands():
    """Typical steel roller: Moes (sum speed), Pan-Hamrock and Dowson-Higginson (mean
    speed) central/minimum films. Agreement within bands checks the speed conventions: a
    factor 2 slip in U would move the films by 2^0.7 = 1.6."""
    args = (3.0e5, 0.01, 2.2e11, 0.04, 2.0, 2.0e-8)
    h_moes = formulas.line_central_film_moes(*args)
    h_min_ph, h_c_ph = formulas.line_films_pan_hamrock(*args)
    h_min_dh = formulas.line_min_film_dowson_higginson(*args)
    assert_allclose(h_c_ph, h_moes, rtol=0.25, err_msg="two fits of the same physics: 25% band")
    assert_allclose(h_min_ph, h_min_dh, rtol=0.25, err_msg="two h_min fits: 25% band")
    assert h_min_ph < h_c_ph


def test_point_fits_agree_within_their_bands():
    args = (30.0, 0.0127, 0.0127, 2.3e11, 0.04, 1.0, 2.2e-8)
    h_nvm = formulas.point_central_film_nvm(*args)
    h_min, h_c = formulas.point_films_hamrock_dowson(*args)
    assert_allclose(h_c, h_nvm, rtol=0.25,
                    err_msg="Hamrock-Dowson vs Nijenbanning central film: 25% band")
    assert h_min < h_c
    g = units.moes_point(*args)
    assert_allclose(h_nvm / args[1] / np.sqrt(g["U_sum"]),
                    formulas.nijenbanning_central(g["M"], g["L"], 1.0), rtol=1e-13,
                    err_msg="dimensional wrapper = dimensionless fit, round-off")


def test_formulas_reject_nonpositive_groups():
    with pytest.raises(ValueError, match="M must be > 0"):
        formulas.moes_line_central(-1.0, 5.0)
    with pytest.raises(ValueError, match="viscosity must be > 0 Pa s"):
        formulas.line_central_film_moes(1e5, 0.01, 2.2e11, 0.0, 1.0, 2e-8)


def test_summary_units_refuses_an_unknown_kind():
    """summary_units("Point") (or any typo) returned the line-contact units, per metre,
    without a word; only "line" and "point" are contact kinds."""
    from bearing_fem.result import summary_units

    assert summary_units("line")["load"] == "N/m" and summary_units("point")["load"] == "N"
    for bad in ("Point", "ball", ""):
        with pytest.raises(ValueError, match=r"kind must be 'line' or 'point', got "):
            summary_units(bad)


def test_moes_fits_reach_the_isoviscous_limit_without_overflow_warnings():
    """L = 1e-290 (alpha = 1e-300 1/Pa) overflowed H_RP^-3.5 (line) and H_RP^-8 (point) to
    inf, the exact limit, with a raw RuntimeWarning; the result is the L = 0 film."""
    import warnings

    from bearing_fem import formulas

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        line = formulas.moes_line_central(20.0, 1e-290)
        point = formulas.nijenbanning_central(50.0, 1e-290, 0.1)
    assert line == pytest.approx(float(formulas.moes_line_central(20.0, 0.0)), rel=1e-12)
    assert point == pytest.approx(float(formulas.nijenbanning_central(50.0, 0.0, 0.1)),
                                  rel=1e-12)

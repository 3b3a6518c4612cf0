"""Closed-form oracles of bearing_fem.analytic, Section A (docs/theory.md sections 14.1-14.3).

Each closed form is checked against independent numerical evidence: finite-difference
residuals of the Reynolds equation it claims to solve, quadrature of loads, direct
quadrature of the Boussinesq / plane-strain compliance integrals. No pasted numbers.
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad
from scipy.optimize import minimize_scalar

from bearing_fem import analytic, units

RNG_SEED = 20240601
ETA, U_M = 0.04, 1.5            # Pa s, m/s
RX, RY = 0.01, 0.03             # m
A_CURV, B_CURV = 1 / (2 * RX), 1 / (2 * RY)
H0 = 2e-7                       # m


# ----------------------------------------------------------------------------- helpers
def _reynolds_residual_2d(p_fun, h_fun, eta_fun, x, y, step):
    """div(h^3/(12 eta(p)) grad p) by nested central differences (O(step^2))."""
    def flux_x(xm, ym, dx):
        hm = h_fun(xm, ym)
        pm = p_fun(xm, ym)
        dp = (p_fun(xm + dx / 2, ym) - p_fun(xm - dx / 2, ym)) / dx
        return hm**3 / (12 * eta_fun(pm)) * dp

    def flux_y(xm, ym, dy):
        hm = h_fun(xm, ym)
        pm = p_fun(xm, ym)
        dp = (p_fun(xm, ym + dy / 2) - p_fun(xm, ym - dy / 2)) / dy
        return hm**3 / (12 * eta_fun(pm)) * dp

    dx, dy = step
    div = (flux_x(x + dx / 2, y, dx) - flux_x(x - dx / 2, y, dx)) / dx
    if dy is not None:
        div = div + (flux_y(x, y + dy / 2, dy) - flux_y(x, y - dy / 2, dy)) / dy
    return div


def _random_points(n, scale_x, scale_y):
    rng = np.random.default_rng(RNG_SEED)
    return rng.uniform(-3 * scale_x, 3 * scale_x, n), rng.uniform(-3 * scale_y, 3 * scale_y, n)


def _boussinesq_ellipse(x0, y0, a_x, a_y, p_h, e_prime):
    """v(x0, y0) = (2/(pi E')) int p/dist for p = p_h sqrt(1 - (x/a_x)^2 - (y/a_y)^2).

    Polar coordinates centred on (x0, y0) remove the 1/dist singularity; the radial
    integral of the square root of a quadratic is done exactly, the angular one by quad.
    """
    def radial(theta):
        c, s = np.cos(theta), np.sin(theta)
        c2 = c**2 / a_x**2 + s**2 / a_y**2
        c1 = 2 * (x0 * c / a_x**2 + y0 * s / a_y**2)
        c0 = x0**2 / a_x**2 + y0**2 / a_y**2 - 1
        disc = c1**2 - 4 * c2 * c0
        if disc <= 0:
            return 0.0
        s_lo, s_hi = (-c1 - np.sqrt(disc)) / (2 * c2), (-c1 + np.sqrt(disc)) / (2 * c2)
        if s_hi <= 0:
            return 0.0
        mid, half = (s_lo + s_hi) / 2, (s_hi - s_lo) / 2
        start = max(s_lo, 0.0)
        phi1 = np.arccos(np.clip((start - mid) / half, -1, 1))
        # int_start^s_hi sqrt(c2 (s_hi - s)(s - s_lo)) ds with s = mid + half cos(phi)
        return np.sqrt(c2) * half**2 * (phi1 / 2 - np.sin(2 * phi1) / 4)

    inside = x0**2 / a_x**2 + y0**2 / a_y**2 < 1
    if inside:
        total, _ = quad(radial, 0, 2 * np.pi, epsabs=0, epsrel=1e-11, limit=200)
    else:  # tangent directions are kinks of the integrand: split there
        phi0 = np.arctan2(y0, x0) + np.pi
        total, _ = quad(lambda t: radial(phi0 + t), -np.pi / 2, np.pi / 2, epsabs=0,
                        epsrel=1e-10, limit=400)
    return 2 * p_h * total / (np.pi * e_prime)


# ----------------------------------------------------------------------------- Barus
def test_barus_round_trip_limits_and_blow_up():
    alpha = 2e-8
    p = np.array([-1e8, 0.0, 1e6, 5e8, 1e9])
    q = analytic.reduced_from_barus(p, alpha)
    assert_allclose(analytic.barus_from_reduced(q, alpha), p, rtol=1e-7,
                    err_msg="round trip; at 1 GPa 1 - alpha q = e^-20 ~ 2e-9 keeps only "
                            "~7 digits of p (beyond ~1.8 GPa q rounds to 1/alpha: inf)")
    assert_allclose(analytic.barus_from_reduced(q, 0.0), q, rtol=0,
                    err_msg="alpha = 0 is the identity exactly")
    assert_allclose(analytic.barus_from_reduced(1e4, 1e-12), 1e4, rtol=1e-8,
                    err_msg="small alpha q: p = q (1 + alpha q/2 + ...), alpha q = 1e-8")
    blown = analytic.barus_from_reduced([1 / alpha, 2 / alpha], alpha)
    assert np.all(np.isinf(blown)), "no pressure exists where alpha q >= 1"
    with pytest.raises(ValueError, match=r"piezo must be >= 0 1/Pa"):
        analytic.barus_from_reduced(1.0, -1e-8)


# ----------------------------------------------------------------------------- Kapitsa
@pytest.mark.parametrize("dh0dt", [0.0, -5e-3, 3e-3])
@pytest.mark.parametrize("piezo_fraction", [0.0, 0.9])
def test_kapitsa_point_solves_reynolds(dh0dt, piezo_fraction):
    """Wedge + squeeze solution solves div(h^3/(12 eta) grad p) = u_m dh/dx + dh0/dt,
    isoviscous (alpha = 0) and with Barus eta = eta0 exp(alpha p) at alpha q_max = 0.9.
    The squeeze rates are of the order of the wedge source u_m 2 a sqrt(h0/a) ~ 1e-2 m/s
    so that an error in either coefficient shows above the tolerance."""
    q_max = analytic.kapitsa_point_max_reduced(H0, A_CURV, B_CURV, ETA, U_M, dh0dt)
    alpha = piezo_fraction / float(q_max)

    def p_fun(x, y):
        return analytic.kapitsa_point_pressure(x, y, H0, A_CURV, B_CURV, ETA, U_M, dh0dt,
                                               alpha)

    def h_fun(x, y):
        return H0 + A_CURV * x**2 + B_CURV * y**2

    lx, ly = np.sqrt(H0 / A_CURV), np.sqrt(H0 / B_CURV)
    x, y = _random_points(25, lx, ly)
    lhs = _reynolds_residual_2d(p_fun, h_fun, lambda p: ETA * np.exp(alpha * p), x, y,
                                (1e-3 * lx, 1e-3 * ly))
    rhs = U_M * 2 * A_CURV * x + dh0dt
    scale = U_M * 2 * A_CURV * lx + abs(dh0dt)
    assert_allclose(lhs, rhs, rtol=0, atol=1e-5 * scale,
                    err_msg="central differences with step 1e-3 L: O(1e-6) truncation, "
                            "tolerance 1e-5 of the source-term scale")


@pytest.mark.parametrize("dh0dt", [0.0, -5e-3])
def test_kapitsa_line_solves_reynolds_and_limits(dh0dt):
    radius = RX

    def p_fun(x, y):
        return analytic.kapitsa_line_pressure(x, H0, radius, ETA, U_M, dh0dt)

    def h_fun(x, y):
        return H0 + x**2 / (2 * radius)

    lx = np.sqrt(2 * radius * H0)
    x, _ = _random_points(25, lx, lx)
    lhs = _reynolds_residual_2d(p_fun, h_fun, lambda p: ETA, x, 0 * x, (1e-3 * lx, None))
    rhs = U_M * x / radius + dh0dt
    scale = U_M * lx / radius + abs(dh0dt)
    assert_allclose(lhs, rhs, rtol=0, atol=1e-5 * scale,
                    err_msg="1D Reynolds residual by central differences, O(1e-6)")
    # the line function is the b -> 0 limit of the point solution
    x_grid = np.linspace(-4 * lx, 4 * lx, 41)
    p_line = p_fun(x_grid, 0.0)
    assert_allclose(analytic.kapitsa_point_pressure(x_grid, 0.0, H0, A_CURV, 1e-9 * A_CURV,
                                                    ETA, U_M, dh0dt),
                    p_line, rtol=0, atol=1e-8 * np.max(np.abs(p_line)),
                    err_msg="b = 1e-9 a: O(b/a) = 1e-9 difference from the line limit")


def test_kapitsa_line_full_sommerfeld_forms():
    """docs/theory.md section 14.2: p = -4 P0 sin(g) cos^3(g), dp/dx = 0 at h = 4 h0/3, zero load."""
    radius = RX
    length = np.sqrt(2 * radius * H0)
    p0 = ETA * U_M * length / H0**2
    x = np.linspace(-5, 5, 101) * length
    g = np.arctan(x / length)
    assert_allclose(analytic.kapitsa_line_pressure(x, H0, radius, ETA, U_M),
                    -4 * p0 * np.sin(g) * np.cos(g) ** 3, rtol=1e-12, atol=1e-12 * p0,
                    err_msg="trigonometric form of the same expression, round-off")
    x_ext = -np.sqrt(2 * radius * (4 * H0 / 3 - H0))
    res = minimize_scalar(lambda s: -analytic.kapitsa_line_pressure(s, H0, radius, ETA, U_M),
                          bracket=(-2 * length, -0.3 * length), tol=1e-12)
    assert_allclose(res.x, x_ext, rtol=1e-5,
                    err_msg="numerical maximiser; x resolved to ~sqrt(eps) relative")
    load, _ = quad(lambda s: analytic.kapitsa_line_pressure(s, H0, radius, ETA, U_M),
                   -np.inf, np.inf, epsabs=1e-10 * p0 * length)
    assert abs(load) < 1e-8 * p0 * length, "odd pressure: zero load (full-Sommerfeld)"


@pytest.mark.parametrize("b_curv", [0.0, B_CURV])
@pytest.mark.parametrize("dh0dt", [0.0, -2e-6, 2e-6, -2e-8])
def test_kapitsa_max_reduced_matches_numerical_maximum(b_curv, dh0dt):
    q_max = float(analytic.kapitsa_point_max_reduced(H0, A_CURV, b_curv, ETA, U_M, dh0dt))
    lx = np.sqrt(H0 / A_CURV)

    def q_line(x):
        return analytic.kapitsa_point_pressure(x, 0.0, H0, A_CURV, b_curv, ETA, U_M, dh0dt)

    xs = np.linspace(-20 * lx, 20 * lx, 8001)
    i = int(np.argmax(q_line(xs)))
    res = minimize_scalar(lambda s: -q_line(s), bounds=(xs[max(i - 1, 0)], xs[min(i + 1, 8000)]),
                          method="bounded", options={"xatol": 1e-14 * lx})
    numeric = max(-res.fun, 0.0)
    assert_allclose(q_max, numeric, rtol=1e-9,
                    err_msg="grid search + bounded refinement; the maximum is quadratic "
                            "in x, so ~1e-7 relative accuracy of x gives 1e-14 in q")
    # off the axis the pressure is never larger (the maximum is on y = 0)
    x2, y2 = np.meshgrid(np.linspace(-5, 5, 61) * lx, np.linspace(-5, 5, 61) * lx)
    assert np.max(analytic.kapitsa_point_pressure(x2, y2, H0, A_CURV, b_curv, ETA, U_M,
                                                  dh0dt)) <= q_max * (1 + 1e-12)


def test_kapitsa_wedge_closed_forms_and_squeeze_load():
    a_coef, b_coef = analytic.kapitsa_point_coefficients(ETA, U_M, A_CURV, B_CURV, -1e-6)
    q_max = analytic.kapitsa_point_max_reduced(H0, A_CURV, B_CURV, ETA, U_M)
    assert_allclose(q_max, 9 * abs(a_coef) / 16 / np.sqrt(3 * A_CURV) * H0**-1.5, rtol=1e-13,
                    err_msg="docs/theory.md section 14.1 wedge maximum, round-off")
    # squeeze load B pi/(sqrt(ab) h0) against quadrature in elliptic polar coordinates
    # x = r cos(t)/sqrt(a), y = r sin(t)/sqrt(b) (Jacobian r/sqrt(ab)); the pressure is
    # evaluated by the oracle itself along two different rays t
    for t in (0.3, 2.0):
        def integrand(r, t=t):
            x, y = r * np.cos(t) / np.sqrt(A_CURV), r * np.sin(t) / np.sqrt(B_CURV)
            q = analytic.kapitsa_point_pressure(x, y, H0, A_CURV, B_CURV, ETA, 0.0, -1e-6)
            return q * r / np.sqrt(A_CURV * B_CURV)

        radial, _ = quad(integrand, 0, np.inf, epsabs=0, epsrel=1e-12)
        assert_allclose(2 * np.pi * radial, b_coef * np.pi / (np.sqrt(A_CURV * B_CURV) * H0),
                        rtol=1e-9, err_msg="radial quadrature, 1e-12 asked")


def test_kapitsa_existence_boundary():
    ratio_one = float(analytic.kapitsa_existence_ratio(H0, A_CURV, B_CURV, ETA, U_M, -1e-6,
                                                       piezo=1.0))
    lx = np.sqrt(H0 / A_CURV)
    x, y = np.meshgrid(np.linspace(-6, 6, 2401) * lx, np.linspace(-2, 2, 5) * lx)
    below = analytic.kapitsa_point_pressure(x, y, H0, A_CURV, B_CURV, ETA, U_M, -1e-6,
                                            0.99 / ratio_one)
    above = analytic.kapitsa_point_pressure(x, y, H0, A_CURV, B_CURV, ETA, U_M, -1e-6,
                                            1.01 / ratio_one)
    assert np.all(np.isfinite(below)), "alpha q_max = 0.99: solution exists everywhere"
    assert np.any(np.isinf(above)), "alpha q_max = 1.01: blow-up region reported as inf"
    with pytest.raises(ValueError, match=r"h0 must be > 0 m"):
        analytic.kapitsa_point_pressure(0.0, 0.0, -1e-7, A_CURV, B_CURV, ETA, U_M)


# ----------------------------------------------------------------------------- Martin
def test_martin_outlet_conditions():
    """p(x_c) = 0 and dp/dx(x_c) = 0, with x_c = sqrt(2 R h0) tan g_c and h(x_c) = h*."""
    radius = RX
    x_c = float(analytic.martin_outlet_position(H0, radius))
    length = np.sqrt(2 * radius * H0)
    p0 = ETA * U_M * length / H0**2
    assert_allclose(H0 + x_c**2 / (2 * radius), analytic.martin_hstar(H0), rtol=1e-13,
                    err_msg="h(x_c) = h* = h0 sec^2 g_c, round-off")
    step = 1e-5 * length
    p_left = analytic.martin_pressure(x_c - np.array([0.0, step, 2 * step]), H0, radius,
                                      ETA, U_M)
    assert abs(p_left[0]) < 1e-12 * p0, "p(x_c) = 0"
    slope = (3 * p_left[0] - 4 * p_left[1] + p_left[2]) / (2 * step)  # one-sided, O(step^2)
    assert abs(slope) < 1e-8 * p0 / length, "dp/dx(x_c) = 0: p ~ (x - x_c)^2 at the outlet"
    assert np.all(analytic.martin_pressure(x_c * np.array([1.0001, 2, 10]), H0, radius,
                                           ETA, U_M) == 0)


@pytest.mark.parametrize("fraction", [0.0, 0.95])
def test_martin_solves_integrated_reynolds(fraction):
    """exp(-alpha p) dp/dx = 12 eta0 u_m (h - h*)/h^3 on the inlet side x < x_c."""
    radius = RX
    alpha = fraction / float(analytic.martin_max_reduced(H0, radius, ETA, U_M))
    length = np.sqrt(2 * radius * H0)
    x_c = float(analytic.martin_outlet_position(H0, radius))
    h_star = float(analytic.martin_hstar(H0))
    rng = np.random.default_rng(RNG_SEED)
    x = rng.uniform(-30 * length, 0.9 * x_c, 40)
    step = 1e-4 * length
    p_plus = analytic.martin_pressure(x + step, H0, radius, ETA, U_M, alpha)
    p_minus = analytic.martin_pressure(x - step, H0, radius, ETA, U_M, alpha)
    p_mid = analytic.martin_pressure(x, H0, radius, ETA, U_M, alpha)
    lhs = np.exp(-alpha * p_mid) * (p_plus - p_minus) / (2 * step)
    h = H0 + x**2 / (2 * radius)
    rhs = 12 * ETA * U_M * (h - h_star) / h**3
    scale = 12 * ETA * U_M / H0**2
    assert_allclose(lhs, rhs, rtol=0, atol=1e-6 * scale,
                    err_msg="central difference with step 1e-4 L: O(1e-8) truncation")


def test_martin_load_by_quadrature_and_peak():
    radius = RX
    x_c = float(analytic.martin_outlet_position(H0, radius))
    length = np.sqrt(2 * radius * H0)
    def p_fun(s):
        return analytic.martin_pressure(s, H0, radius, ETA, U_M)

    far, _ = quad(p_fun, -np.inf, -10 * length, epsabs=0, epsrel=1e-11)
    near, _ = quad(p_fun, -10 * length, x_c, epsabs=0, epsrel=1e-11, limit=200)
    load = far + near
    assert_allclose(load, analytic.martin_load(H0, radius, ETA, U_M), rtol=1e-9,
                    err_msg="quadrature of the closed-form pressure, 1e-11 asked")
    xs = np.linspace(-3 * length, x_c, 20001)
    p = analytic.martin_pressure(xs, H0, radius, ETA, U_M)
    assert_allclose(np.max(p), analytic.martin_max_reduced(H0, radius, ETA, U_M), rtol=1e-7,
                    err_msg="peak on a grid of spacing 1.6e-4 L, error quadratic in spacing")
    assert_allclose(xs[np.argmax(p)], -x_c, atol=2 * (xs[1] - xs[0]),
                    err_msg="peak where h = h* on the inlet side, within two grid steps")


def test_martin_outlet_angle_is_a_root():
    gc = analytic.martin_outlet_angle()
    assert 0 < gc < np.pi / 2
    # p just before the outlet is positive and ~ quadratic: check the sign pattern
    radius = RX
    x_c = float(analytic.martin_outlet_position(H0, radius))
    assert analytic.martin_pressure(0.99 * x_c, H0, radius, ETA, U_M) > 0
    assert_allclose(np.tan(gc), x_c / np.sqrt(2 * radius * H0), rtol=1e-14,
                    err_msg="definition of the outlet position")


# ----------------------------------------------------------------------------- Hertz
def test_hertz_line_gap_against_plane_strain_quadrature():
    """x^2/(2R) + v(x), v = -(4/(pi E')) int p ln|x - s| ds, is flat inside and equals
    hertz_line_gap_outside outside (docs/theory.md sections 11 and 14.3)."""
    w, radius, e_prime = 2e5, RX, 2.2e11
    b, p_h = units.hertz_line(w, radius, e_prime)

    def gap(x):
        def integrand(t):  # s = b sin(t): p(s) ds = p_h cos(t)^2 b dt
            return p_h * np.cos(t) ** 2 * b * np.log(abs(x - b * np.sin(t)))

        pts = [np.arcsin(x / b)] if abs(x) < b else None
        val, _ = quad(integrand, -np.pi / 2, np.pi / 2, points=pts, epsabs=0, epsrel=1e-12,
                      limit=200)
        return x**2 / (2 * radius) - 4 / (np.pi * e_prime) * val

    g0 = gap(0.0)
    xs = b * np.array([-0.9, -0.3, 0.5, 1.0, 1.2, -1.7, 3.0, 6.0])
    numeric = np.array([gap(x) for x in xs]) - g0
    scale = b**2 / (2 * radius)
    assert_allclose(numeric, analytic.hertz_line_gap_outside(xs, b, radius), rtol=0,
                    atol=1e-9 * scale,
                    err_msg="adaptive quadrature with the log singularity split, 1e-12 asked")


def test_hertz_point_pressure_integrates_to_load():
    force, radius, e_prime = 40.0, RX, 2.2e11
    hp = units.hertz_point(force, radius, radius, e_prime)
    load, _ = quad(lambda r: 2 * np.pi * r * analytic.hertz_point_pressure(r, 0.0, hp.a_x,
                                                                           hp.p_h),
                   0, hp.a_x, epsabs=0, epsrel=1e-12)
    assert_allclose(load, force, rtol=1e-9, err_msg="radial quadrature, 1e-12 asked")


def test_hertz_point_displacement_forms():
    force, radius, e_prime = 40.0, RX, 2.2e11
    hp = units.hertz_point(force, radius, radius, e_prime)
    a = hp.a_x
    v = analytic.hertz_point_displacement
    assert_allclose(v(0.0, a, hp.p_h, e_prime), hp.delta, rtol=1e-13,
                    err_msg="v(0) = delta = a^2/R, round-off")
    assert_allclose(v(a * (1 - 1e-12), a, hp.p_h, e_prime), v(a * (1 + 1e-12), a, hp.p_h,
                                                               e_prime),
                    rtol=1e-9, err_msg="continuous at r = a (sqrt(r - a) term: ~1e-6 a "
                                       "shift gives 1e-9)")
    r_in = np.linspace(0, a, 7)
    assert_allclose(v(r_in, a, hp.p_h, e_prime), hp.delta - r_in**2 / (2 * radius),
                    rtol=1e-13, err_msg="inside: Hertz flattens the gap exactly")
    # Boussinesq quadrature, inside and outside
    for r in (0.0, 0.4 * a, 0.95 * a, 1.3 * a, 3.0 * a):
        numeric = _boussinesq_ellipse(r, 0.0, a, a, hp.p_h, e_prime)
        assert_allclose(v(r, a, hp.p_h, e_prime), numeric, rtol=1e-8,
                        err_msg=f"r = {r / a:.2f} a: angular quad, 1e-10 asked")


@pytest.mark.parametrize("ratio", [2.0, 8.0])
def test_elliptic_hertz_flattens_the_gap(ratio):
    """Exact elliptic Hertz (units.hertz_point): Boussinesq displacement of its pressure
    makes delta - v = x^2/(2 rx) + y^2/(2 ry) inside the contact ellipse."""
    force, e_prime = 60.0, 2.2e11
    rx, ry = RX, RX * ratio
    hp = units.hertz_point(force, rx, ry, e_prime)
    for fx, fy in ((0.0, 0.0), (0.5, 0.0), (0.0, 0.7), (-0.4, 0.5)):
        x0, y0 = fx * hp.a_x, fy * hp.a_y
        v = _boussinesq_ellipse(x0, y0, hp.a_x, hp.a_y, hp.p_h, e_prime)
        assert_allclose(hp.delta - v, x0**2 / (2 * rx) + y0**2 / (2 * ry),
                        rtol=0, atol=1e-8 * hp.delta,
                        err_msg="angular quadrature (1e-11 asked) of the exact radial "
                                "integral; elliptic-integral solve to 1e-14")


# --- Roelands reduced pressure (the rigid Roelands linear path) -----------------------
ROELANDS_OILS = [(0.01, 2e-8), (0.1, 1.5e-8), (1e-3, 3e-8), (2.0, 1e-8), (1e-4, 5e-9)]
#: nearly isoviscous laws (pressure index Z = 0.039 and 0.0106: the lower incomplete
#: gamma form, orders 1/Z = 26 and 94)
ROELANDS_SMALL_INDEX = [(0.01, 1e-9), (1e-3, 1.5e-10)]


@pytest.mark.parametrize("eta0,alpha", ROELANDS_OILS + ROELANDS_SMALL_INDEX)
def test_roelands_reduced_pressure_is_the_integral_of_eta0_over_eta(eta0, alpha):
    from scipy.integrate import quad

    from bearing_fem.analytic import reduced_from_roelands, roelands_reduced_limit
    from bearing_fem.physics.rheology import roelands

    def integrand(s):
        with np.errstate(over="ignore"):  # eta = inf beyond ~1e10 Pa: eta0/eta = 0
            return eta0 / float(roelands(s, eta0, alpha))

    ps = np.array([1e3, 1e6, 1e8, 5e8, 1e9])
    q = reduced_from_roelands(ps, eta0, alpha)
    ref = [quad(integrand, 0.0, p, limit=400, epsabs=0.0, epsrel=1e-12)[0] for p in ps]
    np.testing.assert_allclose(q, ref, rtol=2e-8,
                               err_msg="closed form (incomplete gamma) against quadrature")
    if (eta0, alpha) in ROELANDS_SMALL_INDEX:
        return  # q_inf is astronomically large (1e18 Pa and more)
    # the limit: the integrand has fallen below 1e-30 of eta0/eta0 well before 1e11 Pa
    far = quad(integrand, 0.0, 1e9, limit=400, epsrel=1e-12)[0] + quad(
        integrand, 1e9, 1e11, limit=400, epsrel=1e-12)[0]
    np.testing.assert_allclose(roelands_reduced_limit(eta0, alpha), far, rtol=1e-8,
                               err_msg="q_inf against the quadrature to 1e11 Pa")


@pytest.mark.parametrize("eta0,alpha", ROELANDS_OILS + ROELANDS_SMALL_INDEX)
def test_roelands_reduced_pressure_round_trip(eta0, alpha):
    from bearing_fem.analytic import (reduced_from_roelands, roelands_from_reduced,
                                      roelands_reduced_limit)
    from bearing_fem.physics.rheology import roelands

    ps = np.array([0.0, 1.0, 1e4, 1e6, 1e7, 1e8, 3e8])
    back = roelands_from_reduced(reduced_from_roelands(ps, eta0, alpha), eta0, alpha)
    # p is ill-conditioned in q where eta/eta0 is large (dp = eta/eta0 dq): the
    # round-trip error grows as (eta/eta0) times the rounding of q
    tol = 1e-12 * np.maximum(roelands(ps, eta0, alpha) / eta0, 1.0) * 1e4
    assert np.all(np.abs(back - ps) <= tol * np.maximum(ps, 1e3)), (back, ps)
    lim = roelands_reduced_limit(eta0, alpha)
    assert np.all(np.isinf(roelands_from_reduced([lim, 2 * lim], eta0, alpha)))
    assert np.isfinite(roelands_from_reduced(0.999 * lim, eta0, alpha))


def test_roelands_reduced_limit_is_near_one_over_alpha_for_a_mineral_oil():
    """Same low-pressure slope as Barus (Z = alpha p0 / A): q_inf lies near 1/alpha; the
    docs quote 5.26e7 Pa against 5e7 Pa at eta0 = 0.01 Pa s, alpha = 2e-8 1/Pa."""
    from bearing_fem.analytic import roelands_reduced_limit

    q_inf = roelands_reduced_limit(0.01, 2e-8)
    assert f"{q_inf:.3g}" == "5.26e+07", q_inf
    with pytest.raises(ValueError, match="6.3e-5 Pa s"):
        roelands_reduced_limit(5e-5, 2e-8)
    with pytest.raises(ValueError, match="Z = 2.94e-05"):
        roelands_reduced_limit(0.05, 1e-12)


@pytest.mark.parametrize("eta0,alpha", ROELANDS_OILS + ROELANDS_SMALL_INDEX)
def test_roelands_reduced_pressure_of_a_negative_pressure(eta0, alpha):
    """An end pressure below ambient (down to -p0, where the law's base 1 + p/p0 is 0)
    has a negative reduced pressure, and back."""
    from scipy.integrate import quad

    from bearing_fem.analytic import reduced_from_roelands, roelands_from_reduced
    from bearing_fem.physics.rheology import roelands

    ps = np.array([-1e8, -1e6, -1e4, -1e3])
    q = reduced_from_roelands(ps, eta0, alpha)
    ref = [-quad(lambda s: eta0 / float(roelands(s, eta0, alpha)), p, 0.0, limit=400,
                 epsabs=0.0, epsrel=1e-12)[0] for p in ps]
    np.testing.assert_allclose(q, ref, rtol=2e-8,
                               err_msg="closed form against quadrature below ambient")
    # dp = eta/eta0 dq with eta <= eta0 below ambient: p as well conditioned as q
    np.testing.assert_allclose(roelands_from_reduced(q, eta0, alpha), ps, rtol=1e-9,
                               err_msg="round trip of negative pressures")
    floor = float(reduced_from_roelands(-1.96e8, eta0, alpha))
    np.testing.assert_allclose(roelands_from_reduced(floor, eta0, alpha), -1.96e8,
                               rtol=1e-9, err_msg="q(-p0) is the pressure -p0")
    with pytest.raises(ValueError, match="got -2e\\+08 Pa"):
        reduced_from_roelands(-2e8, eta0, alpha)
    with pytest.raises(ValueError, match="q must be >= q\\(-p0\\)"):
        roelands_from_reduced(2.0 * floor, eta0, alpha)


def test_roelands_reduced_pressure_where_its_constant_overflows():
    """ln eta0 + 9.67 = 0.0289 and Z = 0.0101 put C = (p0/Z) e^A A^(-1/Z) Gamma(1/Z) at
    e^800, beyond the double range, while q(p) is a pressure: it came out inf."""
    from scipy.integrate import quad

    from bearing_fem.analytic import reduced_from_roelands, roelands_from_reduced
    from bearing_fem.physics.rheology import roelands

    eta0 = 6.5e-5
    alpha = 0.0101 * (np.log(eta0) + 9.67) / 1.96e8
    ps = np.array([-1e5, 1e3, 1e6, 1e8])
    q = reduced_from_roelands(ps, eta0, alpha)
    ref = [np.sign(p) * quad(lambda s: eta0 / float(roelands(s, eta0, alpha)),
                             min(p, 0.0), max(p, 0.0), epsabs=0.0, epsrel=1e-12)[0]
           for p in ps]
    # rtol: the cancellation of the two incomplete gamma values, about 1e-8 at 1e3 Pa
    np.testing.assert_allclose(q, ref, rtol=1e-7, err_msg="closed form against quadrature")
    np.testing.assert_allclose(roelands_from_reduced(q, eta0, alpha), ps, rtol=1e-7,
                               err_msg="round trip (eta/eta0 = O(1) here)")


def test_kapitsa_exterior_load_matches_its_closed_form_strip_and_a_direct_sum():
    """The load of Kapitsa's inlet film beyond a rectangle: with the rectangle as tall as
    the plane only the strip x < x0 is left, -A pi/(2 a sqrt(b)) (h0 + a x0^2)^(-1/2) in
    closed form; on the default rigid domain of a ball the side strips are summed
    directly on a fine tensor grid (midpoints) as a second check."""
    import math

    from bearing_fem import analytic as an

    h0, a, b, eta, u = 1e-6, 50.0, 12.5, 0.01, 1.0
    lx, ly = math.sqrt(2 * h0 / (2 * a)), math.sqrt(2 * h0 / (2 * b))
    x0, x1 = -30 * lx, 8 * lx
    big_a, _ = an.kapitsa_point_coefficients(eta, u, a, b)
    strip = -big_a * math.pi / (2 * a * math.sqrt(b)) / math.sqrt(h0 + a * x0**2)
    tall = an.kapitsa_point_exterior_load((x0, x1), (-1e9 * ly, 1e9 * ly), h0, a, b, eta, u)
    np.testing.assert_allclose(tall, strip, rtol=1e-10,
                               err_msg="the strip x < x0 against its closed form")
    box = an.kapitsa_point_exterior_load((x0, x1), (-30 * ly, 30 * ly), h0, a, b, eta, u)
    # side strips x0 <= x <= 0, |y| >= 30 ly, by midpoints out to |y| = 3e4 ly (the rest
    # of the tail, ~ 1/y^3 integrated, is below 1e-9 of it)
    xs = x0 * (np.arange(1000) + 0.5) / 1000
    t = np.linspace(math.log(30 * ly), math.log(3e4 * ly), 4001)
    tm = 0.5 * (t[1:] + t[:-1])
    ys = np.exp(tm)
    q = np.maximum(big_a * xs[:, None] / (h0 + a * xs[:, None]**2 + b * ys[None, :]**2)**2,
                   0.0)
    sides = 2.0 * float(np.sum(q * (ys * np.diff(t))[None, :]) * abs(x0) / 1000)
    np.testing.assert_allclose(box, strip + sides, rtol=1e-5,
                               err_msg="the side strips against a direct midpoint sum")
    barus = an.kapitsa_point_exterior_load((x0, x1), (-30 * ly, 30 * ly), h0, a, b, eta, u,
                                           from_reduced=lambda v: an.barus_from_reduced(
                                               v, 2e-8))
    assert barus > box, "p(q) >= q for Barus"
    with pytest.raises(ValueError, match="contain the origin"):
        an.kapitsa_point_exterior_load((lx, x1), (-ly, ly), h0, a, b, eta, u)
    with pytest.raises(ValueError, match="b must be > 0"):
        an.kapitsa_point_exterior_load((x0, x1), (-ly, ly), h0, a, 0.0, eta, u)

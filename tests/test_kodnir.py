"""Tests of bearing_fem.contacts.kodnir: the dimensionless Kodnir problem (4)-(6) by FE.

Oracles are computed here from closed forms (Martin, Kapitsa/Barus transform), never
hard-coded. Grids are small so the whole file runs in well under a minute.
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy.integrate import quad

import bearing_fem as bf
from bearing_fem import analytic as A
from bearing_fem.contacts import kodnir as K

NODES, COARSE = 1201, 201


def _martin_k(z: np.ndarray) -> np.ndarray:
    """Martin's rigid isoviscous solution in Kodnir variables.

    Martin (docs/theory.md section 14.2): x along the motion, X = x/sqrt(2 R h0) = tan g, h* = h0/cos^2 g_c.
    Kodnir: z = -x/B1 with B1 = sqrt(2 R h*), so tan g = -z/cos g_c; k = p/B with
    B = 12 eta0 u_m B1/h*^2 and P0 = eta0 u_m sqrt(2 R h0)/h0^2, hence
    k = (p/P0) / (12 cos^3 g_c); zero downstream of the outlet z_a = -sin g_c.
    """
    gc = A.martin_outlet_angle()
    g = np.arctan(-np.asarray(z) / math.cos(gc))
    k = A._martin_shape(g, 1.0 / math.cos(gc) ** 2) / (12.0 * math.cos(gc) ** 3)
    return np.where(np.asarray(z) > -math.sin(gc), k, 0.0)


@pytest.fixture(scope="module")
def martin():
    # z_b = 60: the oracle has its inlet at infinity (k(20) ~1e-4 k_max); much larger z_b
    # puts the flux row below rounding (H(z_b)^3 ~ z_b^6 multiplies dk/dz)
    return K.solve(0.0, 0.0, z_b=20.0, nodes=NODES, coarse_nodes=COARSE)


@pytest.fixture(scope="module")
def elastic():
    return K.solve(1.0, 4.5, nodes=NODES, coarse_nodes=COARSE)


def test_lazy_import():
    assert bf.kodnir.solve is K.solve


def test_martin_limit(martin):
    r = martin
    assert r.success, r.message
    za = -math.sin(A.martin_outlet_angle())
    np.testing.assert_allclose(r.z_a, za, rtol=2e-3,
                               err_msg="outlet z_a = -sin(g_c) (H(0) = cos^2 g_c), P1 grid "
                                       "spacing ~3e-3 near the outlet")
    np.testing.assert_allclose(r.z_a_free_boundary, za, rtol=5e-3,
                               err_msg="free boundary (sqrt(k) extrapolation) at Martin's outlet")
    np.testing.assert_allclose(r.h_offset, math.cos(A.martin_outlet_angle()) ** 2, rtol=2e-3,
                               err_msg="H_off = H(z=0) = h0/h* = cos^2 g_c")
    kex = _martin_k(r.z)
    np.testing.assert_allclose(r.k_max, kex.max(), rtol=2e-3,
                               err_msg="k_max of Martin's profile, discretisation error")
    assert np.max(np.abs(r.k - kex)) < 3e-3 * kex.max(), "profile within 0.3 % of k_max"
    np.testing.assert_allclose(r.h_min, r.h_offset, rtol=1e-6,
                               err_msg="rigid film: minimum at z = 0 equals H_off")


def test_barus_limit_kapitsa_transform(martin):
    """C = 0, b_alpha > 0: k = -ln(1 - b_alpha q)/b_alpha with q the isoviscous solution,
    same outlet (docs/theory.md sections 14.1/14.2)."""
    qmax = _martin_k(np.linspace(-0.5, 2.0, 20001)).max()
    b_alpha = 0.6 / qmax   # b_alpha q_max = 0.6 < 1: a solution exists
    r = K.solve(0.0, b_alpha, z_b=20.0, nodes=NODES, coarse_nodes=COARSE)
    assert r.success, r.message
    np.testing.assert_allclose(r.z_a, -math.sin(A.martin_outlet_angle()), rtol=2e-3,
                               err_msg="the transform keeps the outlet of the isoviscous solution")
    kex = A.barus_from_reduced(_martin_k(r.z), b_alpha)
    np.testing.assert_allclose(r.k_max, kex.max(), rtol=4e-3,
                               err_msg="transformed k_max; the transform amplifies the "
                                       "isoviscous error by 1/(1 - b_alpha q) = 2.5")
    # beyond existence: an explicit status, no NaN fields
    bad = K.solve(0.0, 1.2 / qmax, z_b=20.0, nodes=NODES, coarse_nodes=COARSE)
    assert not bad.success and bad.status == "no_solution", bad.message
    assert "b_alpha" in bad.message


def test_ode_satisfied_at_nodes(elastic):
    """The paper's eq (4) in flux form, H^3 exp(-b_alpha k) dk/dz = 1 - H, at the nodes of
    the pressurised zone (nodal dk/dz: average of the two element slopes)."""
    r = elastic
    assert r.success, r.message
    z, k, H = r.z, r.k, r.H
    slope = np.diff(k) / np.diff(z)
    kp = 0.5 * (slope[:-1] + slope[1:])
    inner = np.arange(1, z.size - 1)
    sel = inner[(z[inner] > r.z_a + 0.05) & (z[inner] < 5.0)]
    lhs = H[sel] ** 3 * np.exp(-r.b_alpha * k[sel]) * kp[sel - 1]
    rhs = 1.0 - H[sel]
    dz = np.max(np.diff(z[sel]))
    err = np.max(np.abs(lhs - rhs))
    assert err < 20 * dz**2 + 1e-6 and err < 2e-3, (
        f"flux form of eq 4 violated by {err:.2e} (dz = {dz:.2e}); expected O(dz^2)")
    # and in the paper's own form, where (1 - H) is not tiny
    zone = sel[np.abs(1.0 - H[sel]) > 0.05]
    paper = (1.0 - H[zone]) / H[zone] ** 3 * np.exp(r.b_alpha * k[zone])
    np.testing.assert_allclose(kp[zone - 1], paper, rtol=1e-2, atol=1e-3 * np.max(np.abs(paper)),
                               err_msg="dk/dz = (1 - H)/H^3 exp(B alpha k) at the nodes, "
                                       "central-difference accuracy")
    np.testing.assert_allclose(r.flux, 1.0, atol=1e-9, err_msg="the flux condition Q = 1")


def test_outlet_conditions(elastic):
    r = elastic
    # H(z_a) = 1 by construction; k drops to 0 at z_a to grid accuracy
    dz = np.min(np.diff(r.z))
    assert abs(r.z_a - r.z_a_free_boundary) < 2 * dz, "two outlet estimates agree"
    assert np.all(r.k[r.z < r.z_a - 2 * dz] == 0.0) or np.max(r.k[r.z < r.z_a - 2 * dz]) < 1e-12
    assert r.h_min < 1.0 and r.k_max > 0.0


def test_integrals_independent_quadrature(elastic):
    """I and J against scipy.quad on the P1 interpolant over [z_a, z_b]."""
    r = elastic
    z, k = r.z, r.k

    def kk(s):
        return np.interp(s, z, k)

    def H(s):
        return r.h_offset + s * s + r.C * kk(s)

    def kp(s):
        i = min(max(int(np.searchsorted(z, s) - 1), 0), z.size - 2)
        return (k[i + 1] - k[i]) / (z[i + 1] - z[i])

    pts = z[z > r.z_a][:-1]
    I = sum(quad(lambda s: (1 - H(s)) * kp(s), a, b)[0]
            for a, b in zip(np.r_[r.z_a, pts], np.r_[pts, r.z_b]))
    J = sum(quad(lambda s: math.exp(r.b_alpha * kk(s)) / H(s), a, b)[0]
            for a, b in zip(np.r_[r.z_a, pts], np.r_[pts, r.z_b]))
    np.testing.assert_allclose(r.friction_integral, I, rtol=1e-7,
                               err_msg="same interpolant, two quadratures: rounding only")
    np.testing.assert_allclose(r.couette_integral, J, rtol=1e-7,
                               err_msg="same interpolant, two quadratures: rounding only")


def test_friction_heat_consistency(elastic):
    r = elastic
    out = K.kodnir_friction_heat(r, h_star=1e-6, B=1e8, q_H=1e6, sum_speed=10.0,
                                 sliding_speed=1.0)
    np.testing.assert_allclose(out.rolling_force, 0.5 * 1e8 * 1e-6 * r.friction_integral,
                               rtol=1e-14, err_msg="w_k = (B h*/2) I (Yachikov & Vostrikov 2015, eq 8)")
    np.testing.assert_allclose(out.friction_coefficient, 2 * out.rolling_force / 1e6,
                               rtol=1e-14, err_msg="f = 2 w_k/q_H (Yachikov & Vostrikov 2015, eq 7)")
    np.testing.assert_allclose(out.heat_power, 10.0 * (out.rolling_force + 0.01 * 1e8 * 1e-6
                                                       / 6 * r.couette_integral),
                               rtol=1e-14, err_msg="Yachikov & Vostrikov (2015) eq 9")
    # Poiseuille energy identity in Kodnir variables: int eps k'^2 = int (1 - H) k' = I
    z, k, H = r.z, r.k, r.H
    zm = 0.5 * (z[1:] + z[:-1])
    km = 0.5 * (k[1:] + k[:-1])
    Hm = 0.5 * (H[1:] + H[:-1])
    s = np.diff(k) / np.diff(z)
    diss = np.sum(Hm**3 * np.exp(-r.b_alpha * km) * s**2 * np.diff(z) * (zm > r.z_a))
    np.testing.assert_allclose(diss, r.friction_integral, rtol=2e-2,
                               err_msg="Poiseuille heat = U_sum w_k (docs/theory.md section 15), midpoint rule")


def test_scales_roundtrip():
    s = K.kodnir_scales(h_star=1e-6, radius=0.02, viscosity=0.1, sum_speed=10.0,
                        youngs_modulus=2.1e11, load_per_length=1e6, piezo=2e-8)
    np.testing.assert_allclose(s.B1, math.sqrt(2e-6 * 0.02), rtol=1e-15, err_msg="B1")
    np.testing.assert_allclose(s.B, 6 * 0.1 * 10 * s.B1 / 1e-12, rtol=1e-15, err_msg="B")
    b_h = 1.52 * math.sqrt(1e6 * 0.02 / 2.1e11)
    np.testing.assert_allclose(s.C, 2.54 * b_h * s.B / (2.1e11 * 1e-6), rtol=1e-14,
                               err_msg="C = A' B/(E h*)")
    np.testing.assert_allclose(s.b_alpha, s.B * 2e-8, rtol=1e-15, err_msg="B alpha")


@pytest.mark.parametrize("kwargs, name", [
    ({"C": -1.0, "b_alpha": 1.0}, "C"),
    ({"C": 1.0, "b_alpha": -1.0}, "b_alpha"),
    ({"C": 1.0, "b_alpha": 1.0, "z_b": 0.0}, "z_b"),
    ({"C": 1.0, "b_alpha": 1.0, "z_b": -5.0}, "z_b"),
])
def test_bad_arguments(kwargs, name):
    with pytest.raises(ValueError, match=name):
        K.solve(**kwargs)


def test_graded_grid_bands_refine_with_nodes():
    """Layer bands keep their spacing ratio to the zone, so doubling the nodes halves
    every spacing (a proper refinement), and the node count and ends are exact."""
    bands, ratio = ((-6.3, -5.5), (5.5, 6.8)), 0.25
    spacing = {}
    for n in (1001, 2001, 4001):
        z = K.graded_grid(-7.36, 9.23, 20.0, n, bands=bands, band_ratio=ratio)
        d = np.diff(z)
        assert z.size == n and z[0] == -7.36 and z[-1] == 20.0 and np.all(d > 0)
        spacing[n] = (d[np.searchsorted(z, -6.0)], d[np.searchsorted(z, 6.0)],
                      d[np.searchsorted(z, 0.0)])
        np.testing.assert_allclose(spacing[n][:2], ratio * spacing[n][2], rtol=0.02,
                                   err_msg="band spacing = ratio x zone spacing, up to "
                                   "rounding the interval counts")
    np.testing.assert_allclose(np.array(spacing[4001]) / spacing[2001], 0.5, rtol=0.01,
                               err_msg="doubling the nodes halves the spacings")
    plain = K.graded_grid(-7.36, 9.23, 20.0, 2001)
    np.testing.assert_allclose(np.diff(plain[:1601]), (9.23 + 7.36) / 1600, rtol=1e-9,
                               err_msg="no bands: uniform zone")


@pytest.mark.parametrize("kwargs, match", [
    ({"h_star": math.inf}, r"h_star must be finite.*m"),
    ({"piezo": math.inf}, r"piezo must be finite.*1/Pa"),
    ({"piezo": -1e-8}, r"piezo must be >= 0 1/Pa"),
    ({"viscosity": math.nan}, r"viscosity must be finite.*Pa s"),
])
def test_scales_refuse_non_finite_numbers(kwargs, match):
    """inf for h* or alpha gave B1 = inf or B alpha = inf (then NaN downstream)."""
    args = dict(h_star=1e-6, radius=0.02, viscosity=0.1, sum_speed=10.0,
                youngs_modulus=2.1e11, load_per_length=1e6, piezo=2e-8)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        K.kodnir_scales(**args)


@pytest.mark.parametrize("kwargs, match", [
    ({"sliding_speed": math.nan}, r"sliding_speed must be finite.*m/s"),
    ({"sliding_speed": math.inf}, r"sliding_speed must be finite.*m/s"),
    ({"q_H": -1e6}, r"q_H must be > 0 N/m"),
    ({"B": 0.0}, r"B must be > 0 Pa"),
])
def test_friction_heat_refuses_bad_numbers_with_units(elastic, kwargs, match):
    """A NaN sliding speed gave heat_power = NaN, an infinite one inf; the other messages
    named no unit."""
    args = dict(h_star=1e-6, B=1e8, q_H=1e6, sum_speed=10.0, sliding_speed=1.0)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        K.kodnir_friction_heat(elastic, **args)


def test_stiff_compliance_continuation_iterations_capped():
    # C = 150: the outlet layer (~1/C) and the inlet critical point (z = 2C/27, H = 3/2)
    # move through the continuation grid; with layer bands that follow them and a
    # predictor that moves the free boundary this takes 1720 Newton iterations (8446 on
    # the fixed 401-node grid with the nodal secant)
    r = K.solve(150.0, 0.0)
    assert r.success, r.message
    assert r.iterations <= 3000, r.message
    np.testing.assert_allclose(r.flux, 1.0, atol=1e-8, err_msg="flux condition Q = 1")
    i = int(np.searchsorted(r.z, r.z_a))
    np.testing.assert_allclose(r.z_a_free_boundary, r.z_a, atol=2.0 * (r.z[i + 1] - r.z[i]),
                               err_msg="free boundary within two local cells of z_a")
    # inlet critical point: the pressure falls at most (H - 1)/H^3 <= 4/27 per unit z
    slope = np.diff(r.k) / np.diff(r.z)
    assert slope.min() >= -4.0 / 27.0 * (1.0 + 1e-3), slope.min()


def test_huge_compliance_message_names_continuation_stage():
    # C = 1e6 put the left end of the first grid at z = -1e5 (outlet guess -(2 + 0.1 C)),
    # and the rigid start failed there: the message named C = 0. The outlet lies right of
    # -sqrt(1 + z_b^2) (film at the inlet > 0), so the grid is capped and the message
    # names the C where the continuation stalls
    r = K.solve(1e6, 0.0, max_iterations=10)
    assert not r.success and r.status == "no_convergence"
    m = re.search(r"continuation stalled at C=([0-9.e+]+), b_alpha=0", r.message)
    assert m is not None, r.message
    assert float(m.group(1)) > 100.0, r.message
    assert r.z.size == r.k.size == r.H.size and np.all(np.isfinite(r.k))


@pytest.mark.slow
def test_stiff_compliance_march_in_b_alpha_on_base_grid():
    # the march in b_alpha stalled at b_alpha = 0.018 on the banded continuation grid
    # (C = 100); it runs on the base grid, as for C < 60, and converges
    r = K.solve(100.0, 4.5)
    assert r.success, r.message
    assert r.iterations <= 10000, r.message
    np.testing.assert_allclose(r.flux, 1.0, atol=1e-8, err_msg="flux condition Q = 1")

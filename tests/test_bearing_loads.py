"""Internal load distribution against Stribeck's and Harris' closed forms (analytic.py)."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from bearing_fem import analytic
from bearing_fem.bearing import Bearing, distribute_loads, load_example
from bearing_fem.bearing.geometry import groove_centre_distance, roller_compliance
from bearing_fem.bearing.kinematics import element_kinematics
from bearing_fem.bearing.loads import centrifugal_force, profile_drop, series_ball_stiffness


def _ball(z: int = 9, clearance: float = 0.0, psi0: float = 0.0, **op) -> Bearing:
    b = load_example("6209")
    dw = 0.0127 if z <= 16 else 0.9 * math.pi * 0.065 / z
    g = replace(b.geometry, elements=z, radial_clearance=clearance, element_diameter=dw,
                first_element_azimuth=psi0)
    return replace(b, geometry=g, operation=replace(b.operation, **op))


def _roller(z: int = 28, clearance: float = 0.0, **geo) -> Bearing:
    b = load_example("nncf5040")
    return replace(b, geometry=replace(b.geometry, elements=z, radial_clearance=clearance,
                                       **geo))


def test_stribeck_ball_and_roller():
    """Zero clearance, element at psi = 0: Z Q_max / F_r -> 4.37 (balls), 4.08 (rollers)."""
    k_ball, k_line = analytic.stribeck_constant(1.5), analytic.stribeck_constant(10 / 9)
    assert k_ball == pytest.approx(4.37, abs=5e-3) and k_line == pytest.approx(4.08, abs=5e-3)
    for z in (9, 40):
        d = distribute_loads(_ball(z))
        np.testing.assert_allclose(d.max_load * z / 4000.0, k_ball, rtol=1e-2,
                                   err_msg=f"Z = {z} balls, one at psi = 0: within 1% of the "
                                           "continuous Stribeck value (the acceptance)")
    d40 = distribute_loads(_ball(40))
    np.testing.assert_allclose(d40.max_load * 40 / 4000.0, k_ball, rtol=1e-4,
                               err_msg="the discrete sum tends to the integral as Z grows")
    b = _roller(28)
    d = distribute_loads(b)
    z_total = b.geometry.elements * b.geometry.rows
    np.testing.assert_allclose(d.max_load * z_total / b.operation.radial_load, k_line,
                               rtol=1e-2, err_msg="28 rollers per row, two rows: 4.08 within 1%")
    # an element BETWEEN the load line: the maximum is lower (Z = 9: about 9% lower)
    d_half = distribute_loads(_ball(9, psi0=20.0))
    assert d_half.max_load * 9 / 4000.0 < 0.95 * k_ball, \
        "with no element at psi = 0 the largest load is well below Stribeck's value"


@pytest.mark.parametrize("bearing", [
    _ball(9, 7.5e-6), _ball(9, 0.0, axial_load=1500.0), _ball(9, 7.5e-6, radial_load=0.0,
                                                             axial_load=2000.0),
    load_example("7010-steel"), load_example("7010-hybrid"), _roller(28, 40e-6),
])
def test_loads_balance_applied_load(bearing):
    d = distribute_loads(bearing)
    op = bearing.operation
    for got, want, what in ((d.radial_sum, op.radial_load, "radial"),
                            (d.axial_sum, op.axial_load, "axial")):
        if want > 0:
            np.testing.assert_allclose(got, want, rtol=1e-9,
                                       err_msg=f"{what} sum of element loads = applied load "
                                               "(Brent to 1e-12; acceptance is 0.1%)")
        else:
            assert abs(got) <= 1e-9 * max(op.radial_load, op.axial_load), f"no {what} load"


def test_load_zone_matches_harris_integral():
    """With clearance, psi_l of the discrete solution vs Harris' continuous J_r(epsilon)."""
    for z, cr in ((9, 7.5e-6), (9, 20e-6), (40, 7.5e-6), (40, 20e-6)):
        b = _ball(z, cr)
        d = distribute_loads(b)
        kn = float(series_ball_stiffness(b)[0](0.0))
        h = analytic.harris_load_zone(4000.0, z, kn, 1.5, cr)
        np.testing.assert_allclose(d.load_zone_half_angle, h["half_angle"], rtol=1e-2,
                                   err_msg=f"Z = {z}, c_r = {cr}: load-zone extent within 1% "
                                           "of the Harris integral (acceptance)")
        if z == 40:
            np.testing.assert_allclose(d.radial_displacement, h["radial_displacement"],
                                       rtol=1e-3, err_msg="many elements: the sum is the integral")
    b = _roller(28, 40e-6)
    d = distribute_loads(b)
    h = analytic.harris_load_zone(b.operation.radial_load / 2, 28, d.stiffness, 10 / 9, 40e-6)
    np.testing.assert_allclose(d.load_zone_half_angle, h["half_angle"], rtol=1e-2,
                               err_msg="roller bearing with clearance: within 1% of Harris")
    assert d.load_zone_half_angle < math.pi / 2, "clearance shrinks the load zone below 90 deg"


def test_pure_axial_load_contact_angle():
    """Deep-groove ball bearing under axial load only: every ball equal, at the angle of
    Harris' relation delta = A (cos alpha0/cos alpha - 1), Q = Fa/(Z sin alpha)."""
    b = _ball(9, 7.5e-6, radial_load=0.0, axial_load=2000.0)
    d = distribute_loads(b)
    assert np.ptp(d.load_inner) < 1e-9 * d.max_load, "axial load: equal loads"
    alpha = float(d.alpha_inner[0])
    a = groove_centre_distance(b)
    alpha0 = math.acos(1.0 - 7.5e-6 / a)
    assert alpha > alpha0, "the contact angle grows with load beyond the free angle"
    delta = a * (math.cos(alpha0) / math.cos(alpha) - 1.0)
    kn = float(series_ball_stiffness(b)[0](alpha))
    np.testing.assert_allclose(kn * delta**1.5, 2000.0 / (9 * math.sin(alpha)), rtol=1e-6,
                               err_msg="ball equilibrium along the contact line")


def test_angular_contact_angle_grows_with_axial_load():
    b = load_example("7010-steel")
    light = distribute_loads(replace(b, operation=replace(b.operation, axial_load=500.0)))
    heavy = distribute_loads(b)
    loaded = light.in_load_zone
    assert loaded.all() and heavy.in_load_zone.all(), "Fa/Fr >= 1: all balls loaded"
    assert np.all(heavy.alpha_inner > light.alpha_inner) and \
        np.all(light.alpha_inner > math.radians(15.0)), \
        "contact angles rise above the nominal 15 deg with axial load"
    hybrid = distribute_loads(load_example("7010-hybrid"))
    assert np.all(hybrid.alpha_inner < heavy.alpha_inner), \
        "stiffer Si3N4 balls deflect less: smaller contact-angle change"


def test_centrifugal_force_loads_outer_contacts():
    b = _roller(28, 40e-6)
    b = replace(b, operation=replace(b.operation, inner_rpm=3000.0),
                model=replace(b.model, centrifugal=True))
    d = distribute_loads(b)
    assert d.centrifugal_force > 0
    np.testing.assert_allclose(d.load_outer - d.load_inner, d.centrifugal_force, rtol=1e-9,
                               err_msg="roller: Q_o = Q_i + F_c")
    np.testing.assert_allclose(d.radial_sum, b.operation.radial_load / 1, rtol=1e-9,
                               err_msg="inner contacts still balance F_r")
    bb = replace(_ball(9, 7.5e-6, axial_load=1000.0, inner_rpm=20000.0),
                 model=replace(load_example("6209").model, centrifugal=True))
    db = distribute_loads(bb)
    assert np.all(db.alpha_outer < db.alpha_inner), \
        "centrifugal force turns the outer contact angle below the inner one (Jones)"
    fc = db.centrifugal_force
    for j in range(9):
        qi, qo = db.load_inner[j], db.load_outer[j]
        ai, ao = db.alpha_inner[j], db.alpha_outer[j]
        np.testing.assert_allclose(qi * math.sin(ai), qo * math.sin(ao), rtol=1e-6,
                                   atol=1e-8 * fc, err_msg="ball axial equilibrium")
        np.testing.assert_allclose(qi * math.cos(ai) + fc, qo * math.cos(ao), rtol=1e-6,
                                   err_msg="ball radial equilibrium with F_c")
    np.testing.assert_allclose([db.radial_sum, db.axial_sum], [4000.0, 1000.0], rtol=1e-9,
                               err_msg="ring equilibrium")


def test_tapered_centrifugal_force_is_reported_whole_and_loads_the_cup_normally():
    """load_distribution.centrifugal_force of a tapered bearing was the cup's normal
    component F_c cos(beta) (0.892 N for the 30205 at 3000 rpm) under the name of the
    element's centrifugal force F_c = m (d_m/2) omega_c^2 (0.919 N)."""
    b = load_example("30205")
    b = replace(b, model=replace(b.model, centrifugal=True))
    d = distribute_loads(b)
    fc = centrifugal_force(b)
    np.testing.assert_allclose(d.centrifugal_force, fc, rtol=1e-14,
                               err_msg="the element's whole centrifugal force")
    beta = math.radians(b.geometry.contact_angle)
    np.testing.assert_allclose(d.load_outer - d.load_inner, fc * math.cos(beta), rtol=1e-9,
                               err_msg="the cup carries its normal component")


def test_deep_groove_centrifugal_force_at_the_cage_speed_of_its_radially_loaded_balls():
    """docs/bearing.md 2.1: F_c at the cage speed of the nominal angle. A deep-groove
    bearing's F_c took the free contact angle of its clearance (9.9 deg for the 6209) and
    was 0.72 % above m (d_m/2) omega_c^2 of its balls, which run at 0 deg under a radial
    load (195.7 N instead of 194.3 N at 20000 rpm)."""
    b = load_example("6209")
    b = replace(b, model=replace(b.model, centrifugal=True),
                operation=replace(b.operation, inner_rpm=20000.0))
    d = distribute_loads(b)
    assert np.all(d.alpha_inner == 0.0) and np.all(d.alpha_outer == 0.0), "radial load"
    g = b.geometry
    kin = element_kinematics(b.operation.inner_speed, g.mean_diameter, g.element_diameter,
                             d.alpha_inner, d.alpha_outer)
    mass = b.materials.density * math.pi * g.element_diameter**3 / 6.0
    np.testing.assert_allclose(d.centrifugal_force,
                               mass * 0.5 * g.mean_diameter * kin.cage_speed**2, rtol=1e-12,
                               err_msg="the balls' own orbital speed")


@pytest.mark.parametrize("rpm, fa", [(30000.0, 50.0), (30000.0, 200.0), (20000.0, 5.0)])
def test_light_axial_load_at_high_speed_balances_with_centrifugal_force(rpm, fa):
    """A 7010 under a light axial load at high speed: the ball equilibrium's Newton
    stalled for a small inner load against a large F_c, the ball was taken for one without
    inner contact, and Brent settled on the jump: axial sums of 0 N for Fa = 50 N at
    30000 rpm and 5 N at 20000 rpm, 206.8 N for 200 N, without an error."""
    b = load_example("7010-steel")
    b = replace(b, model=replace(b.model, centrifugal=True),
                operation=replace(b.operation, inner_rpm=rpm, axial_load=fa, radial_load=0.0))
    d = distribute_loads(b)
    np.testing.assert_allclose(d.axial_sum, fa, rtol=1e-9, err_msg="axial balance")
    assert np.all(d.load_inner > 0.0), "every ball keeps its inner contact"
    np.testing.assert_allclose(d.load_outer * np.cos(d.alpha_outer),
                               d.load_inner * np.cos(d.alpha_inner) + d.centrifugal_force,
                               rtol=1e-7, err_msg="ball radial equilibrium with F_c")


def test_a_jump_of_the_element_loads_is_no_balance(monkeypatch):
    """Brent brackets the sign change of a jump as well as a root: the loads it returns
    are checked against the applied ones (RuntimeError, reported as
    load_distribution_failed), not passed on unbalanced."""
    from bearing_fem.bearing import loads as loads_module

    def jumpy(self, dr, za):  # the axial sum jumps from 0 to 10 kN at z_a = 0.1 mm
        return 0.0, (1e4 if za > 1e-4 else 0.0)

    monkeypatch.setattr(loads_module._BallModel, "sums", jumpy)
    b = load_example("7010-steel")
    b = replace(b, operation=replace(b.operation, radial_load=0.0))
    with pytest.raises(RuntimeError, match="axial force of .* instead of 2000 N"):
        distribute_loads(b)


def test_sliced_roller_profile():
    b = _roller(28, 0.0, profile="crowned", crown_drop=15e-6, slices=11)
    d = distribute_loads(b)
    np.testing.assert_allclose(d.slice_loads.sum(axis=1), d.load_inner, rtol=1e-12,
                               err_msg="slice loads add up to the element load")
    j = int(np.argmax(d.load_inner))
    assert d.slice_loads[j, 5] > d.slice_loads[j, 0], "the crown unloads the roller ends"
    np.testing.assert_allclose(d.radial_sum, b.operation.radial_load, rtol=1e-9,
                               err_msg="balance with slices")
    # straight roller cut into slices == Palmgren's law for the whole roller
    y = d.slice_positions
    assert profile_drop(_roller(28), y).max() == 0.0
    c = roller_compliance(b)
    q = 30e3
    delta = 2.0 * c * q**0.9
    c_l = c * b.geometry.effective_length ** 0.9
    per_length = (0.5 * delta / c_l) ** (1 / 0.9)
    np.testing.assert_allclose(per_length * b.geometry.effective_length, q, rtol=1e-12,
                               err_msg="slice law reduces to Palmgren for a straight roller")


# ---------------------------------------------------------------------------------------
# tapered rollers under a combined load (Sjovall's integrals)
# ---------------------------------------------------------------------------------------
def _tapered(z: int = 20, rows: int = 1, fr: float = 1e5, fa: float = 0.0,
             beta: float = 15.0, clearance: float = 0.0) -> Bearing:
    b = load_example("nncf5040")
    dm = b.geometry.mean_diameter
    g = replace(b.geometry, type="tapered-roller", contact_angle=beta, rows=rows, elements=z,
                radial_clearance=clearance, element_diameter=0.9 * math.pi * dm / z)
    return replace(b, geometry=g,
                   operation=replace(b.operation, radial_load=fr, axial_load=fa))


@pytest.mark.parametrize("eps", [0.3, 0.5, 1.0, 2.0])
def test_tapered_single_row_matches_sjovall_integrals(eps):
    """One zero-clearance row under F_a = F_r tan(beta) J_a(eps)/J_r(eps): the load-zone
    factor is eps, Z Q_max cos(beta) / F_r = 1/J_r(eps), psi_l = arccos(1 - 2 eps)."""
    n, beta, fr = 10.0 / 9.0, 15.0, 1e5
    fa = fr * math.tan(math.radians(beta)) * (analytic.harris_axial_integral(eps, n)
                                              / analytic.harris_radial_integral(eps, n))
    z = 200
    d = distribute_loads(_tapered(z=z, fr=fr, fa=fa, beta=beta))
    np.testing.assert_allclose([d.radial_sum, d.axial_sum], [fr, fa], rtol=1e-9,
                               err_msg="the ring displacement balances both loads")
    np.testing.assert_allclose(d.max_load * z * math.cos(math.radians(beta)) / fr,
                               1.0 / analytic.harris_radial_integral(eps, n), rtol=1e-3,
                               err_msg="200 rollers: the discrete sums within 0.1% of the "
                                       "continuous integrals (measured 5e-5)")
    expected = math.pi if eps >= 1.0 else math.acos(1.0 - 2.0 * eps)
    assert abs(d.load_zone_half_angle - expected) < math.radians(0.05), (
        math.degrees(d.load_zone_half_angle), math.degrees(expected))
    # epsilon = (1 + (delta_a/delta_r) tan(beta))/2 (Harris)
    ratio = d.axial_displacement / d.radial_displacement
    np.testing.assert_allclose(0.5 * (1.0 + ratio * math.tan(math.radians(beta))), eps,
                               rtol=2e-3, atol=1e-6, err_msg="load-zone factor of the "
                               "displacements (the continuous limit)")


def test_sjovall_ratio_of_half_loaded_rows():
    """J_a/J_r at eps = 1/2: 1.258 for line contacts, 1.216 for point contacts (Harris;
    the axial force a radial load induces in one row), to the digits the docstring of
    harris_axial_integral and docs/bearing.md 2.4 quote."""
    for n, value in ((10.0 / 9.0, 1.258), (1.5, 1.216)):
        r = analytic.harris_axial_integral(0.5, n) / analytic.harris_radial_integral(0.5, n)
        assert r == pytest.approx(value, abs=5e-4), (n, r)
        assert f"J_a(1/2)/J_r(1/2) = {1.258:.3f}" in analytic.harris_axial_integral.__doc__, \
            "the docstring quotes the line-contact ratio to three decimals"


def test_tapered_pairs_and_pure_axial_load():
    # opposed rows: the first row takes the axial load, both balance to rounding
    for fa in (1e3, 2e4, 1e5):
        d = distribute_loads(_tapered(rows=2, fa=fa))
        np.testing.assert_allclose([d.radial_sum, d.axial_sum], [1e5, fa], rtol=1e-9)
        q = d.load_inner.reshape(2, -1)
        assert q[0].max() > q[1].max(), "the row facing the axial load carries more"
    # a small axial load changes the pair's loads continuously from the radial-only model
    d0 = distribute_loads(_tapered(rows=2))
    d1 = distribute_loads(_tapered(rows=2, fa=1.0))
    np.testing.assert_allclose(d1.load_inner, d0.load_inner, rtol=0, atol=1e-3 * d0.max_load,
                               err_msg="F_a = 1 N against F_r = 100 kN")
    # axial load only: every roller of the row equal, Q = F_a / (Z sin(beta))
    d = distribute_loads(_tapered(fr=0.0, fa=5e4))
    np.testing.assert_allclose(d.load_inner, 5e4 / (20 * math.sin(math.radians(15.0))),
                               rtol=1e-9)
    assert d.load_zone_half_angle == pytest.approx(math.pi)


def test_tapered_single_row_axial_load_limits():
    from bearing_fem.bearing.description import single_row_min_axial_load
    from bearing_fem.errors import SceneError

    b = _tapered(fa=1e5)
    fa_min = single_row_min_axial_load(b.geometry, 1e5)
    np.testing.assert_allclose(fa_min, 1e5 * math.tan(math.radians(15.0)), rtol=1e-12,
                               err_msg="a roller on the load line: F_r tan(beta)")
    with pytest.raises(SceneError, match=r"operation\.axial_load = 25000 N is too small.*"
                                         r"needs more than 2\.679e\+04 N.*psi_j = 0 deg.*"
                                         r"1\.26 F_r"):
        _tapered(fa=2.5e4)
    # rollers at +-9 deg of the load line (20 rollers, element 0 at 9 deg): the limit is
    # F_r tan(beta)/cos(9 deg), and the message names that azimuth
    shifted = _tapered(fa=1e5)
    with pytest.raises(SceneError, match=r"needs more than 2\.713e\+04 N = "
                                         r"F_r tan\(beta\)/cos\(psi_j\), psi_j = 9 deg"):
        replace(shifted, geometry=replace(shifted.geometry, first_element_azimuth=9.0),
                operation=replace(shifted.operation, axial_load=2.7e4))
    d = distribute_loads(_tapered(fa=1.02 * fa_min))
    np.testing.assert_allclose([d.radial_sum, d.axial_sum], [1e5, 1.02 * fa_min], rtol=1e-9,
                               err_msg="just above the limit the row still balances")
    assert d.load_zone_half_angle < math.radians(30.0), "a narrow load zone near the limit"


def test_30205_example_has_a_full_load_zone():
    """The shipped single-row tapered example: F_a/F_r = 0.5 lies above
    tan(beta) J_a(1)/J_r(1) (= 0.47 at 13.9 deg), so every roller is loaded."""
    b = load_example("30205")
    n = 10.0 / 9.0
    full = math.tan(math.radians(b.geometry.contact_angle)) * (
        analytic.harris_axial_integral(1.0, n) / analytic.harris_radial_integral(1.0, n))
    assert b.operation.axial_load / b.operation.radial_load > full
    d = distribute_loads(b)
    assert d.in_load_zone.all() and d.load_zone_half_angle == pytest.approx(math.pi)
    np.testing.assert_allclose([d.radial_sum, d.axial_sum], [4000.0, 2000.0], rtol=1e-9)


def test_tapered_combined_loads_seeded_sweep():
    """120 seeded tapered bearings (1, 2 or 4 rows, 8-30 deg, clearance, crowned
    profiles, centrifugal force, F_a from half to 100x a single row's limit): each is
    refused by the description (SceneError naming the field) or balances both loads to
    1e-8 with finite loads."""
    from bearing_fem.bearing.description import single_row_min_axial_load
    from bearing_fem.errors import SceneError

    base = load_example("30205")
    rng = np.random.default_rng(20261127)
    solved = refused = 0
    for _ in range(120):
        rows = int(rng.choice([1, 2, 4]))
        g = replace(base.geometry, rows=rows, contact_angle=float(rng.uniform(8.0, 30.0)),
                    radial_clearance=float(rng.choice([0.0, 1e-6, 1e-5, 5e-5])),
                    first_element_azimuth=float(rng.uniform(0.0, 30.0)), width=0.015 * rows)
        fr = float(10 ** rng.uniform(0.0, 5.0)) if rng.random() > 0.1 else 0.0
        if rows == 1 and fr > 0.0:
            fa = single_row_min_axial_load(g, fr) * float(
                rng.choice([0.5, 1.0, 1.0 + 1e-8, 1.001, 1.1, 2.0, 10.0, 100.0]))
        else:
            fa = float(10 ** rng.uniform(0.0, 5.0))
        try:
            if rng.random() < 0.3:
                g = replace(g, profile="crowned", crown_drop=5e-6)
            b = replace(base, geometry=g,
                        operation=replace(base.operation, radial_load=fr, axial_load=fa,
                                          inner_rpm=float(10 ** rng.uniform(1.0, 4.5))),
                        model=replace(base.model, centrifugal=bool(rng.random() < 0.3)))
        except SceneError as exc:
            assert "operation.axial_load" in str(exc) or "bearing." in str(exc), str(exc)
            refused += 1
            continue
        d = distribute_loads(b)
        assert np.all(np.isfinite(d.load_inner)) and np.all(d.load_inner >= 0.0)
        scale = max(fr, fa)
        assert abs(d.radial_sum - fr) <= 1e-8 * scale and abs(d.axial_sum - fa) <= 1e-8 * scale, (
            rows, fr, fa, d.radial_sum, d.axial_sum)
        solved += 1
    assert solved > 80 and refused > 5, (solved, refused)


def test_row_axial_force_of_a_radially_loaded_tapered_pair():
    """Opposed tapered rows under a radial load only: each row induces the axial force
    F_r,row tan(beta) J_a/J_r at eps = 1/2 (zero clearance; Sjovall), the force the
    opposed row reacts; the summary reports it (N)."""
    from bearing_fem.bearing.loads import row_axial_force

    b = _tapered(z=200, rows=2)
    d = distribute_loads(b)
    n, fr_row = 10.0 / 9.0, 1e5 / 2
    expected = fr_row * math.tan(math.radians(15.0)) * (
        analytic.harris_axial_integral(0.5, n) / analytic.harris_radial_integral(0.5, n))
    np.testing.assert_allclose(row_axial_force(d), expected, rtol=1e-3,
                               err_msg="200 rollers per row: the continuous limit within "
                                       "0.1% (measured 5e-5)")
    assert d.axial_sum == 0.0, "the two rows' axial forces cancel"
    # one row under a combined load carries the applied axial load itself
    single = distribute_loads(_tapered(fa=5e4))
    np.testing.assert_allclose(row_axial_force(single), 5e4, rtol=1e-9)


@pytest.mark.parametrize("radial, axial", [(0.0, 100.0), (3000.0, 200.0)])
def test_centrifugal_load_zone_follows_the_loaded_balls(radial, axial):
    """7010 with the centrifugal force: the load zone is where the inner contacts carry
    load (the rigid-geometry boundary gave 0 deg under a pure axial 100 N with all 20
    balls loaded): 180 deg when all are, else midway between the last loaded ball's
    azimuth and the next one's."""
    b = load_example("7010-steel")
    b = replace(b, operation=replace(b.operation, radial_load=radial, axial_load=axial),
                model=replace(b.model, centrifugal=True))
    d = distribute_loads(b)
    angle = np.abs(np.angle(np.exp(1j * d.azimuth)))
    loaded = d.load_inner > 0.0
    assert d.centrifugal_force > 0.0 and np.any(loaded)
    if loaded.all():
        assert d.load_zone_half_angle == math.pi, math.degrees(d.load_zone_half_angle)
    else:
        last, first_out = angle[loaded].max(), angle[~loaded].min()
        assert last < d.load_zone_half_angle < first_out, (
            math.degrees(last), math.degrees(d.load_zone_half_angle), math.degrees(first_out))

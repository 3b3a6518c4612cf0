"""Thermal coupling (coupling.solve_thermal), flash temperature and the new scene sections."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import bearing_fem as bf
from bearing_fem.contacts import coupling
from bearing_fem.physics import thermal
from bearing_fem.errors import SceneError
from bearing_fem.physics.rheology import prokofiev
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec, Model,
                               Scene, Thermal, Traction)

STEEL = dict(conductivity=46.0, density=7850.0, heat_capacity=470.0)


def _scene(*, u1=2.2, u2=1.8, traction="eyring", nodes=401, **th) -> Scene:
    """Small local-compliance (Kodnir) roller: fast line solves (~0.2 s each)."""
    kw = dict(oil_temperature=60.0, exponent=2.93)
    kw.update(th)
    return Scene(contact=Contact(kind="line", rx=0.01, length=0.02),
                 materials=Materials(e1=2.1e11, nu1=0.3, e2=2.1e11, nu2=0.3),
                 lubricant=Lubricant(viscosity=0.05, piezo=2e-8),
                 kinematics=Kinematics(u1=u1, u2=u2), load=Load(force=2e5),
                 model=Model(elasticity="local", thermal="patch"), mesh=MeshSpec(nodes=nodes),
                 thermal=Thermal(**kw), traction=Traction(model=traction))


# ----------------------------------------------------------------------------- scene
def test_thermal_section_required_and_validated():
    s = _scene()
    with pytest.raises(SceneError, match=r"\[thermal\]"):
        replace(s, thermal=None)
    with pytest.raises(SceneError, match=r"thermal.oil_temperature.*deg C.*-5"):
        Thermal(oil_temperature=-5.0, exponent=2.9)
    with pytest.raises(SceneError, match=r"thermal.relaxation.*1.5"):
        Thermal(oil_temperature=50.0, exponent=2.9, relaxation=1.5)
    with pytest.raises(SceneError, match=r"piezo_temperatures.*ascending"):
        Thermal(oil_temperature=50.0, exponent=2.9, piezo_temperatures=[150, 30],
                piezo_values=[0.65e-8, 1.6e-8])
    with pytest.raises(SceneError, match=r"traction.eyring_stress.*Pa"):
        Traction(model="eyring", eyring_stress=0.0)
    with pytest.raises(SceneError, match=r"traction.model"):
        Traction(model="bingham")


def test_scene_round_trip_and_unknown_key():
    s = _scene(piezo_temperatures=[30.0, 150.0], piezo_values=[1.6e-8, 0.65e-8])
    d = s.to_dict()
    assert Scene.from_dict(d) == s, "to_dict/from_dict round-trips the new sections"
    d["thermal"]["colour"] = "red"
    with pytest.raises(SceneError, match=r"thermal.colour.*known keys"):
        Scene.from_dict(d)
    plain = Scene.from_dict({k: v for k, v in s.to_dict().items()
                             if k not in ("thermal", "traction", "model")})
    assert plain.thermal is None and plain.traction is None, \
        "both sections are optional for isothermal scenes (generic traction when sliding)"


def test_piezo_table_is_log_linear():
    s = _scene(piezo_temperatures=[30.0, 150.0], piezo_values=[1.6e-8, 0.65e-8])
    np.testing.assert_allclose(coupling.contact_piezo(s, 30.0), 1.6e-8, rtol=1e-12,
                               err_msg="table node")
    mid = coupling.contact_piezo(s, 90.0)
    np.testing.assert_allclose(mid, math.sqrt(1.6e-8 * 0.65e-8), rtol=1e-12,
                               err_msg="ln alpha linear in t: geometric mean at the midpoint")
    assert coupling.contact_piezo(s, 20.0) > 1.6e-8, "extrapolates below the table"


def test_far_extrapolation_of_the_piezo_table_is_warned():
    """A table over [40, 41] deg C extrapolated to 60 deg C gives alpha = 2e-14 1/Pa
    without a word before; within 10 K of the table nothing is said."""
    th = Thermal(oil_temperature=60.0, exponent=2.93, piezo_temperatures=[40.0, 41.0],
                 piezo_values=[2.0e-8, 1.2e-8])
    note = coupling.piezo_table_warning(th, 60.0)
    alpha = coupling.contact_piezo(_scene(piezo_temperatures=[40.0, 41.0],
                                          piezo_values=[2.0e-8, 1.2e-8]), 60.0)
    assert note is not None and "[40, 41] deg C" in note and f"{alpha:.3g} 1/Pa" in note, note
    assert coupling.piezo_table_warning(th, 50.9) is None
    assert coupling.piezo_table_warning(th, 29.0) is not None
    assert coupling.piezo_table_warning(Thermal(oil_temperature=60.0, exponent=2.9), 500.0) \
        is None, "no table, no warning"
    r = coupling.solve_thermal(_scene(piezo_temperatures=[20.0, 30.0],
                                      piezo_values=[2.2e-8, 2.0e-8]))
    assert any("outside the piezo_temperatures table [20, 30]" in w for w in r.warnings), \
        r.warnings


# ------------------------------------------------------------------ flash temperature
def test_jaeger_uniform_band_maximum():
    lam, rho, c, V, b, q = 46.0, 7850.0, 470.0, 3.0, 2e-4, 1e8
    x = np.linspace(-b, b, 401)
    T = coupling.jaeger_surface_temperature(x, np.full(400, q), x, lam, rho, c, V)
    expected = 2.0 * math.sqrt(2.0 / math.pi) * q * math.sqrt(b) / math.sqrt(lam * rho * c * V)
    np.testing.assert_allclose(T.max(), expected, rtol=1e-12,
                               err_msg="uniform band: T_max = 2 sqrt(2/pi) q sqrt(b)/sqrt(K rho c V)"
                                       " (= 1.596..., docs/theory.md section 14.4) at the trailing edge")
    assert np.argmax(T) == x.size - 1


def test_jaeger_agrees_with_fe_moving_source_at_high_peclet():
    lam, rho, c, V, b = 46.0, 7850.0, 470.0, 4.0, 3e-4
    pe = V * b * rho * c / (2 * lam)
    assert pe > 40, "high-Peclet regime of the closed form"
    x = np.linspace(-b, b, 201)
    xm = 0.5 * (x[1:] + x[:-1])
    q = 1e8 * np.sqrt(1 - (xm / b) ** 2)
    tj = coupling.flash_temperature(x, q, x, lam, rho, c, V, source_model="jaeger")
    tf = coupling.flash_temperature(x, q, x, lam, rho, c, V, source_model="fe")
    # finite-Pe conduction along x lowers the FE maximum by O(Pe^-1/2)
    np.testing.assert_allclose(tf.max(), tj.max(), rtol=0.05,
                               err_msg="FE moving source vs Jaeger high-Pe integral")


def test_flash_temperature_of_a_surface_running_along_minus_x():
    """A body moving along -x carries its heat towards -x: the Blok maximum of a
    semi-elliptic band lies at x = -0.652 b, the mirror image of the +x body's (the
    coupled loop used |u| for both surfaces, so a counter-running surface got the field of
    one running along +x)."""
    b = 1e-4
    x = np.linspace(-1.5 * b, 1.5 * b, 1201)
    xm = 0.5 * (x[1:] + x[:-1])
    q = 1e8 * np.sqrt(np.clip(1.0 - (xm / b) ** 2, 0.0, None))
    forward = coupling.flash_temperature(x, q, x, 46.0, 7850.0, 470.0, 5.0)
    backward = coupling.flash_temperature(x, q, x, 46.0, 7850.0, 470.0, -5.0)
    np.testing.assert_allclose(backward, forward[::-1], rtol=1e-12, atol=1e-12,
                               err_msg="a symmetric band: T(-V)(x) = T(+V)(-x)")
    np.testing.assert_allclose(x[np.argmax(backward)] / b, -0.652, atol=0.01,
                               err_msg="Blok maximum 0.652 b downstream of the motion")


def test_counter_running_surface_heats_upstream():
    """End to end: with u2 < 0 the second surface's temperature field peaks at x < 0 and
    the first surface's at x > 0."""
    r = bf.solve(_scene(u1=3.0, u2=-0.5))
    assert r.success, r.message
    t1 = r.extra_fields["surface_temperature_rise_body1_K"]
    t2 = r.extra_fields["surface_temperature_rise_body2_K"]
    assert r.x[np.argmax(t1)] > 0.0 > r.x[np.argmax(t2)], \
        (r.x[np.argmax(t1)], r.x[np.argmax(t2)])


def test_oil_too_thin_for_its_law_is_named_in_thermal_terms():
    """A Roelands oil of 0.001 Pa s at 40 deg C is 1.9e-5 Pa s at 150 deg C, below the
    Roelands range: the refusal said 'lubricant.viscosity = 1.9e-05 Pa s is outside ...',
    a value the file does not hold. It now names the oil temperature and the given value;
    a temperature reached only during the loop ends it with status 'diverged'."""
    base = _scene(oil_temperature=150.0, exponent=3.0)
    thin = replace(base, lubricant=replace(base.lubricant, viscosity=0.001,
                                           viscosity_law="roelands"))
    with pytest.raises(SceneError) as err:
        bf.solve(thin)
    text = str(err.value)
    assert text.startswith("thermal.oil_temperature = 150 deg C") and \
        "lubricant.viscosity = 0.001 Pa s at 40 deg C" in text, text


def test_leaving_the_law_during_the_loop_is_diverged(monkeypatch):
    calls = []
    real = coupling.contact_viscosity

    def viscosity(scene, temperature):
        calls.append(temperature)
        return real(scene, temperature) if len(calls) == 1 else 1e-9   # below 1e-6 Pa s

    monkeypatch.setattr(coupling, "contact_viscosity", viscosity)
    r = bf.solve(_scene())
    assert r.status == "diverged" and not r.success, r.message
    assert "thermal iteration 2" in r.message and "eta0 = 1e-09 Pa s" in r.message, r.message


# ------------------------------------------------------------------ coupled solve
@pytest.fixture(scope="module")
def eyring_result():
    return bf.solve(_scene())


def test_coupled_solve_converges_to_a_fixed_point(eyring_result):
    r = eyring_result
    q = r.quantities
    assert r.status == "converged" and r.success, r.message
    assert all(np.isfinite(v) for v in q.values()), "no NaN in the quantities"
    th = r.scene.thermal
    assert abs(q["contact_temperature_rise_computed"] - q["contact_temperature_rise"]) < th.tolerance, \
        "fixed point: the temperature used equals the one computed from it"
    np.testing.assert_allclose(q["contact_temperature"], th.oil_temperature
                               + q["contact_temperature_rise"], rtol=1e-12, err_msg="datum")
    np.testing.assert_allclose(q["contact_viscosity"],
                               prokofiev(q["contact_temperature"], 0.05, 40.0, 2.93),
                               rtol=1e-12, err_msg="eta0 from the Prokofiev law at T_contact")
    assert 0 < q["contact_temperature_rise"] < q["contact_temperature_rise_max"]
    assert q["peclet_min"] > 5, "high-Peclet regime (Jaeger formula valid)"
    n_it = r.summary()["thermal_iterations"]
    assert isinstance(n_it, int) and n_it >= 1, \
        f"the thermal loop count is a whole number in the summary, got {n_it!r}"


def test_dimensionless_groups_use_the_solved_contact_viscosity(eyring_result):
    """The Moes groups of a thermal result describe the contact that was solved: eta0 at
    the contact temperature, not lubricant.viscosity (the value at the reference
    temperature, 40 deg C here, or unused when thermal.reference_viscosity is given)."""
    from bearing_fem import units
    r = eyring_result
    q, s = r.quantities, r.scene
    groups = r.summary()["dimensionless"]
    want = units.moes_line(s.load.force, s.contact.rx, s.e_prime, q["contact_viscosity"],
                           s.kinematics.mean_speed, q["contact_piezo"])
    for key in ("M", "L", "U"):
        np.testing.assert_allclose(groups[key], want[key], rtol=1e-12,
                                   err_msg=f"{key} at the contact viscosity, not eta(40 C)")
    ref = replace(s, thermal=replace(s.thermal, reference_viscosity=0.05),
                  lubricant=replace(s.lubricant, viscosity=1e-3))
    r2 = replace(r, scene=ref)
    np.testing.assert_allclose(r2.summary()["dimensionless"]["M"], groups["M"], rtol=1e-12,
                               err_msg="lubricant.viscosity is unused beside "
                               "thermal.reference_viscosity; the groups do not depend on it")


def test_energy_heat_into_bodies_equals_heat_power(eyring_result):
    q = eyring_result.quantities
    np.testing.assert_allclose(q["heat_flux_body1"] + q["heat_flux_body2"], q["heat_power"],
                               rtol=1e-2, err_msg="energy: both patches receive the EHL heat")
    f1 = thermal.heat_partition((46.0, 46.0), (7850.0, 7850.0), (470.0, 470.0), (2.2, 1.8)).fraction_1
    np.testing.assert_allclose(q["heat_flux_body1"] / (q["heat_flux_body1"] + q["heat_flux_body2"]),
                               f1, rtol=1e-12,
                               err_msg="Blok partition: the faster body takes more heat")
    np.testing.assert_allclose(q["heat_power_couette"], q["sliding_friction"] * 0.4, rtol=1e-12,
                               err_msg="Couette heat = traction x sliding speed")
    np.testing.assert_allclose(q["heat_power_poiseuille"], q["heat_power_poiseuille_direct"],
                               rtol=2e-2, err_msg="conservative vs direct Poiseuille heat "
                                                  "(resolved local-compliance film)")


def test_pure_rolling_newtonian_heat_matches_post():
    r = bf.solve(_scene(u1=2.0, u2=2.0, traction="newtonian"))
    q = r.quantities
    assert r.success, r.message
    np.testing.assert_allclose(q["heat_flux_body1"] + q["heat_flux_body2"], q["heat_power"],
                               rtol=1e-2, err_msg="heat into the patches = the EHL heat power")


def test_newtonian_sliding_reports_divergence_not_nan():
    r = bf.solve(_scene(traction="newtonian"))
    assert r.status == "diverged" and not r.success, r.message
    assert "eyring" in r.message
    assert all(np.isfinite(v) for v in r.quantities.values())


def test_max_iterations_status():
    r = bf.solve(_scene(max_iterations=1))
    assert r.status == "max_iterations" and not r.success, r.message
    assert all(np.isfinite(v) for v in r.quantities.values())


def test_point_contact_rejected():
    s = _scene()
    with pytest.raises(SceneError, match="line contacts only"):
        coupling.solve_thermal(replace(s, contact=Contact(kind="point", rx=0.01, ry=0.01),
                                       mesh=MeshSpec()))


def test_peclet_number_does_not_depend_on_the_mesh_domain():
    """The Peclet number is that of the band holding the heat, not of the mesh domain: a
    slow contact (Hertz half-width b = 0.15 mm, u2 = 0.15 m/s, Pe ~ 1 with b) keeps its
    Pe and its low-Peclet warning when the domain is widened from [-4.5, 1.5] b to
    [-20, 5] b (the whole non-zero flux gave 2.7 and 11.2, and no warning on the wider
    domain)."""
    from bearing_fem import units
    slow = _scene(u1=0.25, u2=0.15, nodes=601)
    wide = replace(slow, mesh=MeshSpec(nodes=2001, x_range=(-20.0, 5.0)))
    r1, r2 = bf.solve(slow), bf.solve(wide)
    assert r1.success and r2.success, (r1.message, r2.message)
    pe1, pe2 = r1.quantities["peclet_min"], r2.quantities["peclet_min"]
    np.testing.assert_allclose(pe2, pe1, rtol=0.05,
                               err_msg="same contact, same heated band: the domain's extent "
                                       "must not set the Peclet number (5 %: the two grids "
                                       "resolve the flux differently)")
    b = units.hertz_line(2e5, 0.01, slow.e_prime)[0]
    kappa = 46.0 / (7850.0 * 470.0)
    pe_hertz = 0.15 * b / (2 * kappa)
    assert 0.5 * pe_hertz < pe1 < 2.0 * pe_hertz, \
        f"the heat sits in the Hertz zone: Pe {pe1:.3g} near the Hertz value {pe_hertz:.3g}"
    for r in (r1, r2):
        assert any("Peclet number" in w for w in r.warnings), r.warnings


def test_heated_half_length_of_a_uniform_band_in_a_wide_domain():
    x = np.linspace(-10.0, 10.0, 2001)
    xm = 0.5 * (x[1:] + x[:-1])
    q = np.where(np.abs(xm) < 1.0, 1.0, 0.0)
    np.testing.assert_allclose(coupling.heated_half_length(x, q), 0.98, rtol=1e-9,
                               err_msg="uniform band of half-length 1: the central 98 % of "
                                       "its heat spans 0.98")
    np.testing.assert_allclose(coupling.heated_half_length(x, np.zeros_like(xm)), 10.0,
                               err_msg="no heat: half the domain")


def test_every_number_of_a_thermal_summary_has_its_unit(eyring_result):
    """thermal_residual |G(T) - T| [K] was written without a unit."""
    s = eyring_result.summary()
    missing = [k for k, v in s.items() if isinstance(v, float) and k not in s["units"]]
    assert not missing, f"thermal summary numbers without a unit: {missing}"
    assert s["units"]["thermal_residual"] == "K"


def test_unequal_surface_temperatures_are_reported():
    """Blok's partition gives both surfaces the same flash temperature only in the
    high-Peclet limit. With the FE moving source and an almost standing surface (u2 =
    0.01 m/s, Pe 0.06) the surfaces' mean rises came out 74 K and 56 K and the contact
    temperature, their mean, carried no word about it."""
    slow = bf.solve(_scene(u1=2.2, u2=0.01, nodes=601, source_model="fe"))
    assert slow.success, slow.message
    found = [w for w in slow.warnings if "Blok's heat partition" in w]
    assert found, slow.warnings
    fast = bf.solve(_scene(u1=2.2, u2=1.8, nodes=601, source_model="fe"))
    assert fast.success, fast.message
    assert not [w for w in fast.warnings if "Blok's heat partition" in w], \
        "Pe 13 on both surfaces: the partition holds (rises within 1 %), no warning"


def test_failed_isothermal_solve_reports_its_own_temperature():
    """When the isothermal solve of thermal iteration 2 fails, the result holds that
    solve's fields; its summary gave the temperature, viscosity, heat fluxes and count of
    iteration 1 (contact_temperature 60 deg C beside fields solved at 64.8 deg C)."""
    first = bf.solve(_scene(max_iterations=1))
    n1 = first.newton_iterations
    s = _scene()
    s = replace(s, solver=replace(s.solver, iteration_budget=n1 + 1))
    r = bf.solve(s)
    q = r.quantities
    assert r.status == "budget_exhausted" and "thermal iteration 2" in r.message, r.message
    assert q["thermal_iterations"] == 2
    assert q["contact_temperature"] > s.thermal.oil_temperature + 1.0, \
        "iteration 2 runs at the temperature computed by iteration 1 (a rise of several K)"
    assert f"contact temperature {q['contact_temperature']:.4g} deg C" in r.message
    np.testing.assert_allclose(q["contact_viscosity"],
                               prokofiev(q["contact_temperature"], 0.05, 40.0, 2.93),
                               rtol=1e-12, err_msg="eta0 of the returned solve")
    for key in ("heat_flux_body1", "heat_flux_body2", "contact_temperature_rise_mean",
                "thermal_residual"):
        assert key not in q, f"{key} belonged to iteration 1's fields"
    assert all(np.isfinite(v) for v in q.values())


def test_rise_above_a_low_user_limit_is_not_called_unphysical():
    """A rise of a few kelvin above a 1 K thermal.max_temperature_rise stops the loop;
    the message said 'no physical fixed point' for it, although the rise is physical."""
    r = bf.solve(_scene(max_temperature_rise=1.0))
    assert r.status == "diverged", r.message
    assert "no physical fixed point" not in r.message, r.message
    assert "thermal.max_temperature_rise = 1 K" in r.message, r.message
    assert "raise thermal.max_temperature_rise" in r.message, r.message


def test_nncf5040_contact_study_writes_the_direct_heat_power(tmp_path, load_study):
    """The contact study read a summary key that no longer exists ('heat_power_direct'),
    so results.json held null for the direct-quadrature heat power of every contact."""
    import json
    study = load_study("nncf5040_heat_power")
    study.contact_study(tmp_path, models=("local",), temperatures=(100.0,), nodes=401)
    row = json.loads((tmp_path / "results.json").read_text())["rows"][0]
    for side in ("inner", "outer"):
        c = row[side]
        assert c["status"] == "converged", c["message"]
        assert c["heat_power_direct_W_per_m"] is not None
        np.testing.assert_allclose(c["heat_power_direct_W_per_m"], c["heat_power_W_per_m"],
                                   rtol=2e-2, err_msg="local compliance: the direct and the "
                                   "conservative Poiseuille heat agree (docs/coupling.md "
                                   "section 3: 368.4 vs 368.4 W/m at 100 C, 1201 nodes)")


def test_lightly_loaded_local_compliance_roller_is_solved():
    """A local-compliance (Kodnir) roller at 100 N/m: its dry contact (a = 4 um) falls
    between the nodes of the default 801-node grid (spacing 20 um), the start pressure
    was 0 everywhere and its load scaling NaN, and the solve ended 'diverged' with
    'int p dA = nan'. At such a load the bodies barely deform: the film equals that of
    the half-space model."""
    base = _scene(nodes=801)
    light = replace(base, model=Model(elasticity="local"), thermal=None,
                    load=Load(force=100.0))
    r_loc = bf.solve(light)
    assert r_loc.success, r_loc.message
    r_hs = bf.solve(replace(light, model=Model(elasticity="half-space")))
    assert r_hs.success, r_hs.message
    np.testing.assert_allclose(r_loc.quantities["h_central"], r_hs.quantities["h_central"],
                               rtol=1e-3, err_msg="rigid-like contact: the compliance model "
                               "does not matter (both deform by < 1e-4 of the film)")


@pytest.mark.parametrize("elasticity", ["half-space", "local"])
def test_lightly_loaded_elastic_line_keeps_its_outlet_in_the_domain(elasticity):
    """At 300 N/m on a 10 mm steel roller (Moes M ~ 0.05) the film is that of a rigid
    cylinder, whose Martin outlet lies 40 Hertz half-widths downstream; the default
    domain ended at 1.5 b, cut the pressure zone there and gave h_central 1.20e-5 m,
    17 % below the rigid 1.46e-5 m."""
    from bearing_fem.contacts.line import default_x_range
    base = _scene(nodes=801)
    light = replace(base, model=Model(elasticity=elasticity), thermal=None,
                    load=Load(force=300.0), mesh=MeshSpec())
    r = bf.solve(light)
    assert r.success, r.message
    rigid = bf.solve(replace(light, model=Model(elasticity="rigid"), materials=None))
    assert rigid.success, rigid.message
    np.testing.assert_allclose(r.quantities["h_central"], rigid.quantities["h_central"],
                               rtol=2e-2, err_msg="rigid-like contact (deformation < 1e-3 "
                               "of the film); 2 %: the two solvers' grids and domains")
    b = bf.units.hertz_line(300.0, 0.01, light.e_prime)[0]
    assert r.quantities["outlet_position"] < 0.9 * default_x_range(light)[1] * b, \
        "the free outlet lies inside the domain, not at its end"


def test_time_limit_stops_before_an_iteration_that_would_overrun(monkeypatch):
    """With a fake clock (0.1 s per reading in the loop) the first thermal iteration takes
    0.3 s; at 0.6 s a second one would end at 0.9 s, the limit: the loop stops before it
    (it used to start it, and with source_model = "fe" one iteration overran a 0.5 s limit
    by 70 %: a thermal NNCF 5040 contact took 0.84 s)."""
    ticks = iter(np.arange(0.0, 100.0, 0.1))

    class Clock:
        @staticmethod
        def perf_counter() -> float:
            return float(next(ticks))

    monkeypatch.setattr(coupling, "time", Clock)
    s = _scene(max_iterations=5)
    s = replace(s, solver=replace(s.solver, time_limit=0.9))
    r = bf.solve(s)
    assert r.status == "time_limit" and not r.success, r.message
    assert "stopped before iteration 2" in r.message and "previous iteration took" in r.message
    assert r.quantities["thermal_iterations"] == 1, "the first iteration's result is kept"


def test_default_grid_follows_the_contact_temperature():
    """Each isothermal solve of the loop is the scene with eta0(T) (docs/coupling.md,
    section 1), so its default grid is the grid rule's for the contact solved: the hot,
    thin film of a sliding 2e6 N/m roller (Moes M grows as eta0 falls) gets more nodes
    than line_setup gives for the thermal scene itself, which sizes from the oil at the
    reference temperature (measured: 2289 nodes against 1801)."""
    from bearing_fem.contacts.line import line_setup

    scene = replace(_scene(nodes=None), load=Load(force=2e6))
    r = bf.solve(scene)
    assert r.success, r.message
    q = r.quantities
    solved = replace(scene, model=replace(scene.model, thermal="none"), thermal=None,
                     lubricant=replace(scene.lubricant, viscosity=q["contact_viscosity"],
                                       piezo=q["contact_piezo"]))
    assert r.x.size == line_setup(solved).disc.x.size, \
        "the returned grid is the default grid of the contact at its own temperature"
    assert r.x.size > line_setup(scene).disc.x.size, \
        "hotter and thinner than the oil at the reference temperature: a finer grid"

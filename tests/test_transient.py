"""Elastic transient squeeze (bearing_fem.contacts.transient): rigid limit vs Kapitsa, time order,
steady limit, Jacobian of the time terms, status contract, bad input.

Grids are coarse (25^2 to 57^2) to keep the module fast; every tolerance says why.
"""
from __future__ import annotations

import json
import math
import pathlib

import h5py
import meshio
import numpy as np
import pytest

import bearing_fem as bf
from bearing_fem import analytic as an
from bearing_fem.errors import SceneError
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec,
                               Model, Scene)
from bearing_fem.contacts.transient import (BDF_COEFFICIENTS, solve_elastic_gap,
                                   solve_elastic_squeeze_series)

U_M = 1.0                 # m/s
H0 = 1e-7                 # m, mean gap
R_BALL = 6.35e-3          # m, ball of bearing 209 on a plane (Kadochnikova 2018)
E_STEEL = 2.26e11         # Pa, E' of two steel bodies
ETA_I40A = 0.0612         # Pa s, oil I-40A (Kadochnikova 2018): strongly elastic at this gap


def scene(*, rx=R_BALL, ry=R_BALL, e_prime=E_STEEL, viscosity=ETA_I40A,
          cavitation="none", density="incompressible", nodes=33, half_width=4.0,
          elasticity="half-space", load=None) -> Scene:
    return Scene(contact=Contact(kind="point", rx=rx, ry=ry),
                 materials=Materials(reduced_modulus=e_prime),
                 lubricant=Lubricant(viscosity=viscosity, viscosity_law="constant",
                                     density=density),
                 kinematics=Kinematics(u1=U_M, u2=U_M),
                 load=load or Load(gap=H0),
                 model=Model(elasticity=elasticity, cavitation=cavitation),
                 mesh=MeshSpec(nodes=(nodes, nodes), x_range=(-half_width, half_width),
                               y_range=(-half_width, half_width)))


# ---------------------------------------------------------------------------------------
# (a) rigid limit: Kapitsa wedge + squeeze at every step
# ---------------------------------------------------------------------------------------
def test_stiff_transient_reproduces_kapitsa_each_step(tmp_path):
    rx, ry, eta = 0.01, 0.02, 0.01
    a, b = 1 / (2 * rx), 1 / (2 * ry)
    eps = 0.3
    omega = U_M / math.sqrt(2 * rx * H0)  # squeeze and wedge pressures comparable

    def gap(t):
        return H0 * (1 + eps * np.cos(omega * t))

    def rate(t):
        return -H0 * eps * omega * np.sin(omega * t)

    def exact(x, y, t):
        return an.kapitsa_point_pressure(x, y, gap(t), a, b, eta, U_M, rate(t))

    # E' = 1e25 Pa: the deformation is ~1e-14 of the film, the elastic code path (FFT
    # compliance, GMRES, time terms through A_h) runs unchanged
    sc = scene(rx=rx, ry=ry, e_prime=1e25, viscosity=eta, nodes=57, half_width=3.0)
    series = solve_elastic_squeeze_series(sc, eps=eps, omega=omega, n_steps=32,
                                          boundary_pressure=exact)
    assert series.status == "converged", series.message
    assert len(series.results) == 33 and series.n_planned == 33
    np.testing.assert_allclose(series.gap, gap(series.times), rtol=1e-14)
    np.testing.assert_allclose(series.h_central, series.gap, rtol=1e-9,
                               err_msg="E' = 1e25 Pa: no visible deformation")
    kap = np.array([float(an.kapitsa_point_max_reduced(g, a, b, eta, U_M, r))
                    for g, r in zip(series.gap, series.squeeze_velocity)])
    np.testing.assert_allclose(series.p_max, kap, rtol=1e-2,
                               err_msg="each step's p_max within 1% of Kapitsa with the "
                                       "exact dh0/dt (design target): measured 0.71% "
                                       "= nodal sampling of the peak on 57^2 over +-3 "
                                       "lengths (~0.4%) + BDF2 rate error (omega dt)^2/3 "
                                       "of the squeeze part")
    assert series.newton_iterations.max() <= 3, (
        f"cost cap: the stiff problem is nearly linear, got {series.newton_iterations}")
    assert np.all(np.isfinite(series.p_max))

    paths = {k: str(v) for k, v in bf.io.export_series(series, tmp_path / "stiff").items()}
    assert paths["pvd"].endswith(".pvd") and "DataSet" in open(paths["pvd"]).read()
    with meshio.xdmf.TimeSeriesReader(paths["xdmf"]) as reader:
        reader.read_points_cells()
        t, data, _ = reader.read_data(5)
    np.testing.assert_allclose(t, series.times[5])
    np.testing.assert_allclose(data["pressure_Pa"], series.results[5].pressure.ravel())
    np.testing.assert_allclose(data["film_m"], series.results[5].film.ravel())


# ---------------------------------------------------------------------------------------
# (b) time-discretisation error: observed order of backward Euler and BDF2
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("scheme, order", [("euler", 1.0), ("bdf2", 2.0)])
def test_time_step_convergence_order(scheme, order):
    sc = scene(nodes=25)  # I-40A at 0.1 um: the deformation is ~20% of the film
    coarse = 8
    series = [solve_elastic_squeeze_series(sc, eps=0.3, n_steps=m, scheme=scheme)
              for m in (coarse, 2 * coarse, 4 * coarse)]
    for s in series:
        assert s.status == "converged", s.message
    # p_max at the instants shared by all three step sizes (k T/8)
    common = [s.p_max[::len(s.p_max) // coarse] for s in series]
    np.testing.assert_allclose(common[0][0], common[2][0], rtol=1e-12,
                               err_msg="same steady start for every dt")
    scale = np.max(common[-1])
    d1 = np.max(np.abs(common[1] - common[0])) / scale
    d2 = np.max(np.abs(common[2] - common[1])) / scale
    assert d2 < d1, f"halving dt must change p_max by less: {d1:.3e} then {d2:.3e}"
    observed = math.log2(d1 / d2)
    assert abs(observed - order) < 0.4, (
        f"{scheme}: observed order {observed:.2f} (changes {d1:.2e}, {d2:.2e}), theory "
        f"{order}; 0.4 allows the pre-asymptotic coarsest step (omega dt = pi/4); "
        "measured 1.09 (euler), 2.26 (bdf2)")


# ---------------------------------------------------------------------------------------
# (c) eps = 0: the time term vanishes, every step is the steady elastic solution
# ---------------------------------------------------------------------------------------
def test_zero_amplitude_gives_steady_solution_every_step():
    # compressible + Reynolds cavitation: the rho(p) and Fischer-Burmeister parts of the
    # time term must vanish too
    sc = scene(cavitation="reynolds", density="dowson-higginson")
    steady = solve_elastic_gap(sc)
    assert steady.status == "converged", steady.message
    series = solve_elastic_squeeze_series(sc, eps=0.0, n_steps=4, periods=1)
    assert series.status == "converged", series.message
    assert list(series.newton_iterations[1:]) == [0] * 4, (
        f"the steady state must satisfy every time step as it is: "
        f"{series.newton_iterations}")
    for r in series.results:
        np.testing.assert_allclose(r.pressure, steady.pressure, rtol=0,
                                   atol=1e-9 * steady.quantities["p_max"],
                                   err_msg="eps = 0: steady elastic pressure at every step "
                                           "(Newton tolerance 1e-8 on scaled rows)")
    np.testing.assert_allclose(series.h_central, steady.quantities["h_central"], rtol=1e-12)


def test_series_warnings_are_said_once_and_truly():
    """A series' summary names each finding once and gives the true reason for the
    missing error estimate (its instants share one grid by design), not "no coarser grid
    of this solve converged", repeated at every instant."""
    from types import SimpleNamespace

    from bearing_fem.contacts.series import series_warnings

    rs = [SimpleNamespace(warnings=w) for w in (
        ["h_min lies between the nodes (3.15e-07 m, 1.93% below ...)", "generic traction"],
        ["generic traction"],
        ["h_min lies between the nodes (2.85e-07 m, 2.4% below ...)", "generic traction"])]
    got = series_warnings(np.array([0.0, 1e-5, 2e-5]), rs)
    assert got == ["h_min lies between the nodes (3.15e-07 m, 1.93% below ...) (at t = 0 s; "
                   "2 of 3 instants, with their own numbers)", "generic traction"], got

    series = solve_elastic_squeeze_series(scene(cavitation="reynolds"), eps=0.3, n_steps=4)
    assert series.status == "converged", series.message
    assert all(r.error_estimate is None for r in series.results), \
        "no estimate by design: the instants share one grid"
    warns = series.summary()["warnings"]
    assert not any("no coarser grid of this solve converged" in w for w in warns), warns
    assert sum(w.startswith("no error estimate") for w in warns) == 1, warns
    assert "solved on one grid" in warns[-1], warns
    import re
    masked = [re.sub(r"[-+]?[0-9.]+(e[-+]?[0-9]+)?", "#", w) for w in warns]
    assert len(masked) == len(set(masked)), f"a finding repeated with other numbers: {warns}"


# ---------------------------------------------------------------------------------------
# (d) consistency: steady gap solve vs the load-controlled solver; exact time Jacobian
# ---------------------------------------------------------------------------------------
def test_steady_gap_solution_matches_load_controlled_solver():
    from bearing_fem.contacts.point import solve_point
    from bearing_fem.units import hertz_point

    sc = scene(cavitation="reynolds")
    gap_res = solve_elastic_gap(sc)
    assert gap_res.status == "converged", gap_res.message
    force = gap_res.quantities["load"]
    hz = hertz_point(force, sc.contact.rx, sc.contact.ry, sc.e_prime)
    lx = math.sqrt(2 * sc.contact.rx * H0)
    k = 4.0 * lx / hz.a_x   # same nodes, ranges given in Hertz semi-axes
    loaded = sc.replace(load=Load(force=force),
                        mesh=MeshSpec(nodes=sc.mesh.nodes, x_range=(-k, k), y_range=(-k, k)))
    res = solve_point(loaded)
    assert res.status == "converged", res.message
    np.testing.assert_allclose(res.x, gap_res.x, rtol=1e-12)
    np.testing.assert_allclose(res.h0, H0, rtol=1e-3,
                               err_msg="under the load the gap solution carries, the load-"
                                       "controlled solver must find the same offset; the "
                                       "two differ only in the upwinding length scale "
                                       "(4 a_x vs 4 sqrt(2 rx h0) over pi E'), measured "
                                       "0.03%")
    np.testing.assert_allclose(res.pressure, gap_res.pressure, rtol=0,
                               atol=5e-3 * gap_res.quantities["p_max"],
                               err_msg="same pressure field (measured 0.1% of p_max)")


def test_newton_step_consistent_with_time_residual(monkeypatch):
    # The time terms of the Jacobian (rho' h and rho C, Fischer-Burmeister rows) are exact:
    # along the Newton direction dz, F(z + d dz) - F(z - d dz) = -2 d F(z) to O(d^2) and
    # the GMRES tolerance.
    from bearing_fem.contacts import point
    from bearing_fem.contacts.transient import _make_step_problem, elastic_gap_setup

    # the solver's inexact Newton loosens GMRES to |F| far from the solution; this check
    # needs the exact step, so GMRES runs to its tight tolerance
    monkeypatch.setattr(point, "GMRES_FORCING_MAX", point.GMRES_RTOL)
    sc = scene(cavitation="reynolds", density="dowson-higginson")
    start = solve_elastic_gap(sc)
    setup = elastic_gap_setup(sc)
    p0 = start.pressure.ravel()
    zero = np.zeros(setup.grid.size)
    prev = _make_step_problem(sc, setup, H0, zero)
    m0 = prev.mass_q(p0, H0)
    m1 = prev.mass_q(p0, 1.02 * H0)
    omega = U_M / math.sqrt(2 * sc.contact.rx * H0)
    problem = _make_step_problem(sc, setup, 0.97 * H0, zero, time_step=0.2 / omega,
                                 coefficients=BDF_COEFFICIENTS["bdf2"], history=[m0, m1])
    z = problem.pack(p0, 0.97 * H0)
    problem.prepare(z)
    f = problem.residual(z)
    dz = problem.newton_step(z)
    d = 1e-4
    slope = (problem.residual(z + d * dz) - problem.residual(z - d * dz)) / (2 * d)
    err = np.max(np.abs(slope + f)) / np.max(np.abs(f))
    assert err < 1e-5, (f"directional derivative of the residual along the Newton step "
                        f"differs from -F by {err:.2e} (relative): the Jacobian of the time "
                        "terms is inconsistent")


# ---------------------------------------------------------------------------------------
# status contract and bad input
# ---------------------------------------------------------------------------------------
def test_failed_step_stops_series_with_status(monkeypatch, tmp_path):
    import bearing_fem.contacts.transient as tr

    real = tr.damped_newton
    calls = {"n": 0}

    def failing_after_three(problem, z0, **kw):
        # the steady start (step 0) is solved by the shared driver, the time steps here
        calls["n"] += 1
        if calls["n"] > 2:  # steps >= 3: no iteration allowed -> max_iterations
            kw["max_iterations"] = 0
        return real(problem, z0, **kw)

    monkeypatch.setattr(tr, "damped_newton", failing_after_three)
    series = solve_elastic_squeeze_series(scene(nodes=25), eps=0.3, n_steps=8)
    assert series.status == "max_iterations" and not series.success
    assert len(series.results) == 3 and series.n_planned == 9
    assert "step 3" in series.message and "stopped" in series.message
    assert series.failure is not None and series.failure.status == "max_iterations"
    for arr in (series.p_max, series.h_min, series.h_central, series.load):
        assert arr.shape == (3,) and np.all(np.isfinite(arr))
    assert np.all(np.isfinite(series.failure.pressure))
    assert series.failure_time == pytest.approx(3 * series.time_step, rel=1e-12)
    # the failed step's fields are exported apart from the solved steps
    files = bf.io.export_series(series, tmp_path / "series")
    failed = meshio.read(files["failed"])
    np.testing.assert_array_equal(failed.point_data["pressure_Pa"],
                                  np.ravel(series.failure.pressure),
                                  err_msg="the failed step's VTU holds its last iterate")
    pvd = files["pvd"].read_text()
    assert pvd.count("<DataSet") == 3 and "failed" not in pvd, "not in the time series"
    with h5py.File(files["h5"]) as f:
        assert f["failed"].attrs["status"] == "max_iterations"
        np.testing.assert_array_equal(f["failed/film_m"][()], np.ravel(series.failure.film))
    summary = json.loads(files["summary"].read_text())
    assert summary["failed_step"]["step"] == 3 and summary["failed_step"]["status"] == \
        "max_iterations", summary["failed_step"]
    # a later export of a complete series into the same folder removes that file
    monkeypatch.setattr(tr, "damped_newton", real)
    whole = solve_elastic_squeeze_series(scene(nodes=25), eps=0.3, n_steps=8)
    assert whole.success and whole.summary()["failed_step"] is None, whole.message
    again = bf.io.export_series(whole, tmp_path / "series")
    assert "failed" not in again and not files["failed"].exists(), \
        "a stale failed step would be taken for this series'"


def test_start_falls_back_to_compliance_continuation(monkeypatch):
    # If the direct Newton solve of the steady start fails, the start is reached by
    # continuation in the compliance 1/E' (rigid -> elastic) and is the same solution.
    import bearing_fem.contacts.driver as driver

    sc = scene(nodes=25, cavitation="reynolds")
    direct = solve_elastic_gap(sc)
    real = driver.damped_newton
    calls = {"n": 0}

    def first_attempt_fails(problem, z0, **kw):
        calls["n"] += 1
        if calls["n"] == 1:
            kw["max_iterations"] = 0
        return real(problem, z0, **kw)

    monkeypatch.setattr(driver, "damped_newton", first_attempt_fails)
    res = solve_elastic_gap(sc)
    assert res.status == "converged", res.message
    assert "continuation in compliance" in res.message
    assert res.continuation[0][:2] == (1.0, "max_iterations (25x25 nodes)"), \
        "the failed direct attempt comes first"
    assert res.continuation[1][0] == 0.0 and res.continuation[-1][0] == 1.0
    np.testing.assert_allclose(res.pressure, direct.pressure, rtol=0,
                               atol=1e-6 * direct.quantities["p_max"],
                               err_msg="same steady solution by either route (Newton "
                                       "tolerance 1e-8 on scaled rows)")


def test_start_failure_exports_its_summary_and_failed_fields(tmp_path):
    series = solve_elastic_squeeze_series(scene(nodes=25), eps=0.3, n_steps=4,
                                          max_iterations=1)
    assert series.status == "max_iterations" and series.results == []
    assert "step 0" in series.message
    files = bf.io.export_series(series, tmp_path)
    assert set(files) == {"summary", "failed"}, "nothing solved: no time series"
    summary = json.loads(files["summary"].read_text())
    assert summary["status"] == "max_iterations" and summary["success"] is False
    assert summary["instants"] == 0 and "step 0" in summary["message"]
    assert summary["failed_step"] == {"step": 0, "time": 0.0, "gap": pytest.approx(1.3 * H0),
                                      "status": "max_iterations"}, summary["failed_step"]
    assert np.all(np.isfinite(meshio.read(files["failed"]).point_data["film_m"]))


@pytest.mark.parametrize("kwargs, match", [
    ({"eps": -0.1}, r"eps must lie in \[0, 1\).*-0.1"),
    ({"eps": 1.0}, r"eps must lie in \[0, 1\)"),
    ({"eps": float("nan")}, r"eps must lie"),
    ({"omega": 0.0}, r"omega must be .*> 0 rad/s, got 0.0"),
    ({"omega": -5.0}, r"omega .*rad/s"),
    ({"omega": float("inf")}, r"omega .*rad/s"),
    ({"n_steps": 1}, r"n_steps must be an integer >= 2"),
    ({"n_steps": 8.0}, r"n_steps"),
    ({"periods": 0}, r"periods must be an integer >= 1"),
    ({"scheme": "crank-nicolson"}, r"scheme must be one of"),
    ({"t0": float("nan")}, r"t0 must be finite \(s\)"),
    ({"boundary_pressure": np.zeros(3)}, r"boundary_pressure must be a callable"),
])
def test_bad_numbers_rejected(kwargs, match):
    with pytest.raises(ValueError, match=match):
        solve_elastic_squeeze_series(scene(nodes=25), **kwargs)


@pytest.mark.parametrize("sc, match", [
    (scene(elasticity="rigid"), r"model.elasticity = 'half-space'.*got 'rigid'"),
    (scene(load=Load(force=10.0)), r"load.gap \(m\).*load.force = 10.0 N"),
])
def test_bad_scenes_rejected(sc, match):
    with pytest.raises(SceneError, match=match):
        solve_elastic_squeeze_series(sc)
    with pytest.raises(SceneError, match=match):
        solve_elastic_gap(sc)


def test_line_scene_rejected():
    line = Scene(contact=Contact(kind="line", rx=0.01, length=0.01),
                 materials=Materials(reduced_modulus=E_STEEL),
                 lubricant=Lubricant(viscosity=0.01), kinematics=Kinematics(u1=1.0, u2=1.0),
                 load=Load(gap=H0))
    with pytest.raises(SceneError, match="contact.kind = 'point', got 'line'"):
        solve_elastic_squeeze_series(line)


@pytest.mark.slow
def test_elastic_squeeze_study_coarse(tmp_path, load_study):
    mod = load_study("point_elastic_squeeze")
    out = mod.main(tmp_path, nodes=25, n_steps=8, periods=2, slow=False, grid_check=False,
                   rigid_nodes=41, plot=False)
    assert out["status"] == "converged", out["message"]
    h = out["harmonics_last_period"]
    assert h["elastic_transient"]["max_Pa"] < h["rigid_quasi_steady"]["max_Pa"], (
        "elastic deformation relieves the peak pressure at this gap")
    assert out["memory_lag_deg"] > 0.0, "memory delays the elastic response"
    assert out["max_rel_change_period2_vs_period1_second_half"] < 0.01, (
        "the start-up has decayed after half a period (measured 0.05% on 25^2, 8 steps)")
    for key in ("pvd", "xdmf"):
        assert pathlib.Path(out["files"][key]).exists()
    assert (tmp_path / "point_elastic_squeeze.txt").exists()


def test_solve_routes_elastic_gap_scenes_to_the_elastic_solver():
    """bf.solve on a half-space point scene with load.gap is elastic, not rigid."""
    import bearing_fem as bf
    from bearing_fem.contacts.transient import solve_elastic_gap

    sc = scene()  # I-40A ball, 33^2: strongly elastic at the 0.1 um gap
    via_solve = bf.solve(sc)
    direct = solve_elastic_gap(sc)
    assert via_solve.status == direct.status == "converged", via_solve.message
    np.testing.assert_allclose(via_solve.pressure, direct.pressure, rtol=0,
                               atol=1e-9 * np.max(direct.pressure),
                               err_msg="the same elastic gap-controlled solve")
    rigid = bf.solve(scene(elasticity="rigid"))
    assert np.max(via_solve.pressure) < 0.99 * np.max(rigid.pressure), \
        "elastic bodies flatten the pressure peak of the rigid solution"


def test_iteration_budget_applies_to_each_instant_time_limit_to_the_series():
    """A long series is not cut by the default budget of one solve: 3 periods of 64
    BDF2 steps (193 instants, about 550 Newton iterations in all) stopped with
    budget_exhausted after 141 instants when the 400 iterations of solver.iteration_budget
    were shared by the whole series. The wall-clock limit still bounds the whole series."""
    from dataclasses import replace
    from bearing_fem.scene import SolverSpec
    sc = scene(nodes=25, cavitation="reynolds")
    series = solve_elastic_squeeze_series(sc, eps=0.3, n_steps=64, periods=3)
    assert series.status == "converged" and len(series.results) == 193, series.message
    assert series.newton_iterations.sum() > sc.solver.iteration_budget, \
        "the series as a whole needs more than one solve's budget (else the test is void)"
    assert series.newton_iterations.max() <= sc.solver.iteration_budget
    tight = replace(sc, solver=SolverSpec(time_limit=0.05))
    short = solve_elastic_squeeze_series(tight, eps=0.3, n_steps=64, periods=3)
    assert short.status == "time_limit" and len(short.results) < 193, short.message
    assert "whole series" in short.message, short.message


def test_default_gap_domain_says_how_much_load_it_cuts():
    """The default domain of a gap-controlled elastic scene with the Reynolds outlet,
    [-10, 5] x [-10, 10] hydrodynamic lengths, carries about 11 % less load than
    [-30, 8] x [-30, 30]: the pressure of a flooded film decays as r^-3. The result says so
    (it had not), and the rigid self-similar share it quotes agrees with the elastic solves
    (measured: 0.0926 N against 0.1044 N, 11.3 %; the share 10 %)."""
    from bearing_fem.contacts.point import rigid_domain_load_share

    share = rigid_domain_load_share(1.0, (-10.0, 5.0), (-10.0, 10.0))
    assert 0.85 < share < 0.92, share
    fine = rigid_domain_load_share(1.0, (-10.0, 5.0), (-10.0, 10.0), nodes=81)
    np.testing.assert_allclose(share, fine, rtol=0.01,
                               err_msg="the 41^2 estimate within 1 % of 81^2 (0.897/0.890)")
    base = scene(rx=0.005, ry=0.005, e_prime=2.2e11, viscosity=0.01, cavitation="reynolds",
                 nodes=49)
    default = base.replace(load=Load(gap=1.4e-7), mesh=MeshSpec(nodes=(49, 49)))
    res = solve_elastic_gap(default)
    assert res.status == "converged", res.message
    (note,) = [w for w in res.warnings if w.startswith("load (and friction) cut by the domain")]
    assert f"{100 * (1 - share):.2g}% less load" in note and "mesh.x_range" in note
    wide = base.replace(load=Load(gap=1.4e-7),
                        mesh=MeshSpec(nodes=(97, 129), x_range=(-30, 8), y_range=(-30, 30)))
    res_wide = solve_elastic_gap(wide)
    assert res_wide.status == "converged", res_wide.message
    assert not [w for w in res_wide.warnings if "cut by the domain" in w]
    assert res_wide.quantities["load"] > 1.05 * res.quantities["load"], (
        "the wider domain carries more load (49^2 against 97 x 129; measured 11 % on "
        "97^2 against 193 x 257)")
    fs = solve_elastic_gap(default.replace(model=Model(elasticity="half-space",
                                                      cavitation="none")))
    assert not [w for w in fs.warnings if "cut by the domain" in w], (
        "full-Sommerfeld: a rigid film carries no net load, no share to quote")


def test_elastic_squeeze_series_on_the_default_domain_says_once_how_much_load_it_cuts():
    """The series shares the default domain of the steady gap-controlled scene, and its
    loads are cut alike (about 10 % with the Reynolds outlet); the series said nothing (only
    ``solve_elastic_gap`` did). Now its first instant carries the warning, so the series'
    warnings name it once."""
    from bearing_fem.contacts.point import rigid_domain_load_share

    base = scene(rx=0.005, ry=0.005, e_prime=2.2e11, viscosity=0.01, cavitation="reynolds")
    default = base.replace(load=Load(gap=1.4e-7), mesh=MeshSpec(nodes=(33, 33)))
    ser = solve_elastic_squeeze_series(default, eps=0.2, n_steps=4)
    assert ser.success, ser.message
    notes = [w for w in ser.summary()["warnings"] if "cut by the domain" in w]
    share = rigid_domain_load_share(1.0, (-10.0, 5.0), (-10.0, 10.0))
    assert len(notes) == 1 and f"{100 * (1 - share):.2g}% less load" in notes[0], notes
    assert sum("cut by the domain" in w for r in ser.results for w in r.warnings) == 1


def test_rigid_domain_load_share_takes_ranges_as_any_sequence():
    """The share is cached by its arguments: lists or numpy numbers (a scene's ranges read
    from a file) gave TypeError: unhashable type: 'list'."""
    from bearing_fem.contacts.point import rigid_domain_load_share

    ref = rigid_domain_load_share(1.0, (-10.0, 5.0), (-10.0, 10.0))
    assert rigid_domain_load_share(np.float64(1.0), [-10, 5], np.array([-10.0, 10.0])) == ref


def test_rigid_domain_load_share_names_a_bad_argument():
    """A negative ratio failed with 'math domain error', a NaN ratio returned NaN (with a
    singular-matrix warning) and reversed ranges blamed 'grid x'; each is now named."""
    from bearing_fem.contacts.point import rigid_domain_load_share

    with pytest.raises(ValueError, match=r"ratio must be > 0 \(ry/rx"):
        rigid_domain_load_share(-1.0, (-10.0, 5.0), (-10.0, 10.0))
    with pytest.raises(ValueError, match="ratio must be finite"):
        rigid_domain_load_share(float("nan"), (-10.0, 5.0), (-10.0, 10.0))
    with pytest.raises(ValueError, match=r"x_range must be \(low, high\) with low < high"):
        rigid_domain_load_share(1.0, (5.0, -10.0), (-10.0, 10.0))
    with pytest.raises(ValueError, match=r"y_range must be \(low, high\)"):
        rigid_domain_load_share(1.0, (-10.0, 5.0), (-10.0, 10.0, 20.0))
    with pytest.raises(ValueError, match="nodes must be an integer >= 3"):
        rigid_domain_load_share(1.0, (-10.0, 5.0), (-10.0, 10.0), nodes=2)

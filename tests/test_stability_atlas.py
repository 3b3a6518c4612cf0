"""The stability atlas study (quick mode) and the line grid-sequence fix it led to."""
from __future__ import annotations

import csv
import math

import numpy as np

import bearing_fem as bf
from bearing_fem.contacts.line import COARSEST_NODES, MAX_COARSENINGS, line_levels

#: Statuses a solve may end with (the Result contract), plus the atlas' own outcome for a
#: scene its builder could not make.
KNOWN = {"converged", "linear", "no_solution", "max_iterations", "stalled", "diverged",
         "budget_exhausted", "time_limit", "error", "invalid_scene"}


def test_stability_atlas_quick_and_resume(tmp_path, load_study):
    mod = load_study("stability_atlas")
    res = mod.main(tmp_path, quick=True, workers=2)
    recs = res["records"]
    families = {r["family"] for r in recs}
    assert families == {"line_map", "point_map", "ellipse", "high_pressure", "near_rigid",
                        "light_load", "low_speed", "rigid_limit"}, "every family in quick mode"
    assert res["solved_now"] == len({r["hash"] for r in recs if "hash" in r})
    for r in recs:
        assert r["status"] in KNOWN, (r["family"], r["status"])
        assert r["message"], f"every case has a message ({r['family']}, {r['status']})"
        assert r["non_finite"] == [], f"NaN/inf in the summary of {r['family']}: {r['non_finite']}"
        if r["status"] not in ("invalid_scene",):
            assert r["summary_checked"], "the summary file of every run was read and checked"
            assert r["newton_iterations"] is not None and r["wall_time_s"] is not None
    summ = res["summary"]
    assert summ["non_finite"] == []
    assert summ["line_map"]["rate"] == 1.0 and summ["point_map"]["rate"] == 1.0, \
        "the quick map cases (alpha p_h <= 100 and one beyond) all converge"
    rigid = [r for r in recs if r["family"] == "rigid_limit"]
    assert {r["status"] for r in rigid if r["ratio"] > 1} == {"no_solution"}, \
        "beyond the closed-form existence limit the solver says so"
    assert all(r["success"] for r in rigid if r["ratio"] < 1)
    for r in recs:   # every failure is explained: an unsuccessful status and its message
        if not r["ok"]:
            assert r["status"] not in ("converged", "linear") and len(r["message"]) > 20
    with open(tmp_path / "stability_atlas.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == len(recs)
    for row in rows:
        cells = [v.lower() for k, v in row.items() if k != "message"]
        assert not {"nan", "inf", "-inf"} & set(cells), f"no NaN/inf numbers in the table: {row}"
    md = (tmp_path / "stability_atlas.md").read_text()
    for r in recs:
        if not r["ok"]:
            assert r["status"] in md
    for name in res["figures"]:
        assert (tmp_path / name).stat().st_size > 1000
    again = mod.main(tmp_path, quick=True, workers=2)
    assert again["solved_now"] == 0, "a second run resumes from the store and solves nothing"
    assert [r["status"] for r in again["records"]] == [r["status"] for r in recs]


def test_line_levels_stop_two_halvings_below_the_grid():
    two = MAX_COARSENINGS
    assert line_levels(4001, max_coarsenings=two) == [1001, 2001, 4001], \
        "capped high-M grid: coarsest 1001"
    assert line_levels(4001) == [251, 501, 1001, 2001, 4001], "no limit: down to 251 nodes"
    assert line_levels(3601, max_coarsenings=two) == [901, 1801, 3601]
    assert line_levels(3601) == [226, 451, 901, 1801, 3601], "a level needs (N - 1)/2 integer"
    assert line_levels(2001, max_coarsenings=two) == [501, 1001, 2001]
    assert line_levels(801, max_coarsenings=two) == [201, 401, 801]
    assert line_levels(301) == [301], "no level below COARSEST_NODES"
    assert MAX_COARSENINGS == 2 and COARSEST_NODES == 201


def test_high_load_line_converges_on_the_default_grid(load_study):
    # M = 1874, L = 0 stalled in every continuation step when the sequence started on 501
    # nodes of the capped 4001-node grid (83 nodes per Hertz half-width)
    mod = load_study("stability_atlas")
    r = bf.solve(mod.line_scene(1874.0, 0.0))
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 40, "three levels, no continuation (measured 16)"
    assert math.isfinite(r.summary()["h_central"])


def test_barus_line_where_the_film_coefficient_underflows(load_study):
    """alpha p_h = 698 (accepted input): exp(-alpha p) underflows to 0 at the pressure
    spike, so eps = 0 and the cell Peclet number is infinite. Its film derivative
    xi'(Pe) dPe/dh must take its limit 0 there, not 0 * inf = NaN, which made every
    Jacobian non-finite (stalled after 161 Newton iterations; converges in 14)."""
    mod = load_study("stability_atlas")
    r = bf.solve(mod.line_scene(1e4, 17.5))
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 30, "three levels, no continuation (measured 14)"
    s = r.summary()
    assert all(math.isfinite(s[k]) for k in ("h_central", "h_min", "p_max")), s


def test_barus_line_beyond_the_double_precision_viscosity(load_study):
    """alpha p_h = 997 (Moes M = 1e4, L = 25): exp(alpha p) overflows, the reduced-pressure
    film equation does not. The scene is accepted and converges; nothing in the summary or
    the fields is NaN/inf; the clipped viscosity field and a traction that grows without
    bound with the viscosity are said in warnings."""
    import warnings

    from bearing_fem.contacts.line import solve_line

    mod = load_study("stability_atlas")
    scene = mod.line_scene(1e4, 25.0, srr=0.5)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = solve_line(scene)   # the module-level solver: no numpy overflow warnings either
    assert not [w for w in caught if issubclass(w.category, RuntimeWarning)], \
        [str(w.message) for w in caught]
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 40, "three levels, no continuation (measured 16)"
    s = r.summary()
    assert mod._non_finite(s) == [], mod._non_finite(s)
    assert 0.002 < s["friction_coefficient"] < 0.15, "eyring-limiting: a physical friction"
    eta = r.extra_fields["viscosity_Pa_s"]
    assert np.all(np.isfinite(eta)) and eta.max() == np.finfo(float).max
    assert any("viscosity overflows double precision" in w and "Barus" in w
               and "reduced pressure, is not affected" in w for w in r.warnings), r.warnings
    d = scene.to_dict()
    d["traction"] = {"model": "newtonian"}
    newt = bf.solve(bf.Scene.from_dict(d))
    s = newt.summary()
    assert newt.success and s["friction_force"] is None and s["heat_power"] is None
    assert mod._non_finite(s) == [], "undefined numbers are None, never inf/NaN"
    assert any("friction_force and heat_power undefined" in w for w in newt.warnings)


def test_light_point_load_starts_from_a_finite_guess(load_study):
    # M = 0.3 on 97^2: the default domain is about 320 Hertz radii long (8 hydrodynamic
    # lengths), 3.3 Hertz radii per cell; the Hertzian start fell between the nodes, its
    # integral was 0 and every attempt "diverged" at iteration 0 with residual NaN
    mod = load_study("stability_atlas")
    for L in (0.0, 5.0):
        r = bf.solve(mod.point_scene(0.3, L))
        assert r.status == "converged", r.message
        assert r.newton_iterations <= 30, "measured 14"
        assert math.isfinite(r.summary()["h_central"])


def test_isoviscous_high_load_point_continues_in_speed(load_study):
    # M = 1160, L = 0 on 97^2 stalled from the Hertzian start and had no continuation
    # path (alpha = 0); it now continues in the entrainment speed, as line contacts do
    # (on the wide domain it had then; the default domain is now narrower, below)
    import dataclasses

    from bearing_fem.contacts.point import ELASTIC_RANGE

    mod = load_study("stability_atlas")
    scene = mod.point_scene(1160.0, 0.0)
    scene = dataclasses.replace(scene, mesh=dataclasses.replace(
        scene.mesh, x_range=ELASTIC_RANGE[0], y_range=ELASTIC_RANGE[1]))
    r = bf.solve(scene)
    assert r.status == "converged", r.message
    assert "continuation in speed" in r.message
    assert r.newton_iterations <= 150, "measured 81 (4 continuation steps)"


def test_high_load_point_contacts_converge(load_study):
    # M = 2000 on the default domain: L = 0 stalled on 97^2 and 129^2 (11-16 nodes per
    # Hertz radius), L = 3.57 stalled on its 65^2 level; isoviscous scenes above
    # HIGH_LOAD_MOES_M now take the narrow domain, and a grid sequence whose coarsest
    # level fails starts again one level finer
    from bearing_fem.contacts.point import (ISOVISCOUS_HIGH_LOAD_INLET,
                                            ISOVISCOUS_HIGH_LOAD_OUTLET, PointModel)

    mod = load_study("stability_atlas")
    iso = mod.point_scene(2000.0, 0.0)
    setup = PointModel(iso).setup
    x = setup.grid.x / setup.x_unit
    np.testing.assert_allclose(x[-1], ISOVISCOUS_HIGH_LOAD_OUTLET, rtol=1e-12,
                               err_msg="narrow default domain: outlet end [Hertz radii]")
    # the inlet end: 1.5 radii, or 8 hydrodynamic lengths beyond the Hertz edge (here
    # 0.735 radii: -1.735), instead of -4.5
    assert -2.0 < x[0] <= -ISOVISCOUS_HIGH_LOAD_INLET, x[0]
    r = bf.solve(iso)
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 100, "measured 51"
    piezo = mod.point_scene(2000.0, 25 / 7, nodes=129)
    events = []
    r = bf.solve(piezo, progress=events.append)
    assert [e["grid"] for e in events if e["event"] == "level"] == \
        ["65x65 nodes", "129x129 nodes"], "65^2 failed, 129^2 from the Hertzian start"
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 80, "measured 20 on 65^2 (stalled) + 14 on 129^2"
    s = r.summary()
    assert 0.0 < s["h_min"] <= s["h_central"]
    # one level and no coarser grid that converges: no error estimate, and a warning
    assert any(w.startswith("no error estimate") for w in s["warnings"]), s["warnings"]


def test_light_line_load_starts_from_a_finite_guess(load_study):
    # M = 0.01: the default domain is so long against the Hertz half-width that the
    # Hertzian start fell between the 501 nodes of the first level (NaN residual, status
    # "diverged" at iteration 0)
    mod = load_study("stability_atlas")
    r = bf.solve(mod.line_scene(0.01, 5.0))
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 60, "measured 26"


def test_isoviscous_line_at_the_node_cap_converges_on_a_narrow_domain(load_study):
    # L = 0, M = 4329 and 1e4: on the default [-4.5, 1.5] b domain the capped 4001-node
    # grid gave 667 nodes per Hertz half-width and Newton never converged (budget of 400
    # iterations spent / stalled after 140); isoviscous scenes at the cap now use
    # [-1.5, 1.2] b, where the inlet pressure still builds up well inside the domain
    from bearing_fem.contacts.line import (ISOVISCOUS_CAPPED_INLET, ISOVISCOUS_CAPPED_OUTLET,
                                           line_setup)
    from bearing_fem.formulas import line_central_film_moes

    mod = load_study("stability_atlas")
    for M in (4329.0, 1e4):
        scene = mod.line_scene(M, 0.0)
        setup = line_setup(scene)
        x = setup.disc.x / setup.x_unit
        np.testing.assert_allclose([x[0], x[-1]], [-ISOVISCOUS_CAPPED_INLET,
                                                   ISOVISCOUS_CAPPED_OUTLET], rtol=1e-12,
                                   err_msg=f"M = {M}: narrowed default domain [b]")
        r = bf.solve(scene)
        assert r.status == "converged", r.message
        assert r.newton_iterations <= 90, "measured 41 (M = 4329) and 45 (M = 1e4)"
        s = r.summary()
        lub, c = scene.lubricant, scene.contact
        moes = line_central_film_moes(scene.load.force, c.rx, scene.e_prime, lub.viscosity,
                                      scene.kinematics.mean_speed, 0.0)
        np.testing.assert_allclose(s["h_central"], moes, rtol=0.15,
                                   err_msg=f"M = {M}: central film against Moes' fit "
                                           "(measured -5.4 % and -5.7 %; the fit's IE "
                                           "asymptote is itself a fit)")
        assert 0.0 < s["h_min"] <= s["h_central"]
    # a piezo-viscous scene at the cap keeps the wide domain
    setup = line_setup(mod.line_scene(1e4, 3.571))
    assert setup.disc.x[0] / setup.x_unit <= -4.5 + 1e-9


def test_failed_single_grid_starts_from_a_finer_solution(load_study):
    # circular M = 2000, L = 25 on the atlas' 97^2 grid (one level: it cannot be halved to
    # 65^2 or more) runs out of iterations from the Hertzian start (residual ~1e-4). The
    # driver then solves 193^2 and starts 97^2 from that solution restricted to it.
    # (L = 3.57 took this path too on one machine and converged directly on another: a
    # knife edge, not a test case.)
    mod = load_study("stability_atlas")
    events = []
    r = bf.solve(mod.point_scene(2000.0000000000002, 25.0), progress=events.append)
    assert r.status == "converged", r.message
    assert [e["grid"] for e in events if e["event"] == "level"] == \
        ["97x97 nodes", "193x193 nodes", "97x97 nodes"]
    assert "started from the solution on 193x193 nodes" in r.message
    assert r.newton_iterations <= 150, "measured 100 on two machines"
    s = r.summary()
    assert r.pressure.shape == (97, 97), "the result is on the requested grid"
    assert 0.0 < s["h_min"] <= s["h_central"]


def test_failed_finer_grid_leaves_the_requested_grid(load_study):
    # the low-speed ball (M = 1.5e5 on 97^2) fails on 97^2 and on 193^2: the result is
    # the last iterate on the requested grid, with the status of that grid's attempt
    mod = load_study("stability_atlas")
    case = next(c for c in mod.atlas_cases() if c["family"] == "low_speed"
                and c["kind"] == "point")
    events = []
    r = bf.solve(case["builder"](), progress=events.append)
    assert not r.success
    assert r.status == "stalled", r.message
    grids = [e["grid"] for e in events if e["event"] == "level"]
    assert grids[:2] == ["97x97 nodes", "193x193 nodes"], grids
    assert "was tried too" in r.message, "then the high-load second solve, which fails too"
    assert f"({r.newton_iterations} in all)" in r.message, \
        "the message ends with the iteration count the exit-3 line and the summary give"
    assert r.pressure.shape == (97, 97), "the requested grid, not the finer one"
    assert np.all(np.isfinite(r.pressure)) and np.all(np.isfinite(r.film))


def _slow_ball(u_m: float, **mesh) -> bf.Scene:
    """A 100 N steel ball (rx = ry = 10 mm) in a thin oil (0.01 Pa s, alpha = 2e-8 1/Pa);
    at u_m = 0.1 m/s Moes M is about 4.9e3, L 4.3: beyond the checked circular map."""
    return bf.Scene.from_dict({
        "contact": {"kind": "point", "rx": 0.01, "ry": 0.01},
        "materials": {"reduced_modulus": 2.2e11},
        "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
        "kinematics": {"u1": u_m, "u2": u_m}, "load": {"force": 100.0},
        "mesh": {"nodes": [97, 97]} | mesh})


def test_point_result_on_the_finer_grid_when_the_requested_grid_fails_from_it():
    """97^2 fails from the Hertzian start and again from the converged 193^2 solution:
    the result is that 193^2 solution, said in the message and the warnings."""
    res = bf.solve(_slow_ball(0.1))
    assert res.success, res.message
    assert res.pressure.shape == (193, 193), "the result holds the finer grid's fields"
    assert "the result is that solution on 193x193 nodes, not one on the requested 97x97 " \
        "nodes" in res.message, res.message
    assert "failed too" not in res.message, "the finer grid converged: no 'failed too'"
    assert any("requested grid (97x97 nodes) has no converged solution" in w
               for w in res.warnings), res.warnings
    assert res.quantities["h_min"] > 0 and np.all(np.isfinite(res.pressure))


def test_point_above_the_checked_map_is_solved_on_the_narrower_domain():
    """M ~ 8.2e3 (a 100 N ball at 0.05 m/s): the default 97^2 solve and its finer-grid
    fallback stall; the second solve on the narrower domain with 257^2 converges, and
    the result says where it was solved and what that costs."""
    from bearing_fem.contacts.point import (CHECKED_MOES_M, HIGH_LOAD_NODES,
                                            HIGH_LOAD_RANGES, high_load_scene)

    res = bf.solve(_slow_ball(0.05))
    assert res.success, res.message
    n = HIGH_LOAD_NODES
    assert res.pressure.shape == (n, n), "the fields are those of the second solve"
    (x0, x1), (y0, y1) = HIGH_LOAD_RANGES
    assert res.scene.mesh.x_range == (x0, x1) and res.scene.mesh.y_range == (y0, y1), \
        "the result's scene is the one solved (an export reproduces it)"
    assert "the default domain failed first" in res.message, res.message
    assert f"; {res.newton_iterations} in all)" in res.message, res.message
    assert any("narrower domain" in w and "starve" in w for w in res.warnings), res.warnings
    assert res.quantities["h_min"] < 5e-9 and any("molecular" in w for w in res.warnings), \
        "a film of a few nm is flagged: the continuum model is doubtful there"
    assert res.newton_iterations <= _slow_ball(0.05).solver.iteration_budget, \
        "both solves share one iteration budget"
    # where it applies, and the budget it gets
    assert high_load_scene(_slow_ball(1.0)) is None, f"M ~ 870 <= {CHECKED_MOES_M:g}"
    assert high_load_scene(_slow_ball(0.05, x_range=[-3.0, 1.2])) is None, \
        "a user's own domain is not replaced"
    left = high_load_scene(_slow_ball(0.05), spent_iterations=150).solver.iteration_budget
    assert left == _slow_ball(0.05).solver.iteration_budget - 150
    assert high_load_scene(_slow_ball(0.05), spent_iterations=10_000) is None, \
        "no budget left: no second solve"


def test_point_far_above_the_checked_map_fails_saying_what_was_tried():
    res = bf.solve(_slow_ball(0.001))   # M ~ 1.5e5
    assert not res.success
    assert "the narrower domain x in [-2.5, 1.2] a_x" in res.message, res.message
    assert res.pressure.shape == (97, 97), "a failure stays on the requested grid"
    assert res.newton_iterations <= _slow_ball(0.001).solver.iteration_budget


def test_status_message_counts_continuation_steps_in_words():
    """'continuation in alpha (1 step)', not '(1 steps)' (outcome_text, every solve's
    message)."""
    from types import SimpleNamespace

    from bearing_fem.contacts.driver import DriverOutcome, outcome_text

    solver = SimpleNamespace(tolerance=1e-8, max_iterations=50)
    for n, want in ((1, "(1 step)"), (3, "(3 steps)")):
        out = DriverOutcome(z=np.zeros(1), problem=None, status="converged", iterations=9,
                            labels=["65x65 nodes"], continuation_steps=n)
        text = outcome_text(out, 1e-10, solver, budget=None, parameter="alpha")
        assert f"continuation in alpha {want}" in text, text

"""Graded line grids (``mesh.file`` with non-uniform nodes) and their study."""
from __future__ import annotations

import numpy as np


def rows_auto(folder):
    import json

    return json.loads((folder / "summary.json").read_text())["auto"]


def test_graded_grid_study_quick(load_study, tmp_path):
    mod = load_study("line_graded_grid")
    rows = mod.main(tmp_path, quick=True)["rows"]
    assert all(r["status"] == "converged" for r in rows), [r["status"] for r in rows]
    by = {(r["grid"], r["nodes"]): r for r in rows}
    for n in (401, 801):
        uni, gra = by[("uniform", n)], by[("graded", n)]
        assert gra["h_min_error"] < uni["h_min_error"], \
            f"{n} nodes: graded h_min closer to the reference (measured 8e-4 vs 2.7e-3 on " \
            "401, 1e-6 vs 7e-3 on 801)"
        assert gra["friction_force_error"] < 0.5 * uni["friction_force_error"], \
            f"{n} nodes: graded friction (measured 4.5e-3 vs 3.3e-2, 1.1e-3 vs 1.2e-2)"
        assert gra["h_central_error"] < 5e-3, "h_central within 0.5 % (measured 3.7e-3 on 401)"
        assert gra["estimate_h_min"] is not None, "nested levels: the error estimate exists"
    (auto,) = rows_auto(tmp_path)
    assert auto["graded_status"] == "converged" and auto["uniform_status"] == "converged"
    assert auto["h_min_graded_change"] < 0.1 * auto["h_min_uniform_error"], \
        "mesh.grading = 'outlet' at M = 100, L = 10, 801 nodes: h_min (measured 3.6e-5 " \
        "vs 7.2e-3)"
    assert auto["friction_force_graded_change"] < 0.2 * auto["friction_force_uniform_error"], \
        "friction (measured 6.5e-4 vs 1.1e-2)"
    for name in ("runs.csv", "auto.csv", "line_graded_grid.md", "summary.json",
                 "line_graded_grid.png"):
        assert (tmp_path / name).stat().st_size > 100


def test_a_repeated_node_in_a_line_grid_file_is_refused(tmp_path):
    import numpy as np
    import pytest
    from skfem import MeshLine

    import bearing_fem as bf
    from bearing_fem.errors import SceneError
    from bearing_fem.mesh import write_mesh

    x = np.linspace(-4.5, 1.5, 401)
    x[200] = x[199]
    path = write_mesh(MeshLine(x), tmp_path / "dup.vtu")
    for model, load in (({}, {"force": 2e5}), ({"elasticity": "rigid"}, {"gap": 1e-6}),
                        ({"elasticity": "local"}, {"force": 2e5})):
        scene = bf.Scene.from_dict({
            "contact": {"kind": "line", "rx": 0.01}, "materials": {"reduced_modulus": 2.2e11},
            "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
            "kinematics": {"u1": 1.0, "u2": 1.0}, "load": load, "model": model,
            "mesh": {"file": str(path)}})
        with pytest.raises(SceneError, match=r"mesh.file .*dup.vtu': the nodes must be "
                                             r"distinct; x = .* appears 2 times") as err:
            bf.solve(scene)
        assert "np.float64" not in str(err.value), \
            f"the value as a number, not a numpy repr: {err.value}"


def test_rigid_barus_line_beyond_its_load_limit_is_no_solution():
    """Kapitsa: a rigid piezo-viscous cylinder carries a finite load. Beyond it Newton
    'converged' to a one-node spike (p_max 47.7 GPa, alpha p = 954) and reported success;
    then it ended no_solution after 330 Newton iterations (12 s). Now a load above the
    margin times the closed-form limit ends before any Newton iteration."""
    import bearing_fem as bf
    from bearing_fem import analytic
    from bearing_fem.contacts.line import RIGID_BARUS_LOAD_MARGIN

    def scene(force):
        return bf.Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                                   "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
                                   "kinematics": {"u1": 1.0, "u2": 1.0},
                                   "load": {"force": force}, "model": {"elasticity": "rigid"}})

    ok = bf.solve(scene(1e4))
    assert ok.status == "converged" and 2e-8 * ok.quantities["p_max"] < 3.0, \
        "below the limit: a resolved solution (alpha p_max 2.1)"
    limit, h_limit = analytic.martin_barus_load_limit(0.01, 0.05, 1.0, 2e-8)
    assert 1e5 > RIGID_BARUS_LOAD_MARGIN * limit, "the case lies beyond the margin"
    over = bf.solve(scene(1e5))
    assert over.status == "no_solution" and not over.success, over.message
    assert over.newton_iterations == 0 and over.linear_solves >= 1, over.message
    assert "exceeds what the rigid Barus contact can carry" in over.message
    assert f"{limit:.4g} N/m" in over.message and "no Newton iteration" in over.message
    # the documented no_solution field: the reduced pressure q at 0.95 h0*; Martin's q is
    # self-similar on the default domain (which scales with sqrt(h0)), q_max ~ h0^(-3/2)
    np.testing.assert_allclose(2e-8 * over.pressure.max(), 0.95 ** -1.5, rtol=2e-3,
                               err_msg="no_solution holds the reduced pressure q at 0.95 h0*")
    s = over.summary()
    assert s["error_estimate"] is None and "p_max" not in s, "no film numbers"


def test_converged_spike_beyond_the_resolvable_pressure_is_no_solution():
    """A converged rigid Barus load solve whose peak lies beyond alpha p = 36 (where q
    equals 1/alpha to double precision) is no solution, its field the reduced pressure."""
    import dataclasses

    import bearing_fem as bf
    from bearing_fem.contacts.line import (RIGID_BARUS_RESOLVABLE_ALPHA_P,
                                           rigid_barus_beyond_limit)

    ok = bf.solve(bf.Scene.from_dict({
        "contact": {"kind": "line", "rx": 0.01},
        "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
        "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"force": 1e4},
        "model": {"elasticity": "rigid"}, "mesh": {"nodes": 201}}))
    assert ok.success and rigid_barus_beyond_limit(ok) is ok, "a resolved peak stays"
    spike = ok.pressure.copy()
    spike[np.argmax(spike)] = 1.5 * RIGID_BARUS_RESOLVABLE_ALPHA_P / 2e-8
    out = rigid_barus_beyond_limit(dataclasses.replace(ok, pressure=spike))
    assert out.status == "no_solution" and not out.success and not out.quantities
    assert f"alpha p = {1.5 * RIGID_BARUS_RESOLVABLE_ALPHA_P:.4g}" in out.message, out.message
    np.testing.assert_allclose(2e-8 * out.pressure.max(), 1.0, rtol=1e-12,
                               err_msg="q = (1 - exp(-alpha p))/alpha is 1/alpha there")


def test_failed_rigid_barus_line_above_the_load_limit_is_no_solution():
    """A rigid Barus roller at a realistic load (1e5 N/m, 5 m/s) cannot exist: the
    largest load of the contact is 21.5 kN/m (checked here against Martin's film). Newton
    once ran out of its budget and said 'budget_exhausted'; the solve now ends, naming
    the limit, before any Newton iteration, and half the limit still converges."""
    import bearing_fem as bf
    from bearing_fem import analytic

    limit, h_limit = analytic.martin_barus_load_limit(0.008, 0.04, 5.0, 2e-8)
    np.testing.assert_allclose(
        analytic.martin_existence_ratio(h_limit, 0.008, 0.04, 5.0, piezo=2e-8), 1.0,
        rtol=1e-12, err_msg="the limit lies where alpha q_max = 1")
    x = np.linspace(-3e-3, 3e-4, 600001)     # +-100 sqrt(2 R h0): the whole film
    below = np.trapezoid(analytic.martin_pressure(x, 1.001 * h_limit, 0.008, 0.04, 5.0,
                                                  2e-8), x)
    assert 0.9 * limit < below < limit, f"the load rises to the limit: {below}, {limit}"
    scene = bf.Scene.from_dict({
        "contact": {"kind": "line", "rx": 0.008},
        "lubricant": {"viscosity": 0.04, "piezo": 2e-8},
        "kinematics": {"u1": 5.0, "u2": 5.0}, "load": {"force": 1e5},
        "model": {"elasticity": "rigid"}, "solver": {"iteration_budget": 40}})
    r = bf.solve(scene)
    assert r.status == "no_solution" and not r.success, r.message
    assert f"{limit:.4g} N/m" in r.message and r.newton_iterations == 0, r.message
    ok = bf.solve(bf.Scene.from_dict(dict(scene.to_dict(), load={"force": 0.5 * limit})))
    assert ok.status == "converged", ok.message



def test_converged_rigid_barus_line_above_the_load_limit_is_no_solution():
    """1.3 times the largest load of the rigid Barus roller 'converged' on 401 nodes (alpha
    p_max 14, h0 at the limit gap): the grid carried the excess on a one-element pressure
    spike. No solution exists (a finite domain carries less than the limit), so the
    status says so, whatever the grid, before any Newton iteration."""
    import bearing_fem as bf
    from bearing_fem import analytic

    limit, _ = analytic.martin_barus_load_limit(0.008, 0.04, 5.0, 2e-8)
    scene = bf.Scene.from_dict({
        "contact": {"kind": "line", "rx": 0.008},
        "lubricant": {"viscosity": 0.04, "piezo": 2e-8},
        "kinematics": {"u1": 5.0, "u2": 5.0}, "load": {"force": 1.3 * limit},
        "model": {"elasticity": "rigid"}, "mesh": {"nodes": 401}})
    r = bf.solve(scene)
    assert r.status == "no_solution" and not r.success, (r.status, r.message)
    assert f"{limit:.4g} N/m" in r.message and r.newton_iterations == 0, r.message
    assert r.x.size == 401, "the fields are on the scene's grid"
    # just above the limit on the default grid: 1.02 and 1.05 times it converged there
    # (alpha p_max 16 and 21) while the refusal waited for 1.1 times it
    for factor in (1.02, 1.05):
        over = bf.solve(bf.Scene.from_dict({**scene.to_dict(), "mesh": {},
                                            "load": {"force": factor * limit}}))
        assert over.status == "no_solution" and over.newton_iterations == 0, \
            (factor, over.status, over.message)


def _moes_line(mesh=None, **over):
    """The Moes M = 100, L = 10 line contact of the studies."""
    import bearing_fem as bf
    from bearing_fem import units

    par = units.line_scene_from_moes(100.0, 10.0)
    d = {"contact": {"kind": "line", "rx": par["radius"]},
         "materials": {"reduced_modulus": par["e_prime"]},
         "lubricant": {"viscosity": par["viscosity"], "piezo": par["piezo"]},
         "kinematics": {"u1": par["mean_speed"], "u2": par["mean_speed"]},
         "load": {"force": par["load_per_length"]}}
    d.update(over)
    if mesh is not None:
        d["mesh"] = mesh
    return bf.Scene.from_dict(d)


def test_outlet_grading_locates_the_spike_and_refines_there():
    """mesh.grading = 'outlet': the uniform and the graded solve on the same node count;
    the graded one has its finest spacing at the smallest film, a far smaller h_min and
    friction error estimate, and the same films to the uniform grid's accuracy."""
    import numpy as np

    import bearing_fem as bf

    uni = bf.solve(_moes_line())
    gra = bf.solve(_moes_line({"grading": "outlet"}))
    assert uni.success and gra.success, (uni.message, gra.message)
    assert gra.x.size == uni.x.size, "same node count as the default uniform grid"
    steps = np.diff(gra.x)
    x_fine = gra.x[np.argmin(steps)]
    x_hmin = gra.x[np.argmin(gra.film)]
    b = (x_hmin - x_fine)  # distance between the refinement centre and the minimum film
    assert abs(b) < 0.02 * gra.x[-1], \
        f"refined where the film is smallest (centre {x_fine:.3e} m, h_min at {x_hmin:.3e} m)"
    assert steps.max() / steps.min() > 5, "graded (density ratio 9)"
    assert "grid refined at the outlet spike" in gra.message
    import re

    located = int(re.search(r"located at x = \S+ b in (\d+) Newton", gra.message).group(1))
    assert located == sum(its for _, st, its in gra.continuation if "spike locator" in st) > 0
    assert gra.newton_iterations == sum(its for *_, its in gra.continuation), \
        "the locator's iterations are counted with the graded solve's"
    eu, eg = uni.error_estimate, gra.error_estimate
    assert eg["h_min"] < 0.1 * eu["h_min"], \
        f"h_min estimate {eg['h_min']:.2e} vs uniform {eu['h_min']:.2e} (measured 3e-6 vs 2e-3)"
    assert eg["friction_force"] < 0.2 * eu["friction_force"], \
        "friction estimate (measured 2.3e-4 vs 8.4e-3)"
    for k in ("h_central", "h_min", "friction_force"):
        np.testing.assert_allclose(gra.quantities[k], uni.quantities[k],
                                   rtol=3 * eu[k] + 1e-4,
                                   err_msg=f"{k}: graded and uniform agree within the "
                                           "uniform grid's estimated error")


def test_outlet_grading_is_refused_where_it_has_no_meaning(tmp_path):
    import pytest
    from skfem import MeshLine

    from bearing_fem.errors import SceneError
    from bearing_fem.mesh import outlet_graded_nodes, write_mesh

    with pytest.raises(SceneError, match=r"mesh.grading must be one of 'uniform', "
                                         r"'outlet', got 'graded'"):
        _moes_line({"grading": "graded"})
    with pytest.raises(SceneError, match=r"mesh.grading = 'outlet' .* model.elasticity = "
                                         r"'rigid'"):
        _moes_line({"grading": "outlet"}, model={"elasticity": "rigid"})
    with pytest.raises(SceneError, match=r"contact.kind = 'point'"):
        _moes_line({"grading": "outlet"}, contact={"kind": "point", "rx": 0.01,
                                                   "ry": 0.01})
    path = write_mesh(MeshLine(outlet_graded_nodes(401)), tmp_path / "g.vtu")
    with pytest.raises(SceneError, match=r"mesh.file replaces mesh.grading"):
        _moes_line({"grading": "outlet", "file": str(path)})
    assert _moes_line({"grading": "uniform"}) == _moes_line(), \
        "'uniform' is the default: the same scene (and hash) as no grading"
    with pytest.raises(SceneError, match=r"mesh.grading = 'outlet' is not available with "
                                         r"model.thermal = 'patch'"):
        _moes_line({"grading": "outlet"}, model={"thermal": "patch"},
                   thermal={"oil_temperature": 60.0, "exponent": 3.0})


def test_outlet_grading_budget_fallback_and_history():
    """The locator's iterations count against the scene's budget (a budget the locator
    spends ends before the graded grid; the graded solve's budget message names the
    scene's); a graded grid that fails falls back to the uniform grid with a warning;
    history and continuation include the locator's iterations."""
    import bearing_fem as bf

    ok = bf.solve(_moes_line({"grading": "outlet"}))
    assert ok.success and len(ok.history) >= ok.newton_iterations, \
        "every accepted Newton step's residual, locator included"
    assert sum(its for _, _, its in ok.continuation) == ok.newton_iterations
    assert any("spike locator" in st for _, st, _ in ok.continuation)
    spent = bf.solve(_moes_line({"grading": "outlet"}, solver={"iteration_budget": 12}))
    assert spent.status == "budget_exhausted" and spent.newton_iterations <= 12, spent.message
    short = bf.solve(_moes_line({"grading": "outlet"}, solver={"iteration_budget": 20}))
    assert short.status == "budget_exhausted" and short.newton_iterations <= 20
    assert "the scene's budget is 20 Newton iterations" in short.message, short.message
    # 1801 nodes (8 iterations are too few for the graded grid there; the default 801
    # converges within them)
    hard = bf.solve(_moes_line({"grading": "outlet", "nodes": 1801},
                               solver={"max_iterations": 8, "continuation": False}))
    assert hard.success, hard.message
    assert hard.newton_iterations == sum(its for *_, its in hard.continuation), \
        "the failed graded attempt's iterations are recorded and counted"
    assert "the graded grid failed" in hard.message
    for budget in (40, 50):  # the fallback overran the budget (59 iterations)
        capped = bf.solve(_moes_line({"grading": "outlet", "nodes": 1801}, solver={
            "max_iterations": 8, "continuation": False, "iteration_budget": budget}))
        assert capped.newton_iterations <= budget, (budget, capped.newton_iterations)
    assert any(w.startswith("mesh.grading = 'outlet': the graded grid failed")
               for w in hard.warnings), hard.warnings
    import numpy as np

    steps = np.diff(hard.x)
    assert steps.max() / steps.min() < 1.0 + 1e-6, "the fallback result is on the uniform grid"


def test_outlet_grading_locator_uses_the_end_pressures():
    """With a high inlet pressure the constriction moves upstream (0.89 b instead of
    0.975 b): the locator solved with zero end pressures refined the wrong place and took
    230 Newton iterations (or fell back to the uniform grid)."""
    import numpy as np

    import bearing_fem as bf

    bp = (1e8, 0.0)
    uni = bf.solve(_moes_line(), boundary_pressure=bp)
    gra = bf.solve(_moes_line({"grading": "outlet"}), boundary_pressure=bp)
    assert gra.success and not any("graded grid failed" in w for w in gra.warnings)
    steps = np.diff(gra.x)
    x_fine = gra.x[np.argmin(steps)]
    x_hmin = uni.x[np.argmin(uni.film)]
    assert abs(x_fine - x_hmin) < 0.02 * (gra.x[-1] - gra.x[0]), (x_fine, x_hmin)
    assert gra.newton_iterations < 80, f"{gra.newton_iterations} (was 230)"


def test_graded_grid_study_row_of_a_failed_outlet_solve(load_study):
    """Isoviscous M = 1000 (the narrow default domain [-1.5, 1.2] b, 3041 nodes): the
    outlet-graded solve converges (its spike locator runs on the scene's own grid, capped
    at 2001 nodes; on 401 nodes it spent the 400-iteration budget). A row whose
    outlet-graded solve fails gives the default node count (not the grid of the failed
    spike locator) and says which solve did not converge."""
    from bearing_fem.contacts.line import line_setup

    mod = load_study("line_graded_grid")
    row = mod.auto_case(1000.0, 0.0)
    default = int(line_setup(mod.scene_for(1000.0, 0.0)).disc.x.size)
    assert row["nodes"] == default, (row["nodes"], default)
    assert row["graded_status"] == "converged", row["graded_status"]
    failed = dict(row, graded_status="budget_exhausted")
    table = mod.auto_markdown([failed])
    assert "M = 1000, L = 0: uniform converged, outlet budget_exhausted" in table, table


def test_locator_nodes_nest_for_any_scene_node_count():
    """Above M = 250 the spike locator takes the scene's own node count; a ``mesh.nodes``
    of 1000 gave a 1000-node locator grid (N - 1 not divisible by 4, no coarser level),
    against the documented 4k + 1."""
    import bearing_fem as bf
    from bearing_fem import units
    from bearing_fem.contacts.line import SPIKE_LOCATOR_MAX_NODES, locator_nodes

    par = units.line_scene_from_moes(500.0, 5.0)
    for nodes in (1000, 1001, 1002, 1003, 1500, 2500):
        scene = bf.Scene.from_dict({
            "contact": {"kind": "line", "rx": par["radius"]},
            "materials": {"reduced_modulus": par["e_prime"]},
            "lubricant": {"viscosity": par["viscosity"], "piezo": par["piezo"]},
            "kinematics": {"u1": par["mean_speed"], "u2": par["mean_speed"]},
            "load": {"force": par["load_per_length"]},
            "mesh": {"grading": "outlet", "nodes": nodes}})
        n = locator_nodes(scene)
        assert (n - 1) % 4 == 0, (nodes, n)
        assert min(nodes, SPIKE_LOCATOR_MAX_NODES) <= n <= SPIKE_LOCATOR_MAX_NODES, (nodes, n)


def test_graded_grid_study_row_nodes_when_the_uniform_solve_fails(load_study, monkeypatch):
    """A row's node count is the default grid's even when the uniform solve fails and its
    result lies on a coarser level (the row took the result's node count: 401 here)."""
    from bearing_fem.contacts.line import line_setup

    mod = load_study("line_graded_grid")
    real = mod._solve

    def failing_uniform(scene):
        row = real(scene)
        if scene.mesh.grading is None and scene.mesh.nodes is None:
            row.update(status="stalled", nodes=401)
        return row

    monkeypatch.setattr(mod, "_solve", failing_uniform)
    row = mod.auto_case(20.0, 5.0)
    default = int(line_setup(mod.scene_for(20.0, 5.0)).disc.x.size)
    assert row["nodes"] == default == 801, (row["nodes"], default)
    assert row["reference_status"] == "converged", row["reference_status"]

"""Rigid Roelands scenes with a gap and Reynolds cavitation take the linear path of the
reduced pressure q = int_0^p eta0/eta dp: the same film as the Newton path, and
``no_solution`` at once beyond q_max < q_inf."""
import numpy as np
import pytest

import bearing_fem as bf
import bearing_fem.contacts.line as line_mod
import bearing_fem.contacts.point as point_mod


def scene(kind: str, gap: float, nodes, cavitation: str = "reynolds") -> bf.Scene:
    contact = {"kind": kind, "rx": 0.01}
    mesh = {"nodes": nodes}
    if kind == "point":
        contact["ry"] = 0.01
    return bf.Scene.from_dict({
        "contact": contact,
        "lubricant": {"viscosity": 0.01, "piezo": 2e-8, "viscosity_law": "roelands"},
        "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": gap}, "mesh": mesh,
        "model": {"elasticity": "rigid", "cavitation": cavitation}})


@pytest.mark.parametrize("kind,gap,nodes,rtol", [
    # line: two discretisations of one equation (P1 in q against P1 in p with the
    # viscosity at the quadrature points) on 801 nodes (measured 6e-5 apart)
    ("line", 1e-6, 801, 3e-4),
    # point: two discretisations of one equation (P1 in q against P1 in p with the
    # viscosity at the quadrature points) on a 41^2 grid
    ("point", 3e-7, [41, 41], 2e-3)])
def test_linear_path_matches_the_newton_path(kind, gap, nodes, rtol, monkeypatch):
    lin = bf.solve(scene(kind, gap, nodes))
    assert lin.status == "linear" and lin.newton_iterations == 0, lin.message
    assert "q_max/q_inf" in lin.message
    mod = line_mod if kind == "line" else point_mod
    monkeypatch.setattr(mod, "is_linear", lambda s: False)
    newton = bf.solve(scene(kind, gap, nodes))
    assert newton.status == "converged", newton.message
    for key in ("load", "p_max", "friction_force"):
        np.testing.assert_allclose(lin.quantities[key], newton.quantities[key], rtol=rtol,
                                   err_msg=f"{kind} {key}: linear against Newton path")


@pytest.mark.parametrize("kind,nodes", [("line", 801), ("point", [41, 41])])
def test_gap_beyond_the_roelands_limit_is_no_solution(kind, nodes):
    from bearing_fem.analytic import roelands_reduced_limit

    r = bf.solve(scene(kind, 1e-8, nodes))
    assert r.status == "no_solution" and not r.success
    assert r.newton_iterations == 0
    q_inf = roelands_reduced_limit(0.01, 2e-8)
    assert f"q_inf = {q_inf:.4g} Pa" in r.message, r.message
    assert np.all(np.isfinite(r.pressure)) and float(np.max(r.pressure)) >= q_inf
    assert r.quantities == {}


def test_full_sommerfeld_roelands_stays_on_newton():
    """q < 0 has no Roelands pressure below -p0 (the law is clipped there): the linear
    path is for Reynolds cavitation only."""
    from bearing_fem.contacts.linear import is_linear_scene

    assert is_linear_scene(scene("line", 1e-6, 801))
    assert not is_linear_scene(scene("line", 1e-6, 801, cavitation="none"))


def test_rigid_roelands_squeeze_series_runs():
    s = bf.Scene.from_dict({
        "contact": {"kind": "point", "rx": 0.00635, "ry": 0.00635},
        "lubricant": {"viscosity": 0.0106, "piezo": 2e-8, "viscosity_law": "roelands"},
        "kinematics": {"u1": 2.0, "u2": 2.0}, "load": {"gap": 2e-7},
        "mesh": {"nodes": [33, 33]},
        "model": {"elasticity": "rigid", "cavitation": "reynolds"},
        "transient": {"kind": "squeeze", "amplitude": 0.3, "steps": 4}})
    series = bf.solve_series(s)
    assert series.success, series.message
    loads = [r.quantities["load"] for r in series.results]
    assert len(loads) == 5 and all(r.status == "linear" for r in series.results)  # 4 steps + end
    assert np.all(np.isfinite(loads)) and min(loads) > 0.0


@pytest.mark.parametrize("kind", ["line", "point"])
def test_negative_end_pressure_takes_the_linear_path(kind):
    """An end pressure below ambient has a (negative) Roelands reduced pressure: the
    scene is solved like a Barus one, the end nodes holding that pressure (it raised
    'p must be finite and >= 0 Pa' where the Newton path had solved it)."""
    if kind == "line":
        r = line_mod.solve_line(scene("line", 1e-6, 801), boundary_pressure=(-2e4, 0.0))
        ends = r.pressure[[0]]
    else:
        r = point_mod.solve_point(scene("point", 3e-7, [41, 41]),
                                  boundary_pressure=lambda x, y: np.full(x.shape, -2e4))
        ends = np.concatenate((r.pressure[0], r.pressure[-1], r.pressure[:, 0]))
    assert r.status == "linear", r.message
    assert np.all(np.isfinite(r.pressure))
    np.testing.assert_allclose(ends, -2e4, rtol=1e-9,
                               err_msg="end pressures through q and back (well conditioned)")

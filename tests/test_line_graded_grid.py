"""Graded line grids (``mesh.file`` with non-uniform nodes) and their study."""
from __future__ import annotations


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
    for name in ("runs.csv", "line_graded_grid.md", "summary.json", "line_graded_grid.png"):
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
                                             r"distinct; x = .* appears 2 times"):
            bf.solve(scene)


def test_rigid_barus_line_beyond_its_load_limit_is_no_solution():
    """Kapitsa: a rigid piezo-viscous cylinder carries a finite load. Beyond it Newton
    'converged' to a one-node spike (p_max 47.7 GPa, alpha p = 954) and reported success."""
    import bearing_fem as bf
    from bearing_fem.contacts.line import RIGID_BARUS_RESOLVABLE_ALPHA_P

    def scene(force):
        return bf.Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                                   "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
                                   "kinematics": {"u1": 1.0, "u2": 1.0},
                                   "load": {"force": force}, "model": {"elasticity": "rigid"}})

    ok = bf.solve(scene(1e4))
    assert ok.status == "converged" and 2e-8 * ok.quantities["p_max"] < 3.0, \
        "below the limit: a resolved solution (alpha p_max 2.1)"
    over = bf.solve(scene(1e5))
    assert over.status == "no_solution" and not over.success, over.message
    assert "exceeds what the rigid Barus contact can carry" in over.message
    assert 2e-8 * over.pressure.max() > RIGID_BARUS_RESOLVABLE_ALPHA_P
    assert over.summary()["error_estimate"] is None

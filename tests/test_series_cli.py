"""[transient] scenes: ``bearing-fem solve`` runs the squeeze series and writes PVD/XDMF."""
from __future__ import annotations

import json
import math

import meshio
import numpy as np

import bearing_fem as bf
from bearing_fem import analytic, cli
from bearing_fem.io import read_series, scene_to_toml

RIGID = {
    "title": "rigid ball, vibrating gap",
    "contact": {"kind": "point", "rx": 0.00635, "ry": 0.00635},
    "lubricant": {"viscosity": 0.0106, "piezo": 2e-8},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"gap": 2e-7},
    "model": {"elasticity": "rigid", "cavitation": "none"},
    "mesh": {"nodes": [101, 101]},     # the default sinh-graded rigid grid, coarser
    "transient": {"amplitude": 0.3, "steps": 4},
}


def _write(tmp_path, data, name):
    path = tmp_path / f"{name}.toml"
    path.write_text(scene_to_toml(data), encoding="utf-8")
    return path


def test_rigid_series_via_cli_matches_kapitsa(tmp_path):
    out = tmp_path / "out"
    assert cli.main(["solve", str(_write(tmp_path, RIGID, "rigid")), "--out", str(out)]) == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["status"] == "linear" and s["success"] and s["instants"] == 5
    h0, eps, r = 2e-7, 0.3, 0.00635
    omega = 2.0 / math.sqrt(2 * r * h0)  # the default: u_m / sqrt(2 rx h0)
    np.testing.assert_allclose(s["times"][1], 2 * math.pi / (4 * omega), rtol=1e-12,
                               err_msg="4 steps per period of the default frequency")
    for t, g, rate, pm in zip(s["times"], s["gap"], s["squeeze_velocity"], s["p_max"]):
        np.testing.assert_allclose(g, h0 * (1 + eps * math.cos(omega * t)), rtol=1e-12)
        q = float(analytic.kapitsa_point_max_reduced(g, 1 / (2 * r), 1 / (2 * r), 0.0106,
                                                     2.0, rate))
        exact = float(analytic.barus_from_reduced(q, 2e-8))
        np.testing.assert_allclose(pm, exact, rtol=2e-2,
                                   err_msg="each instant within 2% of Kapitsa (graded 101^2 on "
                                           "+-30 lengths: the zero boundary truncates the far "
                                           "field)")
    with meshio.xdmf.TimeSeriesReader(out / "squeeze.xdmf") as reader:
        reader.read_points_cells()
        t, data, _ = reader.read_data(2)
    np.testing.assert_allclose(t, s["times"][2], err_msg="XDMF times are the series' times")
    np.testing.assert_allclose(np.max(data["pressure_Pa"]), s["p_max"][2], rtol=2e-2,
                               err_msg="nodal maximum vs the refined p_max")
    assert "DataSet" in (out / "squeeze.pvd").read_text()


def test_elastic_series_via_python_and_cli(tmp_path):
    elastic = json.loads(json.dumps(RIGID))
    elastic["model"] = {"elasticity": "half-space", "cavitation": "reynolds"}
    elastic["materials"] = {"reduced_modulus": 2.3e11}
    elastic["mesh"] = {"nodes": [25, 25]}
    elastic["transient"] = {"amplitude": 0.3, "steps": 4, "scheme": "euler"}
    series = bf.solve_series(bf.Scene.from_dict(elastic))
    assert series.success and len(series.results) == 5, series.message
    assert max(series.newton_iterations) <= 10, "cost cap per step"
    out = tmp_path / "out"
    assert cli.main(["solve", str(_write(tmp_path, elastic, "elastic")), "--out",
                     str(out), "-q"]) == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["scheme"] == "euler" and s["status"] == "converged"
    np.testing.assert_allclose(s["p_max"], series.p_max, rtol=1e-10,
                               err_msg="the CLI runs the same series (bitwise-reproducible)")
    assert (out / "elastic_squeeze.pvd").is_file() and (out / "elastic_squeeze.xdmf").is_file()
    back = read_series(out)
    for key in ("times", "gap", "p_max", "h_min", "h_central", "load"):
        np.testing.assert_allclose(back[key], getattr(series, key), rtol=1e-10,
                                   err_msg=f"{key} read back from summary.json as solved")
    assert cli.main(["plot", str(out), "-q"]) == 0, "a converged series plots with exit 0"
    assert (out / "series.png").stat().st_size > 0, "the figure of the series against time"


def test_failed_series_writes_its_status_and_exits_3(tmp_path):
    bad = json.loads(json.dumps(RIGID))
    bad["lubricant"]["piezo"] = 1e-6       # alpha q_max far beyond 1: no rigid solution
    out = tmp_path / "out"
    assert cli.main(["solve", str(_write(tmp_path, bad, "bad")), "--out", str(out)]) == 3
    s = json.loads((out / "summary.json").read_text())
    assert s["status"] == "no_solution" and s["success"] is False
    assert all(v is None for v in s["p_max"]), "no pressure where no solution exists"


def test_solve_refuses_a_series_scene_instead_of_ignoring_its_transient_section():
    """bf.solve on a [transient] scene returned the steady solution at the mean gap,
    silently dropping the series; it now says to use solve_series (the command line
    runs the series)."""
    import pytest

    scene = bf.Scene.from_dict(RIGID)
    with pytest.raises(bf.SceneError, match=r"\[transient\].*solve_series"):
        bf.solve(scene)
    steady = bf.solve(scene.replace(transient=None))
    assert steady.success, "without the section: the steady solve at the mean gap"


def test_rigid_series_honours_the_time_limit_of_the_whole_series(tmp_path):
    """solver.time_limit bounds the whole series; a rigid series ran every instant
    whatever the limit (201 instants, 36 s, with time_limit = 0.5 s)."""
    data = json.loads(json.dumps(RIGID))
    data["transient"] = {"amplitude": 0.3, "steps": 64}
    data["solver"] = {"time_limit": 0.05}
    series = bf.solve_series(bf.Scene.from_dict(data))
    assert series.status == "time_limit" and not series.success, series.message
    assert 1 <= len(series.results) < 65, len(series.results)
    assert "whole series" in series.message, series.message
    s = series.summary()
    assert len(s["times"]) == len(s["p_max"]) == s["instants"] == len(series.results)
    out = tmp_path / "out"
    assert cli.main(["solve", str(_write(tmp_path, data, "limited")), "--out", str(out),
                     "-q"]) == 3, "an unfinished series is not a success"
    assert json.loads((out / "summary.json").read_text())["status"] == "time_limit"

"""Command line: subcommands, exit codes 0/2/3, files written, plot fallback."""
from __future__ import annotations

import json
import subprocess
import sys

from bearing_fem import analytic, cli
from bearing_fem.io import read_result, scene_to_toml

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"

#: A rigid, prescribed-gap line scene: solved by a few linear solves (fast).
RIGID_OK = {
    "title": "rigid cylinder, Barus, gap 1 um",
    "contact": {"kind": "line", "rx": 0.01},
    "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"gap": 1e-6},
    "model": {"elasticity": "rigid", "cavitation": "reynolds"},
    "mesh": {"nodes": 401, "x_range": [-50.0, 5.0]},
}
#: Rigid Barus cylinder beyond Kapitsa's existence limit (alpha q_max > 1).
RIGID_NO_SOLUTION = {
    "contact": {"kind": "line", "rx": 0.01},
    "lubricant": {"viscosity": 0.05, "piezo": 5e-8},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"gap": 1e-7},
    "model": {"elasticity": "rigid", "cavitation": "none"},
}


def _write(tmp_path, data, name="scene.toml"):
    path = tmp_path / name
    path.write_text(scene_to_toml(data), encoding="utf-8")
    return str(path)


def _summary(outdir):
    return json.loads((outdir / "summary.json").read_text(encoding="utf-8"))


def test_help_lists_subcommands(capsys):
    assert cli.main(["--help"]) == 0
    out = capsys.readouterr().out
    for command in ("solve", "demo", "plot"):
        assert command in out
    assert "--version" in out and "--verbose" in out


def test_version(capsys):
    import bearing_fem

    assert cli.main(["--version"]) == 0
    assert bearing_fem.__version__ in capsys.readouterr().out


def test_module_entry_point_help():
    proc = subprocess.run([sys.executable, "-m", "bearing_fem.cli", "--help"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "solve" in proc.stdout


def test_usage_error_exit_2(capsys):
    assert cli.main(["solve"]) == 2  # missing SCENE and --out
    assert cli.main(["frobnicate"]) == 2
    assert "usage" in capsys.readouterr().err


def test_demo_writes_four_files(tmp_path, monkeypatch, capsys):
    # a coarse mesh keeps the test short (the default mesh takes tens of seconds);
    # no --out: the default directory is used
    monkeypatch.chdir(tmp_path)
    assert cli.main(["demo", "--nodes", "201"]) == 0
    out = tmp_path / cli.DEMO_DIR
    for name in ("summary.json", "result.h5", "fields.vtu", "pressure_film.png"):
        assert (out / name).is_file(), name
    assert (out / "pressure_film.png").read_bytes()[:8] == PNG_MAGIC
    summary = _summary(out)
    assert summary["success"] is True and summary["status"] == "converged"
    assert summary["scene"]["mesh"]["nodes"] == 201
    assert summary["scene"]["title"].startswith("Roller")
    stdout = capsys.readouterr().out
    for key in ("status", "h_central", "h_min", "p_max", "friction coefficient",
                "heat power", "iterations", "wall time"):
        assert key in stdout, key


def test_demo_out_option(tmp_path, monkeypatch):
    """--out is honoured (the solve itself is replaced: covered by the test above)."""
    import bearing_fem.contacts.dispatch
    from bearing_fem.result import Result

    def fake_solve(scene):
        import numpy as np

        x = np.linspace(-1e-3, 1e-3, 11)
        return Result(success=True, status="converged", message="fake", scene=scene, x=x,
                      pressure=np.zeros_like(x), film=np.full_like(x, 1e-6), h0=1e-6)

    monkeypatch.setattr(bearing_fem.contacts.dispatch, "solve", fake_solve)
    out = tmp_path / "elsewhere"
    assert cli.main(["demo", "--out", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == sorted(
        ["summary.json", "result.h5", "fields.vtu", "pressure_film.png"])


def test_solve_exit_0(tmp_path, capsys):
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(out)]) == 0
    summary = _summary(out)
    assert summary["status"] == "linear" and summary["success"] is True
    data = read_result(out / "result.h5")
    assert data["status"] == "linear"
    assert (out / "fields.vtu").is_file()
    captured = capsys.readouterr()
    assert "linear" in captured.out and captured.err == ""


def test_solve_verbose_logs_to_stderr(tmp_path, capsys):
    import logging

    logging.getLogger("bearing_fem").handlers.clear()
    out = tmp_path / "out"
    assert cli.main(["-v", "solve", _write(tmp_path, RIGID_OK), "--out", str(out)]) == 0
    assert logging.getLogger("bearing_fem").getEffectiveLevel() == logging.INFO
    logging.getLogger("bearing_fem").setLevel(logging.NOTSET)


def test_solve_exit_2_on_scene_error(tmp_path, capsys):
    bad = {**RIGID_OK, "lubricant": {"viscosity": -0.01}}
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, bad), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "lubricant.viscosity" in err and "-0.01" in err and "Pa s" in err
    assert "Traceback" not in err
    assert not out.exists()  # validation happens before any work


def test_solve_exit_2_on_unwritable_output(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(blocker)]) == 2
    assert "cannot write results" in capsys.readouterr().err


def test_solve_exit_3_no_solution(tmp_path, capsys):
    sc = RIGID_NO_SOLUTION
    q_max = analytic.kapitsa_line_max_reduced(sc["load"]["gap"], sc["contact"]["rx"],
                                              sc["lubricant"]["viscosity"],
                                              sc["kinematics"]["u1"])
    ratio = sc["lubricant"]["piezo"] * float(q_max)
    assert ratio > 1.0, "test scene must lie beyond Kapitsa's existence limit"
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, sc), "--out", str(out)]) == 3
    err = capsys.readouterr().err
    assert "no solution exists" in err and "no_solution" in err
    summary = _summary(out)  # files are still written, with the status
    assert summary["status"] == "no_solution" and summary["success"] is False
    assert read_result(out)["status"] == "no_solution"


def test_solve_exit_3_not_converged(tmp_path, capsys):
    # the elastic roller cannot converge in one Newton iteration without continuation
    from bearing_fem.scene import load_embedded

    data = load_embedded("roller").to_dict()
    data["mesh"] = {"nodes": 201}
    data["solver"] = {"max_iterations": 1, "continuation": False}
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, data), "--out", str(out)]) == 3
    err = capsys.readouterr().err
    assert "no converged solution" in err and "residual" in err
    summary = _summary(out)
    assert summary["success"] is False and summary["status"] != "no_solution"


def test_plot_subcommand(tmp_path, capsys):
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(out)]) == 0
    png = tmp_path / "figure.png"
    assert cli.main(["plot", str(out / "result.h5"), "--out", str(png),
                     "--kind", "line"]) == 0
    assert png.read_bytes()[:8] == PNG_MAGIC
    # default name: next to the result file
    assert cli.main(["plot", str(out / "result.h5")]) == 0
    assert (out / "result.png").read_bytes()[:8] == PNG_MAGIC


def test_plot_falls_back_without_plot_module(tmp_path, monkeypatch):
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(out)]) == 0
    monkeypatch.setitem(sys.modules, "bearing_fem.plot", None)  # import now fails
    png = tmp_path / "fallback.png"
    assert cli.main(["plot", str(out), "--out", str(png)]) == 0
    assert png.read_bytes()[:8] == PNG_MAGIC


def test_plot_exit_2_on_missing_or_foreign_file(tmp_path, capsys):
    assert cli.main(["plot", str(tmp_path / "missing.h5")]) == 2
    foreign = tmp_path / "foreign.h5"
    foreign.write_bytes(b"this is not HDF5")
    assert cli.main(["plot", str(foreign)]) == 2
    err = capsys.readouterr().err
    assert "missing.h5" in err and "foreign.h5" in err and "Traceback" not in err

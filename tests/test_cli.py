"""Command line: subcommands, exit codes 0/2/3, files written, plot fallback."""
from __future__ import annotations

import json
import logging
import re
import subprocess
import sys

import numpy as np
import pytest

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


@pytest.mark.parametrize("module", ["bearing_fem", "bearing_fem.cli"])
def test_module_entry_point_help(module):
    proc = subprocess.run([sys.executable, "-m", module, "--help"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "solve" in proc.stdout and "exit codes" in proc.stdout


def test_help_stands_alone(capsys):
    """The help itself explains the subcommands and every exit code (an installed copy
    has no docs folder to point to)."""
    assert cli.main(["--help"]) == 0
    out = capsys.readouterr().out
    for text in ("solve", "demo", "plot", "exit codes", "130", "-q", "anywhere"):
        assert text in out, text
    for code in ("0 ", "2 ", "3 "):
        assert re.search(rf"^\s+{code}\s+\S", out, re.M), f"exit code {code}explained"


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
    import bearing_fem.contacts.dispatch as dispatch

    monkeypatch.setattr(dispatch, "solve", _fake_solve())
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


@pytest.mark.parametrize("argv_of,level,quiet", [
    (lambda scene, out: ["-v", "solve", scene, "--out", out], logging.INFO, False),
    (lambda scene, out: ["solve", scene, "-v", "--out", out], logging.INFO, False),
    (lambda scene, out: ["solve", scene, "--out", out, "-vv"], logging.DEBUG, False),
    (lambda scene, out: ["-v", "solve", "--verbose", scene, "--out", out], logging.DEBUG,
     False),
    (lambda scene, out: ["solve", scene, "-q", "--out", out], logging.ERROR, True),
    (lambda scene, out: ["--quiet", "solve", scene, "--out", out], logging.ERROR, True),
], ids=["v-before", "v-after", "vv-at-end", "v-twice", "q-after", "quiet-before"])
def test_verbosity_anywhere(tmp_path, capsys, monkeypatch, argv_of, level, quiet):
    import bearing_fem.contacts.dispatch as dispatch

    out = tmp_path / "out"
    logger = logging.getLogger("bearing_fem")
    before = (logger.level, logger.propagate, list(logger.handlers))
    real_solve, seen = dispatch.solve, []

    def solve_and_look(scene):  # the level in force during the command
        seen.append(logger.level)
        return real_solve(scene)

    monkeypatch.setattr(dispatch, "solve", solve_and_look)
    assert cli.main(argv_of(_write(tmp_path, RIGID_OK), str(out))) == 0
    assert seen == [level]
    assert (logger.level, logger.propagate, list(logger.handlers)) == before, \
        "main() restores the package logger"
    captured = capsys.readouterr()
    assert ("h_central" in captured.out) != quiet, "-q prints no summary"
    if level <= logging.INFO:
        assert "INFO bearing_fem.cli: solving" in captured.err
    else:
        assert captured.err == ""
    assert (out / "summary.json").is_file()


def test_split_verbosity():
    assert cli.split_verbosity(["-vv", "solve", "-q", "a.toml", "--verbose"]) == (
        ["solve", "a.toml"], 2)
    # after "--" nothing is an option; other dashed tokens are left to argparse
    assert cli.split_verbosity(["plot", "--", "-v"]) == (["plot", "--", "-v"], 0)
    assert cli.split_verbosity(["-o", "-v.png", "-vq"]) == (["-o", "-v.png", "-vq"], 0)


@pytest.mark.parametrize("argv", [["solve", "SCENE", "--out", ""], ["demo", "--out", " "],
                                  ["demo", "-o", ""], ["plot", "RESULT", "--out", ""]])
def test_empty_out_is_refused(tmp_path, monkeypatch, capsys, argv):
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(out)]) == 0
    before = sorted(p.name for p in tmp_path.iterdir())
    argv = [{"SCENE": str(tmp_path / "scene.toml"), "RESULT": str(out / "result.h5")}.get(a, a)
            for a in argv]
    assert cli.main(argv) == 2
    assert "--out must name a directory or file, got an empty string" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == before, "nothing written in ."


def _fake_solve(warnings=(), raise_=None, runtime_warning=False):
    def fake(scene):
        from bearing_fem.result import Result

        if raise_ is not None:
            raise raise_
        if runtime_warning:
            np.log(np.zeros(3))  # a numpy RuntimeWarning outside any errstate
        x = np.linspace(-1e-3, 1e-3, 11)
        return Result(success=True, status="converged", message="fake", scene=scene, x=x,
                      pressure=np.zeros_like(x), film=np.full_like(x, 1e-6), h0=1e-6,
                      warnings=list(warnings))
    return fake


def test_ctrl_c_exits_130_with_one_line(tmp_path, monkeypatch, capsys):
    import bearing_fem.contacts.dispatch as dispatch

    monkeypatch.setattr(dispatch, "solve", _fake_solve(raise_=KeyboardInterrupt()))
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(out)]) == 130
    err = capsys.readouterr().err
    assert err == "bearing-fem: interrupted\n"
    assert not out.exists()


def test_sigint_of_a_running_solve(tmp_path):
    """A real Ctrl-C (SIGINT) during a solve: exit 130, one line, no traceback, no files."""
    import signal

    data = {"contact": {"kind": "point", "rx": 0.0127, "ry": 0.0127},
            "materials": {"reduced_modulus": 2.3e11},
            "lubricant": {"viscosity": 0.04, "piezo": 2.2e-8},
            "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"force": 30.0},
            "mesh": {"nodes": [257, 257]}}  # several seconds: interrupted long before
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "bearing_fem", "-v", "solve",
                             _write(tmp_path, data), "--out", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            # a runner started in the background (`cmd &`) ignores SIGINT
                            # and its children inherit that: give the child the default
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        first = proc.stderr.readline()
        assert "solving" in first, first
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
    assert proc.returncode == 130, err
    assert "Traceback" not in err and err.strip().splitlines()[-1] == "bearing-fem: interrupted"
    assert not out.exists() or not any(out.iterdir())


def test_closed_output_pipe_exits_141_without_a_traceback(tmp_path):
    """``bearing-fem ... | head``: the reader closes the pipe before the summary is
    printed; the files are written, the exit code is 141 and nothing is printed."""
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "bearing_fem", "solve",
                             _write(tmp_path, RIGID_OK), "--out", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()  # the reader has gone before the first line
    err = proc.stderr.read().decode()
    proc.wait(timeout=120)
    assert proc.returncode == cli.EXIT_BROKEN_PIPE, err
    assert "Traceback" not in err and "BrokenPipeError" not in err, err
    assert (out / "summary.json").is_file(), "the files were written before the summary"


def test_python_warnings_go_to_the_log(tmp_path, monkeypatch, capsys):
    """A numpy RuntimeWarning never reaches the terminal raw; -v shows it as a log line."""
    import bearing_fem.contacts.dispatch as dispatch

    monkeypatch.setattr(dispatch, "solve", _fake_solve(runtime_warning=True))
    scene = _write(tmp_path, RIGID_OK)
    assert cli.main(["solve", scene, "--out", str(tmp_path / "a")]) == 0
    err = capsys.readouterr().err
    assert "RuntimeWarning" not in err and "divide by zero" not in err, err
    assert cli.main(["solve", scene, "--out", str(tmp_path / "b"), "-v"]) == 0
    err = capsys.readouterr().err
    assert "INFO bearing_fem.cli: RuntimeWarning: divide by zero" in err, err
    assert ".py:" not in err, "no internal file paths at info level"


def test_summary_prints_the_warnings(tmp_path, monkeypatch, capsys):
    import bearing_fem.contacts.dispatch as dispatch

    monkeypatch.setattr(dispatch, "solve", _fake_solve(warnings=["first thing", "second"]))
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(tmp_path / "o")]) == 0
    out = capsys.readouterr().out
    assert re.search(r"warning\s+first thing", out) and re.search(r"warning\s+second", out)


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
    assert "no converged solution" in err
    # only numbers whose meaning is known, each with its unit
    assert re.search(r"\d+ Newton iterations", err)
    m = re.search(r"scaled Newton residual of the returned fields (\S+) \(dimensionless; "
                  r"tolerance 1e-08\)", err)
    assert m, err
    # the same number as the message's residual (that of the fields written)
    msg = re.search(r"residual ([0-9.e+-]+) > tol", err)
    assert msg, err
    np.testing.assert_allclose(float(m.group(1)), float(msg.group(1)), rtol=5e-3,
                               err_msg="one residual, printed to 3 digits in both")
    assert re.search(r"; [0-9.e+-]+ s\)", err), "wall time in s"
    summary = _summary(out)
    assert summary["success"] is False and summary["status"] != "no_solution"


def _stalled_9_node_line(**sections) -> dict:
    """A heavy line contact on 9 nodes: Newton stalls from the Hertzian start, and so does
    its continuation step (alpha = 0)."""
    return {"contact": {"kind": "line", "rx": 0.01},
            "materials": {"reduced_modulus": 2.2e11},
            "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
            "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"force": 2e6},
            "mesh": {"nodes": 9}, **sections}


def _printed_and_message_residuals(err: str, label: str) -> None:
    printed = re.search(rf"scaled Newton residual {label} (\S+) ", err)
    msg = re.search(r"residual ([0-9.e+-]+) > tol", err)
    assert printed and msg, err
    np.testing.assert_allclose(float(printed.group(1)), float(msg.group(1)), rtol=5e-3,
                               err_msg="the fields' residual in both places")


def test_exit_3_after_failed_continuation_prints_the_fields_residual(tmp_path, capsys):
    """The printed residual is that of the returned fields on the scene's own problem
    (the message's), not the last continuation step's."""
    data = _stalled_9_node_line()
    assert cli.main(["solve", _write(tmp_path, data), "--out", str(tmp_path / "o")]) == 3
    err = capsys.readouterr().err
    _printed_and_message_residuals(err, "of the returned fields")
    # no step was accepted from the Hertzian start, whose film on 9 nodes is negative
    # between them: the message does not promise an admissible iterate
    assert "it is not admissible" in err and "last admissible iterate" not in err, err
    s = _summary(tmp_path / "o")
    assert s["h_min"] < 0.0, "the fields' own (negative) film minimum, explained above"


def test_exit_3_thermal_after_failed_continuation_prints_the_fields_residual(tmp_path,
                                                                             capsys):
    """The isothermal solve of a thermal scene fails after its continuation step: the
    printed residual is that of the returned fields (the message's), not the last
    continuation step's."""
    data = _stalled_9_node_line(model={"thermal": "patch"},
                                thermal={"oil_temperature": 60.0, "exponent": 2.93})
    assert cli.main(["solve", _write(tmp_path, data), "--out", str(tmp_path / "o")]) == 3
    err = capsys.readouterr().err
    _printed_and_message_residuals(err, "of the isothermal solve")


def test_exit_3_thermal_names_the_temperature_residual(tmp_path, capsys):
    """A thermal loop stopped after one iteration: its residual is a temperature in K
    and is printed as one; the Newton residual is labelled as the isothermal solve's."""
    data = {"contact": {"kind": "line", "rx": 0.01, "length": 0.02},
            "materials": {"e1": 2.1e11, "nu1": 0.3, "e2": 2.1e11, "nu2": 0.3},
            "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
            "kinematics": {"u1": 2.2, "u2": 1.8}, "load": {"force": 2e5},
            "model": {"elasticity": "local", "thermal": "patch"}, "mesh": {"nodes": 401},
            "thermal": {"oil_temperature": 60.0, "exponent": 2.93, "max_iterations": 1},
            "traction": {"model": "eyring"}}
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, data), "--out", str(out)]) == 3
    err = capsys.readouterr().err
    assert "status max_iterations" in err
    m = re.search(r"thermal residual \|G\(T\) - T\| = (\S+) K", err)
    assert m, err
    assert float(m.group(1)) == pytest.approx(_summary(out)["thermal_residual"], rel=1e-2)
    assert "last scaled Newton residual of the isothermal solve" in err
    assert not re.search(r"last scaled residual", err)


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


def test_plot_refuses_point_kinds_for_a_line_result(tmp_path, capsys):
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, RIGID_OK), "--out", str(out)]) == 0
    capsys.readouterr()
    for kind in ("map", "surface"):
        png = tmp_path / f"{kind}.png"
        assert cli.main(["plot", str(out), "--kind", kind, "--out", str(png)]) == 2
        err = capsys.readouterr().err
        assert f"--kind {kind} applies to point contacts only" in err and "line" in err
        assert not png.exists()


@pytest.mark.parametrize("status", ["no_solution", "max_iterations", "stalled", "diverged",
                                    "budget_exhausted", "time_limit"])
def test_plot_of_a_failure_writes_a_stamped_figure_and_exits_3(tmp_path, capsys, status):
    from bearing_fem.contacts.dispatch import solve
    from bearing_fem.io import export
    from bearing_fem.scene import Scene

    result = solve(Scene.from_dict(RIGID_OK))
    result.status, result.success = status, False
    export(result, tmp_path)
    png = tmp_path / "fig.png"
    assert cli.main(["plot", str(tmp_path), "--out", str(png)]) == 3
    assert png.read_bytes()[:8] == PNG_MAGIC
    err = capsys.readouterr().err
    assert f"(status {status})" in err and "stamped with the status" in err
    assert ("reduced pressure q" in err) == (status == "no_solution")


def test_plot_exit_2_on_missing_or_foreign_file(tmp_path, capsys):
    assert cli.main(["plot", str(tmp_path / "missing.h5")]) == 2
    foreign = tmp_path / "foreign.h5"
    foreign.write_bytes(b"this is not HDF5")
    assert cli.main(["plot", str(foreign)]) == 2
    err = capsys.readouterr().err
    assert "missing.h5" in err and "foreign.h5" in err and "Traceback" not in err
    # an HDF5 file of another output (a squeeze series' time series): the reason in words,
    # not h5py's "Unable to synchronously open attribute"
    import h5py
    other = tmp_path / "squeeze.h5"
    with h5py.File(other, "w") as f:
        f.create_dataset("x", data=[0.0, 1.0])
    assert cli.main(["plot", str(other)]) == 2
    err = capsys.readouterr().err
    assert "not a contact result" in err and "no attribute(s) kind" in err, err
    assert "synchronously" not in err and "Traceback" not in err, err


def test_plot_of_a_bearing_output_points_to_its_contact_folders(tmp_path, capsys):
    """'bearing-fem plot OUT' on the folder of 'bearing-fem bearing' (or its
    bearing_summary.json) said "no result file 'OUT/result.h5'" or "not an HDF5 file":
    the message now says what the folder is and names a contact folder to plot."""
    out = tmp_path / "b"
    (out / "contact_000_inner").mkdir(parents=True)
    (out / "contact_000_outer").mkdir()
    (out / "bearing_summary.json").write_text("{}")
    for arg in (out, out / "bearing_summary.json"):
        assert cli.main(["plot", str(arg)]) == 2
        err = capsys.readouterr().err
        assert "is the output of 'bearing-fem bearing'" in err, err
        assert f"bearing-fem plot {out / 'contact_000_inner'}" in err, err
        assert "load_distribution.png" in err and "Traceback" not in err, err


def test_solve_series_prints_its_warnings(tmp_path, capsys):
    """A [transient] scene's summary lists its warnings as 'warning' lines, as a single
    solve's does (docs/cli.md); an elastic series says it has no error estimate."""
    data = {
        "title": "elastic squeeze",
        "contact": {"kind": "point", "rx": 6.35e-3, "ry": 6.35e-3},
        "materials": {"reduced_modulus": 2.26e11},
        "lubricant": {"viscosity": 0.0612, "viscosity_law": "constant"},
        "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": 1e-7},
        "mesh": {"nodes": [33, 33], "x_range": [-4.0, 4.0], "y_range": [-4.0, 4.0]},
        "transient": {"amplitude": 0.3, "steps": 4},
    }
    out = tmp_path / "out"
    assert cli.main(["solve", str(_write(tmp_path, data)), "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    lines = [ln for ln in printed.splitlines() if ln.strip().startswith("warning")]
    saved = json.loads((out / "summary.json").read_text())["warnings"]
    assert saved and len(lines) == len(saved), (printed, saved)
    assert any("no error estimate" in ln and "one grid" in ln for ln in lines), printed


def test_contact_length_gives_totals(tmp_path, capsys):
    """contact.length is documented as 'used for totals': the summary of a line contact
    with a length has the load, friction force and heat power over that length (N, W),
    and the printed heat power gives the total beside the per-metre value."""
    data = dict(RIGID_OK, contact={"kind": "line", "rx": 0.01, "length": 0.012})
    out = tmp_path / "out"
    assert cli.main(["solve", _write(tmp_path, data), "--out", str(out)]) == 0
    s = _summary(out)
    for key, total, unit in (("load", "load_total", "N"),
                             ("friction_force", "friction_force_total", "N"),
                             ("heat_power", "heat_power_total", "W")):
        np.testing.assert_allclose(s[total], s[key] * 0.012, rtol=1e-12,
                                   err_msg=f"{total} = {key} [per metre] x contact.length")
        assert s["units"][total] == unit and s["units"][key] == unit + "/m"
    printed = capsys.readouterr().out
    assert f"{s['heat_power_total']:.4g} W over contact.length" in printed, printed
    out2 = tmp_path / "no_length"
    assert cli.main(["solve", _write(tmp_path, RIGID_OK, "b.toml"), "--out", str(out2)]) == 0
    assert not [k for k in _summary(out2) if k.endswith("_total")], "no length, no totals"


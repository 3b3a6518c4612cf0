"""I/O round trips: summary.json, result.h5 and fields.vtu (meshio's write_read pattern).

Every comparison of stored arrays is exact: the files hold float64, so a round trip must
give back the identical bits; any tolerance would hide a dtype or ordering bug.
"""
from __future__ import annotations

import copy
import json

import meshio
import numpy as np
import pytest

import bearing_fem as bf
from bearing_fem import io
from bearing_fem.result import Result
from bearing_fem.scene import Scene, load_embedded

RIGID_LINE = {
    "title": "rigid line, prescribed gap",
    "contact": {"kind": "line", "rx": 0.01, "length": 0.02},
    "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"gap": 1e-6},
    "model": {"elasticity": "rigid", "cavitation": "reynolds"},
    "mesh": {"nodes": 201, "x_range": [-50.0, 5.0]},
}
RIGID_POINT = {
    "contact": {"kind": "point", "rx": 0.01, "ry": 0.02},
    "lubricant": {"viscosity": 0.05},
    "kinematics": {"u1": 1.0, "u2": 1.0},
    "load": {"gap": 1e-6},
    "model": {"elasticity": "rigid"},
}


def _strict_json(path):
    def _reject(token):
        raise AssertionError(f"non-strict JSON constant {token} in {path}")
    return json.loads(path.read_text(encoding="utf-8"), parse_constant=_reject)


def _snapshot(result: Result) -> dict:
    return {"x": result.x.copy(), "pressure": result.pressure.copy(),
            "film": result.film.copy(), "history": list(result.history),
            "quantities": dict(result.quantities), "status": result.status,
            "extra": {k: v.copy() for k, v in result.extra_fields.items()},
            "y": None if result.y is None else result.y.copy()}


def _assert_unchanged(result: Result, snap: dict) -> None:
    np.testing.assert_array_equal(result.x, snap["x"])
    np.testing.assert_array_equal(result.pressure, snap["pressure"])
    np.testing.assert_array_equal(result.film, snap["film"])
    assert result.history == snap["history"]
    assert result.quantities == snap["quantities"]
    assert result.status == snap["status"]
    assert result.extra_fields.keys() == snap["extra"].keys()
    for k, v in snap["extra"].items():
        np.testing.assert_array_equal(result.extra_fields[k], v)
    if snap["y"] is not None:
        np.testing.assert_array_equal(result.y, snap["y"])


@pytest.fixture(scope="module")
def line_result() -> Result:
    result = bf.solve(Scene.from_dict(RIGID_LINE))
    assert result.success, result.message
    # an extra field with a unit suffix, as the solver adds for Newton solves
    result.extra_fields = {**result.extra_fields,
                           "test_temperature_K": np.linspace(300.0, 310.0, result.x.size)}
    return result


def test_line_round_trip(line_result, tmp_path):
    snap = _snapshot(line_result)
    files = bf.export(line_result, tmp_path / "out" / "nested")
    assert set(files) == {"summary", "h5", "vtu"}
    assert all(p.is_file() for p in files.values())
    _assert_unchanged(line_result, snap)

    data = io.read_result(files["h5"])
    assert data["kind"] == "line" and data["y"] is None
    assert data["status"] == line_result.status and data["success"] is True
    assert data["message"] == line_result.message
    assert data["version"] == bf.__version__
    assert data["h0"] == line_result.h0
    np.testing.assert_array_equal(data["x"], line_result.x)
    np.testing.assert_array_equal(data["pressure_Pa"], line_result.pressure)
    np.testing.assert_array_equal(data["film_m"], line_result.film)
    for name, arr in line_result.extra_fields.items():
        np.testing.assert_array_equal(data["fields"][name], arr)
    assert data["units"]["x"] == "m" and data["units"]["pressure_Pa"] == "Pa"
    assert data["units"]["film_m"] == "m" and data["units"]["test_temperature_K"] == "K"
    np.testing.assert_array_equal(data["history"], np.array(line_result.history, float))
    assert data["newton_iterations"] == line_result.newton_iterations
    assert data["linear_solves"] == line_result.linear_solves
    # the stored scene rebuilds the same scene
    assert Scene.from_dict(data["scene"]) == line_result.scene
    assert Scene.from_toml_string(data["scene_toml"]) == line_result.scene

    summary = _strict_json(files["summary"])
    assert summary == json.loads(json.dumps(line_result.summary()))
    assert data["summary"] == summary

    mesh = meshio.read(files["vtu"])
    np.testing.assert_array_equal(mesh.points[:, 0], line_result.x)
    np.testing.assert_array_equal(mesh.points[:, 1:], 0.0)
    lines = mesh.cells_dict["line"]
    assert lines.shape == (line_result.x.size - 1, 2)
    np.testing.assert_array_equal(lines[:, 1] - lines[:, 0], 1)
    np.testing.assert_array_equal(mesh.point_data["pressure_Pa"], line_result.pressure)
    np.testing.assert_array_equal(mesh.point_data["film_m"], line_result.film)
    np.testing.assert_array_equal(mesh.point_data["test_temperature_K"],
                                  line_result.extra_fields["test_temperature_K"])


def test_read_result_on_other_files_says_what_it_reads(line_result, tmp_path):
    import h5py

    io.export(line_result, tmp_path)
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f.attrs["eps"] = 0.3
    for path, match in ((tmp_path / "summary.json", "is not an HDF5 file"),
                        (tmp_path / "other.h5", r"not a contact result written by "
                                                 r"bearing_fem.export \(no attribute\(s\) "
                                                 r"kind, status"),
                        (tmp_path / "nothing", "no result file")):
        with pytest.raises(ValueError, match=match):
            io.read_result(path)


def test_read_result_accepts_directory(line_result, tmp_path):
    bf.export(line_result, tmp_path)
    np.testing.assert_array_equal(io.read_result(tmp_path)["pressure_Pa"],
                                  line_result.pressure)


def test_export_overwrites_and_leaves_no_temporaries(line_result, tmp_path):
    bf.export(line_result, tmp_path)
    bf.export(line_result, tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(io.FILES.values())


def test_export_is_atomic_on_failure(line_result, tmp_path, monkeypatch):
    """A failing writer leaves the previous export untouched and no temporary files."""
    bf.export(line_result, tmp_path)
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}

    def broken(result, path):
        path.write_bytes(b"half")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(io, "write_vtu", broken)
    failed = copy.copy(line_result)
    failed.status = "max_iterations"
    with pytest.raises(OSError, match="No space"):
        io.export(failed, tmp_path)
    after = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert after == before


def _dead_pid() -> int:
    """The process id of a process that has ended (a child that already exited)."""
    import subprocess
    import sys

    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_stale_temporaries_of_dead_processes_are_removed(line_result, tmp_path):
    """Leftovers of a killed export are removed by the next one; a running export's
    files, old-looking but unrelated files and the user's own files are kept."""
    import os
    import time

    dead = _dead_pid()
    stale = [tmp_path / f".summary.json.{dead}.0123456789ab.tmp.json",
             tmp_path / f".result.h5.{dead}.0123456789ab.tmp.h5",
             tmp_path / f".squeeze_0001.vtu.{dead}.abcdefabcdef.tmp.vtu"]
    alive = tmp_path / f".fields.vtu.{os.getpid()}.0123456789ab.tmp.vtu"
    unrelated = [tmp_path / ".notes.tmp", tmp_path / f".x.{dead}.0123456789ab.tmp.h5",
                 tmp_path / "mine.txt"]  # wrong suffix for its final name; user files
    for path in stale + [alive] + unrelated:
        path.write_bytes(b"half-written")
    removed = io.clean_stale_temporaries(tmp_path)
    assert sorted(removed) == sorted(stale)
    assert all(p.exists() for p in [alive] + unrelated)
    # a running process id whose file is older than the stale age: removed
    old = time.time() - io.STALE_TEMP_AGE - 10.0
    os.utime(alive, (old, old))
    files = bf.export(line_result, tmp_path)
    assert not alive.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [f.name for f in files.values()] + [p.name for p in unrelated])


def test_sigkill_during_export_leaves_files_that_the_next_export_removes(line_result,
                                                                         tmp_path):
    """A real SIGKILL between writing the temporaries and moving them into place."""
    import signal
    import subprocess
    import sys

    out = tmp_path / "out"
    script = f"""
import time, bearing_fem as bf
from bearing_fem import io
from bearing_fem.scene import Scene
result = bf.solve(Scene.from_dict({RIGID_LINE!r}))
def stuck(result, path):
    path.write_bytes(b"half")
    print("writing", flush=True)
    time.sleep(60)
io.write_vtu = stuck
io.export(result, {str(out)!r})
"""
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        assert proc.stdout.readline().strip() == "writing"
        proc.send_signal(signal.SIGKILL)
    finally:
        proc.wait(timeout=30)
    left = sorted(p.name for p in out.iterdir())
    assert len(left) == 3 and all(n.startswith(".") and ".tmp" in n for n in left), left
    bf.export(line_result, out)
    assert sorted(p.name for p in out.iterdir()) == sorted(io.FILES.values())


def _point_result(x_axis, y_axis, nodal: bool, shuffle: bool, grid2d: bool = False) -> Result:
    scene = Scene.from_dict(RIGID_POINT)
    xx, yy = np.meshgrid(x_axis, y_axis)  # (ny, nx)
    p = 1e8 * np.exp(-(xx / 1e-4) ** 2 - (yy / 2e-4) ** 2)
    h = 1e-6 + xx**2 / 0.02 + yy**2 / 0.04
    extra = {"viscosity_Pa_s": 0.05 * np.exp(2e-8 * p)}
    if nodal:
        order = np.random.default_rng(0).permutation(xx.size) if shuffle \
            else np.arange(xx.size)
        x, y = xx.ravel()[order], yy.ravel()[order]
        p, h = p.ravel()[order], h.ravel()[order]
        extra = {k: v.ravel()[order] for k, v in extra.items()}
    elif grid2d:  # the solver's layout: axes and (ny, nx) nodal arrays
        x, y = x_axis, y_axis
    else:
        x, y, p, h = x_axis, y_axis, p.ravel(), h.ravel()
        extra = {k: v.ravel() for k, v in extra.items()}
    return Result(success=True, status="converged", message="synthetic", scene=scene,
                  x=x, y=y, pressure=p, film=h, h0=1e-6, history=[1e-2, 1e-9],
                  newton_iterations=1, quantities={"p_max": float(p.max()),
                                                   "friction_coefficient": float("nan")},
                  extra_fields=extra)


@pytest.mark.parametrize("nodal,shuffle,grid2d",
                         [(False, False, True), (False, False, False), (True, False, False),
                          (True, True, False)],
                         ids=["grid-axes-2d", "grid-axes-flat", "nodal", "nodal-shuffled"])
def test_point_round_trip(tmp_path, nodal, shuffle, grid2d):
    nx, ny = 7, 5
    x_axis = np.linspace(-3e-4, 1e-4, nx)
    y_axis = np.linspace(-2e-4, 2e-4, ny)
    result = _point_result(x_axis, y_axis, nodal, shuffle, grid2d)
    snap = _snapshot(result)
    files = bf.export(result, tmp_path)
    _assert_unchanged(result, snap)

    data = io.read_result(files["h5"])
    assert data["kind"] == "point" and data["title"] == ""
    assert data["pressure_Pa"].shape == result.pressure.shape
    np.testing.assert_array_equal(data["x"], result.x)
    np.testing.assert_array_equal(data["y"], result.y)
    np.testing.assert_array_equal(data["pressure_Pa"], result.pressure)
    np.testing.assert_array_equal(data["fields"]["viscosity_Pa_s"],
                                  result.extra_fields["viscosity_Pa_s"])
    assert data["units"]["y"] == "m" and data["units"]["viscosity_Pa_s"] == "Pa s"

    # the non-finite friction coefficient becomes null, the file stays strict JSON
    summary = _strict_json(files["summary"])
    assert summary["friction_coefficient"] is None
    assert summary["p_max"] == result.quantities["p_max"]

    mesh = meshio.read(files["vtu"])
    quads = mesh.cells_dict["quad"]
    assert quads.shape == ((nx - 1) * (ny - 1), 4)
    # every quad is an axis-aligned grid cell: 2 distinct x and 2 distinct y values,
    # and its area is one grid cell (catches crossed or mis-ordered connectivity)
    corners = mesh.points[quads][:, :, :2]
    dx, dy = x_axis[1] - x_axis[0], y_axis[1] - y_axis[0]
    for c in corners:
        assert len(np.unique(c[:, 0])) == 2 and len(np.unique(c[:, 1])) == 2
        area = 0.5 * abs(np.dot(c[:, 0], np.roll(c[:, 1], -1))
                         - np.dot(c[:, 1], np.roll(c[:, 0], -1)))
        # rel 1e-9: shoelace area of float64 corners, exact up to rounding
        assert area == pytest.approx(dx * dy, rel=1e-9)
    # point data follows the points: p is a function of the coordinates
    xs, ys = mesh.points[:, 0], mesh.points[:, 1]
    expect = 1e8 * np.exp(-(xs / 1e-4) ** 2 - (ys / 2e-4) ** 2)
    # rel 1e-12: same formula evaluated on the same float64 coordinates
    np.testing.assert_allclose(mesh.point_data["pressure_Pa"], expect, rtol=1e-12)


def test_point_fields_must_form_a_grid(tmp_path):
    result = _point_result(np.linspace(0, 1, 4), np.linspace(0, 1, 3), True, False)
    result.x = result.x.copy()
    result.x[0] = 0.123  # one node off the tensor grid
    with pytest.raises(ValueError, match="tensor grid"):
        io.write_vtu(result, tmp_path / "f.vtu")


def test_scene_to_toml_round_trip():
    scene = load_embedded("roller")
    assert Scene.from_toml_string(io.scene_to_toml(scene)) == scene
    text = io.scene_to_toml({"title": 'quote " and \\', "mesh": {"x_range": [-4.5, 1.5]},
                             "solver": {"continuation": False, "tolerance": float("nan")}})
    import tomllib

    back = tomllib.loads(text)
    assert back["title"] == 'quote " and \\'
    assert back["mesh"]["x_range"] == [-4.5, 1.5]
    assert back["solver"]["continuation"] is False
    assert np.isnan(back["solver"]["tolerance"])


@pytest.mark.parametrize("name,unit", [("pressure_Pa", "Pa"), ("film_m", "m"),
                                       ("viscosity_Pa_s", "Pa s"), ("temperature_K", "K"),
                                       ("heat_flux_W_m2", "W/m^2"), ("shape", "")])
def test_field_unit(name, unit):
    assert io.field_unit(name) == unit


def test_every_dimensional_summary_number_has_a_unit():
    """Every float in the summary of an elastic line and point solve, and of a rigid point
    solve, has its unit in summary["units"] (heat_power_poiseuille_direct and
    heat_power_stabilisation had none, nor had the rigid point's load_beyond_domain);
    counts (iterations, unknowns) are whole numbers."""
    import bearing_fem as bf

    def base(kind):
        contact = {"kind": kind, "rx": 0.01} | ({"ry": 0.01} if kind == "point" else {})
        return bf.Scene.from_dict({
            "contact": contact, "materials": {"reduced_modulus": 2.2e11},
            "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
            "kinematics": {"u1": 1.0, "u2": 1.0},
            "load": {"force": 2e5 if kind == "line" else 50.0},
            "mesh": {"nodes": 401 if kind == "line" else [33, 33]}})

    rigid = bf.Scene.from_dict({
        "contact": {"kind": "point", "rx": 0.01, "ry": 0.01},
        "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
        "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": 1e-6},
        "mesh": {"nodes": [33, 33]}, "model": {"elasticity": "rigid"}})
    rigid_summary = bf.solve(rigid).summary()
    assert "load_beyond_domain" in rigid_summary, "the rigid default domain's far field"
    for kind, s in (("line", bf.solve(base("line")).summary()),
                    ("point", bf.solve(base("point")).summary()),
                    ("rigid point", rigid_summary)):
        missing = [k for k, v in s.items() if isinstance(v, float) and k not in s["units"]]
        assert not missing, f"{kind}: summary numbers without a unit: {missing}"
        for k in ("newton_iterations", "dofs"):
            assert isinstance(s[k], int), f"{kind}: {k} is a count"

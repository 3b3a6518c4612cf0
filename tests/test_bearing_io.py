"""export_bearing, the figures and the ``bearing-fem bearing`` subcommand."""
from __future__ import annotations

import csv
import json

import pytest

from bearing_fem import cli, io
from bearing_fem.bearing import solve_bearing

from test_bearing_solve import small_roller  # noqa: E402  (tests/ is on sys.path)

TOML = """title = "small roller bearing"
[bearing]
type = "cylindrical-roller"
bore = 0.03
outside_diameter = 0.062
pitch_diameter = 0.046
element_diameter = 0.009
elements = 13
effective_length = 0.009
radial_clearance = 5e-6
[lubricant]
viscosity = 0.05
piezo = 2e-8
[operation]
inner_rpm = 1500
radial_load = 2000
[mesh]
line_nodes = 201
"""


@pytest.fixture(scope="module")
def result():
    return solve_bearing(small_roller(mesh={"line_nodes": 201}))


def test_interrupted_export_leaves_nothing(result, tmp_path, monkeypatch):
    """Ctrl-C while the contact files are written: no file and no directory the export
    made is left (an empty ``contacts_vtk/`` was)."""
    calls = {"n": 0}

    def interrupted(*args, **kwargs):
        calls["n"] += 1
        raise KeyboardInterrupt

    monkeypatch.setattr(io, "write_h5", interrupted)
    out = tmp_path / "new" / "out"
    with pytest.raises(KeyboardInterrupt):
        io.export_bearing(result, out)
    assert calls["n"] == 1, "interrupted at the first contact file"
    assert not (tmp_path / "new").exists(), [str(p) for p in tmp_path.rglob("*")]
    # an existing output directory and its files stay
    keep = tmp_path / "mine"
    keep.mkdir()
    (keep / "notes.txt").write_text("mine")
    with pytest.raises(KeyboardInterrupt):
        io.export_bearing(result, keep)
    assert sorted(p.name for p in keep.iterdir()) == ["notes.txt"]


def test_export_bearing_files(result, tmp_path):
    files = io.export_bearing(result, tmp_path)
    j = result.most_loaded_element()
    assert {"summary", "elements", "vtm", f"contact_{j:03d}_inner",
            f"contact_{j:03d}_outer"} <= set(files)
    s = json.loads(files["summary"].read_text())
    assert s["status"] == "converged" and s["friction_torque"] == pytest.approx(
        result.totals["friction_torque"], rel=1e-12)
    rows = list(csv.DictReader(files["elements"].open()))
    assert len(rows) == 13 and rows[0]["load_N"] and "inner_h_min_m" in rows[0]
    unloaded = [r for r in rows if r["in_load_zone"] == "False"]
    assert unloaded and unloaded[0]["inner_h_min_m"] == "", "undefined numbers are empty"
    loaded = rows[j]
    est = result.elements[j]["inner"]["error_estimate"]
    assert float(loaded["inner_friction_force_rel_error"]) == pytest.approx(
        est["friction_force"], rel=1e-12), "each contact's error bars in the element table"
    assert unloaded[0]["inner_friction_force_rel_error"] == "", "none for an excluded contact"
    contact = files[f"contact_{j:03d}_inner"]
    assert {p.name for p in contact.iterdir()} == {"summary.json", "result.h5", "fields.vtu"}
    vtm = files["vtm"].read_text()
    n_blocks = sum(len(sp.keys) for sp in result.specs)
    assert vtm.count("<DataSet ") == n_blocks, "one block per solved contact"
    assert not [p for p in tmp_path.rglob(".*tmp*")], "no temporary files left"
    pv = pytest.importorskip("pyvista")
    mb = pv.read(files["vtm"])
    assert mb.n_blocks == n_blocks and "pressure_Pa" in mb[0].point_data


def test_export_is_atomic(result, tmp_path, monkeypatch):
    def boom(*a, **k):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(io, "write_h5", boom)
    with pytest.raises(OSError):
        io.export_bearing(result, tmp_path)
    assert [p for p in tmp_path.rglob("*") if p.is_file()] == [], \
        "a failed export leaves neither final nor temporary files"


def test_figures(result, tmp_path):
    from bearing_fem.plot_bearing import FIGURES, write_figures

    files = write_figures(result, tmp_path)
    assert set(files) == set(FIGURES)
    for p in files.values():
        assert p.stat().st_size > 5000, f"{p.name} is a real PNG"


def test_cli_bearing(tmp_path, capsys):
    path = tmp_path / "b.toml"
    path.write_text(TOML)
    out = tmp_path / "out"
    assert cli.main(["bearing", str(path), "--out", str(out)]) == cli.EXIT_OK
    names = {p.name for p in out.iterdir()}
    assert {"bearing_summary.json", "elements.csv", "contacts.vtm", "load_distribution.png",
            "films_pressures.png", "torque_comparison.png"} <= names
    printed = capsys.readouterr().out
    assert "friction torque" in printed
    # one column for the values, however long a row's name (an empirical model's torque)
    summary = json.loads((out / "bearing_summary.json").read_text())
    names = ["status", "friction torque", "heat power", "h_min", "p_max", "wall time",
             "message", "warning", "wrote"]
    names += [f"{n} torque" for n, m in summary["empirical"].items()
              if m.get("torque") is not None]
    width = max(len(n) for n in names)
    rows = [(n, line) for line in printed.splitlines() for n in names
            if line.startswith(f"  {n} ")]
    assert len(rows) >= 8, printed
    for n, line in rows:
        assert line[2 + width] == " " and line[3 + width] != " ", \
            f"the value of {n!r} starts in column {3 + width}: {line!r}"
    bad = tmp_path / "bad.toml"
    bad.write_text(TOML.replace("radial_clearance = 5e-6", "radial_clearance = -5e-6"))
    assert cli.main(["bearing", str(bad), "--out", str(out)]) == cli.EXIT_INVALID
    assert "radial_clearance must be >= 0 m" in capsys.readouterr().err
    fail = tmp_path / "fail.toml"
    fail.write_text(TOML + "[solver]\nmax_iterations = 1\ncontinuation = false\n"
                           "iteration_budget = 1\n")
    out3 = tmp_path / "out3"
    assert cli.main(["bearing", str(fail), "--out", str(out3), "--no-figures"]) == \
        cli.EXIT_NO_SOLUTION
    s = json.loads((out3 / "bearing_summary.json").read_text())
    assert s["status"] == "contacts_failed", "files are written with the status"
    capsys.readouterr()
    out4 = tmp_path / "out4"
    assert cli.main(["bearing", str(path), "--out", str(out4), "--no-figures", "-q"]) == \
        cli.EXIT_OK
    printed = capsys.readouterr()
    assert printed.out == "" and printed.err == "", "-q prints errors only (docs/cli.md)"
    assert (out4 / "bearing_summary.json").is_file()


def test_cli_bearing_refuses_an_empty_out(tmp_path, monkeypatch, capsys):
    """--out "" wrote every file into the current folder with exit 0."""
    monkeypatch.chdir(tmp_path)
    assert cli.main(["bearing", "6209", "--out", ""]) == cli.EXIT_INVALID
    assert "--out must name a directory" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == [], "nothing written"


@pytest.mark.parametrize("name, hint", [("6208", ""), ("6209.toml", "bearing-fem bearing 6209")])
def test_cli_bearing_names_the_shipped_examples(tmp_path, monkeypatch, capsys, name, hint):
    """Neither a file nor a shipped example: exit 2, naming the examples (and the example's
    name without .toml when that is what was meant); nothing written."""
    monkeypatch.chdir(tmp_path)
    assert cli.main(["bearing", name, "--out", "o"]) == cli.EXIT_INVALID
    err = capsys.readouterr().err
    assert f"no bearing file {name!r}" in err and "6209, 7010-hybrid" in err, err
    assert hint in err
    assert not (tmp_path / "o").exists()


def test_one_loaded_slice_keeps_its_slice_number_in_the_folder_name(tmp_path):
    """A profiled roller whose contacts have one loaded slice: the folder is named by that
    slice's number, as its warnings and labels are ("slice 6 of 11")."""
    from bearing_fem.bearing.totals import slice_label

    r = solve_bearing(small_roller(bearing={"profile": "crowned", "crown_drop": 8e-5,
                                            "slices": 11},
                                   operation={"radial_load": 100.0}, mesh={"line_nodes": 101}))
    j = r.most_loaded_element()
    spec = next(s for s in r.specs if s.element == j and s.raceway == "inner")
    assert len(spec.keys) == 1 and spec.slice_numbers, (spec.keys, spec.slice_numbers)
    n = spec.slice_numbers[0]
    assert slice_label(spec, 0, 11) == f"slice {n} of 11"
    files = io.export_bearing(r, tmp_path)
    assert f"contact_{j:03d}_inner_slice{n:02d}" in files, sorted(files)
    assert f"contact_{j:03d}_inner" not in files, "the slice number is in the name"


def test_figures_show_an_opposed_tapered_row_that_differs(tmp_path):
    """A tapered pair under a small axial load: the two rows carry different loads, and
    the films figure draws the opposed row too; under radial load only the rows are equal
    and one is drawn."""
    import matplotlib.pyplot as plt

    from bearing_fem.plot_bearing import _opposed_row, films_figure, write_figures

    geometry = {"type": "tapered-roller", "contact_angle": 14.0, "rows": 2,
                "radial_clearance": 0.0, "width": 0.03}
    pair = solve_bearing(small_roller(bearing=geometry, operation={"axial_load": 100.0},
                                      mesh={"line_nodes": 201}))
    assert pair.success, pair.message
    other = _opposed_row(pair)
    assert other is not None and other["load"].max() < pair.distribution.max_load
    fig = films_figure(pair)
    labels = [line.get_label() for line in fig.axes[0].lines]
    plt.close(fig)
    assert {"inner, row 0", "inner, row 1 (opposed)"} <= set(labels), \
        f"rows named by their elements.csv / summary 'row' index (0, 1): {labels}"
    assert set(write_figures(pair, tmp_path)) == {"load_distribution", "films", "torque"}
    radial = solve_bearing(small_roller(bearing=geometry, mesh={"line_nodes": 201}))
    assert _opposed_row(radial) is None, "equal rows: one row is drawn"

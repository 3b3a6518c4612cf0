"""meshes/: the shipped mesh files, read and written through meshio (bearing_fem.mesh)."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from bearing_fem import mesh as bm
from bearing_fem.physics import thermal

MESHES = Path(__file__).resolve().parents[1] / "meshes"
sys.path.insert(0, str(MESHES))
import make_meshes  # noqa: E402


def test_shipped_meshes_are_what_their_parameters_give(tmp_path):
    """The files in meshes/ equal a fresh run of make_meshes.py (none is stale)."""
    fresh = make_meshes.main(tmp_path)
    for name, path in fresh.items():
        shipped = bm.read_mesh(MESHES / path.name)
        new = bm.read_mesh(path)
        assert type(shipped) is type(new), name
        np.testing.assert_allclose(shipped.p, new.p, rtol=0, atol=1e-12,
                                   err_msg=f"{name}: node coordinates")
        np.testing.assert_array_equal(shipped.t, new.t, err_msg=f"{name}: cells")


def test_round_trip_and_atomic_write(tmp_path):
    m = bm.tensor_mesh(np.linspace(0, 1, 5), np.linspace(-1, 1, 4))
    path = bm.write_mesh(m, tmp_path / "grid.vtu")
    back = bm.read_mesh(path)
    x, y = bm.tensor_axes(back)
    np.testing.assert_allclose(x, np.linspace(0, 1, 5), err_msg="x axis survives the file")
    np.testing.assert_allclose(y, np.linspace(-1, 1, 4), err_msg="y axis survives the file")
    assert [p.name for p in tmp_path.iterdir()] == ["grid.vtu"], "no temporary file left"


def test_point_grid_file_is_the_solver_default():
    from bearing_fem.contacts.point import ELASTIC_NODES, ELASTIC_RANGE

    x, y = bm.tensor_axes(bm.read_mesh(MESHES / "point_elastic_129.vtu"))
    assert x.size == y.size == ELASTIC_NODES
    np.testing.assert_allclose([x[0], x[-1]], ELASTIC_RANGE[0], err_msg="x range [a]")
    np.testing.assert_allclose([y[0], y[-1]], ELASTIC_RANGE[1], err_msg="y range [b]")


def test_korovchinsky_patch_from_file_equals_built_in():
    patch = bm.read_mesh(MESHES / "korovchinsky_patch.vtu")
    a, q, lam = 1e-4, 1e8, 46.0
    from_file = thermal.strip_source(a, q, lam, mesh=patch)
    built = thermal.strip_source(a, q, lam)
    for x, y in ((0.0, 0.0), (0.5 * a, 0.0), (2 * a, 0.0), (0.0, 3 * a)):
        np.testing.assert_allclose(from_file.temperature(x, y), built.temperature(x, y),
                                   rtol=1e-10, err_msg="same mesh, same field (read back "
                                                       "from the .vtu to rounding)")


@pytest.mark.parametrize("bad, match", [("missing.vtu", "does not exist"),
                                        ("garbage.vtu", "cannot be read")])
def test_bad_files_name_the_file(tmp_path, bad, match):
    (tmp_path / "garbage.vtu").write_text("not a mesh")
    with pytest.raises(ValueError, match=match):
        bm.read_mesh(tmp_path / bad)


def test_wrong_mesh_kind_is_refused():
    with pytest.raises(ValueError, match="tensor grid"):
        bm.tensor_axes(bm.read_mesh(MESHES / "korovchinsky_patch.vtu"))
    with pytest.raises(ValueError, match="triangles"):
        thermal.patch_from_mesh(bm.read_mesh(MESHES / "point_elastic_129.vtu"), 1e-4)


# ---------------------------------------------------------------------------------------
# scenes naming a grid file
# ---------------------------------------------------------------------------------------
BALL = {"contact": {"kind": "point", "rx": 0.0127, "ry": 0.0127},
        "materials": {"reduced_modulus": 2.3e11},
        "lubricant": {"viscosity": 0.04, "piezo": 2.2e-8},
        "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"force": 30.0}}


def test_point_scene_with_a_grid_file_equals_its_ranges(tmp_path):
    import bearing_fem as bf

    path = bm.write_mesh(bm.tensor_mesh(np.linspace(-4.5, 1.5, 65), np.linspace(-3, 3, 65)),
                         tmp_path / "grid.vtu")
    ranged = bf.solve(bf.Scene.from_dict(dict(BALL, mesh={
        "nodes": [65, 65], "x_range": [-4.5, 1.5], "y_range": [-3.0, 3.0]})))
    (tmp_path / "ball.toml").write_text(
        '[contact]\nkind = "point"\nrx = 0.0127\nry = 0.0127\n[materials]\n'
        'reduced_modulus = 2.3e11\n[lubricant]\nviscosity = 0.04\npiezo = 2.2e-8\n'
        '[kinematics]\nu1 = 1.0\nu2 = 1.0\n[load]\nforce = 30.0\n[mesh]\nfile = "grid.vtu"\n',
        encoding="utf-8")
    scene = bf.Scene.from_toml(tmp_path / "ball.toml")
    assert scene.mesh.file == str(path), "a relative mesh.file is relative to the scene file"
    filed = bf.solve(scene)
    assert ranged.success and filed.success, (ranged.message, filed.message)
    assert filed.newton_iterations == ranged.newton_iterations
    for key in ("h_central", "h_min", "p_max"):
        np.testing.assert_allclose(filed.quantities[key], ranged.quantities[key], rtol=1e-9,
                                   err_msg=f"{key}: the file holds the same grid")


def test_line_scene_with_the_shipped_grid_file():
    import bearing_fem as bf

    line = {"contact": {"kind": "line", "rx": 0.01}, "materials": {"reduced_modulus": 2.2e11},
            "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
            "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"force": 2e5}}
    ranged = bf.solve(bf.Scene.from_dict(dict(line, mesh={"nodes": 1801,
                                                          "x_range": [-4.5, 1.5]})))
    filed = bf.solve(bf.Scene.from_dict(dict(line, mesh={
        "file": str(MESHES / "line_elastic_1801.vtu")})))
    np.testing.assert_allclose(filed.quantities["h_central"], ranged.quantities["h_central"],
                               rtol=1e-9, err_msg="meshes/line_elastic_1801.vtu is that grid")


def test_grid_file_errors_name_the_field(tmp_path):
    import bearing_fem as bf
    from bearing_fem.errors import SceneError

    graded = str(MESHES / "point_rigid_graded_161.vtu")
    cases = [({"file": str(tmp_path / "none.vtu")}, "does not exist"),
             ({"file": graded, "nodes": [65, 65]}, "replaces mesh.nodes"),
             ({"file": graded}, "uniformly spaced"),
             ({"file": str(MESHES / "line_elastic_1801.vtu")}, "tensor grid"),
             ({"file": str(MESHES / "korovchinsky_patch.vtu")}, "triangles")]
    for mesh, match in cases:
        with pytest.raises(SceneError, match=match):
            scene = bf.Scene.from_dict(dict(BALL, mesh=mesh))
            bf.solve(scene)


def test_outlet_graded_nodes():
    from bearing_fem.mesh import every_other, outlet_graded_nodes

    x = outlet_graded_nodes(801, (-4.5, 1.5), centre=0.95, width=0.1, ratio=9.0)
    assert x.size == 801 and x[0] == -4.5 and x[-1] == 1.5 and np.all(np.diff(x) > 0)
    steps = np.diff(x)
    np.testing.assert_allclose(steps.max() / steps.min(), 9.0, rtol=0.02,
                               err_msg="the density ratio is the spacing ratio (2 % for the "
                                       "discrete density)")
    assert abs(x[np.argmin(steps)] - 0.95) < 0.01, "finest at the centre"
    assert every_other(x, 401).size == 401, "n - 1 divisible by 4: nested coarser levels"
    for kwargs, match in (({"nodes": 2}, "nodes"), ({"nodes": 11, "ratio": 0.5}, "ratio"),
                          ({"nodes": 11, "width": 0.0}, "width"),
                          ({"nodes": 11, "x_range": (1.0, -1.0)}, "x_range")):
        with pytest.raises(ValueError, match=match):
            outlet_graded_nodes(**kwargs)


def test_relative_grid_file_is_stored_so_that_the_result_reads_back(tmp_path, monkeypatch):
    """A scene read as 'scene.toml' from its own folder with mesh.file = 'grid.vtu' keeps
    the grid's absolute path: the scene stored in result.h5 (and summary.json) solves again
    from any other folder (it held 'grid.vtu', relative to the folder of the first run)."""
    import bearing_fem as bf
    from bearing_fem.io import read_result

    work = tmp_path / "work"
    work.mkdir()
    from skfem import MeshLine

    bm.write_mesh(MeshLine(np.linspace(-50.0, 5.0, 201)), work / "grid.vtu")
    (work / "scene.toml").write_text(
        '[contact]\nkind = "line"\nrx = 0.01\n[lubricant]\nviscosity = 0.05\n'
        '[kinematics]\nu1 = 2.0\nu2 = 2.0\n[load]\ngap = 1e-6\n[model]\n'
        'elasticity = "rigid"\n[mesh]\nfile = "grid.vtu"\n', encoding="utf-8")
    monkeypatch.chdir(work)
    first = bf.solve(bf.Scene.from_toml("scene.toml"))
    bf.export(first, "out")
    monkeypatch.chdir(tmp_path)
    again = bf.solve(bf.Scene.from_toml_string(read_result(work / "out")["scene_toml"]))
    assert first.success and again.success, (first.message, again.message)
    np.testing.assert_allclose(again.pressure, first.pressure, rtol=1e-12,
                               err_msg="the stored scene is the scene that was solved")

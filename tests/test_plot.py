"""bearing_fem.plot: PNGs are produced off-screen and are not blank, for every input kind."""
from __future__ import annotations

import numpy as np
import pytest

from bearing_fem.plot import plot_result
from bearing_fem.contacts.point import solve_point
from bearing_fem.scene import Contact, Kinematics, Load, Lubricant, MeshSpec, Model, Scene


def _pixel_std(path) -> float:
    import matplotlib.image as mpimg

    img = mpimg.imread(str(path))
    return float(np.std(img[..., :3]))


@pytest.fixture(scope="module")
def point_result():
    scene = Scene(contact=Contact(kind="point", rx=0.01, ry=0.02),
                  lubricant=Lubricant(viscosity=0.01), kinematics=Kinematics(u1=1.0, u2=1.0),
                  load=Load(gap=1e-7), model=Model(elasticity="rigid", cavitation="reynolds"),
                  mesh=MeshSpec(nodes=(41, 41), x_range=(-6.0, 3.0), y_range=(-4.0, 4.0)))
    return solve_point(scene)


@pytest.mark.parametrize("kind", ["map", "surface", "line"])
def test_point_png_not_blank(point_result, tmp_path, kind):
    out = plot_result(point_result, tmp_path / f"{kind}.png", kind=kind)
    assert out.is_file()
    assert _pixel_std(out) > 0.02, "a blank (uniform) image has zero pixel variance"


def test_matplotlib_fallback(point_result, tmp_path, monkeypatch):
    monkeypatch.setenv("BEARING_FEM_PLOT_BACKEND", "matplotlib")
    out = plot_result(point_result, tmp_path / "fallback.png", kind="map")
    assert _pixel_std(out) > 0.02, "fallback figure must not be blank"


def test_line_result_png(tmp_path):
    from bearing_fem.contacts.dispatch import solve

    scene = Scene(contact=Contact(kind="line", rx=0.01), lubricant=Lubricant(viscosity=0.01),
                  kinematics=Kinematics(u1=1.0, u2=1.0), load=Load(gap=1e-6),
                  model=Model(elasticity="rigid", cavitation="reynolds"),
                  mesh=MeshSpec(nodes=401, x_range=(-20.0, 5.0)))
    res = solve(scene)
    out = plot_result(res, tmp_path / "line.png", kind="map")
    assert _pixel_std(out) > 0.02, "line plot must not be blank"


def test_from_h5_file(point_result, tmp_path):
    h5py = pytest.importorskip("h5py")
    path = tmp_path / "result.h5"
    with h5py.File(path, "w") as f:  # the layout bearing_fem.io writes
        f["x"] = point_result.x
        f["y"] = point_result.y
        f["pressure_Pa"] = point_result.pressure.ravel()
        f["film_m"] = point_result.film
        f.attrs["kind"] = "point"
    out = plot_result(path, tmp_path / "h5.png", kind="map")
    assert _pixel_std(out) > 0.02
    out = plot_result(tmp_path, tmp_path / "h5dir.png", kind="line")
    assert _pixel_std(out) > 0.02


def test_bad_kind(point_result, tmp_path):
    with pytest.raises(ValueError, match="kind"):
        plot_result(point_result, tmp_path / "x.png", kind="contour")

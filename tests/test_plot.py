"""bearing_fem.plot: PNGs are produced off-screen, are not blank, show the contact, and
never dress up a failure."""
from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from bearing_fem import plot
from bearing_fem.contacts.dispatch import solve
from bearing_fem.contacts.point import solve_point
from bearing_fem.plot import plot_result
from bearing_fem.result import Result
from bearing_fem.scene import Contact, Kinematics, Load, Lubricant, MeshSpec, Model, Scene

README = Path(__file__).resolve().parents[1] / "README.md"

#: Every unsuccessful status a solve can report (bearing_fem.result, numerics.newton).
FAILURES = ("no_solution", "max_iterations", "stalled", "diverged", "budget_exhausted",
            "time_limit")


def _pixel_std(path) -> float:
    import matplotlib.image as mpimg

    img = mpimg.imread(str(path))
    return float(np.std(img[..., :3]))


class _Figures:
    """Records every matplotlib figure saved while active (to inspect what was drawn)."""

    def __init__(self, monkeypatch):
        from matplotlib.figure import Figure

        self.saved: list = []
        original = Figure.savefig

        def savefig(fig, *args, **kwargs):
            self.saved.append(fig)
            return original(fig, *args, **kwargs)

        monkeypatch.setattr(Figure, "savefig", savefig)

    def texts(self) -> str:
        """Every title, axis label and free text of the last figure, one string."""
        fig = self.saved[-1]
        parts = [t.get_text() for t in fig.texts]
        for ax in fig.axes:
            parts += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
            if hasattr(ax, "get_zlabel"):
                parts.append(ax.get_zlabel())
        return "\n".join(parts)


@pytest.fixture
def figures(monkeypatch):
    return _Figures(monkeypatch)


@pytest.fixture(scope="module")
def point_result():
    scene = Scene(contact=Contact(kind="point", rx=0.01, ry=0.02),
                  lubricant=Lubricant(viscosity=0.01), kinematics=Kinematics(u1=1.0, u2=1.0),
                  load=Load(gap=1e-7), model=Model(elasticity="rigid", cavitation="reynolds"),
                  mesh=MeshSpec(nodes=(41, 41), x_range=(-6.0, 3.0), y_range=(-4.0, 4.0)))
    return solve_point(scene)


@pytest.fixture(scope="module")
def line_result():
    scene = Scene(contact=Contact(kind="line", rx=0.01), lubricant=Lubricant(viscosity=0.01),
                  kinematics=Kinematics(u1=1.0, u2=1.0), load=Load(gap=1e-6),
                  model=Model(elasticity="rigid", cavitation="reynolds"),
                  mesh=MeshSpec(nodes=401, x_range=(-20.0, 5.0)))
    return solve(scene)


@pytest.fixture(scope="module")
def readme_ball():
    """The README's ball scene (the TOML block titled "Ball on flat"), solved as given."""
    blocks = re.findall(r"^```toml[^\n]*\n(.*?)^```", README.read_text(encoding="utf-8"),
                        re.S | re.M)
    text = next(b for b in blocks if 'title = "Ball on flat"' in b)
    result = solve(Scene.from_toml_string(text, source="README ball scene"))
    assert result.success, result.message
    return result


@pytest.mark.parametrize("kind", ["map", "surface", "line"])
def test_point_png_not_blank(point_result, tmp_path, kind):
    out = plot_result(point_result, tmp_path / f"{kind}.png", kind=kind)
    assert out.is_file()
    assert _pixel_std(out) > 0.02, "a blank (uniform) image has zero pixel variance"


def test_matplotlib_fallback(point_result, tmp_path, monkeypatch, figures):
    monkeypatch.setenv("BEARING_FEM_PLOT_BACKEND", "matplotlib")
    out = plot_result(point_result, tmp_path / "fallback.png", kind="surface")
    assert _pixel_std(out) > 0.02, "fallback figure must not be blank"
    assert figures.saved, "the surface must come from matplotlib when forced"


def test_line_result_png(line_result, tmp_path):
    out = plot_result(line_result, tmp_path / "line.png")
    assert _pixel_std(out) > 0.02, "line plot must not be blank"


@pytest.mark.parametrize("kind", ["map", "surface"])
def test_line_result_refuses_point_kinds(line_result, tmp_path, kind):
    """A map of a line contact is not silently replaced by a line plot."""
    with pytest.raises(ValueError, match="point contacts only"):
        plot_result(line_result, tmp_path / "x.png", kind=kind)
    assert not (tmp_path / "x.png").exists()


def test_from_h5_file(point_result, tmp_path):
    h5py = pytest.importorskip("h5py")
    path = tmp_path / "result.h5"
    with h5py.File(path, "w") as f:  # the minimal layout (no status, no scene)
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


# ---------------------------------------------------------------------------------------
# failures are stamped, reduced pressure is never called pressure
# ---------------------------------------------------------------------------------------
def _failed(result: Result, status: str) -> Result:
    import copy

    bad = copy.copy(result)
    bad.status, bad.success = status, False
    return bad


@pytest.mark.parametrize("status,which", [(s, w) for s in FAILURES
                                           for w in ("line", "point-map")]
                         + [(s, "point-surface") for s in ("no_solution", "diverged")])
def test_every_failure_is_stamped(status, which, line_result, point_result, tmp_path,
                                  monkeypatch, figures):
    """Every unsuccessful status gives a figure whose title and stamp say so, through a
    Result and through the result.h5 that the command line plots."""
    from bearing_fem.io import export

    monkeypatch.setenv("BEARING_FEM_PLOT_BACKEND", "matplotlib")  # inspectable figures
    base = line_result if which == "line" else point_result
    kind = {"line": "line", "point-map": "map", "point-surface": "surface"}[which]
    bad = _failed(base, status)
    export(bad, tmp_path)
    for source in (bad, tmp_path / "result.h5"):
        out = plot_result(source, tmp_path / "fig.png", kind=kind)
        assert _pixel_std(out) > 0.02
        text = figures.texts()
        assert f"NOT A SOLUTION (status {status})" in text, text
        assert f"status: {status}" in text, "the red stamp across the axes"
        labels = [line for line in text.splitlines() if "[MPa]" in line]
        assert labels, text
        if status == "no_solution":
            assert all(lab.startswith("reduced pressure q") for lab in labels), labels
        else:
            assert all("last iterate" in lab for lab in labels), labels


def test_success_is_not_stamped(line_result, tmp_path, figures):
    plot_result(line_result, tmp_path / "ok.png")
    text = figures.texts()
    assert "NOT A SOLUTION" not in text and "pressure [MPa]" in text


def test_real_no_solution_labelled_reduced_pressure(tmp_path, figures):
    """A real no_solution result (rigid Barus beyond Kapitsa's limit): the drawn field is
    q, which the message states, and the label says so."""
    res = solve(Scene.from_dict({
        "contact": {"kind": "line", "rx": 0.01},
        "lubricant": {"viscosity": 0.05, "piezo": 5e-8},
        "kinematics": {"u1": 2.0, "u2": 2.0}, "load": {"gap": 1e-7},
        "model": {"elasticity": "rigid", "cavitation": "none"}}))
    assert res.status == "no_solution" and "reduced pressure q" in res.message
    plot_result(res, tmp_path / "q.png")
    assert "reduced pressure q [MPa]" in figures.texts()


# ---------------------------------------------------------------------------------------
# point maps show the contact (README ball scene, headless)
# ---------------------------------------------------------------------------------------
def test_readme_ball_map_contours_inside_the_contact(readme_ball, tmp_path, figures):
    """The film contours of the README ball lie in the Hertz circle and show the horseshoe;
    the map is zoomed on the contact, with equal aspect, the Hertz circle drawn, labelled
    contours and a colour bar that overlaps no tick label."""
    from matplotlib.contour import ContourSet
    from matplotlib.patches import Ellipse

    from bearing_fem import units

    c = readme_ball.scene.contact
    a = units.hertz_point(readme_ball.scene.load.force, c.rx, c.ry,
                          readme_ball.scene.e_prime).a_x
    out = plot_result(readme_ball, tmp_path / "ball.png")
    assert _pixel_std(out) > 0.02
    fig = figures.saved[-1]
    ax = fig.axes[0]
    sets = [cs for cs in ax.collections if isinstance(cs, ContourSet)]
    assert len(sets) == 1
    cs = sets[0]
    assert len(cs.levels) == len(plot.MAP_LEVELS)
    radii = [np.hypot(seg[:, 0], seg[:, 1]) * 1e-3 / a            # mm -> m, over a
             for segs in cs.allsegs for seg in segs if len(seg)]
    r_max = max(float(np.max(r)) for r in radii)
    # the EHL contact reaches slightly beyond the dry Hertz circle (the film closes the
    # horseshoe where it rises again, measured at 1.12 a on this 129x129 grid); 1.15 a
    # keeps every contour on the contact, while contours of the old whole-domain levels
    # reached 3 a
    assert r_max <= 1.15, f"film contours reach {r_max:.3f} a, outside the contact"
    # horseshoe: the lowest level (the side lobes of the constriction) lies off the axis
    lowest = np.concatenate([seg for seg in cs.allsegs[0] if len(seg)]) * 1e-3 / a
    assert np.min(np.abs(lowest[:, 1])) > 0.5, "minimum film must sit in the side lobes"
    assert len(cs.labelTexts) >= len(cs.levels) // 2, "contour values are labelled"
    for t in cs.labelTexts:
        value = float(t.get_text())
        assert any(np.isclose(value, lev, rtol=1e-2) for lev in cs.levels), t.get_text()
    ellipses = [p for p in ax.patches if isinstance(p, Ellipse)]
    assert len(ellipses) == 1
    np.testing.assert_allclose([ellipses[0].width, ellipses[0].height],
                               [2e3 * a, 2e3 * a], rtol=1e-12,
                               err_msg="Hertz circle drawn with the Hertz radius (mm)")
    assert ax.get_aspect() == 1.0
    x0, x1 = ax.get_xlim()
    assert x0 >= -2.5 * a * 1e3 - 1e-12 and x1 <= 1.6 * a * 1e3 + 1e-12, (x0, x1)
    # colour bar beside the axes: its box overlaps neither the map nor its tick labels
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)  # the saved figure was closed: draw it again, same layout
    canvas.draw()
    renderer = canvas.get_renderer()
    cbar_box = fig.axes[1].get_window_extent(renderer)
    for label in ax.get_xticklabels() + ax.get_yticklabels() + [ax.yaxis.label]:
        if label.get_text():
            assert not cbar_box.overlaps(label.get_window_extent(renderer)), label.get_text()
    assert not cbar_box.overlaps(ax.get_window_extent(renderer))
    assert re.search(r"\bBall on flat\b", ax.get_title())


def test_readme_ball_line_plot_zoomed(readme_ball, tmp_path, figures):
    """The centre-line plot spans a few Hertz radii, not the whole inlet."""
    plot_result(readme_ball, tmp_path / "line.png", kind="line")
    ax = figures.saved[-1].axes[0]
    assert ax.get_xlabel() == "x/a_x [-]"
    from bearing_fem import units

    sc = readme_ball.scene
    a_x = units.hertz_point(sc.load.force, sc.contact.rx, sc.contact.ry, sc.e_prime).a_x
    lo, hi = readme_ball.x[0] / a_x, readme_ball.x[-1] / a_x
    assert lo < plot.LINE_WINDOW[0], "the default domain reaches further into the inlet"
    assert ax.get_xlim() == pytest.approx((plot.LINE_WINDOW[0], min(hi, plot.LINE_WINDOW[1])))


def test_line_plot_of_an_even_grid_names_the_row_it_draws(point_result, tmp_path, figures):
    """On a grid without a node row at y = 0 (even ny) the line plot draws the nearest row
    and says so, instead of calling it the centre line y = 0."""
    plot_result(point_result, tmp_path / "odd.png", kind="line")
    assert "centre line y = 0" in figures.texts()
    scene = replace(point_result.scene, mesh=replace(point_result.scene.mesh, nodes=(41, 40)))
    even = solve_point(scene)
    assert even.success and not np.any(even.y == 0.0), even.message
    plot_result(even, tmp_path / "even.png", kind="line")
    text = figures.texts()
    assert "centre line y = 0" not in text and "no node row at y = 0" in text, text
    dy = float(np.min(np.abs(even.y))) * 1e3
    assert f"y = {dy:.3g} mm" in text or f"y = {-dy:.3g} mm" in text, text


def test_thermal_line_plot_draws_the_surface_temperatures(tmp_path, figures):
    """A thermal line result's figure shows both surface temperature rises under the
    pressure and film (from the Result and from its exported result.h5)."""
    import bearing_fem as bf
    from bearing_fem.scene import Materials, Thermal, Traction

    scene = Scene(contact=Contact(kind="line", rx=0.01, length=0.02),
                  materials=Materials(e1=2.1e11, nu1=0.3, e2=2.1e11, nu2=0.3),
                  lubricant=Lubricant(viscosity=0.05, piezo=2e-8),
                  kinematics=Kinematics(u1=2.2, u2=1.8), load=Load(force=2e5),
                  model=Model(elasticity="local", thermal="patch"), mesh=MeshSpec(nodes=401),
                  thermal=Thermal(oil_temperature=60.0, exponent=2.93),
                  traction=Traction(model="eyring"))
    res = solve(scene)
    assert res.success, res.message
    d = plot.load_plot_data(res)
    assert d.surface_rise is not None and float(np.max(d.surface_rise[0])) > 0.0
    out = plot_result(res, tmp_path / "thermal.png")
    assert _pixel_std(out) > 0.02
    assert len(figures.saved[-1].axes) == 3, "pressure, film (twin) and temperature axes"
    bf.export(res, tmp_path / "run")
    d5 = plot.load_plot_data(tmp_path / "run")
    np.testing.assert_allclose(d5.surface_rise[1], d.surface_rise[1], rtol=1e-12,
                               err_msg="the same rises from result.h5")
    assert plot.load_plot_data(solve(replace(scene, model=Model(elasticity="local"),
                                             thermal=None))).surface_rise is None

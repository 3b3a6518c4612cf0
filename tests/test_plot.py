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


# ---------------------------------------------------------------------------------------
# squeeze series: drawn against time, stamped unless solved, read back as exported
# ---------------------------------------------------------------------------------------
#: A rigid ball with a vibrating gap h0(t) = 0.2 um (1 + 0.3 cos(omega t)), 4 steps on
#: 33^2 nodes (about 0.2 s).
SERIES = {
    "title": "ball, vibrating gap",
    "contact": {"kind": "point", "rx": 0.00635, "ry": 0.00635},
    "lubricant": {"viscosity": 0.0106, "piezo": 2e-8},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"gap": 2e-7},
    "model": {"elasticity": "rigid", "cavitation": "none"},
    "mesh": {"nodes": [33, 33]},
    "transient": {"amplitude": 0.3, "steps": 4},
}


def _series(**lubricant):
    from bearing_fem.contacts.dispatch import solve_series

    data = {**SERIES, "lubricant": {**SERIES["lubricant"], **lubricant}}
    return solve_series(Scene.from_dict(data))


@pytest.fixture(scope="module")
def rigid_series():
    series = _series()
    assert series.success and len(series.results) == 5, series.message
    return series


@pytest.fixture(scope="module")
def mixed_series():
    """alpha = 3.2e-8 1/Pa: Kapitsa's limit alpha q_max < 1 holds at every instant but the
    narrowest gap (alpha q_max = 1.2 there, below 0.9 elsewhere): a real series with one
    instant without solution."""
    series = _series(piezo=3.2e-8)
    assert [r.success for r in series.results] == [True, True, False, True, True], \
        series.statuses
    return series


def _series_texts(fig) -> str:
    """Titles, axis labels, free texts and legend entries of a figure, one string."""
    parts = [t.get_text() for t in fig.texts]
    for ax in fig.axes:
        parts += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
        parts += [t.get_text() for t in ax.texts]
        if ax.get_legend() is not None:
            parts += [t.get_text() for t in ax.get_legend().get_texts()]
    return "\n".join(parts)


def _assert_read_back(series, tmp_path):
    """The exported series reads back as its own arrays, masked where unsolved."""
    from bearing_fem.io import export_series, read_series

    files = export_series(series, tmp_path)
    # any file of the export leads to its summary (without instants: the summary alone)
    back = read_series(files.get("h5", files["summary"]))
    assert back["status"] == series.status and back["success"] == series.success
    for key in ("times", "gap", "squeeze_velocity"):
        np.testing.assert_array_equal(back[key], getattr(series, key),
                                      err_msg=f"{key}: JSON keeps every digit of a float")
    solved = np.array([r.success for r in series.results], dtype=bool)
    for key in ("p_max", "h_min", "h_central", "load"):
        col = back[key]
        np.testing.assert_array_equal(np.ma.getmaskarray(col), ~solved,
                                      err_msg=f"{key} masked exactly at the unsolved instants")
        np.testing.assert_array_equal(
            col.compressed(), [r.quantities[key] for r in series.results if r.success],
            err_msg=f"{key}: read back as exported")
    return back


def test_series_figure_against_time(rigid_series, tmp_path, figures):
    back = _assert_read_back(rigid_series, tmp_path)
    assert back["instants"] == 5 and back["title"] == "ball, vibrating gap"
    for source in (rigid_series, tmp_path):
        out = plot.plot_series(source, tmp_path / "series.png")
        assert out.is_file() and _pixel_std(out) > 0.02, "a blank image has no variance"
        text = _series_texts(figures.saved[-1])
        assert "NOT A" not in text, "a solved series is not stamped"
        for label in ("film [um]", "p_max [MPa]", "[N]", "t [us]", "h0(t), prescribed",
                      "squeeze series (rigid, quasi-steady) - ball, vibrating gap"):
            assert label in text, (label, text)
    axp = figures.saved[-1].axes[1]
    np.testing.assert_allclose(axp.lines[0].get_ydata(), rigid_series.p_max / 1e6,
                               rtol=1e-15, err_msg="the drawn p_max [MPa] is the series'")
    np.testing.assert_allclose(axp.lines[0].get_xdata(), rigid_series.times * 1e6,
                               rtol=1e-15, err_msg="the time axis in us")


def test_series_with_an_unsolved_instant_is_stamped(mixed_series, tmp_path, figures):
    from bearing_fem import cli

    _assert_read_back(mixed_series, tmp_path)
    assert cli.main(["plot", str(tmp_path), "-q"]) == 3, "not a solved series: exit 3"
    assert (tmp_path / "series.png").is_file(), "the default figure beside summary.json"
    text = _series_texts(figures.saved[-1])
    assert "NOT A SOLVED SERIES (status no_solution)" in text, text
    assert "status: no_solution" in text, "the red stamp across the axes"
    assert "1 of 5 instants without solution" in text, "the series' message under the title"
    assert "instant without solution" in text, "the unsolved instant is marked"
    drawn = figures.saved[-1].axes[1].lines[0].get_ydata()
    assert np.ma.is_masked(drawn) and np.ma.getmaskarray(drawn).tolist() == \
        [False, False, True, False, False], "no p_max drawn where there is no solution"


def test_partial_and_empty_series_are_stamped(rigid_series, tmp_path, figures):
    """A series stopped by solver.time_limit after two instants, and one that solved no
    instant (its export is the summary alone): figures stamped, exit code 3."""
    from dataclasses import replace as dc_replace

    from bearing_fem import cli
    from bearing_fem.io import export_series

    stop = ("time_limit", "time_limit: the series stopped after 2 of 5 instants")
    partial = dc_replace(rigid_series, times=rigid_series.times[:2],
                         gap=rigid_series.gap[:2],
                         squeeze_velocity=rigid_series.squeeze_velocity[:2],
                         p_max=rigid_series.p_max[:2], results=rigid_series.results[:2],
                         stop=stop)
    empty = dc_replace(partial, times=partial.times[:0], gap=partial.gap[:0],
                       squeeze_velocity=partial.squeeze_velocity[:0],
                       p_max=partial.p_max[:0], results=[])
    for name, series, n in (("partial", partial, 2), ("empty", empty, 0)):
        back = _assert_read_back(series, tmp_path / name)
        assert back["instants"] == n and back["status"] == "time_limit"
        out = tmp_path / f"{name}.png"
        assert cli.main(["plot", str(tmp_path / name), "--out", str(out), "-q"]) == 3
        assert out.is_file() and _pixel_std(out) > 0.02
        text = _series_texts(figures.saved[-1])
        assert "NOT A SOLVED SERIES (status time_limit)" in text, text
        assert "stopped after 2 of 5 instants" in text, text
        assert ("no instant solved" in text) == (n == 0), text


def test_series_compare_and_cli_refusals(rigid_series, mixed_series, tmp_path, figures,
                                         point_result):
    from bearing_fem import cli
    from bearing_fem.io import export, export_series

    export_series(rigid_series, tmp_path / "a")
    export_series(mixed_series, tmp_path / "b")
    out = tmp_path / "ab.png"
    assert cli.main(["plot", str(tmp_path / "a" / "squeeze.xdmf"), "--compare",
                     str(tmp_path / "b"), "-o", str(out), "-q"]) == 0, \
        "the drawn series decides the exit code"
    text = _series_texts(figures.saved[-1])
    assert "rigid, quasi-steady (status no_solution)" in text, "the compared series named"
    assert "NOT A" not in text, text
    axp = figures.saved[-1].axes[1]
    assert [ln.get_linestyle() for ln in axp.lines[:2]] == ["-", "--"], "compared: dashed"
    n_figures = len(figures.saved)
    refused = [["plot", str(tmp_path / "a"), "--kind", "map", "-o", str(tmp_path / "k.png")],
               ["plot", str(tmp_path / "a"), "--compare", str(tmp_path / "nowhere"),
                "-o", str(tmp_path / "c.png")]]
    export(point_result, tmp_path / "single")
    refused.append(["plot", str(tmp_path / "single"), "--compare", str(tmp_path / "a"),
                    "-o", str(tmp_path / "s.png")])
    for argv in refused:
        assert cli.main(argv) == 2, argv
    from bearing_fem.io import read_series

    with pytest.raises(ValueError, match="not the summary of a squeeze series"):
        read_series(tmp_path / "single")  # a contact result's summary.json
    assert len(figures.saved) == n_figures and not list(tmp_path.glob("[kcs].png")), \
        "a refused plot writes nothing"


@pytest.mark.parametrize("kind", ["map", "line"])
def test_long_title_stays_inside_the_figure(point_result, tmp_path, figures, kind):
    """A title longer than the figure is wide (a bearing contact's map, 5 inches wide for
    the slender ellipse of a deep-groove race, "... element 0 inner (psi = 0.0 deg)", or a
    long scene title) ran off the figure's edge, cut; it is wrapped onto more lines."""
    scene = replace(point_result.scene, title="a long scene title " * 8)
    plot_result(replace(point_result, scene=scene), tmp_path / f"{kind}.png", kind=kind)
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = figures.saved[-1]
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    box = fig.axes[0].title.get_window_extent(renderer)
    width = fig.get_figwidth() * fig.dpi
    assert box.x0 >= -1.0 and box.x1 <= width + 1.0, \
        (box, width, "title within the figure's width (1 px: rounding)")

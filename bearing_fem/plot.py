"""Figures of results, off-screen: matplotlib maps and line plots, pyvista surfaces.

``plot_result(result_or_path, out_png, kind=None)``:

* point contacts, ``kind="map"`` (default): 2D colour map of the pressure [MPa] zoomed on
  the contact, with labelled film-thickness contours [um] whose levels come from the
  film inside the Hertz contact (from its minimum up to the central film, so the
  horseshoe shows), the Hertz ellipse dashed, equal aspect and a colour bar beside the
  axes; ``kind="surface"``: the pressure as a 3D warped surface; ``kind="line"``:
  pressure and film along the centre line y = 0;
* line contacts: pressure and film versus x/b, zoomed on the contact (``kind="line"``;
  ``map`` and ``surface`` are refused with a ValueError).

``plot_series(series_or_path, out_png, compare=())``: a squeeze series (or its export,
read by :func:`bearing_fem.io.read_series`) against time: the films h0(t), h_central and
h_min [um], p_max [MPa] and the film force [N], one point per instant; instants without
solution are marked, a series without success is stamped with its status; ``compare``
draws further series dashed on the same axes. matplotlib (Agg) only.

A result without success is still drawn, but never dressed up as a solution: its title
starts with "NOT A SOLUTION (status ...)" and a red stamp crosses the axes; the field of
a ``no_solution`` result is the isoviscous reduced pressure q (the solver's message says
so), labelled "reduced pressure q", never "pressure".

Maps are drawn by matplotlib (labelled contour lines and a colour bar laid out beside
the axes are its strength). The 3D surface uses pyvista (VTK) off-screen where it works:
before importing pyvista the system libraries are probed with ctypes: libEGL -> set
``VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow``; else libOSMesa ->
``vtkOSOpenGLRenderWindow``; else (or if pyvista/VTK is missing or rendering fails) the
surface is drawn by matplotlib (Agg), so a figure is always produced. The environment
variable ``BEARING_FEM_PLOT_BACKEND=matplotlib`` forces the fallback. pyvista, h5py and
matplotlib are imported inside the functions only.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import logging
import os
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Sequence

import numpy as np

if TYPE_CHECKING:
    from .result import Result

log = logging.getLogger(__name__)

KINDS = ("map", "surface", "line")


@dataclass
class PlotData:
    """Fields to draw (SI). ``pressure``/``film`` are (ny, nx) for points, (n,) for lines."""

    kind: str                 # "point" | "line"
    x: np.ndarray             # m
    y: np.ndarray | None      # m
    pressure: np.ndarray      # Pa (the reduced pressure q for status no_solution)
    film: np.ndarray          # m
    title: str = ""
    x_unit: float | None = None   # Hertz half-width b [m] for line plots, if known
    status: str = "converged"
    success: bool = True
    semi_axes: tuple[float, float] | None = None   # Hertz a_x, a_y [m] (point), if known
    #: surface temperature rises of bodies 1 and 2 [K] at the nodes (thermal line results)
    surface_rise: tuple[np.ndarray, np.ndarray] | None = None


#: Nodal fields of a thermal result drawn by the line plot (``model.thermal = "patch"``).
SURFACE_RISE_FIELDS = ("surface_temperature_rise_body1_K", "surface_temperature_rise_body2_K")


def _surface_rise(fields: dict, n: int) -> tuple[np.ndarray, np.ndarray] | None:
    """Both surface temperature rises [K] if ``fields`` holds them with ``n`` nodes each."""
    arrs = [fields.get(k) for k in SURFACE_RISE_FIELDS]
    if any(a is None for a in arrs):
        return None
    arrs = [np.asarray(a, dtype=float).ravel() for a in arrs]
    return (arrs[0], arrs[1]) if all(a.size == n for a in arrs) else None


def _hertz_of(scene: Any) -> tuple[float | None, tuple[float, float] | None]:
    """(b, (a_x, a_y)) of a scene: the Hertz half-width of a line contact or the semi-axes
    of a point contact, None where Hertz theory does not apply (rigid, prescribed gap)."""
    hertz = None if scene is None else scene.hertz_scales()
    if hertz is None:
        return None, None
    widths = [w for _, w, _, _ in hertz["widths"]]
    if len(widths) == 1:
        return widths[0], None
    return None, (widths[0], widths[1])


def _decode(v: Any) -> str:
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.ndarray) and v.shape == ():
        return _decode(v[()])
    return str(v)


def _from_h5(path: Path) -> PlotData:
    import h5py

    if path.is_dir():
        path = path / "result.h5"
    if not path.is_file():
        raise FileNotFoundError(f"no result file at {str(path)!r} (expected result.h5; "
                                "the output of a squeeze series is drawn by plot_series)")
    with h5py.File(path, "r") as f:
        def find(*names):
            for n in names:
                if n in f:
                    return np.asarray(f[n][()], dtype=float)
                for grp in f.values():  # one level of groups
                    if hasattr(grp, "keys") and n in grp:
                        return np.asarray(grp[n][()], dtype=float)
            return None

        x = find("x", "x_m")
        y = find("y", "y_m")
        p = find("pressure_Pa", "pressure")
        h = find("film_m", "film")
        rise = {k: find(k) for k in SURFACE_RISE_FIELDS}
        kind = _decode(f.attrs.get("kind", "point" if y is not None and y.size > 1 else "line"))
        title = _decode(f.attrs.get("title", ""))
        status = _decode(f.attrs.get("status", "converged"))
        success = bool(f.attrs.get("success", True))
        scene_toml = _decode(f.attrs["scene"]) if "scene" in f.attrs else None
    if x is None or p is None or h is None:
        raise ValueError(f"{str(path)!r} lacks the datasets x, pressure_Pa and film_m")
    b, axes = _hertz_of(_scene_or_none(scene_toml))
    kind = "point" if "point" in kind else "line"
    if kind == "point":
        if y is None:
            raise ValueError(f"{str(path)!r}: a point result needs the dataset y")
        shape = (y.size, x.size)
        if p.shape != shape:
            p = p.reshape(shape) if p.size == x.size * y.size else p.reshape(shape[::-1]).T
            h = h.reshape(p.shape)
    return PlotData(kind, x.ravel(), None if y is None else y.ravel(), p, h, title,
                    x_unit=b, status=status, success=success, semi_axes=axes,
                    surface_rise=_surface_rise(rise, x.size) if kind == "line" else None)


def _scene_or_none(text: str | None) -> Any:
    """The scene stored in a result file, or None if absent or unreadable (the figure
    then goes without Hertz marks)."""
    if not text:
        return None
    from .errors import SceneError
    from .scene import Scene

    try:
        return Scene.from_toml_string(text, source="the scene of the result file")
    except (SceneError, ValueError) as exc:
        log.info("figure without Hertz marks: %s", exc)
        return None


def _from_result(res) -> PlotData:
    scene = getattr(res, "scene", None)
    kind = scene.contact.kind if scene is not None else ("point" if res.y is not None
                                                         else "line")
    title = getattr(scene, "title", "") or ""
    b, axes = _hertz_of(scene)
    p, h = np.asarray(res.pressure, float), np.asarray(res.film, float)
    if kind == "point":
        shape = (np.size(res.y), np.size(res.x))
        p, h = p.reshape(shape), h.reshape(shape)
    return PlotData(kind, np.asarray(res.x, float),
                    None if res.y is None else np.asarray(res.y, float), p, h, title, b,
                    status=str(getattr(res, "status", "converged")),
                    success=bool(getattr(res, "success", True)), semi_axes=axes,
                    surface_rise=(_surface_rise(getattr(res, "extra_fields", None) or {},
                                                np.size(res.x)) if kind == "line" else None))


def load_plot_data(result_or_path: Result | str | os.PathLike) -> PlotData:
    """The fields and metadata a plot needs.

    Parameters
    ----------
    result_or_path : Result or path
        A :class:`~bearing_fem.result.Result`, a ``result.h5`` path or its directory.

    Returns
    -------
    PlotData
        Coordinates [m], pressure [Pa], film [m], kind, status and success.

    Raises
    ------
    TypeError
        Neither a result nor a path.
    """
    if isinstance(result_or_path, (str, os.PathLike)):
        return _from_h5(Path(result_or_path))
    if hasattr(result_or_path, "pressure") and hasattr(result_or_path, "x"):
        return _from_result(result_or_path)
    raise TypeError(f"plot_result needs a Result or a path to result.h5, got "
                    f"{type(result_or_path).__name__}")


# ---------------------------------------------------------------------------------------
def _loadable(name: str) -> bool:
    try:
        ctypes.CDLL(name)
        return True
    except OSError:
        return False


def offscreen_backend() -> str | None:
    """Choose the VTK off-screen window: ``"egl"``, ``"osmesa"`` or None (use matplotlib).

    Sets ``VTK_DEFAULT_OPENGL_WINDOW`` accordingly (unless the user already set it).
    """
    if os.environ.get("BEARING_FEM_PLOT_BACKEND", "").lower() == "matplotlib":
        return None
    if os.environ.get("VTK_DEFAULT_OPENGL_WINDOW"):
        return "user"
    for backend, libs, window in (
            ("egl", ("libEGL.so.1", ctypes.util.find_library("EGL")), "vtkEGLRenderWindow"),
            ("osmesa", ("libOSMesa.so.8", "libOSMesa.so.6", ctypes.util.find_library("OSMesa")),
             "vtkOSOpenGLRenderWindow")):
        if any(lib and _loadable(lib) for lib in libs):
            os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = window
            return backend
    return None


def plot_result(result_or_path: Result | str | os.PathLike, out_png: str | os.PathLike,
                kind: str | None = None, *,
                window_size: tuple[int, int] = (1000, 750)) -> Path:
    """Draw a result to a PNG file, off-screen.

    Parameters
    ----------
    result_or_path : Result or path
        A solve result, or a ``result.h5`` written by :mod:`bearing_fem.io` (datasets
        ``x``, ``y`` [m], ``pressure_Pa``, ``film_m``, attributes ``kind``, ``status``,
        ``success``, ``scene``), or its directory.
    out_png : path
        Output file [PNG].
    kind : {"map", "surface", "line"} or None
        Point contacts: colour map with film contours (default), 3D warped pressure
        surface, or the centre line y = 0. Line contacts: ``"line"`` (default) only.
    window_size : (int, int)
        Pixels of the pyvista surface.

    Returns
    -------
    Path
        The written PNG.

    Raises
    ------
    ValueError
        An unknown ``kind``, or ``"map"``/``"surface"`` for a line contact.
    """
    if kind is not None and kind not in KINDS:
        raise ValueError(f"kind must be one of {', '.join(map(repr, KINDS))}, got {kind!r}")
    data = load_plot_data(result_or_path)
    if kind is None:
        kind = "line" if data.kind == "line" else "map"
    if data.kind == "line" and kind != "line":
        raise ValueError(f"kind {kind!r} applies to point contacts only; a line-contact "
                         "result has the line plot (kind='line')")
    out = Path(out_png)
    out.parent.mkdir(parents=True, exist_ok=True)
    if kind == "line":
        _matplotlib_line(data, out)
    elif kind == "map":
        _matplotlib_map(data, out)
    else:
        if offscreen_backend() is not None:
            try:
                _pyvista_surface(data, out, window_size)
                if out.is_file() and out.stat().st_size > 0:
                    return out
            except Exception as exc:  # no GL context, missing pyvista, ...: fall back
                log.warning("pyvista rendering failed (%s); using matplotlib", exc)
        _matplotlib_surface(data, out)
    return out


# ---------------------------------------------------------------------------------------
# what a figure says: status stamp, field label, zoom window, contour levels
# ---------------------------------------------------------------------------------------
#: Zoom of a point map around the Hertz contact [semi-axes]: x in [-2.5, 1.6] a_x (the
#: inlet meniscus and the outlet constriction), y in +-1.6 a_y.
MAP_WINDOW = ((-2.5, 1.6), (-1.6, 1.6))
#: Zoom of a line plot around the Hertz contact [half-widths b]: the inlet build-up, the
#: pressure spike and the outlet.
LINE_WINDOW = (-3.0, 1.8)
#: Film contour levels of a point map, as fractions of [h_min, h_central] taken inside
#: the Hertz contact: the horseshoe-shaped constriction and its sides.
MAP_LEVELS = (0.1, 0.25, 0.4, 0.55, 0.7, 0.85, 0.95)
#: Without Hertz scales (rigid scenes, a prescribed gap) a figure is zoomed on the nodes
#: where |pressure| exceeds this fraction of its maximum, with a margin of 25%.
PRESSURE_FRACTION = 0.05


def field_label(d: PlotData) -> str:
    """Label of the drawn pressure field: the reduced pressure q for ``no_solution``."""
    if d.status == "no_solution":
        return "reduced pressure q [MPa] (no solution: not a pressure)"
    return "pressure [MPa]" if d.success else "pressure of the last iterate [MPa]"


def figure_title(d: PlotData | SeriesPlotData, what: str) -> str:
    """Title of a figure: ``what``, the scene title, and a status stamp unless solved."""
    text = what + (f" - {d.title}" if d.title else "")
    if not d.success:
        text = f"{_headline(d)} (status {d.status})\n" + text
    return text


def _headline(d: PlotData | SeriesPlotData) -> str:
    return "NOT A SOLVED SERIES" if isinstance(d, SeriesPlotData) else "NOT A SOLUTION"


def _stamp(fig: Any, d: PlotData | SeriesPlotData) -> None:
    """A red stamp across an unsuccessful result's (or series') figure."""
    if d.success:
        return
    fig.text(0.5, 0.5, f"{_headline(d)}\nstatus: {d.status}", color="red", alpha=0.35,
             fontsize=28, fontweight="bold", ha="center", va="center", rotation=20)


def _window(coord: np.ndarray, field: np.ndarray, scale: float | None,
            limits: tuple[float, float]) -> tuple[float, float]:
    """Zoom interval [m] of one axis: ``limits`` x ``scale`` around 0, or where the field
    exceeds :data:`PRESSURE_FRACTION` of its maximum; clipped to the nodes."""
    lo, hi = float(np.min(coord)), float(np.max(coord))
    if scale is not None and scale > 0.0:
        a, b = limits[0] * scale, limits[1] * scale
    else:
        field = np.abs(field)  # full-Sommerfeld fields go negative
        peak = float(np.nanmax(field)) if np.any(np.isfinite(field)) else 0.0
        sel = coord[np.isfinite(field) & (field > PRESSURE_FRACTION * peak)] if peak > 0 \
            else coord[:0]
        if sel.size < 2:
            return lo, hi
        pad = 0.25 * float(np.ptp(sel))
        a, b = float(np.min(sel)) - pad, float(np.max(sel)) + pad
    a, b = max(a, lo), min(b, hi)
    return (a, b) if b > a else (lo, hi)


def _save(fig: Any, ax: Any, d: PlotData, what: str, out: Path) -> None:
    """Title (with the status stamp of an unsuccessful result), save as PNG, close."""
    import matplotlib.pyplot as plt

    ax.set_title(figure_title(d, what), fontsize=10, wrap=True)
    _stamp(fig, d)
    fig.savefig(out, dpi=100)
    plt.close(fig)


def _map_window(d: PlotData) -> tuple[tuple[float, float], tuple[float, float], Any]:
    """Zoom of a point result: x and y intervals [m] and the index of the nodes inside."""
    ax_, ay_ = d.semi_axes if d.semi_axes is not None else (None, None)
    row = d.pressure[int(np.argmin(np.abs(d.y)))]
    col = d.pressure[:, int(np.argmin(np.abs(d.x)))]
    x0, x1 = _window(d.x, row, ax_, MAP_WINDOW[0])
    y0, y1 = _window(d.y, col, ay_, MAP_WINDOW[1])
    ix = np.nonzero((d.x >= x0) & (d.x <= x1))[0]
    iy = np.nonzero((d.y >= y0) & (d.y <= y1))[0]
    return (x0, x1), (y0, y1), np.ix_(iy, ix)


def film_levels(d: PlotData, X: np.ndarray, Y: np.ndarray) -> np.ndarray:
    """Film contour levels [m] of a point map from the film inside the contact.

    Inside the Hertz ellipse (or, without Hertz scales, where the pressure exceeds
    :data:`PRESSURE_FRACTION` of its maximum): the fractions :data:`MAP_LEVELS` of the
    range from the minimum film to the central film (the film at the node nearest the
    origin). Empty when the film is flat there or not finite.
    """
    h = d.film
    if d.semi_axes is not None:
        ax, ay = d.semi_axes
        inside = (X / ax) ** 2 + (Y / ay) ** 2 <= 1.0
    else:
        peak = float(np.nanmax(d.pressure)) if np.any(np.isfinite(d.pressure)) else 0.0
        inside = d.pressure > PRESSURE_FRACTION * peak if peak > 0 else np.ones_like(h, bool)
    inside &= np.isfinite(h)
    if not np.any(inside):
        return np.zeros(0)
    h_min = float(np.min(h[inside]))
    h_c = float(h[int(np.argmin(np.abs(d.y))), int(np.argmin(np.abs(d.x)))])
    if d.semi_axes is None:  # rigid: the film grows from its minimum; show up to twice it
        h_c = 2.0 * h_min if h_min > 0 else h_c
    if not (np.isfinite(h_c) and h_c > h_min):
        return np.zeros(0)
    return h_min + np.asarray(MAP_LEVELS) * (h_c - h_min)


def _matplotlib_map(d: PlotData, out: Path) -> None:
    """Pressure map with labelled film contours and the Hertz ellipse (matplotlib)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib.patches import Ellipse

    X, Y = np.meshgrid(d.x, d.y)
    (x0, x1), (y0, y1), sub = _map_window(d)
    # the figure follows the window's shape (equal aspect), plus room for the colour bar
    width = min(max(5.5 * (x1 - x0) / (y1 - y0) + 2.5, 5.0), 12.0)
    fig, ax = plt.subplots(figsize=(width, 6), layout="constrained")
    mesh = ax.pcolormesh(X[sub] * 1e3, Y[sub] * 1e3, d.pressure[sub] / 1e6, shading="auto",
                         cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=field_label(d), shrink=0.9)
    levels = film_levels(d, X, Y)
    if levels.size:
        cs = ax.contour(X[sub] * 1e3, Y[sub] * 1e3, d.film[sub] * 1e6, levels=levels * 1e6,
                        colors="white", linewidths=1.0)
        ax.clabel(cs, fmt="%.3g", fontsize=7)
    if d.semi_axes is not None:
        ax.add_patch(Ellipse((0.0, 0.0), 2e3 * d.semi_axes[0], 2e3 * d.semi_axes[1], fill=False, color="orange",
                             linestyle="--", linewidth=1.2, label="Hertz contact"))
        ax.legend(loc="upper left", fontsize=8, framealpha=0.6)
    ax.set_aspect("equal")
    ax.set_xlim(x0 * 1e3, x1 * 1e3)
    ax.set_ylim(y0 * 1e3, y1 * 1e3)
    ax.set_xlabel("x [mm] (rolling direction)")
    ax.set_ylabel("y [mm]")
    _save(fig, ax, d, "pressure, film contours [um]", out)


def _matplotlib_surface(d: PlotData, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    _, _, sub = _map_window(d)
    X, Y = np.meshgrid(d.x * 1e3, d.y * 1e3)
    fig = plt.figure(figsize=(8, 6))
    ax = fig.add_subplot(projection="3d")
    ax.plot_surface(X[sub], Y[sub], d.pressure[sub] / 1e6, cmap="viridis")
    ax.set_zlabel(field_label(d))
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    _save(fig, ax, d, "pressure surface", out)


def _pyvista_surface(d: PlotData, out: Path, window_size) -> None:
    import pyvista as pv

    _, _, sub = _map_window(d)
    X, Y = np.meshgrid(d.x * 1e3, d.y * 1e3)
    X, Y, p_mpa = X[sub], Y[sub], d.pressure[sub] / 1e6
    span = max(float(np.ptp(X)), float(np.ptp(Y)))
    zscale = 0.4 * span / max(float(np.max(np.abs(p_mpa))), 1e-300)
    grid = pv.StructuredGrid(X, Y, p_mpa * zscale)
    label = field_label(d)
    grid[label] = p_mpa.ravel(order="F")
    plotter = pv.Plotter(off_screen=True, window_size=list(window_size))
    plotter.set_background("white")
    plotter.add_mesh(grid, scalars=label, cmap="viridis",
                     scalar_bar_args={"title": label, "color": "black", "vertical": True,
                                      "position_x": 0.86, "position_y": 0.15,
                                      "height": 0.7, "width": 0.05})
    plotter.view_isometric()
    plotter.add_text(figure_title(d, "pressure surface"), font_size=10,
                     color="black" if d.success else "red")
    # the heights are the pressure scaled to the plan size: label the z axis with the
    # pressure itself (axes_ranges maps the bounds linearly onto the given ranges)
    plotter.show_bounds(xtitle="x [mm]", ytitle="y [mm]", ztitle=label, color="black",
                        axes_ranges=[float(X.min()), float(X.max()), float(Y.min()),
                                     float(Y.max()), float(p_mpa.min()), float(p_mpa.max())],
                        fmt="%.3g")
    plotter.screenshot(str(out))
    plotter.close()


def _matplotlib_line(d: PlotData, out: Path) -> None:
    """Pressure and film along x (the centre line y = 0 of a point contact), zoomed on the
    contact: :data:`LINE_WINDOW` Hertz half-widths, or the pressurised region; a thermal
    line result adds its two surface temperature rises in a panel below."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    what = "line contact"
    if d.kind == "point":  # centre line y = 0, or the grid line nearest to it
        j = int(np.argmin(np.abs(d.y)))
        p, h = d.pressure[j], d.film[j]
        scale = None if d.semi_axes is None else d.semi_axes[0]
        what = ("centre line y = 0" if d.y[j] == 0.0 else
                f"grid line y = {d.y[j] * 1e3:.3g} mm (no node row at y = 0)")
    else:
        p, h = d.pressure, d.film
        scale = d.x_unit
    x0, x1 = _window(d.x, p, scale, LINE_WINDOW)
    if scale:
        xs, xlabel = d.x / scale, ("x/b [-]" if d.kind == "line" else "x/a_x [-]")
        lim = (x0 / scale, x1 / scale)
    else:
        xs, xlabel, lim = d.x * 1e3, "x [mm]", (x0 * 1e3, x1 * 1e3)
    if d.surface_rise is not None:  # thermal result: the surface temperatures below
        fig, (ax, axt) = plt.subplots(2, 1, figsize=(8, 7), layout="constrained",
                                      sharex=True, height_ratios=(3, 2))
        axt.plot(xs, d.surface_rise[0], color="tab:orange", label="surface 1")
        axt.plot(xs, d.surface_rise[1], color="tab:green", linestyle="--", label="surface 2")
        axt.set_ylabel("temperature rise [K]")
        axt.set_xlabel(xlabel)
        axt.legend(loc="upper left", fontsize=8)
    else:
        fig, ax = plt.subplots(figsize=(8, 5), layout="constrained")
    ax.plot(xs, p / 1e6, color="tab:blue", label="pressure")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(field_label(d), color="tab:blue")
    ax.set_xlim(*lim)
    ax2 = ax.twinx()
    ax2.plot(xs, h * 1e6, color="tab:red", label="film")
    ax2.set_ylabel("film [um]", color="tab:red")
    shown = h[(d.x >= x0) & (d.x <= x1) & np.isfinite(h)] * 1e6
    if shown.size:
        lo, top = float(np.min(shown)), float(np.max(shown))
        centre = float(h[int(np.argmin(np.abs(d.x)))]) * 1e6
        ref = max(lo, centre) if np.isfinite(centre) else lo
        top = min(top, 4.0 * ref) if ref > 0 else top
        ax2.set_ylim(min(0.0, lo), max(top * 1.05, 1e-9))
    _save(fig, ax, d, what, out)


# ---------------------------------------------------------------------------------------
# squeeze series: the per-instant quantities against time
# ---------------------------------------------------------------------------------------
@dataclass
class SeriesPlotData:
    """A squeeze series to draw against time (SI). The solved columns are masked arrays,
    masked at the instants without solution."""

    times: np.ndarray               # s
    gap: np.ndarray                 # h0(t) [m], prescribed
    p_max: np.ma.MaskedArray        # Pa
    h_min: np.ma.MaskedArray        # m
    h_central: np.ma.MaskedArray    # m
    load: np.ma.MaskedArray         # film force int p dA [N]
    title: str = ""
    status: str = "converged"
    success: bool = True
    message: str = ""
    #: "rigid, quasi-steady", "elastic, bdf2", ...: names the series in a legend
    label: str = "series"


def _series_label(summary: dict) -> str:
    scene = summary.get("scene")
    model = scene.get("model") if isinstance(scene, dict) else None
    elasticity = model.get("elasticity") if isinstance(model, dict) else None
    what = {"rigid": "rigid", "half-space": "elastic"}.get(str(elasticity), "")
    scheme = str(summary.get("scheme") or "")
    return ", ".join(x for x in (what, scheme) if x) or "series"


def load_series_data(series_or_path: Any) -> SeriesPlotData:
    """The per-instant quantities of a squeeze series, to draw against time.

    Parameters
    ----------
    series_or_path : SqueezeSeries, ElasticSqueezeSeries or path
        A series (anything with ``summary()`` of a squeeze series), or an export of
        :func:`bearing_fem.io.export_series` (its directory, its ``summary.json`` or one
        of its files), read by :func:`bearing_fem.io.read_series`.

    Returns
    -------
    SeriesPlotData
        t [s], h0(t) [m], p_max [Pa], h_min and h_central [m], load [N] (masked where an
        instant has no solution), title, status, success, message and a legend label.

    Raises
    ------
    ValueError
        Not a squeeze series (see :func:`bearing_fem.io.read_series`).
    TypeError
        Neither a series nor a path.
    """
    from .io import read_series, series_from_summary

    if isinstance(series_or_path, (str, os.PathLike)):
        s = read_series(series_or_path)
    elif hasattr(series_or_path, "summary") and hasattr(series_or_path, "times"):
        s = series_from_summary(series_or_path.summary())
    else:
        raise TypeError(f"plot_series needs a squeeze series or the path of its export, "
                        f"got {type(series_or_path).__name__}")
    return SeriesPlotData(times=s["times"], gap=s["gap"], p_max=s["p_max"],
                          h_min=s["h_min"], h_central=s["h_central"], load=s["load"],
                          title=s["title"], status=str(s["status"]),
                          success=bool(s["success"]), message=str(s.get("message", "")),
                          label=_series_label(s))


def _time_unit(times: list[np.ndarray]) -> tuple[float, str]:
    """Scale and name of the time axis: us below 1 ms, ms below 1 s, else s."""
    top = max((float(np.max(np.abs(t))) for t in times if t.size), default=0.0)
    if 0.0 < top < 1e-3:
        return 1e6, "us"
    if 0.0 < top < 1.0:
        return 1e3, "ms"
    return 1.0, "s"


def plot_series(series_or_path: Any, out_png: str | os.PathLike, *,
                compare: Sequence[Any] = ()) -> Path:
    """Draw a squeeze series against time to a PNG, off-screen (matplotlib, Agg).

    Three panels over t: the films (the prescribed rigid offset h0(t), the central film
    h_central and the minimum film h_min) [um], the maximum pressure p_max [MPa] and the
    film force (``load``, int p dA) [N]. Instants without solution are marked by red
    dotted vertical lines and leave a gap in the solved curves. A series without success
    is stamped with its status (title "NOT A SOLVED SERIES (status ...)", its message
    below, a red stamp across the figure), as :func:`plot_result` stamps a failed result.

    Parameters
    ----------
    series_or_path : SqueezeSeries, ElasticSqueezeSeries or path
        The series, or its export (see :func:`load_series_data`).
    out_png : path
        Output file [PNG].
    compare : sequence of series or paths
        Further series drawn dashed on the same axes (e.g. the rigid or elastic
        quasi-steady series of the same scene), each named by its model and scheme.

    Returns
    -------
    Path
        The written PNG.
    """
    import textwrap

    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    d = load_series_data(series_or_path)
    others = [load_series_data(c) for c in compare]
    out = Path(out_png)
    out.parent.mkdir(parents=True, exist_ok=True)
    scale, unit = _time_unit([d.times] + [o.times for o in others])
    fig, (axh, axp, axf) = plt.subplots(3, 1, figsize=(8, 9), sharex=True,
                                        layout="constrained")
    colours = ("tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown")
    for k, s in enumerate([d] + others):
        c, ls = colours[k % len(colours)], "-" if k == 0 else "--"
        # the title names the drawn series' status; a compared one's is in its label
        name = s.label + ("" if s.success or k == 0 else f" (status {s.status})")
        t = s.times * scale
        same_gap = (k > 0 and s.times.shape == d.times.shape
                    and np.allclose(s.times, d.times) and np.allclose(s.gap, d.gap))
        if not same_gap:  # a compared series on the same h0(t) does not repeat it
            axh.plot(t, s.gap * 1e6, color="black" if k == 0 else c, linewidth=0.9,
                     linestyle="-" if k == 0 else ":",
                     label="h0(t), prescribed" + (f" ({s.label})" if k else ""))
        axh.plot(t, s.h_central * 1e6, color=c, linestyle=ls, marker=".",
                 label=f"h_central, {name}")
        axh.plot(t, s.h_min * 1e6, color=c, linestyle="-." if k == 0 else (0, (1, 2)),
                 marker="v", markersize=3, label=f"h_min, {name}")
        axp.plot(t, s.p_max / 1e6, color=c, linestyle=ls, marker=".", label=name)
        axf.plot(t, s.load, color=c, linestyle=ls, marker=".", label=name)
        failed = t[np.ma.getmaskarray(s.p_max)]
        for ax in (axh, axp, axf):
            for j, tf in enumerate(failed):
                ax.axvline(tf, color="red", linestyle=":", linewidth=1.0,
                           label="instant without solution" if j == 0 and ax is axp else None)
    if d.times.size == 0:
        axp.text(0.5, 0.85, "no instant solved", transform=axp.transAxes, ha="center",
                 va="center", color="red")
    axf.axhline(0.0, color="grey", linewidth=0.5)
    axh.set_ylabel("film [um]")
    axp.set_ylabel("p_max [MPa]")
    axf.set_ylabel("load: film force int p dA [N]")
    axf.set_xlabel(f"t [{unit}]")
    for ax in (axh, axp, axf):
        ax.grid(True, linewidth=0.3)
        handles, _ = ax.get_legend_handles_labels()
        if handles:
            ax.legend(fontsize=7, loc="best", framealpha=0.6)
    title = figure_title(d, f"squeeze series ({d.label})")
    if not d.success and d.message:
        title += "\n" + "\n".join(textwrap.wrap(d.message, 110, max_lines=3))
    axh.set_title(title, fontsize=9)
    _stamp(fig, d)
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out

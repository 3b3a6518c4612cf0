"""Figures of results, off-screen: pyvista for point-contact maps, matplotlib otherwise.

``plot_result(result_or_path, out_png, kind=...)``:

* point contacts, ``kind="map"``: 2D colour map of the pressure [Pa] with film-thickness
  [m] contour lines; ``kind="surface"``: the pressure as a 3D warped surface;
  ``kind="line"``: pressure and film along the centre line y = 0 (matplotlib);
* line contacts: pressure and film versus x/b (matplotlib, any ``kind``).

Headless rendering: pyvista (VTK) needs an off-screen OpenGL context. Before importing
pyvista we probe the system libraries with ctypes: libEGL -> set
``VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow``; else libOSMesa ->
``vtkOSOpenGLRenderWindow``; else (or if pyvista/VTK is missing or rendering fails) the
figure is drawn by matplotlib (Agg), so a figure is always produced. The environment
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
from typing import Any

import numpy as np

log = logging.getLogger(__name__)

KINDS = ("map", "surface", "line")


@dataclass
class PlotData:
    """Fields to draw (SI). ``pressure``/``film`` are (ny, nx) for points, (n,) for lines."""

    kind: str                 # "point" | "line"
    x: np.ndarray             # m
    y: np.ndarray | None      # m
    pressure: np.ndarray      # Pa
    film: np.ndarray          # m
    title: str = ""
    x_unit: float | None = None   # Hertz half-width b [m] for line plots, if known


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
        raise FileNotFoundError(f"no result file at {str(path)!r} (expected result.h5)")
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
        kind = _decode(f.attrs.get("kind", "point" if y is not None and y.size > 1 else "line"))
        title = _decode(f.attrs.get("title", ""))
    if x is None or p is None or h is None:
        raise ValueError(f"{str(path)!r} lacks the datasets x, pressure_Pa and film_m")
    kind = "point" if "point" in kind else "line"
    if kind == "point":
        if y is None:
            raise ValueError(f"{str(path)!r}: a point result needs the dataset y")
        shape = (y.size, x.size)
        if p.shape != shape:
            p = p.reshape(shape) if p.size == x.size * y.size else p.reshape(shape[::-1]).T
            h = h.reshape(p.shape)
    return PlotData(kind, x.ravel(), None if y is None else y.ravel(), p, h, title)


def _from_result(res) -> PlotData:
    scene = getattr(res, "scene", None)
    kind = scene.contact.kind if scene is not None else ("point" if res.y is not None
                                                         else "line")
    title = getattr(scene, "title", "") or ""
    x_unit = None
    if kind == "line" and scene is not None and scene.load.force is not None \
            and scene.e_prime is not None:
        from .units import hertz_line

        x_unit = hertz_line(scene.load.force, scene.contact.rx, scene.e_prime)[0]
    p, h = np.asarray(res.pressure, float), np.asarray(res.film, float)
    if kind == "point":
        shape = (np.size(res.y), np.size(res.x))
        p, h = p.reshape(shape), h.reshape(shape)
    return PlotData(kind, np.asarray(res.x, float),
                    None if res.y is None else np.asarray(res.y, float), p, h, title, x_unit)


def load_plot_data(result_or_path) -> PlotData:
    """A :class:`~bearing_fem.result.Result`, a ``result.h5`` path or its directory."""
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


def plot_result(result_or_path, out_png: str | os.PathLike, kind: str = "map", *,
                window_size: tuple[int, int] = (1000, 750)) -> Path:
    """Draw a result to a PNG file, off-screen.

    Parameters
    ----------
    result_or_path : Result or path
        A solve result, or a ``result.h5`` written by :mod:`bearing_fem.io` (datasets
        ``x``, ``y`` [m], ``pressure_Pa``, ``film_m``, attribute ``kind``), or its directory.
    out_png : path
        Output file [PNG].
    kind : {"map", "surface", "line"}
        Point contacts: colour map with film contours, 3D warped pressure surface, or the
        centre line y = 0. Line contacts always give the line plot.
    window_size : (int, int)
        Pixels.

    Returns
    -------
    Path
        The written PNG.
    """
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {', '.join(map(repr, KINDS))}, got {kind!r}")
    data = load_plot_data(result_or_path)
    out = Path(out_png)
    out.parent.mkdir(parents=True, exist_ok=True)
    if data.kind == "line" or kind == "line":
        _matplotlib_line(data, out)
        return out
    backend = offscreen_backend()
    if backend is not None:
        try:
            _pyvista_point(data, out, kind, window_size)
            if out.is_file() and out.stat().st_size > 0:
                return out
        except Exception as exc:  # no GL context, missing pyvista, ...: fall back
            log.warning("pyvista rendering failed (%s); using matplotlib", exc)
    _matplotlib_point(data, out, kind)
    return out


def _pyvista_point(d: PlotData, out: Path, kind: str, window_size) -> None:
    import pyvista as pv

    x_mm, y_mm = d.x * 1e3, d.y * 1e3
    X, Y = np.meshgrid(x_mm, y_mm)
    p_mpa = d.pressure / 1e6
    span = max(float(np.ptp(x_mm)), float(np.ptp(y_mm)))
    zscale = 0.0
    if kind == "surface":
        zscale = 0.4 * span / max(float(np.max(np.abs(p_mpa))), 1e-300)
    grid = pv.StructuredGrid(X, Y, p_mpa * zscale)
    grid["pressure_MPa"] = p_mpa.ravel(order="F")
    grid["film_um"] = (d.film * 1e6).ravel(order="F")
    plotter = pv.Plotter(off_screen=True, window_size=list(window_size))
    plotter.set_background("white")
    plotter.add_mesh(grid, scalars="pressure_MPa", cmap="viridis",
                     scalar_bar_args={"title": "pressure [MPa]", "color": "black"})
    if kind == "map":
        h = d.film * 1e6
        lo, hi = float(np.min(h)), float(np.percentile(h, 60))
        if hi > lo:
            levels = np.linspace(lo, hi, 8)[1:]
            cont = grid.contour(isosurfaces=list(levels), scalars="film_um")
            if cont.n_points:
                cont.points[:, 2] += 1e-3 * span
                plotter.add_mesh(cont, color="white", line_width=2)
        plotter.view_xy()
        plotter.add_text("pressure, film contours [um]" + (f" - {d.title}" if d.title else ""),
                         font_size=10, color="black")
    else:
        plotter.view_isometric()
        plotter.add_text("pressure surface" + (f" - {d.title}" if d.title else ""),
                         font_size=10, color="black")
    plotter.show_bounds(xtitle="x [mm]", ytitle="y [mm]",
                        ztitle="p (scaled)" if kind == "surface" else " ", color="black")
    plotter.screenshot(str(out))
    plotter.close()


def _matplotlib_point(d: PlotData, out: Path, kind: str) -> None:
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    X, Y = np.meshgrid(d.x * 1e3, d.y * 1e3)
    fig = plt.figure(figsize=(8, 6))
    if kind == "surface":
        ax = fig.add_subplot(projection="3d")
        ax.plot_surface(X, Y, d.pressure / 1e6, cmap="viridis")
        ax.set_zlabel("pressure [MPa]")
    else:
        ax = fig.add_subplot()
        cf = ax.pcolormesh(X, Y, d.pressure / 1e6, shading="auto", cmap="viridis")
        fig.colorbar(cf, ax=ax, label="pressure [MPa]")
        h = d.film * 1e6
        lo, hi = float(np.min(h)), float(np.percentile(h, 60))
        if hi > lo:
            cs = ax.contour(X, Y, h, levels=np.linspace(lo, hi, 8)[1:], colors="white",
                            linewidths=1)
            ax.clabel(cs, fmt="%.3g", fontsize=7)
        ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(("pressure, film contours [um]" if kind != "surface" else "pressure")
                 + (f" - {d.title}" if d.title else ""))
    fig.savefig(out, dpi=100)
    plt.close(fig)


def _matplotlib_line(d: PlotData, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    if d.kind == "point":  # centre line y = 0
        j = int(np.argmin(np.abs(d.y)))
        p, h = d.pressure[j], d.film[j]
    else:
        p, h = d.pressure, d.film
    if d.x_unit:
        xs, xlabel = d.x / d.x_unit, "x/b [-]"
    else:
        xs, xlabel = d.x * 1e3, "x [mm]"
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(xs, p / 1e6, color="tab:blue", label="pressure")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("pressure [MPa]", color="tab:blue")
    ax2 = ax.twinx()
    ax2.plot(xs, h * 1e6, color="tab:red", label="film")
    ax2.set_ylabel("film [um]", color="tab:red")
    hmin = float(np.min(h)) * 1e6
    ax2.set_ylim(0.0, max(5 * hmin, hmin + 1e-9))
    ax.set_title(("centre line y = 0" if d.kind == "point" else "line contact")
                 + (f" - {d.title}" if d.title else ""))
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)

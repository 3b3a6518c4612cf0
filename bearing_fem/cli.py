"""Command line: ``bearing-fem solve | demo | plot`` (see ``docs/cli.md``).

The only module of the package that prints or exits. Exit codes (INTERFACE.md 2):

* 0 -- solved (status ``converged`` or ``linear``), or a plot written;
* 2 -- invalid input: a scene error (the message names the field, value and unit),
  an unreadable or malformed TOML file, a bad command line, an unwritable output
  directory or an unreadable result file. One line on stderr, no traceback;
* 3 -- no converged solution (``max_iterations``, ``stalled``, ``diverged``) or no
  solution exists (``no_solution``); the files are still written, with the status.
"""
from __future__ import annotations

import argparse
import logging
import sys
from pathlib import Path
from typing import Any, Sequence

EXIT_OK = 0
EXIT_INVALID = 2
EXIT_NO_SOLUTION = 3

#: Default output directory of ``bearing-fem demo``.
DEMO_DIR = "bearing_fem_demo"
#: Figure written by ``bearing-fem demo``.
DEMO_PNG = "pressure_film.png"

log = logging.getLogger("bearing_fem.cli")


class _InputError(Exception):
    """Invalid user input detected by the CLI itself (exit code 2)."""


# ---------------------------------------------------------------------------------------
# printing
# ---------------------------------------------------------------------------------------
def _fmt(value: Any, unit: str = "") -> str:
    if value is None:
        return "n/a"
    try:
        text = f"{float(value):.4g}"
    except (TypeError, ValueError):
        return str(value)
    return f"{text} {unit}".rstrip()


def _print_summary(result: Any, files: dict[str, Path] | None) -> None:
    """Short human summary of a result on stdout."""
    s = result.summary()
    units = s.get("units", {})
    title = getattr(result.scene, "title", "") or "scene"
    rows = [
        ("status", f"{s['status']} ({'success' if s['success'] else 'no success'})"),
        ("h_central", _fmt(s.get("h_central"), units.get("h_central", "m"))),
        ("h_min", _fmt(s.get("h_min"), units.get("h_min", "m"))),
        ("p_max", _fmt(s.get("p_max"), units.get("p_max", "Pa"))),
        ("friction coefficient", _fmt(s.get("friction_coefficient"))),
        ("heat power", _fmt(s.get("heat_power"), units.get("heat_power", "W"))),
        ("iterations", f"{s.get('newton_iterations', 0)} Newton, "
                       f"{s.get('linear_solves', 0)} linear solves"),
        ("wall time", _fmt(s.get("wall_time_s"), "s")),
        ("dofs", str(s.get("dofs", "n/a"))),
    ]
    print(title)
    for name, value in rows:
        print(f"  {name:<21} {value}")
    print(f"  {'message':<21} {s['message']}")
    if files:
        print(f"  {'wrote':<21} " + ", ".join(str(p) for p in files.values()))


def _report_status(result: Any) -> int:
    """Exit code of a result, with a one-line explanation on stderr when unsuccessful."""
    if result.success:
        return EXIT_OK
    history = list(getattr(result, "history", []) or [])
    residual = f", last scaled residual {history[-1]:.3e}" if history else ""
    what = "no solution exists" if result.status == "no_solution" else "no converged solution"
    print(f"bearing-fem: {what} (status {result.status}{residual}): {result.message}",
          file=sys.stderr)
    return EXIT_NO_SOLUTION


# ---------------------------------------------------------------------------------------
# plotting (plot.py when available, else a minimal matplotlib line plot)
# ---------------------------------------------------------------------------------------
def _fallback_plot(source: Any, out_png: Path) -> Path:
    """Pressure and film along x (the centre line y ~ 0 of a point contact), matplotlib Agg."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    if isinstance(source, (str, Path)):
        from .io import read_result

        data = read_result(source)
        x, y, p, h = data["x"], data["y"], data["pressure_Pa"], data["film_m"]
        title = data["scene"].get("title", "") + f" ({data['status']})"
    else:
        x, y, p, h = source.x, source.y, source.pressure, source.film
        title = f"{getattr(source.scene, 'title', '')} ({source.status})"
    x, p, h = np.asarray(x, float), np.asarray(p, float), np.asarray(h, float)
    if y is not None:  # point contact: take the row of nodes nearest to y = 0
        y = np.asarray(y, float)
        if x.ndim == 1 and y.ndim == 1 and x.size * y.size == p.size and x.size != p.size:
            row = int(np.argmin(np.abs(y)))
            p, h = p.reshape(y.size, x.size)[row], h.reshape(y.size, x.size)[row]
        else:
            x, y, p, h = x.ravel(), y.ravel(), p.ravel(), h.ravel()
            sel = np.isclose(y, y[np.argmin(np.abs(y))])
            order = np.argsort(x[sel])
            x, p, h = x[sel][order], p[sel][order], h[sel][order]
    fig, ax1 = plt.subplots(figsize=(7, 4))
    ax1.plot(x * 1e3, p / 1e6, color="C0")
    ax1.set_xlabel("x [mm]")
    ax1.set_ylabel("pressure [MPa]", color="C0")
    ax2 = ax1.twinx()
    ax2.plot(x * 1e3, h * 1e6, color="C1")
    ax2.set_ylabel("film [um]", color="C1")
    hc = float(np.interp(0.0, x, h)) if x.size > 1 else float(h[0])
    ax2.set_ylim(0.0, max(4.0 * hc, 1e-12) * 1e6)
    ax1.set_title(title.strip())
    fig.tight_layout()
    out_png.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out_png, dpi=120)
    plt.close(fig)
    return out_png


def _plot(source: Any, out_png: Path, kind: str | None) -> Path:
    """Plot with :func:`bearing_fem.plot.plot_result`; fall back to a matplotlib line plot."""
    if kind is None:
        is_line = (getattr(source, "y", None) is None) if not isinstance(source, (str, Path)) \
            else _h5_kind(source) == "line"
        kind = "line" if is_line else "map"
    try:
        from .plot import plot_result

        plot_result(source, out_png, kind=kind)
        if not Path(out_png).is_file():
            raise RuntimeError(f"plot_result did not write {out_png}")
        return Path(out_png)
    except Exception as exc:  # plot.py missing or failing (e.g. no rendering libraries)
        log.warning("bearing_fem.plot unavailable or failed (%s: %s); writing a "
                    "matplotlib line plot instead", type(exc).__name__, exc)
        return _fallback_plot(source, Path(out_png))


def _h5_kind(path: str | Path) -> str:
    import h5py

    with h5py.File(path, "r") as f:
        return str(f.attrs["kind"])


# ---------------------------------------------------------------------------------------
# subcommands
# ---------------------------------------------------------------------------------------
def _export(result: Any, outdir: Path) -> dict[str, Path]:
    from .io import export

    try:
        return export(result, outdir)
    except OSError as exc:
        raise _InputError(f"cannot write results to {str(outdir)!r}: "
                          f"{exc.strerror or exc}") from None


def _solve_and_write(scene: Any, outdir: Path, png: Path | None = None) -> int:
    from .contacts.dispatch import solve

    log.info("solving %r", getattr(scene, "title", ""))
    result = solve(scene)
    files = _export(result, outdir)
    if png is not None:
        files["png"] = _plot(result, png, None)
    _print_summary(result, files)
    return _report_status(result)


def _cmd_solve(args: argparse.Namespace) -> int:
    from .scene import Scene

    scene = Scene.from_toml(args.scene)
    return _solve_and_write(scene, Path(args.out))


def _cmd_demo(args: argparse.Namespace) -> int:
    from dataclasses import replace

    from .scene import load_embedded

    scene = load_embedded("roller")
    if args.nodes is not None:
        scene = replace(scene, mesh=replace(scene.mesh, nodes=args.nodes))
    out = Path(args.out)
    return _solve_and_write(scene, out, png=out / DEMO_PNG)


def _cmd_plot(args: argparse.Namespace) -> int:
    path = Path(args.result)
    if path.is_dir():
        path = path / "result.h5"
    if not path.is_file():
        raise _InputError(f"no result file {str(path)!r} (give a result.h5 written by "
                          "'bearing-fem solve')")
    try:
        _h5_kind(path)
    except (OSError, KeyError) as exc:
        raise _InputError(f"{str(path)!r} is not a bearing_fem result.h5: {exc}") from None
    out = Path(args.out) if args.out else path.with_suffix(".png")
    written = _plot(path, out, args.kind)
    print(f"wrote {written}")
    return EXIT_OK


def _cmd_bearing(args: argparse.Namespace) -> int:
    """``bearing-fem bearing FILE --out DIR``: solve a bearing file (docs/bearing.md)."""
    from .bearing import Bearing, example_names, load_example, solve_bearing
    from .io import export_bearing

    path = Path(args.bearing)
    if not path.is_file() and args.bearing in example_names():
        bearing = load_example(args.bearing)
    else:
        bearing = Bearing.from_toml(path)
    result = solve_bearing(bearing)
    out = Path(args.out)
    try:
        files = export_bearing(result, out)
        if not args.no_figures:
            from .plot_bearing import write_figures

            files.update(write_figures(result, out))
    except OSError as exc:
        raise _InputError(f"cannot write results to {str(out)!r}: {exc.strerror or exc}") \
            from None
    s = result.summary()
    print(bearing.title or bearing.geometry.type)
    loc = s.get("h_min_location") or {}
    rows = [("status", f"{s['status']} ({'success' if s['success'] else 'no success'})"),
            ("friction torque", _fmt(s["friction_torque"], "N m")),
            ("heat power", _fmt(s["heat_power"], "W")),
            ("h_min", _fmt(s["h_min"], "m") + (f" (element {loc['element']}, "
                                                f"{loc['raceway']})" if loc else "")),
            ("p_max", _fmt(s["p_max"], "Pa"))]
    for name, m in s["empirical"].items():
        if m.get("torque") is not None:
            rows.append((f"{name} torque", _fmt(m["torque"], "N m")))
    rows.append(("wall time", _fmt(s["wall_time_s"], "s")))
    for name, value in rows:
        print(f"  {name:<24} {value}")
    print(f"  {'message':<24} {s['message']}")
    for w in s["warnings"]:
        print(f"  {'warning':<24} {w}")
    print(f"  {'wrote':<24} " + ", ".join(str(p) for p in files.values()))
    if result.success:
        return EXIT_OK
    print(f"bearing-fem: no complete bearing solution (status {result.status}): "
          f"{result.message}", file=sys.stderr)
    return EXIT_NO_SOLUTION


# ---------------------------------------------------------------------------------------
def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``bearing-fem`` (subcommands solve, demo, plot)."""
    from . import __version__

    parser = argparse.ArgumentParser(
        prog="bearing-fem",
        description="Finite-element EHL solver for rolling-bearing contacts: film, "
                    "pressure, friction and heat of line and point contacts.",
        epilog="Exit codes: 0 solved; 2 invalid input; 3 no converged solution or no "
               "solution exists (files are still written). Docs: docs/cli.md.")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.add_argument("-v", "--verbose", action="count", default=0,
                        help="log progress to stderr (-v info, -vv debug)")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = sub.add_parser("solve", help="solve a TOML scene and write summary.json, "
                                     "result.h5 and fields.vtu",
                       description="Solve a scene file (docs/scenes.md) and write "
                                   "DIR/summary.json, DIR/result.h5 and DIR/fields.vtu.")
    p.add_argument("scene", metavar="SCENE.toml", help="scene file")
    p.add_argument("--out", "-o", metavar="DIR", required=True, help="output directory")
    p.set_defaults(func=_cmd_solve)

    p = sub.add_parser("demo", help="solve the embedded roller scene and plot it",
                       description="Solve the embedded example scene 'roller' (a steel "
                                   "roller on an inner ring) and write summary.json, "
                                   f"result.h5, fields.vtu and {DEMO_PNG}.")
    p.add_argument("--out", "-o", metavar="DIR", default=DEMO_DIR,
                   help=f"output directory (default: {DEMO_DIR}/)")
    p.add_argument("--nodes", type=int, default=None, metavar="N",
                   help="override the mesh node count (default: the scene's automatic "
                        "mesh); a coarse mesh, e.g. 401, gives a quick look")
    p.set_defaults(func=_cmd_demo)

    p = sub.add_parser("plot", help="plot a result.h5",
                       description="Plot a result.h5 written by 'bearing-fem solve' or "
                                   "'bearing-fem demo'.")
    p.add_argument("result", metavar="RESULT_H5", help="result.h5 (or its directory)")
    p.add_argument("--out", "-o", metavar="PNG", default=None,
                   help="figure file (default: RESULT_H5 with the suffix .png)")
    p.add_argument("--kind", choices=("map", "surface", "line"), default=None,
                   help="figure kind (default: line for line contacts, map for point "
                        "contacts)")
    p.set_defaults(func=_cmd_plot)

    p = sub.add_parser("bearing", help="solve a bearing file: EHL at every rolling element",
                       description="Solve a bearing file (docs/bearing.md; a shipped example "
                                   "name such as 6209 also works) and write "
                                   "DIR/bearing_summary.json, elements.csv, contacts.vtm, "
                                   "the most loaded element's contact files and figures.")
    p.add_argument("bearing", metavar="BEARING.toml", help="bearing file or example name")
    p.add_argument("--out", "-o", metavar="DIR", required=True, help="output directory")
    p.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    p.set_defaults(func=_cmd_bearing)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``bearing-fem``; returns the exit code (see module docstring).

    Parameters
    ----------
    argv : sequence of str, optional
        Arguments without the program name (default: ``sys.argv[1:]``).
    """
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version (0) or a usage error (2)
        return int(exc.code or 0)
    level = {0: logging.WARNING, 1: logging.INFO}.get(args.verbose, logging.DEBUG)
    logging.basicConfig(level=level, format="%(levelname)s %(name)s: %(message)s",
                        stream=sys.stderr)
    logging.getLogger("bearing_fem").setLevel(level)

    from .errors import SceneError

    try:
        return int(args.func(args))
    except SceneError as exc:
        print(f"bearing-fem: invalid input: {exc}", file=sys.stderr)
        return EXIT_INVALID
    except UnicodeDecodeError as exc:
        print(f"bearing-fem: invalid input: the scene file is not UTF-8 text ({exc})",
              file=sys.stderr)
        return EXIT_INVALID
    except _InputError as exc:
        print(f"bearing-fem: invalid input: {exc}", file=sys.stderr)
        return EXIT_INVALID


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

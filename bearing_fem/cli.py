"""Command line: ``bearing-fem solve | demo | plot | bearing | bench | sweep | runs`` (see
``docs/cli.md``).

The only module of the package that prints or exits. Exit codes:

* 0 -- solved (status ``converged`` or ``linear``), or a plot of a solved result written;
* 2 -- invalid input: a scene error (the message names the field, value and unit),
  an unreadable or malformed TOML file, a bad command line, an unwritable output
  directory, an unreadable result file or a plot option that does not apply. One line
  on stderr, no traceback, nothing written;
* 3 -- no converged solution (``max_iterations``, ``stalled``, ``diverged``,
  ``budget_exhausted``, ``time_limit``) or no solution exists (``no_solution``); the
  files are still written, with the status (``plot`` of such a result, or of a squeeze
  series without success, writes the figure stamped with the status and also exits 3);
* 130 -- interrupted (Ctrl-C): one line on stderr; an export in progress leaves no file
  behind;
* 141 -- the reader of the output closed it (``bearing-fem runs STORE | head``): no
  traceback (128 + SIGPIPE, as the shell reports a process killed by a broken pipe).

Python warnings (e.g. numpy floating-point warnings) never reach the terminal as such:
they are logged at info level (shown with ``-v``).
"""
from __future__ import annotations

import argparse
import contextlib
import logging
import math
import re
import sys
import warnings
from pathlib import Path
from typing import Any, Sequence

EXIT_OK = 0
EXIT_INVALID = 2
EXIT_NO_SOLUTION = 3
EXIT_INTERRUPTED = 130
EXIT_BROKEN_PIPE = 141

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
    """Short human summary of a result on stdout, each number with its estimated error
    where the solve made one."""
    s = result.summary()
    units = s.get("units", {})
    title = getattr(result.scene, "title", "") or "scene"
    est = s.get("error_estimate") or {}

    def number(key: str, est_key: str | None = None) -> str:
        return (_fmt(s.get(key), units.get(key, "")) if key != "friction_coefficient"
                else _fmt(s.get(key))) + _error_note(est, est_key or key)

    rows = [
        ("status", f"{s['status']} ({'success' if s['success'] else 'no success'})"),
        ("h_central", number("h_central")),
        ("h_min", number("h_min")),
        ("p_max", number("p_max")),
        ("friction coefficient", number("friction_coefficient", "friction_force")),
        ("heat power", number("heat_power")
         + (f" ({_fmt(s['heat_power_total'], 'W')} over contact.length)"
            if s.get("heat_power_total") is not None else "")),
        ("iterations", f"{s.get('newton_iterations', 0)} Newton, "
                       f"{s.get('linear_solves', 0)} linear solves"),
        ("wall time", _fmt(s.get("wall_time_s"), "s")),
        ("dofs", str(s.get("dofs", "n/a"))),
    ]
    ref = s.get("refinement")
    if ref:
        rows.append(("grids", f"{', '.join(ref['grids'])} (mesh.target_error = "
                              f"{ref['target_error']:g}, {'met' if ref['met'] else 'not met'})"))
    print(title)
    for name, value in rows:
        print(f"  {name:<21} {value}")
    print(f"  {'message':<21} {s['message']}")
    for text in s.get("warnings") or []:
        print(f"  {'warning':<21} {text}")
    if files:
        print(f"  {'wrote':<21} " + ", ".join(str(p) for p in files.values()))


def _error_note(estimate: dict[str, Any], key: str) -> str:
    """" (estimated error 0.21 %)" of ``key`` in a summary's error estimate, or ""."""
    e = estimate.get(key)
    return f" (estimated error {100 * e:.2g} %)" if isinstance(e, (int, float)) else ""


def failure_numbers(result: Any) -> str:
    """The numbers of an unsuccessful result whose meaning is known, with their units.

    Newton iterations, the scaled Newton residual of the returned fields (dimensionless,
    with the tolerance; the last history entry where the solve did not record it) where
    Newton ran, the thermal fixed-point residual [K] of a thermal
    solve, and the wall time [s]. Nothing else is printed: the result's own message
    carries the rest.
    """
    parts = []
    its = int(getattr(result, "newton_iterations", 0) or 0)
    if its:
        parts.append(f"{its} Newton iteration{'' if its == 1 else 's'}")
    history = list(getattr(result, "history", []) or [])
    own = getattr(result, "residual", None)
    if (history or own is not None) and result.status != "no_solution":
        # the residual of the returned fields where the solve recorded it (after a failed
        # continuation the last history entry belongs to an easier step's problem)
        last = float(own) if own is not None else float(history[-1])
        tol = result.scene.solver.tolerance
        thermal = result.scene.model.thermal == "patch"
        what = ("last scaled Newton residual of the isothermal solve" if thermal
                else "scaled Newton residual of the returned fields" if own is not None
                else "last scaled Newton residual")
        shown = f"{last:.3g}" if math.isfinite(last) else "not finite"
        parts.append(f"{what} {shown} (dimensionless; tolerance {tol:.1g})")
    thermal_residual = (getattr(result, "quantities", {}) or {}).get("thermal_residual")
    if thermal_residual is not None and math.isfinite(float(thermal_residual)):
        parts.append(f"thermal residual |G(T) - T| = {float(thermal_residual):.3g} K")
    wall = float(getattr(result, "wall_time_s", 0.0) or 0.0)
    parts.append(f"{wall:.3g} s")
    return "; ".join(parts)


def _report_status(result: Any) -> int:
    """Exit code of a result, with a one-line explanation on stderr when unsuccessful."""
    if result.success:
        return EXIT_OK
    what = "no solution exists" if result.status == "no_solution" else "no converged solution"
    print(f"bearing-fem: {what} (status {result.status}; {failure_numbers(result)}): "
          f"{result.message}", file=sys.stderr)
    return EXIT_NO_SOLUTION


# ---------------------------------------------------------------------------------------
# subcommands
# ---------------------------------------------------------------------------------------
def _out_dir(value: str, option: str = "--out") -> Path:
    """An output path from the command line: an empty string is refused (it would
    silently mean the current folder)."""
    if not value or not value.strip():
        raise _InputError(f"{option} must name a directory or file, got an empty string "
                          "(use '.' for the current folder)")
    return Path(value)


def _export(result: Any, outdir: Path) -> dict[str, Path]:
    from .io import export

    try:
        return export(result, outdir)
    except OSError as exc:
        raise _InputError(f"cannot write results to {str(outdir)!r}: "
                          f"{exc.strerror or exc}") from None


def _solve_and_write(scene: Any, outdir: Path, png: Path | None, quiet: bool) -> int:
    from .contacts.dispatch import solve

    log.info("solving %r", getattr(scene, "title", ""))
    result = solve(scene)
    files = _export(result, outdir)
    if png is not None:
        from .plot import plot_result

        files["png"] = plot_result(result, png)
    if not quiet:
        _print_summary(result, files)
    return _report_status(result)


def _solve_series_and_write(scene: Any, outdir: Path, quiet: bool) -> int:
    """A [transient] scene: the squeeze series, its files and a short summary."""
    from .contacts.dispatch import solve_series
    from .io import export_series

    series = solve_series(scene)
    try:
        files = export_series(series, outdir)
    except OSError as exc:
        raise _InputError(f"cannot write results to {str(outdir)!r}: "
                          f"{exc.strerror or exc}") from None
    if not quiet:
        s = series.summary()
        print(getattr(scene, "title", "") or "squeeze series")
        print(f"  {'status':<21} {s['status']} ({'success' if s['success'] else 'no success'})")
        pm = [v for v in s["p_max"] if v is not None]
        if pm:
            print(f"  {'p_max over time':<21} {_fmt(min(pm), 'Pa')} .. {_fmt(max(pm), 'Pa')}")
        print(f"  {'instants':<21} {s['instants']} ({s['scheme']})")
        print(f"  {'wall time':<21} {_fmt(s['wall_time_s'], 's')}")
        print(f"  {'message':<21} {s['message']}")
        for text in s.get("warnings") or []:
            print(f"  {'warning':<21} {text}")
        print(f"  {'wrote':<21} " + ", ".join(str(p) for p in files.values()))
    if series.success:
        return EXIT_OK
    print(f"bearing-fem: no converged series (status {series.status}): {series.message}",
          file=sys.stderr)
    return EXIT_NO_SOLUTION


def _cmd_solve(args: argparse.Namespace) -> int:
    from .scene import Scene

    out = _out_dir(args.out)
    scene = Scene.from_toml(args.scene)
    if scene.transient is not None:
        return _solve_series_and_write(scene, out, args.quiet)
    return _solve_and_write(scene, out, None, args.quiet)


def _cmd_demo(args: argparse.Namespace) -> int:
    from dataclasses import replace

    from .scene import load_embedded

    out = _out_dir(args.out)
    scene = load_embedded("roller")
    if args.nodes is not None:
        scene = replace(scene, mesh=replace(scene.mesh, nodes=args.nodes))
    return _solve_and_write(scene, out, out / DEMO_PNG, args.quiet)


#: Figure written by ``bearing-fem plot`` of a squeeze series, beside its summary.json.
SERIES_PNG = "series.png"


def _is_series(path: Path) -> bool:
    """True if ``path`` is a squeeze-series export (its folder, its summary.json or one of
    its files): the summary.json there says ``"kind": "squeeze series"``."""
    import json

    if path.is_dir():
        if (path / "result.h5").is_file():
            return False
        summary = path / "summary.json"
    elif path.name == "result.h5":
        return False
    else:
        summary = path if path.name == "summary.json" else path.parent / "summary.json"
    try:
        data = json.loads(summary.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return False
    return isinstance(data, dict) and data.get("kind") == "squeeze series"


def _cmd_plot_series(path: Path, args: argparse.Namespace) -> int:
    """``bearing-fem plot`` of a squeeze-series export: the series against time."""
    import numpy as np

    from .io import read_series

    if args.kind is not None:
        raise _InputError(f"--kind {args.kind} applies to a contact result.h5; "
                          f"{str(path)!r} holds a squeeze series, drawn as one figure "
                          "against time (leave --kind out)")
    try:
        main = read_series(path)
        compare = [read_series(Path(c)) for c in args.compare]
    except ValueError as exc:  # names the file and what it lacks
        raise _InputError(str(exc)) from None
    out = (_out_dir(args.out) if args.out is not None
           else main["path"].parent / SERIES_PNG)
    from .plot import plot_series

    written = plot_series(main["path"], out, compare=[c["path"] for c in compare])
    if not args.quiet:
        print(f"wrote {written}")
    if not main["success"]:
        unsolved = int(np.ma.count_masked(main["p_max"]))
        print(f"bearing-fem: no converged series (status {main['status']}): the figure "
              f"{str(written)!r} is stamped with the status and shows the "
              f"{main['instants'] - unsolved} solved of {main['instants']} exported "
              f"instants: {main['message']}", file=sys.stderr)
        return EXIT_NO_SOLUTION
    return EXIT_OK


def _refuse_bearing_output(path: Path) -> None:
    """The folder of 'bearing-fem bearing' (or its bearing_summary.json) is no contact
    result: say so, with its figures and a contact folder to plot instead."""
    from .io import BEARING_FILES
    from .plot_bearing import FIGURES

    if path.is_dir():
        folder = path
    elif path.name == BEARING_FILES["summary"]:
        folder = path.parent
    else:
        return
    if not (folder / BEARING_FILES["summary"]).is_file():
        return
    contacts = sorted(p for p in folder.glob("contact_*") if p.is_dir())
    example = (f"bearing-fem plot {contacts[0]}" if contacts
               else "bearing-fem plot DIR/contact_<element>_<raceway>")
    raise _InputError(f"{str(path)!r} is the output of 'bearing-fem bearing', not a contact "
                      f"result: its figures ({', '.join(FIGURES.values())}) are written "
                      "there by that command; plot one of its contacts with "
                      f"'{example}'")


def _cmd_plot(args: argparse.Namespace) -> int:
    from .io import read_result

    path = Path(args.result)
    if _is_series(path):
        return _cmd_plot_series(path, args)
    if args.compare:
        raise _InputError(f"--compare applies to squeeze series; {str(path)!r} is not a "
                          "series export (a folder with the summary.json of a "
                          "[transient] scene)")
    _refuse_bearing_output(path)
    if path.is_dir():
        path = path / "result.h5"
    if not path.is_file():
        raise _InputError(f"no result file {str(path)!r} (give a result.h5 written by "
                          "'bearing-fem solve', or the folder of a squeeze series)")
    try:
        attrs = read_result(path)   # the one check of a contact result file
    except ValueError as exc:       # names the file and what it lacks
        raise _InputError(str(exc)) from None
    except (OSError, KeyError) as exc:
        raise _InputError(f"{str(path)!r} is not a bearing_fem result.h5: {exc}") from None
    if attrs["kind"] == "line" and args.kind in ("map", "surface"):
        raise _InputError(f"--kind {args.kind} applies to point contacts only; {str(path)!r} "
                          "holds a line-contact result (use --kind line, or leave --kind out)")
    out = _out_dir(args.out) if args.out is not None else path.with_suffix(".png")
    from .plot import plot_result

    written = plot_result(path, out, kind=args.kind)
    if not args.quiet:
        print(f"wrote {written}")
    if not attrs["success"]:
        what = ("no solution exists" if attrs["status"] == "no_solution"
                else "no converged solution")
        print(f"bearing-fem: {what} (status {attrs['status']}): the figure {str(written)!r} "
              "is stamped with the status and shows "
              + ("the reduced pressure q, not a pressure" if attrs["status"] == "no_solution"
                 else "the last iterate, not a solution"), file=sys.stderr)
        return EXIT_NO_SOLUTION
    return EXIT_OK


def _cmd_bearing(args: argparse.Namespace) -> int:
    """``bearing-fem bearing FILE --out DIR``: solve a bearing file (docs/bearing.md)."""
    from .bearing import Bearing, example_names, load_example, solve_bearing
    from .io import export_bearing

    out = _out_dir(args.out)
    path = Path(args.bearing)
    if not path.is_file() and args.bearing in example_names():
        bearing = load_example(args.bearing)
    elif not path.exists():
        names = example_names()
        hint = (f" (the shipped example is named without .toml: `bearing-fem bearing "
                f"{path.stem}`)" if path.stem in names else "")
        raise _InputError(f"no bearing file {args.bearing!r}, and no shipped example of that "
                          f"name; shipped examples: {', '.join(names)}{hint}")
    else:
        bearing = Bearing.from_toml(path)
    result = solve_bearing(bearing)
    try:
        files = export_bearing(result, out)
        if not args.no_figures:
            from .plot_bearing import write_figures

            files.update(write_figures(result, out))
    except OSError as exc:
        raise _InputError(f"cannot write results to {str(out)!r}: {exc.strerror or exc}") \
            from None
    if not args.quiet:
        _print_bearing(bearing, result, files)
    if result.success:
        return EXIT_OK
    print(f"bearing-fem: no complete bearing solution (status {result.status}): "
          f"{result.message}", file=sys.stderr)
    return EXIT_NO_SOLUTION


def _print_bearing(bearing: Any, result: Any, files: dict[str, Path]) -> None:
    """The summary table of ``bearing-fem bearing`` on stdout."""
    s = result.summary()
    print(bearing.title or bearing.geometry.type)
    loc = s.get("h_min_location") or {}
    est = s.get("error_estimate") or {}

    rows = [("status", f"{s['status']} ({'success' if s['success'] else 'no success'})"),
            ("friction torque", _fmt(s["friction_torque"], "N m") + _error_note(est, "friction_torque")),
            ("heat power", _fmt(s["heat_power"], "W") + _error_note(est, "heat_power")),
            ("h_min", _fmt(s["h_min"], "m") + _error_note(est, "h_min")
             + (f" (element {loc['element']}, {loc['raceway']})" if loc else "")),
            ("p_max", _fmt(s["p_max"], "Pa") + _error_note(est, "p_max"))]
    for name, m in s["empirical"].items():
        if m.get("torque") is not None:
            rows.append((f"{name} torque", _fmt(m["torque"], "N m")))
    rows.append(("wall time", _fmt(s["wall_time_s"], "s")))
    rows.append(("message", s["message"]))
    rows += [("warning", w) for w in s["warnings"]]
    rows.append(("wrote", ", ".join(str(p) for p in files.values())))
    width = max(len(name) for name, _ in rows)  # one column, however long a model's name
    for name, value in rows:
        print(f"  {name:<{width}} {value}")


def _cmd_bench(args: argparse.Namespace) -> int:
    """``bearing-fem bench [--quick] [--json FILE]``: time the reference cases."""
    from .bench import format_table, run_bench, write_json

    if args.repeat is not None and args.repeat < 1:
        raise _InputError(f"--repeat must be at least 1, got {args.repeat}")
    if args.json and not Path(args.json).resolve().parent.is_dir():
        raise _InputError(f"cannot write {args.json!r}: its directory does not exist")
    if args.json and Path(args.json).is_dir():
        raise _InputError(f"cannot write {args.json!r}: it is a directory; give a file "
                          "name such as bench.json")
    report = run_bench(quick=args.quick, repeats=args.repeat)
    if not args.quiet:
        print(format_table(report))
    if args.json:
        try:
            written = write_json(report, args.json)
        except OSError as exc:
            raise _InputError(f"cannot write {args.json!r}: {exc.strerror or exc}") from None
        if not args.quiet:
            print(f"wrote {written}")
    return EXIT_OK if all(r["success"] for r in report["cases"]) else EXIT_NO_SOLUTION


# ---------------------------------------------------------------------------------------
# sweeps (logic in bearing_fem.sweep; see docs/sweeps.md)
# ---------------------------------------------------------------------------------------
def _cmd_sweep(args: argparse.Namespace) -> int:
    from .sweep import sweep

    report = sweep(args.sweep_file, args.store, scheduler=args.scheduler,
                   workers=args.workers, retry_failed=True if args.retry_failed else None,
                   progress=not args.quiet, dry_run=args.dry_run)
    if not args.quiet:
        print(report.text())
    if args.dry_run or report.all_successful:
        return EXIT_OK
    print(f"bearing-fem: {report.failures} case(s) unsuccessful and {report.unfinished} "
          f"unfinished of {report.cases} (see 'bearing-fem runs {report.store} --status "
          "failed --status unfinished')", file=sys.stderr)
    return EXIT_NO_SOLUTION


def _cmd_runs(args: argparse.Namespace) -> int:
    from .sweep import export_runs, format_runs, query_runs, store_units

    columns = args.columns.split(",") if args.columns and "," in args.columns \
        else args.columns
    if columns is None and (args.csv or args.parquet):
        columns = "all"
    rows, cols = query_runs(args.store, status=args.status, where=args.where,
                            columns=[columns] if isinstance(columns, str) and columns not in
                            ("all", "default") else columns, limit=args.limit,
                            sweep=args.sweep)
    if args.csv or args.parquet:
        text = export_runs(rows, cols, csv=args.csv, parquet=args.parquet)
        if text is not None:
            sys.stdout.write(text)
        elif not args.quiet:
            print(f"wrote {len(rows)} rows to "
                  + ", ".join(str(p) for p in (args.csv, args.parquet) if p))
        return EXIT_OK
    print(format_runs(rows, cols, store_units(args.store)))
    if args.status and not rows and not args.quiet:
        print(_no_status_note(args.store, args.status), file=sys.stderr)
    return EXIT_OK


#: The status groups of ``bearing-fem runs --status`` (docs/sweeps.md).
STATUS_GROUPS = ("success", "failed", "final", "unfinished")


def _no_status_note(store: Any, asked: list[str]) -> str:
    """Why ``runs --status`` kept no row: the statuses and groups asked for, what the store
    holds, and the closest name to one that looks misspelt."""
    import difflib

    from .sweep import query_runs

    present, _ = query_runs(store, columns=["status"])
    have = sorted({r["status"] for r in present})
    groups = [s for s in asked if s in STATUS_GROUPS]
    named = [s for s in asked if s not in STATUS_GROUPS]
    parts = ([f"in the group{'s' if len(groups) > 1 else ''} {', '.join(map(repr, groups))}"]
             if groups else [])
    parts += [f"with status {', '.join(map(repr, named))}"] if named else []
    guesses = {s: difflib.get_close_matches(s, have + list(STATUS_GROUPS), n=1, cutoff=0.75)
               for s in named if s not in have}
    hint = "".join(f" ('{s}': did you mean {g[0]!r}?)" for s, g in guesses.items() if g)
    return (f"no row {' or '.join(parts)}{hint}; statuses in this store: "
            f"{', '.join(have) or 'none'} (groups: {', '.join(STATUS_GROUPS)})")


def _add_sweep_parsers(sub: Any) -> None:
    """The ``sweep`` and ``runs`` subcommands."""
    p = sub.add_parser("sweep", help="run a parameter sweep into a run store",
                       description="Run every case of a sweep file (a base scene or bearing "
                                   "file and axes over its keys; docs/sweeps.md) that the "
                                   "run store does not hold yet, on a local process pool or "
                                   "a Dask cluster. Rerunning resumes an interrupted sweep. "
                                   "Exit code 0 when every case is stored successful, 3 "
                                   "when some are unsuccessful or unfinished, 2 for invalid "
                                   "input.")
    p.add_argument("sweep_file", metavar="SWEEP.toml", help="sweep file")
    p.add_argument("--store", metavar="FILE", default=None,
                   help="SQLite run store (default: [sweep] store, else SWEEP.sqlite)")
    p.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help="Dask scheduler address, e.g. tcp://127.0.0.1:8786 (default: "
                        "[sweep] scheduler, else a local process pool)")
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="processes of the local pool (default: [sweep] workers, else one "
                        "per core; 1 runs in this process)")
    p.add_argument("--retry-failed", action="store_true",
                   help="also rerun cases stored with an unsuccessful status")
    p.add_argument("--dry-run", action="store_true",
                   help="validate every case and say what would run; solve nothing")
    p.set_defaults(func=_cmd_sweep)

    p = sub.add_parser("runs", help="list or export a run store",
                       description="List the rows of a run store written by 'bearing-fem "
                                   "sweep', or export them as CSV or Parquet (Parquet needs "
                                   "pyarrow).")
    p.add_argument("store", metavar="STORE", help="run store (SQLite file)")
    p.add_argument("--status", action="append", default=None, metavar="STATUS",
                   help="keep rows with this status (repeatable); also the groups success, "
                        "failed, final, unfinished")
    p.add_argument("--where", action="append", default=None, metavar="EXPR",
                   help="filter such as 'load.force>=20' (operators = != < <= > >=; "
                        "repeatable, combined with AND)")
    p.add_argument("--columns", default=None, metavar="COLS",
                   help="comma-separated columns, or 'all' (default: hash, status, the "
                        "parameters and the main results; exports: all)")
    p.add_argument("--limit", type=int, default=None, metavar="N", help="at most N rows")
    p.add_argument("--sweep", metavar="SWEEP.toml", default=None,
                   help="keep the rows of this sweep file's cases (as the file and its base "
                        "file read now)")
    p.add_argument("--csv", metavar="FILE", default=None,
                   help="write CSV to FILE ('-' for standard output)")
    p.add_argument("--parquet", metavar="FILE", default=None, help="write Parquet to FILE")
    p.set_defaults(func=_cmd_runs)


# ---------------------------------------------------------------------------------------
_EPILOG = """\
Run 'bearing-fem COMMAND --help' for the options of one command.
options -v, -vv and -q may stand anywhere on the line (before or after COMMAND).

exit codes:
  0    solved (status converged or linear), or a figure of a solved result written
  2    invalid input: the one-line message names the field, its value and its unit;
       nothing is written
  3    no converged solution, or no solution exists: the files (or the figure) are
       still written and carry the status; the message gives the status, the
       iterations, the last residual and the time
  130  interrupted (Ctrl-C); no half-written file is left behind
  141  the reader of the output closed it (| head); no traceback

Scene files are TOML in SI units (m, Pa, Pa s, m/s, N; line contacts per metre of
length). The scene format and every key are described in the package documentation
(docs/scenes.md and docs/cli.md in the source repository).
"""

#: Verbosity flags accepted anywhere on the command line (see :func:`split_verbosity`).
_VERBOSITY = re.compile(r"^-(v+|q+)$")


def split_verbosity(argv: Sequence[str]) -> tuple[list[str], int]:
    """Take the verbosity flags out of a command line, wherever they stand.

    ``-v``/``--verbose`` adds one, ``-vv`` two, ``-q``/``--quiet`` subtracts one; a
    ``--`` ends the options (later tokens are kept as they are).

    Parameters
    ----------
    argv : sequence of str
        Arguments without the program name.

    Returns
    -------
    (list of str, int)
        The remaining arguments and the verbosity (0 by default).
    """
    rest: list[str] = []
    level = 0
    tokens = list(argv)
    for i, token in enumerate(tokens):
        if token == "--":
            rest.extend(tokens[i:])
            break
        match = _VERBOSITY.match(token)
        if token == "--verbose":
            level += 1
        elif token == "--quiet":
            level -= 1
        elif match:
            level += len(token) - 1 if token[1] == "v" else -(len(token) - 1)
        else:
            rest.append(token)
    return rest, level


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``bearing-fem`` (subcommands solve, demo, plot, bearing, bench,
    sweep, runs)."""
    from .version import VERSION as package_version

    parser = argparse.ArgumentParser(
        prog="bearing-fem",
        description="Finite-element EHL solver for rolling-bearing contacts: film, "
                    "pressure, friction and heat of line and point contacts.",
        epilog=_EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"%(prog)s {package_version}")
    parser.add_argument("-v", "--verbose", action="count", default=0,
                        help="log progress to stderr (-v info, -vv debug); anywhere on "
                             "the line")
    parser.add_argument("-q", "--quiet", action="count", default=0,
                        help="print errors only (no summary); anywhere on the line")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = sub.add_parser("solve", help="solve a TOML scene and write summary.json, "
                                     "result.h5 and fields.vtu",
                       description="Solve a scene file (TOML, SI units) and write "
                                   "DIR/summary.json, DIR/result.h5 and DIR/fields.vtu. "
                                   "Exit code 0 solved, 2 invalid input, 3 no converged "
                                   "solution or no solution (files still written).")
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
                   help="override the mesh node count (default: the scene's own mesh, "
                        "1201 nodes); a coarse mesh, e.g. 401, gives a quick look")
    p.set_defaults(func=_cmd_demo)

    p = sub.add_parser("plot", help="plot a result.h5 or a squeeze series",
                       description="Plot a result.h5 written by 'bearing-fem solve' or "
                                   "'bearing-fem demo', or the output folder of a squeeze "
                                   "series (a [transient] scene): its films, p_max and "
                                   "load against time. A result or series without success "
                                   "is still drawn, stamped with its status, and the exit "
                                   "code is 3.")
    p.add_argument("result", metavar="RESULT_H5",
                   help="result.h5 (or its directory), or a series output folder")
    p.add_argument("--out", "-o", metavar="PNG", default=None,
                   help="figure file (default: RESULT_H5 with the suffix .png; "
                        f"DIR/{SERIES_PNG} for a series)")
    p.add_argument("--kind", choices=("map", "surface", "line"), default=None,
                   help="figure kind of a contact result (default: line for line "
                        "contacts, map for point contacts; map and surface apply to point "
                        "contacts only)")
    p.add_argument("--compare", metavar="DIR", action="append", default=[],
                   help="series only: another series output drawn dashed on the same axes "
                        "(e.g. the rigid or quasi-steady series of the scene); repeatable")
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
    p = sub.add_parser("bench", help="time fixed reference cases (line, point, thermal, 6209)",
                       description="Solve fixed reference cases (docs/performance.md), print "
                                   "time, Newton iterations, status, h_central and its error "
                                   "estimate per case, and optionally write them as JSON "
                                   "with the package version and the machine. Exit code 3 "
                                   "when a case is unsuccessful.")
    p.add_argument("--quick", action="store_true",
                   help="coarse bearing contact grids, two repetitions (well under a minute)")
    p.add_argument("--json", metavar="FILE", default=None, help="write the report to FILE")
    p.add_argument("--repeat", type=int, default=None, metavar="N",
                   help="repetitions per case (default 2 quick, 3 full); the minimum is shown")
    p.set_defaults(func=_cmd_bench)
    _add_sweep_parsers(sub)
    return parser


class _StderrHandler(logging.StreamHandler):
    """Log handler writing to whatever ``sys.stderr`` is at the time of each record."""

    def __init__(self) -> None:
        super().__init__(sys.stderr)

    @property
    def stream(self):  # type: ignore[override]
        return sys.stderr

    @stream.setter
    def stream(self, value) -> None:
        pass


@contextlib.contextmanager
def _logging_to_stderr(verbosity: int):
    """Log the package's records to stderr at the level of ``verbosity`` for the duration
    of one command; the logger's previous handlers, level and propagation come back
    afterwards (``main`` may be called in-process, e.g. by tests or the fuzz study)."""
    level = {-1: logging.ERROR, 0: logging.WARNING, 1: logging.INFO}.get(
        max(min(verbosity, 2), -1), logging.DEBUG)
    logger = logging.getLogger("bearing_fem")
    saved = (logger.level, logger.propagate)
    handler = _StderrHandler()
    handler.setFormatter(logging.Formatter("%(levelname)s %(name)s: %(message)s"))
    logger.addHandler(handler)
    logger.setLevel(level)
    logger.propagate = False
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.setLevel(saved[0])
        logger.propagate = saved[1]


def _log_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """``warnings.showwarning`` of the command line: to the log (info), never raw."""
    log.info("%s: %s", category.__name__, message)
    log.debug("  (raised at %s:%s)", filename, lineno)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``bearing-fem``; returns the exit code (see module docstring).

    Parameters
    ----------
    argv : sequence of str, optional
        Arguments without the program name (default: ``sys.argv[1:]``).
    """
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("default")
            warnings.showwarning = _log_warning
            code = _main(sys.argv[1:] if argv is None else argv)
        sys.stdout.flush()  # a closed pipe shows here, not at the interpreter's exit
        return code
    except KeyboardInterrupt:
        print("bearing-fem: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        # the reader (``| head``) has gone: send what is still buffered nowhere, so that
        # the interpreter's final flush of stdout does not raise (and print) again
        _silence_stdout()
        return EXIT_BROKEN_PIPE


def _silence_stdout() -> None:
    """Point the stdout file descriptor at the null device."""
    import os
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # no real file descriptor (captured)
        pass


def _main(argv: Sequence[str]) -> int:
    rest, verbosity = split_verbosity(argv)
    parser = build_parser()
    try:
        args = parser.parse_args(rest)
    except SystemExit as exc:  # --help, --version (0) or a usage error (2)
        return int(exc.code or 0)
    verbosity += args.verbose - args.quiet  # (split_verbosity took them all; kept for API)
    args.quiet = verbosity < 0
    with _logging_to_stderr(verbosity):
        return _run(args)


def _run(args: argparse.Namespace) -> int:
    """Run a parsed command; turn input errors into one line and exit code 2."""
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

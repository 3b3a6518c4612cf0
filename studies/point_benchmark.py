"""Cost of the elastic point-contact solver versus grid size, and against multigrid.

Question
--------
How do wall and CPU time, Newton and GMRES iterations, the time per Newton iteration of
the finest grid and the peak memory of :func:`bearing_fem.contacts.point.solve_point`
grow from 129^2 to 513^2 nodes (65^2 to 257^2 with ``quick``, 1025^2 on request)? How
does the 513^2 solve compare with the full-multigrid program for the circular contact of
Venner and Lubrecht (*Multilevel Methods in Lubrication*, Elsevier 2000), run on the same
domain and node spacing in the same session?

Scene
-----
Circular contact at Moes M = 100, L = 10 (alpha p_h = 16.9), built as in
``studies/point_ehl_map.py`` (X in [-4.5, 1.5], Y in [-3, 3] Hertz radii: the
multigrid program's domain). Each grid n is solved from scratch with the solver's
defaults: grid sequencing 65 -> ... -> n on the half grid y >= 0 (the scene is symmetric),
then the error estimate from the two coarser levels and the whole-grid residual and
post-processing. The multigrid program solves 512 x 512 intervals (6 levels, the node
spacing of 513^2 here), start level 1, 3 W cycles: the reference setting of the multigrid
timings.

Method
------
Every solve runs in a fresh Python process (this script with ``--child``), which reports
its own peak resident memory (``VmHWM``, interpreter and imports included; the
imports alone are measured too), wall and process CPU time of the solve, and the
1-minute load average before and after. The finest grid's Newton iterations and CPU time
come from the solver's progress events (the time from the finest level's start to its
last Newton iteration); their ratio is the time per Newton iteration, and the growth
exponent is the slope of its logarithm against that of the unknowns solved. With
``fmg`` (the compiled multigrid program, which reads ``M L levels start cycles type`` on
standard input; see ``studies/point_fmg_crosscheck.py``) and ``repeats`` > 0, the
program and the 513^2 solve run alternately ``repeats`` times and the CPU-time ratio of
each pair is reported (on a shared machine the pair shares the load). ``baseline`` (a
checkout of an earlier version of the package) runs the same children on that code,
interleaved with the current one, for before/after tables.

Expected outcome
----------------
A few Newton iterations per fine level, time per iteration growing like the unknowns
(exponent ~1.0-1.1), total time 257^2 -> 513^2 at most 4.5x, peak memory at 513^2 below
400 MB, and the 513^2 solve within 2x of the multigrid program's W-cycle time.
Wall times are meaningful only next to the load average (recorded per row).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
M_DEFAULT, L_DEFAULT = 100.0, 10.0
GRIDS = (129, 257, 513)
QUICK_GRIDS = (65, 129, 257)
#: The multigrid program's input for the comparison: 6 levels (512 x 512 intervals),
#: start level 1, 3 cycles, W cycle.
FMG_SETTING = (6, 1, 3, 2)
FMG_TIMEOUT_S = 600.0


def _rss_mb() -> float:
    """Peak resident memory of this process image [MB].

    ``VmHWM`` of /proc/self/status where it exists: unlike ``ru_maxrss`` it starts afresh
    at exec, so a child of a large process (a test runner) reports its own peak.
    """
    try:
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith("VmHWM:"):
                    return float(line.split()[1]) / 1024.0
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def child(n: int, M: float, L: float, symmetric: bool = True) -> dict:
    """One solve in this process (run it in a fresh one); returns the row."""
    sys.path.insert(0, str(HERE))
    from point_ehl_map import moes_scene

    from bearing_fem.contacts import point
    from bearing_fem.contacts.point import solve_point

    point.Y_SYMMETRY = symmetric
    import_rss = _rss_mb()
    scene = moes_scene(M, L, n)
    marks: list[tuple[str, int, float]] = []

    def progress(event: dict) -> None:
        if event["event"] == "level":
            marks.append((event["grid"], -1, time.process_time()))
        elif event["event"] == "newton":
            marks.append(("", event["iteration"], time.process_time()))

    load_before = os.getloadavg()[0]
    t0, c0 = time.perf_counter(), time.process_time()
    res = solve_point(scene, progress=progress)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    load_after = os.getloadavg()[0]
    starts = [i for i, m in enumerate(marks) if m[0]]
    fine = marks[starts[-1]:] if starts else []
    fine_cpu = (fine[-1][2] - fine[0][2]) if len(fine) > 1 else float("nan")
    tag = f"({n}x{n} nodes)"  # every attempt on the finest grid, rejected steps included
    fine_its = int(sum(its for _, status, its in res.continuation if tag in status))
    q = res.quantities
    return {"nodes": n, "M": M, "L": L, "status": res.status,
            "grid_solved": "half" if "by symmetry" in res.message else "whole",
            "unknowns": n * n,
            "unknowns_solved": n * (n + 1) // 2 if "by symmetry" in res.message else n * n,
            "wall_time_s": wall, "cpu_time_s": cpu,
            "load_average_1min": [load_before, load_after],
            "newton_iterations_total": res.newton_iterations,
            "newton_iterations_finest": fine_its,
            "finest_level_cpu_s": fine_cpu,
            "time_per_iteration_s": fine_cpu / max(fine_its, 1),
            "gmres_iterations_total": q.get("gmres_iterations"),
            "levels": [f"{st} ({its} its)" for _, st, its in res.continuation],
            "level_iterations": [int(its) for _, _, its in res.continuation],
            "h_central_m": q.get("h_central"), "h_min_m": q.get("h_min"),
            "p_max_Pa": q.get("p_max"), "peak_rss_mb": _rss_mb(),
            "import_rss_mb": import_rss, "message": res.message}


def _run_child(n: int, M: float, L: float, symmetric: bool = True,
               code: str | None = None) -> dict:
    """:func:`child` in a fresh interpreter (on the package at ``code`` if given)."""
    env = dict(os.environ)
    if code is not None:
        env["PYTHONPATH"] = str(code) + os.pathsep + env.get("PYTHONPATH", "")
    cmd = [sys.executable, str(Path(__file__).resolve()), "--child", str(n), "--M", str(M),
           "--L", str(L)] + ([] if symmetric else ["--whole"])
    out = subprocess.run(cmd, capture_output=True, text=True, env=env, check=True,
                         cwd=str(code) if code is not None else None)
    row = json.loads(out.stdout.strip().splitlines()[-1])
    row["code"] = "baseline" if code is not None else "current"
    return row


def run_fmg(path: str | Path, M: float, L: float, setting=FMG_SETTING) -> dict:
    """The multigrid program once: CPU and wall time, peak memory and its films."""
    sys.path.insert(0, str(HERE))
    from point_fmg_crosscheck import parse_fmg_output

    levels, start, cycles, kind = setting
    load_before = os.getloadavg()[0]
    with tempfile.TemporaryFile("w+") as stdout:
        t0 = time.perf_counter()
        proc = subprocess.Popen([str(path)], stdin=subprocess.PIPE, stdout=stdout,
                                stderr=subprocess.DEVNULL, text=True,
                                cwd=str(Path(path).resolve().parent))
        timer = threading.Timer(FMG_TIMEOUT_S, proc.kill)
        timer.start()
        try:
            proc.stdin.write(f"{M} {L} {levels} {start} {cycles} {kind}\n")
            proc.stdin.close()
            # the rusage of this child alone (RUSAGE_CHILDREN's peak would be the largest
            # of every child so far, the solves' included)
            _, status, usage = os.wait4(proc.pid, 0)
        finally:
            timer.cancel()
        wall = time.perf_counter() - t0
        proc.returncode = os.waitstatus_to_exitcode(status)
        stdout.seek(0)
        parsed = parse_fmg_output(stdout.read(), levels)
    return {"setting": list(setting), "wall_time_s": wall,
            "cpu_time_s": usage.ru_utime + usage.ru_stime,
            "peak_rss_mb": usage.ru_maxrss / 1024.0,
            "load_average_1min": [load_before, os.getloadavg()[0]],
            "H_min": parsed["H_min"], "H_c": parsed["H_c"], "returncode": proc.returncode}


def _exponent(rows: list[dict]) -> float:
    """Slope of log(time per finest-level Newton iteration) vs log(unknowns solved)."""
    rows = [r for r in rows if math.isfinite(r["time_per_iteration_s"])]
    if len(rows) < 2:
        return float("nan")
    n = np.array([r["unknowns_solved"] for r in rows], dtype=float)
    t = np.array([r["time_per_iteration_s"] for r in rows])
    return float(np.polyfit(np.log(n), np.log(t), 1)[0])


#: Targets of the benchmark (M = 100, L = 10): CPU seconds at 257^2 and 513^2, peak MB at
#: 513^2, growth exponent of the time per finest-level Newton iteration, CPU-time ratio
#: 513^2 / 257^2, and CPU-time ratio to the multigrid program's W cycles.
TARGETS = {"cpu_257_s": 3.0, "cpu_513_s": 12.0, "peak_513_mb": 400.0, "exponent": 1.1,
           "ratio_513_257": 4.5, "fmg_ratio": 2.0}


def _targets(by_n: dict, exponent: float, ratio: float | None, pairs: list) -> list[dict]:
    """Each target the run can judge: what it asks, what was measured, whether met."""
    t, out = TARGETS, []
    if 257 in by_n:
        c = by_n[257]["cpu_time_s"]
        out.append({"target": f"257^2 under {t['cpu_257_s']:g} s", "measured": f"{c:.2f} s",
                    "met": c < t["cpu_257_s"]})
    if 513 in by_n:
        c, m = by_n[513]["cpu_time_s"], by_n[513]["peak_rss_mb"]
        out.append({"target": f"513^2 under {t['cpu_513_s']:g} s", "measured": f"{c:.2f} s",
                    "met": c < t["cpu_513_s"]})
        out.append({"target": f"peak memory at 513^2 under {t['peak_513_mb']:g} MB",
                    "measured": f"{m:.0f} MB", "met": m < t["peak_513_mb"]})
    if math.isfinite(exponent) and len(by_n) >= 2:
        out.append({"target": f"time per Newton iteration growing at most as "
                              f"N^{t['exponent']:g}", "measured": f"N^{exponent:.2f}",
                    "met": exponent <= t["exponent"]})
    if ratio is not None:
        out.append({"target": f"CPU time 257^2 -> 513^2 at most x{t['ratio_513_257']:g}",
                    "measured": f"x{ratio:.2f}", "met": ratio <= t["ratio_513_257"]})
    if pairs:
        med = statistics.median(p["cpu_ratio"] for p in pairs)
        out.append({"target": f"513^2 at most {t['fmg_ratio']:g}x the multigrid W cycles",
                    "measured": f"{med:.2f}x (median of {len(pairs)} pairs)",
                    "met": med <= t["fmg_ratio"]})
    return out


def _table(rows: list[dict], finest: dict) -> list[str]:
    lines = [f"{'grid':>7} {'code':>8} {'solved':>6} {'status':>10} {'wall s':>7} "
             f"{'cpu s':>7} {'its':>4} {'its(fine)':>9} {'s/it':>6} {'gmres':>6} "
             f"{'peak MB':>8} {'h_c [nm]':>10} {'h_min [nm]':>10} {'h_c err':>8} "
             f"{'h_min err':>9} {'load before/after':>18}  its per level"]
    for r in rows:
        lb, la = r["load_average_1min"]
        lines.append(
            f"{r['nodes']:>5}^2 {r['code']:>8} {r['grid_solved']:>6} {r['status']:>10} "
            f"{r['wall_time_s']:7.2f} {r['cpu_time_s']:7.2f} "
            f"{r['newton_iterations_total']:4d} {r['newton_iterations_finest']:9d} "
            f"{r['time_per_iteration_s']:6.3f} {r['gmres_iterations_total'] or 0:6.0f} "
            f"{r['peak_rss_mb']:8.0f} {1e9 * r['h_central_m']:10.4f} "
            f"{1e9 * r['h_min_m']:10.4f} "
            f"{abs(r['h_central_m'] / finest['h_central_m'] - 1):8.1e} "
            f"{abs(r['h_min_m'] / finest['h_min_m'] - 1):9.1e} {lb:9.2f}/{la:<8.2f}  "
            + "+".join(str(its) for its in r.get("level_iterations", [])))
    return lines


def main(outdir, quick: bool = False, *, M: float = M_DEFAULT, L: float = L_DEFAULT,
         grids: tuple[int, ...] | None = None, whole: bool = False,
         fmg: str | Path | None = None, repeats: int = 3,
         baseline: str | Path | None = None, ratio_repeats: int = 2) -> dict:
    """Run the benchmark; write ``point_benchmark.json``/``.txt``; return the numbers.

    Parameters
    ----------
    outdir : path
    quick : bool
        Grids 65, 129, 257 (no multigrid comparison).
    M, L : float
        Moes parameters.
    grids : tuple of int, optional
        Grids (nodes per direction, increasing; default 129, 257, 513).
    whole : bool
        Also solve every grid on the whole grid (``point.Y_SYMMETRY = False``, the same
        equations with twice the unknowns).
    fmg : path, optional
        The compiled multigrid program; with ``repeats`` > 0 it and the 513^2 solve run
        alternately ``repeats`` times.
    baseline : path, optional
        A checkout of an earlier version: every grid is also solved on that code,
        alternating with the current one.
    ratio_repeats : int
        Further 257^2, 513^2 pairs solved alternately; the CPU-time ratio 513^2 / 257^2
        is the median over these and the grid rows' pair.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    grids = tuple(grids) if grids else (QUICK_GRIDS if quick else GRIDS)
    rows, base_rows, whole_rows = [], [], []
    for n in grids:
        if baseline is not None:
            base_rows.append(_run_child(n, M, L, code=baseline))
        rows.append(_run_child(n, M, L))
        if whole:
            whole_rows.append(_run_child(n, M, L, symmetric=False))
    growth = []
    by_n0 = {r["nodes"]: r for r in rows}
    if 257 in by_n0 and 513 in by_n0:
        growth.append(by_n0[513]["cpu_time_s"] / by_n0[257]["cpu_time_s"])
        for _ in range(int(ratio_repeats)):  # interleaved: one sample is at the mercy of noise
            a, b = _run_child(257, M, L), _run_child(513, M, L)
            growth.append(b["cpu_time_s"] / a["cpu_time_s"])
    pairs = []
    if fmg is not None and not quick:
        for _ in range(int(repeats)):
            f = run_fmg(fmg, M, L)
            s = _run_child(513, M, L)
            pairs.append({"fmg": f, "solve": s, "cpu_ratio": s["cpu_time_s"] / f["cpu_time_s"],
                          "wall_ratio": s["wall_time_s"] / f["wall_time_s"]})
    finest = rows[-1]
    lines = [f"Moes M = {M:g}, L = {L:g}; each row a fresh process; its = Newton iterations "
             "(all levels), its(fine) and s/it those of the finest grid (CPU s); h_c/h_min "
             f"err against the current {finest['nodes']}^2 solve"]
    lines += _table(base_rows + rows + whole_rows, finest)
    exps = {"current": _exponent(rows)}
    if base_rows:
        exps["baseline"] = _exponent(base_rows)
    if whole_rows:
        exps["whole"] = _exponent(whole_rows)
    for k, e in exps.items():
        lines.append(f"growth exponent of the time per finest-level Newton iteration vs "
                     f"unknowns ({k}): {e:.2f}")
    by_n = {r["nodes"]: r for r in rows}
    ratio = None
    if growth:
        ratio = statistics.median(growth)
        lines.append(f"CPU time 513^2 / 257^2: median {ratio:.2f} of {len(growth)} "
                     f"interleaved pairs ({', '.join(f'{g:.2f}' for g in growth)})")
    lines.append(f"interpreter and imports: {rows[0]['import_rss_mb']:.0f} MB of each peak")
    if pairs:
        lines.append("multigrid program (512 x 512 intervals, start level 1, 3 W cycles) and "
                     "the 513^2 solve, alternately:")
        for p in pairs:
            f, s = p["fmg"], p["solve"]
            lines.append(f"  multigrid cpu {f['cpu_time_s']:6.2f} s (wall {f['wall_time_s']:.2f}, "
                         f"{f['peak_rss_mb']:.0f} MB, load {f['load_average_1min'][0]:.2f}); "
                         f"here cpu {s['cpu_time_s']:6.2f} s (wall {s['wall_time_s']:.2f}, "
                         f"{s['peak_rss_mb']:.0f} MB, load {s['load_average_1min'][0]:.2f}); "
                         f"ratio {p['cpu_ratio']:.2f}")
        lines.append(f"  median CPU ratio {statistics.median(p['cpu_ratio'] for p in pairs):.2f}")
    targets = _targets(by_n, exps["current"], ratio, pairs)
    if targets:
        lines.append("targets (CPU time; wall time equals it only on an idle machine):")
        lines += [f"  {t['target']}: {t['measured']} -> {'met' if t['met'] else 'NOT met'}"
                  for t in targets]
    table = "\n".join(lines)
    print(table)
    (outdir / "point_benchmark.txt").write_text(table + "\n")
    for group in (rows, base_rows, whole_rows):
        for r in group:
            r["h_central_error_vs_finest"] = abs(r["h_central_m"] / finest["h_central_m"] - 1)
            r["h_min_error_vs_finest"] = abs(r["h_min_m"] / finest["h_min_m"] - 1)
    out = {"M": M, "L": L, "rows": rows, "rows_baseline": base_rows,
           "rows_whole_grid": whole_rows, "growth_exponent": exps["current"],
           "growth_exponent_baseline": exps.get("baseline"),
           "growth_exponent_whole_grid": exps.get("whole"),
           "cpu_ratio_513_257": ratio, "cpu_ratio_513_257_samples": growth,
           "fmg_pairs": pairs, "targets": targets,
           "fmg_median_cpu_ratio": (statistics.median(p["cpu_ratio"] for p in pairs)
                                    if pairs else None)}
    tmp = outdir / "point_benchmark.json.tmp"
    tmp.write_text(json.dumps(out, indent=1))
    os.replace(tmp, outdir / "point_benchmark.json")
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default="out_point_benchmark")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--grids", default=None, help="comma-separated node counts, e.g. 257,513,1025")
    ap.add_argument("--whole", action="store_true", help="also solve on the whole grid")
    ap.add_argument("--fmg", default=None, help="compiled multigrid program")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--ratio-repeats", type=int, default=2,
                    help="further interleaved 257^2/513^2 pairs for the growth ratio")
    ap.add_argument("--baseline", default=None, help="checkout of an earlier version")
    ap.add_argument("--M", type=float, default=M_DEFAULT)
    ap.add_argument("--L", type=float, default=L_DEFAULT)
    ap.add_argument("--child", type=int, default=None, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child is not None:
        print(json.dumps(child(args.child, args.M, args.L, symmetric=not args.whole)))
    else:
        main(args.outdir, args.quick, M=args.M, L=args.L,
             grids=tuple(int(g) for g in args.grids.split(",")) if args.grids else None,
             whole=args.whole, fmg=args.fmg, repeats=args.repeats, baseline=args.baseline,
             ratio_repeats=args.ratio_repeats)

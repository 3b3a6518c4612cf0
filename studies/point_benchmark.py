"""Cost of the elastic point-contact solver versus grid size.

Question
--------
How do wall time, Newton iterations, time per Newton iteration and peak memory of
:func:`bearing_fem.contacts.point.solve_point` grow from 65^2 to 513^2 nodes?

Scene
-----
Circular contact at Moes M = 100, L = 10 (alpha p_h = 16.9), built as in
``studies/point_ehl_map.py``. Each grid n is solved from scratch with the solver's grid
sequencing (65 -> 129 -> ... -> n), so T(n) - T(n_prev) is the cost of the finest level
alone, and the time per Newton iteration on the finest level is that difference over the
finest-level iteration count. The growth exponent is the slope of log(time per
iteration) against log(unknowns solved): ~1 for an O(N log N) FFT + sparse LU of the
near-field preconditioner, plus the GMRES iteration growth.

The scene is symmetric about y = 0, so by default (``point.Y_SYMMETRY``) the solver works
on the half grid y >= 0 (n (n + 1)/2 unknowns) and mirrors the result to the whole n x n
grid, where the whole system's residual is reported. Every grid is solved a second time
on the whole grid (n^2 unknowns, ``Y_SYMMETRY = False``; the same equations): rows
"half" and "whole".

Expected outcome
----------------
A few Newton iterations per fine level, exponent ~1.0-1.3, peak memory well below 4 GB
at 513^2 (the dense 2D compliance is never formed). The error columns (h_c and h_min of
each grid against the finest grid's) set the run time against the accuracy it buys.

The machine load is recorded with each row (1-minute load average before and after the
solve, ``os.getloadavg``) together with the process CPU time: on a shared machine the wall
time is only meaningful next to the load.
"""
from __future__ import annotations

import json
import os
import resource
import sys
import time
from pathlib import Path

import numpy as np

from bearing_fem.contacts import point
from bearing_fem.contacts.point import solve_point

sys.path.insert(0, str(Path(__file__).resolve().parent))
from point_ehl_map import moes_scene  # noqa: E402


def _finest_iterations(res, n: int) -> int:
    tag = f"({n}x{n} nodes)"
    return int(sum(its for _, status, its in res.continuation if tag in status))


def _run(grids: tuple[int, ...], M: float, L: float, symmetric: bool) -> list[dict]:
    """Solve M, L from scratch on every grid; ``symmetric`` sets ``point.Y_SYMMETRY``."""
    rows = []
    prev_time = 0.0
    saved = point.Y_SYMMETRY
    point.Y_SYMMETRY = symmetric
    try:
        for n in grids:
            scene = moes_scene(M, L, n)
            load_before = os.getloadavg()[0]
            rss_before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
            t0, c0 = time.perf_counter(), time.process_time()
            res = solve_point(scene)
            wall, cpu = time.perf_counter() - t0, time.process_time() - c0
            load_after = os.getloadavg()[0]
            its = _finest_iterations(res, n)
            level_time = wall - prev_time if n != grids[0] else wall
            prev_time = wall
            rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
            solved = n * (n + 1) // 2 if "by symmetry" in res.message else n * n
            rows.append({"nodes": n, "unknowns": n * n, "unknowns_solved": solved,
                         "grid_solved": "half" if solved < n * n else "whole",
                         "status": res.status, "wall_time_s": wall, "cpu_time_s": cpu,
                         "load_average_1min": [load_before, load_after],
                         "newton_iterations_total": res.newton_iterations,
                         "newton_iterations_finest": its,
                         "time_per_iteration_s": level_time / max(its, 1),
                         "gmres_iterations_total": res.quantities.get("gmres_iterations"),
                         "h_central_m": res.quantities.get("h_central"),
                         "h_min_m": res.quantities.get("h_min"),
                         "p_max_Pa": res.quantities.get("p_max"),
                         "peak_rss_mb": rss_mb,
                         # ru_maxrss is the process's peak so far: this solve's own
                         # peak only if it raised it
                         "peak_rss_is_this_solve": bool(rss_mb > rss_before)})
    finally:
        point.Y_SYMMETRY = saved
    return rows


def _exponent(rows: list[dict]) -> float:
    """Slope of log(time per finest-level Newton iteration) vs log(unknowns solved)."""
    if len(rows) < 2:
        return float("nan")
    n_arr = np.array([r["unknowns_solved"] for r in rows], dtype=float)
    t_arr = np.array([r["time_per_iteration_s"] for r in rows])
    return float(np.polyfit(np.log(n_arr), np.log(t_arr), 1)[0])


def main(outdir, quick: bool = False, *, M: float = 100.0, L: float = 10.0,
         whole: bool = True) -> dict:
    """Run the benchmark; write ``point_benchmark.json``/``.txt``; return the numbers.

    quick: grids 65, 129, 257 (513 skipped). The solver's default solves this symmetric
    scene on the half grid y >= 0 (``point.Y_SYMMETRY``); ``whole`` (default True) also
    solves every grid on the whole grid, the same equations with twice the unknowns.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    grids = (65, 129, 257) if quick else (65, 129, 257, 513)
    runs = {"half": _run(grids, M, L, True)}
    if whole:
        runs["whole"] = _run(grids, M, L, False)
    finest = runs["half"][-1]
    for rows in runs.values():  # error against run time: films against the finest half's
        for r in rows:
            r["h_central_error_vs_finest"] = abs(r["h_central_m"] / finest["h_central_m"] - 1.0)
            r["h_min_error_vs_finest"] = abs(r["h_min_m"] / finest["h_min_m"] - 1.0)
    exponents = {k: _exponent(rows) for k, rows in runs.items()}
    lines = [f"{'grid':>8} {'solved':>6} {'status':>10} {'time s':>8} {'cpu s':>7} "
             f"{'its(fine)':>9} {'s/it':>7} {'gmres':>6} {'peak MB':>8} {'h_c err':>8} "
             f"{'h_min err':>9} {'load before/after':>18}"]
    for rows in runs.values():
        for r in rows:
            lb, la = r["load_average_1min"]
            lines.append(f"{r['nodes']:>4}^2    {r['grid_solved']:>6} {r['status']:>10} "
                         f"{r['wall_time_s']:8.1f} {r['cpu_time_s']:7.1f} "
                         f"{r['newton_iterations_finest']:9d} "
                         f"{r['time_per_iteration_s']:7.2f} {r['gmres_iterations_total']:6.0f} "
                         f"{r['peak_rss_mb']:7.0f}{' ' if r['peak_rss_is_this_solve'] else '*'} "
                         f"{r['h_central_error_vs_finest']:8.1e} "
                         f"{r['h_min_error_vs_finest']:9.1e} {lb:9.2f}/{la:<8.2f}")
    if not all(r["peak_rss_is_this_solve"] for rows in runs.values() for r in rows):
        lines.append("* peak MB of an earlier, larger solve in this process (the solve itself "
                     "stayed below it)")
    for k, e in exponents.items():
        lines.append(f"growth exponent of time per Newton iteration vs unknowns ({k} grid): "
                     f"{e:.2f}")
    table = "\n".join(lines)
    print(table)
    (outdir / "point_benchmark.txt").write_text(table + "\n")
    out = {"M": M, "L": L, "rows": runs["half"], "rows_whole_grid": runs.get("whole", []),
           "growth_exponent": exponents["half"],
           "growth_exponent_whole_grid": exponents.get("whole")}
    (outdir / "point_benchmark.json").write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out_point_benchmark",
         quick="--quick" in sys.argv)

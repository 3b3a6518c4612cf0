"""Line-contact speed benchmark: error against run time.

Question
    How long does the damped-Newton FE solver take for a moderately loaded EHL line
    contact (Moes M = 100, L = 10) at >= 2000 nodes, what does one Newton iteration
    cost, and how does h_central converge with the grid (error against time)?

Scene
    :func:`studies.line_ehl_map.scene_for` (E' = 2.2e11 Pa, R = 10 mm,
    alpha = 2e-8 1/Pa, Barus, Reynolds cavitation, half-space), nodes 501..4001.

Expected outcome
    Target: grid-converged h_central at 2001 nodes in under 0.3 s on a 2-core machine.
    Each grid is solved ``repeats`` times in a row (after a warm-up solve); the table
    gives the fastest and the median wall time, the CPU time of the fastest, and the
    1-minute load average when each grid's solves start (timings are meaningful only next
    to it: other jobs on the machine slow the dense factorisations most), with the grid
    levels of the solve and their Newton iterations.

Run ``python studies/line_benchmark.py [outdir] [--quick] [--repeats N]``.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from line_ehl_map import scene_for  # noqa: E402


def main(outdir: str | Path = "out/line_benchmark", quick: bool = False,
         M: float = 100.0, L: float = 10.0, repeats: int = 3) -> dict:
    """Solve (M, L) on a grid sequence; return and write the timing table."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    grids = (501, 1001) if quick else (501, 1001, 2001, 4001)
    rows = []
    bf.solve(scene_for(M, L, 201))  # warm-up: imports and first-call costs
    for n in grids:
        load = os.getloadavg()[0]
        walls, cpus = [], []
        for _ in range(max(int(repeats), 1)):
            t0, c0 = time.perf_counter(), time.process_time()
            r = bf.solve(scene_for(M, L, n))
            walls.append(time.perf_counter() - t0)
            cpus.append(time.process_time() - c0)
        best = min(range(len(walls)), key=walls.__getitem__)
        rows.append({"nodes": n, "status": r.status, "newton_iterations": r.newton_iterations,
                     "wall_time_s": walls[best], "wall_time_median_s": statistics.median(walls),
                     "cpu_time_s": cpus[best], "wall_times_s": walls,
                     "load_average_1min": load,
                     "levels": [f"{st} ({its} its)" for _, st, its in r.continuation],
                     "time_per_iteration_s": walls[best] / max(r.newton_iterations, 1),
                     "h_central": r.quantities.get("h_central"),
                     "h_min": r.quantities.get("h_min"), "message": r.message})
    finest = rows[-1]["h_central"]
    for row in rows:
        if row["h_central"] and finest:
            row["h_central_error_vs_finest"] = abs(row["h_central"] / finest - 1.0)
    lines = [f"Moes M={M}, L={L}; wall time: fastest and median of {repeats} solves",
             f"{'nodes':>6} {'status':>10} {'its':>4} {'wall s':>8} {'median':>7} {'cpu s':>7} "
             f"{'s/it':>7} {'h_c err vs finest':>18} {'load avg':>8}  grids (its)"]
    for row in rows:
        lines.append(f"{row['nodes']:>6} {row['status']:>10} {row['newton_iterations']:>4} "
                     f"{row['wall_time_s']:>8.3f} {row['wall_time_median_s']:>7.3f} "
                     f"{row['cpu_time_s']:>7.3f} {row['time_per_iteration_s']:>7.3f} "
                     f"{row.get('h_central_error_vs_finest', float('nan')):>18.2e} "
                     f"{row['load_average_1min']:>8.2f}  " + "; ".join(row["levels"]))
    text = "\n".join(lines)
    print(text)
    (outdir / "line_benchmark.txt").write_text(text + "\n")
    (outdir / "line_benchmark.json").write_text(json.dumps(rows, indent=1))
    return {"rows": rows, "table": text}


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description="Line-contact speed benchmark")
    ap.add_argument("outdir", nargs="?", default="out/line_benchmark")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    main(args.outdir, args.quick, repeats=args.repeats)

"""Line-contact speed benchmark: error against run time.

Question
    How long does the damped-Newton FE solver take for a moderately loaded EHL line
    contact (Moes M = 100, L = 10) at >= 2000 nodes, what does one Newton iteration
    cost, and how does h_central converge with the grid (error against time)?

Scene
    :func:`studies.line_ehl_map.scene_for` (E' = 2.2e11 Pa, R = 10 mm,
    alpha = 2e-8 1/Pa, Barus, Reynolds cavitation, half-space), nodes 501..4001.

Expected outcome
    Target of the issue: grid-converged h_central at >= 2000 nodes in under 2 s wall
    time on a 2-core machine. The printed table reports what is measured, whatever it is,
    with the 1-minute load average when each solve starts (timings are meaningful only
    when it is near 0: other jobs on the machine slow the dense factorisations most)
    and the grid levels of the solve with their Newton iterations.

Run ``python studies/line_benchmark.py [outdir]``.
"""
from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from line_ehl_map import scene_for  # noqa: E402


def main(outdir: str | Path = "out/line_benchmark", quick: bool = False,
         M: float = 100.0, L: float = 10.0) -> dict:
    """Solve (M, L) on a grid sequence; return and write the timing table."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    grids = (501, 1001) if quick else (501, 1001, 2001, 4001)
    rows = []
    bf.solve(scene_for(M, L, 201))  # warm-up: imports and first-call costs
    for n in grids:
        load = os.getloadavg()[0]
        t0 = time.perf_counter()
        r = bf.solve(scene_for(M, L, n))
        wall = time.perf_counter() - t0
        rows.append({"nodes": n, "status": r.status, "newton_iterations": r.newton_iterations,
                     "wall_time_s": wall, "load_average_1min": load,
                     "levels": [f"{st} ({its} its)" for _, st, its in r.continuation],
                     "time_per_iteration_s": wall / max(r.newton_iterations, 1),
                     "h_central": r.quantities.get("h_central"),
                     "h_min": r.quantities.get("h_min"), "message": r.message})
    finest = rows[-1]["h_central"]
    for row in rows:
        if row["h_central"] and finest:
            row["h_central_error_vs_finest"] = abs(row["h_central"] / finest - 1.0)
    lines = [f"Moes M={M}, L={L}",
             f"{'nodes':>6} {'status':>10} {'its':>4} {'wall s':>8} {'s/it':>7} "
             f"{'h_c err vs finest':>18} {'load avg':>8}  grids (its)"]
    for row in rows:
        lines.append(f"{row['nodes']:>6} {row['status']:>10} {row['newton_iterations']:>4} "
                     f"{row['wall_time_s']:>8.2f} {row['time_per_iteration_s']:>7.3f} "
                     f"{row.get('h_central_error_vs_finest', float('nan')):>18.2e} "
                     f"{row['load_average_1min']:>8.2f}  " + "; ".join(row["levels"]))
    text = "\n".join(lines)
    print(text)
    (outdir / "line_benchmark.txt").write_text(text + "\n")
    (outdir / "line_benchmark.json").write_text(json.dumps(rows, indent=1))
    return {"rows": rows, "table": text}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/line_benchmark")

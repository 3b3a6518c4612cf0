"""Benchmark: wall time of ``bearing-fem bearing`` on the shipped 6209 example.

Question
--------
How long does the command line take, from start-up to the last file, for the 6209
deep-groove ball bearing (3000 rpm, Fr = 4 kN: three loaded balls, four distinct contact
scenes on the default 129^2 point-contact grid)? Target: under 60 s on 2 cores. The
benchmark also checks that the run wrote per-element results and every file.

Each repetition runs the ``bearing-fem`` entry point (``bearing_fem.cli.main``) with
``bearing 6209 --out DIR`` in a fresh process (so the import time counts) and records the
wall time; the machine load (1-minute load average) is recorded with it, since the machine
may be shared.

Run ``python studies/bearing_benchmark.py OUTDIR [--quick] [--repeat N]``.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

EXPECTED = ("bearing_summary.json", "elements.csv", "contacts.vtm", "load_distribution.png",
            "films_pressures.png", "torque_comparison.png")


def run_once(outdir: Path, example: str = "6209") -> dict:
    """One timed ``bearing-fem bearing`` run in a fresh interpreter."""
    t0 = time.perf_counter()
    code = "import sys; from bearing_fem.cli import main; sys.exit(main(sys.argv[1:]))"
    proc = subprocess.run([sys.executable, "-c", code, "bearing", example, "--out",
                           str(outdir)], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    summary = json.loads((outdir / "bearing_summary.json").read_text()) \
        if (outdir / "bearing_summary.json").is_file() else {}
    missing = [f for f in EXPECTED if not (outdir / f).is_file()]
    contact_dirs = sorted(p.name for p in outdir.glob("contact_*") if p.is_dir())
    return {"wall_time_s": wall, "exit_code": proc.returncode,
            "solve_wall_time_s": summary.get("wall_time_s"),
            "status": summary.get("status"), "elements": len(summary.get("elements", [])),
            "friction_torque_N_m": summary.get("friction_torque"),
            "missing_files": missing, "contact_dirs": contact_dirs,
            "load_average_1min": os.getloadavg()[0]}


def main(outdir: str | Path = "out/bearing_benchmark", quick: bool = False,
         repeat: int | None = None) -> dict:
    """Time the command; write ``benchmark.json`` and ``benchmark.md``; return the numbers.

    quick: one repetition; full: three (the minimum is the figure to quote).
    """
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    n = repeat or (1 if quick else 3)
    runs = [run_once(out / f"run{i}") for i in range(n)]
    times = [r["wall_time_s"] for r in runs]
    res = {"example": "6209", "runs": runs, "min_wall_time_s": min(times),
           "median_wall_time_s": statistics.median(times), "target_s": 60.0,
           "cpu_count": os.cpu_count()}
    (out / "benchmark.json").write_text(json.dumps(res, indent=1))
    lines = ["| run | wall s | solve s | exit | status | elements | missing files | load avg |",
             "|---|---|---|---|---|---|---|---|"]
    for i, r in enumerate(runs):
        solve = "-" if r["solve_wall_time_s"] is None else f"{r['solve_wall_time_s']:.1f}"
        lines.append(f"| {i} | {r['wall_time_s']:.1f} | {solve} | "
                     f"{r['exit_code']} | {r['status']} | {r['elements']} | "
                     f"{', '.join(r['missing_files']) or 'none'} | "
                     f"{r['load_average_1min']:.2f} |")
    lines.append(f"\nminimum {min(times):.1f} s, median {statistics.median(times):.1f} s "
                 f"(target < 60 s on 2 cores; {os.cpu_count()} CPUs here)")
    (out / "benchmark.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return res


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/bearing_benchmark")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--repeat", type=int, default=None)
    a = parser.parse_args()
    main(a.outdir, quick=a.quick, repeat=a.repeat)

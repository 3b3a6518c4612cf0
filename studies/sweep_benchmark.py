"""Wall time of the circular EHL map as a sweep on 2 local Dask workers against the serial loop.

Question
--------
How much faster is the circular point-contact map of ``studies/point_ehl_map.py`` (its 13
(M, L) cases with alpha p_h <= 40, each solved on every grid) when its solves run as a
sweep (:func:`bearing_fem.sweep`) on a Dask ``LocalCluster`` of 2 worker processes (one
thread each) than when they run one after another in one process? Target: the sweep
takes at most 0.6 of the serial loop's wall time.

Scene
-----
The map's own cases: :func:`point_ehl_map.map_cases` and :func:`point_ehl_map.moes_scene`
(rx = ry = 10 mm, E' = 2.2e11 Pa, alpha = 2e-8 1/Pa, eta0 = 0.01 Pa s, pure rolling), on
the map's grids 129^2, 257^2, 513^2 (``quick``: 65^2 only). The serial loop calls
``bearing_fem.solve`` on each (case, grid); the sweep solves the same scenes into a fresh
run store, writing each run's result files (summary.json, result.h5, fields.vtu) as a
sweep does, largest grids first. The sweep's films must equal the loop's (the same
solver on the same scenes).

Expected outcome
----------------
With two idle cores, close to 0.5 (the 513^2 solves dominate and balance over the two
workers; the cluster start-up, the store and the result files cost seconds). The machine
is shared: the load average before and after each phase is recorded, and a busy machine
shows in the ratio.

Run ``python studies/sweep_benchmark.py OUTDIR [--quick] [--pool]`` (``--pool``: also the
default local process pool). Writes ``sweep_benchmark.json`` and ``sweep_benchmark.md``.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from point_ehl_map import GRIDS, map_cases, moes_scene  # noqa: E402

#: Design target: sweep wall time / serial wall time on 2 workers.
TARGET_RATIO = 0.6
WORKERS = 2


def _load() -> float:
    """1-minute load average of the machine (0 where unknown)."""
    try:
        return float(os.getloadavg()[0])
    except (AttributeError, OSError):  # pragma: no cover - not Unix
        return 0.0


def serial_loop(runs: list[tuple[float, float, int]]) -> dict:
    """Solve every (M, L, n) one after another in this process."""
    t0, load0 = time.perf_counter(), _load()
    cpu0 = time.process_time()
    films, statuses = {}, {}
    for M, L, n in runs:
        r = bf.solve(moes_scene(M, L, n))
        films[(M, L, n)] = r.quantities.get("h_central")
        statuses[(M, L, n)] = r.status
    return {"wall_s": time.perf_counter() - t0, "cpu_s": time.process_time() - cpu0,
            "load_before": load0, "load_after": _load(), "films": films,
            "statuses": statuses}


_CHILD = """
import json, os, sys, time
sys.path.insert(0, sys.argv[2])
import bearing_fem as bf
from point_ehl_map import moes_scene
scene = moes_scene(100.0, 10.0, int(sys.argv[1]))
bf.solve(moes_scene(100.0, 10.0, 33))  # imports and first-call costs out of the timing
t0, c0 = time.perf_counter(), os.times()
r = bf.solve(scene)
c1 = os.times()
print(json.dumps({"wall_s": time.perf_counter() - t0, "user_s": c1.user - c0.user,
                  "system_s": c1.system - c0.system, "status": r.status}))
"""


def malloc_check(nodes: int, repeats: int = 2) -> dict:
    """One M = 100, L = 10 solve on ``nodes``^2 in a fresh process with the environment
    of a Dask worker by default (MALLOC_TRIM_THRESHOLD_=65536), with
    :data:`bearing_fem.sweep.WORKER_MALLOC_ENV`, and with neither; interleaved,
    ``repeats`` times, the fastest kept."""
    import subprocess

    from bearing_fem.sweep import WORKER_MALLOC_ENV

    base = {k: v for k, v in os.environ.items() if k not in WORKER_MALLOC_ENV}
    envs = {"plain": base, "dask default": base | {"MALLOC_TRIM_THRESHOLD_": "65536"},
            "WORKER_MALLOC_ENV": base | WORKER_MALLOC_ENV}
    best: dict[str, dict] = {}
    for _ in range(repeats):
        for name, env in envs.items():
            out = subprocess.run([sys.executable, "-c", _CHILD, str(nodes),
                                  str(Path(__file__).resolve().parent)], env=env,
                                 capture_output=True, text=True, check=True)
            row = json.loads(out.stdout.strip().splitlines()[-1])
            if name not in best or row["wall_s"] < best[name]["wall_s"]:
                best[name] = row
    return {"nodes": nodes, "runs": best}


def sweep_run(runs: list[tuple[float, float, int]], outdir: Path, executor: str,
              files: str = "all") -> dict:
    """The same solves as a sweep into a fresh store: on a Dask LocalCluster of
    ``WORKERS`` processes (``executor = "dask"``) or the local pool (``"pool"``), each
    run writing its result files (``files = "all"``) or its summary alone
    (``"summary"``: like the serial loop, which writes no per-run files)."""
    from bearing_fem.sweep import Case, RunStore, sweep

    store = outdir / f"benchmark_{executor}_{files}.sqlite"
    for p in (store, outdir / f"benchmark_{executor}_{files}_runs"):
        if p.is_dir():
            shutil.rmtree(p)
        elif p.exists():
            p.unlink()
    for suffix in ("-wal", "-shm"):
        Path(str(store) + suffix).unlink(missing_ok=True)
    cases = {(M, L, n): Case({"M": M, "L": L, "nodes": n}, moes_scene(M, L, n))
             for M, L, n in sorted(runs, key=lambda r: -r[2])}
    load0 = _load()
    t_start = time.perf_counter()
    cluster = None
    if executor == "dask":
        from bearing_fem.sweep import local_cluster

        cluster = local_cluster(WORKERS)
    t0 = time.perf_counter()
    try:
        report = sweep(list(cases.values()), store=store, scheduler=cluster,
                       workers=WORKERS if cluster is None else None, files=files)
        wall = time.perf_counter() - t0
    finally:
        if cluster is not None:
            cluster.close()
    with RunStore(store) as s:
        rows = {r["hash"]: r for r in s.rows()}
    return {"executor": report.executor, "files": files, "wall_s": wall,
            "startup_s": t0 - t_start, "load_before": load0, "load_after": _load(),
            "ran": report.ran, "successes": report.successes,
            "films": {k: rows[c.hash]["h_central"] for k, c in cases.items()},
            "statuses": {k: rows[c.hash]["status"] for k, c in cases.items()},
            "solver_s": sum(r["wall_time_s"] or 0.0 for r in rows.values()),
            "run_s": sum(r["run_time_s"] or 0.0 for r in rows.values())}


def main(outdir, quick: bool = False, *, pool: bool = False) -> dict:
    """Run the serial loop and the sweep(s); write the tables; return the numbers."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    grids = (65,) if quick else GRIDS
    runs = [(M, L, n) for M, L in map_cases() for n in grids]
    malloc = malloc_check(65 if quick else 257)
    serial = serial_loop(runs)
    results = {"dask": sweep_run(runs, outdir, "dask"),
               "dask_summary": sweep_run(runs, outdir, "dask", files="summary")}
    if pool or quick:
        results["pool"] = sweep_run(runs, outdir, "pool")
    out = {"grids": list(grids), "runs": len(runs), "workers": WORKERS,
           "cores": os.cpu_count(), "serial_s": serial["wall_s"],
           "serial_cpu_s": serial["cpu_s"],
           "serial_load": [serial["load_before"], serial["load_after"]],
           "target_ratio": TARGET_RATIO, "malloc": malloc, "sweeps": {}}
    for name, r in results.items():
        diffs = [abs(r["films"][k] / serial["films"][k] - 1.0) for k in serial["films"]
                 if r["films"][k] is not None and serial["films"][k]]
        out["sweeps"][name] = {
            "executor": r["executor"], "files": r["files"], "wall_s": r["wall_s"],
            "startup_s": r["startup_s"],
            "ratio": r["wall_s"] / serial["wall_s"],
            "ratio_with_startup": (r["wall_s"] + r["startup_s"]) / serial["wall_s"],
            "load": [r["load_before"], r["load_after"]], "ran": r["ran"],
            "successes": r["successes"], "solver_s": r["solver_s"], "run_s": r["run_s"],
            "statuses_match": r["statuses"] == serial["statuses"],
            "max_film_difference": max(diffs) if diffs else None}
    (outdir / "sweep_benchmark.json").write_text(json.dumps(out, indent=1) + "\n")
    lines = [f"Circular EHL map, {len(runs)} solves ({len(map_cases())} cases on "
             f"{', '.join(f'{n}^2' for n in grids)}), {os.cpu_count()} cores",
             "", "| run | files per run | wall time [s] | ratio to serial | solver time, "
             "sum [s] | files, sum [s] | start-up [s] | load average before/after | "
             "films as serial |", "|---|---|---|---|---|---|---|---|---|",
             f"| serial loop (one process) | none | {serial['wall_s']:.1f} | 1 | "
             f"{serial['wall_s']:.1f} | 0 | - | "
             f"{serial['load_before']:.2f}/{serial['load_after']:.2f} | - |"]
    for name, s in out["sweeps"].items():
        same = ("yes" if s["statuses_match"] and (s["max_film_difference"] or 0.0) < 1e-9
                else f"no (max rel. diff {s['max_film_difference']})")
        lines.append(f"| sweep, {s['executor'].split(' at ')[0]} of {WORKERS} | "
                     f"{s['files']} | {s['wall_s']:.1f} | {s['ratio']:.3f} | "
                     f"{s['solver_s']:.1f} | {s['run_s'] - s['solver_s']:.1f} | "
                     f"{s['startup_s']:.1f} | "
                     f"{s['load'][0]:.2f}/{s['load'][1]:.2f} | {same} |")
    lines += ["", f"Target: ratio <= {TARGET_RATIO} on {WORKERS} workers. The serial loop "
              "(as in the map study) writes no per-run files; a sweep with files = \"all\" "
              "also writes summary.json, result.h5 and a compressed fields.vtu per run "
              "('files, sum'). 'solver time, sum' adds the solves' own wall times over the "
              "workers (two solves at once share the memory bandwidth). A load average "
              "above 0 before a phase means other programs shared the cores."]
    lines += ["", f"One {malloc['nodes']}^2 solve (M = 100, L = 10) in a fresh process, "
              "fastest of 2 interleaved runs, by the malloc environment:", "",
              "| environment | wall [s] | user [s] | system [s] |", "|---|---|---|---|"]
    for name, row in malloc["runs"].items():
        lines.append(f"| {name} | {row['wall_s']:.2f} | {row['user_s']:.2f} | "
                     f"{row['system_s']:.2f} |")
    text = "\n".join(lines) + "\n"
    (outdir / "sweep_benchmark.md").write_text(text)
    print(text)
    return out


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir", nargs="?", default="out_sweep_benchmark")
    parser.add_argument("--quick", action="store_true", help="65^2 grids only")
    parser.add_argument("--pool", action="store_true", help="also the local process pool")
    a = parser.parse_args()
    main(a.outdir, quick=a.quick, pool=a.pool)

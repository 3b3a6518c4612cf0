"""Elastic circular point contacts over the Moes (M, L) map: convergence, grid
convergence and the central/minimum film against Nijenbanning-Venner-Moes and
Hamrock-Dowson.

Question
--------
Does the elastic point-contact solver (:func:`bearing_fem.contacts.point.solve_point`: Newton on
(p, h0), Fischer-Burmeister cavitation, FFT half-space, GMRES) converge without tuning
for M in {20, 50, 100, 200, 500} and L in {5, 10, 20} with alpha p_h <= 40? Is h_c
grid-converged at 257^2 (change from 257^2 to the next finer grid, 513^2, below 1%), within 10% of the
Nijenbanning-Venner-Moes (1994) formula, and are h_c and h_min within 20% of
Hamrock-Dowson (1977)?

Scene
-----
Circular contact rx = ry = 10 mm, E' = 2.2e11 Pa, alpha = 2e-8 1/Pa, eta0 = 0.01 Pa s,
pure rolling; (M, L) realised by :func:`bearing_fem.units.point_scene_parameters_from_moes`
(sum-speed Moes groups). Default domain of the solver (x in [-4.5, 1.5] a or longer at
low M, y symmetric), each grid solved from scratch (the solver's own grid sequencing
65 -> ... -> n). Formulas from :mod:`bearing_fem.formulas`.

Expected outcome
----------------
All cases converge; h_c changes by less than 1% from 257^2 to 513^2, lies within 10% of
NVM, and h_c and h_min lie within 20% of Hamrock-Dowson (fits with a stated scatter of
5-10%; their h_min fit is the weaker one).

``python studies/point_ehl_map.py --groups`` prints the Hamrock-Dowson groups of the map
cases (no solve). Run ``python studies/point_ehl_map.py [outdir] [--quick] [--grids=129,257,513]
[--workers=N] [--scheduler=ADDRESS]`` (about 16 minutes on one core with the default grids;
the 513^2 solves dominate). The solves run as a sweep (:func:`bearing_fem.sweep`): on a
local process pool (one process per core, or ``--workers``) or on a Dask cluster
(``--scheduler``), each recorded in the run store ``point_ehl_map.sqlite`` with its result
files in ``point_ehl_map_runs/``. An interrupted run resumes: running it again solves only
the cases the store does not hold, and the tables are built from the store.
"""
from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

from bearing_fem.formulas import point_central_film_nvm, point_films_hamrock_dowson
from bearing_fem.contacts.point import solve_point
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec,
                               Scene, SolverSpec)
from bearing_fem.units import moes_point, point_scene_parameters_from_moes

M_VALUES = (20, 50, 100, 200, 500)
L_VALUES = (5, 10, 20)
MAX_ALPHA_PH = 40.0
#: Default grids (nodes per direction); the grid change of the 257^2 result is measured
#: against the next finer grid, 513^2 (the last two).
GRIDS = (129, 257, 513)
#: Acceptance targets: relative h_c change between the two finest grids, |h_c/NVM - 1|,
#: |h/HD - 1| for h_c and h_min.
GRID_CHANGE_TARGET = 0.01
NVM_TARGET = 0.10
HD_TARGET = 0.20
#: The extra grid check (``check_next_grid``) is skipped above this many nodes per direction
#: (a 1025^2 solve needs about 10 GB).
MAX_CHECK_GRID = 513


def moes_scene(M: float, L: float, nodes: int, *, ry_over_rx: float = 1.0,
               max_iterations: int = 30) -> Scene:
    """Elastic point scene realising (M, L) (circular unless ``ry_over_rx`` != 1)."""
    d = point_scene_parameters_from_moes(M, L, rx=0.01, ry=0.01 * ry_over_rx)
    u = d["mean_speed"]
    return Scene(title=f"M={M:g}, L={L:g}",
                 contact=Contact(kind="point", rx=d["rx"], ry=d["ry"]),
                 materials=Materials(reduced_modulus=d["e_prime"]),
                 lubricant=Lubricant(viscosity=d["viscosity"], piezo=d["piezo"]),
                 kinematics=Kinematics(u1=u, u2=u), load=Load(force=d["force"]),
                 mesh=MeshSpec(nodes=(nodes, nodes)),
                 solver=SolverSpec(max_iterations=max_iterations))


def _formulas(scene: Scene) -> dict:
    c, lub, u = scene.contact, scene.lubricant, scene.kinematics.mean_speed
    args = (scene.load.force, c.rx, c.ry, scene.e_prime, lub.viscosity, u, lub.piezo)
    h_min_hd, h_c_hd = point_films_hamrock_dowson(*args)
    return {"moes": moes_point(*args), "h_central_nvm_m": point_central_film_nvm(*args),
            "h_central_hd_m": h_c_hd, "h_min_hd_m": h_min_hd}


def run_case(M: float, L: float, nodes: int) -> tuple[dict, object]:
    """Solve one (M, L) case on nodes x nodes in this process; return (row, Result)."""
    scene = moes_scene(M, L, nodes)
    t0 = time.perf_counter()
    res = solve_point(scene)
    wall = time.perf_counter() - t0
    return case_row(M, L, nodes, scene, res.quantities, res.status, res.newton_iterations,
                    wall, [list(s) for s in res.continuation], res.message), res


def case_row(M: float, L: float, nodes: int, scene: Scene, q: dict, status: str,
             newton_iterations: int, wall: float, continuation: list, message: str) -> dict:
    """The table row of one solve: its numbers against the film formulas."""
    f = _formulas(scene)
    g = f["moes"]
    q = {k: math.nan if v is None else v for k, v in q.items()}  # a store keeps NaN as None
    hc, hmin = q.get("h_central", math.nan), q.get("h_min", math.nan)
    return {"M": M, "L": L, "alpha_ph": g["alpha_ph"], "nodes": nodes, "status": status,
            "newton_iterations": newton_iterations, "wall_time_s": wall,
            "continuation": continuation,
            "gmres_iterations": q.get("gmres_iterations"),
            "h_central_m": hc, "h_min_m": hmin, "p_max_Pa": q.get("p_max"),
            "h_central_nvm_m": f["h_central_nvm_m"], "h_central_hd_m": f["h_central_hd_m"],
            "h_min_hd_m": f["h_min_hd_m"],
            "h_central_ratio": hc / f["h_central_nvm_m"],
            "h_central_vs_hd": hc / f["h_central_hd_m"] - 1.0,
            "h_min_vs_hd": hmin / f["h_min_hd_m"] - 1.0,
            "p_max_over_ph": q.get("p_max", math.nan) / g["p_h"],
            "load_ratio": q.get("load", math.nan) / scene.load.force,
            "message": message}


def _assess(case: dict) -> dict:
    """Grid change and target checks of one case (finest grid against the formulas)."""
    runs = case["runs"]
    fine = runs[-1]
    case["status"] = "converged" if all(r["status"] == "converged" for r in runs) \
        else next(r["status"] for r in runs if r["status"] != "converged")
    case["message"] = fine["message"]
    case["h_central_ratio"] = fine["h_central_ratio"]
    case["h_central_vs_nvm"] = fine["h_central_ratio"] - 1.0
    case["h_central_vs_hd"] = fine["h_central_vs_hd"]
    case["h_min_vs_hd"] = fine["h_min_vs_hd"]
    case["grid_change"] = (fine["h_central_m"] / runs[-2]["h_central_m"] - 1.0
                           if len(runs) > 1 else math.nan)
    case["h_min_grid_change"] = (fine["h_min_m"] / runs[-2]["h_min_m"] - 1.0
                                 if len(runs) > 1 else math.nan)
    # how far the two fits disagree with each other (formula against formula)
    case["nvm_vs_hd"] = fine["h_central_nvm_m"] / fine["h_central_hd_m"] - 1.0
    # side-lobe constriction: FE h_min/h_c against the ratio of Hamrock-Dowson's two fits
    case["h_min_over_h_c"] = fine["h_min_m"] / fine["h_central_m"]
    case["h_min_over_h_c_hd"] = fine["h_min_hd_m"] / fine["h_central_hd_m"]
    missed = []
    if case["status"] != "converged":
        missed.append("not converged")
    if len(runs) > 1 and not abs(case["grid_change"]) < GRID_CHANGE_TARGET:
        missed.append("grid change")
    if not abs(case["h_central_vs_nvm"]) < NVM_TARGET:
        missed.append("NVM")
    if not abs(case["h_central_vs_hd"]) < HD_TARGET:
        missed.append("HD h_c")
    if not abs(case["h_min_vs_hd"]) < HD_TARGET:
        missed.append("HD h_min")
    case["missed"] = missed
    case["met"] = not missed
    return case


#: Per-case columns after the per-grid ones: (key, scale, text format, markdown format).
_COLUMNS = (("grid_change", 100, "+7.2f", "+.2f"), ("h_central_vs_nvm", 100, "+6.1f", "+.1f"),
            ("h_central_vs_hd", 100, "+7.1f", "+.1f"), ("h_min_vs_hd", 100, "+9.1f", "+.1f"),
            ("h_min_grid_change", 100, "+11.2f", "+.2f"), ("nvm_vs_hd", 100, "+8.1f", "+.1f"),
            ("h_min_over_h_c", 1, "7.3f", ".3f"), ("h_min_over_h_c_hd", 1, "5.3f", ".3f"))


def _table(cases: list[dict], grids: tuple[int, ...]) -> tuple[str, str]:
    """Plain-text and markdown tables of the map."""
    head = (f"{'M':>5} {'L':>4} {'aph':>5} " + " ".join(
        f"{f'{n}^2: its':>10} {'s':>6} {'h_c/NVM':>7}" for n in grids)
        + f" {'grid %':>7} {'NVM %':>6} {'HD hc %':>7} {'HD hmin %':>9} {'hmin grid %':>11}"
        f" {'NVM/HD %':>8} {'hmin/hc':>7} {'HD':>5}  status")
    lines = [head]
    md = ["| M | L | alpha p_h | " + " | ".join(
        f"{n}^2 h_c [nm] | {n}^2 its | {n}^2 s" for n in grids)
        + " | grid change % | vs NVM % | vs HD h_c % | vs HD h_min % | h_min grid change %"
        " | NVM vs HD h_c % | h_min/h_c | HD h_min/h_c | status |",
        "|---|---|---|" + "---|---|---|" * len(grids) + "---|" * (len(_COLUMNS) + 1)]
    for c in cases:
        if c["status"] == "skipped":
            lines.append(f"{c['M']:5g} {c['L']:4g} {c['alpha_ph']:5.1f}  skipped "
                         f"(alpha p_h > {MAX_ALPHA_PH:g})")
            md.append(f"| {c['M']:g} | {c['L']:g} | {c['alpha_ph']:.1f} | "
                      + " | ".join("-" for _ in range(3 * len(grids) + len(_COLUMNS)))
                      + f" | skipped (alpha p_h > {MAX_ALPHA_PH:g}) |")
            continue
        verdict = "MET" if c["met"] else "NOT MET: " + ", ".join(c["missed"])
        cells = " ".join(f"{r['newton_iterations']:>10d} {r['wall_time_s']:6.1f} "
                         f"{r['h_central_ratio']:7.3f}" for r in c["runs"])
        tail = " ".join(format(scale * c[key], fmt) for key, scale, fmt, _ in _COLUMNS)
        lines.append(f"{c['M']:5g} {c['L']:4g} {c['alpha_ph']:5.1f} {cells} {tail}  {verdict}")
        mcells = " | ".join(f"{1e9 * r['h_central_m']:.2f} | {r['newton_iterations']} | "
                            f"{r['wall_time_s']:.1f}" for r in c["runs"])
        mtail = " | ".join(format(scale * c[key], fmt) for key, scale, _, fmt in _COLUMNS)
        md.append(f"| {c['M']:g} | {c['L']:g} | {c['alpha_ph']:.1f} | {mcells} | {mtail} | "
                  f"{verdict} |")
    return "\n".join(lines), "\n".join(md)


def sweep_cases(runs: list[tuple[float, float, int]], store: Path, *, scheduler=None,
                workers: int | None = None) -> dict[tuple[float, float, int], dict]:
    """Solve (M, L, nodes) runs as a sweep into ``store``; return their rows.

    Runs the store already holds are not solved again (resume). The largest grids are
    submitted first (the cases differ in cost by 50x). A run whose worker was lost has
    status ``lost`` and no numbers (run the study again to finish it).
    """
    from bearing_fem.io import read_result
    from bearing_fem.sweep import Case, RunStore, sweep

    cases = {(M, L, n): Case({"M": M, "L": L, "nodes": n}, moes_scene(M, L, n))
             for M, L, n in sorted(runs, key=lambda r: -r[2])}
    sweep(list(cases.values()), store=store, scheduler=scheduler, workers=workers,
          progress=True)
    with RunStore(store) as s:
        stored = {r["hash"]: r for r in s.rows()}
        paths = {h: s.resolve(r["result_path"]) for h, r in stored.items()}
    rows = {}
    for (M, L, n), case in cases.items():
        r = stored[case.hash]
        h5 = paths[case.hash] / "result.h5" if paths[case.hash] else None
        continuation = (read_result(h5)["continuation"] if h5 is not None and h5.is_file()
                        else [])
        rows[(M, L, n)] = case_row(M, L, n, case.scene, r, r["status"],
                                   r.get("newton_iterations") or 0, r.get("wall_time_s"),
                                   continuation, r["message"])
        rows[(M, L, n)]["result_path"] = str(paths[case.hash]) if paths[case.hash] else None
    return rows


def main(outdir, quick: bool = False, *, nodes: int | None = None,
         grids: tuple[int, ...] | None = None, plot: bool = True,
         check_next_grid: bool = True, scheduler=None, workers: int | None = None,
         store: str | Path | None = None) -> dict:
    """Run the map; write ``point_ehl_map.json``/``.txt``/``.md`` (and a PNG); return it.

    Parameters
    ----------
    outdir : path
    quick : bool
        M in {20, 100}, L = 10 on 65^2 and 129^2.
    nodes : int, optional
        A single grid (no grid change is measured).
    grids : tuple of int, optional
        Grids (nodes per direction, increasing); default ``GRIDS``.
    plot : bool
        Pressure map of the last case on the finest grid.
    check_next_grid : bool
        Cases that miss the grid-change target are also solved on the next finer grid
        (2 n - 1 nodes), to show how far the finest of ``grids`` is from convergence
        (``grid_change_next``), up to ``MAX_CHECK_GRID`` nodes; the acceptance verdict is
        not changed by it.
    scheduler : str or distributed.Client or cluster, optional
        Run the solves on a Dask cluster (default: a local process pool).
    workers : int, optional
        Processes of the local pool (default: one per core; 1 solves in this process).
    store : path, optional
        The run store (default ``outdir/point_ehl_map.sqlite``); a rerun resumes from it.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    if grids is None:
        grids = (nodes,) if nodes else ((65, 129) if quick else GRIDS)
    grids = tuple(int(n) for n in grids)
    pairs = [(20, 10), (100, 10)] if quick else [(m, l) for m in M_VALUES for l in L_VALUES]
    store = Path(store) if store is not None else outdir / "point_ehl_map.sqlite"
    cases = []
    t_start = time.perf_counter()
    alpha_ph = {(M, L): _formulas(moes_scene(M, L, grids[0]))["moes"]["alpha_ph"]
                for M, L in pairs}
    solved = [(M, L) for M, L in pairs if alpha_ph[(M, L)] <= MAX_ALPHA_PH]
    rows = sweep_cases([(M, L, n) for M, L in solved for n in grids], store,
                       scheduler=scheduler, workers=workers)
    for M, L in pairs:
        if alpha_ph[(M, L)] > MAX_ALPHA_PH:
            cases.append({"M": M, "L": L, "alpha_ph": alpha_ph[(M, L)], "status": "skipped",
                          "message": f"alpha p_h = {alpha_ph[(M, L)]:.1f} > {MAX_ALPHA_PH}"})
            continue
        runs = [rows[(M, L, n)] for n in grids]
        for row in runs:
            print(_run_text(row), flush=True)
        cases.append(_assess({"M": M, "L": L, "alpha_ph": alpha_ph[(M, L)], "runs": runs}))
    finer = 2 * grids[-1] - 1
    checks = [c for c in cases if c["status"] != "skipped" and "grid change" in c["missed"]]
    if check_next_grid and checks and finer <= MAX_CHECK_GRID:
        extra = sweep_cases([(c["M"], c["L"], finer) for c in checks], store,
                            scheduler=scheduler, workers=workers)
        for case in checks:
            row = extra[(case["M"], case["L"], finer)]
            case["next_run"] = row
            case["grid_change_next"] = row["h_central_m"] / case["runs"][-1]["h_central_m"] - 1.0
            print(_run_text(row, " (grid check)"), flush=True)
    if plot and solved:
        path = rows[(*solved[-1], grids[-1])]["result_path"]
        if path is not None:
            from bearing_fem.plot import plot_result

            plot_result(Path(path) / "result.h5", outdir / "point_ehl_map_last.png", kind="map")
    for c in cases:  # where each run's files are is in the store, not in the tables
        for row in c.get("runs", []) + ([c["next_run"]] if "next_run" in c else []):
            row.pop("result_path", None)
    return _write(outdir, cases, grids, t_start, final=True)


def _run_text(row: dict, note: str = "") -> str:
    return (f"M={row['M']:g} L={row['L']:g} {row['nodes']}^2{note}: {row['status']}, "
            f"{row['newton_iterations']} Newton its, {row['wall_time_s']:.1f} s, h_c/NVM "
            f"{row['h_central_ratio']:.4f}")


def _write(outdir: Path, cases: list[dict], grids: tuple[int, ...], t_start: float,
           final: bool = False) -> dict:
    """Write the tables of the cases done so far (``final``: also print them)."""
    solved = [c for c in cases if c["status"] != "skipped"]
    worst = max((abs(c["h_central_ratio"] - 1) for c in solved), default=math.nan)
    worst_change = max((abs(c["grid_change"]) for c in solved), default=math.nan)
    n_conv = sum(c["status"] == "converged" for c in solved)
    n_met = sum(c["met"] for c in solved)
    text, md = _table(cases, grids)
    checks = [c for c in cases if "next_run" in c]
    if checks:
        note = "\n".join(
            f"grid check M={c['M']:g} L={c['L']:g}: {c['next_run']['nodes']}^2 "
            f"{c['next_run']['status']}, {c['next_run']['newton_iterations']} its, "
            f"{c['next_run']['wall_time_s']:.1f} s, h_c/NVM "
            f"{c['next_run']['h_central_ratio']:.3f}, change from {grids[-1]}^2 "
            f"{100 * c['grid_change_next']:+.2f}%" for c in checks)
        text, md = text + "\n" + note, md + "\n\n" + note.replace("\n", "  \n")
    summary = (f"{n_conv} of {len(solved)} converged on {' and '.join(f'{n}^2' for n in grids)}; "
               f"max |h_c/NVM - 1| = {worst:.3f} on {grids[-1]}^2"
               + (f"; max |grid change| = {100 * worst_change:.2f}%" if len(grids) > 1 else "")
               + f"; all targets met in {n_met} of {len(solved)} "
               f"(grid change < {100 * GRID_CHANGE_TARGET:g}%, NVM < {100 * NVM_TARGET:g}%, "
               f"Hamrock-Dowson h_c and h_min < {100 * HD_TARGET:g}%); "
               f"total {time.perf_counter() - t_start:.0f} s")
    if final:
        print(text + "\n" + summary)
    (outdir / "point_ehl_map.txt").write_text(text + "\n" + summary + "\n")
    (outdir / "point_ehl_map.md").write_text(md + "\n\n" + summary + "\n")
    out = {"grids": list(grids), "cases": cases, "max_abs_hc_deviation": worst,
           "max_abs_grid_change": worst_change, "targets_met": n_met, "summary": summary}
    (outdir / "point_ehl_map.json").write_text(json.dumps(out, indent=1))
    return out


def map_cases() -> list[tuple[float, float]]:
    """The (M, L) cases of the map that are solved (alpha p_h <= MAX_ALPHA_PH)."""
    return [(float(M), float(L)) for M in M_VALUES for L in L_VALUES
            if _formulas(moes_scene(M, L, 65))["moes"]["alpha_ph"] <= MAX_ALPHA_PH]


def hamrock_groups() -> str:
    """Hamrock-Dowson groups U, W, G (mean speed, rx) of the map cases, and their spans.

    No solve: the range of the map in the variables of the Hamrock-Dowson fits (which
    varied U over nearly two orders of magnitude and W over one).
    """
    rows = []
    for M, L in map_cases():
        g = _formulas(moes_scene(M, L, 65))["moes"]
        rows.append((M, L, g["U"], g["W"], g["G"]))
    lines = ["| M | L | U | W | G |", "|---|---|---|---|---|"]
    lines += [f"| {M:g} | {L:g} | {U:.3g} | {W:.3g} | {G:.0f} |" for M, L, U, W, G in rows]
    us, ws = [r[2] for r in rows], [r[3] for r in rows]
    lines.append(f"\nU spans {min(us):.3g}..{max(us):.3g} (x{max(us) / min(us):.0f}, "
                 f"{math.log10(max(us) / min(us)):.1f} decades); W spans {min(ws):.3g}.."
                 f"{max(ws):.3g} (x{max(ws) / min(ws):.0f}, "
                 f"{math.log10(max(ws) / min(ws)):.1f} decades)")
    return "\n".join(lines)


if __name__ == "__main__":
    if "--groups" in sys.argv:
        print(hamrock_groups())
        sys.exit(0)
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    opts = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--") and "=" in a)
    main(args[0] if args else "out_point_ehl_map", quick="--quick" in sys.argv,
         grids=tuple(int(n) for n in opts["grids"].split(",")) if "grids" in opts else None,
         workers=int(opts["workers"]) if "workers" in opts else None,
         scheduler=opts.get("scheduler"))

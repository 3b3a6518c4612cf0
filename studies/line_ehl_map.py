"""Line-contact EHL map: robustness, grid convergence and the Moes film formula.

Question
    Does the damped-Newton FE solver converge, with no per-case tuning, over the Moes
    map M in {5, 10, 20, 50, 100, 200, 500, 1000} x L in {0, 2, 5, 10, 15, 20}
    (alpha p_h <= 40), is h_central grid-converged, and how far is it from the Moes
    line formula? Cases with 40 < alpha p_h <= 100 must converge or fail explicitly.

Scene
    Steel-like E' = 2.2e11 Pa, R = 10 mm, alpha = 2e-8 1/Pa (L > 0; alpha = 0 for L = 0),
    eta0 = 0.01 Pa s, pure rolling; (M, L) realised by
    :func:`bearing_fem.units.line_scene_from_moes`; Barus viscosity, incompressible,
    Reynolds cavitation, half-space elasticity; default domain; the solver's default
    mesh (800/6 (M/100)^0.75 nodes per Hertz half-width, at least 801 and at most 4001
    nodes; isoviscous scenes whose grid reaches the cap take the shorter domain
    [-1.5, 1.2] b; or ``nodes``) and one
    with half its spacing (``2 nodes - 1``) for the grid-convergence check.

Expected outcome
    Every case converges; h_central changes < 0.5 % between the two grids and lies within
    12 % of Moes (the formula is a fit with a stated accuracy of a few per cent).

Run ``python studies/line_ehl_map.py [outdir]``; ``main(outdir, quick=True)`` runs a
subset for the tests. The solves run as sweeps (:func:`bearing_fem.sweep`; first every
coarse grid, then the fine grid of each case whose coarse solve succeeded) on a local
process pool (``main(..., workers=N)``) or a Dask cluster (``scheduler=ADDRESS``), each
recorded in the run store ``line_ehl_map.sqlite`` with its result files in
``line_ehl_map_runs/``; running the study again resumes from the store.
"""
from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

import bearing_fem as bf
from bearing_fem import formulas, units
from bearing_fem.scene import Scene

M_VALUES = (5, 10, 20, 50, 100, 200, 500, 1000)
L_VALUES = (0, 2, 5, 10, 15, 20)


def scene_for(M: float, L: float, nodes: int | None = None, u_sum_isoviscous: float = 1e-11) -> Scene:
    """Scene realising Moes (M, L); for L = 0 the lubricant is isoviscous at U_sum given."""
    if L > 0:
        par = units.line_scene_from_moes(M, L)
    else:
        R, E = 0.01, 2.2e11
        eta = 0.01
        par = {"radius": R, "e_prime": E, "viscosity": eta, "piezo": 0.0,
               "mean_speed": u_sum_isoviscous * E * R / (2 * eta),
               "load_per_length": M * math.sqrt(u_sum_isoviscous) * E * R}
    d = {
        "title": f"Moes M={M}, L={L}",
        "contact": {"kind": "line", "rx": par["radius"]},
        "materials": {"reduced_modulus": par["e_prime"]},
        "lubricant": {"viscosity": par["viscosity"], "piezo": par["piezo"]},
        "kinematics": {"u1": par["mean_speed"], "u2": par["mean_speed"]},
        "load": {"force": par["load_per_length"]},
    }
    if nodes:
        d["mesh"] = {"nodes": nodes}
    return Scene.from_dict(d)


def default_nodes(M: float, L: float) -> int:
    """Node count of the solver's own default mesh for case (M, L)."""
    from bearing_fem.contacts.line import line_setup

    return int(line_setup(scene_for(M, L)).disc.x.size)


def run_case(M: float, L: float, nodes: int | None = None) -> dict:
    """Solve one case on ``nodes`` (default: the solver's default mesh) and on
    ``2 nodes - 1`` points (half the spacing); return the numbers."""
    out: dict = {"M": M, "L": L}
    if nodes is None:
        nodes = default_nodes(M, L)
    s = scene_for(M, L, nodes)
    g = units.moes_line(s.load.force, s.contact.rx, s.e_prime, s.lubricant.viscosity,
                        s.kinematics.mean_speed, s.lubricant.piezo)
    out["alpha_ph"] = g["alpha_ph"]
    h_moes = formulas.line_central_film_moes(s.load.force, s.contact.rx, s.e_prime,
                                             s.lubricant.viscosity, s.kinematics.mean_speed,
                                             s.lubricant.piezo)
    for tag, n in (("coarse", nodes), ("fine", 2 * nodes - 1)):
        t0 = time.perf_counter()
        r = bf.solve(scene_for(M, L, n))
        out[tag] = grid_entry(n, r.status, r.newton_iterations, time.perf_counter() - t0,
                              r.quantities, r.message, g["p_h"])
        if not r.success:
            break
    return finish_case(out, h_moes)


def grid_entry(n: int, status: str, iterations: int, seconds: float, q: dict, message: str,
               p_h: float) -> dict:
    """The numbers of one grid of a case (``q``: the result's quantities or stored row)."""
    p_max = q.get("p_max", 0.0)
    return {"nodes": n, "status": status, "iterations": iterations, "seconds": seconds,
            "h_central": q.get("h_central"), "h_min": q.get("h_min"),
            "p_max_over_ph": (math.nan if p_max is None else p_max) / p_h,
            "message": message}


def finish_case(out: dict, h_moes: float) -> dict:
    """Grid change and Moes deviation of a case whose grids are in ``out``."""
    out["h_moes"] = h_moes
    c, f = out["coarse"], out.get("fine")
    if f and c["status"] == f["status"] == "converged":
        out["grid_change"] = abs(c["h_central"] / f["h_central"] - 1.0)
        out["moes_deviation"] = f["h_central"] / h_moes - 1.0
    return out


def sweep_grids(runs: list[tuple[float, float, int]], store: Path, *, scheduler=None,
                workers: int | None = None) -> dict[tuple[float, float, int], dict]:
    """Solve (M, L, nodes) runs as a sweep into ``store`` (resuming from it); return
    (M, L, nodes) -> the stored row (status, message, summary numbers)."""
    from bearing_fem.sweep import Case, RunStore, sweep

    cases = {(M, L, n): Case({"M": M, "L": L, "nodes": n}, scene_for(M, L, n))
             for M, L, n in sorted(runs, key=lambda r: -r[2])}  # largest first
    sweep(list(cases.values()), store=store, scheduler=scheduler, workers=workers,
          progress=True)
    with RunStore(store) as s:
        stored = {r["hash"]: r for r in s.rows()}
    return {key: stored[c.hash] for key, c in cases.items()}


def main(outdir: str | Path = "out/line_ehl_map", quick: bool = False, nodes: int | None = None,
         max_alpha_ph: float = 100.0, l_values: tuple[float, ...] = L_VALUES,
         m_values: tuple[float, ...] = M_VALUES, *, scheduler=None, workers: int | None = None,
         store: str | Path | None = None) -> dict:
    """Run the map; write ``line_ehl_map.json`` and ``line_ehl_map.md``; return the rows.

    ``nodes`` None: each case on the solver's default mesh and on one twice as fine.
    ``scheduler`` (a Dask scheduler address or client), ``workers`` (local pool size;
    1 solves in this process) and ``store`` (default ``outdir/line_ehl_map.sqlite``) say
    where the solves run and where they are kept; a rerun resumes from the store."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    store = Path(store) if store is not None else outdir / "line_ehl_map.sqlite"
    cases = [(M, L) for L in l_values for M in m_values]
    if quick:
        cases = [(20, 5), (100, 10)]
    cases = [(M, L) for M, L in cases if L * math.sqrt(M / (2 * math.pi)) <= max_alpha_ph]
    coarse_nodes = {(M, L): nodes or default_nodes(M, L) for M, L in cases}
    info = {}
    for M, L in cases:
        s = scene_for(M, L, coarse_nodes[(M, L)])
        g = units.moes_line(s.load.force, s.contact.rx, s.e_prime, s.lubricant.viscosity,
                            s.kinematics.mean_speed, s.lubricant.piezo)
        h_moes = formulas.line_central_film_moes(s.load.force, s.contact.rx, s.e_prime,
                                                 s.lubricant.viscosity,
                                                 s.kinematics.mean_speed, s.lubricant.piezo)
        info[(M, L)] = (g, h_moes)
    # the fine grid of a case is solved only when its coarse grid succeeded
    coarse = sweep_grids([(M, L, coarse_nodes[(M, L)]) for M, L in cases], store,
                         scheduler=scheduler, workers=workers)
    ok = [(M, L) for M, L in cases if coarse[(M, L, coarse_nodes[(M, L)])]["success"]]
    fine = sweep_grids([(M, L, 2 * coarse_nodes[(M, L)] - 1) for M, L in ok], store,
                       scheduler=scheduler, workers=workers)
    rows = []
    for M, L in cases:
        g, h_moes = info[(M, L)]
        row: dict = {"M": M, "L": L, "alpha_ph": g["alpha_ph"]}
        for tag, table in (("coarse", coarse), ("fine", fine)):
            n = coarse_nodes[(M, L)] if tag == "coarse" else 2 * coarse_nodes[(M, L)] - 1
            r = table.get((M, L, n))
            if r is not None:
                row[tag] = grid_entry(n, r["status"], r.get("newton_iterations") or 0,
                                      r.get("wall_time_s"), r, r["message"], g["p_h"])
        rows.append(finish_case(row, h_moes))
        print(_row_text(row), flush=True)
    core = [r for r in rows if r["alpha_ph"] <= 40.0]
    summary = {
        "cases": len(core),
        "converged": sum(1 for r in core if "grid_change" in r),
        "worst_grid_change": max((r.get("grid_change", math.inf) for r in core), default=None),
        "worst_moes_deviation": max(core, key=lambda r: abs(r.get("moes_deviation", math.inf)),
                                    default=None),
        "extra_cases": [(r["M"], r["L"], r["coarse"]["status"]) for r in rows
                        if r["alpha_ph"] > 40.0],
    }
    if summary["worst_moes_deviation"] is not None:
        w = summary["worst_moes_deviation"]
        summary["worst_moes_deviation"] = {"M": w["M"], "L": w["L"],
                                           "deviation": w.get("moes_deviation")}
    summary["complete"] = True
    _write(outdir, rows, summary)
    return {"rows": rows, "summary": summary}


def _write(outdir: Path, rows: list[dict], summary: dict) -> None:
    (outdir / "line_ehl_map.json").write_text(json.dumps({"rows": rows, "summary": summary},
                                                         indent=1, default=str))
    lines = ["| M | L | alpha p_h | status | Newton its (coarse/fine) | s (fine) | "
             "H_c grid change % | H_c vs Moes % | h_min/h_c |", "|" + "---|" * 9]
    lines += [_row_md(r) for r in rows]
    (outdir / "line_ehl_map.md").write_text("\n".join(lines) + "\n")


def _row_text(r: dict) -> str:
    c, f = r["coarse"], r.get("fine", {})
    return (f"M={r['M']:5} L={r['L']:3} aph={r['alpha_ph']:6.1f} {c['status']:>12}/"
            f"{f.get('status', '-'):>12} its {c['iterations']}/{f.get('iterations', '-')} "
            f"grid {100 * r.get('grid_change', float('nan')):.3f}% "
            f"moes {100 * r.get('moes_deviation', float('nan')):+.2f}%")


def _row_md(r: dict) -> str:
    c, f = r["coarse"], r.get("fine", {})
    hmin = (f.get("h_min") or 0.0) / (f.get("h_central") or 1.0) if f else float("nan")
    return (f"| {r['M']} | {r['L']} | {r['alpha_ph']:.1f} | {f.get('status', c['status'])} | "
            f"{c['iterations']}/{f.get('iterations', '-')} | {f.get('seconds', float('nan')):.1f} | "
            f"{100 * r.get('grid_change', float('nan')):.3f} | "
            f"{100 * r.get('moes_deviation', float('nan')):+.2f} | {hmin:.3f} |")


if __name__ == "__main__":
    # python studies/line_ehl_map.py [outdir] [nodes | default] [L values] [M values]
    #     [--workers=N] [--scheduler=ADDRESS]        (value lists comma-separated)
    opts = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--") and "=" in a)
    argv = [a for a in sys.argv if not a.startswith("--")]
    main(argv[1] if len(argv) > 1 else "out/line_ehl_map",
         nodes=int(argv[2]) if len(argv) > 2 and argv[2] != "default" else None,
         l_values=tuple(float(v) for v in argv[3].split(",")) if len(argv) > 3
         else L_VALUES,
         m_values=tuple(float(v) for v in argv[4].split(",")) if len(argv) > 4
         else M_VALUES,
         workers=int(opts["workers"]) if "workers" in opts else None,
         scheduler=opts.get("scheduler"))

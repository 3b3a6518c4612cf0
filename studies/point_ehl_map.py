"""Elastic circular point contacts over the Moes (M, L) map: convergence and central film.

Question
--------
Does the elastic point-contact solver (:func:`bearing_fem.point.solve_point`: Newton on
(p, h0), Fischer-Burmeister cavitation, FFT half-space, GMRES) converge without tuning
for M in {20, 50, 100, 200, 500} and L in {5, 10, 20} with alpha p_h <= 40, and how
close is its central film to the Nijenbanning-Venner-Moes (1994) formula?

Scene
-----
Circular contact rx = ry = 10 mm, E' = 2.2e11 Pa, alpha = 2e-8 1/Pa, eta0 = 0.01 Pa s,
pure rolling; (M, L) realised by :func:`bearing_fem.units.point_scene_parameters_from_moes`
(sum-speed Moes groups). Default grid and domain of the solver (x in [-4.5, 1.5] a or
longer at low M, y symmetric), ``nodes`` per direction.

Expected outcome
----------------
All cases converge; h_central within 10% of NVM on 129^2 (the wedge term is upwinded
to first order where the Poiseuille flow is negligible, so coarse grids overestimate
the film at high M).
"""
from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

from bearing_fem.formulas import point_central_film_nvm
from bearing_fem.point import solve_point
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec,
                               Scene, SolverSpec)
from bearing_fem.units import moes_point, point_scene_parameters_from_moes

M_VALUES = (20, 50, 100, 200, 500)
L_VALUES = (5, 10, 20)
MAX_ALPHA_PH = 40.0


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


def run_case(M: float, L: float, nodes: int) -> dict:
    scene = moes_scene(M, L, nodes)
    c, lub = scene.contact, scene.lubricant
    g = moes_point(scene.load.force, c.rx, c.ry, scene.e_prime, lub.viscosity,
                   scene.kinematics.mean_speed, lub.piezo)
    t0 = time.perf_counter()
    res = solve_point(scene)
    wall = time.perf_counter() - t0
    hc_nvm = point_central_film_nvm(scene.load.force, c.rx, c.ry, scene.e_prime,
                                    lub.viscosity, scene.kinematics.mean_speed, lub.piezo)
    q = res.quantities
    return {"M": M, "L": L, "alpha_ph": g["alpha_ph"], "nodes": nodes, "status": res.status,
            "newton_iterations": res.newton_iterations, "wall_time_s": wall,
            "h_central_m": q.get("h_central"), "h_central_nvm_m": hc_nvm,
            "h_central_ratio": q.get("h_central", math.nan) / hc_nvm,
            "h_min_m": q.get("h_min"), "p_max_over_ph": q.get("p_max", math.nan) / g["p_h"],
            "load_ratio": q.get("load", math.nan) / scene.load.force,
            "message": res.message}, res


def main(outdir, quick: bool = False, *, nodes: int | None = None, plot: bool = True) -> dict:
    """Run the map; write ``point_ehl_map.json``/``.txt`` (and a PNG); return the numbers.

    quick: M in {20, 100}, L = 10 on 65^2.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    nodes = nodes or (65 if quick else 129)
    pairs = [(20, 10), (100, 10)] if quick else [(m, l) for m in M_VALUES for l in L_VALUES]
    rows = []
    for M, L in pairs:
        scene = moes_scene(M, L, 65)
        g = moes_point(scene.load.force, scene.contact.rx, scene.contact.ry, scene.e_prime,
                       scene.lubricant.viscosity, scene.kinematics.mean_speed,
                       scene.lubricant.piezo)
        if g["alpha_ph"] > MAX_ALPHA_PH:
            rows.append({"M": M, "L": L, "alpha_ph": g["alpha_ph"], "status": "skipped",
                         "message": f"alpha p_h = {g['alpha_ph']:.1f} > {MAX_ALPHA_PH}"})
            continue
        row, res = run_case(M, L, nodes)
        rows.append(row)
        if plot and (M, L) == pairs[-1]:
            from bearing_fem.plot import plot_result

            plot_result(res, outdir / "point_ehl_map_last.png", kind="map")
    lines = [f"{'M':>5} {'L':>4} {'aph':>6} {'status':>10} {'its':>4} {'time s':>7} "
             f"{'hc/NVM':>7} {'pmax/ph':>8}"]
    for r in rows:
        if r["status"] == "skipped":
            lines.append(f"{r['M']:5g} {r['L']:4g} {r['alpha_ph']:6.1f}    skipped")
            continue
        lines.append(f"{r['M']:5g} {r['L']:4g} {r['alpha_ph']:6.1f} {r['status']:>10} "
                     f"{r['newton_iterations']:4d} {r['wall_time_s']:7.1f} "
                     f"{r['h_central_ratio']:7.3f} {r['p_max_over_ph']:8.3f}")
    solved = [r for r in rows if r["status"] != "skipped"]
    worst = max((abs(r["h_central_ratio"] - 1) for r in solved), default=math.nan)
    lines.append(f"{sum(r['status'] == 'converged' for r in solved)} of {len(solved)} "
                 f"converged on {nodes}^2; max |h_c/NVM - 1| = {worst:.3f}")
    table = "\n".join(lines)
    print(table)
    (outdir / "point_ehl_map.txt").write_text(table + "\n")
    out = {"nodes": nodes, "cases": rows, "max_abs_hc_deviation": worst}
    (outdir / "point_ehl_map.json").write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out_point_ehl_map", quick="--quick" in sys.argv)

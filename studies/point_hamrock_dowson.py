"""Point and elliptical EHL contacts against the Hamrock-Dowson film formulas.

Question
    Are the FE central and minimum films of circular and elliptical contacts
    (Ry/Rx in {1, 2, 4, 8}) within 20 % of Hamrock-Dowson (1977)?

Scene
    :func:`studies.point_ehl_map.moes_scene` at Moes M = 100, L = 10 (rx = 10 mm,
    E' = 2.2e11 Pa, alpha = 2e-8 1/Pa, Barus, Reynolds cavitation, half-space), with
    ry = rx * (Ry/Rx); the solver's default domain for the ellipse; ``nodes`` per direction.

Expected outcome
    Within the 20 % band (Hamrock-Dowson is a fit to a few tens of cases with a stated
    scatter of about 5-10 %, and its minimum-film fit is the weaker one).

Run ``python studies/point_hamrock_dowson.py [outdir] [nodes] [M L] [--density=LAW]
[--ratios=1,2] [--domain-scale=S]``; ``--density=dowson-higginson`` adds the
compressibility of the lubricant (default: incompressible, as the Moes map);
``--domain-scale=1.5`` enlarges the solver's default domain 1.5 times in every direction
(inlet, outlet and sides, in Hertz semi-axes) at the same grid spacing, (nodes - 1) S + 1
nodes per direction: do the films depend on where the domain ends?
"""
from __future__ import annotations

import json
import sys
import time
from dataclasses import replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bearing_fem.formulas import point_films_hamrock_dowson  # noqa: E402
from bearing_fem.contacts.point import point_setup, solve_point  # noqa: E402
from bearing_fem.scene import MeshSpec  # noqa: E402
from point_ehl_map import moes_scene  # noqa: E402

RATIOS = (1.0, 2.0, 4.0, 8.0)


def main(outdir: str | Path = "out/point_hamrock_dowson", nodes: int = 65,
         M: float = 100.0, L: float = 10.0, ratios: tuple[float, ...] = RATIOS,
         density: str | None = None, domain_scale: float = 1.0) -> dict:
    """Solve each ellipse, compare with Hamrock-Dowson, write JSON and a markdown table.

    ``density``: the lubricant's density law (None: the scene default, incompressible).
    ``domain_scale``: the default domain enlarged this many times about the contact
    centre at the same spacing ((nodes - 1) domain_scale + 1 must be an odd integer).
    """
    grid_nodes = (nodes - 1) * domain_scale + 1
    if abs(grid_nodes - round(grid_nodes)) > 1e-9 or round(grid_nodes) % 2 == 0:
        raise ValueError(f"(nodes - 1) * domain_scale + 1 must be an odd integer, got "
                         f"{grid_nodes:g} for nodes = {nodes}, domain_scale = {domain_scale}")
    grid_nodes = int(round(grid_nodes))
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    rows = []
    for ratio in ratios:
        scene = moes_scene(M, L, nodes, ry_over_rx=ratio, max_iterations=60)
        if density is not None:
            scene = replace(scene, lubricant=replace(scene.lubricant, density=density))
        if domain_scale != 1.0:
            setup = point_setup(scene)
            xr = (setup.grid.x[0] / setup.x_unit, setup.grid.x[-1] / setup.x_unit)
            yr = (setup.grid.y[0] / setup.y_unit, setup.grid.y[-1] / setup.y_unit)
            scene = replace(scene, mesh=MeshSpec(
                nodes=(grid_nodes, grid_nodes),
                x_range=tuple(domain_scale * v for v in xr),
                y_range=tuple(domain_scale * v for v in yr)))
        t0 = time.perf_counter()
        r = solve_point(scene)
        row = {"ry_over_rx": ratio, "status": r.status, "iterations": r.newton_iterations,
               "seconds": time.perf_counter() - t0, "nodes": grid_nodes,
               "domain_scale": domain_scale,  # ranges in Hertz semi-axes; None: default
               "x_range": list(scene.mesh.x_range) if scene.mesh.x_range else None,
               "y_range": list(scene.mesh.y_range) if scene.mesh.y_range else None}
        if r.success:
            lub, kin = scene.lubricant, scene.kinematics
            h_min_hd, h_c_hd = point_films_hamrock_dowson(
                scene.load.force, scene.contact.rx, scene.contact.ry, scene.e_prime,
                lub.viscosity, kin.mean_speed, lub.piezo)
            row.update(h_central=r.quantities["h_central"], h_min=r.quantities["h_min"],
                       h_central_vs_hd=r.quantities["h_central"] / h_c_hd - 1.0,
                       h_min_vs_hd=r.quantities["h_min"] / h_min_hd - 1.0,
                       h_min_over_h_c=r.quantities["h_min"] / r.quantities["h_central"])
        rows.append(row)
        print(row, flush=True)
    nan = float("nan")
    domain = "" if domain_scale == 1.0 else (
        f", default domain x {domain_scale:g} ({grid_nodes} x {grid_nodes} nodes, the "
        f"spacing of {nodes} x {nodes})")
    lines = [f"Moes M = {M}, L = {L}, {nodes} x {nodes} nodes, density "
             f"{density or 'incompressible'}{domain}", "",
             "| Ry/Rx | status | Newton its | s | h_c vs HD % | h_min vs HD % | h_min/h_c |",
             "|---|---|---|---|---|---|---|"]
    for row in rows:
        lines.append(f"| {row['ry_over_rx']:g} | {row['status']} | {row['iterations']} | "
                     f"{row['seconds']:.1f} | {100 * row.get('h_central_vs_hd', nan):+.1f} | "
                     f"{100 * row.get('h_min_vs_hd', nan):+.1f} | "
                     f"{row.get('h_min_over_h_c', nan):.3f} |")
    (outdir / "point_hamrock_dowson.md").write_text("\n".join(lines) + "\n")
    (outdir / "point_hamrock_dowson.json").write_text(json.dumps(rows, indent=1))
    return {"rows": rows}


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    opts = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--") and "=" in a)
    main(args[0] if args else "out/point_hamrock_dowson",
         int(args[1]) if len(args) > 1 else 65,
         *(float(v) for v in args[2:4]),
         ratios=tuple(float(v) for v in opts["ratios"].split(",")) if "ratios" in opts
         else RATIOS,
         density=opts.get("density"),
         domain_scale=float(opts.get("domain-scale", 1.0)))

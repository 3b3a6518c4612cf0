"""Graded line grids: does refining at the outlet spike buy film accuracy per node?

Question
    On uniform grids the h_min of an elastic piezo-viscous line contact converges
    erratically (docs/performance.md: 0.27 % on 401 nodes, 1.0 % on 601, 0.70 % on 801
    at Moes M = 100, L = 10), because the outlet spike and constriction are a few
    elements wide. Does a grid refined there (``bearing_fem.mesh.outlet_graded_nodes``,
    given to the solver as ``mesh.file``) give smaller and steadier film errors for the
    same number of nodes, and at what cost?

Scenes
    ``line_ehl_map.scene_for(M, L)`` (R = 10 mm, E' = 2.2e11 Pa, alpha = 2e-8 1/Pa,
    Barus, pure rolling) on its default domain; uniform grids and graded grids of the
    same node counts (density ratio 9 around x = 0.95 b, width 0.1 b).

Reference
    Richardson extrapolation (p = 2) of the two finest graded grids; the study prints the
    order the three finest graded grids show.

Automatic grading (``mesh.grading = "outlet"``)
    The solver's own option: the spike located on a uniform 401-node grid, then the
    default node count refined there. Over Moes points (M 20-1000, L 0-10) it is compared
    with the default uniform grid of the same node count; both against the graded solve
    on 2N - 1 nodes (same refinement, twice finer), whose change from the graded N-node
    solve is reported too, with the graded solve's own error estimate.

Run ``python studies/line_graded_grid.py OUTDIR [--quick]``; writes ``runs.csv``,
``auto.csv``, ``line_graded_grid.md``, ``summary.json`` and ``line_graded_grid.png`` into
OUTDIR.
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from bearing_fem.contacts.line import line_setup  # noqa: E402
from bearing_fem.mesh import outlet_graded_nodes, write_mesh  # noqa: E402
from bearing_fem.scene import MeshSpec  # noqa: E402
from line_ehl_map import scene_for  # noqa: E402

#: Moes (M, L) cases: the issue case, a heavier one where uniform grids are erratic, a
#: light one.
CASES = ((100.0, 10.0), (500.0, 10.0), (20.0, 5.0))
QUICK_CASES = ((100.0, 10.0),)
GRIDS = (401, 801, 1601)
QUICK_GRIDS = (401, 801)
#: The graded grids of the reference (Richardson of the last two).
REFERENCE_GRIDS = (3201, 6401)
QUICK_REFERENCE_GRIDS = (1601, 3201)
QUANTITIES = ("h_central", "h_min", "friction_force")
#: Moes points of the automatic-grading comparison.
AUTO_CASES = tuple((M, L) for M in (20.0, 100.0, 500.0, 1000.0) for L in (0.0, 5.0, 10.0))
QUICK_AUTO_CASES = ((100.0, 10.0),)


def graded_scene(base: bf.Scene, nodes: int, folder: Path) -> bf.Scene:
    """``base`` on a graded grid over its default domain, written to ``folder``."""
    from skfem import MeshLine

    setup = line_setup(base)
    x0, x1 = (float(v) / setup.x_unit for v in setup.disc.x[[0, -1]])
    path = write_mesh(MeshLine(outlet_graded_nodes(nodes, (x0, x1))),
                      folder / f"graded_{nodes}.vtu")
    return replace(base, mesh=MeshSpec(file=str(path)))


def _solve(scene: bf.Scene) -> dict:
    t0 = time.perf_counter()
    r = bf.solve(scene)
    row = {"status": r.status, "newton_iterations": r.newton_iterations,
           "seconds": time.perf_counter() - t0, "nodes": int(r.x.size)}
    for k in QUANTITIES:
        row[k] = r.quantities.get(k) if r.success else None
    row["estimate_h_min"] = (r.error_estimate or {}).get("h_min")
    return row


def run_case(M: float, L: float, grids, ref_grids, folder: Path) -> list[dict]:
    """Every uniform and graded solve of one case, with errors against the reference."""
    base = scene_for(M, L)
    folder.mkdir(parents=True, exist_ok=True)
    rows = []
    for n in grids:
        rows.append({"M": M, "L": L, "grid": "uniform", **_solve(scene_for(M, L, n))})
        rows.append({"M": M, "L": L, "grid": "graded", **_solve(graded_scene(base, n, folder))})
    refs = [{"M": M, "L": L, "grid": "graded (reference)",
             **_solve(graded_scene(base, n, folder))} for n in ref_grids]
    rows += refs
    ok = all(r["status"] == "converged" for r in refs)
    coarse, fine = refs
    reference = {k: (fine[k] + (fine[k] - coarse[k]) / 3.0) if ok else None
                 for k in QUANTITIES}
    graded = [r for r in rows if r["grid"].startswith("graded")]
    for r in rows:
        for k in QUANTITIES:
            good = reference[k] is not None and r[k] is not None
            r[f"{k}_error"] = abs(r[k] / reference[k] - 1.0) if good else None
    # observed order of the three finest graded grids
    last = sorted(graded, key=lambda r: r["nodes"])[-3:]
    orders = {}
    for k in QUANTITIES:
        v = [r[k] for r in last]
        if None in v or (v[1] - v[2]) == 0.0 or (v[0] - v[1]) / (v[1] - v[2]) <= 0.0:
            orders[k] = None
        else:
            orders[k] = math.log2((v[0] - v[1]) / (v[1] - v[2]))
    for r in rows:
        r["reference"] = json.dumps(reference)
        r["graded_orders"] = json.dumps(orders)
    return rows


def auto_case(M: float, L: float) -> dict:
    """Default uniform grid and ``mesh.grading = "outlet"`` on the same node count, both
    against the graded solve on 2N - 1 nodes."""
    base = scene_for(M, L)

    def graded(nodes=None):
        return replace(base, mesh=MeshSpec(grading="outlet", nodes=nodes))

    uni = _solve(base)
    t0 = time.perf_counter()
    gra = bf.solve(graded())
    graded_seconds = time.perf_counter() - t0
    # the default node count (that of the graded grid too; a failed solve's result may
    # be on a coarser level or the locator's grid, which is not the row's grid)
    n = int(line_setup(base).disc.x.size)
    ref = _solve(graded(2 * n - 1))
    row = {"M": M, "L": L, "nodes": n, "uniform_status": uni["status"],
           "graded_status": gra.status, "reference_status": ref["status"],
           "uniform_seconds": uni["seconds"], "graded_seconds": graded_seconds,
           "uniform_newton": uni["newton_iterations"], "graded_newton": gra.newton_iterations}
    est = gra.error_estimate or {}
    for k in QUANTITIES:
        r, g, u = ref[k], gra.quantities.get(k) if gra.success else None, uni[k]
        row[f"{k}_uniform_error"] = abs(u / r - 1.0) if None not in (u, r) else None
        row[f"{k}_graded_change"] = abs(g / r - 1.0) if None not in (g, r) else None
        row[f"{k}_graded_estimate"] = est.get(k)
    return row


def auto_markdown(rows: list[dict]) -> str:
    out = ["| M | L | nodes | time s uniform / outlet | h_central err uniform / outlet | "
           "h_min err uniform / outlet | friction err uniform / outlet | "
           "outlet estimate h_min / friction |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(
            f"| {r['M']:g} | {r['L']:g} | {r['nodes']} | {r['uniform_seconds']:.3f} / "
            f"{r['graded_seconds']:.3f} | "
            + " | ".join(f"{_fmt(r[f'{k}_uniform_error'])} / {_fmt(r[f'{k}_graded_change'])}"
                         for k in QUANTITIES)
            + f" | {_fmt(r['h_min_graded_estimate'])} / "
              f"{_fmt(r['friction_force_graded_estimate'])} |")
    failed = [r for r in rows if {r["uniform_status"], r["graded_status"],
                                  r["reference_status"]} != {"converged"}]
    if failed:
        out.append("")
        out += [f"M = {r['M']:g}, L = {r['L']:g}: uniform {r['uniform_status']}, outlet "
                f"{r['graded_status']}, reference {r['reference_status']}" for r in failed]
    return "\n".join(out) + "\n"


def _fmt(v, spec=".2e") -> str:
    return "-" if v is None else format(v, spec)


def markdown(rows: list[dict]) -> str:
    out = ["| M | L | grid | nodes | status | Newton its | time s | h_central err | "
           "h_min err | friction err | h_min estimate |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['M']:g} | {r['L']:g} | {r['grid']} | {r['nodes']} | {r['status']} | "
                   f"{r['newton_iterations']} | {r['seconds']:.3f} | "
                   f"{_fmt(r['h_central_error'])} | {_fmt(r['h_min_error'])} | "
                   f"{_fmt(r['friction_force_error'])} | {_fmt(r['estimate_h_min'])} |")
    cases = sorted({(r["M"], r["L"]) for r in rows})
    for M, L in cases:
        r = next(r for r in rows if (r["M"], r["L"]) == (M, L))
        orders = json.loads(r["graded_orders"])
        out.append("")
        out.append(f"M = {M:g}, L = {L:g}: order of the three finest graded grids: "
                   + ", ".join(f"{k} {_fmt(v, '.2f')}" for k, v in orders.items()))
    return "\n".join(out) + "\n"


def figure(path: Path, rows: list[dict]) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cases = sorted({(r["M"], r["L"]) for r in rows})
    fig, axes = plt.subplots(1, len(cases), figsize=(4.5 * len(cases), 3.6), squeeze=False)
    for ax, (M, L) in zip(axes[0], cases):
        for grid, style in (("uniform", "o--"), ("graded", "s-")):
            sel = sorted((r for r in rows if (r["M"], r["L"]) == (M, L) and r["grid"] == grid
                          and r["h_min_error"]), key=lambda r: r["nodes"])
            for k, colour in (("h_min", "C0"), ("h_central", "C1")):
                pts = [(r["nodes"], r[f"{k}_error"]) for r in sel if r[f"{k}_error"]]
                if pts:
                    ax.loglog(*zip(*pts), style, color=colour, label=f"{k}, {grid}")
        ax.set_title(f"M = {M:g}, L = {L:g}")
        ax.set_xlabel("nodes")
        ax.set_ylabel("relative error")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(outdir: str | Path = "out/line_graded_grid", quick: bool = False) -> dict:
    """Solve every case on uniform and graded grids; write the tables and the figure."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    rows: list[dict] = []
    for M, L in (QUICK_CASES if quick else CASES):
        rows += run_case(M, L, QUICK_GRIDS if quick else GRIDS,
                         QUICK_REFERENCE_GRIDS if quick else REFERENCE_GRIDS,
                         outdir / "meshes" / f"M{M:g}_L{L:g}")
    cols = ["M", "L", "grid", "nodes", "status", "newton_iterations", "seconds",
            *QUANTITIES, *(f"{k}_error" for k in QUANTITIES), "estimate_h_min", "reference",
            "graded_orders"]
    with open(outdir / "runs.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=cols)
        w.writeheader()
        for r in rows:
            w.writerow({c: r.get(c) for c in cols})
    auto = [auto_case(M, L) for M, L in (QUICK_AUTO_CASES if quick else AUTO_CASES)]
    with open(outdir / "auto.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=list(auto[0]))
        w.writeheader()
        w.writerows(auto)
    text = (markdown(rows) + "\n## Automatic grading (mesh.grading = 'outlet')\n\n"
            "Errors against the graded solve on 2N - 1 nodes (for 'outlet': its change to "
            "that solve).\n\n" + auto_markdown(auto))
    (outdir / "line_graded_grid.md").write_text(text, encoding="utf-8")
    figure(outdir / "line_graded_grid.png", rows)
    summary = {"quick": quick, "seconds": time.perf_counter() - t0, "rows": rows,
               "auto": auto}
    (outdir / "summary.json").write_text(json.dumps(summary, indent=1), encoding="utf-8")
    return summary


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", nargs="?", default="out/line_graded_grid")
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    res = main(args.outdir, args.quick)
    print(markdown(res["rows"]))
    print(auto_markdown(res["auto"]))
    print(f"{res['seconds']:.1f} s")

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
    mesh (300 nodes per Hertz half-width, times sqrt(M/250) above M = 250, at most 4001
    nodes; or ``nodes``) and one
    with half its spacing (``2 nodes - 1``) for the grid-convergence check.

Expected outcome
    Every case converges; h_central changes < 0.5 % between the two grids and lies within
    12 % of Moes (the formula is a fit with a stated accuracy of a few per cent).

Run ``python studies/line_ehl_map.py [outdir]``; ``main(outdir, quick=True)`` runs a
subset for the tests.
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
        out[tag] = {"nodes": n, "status": r.status, "iterations": r.newton_iterations,
                    "seconds": time.perf_counter() - t0,
                    "h_central": r.quantities.get("h_central"),
                    "h_min": r.quantities.get("h_min"), "p_max_over_ph":
                    r.quantities.get("p_max", 0.0) / g["p_h"], "message": r.message}
        if not r.success:
            break
    out["h_moes"] = h_moes
    c, f = out["coarse"], out.get("fine")
    if f and c["status"] == f["status"] == "converged":
        out["grid_change"] = abs(c["h_central"] / f["h_central"] - 1.0)
        out["moes_deviation"] = f["h_central"] / h_moes - 1.0
    return out


def main(outdir: str | Path = "out/line_ehl_map", quick: bool = False, nodes: int | None = None,
         max_alpha_ph: float = 100.0, l_values: tuple[float, ...] = L_VALUES,
         m_values: tuple[float, ...] = M_VALUES) -> dict:
    """Run the map; write ``line_ehl_map.json`` and ``line_ehl_map.md``; return the rows.

    ``nodes`` None: each case on the solver's default mesh and on one twice as fine."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    cases = [(M, L) for L in l_values for M in m_values]
    if quick:
        cases = [(20, 5), (100, 10)]
    rows = []
    for M, L in cases:
        a_ph = L * math.sqrt(M / (2 * math.pi))
        if a_ph > max_alpha_ph:
            continue
        row = run_case(M, L, nodes)
        rows.append(row)
        print(_row_text(row), flush=True)
        _write(outdir, rows, {"complete": False})  # keep what is done if interrupted
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
    # (value lists comma-separated)
    main(sys.argv[1] if len(sys.argv) > 1 else "out/line_ehl_map",
         nodes=int(sys.argv[2]) if len(sys.argv) > 2 and sys.argv[2] != "default" else None,
         l_values=tuple(float(v) for v in sys.argv[3].split(",")) if len(sys.argv) > 3
         else L_VALUES,
         m_values=tuple(float(v) for v in sys.argv[4].split(",")) if len(sys.argv) > 4
         else M_VALUES)

"""Yachikov & Vostrikov's (2015) friction and heat formulas against the general solver and post-processor.

Question
    Do Yachikov & Vostrikov's (2015) formulas (7)-(9) evaluated on a :func:`bearing_fem.contacts.kodnir.solve`
    result (rolling friction w_k = (B h*/2) I, heat Q = U_sum (w_k + (U_s/U_sum)^2
    (B h*/6) J)) equal the general post-processor (docs/theory.md section 8.2) applied to the
    equivalent dimensional problem solved independently by the general line solver?

Scene
    For each (C, B alpha): R = 10 mm, E = 210 GPa, eta0 = 0.1 Pa s, U_sum = 2 m/s,
    U_s = 0.2 m/s, h* = 1 um; then B1 = sqrt(2 h* R), B = 6 eta0 U_sum B1/h*^2,
    alpha = (B alpha)/B, Kodnir's local compliance c = C h*/B [m/Pa], and the rigid offset
    h0 = h* (1 - z_a^2) from the Kodnir solution. The dimensional problem (x along the
    motion, Reynolds cavitation by Fischer-Burmeister, SUPG, local compliance, prescribed
    gap h0) is solved by :class:`bearing_fem.contacts.line.LineProblem` with damped Newton,
    started from the Kodnir pressure interpolated to its own grid; friction and heat come
    from :func:`bearing_fem.post.friction_and_heat`.

Expected outcome
    Rolling friction, heat power and friction coefficient agree within 0.5 % where both
    discretisations are grid-converged (the Couette integral J of B alpha = 12 is not:
    it varies by ~10-15 % between grids, see studies/kodnir_table.py).

Run ``python studies/kodnir_crosscheck.py [outdir] [nodes]``.
"""
from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

from bearing_fem.contacts import kodnir

from bearing_fem import post
from bearing_fem.physics.elasticity import LocalCompliance
from bearing_fem.contacts.line import LineDiscretisation, LineProblem
from bearing_fem.numerics.newton import damped_newton
from bearing_fem.physics.rheology import barus
from bearing_fem.physics.reynolds import FluxModel
from bearing_fem.scene import Traction

C_VALUES = (0.6, 1.0, 5.0, 10.0, 40.0)
B_ALPHA_VALUES = (0.0, 4.5, 7.0, 12.0)
R, E, ETA0, U_SUM, U_S, H_STAR = 0.01, 2.1e11, 0.1, 2.0, 0.2, 1e-6


def crosscheck(C: float, b_alpha: float, nodes: int = 2001, z_b: float = 20.0) -> dict:
    """Compare Yachikov & Vostrikov's (2015) friction/heat with the general solver for one case."""
    k_res = kodnir.solve(C, b_alpha, z_b=z_b, nodes=nodes)
    out = {"C": C, "b_alpha": b_alpha, "kodnir_status": k_res.status}
    if not k_res.success:
        return out
    B1 = math.sqrt(2 * H_STAR * R)
    B = 6 * ETA0 * U_SUM * B1 / H_STAR**2
    alpha = b_alpha / B
    c = C * H_STAR / B
    h0 = H_STAR * k_res.h_offset
    # the same physical interval: inlet z_b, outlet side to the Kodnir grid's end
    x_min, x_max = -B1 * float(k_res.z.max()), -B1 * float(k_res.z.min())
    disc = LineDiscretisation.uniform(x_min, x_max, nodes)
    flux = FluxModel(viscosity=lambda p: barus(p, ETA0, alpha),
                     density=lambda p: np.ones_like(p), mean_speed=U_SUM / 2,
                     compliance=c, log_viscosity_slope=alpha)
    p_ref = B * max(k_res.k_max, 1e-3)
    prob = LineProblem(disc, flux, R, LocalCompliance(c), "reynolds", None, h0, p_ref,
                       H_STAR, ETA0)
    dim = kodnir.to_dimensional(k_res, kodnir.KodnirScales(**_scales(B1, B, c, alpha)))
    p0 = np.interp(disc.x, dim["x"], dim["pressure"])
    newton = damped_newton(prob, prob.pack(p0, h0), tol=1e-9, max_iterations=60)
    out["newton_status"], out["newton_iterations"] = newton.status, newton.iterations
    p, _ = prob.unpack(newton.z)
    p = np.maximum(p, 0.0)
    ops = disc.ops
    pq, h, px, _ = prob.fields_q(p, h0)
    outlet = post.outlet_position_line(disc.x, p, "reynolds")
    ind = post.full_film_indicator_line(ops.points[0], outlet)
    load = float(ops.mass @ p)
    # the paper's formulas are Newtonian: the same traction here
    gen, _, _ = post.friction_and_heat(ops, h, (px,), flux.viscosity(pq), pq,
                                       mean_speed=U_SUM / 2, sliding_speed=U_S,
                                       indicator_q=ind, load=load, gross_load=load,
                                       traction=Traction(model="newtonian"))
    k_load = B * B1 * float(np.trapezoid(k_res.k, k_res.z))
    kod = kodnir.kodnir_friction_heat(k_res, H_STAR, B, k_load, U_SUM, U_S)
    out.update({
        "rolling_friction_kodnir": kod.rolling_force,
        "rolling_friction_general": gen["rolling_resistance"],
        "heat_kodnir": kod.heat_power, "heat_general": gen["heat_power"],
        "f_kodnir": kod.friction_coefficient, "f_general": 2 * gen["rolling_resistance"] / load,
        "load_kodnir": k_load, "load_general": load,
    })
    for key in ("rolling_friction", "heat", "f"):
        out[f"{key}_deviation"] = out[f"{key}_general"] / out[f"{key}_kodnir"] - 1.0
    return out


def _scales(B1: float, B: float, c: float, alpha: float) -> dict:
    import dataclasses

    names = [f.name for f in dataclasses.fields(kodnir.KodnirScales)]
    values = {"B1": B1, "B": B, "h_star": H_STAR, "b_alpha": alpha * B,
              "C": c * B / H_STAR, "compliance": c}
    return {n: values.get(n, 0.0) for n in names}


def main(outdir: str | Path = "out/kodnir_crosscheck", nodes: int = 2001,
         quick: bool = False) -> dict:
    """Run the 20 cases (3 if quick); write JSON and a markdown table; return rows."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    cases = [(1.0, 0.0), (5.0, 4.5), (10.0, 7.0)] if quick else \
        [(c, ba) for c in C_VALUES for ba in B_ALPHA_VALUES]
    rows = [crosscheck(c, ba, nodes) for c, ba in cases]
    lines = ["| C | B alpha | Newton | rolling friction dev % | heat dev % | f dev % |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['C']} | {r['b_alpha']} | {r.get('newton_status', r['kodnir_status'])} | "
                     f"{100 * r.get('rolling_friction_deviation', float('nan')):+.3f} | "
                     f"{100 * r.get('heat_deviation', float('nan')):+.3f} | "
                     f"{100 * r.get('f_deviation', float('nan')):+.3f} |")
    table = "\n".join(lines)
    print(table)
    (outdir / "kodnir_crosscheck.md").write_text(f"nodes = {nodes}\n\n" + table + "\n")
    (outdir / "kodnir_crosscheck.json").write_text(json.dumps(rows, indent=1))
    return {"rows": rows, "table": table}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/kodnir_crosscheck",
         int(sys.argv[2]) if len(sys.argv) > 2 else 2001)

"""Line-contact solver against its closed-form oracles: the numbers behind the tests.

Question
    How close are the rigid line-contact solutions to Martin's and Kapitsa's closed forms
    (docs/theory.md sections 14.1-14.2), what L2 order does P1 reach, and what does each solve cost?

Scene
    Rigid cylinder R = 10 mm, eta0 = 0.05 Pa s, u1 = u2 = 1 m/s, gap h0 = 1 um; default
    meshes ([-100, 5] or [-100, 100] sqrt(2 R h0), 40 nodes per unit); Barus cases at
    0.5 and 0.9 of the existence limit; the L2 order on [-5, 2] sqrt(2 R h0) with exact
    Dirichlet data, 101..1601 nodes.

Expected outcome
    Load, p_max within 0.5 %, outlet and h*/h0 within 0.2 %, order >= 1.8; beyond the
    existence limit the status is ``no_solution``.

Run ``python studies/line_oracles.py [outdir]``.
"""
from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

import bearing_fem as bf
from bearing_fem import analytic as an
from bearing_fem.scene import Scene

R, ETA, U, H0 = 0.01, 0.05, 1.0, 1e-6


def rigid_scene(cavitation: str, piezo: float = 0.0, law: str = "barus", nodes=None,
                x_range=None) -> Scene:
    """Rigid cylinder with the prescribed gap H0 (the oracle scenes of this study)."""
    mesh = {}
    if nodes:
        mesh["nodes"] = nodes
    if x_range:
        mesh["x_range"] = list(x_range)
    return Scene.from_dict({
        "contact": {"kind": "line", "rx": R},
        "lubricant": {"viscosity": ETA, "piezo": piezo, "viscosity_law": law},
        "kinematics": {"u1": U, "u2": U}, "load": {"gap": H0},
        "model": {"elasticity": "rigid", "cavitation": cavitation}, "mesh": mesh})


def main(outdir: str | Path = "out/line_oracles") -> dict:
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    res: dict = {}
    r = bf.solve(rigid_scene("reynolds", law="constant"))
    q = r.quantities
    res["martin"] = {
        "nodes": r.dofs, "linear_solves": r.linear_solves, "seconds": r.wall_time_s,
        "load_error": q["load"] / float(an.martin_load(H0, R, ETA, U)) - 1,
        "outlet_error": q["outlet_position"] / float(an.martin_outlet_position(H0, R)) - 1,
        "hstar_error": q["h_outlet"] / float(an.martin_hstar(H0)) - 1,
    }
    L = math.sqrt(2 * R * H0)
    hs, errs = [], []
    for n in (101, 201, 401, 801, 1601):
        rr = bf.solve(rigid_scene("reynolds", law="constant", nodes=n, x_range=(-5, 2)),
                      boundary_pressure=(float(an.martin_pressure(np.array([-5 * L]), H0, R,
                                                                   ETA, U)[0]), 0.0))
        pex = an.martin_pressure(rr.x, H0, R, ETA, U)
        hs.append(rr.x[1] - rr.x[0])
        errs.append(math.sqrt(np.trapezoid((rr.pressure - pex) ** 2, rr.x)
                              / np.trapezoid(pex**2, rr.x)))
    res["martin_l2"] = {"errors": errs, "order": float(np.polyfit(np.log(hs), np.log(errs), 1)[0])}
    res["kapitsa"] = []
    for cav, qmax_fn, exact in (
            ("none", an.kapitsa_line_max_reduced,
             lambda x, a: an.kapitsa_line_pressure(x, H0, R, ETA, U, piezo=a)),
            ("reynolds", an.martin_max_reduced,
             lambda x, a: an.martin_pressure(x, H0, R, ETA, U, piezo=a))):
        qmax = float(qmax_fn(H0, R, ETA, U))
        for ratio in (0.0, 0.5, 0.9, 1.1):
            rr = bf.solve(rigid_scene(cav, piezo=ratio / qmax))
            row = {"cavitation": cav, "alpha_qmax": ratio, "status": rr.status}
            if rr.success:
                pex = exact(rr.x, ratio / qmax)
                row["p_max_error"] = rr.quantities["p_max"] / pex.max() - 1
                row["load_error_rel_int_abs_p"] = ((rr.quantities["load"]
                                                    - np.trapezoid(pex, rr.x))
                                                   / np.trapezoid(np.abs(pex), rr.x))
            res["kapitsa"].append(row)
    (outdir / "line_oracles.json").write_text(json.dumps(res, indent=1))
    print(json.dumps(res, indent=1))
    return res


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/line_oracles")

"""Seed 001 (Kadochnikova 2018): maximum pressure of a vibrating rigid ball, bearing 209.

Question
--------
For the ball of bearing 209 rolling on a lubricated raceway whose gap vibrates as
h0(t) = h0 (1 + eps cos(omega t)), what is the maximum film pressure (wedge + squeeze,
at the worst phase), for the oils I-5A, I-12A, I-40A, eps in {0.1, 0.3, 0.6}, speeds
0.5..7.5 m/s and h0 in {0.2, 0.1, 0.05} um, and where does the piezo-viscous (Barus)
rigid solution cease to exist (alpha q_max >= 1, PHYSICS.md 5.1)?

Scene and assumptions (stated, since the thesis leaves them implicit)
--------------------------------------------------------------------
* Geometry: Kapitsa's rigid ball on a plane, h = h0 + a x^2 + b y^2 with
  a = b = 1/(2 R_w), R_w = D_w/2 = 6.35 mm (ball D_w = 12.7 mm; the raceway curvature
  is ignored, as in the thesis' "a = b = 1/(2 R_w)").
* Oils: dynamic viscosity eta0 = nu rho: I-5A 7 mm^2/s, 870 kg/m^3; I-12A 12, 880;
  I-40A 68, 900 (mid-range of the seed's viscosity bands; the thesis misprints
  10560 Pa s for 12e-6 * 880 = 0.01056 Pa s). Barus alpha = 2.2e-8 1/Pa for all three
  (the thesis' gamma is not in the seed summary; a typical mineral-oil value).
* Speed: the seed's speed v is the SUM (rolling) speed of the Russian texts,
  u_m = v/2 (PHYSICS.md 1); pass ``speed_is_sum=False`` to use u_m = v.
* Vibration frequency: shaft rotation, omega = 2 v / d_i with the inner-raceway
  diameter d_i = d_m - D_w = 65 - 12.7 = 52.3 mm (assumed; the squeeze term is then
  small beside the wedge: |dh0/dt| = eps h0 omega). ``omega`` may be given instead.
* Full-Sommerfeld (Kapitsa), isothermal, rigid: the problem is LINEAR in the reduced
  pressure, q = eta0 [u_m q_w(h0(t)) + dh0/dt q_s(h0(t))], where q_w, q_s are the FE
  solutions for unit speed/viscosity and unit approach rate on the mesh of the gap
  h0(t). The FE solver (:func:`bearing_fem.contacts.point.reduced_pressure_solve`) is run for
  q_w, q_s at each phase; every oil and speed is then a linear combination (exact).
  p_max = -ln(1 - alpha q_max)/alpha, or "no solution" when alpha q_max >= 1.

Expected outcome
----------------
Isoviscous maxima agree with Kapitsa's closed form (checked per case, < 0.5%); the
piezo-viscous solution ceases to exist at high speed, thick oil and thin films.
"""
from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

from bearing_fem.analytic import barus_from_reduced, kapitsa_point_max_reduced
from bearing_fem.contacts.point import point_setup, reduced_pressure_solve
from bearing_fem.scene import Contact, Kinematics, Load, Lubricant, MeshSpec, Model, Scene

BALL_DIAMETER = 12.7e-3          # m, D_w of bearing 209
PITCH_DIAMETER = 65e-3           # m, d_m = (d + D)/2 = (45 + 85)/2 mm
OILS = {  # name: (kinematic viscosity m^2/s, density kg/m^3)
    "I-5A": (7e-6, 870.0),
    "I-12A": (12e-6, 880.0),
    "I-40A": (68e-6, 900.0),
}
PIEZO = 2.2e-8                   # 1/Pa (assumed, see module docstring)
EPSILONS = (0.1, 0.3, 0.6)
GAPS = (0.2e-6, 0.1e-6, 0.05e-6)  # m
SPEEDS = tuple(np.round(np.arange(0.5, 7.51, 0.5), 2))  # m/s


def _unit_solutions(h0_mean: float, eps: float, phases: np.ndarray, nodes: int):
    """q_w, q_s fields (unit eta0, u_m, dh0/dt) at each phase, on the mean-gap grid."""
    rw = BALL_DIAMETER / 2.0
    scene = Scene(contact=Contact(kind="point", rx=rw, ry=rw),
                  lubricant=Lubricant(viscosity=1.0, viscosity_law="constant"),
                  kinematics=Kinematics(u1=1.0, u2=1.0), load=Load(gap=h0_mean),
                  model=Model(elasticity="rigid", cavitation="none"),
                  mesh=MeshSpec(nodes=(nodes, nodes)))
    grid = point_setup(scene).grid
    zero = np.zeros(grid.size)
    out = []
    for ph in phases:
        g = h0_mean * (1.0 + eps * math.cos(ph))
        qw, _, _ = reduced_pressure_solve(grid, g, rw, rw, 1.0, 1.0, zero, "none", 0.0)
        qs, _, _ = reduced_pressure_solve(grid, g, rw, rw, 0.0, 1.0, zero, "none", 1.0)
        out.append((g, qw, qs))
    return out


def main(outdir, quick: bool = False, *, speed_is_sum: bool = True,
         omega: float | None = None, nodes: int | None = None) -> dict:
    """Run the study; write ``seed001_bearing209.json`` and a table; return the numbers.

    Parameters
    ----------
    outdir : path
        Output directory.
    quick : bool
        Coarser mesh, 6 phases and speeds (0.5, 2.5, 7.5) m/s only.
    speed_is_sum : bool
        Seed speed is u1 + u2 (True) or the mean speed (False).
    omega : float, optional
        Vibration angular frequency [rad/s]; default 2 v/d_i (shaft rotation).
    nodes : int, optional
        Mesh nodes per direction (default 121, quick 81).
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    nodes = nodes or (81 if quick else 121)
    n_phase = 6 if quick else 16
    speeds = (0.5, 2.5, 7.5) if quick else SPEEDS
    phases = np.arange(n_phase) * 2 * math.pi / n_phase
    d_inner = PITCH_DIAMETER - BALL_DIAMETER
    rw = BALL_DIAMETER / 2.0
    a = b = 1.0 / (2.0 * rw)
    rows = []
    worst_kapitsa = 0.0
    for h0 in GAPS:
        for eps in EPSILONS:
            units_q = _unit_solutions(h0, eps, phases, nodes)
            for oil, (nu, rho) in OILS.items():
                eta0 = nu * rho
                for v in speeds:
                    u_m = v / 2.0 if speed_is_sum else v
                    om = omega if omega is not None else 2.0 * v / d_inner
                    q_best, at = -np.inf, None
                    for ph, (g, qw, qs) in zip(phases, units_q):
                        rate = -h0 * eps * om * math.sin(ph)
                        qmax = float(np.max(eta0 * (u_m * qw + rate * qs)))
                        exact = float(kapitsa_point_max_reduced(g, a, b, eta0, u_m, rate))
                        worst_kapitsa = max(worst_kapitsa, abs(qmax / exact - 1.0))
                        if qmax > q_best:
                            q_best, at = qmax, (ph, g, rate)
                    ratio = PIEZO * q_best
                    p_max = float(barus_from_reduced(q_best, PIEZO)) if ratio < 1 else None
                    rows.append({"h0_m": h0, "eps": eps, "oil": oil, "eta0_Pa_s": eta0,
                                 "speed_m_s": float(v), "mean_speed_m_s": u_m,
                                 "omega_rad_s": om, "worst_phase_rad": at[0],
                                 "q_max_Pa": q_best, "alpha_q_max": ratio,
                                 "p_max_Pa": p_max, "solution_exists": ratio < 1.0})
    n_none = sum(1 for r in rows if not r["solution_exists"])
    out = {"cases": rows, "n_cases": len(rows), "n_no_solution": n_none,
           "max_rel_diff_isoviscous_vs_kapitsa": worst_kapitsa, "nodes": nodes,
           "phases": n_phase, "piezo_1_Pa": PIEZO, "speed_is_sum": speed_is_sum}
    (outdir / "seed001_bearing209.json").write_text(json.dumps(out, indent=1))
    lines = [f"{'h0 um':>6} {'eps':>4} {'oil':>6} {'v m/s':>6} {'alpha q':>8} {'p_max MPa':>10}"]
    for r in rows:
        pm = f"{r['p_max_Pa'] / 1e6:10.2f}" if r["solution_exists"] else "  no sol."
        lines.append(f"{r['h0_m'] * 1e6:6.2f} {r['eps']:4.1f} {r['oil']:>6} "
                     f"{r['speed_m_s']:6.2f} {r['alpha_q_max']:8.3f} {pm}")
    lines.append(f"{n_none} of {len(rows)} cases without a piezo-viscous solution; "
                 f"FE isoviscous q_max vs Kapitsa: max rel. diff {worst_kapitsa:.2e}")
    table = "\n".join(lines)
    (outdir / "seed001_bearing209.txt").write_text(table + "\n")
    print(table)
    return out


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out_seed001", quick="--quick" in sys.argv)

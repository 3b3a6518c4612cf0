"""The 209 ball bearing (Kadochnikova 2018): a vibrating rigid ball, and the whole bearing.

Questions
---------
1. (Kapitsa's rigid ball, the thesis' model) For the ball of bearing 209 rolling on a
   lubricated raceway whose gap vibrates as h0(t) = h0 (1 + eps cos(omega t)), what is the
   maximum film pressure (wedge + squeeze, at the worst phase), for the oils I-5A, I-12A,
   I-40A, eps in {0.1, 0.3, 0.6}, speeds 0.5..7.5 m/s and h0 in {0.2, 0.1, 0.05} um, and
   where does the piezo-viscous (Barus) rigid solution cease to exist (alpha q_max >= 1;
   docs/analytic.md)?
2. (Whole bearing) What are the load distribution, the EHL films and the pressures of the
   real 209 bearing with the thesis' oils and speeds, and how do they compare with the
   thesis' prescribed gaps h0 = 0.05..0.2 um and its rigid (Kapitsa) pressures?

Scene and assumptions (stated, since the thesis leaves them implicit)
--------------------------------------------------------------------
* Geometry: Kapitsa's rigid ball on a plane, h = h0 + a x^2 + b y^2 with
  a = b = 1/(2 R_w), R_w = D_w/2 = 6.35 mm (ball D_w = 12.7 mm; the raceway curvature
  is ignored, as in the thesis' "a = b = 1/(2 R_w)").
* Oils: dynamic viscosity eta0 = nu rho: I-5A 7 mm^2/s, 870 kg/m^3; I-12A 12, 880;
  I-40A 68, 900 (mid-range of the thesis' viscosity bands; it misprints
  10560 Pa s for 12e-6 * 880 = 0.01056 Pa s). Barus alpha = 2.2e-8 1/Pa for all three
  (the thesis' piezo-viscous coefficient is not used here; a typical mineral-oil value).
* Speed: the thesis' speed v is the SUM (rolling) speed of the Russian texts,
  u_m = v/2 (docs/theory.md); pass ``speed_is_sum=False`` to use u_m = v.
* Vibration frequency: shaft rotation, omega = 2 v / d_i with the inner-raceway
  diameter d_i = d_m - D_w = 65 - 12.7 = 52.3 mm (assumed; the squeeze term is then
  small beside the wedge: |dh0/dt| = eps h0 omega). ``omega`` may be given instead.
* Full-Sommerfeld (Kapitsa), isothermal, rigid: the problem is LINEAR in the reduced
  pressure, q = eta0 [u_m q_w(h0(t)) + dh0/dt q_s(h0(t))], where q_w, q_s are the FE
  solutions for unit speed/viscosity and unit approach rate on the mesh of the gap
  h0(t). The FE solver (:func:`bearing_fem.contacts.point.reduced_pressure_solve`) is run for
  q_w, q_s at each phase; every oil and speed is then a linear combination (exact).
  p_max = -ln(1 - alpha q_max)/alpha, or "no solution" when alpha q_max >= 1.

Whole bearing (``whole_bearing``)
--------------------------------
The 209 with the internal geometry of Harris & Kotzalas' 209 example
(``bearing_fem/bearings/6209.toml``: nine 12.7 mm balls, d_m = 65 mm, f_i = f_o = 0.52,
diametral clearance 15 um), radial load 4 kN (the thesis gives none), the thesis' oils at
their mid-range viscosity, alpha = 2.2e-8 1/Pa, and its speeds v read as the sum speed at
the contact: u_m = v/2 = omega_i d_m (1 - gamma^2)/4 gives the inner-ring speed. Every
loaded ball is solved by elastic, piezo-viscous EHL (bearing_fem.solve_bearing). For each
case the rigid Kapitsa maximum pressure at the EHL central film of the most loaded ball
(the thesis' ball-on-plane geometry a = b = 1/(2 R_w)) is set beside the EHL maximum.

Expected outcome
----------------
Isoviscous maxima agree with Kapitsa's closed form (checked per case, < 0.5%); the
piezo-viscous solution ceases to exist at high speed, thick oil and thin films. In the
whole bearing the balls at 0 and +-40 deg carry the load; the EHL films are of the order of
0.1..1 um and the pressures are Hertzian (GPa), while the rigid model at the same gap gives
MPa or no solution at all.
"""
from __future__ import annotations

import argparse
import json
import math
from dataclasses import replace
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
    """Run the study; write ``bearing209.json``, ``bearing209.txt`` (Kapitsa part) and the
    whole-bearing files (:func:`whole_bearing`); return the numbers (the whole-bearing
    numbers under ``"whole_bearing"``).

    Parameters
    ----------
    outdir : path
        Output directory.
    quick : bool
        Coarser mesh, 6 phases and speeds (0.5, 2.5, 7.5) m/s only.
    speed_is_sum : bool
        The thesis' speed is u1 + u2 (True) or the mean speed (False).
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
    out["whole_bearing"] = whole_bearing(outdir, quick=quick, speed_is_sum=speed_is_sum)
    (outdir / "bearing209.json").write_text(json.dumps(out, indent=1))
    lines = [f"{'h0 um':>6} {'eps':>4} {'oil':>6} {'v m/s':>6} {'alpha q':>8} {'p_max MPa':>10}"]
    for r in rows:
        pm = f"{r['p_max_Pa'] / 1e6:10.2f}" if r["solution_exists"] else "  no sol."
        lines.append(f"{r['h0_m'] * 1e6:6.2f} {r['eps']:4.1f} {r['oil']:>6} "
                     f"{r['speed_m_s']:6.2f} {r['alpha_q_max']:8.3f} {pm}")
    lines.append(f"{n_none} of {len(rows)} cases without a piezo-viscous solution; "
                 f"FE isoviscous q_max vs Kapitsa: max rel. diff {worst_kapitsa:.2e}")
    table = "\n".join(lines)
    (outdir / "bearing209.txt").write_text(table + "\n")
    print(table)
    return out


#: Radial load of the whole-bearing part [N] (the thesis gives none; C0/5 of a 6209).
RADIAL_LOAD = 4000.0
#: GOST 20918 limiting surface speed of the thesis [m/s].
LIMIT_SPEED = 5.45


#: Contact meshes tried in turn until every contact converges (full mode). At the high
#: Moes loads of the thin oils at low speed (M ~ 1e4..1e5, R_y/R_x = 22..32) the point
#: solver stalls on the default 129^2 grid; a grid refined along x on a shorter inlet
#: converges there (measured: M = 33700 stalls on 129^2 and 257x129 over the default
#: domain, converges on 257x129 over x in [-2.5, 1.2] a, y in [-2, 2] b and on 385x193).
#: A rung of :data:`MESH_LADDER` is taken when every contact converged and the bearing's
#: h_min error estimate is at most this (relative); else the next rung is tried (the last
#: successful rung is reported when none reaches it).
FILM_ESTIMATE_LIMIT = 0.05
MESH_LADDER = ({},
               {"point_nodes": (257, 129), "x_range": (-2.5, 1.2), "y_range": (-2.0, 2.0)},
               {"point_nodes": (385, 193), "x_range": (-3.0, 1.5)})


def bearing_for(oil: str, v: float, speed_is_sum: bool = True, nodes: int | None = None,
                mesh: dict | None = None):
    """The 209 (Harris' internal geometry) with the thesis' ``oil`` at speed ``v`` [m/s];
    ``nodes`` (square grid) or ``mesh`` (BearingMesh keys) set the contact mesh."""
    from bearing_fem.bearing import load_example

    b = load_example("6209")
    nu, rho = OILS[oil]
    dm, dw = b.geometry.mean_diameter, b.geometry.element_diameter
    u_m = v / 2.0 if speed_is_sum else v
    omega = 4.0 * u_m / (dm * (1.0 - (dw / dm) ** 2))
    return replace(b, title=f"209, {oil}, v = {v:g} m/s",
                   lubricant=replace(b.lubricant, viscosity=nu * rho, piezo=PIEZO, density=rho),
                   operation=replace(b.operation, inner_rpm=omega * 60.0 / (2 * math.pi),
                                     radial_load=RADIAL_LOAD),
                   mesh=replace(b.mesh, **(mesh or {}),
                                **({} if nodes is None else {"point_nodes": (nodes, nodes)})))


def whole_bearing(outdir, quick: bool = False, speed_is_sum: bool = True) -> dict:
    """Whole-bearing EHL of the 209 for the thesis' oils and speeds.

    Writes ``whole_bearing.json``, ``whole_bearing.md`` and ``whole_bearing.png`` (load
    distribution and films). quick: oil I-40A at 2.5 and 7.5 m/s on 81^2 contact grids;
    full: the three oils at 0.5, 2.5, 5.45 (GOST limit) and 7.5 m/s, each on the first
    mesh of :data:`MESH_LADDER` on which every contact converges with an h_min error
    estimate within :data:`FILM_ESTIMATE_LIMIT` (else the last mesh on which every contact
    converged; the mesh and the estimate are reported).
    """
    from bearing_fem.bearing import solve_bearing

    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    oils = ("I-40A",) if quick else tuple(OILS)
    speeds = (2.5, 7.5) if quick else (0.5, 2.5, LIMIT_SPEED, 7.5)
    ladder = ({"point_nodes": (81, 81)},) if quick else MESH_LADDER
    rows, dist = [], None
    rw = BALL_DIAMETER / 2.0
    for oil in oils:
        for v in speeds:
            chosen = None
            for mesh in ladder:
                b = bearing_for(oil, v, speed_is_sum, mesh=mesh)
                r = solve_bearing(b)
                if r.success:
                    chosen = (b, r, mesh)
                    est = (r.summary().get("error_estimate") or {}).get("h_min")
                    if est is not None and est <= FILM_ESTIMATE_LIMIT:
                        break
            if chosen is not None:
                b, r, mesh = chosen
            s = r.summary()
            if dist is None:
                dist = [(e["azimuth_deg"], e["load"]) for e in s["elements"]]
            j = r.most_loaded_element()
            e = s["elements"][j]
            hc = e["inner"]["h_central"]
            u_m = e["inner"]["entrainment_speed"]
            eta = b.lubricant.viscosity
            kap = None                     # rigid Barus pressure: None = no solution
            if hc is not None:
                q = float(kapitsa_point_max_reduced(hc, 1 / (2 * rw), 1 / (2 * rw), eta, u_m))
                kap = float(barus_from_reduced(q, PIEZO)) if PIEZO * q < 1 else None
            rows.append({"oil": oil, "speed_m_s": v, "inner_rpm": b.operation.inner_rpm,
                         "status": r.status, "mesh": {k: list(val) for k, val in mesh.items()},
                         "max_moes_M": max((res.summary()["dimensionless"].get("M", 0.0)
                                            for res in r.contacts.values()), default=None),
                         "max_ball_load_N": e["load"],
                         "h_min_m": s["h_min"], "h_central_m": hc, "p_max_Pa": s["p_max"],
                         "film_parameter": s["film_parameter_min"],
                         "friction_torque_N_m": s["friction_torque"],
                         "heat_power_W": s["heat_power"],
                         "h_min_estimate": (s.get("error_estimate") or {}).get("h_min"),
                         "kapitsa_rigid_p_max_Pa_at_h_central": kap,
                         "h_central_vs_nvm": (hc / e["inner"]["h_central_formula"]
                                              if hc else None),
                         "elements_loaded": s["load_distribution"]["elements_loaded"],
                         "solved_again": s["contact_solves"]["solved_again"],
                         # the smallest first-grid h_min of the contacts solved again on
                         # a finer grid (None if none was)
                         "h_min_first_grid_m": min((v["h_min"] for v in r.refined.values()),
                                                   default=None),
                         "wall_time_s": s["wall_time_s"],
                         "load_zone_half_angle_deg":
                             s["load_distribution"]["load_zone_half_angle_deg"]})
            print(f"209 {oil:6s} v={v:5.2f} m/s {r.status}: h_min={s['h_min']} m "
                  f"p_max={s['p_max']} Pa", flush=True)
    res = {"radial_load_N": RADIAL_LOAD, "piezo_1_Pa": PIEZO, "speed_is_sum": speed_is_sum,
           "load_distribution": [{"azimuth_deg": a, "load_N": q} for a, q in dist],
           "cases": rows, "thesis_gaps_m": list(GAPS)}
    (outdir / "whole_bearing.json").write_text(json.dumps(res, indent=1))
    lines = ["| oil | v m/s | n rpm | max M | status (mesh) | h_min um | h_min estimate % | "
             "h_c um | h_c/NVM | p_max GPa | rigid Kapitsa p_max at h_c MPa | lambda | "
             "torque N m | heat W |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def f(v, fmt, scale=1.0):
        return "-" if v is None else format(v * scale, fmt)

    for c in rows:
        kap = c["kapitsa_rigid_p_max_Pa_at_h_central"]
        rigid = "-" if c["h_central_m"] is None else (
            "no solution" if kap is None else f"{kap / 1e6:.2f}")
        mesh = c["mesh"].get("point_nodes", "129x129 default")
        if c["solved_again"]:
            mesh = f"{mesh}; {c['solved_again']} solved again twice as fine"
            if c["h_min_first_grid_m"] is not None:
                mesh += f", its h_min {c['h_min_first_grid_m'] * 1e6:.3f} um on the first grid"
        lines.append(
            f"| {c['oil']} | {c['speed_m_s']:g} | {c['inner_rpm']:.0f} | "
            f"{f(c['max_moes_M'], '.0f')} | {c['status']} ({mesh}) | "
            f"{f(c['h_min_m'], '.3f', 1e6)} | {f(c['h_min_estimate'], '.2g', 100)} | "
            f"{f(c['h_central_m'], '.3f', 1e6)} | "
            f"{f(c['h_central_vs_nvm'], '.3f')} | {f(c['p_max_Pa'], '.2f', 1e-9)} | "
            f"{rigid} | "
            f"{f(c['film_parameter'], '.2f')} | {f(c['friction_torque_N_m'], '.4f')} | "
            f"{f(c['heat_power_W'], '.2f')} |")
    (outdir / "whole_bearing.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    _whole_bearing_figure(outdir, res)
    return res


def _whole_bearing_figure(outdir: Path, res: dict) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    d = sorted(res["load_distribution"], key=lambda r: r["azimuth_deg"])
    ax1.bar([r["azimuth_deg"] for r in d], [r["load_N"] for r in d], width=20)
    ax1.set_xlabel("azimuth [deg]")
    ax1.set_ylabel("ball load [N]")
    ax1.set_title(f"209, Fr = {res['radial_load_N']:.0f} N", fontsize=10)
    for oil in dict.fromkeys(c["oil"] for c in res["cases"]):
        cs = [c for c in res["cases"] if c["oil"] == oil]
        ax2.plot([c["speed_m_s"] for c in cs],
                 [float("nan") if c["h_min_m"] is None else c["h_min_m"] * 1e6 for c in cs],
                 "o-", label=f"EHL h_min, {oil}")
    for g in res["thesis_gaps_m"]:
        ax2.axhline(g * 1e6, color="0.6", ls=":", lw=1)
    ax2.set_xlabel("speed v (sum speed) [m/s]")
    ax2.set_ylabel("film [um]")
    ax2.set_yscale("log")
    ax2.set_title("EHL minimum film vs the thesis' gaps (dotted)", fontsize=10)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(outdir / "whole_bearing.png", dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/bearing209")
    parser.add_argument("--quick", action="store_true")
    a = parser.parse_args()
    main(a.outdir, quick=a.quick)

"""Seed 000: heat power of an SKF NNCF 5040 CV roller bearing, thermally coupled EHL vs Palmgren.

Question
--------
Does the thermally coupled line-EHL solve (contact temperature <-> Prokofiev viscosity,
bearing_fem.contacts.coupling) converge for the seed's operating point at oil temperatures
20..100 C, and how do its contact temperature rise, heat power and friction coefficient
compare with the seed's empirical Palmgren-form heat power Q = 1.047e-4 M n?

Scene (seed 000 data)
---------------------
SKF NNCF 5040 CV, full-complement double-row cylindrical roller bearing, d = 200 mm,
D = 310 mm, B = 150 mm; inner ring 537 rpm, outer ring fixed; Fr = 500 kN, Fa = 0.
Oil Mobilgear 600 XP 320: eta = 0.281 Pa s at 40 C, Prokofiev eta0(t) = eta_40 (40/t)^2.93
(t in C); alpha = 1.6e-8 1/Pa at 30 C and 0.65e-8 1/Pa at 150 C, interpolated with
ln(alpha) linear in t (alpha(20 C) = 1.72e-8, alpha(100 C) = 0.93e-8 1/Pa).

Assumptions (roller data are not in the paper)
----------------------------------------------
* roller diameter D_w = 28 mm, pitch diameter d_m = (d + D)/2 = 255 mm;
* full complement: z_row = floor(pi d_m / D_w) = 28 rollers per row, 2 rows, z = 56;
* effective roller length l_w = 60 mm per row (2 x 60 mm of the 150 mm width);
* q_H = K Fr/(z l_w), K = 4.6 (seed), the most loaded roller; steel E = 210 GPa, nu = 0.3;
* pure rolling (cylindrical rollers driven by traction: u_s = 0; Blok partition 50/50),
  so the heat is the Poiseuille (rolling) dissipation only; Newtonian, Barus, Reynolds
  cavitation; steel bodies lambda = 46 W/(m K), rho = 7850 kg/m^3, c = 470 J/(kg K);
* bearing total by the seed's rule: every roller at q_H, inner + outer contact,
  Q_bearing = z l_w (Q'_inner + Q'_outer) (an upper bound: rollers outside the load
  zone carry less);
* oil density 870 kg/m^3 for the kinematic viscosity nu of the Palmgren formula
  (d0 = d_m = 255 mm, f0 = 5, f_pr = 0.003 as in the paper).

Run ``python studies/seed000_nncf5040.py [outdir] [--quick]``.
"""
from __future__ import annotations

import json
import math
import sys
import time
from dataclasses import replace
from pathlib import Path

from bearing_fem import bearing
from bearing_fem.contacts.coupling import contact_piezo, solve_thermal
from bearing_fem.physics.rheology import prokofiev
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec, Model,
                               Scene, Thermal, Traction)

BORE, OUTER, WIDTH = 0.200, 0.310, 0.150          # m
ROLLER_D, ROLLER_L, ROWS = 0.028, 0.060, 2        # m, m, -   (assumed)
RPM, FR, K_LOAD = 537.0, 500e3, 4.6               # 1/min, N, -
ETA_40, T_REF, N_PROK = 0.281, 40.0, 2.93         # Pa s, C, -
PIEZO_T, PIEZO_A = (30.0, 150.0), (1.6e-8, 0.65e-8)
OIL_DENSITY = 870.0                               # kg/m^3 (assumed)
F0, F_PR = 5.0, 0.003


def bearing_geometry() -> dict:
    """Pitch diameter, roller count, line load and contact kinematics (SI)."""
    dm = 0.5 * (BORE + OUTER)
    z_row = int(math.floor(math.pi * dm / ROLLER_D))
    z = ROWS * z_row
    kin = bearing.cylindrical_roller_contacts(dm, ROLLER_D, RPM)
    q_h = bearing.max_line_load(FR, z, ROLLER_L, K_LOAD)
    return {"pitch_diameter": dm, "rollers_per_row": z_row, "rollers": z, "line_load": q_h,
            "mean_speed": kin.mean_speed, "rx_inner": kin.rx_inner, "rx_outer": kin.rx_outer}


def contact_scene(t_oil: float, rx: float, geo: dict, elasticity: str, nodes: int) -> Scene:
    """Thermal line scene of one roller/raceway contact at oil temperature t_oil [C]."""
    u = geo["mean_speed"]
    return Scene(title=f"NNCF 5040 CV, {t_oil:g} C", contact=Contact(kind="line", rx=rx,
                                                                    length=ROLLER_L),
                 materials=Materials(e1=2.1e11, nu1=0.3, e2=2.1e11, nu2=0.3),
                 lubricant=Lubricant(viscosity=ETA_40, piezo=PIEZO_A[0]),
                 kinematics=Kinematics(u1=u, u2=u), load=Load(force=geo["line_load"]),
                 model=Model(elasticity=elasticity, thermal="patch"), mesh=MeshSpec(nodes=nodes),
                 thermal=Thermal(oil_temperature=t_oil, exponent=N_PROK, reference_temperature=T_REF,
                                 piezo_temperatures=PIEZO_T, piezo_values=PIEZO_A, tolerance=0.05),
                 traction=Traction(model="newtonian"))


def palmgren(t_oil: float) -> float:
    """Seed 000 empirical bearing heat power [W] at oil temperature t_oil [C]."""
    nu_mm2s = prokofiev(t_oil, ETA_40, T_REF, N_PROK) / OIL_DENSITY * 1e6
    return bearing.palmgren_heat_power(nu_mm2s, RPM, 0.5 * (BORE + OUTER) * 1e3, BORE * 1e3, FR,
                                       f0=F0, f_pr=F_PR)


def main(outdir: str | Path = "out/seed000_nncf5040", quick: bool = False,
         models: tuple[str, ...] = ("local", "half-space"),
         temperatures: tuple[float, ...] | None = None, nodes: int | None = None) -> dict:
    """Run the study; write ``results.json`` and ``table.md`` to outdir; return the results.

    quick: 801 nodes and t_oil = 20, 50, 100 C (else 1201 nodes, 20..100 C in 10 K steps);
    models: elasticity models to run; temperatures: override the oil temperatures [deg C];
    nodes: override the node count.
    """
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    geo = bearing_geometry()
    nodes = nodes or (801 if quick else 1201)
    temps = [20.0, 50.0, 100.0] if quick else [20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 90.0, 100.0]
    if temperatures is not None:
        temps = [float(t) for t in temperatures]
    rows = []
    for model in models:
        for t in temps:
            row = {"elasticity": model, "oil_temperature_C": t, "alpha_1_Pa": contact_piezo(
                contact_scene(t, geo["rx_inner"], geo, model, nodes), t)}
            for side, rx in (("inner", geo["rx_inner"]), ("outer", geo["rx_outer"])):
                t0 = time.perf_counter()
                r = solve_thermal(contact_scene(t, rx, geo, model, nodes))
                q = r.quantities
                row[side] = {
                    "status": r.status, "wall_time_s": round(time.perf_counter() - t0, 1),
                    "thermal_iterations": q.get("thermal_iterations"),
                    "contact_temperature_rise_K": q.get("contact_temperature_rise"),
                    "contact_temperature_rise_max_K": q.get("contact_temperature_rise_max"),
                    "heat_power_W_per_m": q.get("heat_power"),
                    "heat_power_direct_W_per_m": q.get("heat_power_direct"),
                    "heat_power_per_contact_W": (q["heat_power"] * ROLLER_L
                                                 if "heat_power" in q and r.success else None),
                    "friction_coefficient": q.get("friction_coefficient"),
                    "h_central_m": q.get("h_central"), "p_max_Pa": q.get("p_max"),
                    "message": r.message[:300],
                }
                print(f"{model:10s} {t:5.0f} C {side:5s} {r.status:14s} "
                      f"dT={q.get('contact_temperature_rise', float('nan')):.3g} K "
                      f"Q'={q.get('heat_power', float('nan')):.4g} W/m "
                      f"f={q.get('friction_coefficient', float('nan')):.3g} "
                      f"({time.perf_counter() - t0:.0f} s)", flush=True)
            ok = row["inner"]["status"] == "converged" and row["outer"]["status"] == "converged"
            row["bearing_heat_power_W"] = (geo["rollers"] * (row["inner"]["heat_power_per_contact_W"]
                                           + row["outer"]["heat_power_per_contact_W"])
                                           if ok else None)
            row["palmgren_heat_power_W"] = palmgren(t)
            rows.append(row)
    results = {"geometry": geo, "nodes": nodes, "quick": quick, "models": list(models),
               "rows": rows}
    (out / "results.json").write_text(json.dumps(results, indent=2))
    lines = ["| elasticity | t_oil C | status in/out | dT in K | Q' in W/m | Q contact in W | f in "
             "| Q bearing W | Palmgren W |", "|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        i, o = row["inner"], row["outer"]
        fmt = (lambda v, f: "-" if v is None else format(v, f))
        lines.append(f"| {row['elasticity']} | {row['oil_temperature_C']:g} | {i['status']}/"
                     f"{o['status']} | {fmt(i['contact_temperature_rise_K'], '.3g')} | "
                     f"{fmt(i['heat_power_W_per_m'], '.4g')} | "
                     f"{fmt(i['heat_power_per_contact_W'], '.3g')} | "
                     f"{fmt(i['friction_coefficient'], '.3g')} | "
                     f"{fmt(row['bearing_heat_power_W'], '.4g')} | "
                     f"{row['palmgren_heat_power_W']:.4g} |")
    (out / "table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return results


def rise_scan(outdir: str | Path = "out/seed000_rise_scan", side: str = "outer",
              model: str = "half-space", nodes: int = 801,
              temperatures: tuple[float, ...] = tuple(22.0 + 0.25 * k for k in range(17))
              ) -> list[dict]:
    """Computed contact temperature rise as a function of the contact temperature T.

    One thermal iteration with the oil at T (the 20 C scene otherwise) gives
    rise(T) = G(T) - t_oil, the map whose fixed point the coupling seeks; a jump in rise(T) between neighbouring T means the
    fixed-point map is not continuous on this mesh. Writes ``rise_scan.json``/``.md``.
    """
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    geo = bearing_geometry()
    rx = geo["rx_outer"] if side == "outer" else geo["rx_inner"]
    rows = []
    for t in temperatures:
        scene = contact_scene(20.0, rx, geo, model, nodes)
        scene = replace(scene, thermal=replace(scene.thermal, oil_temperature=float(t),
                                               max_iterations=1))
        q = solve_thermal(scene).quantities
        rows.append({"contact_temperature_C": t,
                     "rise_K": q.get("contact_temperature_rise_computed"),
                     "heat_power_W_per_m": q.get("heat_power"), "h_central_m": q.get("h_central")})
        print(rows[-1], flush=True)
    lines = [f"{model}, {side} contact, {nodes} nodes", "",
             "| T C | computed rise K | Q' W/m |", "|---|---|---|"]
    lines += [f"| {r['contact_temperature_C']:.2f} | {r['rise_K']:.3f} | "
              f"{r['heat_power_W_per_m']:.1f} |" for r in rows]
    (out / "rise_scan.md").write_text("\n".join(lines) + "\n")
    (out / "rise_scan.json").write_text(json.dumps(rows, indent=1))
    return rows


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if "--rise-scan" in sys.argv:
        rise_scan(args[0] if args else "out/seed000_rise_scan")
    else:
        main(args[0] if args else "out/seed000_nncf5040", quick="--quick" in sys.argv)

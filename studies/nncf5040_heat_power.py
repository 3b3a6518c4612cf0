"""NNCF 5040 CV heat power over oil temperature: bearing-level EHL vs Palmgren.

Question
--------
Yachikov & Vostrikov (2015) compare the heat power of the SKF NNCF 5040 CV work-roll
bearing of a cold-rolling mill (537 rpm, Fr = 500 kN, Mobilgear 600 XP 320) computed by
Kodnir-school EHL with the Palmgren-form estimate Q = 1.047e-4 M n, and report that they
differ by about 33% at 20 C, by less than 6% at 50 C and by less than 3% at 100 C.
Does a bearing-level EHL solution (load distribution over all rollers, EHL at every loaded
contact, isothermal and thermally coupled) reproduce that agreement?

Scene
-----
Bearing file ``bearing_fem/bearings/nncf5040.toml``. The roller data are not in the paper;
the internal geometry is derived from the catalogue dimensions d = 200, D = 310, B = 150 mm
(``derived_geometry``):

* roller diameter D_w = (D - d)/4 = 27.5 mm: half the radial section height (D - d)/2, the
  usual proportion of cylindrical roller bearings;
* pitch diameter d_m = (d + D)/2 = 255 mm;
* full complement: Z = floor(pi d_m/(1.03 D_w)) = 28 rollers per row (3% circumferential
  play), two rows;
* effective roller length l_we = 0.4 B = 60 mm per row (the width shared by two rows, the
  ribs and the roller end chamfers);
* radial clearance: the paper's load factor K = Z Q_max/Fr = 4.6 (Z all rollers; Stribeck's
  zero-clearance value is 4.08) is met by c_r = 18 um with this geometry (``paper_clearance``);
* oil: Prokofiev eta0(t) = 0.281 (40/t)^2.93 Pa s, alpha from 1.6e-8 (30 C) to
  0.65e-8 1/Pa (150 C), ln(alpha) linear in t; density 878 kg/m^3 = 0.281 Pa s / 320 mm^2/s
  (ISO VG 320 at 40 C), used for the kinematic viscosity of the Palmgren formulas;
* steel rings and rollers, Newtonian, Barus, Reynolds cavitation, pure rolling.

Palmgren: the paper's form M0 = 1e-7 f0 (nu n)^(2/3) d_m^3, M1 = f_pr P d/2 with f0 = 5,
f_pr = 0.003, Q = 1.047e-4 M n; and Harris' form M1 = f1 Fr d_m, f1 = 0.00055 (full complement).

EHL heat power is reported two ways: the sum of the contact solver's heat powers, and the
bearing friction torque from forces and moment arms times omega (equal when the contact
heat satisfies Q = 2 u_m F_P; see docs/bearing.md). The thermal variant solves every contact
with ``model.thermal = "patch"`` (contact temperature <-> Prokofiev viscosity).

Run ``python studies/nncf5040_heat_power.py OUTDIR [--quick]``; ``contact_study`` and
``rise_scan`` keep the contact-level thermal analysis of docs/coupling.md (one roller at
the paper's q_H, earlier assumption D_w = 28 mm).
"""
from __future__ import annotations

import argparse
import json
import math
import time
from dataclasses import replace
from pathlib import Path

from scipy.optimize import brentq

from bearing_fem.bearing import (Bearing, cylindrical_roller_contacts, distribute_loads,
                                 load_example, max_line_load, palmgren_heat_power,
                                 solve_bearing)
from bearing_fem.contacts.coupling import contact_piezo, solve_thermal
from bearing_fem.physics.rheology import prokofiev
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec, Model,
                               Scene, Thermal, Traction)

BORE, OUTER, WIDTH = 0.200, 0.310, 0.150          # m, catalogue
RPM, FR = 537.0, 500e3                            # 1/min, N
K_PAPER = 4.6                                     # -, the paper's load factor
ETA_40, T_REF, N_PROK = 0.281, 40.0, 2.93         # Pa s, C, -
PIEZO_T, PIEZO_A = (30.0, 150.0), (1.6e-8, 0.65e-8)
OIL_DENSITY = 878.0                               # kg/m^3 (VG 320: 0.281 Pa s / 320 mm^2/s)
F0, F_PR = 5.0, 0.003
#: The paper's claimed EHL vs Palmgren differences [%] at 20, 50 and 100 C (upper bounds
#: at 50 and 100 C).
PAPER_CLAIM = {20.0: 33.0, 50.0: 6.0, 100.0: 3.0}

# contact-level study (docs/coupling.md section 6): the earlier roller assumptions
ROLLER_D, ROLLER_L, ROWS = 0.028, 0.060, 2        # m, m, -
K_LOAD = K_PAPER


def derived_geometry() -> dict:
    """Internal geometry from the catalogue dimensions (see the module docstring) [SI]."""
    dw = 0.25 * (OUTER - BORE)
    dm = 0.5 * (BORE + OUTER)
    z = int(math.floor(math.pi * dm / (1.03 * dw)))
    return {"element_diameter": dw, "pitch_diameter": dm, "elements_per_row": z, "rows": 2,
            "effective_length": 0.4 * WIDTH,
            "rule": "D_w = (D - d)/4; d_m = (d + D)/2; Z = floor(pi d_m/(1.03 D_w)) per row; "
                    "l_we = 0.4 B"}


def base_bearing() -> Bearing:
    """The example bearing file, checked against :func:`derived_geometry`."""
    b = load_example("nncf5040")
    geo = derived_geometry()
    g = b.geometry
    assert (abs(g.element_diameter - geo["element_diameter"]) < 1e-12
            and abs(g.mean_diameter - geo["pitch_diameter"]) < 1e-12
            and g.elements == geo["elements_per_row"]
            and abs(g.effective_length - geo["effective_length"]) < 1e-12), \
        "nncf5040.toml must hold the derived geometry"
    return b


def load_factor(bearing: Bearing) -> float:
    """K = Z Q_max / Fr (Z = all rollers) of the bearing's load distribution [-]."""
    d = distribute_loads(bearing)
    g = bearing.geometry
    return d.max_load * g.elements * g.rows / bearing.operation.radial_load


def paper_clearance(k: float = K_PAPER) -> float:
    """Radial clearance [m] for which the load factor Z Q_max/Fr equals ``k``."""
    b = base_bearing()

    def resid(cr: float) -> float:
        return load_factor(replace(b, geometry=replace(b.geometry, radial_clearance=cr))) - k

    return float(brentq(resid, 0.0, 200e-6, xtol=1e-10))


def bearing_at(t_oil: float, thermal: str = "none", nodes: int | None = None,
               clearance: float | None = None) -> Bearing:
    """The NNCF 5040 CV bearing at oil temperature ``t_oil`` [C]."""
    b = base_bearing()
    g = b.geometry if clearance is None else replace(b.geometry, radial_clearance=clearance)
    return replace(b, geometry=g, operation=replace(b.operation, oil_temperature=float(t_oil)),
                   model=replace(b.model, thermal=thermal),
                   mesh=replace(b.mesh, line_nodes=nodes))


def palmgren_paper(t_oil: float) -> float:
    """The paper's empirical bearing heat power [W] at oil temperature t_oil [C]."""
    nu_mm2s = prokofiev(t_oil, ETA_40, T_REF, N_PROK) / OIL_DENSITY * 1e6
    return palmgren_heat_power(nu_mm2s, RPM, 0.5 * (BORE + OUTER) * 1e3, BORE * 1e3, FR,
                               f0=F0, f_pr=F_PR)


def _solve_row(bearing: Bearing) -> dict:
    t0 = time.perf_counter()
    r = solve_bearing(bearing)
    s = r.summary()
    eb = s["energy_balance"] or {}
    # the paper's bearing total: every roller at the most loaded roller's load (inner plus
    # outer contact), an upper bound, for comparison with the bearing-level total
    e = r.elements[r.most_loaded_element()]
    n = bearing.geometry.elements * bearing.geometry.rows
    ok = e["inner"]["success"] and e["outer"]["success"]
    rule = {"heat_power_W": n * (e["inner"]["heat_power"] + e["outer"]["heat_power"])
            if ok else None,
            "heat_power_torque_W": n * e["torque"] * bearing.operation.inner_speed
            if ok and e["torque"] is not None else None}
    return {"all_rollers_at_max_load": rule,
            "status": r.status, "success": r.success, "wall_time_s": time.perf_counter() - t0,
            "heat_power_contacts_W": s["heat_power"],
            "heat_power_torque_W": eb.get("torque_times_speed"),
            "friction_torque_N_m": s["friction_torque"], "h_min_m": s["h_min"],
            "p_max_Pa": s["p_max"], "elements_loaded": s["load_distribution"]["elements_loaded"],
            "distinct_contacts": s["contact_solves"]["distinct_solved"],
            "empirical": {k: v.get("heat_power") for k, v in s["empirical"].items()},
            "message": r.message[:300]}


def _rel(a, b):
    return None if a is None or b is None else 100.0 * (a - b) / b


def main(outdir: str | Path = "out/nncf5040_heat_power", quick: bool = False) -> dict:
    """Run the study; write ``results.json``, ``table.md``, ``table.csv`` and
    ``heat_power.png`` into ``outdir``; return the numbers.

    quick: oil temperatures 20 and 100 C on 401-node contact meshes, the thermal variant at
    100 C only (about 10 s); full: 20..100 C in 10 K steps, isothermal on the solver's
    automatic meshes, thermal on 801 nodes.
    """
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    temps = [20.0, 100.0] if quick else [20.0 + 10.0 * k for k in range(9)]
    iso_nodes = 401 if quick else None
    th_nodes = 401 if quick else 801
    cr = paper_clearance()
    k0 = load_factor(replace(base_bearing(), geometry=replace(base_bearing().geometry,
                                                              radial_clearance=0.0)))
    rows = []
    for t in temps:
        b = bearing_at(t, nodes=iso_nodes, clearance=cr)
        iso = _solve_row(b)
        th = _solve_row(bearing_at(t, thermal="patch", nodes=th_nodes, clearance=cr)) \
            if (not quick or t == temps[-1]) else {"status": "not run (quick)",
                                                   "heat_power_contacts_W": None}
        pal = palmgren_paper(t)
        row = {"oil_temperature_C": t,
               "viscosity_Pa_s": prokofiev(t, ETA_40, T_REF, N_PROK),
               "palmgren_paper_W": pal,
               "palmgren_harris_W": iso["empirical"].get("palmgren"),
               "isothermal": iso, "thermal": th,
               "diff_isothermal_contacts_pct": _rel(iso["heat_power_contacts_W"], pal),
               "diff_isothermal_torque_pct": _rel(iso["heat_power_torque_W"], pal),
               "diff_thermal_pct": _rel(th["heat_power_contacts_W"], pal),
               "paper_claim_pct": PAPER_CLAIM.get(t)}
        rows.append(row)
        print(f"{t:5.0f} C  iso {iso['status']} Q={_fmt(iso['heat_power_contacts_W'])} W "
              f"(M w {_fmt(iso['heat_power_torque_W'])} W), thermal {th['status']} "
              f"Q={_fmt(th['heat_power_contacts_W'])} W, Palmgren {pal:.0f} W", flush=True)
    results = {"quick": quick, "geometry": derived_geometry(), "radial_clearance_m": cr,
               "load_factor_K": K_PAPER, "load_factor_zero_clearance": k0, "rows": rows}
    (out / "results.json").write_text(json.dumps(results, indent=1, default=float))
    _write_tables(out, rows)
    _figure(out, rows)
    return results


def _fmt(v, f=".4g"):
    return "-" if v is None else format(v, f)


def _write_tables(out: Path, rows: list[dict]) -> None:
    head = ("| t_oil C | eta0 Pa s | EHL iso, contacts W | EHL iso, M omega W | EHL thermal W "
            "| Palmgren (paper) W | Palmgren (Harris) W | iso vs paper % | thermal vs paper % "
            "| paper's claim % |")
    lines = [head, "|" + "---|" * 10]
    csv = ["t_oil_C,eta0_Pa_s,ehl_iso_contacts_W,ehl_iso_torque_W,ehl_thermal_W,palmgren_paper_W,"
           "palmgren_harris_W,iso_status,thermal_status"]
    for r in rows:
        i, t = r["isothermal"], r["thermal"]
        lines.append(f"| {r['oil_temperature_C']:g} | {r['viscosity_Pa_s']:.4g} | "
                     f"{_fmt(i['heat_power_contacts_W'])} | {_fmt(i['heat_power_torque_W'])} | "
                     f"{_fmt(t['heat_power_contacts_W'])} ({t['status']}) | "
                     f"{r['palmgren_paper_W']:.4g} | {_fmt(r['palmgren_harris_W'])} | "
                     f"{_fmt(r['diff_isothermal_contacts_pct'], '+.0f')} | "
                     f"{_fmt(r['diff_thermal_pct'], '+.0f')} | "
                     f"{_fmt(r['paper_claim_pct'], '.0f')} |")
        csv.append(",".join(str(v) for v in (
            r["oil_temperature_C"], r["viscosity_Pa_s"], i["heat_power_contacts_W"],
            i["heat_power_torque_W"], t["heat_power_contacts_W"], r["palmgren_paper_W"],
            r["palmgren_harris_W"], i["status"], t["status"])))
    (out / "table.md").write_text("\n".join(lines) + "\n")
    (out / "table.csv").write_text("\n".join(csv) + "\n")
    print("\n".join(lines))


def _figure(out: Path, rows: list[dict]) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = [r["oil_temperature_C"] for r in rows]

    def col(f):
        return [float("nan") if f(r) is None else f(r) / 1e3 for r in rows]

    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(t, col(lambda r: r["isothermal"]["heat_power_contacts_W"]), "o-",
            label="EHL isothermal (sum of contact heat)")
    ax.plot(t, col(lambda r: r["isothermal"]["heat_power_torque_W"]), "o--",
            label="EHL isothermal (torque x omega)")
    ax.plot(t, col(lambda r: r["thermal"]["heat_power_contacts_W"]), "s-",
            label="EHL thermal patch")
    ax.plot(t, col(lambda r: r["palmgren_paper_W"]), "k-", label="Palmgren, paper's form")
    ax.plot(t, col(lambda r: r["palmgren_harris_W"]), "k:", label="Palmgren, Harris f1")
    ax.set_xlabel("oil temperature [C]")
    ax.set_ylabel("bearing heat power [kW]")
    ax.set_yscale("log")
    ax.set_title("NNCF 5040 CV, 537 rpm, Fr = 500 kN, ISO VG 320", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "heat_power.png", dpi=120)
    plt.close(fig)


# ---------------------------------------------------------------------------------------
# contact-level thermal study (docs/coupling.md section 6)
# ---------------------------------------------------------------------------------------
def contact_rule_geometry() -> dict:
    """Pitch diameter, roller count, line load and contact kinematics of the contact-level
    study (D_w = 28 mm, 28 rollers per row, l_w = 60 mm; q_H = K Fr/(z l_w)) [SI]."""
    dm = 0.5 * (BORE + OUTER)
    z_row = int(math.floor(math.pi * dm / ROLLER_D))
    z = ROWS * z_row
    kin = cylindrical_roller_contacts(dm, ROLLER_D, RPM)
    q_h = max_line_load(FR, z, ROLLER_L, K_LOAD)
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


def contact_study(outdir: str | Path = "out/nncf5040_contacts", quick: bool = False,
                  models: tuple[str, ...] = ("local", "half-space"),
                  temperatures: tuple[float, ...] | None = None,
                  nodes: int | None = None) -> dict:
    """Contact-level thermal study (docs/coupling.md, section 6): one roller at the paper's
    q_H = K Fr/(z l_w), inner and outer contact, thermally coupled; bearing total by the
    paper's rule (every roller at q_H). Writes ``results.json`` and ``table.md``.

    quick: 801 nodes and t_oil = 20, 50, 100 C (else 1201 nodes, 20..100 C in 10 K steps);
    models: elasticity models to run; temperatures: override the oil temperatures [deg C];
    nodes: override the node count.
    """
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    geo = contact_rule_geometry()
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
                    "peclet_min": q.get("peclet_min"),
                    "contact_temperature_rise_K": q.get("contact_temperature_rise"),
                    "contact_temperature_rise_max_K": q.get("contact_temperature_rise_max"),
                    "heat_power_W_per_m": q.get("heat_power"),
                    "heat_power_direct_W_per_m": (
                        q["heat_power_couette"] + q["heat_power_poiseuille_direct"]
                        if "heat_power_poiseuille_direct" in q else None),
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
            row["palmgren_heat_power_W"] = palmgren_paper(t)
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


def rise_scan(outdir: str | Path = "out/nncf5040_rise_scan", side: str = "outer",
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
    geo = contact_rule_geometry()
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
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/nncf5040_heat_power")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--contacts", action="store_true",
                        help="run the contact-level thermal study (docs/coupling.md)")
    parser.add_argument("--rise-scan", action="store_true",
                        help="computed contact temperature rise vs contact temperature")
    a = parser.parse_args()
    if a.rise_scan:
        rise_scan(a.outdir)
    elif a.contacts:
        contact_study(a.outdir, quick=a.quick)
    else:
        main(a.outdir, quick=a.quick)

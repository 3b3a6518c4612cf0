"""Hybrid (Si3N4 balls) vs all-steel angular-contact bearing: EHL losses vs Nikitin's model.

Question
--------
Nikitin (2011) measured the power loss of jet-lubricated angular-contact ball bearings with
steel and with silicon-nitride balls, split it into friction (air-oil lubrication) and oil
churning, and fitted criterial (similarity) models Q = phi m rho d_b^2 u^3; he concludes
that in his range the losses of hybrid and steel bearings are comparable because churning
dominates. What do bearing-level EHL solutions say about the contact (friction) part of
the loss when only the balls' material changes (E' and, at speed, the centrifugal force)?

Scene
-----
``bearing_fem/bearings/7010-steel.toml`` and ``7010-hybrid.toml``: a 7010-size spindle
bearing (d = 50, D = 80 mm, 15 deg nominal contact angle, twenty 8.731 mm balls; internal
geometry representative of the series, not manufacturer data), steel rings, steel or
Si3N4 balls (E = 310 GPa, nu = 0.26, 3200 kg/m^3), turbine oil of 8 mm^2/s at the bearing
temperature (eta0 = 6.8 mPa s, alpha = 1.2e-8 1/Pa). Pure axial load Fa = 2 kN (the load of
Nikitin's reported curves), so every ball carries the same load and one inner and one outer
contact are solved per case. Speeds 4000..20000 rpm (quick: 10000 rpm), with and without
the centrifugal ball force (``model.centrifugal``; Jones-Harris ball equilibrium, the
kinematics at each ball's contact angles, see docs/bearing.md).

Nikitin's model: total loss with the steel, ceramic and joint coefficient sets at the
nominal oil flow (q/q_nom = 1); friction and churning parts by his table-1/table-2
coefficients at the maximum oil flow; oil conductivity 0.14 W/(m K), specific heat
1900 J/(kg K), density 850 kg/m^3 (assumed; the paper gives no oil data).

What the EHL total contains: rolling (Poiseuille) losses of pure rolling contacts. Spin of
the ball contacts (nonzero at a contact angle), Heathcote micro-slip, cage and churning
losses are not modelled: the EHL number is a lower bound of the friction part, not of the
total.

Run ``python studies/hybrid_vs_steel.py OUTDIR [--quick]``.
"""
from __future__ import annotations

import argparse
import json
import time
from dataclasses import replace
from pathlib import Path

from bearing_fem.bearing import load_example, nikitin_power_loss, nikitin_split, solve_bearing

AXIAL_LOAD = 2000.0            # N
FLOW_RATIO = 1.0               # q/q_nom


def bearing_case(material: str, rpm: float, centrifugal: bool, nodes: int | None = None):
    """The 7010 bearing with ``material`` balls ("steel" or "hybrid") at ``rpm``."""
    b = load_example(f"7010-{material}")
    return replace(b, operation=replace(b.operation, inner_rpm=float(rpm), radial_load=0.0,
                                        axial_load=AXIAL_LOAD),
                   model=replace(b.model, centrifugal=centrifugal),
                   mesh=replace(b.mesh, point_nodes=None if nodes is None else (nodes, nodes)))


def nikitin(b) -> dict:
    """Nikitin's total (three sets) and split for a bearing [W]."""
    g, lub, op = b.geometry, b.lubricant, b.operation
    nu = lub.viscosity / lub.density
    a = lub.thermal_conductivity / (lub.density * lub.specific_heat)
    args = (op.inner_rpm, g.bore, g.outside_diameter, g.element_diameter, g.contact_angle,
            g.elements, nu, lub.density, a, op.radial_load, op.axial_load)
    out = {f"total_{s}_W": nikitin_power_loss(*args, flow_ratio=FLOW_RATIO,
                                              coefficient_set=s)["heat_power"]
           for s in ("steel", "ceramic", "joint")}
    for m in ("steel", "ceramic"):
        sp = nikitin_split(*args, material=m, flow_range="max")
        out[f"friction_{m}_W"] = sp["friction"]
        out[f"churning_{m}_W"] = sp["churning"]
        out[f"friction_coefficient_{m}"] = sp["friction_coefficient"]
    return out


def main(outdir: str | Path = "out/hybrid_vs_steel", quick: bool = False) -> dict:
    """Run the study; write ``results.json``, ``table.md`` and ``losses.png``; return the
    numbers. quick: 10000 rpm with the centrifugal force (two bearing solves)."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    speeds = (10000.0,) if quick else (4000.0, 8000.0, 12000.0, 16000.0, 20000.0)
    variants = (True,) if quick else (False, True)
    rows = []
    for rpm in speeds:
        for centrifugal in variants:
            row = {"rpm": rpm, "centrifugal": centrifugal}
            for material in ("steel", "hybrid"):
                b = bearing_case(material, rpm, centrifugal)
                t0 = time.perf_counter()
                r = solve_bearing(b)
                s = r.summary()
                e = s["elements"][0]
                row[material] = {
                    "status": r.status, "wall_time_s": time.perf_counter() - t0,
                    "heat_power_W": s["heat_power"],
                    "heat_power_torque_W": (s["energy_balance"] or {}).get("torque_times_speed"),
                    "heat_power_inner_W": s["heat_power_inner"],
                    "heat_power_outer_W": s["heat_power_outer"],
                    "friction_torque_N_m": s["friction_torque"], "h_min_m": s["h_min"],
                    "p_max_Pa": s["p_max"], "ball_load_inner_N": e["load"],
                    "ball_load_outer_N": e["load_outer"],
                    "contact_angle_inner_deg": e["contact_angle_deg"],
                    "contact_angle_outer_deg": e["contact_angle_outer_deg"],
                    "centrifugal_force_N": s["load_distribution"]["centrifugal_force"],
                    "nikitin": nikitin(b)}
                print(f"{rpm:7.0f} rpm centrifugal={centrifugal!s:5} {material:6s} {r.status}: "
                      f"Q_EHL = {_g(s['heat_power'])} W, h_min = {_g(s['h_min'])} m, "
                      f"p_max = {_g(s['p_max'])} Pa", flush=True)
            st, hy = row["steel"], row["hybrid"]
            row["ehl_ratio_hybrid_to_steel"] = (hy["heat_power_W"] / st["heat_power_W"]
                                                if st["heat_power_W"] and hy["heat_power_W"]
                                                else None)
            row["nikitin_friction_ratio_ceramic_to_steel"] = (
                st["nikitin"]["friction_ceramic_W"] / st["nikitin"]["friction_steel_W"])
            row["nikitin_total_ratio_ceramic_to_steel"] = (
                st["nikitin"]["total_ceramic_W"] / st["nikitin"]["total_steel_W"])
            rows.append(row)
    results = {"quick": quick, "axial_load_N": AXIAL_LOAD, "flow_ratio": FLOW_RATIO,
               "rows": rows}
    (out / "results.json").write_text(json.dumps(results, indent=1))
    _table(out, rows)
    _figure(out, rows)
    return results


def _g(v, f=".4g"):
    return "-" if v is None else format(v, f)


def _table(out: Path, rows: list[dict]) -> None:
    lines = ["| rpm | centrifugal | EHL steel W | EHL hybrid W | EHL hybrid/steel | h_min steel/"
             "hybrid um | p_max steel/hybrid GPa | alpha_i/alpha_o steel deg | Nikitin friction "
             "steel / ceramic W | Nikitin churning steel / ceramic W | Nikitin total joint W |",
             "|" + "---|" * 11]
    for r in rows:
        st, hy = r["steel"], r["hybrid"]
        ns = st["nikitin"]
        lines.append(
            f"| {r['rpm']:.0f} | {r['centrifugal']} | {_g(st['heat_power_W'])} | "
            f"{_g(hy['heat_power_W'])} | {_g(r['ehl_ratio_hybrid_to_steel'], '.3f')} | "
            f"{_g(st['h_min_m'] and st['h_min_m'] * 1e6, '.3f')} / "
            f"{_g(hy['h_min_m'] and hy['h_min_m'] * 1e6, '.3f')} | "
            f"{_g(st['p_max_Pa'] and st['p_max_Pa'] / 1e9, '.2f')} / "
            f"{_g(hy['p_max_Pa'] and hy['p_max_Pa'] / 1e9, '.2f')} | "
            f"{st['contact_angle_inner_deg']:.2f} / {st['contact_angle_outer_deg']:.2f} | "
            f"{ns['friction_steel_W']:.4g} / {ns['friction_ceramic_W']:.4g} | "
            f"{ns['churning_steel_W']:.4g} / {ns['churning_ceramic_W']:.4g} | "
            f"{ns['total_joint_W']:.4g} |")
    (out / "table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


def _figure(out: Path, rows: list[dict]) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rr = [r for r in rows if r["centrifugal"]]
    n = [r["rpm"] for r in rr]
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for mat, mk in (("steel", "o-"), ("hybrid", "s-")):
        ax.plot(n, [r[mat]["heat_power_W"] or float("nan") for r in rr], mk,
                label=f"EHL rolling loss, {mat}")
    ax.plot(n, [r["steel"]["nikitin"]["friction_steel_W"] for r in rr], "o:",
            label="Nikitin friction part, steel")
    ax.plot(n, [r["steel"]["nikitin"]["friction_ceramic_W"] for r in rr], "s:",
            label="Nikitin friction part, ceramic")
    ax.plot(n, [r["steel"]["nikitin"]["total_joint_W"] for r in rr], "k--",
            label="Nikitin total (joint set)")
    ax.set_yscale("log")
    ax.set_xlabel("inner-ring speed [rpm]")
    ax.set_ylabel("power loss [W]")
    ax.set_title("7010-size angular-contact bearing, Fa = 2 kN", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "losses.png", dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/hybrid_vs_steel")
    parser.add_argument("--quick", action="store_true")
    a = parser.parse_args()
    main(a.outdir, quick=a.quick)

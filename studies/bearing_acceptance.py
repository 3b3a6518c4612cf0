"""Bearing-level checks: load distribution, films and energy balance against closed forms.

Question
--------
Does the bearing model reproduce what is known exactly or by accepted fits?

- zero-clearance radial ball and roller bearings: Stribeck's maximum element load
  Z Q_max / F_r = 4.37 (balls) and 4.08 (rollers), from the continuous load integral
  (``analytic.stribeck_constant``);
- every bearing: the element loads balance the applied radial and axial load;
- with clearance: the load-zone half angle against Harris' load-distribution integral
  (``analytic.harris_load_zone``);
- the most loaded contacts: EHL central film against Nijenbanning-Venner-Moes (balls)
  and Moes (rollers);
- the whole bearing: friction torque x inner-ring speed = heat power dissipated in the
  films. The torque comes from the contact forces and the moment arms, the heat from each
  contact's conservative dissipation u_m int h dp/dx (+ Couette), which equals 2 u_m F_P
  contact by contact; the balance therefore checks the kinematics and moment arms of the
  torque derivation, not the contact solutions. The share of the heat that is the
  solver's stabilisation dissipation (the conservative minus the direct quadrature of
  h^3 |grad p|^2 / 12 eta) is reported beside it as a measure of film resolution.

Run ``python studies/bearing_acceptance.py OUTDIR [--quick]``. Quick mode solves the EHL
contacts on coarser grids (81^2 for balls, 401 nodes for rollers); full mode on the
package defaults. Writes ``bearing_acceptance.json`` and ``bearing_acceptance.md``.
"""
from __future__ import annotations

import argparse
import json
import math
from dataclasses import replace
from pathlib import Path

from bearing_fem import analytic, formulas
from bearing_fem.bearing import Bearing, distribute_loads, load_example, solve_bearing
from bearing_fem.bearing.loads import series_ball_stiffness


def _ball(z: int, clearance: float = 0.0, **op) -> Bearing:
    """The 6209 example with Z balls (diameter scaled to fit for large Z)."""
    b = load_example("6209")
    dw = 0.0127 if z <= 16 else 0.9 * math.pi * 0.065 / z
    g = replace(b.geometry, elements=z, radial_clearance=clearance, element_diameter=dw,
                first_element_azimuth=0.0)
    return replace(b, geometry=g, operation=replace(b.operation, **op))


def _roller(z: int = 28, clearance: float = 0.0) -> Bearing:
    b = load_example("nncf5040")
    return replace(b, geometry=replace(b.geometry, elements=z, radial_clearance=clearance))


def stribeck_rows() -> list[dict]:
    """Z Q_max / F_r of the discrete solution vs the continuous Stribeck constant."""
    rows = []
    for label, b, exponent in (("ball Z = 9", _ball(9), 1.5), ("ball Z = 40", _ball(40), 1.5),
                               ("roller Z = 28 x 2 rows", _roller(28), 10 / 9)):
        d = distribute_loads(b)
        z = b.geometry.elements * b.geometry.rows
        got = d.max_load * z / b.operation.radial_load
        want = analytic.stribeck_constant(exponent)
        rows.append({"case": label, "Z_Qmax_over_Fr": got, "stribeck": want,
                     "relative_difference": got / want - 1.0})
    return rows


def balance_rows() -> list[dict]:
    """Sum of element loads vs applied loads, over the examples and load cases."""
    cases = {"6209 radial, c_r 7.5 um": _ball(9, 7.5e-6),
             "6209 radial + axial 1.5 kN": _ball(9, 0.0, axial_load=1500.0),
             "6209 axial only": _ball(9, 7.5e-6, radial_load=0.0, axial_load=2000.0),
             "7010 steel": load_example("7010-steel"), "7010 hybrid": load_example("7010-hybrid"),
             "NNCF 5040, c_r 40 um": _roller(28, 40e-6)}
    rows = []
    for label, b in cases.items():
        d = distribute_loads(b)
        op = b.operation
        errs = [abs(got / want - 1.0) for got, want in ((d.radial_sum, op.radial_load),
                                                          (d.axial_sum, op.axial_load))
                if want > 0]
        rows.append({"case": label, "max_relative_imbalance": max(errs)})
    return rows


def harris_rows() -> list[dict]:
    """Load-zone half angle vs Harris' continuous load-distribution integral."""
    rows = []
    for z, cr in ((9, 7.5e-6), (9, 20e-6), (40, 7.5e-6), (40, 20e-6)):
        b = _ball(z, cr)
        d = distribute_loads(b)
        kn = float(series_ball_stiffness(b)[0](0.0))
        h = analytic.harris_load_zone(b.operation.radial_load, z, kn, 1.5, cr)
        rows.append({"case": f"ball Z = {z}, c_r = {cr * 1e6:.1f} um",
                     "half_angle_deg": math.degrees(d.load_zone_half_angle),
                     "harris_deg": math.degrees(h["half_angle"]),
                     "relative_difference": d.load_zone_half_angle / h["half_angle"] - 1.0})
    b = _roller(28, 40e-6)
    d = distribute_loads(b)
    h = analytic.harris_load_zone(b.operation.radial_load / b.geometry.rows, 28, d.stiffness,
                                  10 / 9, 40e-6)
    rows.append({"case": "roller Z = 28, c_r = 40 um",
                 "half_angle_deg": math.degrees(d.load_zone_half_angle),
                 "harris_deg": math.degrees(h["half_angle"]),
                 "relative_difference": d.load_zone_half_angle / h["half_angle"] - 1.0})
    return rows


def small_roller(line_nodes: int) -> Bearing:
    """A small cylindrical roller bearing (NU 206 size), piezo-viscous oil."""
    return Bearing.from_dict({
        "title": "small roller bearing (NU 206 size)",
        "bearing": {"type": "cylindrical-roller", "bore": 0.03, "outside_diameter": 0.062,
                    "element_diameter": 0.009, "elements": 13, "effective_length": 0.009,
                    "pitch_diameter": 0.046, "radial_clearance": 5e-6},
        "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
        "operation": {"inner_rpm": 1500.0, "radial_load": 2000.0},
        "mesh": {"line_nodes": line_nodes}})


def ehl_rows(quick: bool) -> list[dict]:
    """Most loaded contact films vs the fits, and torque x omega vs heat power."""
    b6209 = load_example("6209")
    if quick:
        b6209 = replace(b6209, mesh=replace(b6209.mesh, point_nodes=(81, 81)))
    rows = []
    for label, b in (("6209 (balls)", b6209),
                     ("NU 206 size (rollers)", small_roller(401 if quick else 1601))):
        r = solve_bearing(b)
        s = r.summary()
        j = r.most_loaded_element()
        ball = b.geometry.type.endswith("ball")
        nodes = b.mesh.point_nodes if ball else b.mesh.line_nodes
        grid = ("package default" if nodes is None
                else f"{nodes[0]}^2" if ball else f"{nodes} nodes")
        row = {"case": label, "status": s["status"], "wall_time_s": s["wall_time_s"],
               "grid": grid}
        for race in ("inner", "outer"):
            c = r.elements[j][race]
            if ball:
                fit, name = c["h_central_formula"], c["h_central_formula_name"]
            else:
                sc = r.contact_spec(j, race).scenes[0]
                fit = formulas.line_central_film_moes(sc.load.force, c["rx"], sc.e_prime,
                                                      b.lubricant.viscosity,
                                                      c["entrainment_speed"], b.lubricant.piezo)
                name = "Moes"
            row[f"{race}_h_central_m"] = c["h_central"]
            row[f"{race}_fit_m"] = fit
            row[f"{race}_fit"] = name
            row[f"{race}_relative_difference"] = c["h_central"] / fit - 1.0
        eb = r.totals["energy_balance"]
        row["torque_times_speed_W"] = eb["torque_times_speed"]
        row["heat_power_W"] = s["heat_power"]
        row["energy_balance_relative_difference"] = eb["relative_difference"]
        row["stabilisation_fraction"] = eb["stabilisation_fraction"]
        rows.append(row)
    return rows


def _table(rows: list[dict], keys: list[str]) -> list[str]:
    def fmt(v):
        if isinstance(v, float):
            return f"{v:.4g}"
        return str(v)
    return (["| " + " | ".join(keys) + " |", "|" + "---|" * len(keys)]
            + ["| " + " | ".join(fmt(r.get(k)) for k in keys) + " |" for r in rows])


def main(outdir: str | Path = "out/bearing_acceptance", quick: bool = False) -> dict:
    """Run every check; write ``bearing_acceptance.json`` and ``.md``; return the numbers."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    res = {"stribeck": stribeck_rows(), "balance": balance_rows(), "harris": harris_rows(),
           "ehl": ehl_rows(quick), "quick": quick}
    res["max_stribeck_difference"] = max(abs(r["relative_difference"])
                                         for r in res["stribeck"])
    res["max_imbalance"] = max(r["max_relative_imbalance"] for r in res["balance"])
    res["max_harris_difference"] = max(abs(r["relative_difference"]) for r in res["harris"])
    res["max_film_difference"] = max(abs(r[f"{race}_relative_difference"])
                                     for r in res["ehl"] for race in ("inner", "outer"))
    res["max_energy_balance_difference"] = max(abs(r["energy_balance_relative_difference"])
                                               for r in res["ehl"])
    lines = ["# Bearing-level checks (studies/bearing_acceptance.py"
             + (", quick)" if quick else ")"), "",
             "## Stribeck's maximum element load (zero clearance)", ""]
    lines += _table(res["stribeck"], ["case", "Z_Qmax_over_Fr", "stribeck",
                                      "relative_difference"])
    lines += ["", "## Element loads vs applied load", ""]
    lines += _table(res["balance"], ["case", "max_relative_imbalance"])
    lines += ["", "## Load zone vs Harris' integral", ""]
    lines += _table(res["harris"], ["case", "half_angle_deg", "harris_deg",
                                    "relative_difference"])
    lines += ["", "## Most loaded contact films and energy balance", ""]
    lines += _table(res["ehl"], ["case", "grid", "status", "inner_relative_difference",
                                 "outer_relative_difference", "inner_fit",
                                 "energy_balance_relative_difference", "stabilisation_fraction",
                                 "wall_time_s"])
    lines += ["", f"largest differences: Stribeck {res['max_stribeck_difference']:.2e}, "
              f"load balance {res['max_imbalance']:.2e}, Harris load zone "
              f"{res['max_harris_difference']:.2e}, films vs fits "
              f"{res['max_film_difference']:.2e}, torque x speed vs heat power "
              f"{res['max_energy_balance_difference']:.2e}"]
    (out / "bearing_acceptance.md").write_text("\n".join(lines) + "\n")
    (out / "bearing_acceptance.json").write_text(json.dumps(res, indent=1, allow_nan=False))
    return res


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/bearing_acceptance")
    parser.add_argument("--quick", action="store_true")
    a = parser.parse_args()
    main(a.outdir, quick=a.quick)
    print((Path(a.outdir) / "bearing_acceptance.md").read_text())

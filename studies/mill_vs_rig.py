"""Cold-mill bearing vs lab rig (Zhirkin et al.): FE films vs the film formulas, and the
similarity scaling of speed between the two bearings.

Question
--------
Zhirkin et al. size the oil film of the four-row roller bearings of a cold-rolling mill with
power-law film formulas H = K U^a G^b W^c (five published coefficient sets), and scale the
mill's operating point to a laboratory rig bearing by similarity of Ratner's formula: with
the same oil (m_eta = m_alpha = 1) and the same film (m_h = 1),
m_U^0.75 m_r^0.4 m_q^-0.15 = 1, which gives the rig speed n_rig = n_mill / m_n with
m_n = m_U / (m_D0 m_(1+gamma)). (1) How do FE (elastic, piezo-viscous) films of the whole mill
bearing over the mill's speed range compare with the five sets and the modern fits
(Pan-Hamrock, Dowson-Higginson, Moes)? (2) Does the paper's scaling give the same FE film on
the rig as in the mill?

Scene (the paper's table 2; assumptions stated)
-----------------------------------------------
* Mill bearing: d = 317 mm, mean diameter D0 = 369.5 mm, rollers 23 x 40 mm, Z = 39 per row,
  4 rows, contact angle 15 deg; load 515 kN. Modelled as ``tapered-roller`` (both raceways
  at 15 deg, rows sharing the radial load, rib contact neglected; docs/bearing.md), outside
  diameter D = 2 D0 - d = 422 mm (not in the paper), zero clearance, effective roller length
  = roller length.
* Rig bearing Koyo 97516: d = 80 mm, D0 = 110 mm, rollers 14.7 x 23.4 mm, Z = 19, 2 rows,
  15 deg; load 6 kN; D = 140 mm.
* Oils (the paper's four): ISO VG 68, 100, 220 and 460 at 40 C: eta0 = VG x 1e-6 x 880
  kg/m^3; alpha = 2.2e-8 1/Pa for all (assumed; not in the paper).
* Mill speeds 100, 300 and 756 rpm (stand 3 of the paper's mill runs at 0-756 rpm); quick:
  756 rpm with VG 220.
* Film formulas at the most loaded roller's inner contact (the thinnest film), with the
  mean speed in U = eta0 u_m/(E' R) (:data:`bearing_fem.formulas.ZHIRKIN_CONVENTIONS`: the
  paper does not define its speed; the originals use the mean speed).

Similarity arithmetic reproduced (``similarity``): the paper prints m_z = 2.05, m_i = 2,
m_l = 1.71, m_zil = 7.01, m_P = 88 (515/6 is 85.8: a slip), m_q = 12.55, m_r = 1.47 (from
D_w (1 + gamma), the outer-contact reduced radius, with gamma = 0.062 for the mill (23/369.5,
without cos 15) and 0.13 for the rig (with cos 15)), m_U = 1.35, m_n = 0.43, hence rig
speeds of about 1200 and 1700 rpm for the mill's stands 2 and 3.

Run ``python studies/mill_vs_rig.py OUTDIR [--quick]``.
"""
from __future__ import annotations

import argparse
import json
import math
import time
from pathlib import Path

from bearing_fem.bearing import Bearing, solve_bearing

MILL = {"bore": 0.317, "pitch_diameter": 0.3695, "element_diameter": 0.023,
        "effective_length": 0.040, "elements": 39, "rows": 4, "load": 515e3}
RIG = {"bore": 0.080, "pitch_diameter": 0.110, "element_diameter": 0.0147,
       "effective_length": 0.0234, "elements": 19, "rows": 2, "load": 6e3}
BETA = 15.0                                  # deg
OILS = {"VG 68": 68.0, "VG 100": 100.0, "VG 220": 220.0, "VG 460": 460.0}  # mm^2/s at 40 C
OIL_DENSITY = 880.0                          # kg/m^3
PIEZO = 2.2e-8                               # 1/Pa
RATNER = (0.75, 0.4, -0.15)                  # exponents of speed, radius, line load (dim.)


def bearing(which: dict, rpm: float, oil: str, nodes: int | None) -> Bearing:
    """Mill or rig bearing (``MILL``/``RIG``) at ``rpm`` with ``oil``."""
    dm, d = which["pitch_diameter"], which["bore"]
    data = {
        "title": f"{'mill' if which is MILL else 'rig'} bearing, {rpm:g} rpm, {oil}",
        "bearing": {"type": "tapered-roller", "bore": d, "outside_diameter": 2 * dm - d,
                    "pitch_diameter": dm, "element_diameter": which["element_diameter"],
                    "elements": which["elements"], "rows": which["rows"],
                    "effective_length": which["effective_length"], "contact_angle": BETA},
        "lubricant": {"viscosity": OILS[oil] * 1e-6 * OIL_DENSITY, "piezo": PIEZO,
                      "density": OIL_DENSITY},
        "operation": {"inner_rpm": float(rpm), "radial_load": which["load"]},
    }
    if nodes is not None:
        data["mesh"] = {"line_nodes": nodes}
    return Bearing.from_dict(data)


def similarity(printed: bool = False) -> dict:
    """The paper's scale factors (mill / rig) and the rig speed factor m_n.

    printed=True uses the paper's printed m_P = 88 and gamma_mill = 0.062; otherwise
    m_P = 515/6 and gamma = D_w cos(beta)/D0 for both bearings.
    """
    cb = math.cos(math.radians(BETA))
    g_mill = MILL["element_diameter"] / MILL["pitch_diameter"] * (1.0 if printed else cb)
    g_rig = RIG["element_diameter"] * cb / RIG["pitch_diameter"]
    m_z = MILL["elements"] / RIG["elements"]
    m_i = MILL["rows"] / RIG["rows"]
    m_l = MILL["effective_length"] / RIG["effective_length"]
    m_p = 88.0 if printed else MILL["load"] / RIG["load"]
    m_q = m_p / (m_z * m_i * m_l)
    m_r = (MILL["element_diameter"] * (1 + g_mill)) / (RIG["element_diameter"] * (1 + g_rig))
    a, b, c = RATNER
    m_u = (m_r ** -b * m_q ** -c) ** (1.0 / a)
    m_d0 = MILL["pitch_diameter"] / RIG["pitch_diameter"]
    m_1g = (1 + g_mill) / (1 + g_rig)
    m_n = m_u / (m_d0 * m_1g)
    return {"gamma_mill": g_mill, "gamma_rig": g_rig, "m_z": m_z, "m_i": m_i, "m_l": m_l,
            "m_P": m_p, "m_q": m_q, "m_r": m_r, "m_U": m_u, "m_D0": m_d0,
            "m_1_plus_gamma": m_1g, "m_n": m_n}


def _most_loaded_inner(r) -> dict:
    j = r.most_loaded_element()
    c = r.elements[j]["inner"]
    spec = r.contact_spec(j, "inner")
    sc = spec.scenes[0]
    return {"h_min_m": c["h_min"], "h_central_m": c["h_central"], "p_max_Pa": c["p_max"],
            "load_per_length_N_m": sc.load.force, "rx_m": c["rx"],
            "entrainment_speed_m_s": c["entrainment_speed"], "status": c["status"],
            "moes_M": r.contacts[spec.keys[0]].summary()["dimensionless"].get("M"),
            "moes_L": r.contacts[spec.keys[0]].summary()["dimensionless"].get("L")}


def main(outdir: str | Path = "out/mill_vs_rig", quick: bool = False) -> dict:
    """Run the study; write ``results.json``, ``films.md``, ``similarity.md`` and
    ``films.png``; return the numbers. quick: VG 220 at 756 rpm on 401-node contact
    meshes; full: four oils at 100, 300 and 756 rpm on 801 nodes."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    oils = ("VG 220",) if quick else tuple(OILS)
    speeds = (756.0,) if quick else (100.0, 300.0, 756.0)
    nodes = 401 if quick else 801
    sim_paper, sim = similarity(printed=True), similarity(printed=False)
    rows = []
    for oil in oils:
        for n in speeds:
            t0 = time.perf_counter()
            rm = solve_bearing(bearing(MILL, n, oil, nodes))
            mill = _most_loaded_inner(rm)
            n_rig = n / sim["m_n"]
            rr = solve_bearing(bearing(RIG, n_rig, oil, nodes))
            rig = _most_loaded_inner(rr)
            row = {"oil": oil, "mill_rpm": n, "rig_rpm": n_rig, "mill_status": rm.status,
                   "rig_status": rr.status, "mill": mill, "rig": rig,
                   "films_formulas": rm.films.get("inner", {}),
                   "mill_friction_torque_N_m": rm.totals.get("friction_torque"),
                   "rig_friction_torque_N_m": rr.totals.get("friction_torque"),
                   "wall_time_s": time.perf_counter() - t0}
            ok = mill["h_min_m"] and rig["h_min_m"]
            row["rig_over_mill_h_min"] = rig["h_min_m"] / mill["h_min_m"] if ok else None
            row["rig_over_mill_h_central"] = (rig["h_central_m"] / mill["h_central_m"]
                                              if ok else None)
            rows.append(row)
            print(f"{oil} {n:5.0f} rpm: mill h_min {mill['h_min_m']} m ({rm.status}), rig at "
                  f"{n_rig:.0f} rpm h_min {rig['h_min_m']} m ({rr.status})", flush=True)
    results = {"quick": quick, "similarity_printed": sim_paper, "similarity": sim,
               "rows": rows}
    (out / "results.json").write_text(json.dumps(results, indent=1))
    _tables(out, results)
    _figure(out, rows)
    return results


def _g(v, f=".3g", scale=1.0):
    return "-" if v is None else format(v * scale, f)


def _tables(out: Path, res: dict) -> None:
    rows = res["rows"]
    names = list(rows[0]["films_formulas"]) if rows else []
    lines = ["| oil | mill rpm | M | L | FE h_min um | FE h_c um | "
             + " | ".join(f"{n} um" for n in names) + " |",
             "|" + "---|" * (6 + len(names))]
    for r in rows:
        m = r["mill"]
        cells = []
        for n in names:
            f = r["films_formulas"][n]
            h = f["h_min"] if f["h_min"] is not None else f["h_central"]
            kind = "min" if f["h_min"] is not None else "c"
            cells.append(f"{_g(h, '.3f', 1e6)} ({kind})")
        lines.append(f"| {r['oil']} | {r['mill_rpm']:.0f} | {_g(m['moes_M'])} | "
                     f"{_g(m['moes_L'])} | {_g(m['h_min_m'], '.3f', 1e6)} | "
                     f"{_g(m['h_central_m'], '.3f', 1e6)} | " + " | ".join(cells) + " |")
    (out / "films.md").write_text("\n".join(lines) + "\n")
    sp, s = res["similarity_printed"], res["similarity"]
    sl = ["| factor | paper's arithmetic (m_P = 88, gamma_mill without cos) | consistent "
          "(m_P = 515/6, gamma with cos) |", "|---|---|---|"]
    for k in ("gamma_mill", "gamma_rig", "m_z", "m_i", "m_l", "m_P", "m_q", "m_r", "m_U",
              "m_D0", "m_1_plus_gamma", "m_n"):
        sl.append(f"| {k} | {sp[k]:.4g} | {s[k]:.4g} |")
    sl += ["", "| oil | mill rpm | rig rpm | FE h_min mill um | FE h_min rig um | rig/mill "
           "h_min | rig/mill h_c |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        sl.append(f"| {r['oil']} | {r['mill_rpm']:.0f} | {r['rig_rpm']:.0f} | "
                  f"{_g(r['mill']['h_min_m'], '.3f', 1e6)} | "
                  f"{_g(r['rig']['h_min_m'], '.3f', 1e6)} | "
                  f"{_g(r['rig_over_mill_h_min'], '.3f')} | "
                  f"{_g(r['rig_over_mill_h_central'], '.3f')} |")
    (out / "similarity.md").write_text("\n".join(sl) + "\n")
    print("\n".join(lines))
    print("\n".join(sl))


def _figure(out: Path, rows: list[dict]) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    oil = rows[0]["oil"] if rows else None
    rr = [r for r in rows if r["oil"] == oil]
    n = [r["mill_rpm"] for r in rr]
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    ax.plot(n, [_nan(r["mill"]["h_min_m"]) * 1e6 for r in rr], "ko-", lw=2, label="FE h_min")
    ax.plot(n, [_nan(r["mill"]["h_central_m"]) * 1e6 for r in rr], "ks--", label="FE h_c")
    for name in rr[0]["films_formulas"] if rr else []:
        f = [r["films_formulas"][name] for r in rr]
        key = "h_min" if f[0]["h_min"] is not None else "h_central"
        ax.plot(n, [_nan(x[key]) * 1e6 for x in f], ".-", lw=1,
                label=f"{name} ({'min' if key == 'h_min' else 'central'})")
    ax.plot(n, [_nan(r["rig"]["h_min_m"]) * 1e6 for r in rr], "r^-",
            label="FE h_min, rig at the scaled speed")
    ax.set_xlabel("mill inner-ring speed [rpm]")
    ax.set_ylabel("film at the most loaded roller, inner race [um]")
    ax.set_title(f"mill bearing, 515 kN, {oil}", fontsize=10)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out / "films.png", dpi=120)
    plt.close(fig)


def _nan(v):
    return float("nan") if v is None else v


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/mill_vs_rig")
    parser.add_argument("--quick", action="store_true")
    a = parser.parse_args()
    main(a.outdir, quick=a.quick)

"""Study: Korovchinsky's two-point reconstruction of a contact temperature.

The printed formula (Sanko) beside the corrected one.

Question
    Sanko (after Korovchinsky 1965) recovers the contact (track) temperature of a
    bearing ring from the temperatures measured at two points near the track: the
    half-plane field T = T_n (C + f(x/a, y/a)) of a semi-elliptic strip source is linear
    in the two unknowns T_n C and T_n, so two readings give C, T_n, the whole field, the
    contact temperature T_max = T_n (C + ln sqrt 2) and the source power
    theta = pi lambda T_n / 2. The printed field carries the coefficient 1 instead of 1/2
    on its two quadratic terms (docs/thermal.md, docs/studies_kodnir_korovchinsky.md).
    How far apart are the printed and the corrected reconstructions, and which one reproduces a known truth
    within what the measurement noise allows?

Scene
    Synthetic "measured" field: the thermal FE patch (``bf.thermal.strip_source``, P2 on
    the shipped mesh ``meshes/korovchinsky_patch.vtu``) under a semi-elliptic strip
    source, half-width a = 1 mm, lambda = 40 W/(m K) (bearing steel), q_max = 0.8 MW/m^2
    (T_n = a q_max/lambda = 20 K, theta = 1.257 kW per metre of track), plus a ring bulk
    temperature of 60 C as the datum. Thermocouple readings = that field at two points +
    Gaussian noise, standard deviation 0.05 K, fixed seed. Four point pairs (units of a):
    two depths below the track centre (0, 1.5) & (0, 3) (the main case), two surface
    points beside the track (1.5, 0) & (3, 0), a surface and a depth point (1.5, 0) &
    (0, 3), and a close pair (0, 1) & (2, 0). The noise-implied spread of each recovered
    quantity comes from a seeded Monte Carlo over 2000 noise draws.

Expected outcome
    Corrected: T_max and theta within a few noise standard deviations of the truth
    (the FE discretisation error is ~1e-5 T_n, far below the noise). Printed: errors of
    several kelvin in T_max and tens of percent in theta, far outside the noise band.

Run ``python studies/korovchinsky_reconstruction.py [outdir] [--quick]``; ``main``
returns the numbers and writes ``korovchinsky_reconstruction.json``, ``.md`` and ``.png``.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

from bearing_fem import __version__
from bearing_fem import analytic as A
from bearing_fem.mesh import read_mesh
from bearing_fem.physics import thermal as th

A_HALF = 1.0e-3          # strip half-width a [m]
LAM = 40.0               # conductivity [W/(m K)]
Q_MAX = 8.0e5            # peak flux [W/m^2] -> T_n = 20 K
T_BULK = 60.0            # datum of the synthetic readings [C]
NOISE_K = 0.05           # thermocouple noise, standard deviation [K]
SEED = 20240614
N_DRAWS = 2000
#: point pairs in units of a: (label, (x1, y1), (x2, y2)); the first is the main case
PAIRS = [("two depths below the centre", (0.0, 1.5), (0.0, 3.0)),
         ("two surface points beside the track", (1.5, 0.0), (3.0, 0.0)),
         ("surface point and depth point", (1.5, 0.0), (0.0, 3.0)),
         ("close pair", (0.0, 1.0), (2.0, 0.0))]
FORMS = ("corrected", "printed")
MESH = Path(__file__).resolve().parents[1] / "meshes" / "korovchinsky_patch.vtu"


def _truth(quick: bool) -> th.StripSourceResult:
    """The synthetic field: FE patch on the shipped mesh (quick: a coarser built mesh)."""
    if quick or not MESH.exists():
        return th.strip_source(A_HALF, Q_MAX, LAM, radius=50 * A_HALF, n_across=24)
    return th.strip_source(A_HALF, Q_MAX, LAM, mesh=read_mesh(MESH))


def _field_grid(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Grid of the isotherm figure and of the field error, |x| <= 4a, 0 <= y <= 4a."""
    xs = np.linspace(-4.0, 4.0, 2 * n + 1) * A_HALF
    ys = np.linspace(0.0, 4.0, n + 1) * A_HALF
    return np.meshgrid(xs, ys)


def _reconstruct(p1, p2, T1: float, T2: float, form: str) -> th.TwoPointReconstruction:
    return th.reconstruct_two_point(A_HALF, (p1[0] * A_HALF, p1[1] * A_HALF, T1),
                                    (p2[0] * A_HALF, p2[1] * A_HALF, T2), LAM, form=form)


def main(outdir: str | Path = "out/korovchinsky_reconstruction", quick: bool = False) -> dict:
    """Run the study; return its numbers and write JSON, markdown and PNG into outdir.

    ``quick`` uses a coarser FE patch (24 cells along the strip), 400 noise draws and a
    coarser field grid; the conclusions are the same.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    fe = _truth(quick)
    t_fe = time.perf_counter() - t0
    rng = np.random.default_rng(SEED)
    n_draws = 400 if quick else N_DRAWS

    def measured(x_over_a: float, y_over_a: float) -> float:
        return T_BULK + float(fe.temperature(x_over_a * A_HALF, y_over_a * A_HALF))

    T_contact = measured(0.0, 0.0)          # the truth the method is after
    theta = fe.total_heat                   # W/m, the FE's own imposed power
    Tn = A.korovchinsky_characteristic_temperature(A_HALF, Q_MAX, LAM)
    # FE discretisation error at the contact (datum C = 1/4), for the record
    fe_err = float(fe.temperature(0.0, 0.0)
                   - A.korovchinsky_temperature(0.0, 0.0, A_HALF, Q_MAX, LAM,
                                                C=fe.C_equivalent))
    X, Y = _field_grid(20 if quick else 40)
    T_grid = T_BULK + fe.temperature(X, Y)

    pairs = []
    for label, p1, p2 in PAIRS:
        T1, T2 = measured(*p1), measured(*p2)
        noise = rng.normal(0.0, NOISE_K, size=(n_draws + 1, 2))
        row: dict = {"pair": label, "p1_over_a": list(p1), "p2_over_a": list(p2),
                     "T1_true_C": T1, "T2_true_C": T2,
                     "T1_measured_C": T1 + noise[0, 0], "T2_measured_C": T2 + noise[0, 1]}
        for form in FORMS:
            rec = _reconstruct(p1, p2, T1 + noise[0, 0], T2 + noise[0, 1], form)
            clean = _reconstruct(p1, p2, T1, T2, form)
            mc = np.array([[r.T_max, r.source_power] for r in
                           (_reconstruct(p1, p2, T1 + e1, T2 + e2, form)
                            for e1, e2 in noise[1:])])
            field_err = clean.temperature(X, Y) - T_grid
            row[form] = {
                "C": rec.C, "T_n_K": rec.T_n, "T_max_C": rec.T_max,
                "source_power_W_per_m": rec.source_power,
                "T_max_error_K": rec.T_max - T_contact,
                "source_power_error_pct": 100 * (rec.source_power / theta - 1),
                "noise_free_T_max_error_K": clean.T_max - T_contact,
                "noise_free_source_power_error_pct": 100 * (clean.source_power / theta - 1),
                "noise_sd_T_max_K": float(np.std(mc[:, 0], ddof=1)),
                "noise_sd_source_power_pct": float(100 * np.std(mc[:, 1], ddof=1) / theta),
                "noise_free_field_max_error_K": float(np.max(np.abs(field_err))),
                "noise_free_field_rms_error_K": float(np.sqrt(np.mean(field_err**2))),
            }
        c, p = row["corrected"], row["printed"]
        row["printed_minus_corrected_T_max_K"] = p["T_max_C"] - c["T_max_C"]
        row["printed_minus_corrected_source_power_pct"] = (
            100 * (p["source_power_W_per_m"] / c["source_power_W_per_m"] - 1))
        for form in FORMS:                  # error in units of the noise-implied spread
            r = row[form]
            r["T_max_error_in_sd"] = r["T_max_error_K"] / r["noise_sd_T_max_K"]
            r["source_power_error_in_sd"] = (r["source_power_error_pct"]
                                             / r["noise_sd_source_power_pct"])
        pairs.append(row)

    out = {
        "version": __version__, "quick": quick,
        "command": "python studies/korovchinsky_reconstruction.py OUTDIR"
                   + (" --quick" if quick else ""),
        "scene": {"half_width_m": A_HALF, "conductivity_W_per_mK": LAM, "q_max_W_per_m2": Q_MAX,
                  "T_n_K": Tn, "bulk_temperature_C": T_BULK, "noise_sd_K": NOISE_K,
                  "seed": SEED, "noise_draws": n_draws,
                  "fe_patch": "shipped mesh" if not quick and MESH.exists()
                  else "strip_mesh n_across=24", "fe_dofs": fe.dofs,
                  "fe_wall_time_s": t_fe},
        "truth": {"T_contact_C": T_contact, "source_power_W_per_m": theta,
                  "fe_contact_error_K": fe_err},
        "pairs": pairs,
        "wall_time_s": time.perf_counter() - t0,
    }
    _write(outdir / "korovchinsky_reconstruction.json", json.dumps(out, indent=1))
    _write(outdir / "korovchinsky_reconstruction.md", _markdown(out))
    _plot(fe, out, X, Y, T_grid, outdir / "korovchinsky_reconstruction.png")
    return out


def _write(path: Path, text: str) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def _markdown(out: dict) -> str:
    tr = out["truth"]
    lines = [f"Truth (FE patch + {T_BULK:g} C datum): contact temperature "
             f"{tr['T_contact_C']:.3f} C, source power {tr['source_power_W_per_m']:.1f} W/m; "
             f"noise sd {NOISE_K} K per reading, {out['scene']['noise_draws']} draws.", "",
             "| pair (x/a, y/a) | form | C | T_n K | T_max C | T_max err K | err / sd | "
             "theta W/m | theta err % | err / sd | field max err K (noise-free) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in out["pairs"]:
        name = (f"{row['pair']}: ({row['p1_over_a'][0]:g}, {row['p1_over_a'][1]:g}) & "
                f"({row['p2_over_a'][0]:g}, {row['p2_over_a'][1]:g})")
        for form in FORMS:
            r = row[form]
            lines.append(
                f"| {name} | {form} | {r['C']:.4f} | {r['T_n_K']:.3f} | {r['T_max_C']:.3f} | "
                f"{r['T_max_error_K']:+.3f} | {r['T_max_error_in_sd']:+.1f} | "
                f"{r['source_power_W_per_m']:.1f} | {r['source_power_error_pct']:+.2f} | "
                f"{r['source_power_error_in_sd']:+.1f} | "
                f"{r['noise_free_field_max_error_K']:.3f} |")
    lines += ["", "| pair | printed - corrected T_max K | printed / corrected theta - 1, % |",
              "|---|---|---|"]
    for row in out["pairs"]:
        lines.append(f"| {row['pair']} | {row['printed_minus_corrected_T_max_K']:+.3f} | "
                     f"{row['printed_minus_corrected_source_power_pct']:+.2f} |")
    return "\n".join(lines) + "\n"


def _plot(fe, out: dict, X, Y, T_grid, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    main_pair = out["pairs"][0]
    p1, p2 = main_pair["p1_over_a"], main_pair["p2_over_a"]
    levels = np.linspace(np.floor(T_grid.min()), np.ceil(T_grid.max()), 13)
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.4), layout="constrained")
    for k, form in enumerate(FORMS):
        rec = _reconstruct(p1, p2, main_pair["T1_measured_C"], main_pair["T2_measured_C"],
                           form)
        a = ax[k]
        cf = a.contourf(X / A_HALF, Y / A_HALF, T_grid, levels=levels, cmap="inferno")
        cs = a.contour(X / A_HALF, Y / A_HALF, rec.temperature(X, Y), levels=levels,
                       colors="c", linestyles="--", linewidths=1)
        a.clabel(cs, fmt="%.0f", fontsize=7)
        a.plot([p1[0], p2[0]], [p1[1], p2[1]], "wo", ms=6, mec="k", label="thermocouples")
        a.plot([-1, 1], [0, 0], "g-", lw=4, label="heated strip")
        a.set_ylim(4, 0)
        a.set_aspect("equal")
        a.set_xlabel("x / a (across the track)")
        a.set_ylabel("y / a (depth)")
        a.set_title(f"truth (filled) vs {form} reconstruction (dashed)\n"
                    f"T_max error {main_pair[form]['T_max_error_K']:+.2f} K", fontsize=9)
        a.legend(fontsize=7, loc="lower right")
    fig.colorbar(cf, ax=ax[1], label="temperature [C]")
    s = np.linspace(0.0, 4.0, 161)
    b = ax[2]
    b.plot(s, T_BULK + fe.temperature(s * A_HALF, 0 * s), "k-", label="truth, surface")
    b.plot(s, T_BULK + fe.temperature(0 * s, s * A_HALF), "b-", label="truth, below centre")
    for form, ls in (("corrected", "--"), ("printed", ":")):
        rec = _reconstruct(p1, p2, main_pair["T1_measured_C"], main_pair["T2_measured_C"],
                           form)
        b.plot(s, rec.temperature(s * A_HALF, 0 * s), "k" + ls, label=f"{form}, surface")
        b.plot(s, rec.temperature(0 * s, s * A_HALF), "b" + ls, label=f"{form}, below centre")
    b.plot([p[1] for p in (p1, p2)], [main_pair["T1_measured_C"], main_pair["T2_measured_C"]],
           "ro", label="readings")
    b.set_xlabel("x/a (surface)  or  y/a (depth below centre)")
    b.set_ylabel("temperature [C]")
    b.legend(fontsize=7)
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default="out/korovchinsky_reconstruction")
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    res = main(args.outdir, quick=args.quick)
    sys.stdout.write((Path(args.outdir) / "korovchinsky_reconstruction.md").read_text())

"""Study: accuracy and cost of the Korovchinsky thermal FE patch.

Question
    How accurately does ``bearing_fem.physics.thermal.strip_source`` reproduce the corrected
    Korovchinsky half-plane field (docs/theory.md section 14.4), how large is the error caused by
    truncating the half-plane at radius R under each far-field condition, and what does a
    solve cost?

Scene
    Semi-elliptic strip source, a = 0.1 mm, q_max = 100 MW/m^2, lambda = 40 W/(m K)
    (T_n = 250 K). Acceptance points: surface x/a in {0.5, 1, 1.5, 2, 3}, depth y/a in
    {0.5, 1, 2, 3} below the centre, and four interior points; errors of
    T(0,0) - T(x,y) in % of T_n. Truncation: R/a in {5, 10, 20, 50, 100} with the
    Dirichlet multipole datum (monopole + quadrupole), the monopole-only Dirichlet datum and
    the monopole-exact Robin condition, on a fine mesh so that the discretisation floor
    sits below the truncation error. Two-point reconstruction from FE temperatures.

Expected outcome
    Difference errors far below the 1 % acceptance (P2 elements on the graded elliptic
    mesh). Monopole-only conditions leave the quadrupole, ~ (a/R)^2 cos(2 phi) on the
    arc, which decays inwards like (r/R)^2, so the error near the contact falls like
    (a/R)^4; the quadrupole datum reaches the discretisation floor by R ~ 10a; observed
    mesh orders
    near 2 (P1) and 3 (P2); source power recovered within 1 %.

Run ``python studies/korovchinsky_patch.py [outdir]``; ``main`` returns the numbers.
"""
from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import numpy as np

from bearing_fem import __version__, analytic as A

from bearing_fem.physics import thermal as th

A_HALF, Q_MAX, LAM = 1.0e-4, 1.0e8, 40.0
SURFACE_X = [0.5, 1.0, 1.5, 2.0, 3.0]
DEPTH_Y = [0.5, 1.0, 2.0, 3.0]
INTERIOR = [(0.5, 0.5), (1.2, 0.8), (2.0, 1.5), (-0.7, 0.3)]
RADII = [5, 10, 20, 50, 100]


def _points() -> tuple[np.ndarray, np.ndarray, list[str]]:
    pts = ([(x, 0.0) for x in SURFACE_X] + [(0.0, y) for y in DEPTH_Y] + INTERIOR)
    labels = [f"({x:g}, {y:g})" for x, y in pts]
    arr = np.array(pts) * A_HALF
    return arr[:, 0], arr[:, 1], labels


def _errors(res: th.StripSourceResult) -> tuple[np.ndarray, np.ndarray]:
    """(difference error, absolute error in the C = 1/4 datum), both in % of T_n."""
    x, y, _ = _points()
    ex = A.korovchinsky_temperature(x, y, A_HALF, Q_MAX, LAM, C=0.25)
    ex0 = A.korovchinsky_temperature(0.0, 0.0, A_HALF, Q_MAX, LAM, C=0.25)
    fe = res.temperature(x, y)
    fe0 = res.temperature(0.0, 0.0)
    diff = ((fe0 - fe) - (ex0 - ex)) / res.T_n * 100
    absolute = (fe - ex) / res.T_n * 100
    return diff, absolute


def main(outdir: str | Path = "out/korovchinsky_patch", n: int = 48, quick: bool = False) -> dict:
    """Run the study; write ``korovchinsky_patch.json`` and ``.png`` to ``outdir``.

    Parameters
    ----------
    outdir : path
        Output directory (created).
    n : int
        ``n_across`` of the accuracy run (the truncation sweep uses 2n, quick: n).
    quick : bool
        Fewer radii and meshes (for tests).
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    x, y, labels = _points()
    out: dict = {"version": __version__, "scene": {"half_width_m": A_HALF,
                 "q_max_W_m2": Q_MAX, "conductivity_W_mK": LAM,
                 "T_n_K": A.korovchinsky_characteristic_temperature(A_HALF, Q_MAX, LAM)},
                 "command": " ".join(sys.argv)}

    # 1. accuracy table at the acceptance points
    t0 = time.perf_counter()
    res = th.strip_source(A_HALF, Q_MAX, LAM, radius=50 * A_HALF, n_across=n)
    wall = time.perf_counter() - t0
    diff, absolute = _errors(res)
    out["accuracy"] = {
        "n_across": n, "radius_over_a": 50, "dofs": res.dofs, "wall_time_s": wall,
        "points_x_over_a_y_over_a": labels,
        "difference_error_pct_Tn": diff.tolist(),
        "absolute_error_pct_Tn": absolute.tolist(),
        "max_abs_difference_error_pct_Tn": float(np.abs(diff).max()),
        "total_heat_rel_error": res.total_heat / (np.pi * A_HALF * Q_MAX / 2) - 1,
        "heat_out_over_heat_in_minus_1": res.heat_out / res.total_heat - 1,
    }

    # 2. truncation error vs radius
    radii = [5, 20, 100] if quick else RADII
    n_tr = n if quick else 2 * n
    conds = {"dirichlet_quadrupole": dict(far_field="dirichlet", multipole_order=2),
             "dirichlet_monopole": dict(far_field="dirichlet", multipole_order=0),
             "robin_monopole": dict(far_field="robin")}
    trunc: dict = {"radius_over_a": radii, "n_across": n_tr}
    for name, kw in conds.items():
        d_err, a_err, times, dofs = [], [], [], []
        for R in radii:
            t0 = time.perf_counter()
            r = th.strip_source(A_HALF, Q_MAX, LAM, radius=R * A_HALF, n_across=n_tr, **kw)
            times.append(time.perf_counter() - t0)
            dofs.append(r.dofs)
            d, ab = _errors(r)
            d_err.append(float(np.abs(d).max()))
            a_err.append(float(np.abs(ab).max()))
        trunc[name] = {"max_difference_error_pct_Tn": d_err,
                       "max_absolute_error_pct_Tn": a_err, "wall_time_s": times,
                       "dofs": dofs}
    out["truncation"] = trunc

    # 3. mesh convergence (observed order of the max difference error)
    ns = [8, 16, 32] if quick else [8, 16, 32, 64]
    conv: dict = {"n_across": ns}
    for order in (1, 2):
        errs = []
        for m in ns:
            r = th.strip_source(A_HALF, Q_MAX, LAM, radius=20 * A_HALF, n_across=m, order=order)
            errs.append(float(np.abs(_errors(r)[0]).max()))
        conv[f"P{order}_max_difference_error_pct_Tn"] = errs
        conv[f"P{order}_observed_order"] = float(np.polyfit(np.log(1.0 / np.array(ns)),
                                                            np.log(errs), 1)[0])
    out["convergence"] = conv

    # 4. two-point reconstruction from FE temperatures
    theta = np.pi * A_HALF * Q_MAX / 2
    pairs = [((0.0, 2.0), (1.5, 0.0)), ((0.0, 1.0), (3.0, 0.0)), ((0.5, 0.0), (2.0, 1.5))]
    tp = []
    T0 = float(res.temperature(0.0, 0.0))
    for p1, p2 in pairs:
        q1, q2 = ((px * A_HALF, py * A_HALF, float(res.temperature(px * A_HALF, py * A_HALF)))
                  for px, py in (p1, p2))
        rec = th.reconstruct_two_point(A_HALF, q1, q2, LAM)
        tp.append({"p1_over_a": p1, "p2_over_a": p2, "C": rec.C,
                   "source_power_rel_error": rec.source_power / theta - 1,
                   "T_max_rel_error": rec.T_max / T0 - 1})
    out["two_point"] = tp

    (outdir / "korovchinsky_patch.json").write_text(json.dumps(out, indent=2))
    _plot(res, out, outdir / "korovchinsky_patch.png")
    return out


def _plot(res: th.StripSourceResult, out: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    s = np.linspace(0, 4, 161)
    Tn = res.T_n
    ax[0].plot(s, A.korovchinsky_surface(s, C=0.25), "k-", label="closed form, surface")
    ax[0].plot(s, res.temperature(s * A_HALF, 0 * s) / Tn, "r--", label="FE, surface")
    ax[0].plot(s, A.korovchinsky_depth(s, C=0.25), "b-", label="closed form, below centre")
    ax[0].plot(s, res.temperature(0 * s, s * A_HALF) / Tn, "c--", label="FE, below centre")
    ax[0].set_xlabel("x/a  or  y/a")
    ax[0].set_ylabel("T / T_n  (datum C = 1/4)")
    ax[0].legend(fontsize=8)
    tr = out["truncation"]
    for name, mk in (("dirichlet_quadrupole", "o-"), ("dirichlet_monopole", "s-"),
                     ("robin_monopole", "^-")):
        ax[1].loglog(tr["radius_over_a"], tr[name]["max_absolute_error_pct_Tn"], mk, label=name)
    R = np.array(tr["radius_over_a"], float)
    ax[1].loglog(R, tr["dirichlet_monopole"]["max_absolute_error_pct_Tn"][0] * (R[0] / R) ** 4,
                 "k:", label="(a/R)^4")
    ax[1].set_xlabel("R / a")
    ax[1].set_ylabel("max |T_FE - T_exact|  [% of T_n]")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    res = main(sys.argv[1] if len(sys.argv) > 1 else "out/korovchinsky_patch")
    print(json.dumps({k: res[k] for k in ("accuracy", "truncation", "convergence")}, indent=1))

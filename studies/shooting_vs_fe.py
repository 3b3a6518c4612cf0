"""Study: the Kodnir line-contact problem by shooting (as Yachikov & Vostrikov 2015) vs by FE.

Question
    Yachikov & Vostrikov (2015) solve Kodnir's dimensionless EHL problem of the locally
    compliant line contact (docs/kodnir.md, docs/theory.md)

        dk/dz = (1 - H)/H^3 exp(B alpha k),  H = 1 - z_a^2 + z^2 + C k,
        k(z_a) = 0, H(z_a) = 1, k(z_b = 20) = 0,

    by shooting on the outlet z_a with a Runge-Kutta method, and report that it fails for
    many (B alpha, C): they had to cut the step from 1e-3 to 1e-6 or cap B alpha k < 7.
    Over a 10 x 10 map of the two groups in Ratner's range (C = 0.6..40 log-spaced,
    B alpha = 0..12), how often does shooting succeed, how accurate is it and what does it
    cost, next to the finite-element solver ``bf.kodnir.solve``?

Scene
    Dimensionless, z_b = 20. Shooting (``studies/kodnir_shooting.py``): scipy
    ``solve_ivp`` from the trial outlet to z_b, a scan of 18 trial outlets
    z_a in [-12, -0.05] for a sign change of k(z_b), then ``brentq``; two integrators:
    the explicit RK45 (the authors' Runge-Kutta; at most 20 000 right-hand-side
    evaluations per integration, 150 000 per case) and LSODA (stiff/non-stiff switching,
    analytic Jacobian, same caps); rtol 1e-9, atol 1e-12; success needs
    |k(z_b)| <= 1e-6 max(1, k_max) at the root and k >= 0 along the trajectory.
    FE: ``bf.kodnir.solve(C, B alpha, nodes=1001)``. Accuracy references: a better-
    resolved FE (2001 nodes, the package default) on a 3 x 3 sub-map and on every case
    the 1001-node FE fails, and the analytic
    rigid limits C = 0 (Martin's outlet z_a = -sin g_c and peak pressure; for
    B alpha > 0 the Barus/Kapitsa transform of it, which exists while B alpha q_max < 1).
    Quick mode: 3 x 3 map C in {0.6, 1.53, 3.88} x B alpha in {0, 4, 8}, one reference.

Expected outcome
    FE succeeds everywhere. Explicit shooting fails wherever the problem is stiff (the
    Hertzian zone with exp(B alpha k) large); LSODA shooting succeeds further but fails
    where B alpha k_max is so large that 1 - H in the Hertzian zone is below double
    precision (the shooting function becomes discontinuous). Where shooting succeeds it
    agrees with FE to the FE discretisation error.

Run ``python studies/shooting_vs_fe.py [outdir] [--quick]``; ``main`` returns the numbers
and writes ``shooting_vs_fe.json``, ``shooting_vs_fe.md``, ``shooting_vs_fe.csv`` and
``shooting_vs_fe.png`` into outdir.
"""
from __future__ import annotations

import argparse
import csv
import io
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np
from threadpoolctl import threadpool_limits

sys.path.insert(0, str(Path(__file__).resolve().parent))

from kodnir_shooting import shoot  # noqa: E402  (study-local baseline, not product)

from bearing_fem import __version__  # noqa: E402
from bearing_fem import analytic as A  # noqa: E402
from bearing_fem.contacts import kodnir  # noqa: E402

C_FULL = [float(c) for c in np.geomspace(0.6, 40.0, 10)]
BA_FULL = [float(b) for b in np.linspace(0.0, 12.0, 10)]
C_QUICK = [C_FULL[0], C_FULL[2], C_FULL[4]]
BA_QUICK = [0.0, 4.0, 8.0]
FE_NODES, REF_NODES = 1001, 2001
METHODS = ("RK45", "LSODA")
SHOOT_BUDGET = {"max_rhs": 20_000, "max_total_rhs": 150_000}
KEYS = ("z_a", "k_max", "h_min", "friction_integral")


def martin_limit(b_alpha: float) -> dict:
    """Analytic rigid (C = 0) limit in Kodnir variables (inlet at infinity).

    Martin: z_a = -sin g_c, isoviscous peak q_max = (p/P0)_max/(12 cos^3 g_c) (with
    P0 = 1 for h0 = 1, R = 1/2, eta u_m = 1); Barus/Kapitsa transform
    k_max = -ln(1 - B alpha q_max)/(B alpha), same outlet; exists iff B alpha q_max < 1.
    """
    gc = A.martin_outlet_angle()
    q_max = float(A.martin_max_reduced(1.0, 0.5, 1.0, 1.0)) / (12.0 * math.cos(gc) ** 3)
    return {"z_a": -math.sin(gc),
            "k_max": float(A.barus_from_reduced(q_max, b_alpha)) if b_alpha > 0 else q_max,
            "exists": b_alpha * q_max < 1.0, "b_alpha_q_max": b_alpha * q_max}


def _rel(a: float, b: float) -> float | None:
    if not (math.isfinite(a) and math.isfinite(b)):
        return None
    return abs(a - b) / max(abs(b), 1e-300)


def _fe(C: float, b_alpha: float, nodes: int) -> dict:
    t0 = time.perf_counter()
    r = kodnir.solve(C, b_alpha, nodes=nodes)
    out = {"success": r.success, "status": r.status, "message": r.message,
           "seconds": time.perf_counter() - t0, "nodes": nodes}
    out.update({k: float(getattr(r, k)) for k in KEYS})
    return out


def _shoot(C: float, b_alpha: float, method: str) -> dict:
    r = shoot(C, b_alpha, method, **SHOOT_BUDGET)
    out = {"success": r.success, "status": r.status, "message": r.message,
           "seconds": r.seconds, "integrations": r.integrations, "n_rhs": r.n_rhs}
    out.update({k: float(getattr(r, k)) for k in KEYS})
    return out


def _case(C: float, b_alpha: float, reference: bool) -> dict:
    row = {"C": C, "b_alpha": b_alpha, "fe": _fe(C, b_alpha, FE_NODES)}
    for m in METHODS:
        row[m] = _shoot(C, b_alpha, m)
    fe = row["fe"]
    for m in METHODS:                        # shooting vs FE where both succeed
        s = row[m]
        s["rel_diff_vs_fe"] = ({k: _rel(s[k], fe[k]) for k in KEYS}
                               if s["success"] and fe["success"] else None)
    if reference or not fe["success"]:       # a failed FE case: try the default grid
        ref = _fe(C, b_alpha, REF_NODES)
        row["reference_fe"] = ref
        for name in ("fe",) + METHODS:
            r = row[name]
            r["rel_error_vs_reference"] = ({k: _rel(r[k], ref[k]) for k in KEYS}
                                           if r["success"] and ref["success"] else None)
    return row


def _analytic_rows(b_alphas: list[float]) -> list[dict]:
    rows = []
    for b in b_alphas:
        ex = martin_limit(b)
        row = {"C": 0.0, "b_alpha": b, "analytic": ex, "fe": _fe(0.0, b, FE_NODES)}
        for m in METHODS:
            row[m] = _shoot(0.0, b, m)
        for name in ("fe",) + METHODS:
            r = row[name]
            r["rel_error_vs_analytic"] = ({k: _rel(r[k], ex[k]) for k in ("z_a", "k_max")}
                                          if r["success"] else None)
        rows.append(row)
    return rows


def _stats(rows: list[dict], name: str) -> dict:
    ok = [r for r in rows if r[name]["success"]]
    out = {"cases": len(rows), "successes": len(ok),
           "success_rate": len(ok) / max(len(rows), 1),
           "median_seconds": float(np.median([r[name]["seconds"] for r in rows])),
           "total_seconds": float(sum(r[name]["seconds"] for r in rows)),
           "failures_by_status": {}}
    for r in rows:
        if not r[name]["success"]:
            st = r[name]["status"]
            out["failures_by_status"][st] = out["failures_by_status"].get(st, 0) + 1
    if name != "fe":
        d = [r[name]["rel_diff_vs_fe"] for r in ok if r[name]["rel_diff_vs_fe"]]
        for k in KEYS:
            vals = [x[k] for x in d if x[k] is not None]
            out[f"max_rel_diff_vs_fe_{k}"] = max(vals) if vals else None
        out["max_b_alpha_k_max_succeeded"] = max(
            [r["b_alpha"] * r[name]["k_max"] for r in ok], default=None)
    refd = [r[name].get("rel_error_vs_reference") for r in rows if "reference_fe" in r]
    refd = [x for x in refd if x]
    for k in KEYS:
        vals = [x[k] for x in refd if x[k] is not None]
        out[f"max_rel_error_vs_reference_{k}"] = max(vals) if vals else None
    return out


def main(outdir: str | Path = "out/shooting_vs_fe", quick: bool = False) -> dict:
    """Run the map; return the numbers and write JSON, markdown, CSV and PNG to outdir."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    cs, bas = (C_QUICK, BA_QUICK) if quick else (C_FULL, BA_FULL)
    ref_idx = ({(1, 1)} if quick else {(i, j) for i in (0, 4, 9) for j in (0, 4, 9)})
    t0 = time.perf_counter()
    rows = []
    with threadpool_limits(1):
        for i, c in enumerate(cs):
            for j, b in enumerate(bas):
                rows.append(_case(c, b, (i, j) in ref_idx))
        analytic_rows = _analytic_rows([0.0, 2.5] if quick else [0.0, 2.5, 5.0])
    out = {"version": __version__, "quick": quick,
           "command": "python studies/shooting_vs_fe.py OUTDIR" + (" --quick" if quick else ""),
           "C_values": cs, "b_alpha_values": bas, "z_b": 20.0,
           "fe_nodes": FE_NODES, "reference_nodes": REF_NODES,
           "shooting_budget": SHOOT_BUDGET,
           "summary": {name: _stats(rows, name) for name in ("fe",) + METHODS},
           "rows": rows, "analytic_rows": analytic_rows,
           "wall_time_s": time.perf_counter() - t0}
    _write(outdir / "shooting_vs_fe.json", json.dumps(out, indent=1))
    _write(outdir / "shooting_vs_fe.md", _markdown(out))
    _write(outdir / "shooting_vs_fe.csv", _csv(rows))
    _plot(out, outdir / "shooting_vs_fe.png")
    return out


def _write(path: Path, text: str) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def _csv(rows: list[dict]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf)
    head = ["C", "b_alpha"]
    for name in ("fe",) + METHODS:
        head += [f"{name}_success", f"{name}_status", f"{name}_seconds"] + \
                [f"{name}_{k}" for k in KEYS]
    w.writerow(head)
    for r in rows:
        line = [f"{r['C']:.6g}", f"{r['b_alpha']:.6g}"]
        for name in ("fe",) + METHODS:
            s = r[name]
            line += [s["success"], s["status"], f"{s['seconds']:.3f}"] + \
                    [f"{s[k]:.8g}" if s["success"] else "" for k in KEYS]
        w.writerow(line)
    return buf.getvalue()


def _pct(x: float | None, digits: int = 3) -> str:
    return "—" if x is None else f"{100 * x:.{digits}f}"


def _markdown(out: dict) -> str:
    s = out["summary"]
    lines = [f"Map {len(out['C_values'])} x {len(out['b_alpha_values'])} (C x B alpha), "
             f"z_b = 20; FE {out['fe_nodes']} nodes; reference FE {out['reference_nodes']} "
             "nodes on the sub-map marked below.", "",
             "| solver | successes | success rate | median s/case | total s | failures | "
             "max rel. diff vs FE z_a / k_max / H_min / I, % | max B alpha k_max solved |",
             "|---|---|---|---|---|---|---|---|"]
    for name, label in (("fe", "FE (bf.kodnir.solve)"), ("RK45", "shooting, RK45"),
                        ("LSODA", "shooting, LSODA")):
        st = s[name]
        fails = ", ".join(f"{k} {v}" for k, v in st["failures_by_status"].items()) or "none"
        diffs = ("—" if name == "fe" else " / ".join(
            _pct(st[f"max_rel_diff_vs_fe_{k}"]) for k in KEYS))
        bk = st.get("max_b_alpha_k_max_succeeded")
        lines.append(f"| {label} | {st['successes']}/{st['cases']} | "
                     f"{100 * st['success_rate']:.0f} % | {st['median_seconds']:.2f} | "
                     f"{st['total_seconds']:.1f} | {fails} | {diffs} | "
                     f"{'—' if bk is None else f'{bk:.3g}'} |")
    lines += ["", "Success map (F = FE, R = RK45 shooting, L = LSODA shooting; '.' = failed):",
              "", "| C \\ B alpha | " + " | ".join(f"{b:.3g}" for b in out["b_alpha_values"])
              + " |", "|---|" + "---|" * len(out["b_alpha_values"])]
    for c in out["C_values"]:
        cells = []
        for b in out["b_alpha_values"]:
            r = next(x for x in out["rows"] if x["C"] == c and x["b_alpha"] == b)
            cells.append("".join(ch if r[n]["success"] else "." for n, ch in
                                 (("fe", "F"), ("RK45", "R"), ("LSODA", "L")))
                         + ("*" if "reference_fe" in r else ""))
        lines.append(f"| {c:.3g} | " + " | ".join(cells) + " |")
    lines += ["", "(* = also run with the reference FE: the 3 x 3 sub-map and every case "
              "the FE failed; its outcome is in the next table.)", "",
              f"Against the reference FE ({out['reference_nodes']} nodes), relative error "
              "in % (z_a / k_max / H_min / I):", "",
              "| C | B alpha | reference FE | FE | RK45 | LSODA |", "|---|---|---|---|---|---|"]
    for r in out["rows"]:
        if "reference_fe" not in r:
            continue
        ref = r["reference_fe"]
        cells = ["solved" if ref["success"] else f"failed ({ref['status']})"]
        for name in ("fe",) + METHODS:
            e = r[name].get("rel_error_vs_reference")
            cells.append("failed" if not r[name]["success"] else
                         " / ".join(_pct(e[k]) for k in KEYS) if e else "—")
        lines.append(f"| {r['C']:.3g} | {r['b_alpha']:.3g} | " + " | ".join(cells) + " |")
    lines += ["", "Analytic rigid limit C = 0 (Martin, Barus/Kapitsa transform; inlet at "
              "infinity vs z_b = 20), relative error in % (z_a / k_max):", "",
              "| B alpha | B alpha q_max | FE | RK45 | LSODA |", "|---|---|---|---|---|"]
    for r in out["analytic_rows"]:
        cells = []
        for name in ("fe",) + METHODS:
            e = r[name]["rel_error_vs_analytic"]
            cells.append(f"failed ({r[name]['status']})" if e is None else
                         f"{_pct(e['z_a'])} / {_pct(e['k_max'])}")
        lines.append(f"| {r['b_alpha']:.3g} | {r['analytic']['b_alpha_q_max']:.3f} | "
                     + " | ".join(cells) + " |")
    lines += ["", f"Wall time of the study: {out['wall_time_s']:.0f} s."]
    return "\n".join(lines) + "\n"


def _plot(out: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cs, bas = out["C_values"], out["b_alpha_values"]
    fig, ax = plt.subplots(1, 4, figsize=(18, 4.4), layout="constrained")
    titles = {"fe": "FE (bf.kodnir.solve)", "RK45": "shooting, explicit RK45",
              "LSODA": "shooting, LSODA"}
    for a, name in zip(ax[:3], ("fe",) + METHODS):
        ok = np.zeros((len(cs), len(bas)))
        for r in out["rows"]:
            ok[cs.index(r["C"]), bas.index(r["b_alpha"])] = r[name]["success"]
        a.pcolormesh(np.arange(len(bas) + 1), np.arange(len(cs) + 1), ok, cmap="RdYlGn",
                     vmin=0, vmax=1, edgecolors="w")
        for r in out["rows"]:
            i, j = cs.index(r["C"]), bas.index(r["b_alpha"])
            txt = f"{r[name]['seconds']:.1f}s" if r[name]["success"] else r[name]["status"][:6]
            a.text(j + 0.5, i + 0.5, txt, ha="center", va="center", fontsize=6)
        a.set_xticks(np.arange(len(bas)) + 0.5, [f"{b:.3g}" for b in bas], fontsize=7)
        a.set_yticks(np.arange(len(cs)) + 0.5, [f"{c:.3g}" for c in cs], fontsize=7)
        a.set_xlabel("B alpha")
        a.set_ylabel("C")
        st = out["summary"][name]
        a.set_title(f"{titles[name]}: {st['successes']}/{st['cases']} solved", fontsize=9)
    b = ax[3]
    for name, mk in (("RK45", "s"), ("LSODA", "o")):
        pts = [(r["b_alpha"] * r["fe"]["k_max"], r[name]["rel_diff_vs_fe"]["z_a"])
               for r in out["rows"] if r[name]["rel_diff_vs_fe"]]
        if pts:
            x, y = np.array(pts).T
            b.loglog(np.maximum(x, 1e-2), np.maximum(y, 1e-9), mk, label=f"{name} vs FE, z_a")
    b.set_xlabel("B alpha k_max (FE; isoviscous cases drawn at 0.01)")
    b.set_ylabel("relative difference")
    b.set_title("where shooting succeeds: agreement with FE", fontsize=9)
    b.legend(fontsize=7)
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default="out/shooting_vs_fe")
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    main(args.outdir, quick=args.quick)
    sys.stdout.write((Path(args.outdir) / "shooting_vs_fe.md").read_text())

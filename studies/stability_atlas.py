"""Stability atlas: where the solver converges, on stiff and extreme cases, with no tuning.

Question
--------
Does ``bearing_fem.solve`` return a converged answer, or else an explicit unsuccessful
status with a message (never NaN or inf), over the whole Moes map and beyond it, with
the solver's defaults and no per-case setting?

Scenes (all isothermal, incompressible, Reynolds cavitation unless said)
------------------------------------------------------------------------
* ``line_map``: elastic line contacts (R = 10 mm, E' = 2.2e11 Pa, eta0 = 0.01 Pa s),
  Moes M in 12 log-spaced values 1 .. 1e4 x L in 8 values 0 .. 25, each for Barus and
  Roelands viscosity, pure rolling and slide-to-roll ratios 0.5 and 2 (Barus). (M, L) are
  realised by :func:`bearing_fem.units.line_scene_from_moes` with alpha = 2e-8 1/Pa; where
  alpha p_h > 110, E' is raised to 40 p_h (else the Hertz contact would not be small
  against the radius and the scene would be refused); L = 0 is isoviscous. The solver's
  default mesh. Barus half-space scenes with alpha p_h > 700 (exp(alpha p_h) beyond
  double precision) are accepted: their film equation uses the reduced pressure
  (docs/scenes.md, "Ranges"); a scene refused as input would be an explicit
  ``invalid_scene`` outcome.
* ``point_map``: elastic circular contacts (rx = ry = 10 mm, same materials), M in 12
  log-spaced values 5 .. 2000 x L in 8 values 0 .. 25
  (:func:`bearing_fem.units.point_scene_parameters_from_moes`, alpha and E' as above), Barus
  pure rolling on :data:`POINT_NODES`^2 nodes (the solver's default domain and solver
  settings); Roelands and slide-to-roll 0.5 and 2 on every other M and L (6 x 4).
* ``ellipse``: ry/rx from 0.2 to 20 at M = 100, L = 10 (Barus, pure rolling).
* ``high_pressure``: line contacts at L = 10 and circular ones at L = 20 with alpha p_h =
  40, 60, 80, 100 (M solved for).
* ``near_rigid`` (M ~ 1) and ``light_load`` (M = 0.01 .. 0.3): line and circular.
* ``low_speed``: a loaded steel cylinder (w = 1e5 N/m) and ball (F = 100 N), alpha =
  2e-8 1/Pa, eta0 = 0.01 Pa s, entrainment speed 1e-3 .. 1e-6 m/s (the smallest the
  scene accepts): M from 477 to 1.5e4 (cylinder) and 1.5e5 to 2.7e7 (ball).
* ``rigid_limit``: rigid piezo-viscous scenes with a prescribed gap on both sides of the
  existence limit alpha q_max = 1 of the closed forms (:mod:`bearing_fem.analytic`):
  Kapitsa's full-Sommerfeld cylinder and ball (:func:`~bearing_fem.analytic.kapitsa_existence_ratio`)
  and Martin's cylinder with the Reynolds outlet (:func:`~bearing_fem.analytic.martin_existence_ratio`),
  at alpha q_max = 0.5, 0.9, 0.97 (a solution exists: success expected) and 1.03, 1.2, 2
  (none exists: status ``no_solution`` expected).

Each case records status, message, Newton iterations, continuation steps (solver stages
below the target parameter: continuation in speed or alpha), wall time, the error
estimate of h_central and the main numbers. A case is ``ok`` when it succeeded, or, for a
rigid scene beyond the existence limit, when it says ``no_solution``.

Expected outcome
----------------
At least 97% of the line map and 95% of the circular map (Barus, pure rolling) converge,
all of their alpha p_h <= 40 part; every failure has an explicit status and message; no
summary holds NaN or inf.

Run ``python studies/stability_atlas.py OUTDIR [--quick] [--workers N]``. The cases run as
one sweep (:func:`bearing_fem.sweep`) into the run store ``OUTDIR/stability_atlas.sqlite``
(result folders in ``OUTDIR/stability_atlas_runs/``): an interrupted atlas resumes, and a
second run solves nothing. Writes ``stability_atlas.csv`` (every case),
``stability_atlas.md`` (success per family, every failure with its message),
``stability_atlas.json`` and the maps ``stability_line_map.png``,
``stability_point_map.png``.
"""
from __future__ import annotations

import csv
import json
import math
import os
import time
from pathlib import Path

import numpy as np

from bearing_fem import analytic, units
from bearing_fem.errors import SceneError
from bearing_fem.scene import Scene

#: Circular-map grid (nodes per direction; the error estimate comes from its 25^2, 49^2
#: sub-grids). 97^2 rather than 129^2: the default grid sequence of 129^2 starts on 65^2,
#: which is too coarse at M = 2000 (measured: stalled at M = 2000, L = 7).
POINT_NODES = 97
LINE_M = tuple(float(v) for v in np.logspace(0.0, 4.0, 12))
POINT_M = tuple(float(v) for v in np.logspace(math.log10(5.0), math.log10(2000.0), 12))
MAP_L = tuple(float(v) for v in np.linspace(0.0, 25.0, 8))
#: Barus alpha of the map scenes [1/Pa] and their reduced modulus [Pa], raised to
#: HERTZ_MODULUS_RATIO p_h where alpha p_h > 110 (p_h = alpha p_h / alpha), so that the
#: Hertz contact stays small against the radius (b/R = 4 p_h/E' = 0.1).
PIEZO = 2.0e-8
E_PRIME = 2.2e11
HERTZ_MODULUS_RATIO = 40.0
#: Variants of the maps: (viscosity law, slide-to-roll ratio (u1 - u2)/u_m).
VARIANTS = (("barus", 0.0), ("roelands", 0.0), ("barus", 0.5), ("barus", 2.0))
#: Acceptance targets (Barus, pure rolling maps).
LINE_TARGET = 0.97
POINT_TARGET = 0.95
RIGID_RATIOS = (0.5, 0.9, 0.97, 1.03, 1.2, 2.0)
STORE = "stability_atlas.sqlite"


# --- scenes ------------------------------------------------------------------------------
def _e_prime_for(alpha_ph: float) -> float:
    """E' [Pa]: E_PRIME, or HERTZ_MODULUS_RATIO p_h where that is larger."""
    return max(E_PRIME, HERTZ_MODULUS_RATIO * alpha_ph / PIEZO)


def _line_alpha_ph(M: float, L: float) -> float:
    return L * math.sqrt(M / (2.0 * math.pi))     # Moes: alpha p_h = L sqrt(M / 2 pi)


def _point_alpha_ph(M: float, L: float) -> float:
    if L == 0:
        return 0.0
    d = units.point_scene_parameters_from_moes(M, L)
    return units.moes_point(d["force"], d["rx"], d["ry"], d["e_prime"], d["viscosity"],
                            d["mean_speed"], d["piezo"])["alpha_ph"]


def _with_kinematics(d: dict, u_m: float, law: str, srr: float) -> dict:
    d["lubricant"]["viscosity_law"] = law
    d["kinematics"] = {"u1": u_m * (1.0 + srr / 2.0), "u2": u_m * (1.0 - srr / 2.0)}
    return d


def line_scene(M: float, L: float, law: str = "barus", srr: float = 0.0) -> Scene:
    """Elastic line scene realising Moes (M, L) (L = 0: isoviscous), default mesh."""
    if L > 0:
        par = units.line_scene_from_moes(M, L, piezo=PIEZO,
                                         e_prime=_e_prime_for(_line_alpha_ph(M, L)))
    else:
        par = units.line_scene_from_moes(M, 1.0)   # W, U do not depend on alpha
        par["piezo"] = 0.0
    d = {"title": f"line M={M:.4g} L={L:.3g}",
         "contact": {"kind": "line", "rx": par["radius"]},
         "materials": {"reduced_modulus": par["e_prime"]},
         "lubricant": {"viscosity": par["viscosity"], "piezo": par["piezo"]},
         "load": {"force": par["load_per_length"]}}
    if L == 0:
        law = "constant"   # isoviscous: no pressure-viscosity law
    return Scene.from_dict(_with_kinematics(d, par["mean_speed"], law, srr))


def point_scene(M: float, L: float, law: str = "barus", srr: float = 0.0, *,
                ry_over_rx: float = 1.0, nodes: int = POINT_NODES) -> Scene:
    """Elastic point scene realising Moes (M, L) on nodes^2 (solver defaults otherwise)."""
    rx = 0.01
    if L > 0:
        d = units.point_scene_parameters_from_moes(M, L, rx=rx, ry=rx * ry_over_rx,
                                                   piezo=PIEZO,
                                                   e_prime=_e_prime_for(_point_alpha_ph(M, L)))
    else:
        d = units.point_scene_parameters_from_moes(M, 1.0, rx=rx, ry=rx * ry_over_rx)
        d["piezo"] = 0.0
    s = {"title": f"point M={M:.4g} L={L:.3g} ry/rx={ry_over_rx:g}",
         "contact": {"kind": "point", "rx": d["rx"], "ry": d["ry"]},
         "materials": {"reduced_modulus": d["e_prime"]},
         "lubricant": {"viscosity": d["viscosity"], "piezo": d["piezo"]},
         "load": {"force": d["force"]}, "mesh": {"nodes": [nodes, nodes]}}
    if L == 0:
        law = "constant"   # isoviscous: no pressure-viscosity law
    return Scene.from_dict(_with_kinematics(s, d["mean_speed"], law, srr))


def _physical_scene(kind: str, u_m: float) -> Scene:
    """Steel cylinder (1e5 N/m) or ball (100 N), eta0 = 0.01 Pa s, alpha = 2e-8 1/Pa."""
    contact = {"kind": kind, "rx": 0.01} | ({"ry": 0.01} if kind == "point" else {})
    d = {"title": f"{kind} at u_m = {u_m:g} m/s", "contact": contact,
         "materials": {"reduced_modulus": 2.2e11},
         "lubricant": {"viscosity": 0.01, "piezo": PIEZO},
         "kinematics": {"u1": u_m, "u2": u_m},
         "load": {"force": 1e5 if kind == "line" else 100.0}}
    if kind == "point":
        d["mesh"] = {"nodes": [POINT_NODES, POINT_NODES]}
    return Scene.from_dict(d)


def rigid_scene(kind: str, cavitation: str, ratio: float) -> Scene:
    """Rigid scene (gap 1 um, R = 10 mm, eta0 = 0.1 Pa s, u_m = 1 m/s) whose Barus alpha
    puts it at alpha q_max = ``ratio`` of the closed form (Kapitsa for ``cavitation =
    "none"``, Martin for a line with ``"reynolds"``); alpha <= 2e-7 1/Pa."""
    h0, r, eta, u = 1e-6, 0.01, 0.1, 1.0
    if cavitation == "reynolds":
        q_max = float(analytic.martin_max_reduced(h0, r, eta, u))
    elif kind == "line":
        q_max = float(analytic.kapitsa_line_max_reduced(h0, r, eta, u))
    else:
        a = 1.0 / (2.0 * r)
        q_max = float(analytic.kapitsa_point_max_reduced(h0, a, a, eta, u))
    piezo = ratio / q_max
    contact = {"kind": kind, "rx": r} | ({"ry": r} if kind == "point" else {})
    d = {"title": f"rigid {kind} {cavitation} alpha q_max = {ratio:g}", "contact": contact,
         "lubricant": {"viscosity": eta, "piezo": piezo},
         "kinematics": {"u1": u, "u2": u}, "load": {"gap": h0},
         "model": {"elasticity": "rigid", "cavitation": cavitation}}
    return Scene.from_dict(d)


def _m_for_point_alpha_ph(target: float, L: float) -> float:
    """M of a circular contact with alpha p_h = ``target`` at ``L`` (bisection in log M)."""
    lo, hi = 0.0, 6.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _point_alpha_ph(10**mid, L) < target else (lo, mid)
    return 10 ** (0.5 * (lo + hi))


def atlas_cases(quick: bool = False) -> list[dict]:
    """Every case of the atlas: a dict of labels plus ``builder`` (a zero-argument scene
    factory) and ``expected`` (``success`` or ``no_solution``)."""
    out: list[dict] = []

    def add(family, kind, builder, expected="success", **labels):
        row = {"family": family, "kind": kind, "M": math.nan, "L": math.nan,
               "law": "barus", "srr": 0.0, "ry_over_rx": 1.0 if kind == "point" else math.nan,
               "alpha_ph": math.nan, "speed": math.nan, "ratio": math.nan,
               "cavitation": "reynolds", "expected": expected}
        row.update(labels)
        row["builder"] = builder
        out.append(row)

    line_m, point_m, map_l = LINE_M, POINT_M, MAP_L
    if quick:
        line_m, point_m, map_l = (LINE_M[0], LINE_M[6], LINE_M[-1]), (POINT_M[5],), (MAP_L[3],)
    for law, srr in VARIANTS:
        sub = (law, srr) != ("barus", 0.0)
        if quick and sub:
            continue
        for L in map_l:
            for M in line_m:
                add("line_map", "line", lambda M=M, L=L, law=law, srr=srr:
                    line_scene(M, L, law, srr), M=M, L=L, law=law, srr=srr,
                    alpha_ph=_line_alpha_ph(M, L))
        pm = point_m[::2] if sub else point_m
        pl = map_l[::2] if sub else map_l
        for L in pl:
            for M in pm:
                add("point_map", "point", lambda M=M, L=L, law=law, srr=srr:
                    point_scene(M, L, law, srr), M=M, L=L, law=law, srr=srr,
                    alpha_ph=_point_alpha_ph(M, L))
    for k in ((0.2, 20.0) if quick else (0.2, 0.5, 2.0, 5.0, 10.0, 20.0)):
        add("ellipse", "point", lambda k=k: point_scene(100.0, 10.0, ry_over_rx=k),
            M=100.0, L=10.0, ry_over_rx=k)
    for target in ((100.0,) if quick else (40.0, 60.0, 80.0, 100.0)):
        m_line = 2.0 * math.pi * (target / 10.0) ** 2
        add("high_pressure", "line", lambda m=m_line: line_scene(m, 10.0), M=m_line, L=10.0,
            alpha_ph=target)
        m_point = _m_for_point_alpha_ph(target, 20.0)
        add("high_pressure", "point", lambda m=m_point: point_scene(m, 20.0), M=m_point,
            L=20.0, alpha_ph=target)
    for family, ms in (("near_rigid", (0.5, 1.0, 2.0)), ("light_load", (0.01, 0.03, 0.1, 0.3))):
        for M in (ms[-1:] if quick else ms):
            for L in ((5.0,) if quick else (0.0, 5.0)):
                add(family, "line", lambda M=M, L=L: line_scene(M, L), M=M, L=L,
                    alpha_ph=_line_alpha_ph(M, L))
                add(family, "point", lambda M=M, L=L: point_scene(M, L), M=M, L=L,
                    alpha_ph=_point_alpha_ph(M, L))
    for u in ((1e-4,) if quick else (1e-3, 1e-4, 1e-5, 1e-6)):
        for kind in ("line", "point"):
            add("low_speed", kind, lambda kind=kind, u=u: _physical_scene(kind, u), speed=u)
    rigid = [("line", "none"), ("line", "reynolds"), ("point", "none")]
    for kind, cav in rigid[:1] if quick else rigid:
        for ratio in ((0.9, 1.2) if quick else RIGID_RATIOS):
            add("rigid_limit", kind, lambda kind=kind, cav=cav, ratio=ratio:
                rigid_scene(kind, cav, ratio), ratio=ratio, cavitation=cav,
                expected="success" if ratio < 1.0 else "no_solution")
    return out


# --- running -----------------------------------------------------------------------------
def _labels(case: dict) -> dict:
    """Store parameter columns of a case (finite numbers and strings only)."""
    keep = ("family", "M", "L", "law", "srr", "ry_over_rx", "speed", "ratio",
            "cavitation")
    out = {k: case[k] for k in keep
           if not (isinstance(case[k], float) and math.isnan(case[k]))}
    out["contact"] = case["kind"]     # "kind" is a column of the run store
    return out


def _non_finite(value, path: str = "") -> list[str]:
    """Paths of NaN/inf numbers anywhere in a (nested) summary."""
    if isinstance(value, float):
        return [] if math.isfinite(value) else [path or "<value>"]
    if isinstance(value, dict):
        return [p for k, v in value.items() for p in _non_finite(v, f"{path}.{k}".lstrip("."))]
    if isinstance(value, (list, tuple)):
        return [p for i, v in enumerate(value) for p in _non_finite(v, f"{path}[{i}]")]
    return []


def _read_summary(folder: Path | None) -> tuple[dict | None, list[str]]:
    """The run's summary.json (NaN/Infinity tokens allowed while reading, then reported)."""
    if folder is None or not (folder / "summary.json").is_file():
        return None, []
    data = json.loads((folder / "summary.json").read_text())
    return data, _non_finite(data)


def run_atlas(cases: list[dict], store: Path, *, workers: int | None = None,
              scheduler=None, retry_failed: bool = False) -> tuple[list[dict], int]:
    """Solve the cases as one sweep into ``store``; return (records, cases solved now)."""
    from bearing_fem.io import read_result
    from bearing_fem.sweep import Case, RunStore, sweep

    sweep_cases, by_hash, records = [], {}, []
    for case in cases:
        try:
            scene = case["builder"]()
        except SceneError as exc:   # an input the scene refuses is an explicit outcome too
            case["status"], case["message"] = "invalid_scene", str(exc)
            continue
        c = Case(_labels(case), scene)
        case["hash"] = c.hash
        if c.hash not in by_hash:
            by_hash[c.hash] = c
            sweep_cases.append(c)
    report = sweep(sweep_cases, store=store, workers=workers, scheduler=scheduler,
                   retry_failed=retry_failed, progress=True)
    with RunStore(store) as s:
        stored = {r["hash"]: r for r in s.rows()}
        paths = {h: s.resolve(r["result_path"]) if r.get("result_path") else None
                 for h, r in stored.items()}
    for case in cases:
        rec = {k: v for k, v in case.items() if k != "builder"}
        h = case.get("hash")
        row = stored.get(h) if h else None
        if row is not None:
            folder = paths.get(h)
            summary, bad = _read_summary(folder)
            steps = []
            h5 = folder / "result.h5" if folder is not None else None
            if h5 is not None and h5.is_file():
                steps = read_result(h5)["continuation"]
            err = json.loads(row["error_estimate"]) if row.get("error_estimate") else None
            rec.update(status=row["status"], message=row["message"],
                       success=bool(row["success"]),
                       newton_iterations=row.get("newton_iterations"),
                       continuation_steps=sum(1 for st in steps if float(st[0]) < 1.0),
                       solver_stages=len(steps),
                       wall_time_s=row.get("wall_time_s"),
                       error_h_central=(err or {}).get("h_central"),
                       h_central=row.get("h_central"), h_min=row.get("h_min"),
                       p_max=row.get("p_max"), dofs=row.get("dofs"),
                       non_finite=bad + _non_finite({k: v for k, v in row.items()
                                                     if isinstance(v, float)}),
                       summary_checked=summary is not None)
        else:
            rec.setdefault("status", "not_run")
            rec.setdefault("message", "no row in the store (run the atlas again)")
            rec.update(success=False, newton_iterations=None, continuation_steps=None,
                       solver_stages=None, wall_time_s=None, error_h_central=None,
                       h_central=None, h_min=None, p_max=None, dofs=None, non_finite=[],
                       summary_checked=False)
        if rec["expected"] == "no_solution":
            rec["ok"] = rec["status"] == "no_solution"
        else:
            rec["ok"] = bool(rec["success"])
        records.append(rec)
    return records, report.ran


def _rate(recs: list[dict]) -> dict:
    n = len(recs)
    ok = sum(r["ok"] for r in recs)
    return {"cases": n, "ok": ok, "rate": ok / n if n else math.nan}


def summarise(records: list[dict]) -> dict:
    """Success rates per family and the acceptance numbers."""
    def sel(family, law="barus", srr=0.0, max_aph=math.inf):
        return [r for r in records if r["family"] == family and r["law"] == law
                and r["srr"] == srr and not (r["alpha_ph"] > max_aph)]

    out = {"line_map": _rate(sel("line_map")), "point_map": _rate(sel("point_map")),
           "line_map_aph40": _rate(sel("line_map", max_aph=40.0)),
           "point_map_aph40": _rate(sel("point_map", max_aph=40.0)),
           "line_map_aph100": _rate(sel("line_map", max_aph=100.0)),
           "point_map_aph100": _rate(sel("point_map", max_aph=100.0))}
    groups: dict = {}
    for r in records:
        key = (r["family"], r["kind"], r["law"], r["srr"])
        groups.setdefault(key, []).append(r)
    out["groups"] = [{"family": f, "kind": k, "law": law, "srr": srr, **_rate(g),
                      "newton_iterations_max": max((x["newton_iterations"] or 0) for x in g),
                      "wall_time_s_total": sum((x["wall_time_s"] or 0.0) for x in g)}
                     for (f, k, law, srr), g in groups.items()]
    out["all"] = _rate(records)
    out["failures"] = [r for r in records if not r["ok"]]
    out["non_finite"] = [(r["family"], r["M"], r["L"], r["non_finite"])
                         for r in records if r["non_finite"]]
    out["line_target_met"] = out["line_map"]["rate"] >= LINE_TARGET
    out["point_target_met"] = out["point_map"]["rate"] >= POINT_TARGET
    out["aph40_all_ok"] = (out["line_map_aph40"]["ok"] == out["line_map_aph40"]["cases"]
                           and out["point_map_aph40"]["ok"] == out["point_map_aph40"]["cases"])
    return out


# --- tables and figures ------------------------------------------------------------------
COLUMNS = ("family", "kind", "M", "L", "alpha_ph", "law", "srr", "ry_over_rx", "speed",
           "cavitation", "ratio", "expected", "status", "ok", "newton_iterations",
           "continuation_steps", "solver_stages", "wall_time_s", "error_h_central",
           "h_central", "h_min", "p_max", "dofs", "message")


def _fmt(v) -> str:
    if v is None:
        return ""
    if isinstance(v, float):
        return "" if math.isnan(v) else f"{v:.4g}"
    return str(v)


def _atomic_write(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def write_tables(outdir: Path, records: list[dict], summary: dict) -> None:
    tmp = outdir / ".stability_atlas.csv.tmp"
    with open(tmp, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(COLUMNS)
        for r in records:
            w.writerow([_fmt(r.get(c)) for c in COLUMNS])
    os.replace(tmp, outdir / "stability_atlas.csv")
    md = ["| family | kind | law | slide-to-roll | cases | ok | rate % | max Newton its | "
          "solve time s |", "|---|---|---|---|---|---|---|---|---|"]
    for g in summary["groups"]:
        md.append(f"| {g['family']} | {g['kind']} | {g['law']} | {g['srr']:g} | {g['cases']} | "
                  f"{g['ok']} | {100 * g['rate']:.1f} | {g['newton_iterations_max']} | "
                  f"{g['wall_time_s_total']:.1f} |")
    acc = ["", "| acceptance set (Barus, pure rolling) | cases | ok | rate % |",
           "|---|---|---|---|"]
    for key, name in (("line_map", "line map, all"), ("line_map_aph100", "line map, alpha p_h <= 100"),
                      ("line_map_aph40", "line map, alpha p_h <= 40"),
                      ("point_map", "circular map, all"),
                      ("point_map_aph100", "circular map, alpha p_h <= 100"),
                      ("point_map_aph40", "circular map, alpha p_h <= 40")):
        s = summary[key]
        acc.append(f"| {name} | {s['cases']} | {s['ok']} | {100 * s['rate']:.1f} |")
    fail = ["", "| family | kind | M | L | alpha p_h | law | slide-to-roll | extra | expected | "
            "status | Newton its | message |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in summary["failures"]:
        extra = "; ".join(f"{k} {_fmt(r[k])}" for k in ("ry_over_rx", "speed", "ratio")
                          if _fmt(r[k]) and not (k == "ry_over_rx" and r[k] == 1.0))
        if r["family"] == "rigid_limit":
            extra += f"; cavitation {r['cavitation']}"
        msg = str(r["message"]).replace("|", "/").replace("\n", " ")
        fail.append(f"| {r['family']} | {r['kind']} | {_fmt(r['M'])} | {_fmt(r['L'])} | "
                    f"{_fmt(r['alpha_ph'])} | {r['law']} | {r['srr']:g} | {extra} | "
                    f"{r['expected']} | {r['status']} | {_fmt(r['newton_iterations'])} | "
                    f"{msg} |")
    if not summary["failures"]:
        fail.append("| (none) |" + " |" * 11)
    text = "\n".join(md + acc + fail) + "\n"
    _atomic_write(outdir / "stability_atlas.md", text)
    js = {k: v for k, v in summary.items()}
    js["records"] = records
    _atomic_write(outdir / "stability_atlas.json", json.dumps(js, indent=1, default=str))


def plot_maps(outdir: Path, records: list[dict]) -> list[str]:
    """One figure per contact kind: a panel per variant, Newton iterations coloured,
    failures crossed, refused scenes boxed, alpha p_h = 40 and 100 drawn."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    written = []
    for kind, family, aph in (("line", "line_map", _line_alpha_ph),
                              ("point", "point_map", _point_alpha_ph)):
        recs = [r for r in records if r["family"] == family]
        variants = [v for v in VARIANTS if any((r["law"], r["srr"]) == v for r in recs)]
        if not variants:
            continue
        fig, axes = plt.subplots(1, len(variants), figsize=(3.6 * len(variants) + 1.0, 3.6),
                                 squeeze=False, sharey=True, constrained_layout=True)
        for ax, (law, srr) in zip(axes[0], variants):
            rs = [r for r in recs if (r["law"], r["srr"]) == (law, srr)]
            ok = [r for r in rs if r["ok"]]
            bad = [r for r in rs if not r["ok"] and r["status"] != "invalid_scene"]
            refused = [r for r in rs if r["status"] == "invalid_scene"]
            sc = ax.scatter([r["M"] for r in ok], [r["L"] for r in ok],
                            c=[r["newton_iterations"] or 0 for r in ok], cmap="viridis",
                            s=40, vmin=0, vmax=80)
            ax.scatter([r["M"] for r in bad], [r["L"] for r in bad], marker="x", c="red",
                       s=60, label="failed")
            ax.scatter([r["M"] for r in refused], [r["L"] for r in refused], marker="s",
                       facecolors="none", edgecolors="grey", s=50, label="scene refused")
            ms = np.logspace(math.log10(min(r["M"] for r in rs)),
                             math.log10(max(r["M"] for r in rs)), 60)
            for level, style in ((40.0, "--"), (100.0, ":")):
                ls = [level / max(aph(m, 1.0), 1e-300) for m in ms]   # alpha p_h ~ L
                ax.plot(ms, ls, "k" + style, lw=0.8, label=f"alpha p_h = {level:g}")
            ax.set_xscale("log")
            ax.set_ylim(-1, 26)
            ax.set_xlabel("Moes M")
            ax.set_title(f"{kind}: {law}, slide-to-roll {srr:g}", fontsize=9)
        axes[0][0].set_ylabel("Moes L")
        axes[0][0].legend(fontsize=6, loc="lower left", framealpha=0.9)
        fig.colorbar(sc, ax=axes[0].tolist(), label="Newton iterations")
        path = outdir / f"stability_{kind}_map.png"
        tmp = outdir / f".stability_{kind}_map.tmp.png"
        fig.savefig(tmp, dpi=110)
        plt.close(fig)
        os.replace(tmp, path)
        written.append(path.name)
    return written


def main(outdir: str | Path = "out/stability_atlas", quick: bool = False, *,
         workers: int | None = None, scheduler=None, retry_failed: bool = False) -> dict:
    """Run (or resume) the atlas; write its tables and maps; return its numbers.

    ``workers`` (local pool size) and ``scheduler`` (a Dask address or client) say where
    the cases run; ``retry_failed`` solves the stored failures again (after a solver
    change).

    Returns
    -------
    dict
        ``summary`` (rates per family, acceptance numbers, failures), ``records`` (every
        case), ``solved_now`` (cases solved by this call; 0 when the store had them all),
        ``wall_time_s`` and ``figures``.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    cases = atlas_cases(quick)
    records, solved = run_atlas(cases, outdir / STORE, workers=workers, scheduler=scheduler,
                                retry_failed=retry_failed)
    summary = summarise(records)
    write_tables(outdir, records, summary)
    figures = plot_maps(outdir, records)
    wall = time.perf_counter() - t0
    print(f"stability atlas: {summary['all']['ok']} of {summary['all']['cases']} ok; line map "
          f"{100 * summary['line_map']['rate']:.1f}%, circular map "
          f"{100 * summary['point_map']['rate']:.1f}% (Barus, pure rolling); "
          f"{len(summary['failures'])} failures; {solved} solved now; {wall:.0f} s")
    return {"summary": summary, "records": records, "solved_now": solved,
            "wall_time_s": wall, "figures": figures}


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/stability_atlas")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--workers", type=int, default=None)
    parser.add_argument("--scheduler", default=None)
    parser.add_argument("--retry-failed", action="store_true",
                        help="solve the cases stored as failed again")
    ns = parser.parse_args()
    main(ns.outdir, quick=ns.quick, workers=ns.workers, scheduler=ns.scheduler,
         retry_failed=ns.retry_failed)

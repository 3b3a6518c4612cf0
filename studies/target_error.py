"""Does ``[mesh] target_error`` deliver what it promises?

Question
--------
A user who sets ``mesh.target_error = t`` asks for results whose estimated relative
discretisation error of friction force, heat power, h_min and h_central is at most t:
the contact is solved again on grids of half the spacing until its estimates meet t or
the grid reaches its cap (``bearing_fem.contacts.refine``). Is the *true* error then
within t? And what does it cost?

Scene
-----
The line map (Moes M 5-1000, L 0-20, alpha p_h <= 100: 42 cases) and the circular map
(M 20-500, L 5-20, alpha p_h <= 40: 13 cases) of ``studies/error_estimates.py``: the
line cases from the solver's default grids, the circular ones from 129^2. Targets: 1 %
and 0.2 % (lines), 5 % and 1 % (circular). The truth, as in that study, is the change of
each quantity to a solve on the grid twice finer than the final one (up to 8001 line
nodes and 513^2 point nodes: a result already on 513^2 has no truth here, and is
counted apart).

Expected outcome
----------------
The estimate is conservative on most map cases (docs/accuracy.md: 52 of its 65 misses
lie above the change), so a met target should hold: the change within t in nearly every
case-quantity. Reported per map and target: ``within`` (change <= t), ``within_3x``
(change <= 3 t), ``met`` (the solver says every estimate meets t), ``no_truth``, and the
cost (``seconds``: all solves of the target run; ``default_seconds``: the one solve on the
starting grid).

Run ``python studies/target_error.py OUT [--quick]`` (full: about 10 minutes on 2 cores;
quick: two line cases and one circular case at the looser target, about a minute);
writes ``cases.csv`` and ``summary.json`` into OUT.
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import sys
import time
from dataclasses import replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from bearing_fem.contacts.refine import (TARGET_ERROR_MAX_POINT_NODES,  # noqa: E402
                                         TARGET_ERROR_QUANTITIES, finer_grid)

#: Targets per map kind (looser first; the quick run uses the first only).
TARGETS = {"line": (0.01, 0.002), "point": (0.05, 0.01)}
#: Starting grid of the circular cases (per direction; the map studies' default).
POINT_NODES = 129
#: Finest line grid of a truth solve [nodes] (the refinement's own cap: a result on 8001
#: nodes has no truth here).
MAX_TRUTH_LINE_NODES = 8001


def scenes(kind: str, quick: bool):
    """(M, L, scene) of the map cases of ``kind`` ("line" or "point")."""
    import error_estimates as ee

    if kind == "line":
        return [(M, L, ee.line_scene(M, L)) for M, L in ee.line_cases(quick)]
    return [(M, L, ee.point_scene(M, L, POINT_NODES)) for M, L in ee.point_cases(quick)]


def run_case(kind: str, M: float, L: float, scene, target: float) -> dict:
    """One map case held to ``target``: the refinement, its truth and its cost."""
    t0 = time.perf_counter()
    first = bf.solve(scene)
    default_s = time.perf_counter() - t0
    held = bf.solve(replace(scene, mesh=replace(scene.mesh, target_error=target)))
    ref = held.refinement or {}
    row = {"kind": kind, "M": M, "L": L, "target": target, "status": held.status,
           "grids": " ".join(ref.get("grids", [])), "met": ref.get("met"),
           "seconds": held.wall_time_s, "default_seconds": default_s,
           "first_status": first.status}
    truth = None
    if held.success:
        finer, nodes = finer_grid(scene, held)
        n = max(nodes) if isinstance(nodes, tuple) else nodes
        cap = TARGET_ERROR_MAX_POINT_NODES if kind == "point" else MAX_TRUTH_LINE_NODES
        if n <= cap:
            truth = bf.solve(finer)
            row["truth_status"] = truth.status
            row["truth_seconds"] = truth.wall_time_s
    est = held.error_estimate or {}
    for q in TARGET_ERROR_QUANTITIES:
        row[f"{q}_estimate"] = est.get(q)
        change = None
        if truth is not None and truth.success:
            a, b = held.quantities.get(q), truth.quantities.get(q)
            if a is not None and b:
                change = abs(a / b - 1.0)
        row[f"{q}_change"] = change
    return row


def summarise(rows: list[dict]) -> dict:
    """Shares per map kind and target (``within``, ``within_3x`` over case-quantities
    with a truth; ``met``, ``no_truth`` over cases) and the cost."""
    out: dict = {}
    for kind, targets in TARGETS.items():
        for t in targets:
            sel = [r for r in rows if r["kind"] == kind and r["target"] == t]
            if not sel:
                continue
            changes = [r[f"{q}_change"] for r in sel for q in TARGET_ERROR_QUANTITIES
                       if r[f"{q}_change"] is not None]
            worst = [r for r in sel if any(r[f"{q}_change"] is not None
                                           and r[f"{q}_change"] > t
                                           for q in TARGET_ERROR_QUANTITIES)]
            out[f"{kind} {t:g}"] = {
                "cases": len(sel),
                "pairs": len(changes),
                "within": sum(c <= t for c in changes) / len(changes) if changes else None,
                "within_3x": (sum(c <= 3 * t for c in changes) / len(changes)
                              if changes else None),
                "largest_change": max(changes, default=None),
                "cases_over": [f"M={r['M']:g} L={r['L']:g}" for r in worst],
                "met": sum(bool(r["met"]) for r in sel),
                "no_truth": sum(all(r[f"{q}_change"] is None
                                    for q in TARGET_ERROR_QUANTITIES) for r in sel),
                "refined": sum(len(r["grids"].split()) > 1 for r in sel),
                "seconds": sum(r["seconds"] for r in sel),
                "default_seconds": sum(r["default_seconds"] for r in sel),
            }
    return out


def main(outdir: str | Path = "out/target_error", quick: bool = False) -> dict:
    """Run every map case at every target; write ``cases.csv`` and ``summary.json``;
    return ``{"rows": [...], "summary": {...}}``."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    rows = []
    for kind, targets in TARGETS.items():
        for M, L, scene in scenes(kind, quick):
            for t in targets[:1] if quick else targets:
                rows.append(run_case(kind, M, L, scene, t))
                r = rows[-1]
                print(f"{kind} M={M:g} L={L:g} target {t:g}: {r['grids']} met={r['met']} "
                      + " ".join(f"{q} {r[f'{q}_change'] or math.nan:.1e}"
                                 for q in TARGET_ERROR_QUANTITIES), flush=True)
    summary = summarise(rows)
    summary["seconds"] = time.perf_counter() - t0
    keys = list(dict.fromkeys(k for r in rows for k in r))
    with open(outdir / "cases.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    (outdir / "summary.json").write_text(json.dumps(summary, indent=1), encoding="utf-8")
    return {"rows": rows, "summary": summary}


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/target_error")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    res = main(args.outdir, quick=args.quick)
    print(json.dumps(res["summary"], indent=1))

"""Circular EHL films against an independent multigrid solver of the same equations.

Question
--------
The circular map (``studies/point_ehl_map.py``, docs/point.md) misses the Hamrock-Dowson
(1977) 20% band in 6 of 13 cases while h_c stays within 5% of Nijenbanning-Venner-Moes.
Is that a property of the model (isothermal, Barus, incompressible, Reynolds cavitation,
elastic half-space) or of this package's discretisation? An independent, established
solver of the same dimensionless problem answers it: the full-multigrid finite-difference
code for the circular contact of Venner and Lubrecht, *Multilevel Methods in
Lubrication* (Elsevier, 2000), with multilevel multi-integration for the deformation.
It solves on X in [-4.5, 1.5], Y in [-3, 3] (Hertz radii); the solves here use the same
domain (the default one here has a longer inlet at low M and high L) and the same node
spacing: 512 x 512 intervals there (6 levels) is 513^2 nodes here, 256 x 256 (5 levels)
is 257^2, 128 x 128 (4 levels) is 129^2; the finest level where the multigrid program
gives a result is used.

That program is not part of this package (it is printed in the book); pass the path of
its compiled executable with ``--fmg``. It reads ``M L levels startlevel cycles
cycletype`` on standard input and prints, per relaxation of the output level,
``k=.., resn=.., g=.., h0=..`` and at the end a table ``Level Hm Hm(Moes) Hc Hc(Moes)
Hc(Moes)(p_x=0)``. It needs per-case settings (start level, cycles, V or W cycle): the
study tries :data:`FMG_LADDER` in order and keeps the first result that passes
:func:`fmg_accepted` (finite, final force-balance residual |g| below 1% of its 2 pi/3
load term, final mean Reynolds residual below :data:`FMG_MAX_RESIDUAL`), and reports how
many settings failed before it. A case where no setting passes is reported as such.

Scene
-----
:func:`point_ehl_map.moes_scene` (the map's scenes: Barus, incompressible, Reynolds
cavitation, half-space, pure rolling) on the multigrid domain and grid; the films compared in
Moes units H = h / (rx sqrt(U_sum)) (docs/theory.md section 13): H_min (minimum over the grid) and
H_c (at the contact centre), with Hamrock-Dowson (mean speed) in the same units.

Expected outcome
----------------
Where the multigrid code converges, both solvers give the same films to a few percent,
so the Hamrock-Dowson deviations of the two agree: the misses are the model's, not the
discretisation's.

Run ``python studies/point_fmg_crosscheck.py OUTDIR --fmg PATH`` (about 20 minutes on
one core: 7.5 minutes of solves here, mostly 513^2, and the multigrid settings tried).
"""
from __future__ import annotations

import json
import math
import re
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from point_ehl_map import _formulas, map_cases, moes_scene  # noqa: E402

from bearing_fem.contacts.point import solve_point  # noqa: E402

#: Settings tried for the multigrid program, in order: (start level, cycles per level,
#: cycle type 1 = V, 2 = W). Six W cycles close the force balance best (|g| ~ 1e-6);
#: fewer cycles or V cycles are the fall-backs.
FMG_LADDER = tuple((start, cycles, kind) for cycles in (6, 3)
                   for start in (1, 2, 3) for kind in (2, 1))
#: Multigrid levels tried, finest first: 6 gives 512 x 512 intervals (the node spacing of
#: 513^2 here), 5 gives 256 x 256 (257^2 here), 4 gives 128 x 128 (129^2 here). The solve
#: here uses the matching grid.
FMG_LEVELS = (6, 5, 4)
#: Acceptance of a multigrid result: |g| below this fraction of its load term 2 pi/3
#: (the force balance; a load error e moves the films by about 0.07 e, the load exponent
#: of the film fits, so 5% is 0.4% in film), and the mean Reynolds residual of the last
#: relaxation below FMG_MAX_RESIDUAL (converged runs end at 1e-5..1e-2, diverged ones at
#: 1 or more).
FMG_MAX_FORCE_ERROR = 0.05
FMG_MAX_RESIDUAL = 0.05
#: The multigrid program's domain, in Hertz radii; the solve here uses the same.
FMG_X_RANGE = (-4.5, 1.5)
FMG_Y_RANGE = (-3.0, 3.0)
FMG_TIMEOUT_S = 600.0

_RELAX = re.compile(r"k=\s*(\d+), resn=\s*(\S+), g=\s*(\S+), h0=\s*(\S+)")
_TABLE = re.compile(r"^\s*(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$", re.M)


def _float(text: str) -> float:
    try:
        return float(text)
    except ValueError:          # "-nan", "inf" spellings of C printf
        return math.nan


def parse_fmg_output(text: str, levels: int) -> dict:
    """Films and final residuals of ``levels`` from the multigrid program's output.

    Returns a dict with ``H_min``, ``H_c`` (Moes units, NaN where missing),
    ``H_min_coarser``, ``H_c_coarser`` (the same run's films on the next coarser level,
    twice the spacing), ``residual`` and ``force_residual`` (the last relaxation of that
    level, NaN where missing) and ``relaxations`` (how many were printed for that level).
    """
    relax = [m for m in _RELAX.findall(text) if int(m[0]) == levels]
    rows = {int(r[0]): r for r in _TABLE.findall(text)}
    row, coarser = rows.get(levels), rows.get(levels - 1)
    return {"H_min": _float(row[2]) if row else math.nan,
            "H_c": _float(row[4]) if row else math.nan,
            "H_min_coarser": _float(coarser[2]) if coarser else math.nan,
            "H_c_coarser": _float(coarser[4]) if coarser else math.nan,
            "residual": _float(relax[-1][1]) if relax else math.nan,
            "force_residual": _float(relax[-1][2]) if relax else math.nan,
            "relaxations": len(relax)}


def fmg_accepted(parsed: dict) -> bool:
    """True for a finite, converged multigrid result (see :data:`FMG_MAX_FORCE_ERROR`)."""
    values = (parsed["H_min"], parsed["H_c"], parsed["residual"], parsed["force_residual"])
    return (all(math.isfinite(v) for v in values) and parsed["H_min"] > 0.0
            and abs(parsed["force_residual"]) < FMG_MAX_FORCE_ERROR * 2.0 * math.pi / 3.0
            and parsed["residual"] < FMG_MAX_RESIDUAL)


def run_fmg(program: str | Path, M: float, L: float, levels: int = FMG_LEVELS[0],
            ladder: tuple = FMG_LADDER) -> dict:
    """Run the multigrid program through ``ladder``; the first accepted result, or None.

    The program writes P.dat and H.dat into its working directory: it runs in a
    temporary one.
    """
    tried = []
    for start, cycles, kind in ladder:
        stdin = f"{M:g} {L:g} {levels} {start} {cycles} {kind}\n"
        t0 = time.perf_counter()
        with tempfile.TemporaryDirectory() as work:
            try:
                proc = subprocess.run([str(program)], input=stdin, capture_output=True,
                                      text=True, cwd=work, timeout=FMG_TIMEOUT_S)
                out = proc.stdout
            except subprocess.TimeoutExpired:
                out = ""
        parsed = parse_fmg_output(out, levels)
        parsed.update(start=start, cycles=cycles, cycle="V" if kind == 1 else "W",
                      wall_time_s=time.perf_counter() - t0)
        tried.append(parsed)
        if fmg_accepted(parsed):
            return {"result": parsed, "failed_settings": len(tried) - 1, "tried": tried}
    return {"result": None, "failed_settings": len(tried), "tried": tried}


def _pct(a: float, b: float) -> float:
    return 100.0 * (a / b - 1.0) if (a is not None and b and math.isfinite(a)) else math.nan


def main(outdir: str | Path = "out/point_fmg_crosscheck", fmg: str | Path | None = None,
         nodes: int = 257, cases: list[tuple[float, float]] | None = None,
         levels: tuple[int, ...] = FMG_LEVELS) -> dict:
    """Solve each case with the multigrid program and here; write JSON and a table.

    The multigrid program is tried on ``levels`` (finest first, :data:`FMG_LADDER` on
    each); the solve here uses the node spacing of the level that gave a result, or
    ``nodes`` where none did.
    """
    if fmg is None or not Path(fmg).is_file():
        raise ValueError(f"fmg: the multigrid program {fmg!r} is not a file; pass the path "
                         "of the compiled Venner-Lubrecht circular-contact code (--fmg PATH)")
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    rows = []
    for M, L in cases or map_cases():
        failed = 0
        for lev in levels:
            ref = run_fmg(fmg, M, L, lev)
            failed += ref["failed_settings"]
            if ref["result"]:
                break
        r = ref["result"]
        n = 16 * 2 ** (lev - 1) + 1 if r else nodes      # the multigrid node spacing
        base = moes_scene(M, L, n)
        scene = replace(base, mesh=replace(base.mesh, x_range=FMG_X_RANGE,
                                           y_range=FMG_Y_RANGE))
        t0 = time.perf_counter()
        res = solve_point(scene)
        wall = time.perf_counter() - t0
        f = _formulas(scene)
        h_min_hd, h_c_hd = f["h_min_hd_m"], f["h_central_hd_m"]
        scale = 1.0 / (scene.contact.rx * math.sqrt(f["moes"]["U_sum"]))  # h -> H_Moes
        q = res.quantities
        row = {"M": M, "L": L, "nodes": n, "status": res.status,
               "newton_iterations": res.newton_iterations, "wall_time_s": wall,
               "H_min": q.get("h_min", math.nan) * scale,
               "H_c": q.get("h_central", math.nan) * scale,
               "H_min_hd": h_min_hd * scale, "H_c_hd": h_c_hd * scale,
               "fmg": r, "fmg_levels": lev if r else None, "fmg_failed_settings": failed}
        row["H_min_vs_fmg"] = _pct(row["H_min"], r["H_min"]) if r else math.nan
        row["H_c_vs_fmg"] = _pct(row["H_c"], r["H_c"]) if r else math.nan
        rows.append(row)
        print(f"M={M:g} L={L:g}: here {n}^2 {row['status']} H_min {row['H_min']:.4f} "
              f"H_c {row['H_c']:.4f}; multigrid "
              + (f"{16 * 2 ** (lev - 1)}^2 intervals H_min {r['H_min']:.4f} H_c "
                 f"{r['H_c']:.4f} after {failed} failed settings" if r
                 else f"no accepted result in {failed} settings"), flush=True)
    hd = "Hamrock-Dowson"
    lines = [f"| M | L | grid here | multigrid setting (levels, start, cycles, cycle) | "
             f"settings failed first | multigrid H_min change from half the grid % | "
             f"multigrid H_c change from half the grid % | "
             f"multigrid H_min | multigrid H_c | H_min here | H_c here | H_min here vs "
             f"multigrid % | H_c here vs multigrid % | {hd} H_min | {hd} H_c | multigrid "
             f"H_min vs HD % | here H_min vs HD % | multigrid H_c vs HD % | here H_c vs "
             f"HD % |", "|" + "---|" * 19]
    for w in rows:
        r = w["fmg"]
        fm = (f"{w['fmg_levels']}, {r['start']}, {r['cycles']}, {r['cycle']} | "
              f"{w['fmg_failed_settings']} | {_pct(r['H_min'], r['H_min_coarser']):+.1f} | "
              f"{_pct(r['H_c'], r['H_c_coarser']):+.1f} | "
              f"{r['H_min']:.4f} | {r['H_c']:.4f}") if r else \
            f"none accepted | {w['fmg_failed_settings']} | - | - | - | -"
        lines.append(
            f"| {w['M']:g} | {w['L']:g} | {w['nodes']}^2 | {fm} | {w['H_min']:.4f} | "
            f"{w['H_c']:.4f} | "
            f"{w['H_min_vs_fmg']:+.1f} | {w['H_c_vs_fmg']:+.1f} | {w['H_min_hd']:.4f} | "
            f"{w['H_c_hd']:.4f} | "
            f"{_pct(r['H_min'], w['H_min_hd']) if r else math.nan:+.1f} | "
            f"{_pct(w['H_min'], w['H_min_hd']):+.1f} | "
            f"{_pct(r['H_c'], w['H_c_hd']) if r else math.nan:+.1f} | "
            f"{_pct(w['H_c'], w['H_c_hd']):+.1f} |")
    both = [w for w in rows if w["fmg"]]
    summary = (f"{len(both)} of {len(rows)} cases with an accepted multigrid result; "
               + (f"max |H_min here / multigrid - 1| = "
                  f"{max(abs(w['H_min_vs_fmg']) for w in both):.1f}%, max |H_c here / "
                  f"multigrid - 1| = {max(abs(w['H_c_vs_fmg']) for w in both):.1f}%"
                  if both else "no comparison"))
    table = "\n".join(lines) + "\n\n" + summary
    print(table)
    (outdir / "point_fmg_crosscheck.md").write_text(table + "\n")
    out = {"fmg_levels": list(levels), "cases": rows, "summary": summary}
    (outdir / "point_fmg_crosscheck.json").write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/point_fmg_crosscheck")
    parser.add_argument("--fmg", required=True, help="compiled multigrid program")
    ns = parser.parse_args()
    try:
        main(ns.outdir, fmg=ns.fmg)
    except ValueError as exc:
        sys.exit(f"point_fmg_crosscheck: {exc}")

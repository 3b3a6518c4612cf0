"""Half-space line contacts: SUPG against the upwinded wedge term, error against run time.

Question
    The Reynolds equation of an EHL contact degenerates to pure advection where the
    viscosity is huge, and needs stabilisation. Which of the two stabilisations in
    :mod:`bearing_fem.physics.reynolds` (SUPG on the whole strong residual, or the first-order
    upwinded wedge term, :class:`~bearing_fem.physics.reynolds.UpwindFluxModel`) converges on fine
    grids, at what cost, and do they agree on h_central and h_min?

Scene
    :func:`studies.line_ehl_map.scene_for` at Moes (M, L) = (100, 10) and (20, 5), each
    on 1001, 2001 and 4001 nodes; the solver's grid sequencing and continuation as in
    ``bearing_fem.solve``.

Expected outcome
    Both agree to a small fraction of a per cent where both converge; the upwinded flux
    also converges where SUPG stagnates at the outlet pressure spike.

Run ``python studies/line_stabilisation.py [outdir]``.
"""
from __future__ import annotations

import json
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from bearing_fem.contacts import line as solver  # noqa: E402
from line_ehl_map import scene_for  # noqa: E402

CASES = ((100.0, 10.0), (20.0, 5.0))
GRIDS = (1001, 2001, 4001)


def main(outdir: str | Path = "out/line_stabilisation", quick: bool = False) -> dict:
    """Run both stabilisations on every case and grid; write a table; return the rows."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    grids = GRIDS[:2] if quick else GRIDS
    cases = CASES[:1] if quick else CASES
    rows = []
    saved = solver.HALF_SPACE_STABILISATION
    try:
        for M, L in cases:
            for method in ("supg", "upwind"):
                solver.HALF_SPACE_STABILISATION = method
                for n in grids:
                    t0 = time.perf_counter()
                    r = bf.solve(scene_for(M, L, n))
                    rows.append({"M": M, "L": L, "method": method, "nodes": n,
                                 "status": r.status, "iterations": r.newton_iterations,
                                 "seconds": time.perf_counter() - t0,
                                 "h_central": r.quantities.get("h_central"),
                                 "h_min": r.quantities.get("h_min")})
                    print(_text(rows[-1]), flush=True)
    finally:
        solver.HALF_SPACE_STABILISATION = saved
    # reference: the finest converged upwind solution of each case
    for row in rows:
        ref = [r for r in rows if (r["M"], r["L"]) == (row["M"], row["L"])
               and r["method"] == "upwind" and r["status"] == "converged"]
        if ref and row["status"] == "converged":
            f = max(ref, key=lambda r: r["nodes"])
            row["h_central_vs_finest_upwind"] = row["h_central"] / f["h_central"] - 1.0
            row["h_min_vs_finest_upwind"] = row["h_min"] / f["h_min"] - 1.0
    lines = ["| M | L | stabilisation | nodes | status | Newton its | s | h_c vs finest upwind | "
             "h_min vs finest upwind |", "|" + "---|" * 9]
    for r in rows:
        hc = r.get("h_central_vs_finest_upwind")
        hm = r.get("h_min_vs_finest_upwind")
        lines.append(f"| {r['M']:g} | {r['L']:g} | {r['method']} | {r['nodes']} | {r['status']} | "
                     f"{r['iterations']} | {r['seconds']:.2f} | "
                     f"{'-' if hc is None else f'{100 * hc:+.3f} %'} | "
                     f"{'-' if hm is None else f'{100 * hm:+.3f} %'} |")
    text = "\n".join(lines)
    print(text)
    (outdir / "line_stabilisation.md").write_text(text + "\n")
    (outdir / "line_stabilisation.json").write_text(json.dumps(rows, indent=1))
    return {"rows": rows, "table": text}


def _text(r: dict) -> str:
    return (f"M={r['M']:g} L={r['L']:g} {r['method']:>6} {r['nodes']:>5} {r['status']:>14} "
            f"its {r['iterations']:>3} {r['seconds']:7.2f} s h_c {r['h_central']:.5e} "
            f"h_min {r['h_min']:.5e}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/line_stabilisation")

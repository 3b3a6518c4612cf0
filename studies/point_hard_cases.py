"""Circular EHL cases that a classic multigrid code could not solve without hand tuning.

Question
--------
Does :func:`bearing_fem.contacts.point.solve_point` converge, with its defaults and no per-case
setting, on the three circular cases where a published multigrid EHL code (C, Barus
viscosity) returned NaN or diverged on 512 x 512 unless its coarsest start level was
tuned by hand: M = 200, L = 10; M = 1000, L = 10; M = 50, L = 20? How grid-converged is
h_c, how long does each grid take, and how does h_c compare with
Nijenbanning-Venner-Moes?

Scene
-----
:func:`point_ehl_map.moes_scene` (rx = ry = 10 mm, E' = 2.2e11 Pa, alpha = 2e-8 1/Pa,
Barus, Reynolds cavitation, half-space, pure rolling), each case on 257^2 and 513^2,
each grid solved from scratch (the solver's own grid sequencing 65 -> ... -> n).

Expected outcome
----------------
All converge on both grids; h_c changes by well under 1% from 257^2 to 513^2 and lies
within 10% of NVM (as in the acceptance map, which covers M <= 500).

Run ``python studies/point_hard_cases.py [outdir]`` (about 4 minutes on one core).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from point_ehl_map import run_case  # noqa: E402

#: (M, L) of the three cases.
CASES = ((200.0, 10.0), (1000.0, 10.0), (50.0, 20.0))
GRIDS = (257, 513)


def main(outdir: str | Path = "out/point_hard_cases", quick: bool = False) -> dict:
    """Solve each case on ``GRIDS`` (quick: 65 and 129); write JSON and a markdown table."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    grids = (65, 129) if quick else GRIDS
    cases = []
    for M, L in CASES:
        runs = []
        for n in grids:
            row, _ = run_case(M, L, n)
            runs.append(row)
            print(f"M={M:g} L={L:g} {n}^2: {row['status']}, {row['newton_iterations']} "
                  f"Newton its, {row['wall_time_s']:.1f} s", flush=True)
        coarse, fine = runs[-2], runs[-1]
        cases.append({"M": M, "L": L, "alpha_ph": fine["alpha_ph"], "runs": runs,
                      "converged": all(r["status"] == "converged" for r in runs),
                      "grid_change": fine["h_central_m"] / coarse["h_central_m"] - 1.0,
                      "h_central_vs_nvm": fine["h_central_ratio"] - 1.0})
    lines = ["| M | L | alpha p_h | " + " | ".join(
        f"{n}^2 status | {n}^2 its | {n}^2 s | {n}^2 h_c [nm]" for n in grids)
        + f" | h_c change {grids[0]}^2 -> {grids[1]}^2 % | vs NVM % |",
        "|---|---|---|" + "---|---|---|---|" * len(grids) + "---|---|"]
    for c in cases:
        cells = " | ".join(f"{r['status']} | {r['newton_iterations']} | "
                           f"{r['wall_time_s']:.1f} | {1e9 * r['h_central_m']:.2f}"
                           for r in c["runs"])
        lines.append(f"| {c['M']:g} | {c['L']:g} | {c['alpha_ph']:.1f} | {cells} | "
                     f"{100 * c['grid_change']:+.2f} | {100 * c['h_central_vs_nvm']:+.1f} |")
    table = "\n".join(lines)
    print(table)
    (outdir / "point_hard_cases.md").write_text(table + "\n")
    out = {"grids": list(grids), "cases": cases}
    (outdir / "point_hard_cases.json").write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/point_hard_cases",
         quick="--quick" in sys.argv)

"""Study: the dimensionless Kodnir boundary problem over the Ratner range, by FE.

Question
    Does the FE solver (``bearing_fem.contacts.kodnir.solve``: P1, SUPG, Fischer-Burmeister
    cavitation, flux condition, continuation) solve every case of the grid
    C in {0.6, 1, 5, 10, 40} x B alpha in {0, 4.5, 7, 12} at z_b = 20, where the paper's
    shooting method failed for many (B alpha, C)? What are z_a, k_max, H_min, I and J, and
    how grid-converged are they (relative change from ``n`` nodes to ``2n - 1`` nodes)?

Scene
    Dimensionless; no physical data.

Expected outcome
    All 20 cases succeed; target < 0.1 % change of z_a and k_max between the two grids.

Run ``python studies/kodnir_table.py [outdir] [n]``; ``main`` returns the numbers and
writes ``kodnir_table.json`` and ``kodnir_table.md`` to ``outdir``.
"""
from __future__ import annotations

import json
import sys
import time
from pathlib import Path

from bearing_fem import __version__

from bearing_fem.contacts import kodnir

C_VALUES = [0.6, 1.0, 5.0, 10.0, 40.0]
B_ALPHA_VALUES = [0.0, 4.5, 7.0, 12.0]
KEYS = ["z_a", "k_max", "h_min", "friction_integral", "couette_integral"]


def _rel(a: float, b: float) -> float:
    return abs(a - b) / max(abs(b), 1e-300)


def _markdown(rows: list[dict], n: int) -> str:
    head = ("| C | B alpha | ok | z_a | k_max | H_min | I | J | dz_a % | dk_max % | "
            "dH_min % | dI % | dJ % | Newton it. | s |\n" + "|" + "---|" * 15 + "\n")
    lines = []
    for r in rows:
        if not r["success"]:
            lines.append(f"| {r['C']} | {r['b_alpha']} | no: {r['message']} |" + " |" * 12)
            continue
        d = r["relative_change"]
        lines.append(
            f"| {r['C']} | {r['b_alpha']} | yes | {r['z_a']:.5f} | {r['k_max']:.5g} | "
            f"{r['h_min']:.5f} | {r['friction_integral']:.5f} | {r['couette_integral']:.5g} | "
            + " | ".join("—" if d.get(k) is None else f"{100 * d[k]:.3f}" for k in KEYS)
            + f" | {r['iterations']} | {r['seconds']:.1f} |")
    return (f"Grid: n = {n} nodes (values) vs 2n - 1 = {2 * n - 1} nodes (relative change, "
            f"%); z_b = 20.\n\n" + head + "\n".join(lines) + "\n")


def main(outdir: str | Path, n: int = 2001, quick: bool = False,
         c_values: list[float] | None = None) -> dict:
    """Solve the table; return {"rows": [...], ...} and write JSON + markdown to outdir.

    ``c_values``: a subset of C (default all of ``C_VALUES``)."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    cs = C_VALUES if c_values is None else c_values
    cases = [(1.0, 4.5)] if quick else [(c, b) for c in cs for b in B_ALPHA_VALUES]
    rows = []
    for c, b in cases:
        t0 = time.perf_counter()
        r = kodnir.solve(c, b, nodes=n)
        t1 = time.perf_counter()
        row = {"C": c, "b_alpha": b, "success": r.success, "message": r.message,
               "iterations": r.iterations, "seconds": t1 - t0}
        if r.success:
            row.update({k: getattr(r, k) for k in KEYS})
            row["z_a_free_boundary"] = r.z_a_free_boundary
            rf = kodnir.solve(c, b, nodes=2 * n - 1)
            row["fine_success"] = rf.success
            row["relative_change"] = {k: (_rel(getattr(r, k), getattr(rf, k))
                                          if rf.success else None) for k in KEYS}
            row["fine"] = {k: getattr(rf, k) for k in KEYS} if rf.success else None
        rows.append(row)
        data = {"version": __version__, "n": n, "command": " ".join(sys.argv), "rows": rows}
        (out / "kodnir_table.json").write_text(json.dumps(data, indent=1, default=float))
        (out / "kodnir_table.md").write_text(_markdown(rows, n))
    return data


if __name__ == "__main__":
    outdir = sys.argv[1] if len(sys.argv) > 1 else "out/kodnir_table"
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 2001
    # optional third argument: C values, comma-separated
    main(outdir, n=n, c_values=[float(v) for v in sys.argv[3].split(",")]
         if len(sys.argv) > 3 else None)

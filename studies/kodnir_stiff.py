"""Study: how far in the local compliance C does the Kodnir FE solver go (z_b = 20)?

Question
    Beyond the paper's table (C <= 40), up to which C does
    ``bearing_fem.contacts.kodnir.solve`` converge, at what cost (Newton iterations,
    continuation solves, seconds), how grid-converged are z_a, k_max and H_min there
    (``n`` vs ``2n - 1`` nodes), and what does the message say where it fails?

Scene
    Dimensionless; no physical data. z_b = 20 (the paper's value).

Expected outcome
    Isoviscous cases converge up to C ~ 200; larger C (and B alpha = 10 at C = 100) end
    with ``no_convergence`` and a message naming the continuation stage.

Run ``python studies/kodnir_stiff.py [outdir] [n] [--quick]``; ``main`` returns the rows
and writes ``kodnir_stiff.json`` and ``kodnir_stiff.md`` to ``outdir``. ``quick``: the
cases QUICK_CASES only.
"""
from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

from bearing_fem import __version__
from bearing_fem.contacts import kodnir

CASES = [(60.0, 0.0), (100.0, 0.0), (150.0, 0.0), (170.0, 0.0), (200.0, 0.0),
         (400.0, 0.0), (1000.0, 0.0), (1e4, 0.0), (1e6, 0.0), (100.0, 4.5), (100.0, 10.0),
         (400.0, 10.0)]
#: The quick run: one stiff case that converges and one beyond the reach.
QUICK_CASES = [(150.0, 0.0), (400.0, 0.0)]
KEYS = ["z_a", "k_max", "h_min"]


def _write(path: Path, text: str) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def _markdown(rows: list[dict], n: int) -> str:
    head = (f"Grid: n = {n} nodes (values) vs 2n - 1 = {2 * n - 1} nodes (relative change, "
            f"%); z_b = 20.\n\n| C | B alpha | status | z_a | k_max | H_min | dz_a % | "
            f"dk_max % | dH_min % | Newton it. | solves | s | message |\n" + "|" + "---|" * 13)
    lines = []
    for r in rows:
        if r["success"]:
            d = r["relative_change"]
            vals = (f"{r['z_a']:.5f} | {r['k_max']:.5g} | {r['h_min']:.5f} | " + " | ".join(
                "—" if d[k] is None else f"{100 * d[k]:.3f}" for k in KEYS))
        else:
            vals = " | ".join(["—"] * 6)
        lines.append(f"| {r['C']:g} | {r['b_alpha']:g} | {r['status']} | {vals} | "
                     f"{r['iterations']} | {r['solves']} | {r['seconds']:.1f} | "
                     f"{r['message'].replace('|', chr(92) + '|') if not r['success'] else ''} |")
    return head + "\n" + "\n".join(lines) + "\n"


def main(outdir: str | Path, quick: bool = False, n: int = 2001) -> dict:
    """Solve CASES (QUICK_CASES if ``quick``); return {"rows": [...], ...} and write JSON
    + markdown to outdir."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for c, b in (QUICK_CASES if quick else CASES):
        t0 = time.perf_counter()
        r = kodnir.solve(c, b, nodes=n)
        row = {"C": c, "b_alpha": b, "success": r.success, "status": r.status,
               "message": r.message, "iterations": r.iterations,
               "solves": len(r.continuation), "seconds": time.perf_counter() - t0}
        if r.success:
            row.update({k: getattr(r, k) for k in KEYS})
            rf = kodnir.solve(c, b, nodes=2 * n - 1)
            row["relative_change"] = {k: (abs(getattr(r, k) / getattr(rf, k) - 1.0)
                                          if rf.success else None) for k in KEYS}
        rows.append(row)
        print(row, flush=True)
    data = {"version": __version__, "n": n, "quick": quick, "command": " ".join(sys.argv),
            "rows": rows}
    _write(out / "kodnir_stiff.json", json.dumps(data, indent=1, default=float))
    _write(out / "kodnir_stiff.md", _markdown(rows, n))
    return data


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--quick"]
    main(args[0] if args else "out/kodnir_stiff", quick="--quick" in sys.argv[1:],
         n=int(args[1]) if len(args) > 1 else 2001)

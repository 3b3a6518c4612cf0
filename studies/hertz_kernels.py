"""Study: accuracy and cost of the half-space compliance operators in the Hertz dry limit.

Question
--------
How close do the discrete compliance operators of ``bearing_fem.physics.elasticity`` come to the
Hertz closed forms (docs/theory.md section 14.3), how fast does the error fall with the grid, and what
do building and applying them cost?

Scene
-----
Steel on steel, E' = 2.2e11 Pa, reduced radius R = 0.01 m.

* Line contact, w = 1e5 N/m (b = 107.6 um, p_h = 0.592 GPa), Hertz pressure
  ``p_h sqrt(1 - (x/b)^2)`` sampled at N uniform nodes on [-4b, 4b], N = 500 2^k + 1.
  Error: max over the nodes of the deviation of the gap ``x^2/(2R) + v`` from the Hertz
  gap (flat inside, ``(b^2/2R)[|X| sqrt(X^2-1) - arccosh|X|]`` outside), both relative
  to the centre node, divided by the central deflection ``v(0) - mean(v(+-4b))``
  (the log kernel fixes v only up to a constant).
* Point contact, F = 50 N (a = 150.5 um, p_h = 1.054 GPa, delta = 2.27 um), Hertz
  pressure on an n x n grid over [-2a, 2a]^2,
  n = 32 2^k + 1. Error: max |v - v_Hertz| / delta, delta = a^2/R.

Expected outcome
----------------
Errors converge at about O(D^1.5) (the pressure has a square-root edge); line build at
4000 nodes < 0.5 s; point apply at 513 x 513 < 0.3 s with memory in the tens of MB.

Run ``python studies/hertz_kernels.py [outdir]``; the numbers are written to
``outdir/hertz_kernels.json`` and printed as a table.
"""
from __future__ import annotations

import json
import math
import pathlib
import platform
import sys
import time
import tracemalloc
from typing import Any, Callable

import numpy as np
import scipy

import bearing_fem
from bearing_fem.physics.elasticity import LINE_DENSE_AUTO_CAP, HalfSpaceLine, HalfSpacePoint

E_PRIME = 2.2e11     # Pa
RADIUS = 0.01        # m
LINE_LOAD = 1.0e5    # N/m
POINT_LOAD = 50.0    # N


def _best_time(fn: Callable[[], Any], repeats: int) -> float:
    """Shortest wall time of ``repeats`` calls, s."""
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def line_case(n_nodes: int, repeats: int = 3) -> dict[str, Any]:
    """Hertz line-contact error and timings for ``n_nodes`` nodes on [-4b, 4b]."""
    b = math.sqrt(8.0 * LINE_LOAD * RADIUS / (math.pi * E_PRIME))
    p_h = E_PRIME * b / (4.0 * RADIUS)
    x = np.linspace(-4.0 * b, 4.0 * b, n_nodes)
    X = x / b
    p = p_h * np.sqrt(np.clip(1.0 - X ** 2, 0.0, None))

    build_fft = _best_time(lambda: HalfSpaceLine(x, E_PRIME, method="fft"), repeats)
    op_fft = HalfSpaceLine(x, E_PRIME, method="fft")
    apply_fft = _best_time(lambda: op_fft.apply(p), repeats)
    build_dense = apply_dense = None
    if n_nodes <= LINE_DENSE_AUTO_CAP + 1:
        build_dense = _best_time(lambda: HalfSpaceLine(x, E_PRIME, method="dense"), repeats)
        op_dense = HalfSpaceLine(x, E_PRIME, method="dense")
        apply_dense = _best_time(lambda: op_dense.apply(p), repeats)

    v = op_fft.apply(p)
    gap = x ** 2 / (2.0 * RADIUS) + v
    c = n_nodes // 2
    deflection = v[c] - 0.5 * (v[0] + v[-1])
    ax = np.abs(X)
    hertz = np.where(ax > 1.0, (b * b / (2.0 * RADIUS))
                     * (ax * np.sqrt(np.clip(ax * ax - 1.0, 0.0, None))
                        - np.arccosh(np.maximum(ax, 1.0))), 0.0)
    err = np.abs(gap - gap[c] - hertz)
    return {
        "nodes": n_nodes,
        "spacing_m": float(x[1] - x[0]),
        "central_deflection_m": float(deflection),
        "error_rel_deflection": float(err.max() / deflection),
        "error_inside_rel_deflection": float(err[ax < 1.0].max() / deflection),
        "build_fft_s": build_fft,
        "apply_fft_s": apply_fft,
        "build_dense_s": build_dense,
        "apply_dense_s": apply_dense,
        "dense_matrix_MB": n_nodes * n_nodes * 8 / 1e6,
    }


def point_case(n: int, repeats: int = 3) -> dict[str, Any]:
    """Hertz point-contact error, timings and memory on an n x n grid over [-2a, 2a]^2."""
    a = (3.0 * POINT_LOAD * RADIUS / (2.0 * E_PRIME)) ** (1.0 / 3.0)
    p_h = a * E_PRIME / (math.pi * RADIUS)
    delta = a * a / RADIUS
    x = np.linspace(-2.0 * a, 2.0 * a, n)
    xx, yy = np.meshgrid(x, x)
    r = np.hypot(xx, yy)
    p = p_h * np.sqrt(np.clip(1.0 - (r / a) ** 2, 0.0, None))

    build = _best_time(lambda: HalfSpacePoint(x, x, E_PRIME), repeats)
    tracemalloc.start()
    op = HalfSpacePoint(x, x, E_PRIME)
    _, peak_build = tracemalloc.get_traced_memory()
    tracemalloc.reset_peak()
    base, _ = tracemalloc.get_traced_memory()
    v = op.apply(p)
    _, peak_apply = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    apply = _best_time(lambda: op.apply(p), repeats)
    near_field = _best_time(lambda: op.near_field(2), 1)

    inside = r <= a
    v_ref = np.empty_like(r)
    v_ref[inside] = math.pi * p_h / (2.0 * a * E_PRIME) * (2.0 * a * a - r[inside] ** 2)
    ro = r[~inside]
    v_ref[~inside] = (p_h / (a * E_PRIME)) * ((2.0 * a * a - ro ** 2) * np.arcsin(a / ro)
                                              + a * np.sqrt(ro ** 2 - a * a))
    return {
        "nodes": n,
        "unknowns": n * n,
        "spacing_m": float(x[1] - x[0]),
        "delta_m": delta,
        "error_rel_delta": float(np.max(np.abs(v - v_ref)) / delta),
        "central_error_rel_delta": float(abs(v[n // 2, n // 2] - delta) / delta),
        "build_s": build,
        "apply_s": apply,
        "near_field_r2_s": near_field,
        "padded_shape": list(op._padded_shape),
        "spectrum_MB": op._spectrum.nbytes / 1e6,
        "peak_build_MB": peak_build / 1e6,
        "peak_apply_extra_MB": (peak_apply - base) / 1e6,
    }


def _order(rows: list[dict[str, Any]], key: str) -> float | None:
    if len(rows) < 2:
        return None
    h = np.log([row["spacing_m"] for row in rows])
    e = np.log([row[key] for row in rows])
    return float(np.polyfit(h, e, 1)[0])


def main(outdir: str | pathlib.Path = "out/hertz_kernels", n: int = 5,
         repeats: int = 3) -> dict[str, Any]:
    """Run the study on ``n`` refinement levels per family and write the JSON.

    Parameters
    ----------
    outdir : path
        Output directory (created); ``hertz_kernels.json`` is written there.
    n : int
        Number of levels: line N = 500 2^k + 1 nodes, point 32 2^k + 1 nodes per side,
        k = 0..n-1 (n = 5 gives 501..8001 and 33..513).
    repeats : int
        Timings are the best of this many runs.

    Returns
    -------
    dict
        ``{"line": [...], "point": [...], "line_order": .., "point_order": .., ...}``.
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ValueError(f"n must be a positive integer number of refinement levels, got {n!r}")
    outdir = pathlib.Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    line = [line_case(500 * 2 ** k + 1, repeats) for k in range(n)]
    point = [point_case(32 * 2 ** k + 1, repeats) for k in range(n)]
    result = {
        "line": line,
        "point": point,
        "line_order": _order(line, "error_rel_deflection"),
        "point_order": _order(point, "error_rel_delta"),
        "scene": {"e_prime_Pa": E_PRIME, "radius_m": RADIUS, "line_load_N_per_m": LINE_LOAD,
                  "point_load_N": POINT_LOAD},
        "provenance": {"bearing_fem": bearing_fem.__version__, "numpy": np.__version__,
                       "scipy": scipy.__version__, "python": platform.python_version(),
                       "machine": platform.machine(), "command": " ".join(sys.argv),
                       "study": "studies/hertz_kernels.py"},
    }
    (outdir / "hertz_kernels.json").write_text(json.dumps(result, indent=2))
    return result


def _fmt(t: float | None, scale: float = 1e3) -> str:
    return "   -   " if t is None else f"{t * scale:7.2f}"


if __name__ == "__main__":
    res = main(sys.argv[1] if len(sys.argv) > 1 else "out/hertz_kernels")
    print("Line contact, Hertz pressure on [-4b, 4b] (times in ms)")
    print("  nodes   error/defl  build_fft apply_fft build_dense apply_dense")
    for row in res["line"]:
        print(f"  {row['nodes']:5d}   {row['error_rel_deflection']:.3e}  "
              f"{_fmt(row['build_fft_s'])}   {_fmt(row['apply_fft_s'])}   "
              f"{_fmt(row['build_dense_s'])}     {_fmt(row['apply_dense_s'])}")
    print(f"  observed order {res['line_order']:.2f}")
    print("Point contact, Hertz pressure on [-2a, 2a]^2 (times in ms, memory in MB)")
    print("  grid      error/delta  build    apply   near_field(2)  spectrum  apply_peak")
    for row in res["point"]:
        print(f"  {row['nodes']:3d}^2   {row['error_rel_delta']:.3e}  {_fmt(row['build_s'])} "
              f"{_fmt(row['apply_s'])}   {_fmt(row['near_field_r2_s'])}       "
              f"{row['spectrum_MB']:6.1f}    {row['peak_apply_extra_MB']:6.1f}")
    print(f"  observed order {res['point_order']:.2f}")

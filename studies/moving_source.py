"""Study: moving band source in the rolling plane, FE (SUPG) vs Jaeger/Blok and exact 2D.

Question
    How close is the flash-temperature coefficient T_max sqrt(K rho c V)/(q sqrt b) of the
    FE convection-diffusion solution (``bearing_fem.physics.thermal.moving_source``) to Jaeger's
    high-Peclet value 2 sqrt(2/pi) = 1.596 (uniform band, half-length b) as a function of
    Pe = V b/(2 kappa), and where does the maximum under a semi-elliptic (Hertzian) flux
    sit compared with Blok's location (computed from the high-Pe integral, ~0.652 b)?

Scene
    Steel body (K = 40 W/(m K), rho = 7800 kg/m^3, c = 460 J/(kg K)), b = 0.1 mm,
    q_max = 100 MW/m^2, Pe in {1, 2, 5, 10, 20, 50, 100} (speed set from Pe). Every FE
    value is also compared with the exact 2D moving line-source superposition (K0 kernel,
    any Pe), which separates the discretisation error from the finite-Pe departure of
    the boundary-layer formula.

Expected outcome
    FE within ~1 % of exact 2D at every Pe; the coefficient approaches 1.596 from below,
    within 3 % from Pe ~ 10 (exact 2D: -2.3 % at Pe = 10); the semi-elliptic maximum
    moves downstream towards Blok's location, within 0.03 b from Pe ~ 10-20.

Run ``python studies/moving_source.py [outdir]``; ``main`` returns the numbers.
"""
from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import numpy as np
from scipy.optimize import minimize_scalar

from bearing_fem import __version__, analytic as A

from bearing_fem.physics import thermal as th

B, Q_MAX, K, RHO, CP = 1.0e-4, 1.0e8, 40.0, 7800.0, 460.0
KAPPA = K / (RHO * CP)
PECLET = [1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0]


def _flux(kind: str):
    if kind == "uniform":
        return lambda s: Q_MAX
    return lambda s: Q_MAX * np.sqrt(max(1.0 - (s / B) ** 2, 0.0))


def _exact_max(kind: str, V: float) -> tuple[float, float]:
    """(x_max/b, T_max [K]) of the exact 2D moving line-source superposition."""
    f = _flux(kind)
    T = lambda xb: float(A.moving_line_source_surface_temperature(  # noqa: E731
        xb * B, f, B, K, RHO, CP, V))
    r = minimize_scalar(lambda xb: -T(xb), bounds=(-0.5, 1.0), method="bounded",
                        options={"xatol": 1e-6})
    return float(r.x), float(-r.fun)


def main(outdir: str | Path = "out/moving_source", n: int = 160, quick: bool = False) -> dict:
    """Run the study; write ``moving_source.json`` and ``.png`` to ``outdir``.

    Parameters
    ----------
    outdir : path
        Output directory (created).
    n : int
        FE cells across the band (``n_source``).
    quick : bool
        Only Pe = 10 and 50 (for tests).
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    pes = [10.0, 50.0] if quick else PECLET
    cu = A.uniform_band_max_coefficient()
    xb_blok, ce = A.blok_semielliptic_maximum()
    out: dict = {"version": __version__, "command": " ".join(sys.argv),
                 "scene": {"half_length_m": B, "q_max_W_m2": Q_MAX, "conductivity_W_mK": K,
                           "density_kg_m3": RHO, "heat_capacity_J_kgK": CP, "n_source": n},
                 "jaeger_uniform_coefficient": cu, "blok_x_max_over_b": xb_blok,
                 "blok_semielliptic_coefficient": ce, "peclet": pes,
                 "uniform": {k: [] for k in ("coefficient_fe", "coefficient_exact2d",
                                             "error_vs_jaeger_pct", "error_vs_exact2d_pct",
                                             "wall_time_s", "dofs")},
                 "semi_elliptic": {k: [] for k in ("x_max_over_b_fe", "x_max_over_b_exact2d",
                                                   "x_max_error_vs_blok_b",
                                                   "coefficient_fe", "coefficient_exact2d",
                                                   "error_vs_exact2d_pct")}}
    profiles = {}
    for Pe in pes:
        V = 2.0 * KAPPA * Pe / B
        e = np.sqrt(K * RHO * CP * V)
        t0 = time.perf_counter()
        ru = th.moving_source(B, Q_MAX, K, RHO, CP, V, flux="uniform", n_source=n)
        wall = time.perf_counter() - t0
        _, tmax_ex = _exact_max("uniform", V)
        c_ex = tmax_ex * e / (Q_MAX * np.sqrt(B))
        u = out["uniform"]
        u["coefficient_fe"].append(ru.coefficient)
        u["coefficient_exact2d"].append(c_ex)
        u["error_vs_jaeger_pct"].append((ru.coefficient / cu - 1) * 100)
        u["error_vs_exact2d_pct"].append((ru.coefficient / c_ex - 1) * 100)
        u["wall_time_s"].append(wall)
        u["dofs"].append(int(ru.basis.N))

        rs = th.moving_source(B, Q_MAX, K, RHO, CP, V, flux="semi-elliptic", n_source=n)
        xm_ex, tmax_ex = _exact_max("semi-elliptic", V)
        c_ex = tmax_ex * e / (Q_MAX * np.sqrt(B))
        s = out["semi_elliptic"]
        s["x_max_over_b_fe"].append(rs.x_max / B)
        s["x_max_over_b_exact2d"].append(xm_ex)
        s["x_max_error_vs_blok_b"].append(rs.x_max / B - xb_blok)
        s["coefficient_fe"].append(rs.coefficient)
        s["coefficient_exact2d"].append(c_ex)
        s["error_vs_exact2d_pct"].append((rs.coefficient / c_ex - 1) * 100)
        profiles[Pe] = (ru, rs, e)

    (outdir / "moving_source.json").write_text(json.dumps(out, indent=2))
    _plot(out, profiles, outdir / "moving_source.png")
    return out


def _plot(out: dict, profiles: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    pes = out["peclet"]
    ax[0].semilogx(pes, out["uniform"]["coefficient_fe"], "o-", label="FE, uniform")
    ax[0].semilogx(pes, out["uniform"]["coefficient_exact2d"], "k+", ms=10,
                   label="exact 2D, uniform")
    ax[0].axhline(out["jaeger_uniform_coefficient"], color="k", ls=":", label="Jaeger 1.596")
    ax[0].semilogx(pes, out["semi_elliptic"]["coefficient_fe"], "s-", label="FE, semi-elliptic")
    ax[0].axhline(out["blok_semielliptic_coefficient"], color="g", ls=":", label="Blok")
    ax[0].set_xlabel("Pe = V b / (2 kappa)")
    ax[0].set_ylabel("T_max sqrt(K rho c V) / (q_max sqrt b)")
    ax[0].legend(fontsize=8)
    for Pe, (ru, rs, e) in profiles.items():
        m = (rs.x > -1.5 * B) & (rs.x < 2.5 * B)
        ax[1].plot(rs.x[m] / B, rs.surface_temperature[m] * e / (Q_MAX * np.sqrt(B)),
                   label=f"semi-elliptic, Pe = {Pe:g}")
    ax[1].axvline(out["blok_x_max_over_b"], color="k", ls=":", label="Blok x_max")
    ax[1].set_xlabel("x / b (body moves to +x)")
    ax[1].set_ylabel("T sqrt(K rho c V) / (q_max sqrt b)")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    res = main(sys.argv[1] if len(sys.argv) > 1 else "out/moving_source")
    print(json.dumps({k: res[k] for k in ("peclet", "uniform", "semi_elliptic")}, indent=1))

"""Kadochnikova's (2018) ball with elasticity: transient squeeze of an elastic ball, h0(t) = h0 (1 + eps cos wt).

Question
--------
Kadochnikova (2018 thesis, 209 ball bearing vibration, after Kapitsa) computes the maximum film pressure of a ball whose
gap vibrates as h0(t) = h0 (1 + eps cos(omega t)) for RIGID bodies, where every instant
is a quasi-steady wedge + squeeze problem without memory. How do elastic (half-space)
bodies change p_max(t): its level, its phase relative to the gap, and the energy the film
takes from the vibration per cycle? How much of the difference is memory, i.e. the
elastic deformation rate dv/dt in d(rho h)/dt, rather than the elastic deformation itself?

Scene (stated, since the thesis is rigid)
-----------------------------------------
* Ball of bearing 209 on a plane: rx = ry = D_w/2 = 6.35 mm; steel on steel,
  E = 210 GPa, nu = 0.3 (E' = E/(1 - nu^2)).
* Oil I-40A: eta0 = 68 mm^2/s * 900 kg/m^3 = 0.0612 Pa s, isoviscous (the rigid Barus
  solution of this case does not exist: alpha q_max > 1 for alpha = 2.2e-8 1/Pa, see
  ``bearing209.py``), incompressible, Reynolds cavitation.
* Mean gap h0 = 0.1 um (the paper's middle gap), eps = 0.3 (the paper's value), u_m = 1 m/s (the
  paper's sum speed 2 m/s).
* omega = u_m / sqrt(2 rx h0) (printed; kHz range): one hydrodynamic length of rolling
  per radian, where squeeze and wedge pressures are comparable. At the paper's own
  frequency (shaft rotation 2 v/d_i, v the sum speed, d_i = d_m - D_w) the squeeze term
  is a few hundred times weaker and the response should be quasi-static; the study
  checks that too (``slow`` case).
* Grid: the solver's default for gap-controlled elastic scenes (97 x 97 uniform over
  x in [-10, 5], y in [-10, 10] hydrodynamic lengths sqrt(2 rx h0)); BDF2 with 32 steps
  per period, two periods (the second shows whether the start-up has decayed).

Three series on the same instants:

1. rigid quasi-steady (``bearing_fem.contacts.point.solve_squeeze_series``, graded 121^2 grid);
2. elastic quasi-steady (``scheme="quasi-steady"``: each instant a steady elastic solve
   with the squeeze source dh0/dt, no dv/dt): the elastic deformation without memory;
3. elastic transient (BDF2): deformation and memory.

Expected outcome
----------------
Elasticity lowers p_max substantially (the deformation is a sizeable fraction of the
film at this gap); the transient lags the quasi-steady elastic response by a few degrees
(memory); the second period repeats the first once the start-up has decayed; halving
dt changes p_max by well under 1% (BDF2); at the paper's shaft frequency transient and
quasi-steady agree.

Run ``python studies/point_elastic_squeeze.py [outdir] [--quick]``.
"""
from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np

import bearing_fem as bf
from bearing_fem.contacts.series import solve_squeeze_series
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec,
                               Model, Scene)
from bearing_fem.contacts.transient import (ELASTIC_GAP_RANGE_REYNOLDS, solve_elastic_gap,
                                   solve_elastic_squeeze_series)

BALL_DIAMETER = 12.7e-3                  # m, D_w of bearing 209
INNER_RACE_DIAMETER = 65e-3 - 12.7e-3    # m, d_i = d_m - D_w (bearing209.py)
VISCOSITY = 68e-6 * 900.0                # Pa s, I-40A
GAP = 0.1e-6                             # m, mean h0
EPS = 0.3
MEAN_SPEED = 1.0                         # m/s (the paper's sum speed 2 m/s)
YOUNG, POISSON = 2.1e11, 0.3             # Pa, -


def make_scene(elasticity: str = "half-space", nodes: int | None = None) -> Scene:
    """The study's ball-on-plane scene (``nodes`` per direction, default grid if None)."""
    r = BALL_DIAMETER / 2.0
    mesh = MeshSpec(nodes=(nodes, nodes)) if nodes else MeshSpec()
    return Scene(contact=Contact(kind="point", rx=r, ry=r),
                 materials=Materials(e1=YOUNG, nu1=POISSON, e2=YOUNG, nu2=POISSON),
                 lubricant=Lubricant(viscosity=VISCOSITY, viscosity_law="constant"),
                 kinematics=Kinematics(u1=MEAN_SPEED, u2=MEAN_SPEED), load=Load(gap=GAP),
                 model=Model(elasticity=elasticity, cavitation="reynolds"), mesh=mesh)


def first_harmonic(values: np.ndarray, times: np.ndarray, omega: float) -> tuple[float, float]:
    """Amplitude and phase [deg] of the omega-harmonic of periodic samples (one period,
    uniform, endpoint excluded): values ~ mean + A cos(omega t + phase)."""
    c = 2.0 * np.mean(values * np.exp(-1j * omega * times))
    return float(abs(c)), float(np.degrees(np.angle(c)))


def cycle_work(load: np.ndarray, rate: np.ndarray, dt: float) -> float:
    """-closed integral F dh0 = -int F dh0/dt dt over one period [J]: energy the film
    takes from the vibration (periodic rectangle rule, spectrally accurate)."""
    return float(-np.sum(load * rate) * dt)


def _wrap_deg(angle: float) -> float:
    """Angle in (-180, 180] degrees."""
    return float(-((-angle + 180.0) % 360.0 - 180.0))


def _last_period(n_steps: int, periods: int) -> slice:
    return slice((periods - 1) * n_steps, periods * n_steps)


def main(outdir, quick: bool = False, *, nodes: int | None = None,
         n_steps: int | None = None, periods: int | None = None, slow: bool = True,
         grid_check: bool | None = None, rigid_nodes: int | None = None,
         plot: bool = True) -> dict:
    """Run the study; write the table, a JSON summary, the PVD/XDMF series; return numbers.

    Parameters
    ----------
    outdir : path
        Output directory (created).
    quick : bool
        49^2 nodes, 16 steps per period (defaults of the full run: 97^2, 32).
    nodes, n_steps, periods : int, optional
        Override the grid (nodes per direction), steps per period and periods (2).
    slow : bool
        Also run the paper's shaft frequency (one period, n_steps/4 steps).
    grid_check : bool, optional
        Steady elastic solves at the smallest gap on 65^2, 97^2, 129^2 (default: full
        run only).
    rigid_nodes : int, optional
        Nodes per direction of the rigid graded grid (default 121, quick 81).
    plot : bool
        Write ``point_elastic_squeeze.png`` (matplotlib, Agg).
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    n_steps = n_steps or (16 if quick else 32)
    periods = periods or 2
    nodes = nodes or (49 if quick else None)
    rigid_nodes = rigid_nodes or (81 if quick else 121)
    elastic = make_scene("half-space", nodes)
    omega = MEAN_SPEED / math.sqrt(2.0 * elastic.contact.rx * GAP)

    clock = time.perf_counter()
    tr = solve_elastic_squeeze_series(elastic, eps=EPS, omega=omega, n_steps=n_steps,
                                      periods=periods, scheme="bdf2")
    t_transient = time.perf_counter() - clock
    clock = time.perf_counter()
    qs = solve_elastic_squeeze_series(elastic, eps=EPS, omega=omega, n_steps=n_steps,
                                      periods=periods, scheme="quasi-steady")
    t_quasi = time.perf_counter() - clock
    clock = time.perf_counter()
    half = solve_elastic_squeeze_series(elastic, eps=EPS, omega=omega, n_steps=n_steps // 2,
                                        periods=periods, scheme="bdf2")
    t_half = time.perf_counter() - clock
    clock = time.perf_counter()
    # rigid: no memory, so one period of instants serves every period (81^2 graded grid
    # in the quick run: p_max within 0.3% of the default 161^2 at this gap)
    rigid_one = solve_squeeze_series(make_scene("rigid", rigid_nodes), eps=EPS, omega=omega,
                                     times=tr.times[:n_steps])
    t_rigid = time.perf_counter() - clock
    idx = np.arange(len(tr.times)) % n_steps
    rigid = SimpleNamespace(p_max=rigid_one.p_max[idx], gap=rigid_one.gap[idx],
                            squeeze_velocity=rigid_one.squeeze_velocity[idx],
                            statuses=rigid_one.statuses,
                            load=np.array([r.quantities["load"] for r in rigid_one.results])[idx])
    for s in (tr, qs, half):
        if not s.success:
            raise RuntimeError(f"elastic series failed: {s.message}")
    if not all(st == "linear" for st in rigid.statuses):
        raise RuntimeError(f"rigid series: {rigid.statuses}")

    dt = tr.time_step
    last = _last_period(n_steps, periods)
    t_last = tr.times[last]
    harmonics = {}
    for name, pm in (("rigid_quasi_steady", rigid.p_max), ("elastic_quasi_steady", qs.p_max),
                     ("elastic_transient", tr.p_max)):
        amp, phase = first_harmonic(pm[last], t_last, omega)
        harmonics[name] = {"mean_Pa": float(np.mean(pm[last])), "amplitude_Pa": amp,
                           # phase of p_max relative to the gap minimum (cos(wt) = -1):
                           # positive = p_max peaks before the minimum gap
                           "lead_vs_min_gap_deg": _wrap_deg(phase + 180.0),
                           "max_Pa": float(np.max(pm[last]))}
    work = {"rigid_quasi_steady": cycle_work(rigid.load[last], rigid.squeeze_velocity[last], dt),
            "elastic_quasi_steady": cycle_work(qs.load[last], qs.squeeze_velocity[last], dt),
            "elastic_transient": cycle_work(tr.load[last], tr.squeeze_velocity[last], dt)}
    lag = (harmonics["elastic_quasi_steady"]["lead_vs_min_gap_deg"]
           - harmonics["elastic_transient"]["lead_vs_min_gap_deg"])
    scale = float(np.max(tr.p_max))
    periodicity = periodicity_late = None
    if periods >= 2:
        change = np.abs(tr.p_max[n_steps:2 * n_steps] - tr.p_max[:n_steps]) / scale
        periodicity = float(np.max(change))
        periodicity_late = float(np.max(change[n_steps // 2:]))  # second half-period
    # BDF2 time error: dt vs 2 dt at the shared instants; Richardson: error(dt) ~ diff/3
    dt_change = float(np.max(np.abs(tr.p_max[::2] - half.p_max)) / scale)
    memory = float(np.max(np.abs(tr.p_max - qs.p_max)) / scale)

    grid_rows = None
    if grid_check if grid_check is not None else not quick:
        grid_rows = []
        low = make_scene("half-space").replace(load=Load(gap=GAP * (1.0 - EPS)))
        for n in (65, 97, 129):
            clock = time.perf_counter()
            # the default x/y ranges are in units of sqrt(2 rx gap): scale them to the
            # mean-gap lengths of the series grid
            k = math.sqrt(1.0 / (1.0 - EPS))
            (x0, x1), (y0, y1) = ELASTIC_GAP_RANGE_REYNOLDS
            r = solve_elastic_gap(low.replace(mesh=MeshSpec(
                nodes=(n, n), x_range=(x0 * k, x1 * k), y_range=(y0 * k, y1 * k))))
            grid_rows.append({"nodes": n, "status": r.status, "p_max_Pa": r.quantities["p_max"],
                         "h_central_m": r.quantities["h_central"],
                         "seconds": time.perf_counter() - clock})

    slow_out = None
    if slow:
        v_sum = 2.0 * MEAN_SPEED
        omega_shaft = 2.0 * v_sum / INNER_RACE_DIAMETER
        m = max(4, n_steps // 4)
        clock = time.perf_counter()
        s_tr = solve_elastic_squeeze_series(elastic, eps=EPS, omega=omega_shaft, n_steps=m)
        s_qs = solve_elastic_squeeze_series(elastic, eps=EPS, omega=omega_shaft, n_steps=m,
                                            scheme="quasi-steady")
        slow_out = {"omega_rad_s": omega_shaft, "steps": m,
                    "omega_ratio": omega / omega_shaft,
                    "status": [s_tr.status, s_qs.status],
                    "max_rel_diff_transient_vs_quasi_steady":
                        float(np.max(np.abs(s_tr.p_max - s_qs.p_max)) / np.max(s_qs.p_max)),
                    "seconds": time.perf_counter() - clock}

    paths = {k: str(v) for k, v in bf.io.export_series(tr, outdir / "series",
                                                       name="elastic_squeeze").items()}
    header = (f"{'k':>3} {'t us':>7} {'h0 nm':>6} {'p_max MPa':>9} {'h_min nm':>8} "
              f"{'h_c nm':>7} {'F N':>6} {'its':>3} {'s':>5} {'qs MPa':>7} {'rigid MPa':>9}")
    lines = [header]
    rows = []
    for k in range(len(tr.times)):
        row = {"k": k, "t_s": float(tr.times[k]), "h0_m": float(tr.gap[k]),
               "p_max_Pa": float(tr.p_max[k]), "h_min_m": float(tr.h_min[k]),
               "h_central_m": float(tr.h_central[k]), "load_N": float(tr.load[k]),
               "newton_iterations": int(tr.newton_iterations[k]),
               "seconds": float(tr.wall_time_s[k]),
               "p_max_quasi_steady_elastic_Pa": float(qs.p_max[k]),
               "p_max_rigid_Pa": float(rigid.p_max[k])}
        rows.append(row)
        lines.append(f"{k:3d} {row['t_s'] * 1e6:7.1f} {row['h0_m'] * 1e9:6.1f} "
                     f"{row['p_max_Pa'] / 1e6:9.1f} {row['h_min_m'] * 1e9:8.1f} "
                     f"{row['h_central_m'] * 1e9:7.1f} {row['load_N']:6.3f} "
                     f"{row['newton_iterations']:3d} {row['seconds']:5.2f} "
                     f"{row['p_max_quasi_steady_elastic_Pa'] / 1e6:7.1f} "
                     f"{row['p_max_rigid_Pa'] / 1e6:9.1f}")
    grid = tr.results[0]
    summary = {
        "scene": {"rx_m": elastic.contact.rx, "e_prime_Pa": elastic.e_prime,
                  "viscosity_Pa_s": VISCOSITY, "mean_speed_m_s": MEAN_SPEED,
                  "gap_m": GAP, "eps": EPS, "omega_rad_s": omega,
                  "nodes": [int(grid.x.size), int(grid.y.size)], "n_steps": n_steps,
                  "periods": periods, "time_step_s": dt, "scheme": tr.scheme},
        "harmonics_last_period": harmonics,
        "memory_lag_deg": lag,
        "cycle_work_J": work,
        "max_rel_diff_transient_vs_quasi_steady_elastic": memory,
        "max_rel_change_period2_vs_period1": periodicity,
        "max_rel_change_period2_vs_period1_second_half": periodicity_late,
        "grid_check": grid_rows,
        "max_rel_change_dt_vs_2dt": dt_change,
        "newton_iterations": {"transient": int(tr.newton_iterations.sum()),
                              "quasi_steady": int(qs.newton_iterations.sum()),
                              "transient_2dt": int(half.newton_iterations.sum())},
        "seconds": {"transient": t_transient, "quasi_steady": t_quasi,
                    "transient_2dt": t_half, "rigid": t_rigid},
        "slow_shaft_frequency": slow_out,
        "status": tr.status, "message": tr.message, "files": paths,
    }
    h = harmonics
    lines += [
        "",
        f"E' = {elastic.e_prime:.3e} Pa, eta0 = {VISCOSITY:.4f} Pa s, u_m = {MEAN_SPEED} m/s, "
        f"h0 = {GAP * 1e9:.0f} nm, eps = {EPS}, omega = {omega:.4g} rad/s, "
        f"{grid.x.size}x{grid.y.size} nodes, BDF2 dt = {dt:.4g} s "
        f"({n_steps}/period, {periods} periods)",
        "last period       mean MPa  ampl MPa  max MPa  lead vs min gap deg  work/cycle J",
    ]
    for name in ("rigid_quasi_steady", "elastic_quasi_steady", "elastic_transient"):
        lines.append(f"{name:<20} {h[name]['mean_Pa'] / 1e6:7.1f} "
                     f"{h[name]['amplitude_Pa'] / 1e6:9.1f} {h[name]['max_Pa'] / 1e6:8.1f} "
                     f"{h[name]['lead_vs_min_gap_deg']:20.1f} {work[name]:13.3e}")
    lines.append(f"memory: transient lags the quasi-steady elastic p_max by {lag:.1f} deg; "
                 f"max |transient - quasi-steady| = {100 * memory:.1f}% of max p_max")
    if periodicity is not None:
        lines.append(f"start-up: period 2 vs period 1 differ by {100 * periodicity:.2f}% "
                     f"of max p_max ({100 * periodicity_late:.2f}% over the second "
                     f"half-period)")
    lines.append(f"time step: dt vs 2 dt differ by {100 * dt_change:.2f}% of max p_max "
                 f"(BDF2 error at dt ~ 1/3 of that)")
    if slow_out:
        lines.append(f"shaft frequency omega = {slow_out['omega_rad_s']:.1f} rad/s "
                     f"({slow_out['omega_ratio']:.0f} times lower): transient vs "
                     f"quasi-steady elastic p_max differ by "
                     f"{100 * slow_out['max_rel_diff_transient_vs_quasi_steady']:.3f}%")
    for g in grid_rows or []:
        lines.append(f"grid check (steady, h0(1 - eps), no squeeze): {g['nodes']}^2 "
                     f"p_max = {g['p_max_Pa'] / 1e6:.2f} MPa, h_c = "
                     f"{g['h_central_m'] * 1e9:.2f} nm, {g['seconds']:.1f} s")
    lines.append(f"wall time: transient {t_transient:.1f} s "
                 f"({int(tr.newton_iterations.sum())} Newton its), quasi-steady "
                 f"{t_quasi:.1f} s, transient at 2 dt {t_half:.1f} s, rigid {t_rigid:.1f} s")
    table = "\n".join(lines)
    (outdir / "point_elastic_squeeze.txt").write_text(table + "\n", encoding="utf-8")
    (outdir / "point_elastic_squeeze.json").write_text(
        json.dumps({"summary": summary, "steps": rows}, indent=1), encoding="utf-8")
    print(table)
    if plot:
        _plot(outdir / "point_elastic_squeeze.png", tr, qs, rigid, last)
    summary["steps"] = rows
    return summary


def _plot(path: Path, tr, qs, rigid, last: slice) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4))
    t = tr.times * 1e6
    ax1.plot(t, rigid.p_max / 1e6, "k:", label="rigid quasi-steady")
    ax1.plot(t, qs.p_max / 1e6, "b--", label="elastic quasi-steady")
    ax1.plot(t, tr.p_max / 1e6, "r-", label="elastic transient (BDF2)")
    ax1.set_xlabel("t [us]")
    ax1.set_ylabel("p_max [MPa]")
    ax1.legend()
    for load, gap, style, name in ((rigid.load, rigid.gap, "k:", "rigid quasi-steady"),
                                   (qs.load, qs.gap, "b--", "elastic quasi-steady"),
                                   (tr.load, tr.gap, "r-", "elastic transient")):
        g = np.append(gap[last], gap[last][0]) * 1e9
        f = np.append(load[last], load[last][0])
        ax2.plot(g, f, style, label=name)
    ax2.set_xlabel("h0 [nm]")
    ax2.set_ylabel("film force [N]")
    ax2.set_title("last period: F vs h0 (loop area = work per cycle)")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    main(args[0] if args else "out/point_elastic_squeeze", quick="--quick" in sys.argv)

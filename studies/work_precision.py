"""Work against precision: how much accuracy each second (and each unknown) buys.

Question
--------
For exact-oracle cases and EHL cases, what is the error in h_central, h_min, p_max, the
friction force and the heat power as a function of wall time and of the number of
unknowns, over mesh sizes and solver settings (Newton tolerance, grid grading where the
solver has it, the thermal loop tolerance)? What are the fitted convergence orders? Which
are the cheapest settings that reach 1 % and 0.1 % in both h_central and h_min for the
line and the circular contact at Moes M = 100, L = 10, and do the package defaults reach
1 % within 1.5 times the time of the fastest 1 % setting?

Cases
-----
Oracles (exact values from the closed forms in :mod:`bearing_fem.analytic`; the gap is
prescribed, so h_central and h_min are exact by construction and not measured):

* ``kapitsa_line``: rigid cylinder, Barus (alpha q_max = 0.5), full-Sommerfeld, gap
  h0 = 1 um, exact end pressures on x in [-10, 10] sqrt(2 R h0), uniform grids; plus the
  solver's default grid (8001 nodes on [-100, 100]).
* ``kapitsa_point``: rigid ball, same settings, exact boundary pressure; the solver's
  default domain [-30, 30]^2 with its sinh-graded grid and with a uniform grid of the same
  node count (the *grading* setting), and a uniform grid on [-3, 3]^2.
* ``martin``: rigid isoviscous cylinder with the Reynolds outlet (Martin), gap given,
  exact inlet pressure at x = -20 sqrt(2 R h0).

Exact p_max is the closed-form peak; the exact rolling friction F_P = int (h/2) dp/dx
and Poiseuille heat 2 u_m F_P are Gauss quadratures of the closed-form pressure over
the solved domain.

EHL cases (no closed form: the reference is the **Richardson extrapolation of the two
finest grids** of the nested family at the tightest tolerance, with the P1 order p = 2:
ref = f_fine + (f_fine - f_coarse)/(2^p - 1); the tables give its distance from the
finest solve as the reference uncertainty):

* ``line_ehl``: Moes M = 100, L = 10 line contact (R = 10 mm, E' = 2.2e11 Pa,
  alpha = 2e-8 1/Pa, eta0 = 0.01 Pa s, pure rolling; ``line_ehl_map.scene_for``),
  uniform node counts 2^k 100 + 1 times Newton tolerances 1e-4, 1e-6, 1e-8, grids
  refined at the outlet spike (``bearing_fem.mesh.outlet_graded_nodes`` as grid files in
  ``OUTDIR/meshes``; the *grading* setting of lines), and the defaults (no mesh or
  solver section).
* ``circular_ehl``: Moes M = 100, L = 10 circular contact (``point_ehl_map.moes_scene``),
  n^2 grids, n = 2^k + 1, times tolerances; and the defaults.
* ``ellipse_ehl``: the same groups with ry/rx = 4.
* ``thermal_line``: a sliding (u1 = 2.2, u2 = 1.8 m/s) half-space roller,
  w = 2e5 N/m, R = 10 mm, eta0 = 0.05 Pa s, alpha = 2e-8 1/Pa, thermal patch (oil
  60 deg C, Prokofiev n = 2.93), Eyring traction; node counts times thermal-loop
  tolerances 2, 0.05 (default) and 1e-4 K.
* ``bearing_6209``: ``bf.solve_bearing`` on the shipped 6209 example with contact grids
  65^2, 129^2 (the default), 257^2 (and 33^2, which the solver may not converge on; its
  status is reported). h_central and h_min of the most loaded inner contact, the
  bearing's largest p_max, friction torque (in the friction column) and heat power.

Timings: every setting of a case is run ``repeats`` times, interleaved (round robin over
the settings), and the minimum wall time is kept. The machine may be shared with other
work; the load average at the start and end of each case is written with the results.

Orders: least-squares slope of log(error) against log(grid spacing) over the nested family
at the tightest tolerance, excluding the two finest grids where they make the reference.

Run ``python studies/work_precision.py OUTDIR [--quick]``; writes ``runs.csv``,
``orders.csv``, ``targets.md``, ``work_precision.md``, ``summary.json`` and one
``wp_<case>.png`` per case plus ``wp_targets.png`` into OUTDIR. ``--quick`` runs the
oracles and the line and circular EHL cases on smaller grid families (about a minute).
"""

import argparse
import csv
import json
import math
import os
import sys
import time
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from bearing_fem import analytic  # noqa: E402
from bearing_fem.bearing import load_example  # noqa: E402
from bearing_fem.bench import machine_info, thermal_line_scene  # noqa: E402
from bearing_fem.contacts.point import solve_point  # noqa: E402
from bearing_fem.scene import (  # noqa: E402
    Contact, Kinematics, Load, Lubricant, MeshSpec, Model, Scene, SolverSpec)
from line_ehl_map import scene_for as line_moes_scene  # noqa: E402
from point_ehl_map import moes_scene as point_moes_scene  # noqa: E402

QUANTITIES = ("h_central", "h_min", "p_max", "friction_force", "heat_power")
#: Accuracy targets of the settings search (relative error in h_central and h_min).
TARGETS = (0.01, 0.001)
#: The defaults must reach the 1 % target within this factor of the fastest 1 % time.
DEFAULT_TIME_FACTOR = 1.5
#: Order of the Richardson reference (P1 elements, smooth solution).
RICHARDSON_ORDER = 2.0
MOES_M, MOES_L = 100.0, 10.0
SPIKE_NOTE = ("p_max is the height of the pressure spike near the outlet, which grows as the "
              "grid resolves it: its error against the reference only says that p_max is "
              "not grid-converged (the films, friction and heat power are)")


@dataclass
class Setting:
    """One solver setting of a case: a label, the grid family it belongs to (None: not
    part of a nested family), its nodes per direction and its tolerance."""
    label: str
    build: Callable[[], Any]
    family: str | None = None
    nodes: int | None = None
    tolerance: float | None = None
    default: bool = False


@dataclass
class Case:
    name: str
    title: str
    solve: Callable[[Any], dict]
    settings: list[Setting]
    repeats: int
    exact: dict[str, dict[str, float]] | None = None  # per family/label: exact values
    reference_family: str | None = None
    notes: list[str] = field(default_factory=list)


# ---------------------------------------------------------------------------------------
# solves
# ---------------------------------------------------------------------------------------
def _summary_values(res) -> dict:
    s = res.summary()
    out = {k: s.get(k) for k in QUANTITIES}
    out.update(status=s["status"], success=bool(s["success"]), dofs=int(s["dofs"]),
               newton_iterations=int(s.get("newton_iterations") or 0))
    return out


def solve_contact(job) -> dict:
    """``job`` = (scene, kwargs for the solve); line scenes through ``bf.solve``, rigid
    point scenes with a Dirichlet boundary callable through ``solve_point``."""
    scene, kw = job
    if scene.contact.kind == "point" and kw:
        return _summary_values(solve_point(scene, **kw))
    return _summary_values(bf.solve(scene, **kw))


def solve_bearing_job(bearing) -> dict:
    """Bearing quantities: films of the most loaded inner contact, largest p_max,
    friction torque [N m] (reported as friction) and heat power [W]."""
    r = bf.solve_bearing(bearing)
    out = {"status": r.status, "success": bool(r.success),
           "newton_iterations": int(sum(c.summary().get("newton_iterations") or 0
                                        for c in r.contacts.values())),
           "dofs": int(sum(c.summary()["dofs"] for c in r.contacts.values()))}
    if not r.success:
        out.update({k: None for k in QUANTITIES})
        return out
    j = int(np.argmax([e["load"] for e in r.elements]))
    inner = r.elements[j]["inner"]
    out.update(h_central=inner["h_central"], h_min=inner["h_min"], p_max=r.totals["p_max"],
               friction_force=r.totals["friction_torque"], heat_power=r.totals["heat_power"])
    return out


# ---------------------------------------------------------------------------------------
# oracle cases
# ---------------------------------------------------------------------------------------
def _gauss_panels(a: float, b: float, panels: int, order: int = 16):
    t, w = np.polynomial.legendre.leggauss(order)
    edges = np.linspace(a, b, panels + 1)
    lo, hi = edges[:-1, None], edges[1:, None]
    x = (0.5 * (hi - lo) * t + 0.5 * (hi + lo)).ravel()
    wx = (0.5 * (hi - lo) * w).ravel()
    return x, wx


KL = dict(eta=0.05, u=2.0, R=0.01, h0=1e-6)


def kapitsa_line_case(quick: bool) -> Case:
    eta, u, R, h0 = KL["eta"], KL["u"], KL["R"], KL["h0"]
    q_max = float(analytic.kapitsa_line_max_reduced(h0, R, eta, u))
    alpha = 0.5 / q_max
    L = math.sqrt(2 * R * h0)

    def p(x):
        return analytic.kapitsa_line_pressure(x, h0, R, eta, u, piezo=alpha)

    def scene(nodes, x_range):
        mesh = MeshSpec(nodes=nodes, x_range=x_range) if nodes else MeshSpec()
        return Scene(title="Kapitsa line", contact=Contact(kind="line", rx=R),
                     lubricant=Lubricant(viscosity=eta, piezo=alpha),
                     kinematics=Kinematics(u1=u, u2=u), load=Load(gap=h0),
                     model=Model(elasticity="rigid", cavitation="none"), mesh=mesh)

    def exact(x_range):
        x0, x1 = x_range[0] * L, x_range[1] * L
        xg, wg = _gauss_panels(x0, x1, 200)
        d = 1e-4 * L
        dp = (p(xg + d) - p(xg - d)) / (2 * d)
        f_p = float(wg @ (0.5 * (h0 + xg**2 / (2 * R)) * dp))
        return {"p_max": float(analytic.barus_from_reduced(q_max, alpha)),
                "friction_force": f_p, "heat_power": 2 * u * f_p}

    rng = (-10.0, 10.0)
    bp = (float(p(np.array([rng[0] * L]))[0]), float(p(np.array([rng[1] * L]))[0]))
    grids = (101, 201, 401, 801, 1601) if quick else (101, 201, 401, 801, 1601, 3201, 6401)
    settings = [Setting(f"uniform n={n}", (lambda n=n: (scene(n, rng), {"boundary_pressure": bp})),
                        "uniform", n, 1e-8) for n in grids]
    # the solver's default grid (range [-100, 100], 8001 nodes) with its exact end data
    drng = (-100.0, 100.0)
    dbp = (float(p(np.array([drng[0] * L]))[0]), float(p(np.array([drng[1] * L]))[0]))
    settings.append(Setting("defaults", lambda: (scene(None, None), {"boundary_pressure": dbp}),
                            None, None, 1e-8, default=True))
    return Case("kapitsa_line", "Kapitsa rigid cylinder (Barus, full-Sommerfeld)", solve_contact,
                settings, repeats=2, exact={"uniform": exact(rng), "defaults": exact(drng)},
                notes=["gap prescribed: h_central, h_min exact by construction"])


def kapitsa_point_case(quick: bool) -> Case:
    eta, u, r, h0 = KL["eta"], KL["u"], KL["R"], KL["h0"]
    a = b = 1.0 / (2 * r)
    q_max = float(analytic.kapitsa_point_max_reduced(h0, a, b, eta, u))
    alpha = 0.5 / q_max
    L = math.sqrt(2 * r * h0)

    def p(x, y):
        return analytic.kapitsa_point_pressure(x, y, h0, a, b, eta, u, piezo=alpha)

    def scene(nodes, rng):
        mesh = MeshSpec(nodes=(nodes, nodes), x_range=rng, y_range=rng) if rng else \
            MeshSpec(nodes=(nodes, nodes))
        return Scene(title="Kapitsa point", contact=Contact(kind="point", rx=r, ry=r),
                     lubricant=Lubricant(viscosity=eta, piezo=alpha),
                     kinematics=Kinematics(u1=u, u2=u), load=Load(gap=h0),
                     model=Model(elasticity="rigid", cavitation="none"), mesh=mesh)

    def exact(half: float) -> dict:
        # composite Gauss in x; in y the pressure decays fast: same rule
        xg, wx = _gauss_panels(-half * L, half * L, 60 if half > 5 else 12, 12)
        X, Y = np.meshgrid(xg, xg, indexing="ij")
        d = 1e-4 * L
        px = (p(X + d, Y) - p(X - d, Y)) / (2 * d)
        f_p = float(wx @ (0.5 * (h0 + a * X**2 + b * Y**2) * px) @ wx)
        return {"p_max": float(analytic.barus_from_reduced(q_max, alpha)),
                "friction_force": f_p, "heat_power": 2 * u * f_p}

    kw = {"boundary_pressure": p}
    big, small = (-30.0, 30.0), (-3.0, 3.0)
    graded = (41, 81, 161) if quick else (41, 81, 161, 321)
    settings = [Setting(f"graded [-30,30] n={n}", (lambda n=n: (scene(n, None), kw)), "graded", n)
                for n in graded]
    settings += [Setting(f"uniform [-30,30] n={n}", (lambda n=n: (scene(n, big), kw)), "uniform",
                         n) for n in graded]
    small_grids = (21, 41, 81) if quick else (21, 41, 81, 161)
    settings += [Setting(f"uniform [-3,3] n={n}", (lambda n=n: (scene(n, small), kw)),
                         "uniform_small", n) for n in small_grids]
    ex_big = exact(30.0)
    return Case("kapitsa_point", "Kapitsa rigid ball (Barus, full-Sommerfeld)", solve_contact,
                settings, repeats=2,
                exact={"graded": ex_big, "uniform": ex_big, "uniform_small": exact(3.0)},
                notes=["gap prescribed: h_central, h_min exact by construction",
                       "default grid: 161^2 sinh-graded on [-30, 30]^2"])


def martin_case(quick: bool) -> Case:
    eta, u, R, h0 = 0.1, 1.0, 0.01, 1e-6
    L = math.sqrt(2 * R * h0)
    rng = (-20.0, 3.0)
    x0 = rng[0] * L
    xc = float(analytic.martin_outlet_position(h0, R))
    h_star = float(analytic.martin_hstar(h0))

    def scene(nodes):
        return Scene(title="Martin", contact=Contact(kind="line", rx=R),
                     lubricant=Lubricant(viscosity=eta, viscosity_law="constant"),
                     kinematics=Kinematics(u1=u, u2=u), load=Load(gap=h0),
                     model=Model(elasticity="rigid", cavitation="reynolds"),
                     mesh=MeshSpec(nodes=nodes, x_range=rng))

    bp = (float(analytic.martin_pressure(np.array([x0]), h0, R, eta, u)[0]), 0.0)
    xg, wg = _gauss_panels(x0, xc, 200)
    hg = h0 + xg**2 / (2 * R)
    dp = 12 * eta * u * (hg - h_star) / hg**3  # Martin's dp/dx up to the outlet
    f_p = float(wg @ (0.5 * hg * dp))
    exact = {"p_max": float(analytic.martin_max_reduced(h0, R, eta, u)),
             "friction_force": f_p, "heat_power": 2 * u * f_p}
    grids = (101, 201, 401, 801, 1601) if quick else (101, 201, 401, 801, 1601, 3201, 6401)
    settings = [Setting(f"uniform n={n}", (lambda n=n: (scene(n), {"boundary_pressure": bp})),
                        "uniform", n, 1e-8) for n in grids]
    return Case("martin", "Martin rigid isoviscous cylinder (Reynolds outlet)", solve_contact,
                settings, repeats=2, exact={"uniform": exact},
                notes=["gap prescribed: h_central, h_min exact by construction",
                       "free boundary (Reynolds outlet) inside a cell: p_max and F_P converge "
                       "at the order the outlet allows"])


# ---------------------------------------------------------------------------------------
# EHL cases
# ---------------------------------------------------------------------------------------
def grid_tolerance_settings(grids, tols, scene, label: str = "tol={tol:g}") -> list[Setting]:
    """Settings over grids x tolerances: the tightest tolerance on every grid is the
    nested family ("uniform"); looser ones skip the two finest (reference) grids.
    ``scene(n, tol)`` builds the scene of one setting."""
    out = []
    for tol in tols:
        for n in grids:
            if tol != min(tols) and n >= grids[-2]:
                continue
            out.append(Setting(f"n={n} " + label.format(tol=tol),
                               (lambda n=n, tol=tol: (scene(n, tol), {})),
                               "uniform" if tol == min(tols) else None, n, tol))
    return out


def _with_solver(scene: Scene, tol: float | None) -> Scene:
    return replace(scene, solver=SolverSpec() if tol is None else SolverSpec(tolerance=tol))


def graded_line_scene(M: float, L: float, nodes: int, mesh_dir: Path) -> Scene:
    """The Moes (M, L) line scene on a grid of ``nodes`` refined at the outlet spike (a
    grid file in ``mesh_dir``; ``line_graded_grid.graded_scene``)."""
    from line_graded_grid import graded_scene

    return graded_scene(line_moes_scene(M, L), nodes, mesh_dir / f"M{M:g}_L{L:g}")


def line_ehl_case(quick: bool, mesh_dir: Path) -> Case:
    grids = (201, 401, 801, 1601, 3201) if quick else (201, 401, 801, 1601, 3201, 6401, 12801)
    tols = (1e-5, 1e-8) if quick else (1e-4, 1e-6, 1e-8)
    settings = grid_tolerance_settings(
        grids, tols, lambda n, tol: _with_solver(line_moes_scene(MOES_M, MOES_L, n), tol))
    # node counts between the nested ones, at the default tolerance (candidate defaults)
    for n in ((601,) if quick else (601, 1201, 2401)):
        settings.append(Setting(f"n={n} tol=1e-08", (lambda n=n: (_with_solver(
            line_moes_scene(MOES_M, MOES_L, n), 1e-8), {})), None, n, 1e-8))
    # grids refined at the outlet spike (grid files), at the default tolerance
    for n in ((401, 801) if quick else (401, 801, 1601)):
        settings.append(Setting(f"graded n={n}", (lambda n=n: (
            graded_line_scene(MOES_M, MOES_L, n, mesh_dir), {})), "graded", n, 1e-8))
    settings.append(Setting("defaults", lambda: (line_moes_scene(MOES_M, MOES_L), {}),
                            None, None, None, default=True))
    return Case("line_ehl", "EHL line contact, Moes M = 100, L = 10", solve_contact, settings,
                repeats=3 if not quick else 2, reference_family="uniform",
                notes=[SPIKE_NOTE,
                       "h_min is the minimum of the film at the outlet constriction (between "
                       "the nodes included); on uniform grids it converges slowly from below "
                       "until the outlet spike is resolved, on grids graded there at about "
                       "second order"])


def point_ehl_case(quick: bool, ry_over_rx: float = 1.0) -> Case:
    if ry_over_rx == 1.0:
        grids = (33, 65, 129, 257) if quick else (33, 65, 129, 257, 513)
    else:
        grids = (33, 65, 129, 257)
    tols = (1e-5, 1e-8) if quick else (1e-4, 1e-6, 1e-8)

    def scene(n, tol):
        s = point_moes_scene(MOES_M, MOES_L, n or 129, ry_over_rx=ry_over_rx)
        if n is None:
            s = replace(s, mesh=MeshSpec())
        return _with_solver(s, tol)

    settings = grid_tolerance_settings(grids, tols, scene)
    settings.append(Setting("defaults", lambda: (scene(None, None), {}), None, None, None,
                            default=True))
    name = "circular_ehl" if ry_over_rx == 1.0 else "ellipse_ehl"
    title = ("EHL circular contact, Moes M = 100, L = 10" if ry_over_rx == 1.0 else
             f"EHL elliptical contact ry/rx = {ry_over_rx:g}, Moes M = 100, L = 10")
    return Case(name, title, solve_contact, settings, repeats=2 if quick else 3,
                reference_family="uniform",
                notes=[SPIKE_NOTE, f"the finest grid ({grids[-1]}^2) runs like the others"])


def thermal_scene(nodes: int | None, thermal_tol: float | None) -> Scene:
    """The bench's sliding half-space roller with the thermal patch
    (:func:`bearing_fem.bench.thermal_line_scene`) on ``nodes`` with a thermal-loop
    tolerance (None: the defaults)."""
    s = thermal_line_scene()
    if thermal_tol is not None:
        s = replace(s, thermal=replace(s.thermal, tolerance=thermal_tol))
    return replace(s, mesh=MeshSpec(nodes=nodes)) if nodes else s


def thermal_case(quick: bool) -> Case:
    grids = (401, 801, 1601, 3201, 6401)
    settings = grid_tolerance_settings(grids, (2.0, 0.05, 1e-4), thermal_scene,
                                       label="thermal tol={tol:g} K")
    settings.append(Setting("defaults", lambda: (thermal_scene(None, None), {}), None, None, None,
                            default=True))
    return Case("thermal_line", "Thermal line contact (patch, Eyring, sliding)", solve_contact,
                settings, repeats=2, reference_family="uniform",
                notes=["tolerance column: the thermal loop tolerance [K]",
                       SPIKE_NOTE])


def bearing_case(quick: bool) -> Case:
    base = load_example("6209")

    def with_nodes(n):
        if n is None:
            return base
        # each setting on its own grid: no second solve of thin films on a finer one
        return replace(base, mesh=replace(base.mesh, point_nodes=(n, n),
                                          refine_thin_films=False))

    settings = [Setting(f"contacts {n}^2", (lambda n=n: with_nodes(n)),
                        "uniform" if n >= 65 else None, n) for n in (33, 65, 129, 257)]
    settings.append(Setting("defaults", lambda: with_nodes(None), None, None, default=True))
    return Case("bearing_6209", "6209 ball bearing (solve_bearing)", solve_bearing_job, settings,
                repeats=2, reference_family="uniform",
                notes=["friction column: friction torque [N m]; heat power [W]",
                       "h_central, h_min: most loaded inner contact; p_max: the bearing's largest"])


def cases(quick: bool, mesh_dir: Path = Path("out/work_precision/meshes")) -> list[Case]:
    out = [kapitsa_line_case(quick), kapitsa_point_case(quick), martin_case(quick),
           line_ehl_case(quick, mesh_dir), point_ehl_case(quick)]
    if not quick:
        out += [point_ehl_case(quick, ry_over_rx=4.0), thermal_case(quick), bearing_case(quick)]
    return out


# ---------------------------------------------------------------------------------------
# runs, references, orders, targets
# ---------------------------------------------------------------------------------------
def run_case(case: Case, log: Callable[[str], None] = lambda s: None) -> list[dict]:
    """Run every setting ``case.repeats`` times, interleaved; keep the minimum time."""
    load0 = os.getloadavg()[0]
    rows: dict[str, dict] = {}
    for rep in range(case.repeats):
        for st in case.settings:
            job = st.build()
            t0 = time.perf_counter()
            vals = case.solve(job)
            dt = time.perf_counter() - t0
            row = rows.setdefault(st.label, {"case": case.name, "setting": st.label,
                                             "family": st.family, "nodes": st.nodes,
                                             "tolerance": st.tolerance, "default": st.default,
                                             "times": []})
            row["times"].append(dt)
            row.update(vals)
            log(f"{case.name:14s} {st.label:28s} {vals['status']:12s} {dt:8.3f} s")
    load1 = os.getloadavg()[0]
    out = []
    for st in case.settings:
        row = rows[st.label]
        row["time_s"] = min(row["times"])
        row["load_average"] = (load0, load1)
        out.append(row)
    return out


def richardson(coarse: float, fine: float, ratio: float = 2.0,
               order: float = RICHARDSON_ORDER) -> float:
    """Richardson extrapolation of two grid values (spacing ratio ``ratio``)."""
    return fine + (fine - coarse) / (ratio**order - 1.0)


def references(case: Case, rows: list[dict]) -> dict:
    """Per row label: the reference values and their source."""
    refs: dict[str, dict] = {}
    if case.exact is not None:
        for r in rows:
            key = r["family"] if r["family"] in case.exact else r["setting"]
            refs[r["setting"]] = {"values": case.exact.get(key, {}), "source": "exact"}
        return refs
    fam = sorted((r for r in rows if r["family"] == case.reference_family and r["success"]),
                 key=lambda r: r["nodes"])
    if len(fam) < 2:
        return {r["setting"]: {"values": {}, "source": "none"} for r in rows}
    c, f = fam[-2], fam[-1]
    vals, unc = {}, {}
    for k in QUANTITIES:
        if c.get(k) is None or f.get(k) is None:
            continue
        ratio = (f["nodes"] - 1) / (c["nodes"] - 1)
        vals[k] = richardson(c[k], f[k], ratio)
        unc[k] = abs(f[k] / vals[k] - 1.0) if vals[k] else math.nan
    src = f"Richardson p=2 from {c['nodes']} and {f['nodes']} nodes"
    observed = {}
    if len(fam) >= 3:  # the order the three finest grids show (a check of p = 2)
        g3 = fam[-3:]
        for k in vals:
            d1, d2 = g3[1][k] - g3[0][k], g3[2][k] - g3[1][k]
            observed[k] = (math.log(abs(d1 / d2)) / math.log(2.0)
                           if d1 != 0.0 and d2 != 0.0 and d1 * d2 > 0 else None)
    for r in rows:
        refs[r["setting"]] = {"values": vals, "source": src, "uncertainty": unc,
                              "observed_order": observed}
    c["reference_grid"] = "coarse"
    f["reference_grid"] = "finest"
    return refs


def add_errors(case: Case, rows: list[dict]) -> dict:
    refs = references(case, rows)
    for r in rows:
        ref = refs[r["setting"]]
        r["reference"] = ref["source"]
        for k in QUANTITIES:
            v, e = r.get(k), ref["values"].get(k)
            r[f"{k}_error"] = (abs(v / e - 1.0) if (v is not None and e not in (None, 0.0)
                                                    and r["success"]) else None)
    any_ref = next(iter(refs.values()), {})
    return {"source": any_ref.get("source"), "uncertainty": any_ref.get("uncertainty", {}),
            "values": any_ref.get("values", {}),
            "observed_order": any_ref.get("observed_order", {})}


def fitted_orders(case: Case, rows: list[dict]) -> dict:
    """Least-squares log-log slope of the error against the spacing, per family and
    quantity (grids making the Richardson reference excluded)."""
    out: dict[str, dict] = {}
    fams = sorted({r["family"] for r in rows if r["family"]})
    for fam in fams:
        fr = sorted((r for r in rows if r["family"] == fam and r["success"]),
                    key=lambda r: r["nodes"])
        if case.exact is None and fam == case.reference_family:
            fr = fr[:-2]
        out[fam] = {}
        for k in QUANTITIES:
            pts = [(1.0 / (r["nodes"] - 1), r[f"{k}_error"]) for r in fr
                   if r.get(f"{k}_error") not in (None, 0.0)]
            if len(pts) < 2:
                out[fam][k] = None
                continue
            h, e = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
            out[fam][k] = {"order": float(np.polyfit(h, e, 1)[0]), "grids": len(pts),
                           "nodes": [r["nodes"] for r in fr]}
    return out


def _meets(r: dict, target: float) -> bool:
    return (r["success"] and r.get("h_central_error") is not None
            and r.get("h_min_error") is not None
            and r["h_central_error"] <= target and r["h_min_error"] <= target)


def _brief(r: dict, **extra) -> dict:
    return {"setting": r["setting"], "time_s": r["time_s"], "dofs": r["dofs"],
            "h_central_error": r["h_central_error"], "h_min_error": r["h_min_error"], **extra}


def cheapest(rows: list[dict], target: float) -> dict | None:
    """The fastest successful row with both h_central and h_min errors <= target.

    The finest reference grid is a candidate only when nothing else reaches the target
    (then ``estimate_only`` is True: its error is by construction a third of its change
    from the next coarser grid, an estimate, not a measurement).
    """
    ok = [r for r in rows if r.get("reference_grid") != "finest" and _meets(r, target)]
    if ok:
        return _brief(min(ok, key=lambda r: r["time_s"]), estimate_only=False)
    fin = [r for r in rows if r.get("reference_grid") == "finest" and _meets(r, target)]
    return _brief(fin[0], estimate_only=True) if fin else None


def cheapest_robust(rows: list[dict], target: float) -> dict | None:
    """The fastest row that reaches the target together with every row on at least as
    many unknowns (any tolerance), so that a lucky coarse grid whose error happens to dip
    (h_min between nodes) does not count. The finest reference grid is excluded."""
    pool = [r for r in rows if r.get("reference_grid") != "finest"]
    cands = [r for r in pool if all(_meets(x, target) for x in pool if x["dofs"] >= r["dofs"])]
    return _brief(min(cands, key=lambda r: r["time_s"])) if cands else None


def target_report(rows: list[dict], ref: dict) -> dict:
    d = next(r for r in rows if r["default"])
    out = {"defaults": {"time_s": d["time_s"], "dofs": d["dofs"],
                        "h_central_error": d["h_central_error"],
                        "h_min_error": d["h_min_error"]},
           "reference_uncertainty": {k: ref["uncertainty"].get(k)
                                     for k in ("h_central", "h_min")}}
    for t in TARGETS:
        out[f"{t:g}"] = cheapest(rows, t)
        out[f"{t:g}_robust"] = cheapest_robust(rows, t)
    f1, r1 = out["0.01"], out["0.01_robust"]
    meets = _meets(d, 0.01)
    out["defaults_meet_1pct"] = bool(meets)
    out["defaults_time_ratio"] = d["time_s"] / f1["time_s"] if f1 else None
    out["defaults_within_factor"] = bool(meets and out["defaults_time_ratio"]
                                         <= DEFAULT_TIME_FACTOR)
    out["defaults_time_ratio_robust"] = d["time_s"] / r1["time_s"] if r1 else None
    out["defaults_within_factor_robust"] = bool(
        meets and r1 is not None and out["defaults_time_ratio_robust"] <= DEFAULT_TIME_FACTOR)
    return out


# ---------------------------------------------------------------------------------------
# output
# ---------------------------------------------------------------------------------------
def _fmt(v, spec=".3g") -> str:
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    return format(v, spec)


def _write_atomic(path: Path, text: str) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def write_runs_csv(path: Path, rows: list[dict]) -> None:
    cols = ["case", "setting", "family", "nodes", "tolerance", "default", "status", "dofs",
            "newton_iterations", "time_s", "reference", "reference_grid"] + list(QUANTITIES) + \
        [f"{k}_error" for k in QUANTITIES]
    tmp = path.with_name(path.name + ".tmp")
    with tmp.open("w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    os.replace(tmp, path)


def markdown(results: dict) -> str:
    lines = [f"# Work against precision\n",
             f"Written by `python studies/work_precision.py OUTDIR"
             f"{' --quick' if results['quick'] else ''}` on {results['machine']['timestamp']} "
             f"({results['machine']['cpu_count']} CPUs, {results['machine']['platform']}). "
             "Times are the minimum of interleaved repeats on a possibly shared machine "
             "(load averages in the case headers).\n"]
    for name, c in results["cases"].items():
        la = c["load_average"]
        lines.append(f"## {c['title']} (`{name}`)\n")
        lines.append(f"Reference: {c['reference']['source']}. Load average "
                     f"{la[0]:.2f} -> {la[1]:.2f}.")
        if c["reference"].get("uncertainty"):
            u = c["reference"]["uncertainty"]
            lines.append("Reference uncertainty (|finest/reference - 1|): " + ", ".join(
                f"{k} {_fmt(v, '.1e')}" for k, v in u.items()) + ".")
        if c["reference"].get("observed_order"):
            o = c["reference"]["observed_order"]
            lines.append("Order observed on the three finest grids (p = 2 assumed by the "
                         "reference): " + ", ".join(f"{k} {_fmt(v, '.2f')}" for k, v in o.items())
                         + ".")
        for n in c["notes"]:
            lines.append(f"- {n}")
        lines.append("")
        lines.append("| setting | status | unknowns | Newton it. | time s | "
                     + " | ".join(f"{k} err" for k in QUANTITIES) + " |")
        lines.append("|---|---|---|---|---|" + "---|" * len(QUANTITIES))
        for r in c["rows"]:
            mark = {"finest": " (reference, finest)", "coarse": " (reference, coarse)"}.get(
                r.get("reference_grid"), "")
            lines.append(f"| {r['setting']}{mark} "
                         f"| {r['status']} | {r['dofs']} | {r['newton_iterations']} | "
                         f"{r['time_s']:.3f} | "
                         + " | ".join(_fmt(r.get(f'{k}_error'), '.2e') for k in QUANTITIES)
                         + " |")
        lines.append("")
        fits = "; ".join(f"{fam}: " + ", ".join(f"{k} {v['order']:.2f}" for k, v in q.items()
                                               if v)
                         for fam, q in c["orders"].items() if any(q.values()))
        lines.append("Fitted orders (error ~ spacing^order): "
                     + (fits or "none (fewer than two grids below the reference grids)") + "\n")
    lines.append("## Cheapest settings reaching the targets (h_central and h_min)\n")
    lines.append("'fastest': the fastest setting whose errors reach the target; 'robust': "
                 "the fastest whose errors reach it together with every setting on at least "
                 "as many unknowns. Errors against the reference named in the case section.\n")
    lines.append("| case | target | kind | setting | time s | unknowns | h_central err | "
                 "h_min err |")
    lines.append("|---|---|---|---|---|---|---|---|")
    for name, t in results["targets"].items():
        for tgt in TARGETS:
            for kind in ("", "_robust"):
                b = t[f"{tgt:g}{kind}"]
                label = "robust" if kind else "fastest"
                if b is None:
                    lines.append(f"| {name} | {100 * tgt:g} % | {label} | none reached below "
                                 "the finest grid | - | - | - | - |")
                    continue
                est = " (finest grid: estimate only)" if b.get("estimate_only") else ""
                lines.append(f"| {name} | {100 * tgt:g} % | {label} | {b['setting']}{est} | "
                             f"{b['time_s']:.3f} | {b['dofs']} | {b['h_central_error']:.2e} | "
                             f"{b['h_min_error']:.2e} |")
        d = t["defaults"]
        lines.append(f"| {name} | - | defaults | defaults | {d['time_s']:.3f} | {d['dofs']} | "
                     f"{_fmt(d['h_central_error'], '.2e')} | {_fmt(d['h_min_error'], '.2e')} |")
    lines.append("")
    for name, t in results["targets"].items():
        ok = "met" if t["defaults_within_factor"] else "NOT met"
        okr = "met" if t["defaults_within_factor_robust"] else "NOT met"
        lines.append(f"- {name}: defaults reach 1 % in h_central and h_min: "
                     f"{t['defaults_meet_1pct']}; defaults time / fastest 1 % time = "
                     f"{_fmt(t['defaults_time_ratio'], '.2f')} (<= {DEFAULT_TIME_FACTOR}: {ok}); "
                     f"/ robust 1 % time = {_fmt(t['defaults_time_ratio_robust'], '.2f')} "
                     f"({okr})")
    return "\n".join(lines) + "\n"


def figures(outdir: Path, results: dict) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    markers = dict(zip(QUANTITIES, "osd^v"))
    for name, c in results["cases"].items():
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
        for k in QUANTITIES:
            pts = [(r["time_s"], r["dofs"], r[f"{k}_error"]) for r in c["rows"]
                   if r.get(f"{k}_error") not in (None, 0.0)]
            if not pts:
                continue
            t, n, e = zip(*pts)
            axes[0].loglog(t, e, markers[k], label=k, alpha=0.75)
            axes[1].loglog(n, e, markers[k], label=k, alpha=0.75)
        d = next((r for r in c["rows"] if r["default"]), None)
        for ax, xkey in zip(axes, ("time_s", "dofs")):
            for tgt in TARGETS:
                ax.axhline(tgt, color="grey", lw=0.6, ls="--")
            if d is not None and d.get("h_central_error"):
                ax.loglog([d[xkey]], [d["h_central_error"]], "k*", ms=12, label="defaults (h_c)")
            ax.set_ylabel("relative error")
            ax.grid(True, which="both", lw=0.3)
        axes[0].set_xlabel("wall time [s] (min of repeats)")
        axes[1].set_xlabel("unknowns")
        axes[1].legend(fontsize=7)
        fig.suptitle(f"{c['title']}: error vs work (reference: {c['reference']['source']})",
                     fontsize=9)
        fig.tight_layout()
        fig.savefig(outdir / f"wp_{name}.png", dpi=110)
        plt.close(fig)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for name in results["targets"]:
        rows = [r for r in results["cases"][name]["rows"] if r.get("h_central_error")]
        t = [r["time_s"] for r in rows]
        e = [max(r["h_central_error"], r["h_min_error"] or 0.0) for r in rows]
        ax.loglog(t, e, "o", label=name, alpha=0.7)
        d = next(r for r in rows if r["default"]) if any(r["default"] for r in rows) else None
        if d is not None:
            ax.loglog([d["time_s"]], [max(d["h_central_error"], d["h_min_error"] or 0)], "k*",
                      ms=12)
    for tgt in TARGETS:
        ax.axhline(tgt, color="grey", lw=0.6, ls="--")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("max(h_central, h_min) relative error")
    ax.set_title("Moes M = 100, L = 10 (star: defaults)", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(outdir / "wp_targets.png", dpi=110)
    plt.close(fig)


# ---------------------------------------------------------------------------------------
# line default density over the Moes map (evidence for the line default)
# ---------------------------------------------------------------------------------------
#: Moes points of the check and the node densities tried, as fractions of the default.
DENSITY_CASES = tuple((M, L) for M in (20, 100, 200, 500) for L in (5, 10, 20))
DENSITY_FRACTIONS = (0.5, 0.75, 1.0, 1.5)


def _nodes_fraction(n_default: int, fraction: float) -> int:
    """Node count with ``fraction`` of the default density, N - 1 divisible by 4."""
    return 4 * max(2, round(fraction * (n_default - 1) / 4)) + 1


def line_density_check(repeats: int = 2, log: Callable[[str], None] = lambda s: None) -> list[dict]:
    """h_central and h_min errors of the line solver at fractions of its default node
    density, for Moes points over the map; reference: Richardson (p = 2) from 2 N - 1 and
    4 N - 3 nodes (N the default count). Times: minimum of ``repeats`` interleaved runs."""
    from line_ehl_map import default_nodes

    out = []
    for M, L in DENSITY_CASES:
        n_def = default_nodes(M, L)
        fine = [2 * n_def - 1, 4 * n_def - 3]
        vals = {}
        for n in fine:
            vals[n] = _summary_values(bf.solve(line_moes_scene(M, L, n)))
        row = {"M": M, "L": L, "default_nodes": n_def, "status": vals[fine[1]]["status"]}
        if not all(v["success"] for v in vals.values()):
            row["error"] = "reference grids did not converge"
            out.append(row)
            log(f"density M={M} L={L}: reference failed")
            continue
        ref = {k: richardson(vals[fine[0]][k], vals[fine[1]][k]) for k in ("h_central", "h_min")}
        runs: dict[float, dict] = {}
        for _ in range(repeats):
            for f in DENSITY_FRACTIONS:
                n = _nodes_fraction(n_def, f) if f != 1.0 else None
                t0 = time.perf_counter()
                v = _summary_values(bf.solve(line_moes_scene(M, L, n)))
                dt = time.perf_counter() - t0
                r = runs.setdefault(f, {"nodes": v["dofs"], "times": []})
                r["times"].append(dt)
                r.update(status=v["status"], success=v["success"],
                         h_central_error=abs(v["h_central"] / ref["h_central"] - 1)
                         if v["success"] else None,
                         h_min_error=abs(v["h_min"] / ref["h_min"] - 1) if v["success"] else None)
        for f, r in runs.items():
            r["time_s"] = min(r["times"])
            del r["times"]
        row["fractions"] = {f"{f:.3f}": r for f, r in runs.items()}
        out.append(row)
        log(f"density M={M} L={L}: " + ", ".join(
            f"{f}: {r['nodes']} {_fmt(r['h_central_error'], '.1e')}/{_fmt(r['h_min_error'], '.1e')}"
            f" {r['time_s']:.3f}s" for f, r in row["fractions"].items()))
    return out


def density_markdown(rows: list[dict]) -> str:
    heads = " | ".join(f"{f:.2f} x default: nodes, h_c err, h_min err, s"
                       for f in DENSITY_FRACTIONS)
    lines = ["## Line node density over the Moes map\n",
             "Errors of h_central and h_min at fractions of the default node density "
             "(the default: 800/6 (M/100)^0.75 nodes per Hertz half-width, at least 801 "
             "nodes: 801 at M = 100) against "
             "Richardson (p = 2) from 2N - 1 and 4N - 3 nodes; minimum of interleaved "
             "times.\n",
             f"| M | L | {heads} |", "|---|---|" + "---|" * len(DENSITY_FRACTIONS)]
    for r in rows:
        if "fractions" not in r:
            lines.append(f"| {r['M']} | {r['L']} | " + " | ".join(
                [r.get("error", "-")] * len(DENSITY_FRACTIONS)) + " |")
            continue
        cells = []
        for f in DENSITY_FRACTIONS:
            x = r["fractions"][f"{f:.3f}"]
            cells.append(f"{x['nodes']}, {_fmt(x['h_central_error'], '.1e')}, "
                         f"{_fmt(x['h_min_error'], '.1e')}, {x['time_s']:.3f}")
        lines.append(f"| {r['M']} | {r['L']} | " + " | ".join(cells) + " |")
    def film_error(x: dict) -> float:  # a failed solve counts as 100 %
        e = (x["h_central_error"], x["h_min_error"])
        return 1.0 if None in e else max(e)

    worst = {f"{f:.3f}": max((film_error(r["fractions"][f"{f:.3f}"])
                              for r in rows if "fractions" in r), default=None)
             for f in DENSITY_FRACTIONS}
    lines.append("")
    lines.append("Largest film error over the map: " + ", ".join(
        f"{float(k):.2f} x default {_fmt(v, '.1e')}" for k, v in worst.items()) + ".")
    return "\n".join(lines) + "\n"


def machine() -> dict:
    """The machine (:func:`bearing_fem.bench.machine_info`), package version, timestamp."""
    return {**machine_info(), "bearing_fem": bf.__version__,
            "timestamp": time.strftime("%Y-%m-%d %H:%M:%S %Z")}


def main(outdir, quick: bool = False, verbose: bool = False) -> dict:
    """Run the study; write its tables and figures into ``outdir``; return the numbers."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    log = print if verbose else (lambda s: None)
    results: dict[str, Any] = {"quick": quick, "machine": machine(), "cases": {},
                               "targets": {}}
    all_rows: list[dict] = []
    for case in cases(quick, out / "meshes"):
        rows = run_case(case, log)
        ref = add_errors(case, rows)
        orders = fitted_orders(case, rows)
        results["cases"][case.name] = {
            "title": case.title, "rows": rows, "reference": ref, "orders": orders,
            "notes": case.notes, "load_average": rows[0]["load_average"]}
        if case.name in ("line_ehl", "circular_ehl"):
            results["targets"][case.name] = target_report(rows, ref)
        all_rows += rows
    if not quick:
        results["line_density"] = line_density_check(log=log)
    write_runs_csv(out / "runs.csv", all_rows)
    with (out / "orders.csv.tmp").open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["case", "family", "quantity", "order", "grids", "nodes"])
        for name, c in results["cases"].items():
            for fam, q in c["orders"].items():
                for k, v in q.items():
                    if v:
                        w.writerow([name, fam, k, f"{v['order']:.3f}", v["grids"],
                                    " ".join(map(str, v["nodes"]))])
    os.replace(out / "orders.csv.tmp", out / "orders.csv")
    md = markdown(results)
    if results.get("line_density"):
        md += "\n" + density_markdown(results["line_density"])
    _write_atomic(out / "work_precision.md", md)
    _write_atomic(out / "targets.md", md[md.index("## Cheapest"):])
    _write_atomic(out / "summary.json", json.dumps(results, indent=1, default=str))
    figures(out, results)
    return results


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/work_precision")
    parser.add_argument("--quick", action="store_true")
    a = parser.parse_args()
    res = main(a.outdir, quick=a.quick, verbose=True)
    print(Path(a.outdir, "targets.md").read_text())

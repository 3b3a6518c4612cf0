"""Can a user trust the error bar on every number? Error estimates against true errors,
and the energy balance of the heat power.

Question
--------
Every successful solve reports ``error_estimate``: the estimated relative discretisation
error of h_central, h_min, p_max, friction_force and heat_power, by Richardson
extrapolation with the observed order over the solution and the same scene on two
coarser grids (each with twice the spacing), or the plain level difference where the
order is not observable. Does it predict the true error?

1. **Oracles** (exact solutions, computed from the closed forms of
   :mod:`bearing_fem.analytic`): Martin's rigid isoviscous cylinder with a Reynolds
   outlet and Kapitsa's rigid piezo-viscous ball (full-Sommerfeld), both with the exact
   pressure as Dirichlet data, each at three resolutions. Quantities: p_max (closed
   form), rolling friction F_P = int (h/2) dp/dx dA and the Poiseuille heat
   2 u_m F_P (Gauss quadrature of the closed-form pressure). Target: the estimate within
   a factor 3 of the true error.
2. **EHL maps**: the line map (Moes M 5-1000, L 0-20, alpha p_h <= 100) and the circular
   map (M 20-500, L 5-20, alpha p_h <= 40) on the solver's default grids. The truth is
   the change to a solve on a twice-finer grid. Target: within a factor 3 in at least
   90% of the cases, per quantity. Pairs where both the estimate and the change are
   below ``FLOOR`` (the Newton tolerance's reach) count as agreeing.
3. **Bearings**: the error bar of a bearing's friction torque, heat power, h_min and
   p_max (from its contacts' estimates, ``BearingResult.summary()["error_estimate"]``)
   against the change to the same bearing with twice-finer contact grids: the 6209 ball
   bearing at its default 129^2 (against 257^2) and the NNCF 5040 roller bearing on its
   default line grids (against 2N - 1 nodes, ~80 s); quick: 6209 only.
4. **What the levels can tell** (``estimator_ceiling``): every estimate made from the
   grid sequence is a function of its level differences. With d2 the last difference
   (solution minus the level below) and d3 the change to the twice-finer solve, any
   estimate c |d2| agrees only where |d3/d2| lies in a window of width FACTOR^2: the
   share reached by the best constant c, fitted to these very data, bounds every rule
   with one constant; the best constant per map kind and quantity (ten constants, also
   fitted after the fact) bounds the rules that treat each kind and quantity alike; the
   correlation of log|d3/d2| with log|d2/d1| over the map says whether the trend of the
   coarser levels (the observed order) predicts the next change at all. Rules of other
   forms are not bounded by these shares. ``intermediate_check`` then asks whether a
   fourth solve, on 4/3 times the default spacing (finer than the coarsest level, which
   is the least asymptotic), would do: Richardson over the spacings h, 4h/3 and 2h.
5. **Energy balance** of the same map solves: the heat power uses the conservative
   Poiseuille form Q_P = u_m int h dp/dx dA; the discrete physical dissipation
   int h^3 |grad p|^2/(12 eta) dA plus the numerical dissipation of the stabilisation
   must add up to it (the discrete weak form tested with the pressure itself), and Q_P
   must be grid-converged (its change to the twice-finer grid). The balance equals
   sum_i p_i R_i, R_i the nodal residual, so any row whose residual is not small against
   its own fluxes spoils it (the far inlet did, at 1e-9 p_h, until the complementarity
   smoothing was scaled per row: ``bearing_fem.contacts.problem.row_smoothing``); the
   full run follows it over node counts for M = 1000, L = 5
   (``energy.line_balance_grids`` in ``summary.json``).

Run ``python studies/error_estimates.py OUT [--quick]``; writes ``oracles.csv``,
``maps.csv``, ``bearings.csv``, ``summary.json`` and ``estimates.png`` into OUT.
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

import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bearing_fem as bf  # noqa: E402
from bearing_fem import analytic, post, units  # noqa: E402
from bearing_fem.contacts.line import line_setup  # noqa: E402
from bearing_fem.contacts.point import solve_point  # noqa: E402
from bearing_fem.post import ESTIMATED_QUANTITIES  # noqa: E402
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, MeshSpec, Model,  # noqa: E402
                               Scene)

#: Acceptance: estimate/true within [1/FACTOR, FACTOR].
FACTOR = 3.0
#: Share of map cases that must meet it, per quantity.
SHARE = 0.90
#: Relative changes below this are at the Newton tolerance's reach: an estimate and a
#: change both below it agree.
FLOOR = 1e-5
#: Line map and circular map limits (as the map studies).
LINE_M = (5, 10, 20, 50, 100, 200, 500, 1000)
LINE_L = (0, 2, 5, 10, 15, 20)
LINE_MAX_ALPHA_PH = 100.0
POINT_M = (20, 50, 100, 200, 500)
POINT_L = (5, 10, 20)
POINT_MAX_ALPHA_PH = 40.0
POINT_NODES = 129
QUANTITIES = ESTIMATED_QUANTITIES


def agree(estimate: float | None, truth: float) -> bool:
    """The estimate within a factor FACTOR of the true relative error (or both below
    FLOOR)."""
    if estimate is None or not math.isfinite(truth):
        return False
    if estimate < FLOOR and truth < FLOOR:
        return True
    if estimate <= 0.0 or truth <= 0.0:
        return False
    return 1.0 / FACTOR <= estimate / truth <= FACTOR


# ---------------------------------------------------------------------------------------
# oracles
# ---------------------------------------------------------------------------------------
def _gauss(a: float, b: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    t, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * t + 0.5 * (b + a), 0.5 * (b - a) * w


def martin_case(nodes: int) -> dict:
    """Martin's cylinder (rigid, isoviscous, Reynolds outlet, gap h0) on ``nodes``."""
    eta, u, R, h0 = 0.1, 1.0, 0.01, 1e-6
    L = math.sqrt(2 * R * h0)
    x_range = (-20.0, 3.0)
    scene = Scene(title="Martin", contact=Contact(kind="line", rx=R),
                  lubricant=Lubricant(viscosity=eta, viscosity_law="constant"),
                  kinematics=Kinematics(u1=u, u2=u), load=Load(gap=h0),
                  model=Model(elasticity="rigid", cavitation="reynolds"),
                  mesh=MeshSpec(nodes=nodes, x_range=x_range))
    x0 = x_range[0] * L
    bp = (float(analytic.martin_pressure(np.array([x0]), h0, R, eta, u)[0]), 0.0)
    res = bf.solve(scene, boundary_pressure=bp)
    xc = float(analytic.martin_outlet_position(h0, R))
    # exact numbers: p_max on a fine sampling refined by a parabola, F_P by Gauss
    xs = np.linspace(x0, xc, 200001)
    ps = analytic.martin_pressure(xs, h0, R, eta, u)
    p_max = float(ps.max())
    xg, wg = _gauss(x0, xc, 400)
    dp = np.gradient(analytic.martin_pressure(xs, h0, R, eta, u), xs)
    f_p = float(wg @ (0.5 * (h0 + xg**2 / (2 * R)) * np.interp(xg, xs, dp)))
    exact = {"p_max": p_max, "friction_force": f_p, "heat_power": 2 * u * f_p}
    return _oracle_row("martin", nodes, res, exact)


def kapitsa_case(nodes: int) -> dict:
    """Kapitsa's rigid ball, Barus (alpha q_max = 0.5), full-Sommerfeld, on nodes^2."""
    eta, u, r, h0 = 0.05, 2.0, 0.01, 1e-6
    a = b = 1.0 / (2 * r)
    q_max = float(analytic.kapitsa_point_max_reduced(h0, a, b, eta, u))
    alpha = 0.5 / q_max
    scene = Scene(title="Kapitsa", contact=Contact(kind="point", rx=r, ry=r),
                  lubricant=Lubricant(viscosity=eta, piezo=alpha),
                  kinematics=Kinematics(u1=u, u2=u), load=Load(gap=h0),
                  model=Model(elasticity="rigid", cavitation="none"),
                  mesh=MeshSpec(nodes=(nodes, nodes), x_range=(-3.0, 3.0),
                                y_range=(-3.0, 3.0)))

    def exact_p(x, y):
        return analytic.kapitsa_point_pressure(x, y, h0, a, b, eta, u, piezo=alpha)

    res = solve_point(scene, boundary_pressure=exact_p)
    L = math.sqrt(2 * r * h0)
    xg, wx = _gauss(-3 * L, 3 * L, 300)
    X, Y = np.meshgrid(xg, xg, indexing="ij")
    W = np.outer(wx, wx)
    d = 1e-3 * L
    px = (exact_p(X + d, Y) - exact_p(X - d, Y)) / (2 * d)
    f_p = float(np.sum(W * 0.5 * (h0 + a * X**2 + b * Y**2) * px))
    p_max = float(analytic.barus_from_reduced(q_max, alpha))
    exact = {"p_max": p_max, "friction_force": f_p, "heat_power": 2 * u * f_p}
    return _oracle_row("kapitsa", nodes, res, exact)


def _oracle_row(case: str, nodes: int, res, exact: dict) -> dict:
    row = {"case": case, "nodes": nodes, "status": res.status}
    est = res.error_estimate or {}
    for k, v in exact.items():
        num = res.quantities.get(k, math.nan)
        truth = abs(num / v - 1.0)
        row[f"{k}_true"] = truth
        row[f"{k}_estimate"] = est.get(k)
        row[f"{k}_method"] = (est.get("method") or {}).get(k)
        row[f"{k}_agree"] = agree(est.get(k), truth)
    return row


# ---------------------------------------------------------------------------------------
# EHL maps
# ---------------------------------------------------------------------------------------
def line_scene(M: float, L: float, nodes: int | None = None) -> Scene:
    from line_ehl_map import scene_for

    return scene_for(M, L, nodes)


def point_scene(M: float, L: float, nodes: int) -> Scene:
    from point_ehl_map import moes_scene

    return moes_scene(M, L, nodes)


def _alpha_ph(scene: Scene) -> float:
    s, lub = scene, scene.lubricant
    args = (s.e_prime, lub.viscosity, s.kinematics.mean_speed, lub.piezo)
    if s.contact.kind == "line":
        return units.moes_line(s.load.force, s.contact.rx, *args)["alpha_ph"]
    return units.moes_point(s.load.force, s.contact.rx, s.contact.ry, *args)["alpha_ph"]


def line_cases(quick: bool) -> list[tuple[float, float]]:
    if quick:
        return [(20, 5), (100, 10)]
    return [(M, L) for M in LINE_M for L in LINE_L
            if _alpha_ph(line_scene(M, L)) <= LINE_MAX_ALPHA_PH]


def point_cases(quick: bool) -> list[tuple[float, float]]:
    if quick:
        return [(100, 10)]
    return [(M, L) for M in POINT_M for L in POINT_L
            if _alpha_ph(point_scene(M, L, 33)) <= POINT_MAX_ALPHA_PH]


def map_row(kind: str, M: float, L: float, coarse, fine, between=None) -> dict:
    """Estimate of the default-grid solve against its change to the twice-finer solve;
    ``between`` (optional) is the solve with 4/3 times the default spacing, for
    :func:`intermediate_check`."""
    row = {"kind": kind, "M": M, "L": L, "status": coarse.status,
           "fine_status": fine.status, "nodes": coarse.dofs, "fine_nodes": fine.dofs,
           "seconds": coarse.wall_time_s, "fine_seconds": fine.wall_time_s}
    if between is not None:
        row["between_status"] = between.status
        row["between_seconds"] = between.wall_time_s
        for k in QUANTITIES:
            row[f"{k}_between"] = between.quantities.get(k) if between.success else None
    est = coarse.error_estimate or {}
    for k in QUANTITIES:
        c, f = coarse.quantities.get(k, math.nan), fine.quantities.get(k, math.nan)
        truth = abs(c / f - 1.0) if f else math.nan
        row[f"{k}_change"] = truth
        row[f"{k}_estimate"] = est.get(k)
        row[f"{k}_method"] = (est.get("method") or {}).get(k)
        row[f"{k}_agree"] = agree(est.get(k), truth)
        # the grid sequence behind the estimate, then the twice-finer solve
        row[f"{k}_values"] = json.dumps((est.get("values") or {}).get(k, []) + [f])
    q = coarse.quantities
    qp = q["heat_power_poiseuille"]
    row["heat_poiseuille"] = qp
    row["heat_poiseuille_direct"] = q["heat_power_poiseuille_direct"]
    row["heat_stabilisation"] = q["heat_power_stabilisation"]
    row["energy_balance_residual"] = abs(q["heat_power_poiseuille_direct"]
                                         + q["heat_power_stabilisation"] - qp) / abs(qp)
    row["direct_vs_conservative"] = q["heat_power_poiseuille_direct"] / qp - 1.0
    row["poiseuille_heat_change"] = abs(qp / fine.quantities["heat_power_poiseuille"] - 1.0)
    return row


def run_maps(quick: bool) -> list[dict]:
    rows = []
    for M, L in line_cases(quick):
        base = line_scene(M, L)
        n = base.mesh.nodes or line_setup(base).disc.x.size
        if quick:
            n = 601
        coarse = bf.solve(line_scene(M, L, n))
        fine = bf.solve(line_scene(M, L, 2 * n - 1))
        between = bf.solve(line_scene(M, L, _three_quarters(n)))
        rows.append(map_row("line", M, L, coarse, fine, between))
        print(_brief(rows[-1]), flush=True)
    for M, L in point_cases(quick):
        n = 65 if quick else POINT_NODES
        coarse = solve_point(point_scene(M, L, n))
        fine = solve_point(point_scene(M, L, 2 * n - 1))
        between = solve_point(point_scene(M, L, _three_quarters(n)))
        rows.append(map_row("point", M, L, coarse, fine, between))
        print(_brief(rows[-1]), flush=True)
    return rows


def _three_quarters(nodes: int) -> int:
    """Node count (per side) with 4/3 times the spacing of ``nodes`` (4k + 1)."""
    return 3 * (nodes - 1) // 4 + 1


#: Bearing checks: (example, contact grid or None for the defaults, quick).
BEARING_CASES = (("6209", 129, True), ("nncf5040", None, False))
BEARING_QUANTITIES = ("friction_torque", "heat_power", "h_min", "p_max")


def _bearing_on(name: str, nodes: int | None, finer: bool = False):
    """A shipped bearing example with its contact grids set (``nodes``: point grids n^2;
    None: the defaults) or twice finer (2n - 1 per direction, or 2N - 1 line nodes)."""
    from bearing_fem.bearing import load_example
    from bearing_fem.contacts.line import line_setup

    b = load_example(name)
    if b.geometry.is_ball:
        n = nodes or 129
        n = 2 * n - 1 if finer else n
        return replace(b, mesh=replace(b.mesh, point_nodes=(n, n)))
    if not finer:
        return b
    from bearing_fem.bearing.contacts import contact_specs
    from bearing_fem.bearing.kinematics import element_kinematics
    from bearing_fem.bearing.loads import distribute_loads

    dist = distribute_loads(b)
    g, op = b.geometry, b.operation
    kin = element_kinematics(op.inner_speed, g.mean_diameter, g.element_diameter,
                             dist.alpha_inner, dist.alpha_outer)
    sizes = {line_setup(sc).disc.x.size for spec in contact_specs(b, dist, kin)
             if spec.excluded is None for sc in spec.scenes}
    if len(sizes) != 1:  # one line_nodes for every contact: only "twice finer" if one size
        raise ValueError(f"{name}: default line grids of {sorted(sizes)} nodes")
    return replace(b, mesh=replace(b.mesh, line_nodes=2 * sizes.pop() - 1))


def run_bearings(quick: bool) -> list[dict]:
    """Each bearing's estimate against the change to twice-finer contact grids."""
    from bearing_fem.bearing import solve_bearing

    rows = []
    for name, nodes, in_quick in BEARING_CASES:
        if quick and not in_quick:
            continue
        coarse = solve_bearing(_bearing_on(name, nodes))
        fine = solve_bearing(_bearing_on(name, nodes, finer=True))
        sc, sf = coarse.summary(), fine.summary()
        row = {"bearing": name, "contacts": f"{nodes}^2" if nodes else "defaults",
               "status": coarse.status, "fine_status": fine.status,
               "seconds": coarse.wall_time_s, "fine_seconds": fine.wall_time_s}
        est = sc.get("error_estimate") or {}
        for k in BEARING_QUANTITIES:
            c, f = sc.get(k), sf.get(k)
            truth = abs(c / f - 1.0) if (c is not None and f) else math.nan
            row[f"{k}_change"] = truth
            row[f"{k}_estimate"] = est.get(k)
            row[f"{k}_agree"] = agree(est.get(k), truth)
        rows.append(row)
        print(f"bearing {name} {row['contacts']}: " + "  ".join(
            f"{k} {row[f'{k}_change']:.1e}/{row[f'{k}_estimate'] or float('nan'):.1e}"
            for k in BEARING_QUANTITIES), flush=True)
    return rows


def _brief(row: dict) -> str:
    parts = [f"{row['kind']} M={row['M']:g} L={row['L']:g} {row['status']}"]
    for k in QUANTITIES:
        e = row[f"{k}_estimate"]
        parts.append(f"{k} {row[f'{k}_change']:.1e}/{e if e is None else f'{e:.1e}'}")
    return "  ".join(parts)


# ---------------------------------------------------------------------------------------
def main(outdir: str | Path = "out/error_estimates", quick: bool = False) -> dict:
    """Run the oracle and map checks; write the tables and figure; return the numbers."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    resolutions = {"martin": (401, 801, 1601), "kapitsa": (129, 257, 513)}
    oracles = [martin_case(n) for n in resolutions["martin"]]
    oracles += [kapitsa_case(n) for n in (resolutions["kapitsa"][:1] if quick
                                          else resolutions["kapitsa"])]
    maps = run_maps(quick)
    bearings = run_bearings(quick)
    _write_csv(outdir / "oracles.csv", oracles)
    _write_csv(outdir / "maps.csv", maps)
    _write_csv(outdir / "bearings.csv", bearings)
    summary: dict = {"oracle_agreement": {}, "map_agreement": {}, "energy": {}}
    for k in ("p_max", "friction_force", "heat_power"):
        summary["oracle_agreement"][k] = [r[f"{k}_agree"] for r in oracles]
    for kind in ("line", "point"):
        sel = [r for r in maps if r["kind"] == kind and r["status"] == "converged"
               and r["fine_status"] == "converged"]
        summary["map_agreement"][kind] = {
            k: (sum(r[f"{k}_agree"] for r in sel) / len(sel) if sel else math.nan)
            for k in QUANTITIES}
        summary["map_agreement"][kind]["cases"] = len(sel)
        # the misses: estimates more than FACTOR above (conservative) or below the change
        summary["map_misses"] = summary.get("map_misses", {})
        summary["map_misses"][kind] = {
            k: {"over": sum(1 for r in sel if not r[f"{k}_agree"]
                            and (r[f"{k}_estimate"] or 0.0) > r[f"{k}_change"]),
                "under": sum(1 for r in sel if not r[f"{k}_agree"]
                             and (r[f"{k}_estimate"] or 0.0) <= r[f"{k}_change"])}
            for k in QUANTITIES}
        summary["energy"][kind] = {
            "max_balance_residual": max((r["energy_balance_residual"] for r in sel),
                                        default=math.nan),
            "max_poiseuille_heat_change": max((r["poiseuille_heat_change"] for r in sel),
                                              default=math.nan),
            "max_direct_vs_conservative": max((abs(r["direct_vs_conservative"]) for r in sel),
                                              default=math.nan)}
    if not quick:
        summary["energy"]["line_balance_grids"] = energy_balance_grids()
    both = [r for r in maps if r["status"] == "converged" and r["fine_status"] == "converged"]
    summary["estimator_ceiling"] = estimator_ceiling(both)
    summary["intermediate_check"] = intermediate_check(both)
    summary["agreement_by_method"] = agreement_by_method(both)
    summary["bearing_agreement"] = {
        k: [r[f"{k}_agree"] for r in bearings] for k in BEARING_QUANTITIES}
    summary["seconds"] = time.perf_counter() - t0
    (outdir / "summary.json").write_text(json.dumps(summary, indent=1, default=str))
    _figure(outdir / "estimates.png", maps, oracles)
    return {"oracles": oracles, "maps": maps, "bearings": bearings, "summary": summary}


#: Line case and node counts of :func:`energy_balance_grids` (the line map's largest
#: energy-balance misses are at M = 1000, L = 2 and 5).
BALANCE_CASE = (1000.0, 5.0)
BALANCE_NODES = (2401, 3201, 3601, 4001, 4801, 6001)


def energy_balance_grids() -> list[dict]:
    """The discrete energy balance of one line case over node counts: the balance
    residual abs(direct + stabilisation - conservative)/conservative, the conservative
    Poiseuille heat [W/m] and sum_i p_i R_i [W/m] (R_i the nodal Reynolds residual of the
    reported solution, which the balance equals), so that a residual growing with the
    node count can be told from a heat that does not converge."""
    from bearing_fem.contacts.line import LineModel

    out = []
    M, L = BALANCE_CASE
    for n in BALANCE_NODES:
        scene = line_scene(M, L, n)
        res = bf.solve(scene)
        row = {"M": M, "L": L, "nodes": n, "status": res.status}
        if res.success:
            q = res.quantities
            qp = q["heat_power_poiseuille"]
            model = LineModel(scene)
            p = np.asarray(res.pressure)
            residual = model.problem(model.setup).reynolds_residual(p, float(res.h0))
            row.update(
                balance_residual=abs(q["heat_power_poiseuille_direct"]
                                     + q["heat_power_stabilisation"] - qp) / abs(qp),
                heat_poiseuille=qp, sum_p_residual=float(p @ residual))
        out.append(row)
    return out


def _level_differences(row: dict, key: str) -> np.ndarray | None:
    """Relative differences of ``key`` between successive solves of a map row (the grid
    sequence behind its estimate, then the twice-finer solve), or None if a value is
    missing."""
    values = json.loads(row[f"{key}_values"])
    if len(values) < 3 or any(v is None for v in values) or values[-2] == 0.0:
        return None
    return np.diff(np.asarray(values, dtype=float)) / abs(values[-2])


def estimator_ceiling(rows: list[dict]) -> dict:
    """How well any estimate built from the grid sequence's level differences can agree
    with the change to the twice-finer solve, over map rows (see item 4 of the module
    docstring).

    Returns
    -------
    dict
        ``pairs`` (case-quantities), ``best_constant_share`` and ``best_constant`` (the
        largest share of pairs whose change d3 lies within a factor FACTOR of c |d2|, over
        c; pairs without two differences before d3 count as misses, pairs with d2 and d3
        both below FLOOR as agreeing; ``best_constant`` None if no c agrees anywhere),
        ``best_group_constants_share`` (the same with one constant per map kind and
        quantity, each the best for its group: a row's ``kind``, '' if absent),
        ``trend_correlation`` (Pearson correlation of log|d3/d2| with log|d2/d1| over
        the pairs with three non-zero differences; None where undefined: fewer than
        three such pairs, or a constant ratio), ``trend_pairs`` (how many), and for the
        rule |d2|/3 (Richardson with the formal order 2 assumed everywhere)
        ``formal_order_agree`` (pairs agreeing) and ``formal_order_under`` (misses below
        the change).
    """
    last, change, group, r_next, r_prev = [], [], [], [], []
    for row in rows:
        for k in QUANTITIES:
            group.append((row.get("kind", ""), k))
            d = _level_differences(row, k)
            if d is None:
                last.append(math.nan)
                change.append(math.nan)
                continue
            last.append(abs(d[-2]))
            change.append(abs(d[-1]))
            if d.size >= 3 and np.all(d != 0.0):
                r_next.append(math.log(abs(d[-1] / d[-2])))
                r_prev.append(math.log(abs(d[-2] / d[-3])))
    last_a, change_a = np.asarray(last), np.asarray(change)
    hits, best_c = _best_constant(last, change)
    best = hits / len(last) if last else 0.0
    group_hits = 0
    for g in dict.fromkeys(group):
        sel = [i for i, gi in enumerate(group) if gi == g]
        group_hits += _best_constant([last[i] for i in sel], [change[i] for i in sel])[0]
    # the formal order assumed everywhere: c = 1/(2^2 - 1)
    formal = [(agree(a / 3.0, b), a / 3.0 < b) for a, b in zip(last_a, change_a)
              if math.isfinite(a)]
    corr = None  # undefined with fewer than three pairs or a constant ratio
    if len(r_next) > 2 and np.std(r_next) > 0.0 and np.std(r_prev) > 0.0:
        corr = float(np.corrcoef(r_next, r_prev)[0, 1])
    return {"pairs": len(last), "best_constant_share": best,
            "best_constant": best_c if math.isfinite(best_c) else None,
            "best_group_constants_share": group_hits / len(last) if last else 0.0,
            "trend_correlation": corr, "trend_pairs": len(r_next),
            "formal_order_agree": sum(1 for ok, _ in formal if ok),
            "formal_order_under": sum(1 for ok, low in formal if not ok and low)}


def richardson_spacings(h: tuple[float, float, float], q: tuple[float, float, float],
                        cap: float = 2.0) -> tuple[float, str]:
    """Estimated absolute error of q[0] from three solutions on spacings h[0] < h[1] <
    h[2] (any ratios): the observed order p solves
    (h3^p - h2^p) / (h2^p - h1^p) = (q3 - q2) / (q2 - q1), for p in [MIN_ORDER, 8];
    the error is |q2 - q1| / ((h2/h1)^min(p, cap) - 1) (Richardson), else (changes of
    alternating sign, or no such p) the plain level difference |q2 - q1|.

    Parameters
    ----------
    h : tuple of float
        The three spacings, finest first (any unit; only their ratios matter).
    q : tuple of float
        The quantity on those spacings.
    cap : float
        Largest order used in the error (the formal order).

    Returns
    -------
    error : float
        Estimated absolute error of q[0] (unit of q).
    method : str
        ``"richardson"`` or ``"level difference"``.
    """
    (h1, h2, h3), (q1, q2, q3) = h, q
    d12, d23 = q2 - q1, q3 - q2
    if d12 == 0.0:
        return 0.0, "richardson"
    if d12 * d23 > 0.0:
        def g(p: float) -> float:
            return (h3**p - h2**p) / (h2**p - h1**p) - d23 / d12
        lo, hi = post.MIN_ORDER, 8.0
        if g(lo) <= 0.0 <= g(hi):
            p = brentq(g, lo, hi)
            return abs(d12) / ((h2 / h1) ** min(p, cap) - 1.0), "richardson"
    return abs(d12), "level difference"


def intermediate_check(rows: list[dict]) -> dict:
    """Would a fourth grid, finer than the coarsest level, make the estimate reach the
    target? For each map row with a solve on 4/3 times the default spacing
    (``{q}_between``), the estimate from the spacings h, 4h/3, 2h (default grid, that
    solve, the grid sequence's level below) by :func:`richardson_spacings`, against the
    same change to the twice-finer solve.

    Parameters
    ----------
    rows : list of dict
        Map rows of :func:`map_row` (converged default and twice-finer solves).

    Returns
    -------
    dict
        ``share`` (all case-quantities), ``line`` and ``point`` (shares per kind),
        ``pairs``, and ``cost``: the median time of the extra solve over that of the
        default solve (it starts from scratch here; a solver would start it from the
        default solution).
    """
    hits: dict[str, list[bool]] = {"line": [], "point": []}
    cost = []
    for row in rows:
        if row.get("between_status") not in ("converged", "linear"):
            continue
        cost.append(row["between_seconds"] / row["seconds"])
        for k in QUANTITIES:
            values = json.loads(row[f"{k}_values"])  # levels, then the fine solve
            if len(values) < 3 or any(v is None for v in values[-3:]) \
                    or row[f"{k}_between"] is None:
                hits[row["kind"]].append(False)
                continue
            q1, q3 = values[-2], values[-3]  # default grid, the level below
            err, _ = richardson_spacings((1.0, 4.0 / 3.0, 2.0), (q1, row[f"{k}_between"], q3))
            hits[row["kind"]].append(agree(err / abs(q1), row[f"{k}_change"]))
    every = hits["line"] + hits["point"]

    def share(x: list[bool]) -> float | None:
        return sum(x) / len(x) if x else None

    return {"share": share(every), "line": share(hits["line"]),
            "point": share(hits["point"]), "pairs": len(every),
            "cost": float(np.median(cost)) if cost else None}


def agreement_by_method(rows: list[dict]) -> dict:
    """Share of map case-quantities within a factor FACTOR, per map kind and per method
    of the estimate (``richardson``, ``level difference``): ``{kind: {method: {"pairs":
    n, "agree": share}}}``, kind ``all`` over both maps.

    Parameters
    ----------
    rows : list of dict
        Map rows of :func:`map_row`.

    Returns
    -------
    dict
        Per kind (``line``, ``point``, ``all``) and method (``richardson``, ``level
        difference``, ``none``): ``pairs`` (count) and ``agree`` (share in [0, 1]).
    """
    out: dict[str, dict[str, dict[str, float]]] = {}
    for row in rows:
        for k in QUANTITIES:
            method = row[f"{k}_method"] or "none"
            for kind in (row["kind"], "all"):
                cell = out.setdefault(kind, {}).setdefault(method, {"pairs": 0, "agree": 0})
                cell["pairs"] += 1
                cell["agree"] += int(bool(row[f"{k}_agree"]))
    for by_method in out.values():
        for cell in by_method.values():
            cell["agree"] = cell["agree"] / cell["pairs"]
    return out


def _best_constant(last: list[float], change: list[float]) -> tuple[int, float]:
    """(pairs agreeing, c) of the constant c in 1e-2 .. 1 whose estimates c |d2| agree
    with the most changes |d3| (:func:`agree`; a NaN |d2| is a miss); c NaN if none
    agrees."""
    best, best_c = 0, math.nan
    for c in np.geomspace(1e-2, 1.0, 401):
        hits = sum(1 for a, b in zip(last, change) if math.isfinite(a) and agree(c * a, b))
        if hits > best:
            best, best_c = hits, float(c)
    return best, best_c


def _write_csv(path: Path, rows: list[dict]) -> None:
    if not rows:
        return
    keys = list(rows[0])
    with path.open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


def _figure(path: Path, maps: list[dict], oracles: list[dict]) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 5.5))
    markers = dict(zip(QUANTITIES, "osD^v"))
    for k in QUANTITIES:
        pts = [(r[f"{k}_change"], r[f"{k}_estimate"]) for r in maps
               if r[f"{k}_estimate"] and r[f"{k}_change"] > 0]
        if pts:
            x, y = zip(*pts)
            ax.loglog(x, y, markers[k], mfc="none", label=f"maps: {k}")
    for k in ("p_max", "friction_force", "heat_power"):
        pts = [(r[f"{k}_true"], r[f"{k}_estimate"]) for r in oracles
               if r[f"{k}_estimate"] and r[f"{k}_true"] > 0]
        if pts:
            x, y = zip(*pts)
            ax.loglog(x, y, "k" + markers[k], ms=4, label=f"oracles: {k}")
    lim = np.array([1e-7, 1.0])
    ax.loglog(lim, lim, "k-", lw=0.8)
    ax.loglog(lim, FACTOR * lim, "k:", lw=0.8)
    ax.loglog(lim, lim / FACTOR, "k:", lw=0.8)
    ax.set_xlabel("true relative error (oracles) or change to a 2x finer grid (maps)")
    ax.set_ylabel("reported error_estimate")
    ax.legend(fontsize=7)
    ax.set_title("Error estimate against the true error (dotted: factor 3)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default="out/error_estimates")
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    res = main(a.outdir, quick=a.quick)
    print(json.dumps(res["summary"], indent=1, default=str))

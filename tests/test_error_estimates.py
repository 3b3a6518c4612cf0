"""The error estimate of every result against true errors (studies/error_estimates.py)."""
from __future__ import annotations

import sys
from pathlib import Path

from dataclasses import replace

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "studies"))
import error_estimates  # noqa: E402

from bearing_fem import post, solve  # noqa: E402


def test_richardson_on_a_known_sequence():
    # q_h = 1 + 0.1 h^2: the error of the last value is 0.1 h3^2, observed order 2
    hs = np.array([0.4, 0.2, 0.1])
    err, how, p = post.richardson(1.0 + 0.1 * hs**2)
    assert how == "richardson"
    np.testing.assert_allclose(p, 2.0, rtol=1e-10, err_msg="observed order of h^2 data")
    np.testing.assert_allclose(err, 0.1 * 0.1**2, rtol=1e-10, err_msg="exact for h^2 data")
    # first order: the cap at the formal order 2 is not reached
    err1, _, p1 = post.richardson(1.0 + 0.1 * hs)
    np.testing.assert_allclose([p1, err1], [1.0, 0.01], rtol=1e-10)
    # alternating changes: the plain level difference
    err2, how2, _ = post.richardson([1.0, 1.2, 1.1])
    assert how2 == "level difference"
    np.testing.assert_allclose(err2, 0.1, rtol=1e-12)


def test_quick_study(tmp_path):
    out = error_estimates.main(tmp_path, quick=True)
    s = out["summary"]
    for key, flags in s["oracle_agreement"].items():
        assert all(flags), (f"{key}: the estimate within a factor 3 of the true error at "
                            f"every resolution of the Martin and Kapitsa oracles")
    for kind in ("line", "point"):
        e = s["energy"][kind]
        assert e["max_balance_residual"] < 1e-2, (
            f"{kind}: discrete energy balance (direct + stabilisation = conservative "
            "Poiseuille heat) within 1% (Newton tolerance and the cavitation cut)")
        assert e["max_poiseuille_heat_change"] < 5e-2, (
            f"{kind}: conservative heat within 5% of the twice-finer solve (docs/accuracy.md: "
            "<1% line, <4% circular)")
    for row in out["maps"]:
        for q in error_estimates.QUANTITIES:
            est = row[f"{q}_estimate"]
            assert est is not None and np.isfinite(est) and est >= 0.0, (row["kind"], q)
    ic = s["intermediate_check"]
    assert ic["pairs"] == 5 * len(out["maps"]) and 0.0 <= ic["share"] <= 1.0, ic
    assert ic["cost"] > 0.0, "the extra solve's time over the default solve's"
    by = s["agreement_by_method"]["all"]
    assert sum(c["pairs"] for c in by.values()) == 5 * len(out["maps"]), by
    assert (tmp_path / "maps.csv").is_file() and (tmp_path / "estimates.png").is_file()
    (b,) = out["bearings"]
    assert b["status"] == "converged" and b["fine_status"] == "converged"
    for k in ("friction_torque", "heat_power"):
        assert b[f"{k}_agree"], (
            f"6209 bearing {k}: estimate {b[f'{k}_estimate']:.2e} within a factor 3 of the "
            f"change to 257^2 contacts {b[f'{k}_change']:.2e} (measured 5.9e-2 vs 3.6e-2)")
    assert (tmp_path / "bearings.csv").is_file()


def _row(sequences: dict[str, list[float]]) -> dict:
    """A map row holding, per quantity, its values on the grid sequence and the finer
    solve (as ``map_row`` writes them)."""
    import json
    return {f"{q}_values": json.dumps(sequences.get(q, [1.0, 1.0, 1.0, 1.0]))
            for q in error_estimates.QUANTITIES}


def test_estimator_ceiling_on_known_sequences():
    # second-order sequences q = 1 + a h^2 (h = 8, 4, 2, 1 in units of the finest step):
    # d3/d2 = 1/4 everywhere, so one constant (near 1/4) makes every pair agree, and the
    # trend is exactly predictive (every pair has the same ratios: the correlation is
    # undefined, None, because both ratio lists are constant)
    seq = [1.0 + 1e-3 * h**2 for h in (8.0, 4.0, 2.0, 1.0)]
    rows = [_row({q: seq for q in error_estimates.QUANTITIES}) for _ in range(4)]
    c = error_estimates.estimator_ceiling(rows)
    assert c["pairs"] == 20 and c["trend_pairs"] == 20
    np.testing.assert_allclose(c["best_constant_share"], 1.0,
                               err_msg="geometric sequences: a constant rule agrees everywhere")
    assert 0.25 / 3 <= c["best_constant"] <= 0.25 * 3, c["best_constant"]
    assert c["trend_correlation"] is None
    # |d2|/3 against d3 = |d2|/4: within the factor 3 everywhere
    assert c["formal_order_agree"] == 20 and c["formal_order_under"] == 0
    # changes whose ratio d3/d2 spreads over 1/100 .. 1 (beyond the factor-3 window of
    # width 9): no constant reaches every pair, and a trend that runs against the next
    # change correlates negatively
    spread = []
    for r3, r2 in ((1e-2, 1.0), (1.0, 1e-2), (1e-2, 1.0), (1.0, 1e-2), (1e-1, 0.3)):
        d1 = 1e-2
        d2 = d1 * r2
        d3 = d2 * r3
        spread.append(_row({"h_central": list(np.cumsum([1.0, d1, d2, d3]))}))
    c2 = error_estimates.estimator_ceiling(spread)
    assert c2["best_constant_share"] < 1.0
    assert c2["trend_correlation"] < -0.5, c2["trend_correlation"]


def test_estimator_ceiling_per_kind_and_quantity():
    # two map kinds whose next changes d3/d2 differ by a factor 25 (> the window of width
    # 9): no single constant fits both, one constant per kind and quantity fits every pair
    def seq(ratio: float) -> list[float]:
        return list(np.cumsum([1.0, 1e-2, 1e-3, 1e-3 * ratio]))

    rows = []
    for kind, ratio in (("line", 1.0 / 30.0), ("point", 0.8)):
        for _ in range(3):
            row = _row({q: seq(ratio) for q in error_estimates.QUANTITIES})
            row["kind"] = kind
            rows.append(row)
    c = error_estimates.estimator_ceiling(rows)
    assert c["best_constant_share"] == 0.5, c
    np.testing.assert_allclose(c["best_group_constants_share"], 1.0,
                               err_msg="a constant per kind and quantity fits each group")


def test_line_h_min_is_the_film_minimum_between_the_nodes():
    """h_min of a half-space line contact includes the film between the nodes near the
    outlet constriction (the interpolant plus the bow of the geometry and of the deflection
    of the piecewise-linear pressure): it converges monotonically where the nodal minimum
    jumps with the grid (measured at M = 100, L = 5, 401 .. 3201 nodes: nodal 2.6975,
    2.7374, 2.7337, 2.7368e-8 m; h_min 2.6753, 2.7223, 2.7335, 2.7366e-8 m), which is
    what lets the error estimate read it."""
    h_min, nodal = [], []
    for n in (401, 801, 1601, 3201):
        r = solve(error_estimates.line_scene(100, 5, n))
        assert r.success, r.message
        h_min.append(r.quantities["h_min"])
        nodal.append(float(r.film.min()))
        assert r.quantities["h_min"] <= nodal[-1], "the minimum over the nodes and between"
    assert np.all(np.diff(h_min) > 0.0), (h_min, "monotone: the grid resolves the outlet "
                                                 "constriction better each level")
    assert not np.all(np.diff(nodal) > 0.0), (nodal, "the nodal minimum is not (the reason "
                                                     "for sampling between the nodes)")
    changes = np.abs(np.diff(h_min))
    assert np.all(changes[1:] < 0.5 * changes[:-1]), (
        changes, "each change at most half the one before: the sequence a Richardson "
                 "estimate needs (measured ratios 4.2, 3.6)")


def test_film_between_the_nodes_lowers_h_min_without_the_grid_warning():
    """The deflection's bow between the nodes (``h_near``) enters h_min but not the warning
    that the grid misses the constriction: that reads the quadrature-point film (exact
    geometry, interpolated deformation). The bow is discretisation error, which the error
    estimate reports at its own threshold: on the default grid of Moes M = 1000, L = 0
    (3601 nodes) h_min lies 1.1 % below the nodal minimum with an estimated error of 3.9 %
    (the film converges towards 1.576e-8 m: 1.5328e-8 m here, 1.5656e-8 on 7201 nodes and
    1.5736e-8 on 14401), and the warning had told the user of the default grid to refine."""
    x = np.linspace(-1.0, 1.0, 5)
    h = np.array([3.0, 2.0, 1.0, 2.0, 3.0])
    nums, notes = post.film_numbers(h, h.copy(), 1.0, np.zeros(5), 0.0, x,
                                    h_near=np.array([0.95]))
    assert nums["h_min"] == 0.95, nums
    assert not [n for n in notes if "between the nodes" in n], notes
    nums, notes = post.film_numbers(h, np.array([0.95, 2.0]), 1.0, np.zeros(5), 0.0, x,
                                    h_near=np.array([0.9]))
    assert nums["h_min"] == 0.9, nums
    assert [n for n in notes if n.startswith("h_min lies between the nodes (0.9 m, 10% below")
            ], notes
    # a bow beyond the error estimate's threshold is reported as well (a grid without an
    # estimate, e.g. one mesh.file level, would otherwise not hear of it)
    nums, notes = post.film_numbers(h, h.copy(), 1.0, np.zeros(5), 0.0, x,
                                    h_near=np.array([0.94]))
    assert [n for n in notes if n.startswith("h_min lies between the nodes (0.94 m, 6% below")
            ], notes

    # M = 1000, L = 0 on [-4.5, 1.5] b with 3601 nodes (the default grid before the
    # default density followed M^0.75 and the isoviscous default domain became shorter)
    base = error_estimates.line_scene(1000, 0)
    r = solve(replace(base, mesh=replace(base.mesh, nodes=3601, x_range=(-4.5, 1.5))))
    assert r.success and r.dofs == 3601, (r.status, r.dofs)
    nodal = float(r.film.min())
    assert r.quantities["h_min"] < 0.99 * nodal, (r.quantities["h_min"], nodal,
                                                   "measured 1.13 % below")
    assert not [w for w in r.warnings if "between the nodes" in w], r.warnings
    assert r.error_estimate["h_min"] < post.ERROR_WARNING_THRESHOLD, r.error_estimate


def test_energy_balance_of_a_heavy_line_contact_on_a_fine_grid():
    """M = 1000, L = 5 on 3201 nodes: the discrete energy balance closes to the Newton
    tolerance. With one Fischer-Burmeister smoothing for every row, the far-inlet rows
    (film a thousand times h_min) broke it by 0.69 % here, growing as N^2."""
    (row,) = [r for r in _balance_rows(3201)]
    assert row["status"] == "converged", row
    assert row["balance_residual"] < 1e-5, (
        f"energy balance {row['balance_residual']:.2e}: direct + stabilisation = "
        "conservative Poiseuille heat to ~1e-8 (measured 1.2e-7 on 3201 nodes)")
    np.testing.assert_allclose(row["sum_p_residual"], 0.0, atol=1e-5 * row["heat_poiseuille"],
                               err_msg="the balance is sum_i p_i R_i [W/m], ~0 at the root")


def _balance_rows(nodes):
    old = error_estimates.BALANCE_NODES
    error_estimates.BALANCE_NODES = (nodes,)
    try:
        return error_estimates.energy_balance_grids()
    finally:
        error_estimates.BALANCE_NODES = old


def test_row_smoothing_keeps_mu_at_the_thinnest_film():
    from scipy.optimize import brentq

    from bearing_fem.contacts.problem import FB_SMOOTHING, fischer_burmeister, row_smoothing

    s = np.array([1e-9, 1e-3, 1.0, 0.25])
    mu = row_smoothing(s)
    np.testing.assert_allclose(mu, FB_SMOOTHING * np.sqrt(s), rtol=1e-14,
                               err_msg="mu_i = mu sqrt(s_i / max s)")
    # the root of the smoothed function in b, found numerically (a smoothing large
    # enough for the root to be resolved in double precision): a b = mu^2
    for m in (1e-3, 1e-4):
        for a in (0.01, 0.3, 2.0):
            b = brentq(lambda x: float(fischer_burmeister(np.array(a), np.array(x), m)[0]),
                       0.0, 1.0, xtol=1e-30, rtol=1e-14)
            np.testing.assert_allclose(a * b, m**2, rtol=1e-6,
                                       err_msg="root of the smoothed FB: a b = mu^2")
    # so the unscaled p_i R_i = p_ref a_i b_i / s_i = p_ref mu_i^2 / s_i is the same in
    # every row
    np.testing.assert_allclose(mu**2 / s, FB_SMOOTHING**2 * np.ones(4), rtol=1e-12,
                               err_msg="equal energy-balance share per row")


def test_richardson_on_uneven_spacings():
    # q_h = 1 + 0.1 h^2 on h = 1, 4/3, 2: the error of q(1) is 0.1, observed order 2
    h = (1.0, 4.0 / 3.0, 2.0)
    err, how = error_estimates.richardson_spacings(h, tuple(1.0 + 0.1 * x**2 for x in h))
    assert how == "richardson"
    np.testing.assert_allclose(err, 0.1, rtol=1e-9, err_msg="exact for h^2 data")
    # order 3 capped at 2: |d12| / ((4/3)^2 - 1) = 0.1 (64/27 - 1) / (7/9)
    err3, _ = error_estimates.richardson_spacings(h, tuple(1.0 + 0.1 * x**3 for x in h))
    np.testing.assert_allclose(err3, 0.1 * (64 / 27 - 1) / (7 / 9), rtol=1e-9,
                               err_msg="observed order above the cap 2 is capped")
    err2, how2 = error_estimates.richardson_spacings(h, (1.0, 1.2, 1.1))
    assert how2 == "level difference"
    np.testing.assert_allclose(err2, 0.2, rtol=1e-12)

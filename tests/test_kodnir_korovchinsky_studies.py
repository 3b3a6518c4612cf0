"""The Korovchinsky reconstruction and shooting-vs-FE studies in quick mode, and the
printed Korovchinsky field they compare against (Sanko; Yachikov & Vostrikov 2015)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_fem import analytic as A
from bearing_fem.physics import thermal as th


# ------------------------------------------------------------------ the printed field


def test_printed_field_special_forms():
    """Sanko's printed eq. (7) on the strip is ln sqrt 2 - x'^2 and on the free surface
    outside it is -U_x of his eq. (17); the corrected field has 1/2 on both quadratics."""
    x = np.linspace(-1.0, 1.0, 11)
    np.testing.assert_allclose(A.korovchinsky_shape_printed(x, 0.0),
                               math.log(math.sqrt(2.0)) - x**2, atol=1e-14,
                               err_msg="printed field on the strip (t = 0), exact")
    xo = np.array([1.2, 2.0, 5.0])
    s = np.sqrt(xo**2 - 1.0)
    u_x = 0.5 * np.log((s + xo) / 2.0) - xo * s + xo**2
    np.testing.assert_allclose(A.korovchinsky_shape_printed(xo, 0.0), -u_x, rtol=1e-12,
                               err_msg="printed field outside the strip equals -U_x (eq. 17)")
    np.testing.assert_allclose(A.korovchinsky_shape(xo, 0.0), A.korovchinsky_surface(xo),
                               rtol=1e-12, err_msg="corrected shape vs its surface form")


def test_printed_field_has_the_wrong_strip_flux():
    """-dT/dy on the strip: sqrt(1 - x'^2) (corrected) vs (3 - 4x'^2)/(2 sqrt(1 - x'^2))
    (printed; derived from the small-t expansion), both with total power pi/2 (q_max a)."""
    x = np.linspace(-0.9, 0.9, 7)
    h = 1e-7
    for f, exact in ((A.korovchinsky_shape, np.sqrt(1 - x**2)),
                     (A.korovchinsky_shape_printed, (3 - 4 * x**2) / (2 * np.sqrt(1 - x**2)))):
        flux = -(f(x, h) - f(x, 0.0)) / h
        np.testing.assert_allclose(flux, exact, atol=1e-5,
                                   err_msg=f"{f.__name__}: one-sided difference, O(h) error")


def test_reconstruct_two_point_printed_form_and_bad_form():
    a, lam = 1e-3, 40.0
    pts = [(0.0, 1.5), (0.0, 3.0)]
    T = [20.0 * (2.0 + float(A.korovchinsky_shape_printed(px, py))) for px, py in pts]
    rec = th.reconstruct_two_point(a, (0.0, 1.5 * a, T[0]), (0.0, 3.0 * a, T[1]), lam,
                                   form="printed")
    assert rec.form == "printed"
    assert rec.T_n == pytest.approx(20.0, rel=1e-12), "printed data, printed fit: exact"
    assert rec.C == pytest.approx(2.0, rel=1e-12)
    assert rec.T_max == pytest.approx(20.0 * (2.0 + math.log(math.sqrt(2.0))), rel=1e-12)
    with pytest.raises(ValueError, match="form"):
        th.reconstruct_two_point(a, (0, a, 1.0), (0, 2 * a, 0.5), lam, form="typo")


# ------------------------------------------------------------------ the studies


def test_korovchinsky_reconstruction_quick(tmp_path, load_study):
    mod = load_study("korovchinsky_reconstruction")
    out = mod.main(tmp_path, quick=True)
    for ext in ("json", "md", "png"):
        assert (tmp_path / f"korovchinsky_reconstruction.{ext}").stat().st_size > 0
    assert abs(out["truth"]["fe_contact_error_K"]) < 1e-3 * out["scene"]["T_n_K"], \
        "the synthetic FE truth matches the closed form to 0.1 % of T_n (quick mesh)"
    assert len(out["pairs"]) == 4
    for row in out["pairs"]:
        c, p = row["corrected"], row["printed"]
        # a 4-sigma band of the noise-implied spread (Monte Carlo over seeded draws)
        assert abs(c["T_max_error_K"]) < 4 * c["noise_sd_T_max_K"], \
            f"{row['pair']}: corrected T_max within 4 noise sd of the truth"
        assert abs(c["source_power_error_pct"]) < 4 * c["noise_sd_source_power_pct"], \
            f"{row['pair']}: corrected source power within 4 noise sd"
        assert abs(c["noise_free_T_max_error_K"]) < 0.01, \
            "noise-free corrected reconstruction: only the FE error of the truth (< 0.01 K)"
        assert c["noise_free_field_max_error_K"] < 0.02, \
            "noise-free corrected field within 0.02 K everywhere in |x|, y <= 4a"
        # the printed field: far outside the noise band in T_max or in theta
        assert max(abs(p["T_max_error_in_sd"]), abs(p["source_power_error_in_sd"])) > 10, \
            f"{row['pair']}: printed reconstruction should be > 10 noise sd off"
        assert p["noise_free_field_max_error_K"] > 1.0, \
            "printed field differs from the truth by kelvins even without noise"
    main = out["pairs"][0]
    assert main["printed_minus_corrected_T_max_K"] > 1.0, \
        "depth pair: printed contact temperature kelvins above the corrected one"


def test_shooting_vs_fe_quick(tmp_path, load_study):
    mod = load_study("shooting_vs_fe")
    out = mod.main(tmp_path, quick=True)
    for ext in ("json", "md", "csv", "png"):
        assert (tmp_path / f"shooting_vs_fe.{ext}").stat().st_size > 0
    rows = out["rows"]
    assert len(rows) == 9
    assert all(r["fe"]["success"] for r in rows + out["analytic_rows"]), \
        [r["fe"]["message"] for r in rows if not r["fe"]["success"]]
    agreed = 0
    for r in rows:
        for m in ("RK45", "LSODA"):
            d = r[m]["rel_diff_vs_fe"]
            if d is None:
                assert not r[m]["success"] and r[m]["message"], "a failure says why"
                continue
            agreed += 1
            # FE at 1001 nodes: its P1 error is ~4x that of 2001 nodes (0.05 % of z_a,
            # k_max vs 4001 nodes, docs/kodnir.md), so 0.2 % bounds the FE error
            assert d["z_a"] < 2e-3 and d["k_max"] < 2e-3 and d["h_min"] < 2e-3, \
                (r["C"], r["b_alpha"], m, d)
    assert agreed >= 8, "shooting succeeds on the non-stiff quick cases"
    stiff = [r for r in rows if r["b_alpha"] == 8.0]
    assert not any(r["RK45"]["success"] for r in stiff), \
        "explicit shooting fails on the stiff B alpha = 8 column (the paper's failure range)"
    ref = [r for r in rows if "reference_fe" in r]
    assert ref and all(r["fe"]["rel_error_vs_reference"]["z_a"] < 1e-3 for r in ref), \
        "FE 1001 vs 2001 nodes within 0.1 % (P1 grid error)"
    for r in out["analytic_rows"]:
        e = r["fe"]["rel_error_vs_analytic"]
        # the analytic limit has its inlet at infinity, the problem at z_b = 20: k(20) is
        # ~1e-4 k_max there, plus the P1 error; 0.2 % covers both
        assert e["z_a"] < 2e-3 and e["k_max"] < 2e-3, (r["b_alpha"], e)


@pytest.mark.slow
def test_kodnir_stiff_quick(tmp_path, load_study):
    """The quick run of the stiff-compliance study: C = 150 converges (1720 Newton
    iterations measured, 8446 before the banded continuation grids) and is grid-converged
    between n and 2n - 1 nodes; C = 400 ends with a message naming the C of the stall."""
    mod = load_study("kodnir_stiff")
    out = mod.main(tmp_path, quick=True)
    assert (tmp_path / "kodnir_stiff.json").stat().st_size > 0
    assert (tmp_path / "kodnir_stiff.md").stat().st_size > 0
    ok, beyond = out["rows"]
    assert ok["success"] and ok["iterations"] <= 3000, ok
    assert max(ok["relative_change"].values()) < 1e-3, (
        ok["relative_change"], "z_a, k_max and H_min within 0.1 % of 4001 nodes "
                               "(measured at most 0.011 %)")
    assert not beyond["success"] and "continuation stalled at C=" in beyond["message"]

"""The bearing studies in quick mode: they run, write their files and return these numbers."""
from __future__ import annotations

import math

import numpy as np
import pytest


def test_hybrid_vs_steel_quick(tmp_path, load_study):
    res = load_study("hybrid_vs_steel").main(tmp_path, quick=True)
    row = res["rows"][0]
    st, hy = row["steel"], row["hybrid"]
    assert st["status"] == hy["status"] == "converged"
    assert hy["p_max_Pa"] > 1.05 * st["p_max_Pa"], \
        "stiffer Si3N4 balls (E' 272 vs 229 GPa): smaller contact, higher pressure"
    np.testing.assert_allclose(hy["h_min_m"], st["h_min_m"], rtol=0.05,
                               err_msg="film nearly material-independent (E'^-0.07..-0.1)")
    assert abs(row["ehl_ratio_hybrid_to_steel"] - 1.0) < 0.05, \
        "EHL rolling loss of the hybrid within a few % of the steel bearing's (full: 0.99-1.01)"
    assert hy["centrifugal_force_N"] < 0.5 * st["centrifugal_force_N"], "3200 vs 7850 kg/m^3"
    assert st["contact_angle_outer_deg"] < st["contact_angle_inner_deg"], \
        "centrifugal force: outer contact angle below the inner one"
    n = st["nikitin"]
    assert n["churning_steel_W"] > 3 * n["friction_steel_W"], \
        "Nikitin: churning dominates at jet lubrication (his conclusion)"
    assert 0.5 < st["heat_power_W"] / n["friction_steel_W"] < 2.0, \
        "EHL rolling loss of the order of Nikitin's friction part for steel balls"
    assert (tmp_path / "table.md").is_file() and (tmp_path / "losses.png").is_file()


def test_bearing209_whole_bearing_quick(tmp_path, load_study):
    mod = load_study("bearing209")
    res = mod.whole_bearing(tmp_path, quick=True)
    loads = {round(d["azimuth_deg"]): d["load_N"] for d in res["load_distribution"]}
    assert {a for a, q in loads.items() if q > 0} == {0, 40, -40}, \
        "Fr = 4 kN, c_r = 7.5 um: three balls loaded"
    np.testing.assert_allclose(loads[0] + 2 * loads[40] * math.cos(math.radians(40)), 4000.0,
                               rtol=1e-9, err_msg="ball loads balance Fr")
    for c in res["cases"]:
        assert c["status"] == "converged"
        assert 1.5e9 < c["p_max_Pa"] < 3.0e9, "Hertzian pressures (GPa) at the 209's balls"
        assert c["kapitsa_rigid_p_max_Pa_at_h_central"] < 0.05 * c["p_max_Pa"], \
            "the rigid model at the same gap gives MPa, far below the elastic EHL pressure"
        assert abs(c["h_central_vs_nvm"] - 1) < 0.15, \
            "81^2 grids at M = 4000..9000: central film within 15% of NVM (quick grid)"
    fast, slow = sorted(res["cases"], key=lambda c: c["speed_m_s"])[::-1]
    assert fast["h_min_m"] > 2 * slow["h_min_m"], "film grows with speed (~u^0.7)"
    assert (tmp_path / "whole_bearing.md").is_file()


@pytest.mark.slow
def test_nncf5040_heat_power_quick(tmp_path, load_study):
    res = load_study("nncf5040_heat_power").main(tmp_path, quick=True)
    np.testing.assert_allclose(res["radial_clearance_m"], 17.8e-6, rtol=0.02,
                               err_msg="the paper's K = 4.6 needs c_r ~ 18 um here")
    assert 4.07 < res["load_factor_zero_clearance"] < 4.10, "Stribeck's 4.08 at c_r = 0"
    r20, r100 = res["rows"]
    assert r20["isothermal"]["status"] == r100["isothermal"]["status"] == "converged"
    assert r20["diff_isothermal_contacts_pct"] > 100, \
        "20 C: bearing-level EHL far above Palmgren (the paper: 33%)"
    assert r100["diff_isothermal_contacts_pct"] < -70, \
        "100 C: far below Palmgren (the paper: < 3%): the agreement is not reproduced"
    assert r100["thermal"]["status"] == "converged"
    np.testing.assert_allclose(r100["thermal"]["heat_power_contacts_W"],
                               r100["isothermal"]["heat_power_torque_W"], rtol=0.05,
                               err_msg="pure rolling at 100 C: thermal correction small")
    assert (tmp_path / "heat_power.png").is_file()


@pytest.mark.slow
def test_mill_vs_rig_quick(tmp_path, load_study):
    res = load_study("mill_vs_rig").main(tmp_path, quick=True)
    sp = res["similarity_printed"]
    np.testing.assert_allclose([sp["m_q"], sp["m_r"], sp["m_U"], sp["m_n"]],
                               [12.55, 1.47, 1.35, 0.43], rtol=0.01,
                               err_msg="the paper's printed scale factors are reproduced")
    row = res["rows"][0]
    assert row["mill_status"] == row["rig_status"] == "converged"
    moes = row["films_formulas"]["Moes"]["h_central"]
    np.testing.assert_allclose(row["mill"]["h_central_m"], moes, rtol=0.10,
                               err_msg="mill's most loaded roller: FE h_c within 10% of Moes")
    assert row["rig_over_mill_h_min"] < 0.9, \
        "the Ratner-based scaling does not give the same FE film on the rig"


def test_bearing_acceptance_quick(tmp_path, load_study):
    out = load_study("bearing_acceptance").main(tmp_path, quick=True)
    assert out["max_stribeck_difference"] < 1e-2, "Stribeck 4.37 / 4.08 within 1% (Z = 9 is "\
        "0.35% above the continuous value)"
    assert out["max_imbalance"] < 1e-3, "element loads balance the applied load within 0.1%"
    assert out["max_harris_difference"] < 1e-2, "load zone within 1% of Harris' integral"
    assert out["max_film_difference"] < 0.10, "most loaded contacts within 10% of NVM / Moes"
    assert out["max_energy_balance_difference"] < 1e-3, "torque x speed = heat within 0.1%"
    for row in out["ehl"]:
        assert row["status"] == "converged"
        assert 0.0 <= row["stabilisation_fraction"] < 0.5, \
            "the stabilisation share of the heat is reported and bounded on coarse grids"
    assert (tmp_path / "bearing_acceptance.md").is_file()

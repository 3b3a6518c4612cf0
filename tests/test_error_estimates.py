"""The error estimate of every result against true errors (studies/error_estimates.py)."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "studies"))
import error_estimates  # noqa: E402

from bearing_fem import post  # noqa: E402


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
    assert (tmp_path / "maps.csv").is_file() and (tmp_path / "estimates.png").is_file()
    (b,) = out["bearings"]
    assert b["status"] == "converged" and b["fine_status"] == "converged"
    for k in ("friction_torque", "heat_power"):
        assert b[f"{k}_agree"], (
            f"6209 bearing {k}: estimate {b[f'{k}_estimate']:.2e} within a factor 3 of the "
            f"change to 257^2 contacts {b[f'{k}_change']:.2e} (measured 5.9e-2 vs 3.6e-2)")
    assert (tmp_path / "bearings.csv").is_file()

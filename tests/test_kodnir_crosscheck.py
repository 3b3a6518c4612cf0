"""Yachikov & Vostrikov's (2015) friction/heat formulas (7)-(9) vs the general solver and post-processor."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "studies"))
import kodnir_crosscheck  # noqa: E402


@pytest.mark.parametrize("C, b_alpha", [(1.0, 0.0), (5.0, 4.5), (10.0, 7.0)])
def test_kodnir_formulas_match_general_post_processor(C, b_alpha):
    r = kodnir_crosscheck.crosscheck(C, b_alpha, nodes=801)
    assert r["kodnir_status"] == "converged" and r["newton_status"] == "converged", r
    for key in ("rolling_friction", "heat", "f"):
        assert abs(r[f"{key}_deviation"]) < 5e-3, (
            f"acceptance: {key} of Yachikov & Vostrikov's (2015) formulas within 0.5% of the general "
            f"post-processor on the equivalent dimensional solve, got {r[f'{key}_deviation']:.2e}")

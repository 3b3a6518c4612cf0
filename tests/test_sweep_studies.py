"""The map studies run as sweeps: same numbers as a solve in this process, and resume."""
from __future__ import annotations

import json

import numpy as np
import pytest

from bearing_fem.sweep import RunStore


def test_point_map_quick_as_a_sweep(tmp_path, load_study):
    mod = load_study("point_ehl_map")
    out = mod.main(tmp_path, quick=True, plot=False)
    cases = out["cases"]
    assert [(c["M"], c["L"]) for c in cases] == [(20, 10), (100, 10)]
    assert all(c["status"] == "converged" and c["met"] for c in cases), cases
    assert [[r["nodes"] for r in c["runs"]] for c in cases] == [[65, 129], [65, 129]]
    # the same numbers as the solve of one case in this process (the study's run_case)
    row, _ = mod.run_case(20, 10, 65)
    swept = cases[0]["runs"][0]
    for key in ("h_central_m", "h_min_m", "p_max_Pa", "h_central_ratio", "load_ratio"):
        np.testing.assert_allclose(swept[key], row[key], rtol=1e-10, err_msg=(
            f"{key}: same scene, same solver; only the BLAS thread count of the worker "
            "differs (measured 1e-16)"))
    assert swept["newton_iterations"] == row["newton_iterations"]
    assert swept["continuation"] == row["continuation"]
    assert "129^2 h_c [nm]" in (tmp_path / "point_ehl_map.md").read_text()
    store = tmp_path / "point_ehl_map.sqlite"
    with RunStore(store) as s:
        before = {r["hash"]: r["updated_at"] for r in s.rows()}
    assert len(before) == 4
    again = mod.main(tmp_path, quick=True, plot=False)  # resume: nothing is solved again
    with RunStore(store) as s:
        after = {r["hash"]: (r["updated_at"], r["attempts"]) for r in s.rows()}
    assert {h: a[0] for h, a in after.items()} == before
    assert all(a[1] == 1 for a in after.values())
    assert json.dumps(again["cases"], default=str) == json.dumps(cases, default=str)


def test_line_map_as_a_sweep_in_process(tmp_path, load_study):
    mod = load_study("line_ehl_map")
    out = mod.main(tmp_path, nodes=201, m_values=(20,), l_values=(5,), workers=1)
    (row,) = out["rows"]
    ref = mod.run_case(20, 5, 201)
    for tag in ("coarse", "fine"):
        for key in ("nodes", "status", "iterations", "h_central", "h_min", "p_max_over_ph",
                    "message"):
            assert row[tag][key] == ref[tag][key], (tag, key)
    assert row["grid_change"] == ref["grid_change"]
    assert row["moes_deviation"] == ref["moes_deviation"]
    assert out["summary"]["converged"] == 1
    with RunStore(tmp_path / "line_ehl_map.sqlite") as s:
        assert sorted(r["nodes"] for r in s.rows()) == [201, 401]


@pytest.mark.slow
def test_sweep_benchmark_quick(tmp_path, load_study):
    out = load_study("sweep_benchmark").main(tmp_path, quick=True)
    assert out["runs"] == 13 and out["grids"] == [65]
    assert out["sweeps"]["dask_summary"]["files"] == "summary"
    for name in ("dask", "dask_summary", "pool"):
        s = out["sweeps"][name]
        assert s["successes"] == s["ran"] == 13
        assert s["statuses_match"], "the sweep solves what the serial loop solves"
        assert s["max_film_difference"] < 1e-9, (
            "same scenes, same solver: the films agree to round-off (measured 6e-13; only "
            "the worker's BLAS thread count differs)")
        assert s["ratio"] > 0  # wall times are reported, never asserted
        assert s["run_s"] >= s["solver_s"] > 0, "a run's time includes its solve"
    assert "| serial loop (one process) |" in (tmp_path / "sweep_benchmark.md").read_text()
    runs = out["malloc"]["runs"]
    assert set(runs) == {"plain", "dask default", "WORKER_MALLOC_ENV"}
    assert all(r["status"] == "converged" and r["wall_s"] > 0 for r in runs.values())

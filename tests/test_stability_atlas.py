"""The stability atlas study (quick mode) and the line grid-sequence fix it led to."""
from __future__ import annotations

import csv
import math

import bearing_fem as bf
from bearing_fem.contacts.line import COARSEST_NODES, MAX_COARSENINGS, line_levels

#: Statuses a solve may end with (the Result contract), plus the atlas' own outcome for a
#: scene its builder could not make.
KNOWN = {"converged", "linear", "no_solution", "max_iterations", "stalled", "diverged",
         "budget_exhausted", "time_limit", "error", "invalid_scene"}


def test_stability_atlas_quick_and_resume(tmp_path, load_study):
    mod = load_study("stability_atlas")
    res = mod.main(tmp_path, quick=True, workers=2)
    recs = res["records"]
    families = {r["family"] for r in recs}
    assert families == {"line_map", "point_map", "ellipse", "high_pressure", "near_rigid",
                        "light_load", "low_speed", "rigid_limit"}, "every family in quick mode"
    assert res["solved_now"] == len({r["hash"] for r in recs if "hash" in r})
    for r in recs:
        assert r["status"] in KNOWN, (r["family"], r["status"])
        assert r["message"], f"every case has a message ({r['family']}, {r['status']})"
        assert r["non_finite"] == [], f"NaN/inf in the summary of {r['family']}: {r['non_finite']}"
        if r["status"] not in ("invalid_scene",):
            assert r["summary_checked"], "the summary file of every run was read and checked"
            assert r["newton_iterations"] is not None and r["wall_time_s"] is not None
    summ = res["summary"]
    assert summ["non_finite"] == []
    assert summ["line_map"]["rate"] == 1.0 and summ["point_map"]["rate"] == 1.0, \
        "the quick map cases (alpha p_h <= 100 and one beyond) all converge"
    rigid = [r for r in recs if r["family"] == "rigid_limit"]
    assert {r["status"] for r in rigid if r["ratio"] > 1} == {"no_solution"}, \
        "beyond the closed-form existence limit the solver says so"
    assert all(r["success"] for r in rigid if r["ratio"] < 1)
    for r in recs:   # every failure is explained: an unsuccessful status and its message
        if not r["ok"]:
            assert r["status"] not in ("converged", "linear") and len(r["message"]) > 20
    with open(tmp_path / "stability_atlas.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == len(recs)
    for row in rows:
        cells = [v.lower() for k, v in row.items() if k != "message"]
        assert not {"nan", "inf", "-inf"} & set(cells), f"no NaN/inf numbers in the table: {row}"
    md = (tmp_path / "stability_atlas.md").read_text()
    for r in recs:
        if not r["ok"]:
            assert r["status"] in md
    for name in res["figures"]:
        assert (tmp_path / name).stat().st_size > 1000
    again = mod.main(tmp_path, quick=True, workers=2)
    assert again["solved_now"] == 0, "a second run resumes from the store and solves nothing"
    assert [r["status"] for r in again["records"]] == [r["status"] for r in recs]


def test_line_levels_stop_two_halvings_below_the_grid():
    two = MAX_COARSENINGS
    assert line_levels(4001, max_coarsenings=two) == [1001, 2001, 4001], \
        "capped high-M grid: coarsest 1001"
    assert line_levels(4001) == [501, 1001, 2001, 4001], "no limit: down to 501 nodes"
    assert line_levels(3601, max_coarsenings=two) == line_levels(3601) == [901, 1801, 3601]
    assert line_levels(2001, max_coarsenings=two) == [501, 1001, 2001]
    assert line_levels(801, max_coarsenings=two) == [801]
    assert MAX_COARSENINGS == 2 and COARSEST_NODES == 501


def test_high_load_line_converges_on_the_default_grid(load_study):
    # M = 1874, L = 0 stalled in every continuation step when the sequence started on 501
    # nodes of the capped 4001-node grid (83 nodes per Hertz half-width)
    mod = load_study("stability_atlas")
    r = bf.solve(mod.line_scene(1874.0, 0.0))
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 40, "three levels, no continuation (measured 16)"
    assert math.isfinite(r.summary()["h_central"])


def test_light_point_load_starts_from_a_finite_guess(load_study):
    # M = 0.3 on 97^2: the default domain is about 320 Hertz radii long (8 hydrodynamic
    # lengths), 3.3 Hertz radii per cell; the Hertzian start fell between the nodes, its
    # integral was 0 and every attempt "diverged" at iteration 0 with residual NaN
    mod = load_study("stability_atlas")
    for L in (0.0, 5.0):
        r = bf.solve(mod.point_scene(0.3, L))
        assert r.status == "converged", r.message
        assert r.newton_iterations <= 30, "measured 14"
        assert math.isfinite(r.summary()["h_central"])


def test_isoviscous_high_load_point_continues_in_speed(load_study):
    # M = 1160, L = 0 on 97^2 stalled from the Hertzian start and had no continuation
    # path (alpha = 0); it now continues in the entrainment speed, as line contacts do
    mod = load_study("stability_atlas")
    r = bf.solve(mod.point_scene(1160.0, 0.0))
    assert r.status == "converged", r.message
    assert "continuation in speed" in r.message
    assert r.newton_iterations <= 150, "measured 81 (4 continuation steps)"


def test_light_line_load_starts_from_a_finite_guess(load_study):
    # M = 0.01: the default domain is so long against the Hertz half-width that the
    # Hertzian start fell between the 501 nodes of the first level (NaN residual, status
    # "diverged" at iteration 0)
    mod = load_study("stability_atlas")
    r = bf.solve(mod.line_scene(0.01, 5.0))
    assert r.status == "converged", r.message
    assert r.newton_iterations <= 60, "measured 26"

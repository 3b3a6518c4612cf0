"""The quick subset of the seeded command-line fuzz (studies/scene_fuzz.py): no violation.

Each violation names its case; the reproducer scene is written by the study into
``violations/<case>.toml`` (the table of every case is ``cases.md``).
"""
from __future__ import annotations

import json


def test_quick_fuzz_has_no_violation(load_study, tmp_path):
    fuzz = load_study("scene_fuzz")
    res = fuzz.main(tmp_path, quick=True)
    assert res["cases"] >= 30 and set(res["by_category"]) == set(fuzz.COUNTS)
    # the subset reaches every outcome: solved, invalid input, and no (converged) solution
    assert {"0", "2", "3"} <= set(res["by_exit"]), res["by_exit"]
    details = json.dumps(res["violating"], indent=1)
    assert res["violations"] == 0, f"fuzz violations:\n{details}"
    table = (tmp_path / "cases.md").read_text(encoding="utf-8")
    assert table.count("\n| ") == res["cases"], "one table row per case (after the header)"


def test_checks_catch_what_they_claim(load_study, tmp_path):
    """Negative controls: a hand-made run of each kind of violation is flagged."""
    fuzz = load_study("scene_fuzz")
    case = fuzz.Case("c", "sliding", "synthetic", b"", time_limit=2.0, iteration_budget=10)

    def run(exit_code, stderr="", summary=None, files=(), wall=0.1):
        folder = tmp_path / f"run{run.n}"
        run.n += 1
        (folder / "out").mkdir(parents=True)
        (folder / "stderr.txt").write_text(stderr, encoding="utf-8")
        for name in files:
            (folder / "out" / name).write_text("x", encoding="utf-8")
        if summary is not None:
            (folder / "out" / "summary.json").write_text(summary, encoding="utf-8")
        return fuzz.check(case, folder, exit_code, wall).violations
    run.n = 0

    good = {"status": "converged", "success": True, "h_min": 1e-7, "h_central": 2e-7,
            "load": 1e5, "friction_coefficient": 0.05, "heat_power": 3.0,
            "newton_iterations": 5, "wall_time_s": 1.0}
    assert run(0, summary=json.dumps(good)) == []

    def bad(**changes):
        return json.dumps({**good, **changes})

    assert run(1, "Traceback (most recent call last):") == ["traceback"]
    assert "raw-warning" in run(0, "/x/y.py:12: RuntimeWarning: divide by zero",
                                summary=json.dumps(good))
    assert run(0, summary=bad(p_max=float("nan"))) == ["nonfinite"]
    assert run(3, summary=json.dumps(good)) == ["exit-vs-success"]
    assert run(2, "bearing-fem: invalid input: x", files=["result.h5"]) == ["exit-vs-success"]
    assert run(2, "bearing-fem: invalid input: " + "x" * 1000) == ["long-message"]
    assert run(0, summary=bad(h_min=-1e-9)) == ["negative-film"]
    assert run(0, summary=bad(h_min=3e-7)) == ["film-order"]
    assert run(0, summary=bad(load=-1.0)) == ["negative-load"]
    assert run(0, summary=bad(friction_coefficient=6.8e14)) == ["friction>1"]
    assert run(0, summary=bad(friction_coefficient=-4.6)) == ["friction>1"]
    assert run(0, summary=bad(heat_power=-1.0)) == ["negative-heat"]
    assert run(0, summary=bad(newton_iterations=11)) == ["budget-iterations"]
    assert run(0, summary=bad(wall_time_s=2.0 * fuzz.TIME_FACTOR + fuzz.TIME_SLACK + 0.1)) \
        == ["budget-time"]
    assert run(None) == ["budget-time"], "a run killed at its hard timeout"
    # a failure may carry any numbers: the physical checks apply to successes only
    assert run(3, summary=bad(success=False, status="diverged", load=-1.0,
                              friction_coefficient=5.0)) == []


def test_bearing_checks_catch_what_they_claim(load_study, tmp_path):
    """Negative controls of the bearing-file checks: signs and friction coefficients
    anywhere in bearing_summary.json (not in the input echo or the relative errors),
    each contact's film order, and the per-contact budget (per slice of a roller)."""
    fuzz = load_study("scene_fuzz")
    case = fuzz.Case("b", "bearing-variant", "synthetic", b"", time_limit=1.0,
                     iteration_budget=10, command="bearing")

    def contact(**changes):
        return {"raceway": "inner", "status": "converged", "success": True, "load": 100.0,
                "h_min": 1e-7, "h_central": 2e-7, "heat_power": 1.0, "newton_iterations": 5,
                "wall_time_s": 0.2, "error_estimate": {"h_min": 0.5, "h_central": 0.1},
                **changes}

    def summary(inner=None, **changes):
        return {"status": "converged", "success": True, "wall_time_s": 0.5,
                "friction_torque": 0.1, "heat_power": 30.0, "h_min": 1e-7,
                "radial_load": 4000.0, "axial_load": 0.0,
                "contact_solves": {"distinct_solved": 2},
                "elements": [{"load": 100.0, "torque": 0.01, "heat_power": 1.0,
                              "inner": inner or contact(), "outer": contact()}],
                "empirical": {"nikitin": {"friction_coefficient": 0.004, "torque": 1.0}},
                "bearing": {"empirical": {"friction_coefficient": 5.0}},
                "units": {"h_min": "m"}, **changes}

    def run(exit_code, data):
        folder = tmp_path / f"run{run.n}"
        run.n += 1
        (folder / "out").mkdir(parents=True)
        (folder / "stderr.txt").write_text("", encoding="utf-8")
        (folder / "out" / "bearing_summary.json").write_text(json.dumps(data),
                                                              encoding="utf-8")
        return fuzz.check(case, folder, exit_code, 1.0).violations
    run.n = 0

    assert run(0, summary()) == []
    assert run(0, summary(heat_power=-1.0)) == ["negative-heat"]
    assert run(0, summary(friction_torque=-0.1)) == ["negative-torque"]
    assert run(0, summary(inner=contact(h_min=-1e-9))) == ["negative-film"]
    assert run(0, summary(inner=contact(h_min=3e-7))) == ["film-order"]
    assert run(0, summary(inner=contact(load=-1.0))) == ["negative-load"]
    assert run(0, summary(empirical={"nikitin": {"friction_coefficient": 2.0}})) \
        == ["friction>1"]
    assert run(0, summary(film_formulas={"inner": {"HD": {"h_min": 2e-7, "h_central": 1e-7}}})) \
        == ["film-order"]
    assert run(3, summary()) == ["exit-vs-success"]
    assert run(0, summary(inner=contact(newton_iterations=11))) == ["budget-iterations"]
    assert run(0, summary(inner=contact(newton_iterations=55, slices=11))) == []
    assert run(0, summary(inner=contact(wall_time_s=2.5))) == ["budget-time"]
    assert run(0, summary(wall_time_s=4.0)) == ["budget-time"], "2 solves x 1 s x 1.25 + 1"
    # a failure may carry any numbers
    assert run(3, summary(success=False, status="contacts_failed", heat_power=-1.0)) == []

"""Graded line grids (``mesh.file`` with non-uniform nodes) and their study."""
from __future__ import annotations


def test_graded_grid_study_quick(load_study, tmp_path):
    mod = load_study("line_graded_grid")
    rows = mod.main(tmp_path, quick=True)["rows"]
    assert all(r["status"] == "converged" for r in rows), [r["status"] for r in rows]
    by = {(r["grid"], r["nodes"]): r for r in rows}
    for n in (401, 801):
        uni, gra = by[("uniform", n)], by[("graded", n)]
        assert gra["h_min_error"] < uni["h_min_error"], \
            f"{n} nodes: graded h_min closer to the reference (measured 8e-4 vs 2.7e-3 on " \
            "401, 1e-6 vs 7e-3 on 801)"
        assert gra["friction_force_error"] < 0.5 * uni["friction_force_error"], \
            f"{n} nodes: graded friction (measured 4.5e-3 vs 3.3e-2, 1.1e-3 vs 1.2e-2)"
        assert gra["h_central_error"] < 5e-3, "h_central within 0.5 % (measured 3.7e-3 on 401)"
        assert gra["estimate_h_min"] is not None, "nested levels: the error estimate exists"
    for name in ("runs.csv", "line_graded_grid.md", "summary.json", "line_graded_grid.png"):
        assert (tmp_path / name).stat().st_size > 100

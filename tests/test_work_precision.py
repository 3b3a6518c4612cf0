"""Work-precision study (quick mode) and ``bearing-fem bench``: they run and their numbers
hold. No assertion on wall time (the machine may be shared); only on errors, orders and
the consistency of the settings search."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from bearing_fem import bench
from bearing_fem.cli import main as cli_main


@pytest.fixture(scope="module")
def wp(tmp_path_factory):
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "studies" / "work_precision.py"
    spec = importlib.util.spec_from_file_location("work_precision", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    out = tmp_path_factory.mktemp("wp")
    return mod, mod.main(out, quick=True), out


def _family(case: dict, fam: str) -> list[dict]:
    return sorted((r for r in case["rows"] if r["family"] == fam), key=lambda r: r["nodes"])


def test_files_written(wp):
    _, res, out = wp
    for name in ("runs.csv", "orders.csv", "targets.md", "work_precision.md", "summary.json",
                 "wp_line_ehl.png", "wp_circular_ehl.png", "wp_targets.png"):
        assert (out / name).is_file(), name
    json.loads((out / "summary.json").read_text())


def test_every_solve_successful_and_finite(wp):
    _, res, _ = wp
    for name, case in res["cases"].items():
        for r in case["rows"]:
            assert r["success"], (name, r["setting"], r["status"])
            for k in ("h_central", "h_min", "p_max", "friction_force", "heat_power"):
                assert r[k] is not None and math.isfinite(r[k]), (name, r["setting"], k)


@pytest.mark.parametrize("case,family,quantities", [
    ("kapitsa_line", "uniform", ("p_max", "friction_force", "heat_power")),
    ("kapitsa_point", "graded", ("p_max", "friction_force", "heat_power")),
    ("kapitsa_point", "uniform_small", ("p_max", "friction_force", "heat_power")),
    ("martin", "uniform", ("friction_force", "heat_power")),
])
def test_oracle_orders_and_monotone_errors(wp, case, family, quantities):
    """Smooth oracles: P1 gives second order (acceptance >= 1.8), errors fall with h."""
    _, res, _ = wp
    c = res["cases"][case]
    assert c["reference"]["source"] == "exact"
    for q in quantities:
        order = c["orders"][family][q]["order"]
        assert order >= 1.8, f"{case}/{family} {q}: fitted order {order:.2f} < 1.8 (P1, smooth)"
        errs = [r[f"{q}_error"] for r in _family(c, family)]
        assert all(b < a for a, b in zip(errs, errs[1:])), \
            f"{case}/{family} {q}: error must fall on every refinement, got {errs}"


def test_martin_pmax_converges(wp):
    """The Reynolds outlet is a free boundary inside a cell: p_max still converges, at
    a lower order (quick grids: about 1.5), and falls below 0.01 % on 1601 nodes."""
    _, res, _ = wp
    c = res["cases"]["martin"]
    assert c["orders"]["uniform"]["p_max"]["order"] > 1.0
    assert _family(c, "uniform")[-1]["p_max_error"] < 1e-4


def test_grading_helps_kapitsa_point(wp):
    """Same domain and node count: the sinh-graded grid beats the uniform one on p_max."""
    _, res, _ = wp
    c = res["cases"]["kapitsa_point"]
    for g, u in zip(_family(c, "graded"), _family(c, "uniform")):
        assert g["nodes"] == u["nodes"]
        assert g["p_max_error"] < u["p_max_error"], (g["setting"], u["setting"])


def test_grading_helps_line_h_min_and_friction(wp):
    """Same node count: the line grid refined at the outlet spike beats the uniform one in
    h_min and friction (quick run, 801 nodes: h_min 2.3e-5 vs 7.0e-3, friction 8.7e-4 vs
    1.2e-2) and keeps h_central within 0.1 %."""
    _, res, _ = wp
    rows = res["cases"]["line_ehl"]["rows"]
    graded = {r["nodes"]: r for r in rows if r["family"] == "graded"}
    uniform = {r["nodes"]: r for r in rows if r["setting"] == "n=801 tol=1e-08"}
    g, u = graded[801], uniform[801]
    assert g["h_min_error"] < 0.1 * u["h_min_error"], (g["h_min_error"], u["h_min_error"])
    assert g["friction_force_error"] < 0.5 * u["friction_force_error"]
    assert g["h_central_error"] < 1e-3, "0.1 % in h_central on 801 graded nodes"


@pytest.mark.parametrize("case", ["line_ehl", "circular_ehl"])
def test_ehl_h_central_converges(wp, case):
    """h_central error falls on every refinement of the nested family (the finest grid
    excluded: it makes the Richardson reference), at an order of at least 1.8."""
    _, res, _ = wp
    c = res["cases"][case]
    assert c["reference"]["source"].startswith("Richardson")
    rows = [r for r in _family(c, "uniform") if r.get("reference_grid") != "finest"]
    errs = [r["h_central_error"] for r in rows]
    assert all(b < a for a, b in zip(errs, errs[1:])), f"{case}: {errs}"
    assert c["orders"]["uniform"]["h_central"]["order"] >= 1.8
    unc = c["reference"]["uncertainty"]["h_central"]
    assert unc < 1e-3, f"{case}: reference uncertainty {unc:.1e} must resolve the 1 % target"


@pytest.mark.parametrize("case", ["line_ehl", "circular_ehl"])
def test_one_percent_setting_found_and_cheapest(wp, case):
    """The search names a 1 % setting, it meets 1 % in both films, no qualifying setting
    is faster, and the defaults meet 1 % (the time ratio is reported, not asserted)."""
    _, res, _ = wp
    t = res["targets"][case]
    best = t["0.01"]
    assert best is not None, f"{case}: no setting reaches 1 %"
    assert best["h_central_error"] <= 0.01 and best["h_min_error"] <= 0.01
    rows = res["cases"][case]["rows"]
    faster = [r for r in rows if r["time_s"] < best["time_s"]
              and r.get("reference_grid") != "finest"
              and r["h_central_error"] <= 0.01 and r["h_min_error"] <= 0.01]
    assert not faster, f"{case}: a faster 1 % setting was missed: {faster[0]['setting']}"
    assert t["defaults_meet_1pct"], f"{case}: defaults miss 1 %: {t['defaults']}"
    ratio = t["defaults_time_ratio"]
    assert ratio >= 1.0 - 1e-12, "the defaults row is a candidate: never faster than the best"
    assert t["defaults_within_factor"] == (ratio <= 1.5)


@pytest.mark.parametrize("case", ["line_ehl", "circular_ehl"])
def test_robust_one_percent_setting(wp, case):
    """The robust 1 % setting: every setting on at least as many unknowns (finest
    reference grid aside) also reaches 1 % in both films, and it is never faster than the
    plain fastest one."""
    _, res, _ = wp
    t = res["targets"][case]
    rob = t["0.01_robust"]
    assert rob is not None, f"{case}: no robust 1 % setting"
    rows = [r for r in res["cases"][case]["rows"] if r.get("reference_grid") != "finest"]
    for r in rows:
        if r["dofs"] >= rob["dofs"]:
            assert r["h_central_error"] <= 0.01 and r["h_min_error"] <= 0.01, r["setting"]
    assert rob["time_s"] >= t["0.01"]["time_s"]


def test_density_node_counts(wp):
    """The line density check keeps N - 1 divisible by 4 (a node at x = 0 on every
    coarser level of the grid sequence) and the requested fraction within one step."""
    mod, _, _ = wp
    for n_def in (801, 1801, 2549, 4001):
        for f in mod.DENSITY_FRACTIONS:
            n = mod._nodes_fraction(n_def, f)
            assert (n - 1) % 4 == 0
            assert abs((n - 1) - f * (n_def - 1)) <= 2, (n_def, f, n)


def test_richardson_formula(wp):
    mod, _, _ = wp
    # f(h) = 1 + h^2 sampled at h = 2, 1: the extrapolation is exact for order 2
    assert mod.richardson(5.0, 2.0) == pytest.approx(1.0, rel=1e-15)


# ---------------------------------------------------------------------------------------
# bench
# ---------------------------------------------------------------------------------------
def test_bench_cli_one_repeat_writes_json(tmp_path, capsys):
    """``bearing-fem bench --quick --repeat 1 --json FILE``: table and JSON keys."""
    path = tmp_path / "bench.json"
    code = cli_main(["bench", "--quick", "--repeat", "1", "--json", str(path)])
    out = capsys.readouterr().out
    assert code == 0, out
    for name in ("line", "point", "thermal", "bearing_6209", "Newton it.", "error est."):
        assert name in out
    d = json.loads(path.read_text())
    assert d["version"] == __import__("bearing_fem").__version__
    assert set(d["machine"]) >= {"platform", "cpu_model", "cpu_count", "python", "numpy",
                                 "scipy"}
    assert d["quick"] is True and d["repeats"] == 1 and "timestamp" in d
    rows = {r["case"]: r for r in d["cases"]}
    assert set(rows) == {"line", "point", "thermal", "bearing_6209"}
    for name, r in rows.items():
        assert r["status"] == "converged", (name, r["status"])
        assert r["newton_iterations"] > 0 and r["time_s"] > 0
        assert 1e-8 < r["h_central"] < 1e-5, (name, r["h_central"])
        assert r["error_estimate"] is not None and 0 <= r["error_estimate"] < 0.5
    assert rows["bearing_6209"]["contact_nodes"] == bench.QUICK_BEARING_NODES
    assert rows["line"]["error_estimate"] < 1e-3, "default line grid: below 0.1 %"


def test_bench_cli_bad_json_directory(tmp_path, capsys):
    code = cli_main(["bench", "--quick", "--json", str(tmp_path / "no" / "such" / "b.json")])
    assert code == 2
    assert "directory does not exist" in capsys.readouterr().err


def test_bench_cli_json_is_a_directory(tmp_path, capsys, monkeypatch):
    """``--json DIR`` is refused before anything is solved (it used to run the whole bench,
    then fail and leave ``DIR.tmp`` behind)."""
    def no_run(**kwargs):
        raise AssertionError("the bench ran although its output cannot be written")

    monkeypatch.setattr(bench, "run_bench", no_run)
    (tmp_path / "out").mkdir()
    assert cli_main(["bench", "--quick", "--json", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "it is a directory" in err and "bench.json" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"], "no file left behind"


def test_bench_write_json_strict_and_clean(tmp_path):
    """The report is strict JSON (a non-finite number is null, never NaN), and a failed
    write leaves no temporary file."""
    report = {"version": "x", "cases": [{"h_central": float("nan"), "time_s": np.float64(1)}]}
    path = bench.write_json(report, tmp_path / "b.json")
    assert json.loads(path.read_text(), parse_constant=lambda c: pytest.fail(c)) == \
        {"version": "x", "cases": [{"h_central": None, "time_s": 1.0}]}
    (tmp_path / "d").mkdir()
    with pytest.raises(IsADirectoryError):
        bench.write_json(report, tmp_path / "d")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.json", "d"]


@pytest.mark.skipif(not Path("/proc/cpuinfo").is_file(), reason="Linux /proc/cpuinfo")
def test_bench_machine_names_the_cpu():
    """Two machines are told apart by their CPU: on Linux platform.processor() is empty,
    so the model name comes from /proc/cpuinfo."""
    m = bench.machine_info()
    assert m["cpu_model"], m
    assert m["cpu_model"] in bench.format_table(
        {"version": "v", "machine": m, "load_average": [0.0, 0.0], "repeats": 1,
         "cases": [{"case": "line"}]})


def test_bench_cli_bad_repeat(capsys):
    assert cli_main(["bench", "--quick", "--repeat", "0"]) == 2
    assert "--repeat" in capsys.readouterr().err


@pytest.mark.slow
def test_bench_quick_default_repeats(tmp_path, capsys):
    """The documented ``bearing-fem bench --quick`` (two interleaved repetitions)."""
    path = tmp_path / "bench.json"
    assert cli_main(["bench", "--quick", "--json", str(path)]) == 0
    d = json.loads(path.read_text())
    assert d["repeats"] == 2
    assert all(len(r["times_s"]) == 2 and r["time_s"] == min(r["times_s"]) for r in d["cases"])


@pytest.mark.parametrize("bad", [0, 2.5, "2", True])
def test_run_bench_refuses_a_bad_repeat_count(bad):
    """run_bench(repeats=2.5) ended in a TypeError from range() and repeats="2" in one
    from '<'; both are a ValueError naming the argument and the value, before any
    solve."""
    with pytest.raises(ValueError, match=r"repeats must be a whole number of runs >= 1, "
                                         r"got "):
        bench.run_bench(quick=True, repeats=bad)

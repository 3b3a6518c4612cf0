"""The run store: schema, migration, filters, exports, and concurrent writers."""
from __future__ import annotations

import json
import sqlite3
import subprocess
import sys
import textwrap
import time

import pytest

from bearing_fem.errors import SceneError
from bearing_fem.scene import Scene
from bearing_fem.sweep import Case, RunStore, query_runs
from bearing_fem.sweep.store import (CORE_COLUMNS, export_csv, flatten_summary,
                                     parse_filter)


def rigid(gap: float) -> Scene:
    return Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                            "lubricant": {"viscosity": 0.01},
                            "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": gap},
                            "model": {"elasticity": "rigid"}, "mesh": {"nodes": 51}})


def outcome(status="linear", success=True, **numbers):
    summary = {"status": status, "success": success, "message": f"{status} done",
               "warnings": ["a note"], "error_estimate": {"h_central": 1e-3, "method": "x"},
               "wall_time_s": 0.5, "version": "9.9", "units": {"h_central": "m"},
               "dimensionless": {"M": 10.0}, "scene": {"ignored": True}, "history": [1, 2],
               **numbers}
    return {"status": status, "success": success, "message": summary["message"],
            "summary": summary, "result_path": None, "run_time_s": 0.7, "worker": "w:1",
            "attempts": 1}


def test_schema_columns_units_and_migration(tmp_path):
    path = tmp_path / "runs.sqlite"
    c1, c2 = Case({"load.gap": 1e-6}, rigid(1e-6)), Case({"load.gap": 2e-6}, rigid(2e-6))
    with RunStore(path) as store:
        assert store.conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
        assert list(CORE_COLUMNS) == store.columns()
        store.write(c1, outcome(h_central=1.1e-6))
        store.write(c2, outcome(h_central=2.2e-6, p_max=3e5))  # a new summary key: migrated
        cols = store.columns()
        assert {"load.gap", "h_central", "p_max", "dimensionless.M",
                "error_estimate.h_central", "error_estimate.method"} <= set(cols)
        assert "history" not in cols and "units" not in cols, "lists and units are not columns"
        info = store.column_info()
        assert info["h_central"] == {"role": "summary", "unit": "m"}
        assert info["load.gap"]["role"] == "param" and info["hash"]["role"] == "core"
        assert info["wall_time_s"]["unit"] == "s"
        rows = {r["hash"]: r for r in store.rows()}
    r1, r2 = rows[c1.hash], rows[c2.hash]
    assert r1["p_max"] is None and r2["p_max"] == 3e5
    assert r1["load.gap"] == 1e-6 and r1["status"] == "linear" and r1["success"] == 1
    assert json.loads(r1["warnings"]) == ["a note"]
    assert json.loads(r1["error_estimate"]) == {"h_central": 1e-3, "method": "x"}
    assert r1["version"] == "9.9" and r1["wall_time_s"] == 0.5 and r1["run_time_s"] == 0.7
    assert json.loads(r1["scene"])["load"] == {"gap": 1e-6}
    # reopening keeps everything (schema created once)
    with RunStore(path) as store:
        assert len(store.rows()) == 2


def test_pending_then_final_replaces_the_row(tmp_path):
    case = Case({"load.gap": 1e-6}, rigid(1e-6))
    with RunStore(tmp_path / "s.sqlite") as store:
        store.write(case, outcome(h_central=1.0))
        store.mark_pending([case], {case.hash: 1})
        (row,) = store.rows()
        assert row["status"] == "pending" and row["success"] is None
        assert row["h_central"] is None, "a pending row carries no stale result"
        assert store.states([case.hash])[case.hash]["attempts"] == 1
        store.write(case, outcome("max_iterations", False, h_central=2.0))
        (row,) = store.rows()
        assert (row["status"], row["success"], row["h_central"]) == ("max_iterations", 0, 2.0)


def test_a_case_finished_elsewhere_since_planning_is_not_set_back_to_pending(tmp_path):
    """Two sweeps share a store: one plans while a case is pending, the other finishes it,
    then the first marks its cases. The finished row stays final (else the other sweep's
    report counted it as unfinished) and the first sweep does not run it again."""
    done, todo = (Case({"load.gap": g}, rigid(g)) for g in (1e-6, 2e-6))
    with RunStore(tmp_path / "s.sqlite") as store:
        store.mark_pending([done, todo])
        planned = store.states([done.hash, todo.hash])
        store.write(done, outcome(h_central=1.0))            # the other process
        marked = store.mark_pending([done, todo], planned=planned)
        assert [c.hash for c in marked] == [todo.hash], "only the still-pending case runs"
        assert store.states([done.hash])[done.hash]["status"] == "linear"
        # a failed row planned for a retry is replaced as before
        store.write(todo, outcome("stalled", False))
        planned = store.states([todo.hash])
        assert store.mark_pending([todo], planned=planned) == [todo]
        assert store.states([todo.hash])[todo.hash]["status"] == "pending"


def test_filters_statuses_and_exports(tmp_path):
    path = tmp_path / "s.sqlite"
    cases = [Case({"load.gap": g}, rigid(g)) for g in (1e-6, 2e-6, 3e-6, 4e-6)]
    with RunStore(path) as store:
        store.write(cases[0], outcome(h_central=1.0))
        store.write(cases[1], outcome("no_solution", False))
        store.mark_pending([cases[2]])
        store.write(cases[3], outcome(h_central=4.0))
    rows, cols = query_runs(path, status=["success"])
    assert sorted(r["load.gap"] for r in rows) == [1e-6, 4e-6]
    assert cols[:3] == ["hash", "status", "load.gap"] and "h_central" in cols
    assert [r["status"] for r in query_runs(path, status=["failed"])[0]] == ["no_solution"]
    assert [r["status"] for r in query_runs(path, status=["unfinished"])[0]] == ["pending"]
    assert len(query_runs(path, status=["final"])[0]) == 3
    rows, _ = query_runs(path, where=["load.gap>=2e-6", "status!=pending"])
    assert [r["load.gap"] for r in rows] == [2e-6, 4e-6], "sorted by the parameters"
    rows, cols = query_runs(path, columns=["hash", "h_central"], where=[("h_central", ">", 2)])
    assert cols == ["hash", "h_central"] and rows == [{"hash": cases[3].hash,
                                                        "h_central": 4.0}]
    text = export_csv(query_runs(path, columns="all")[0], None, ["load.gap", "status"])
    assert text.splitlines()[0] == "load.gap,status" and len(text.splitlines()) == 5
    export_csv(rows, tmp_path / "out.csv", ["hash", "h_central"])
    assert (tmp_path / "out.csv").read_text().splitlines()[1] == f"{cases[3].hash},4.0"
    with pytest.raises(SceneError, match="no column 'nope'"):
        query_runs(path, where=["nope=1"])
    with pytest.raises(SceneError, match="COLUMN OP VALUE"):
        parse_filter("load.gap")
    with pytest.raises(SceneError, match="no run store"):
        query_runs(tmp_path / "missing.sqlite")


def test_parquet_needs_pyarrow(tmp_path):
    from bearing_fem.sweep import export_runs

    try:
        import pyarrow  # noqa: F401
    except ImportError:
        with pytest.raises(SceneError, match="Parquet export needs pyarrow"):
            export_runs([{"a": 1}], ["a"], parquet=tmp_path / "x.parquet")
        assert not (tmp_path / "x.parquet").exists()
    else:  # pragma: no cover - pyarrow is optional
        import pyarrow.parquet as pq

        export_runs([{"a": 1, "b": "x"}, {"a": None, "b": None}], ["a", "b"],
                    parquet=tmp_path / "x.parquet")
        assert pq.read_table(tmp_path / "x.parquet").to_pydict() == {"a": [1, None],
                                                                    "b": ["x", None]}


def test_flatten_summary():
    cols, units = flatten_summary({"status": "converged", "h_min": None, "p_max": 1.0,
                                   "units": {"p_max": "Pa", "nope": "m"}, "warnings": ["x"],
                                   "dimensionless": {"M": 1.0, "deep": {"x": 1}},
                                   "elements": [{"load": 1.0}], "scene": {}})
    assert cols == {"status": "converged", "h_min": None, "p_max": 1.0, "dimensionless.M": 1.0}
    assert units == {"p_max": "Pa"}


def test_not_a_store(tmp_path):
    (tmp_path / "junk.sqlite").write_bytes(b"this is not sqlite" * 100)
    with pytest.raises(SceneError, match="is not a bearing_fem run store"):
        RunStore(tmp_path / "junk.sqlite")
    with pytest.raises(SceneError, match="is a directory"):
        RunStore(tmp_path)


def test_another_sqlite_database_is_refused_untouched(tmp_path):
    for name, schema in (("other.sqlite", "CREATE TABLE x (a INTEGER)"),
                         ("lookalike.sqlite", "CREATE TABLE runs (id INTEGER, name TEXT)")):
        path = tmp_path / name
        con = sqlite3.connect(path)
        con.execute(schema)
        con.commit()
        con.close()
        before = path.read_bytes()
        with pytest.raises(SceneError, match=r"is an SQLite database but not a bearing_fem "
                                             r"run store \(its tables: "):
            RunStore(path)
        assert path.read_bytes() == before, f"{name}: not changed (no tables, no WAL mode)"


def test_status_and_limit_arguments(tmp_path):
    with RunStore(tmp_path / "s.sqlite") as store:
        store.write(Case({"i": 1}, rigid(1e-6)), outcome())
        assert len(store.rows(status="linear")) == 1, "a single status, not its characters"
        assert store.rows(status="li") == []
        for bad in (0, -1, 2.5, True):
            with pytest.raises(SceneError, match="limit must be a positive whole number"):
                store.rows(limit=bad)


# ---------------------------------------------------------------------------------------
# several processes writing one store at once
# ---------------------------------------------------------------------------------------
WRITER = textwrap.dedent("""
    import sys, time
    from pathlib import Path
    from bearing_fem.scene import Scene
    from bearing_fem.sweep import Case, RunStore

    store_path, k, n, go = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), Path(sys.argv[4])

    def scene(gap):
        return Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                                "lubricant": {"viscosity": 0.01},
                                "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": gap},
                                "model": {"elasticity": "rigid"}})

    cases = [Case({"writer": k, "i": i}, scene(1e-7 * (1 + k + 10 * i))) for i in range(n)]
    shared = Case({"shared": 1}, scene(5e-4))  # every writer writes this one too
    store = RunStore(store_path, timeout=60)
    while not go.exists():
        time.sleep(0.005)
    store.mark_pending(cases)
    for i, c in enumerate(cases):
        summary = {"status": "linear", "success": True, "message": f"w{k} i{i}",
                   "h_central": float(1000 * k + i), f"only_writer_{k}": float(i),
                   "units": {"h_central": "m"}}
        store.write(c, {"status": "linear", "success": True, "message": summary["message"],
                        "summary": summary, "result_path": None, "run_time_s": 0.0,
                        "worker": f"writer{k}", "attempts": 1})
        if i == n // 2:
            store.write(shared, {"status": "linear", "success": True, "message": f"w{k}",
                                 "summary": {"status": "linear", "h_central": -1.0},
                                 "result_path": None, "attempts": 1})
    store.close()
""")


def test_concurrent_writers_from_several_processes(tmp_path):
    """Four processes write 40 cases each (plus one case all of them write) at once, each
    bringing its own new summary column: every row arrives intact, no lock error."""
    path, go = tmp_path / "shared.sqlite", tmp_path / "go"
    script = tmp_path / "writer.py"
    script.write_text(WRITER, encoding="utf-8")
    n, writers = 40, 4
    procs = [subprocess.Popen([sys.executable, str(script), str(path), str(k), str(n), str(go)],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for k in range(writers)]
    time.sleep(0.5)  # let them all open the store and wait
    go.write_text("go")
    errors = []
    for p in procs:
        out, err = p.communicate(timeout=120)
        if p.returncode:
            errors.append(err)
    assert not errors, errors
    with RunStore(path) as store:
        assert store.conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        rows = store.rows()
        cols = store.columns()
    assert len(rows) == writers * n + 1
    assert {f"only_writer_{k}" for k in range(writers)} <= set(cols)
    for r in rows:
        if r["shared"] == 1:
            assert r["status"] == "linear" and r["h_central"] == -1.0
            continue
        k, i = r["writer"], r["i"]
        assert (r["status"], r["success"], r["message"]) == ("linear", 1, f"w{k} i{i}")
        assert r["h_central"] == 1000 * k + i and r[f"only_writer_{k}"] == i
        assert all(r[f"only_writer_{j}"] is None for j in range(writers) if j != k)
    # a plain sqlite3 reader sees the same (the WAL is readable by any client)
    with sqlite3.connect(path) as conn:
        assert conn.execute("SELECT COUNT(*) FROM runs WHERE status = 'linear'"
                            ).fetchone()[0] == writers * n + 1


def test_error_estimate_columns_are_dimensionless(tmp_path):
    """The run store's error_estimate.* columns (relative errors) had no unit; they get
    "1", the unit of the summaries' other dimensionless ratios (friction_coefficient,
    film_parameter_min), and so do the counts and the Moes groups."""
    import bearing_fem as bf
    from bearing_fem.bearing import Bearing, solve_bearing

    scene = Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                             "materials": {"reduced_modulus": 2.2e11},
                             "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
                             "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"force": 2e5},
                             "mesh": {"nodes": 401}})
    contact = bf.solve(scene).summary()
    assert contact["units"]["friction_coefficient"] == "1"
    bearing = solve_bearing(Bearing.from_dict({
        "bearing": {"type": "cylindrical-roller", "bore": 0.03, "outside_diameter": 0.062,
                    "element_diameter": 0.009, "elements": 13, "effective_length": 0.009,
                    "pitch_diameter": 0.046, "radial_clearance": 5e-6},
        "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
        "operation": {"inner_rpm": 1500.0, "radial_load": 2000.0},
        "mesh": {"line_nodes": 201}})).summary()
    assert bearing["units"]["film_parameter_min"] == "1"
    for summary in (contact, bearing):
        cols, units = flatten_summary(summary)
        rel = [c for c, v in cols.items()
               if c.startswith("error_estimate.") and isinstance(v, float)]
        assert len(rel) >= 4, cols
        assert {c: units.get(c) for c in rel} == dict.fromkeys(rel, "1"), units
    # counts and dimensionless groups too: one rule, every dimensionless number has "1"
    cols, units = flatten_summary(contact)
    for c in ("error_estimate.levels", "newton_iterations", "dofs", "dimensionless.M",
              "dimensionless.L"):
        assert c in cols and units.get(c) == "1", (c, units.get(c))
        with RunStore(tmp_path / "runs.sqlite") as store:
            store.write(Case({"i": len(rel)}, rigid(1e-6 * len(rel))),
                        {"status": summary["status"], "success": True, "message": "",
                         "summary": summary, "result_path": None, "run_time_s": 0.1,
                         "worker": "w", "attempts": 1})
            info = store.column_info()
        assert all(info[c]["unit"] == "1" for c in rel), {c: info[c] for c in rel}


def test_column_units_of_line_and_point_rows_in_one_store(tmp_path):
    """A line contact's load is in N/m, a point contact's in N. A store holding both (two
    sweeps into one store) labelled the column with the first unit written, so
    ``bearing-fem runs`` printed the point loads under "load [N/m]"; the column's unit
    names both."""
    import bearing_fem as bf

    point = Scene.from_dict({"contact": {"kind": "point", "rx": 0.01, "ry": 0.01},
                             "lubricant": {"viscosity": 0.01},
                             "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": 1e-6},
                             "model": {"elasticity": "rigid"}, "mesh": {"nodes": [21, 21]}})
    path = tmp_path / "runs.sqlite"
    with RunStore(path) as store:
        for i, scene in enumerate((rigid(1e-6), point, rigid(2e-6))):
            r = bf.solve(scene)
            store.write(Case({"i": i}, scene),
                        {"status": r.status, "success": r.success, "message": r.message,
                         "summary": r.summary(), "result_path": None, "run_time_s": 0.1,
                         "worker": "w", "attempts": 1})
        info = store.column_info()
    assert info["load"]["unit"] == "N/m or N", info["load"]
    assert info["heat_power"]["unit"] == "W/m or W", info["heat_power"]
    assert info["h_central"]["unit"] == "m", "one unit where the rows agree"
    from bearing_fem.sweep import store_units
    assert store_units(path)["friction_force"] == "N/m or N"


def test_every_number_of_a_bearing_row_has_a_unit(tmp_path):
    """The run store takes its column units from the summary's ``units``. A bearing's
    summary named none for its tables' numbers, so the store listed
    load_balance.radial_sum (N), energy_balance.torque_times_speed (W),
    load_distribution.load_zone_half_angle_deg (deg), kinematics.element_rpm (1/min), ...
    without a unit. Every float column of a bearing row has one now (integers are counts
    and indices)."""
    from bearing_fem.bearing import Bearing, solve_bearing

    bearing = Bearing.from_dict({
        "bearing": {"type": "cylindrical-roller", "bore": 0.03, "outside_diameter": 0.062,
                    "element_diameter": 0.009, "elements": 13, "effective_length": 0.009,
                    "pitch_diameter": 0.046, "radial_clearance": 5e-6},
        "lubricant": {"viscosity": 0.05, "piezo": 2e-8},
        "operation": {"inner_rpm": 1500.0, "radial_load": 2000.0},
        "mesh": {"line_nodes": 201}})
    r = solve_bearing(bearing)
    assert r.success, r.message
    cols, units = flatten_summary(r.summary())
    floats = sorted(c for c, v in cols.items() if isinstance(v, float))
    assert {"load_balance.radial_sum", "energy_balance.torque_times_speed",
            "load_distribution.max_element_load", "kinematics.element_rpm"} <= set(floats)
    assert [c for c in floats if not units.get(c)] == [], units
    assert units["load_balance.radial_sum"] == "N"
    assert units["energy_balance.torque_times_speed"] == "W"
    assert units["load_distribution.load_zone_half_angle_deg"] == "deg"


def test_filter_value_that_is_not_a_number_on_a_number_column(tmp_path):
    """``--where "load.force>=2O"`` (a letter O) compared the numbers with the text '2O'
    and listed no row (or, with <, every row) without a word; it is refused naming the
    column and the value. Numbers JSON does not read (".5", "+2") are numbers."""
    path = tmp_path / "s.sqlite"
    cases = [Case({"load.gap": g}, rigid(g)) for g in (1e-6, 2e-6)]
    with RunStore(path) as store:
        store.write(cases[0], outcome(h_central=0.25))
        store.write(cases[1], outcome(h_central=0.75))
    for bad in ("h_central>abc", "load.gap<=1e-6x", "h_central=O.5"):
        with pytest.raises(SceneError, match=r"holds numbers and '.*' is not a number"):
            query_runs(path, where=[bad])
    assert parse_filter("h_central<=.5") == ("h_central", "<=", 0.5)
    assert parse_filter("h_central>+0.5") == ("h_central", ">", 0.5)
    assert [r["h_central"] for r in query_runs(path, where=["h_central<=.5"])[0]] == [0.25]
    assert len(query_runs(path, where=["status=linear"])[0]) == 2, "text columns as before"


def test_export_to_a_directory_is_an_input_error(tmp_path, capsys):
    """``bearing-fem runs STORE --csv DIR`` ended in a traceback (IsADirectoryError, exit
    1); it is an input error (exit 2, one line), and no temporary file is left."""
    from bearing_fem.cli import main

    path = tmp_path / "s.sqlite"
    with RunStore(path) as store:
        store.write(Case({"load.gap": 1e-6}, rigid(1e-6)), outcome(h_central=1.0))
    (tmp_path / "out").mkdir()
    assert main(["runs", str(path), "--csv", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "cannot write the CSV export to" in err and "it is a directory" in err, err
    assert "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith("s.sqlite")) \
        == ["out"], "no temporary file left"
    with pytest.raises(SceneError, match="it is a directory"):
        export_csv([], tmp_path / "out", ["hash"])


def test_query_one_column_or_filter_as_a_string(tmp_path):
    """query_runs(store, columns="h_central") looked for the columns 'h', '_', 'c', ...
    and where="load.gap>1e-6" for the filter 'l'; a string is one name (or comma-separated
    names, as on the command line) and one filter."""
    path = tmp_path / "s.sqlite"
    with RunStore(path) as store:
        for g in (1e-6, 2e-6):
            store.write(Case({"load.gap": g}, rigid(g)), outcome(h_central=g))
        assert [r["h_central"] for r in store.rows(columns="h_central")] == [1e-6, 2e-6]
    rows, cols = query_runs(path, columns="h_central", where="load.gap>1e-6")
    assert cols == ["h_central"] and rows == [{"h_central": 2e-6}]
    rows, cols = query_runs(path, columns="load.gap, h_central")
    assert cols == ["load.gap", "h_central"] and len(rows) == 2

"""Running sweeps locally: the pool, resume, retry, adoption, errors, CLI, progress."""
from __future__ import annotations

import io
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import tomli_w

import bearing_fem as bf
from bearing_fem.cli import main
from bearing_fem.errors import SceneError
from bearing_fem.scene import Scene
from bearing_fem.sweep import (Case, RunStore, SolveProgress, SweepProgress, SweepSpec,
                               query_runs, solve_progress)
from bearing_fem.sweep import execute
from bearing_fem.sweep.execute import (PoolExecutor, Task, adopt, result_complete,
                                       run_task)

#: Rigid Barus cylinder, full-Sommerfeld: beyond Kapitsa's existence limit at gap 1e-7 m
#: (status no_solution), solved by one linear solve at the larger gaps (status linear).
BASE = {
    "title": "rigid cylinder",
    "contact": {"kind": "line", "rx": 0.01},
    "lubricant": {"viscosity": 0.05, "piezo": 5e-8},
    "kinematics": {"u1": 1.0, "u2": 1.0},
    "load": {"gap": 1e-6},
    "model": {"elasticity": "rigid", "cavitation": "none"},
    "mesh": {"nodes": 101},
}
SWEEP = {"sweep": {"scene": "base.toml"},
         "axes": {"load.gap": [1e-7, 3e-7, 1e-6], "kinematics.u1": [1.0, 2.0]},
         "zip": {"kinematics.u2": "kinematics.u1"}}


def write_sweep(tmp_path: Path, sweep: dict = SWEEP, base: dict = BASE) -> Path:
    (tmp_path / "base.toml").write_text(tomli_w.dumps(base), encoding="utf-8")
    path = tmp_path / "sweep.toml"
    path.write_text(tomli_w.dumps(sweep), encoding="utf-8")
    return path


def successes_have_files(store_path: Path) -> None:
    """No row claims success without its complete result folder."""
    with RunStore(store_path) as store:
        for r in store.rows():
            if r["success"]:
                assert result_complete(store.resolve(r["result_path"]), r["kind"]), r
                run = json.loads((store.resolve(r["result_path"]) / "run.json").read_text())
                assert run["hash"] == r["hash"]


def test_pool_resume_and_retry_failed(tmp_path):
    path = write_sweep(tmp_path)
    report = bf.sweep(path, workers=2)
    store = tmp_path / "sweep.sqlite"
    assert report.store == store and report.executor == "local pool of 2 processes"
    assert (report.cases, report.ran, report.skipped) == (6, 6, 0)
    assert (report.successes, report.failures, report.unfinished) == (4, 2, 0)
    rows, _ = query_runs(store, columns="all")
    by = {(r["load.gap"], r["kinematics.u1"]): r for r in rows}
    assert {k: r["status"] for k, r in by.items()} == {
        (1e-7, 1.0): "no_solution", (1e-7, 2.0): "no_solution", (3e-7, 1.0): "linear",
        (3e-7, 2.0): "linear", (1e-6, 1.0): "linear", (1e-6, 2.0): "linear"}
    assert all(r["kinematics.u2"] == r["kinematics.u1"] for r in rows)
    r = by[(1e-6, 2.0)]
    assert r["h_central"] == pytest.approx(1e-6, rel=1e-12), "rigid: h(0) is the gap"
    assert r["p_max"] > 0 and r["version"] == bf.__version__
    assert r["result_path"] == f"sweep_runs/{r['hash']}"
    summary = json.loads((tmp_path / r["result_path"] / "summary.json").read_text())
    assert summary["h_central"] == r["h_central"] and summary["status"] == "linear"
    assert (tmp_path / r["result_path"] / "result.h5").is_file()
    assert json.loads(r["scene"])["load"]["gap"] == 1e-6
    successes_have_files(store)

    again = bf.sweep(path, workers=2)
    assert (again.ran, again.skipped, again.adopted) == (0, 6, 0), "resume: nothing solved"
    assert again.statuses == report.statuses

    retry = bf.sweep(path, workers=1, retry_failed=True)
    assert (retry.ran, retry.skipped) == (2, 4), "only the two failures run again"
    assert retry.executor == "serial (this process)"
    with RunStore(store) as s:
        assert sorted(s.count().items()) == [("linear", 4), ("no_solution", 2)]


def test_missing_result_folder_is_run_again(tmp_path):
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.gap": [3e-7, 1e-6]}})
    first = bf.sweep(path, workers=1)
    assert first.successes == 2
    rows, _ = query_runs(tmp_path / "sweep.sqlite", columns="all")
    shutil.rmtree(tmp_path / rows[0]["result_path"])
    again = bf.sweep(path, workers=1)
    assert (again.ran, again.skipped) == (1, 1)
    assert again.to_run == [rows[0]["hash"]]
    successes_have_files(tmp_path / "sweep.sqlite")


def test_interrupted_client_results_are_adopted(tmp_path):
    """A worker finished and wrote its folder but the client died before recording it
    (its row is still pending): the next run records the folder instead of solving."""
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.gap": [3e-7, 1e-6, 2e-6]}})
    cases = SweepSpec.from_toml(path).cases()
    store = tmp_path / "sweep.sqlite"
    runs = tmp_path / "sweep_runs"
    with RunStore(store) as s:
        s.mark_pending(cases)
    out = run_task(Task(cases[1], str(runs / cases[1].hash)))
    assert out["status"] == "linear" and result_complete(runs / cases[1].hash, "scene")
    # a half-written folder (no run.json) of another case is not adopted
    (runs / cases[2].hash).mkdir()
    (runs / cases[2].hash / "summary.json").write_text("{}")
    assert adopt(cases[2], runs / cases[2].hash) is None
    report = bf.sweep(path, workers=1)
    assert (report.adopted, report.ran, report.successes) == (1, 2, 3)
    rows = {r["hash"]: r for r in query_runs(store, columns="all")[0]}
    assert rows[cases[1].hash]["h_central"] == out["summary"]["h_central"]
    assert rows[cases[1].hash]["load.gap"] == 1e-6
    successes_have_files(store)


def test_a_solve_that_raises_is_an_error_row(tmp_path, monkeypatch):
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.gap": [3e-7, 1e-6]}})
    real = execute._solve

    def flaky(case):
        if case.scene.load.gap == 1e-6:
            raise MemoryError("pretend the machine ran out of memory")
        return real(case)

    monkeypatch.setattr(execute, "_solve", flaky)
    report = bf.sweep(path, workers=1)  # in this process, so the patch applies
    assert (report.successes, report.failures) == (1, 1)
    (row,) = query_runs(tmp_path / "sweep.sqlite", status=["error"], columns="all")[0]
    assert row["success"] == 0 and row["result_path"] is None
    assert "raised MemoryError: pretend the machine ran out of memory" in row["message"]
    monkeypatch.setattr(execute, "_solve", real)
    assert bf.sweep(path, workers=1).ran == 0, "error is a final status"
    assert bf.sweep(path, workers=1, retry_failed=True).successes == 2


def kill_once(task: Task) -> dict:
    """A worker function whose first run of the case with params kill=1 dies."""
    marker = Path(task.run_dir).parent / "killed"
    if task.case.params.get("kill") and not marker.exists():
        marker.parent.mkdir(parents=True, exist_ok=True)
        marker.write_text("killed")
        os._exit(1)
    return run_task(task)


def test_pool_survives_a_dead_worker(tmp_path, monkeypatch):
    scenes = [Scene.from_dict({**BASE, "load": {"gap": g}}) for g in (3e-7, 1e-6, 2e-6, 4e-6)]
    cases = [Case({"kill": int(i == 1), "i": i}, s) for i, s in enumerate(scenes)]
    tasks = [Task(c, str(tmp_path / "runs" / c.hash)) for c in cases]
    monkeypatch.setattr(execute, "run_task", kill_once)  # the pool submits execute.run_task
    done = {}
    PoolExecutor(2).run(tasks, lambda t, out: done.__setitem__(t.case.params["i"], (t, out)))
    assert (tmp_path / "runs" / "killed").exists(), "the worker was killed once"
    assert sorted(done) == [0, 1, 2, 3]
    assert all(out["status"] == "linear" for _, out in done.values()), done
    assert done[1][0].attempts == 2, "the killed case ran again in a new pool"


def test_cli_sweep_and_runs(tmp_path, capsys):
    path = write_sweep(tmp_path)
    store = tmp_path / "cli.sqlite"
    assert main(["sweep", str(path), "--store", str(store), "--workers", "1",
                 "--dry-run"]) == 0
    assert "6 cases: 6 to run" in capsys.readouterr().out
    assert not store.exists(), "a dry run writes nothing"
    assert main(["sweep", str(path), "--store", str(store), "--workers", "1"]) == 3
    out, err = capsys.readouterr()
    assert "6 solved now" in out and "2 case(s) unsuccessful" in err
    assert main(["runs", str(store), "--status", "linear", "--where", "load.gap<1e-6"]) == 0
    out = capsys.readouterr().out
    assert "(2 rows)" in out and "h_central [m]" in out and "no_solution" not in out
    assert main(["runs", str(store), "--csv", "-", "--columns", "load.gap,status"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "load.gap,status" and len(lines) == 7
    assert main(["runs", str(store), "--csv", str(tmp_path / "all.csv"), "-q"]) == 0
    head = (tmp_path / "all.csv").read_text().splitlines()[0].split(",")
    assert {"hash", "status", "load.gap", "h_central", "result_path"} <= set(head)
    # invalid input: exit 2 with one line naming the problem
    bad = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                 "axes": {"load.gap": [-1.0]}})
    assert main(["sweep", str(bad), "--workers", "1"]) == 2
    err = capsys.readouterr().err
    assert "invalid input" in err and "load.gap = -1.0" in err and " m, got -1.0" in err
    assert main(["runs", str(tmp_path / "none.sqlite")]) == 2


def test_unguarded_script_stops_with_the_reason(tmp_path):
    """A script calling bf.sweep() at its top level: each worker process imports it again
    (forkserver/spawn). The sweep stops after two broken pools with the cause and the
    remedy, instead of restarting the pool for every case; the cases stay pending."""
    path = write_sweep(tmp_path)
    script = tmp_path / "run_it.py"
    script.write_text("import bearing_fem as bf\n"
                      f"bf.sweep({str(path)!r}, store={str(tmp_path / 's.sqlite')!r}, "
                      "workers=2)\n", encoding="utf-8")
    proc = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                          timeout=300, cwd=tmp_path)
    assert proc.returncode == 1
    last = proc.stderr.strip().splitlines()
    assert any("died 2 times before finishing any case" in ln and
               'if __name__ == "__main__":' in ln for ln in last), proc.stderr[-2000:]
    assert proc.stderr.count("Traceback") <= 1, "the client's own; a worker prints one line"
    assert "bearing_fem.sweep() was called while a worker process imported" in proc.stderr
    with RunStore(tmp_path / "s.sqlite") as store:
        assert {r["status"] for r in store.rows()} == {"pending"}, "resumable"


def test_cli_runs_options(tmp_path, capsys):
    path = write_sweep(tmp_path)
    store = tmp_path / "o.sqlite"
    assert main(["sweep", str(path), "--store", str(store), "--workers", "1", "-q"]) == 3
    capsys.readouterr()
    assert main(["runs", str(store), "--status", "bogus"]) == 0
    out, err = capsys.readouterr()
    assert "(0 rows)" in out and "no row with status 'bogus'; statuses in this store: " \
        "linear, no_solution" in err, err
    assert main(["runs", str(store), "--status", "unfinished"]) == 0
    err = capsys.readouterr().err
    assert "no row in the group 'unfinished'; statuses in this store" in err, err
    assert main(["runs", str(store), "--status", "lineer", "--where", "load.gap>1"]) == 0
    err = capsys.readouterr().err
    assert "no row with status 'lineer' ('lineer': did you mean 'linear'?)" in err, err
    assert main(["runs", str(store), "--limit", "-1"]) == 2
    assert "limit must be a positive whole number of rows, got -1" in capsys.readouterr().err


def test_cli_retry_failed_and_quiet(tmp_path, capsys):
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml", "store": "q.sqlite"},
                                  "axes": {"load.gap": [1e-7, 1e-6]}})
    assert main(["sweep", str(path), "--workers", "1", "-q"]) == 3
    out, err = capsys.readouterr()
    assert out == "" and "1 case(s) unsuccessful" in err
    assert (tmp_path / "q.sqlite").is_file(), "[sweep] store is relative to the sweep file"
    assert main(["sweep", str(path), "--workers", "1", "--retry-failed"]) == 3
    assert "1 solved now" in capsys.readouterr().out


def test_concurrent_sweeps_on_one_store(tmp_path):
    """Two sweep commands with overlapping cases write one store at the same time."""
    a = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                               "axes": {"load.gap": {"linspace": [3e-7, 3e-6, 8]}}})
    b = tmp_path / "b.toml"
    b.write_text(tomli_w.dumps({"sweep": {"scene": "base.toml"},
                                "axes": {"load.gap": {"linspace": [3e-7, 3e-6, 8]},
                                         "kinematics.u1": [1.0, 3.0]}}), encoding="utf-8")
    store = tmp_path / "shared.sqlite"
    procs = [subprocess.Popen([sys.executable, "-m", "bearing_fem", "sweep", str(p), "--store",
                               str(store), "--workers", "1", "-q"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for p in (a, b)]
    results = [p.communicate(timeout=300) for p in procs]
    assert [p.returncode for p in procs] == [0, 0], results
    with RunStore(store) as s:
        assert s.conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        rows = s.rows()
    assert len(rows) == 16, "8 shared cases (u1 = 1) and 8 of the second sweep's own"
    assert all(r["status"] == "linear" and r["success"] == 1 for r in rows)
    successes_have_files(store)


def test_sweep_of_cases_from_python(tmp_path):
    scenes = {g: Scene.from_dict({**BASE, "load": {"gap": g}}) for g in (3e-7, 1e-6)}
    seen = []
    report = bf.sweep([({"label": f"g{g:g}"}, s) for g, s in scenes.items()],
                      store=tmp_path / "py.sqlite", workers=1, files="summary",
                      on_outcome=lambda c, out: seen.append(out["status"]))
    assert report.successes == 2 and seen == ["linear", "linear"]
    rows, cols = query_runs(tmp_path / "py.sqlite", columns="all")
    assert sorted(r["label"] for r in rows) == ["g1e-06", "g3e-07"]
    folder = tmp_path / rows[0]["result_path"]
    assert sorted(p.name for p in folder.iterdir()) == ["run.json", "summary.json"]
    with pytest.raises(SceneError, match="needs a run store"):
        bf.sweep([({"x": 1}, scenes[1e-6])])
    with pytest.raises(SceneError, match="resolve to the same scene"):
        bf.sweep([({"x": 1}, scenes[1e-6]), ({"x": 2}, scenes[1e-6])], store=tmp_path / "d")
    with pytest.raises(SceneError, match="workers must be an integer"):
        bf.sweep([({"x": 1}, scenes[1e-6])], store=tmp_path / "w.sqlite", workers=0)
    import bearing_fem.sweep as module

    assert callable(module) and callable(bf.sweep), "bf.sweep(...) works as module or function"


# ---------------------------------------------------------------------------------------
# progress
# ---------------------------------------------------------------------------------------
def test_solve_progress_from_synthetic_events():
    buf = io.StringIO()
    bar = SolveProgress(enabled=True, file=buf, desc="ball")
    bar({"event": "level", "level": 0, "levels": 2, "grid": "129x129"})
    for k, r in enumerate([1e-2, 1e-5], start=1):
        bar({"event": "newton", "level": 0, "iteration": k, "residual": r})
    bar({"event": "level", "level": 1, "levels": 2, "grid": "257x257"})
    bar({"event": "newton", "level": 1, "iteration": 1, "residual": 3.25e-9})
    bar({"event": "something else"})
    bar.close()
    text = buf.getvalue()
    assert "ball: grid 129x129 (level 1/2)" in text and "grid 257x257 (level 2/2)" in text
    assert "Newton 2, residual 1.00e-05" in text and "Newton 1, residual 3.25e-09" in text, text
    assert (bar.levels_started, bar.iterations, bar.last_residual) == (2, 3, 3.25e-9)
    quiet = io.StringIO()
    silent = SolveProgress(file=quiet)  # a StringIO is not a terminal: nothing drawn
    silent({"event": "level", "level": 0, "levels": 1, "grid": "65x65"})
    silent({"event": "newton", "level": 0, "iteration": 1, "residual": 0.1})
    silent.close()
    assert quiet.getvalue() == "" and silent.iterations == 1
    assert solve_progress(file=io.StringIO()) is None, "not a terminal"
    assert solve_progress(quiet=True) is None


def test_solve_progress_on_a_real_solve():
    scene = Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                             "materials": {"reduced_modulus": 2.2e11},
                             "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
                             "kinematics": {"u1": 0.1834, "u2": 0.1834},
                             "load": {"force": 2.84e5}, "mesh": {"nodes": 101}})
    buf = io.StringIO()
    with SolveProgress(enabled=True, file=buf) as bar:
        result = bf.solve(scene, progress=bar)
    assert result.success
    assert bar.levels_started >= 1 and bar.iterations == result.newton_iterations
    assert bar.last_residual < scene.solver.tolerance
    assert "101 nodes" in buf.getvalue()


def test_sweep_progress_counts_failures():
    buf = io.StringIO()
    with SweepProgress(3, enabled=True, file=buf) as bar:
        for ok in (True, False, True):
            bar.update({"success": ok})
    assert (bar.done, bar.failures) == (3, 1)
    assert "3/3" in buf.getvalue() and "failed=1" in buf.getvalue()
    off = io.StringIO()
    SweepProgress(3, file=off).close()
    assert off.getvalue() == ""


# ---------------------------------------------------------------------------------------
# bearing files (needs the bearing package: bearing_fem.bearing.solve)
# ---------------------------------------------------------------------------------------
def test_bearing_file_sweep(tmp_path):
    pytest.importorskip("bearing_fem.bearing.solve")
    from bearing_fem.bearing import load_example

    base = load_example("6209").to_dict()
    base["mesh"] = {"point_nodes": [49, 49]}  # coarse contacts (converge at both loads)
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"operation.radial_load": [2000.0, 4000.0]}},
                       base=base)
    spec = SweepSpec.from_toml(path)
    assert spec.kind == "bearing"
    report = bf.sweep(path, workers=1)
    assert (report.cases, report.successes) == (2, 2), report.statuses
    rows, _ = query_runs(tmp_path / "sweep.sqlite", columns="all")
    assert sorted(r["operation.radial_load"] for r in rows) == [2000.0, 4000.0]
    for r in rows:
        assert r["kind"] == "bearing" and r["status"] == "converged"
        folder = tmp_path / r["result_path"]
        summary = json.loads((folder / "bearing_summary.json").read_text())
        assert summary["radial_load"] == r["operation.radial_load"] == r["radial_load"]
        assert summary["friction_torque"] == r["friction_torque"] > 0
        assert (folder / "elements.csv").is_file()
    light, heavy = sorted(rows, key=lambda r: r["radial_load"])
    assert heavy["friction_torque"] > light["friction_torque"], "more load, more torque"
    assert bf.sweep(path, workers=1).ran == 0, "resume"


def test_solve_quiet_prints_nothing(tmp_path, capsys):
    scene = tmp_path / "scene.toml"
    scene.write_text(tomli_w.dumps({**BASE, "load": {"gap": 1e-6}}), encoding="utf-8")
    assert main(["solve", str(scene), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    assert capsys.readouterr() == ("", "")
    assert (tmp_path / "out" / "summary.json").is_file()


CLIENT_SCRIPT = '''
import os, sys, time
from pathlib import Path
from bearing_fem.scene import Scene
from bearing_fem.sweep import Case, execute
from bearing_fem.sweep.execute import PoolExecutor, Task

def slow(task):
    Path(sys.argv[1], f"{os.getpid()}.pid").write_text("")
    time.sleep(2.0)
    return {"status": "linear"}

if __name__ == "__main__":
    execute.run_task = slow
    scene = Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                             "lubricant": {"viscosity": 0.01}, "load": {"gap": 1e-6},
                             "kinematics": {"u1": 1.0, "u2": 1.0},
                             "model": {"elasticity": "rigid"}})
    tasks = [Task(Case({"i": i}, scene), sys.argv[1]) for i in range(4)]
    PoolExecutor(2).run(tasks, lambda t, out: None)
'''


def _running(pid: int) -> bool:
    """True while process ``pid`` runs (not gone, not a zombie)."""
    try:
        os.kill(pid, 0)
        state = Path(f"/proc/{pid}/stat").read_bytes().rsplit(b")", 1)[1].split()[0]
    except (ProcessLookupError, FileNotFoundError):
        return False
    return state != b"Z"


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads /proc")
def test_pool_workers_exit_when_the_client_is_killed(tmp_path):
    """A client killed with SIGKILL (or by a batch system) cannot shut its pool down; its
    worker processes must not wait for work forever (keeping their memory and the
    client's stdout open, so that a caller reading that pipe never returns). They finish
    the case they run and exit."""
    import signal
    import time

    script = tmp_path / "client.py"
    script.write_text(CLIENT_SCRIPT, encoding="utf-8")
    proc = subprocess.Popen([sys.executable, str(script), str(tmp_path)], cwd=tmp_path,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    t0 = time.monotonic()
    while len(list(tmp_path.glob("*.pid"))) < 2 and time.monotonic() - t0 < 120:
        time.sleep(0.05)
    pids = [int(p.stem) for p in tmp_path.glob("*.pid")]
    assert len(pids) == 2, "both pool workers started a case"
    proc.kill()
    proc.wait(timeout=60)
    t1 = time.monotonic()
    alive = pids
    while alive and time.monotonic() - t1 < 20:
        time.sleep(0.2)
        alive = [p for p in pids if _running(p)]
    for p in alive:  # clean up before failing
        os.kill(p, signal.SIGKILL)
    assert not alive, ("pool workers still running 20 s after their client was killed "
                       "(each case takes 2 s, the check runs every second)")


def test_changed_base_file_rows_are_told_apart(tmp_path, capsys):
    """Editing the base file and running the sweep again adds new rows with the same
    parameter values as the old ones (other scenes, other hashes). A query by parameters
    then silently mixed both; the report now says so and ``runs --sweep`` (``query_runs(
    sweep=...)``) selects the rows of the sweep as its files read now."""
    sweep = {"sweep": {"scene": "base.toml"}, "axes": {"load.gap": [1e-6, 2e-6]}}
    path = write_sweep(tmp_path, sweep)
    store = tmp_path / "sweep.sqlite"
    first = bf.sweep(path, workers=1)
    assert first.others_same_params == 0 and "note:" not in first.text()
    write_sweep(tmp_path, sweep, {**BASE, "lubricant": {"viscosity": 0.1, "piezo": 5e-8}})
    second = bf.sweep(path, workers=1)
    assert second.ran == 2 and second.others_same_params == 2, second
    assert "2 row(s) with the parameters of cases of this sweep" in second.text()
    rows, _ = query_runs(store, where=["load.gap=1e-6"])
    assert len(rows) == 2, "both versions of the base file are in the store"
    rows, _ = query_runs(store, where=["load.gap=1e-6"], sweep=path, columns="all")
    assert len(rows) == 1 and rows[0]["hash"] in second.statuses, rows
    assert json.loads(rows[0]["scene"])["lubricant"]["viscosity"] == 0.1, "the new base"
    assert main(["runs", str(store), "--sweep", str(path), "--columns", "hash"]) == 0
    out = capsys.readouterr().out
    assert "(2 rows)" in out and all(h[:12] in out for h in second.statuses), out


def test_all_files_after_a_summary_only_run(tmp_path):
    """A sweep run with files = "summary" and then with files = "all" (the default)
    skipped every case as already stored, so the result.h5 and fields.vtu asked for were
    never written. Folders with the summary alone are solved again when all files are
    asked for, and skipped when the summary is all that is asked for."""
    sweep = {"sweep": {"scene": "base.toml", "files": "summary"},
             "axes": {"load.gap": [1e-6, 2e-6]}}
    path = write_sweep(tmp_path, sweep)
    assert bf.sweep(path, workers=1).ran == 2
    runs = tmp_path / "sweep_runs"
    assert not list(runs.glob("*/result.h5")), "summary alone"
    again = bf.sweep(path, workers=1)
    assert again.ran == 0 and again.skipped == 2, "files = summary: nothing missing"
    full = bf.sweep(path, workers=1, files="all")
    assert full.ran == 2 and full.all_successful, full.text()
    assert len(list(runs.glob("*/result.h5"))) == 2 and len(list(runs.glob("*/fields.vtu"))) == 2
    assert bf.sweep(path, workers=1, files="all").ran == 0, "now complete"
    successes_have_files(tmp_path / "sweep.sqlite")


def test_dry_run_counts_the_folders_it_would_record(tmp_path):
    """After a client died with finished result folders not yet recorded, a dry run said
    "2 cases: 1 to run, 0 already in ..." (the numbers did not add up to the cases); it
    names the folders the run would record."""
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.gap": [1e-6, 2e-6]}})
    bf.sweep(path, workers=1)
    store = tmp_path / "sweep.sqlite"
    for suffix in ("", "-wal", "-shm"):  # the client's store is gone; the folders stay
        Path(f"{store}{suffix}").unlink(missing_ok=True)
    shutil.rmtree(next((tmp_path / "sweep_runs").iterdir()))
    for make_store in (False, True):  # without a store, and with an empty one
        if make_store:
            with RunStore(store):
                pass
        report = bf.sweep(path, workers=1, dry_run=True)
        assert (len(report.to_run), report.adopted, report.skipped) == (1, 1, 0), report
        assert report.text().startswith("2 cases: 1 to run, 1 to record from earlier "
                                        "result folders, 0 already in"), report.text()
    assert bf.sweep(path, workers=1).adopted == 1, "as the dry run said"


def test_temporary_folders_of_killed_workers_are_removed(tmp_path):
    """A worker killed while writing a case's files left its hidden temporary folder
    (with every file written so far) in the results folder for good. The next run
    removes those whose process on this host is gone, or that are older than a day;
    those of running writers and of other hosts stay."""
    import socket
    import time

    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.gap": [1e-6]}})
    runs = tmp_path / "sweep_runs"
    runs.mkdir()
    gone = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True).stdout.strip()
    host, h = socket.gethostname(), "ab" * 32
    names = {"dead": f".{h}.tmp-{gone}-0123abcd-{host}",
             "running": f".{h}.tmp-{os.getpid()}-0123abcd-{host}",
             "other_host": f".{h}.tmp-{gone}-0123abcd-elsewhere.example",
             "old_other_host": f".{h}.old-{gone}-89abcdef-elsewhere.example",
             "unnamed_host": f".{h}.tmp-{gone}-01234567",
             "not_ours": ".keep-me"}
    for name in names.values():
        (runs / name).mkdir()
        (runs / name / "fields.vtu").write_text("partial")
    day_ago = time.time() - 2 * 24 * 3600
    os.utime(runs / names["old_other_host"], (day_ago, day_ago))
    report = bf.sweep(path, workers=1)
    assert report.ran == 1 and report.all_successful
    left = {p.name for p in runs.iterdir() if p.name.startswith(".")}
    assert left == {names[k] for k in ("running", "other_host", "unnamed_host", "not_ours")}
    assert not list(runs.glob(".*.tmp-*-*-*/run.json")), "the case's own folder is in place"

"""A 12-case sweep on a Dask LocalCluster of 2 worker processes: the store, resume, and
workers killed while they run a case."""
from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

distributed = pytest.importorskip("distributed")
import cloudpickle  # noqa: E402  (a dependency of distributed)
import dask  # noqa: E402
from distributed.diagnostics.plugin import WorkerPlugin  # noqa: E402

import bearing_fem as bf  # noqa: E402
from bearing_fem.errors import SceneError  # noqa: E402
from bearing_fem.sweep import RunStore, SweepSpec, local_cluster, query_runs  # noqa: E402
from bearing_fem.sweep.execute import (WORKER_MALLOC_ENV, malloc_environment,  # noqa: E402
                                       slow_malloc_workers)

from test_sweep_run import successes_have_files, write_sweep  # noqa: E402

#: The rigid cylinder of test_sweep_run (one linear solve per case, milliseconds): at the
#: gap 1e-7 m the pressure does not exist (status no_solution), at 3e-7 and 1e-6 m it does
#: (status linear) at these speeds.
SWEEP = {"sweep": {"scene": "base.toml"},
         "axes": {"load.gap": [1e-7, 3e-7, 1e-6], "kinematics.u1": [0.75, 1.0, 1.5, 2.0]},
         "zip": {"kinematics.u2": "kinematics.u1"}}


class KillOnStart(WorkerPlugin):
    """Kills the worker process (``os._exit``) when the case whose hash starts with
    ``prefix`` starts executing on it, ``times`` times in all (counted in a file, which
    outlives the workers)."""

    name = "bearing-fem-test-killer"

    def __init__(self, case_hash: str, counter: str, times: int) -> None:
        self.prefix = f"bearing_fem-{case_hash[:16]}"  # DaskExecutor's task keys
        self.counter, self.times = counter, times

    def transition(self, key, start, finish, **kwargs):
        if finish == "executing" and str(key).startswith(self.prefix):
            path = Path(self.counter)
            n = int(path.read_text()) if path.exists() else 0
            if n < self.times:
                path.write_text(str(n + 1))
                os._exit(1)


@pytest.fixture(scope="module")
def client():
    """One LocalCluster for the module: 2 worker processes of 1 thread. A task whose
    worker dies is rescheduled once; the second death makes it KilledWorker. One task
    per worker at a time, so a dying worker takes no other case with it."""
    cloudpickle.register_pickle_by_value(sys.modules[__name__])  # the plugin travels
    with dask.config.set({"distributed.scheduler.allowed-failures": 1,
                          "distributed.scheduler.worker-saturation": 1.0}):
        cluster = local_cluster(2)
        c = distributed.Client(cluster, set_as_default=False)
    try:
        yield c
    finally:
        c.close()
        cluster.close()


def test_local_cluster_workers_run_with_the_malloc_settings(client):
    envs = client.run(malloc_environment)
    assert len(envs) == 2
    for worker, env in envs.items():
        assert env == WORKER_MALLOC_ENV, (worker, env)
    assert slow_malloc_workers(envs) == []
    dask_default = {"w1": {"MALLOC_TRIM_THRESHOLD_": "65536", "MALLOC_MMAP_THRESHOLD_": None},
                    "w2": dict(WORKER_MALLOC_ENV)}
    assert slow_malloc_workers(dask_default) == ["w1"], "Dask's default is flagged"


def make_sweep(tmp_path: Path) -> Path:
    return write_sweep(tmp_path, SWEEP)


def test_twelve_cases_on_two_dask_workers(tmp_path, client):
    path = make_sweep(tmp_path)
    cases = SweepSpec.from_toml(path).cases()
    assert len(cases) == 12
    victim = next(c for c in cases if c.params["load.gap"] == 1e-6)
    counter = tmp_path / "kills"
    client.register_plugin(KillOnStart(victim.hash, str(counter), times=1))
    store = tmp_path / "sweep.sqlite"
    finals_seen = []

    def after_each(case, outcome):  # the client records each case as it arrives
        with RunStore(store) as reader:
            finals_seen.append(sum(n for s, n in reader.count().items() if s != "pending"))

    try:
        report = bf.sweep(path, scheduler=client, on_outcome=after_each)
    finally:
        client.unregister_worker_plugin(KillOnStart.name)
    assert counter.read_text() == "1", "the worker running the victim case was killed once"
    assert report.executor.startswith("Dask cluster at tcp://")
    assert (report.cases, report.ran, report.skipped) == (12, 12, 0)
    assert (report.successes, report.failures, report.unfinished) == (8, 4, 0)
    assert finals_seen == list(range(1, 13)), "one final row per finished case, in turn"
    rows, _ = query_runs(store, columns="all")
    assert len(rows) == 12
    for r in rows:
        expected = "no_solution" if r["load.gap"] == 1e-7 else "linear"
        assert r["status"] == expected and r["success"] == (expected == "linear"), r
        assert r["kinematics.u2"] == r["kinematics.u1"]
    (v,) = [r for r in rows if r["hash"] == victim.hash]
    assert v["status"] == "linear" and v["h_central"] == pytest.approx(1e-6, rel=1e-12), (
        "the killed case was run again on the other worker and solved (rigid: h(0) = gap)")
    assert len({r["worker"] for r in rows}) >= 2, "both workers (and the restarted one) ran"
    successes_have_files(store)

    again = bf.sweep(path, scheduler=client)
    assert (again.ran, again.skipped, again.adopted) == (0, 12, 0), "resume solves nothing"
    assert again.statuses == report.statuses


def test_case_that_kills_every_worker_is_lost_then_rerun(tmp_path, client):
    path = make_sweep(tmp_path)
    cases = SweepSpec.from_toml(path).cases()
    victim = next(c for c in cases if c.params["load.gap"] == 3e-7)
    counter = tmp_path / "kills"
    store = tmp_path / "sweep.sqlite"
    # the victim alone first: a dying worker then takes no other case with it (the
    # scheduler counts every task it had in flight as a suspect)
    client.register_plugin(KillOnStart(victim.hash, str(counter), times=100))
    try:
        report = bf.sweep([victim], store=store, scheduler=client)
    finally:
        client.unregister_worker_plugin(KillOnStart.name)
    assert counter.read_text() == "2", "allowed-failures = 1: two deaths, then KilledWorker"
    assert (report.successes, report.failures, report.unfinished) == (0, 0, 1)
    (lost,) = query_runs(store, columns="all")[0]
    assert lost["hash"] == victim.hash and lost["status"] == "lost"
    assert lost["success"] == 0 and lost["result_path"] is None
    assert "KilledWorker" in lost["message"]
    assert lost["load.gap"] == 3e-7, "the parameters are stored with the lost case"

    rerun = bf.sweep(path, store=store, scheduler=client)  # the workers are healthy again
    assert (rerun.ran, rerun.skipped) == (12, 0), "the lost case runs again with the rest"
    assert (rerun.successes, rerun.failures, rerun.unfinished) == (8, 4, 0)
    assert rerun.statuses[victim.hash] == "linear"
    successes_have_files(store)


def flaky_run_task(task):
    """run_task that fails on a task's first attempt for one case (the sweep client must
    submit it again), as when a result is lost with its worker before it is gathered."""
    from bearing_fem.sweep import execute

    if task.attempts == 1 and task.case.params["load.gap"] == 3e-7 and \
            task.case.params["kinematics.u1"] == 1.0:
        raise RuntimeError("result lost with its worker (test)")
    return execute.run_task(task)


def test_task_failing_on_the_cluster_is_submitted_again(tmp_path, client, monkeypatch):
    from bearing_fem.sweep import execute

    monkeypatch.setattr(execute, "run_task", flaky_run_task)
    report = bf.sweep(make_sweep(tmp_path), scheduler=client)
    assert (report.successes, report.failures, report.unfinished) == (8, 4, 0), (
        "the failed first attempt was submitted again and solved")
    rows, _ = query_runs(tmp_path / "sweep.sqlite", columns="all")
    (again,) = [r for r in rows if r["load.gap"] == 3e-7 and r["kinematics.u1"] == 1.0]
    assert again["status"] == "linear" and again["attempts"] == 2, again


def test_unreachable_scheduler_is_an_input_error(tmp_path):
    from bearing_fem.errors import SceneError
    from bearing_fem.sweep.execute import DaskExecutor

    with pytest.raises(SceneError, match="cannot reach the Dask scheduler at "
                                         "'tcp://127.0.0.1:1'"):
        DaskExecutor("tcp://127.0.0.1:1", timeout=1).open()


def test_unreachable_scheduler_leaves_no_store(tmp_path, monkeypatch):
    """An input error writes nothing: the run store the sweep would have created is
    removed again (it was left empty)."""
    from bearing_fem.errors import SceneError
    from bearing_fem.sweep import execute

    init = execute.DaskExecutor.__init__
    monkeypatch.setattr(execute.DaskExecutor, "__init__",
                        lambda self, scheduler, timeout=1.0: init(self, scheduler, timeout))
    scene = bf.Scene.from_dict({"contact": {"kind": "line", "rx": 0.01},
                                "lubricant": {"viscosity": 0.05},
                                "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": 1e-6},
                                "model": {"elasticity": "rigid"}})
    store = tmp_path / "never.sqlite"
    with pytest.raises(SceneError, match="cannot reach the Dask scheduler"):
        bf.sweep([({"load.gap": 1e-6}, scene)], store=store, scheduler="tcp://127.0.0.1:1")
    assert not store.exists() and not list(tmp_path.iterdir()), list(tmp_path.iterdir())


@pytest.mark.parametrize("bad", [2.5, 0, "2", True])
def test_local_cluster_refuses_a_bad_worker_count(bad):
    """local_cluster(2.5) started 2 workers without a word and local_cluster("a") raised a
    bare ValueError; every count that is not a whole number >= 1 is a SceneError naming
    the argument and the value, before any process starts."""
    with pytest.raises(SceneError, match=r"n_workers must be an integer in \[1, 4096\] "
                                         r"\(worker processes\), got "):
        local_cluster(bad)


@pytest.mark.parametrize("address", ["foo bar", "localhost", "foo://x", "tcp://h:abc"])
def test_malformed_scheduler_address_is_an_input_error(tmp_path, capsys, address):
    """``--scheduler "foo bar"`` made distributed.Client raise a bare ValueError, whose
    cleanup then waited 60 s and ended in a TimeoutError traceback (exit 1), leaving an
    empty store behind. A malformed address is refused at once (exit 2, one line naming
    the value), and nothing is written."""
    import time

    from bearing_fem.cli import main

    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.gap": [1e-6]}})
    t0 = time.monotonic()
    assert main(["sweep", str(path), "--scheduler", address]) == 2
    assert time.monotonic() - t0 < 20, "refused before any connection attempt"
    err = capsys.readouterr().err
    assert f"scheduler must be a Dask scheduler address such as tcp://10.0.0.5:8786, " \
           f"got {address!r}" in err, err
    assert not (tmp_path / "sweep.sqlite").exists(), "an input error writes nothing"

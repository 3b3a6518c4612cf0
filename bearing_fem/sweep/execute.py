"""Running the cases of a sweep: the worker function, the executors and the client loop.

Workers solve a case and write its result files into ``<results>/<hash>/`` (first into a
temporary folder, renamed into place when complete); the client alone writes the run
store, one transaction per finished case, as soon as it is reported. So a worker that
fails or is killed loses only the case it was running, which stays ``pending`` or
becomes ``lost`` and runs again on the next run of the sweep; a row never claims success
unless the client has seen the result folder. A client that is killed leaves its
finished result folders behind; the next run adopts them (their ``run.json`` names the
case's hash) instead of solving them again.

Executors
    :class:`SerialExecutor` (``workers = 1``: in the calling process),
    :class:`PoolExecutor` (default: a local process pool with one process per core, BLAS
    limited to one thread per process) and :class:`DaskExecutor` (a Dask distributed
    cluster: a scheduler address, a ``distributed.Client`` or a cluster object such as
    ``LocalCluster``). The result folder must be on a filesystem that the workers and
    the client share.
"""
from __future__ import annotations

import json
import logging
import os
import re
import secrets
import shutil
import socket
import threading
import time
import traceback
import warnings
from collections import deque
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

from ..errors import SceneError
from .spec import Case
from .store import ERROR_STATUS, NON_FINAL, RunStore

log = logging.getLogger(__name__)

#: Times a case may be in flight on a worker that dies before it is recorded ``lost``.
MAX_ATTEMPTS = 3
#: Marker file written into every result folder (hash, kind, params, status).
RUN_FILE = "run.json"
#: The summary file of a result folder, per kind.
SUMMARY_FILE = {"scene": "summary.json", "bearing": "bearing_summary.json"}

#: glibc malloc settings for Dask worker processes. Dask's nanny starts its workers with
#: ``MALLOC_TRIM_THRESHOLD_=65536`` (``distributed.nanny.pre-spawn-environ``); setting it
#: switches off glibc's adaptive mmap threshold, so every array above 128 KiB is mapped
#: and unmapped anew and a point solve spends most of its time in page faults: a 257^2
#: circular solve took 5.0 s (3.1 s of it system time) in such a worker against 1.8 s in
#: a plain process. With a 32 MiB mmap threshold (glibc's adaptive maximum) and a 64 MiB
#: trim threshold the worker is as fast as a plain process (1.7 s; the malloc table of
#: ``studies/sweep_benchmark.py``).
#: :func:`local_cluster` starts its workers with these; a worker started by
#: ``dask worker`` needs them in its environment (docs/sweeps.md).
WORKER_MALLOC_ENV = {"MALLOC_MMAP_THRESHOLD_": "33554432",
                     "MALLOC_TRIM_THRESHOLD_": "67108864"}

Outcome = dict[str, Any]
Done = Callable[["Task", Outcome], None]


def local_cluster(n_workers: int = 2, **kwargs: Any) -> Any:
    """A Dask ``LocalCluster`` of ``n_workers`` processes of one thread each, whose workers
    run with :data:`WORKER_MALLOC_ENV` (as fast per solve as a plain process).

    Parameters
    ----------
    n_workers : int
        Worker processes (one per core is the useful maximum: a solve uses one core).
    **kwargs
        Further ``distributed.LocalCluster`` arguments (``threads_per_worker``,
        ``dashboard_address`` = None by default, ...).

    Returns
    -------
    distributed.LocalCluster
        Pass it as ``scheduler=`` to :func:`bearing_fem.sweep.sweep`; close it when done.

    Notes
    -----
    The settings are put into this process's ``os.environ``, which the workers inherit;
    Dask's own ``distributed.nanny.pre-spawn-environ`` default for
    ``MALLOC_TRIM_THRESHOLD_`` yields to a variable already set there (Dask's rule).
    """
    try:
        from distributed import LocalCluster
    except ImportError:
        raise SceneError("a local Dask cluster needs dask.distributed: "
                         "pip install 'bearing_fem[sweep]'") from None
    from .spec import check_workers

    n = check_workers(n_workers, "local_cluster: n_workers")
    kwargs.setdefault("threads_per_worker", 1)
    kwargs.setdefault("dashboard_address", None)
    os.environ.update(WORKER_MALLOC_ENV)
    return LocalCluster(n_workers=n, processes=True, **kwargs)


def malloc_environment() -> dict[str, str | None]:
    """The malloc variables of :data:`WORKER_MALLOC_ENV` in the environment of the process
    this runs in (:class:`DaskExecutor` runs it on each worker).

    Returns
    -------
    dict
        Variable name -> its value, None where unset.
    """
    return {k: os.environ.get(k) for k in WORKER_MALLOC_ENV}


def slow_malloc_workers(environments: Mapping[str, Mapping[str, str | None]]) -> list[str]:
    """Workers whose environment sets a malloc trim threshold without an mmap threshold
    (Dask's default: ~3x slower point solves, :data:`WORKER_MALLOC_ENV`).

    Parameters
    ----------
    environments : mapping
        Worker address -> :func:`malloc_environment` of that worker.

    Returns
    -------
    list of str
        The addresses of the slow workers, sorted.
    """
    return sorted(w for w, env in environments.items()
                  if env.get("MALLOC_TRIM_THRESHOLD_") is not None
                  and env.get("MALLOC_MMAP_THRESHOLD_") is None)


@dataclass(frozen=True)
class Task:
    """What a worker needs to run one case.

    Attributes
    ----------
    case : Case
    run_dir : str
        Absolute path of the case's result folder (``<results>/<hash>``).
    files : {"all", "summary"}
    blas_threads : int or None
        Limit of BLAS/OpenMP threads inside the worker (None: as configured).
    attempts : int
        How many times the case has been started (this one included).
    """

    case: Case
    run_dir: str
    files: str = "all"
    blas_threads: int | None = None
    attempts: int = 1


def worker_name() -> str:
    """``host:pid`` of the running process."""
    return f"{socket.gethostname()}:{os.getpid()}"


# ---------------------------------------------------------------------------------------
# worker side
# ---------------------------------------------------------------------------------------
def _solve(case: Case) -> tuple[Any, Callable[[Any, Path], Any]]:
    """Solve a case; return the result and the function that exports it."""
    if case.kind == "bearing":
        from ..bearing import solve_bearing  # type: ignore[attr-defined]
        from ..io import export_bearing  # type: ignore[attr-defined]

        return solve_bearing(case.scene), export_bearing
    if getattr(case.scene, "transient", None) is not None:
        from ..contacts.dispatch import solve_series
        from ..io import export_series

        return solve_series(case.scene), export_series
    from ..contacts.dispatch import solve
    from ..io import export

    return solve(case.scene), export


def _limits(threads: int | None):
    """Context limiting BLAS/OpenMP threads (threadpoolctl), or a no-op."""
    import contextlib

    if not threads:
        return contextlib.nullcontext()
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - threadpoolctl is a dependency
        return contextlib.nullcontext()
    return threadpool_limits(limits=threads)


def run_task(task: Task) -> Outcome:
    """Solve one case and write its result folder (the function the workers run).

    Never raises for a failed solve: a solve that raises gives status ``error``
    (final), a failure to write the files status ``lost`` (not final), each with the
    exception in the message.

    Parameters
    ----------
    task : Task
        The case, its result folder, the files to write and the BLAS thread limit.

    Returns
    -------
    dict
        ``status``, ``success``, ``message``, ``summary`` (the result's summary or None),
        ``result_path`` (the folder, or None), ``run_time_s`` [s], ``worker``,
        ``attempts``.
    """
    t0 = time.perf_counter()
    case = task.case
    base = {"hash": case.hash, "worker": worker_name(), "attempts": task.attempts}
    try:
        with _limits(task.blas_threads):
            result, exporter = _solve(case)
        summary = result.summary()
    except Exception as exc:  # a bug or an input the solver refuses: recorded, not raised
        log.debug("case %s raised:\n%s", case.hash[:12], traceback.format_exc())
        return {**base, "status": ERROR_STATUS, "success": False, "summary": None,
                "message": f"the solve raised {type(exc).__name__}: {exc}",
                "result_path": None, "run_time_s": time.perf_counter() - t0}
    try:
        path = publish(result, exporter, case, Path(task.run_dir), task.files,
                       summary, time.perf_counter() - t0)
    except Exception as exc:
        return {**base, "status": "lost", "success": False, "summary": None,
                "message": f"writing the result files into {task.run_dir!r} failed: "
                           f"{type(exc).__name__}: {exc}",
                "result_path": None, "run_time_s": time.perf_counter() - t0}
    return {**base, "status": str(result.status), "success": bool(result.success),
            "message": str(result.message), "summary": summary, "result_path": str(path),
            "run_time_s": time.perf_counter() - t0}


def publish(result: Any, exporter: Callable[[Any, Path], Any], case: Case, run_dir: Path,
            files: str, summary: Mapping[str, Any], run_time_s: float) -> Path:
    """Write the result folder of a case atomically.

    The files are written into a temporary sibling folder, which is renamed to
    ``run_dir`` once complete (an older folder of the same case is moved aside first and
    removed after). ``files = "summary"`` writes the summary file alone.
    """
    run_dir.parent.mkdir(parents=True, exist_ok=True)
    token = f"{os.getpid()}-{secrets.token_hex(4)}-{socket.gethostname()}"
    tmp = run_dir.with_name(f".{run_dir.name}.tmp-{token}")
    try:
        tmp.mkdir()
        if files == "summary":
            text = json.dumps(summary, indent=2, allow_nan=False, default=str)
            (tmp / SUMMARY_FILE[case.kind]).write_text(text + "\n", encoding="utf-8")
        else:
            exporter(result, tmp)
        marker = {"hash": case.hash, "kind": case.kind, "params": case.params,
                  "files": files, "status": str(result.status),
                  "success": bool(result.success),
                  "run_time_s": run_time_s, "worker": worker_name()}
        (tmp / RUN_FILE).write_text(json.dumps(marker, indent=1, default=str) + "\n",
                                    encoding="utf-8")
        if _same_outcome(run_dir, marker):
            # another process sharing the store ran this case at the same time and has
            # published the same outcome: keep its folder (replacing it would leave a
            # moment without one, which that process would record as lost)
            shutil.rmtree(tmp, ignore_errors=True)
            return run_dir
        old = None
        if run_dir.exists():
            old = run_dir.with_name(f".{run_dir.name}.old-{token}")
            os.replace(run_dir, old)
        try:
            os.replace(tmp, run_dir)
        except OSError:
            if not _same_outcome(run_dir, marker):  # published meanwhile by another process
                raise
            shutil.rmtree(tmp, ignore_errors=True)
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return run_dir


#: Hidden folder of an unfinished :func:`publish`: ``.<hash>.tmp-<pid>-<8 hex>[-<host>]``
#: (``old`` for a folder moved aside).
_TEMP_RUN_DIR = re.compile(r"^\.[0-9a-f]{64}\.(?:tmp|old)-(?P<pid>\d+)-[0-9a-f]{8}"
                           r"(?:-(?P<host>.+))?$")
#: Age [s] after which such a folder counts as stale whatever wrote it.
STALE_RUN_DIR_AGE = 24 * 3600.0


def clean_stale_run_dirs(results: Path, max_age: float = STALE_RUN_DIR_AGE) -> list[Path]:
    """Remove the hidden temporary folders that killed workers left in ``results``.

    A worker (or a serial client) killed while it wrote a case's files leaves its
    temporary folder ``.<hash>.tmp-<pid>-<random>-<host>`` behind, with every file
    written so far (a point result's ``fields.vtu`` is tens of MB). Such a folder is
    removed when its process, on this host, no longer runs, or when it is older than
    ``max_age`` (a folder of another host, or one named without its host). Folders of
    running writers, result folders and every other file are left alone.

    Parameters
    ----------
    results : Path
        The sweep's results folder (nothing happens if it does not exist).
    max_age : float
        Age [s] beyond which a temporary folder counts as stale whatever wrote it.

    Returns
    -------
    list of Path
        The removed folders.
    """
    removed: list[Path] = []
    try:
        entries = [p for p in Path(results).iterdir() if p.name.startswith(".")]
    except OSError:
        return removed
    host, now = socket.gethostname(), time.time()
    for path in entries:
        m = _TEMP_RUN_DIR.match(path.name)
        if m is None or path.is_symlink() or not path.is_dir():
            continue
        try:
            age = now - path.stat().st_mtime
        except OSError:
            continue
        dead = m.group("host") == host and not _process_alive(int(m.group("pid")))
        if dead or age > max_age:
            shutil.rmtree(path, ignore_errors=True)
            removed.append(path)
    if removed:
        log.info("removed %d temporary folder(s) of killed workers in %s", len(removed),
                 results)
    return removed


def _same_outcome(run_dir: Path, marker: Mapping[str, Any]) -> bool:
    """True when ``run_dir`` is a complete result folder of the same case with the same
    successful status (as a concurrent run of that case writes it; an unsuccessful folder
    is always replaced, as a retry should)."""
    if not marker["success"] or not result_complete(run_dir, str(marker["kind"])):
        return False
    if marker.get("files") == "all" and not has_all_files(run_dir, str(marker["kind"])):
        return False  # a summary-only folder is replaced by the whole export
    try:
        theirs = json.loads((run_dir / RUN_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return all(theirs.get(k) == marker[k] for k in ("hash", "status", "success"))


def result_complete(path: Path | None, kind: str) -> bool:
    """True when ``path`` is a complete result folder (its marker and summary exist)."""
    return (path is not None and (path / RUN_FILE).is_file()
            and (path / SUMMARY_FILE.get(kind, "summary.json")).is_file())


def has_all_files(path: Path | None, kind: str) -> bool:
    """True when a complete result folder holds the export of the result, not its summary
    file alone (as ``files = "summary"`` writes it).

    Parameters
    ----------
    path : Path or None
        A result folder.
    kind : {"scene", "bearing"}

    Returns
    -------
    bool
    """
    if not result_complete(path, kind):
        return False
    alone = {RUN_FILE, SUMMARY_FILE.get(kind, "summary.json")}
    return any(p.name not in alone for p in path.iterdir())  # type: ignore[union-attr]


def adopt(case: Case, run_dir: Path) -> Outcome | None:
    """The outcome stored in a complete result folder of ``case`` (written by a worker
    whose client did not record it), or None."""
    if not result_complete(run_dir, case.kind):
        return None
    try:
        marker = json.loads((run_dir / RUN_FILE).read_text(encoding="utf-8"))
        summary = json.loads((run_dir / SUMMARY_FILE[case.kind]).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if marker.get("hash") != case.hash or "status" not in summary:
        return None
    return {"hash": case.hash, "status": str(summary["status"]),
            "success": bool(summary.get("success")), "message": str(summary.get("message", "")),
            "summary": summary, "result_path": str(run_dir),
            "run_time_s": marker.get("run_time_s"), "worker": marker.get("worker"),
            "attempts": 1}


def lost(task: Task, message: str) -> Outcome:
    """Outcome of a case whose worker never reported (status ``lost``, not final)."""
    return {"hash": task.case.hash, "status": "lost", "success": False, "summary": None,
            "message": message, "result_path": None, "run_time_s": None, "worker": None,
            "attempts": task.attempts}


# ---------------------------------------------------------------------------------------
# executors
# ---------------------------------------------------------------------------------------
class SerialExecutor:
    """Run the tasks one after another in the calling process."""

    name = "serial (this process)"

    def open(self) -> None:
        """Nothing to start."""

    def close(self) -> None:
        """Nothing to stop."""

    def run(self, tasks: Sequence[Task], done: Done) -> None:
        for t in tasks:
            done(t, run_task(t))


#: The local pool broke this many times before any case finished: the sweep stops with
#: :data:`_POOL_START_MESSAGE` (the cases stay pending) instead of restarting it again.
POOL_START_FAILURES = 2
_POOL_START_MESSAGE = (
    "the local pool's worker processes died {breaks} times before finishing any case: "
    "they could not start, or ran out of memory. A script that calls bearing_fem.sweep() "
    "must call it under `if __name__ == \"__main__\":` (each worker process imports the "
    "main script); the cases are still pending, and running the sweep again resumes them")


def in_worker_bootstrap() -> bool:
    """True in a worker process of a pool (spawn or forkserver start) while it imports
    the parent's main script: a sweep started there would start a pool of its own."""
    import multiprocessing as mp

    # multiprocessing's own test (spawn._check_not_importing_main): the flag is set while
    # a child process runs its preparation, which imports the main script
    return bool(getattr(mp.current_process(), "_inheriting", False))


#: Seconds between a pool worker's checks that the process which started the pool (the
#: client) still runs; a worker whose client has gone (killed with SIGKILL, or by a batch
#: system's time limit) exits once its current case is done instead of waiting forever.
CLIENT_CHECK_S = 1.0
_running = [0]  # cases running in this pool worker process (0 or 1)


def _process_alive(pid: int) -> bool:
    """True while process ``pid`` exists (a zombie counts as gone on Linux)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # pragma: no cover - a process of another user
        return True
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            return fh.read().rsplit(b")", 1)[1].split()[0] != b"Z"
    except (OSError, IndexError):
        return True


def watch_client(pid: int, interval: float = CLIENT_CHECK_S) -> None:
    """Initializer of the local pool's worker processes: a daemon thread that ends the
    process once the client ``pid`` has gone and no case is running.

    Without it the workers of a client killed by SIGKILL (or SIGTERM) would wait for
    work forever (each holds its own end of the pool's queues), keeping their memory
    and the client's standard output open. A case running when the client goes is
    finished and its result folder written, so that the next run adopts it.

    Parameters
    ----------
    pid : int
        Process id of the client (the process that started the pool).
    interval : float
        Seconds between checks.
    """
    def watch() -> None:
        while True:
            time.sleep(interval)
            if not _running[0] and not _process_alive(pid):
                os._exit(0)

    threading.Thread(target=watch, name="bearing_fem-client-watch", daemon=True).start()


def pool_task(fn: Callable[[Task], Outcome], task: Task) -> Outcome:
    """Run ``fn(task)`` in a pool worker, marked as running for :func:`watch_client`."""
    _running[0] += 1
    try:
        return fn(task)
    finally:
        _running[0] -= 1


class PoolExecutor:
    """A local process pool (``concurrent.futures``; forkserver start where available).

    At most ``workers`` tasks are in flight; a worker process that dies breaks the pool,
    which is started again, and the tasks that were in flight are resubmitted until they
    have been started :data:`MAX_ATTEMPTS` times (then recorded ``lost``). Its workers
    exit on their own once the client process has gone (:func:`watch_client`).
    """

    def __init__(self, workers: int) -> None:
        self.workers = int(workers)
        self.name = f"local pool of {self.workers} processes"

    def open(self) -> None:
        """Nothing to start (the pool starts in :meth:`run`)."""

    def close(self) -> None:
        """Nothing to stop (the pool stops at the end of :meth:`run`)."""

    def _pool(self):
        import multiprocessing as mp
        import sys
        from concurrent.futures import ProcessPoolExecutor

        main_file = getattr(sys.modules.get("__main__"), "__file__", None)
        if main_file is not None and not Path(main_file).is_file() and \
                "fork" in mp.get_all_start_methods():
            # e.g. a script read from standard input: a forkserver or spawned worker
            # would try to import it again from a file that does not exist
            ctx = mp.get_context("fork")
        else:
            try:
                ctx = mp.get_context("forkserver")
                ctx.set_forkserver_preload(["bearing_fem.sweep.execute",
                                            "bearing_fem.contacts.dispatch"])
            except ValueError:  # pragma: no cover - platforms without forkserver
                ctx = mp.get_context("spawn")
        return ProcessPoolExecutor(max_workers=self.workers, mp_context=ctx,
                                   initializer=watch_client, initargs=(os.getpid(),))

    def run(self, tasks: Sequence[Task], done: Done) -> None:
        from concurrent.futures import FIRST_COMPLETED, wait
        from concurrent.futures.process import BrokenProcessPool

        queue = deque(tasks)
        inflight: dict[Any, Task] = {}
        pool = self._pool()
        finished_any, breaks = False, 0
        try:
            while queue or inflight:
                while queue and len(inflight) < self.workers:
                    t = queue.popleft()
                    inflight[pool.submit(pool_task, run_task, t)] = t
                finished, _ = wait(list(inflight), return_when=FIRST_COMPLETED)
                broken = False
                for f in finished:
                    t = inflight.pop(f)
                    try:
                        out = f.result()
                    except BrokenProcessPool:
                        broken = True
                        if t.attempts >= MAX_ATTEMPTS:
                            done(t, lost(t, f"its worker process died {t.attempts} times "
                                            "while running it"))
                        else:
                            queue.appendleft(_again(t))
                        continue
                    except Exception as exc:  # e.g. the task could not be pickled
                        done(t, lost(t, f"the local pool failed to run it: "
                                        f"{type(exc).__name__}: {exc}"))
                        continue
                    done(t, out)
                    finished_any = True
                if broken:
                    breaks += 1
                    if not finished_any and breaks >= POOL_START_FAILURES:
                        raise SceneError(_POOL_START_MESSAGE.format(breaks=breaks))
                    log.warning("a worker process died; restarting the local pool")
                    for f, t in list(inflight.items()):  # they died with the pool
                        inflight.pop(f)
                        if t.attempts >= MAX_ATTEMPTS:
                            done(t, lost(t, f"its worker process died {t.attempts} times "
                                            "while running it"))
                        else:
                            queue.appendleft(_again(t))
                    pool.shutdown(wait=True, cancel_futures=True)
                    pool = self._pool()
        finally:
            pool.shutdown(wait=False, cancel_futures=True)


def _again(t: Task) -> Task:
    return Task(t.case, t.run_dir, t.files, t.blas_threads, t.attempts + 1)


def check_address(address: str) -> str:
    """A Dask scheduler address as given, or SceneError when it cannot be one.

    A malformed address (``"foo bar"``, ``"localhost"`` without a port, an unknown
    scheme) made ``distributed.Client`` raise a bare ValueError and then wait 60 s in its
    cleanup; it is refused at once, naming the value.

    Parameters
    ----------
    address : str
        ``tcp://host:port`` (``host:port`` means tcp), ``tls://host:port``, or another
        scheme Dask knows (``inproc://``, ``ucx://``, ...).

    Returns
    -------
    str
        ``address``.
    """
    from distributed.comm import registry
    from distributed.comm.addressing import parse_address, parse_host_port

    try:
        scheme, location = parse_address(address)
        if scheme not in registry.backends:
            raise ValueError(f"unknown scheme {scheme!r} (known: "
                             f"{', '.join(sorted(registry.backends))})")
        if scheme in ("tcp", "tls"):
            parse_host_port(location)
    except (ValueError, TypeError) as exc:
        raise SceneError(f"scheduler must be a Dask scheduler address such as "
                         f"tcp://10.0.0.5:8786, got {address!r} ({exc})") from None
    return address


class DaskExecutor:
    """Cases on a Dask distributed cluster.

    Parameters
    ----------
    scheduler : str or distributed.Client or cluster
        A scheduler address (``tcp://host:8786``), a connected ``Client`` (left open), or
        a cluster object with a ``scheduler_address`` (``LocalCluster``).
    timeout : float
        Seconds to wait for the scheduler when connecting.

    A worker that dies is handled by the scheduler: it reschedules the task on another
    worker (up to its ``allowed-failures``); a task that kills every worker it runs on
    comes back as ``KilledWorker`` and is recorded ``lost``. A task that fails for any
    other reason (e.g. its result was lost with its worker before the client gathered
    it) is submitted again, up to :data:`MAX_ATTEMPTS` runs in all, then recorded
    ``lost``.
    """

    def __init__(self, scheduler: Any, timeout: float = 30.0) -> None:
        try:
            import distributed  # noqa: F401
        except ImportError:
            raise SceneError("running a sweep on a Dask scheduler needs dask.distributed: "
                             "pip install 'bearing_fem[sweep]'") from None
        self.scheduler = scheduler
        self.timeout = timeout
        self.name = f"Dask cluster at {self.address}"
        self.client = None
        self.own = False

    @property
    def address(self) -> str:
        s = self.scheduler
        if isinstance(s, str):
            return s
        return str(getattr(s, "scheduler_address", None) or getattr(
            getattr(s, "scheduler", None), "address", None) or s)

    def _client(self):
        from distributed import Client

        if isinstance(self.scheduler, Client):
            return self.scheduler, False
        if isinstance(self.scheduler, str):
            check_address(self.scheduler)
        try:
            if isinstance(self.scheduler, str):
                client = Client(self.scheduler, timeout=self.timeout,
                                set_as_default=False)
            else:
                client = Client(self.scheduler, set_as_default=False)
        except (OSError, TimeoutError) as exc:
            raise SceneError(f"cannot reach the Dask scheduler at {self.address!r}: "
                             f"{type(exc).__name__}: {exc}") from None
        return client, True

    def open(self) -> None:
        """Connect to the scheduler (SceneError when it does not answer) and warn if its
        workers run with Dask's default malloc settings (:data:`WORKER_MALLOC_ENV`)."""
        if self.client is None:
            self.client, self.own = self._client()
            try:
                slow = slow_malloc_workers(self.client.run(malloc_environment))
            except Exception as exc:  # noqa: BLE001 - a check, never a reason to fail
                log.debug("could not read the workers' environment: %s", exc)
                slow = []
            if slow:
                warnings.warn(
                    f"{len(slow)} Dask worker(s) run with MALLOC_TRIM_THRESHOLD_ set and no "
                    f"MALLOC_MMAP_THRESHOLD_ (Dask's default): point solves there are "
                    f"about 3x slower. Start the workers with "
                    + " ".join(f"{k}={v}" for k, v in WORKER_MALLOC_ENV.items())
                    + " or use bearing_fem.sweep.local_cluster (docs/sweeps.md)",
                    RuntimeWarning, stacklevel=2)

    def close(self) -> None:
        """Close the connection if this executor opened it (a given Client stays open)."""
        if self.client is not None and self.own:
            self.client.close()
        self.client = None

    def run(self, tasks: Sequence[Task], done: Done) -> None:
        from distributed import as_completed

        self.open()
        client = self.client
        futures: dict[Any, Task] = {}
        token = secrets.token_hex(4)

        def submit(t: Task, priority: int = 0):
            fut = client.submit(run_task, t, pure=False, priority=priority,
                                key=f"bearing_fem-{t.case.hash[:16]}-{token}-{t.attempts}")
            futures[fut] = t
            return fut

        try:
            for i, t in enumerate(tasks):
                submit(t, priority=-i)
            pending = as_completed(list(futures), loop=client.loop)
            for fut in pending:
                t = futures.pop(fut)
                try:  # raises the task's error, or a gathering error (e.g. the result
                    out, exc = fut.result(), None  # was lost with its worker)
                except Exception as err:  # noqa: BLE001
                    out, exc = None, err
                fut.release()
                if out is None:
                    name = type(exc).__name__
                    if name != "KilledWorker" and t.attempts < MAX_ATTEMPTS:
                        log.info("case %s: %s (%s), submitted again", t.case.hash[:12],
                                 name, exc)
                        pending.add(submit(_again(t)))
                        continue
                    out = lost(t, "its worker died each time it ran it (KilledWorker)"
                               if name == "KilledWorker" else
                               f"the cluster failed to run it {t.attempts} times; last: "
                               f"{name}: {exc}")
                done(t, out)
        finally:
            for fut in futures:
                fut.cancel()


def default_workers() -> int:
    """Processes of the default local pool: the cores this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def make_executor(scheduler: Any = None, workers: int | None = None, cases: int = 1):
    """The executor for ``scheduler`` (Dask) or ``workers`` (local; 1 = in process)."""
    if scheduler is not None:
        return DaskExecutor(scheduler)
    n = default_workers() if workers is None else int(workers)
    n = max(1, min(n, cases))
    return SerialExecutor() if n == 1 else PoolExecutor(n)


# ---------------------------------------------------------------------------------------
# the client loop
# ---------------------------------------------------------------------------------------
@dataclass
class SweepReport:
    """What a run of a sweep did.

    Attributes
    ----------
    store : Path
    results : Path
        Folder of the per-run result folders.
    executor : str
    cases : int
        Cases in the sweep.
    ran : int
        Cases solved by this run.
    adopted : int
        Cases recorded from result folders that an earlier, interrupted run left.
    skipped : int
        Cases already in the store with a final status (not run again).
    statuses : dict
        hash -> status of every case after this run.
    successes, failures, unfinished : int
        Cases whose stored status is successful, unsuccessful and final, or not final
        (``pending``/``lost``) after this run.
    wall_time_s : float
    dry_run : bool
    to_run : list of str
        Hashes that were (or, for a dry run, would be) run.
    others_same_params : int
        Rows of the store that are not cases of this sweep but have the parameter values
        of one of its cases: cases of an earlier version of the base file (or of another
        sweep with other fixed keys). A query by parameters returns them too; select this
        sweep's rows with ``query_runs(store, sweep=...)`` (``bearing-fem runs STORE
        --sweep FILE``).
    """

    store: Path
    results: Path
    executor: str
    cases: int
    ran: int = 0
    adopted: int = 0
    skipped: int = 0
    statuses: dict[str, str] = field(default_factory=dict)
    successes: int = 0
    failures: int = 0
    unfinished: int = 0
    wall_time_s: float = 0.0
    dry_run: bool = False
    to_run: list[str] = field(default_factory=list)
    others_same_params: int = 0

    @property
    def all_successful(self) -> bool:
        """Every case of the sweep is stored with a successful status."""
        return self.successes == self.cases

    def text(self) -> str:
        """A few lines for a terminal."""
        if self.dry_run:
            adopt = (f"{self.adopted} to record from earlier result folders, "
                     if self.adopted else "")
            return (f"{self.cases} cases: {len(self.to_run)} to run, {adopt}{self.skipped} "
                    f"already in {self.store} (dry run: nothing solved)")
        lines = [f"{self.cases} cases: {self.ran} solved now, {self.adopted} recorded from "
                 f"earlier result folders, {self.skipped} already in the store",
                 f"  {self.successes} successful, {self.failures} unsuccessful, "
                 f"{self.unfinished} unfinished (pending or lost: run the sweep again)",
                 f"  store {self.store}; result folders in {self.results}",
                 f"  {self.executor}, {self.wall_time_s:.1f} s"]
        if self.others_same_params:
            lines.append(f"  note: the store also holds {self.others_same_params} row(s) with "
                         "the parameters of cases of this sweep but another scene (an "
                         "earlier base file, or another sweep); 'bearing-fem runs "
                         f"{self.store} --sweep SWEEP.toml' lists this sweep's rows alone")
        return "\n".join(lines)


def plan(cases: Sequence[Case], store: RunStore, results: Path, retry_failed: bool,
         files: str = "all") -> tuple[list[Case], list[Case], list[tuple[Case, Outcome]]]:
    """Split cases into (to run, skipped, adoptable with their outcome).

    A case is skipped when its row has a final status and, if successful, its result
    folder exists (with ``files = "all"``: with the whole export, not the summary alone
    that a ``files = "summary"`` run wrote); unsuccessful final rows are run again only
    with ``retry_failed``. Rows ``pending`` or ``lost``, and successful rows whose result
    folder is gone or too short, run again (or are adopted from a result folder of the
    same hash that has the files asked for).
    """
    def enough(path: Path | None, kind: str) -> bool:
        return has_all_files(path, kind) if files == "all" else result_complete(path, kind)

    states = store.states([c.hash for c in cases])
    run, skip, adopted = [], [], []
    for c in cases:
        s = states.get(c.hash)
        if s is not None and s["status"] not in NON_FINAL:
            if s["success"]:
                if enough(store.resolve(s["result_path"]), c.kind):
                    skip.append(c)
                    continue
                log.info("case %s: stored as %s but its result folder is missing or holds "
                         "the summary alone; running it again", c.hash[:12], s["status"])
            elif not retry_failed:
                skip.append(c)
                continue
            else:
                run.append(c)
                continue
        found = adopt(c, results / c.hash) if enough(results / c.hash, c.kind) else None
        if found is not None:
            adopted.append((c, found))
        else:
            run.append(c)
    return run, skip, adopted


def _remove_store_files(path: Path) -> None:
    """Delete a store file this run created (and SQLite's -wal and -shm files)."""
    for p in (path, path.with_name(path.name + "-wal"), path.with_name(path.name + "-shm")):
        try:
            p.unlink()
        except FileNotFoundError:
            pass


def others_with_same_params(store: RunStore, cases: Sequence[Case]) -> int:
    """Rows of ``store`` that are not among ``cases`` but have the parameter values of one
    of them (same parameter names and values, another resolved scene).

    Parameters
    ----------
    store : RunStore
    cases : sequence of Case

    Returns
    -------
    int
        The number of such rows (0 when the cases have no parameters).
    """
    from .store import sql_value

    names = sorted({k for c in cases for k in c.params})
    if not names or not set(names) <= set(store.columns()):
        return 0
    mine = {c.hash for c in cases}
    keys = {tuple(sql_value(c.params.get(n)) for n in names) for c in cases}
    return sum(1 for r in store.rows(columns=["hash", *names])
               if r["hash"] not in mine and tuple(r[n] for n in names) in keys)


def run_cases(cases: Sequence[Case], store_path: str | Path, *, results: str | Path | None = None,
              files: str = "all", scheduler: Any = None, workers: int | None = None,
              retry_failed: bool = False, progress: bool = False, dry_run: bool = False,
              on_outcome: Callable[[Case, Outcome], None] | None = None) -> SweepReport:
    """Run the cases that the store does not hold yet and record every outcome.

    Parameters
    ----------
    cases : sequence of Case
    store_path : path
        The SQLite run store (created if missing).
    results : path, optional
        Folder of the per-run result folders (default ``<store stem>_runs`` next to the
        store).
    files : {"all", "summary"}
    scheduler : str or Client or cluster, optional
        Run on Dask; default: the local pool.
    workers : int, optional
        Local pool size (default: the machine's cores; 1 runs in this process).
    retry_failed : bool
        Also rerun cases stored with an unsuccessful final status.
    progress : bool
        A progress bar on stderr (only when stderr is a terminal).
    dry_run : bool
        Plan only: report what would run, solve and write nothing.
    on_outcome : callable, optional
        Called with (case, outcome) after each case is recorded.

    Returns
    -------
    SweepReport
    """
    from .progress import SweepProgress

    t0 = time.perf_counter()
    store_path = Path(store_path)
    results = Path(results) if results is not None else \
        store_path.parent / f"{store_path.stem}_runs"
    results = results.resolve()
    if dry_run and not store_path.exists():  # nothing stored: every case runs or is adopted
        ready = {c.hash for c in cases
                 if (has_all_files if files == "all" else result_complete)(
                     results / c.hash, c.kind) and adopt(c, results / c.hash) is not None}
        executor = make_executor(scheduler, workers, max(1, len(cases)))
        return SweepReport(store=store_path, results=results, executor=executor.name,
                           cases=len(cases), dry_run=True, adopted=len(ready),
                           to_run=[c.hash for c in cases if c.hash not in ready],
                           wall_time_s=time.perf_counter() - t0)
    created = not store_path.exists()
    with RunStore(store_path) as store:
        planned = store.states([c.hash for c in cases])
        to_run, skipped, adoptable = plan(cases, store, results, retry_failed, files)
        executor = make_executor(scheduler, workers, max(1, len(to_run)))
        report = SweepReport(store=store_path, results=results,
                             executor=executor.name if to_run else "nothing to run",
                             cases=len(cases), skipped=len(skipped), dry_run=dry_run,
                             to_run=[c.hash for c in to_run])
        if dry_run:
            report.adopted = len(adoptable)
            report.wall_time_s = time.perf_counter() - t0
            return report
        if to_run:
            try:
                executor.open()  # e.g. reach the scheduler before anything is written
            except SceneError:
                if created:  # an input error writes nothing: not even an empty store
                    store.close()
                    _remove_store_files(store_path)
                raise
        bar = SweepProgress(len(to_run), enabled=None if progress else False)
        try:
            if to_run:
                clean_stale_run_dirs(results)
            store.fill_params(skipped)
            for c, out in adoptable:
                store.write(c, out)
                report.adopted += 1
            states = store.states([c.hash for c in to_run])
            attempts = {h: s["attempts"] for h, s in states.items()}
            # a case another process sharing the store finished since ``plan`` is not run
            # again (nor set back to pending, which its report would count as unfinished)
            to_run = store.mark_pending(to_run, attempts, planned=planned)
            blas = 1 if isinstance(executor, PoolExecutor) else None
            tasks = [Task(c, str(results / c.hash), files, blas, attempts.get(c.hash, 0) + 1)
                     for c in to_run]

            def done(task: Task, outcome: Outcome) -> None:
                outcome = dict(outcome)
                path = outcome.get("result_path")
                if outcome["status"] not in NON_FINAL and outcome["status"] != ERROR_STATUS \
                        and not result_complete(Path(path) if path else None, task.case.kind):
                    outcome = lost(task, f"the worker ({outcome.get('worker')}) reported "
                                         f"status {outcome['status']} but its result folder "
                                         f"{path!r} is not visible here: the results folder "
                                         "must be on a filesystem shared by the workers and "
                                         "the client")
                store.write(task.case, outcome)
                report.ran += 1
                bar.update(outcome)
                if on_outcome is not None:
                    on_outcome(task.case, outcome)

            if tasks:
                executor.run(tasks, done)
        finally:
            executor.close()
            bar.close()
            final = store.states([c.hash for c in cases])
            report.statuses = {h: s["status"] for h, s in final.items()}
            report.successes = sum(1 for s in final.values() if s["success"])
            report.unfinished = sum(1 for s in final.values() if s["status"] in NON_FINAL)
            report.failures = len(final) - report.successes - report.unfinished
            report.others_same_params = others_with_same_params(store, cases)
            report.wall_time_s = time.perf_counter() - t0
    return report

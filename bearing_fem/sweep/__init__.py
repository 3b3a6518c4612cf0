"""Parameter sweeps: many solves of one base scene (or bearing), kept in a run store.

    import bearing_fem as bf
    report = bf.sweep("speed_load.toml", store="runs.sqlite")   # a sweep file
    report = bf.sweep(cases, store="map.sqlite", scheduler="tcp://10.0.0.5:8786")

``bf.sweep`` (this module is callable: ``bf.sweep(...)`` is :func:`sweep`) runs every case
that the store does not hold yet -- on a local process pool by default, or on a Dask
distributed cluster -- and records one row per case in an SQLite store; rerunning it
resumes where an interrupted run stopped. See ``docs/sweeps.md``.

Modules: :mod:`~bearing_fem.sweep.spec` (sweep files, axes, cases and their hashes),
:mod:`~bearing_fem.sweep.store` (the run store), :mod:`~bearing_fem.sweep.execute`
(workers, executors, the client loop), :mod:`~bearing_fem.sweep.progress` (progress bars).
"""
from __future__ import annotations

import sys
import types
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

from ..errors import SceneError
from .execute import (WORKER_MALLOC_ENV, SweepReport, in_worker_bootstrap, local_cluster,
                      run_cases)
from .progress import SolveProgress, SweepProgress, solve_progress
from .spec import Axis, Case, SweepSpec, ZipAxis, cases_of, check_workers, scene_hash
from .store import RunStore, export_csv, export_parquet, parse_filter

__all__ = ["sweep", "SweepSpec", "Case", "Axis", "ZipAxis", "SweepReport", "RunStore",
           "scene_hash", "SweepProgress", "SolveProgress", "solve_progress", "query_runs",
           "format_runs", "export_runs", "DEFAULT_COLUMNS", "local_cluster",
           "WORKER_MALLOC_ENV"]

#: Summary columns ``bearing-fem runs`` lists by default (when the store has them).
DEFAULT_COLUMNS = ("h_central", "h_min", "p_max", "friction_coefficient", "friction_torque",
                   "heat_power", "wall_time_s")


def sweep(spec: Any, store: str | Path | None = None, *, scheduler: Any = None,
          workers: int | None = None, retry_failed: bool | None = None,
          results: str | Path | None = None, files: str | None = None,
          progress: bool = False, dry_run: bool = False,
          on_outcome: Callable[[Case, Mapping[str, Any]], None] | None = None) -> SweepReport:
    """Run a sweep: every case the run store does not already hold with a final status.

    Parameters
    ----------
    spec : str or Path or SweepSpec or mapping or sequence of Case
        A sweep file (TOML, see ``docs/sweeps.md``), a parsed :class:`SweepSpec`, a table
        with the layout of a sweep file (relative paths from the current folder), or the
        cases themselves (:class:`Case` or ``(params, scene)`` pairs).
    store : str or Path, optional
        The SQLite run store. Default: ``[sweep] store``, else the sweep file's name with
        the suffix ``.sqlite``; required for cases.
    scheduler : str or distributed.Client or cluster, optional
        Run on a Dask distributed cluster (an address such as ``tcp://host:8786``, a
        ``Client`` or a ``LocalCluster``). Default: ``[sweep] scheduler``, else a local
        process pool.
    workers : int, optional
        Size of the local pool (default ``[sweep] workers``, else one process per core);
        1 runs the cases one after another in this process.
    retry_failed : bool, optional
        Rerun cases stored with an unsuccessful final status (default ``[sweep]
        retry_failed``, else False).
    results : str or Path, optional
        Folder of the per-run result folders ``<hash>/`` (default ``[sweep] results``,
        else ``<store stem>_runs`` next to the store). Must be shared by the workers and
        this process.
    files : {"all", "summary"}, optional
        ``all`` (default): the export of each result (``summary.json``, ``result.h5``,
        ``fields.vtu``; a bearing's files); ``summary``: its summary file alone.
    progress : bool
        Show a progress bar on stderr when it is a terminal.
    dry_run : bool
        Validate and plan only: nothing is solved or written.
    on_outcome : callable, optional
        Called in this process with (case, outcome dict) after each case is recorded.

    Returns
    -------
    SweepReport
        Counts (ran, adopted, skipped, successes, failures, unfinished), the status of
        every case, the store and result paths and the wall time [s].

    Raises
    ------
    SceneError
        An invalid sweep file, base file or case (the message names the key, the value
        and the unit), a store that cannot be opened, or a scheduler that cannot be
        reached. Unsuccessful solves do not raise: they are rows with their status.
    """
    if in_worker_bootstrap():
        # a pool worker importing an unguarded main script: one line and a quiet exit (a
        # raise would print a multiprocessing traceback per worker); the client's pool
        # then stops with the cause and the remedy
        import os
        import sys

        sys.stderr.write("bearing_fem.sweep() was called while a worker process imported "
                         "the main script: call it under `if __name__ == \"__main__\":`\n")
        sys.stderr.flush()
        os._exit(1)
    if isinstance(spec, (str, Path)):
        spec = SweepSpec.from_toml(spec)
        default_store = Path(spec.source).with_suffix(".sqlite")
    elif isinstance(spec, Mapping):
        spec = SweepSpec.from_dict(spec, base_dir=Path.cwd())
        default_store = None
    else:
        default_store = None
    if isinstance(spec, SweepSpec):
        store = store if store is not None else (spec.store or default_store)
        scheduler = scheduler if scheduler is not None else spec.scheduler
        workers = workers if workers is not None else spec.workers
        retry_failed = spec.retry_failed if retry_failed is None else retry_failed
        results = results if results is not None else spec.results
        files = files if files is not None else spec.files
    if store is None:
        raise SceneError("a sweep needs a run store: give store='runs.sqlite' (or [sweep] "
                         "store in the sweep file)")
    files = files or "all"
    if files not in ("all", "summary"):
        raise SceneError(f"files must be 'all' or 'summary', got {files!r}")
    check_workers(workers, "workers")
    cases = cases_of(spec)
    return run_cases(cases, store, results=results, files=files, scheduler=scheduler,
                     workers=workers, retry_failed=bool(retry_failed), progress=progress,
                     dry_run=dry_run, on_outcome=on_outcome)


# ---------------------------------------------------------------------------------------
# reading a store (``bearing-fem runs``)
# ---------------------------------------------------------------------------------------
def _open_existing(path: str | Path) -> RunStore:
    p = Path(path)
    if not p.is_file():
        raise SceneError(f"no run store {str(p)!r} (a file written by 'bearing-fem sweep')")
    return RunStore(p)


def query_runs(path: str | Path, *, status: str | Sequence[str] | None = None,
               where: Sequence[str | tuple[str, str, Any]] | None = None,
               columns: Sequence[str] | str | None = None, limit: int | None = None,
               sweep: Any = None) -> tuple[list[dict[str, Any]], list[str]]:
    """Rows of a run store with filters.

    Parameters
    ----------
    path : path
        An existing run store.
    status : str or sequence of str, optional
        Statuses to keep (also the groups ``success``, ``failed``, ``final``,
        ``unfinished``; see :meth:`RunStore.rows`).
    where : str or sequence, optional
        Filters ``"COLUMN OP VALUE"`` (``"load.force>=20"``) or (column, op, value); one
        filter may be given as a string.
    columns : str or sequence of str, optional
        Columns to return (a string: one name, or comma-separated names as on the
        command line); ``default`` (or None): hash, status, the parameters and the main
        summary columns present; ``all``: every column.
    limit : int, optional
    sweep : str or Path or SweepSpec or mapping or sequence of Case, optional
        Keep the rows of this sweep's cases only (as :func:`sweep` takes it; a sweep file
        as it reads now): a store may also hold other sweeps' rows, and rows of an earlier
        version of the base file with the same parameter values.

    Returns
    -------
    (list of dict, list of str)
        The rows (sorted by the parameter columns) and the column names.
    """
    if isinstance(where, str):  # one filter, not its characters
        where = [where]
    if isinstance(columns, str) and columns not in ("all", "default"):
        columns = [c.strip() for c in columns.split(",")]
    hashes = None
    if sweep is not None:
        if isinstance(sweep, (str, Path)):
            sweep = SweepSpec.from_toml(sweep)
        elif isinstance(sweep, Mapping):
            sweep = SweepSpec.from_dict(sweep, base_dir=Path.cwd())
        hashes = [c.hash for c in cases_of(sweep)]
    with _open_existing(path) as store:
        info = store.column_info()
        have = store.columns()
        if columns is None or columns == "default":
            params = [c for c in have if info.get(c, {}).get("role") == "param"]
            cols = ["hash", "status"] + params + [c for c in DEFAULT_COLUMNS if c in have]
        elif columns == "all":
            cols = have
        else:
            cols = list(columns)
        filters = [parse_filter(w) if isinstance(w, str) else tuple(w) for w in where or ()]
        order = [c for c in have if info.get(c, {}).get("role") == "param"]
        rows = store.rows(status=status, where=filters, columns=cols, limit=limit,
                          order=order, hashes=hashes)
    return rows, cols


def format_runs(rows: Sequence[Mapping[str, Any]], columns: Sequence[str],
                units: Mapping[str, str] | None = None) -> str:
    """A plain-text table of rows (``bearing-fem runs``).

    Parameters
    ----------
    rows : sequence of mapping
        Rows as :func:`query_runs` returns them.
    columns : sequence of str
        The columns to show, in order.
    units : mapping, optional
        Column -> unit (:func:`store_units`), shown in the header as ``name [unit]``.

    Returns
    -------
    str
        One line per row under a header, then ``(N rows)``; hashes cut to 12 digits,
        numbers to 4 significant digits, NULL as ``-``.
    """
    def cell(col: str, v: Any) -> str:
        if v is None:
            return "-"
        if col == "hash" and isinstance(v, str):
            return v[:12]
        if isinstance(v, float):
            return f"{v:.4g}"
        text = str(v)
        return text if len(text) <= 40 else text[:37] + "..."

    units = units or {}
    head = [f"{c} [{units[c]}]" if units.get(c) else c for c in columns]
    body = [[cell(c, r.get(c)) for c in columns] for r in rows]
    widths = [max([len(h)] + [len(b[i]) for b in body]) for i, h in enumerate(head)]
    lines = ["  ".join(h.ljust(w) for h, w in zip(head, widths))]
    lines += ["  ".join(v.ljust(w) for v, w in zip(b, widths)) for b in body]
    lines.append(f"({len(rows)} row{'' if len(rows) == 1 else 's'})")
    return "\n".join(lines)


def store_units(path: str | Path) -> dict[str, str]:
    """The units of an existing run store's columns.

    Parameters
    ----------
    path : str or Path
        The run store.

    Returns
    -------
    dict
        Column -> unit for the columns whose unit is known (``"N/m or N"`` for a column
        whose rows carry different units).
    """
    with _open_existing(path) as store:
        return {k: v["unit"] for k, v in store.column_info().items() if v.get("unit")}


def export_runs(rows: Sequence[Mapping[str, Any]], columns: Sequence[str], *,
                csv: str | Path | None = None, parquet: str | Path | None = None
                ) -> str | None:
    """Write rows as CSV and/or Parquet (each atomically).

    Parameters
    ----------
    rows : sequence of mapping
        Rows as :func:`query_runs` returns them.
    columns : sequence of str
        The columns to write, in order.
    csv : str or Path, optional
        The CSV file; ``"-"`` returns the CSV text instead of writing it.
    parquet : str or Path, optional
        The Parquet file (needs pyarrow).

    Returns
    -------
    str or None
        The CSV text when ``csv="-"``, else None.
    """
    text = None
    if parquet is not None:
        export_parquet(rows, parquet, columns)
    if csv is not None:
        text = export_csv(rows, None if str(csv) == "-" else csv, columns)
    return text


class _CallableModule(types.ModuleType):
    """``bf.sweep`` is this module once it is imported: calling it calls :func:`sweep`."""

    def __call__(self, *args: Any, **kwargs: Any) -> SweepReport:
        return sweep(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule

"""The run store: one SQLite database (stdlib :mod:`sqlite3`) with one row per case.

Table ``runs`` (the schema is in ``docs/sweeps.md``):

* ``hash`` (primary key): SHA-256 of the fully-resolved scene
  (:func:`bearing_fem.sweep.spec.scene_hash`);
* the core columns ``kind``, ``status``, ``success``, ``message``, ``warnings`` (JSON
  list), ``error_estimate`` (JSON), ``wall_time_s`` (the solver's), ``run_time_s`` (the
  worker's: solve and files), ``version``, ``result_path`` (relative to the store's
  folder when under it), ``scene`` (canonical JSON of the scene), ``worker``,
  ``attempts`` and ``updated_at`` (UTC, ISO 8601);
* one column per parameter, named as the swept key (``"load.force"``) or label;
* one column per scalar summary key (``h_central``, ``p_max``, ...), per entry of a
  summary table of scalars (``dimensionless.M``, ``error_estimate.h_central``, ...).

Table ``columns`` gives each column's role (``core``, ``param`` or ``summary``) and unit.

Safe for several writers in several processes at once: write-ahead logging (WAL), a busy
timeout, every write in one ``BEGIN IMMEDIATE`` transaction, and columns added inside
that transaction when a result brings a new summary key (the schema is re-read there, so
two writers adding the same column do not collide). Statuses: ``pending`` (submitted,
not finished) and ``lost`` (its worker died or its result file is missing) are not
final; every other status (the solver's, or ``error`` when the solve raised) is final.
"""
from __future__ import annotations

import json
import math
import os
import sqlite3
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

from ..errors import SceneError

#: Core columns of ``runs`` and their SQLite declarations.
CORE_COLUMNS: dict[str, str] = {
    "hash": "TEXT PRIMARY KEY",
    "kind": "TEXT",
    "status": "TEXT NOT NULL",
    "success": "INTEGER",
    "message": "TEXT",
    "warnings": "TEXT",
    "error_estimate": "TEXT",
    "wall_time_s": "REAL",
    "run_time_s": "REAL",
    "version": "TEXT",
    "result_path": "TEXT",
    "scene": "TEXT",
    "worker": "TEXT",
    "attempts": "INTEGER",
    "updated_at": "TEXT",
}
#: Units of the core columns that have one.
CORE_UNITS = {"wall_time_s": "s", "run_time_s": "s"}
#: Statuses that are not final: a resumed sweep runs these cases again.
NON_FINAL = ("pending", "lost")
#: Status of a case whose solve raised an exception (final; ``retry_failed`` reruns it).
ERROR_STATUS = "error"
#: The tables of a run store.
STORE_TABLES = frozenset({"runs", "columns", "meta"})
#: Schema version written to the ``meta`` table.
SCHEMA_VERSION = 1
#: Default busy timeout [s]: how long a writer waits for another one's transaction.
BUSY_TIMEOUT_S = 60.0
#: Summary keys that are not stored as columns (kept elsewhere or too large).
_SKIP_SUMMARY = ("units", "scene", "bearing", "version")


def quote(name: str) -> str:
    """An SQL identifier in double quotes (``load.force`` -> ``"load.force"``)."""
    return '"' + str(name).replace('"', '""') + '"'


def now_utc() -> str:
    """The current UTC time, ISO 8601 to the second."""
    return datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")


def sql_value(value: Any) -> Any:
    """A Python value as stored: numbers and strings as they are, booleans as 0/1,
    non-finite floats as NULL, lists and tables as JSON text."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, int):
        return value if -2**63 <= value < 2**63 else str(value)
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if hasattr(value, "item") and not isinstance(value, (list, tuple, dict)):
        return sql_value(value.item())  # numpy scalar
    return json.dumps(value, sort_keys=True, default=str, allow_nan=False)


def flatten_summary(summary: Mapping[str, Any]) -> tuple[dict[str, Any], dict[str, str]]:
    """The columns of a summary and their units.

    Scalars become columns named as their key; a table of scalars (``dimensionless``,
    ``error_estimate``, a bearing's ``load_balance``) gives ``table.key`` columns; lists
    and deeper tables are left out (``warnings`` and ``error_estimate`` are also stored
    whole as JSON by :meth:`RunStore.write`). ``units``, ``scene``, ``bearing`` and
    ``version`` are not summary columns.

    Returns
    -------
    (dict, dict)
        Column -> value, and column -> unit for the columns whose unit the summary names.
    """
    units = summary.get("units") or {}
    cols: dict[str, Any] = {}
    for key, value in summary.items():
        if key in _SKIP_SUMMARY or key in ("warnings",):
            continue
        if isinstance(value, Mapping):
            for sub, v in value.items():
                if v is None or isinstance(v, (bool, int, float, str)):
                    cols[f"{key}.{sub}"] = v
            continue
        if isinstance(value, (list, tuple)):
            continue
        cols[key] = value
    cols.pop("error_estimate", None)
    known = {k: str(u) for k, u in units.items() if k in cols} if isinstance(units, Mapping) \
        else {}
    return cols, known


#: Joins the units of a column whose rows carry different units (``N/m or N``).
UNIT_SEPARATOR = " or "


def merged_unit(stored: str | None, unit: str | None) -> str | None:
    """The unit of a store column after a row with ``unit`` is written into it.

    A store may hold line contacts (per metre: ``N/m``, ``W/m``), point contacts (``N``,
    ``W``) and bearings in one column such as ``load`` or ``heat_power``; its unit then
    names each unit its rows carry, in the order they appeared (``"N/m or N"``), never
    the first one alone.

    Parameters
    ----------
    stored : str or None
        The column's unit so far (None: unknown).
    unit : str or None
        The unit the new row's summary names (None: none).

    Returns
    -------
    str or None
    """
    if not unit:
        return stored
    if not stored:
        return unit
    return stored if unit in stored.split(UNIT_SEPARATOR) else stored + UNIT_SEPARATOR + unit


class RunStore:
    """An open run store (see the module docstring).

    Parameters
    ----------
    path : str or Path
        The SQLite file; created with its schema when missing (its folder must exist or
        is created).
    timeout : float
        Busy timeout [s] of every write.

    Use as a context manager or call :meth:`close`.
    """

    def __init__(self, path: str | Path, *, timeout: float = BUSY_TIMEOUT_S) -> None:
        self.path = Path(path)
        if str(path) in ("", ":memory:"):
            raise SceneError("the run store must be a file (e.g. runs.sqlite), got "
                             f"{str(path)!r}")
        if self.path.is_dir():
            raise SceneError(f"the run store {str(self.path)!r} is a directory; give a file "
                             "name such as runs.sqlite")
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            self.conn = sqlite3.connect(str(self.path), timeout=timeout,
                                        isolation_level=None, check_same_thread=False)
        except (OSError, sqlite3.Error) as exc:
            raise SceneError(f"cannot open the run store {str(self.path)!r}: {exc}") from None
        self.timeout = timeout
        try:
            self._setup()
        except sqlite3.OperationalError as exc:
            self.conn.close()
            if "locked" in str(exc) or "busy" in str(exc):
                raise SceneError(f"the run store {str(self.path)!r} stayed locked by another "
                                 f"writer for more than {timeout:g} s") from None
            raise SceneError(f"cannot use the run store {str(self.path)!r}: {exc}") from None
        except sqlite3.DatabaseError as exc:
            self.conn.close()
            raise SceneError(f"{str(self.path)!r} is not a bearing_fem run store (SQLite): "
                             f"{exc}") from None

    # -----------------------------------------------------------------------------------
    def __enter__(self) -> "RunStore":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def close(self) -> None:
        """Close the connection (idempotent)."""
        conn = getattr(self, "conn", None)
        if conn is not None:
            conn.close()
            self.conn = None

    @property
    def folder(self) -> Path:
        """The folder of the store file (result paths are relative to it)."""
        return self.path.resolve().parent

    # -----------------------------------------------------------------------------------
    def _retrying(self, fn, *args):
        """Run ``fn`` and retry on 'database is locked' until the busy timeout has passed
        (the busy handler does not cover every case, e.g. switching to WAL)."""
        deadline = time.monotonic() + self.timeout
        while True:
            try:
                return fn(*args)
            except sqlite3.OperationalError as exc:
                if "locked" not in str(exc) and "busy" not in str(exc):
                    raise
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.05)

    def _setup(self) -> None:
        c = self.conn
        c.execute(f"PRAGMA busy_timeout = {int(self.timeout * 1000)}")
        # another application's database is neither changed nor used (not even its
        # journal mode): a store has exactly these tables, or none yet
        tables = {r[0] for r in c.execute(
            "SELECT name FROM sqlite_master WHERE type = 'table'")}
        if tables and (tables - STORE_TABLES or "meta" not in tables or not c.execute(
                "SELECT 1 FROM meta WHERE key = 'schema_version'").fetchone()):
            raise SceneError(f"{str(self.path)!r} is an SQLite database but not a "
                             f"bearing_fem run store (its tables: {', '.join(sorted(tables))}); "
                             "give the sweep a new file name")
        mode = self._retrying(lambda: c.execute("PRAGMA journal_mode = WAL").fetchone()[0])
        if str(mode).lower() != "wal":  # pragma: no cover - e.g. a network filesystem
            raise SceneError(f"the run store {str(self.path)!r} cannot use write-ahead "
                             f"logging (journal mode {mode!r}); put it on a local disk")
        c.execute("PRAGMA synchronous = NORMAL")
        cols = ", ".join(f"{quote(k)} {v}" for k, v in CORE_COLUMNS.items())
        with self.transaction():
            c.execute(f"CREATE TABLE IF NOT EXISTS runs ({cols})")
            c.execute("CREATE TABLE IF NOT EXISTS columns (name TEXT PRIMARY KEY, "
                      "role TEXT NOT NULL, unit TEXT)")
            c.execute("CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT)")
            c.execute("INSERT OR IGNORE INTO meta VALUES ('schema_version', ?)",
                      (str(SCHEMA_VERSION),))
            have = {r[0] for r in c.execute("SELECT name FROM columns")}
            for name in CORE_COLUMNS:
                if name not in have:
                    c.execute("INSERT OR IGNORE INTO columns VALUES (?, 'core', ?)",
                              (name, CORE_UNITS.get(name)))

    class _Transaction:
        def __init__(self, store: "RunStore") -> None:
            self.store = store

        def __enter__(self) -> sqlite3.Connection:
            self.store._retrying(self.store.conn.execute, "BEGIN IMMEDIATE")
            return self.store.conn

        def __exit__(self, exc_type, exc, tb) -> None:
            if exc_type is None:
                self.store.conn.execute("COMMIT")
            else:
                self.store.conn.execute("ROLLBACK")

    def transaction(self) -> "RunStore._Transaction":
        """``with store.transaction() as conn:``: one ``BEGIN IMMEDIATE`` ... ``COMMIT``
        (rolled back on an exception)."""
        return RunStore._Transaction(self)

    # -----------------------------------------------------------------------------------
    def columns(self) -> list[str]:
        """Column names of ``runs``, in table order."""
        return [r[1] for r in self.conn.execute("PRAGMA table_info(runs)")]

    def column_info(self) -> dict[str, dict[str, Any]]:
        """Column -> ``{"role": ..., "unit": ...}`` from the ``columns`` table."""
        return {r[0]: {"role": r[1], "unit": r[2]}
                for r in self.conn.execute("SELECT name, role, unit FROM columns")}

    def _ensure_columns(self, conn: sqlite3.Connection, names: Iterable[str], role: str,
                        units: Mapping[str, str] | None = None) -> None:
        """Add missing columns (inside the caller's transaction: the schema read here is
        current, so concurrent writers never add the same column twice)."""
        have = {r[1] for r in conn.execute("PRAGMA table_info(runs)")}
        units = units or {}
        for name in names:
            if name not in have:
                conn.execute(f"ALTER TABLE runs ADD COLUMN {quote(name)}")
                have.add(name)
            conn.execute("INSERT OR IGNORE INTO columns VALUES (?, ?, ?)",
                         (name, role, units.get(name)))
            if units.get(name):
                old = conn.execute("SELECT unit FROM columns WHERE name = ?",
                                   (name,)).fetchone()[0]
                unit = merged_unit(old, units[name])
                if unit != old:
                    conn.execute("UPDATE columns SET unit = ? WHERE name = ?", (unit, name))

    def _upsert(self, conn: sqlite3.Connection, row: Mapping[str, Any]) -> None:
        names = list(row)
        conn.execute(f"INSERT OR REPLACE INTO runs ({', '.join(map(quote, names))}) VALUES "
                     f"({', '.join('?' for _ in names)})", [sql_value(row[n]) for n in names])

    # -----------------------------------------------------------------------------------
    def states(self, hashes: Sequence[str]) -> dict[str, dict[str, Any]]:
        """The stored state of cases.

        Parameters
        ----------
        hashes : sequence of str
            Case hashes (:func:`~bearing_fem.sweep.spec.scene_hash`).

        Returns
        -------
        dict
            ``hash -> {"status", "success", "result_path", "attempts"}`` for the hashes
            that have a row (others are absent).
        """
        out: dict[str, dict[str, Any]] = {}
        hashes = list(hashes)
        for i in range(0, len(hashes), 500):
            chunk = hashes[i:i + 500]
            q = ("SELECT hash, status, success, result_path, attempts FROM runs WHERE hash IN "
                 f"({', '.join('?' for _ in chunk)})")
            for h, status, success, path, attempts in self.conn.execute(q, chunk):
                out[h] = {"status": status, "success": bool(success), "result_path": path,
                          "attempts": attempts or 0}
        return out

    def resolve(self, result_path: str | None) -> Path | None:
        """A stored result path as a path.

        Parameters
        ----------
        result_path : str or None
            A ``result_path`` column value (relative ones are under the store's folder).

        Returns
        -------
        Path or None
            The result folder, or None for a row without one.
        """
        if not result_path:
            return None
        p = Path(result_path)
        return p if p.is_absolute() else self.folder / p

    def relative(self, path: str | Path | None) -> str | None:
        """``path`` as stored: relative to the store's folder when under it (POSIX)."""
        if path is None:
            return None
        p = Path(path).resolve()
        try:
            return p.relative_to(self.folder).as_posix()
        except ValueError:
            return str(p)

    def mark_pending(self, cases: Sequence[Any], attempts: Mapping[str, int] | None = None,
                     planned: Mapping[str, Mapping[str, Any]] | None = None) -> list[Any]:
        """Record cases about to run as ``pending`` (one transaction): their parameters,
        kind and scene; any earlier result of theirs is replaced.

        Parameters
        ----------
        cases : sequence of Case
        attempts : mapping, optional
            ``hash -> attempts`` so far (the row keeps this count; default 0).
        planned : mapping, optional
            The rows (:meth:`states`) the caller planned from. A case whose row has become
            final since then (another process sharing the store finished it) is left as it
            is and not returned.

        Returns
        -------
        list of Case
            The cases marked ``pending``.
        """
        if not cases:
            return []
        from .spec import canonical_json

        attempts = attempts or {}
        params = sorted({k for c in cases for k in c.params})
        with self.transaction() as conn:
            self._ensure_columns(conn, params, "param")
            if planned is not None:
                now = self.states([c.hash for c in cases])
                cases = [c for c in cases
                         if now.get(c.hash, {}).get("status", "pending") in NON_FINAL
                         or now.get(c.hash) == planned.get(c.hash)]
            for c in cases:
                row = {"hash": c.hash, "kind": c.kind, "status": "pending", "success": None,
                       "message": f"submitted {now_utc()}", "attempts": attempts.get(c.hash, 0),
                       "scene": canonical_json(c.scene.to_dict()), "updated_at": now_utc()}
                row.update(c.params)
                self._upsert(conn, row)
        return list(cases)

    def fill_params(self, cases: Sequence[Any]) -> None:
        """Write the parameters of cases that are already stored (e.g. run by another
        sweep under other names) into their rows, where those columns are empty."""
        if not cases:
            return
        params = sorted({k for c in cases for k in c.params})
        with self.transaction() as conn:
            self._ensure_columns(conn, params, "param")
            for c in cases:
                for k, v in c.params.items():
                    conn.execute(f"UPDATE runs SET {quote(k)} = ? WHERE hash = ? AND "
                                 f"{quote(k)} IS NULL", (sql_value(v), c.hash))

    def write(self, case: Any, outcome: Mapping[str, Any]) -> None:
        """Record the outcome of one case (one transaction; the row is replaced whole).

        Parameters
        ----------
        case : Case
        outcome : mapping
            ``status``, ``success``, ``message``, ``summary`` (the result's summary, or
            None), ``result_path``, ``run_time_s``, ``worker``, ``attempts``.
        """
        from .spec import canonical_json

        summary = outcome.get("summary") or {}
        cols, units = flatten_summary(summary)
        for k in CORE_COLUMNS:
            cols.pop(k, None)
        for k in case.params:  # a label of the same name as a summary key keeps its value
            cols.pop(k, None)
        status = str(outcome["status"])
        success = bool(outcome.get("success")) if status not in NON_FINAL else False
        row: dict[str, Any] = {
            "hash": case.hash, "kind": case.kind, "status": status,
            "success": success, "message": str(outcome.get("message") or ""),
            "warnings": list(summary.get("warnings") or outcome.get("warnings") or []),
            "error_estimate": summary.get("error_estimate"),
            "wall_time_s": summary.get("wall_time_s"),
            "run_time_s": outcome.get("run_time_s"),
            "version": summary.get("version") or outcome.get("version"),
            "result_path": self.relative(outcome.get("result_path")),
            "scene": canonical_json(case.scene.to_dict()),
            "worker": outcome.get("worker"), "attempts": int(outcome.get("attempts") or 1),
            "updated_at": now_utc(),
        }
        row.update(case.params)
        row.update(cols)
        with self.transaction() as conn:
            self._ensure_columns(conn, list(case.params), "param")
            self._ensure_columns(conn, list(cols), "summary", units)
            self._upsert(conn, row)

    # -----------------------------------------------------------------------------------
    def rows(self, *, status: Sequence[str] | None = None,
             where: Sequence[tuple[str, str, Any]] | None = None,
             columns: Sequence[str] | None = None, limit: int | None = None,
             order: Sequence[str] | None = None,
             hashes: Iterable[str] | None = None) -> list[dict[str, Any]]:
        """Rows of ``runs`` as dicts, in the order they were last written.

        Parameters
        ----------
        status : str or sequence of str, optional
            Keep rows whose status is one of these; the groups ``success`` (success = 1),
            ``failed`` (final and not successful), ``final`` and ``unfinished``
            (``pending`` or ``lost``) may be named too.
        where : sequence of (column, operator, value), optional
            Filters on any column, combined with AND; operators ``=``, ``!=``, ``<``,
            ``<=``, ``>``, ``>=``.
        columns : sequence of str, optional
            Columns to return (default all).
        limit : int, optional
            At most this many rows (>= 1).
        order : sequence of str, optional
            Sort by these columns (ascending); default: the order the rows were written.
        hashes : iterable of str, optional
            Keep the rows of these cases only (e.g. the cases of one sweep).
        """
        if isinstance(status, str):  # one status, not its characters
            status = (status,)
        if limit is not None and (isinstance(limit, bool) or not isinstance(limit, int)
                                  or limit < 1):
            raise SceneError(f"limit must be a positive whole number of rows, got {limit!r}")
        have = self.columns()
        if isinstance(columns, str):  # one column, not its characters
            columns = [columns]
        cols = list(columns) if columns else have
        missing = [c for c in cols if c not in have]
        if missing:
            raise SceneError(f"no column(s) {', '.join(map(repr, missing))} in the run store; "
                             f"columns: {', '.join(have)}")
        sql = f"SELECT {', '.join(map(quote, cols))} FROM runs"
        clauses, args = [], []
        if status:
            parts = []
            for s in status:
                if s == "success":
                    parts.append("success = 1")
                elif s == "failed":
                    parts.append(f"(success = 0 AND status NOT IN ({_list_sql(NON_FINAL)}))")
                elif s == "final":
                    parts.append(f"status NOT IN ({_list_sql(NON_FINAL)})")
                elif s == "unfinished":
                    parts.append(f"status IN ({_list_sql(NON_FINAL)})")
                else:
                    parts.append("status = ?")
                    args.append(s)
            clauses.append("(" + " OR ".join(parts) + ")")
        for col, op, value in where or ():
            if col not in have:
                raise SceneError(f"no column {col!r} in the run store to filter on; columns: "
                                 f"{', '.join(have)}")
            if op not in ("=", "!=", "<", "<=", ">", ">="):
                raise SceneError(f"filter operator must be one of = != < <= > >=, got {op!r}")
            if isinstance(value, str) and self._numeric_column(col):
                raise SceneError(f"filter {col} {op} {value!r}: the column {col!r} holds "
                                 f"numbers and {value!r} is not a number (it would compare "
                                 "as text and keep no row, or every row)")
            clauses.append(f"{quote(col)} {op} ?")
            args.append(sql_value(value))
        if hashes is not None:
            clauses.append("hash IN (SELECT value FROM json_each(?))")
            args.append(json.dumps(sorted(set(hashes))))
        if clauses:
            sql += " WHERE " + " AND ".join(clauses)
        for col in order or ():
            if col not in have:
                raise SceneError(f"no column {col!r} in the run store to sort by")
        sql += " ORDER BY " + ", ".join([quote(c) for c in order or ()] + ["rowid"])
        if limit is not None:
            sql += f" LIMIT {int(limit)}"
        cur = self.conn.execute(sql, args)
        return [dict(zip(cols, r)) for r in cur.fetchall()]

    def _numeric_column(self, col: str) -> bool:
        """True when every non-NULL value of ``col`` is a number (and there is one)."""
        types = {t for (t,) in self.conn.execute(
            f"SELECT DISTINCT typeof({quote(col)}) FROM runs WHERE {quote(col)} IS NOT NULL")}
        return bool(types) and types <= {"integer", "real"}

    def count(self) -> dict[str, int]:
        """Number of rows per status."""
        return {s: n for s, n in self.conn.execute(
            "SELECT status, COUNT(*) FROM runs GROUP BY status ORDER BY status")}


def _list_sql(values: Sequence[str]) -> str:
    return ", ".join("'" + v.replace("'", "''") + "'" for v in values)


def parse_filter(text: str) -> tuple[str, str, Any]:
    """``"load.force>=20"`` -> ``("load.force", ">=", 20.0)``.

    The value is read as JSON where it can be (numbers, true/false, lists), else as a
    string.
    """
    for op in ("<=", ">=", "!=", "=", "<", ">"):
        i = text.find(op)
        if i > 0:
            col, raw = text[:i].strip(), text[i + len(op):].strip()
            if not col or not raw:
                break
            try:
                value = json.loads(raw)
            except ValueError:
                value = raw
                try:  # numbers JSON does not read: ".5", "5.", "+2", "1E-6"
                    number = float(raw)
                    if math.isfinite(number):
                        value = number
                except ValueError:
                    pass
            if isinstance(value, (list, dict)):
                value = json.dumps(value, sort_keys=True)
            return col, op, value
    raise SceneError(f"a filter must read COLUMN OP VALUE with OP one of = != < <= > >=, "
                     f"e.g. 'load.force>=20', got {text!r}")


def export_csv(rows: Sequence[Mapping[str, Any]], path: str | Path | None,
               columns: Sequence[str]) -> str | None:
    """Write rows as CSV to ``path`` (atomically: a temporary name, then
    :func:`os.replace`), or return the text when ``path`` is None."""
    import csv
    import io

    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(columns)
    for r in rows:
        w.writerow(["" if r.get(c) is None else r.get(c) for c in columns])
    if path is None:
        return buf.getvalue()
    _atomic_write(Path(path), buf.getvalue().encode("utf-8"))
    return None


def export_parquet(rows: Sequence[Mapping[str, Any]], path: str | Path,
                   columns: Sequence[str]) -> None:
    """Write rows as Parquet (needs pyarrow; SceneError with the install command if
    missing). Each column keeps one type: numbers as float64 or int64, else text."""
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        raise SceneError("Parquet export needs pyarrow, which is not installed "
                         "(pip install pyarrow); use CSV instead") from None
    data = {}
    for c in columns:
        vals = [r.get(c) for r in rows]
        present = [v for v in vals if v is not None]
        if present and all(isinstance(v, int) for v in present):
            data[c] = pa.array(vals, type=pa.int64())
        elif present and all(isinstance(v, (int, float)) for v in present):
            data[c] = pa.array([None if v is None else float(v) for v in vals],
                               type=pa.float64())
        else:
            data[c] = pa.array([None if v is None else str(v) for v in vals], type=pa.string())
    path = Path(path)
    _export_target(path, "Parquet")
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        pq.write_table(pa.table(data), str(tmp))
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()


def _export_target(path: Path, what: str) -> None:
    """Refuse an export file that cannot be written (SceneError naming it), before any
    temporary file is made."""
    if path.is_dir():
        raise SceneError(f"cannot write the {what} export to {str(path)!r}: it is a "
                         f"directory; give a file name such as runs.{what.lower()}")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise SceneError(f"cannot write the {what} export to {str(path)!r}: "
                         f"{exc.strerror or exc}") from None


def _atomic_write(path: Path, data: bytes) -> None:
    _export_target(path, "CSV")
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        tmp.write_bytes(data)
        os.replace(tmp, path)
    except OSError as exc:
        raise SceneError(f"cannot write the CSV export to {str(path)!r}: "
                         f"{exc.strerror or exc}") from None
    finally:
        if tmp.exists():
            tmp.unlink()

"""Sweep files: a base scene (or bearing) file and the axes that vary it.

A sweep file is TOML (``docs/sweeps.md``)::

    [sweep]
    scene = "ball.toml"            # relative to the sweep file; a bearing file works too
    [axes]                         # the product of all axes, the first one outermost
    "load.force" = [10.0, 20.0, 40.0]
    "kinematics.u1" = { logspace = [-1.0, 1.0, 5] }   # also linspace = [start, stop, n]
    [zip]                          # optional: axes that move together with another one
    "kinematics.u2" = "kinematics.u1"                  # the same values as its leader
    "lubricant.viscosity" = { with = "kinematics.u1", values = [0.01, 0.02, 0.03, 0.04, 0.05] }

Every case is the base file's table with the swept dotted keys set, validated by
:meth:`bearing_fem.scene.Scene.from_dict` (or ``Bearing.from_dict`` for a file with a
top-level ``[bearing]`` table) before anything runs; a bad value is a
:class:`~bearing_fem.errors.SceneError` that names the swept key, the value and (from the
scene's own validation) the unit. Each case carries the hash of its fully-resolved scene
(:func:`scene_hash`), which keys the run store.

No solving and no I/O beyond reading the sweep and base files.
"""
from __future__ import annotations

import copy
import hashlib
import itertools
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

from ..errors import SceneError
from ..validation import shown

#: Keys of the ``[sweep]`` table.
SWEEP_KEYS = ("scene", "title", "store", "results", "files", "scheduler", "workers",
              "retry_failed")
#: Top-level tables of a sweep file.
SWEEP_TABLES = ("sweep", "axes", "zip")
#: What a run writes into its result directory: ``all`` (the export of the result:
#: summary.json, result.h5, fields.vtu for a contact) or ``summary`` (summary.json only).
FILES_CHOICES = ("all", "summary")
#: Most cases a sweep may have (a typo such as ``linspace = [0, 1, 1e6]`` is refused).
MAX_CASES = 1_000_000
#: Columns of the run store that a case's parameter names must not shadow.
RESERVED_NAMES = ("hash", "kind", "status", "success", "message", "warnings",
                  "error_estimate", "wall_time_s", "run_time_s", "version", "result_path",
                  "scene", "worker", "attempts", "updated_at", "units", "dimensionless")


# ---------------------------------------------------------------------------------------
# the resolved target of a case and its hash
# ---------------------------------------------------------------------------------------
def canonical_json(data: Any) -> str:
    """Canonical JSON text of a scene dict: sorted keys, no spaces, finite numbers only.

    Parameters
    ----------
    data : mapping
        ``scene.to_dict()`` (or ``bearing.to_dict()``).

    Returns
    -------
    str
    """
    return json.dumps(data, sort_keys=True, separators=(",", ":"), allow_nan=True,
                      ensure_ascii=True)


def scene_hash(target: Any) -> str:
    """SHA-256 (hex) of the canonical JSON of a fully-resolved scene or bearing.

    Two cases with the same hash solve the same problem. Numbers are compared after
    validation (``10`` and ``10.0`` give the same scene and the same hash).

    Parameters
    ----------
    target : Scene or Bearing
        Anything with ``to_dict()``.

    Returns
    -------
    str
        64 hexadecimal digits.
    """
    kind = target_kind(target)
    text = canonical_json({"kind": kind, "scene": target.to_dict()})
    return hashlib.sha256(text.encode("ascii")).hexdigest()


def target_kind(target: Any) -> str:
    """``"scene"`` for a contact :class:`~bearing_fem.scene.Scene`, ``"bearing"`` for a
    bearing (``bearing_fem.bearing.Bearing``); SceneError otherwise."""
    from ..scene import Scene

    if isinstance(target, Scene):
        return "scene"
    try:
        from ..bearing import Bearing  # type: ignore[attr-defined]
    except ImportError:  # pragma: no cover - an installation without bearing files
        Bearing = None
    if Bearing is not None and isinstance(target, Bearing):
        return "bearing"
    raise SceneError(f"a sweep case must be a Scene or a Bearing, got "
                     f"{type(target).__name__}")


def is_bearing_table(data: Mapping[str, Any]) -> bool:
    """True for a bearing file's table (it has a top-level ``[bearing]`` table)."""
    return isinstance(data.get("bearing"), Mapping)


def build_target(data: Mapping[str, Any]) -> Any:
    """A validated Scene, or a Bearing when ``data`` has a top-level ``[bearing]`` table.

    The bearing package is imported only for a bearing file.
    """
    if is_bearing_table(data):
        try:
            from ..bearing import Bearing  # type: ignore[attr-defined]
        except ImportError as exc:  # pragma: no cover - depends on the installed package
            raise SceneError(f"this is a bearing file ([bearing] table) but bearing files "
                             f"cannot be solved by this installation: {exc}") from None
        return Bearing.from_dict(data)
    from ..scene import Scene

    return Scene.from_dict(data)


@dataclass(frozen=True)
class Case:
    """One case of a sweep: its parameters (the store's columns) and its resolved scene.

    Parameters
    ----------
    params : mapping
        Column name -> value: the swept keys of a sweep file (``"load.force"``), or any
        labels a script chooses (``"M"``, ``"L"``). Values are numbers, strings, booleans
        or lists (stored as JSON text).
    scene : Scene or Bearing
        The fully-resolved, validated target.
    """

    params: Mapping[str, Any]
    scene: Any
    kind: str = field(init=False)
    hash: str = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "params", dict(self.params))
        for name in self.params:
            check_param_name(name)
        object.__setattr__(self, "kind", target_kind(self.scene))
        object.__setattr__(self, "hash", scene_hash(self.scene))


def check_param_name(name: Any) -> str:
    """A case parameter name, or SceneError (empty, not a string, or a store column)."""
    if not isinstance(name, str) or not name.strip():
        raise SceneError(f"a sweep parameter name must be a non-empty string, got "
                         f"{shown(name)}")
    if name in RESERVED_NAMES or name.startswith(("error_estimate.", "dimensionless.")):
        raise SceneError(f"sweep parameter name {name!r} clashes with a column of the run "
                         f"store ({', '.join(RESERVED_NAMES)}); choose another name")
    return name


def unique_cases(cases: Iterable[Case]) -> list[Case]:
    """The cases as a list; SceneError if two of them resolve to the same scene."""
    out: list[Case] = []
    seen: dict[str, int] = {}
    for i, case in enumerate(cases):
        if not isinstance(case, Case):
            raise SceneError(f"sweep case {i} must be a bearing_fem.sweep.Case, got "
                             f"{type(case).__name__}")
        if case.hash in seen:
            j = seen[case.hash]
            raise SceneError(f"sweep cases {j} ({_params_text(out[j].params)}) and {i} "
                             f"({_params_text(case.params)}) resolve to the same scene "
                             f"(hash {case.hash[:12]}); remove the duplicate value")
        seen[case.hash] = i
        out.append(case)
    return out


def _params_text(params: Mapping[str, Any]) -> str:
    return ", ".join(f"{k} = {shown(v)}" for k, v in params.items()) or "the base scene"


# ---------------------------------------------------------------------------------------
# axes
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Axis:
    """A swept key and its values (in order)."""

    key: str
    values: tuple[Any, ...]


@dataclass(frozen=True)
class ZipAxis:
    """A key that moves together with the axis ``leader``: case i takes ``values[i]``."""

    key: str
    leader: str
    values: tuple[Any, ...]


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _check_key(key: Any, where: str) -> str:
    if not isinstance(key, str) or not key:
        raise SceneError(f"[{where}]: a swept key must be a dotted scene key such as "
                         f"'load.force', got {shown(key)}")
    parts = key.split(".")
    if len(parts) < 2 or any(not p.strip() for p in parts):
        raise SceneError(f"[{where}] {key!r}: a swept key must be a dotted key "
                         "'section.key' of the base file, e.g. 'load.force' or "
                         "'kinematics.u1'")
    return key


def _range(key: str, form: str, spec: Any) -> tuple[float, ...]:
    """Values of ``{linspace = [a, b, n]}`` or ``{logspace = [a, b, n]}``."""
    import numpy as np

    if (not isinstance(spec, (list, tuple)) or len(spec) != 3
            or not all(_is_number(v) for v in spec[:2])):
        raise SceneError(f"axis {key!r}: {form} must be [start, stop, n] with numbers "
                         f"start, stop and an integer n, got {shown(spec)}")
    a, b, n = spec
    if not (math.isfinite(a) and math.isfinite(b)):
        raise SceneError(f"axis {key!r}: {form} start and stop must be finite, got "
                         f"{shown(spec)}")
    if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= MAX_CASES:
        raise SceneError(f"axis {key!r}: {form} n must be an integer in [1, {MAX_CASES}] "
                         f"(number of values), got {shown(n)}")
    if form == "logspace":
        if max(abs(a), abs(b)) > 300:
            raise SceneError(f"axis {key!r}: logspace exponents must lie in [-300, 300] "
                             f"(values 10**start .. 10**stop), got {shown(spec)}")
        return tuple(float(v) for v in np.logspace(a, b, n))
    return tuple(float(v) for v in np.linspace(a, b, n))


def axis_values(key: str, spec: Any) -> tuple[Any, ...]:
    """The values of one axis: a non-empty list, ``{linspace = [a, b, n]}`` or
    ``{logspace = [a, b, n]}`` (numpy's convention: 10**a .. 10**b).

    Parameters
    ----------
    key : str
        The swept key (for messages).
    spec : list or mapping
        As written in the sweep file.

    Returns
    -------
    tuple
    """
    if isinstance(spec, Mapping):
        forms = [f for f in ("linspace", "logspace", "values") if f in spec]
        bad = [k for k in spec if k not in ("linspace", "logspace", "values")]
        if bad or len(forms) != 1:
            raise SceneError(f"axis {key!r}: give a list of values, or a table with exactly "
                             "one of linspace = [start, stop, n], logspace = [start, stop, "
                             f"n] or values = [...], got {shown(dict(spec))}")
        if forms[0] != "values":
            return _range(key, forms[0], spec[forms[0]])
        spec = spec["values"]
    if not isinstance(spec, (list, tuple)) or not spec:
        raise SceneError(f"axis {key!r}: values must be a non-empty list, got {shown(spec)}")
    for v in spec:
        if isinstance(v, Mapping):
            raise SceneError(f"axis {key!r}: a value must be a number, string, boolean or "
                             f"list, got the table {shown(v)}")
        if isinstance(v, float) and not math.isfinite(v):
            raise SceneError(f"axis {key!r}: values must be finite, got {shown(v)}")
    return tuple(list(v) if isinstance(v, (list, tuple)) else v for v in spec)


def set_dotted(data: dict[str, Any], key: str, value: Any) -> None:
    """Set ``data["a"]["b"] = value`` for ``key = "a.b"`` (tables made where missing).

    SceneError when a part of the path is not a table (``load.force.x`` with a number at
    ``load.force``).
    """
    parts = key.split(".")
    node = data
    for i, part in enumerate(parts[:-1]):
        child = node.get(part)
        if child is None:
            child = node[part] = {}
        elif not isinstance(child, dict):
            where = ".".join(parts[:i + 1])
            raise SceneError(f"cannot set {key!r}: {where!r} is {shown(child)} in the base "
                             "file, not a table")
        node = child
    node[parts[-1]] = copy.deepcopy(value)


# ---------------------------------------------------------------------------------------
# the sweep
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SweepSpec:
    """A parsed, validated sweep file (see the module docstring and ``docs/sweeps.md``).

    Attributes
    ----------
    base : dict
        The base scene (or bearing) file's table.
    axes : tuple of Axis
        The product axes, first outermost.
    zipped : tuple of ZipAxis
    source : str
        Where the sweep came from (for messages).
    title : str
    store : Path or None
        ``[sweep] store``: the run store (relative paths resolved against the sweep file).
    results : Path or None
        ``[sweep] results``: the folder of the per-run result directories (default
        ``<store stem>_runs`` next to the store).
    files : {"all", "summary"}
    scheduler : str or None
        ``[sweep] scheduler``: address of a Dask scheduler (``tcp://host:8786``).
    workers : int or None
        ``[sweep] workers``: processes of the local pool (default: the machine's cores).
    retry_failed : bool
        ``[sweep] retry_failed``: rerun cases stored with an unsuccessful final status.
    """

    base: Mapping[str, Any]
    axes: tuple[Axis, ...] = ()
    zipped: tuple[ZipAxis, ...] = ()
    source: str = "<sweep>"
    title: str = ""
    store: Path | None = None
    results: Path | None = None
    files: str = "all"
    scheduler: str | None = None
    workers: int | None = None
    retry_failed: bool = False

    @property
    def kind(self) -> str:
        """``"bearing"`` for a bearing base file, else ``"scene"``."""
        return "bearing" if is_bearing_table(self.base) else "scene"

    @property
    def keys(self) -> list[str]:
        """Every swept key (axes, then zipped), in order: the store's parameter columns."""
        return [a.key for a in self.axes] + [z.key for z in self.zipped]

    def __len__(self) -> int:
        return math.prod(len(a.values) for a in self.axes)

    def params(self) -> list[dict[str, Any]]:
        """The swept values of every case (product of the axes, first axis outermost;
        zipped keys take the value of their leader's index)."""
        index = {a.key: i for i, a in enumerate(self.axes)}
        out = []
        for combo in itertools.product(*(range(len(a.values)) for a in self.axes)):
            p = {a.key: a.values[i] for a, i in zip(self.axes, combo)}
            for z in self.zipped:
                p[z.key] = z.values[combo[index[z.leader]]]
            out.append(p)
        return out

    def cases(self) -> list[Case]:
        """Every case, resolved and validated (SceneError names the case and the key)."""
        cases = []
        for i, p in enumerate(self.params()):
            data = copy.deepcopy(dict(self.base))
            try:
                for key, value in p.items():
                    set_dotted(data, key, value)
                target = build_target(data)
            except SceneError as exc:
                raise SceneError(f"{self.source}: case {i} ({_params_text(p)}): {exc}") from None
            cases.append(Case(p, target))
        return unique_cases(cases)

    # -----------------------------------------------------------------------------------
    @classmethod
    def from_toml(cls, path: str | Path) -> "SweepSpec":
        """Read a sweep file; the base file is resolved relative to it.

        Parameters
        ----------
        path : str or Path
            The sweep file (TOML, ``docs/sweeps.md``).

        Returns
        -------
        SweepSpec

        Raises
        ------
        SceneError
            The file cannot be read, is not valid TOML, or is not a valid sweep (the
            message names the key, the value and, for scene keys, the unit).
        """
        from ..scene import read_toml

        path = Path(path)
        data = read_toml(path, "sweep file")
        return cls.from_dict(data, base_dir=path.parent, source=str(path))

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], *, base_dir: str | Path = ".",
                  source: str = "<sweep>") -> "SweepSpec":
        """Build a sweep from a table with the layout of a sweep file.

        Parameters
        ----------
        data : mapping
            ``{"sweep": {"scene": ...}, "axes": {...}, "zip": {...}}``. ``scene`` is a
            path (relative to ``base_dir``) or the base table itself.
        base_dir : path
            Folder that relative paths (scene, store, results) are taken from.
        source : str
            Name of the sweep in messages.
        """
        if not isinstance(data, Mapping):
            raise SceneError(f"{source}: a sweep must be a table, got {type(data).__name__}")
        unknown = [k for k in data if k not in SWEEP_TABLES]
        if unknown:
            raise SceneError(f"{source}: unknown table(s) or key(s) "
                             f"{', '.join(map(repr, unknown))}; a sweep file has the tables "
                             f"{', '.join(f'[{t}]' for t in SWEEP_TABLES)}")
        head = data.get("sweep")
        if not isinstance(head, Mapping):
            raise SceneError(f"{source}: missing [sweep] table (with scene = \"base.toml\")")
        bad = [k for k in head if k not in SWEEP_KEYS]
        if bad:
            raise SceneError(f"{source}: unknown key(s) {', '.join(f'sweep.{k}' for k in bad)}"
                             f"; known keys of [sweep]: {', '.join(SWEEP_KEYS)}")
        base_dir = Path(base_dir)
        if "scene" not in head:
            raise SceneError(f"{source}: missing sweep.scene (the base scene or bearing file, "
                             "relative to the sweep file)")
        scene = head["scene"]
        if isinstance(scene, Mapping):
            base = copy.deepcopy(dict(scene))
        elif isinstance(scene, (str, Path)) and str(scene).strip():
            from ..scene import read_toml

            base = read_toml(base_dir / scene, "base file (sweep.scene)")
        else:
            raise SceneError(f"{source}: sweep.scene must be a file name (relative to the "
                             f"sweep file) or a table, got {shown(scene)}")
        kw: dict[str, Any] = {"base": base, "source": source}
        title = head.get("title", "")
        if not isinstance(title, str):
            raise SceneError(f"{source}: sweep.title must be a string, got {shown(title)}")
        kw["title"] = title
        for name in ("store", "results"):
            v = head.get(name)
            if v is not None:
                if not isinstance(v, (str, Path)) or not str(v).strip():
                    raise SceneError(f"{source}: sweep.{name} must be a path, got {shown(v)}")
                kw[name] = base_dir / v
        files = head.get("files", "all")
        if files not in FILES_CHOICES:
            raise SceneError(f"{source}: sweep.files must be one of "
                             f"{', '.join(map(repr, FILES_CHOICES))}, got {shown(files)}")
        kw["files"] = files
        sched = head.get("scheduler")
        if sched is not None and (not isinstance(sched, str) or not sched.strip()):
            raise SceneError(f"{source}: sweep.scheduler must be a scheduler address such as "
                             f"'tcp://127.0.0.1:8786', got {shown(sched)}")
        kw["scheduler"] = sched
        kw["workers"] = check_workers(head.get("workers"), f"{source}: sweep.workers")
        retry = head.get("retry_failed", False)
        if not isinstance(retry, bool):
            raise SceneError(f"{source}: sweep.retry_failed must be true or false, got "
                             f"{shown(retry)}")
        kw["retry_failed"] = retry
        try:
            kw["axes"], kw["zipped"] = parse_axes(data.get("axes", {}), data.get("zip", {}),
                                                  source)
        except SceneError as exc:  # every message names the sweep file
            text = str(exc)
            raise SceneError(text if text.startswith(f"{source}:") else f"{source}: {text}") \
                from None
        spec = cls(**kw)
        if len(spec) > MAX_CASES:
            raise SceneError(f"{source}: the axes make {len(spec)} cases, more than "
                             f"{MAX_CASES}")
        return spec


def check_workers(value: Any, name: str) -> int | None:
    """``workers``: None (the machine's cores) or an integer >= 1 (processes)."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= 4096:
        raise SceneError(f"{name} must be an integer in [1, 4096] (worker processes), got "
                         f"{shown(value)}")
    return value


def parse_axes(axes: Any, zipped: Any, source: str = "<sweep>"
               ) -> tuple[tuple[Axis, ...], tuple[ZipAxis, ...]]:
    """Parse the ``[axes]`` and ``[zip]`` tables (see the module docstring)."""
    if not isinstance(axes, Mapping):
        raise SceneError(f"{source}: [axes] must be a table of 'section.key' = values, got "
                         f"{shown(axes)}")
    if not isinstance(zipped, Mapping):
        raise SceneError(f"{source}: [zip] must be a table of 'section.key' = "
                         f"'leader.key', got {shown(zipped)}")
    out_axes = []
    for key, spec in _once(_flat_keys(axes), "axes", source):
        _check_key(key, "axes")
        out_axes.append(Axis(key, axis_values(key, spec)))
    leaders = {a.key: a for a in out_axes}
    out_zip = []
    for key, spec in _once(_flat_keys(zipped), "zip", source):
        _check_key(key, "zip")
        if key in leaders:
            raise SceneError(f"{source}: {key!r} is both an axis and a zipped key")
        if isinstance(spec, str):
            leader, values = spec, None
        elif isinstance(spec, Mapping) and "with" in spec:
            leader = spec["with"]
            rest = {k: v for k, v in spec.items() if k != "with"}
            values = axis_values(key, rest if len(rest) != 1 or "values" not in rest
                                 else rest["values"])
        else:
            raise SceneError(f"zip {key!r}: give the name of its leader axis ('{key}' = "
                             "'kinematics.u1': the same values), or a table "
                             "{ with = 'kinematics.u1', values = [...] } (or linspace/logspace "
                             f"instead of values), got {shown(spec)}")
        if leader not in leaders:
            raise SceneError(f"zip {key!r}: the leader {shown(leader)} is not an axis of "
                             f"[axes] (axes: {', '.join(leaders) or 'none'})")
        lead = leaders[leader]
        if values is None:
            values = lead.values
        elif len(values) != len(lead.values):
            raise SceneError(f"zip {key!r}: {len(values)} values for {len(lead.values)} "
                             f"values of its leader {leader!r}; they must match")
        out_zip.append(ZipAxis(key, leader, tuple(values)))
    return tuple(out_axes), tuple(out_zip)


def _flat_keys(table: Mapping[str, Any], prefix: str = "") -> list[tuple[str, Any]]:
    """``{"load.force": v}`` as written with quotes, or ``{"load": {"force": v}}`` as
    TOML makes of unquoted dotted keys: both as ``("load.force", v)``. Only a section
    name (a key without a dot) is taken apart this way: below it, a table is the axis
    itself (``{linspace = [...]}``). TOML keeps a key written both ways twice
    (:func:`_once` refuses it)."""
    out = []
    for key, value in table.items():
        key = f"{prefix}{key}"
        if isinstance(value, Mapping) and "." not in key:
            out += _flat_keys(value, prefix=f"{key}.")
        else:
            out.append((key, value))
    return out


def _once(pairs: list[tuple[str, Any]], table: str, source: str) -> list[tuple[str, Any]]:
    """``pairs`` (of :func:`_flat_keys`), or SceneError naming a key given twice."""
    seen: set[str] = set()
    for key, _ in pairs:
        if key in seen:
            raise SceneError(f"{source}: [{table}] gives {key!r} twice (quoted, \"{key}\" = "
                             "..., and unquoted or as a table): one would silently replace "
                             "the other's values; give it once")
        seen.add(key)
    return pairs


def cases_of(spec_or_cases: Any) -> list[Case]:
    """The cases of a SweepSpec, or a sequence of :class:`Case` or ``(params, scene)``
    pairs, checked for duplicates."""
    if isinstance(spec_or_cases, SweepSpec):
        return spec_or_cases.cases()
    if isinstance(spec_or_cases, (str, bytes, Mapping)) or not isinstance(
            spec_or_cases, (Sequence, Iterable)):
        raise SceneError(f"sweep cases must be a SweepSpec or a list of Case, got "
                         f"{type(spec_or_cases).__name__}")
    cases = []
    for i, c in enumerate(spec_or_cases):
        if isinstance(c, Case):
            cases.append(c)
        elif isinstance(c, tuple) and len(c) == 2 and isinstance(c[0], Mapping):
            cases.append(Case(c[0], c[1]))
        else:
            raise SceneError(f"sweep case {i} must be a Case or a (params, scene) pair, got "
                             f"{type(c).__name__}")
    return unique_cases(cases)

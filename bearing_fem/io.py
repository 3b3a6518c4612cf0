"""Export and read back solve results: ``summary.json``, ``result.h5``, ``fields.vtu``.

I/O only, no physics. Every file is written under a temporary name in the output
directory and moved into place with :func:`os.replace` once all files of an export are
complete, so a crash or a full disk never leaves a half-written ``summary.json`` next to
an older ``result.h5``. A process killed in between (SIGKILL, power cut) can leave hidden
temporary files; the next export into the same directory removes those of processes that
no longer run (:func:`clean_stale_temporaries`). h5py and meshio are imported inside the
functions that use them.

Files written by :func:`export`
-------------------------------
``summary.json``
    :meth:`bearing_fem.result.Result.summary` as strict JSON (``allow_nan=False``);
    a non-finite number, which the solver should never produce, is written as ``null``.
``result.h5``
    Datasets ``x`` [m], ``y`` [m] (point contacts only), ``pressure_Pa``, ``film_m`` and
    every entry of ``result.extra_fields``, each with a ``unit`` attribute. Root
    attributes ``kind``, ``status``, ``success``, ``message``, ``version``, ``title``,
    ``h0`` [m],
    ``scene`` (the scene as TOML text), ``summary`` (the summary as JSON text). Group
    ``convergence``: dataset ``history`` (scaled residual after each Newton iteration),
    attributes ``newton_iterations``, ``linear_solves``, ``wall_time_s`` and
    ``continuation`` (JSON list of ``[parameter, status, iterations]``).
``fields.vtu``
    VTK unstructured grid (meshio): a 1D line mesh of the nodes (line contact) or quads
    on the structured (ny, nx) grid (point contact), with point data ``pressure_Pa``,
    ``film_m`` and the extra fields. Coordinates in metres.
"""
from __future__ import annotations

import json
import logging
import math
import os
import re
import secrets
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from .result import json_safe

__all__ = ["export", "export_series", "read_result", "scene_to_toml", "write_summary", "write_h5",
           "write_vtu", "clean_stale_temporaries", "FILES"]

log = logging.getLogger(__name__)

#: File names written by :func:`export`, keyed as in its returned dict.
FILES = {"summary": "summary.json", "h5": "result.h5", "vtu": "fields.vtu"}

#: Unit suffixes of field names (longest first), e.g. ``viscosity_Pa_s`` -> ``Pa s``.
_SUFFIX_UNITS = (
    ("_W_m2", "W/m^2"), ("_Pa_s", "Pa s"), ("_m_s", "m/s"), ("_Pa", "Pa"), ("_K", "K"),
    ("_degC", "degC"), ("_C", "degC"), ("_W", "W"), ("_m", "m"), ("_s", "s"), ("_1", "1"),
)


def field_unit(name: str) -> str:
    """Unit encoded in a field name's suffix (``film_m`` -> ``m``), or ``""`` if none.

    Parameters
    ----------
    name : str
        Field name; by convention it ends with its unit (e.g. ``film_m``, ``viscosity_Pa_s``).

    Returns
    -------
    str
    """
    for suffix, unit in _SUFFIX_UNITS:
        if name.endswith(suffix):
            return unit
    return ""


# ---------------------------------------------------------------------------------------
# TOML text of a scene (tomllib reads only; scenes are small nested tables)
# ---------------------------------------------------------------------------------------
def _toml_value(value: Any, where: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        v = float(value)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(value, str):
        return json.dumps(value)  # a JSON string is a valid TOML basic string
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v, where) for v in value) + "]"
    raise TypeError(f"cannot write {where} = {value!r} ({type(value).__name__}) as TOML")


def _toml_key(key: Any) -> str:
    key = str(key)
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else json.dumps(key)


def scene_to_toml(scene: Any) -> str:
    """TOML text of a scene (a :class:`~bearing_fem.scene.Scene` or its ``to_dict()``).

    The text reads back with :meth:`Scene.from_toml_string` to an equal scene. Top-level
    scalars come first, then one ``[section]`` table per nested mapping.

    Parameters
    ----------
    scene : Scene or mapping
        A scene, or a nested mapping with the TOML layout of ``docs/scenes.md``.

    Returns
    -------
    str
    """
    data = scene.to_dict() if hasattr(scene, "to_dict") else scene
    if not isinstance(data, Mapping):
        raise TypeError(f"scene_to_toml needs a Scene or a mapping, got {type(data).__name__}")
    lines: list[str] = []
    tables = [(k, v) for k, v in data.items() if isinstance(v, Mapping)]
    for key, value in data.items():
        if not isinstance(value, Mapping):
            lines.append(f"{_toml_key(key)} = {_toml_value(value, key)}")
    for name, table in tables:
        if lines:
            lines.append("")
        lines.append(f"[{_toml_key(name)}]")
        for key, value in table.items():
            if isinstance(value, Mapping):
                raise TypeError(f"scene_to_toml: nested table {name}.{key} is not supported")
            lines.append(f"{_toml_key(key)} = {_toml_value(value, f'{name}.{key}')}")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------
# helpers
# ---------------------------------------------------------------------------------------
def _kind(result: Any) -> str:
    return "point" if result.y is not None else "line"


def _fields(result: Any) -> dict[str, np.ndarray]:
    """Nodal fields to export, name (with unit suffix) -> array (copies)."""
    out = {"pressure_Pa": np.array(result.pressure, dtype=float),
           "film_m": np.array(result.film, dtype=float)}
    for name, arr in (result.extra_fields or {}).items():
        if name in out or name in ("x", "y"):
            raise ValueError(f"extra field name {name!r} clashes with a standard dataset")
        out[str(name)] = np.array(arr, dtype=float)
    return out


def _grid(result: Any) -> tuple[np.ndarray, np.ndarray | None]:
    """Node coordinates (n, 3) and, for point contacts, the (ny, nx) node-index grid.

    Accepts for a point contact either grid axes (``x`` of size nx, ``y`` of size ny,
    fields with nx*ny values in C order of (ny, nx)) or nodal coordinates (``x``, ``y``
    and the fields all of one size, any node order, on a tensor-product grid).
    """
    x = np.asarray(result.x, dtype=float)
    n = np.asarray(result.pressure).size
    if result.y is None:
        if x.size != n:
            raise ValueError(f"line result: x has {x.size} nodes but pressure has {n}")
        pts = np.zeros((n, 3))
        pts[:, 0] = x.ravel()
        return pts, None
    y = np.asarray(result.y, dtype=float)
    if x.ndim == 1 and y.ndim == 1 and x.size * y.size == n and x.size != n:
        xx, yy = np.meshgrid(x, y)  # (ny, nx)
        pts = np.column_stack([xx.ravel(), yy.ravel(), np.zeros(n)])
        index = np.arange(n).reshape(y.size, x.size)
        return pts, index
    if x.size != n or y.size != n:
        raise ValueError(f"point result: x ({x.shape}), y ({y.shape}) and pressure ({n} "
                         "values) are neither grid axes nor nodal coordinates")
    xs, ix = np.unique(x.ravel(), return_inverse=True)
    ys, iy = np.unique(y.ravel(), return_inverse=True)
    if xs.size * ys.size != n:
        raise ValueError(f"point result: {n} nodes do not form a tensor grid "
                         f"({xs.size} x values, {ys.size} y values)")
    index = np.full((ys.size, xs.size), -1, dtype=np.int64)
    index[iy, ix] = np.arange(n)
    pts = np.column_stack([x.ravel(), y.ravel(), np.zeros(n)])
    return pts, index


#: Name of a temporary file of :class:`_Staging`: ``.<final name>.<pid>.<12 hex>.tmp<suffix>``.
_TEMP_NAME = re.compile(r"^\.(?P<final>.+)\.(?P<pid>\d+)\.[0-9a-f]{12}\.tmp(?P<suffix>\.[^.]*)?$")
#: Age after which a temporary file of a still-running process id counts as stale [s]
#: (the process id may have been reused by an unrelated process).
STALE_TEMP_AGE = 24 * 3600.0


def _process_alive(pid: int) -> bool:
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OSError):
        return True  # exists (another user's process), or cannot tell: keep its files
    return True


def clean_stale_temporaries(outdir: str | Path, max_age: float = STALE_TEMP_AGE) -> list[Path]:
    """Remove temporary files that an interrupted export left in ``outdir``.

    An export killed between writing its temporary files and moving them into place
    (e.g. by SIGKILL or a power cut) leaves hidden files named
    ``.<final name>.<pid>.<random>.tmp<suffix>``. A file of that exact form is removed
    when its process no longer runs, or when it is older than ``max_age`` (the process
    id may have been reused). Files of a running export (this or another process) and
    every other file are left alone. Called by :func:`export` and :func:`export_series`.

    Parameters
    ----------
    outdir : str or Path
        Output directory (nothing happens if it does not exist).
    max_age : float
        Age [s] beyond which a temporary file counts as stale even if its process id runs.

    Returns
    -------
    list of Path
        The removed files.
    """
    import time

    outdir = Path(outdir)
    removed: list[Path] = []
    try:
        entries = list(outdir.iterdir())
    except OSError:
        return removed
    now = time.time()
    for path in entries:
        m = _TEMP_NAME.match(path.name)
        if m is None or (m.group("suffix") or "") != Path(m.group("final")).suffix:
            continue
        try:
            st = path.lstat()
        except OSError:
            continue
        if not path.is_file() or path.is_symlink():
            continue
        if _process_alive(int(m.group("pid"))) and now - st.st_mtime < max_age:
            continue
        try:
            path.unlink()
            removed.append(path)
        except OSError:
            continue
    if removed:
        log.info("removed %d temporary file(s) of an interrupted export in %s: %s",
                 len(removed), outdir, ", ".join(p.name for p in removed))
    return removed


class _Staging:
    """Temporary files in ``outdir`` moved into place together by :meth:`commit`."""

    def __init__(self, outdir: Path):
        self.outdir = outdir
        self.pending: list[tuple[Path, Path]] = []

    def temp(self, final_name: str) -> Path:
        # a fresh, unguessable name; the writer creates it with the usual permissions
        # (mkstemp would make it 0600)
        suffix = Path(final_name).suffix
        tmp = self.outdir / f".{final_name}.{os.getpid()}.{secrets.token_hex(6)}.tmp{suffix}"
        self.pending.append((tmp, self.outdir / final_name))
        return tmp

    def commit(self) -> None:
        for tmp, final in self.pending:
            os.replace(tmp, final)
        self.pending.clear()

    def discard(self) -> None:
        for tmp, _ in self.pending:
            try:
                tmp.unlink()
            except FileNotFoundError:
                pass
        self.pending.clear()


# ---------------------------------------------------------------------------------------
# writers
# ---------------------------------------------------------------------------------------
def write_summary(result: Any, path: str | Path) -> Path:
    """Write ``result.summary()`` as strict JSON to ``path`` (not atomic; see :func:`export`).

    Parameters
    ----------
    result : Result
        Any result with ``summary()`` (numbers in SI units, named in its ``units``).
    path : str or Path
        The JSON file; a non-finite number is written as ``null``.

    Returns
    -------
    Path
    """
    path = Path(path)
    text = json.dumps(json_safe(result.summary()), indent=2, allow_nan=False)
    path.write_text(text + "\n", encoding="utf-8")
    return path


def write_h5(result: Any, path: str | Path) -> Path:
    """Write fields, provenance and convergence history to an HDF5 file at ``path``.

    The layout is described in the module docstring. Not atomic on its own; use
    :func:`export` for that.

    Parameters
    ----------
    result : Result
        Coordinates [m], ``pressure`` [Pa], ``film`` [m] and the extra fields (their
        names carry their units) are written as datasets, the summary as attributes.
    path : str or Path
        The HDF5 file.

    Returns
    -------
    Path
    """
    import h5py

    from .version import VERSION as package_version

    path = Path(path)
    summary = json_safe(result.summary())
    with h5py.File(path, "w") as f:
        f.attrs["kind"] = _kind(result)
        f.attrs["status"] = str(result.status)
        f.attrs["success"] = bool(result.success)
        f.attrs["message"] = str(result.message)
        f.attrs["version"] = package_version
        f.attrs["title"] = str(getattr(result.scene, "title", "") or "")
        f.attrs["h0"] = float(result.h0)
        f.attrs["scene"] = scene_to_toml(result.scene)
        f.attrs["summary"] = json.dumps(summary, allow_nan=False)
        coords = {"x": result.x} if result.y is None else {"x": result.x, "y": result.y}
        for name, arr in coords.items():
            ds = f.create_dataset(name, data=np.array(arr, dtype=float))
            ds.attrs["unit"] = "m"
        for name, arr in _fields(result).items():
            ds = f.create_dataset(name, data=arr)
            ds.attrs["unit"] = field_unit(name)
        g = f.create_group("convergence")
        ds = g.create_dataset("history", data=np.array(result.history, dtype=float))
        ds.attrs["unit"] = "1"
        ds.attrs["description"] = "scaled residual norm after each Newton iteration"
        g.attrs["newton_iterations"] = int(result.newton_iterations)
        g.attrs["linear_solves"] = int(getattr(result, "linear_solves", 0))
        g.attrs["wall_time_s"] = float(result.wall_time_s)
        g.attrs["continuation"] = json.dumps(json_safe(
            [list(step) for step in getattr(result, "continuation", [])]))
    return path


def write_vtu(result: Any, path: str | Path) -> Path:
    """Write the nodal fields as a VTK unstructured grid (``.vtu``) at ``path``.

    Line contact: 1D line cells between consecutive nodes. Point contact: quads on the
    structured (ny, nx) grid. Point data: ``pressure_Pa``, ``film_m``, extra fields.
    """
    import meshio

    pts, index = _grid(result)
    if index is None:
        n = pts.shape[0]
        cells = [("line", np.column_stack([np.arange(n - 1), np.arange(1, n)]))]
    else:
        quads = np.column_stack([index[:-1, :-1].ravel(), index[:-1, 1:].ravel(),
                                 index[1:, 1:].ravel(), index[1:, :-1].ravel()])
        cells = [("quad", quads)]
    data = {name: arr.ravel() for name, arr in _fields(result).items()}
    mesh = meshio.Mesh(pts, cells, point_data=data)
    meshio.write(str(path), mesh, file_format="vtu")
    return Path(path)


def export(result: Any, outdir: str | Path) -> dict[str, Path]:
    """Write ``summary.json``, ``result.h5`` and ``fields.vtu`` of a result into ``outdir``.

    All three files are first written under temporary names in ``outdir`` and then moved
    into place with :func:`os.replace`; if any writer fails, the temporary files are
    removed and existing files are left untouched. ``result`` is not modified.

    Parameters
    ----------
    result : Result
        Any result of :func:`bearing_fem.solve` (successful or not: the status is stored).
    outdir : str or Path
        Output directory, created with its parents if needed.

    Returns
    -------
    dict[str, Path]
        ``{"summary": .../summary.json, "h5": .../result.h5, "vtu": .../fields.vtu}``.
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    clean_stale_temporaries(outdir)
    stage = _Staging(outdir)
    try:
        write_summary(result, stage.temp(FILES["summary"]))
        write_h5(result, stage.temp(FILES["h5"]))
        write_vtu(result, stage.temp(FILES["vtu"]))
        stage.commit()
    except BaseException:
        stage.discard()
        raise
    return {key: outdir / name for key, name in FILES.items()}


# ---------------------------------------------------------------------------------------
# time series (squeeze series of point contacts)
# ---------------------------------------------------------------------------------------
def _series_mesh(result: Any) -> tuple[np.ndarray, np.ndarray]:
    """Points (n, 3) and quad cells (m, 4) of a point result's (ny, nx) grid."""
    pts, index = _grid(result)
    if index is None:
        raise ValueError("a squeeze series holds point-contact results (a 2D grid)")
    quads = np.column_stack([index[:-1, :-1].ravel(), index[:-1, 1:].ravel(),
                             index[1:, 1:].ravel(), index[1:, :-1].ravel()])
    return pts, quads


def _xdmf_item(h5name: str, path: str, shape: tuple[int, ...], kind: str) -> str:
    number = "Int" if kind == "int" else "Float"
    precision = "" if kind == "int" else ' Precision="8"'
    dims = " ".join(str(d) for d in shape)
    return (f'<DataItem DataType="{number}" Dimensions="{dims}" Format="HDF"{precision}>'
            f"{h5name}:{path}</DataItem>")


def export_series(series: Any, outdir: str | Path, name: str | None = None) -> dict[str, Path]:
    """Write a squeeze series as VTU files with a PVD index and as one XDMF/HDF5 series.

    Fields per node and step: ``pressure_Pa``, ``film_m``. The failed step of an elastic
    series that stopped (``series.failure``, its last admissible iterate) is written
    apart, as ``<name>_failed.vtu`` and the group ``failed`` of the HDF5 file, outside
    the time series: it is not a solution. Every file is written under a temporary name
    and moved into place when all are complete (as :func:`export`); a ``<name>_failed.vtu``
    left by an earlier export into the same folder is removed when this series has no
    failed step.

    Parameters
    ----------
    series : SqueezeSeries or ElasticSqueezeSeries
        From :mod:`bearing_fem.contacts.series` or :mod:`bearing_fem.contacts.transient`
        (``times`` [s] and one point-contact ``Result`` per step in ``results``).
    outdir : str or Path
        Output directory (created).
    name : str, optional
        Stem of the file names (default ``"elastic_squeeze"`` for elastic series,
        ``"squeeze"`` for rigid ones).

    Returns
    -------
    dict[str, Path]
        ``{"pvd": ..., "xdmf": ..., "h5": ..., "summary": .../summary.json}`` (the series'
        :meth:`summary`), with ``"failed": .../<name>_failed.vtu`` where a step failed; a
        series with no solved instant writes its summary (with the status) and its failed
        step's VTU, if any, alone: ``{"summary": ...[, "failed": ...]}``.
    """
    import h5py

    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    clean_stale_temporaries(outdir)
    summary_text = json.dumps(json_safe(series.summary()), indent=2, allow_nan=False) + "\n"
    if name is None:
        name = "elastic_squeeze" if hasattr(series, "scheme") else "squeeze"
    failure = getattr(series, "failure", None)
    failed_fields = None if failure is None else _series_fields(failure)
    failed_name = f"{name}_failed.vtu"
    if not series.results:  # nothing solved: the summary (with the status) alone
        stage = _Staging(outdir)
        try:
            stage.temp(FILES["summary"]).write_text(summary_text, encoding="utf-8")
            if failure is not None:
                _write_quad_vtu(stage.temp(failed_name), *_series_mesh(failure),
                                failed_fields)
            stage.commit()
        except BaseException:
            stage.discard()
            raise
        written = {"summary": outdir / FILES["summary"]}
        if failure is not None:
            written["failed"] = outdir / failed_name
        return written
    points, quads = _series_mesh(series.results[0])
    stage = _Staging(outdir)
    final = {"pvd": outdir / f"{name}.pvd", "xdmf": outdir / f"{name}.xdmf",
             "h5": outdir / f"{name}.h5", "summary": outdir / FILES["summary"]}
    if failure is not None:
        final["failed"] = outdir / failed_name
    try:
        entries, grids = [], []
        h5name = final["h5"].name
        with h5py.File(stage.temp(h5name), "w") as f:
            f.create_dataset("points", data=points)
            f.create_dataset("cells", data=quads.astype(np.int64))
            for k, (t, r) in enumerate(zip(series.times, series.results)):
                fname = f"{name}_{k:04d}.vtu"
                data = _series_fields(r)
                _write_quad_vtu(stage.temp(fname), points, quads, data)
                entries.append(f'    <DataSet timestep="{float(t):.9g}" part="0" '
                               f'file="{fname}"/>')
                attrs = []
                for key, arr in data.items():
                    f.create_dataset(f"{key}_{k:04d}", data=arr)
                    attrs.append(f'<Attribute Name="{key}" AttributeType="Scalar" '
                                 f'Center="Node">'
                                 + _xdmf_item(h5name, f"/{key}_{k:04d}", arr.shape, "float")
                                 + "</Attribute>")
                grids.append(
                    f'<Grid Name="step_{k:04d}" GridType="Uniform"><Time Value="{float(t):.17g}"/>'
                    f'<Topology TopologyType="Quadrilateral" NumberOfElements="{len(quads)}">'
                    + _xdmf_item(h5name, "/cells", quads.shape, "int") + "</Topology>"
                    '<Geometry GeometryType="XYZ">'
                    + _xdmf_item(h5name, "/points", points.shape, "float") + "</Geometry>"
                    + "".join(attrs) + "</Grid>")
            if failure is not None:
                group = f.create_group("failed")
                for key, arr in failed_fields.items():
                    group.create_dataset(key, data=arr)
                group.attrs["status"] = failure.status
        if failure is not None:
            _write_quad_vtu(stage.temp(failed_name), points, quads, failed_fields)
        stage.temp(final["summary"].name).write_text(summary_text, encoding="utf-8")
        stage.temp(final["pvd"].name).write_text(
            '<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
            "  <Collection>\n" + "\n".join(entries) + "\n  </Collection>\n</VTKFile>\n",
            encoding="utf-8")
        stage.temp(final["xdmf"].name).write_text(
            '<?xml version="1.0"?>\n<Xdmf Version="3.0"><Domain>'
            '<Grid Name="TimeSeries" GridType="Collection" CollectionType="Temporal">'
            + "\n".join(grids) + "</Grid></Domain></Xdmf>\n", encoding="utf-8")
        stage.commit()
    except BaseException:
        stage.discard()
        raise
    if failure is None:  # an earlier export's failed step is not this series'
        (outdir / failed_name).unlink(missing_ok=True)
    return final


def _series_fields(result: Any) -> dict[str, np.ndarray]:
    """The nodal fields of one instant of a series, flattened in node order."""
    return {"pressure_Pa": np.ravel(result.pressure), "film_m": np.ravel(result.film)}


def _write_quad_vtu(path: Path, points: np.ndarray, quads: np.ndarray,
                    fields: dict[str, np.ndarray]) -> None:
    """One instant of a series (a solved step, or the failed step's last iterate) as a VTU
    file of quads with its nodal fields."""
    import meshio

    meshio.write(str(path), meshio.Mesh(points, [("quad", quads)], point_data=fields),
                 file_format="vtu")


#: Columns of a series summary: the prescribed ones (every instant has them) and the
#: solved ones (``null`` where an instant has no solution), with their units.
SERIES_PRESCRIBED = {"times": "s", "gap": "m", "squeeze_velocity": "m/s"}
SERIES_SOLVED = {"p_max": "Pa", "h_min": "m", "h_central": "m", "load": "N"}


def read_series(path: str | Path) -> dict[str, Any]:
    """Read the ``summary.json`` of a squeeze series written by :func:`export_series`.

    Parameters
    ----------
    path : str or Path
        The export directory, its ``summary.json``, or one of the series' files in it
        (``.h5``, ``.xdmf``, ``.pvd``, ``.vtu``).

    Returns
    -------
    dict
        The summary's keys (``status``, ``success``, ``message``, ``scheme``,
        ``instants``, ``warnings``, ``units``, ``scene``, ...) with the columns as arrays:
        ``times`` [s], ``gap`` = h0(t) [m], ``squeeze_velocity`` = dh0/dt [m/s] as float
        arrays; ``p_max`` [Pa], ``h_min``, ``h_central`` [m] and ``load`` [N] as masked
        float arrays, masked at the instants without solution (``null`` in the file);
        ``title`` (the scene's, or "") and ``path`` (the summary file).

    Raises
    ------
    ValueError
        No ``summary.json`` there, not strict JSON, not a series summary (``kind`` is not
        ``"squeeze series"``), a missing column, columns of unequal length or a
        non-finite value.
    """
    path = Path(path)
    if not path.exists():
        raise ValueError(f"no series export {str(path)!r}: no such file or folder")
    if path.is_dir():
        path = path / FILES["summary"]
    elif path.name != FILES["summary"]:
        path = path.parent / FILES["summary"]
    if not path.is_file():
        raise ValueError(f"no series summary {str(path)!r} (the summary.json written by "
                         "bearing_fem.io.export_series or 'bearing-fem solve' of a "
                         "[transient] scene)")
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"{str(path)!r} is not a JSON summary ({exc})") from None
    out = series_from_summary(data, repr(str(path)))
    out["path"] = path
    return out


def series_from_summary(summary: Mapping[str, Any], source: str = "the series summary"
                        ) -> dict[str, Any]:
    """The columns of a squeeze series' summary as arrays (the layout of
    :func:`read_series`, without ``path``).

    Parameters
    ----------
    summary : mapping
        ``SqueezeSeries.summary()`` or its JSON read back.
    source : str
        Names the summary in error messages.

    Returns
    -------
    dict
        The summary's keys; ``times`` [s], ``gap`` [m], ``squeeze_velocity`` [m/s] as
        float arrays, ``p_max`` [Pa], ``h_min``, ``h_central`` [m], ``load`` [N] as masked
        float arrays (masked where the summary holds ``None``); ``title`` (the scene's).

    Raises
    ------
    ValueError
        Not a series summary, a missing column, columns of unequal length, a missing
        prescribed value or a non-finite value.
    """
    data = summary
    if not isinstance(data, Mapping) or data.get("kind") != "squeeze series":
        kind = data.get("kind") if isinstance(data, Mapping) else type(data).__name__
        raise ValueError(f"{source} is not the summary of a squeeze series (kind "
                         f"{kind!r}, expected 'squeeze series')")
    missing = [k for k in ("status", "success", "message", "instants", *SERIES_PRESCRIBED,
                           *SERIES_SOLVED) if k not in data]
    if missing:
        raise ValueError(f"{source}: the series summary lacks {', '.join(missing)}")
    n = data["instants"]
    out = dict(data)
    for key, unit in {**SERIES_PRESCRIBED, **SERIES_SOLVED}.items():
        column = data[key]
        if not isinstance(column, (list, tuple)) or len(column) != n:
            raise ValueError(f"{source}: {key} must list one value [{unit}] per instant "
                             f"({n}), got "
                             f"{len(column) if isinstance(column, (list, tuple)) else column!r}")
        solved = key in SERIES_SOLVED
        mask = np.array([v is None for v in column], dtype=bool)
        if mask.any() and not solved:
            raise ValueError(f"{source}: {key} [{unit}] has no value at instant "
                             f"{int(np.argmax(mask))}")
        try:
            values = np.array([0.0 if v is None else float(v) for v in column], dtype=float)
        except (TypeError, ValueError):
            raise ValueError(f"{source}: {key} [{unit}] holds a non-number") from None
        if not np.all(np.isfinite(values)):
            raise ValueError(f"{source}: {key} [{unit}] holds a non-finite value")
        out[key] = np.ma.MaskedArray(values, mask=mask) if solved else values
    scene = data.get("scene")
    out["title"] = str(scene.get("title") or "") if isinstance(scene, Mapping) else ""
    return out


__all__ += ["read_series", "series_from_summary", "SERIES_PRESCRIBED", "SERIES_SOLVED"]


# ---------------------------------------------------------------------------------------
# reader
# ---------------------------------------------------------------------------------------
def read_result(path: str | Path) -> dict[str, Any]:
    """Read a ``result.h5`` written by :func:`export` (or the directory holding it).

    Parameters
    ----------
    path : str or Path
        The HDF5 file, or an export directory containing ``result.h5``.

    Returns
    -------
    dict
        ``kind``, ``status``, ``success``, ``message``, ``version``, ``title``, ``h0`` [m];
        ``x``, ``y`` (None for line contacts) [m]; ``pressure_Pa``, ``film_m``;
        ``fields`` (every nodal dataset by name, including the two above and the extra
        fields); ``units`` (dataset name -> unit); ``scene`` (dict with the TOML
        layout) and ``scene_toml`` (text); ``summary`` (dict); ``history``,
        ``newton_iterations``, ``linear_solves``, ``wall_time_s``, ``continuation``.

    Raises
    ------
    ValueError
        If ``path`` does not exist, is not HDF5, or is not a contact result.
    """
    import h5py

    try:
        import tomllib
    except ModuleNotFoundError:  # pragma: no cover
        import tomli as tomllib  # type: ignore[no-redef]

    path = Path(path)
    if path.is_dir():
        path = path / FILES["h5"]
    if not path.is_file():
        raise ValueError(f"no result file {str(path)!r} (a result.h5 written by "
                         "bearing_fem.export or 'bearing-fem solve', or its folder)")
    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        raise ValueError(f"{str(path)!r} is not an HDF5 file ({exc}); read_result reads a "
                         "result.h5 written by bearing_fem.export") from None
    out: dict[str, Any] = {}
    with f:
        a = f.attrs
        missing = [k for k in ("kind", "status", "success", "message", "version", "h0",
                               "scene", "summary") if k not in a]
        if missing:
            raise ValueError(f"{str(path)!r} is an HDF5 file but not a contact result "
                             f"written by bearing_fem.export (no attribute(s) "
                             f"{', '.join(missing)}): series and bearing outputs have files "
                             "of their own")
        out["kind"] = str(a["kind"])
        out["status"] = str(a["status"])
        out["success"] = bool(a["success"])
        out["message"] = str(a["message"])
        out["version"] = str(a["version"])
        out["title"] = str(a.get("title", ""))
        out["h0"] = float(a["h0"])
        out["scene_toml"] = str(a["scene"])
        out["scene"] = tomllib.loads(out["scene_toml"])
        out["summary"] = json.loads(str(a["summary"]))
        units: dict[str, str] = {}
        fields: dict[str, np.ndarray] = {}
        for name, ds in f.items():
            if not isinstance(ds, h5py.Dataset):
                continue
            units[name] = str(ds.attrs.get("unit", ""))
            if name not in ("x", "y"):
                fields[name] = ds[()]
        out["x"] = f["x"][()]
        out["y"] = f["y"][()] if "y" in f else None
        out["pressure_Pa"] = fields["pressure_Pa"]
        out["film_m"] = fields["film_m"]
        out["fields"] = fields
        out["units"] = units
        g = f["convergence"]
        out["history"] = g["history"][()]
        out["newton_iterations"] = int(g.attrs["newton_iterations"])
        out["linear_solves"] = int(g.attrs["linear_solves"])
        out["wall_time_s"] = float(g.attrs["wall_time_s"])
        out["continuation"] = json.loads(str(g.attrs["continuation"]))
    return out


# =======================================================================================
# Bearing exports (results of bearing_fem.bearing.solve_bearing)
# =======================================================================================
#: Files written by :func:`export_bearing` in the output directory, keyed as returned.
BEARING_FILES = {"summary": "bearing_summary.json", "elements": "elements.csv",
                 "vtm": "contacts.vtm"}
#: Subdirectory of the per-contact VTK blocks referenced by ``contacts.vtm``.
BEARING_VTK_DIR = "contacts_vtk"

__all__ += ["export_bearing", "write_bearing_summary", "write_elements_csv", "BEARING_FILES"]


def write_bearing_summary(result: Any, path: str | Path) -> Path:
    """Write ``result.summary()`` of a bearing result as strict JSON (not atomic; the
    same writer as a contact's :func:`write_summary`)."""
    return write_summary(result, path)


def write_elements_csv(result: Any, path: str | Path) -> Path:
    """Write the per-element table (:meth:`BearingResult.element_table`) as CSV (not atomic).

    One row per element; column names carry their unit (``load_N``, ``inner_h_min_m``);
    an undefined number (excluded or failed contact) is an empty field.
    """
    import csv

    rows = result.element_table()
    path = Path(path)
    with path.open("w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh)
        cols = list(rows[0]) if rows else []
        writer.writerow(cols)
        for row in rows:
            out = []
            for c in cols:
                v = json_safe(row[c])
                out.append("" if v is None else (repr(v) if isinstance(v, float) else v))
            writer.writerow(out)
    return path


def _contact_block_points(res: Any, azimuth: float, race_radius: float, alpha: float,
                          raceway: str, element_radius: float, position: float,
                          width: float | None) -> tuple[np.ndarray, list, dict[str, np.ndarray]]:
    """3D points, cells and point data of one contact result placed on its raceway.

    The contact centre sits at the raceway radius ``race_radius`` from the bearing axis
    (z) at azimuth ``azimuth`` [rad] and axial position -+ (D_w/2) sin(alpha) (inner,
    outer); local x runs along the entrainment (the inner ring's rotation direction at
    an inner contact, against it at an outer one), local y across it in the contact
    plane. Line contacts are extruded over their length (slice width) at ``position``.
    """
    sgn = 1.0 if raceway == "inner" else -1.0
    radial = np.array([math.cos(azimuth), math.sin(azimuth), 0.0])
    tangent = np.array([-math.sin(azimuth), math.cos(azimuth), 0.0])
    axial = np.array([0.0, 0.0, 1.0])
    centre = race_radius * radial - sgn * element_radius * math.sin(alpha) * axial
    ex = sgn * tangent
    ey = math.cos(alpha) * axial + sgn * math.sin(alpha) * radial
    x = np.asarray(res.x, dtype=float)
    p = np.asarray(res.pressure, dtype=float)
    h = np.asarray(res.film, dtype=float)
    if res.y is None:
        half = 0.5 * (width or 0.0)
        ys = np.array([position - half, position + half])
        xx, yy = np.meshgrid(x, ys)
        pp = np.vstack([p, p])
        hh = np.vstack([h, h])
    else:
        y = np.asarray(res.y, dtype=float)
        xx, yy = np.meshgrid(x, y)
        pp, hh = p.reshape(xx.shape), h.reshape(xx.shape)
    pts = centre[None, :] + xx.ravel()[:, None] * ex[None, :] + yy.ravel()[:, None] * ey[None, :]
    ny, nx = xx.shape
    index = np.arange(nx * ny).reshape(ny, nx)
    quads = np.column_stack([index[:-1, :-1].ravel(), index[:-1, 1:].ravel(),
                             index[1:, 1:].ravel(), index[1:, :-1].ravel()])
    data = {"pressure_Pa": pp.ravel(), "film_m": hh.ravel()}
    return pts, [("quad", quads)], data


def _slice_suffix(spec: Any, k: int) -> str:
    """``"_slice<n>"`` of the ``k``-th scene of a profiled roller's contact, ``n`` the
    slice's number counted from one roller end, as in the warnings ("slice 6 of 11",
    :func:`bearing_fem.bearing.totals.slice_label`), also when one slice alone is loaded;
    ``""`` for a contact that is not sliced."""
    if not spec.slice_numbers:
        return ""
    return f"_slice{spec.slice_numbers[k]:02d}"


class _BearingContactSummary:
    """The summary of one contact scene of a bearing as the bearing reports it: that of
    the scene's :class:`~bearing_fem.result.Result`, but for an unsuccessful solve every
    result quantity is null (its last iterate is no result; the bearing summary's
    contacts say the same), with the status and message kept. ``result.h5`` and
    ``fields.vtu`` keep the last iterate for diagnosis."""

    def __init__(self, result: Any) -> None:
        self.result = result

    def summary(self) -> dict[str, Any]:
        out = self.result.summary()
        if self.result.success:
            return out
        for key in getattr(self.result, "quantities", {}) or {}:
            if key in out:
                out[key] = None
        for key in ("friction_coefficient", "h0", "error_estimate"):
            if key in out:
                out[key] = None
        out["note"] = ("unsuccessful solve: the result quantities are null (the last iterate "
                       "in result.h5 and fields.vtu is no result)")
        return out


def export_bearing(result: Any, outdir: str | Path) -> dict[str, Path]:
    """Write the files of a bearing result into ``outdir``, all atomically.

    Files: ``bearing_summary.json`` (:meth:`BearingResult.summary`), ``elements.csv``
    (one row per element), ``contacts.vtm`` (VTK multi-block of every successfully solved
    contact, placed on its raceway in 3D, blocks in ``contacts_vtk/``; unsuccessful ones
    are left out) and the per-contact result files (``summary.json``, ``result.h5``,
    ``fields.vtu``) of the most loaded element's contacts in
    ``contact_<element>_<raceway>[_slice<k>]/`` (``k`` the slice number from 1, as in the
    warnings; an unsuccessful contact's ``summary.json`` has its result quantities null).
    Every file is written under a temporary name first and moved into place with
    :func:`os.replace` once all are complete; on failure the temporary files are removed.

    Parameters
    ----------
    result : BearingResult
    outdir : str or Path
        Created with its parents if needed.

    Returns
    -------
    dict[str, Path]
        ``summary``, ``elements``, ``vtm``, and ``contact_<element>_<raceway>...`` ->
        the directory of each exported contact.
    """
    import meshio

    outdir = Path(outdir)
    made: list[Path] = []  # directories this export created (removed again on failure)

    def make_dir(d: Path) -> None:
        missing = [q for q in (d, *d.parents) if not q.exists()]
        d.mkdir(parents=True, exist_ok=True)
        made.extend(reversed(missing))

    make_dir(outdir)
    stages: list[_Staging] = []

    def stage(d: Path) -> _Staging:
        make_dir(d)
        st = _Staging(d)
        stages.append(st)
        return st

    files: dict[str, Path] = {}
    try:
        top = stage(outdir)
        write_bearing_summary(result, top.temp(BEARING_FILES["summary"]))
        files["summary"] = outdir / BEARING_FILES["summary"]
        if result.elements:
            write_elements_csv(result, top.temp(BEARING_FILES["elements"]))
            files["elements"] = outdir / BEARING_FILES["elements"]
        # VTK multi-block of every solved contact
        blocks = []
        if result.contacts and result.distribution is not None:
            vtk = stage(outdir / BEARING_VTK_DIR)
            dist = result.distribution
            r_el = 0.5 * result.bearing.geometry.element_diameter
            for spec in result.specs:
                for k, key in enumerate(spec.keys):
                    res = result.contacts[key]
                    if not res.success:  # its last iterate is no result: not a block
                        continue
                    name = f"element_{spec.element:03d}_{spec.raceway}" + _slice_suffix(spec, k)
                    pts, cells, data = _contact_block_points(
                        res, float(dist.azimuth[spec.element]), spec.race_radius,
                        spec.contact_angle, spec.raceway, r_el,
                        spec.positions[k] if spec.positions else 0.0,
                        spec.widths[k] if spec.widths else None)
                    tmp = vtk.temp(name + ".vtu")
                    meshio.write(str(tmp), meshio.Mesh(pts, cells, point_data=data),
                                 file_format="vtu")
                    blocks.append(name)
            lines = ['<?xml version="1.0"?>',
                     '<VTKFile type="vtkMultiBlockDataSet" version="1.0" '
                     'byte_order="LittleEndian">', "  <vtkMultiBlockDataSet>"]
            for i, name in enumerate(blocks):
                lines.append(f'    <DataSet index="{i}" name="{name}" '
                             f'file="{BEARING_VTK_DIR}/{name}.vtu"/>')
            lines += ["  </vtkMultiBlockDataSet>", "</VTKFile>"]
            top.temp(BEARING_FILES["vtm"]).write_text("\n".join(lines) + "\n",
                                                       encoding="utf-8")
            files["vtm"] = outdir / BEARING_FILES["vtm"]
            # per-contact files of the most loaded element
            j = result.most_loaded_element()
            for race in ("inner", "outer"):
                spec = result.contact_spec(j, race)
                for k, key in enumerate(spec.keys):
                    name = f"contact_{j:03d}_{race}" + _slice_suffix(spec, k)
                    st = stage(outdir / name)
                    res = result.contacts[key]
                    write_summary(_BearingContactSummary(res), st.temp(FILES["summary"]))
                    write_h5(res, st.temp(FILES["h5"]))
                    write_vtu(res, st.temp(FILES["vtu"]))
                    files[name] = outdir / name
        for st in stages:
            st.commit()
    except BaseException:
        for st in stages:
            st.discard()
        for d in reversed(made):  # innermost first; only what is empty again
            try:
                d.rmdir()
            except OSError:
                pass
        raise
    return files

"""Fixed reference cases for comparing versions and machines (``bearing-fem bench``).

Each case is solved ``repeats`` times, interleaved with the other cases, and the minimum
wall time is kept (the machine may be shared: the 1-minute load average before and after
is recorded). The cases are fixed so that two reports, from two versions of the package
or two machines, compare case by case:

* ``line``: elastic line contact at Moes M = 100, L = 10 (R = 10 mm, E' = 2.2e11 Pa,
  alpha = 2e-8 1/Pa, eta0 = 0.01 Pa s, pure rolling), default grid;
* ``point``: the circular contact at the same Moes groups, default grid;
* ``thermal``: a sliding half-space roller (w = 2e5 N/m, R = 10 mm, eta0 = 0.05 Pa s,
  u1 = 2.2, u2 = 1.8 m/s) with the thermal patch (oil 60 deg C, Prokofiev n = 2.93) and
  Eyring traction, default grid;
* ``bearing_6209``: :func:`bearing_fem.solve_bearing` on the shipped 6209 example, on
  65 x 65 contact grids in quick mode and on the default grids otherwise.

No printing here: :func:`run_bench` returns a dict, :func:`format_table` a string, and the
command line (``bearing-fem bench``, ``bearing_fem.cli``) prints and writes the JSON. The
work-precision study (``studies/work_precision.py``, ``docs/performance.md``) says what
accuracy these settings buy.
"""
from __future__ import annotations

import errno
import json
import os
import platform
import time
from dataclasses import replace
from pathlib import Path
from typing import Any, Callable

import numpy as np

from . import units
from .bearing import load_example, solve_bearing
from .contacts.dispatch import solve
from .result import json_safe
from .scene import (Contact, Kinematics, Load, Lubricant, Materials, Model, Scene, Thermal,
                    Traction)
from .version import VERSION

#: Contact grid (nodes per direction) of the bearing case in quick mode.
QUICK_BEARING_NODES = 65
#: Repetitions per case (the minimum time is reported).
REPEATS = {True: 2, False: 3}
#: Columns of the table: key, header, format.
COLUMNS = (("case", "case", "s"), ("time_s", "time s", ".3f"),
           ("newton_iterations", "Newton it.", "d"), ("status", "status", "s"),
           ("h_central", "h_central m", ".4e"), ("error_estimate", "error est.", ".1e"))


def moes_line_scene(M: float = 100.0, L: float = 10.0) -> Scene:
    """Elastic line contact realising the Moes groups (M, L) (default grid).

    Parameters
    ----------
    M, L : float
        Moes load and material groups [-].

    Returns
    -------
    Scene
    """
    par = units.line_scene_from_moes(M, L)
    u = par["mean_speed"]
    return Scene(title=f"bench line M={M:g} L={L:g}",
                 contact=Contact(kind="line", rx=par["radius"]),
                 materials=Materials(reduced_modulus=par["e_prime"]),
                 lubricant=Lubricant(viscosity=par["viscosity"], piezo=par["piezo"]),
                 kinematics=Kinematics(u1=u, u2=u), load=Load(force=par["load_per_length"]))


def moes_point_scene(M: float = 100.0, L: float = 10.0) -> Scene:
    """Elastic circular contact (rx = ry = 10 mm) realising (M, L) (default grid).

    Parameters
    ----------
    M, L : float
        Moes load and material groups [-].

    Returns
    -------
    Scene
    """
    d = units.point_scene_parameters_from_moes(M, L, rx=0.01, ry=0.01)
    u = d["mean_speed"]
    return Scene(title=f"bench point M={M:g} L={L:g}",
                 contact=Contact(kind="point", rx=d["rx"], ry=d["ry"]),
                 materials=Materials(reduced_modulus=d["e_prime"]),
                 lubricant=Lubricant(viscosity=d["viscosity"], piezo=d["piezo"]),
                 kinematics=Kinematics(u1=u, u2=u), load=Load(force=d["force"]))


def thermal_line_scene() -> Scene:
    """Sliding half-space roller with the thermal patch and Eyring traction.

    Returns
    -------
    Scene
    """
    return Scene(title="bench thermal line", contact=Contact(kind="line", rx=0.01, length=0.02),
                 materials=Materials(e1=2.1e11, nu1=0.3, e2=2.1e11, nu2=0.3),
                 lubricant=Lubricant(viscosity=0.05, piezo=2e-8),
                 kinematics=Kinematics(u1=2.2, u2=1.8), load=Load(force=2e5),
                 model=Model(thermal="patch"),
                 thermal=Thermal(oil_temperature=60.0, exponent=2.93),
                 traction=Traction(model="eyring"))


def _contact_row(scene: Scene) -> dict[str, Any]:
    s = solve(scene).summary()
    est = s.get("error_estimate") or {}
    return {"status": s["status"], "success": bool(s["success"]),
            "newton_iterations": int(s.get("newton_iterations") or 0),
            "h_central": s.get("h_central"), "h_min": s.get("h_min"), "p_max": s.get("p_max"),
            "error_estimate": est.get("h_central"), "dofs": int(s["dofs"])}


def _bearing_row(nodes: int | None) -> dict[str, Any]:
    b = load_example("6209")
    if nodes is not None:
        b = replace(b, mesh=replace(b.mesh, point_nodes=(nodes, nodes)))
    r = solve_bearing(b)
    contacts = [c.summary() for c in r.contacts.values()]
    ests = [(c.get("error_estimate") or {}).get("h_central") for c in contacts]
    row: dict[str, Any] = {
        "status": r.status, "success": bool(r.success),
        "newton_iterations": int(sum(c.get("newton_iterations") or 0 for c in contacts)),
        "dofs": int(sum(c["dofs"] for c in contacts)), "h_central": None, "h_min": None,
        "p_max": None, "error_estimate": max((e for e in ests if e is not None), default=None),
        "contact_nodes": nodes}
    if r.success:
        j = int(np.argmax([e["load"] for e in r.elements]))
        row.update(h_central=r.elements[j]["inner"]["h_central"], h_min=r.totals["h_min"],
                   p_max=r.totals["p_max"], friction_torque=r.totals["friction_torque"],
                   heat_power=r.totals["heat_power"])
    return row


def cases(quick: bool) -> dict[str, Callable[[], dict[str, Any]]]:
    """The reference cases: name -> a function solving it and returning its row.

    Parameters
    ----------
    quick : bool
        Coarse contact grids for the bearing case.

    Returns
    -------
    dict
        Case name -> a function without arguments that solves it and returns its row.
    """
    line, point, thermal = moes_line_scene(), moes_point_scene(), thermal_line_scene()
    bearing_nodes = QUICK_BEARING_NODES if quick else None
    return {"line": lambda: _contact_row(line), "point": lambda: _contact_row(point),
            "thermal": lambda: _contact_row(thermal),
            "bearing_6209": lambda: _bearing_row(bearing_nodes)}


def cpu_model() -> str | None:
    """The CPU's model name (``/proc/cpuinfo`` on Linux, where ``platform.processor()``
    is empty; ``platform.processor()`` elsewhere), or None when unknown."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8", errors="replace") as fh:
            for line in fh:
                key, _, value = line.partition(":")
                if key.strip() in ("model name", "Model", "cpu model", "Hardware") \
                        and value.strip():
                    return value.strip()
    except OSError:
        pass
    return platform.processor() or None


def machine_info() -> dict[str, Any]:
    """The machine and software a bench ran on.

    Returns
    -------
    dict
        ``platform``, ``machine`` (architecture), ``processor``, ``cpu_model`` (the CPU's
        model name, None when unknown), ``cpu_count``, ``python``, ``numpy``, ``scipy``.
    """
    import scipy

    return {"platform": platform.platform(), "machine": platform.machine(),
            "processor": platform.processor(), "cpu_model": cpu_model(),
            "cpu_count": os.cpu_count(), "python": platform.python_version(),
            "numpy": np.__version__, "scipy": scipy.__version__}


def run_bench(quick: bool = False, repeats: int | None = None,
              progress: Callable[[str, int, dict], None] | None = None) -> dict[str, Any]:
    """Solve the reference cases and return the report.

    Parameters
    ----------
    quick : bool
        Coarse bearing contact grids and two repetitions (about 6 s on 2 idle cores).
    repeats : int, optional
        Repetitions per case (default 2 quick, 3 full); the minimum time is reported.
        ValueError unless a whole number >= 1.
    progress : callable, optional
        ``progress(case, repetition, row)`` after each solve.

    Returns
    -------
    dict
        ``version``, ``timestamp`` (UTC, ISO 8601), ``quick``, ``repeats``, ``machine``
        (:func:`machine_info`), ``load_average`` (1-minute, before and after) and ``cases``:
        one row per case with ``case``, ``time_s`` (minimum), ``times_s`` (all),
        ``newton_iterations``, ``status``, ``success``, ``h_central`` [m], ``h_min`` [m],
        ``p_max`` [Pa], ``error_estimate`` (relative, of h_central; the largest over the
        bearing's contacts) and ``dofs``.
    """
    n = repeats if repeats is not None else REPEATS[bool(quick)]
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"repeats must be a whole number of runs >= 1, got {n!r}")
    n = int(n)
    jobs = cases(quick)
    load0 = os.getloadavg()[0]
    rows: dict[str, dict[str, Any]] = {}
    for rep in range(n):
        for name, job in jobs.items():
            t0 = time.perf_counter()
            row = job()
            dt = time.perf_counter() - t0
            prev = rows.get(name)
            row["case"] = name
            row["times_s"] = (prev["times_s"] if prev else []) + [dt]
            row["time_s"] = min(row["times_s"])
            rows[name] = row
            if progress is not None:
                progress(name, rep, row)
    return {"version": VERSION, "timestamp": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
            "quick": bool(quick), "repeats": n, "machine": machine_info(),
            "load_average": [load0, os.getloadavg()[0]], "cases": list(rows.values())}


def format_table(report: dict[str, Any]) -> str:
    """The report as a fixed-width text table.

    Parameters
    ----------
    report : dict
        A report of :func:`run_bench`.

    Returns
    -------
    str
        One line per case (time [s], Newton iterations, status, h_central [m], relative
        error estimate), then a line naming the version, the machine and the load average.
    """
    def cell(v: Any, fmt: str) -> str:
        if v is None:
            return "-"
        return format(v, fmt)

    head = [h for _, h, _ in COLUMNS]
    body = [[cell(r.get(k), f) for k, _, f in COLUMNS] for r in report["cases"]]
    widths = [max(len(h), *(len(b[i]) for b in body)) for i, h in enumerate(head)]
    lines = ["  ".join(h.ljust(w) for h, w in zip(head, widths))]
    lines += ["  ".join(c.ljust(w) for c, w in zip(b, widths)) for b in body]
    m = report["machine"]
    la = report["load_average"]
    cpu = f"{m['cpu_model']}, " if m.get("cpu_model") else ""
    lines.append(f"bearing_fem {report['version']}, {m['platform']}, {cpu}{m['cpu_count']} CPUs, "
                 f"Python {m['python']}, numpy {m['numpy']}, scipy {m['scipy']}; "
                 f"min of {report['repeats']} interleaved runs; load average "
                 f"{la[0]:.2f} -> {la[1]:.2f}")
    return "\n".join(lines)


def write_json(report: dict[str, Any], path: str | Path) -> Path:
    """Write the report as strict JSON (via a temporary name and ``os.replace``).

    Parameters
    ----------
    report : dict
        A report of :func:`run_bench`; non-finite numbers are written as ``null``.
    path : str or Path
        The JSON file (not a directory).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    OSError
        The file cannot be written (``path`` is a directory, its folder does not exist,
        ...); no temporary file is left behind.
    """
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(errno.EISDIR, "is a directory, not a file", str(path))
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        tmp.write_text(json.dumps(json_safe(report), indent=1, allow_nan=False) + "\n",
                       encoding="utf-8")
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path

"""Rigid transient squeeze of a point contact: h0(t) = h0 (1 + eps cos(omega t)).

The rigid incompressible Reynolds equation has no memory (no dv/dt, no d(rho)/dt), so
each instant is the quasi-steady wedge + squeeze problem at the gap h0(t) with the
source dh0/dt, solved on the linear (reduced-pressure) path. Elastic series, whose
pressure does have memory, are in :mod:`bearing_fem.contacts.transient`. Series are
written to files by :func:`bearing_fem.io.export_series` (VTU + PVD, XDMF/HDF5).
"""
from __future__ import annotations

import math
import re
import time
from dataclasses import dataclass
from dataclasses import replace as dc_replace
from typing import Any, Callable

import numpy as np

from ..errors import SceneError
from ..result import SUCCESS_STATUSES, number_or_none
from ..scene import Scene
from ..validation import require_finite
from ..version import VERSION
from .driver import solve_linear_model
from .point import PointModel, is_linear


@dataclass
class SqueezeSeries:
    """Rigid transient squeeze series h0(t) = h0 (1 + eps cos(omega t)) (docs/theory.md: Kapitsa's squeeze solution).

    Attributes
    ----------
    times : ndarray
        t [s].
    gap : ndarray
        h0(t) [m].
    squeeze_velocity : ndarray
        dh0/dt = -h0 eps omega sin(omega t) [m/s].
    p_max : ndarray
        Maximum pressure of each step [Pa] (``inf`` for a step without solution).
    results : list of Result
        One quasi-steady solve per step, all on the same grid.
    scene : Scene or None
        The scene of the series (``load.gap`` = the mean offset h0).
    stop : (str, str) or None
        (status, message) when the series stopped before its last instant
        (``solver.time_limit`` reached); the arrays cover the solved instants.
    """

    times: np.ndarray
    gap: np.ndarray
    squeeze_velocity: np.ndarray
    p_max: np.ndarray
    results: list
    scene: Any = None
    stop: tuple[str, str] | None = None

    #: A warning of the whole series when its instants carry no error estimate (each
    #: rigid instant has its own; the elastic series overrides this).
    ESTIMATE_NOTE = ""

    @property
    def statuses(self) -> list[str]:
        return [r.status for r in self.results]

    @property
    def status(self) -> str:
        """``linear`` when every instant was solved, else the first failed instant's, or
        ``time_limit`` when the series stopped early."""
        failed = next((st for st in self.statuses if st not in SUCCESS_STATUSES), None)
        if failed is not None:
            return failed
        return self.stop[0] if self.stop is not None else "linear"

    @property
    def success(self) -> bool:
        return self.status in SUCCESS_STATUSES

    @property
    def message(self) -> str:
        failed = [k for k, r in enumerate(self.results) if not r.success]
        if not failed:
            if self.stop is not None:
                return self.stop[1]
            return (f"{len(self.results)} instants of the rigid squeeze solved on the linear "
                    "path (no memory: each instant on its own)")
        r = self.results[failed[0]]
        return (f"{len(failed)} of {len(self.results)} instants without solution, the first "
                f"at t = {self.times[failed[0]]:.6g} s: {r.message}")

    def summary(self) -> dict[str, Any]:
        """The series as a dict of lists (SI): status, success, message, the time and gap
        of every instant with p_max, h_min, h_central and load (None where an instant has
        no solution), iteration and time totals, warnings, units, version, scene."""
        def column(key: str) -> list:
            return [number_or_none(r.quantities.get(key)) if r.success else None
                    for r in self.results]

        warnings = series_warnings(self.times, self.results)
        if self.ESTIMATE_NOTE and self.results:
            warnings.append(self.ESTIMATE_NOTE)
        return {
            "status": self.status, "success": bool(self.success), "message": self.message,
            "kind": "squeeze series", "scheme": getattr(self, "scheme", "quasi-steady"),
            "instants": len(self.results),
            "times": [float(t) for t in self.times], "gap": [float(g) for g in self.gap],
            "squeeze_velocity": [float(v) for v in self.squeeze_velocity],
            "p_max": column("p_max"), "h_min": column("h_min"),
            "h_central": column("h_central"), "load": column("load"),
            "newton_iterations": int(sum(r.newton_iterations for r in self.results)),
            "linear_solves": int(sum(r.linear_solves for r in self.results)),
            "wall_time_s": float(sum(r.wall_time_s for r in self.results)),
            "warnings": warnings,
            "units": {"times": "s", "gap": "m", "squeeze_velocity": "m/s", "p_max": "Pa",
                      "h_min": "m", "h_central": "m", "load": "N", "wall_time_s": "s"},
            "version": VERSION,
            "scene": None if self.scene is None else self.scene.to_dict(),
        }


#: A number in a warning's text (1, 0.5, 3.15e-07, 1.93%).
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def series_warnings(times: np.ndarray, results: list) -> list[str]:
    """The warnings of a series' instants, each kind once.

    Warnings that differ only in their numbers (the same finding at several instants,
    e.g. an unresolved outlet constriction) are one entry: the first instant's text, its
    time and the number of instants that have it.

    Parameters
    ----------
    times : ndarray
        t [s] of each instant.
    results : list of Result
        One per instant, in the order of ``times``.

    Returns
    -------
    list of str
    """
    groups: dict[str, list] = {}
    for t, r in zip(times, results):
        for w in r.warnings:
            key = _NUMBER.sub("#", w)
            if key in groups:
                groups[key][2] += 1
                groups[key][3] = groups[key][3] or w != groups[key][0]
            else:
                groups[key] = [w, float(t), 1, False]
    n = len(results)
    return [first if not differ else
            f"{first} (at t = {t:.6g} s; {count} of {n} instants, with their own numbers)"
            for first, t, count, differ in groups.values()]


def solve_squeeze_series(scene: Scene, eps: float = 0.3, omega: float | None = None,
                         times: np.ndarray | None = None, n_steps: int = 16, *,
                         boundary_pressure: Callable | None = None) -> SqueezeSeries:
    """Quasi-steady rigid series for h0(t) = h0 (1 + eps cos(omega t)).

    Each step solves the rigid wedge + squeeze problem with the gap h0(t) and the
    squeeze source dh0/dt = -h0 eps omega sin(omega t) (the film has no memory in the
    rigid incompressible Reynolds equation, so the steps are independent). All steps use
    the grid of the mean gap h0, so the series exports on one mesh.

    Parameters
    ----------
    scene : Scene
        Rigid point scene with a prescribed gap (``load.gap`` = h0, the mean) and a
        linear lubricant law (incompressible; constant or Barus, or Roelands with
        Reynolds cavitation).
    eps : float
        Relative amplitude [-], 0 <= eps < 1.
    omega : float, optional
        Angular frequency [rad/s]; default u_m / sqrt(2 rx h0) (one hydrodynamic length
        per period/(2 pi)).
    times : array, optional
        Instants [s]; default ``n_steps`` instants over one period.
    n_steps : int
        Used when ``times`` is None.
    boundary_pressure : callable, optional
        ``(x, y, t) -> p`` Dirichlet data [Pa] (default 0).

    Returns
    -------
    SqueezeSeries
    """
    if scene.contact.kind != "point":
        raise SceneError(f"solve_squeeze_series needs contact.kind = 'point', got "
                         f"{scene.contact.kind!r}")
    if not is_linear(scene):
        raise SceneError("solve_squeeze_series needs a rigid, incompressible scene with "
                         "load.gap (m) and a constant or Barus viscosity law (or Roelands with "
                         "Reynolds cavitation)")
    eps = float(eps)
    if not 0.0 <= eps < 1.0:
        raise ValueError(f"eps must lie in [0, 1) (dimensionless), got {eps!r}")
    h0 = scene.load.gap
    if omega is None:
        omega = scene.kinematics.mean_speed / math.sqrt(2 * scene.contact.rx * h0)
    omega = float(omega)
    if not (math.isfinite(omega) and omega > 0.0):
        raise ValueError(f"omega must be > 0 rad/s, got {omega!r}")
    if times is None:
        if not isinstance(n_steps, int) or n_steps < 1:
            raise ValueError(f"n_steps must be a positive integer, got {n_steps!r}")
        times = np.arange(n_steps) * (2 * math.pi / omega) / n_steps
    times = np.atleast_1d(require_finite("times", times, "s")).ravel()
    gaps = h0 * (1.0 + eps * np.cos(omega * times))
    rates = -h0 * eps * omega * np.sin(omega * times)
    results = []
    limit = scene.solver.time_limit          # for the whole series [s]
    start = time.perf_counter()
    stop = None
    for k, (t, g, r) in enumerate(zip(times, gaps, rates)):
        elapsed = time.perf_counter() - start
        if k > 0 and limit is not None and elapsed >= limit:
            stop = ("time_limit", f"time_limit: the series stopped after {k} of {times.size} "
                                  f"instants, {elapsed:.3g} s of a time limit of {limit:.3g} s "
                                  "(solver.time_limit applies to the whole series)")
            times, gaps, rates = times[:k], gaps[:k], rates[:k]
            break
        sc = dc_replace(scene, load=dc_replace(scene.load, gap=float(g)))
        bp = None if boundary_pressure is None else (
            lambda x, y, _t=t: boundary_pressure(x, y, _t))
        t0 = time.perf_counter()
        model = PointModel(sc, bp, float(r), grid_scene=scene)
        res = solve_linear_model(model, sc, t0)
        results.append(res)
    p_max = np.array([r.quantities.get("p_max", np.inf) if r.success else np.inf
                      for r in results])
    return SqueezeSeries(times, gaps, rates, p_max, results, scene, stop)


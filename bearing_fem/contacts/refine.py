"""Solving a contact again on finer grids: ``[mesh] target_error``.

Every elastic solve reports the estimated relative discretisation error of its main
quantities (``Result.error_estimate``, docs/accuracy.md). With ``mesh.target_error`` the
user asks for a bound on it: a contact whose estimated error of friction force, heat
power, h_min or h_central exceeds the target (or that has no estimate of one of them) is
solved again on the grid of half the spacing (2 n - 1 nodes per direction), until the
target is met or the next grid would exceed :data:`TARGET_ERROR_MAX_POINT_NODES` per
direction (points) or :data:`TARGET_ERROR_MAX_LINE_NODES` (lines). p_max is not held to
the target: at the outlet spike of heavily loaded contacts it converges slowly or not at
all.

The grid helpers here are shared with the bearing solver, which applies the same rule to
every rolling-element contact (and one more, for thin ball films).
"""
from __future__ import annotations

import time
from dataclasses import replace
from typing import Any, Callable

import numpy as np

from ..scene import Scene

__all__ = ["TARGET_ERROR_QUANTITIES", "TARGET_ERROR_MAX_POINT_NODES",
           "TARGET_ERROR_MAX_LINE_NODES", "grid_nodes", "grid_label", "finer_grid",
           "target_errors", "misses_target", "target_grid_cap", "hold_target_error"]

#: The quantities ``mesh.target_error`` applies to (p_max is left out: at the outlet
#: spike of heavily loaded contacts it converges slowly or not at all, docs/accuracy.md).
TARGET_ERROR_QUANTITIES = ("friction_force", "heat_power", "h_min", "h_central")
#: Finest grid a ``target_error`` refinement reaches: nodes per direction of a point
#: contact (513^2 costs 10-17 s per heavily loaded ball contact) ...
TARGET_ERROR_MAX_POINT_NODES = 513
#: ... and nodes of a line contact (twice the cap of the default line grids: the dense
#: compliance's memory grows as N^2, 0.5 GB at 8001 nodes; an 8001-node solve of the
#: line map's M = 1000 cases took about 6 s, ``studies/target_error.py``).
TARGET_ERROR_MAX_LINE_NODES = 8001


def grid_nodes(result: Any) -> tuple[int, ...]:
    """The node counts of a contact result's grid: (n,) for a line, (nx, ny) for a point."""
    return (result.x.size,) if result.y is None else (result.x.size, result.y.size)


def grid_label(nodes: tuple[int, ...] | int) -> str:
    """Node counts as written in messages: "801", "129x129"."""
    return "x".join(str(n) for n in np.atleast_1d(nodes))


def finer_grid(scene: Scene, result: Any) -> tuple[Scene, int | tuple[int, int]]:
    """``scene`` on the grid of half the spacing of ``result`` (2 n - 1 nodes per
    direction), and those nodes (an int for a line, (nx, ny) for a point)."""
    nodes = tuple(2 * n - 1 for n in grid_nodes(result))
    nodes = nodes[0] if len(nodes) == 1 else nodes
    return replace(scene, mesh=replace(scene.mesh, nodes=nodes, file=None)), nodes


def target_errors(result: Any) -> list[float | None]:
    """A result's estimates of :data:`TARGET_ERROR_QUANTITIES` [-] (None where unknown)."""
    est = result.error_estimate or {}
    return [est.get(q) for q in TARGET_ERROR_QUANTITIES]


def misses_target(result: Any, target: float) -> bool:
    """An estimate of :data:`TARGET_ERROR_QUANTITIES` is above ``target`` [-], or
    unknown."""
    return any(e is None or e > target for e in target_errors(result))


def target_grid_cap(result: Any) -> int:
    """The finest grid a ``target_error`` refinement of ``result``'s contact may reach:
    nodes per direction."""
    return TARGET_ERROR_MAX_LINE_NODES if result.y is None else TARGET_ERROR_MAX_POINT_NODES


def hold_target_error(scene: Scene, result: Any,
                      solve: Callable[[Scene], Any]) -> Any:
    """Solve ``scene`` again on grids of half the spacing until its estimated errors meet
    ``scene.mesh.target_error``.

    The scene's ``[solver]`` budget covers every solve together: each finer solve gets
    the Newton iterations and the wall-clock time (``solver.time_limit``) the solves
    before it left. The first solve's result is refined only when it succeeded.

    Parameters
    ----------
    scene : Scene
        With ``mesh.target_error`` [-] set.
    result : Result
        Its solve on the scene's own grid.
    solve : callable
        ``solve(scene) -> Result`` for the finer scenes (the same path as the first).

    Returns
    -------
    Result
        The result on the finest grid that succeeded, with ``scene`` (the user's scene),
        ``refinement`` (``{"target_error", "grids", "met", "newton_iterations",
        "wall_time_s"}``: the grids solved, coarse to fine, whether every estimate
        meets the target, and the Newton iterations and seconds of all solves together),
        ``wall_time_s`` of all solves, and a warning when the target is not met (which
        says why: the cap, a failed solve, the budget or the time limit).
    """
    target = scene.mesh.target_error
    start = time.perf_counter() - result.wall_time_s
    spent = result.newton_iterations
    grids = [grid_label(grid_nodes(result))]
    best, why = result, None
    while best.success and misses_target(best, target):
        finer, nodes = finer_grid(scene, best)
        label = grid_label(nodes)
        if max(np.atleast_1d(nodes)) > target_grid_cap(best):
            why = f"the next grid, {label}, would exceed the cap of {_cap_label(best)}"
            break
        budget = scene.solver.iteration_budget - spent
        left = (None if scene.solver.time_limit is None
                else scene.solver.time_limit - (time.perf_counter() - start))
        if budget < 1 or (left is not None and left <= 0.0):
            why = (f"solver.iteration_budget ({scene.solver.iteration_budget} Newton "
                   f"iterations) is spent" if budget < 1 else
                   f"solver.time_limit ({scene.solver.time_limit:g} s) is reached")
            break
        res = solve(replace(finer, solver=replace(finer.solver, iteration_budget=budget,
                                                  time_limit=left)))
        spent += res.newton_iterations
        grids.append(label)
        if not res.success:
            why = f"the solve on {label} nodes did not succeed ({res.status})"
            break
        best = res
    if not best.success:
        return best
    met = not misses_target(best, target)
    best.scene = scene
    best.wall_time_s = time.perf_counter() - start
    best.refinement = {"target_error": target, "grids": grids, "met": met,
                       "newton_iterations": spent, "wall_time_s": best.wall_time_s}
    if not met:
        worst = max((e for e in target_errors(best) if e is not None), default=None)
        largest = ("no estimate of one of them" if worst is None
                   else f"the largest estimate is {100 * worst:.2g} %")
        best.warnings.append(
            f"mesh.target_error = {target:g} is not met on "
            f"{grid_label(grid_nodes(best))} nodes ({largest} of friction_force, "
            f"heat_power, h_min and h_central): {why}; the results are those on "
            f"{grid_label(grid_nodes(best))} nodes")
    return best


def _cap_label(result: Any) -> str:
    cap = target_grid_cap(result)
    return f"{cap} nodes" if result.y is None else f"{cap}x{cap} nodes"

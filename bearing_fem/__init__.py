"""bearing_fem: finite-element Reynolds-elasticity solver for rolling-bearing contacts.

Public API (see ``docs/api.md``)::

    import bearing_fem as bf
    scene = bf.Scene.from_toml("scene.toml")
    result = bf.solve(scene)
    bf.export(result, "out/")

Sub-modules are imported lazily so a scene only pays for what it uses
(no thermal patch for an isothermal scene, no pyvista unless plotting).
"""
from __future__ import annotations

import importlib
from typing import Any

from .version import VERSION as __version__

_LAZY = {
    "Scene": ("bearing_fem.scene", "Scene"),
    "SceneError": ("bearing_fem.errors", "SceneError"),
    "solve": ("bearing_fem.contacts.dispatch", "solve"),
    "solve_series": ("bearing_fem.contacts.dispatch", "solve_series"),
    "Result": ("bearing_fem.result", "Result"),
    "export": ("bearing_fem.io", "export"),
    "Bearing": ("bearing_fem.bearing", "Bearing"),
    "solve_bearing": ("bearing_fem.bearing", "solve_bearing"),
    "sweep": ("bearing_fem.sweep", "sweep"),
}
#: Short attribute names of the modules (``bf.kodnir.solve(...)``,
#: ``bf.thermal.strip_source(...)``), imported on first use.
_SUBMODULES = {
    "analytic": "analytic", "formulas": "formulas", "units": "units", "scene": "scene",
    "result": "result", "errors": "errors", "post": "post", "io": "io", "plot": "plot",
    "bearing": "bearing", "physics": "physics", "numerics": "numerics",
    "contacts": "contacts", "rheology": "physics.rheology", "reynolds": "physics.reynolds",
    "elasticity": "physics.elasticity", "traction": "physics.traction",
    "thermal": "physics.thermal", "newton": "numerics.newton", "line": "contacts.line",
    "point": "contacts.point", "kodnir": "contacts.kodnir",
    "transient": "contacts.transient", "coupling": "contacts.coupling",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        mod, attr = _LAZY[name]
        return getattr(importlib.import_module(mod), attr)
    if name in _SUBMODULES:
        return importlib.import_module(f"bearing_fem.{_SUBMODULES[name]}")
    raise AttributeError(f"module 'bearing_fem' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(list(globals()) + list(_LAZY) + list(_SUBMODULES))

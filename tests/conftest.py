"""Shared test helpers."""
from __future__ import annotations

import dataclasses
import importlib.util
from pathlib import Path
from types import ModuleType
from typing import Callable

import pytest

STUDIES = Path(__file__).resolve().parents[1] / "studies"


@pytest.fixture
def load_study() -> Callable[[str], ModuleType]:
    """Import ``studies/<name>.py`` as a module (the studies are scripts, not a package)."""

    def load(name: str) -> ModuleType:
        spec = importlib.util.spec_from_file_location(name, STUDIES / f"{name}.py")
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        return mod

    return load



@pytest.fixture
def far_field_on_given_domain(monkeypatch) -> Callable[[], None]:
    """A call that lets point scenes with a given ``mesh.x_range``/``mesh.y_range`` take
    Kapitsa's far field on their edges from then on, as the default domain does (a given
    range otherwise keeps p = 0): the wider reference domains that check the default
    domain's far field need it."""
    import bearing_fem.contacts.point as point

    original = point.far_field_applies

    def applies(scene, grid) -> bool:
        mesh = dataclasses.replace(scene.mesh, x_range=None, y_range=None)
        return original(dataclasses.replace(scene, mesh=mesh), grid)

    return lambda: monkeypatch.setattr(point, "far_field_applies", applies)

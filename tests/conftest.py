"""Shared test helpers."""
from __future__ import annotations

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

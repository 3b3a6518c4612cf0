"""Exceptions of bearing_fem."""
from __future__ import annotations


class SceneError(ValueError):
    """Invalid scene input. The message names the field, the value and the unit."""


class SolveError(RuntimeError):
    """Raised by :meth:`bearing_fem.result.Result.raise_for_status` for an unsuccessful solve."""

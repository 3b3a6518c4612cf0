"""Argument checks shared by the whole package.

Each check raises an error (``ValueError`` by default; scene and bearing files use
:class:`~bearing_fem.errors.SceneError`) that names the argument, the value -- shortened,
so that a huge input never becomes a huge message -- and the unit. Scalars come back as
floats, arrays as float arrays.
"""
from __future__ import annotations

from typing import Any

import numpy as np

#: Longest rendering of a bad value in a message [characters].
MAX_SHOWN = 60


def shown(value: Any) -> str:
    """``repr(value)``, cut to :data:`MAX_SHOWN` characters (an integer too long to print
    is described by its size)."""
    try:
        text = repr(value)
    except ValueError:  # int beyond sys.get_int_max_str_digits()
        return f"an integer of about {int(value.bit_length() * 0.30103) + 1} digits"
    return text if len(text) <= MAX_SHOWN else text[:MAX_SHOWN - 15] + f"... ({len(text)} chars)"


def _as_float(name: str, value: Any, unit: str, error: type[Exception]) -> Any:
    if isinstance(value, (bool, np.bool_, str, bytes)):  # "1e8" is a unit slip or a typo
        raise error(f"{name} must be a number in {unit}, got {shown(value)}")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise error(f"{name} must be a number in {unit}, got {shown(value)}") from None
    if arr.size == 0 or not np.all(np.isfinite(arr)):
        raise error(f"{name} must be finite ({unit}), got {shown(value)}")
    return arr


def _out(arr: np.ndarray) -> Any:
    return float(arr) if arr.ndim == 0 else arr


def require_finite(name: str, value: Any, unit: str, *,
                   error: type[Exception] = ValueError) -> Any:
    """``value`` as float(s), or ``error`` unless every value is a finite number."""
    return _out(_as_float(name, value, unit, error))


def require_positive(name: str, value: Any, unit: str, *,
                     error: type[Exception] = ValueError) -> Any:
    """``value`` as float(s), or ``error`` unless every value is finite and > 0."""
    arr = _as_float(name, value, unit, error)
    if np.any(arr <= 0.0):
        raise error(f"{name} must be > 0 {unit}, got {shown(value)}")
    return _out(arr)


def require_nonnegative(name: str, value: Any, unit: str, *,
                        error: type[Exception] = ValueError) -> Any:
    """``value`` as float(s), or ``error`` unless every value is finite and >= 0."""
    arr = _as_float(name, value, unit, error)
    if np.any(arr < 0.0):
        raise error(f"{name} must be >= 0 {unit}, got {shown(value)}")
    return _out(arr)


def require_poisson(name: str, value: Any, *, error: type[Exception] = ValueError) -> float:
    """A Poisson ratio in (-1, 0.5], or ``error``."""
    v = require_finite(name, value, "(dimensionless)", error=error)
    if not -1.0 < v <= 0.5:
        raise error(f"{name} must lie in (-1, 0.5] (dimensionless), got {shown(value)}")
    return v


def require_int(name: str, value: Any, lo: int, hi: int | None = None, *, what: str = "count",
                error: type[Exception] = ValueError) -> int:
    """An integer in [lo, hi] (``what`` names its meaning in the message), or ``error``."""
    ok = not isinstance(value, (bool, np.bool_)) and isinstance(value, (int, np.integer))
    if not ok and isinstance(value, (float, np.floating)) and float(value).is_integer():
        ok = True
    if not ok or value < lo or (hi is not None and value > hi):
        bound = f">= {lo}" if hi is None else f"in [{lo}, {hi}]"
        raise error(f"{name} must be an integer {bound} ({what}), got {shown(value)}")
    return int(value)

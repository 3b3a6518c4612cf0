"""Lubricant constitutive laws: viscosity-pressure, density-pressure, temperature.

Symbols (SI): p pressure [Pa], eta viscosity [Pa s], eta0 ambient viscosity [Pa s],
alpha pressure-viscosity coefficient [1/Pa], rho/rho0 relative density [-],
t temperature [deg C] (Prokofiev law, as used by Yachikov & Vostrikov 2015).

All functions accept real or complex arrays: the solver differentiates them by the
complex-step method, so they must stay analytic (no ``abs``/``max`` on the argument).
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from ..validation import require_finite, require_positive

#: Roelands reference pressure p0 [Pa] and the constant 9.67 of ln(eta_inf) = -9.67 (Pa s).
ROELANDS_P0 = 1.96e8
ROELANDS_LN_ETA_INF = -9.67


def barus(p: np.ndarray, viscosity: float, piezo: float) -> np.ndarray:
    """Barus law eta = eta0 exp(alpha p) [Pa s].

    Beyond alpha p = 709.78 the value overflows to inf (silently: the film equation of
    Barus scenes uses the reduced pressure, and the callers take the limits of
    1/eta -> 0; ``docs/scenes.md``, "Ranges").
    """
    with np.errstate(over="ignore", invalid="ignore"):
        return viscosity * np.exp(piezo * p)


def roelands_index(viscosity: float, piezo: float) -> float:
    """Roelands pressure index Z = alpha p0 / (ln eta0 + 9.67) [-] (same low-p slope as Barus)."""
    return piezo * ROELANDS_P0 / (np.log(viscosity) - ROELANDS_LN_ETA_INF)


def roelands(p: np.ndarray, viscosity: float, piezo: float) -> np.ndarray:
    """Roelands law eta = eta0 exp{(ln eta0 + 9.67)[-1 + (1 + p/p0)^Z]} [Pa s].

    For p <= -p0 (only reachable with full-Sommerfeld cavitation) the base is clipped
    to a small positive number so the law stays finite.
    """
    z = roelands_index(viscosity, piezo)
    base = 1.0 + p / ROELANDS_P0
    base = np.where(np.real(base) > 1e-3, base, 1e-3)
    return viscosity * np.exp((np.log(viscosity) - ROELANDS_LN_ETA_INF) * (-1.0 + base**z))


def viscosity_function(law: str, viscosity: float, piezo: float) -> Callable[[np.ndarray], np.ndarray]:
    """Return eta(p) [Pa s] for a scene's ``viscosity_law``."""
    if law == "constant" or piezo == 0.0:
        return lambda p: viscosity * np.ones_like(p)
    if law == "barus":
        return lambda p: barus(p, viscosity, piezo)
    if law == "roelands":
        return lambda p: roelands(p, viscosity, piezo)
    raise ValueError(f"unknown viscosity law {law!r}; known: barus, roelands, constant")


def dowson_higginson(p: np.ndarray) -> np.ndarray:
    """Dowson-Higginson relative density rho/rho0 = 1 + 0.6e-9 p / (1 + 1.7e-9 p) [-], p in Pa."""
    return 1.0 + 0.6e-9 * p / (1.0 + 1.7e-9 * p)


def density_function(law: str) -> Callable[[np.ndarray], np.ndarray]:
    """Return rho(p)/rho0 [-] for a scene's ``density`` option."""
    if law == "incompressible":
        return lambda p: np.ones_like(p)
    if law == "dowson-higginson":
        return dowson_higginson
    raise ValueError(f"unknown density law {law!r}; known: incompressible, dowson-higginson")


def prokofiev(t_celsius: float | np.ndarray, viscosity_ref: float, t_ref_celsius: float,
              exponent: float) -> float | np.ndarray:
    """Prokofiev temperature law eta0(t) = eta_ref (t_ref / t)^n [Pa s], t in deg C
    (Yachikov & Vostrikov 2015).

    Parameters
    ----------
    t_celsius : float or array
        Temperature t > 0 [deg C].
    viscosity_ref : float
        eta_ref > 0 [Pa s] at ``t_ref_celsius`` > 0 [deg C].
    exponent : float
        n [-], finite.

    Raises
    ------
    ValueError
        Naming the argument, its value and unit.
    """
    t = require_positive("t_celsius", t_celsius, "deg C (the Prokofiev law needs t > 0)")
    eta = require_positive("viscosity_ref", viscosity_ref, "Pa s")
    t_ref = require_positive("t_ref_celsius", t_ref_celsius, "deg C")
    n = require_finite("exponent", exponent, "dimensionless")
    return eta * (t_ref / t) ** n

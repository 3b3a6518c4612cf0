"""Shear-stress (traction) models of the sliding (Couette) stress in an EHL film.

Symbols (SI): eta viscosity [Pa s], gamma_dot = u_s / h shear rate [1/s], p pressure
[Pa], tau shear stress [Pa], tau0 Eyring stress [Pa], tau_L0 limiting shear stress at
p = 0 [Pa], Lambda its pressure slope [-].

* ``newtonian``        tau = eta gamma_dot;
* ``eyring``           tau = tau0 asinh(eta gamma_dot / tau0)   (-> Newtonian as tau0 -> inf;
  Johnson & Tevaarwerk 1977);
* ``limiting``         tau = sign(gamma_dot) min(eta |gamma_dot|, tau_L0 + Lambda p) (Bair &
  Winer 1979), exact, or a smooth minimum tau_N tau_L / (tau_N^k + tau_L^k)^(1/k);
* ``eyring-limiting``  tau = sign(gamma_dot) min(tau0 asinh(eta |gamma_dot| / tau0),
  tau_L0 + Lambda p): Eyring shear thinning capped by the limiting shear stress.

With Barus viscosity at GPa pressures the Newtonian stress is unphysically large (friction
coefficients of 1e3 and more under sliding); the package's default when surfaces slide and
a scene names no model is ``eyring-limiting`` with the generic mineral-oil parameters
:data:`GENERIC_MINERAL_OIL` (``docs/theory.md``, "Traction"). The Poiseuille (rolling)
shear of the film stays Newtonian. Friction and heat integrals over a solved film are in
:mod:`bearing_fem.post`.

Only numpy is imported here.
"""
from __future__ import annotations

from typing import Any, Literal

import numpy as np

from ..validation import require_nonnegative, require_positive

TractionModel = Literal["newtonian", "eyring", "limiting", "eyring-limiting"]
#: The traction models, as named in a scene's ``[traction] model``.
TRACTION_MODELS = ("newtonian", "eyring", "limiting", "eyring-limiting")

#: Generic traction parameters of mineral oils, used when surfaces slide and a scene names
#: no traction model (the result then says so in its warnings): Eyring stress tau0 = 5 MPa
#: (2-10 MPa measured for mineral and traction oils by Johnson & Tevaarwerk 1977 and
#: Evans & Johnson 1986), limiting shear stress tau_L = 2 MPa + 0.075 p (Lambda = 0.06-0.09
#: for mineral oils, Bair & Winer 1979; Hoglund & Jacobson 1986).
GENERIC_MINERAL_OIL = {"model": "eyring-limiting", "eyring_stress": 5.0e6,
                       "limiting_shear_stress": 2.0e6, "limiting_slope": 0.075}

__all__ = ["newtonian_stress", "eyring_stress", "limiting_stress", "shear_stress",
           "shear_parameters", "TRACTION_MODELS", "GENERIC_MINERAL_OIL"]


def newtonian_stress(eta: np.ndarray, shear_rate: np.ndarray) -> np.ndarray:
    """Newtonian shear stress tau = eta gamma_dot [Pa] (eta in Pa s, gamma_dot in 1/s);
    inf where the product overflows (a Barus viscosity beyond double precision: the
    limiting models cap it, :func:`bearing_fem.post.friction_and_heat` reports an
    unbounded friction as undefined)."""
    with np.errstate(over="ignore"):
        return np.asarray(eta, dtype=float) * np.asarray(shear_rate, dtype=float)


def eyring_stress(eta: np.ndarray, shear_rate: np.ndarray, tau0: float) -> np.ndarray:
    """Eyring shear stress tau = tau0 asinh(eta gamma_dot / tau0) [Pa].

    Parameters
    ----------
    eta : viscosity [Pa s]; shear_rate : gamma_dot [1/s]; tau0 : Eyring stress [Pa].
    """
    tau0 = require_positive("eyring_stress (tau0)", tau0, "Pa")
    return tau0 * np.arcsinh(newtonian_stress(eta, shear_rate) / tau0)


_eyring = eyring_stress  # shear_stress() has a keyword of the same name


def limiting_stress(eta: np.ndarray, shear_rate: np.ndarray, pressure: np.ndarray,
                    tau_l0: float, slope: float, *, smooth: bool = False,
                    sharpness: float = 8.0) -> np.ndarray:
    """Limiting-shear-stress law [Pa]: |tau| = min(eta |gamma_dot|, tau_L0 + Lambda p).

    Parameters
    ----------
    eta : [Pa s]; shear_rate : [1/s]; pressure : p [Pa] (negative p counts as 0);
    tau_l0 : tau_L0 [Pa]; slope : Lambda [-];
    smooth : use the smooth minimum tau_N tau_L/(tau_N^k + tau_L^k)^(1/k) (always below
        both; relative deficit 2^(-1/k) where they cross); sharpness : k [-].
    """
    tau_l0 = require_nonnegative("limiting_shear_stress (tau_L0)", tau_l0, "Pa")
    slope = require_nonnegative("limiting_slope (Lambda)", slope, "(dimensionless)")
    if tau_l0 == 0.0 and slope == 0.0:
        raise ValueError("the limiting shear stress tau_L0 + Lambda p vanishes: tau_L0 = 0 Pa "
                         "and Lambda = 0")
    tau_n = newtonian_stress(eta, shear_rate)
    return np.sign(tau_n) * _capped(np.abs(tau_n), tau_l0, slope, pressure, smooth, sharpness)


def _capped(mag: np.ndarray, tau_l0: float, slope: float, pressure: np.ndarray,
            smooth: bool = False, sharpness: float = 8.0) -> np.ndarray:
    """min(mag, tau_L0 + Lambda max(p, 0)) (or its smooth version), mag >= 0 [Pa]."""
    tau_l = tau_l0 + slope * np.maximum(np.asarray(pressure, dtype=float), 0.0)
    if not smooth:
        return np.minimum(mag, tau_l)
    k = require_positive("sharpness", sharpness, "(dimensionless)")
    with np.errstate(divide="ignore", invalid="ignore"):
        r = mag / tau_l
        out = tau_l * r / (1.0 + r**k) ** (1.0 / k)
    return np.where(tau_l > 0.0, out, 0.0)


def shear_stress(eta: np.ndarray, shear_rate: np.ndarray, pressure: np.ndarray | None = None,
                 *, model: TractionModel = "newtonian",
                 eyring_stress: float = GENERIC_MINERAL_OIL["eyring_stress"],
                 limiting_shear_stress: float = GENERIC_MINERAL_OIL["limiting_shear_stress"],
                 limiting_slope: float = GENERIC_MINERAL_OIL["limiting_slope"],
                 smooth: bool = False) -> np.ndarray:
    """Shear stress [Pa] of the chosen model (module docstring); parameters as in the
    ``[traction]`` scene section: ``eyring_stress`` tau0 [Pa], ``limiting_shear_stress``
    tau_L0 [Pa], ``limiting_slope`` Lambda [-]; ``pressure`` [Pa] for the limiting models."""
    if model == "newtonian":
        return newtonian_stress(eta, shear_rate)
    if model == "eyring":
        return _eyring(eta, shear_rate, eyring_stress)
    if model in ("limiting", "eyring-limiting"):
        if pressure is None:
            raise ValueError(f"the {model} model needs the pressure field (Pa), got None")
        if model == "limiting":
            return limiting_stress(eta, shear_rate, pressure, limiting_shear_stress,
                                   limiting_slope, smooth=smooth)
        tau_e = _eyring(eta, shear_rate, eyring_stress)
        tau_l0 = require_nonnegative("limiting_shear_stress (tau_L0)", limiting_shear_stress, "Pa")
        slope = require_nonnegative("limiting_slope (Lambda)", limiting_slope, "(dimensionless)")
        return np.sign(tau_e) * _capped(np.abs(tau_e), tau_l0, slope, pressure, smooth)
    raise ValueError(f"traction model must be one of {', '.join(map(repr, TRACTION_MODELS))}, "
                     f"got {model!r}")


def shear_parameters(traction: Any) -> dict[str, Any]:
    """Keyword arguments of :func:`shear_stress` from a scene ``Traction`` section, or the
    generic mineral-oil parameters (:data:`GENERIC_MINERAL_OIL`) for None."""
    if traction is None:
        return dict(GENERIC_MINERAL_OIL)
    return {"model": traction.model, "eyring_stress": traction.eyring_stress,
            "limiting_shear_stress": traction.limiting_shear_stress,
            "limiting_slope": traction.limiting_slope}

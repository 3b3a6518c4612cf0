"""Shear-stress (traction) models, Couette friction and the film's heat-flux distribution.

Symbols (SI): eta viscosity [Pa s], gamma_dot shear rate [1/s], p pressure [Pa],
tau shear stress [Pa], h film [m], u_s = u1 - u2 sliding speed [m/s],
u_m = (u1 + u2)/2 mean speed [m/s], q heat flux per unit contact area [W/m^2].

Models of the sliding (Couette) shear stress, gamma_dot = u_s / h:

* ``newtonian``  tau = eta gamma_dot;
* ``eyring``     tau = tau0 asinh(eta gamma_dot / tau0)   (-> Newtonian as tau0 -> inf);
* ``limiting``   tau = sign(gamma_dot) min(eta |gamma_dot|, tau_L0 + Lambda p), exact, or a
  smooth minimum tau = tau_N tau_L / (tau_N^k + tau_L^k)^(1/k) (k = ``sharpness``).

Heat flux along a line film (:func:`heat_flux_line`). Dissipation per unit area is
Couette ``tau u_s`` plus Poiseuille ``h^3 p'^2 / (12 eta)``. The Poiseuille term is
evaluated in the conservative form ``u_m p' (h - h*)``, which is identical for the exact
steady incompressible film (Reynolds: h^3 p'/(12 eta) = u_m (h - h*), h* = film where
p' = 0) but does not multiply discretisation errors by the viscosity: its integral is
exactly ``u_m int h p' dx = 2 u_m F_P`` (PHYSICS.md section 6 identity), whatever h*.
The direct form blows up at an under-resolved pressure spike (measured: 60x too large on
a half-space case at 801 nodes, see docs/coupling.md). The Newtonian Reynolds flow is
kept for the Poiseuille part (the traction model acts on the sliding shear only).

Only numpy is imported here.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np

TractionModel = Literal["newtonian", "eyring", "limiting"]

__all__ = ["newtonian_stress", "eyring_stress", "limiting_stress", "shear_stress",
           "couette_line", "couette_2d", "LineHeatFlux", "heat_flux_line",
           "friction_and_heat_line", "shear_parameters"]


def _check_positive(name: str, value: float, unit: str) -> float:
    v = float(value)
    if not np.isfinite(v) or v <= 0.0:
        raise ValueError(f"{name} must be > 0 {unit}, got {value!r}")
    return v


def _check_nonneg(name: str, value: float, unit: str) -> float:
    v = float(value)
    if not np.isfinite(v) or v < 0.0:
        raise ValueError(f"{name} must be >= 0 {unit}, got {value!r}")
    return v


def newtonian_stress(eta: np.ndarray, shear_rate: np.ndarray) -> np.ndarray:
    """Newtonian shear stress tau = eta gamma_dot [Pa] (eta in Pa s, gamma_dot in 1/s)."""
    return np.asarray(eta, dtype=float) * np.asarray(shear_rate, dtype=float)


def eyring_stress(eta: np.ndarray, shear_rate: np.ndarray, tau0: float) -> np.ndarray:
    """Eyring shear stress tau = tau0 asinh(eta gamma_dot / tau0) [Pa].

    Parameters
    ----------
    eta : viscosity [Pa s]; shear_rate : gamma_dot [1/s]; tau0 : Eyring stress [Pa].
    """
    tau0 = _check_positive("eyring_stress (tau0)", tau0, "Pa")
    return tau0 * np.arcsinh(newtonian_stress(eta, shear_rate) / tau0)


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
    tau_l0 = _check_nonneg("limiting_shear_stress (tau_L0)", tau_l0, "Pa")
    slope = _check_nonneg("limiting_slope (Lambda)", slope, "(dimensionless)")
    tau_n = newtonian_stress(eta, shear_rate)
    tau_l = tau_l0 + slope * np.maximum(np.asarray(pressure, dtype=float), 0.0)
    if np.any(tau_l <= 0.0):
        raise ValueError("the limiting shear stress tau_L0 + Lambda p must be > 0 Pa, got "
                         f"tau_L0 = {tau_l0!r} Pa, Lambda = {slope!r}")
    mag = np.abs(tau_n)
    if smooth:
        k = _check_positive("sharpness", sharpness, "(dimensionless)")
        r = mag / tau_l
        out = tau_l * r / (1.0 + r**k) ** (1.0 / k)
    else:
        out = np.minimum(mag, tau_l)
    return np.sign(tau_n) * out


def shear_stress(eta: np.ndarray, shear_rate: np.ndarray, pressure: np.ndarray | None = None,
                 *, model: TractionModel = "newtonian", eyring_stress_pa: float = 5.0e6,
                 limiting_shear_stress: float = 2.0e6, limiting_slope: float = 0.075,
                 smooth: bool = False) -> np.ndarray:
    """Shear stress [Pa] of the chosen model (see module docstring; parameters as in the
    ``[traction]`` scene section: eyring_stress_pa = tau0 [Pa], limiting_shear_stress =
    tau_L0 [Pa], limiting_slope = Lambda [-])."""
    if model == "newtonian":
        return newtonian_stress(eta, shear_rate)
    if model == "eyring":
        return eyring_stress(eta, shear_rate, eyring_stress_pa)
    if model == "limiting":
        if pressure is None:
            raise ValueError("the limiting model needs the pressure field (Pa), got None")
        return limiting_stress(eta, shear_rate, pressure, limiting_shear_stress,
                               limiting_slope, smooth=smooth)
    raise ValueError(f"traction model must be 'newtonian', 'eyring' or 'limiting', got {model!r}")


def shear_parameters(traction) -> dict:
    """Keyword arguments of :func:`shear_stress` from a scene ``Traction`` section (or None)."""
    if traction is None:
        return {"model": "newtonian"}
    return {"model": traction.model, "eyring_stress_pa": traction.eyring_stress,
            "limiting_shear_stress": traction.limiting_shear_stress,
            "limiting_slope": traction.limiting_slope}


def _elements(x: np.ndarray, *arrays: np.ndarray):
    x = np.asarray(x, dtype=float)
    if x.ndim != 1 or x.size < 2 or np.any(np.diff(x) <= 0):
        raise ValueError(f"x must be a strictly ascending 1D array of >= 2 nodes (m), "
                         f"got shape {x.shape}")
    out = []
    for a in arrays:
        a = np.asarray(a, dtype=float)
        if a.shape != x.shape:
            raise ValueError(f"nodal arrays must match x (shape {x.shape}), got {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError("nodal arrays must be finite")
        out.append(a)
    return x, out


def _midpoint_fields(x, p, h, eta):
    """Element midpoints, lengths, p, h, eta (geometric mean: exact for Barus) and p'."""
    dx = np.diff(x)
    xm = 0.5 * (x[1:] + x[:-1])
    pm = 0.5 * (p[1:] + p[:-1])
    hm = 0.5 * (h[1:] + h[:-1])
    em = np.sqrt(eta[1:] * eta[:-1])
    px = np.diff(p) / dx
    return xm, dx, pm, hm, em, px


def couette_line(x: np.ndarray, p: np.ndarray, h: np.ndarray, eta: np.ndarray,
                 sliding_speed: float, *, indicator: np.ndarray | None = None,
                 model: TractionModel = "newtonian", **params) -> tuple[float, float]:
    """Couette friction force [N/m] and Couette heat [W/m] of a line film.

    F_C = int tau(u_s/h) dx, Q_C = int tau u_s dx (midpoint rule on the elements of the
    nodal arrays x [m], p [Pa], h [m], eta [Pa s]); ``indicator`` (per element, 0..1)
    masks the cavitated zone. Q_C = F_C u_s exactly (energy).
    """
    x, (p, h, eta) = _elements(x, p, h, eta)
    if np.any(h <= 0):
        raise ValueError(f"film h must be > 0 m, got min {h.min()!r}")
    xm, dx, pm, hm, em, _ = _midpoint_fields(x, p, h, eta)
    w = dx if indicator is None else dx * np.asarray(indicator, dtype=float)
    tau = shear_stress(em, sliding_speed / hm, pm, model=model, **params)
    force = float(w @ tau)
    return force, float(force * sliding_speed)


def couette_2d(x: np.ndarray, y: np.ndarray, p: np.ndarray, h: np.ndarray, eta: np.ndarray,
               sliding_speed: float, *, indicator: np.ndarray | None = None,
               model: TractionModel = "newtonian", **params) -> tuple[float, float]:
    """Couette force [N] and heat [W] on a tensor grid (p, h, eta of shape (len(x), len(y)),
    trapezoid rule; ``indicator`` of the same shape masks the cavitated zone)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    p, h, eta = (np.asarray(a, dtype=float) for a in (p, h, eta))
    shape = (x.size, y.size)
    if any(a.shape != shape for a in (p, h, eta)):
        raise ValueError(f"p, h, eta must have shape (len(x), len(y)) = {shape}")
    if np.any(h <= 0):
        raise ValueError(f"film h must be > 0 m, got min {h.min()!r}")
    tau = shear_stress(eta, sliding_speed / h, p, model=model, **params)
    if indicator is not None:
        tau = tau * np.asarray(indicator, dtype=float)
    wx = np.diff(x)
    wx = np.concatenate([[wx[0] / 2], (wx[1:] + wx[:-1]) / 2, [wx[-1] / 2]])
    wy = np.diff(y)
    wy = np.concatenate([[wy[0] / 2], (wy[1:] + wy[:-1]) / 2, [wy[-1] / 2]])
    force = float(wx @ tau @ wy)
    return force, float(force * sliding_speed)


@dataclass(frozen=True)
class LineHeatFlux:
    """Heat generated in a line film, per element (see :func:`heat_flux_line`).

    Attributes
    ----------
    x : element midpoints [m]; dx : element lengths [m];
    q, q_couette, q_poiseuille : heat flux per unit area [W/m^2] (q = sum);
    heat_power, heat_power_couette, heat_power_poiseuille : [W/m];
    rolling_resistance F_P [N/m]; sliding_friction F_C [N/m]; friction_force F_P + F_C [N/m];
    heat_power_direct_poiseuille : int h^3 p'^2/(12 eta) dx [W/m] (diagnostic, direct form);
    h_star : film h* used by the conservative Poiseuille form [m];
    outlet : cavitation boundary [m] or None.
    """

    x: np.ndarray = field(repr=False)
    dx: np.ndarray = field(repr=False)
    q: np.ndarray = field(repr=False)
    q_couette: np.ndarray = field(repr=False)
    q_poiseuille: np.ndarray = field(repr=False)
    heat_power: float = 0.0
    heat_power_couette: float = 0.0
    heat_power_poiseuille: float = 0.0
    heat_power_direct_poiseuille: float = 0.0
    rolling_resistance: float = 0.0
    sliding_friction: float = 0.0
    friction_force: float = 0.0
    h_star: float = 0.0
    outlet: float | None = None


def heat_flux_line(x: np.ndarray, p: np.ndarray, h: np.ndarray, eta: np.ndarray,
                   mean_speed: float, sliding_speed: float, *, cavitation: str = "reynolds",
                   model: TractionModel = "newtonian", **params) -> LineHeatFlux:
    """Heat-flux distribution q(x) [W/m^2] generated in a steady line film.

    Parameters
    ----------
    x, p, h, eta : nodal arrays: position [m], pressure [Pa], film [m], viscosity [Pa s].
    mean_speed : u_m [m/s] (> 0); sliding_speed : u_s [m/s].
    cavitation : "reynolds" (integrate up to the outlet: first node downstream of the
        pressure maximum with p <= 0) or "none" (whole domain).
    model, params : traction model of the Couette stress (:func:`shear_stress`).

    Notes
    -----
    Per element (midpoint rule): q_C = tau(u_s/h) u_s, q_P = u_m p' (h - h*), with
    h* the median of h - h^3 p'/(12 eta u_m) over the elements with p > p_max/2 (in the
    exact solution this "flux film" is constant; the median is robust against the
    pressure spike). The integral of q_P equals u_m int h p' dx = 2 u_m F_P whatever h*.
    """
    x, (p, h, eta) = _elements(x, p, h, eta)
    u_m = _check_positive("mean_speed", mean_speed, "m/s")
    if np.any(h <= 0) or np.any(eta <= 0):
        raise ValueError("film h (m) and viscosity eta (Pa s) must be > 0 everywhere")
    xm, dx, pm, hm, em, px = _midpoint_fields(x, p, h, eta)
    outlet = None
    if cavitation == "reynolds" and np.any(p > 0):
        i = int(np.argmax(p))
        idx = np.nonzero(p[i:] <= 0.0)[0]
        outlet = float(x[i + idx[0]]) if idx.size else None
    elif cavitation not in ("reynolds", "none"):
        raise ValueError(f"cavitation must be 'reynolds' or 'none', got {cavitation!r}")
    ind = np.ones_like(xm) if outlet is None else (xm <= outlet).astype(float)
    w = dx * ind
    flux_film = hm - hm**3 * px / (12.0 * em * u_m)
    sel = (pm > 0.5 * np.max(p)) & (ind > 0)
    h_star = float(np.median(flux_film[sel])) if np.any(sel) else float(np.median(flux_film))
    q_p = u_m * px * (hm - h_star) * ind
    tau = shear_stress(em, sliding_speed / hm, pm, model=model, **params)
    q_c = tau * sliding_speed * ind
    f_p = float(w @ (0.5 * hm * px))
    f_c = float(w @ tau)
    q = q_c + q_p
    return LineHeatFlux(
        x=xm, dx=dx, q=q, q_couette=q_c, q_poiseuille=q_p,
        heat_power=float(dx @ q), heat_power_couette=float(dx @ q_c),
        heat_power_poiseuille=float(dx @ q_p),
        heat_power_direct_poiseuille=float(w @ (hm**3 * px**2 / (12.0 * em))),
        rolling_resistance=f_p, sliding_friction=f_c, friction_force=f_p + f_c,
        h_star=h_star, outlet=outlet)


def friction_and_heat_line(x: np.ndarray, p: np.ndarray, h: np.ndarray, eta: np.ndarray,
                           mean_speed: float, sliding_speed: float, load: float, *,
                           cavitation: str = "reynolds", traction=None) -> dict[str, float]:
    """Drop-in for ``post.friction_and_heat`` of a line solution, from NODAL fields.

    Same keys (rolling_resistance, sliding_friction, friction_force,
    friction_force_surface2, friction_coefficient [N/m, -], heat_power,
    heat_power_couette, heat_power_poiseuille [W/m]) plus heat_power_direct_poiseuille;
    the Couette stress follows ``traction`` (a scene ``Traction`` section, or None for
    Newtonian) and the Poiseuille heat is the conservative form (module docstring).
    ``load`` [N/m] (> 0 for a friction coefficient).
    """
    hf = heat_flux_line(x, p, h, eta, mean_speed, sliding_speed, cavitation=cavitation,
                        **shear_parameters(traction))
    return {
        "rolling_resistance": hf.rolling_resistance,
        "sliding_friction": hf.sliding_friction,
        "friction_force": hf.friction_force,
        "friction_force_surface2": hf.rolling_resistance - hf.sliding_friction,
        "friction_coefficient": hf.friction_force / load if load > 0 else 0.0,
        "heat_power": hf.heat_power,
        "heat_power_couette": hf.heat_power_couette,
        "heat_power_poiseuille": hf.heat_power_poiseuille,
        "heat_power_direct_poiseuille": hf.heat_power_direct_poiseuille,
    }

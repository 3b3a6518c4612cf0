"""Bearing-level helpers: roller kinematics and geometry, line load, empirical heat power.

Units: SI unless a function says otherwise. The empirical Palmgren-form formulas use the
catalogue units of seed 000 (N mm, rpm, mm, mm^2/s) and say so. Only numpy/math here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["RollerContacts", "cylindrical_roller_contacts", "max_line_load",
           "palmgren_friction_torque", "palmgren_heat_power"]


def _pos(name: str, value: float, unit: str) -> float:
    v = float(value)
    if not math.isfinite(v) or v <= 0.0:
        raise ValueError(f"{name} must be > 0 {unit}, got {value!r}")
    return v


@dataclass(frozen=True)
class RollerContacts:
    """Kinematics and reduced radii of a cylindrical roller bearing (inner ring rotating,
    outer ring fixed, rolling without sliding).

    Attributes
    ----------
    pitch_diameter : d_m [m]; roller_diameter : D_w [m]; gamma : D_w/d_m [-];
    mean_speed : entrainment speed u_m = omega_i d_m (1 - gamma^2)/4 [m/s] (the same at
        both raceways for pure rolling); cage_speed : omega_c [rad/s];
    rx_inner, rx_outer : reduced radii of the roller/inner-ring and roller/outer-ring
        contacts [m] (1/R = 2/D_w +- 2/(d_m -+ D_w)).
    """

    pitch_diameter: float
    roller_diameter: float
    gamma: float
    mean_speed: float
    cage_speed: float
    rx_inner: float
    rx_outer: float


def cylindrical_roller_contacts(pitch_diameter: float, roller_diameter: float,
                                inner_rpm: float) -> RollerContacts:
    """Contact kinematics of a cylindrical roller bearing with rotating inner ring.

    Parameters
    ----------
    pitch_diameter : d_m [m]; roller_diameter : D_w [m] (< d_m); inner_rpm : n [1/min].
    """
    dm = _pos("pitch_diameter", pitch_diameter, "m")
    dw = _pos("roller_diameter", roller_diameter, "m")
    n = _pos("inner_rpm", inner_rpm, "1/min")
    if dw >= dm:
        raise ValueError(f"roller_diameter must be < pitch_diameter (m), got {dw!r} >= {dm!r}")
    g = dw / dm
    omega = 2.0 * math.pi * n / 60.0
    u_m = omega * dm * (1.0 - g * g) / 4.0
    r_roll = dw / 2
    r_in = (dm - dw) / 2
    r_out = (dm + dw) / 2
    rx_inner = 1.0 / (1.0 / r_roll + 1.0 / r_in)
    rx_outer = 1.0 / (1.0 / r_roll - 1.0 / r_out)
    return RollerContacts(dm, dw, g, u_m, omega * (1.0 - g) / 2.0, rx_inner, rx_outer)


def max_line_load(radial_load: float, rollers: int, roller_length: float,
                  k: float = 4.6) -> float:
    """Seed 000's line load of the most loaded roller q_H = K Fr/(z l_w) [N/m].

    radial_load Fr [N]; rollers z (all rows); roller_length l_w [m]; k: K [-]
    (Stribeck's 4.08 for zero clearance, ~4.6 with clearance, seed 000).
    """
    fr = _pos("radial_load", radial_load, "N")
    if isinstance(rollers, bool) or not isinstance(rollers, int) or rollers < 1:
        raise ValueError(f"rollers must be a positive integer, got {rollers!r}")
    lw = _pos("roller_length", roller_length, "m")
    return _pos("k", k, "(dimensionless)") * fr / (rollers * lw)


def palmgren_friction_torque(kinematic_viscosity_mm2s: float, rpm: float, mean_diameter_mm: float,
                             bore_mm: float, radial_load: float, axial_load: float = 0.0, *,
                             f0: float, f_pr: float) -> dict[str, float]:
    """Palmgren-form friction torque of seed 000 [N mm].

    M0 = 1e-7 f0 (nu n)^(2/3) d0^3 if nu n >= 2000, else 160e-7 f0 d0^3;
    M1 = f_pr P d/2 with P = sqrt(Fr^2 + Fa^2) [N], d = bore [mm]; M = M0 + M1.

    Parameters
    ----------
    kinematic_viscosity_mm2s : nu [mm^2/s]; rpm : n [1/min]; mean_diameter_mm : d0 [mm];
    bore_mm : d [mm]; radial_load, axial_load : Fr, Fa [N]; f0, f_pr : coefficients [-].

    Returns
    -------
    dict with M0, M1, M [N mm].
    """
    nu = _pos("kinematic_viscosity_mm2s", kinematic_viscosity_mm2s, "mm^2/s")
    n = _pos("rpm", rpm, "1/min")
    d0 = _pos("mean_diameter_mm", mean_diameter_mm, "mm")
    d = _pos("bore_mm", bore_mm, "mm")
    fr = _pos("radial_load", radial_load, "N")
    fa = float(axial_load)
    if not math.isfinite(fa) or fa < 0:
        raise ValueError(f"axial_load must be >= 0 N, got {axial_load!r}")
    f0 = _pos("f0", f0, "(dimensionless)")
    f_pr = _pos("f_pr", f_pr, "(dimensionless)")
    m0 = 1e-7 * f0 * (nu * n) ** (2.0 / 3.0) * d0**3 if nu * n >= 2000.0 else \
        160e-7 * f0 * d0**3
    m1 = f_pr * math.hypot(fr, fa) * d / 2.0
    return {"M0": m0, "M1": m1, "M": m0 + m1}


def palmgren_heat_power(kinematic_viscosity_mm2s: float, rpm: float, mean_diameter_mm: float,
                        bore_mm: float, radial_load: float, axial_load: float = 0.0, *,
                        f0: float, f_pr: float) -> float:
    """Empirical bearing heat power Q = 1.047e-4 M n [W] (M in N mm, n in rpm; seed 000).

    1.047e-4 = 2 pi / 60 / 1000 converts N mm x rpm to W.
    """
    m = palmgren_friction_torque(kinematic_viscosity_mm2s, rpm, mean_diameter_mm, bore_mm,
                                 radial_load, axial_load, f0=f0, f_pr=f_pr)["M"]
    return 1.047e-4 * m * float(rpm)

"""Empirical bearing friction and film models, each with its source and units.

These are the engineering formulas the EHL bearing totals are set beside (see
docs/bearing.md, "Empirical models"). They use the catalogue units of their sources
(N mm, rpm, mm, mm^2/s) where the source does, and each docstring says so; the
:func:`empirical_models` wrapper converts to SI (N m, W).

* Palmgren (Harris & Kotzalas): M = M0 + M1, M0 the viscous (load-independent) term
  with the lubrication factor f0, M1 = f1 P1 d_m the load term.
* Palmgren, bore form (Yachikov & Vostrikov 2015): M1 = f_pr P d/2, and the heat power
  Q = 1.047e-4 M n they use.
* SKF four-component model (SKF catalogue): M = M_rr + M_sl + M_seal + M_drag.
* Nikitin (2011): criterial (similarity) model of the total loss of jet-lubricated ball
  bearings with steel or Si3N4 balls, and its split into friction and churning.
* Film formulas: Hamrock-Dowson, Dowson-Higginson, Pan-Hamrock, Moes, Nijenbanning and
  the five sets quoted by Zhirkin et al. (all from :mod:`bearing_fem.formulas`).

Only math/numpy, :mod:`bearing_fem.formulas` and the SKF table of the bearing description
(``SKF_GEOMETRY_CONSTANTS``, re-exported here) are used.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from .. import formulas
from ..validation import require_nonnegative, require_positive
from .description import SKF_CONSTANTS_USED, SKF_GEOMETRY_CONSTANTS

if TYPE_CHECKING:
    from .description import Bearing

__all__ = ["palmgren_friction_torque", "palmgren_heat_power", "palmgren_torque",
           "palmgren_f1", "palmgren_equivalent_load", "PALMGREN_F0",
           "skf_friction_torque", "SKF_GEOMETRY_CONSTANTS", "SKF_KZ",
           "nikitin_power_loss", "nikitin_split", "NIKITIN_TOTAL", "NIKITIN_FRICTION",
           "NIKITIN_CHURNING", "film_formulas", "torque_to_heat_power", "empirical_models"]




def torque_to_heat_power(torque_nmm: float, rpm: float) -> float:
    """Heat power Q = M omega [W] of a friction torque M [N mm] at n [1/min]:
    Q = 1.047e-4 M n (1.047e-4 = 2 pi/60/1000; Yachikov & Vostrikov 2015)."""
    torque = require_nonnegative("torque_nmm", torque_nmm, "N mm")
    n = require_nonnegative("rpm", rpm, "1/min")
    return 2.0 * math.pi / 60.0 / 1000.0 * torque * n


def _palmgren_viscous(kinematic_viscosity_mm2s: float, rpm: float, mean_diameter_mm: float,
                      f0: float) -> float:
    """Palmgren's viscous torque M0 [N mm]: 1e-7 f0 (nu n)^(2/3) d_m^3 for nu n >= 2000,
    else 160e-7 f0 d_m^3 (nu [mm^2/s], n [1/min], d_m [mm], f0 [-]; each checked to be
    positive, ValueError naming the argument otherwise)."""
    nu = require_positive("kinematic_viscosity_mm2s", kinematic_viscosity_mm2s, "mm^2/s")
    n = require_positive("rpm", rpm, "1/min")
    dm = require_positive("mean_diameter_mm", mean_diameter_mm, "mm")
    f0 = require_positive("f0", f0, "(dimensionless)")
    nu_n = nu * n
    if nu_n >= 2000.0:
        return 1e-7 * f0 * nu_n ** (2.0 / 3.0) * dm**3
    return 160e-7 * f0 * dm**3


# ---------------------------------------------------------------------------------------
# Palmgren, bore form (Yachikov & Vostrikov 2015)
# ---------------------------------------------------------------------------------------
def palmgren_friction_torque(kinematic_viscosity_mm2s: float, rpm: float, mean_diameter_mm: float,
                             bore_mm: float, radial_load: float, axial_load: float = 0.0, *,
                             f0: float, f_pr: float) -> dict[str, float]:
    """Palmgren-form friction torque with a bore-based load term [N mm]
    (Yachikov & Vostrikov 2015).

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
    m0 = _palmgren_viscous(kinematic_viscosity_mm2s, rpm, mean_diameter_mm, f0)
    d = require_positive("bore_mm", bore_mm, "mm")
    fr = require_positive("radial_load", radial_load, "N")
    fa = require_nonnegative("axial_load", axial_load, "N")
    m1 = require_positive("f_pr", f_pr, "(dimensionless)") * math.hypot(fr, fa) * d / 2.0
    return {"M0": m0, "M1": m1, "M": m0 + m1}


def palmgren_heat_power(kinematic_viscosity_mm2s: float, rpm: float, mean_diameter_mm: float,
                        bore_mm: float, radial_load: float, axial_load: float = 0.0, *,
                        f0: float, f_pr: float) -> float:
    """Empirical bearing heat power Q = 1.047e-4 M n [W] (M in N mm, n in rpm) of
    :func:`palmgren_friction_torque` (Yachikov & Vostrikov 2015).

    1.047e-4 is the paper's rounding of 2 pi / 60 / 1000, which converts N mm x rpm to W;
    the exact factor is used (:func:`torque_to_heat_power`), so that Q = M omega.
    """
    m = palmgren_friction_torque(kinematic_viscosity_mm2s, rpm, mean_diameter_mm, bore_mm,
                                 radial_load, axial_load, f0=f0, f_pr=f_pr)["M"]
    return torque_to_heat_power(m, rpm)


# ---------------------------------------------------------------------------------------
# Palmgren with Harris' f0 / f1 (Harris & Kotzalas, "Rolling Bearing Analysis")
# ---------------------------------------------------------------------------------------
#: Typical Palmgren lubrication factors f0 [-] for an oil bath (Harris & Kotzalas; the
#: ranges there are about +-30%: grease and oil mist lower, oil jet and vertical shafts
#: higher). The full-complement value is the one Yachikov & Vostrikov (2015) use for
#: the NNCF 5040 CV.
PALMGREN_F0: dict[str, float] = {
    "deep-groove-ball": 2.0,
    "angular-contact-ball": 3.3,
    "cylindrical-roller": 3.0,
    "cylindrical-roller-full-complement": 5.0,
    "tapered-roller": 4.0,
}


def palmgren_f1(bearing_type: str, static_equivalent_load: float | None = None,
                static_load_rating: float | None = None,
                full_complement: bool = False) -> float:
    """Palmgren's load factor f1 [-] (Harris & Kotzalas).

    Ball bearings: f1 = z (P0/C0)^y with z = 0.0005 (the middle of Harris' 0.0004-0.0006),
    y = 0.55 (deep groove) and z = 0.001, y = 0.33 (angular contact); P0/C0 = 1/8 is
    assumed when C0 is not given.
    Roller bearings: constants, 0.0003 (cylindrical with cage), 0.00055 (full
    complement), 0.0004 (tapered).
    """
    if bearing_type in ("deep-groove-ball", "angular-contact-ball"):
        z, y = (0.0005, 0.55) if bearing_type == "deep-groove-ball" else (0.001, 0.33)
        ratio = 0.125
        if static_equivalent_load is not None and static_load_rating is not None:
            ratio = require_positive("static_equivalent_load", static_equivalent_load, "N") / \
                require_positive("static_load_rating", static_load_rating, "N")
        return z * ratio**y
    if bearing_type == "cylindrical-roller":
        return 0.00055 if full_complement else 0.0003
    if bearing_type == "tapered-roller":
        return 0.0004
    raise ValueError(f"unknown bearing type {bearing_type!r}")


#: ISO 76 static axial load factor Y0 of single-row angular-contact ball bearings by
#: nominal contact angle [deg] (X0 = 0.5); linear between the tabulated angles, the end
#: values beyond them.
ISO76_ANGULAR_Y0 = ((15.0, 0.46), (20.0, 0.42), (25.0, 0.38), (30.0, 0.33), (35.0, 0.29),
                    (40.0, 0.26), (45.0, 0.22))


def static_equivalent_load(bearing_type: str, radial_load: float, axial_load: float,
                           contact_angle_deg: float = 0.0) -> float:
    """ISO 76 static equivalent load P0 = max(Fr, X0 Fr + Y0 Fa) [N] of a ball bearing.

    Deep groove: X0 = 0.6, Y0 = 0.5; single-row angular contact: X0 = 0.5 and Y0 from
    :data:`ISO76_ANGULAR_Y0` at the nominal contact angle (0.46 at 15 deg to 0.22 at
    45 deg). Palmgren's f1 of ball bearings takes P0/C0.

    Parameters
    ----------
    bearing_type : str
        "deep-groove-ball" or "angular-contact-ball".
    radial_load, axial_load : float
        Fr, Fa [N], >= 0.
    contact_angle_deg : float
        Nominal contact angle [deg] (angular contact).
    """
    fr = require_nonnegative("radial_load", radial_load, "N")
    fa = require_nonnegative("axial_load", axial_load, "N")
    if bearing_type == "angular-contact-ball":
        angles, y0 = zip(*ISO76_ANGULAR_Y0)
        return max(fr, 0.5 * fr + float(np.interp(contact_angle_deg, angles, y0)) * fa)
    return max(fr, 0.6 * fr + 0.5 * fa)


def palmgren_equivalent_load(bearing_type: str, radial_load: float, axial_load: float,
                             contact_angle_deg: float = 0.0) -> float:
    """Palmgren's load P1 [N] of M1 = f1 P1 d_m (Harris & Kotzalas).

    Deep groove: max(0.9 Fa cot(alpha) - 0.1 Fr, Fr) with the loaded contact angle
    alpha (radial load only: Fr); angular contact: max(Fa - 0.1 Fr, Fr); roller: Fr.
    """
    fr = require_nonnegative("radial_load", radial_load, "N")
    fa = require_nonnegative("axial_load", axial_load, "N")
    if bearing_type == "deep-groove-ball":
        if fa == 0.0:
            return fr
        a = math.radians(max(float(contact_angle_deg), 1e-6))
        return max(0.9 * fa / math.tan(a) - 0.1 * fr, fr)
    if bearing_type == "angular-contact-ball":
        return max(fa - 0.1 * fr, fr)
    return fr


def palmgren_torque(kinematic_viscosity_mm2s: float, rpm: float, mean_diameter_mm: float,
                    equivalent_load: float, *, f0: float, f1: float) -> dict[str, float]:
    """Palmgren's friction torque M = M0 + M1 [N mm] (Harris & Kotzalas).

    M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 (nu n >= 2000) else 160e-7 f0 d_m^3;
    M1 = f1 P1 d_m.

    Parameters
    ----------
    kinematic_viscosity_mm2s : nu [mm^2/s]; rpm : n [1/min]; mean_diameter_mm : d_m [mm];
    equivalent_load : P1 [N] (:func:`palmgren_equivalent_load`); f0, f1 [-].

    Returns
    -------
    dict with M0, M1, M [N mm].
    """
    m0 = _palmgren_viscous(kinematic_viscosity_mm2s, rpm, mean_diameter_mm, f0)
    p1 = require_nonnegative("equivalent_load", equivalent_load, "N")
    m1 = require_positive("f1", f1, "(dimensionless)") * p1 * float(mean_diameter_mm)
    return {"M0": m0, "M1": m1, "M": m0 + m1}


# ---------------------------------------------------------------------------------------
# SKF four-component model (SKF rolling bearings catalogue, section "Friction")
# ---------------------------------------------------------------------------------------
# SKF_GEOMETRY_CONSTANTS (R1, R2, S1, S2 by type and series) is defined with the
# bearing description, which checks empirical.skf_series against it.
#: Bearing-type constant K_z of the replenishment/starvation factor (SKF).
SKF_KZ: dict[str, float] = {"deep-groove-ball": 3.1, "angular-contact-ball": 4.4,
                            "cylindrical-roller": 5.1, "tapered-roller": 6.0}


def skf_friction_torque(bearing_type: str, bore_mm: float, outside_mm: float, rpm: float,
                        kinematic_viscosity_mm2s: float, radial_load: float,
                        axial_load: float = 0.0, *, r1: float, r2: float, s1: float,
                        s2: float, lubrication: str = "oil-bath",
                        static_load_rating: float | None = None,
                        mu_ehl: float | None = None) -> dict[str, float]:
    """SKF four-component friction torque [N mm] (SKF catalogue, section "Friction").

    M = M_rr + M_sl + M_seal + M_drag with
    M_rr = phi_ish phi_rs G_rr (nu n)^0.6,  M_sl = G_sl mu_sl,
    phi_ish = 1/(1 + 1.84e-9 (n d_m)^1.28 nu^0.64),
    phi_rs = exp(-K_rs nu n (d + D) sqrt(K_z/(2 (D - d)))), K_rs = 3e-8 (oil bath, oil
    jet) or 6e-8 (grease, oil-air),
    mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL, phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m),
    mu_bl = 0.12, mu_EHL = 0.05 (ball bearings, mineral oil), 0.02 (cylindrical), 0.002
    (tapered). G_rr, G_sl: deep groove ball bearings R1 d_m^1.96 F^0.54 and
    S1 d_m^-0.26 Fr^(5/3) (Fa = 0), with Fa > 0: F = Fr + R2 Fa/sin(alpha_F) and
    S1 d_m^-0.145 (Fr^5 + S2 d_m^1.5 Fa^4/sin(alpha_F))^(1/3), alpha_F = 24.6 (Fa/C0)^0.24
    deg; cylindrical roller bearings R1 d_m^2.41 Fr^0.31 and S1 d_m^0.9 Fa + S2 d_m Fr.
    Open bearings (M_seal = 0) with oil-jet or oil-air lubrication (M_drag = 0; the
    oil-bath drag term needs the oil level and is not evaluated). Units: d, D, d_m [mm],
    n [1/min], nu [mm^2/s], loads [N], torques [N mm].

    Returns
    -------
    dict with M_rr, M_sl, M_seal, M_drag, M [N mm] and phi_ish, phi_rs, phi_bl, mu_sl,
    G_rr, G_sl.
    """
    d = require_positive("bore_mm", bore_mm, "mm")
    big_d = require_positive("outside_mm", outside_mm, "mm")
    n = require_positive("rpm", rpm, "1/min")
    nu = require_positive("kinematic_viscosity_mm2s", kinematic_viscosity_mm2s, "mm^2/s")
    fr = require_nonnegative("radial_load", radial_load, "N")
    fa = require_nonnegative("axial_load", axial_load, "N")
    if bearing_type not in SKF_CONSTANTS_USED:
        raise ValueError(f"SKF model implemented for {' and '.join(SKF_CONSTANTS_USED)} "
                         f"bearings, got {bearing_type!r}")
    dm = 0.5 * (d + big_d)
    if bearing_type == "deep-groove-ball":
        if fa == 0.0:
            g_rr = r1 * dm**1.96 * fr**0.54
            g_sl = s1 * dm**-0.26 * fr ** (5.0 / 3.0)
        else:
            if static_load_rating is None:
                raise ValueError("static_load_rating C0 (N) is required for an axially "
                                 "loaded deep groove ball bearing (SKF alpha_F)")
            sin_af = math.sin(math.radians(24.6 * (fa / static_load_rating) ** 0.24))
            g_rr = r1 * dm**1.96 * (fr + r2 / sin_af * fa) ** 0.54
            g_sl = s1 * dm**-0.145 * (fr**5 + s2 * dm**1.5 / sin_af * fa**4) ** (1.0 / 3.0)
        mu_default = 0.05
    elif bearing_type == "cylindrical-roller":
        g_rr = r1 * dm**2.41 * fr**0.31
        g_sl = s1 * dm**0.9 * fa + s2 * dm * fr
        mu_default = 0.02
    else:  # a type of SKF_CONSTANTS_USED needs its G_rr and G_sl here
        raise ValueError(f"no SKF G_rr, G_sl formulas for {bearing_type!r} bearings")
    k_rs = 3e-8 if lubrication in ("oil-bath", "oil-jet") else 6e-8
    kz = SKF_KZ[bearing_type]
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = math.exp(-k_rs * nu * n * (d + big_d) * math.sqrt(kz / (2.0 * (big_d - d))))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * 0.12 + (1.0 - phi_bl) * (mu_default if mu_ehl is None else mu_ehl)
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** 0.6
    m_sl = g_sl * mu_sl
    return {"M_rr": m_rr, "M_sl": m_sl, "M_seal": 0.0, "M_drag": 0.0, "M": m_rr + m_sl,
            "phi_ish": phi_ish, "phi_rs": phi_rs, "phi_bl": phi_bl, "mu_sl": mu_sl,
            "G_rr": g_rr, "G_sl": g_sl}


# ---------------------------------------------------------------------------------------
# Nikitin (2011): criterial power loss of jet-lubricated (hybrid) ball bearings
# ---------------------------------------------------------------------------------------
#: Total loss Q = phi m rho d_b^2 u^3, phi = K (q/q_nom)^b Re^x Pr^y Eu^z:
#: set -> (K, b, x, y, z) (Nikitin 2011, final equations).
NIKITIN_TOTAL: dict[str, tuple[float, float, float, float, float]] = {
    "steel": (4.043e6, 2.166, -0.952, -1.727, 0.418),
    "ceramic": (6.256e15, 2.627, -2.257, -3.280, -0.157),
    "joint": (1.740e10, 2.260, -1.483, -2.299, 0.155),
}
#: Friction part phi_1 = K1 Re^x1 Eu^z1 Pr^y1 (Nikitin 2011, table 1):
#: (material, oil-flow range) -> (ln K1, x1, z1, y1). Flow ranges: "min" 8.5-10 g/s,
#: "low" 11-14 g/s, "high" 14-15.5 g/s, "max" 19-24 g/s.
NIKITIN_FRICTION: dict[tuple[str, str], tuple[float, float, float, float]] = {
    ("ceramic", "min"): (-23.232, 1.153, 1.218, 1.397),
    ("steel", "min"): (16.453, -1.052, 0.534, -2.226),
    ("ceramic", "low"): (-18.389, 0.862, 0.867, 1.102),
    ("steel", "low"): (6.879, -0.561, 0.558, -1.200),
    ("ceramic", "high"): (-26.003, 1.349, 1.318, 1.546),
    ("steel", "high"): (8.281, -0.695, 0.472, -1.205),
    ("ceramic", "max"): (-20.582, 1.019, 1.223, 1.108),
    ("steel", "max"): (8.278, -0.675, 0.515, -1.265),
}
#: Churning part phi_2 = K2 Re^x2 Pr^y2 (Nikitin 2011, table 2):
#: (material, oil-flow range) -> (ln K2, x2, y2).
NIKITIN_CHURNING: dict[tuple[str, str], tuple[float, float, float]] = {
    ("ceramic", "min"): (49.982, -2.912, -5.226),
    ("steel", "min"): (35.072, -2.263, -3.329),
    ("ceramic", "low"): (30.308, -1.997, -2.798),
    ("steel", "low"): (39.563, -2.347, -3.983),
    ("ceramic", "high"): (29.023, -1.766, -2.824),
    ("steel", "high"): (19.354, -1.246, -1.894),
    ("ceramic", "max"): (11.518, -0.846, -0.989),
    ("steel", "max"): (8.348, -0.752, -0.486),
}


def _nikitin_groups(rpm: float, bore: float, outside: float, ball_diameter: float,
                    contact_angle_deg: float, balls: int, kinematic_viscosity: float,
                    density: float, thermal_diffusivity: float, radial_load: float,
                    axial_load: float) -> dict[str, float]:
    n = require_positive("rpm", rpm, "1/min")
    db = require_positive("ball_diameter", ball_diameter, "m")
    nu = require_positive("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    rho = require_positive("density", density, "kg/m^3")
    a = require_positive("thermal_diffusivity", thermal_diffusivity, "m^2/s")
    m = int(balls)
    # the paper prints the ball-centre diameter as (D - d)/2; the pitch diameter
    # (D + d)/2 is meant (a diameter of the ball centres)
    dcg = 0.5 * (require_positive("bore", bore, "m") + require_positive("outside", outside, "m"))
    u = math.pi * (dcg - db * math.cos(math.radians(contact_angle_deg))) * n / 120.0
    fa = require_nonnegative("axial_load", axial_load, "N")
    fr = require_nonnegative("radial_load", radial_load, "N")
    p_eq = 0.41 * fr + 0.87 * fa if fa > 0.0 else fr
    re = u * db / nu
    pr = nu / a
    eu = (p_eq / m) / (rho * u**2 * db**2)
    return {"u": u, "Re": re, "Pr": pr, "Eu": eu, "scale": m * rho * db**2 * u**3,
            "P_equivalent": p_eq}


def nikitin_power_loss(rpm: float, bore: float, outside: float, ball_diameter: float,
                       contact_angle_deg: float, balls: int, kinematic_viscosity: float,
                       density: float, thermal_diffusivity: float, radial_load: float,
                       axial_load: float, flow_ratio: float,
                       coefficient_set: str = "joint") -> dict[str, float]:
    """Total power loss of a jet-lubricated ball bearing by Nikitin's (2011) criterial model [W].

    Q = phi m rho d_b^2 u^3, phi = K (q/q_nom)^b Re^x Pr^y Eu^z with the cage speed
    u = pi (d_cg - d_b cos(gamma)) n/120 [m/s] (n [1/min], d_cg the pitch diameter [m]),
    Re = u d_b/nu, Pr = nu/a, Eu = (P/m)/(rho u^2 d_b^2), P = 0.41 Fr + 0.87 Fa
    (Fa > 0; else Fr). SI inputs: bore, outside, ball_diameter [m]; kinematic viscosity
    nu [m^2/s]; density rho [kg/m^3]; thermal diffusivity a = lambda/(rho c) [m^2/s];
    loads [N]; ``flow_ratio`` q/q_nom [-]; ``coefficient_set`` "steel", "ceramic" or
    "joint" (:data:`NIKITIN_TOTAL`). The fits were made on one aero-engine bearing size at
    axial loads to 2 kN; outside that range they are extrapolations.

    Returns
    -------
    dict with ``heat_power`` [W], ``phi`` [-], ``u`` [m/s], ``Re``, ``Pr``, ``Eu`` [-].
    """
    g = _nikitin_groups(rpm, bore, outside, ball_diameter, contact_angle_deg, balls,
                        kinematic_viscosity, density, thermal_diffusivity, radial_load,
                        axial_load)
    k, b, x, y, z = NIKITIN_TOTAL[coefficient_set]
    phi = k * require_positive("flow_ratio", flow_ratio, "(dimensionless)") ** b * g["Re"] ** x \
        * g["Pr"] ** y * g["Eu"] ** z
    return {"heat_power": phi * g["scale"], "phi": phi, "u": g["u"], "Re": g["Re"],
            "Pr": g["Pr"], "Eu": g["Eu"]}


def nikitin_split(rpm: float, bore: float, outside: float, ball_diameter: float,
                  contact_angle_deg: float, balls: int, kinematic_viscosity: float,
                  density: float, thermal_diffusivity: float, radial_load: float,
                  axial_load: float, material: str, flow_range: str = "max") -> dict[str, float]:
    """Nikitin's (2011) split of the loss into friction Q1 and oil churning Q2 [W].

    Q1 = phi1 m rho d_b^2 u^3, phi1 = K1 Re^x1 Eu^z1 Pr^y1 (:data:`NIKITIN_FRICTION`);
    Q2 = phi2 m rho d_b^2 u^3, phi2 = K2 Re^x2 Pr^y2 (:data:`NIKITIN_CHURNING`); the
    reduced friction coefficient f_pr = phi1/(K Eu), K = d omega/(2u) (d the bore).
    Inputs as :func:`nikitin_power_loss`; ``material`` "steel" or "ceramic"; ``flow_range``
    "min", "low", "high" or "max".

    Returns
    -------
    dict with ``friction`` Q1, ``churning`` Q2, ``total`` [W], ``friction_coefficient``
    f_pr [-], ``u`` [m/s], ``Re``, ``Pr``, ``Eu``.
    """
    g = _nikitin_groups(rpm, bore, outside, ball_diameter, contact_angle_deg, balls,
                        kinematic_viscosity, density, thermal_diffusivity, radial_load,
                        axial_load)
    lk1, x1, z1, y1 = NIKITIN_FRICTION[(material, flow_range)]
    lk2, x2, y2 = NIKITIN_CHURNING[(material, flow_range)]
    phi1 = math.exp(lk1) * g["Re"] ** x1 * g["Eu"] ** z1 * g["Pr"] ** y1
    phi2 = math.exp(lk2) * g["Re"] ** x2 * g["Pr"] ** y2
    omega = 2.0 * math.pi * float(rpm) / 60.0
    k = float(bore) * omega / (2.0 * g["u"])
    return {"friction": phi1 * g["scale"], "churning": phi2 * g["scale"],
            "total": (phi1 + phi2) * g["scale"], "friction_coefficient": phi1 / (k * g["Eu"]),
            "u": g["u"], "Re": g["Re"], "Pr": g["Pr"], "Eu": g["Eu"]}


# ---------------------------------------------------------------------------------------
# film formulas
# ---------------------------------------------------------------------------------------
#: Smallest materials parameter G = alpha E' [-] at which the piezoviscous fits
#: (Pan-Hamrock, Dowson-Higginson, Zhirkin's sets, Hamrock-Dowson: H ~ G^b) are evaluated.
#: Oils on steel have G of 2000..6000; as G -> 0 the fits' films vanish like G^b (1e-150 m
#: at alpha = 1e-300 1/Pa) and Hamrock-Dowson's h_min exceeds its h_central, so a contact
#: below this G is isoviscous for them, as alpha = 0 is.
FIT_MIN_MATERIALS_PARAMETER = 100.0


def film_formulas(kind: str, load: float, rx: float, e_prime: float, viscosity: float,
                  mean_speed: float, piezo: float, ry: float | None = None) -> dict[str, Any]:
    """Films of the published fits for one contact [m] (mean-speed inputs, SI).

    Line contacts (``load`` in N/m): Moes central, Pan-Hamrock (minimum and central),
    Dowson-Higginson minimum and the five sets quoted by Zhirkin et al. (minimum films
    H = K U^a G^b W^c in Hamrock's mean-speed groups; see
    :data:`bearing_fem.formulas.ZHIRKIN_CONVENTIONS`). Point contacts (``load`` in N):
    Nijenbanning-Venner-Moes central and Hamrock-Dowson (minimum and central). An
    isoviscous contact (alpha E' below :data:`FIT_MIN_MATERIALS_PARAMETER`, alpha = 0
    included) gets only the Moes-type fits (the others are fits in G = alpha E' that
    vanish as G -> 0).

    Parameters
    ----------
    kind : {"line", "point"}
    load : float
        Contact load [N] (point) or load per unit length [N/m] (line).
    rx, ry : float
        Reduced radii [m] in and across the rolling direction (``ry`` for points only).
    e_prime : float
        Reduced modulus E' [Pa].
    viscosity : float
        Inlet viscosity eta0 [Pa s].
    mean_speed : float
        Mean entrainment speed u_m [m/s].
    piezo : float
        Pressure-viscosity coefficient alpha [1/Pa].

    Returns
    -------
    dict
        name -> {"h_min": m or None, "h_central": m or None, "convention": str}.
    """
    out: dict[str, Any] = {}
    # the Hamrock-style fits need a G = alpha E' of a piezoviscous oil
    piezo_viscous = piezo * e_prime >= FIT_MIN_MATERIALS_PARAMETER
    if kind == "line":
        hc = formulas.line_central_film_moes(load, rx, e_prime, viscosity, mean_speed, piezo)
        out["Moes"] = {"h_min": None, "h_central": hc, "convention": "sum speed (Moes groups)"}
        if not piezo_viscous:
            return out
        hm, hc2 = formulas.line_films_pan_hamrock(load, rx, e_prime, viscosity, mean_speed,
                                                 piezo)
        out["Pan-Hamrock"] = {"h_min": hm, "h_central": hc2, "convention": "mean speed"}
        out["Dowson-Higginson"] = {
            "h_min": formulas.line_min_film_dowson_higginson(load, rx, e_prime, viscosity,
                                                             mean_speed, piezo),
            "h_central": None, "convention": "mean speed"}
        u = viscosity * mean_speed / (e_prime * rx)
        g = piezo * e_prime
        w = load / (e_prime * rx)
        for name, coeffs in formulas.ZHIRKIN_FITS.items():
            out[f"{name} (Zhirkin et al.)"] = {
                "h_min": float(formulas.power_law_film(u, g, w, coeffs)) * rx,
                "h_central": None, "convention": formulas.ZHIRKIN_CONVENTIONS[name]}
        return out
    if ry is None:
        raise ValueError("ry (m) is required for a point contact")
    out["Nijenbanning-Venner-Moes"] = {
        "h_min": None, "convention": "sum speed (Moes groups)",
        "h_central": formulas.point_central_film_nvm(load, rx, ry, e_prime, viscosity,
                                                     mean_speed, piezo)}
    if not piezo_viscous:
        return out
    hm, hc = formulas.point_films_hamrock_dowson(load, rx, ry, e_prime, viscosity,
                                                 mean_speed, piezo)
    out["Hamrock-Dowson"] = {"h_min": hm, "h_central": hc, "convention": "mean speed"}
    return out


# ---------------------------------------------------------------------------------------
# all models for one bearing, in SI
# ---------------------------------------------------------------------------------------
def empirical_models(bearing: Bearing, loaded_contact_angle_deg: float = 0.0
                     ) -> dict[str, Any]:
    """Every applicable empirical model for a :class:`~bearing_fem.bearing.Bearing` [SI].

    Parameters
    ----------
    bearing : Bearing
    loaded_contact_angle_deg : float
        Mean contact angle of the loaded elements [deg] (Palmgren's P1 of an axially
        loaded deep groove bearing).

    Returns
    -------
    dict
        model name -> {"torque": N m, "heat_power": W, "source": str, "parameters": dict,
        plus model-specific parts}, or {"available": False, "reason": str}.
    """
    from .contacts import lubricant_at_oil_temperature

    g, op, lub, opts = bearing.geometry, bearing.operation, bearing.lubricant, bearing.empirical
    eta, _ = lubricant_at_oil_temperature(bearing)
    nu_m2s = eta / lub.density
    nu = nu_m2s * 1e6                       # mm^2/s
    n = float(op.inner_rpm)
    dm_mm = g.mean_diameter * 1e3
    fr, fa = float(op.radial_load), float(op.axial_load)
    omega = op.inner_speed
    full = g.elements * g.element_diameter >= 0.95 * math.pi * g.mean_diameter
    out: dict[str, Any] = {}

    key = "cylindrical-roller-full-complement" if (full and g.type == "cylindrical-roller") \
        else g.type
    f0 = opts.palmgren_f0 if opts.palmgren_f0 is not None else PALMGREN_F0[key]
    p0 = static_equivalent_load(g.type, fr, fa, g.contact_angle or 0.0) if g.is_ball else fr
    f1 = opts.palmgren_f1 if opts.palmgren_f1 is not None else palmgren_f1(
        g.type, p0 if g.static_load_rating else None, g.static_load_rating, full)
    p1 = palmgren_equivalent_load(g.type, fr, fa, loaded_contact_angle_deg)
    m = palmgren_torque(nu, n, dm_mm, p1, f0=f0, f1=f1)
    out["palmgren"] = {"torque": m["M"] * 1e-3, "heat_power": m["M"] * 1e-3 * omega,
                       "torque_viscous": m["M0"] * 1e-3, "torque_load": m["M1"] * 1e-3,
                       "source": "Palmgren (Harris & Kotzalas): M0 = 1e-7 f0 (nu n)^(2/3) "
                                 "d_m^3, M1 = f1 P1 d_m",
                       "parameters": {"f0": f0, "f1": f1, "P1_N": p1,
                                      "kinematic_viscosity_mm2_s": nu}}
    if opts.friction_coefficient is not None:
        mb = palmgren_friction_torque(nu, n, dm_mm, g.bore * 1e3, max(fr, 1e-300), fa, f0=f0,
                                      f_pr=opts.friction_coefficient)
        out["palmgren_bore_form"] = {
            "torque": mb["M"] * 1e-3, "heat_power": torque_to_heat_power(mb["M"], n),
            "torque_viscous": mb["M0"] * 1e-3, "torque_load": mb["M1"] * 1e-3,
            "source": "Yachikov & Vostrikov (2015): M1 = f_pr P d/2, Q = 1.047e-4 M n",
            "parameters": {"f0": f0, "f_pr": opts.friction_coefficient,
                           "kinematic_viscosity_mm2_s": nu}}
    consts = None
    if opts.skf_r1 is not None:  # the constants the type uses (checked by Bearing)
        consts = (opts.skf_r1, opts.skf_r2 if opts.skf_r2 is not None else 0.0, opts.skf_s1,
                  opts.skf_s2)
    elif opts.skf_series is not None:
        consts = SKF_GEOMETRY_CONSTANTS.get((g.type, opts.skf_series))
    if g.type not in SKF_CONSTANTS_USED:
        out["skf"] = {"available": False, "reason": f"SKF model not implemented here for "
                                                    f"{g.type} bearings"}
    elif consts is None:
        out["skf"] = {"available": False,
                      "reason": "no SKF geometry constants (give empirical.skf_series of a "
                                "listed series, or the constants skf_r1, ... from the SKF "
                                "catalogue)"}
    elif g.type == "deep-groove-ball" and fa > 0.0 and g.static_load_rating is None:
        out["skf"] = {"available": False,
                      "reason": "bearing.static_load_rating (C0, N) is needed under axial load"}
    else:
        r1, r2, s1, s2 = consts
        sk = skf_friction_torque(g.type, g.bore * 1e3, g.outside_diameter * 1e3, n, nu, fr, fa,
                                 r1=r1, r2=r2, s1=s1, s2=s2, lubrication=opts.lubrication,
                                 static_load_rating=g.static_load_rating)
        out["skf"] = {"torque": sk["M"] * 1e-3, "heat_power": sk["M"] * 1e-3 * omega,
                      "torque_rolling": sk["M_rr"] * 1e-3, "torque_sliding": sk["M_sl"] * 1e-3,
                      "torque_seal": 0.0, "torque_drag": 0.0,
                      "source": "SKF four-component model (SKF catalogue); open bearing, "
                                "drag not evaluated",
                      "parameters": {"R1": r1, "R2": r2 if g.is_ball else None, "S1": s1,
                                     "S2": s2,
                                     "phi_ish": sk["phi_ish"], "phi_rs": sk["phi_rs"],
                                     "mu_sl": sk["mu_sl"], "lubrication": opts.lubrication}}
    if opts.nikitin_flow_ratio is not None:
        if not g.is_ball:
            out["nikitin"] = {"available": False,
                              "reason": "Nikitin's model is fitted on ball bearings"}
        else:
            out["nikitin"] = _nikitin_entry(bearing, n, nu_m2s, fr, fa, omega)
    return out


def _nikitin_entry(bearing: Bearing, rpm: float, nu_m2s: float, fr: float, fa: float,
                   omega: float) -> dict[str, Any]:
    """Nikitin's total loss and its split for a ball bearing (``empirical_models``), or
    ``{"available": False, ...}`` when his criteria overflow (an oil and speed far outside
    the fitted range)."""
    g, lub, opts = bearing.geometry, bearing.lubricant, bearing.empirical
    a_th = lub.thermal_conductivity / (lub.density * lub.specific_heat)
    args = (rpm, g.bore, g.outside_diameter, g.element_diameter, g.contact_angle,
            g.elements, nu_m2s, lub.density, a_th, fr, fa)
    material = "ceramic" if bearing.materials.elements == "si3n4" else "steel"
    try:
        tot = nikitin_power_loss(*args, flow_ratio=opts.nikitin_flow_ratio,
                                 coefficient_set=opts.nikitin_set)
        split = nikitin_split(*args, material=material, flow_range="max")
        finite = all(math.isfinite(v) for v in (tot["heat_power"], *split.values()))
    except OverflowError:
        finite = False
    if not finite:
        return {"available": False,
                "reason": "Nikitin's criteria overflow for this oil and speed (Re, Pr or Eu "
                          "beyond double precision): far outside the fitted range"}
    return {"torque": tot["heat_power"] / omega, "heat_power": tot["heat_power"],
            "friction_heat_power": split["friction"], "churning_heat_power": split["churning"],
            "friction_coefficient": split["friction_coefficient"],
            "source": "Nikitin (2011): Q = phi m rho d_b^2 u^3 (criterial); split by the "
                      f"{material} coefficients at the maximum oil flow",
            "parameters": {"flow_ratio": opts.nikitin_flow_ratio,
                           "coefficient_set": opts.nikitin_set, "Re": tot["Re"],
                           "Pr": tot["Pr"], "Eu": tot["Eu"], "cage_speed_m_s": tot["u"]}}

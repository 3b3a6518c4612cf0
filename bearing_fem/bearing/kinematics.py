"""Rolling kinematics of a bearing: cage speed, entrainment speeds, slide-to-roll ratios.

Inner ring rotating at omega_i, outer ring fixed, pure rolling at every contact (the
default and only kinematic model): seen from the cage, the inner raceway moves at
(omega_i - omega_c) r_i, the outer raceway at omega_c r_o, and the element surface at
both contacts at omega_R D_w/2. Pure rolling at both contacts gives

    omega_c = omega_i r_i / (r_i + r_o),   u_m = omega_i r_i r_o / (r_i + r_o),

the same entrainment (mean) speed u_m at the inner and outer contact and slide-to-roll
ratio 0. With equal contact angles r_i + r_o = d_m, so omega_c = omega_i (1 - gamma)/2
and u_m = omega_i d_m (1 - gamma^2)/4 (gamma = D_w cos(alpha)/d_m; Harris & Kotzalas).
Each element takes the cage speed of its own contact angles.

Neglected (see docs/bearing.md): spin about the contact normal of ball contacts at a
contact angle, the micro-slip of the curved ball-groove contact (Heathcote), the
gyroscopic moment of the balls, cage slip and the drag of the oil on the elements and
the cage. The centrifugal force of the elements is an option of the load distribution
(``model.centrifugal``).

The first part of the module keeps the roller-bearing helpers of earlier versions
(:func:`cylindrical_roller_contacts`, :func:`max_line_load`). Only numpy and the
bearing geometry here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..validation import require_finite, require_positive
from .geometry import contact_radii

__all__ = ["RollerContacts", "cylindrical_roller_contacts", "max_line_load",
           "ElementKinematics", "element_kinematics"]



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
    dm = require_positive("pitch_diameter", pitch_diameter, "m")
    dw = require_positive("roller_diameter", roller_diameter, "m")
    n = require_positive("inner_rpm", inner_rpm, "1/min")
    if dw >= dm:
        raise ValueError(f"roller_diameter must be < pitch_diameter (m), got {dw!r} >= {dm!r}")
    k = element_kinematics(2.0 * math.pi * n / 60.0, dm, dw, 0.0, 0.0)
    return RollerContacts(dm, dw, dw / dm, float(k.entrainment_speed),
                          float(k.cage_speed), float(k.rx_inner), float(k.rx_outer))


def max_line_load(radial_load: float, rollers: int, roller_length: float,
                  k: float = 4.6) -> float:
    """Line load of the most loaded roller by the rule q_H = K Fr/(z l_w) [N/m]
    (Yachikov & Vostrikov 2015).

    radial_load Fr [N]; rollers z (all rows); roller_length l_w [m]; k: K [-]
    (Stribeck's 4.08 for zero clearance, ~4.6 with clearance).
    """
    fr = require_positive("radial_load", radial_load, "N")
    if isinstance(rollers, bool) or not isinstance(rollers, int) or rollers < 1:
        raise ValueError(f"rollers must be a positive integer, got {rollers!r}")
    lw = require_positive("roller_length", roller_length, "m")
    return require_positive("k", k, "(dimensionless)") * fr / (rollers * lw)


@dataclass(frozen=True)
class ElementKinematics:
    """Pure-rolling kinematics of rolling elements (arrays over elements).

    Attributes
    ----------
    cage_speed : omega_c [rad/s] (each element's own pure-rolling orbital speed).
    element_speed : omega_R [rad/s], spin of the element about its own axis.
    entrainment_speed : u_m [m/s], the same at the inner and outer contact.
    race_radius_inner, race_radius_outer : r_i, r_o [m].
    rx_inner, rx_outer : reduced radii along the rolling direction [m].
    slide_to_roll_inner, slide_to_roll_outer : SRR = (u_ring - u_element)/u_m [-] (0).
    """

    cage_speed: np.ndarray
    element_speed: np.ndarray
    entrainment_speed: np.ndarray
    race_radius_inner: np.ndarray
    race_radius_outer: np.ndarray
    rx_inner: np.ndarray
    rx_outer: np.ndarray
    slide_to_roll_inner: np.ndarray
    slide_to_roll_outer: np.ndarray


def element_kinematics(inner_speed: float, pitch_diameter: float, element_diameter: float,
                       alpha_inner: float | np.ndarray,
                       alpha_outer: float | np.ndarray) -> ElementKinematics:
    """Pure-rolling kinematics at the given contact angles.

    Parameters
    ----------
    inner_speed : float
        omega_i [rad/s] (outer ring fixed).
    pitch_diameter, element_diameter : float
        d_m, D_w [m].
    alpha_inner, alpha_outer : float or array
        Contact angles [rad].

    Returns
    -------
    ElementKinematics

    Raises
    ------
    ValueError
        A non-finite speed, a diameter <= 0 or D_w >= d_m, a non-finite angle.
    """
    wi = require_finite("inner_speed", inner_speed, "rad/s")
    ri, ro, rxi, rxo = contact_radii(pitch_diameter, element_diameter, alpha_inner,
                                     alpha_outer)
    wc = wi * ri / (ri + ro)
    u = wi * ri * ro / (ri + ro)
    zero = np.zeros(np.shape(u))
    return ElementKinematics(cage_speed=wc, element_speed=u / (0.5 * float(element_diameter)),
                             entrainment_speed=u, race_radius_inner=ri,
                             race_radius_outer=ro, rx_inner=rxi, rx_outer=rxo,
                             slide_to_roll_inner=zero, slide_to_roll_outer=zero.copy())

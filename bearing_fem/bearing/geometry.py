"""Contact geometry of a bearing: raceway radii, reduced radii, E', contact stiffness.

Symbols (SI; see docs/bearing.md, section "Geometry"):

==========  ==================================================  =======
symbol      meaning                                             unit
==========  ==================================================  =======
d_m         pitch diameter                                      m
D_w         ball or roller diameter                             m
alpha       contact angle (0 for radial line contacts)          rad
gamma       D_w cos(alpha) / d_m                                -
r_i, r_o    raceway radius at the contact, from the bearing     m
            axis: (d_m -+ D_w cos alpha)/2
R_x         reduced radius along the rolling direction:         m
            inner D_w (1 - gamma)/2, outer D_w (1 + gamma)/2
R_y         ball contacts, across: f D_w/(2 f - 1)               m
            (f = groove radius / D_w; the ball radius D_w/2 and the
            concave groove radius -f D_w combined)
A           distance between the groove curvature centres       m
            (f_i + f_o - 1) D_w
E'          reduced modulus of ring and element                 Pa
==========  ==================================================  =======

Load-deflection laws: ball contacts Q = K delta^(3/2) with K from the exact Hertz
solution (:func:`bearing_fem.units.hertz_point`); roller contacts Palmgren's
delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N; Harris & Kotzalas), scaled to other materials
by (E'_steel / E')^0.9. Only numpy/scipy and :mod:`bearing_fem.units` here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import units
from ..validation import require_finite, require_positive, shown
from .description import Bearing

__all__ = ["ContactGeometry", "contact_geometry", "contact_radii", "reduced_modulus",
           "ball_stiffness",
           "PALMGREN_LINE_COMPLIANCE", "PALMGREN_REFERENCE_MODULUS", "roller_compliance",
           "groove_centre_distance", "free_contact_angle", "radial_clearance"]

#: Palmgren's roller-raceway approach delta = C Q^0.9 l^-0.8 in SI units [m N^-0.9 m^0.8]:
#: delta_mm = 3.84e-5 Q^0.9 l_mm^-0.8, so C = 1e-3 * 3.84e-5 * (1e3)^-0.8 = 3.84e-8 * 10^-2.4.
PALMGREN_LINE_COMPLIANCE = 3.84e-8 * 10.0 ** (-2.4)
#: E' of the steel bodies behind Palmgren's formula (E = 207.5 GPa, nu = 0.3) [Pa].
PALMGREN_REFERENCE_MODULUS = 2.075e11 / (1.0 - 0.3**2)


def reduced_modulus(bearing: Bearing) -> float:
    """E' [Pa] of a ring and a rolling element (Hamrock's convention)."""
    e1, nu1 = bearing.materials.ring
    e2, nu2 = bearing.materials.element
    return units.reduced_modulus(e1, nu1, e2, nu2)


def groove_centre_distance(bearing: Bearing) -> float:
    """A = (f_i + f_o - 1) D_w [m], distance between the groove curvature centres."""
    g = bearing.geometry
    return (g.inner_conformity + g.outer_conformity - 1.0) * g.element_diameter


def free_contact_angle(bearing: Bearing) -> float:
    """Unloaded contact angle alpha_0 [rad] once the clearance is taken up axially.

    Angular-contact ball bearings: the nominal angle. Deep-groove ball bearings:
    cos alpha_0 = 1 - c_r / A (Harris & Kotzalas), 0 without clearance. Rollers: the
    nominal angle (0 for cylindrical).
    """
    g = bearing.geometry
    if g.type == "deep-groove-ball":
        return math.acos(1.0 - g.radial_clearance / groove_centre_distance(bearing))
    return math.radians(g.contact_angle)


def radial_clearance(bearing: Bearing) -> float:
    """Radial clearance c_r [m]; for angular-contact ball bearings A (1 - cos alpha_0)."""
    g = bearing.geometry
    if g.type == "angular-contact-ball":
        return groove_centre_distance(bearing) * (1.0 - math.cos(math.radians(g.contact_angle)))
    return float(g.radial_clearance)


@dataclass(frozen=True)
class ContactGeometry:
    """Radii of one rolling element's inner and outer contact at contact angles.

    Attributes
    ----------
    gamma_inner, gamma_outer : D_w cos(alpha)/d_m [-] at each contact.
    race_radius_inner, race_radius_outer : r_i, r_o [m], raceway radius at the contact
        measured from the bearing axis.
    rx_inner, rx_outer : reduced radii along the rolling direction [m].
    ry_inner, ry_outer : reduced radii across it [m] (balls; None for rollers).
    element_radius : D_w/2 [m], the rolling radius of the element.
    """

    gamma_inner: np.ndarray
    gamma_outer: np.ndarray
    race_radius_inner: np.ndarray
    race_radius_outer: np.ndarray
    rx_inner: np.ndarray
    rx_outer: np.ndarray
    ry_inner: float | None
    ry_outer: float | None
    element_radius: float


def contact_radii(pitch_diameter: float, element_diameter: float,
                  alpha_inner: float | np.ndarray, alpha_outer: float | np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(r_i, r_o, R_x,inner, R_x,outer) [m] at contact angles ``alpha_inner``, ``alpha_outer``.

    r_i,o = (d_m -+ D_w cos alpha)/2 (raceway radius at the contact, from the bearing
    axis); R_x = D_w (1 -+ gamma)/2, gamma = D_w cos(alpha)/d_m: the element radius D_w/2
    and the raceway's normal-section radius r/cos(alpha) (convex inner, concave outer).

    Parameters
    ----------
    pitch_diameter, element_diameter : float
        d_m > D_w > 0 [m].
    alpha_inner, alpha_outer : float or array
        Contact angles [rad] in (-pi/2, pi/2), of one shape.

    Raises
    ------
    ValueError
        Naming the argument, its value and unit.
    """
    for name, value in (("pitch_diameter", pitch_diameter),
                        ("element_diameter", element_diameter)):
        if np.ndim(value) != 0:
            raise ValueError(f"{name} must be one number in m, got {shown(value)}")
    dm = require_positive("pitch_diameter", pitch_diameter, "m")
    dw = require_positive("element_diameter", element_diameter, "m")
    if dw >= dm:
        raise ValueError(f"element_diameter must be smaller than pitch_diameter (m), got "
                         f"{dw!r} m >= {dm!r} m")
    angles = []
    for name, value in (("alpha_inner", alpha_inner), ("alpha_outer", alpha_outer)):
        a = require_finite(name, value, "rad")
        if np.any(np.abs(a) >= 0.5 * math.pi):
            raise ValueError(f"{name} must lie in (-pi/2, pi/2) rad (a contact angle in "
                             f"radians, not degrees), got {shown(value)}")
        angles.append(np.asarray(a))
    if angles[0].shape != angles[1].shape:
        raise ValueError(f"alpha_inner and alpha_outer must have one shape, got "
                         f"{angles[0].shape} and {angles[1].shape}")
    ci, co = np.cos(angles[0]), np.cos(angles[1])
    return (0.5 * (dm - dw * ci), 0.5 * (dm + dw * co), 0.5 * dw * (1.0 - dw * ci / dm),
            0.5 * dw * (1.0 + dw * co / dm))


def contact_geometry(bearing: Bearing, alpha_inner: float | np.ndarray,
                     alpha_outer: float | np.ndarray) -> ContactGeometry:
    """Contact radii at the contact angles ``alpha_inner``, ``alpha_outer`` [rad] (arrays)."""
    g = bearing.geometry
    dm, dw = g.mean_diameter, g.element_diameter
    ri, ro, rxi, rxo = contact_radii(dm, dw, alpha_inner, alpha_outer)
    ry_i = ry_o = None
    if g.is_ball:
        fi, fo = g.inner_conformity, g.outer_conformity
        ry_i = fi * dw / (2.0 * fi - 1.0)
        ry_o = fo * dw / (2.0 * fo - 1.0)
    return ContactGeometry(gamma_inner=1.0 - 2.0 * rxi / dw, gamma_outer=2.0 * rxo / dw - 1.0,
                           race_radius_inner=ri, race_radius_outer=ro, rx_inner=rxi,
                           rx_outer=rxo, ry_inner=ry_i, ry_outer=ry_o, element_radius=0.5 * dw)


def ball_stiffness(bearing: Bearing, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Hertz constants K_i, K_o [N/m^1.5] of Q = K delta^1.5 at contact angles ``alpha``.

    From the exact elliptical Hertz solution at Q = 1 N: K = 1 / delta(1 N)^1.5.
    """
    e_prime = reduced_modulus(bearing)
    alpha = np.atleast_1d(np.asarray(alpha, dtype=float))
    cg = contact_geometry(bearing, alpha, alpha)
    k_i = np.array([units.hertz_point(1.0, rx, cg.ry_inner, e_prime).delta ** -1.5
                    for rx in cg.rx_inner])
    k_o = np.array([units.hertz_point(1.0, rx, cg.ry_outer, e_prime).delta ** -1.5
                    for rx in cg.rx_outer])
    return k_i, k_o


def roller_compliance(bearing: Bearing) -> float:
    """c [m N^-0.9] of one roller-raceway contact, delta = c Q^0.9 (Palmgren).

    c = 3.84e-5 (mm) scaled to SI, times l^-0.8 and (E'_steel / E')^0.9.
    """
    g = bearing.geometry
    scale = (PALMGREN_REFERENCE_MODULUS / reduced_modulus(bearing)) ** 0.9
    return PALMGREN_LINE_COMPLIANCE * g.effective_length ** -0.8 * scale

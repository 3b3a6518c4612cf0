"""Hertz, Hamrock and Moes scalings of line and point contacts (docs/theory.md sections 1, 13).

Symbols and units (SI throughout):

=============  =====================================================  =========
symbol         meaning                                                unit
=============  =====================================================  =========
e_prime (E')   reduced modulus 2/((1-nu1^2)/E1 + (1-nu2^2)/E2)        Pa
R, rx, ry      reduced radii (1/R = 1/r1 + 1/r2, concave negative)    m
w              load per unit length (line contact)                    N/m
F              load (point contact)                                   N
eta0           viscosity at ambient pressure                          Pa s
u_m            mean entrainment speed (u1 + u2)/2 along +x            m/s
alpha          Barus pressure-viscosity coefficient                   1/Pa
b, a           Hertz half-width (line) / contact radius (point)       m
p_h            maximum Hertz pressure                                 Pa
=============  =====================================================  =========

Velocity convention: the Hamrock groups ``U`` use the MEAN speed u_m; the Moes groups
``M``, ``L`` and ``H_Moes`` use the SUM speed through ``U_sum = 2 U`` (docs/theory.md section 13).
Both are returned by :func:`moes_line` and :func:`moes_point`, with names saying which.

This module imports numpy and scipy only.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from .validation import (require_finite, require_nonnegative, require_poisson,
                         require_positive)

__all__ = [
    "HertzPoint",
    "reduced_modulus",
    "reduced_radius",
    "hertz_line",
    "hertz_point",
    "moes_line",
    "moes_point",
    "venner_to_moes_line",
    "moes_to_venner_line",
    "venner_to_moes_point",
    "moes_to_venner_point",
    "line_scene_from_moes",
    "point_scene_parameters_from_moes",
    "point_scene_from_moes",
    "hamrock_ellipticity",
]

#: Default reference viscosity of the inverse maps (Pa s) when neither viscosity nor
#: speed is given; a mineral oil of ISO VG 32-68 class at 40 C.
DEFAULT_VISCOSITY = 0.01


# ----------------------------------------------------------------------------------------
# materials and geometry
# ----------------------------------------------------------------------------------------
def reduced_modulus(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """Reduced (Hamrock) modulus E' of two elastic bodies, docs/theory.md section 1.

    E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2). Johnson's E* is E'/2.

    Parameters
    ----------
    e1, e2 : float
        Young's moduli of the two bodies [Pa], > 0 (``inf`` for a rigid body).
    nu1, nu2 : float
        Poisson ratios [-], in (-1, 0.5].

    Returns
    -------
    float
        E' [Pa].
    """
    for name, e in (("e1", e1), ("e2", e2)):
        if not (e > 0.0):
            raise ValueError(f"{name} must be > 0 Pa, got {e!r}")
    require_poisson("nu1", nu1)
    require_poisson("nu2", nu2)
    compliance = (1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2
    if not compliance > 0.0:
        raise ValueError("both bodies are rigid (e1 = e2 = inf Pa): E' is infinite")
    return float(2.0 / compliance)


def reduced_radius(r1: float, r2: float) -> float:
    """Reduced radius of curvature, 1/R = 1/r1 + 1/r2 (docs/theory.md section 1).

    Parameters
    ----------
    r1, r2 : float
        Radii of curvature of the two surfaces [m]; convex > 0, concave (e.g. an outer
        race groove) < 0, flat ``inf``.

    Returns
    -------
    float
        R [m], > 0.

    Raises
    ------
    ValueError
        If a radius is zero or NaN, or if 1/r1 + 1/r2 <= 0 (the surfaces do not form a
        converging gap: conformal or diverging contact).
    """
    for name, r in (("r1", r1), ("r2", r2)):
        if r == 0.0 or not np.isfinite(1.0 / r) or np.isnan(r):
            raise ValueError(f"{name} must be a non-zero radius in m (inf = flat), got {r!r}")
    curvature = 1.0 / r1 + 1.0 / r2
    if not curvature > 0.0:
        raise ValueError(
            f"1/r1 + 1/r2 must be > 0 1/m (converging gap), got {curvature!r} 1/m "
            f"from r1 = {r1!r} m, r2 = {r2!r} m")
    return float(1.0 / curvature)


# ----------------------------------------------------------------------------------------
# Hertz
# ----------------------------------------------------------------------------------------
def hertz_line(load_per_length: float, radius: float, e_prime: float) -> tuple[float, float]:
    """Hertz line contact (docs/theory.md section 13): b = sqrt(8 w R/(pi E')), p_h = 2 w/(pi b).

    Parameters
    ----------
    load_per_length : float
        w [N/m], > 0.
    radius : float
        Reduced radius R [m], > 0.
    e_prime : float
        Reduced modulus E' [Pa], > 0.

    Returns
    -------
    (b, p_h) : tuple of float
        Half-width b [m] and maximum pressure p_h [Pa] (= E' b/(4R)).
    """
    require_positive("load_per_length", load_per_length, "N/m")
    require_positive("radius", radius, "m")
    require_positive("e_prime", e_prime, "Pa")
    b = float(np.sqrt(8.0 * load_per_length * radius / (np.pi * e_prime)))
    p_h = float(2.0 * load_per_length / (np.pi * b))
    return b, p_h


@dataclass(frozen=True)
class HertzPoint:
    """Hertz (dry, frictionless) elliptical point contact.

    Attributes
    ----------
    a_x : float
        Semi-axis along the rolling direction x [m].
    a_y : float
        Semi-axis across the rolling direction y [m].
    p_h : float
        Maximum (centre) pressure 3F/(2 pi a_x a_y) [Pa].
    delta : float
        Mutual approach of distant points of the two bodies [m].
    k : float
        Ellipticity a_y / a_x [-] (> 1 when ry > rx, as in Hamrock's convention).
    """

    a_x: float
    a_y: float
    p_h: float
    delta: float
    k: float

    @property
    def a(self) -> float:
        """Geometric-mean radius sqrt(a_x a_y) [m] (the contact radius when circular)."""
        return float(np.sqrt(self.a_x * self.a_y))


def _ellipse_ratio(m: float) -> float:
    """Curvature ratio B/A (along minor / along major axis) for Hertz eccentricity m = e^2.

    Johnson (1985) eq. 3.35: with a the semi-major axis, A the gap curvature coefficient
    along it, B along the minor axis, B/A = [E(m)/(1 - m) - K(m)] / [K(m) - E(m)].
    """
    kk, ee = ellipk(m), ellipe(m)
    return float((ee / (1.0 - m) - kk) / (kk - ee))


def _k_minus_e_over_m(m: float) -> float:
    """(K(m) - E(m)) / m, with its series pi/4 (1 + 3m/8) for tiny m (no cancellation)."""
    if m < 1e-6:
        return float(np.pi / 4.0 * (1.0 + 3.0 * m / 8.0))
    return float((ellipk(m) - ellipe(m)) / m)


def hertz_point(force: float, rx: float, ry: float, e_prime: float) -> HertzPoint:
    """Hertz elliptical point contact from the exact elliptic-integral solution.

    The gap is h = x^2/(2 rx) + y^2/(2 ry). The major semi-axis lies along the direction
    of the LARGER radius. With m = e^2 = 1 - (minor/major)^2, K(m), E(m) the complete
    elliptic integrals (scipy ``ellipk``/``ellipe``, parameter m) and A_J = 1/(2 R_major),
    Johnson (1985, eqs. 3.35-3.36, with E* = E'/2) gives

    - ratio:  R_major/R_minor = [E/(1 - m) - K] / (K - E)   (solved for m with brentq),
    - size:   a_major^3 = 3 F (K - E) / (pi E' m A_J),  a_minor = a_major sqrt(1 - m),
    - p_h = 3 F / (2 pi a_x a_y),  delta = 2 p_h a_minor K / E'.

    The circular case rx == ry is exact: a = (3 F R/(2 E'))^(1/3), p_h = 3F/(2 pi a^2),
    delta = a^2/R (docs/theory.md section 13). For |ratio - 1| < 1e-6 the series m = (4/3)(ratio - 1)
    is used (relative error of a, p_h below 1e-12).

    Parameters
    ----------
    force : float
        Normal load F [N], > 0.
    rx, ry : float
        Reduced radii along x (rolling) and y (across) [m], > 0.
    e_prime : float
        Reduced modulus E' [Pa], > 0.

    Returns
    -------
    HertzPoint
        Semi-axes a_x, a_y [m], p_h [Pa], approach delta [m], ellipticity k = a_y/a_x.
    """
    require_positive("force", force, "N")
    require_positive("rx", rx, "m")
    require_positive("ry", ry, "m")
    require_positive("e_prime", e_prime, "Pa")
    r_major, r_minor = (ry, rx) if ry >= rx else (rx, ry)
    ratio = r_major / r_minor
    if ratio == 1.0:
        m = 0.0
    elif ratio - 1.0 < 1e-6:
        m = 4.0 / 3.0 * (ratio - 1.0)
    else:
        # ratio(m) increases monotonically from 1 (m = 0) to inf (m -> 1); solve in
        # s = -log10(1 - m) so that very slender ellipses are resolved.
        def resid(s: float) -> float:
            return np.log(_ellipse_ratio(-np.expm1(-s * np.log(10.0)))) - np.log(ratio)

        s_hi = 1.0
        while resid(s_hi) < 0.0:
            s_hi *= 2.0
            if s_hi > 15.0:
                raise ValueError(
                    f"ry/rx = {ry / rx!r} is too extreme for a Hertz point contact "
                    "(ellipticity beyond 1e7); treat it as a line contact")
        s = brentq(resid, 1e-12, s_hi, xtol=1e-15, rtol=1e-14)
        m = float(-np.expm1(-s * np.log(10.0)))
    a_j = 1.0 / (2.0 * r_major)
    a_major = (3.0 * force * _k_minus_e_over_m(m) / (np.pi * e_prime * a_j)) ** (1.0 / 3.0)
    a_minor = a_major * np.sqrt(1.0 - m)
    p_h = 3.0 * force / (2.0 * np.pi * a_major * a_minor)
    delta = 2.0 * p_h * a_minor * float(ellipk(m)) / e_prime
    a_x, a_y = (a_minor, a_major) if ry >= rx else (a_major, a_minor)
    return HertzPoint(a_x=float(a_x), a_y=float(a_y), p_h=float(p_h), delta=float(delta),
                      k=float(a_y / a_x))


def hamrock_ellipticity(rx: float, ry: float) -> float:
    """Hamrock-Brewe approximate ellipticity k = 1.03 (ry/rx)^0.64 [-] (docs/theory.md section 16).

    This is the k used in the Hamrock-Dowson fits; :func:`hertz_point` gives the exact one
    (they agree within 3% for 1 <= ry/rx <= 30; the fit is 8% high at ry/rx = 100).
    """
    require_positive("rx", rx, "m")
    require_positive("ry", ry, "m")
    return float(1.03 * (ry / rx) ** 0.64)


# ----------------------------------------------------------------------------------------
# Moes / Venner groups
# ----------------------------------------------------------------------------------------
def _check_lubricant(viscosity: float, mean_speed: float, piezo: float) -> None:
    require_positive("viscosity", viscosity, "Pa s")
    require_positive("mean_speed", mean_speed, "m/s")
    require_nonnegative("piezo", piezo, "1/Pa")


def moes_line(load_per_length: float, radius: float, e_prime: float, viscosity: float,
              mean_speed: float, piezo: float) -> dict[str, float]:
    """Dimensionless groups of a line contact (docs/theory.md section 13).

    Parameters
    ----------
    load_per_length : float
        w [N/m].
    radius : float
        Reduced radius R [m].
    e_prime : float
        Reduced modulus E' [Pa].
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m = (u1 + u2)/2 [m/s], > 0.
    piezo : float
        Barus alpha [1/Pa], >= 0.

    Returns
    -------
    dict
        ``W`` = w/(E' R), ``U`` = eta0 u_m/(E' R) (mean speed), ``G`` = alpha E',
        ``U_sum`` = 2 U, ``M`` = W U_sum^(-1/2), ``L`` = G U_sum^(1/4) (Moes, sum speed),
        ``b`` [m], ``p_h`` [Pa] (Hertz), ``alpha_ph`` = alpha p_h [-].
    """
    b, p_h = hertz_line(load_per_length, radius, e_prime)
    _check_lubricant(viscosity, mean_speed, piezo)
    w_dim = load_per_length / (e_prime * radius)
    u_dim = viscosity * mean_speed / (e_prime * radius)
    g_dim = piezo * e_prime
    u_sum = 2.0 * u_dim
    return {"W": w_dim, "U": u_dim, "G": g_dim, "U_sum": u_sum,
            "M": w_dim * u_sum ** -0.5, "L": g_dim * u_sum ** 0.25,
            "b": b, "p_h": p_h, "alpha_ph": piezo * p_h}


def venner_to_moes_line(H: Any, M: Any) -> Any:
    """Venner film H = h R/b^2 -> Moes film H_Moes = (h/R) U_sum^(-1/2): H_Moes = 8 M H/pi.

    Parameters
    ----------
    H : float or array
        Venner dimensionless film [-].
    M : float or array
        Moes load parameter [-].
    """
    return 8.0 * np.asarray(M) * np.asarray(H) / np.pi


def moes_to_venner_line(H_moes: Any, M: Any) -> Any:
    """Moes film -> Venner film for a line contact: H = pi H_Moes / (8 M) (docs/theory.md section 13)."""
    return np.pi * np.asarray(H_moes) / (8.0 * np.asarray(M))


def moes_point(force: float, rx: float, ry: float, e_prime: float, viscosity: float,
               mean_speed: float, piezo: float) -> dict[str, float]:
    """Dimensionless groups of a point contact (docs/theory.md section 13), Hertz from :func:`hertz_point`.

    Parameters
    ----------
    force : float
        F [N].
    rx, ry : float
        Reduced radii along and across the rolling direction [m].
    e_prime : float
        E' [Pa].
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s].
    piezo : float
        alpha [1/Pa].

    Returns
    -------
    dict
        ``W`` = F/(E' rx^2), ``U`` = eta0 u_m/(E' rx) (mean speed), ``G`` = alpha E',
        ``U_sum`` = 2U, ``M`` = W U_sum^(-3/4), ``L`` = G U_sum^(1/4) (sum speed),
        ``a`` = a_x [m] (semi-axis along x; the radius when circular), ``a_x``, ``a_y`` [m],
        ``p_h`` [Pa], ``alpha_ph`` [-], ``k`` = a_y/a_x [-] (exact Hertz),
        ``delta`` [m], ``lam`` = rx/ry [-] (Nijenbanning's lambda).
    """
    hp = hertz_point(force, rx, ry, e_prime)
    _check_lubricant(viscosity, mean_speed, piezo)
    w_dim = force / (e_prime * rx**2)
    u_dim = viscosity * mean_speed / (e_prime * rx)
    g_dim = piezo * e_prime
    u_sum = 2.0 * u_dim
    return {"W": w_dim, "U": u_dim, "G": g_dim, "U_sum": u_sum,
            "M": w_dim * u_sum ** -0.75, "L": g_dim * u_sum ** 0.25,
            "a": hp.a_x, "a_x": hp.a_x, "a_y": hp.a_y, "p_h": hp.p_h,
            "alpha_ph": piezo * hp.p_h, "k": hp.k, "delta": hp.delta, "lam": rx / ry}


def venner_to_moes_point(H: Any, M: Any) -> Any:
    """Circular contact: Venner H = h R/a^2 -> H_Moes = H (3M/2)^(2/3) (docs/theory.md section 13)."""
    return np.asarray(H) * (1.5 * np.asarray(M)) ** (2.0 / 3.0)


def moes_to_venner_point(H_moes: Any, M: Any) -> Any:
    """Circular contact: H_Moes -> Venner H = H_Moes (3M/2)^(-2/3) (docs/theory.md section 13)."""
    return np.asarray(H_moes) * (1.5 * np.asarray(M)) ** (-2.0 / 3.0)


# ----------------------------------------------------------------------------------------
# inverse maps: (M, L) -> dimensional operating point
# ----------------------------------------------------------------------------------------
def _moes_sum_speed(M: float, L: float, e_prime: float, piezo: float,
                    **radii: float) -> float:
    """Check the inputs of the Moes inverse maps (M, L, the radii [m], E' [Pa],
    alpha [1/Pa], all > 0) and return U_sum = (L/(alpha E'))^4 [-]."""
    require_positive("M", M, "(dimensionless)")
    require_positive("L", L, "(dimensionless)")
    for name, value in radii.items():
        require_positive(name, value, "m")
    require_positive("e_prime", e_prime, "Pa")
    require_positive("piezo", piezo, "1/Pa")
    return (L / (piezo * e_prime)) ** 4


def _speed_and_viscosity(u_sum: float, length: float, e_prime: float,
                         viscosity: float | None, mean_speed: float | None
                         ) -> tuple[float, float]:
    """Split U_sum = 2 eta0 u_m/(E' R) into (eta0, u_m), one of them given."""
    if viscosity is not None and mean_speed is not None:
        raise ValueError("give viscosity (Pa s) or mean_speed (m/s), not both: "
                         "(M, L) fix only their product")
    if mean_speed is None:
        eta = DEFAULT_VISCOSITY if viscosity is None else viscosity
        require_positive("viscosity", eta, "Pa s")
        return eta, u_sum * e_prime * length / (2.0 * eta)
    require_positive("mean_speed", mean_speed, "m/s")
    return u_sum * e_prime * length / (2.0 * mean_speed), mean_speed


def line_scene_from_moes(M: float, L: float, *, radius: float = 0.01,
                         e_prime: float = 2.2e11, piezo: float = 2.0e-8,
                         viscosity: float | None = None,
                         mean_speed: float | None = None) -> dict[str, float]:
    """Dimensional line-contact operating point realising the Moes pair (M, L).

    Convention: R, E' and alpha are fixed (so G = alpha E'); then
    U_sum = (L/G)^4 and w = M U_sum^(1/2) E' R. The product eta0 u_m = U_sum E' R/2 is
    split by fixing ONE of ``viscosity`` or ``mean_speed`` (if neither is given,
    eta0 = ``DEFAULT_VISCOSITY`` = 0.01 Pa s).

    Parameters
    ----------
    M, L : float
        Moes load and lubricant parameters [-], M > 0, L > 0.
    radius : float
        R [m].
    e_prime : float
        E' [Pa].
    piezo : float
        alpha [1/Pa], > 0 (L > 0 needs a piezo-viscous lubricant).
    viscosity : float, optional
        eta0 [Pa s].
    mean_speed : float, optional
        u_m [m/s].

    Returns
    -------
    dict
        ``load_per_length`` [N/m], ``mean_speed`` [m/s], ``viscosity`` [Pa s],
        ``piezo`` [1/Pa], ``radius`` [m], ``e_prime`` [Pa].
    """
    u_sum = _moes_sum_speed(M, L, e_prime, piezo, radius=radius)
    eta, u_m = _speed_and_viscosity(u_sum, radius, e_prime, viscosity, mean_speed)
    return {"load_per_length": float(M * np.sqrt(u_sum) * e_prime * radius),
            "mean_speed": float(u_m), "viscosity": float(eta), "piezo": float(piezo),
            "radius": float(radius), "e_prime": float(e_prime)}


def point_scene_parameters_from_moes(M: float, L: float, *, rx: float = 0.01,
                                     ry: float | None = None, e_prime: float = 2.2e11,
                                     piezo: float = 2.0e-8,
                                     viscosity: float | None = None,
                                     mean_speed: float | None = None) -> dict[str, float]:
    """Dimensional point-contact operating point realising the Moes pair (M, L).

    Same convention as :func:`line_scene_from_moes`: rx, ry, E', alpha fixed,
    U_sum = (L/G)^4, F = M U_sum^(3/4) E' rx^2, and one of eta0, u_m fixed.

    Parameters
    ----------
    M, L : float
        Moes parameters [-].
    rx : float
        Reduced radius along x [m].
    ry : float, optional
        Reduced radius across [m]; default ``rx`` (circular contact).
    e_prime : float
        E' [Pa].
    piezo : float
        alpha [1/Pa].
    viscosity, mean_speed : float, optional
        eta0 [Pa s] or u_m [m/s] (not both; default eta0 = 0.01 Pa s).

    Returns
    -------
    dict
        ``force`` [N], ``mean_speed`` [m/s], ``viscosity`` [Pa s], ``piezo`` [1/Pa],
        ``rx``, ``ry`` [m], ``e_prime`` [Pa].
    """
    ry = rx if ry is None else ry
    u_sum = _moes_sum_speed(M, L, e_prime, piezo, rx=rx, ry=ry)
    eta, u_m = _speed_and_viscosity(u_sum, rx, e_prime, viscosity, mean_speed)
    return {"force": float(M * u_sum**0.75 * e_prime * rx**2), "mean_speed": float(u_m),
            "viscosity": float(eta), "piezo": float(piezo), "rx": float(rx),
            "ry": float(ry), "e_prime": float(e_prime)}


#: Alias with the naming of :func:`line_scene_from_moes`.
point_scene_from_moes = point_scene_parameters_from_moes

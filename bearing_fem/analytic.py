"""Closed-form oracles (docs/theory.md section 14), used by the tests and the studies.

Every oracle here is evaluated from its closed form; nothing is tabulated.
SI units unless a docstring says otherwise.
"""
from __future__ import annotations

import numpy as np

# ----------------------------------------------------------------------------------------
# Section A: Kapitsa (point/line, rigid), Martin (rigid cylinder), Hertz dry limits.
# ----------------------------------------------------------------------------------------

# Section A imports and helpers (kept inside this section so Section B stays independent).
import functools as _functools
from typing import Any as _Any

from scipy.optimize import brentq as _brentq

from .validation import require_finite, require_nonnegative, require_positive

# Symbols (Section A): x, y [m] (x along the entrainment, inlet at x < 0); h0 [m] central
# gap; a = 1/(2 rx), b = 1/(2 ry) [1/m] gap curvatures; eta0 = viscosity [Pa s];
# u_m = mean_speed [m/s]; dh0dt [m/s]; alpha = piezo [1/Pa]; q reduced pressure [Pa];
# p pressure [Pa]; R = radius [m]; E' = e_prime [Pa]; p_h [Pa].


def barus_from_reduced(q: _Any, piezo: _Any) -> np.ndarray:
    """Pressure from the Barus (Kapitsa) reduced pressure, docs/theory.md section 14.1.

    p = -ln(1 - alpha q)/alpha  (p = q when alpha = 0). Where alpha q >= 1 no pressure
    exists (the piezo-viscous solution has blown up) and ``inf`` is returned.

    Parameters
    ----------
    q : float or array
        Reduced pressure q = (1 - exp(-alpha p))/alpha [Pa].
    piezo : float or array
        Barus coefficient alpha [1/Pa], >= 0.

    Returns
    -------
    ndarray
        p [Pa] (``inf`` where alpha q >= 1).
    """
    require_nonnegative("piezo", piezo, "1/Pa")
    q = np.asarray(q, dtype=float)
    alpha = np.asarray(piezo, dtype=float)
    z = alpha * q
    safe_alpha = np.where(alpha > 0.0, alpha, 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        p = -np.log1p(-np.minimum(z, 0.5)) / safe_alpha
        p = np.where(z < 0.5, p, -np.log(np.maximum(1.0 - z, 0.0)) / safe_alpha)
    p = np.where(z >= 1.0, np.inf, p)
    return np.where(alpha > 0.0, p, q)


def reduced_from_barus(p: _Any, piezo: _Any) -> np.ndarray:
    """Barus (Kapitsa) reduced pressure q = (1 - exp(-alpha p))/alpha [Pa], docs/theory.md section 14.1.

    q = p when alpha = 0; q -> 1/alpha as p -> inf.

    Parameters
    ----------
    p : float or array
        Pressure [Pa].
    piezo : float or array
        alpha [1/Pa], >= 0.
    """
    require_nonnegative("piezo", piezo, "1/Pa")
    if isinstance(p, (str, bytes)):
        raise ValueError(f"p must be a number in Pa, got {p!r}")
    p = np.asarray(p, dtype=float)
    alpha = np.asarray(piezo, dtype=float)
    safe_alpha = np.where(alpha > 0.0, alpha, 1.0)
    with np.errstate(over="ignore", invalid="ignore"):
        q = -np.expm1(-alpha * p) / safe_alpha
    return np.where(alpha > 0.0, q, p)


#: Smallest Roelands pressure index Z = alpha p0 / (ln eta0 + 9.67) of the closed-form
#: reduced pressure: below it (alpha under about 3e-10 1/Pa) the incomplete gamma
#: functions of order 1/Z > 100 underflow, and the law is nearly isoviscous anyway.
ROELANDS_REDUCED_MIN_INDEX = 0.01


def _roelands_reduced_constants(viscosity: float, piezo: float) -> tuple[float, float, float]:
    """(a, A, ln C) of the Roelands reduced pressure: a = 1/Z, A = ln eta0 + 9.67 and
    C = (p0/Z) e^A A^(-1/Z) Gamma(1/Z), so that q(p) = C [Q(a, A) - Q(a, A (1 + p/p0)^Z)]
    = C [P(a, A (1 + p/p0)^Z) - P(a, A)] with P, Q the regularised lower and upper
    incomplete gamma functions (the P form where A < a, where Q rounds to 1)."""
    from scipy.special import gammaln

    from .physics.rheology import ROELANDS_LN_ETA_INF, ROELANDS_P0, roelands_index

    require_positive("viscosity", viscosity, "Pa s")
    require_positive("piezo", piezo, "1/Pa")
    big_a = float(np.log(viscosity) - ROELANDS_LN_ETA_INF)
    if big_a <= 0.0:
        raise ValueError(f"viscosity must exceed exp(-9.67) = 6.3e-5 Pa s for the Roelands "
                         f"law (ln eta0 + 9.67 > 0), got {viscosity!r} Pa s")
    z = float(roelands_index(viscosity, piezo))
    if z < ROELANDS_REDUCED_MIN_INDEX:
        raise ValueError(f"the Roelands reduced pressure needs the pressure index Z = alpha p0 "
                         f"/ (ln eta0 + 9.67) >= {ROELANDS_REDUCED_MIN_INDEX:g}, got Z = "
                         f"{z:.3g} (piezo = {piezo!r} 1/Pa, viscosity = {viscosity!r} Pa s)")
    a = 1.0 / z
    log_c = float(np.log(ROELANDS_P0 / z) + big_a - a * np.log(big_a) + gammaln(a))
    return a, big_a, log_c


def _times_c(log_c: float, v: _Any) -> np.ndarray:
    """e^log_c v without forming e^log_c, which overflows (ln C above 709) for small
    ln eta0 + 9.67 and pressure indices near 0.01 while the product is a pressure."""
    v = np.asarray(v, dtype=float)
    with np.errstate(divide="ignore", over="ignore"):
        return np.sign(v) * np.exp(log_c + np.log(np.abs(v)))


def roelands_reduced_limit(viscosity: float, piezo: float) -> float:
    """Largest Roelands reduced pressure q_inf = int_0^inf eta0/eta(p) dp [Pa].

    The Roelands viscosity eta = eta0 exp{A[(1 + p/p0)^Z - 1]}, A = ln eta0 + 9.67, grows
    without bound, so the reduced pressure q = int_0^p eta0/eta ds of any pressure stays
    below q_inf = (p0/Z) e^A A^(-1/Z) Gamma(1/Z, A) (substitute t = (1 + s/p0)^Z: an upper
    incomplete gamma function). A rigid Roelands film exists only while q_max < q_inf,
    as a Barus film only while alpha q_max < 1 (Kapitsa); with the same low-pressure
    slope (Z = alpha p0/A) q_inf lies near 1/alpha for mineral oils.

    Parameters
    ----------
    viscosity : float
        eta0 [Pa s], above exp(-9.67) = 6.3e-5 Pa s.
    piezo : float
        alpha [1/Pa], > 0 (sets Z).

    Returns
    -------
    float
        q_inf [Pa]; ``inf`` where it exceeds the double range (nearly isoviscous laws:
        Z near 0.01 with ln eta0 + 9.67 below about 0.03).
    """
    from scipy.special import gammainc, gammaincc

    a, big_a, log_c = _roelands_reduced_constants(viscosity, piezo)
    upper = 1.0 - gammainc(a, big_a) if big_a < a else gammaincc(a, big_a)
    return float(_times_c(log_c, upper))


def reduced_from_roelands(p: _Any, viscosity: float, piezo: float) -> np.ndarray:
    """Roelands reduced pressure q = int_0^p eta0/eta(s) ds [Pa], p >= -p0 [Pa].

    q = C [Q(1/Z, A) - Q(1/Z, A (1 + p/p0)^Z)], C = (p0/Z) e^A A^(-1/Z) Gamma(1/Z) and
    Q the regularised upper incomplete gamma function (see
    :func:`roelands_reduced_limit`). With it the rigid isothermal Reynolds equation of
    an incompressible Roelands oil is the isoviscous one in q, as with Kapitsa's Barus
    transform. A negative pressure (an end pressure below ambient) has a negative q,
    down to q(-p0) = -C P(1/Z, A) where the law's base 1 + p/p0 reaches 0.

    Parameters
    ----------
    p : float or array
        Pressure [Pa], >= -p0 = -1.96e8 Pa.
    viscosity, piezo : float
        eta0 [Pa s] and alpha [1/Pa] of the law.
    """
    from scipy.special import gammainc, gammaincc

    from .physics.rheology import ROELANDS_P0

    a, big_a, log_c = _roelands_reduced_constants(viscosity, piezo)
    p = np.asarray(p, dtype=float)
    if np.any(p < -ROELANDS_P0) or not np.all(np.isfinite(p)):
        bad = p[(p < -ROELANDS_P0) | ~np.isfinite(p)].flat[0]
        raise ValueError(f"p must be finite and >= -p0 = {-ROELANDS_P0:g} Pa for the "
                         f"Roelands reduced pressure, got {float(bad):g} Pa")
    with np.errstate(over="ignore"):  # an infinite t has Q(1/Z, inf) = 0: q = q_inf
        t = (1.0 + p / ROELANDS_P0) ** (1.0 / a)
    if big_a < a:
        return _times_c(log_c, gammainc(a, big_a * t) - gammainc(a, big_a))
    return _times_c(log_c, gammaincc(a, big_a) - gammaincc(a, big_a * t))


def roelands_from_reduced(q: _Any, viscosity: float, piezo: float) -> np.ndarray:
    """Pressure from the Roelands reduced pressure [Pa]: the inverse of
    :func:`reduced_from_roelands`.

    p = p0 [(x/A)^(1/Z) - 1] with x = Q^-1(1/Z, Q(1/Z, A) - q/C) (the inverse regularised
    upper incomplete gamma function); ``inf`` where q >= q_inf
    (:func:`roelands_reduced_limit`: no pressure has that reduced pressure) or within
    rounding of it. A negative q has a negative pressure, down to -p0 at q(-p0).

    Parameters
    ----------
    q : float or array
        Reduced pressure [Pa], >= q(-p0) (:func:`reduced_from_roelands`).
    viscosity, piezo : float
        eta0 [Pa s] and alpha [1/Pa] of the law.
    """
    from scipy.special import gammainc, gammaincc, gammainccinv, gammaincinv

    from .physics.rheology import ROELANDS_P0

    a, big_a, log_c = _roelands_reduced_constants(viscosity, piezo)
    q = np.asarray(q, dtype=float)
    if np.any(np.isnan(q)):
        raise ValueError("q must be a number (Pa) for the Roelands pressure, got nan")
    eps = 8.0 * np.finfo(float).eps  # within rounding of q_inf: noise, not a pressure
    q_min = -float(_times_c(log_c, gammainc(a, big_a)))  # q(-p0) = -C P(1/Z, A)
    below = q < q_min * (1.0 + eps)
    if np.any(below):
        raise ValueError(f"q must be >= q(-p0) = {q_min:.6g} Pa for the Roelands pressure "
                         f"(p >= -p0 = {-ROELANDS_P0:g} Pa), got "
                         f"{float(q[below].flat[0]):.6g} Pa")
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        if big_a < a:
            target = np.maximum(gammainc(a, big_a) + _times_c(-log_c, q), 0.0)
            exists = target < 1.0 - eps
            x = gammaincinv(a, np.where(exists, target, 0.5))
        else:
            top = gammaincc(a, big_a)
            target = np.minimum(top - _times_c(-log_c, q), 1.0)
            exists = target > eps * top
            x = gammainccinv(a, np.where(exists, target, 0.5))
        p = ROELANDS_P0 * np.expm1(a * np.log(x / big_a))
    # the sign of q is that of p (q = 0 is p = 0 exactly)
    p = np.where(q > 0.0, np.maximum(p, 0.0), np.where(q < 0.0, np.minimum(p, 0.0), 0.0))
    return np.where(exists, p, np.inf)


def _check_kapitsa(h0: _Any, a: _Any, b: _Any, viscosity: _Any, mean_speed: _Any,
                   dh0dt: _Any) -> None:
    require_positive("h0", h0, "m")
    require_positive("a", a, "1/m")
    require_nonnegative("b", b, "1/m")
    require_positive("viscosity", viscosity, "Pa s")
    require_nonnegative("mean_speed", mean_speed, "m/s")
    require_finite("dh0dt", dh0dt, "m/s")


def kapitsa_point_coefficients(viscosity: _Any, mean_speed: _Any, a: _Any, b: _Any,
                               dh0dt: _Any = 0.0) -> tuple[_Any, _Any]:
    """Coefficients of Kapitsa's rigid full-Sommerfeld solution q = (A x + B)/h^2 (5.1).

    A = -12 eta0 u_m a/(3a + 2b) [Pa m], B = -3 eta0 (dh0/dt)/(a + b) [Pa m^2], for the
    gap h = h0 + a x^2 + b y^2. The line limit b = 0 gives A = -4 eta0 u_m,
    B = -3 eta0 (dh0/dt)/a.

    Parameters
    ----------
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s], >= 0 (along +x, inlet at x < 0).
    a, b : float
        Gap curvatures 1/(2 rx) > 0 and 1/(2 ry) >= 0 [1/m].
    dh0dt : float
        Approach rate dh0/dt [m/s] (< 0: squeezing, positive pressure).

    Returns
    -------
    (A, B)
        A [Pa m] and B [Pa m^2].
    """
    require_positive("viscosity", viscosity, "Pa s")
    require_nonnegative("mean_speed", mean_speed, "m/s")
    require_positive("a", a, "1/m")
    require_nonnegative("b", b, "1/m")
    require_finite("dh0dt", dh0dt, "m/s")
    big_a = -12.0 * viscosity * mean_speed * a / (3.0 * a + 2.0 * b)
    big_b = -3.0 * viscosity * dh0dt / (a + b)
    return big_a, big_b


def kapitsa_point_pressure(x: _Any, y: _Any, h0: float, a: float, b: float,
                           viscosity: float, mean_speed: float, dh0dt: float = 0.0,
                           piezo: float = 0.0) -> np.ndarray:
    """Kapitsa rigid point-contact pressure, full-Sommerfeld (docs/theory.md section 14.1).

    q = (A x + B)/h^2 with h = h0 + a x^2 + b y^2 solves the isoviscous Reynolds equation
    div(h^3/(12 eta0) grad q) = u_m dh/dx + dh0/dt exactly; then p = -ln(1 - alpha q)/alpha
    (Barus transform). p may be negative (no cavitation condition) and is ``inf`` where
    alpha q >= 1 (no piezo-viscous solution, see :func:`kapitsa_existence_ratio`).

    Parameters
    ----------
    x, y : float or array
        Coordinates [m] (broadcast together).
    h0 : float
        Central gap [m].
    a, b : float
        Gap curvatures 1/(2 rx), 1/(2 ry) [1/m].
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s].
    dh0dt : float
        dh0/dt [m/s].
    piezo : float
        alpha [1/Pa].

    Returns
    -------
    ndarray
        p [Pa].
    """
    _check_kapitsa(h0, a, b, viscosity, mean_speed, dh0dt)
    big_a, big_b = kapitsa_point_coefficients(viscosity, mean_speed, a, b, dh0dt)
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    h = h0 + a * x**2 + b * y**2
    return barus_from_reduced((big_a * x + big_b) / h**2, piezo)


def kapitsa_point_max_reduced(h0: _Any, a: _Any, b: _Any, viscosity: _Any,
                              mean_speed: _Any, dh0dt: _Any = 0.0) -> np.ndarray:
    """Supremum over the plane of the isoviscous Kapitsa pressure q = (A x + B)/h^2 [Pa].

    Where A x + B > 0 the maximum over y is at y = 0, so the supremum is that of
    f(x) = (A x + B)/(h0 + a x^2)^2 along y = 0, or 0 (the value at infinity) if f < 0
    everywhere. f'(x) = 0 reduces to the quadratic 3 a A x^2 + 4 a B x - A h0 = 0, with
    real roots x = (-4 a B -+ sqrt(16 a^2 B^2 + 12 a A^2 h0))/(6 a A); f is evaluated at
    both (closed form, any mix of wedge and squeeze). For A = 0 (pure squeeze) the maximum
    is B/h0^2 at x = 0 if B > 0. Pure wedge: (9|A|/16)(3a)^(-1/2) h0^(-3/2) (docs/theory.md section 14.1).

    Parameters
    ----------
    h0, a, b, viscosity, mean_speed, dh0dt
        As :func:`kapitsa_point_pressure` [m, 1/m, 1/m, Pa s, m/s, m/s]; broadcast.

    Returns
    -------
    ndarray
        sup q [Pa], >= 0.
    """
    _check_kapitsa(h0, a, b, viscosity, mean_speed, dh0dt)
    big_a, big_b = kapitsa_point_coefficients(viscosity, mean_speed, a, b, dh0dt)
    big_a, big_b, h0, a = np.broadcast_arrays(*(np.asarray(v, dtype=float)
                                                for v in (big_a, big_b, h0, a)))
    wedge = big_a != 0.0
    a_safe = np.where(wedge, big_a, 1.0)
    root = np.sqrt(16.0 * a**2 * big_b**2 + 12.0 * a * big_a**2 * h0)
    best = np.where(wedge, -np.inf, big_b / h0**2)
    for sign in (-1.0, 1.0):
        xs = (-4.0 * a * big_b + sign * root) / (6.0 * a * a_safe)
        fs = (big_a * xs + big_b) / (h0 + a * xs**2) ** 2
        best = np.where(wedge, np.maximum(best, fs), best)
    return np.maximum(best, 0.0)


def kapitsa_existence_ratio(h0: _Any, a: _Any, b: _Any, viscosity: _Any, mean_speed: _Any,
                            dh0dt: _Any = 0.0, *, piezo: _Any) -> np.ndarray:
    """alpha q_max of Kapitsa's rigid solution [-] (docs/theory.md section 14.1).

    A rigid piezo-viscous (Barus) full-Sommerfeld solution exists iff this is < 1; as it
    tends to 1 the peak pressure tends to infinity. Arguments as
    :func:`kapitsa_point_max_reduced`, plus ``piezo`` alpha [1/Pa] (keyword).
    """
    require_nonnegative("piezo", piezo, "1/Pa")
    return np.asarray(piezo, dtype=float) * kapitsa_point_max_reduced(
        h0, a, b, viscosity, mean_speed, dh0dt)


#: Gauss-Legendre points per direction of :func:`kapitsa_point_exterior_load` (measured
#: for ry/rx = 1/20 to 20: the strip x < x0 within 2e-15 of its closed form from 24 points
#: on, 1e-12 on 16; the load beyond the default rigid domain changes by 6e-12 from 32 to
#: 48 points; tests/test_analytic.py checks the closed form to 1e-10).
EXTERIOR_GAUSS_POINTS = 48


def _half_line_rule(start: float, scale: float, direction: float,
                    n: int) -> tuple[np.ndarray, np.ndarray]:
    """Nodes and weights on the half-line from ``start`` towards +inf (``direction`` 1) or
    -inf (-1): xi = start + direction scale t/(1 - t), Gauss-Legendre in t on (0, 1) (an
    integrand decaying as xi^-2 or faster becomes smooth in t)."""
    g, w = np.polynomial.legendre.leggauss(n)
    t = 0.5 * (g + 1.0)
    xi = start + direction * scale * t / (1.0 - t)
    return xi, 0.5 * w * scale / (1.0 - t) ** 2


def kapitsa_point_exterior_load(x_range: tuple[float, float], y_range: tuple[float, float],
                                h0: float, a: float, b: float, viscosity: float,
                                mean_speed: float, from_reduced=None) -> float:
    """Load [N] that Kapitsa's rigid inlet film carries outside a rectangle: the integral of
    p(max(q, 0)) over the half-plane x < 0 outside [x0, x1] x [y0, y1], where
    q = A x/h^2 is the isoviscous full-Sommerfeld reduced pressure of a pure wedge
    (:func:`kapitsa_point_pressure`) and p(q) the viscosity law's pressure of a reduced
    pressure (default p = q, isoviscous).

    Far from a rigid point contact with the Reynolds outlet, the film is that of Kapitsa:
    on the inlet side q ~ x/r^4, and downstream of the contact the film is cavitated
    (p = 0). The integral is taken by Gauss-Legendre quadrature
    (:data:`EXTERIOR_GAUSS_POINTS` per direction) of the closed form over the strip
    x < x0 and the two side strips x0 <= x <= 0, |y| beyond the rectangle, each
    semi-infinite direction mapped to (0, 1). For p = q the strip x < x0 has the closed
    form -A pi/(2 a sqrt(b)) (h0 + a x0^2)^(-1/2), which the tests compare with.

    Parameters
    ----------
    x_range, y_range : (float, float)
        The rectangle [m]: x0 < 0 < x1 and y0 < 0 < y1.
    h0 : float
        Central gap [m].
    a, b : float
        Gap curvatures 1/(2 rx), 1/(2 ry) [1/m], > 0.
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s], >= 0.
    from_reduced : callable, optional
        Reduced pressure [Pa] -> pressure [Pa] (e.g. ``lambda q: barus_from_reduced(q,
        alpha)``); None: p = q.

    Returns
    -------
    float
        The load beyond the rectangle [N], >= 0 (inf where ``from_reduced`` has no
        pressure, e.g. alpha q >= 1 for Barus).

    Raises
    ------
    ValueError
        A non-positive h0, a, b or viscosity, a negative speed, or a rectangle that does
        not contain the origin.
    """
    _check_kapitsa(h0, a, b, viscosity, mean_speed, 0.0)
    require_positive("b", b, "1/m")
    x0, x1 = (float(v) for v in x_range)
    y0, y1 = (float(v) for v in y_range)
    if not (x0 < 0.0 < x1 and y0 < 0.0 < y1):
        raise ValueError(f"x_range {x_range!r} and y_range {y_range!r} (m) must contain the "
                         "origin (x0 < 0 < x1, y0 < 0 < y1)")
    big_a, _ = kapitsa_point_coefficients(viscosity, mean_speed, a, b)
    n = EXTERIOR_GAUSS_POINTS

    def beyond(xs: np.ndarray, wx: np.ndarray, y_start: np.ndarray) -> float:
        """Integral over the nodes xs (weights wx) of the film beyond |y| = y_start(x) on
        one side: y = y_start + w(x) t/(1 - t), w(x) = sqrt((h0 + a x^2)/b) the film's
        width at x (the integrand then has one shape for every x)."""
        c = h0 + a * xs**2
        width = np.sqrt(c / b)
        g, w = np.polynomial.legendre.leggauss(n)
        t = 0.5 * (g + 1.0)
        ys = y_start[:, None] + width[:, None] * (t / (1.0 - t))[None, :]
        wy = width[:, None] * (0.5 * w / (1.0 - t) ** 2)[None, :]
        q = np.maximum(big_a * xs[:, None] / (c[:, None] + b * ys**2) ** 2, 0.0)
        p = q if from_reduced is None else np.asarray(from_reduced(q), dtype=float)
        return float(wx @ np.sum(p * wy, axis=1))

    # x < x0, every y (both sides of y = 0, the film is even in y)
    xs, wx = _half_line_rule(x0, max(abs(x0), float(np.sqrt(h0 / a))), -1.0, n)
    total = 2.0 * beyond(xs, wx, np.zeros_like(xs))
    # x0 <= x <= 0, beyond y1 and below y0
    g, w = np.polynomial.legendre.leggauss(n)
    xm, wm = 0.5 * x0 * (g + 1.0), 0.5 * abs(x0) * w
    for edge in (y1, -y0):
        total += beyond(xm, wm, np.full_like(xm, edge))
    return total


def kapitsa_line_pressure(x: _Any, h0: float, radius: float, viscosity: float,
                          mean_speed: float, dh0dt: float = 0.0,
                          piezo: float = 0.0) -> np.ndarray:
    """Rigid cylinder, full-Sommerfeld (docs/theory.md section 14.1 line limit b = 0, and 14.2).

    q = (A x + B)/h^2, h = h0 + x^2/(2R), A = -4 eta0 u_m, B = -6 eta0 R dh0/dt; solves
    d/dx(h^3/(12 eta0) dq/dx) = u_m dh/dx + dh0/dt; p = Barus transform of q.

    Parameters
    ----------
    x : float or array
        [m].
    h0 : float
        Central gap [m].
    radius : float
        R [m].
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s].
    dh0dt : float
        [m/s].
    piezo : float
        alpha [1/Pa].

    Returns
    -------
    ndarray
        p [Pa] (``inf`` where alpha q >= 1).
    """
    require_positive("radius", radius, "m")
    a = 1.0 / (2.0 * radius)
    return kapitsa_point_pressure(x, 0.0, h0, a, 0.0, viscosity, mean_speed, dh0dt, piezo)


def kapitsa_line_max_reduced(h0: _Any, radius: _Any, viscosity: _Any, mean_speed: _Any,
                             dh0dt: _Any = 0.0) -> np.ndarray:
    """max_x of the isoviscous rigid-cylinder q [Pa] (b = 0 case of
    :func:`kapitsa_point_max_reduced`)."""
    require_positive("radius", radius, "m")
    return kapitsa_point_max_reduced(h0, 1.0 / (2.0 * np.asarray(radius, dtype=float)),
                                     0.0, viscosity, mean_speed, dh0dt)


# --- Martin: rigid cylinder with the Reynolds outlet condition (docs/theory.md section 14.2) ---------
def _martin_shape(g: _Any, h_star_ratio: float) -> np.ndarray:
    """p/P0 of Martin's solution as a function of g = arctan(x/sqrt(2 R h0)) (5.2)."""
    g = np.asarray(g, dtype=float)
    return 12.0 * ((g + np.pi / 2.0) * (0.5 - 3.0 * h_star_ratio / 8.0)
                   + (1.0 - h_star_ratio) * np.sin(2.0 * g) / 4.0
                   - h_star_ratio * np.sin(4.0 * g) / 32.0)


@_functools.lru_cache(maxsize=1)
def martin_outlet_angle() -> float:
    """Martin's outlet angle g_c [rad], root of p(g_c) = 0 with H* = sec^2(g_c) (5.2).

    Computed with brentq on (1e-3, 1.2) rad (p/P0 is pi/16 > 0 near g = 0 and negative at
    1.2). The result is g_c ~ 0.4436 rad, i.e. X_c = tan(g_c) ~ 0.475 (the classical
    "0.475" is the outlet position x_c/sqrt(2 R h0), not the angle), H* ~ 1.2257.
    """
    def p_at_outlet(gc: float) -> float:
        return float(_martin_shape(gc, 1.0 / np.cos(gc) ** 2))

    return float(_brentq(p_at_outlet, 1e-3, 1.2, xtol=1e-15))


def martin_hstar(h0: _Any) -> np.ndarray:
    """Film h* = h0 sec^2(g_c) [m] at the Reynolds outlet, where dp/dx = 0 (5.2)."""
    require_positive("h0", h0, "m")
    return np.asarray(h0, dtype=float) / np.cos(martin_outlet_angle()) ** 2


def martin_outlet_position(h0: _Any, radius: _Any) -> np.ndarray:
    """Outlet (cavitation) position x_c = sqrt(2 R h0) tan(g_c) [m] (5.2)."""
    require_positive("h0", h0, "m")
    require_positive("radius", radius, "m")
    return np.sqrt(2.0 * np.asarray(radius, dtype=float) * h0) * np.tan(martin_outlet_angle())


def martin_pressure(x: _Any, h0: float, radius: float, viscosity: float,
                    mean_speed: float, piezo: float = 0.0) -> np.ndarray:
    """Martin's rigid-cylinder pressure with the Reynolds outlet condition (5.2).

    With L = sqrt(2 R h0), g = arctan(x/L), P0 = eta0 u_m L/h0^2, H* = sec^2(g_c):
    q/P0 = 12[(g + pi/2)(1/2 - 3H*/8) + (1 - H*) sin(2g)/4 - H* sin(4g)/32] for
    x <= x_c, and 0 beyond the outlet x_c; then p = Barus transform of q (``inf`` where
    alpha q >= 1). It integrates dp/dx = 12 eta0 u_m (h - h*)/h^3 from p(-inf) = 0.

    Parameters
    ----------
    x : float or array
        [m] (inlet at x < 0).
    h0 : float
        Central (minimum) gap [m].
    radius : float
        R [m].
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s].
    piezo : float
        alpha [1/Pa].

    Returns
    -------
    ndarray
        p [Pa].
    """
    require_positive("h0", h0, "m")
    require_positive("radius", radius, "m")
    require_positive("viscosity", viscosity, "Pa s")
    require_nonnegative("mean_speed", mean_speed, "m/s")
    gc = martin_outlet_angle()
    length = np.sqrt(2.0 * radius * h0)
    p0 = viscosity * mean_speed * length / h0**2
    g = np.arctan(np.asarray(x, dtype=float) / length)
    q = np.where(g <= gc, p0 * _martin_shape(g, 1.0 / np.cos(gc) ** 2), 0.0)
    return barus_from_reduced(q, piezo)


def martin_load(h0: _Any, radius: _Any, viscosity: _Any, mean_speed: _Any) -> np.ndarray:
    """Martin load per unit length w = 6 eta0 u_m R/h* [N/m], h* = h0 sec^2(g_c) (5.2).

    Exact (integration by parts of the isoviscous pressure; ~ 4.896 eta0 u_m R/h0).
    """
    require_positive("radius", radius, "m")
    require_positive("viscosity", viscosity, "Pa s")
    require_nonnegative("mean_speed", mean_speed, "m/s")
    return 6.0 * np.asarray(viscosity * mean_speed * radius, dtype=float) / martin_hstar(h0)


def martin_max_reduced(h0: _Any, radius: _Any, viscosity: _Any,
                       mean_speed: _Any) -> np.ndarray:
    """Peak isoviscous Martin pressure [Pa]: P0 (p/P0)(-g_c), at x = -x_c where h = h* (5.2)."""
    require_positive("h0", h0, "m")
    require_positive("radius", radius, "m")
    require_positive("viscosity", viscosity, "Pa s")
    require_nonnegative("mean_speed", mean_speed, "m/s")
    gc = martin_outlet_angle()
    h0 = np.asarray(h0, dtype=float)
    p0 = viscosity * mean_speed * np.sqrt(2.0 * np.asarray(radius) * h0) / h0**2
    return p0 * _martin_shape(-gc, 1.0 / np.cos(gc) ** 2)


def martin_existence_ratio(h0: _Any, radius: _Any, viscosity: _Any, mean_speed: _Any, *,
                           piezo: _Any) -> np.ndarray:
    """alpha q_max for Martin's cylinder [-]: a Barus solution exists iff < 1 (5.2)."""
    require_nonnegative("piezo", piezo, "1/Pa")
    return np.asarray(piezo, dtype=float) * martin_max_reduced(h0, radius, viscosity,
                                                               mean_speed)


def martin_barus_load_limit(radius: float, viscosity: float, mean_speed: float,
                            piezo: float) -> tuple[float, float]:
    """Largest load per unit length a rigid Barus cylinder with the Reynolds outlet
    carries, and the gap at which it does (5.2).

    The Barus pressure p = -ln(1 - alpha q)/alpha of Martin's reduced pressure q exists
    while alpha q_max < 1; q_max grows as h0^(-3/2) as the gap closes, so the load grows
    to its limit at the gap h0* where alpha q_max = 1. There p has a logarithmic (so
    integrable) singularity at x = -x_c, and the limit is
    W* = int_{-inf}^{x_c} p dx. No load above W* has a solution.

    Parameters
    ----------
    radius : float
        R [m].
    viscosity : float
        eta0 [Pa s].
    mean_speed : float
        u_m [m/s], > 0.
    piezo : float
        alpha [1/Pa], > 0.

    Returns
    -------
    (float, float)
        W* [N/m] and h0* [m].
    """
    from scipy.integrate import quad

    require_positive("radius", radius, "m")
    require_positive("viscosity", viscosity, "Pa s")
    require_positive("mean_speed", mean_speed, "m/s")
    require_positive("piezo", piezo, "1/Pa")
    gc = martin_outlet_angle()
    hs = 1.0 / np.cos(gc) ** 2
    peak = float(_martin_shape(-gc, hs))
    # alpha P0(h0) peak = 1 with P0 = eta0 u_m sqrt(2 R h0)/h0^2
    h0 = (piezo * viscosity * mean_speed * np.sqrt(2.0 * radius) * peak) ** (2.0 / 3.0)
    length = np.sqrt(2.0 * radius * h0)

    def integrand(g: float) -> float:
        aq = min(float(_martin_shape(g, hs)) / peak, 1.0 - 1e-16)   # alpha q
        return -np.log1p(-aq) / piezo * length / np.cos(g) ** 2

    inlet = quad(integrand, -np.pi / 2.0, -gc, limit=200)[0]
    outlet = quad(integrand, -gc, gc, limit=200)[0]
    return float(inlet + outlet), float(h0)


# --- Hertz dry limits (docs/theory.md section 14.3) ---------------------------------------------------
def hertz_line_pressure(x: _Any, b: float, p_h: float) -> np.ndarray:
    """Hertz line pressure p = p_h sqrt(1 - (x/b)^2) for |x| <= b, else 0 [Pa] (5.3).

    Parameters: x [m], half-width b [m], p_h [Pa]. Integrates to w = pi b p_h/2.
    """
    require_positive("b", b, "m")
    require_nonnegative("p_h", p_h, "Pa")
    xi = np.asarray(x, dtype=float) / b
    return p_h * np.sqrt(np.maximum(1.0 - xi**2, 0.0))


def hertz_line_gap_outside(x: _Any, b: float, radius: float) -> np.ndarray:
    """Dry Hertz line gap relative to the flat contact, h - h_centre [m] (5.3).

    For X = |x|/b >= 1: (b^2/(2R)) [X sqrt(X^2 - 1) - arccosh X]; 0 inside (the Hertz
    pressure makes x^2/(2R) + v flat there).

    Parameters: x [m], b [m], R = radius [m].
    """
    require_positive("b", b, "m")
    require_positive("radius", radius, "m")
    big_x = np.maximum(np.abs(np.asarray(x, dtype=float)) / b, 1.0)
    return b**2 / (2.0 * radius) * (big_x * np.sqrt(big_x**2 - 1.0) - np.arccosh(big_x))


def hertz_point_pressure(x: _Any, y: _Any, a: float, p_h: float) -> np.ndarray:
    """Circular Hertz pressure p = p_h sqrt(1 - r^2/a^2), r <= a, else 0 [Pa] (5.3).

    Parameters: x, y [m] (broadcast), contact radius a [m], p_h [Pa].
    Integrates to F = 2 pi a^2 p_h/3.
    """
    require_positive("a", a, "m")
    require_nonnegative("p_h", p_h, "Pa")
    r2 = (np.asarray(x, dtype=float) ** 2 + np.asarray(y, dtype=float) ** 2) / a**2
    return p_h * np.sqrt(np.maximum(1.0 - r2, 0.0))


def hertz_point_displacement(r: _Any, a: float, p_h: float, e_prime: float) -> np.ndarray:
    """Combined surface displacement v(r) of the circular Hertz pressure [m] (5.3).

    v = (2/(pi E')) double-integral p/dist (Boussinesq, docs/theory.md section 11):
    r <= a: v = (pi p_h/(2 a E'))(2a^2 - r^2)  (= delta - r^2/(2R) with Hertz values);
    r >= a: v = (p_h/(a E'))[(2a^2 - r^2) arcsin(a/r) + a sqrt(r^2 - a^2)].

    Parameters: r [m] (|r| is used), a [m], p_h [Pa], E' [Pa].
    """
    require_positive("a", a, "m")
    require_nonnegative("p_h", p_h, "Pa")
    require_positive("e_prime", e_prime, "Pa")
    r = np.abs(np.asarray(r, dtype=float))
    inside = np.pi * p_h / (2.0 * a * e_prime) * (2.0 * a**2 - r**2)
    ro = np.maximum(r, a)
    outside = p_h / (a * e_prime) * ((2.0 * a**2 - ro**2) * np.arcsin(a / ro)
                                     + a * np.sqrt(ro**2 - a**2))
    return np.where(r <= a, inside, outside)



# ----------------------------------------------------------------------------------------
# Section B: Korovchinsky half-plane thermal contact (docs/theory.md section 14.4), Jaeger/Blok.
# ----------------------------------------------------------------------------------------


def korovchinsky_root(x_over_a: np.ndarray | float, y_over_a: np.ndarray | float) -> np.ndarray:
    """Parameter t >= 0 of the confocal ellipse through (x', y') (docs/theory.md section 14.4).

    t is the non-negative root of ``1 - x'^2/(1+t) - y'^2/t = 0``, i.e. of
    ``t^2 + (1 - x'^2 - y'^2) t - y'^2 = 0``; t = 0 on the strip |x'| <= 1, y' = 0.

    Parameters
    ----------
    x_over_a, y_over_a : array_like
        Coordinates in units of the strip half-width a (dimensionless).

    Returns
    -------
    ndarray
        t (dimensionless), broadcast shape of the inputs.
    """
    xp = np.asarray(x_over_a, dtype=float)
    yp = np.asarray(y_over_a, dtype=float)
    B = 1.0 - xp**2 - yp**2
    disc = np.sqrt(B * B + 4.0 * yp**2)
    # two algebraically equal forms; pick the one without cancellation
    with np.errstate(divide="ignore", invalid="ignore"):
        t_pos = 2.0 * yp**2 / (B + disc)           # B > 0 (inside the unit circle)
    t_neg = 0.5 * (disc - B)                        # B <= 0
    t = np.where(B > 0.0, np.where(B + disc > 0.0, t_pos, 0.0), t_neg)
    return np.maximum(t, 0.0)


def korovchinsky_shape(x_over_a: np.ndarray | float, y_over_a: np.ndarray | float) -> np.ndarray:
    """C-free part f of the corrected Korovchinsky field, T/T_n = C + f(x', y').

    ``f = -(1/2) ln[(sqrt(1+t) + sqrt t)/2] - (1/2)(1 - sqrt(t/(1+t))) x'^2
    - (1/2)(sqrt((1+t)/t) - 1) y'^2`` (docs/theory.md section 14.4; Sanko prints the quadratic
    coefficients as 1 instead of 1/2, :func:`korovchinsky_shape_printed`). On the strip
    (t = 0) f = ln sqrt 2 - x'^2/2.

    Parameters
    ----------
    x_over_a, y_over_a : array_like
        x/a across the track and y/a >= 0 into the body (dimensionless).

    Returns
    -------
    ndarray
        f (dimensionless, in units of T_n).
    """
    xp = np.asarray(x_over_a, dtype=float)
    yp = np.abs(np.asarray(y_over_a, dtype=float))
    t = korovchinsky_root(xp, yp)
    st = np.sqrt(t)
    s1 = np.sqrt(1.0 + t)
    with np.errstate(divide="ignore", invalid="ignore"):
        # (sqrt((1+t)/t) - 1) y'^2 = (s1 - st) y'^2 / st -> 0 as y' -> 0 on the strip
        yterm = np.where(st > 0.0, (s1 - st) * yp**2 / st, 0.0)
    return (-0.5 * np.log(0.5 * (s1 + st)) - 0.5 * (1.0 - st / s1) * xp**2 - 0.5 * yterm)


def korovchinsky_shape_printed(x_over_a: np.ndarray | float,
                               y_over_a: np.ndarray | float) -> np.ndarray:
    """The Korovchinsky field as printed by Sanko (eq. 7), for comparison only.

    ``f_printed = -(1/2) ln[(sqrt(1+t) + sqrt t)/2] - (1 - sqrt(t/(1+t))) x'^2
    - (sqrt((1+t)/t) - 1) y'^2``: the two quadratic terms carry the coefficient 1
    instead of 1/2. This field does NOT solve the strip-source problem: it is adiabatic
    on the free surface, but the flux it takes in on the strip is
    ``q_max (3 - 4 x'^2)/(2 sqrt(1 - x'^2))`` instead of ``q_max sqrt(1 - x'^2)``
    (negative for |x'| > sqrt(3)/2, singular at the edges; the same total power
    pi a q_max/2, so far from the strip the two fields agree).
    :func:`korovchinsky_shape` is the correct one (docs/thermal.md). It is kept so that
    the printed two-point reconstruction can be set beside the corrected one
    (``studies/korovchinsky_reconstruction.py``).

    Parameters
    ----------
    x_over_a, y_over_a : array_like
        x/a across the track and y/a >= 0 into the body (dimensionless).

    Returns
    -------
    ndarray
        f_printed (dimensionless, in units of T_n); T/T_n = C + f_printed.
    """
    xp = np.asarray(x_over_a, dtype=float)
    yp = np.abs(np.asarray(y_over_a, dtype=float))
    t = korovchinsky_root(xp, yp)
    log_part = -0.5 * np.log(0.5 * (np.sqrt(1.0 + t) + np.sqrt(t)))
    # f = log_part + quadratic/2 with the corrected 1/2; the printed form doubles it
    return 2.0 * korovchinsky_shape(xp, yp) - log_part


def korovchinsky_characteristic_temperature(half_width: float, q_max: float,
                                            conductivity: float) -> float:
    """Characteristic temperature T_n = a q_max / lambda [K] (= 2 theta/(pi lambda)).

    Parameters
    ----------
    half_width : float
        Strip half-width a [m].
    q_max : float
        Peak of the semi-elliptic flux [W/m^2].
    conductivity : float
        Thermal conductivity lambda [W/(m K)].
    """
    a = require_positive("half_width", half_width, "m")
    lam = require_positive("conductivity", conductivity, "W/(m K)")
    return a * float(q_max) / lam


def korovchinsky_temperature(x: np.ndarray | float, y: np.ndarray | float, half_width: float,
                             q_max: float, conductivity: float, C: float = 0.0) -> np.ndarray:
    """Corrected Korovchinsky temperature T = T_n (C + f(x/a, y/a)) [K].

    Steady conduction in the half-plane y >= 0 with adiabatic surface except the
    semi-elliptic strip flux q = q_max sqrt(1 - x^2/a^2), |x| <= a (docs/theory.md section 14.4).

    Parameters
    ----------
    x, y : array_like
        Position [m]: x across the track, y >= 0 into the body.
    half_width : float
        a [m].
    q_max : float
        [W/m^2].
    conductivity : float
        lambda [W/(m K)].
    C : float
        Korovchinsky's datum constant (dimensionless). ``C = 1/4`` gives the
        logarithmic potential normalised at r = a (see
        :func:`korovchinsky_log_potential_constant`).

    Returns
    -------
    ndarray
        Temperature [K] relative to the datum fixed by C.
    """
    a = require_positive("half_width", half_width, "m")
    Tn = korovchinsky_characteristic_temperature(a, q_max, conductivity)
    return Tn * (C + korovchinsky_shape(np.asarray(x, float) / a, np.asarray(y, float) / a))


def korovchinsky_log_potential_constant() -> float:
    """The C for which T = -(1/(pi lambda)) integral q(s) ln(|r - s|/a) ds.

    As r -> infinity, t -> r'^2 - 1/2 + O(r'^-2), so f -> -(1/2) ln r' - 1/4 (the two
    quadratic terms tend to x'^2/(4t) + y'^2/(4t) = 1/4), while the log potential with
    theta = pi a q_max / 2 tends to -(T_n/2) ln r'. Hence C = 1/4 (exact). The tests
    check this against direct quadrature of the log potential.
    """
    return 0.25


def korovchinsky_surface(x_over_a: np.ndarray | float, C: float = 0.0) -> np.ndarray:
    """Surface temperature T(x, 0)/T_n (docs/theory.md section 14.4 special forms), dimensionless.

    On the strip: C + ln sqrt 2 - x'^2/2. Outside: C - {(1/2) ln[(x' + sqrt(x'^2-1))/2]
    - (1/2) x' sqrt(x'^2-1) + x'^2/2}, with x' -> |x'|.
    """
    xp = np.abs(np.asarray(x_over_a, dtype=float))
    xo = np.maximum(xp, 1.0)                    # outside branch only; avoids log(0)
    s = np.sqrt(xo**2 - 1.0)
    outside = 0.5 * np.log(0.5 * (xo + s)) - 0.5 * xo * s + 0.5 * xo**2
    return np.where(xp <= 1.0, C + np.log(np.sqrt(2.0)) - 0.5 * xp**2, C - outside)


def korovchinsky_depth(y_over_a: np.ndarray | float, C: float = 0.0) -> np.ndarray:
    """Temperature below the centre T(0, y)/T_n, dimensionless (docs/theory.md section 14.4).

    C - {(1/2) ln[(y' + sqrt(y'^2+1))/2] + (1/2) y' sqrt(y'^2+1) - y'^2/2}.
    """
    yp = np.abs(np.asarray(y_over_a, dtype=float))
    s = np.sqrt(yp**2 + 1.0)
    return C - (0.5 * np.log(0.5 * (yp + s)) + 0.5 * yp * s - 0.5 * yp**2)


def korovchinsky_max(C: float = 0.0) -> float:
    """Maximum (centre) temperature T_max/T_n = C + ln sqrt 2, dimensionless."""
    return C + float(np.log(np.sqrt(2.0)))


def korovchinsky_edge(C: float = 0.0) -> float:
    """Strip-edge temperature T(a, 0)/T_n = C + ln sqrt 2 - 1/2 (Sanko prints -1)."""
    return C + float(np.log(np.sqrt(2.0))) - 0.5


def korovchinsky_strip_average(C: float = 0.0) -> float:
    """Strip-average temperature (1/2a) int T dx / T_n = C + ln sqrt 2 - 1/6.

    Average of -x'^2/2 over [-1, 1] is -1/6 (Sanko prints -1/3).
    """
    return C + float(np.log(np.sqrt(2.0))) - 1.0 / 6.0


# --- high-Peclet moving sources (Jaeger 1942, Blok 1937) -------------------------------


def _moving_checks(b: float, conductivity: float, density: float, heat_capacity: float,
                   speed: float) -> tuple[float, float, float, float, float]:
    return (require_positive("b (half-length)", b, "m"),
            require_positive("conductivity", conductivity, "W/(m K)"),
            require_positive("density", density, "kg/m^3"),
            require_positive("heat_capacity", heat_capacity, "J/(kg K)"),
            require_positive("speed", speed, "m/s"))


def jaeger_surface_temperature(x: np.ndarray | float, flux_fn, b: float, conductivity: float,
                               density: float, heat_capacity: float,
                               speed: float) -> np.ndarray:
    """High-Peclet surface temperature under a band source fixed on a moving body [K].

    ``T(x) = (1/sqrt(pi K rho c V)) int_{-b}^{min(x, b)} q(s) (x - s)^(-1/2) ds``
    (docs/theory.md section 14.4), valid for Pe = V b/(2 kappa) >~ 5. The body material moves along
    +x and enters the band at x = -b. The 1/sqrt singularity is removed by the
    substitution s = x - u^2 (ds/sqrt(x - s) = -2 du), leaving a smooth integrand.

    Parameters
    ----------
    x : array_like
        Surface positions [m] along the motion.
    flux_fn : callable
        q(s) [W/m^2] on [-b, b] (vectorised or scalar).
    b : float
        Band half-length [m].
    conductivity, density, heat_capacity, speed : float
        K [W/(m K)], rho [kg/m^3], c [J/(kg K)], V [m/s].

    Returns
    -------
    ndarray
        Temperature rise [K] above the far-upstream body temperature.
    """
    from scipy.integrate import quad

    b, K, rho, c, V = _moving_checks(b, conductivity, density, heat_capacity, speed)
    xs = np.asarray(x, dtype=float)
    out = np.zeros(xs.shape)
    for idx, xi in np.ndenumerate(xs):
        if xi <= -b:
            continue
        lo = np.sqrt(max(xi - b, 0.0))
        hi = np.sqrt(xi + b)
        val, _ = quad(lambda u: 2.0 * float(flux_fn(xi - u * u)), lo, hi, limit=200,
                      epsabs=0.0, epsrel=1e-10)
        out[idx] = val
    return out / np.sqrt(np.pi * K * rho * c * V)


def moving_line_source_surface_temperature(x: np.ndarray | float, flux_fn, b: float,
                                           conductivity: float, density: float,
                                           heat_capacity: float, speed: float) -> np.ndarray:
    """Exact 2D (any Peclet) surface temperature of a band source on a moving half-plane [K].

    Superposes the steady moving line source (Jaeger/Rosenthal), doubled for the
    adiabatic surface: ``T(x, 0) = (1/(pi K)) int q(s) exp(k (x - s)) K0(k |x - s|) ds``,
    k = V/(2 kappa), kappa = K/(rho c), body moving along +x. Reduces to
    :func:`jaeger_surface_temperature` as Pe = k b -> infinity (exp(u) K0(u) ->
    sqrt(pi/(2u))). Uses ``scipy.special.k0e`` = exp(u) K0(u); the log singularity at
    s = x is integrable and handled by splitting the quadrature there.

    Parameters and units as in :func:`jaeger_surface_temperature`.
    """
    from scipy.integrate import quad
    from scipy.special import k0e

    b, K, rho, c, V = _moving_checks(b, conductivity, density, heat_capacity, speed)
    k = V * rho * c / (2.0 * K)
    xs = np.asarray(x, dtype=float)
    out = np.zeros(xs.shape)

    for idx, xi in np.ndenumerate(xs):
        def g(s: float) -> float:
            u = k * abs(xi - s)
            w = k0e(u) if xi >= s else k0e(u) * np.exp(-2.0 * u)
            return float(flux_fn(s)) * w
        pts = [xi] if -b < xi < b else None
        out[idx] = quad(g, -b, b, points=pts, limit=400, epsrel=1e-10)[0]
    return out / (np.pi * K)


def uniform_band_max_coefficient() -> float:
    """Jaeger coefficient c_u in T_max = c_u q sqrt(b)/sqrt(K rho c V), uniform band.

    Band of half-length b (length 2b): T(x) = 2 q sqrt(x + b)/sqrt(pi K rho c V), largest
    at the trailing edge x = b, so c_u = 2 sqrt(2)/sqrt(pi) = 1.5958 (the 1.596 of docs/theory.md
    section 14.4 refers to the HALF-length b).
    """
    return 2.0 * np.sqrt(2.0) / np.sqrt(np.pi)


def blok_semielliptic_maximum() -> tuple[float, float]:
    """Location and coefficient of the high-Peclet maximum under a semi-elliptic flux.

    With q = q_max sqrt(1 - s^2/b^2), T(xi b) = q_max sqrt(b) g(xi)/sqrt(pi K rho c V),
    g(xi) = int sqrt(1 - s^2) (xi - s)^(-1/2) ds; g is maximised numerically (bounded
    Brent on [0, 1.5], s = xi - u^2 substitution for the quadrature).

    Returns
    -------
    (x_max_over_b, coefficient) : tuple of float
        x_max/b (dimensionless, Blok: ~0.652) and c_e with
        T_max = c_e q_max sqrt(b)/sqrt(K rho c V).
    """
    from scipy.integrate import quad
    from scipy.optimize import minimize_scalar

    def g(xi: float) -> float:
        lo = np.sqrt(max(xi - 1.0, 0.0))
        hi = np.sqrt(xi + 1.0)
        return quad(lambda u: 2.0 * np.sqrt(max(1.0 - (xi - u * u) ** 2, 0.0)), lo, hi,
                    limit=200, epsrel=1e-12)[0]

    res = minimize_scalar(lambda xi: -g(xi), bounds=(0.0, 1.5), method="bounded",
                          options={"xatol": 1e-10})
    return float(res.x), float(-res.fun / np.sqrt(np.pi))


# ----------------------------------------------------------------------------------------
# Section D: rolling-bearing load distribution in the continuous (many-element) limit
# (Stribeck 1901; Sjovall 1933; Harris & Kotzalas, "Rolling Bearing Analysis"). The
# discrete load distribution of bearing_fem.bearing.loads is checked against these.
# ----------------------------------------------------------------------------------------
def stribeck_constant(exponent: float) -> float:
    """Z Q_max / F_r of a zero-clearance radial bearing, continuous limit (Stribeck).

    With Q(psi) = Q_max cos(psi)^n on |psi| < pi/2 and F_r = sum Q cos(psi) ~
    (Z/2pi) int Q cos(psi) dpsi:  Z Q_max/F_r = 1 / J_r(1/2), where
    (1/2pi) int_{-pi/2}^{pi/2} cos^(n+1) = Gamma(n/2 + 1) / (2 sqrt(pi) Gamma(n/2 + 3/2)).
    n = 3/2 (point contact) gives 4.37, n = 10/9 (line contact) 4.08.

    Parameters
    ----------
    exponent : float
        Load-deflection exponent n [-] of Q = K delta^n, > 0.

    Returns
    -------
    float
        Z Q_max / F_r [-].
    """
    from scipy.special import gammaln

    require_positive("exponent", exponent, "(dimensionless)")
    n = float(exponent)
    return float(2.0 * np.sqrt(np.pi) * np.exp(gammaln(0.5 * n + 1.5) - gammaln(0.5 * n + 1.0)))


def harris_radial_integral(epsilon: float, exponent: float) -> float:
    """Harris's radial load integral J_r(epsilon) = F_r / (Z Q_max) (continuous limit).

    J_r = (1/2pi) int [1 - (1 - cos psi)/(2 epsilon)]^n cos psi dpsi over the loaded arc
    |psi| <= psi_l, cos psi_l = 1 - 2 epsilon (the whole circle for epsilon >= 1), with
    the load-zone factor epsilon = (1 - c_r/delta_r)/2 of a radial displacement delta_r
    and a radial clearance c_r (Harris & Kotzalas). J_r(1/2) = 1/stribeck_constant(n).

    Parameters
    ----------
    epsilon : float
        Load-zone factor [-], > 0.
    exponent : float
        Load-deflection exponent n [-].

    Returns
    -------
    float
        J_r [-].
    """
    return _load_zone_integral(epsilon, exponent, radial=True)


def _load_zone_integral(epsilon: float, exponent: float, radial: bool) -> float:
    """(1/2pi) int [1 - (1 - cos psi)/(2 epsilon)]^n w(psi) dpsi over the loaded arc,
    w = cos psi (``radial``: J_r) or 1 (J_a) [-]."""
    from scipy.integrate import quad

    require_positive("epsilon", epsilon, "(dimensionless)")
    require_positive("exponent", exponent, "(dimensionless)")
    eps, n = float(epsilon), float(exponent)
    lim = np.pi if eps >= 1.0 else float(np.arccos(1.0 - 2.0 * eps))

    def f(t: float) -> float:  # psi = lim t; 1 - cos psi = 2 sin^2(psi/2) (no cancellation)
        psi = lim * t
        base = max(1.0 - np.sin(0.5 * psi) ** 2 / eps, 0.0) ** n
        return base * np.cos(psi) if radial else base

    val = lim * quad(f, 0.0, 1.0, epsabs=0.0, epsrel=1e-10, limit=200)[0]
    return float(val / np.pi)


def harris_axial_integral(epsilon: float, exponent: float) -> float:
    """Sjovall's axial load integral J_a(epsilon) = F_a / (Z Q_max sin(alpha)) of one row
    under a combined load (continuous limit).

    J_a = (1/2pi) int [1 - (1 - cos psi)/(2 epsilon)]^n dpsi over the loaded arc
    |psi| <= psi_l, cos psi_l = 1 - 2 epsilon (the whole circle for epsilon >= 1). With
    :func:`harris_radial_integral` J_r, a zero-clearance row whose inner ring is displaced
    by delta_r radially and delta_a axially carries F_r = Z Q_max J_r cos(alpha) and
    F_a = Z Q_max J_a sin(alpha), epsilon = (1 + (delta_a / delta_r) tan(alpha))/2
    (Harris & Kotzalas). J_a(1/2)/J_r(1/2) = 1.258 for line contacts (n = 10/9) and 1.216
    for point contacts (n = 3/2): the axial force that a radial load induces in one row
    whose half is loaded.

    Parameters
    ----------
    epsilon : float
        Load-zone factor [-], > 0.
    exponent : float
        Load-deflection exponent n [-].

    Returns
    -------
    float
        J_a [-].
    """
    return _load_zone_integral(epsilon, exponent, radial=False)


def harris_load_zone(radial_load: float, elements: int, stiffness: float, exponent: float,
                     clearance: float) -> dict[str, float]:
    """Load zone of a radial bearing with clearance, continuous limit (Harris).

    Solves F_r = Z K (delta_r - c_r)^n J_r(epsilon), epsilon = (1 - c_r/delta_r)/2, for
    the radial displacement delta_r (Brent), then psi_l = arccos(c_r/delta_r).

    Parameters
    ----------
    radial_load : float
        F_r [N] (per row).
    elements : int
        Z per row.
    stiffness : float
        K of Q = K delta^n for the element (both contacts in series) [N/m^n].
    exponent : float
        n [-].
    clearance : float
        Radial clearance c_r [m], >= 0.

    Returns
    -------
    dict
        ``radial_displacement`` [m], ``epsilon`` [-], ``half_angle`` psi_l [rad],
        ``max_load`` Q_max [N].
    """
    require_positive("radial_load", radial_load, "N")
    require_positive("stiffness", stiffness, "N/m^n")
    require_nonnegative("clearance", clearance, "m")
    z, k, n, c = int(elements), float(stiffness), float(exponent), float(clearance)

    def resid(dr: float) -> float:
        eps = 0.5 * (1.0 - c / dr)
        return z * k * (dr - c) ** n * harris_radial_integral(eps, n) - radial_load

    lo = c * (1.0 + 1e-12) if c > 0 else 1e-15
    hi = max(2.0 * c, (radial_load / (z * k)) ** (1.0 / n) * 10.0 + c)
    while resid(hi) < 0.0:
        hi *= 2.0
    dr = _brentq(resid, lo, hi, xtol=1e-20, rtol=1e-14, maxiter=500)
    eps = 0.5 * (1.0 - c / dr)
    return {"radial_displacement": float(dr), "epsilon": float(eps),
            "half_angle": float(np.arccos(min(c / dr, 1.0))),
            "max_load": float(k * (dr - c) ** n)}

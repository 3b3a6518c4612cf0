"""Film-thickness fits from the literature (docs/theory.md section 16).

These are regression formulas (bands of 5-20%), not oracles: studies set solver results
beside them and report the comparison. Each function states its velocity convention:

- Hamrock groups (mean speed): U = eta0 u_m/(E' R), G = alpha E', W' = w/(E' R) (line),
  W = F/(E' rx^2) (point); film H = h/R (line) or h/rx (point).
- Moes groups (SUM speed): U_sum = 2U, M, L as in :mod:`bearing_fem.units`;
  film H_Moes = (h/R) U_sum^(-1/2).

Dimensional wrappers (``*_film_*``) take SI inputs and return metres.
This module imports numpy only (and :mod:`bearing_fem.units`).
"""
from __future__ import annotations

from typing import Any

import numpy as np

from .units import hamrock_ellipticity, moes_line, moes_point
from .validation import require_nonnegative, require_positive

__all__ = [
    "hamrock_dowson_point",
    "dowson_higginson_line_min",
    "pan_hamrock_line",
    "moes_line_central",
    "moes_line_asymptotes",
    "nijenbanning_central",
    "nijenbanning_asymptotes",
    "ZHIRKIN_FITS",
    "ZHIRKIN_CONVENTIONS",
    "power_law_film",
    "line_central_film_moes",
    "point_central_film_nvm",
    "point_films_hamrock_dowson",
    "line_films_pan_hamrock",
    "line_min_film_dowson_higginson",
]


def _pos(name: str, value: Any) -> np.ndarray:
    require_positive(name, value, "(dimensionless)")
    return np.asarray(value, dtype=float)


# ----------------------------------------------------------------------------------------
# Hamrock-style fits (mean speed)
# ----------------------------------------------------------------------------------------
def hamrock_dowson_point(U: Any, G: Any, W: Any, k: Any) -> tuple[Any, Any]:
    """Hamrock-Dowson (1977) point-contact films, MEAN speed (docs/theory.md section 16).

    H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)),
    H_c   = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)).

    Parameters
    ----------
    U : float or array
        eta0 u_m/(E' rx) [-] (mean speed).
    G : float or array
        alpha E' [-].
    W : float or array
        F/(E' rx^2) [-].
    k : float or array
        Ellipticity a_y/a_x [-] (Hamrock used k = 1.03 (ry/rx)^0.64).

    Returns
    -------
    (H_min, H_c)
        Films h/rx [-].
    """
    U, G, W, k = _pos("U", U), _pos("G", G), _pos("W", W), _pos("k", k)
    h_min = 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1.0 - np.exp(-0.68 * k))
    h_c = 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * k))
    return h_min, h_c


def dowson_higginson_line_min(U: Any, G: Any, W: Any) -> Any:
    """Dowson-Higginson line-contact minimum film, MEAN speed (docs/theory.md section 16).

    H_min = h_min/R = 2.65 U^0.70 G^0.54 W'^-0.13, with U = eta0 u_m/(E'R), G = alpha E',
    W' = w/(E'R) (all [-]). Identical to the ``"Dowson"`` set of :data:`ZHIRKIN_FITS`.
    """
    U, G, W = _pos("U", U), _pos("G", G), _pos("W", W)
    return 2.65 * U**0.70 * G**0.54 * W**-0.13


def pan_hamrock_line(U: Any, G: Any, W: Any) -> tuple[Any, Any]:
    """Pan-Hamrock (1989) line-contact films, MEAN speed (docs/theory.md section 16).

    H_min = 1.714 W'^-0.128 U^0.694 G^0.568,  H_c = 2.922 W'^-0.166 U^0.692 G^0.470,
    films h/R [-]; U, G, W' as in :func:`dowson_higginson_line_min`.
    """
    U, G, W = _pos("U", U), _pos("G", G), _pos("W", W)
    h_min = 1.714 * W**-0.128 * U**0.694 * G**0.568
    h_c = 2.922 * W**-0.166 * U**0.692 * G**0.470
    return h_min, h_c


# ----------------------------------------------------------------------------------------
# Moes-style fits (sum speed)
# ----------------------------------------------------------------------------------------
def moes_line_asymptotes(M: Any, L: Any) -> dict[str, Any]:
    """The four asymptotes of Moes' line-contact central film (H_Moes, SUM speed).

    H_RI = 3/M (rigid-isoviscous), H_EI = 2.621 M^(-1/5) (elastic-isoviscous),
    H_RP = 1.287 L^(2/3) (rigid-piezoviscous), H_EP = 1.311 M^(-1/8) L^(3/4)
    (elastic-piezoviscous), and the blending exponent s = 1.5 (1 + exp(-1.2 H_EI/H_RI)).
    In the rigid limits H_Moes is built on the film h* where dp/dx = 0 (for Martin's
    cylinder h* = h0 sec^2 g_c, not the central gap h0; see docs/analytic.md).
    """
    M = _pos("M", M)
    L = np.asarray(L, dtype=float)
    require_nonnegative("L", L, "(dimensionless)")
    h_ri = 3.0 / M
    h_ei = 2.621 * M ** (-1.0 / 5.0)
    h_rp = 1.287 * L ** (2.0 / 3.0)
    h_ep = 1.311 * M ** (-1.0 / 8.0) * L ** (3.0 / 4.0)
    s = 1.5 * (1.0 + np.exp(-1.2 * h_ei / h_ri))
    return {"H_RI": h_ri, "H_EI": h_ei, "H_RP": h_rp, "H_EP": h_ep, "s": s}


def moes_line_central(M: Any, L: Any) -> Any:
    """Moes line-contact central film H_Moes = (h_c/R) U_sum^(-1/2), SUM speed (docs/theory.md section 16).

    H_c = [(H_RI^(7/3) + H_EI^(7/3))^(3s/7) + (H_RP^(-7/2) + H_EP^(-7/2))^(-2s/7)]^(1/s),
    asymptotes from :func:`moes_line_asymptotes`. L = 0 (isoviscous) is allowed.

    Parameters
    ----------
    M, L : float or array
        Moes load (> 0) and lubricant (>= 0) parameters [-].

    Returns
    -------
    float or array
        H_Moes [-].
    """
    asy = moes_line_asymptotes(M, L)
    s = asy["s"]
    iso = (asy["H_RI"] ** (7.0 / 3.0) + asy["H_EI"] ** (7.0 / 3.0)) ** (3.0 * s / 7.0)
    with np.errstate(divide="ignore", over="ignore"):
        # L = 0 (or L so small that the inverse powers overflow): H_RP, H_EP -> 0 ->
        # inverse powers inf -> piezo-viscous term 0 (exact limit)
        piezo = (asy["H_RP"] ** -3.5 + asy["H_EP"] ** -3.5) ** (-2.0 * s / 7.0)
    return (iso + piezo) ** (1.0 / s)


def nijenbanning_asymptotes(M: Any, L: Any, lam: Any = 1.0) -> dict[str, Any]:
    """Asymptotes of the Nijenbanning-Venner-Moes (1994) central film, SUM speed.

    lambda = rx/ry; A = 1 + 0.006 ln(lambda) + 0.63 lambda^(4/7);
    H_RI = 145 (1 + 0.796 lambda^(14/15))^(-15/7) lambda^-1 M^-2,
    H_EI = 3.18 A^(-14/25) lambda^(-1/15) M^(-2/15),
    H_RP = 1.29 (1 + 0.691 lambda)^(-2/3) L^(2/3),
    H_EP = 1.48 A^(-7/20) lambda^(-1/24) M^(-1/12) L^(3/4),
    s = 1.5 (1 + exp(-1.2 H_EI/H_RI)).
    """
    M = _pos("M", M)
    lam = _pos("lam", lam)
    L = np.asarray(L, dtype=float)
    require_nonnegative("L", L, "(dimensionless)")
    big_a = 1.0 + 0.006 * np.log(lam) + 0.63 * lam ** (4.0 / 7.0)
    h_ri = 145.0 * (1.0 + 0.796 * lam ** (14.0 / 15.0)) ** (-15.0 / 7.0) / lam / M**2
    h_ei = 3.18 * big_a ** (-14.0 / 25.0) * lam ** (-1.0 / 15.0) * M ** (-2.0 / 15.0)
    h_rp = 1.29 * (1.0 + 0.691 * lam) ** (-2.0 / 3.0) * L ** (2.0 / 3.0)
    h_ep = 1.48 * big_a ** (-7.0 / 20.0) * lam ** (-1.0 / 24.0) * M ** (-1.0 / 12.0) \
        * L ** 0.75
    s = 1.5 * (1.0 + np.exp(-1.2 * h_ei / h_ri))
    return {"H_RI": h_ri, "H_EI": h_ei, "H_RP": h_rp, "H_EP": h_ep, "s": s, "A": big_a}


def nijenbanning_central(M: Any, L: Any, lam: Any = 1.0) -> Any:
    """Nijenbanning-Venner-Moes point-contact central film H_Moes, SUM speed (docs/theory.md section 16).

    H_c = [(H_RI^(3/2) + (H_EI^-4 + 0.1^4)^(-3/8))^(2s/3) + (H_RP^-8 + H_EP^-8)^(-s/8)]^(1/s)
    with the asymptotes of :func:`nijenbanning_asymptotes`; H_Moes = (h_c/rx) U_sum^(-1/2),
    M = F/(E' rx^2) U_sum^(-3/4), L = alpha E' U_sum^(1/4).

    Parameters
    ----------
    M, L : float or array
        Moes parameters [-] (L = 0 allowed: isoviscous).
    lam : float or array
        lambda = rx/ry [-] (1 = circular; < 1 for the usual ball-in-groove, ry > rx).

    Returns
    -------
    float or array
        H_Moes [-].
    """
    asy = nijenbanning_asymptotes(M, L, lam)
    s = asy["s"]
    iso = (asy["H_RI"] ** 1.5 + (asy["H_EI"] ** -4.0 + 0.1**4) ** (-3.0 / 8.0)) \
        ** (2.0 * s / 3.0)
    with np.errstate(divide="ignore", over="ignore"):  # L -> 0: term -> 0 (exact limit)
        piezo = (asy["H_RP"] ** -8.0 + asy["H_EP"] ** -8.0) ** (-s / 8.0)
    return (iso + piezo) ** (1.0 / s)


# ----------------------------------------------------------------------------------------
# Zhirkin et al. (cold-mill bearings, table 1): H = K U^a G^b W^c
# ----------------------------------------------------------------------------------------
#: Zhirkin et al.'s five coefficient sets (K, a, b, c) of H = K U^a G^b W^c (line contacts).
#: Ratner's b is printed as 0.6 in the table; the text also quotes 0.4 (ambiguous: the
#: table value is used here; pass your own tuple to :func:`power_law_film` to test 0.4).
#: Ertel-Grubin's exponents are 8/11 and -1/11 rounded.
ZHIRKIN_FITS: dict[str, tuple[float, float, float, float]] = {
    "Ertel-Grubin": (1.95, 0.727, 0.727, -0.091),
    "Higginson": (1.6, 0.7, 0.6, -0.13),
    "Hamrock-Jacobson": (3.07, 0.71, 0.57, -0.11),
    "Dowson": (2.65, 0.7, 0.54, -0.13),
    "Ratner": (3.17, 0.75, 0.6, -0.15),
}

#: Velocity convention we adopt for each set of Zhirkin et al. The paper calls U the "sum
#: rolling speed" but states no definition; the originals of Grubin (1949),
#: Dowson-Higginson (1959, 1966) and Hamrock-Jacobson (1984) use the MEAN speed in
#: U = eta0 u/(E'R), H = h_min/R, W = w/(E'R), and we follow them. Ratner's source is
#: not available; the mean speed is assumed (flagged). A study must say which it uses.
ZHIRKIN_CONVENTIONS: dict[str, str] = {
    "Ertel-Grubin": "mean speed (Grubin 1949)",
    "Higginson": "mean speed (Dowson-Higginson 1959)",
    "Hamrock-Jacobson": "mean speed (Hamrock-Jacobson 1984)",
    "Dowson": "mean speed (Dowson-Higginson 1966)",
    "Ratner": "assumed mean speed (source unavailable; b = 0.6 or 0.4 ambiguous)",
}


def power_law_film(U: Any, G: Any, W: Any,
                   coeffs: tuple[float, float, float, float]) -> Any:
    """Generic film fit H = K U^a G^b W^c (Zhirkin et al., eq. 2).

    Parameters
    ----------
    U, G, W : float or array
        Speed, material and load groups [-] in the convention of the coefficient set
        (for :data:`ZHIRKIN_FITS`: Hamrock line groups, mean speed; see
        :data:`ZHIRKIN_CONVENTIONS`).
    coeffs : tuple
        (K, a, b, c), e.g. ``ZHIRKIN_FITS["Dowson"]``.

    Returns
    -------
    float or array
        H = h/R [-].
    """
    if len(coeffs) != 4:
        raise ValueError(f"coeffs must be (K, a, b, c), got {coeffs!r}")
    big_k, a, b, c = (float(v) for v in coeffs)
    require_positive("coeffs[0] (K)", big_k, "(dimensionless)")
    U, G, W = _pos("U", U), _pos("G", G), _pos("W", W)
    return big_k * U**a * G**b * W**c


# ----------------------------------------------------------------------------------------
# dimensional wrappers (SI in, metres out)
# ----------------------------------------------------------------------------------------
def line_central_film_moes(load_per_length: float, radius: float, e_prime: float,
                           viscosity: float, mean_speed: float, piezo: float) -> float:
    """Moes line-contact central film [m]: h_c = R U_sum^(1/2) H_Moes(M, L).

    Parameters: w [N/m], R [m], E' [Pa], eta0 [Pa s], u_m [m/s] (MEAN speed; the sum
    speed 2 u_m is formed here), alpha [1/Pa].
    """
    g = moes_line(load_per_length, radius, e_prime, viscosity, mean_speed, piezo)
    return float(radius * np.sqrt(g["U_sum"]) * moes_line_central(g["M"], g["L"]))


def point_central_film_nvm(force: float, rx: float, ry: float, e_prime: float,
                           viscosity: float, mean_speed: float, piezo: float) -> float:
    """Nijenbanning-Venner-Moes central film [m]: h_c = rx U_sum^(1/2) H_Moes(M, L, rx/ry).

    Parameters: F [N], rx, ry [m], E' [Pa], eta0 [Pa s], u_m [m/s] (MEAN speed),
    alpha [1/Pa].
    """
    g = moes_point(force, rx, ry, e_prime, viscosity, mean_speed, piezo)
    return float(rx * np.sqrt(g["U_sum"]) * nijenbanning_central(g["M"], g["L"], rx / ry))


def point_films_hamrock_dowson(force: float, rx: float, ry: float, e_prime: float,
                               viscosity: float, mean_speed: float,
                               piezo: float) -> tuple[float, float]:
    """Hamrock-Dowson (h_min, h_c) [m] with k = 1.03 (ry/rx)^0.64 as in the original fit.

    Parameters: F [N], rx, ry [m], E' [Pa], eta0 [Pa s], u_m [m/s] (mean), alpha [1/Pa].
    """
    g = moes_point(force, rx, ry, e_prime, viscosity, mean_speed, piezo)
    h_min, h_c = hamrock_dowson_point(g["U"], g["G"], g["W"], hamrock_ellipticity(rx, ry))
    return float(h_min * rx), float(h_c * rx)


def line_films_pan_hamrock(load_per_length: float, radius: float, e_prime: float,
                           viscosity: float, mean_speed: float,
                           piezo: float) -> tuple[float, float]:
    """Pan-Hamrock (h_min, h_c) [m]; SI inputs as :func:`line_central_film_moes` (mean)."""
    g = moes_line(load_per_length, radius, e_prime, viscosity, mean_speed, piezo)
    h_min, h_c = pan_hamrock_line(g["U"], g["G"], g["W"])
    return float(h_min * radius), float(h_c * radius)


def line_min_film_dowson_higginson(load_per_length: float, radius: float, e_prime: float,
                                   viscosity: float, mean_speed: float,
                                   piezo: float) -> float:
    """Dowson-Higginson h_min [m]; SI inputs as :func:`line_central_film_moes` (mean)."""
    g = moes_line(load_per_length, radius, e_prime, viscosity, mean_speed, piezo)
    return float(dowson_higginson_line_min(g["U"], g["G"], g["W"]) * radius)

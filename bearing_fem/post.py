"""Post-processing: film, pressure, friction and heat power (PHYSICS.md section 6).

Newtonian film between surface 1 (z = 0, speed u1) and surface 2 (z = h, speed u2).
Surface shear stresses, tractions ON the bodies along +x:

    t_1 = -(h/2) dp/dx + eta (u2 - u1)/h,   t_2 = -(h/2) dp/dx + eta (u1 - u2)/h.

Reported (line contacts per metre of length, point contacts in N and W):

* ``rolling_resistance``  F_P = int (h/2) dp/dx dA   (Poiseuille part, per surface),
* ``sliding_friction``    F_C = int eta u_s / h dA    (Couette part, u_s = u1 - u2),
* ``friction_force``      F_P + F_C = -int t_1 dA, the force resisting surface 1's motion
  along +x (positive in the usual case), ``friction_force_surface2`` = F_P - F_C,
* ``friction_coefficient`` friction_force / load,
* ``heat_power``          Q = int [eta u_s^2 / h + h^3/(12 eta) |grad p|^2] dA,
  split into ``heat_power_couette`` and ``heat_power_poiseuille``.

The integrals run over the full-film region: the whole domain for full-Sommerfeld, and
upstream of the cavitation (outlet) boundary for Reynolds cavitation, where the film
ruptures and carries no Couette shear.
"""
from __future__ import annotations

import math
from typing import Any, Mapping, Sequence

import numpy as np

from .numerics.fe import QuadratureOperators


def full_film_indicator_line(x_q: np.ndarray, outlet: float | None) -> np.ndarray:
    """1 upstream of the outlet position [m] (or everywhere if None), else 0."""
    if outlet is None:
        return np.ones_like(x_q)
    return (x_q <= outlet).astype(float)


def outlet_position_line(x: np.ndarray, p: np.ndarray, cavitation: str) -> float | None:
    """Cavitation (outlet) boundary downstream of the pressure maximum [m], sub-grid.

    At a Reynolds free boundary p = dp/dx = 0, so p ~ c (x_c - x)^2 and sqrt(p) is linear
    in x: x_c is found by extrapolating sqrt(p) from the last two pressurised nodes to
    zero (second-order accurate), bounded by the first cavitated node. None when the
    scene has no cavitation or no pressurised node precedes a cavitated one.
    """
    if cavitation != "reynolds" or not np.any(p > 0):
        return None
    i = int(np.argmax(p))
    idx = np.nonzero(p[i:] <= 0.0)[0]
    if not idx.size:
        return None
    k = i + int(idx[0])  # first cavitated node
    if k - 2 < i:
        return float(x[k])
    s1, s2 = np.sqrt(p[k - 1]), np.sqrt(p[k - 2])
    if s2 <= s1:
        return float(x[k])
    xc = x[k - 1] + (x[k - 1] - x[k - 2]) * s1 / (s2 - s1)
    return float(min(xc, x[k]))


def film_quantities(x: np.ndarray, p: np.ndarray, h_nodes: np.ndarray,
                    ops: QuadratureOperators, film_q: np.ndarray) -> dict[str, float]:
    """h_min, h_central (at x = 0), p_max and load (int p) of a line solution."""
    return {
        "h_min": float(np.min(film_q)),
        "h_central": float(np.interp(0.0, x, h_nodes)),
        "p_max": float(np.max(p)),
        "load": float(ops.mass @ p),
    }


def friction_and_heat(ops: QuadratureOperators, h_q: np.ndarray, grad_p_q: tuple[np.ndarray, ...],
                      eta_q: np.ndarray, sliding_speed: float, indicator_q: np.ndarray,
                      load: float) -> dict[str, float]:
    """Friction forces and dissipated power from fields at the quadrature points.

    Parameters
    ----------
    h_q : film [m]; grad_p_q : pressure gradient components [Pa/m], x first;
    eta_q : viscosity [Pa s]; sliding_speed : u1 - u2 [m/s];
    indicator_q : 1 in the full-film region, 0 in the cavitated zone; load : N or N/m.
    """
    w = ops.weights * indicator_q
    px = grad_p_q[0]
    grad2 = sum(g * g for g in grad_p_q)
    f_p = float(w @ (0.5 * h_q * px))
    f_c = float(w @ (eta_q * sliding_speed / h_q))
    q_c = float(w @ (eta_q * sliding_speed**2 / h_q))
    q_p = float(w @ (h_q**3 * grad2 / (12.0 * eta_q)))
    friction = f_p + f_c
    return {
        "rolling_resistance": f_p,
        "sliding_friction": f_c,
        "friction_force": friction,
        "friction_force_surface2": f_p - f_c,
        "friction_coefficient": friction / load if load > 0 else 0.0,
        "heat_power": q_c + q_p,
        "heat_power_couette": q_c,
        "heat_power_poiseuille": q_p,
    }


def energy_identity_line(ops: QuadratureOperators, h_q: np.ndarray, px_q: np.ndarray,
                         eta_q: np.ndarray, mean_speed: float,
                         indicator_q: np.ndarray) -> tuple[float, float]:
    """Both sides of int h^3 p'^2/(12 eta) = u_m int h p' (steady, incompressible, 1D)."""
    w = ops.weights * indicator_q
    return (float(w @ (h_q**3 * px_q**2 / (12.0 * eta_q))),
            float(mean_speed * (w @ (h_q * px_q))))


# ---------------------------------------------------------------------------------------
# error estimate from a sequence of grids
# ---------------------------------------------------------------------------------------
#: Quantities whose discretisation error is estimated.
ESTIMATED_QUANTITIES = ("h_central", "h_min", "p_max", "friction_force", "heat_power")
#: Estimated relative error above which a quantity is named in the result's warnings.
ERROR_WARNING_THRESHOLD = 0.05
#: Observed orders of convergence accepted for Richardson extrapolation: outside this
#: range (or with changes of alternating sign, or not shrinking) the differences are
#: not in the asymptotic range and the plain level difference is reported instead.
RICHARDSON_ORDERS = (0.5, 5.0)


def richardson(values: Sequence[float]) -> tuple[float | None, str, float | None]:
    """Estimated absolute error of the last of a sequence of solutions, each on a grid
    with half the spacing of the one before.

    With three values q1, q2, q3 and changes d1 = q2 - q1, d2 = q3 - q2 of one sign and
    |d2| < |d1|, the observed order is p = log2(d1/d2) and, for p in
    ``RICHARDSON_ORDERS``, the error of q3 is |d2| / (2^p - 1) (Richardson). Otherwise
    it is the plain level difference |d2|; with one value there is no estimate.

    Returns
    -------
    error : float or None
        Estimated |q3 - q_exact| (same unit as the values).
    method : str
        ``"richardson"``, ``"level difference"`` or ``"none"``.
    order : float or None
        Observed order p where Richardson was used.
    """
    q = [float(v) for v in values]
    if len(q) < 2:
        return None, "none", None
    d2 = q[-1] - q[-2]
    if len(q) >= 3:
        d1 = q[-2] - q[-3]
        if d2 == 0.0:
            return 0.0, "richardson", None
        if d1 * d2 > 0.0 and abs(d2) < abs(d1):
            p = math.log2(d1 / d2)
            if RICHARDSON_ORDERS[0] <= p <= RICHARDSON_ORDERS[1]:
                return abs(d2) / (2.0**p - 1.0), "richardson", p
    return abs(d2), "level difference", None


def error_estimate(levels: Sequence[Mapping[str, Any]], note: str = "") -> dict[str, Any]:
    """Relative discretisation errors of the main quantities from a grid sequence.

    Parameters
    ----------
    levels : sequence of dict
        Post-processed quantities of the solutions, coarse to fine, each grid with half
        the spacing of the one before (the last is the reported solution).
    note : str
        Stored as ``grids`` (which grids were used).

    Returns
    -------
    dict
        ``{quantity: relative error or None}`` for ``ESTIMATED_QUANTITIES``, plus
        ``method`` and ``order`` (per quantity, see :func:`richardson`), ``levels``
        (how many solutions were used) and ``grids``.
    """
    out: dict[str, Any] = {}
    methods: dict[str, str] = {}
    orders: dict[str, float | None] = {}
    for key in ESTIMATED_QUANTITIES:
        vals: list[float] = []
        for lv in levels:  # the trailing run of finite values, coarse to fine
            v = lv.get(key)
            ok = isinstance(v, (int, float, np.floating)) and math.isfinite(float(v))
            vals = vals + [float(v)] if ok else []
        if not vals or len(vals) < 1 or levels[-1].get(key) is None or vals[-1] == 0.0:
            out[key], methods[key], orders[key] = None, "none", None
            continue
        err, how, p = richardson(vals[-3:])
        out[key] = None if err is None else err / abs(vals[-1])
        methods[key], orders[key] = how, p
    out["method"] = methods
    out["order"] = orders
    out["levels"] = len(levels)
    out["grids"] = note
    return out


def estimate_warnings(estimate: Mapping[str, Any] | None,
                      threshold: float = ERROR_WARNING_THRESHOLD) -> list[str]:
    """Sentences naming every quantity whose estimated relative error exceeds
    ``threshold``."""
    if not estimate:
        return []
    out = []
    for key in ESTIMATED_QUANTITIES:
        e = estimate.get(key)
        if e is not None and e > threshold:
            how = estimate.get("method", {}).get(key, "")
            out.append(f"{key} is not mesh-converged: estimated discretisation error "
                       f"{100 * e:.3g}% ({how}, {estimate.get('grids', '')}); refine the "
                       "mesh (mesh.nodes)")
    return out

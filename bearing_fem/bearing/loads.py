"""Internal load distribution of a bearing with rigid rings (Harris & Kotzalas).

The inner ring is displaced radially by delta_r along azimuth psi = 0 (the direction of
the radial load) and, for ball bearings under axial load, axially; the ring
displacement is found so that the element loads balance the applied loads.

Ball bearings (one row): the inner groove curvature centre of the ball at azimuth psi
sits, relative to the outer groove curvature centre, at the axial offset z_a and the
radial offset r_0 + delta_r cos(psi), with r_0 = A - c_r (A = (f_i + f_o - 1) D_w,
c_r the radial clearance; for an angular-contact bearing c_r = A (1 - cos alpha_0)).
Their distance s gives the elastic approach delta = s - A and the contact angle
alpha = atan2(z_a, r_0 + delta_r cos psi): contact angles change with load. The load
is Q = K_n(alpha) delta^(3/2), K_n the series Hertz stiffness of the inner and outer
contacts (exact elliptical Hertz). Equilibrium of the inner ring:

    sum_j Q_j cos(alpha_j) cos(psi_j) = F_r,      sum_j Q_j sin(alpha_j) = F_a.

With ``model.centrifugal`` each ball is in equilibrium between its inner and outer
contact forces and its centrifugal force F_c = m d_m omega_c^2 / 2 (Jones-Harris, no
gyroscopic moment): the two contact angles then differ.

Roller bearings (any number of rows sharing the radial load; tapered rollers with both
raceways at the contact angle beta, rib contact neglected): the element approach is
delta = (delta_r cos psi - c_r) cos beta, plus s delta_a sin beta for tapered rows under
an axial load (s = +1, -1 for opposed rows; one row, or rows in opposed pairs;
sum Q cos beta cos psi = F_r and sum s Q sin beta = F_a); straight rollers follow
Palmgren's delta = 2 c Q^0.9 (both contacts), profiled rollers are cut into slices,
each contact's slice approach delta/2 - z(y) (z the profile drop) loading the slice with
q = (approach / c_l)^(10/9) per unit length, c_l = c l^0.9. Row equilibrium:
sum_j Q_j cos(beta) cos(psi_j) = F_r / rows.

Only numpy/scipy, :mod:`bearing_fem.units` and the bearing geometry here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

from .description import Bearing
from .geometry import (ball_stiffness, free_contact_angle, groove_centre_distance,
                       radial_clearance, roller_compliance, reduced_modulus)

__all__ = ["LoadDistribution", "distribute_loads", "row_axial_force", "element_azimuths",
           "profile_drop",
           "series_ball_stiffness", "centrifugal_force", "LOAD_EXPONENT_BALL",
           "LOAD_EXPONENT_LINE"]

#: Load-deflection exponents: point (Hertz) and line (Palmgren) contacts.
LOAD_EXPONENT_BALL = 1.5
LOAD_EXPONENT_LINE = 10.0 / 9.0
#: Relative tolerance of the load balance (Brent on the ring displacement).
BALANCE_RTOL = 1e-12


@dataclass(frozen=True)
class LoadDistribution:
    """Element loads and contact angles of a bearing (every element of every row).

    Attributes
    ----------
    azimuth : ndarray
        psi_j [rad], measured from the direction of the radial load.
    row : ndarray of int
    load_inner, load_outer : ndarray
        Normal contact loads Q_i, Q_o [N] (equal without centrifugal force).
    alpha_inner, alpha_outer : ndarray
        Contact angles [rad].
    approach : ndarray
        Total elastic approach of the element's two contacts [m]; <= 0 outside the load
        zone (a gap, or the clearance not taken up).
    in_load_zone : ndarray of bool
        True where the element carries a load transmitted from the inner ring.
    radial_displacement, axial_displacement : float
        delta_r [m] and the axial displacement of the inner ring [m]: for angular-contact
        ball bearings from the position where the balls just touch at the nominal angle
        (z_a - A sin alpha_0), for deep-groove bearings from the centred ring (z_a); for
        tapered rollers under axial load delta_a, towards the first row's load (its
        rollers approach by delta_a sin(beta)); 0 for other rollers.
    axial_offset : float
        z_a [m] (balls; 0 for rollers).
    load_zone_half_angle : float
        psi_l [rad] where the (continuous) approach vanishes; pi for a full load zone
        (opposed tapered rows under axial load: the wider of the two rows' zones).
    radial_sum, axial_sum : float
        sum Q_i cos(alpha_i) cos(psi) and sum Q_i sin(alpha_i) over all elements [N]
        (opposed tapered rows: their axial components with opposite signs).
    centrifugal_force : float
        F_c per element [N] (0 unless ``model.centrifugal``).
    slice_positions, slice_widths : ndarray or None
        Profiled rollers: slice centres along the roller from its middle, and widths [m].
    slice_loads : ndarray or None
        (elements, slices) slice loads [N] (rollers with a profile).
    exponent : float
        Load-deflection exponent used (3/2 or 10/9).
    stiffness : float
        Series element stiffness K_n at the nominal contact angle [N/m^n] (straight
        rollers and balls), for the load-zone oracle.
    clearance : float
        Radial clearance c_r [m] used.
    """

    azimuth: np.ndarray
    row: np.ndarray
    load_inner: np.ndarray
    load_outer: np.ndarray
    alpha_inner: np.ndarray
    alpha_outer: np.ndarray
    approach: np.ndarray
    in_load_zone: np.ndarray
    radial_displacement: float
    axial_displacement: float
    axial_offset: float
    load_zone_half_angle: float
    radial_sum: float
    axial_sum: float
    centrifugal_force: float
    slice_positions: np.ndarray | None
    slice_widths: np.ndarray | None
    slice_loads: np.ndarray | None
    exponent: float
    stiffness: float
    clearance: float

    @property
    def max_load(self) -> float:
        """Largest inner-contact load [N]."""
        return float(np.max(self.load_inner))


def element_azimuths(bearing: Bearing) -> tuple[np.ndarray, np.ndarray]:
    """(azimuth [rad], row index) of every element: psi_j = psi_0 + 2 pi j / Z per row."""
    g = bearing.geometry
    z = g.elements
    psi = math.radians(g.first_element_azimuth) + 2.0 * math.pi * np.arange(z) / z
    psi = np.angle(np.exp(1j * psi))  # wrap to (-pi, pi]
    return np.tile(psi, g.rows), np.repeat(np.arange(g.rows), z)


def centrifugal_force(bearing: Bearing, *, modelled: bool = True) -> float:
    """F_c = m (d_m/2) omega_c^2 [N] of one element orbiting at the pure-rolling cage speed
    omega_c = omega_i (1 - gamma)/2 at the nominal contact angle ``bearing.contact_angle``
    (0 for deep-groove balls, whose radially loaded balls run at 0 deg).

    Parameters
    ----------
    bearing : Bearing
    modelled : bool
        True: the force of the load distribution, 0 unless ``model.centrifugal``; False:
        the force the elements have whether or not it is modelled.

    Returns
    -------
    float
        [N].
    """
    if modelled and not bearing.model.centrifugal:
        return 0.0
    g = bearing.geometry
    dw, dm = g.element_diameter, g.mean_diameter
    rho = bearing.materials.density
    if g.is_ball:
        mass = rho * math.pi * dw**3 / 6.0
    else:
        mass = rho * math.pi * dw**2 / 4.0 * g.effective_length
    gamma = dw * math.cos(math.radians(g.contact_angle)) / dm
    omega_c = bearing.operation.inner_speed * (1.0 - gamma) / 2.0
    return float(mass * 0.5 * dm * omega_c**2)


def profile_drop(bearing: Bearing, y: np.ndarray) -> np.ndarray:
    """Roller profile drop z(y) [m] at positions y [m] from the roller middle.

    ``crowned``: z = crown_drop ((|y| - f/2)/(l/2 - f/2))^2 outside the flat part f (a
    parabolic crown reaching crown_drop at the roller ends); ``logarithmic``
    (Lundberg/Johns-Gohar form): z = (2 Q_d/(pi l E')) ln[1/(1 - (2y/l)^2)], Q_d the
    design load; ``straight``: 0.
    """
    g = bearing.geometry
    y = np.abs(np.asarray(y, dtype=float))
    lw = g.effective_length
    if g.profile == "crowned":
        half_flat = 0.5 * g.flat_length
        s = np.clip((y - half_flat) / (0.5 * lw - half_flat), 0.0, None)
        return g.crown_drop * s**2
    if g.profile == "logarithmic":
        x = np.clip(2.0 * y / lw, 0.0, 1.0 - 1e-12)
        return 2.0 * g.design_load / (math.pi * lw * reduced_modulus(bearing)) \
            * np.log(1.0 / (1.0 - x**2))
    return np.zeros_like(y)


def series_ball_stiffness(bearing: Bearing):
    """K_n(alpha) [N/m^1.5] of a ball's inner and outer Hertz contacts in series,
    K_n = (K_i^(-2/3) + K_o^(-2/3))^(-3/2), as a cubic spline in alpha [rad] on 0..75 deg,
    and the two contact stiffnesses (K_i(alpha), K_o(alpha)) as splines."""
    grid = np.radians(np.linspace(0.0, 75.0, 31))
    k_i, k_o = ball_stiffness(bearing, grid)
    k_n = (k_i ** (-2.0 / 3.0) + k_o ** (-2.0 / 3.0)) ** -1.5
    return CubicSpline(grid, k_n), CubicSpline(grid, k_i), CubicSpline(grid, k_o)


def _bracket_root(fun, lo: float, hi: float, what: str) -> float:
    """Brent root of an increasing ``fun`` on [lo, hi], growing hi until it brackets."""
    f_hi = fun(hi)
    grow = 0
    while f_hi < 0.0:
        hi *= 2.0
        f_hi = fun(hi)
        grow += 1
        if grow > 200:
            raise RuntimeError(f"no {what} balances the load (bracket grew to {hi!r} m)")
    return brentq(fun, lo, hi, xtol=1e-22, rtol=BALANCE_RTOL * 1e-2, maxiter=500)


#: Relative load imbalance above which a ring displacement is no solution: Brent
#: brackets a sign change, and a jump of the element loads (an equilibrium that did not
#: converge) is one too.
BALANCE_CHECK_RTOL = 1e-6


def _check_balance(sum_r: float, fr: float, sum_a: float, fa: float) -> None:
    """RuntimeError when the element loads miss F_r or F_a by more than
    :data:`BALANCE_CHECK_RTOL` of the larger load."""
    scale = max(fr, fa)
    for name, got, want in (("radial", sum_r, fr), ("axial", sum_a, fa)):
        if abs(got - want) > BALANCE_CHECK_RTOL * scale:
            raise RuntimeError(f"the element loads sum to a {name} force of {got:.6g} N "
                               f"instead of {want:.6g} N (no ring displacement balances the "
                               "loads)")


# ---------------------------------------------------------------------------------------
# ball bearings
# ---------------------------------------------------------------------------------------
class _BallModel:
    """Element loads of a ball bearing for a given ring displacement (delta_r, z_a)."""

    def __init__(self, bearing: Bearing):
        self.b = bearing
        g = bearing.geometry
        self.psi, self.row = element_azimuths(bearing)
        self.cos_psi = np.cos(self.psi)
        self.A = groove_centre_distance(bearing)
        self.cr = radial_clearance(bearing)
        self.r0 = self.A - self.cr
        self.alpha0 = free_contact_angle(bearing)
        self.kn, self.ki, self.ko = series_ball_stiffness(bearing)
        self.fc = centrifugal_force(bearing)
        dw = g.element_diameter
        self.lo = (g.outer_conformity - 0.5) * dw   # outer groove centre -> ball centre
        self.li = (g.inner_conformity - 0.5) * dw   # ball centre -> inner groove centre

    def state(self, dr: float, za: float) -> dict[str, np.ndarray]:
        rad = self.r0 + dr * self.cos_psi
        if self.fc > 0.0:
            return self._centrifugal(rad, za)
        s = np.hypot(za, rad)
        delta = s - self.A
        alpha = np.arctan2(za, rad)
        q = np.where(delta > 0.0, self.kn(alpha) * np.clip(delta, 0.0, None) ** 1.5, 0.0)
        return {"qi": q, "qo": q, "ai": alpha, "ao": alpha, "delta": delta}

    def _centrifugal(self, rad: np.ndarray, za: float) -> dict[str, np.ndarray]:
        """Jones-Harris ball equilibrium with centrifugal force (vectorised Newton).

        Unknowns: ball centre (X1 axial, X2 radial) from the outer groove curvature centre.
        Residuals: Q_i sin a_i - Q_o sin a_o = 0 and Q_i cos a_i - Q_o cos a_o + F_c = 0.
        A ball that F_c alone pushes to the bottom of the outer groove (a_o = 0, Q_o = F_c)
        out of reach of the inner groove has lost its inner contact; every other ball is
        solved from the line of the groove centres, and where that Newton stalls (a small
        inner load against a large F_c) from the bottom of the outer groove. A ball that
        converges from neither raises RuntimeError (taking it for a ball without inner
        contact would make the ring's load balance jump).
        """
        fc, lo, li = self.fc, self.lo, self.li
        s = np.hypot(za, rad)
        do_fc = (fc / self.ko(0.0)) ** (2.0 / 3.0)   # outer approach under F_c alone
        lost = np.hypot(za, rad - (lo + do_fc)) - li <= 0.0

        def forces(x1, x2):
            do = np.hypot(x1, x2) - lo
            di = np.hypot(za - x1, rad - x2) - li
            ao = np.arctan2(x1, x2)
            ai = np.arctan2(za - x1, rad - x2)
            qo = self.ko(ao) * np.clip(do, 0.0, None) ** 1.5
            qi = self.ki(ai) * np.clip(di, 0.0, None) ** 1.5
            r1 = qi * np.sin(ai) - qo * np.sin(ao)
            r2 = qi * np.cos(ai) - qo * np.cos(ao) + fc
            return r1, r2, qi, qo, ai, ao, di, do

        # starts: the ball on the line of the groove centres, outer contact unloaded; the
        # ball at the bottom of the outer groove, outer contact loaded by F_c
        starts = ((za / s * lo, rad / s * lo),
                  (np.zeros_like(rad), np.full_like(rad, lo + do_fc)))
        x1, x2 = starts[0]
        done = lost.copy()
        for y1, y2 in starts:
            if np.all(done):
                break
            y1, y2, converged = self._newton(forces, y1, y2)
            take = converged & ~done
            x1, x2 = np.where(take, y1, x1), np.where(take, y2, x2)
            done |= take
        if not np.all(done):
            j = int(np.flatnonzero(~done)[0])
            raise RuntimeError(
                f"the equilibrium of ball {j} under its centrifugal force F_c = {fc:.4g} N "
                f"did not converge (axial offset of the grooves {za:.4g} m)")
        r1, r2, qi, qo, ai, ao, di, do = forces(x1, x2)
        if np.any(lost):
            qi = np.where(lost, 0.0, qi)
            qo = np.where(lost, fc, qo)
            ao = np.where(lost, 0.0, ao)
            ai = np.where(lost, np.arctan2(za, rad), ai)
            di = np.where(lost, np.hypot(za, rad - (lo + do_fc)) - li, di)
            do = np.where(lost, do_fc, do)
        return {"qi": qi, "qo": qo, "ai": ai, "ao": ao, "delta": di + do}

    def _newton(self, forces, x1: np.ndarray, x2: np.ndarray
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Newton iterations of the ball equilibrium from (x1, x2) [m]: the end point and
        which balls converged (residual below 1e-8 (F_c + Q_o))."""
        fc, lo = self.fc, self.lo
        scale = max(fc, 1e-3)
        h = 1e-9 * self.A
        for _ in range(100):
            r1, r2, *_ = forces(x1, x2)
            if np.max(np.abs(np.concatenate([r1, r2]))) < 1e-10 * scale:
                break
            a1, a2, *_ = forces(x1 + h, x2)
            b1, b2, *_ = forces(x1, x2 + h)
            j11, j21 = (a1 - r1) / h, (a2 - r2) / h
            j12, j22 = (b1 - r1) / h, (b2 - r2) / h
            det = j11 * j22 - j12 * j21
            det = np.where(np.abs(det) > 0.0, det, 1.0)
            d1 = -(j22 * r1 - j12 * r2) / det
            d2 = -(-j21 * r1 + j11 * r2) / det
            step = np.hypot(d1, d2)
            cap = 0.05 * lo
            fac = np.where(step > cap, cap / np.maximum(step, 1e-300), 1.0)
            x1 = x1 + fac * d1
            x2 = x2 + fac * d2
        r1, r2, qi, qo, *_ = forces(x1, x2)
        converged = np.maximum(np.abs(r1), np.abs(r2)) <= 1e-8 * (fc + qo)
        return x1, x2, converged

    def sums(self, dr: float, za: float) -> tuple[float, float]:
        st = self.state(dr, za)
        fr = float(np.sum(st["qi"] * np.cos(st["ai"]) * self.cos_psi))
        fa = float(np.sum(st["qi"] * np.sin(st["ai"])))
        return fr, fa


def _ball_distribution(bearing: Bearing) -> LoadDistribution:
    m = _BallModel(bearing)
    op = bearing.operation
    fr, fa = op.radial_load, op.axial_load
    scale = max(fr, fa)
    # series stiffness at the nominal angle (0 for a deep-groove bearing without axial load)
    k0 = float(m.kn(m.alpha0 if fa > 0.0 else 0.0))
    d_guess = (5.0 * scale / (bearing.geometry.elements * k0)) ** (2.0 / 3.0)

    def solve_dr(za: float) -> float:
        if fr <= 0.0:
            return 0.0
        return _bracket_root(lambda d: m.sums(d, za)[0] - fr, 0.0,
                             max(d_guess + 2.0 * m.cr, 1e-9), "radial displacement")

    if fa <= 0.0:
        za = 0.0
    else:
        # axial offset of first contact when delta_r = 0 (sqrt(A^2 - r0^2)); below it, only
        # the radial displacement can load balls, and the axial sum grows with z_a
        z_lo = 0.0

        def axial_resid(za: float) -> float:
            return m.sums(solve_dr(za), za)[1] - fa

        z_hi = math.sqrt(max(m.A**2 - m.r0**2, 0.0)) + d_guess + 1e-9
        za = _bracket_root(axial_resid, z_lo, z_hi, "axial displacement")
    dr = solve_dr(za)
    st = m.state(dr, za)
    sum_r, sum_a = m.sums(dr, za)
    _check_balance(sum_r, fr, sum_a, fa)
    # continuous load-zone boundary: s(psi) = A  ->  r0 + dr cos psi = sqrt(A^2 - za^2);
    # with the centrifugal force the balls leave the rigid geometry (their equilibrium
    # decides which inner contacts carry load): the boundary from the element loads
    if m.fc > 0.0:
        half = _discrete_load_zone(m.psi, st["qi"] > 0.0)
    elif za >= m.A:
        half = math.pi
    elif dr > 0.0:
        c = (math.sqrt(m.A**2 - za**2) - m.r0) / dr
        half = math.pi if c <= -1.0 else (0.0 if c >= 1.0 else math.acos(c))
    else:
        half = math.pi if za > math.sqrt(max(m.A**2 - m.r0**2, 0.0)) else 0.0
    in_zone = st["qi"] > 0.0
    return LoadDistribution(
        azimuth=m.psi, row=m.row, load_inner=st["qi"], load_outer=st["qo"],
        alpha_inner=st["ai"], alpha_outer=st["ao"], approach=st["delta"],
        in_load_zone=in_zone, radial_displacement=float(dr),
        axial_displacement=float(za - (m.A * math.sin(m.alpha0)
                                      if bearing.geometry.type == "angular-contact-ball" else 0.0)),
        axial_offset=float(za),
        load_zone_half_angle=float(half), radial_sum=sum_r, axial_sum=sum_a,
        centrifugal_force=m.fc, slice_positions=None, slice_widths=None, slice_loads=None,
        exponent=LOAD_EXPONENT_BALL, stiffness=k0, clearance=float(m.cr))


def _discrete_load_zone(psi: np.ndarray, loaded: np.ndarray) -> float:
    """Load-zone half-angle [rad] from which elements carry load: midway between the
    largest |azimuth| of a loaded element and the next unloaded one (pi when every
    element is loaded, 0 when none is)."""
    angle = np.abs(np.angle(np.exp(1j * np.asarray(psi, dtype=float))))
    if not np.any(loaded):
        return 0.0
    last = float(np.max(angle[loaded]))
    beyond = angle[~loaded & (angle > last)]
    return math.pi if beyond.size == 0 else 0.5 * (last + float(np.min(beyond)))


# ---------------------------------------------------------------------------------------
# roller bearings
# ---------------------------------------------------------------------------------------
def _roller_distribution(bearing: Bearing) -> LoadDistribution:
    g = bearing.geometry
    psi, row = element_azimuths(bearing)
    cos_psi = np.cos(psi)
    beta = math.radians(g.contact_angle)
    cb, sb = math.cos(beta), math.sin(beta)
    row_sign = np.where(row % 2 == 0, 1.0, -1.0)  # opposed rows of a tapered pair
    cr = float(g.radial_clearance)
    c = roller_compliance(bearing)          # delta_contact = c Q^0.9
    fc = centrifugal_force(bearing) * cb    # normal component at the outer raceway
    fr_row = bearing.operation.radial_load / g.rows
    n_sl = g.n_slices
    lw = g.effective_length
    if n_sl > 1:
        w = lw / n_sl
        y = -0.5 * lw + w * (np.arange(n_sl) + 0.5)
        drop = profile_drop(bearing, y)
        c_l = c * lw**0.9                  # per unit length: approach = c_l q^0.9
        widths = np.full(n_sl, w)
    else:
        y = widths = drop = None
        c_l = None

    def loads(dr: float, da: float = 0.0):
        delta = (dr * cos_psi - cr) * cb
        if da != 0.0:  # tapered rows under axial load (opposed rows: opposite sign)
            delta = delta + row_sign * (da * sb)
        if n_sl > 1:
            app = np.clip(0.5 * delta[:, None] - drop[None, :], 0.0, None)
            q = (app / c_l) ** (1.0 / 0.9) * widths[None, :]
            qi = q.sum(axis=1)
            return qi, qi, delta, q
        if fc > 0.0:
            qi = np.zeros_like(delta)
            onset = c * fc**0.9
            for j in np.nonzero(delta > onset)[0]:
                dj = delta[j]
                qi[j] = brentq(lambda qq: c * qq**0.9 + c * (qq + fc) ** 0.9 - dj, 0.0,
                               (dj / c) ** (1.0 / 0.9), xtol=1e-12, rtol=1e-14)
            return qi, qi + fc, delta, None
        qi = np.where(delta > 0.0, (np.clip(delta, 0.0, None) / (2.0 * c)) ** (1.0 / 0.9), 0.0)
        return qi, qi, delta, None

    def row_sums(qi: np.ndarray) -> tuple[float, float]:
        """(sum Q cos(beta) cos(psi), sum s_k Q sin(beta)) of inner loads [N]."""
        return float(np.sum(qi * cb * cos_psi)), float(np.sum(row_sign * qi * sb))

    def resid(dr: float) -> float:
        qi = loads(dr)[0]
        return float(np.sum(qi[row == 0] * cb * cos_psi[row == 0])) - fr_row

    fa = float(bearing.operation.axial_load)
    if fa > 0.0:  # a tapered bearing under axial load (the description refuses others)
        dr, da = _tapered_displacements(bearing, lambda r, a: row_sums(loads(r, a)[0]), c)
    else:
        d_guess = 2.0 * c * (5.0 * fr_row / (g.elements * cb)) ** 0.9 / cb + cr
        dr, da = _bracket_root(resid, 0.0, d_guess, "radial displacement"), 0.0
    half = _roller_load_zone(dr, da, cr, cb, sb, g.rows)
    qi, qo, delta, sl = loads(dr, da)
    radial_sum, axial_sum = row_sums(qi)
    _check_balance(radial_sum, bearing.operation.radial_load,
                   axial_sum if da != 0.0 else 0.0, fa)
    alpha = np.full(psi.shape, beta)
    k_n = (2.0 * c) ** (-1.0 / 0.9)
    return LoadDistribution(
        azimuth=psi, row=row, load_inner=qi, load_outer=qo, alpha_inner=alpha,
        alpha_outer=alpha.copy(), approach=delta, in_load_zone=qi > 0.0,
        radial_displacement=float(dr), axial_displacement=float(da), axial_offset=0.0,
        load_zone_half_angle=float(half),
        radial_sum=radial_sum, axial_sum=axial_sum if da != 0.0 else 0.0,
        centrifugal_force=fc / cb,
        slice_positions=y, slice_widths=widths, slice_loads=sl,
        exponent=LOAD_EXPONENT_LINE, stiffness=float(k_n), clearance=cr)


def _tapered_displacements(bearing: Bearing, sums, c: float) -> tuple[float, float]:
    """(delta_r, delta_a) [m] of a tapered-roller bearing under a radial and an axial load.

    Row k's rollers approach by (delta_r cos psi - c_r) cos(beta) + s_k delta_a sin(beta),
    s_k = +1 for even k and -1 for odd k (opposed rows); the ring displacement balances
    sum Q cos(beta) cos(psi) = F_r and sum s_k Q sin(beta) = F_a (nested Brent: delta_r
    for each delta_a); ``sums(delta_r, delta_a)`` gives those two sums [N], ``c`` is the
    roller compliance of Palmgren's law. One row needs F_a above
    :func:`~bearing_fem.bearing.description.single_row_min_axial_load`, which the bearing
    description checks.
    """
    g, op = bearing.geometry, bearing.operation
    fr, fa = float(op.radial_load), float(op.axial_load)
    beta = math.radians(g.contact_angle)
    cb, sb = math.cos(beta), math.sin(beta)

    scale = 2.0 * c * (5.0 * max(fr, fa) / (g.elements * min(cb, sb))) ** 0.9
    scale = max(scale, float(g.radial_clearance), 1e-12)

    def solve_dr(da: float) -> float:
        if fr <= 0.0:
            return 0.0
        return _bracket_root(lambda d: sums(d, da)[0] - fr, 0.0, scale,
                             "radial displacement")

    def axial_resid(da: float) -> float:
        return sums(solve_dr(da), da)[1] - fa

    if axial_resid(0.0) > 0.0:  # the radial load alone induces more than F_a: the ring
        # moves back (the residual increases with delta_a: search -delta_a upwards)
        da = -_bracket_root(lambda t: -axial_resid(-t), 0.0, scale,
                            "axial displacement (drawn back)")
    else:
        da = _bracket_root(axial_resid, 0.0, scale, "axial displacement")
    return solve_dr(da), float(da)


def _roller_load_zone(dr: float, da: float, cr: float, cb: float, sb: float,
                      rows: int) -> float:
    """Half angle psi_l [rad] of the widest load zone of the rows (continuous approach
    (delta_r cos psi - c_r) cos(beta) +- delta_a sin(beta) > 0; with delta_a = 0,
    cos(psi_l) = c_r/delta_r)."""
    half = 0.0
    for s in ((1.0,) if rows == 1 or da == 0.0 else (1.0, -1.0)):
        free = s * da * sb - cr * cb       # the approach at cos(psi) = 0
        if dr <= 0.0:
            h = math.pi if free > 0.0 else 0.0
        else:
            cpl = -free / (dr * cb)
            h = math.pi if cpl <= -1.0 else (0.0 if cpl >= 1.0 else math.acos(cpl))
        half = max(half, h)
    return half


def row_axial_force(dist: LoadDistribution) -> float:
    """Axial force of the first row's inner contacts, sum Q_i sin(alpha_i) over row 0 [N].

    For one row it is the axial load the row carries; for tapered rows in opposed pairs
    under a radial load only it is the axial force each row induces and the opposed row
    (or the opposed bearing of a single row) reacts.

    Parameters
    ----------
    dist : LoadDistribution

    Returns
    -------
    float
        [N], >= 0.
    """
    first = dist.row == 0
    return float(np.sum(dist.load_inner[first] * np.sin(np.abs(dist.alpha_inner[first]))))


def distribute_loads(bearing: Bearing) -> LoadDistribution:
    """Element loads that balance the bearing's radial and axial loads (rigid rings).

    Parameters
    ----------
    bearing : Bearing

    Returns
    -------
    LoadDistribution
        ``radial_sum`` and ``axial_sum`` equal the applied loads to ~1e-12 relative
        (Brent on the ring displacement).
    """
    if bearing.geometry.is_ball:
        return _ball_distribution(bearing)
    return _roller_distribution(bearing)

"""Post-processing of a solved film: film numbers, friction, heat power, error estimate.

Film between surface 1 (z = 0, speed u1) and surface 2 (z = h, speed u2); u_m = (u1 + u2)/2,
u_s = u1 - u2. Shear stresses on the surfaces along +x (Poiseuille part Newtonian, the
sliding part by the scene's traction model tau(eta, u_s/h, p),
:mod:`bearing_fem.physics.traction`):

    t_1 = -(h/2) dp/dx - tau,   t_2 = -(h/2) dp/dx + tau.

Reported (line contacts per metre of length, point contacts in N and W):

* ``rolling_resistance``  F_P = int (h/2) dp/dx dA   (Poiseuille part, per surface),
* ``sliding_friction``    F_C = int tau dA             (Couette part),
* ``friction_force``      F_P + F_C = -int t_1 dA, the force resisting surface 1's motion
  along +x; ``friction_force_surface2`` = F_P - F_C,
* ``friction_coefficient`` friction_force / load (None when the film carries no net
  positive load, e.g. a rigid full-Sommerfeld film whose pressures cancel),
* ``heat_power``          Q = Q_C + Q_P, the whole dissipation in the film:
  ``heat_power_couette`` Q_C = int tau u_s dA = u_s F_C and ``heat_power_poiseuille``
  Q_P = u_m int h dp/dx dA = 2 u_m F_P, the conservative form of the Poiseuille
  dissipation int h^3 |grad p|^2/(12 eta) dA: the two are equal for every steady
  isothermal film (multiply the Reynolds equation by the pressure potential
  int_0^p dp'/rho and integrate by parts; ``docs/theory.md``, "Friction and heat"), but
  the conservative form does not multiply the discretisation error of an under-resolved
  outlet spike by exp(alpha p). The discrete direct form is reported as
  ``heat_power_poiseuille_direct``; their agreement is the energy-identity check.

The Couette (sliding) integrals run over the full-film region: the whole domain for
full-Sommerfeld, and upstream of the cavitation (outlet) boundary for Reynolds
cavitation, where the film ruptures and carries no Couette shear. The Poiseuille
integrals run over the whole domain (p = 0 where the film has cavitated).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

import numpy as np

from .numerics.fe import QuadratureOperators
from .physics.traction import shear_parameters, shear_stress


def full_film_indicator_line(x_q: np.ndarray, outlet: float | None) -> np.ndarray:
    """1 upstream of the outlet position [m] (or everywhere if None), else 0."""
    if outlet is None:
        return np.ones_like(x_q)
    return (x_q <= outlet).astype(float)


#: Nodal pressures at or below this fraction of the maximum count as cavitated when the
#: outlet boundary of a line contact is located: the Newton solution of the cavitation
#: complementarity is zero there only to its tolerance (a scaled residual of 1e-8 leaves
#: pressures of order 1e-8 p_h), and a node of such noise taken as pressurised moved the
#: outlet, and the Couette friction with it, by one element (5e-5 of the friction of a
#: sliding contact on 6401 nodes, from a change of the linear solver's rounding).
CAVITATED_PRESSURE_FRACTION = 1e-6


def outlet_position_line(x: np.ndarray, p: np.ndarray, cavitation: str) -> float | None:
    """Cavitation (outlet) boundary downstream of the pressure maximum [m], sub-grid.

    At a Reynolds free boundary p = dp/dx = 0, so p ~ c (x_c - x)^2 and sqrt(p) is linear
    in x: x_c is found by extrapolating sqrt(p) from the last two pressurised nodes to
    zero (second-order accurate), bounded by the first cavitated node (p at most
    :data:`CAVITATED_PRESSURE_FRACTION` of the maximum). None when the scene has no
    cavitation or no pressurised node precedes a cavitated one.
    """
    if cavitation != "reynolds" or not np.any(p > 0):
        return None
    i = int(np.argmax(p))
    idx = np.nonzero(p[i:] <= CAVITATED_PRESSURE_FRACTION * p[i])[0]
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


def parabola_vertex(x: np.ndarray, f: np.ndarray, i: int) -> tuple[float, float]:
    """Vertex (position, value) of the parabola through the nodes i-1, i, i+1 of
    (x, f); the node itself at an end of the array, for a straight line, or where the
    vertex would lie beyond a neighbour."""
    if i <= 0 or i >= x.size - 1:
        return float(x[i]), float(f[i])
    c = np.polyfit(x[i - 1:i + 2] - x[i], f[i - 1:i + 2], 2)
    if c[0] == 0.0:
        return float(x[i]), float(f[i])
    xv = -c[1] / (2 * c[0])
    if abs(xv) > max(x[i + 1] - x[i], x[i] - x[i - 1]):
        return float(x[i]), float(f[i])
    return float(x[i] + xv), float(np.polyval(c, xv))


def peak(p: np.ndarray, x: np.ndarray, y: np.ndarray | None = None) -> float:
    """Maximum of a nodal field, refined between the nodes [same unit as p].

    The largest nodal value plus the rise of the parabola through it and its two
    neighbours along each grid direction (when the node is a local maximum along it):
    the field's maximum to second order where it is smooth (a nodal maximum alone is
    first order in its position and makes Richardson estimates erratic), the nodal
    value itself at a one-node spike.

    Parameters
    ----------
    p : ndarray
        Nodal values, shape (nx,) or (ny, nx).
    x, y : ndarray
        Node coordinates [m] (``y`` for 2D fields).
    """
    p = np.asarray(p, dtype=float)
    if y is None:
        i = int(np.argmax(p))
        return max(float(p[i]), parabola_vertex(x, p, i)[1])
    grid = p.reshape(y.size, x.size)
    j, i = np.unravel_index(int(np.argmax(grid)), grid.shape)
    top = float(grid[j, i])
    rise = max(parabola_vertex(x, grid[j], i)[1] - top, 0.0) \
        + max(parabola_vertex(y, grid[:, i], j)[1] - top, 0.0)
    return top + rise


#: h_min between the nodes more than this fraction below the nodal minimum is reported:
#: the constriction is narrower than the grid resolves.
SUBGRID_FILM_FRACTION = 0.01
#: A minimum film below this [m] is a few molecular layers of oil (5 nm): there the
#: continuum film of the Reynolds equation, which this package solves, is doubtful and the
#: surfaces' roughness, which it does not model, decides (mixed or boundary lubrication;
#: Johnston, Wayte & Spikes 1991 measured EHL films departing from the continuum theory
#: below about 5-10 nm). The result says so in its warnings.
MOLECULAR_FILM = 5e-9


def film_numbers(h_nodes: np.ndarray, h_q: np.ndarray, h_central: float,
                 p_nodes: np.ndarray, load: float, x: np.ndarray,
                 y: np.ndarray | None = None,
                 h_near: np.ndarray | None = None,
                 constriction: str | None = "the outlet constriction"
                 ) -> tuple[dict[str, float], list[str]]:
    """h_min, h_central, p_max and load of a solution, and warnings when the minimum film
    lies between the nodes or below :data:`MOLECULAR_FILM`.

    h_min is the minimum of the film field: over the nodes, the quadrature points ``h_q``
    and ``h_near`` (for half-space line contacts, points around the nodal minimum with the
    deflection of the discrete pressure between the nodes), and never above h_central.
    p_max is the nodal maximum refined between the nodes (:func:`peak`).

    The warning that h_min lies between the nodes is given when the quadrature-point film
    (exact geometry, interpolated deformation) lies more than
    :data:`SUBGRID_FILM_FRACTION` below the nodal minimum, a grid too coarse for the
    constriction's geometry, or h_min with ``h_near`` more than the error estimate's
    :data:`ERROR_WARNING_THRESHOLD`: the bow of the deflection that ``h_near`` adds is
    discretisation error, which the error estimate reports at that threshold (on the
    3601 nodes over [-4.5, 1.5] b at Moes M = 1000, L = 0, it puts h_min 1.1 % below the nodal
    minimum with an estimated error of 3.9 %).

    Parameters
    ----------
    h_nodes, h_q : film at the nodes and at the quadrature points [m];
    h_central : film at the Hertz centre [m]; p_nodes : nodal pressure [Pa];
    load : int p dA [N or N/m]; x, y : node coordinates [m] (``y`` for point contacts);
    h_near : film at further points between the nodes [m] (optional);
    constriction : what the warning says the grid does not resolve; None: no such warning
    (a rigid body, whose minimum h_central at x = 0 is exact).
    """
    h_node_min = float(np.min(h_nodes))
    h_grid_min = float(min(h_node_min, float(np.min(h_q)), h_central))
    h_min = h_grid_min
    if h_near is not None and np.size(h_near):
        h_min = float(min(h_min, float(np.min(h_near))))
    notes = []
    if constriction is not None and (
            h_grid_min < (1.0 - SUBGRID_FILM_FRACTION) * h_node_min
            or h_min < (1.0 - ERROR_WARNING_THRESHOLD) * h_node_min):
        notes.append(f"h_min lies between the nodes ({h_min:.4g} m, "
                     f"{100 * (1 - h_min / h_node_min):.3g}% below the nodal minimum "
                     f"{h_node_min:.4g} m): {constriction} is not resolved by the "
                     "grid; refine the mesh")
    if 0.0 < h_min < MOLECULAR_FILM:
        notes.append(f"h_min = {h_min:.3g} m is below {MOLECULAR_FILM:.0e} m, a few molecular "
                     "layers of oil: a continuum film (the Reynolds equation) is doubtful "
                     "there, and surface roughness, not modelled, decides (mixed or boundary "
                     "lubrication)")
    return {"h_min": h_min, "h_central": float(h_central), "p_max": peak(p_nodes, x, y),
            "load": float(load)}, notes


@dataclass(frozen=True)
class FilmDissipation:
    """Friction and heat of a film, with the heat densities at the quadrature points.

    Attributes
    ----------
    rolling_resistance, sliding_friction : float
        F_P and F_C [N or N/m] (module docstring).
    heat_power_couette, heat_power_poiseuille : float
        Q_C and the conservative Q_P [W or W/m].
    heat_power_poiseuille_direct : float
        The discrete int h^3 |grad p|^2/(12 eta) dA [W or W/m]: with the reduced-pressure
        Poiseuille term, int h^3/(12 eta0) grad q_h . grad p_h dA (the viscosity
        variation across an element integrated exactly for linear p).
    heat_power_stabilisation : float
        The numerical dissipation of the stabilisation, int F_stab . grad p_h dA
        [W or W/m]. For an incompressible film, direct + stabilisation = Q_P holds to the
        Newton tolerance (the discrete weak form tested with p_h itself): the discrete
        energy balance.
    couette_density, poiseuille_density : ndarray
        Heat generated per unit area at the quadrature points [W/m^2]: tau u_s, and
        u_m dp/dx (h - h*) (integrates to Q_P; in the exact 1D film it equals the local
        Poiseuille dissipation, since h^3 p'/(12 eta) = u_m (h - h*)).
    h_star : float
        The flux film h* of ``poiseuille_density`` [m].
    shear : dict
        The traction model and parameters of the sliding stress.
    """

    rolling_resistance: float
    sliding_friction: float
    heat_power_couette: float
    heat_power_poiseuille: float
    heat_power_poiseuille_direct: float
    heat_power_stabilisation: float
    couette_density: np.ndarray
    poiseuille_density: np.ndarray
    h_star: float
    shear: Mapping[str, Any]

    @property
    def friction_force(self) -> float:
        return self.rolling_resistance + self.sliding_friction

    @property
    def heat_power(self) -> float:
        return self.heat_power_couette + self.heat_power_poiseuille

    def quantities(self) -> dict[str, float]:
        """The summary numbers (without the friction coefficient)."""
        return {
            "rolling_resistance": self.rolling_resistance,
            "sliding_friction": self.sliding_friction,
            "friction_force": self.friction_force,
            "friction_force_surface2": self.rolling_resistance - self.sliding_friction,
            "heat_power": self.heat_power,
            "heat_power_couette": self.heat_power_couette,
            "heat_power_poiseuille": self.heat_power_poiseuille,
            "heat_power_poiseuille_direct": self.heat_power_poiseuille_direct,
            "heat_power_stabilisation": self.heat_power_stabilisation,
        }


def film_dissipation(ops: QuadratureOperators, h_q: np.ndarray,
                     grad_p_q: tuple[np.ndarray, ...], eta_q: np.ndarray, p_q: np.ndarray, *,
                     mean_speed: float, sliding_speed: float, indicator_q: np.ndarray,
                     shear: Mapping[str, Any],
                     reduced: tuple[tuple[np.ndarray, ...], float] | None = None,
                     stabilisation: tuple[np.ndarray, ...] | None = None
                     ) -> FilmDissipation:
    """Friction forces and dissipated power of a film from fields at the quadrature points.

    Parameters
    ----------
    ops : QuadratureOperators
    h_q : film [m]; grad_p_q : pressure gradient components [Pa/m], x first;
    eta_q : viscosity [Pa s]; p_q : pressure [Pa];
    mean_speed, sliding_speed : u_m, u_s [m/s];
    indicator_q : 1 in the full-film region, 0 in the cavitated zone (where the film has
        ruptured and carries no Couette shear; the Poiseuille integrals run over the whole
        domain, where p = 0 in the cavitated zone);
    shear : keyword arguments of :func:`bearing_fem.physics.traction.shear_stress`
        (the traction model and its parameters);
    reduced : (grad q_h at the quadrature points [Pa/m], eta0 [Pa s]), optional
        The reduced-pressure gradient of the Poiseuille term, for the direct form.
    stabilisation : tuple of arrays, optional
        The flux the stabilisation adds [m^2/s]
        (:meth:`bearing_fem.physics.reynolds.FluxModel.stabilisation_flux`): its
        integral against grad p is the scheme's numerical dissipation.
    """
    w = ops.weights
    px = grad_p_q[0]
    f_p = float(w @ (0.5 * h_q * px))
    if sliding_speed != 0.0:
        tau = shear_stress(eta_q, sliding_speed / h_q, p_q, **shear) * indicator_q
    else:
        tau = np.zeros_like(h_q)
    f_c = float(w @ tau)
    q_p = float(mean_speed * (w @ (h_q * px)))
    if reduced is not None:
        gq, eta0 = reduced
        direct = (h_q**3 / (12.0 * eta0)) * sum(a * b for a, b in zip(gq, grad_p_q))
    else:
        direct = h_q**3 * sum(g * g for g in grad_p_q) / (12.0 * eta_q)
    numerical = 0.0
    if stabilisation is not None:
        numerical = float(w @ sum(a * b for a, b in zip(stabilisation, grad_p_q)))
    flux_film = h_q - h_q**3 * px / (12.0 * eta_q * mean_speed)
    sel = (p_q > 0.5 * np.max(p_q)) & (indicator_q > 0)
    h_star = float(np.median(flux_film[sel] if np.any(sel) else flux_film))
    return FilmDissipation(
        rolling_resistance=f_p, sliding_friction=f_c,
        heat_power_couette=float(f_c * sliding_speed), heat_power_poiseuille=q_p,
        heat_power_poiseuille_direct=float(w @ direct),
        heat_power_stabilisation=numerical,
        couette_density=tau * sliding_speed,
        poiseuille_density=mean_speed * px * (h_q - h_star), h_star=h_star,
        shear=dict(shear))


#: A friction coefficient is reported only when the net load is at least this fraction of
#: the gross pressure integral int |p| dA (below, the film's pressures cancel: a rigid
#: full-Sommerfeld film carries almost no net load, and friction/load is meaningless).
NET_LOAD_FRACTION = 1e-6
#: Friction coefficient above which a Newtonian traction result is flagged as unphysical.
NEWTONIAN_FRICTION_LIMIT = 0.2
#: Friction coefficients beyond this (dry-friction values; lubricated contacts stay below
#: ~0.15) are not reported: friction_force and heat_power stay, with a warning.
MAX_FRICTION_COEFFICIENT = 1.0


#: Largest double [-]: a viscosity beyond it (e.g. Barus at alpha p > 709.78) is reported
#: clipped at it (:func:`reported_viscosity`).
_MAX_FLOAT = float(np.finfo(float).max)
#: alpha p beyond which the Barus viscosity overflows [-]: ln(_MAX_FLOAT) = 709.78.
_BARUS_OVERFLOW = math.log(_MAX_FLOAT)


def reported_viscosity(eta: np.ndarray, *, law: str, reduced: bool
                       ) -> tuple[np.ndarray, list[str]]:
    """The viscosity field as reported, and warnings where it overflows double precision.

    Parameters
    ----------
    eta : ndarray
        Nodal viscosity [Pa s] by the scene's law (inf where it overflows).
    law : str
        The scene's ``lubricant.viscosity_law`` (``"barus"``, ``"roelands"``,
        ``"constant"``), named in the warning.
    reduced : bool
        True when the Reynolds equation was solved in the reduced (Kapitsa) pressure,
        which the overflow does not affect; False when the solve itself used this
        viscosity.

    Returns
    -------
    eta : ndarray
        The field [Pa s], clipped at the largest double where the law overflows.
    warnings : list of str
        One sentence when some node overflows, else empty.
    """
    eta = np.asarray(eta, dtype=float)
    over = ~np.isfinite(eta)
    if not np.any(over):
        return eta, []
    share = float(np.mean(over))
    where = (f"Barus at alpha p > {_BARUS_OVERFLOW:.1f}" if law == "barus"
             else f"{law.capitalize()} law")
    effect = ("the film solution, in the reduced pressure, is not affected" if reduced
              else "the Reynolds equation was solved with this viscosity, so the film and "
              "pressure are not meaningful there")
    return np.where(over, _MAX_FLOAT, eta), [
        f"the viscosity overflows double precision at {100 * share:.3g}% of the nodes "
        f"({where}): viscosity_Pa_s is clipped at {_MAX_FLOAT:.3g} Pa s there ({effect})"]


def friction_coefficient(friction: float, load: float, gross: float) -> tuple[float | None,
                                                                                list[str]]:
    """friction / load, or None with a warning when the load is not a positive net load
    or the ratio exceeds :data:`MAX_FRICTION_COEFFICIENT`.

    Parameters
    ----------
    friction, load : float
        Friction force and net load (int p dA) [N or N/m].
    gross : float
        int |p| dA [N or N/m].
    """
    if not (load > 0.0 and load >= NET_LOAD_FRACTION * gross):
        return None, [f"friction coefficient undefined: the film carries no positive net "
                      f"load (int p dA = {load:.4g}, int |p| dA = {gross:.4g}, in N or N/m)"]
    mu = friction / load
    if abs(mu) > MAX_FRICTION_COEFFICIENT:
        return None, [f"friction coefficient not reported: friction / load = {mu:.3g} is "
                      f"beyond {MAX_FRICTION_COEFFICIENT:g}, no lubricated contact's "
                      "(the traction model is outside its range)"]
    return mu, []


def traction_choice(traction: Any, sliding_speed: float) -> tuple[dict[str, Any], list[str]]:
    """Shear-stress parameters of a scene's ``[traction]`` section (None: the generic
    mineral-oil model) and the warnings that go with them under sliding."""
    shear = shear_parameters(traction)
    notes: list[str] = []
    if traction is None and sliding_speed != 0.0:
        notes.append(
            "sliding friction from generic mineral-oil traction parameters (no [traction] "
            f"section): {shear['model']}, Eyring stress {shear['eyring_stress'] / 1e6:.3g} MPa, "
            f"limiting shear stress {shear['limiting_shear_stress'] / 1e6:.3g} MPa + "
            f"{shear['limiting_slope']:.3g} p; give your oil's values in [traction]")
    return shear, notes


def friction_and_heat(ops: QuadratureOperators, h_q: np.ndarray,
                      grad_p_q: tuple[np.ndarray, ...], eta_q: np.ndarray, p_q: np.ndarray, *,
                      mean_speed: float, sliding_speed: float, indicator_q: np.ndarray,
                      load: float, gross_load: float, traction: Any = None,
                      reduced: tuple[tuple[np.ndarray, ...], float] | None = None,
                      stabilisation: tuple[np.ndarray, ...] | None = None
                      ) -> tuple[dict[str, Any], list[str], FilmDissipation]:
    """Summary numbers, warnings and heat densities of a film (line or point contact).

    Parameters as :func:`film_dissipation`, plus ``load``/``gross_load`` (int p dA and
    int |p| dA [N or N/m]) and the scene's ``traction`` section (or None).

    Returns
    -------
    quantities : dict
        :meth:`FilmDissipation.quantities` plus ``friction_coefficient`` (absent when
        undefined, see :func:`friction_coefficient`).
    warnings : list of str
    dissipation : FilmDissipation
        Its ``shear`` holds the traction parameters used.
    """
    shear, notes = traction_choice(traction, sliding_speed)
    d = film_dissipation(ops, h_q, grad_p_q, eta_q, p_q, mean_speed=mean_speed,
                         sliding_speed=sliding_speed, indicator_q=indicator_q, shear=shear,
                         reduced=reduced, stabilisation=stabilisation)
    q: dict[str, Any] = d.quantities()
    mu, more = friction_coefficient(d.friction_force, load, gross_load)
    notes += more
    if mu is not None:
        q["friction_coefficient"] = mu
    if not math.isfinite(d.friction_force):
        notes.append(f"friction_force and heat_power undefined: the viscosity overflows "
                     f"double precision in the film (Barus at alpha p > {_BARUS_OVERFLOW:.1f}) "
                     f"and {shear['model']} traction grows with it without bound; a limiting "
                     "shear stress bounds it (traction.model = 'limiting' or "
                     "'eyring-limiting')")
    ratio = d.friction_force / load if load > 0.0 else 0.0
    if (shear["model"] == "newtonian" and sliding_speed != 0.0
            and abs(ratio) > NEWTONIAN_FRICTION_LIMIT):
        notes.append(f"Newtonian traction gives an unphysical friction coefficient "
                     f"{ratio:.3g} (> {NEWTONIAN_FRICTION_LIMIT}): the pressure-viscosity law "
                     "makes eta u_s/h huge at contact pressures; use traction.model = "
                     "'eyring-limiting'")
    return q, notes, d


# ---------------------------------------------------------------------------------------
# error estimate from a sequence of grids
# ---------------------------------------------------------------------------------------
#: Quantities whose discretisation error is estimated.
ESTIMATED_QUANTITIES = ("h_central", "h_min", "p_max", "friction_force", "heat_power")
#: Estimated relative error above which a quantity is named in the result's warnings.
ERROR_WARNING_THRESHOLD = 0.05
#: Formal order of convergence of the discretisation (P1 elements: second order for
#: nodal values and integrals of smooth solutions). An observed order above it is capped
#: at it, the usual safeguard when the coarsest grid is not in the asymptotic range.
FORMAL_ORDER = 2.0
#: Smallest observed order for which Richardson extrapolation is used: below it (or with
#: changes of alternating sign, or not shrinking) the plain level difference is reported.
MIN_ORDER = 0.5


def richardson(values: Sequence[float]) -> tuple[float | None, str, float | None]:
    """Estimated absolute error of the last of a sequence of solutions, each on a grid
    with half the spacing of the one before.

    With three values q1, q2, q3 and changes d1 = q2 - q1, d2 = q3 - q2 of one sign and
    |d2| < |d1|, the observed order is p = log2(d1/d2); for p >= ``MIN_ORDER`` the error
    of q3 is |d2| / (2^p' - 1) with p' = min(p, ``FORMAL_ORDER``) (Richardson). Otherwise,
    and with only two values, it is the plain level difference |d2|, which overestimates
    the error of a converging sequence; with one value there is no estimate.

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
            if p >= MIN_ORDER:
                return abs(d2) / (2.0 ** min(p, FORMAL_ORDER) - 1.0), "richardson", p
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
        (how many solutions were used), ``grids`` and ``values`` (each quantity on every
        grid, coarse to fine).
    """
    out: dict[str, Any] = {}
    methods: dict[str, str] = {}
    orders: dict[str, float | None] = {}
    for key in ESTIMATED_QUANTITIES:
        vals: list[float] = []
        for lv in levels:  # the trailing run of finite values, coarse to fine
            v = _finite_or_none(lv.get(key))
            vals = vals + [v] if v is not None else []
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
    out["values"] = {k: [_finite_or_none(lv.get(k)) for lv in levels]
                     for k in ESTIMATED_QUANTITIES}
    return out


def _finite_or_none(v: Any) -> float | None:
    """``v`` as a float, or None for a missing, non-numeric or non-finite value (never
    NaN/inf in a summary)."""
    if not isinstance(v, (int, float, np.floating)) or not math.isfinite(float(v)):
        return None
    return float(v)


def estimate_warnings(estimate: Mapping[str, Any] | None,
                      threshold: float = ERROR_WARNING_THRESHOLD) -> list[str]:
    """Sentences naming every quantity whose estimated relative error exceeds
    ``threshold``."""
    if not estimate:
        return []
    if estimate.get("levels", 0) < 2:
        grids = estimate.get("grids") or ""
        return ["no error estimate: no coarser grid of this solve converged (or the grid "
                "cannot be halved" + (f"; {grids}" if grids else "") + "), so the "
                "discretisation error is unknown; compare with a solve on a finer mesh "
                "(mesh.nodes)"]
    out = []
    for key in ESTIMATED_QUANTITIES:
        e = estimate.get(key)
        if e is not None and e > threshold:
            how = estimate.get("method", {}).get(key, "")
            out.append(f"{key} is not mesh-converged: estimated discretisation error "
                       f"{100 * e:.3g}% ({how}, {estimate.get('grids', '')}); refine the "
                       "mesh (mesh.nodes)")
    return out


#: The sentence of :func:`estimate_warnings` for one quantity (its last clause may name
#: the mesh field in other terms, as a bearing does).
_ESTIMATE_WARNING = re.compile(
    r"(?P<key>\w+) is not mesh-converged: estimated discretisation error "
    r"(?P<error>[0-9.e+-]+)% \((?P<how>richardson|level difference), (?P<grids>[^;]*)\); "
    r"(?P<tail>refine the mesh .*)")


def parse_estimate_warning(text: str) -> dict[str, str] | None:
    """The parts of one :func:`estimate_warnings` sentence, or None for another text.

    Returns
    -------
    dict or None
        ``key`` (the quantity), ``error`` (the estimated relative error in per cent, as
        written), ``how`` (``richardson`` or ``level difference``), ``grids`` (the grids
        note) and ``tail`` (the closing advice).
    """
    m = _ESTIMATE_WARNING.fullmatch(text)
    return m.groupdict() if m else None

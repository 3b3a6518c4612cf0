"""The linear path of rigid scenes: Kapitsa's reduced pressure and the obstacle problem.

For a rigid, incompressible, isothermal scene with a prescribed gap, the reduced
pressure q = int_0^p eta0/eta(s) ds turns the Reynolds equation into the isoviscous one
(``docs/theory.md``, "Barus transform"): one sparse solve for full-Sommerfeld, a
primal-dual active set of sparse solves for Reynolds cavitation (an obstacle problem,
q >= 0). For Barus (Kapitsa) q = (1 - exp(-alpha p))/alpha, and p = -ln(1 - alpha q)/alpha
exists only while alpha max q < 1; for Roelands (Reynolds cavitation) p exists only
while max q < q_inf = int_0^inf eta0/eta dp. Beyond either limit the status is
``no_solution``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..analytic import (ROELANDS_REDUCED_MIN_INDEX, barus_from_reduced, reduced_from_barus,
                        reduced_from_roelands, roelands_from_reduced,
                        roelands_reduced_limit)
from ..physics.rheology import roelands_index


@dataclass(frozen=True)
class ReducedLaw:
    """The reduced-pressure transform q(p) = int_0^p eta0/eta(s) ds of a viscosity law.

    Attributes
    ----------
    law : str
        "constant", "barus" or "roelands".
    q_limit : float
        Largest reduced pressure of any pressure [Pa] (inf for a constant viscosity,
        1/alpha for Barus, :func:`bearing_fem.analytic.roelands_reduced_limit`).
    to_reduced, from_reduced : callable
        p [Pa] -> q [Pa] and back (``inf`` beyond ``q_limit``).
    piezo : float
        alpha [1/Pa] (0 for a constant viscosity).
    """

    law: str
    q_limit: float
    to_reduced: Callable[[np.ndarray], np.ndarray]
    from_reduced: Callable[[np.ndarray], np.ndarray]
    piezo: float


def reduced_law(lubricant) -> ReducedLaw:
    """The :class:`ReducedLaw` of a scene's ``[lubricant]`` (its ``effective_piezo``)."""
    alpha = lubricant.effective_piezo
    if lubricant.viscosity_law == "constant" or alpha == 0.0:
        return ReducedLaw("constant", np.inf, lambda p: np.asarray(p, dtype=float),
                          lambda q: np.asarray(q, dtype=float), 0.0)
    if lubricant.viscosity_law == "barus":
        return ReducedLaw("barus", 1.0 / alpha, lambda p: reduced_from_barus(p, alpha),
                          lambda q: barus_from_reduced(q, alpha), alpha)
    if lubricant.viscosity_law == "roelands":
        eta0 = lubricant.viscosity
        return ReducedLaw("roelands", roelands_reduced_limit(eta0, alpha),
                          lambda p: reduced_from_roelands(p, eta0, alpha),
                          lambda q: roelands_from_reduced(q, eta0, alpha), alpha)
    raise ValueError(f"no reduced pressure for viscosity_law {lubricant.viscosity_law!r}")


def is_linear_scene(scene) -> bool:
    """True if a scene is solved by linear solves of the reduced pressure: rigid,
    incompressible, prescribed gap, and a constant or Barus viscosity, or a Roelands one
    with Reynolds cavitation (whose reduced pressure stays >= 0 inside the domain; end
    pressures down to -p0 have their own, negative, q) and a pressure index Z >= ``ROELANDS_REDUCED_MIN_INDEX`` (where its closed
    form holds double precision; a smaller Z is nearly isoviscous and goes to Newton)."""
    m, lub = scene.model, scene.lubricant
    if not (m.elasticity == "rigid" and lub.density == "incompressible"
            and scene.load.gap is not None):
        return False
    if lub.viscosity_law in ("constant", "barus") or lub.effective_piezo == 0.0:
        return True
    return (lub.viscosity_law == "roelands" and m.cavitation == "reynolds"
            and roelands_index(lub.viscosity, lub.effective_piezo)
            >= ROELANDS_REDUCED_MIN_INDEX)


def is_rigid_barus_load(scene) -> bool:
    """True for a rigid, incompressible Barus (alpha > 0) scene with the Reynolds outlet
    under a load: the scenes whose largest load is Kapitsa's existence limit
    alpha q_max = 1 at its own gap (line: ``analytic.martin_barus_load_limit``, point:
    ``contacts.point.rigid_barus_point_load_limit``)."""
    m, lub = scene.model, scene.lubricant
    return (m.elasticity == "rigid" and scene.load.force is not None
            and lub.viscosity_law == "barus" and lub.effective_piezo > 0.0
            and lub.density == "incompressible" and m.cavitation == "reynolds")


def active_set_solve(a: sp.spmatrix, f: np.ndarray, q_bc: np.ndarray, free: np.ndarray,
                     cavitation: str, max_sweeps: int = 200,
                     active: np.ndarray | None = None
                     ) -> tuple[np.ndarray, int, np.ndarray]:
    """Linear Reynolds problem A q = f with Dirichlet data, optionally with q >= 0.

    Full-Sommerfeld (``cavitation != "reynolds"``): one sparse solve on the free nodes.
    Reynolds: primal-dual active set for q >= 0, A q - f >= 0, q (A q - f) = 0 (a node
    is cavitated when its scaled multiplier (A q - f)_i / A_ii exceeds q_i); stops when
    the active set repeats, after at most ``max_sweeps`` solves. ``active`` (bool, per
    node) is a first guess of the cavitated set, e.g. from a coarser grid's solution
    (measured on a 161^2 ball grid started from its 81^2 solution: 3 instead of 20 solves); if the sweeps from it do not
    settle within ``max_sweeps``, they restart from the empty set (and count both runs).

    Parameters
    ----------
    a : sparse matrix
        Assembled Reynolds operator (nodes x nodes).
    f : ndarray
        Load vector.
    q_bc : ndarray
        Nodal vector whose entries at the non-free nodes are the Dirichlet data [Pa].
    free : ndarray of int
        Indices of the unknown nodes.
    cavitation : {"none", "reynolds"}
    max_sweeps : int

    Returns
    -------
    q : ndarray (nodal, Pa); linear_solves : int; active : bool ndarray (cavitated nodes)
    """
    cold = np.zeros(q_bc.size, dtype=bool)
    if active is None or cavitation != "reynolds":
        q, solves, found, _ = _sweeps(a, f, q_bc, free, cavitation, max_sweeps, cold)
        return q, solves, found
    start = cold.copy()
    start[free] = np.asarray(active, dtype=bool)[free]
    q, solves, found, settled = _sweeps(a, f, q_bc, free, cavitation, max_sweeps, start)
    if not settled:
        q, more, found, _ = _sweeps(a, f, q_bc, free, cavitation, max_sweeps, cold)
        solves += more
    return q, solves, found


def _sweeps(a: sp.spmatrix, f: np.ndarray, q_bc: np.ndarray, free: np.ndarray,
            cavitation: str, max_sweeps: int, active: np.ndarray
            ) -> tuple[np.ndarray, int, np.ndarray, bool]:
    """The active-set sweeps of :func:`active_set_solve` from ``active``: q, the number
    of solves, the final set and whether it settled (repeated)."""
    n = q_bc.size
    rhs = f - a @ q_bc
    diag = a.diagonal()
    q, solves = q_bc.copy(), 0
    for _ in range(max_sweeps):
        inactive = free[~active[free]]
        q = q_bc.copy()
        q[active] = 0.0
        if inactive.size:
            q[inactive] = spla.spsolve(a[inactive][:, inactive].tocsc(), rhs[inactive])
        solves += 1
        if cavitation != "reynolds":
            return q, solves, active, True
        lam = a @ q - f
        new_active = np.zeros(n, dtype=bool)
        new_active[free] = lam[free] / diag[free] > q[free]
        if np.array_equal(new_active, active):
            return q, solves, active, True
        active = new_active
    return q, solves, active, False


def no_solution_message(law: ReducedLaw, q_max: float) -> str:
    """Status message of a rigid piezo-viscous scene beyond its existence limit."""
    if law.law == "barus":
        alpha = law.piezo
        return (f"no solution: rigid piezo-viscous (Barus) pressure does not exist since "
                f"alpha*q_max = {alpha * q_max:.4g} >= 1 (Kapitsa transform, docs/theory.md; "
                f"alpha = {alpha:.3g} 1/Pa, q_max = {q_max:.4g} Pa). The pressure field "
                "holds the isoviscous reduced pressure q instead.")
    return (f"no solution: rigid piezo-viscous (Roelands) pressure does not exist since "
            f"q_max = {q_max:.4g} Pa reaches q_inf = {law.q_limit:.4g} Pa, the reduced "
            "pressure int_0^inf eta0/eta dp of the Roelands law (no pressure has a larger "
            "one; docs/theory.md). The pressure field holds the isoviscous reduced "
            "pressure q instead.")


def pressure_from_reduced(q: np.ndarray, law: ReducedLaw, solves: int,
                          detail: str = "") -> tuple[str, np.ndarray, str]:
    """Status, nodal field and message of the linear (reduced-pressure) path.

    ``linear`` with p = law.from_reduced(q) while q_max < law.q_limit and every p is
    finite (q within rounding of the limit has none), else ``no_solution`` with q itself
    as the (finite) field. ``detail`` is appended to the description of the solve in
    the message.
    """
    q_max = float(np.max(q))
    if q_max >= law.q_limit:
        return "no_solution", q, no_solution_message(law, q_max)
    p = law.from_reduced(q)
    if not np.all(np.isfinite(p)):
        return "no_solution", q, no_solution_message(law, q_max)
    if law.law == "barus":
        margin = f"alpha*q_max = {law.piezo * q_max:.3g} < 1"
    elif law.law == "roelands":
        margin = f"q_max/q_inf = {q_max / law.q_limit:.3g} < 1 (Roelands)"
    else:
        margin = "isoviscous"
    return "linear", p, (f"solved by {solves} linear solve(s) (rigid, reduced pressure"
                         f"{detail}); {margin}")



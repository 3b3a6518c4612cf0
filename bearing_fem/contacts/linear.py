"""The linear path of rigid scenes: Kapitsa's reduced pressure and the obstacle problem.

For a rigid, incompressible scene with constant or Barus viscosity and a prescribed gap,
Kapitsa's transform q = (1 - exp(-alpha p))/alpha turns the Reynolds equation into the
isoviscous one (``docs/theory.md``, "Barus transform"): one sparse solve for
full-Sommerfeld, a primal-dual active set of sparse solves for Reynolds cavitation (an
obstacle problem, q >= 0). Then p = -ln(1 - alpha q)/alpha exists only while
alpha max q < 1; beyond that limit the status is ``no_solution``.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..analytic import barus_from_reduced

def active_set_solve(a: sp.spmatrix, f: np.ndarray, q_bc: np.ndarray, free: np.ndarray,
                     cavitation: str, max_sweeps: int = 200
                     ) -> tuple[np.ndarray, int, np.ndarray]:
    """Linear Reynolds problem A q = f with Dirichlet data, optionally with q >= 0.

    Full-Sommerfeld (``cavitation != "reynolds"``): one sparse solve on the free nodes.
    Reynolds: primal-dual active set for q >= 0, A q - f >= 0, q (A q - f) = 0 (a node
    is cavitated when its scaled multiplier (A q - f)_i / A_ii exceeds q_i); stops when
    the active set repeats, after at most ``max_sweeps`` solves.

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
    n = q_bc.size
    rhs = f - a @ q_bc
    active = np.zeros(n, dtype=bool)
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
            break
        lam = a @ q - f
        new_active = np.zeros(n, dtype=bool)
        new_active[free] = lam[free] / diag[free] > q[free]
        if np.array_equal(new_active, active):
            break
        active = new_active
    return q, solves, active


def no_solution_message(alpha: float, q_max: float) -> str:
    """Status message of a rigid Barus scene beyond Kapitsa's existence limit."""
    return (f"no solution: rigid piezo-viscous (Barus) pressure does not exist since "
            f"alpha*q_max = {alpha * q_max:.4g} >= 1 (Kapitsa transform, docs/theory.md; "
            f"alpha = {alpha:.3g} 1/Pa, q_max = {q_max:.4g} Pa). The pressure field "
            "holds the isoviscous reduced pressure q instead.")


def pressure_from_reduced(q: np.ndarray, alpha: float, solves: int,
                          detail: str = "") -> tuple[str, np.ndarray, str]:
    """Status, nodal field and message of the linear (reduced-pressure) path.

    ``linear`` with p = -ln(1 - alpha q)/alpha while alpha q_max < 1, else
    ``no_solution`` with q itself as the (finite) field. ``detail`` is appended to the
    description of the solve in the message.
    """
    q_max = float(np.max(q))
    if alpha * q_max >= 1.0:
        return "no_solution", q, no_solution_message(alpha, q_max)
    p = barus_from_reduced(q, alpha) if alpha > 0 else q
    return "linear", p, (f"solved by {solves} linear solve(s) (rigid, reduced pressure"
                         f"{detail}); alpha*q_max = {alpha * q_max:.3g} < 1")



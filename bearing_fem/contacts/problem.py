"""Parts shared by the discretised contact problems (line, point, transient, Kodnir).

* :func:`fischer_burmeister` - the smoothed Fischer-Burmeister function of the Reynolds
  cavitation complementarity problem p >= 0, R >= 0, p R = 0 (semismooth Newton), and
  :func:`row_smoothing`, its smoothing per row.
* :class:`ScaledResidual` - the scaled residual (Reynolds rows or their FB functions,
  then the load row) and the admissibility test (finite unknowns, positive film).
"""
from __future__ import annotations

import numpy as np

#: Smoothing of the Fischer-Burmeister function (scaled units). A degenerate node with
#: p = R = 0 (the discrete free boundary) makes the plain FB Jacobian singular and lets
#: the semismooth Newton cycle between two active sets; with mu > 0 the function is
#: smooth and its root satisfies p >= 0, R >= 0, p R = mu^2, i.e. complementarity
#: to 1e-20 in scaled units (p/p_ref times the scaled residual).
FB_SMOOTHING = 1e-10


def row_smoothing(row_scale: np.ndarray, mu: float = FB_SMOOTHING) -> np.ndarray:
    """Smoothing of each row's Fischer-Burmeister function, mu_i = mu sqrt(s_i / max s).

    At the root of the smoothed function a b = mu_i^2 (a = p_i / p_ref, b = s_i R_i), so
    every pressurised row carries the residual R_i = mu_i^2 p_ref / (p_i s_i) (``s_i`` the
    row scale, of the inverse unit of the nodal residual R_i), and p_i R_i, the row's
    share of the energy balance (sum_i p_i R_i = 0 for an exact discrete solution), is
    mu_i^2 p_ref / s_i. With a single mu that share grows as h^3 / dx: on the far inlet
    of a heavily loaded line contact (h a thousand times h_min) it summed to 1-2.4 % of
    the Poiseuille heat on fine grids, growing as N^2. With mu_i it is the same in every
    row, that of the row with the largest scale (the thinnest film, where the free
    boundary and its degenerate nodes lie and the full mu is kept). Used by line contacts,
    whose free boundary is the outlet next to the film minimum; a point contact's
    cavitation boundary also runs round the sides of the contact at larger films, and
    keeps the one mu there.

    Parameters
    ----------
    row_scale : ndarray
        Positive row scale s_i of the free rows.
    mu : float
        Smoothing of the row with the largest scale (scaled units).

    Returns
    -------
    ndarray
        mu_i, one per row.
    """
    s = np.asarray(row_scale, dtype=float)
    return mu * np.sqrt(s / np.max(s))

def fischer_burmeister(a: np.ndarray, b: np.ndarray,
                       mu: float = FB_SMOOTHING) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Smoothed FB function phi = a + b - sqrt(a^2 + b^2 + 2 mu^2) and its derivatives."""
    r = np.sqrt(a * a + b * b + 2.0 * mu * mu)
    phi = a + b - r
    zero = r < 1e-300
    rs = np.where(zero, 1.0, r)
    da = np.where(zero, 1.0 - 1.0 / np.sqrt(2.0), 1.0 - a / rs)
    db = np.where(zero, 1.0 - 1.0 / np.sqrt(2.0), 1.0 - b / rs)
    return phi, da, db


class ScaledResidual:
    """Parts shared by the line and point problems: the scaled residual (Reynolds rows, or
    their Fischer-Burmeister functions, at the free nodes, then the load row) and the
    admissibility test (finite unknowns, positive film at every quadrature point), the
    reduced-pressure gradient of the Poiseuille term and the elastic displacement with
    its last product kept. Needs ``unpack``, ``fields_q``, ``reynolds_residual``,
    ``free``, ``_row_scale``, ``_fb_mu`` (the FB smoothing: per row for line contacts),
    ``cavitation``, ``p_ref``, ``has_h0``, ``mass``, ``load``,
    ``flux``, ``ops`` (the quadrature operators) and ``compliance`` (an operator with
    ``apply(p) -> v``)."""

    def compliance_product(self, p: np.ndarray) -> np.ndarray:
        """Elastic displacement v = C p [m] of the nodal pressure ``p`` [Pa] by
        ``self.compliance.apply``; the last product is kept (a Newton iteration needs the
        same iterate's v in the admissibility test, the residual, the row scaling and the
        Jacobian). The returned array is shared with the cache and must not be modified."""
        cached = getattr(self, "_displacement_cache", None)
        if cached is not None and np.array_equal(cached[0], p):
            return cached[1]
        v = self.compliance.apply(p)
        self._displacement_cache = (np.array(p, dtype=float, copy=True), v)
        return v

    @property
    def uses_reduced(self) -> bool:
        """True if the Poiseuille term is rho h^3/(12 eta0) grad q_h (reduced pressure)."""
        return getattr(self.flux, "reduced_alpha", None) is not None

    def grad_reduced(self, p: np.ndarray) -> tuple[np.ndarray, ...]:
        """Gradient of the interpolant q_h of the nodal reduced pressure q(p) at the
        quadrature points [Pa/m], one array per dimension
        (:meth:`~bearing_fem.physics.reynolds.UpwindFluxModel.reduced`)."""
        q = self.flux.reduced(p)
        return tuple(g @ q for g in self.ops.grad)

    def admissible(self, z: np.ndarray) -> bool:
        if not np.all(np.isfinite(z)):
            return False
        p, h0 = self.unpack(z)
        _, h, _, _ = self.fields_q(p, h0)
        return bool(np.min(h) > 0.0)

    def nodal_residual(self, z: np.ndarray) -> tuple[np.ndarray, float, np.ndarray]:
        """p [Pa], h0 [m] and the unscaled nodal Reynolds residual of ``z``.

        The last evaluation is kept: Newton asks for the residual of the same iterate
        up to three times (line search, after the row scaling is updated, and in the
        step), and only the row scaling differs. A problem's data never change after
        construction, so the unknowns alone identify the evaluation.
        """
        cached = getattr(self, "_nodal_cache", None)
        if cached is not None and np.array_equal(cached[0], z):
            return cached[1], cached[2], cached[3]
        p, h0 = self.unpack(z)
        r = self.reynolds_residual(p, h0)
        self._nodal_cache = (np.array(z, dtype=float, copy=True), p, h0, r)
        return p, h0, r

    def residual(self, z: np.ndarray) -> np.ndarray:
        p, h0, r = self.nodal_residual(z)
        r = r[self.free] * self._row_scale
        if self.cavitation == "reynolds":
            r, _, _ = fischer_burmeister(p[self.free] / self.p_ref, r, self._fb_mu)
        if self.has_h0:
            r = np.append(r, (self.mass @ p - self.load) / self.load)
        return r



"""The Reynolds equation in flux form, pointwise, with streamline-upwind stabilisation.

Strong form (docs/theory.md section 2, steady, u_m along +x):

    div( eps grad p ) = u_m d(rho h)/dx,      eps = rho h^3 / (12 eta)

Weak (flux) form used by the finite elements, for every test function v vanishing on
Dirichlet boundaries:

    R(v) = int F . grad v = 0,   F = eps grad p - u_m rho h e_x  +  SUPG

Symbols: p pressure [Pa], h film [m], eta viscosity [Pa s], rho relative density [-],
u_m mean speed [m/s], eps flow coefficient [m^3/(Pa s)], F flux [m^2/s].

Stabilisation (streamline-upwind Petrov-Galerkin, as used for EHL by Habchi et al.):
where eta is huge the equation degenerates to pure advection d(rho h)/dx = 0 and the
Galerkin method oscillates. The test function v is replaced by v + tau beta dv/dx with
an effective advection speed beta = u_m rho c, c being the local compliance dh/dp
[m/Pa] of the elastic model, and the classical optimal tau:

    Pe = beta dx / (2 eps),   tau beta = (dx/2) (coth Pe - 1/Pe).

It multiplies the element-wise strong residual S = -d(eps)/dx dp/dx + u_m d(rho h)/dx
(P1: no second derivatives), so it vanishes for the exact solution (consistent) and
fades out where the Poiseuille term dominates (Pe -> 0). Rigid scenes have no
advection of pressure (h does not depend on p) and use no stabilisation.

The pointwise flux is a plain numpy function of (p, h, grad p, grad h); its
partial derivatives, needed by Newton, are taken by the complex-step method (exact to
rounding), so any analytic viscosity or density law can be plugged in.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Callable

import numpy as np

#: Gradient (or flux) components at the quadrature points, x first.
Grad = tuple[np.ndarray, ...]

from .rheology import density_function, viscosity_function

_STEP = 1e-20  # complex-step size relative to the largest magnitude of the variable


@dataclass(frozen=True)
class FluxModel:
    """Pointwise Reynolds flux of one scene.

    Parameters
    ----------
    viscosity : callable p -> eta [Pa s]
    density : callable p -> rho/rho0 [-]
    mean_speed : float
        u_m [m/s].
    compliance : float
        Effective local compliance c = dh/dp [m/Pa] used by the stabilisation;
        0 disables it (rigid scenes).
    """

    viscosity: Callable[[np.ndarray], np.ndarray]
    density: Callable[[np.ndarray], np.ndarray]
    mean_speed: float
    compliance: float = 0.0
    log_viscosity_slope: float = 0.0  # alpha [1/Pa]: d ln(eta)/dp at p = 0 (step control)

    @classmethod
    def from_lubricant(cls, lubricant, mean_speed: float, compliance: float = 0.0,
                       piezo_scale: float = 1.0) -> "FluxModel":
        """Build from a :class:`~bearing_fem.scene.Lubricant`; ``piezo_scale`` multiplies
        alpha (continuation parameter)."""
        eta = viscosity_function(lubricant.viscosity_law, lubricant.viscosity,
                                 lubricant.effective_piezo * piezo_scale)
        return cls(viscosity=eta, density=density_function(lubricant.density),
                   mean_speed=mean_speed, compliance=compliance,
                   log_viscosity_slope=lubricant.effective_piezo * piezo_scale)

    def coefficient(self, p: np.ndarray, h: np.ndarray) -> np.ndarray:
        """eps = rho h^3 / (12 eta) [m^3/(Pa s)]."""
        return self.density(p) * h**3 / (12.0 * self.viscosity(p))

    def flux(self, p: np.ndarray, h: np.ndarray, gp: Grad, gh: Grad,
             dx: np.ndarray) -> Grad:
        """Flux F at quadrature points [m^2/s].

        Parameters
        ----------
        p, h : arrays
            Pressure [Pa] and film [m] at the quadrature points.
        gp, gh : tuple of arrays
            Gradients of p [Pa/m] and h [-] (one entry per space dimension, x first).
        dx : array
            Element size along x [m] (stabilisation only).

        Returns
        -------
        tuple of arrays, one flux component per dimension.
        """
        rho = self.density(p)
        eps = rho * h**3 / (12.0 * self.viscosity(p))
        out = [eps * g for g in gp]
        out[0] = out[0] - self.mean_speed * rho * h
        if self.compliance > 0.0:
            dlnrho, dlneta = self._log_slopes(p)
            # strong residual of the P1 element: -grad(eps).grad(p) + u_m d(rho h)/dx
            strong = self.mean_speed * rho * (dlnrho * gp[0] * h + gh[0])
            for a, b in zip(gp, gh):
                strong = strong - eps * ((dlnrho - dlneta) * a + 3.0 * b / h) * a
            pe = self.mean_speed * rho * self.compliance * dx / (2.0 * eps)
            out[0] = out[0] + 0.5 * dx * upwind_factor(pe) * strong
        return tuple(out)

    def galerkin_flux(self, p: np.ndarray, h: np.ndarray, gp: Grad,
                      gq: Grad | None = None) -> Grad:
        """The flux without stabilisation, rho h^3/(12 eta) grad p - u_m rho h e_x, at the
        quadrature points [m^2/s] (``gq`` is not used here; see
        :meth:`UpwindFluxModel.galerkin_flux`)."""
        rho = self.density(p)
        out = [rho * h**3 / (12.0 * self.viscosity(p)) * g for g in gp]
        out[0] = out[0] - self.mean_speed * rho * h
        return tuple(out)

    def stabilisation_flux(self, p: np.ndarray, h: np.ndarray, gp: Grad, gh: Grad,
                           dx: np.ndarray, gq: Grad | None = None) -> Grad:
        """What the stabilisation adds to the flux [m^2/s]: :meth:`flux` minus
        :meth:`galerkin_flux`. Its integral against grad p is the numerical dissipation of
        the scheme (``bearing_fem.post``)."""
        full = self.flux(p, h, gp, gh, dx) if gq is None else self.flux(p, h, gp, gh, dx,
                                                                        gq=gq)
        return tuple(f - g for f, g in zip(full, self.galerkin_flux(p, h, gp, gq)))

    def _log_slopes(self, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """d ln(rho)/dp and d ln(eta)/dp [1/Pa] by a central difference on the laws.

        Used only inside the stabilisation term; the complex-step derivative of the whole
        flux still differentiates it consistently.
        """
        dp = 1e3  # Pa; every law here is smooth on this scale
        lr = (np.log(self.density(p + dp)) - np.log(self.density(p - dp))) / (2 * dp)
        le = (np.log(self.viscosity(p + dp)) - np.log(self.viscosity(p - dp))) / (2 * dp)
        return lr, le

    def flux_and_derivatives(self, p: np.ndarray, h: np.ndarray, gp: Grad, gh: Grad,
                             dx: np.ndarray) -> tuple:
        """Flux and its exact partial derivatives (complex step) at each quadrature point.

        Returns
        -------
        F : tuple of arrays (one per dimension)
        dF_dp, dF_dh : tuple of arrays (one per flux component)
        dF_dgp, dF_dgh : list over gradient components k of tuples over flux components
        """
        base = self.flux(p, h, gp, gh, dx)

        def deriv(which: str, k: int = 0):
            return self._complex_step(p, h, gp, gh, dx, which, k)

        dim = len(gp)
        return (base, deriv("p"), deriv("h"),
                [deriv("gp", k) for k in range(dim)], [deriv("gh", k) for k in range(dim)])

    def _complex_step(self, p, h, gp, gh, dx, which: str, k: int = 0):
        """Complex-step derivative of the flux with respect to ``which`` ("p", "h", or
        component ``k`` of "gp"/"gh"): a tuple over flux components."""
        args = {"p": p, "h": h, "gp": list(gp), "gh": list(gh)}
        v = args[which] if which in ("p", "h") else args[which][k]
        vmax = float(np.max(np.abs(v))) if np.size(v) else 0.0
        step = _STEP * (vmax if vmax > 0.0 else 1.0)
        if which in ("p", "h"):
            args[which] = v + 1j * step
        else:
            args[which][k] = v + 1j * step
        out = self.flux(args["p"], args["h"], tuple(args["gp"]), tuple(args["gh"]), dx)
        return tuple(np.imag(f) / step for f in out)


@dataclass(frozen=True)
class UpwindFluxModel(FluxModel):
    """Reynolds flux with a first-order upwinded wedge term (elastic contacts).

    F_x = eps dp/dx - u_m rho h + xi (dx/2) u_m d(rho h)/dx,

    xi = coth(Pe) - 1/Pe, Pe = u_m rho c dx / (2 eps), c = ``upwind_compliance`` [m/Pa].

    Where the wedge term dominates (Pe >> 1: the high-pressure zone, where eta is huge)
    the added streamline diffusion turns the Galerkin (central) wedge difference
    (rho h)_(i+1) - (rho h)_(i-1) into the upwind difference (rho h)_i - (rho h)_(i-1)
    that Venner & Lubrecht use for EHL; where Poiseuille flow dominates (the inlet,
    Pe -> 0) it fades out. Unlike SUPG on the whole strong residual, it leaves out the
    Poiseuille part -d(eps)/dx dp/dx, which at the outlet pressure spike changes by
    orders of magnitude from node to node: measured at M = 100, L = 10 (half-space),
    SUPG stagnated at 2001 nodes while this flux converged at 1001, 2001 and 4001
    nodes, with the same h_central at 4001 nodes to 1e-5 (docs/theory.md). The extra
    term is O(dx) times d(rho h)/dx, which vanishes in the flat Hertzian zone.
    Point contacts use it too: without it, bilinear Galerkin elements give odd-even
    (checkerboard) pressures at the outlet of an elastic point contact.
    ``compliance`` (SUPG) is ignored. Valid in 1D and 2D (the wedge term is along x).
    """

    upwind: float = 1.0
    upwind_compliance: float = 0.0
    #: Barus alpha [1/Pa] of the reduced-pressure Poiseuille term (None: eps grad p at the
    #: quadrature points). See :meth:`reduced`.
    reduced_alpha: float | None = None
    #: eta0 [Pa s] of the reduced-pressure Poiseuille term.
    viscosity0: float = 0.0

    @classmethod
    def elastic(cls, lubricant, mean_speed: float, upwind_compliance: float,
                piezo_scale: float = 1.0,
                reduced_alpha: float | None = None) -> "UpwindFluxModel":
        """Flux of an elastic (half-space) contact.

        Parameters
        ----------
        lubricant : Lubricant
        mean_speed : float
            u_m [m/s].
        upwind_compliance : float
            c of the Peclet fade-out [m/Pa].
        piezo_scale : float
            Multiplies alpha (continuation parameter) [-].
        reduced_alpha : float or None
            Barus alpha [1/Pa] of the reduced-pressure Poiseuille term (None: pointwise).
        """
        return replace(cls.from_lubricant(lubricant, mean_speed, piezo_scale=piezo_scale),
                       upwind_compliance=upwind_compliance, reduced_alpha=reduced_alpha,
                       viscosity0=lubricant.viscosity)

    def reduced(self, p: np.ndarray) -> np.ndarray:
        """Kapitsa reduced pressure q(p) = int_0^p eta0/eta ds = (1 - exp(-alpha p))/alpha
        [Pa] (Barus; q = p when alpha = 0)."""
        a = self.reduced_alpha
        return np.asarray(p, dtype=float) if not a else -np.expm1(-a * np.asarray(p)) / a

    def fluidity(self, p: np.ndarray) -> np.ndarray:
        """dq/dp = eta0/eta(p) [-]."""
        a = self.reduced_alpha
        return np.ones_like(p, dtype=float) if not a else np.exp(-a * np.asarray(p))

    def _coefficients(self, p, h, dx):
        """rho [-], eps [m^3/(Pa s)], d rho/dp [1/Pa], the upwind factor (dx/2) u_m xi
        [m^2/s] and the cell Peclet number Pe [-] (None without the Peclet fade-out) at
        the quadrature points (real or complex-step input)."""
        rho = self.density(p)
        eps = rho * (h * h * h) / (12.0 * self.viscosity(p))  # h*h*h: pow() is slow
        dp = 1e3  # Pa; smooth density laws
        drho = (self.density(p + dp) - self.density(p - dp)) / (2 * dp)
        xi, pe = 1.0, None
        if self.upwind_compliance > 0.0:  # fade out where Poiseuille flow dominates
            # eps underflows to 0 where exp(-alpha p) does (Barus, alpha p > ~745): Pe is
            # infinite there and xi(Pe) = 1, its limit
            with np.errstate(divide="ignore"):
                pe = self.mean_speed * rho * self.upwind_compliance * dx / (2.0 * eps)
            xi = upwind_factor(pe)
        return rho, eps, drho, 0.5 * self.upwind * xi * dx * self.mean_speed, pe

    def _flux_dh(self, rho, eps, drho, c, pe, h, gp, gh, gq, dx):
        """dF/dh at fixed p and gradients [m/s] (tuple over flux components), real input.

        The film enters the flux through h^3 (eps, or rho h^3/(12 eta0) with ``gq``), the
        wedge -u_m rho h, and the upwind factor c = (dx/2) u_m xi(Pe) (times
        rho dh/dx + h drho/dp dp/dx), with Pe ~ 1/eps ~ h^-3, so dPe/dh = -3 Pe/h.
        Replaces a complex-step evaluation of the whole flux (same result to rounding).
        """
        if gq is None:
            out = [3.0 * eps / h * g for g in gp]
        else:
            k3 = rho * (h * h) / (4.0 * self.viscosity0)  # d/dh rho h^3/(12 eta0)
            out = [k3 * g for g in gq]
        out[0] = out[0] - self.mean_speed * rho + c * drho * gp[0]
        if pe is not None:
            # dPe/dh = -3 Pe / h
            dc = 0.5 * self.upwind * dx * self.mean_speed * _xi_chain(pe, -3.0 / h)
            out[0] = out[0] + dc * (rho * gh[0] + h * drho * gp[0])
        return tuple(out)

    def galerkin_flux(self, p: np.ndarray, h: np.ndarray, gp: Grad,
                      gq: Grad | None = None) -> Grad:
        """The flux without the upwind term [m^2/s]: the Poiseuille term (with ``gq``,
        rho h^3/(12 eta0) grad q) minus the wedge term u_m rho h e_x."""
        if gq is None:
            return super().galerkin_flux(p, h, gp)
        rho = self.density(p)
        k = rho * h**3 / (12.0 * self.viscosity0)
        out = [k * g for g in gq]
        out[0] = out[0] - self.mean_speed * rho * h
        return tuple(out)

    def flux(self, p: np.ndarray, h: np.ndarray, gp: Grad, gh: Grad, dx: np.ndarray,
             gq: Grad | None = None) -> Grad:
        """Flux at the quadrature points [m^2/s]; with ``gq`` (gradient of the
        interpolated nodal reduced pressure [Pa/m]) the Poiseuille term is
        rho h^3/(12 eta0) grad q instead of eps grad p."""
        return self._assemble_flux(*self._coefficients(p, h, dx)[:4], h, gp, gh, gq)

    def _assemble_flux(self, rho, eps, drho, c, h, gp, gh, gq):
        if gq is None:
            out = [eps * g for g in gp]
        else:
            k = rho * (h * h * h) / (12.0 * self.viscosity0)
            out = [k * g for g in gq]
        out[0] = out[0] - self.mean_speed * rho * h
        out[0] = out[0] + c * (rho * gh[0] + h * drho * gp[0])
        return tuple(out)

    def flux_and_derivatives_reduced(self, p: np.ndarray, h: np.ndarray, gp: Grad,
                                     gh: Grad, dx: np.ndarray, gq: Grad) -> tuple:
        """Flux with the reduced-pressure Poiseuille term and its derivatives: as
        :meth:`flux_and_derivatives`, plus dF/d(grad q) (list over gradient components
        of tuples over flux components) as a sixth item."""
        rho, eps, drho, c, pe = self._coefficients(p, h, dx)
        base = self._assemble_flux(rho, eps, drho, c, h, gp, gh, gq)
        d_p = self._flux_dp_reduced(p, h, gp, gh, dx, gq, rho, drho, c, pe)
        d_h = self._flux_dh(rho, eps, drho, c, pe, h, gp, gh, gq, dx)
        k = rho * (h * h * h) / (12.0 * self.viscosity0)
        dim = len(gp)
        zero = np.zeros_like(np.real(base[0]))
        return (base, d_p, d_h, _diagonal(dim, c * h * drho + zero, zero),
                _diagonal(dim, c * rho + zero, zero), _diagonal(dim, k + zero, k + zero))

    def _flux_dp_reduced(self, p, h, gp, gh, dx, gq, rho, drho, c, pe):
        """dF/dp at fixed h and gradients [m^2/(s Pa)] of the reduced-pressure flux
        F_x = k dq/dx - u_m rho h + c (rho dh/dx + h drho/dp dp/dx), F_y = k dq/dy,
        k = rho h^3/(12 eta0), c = (dx/2) u_m xi(Pe), Pe = u_m rho C dx/(2 eps) =
        6 u_m C dx eta/h^3 (rho cancels), by the chain rule: only the density, its
        slope and the viscosity are differentiated (complex steps of those scalar laws,
        exact to rounding), not the whole flux (the same result, ~3x cheaper)."""
        vmax = float(np.max(np.abs(p))) if np.size(p) else 0.0
        step = _STEP * (vmax if vmax > 0.0 else 1.0)
        pc = p + 1j * step
        rho_p = np.imag(self.density(pc)) / step
        dp = 1e3  # Pa; as in _coefficients
        drho_p = np.imag(self.density(pc + dp) - self.density(pc - dp)) / (2 * dp * step)
        k_p = rho_p * (h * h * h) / (12.0 * self.viscosity0)
        out = [k_p * g for g in gq]
        dx_term = rho_p * gh[0] + h * drho_p * gp[0]
        fx = out[0] - self.mean_speed * rho_p * h + c * dx_term
        if pe is not None:
            eta = self.viscosity(pc)
            # Pe ~ eta: dPe/dp = Pe eta'/eta
            with np.errstate(over="ignore", invalid="ignore"):
                log_slope = (np.imag(eta) / step) / np.real(eta)
            c_p = 0.5 * self.upwind * dx * self.mean_speed * _xi_chain(pe, log_slope)
            fx = fx + c_p * (rho * gh[0] + h * drho * gp[0])
        out[0] = fx
        return tuple(out)

    def flux_and_derivatives(self, p: np.ndarray, h: np.ndarray, gp: Grad, gh: Grad,
                             dx: np.ndarray) -> tuple:
        """As :meth:`FluxModel.flux_and_derivatives`; the flux is affine in grad p and
        grad h at fixed (p, h), so those derivatives are the coefficients themselves
        (dF_x/dp_x = eps + c h drho/dp, dF_x/dh_x = c rho, dF_y/dp_y = eps, others 0);
        d/dh is analytic (:meth:`_flux_dh`); only d/dp takes a complex step."""
        rho, eps, drho, c, pe = self._coefficients(p, h, dx)
        base = self._assemble_flux(rho, eps, drho, c, h, gp, gh, None)
        d_p = self._complex_step(p, h, gp, gh, dx, "p")
        d_h = self._flux_dh(rho, eps, drho, c, pe, h, gp, gh, None, dx)
        zero = np.zeros_like(np.real(base[0]))
        return (base, d_p, d_h, _diagonal(len(gp), eps + c * h * drho, eps + zero),
                _diagonal(len(gp), c * rho + zero, zero))


def _diagonal(dim: int, first: np.ndarray, others: np.ndarray) -> list[tuple]:
    """Derivatives of the flux with respect to a gradient that enters each flux component
    only through its own direction: entry [k][k] is ``first`` for k = 0 (x, which carries
    the wedge and upwind terms) and ``others`` for k > 0; off-diagonal entries are zero.
    Layout of ``flux_and_derivatives``: a list over gradient components k of tuples over
    flux components."""
    zero = np.zeros_like(first)
    return [tuple((first if k == 0 else others) if i == k else zero for i in range(dim))
            for k in range(dim)]


def upwind_factor(pe: np.ndarray) -> np.ndarray:
    """xi(Pe) = coth(Pe) - 1/Pe, stable for small and huge Pe (real or complex-step input).

    Complex input is a complex step Pe = x + i s (s tiny): the result is
    xi(x) + i s xi'(x) with xi'(x) = 1/x^2 - 1/sinh^2(x), which is what evaluating xi in
    complex arithmetic gives, at the cost of two real evaluations (complex tanh is slow).
    """
    if np.iscomplexobj(pe):
        x = np.real(pe)
        return _xi_real(x) + 1j * np.imag(pe) * _xi_derivative(x)
    return _xi_real(np.asarray(pe, dtype=float))


def _regimes(x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    ax = np.abs(x)
    small = ax < 1e-2  # series
    big = ax > 40.0    # coth = +-1 to double precision
    return small, big, ~(small | big)


def _xi_real(x: np.ndarray) -> np.ndarray:
    small, big, mid = _regimes(x)
    out = np.empty_like(x)
    xs, xb, xm = x[small], x[big], x[mid]
    out[small] = xs / 3.0 - xs**3 / 45.0
    out[big] = np.sign(xb) - 1.0 / xb
    out[mid] = 1.0 / np.tanh(xm) - 1.0 / xm
    return out


def _xi_chain(pe: np.ndarray, log_slope) -> np.ndarray:
    """xi'(Pe) dPe/ds for dPe/ds = Pe * ``log_slope`` (the chain rule of the upwind factor
    in a variable s). Where Pe is infinite (eps underflowed, or the viscosity overflowed:
    Barus at alpha p > ~710) xi saturates at 1 and xi'(Pe) Pe ~ 1/Pe, so the product
    takes its limit 0 there, not the NaN of 0 * inf or inf/inf."""
    with np.errstate(over="ignore", invalid="ignore"):
        out = _xi_derivative(pe) * (pe * log_slope)
    return np.where(np.isfinite(out), out, 0.0)


def _xi_derivative(x: np.ndarray) -> np.ndarray:
    small, big, mid = _regimes(x)
    out = np.empty_like(x)
    xs, xb, xm = x[small], x[big], x[mid]
    out[small] = 1.0 / 3.0 - xs**2 / 15.0
    with np.errstate(over="ignore"):  # |x| > 1e154: xi' = 0
        out[big] = 1.0 / xb**2
    out[mid] = 1.0 / xm**2 - 1.0 / np.sinh(xm) ** 2
    return out

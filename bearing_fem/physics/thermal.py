"""Thermal finite-element patch: Korovchinsky strip source and moving band sources.

Pure conduction / convection-diffusion, solved with scikit-fem; the coupling to the EHL
solver is separate. No I/O and no plotting here (``to_meshio`` only builds an object).

Symbols and units
-----------------
a        strip half-width across the track [m] (``half_width``)
b        band half-length along the rolling direction [m] (``half_length``)
q        heat flux entering the body [W/m^2]; q_max its peak value
lambda   thermal conductivity [W/(m K)] (``conductivity``; K in the moving-source text)
rho, c   density [kg/m^3], specific heat capacity [J/(kg K)]
kappa    thermal diffusivity lambda/(rho c) [m^2/s]
V        speed of the body under the fixed source [m/s]
Pe       Peclet number V b/(2 kappa) [-] (docs/theory.md section 14.4)
theta    total power of the strip per unit track length [W/m] (``total_heat``)
T_n      Korovchinsky characteristic temperature a q_max/lambda [K]
T        temperature rise [K] above the datum documented on each function

Problems
--------
1. :func:`strip_source` -- steady conduction ``div(lambda grad T) = 0`` in the half-plane
   y >= 0 (x across the track, y into the body), ``-lambda dT/dy = q(x)`` on the strip
   |x| <= a, adiabatic elsewhere on y = 0, truncated at r = R with a far-field
   condition (docs/theory.md section 14.4; oracle: :mod:`bearing_fem.analytic` Section B).
2. :func:`moving_source` -- steady convection-diffusion ``rho c V dT/dx = lambda Lap T``
   in the rolling plane (x along the motion of the body, y into it), flux q on the band
   |x| <= b of the surface, Galerkin + SUPG on bilinear quadrilaterals.
3. :func:`reconstruct_two_point` -- Sanko's two-point reconstruction with the
   corrected Korovchinsky field.
4. :func:`heat_partition` -- Blok's equal-flash-temperature split between two bodies.
"""
from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field as dc_field
from typing import Any, Callable, Literal, Sequence

import numpy as np

from .. import analytic
from ..validation import require_int, require_positive

logger = logging.getLogger(__name__)

FluxSpec = str | Callable[[np.ndarray], np.ndarray] | np.ndarray | Sequence[Sequence[float]]

__all__ = [
    "StripSourceResult", "strip_source", "strip_mesh",
    "TwoPointReconstruction", "reconstruct_two_point",
    "MovingSourceResult", "moving_source",
    "HeatPartition", "heat_partition",
]


# ----------------------------------------------------------------------------------------
# validation helpers
# ----------------------------------------------------------------------------------------

def _flux_function(flux: FluxSpec, half_width: float, q_max: float | None,
                   arg: str = "flux") -> tuple[Callable[[np.ndarray], np.ndarray], str, float]:
    """Return (q(x) [W/m^2] vectorised, zero outside |x| <= a; kind; q_max [W/m^2])."""
    a = half_width
    if isinstance(flux, str):
        if q_max is None:
            raise ValueError(f"q_max must be given (W/m^2) for flux={flux!r}, got None")
        qm = require_positive("q_max", q_max, "W/m^2")
        if flux == "semi-elliptic":
            def q(x: np.ndarray) -> np.ndarray:
                return qm * np.sqrt(np.clip(1.0 - (np.asarray(x) / a) ** 2, 0.0, None))
        elif flux == "uniform":
            def q(x: np.ndarray) -> np.ndarray:
                x = np.asarray(x, dtype=float)
                return np.where(np.abs(x) <= a * (1 + 1e-12), qm, 0.0)
        else:
            raise ValueError(f"{arg} must be 'semi-elliptic', 'uniform', a callable q(x) "
                             f"[W/m^2] or (x [m], q [W/m^2]) samples, got {flux!r}")
        return q, flux, qm
    if callable(flux):
        fn = flux

        def q(x: np.ndarray) -> np.ndarray:
            x = np.asarray(x, dtype=float)
            return np.where(np.abs(x) <= a * (1 + 1e-12),
                            np.broadcast_to(np.asarray(fn(x), dtype=float), x.shape), 0.0)
        kind = "callable"
    else:
        arr = np.asarray(flux, dtype=float)
        if arr.ndim != 2 or 2 not in arr.shape or arr.size < 4:
            raise ValueError(f"{arg} samples must be an (n, 2) array of (x [m], q [W/m^2]) "
                             f"with n >= 2, got shape {arr.shape}")
        if arr.shape[1] != 2:
            arr = arr.T
        order = np.argsort(arr[:, 0])
        xs, qs = arr[order, 0], arr[order, 1]
        if not np.all(np.isfinite(arr)):
            raise ValueError(f"{arg} samples must be finite (x in m, q in W/m^2)")

        def q(x: np.ndarray) -> np.ndarray:
            x = np.asarray(x, dtype=float)
            return np.where(np.abs(x) <= a * (1 + 1e-12), np.interp(x, xs, qs), 0.0)
        kind = "samples"
    if q_max is None:
        probe = np.linspace(-a, a, 2001)
        qm = float(np.max(np.abs(q(probe))))
        if qm <= 0.0:
            raise ValueError(f"{arg} is zero everywhere on |x| <= a = {a} m: nothing to solve")
    else:
        qm = require_positive("q_max", q_max, "W/m^2")
    return q, kind, qm


# ----------------------------------------------------------------------------------------
# Korovchinsky strip source (half-plane patch)
# ----------------------------------------------------------------------------------------

def strip_mesh(half_width: float, radius: float, n_across: int = 48):
    """Graded half-disc mesh from elliptic coordinates, returned with boundary facet sets.

    The structured (mu, nu) grid, 0 <= mu <= acosh(R/a), 0 <= nu <= pi, with square cells
    of side pi/n_across, is mapped by the conformal map z = a cosh(mu + i nu). The strip
    |x| <= a is mu = 0 (nodes at x = a cos nu: Chebyshev-clustered at the strip edges,
    where the semi-elliptic flux has its square-root behaviour); cells grow geometrically
    with r (uniform in mu ~ ln(2r/a)), so R = 100 a costs only ~50 % more than R = 10 a.
    Conformality keeps the cells near-square; at the two strip edges the map doubles
    angles, so the diagonal of each corner cell is chosen through the edge node (no
    degenerate triangle). The outer ellipse mu = M (semi-axes a cosh M = R, a sinh M) is
    blended radially onto the circle r = R (shift ~ (a/R)^2/2 relative, 2 % at R = 5a,
    applied smoothly with weight (mu/M)^4).

    Parameters
    ----------
    half_width : float
        a [m].
    radius : float
        Patch radius R [m], R > a.
    n_across : int
        Number of cells along the strip (nu direction), >= 4, even.

    Returns
    -------
    mesh : skfem.MeshTri
    strip_facets, outer_facets : ndarray of int
        Facet indices of the heated strip and of the far-field arc.
    """
    from skfem import MeshTri

    a = require_positive("half_width", half_width, "m")
    R = require_positive("radius", radius, "m")
    if R <= 1.5 * a:
        raise ValueError(f"radius must be > 1.5 * half_width = {1.5 * a:.6g} m, got {radius!r}")
    n_nu = require_int("n_across", n_across, 4)
    n_nu += n_nu % 2
    M = float(np.arccosh(R / a))
    d = np.pi / n_nu
    n_mu = max(2, int(np.ceil(M / d)))
    mu = np.linspace(0.0, M, n_mu + 1)
    nu = np.linspace(0.0, np.pi, n_nu + 1)
    MU, NU = np.meshgrid(mu, nu, indexing="ij")          # node (i, j) -> i*(n_nu+1) + j
    X = a * np.cosh(MU) * np.cos(NU)
    Y = a * np.sinh(MU) * np.sin(NU)
    r_outer = a * np.hypot(np.cosh(M) * np.cos(NU), np.sinh(M) * np.sin(NU))
    blend = 1.0 + (MU / M) ** 4 * (R / r_outer - 1.0)
    X, Y = X * blend, Y * blend
    Y[:, 0] = 0.0
    Y[:, -1] = 0.0
    p = np.vstack([X.ravel(), Y.ravel()])

    ii, jj = np.meshgrid(np.arange(n_mu), np.arange(n_nu), indexing="ij")
    ii, jj = ii.ravel(), jj.ravel()
    w = n_nu + 1
    n00, n10, n01, n11 = ii * w + jj, (ii + 1) * w + jj, ii * w + jj + 1, (ii + 1) * w + jj + 1
    left = jj < n_nu // 2        # diagonal through (0, 0) corner; anti-diagonal near nu = pi
    t1 = np.where(left, np.vstack([n00, n10, n11]), np.vstack([n00, n10, n01]))
    t2 = np.where(left, np.vstack([n00, n11, n01]), np.vstack([n10, n11, n01]))
    t = np.hstack([t1, t2])
    # counter-clockwise orientation
    xy = p[:, t]
    area2 = ((xy[0, 1] - xy[0, 0]) * (xy[1, 2] - xy[1, 0])
             - (xy[0, 2] - xy[0, 0]) * (xy[1, 1] - xy[1, 0]))
    t[[1, 2]] = np.where(area2 < 0, t[[2, 1]], t[[1, 2]])
    mesh = MeshTri(p, t)

    ring = np.arange(p.shape[1]) // w                     # mu index of every node
    f = mesh.facets
    bf = mesh.boundary_facets()
    strip = bf[(ring[f[0, bf]] == 0) & (ring[f[1, bf]] == 0)]
    outer = bf[(ring[f[0, bf]] == n_mu) & (ring[f[1, bf]] == n_mu)]
    return mesh, strip, outer


def patch_from_mesh(mesh, half_width: float):
    """A dimensionless patch mesh scaled to metres, with its strip and far-field facets.

    Parameters
    ----------
    mesh : skfem.MeshTri
        Triangles of the half-disc y >= 0 in units of the strip half-width: the heated
        strip is the boundary on y = 0 with |x| <= 1, the far field the boundary at the
        largest radius.
    half_width : float
        a [m].

    Returns
    -------
    mesh : skfem.MeshTri (in m); strip_facets, outer_facets : ndarray of int
    """
    from skfem import MeshTri

    a = require_positive("half_width", half_width, "m")
    if not isinstance(mesh, MeshTri):  # skfem's MeshTri (MeshTri1)
        raise ValueError(f"a thermal patch mesh must be triangles (skfem MeshTri), got "
                         f"{type(mesh).__name__}")
    pts = np.asarray(mesh.p, dtype=float)
    if np.min(pts[1]) < -1e-9 or np.min(np.abs(pts[0])) > 1.0:
        raise ValueError("a thermal patch mesh lies in y >= 0 around the strip |x| <= 1 "
                         "(units of the half-width)")
    scaled = MeshTri(pts * a, mesh.t)
    f = scaled.facets
    bf = scaled.boundary_facets()
    xm = 0.5 * (pts[0, f[0, bf]] + pts[0, f[1, bf]])
    on_axis = (np.abs(pts[1, f[0, bf]]) < 1e-12) & (np.abs(pts[1, f[1, bf]]) < 1e-12)
    strip = bf[on_axis & (np.abs(xm) <= 1.0 + 1e-12)]
    r = np.hypot(pts[0], pts[1])
    r_max = float(np.max(r))
    outer = bf[(r[f[0, bf]] > 0.999 * r_max) & (r[f[1, bf]] > 0.999 * r_max)]
    if strip.size == 0 or outer.size == 0:
        raise ValueError("the thermal patch mesh has no strip facets (y = 0, |x| <= 1) or "
                         "no far-field arc")
    return scaled, strip, outer


@dataclass(frozen=True)
class StripSourceResult:
    """FE solution of the Korovchinsky half-plane problem (see :func:`strip_source`).

    Attributes
    ----------
    half_width : float
        a [m].
    q_max : float
        Peak (or reference) flux [W/m^2]; T_n = a q_max / lambda.
    conductivity : float
        lambda [W/(m K)].
    radius : float
        Patch radius R [m].
    far_field : str
        "robin" or "dirichlet".
    flux_kind : str
        "semi-elliptic", "uniform", "callable" or "samples".
    T_n : float
        a q_max / lambda [K].
    total_heat : float
        theta = integral of the imposed flux over the strip [W/m] (same quadrature as
        the FE load vector).
    heat_out : float
        Heat leaving through the far-field arc [W/m] (equals total_heat at steady state).
    C_equivalent : float or None
        Korovchinsky's C that the datum corresponds to (1/4 for the semi-elliptic flux).
    mesh, basis, field
        skfem mesh, basis and the nodal temperature vector [K].
    wall_time_s : float
        Assembly + solve time [s].
    probe_radius : float
        Largest r [m] accepted by :meth:`temperature` (the arc is meshed by chords).
    """

    half_width: float
    q_max: float
    conductivity: float
    radius: float
    far_field: str
    flux_kind: str
    T_n: float
    total_heat: float
    heat_out: float
    C_equivalent: float | None
    mesh: Any = dc_field(repr=False)
    basis: Any = dc_field(repr=False)
    field: np.ndarray = dc_field(repr=False)
    wall_time_s: float = 0.0
    probe_radius: float = 0.0

    @property
    def dofs(self) -> int:
        """Number of unknowns."""
        return int(self.basis.N)

    def temperature(self, x: np.ndarray | float, y: np.ndarray | float) -> np.ndarray:
        """FE temperature [K] above the far-field datum at points (x, y) [m], vectorised.

        The datum: T + (theta/(pi lambda)) ln(r/a) -> 0 as r -> infinity, i.e. the FE
        field approximates the logarithmic potential
        ``-(1/(pi lambda)) int q(s) ln(|(x, y) - (s, 0)|/a) ds``. Points must satisfy
        y >= 0 and r < R.
        """
        xs, ys = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        if np.any(ys < -1e-12 * self.half_width):
            raise ValueError(f"y must be >= 0 m (into the body), got min {float(ys.min())!r}")
        r = np.hypot(xs, ys)
        rmax = self.probe_radius
        if np.any(r > rmax):
            raise ValueError(f"points must lie inside the patch r < {rmax:.6g} m, "
                             f"got r = {float(r.max())!r} m")
        pts = np.vstack([xs.ravel(), np.maximum(ys.ravel(), 0.0)])
        return (self.basis.probes(pts) @ self.field).reshape(xs.shape)

    def to_meshio(self):
        """meshio.Mesh of the vertices with point data ``temperature_K``."""
        import meshio

        vals = self.field[self.basis.nodal_dofs[0]]
        return meshio.Mesh(self.mesh.p.T, [("triangle", self.mesh.t.T)],
                           point_data={"temperature_K": vals})


def _far_field_datum(xb: np.ndarray, yb: np.ndarray, a: float, lam: float,
                     moments: Sequence[float]) -> np.ndarray:
    """Multipole expansion of the log potential (datum of :meth:`temperature`) [K].

    ``T = -(1/(pi lambda)) [M0 ln(r/a) - M1 cos(phi)/r - M2 cos(2 phi)/(2 r^2)]`` with
    ``M_k = int q(s) s^k ds`` (from ln|z - s| = ln z - sum (s/z)^k / k; the image source
    of the adiabatic surface doubles the free-space 1/(2 pi lambda)).
    """
    r = np.hypot(xb, yb)
    phi = np.arctan2(yb, xb)
    M0, M1, M2 = moments
    return -(M0 * np.log(r / a) - M1 * np.cos(phi) / r
             - M2 * np.cos(2.0 * phi) / (2.0 * r * r)) / (np.pi * lam)


def strip_source(half_width: float, q_max: float | None, conductivity: float, *,
                 radius: float | None = None,
                 flux: FluxSpec = "semi-elliptic",
                 far_field: Literal["robin", "dirichlet"] = "dirichlet",
                 n_across: int = 48, order: int = 2,
                 multipole_order: int = 2, mesh=None) -> StripSourceResult:
    """Solve steady conduction in the half-plane patch under a strip heat source.

    Body y >= 0 (x across the track, y into the body, metres), ``-lambda dT/dy = q(x)``
    on |x| <= a, adiabatic free surface elsewhere, truncated at r = R. The far-field
    condition imposes the exact large-r behaviour of the logarithmic potential:

    - ``"dirichlet"`` (default): T = its multipole expansion up to the quadrupole
      (:func:`_far_field_datum`); the first neglected term is O((a/R)^3) (odd flux) or
      O((a/R)^4) (even flux) on the arc; ``multipole_order=0`` keeps the monopole only
      (error O((a/R)^2) on the arc, kept to measure what the quadrupole buys);
    - ``"robin"``: ``dT/dn = (n . e_r) T/(r ln(r/a))``, exact for the monopole
      ``T = -(theta/(pi lambda)) ln(r/a)``; needs no moments, but the quadrupole is
      mis-represented, so the error is O((a/R)^2) at the arc.

    Both fix the same datum: T + (theta/(pi lambda)) ln(r/a) -> 0 as r -> infinity. In
    2D only differences are physical; for the semi-elliptic flux this datum is
    Korovchinsky's C = 1/4 (``C_equivalent``). The truncation error is measured in
    ``studies/korovchinsky_patch.py`` and ``docs/thermal.md``.

    Parameters
    ----------
    half_width : float
        Strip half-width a [m].
    q_max : float or None
        Peak flux [W/m^2] for the named shapes; for a callable or samples it only sets
        T_n (None: the sampled maximum of |q|).
    conductivity : float
        lambda [W/(m K)].
    radius : float, optional
        Patch radius R [m]; default 50 a.
    flux : {"semi-elliptic", "uniform"} or callable or (n, 2) array
        Shape: q_max sqrt(1 - x^2/a^2), q_max, a callable q(x) [W/m^2] of x [m]
        (vectorised), or samples (x [m], q [W/m^2]) interpolated linearly; zero outside
        |x| <= a.
    far_field : {"dirichlet", "robin"}
        Far-field condition, see above.
    n_across : int
        Cells along the strip (mesh density; the mesh is graded, see :func:`strip_mesh`).
    order : {1, 2}
        Lagrange element order.
    multipole_order : {0, 1, 2}
        Terms of the Dirichlet far-field datum beyond ln r (ignored for "robin").
    mesh : skfem.MeshTri, optional
        A patch mesh in units of a (the half-disc r <= R/a of y >= 0, the strip
        |x| <= 1 on y = 0), e.g. ``meshes/korovchinsky_patch.vtu`` read by
        :func:`bearing_fem.mesh.read_mesh`; it replaces :func:`strip_mesh` (``radius``
        and ``n_across`` are then taken from it).

    Returns
    -------
    StripSourceResult
    """
    from skfem import (Basis, BilinearForm, ElementTriP1, ElementTriP2, FacetBasis,
                       LinearForm, asm, condense, solve)
    from skfem.helpers import dot, grad

    a = require_positive("half_width", half_width, "m")
    lam = require_positive("conductivity", conductivity, "W/(m K)")
    R = 50.0 * a if radius is None else require_positive("radius", radius, "m")
    if far_field not in ("robin", "dirichlet"):
        raise ValueError(f"far_field must be 'robin' or 'dirichlet' (boundary condition at "
                         f"r = R m), got {far_field!r}")
    if order not in (1, 2):
        raise ValueError(f"order must be 1 or 2 (element degree, dimensionless), "
                         f"got {order!r}")
    if multipole_order not in (0, 1, 2):
        raise ValueError(f"multipole_order must be 0, 1 or 2 (dimensionless), "
                         f"got {multipole_order!r}")
    q, kind, qm = _flux_function(flux, a, q_max)
    t0 = time.perf_counter()
    if mesh is None:
        mesh, strip, outer = strip_mesh(a, R, n_across)
    else:
        mesh, strip, outer = patch_from_mesh(mesh, a)
        R = float(np.max(np.hypot(*mesh.p)))
    elem = ElementTriP2() if order == 2 else ElementTriP1()
    basis = Basis(mesh, elem, intorder=2 * order)
    sb = FacetBasis(mesh, elem, facets=strip, intorder=10)

    @BilinearForm
    def laplace(u, v, w):
        return lam * dot(grad(u), grad(v))

    @LinearForm
    def heat_in(v, w):
        return q(w.x[0]) * v

    @LinearForm
    def moment(v, w):
        return q(w.x[0]) * w.x[0] ** w.k * v

    A = asm(laplace, basis)
    f = asm(heat_in, sb)
    total_heat = float(f.sum())                   # sum of test functions = 1
    moments = [total_heat] + [float(asm(moment, sb, k=float(k)).sum()) if k <= multipole_order
                              else 0.0 for k in (1, 2)]

    if far_field == "robin":
        ob = FacetBasis(mesh, elem, facets=outer, intorder=2 * order + 2)

        @BilinearForm
        def robin(u, v, w):
            r = np.sqrt(w.x[0] ** 2 + w.x[1] ** 2)
            ndr = (w.n[0] * w.x[0] + w.n[1] * w.x[1]) / r
            # lambda dT/dn = lambda (n.e_r) T/(r ln(r/a)); moved to the left-hand side
            return -lam * ndr / (r * np.log(r / a)) * u * v

        B = asm(robin, ob)
        T = solve(A + B, f)                     # indefinite (one negative mode), non-singular
        heat_out = float((B @ T).sum())        # = -int lambda dT/dn ds over the arc
    else:
        D = basis.get_dofs(facets=outer).all()
        xd = basis.doflocs[:, D]
        T = np.zeros(basis.N)
        T[D] = _far_field_datum(xd[0], xd[1], a, lam, moments)
        T = solve(*condense(A, f, x=T, D=D))
        heat_out = float(-(A @ T - f)[D].sum())   # reaction = flux through the arc
    wall = time.perf_counter() - t0
    logger.debug("strip_source: %d dofs, %.3f s", basis.N, wall)
    return StripSourceResult(
        half_width=a, q_max=qm, conductivity=lam, radius=R, far_field=far_field,
        flux_kind=kind, T_n=a * qm / lam, total_heat=total_heat, heat_out=heat_out,
        C_equivalent=analytic.korovchinsky_log_potential_constant()
        if kind == "semi-elliptic" else None,
        mesh=mesh, basis=basis, field=T, wall_time_s=wall,
        probe_radius=float(R * np.cos(np.pi / (2 * len(outer)))))


# ----------------------------------------------------------------------------------------
# two-point reconstruction (Sanko, with the corrected field)
# ----------------------------------------------------------------------------------------

@dataclass(frozen=True)
class TwoPointReconstruction:
    """Korovchinsky field fitted through two measured temperatures.

    Attributes
    ----------
    half_width : float
        a [m].
    conductivity : float
        lambda [W/(m K)].
    C : float
        Korovchinsky constant (dimensionless) in the datum of the measurements.
    T_n : float
        a q_max/lambda [K].
    source_power : float
        theta = pi lambda T_n / 2 [W/m].
    q_max : float
        lambda T_n / a [W/m^2].
    T_max : float
        T_n (C + ln sqrt 2) [K], centre of the strip.
    form : str
        "corrected" (default) or "printed": which field was fitted (see
        :func:`reconstruct_two_point`).
    """

    half_width: float
    conductivity: float
    C: float
    T_n: float
    source_power: float
    q_max: float
    T_max: float
    form: str = "corrected"

    def temperature(self, x: np.ndarray | float, y: np.ndarray | float) -> np.ndarray:
        """Reconstructed temperature [K] at (x, y) [m], same datum as the input points."""
        a = self.half_width
        return self.T_n * (self.C + _SHAPES[self.form](np.asarray(x, float) / a,
                                                       np.asarray(y, float) / a))


#: The C-free field shapes a two-point reconstruction can fit.
_SHAPES = {"corrected": analytic.korovchinsky_shape,
           "printed": analytic.korovchinsky_shape_printed}


def reconstruct_two_point(half_width: float, p1: Sequence[float], p2: Sequence[float],
                          conductivity: float,
                          form: Literal["corrected", "printed"] = "corrected"
                          ) -> TwoPointReconstruction:
    """Find C and T_n of the corrected Korovchinsky field from T at two points.

    T_i = T_n C + T_n f(x_i/a, y_i/a) is linear in (T_n C, T_n), so
    ``T_n = (T_1 - T_2)/(f_1 - f_2)`` and ``C = T_1/T_n - f_1``; then
    theta = pi lambda T_n / 2 (Sanko, eqs. 8-11, with the corrected field; docs/theory.md
    section 14.4).

    Parameters
    ----------
    half_width : float
        a [m].
    p1, p2 : (x [m], y [m], T [K])
        Two points with temperatures in one common datum (y >= 0).
    conductivity : float
        lambda [W/(m K)].
    form : {"corrected", "printed"}
        The field fitted: the corrected Korovchinsky field (default), or the field as
        printed by Sanko, with quadratic coefficients 1 instead of 1/2
        (:func:`bearing_fem.analytic.korovchinsky_shape_printed`), only to reproduce
        and measure the printed method (``studies/korovchinsky_reconstruction.py``).

    Raises
    ------
    ValueError
        Bad arguments (including an unknown ``form``), two points on one isotherm of f (|f_1 - f_2| too small), or a
        non-positive T_n (the temperatures fall towards the source: not a heat source).
    """
    a = require_positive("half_width", half_width, "m")
    lam = require_positive("conductivity", conductivity, "W/(m K)")
    if form not in _SHAPES:
        raise ValueError(f"form must be 'corrected' or 'printed' (which Korovchinsky field "
                         f"to fit, dimensionless), got {form!r}")
    shape = _SHAPES[form]
    pts = []
    for name, p in (("p1", p1), ("p2", p2)):
        arr = np.asarray(p, dtype=float)
        if arr.shape != (3,) or not np.all(np.isfinite(arr)):
            raise ValueError(f"{name} must be (x [m], y [m], T [K]) finite, got {p!r}")
        if arr[1] < 0:
            raise ValueError(f"{name} y must be >= 0 m (into the body), got {float(arr[1])!r}")
        pts.append(arr)
    f1, f2 = (float(shape(p[0] / a, p[1] / a)) for p in pts)
    if abs(f1 - f2) < 1e-9:
        raise ValueError(f"p1 and p2 lie on one isotherm of the Korovchinsky field "
                         f"(f1 = {f1:.6g}, f2 = {f2:.6g}, dimensionless): T_n is undetermined")
    T1, T2 = pts[0][2], pts[1][2]
    Tn = (T1 - T2) / (f1 - f2)
    if Tn <= 0:
        raise ValueError(f"reconstructed T_n = {Tn:.6g} K <= 0: the temperatures "
                         f"T1 = {float(T1)!r} K, T2 = {float(T2)!r} K do not fit a heat source")
    C = T1 / Tn - f1
    return TwoPointReconstruction(half_width=a, conductivity=lam, C=float(C), T_n=float(Tn),
                                  source_power=float(np.pi * lam * Tn / 2.0),
                                  q_max=float(lam * Tn / a),
                                  T_max=float(Tn * (C + shape(0.0, 0.0))), form=form)


# ----------------------------------------------------------------------------------------
# moving band source in the rolling plane (convection-diffusion, SUPG)
# ----------------------------------------------------------------------------------------

@dataclass(frozen=True)
class MovingSourceResult:
    """Steady moving-source solution (see :func:`moving_source`).

    Attributes
    ----------
    half_length : float
        b [m].
    q_max : float
        Reference (peak) flux [W/m^2].
    peclet : float
        Pe = V b/(2 kappa) [-].
    x : ndarray
        Surface node positions [m] (ascending; the body moves towards +x).
    surface_temperature : ndarray
        T(x, 0) [K] above the far-upstream temperature of the body.
    T_max : float
        Maximum surface temperature [K] (parabola through the three highest nodes).
    x_max : float
        Its position [m].
    coefficient : float
        T_max sqrt(lambda rho c V)/(q_max sqrt b) [-]; Jaeger's 1.596 (uniform band) or
        Blok's semi-elliptic coefficient in the high-Pe limit.
    mesh, basis, field
        skfem objects (coordinates in units of b) and the nodal solution in units of
        ``temperature_scale``.
    temperature_scale : float
        q_max b / lambda [K] per unit of ``field``.
    """

    half_length: float
    q_max: float
    peclet: float
    x: np.ndarray = dc_field(repr=False)
    surface_temperature: np.ndarray = dc_field(repr=False)
    T_max: float = 0.0
    x_max: float = 0.0
    coefficient: float = 0.0
    mesh: Any = dc_field(repr=False, default=None)
    basis: Any = dc_field(repr=False, default=None)
    field: np.ndarray = dc_field(repr=False, default=None)
    temperature_scale: float = 1.0

    def temperature(self, x: np.ndarray | float, y: np.ndarray | float) -> np.ndarray:
        """Temperature [K] at points (x [m], y [m] >= 0) inside the computational box."""
        xs, ys = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        b = self.half_length
        pts = np.vstack([xs.ravel() / b, ys.ravel() / b])
        return (self.basis.probes(pts) @ self.field).reshape(xs.shape) * self.temperature_scale


def _graded(start: float, stop: float, h0: float, ratio: float) -> np.ndarray:
    """Nodes from start to stop (either direction), first step h0, growing by ratio."""
    L = abs(stop - start)
    pts = [0.0]
    h = h0
    while pts[-1] + h < L:
        pts.append(pts[-1] + h)
        h *= ratio
    if L - pts[-1] < 0.5 * h and len(pts) > 1:
        pts[-1] = L
    else:
        pts.append(L)
    return start + np.sign(stop - start) * np.asarray(pts)


def moving_source(half_length: float, q_max: float, conductivity: float, density: float,
                  heat_capacity: float, speed: float, *,
                  flux: FluxSpec = "uniform", n_source: int = 160,
                  upstream: float | None = None, downstream: float | None = None,
                  depth: float | None = None, supg: bool = True) -> MovingSourceResult:
    """Steady surface heating of a body moving at speed V under a fixed band source.

    Rolling plane, x along the motion of the body (material enters at x -> -infinity),
    y >= 0 into the body: ``rho c V dT/dx = lambda Lap T`` with ``-lambda dT/dy = q(x)``
    on |x| <= b, adiabatic elsewhere on the surface, T = 0 on the inflow and bottom
    boundaries, natural (zero diffusive flux) outflow. Solved in x/b, y/b and
    T lambda/(q_max b), where the equation reads ``2 Pe dT/dX = Lap T``.

    Discretisation: bilinear quadrilaterals on a tensor mesh, uniform over the band
    (``n_source`` cells), geometrically graded upstream, downstream and in depth (first
    layer 0.03 b/sqrt(max(Pe, 1)), resolving the thermal layer ~ b/sqrt(Pe));
    streamline-upwind Petrov-Galerkin with the optimal 1D parameter
    tau = h/(2|beta|) (coth Pe_h - 1/Pe_h), Pe_h = |beta| h/2 (the diffusion term of
    the residual vanishes for Q1 on rectangles). Box defaults (units of b):
    upstream 1 + max(2, 12/(2 Pe)), downstream 1 + max(3, 12/(2 Pe)),
    depth max(1.5, 4/Pe + 4 sqrt(downstream/(2 Pe))).

    Parameters
    ----------
    half_length : float
        b [m].
    q_max : float
        Peak flux [W/m^2] (uniform: the flux itself).
    conductivity, density, heat_capacity, speed : float
        lambda [W/(m K)], rho [kg/m^3], c [J/(kg K)], V [m/s].
    flux : {"uniform", "semi-elliptic"} or callable or samples
        As in :func:`strip_source`, with a = b.
    n_source : int
        Cells across the band.
    upstream, downstream, depth : float, optional
        Box extents in units of b (measured from the band centre / the surface).
    supg : bool
        Streamline-upwind stabilisation (switch off only to demonstrate oscillations).

    Returns
    -------
    MovingSourceResult
    """
    from skfem import (Basis, BilinearForm, ElementQuad1, FacetBasis, LinearForm, MeshQuad,
                       asm, condense, solve)
    from skfem.helpers import dot, grad

    b = require_positive("half_length", half_length, "m")
    lam = require_positive("conductivity", conductivity, "W/(m K)")
    rho = require_positive("density", density, "kg/m^3")
    c = require_positive("heat_capacity", heat_capacity, "J/(kg K)")
    V = require_positive("speed", speed, "m/s")
    n_src = require_int("n_source", n_source, 4)
    q, kind, qm = _flux_function(flux, b, q_max)
    Pe = V * b * rho * c / (2.0 * lam)
    Lu = 1.0 + max(2.0, 12.0 / (2 * Pe)) if upstream is None else \
        require_positive("upstream", upstream, "(units of b)")
    Ld = 1.0 + max(3.0, 12.0 / (2 * Pe)) if downstream is None else \
        require_positive("downstream", downstream, "(units of b)")
    Dp = max(1.5, 4.0 / Pe + 4.0 * np.sqrt(Ld / (2 * Pe))) if depth is None else \
        require_positive("depth", depth, "(units of b)")
    if Lu <= 1.0 or Ld <= 1.0:
        raise ValueError(f"upstream and downstream must exceed 1 (units of b), "
                         f"got {Lu!r}, {Ld!r}")

    hx = 2.0 / n_src
    xs = np.concatenate([_graded(-1.0, -Lu, hx, 1.12)[::-1][:-1],
                         np.linspace(-1.0, 1.0, n_src + 1),
                         _graded(1.0, Ld, hx, 1.08)[1:]])
    ys = _graded(0.0, Dp, 0.03 / np.sqrt(max(Pe, 1.0)), 1.08)
    mesh = MeshQuad.init_tensor(xs, ys)
    e = ElementQuad1()
    basis = Basis(mesh, e, intorder=3)
    beta = 2.0 * Pe
    # element length along the flow (x) for each element
    px = mesh.p[0, mesh.t]
    hel = px.max(axis=0) - px.min(axis=0)
    peh = beta * hel / 2.0
    tau_el = np.where(peh > 1e-8, hel / (2 * beta) * (1.0 / np.tanh(np.maximum(peh, 1e-8))
                                                      - 1.0 / np.maximum(peh, 1e-8)), 0.0)
    tau = np.repeat(tau_el[:, None], basis.X.shape[1], axis=1) if supg else \
        np.zeros((mesh.t.shape[1], basis.X.shape[1]))

    @BilinearForm
    def adv_diff(u, v, w):
        return (dot(grad(u), grad(v)) + beta * grad(u)[0] * v
                + w.tau * beta * grad(u)[0] * beta * grad(v)[0])

    top = mesh.facets_satisfying(lambda x: x[1] < 1e-12, boundaries_only=True)
    fb = FacetBasis(mesh, e, facets=top, intorder=10)

    @LinearForm
    def heat_in(v, w):
        return q(w.x[0] * b) / qm * v

    A = asm(adv_diff, basis, tau=tau)
    f = asm(heat_in, fb)
    D = basis.get_dofs(lambda x: (np.abs(x[0] + Lu) < 1e-12) | (np.abs(x[1] - Dp) < 1e-12)).all()
    th = solve(*condense(A, f, D=D))

    scale = qm * b / lam                              # K per unit of the dimensionless field
    surf = np.flatnonzero(np.abs(mesh.p[1]) < 1e-12)
    surf = surf[np.argsort(mesh.p[0, surf])]
    Xs, Ts = mesh.p[0, surf], th[surf]
    k = int(np.argmax(Ts))
    k = min(max(k, 1), len(Ts) - 2)
    # parabola through the three highest nodes (non-uniform spacing allowed)
    cpoly = np.polyfit(Xs[k - 1:k + 2] - Xs[k], Ts[k - 1:k + 2], 2)
    if cpoly[0] < 0:
        xv = -cpoly[1] / (2 * cpoly[0])
        xv = float(np.clip(xv, Xs[k - 1] - Xs[k], Xs[k + 1] - Xs[k]))
        tmax = float(np.polyval(cpoly, xv))
        xm = Xs[k] + xv
    else:
        tmax, xm = float(Ts[k]), float(Xs[k])
    tmax = max(tmax, float(Ts.max()))
    coeff = tmax * np.sqrt(2.0 * Pe)                  # = T_max sqrt(lam rho c V)/(q sqrt b)
    return MovingSourceResult(half_length=b, q_max=qm, peclet=float(Pe), x=Xs * b,
                              surface_temperature=Ts * scale, T_max=tmax * scale,
                              x_max=float(xm * b), coefficient=float(coeff), mesh=mesh,
                              basis=basis, field=th, temperature_scale=scale)


# ----------------------------------------------------------------------------------------
# heat partition between the two bodies
# ----------------------------------------------------------------------------------------

@dataclass(frozen=True)
class HeatPartition:
    """Fractions of the contact heat entering body 1 and body 2 (sum 1), and the rule."""

    fraction_1: float
    fraction_2: float
    rule: str

    def __iter__(self):
        return iter((self.fraction_1, self.fraction_2))


def heat_partition(conductivity: Sequence[float], density: Sequence[float] | None = None,
                   heat_capacity: Sequence[float] | None = None,
                   speed: Sequence[float] | None = None, *,
                   rule: Literal["blok", "conduction"] = "blok") -> HeatPartition:
    """Split the contact heat between the two bodies.

    ``"blok"`` (default; Blok 1937 equal-flash-temperature postulate for two fast
    moving surfaces, Pe_i >~ 5): each body sees the same flux shape, its flash
    temperature is c q_i sqrt(b)/e_i with the speed-weighted effusivity
    e_i = sqrt(lambda_i rho_i c_i V_i) (docs/theory.md section 14.4, high-Pe formula), so equal
    temperatures give ``fraction_i = e_i/(e_1 + e_2)``. ``"conduction"``: both bodies
    (nearly) at rest, the same 2D conduction field shape in each: equal temperature
    differences give ``fraction_i = lambda_i/(lambda_1 + lambda_2)``.

    Parameters
    ----------
    conductivity : (lambda_1, lambda_2)
        [W/(m K)].
    density, heat_capacity, speed : (., .), required for "blok"
        [kg/m^3], [J/(kg K)], [m/s] (speeds relative to the contact; magnitudes).

    Returns
    -------
    HeatPartition
    """
    def pair(name: str, v: Any, unit: str, allow_zero: bool = False) -> np.ndarray:
        arr = np.asarray(v, dtype=float) if v is not None else None
        if arr is None or arr.shape != (2,) or not np.all(np.isfinite(arr)):
            raise ValueError(f"{name} must be a pair of finite numbers in {unit}, got {v!r}")
        if np.any(arr < 0) or (not allow_zero and np.any(arr == 0)):
            raise ValueError(f"{name} must be {'>= 0' if allow_zero else '> 0'} {unit}, "
                             f"got {v!r}")
        return arr

    lam = pair("conductivity", conductivity, "W/(m K)")
    if rule == "conduction":
        w = lam
    elif rule == "blok":
        rho = pair("density", density, "kg/m^3")
        cc = pair("heat_capacity", heat_capacity, "J/(kg K)")
        V = np.abs(pair("speed", speed, "m/s", allow_zero=True))
        if np.all(V == 0):
            raise ValueError(f"speed must not be zero for both bodies (m/s) with rule='blok', "
                             f"got {speed!r}; use rule='conduction'")
        w = np.sqrt(lam * rho * cc * V)
    else:
        raise ValueError(f"rule must be 'blok' or 'conduction', got {rule!r}")
    f1 = float(w[0] / w.sum())
    return HeatPartition(fraction_1=f1, fraction_2=1.0 - f1, rule=rule)

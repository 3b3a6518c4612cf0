"""Elastic compliance operators: pressure p -> elastic displacement v (docs/theory.md sections 11, 12).

The film is ``h = h0 + x^2/(2 Rx) + y^2/(2 Ry) + v``; ``v > 0`` pushes the surfaces apart.
Four operators share one interface so the Newton solver can take any of them:

==================  =======  ==========================================================
class               kind     model
==================  =======  ==========================================================
RigidCompliance     rigid    v = 0
LocalCompliance     local    v = c p, c = A'/E (Kodnir; Yachikov & Vostrikov 2015), m/Pa
HalfSpaceLine       half-    plane strain: v(x) = -(4/(pi E')) int p(s) ln|x - s| ds
                    space    (+ const, absorbed in h0); dense symmetric Toeplitz matrix
GradedHalfSpaceLine half-    the same on non-uniform (graded) nodes; dense
                    space
HalfSpacePoint      half-    Boussinesq: v = (2/(pi E')) iint p / |r - r'| dA;
                    space    applied by zero-padded FFT (DC-FFT), never dense unless asked
==================  =======  ==========================================================

Discretisation (docs/theory.md section 12): the grid is uniform and the pressure is piecewise constant
on the cell of width D (or Dx x Dy) centred at each node; the influence coefficient of
cell j on node i is the exact integral of the kernel over cell j, so ``v = C p`` with

* line:  ``C_ij = -(4/(pi E')) K(x_i - x_j)``,
  ``K(d) = (d + D/2) ln|d + D/2| - (d - D/2) ln|d - D/2| - D`` (m, with lengths in m);
* point: ``C = (2/(pi E')) K(X, Y)``, K = corner sum of
  ``G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|)`` (m).

Point-contact arrays: a pressure field is either a 2D array of shape ``(ny, nx)``
(``p[j, i]`` at ``(x[i], y[j])``) or its C-order flattening of length ``nx*ny`` with
x fastest, i.e. flat index ``k = j*nx + i``. ``apply`` returns the same layout it got.

Symbols and units
-----------------
p        pressure, Pa
v        elastic displacement (gap opening), m
E'       reduced modulus 2/((1-nu1^2)/E1 + (1-nu2^2)/E2), Pa (Hamrock; Johnson's E* = E'/2)
D, Dx, Dy  grid spacings, m
K        geometric influence integral: m (point, integral of 1/r over a cell) or
         m (line, integral of ln|x - s| over a cell, with lengths in metres)
c        local compliance coefficient A'/E, m/Pa

Only numpy and scipy are imported.
"""
from __future__ import annotations

import math
from abc import ABC, abstractmethod
from functools import cached_property
from typing import Literal

import numpy as np
import scipy.fft
import scipy.linalg
import scipy.sparse

from ..validation import require_positive

__all__ = [
    "Compliance",
    "RigidCompliance",
    "LocalCompliance",
    "HalfSpaceLine",
    "GradedHalfSpaceLine",
    "HalfSpacePoint",
    "make_compliance",
    "kodnir_local_coefficient",
    "line_kernel",
    "line_displacement_at",
    "point_kernel",
    "DENSE_POINT_CAP",
    "UNIFORMITY_TOLERANCE",
    "spacing_deviation",
]

#: Largest number of unknowns for which a dense 2D (point) matrix is formed on request.
DENSE_POINT_CAP = 5000

#: Largest relative deviation of a node spacing from the mean spacing accepted as uniform.
UNIFORMITY_TOLERANCE = 1e-6

#: Above this many nodes HalfSpaceLine(method="auto") applies by FFT instead of dense.
LINE_DENSE_AUTO_CAP = 4096


# ----------------------------------------------------------------------------------------
# Validation helpers
# ----------------------------------------------------------------------------------------

def _check_increasing(name: str, values: np.ndarray) -> np.ndarray:
    """Return the float array of a strictly increasing 1D node array (>= 2 finite nodes)."""
    arr = np.asarray(values, dtype=float)
    if arr.ndim != 1 or arr.size < 2:
        raise ValueError(
            f"{name} must be a 1D array of at least 2 node coordinates in m, "
            f"got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must contain finite node coordinates in m, got non-finite values")
    if np.any(np.diff(arr) <= 0.0):
        raise ValueError(f"{name} must be strictly increasing (node coordinates in m)")
    return arr


def spacing_deviation(x: np.ndarray) -> float:
    """Largest deviation of a node spacing from the mean spacing, relative to it [-], of
    increasing nodes ``x`` (0 on a uniform grid; see :data:`UNIFORMITY_TOLERANCE`)."""
    x = np.asarray(x, dtype=float)
    mean = (x[-1] - x[0]) / (x.size - 1)
    return float(np.max(np.abs(np.diff(x) - mean)) / mean)


def _check_grid(name: str, values: np.ndarray) -> tuple[np.ndarray, float]:
    """Return (float array, spacing in m) of a uniform, strictly increasing 1D node array."""
    arr = _check_increasing(name, values)
    spacing = (arr[-1] - arr[0]) / (arr.size - 1)
    deviation = spacing_deviation(arr)
    if deviation > UNIFORMITY_TOLERANCE:
        raise ValueError(
            f"{name} must be uniformly spaced: the spacing deviates by {deviation:.3g} "
            f"(relative) from the mean spacing {spacing:.6g} m, tolerance "
            f"{UNIFORMITY_TOLERANCE:g}")
    return arr, float(spacing)


def _check_radius_cells(radius_cells: int) -> int:
    if isinstance(radius_cells, bool) or not isinstance(radius_cells, (int, np.integer)) \
            or radius_cells < 0:
        raise ValueError(
            f"radius_cells must be a non-negative integer number of cells, got {radius_cells!r}")
    return int(radius_cells)


def _normalise_shape(shape: int | tuple[int, ...] | None) -> tuple[int, ...] | None:
    if shape is None:
        return None
    if isinstance(shape, (int, np.integer)) and not isinstance(shape, bool):
        shape = (int(shape),)
    try:
        shape = tuple(int(s) for s in shape)
    except TypeError:
        raise ValueError(f"shape must be an int (line) or (ny, nx) (point) node count, "
                         f"got {shape!r}") from None
    if len(shape) not in (1, 2) or any(s < 1 for s in shape):
        raise ValueError(f"shape must be an int (line) or (ny, nx) (point) with positive "
                         f"node counts, got {shape!r}")
    return shape


def _padded_length(n: int) -> int:
    """FFT length for the linear convolution of n-node fields with a 2n-1 kernel.

    Any length >= 2n - 1 is exact (DC-FFT needs no more); 2n itself is slow for the
    usual 2^k + 1 grids (2 x 257 = 514 has the prime 257), so 2n - 1 is rounded up to a
    fast 2-3-5-7-11-smooth length: 257 nodes -> 540, 513 -> 1080.
    """
    return scipy.fft.next_fast_len(2 * n - 1, real=True)


# ----------------------------------------------------------------------------------------
# Geometric influence integrals (docs/theory.md section 12)
# ----------------------------------------------------------------------------------------

def _xlogx(t: np.ndarray) -> np.ndarray:
    """t ln|t| with the limit 0 at t = 0."""
    t = np.asarray(t, dtype=float)
    out = np.zeros_like(t)
    nz = t != 0.0
    out[nz] = t[nz] * np.log(np.abs(t[nz]))
    return out


def line_kernel(d: np.ndarray | float, spacing: float) -> np.ndarray:
    """Integral of ln|d - s| over the cell s in [-D/2, D/2] (plane-strain log kernel).

    ``K(d) = (d + D/2) ln|d + D/2| - (d - D/2) ln|d - D/2| - D`` (docs/theory.md section 12), with
    ``K(0) = D (ln(D/2) - 1)``. For ``|d| > D`` the algebraically equal form
    ``D ln|d| + |d| [(1+u) log1p(u) - (1-u) log1p(-u)] - D``, ``u = D/(2|d|)``, is used to
    avoid cancellation between the two large logarithms.

    Parameters
    ----------
    d : array_like
        Offset ``x_i - x_j`` of the observation node from the cell centre, m.
    spacing : float
        Cell width D, m.

    Returns
    -------
    numpy.ndarray
        K(d), m (the logarithm is of lengths in metres).
    """
    D = require_positive("spacing", spacing, "m")
    d = np.abs(np.asarray(d, dtype=float))  # K is even in d
    out = np.empty_like(d)
    far = d > D
    near = ~far
    dn = d[near]
    out[near] = _xlogx(dn + 0.5 * D) - _xlogx(dn - 0.5 * D) - D
    df = d[far]
    u = 0.5 * D / df
    out[far] = D * np.log(df) + df * ((1.0 + u) * np.log1p(u) - (1.0 - u) * np.log1p(-u)) - D
    return out


def _corner_g(X: np.ndarray, Y: np.ndarray) -> np.ndarray:
    """G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|), a term being 0 where its divisor is 0."""
    X = np.asarray(X, dtype=float)
    Y = np.asarray(Y, dtype=float)
    X, Y = np.broadcast_arrays(X, Y)
    ax = np.abs(X)
    ay = np.abs(Y)
    safe_x = np.where(ax > 0.0, ax, 1.0)
    safe_y = np.where(ay > 0.0, ay, 1.0)
    t1 = np.where(ax > 0.0, X * np.arcsinh(Y / safe_x), 0.0)
    t2 = np.where(ay > 0.0, Y * np.arcsinh(X / safe_y), 0.0)
    return t1 + t2


def point_kernel(X: np.ndarray | float, Y: np.ndarray | float,
                 dx: float, dy: float) -> np.ndarray:
    """Integral of 1/sqrt((X - x')^2 + (Y - y')^2) over the cell |x'| <= Dx/2, |y'| <= Dy/2.

    ``K = G(X+Dx/2, Y+Dy/2) - G(X-Dx/2, Y+Dy/2) - G(X+Dx/2, Y-Dy/2) + G(X-Dx/2, Y-Dy/2)``
    with ``G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|)`` (docs/theory.md section 12). The square self
    term is ``4 D ln(1 + sqrt 2)``.

    Parameters
    ----------
    X, Y : array_like
        Offsets of the observation point from the cell centre, m (broadcast together).
    dx, dy : float
        Cell sides Dx, Dy, m.

    Returns
    -------
    numpy.ndarray
        K(X, Y), m.
    """
    hx = 0.5 * require_positive("dx", dx, "m")
    hy = 0.5 * require_positive("dy", dy, "m")
    X = np.asarray(X, dtype=float)
    Y = np.asarray(Y, dtype=float)
    return (_corner_g(X + hx, Y + hy) - _corner_g(X - hx, Y + hy)
            - _corner_g(X + hx, Y - hy) + _corner_g(X - hx, Y - hy))


def _point_kernel_grid(nx: int, ny: int, dx: float, dy: float) -> np.ndarray:
    """K for the non-negative offsets (j dy, i dx), shape (ny, nx), m.

    G is evaluated once on the (ny+1) x (nx+1) corner lattice ((i - 1/2) dx, (j - 1/2) dy)
    and differenced, which is the corner sum of :func:`point_kernel` at every offset.
    """
    xc = (np.arange(nx + 1) - 0.5) * dx
    yc = (np.arange(ny + 1) - 0.5) * dy
    g = _corner_g(xc[None, :], yc[:, None])
    return g[1:, 1:] - g[1:, :-1] - g[:-1, 1:] + g[:-1, :-1]


def kodnir_local_coefficient(load_per_length: float, radius: float,
                             youngs_modulus: float) -> float:
    """Kodnir's local compliance coefficient A'/E (Yachikov & Vostrikov 2015, docs/theory.md section 11).

    ``A' = 2.54 b_H``, ``b_H = 1.52 sqrt(w R / E)``; the factor 1.52 already contains
    nu = 0.3 for two equal steel bodies, so E is their Young's modulus (not E').

    Parameters
    ----------
    load_per_length : float
        Load per unit length of the line contact w = q_H, N/m.
    radius : float
        Reduced radius R (the paper's rho), m.
    youngs_modulus : float
        Young's modulus E of the two (equal) bodies, Pa.

    Returns
    -------
    float
        A'/E, m/Pa: ``v = (A'/E) p``.
    """
    w = require_positive("load_per_length", load_per_length, "N/m")
    r = require_positive("radius", radius, "m")
    e = require_positive("youngs_modulus", youngs_modulus, "Pa")
    b_h = 1.52 * math.sqrt(w * r / e)
    return 2.54 * b_h / e


# ----------------------------------------------------------------------------------------
# Operators
# ----------------------------------------------------------------------------------------

class Compliance(ABC):
    """Common interface of the compliance operators ``v = C p`` (all linear, symmetric).

    Attributes
    ----------
    kind : {"rigid", "local", "half-space"}
    is_zero : bool
        True when v is identically 0 (rigid).
    is_local : bool
        True when v_i depends on p_i only (diagonal C: rigid, local).
    shape : tuple of int or None
        ``(N,)`` for a line grid, ``(ny, nx)`` for a point grid; None if not fixed
        (rigid/local operators built without a shape act on any array).
    """

    kind: str
    is_zero: bool = False
    is_local: bool = False
    is_symmetric: bool = True
    shape: tuple[int, ...] | None = None

    @property
    def size(self) -> int | None:
        """Number of unknowns N (None if the operator has no fixed shape)."""
        return None if self.shape is None else int(np.prod(self.shape))

    def _check_p(self, p: np.ndarray) -> np.ndarray:
        p = np.asarray(p, dtype=float)
        if self.shape is None:
            return p
        n = self.size
        if p.shape == self.shape or (p.ndim == 1 and p.size == n):
            return p
        raise ValueError(
            f"p must have shape {self.shape} or ({n},) (pressure in Pa), got {p.shape}")

    def _require_size(self, n: int | None) -> int:
        if self.size is not None:
            if n is not None and int(n) != self.size:
                raise ValueError(f"n must equal the operator size {self.size}, got {n!r}")
            return self.size
        if n is None:
            raise ValueError(
                f"n (number of unknowns) is required: this {type(self).__name__} was built "
                f"without a shape")
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
            raise ValueError(f"n must be a positive integer number of unknowns, got {n!r}")
        return int(n)

    @abstractmethod
    def apply(self, p: np.ndarray) -> np.ndarray:
        """Displacement v (m) for the nodal pressure p (Pa); same layout as p."""

    @abstractmethod
    def diagonal(self, n: int | None = None) -> np.ndarray:
        """Self-influence dv_i/dp_i of every node, shape (N,), m/Pa."""

    @abstractmethod
    def matrix(self, n: int | None = None) -> np.ndarray:
        """Dense influence matrix C (N, N), m/Pa, with ``v.ravel() = C @ p.ravel()``."""

    @abstractmethod
    def near_field(self, radius_cells: int = 1, n: int | None = None) -> scipy.sparse.csr_matrix:
        """Sparse part of C for neighbours within ``radius_cells`` (m/Pa), csr (N, N)."""

    def __call__(self, p: np.ndarray) -> np.ndarray:
        return self.apply(p)


class RigidCompliance(Compliance):
    """Rigid bodies: v = 0.

    Parameters
    ----------
    shape : int or (ny, nx), optional
        Node count (line) or grid shape (point). Without it the operator accepts any
        array and ``matrix``/``diagonal``/``near_field`` need ``n``.
    """

    kind = "rigid"
    is_zero = True
    is_local = True

    def __init__(self, shape: int | tuple[int, int] | None = None) -> None:
        self.shape = _normalise_shape(shape)

    def apply(self, p: np.ndarray) -> np.ndarray:
        return np.zeros_like(self._check_p(p))

    def diagonal(self, n: int | None = None) -> np.ndarray:
        return np.zeros(self._require_size(n))

    def matrix(self, n: int | None = None) -> np.ndarray:
        n = self._require_size(n)
        return np.zeros((n, n))

    def near_field(self, radius_cells: int = 1, n: int | None = None) -> scipy.sparse.csr_matrix:
        _check_radius_cells(radius_cells)
        n = self._require_size(n)
        return scipy.sparse.csr_matrix((n, n))

    def __repr__(self) -> str:
        return f"RigidCompliance(shape={self.shape})"


class LocalCompliance(Compliance):
    """Local (Winkler) compliance (Kodnir; Yachikov & Vostrikov 2015): v = c p with c = A'/E (m/Pa).

    Parameters
    ----------
    coefficient : float
        c >= 0, m/Pa (see :func:`kodnir_local_coefficient`).
    shape : int or (ny, nx), optional
        As for :class:`RigidCompliance`.
    """

    kind = "local"
    is_local = True

    def __init__(self, coefficient: float, shape: int | tuple[int, int] | None = None) -> None:
        try:
            c = float(coefficient)
        except (TypeError, ValueError):
            raise ValueError(f"coefficient must be a number >= 0 m/Pa, got {coefficient!r}") \
                from None
        if not (math.isfinite(c) and c >= 0.0):
            raise ValueError(f"coefficient must be finite and >= 0 m/Pa, got {coefficient!r}")
        self.coefficient = c
        self.is_zero = c == 0.0
        self.shape = _normalise_shape(shape)

    def apply(self, p: np.ndarray) -> np.ndarray:
        return self.coefficient * self._check_p(p)

    def diagonal(self, n: int | None = None) -> np.ndarray:
        return np.full(self._require_size(n), self.coefficient)

    def matrix(self, n: int | None = None) -> np.ndarray:
        return self.coefficient * np.eye(self._require_size(n))

    def near_field(self, radius_cells: int = 1, n: int | None = None) -> scipy.sparse.csr_matrix:
        _check_radius_cells(radius_cells)
        n = self._require_size(n)
        return scipy.sparse.diags(np.full(n, self.coefficient), format="csr")

    def __repr__(self) -> str:
        return f"LocalCompliance(coefficient={self.coefficient!r} m/Pa, shape={self.shape})"


#: HalfSpaceLine.apply uses the FFT product from this many nodes on, even when the dense
#: matrix exists (O(N log N) instead of N^2: at 2001 nodes about 40 us instead of 0.4 ms);
#: the two agree to rounding.
LINE_FFT_APPLY_MIN = 512


class HalfSpaceLine(Compliance):
    """Plane-strain elastic half-spaces, line contact: v = -(4/(pi E')) int p ln|x - s| ds.

    ``v_i = -(4/(pi E')) sum_j K(x_i - x_j) p_j`` with the exact cell integral K of
    :func:`line_kernel`. The logarithm makes v defined up to a constant that depends on
    the length unit (metres here) and on the domain; the solver's rigid offset h0 absorbs
    it, so only differences of v are physical.

    Parameters
    ----------
    x : array_like, shape (N,)
        Uniform, strictly increasing node coordinates, m.
    e_prime : float
        Reduced modulus E', Pa.
    method : {"auto", "dense", "fft"}
        "dense" builds the symmetric Toeplitz matrix at construction and applies it by a
        matrix-vector product; "fft" applies by a zero-padded FFT (O(N log N), memory
        O(N)) and builds the matrix only when :meth:`matrix` is called; "auto" is
        "dense" up to 4096 nodes.
    """

    kind = "half-space"

    def __init__(self, x: np.ndarray, e_prime: float,
                 method: Literal["auto", "dense", "fft"] = "auto") -> None:
        self.x, self.spacing = _check_grid("x", x)
        self.e_prime = require_positive("e_prime", e_prime, "Pa")
        if method not in ("auto", "dense", "fft"):
            raise ValueError(f"method must be one of 'auto', 'dense', 'fft', got {method!r}")
        n = self.x.size
        self.shape = (n,)
        if method == "auto":
            method = "dense" if n <= LINE_DENSE_AUTO_CAP else "fft"
        self.method = method
        offsets = np.arange(n) * self.spacing
        #: first row of C: C_{0j} = dv_0/dp_j, m/Pa (C is symmetric Toeplitz).
        self._row = -(4.0 / (math.pi * self.e_prime)) * line_kernel(offsets, self.spacing)
        self._row.setflags(write=False)
        self._matrix: np.ndarray | None = None
        self._spectrum: np.ndarray | None = None
        if method == "dense":
            self._build_matrix()
        else:
            self._build_spectrum()

    def _build_matrix(self) -> np.ndarray:
        if self._matrix is None:
            m = scipy.linalg.toeplitz(self._row)
            m.setflags(write=False)
            self._matrix = m
        return self._matrix

    def _build_spectrum(self) -> np.ndarray:
        if self._spectrum is None:
            n = self.x.size
            # wrap-around arrangement of the even kernel on a ring of L >= 2N - 1: offsets
            # 0..N-1 at 0..N-1, offset -m at L - m; indices N..L-N are never reached.
            self._padded_length = _padded_length(n)
            k = np.zeros(self._padded_length)
            k[:n] = self._row
            k[self._padded_length - n + 1:] = self._row[:0:-1]
            self._spectrum = scipy.fft.rfft(k)
        return self._spectrum

    def influence_row(self) -> np.ndarray:
        """First row of C, ``C[0, j] = -(4/(pi E')) K(j D)``, shape (N,), m/Pa (read-only)."""
        return self._row

    def apply(self, p: np.ndarray) -> np.ndarray:
        p = self._check_p(p)
        n = self.x.size
        if self._matrix is not None and (n < LINE_FFT_APPLY_MIN or p.ndim != 1):
            return self._matrix @ p
        spec = self._build_spectrum()
        length = self._padded_length
        return scipy.fft.irfft(spec * scipy.fft.rfft(p, length), length)[:n]

    def diagonal(self, n: int | None = None) -> np.ndarray:
        self._require_size(n)
        return np.full(self.x.size, self._row[0])

    def matrix(self, n: int | None = None) -> np.ndarray:
        """Dense symmetric Toeplitz C (N, N), m/Pa (cached, read-only)."""
        self._require_size(n)
        return self._build_matrix()

    def near_field(self, radius_cells: int = 1, n: int | None = None) -> scipy.sparse.csr_matrix:
        """Band of C with ``|i - j| <= radius_cells``, csr (N, N), m/Pa."""
        r = min(_check_radius_cells(radius_cells), self.x.size - 1)
        self._require_size(n)
        offsets = np.arange(-r, r + 1)
        diagonals = [np.full(self.x.size - abs(k), self._row[abs(k)]) for k in offsets]
        return scipy.sparse.diags(diagonals, offsets=offsets, format="csr")

    def __repr__(self) -> str:
        return (f"HalfSpaceLine(N={self.x.size}, D={self.spacing:.4g} m, "
                f"e_prime={self.e_prime:.4g} Pa, method={self.method!r})")


def _log_antiderivative(t: np.ndarray) -> np.ndarray:
    """G(t) = t ln|t| - t, with G(0) = 0: an antiderivative of ln|t| [m]."""
    return _xlogx(t) - np.asarray(t, dtype=float)


def line_displacement_at(x: np.ndarray, p: np.ndarray, e_prime: float,
                         points: np.ndarray) -> np.ndarray:
    """Plane-strain displacement at any points of a piecewise-linear line pressure.

    ``v(x) = -(4/(pi E')) int p(s) ln|x - s| ds`` with p linear between the nodes and 0
    outside them, in closed form per element: with u = s - x,
    ``int ln|u| du = G(u) = u ln|u| - u`` and ``int u ln|u| du = H(u) = u^2 ln|u|/2 - u^2/4``.
    The compliance operators act on cell-constant pressures (:class:`HalfSpaceLine`,
    :class:`GradedHalfSpaceLine`); this is the deflection of the finite element pressure
    itself, smooth between the nodes, whose bow there the film minimum of a line contact
    takes into account (``bearing_fem.contacts.line``). Differences of v are physical;
    v itself carries the constant of the logarithm of lengths in metres.

    Parameters
    ----------
    x : ndarray, shape (N,)
        Increasing node coordinates, m.
    p : ndarray, shape (N,)
        Nodal pressure, Pa.
    e_prime : float
        Reduced modulus E', Pa.
    points : ndarray, shape (K,)
        Where the displacement is wanted, m.

    Returns
    -------
    ndarray, shape (K,)
        Displacement v, m.

    Raises
    ------
    ValueError
        x not at least two finite increasing coordinates, p not finite of the shape of x,
        e_prime not > 0, points not finite.
    """
    x = np.asarray(x, dtype=float)
    p = np.asarray(p, dtype=float)
    pts = np.atleast_1d(np.asarray(points, dtype=float))
    if x.ndim != 1 or x.size < 2 or not np.all(np.isfinite(x)) or np.any(np.diff(x) <= 0.0):
        raise ValueError(f"x must be at least 2 finite, strictly increasing node coordinates "
                         f"in m, got shape {x.shape}")
    if p.shape != x.shape or not np.all(np.isfinite(p)):
        raise ValueError(f"p must be finite nodal pressures in Pa of the shape of x "
                         f"{x.shape}, got shape {p.shape}")
    if pts.ndim != 1 or not np.all(np.isfinite(pts)):
        raise ValueError(f"points must be finite coordinates in m, got shape {pts.shape}")
    scale = -4.0 / (math.pi * require_positive("e_prime", e_prime, "Pa"))
    slope = np.diff(p) / np.diff(x)

    def h_anti(u: np.ndarray) -> np.ndarray:
        return 0.5 * u * _xlogx(u) - 0.25 * u * u

    out = np.empty(pts.size)
    block = max(1, _DISPLACEMENT_BLOCK_ENTRIES // (x.size - 1))  # points per block
    for start in range(0, pts.size, block):
        at = pts[start:start + block, None]
        u0, u1 = x[None, :-1] - at, x[None, 1:] - at
        i0 = _log_antiderivative(u1) - _log_antiderivative(u0)  # int ln|u| over the element
        i1 = (h_anti(u1) - h_anti(u0)) - u0 * i0                # int (u - u0) ln|u| over it
        out[start:start + block] = scale * (i0 @ p[:-1] + i1 @ slope)
    return out


#: Points x elements per block of :func:`line_displacement_at` (each block holds a few
#: arrays of this many doubles: about 8 MB each).
_DISPLACEMENT_BLOCK_ENTRIES = 2**20


class GradedHalfSpaceLine(Compliance):
    """The plane-strain half-space of :class:`HalfSpaceLine` on any increasing nodes.

    The pressure is constant on the cell of node j between the midpoints to its
    neighbours (the end cells reach as far beyond the end nodes as their inner half), and
    ``C_ij = -(4/(pi E')) [G(x_i - a_j) - G(x_i - b_j)]``, G(t) = t ln|t| - t, the exact
    integral of ln|x_i - s| over the cell [a_j, b_j] (docs/theory.md section 12). On
    uniform nodes this is :class:`HalfSpaceLine`'s matrix (to rounding). A graded grid
    refined at the outlet resolves the pressure spike and the constriction with fewer
    nodes than a uniform one (docs/line_contact.md, "Graded grids"). Dense only: memory
    and products grow as N^2 (a few thousand nodes).

    Parameters
    ----------
    x : array_like, shape (N,)
        Strictly increasing node coordinates, m.
    e_prime : float
        Reduced modulus E', Pa.
    """

    kind = "half-space"

    def __init__(self, x: np.ndarray, e_prime: float) -> None:
        arr = _check_increasing("x", x)
        self.x = arr
        self.e_prime = require_positive("e_prime", e_prime, "Pa")
        self.shape = (arr.size,)
        mid = 0.5 * (arr[1:] + arr[:-1])
        a = np.concatenate(([arr[0] - (mid[0] - arr[0])], mid))
        b = np.concatenate((mid, [arr[-1] + (arr[-1] - mid[-1])]))
        d = arr[:, None]
        m = -(4.0 / (math.pi * self.e_prime)) * (
            _log_antiderivative(d - a[None, :]) - _log_antiderivative(d - b[None, :]))
        m.setflags(write=False)
        self._matrix = m

    def apply(self, p: np.ndarray) -> np.ndarray:
        return self._matrix @ self._check_p(p)

    def diagonal(self, n: int | None = None) -> np.ndarray:
        self._require_size(n)
        return np.diag(self._matrix).copy()

    def matrix(self, n: int | None = None) -> np.ndarray:
        """Dense C (N, N), m/Pa (read-only)."""
        self._require_size(n)
        return self._matrix

    def near_field(self, radius_cells: int = 1, n: int | None = None) -> scipy.sparse.csr_matrix:
        """Band of C with ``|i - j| <= radius_cells``, csr (N, N), m/Pa."""
        r = min(_check_radius_cells(radius_cells), self.x.size - 1)
        self._require_size(n)
        return scipy.sparse.csr_matrix(np.triu(np.tril(self._matrix, r), -r))

    def __repr__(self) -> str:
        steps = np.diff(self.x)
        return (f"GradedHalfSpaceLine(N={self.x.size}, spacing {steps.min():.4g}.."
                f"{steps.max():.4g} m, e_prime={self.e_prime:.4g} Pa)")


class HalfSpacePoint(Compliance):
    """Elastic half-spaces, point contact (Boussinesq): v = (2/(pi E')) iint p / |r - r'| dA.

    ``v = (2/(pi E')) sum K p`` with the exact rectangle integrals of
    :func:`point_kernel`, applied by a zero-padded FFT (DC-FFT, Liu, Wang & Liu 2000):
    the pressure is embedded in an ``(Ly, Lx)`` array of zeros, ``L >= 2n - 1`` per axis
    (2n - 1 rounded up to a fast FFT length, see ``_padded_length``; the classic choice
    is 2n), the kernel is laid out with non-negative offsets at the start and negative
    offsets wrapped to the end of each axis (index ``L - m`` for offset ``-m``; indices
    n..L-n unused, zero), and the circular convolution restricted to the first
    ``(ny, nx)`` block is the exact linear one. The kernel spectrum (``rfft2``,
    ``(Ly, Lx//2 + 1)`` complex) is cached.

    Parameters
    ----------
    x : array_like, shape (nx,)
        Uniform node coordinates along the rolling direction, m.
    y : array_like, shape (ny,)
        Uniform node coordinates across it, m.
    e_prime : float
        Reduced modulus E', Pa.

    Notes
    -----
    Fields are ``(ny, nx)`` arrays (``p[j, i]`` at ``(x[i], y[j])``) or their C-order
    flattening, flat index ``j*nx + i`` (x fastest).
    """

    kind = "half-space"

    def __init__(self, x: np.ndarray, y: np.ndarray, e_prime: float) -> None:
        self.x, self.dx = _check_grid("x", x)
        self.y, self.dy = _check_grid("y", y)
        self.e_prime = require_positive("e_prime", e_prime, "Pa")
        nx, ny = self.x.size, self.y.size
        self.shape = (ny, nx)
        scale = 2.0 / (math.pi * self.e_prime)
        # C for the non-negative offsets (j Dy, i Dx), m/Pa; even in both offsets.
        self._kernel = scale * _point_kernel_grid(nx, ny, self.dx, self.dy)
        self._kernel.setflags(write=False)
        ly, lx = _padded_length(ny), _padded_length(nx)
        self._padded_shape = (ly, lx)
        wrapped = np.zeros(self._padded_shape)
        wrapped[:ny, :nx] = self._kernel
        wrapped[ly - ny + 1:, :nx] = self._kernel[:0:-1, :]
        wrapped[:, lx - nx + 1:] = wrapped[:, nx - 1:0:-1]
        self._spectrum = scipy.fft.rfft2(wrapped)

    def kernel(self) -> np.ndarray:
        """Influence coefficients for offsets (j Dy, i Dx), j, i >= 0, shape (ny, nx), m/Pa.

        The kernel is even in both offsets: ``C[(j, i), (l, k)] = kernel()[|j-l|, |i-k|]``.
        Read-only.
        """
        return self._kernel

    def apply(self, p: np.ndarray) -> np.ndarray:
        p = self._check_p(p)
        ny, nx = self.shape
        padded = np.zeros(self._padded_shape)
        padded[:ny, :nx] = p.reshape(ny, nx)
        v = scipy.fft.irfft2(self._spectrum * scipy.fft.rfft2(padded),
                             s=self._padded_shape)[:ny, :nx]
        return v.reshape(p.shape) if p.ndim == 1 else np.ascontiguousarray(v)

    def diagonal(self, n: int | None = None) -> np.ndarray:
        self._require_size(n)
        return np.full(self.size, self._kernel[0, 0])

    def matrix(self, n: int | None = None) -> np.ndarray:
        """Dense C (N, N), m/Pa, in the flat layout ``j*nx + i``; only for N <= 5000."""
        self._require_size(n)
        if self.size > DENSE_POINT_CAP:
            raise ValueError(
                f"HalfSpacePoint.matrix: a dense matrix of {self.size} x {self.size} unknowns "
                f"(grid ny x nx = {self.shape[0]} x {self.shape[1]}) exceeds the cap of "
                f"{DENSE_POINT_CAP} unknowns; use apply() (FFT) and near_field() instead")
        ny, nx = self.shape
        dj = np.abs(np.arange(ny)[:, None] - np.arange(ny)[None, :])   # (j, l)
        di = np.abs(np.arange(nx)[:, None] - np.arange(nx)[None, :])   # (i, k)
        m = self._kernel[dj[:, None, :, None], di[None, :, None, :]]   # (j, i, l, k)
        return m.reshape(self.size, self.size)

    def near_field(self, radius_cells: int = 1, n: int | None = None) -> scipy.sparse.csr_matrix:
        """C truncated to the square stencil ``|j-l|, |i-k| <= radius_cells``, csr (N, N), m/Pa.

        Meant as the compliance block of a sparse preconditioner; it is symmetric.
        """
        r = _check_radius_cells(radius_cells)
        self._require_size(n)
        ny, nx = self.shape
        rx, ry = min(r, nx - 1), min(r, ny - 1)
        # Sparsity pattern = kron(band of half-width ry in y, band of half-width rx in x);
        # the value of entry (j*nx+i, l*nx+k) is kernel[|j-l|, |i-k|].
        band_y = scipy.sparse.diags([np.ones(ny - abs(k)) for k in range(-ry, ry + 1)],
                                    offsets=np.arange(-ry, ry + 1), format="csr")
        band_x = scipy.sparse.diags([np.ones(nx - abs(k)) for k in range(-rx, rx + 1)],
                                    offsets=np.arange(-rx, rx + 1), format="csr")
        mat = scipy.sparse.csr_matrix(scipy.sparse.kron(band_y, band_x, format="csr"))
        rows = np.repeat(np.arange(self.size, dtype=mat.indices.dtype), np.diff(mat.indptr))
        row_j, row_i = np.divmod(rows, nx)
        col_j, col_i = np.divmod(mat.indices, nx)
        mat.data = self._kernel[np.abs(row_j - col_j), np.abs(row_i - col_i)]
        return mat

    def __repr__(self) -> str:
        return (f"HalfSpacePoint(ny x nx = {self.shape[0]} x {self.shape[1]}, "
                f"Dx={self.dx:.4g} m, Dy={self.dy:.4g} m, e_prime={self.e_prime:.4g} Pa)")


class MirroredHalfSpacePoint(Compliance):
    """:class:`HalfSpacePoint` for pressures even in y, on the half grid y >= 0.

    A point contact rolling along x is symmetric about y = 0, so its pressure is even in
    y and the problem can be solved on the nodes with y >= 0 only. This operator maps the
    pressure on those nodes to their displacement under the whole (mirrored) pressure
    field:

        v_(j, i) = sum_(l, k) (K[|j - l|, |i - k|] + [l > 0] K[j + l, |i - k|]) p_(l, k),

    the second term being the image node (-y_l). ``apply`` is the whole grid's product
    restricted to the half grid (equal to rounding) at about a third of its cost: the
    mirrored field and the kernel are even in y, so their zero-padded circular
    convolution along y is a product of type-I discrete cosine transforms of the half
    length (the DFT of an even sequence), and along x an rfft of the padded rows
    (DC-FFT); only the ny half-grid rows are transformed and the kernel's transform is
    real (the kernel is even in x too): (N, Lx//2 + 1) reals with N = Ly/2 + 1,
    Ly >= 4 ny - 3 (every offset |j - l| <= 2 (ny - 1) of the whole grid has its own
    place on the circle of length Ly).

    Parameters
    ----------
    x : array_like, shape (nx,)
        Uniform node coordinates along the rolling direction, m.
    y : array_like, shape (ny,)
        Uniform node coordinates 0 = y_0 < y_1 < ... across it, m.
    e_prime : float
        Reduced modulus E', Pa.

    Attributes
    ----------
    full : HalfSpacePoint
        The operator on the whole grid, y from -y[-1] to y[-1] (2 ny - 1 rows), built on
        first use.
    """

    kind = "half-space"
    #: C[(j, i), (0, k)] has no image term, C[(0, k), (j, i)] has one: not symmetric
    is_symmetric = False

    def __init__(self, x: np.ndarray, y: np.ndarray, e_prime: float) -> None:
        ys, dy = _check_grid("y", y)
        if ys[0] != 0.0:
            raise ValueError(f"y must start at the symmetry line y = 0 m, got y[0] = {ys[0]!r} m")
        self.x, self.dx = _check_grid("x", x)
        self._y_full = np.concatenate([-ys[:0:-1], ys])
        self._y_full_spacing = _check_grid("y", self._y_full)[1]
        self.y, self.dy = ys, self._y_full_spacing
        self.e_prime = require_positive("e_prime", e_prime, "Pa")
        ny, nx = ys.size, self.x.size
        self.shape = (ny, nx)
        scale = 2.0 / (math.pi * self.e_prime)
        # offsets (j Dy, i Dx) of the whole grid, j <= 2 (ny - 1): direct and image
        self._kernel = scale * _point_kernel_grid(nx, 2 * ny - 1, self.dx,
                                                  self._y_full_spacing)
        self._kernel.setflags(write=False)
        lx = _padded_length(nx)
        half = scipy.fft.next_fast_len(2 * ny - 1)   # Ly / 2: Ly >= 4 ny - 2
        self._nd = half + 1                          # DCT-I length
        self._lx = lx
        wrapped = np.zeros((self._nd, lx))
        wrapped[:2 * ny - 1, :nx] = self._kernel
        wrapped[:2 * ny - 1, lx - nx + 1:] = self._kernel[:, :0:-1]
        spectrum = scipy.fft.rfft(scipy.fft.dct(wrapped, type=1, axis=0), axis=1)
        # even in x: the transform is real (its imaginary part is rounding)
        self._spectrum = np.ascontiguousarray(spectrum.real) / (2.0 * half)

    @cached_property
    def full(self) -> HalfSpacePoint:
        return HalfSpacePoint(self.x, self._y_full, self.e_prime)

    def mirror(self, p: np.ndarray) -> np.ndarray:
        """The even extension of a half-grid field to the full grid, shape (2 ny - 1, nx)."""
        half = self._check_p(p).reshape(self.shape)
        return np.concatenate([half[:0:-1], half])

    def kernel(self) -> np.ndarray:
        """The full grid's influence coefficients (see :meth:`HalfSpacePoint.kernel`)."""
        return self._kernel

    def apply(self, p: np.ndarray) -> np.ndarray:
        half = self._check_p(p).reshape(self.shape)
        ny, nx = self.shape
        padded = np.zeros((self._nd, nx))
        padded[:ny] = half
        t = scipy.fft.rfft(scipy.fft.dct(padded, type=1, axis=0), n=self._lx, axis=1)
        t *= self._spectrum
        u = scipy.fft.irfft(t, n=self._lx, axis=1)[:, :nx]
        v = scipy.fft.dct(u, type=1, axis=0)[:ny]
        return v.reshape(np.shape(p)) if np.ndim(p) == 1 else np.ascontiguousarray(v)

    def diagonal(self, n: int | None = None) -> np.ndarray:
        self._require_size(n)
        ny, nx = self.shape
        k = self._kernel
        j = np.arange(ny)
        return np.repeat(k[0, 0] + np.where(j > 0, k[2 * j, 0], 0.0), nx)

    def matrix(self, n: int | None = None) -> np.ndarray:
        """Dense C (N, N), m/Pa, flat layout ``j*nx + i``; only for N <= DENSE_POINT_CAP."""
        self._require_size(n)
        if self.size > DENSE_POINT_CAP:
            raise ValueError(
                f"MirroredHalfSpacePoint.matrix: a dense matrix of {self.size} x {self.size} "
                f"unknowns exceeds the cap of {DENSE_POINT_CAP}; use apply() (FFT)")
        ny, nx = self.shape
        k = self._kernel
        j = np.arange(ny)
        di = np.abs(np.arange(nx)[:, None] - np.arange(nx)[None, :])
        direct = k[np.abs(j[:, None] - j[None, :])[:, None, :, None], di[None, :, None, :]]
        image = k[(j[:, None] + j[None, :])[:, None, :, None], di[None, :, None, :]]
        image = image * (j > 0)[None, None, :, None]
        return (direct + image).reshape(self.size, self.size)

    def near_field(self, radius_cells: int = 1, n: int | None = None) -> scipy.sparse.csr_matrix:
        """The entries of :meth:`matrix` with ``|j-l|, |i-k| <= radius_cells``, csr (N, N)."""
        r = _check_radius_cells(radius_cells)
        self._require_size(n)
        ny, nx = self.shape
        mat = HalfSpacePoint.near_field(self, r)  # pattern and direct term on the half grid
        rows = np.repeat(np.arange(self.size, dtype=mat.indices.dtype), np.diff(mat.indptr))
        row_j, row_i = np.divmod(rows, nx)
        col_j, col_i = np.divmod(mat.indices, nx)
        image = np.where(col_j > 0, self._kernel[row_j + col_j, np.abs(row_i - col_i)], 0.0)
        mat.data = mat.data + image
        return mat

    def __repr__(self) -> str:
        return (f"MirroredHalfSpacePoint(ny x nx = {self.shape[0]} x {self.shape[1]} of "
                f"{2 * self.shape[0] - 1} x {self.shape[1]}, e_prime={self.e_prime:.4g} Pa)")


_KINDS = ("rigid", "local", "half-space")


def make_compliance(kind: str, x: np.ndarray, y: np.ndarray | None = None,
                    e_prime: float | None = None,
                    local_coefficient: float | None = None) -> Compliance:
    """Build the compliance operator a scene asks for.

    Parameters
    ----------
    kind : {"rigid", "local", "half-space"}
    x : array_like
        Node coordinates along x, m (uniform).
    y : array_like, optional
        Node coordinates along y, m, for a point contact; None for a line contact.
    e_prime : float, optional
        Reduced modulus E', Pa; required for "half-space".
    local_coefficient : float, optional
        A'/E, m/Pa; required for "local".

    Returns
    -------
    Compliance
        RigidCompliance, LocalCompliance, HalfSpaceLine or HalfSpacePoint, with its shape
        fixed to ``(len(x),)`` or ``(len(y), len(x))``.
    """
    if kind not in _KINDS:
        raise ValueError(f"kind must be one of {', '.join(repr(k) for k in _KINDS)}, "
                         f"got {kind!r}")
    xs, _ = _check_grid("x", x)
    if y is None:
        shape: tuple[int, ...] = (xs.size,)
    else:
        ys, _ = _check_grid("y", y)
        shape = (ys.size, xs.size)
    if kind == "rigid":
        return RigidCompliance(shape)
    if kind == "local":
        if local_coefficient is None:
            raise ValueError("local_coefficient (A'/E, m/Pa) is required for kind='local'")
        return LocalCompliance(local_coefficient, shape)
    if e_prime is None:
        raise ValueError("e_prime (reduced modulus, Pa) is required for kind='half-space'")
    if y is None:
        return HalfSpaceLine(xs, e_prime)
    return HalfSpacePoint(xs, y, e_prime)

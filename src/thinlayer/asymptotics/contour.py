r"""The leading contact area omega_0 = {delta0 - Phi(x1, x2) > 0} and its contour Gamma_0 (3.1)-(3.14).

The principal term (2.29) of the inner expansion is proportional to ``delta0 - Phi``; it is
positive exactly on

.. math:: \omega_0 = \{x : \delta_0 - \Phi(x_1, x_2) > 0\},

the main approximation of the contact area (section 4).  Its boundary
:math:`\Gamma_0 = \{\Phi = \delta_0\}` carries the local coordinates (3.4) of the boundary layer.

Everything here is in the *dimensional* coordinates ``x = (x1, x2)`` of (1.1).  The paper works in
the scaled coordinates (2.8) ``x = H_* xi`` with the scaled data (1.2) ``delta0 = eps delta0^*``,
``Phi(x) = eps Phi^*(xi)``.  Then arc length and normal distance scale as ``s = H_* s^*``,
``n = H_* n^*``, the unit tangent and normal are unchanged, the curvature radius is
``rho = H_* rho^*``, and from

    delta0 - Phi(f + n n0) = eps (delta0^* - Phi^*(f^* + n^* n0)) = eps H_*^2 (b1^* n^* + b2^* n^{*2})

(the factor ``H_*^2`` is the one pulled out of ``Phi^*`` in (2.13), which makes (3.13) read
``pi^2 vartheta H_* (eps v b1^* + eps^2 v^2 b2^*)`` with (2.25)) one finds

    b1(s) = eps H_* b1^*(s^*) = H b1^*(s^*),     b2(s) = eps b2^*(s^*) = (H / H_*) b2^*(s^*),

where ``b1, b2`` are the dimensional coefficients of :class:`ContactContour`
(``delta0 - Phi(f + n n0) = b1 n + b2 n^2 + O(n^3)``, ``b1 = -grad Phi . n0``,
``2 b2 = -n0^T Hess(Phi) n0``).  For the elliptic paraboloid they reproduce (3.14) term by term.

For the elliptic paraboloid (1.1) the contour is the ellipse with semi-axes
``a = sqrt(2 delta0 R1)``, ``b = sqrt(2 delta0 R2)`` and ``e^2 = 1 - R2/R1`` (3.1); in the scaled
coordinates the semi-axis is ``sqrt(2 delta0^* R1^*)/H_*`` (the printed (3.1) has ``R_1`` in
place of ``R_1^*``; see :meth:`EllipseContour.scaled_semi_axes`).

Method of :func:`contact_contour`:

0. the natural frame (scale-free search): steps 1-3 run on ``Phi(A u)/delta0 = 1`` with
   ``x = A u``, ``A`` built from the principal lengths ``l_j = sqrt(2 delta0/lambda_j)`` of a
   positive definite quadratic part (eigen-decomposition of its Hessian; lengths of the other
   degrees cap them), else from the smallest length at which one degree's terms reach delta0;
   so coefficients from 1e-70 to 1e30 and rotated, elongated regions are found on O(1) grids;
1. a box that contains the whole set ``{Phi < delta0}`` (a rigorous radius when the leading
   homogeneous part of Phi is positive definite, otherwise a box grown from the smallest natural
   length until its edge lies in ``{Phi > delta0}``, confirmed on boxes up to 256 times larger
   and at the largest natural length);
2. the critical points of Phi in the box (Newton on ``grad Phi = 0`` from the grid minima of
   ``|grad Phi|^2``): the minimum of Phi, critical points on the level set (not smooth), maxima
   inside the region (holes), minima outside it (further components);
3. the closed level lines ``Phi = delta0`` on a grid fitted to the region (``contourpy``);
4. a smooth (low-pass trigonometric) reference curve through the polygon, then Newton along its
   normals onto ``Phi = delta0``: the curve is an analytic periodic function of the reference
   parameter, represented spectrally; arc length by spectral integration of the speed, resampled
   at equal arc length and again projected onto the level set.  When that fails its checks
   (contours with features much smaller than the grid), the unit tangent field
   ``(-Phi_x2, Phi_x1)/|grad Phi|`` is integrated in arc length instead (scipy DOP853);
5. the final trigonometric (FFT) interpolant ``f(s)`` and its accuracy: the level residual and
   ``| |f'| - 1 |`` at points halfway between the nodes, the Fourier tail and the turning number
   ``(1/2pi) oint kappa ds = 1``.

Limits: the supported aspect ratio of omega_0 (longest/shortest principal axis, from its second
moments) is ``ASPECT_MAX = 32``: the arc-length Fourier series of an ellipse of aspect ratio
``r`` decays like ``exp(-2 pi k rho/L)`` with tip radius ``rho = b^2/a`` and ``L ~ 4a``, so it needs
about ``18 r^2`` nodes; ``_NMAX = 16384`` nodes reach ``r = 32`` with ``| |f'| - 1 | = 4.9e-7`` (measured;
``r = 35`` gives 4e-6 and fails the 1e-6 check).  A more elongated contour is kept only if it
still passes the spectral checks (ends blunter than an ellipse's, e.g. ``x1^2 + 1e6 x2^4``),
otherwise it is a ValueError naming its aspect ratio and the limit; above ``ASPECT_HARD = 1e3``
(an ellipse would need about 1.8e7 nodes) the spectral parametrisation is not attempted.  The
spectral step itself runs on ``Phi(ell u)/delta0 = 1`` with ``ell`` the size of the region, so its
tolerances do not depend on the units.
Components, holes and critical points smaller than the search grids can be missed
(structures are found from grid cells, grid minima of ``|grad Phi|^2`` and zooms around every
minimum below delta0); when the leading homogeneous part of Phi is only semidefinite, the
boundedness of ``{Phi < delta0}`` is checked on box edges (exact minimum of the 1-D polynomial
on each edge) up to 256 times the first guess and at the largest natural length.
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from typing import ClassVar

import numpy as np
import sympy as sp

from .. import symbols as S
from ..display import RichDisplay, fmt
from ..parse import as_expr
from ._contour_region import (
    ASPECT_HARD,
    ASPECT_MAX,
    Frame,
    Poly2,
    as_polynomial,
    region,
    short,
    signed_area,
    too_elongated,
    transformed,
)

__all__ = ["ContactContour", "ContourAccuracy", "EllipseContour", "contact_contour", "ellipse_contour"]


# ---------------------------------------------------------------------------------------------
# input validation
# ---------------------------------------------------------------------------------------------
def _as_delta0(delta0) -> float:
    if isinstance(delta0, bool):
        raise TypeError(f"delta0 must be a positive real number, got the bool {delta0!r}")
    if isinstance(delta0, sp.Basic):
        if delta0.free_symbols:
            names = ", ".join(sorted(str(q) for q in delta0.free_symbols))
            raise ValueError(
                f"delta0 = {delta0} has free symbol(s) {names}; the contour needs a numeric delta0 > 0 "
                "(substitute values first)"
            )
        val = complex(sp.N(delta0))
        if val.imag != 0:
            raise ValueError(f"delta0 must be a positive real number, got {delta0}")
        val = val.real
    elif isinstance(delta0, (numbers.Real, Fraction, np.floating, np.integer)):
        val = float(delta0)
    else:
        raise TypeError(f"delta0 must be a positive real number, got {delta0!r} ({type(delta0).__name__})")
    if not math.isfinite(val) or val <= 0:
        raise ValueError(f"delta0 (the indentation depth) must be a finite number > 0, got {delta0}")
    return val




# ---------------------------------------------------------------------------------------------
# spectral curve machinery
# ---------------------------------------------------------------------------------------------
def _wavenumbers(N: int) -> np.ndarray:
    return np.fft.fftfreq(N, 1.0 / N)


def _sym_coeffs(zhat: np.ndarray):
    """FFT coefficients -> (k, c) with the Nyquist mode split evenly between +-N/2."""
    N = len(zhat)
    k = _wavenumbers(N)
    c = zhat / N
    if N % 2 == 0:
        ny = N // 2
        k = np.concatenate([k, [ny]])
        c = np.concatenate([c, [0.5 * c[ny]]])
        k[ny] = -ny
        c[ny] = 0.5 * zhat[ny] / N
    return k, c


def _trig_eval(k: np.ndarray, c: np.ndarray, period: float, t, deriv: int = 0) -> np.ndarray:
    """sum_k c_k (i w_k)^m exp(i w_k t), w_k = 2 pi k / period, for integer k; vectorised over t.

    ``c`` may carry a trailing axis (several series at once).  Horner's scheme in
    ``z = exp(2 pi i t / period)`` (|z| = 1, so it is stable), with one complex exponential per point.
    """
    t = np.asarray(t, dtype=float)
    c = np.asarray(c, dtype=complex)
    ki = np.rint(np.asarray(k)).astype(int)
    if deriv:
        w = 2 * np.pi * ki / period
        c = c * ((1j * w) ** deriv).reshape((-1,) + (1,) * (c.ndim - 1))
    kmin, kmax = int(ki.min()), int(ki.max())
    dense = np.zeros((kmax - kmin + 1,) + c.shape[1:], dtype=complex)
    np.add.at(dense, ki - kmin, c)
    flat = t.ravel()
    z = np.exp(2j * np.pi * flat / period)
    extra = (1,) * (c.ndim - 1)
    zz = z.reshape((-1,) + extra)
    acc = np.broadcast_to(dense[-1], (len(flat),) + c.shape[1:]).copy()
    for j in range(len(dense) - 2, -1, -1):
        acc *= zz
        acc += dense[j]
    acc *= np.exp(2j * np.pi * kmin * flat / period).reshape((-1,) + extra)
    return acc.reshape(t.shape + c.shape[1:])


def _newton_onto_level(P: Poly2, delta0, x, y, iters=8):
    """Move points to Phi = delta0 along the gradient (the normal of the level line)."""
    for _ in range(iters):
        f, gx, gy, *_ = P.all(x, y)
        g2 = gx * gx + gy * gy
        r = (f - delta0) / g2
        x = x - r * gx
        y = y - r * gy
    return x, y


def _reference_curve(P, delta0, poly, kc: float = 24.0):
    """Smooth (band-limited) closed curve near the polygon, CCW; returns its Fourier data."""
    x, y = _newton_onto_level(P, delta0, poly[:, 0].copy(), poly[:, 1].copy(), iters=4)
    pts = np.column_stack([x, y])
    if signed_area(pts) < 0:
        pts = pts[::-1]
    seg = np.hypot(*(np.roll(pts, -1, axis=0) - pts).T)
    keep = seg > 1e-12 * seg.sum()
    pts = pts[keep]
    seg = np.hypot(*(np.roll(pts, -1, axis=0) - pts).T)
    cum = np.concatenate([[0.0], np.cumsum(seg)])
    Lp = cum[-1]
    K = max(512, int(16 * kc))
    tt = np.linspace(0.0, Lp, K, endpoint=False)
    closed = np.vstack([pts, pts[:1]])
    z = np.interp(tt, cum, closed[:, 0]) + 1j * np.interp(tt, cum, closed[:, 1])
    zhat = np.fft.fft(z)
    k = _wavenumbers(K)
    zhat = zhat * np.exp(-((np.abs(k) / kc) ** 4))
    zhat[np.abs(k) > 3 * kc] = 0.0
    kk, cc = _trim(*_sym_coeffs(zhat))
    return kk, cc, 2 * np.pi


def _project_along_normals(P, delta0, kk, cc, t):
    """X(t) = C(t) + h(t) nu(t) on Phi = delta0, nu the outward normal of the reference curve C."""
    both = _trig_eval(kk, np.stack([cc, 1j * kk * cc], axis=1), 2 * np.pi, t)
    C, dC = both[:, 0], both[:, 1]
    nu = -1j * dC / np.abs(dC)  # outward for a CCW curve
    h = np.zeros(len(t))
    cx, cy, nx, ny = C.real, C.imag, nu.real, nu.imag
    for _ in range(30):
        f, gx, gy, *_ = P.all(cx + h * nx, cy + h * ny)
        dh = -(f - delta0) / (gx * nx + gy * ny)
        h = h + dh
        if np.max(np.abs(dh)) <= 1e-16 * (np.max(np.abs(C)) + np.max(np.abs(h))):
            break
    return (cx + h * nx) + 1j * (cy + h * ny)


def _tail(zhat: np.ndarray) -> float:
    """Largest Fourier coefficient with |k| >= 3N/8 relative to the largest one (aliasing error)."""
    N = len(zhat)
    k = np.abs(_wavenumbers(N))
    a = np.abs(zhat) / N
    return float(a[k >= 3 * N // 8].max() / max(a.max(), 1e-300))


def _trim(k: np.ndarray, c: np.ndarray, rel: float = 1e-18):
    """Drop negligible Fourier coefficients (they cost time in the direct sums)."""
    keep = np.abs(c) > rel * np.abs(c).max()
    return k[keep], c[keep]


def _uniform_eval(zhat: np.ndarray, period: float, shift: float = 0.0, deriv: int = 0) -> np.ndarray:
    """The trigonometric interpolant (Nyquist split evenly) or its derivative at ``s_j + shift``."""
    N = len(zhat)
    k = _wavenumbers(N)
    w = 2 * np.pi * k / period
    c = zhat * np.exp(1j * w * shift) * (1j * w) ** deriv
    if N % 2 == 0:
        ny = N // 2
        wn = np.pi * N / period
        # 0.5 c_ny (e^{i wn s} (i wn)^m + e^{-i wn s} (-i wn)^m) at s = s_j + shift, s_j = j period / N
        c[ny] = zhat[ny] * 0.5 * (np.exp(1j * wn * shift) * (1j * wn) ** deriv
                                  + np.exp(-1j * wn * shift) * (-1j * wn) ** deriv)
    return np.fft.ifft(c)


def _arc_length_from_X(P, delta0, X):
    """Resample the curve X(t_j) (uniform t in [0, 2 pi), analytic) at equal arc length.

    The speed |X'(t)| is differentiated and integrated spectrally, ``s(t_k) = k L/N`` is solved by
    Newton with direct trigonometric sums, and the points are evaluated there and projected onto
    Phi = delta0.  Returns (points, perimeter).
    """
    N = len(X)
    t = 2 * np.pi * np.arange(N) / N
    Xhat = np.fft.fft(X)
    speed = np.abs(_uniform_eval(Xhat, 2 * np.pi, deriv=1))
    Shat = np.fft.fft(speed)
    L = 2 * np.pi * Shat[0].real / N
    s0 = Shat[0].real / N
    ks, cs = _trim(*_sym_coeffs(Shat))
    ci = np.where(ks != 0, cs / (1j * np.where(ks != 0, ks, 1)), 0.0)
    both = np.stack([ci, cs], axis=1)
    kw = _wavenumbers(N)
    integ = np.where((kw != 0) & (np.abs(kw) < N // 2), Shat / (1j * np.where(kw != 0, kw, 1)), 0.0)
    sn = s0 * t + np.fft.ifft(integ).real
    target = L * np.arange(N) / N
    tq = np.interp(target, np.concatenate([sn, [L]]), np.concatenate([t, [2 * np.pi]]))
    for _ in range(12):
        E = _trig_eval(ks, both, 2 * np.pi, tq)
        ds = (s0 * tq + E[:, 0].real - target) / E[:, 1].real
        tq = tq - ds
        if np.max(np.abs(ds)) < 1e-14:
            break
    kX, cX = _trim(*_sym_coeffs(Xhat))
    Z = _trig_eval(kX, cX, 2 * np.pi, tq)
    x, y = _newton_onto_level(P, delta0, Z.real, Z.imag, iters=3)
    return x + 1j * y, float(L)


_NMAX = 16384


def _nodes_by_reference(P, delta0, poly, n, tol):
    """Equal-arc-length nodes via normal projection from a smooth reference curve (fast path)."""
    kk, cc, _ = _reference_curve(P, delta0, poly)
    N = n or 128
    while True:
        t = 2 * np.pi * np.arange(N) / N
        X = _project_along_normals(P, delta0, kk, cc, t)
        if not np.all(np.isfinite(X)):
            return None
        if n is not None:
            return _arc_length_from_X(P, delta0, X)
        if _tail(np.fft.fft(X)) <= tol:
            Z, L = _arc_length_from_X(P, delta0, X)
            if _tail(np.fft.fft(Z)) <= tol:
                return Z, L
        if N >= 4096:
            return None
        N *= 2


def _nodes_by_ode(P, delta0, poly, n, tol):
    """Equal-arc-length nodes by integrating the unit tangent field ``(-Phi_y, Phi_x)/|grad Phi|``.

    Robust fallback for contours with small features: DOP853 with dense output in the arc
    length, the period from the return to the starting normal line, then projection onto
    Phi = delta0.
    """
    from scipy.integrate import solve_ivp

    x0, y0 = _newton_onto_level(P, delta0, np.array([poly[0, 0]]), np.array([poly[0, 1]]), iters=8)
    x0, y0 = float(x0[0]), float(y0[0])
    scale = float(np.max(np.abs(poly))) + 1e-300
    Lp = float(np.sum(np.hypot(*(np.roll(poly, -1, axis=0) - poly).T)))

    def rhs(_s, u):
        _, gx, gy, *_ = P.all(u[0], u[1])
        g = math.hypot(float(gx), float(gy))
        return [-float(gy) / g, float(gx) / g]  # unit tangent, omega_0 on the left

    _, gx0, gy0, *_ = P.all(x0, y0)
    g0 = math.hypot(float(gx0), float(gy0))
    T0 = (-float(gy0) / g0, float(gx0) / g0)

    def back(_s, u):  # crossing of the normal line through the start, forwards
        return (u[0] - x0) * T0[0] + (u[1] - y0) * T0[1]

    back.direction = 1.0

    sol = solve_ivp(rhs, (0.0, 1.25 * Lp), [x0, y0], method="DOP853", rtol=1e-13, atol=1e-15 * scale,
                    dense_output=True, events=back, max_step=Lp / 64)
    ret = [float(se) for se, ue in zip(sol.t_events[0], sol.y_events[0])
           if se > 0.25 * Lp and math.hypot(ue[0] - x0, ue[1] - y0) < 0.05 * Lp]
    if sol.status < 0 or not ret:
        return None
    L = ret[0]
    N = n or 128
    while True:
        sj = L * np.arange(N) / N
        U = sol.sol(sj)
        x, y = _newton_onto_level(P, delta0, U[0], U[1], iters=3)
        Z = x + 1j * y
        if n is not None or _tail(np.fft.fft(Z)) <= tol or N >= _NMAX:
            return Z, L
        N *= 2


def _accuracy(P, delta0, Z, L) -> ContourAccuracy:
    N = len(Z)
    Zhat = np.fft.fft(Z)
    h = L / (2 * N)
    zm = _uniform_eval(Zhat, L, shift=h)
    d1 = _uniform_eval(Zhat, L, shift=h, deriv=1)
    f, gx, gy, *_ = P.all(zm.real, zm.imag)
    dist = float(np.max(np.abs(f - delta0) / np.hypot(gx, gy))) / L
    speed = float(np.max(np.abs(np.abs(d1) - 1.0)))
    d1n = _uniform_eval(Zhat, L, deriv=1)
    d2n = _uniform_eval(Zhat, L, deriv=2)
    kap = (np.conj(d1n) * d2n).imag
    turning = float(np.sum(kap) * L / N / (2 * np.pi))
    return ContourAccuracy(dist, speed, _tail(Zhat), turning)


def _acceptable(acc: ContourAccuracy, strict: float) -> bool:
    return (abs(acc.turning_number - 1.0) <= 1e-6 and acc.level_distance <= strict
            and acc.speed_error <= strict)


# ---------------------------------------------------------------------------------------------
# results
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContourAccuracy:
    """Self-checks of the spectral contour (all measured between the nodes).

    Attributes
    ----------
    level_distance : float
        max |Phi(f(s)) - delta0| / |grad Phi|, the distance of the interpolant from Gamma_0,
        relative to the perimeter.
    speed_error : float
        max | |f'(s)| - 1 | (arc-length parametrisation).
    spectral_tail : float
        largest Fourier coefficient in the upper half of the band, relative to the largest one.
    turning_number : float
        (1/2 pi) oint kappa ds; 1 for a simple closed CCW curve (closure of the tangent).
    """

    level_distance: float
    speed_error: float
    spectral_tail: float
    turning_number: float


@dataclass(frozen=True, eq=False)
class ContactContour(RichDisplay):
    r"""The leading contact area omega_0 = {delta0 - Phi > 0} and its contour Gamma_0 (3.3)-(3.14).

    Made by :func:`contact_contour`; dimensional coordinates.  ``s`` is the arc length along
    Gamma_0 in ``[0, perimeter)`` (periodic), counterclockwise, ``omega_0`` on the left.
    All evaluators are vectorised over ``s`` (any shape); vector-valued ones return arrays with a
    trailing axis of length 2.

    Attributes
    ----------
    Phi, delta0
        The punch (sympy, in ``thinlayer.symbols.x1, x2``) and the indentation.
    perimeter, area, centroid
        Length of Gamma_0, area and centroid of omega_0.
    nodes : numpy.ndarray
        ``(N, 2)`` points of Gamma_0 at ``s_j = j perimeter / N``.
    min_point, min_value
        Where Phi is smallest and its value (the first point of contact).
    accuracy : ContourAccuracy
        :class:`ContourAccuracy`.
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "3.3"

    Phi: sp.Expr
    delta0: float
    perimeter: float
    area: float
    centroid: tuple[float, float]
    nodes: np.ndarray = field(repr=False)
    min_point: tuple[float, float]
    min_value: float
    accuracy: ContourAccuracy
    _k: np.ndarray = field(repr=False)
    _c: np.ndarray = field(repr=False)
    _poly: Poly2 = field(repr=False)
    _star_center: tuple[float, float] | None = field(repr=False)

    # ---- the curve (3.3) ------------------------------------------------------------------
    def _z(self, s, m=0):
        return _trig_eval(self._k, self._c, self.perimeter, s, m)

    @staticmethod
    def _pair(z):
        return np.stack([z.real, z.imag], axis=-1)

    def f(self, s) -> np.ndarray:
        """The point ``f(s) = (f1(s), f2(s))`` of Gamma_0 (3.3), natural parametrisation."""
        return self._pair(self._z(s))

    def derivative(self, s, order: int = 1) -> np.ndarray:
        """``d^order f / ds^order`` (spectral)."""
        if not isinstance(order, (int, np.integer)) or order < 0:
            raise ValueError(f"order must be an integer >= 0, got {order!r}")
        return self._pair(self._z(s, int(order)))

    def tangent(self, s) -> np.ndarray:
        """Unit tangent ``f'(s) = (cos psi, sin psi)`` (3.9)."""
        return self._pair(self._z(s, 1))

    def normal(self, s) -> np.ndarray:
        """Inward unit normal ``n0(s) = (-f2'(s), f1'(s))`` (3.3)."""
        d = self._z(s, 1)
        return self._pair(1j * d)

    def curvature(self, s) -> np.ndarray:
        """Signed curvature ``kappa = f1' f2'' - f2' f1''`` (> 0 where omega_0 is convex)."""
        d1 = self._z(s, 1)
        d2 = self._z(s, 2)
        return (np.conj(d1) * d2).imag

    def rho(self, s) -> np.ndarray:
        """Curvature radius ``rho(s) = 1/(f2'' f1' - f1'' f2')`` (after (3.6)); inf at inflections."""
        k = self.curvature(s)
        with np.errstate(divide="ignore"):
            return 1.0 / k

    def local_to_cartesian(self, s, n) -> np.ndarray:
        """``x = f(s) + n n0(s)`` (3.4): ``n`` is the signed distance along the inward normal."""
        s, n = np.broadcast_arrays(np.asarray(s, dtype=float), np.asarray(n, dtype=float))
        z = self._z(s) + n * 1j * self._z(s, 1)
        return self._pair(z)

    def g(self, s) -> np.ndarray:
        """``|grad Phi|`` on Gamma_0 at ``f(s)``."""
        p = self.f(s)
        gx, gy = self._poly.grad(p[..., 0], p[..., 1])
        return np.hypot(gx, gy)

    def b1(self, s) -> np.ndarray:
        """``b1(s) = -grad Phi(f(s)) . n0(s)``: ``delta0 - Phi(f + n n0) = b1 n + b2 n^2 + O(n^3)``.

        Dimensional form of (3.14): ``b1 = eps H_* b1^* = H b1^*`` (module docstring).  On the
        level set ``n0 = -grad Phi/|grad Phi|``, so ``b1 = g > 0``.
        """
        p = self.f(s)
        nn = self.normal(s)
        gx, gy = self._poly.grad(p[..., 0], p[..., 1])
        return -(gx * nn[..., 0] + gy * nn[..., 1])

    def b2(self, s) -> np.ndarray:
        """``b2(s) = -n0^T Hess(Phi) n0 / 2`` (dimensional form of (3.14): ``b2 = eps b2^*``)."""
        p = self.f(s)
        nn = self.normal(s)
        _, _, _, hxx, hxy, hyy = self._poly.all(p[..., 0], p[..., 1])
        n1, n2 = nn[..., 0], nn[..., 1]
        return -0.5 * (hxx * n1 * n1 + 2 * hxy * n1 * n2 + hyy * n2 * n2)

    def b_star(self, s, epsilon: float, H_s: float) -> tuple[np.ndarray, np.ndarray]:
        """The starred coefficients of (3.13)-(3.14): ``b1^* = b1/(eps H_*)``, ``b2^* = b2/eps``.

        ``s`` is the dimensional arc length (``s^* = s/H_*``).  Derived in the module docstring from
        (1.2), (2.8), (2.13): ``delta0 - Phi = eps H_*^2 (b1^* n^* + b2^* n^{*2})`` with ``n = H_* n^*``.
        """
        for nm, v in (("epsilon", epsilon), ("H_s", H_s)):
            if isinstance(v, bool) or not isinstance(v, numbers.Real) or not v > 0:
                raise ValueError(f"{nm} must be a number > 0, got {v!r}")
        return self.b1(s) / (epsilon * H_s), self.b2(s) / epsilon

    # ---- the region --------------------------------------------------------------------
    def phi(self, x1, x2) -> np.ndarray:
        """Phi(x1, x2), vectorised."""
        return self._poly.value(x1, x2)

    def contains(self, x1, x2) -> np.ndarray:
        """``delta0 - Phi(x1, x2) > 0``: membership of omega_0 (the whole set is one region)."""
        return self._poly.value(x1, x2) < self.delta0

    @property
    def is_star_shaped(self) -> bool:
        """Whether omega_0 is star-shaped about its centroid or its lowest point (used by integrate)."""
        return self._star_center is not None

    def integrate(self, F: Callable, n_radial: int = 40, n_angular: int | None = None) -> float:
        r"""``\iint_{omega_0} F(x1, x2) dx1 dx2`` for a vectorised numpy function ``F(x1, x2)``.

        Star-shaped omega_0 (about a centre c): ``x = c + lambda (f(s) - c)``,
        ``dA = lambda (f - c) x f'(s) dlambda ds``; trapezoidal rule in the periodic ``s`` (spectral)
        and Gauss-Legendre in ``u`` with ``lambda = 1 - (1 - u)^2``, which also makes integrands
        like ``sqrt(delta0 - Phi)`` or ``1/sqrt(delta0 - Phi)`` smooth at the edge.  F is only
        evaluated inside omega_0.  Otherwise Green's theorem ``iint F = oint G dx2`` with
        ``G(x1, x2) = int_{c1}^{x1} F(t, x2) dt``; then F must be smooth on the horizontal segments
        from ``x1 = c1`` to the contour (e.g. a polynomial).
        """
        if not callable(F):
            raise TypeError(f"F must be a vectorised function F(x1, x2), got {F!r}")
        if not isinstance(n_radial, (int, np.integer)) or n_radial < 2:
            raise ValueError(f"n_radial must be an integer >= 2, got {n_radial!r}")
        N = len(self.nodes)
        M = int(n_angular) if n_angular is not None else max(2 * N, 128)
        if M < 8:
            raise ValueError(f"n_angular must be >= 8, got {n_angular!r}")
        s = self.perimeter * np.arange(M) / M
        z = self._z(s)
        dz = self._z(s, 1)
        u, wu = np.polynomial.legendre.leggauss(int(n_radial))
        u = 0.5 * (u + 1.0)
        wu = 0.5 * wu
        if self._star_center is not None:
            c = complex(*self._star_center)
            lam = 1.0 - (1.0 - u) ** 2
            dlam = 2.0 * (1.0 - u)
            r = z - c
            jac = (np.conj(r) * dz).imag  # (f - c) x f'
            pts = c + lam[:, None] * r[None, :]
            vals = np.asarray(F(pts.real, pts.imag), dtype=float) * np.ones(pts.shape)
            inner = (vals * (lam * dlam * wu)[:, None]).sum(axis=0)
            return float(np.sum(inner * jac) * self.perimeter / M)
        c1 = self.centroid[0]
        x1 = z.real
        pts_x = c1 + u[:, None] * (x1 - c1)[None, :]
        pts_y = np.broadcast_to(z.imag[None, :], pts_x.shape)
        vals = np.asarray(F(pts_x, pts_y), dtype=float) * np.ones(pts_x.shape)
        G = (x1 - c1) * (vals * wu[:, None]).sum(axis=0)
        return float(np.sum(G * dz.imag) * self.perimeter / M)

    def boundary_integral(self, g: Callable, of: str = "x", n: int | None = None) -> float:
        """``oint_{Gamma_0} g ds`` by the trapezoidal rule in arc length (spectral for smooth g).

        ``of="x"``: ``g(x1, x2)`` a vectorised function of the point; ``of="s"``: ``g(s)``
        (e.g. ``contour.b1``).
        """
        if not callable(g):
            raise TypeError(f"g must be a vectorised function, got {g!r}")
        if of not in ("x", "s"):
            raise ValueError(f"of must be 'x' (g(x1, x2)) or 's' (g(s)), got {of!r}")
        M = int(n) if n is not None else max(2 * len(self.nodes), 128)
        if M < 8:
            raise ValueError(f"n must be >= 8, got {n!r}")
        s = self.perimeter * np.arange(M) / M
        if of == "s":
            vals = np.asarray(g(s), dtype=float) * np.ones(M)
        else:
            p = self.f(s)
            vals = np.asarray(g(p[:, 0], p[:, 1]), dtype=float) * np.ones(M)
        return float(np.sum(vals) * self.perimeter / M)

    def latex(self) -> str:
        """LaTeX summary: the contour equation and its measured size."""
        return (
            r"\Gamma_0:\ " + sp.latex(self.Phi) + rf" = {sp.latex(sp.Float(self.delta0, 12))}"
            rf",\quad |\Gamma_0| = {self.perimeter:.12g},\quad |\omega_0| = {self.area:.12g}"
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        acc = self.accuracy
        return [
            f"ContactContour: Gamma_0 = {{{fmt(self.Phi)} = {fmt(self.delta0)}}}   (3.3)-(3.14)",
            f"  perimeter |Gamma_0| = {fmt(self.perimeter)}, area |omega_0| = {fmt(self.area)}",
            f"  centroid ({fmt(self.centroid[0])}, {fmt(self.centroid[1])}), {len(self.nodes)} nodes",
            (f"  accuracy: distance from Gamma_0 {acc.level_distance:.1e}, arc-length speed {acc.speed_error:.1e}, "
            f"turning number {acc.turning_number:.12g}"),
        ]


# ---------------------------------------------------------------------------------------------
# the stage function
# ---------------------------------------------------------------------------------------------
def contact_contour(Phi, delta0, n: int | None = None, tol: float = 1e-12) -> ContactContour:
    r"""The leading contact area ``omega_0 = {delta0 - Phi > 0}`` and its contour Gamma_0 (3.1)-(3.14).

    Parameters
    ----------
    Phi
        The punch shape, a sympy polynomial in ``thinlayer.symbols.x1, x2`` with numeric
        coefficients (or a :class:`thinlayer.Punch` with numeric parameters, or a string).
    delta0
        The indentation depth, a number > 0.
    n : int | None
        Number of equally spaced arc-length nodes of the trigonometric interpolant (even,
        >= 16); then no accuracy is enforced (read ``.accuracy``).  Default: adaptive, doubling
        until the Fourier tail is below ``tol`` and the self-checks pass to 1e-9.
    tol : float
        Target relative size of the Fourier tail (adaptive mode).

    Returns
    -------
    ContactContour

    Raises
    ------
    ValueError
        delta0 <= 0; Phi not a polynomial in x1, x2 or with other free symbols; no contact
        (delta0 <= min Phi, the minimum is named); an unbounded region; several components
        or a hole; a level set through a critical point of Phi (not smooth); a contour more
        elongated than the supported aspect ratio 32 (longest/shortest principal axis of
        omega_0) that the arc-length Fourier series cannot represent with at most 16384 nodes
        (an ellipse needs about ``18 ratio^2``; see the module docstring).  Overall scale is
        free: the region search runs in the natural frame of Phi at delta0, so e.g.
        ``1e-70 (x1^2 + 4 x2^2)`` and ``1e30 (x1^2 + 4 x2^2)`` work alike.

    Examples
    --------
    >>> import math
    >>> from thinlayer.symbols import x1, x2
    >>> c = contact_contour(x1**2/(2*4) + x2**2/(2*1), 0.5)   # a = 2, b = 1
    >>> round(c.area / math.pi, 10)
    2.0
    """
    d0 = _as_delta0(delta0)
    expr, terms = as_polynomial(Phi)
    if n is not None and (not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 16 or n % 2):
        raise ValueError(f"n (number of contour nodes) must be an even integer >= 16, got {n!r}")
    if not (isinstance(tol, (int, float)) and 0 < tol < 1):
        raise ValueError(f"tol must be a number in (0, 1), got {tol!r}")
    P = Poly2(terms)
    if P.deg < 2 and P.deg >= 1:
        raise ValueError(f"the contact area {{delta0 - Phi > 0}} is unbounded: Phi = {expr} is linear "
                         "(a half-plane); the punch must rise in every direction")
    poly, _, best, aspect = region(P, d0, expr)
    if aspect > ASPECT_HARD:
        raise too_elongated(expr, d0, aspect)
    # the spectral work in x = ell u, Phi = d0 Phi~ (ell the size of the region): arc length scales by ell
    ell = float(np.max(np.abs(poly)))
    Ps = transformed(P, Frame(ell * np.eye(2), ell, d0))
    polys = poly / ell
    res = _nodes_by_reference(Ps, 1.0, polys, n, tol)
    acc = _accuracy(Ps, 1.0, *res) if res is not None else None
    if acc is None or (n is None and not _acceptable(acc, 1e-9)):
        alt = _nodes_by_ode(Ps, 1.0, polys, n, tol)
        if alt is not None:
            acc_alt = _accuracy(Ps, 1.0, *alt)
            if acc is None or acc_alt.speed_error < acc.speed_error:
                res, acc = alt, acc_alt
    if acc is None or (not _acceptable(acc, 1e-6) if n is None else abs(acc.turning_number - 1) > 1e-3):
        if aspect > ASPECT_MAX:
            raise too_elongated(expr, d0, aspect)
        raise RuntimeError(
            f"the spectral contour of Phi = {expr} at delta0 = {short(d0)} is inaccurate ({acc}): the contour "
            f"has features too small for {_NMAX} arc-length nodes; try a larger n"
        )
    Z, L = res[0] * ell, res[1] * ell
    N = len(Z)
    Zhat = np.fft.fft(Z)
    k, c = _sym_coeffs(Zhat)
    # area and centroid by Green's theorem (trapezoidal in s, spectral)
    dZ = _uniform_eval(Zhat, L, deriv=1)
    x, y, dx, dy = Z.real, Z.imag, dZ.real, dZ.imag
    ds = L / N
    area = 0.5 * float(np.sum(x * dy - y * dx)) * ds
    cx = 0.5 * float(np.sum(x * x * dy)) * ds / area
    cy = -0.5 * float(np.sum(y * y * dx)) * ds / area
    # a centre about which omega_0 is star-shaped (for integrate)
    star = None
    for cand in ((cx, cy), (best[1], best[2])):
        r = Z - complex(*cand)
        cross = (np.conj(r) * dZ).imag
        if P.value(*cand) < d0 and cross.min() > 1e-3 * cross.max():
            star = (float(cand[0]), float(cand[1]))
            break
    return ContactContour(
        Phi=expr, delta0=d0, perimeter=float(L), area=area, centroid=(cx, cy),
        nodes=np.column_stack([x, y]), min_point=(best[1], best[2]), min_value=best[0],
        accuracy=acc, _k=k, _c=c, _poly=P, _star_center=star,
    )


# ---------------------------------------------------------------------------------------------
# the elliptic paraboloid in closed form (3.1)
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class EllipseContour(RichDisplay):
    r"""Closed form of Gamma_0 for the elliptic paraboloid (1.1), (3.1).

    ``Phi = x1^2/(2 R1) + x2^2/(2 R2) = delta0`` is ``x1^2/a^2 + x2^2/b^2 = 1`` with
    ``a = sqrt(2 delta0 R1)`` (along x1), ``b = sqrt(2 delta0 R2)`` (along x2).  With the paper's
    ``R1 >= R2``, ``a`` is the major semi-axis and ``e^2 = 1 - b^2/a^2 = 1 - R2/R1`` (3.1).
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "3.1"

    R1: sp.Expr
    R2: sp.Expr
    delta0: sp.Expr
    a: sp.Expr
    b: sp.Expr
    e2: sp.Expr
    area: sp.Expr
    perimeter: sp.Expr

    def curvature_radius(self, x1, x2) -> sp.Expr:
        """Curvature radius at a point of the ellipse: ``a^2 b^2 (x1^2/a^4 + x2^2/b^4)^(3/2)``."""
        return self.a**2 * self.b**2 * (x1**2 / self.a**4 + x2**2 / self.b**4) ** sp.Rational(3, 2)

    def scaled_semi_axes(self) -> tuple[sp.Expr, sp.Expr]:
        """Semi-axes in the scaled coordinates xi = x/H_* (2.8) with the data (1.2), (3.1).

        Substitutes ``delta0 = eps delta0^*``, ``R_j = R_j^*/eps`` into ``a/H_*``, ``b/H_*``;
        eps cancels: ``a^* = sqrt(2 delta0^* R1^*)/H_*`` (printed (3.1) shows ``R_1``).
        Needs symbolic ``R1, R2, delta0``.
        """
        for nm, v in (("R1", self.R1), ("R2", self.R2), ("delta0", self.delta0)):
            if not isinstance(v, sp.Symbol):
                raise TypeError(f"scaled_semi_axes needs a symbolic {nm} (a sympy Symbol), got {v}")
        eps = S.epsilon
        rep = {self.delta0: eps * S.delta0_s, self.R1: S.starred(self.R1) / eps,
               self.R2: S.starred(self.R2) / eps}
        return tuple(sp.simplify(v.xreplace(rep) / S.H_s) for v in (self.a, self.b))

    def latex(self) -> str:
        return (
            rf"a = {sp.latex(self.a)},\quad b = {sp.latex(self.b)},\quad "
            rf"e^2 = {sp.latex(self.e2)} \tag{{3.1}}"
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [
            "EllipseContour: x_1**2/a**2 + x_2**2/b**2 = 1   (3.1)",
            f"  a   = {fmt(self.a)}",
            f"  b   = {fmt(self.b)}",
            f"  e^2 = {fmt(self.e2)}",
            f"  area |omega_0| = {fmt(self.area)}, perimeter |Gamma_0| = {fmt(self.perimeter)}",
        ]


def ellipse_contour(R1=None, R2=None, delta0=None) -> EllipseContour:
    """Closed-form contour of the elliptic paraboloid (1.1): semi-axes and eccentricity (3.1).

    Parameters
    ----------
    R1, R2
        Principal radii of curvature (numbers > 0 or symbols; default the symbols ``R_1, R_2``
        of :meth:`thinlayer.Punch.elliptic_paraboloid`).  The paper takes ``R1 >= R2``; numeric
        ``R1 < R2`` gives ``e^2 = 1 - R1/R2`` (major axis along x2).
    delta0
        Indentation (default the symbol ``thinlayer.symbols.delta0``).

    Examples
    --------
    >>> ellipse_contour().a
    sqrt(2)*sqrt(R_1)*sqrt(delta_0)
    >>> ellipse_contour(4, 1, sp.Rational(1, 2)).e2
    3/4
    """
    r1 = sp.Symbol("R_1", positive=True) if R1 is None else as_expr(R1)
    r2 = sp.Symbol("R_2", positive=True) if R2 is None else as_expr(R2)
    d0 = S.delta0 if delta0 is None else as_expr(delta0)
    for nm, v in (("R1", r1), ("R2", r2), ("delta0", d0)):
        if v.is_number and not (v.is_real and v > 0):
            raise ValueError(f"{nm} must be positive, got {v}")
    a = sp.sqrt(2 * d0 * r1)
    b = sp.sqrt(2 * d0 * r2)
    if (r1 - r2).is_number and (r1 - r2) < 0:
        e2 = 1 - r1 / r2
        major = b
    else:
        e2 = 1 - r2 / r1
        major = a
    per = 4 * major * sp.elliptic_e(e2)
    return EllipseContour(r1, r2, d0, a, b, e2, sp.pi * a * b, per)

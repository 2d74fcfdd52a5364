# size: one stage (3.1)-(3.14): spectral curve, round frame of elongated contours, results (region search split out)
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

Steps 4-5 run on ``Phi(ell u)/delta0 = 1`` with ``ell`` the size of the region, so their tolerances
do not depend on the units.  That is the whole representation up to the aspect ratio (longest /
shortest principal axis of omega_0, from its second moments) ``ASPECT_DIRECT = 3``.

Elongated contours.  The arc-length Fourier series of an ellipse of aspect ratio ``r`` decays like
``exp(-2 pi k rho/L)`` with tip radius ``rho = b^2/a`` and ``L ~ 4a``: about ``18 r^2`` nodes (16384
for ``r = 30``, 1.8e61 for ``r = 1e30``).  Above ``ASPECT_DIRECT`` steps 4-5 therefore run in the
round frame ``x = W w``, ``W = A S`` (``A`` of step 0, ``S = (4 M)^(1/2)`` with ``M`` the central second
moments of the region polygon in ``u``; :func:`round_frame`), where omega_0 is about the unit disk,
so ``w(sigma)``, the arc-length (``sigma``) Fourier series of the round image, needs as many nodes as
a circle-like contour whatever ``r``.  Everything in x follows from the linear map and its Jacobian:

    x(sigma) = W w(sigma),   ds = |W w'(sigma)| dsigma,   |omega_0| = det W |W^-1 omega_0|,
    d^m f/ds^m = (|x'(sigma)|^-1 d/dsigma)^m x(sigma)     (tangent (3.9), normal (3.3), curvature),

the centroid is ``W`` times that of the image.  The speed ``|W w'|`` is smooth but nearly a kink at
each tip (branch points at distance about ``1/r`` from the real sigma axis), so the trapezoidal rule
in sigma would need about ``r`` nodes for the perimeter; the arc length ``s(sigma)`` is built on
Chebyshev panels bisected towards the tips instead (:class:`_ArcLength`: a few dozen panels per
tip whatever ``r``, at most 4096), inverted by safeguarded Newton.  Area integrals keep the trapezoidal
rule in the smooth parameter sigma (``f'(s) ds = x'(sigma) dsigma``); line integrals ``oint g ds``
use Gauss-Legendre on the panels.  ``Phi(W w)/delta0`` is expanded in exact rational arithmetic
(:func:`transformed`), so a rotated elongated quadratic form, whose three terms cancel to one part in
``r^2``, gives the contour of the coefficients as given.

Limits: aspect ratio at most ``ASPECT_MAX = 1e100`` (a ValueError naming the ratio beyond it: the tip
curvature, about ``r^2/L``, and the powers of the frame lengths approach the double range).  A tip
shorter than about 1e-16 of the perimeter (an ellipse with ``r > 1e8``: ``rho = L/(4 r^2)``) lies
between adjacent doubles ``s``: the evaluators are accurate at every representable ``s``, but the peak of
the curvature there is not sampled, and line integrals of the curvature itself are not resolved.
Functions evaluated in x (``phi``, ``g``, ``b1``, ``b2``, ``contains``) of a *rotated* elongated punch lose
about ``r^2`` (``phi``) or ``r`` (gradient) units in the last place to the same cancellation.
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
from functools import lru_cache
from typing import ClassVar

import numpy as np
import sympy as sp

from .. import symbols as S
from ..display import RichDisplay, fmt
from ..normal import normal_latex
from ..parse import as_expr
from ._contour_region import (
    ASPECT_DIRECT,
    ASPECT_MAX,
    Frame,
    Poly2,
    as_polynomial,
    region,
    round_frame,
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
# elongated contours: the round frame x = W w(sigma) and the arc length s(sigma) on panels
# ---------------------------------------------------------------------------------------------
_PDEG = 16  # Chebyshev degree of the speed on one panel
_PTHETA = np.pi * np.arange(_PDEG + 1) / _PDEG
# Chebyshev-Lobatto points, with the panel ends: a near-kink between an end and the next point would leave
# every interior sample on one branch and pass unseen, the end sample sees it
_PNODES = np.cos(_PTHETA)
_PMAT = (2.0 / _PDEG) * np.cos(np.outer(np.arange(_PDEG + 1), _PTHETA))  # values -> coefficients (DCT-I)
_PMAT[:, [0, -1]] *= 0.5
_PMAT[[0, -1]] *= 0.5
_GLX, _GLW = np.polynomial.legendre.leggauss(_PDEG + 1)
#: bounded work: at most this many bisections of a panel and this many panels
_PANEL_LEVELS = 64
_PANEL_MAX = 4096


def _clenshaw(C: np.ndarray, xi: np.ndarray) -> np.ndarray:
    """``sum_k C[:, k] T_k(xi)``: one Chebyshev series per point (rows of C)."""
    b1 = np.zeros(len(xi))
    b2 = np.zeros(len(xi))
    for k in range(C.shape[1] - 1, 0, -1):
        b1, b2 = C[:, k] + 2.0 * xi * b1 - b2, b1
    return C[:, 0] + xi * b1 - b2


class _ArcLength:
    r"""The arc length ``s(sigma) = int_0^sigma |x'(t)| dt`` of a smooth closed curve and its inverse.

    ``|x'|`` is smooth and periodic, but for an elongated contour it is nearly a kink at each tip:
    the ellipse ``x = (a cos sigma, b sin sigma)`` has ``|x'| = a sqrt(sin^2 sigma + (b/a)^2 cos^2 sigma)``
    with branch points at distance ``atanh(b/a) ~ b/a`` from the real axis, so the trapezoidal rule
    converges only like ``exp(-N b/a)``.  Hence panels: the period is bisected until the Chebyshev
    interpolant of the speed (degree 16) has a tail below ``tol`` times the mean speed.  A tip then
    costs about ``log2(1e13)`` levels of two panels each, whatever the aspect ratio (beyond about
    1e6 the kink is resolved only down to where it no longer shows at the tolerance: the speed is
    within ``(b/a)^2 a`` of ``a |sin sigma|``); at most ``_PANEL_LEVELS`` bisections and
    ``_PANEL_MAX`` panels, and no splitting below ``noise`` (the rounding error of the speed itself).
    ``s`` is the Chebyshev antiderivative on each panel; its inverse is Newton's iteration on the
    panel that holds ``s`` (bisection where it does not settle).
    """

    def __init__(self, speed: Callable, period: float, tol: float = 1e-13, noise: float = 0.0):
        self.period = float(period)
        a = self.period * np.arange(16) / 16
        h = np.full(16, self.period / 16)
        done_a, done_h, done_c = [], [], []
        vbar = None
        self.resolved = True
        count = 0
        for level in range(_PANEL_LEVELS + 1):
            sig = a[:, None] + 0.5 * h[:, None] * (_PNODES + 1.0)
            vals = speed(sig.ravel()).reshape(sig.shape)
            if not np.all(np.isfinite(vals)):
                raise ValueError("the speed |dx/dsigma| of the contour is not finite (beyond the double range)")
            co = vals @ _PMAT.T
            if vbar is None:
                vbar = float(np.mean(vals))
            ok = np.max(np.abs(co[:, -3:]), axis=1) <= tol * vbar + 8.0 * noise
            if level == _PANEL_LEVELS or count + len(a) + np.count_nonzero(~ok) > _PANEL_MAX:
                self.resolved = bool(np.all(ok))
                ok[:] = True
            done_a.append(a[ok])
            done_h.append(h[ok])
            done_c.append(co[ok])
            count += int(np.count_nonzero(ok))
            a, h = a[~ok], 0.5 * h[~ok]
            if not len(a):
                break
            a, h = np.concatenate([a, a + h]), np.concatenate([h, h])
        a, h, co = np.concatenate(done_a), np.concatenate(done_h), np.concatenate(done_c)
        order = np.argsort(a)
        self.a, self.h, self.cv = a[order], h[order], co[order]
        # s on a panel: (h/2) int_{-1}^{xi} v, a Chebyshev series vanishing at xi = -1
        self.ci = np.polynomial.chebyshev.chebint(self.cv, axis=1, lbnd=-1) * (0.5 * self.h)[:, None]
        self.S0 = np.concatenate([[0.0], np.cumsum(self.ci.sum(axis=1))])
        self.length = float(self.S0[-1])

    @property
    def panels(self) -> int:
        return len(self.a)

    def s_of(self, sig) -> np.ndarray:
        """``s(sigma)`` for sigma in [0, period)."""
        sig = np.mod(np.asarray(sig, dtype=float), self.period)
        j = np.clip(np.searchsorted(self.a, sig, side="right") - 1, 0, len(self.a) - 1)
        xi = np.clip(2.0 * (sig - self.a[j]) / self.h[j] - 1.0, -1.0, 1.0)
        return self.S0[j] + _clenshaw(self.ci[j], xi)

    def sigma_of(self, s) -> np.ndarray:
        """The inverse ``sigma(s)`` (s taken modulo the length), in [0, period)."""
        s = np.mod(np.asarray(s, dtype=float).ravel(), self.length)
        j = np.clip(np.searchsorted(self.S0, s, side="right") - 1, 0, len(self.a) - 1)
        r = s - self.S0[j]
        dS = self.S0[j + 1] - self.S0[j]
        ci, cv, hh = self.ci[j], self.cv[j], 0.5 * self.h[j]
        xi = np.clip(-1.0 + 2.0 * r / np.where(dS > 0, dS, 1.0), -1.0, 1.0)
        act = np.arange(len(s))
        for _ in range(12):  # Newton (s is monotone in xi); the converged points drop out
            x = xi[act]
            with np.errstate(divide="ignore", invalid="ignore"):
                new = x - (_clenshaw(ci[act], x) - r[act]) / (hh[act] * _clenshaw(cv[act], x))
            new = np.clip(np.where(np.isfinite(new), new, x), -1.0, 1.0)
            xi[act] = new
            act = act[np.abs(new - x) > 1e-15]
            if not len(act):
                break
        bad = np.abs(_clenshaw(ci, xi) - r) > 1e-13 * np.maximum(dS, 1e-300)
        if np.any(bad):  # bisection where Newton did not settle
            lo, hi = np.full(np.count_nonzero(bad), -1.0), np.ones(np.count_nonzero(bad))
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                up = _clenshaw(ci[bad], mid) > r[bad]
                hi, lo = np.where(up, mid, hi), np.where(up, lo, mid)
            xi[bad] = 0.5 * (lo + hi)
        return self.a[j] + hh * (xi + 1.0)

    def quadrature(self, min_nodes: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Gauss-Legendre nodes sigma_q, weights (in sigma) and ``s(sigma_q)`` on the panels.

        Each panel is cut into equal parts until there are at least ``min_nodes`` nodes.
        """
        m = max(1, -(-int(min_nodes) // (self.panels * len(_GLX))))
        part = np.arange(m)
        xi = (-1.0 + (2.0 * part[:, None] + 1.0 + _GLX[None, :]) / m).ravel()  # local coordinate on [-1, 1]
        wq = np.tile(_GLW / m, m)
        P, Q = self.panels, len(xi)
        jj = np.repeat(np.arange(P), Q)
        xx = np.tile(xi, P)
        sig = self.a[jj] + 0.5 * self.h[jj] * (xx + 1.0)
        wts = 0.5 * self.h[jj] * np.tile(wq, P)
        sq = self.S0[jj] + _clenshaw(self.ci[jj], xx)
        return sig, wts, sq


class _FramedCurve:
    r"""Gamma_0 as ``x = W w(sigma)``: the round image ``w`` by its own arc-length Fourier series.

    ``W`` is the frame of :func:`round_frame` (the natural lengths of Phi times the square root of
    the region's second moments), so ``w`` traces a nearly round curve and its Fourier series needs
    as few terms as for a circle-like contour, whatever the aspect ratio of omega_0.  Everything in
    ``x`` follows by the linear map and its Jacobian: ``x^(m)(sigma) = W w^(m)(sigma)``, the speed
    ``|dx/dsigma| = |W w'|``, the arc length ``s`` by :class:`_ArcLength`, and with
    ``D = |x'|^-1 d/dsigma`` the natural derivatives ``d^m f/ds^m = D^m x`` (3.3), (3.9), evaluated from the
    Taylor coefficients in sigma (truncated power series of ``|x'|^-1``).  The first two are formed
    without cancellation between the long and the short axis: the unit tangent (3.9) is ``W t_w``
    normalised, ``t_w = (-dPhi~/dw2, dPhi~/dw1)`` the tangent of the level line of ``Phi~(w) = Phi(W w)/delta0``
    at ``w(sigma)``: an error ``e`` of the point turns it by about ``e r``, while ``W w'`` would carry ``r``
    times the interpolation error of the derivative ``w'`` (about 1e-12).  And ``f'' = kappa n0`` with
    ``kappa = det W (w' x w'')/|W w'|^3``.  Areas are
    ``det W`` times those in ``w``.
    """

    def __init__(self, W: np.ndarray, det: float, k: np.ndarray, c: np.ndarray, period: float, Pw: Poly2):
        self.W = np.asarray(W, dtype=float)
        self.det = float(det)
        self.k, self.c, self.period = k, c, float(period)
        self.Pw = Pw
        # rounding of |W w'| in the direct sum: about eps sum_k |k c_k| (2 pi/period) |W|
        wk = 2 * np.pi * np.abs(np.rint(k)) / self.period
        noise = 2.2e-16 * float(np.sum(np.abs(c) * wk)) * float(np.linalg.norm(self.W, 2))
        self.arc = _ArcLength(self.speed, self.period, noise=noise)
        self._last: tuple[np.ndarray, np.ndarray] | None = None

    def apply(self, wz: np.ndarray) -> np.ndarray:
        """``W (Re wz, Im wz)`` as a complex number."""
        u, v = wz.real, wz.imag
        W = self.W
        return (W[0, 0] * u + W[0, 1] * v) + 1j * (W[1, 0] * u + W[1, 1] * v)

    def w(self, sig, m: int = 0) -> np.ndarray:
        return _trig_eval(self.k, self.c, self.period, sig, m)

    def x(self, sig, m: int = 0) -> np.ndarray:
        """``d^m x / dsigma^m`` (complex ``x1 + i x2``)."""
        return self.apply(self.w(sig, m))

    def speed(self, sig) -> np.ndarray:
        """``|dx/dsigma| = |W w'(sigma)|``, the Jacobian of the arc length."""
        return np.abs(self.x(sig, 1))

    def _sigma(self, s: np.ndarray) -> np.ndarray:
        """``sigma(s)``, remembered for the last ``s`` (f, tangent, curvature, b1, b2 are often asked at the same s)."""
        last = self._last
        if last is not None and last[0].shape == s.shape and np.array_equal(last[0], s):
            return last[1]
        sig = self.arc.sigma_of(s)
        self._last = (s.copy(), sig)
        return sig

    def to_w(self, p) -> np.ndarray:
        return np.linalg.solve(self.W, np.asarray(p, dtype=float))

    def z(self, s, m: int = 0) -> np.ndarray:
        """``d^m f / ds^m`` at arc length ``s`` (complex), ``m >= 0``."""
        s = np.asarray(s, dtype=float)
        sig = self._sigma(s)
        if m in (1, 2):
            wz = self.w(sig)
            _, gx, gy, *_ = self.Pw.all(wz.real, wz.imag)
            t = self.apply(-gy + 1j * gx)  # W t_w
            T = t / np.abs(t)
            if m == 1:
                return T.reshape(s.shape)
            d1, d2 = self.w(sig, 1), self.w(sig, 2)
            v = np.abs(self.apply(d1))
            kappa = (self.det / v) * ((np.conj(d1) * d2).imag / v) / v
            return (kappa * 1j * T).reshape(s.shape)
        wk = 2 * np.pi * np.rint(self.k) / self.period
        # Taylor coefficients X_j = x^(j)(sigma)/j! in one pass
        C = np.stack([self.c * (1j * wk) ** j / math.factorial(j) for j in range(m + 1)], axis=1)
        X = self.apply(_trig_eval(self.k, C, self.period, sig)).T  # (m + 1, M)
        if m == 0:
            return X[0].reshape(s.shape)
        D1 = [(j + 1) * X[j + 1] for j in range(m)]  # Taylor coefficients of x'
        v = [np.abs(D1[0])]
        for j in range(1, m):  # |x'| = sqrt(x'.x'), term by term
            q = sum((D1[i] * np.conj(D1[j - i])).real for i in range(j + 1))
            v.append((q - sum(v[i] * v[j - i] for i in range(1, j))) / (2 * v[0]))
        r = [1.0 / v[0]]
        for j in range(1, m):  # 1/|x'|
            r.append(-sum(v[i] * r[j - i] for i in range(1, j + 1)) / v[0])
        g = list(X)
        for _ in range(m):  # g <- (1/|x'|) dg/dsigma
            dg = [(j + 1) * g[j + 1] for j in range(len(g) - 1)]
            g = [sum(r[i] * dg[j - i] for i in range(j + 1)) for j in range(len(dg))]
        return g[0].reshape(s.shape)

    def samples(self, M: int):
        """``M`` equally spaced sigma: ``x``, ``dx/dsigma``, the step, and ``w``, ``dw/dsigma``."""
        sig = self.period * np.arange(M) / M
        wz, dwz = self.w(sig), self.w(sig, 1)
        return self.apply(wz), self.apply(dwz), self.period / M, wz, dwz


# ---------------------------------------------------------------------------------------------
# results
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContourAccuracy:
    """Self-checks of the spectral contour (all measured between the nodes).

    For an elongated contour they are those of its round image ``w`` (``x = W w``, module docstring),
    whose arc length sigma is the parameter of the Fourier series.

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
    trailing axis of length 2.  An elongated contour (aspect ratio above 3) is held as
    ``x = W w(sigma)`` with its arc length ``s(sigma)`` (module docstring); the evaluators are the
    same functions of ``s``.

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
        :class:`ContourAccuracy` (of the round image ``w`` for an elongated contour).
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
    _framed: _FramedCurve | None = field(default=None, repr=False)

    # ---- the curve (3.3) ------------------------------------------------------------------
    def _z(self, s, m=0):
        if self._framed is not None:
            return self._framed.z(s, m)
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
        from ``x1 = c1`` to the contour (e.g. a polynomial).  An elongated contour (round frame
        ``x = W w(sigma)``, see :func:`contact_contour`) uses the same formulas in its smooth
        parameter sigma instead of ``s`` (``f'(s) ds = x'(sigma) dsigma``), with
        ``(f - c) x x'(sigma) = det W (w - w_c) x w'(sigma)``; ``n_angular`` then counts sigma nodes.
        """
        if not callable(F):
            raise TypeError(f"F must be a vectorised function F(x1, x2), got {F!r}")
        if not isinstance(n_radial, (int, np.integer)) or n_radial < 2:
            raise ValueError(f"n_radial must be an integer >= 2, got {n_radial!r}")
        N = len(self.nodes)
        M = int(n_angular) if n_angular is not None else max(2 * N, 128)
        if M < 8:
            raise ValueError(f"n_angular must be >= 8, got {n_angular!r}")
        if self._framed is None:
            s = self.perimeter * np.arange(M) / M
            z, dz, step = self._z(s), self._z(s, 1), self.perimeter / M
        else:
            z, dz, step, wz, dwz = self._framed.samples(M)
        u, wu = _gauss_legendre(int(n_radial))
        u = 0.5 * (u + 1.0)
        wu = 0.5 * wu
        if self._star_center is not None:
            c = complex(*self._star_center)
            lam = 1.0 - (1.0 - u) ** 2
            dlam = 2.0 * (1.0 - u)
            r = z - c
            if self._framed is None:
                jac = (np.conj(r) * dz).imag  # (f - c) x f'
            else:  # det W (w - w_c) x w': no cancellation between the long and the short axis
                cw = complex(*self._framed.to_w(self._star_center))
                jac = self._framed.det * (np.conj(wz - cw) * dwz).imag
            pts = c + lam[:, None] * r[None, :]
            vals = np.asarray(F(pts.real, pts.imag), dtype=float) * np.ones(pts.shape)
            inner = (vals * (lam * dlam * wu)[:, None]).sum(axis=0)
            return float(np.sum(inner * jac) * step)
        c1 = self.centroid[0]
        x1 = z.real
        pts_x = c1 + u[:, None] * (x1 - c1)[None, :]
        pts_y = np.broadcast_to(z.imag[None, :], pts_x.shape)
        vals = np.asarray(F(pts_x, pts_y), dtype=float) * np.ones(pts_x.shape)
        G = (x1 - c1) * (vals * wu[:, None]).sum(axis=0)
        return float(np.sum(G * dz.imag) * step)

    def boundary_integral(self, g: Callable, of: str = "x", n: int | None = None) -> float:
        """``oint_{Gamma_0} g ds`` by the trapezoidal rule in arc length (spectral for smooth g).

        ``of="x"``: ``g(x1, x2)`` a vectorised function of the point; ``of="s"``: ``g(s)``
        (e.g. ``contour.b1``).  An elongated contour (round frame, see :func:`contact_contour`):
        ``oint g ds = oint g |x'(sigma)| dsigma`` by Gauss-Legendre on the panels that resolve the
        speed ``|x'(sigma)|`` near the tips (``n``: at least that many nodes).
        """
        if not callable(g):
            raise TypeError(f"g must be a vectorised function, got {g!r}")
        if of not in ("x", "s"):
            raise ValueError(f"of must be 'x' (g(x1, x2)) or 's' (g(s)), got {of!r}")
        M = int(n) if n is not None else max(2 * len(self.nodes), 128)
        if M < 8:
            raise ValueError(f"n must be >= 8, got {n!r}")
        if self._framed is not None:
            sig, wts, sq = self._framed.arc.quadrature(M if n is not None else 0)
            jac = self._framed.speed(sig) * wts
            if of == "s":
                vals = np.asarray(g(sq), dtype=float) * np.ones(len(sq))
            else:
                p = self._framed.x(sig)
                vals = np.asarray(g(p.real, p.imag), dtype=float) * np.ones(len(sq))
            return float(np.sum(vals * jac))
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
            r"\Gamma_0:\ " + normal_latex(self.Phi) + rf" = {normal_latex(sp.Float(self.delta0, 12), digits=12)}"
            rf",\quad |\Gamma_0| = {self.perimeter:.12g},\quad |\omega_0| = {self.area:.12g}"
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        acc = self.accuracy
        return [
            f"ContactContour: Γ₀ = {{{fmt(self.Phi)} = {fmt(self.delta0)}}}   (3.3)-(3.14)",
            f"  perimeter |Γ₀| = {fmt(self.perimeter)}, area |ω₀| = {fmt(self.area)}",
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
        until the Fourier tail is below ``tol`` and the self-checks pass to 1e-9.  For an elongated
        contour (aspect ratio above 3) the interpolant is that of the round image ``w`` (module
        docstring); ``.nodes`` still holds ``n`` points at equal arc length of Gamma_0.
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
        or a hole; a level set through a critical point of Phi (not smooth); an aspect ratio
        (longest/shortest principal axis of omega_0) above ``ASPECT_MAX = 1e100``, beyond the
        double range.  Overall scale and elongation are free: the region search runs in the
        natural frame of Phi at delta0 and an elongated contour is represented in its round frame
        (module docstring), so ``1e-70 (x1^2 + 4 x2^2)``, ``1e30 (x1^2 + 4 x2^2)`` and
        ``1e-30 x1^2 + 1e30 x2^2`` (aspect ratio 1e30) work alike.

    Examples
    --------
    >>> import math
    >>> from thinlayer.symbols import x1, x2
    >>> c = contact_contour(x1**2/(2*4) + x2**2/(2*1), 0.5)   # a = 2, b = 1
    >>> round(c.area / math.pi, 10)
    2.0
    """
    d0 = _as_delta0(delta0)
    expr, terms = _polynomial(Phi)
    if n is not None and (not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 16 or n % 2):
        raise ValueError(f"n (number of contour nodes) must be an even integer >= 16, got {n!r}")
    if not (isinstance(tol, (int, float)) and 0 < tol < 1):
        raise ValueError(f"tol must be a number in (0, 1), got {tol!r}")
    P = Poly2(terms)
    if P.deg < 2 and P.deg >= 1:
        raise ValueError(f"the contact area {{delta0 - Phi > 0}} is unbounded: Phi = {expr} is linear "
                         "(a half-plane); the punch must rise in every direction")
    poly, _, best, aspect, fr, curve_u = region(P, d0, expr)
    if not aspect <= ASPECT_MAX:
        raise too_elongated(expr, d0, aspect)
    if aspect <= ASPECT_DIRECT:
        # the spectral work in x = ell u, Phi = d0 Phi~ (ell the size of the region): arc length scales by ell
        ell = float(np.max(np.abs(poly)))
        frame, polys, det = Frame(ell * np.eye(2), ell, d0), poly / ell, ell * ell
    else:
        # elongated: the spectral work in the round frame x = W w (step 0 of the module docstring)
        frame, polys, det = round_frame(curve_u, fr)
        kap = float(np.max(np.abs(polys)))
        frame, polys, det = Frame(frame.A * kap, frame.ell * kap, d0), polys / kap, det * kap * kap
    Ps = transformed(P, frame)
    res = _nodes_by_reference(Ps, 1.0, polys, n, tol)
    acc = _accuracy(Ps, 1.0, *res) if res is not None else None
    if acc is None or (n is None and not _acceptable(acc, 1e-9)):
        alt = _nodes_by_ode(Ps, 1.0, polys, n, tol)
        if alt is not None:
            acc_alt = _accuracy(Ps, 1.0, *alt)
            if acc is None or acc_alt.speed_error < acc.speed_error:
                res, acc = alt, acc_alt
    if acc is None or (not _acceptable(acc, 1e-6) if n is None else abs(acc.turning_number - 1) > 1e-3):
        raise RuntimeError(
            f"the spectral contour of Phi = {expr} at delta0 = {short(d0)} is inaccurate ({acc}): the contour "
            f"has features too small for {_NMAX} arc-length nodes; try a larger n"
        )
    if aspect <= ASPECT_DIRECT:
        return _direct_contour(expr, d0, P, res[0] * ell, res[1] * ell, best, acc)
    return _framed_contour(expr, d0, P, Ps, frame.A, det, res[0], res[1], best, acc)


def _polynomial(Phi) -> tuple[sp.Expr, list[tuple[int, int, float]]]:
    """:func:`as_polynomial`, kept per punch (the contour of another depth needs the same terms)."""
    try:
        expr, terms = _polynomial_cached(Phi)
    except TypeError:  # unhashable input: no cache
        return as_polynomial(Phi)
    return expr, list(terms)


@lru_cache(maxsize=256)
def _polynomial_cached(Phi) -> tuple[sp.Expr, tuple[tuple[int, int, float], ...]]:
    expr, terms = as_polynomial(Phi)
    return expr, tuple(terms)


@lru_cache(maxsize=32)
def _gauss_legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss--Legendre nodes and weights on [-1, 1] (read-only arrays, computed once per n)."""
    u, w = np.polynomial.legendre.leggauss(n)
    u.flags.writeable = False
    w.flags.writeable = False
    return u, w


def _direct_contour(expr, d0, P, Z, L, best, acc) -> ContactContour:
    """Gamma_0 by its arc-length Fourier series in x (aspect ratio up to ``ASPECT_DIRECT``)."""
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


def _framed_contour(expr, d0, P, Pw, W, det, Zw, Lw, best, acc) -> ContactContour:
    """Gamma_0 as ``x = W w(sigma)`` (elongated): w by its arc-length Fourier series in the round frame.

    Area and centroid by Green's theorem in w (spectral) and the map: ``|omega_0| = det W |w(omega_0)|``,
    the centroid is ``W`` times the centroid in w; star-shapedness is affine invariant, so it is
    tested in w.  The perimeter is :attr:`_ArcLength.length` (Jacobian ``|W w'|`` on panels).
    """
    N = len(Zw)
    Zhat = np.fft.fft(Zw)
    k, c = _trim(*_sym_coeffs(Zhat))
    fc = _FramedCurve(W, det, k, c, Lw, Pw)
    dZ = _uniform_eval(Zhat, Lw, deriv=1)
    x, y, dx, dy = Zw.real, Zw.imag, dZ.real, dZ.imag
    ds = Lw / N
    area_w = 0.5 * float(np.sum(x * dy - y * dx)) * ds
    cw = (0.5 * float(np.sum(x * x * dy)) * ds / area_w, -0.5 * float(np.sum(y * y * dx)) * ds / area_w)
    cen = fc.apply(complex(*cw))
    star = None
    for cand_x, cand_w in (((cen.real, cen.imag), cw), ((best[1], best[2]), tuple(fc.to_w((best[1], best[2]))))):
        cross = (np.conj(Zw - complex(*cand_w)) * dZ).imag
        if P.value(*cand_x) < d0 and cross.min() > 1e-3 * cross.max():
            star = (float(cand_x[0]), float(cand_x[1]))
            break
    L = fc.arc.length
    nodes = fc.z(L * np.arange(N) / N)
    return ContactContour(
        Phi=expr, delta0=d0, perimeter=L, area=det * area_w, centroid=(float(cen.real), float(cen.imag)),
        nodes=np.column_stack([nodes.real, nodes.imag]), min_point=(best[1], best[2]), min_value=best[0],
        accuracy=acc, _k=k, _c=c, _poly=P, _star_center=star, _framed=fc,
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
            rf"a = {normal_latex(self.a)},\quad b = {normal_latex(self.b)},\quad "
            rf"e^2 = {normal_latex(self.e2)} \tag{{3.1}} \\" + "\n"
            rf"|\omega_0| = {normal_latex(self.area)},\quad |\Gamma_0| = {normal_latex(self.perimeter)}"
            + (r",\quad \mathrm{E}(k) = \int_0^{\pi/2}\sqrt{1 - k^2 \sin^2\theta}\,d\theta,\ k = e"
               if self.perimeter.has(sp.elliptic_e) else "")
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [
            "EllipseContour: x₁²/a² + x₂²/b² = 1   (3.1)",
            f"  a  = {fmt(self.a)}",
            f"  b  = {fmt(self.b)}",
            f"  e² = {fmt(self.e2)}",
            f"  area |ω₀| = {fmt(self.area)}, perimeter |Γ₀| = {fmt(self.perimeter)}"
            + ("   (E(k): complete elliptic integral of the second kind, modulus k = e)"
               if self.perimeter.has(sp.elliptic_e) else ""),
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

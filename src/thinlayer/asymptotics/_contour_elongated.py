r"""Elongated contours: the round frame ``x = W w(sigma)`` and the arc length ``s(sigma)`` on panels (3.3), (3.9).

Private to :mod:`thinlayer.asymptotics.contour` (its module docstring, "Elongated contours", derives the
representation): the arc length of a smooth closed curve on Chebyshev panels bisected towards the tips
(:class:`_ArcLength`) and Gamma_0 held as the linear image of a nearly round curve (:class:`FramedCurve`).
"""
from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from .._checks import InputError
from ._contour_region import Poly2
from ._contour_spectral import trig_eval

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
                raise InputError("the speed |dx/dsigma| of the contour is not finite (beyond the double range)")
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


class FramedCurve:
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
        return trig_eval(self.k, self.c, self.period, sig, m)

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
        X = self.apply(trig_eval(self.k, C, self.period, sig)).T  # (m + 1, M)
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

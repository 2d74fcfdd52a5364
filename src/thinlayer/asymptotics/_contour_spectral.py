r"""The spectral curve of Gamma_0: equal-arc-length nodes on ``Phi = delta0`` (steps 4-5 of (3.3)).

Private to :mod:`thinlayer.asymptotics.contour` (its module docstring describes the method).  Trigonometric
series of a closed curve (coefficients with the Nyquist mode split evenly, evaluation by Horner's scheme,
derivatives, the Fourier tail), Newton onto the level set, and the two constructions of the nodes at equal
arc length: normal projection from a smooth reference curve (:func:`nodes_by_reference`) and, for contours
with small features, integration of the unit tangent field (:func:`nodes_by_ode`).
"""
from __future__ import annotations

import math

import numpy as np

from ._contour_region import Poly2, signed_area


def _wavenumbers(N: int) -> np.ndarray:
    return np.fft.fftfreq(N, 1.0 / N)


def sym_coeffs(zhat: np.ndarray):
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


def trig_eval(k: np.ndarray, c: np.ndarray, period: float, t, deriv: int = 0) -> np.ndarray:
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
    kk, cc = trim(*sym_coeffs(zhat))
    return kk, cc, 2 * np.pi


def _project_along_normals(P, delta0, kk, cc, t):
    """X(t) = C(t) + h(t) nu(t) on Phi = delta0, nu the outward normal of the reference curve C."""
    both = trig_eval(kk, np.stack([cc, 1j * kk * cc], axis=1), 2 * np.pi, t)
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


def tail(zhat: np.ndarray) -> float:
    """Largest Fourier coefficient with |k| >= 3N/8 relative to the largest one (aliasing error)."""
    N = len(zhat)
    k = np.abs(_wavenumbers(N))
    a = np.abs(zhat) / N
    return float(a[k >= 3 * N // 8].max() / max(a.max(), 1e-300))


def trim(k: np.ndarray, c: np.ndarray, rel: float = 1e-18):
    """Drop negligible Fourier coefficients (they cost time in the direct sums)."""
    keep = np.abs(c) > rel * np.abs(c).max()
    return k[keep], c[keep]


def uniform_eval(zhat: np.ndarray, period: float, shift: float = 0.0, deriv: int = 0) -> np.ndarray:
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
    speed = np.abs(uniform_eval(Xhat, 2 * np.pi, deriv=1))
    Shat = np.fft.fft(speed)
    L = 2 * np.pi * Shat[0].real / N
    s0 = Shat[0].real / N
    ks, cs = trim(*sym_coeffs(Shat))
    ci = np.where(ks != 0, cs / (1j * np.where(ks != 0, ks, 1)), 0.0)
    both = np.stack([ci, cs], axis=1)
    kw = _wavenumbers(N)
    integ = np.where((kw != 0) & (np.abs(kw) < N // 2), Shat / (1j * np.where(kw != 0, kw, 1)), 0.0)
    sn = s0 * t + np.fft.ifft(integ).real
    target = L * np.arange(N) / N
    tq = np.interp(target, np.concatenate([sn, [L]]), np.concatenate([t, [2 * np.pi]]))
    for _ in range(12):
        E = trig_eval(ks, both, 2 * np.pi, tq)
        ds = (s0 * tq + E[:, 0].real - target) / E[:, 1].real
        tq = tq - ds
        if np.max(np.abs(ds)) < 1e-14:
            break
    kX, cX = trim(*sym_coeffs(Xhat))
    Z = trig_eval(kX, cX, 2 * np.pi, tq)
    x, y = _newton_onto_level(P, delta0, Z.real, Z.imag, iters=3)
    return x + 1j * y, float(L)


NMAX = 16384


def nodes_by_reference(P, delta0, poly, n, tol):
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
        if tail(np.fft.fft(X)) <= tol:
            Z, L = _arc_length_from_X(P, delta0, X)
            if tail(np.fft.fft(Z)) <= tol:
                return Z, L
        if N >= 4096:
            return None
        N *= 2


def nodes_by_ode(P, delta0, poly, n, tol):
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
        if n is not None or tail(np.fft.fft(Z)) <= tol or N >= NMAX:
            return Z, L
        N *= 2

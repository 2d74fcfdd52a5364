"""Spectral Galerkin discretisation of the axisymmetric contact problem (:mod:`thinlayer.numerics.axisymmetric`).

With ``x = r/c`` the pressure is expanded in the flat-punch basis
``psi_n(x) = (1 - x^2)^{-1/2} P_n^{(0,-1/2)}(1 - 2 x^2)``, whose Hankel transforms are
``beta_n j_{2n}(b)``; the half-space part of the Galerkin matrix is diagonal (Weber-Schafheitlin), the
layer correction ``L - 1`` (2.4) is integrated by composite Gauss-Legendre quadrature.  Every array is in
the basis normalised by ``sqrt(d_n)``, ``d_n`` the half-space diagonal.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from .._lazy import lazy_module
from ..layers.kernels import LayerKernel
from ._layer import GAUSS, U_MAX, gauss_panels, panel_count

special = lazy_module("scipy.special")  # scipy imported on first use

__all__ = ["Discretisation", "RadialLoad", "basis_transform", "beta", "correction_displacement", "half_space_diagonal",
           "pressure_function", "sample_radii", "spherical_jn_even"]


# --------------------------------------------------------------------------- basis
def beta(n: np.ndarray) -> np.ndarray:
    """``beta_n = Gamma(n + 1/2)/(sqrt(pi) n!) = P_n^{(0,-1/2)}(-1) (-1)^n``."""
    return np.exp(special.gammaln(n + 0.5) - special.gammaln(n + 1.0)) / math.sqrt(math.pi)


def basis_transform(n: int, b: np.ndarray) -> np.ndarray:
    """``int_0^1 psi_n(x) J0(b x) x dx = beta_n j_{2n}(b)`` (unnormalised basis)."""
    return beta(np.array(float(n))) * special.spherical_jn(2 * n, np.asarray(b, dtype=float))


def half_space_diagonal(n: np.ndarray) -> np.ndarray:
    """``d_n = int_0^oo (beta_n j_2n(t))^2 dt = beta_n^2 pi / (2 (4n + 1))`` (Weber-Schafheitlin)."""
    return beta(n) ** 2 * math.pi / (2.0 * (4.0 * n + 1.0))


def spherical_jn_even(t: np.ndarray, modes: int) -> np.ndarray:
    """``j_2n(t_k)`` for ``n < modes``, shape (len(t), modes), for ``t > 0``: recurrences over the order.

    ``j_{k-1} + j_{k+1} = (2k+1)/t j_k``.  Upward from ``j_0 = sin t/t``, ``j_1 = (sin t/t - cos t)/t`` where
    ``t >= 2 (modes - 1)`` (every order oscillatory: stable, absolute error ~1e-16); downward (Miller) for the
    other nodes, started far beyond the largest order, rescaled against overflow and normalised by
    ``j_0, j_1``.  Against mpmath both are as accurate as :func:`scipy.special.spherical_jn` or more, and 20x
    faster than it on the quadrature of a thin layer (c/H = 80: 10^4 nodes x 84 modes).
    """
    t = np.asarray(t, dtype=float)
    out = np.empty((t.size, modes))
    K = 2 * (modes - 1)
    up = t >= max(K, 1)
    if up.any():
        out[up] = _upward_even(t[up], modes)
    if not up.all():
        out[~up] = _miller_even(t[~up], modes)
    return out


def _j01(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    s, c = np.sin(t), np.cos(t)
    return s / t, (s / t - c) / t


def _upward_even(t: np.ndarray, modes: int) -> np.ndarray:
    out = np.empty((t.size, modes))
    prev, cur = _j01(t)
    out[:, 0] = prev
    for k in range(1, 2 * (modes - 1)):
        prev, cur = cur, (2 * k + 1) / t * cur - prev  # cur = j_{k+1}
        if k % 2:
            out[:, (k + 1) // 2] = cur
    return out


def _miller_even(t: np.ndarray, modes: int) -> np.ndarray:
    K = 2 * (modes - 1)
    start = K + 60 + int(6 * (K + 1) ** (1 / 3))  # beyond the turning point t < K: the decay is super-exponential
    out = np.zeros((t.size, modes))
    nxt, cur = np.zeros_like(t), np.full_like(t, 1e-150)  # f_{k+1}, f_k: a multiple of j_k
    for k in range(start, 0, -1):
        if k <= K and k % 2 == 0:
            out[:, k // 2] = cur
        nxt, cur = cur, (2 * k + 1) / t * cur - nxt
        big = np.abs(cur) > 1e140
        if big.any():
            s = np.where(big, 1e-140, 1.0)
            cur *= s
            nxt *= s
            out *= s[:, None]
    out[:, 0] = cur
    j0, j1 = _j01(t)
    norm = (cur * j0 + nxt * j1) / (cur * cur + nxt * nxt)  # least squares on the two known orders
    return out * norm[:, None]


def _normalised_transforms(t: np.ndarray, modes: int, scale: np.ndarray) -> np.ndarray:
    """``g~_n(t_k) = beta_n j_2n(t_k)/sqrt(d_n)``, shape (len(t), modes)."""
    n = np.arange(modes, dtype=float)
    return spherical_jn_even(t, modes) * (beta(n) / scale)[None, :]


# --------------------------------------------------------------------------- Galerkin system
@dataclass(frozen=True)
class Discretisation:
    """Fixed modes and t-quadrature, valid for contact radii in [c_lo, c_hi]."""

    layer: LayerKernel
    H: float
    modes: int
    c_lo: float
    c_hi: float
    t: np.ndarray = field(repr=False)
    w: np.ndarray = field(repr=False)
    G: np.ndarray = field(repr=False)  # normalised transforms g~_n(t_k), shape (nt, modes)
    scale: np.ndarray = field(repr=False)  # sqrt(d_n)
    s: np.ndarray = field(repr=False)  # edge-singularity functional in the normalised basis
    xq: np.ndarray = field(repr=False)  # quadrature abscissae x_k = sin(theta_k) in [0, 1]
    Pq: np.ndarray = field(repr=False)  # w_k P_m(cos 2 theta_k) x_k / sqrt(d_m), shape (modes, nq)

    @classmethod
    def build(cls, layer: LayerKernel, H: float, modes: int, c_lo: float, c_hi: float) -> Discretisation:
        """Quadrature in t on ``[0, U_MAX c_hi/H]`` (panels ``<= min(3, c_lo/(2H))``) and in x for the load."""
        n = np.arange(modes, dtype=float)
        scale = np.sqrt(half_space_diagonal(n))
        if not layer.has_thickness:  # L = 1: the half-space part alone, no correction
            t = w = np.zeros(0)
            G = np.zeros((0, modes))
        else:
            T = U_MAX * c_hi / H
            t, w = gauss_panels(T, panel_count(T, min(3.0, 0.5 * c_lo / H)))
            G = _normalised_transforms(t, modes, scale)
        s = (-1.0) ** n * beta(n) / scale
        # F_m = int_0^1 psi_m(x) f(c x) x dx = int_0^{pi/2} P_m(cos 2 th) f(c sin th) sin th d th  (x = sin th):
        # a smooth integrand, Gauss-Legendre in th (more accurate than Gauss-Jacobi nodes from scipy)
        nq = 2 * modes + 48
        xg, wg = special.roots_legendre(nq)
        th = 0.25 * math.pi * (xg + 1.0)
        xq = np.sin(th)
        P = special.eval_jacobi(np.arange(modes)[:, None], 0.0, -0.5, np.cos(2 * th)[None, :])
        Pq = P * (0.25 * math.pi * wg * xq)[None, :] / scale[:, None]
        return cls(layer, H, modes, c_lo, c_hi, t, w, G, scale, s, xq, Pq)

    def matrix(self, c: float) -> np.ndarray:
        """Normalised Galerkin matrix I + C~(c) (half-space part is the identity)."""
        M = np.eye(self.modes)
        # the nodes up to u = t H/c = U_MAX, where the rule was cut for c = c_hi: beyond, |L - 1| < 1e-18
        k = int(np.searchsorted(self.t, U_MAX * c / self.H, side="right"))
        if k:
            lm1 = np.asarray(self.layer.L_numeric(self.t[:k] * (self.H / c), "numpy"), dtype=float) - 1.0
            # G^T diag(w (L - 1)) G by BLAS (4x einsum's plain loop: nt x modes^2 = 7e7 at c/H = 80)
            G = self.G[:k]
            M += (G.T * (self.w[:k] * lm1)[None, :]) @ G
        return M

    def solve(self, c: float, phi: Callable[[np.ndarray], np.ndarray]) -> tuple[float, np.ndarray, np.ndarray]:
        """Return (delta0(c), x~_1, x~_Phi): with S = 0, x~ = (vartheta/c)(delta0 x~_1 - x~_Phi)."""
        M = self.matrix(c)
        F1 = np.zeros(self.modes)
        F1[0] = 1.0 / self.scale[0]  # int psi_0 x dx = beta_0 j_0(0) = 1
        tail = 0.0
        if isinstance(phi, RadialLoad):  # a tip of revolution: graded load and the edge functional's tail
            FPhi, full = phi.loads(c, self.scale)
            if full is not None:
                tail = full - float(self.s @ FPhi)
        else:
            FPhi = self.Pq @ phi(c * self.xq)
        sol = np.linalg.solve(M, np.column_stack([F1, FPhi]))
        x1, xP = sol[:, 0], sol[:, 1]
        den = self.s @ x1
        if den == 0:
            raise ArithmeticError("degenerate edge condition")
        return float((self.s @ xP + tail) / den), x1, xP


# --------------------------------------------------------------------------- the load of a tip that is not a polynomial
#: geometric panels towards an apex, each 4x narrower (innermost ``~(pi/2) 4^-20 ~ 1e-12``): with 6 levels the power
#: law ``r^1.5`` kept a mode-independent error of 7.3e-11 in P against Sneddon's closed form (its slope ``~ th^{1/2}``
#: on the innermost panel); with 20 levels it is at rounding, 336 more load nodes
GRADING_LEVELS = 20

@dataclass(frozen=True)
class RadialLoad:
    r"""The profile of a tip of revolution for the load vector, with what makes it accurate at an apex or a join.

    ``F_m = int_0^{pi/2} P_m(cos 2 th) Phi(c sin th) sin th d th`` is integrated by composite Gauss-Legendre in
    ``th``, split at ``th_b = asin(r_b/c)`` for the radii ``r_b`` where Phi'' jumps (``breaks``, the blunted cone's
    join) and graded geometrically towards ``th = 0`` (``graded``, an apex), so that each panel has a smooth
    integrand.  The panels depend on c, so the load is rebuilt for each radius.

    The edge functional ``S[Phi] = sum_n s_n F_n`` converges only algebraically for a profile that is not a
    polynomial in ``r^2`` (the cone: ``F_n ~ n^{-5/2}``, measured error of delta0 ``~N^{-1.5}``: 1e-4 at 320 modes).
    Its infinite sum is known in closed form: for the half-space (``M = I``) ``S[Phi]/S[1]`` is the depth of the
    half-space, ``D(c) = int_0^{pi/2} c Phi'(c sin th) d th`` (Copson's edge condition,
    :mod:`thinlayer.validation.sneddon`).  With a layer, ``x = M^{-1} F = F - M^{-1} C F`` and ``C`` couples mode n
    only through ``L(t H/c) - 1`` at ``t > 2n``, a factor ``~exp(-4 n H/c)``: the truncation error sits in
    ``s . F`` alone, and :meth:`tail` returns the missing ``sum_{n >= N} s_n F_n = S[1] D(c) - sum_{n < N} s_n F_n``.
    """

    phi: Callable[[np.ndarray], np.ndarray]
    slope: Callable[[np.ndarray], np.ndarray] | None
    breaks: tuple[float, ...] = ()
    graded: bool = False
    rim: float = math.inf

    def __call__(self, rr: np.ndarray) -> np.ndarray:
        return self.phi(rr)

    def edges(self, c: float) -> tuple[float, ...]:
        """The panel ends in ``th`` on ``[0, pi/2]``: the breaks' angles and the apex grading (class docstring)."""
        edges = {0.0, 0.5 * math.pi}
        edges.update(math.asin(b / c) for b in self.breaks if 0.0 < b < c)
        if self.graded:
            first = min(e for e in edges if e > 0)
            edges.update(first * 4.0 ** -j for j in range(1, GRADING_LEVELS + 1))
        return tuple(sorted(edges))

    def loads(self, c: float, scale: np.ndarray) -> tuple[np.ndarray, float | None]:
        """``(F~_Phi, S[1] D(c))``: the normalised projections and the edge functional's infinite sum (None
        without a slope).
        """
        modes = scale.size
        _, w, xq, P = _load_quadrature(self.edges(c), modes)
        F = (P @ (w * xq * self.phi(c * xq))) / scale
        if self.slope is None:
            return F, None
        D = float(np.sum(w * c * self.slope(c * xq)))
        return F, D / scale[0] ** 2  # S[1] = s_0 F1_0 = 1/d_0


@lru_cache(maxsize=64)
def _legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    return special.roots_legendre(n)


@lru_cache(maxsize=16)
def _load_quadrature(edges: tuple[float, ...], modes: int) -> tuple[np.ndarray, ...]:
    """``(th, w, sin th, P_m(cos 2 th))`` of :meth:`RadialLoad.loads` for these panel ends and modes, read-only.

    The panels depend on c only through a break (the blunted cone's join): for a cone, a power law or the exact
    sphere every radius of a solve (the bracketing and Brent's method, about 15 per solve) uses the same nodes, and
    the Jacobi polynomials at them (``eval_jacobi`` on modes x nodes, most of a load's cost) are computed once.
    """
    half = 0.5 * math.pi
    total = 2 * modes + 48
    th, w = [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        n = max(24, math.ceil(total * (hi - lo) / half))
        xg, wg = _legendre(n)
        th.append(0.5 * (hi - lo) * (xg + 1.0) + lo)
        w.append(0.5 * (hi - lo) * wg)
    th, w = np.concatenate(th), np.concatenate(w)
    xq = np.sin(th)
    P = special.eval_jacobi(np.arange(modes)[:, None], 0.0, -0.5, np.cos(2 * th)[None, :])
    for a in (th, w, xq, P):
        a.setflags(write=False)
    return th, w, xq, P


# --------------------------------------------------------------------------- the pressure and its displacement
def pressure_function(coef: np.ndarray, c: float) -> Callable[[np.ndarray], np.ndarray]:
    """p(r) from the normalised coefficients, free of cancellation at the edge.

    ``p = sqrt(2) (1+y)^{-1/2} Q(y)`` with ``Q = sum_n x~_n P_n^{(0,-1/2)}(y)/sqrt(d_n)`` and ``y = 1 - 2 r^2/c^2``;
    the edge condition Q(-1) = 0 lets us write ``p = sqrt(2 (1+y)) R(y)`` with the polynomial
    ``R = Q/(1+y)``, built by Chebyshev interpolation at interior nodes (no division near y = -1).
    """
    N = coef.size
    n = np.arange(N)
    a = coef / np.sqrt(half_space_diagonal(n.astype(float)))

    def Q(y: np.ndarray) -> np.ndarray:
        return special.eval_jacobi(n[:, None], 0.0, -0.5, np.asarray(y)[None, :]).T @ a

    Rcheb = np.polynomial.chebyshev.Chebyshev.interpolate(lambda yy: Q(yy) / (1.0 + yy), max(N - 2, 1))

    def p(r: np.ndarray) -> np.ndarray:
        x = np.abs(np.asarray(r, dtype=float)) / c
        out = np.zeros_like(x)
        inside = x < 1.0
        y = 1.0 - 2.0 * x[inside] ** 2
        out[inside] = np.sqrt(2.0 * (1.0 + y)) * Rcheb(y)
        return out

    return p


def sample_radii(c: float, npts: int = 201) -> np.ndarray:
    """Radii on [0, c], clustered at the edge."""
    return c * np.sin(np.linspace(0.0, 0.5 * math.pi, npts))


def correction_displacement(layer: LayerKernel, H: float, coef: np.ndarray, c: float, vartheta: float,
                            r: np.ndarray) -> np.ndarray:
    """The layer's correction ``(1/vartheta) int_0^oo pbar(a) (L(aH) - 1) J0(a r) da`` to u3 at radii ``r``.

    ``pbar(t/c) = c^2 sum_n coef_n beta_n j_2n(t)/sqrt(d_n)``, ``da = dt/c``; quadrature in t on
    ``[0, U_MAX c/H]`` with panels short against both the kernel scale and the J0 period.
    """
    N = coef.size
    n = np.arange(N, dtype=float)
    scale = np.sqrt(half_space_diagonal(n))
    T = U_MAX * c / H
    t, w = gauss_panels(T, panel_count(T, min(1.0, 0.5 * c / H, 0.5 * c / max(float(r.max()), c))), GAUSS)
    pbar = c**2 * _normalised_transforms(t, N, scale) @ coef
    lm1 = np.asarray(layer.L_numeric(t * H / c, "numpy"), dtype=float) - 1.0
    return (special.j0(np.outer(r, t) / c) @ (w * pbar * lm1)) / (c * vartheta)

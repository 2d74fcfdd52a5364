r"""Maugis-Dugdale adhesion of an axisymmetric punch on a layer, solved with the exact kernel (D.1)-(D.9).

Equation tags ``D.n`` are this module's own.  Assumptions: frictionless contact, the layer bonded to (or lying on) a
rigid base as its kernel ``L(u)`` (2.3) says, and Dugdale's cohesive law (Maugis 1992): outside the contact disc
``r < c`` the surfaces attract each other with the constant tension ``sigma0`` while their separation is below
``h0``, i.e. on the annulus ``c < r < b`` whose outer radius ``b`` is where the separation reaches ``h0``; the work
of adhesion is ``w = sigma0 h0``.

Derivation (own; Copson's representation of :mod:`thinlayer.numerics.flat_punch`, on the whole loaded disc r < b)
-------------------------------------------------------------------------------------------------------------------
(D.1) *Representation.*  The pressure ``p`` (tensile < 0) is carried by ``r < b``.  With ``pbar(alpha) =
int_0^b phi(t) cos(alpha t) dt`` (F.3), ``phi(t) = (2/pi) int_t^b r p(r)/sqrt(r^2 - t^2) dr``, and
``u3(r) = (2/pi) int_0^r G(s)/sqrt(r^2 - s^2) ds`` for every ``r`` (F.4), where by (F.5)
``vartheta G(s) = (pi/2) phi(s) - int_0^b K(s, t) phi(t) dt``, ``K = int_0^oo (1 - L(alpha H)) cos(alpha s)
cos(alpha t) d alpha``.  Scaled (``s = c x``, ``phi(c y) = (2 vartheta/pi) F(y)``, ``lambda = c/H``, ``m = b/c``)::

    G(c x) = F(x) - int_0^m k(x, y) F(y) dy,        k of (F.6), on 0 <= x <= m.

(D.2) *The cohesive zone.*  On ``c < r < b``, ``p = -sigma0``, so for ``1 < y < m``
``F(y) = -s sqrt(m^2 - y^2)``, ``s = sigma0 c/vartheta``, known; ``F = 0`` beyond ``m`` (``phi(b) = 0``: no
singularity at ``b``).  On ``0 <= x <= 1`` the contact condition ``u3 = delta - Phi`` is Abel's (F.11),
``G = delta - h(c x)``, ``h(s) = s int_0^{pi/2} Phi'(s sin theta) d theta``.  Hence, on ``[0, 1]``::

    f - k f = delta - h(c x) - s k S,     S(y) = sqrt(m^2 - y^2) on (1, m), 0 on (0, 1),
    f = delta f_1 - f_Phi - s f_D                                                                (D.3)

(``f_1`` the flat punch's solution of (F.6), ``(1 - k) f_Phi = h(c x)``, ``(1 - k) f_D = k S``: all three are
smooth, so the collocation of (F.6) applies to each).

(D.4) *Bounded stress at the contact edge.*  A jump of ``phi`` at ``t = c`` puts ``jump/sqrt(c^2 - r^2)`` into
``p`` (F.3); the stress is bounded (the Dugdale condition at c) iff ``phi`` is continuous:
``f(1) = -s sqrt(m^2 - 1)``, i.e.

    delta = [f_Phi(1) + s (f_D(1) - sqrt(m^2 - 1))]/f_1(1).

(D.5) *Force.*  ``P = 2 pi pbar(0) = 2 pi int_0^b phi dt``::

    P = 4 vartheta c (delta kappa - int_0^1 f_Phi - s int_0^1 f_D) - 2 sigma0 c^2 [m^2 arccos(1/m) - sqrt(m^2 - 1)].

(D.6) *Separation at b.*  By Abel, ``delta = (2/pi) int_0^b delta/sqrt(b^2 - s^2) ds`` and
``Phi(b) = (2/pi) int_0^b h(s)/sqrt(b^2 - s^2) ds``; the contact part ``s < c`` cancels and the separation
``u3(b) - delta + Phi(b)`` is ``(2/pi) int_c^b (G(s) - delta + h(s))/sqrt(b^2 - s^2) ds``::

    h0 = (2/pi) [ -s (m - 1) - delta arccos(1/m) + int_0^{theta_1} h(c m cos theta) d theta
                  - int_0^oo (2/pi)(1 - L(t/lambda)) W(t) Fhat(t) dt ],         theta_1 = arccos(1/m),

with ``W(t) = int_1^m cos(t x)/sqrt(m^2 - x^2) dx = int_0^{theta_1} cos(t m cos theta) d theta`` and
``Fhat(t) = int_0^m F cos(t y) dy = sum_j a_j (-1)^j j_2j(t) - s Shat(t)``, ``Shat(t) = int_0^{theta_1}
m^2 sin^2 theta cos(t m cos theta) d theta`` (``y = m cos theta``), ``f = sum_j a_j P_2j``.

(D.7) *The half-space* (``k = 0``): ``f = delta - h(c x)`` and (D.4)-(D.6) are closed forms; for the paraboloid they
are Maugis's (1992) three equations, derived symbolically from (D.3)-(D.6) by :func:`half_space_equations` (and
compared with the equations as printed in tests/adhesion/test_cohesive.py).

(D.8) *Tabor and Maugis parameters.*  ``mu_T = (R w^2/(E*^2 h0^3))^{1/3}`` with ``E* = 2 vartheta``, ``R`` the
radius of curvature at the apex, and the Dugdale range ``h0`` (not the Lennard-Jones spacing ``z0``); Maugis's
``lambda = 2 sigma0 (R/(pi w K^2))^{1/3}``, ``K = 4 E*/3``, is then ``lambda = 2 (9/(16 pi))^{1/3} mu_T
= 1.1272 mu_T`` (with ``h0 = 0.971 z0`` matched to Lennard-Jones, Maugis's ``1.16 mu_T(z0)``).  Both are the
half-space's (the layer changes the compliance, not the definition).

(D.9) *States.*  At fixed ``c`` the separation (D.6) is solved for ``m > 1`` (Brent's method); the state's depth and
force follow from (D.4), (D.5).  At a prescribed depth or force, ``c`` is found by Brent's method on the stable
branch (the largest c with that depth or force).  Pull-off (load control): the minimum of ``P(c)``.

(D.10) *Any punch, on the grid of* :func:`~thinlayer.numerics.solve_2d`.  The traction is ``p - sigma0 chi_Z``
with ``chi_Z`` the (fractional) cells whose separation is below ``h0``, contact included, and ``p >= 0`` the
compressive part solved by the contact-set iteration with ``q = -sigma0 chi_Z`` as a prescribed surface load
(``solve_2d(surface_load=)``); ``Z`` by a fixed point (:func:`maugis_dugdale_2d`).  Checked against (D.3)-(D.9) for
the sphere (tests/adhesion/test_cohesive_2d.py).

Pull-off on the layer (measured; sphere, bonded layer nu = 0.3, ``w/(E* R) = 0.01``, ``-P_off/(pi w R)``)
-------------------------------------------------------------------------------------------------------
``lambda`` is the half-space's (D.8).  Refinement (1.5 n nodes) changes every entry by < 2e-14; at large lambda
``P_MD - P_JKR ~ lambda^-2`` and the Richardson value of lambda = 10, 20 equals the JKR direct solver's pull-off
(:func:`~thinlayer.numerics.adhesion.jkr_curve`) to 3e-6 - 4e-6 (tests/adhesion/test_cohesive.py, SLOW)::

    H/R    lambda=0.1   lambda=1     lambda=10    lambda=20    JKR solver   Richardson(10, 20) - JKR
    inf    1.95059489   1.60073491   1.50162486   1.50040866   1.50000000   3.3e-6
    3      1.95211938   1.60186144   1.50264595   1.50142865   1.50101962   3.3e-6
    1      1.96898265   1.62588005   1.52467122   1.52343013   1.52301312   3.3e-6
    0.3    1.99412040   1.83871660   1.72783850   1.72635988   1.72586276   4.2e-6
    0.1    1.99907360   1.99050787   1.89912885   1.89722325   1.89658379   4.3e-6

A thin layer makes the contact stiffer: at a fixed lambda the pull-off moves toward DMT's 2 (H/R = 0.1, lambda = 1).

Discretisation and error
------------------------
The collocation of (F.6) with ``n`` nodes (default ``ceil(4 sqrt(c/H)) + 16``), its t-rule for ``f_1``, ``f_Phi``,
``f_D``; the m-dependent sums of (D.6) on a composite 16-point t-rule with panels no longer than
``min(6/(2^k + 1), lambda/2)``, ``2^k >= m`` (frequencies up to ``m + 1``), and ``W``, ``Shat`` by a composite
Gauss-Legendre rule in theta (``m <= 2``) or by the complements of their closed forms on ``[0, m]`` (``m > 2``), with
4 radians of phase per panel (:func:`_zone_transforms`).  The error estimate is
the change of depth and force against a run with ``0.7 n`` nodes and coarser rules, never below 1e-12 relative.
Measured (sphere, lambda = 1, c/H = 10, bonded nu = 0.3 and incompressible): the error against 60 nodes falls by
20-30 per two nodes (exponential convergence) from 1.4e-5 at 8 nodes to 3e-14 at 20; the estimate exceeds it by
4-700 times (at rounding level, 24 nodes and more, it is the floor).
"""
from __future__ import annotations

import math
import numbers
import warnings
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .._checks import InputError, InputTypeError, check_int, positive
from .._lazy import lazy_module
from ..display import RichDisplay
from ..layers.kernels import LayerKernel
from ._layer import U_MAX, numeric_layer_nu
from .axisymmetric import radial_profile
from .flat_punch import MAX_A_OVER_H, MAX_NODES, check_numeric_layer, collocation_operator, even_bessel_transforms

special, optimize = (lazy_module(f"scipy.{m}") for m in ("special", "optimize"))

__all__ = ["Cohesive2D", "CohesiveState", "half_space_equations", "maugis_dugdale", "maugis_dugdale_2d",
           "maugis_lambda", "mean_radius", "pull_off", "tabor_parameter"]

#: relative floor of the error estimates (rounding of the collocation and the quadratures)
ROUNDING_FLOOR = 1e-12
#: Maugis's lambda over Tabor's mu_T (both with the Dugdale range h0): 2 (9/(16 pi))^(1/3)  (D.8)
LAMBDA_OVER_TABOR = 2.0 * (9.0 / (16.0 * math.pi)) ** (1.0 / 3.0)


# --------------------------------------------------------------------------- parameters (D.8)
def tabor_parameter(R: float, E_star: float, w: float, h0: float) -> float:
    """Tabor's ``mu_T = (R w^2/(E*^2 h0^3))^{1/3}`` with the Dugdale range ``h0`` (D.8)."""
    return (R * w * w / (E_star * E_star * h0**3)) ** (1.0 / 3.0)


def maugis_lambda(R: float, E_star: float, w: float, h0: float) -> float:
    """Maugis's ``lambda = 2 sigma0 (R/(pi w K^2))^{1/3}``, ``sigma0 = w/h0``, ``K = 4 E*/3`` (D.8)."""
    K = 4.0 * E_star / 3.0
    return 2.0 * (w / h0) * (R / (math.pi * w * K * K)) ** (1.0 / 3.0)


# --------------------------------------------------------------------------- (D.7) the half-space, symbolically
@lru_cache(maxsize=1)
def half_space_equations() -> dict[str, sp.Expr]:
    r"""Maugis's three equations for the paraboloid on the half-space, derived from (D.3)-(D.6) with ``k = 0``.

    The profile ``Phi = r^2/(2R)`` gives ``h(s) = s int_0^{pi/2} Phi'(s sin theta) d theta`` (F.11); with ``k = 0``,
    ``f = delta - h(c x)``; the edge condition (D.4), the force (D.5) and the separation (D.6) are integrated by
    sympy and written in Maugis's variables ``A = c/(pi w R^2/K)^{1/3}``, ``Pbar = P/(pi w R)``,
    ``dbar = delta/(pi^2 w^2 R/K^2)^{1/3}``, ``lambda = 2 sigma0 (R/(pi w K^2))^{1/3}``, ``K = 4 E*/3 =
    8 vartheta/3``, ``w = sigma0 h0``.

    Returns
    -------
    dict
        ``{"delta": dbar(A, m, lambda), "force": Pbar(A, m, lambda), "gap": the separation equation's left side,
        equal to 1 (D.6)}``, sympy expressions in the symbols ``A, m, lambda`` (all positive, ``m > 1``).
    """
    A, m, lam = sp.symbols("A m lambda", positive=True)
    R, w, vt, c, s_, th, x, rr, delta = sp.symbols("R w vartheta c s theta x r delta", positive=True)
    K = sp.Rational(8, 3) * vt
    Phi = rr**2 / (2 * R)
    h = sp.simplify(s_ * sp.integrate(sp.diff(Phi, rr).subs(rr, s_ * sp.sin(th)), (th, 0, sp.pi / 2)))  # (F.11)
    sigma0 = lam / 2 * (sp.pi * w * K**2 / R) ** sp.Rational(1, 3)
    sc = sigma0 * c / vt
    f = delta - h.subs(s_, c * x)  # (D.3) with k = 0
    d_edge = sp.solve(sp.Eq(f.subs(x, 1), -sc * sp.sqrt(m**2 - 1)), delta)[0]  # (D.4)
    b = m * c
    # int_c^b sqrt(b^2 - t^2) dt with t = b cos(theta)
    zone = sp.integrate((b * sp.sin(th)) * b * sp.sin(th), (th, 0, sp.acos(1 / m)))
    P = 4 * vt * c * sp.integrate(f, (x, 0, 1)) - 4 * sigma0 * zone  # (D.5): 2 pi int phi, phi_D = -(2/pi) s0 ...
    # (D.6): x = m cos(theta) on (1, m); F = -s sqrt(m^2 - x^2)
    integrand = (-sc * m * sp.sin(th) - delta + h.subs(s_, c * m * sp.cos(th)))
    gap = 2 / sp.pi * sp.integrate(sp.expand(integrand), (th, 0, sp.acos(1 / m)))
    c_of_A = A * (sp.pi * w * R**2 / K) ** sp.Rational(1, 3)
    d_unit = (sp.pi**2 * w**2 * R / K**2) ** sp.Rational(1, 3)
    h0 = w / sigma0
    out = {}
    for key, expr, unit in (("delta", d_edge, d_unit), ("force", P.subs(delta, d_edge), sp.pi * w * R),
                            ("gap", gap.subs(delta, d_edge), h0)):
        e = sp.expand(sp.powsimp(sp.expand((expr / unit).subs(c, c_of_A)), force=True))
        out[key] = sp.simplify(e)
    return out


# --------------------------------------------------------------------------- the punch's Abel load h(s) (F.11)
def _slope_of(punch: Any) -> tuple[Any, float]:
    """``(Phi'(r) vectorised, R)``: the slope of an axisymmetric polynomial punch and its apex radius of curvature."""
    try:
        prof = radial_profile(punch)
    except (InputError, InputTypeError):
        raise
    rr = sp.Symbol("r", nonnegative=True)
    prof = prof.xreplace({sym: rr for sym in prof.free_symbols})
    d1 = sp.diff(prof, rr)
    curv = float(sp.diff(prof, rr, 2).subs(rr, 0))
    if not curv > 0 or sp.expand(d1).subs(rr, 0) != 0:
        raise InputError(f"the Maugis-Dugdale solver needs a smooth punch with a rounded apex (Phi''(0) > 0), got "
                         f"Phi(r) = {prof}")
    fn = sp.lambdify(rr, d1, "numpy")

    def slope(x: np.ndarray) -> np.ndarray:
        return np.broadcast_to(np.asarray(fn(np.asarray(x, dtype=float)), dtype=float), np.shape(x))

    return slope, 1.0 / curv


def _h(slope: Any, s: np.ndarray) -> np.ndarray:
    """``h(s) = s int_0^{pi/2} Phi'(s sin theta) d theta`` (F.11) by the 40-point Gauss-Legendre rule in theta (the
    slope of a polynomial punch is smooth and odd: no apex grading needed; equal to
    :func:`~thinlayer.numerics.revolution.abel_load` to rounding, tested).
    """
    s = np.atleast_1d(np.asarray(s, dtype=float))
    xg, wg = _legendre(40)
    th = 0.25 * math.pi * (xg + 1.0)
    vals = np.asarray(slope(np.outer(s, np.sin(th))), dtype=float).reshape(s.size, th.size)
    return s * (vals @ (0.25 * math.pi * wg))


# --------------------------------------------------------------------------- numerical core (D.3)-(D.6)
@dataclass(frozen=True, eq=False)
class _Radius:
    """What depends on the contact radius only: the collocation of (F.6) and the solutions f_1, f_Phi."""

    c: float
    lam: float  # c/H (0 for the half-space)
    n: int
    y: np.ndarray
    T: np.ndarray
    M: np.ndarray
    E: np.ndarray
    e1: float
    i1: float
    ep: float
    ip: float
    coarse: bool
    sol: np.ndarray  # f_1 and f_Phi at the nodes


def _radius_data(layer: LayerKernel, H: float | None, slope: Any, c: float, n: int | None, coarse: bool) -> _Radius:
    lam = c / H if H is not None else 0.0
    N = n or default_nodes(lam)
    if coarse:
        N = max(6, round(0.7 * N))
    y, T, M, E = collocation_operator(layer, lam if lam > 0 else 1.0, N)
    if lam == 0.0:
        M, E = np.eye(N), np.zeros(N)
    sol = np.linalg.solve(M, np.column_stack([np.ones(N), _h(slope, c * y)]))
    a = T @ sol
    e1 = 1.0 + float(E @ a[:, 0])
    ep = float(_h(slope, np.array([c]))[0]) + float(E @ a[:, 1])
    return _Radius(c, lam, N, y, T, M, E, e1, float(a[0, 0]), ep, float(a[0, 1]), coarse, sol)


def default_nodes(lam: float) -> int:
    """``ceil(4 sqrt(c/H)) + 16`` collocation nodes (at most 400)."""
    return int(min(MAX_NODES, math.ceil(4.0 * math.sqrt(lam)) + 16))


def _gauss(a: float, b: float, npan: int, g: int) -> tuple[np.ndarray, np.ndarray]:
    """Composite Gauss-Legendre rule with ``npan`` equal panels of ``g`` points on ``[a, b]``."""
    xg, wg = _legendre(g)
    e = np.linspace(a, b, npan + 1)
    lo, hi = e[:-1, None], e[1:, None]
    return (0.5 * (hi - lo) * xg + 0.5 * (lo + hi)).ravel(), (0.5 * (hi - lo) * wg).ravel()


@lru_cache(maxsize=32)
def _legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    return special.roots_legendre(n)


def _zone_transforms(t: np.ndarray, m: float, coarse: bool) -> tuple[np.ndarray, np.ndarray]:
    """``W(t) = int_1^m cos(t x)/sqrt(m^2 - x^2) dx`` and ``Shat(t) = int_1^m sqrt(m^2 - x^2) cos(t x) dx`` (D.6).

    For ``m <= 2``: ``x = m cos theta`` on ``[0, arccos(1/m)]`` (phase ``t (m - 1)``); beyond, the complements of
    ``int_0^m cos(t x)/sqrt(m^2 - x^2) dx = (pi/2) J0(m t)`` and ``int_0^m sqrt(m^2 - x^2) cos(t x) dx =
    pi m J1(m t)/(2 t)`` over ``[0, 1]`` with ``x = m sin phi`` (phase ``t``): smooth integrands either way.
    """
    tmax = float(t.max()) if t.size else 0.0
    per = 3.0 if coarse else 4.0  # radians of phase per panel (12 and 16 points)
    g = 12 if coarse else 16
    direct = m <= 2.0
    if direct:
        th, wth = _gauss(0.0, math.acos(1.0 / m), max(2, math.ceil(tmax * (m - 1.0) / per)), g)
        arg, wgt = m * np.cos(th), (m * np.sin(th)) ** 2
    else:
        th, wth = _gauss(0.0, math.asin(1.0 / m), max(2, math.ceil(tmax / per)), g)
        arg, wgt = m * np.sin(th), (m * np.cos(th)) ** 2
    W, Sh = np.empty(t.size), np.empty(t.size)
    for i in range(0, t.size, 1024):
        C = np.cos(np.outer(t[i:i + 1024], arg))
        W[i:i + 1024] = C @ wth
        Sh[i:i + 1024] = C @ (wth * wgt)
    if not direct:
        W = 0.5 * math.pi * special.j0(m * t) - W
        Sh = 0.5 * math.pi * m * special.j1(m * t) / t - Sh
    return W, Sh


@lru_cache(maxsize=64)
def _t_rule(layer: LayerKernel, lam: float, level: int, n: int, coarse: bool
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nodes, weights ``(2/pi) W_k (1 - L(t_k/lambda))`` on ``[0, U_MAX lambda]`` and ``(-1)^j j_2j(t_k)``, j < n,
    for the m-dependent sums of (D.6): panels no longer than ``min(6/(2^level + 1), lambda/2)`` (``2^level >= m``: the
    integrands oscillate with frequencies up to ``m + 1``), 16 points each (12 and 0.75 times as long when coarse).
    """
    T = U_MAX * lam
    length = min(6.0 / (2.0**level + 1.0), 0.5 * lam) * (0.75 if coarse else 1.0)
    t, w = _gauss(0.0, T, max(8, math.ceil(T / length)), 12 if coarse else 16)
    wt = (2.0 / math.pi) * w * (1.0 - np.asarray(layer.L_numeric(t / lam, "numpy"), dtype=float))
    J = np.concatenate([even_bessel_transforms(t[i:i + 4096], n) for i in range(0, t.size, 4096)])
    for arr in (t, wt, J):
        arr.setflags(write=False)
    return t, wt, J


def _equations(layer: LayerKernel, rd: _Radius, slope: Any, vt: float, sigma0: float, m: float
               ) -> tuple[float, float, float, np.ndarray]:
    """``(delta, P, separation at b, a)`` at the contact radius ``c`` and ``m = b/c`` (D.3)-(D.6); ``a`` the Legendre
    coefficients of ``f = sum_j a_j P_2j`` on ``[0, 1]``.
    """
    c, lam = rd.c, rd.lam
    s = sigma0 * c / vt
    root = math.sqrt((m - 1.0) * (m + 1.0))
    th1 = math.acos(1.0 / m)
    thq, thw = _gauss(0.0, th1, 4 if rd.coarse else 6, 16)
    h_zone = float(thw @ _h(slope, c * m * np.cos(thq)))  # int_0^theta_1 h(c m cos theta) d theta
    if lam > 0:
        t, wt, J = _t_rule(layer, lam, max(0, math.ceil(math.log2(m))), rd.n, rd.coarse)
        W, Sh = _zone_transforms(t, m, rd.coarse)
        kS = (np.cos(np.outer(rd.y, t)) * wt) @ Sh
        kS1 = float((np.cos(t) * wt) @ Sh)
        fD = np.linalg.solve(rd.M, kS)
        aD = rd.T @ fD
        eD = kS1 + float(rd.E @ aD)
        iD = float(aD[0])
    else:
        eD = iD = 0.0
        fD = 0.0
    delta = (rd.ep + s * (eD - root)) / rd.e1  # (D.4)
    force = 4.0 * vt * c * (delta * rd.i1 - rd.ip - s * iD) - 2.0 * sigma0 * c * c * (m * m * th1 - root)  # (D.5)
    corr = 0.0
    a = rd.T @ (delta * rd.sol[:, 0] - rd.sol[:, 1] - s * fD)
    if lam > 0:
        corr = float(wt @ (W * (J @ a - s * Sh)))
    gap = (2.0 / math.pi) * (-s * (m - 1.0) - delta * th1 + h_zone - corr)  # (D.6)
    return delta, force, gap, a


def _zone_ratio(layer, rd, slope, vt, sigma0, h0) -> tuple[float, float, float, np.ndarray]:
    """``(m, delta, P, a)`` with the separation at ``b = m c`` equal to ``h0`` (D.6), by Brent's method in m."""
    def fun(m: float) -> float:
        return _equations(layer, rd, slope, vt, sigma0, m)[2] - h0

    lo = 1.0 + 1e-14
    f_lo = fun(lo)
    if f_lo >= 0:
        m = lo
    else:
        hi = 1.0 + max(1e-6, min(1.0, h0 / rd.c))
        for _ in range(200):
            if fun(hi) > 0:
                break
            lo, hi = hi, 1.0 + 2.0 * (hi - 1.0)
        else:
            raise InputError("the cohesive zone could not be bracketed (b/c > 1e60)")
        m = optimize.brentq(fun, lo, hi, xtol=1e-14, rtol=1e-13)
    d, P, _, a = _equations(layer, rd, slope, vt, sigma0, m)
    return m, d, P, a


# --------------------------------------------------------------------------- the result
@dataclass(frozen=True)
class CohesiveState(RichDisplay):
    """A Maugis-Dugdale adhesive state of an axisymmetric punch on a layer (D.3)-(D.9).

    Attributes
    ----------
    layer : LayerKernel
        The layer.
    H, mu, nu, vartheta : float
        Thickness (``nan`` for the half-space), shear modulus, Poisson ratio, ``mu/(1 - nu)``.
    R : float
        Apex radius of curvature of the punch (``1/Phi''(0)``).
    work_of_adhesion, sigma0, h0 : float
        float
        ``w = sigma0 h0`` (D.2).
    radius, zone_radius : float
        float
        Contact radius ``c`` and outer radius ``b`` of the cohesive zone.
    delta, force : float
        float
        Depth and force (negative: the punch is pulled).
    tabor, maugis_lambda : float
        float
        ``mu_T`` and Maugis's ``lambda = 1.1272 mu_T`` (D.8).
    delta_error, force_error : float
        float
        Absolute error estimates (module docstring).
    nodes : int
        Collocation nodes.
    """

    layer: LayerKernel
    H: float
    mu: float
    nu: float
    vartheta: float
    R: float
    work_of_adhesion: float
    sigma0: float
    h0: float
    radius: float
    zone_radius: float
    delta: float
    force: float
    tabor: float
    maugis_lambda: float
    delta_error: float
    force_error: float
    nodes: int
    coefficients: tuple = field(default=(), repr=False)  # f = sum_j a_j P_2j(r/c) on the contact (D.3)

    equation = "D.9"

    @property
    def tensile(self) -> bool:
        """True when the punch is pulled (``P < 0``)."""
        return self.force < 0

    def latex(self) -> str:
        return (rf"c = {self.radius:.10g},\quad b = {self.zone_radius:.10g},\quad \delta = {self.delta:.10g},\quad "
                rf"P = {self.force:.10g},\quad \lambda = {self.maugis_lambda:.6g}\ (\mu_T = {self.tabor:.6g})"
                r" \tag{D.9}")

    def pressure_at(self, r: Any) -> np.ndarray:
        """The surface pressure ``p(r)`` (tensile < 0) from Copson's representation (F.3) over ``r < b`` (D.11)::

            p = -(2 vartheta/(pi c)) int_x^1 f'(y)/sqrt(y^2 - x^2) dy
                - (2 sigma0/pi) arctan sqrt((b^2 - c^2)/(c^2 - r^2))

        for ``x = r/c < 1`` (the second term from ``phi_D' = (2/pi) sigma0 t/sqrt(b^2 - t^2)`` on ``(c, b)``:
        Maugis's term), ``-sigma0`` on ``c < r < b``, zero beyond; continuous at ``c`` (D.4).
        """
        rr = np.atleast_1d(np.asarray(r, dtype=float))
        c, b = self.radius, self.zone_radius
        out = np.zeros_like(rr)
        out[(rr >= c) & (rr < b)] = -self.sigma0
        inside = rr < c
        if inside.any():
            x = rr[inside] / c
            coef = np.zeros(2 * len(self.coefficients) - 1)
            coef[::2] = self.coefficients
            dcoef = np.polynomial.legendre.legder(coef)
            v, wv = _legendre(40)
            v, wv = 0.5 * (v + 1.0), 0.5 * wv
            y = x[:, None] + (1.0 - x[:, None]) * v[None, :] ** 2  # y - x = (1 - x) v^2: no singularity
            integrand = np.polynomial.legendre.legval(y, dcoef) * 2.0 * np.sqrt(1.0 - x[:, None]) / np.sqrt(
                y + x[:, None])
            contact = -(2.0 * self.vartheta / (math.pi * c)) * (integrand @ wv)
            with np.errstate(divide="ignore"):
                zone = -(2.0 * self.sigma0 / math.pi) * np.arctan(np.sqrt((b * b - c * c) / (c * c - rr[inside] ** 2)))
            out[inside] = contact + zone
        return out

    def lambdify(self):
        """The pressure ``p(r)`` as a numeric function (:meth:`pressure_at`)."""
        return self.pressure_at

    def text_lines(self) -> list[str]:
        return [f"CohesiveState (Maugis-Dugdale): {self.layer}, H = {self.H:.6g}, mu = {self.mu:.6g}, "
                f"nu = {self.nu:.6g}   (D.3)-(D.9)",
                f"  w = {self.work_of_adhesion:.6g}, sigma0 = {self.sigma0:.6g}, h0 = {self.h0:.6g}; R = {self.R:.6g}"
                f", lambda = {self.maugis_lambda:.6g} (mu_T = {self.tabor:.6g})",
                f"  c = {self.radius:.10g}, b = {self.zone_radius:.10g}",
                f"  delta = {self.delta:.12g} (+- {self.delta_error:.1e}), P = {self.force:.12g} "
                f"(+- {self.force_error:.1e})" + ("  [tensile]" if self.tensile else "")]


# --------------------------------------------------------------------------- public functions
@dataclass(frozen=True, eq=False)
class _Problem:
    layer: LayerKernel
    H: float | None
    mu: float
    nu: float
    vt: float
    slope: Any
    R: float
    w: float
    sigma0: float
    h0: float
    n: int | None


def _problem(layer, punch, H, mu, w, h0, sigma0, nu, n) -> _Problem:
    layer = check_numeric_layer(layer)
    nu_val = numeric_layer_nu(layer, nu)
    mu_val = positive(mu, "mu")
    if layer.has_thickness:
        if H is None:
            raise InputError(f"{type(layer).__name__} needs the layer thickness H > 0")
        H_val = positive(H, "H")
    else:
        H_val = None
    wv = positive(w, "w (work of adhesion)")
    if (h0 is None) == (sigma0 is None):
        raise InputError("give exactly one of h0 (the Dugdale range) and sigma0 (the cohesive stress), w = sigma0 h0")
    if h0 is not None:
        h0v = positive(h0, "h0")
        s0 = wv / h0v
    else:
        s0 = positive(sigma0, "sigma0")
        h0v = wv / s0
    slope, R = _slope_of(punch)
    if n is not None and (isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 6 <= n <= MAX_NODES):
        raise InputError(f"n (collocation nodes) must be an integer in [6, {MAX_NODES}], got {n!r}")
    return _Problem(layer, H_val, mu_val, nu_val, mu_val / (1.0 - nu_val), slope, R, wv, s0, h0v, n)


def cohesive_equations(pr: _Problem, c: float, coarse: bool = False) -> tuple[float, float, float]:
    """``(m = b/c, delta, P)`` of the Maugis-Dugdale state at the contact radius ``c`` (D.3)-(D.6)."""
    return _solve_radius(pr, c, coarse)[:3]


def _solve_radius(pr: _Problem, c: float, coarse: bool = False) -> tuple[float, float, float, np.ndarray]:
    if pr.H is not None and c / pr.H > MAX_A_OVER_H:
        raise InputError(f"c/H = {c / pr.H:.4g} exceeds {MAX_A_OVER_H:g}, the exact flat-punch solver's limit")
    rd = _radius_data(pr.layer, pr.H, pr.slope, c, pr.n, coarse)
    return _zone_ratio(pr.layer, rd, pr.slope, pr.vt, pr.sigma0, pr.h0)


def _state(pr: _Problem, c: float, error_estimate: bool) -> CohesiveState:
    m, d, P, a = _solve_radius(pr, c)
    d_err = P_err = 0.0
    if error_estimate:
        _, dc, Pc = cohesive_equations(pr, c, coarse=True)
        # never below the rounding floor 1e-12 (relative): measured against 60 nodes at c/H = 10, the converged runs
        # scatter by 1e-13 - 4e-13 while the coarse-run change fell to 4e-14
        d_err = max(abs(d - dc), ROUNDING_FLOOR * abs(d))
        P_err = max(abs(P - Pc), ROUNDING_FLOOR * abs(P))
    E_star = 2.0 * pr.vt
    n = pr.n or default_nodes(c / pr.H if pr.H is not None else 0.0)
    return CohesiveState(pr.layer, pr.H if pr.H is not None else math.nan, pr.mu, pr.nu, pr.vt, pr.R, pr.w, pr.sigma0,
                         pr.h0, c, m * c, d, P, tabor_parameter(pr.R, E_star, pr.w, pr.h0),
                         maugis_lambda(pr.R, E_star, pr.w, pr.h0), d_err, P_err, n, tuple(float(v) for v in a))


def maugis_dugdale(layer: LayerKernel, punch: Any, H: float | None = None, mu: float = 1.0, *, w: float,
                   h0: float | None = None, sigma0: float | None = None, radius: float | None = None,
                   delta0: float | None = None, force: float | None = None, nu: float | None = None,
                   n: int | None = None, error_estimate: bool = True) -> CohesiveState:
    """The Maugis-Dugdale adhesive contact of an axisymmetric punch on a layer (D.1)-(D.9).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``FrictionlessLayer()``, ``IncompressibleLayer()`` or ``HalfSpace()``.
    punch : Punch
        An axisymmetric polynomial punch with a rounded apex (``Punch.paraboloid(R=...)``, a fourth-degree punch).
    H : float, optional
        Layer thickness (omitted for the half-space).
    mu : float
        Shear modulus.
    w : float
        Work of adhesion ``w = sigma0 h0``.
    h0, sigma0 : float
        float
        Exactly one: the Dugdale range or the cohesive stress.
    radius, delta0, force : float
        float
        Exactly one: the contact radius ``c``, the depth, or the force (negative when pulled); at a prescribed depth
        or force the state on the stable branch (the largest contact radius) is returned.
    nu : float, optional
        Poisson ratio for layers that fix none.
    n : int, optional
        Collocation nodes (refinement checks).
    error_estimate : bool
        Also solve with ``0.7 n`` nodes and coarser rules, and record the changes.

    Returns
    -------
    CohesiveState

    Examples
    --------
    Maugis's lambda = 1 on the half-space (E* = 2 vartheta = 1, R = 1, w = 1, so ``h0 = 2/(pi K^2)^{1/3}`` with
    ``K = 4/3``) at ``c = 1``: Maugis's reduced force ``P/(pi w R)`` (the closed form (D.7) gives -1.5546172766140):

    >>> from thinlayer import HalfSpace, Punch
    >>> h0 = 2.0 / (math.pi * (4 / 3) ** 2) ** (1 / 3)
    >>> s = maugis_dugdale(HalfSpace(), Punch.paraboloid(R=1), mu=0.5, w=1.0, h0=h0, radius=1.0, nu=0.0)
    >>> round(s.maugis_lambda, 12), round(s.force / math.pi, 10), s.tensile
    (1.0, -1.5546172766, True)
    """
    pr = _problem(layer, punch, H, mu, w, h0, sigma0, nu, n)
    given = [v is not None for v in (radius, delta0, force)]
    if sum(given) != 1:
        raise InputError("give exactly one of radius (contact radius c), delta0 (depth) and force")
    if radius is not None:
        return _state(pr, positive(radius, "radius"), error_estimate)
    name, which = ("delta0", 1) if delta0 is not None else ("force", 2)
    value = delta0 if delta0 is not None else force
    if isinstance(value, (bool, str)) or not isinstance(value, (numbers.Real, np.floating, sp.Number)):
        raise InputTypeError(f"{name} must be a finite real number, got {value!r:.60} ({type(value).__name__})")
    target = float(value)
    if not math.isfinite(target):
        raise InputError(f"{name} must be a finite number, got {value!r:.60}")
    c = _radius_for(pr, target, which)
    return _state(pr, c, error_estimate)


def _radius_for(pr: _Problem, target: float, which: int) -> float:
    """The largest contact radius whose depth (which = 1) or force (which = 2) is ``target`` (the stable branch):
    a geometric scan of ``c`` from the JKR radius at zero load down to 1/50 of it (and up until the value exceeds
    the target), the last upward crossing refined by Brent's method.
    """
    def fun(c: float) -> float:
        return cohesive_equations(pr, c)[which] - target

    K = 8.0 * pr.vt / 3.0
    c0 = (6.0 * math.pi * pr.w * pr.R**2 / K) ** (1.0 / 3.0)
    grid = list(c0 * np.geomspace(0.02, 1.0, 10))
    vals = [fun(c) for c in grid]
    for _ in range(60):
        if vals[-1] > 0:
            break
        grid.append(2.0 * grid[-1])
        vals.append(fun(grid[-1]))
    else:
        raise InputError("no contact radius reaches the prescribed value (bracketing failed)")
    for j in range(len(grid) - 1, 0, -1):
        if vals[j - 1] <= 0 < vals[j]:
            return optimize.brentq(fun, grid[j - 1], grid[j], xtol=1e-13 * grid[j], rtol=1e-12)
    raise InputError("the prescribed value is below the curve's minimum on the scanned radii: no state on the "
                     "stable branch (the punch has come off; see pull_off)")


def pull_off(layer: LayerKernel, punch: Any, H: float | None = None, mu: float = 1.0, *, w: float,
             h0: float | None = None, sigma0: float | None = None, nu: float | None = None, n: int | None = None,
             error_estimate: bool = True) -> CohesiveState:
    """The pull-off state under load control: the minimum of ``P(c)`` on the Maugis-Dugdale curve (D.9).

    Parameters are those of :func:`maugis_dugdale`.  The minimum is bracketed on a geometric scan of ``c`` around the
    JKR radius at zero load, ``(6 pi w R^2/K)^{1/3}`` (``K = 8 vartheta/3``), and refined by Brent's method
    (``xtol = 1e-7 c``: the force is stationary there, so its error is ``~1e-14`` relative).

    Returns
    -------
    CohesiveState
        The state at pull-off; ``-force`` is the pull-off force.

    Examples
    --------
    >>> from thinlayer import HalfSpace, Punch
    >>> s = pull_off(HalfSpace(), Punch.paraboloid(R=1), w=1.0, h0=1e-3, nu=0.0, error_estimate=False)
    >>> round(s.maugis_lambda), round(-s.force / math.pi, 4)   # JKR: 3 pi w R/2 as lambda -> oo
    (710, 1.5)
    """
    pr = _problem(layer, punch, H, mu, w, h0, sigma0, nu, n)
    K = 8.0 * pr.vt / 3.0
    c0 = (6.0 * math.pi * pr.w * pr.R**2 / K) ** (1.0 / 3.0)
    if pr.H is not None:
        c0 = min(c0, 0.5 * MAX_A_OVER_H * pr.H)
    grid = c0 * np.geomspace(0.02, 1.0, 12)

    def force(c: float) -> float:
        return cohesive_equations(pr, c)[2]

    vals = [force(c) for c in grid]
    i = int(np.argmin(vals))
    if i == grid.size - 1:
        raise InputError("pull-off not found below the JKR radius at zero load (the force decreases up to it)")
    lo = grid[max(i - 1, 0)] if i > 0 else 1e-3 * grid[0]
    res = optimize.minimize_scalar(force, bounds=(lo, grid[i + 1]), method="bounded",
                                   options={"xatol": 1e-7 * grid[i]})
    return _state(pr, float(res.x), error_estimate)


# --------------------------------------------------------------------------- (D.10) the Dugdale law in solve_2d
@dataclass(frozen=True, eq=False)
class Cohesive2D(RichDisplay):
    """A Maugis-Dugdale state of any punch on a layer, on the grid of :func:`~thinlayer.numerics.solve_2d` (D.10).

    Attributes
    ----------
    contact : Contact2D
        The last contact solve: ``pressure`` is the compressive part ``p >= 0`` over the tension ``-sigma0``, ``gap``
        the separation, ``force`` the total force.
    zone : numpy.ndarray
        Boolean n x n array of the cells carrying ``-sigma0`` (separation below ``h0``: contact and cohesive zone).
    force, delta0 : float
        float
        Total force (negative: pulled) and the prescribed depth.
    contact_area, zone_area : float
        float
        Cells in contact (``p > 0`` or zero gap) and in the zone, times ``Delta^2``.
    sigma0, h0, work_of_adhesion : float
        float
        Dugdale's law, ``w = sigma0 h0``.
    tabor, maugis_lambda : float
        float
        Of the apex curvature in the mean (``R = 1/sqrt(k1 k2)``, (D.8)); for an axisymmetric punch the values of
        :class:`CohesiveState`.
    iterations : int
        Fixed-point iterations on the zone.
    """

    contact: Any
    zone: np.ndarray
    force: float
    delta0: float
    contact_area: float
    zone_area: float
    sigma0: float
    h0: float
    work_of_adhesion: float
    tabor: float
    maugis_lambda: float
    iterations: int

    equation = "D.10"

    @property
    def contact_radius(self) -> float:
        """``sqrt(contact_area/pi)``."""
        return math.sqrt(self.contact_area / math.pi)

    @property
    def zone_radius(self) -> float:
        """``sqrt(zone_area/pi)``."""
        return math.sqrt(self.zone_area / math.pi)

    def latex(self) -> str:
        return (rf"P = {self.force:.8g},\quad |\omega| = {self.contact_area:.6g},\quad |\omega_{{D}}| = "
                rf"{self.zone_area:.6g},\quad \lambda = {self.maugis_lambda:.4g} \tag{{D.10}}")

    def text_lines(self) -> list[str]:
        return [f"Cohesive2D (Maugis-Dugdale on the grid, n = {self.contact.n}): delta0 = {self.delta0:.8g}, "
                f"P = {self.force:.10g}   (D.10)",
                f"  contact area {self.contact_area:.8g}, zone area {self.zone_area:.8g}; sigma0 = {self.sigma0:.6g}, "
                f"h0 = {self.h0:.6g}, lambda = {self.maugis_lambda:.6g} (mu_T = {self.tabor:.6g}); "
                f"{self.iterations} iterations"]


def maugis_dugdale_2d(layer: LayerKernel, punch: Any, delta0: float, H: float | None = None, mu: float = 1.0, *,
                      w: float, h0: float | None = None, sigma0: float | None = None, extent: float, n: int = 128,
                      nu: float | None = None, tol: float = 1e-10, max_iterations: int = 200) -> Cohesive2D:
    """Maugis-Dugdale adhesion of any punch on a layer: the Dugdale tension in the contact-set iteration (D.10).

    (D.10) The traction is ``t = p - sigma0 chi_Z``: ``chi_Z`` the cells whose separation is below ``h0`` (contact
    included) and ``p >= 0`` the compressive pressure of the contact problem (1.5) with the prescribed surface load
    ``q = -sigma0 chi_Z`` (:func:`~thinlayer.numerics.solve_2d`'s ``surface_load``).  In contact ``t >= -sigma0``
    (Dugdale's law holds there with any tension up to ``sigma0``: Maugis's pressure inside the contact,
    ``p_Hertz - (2 sigma0/pi) arctan(...)``, is never below ``-sigma0``), in the cohesive zone ``t = -sigma0``, beyond
    it 0.  The zone is found by the fixed point ``Z_{k+1} = {gap_k < h0}``, started from the rigid separation
    ``Phi - delta0 < h0``, until it repeats (Anderson-accelerated, depth 5).

    Parameters
    ----------
    layer, punch, H, mu, nu, tol
        As for :func:`~thinlayer.numerics.solve_2d`; the punch a thinlayer :class:`~thinlayer.punch.Punch` with a
        rounded apex at the origin (its mean radius of curvature defines lambda and mu_T).
    delta0 : float
        Depth of the apex below the undeformed surface; ``<= 0`` when the punch is pulled (solved as the punch
        raised by a constant).
    w, h0, sigma0 : float
        float
        Work of adhesion and exactly one of the range ``h0`` and the stress ``sigma0``.
    extent : float
        Half-width of the computational square centred at the origin: it must hold the cohesive zone.
    n : int
        Cells per side.
    max_iterations : int
        Limit of the fixed point on the zone.

    Returns
    -------
    Cohesive2D
    """
    from ..punch import Punch
    from .fft2d import CoarseGridWarning, solve_2d  # same package, rank 4

    wv = positive(w, "w (work of adhesion)")
    if (h0 is None) == (sigma0 is None):
        raise InputError("give exactly one of h0 (the Dugdale range) and sigma0 (the cohesive stress), w = sigma0 h0")
    h0v = positive(h0, "h0") if h0 is not None else wv / positive(sigma0, "sigma0")
    s0 = wv / h0v
    half = positive(extent, "extent")
    if isinstance(delta0, (bool, str)) or not isinstance(delta0, (numbers.Real, np.floating, sp.Number)) \
            or not math.isfinite(float(delta0)):
        raise InputTypeError(f"delta0 must be a finite real number (negative when the punch is pulled above the "
                             f"surface), got {delta0!r:.60}")
    d0 = float(delta0)
    n = check_int(n, "n (cells per side)", 8)
    max_iterations = check_int(max_iterations, "max_iterations", 1)
    if not (hasattr(punch, "lambdify") and hasattr(punch, "expr")):
        raise InputTypeError(f"punch must be a thinlayer Punch, got {type(punch).__name__}")
    R = mean_radius(punch)
    # solve_2d takes delta0 > 0: a pulled punch (delta0 <= 0) is the same punch raised by k (Phi + k, delta0 + k)
    k = 0.0 if d0 > 0 else 2.0 * h0v - d0
    work_punch = punch if k == 0.0 else Punch(punch.expr + k)
    x = -half + (np.arange(n) + 0.5) * (2.0 * half / n)
    X1, X2 = np.meshgrid(x, x, indexing="ij")
    phi = np.broadcast_to(np.asarray(punch.lambdify()(X1, X2), dtype=float), X1.shape)
    dx = 2.0 * half / n
    frac = _coverage(phi - d0, h0v, dx)
    change, xs, fs = math.inf, [], []
    for it in range(1, max_iterations + 1):
        try:
            res = solve_2d(layer, work_punch, d0 + k, H, mu, n, half, tol, nu=nu, surface_load=-s0 * frac)
        except InputError:
            if len(fs) < 2:
                raise
            frac = np.clip(xs[-1] + fs[-1], 0.0, 1.0).reshape(n, n)  # an Anderson step lost the contact: plain step
            xs, fs = [], []
            continue
        f = (_coverage(np.asarray(res.gap), h0v, dx) - frac).ravel()
        change, last = float(np.abs(f).max()), change
        if change < 1e-9:
            break
        if change > last:  # the mixing overshot (a zone a cell or two wide flips): restart it from a plain step
            xs, fs = [], []
        # Anderson mixing of depth 5 on the covered fraction (measured: 52 instead of > 200 iterations at n = 64,
        # lambda = 3 on a thin layer; 78 instead of 184 at n = 256; the same fixed point)
        xs, fs = [*xs[-5:], frac.ravel().copy()], [*fs[-5:], f]
        step = frac.ravel() + f
        if len(fs) > 1:
            dF, dX = np.diff(np.array(fs), axis=0).T, np.diff(np.array(xs), axis=0).T
            gam = np.linalg.lstsq(dF, f, rcond=None)[0]
            step = step - (dX + dF) @ gam
        frac = np.clip(step, 0.0, 1.0).reshape(n, n)
    else:
        raise InputError(f"the cohesive zone did not settle in {max_iterations} iterations (last change of the "
                         f"covered fraction {change:.2e})")
    res = solve_2d(layer, work_punch, d0 + k, H, mu, n, half, tol, nu=nu, surface_load=-s0 * frac)
    cell = dx * dx
    zone_area = cell * float(frac.sum())
    perimeter = sum(float(np.hypot(*np.diff(line, axis=0).T).sum()) for line in res.contour)
    width = (zone_area - res.contact_area) / perimeter if perimeter > 0 else math.inf
    if width < 0.5 * dx:
        raise InputError(f"the cohesive zone (mean width {max(width, 0.0):.3g}) is narrower than half a cell (Delta = "
                         f"{dx:.3g}): the grid cannot resolve Dugdale's law here (Maugis lambda = "
                         f"{maugis_lambda(R, 2 * res.vartheta, wv, h0v):.3g}); refine n or reduce extent, or use the "
                         "JKR limit (thinlayer.numerics.adhesion) for large lambda")
    if width < 2.0 * dx:
        warnings.warn(f"the cohesive zone is only {width / dx:.2g} cells wide (mean width {width:.3g}, Delta = "
                      f"{dx:.3g}): expect errors of a few percent in the force (measured for the sphere at lambda = 3: "
                      "1.7 % at 1.3 cells, 0.85 % at n doubled); refine n", CoarseGridWarning, stacklevel=2)
    vt = res.vartheta
    frac.setflags(write=False)
    return Cohesive2D(res, frac, res.force, d0, res.contact_area, zone_area, s0, h0v, wv,
                      tabor_parameter(R, 2 * vt, wv, h0v), maugis_lambda(R, 2 * vt, wv, h0v), it)


def _coverage(g: np.ndarray, h0: float, dx: float) -> np.ndarray:
    """The fraction of each cell whose separation is below ``h0`` for the gap linear across the cell (D.10):
    ``clip(1/2 + (h0 - g)/(Delta (|g_x| + |g_y|)), 0, 1)``, the gradient by central differences.
    """
    g1, g2 = np.gradient(g, dx)
    width = dx * (np.abs(g1) + np.abs(g2))
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(width > 0, 0.5 + (h0 - g) / width, np.where(g < h0, 1.0, 0.0))
    return np.clip(f, 0.0, 1.0)


def mean_radius(punch: Any) -> float:
    """``1/sqrt(k1 k2)`` from the Hessian of Phi at the origin (the apex)."""
    from .. import symbols as S

    e = punch.expr
    Hm = sp.Matrix([[sp.diff(e, a, b) for b in (S.x1, S.x2)] for a in (S.x1, S.x2)]).subs({S.x1: 0, S.x2: 0})
    det = float(Hm.det())
    if not det > 0:
        raise InputError("the punch needs a rounded apex (positive-definite Hessian of Phi at the origin)")
    return 1.0 / math.sqrt(det)

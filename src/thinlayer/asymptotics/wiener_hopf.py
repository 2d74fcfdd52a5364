r"""Exact boundary layer (3.15)-(3.18), (3.22) by numerical Wiener--Hopf factorisation.

Problem
-------
Near the contour the pressure is ``q(tau)``, ``tau = v - h`` the distance from the true edge
(paper (3.22) with ``v = h + tau``)::

    int_0^oo q(tau') N(tau' - tau) dtau' = c (h + tau),   tau > 0,     q(0) = 0   (3.18)
    N(t) = pi int_0^oo F(s) cos(s t) ds,   F(s) = L(s)/s                         (3.17)

with ``c = pi^2 vartheta H_* b_1^*(s)``.  ``int N(t) e^{i w t} dt = pi^2 F(w)``.  The paper replaces
F by Alexandrov's ``F~(s) = sqrt(s^2 + B^2)/(s^2 + C)`` (3.19); this module solves the equation
with the exact kernel (2.3) and keeps F~ for comparison.

Derivation (own; checked in ``tests/asymptotics/test_wiener_hopf.py``)
---------------------------------------------------------
Extend the equation to ``tau < 0`` with an unknown left-hand side ``g(tau)`` and Fourier
transform (``Q+(w) = int_0^oo q e^{i w tau} dtau``, analytic for ``Im w > 0``)::

    pi^2 F(w) Q+(w) = c (i h / w - 1/w^2) + G-(w).

Factorise ``F = F+ F-`` (``F+`` analytic and zero-free for ``Im w > 0``, ``F-`` for ``Im w < 0``;
F is even, so take ``F-(w) = F+(-w)``, hence ``F+(0)^2 = A``).  Dividing by ``F-`` and removing
the pole part at ``w = 0`` gives, by Liouville (``F+ ~ w^{-1/2}``, ``Q+ = O(w^{-3/2})``)::

    Q+(w) = c / (pi^2 F+(w)) [ -1/(w^2 F-(0)) + (i h/F-(0) + F-'(0)/F-(0)^2) / w ].

The ``1/w`` bracket would give ``q ~ tau^{-1/2}`` at the edge; ``q(0) = 0`` (3.18) removes it::

    h = i (log F-)'(0) = -i (log F+)'(0),      Q+(w) = -c / (pi^2 sqrt(A) w^2 F+(w)).

With ``w = i p`` (Laplace variable) and ``Phi(p) = F+(ip)/F+(0)``::

    int_0^oo q(tau) e^{-p tau} dtau = (c/(pi^2 A)) / (p^2 Phi(p)),   Phi(p) = 1 - h p + O(p^2).

This module works with the normalised solution ``qhat = pi^2 A q / c``, so ``qhat ~ tau + h``.

*Factorisation.*  Pick an exactly factorisable even normaliser ``F0`` with ``F0(0) = A`` and
``F0 ~ 1/|w|`` at infinity; ``R = F/F0`` is then even, positive, ``R(0) = 1``, ``R -> 1``, and
``log R+(w) = (1/(2 pi i)) int log R(t)/(t - w) dt``.  On ``w = i p`` (``Re p > 0``) and at ``w -> 0``::

    log Phi(p) = log Phi0(p) + (p/pi) int_0^oo log R(t) / (t^2 + p^2) dt,
    h          = h[F0] - (1/pi) int_0^oo log(F(t)/F0(t)) / t^2 dt.

Three normalisers (any of them gives the same ``h``; the tests check this to 1e-12):

=============  ===================================  ==========================  ====================
name           F0(t)                                Phi0(p)                     h[F0]
=============  ===================================  ==========================  ====================
``sqrt``       ``A / sqrt(1 + A^2 t^2)``            ``(1 + A p)^{-1/2}``        ``A/2``
``alexandrov`` ``sqrt(t^2+B^2)/(t^2+C)`` (3.19)     ``sqrt(1+p/B)/(1+p/sqrt C)`` ``1/sqrt C - 1/(2B)``
``tanh``       ``tanh(A t)/t``                      ``Gamma(1/2+Ap/pi)/(sqrt(pi) Gamma(1+Ap/pi))``  ``2 A log2/pi``
=============  ===================================  ==========================  ====================

(``tanh(pi z)/(pi z) = Gamma(1/2+iz) Gamma(1/2-iz) / (pi Gamma(1+iz) Gamma(1-iz))``.)
Alexandrov's constants: ``B = A C`` (3.20) and, by matching the ``s^2`` term of (2.20),
``1/C - 1/(2 B^2) = -m_1`` (the paper prints ``-2 m_1``), i.e. ``1/C = A^2 (1 + sqrt(1 + 2 m_1/A^2))``
(the root with ``C > 0`` for every nu); with F0 = F~ the formula gives (3.25)
``h~ = 1/sqrt(C) - 1/(2B) = sqrt(A/B) - 1/(2B)``.

*Solution.*  ``qhat`` is the inverse Laplace transform of ``1/(p^2 Phi(p))`` (de Hoog's method,
:func:`mpmath.invertlaplace`, which samples only ``Re p > 0`` where the Cauchy integral above is
valid).  :meth:`WienerHopfSolution.q` evaluates ``Phi`` by adaptive mpmath quadrature;
:meth:`WienerHopfSolution.q_numpy` interpolates a table, computed once with ``Phi`` from a fixed
Gauss--Legendre panel rule, by a Chebyshev series in ``z = sqrt(tau)`` on ``[0, sqrt(tau_max)]``
(``qhat`` is a series in ``sqrt(tau)``: ``qhat ~ 2 sqrt(A tau/pi)`` at the edge); beyond ``tau_max``
``qhat = tau + h`` to ``exp(-sigma tau_max) < 1e-15``, ``sigma`` being the decay rate of
``qhat - tau - h``: ``-sigma`` is the pole of ``1/Phi`` nearest to 0, a zero ``F(-i sigma) = 0`` of
the kernel (``sin 2 sigma/(2 sigma) = 1/kappa``; ``sigma = B`` for Alexandrov's kernel).

*Identities used as checks.*  For Alexandrov's kernel ``qhat = (tau + h~) erf sqrt(B tau) +
sqrt(tau/(pi B)) e^{-B tau}`` (3.24).  Since ``log Phi(p) + log Phi(-p) = log(F(ip)/A)``, the
``p^2`` coefficient of ``log Phi`` is ``m_1/2``, whence the force defect
``int_{-oo}^{oo} (Qhat(v) - max(v, 0)) dv = int_0^oo (qhat - tau - h) dtau - h^2/2 = m_1/2``
with ``Qhat(v) = qhat(v - h)`` (``v > h``), for every even kernel.

Physical boundary layer (3.22): ``q**(s, h + tau) = (vartheta H_* b_1^*(s) / A) qhat(tau)``.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from typing import Any, ClassVar

import mpmath
import numpy as np
import sympy as sp

from .._cache import cached
from .._checks import InputError, InputTypeError, parse_nu
from .._mpfr import stieltjes_sums, to_mpfr
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.kernels import BondedLayer, FrictionlessLayer, LayerKernel
from ..normal import normal_latex
from ._wiener_hopf_tables import shipped_table

__all__ = [
    "KERNELS",
    "NORMALISERS",
    "EdgeShiftTable",
    "WienerHopfSolution",
    "boundary_kernel_N",
    "boundary_layer_exact",
    "edge_shift",
    "edge_shift_alexandrov",
    "edge_shift_exact",
    "edge_shift_table",
    "fresh_table",
    "wiener_hopf_solution",
]

KERNELS = ("exact", "alexandrov")
NORMALISERS = ("sqrt", "alexandrov", "tanh")

# de Hoog's abscissa at the precision used for the table (mpmath: dps_goal = int(1.36 dps)):
# Re p = ln(10^(dps_goal - 1))/(4 tau); |Im p| <= 2 M pi/(4 tau) with M = dps_goal.
_TABLE_DPS = 15
_GL = np.polynomial.legendre.leggauss(24)


# ----------------------------------------------------------------------------- inputs
#: key of the layer on a frictionless base (its kernel does not depend on nu)
FRICTIONLESS = "frictionless"


def _rational_nu(nu: Any) -> sp.Rational | str:
    """Exact rational value of a Poisson ratio (a float is taken as its exact binary value).

    A layer gives its :attr:`~thinlayer.layers.kernels.LayerKernel.edge_shift_key`: its exact nu, or
    ``FRICTIONLESS`` for the frictionless base (its kernel is independent of nu); so does the string
    ``"frictionless"``.
    """
    if isinstance(nu, LayerKernel):
        return nu.edge_shift_key
    if isinstance(nu, str) and nu == FRICTIONLESS:
        return FRICTIONLESS
    if isinstance(nu, bool) or not isinstance(nu, (numbers.Real, str, mpmath.mpf, sp.Basic, Fraction)):
        raise InputTypeError(f"nu must be a real number in (-1, 1/2) or a BondedLayer, got {type(nu).__name__}")
    return parse_nu(nu, floats="exact", symbols=False, example="'3/10' or 0.3",
                    range_hint="A = (1-2nu)/(2(1-nu)^2) must be positive")


def _check_choice(value: str, allowed: tuple[str, ...], name: str) -> str:
    if value not in allowed:
        raise InputError(f"{name} must be one of {allowed}, got {value!r}")
    return value


def _mp(r: sp.Rational) -> mpmath.mpf:
    return mpmath.mpf(int(r.p)) / int(r.q)


@dataclass(frozen=True)
class _Layer:
    """Exact data of a layer: key (nu or FRICTIONLESS), A (2.4), m_1 (2.20), as rationals."""

    nu: sp.Rational | str
    layer: BondedLayer | FrictionlessLayer
    A: sp.Rational
    m1: sp.Rational

    @property
    def kappa(self) -> sp.Rational:
        return 3 - 4 * self.nu

    def zero_rate(self) -> float:
        """Sigma > 0 with F(i sigma) = 0: sin(2 sigma)/(2 sigma) = 1/kappa, 2 sigma in (0, pi).

        Frictionless base: ``F(iy) = (1 - cos 2y)/(y (sin 2y + 2y))``, first (double) zero ``y = pi``.
        """
        if self.nu == FRICTIONLESS:
            return math.pi
        k = float(self.kappa)
        if k - 1 < 1e-6:  # sin x/x ~ 1 - x^2/6
            return 0.5 * math.sqrt(6 * (k - 1) / k)

        def root() -> float:
            from scipy import optimize  # imported on a cache miss only: a cached nu needs no scipy

            return 0.5 * optimize.brentq(lambda x: math.sin(x) / x - 1 / k, 1e-12, math.pi, xtol=1e-15)

        return cached("zero_rate", (self.nu,), root)

    def pole_rate(self) -> float:
        """Y > 0 with 1/F(i y) = 0: 2 kappa cos 2y + 1 + kappa^2 - 4 y^2 = 0 (smallest root).

        Frictionless base: ``sin 2y + 2y`` has no real zero but 0, so F has no pole on the imaginary
        axis; the scale 1 (the thickness) is used as a quadrature breakpoint instead.
        """
        if self.nu == FRICTIONLESS:
            return 1.0
        k = float(self.kappa)
        g = lambda y: 2 * k * math.cos(2 * y) + 1 + k * k - 4 * y * y

        def root() -> float:
            from scipy import optimize  # imported on a cache miss only: a cached nu needs no scipy

            return optimize.brentq(g, 0.0, (k + 1) / 2 + 1e-9, xtol=1e-15)

        return cached("pole_rate", (self.nu,), root)


@lru_cache(maxsize=256)
def _layer(nu: sp.Rational | str) -> _Layer:
    lay = FrictionlessLayer() if nu == FRICTIONLESS else BondedLayer(nu)
    return _Layer(nu, lay, sp.Rational(lay.A), sp.Rational(lay.m(1)))


def _alexandrov_BC(A, m1):
    """B, C of (3.19)-(3.21) at the current precision: B = A C, 1/C - 1/(2B^2) = -m_1."""
    invC = A**2 * (1 + mpmath.sqrt(1 + 2 * m1 / A**2))
    C = 1 / invC
    return A * C, C


# ----------------------------------------------------------------------------- kernels
class _Kernel:
    """F(s) = L(s)/s (exact, (2.3)) or Alexandrov's F~ (3.19), in mpmath and numpy."""

    def __init__(self, lay: _Layer, kind: str, dps_hi: int):
        self.lay, self.kind = lay, kind
        with mpmath.workdps(dps_hi):
            self.A = _mp(lay.A)
            self.m1 = _mp(lay.m1)
            self.B, self.C = _alexandrov_BC(self.A, self.m1)
            self.sqrtC = mpmath.sqrt(self.C)
        self.Af, self.Bf, self.Cf = float(self.A), float(self.B), float(self.C)
        if kind == "exact":
            self.sigma = lay.zero_rate()  # decay rate of qhat - tau - h
            self.scales = [self.sigma, lay.pole_rate(), 1.0]
        else:
            self.sigma = self.Bf  # branch point of 1/Phi at p = -B
            self.scales = [self.Bf, math.sqrt(self.Cf), 1.0]
        self.dist = min(self.scales)  # nearest singularity of log F off the real axis

    def F_mp(self, t):
        if self.kind == "exact":
            return self.lay.layer.L_numeric(t, backend="mpmath", over_u=True)
        return mpmath.sqrt(t * t + self.B**2) / (t * t + self.C)

    def F_np(self, t):
        if self.kind == "exact":
            return self.lay.layer.L_numeric(t, backend="numpy", over_u=True)
        return np.sqrt(t * t + self.Bf**2) / (t * t + self.Cf)


class _Normaliser:
    """An exactly factorisable even F0 with F0(0) = A, F0 ~ 1/|t|: see the module table."""

    def __init__(self, kern: _Kernel, kind: str):
        self.kind, self.k = kind, kern
        A, B, C, sC = kern.A, kern.B, kern.C, kern.sqrtC
        if kind == "sqrt":
            self.m1_0 = -A**2 / 2
            self.scales = [float(1 / A)]
        elif kind == "alexandrov":
            self.m1_0 = kern.m1
            self.scales = [kern.Bf, math.sqrt(kern.Cf)]
        else:
            self.m1_0 = -A**2 / 3
            self.scales = [math.pi / (2 * kern.Af)]
        self._BC = (B, C, sC)

    def h0(self):
        A = self.k.A
        B, _, sC = self._BC
        if self.kind == "sqrt":
            return A / 2
        if self.kind == "alexandrov":
            return 1 / sC - 1 / (2 * B)  # (3.25)
        return 2 * A * mpmath.log(2) / mpmath.pi

    def F0_mp(self, t):
        A = self.k.A
        B, C, _ = self._BC
        if self.kind == "sqrt":
            return A / mpmath.sqrt(1 + (A * t) ** 2)
        if self.kind == "alexandrov":
            return mpmath.sqrt(t * t + B**2) / (t * t + C)
        return mpmath.tanh(A * t) / t if t != 0 else A

    def F0_np(self, t):
        A, B, C = self.k.Af, self.k.Bf, self.k.Cf
        if self.kind == "sqrt":
            return A / np.sqrt(1 + (A * t) ** 2)
        if self.kind == "alexandrov":
            return np.sqrt(t * t + B * B) / (t * t + C)
        return np.tanh(A * t) / t

    def log_phi0_mp(self, p):
        A = self.k.A
        B, _, sC = self._BC
        if self.kind == "sqrt":
            return -mpmath.log(1 + A * p) / 2
        if self.kind == "alexandrov":
            return mpmath.log(1 + p / B) / 2 - mpmath.log(1 + p / sC)
        z = A * p / mpmath.pi
        return mpmath.loggamma(z + 0.5) - mpmath.loggamma(z + 1) - mpmath.log(mpmath.pi) / 2

    def log_phi0_np(self, p):
        A, B, C = self.k.Af, self.k.Bf, self.k.Cf
        if self.kind == "sqrt":
            return -np.log1p(A * p) / 2
        if self.kind == "alexandrov":
            return np.log1p(p / B) / 2 - np.log1p(p / math.sqrt(C))
        z = A * p / math.pi
        from scipy import special  # imported on first use

        return special.loggamma(z + 0.5) - special.loggamma(z + 1) - 0.5 * math.log(math.pi)


def _log_ratio_over_t2(kern: _Kernel, norm: _Normaliser, dps: int):
    """T -> log(F(t)/F0(t))/t^2 in mpmath, free of the cancellation at small t.

    ``log R(t) = O(t^2)``: the working precision is raised by ``2 log10(1/t)`` digits, and below
    ``10^-(dps/2+3)`` the limit ``m_1[F] - m_1[F0]`` is used (error ``O(t^2)``, below 10^-dps).
    """
    t_small = mpmath.mpf(10) ** (-(dps // 2 + 3))
    with mpmath.workdps(3 * dps + 20):
        limit = kern.m1 - norm.m1_0

    def f(t):
        if t < t_small:
            return +limit
        extra = 6 + (int(-2 * mpmath.log10(t)) if t < 1 else 0)
        with mpmath.extradps(extra):
            t = +t
            val = mpmath.log(kern.F_mp(t) / norm.F0_mp(t)) / (t * t)
        return +val

    return f


def _breakpoints(kern: _Kernel, norm: _Normaliser) -> list:
    pts = {s for s in kern.scales + norm.scales if 0 < s < 1e12}
    return [mpmath.mpf(0)] + [mpmath.mpf(s) for s in sorted(pts)] + [mpmath.inf]


# ----------------------------------------------------------------------------- edge shift
def _edge_shift(lay: _Layer, kernel: str, normaliser: str, dps: int, error: bool = False):
    if not error:  # h* (3.18) is kept on disk per nu (thinlayer._cache): seconds of quadrature per process
        return cached("edge_shift", (lay.nu, kernel, normaliser, dps),
                      lambda: _edge_shift(lay, kernel, normaliser, dps, error=True)[0])
    with mpmath.workdps(dps):
        kern = _Kernel(lay, kernel, 3 * dps + 20)
        norm = _Normaliser(kern, normaliser)
        f = _log_ratio_over_t2(kern, norm, dps)
        I, err = mpmath.quad(f, _breakpoints(kern, norm), error=True)
        h = norm.h0() - I / mpmath.pi
        return (+h, err / mpmath.pi) if error else +h


def _check_dps(dps: Any) -> int:
    if isinstance(dps, bool) or not isinstance(dps, numbers.Integral) or dps < 10:
        raise InputError(f"dps must be an integer >= 10, got {dps!r}")
    return int(dps)


def edge_shift(nu: Any, kernel: str = "exact", normaliser: str = "alexandrov", dps: int = 20) -> mpmath.mpf:
    r"""Edge shift ``h`` of the boundary layer (3.18), (3.22) by Wiener--Hopf factorisation.

    ``h = h[F0] - (1/pi) int_0^oo log(F(t)/F0(t))/t^2 dt`` (see the module docstring).

    Parameters
    ----------
    nu : Any
        Poisson ratio in (-1, 1/2) (float, rational, string such as ``"3/10"``) or a numeric
        :class:`~thinlayer.BondedLayer`.
    kernel : str
        ``"exact"`` (``F = L(s)/s`` with (2.3)) or ``"alexandrov"`` (``F~`` of (3.19)).
    normaliser : str
        ``"sqrt"``, ``"alexandrov"`` or ``"tanh"``: the exactly factorised F0 (results agree).
    dps : int
        mpmath working precision (decimal digits); the result is good to about ``dps - 3``
        digits (checked against ``dps=40``), for every nu tried in ``[-1 + 1e-10, 1/2 - 1e-12]``.

    Returns
    -------
    mpmath.mpf
        ``h`` in units of the layer thickness (scaled variables of (3.7)).
    """
    _check_choice(kernel, KERNELS, "kernel")
    _check_choice(normaliser, NORMALISERS, "normaliser")
    return _edge_shift(_layer(_rational_nu(nu)), kernel, normaliser, _check_dps(dps))


def _phi0_cubic(norm: _Normaliser):
    """The ``p^3`` Taylor coefficient of ``log Phi0(p)`` for the normalisers of the module table."""
    A = norm.k.A
    B, _, sC = norm._BC
    if norm.kind == "sqrt":  # -log(1 + A p)/2
        return -A**3 / 6
    if norm.kind == "alexandrov":  # log(1 + p/B)/2 - log(1 + p/sqrt C)
        return 1 / (6 * B**3) - 1 / (3 * sC**3)
    # log Gamma(1/2 + z) - log Gamma(1 + z), z = A p/pi
    return (A / mpmath.pi) ** 3 * (mpmath.polygamma(2, mpmath.mpf(1) / 2) - mpmath.polygamma(2, 1)) / 6


def _edge_cubic(lay: _Layer, kernel: str, normaliser: str, dps: int) -> mpmath.mpf:
    return cached("edge_cubic", (lay.nu, kernel, normaliser, dps), lambda: _edge_cubic_computed(lay, kernel, normaliser,
                                                                                               dps))


def _edge_cubic_computed(lay: _Layer, kernel: str, normaliser: str, dps: int) -> mpmath.mpf:
    with mpmath.workdps(dps):
        kern = _Kernel(lay, kernel, 3 * dps + 20)
        norm = _Normaliser(kern, normaliser)
        with mpmath.workdps(3 * dps + 20):
            c = kern.m1 - norm.m1_0  # log R(t) = c t^2 + O(t^4)
        t_small = mpmath.mpf(10) ** (-(dps // 4 + 3))

        def f(t):  # (log R - c t^2)/t^4, bounded at 0: below t_small its value there (error O(t_small^3))
            t = max(t, t_small)
            with mpmath.extradps(6 + (int(-4 * mpmath.log10(t)) if t < 1 else 0)):
                t = +t
                val = (mpmath.log(kern.F_mp(t) / norm.F0_mp(t)) - c * t * t) / t**4
            return +val

        K = mpmath.quad(f, _breakpoints(kern, norm))
        return +(_phi0_cubic(norm) - K / mpmath.pi)


def edge_cubic(nu: Any, kernel: str = "exact", normaliser: str = "alexandrov", dps: int = 20) -> mpmath.mpf:
    r"""The cubic Taylor coefficient ``r_3`` of ``log Phi(p) = -h^* p - (m_1/2) p^2 + r_3 p^3 + O(p^4)``.

    ``Phi(p) = F+(ip)/F+(0)`` is the factor of the boundary-layer equation (3.18) (module docstring).  Its even
    coefficients follow from ``F`` alone (``log F(w) = log F+(w) + log F+(-w)``: the ``p^2`` one is ``-m_1/2``,
    (2.20)); the odd ones are the Wiener--Hopf constants, ``h^*`` the first and ``r_3`` the second.  From
    ``log Phi = log Phi0 + (p/pi) int_0^oo log R(t)/(t^2 + p^2) dt`` (``R = F/F0``, ``log R = c t^2 + O(t^4)``):

        r_3 = r_3[F0] - (1/pi) int_0^oo (log R(t) - c t^2)/t^4 dt,

    the ``p^3`` term of the expansion ``int f/(t^2 + p^2) = int f/t^2 - c pi p/2 - p^2 int (f - c t^2)/t^4 + O(p^3)``.
    ``r_3`` sets the second-order force term (:mod:`thinlayer.asymptotics.second_order`).  The three normalisers
    give the same number (tests: to 1e-12).

    Examples
    --------
    >>> from thinlayer.asymptotics.wiener_hopf import edge_cubic
    >>> r_a, r_s = edge_cubic("3/10"), edge_cubic("3/10", normaliser="sqrt")
    >>> print(mpmath.nstr(r_a, 9), bool(abs(r_a - r_s) < 1e-12))
    0.053008374 True
    """
    _check_choice(kernel, KERNELS, "kernel")
    _check_choice(normaliser, NORMALISERS, "normaliser")
    return _edge_cubic(_layer(_rational_nu(nu)), kernel, normaliser, _check_dps(dps))


@boundary
def edge_shift_exact(nu: Any, dps: int = 20, normaliser: str = "alexandrov") -> mpmath.mpf:
    """Exact edge shift ``h*`` (3.18) with the kernel (2.3): :func:`edge_shift` with ``kernel="exact"``.

    Examples
    --------
    Two different factorisations give the same number:

    >>> from thinlayer.asymptotics.wiener_hopf import edge_shift_exact
    >>> h1 = edge_shift_exact("1/4", normaliser="sqrt")
    >>> h2 = edge_shift_exact("1/4", normaliser="alexandrov")
    >>> bool(abs(h1 - h2) < 1e-12)
    True
    """
    return edge_shift(nu, "exact", normaliser, dps)


@boundary
def edge_shift_alexandrov(nu: Any) -> mpmath.mpf:
    """Alexandrov's edge shift (3.25) ``h~ = 1/sqrt(C) - 1/(2B) = sqrt(A/B) - 1/(2B)``.

    ``B = A C`` (3.20), ``1/C - 1/(2B^2) = -m_1`` ((3.21) corrected: printed ``-2 m_1``).
    Computed at the current ``mpmath.mp.dps``.

    Examples
    --------
    >>> from thinlayer.asymptotics.wiener_hopf import edge_shift_alexandrov
    >>> print(mpmath.nstr(edge_shift_alexandrov(0), 12))   # nu = 0: A = 1/2, m_1 = 0, 1/C = 1/2
    0.207106781187
    """
    lay = _layer(_rational_nu(nu))
    with mpmath.extradps(10):
        B, C = _alexandrov_BC(_mp(lay.A), _mp(lay.m1))
        h = 1 / mpmath.sqrt(C) - 1 / (2 * B)
    return +h


@dataclass(frozen=True)
class EdgeShiftTable(RichDisplay):
    """Rows ``(nu, h_exact, h_alexandrov)`` of the edge shift (3.18) vs Alexandrov's (3.25)."""

    rows: tuple[tuple[sp.Rational, mpmath.mpf, mpmath.mpf], ...]
    dps: int

    def latex(self, digits: int = 10) -> str:
        lines = [r"\begin{tabular}{rrrr}", r"$\nu$ & $h^*$ (exact) & $\tilde h^*$ (3.25) & difference \\ \hline"]
        for nu, he, ha in self.rows:
            lines.append(f"{float(nu):g} & {mpmath.nstr(he, digits)} & {mpmath.nstr(ha, digits)} & "
                         f"{mpmath.nstr(he - ha, 3)} \\\\")
        lines.append(r"\end{tabular}")
        return "\n".join(lines)

    def _display_tex(self) -> str:
        """The table as a LaTeX ``array`` for Jupyter (MathJax renders no ``tabular``)."""
        rows = [r"\nu & h^*\ \text{(exact)} & \tilde h^*\ \text{(3.25)} & \text{difference} \\ \hline"]
        for nu, he, ha in self.rows:
            rows.append(f"{float(nu):g} & {mpmath.nstr(he, 10)} & {mpmath.nstr(ha, 10)} & "
                        f"{mpmath.nstr(he - ha, 3)} \\\\")
        return r"\begin{array}{rrrr}" + " ".join(rows) + r"\end{array}"

    def __str__(self) -> str:
        out = [f"{'nu':>8} {'h_exact':>16} {'h_alexandrov':>16} {'difference':>11}"]
        for nu, he, ha in self.rows:
            out.append(f"{float(nu):>8g} {mpmath.nstr(he, 12):>16} {mpmath.nstr(ha, 12):>16} "
                       f"{mpmath.nstr(he - ha, 3):>11}")
        return "\n".join(out)


def edge_shift_table(nus: Any, dps: int = 20) -> EdgeShiftTable:
    """Exact and Alexandrov edge shifts for each Poisson ratio in ``nus`` (3.18), (3.25)."""
    if isinstance(nus, (str, numbers.Real, LayerKernel)):
        nus = [nus]
    rows = []
    for nu in nus:
        r = _rational_nu(nu)
        with mpmath.workdps(dps):
            rows.append((r, edge_shift_exact(r, dps), edge_shift_alexandrov(r)))
    return EdgeShiftTable(tuple(rows), dps)


# ----------------------------------------------------------------------------- boundary layer
def _panel_edges(w0: float, beta: float, xmax: float) -> list[float]:
    """Panel edges on [0, xmax]: width ``max(w0, beta x)``."""
    edges = [0.0]
    while edges[-1] < xmax:
        edges.append(edges[-1] + max(w0, beta * edges[-1]))
    return edges


def _panel_nodes(edges: list[float]) -> tuple[np.ndarray, np.ndarray]:
    """Composite 24-point Gauss--Legendre nodes and weights on the panels ``edges``."""
    e = np.asarray(edges)
    a, b = e[:-1, None], e[1:, None]
    x = 0.5 * (a + b) + 0.5 * (b - a) * _GL[0][None, :]
    w = 0.5 * (b - a) * _GL[1][None, :]
    return x.ravel(), w.ravel()


def _panel_rule(w0: float, beta: float, xmax: float) -> tuple[np.ndarray, np.ndarray]:
    """Composite 24-point Gauss--Legendre rule on [0, xmax], panel width max(w0, beta x)."""
    return _panel_nodes(_panel_edges(w0, beta, xmax))


class _Transform:
    """``Phi(p) = F+(ip)/F+(0)`` for ``Re p > 0``: precise (mpmath quad) and fast (panel rule)."""

    def __init__(self, kern: _Kernel, norm: _Normaliser, tau_max: float):
        self.kern, self.norm = kern, norm
        # de Hoog at _TABLE_DPS: Re p >= ln(10)(dps_goal - 1)/(4 tau_max) = gmin, |Im p| <= 2.9 Re p.
        goal = int(1.36 * _TABLE_DPS)
        gmin = math.log(10) * (goal - 1) / (4 * tau_max)
        w0 = 1.5 * min(kern.dist, gmin, *norm.scales)
        self.edges = _panel_edges(w0, 0.4, 1e10)
        self.t, self.w = _panel_nodes(self.edges)
        self._mp_rules: dict[int, tuple[list, list]] = {}
        self._gmpy_rules: dict[int, tuple[list, list]] = {}
        with np.errstate(divide="ignore", invalid="ignore"):
            lr = np.log(kern.F_np(self.t) / norm.F0_np(self.t))
        self.wl = self.w * lr / math.pi
        self.t2 = self.t**2

    def log_phi_np(self, p: complex) -> complex:
        return complex(self.norm.log_phi0_np(p)) + p * complex(np.sum(self.wl / (self.t2 + p * p)))

    def h_np(self) -> float:
        return float(self.norm.h0()) - float(np.sum(self.wl / self.t2))

    def mp_rule(self, dps: int) -> tuple[list, list]:
        """The panel rule in mpmath: nodes ``t_j^2`` and ``w_j log R(t_j)/pi`` at ``dps`` digits."""
        if dps not in self._mp_rules:
            with mpmath.workdps(dps):
                f = _log_ratio_over_t2(self.kern, self.norm, dps)
                gl = mpmath.calculus.quadrature.GaussLegendre(mpmath.mp).calc_nodes(4, mpmath.mp.prec)
                t2, wl = [], []
                for a, b in zip(self.edges[:-1], self.edges[1:]):
                    a, b = mpmath.mpf(a), mpmath.mpf(b)
                    for x, w in gl:
                        t = (a + b) / 2 + (b - a) / 2 * x
                        t2.append(t * t)
                        wl.append((b - a) / 2 * w * f(t) * t * t / mpmath.pi)
            self._mp_rules[dps] = (t2, wl)
        return self._mp_rules[dps]

    def log_phi_panel_mp(self, p):
        """``log Phi(p)`` by the panel rule at the current mpmath precision: the node sums in MPFR, mpmath's bits."""
        dps = mpmath.mp.dps + 5
        if dps not in self._gmpy_rules:  # the rule's nodes and weights, exactly, as MPFR numbers
            self._gmpy_rules[dps] = tuple([to_mpfr(x) for x in v] for v in self.mp_rule(dps))
        P = p * p
        re, im = mpmath.re(P), mpmath.im(P)
        sr, si = stieltjes_sums(*self._gmpy_rules[dps], re, im * im)
        return self.norm.log_phi0_mp(p) + p * mpmath.mpc(sr, -im * si)

    def log_phi_mp(self, p, dps: int):
        f = _log_ratio_over_t2(self.kern, self.norm, dps)
        y = abs(mpmath.im(p))
        pts = sorted({y} | {float(s) for s in _breakpoints(self.kern, self.norm)[1:-1]})
        pts = [mpmath.mpf(0)] + [mpmath.mpf(s) for s in pts if s > 0] + [mpmath.inf]
        I = mpmath.quad(lambda t: f(t) * t * t / (t * t + p * p), pts)
        return self.norm.log_phi0_mp(p) + p * I / mpmath.pi


def _qhat_dehoog(laplace, tau: float, dps: int) -> mpmath.mpf:
    with mpmath.workdps(dps):
        return mpmath.invertlaplace(laplace, tau, method="dehoog")


@boundary_methods
@dataclass(frozen=True)
class WienerHopfSolution(RichDisplay):
    r"""Boundary layer ``qhat(tau)`` of (3.22), normalised so that ``qhat ~ tau + h`` (``c = pi^2 A``).

    ``q**(s, h + tau) = (vartheta H_* b_1^*(s)/A) qhat(tau)``; ``qhat(0) = 0`` (3.18).
    Build it with :func:`wiener_hopf_solution` or :func:`boundary_layer_exact`.

    Attributes
    ----------
    nu, A, m1
        Poisson ratio (exact rational), ``A`` (2.4) and ``m_1`` (2.20).
    kernel, normaliser : str
        ``"exact"``/``"alexandrov"`` and the F0 used in the factorisation.
    h : mpmath.mpf
        Edge shift (3.18) at ``dps`` digits; ``h_alexandrov`` is (3.25) for comparison.
    sigma, tau_max : float
        ``qhat - tau - h = O(e^{-sigma tau})``; the table covers ``0 <= tau <= tau_max``.
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "3.18"

    nu: sp.Rational
    kernel: str
    normaliser: str
    A: mpmath.mpf
    m1: mpmath.mpf
    h: mpmath.mpf
    h_alexandrov: mpmath.mpf
    sigma: float
    tau_max: float
    dps: int
    cheb: tuple[float, ...] = field(repr=False)
    _transform: _Transform = field(repr=False, compare=False)

    # ------------------------------------------------------------------ transforms
    def laplace(self, p: Any, dps: int | None = None):
        """``int_0^oo qhat e^{-p tau} dtau = 1/(p^2 Phi(p))`` for ``Re p > 0`` (mpmath quadrature)."""
        dps = self.dps if dps is None else _check_dps(dps)
        with mpmath.workdps(dps):
            p = mpmath.mpmathify(p)
            if mpmath.re(p) <= 0:
                raise InputError(f"the Laplace variable needs Re p > 0, got p = {p}")
            return 1 / (p * p * mpmath.exp(self._transform.log_phi_mp(p, dps)))

    def q(self, tau: Any, dps: int = 15, method: str = "panel") -> mpmath.mpf:
        """``qhat(tau)`` in mpmath by de Hoog inversion of ``1/(p^2 Phi(p))``.

        Parameters
        ----------
        tau : Any
            distance from the edge, ``tau >= 0``.
        dps : int
            working precision; the result has about ``dps - 3`` correct digits (``method="panel"``:
            at most ~20, the panel rule's accuracy).
        method : str
            ``"panel"`` (``Phi`` from the Gauss--Legendre panel rule in mpmath, ~0.5 s; for
            ``tau > tau_max`` returns ``tau + h``, exact to ``e^{-36}``) or ``"quad"`` (adaptive
            :func:`mpmath.quad` per Laplace abscissa: independent of the panel rule, ~10 s).
        """
        dps = _check_dps(dps)
        _check_choice(method, ("panel", "quad"), "method")
        with mpmath.workdps(dps):
            tau = mpmath.mpf(tau)
            if tau < 0:
                raise InputError(f"tau must be >= 0 (distance from the edge), got {tau}")
            if tau == 0:
                return mpmath.mpf(0)
            tr = self._transform
            if method == "panel":
                if tau > self.tau_max:
                    return tau + self.h

                def lap(p):
                    return 1 / (p * p * mpmath.exp(tr.log_phi_panel_mp(p)))
            else:

                def lap(p):
                    return 1 / (p * p * mpmath.exp(tr.log_phi_mp(p, mpmath.mp.dps)))

            return _qhat_dehoog(lap, tau, dps)

    def table_check(self, tau: Any) -> np.ndarray:
        """``q̂(τ) - τ`` at ``0 < τ <= tau_max`` by the table's own route (de Hoog on the panel rule, double
        precision), to check a table (shipped, or from the disk cache) against the code that built it.
        """
        tau = np.atleast_1d(np.asarray(tau, dtype=float))
        if np.any(tau <= 0) or np.any(tau > self.tau_max):
            raise InputError(f"tau must lie in (0, tau_max = {self.tau_max:.6g}]")
        return _table_values(self._transform, tau)

    def q_numpy(self, tau: Any) -> np.ndarray:
        """``qhat(tau)`` vectorised (Chebyshev series in ``sqrt(tau)``, ``tau + h`` beyond ``tau_max``)."""
        tau = np.asarray(tau, dtype=float)
        if np.any(tau < 0) or not np.all(np.isfinite(tau)):
            raise InputError("tau must be finite and >= 0 (distance from the edge)")
        z = np.sqrt(np.minimum(tau, self.tau_max))
        zmax = math.sqrt(self.tau_max)
        g = np.polynomial.chebyshev.chebval(2 * z / zmax - 1, np.asarray(self.cheb))
        return np.where(tau < self.tau_max, tau + g, tau + float(self.h))

    def pressure(self, v: Any, scale: Any = 1.0) -> np.ndarray:
        """``scale * Qhat(v)``: ``qhat(v - h)`` for ``v > h``, 0 otherwise (v measured from the contour Gamma_0)."""
        v = np.asarray(v, dtype=float)
        tau = v - float(self.h)
        return float(scale) * np.where(tau > 0, self.q_numpy(np.maximum(tau, 0.0)), 0.0)

    # ------------------------------------------------------------------ derived numbers
    @property
    def edge_coefficient(self) -> mpmath.mpf:
        """``lim qhat/sqrt(tau) = 2 sqrt(A/pi)`` at the edge (``F ~ 1/|s|``: half-space square root)."""
        with mpmath.workdps(self.dps):
            return 2 * mpmath.sqrt(self.A / mpmath.pi)

    def force_defect(self) -> float:
        """``int (Qhat(v) - max(v, 0)) dv = int_0^oo (qhat - tau - h) dtau - h^2/2`` (numerical; = m_1/2)."""
        zmax = math.sqrt(self.tau_max)
        c = np.polynomial.chebyshev.Chebyshev(np.asarray(self.cheb), domain=[0, zmax])
        # int_0^tau_max (g(z) - h) 2 z dz with g = qhat - tau, a Chebyshev series in z
        z = np.polynomial.chebyshev.Chebyshev.identity(domain=[0, zmax])
        prim = ((c - float(self.h)) * 2 * z).integ()
        val = prim(zmax) - prim(0.0)
        return float(val) - float(self.h) ** 2 / 2

    def latex(self) -> str:
        if self.nu == FRICTIONLESS:
            which = r"\text{frictionless base}"
        else:  # a float nu is kept as its exact binary value: show it as the float
            nu = self.nu if self.nu.q < 10**6 else sp.Float(float(self.nu), 15)
            which = rf"\nu = {normal_latex(nu, digits=15)}"
        return (rf"h^* = {mpmath.nstr(self.h, 12)}\ ({which},\ \text{{{self.kernel} kernel}}),"
                rf"\quad \tilde h^* = {mpmath.nstr(self.h_alexandrov, 12)} \tag{{3.25}}")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        if isinstance(self.nu, str):
            which = "frictionless base"
        else:  # a float nu is kept as its exact binary value: show it as the float
            which = f"ν = {fmt(self.nu) if self.nu.q < 10**6 else fmt(float(self.nu), 15)}"
        return [
            f"WienerHopfSolution: {self.kernel} kernel, {which} (normaliser {self.normaliser})   (3.18), (3.22)",
            f"  h* = {fmt(self.h)}   (Alexandrov (3.25): {fmt(self.h_alexandrov)})",
            f"  𝒜 = {fmt(self.A)}, m₁ = {fmt(self.m1)}",
            f"  q̂(τ) - τ - h* = O(exp(-{self.sigma:.6g} τ)); table for 0 <= τ <= {self.tau_max:.6g}",
        ]


def _table_values(tr: _Transform, tau: np.ndarray) -> np.ndarray:
    def lap(p):
        pc = complex(p)
        return mpmath.mpc(1 / (pc * pc * np.exp(tr.log_phi_np(pc))))

    return np.array([float(_qhat_dehoog(lap, float(t), _TABLE_DPS)) - float(t) for t in tau])


def _build_table(tr: _Transform, tau_max: float, n: int) -> np.ndarray:
    zmax = math.sqrt(tau_max)
    x = np.cos(np.pi * (np.arange(n) + 0.5) / n)
    return np.polynomial.chebyshev.chebfit(x, _table_values(tr, (0.5 * zmax * (x + 1)) ** 2), n - 1)


@lru_cache(maxsize=64)
def _solution(nu: sp.Rational, kernel: str, normaliser: str, dps: int, n: int | None,
              fresh: bool = False) -> WienerHopfSolution:
    lay = _layer(nu)
    h = _edge_shift(lay, kernel, normaliser, dps)
    with mpmath.workdps(dps):
        kern = _Kernel(lay, kernel, 3 * dps + 20)
        norm = _Normaliser(kern, normaliser)
    tau_max = 36.0 / kern.sigma
    tr = _Transform(kern, norm, tau_max)

    def table() -> np.ndarray:
        if n:
            return _build_table(tr, tau_max, n)
        m = 64 if tau_max <= 64 else 128  # double m until the Chebyshev tail is below 2e-11 (scale: 1 + |h|)
        while True:
            cheb = _build_table(tr, tau_max, m)
            if np.max(np.abs(cheb[-8:])) < 2e-11 * (1 + abs(float(h))) or m >= 512:
                return cheb
            m *= 2

    # the table (seconds of de Hoog inversions): shipped for common nu (_wiener_hopf_tables), else kept on disk per
    # argument set (thinlayer._cache); ``fresh`` computes it now (the builder of the shipped file, the tests)
    cheb = table() if fresh else shipped_table(str(nu), kernel, normaliser, dps, n)
    if cheb is None:
        cheb = cached("wiener_hopf_table", (nu, kernel, normaliser, dps, n), table)
    with mpmath.workdps(dps):
        ha = edge_shift_alexandrov(nu)
        A, m1 = _mp(lay.A), _mp(lay.m1)
    return WienerHopfSolution(nu, kernel, normaliser, A, m1, h, ha, kern.sigma, tau_max, dps,
                              tuple(float(c) for c in cheb), tr)


def wiener_hopf_solution(nu: Any, kernel: str = "exact", normaliser: str = "alexandrov",
                         dps: int = 20, n: int | None = None) -> WienerHopfSolution:
    """Solve (3.22) with (3.18) for the exact kernel (2.3) or Alexandrov's (3.19).

    Parameters
    ----------
    nu : Any
        Poisson ratio in (-1, 1/2) or a numeric :class:`~thinlayer.BondedLayer`.
    kernel, normaliser : str
        see :func:`edge_shift`.
    dps : int
        precision of ``h`` and of :meth:`WienerHopfSolution.q`.
    n : int | None
        number of Chebyshev nodes of the numpy table; ``None`` (default) doubles it from 64
        until the trailing coefficients are below ``2e-11 (1 + |h|)`` (the table is built once
        per argument set and cached: ~3 s for 64 nodes).

    Returns
    -------
    WienerHopfSolution
        ``h``, ``q`` (mpmath), ``q_numpy`` (vectorised); ``q_numpy`` agrees with ``q`` to ~1e-11
        (checked for -0.999 <= nu <= 0.499).
    """
    _check_choice(kernel, KERNELS, "kernel")
    _check_choice(normaliser, NORMALISERS, "normaliser")
    return _solution(_rational_nu(nu), kernel, normaliser, _check_dps(dps), _table_nodes(n))


def _table_nodes(n: Any) -> int | None:
    if n is not None and (isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < 8):
        raise InputError(f"n must be None or an integer >= 8, got {n!r}")
    return None if n is None else int(n)


def fresh_table(nu: Any, kernel: str = "exact", normaliser: str = "alexandrov", dps: int = 20,
                n: int | None = None) -> np.ndarray:
    """The Chebyshev table of :meth:`WienerHopfSolution.q_numpy` computed now, by de Hoog inversion (no shipped
    table, no disk cache): the arguments of :func:`wiener_hopf_solution`.
    """
    _check_choice(kernel, KERNELS, "kernel")
    _check_choice(normaliser, NORMALISERS, "normaliser")
    return np.array(_solution(_rational_nu(nu), kernel, normaliser, _check_dps(dps), _table_nodes(n), True).cheb)


@boundary
def boundary_layer_exact(nu: Any, dps: int = 20, n: int | None = None) -> WienerHopfSolution:
    """Exact boundary layer (3.15)-(3.18) of the bonded layer (2.3): see :func:`wiener_hopf_solution`."""
    return wiener_hopf_solution(nu, "exact", "alexandrov", dps, n)


# ----------------------------------------------------------------------------- the kernel N
def boundary_kernel_N(nu: Any, t: Any) -> np.ndarray:
    r"""``N(t) = pi int_0^oo F(s) cos(s t) ds`` (3.17) for the exact kernel, vectorised over t.

    Split ``F = tanh(A s)/s + D(s)``: ``pi int_0^oo tanh(A s) cos(s t)/s ds = pi log coth(pi |t|/(4A))``
    carries the logarithmic singularity at ``t = 0``; ``D`` is smooth, ``D(0) = 0`` and decays like
    ``e^{-2 min(A, 1) s}``, and its cosine transform is a composite Gauss--Legendre sum (double
    precision, ~1e-12 absolute).
    """
    t = np.abs(np.asarray(t, dtype=float))
    if not np.all(np.isfinite(t)):
        raise InputError("t must be finite")
    tmax = 2.0 ** math.ceil(math.log2(max(float(np.max(t, initial=1.0)), 1.0)))
    A, s, wD = _N_rule(_rational_nu(nu), tmax)
    with np.errstate(divide="ignore"):
        sing = np.pi * np.log(1 / np.tanh(np.pi * t / (4 * A)))
    return sing + np.pi * (np.cos(np.multiply.outer(t, s)) @ wD)


@lru_cache(maxsize=32)
def _N_rule(nu: sp.Rational, tmax: float) -> tuple[float, np.ndarray, np.ndarray]:
    kern = _Kernel(_layer(nu), "exact", 40)
    A = kern.Af
    s, w = _panel_rule(min(0.25, kern.dist, 4.0 / tmax), 0.0, 40.0 / min(A, 1.0))
    return A, s, w * (kern.F_np(s) - np.tanh(A * s) / s)

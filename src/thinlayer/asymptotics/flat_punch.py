r"""Flat-ended cylindrical punch: the stiffness ``kappa(a/H)`` of thin and thick layers (F.10)-(F.19).

The stiffness is defined by ``P = 4 mu a w0 kappa/(1 - nu) = 4 vartheta a w0 kappa`` (F.1), ``lambda = a/H``;
its exact value comes from the Fredholm equation (F.6)-(F.7) of :mod:`thinlayer.numerics.flat_punch`, which
this module never imports (it is the independent reference the expansions are measured against).  Equation
tags ``F.n`` are this module's own.

Thin layer (lambda -> oo)
-------------------------
(F.10) *Inner pressure.*  A flat punch is the limit ``R -> oo`` of the paraboloid ``Phi = r^2/(2R)``; the inner
expansion (2.26)-(2.31), (4.1) of :func:`~thinlayer.asymptotics.inner.inner_pressure` then keeps only its
first term, ``p_0 = vartheta w0/(A H)`` (every ``Delta^k`` of a constant vanishes: the inner pressure is exact
to all algebraic orders).  Over the disc, ``P_0 = pi a^2 p_0``, hence

    kappa_0 = pi lambda / (4 A).                                                                     (F.10)

(F.11) *Edge layer.*  Near the edge, with ``tau = (a - r)/H``, the boundary-layer equation of section 4, (3.15),
(3.17), has the flat punch's right side, a constant: ``int_0^oo q(tau') N(tau' - tau) dtau' = c`` for
``tau > 0``, and no condition ``q(0) = 0`` (the edge is fixed; the pressure is singular there).  With the
Wiener-Hopf factors of :mod:`thinlayer.asymptotics.wiener_hopf` (``F = L(s)/s = F+ F-``, ``F-(w) = F+(-w)``,
``F+(0)^2 = A``), transforming the extended equation gives ``pi^2 F(w) Q+(w) = c i/w + G-(w)``; dividing by
``F-`` and removing the pole at ``w = 0`` (Liouville: ``F+ ~ w^{-1/2}``, ``Q+ = O(w^{-1/2})``, an edge
singularity ``tau^{-1/2}``)::

    Q+(w) = i c / (pi^2 F-(0) w F+(w)),      i.e.   int_0^oo q e^{-p tau} dtau = (c/(pi^2 A)) / (p Phi(p)),

with ``Phi(p) = F+(ip)/F+(0) = 1 - h p + O(p^2)`` and ``h = -i (log F+)'(0)`` the exact edge shift of (3.18)
(:func:`~thinlayer.asymptotics.wiener_hopf.edge_shift_exact`).  So the flat-punch edge layer is the
``tau``-derivative of the smooth punch's (whose transform is ``1/(p^2 Phi)``), it tends to
``q_oo = c/(pi^2 A) = p_0`` and carries the excess force ``int_0^oo (q - p_0) dtau = p_0 h`` per unit length
(the ``p^0`` term of ``1/(p Phi) = 1/p + h + ...``).  Along the edge ``2 pi a`` this adds ``2 pi a H h p_0``:

    kappa_2 = (pi/(4 A)) (lambda + 2 h).                                                              (F.11)

The excess force is that of the uniform pressure ``p_0`` on a ring of width ``h H``: the punch acts as if its
radius were ``a + h H``.  Resumming,

    kappa_r = (pi/(4 A)) (lambda + h)^2 / lambda.                                                     (F.12)

(F.11) and (F.12) differ by ``(pi/(4 A)) h^2/lambda``, beyond the derived order.  Measured against the exact
solver (tests): the remainder of (F.11) falls with slope -1.0 and is ``(pi/(4A)) h^2/lambda + O(lambda^-2)``
(``lambda^2`` times the remainder of (F.12) is constant to 1e-3 between ``lambda = 10`` and 40), that of (F.12)
with slope -2.0: the shifted radius is right to second order, which the first-order analysis does not prove.

(F.13) *Incompressible layer (nu = 1/2).*  ``A = 0``, and the operator (I.2) starts with
``u3 = -(c_1 H^3/vartheta) Delta p``, ``c_1 = 2/3`` (I.1) (:func:`~thinlayer.asymptotics.incompressible.
thin_layer_operator`).  On the disc ``u3 = w0``; outside, the surface bulges freely, so the outer problem is
Dirichlet's, ``p(a) = 0`` (not the free boundary (I.4): the edge is fixed), and
``p = vartheta w0 (a^2 - r^2)/(4 c_1 H^3)``, ``P = pi vartheta w0 a^4/(8 c_1 H^3)``:

    kappa_0 = pi lambda^3/(32 c_1) = 3 pi lambda^3/64.                                               (F.13)

(F.14) *Its edge layer.*  Near the edge the outer pressure grows linearly, ``p ~ g (a - r)``; the edge-layer
problem is the homogeneous half-line equation with the kernel ``F ~ c_1 w^2`` at ``w = 0``.  Factorising
``F = c_1 w^2 K``, ``K = K+ K-``, ``K+(w) = 1 + K_1 w + ...``, ``F+ = sqrt(c_1) w K+``, the admissible solution
(edge singularity ``tau^{-1/2}``, ``F+ Q+ -> 0``) is ``F+ Q+ = e/w`` (the pole is allowed: ``F-`` vanishes at
``w = 0``), i.e. ``Q+ = e/(sqrt(c_1) w^2 K+(w))``, the transform of ``q = g (tau + h)`` at large ``tau``
with ``h = -i K_1 = -(1/pi) int_0^oo log(F(t)/(c_1 t^2)) t^{-2} dt``: the edge correction (I.12) at nu = 1/2
(:func:`~thinlayer.asymptotics.incompressible.two_term_edge_shift`, ``h = 1.4591``).  The outer Dirichlet
condition moves to ``r = a + h H``; to first order ``P = pi vartheta w0 (a^4 + 4 a^3 h H)/(8 c_1 H^3)``:

    kappa_2 = (3 pi/64)(lambda^3 + 4 h lambda^2),   resummed   kappa_r = (3 pi/64)(lambda + h)^4/lambda.   (F.14)

The remainder of the two-term form is ``O(lambda)`` (observed: ``(3 pi/64) 6 h^2 lambda``, captured by the
resummed form, whose remainder is ``O(1)``).

(F.15) *Nearly incompressible layers (1/4 < nu < 1/2).*  The compressible form (F.12) needs
``lambda^2 >> m_1 ~ 1/(3(1 - 2 nu))`` (I.13).  The two-term operator (I.10),
``(H/vartheta)(c_0 p - c_1 H^2 Delta p) = w0`` (``c_0 = A``, ``c_1 = A m_1``), with the Dirichlet condition at
the shifted edge ``a_e = a + h H`` (``h`` the edge correction (I.12) of that operator) gives
``p = (vartheta w0/(c_0 H)) (1 - I_0(k r)/I_0(k a_e))``, ``k = 1/(H sqrt(m_1))``, and with
``int_0^{a_e} I_0(k r) r dr = a_e I_1(k a_e)/k``::

    kappa_u = pi (lambda + h)^4 psi(x) / (32 c_1 lambda),   x = (lambda + h)/sqrt(m_1),
    psi(x) = 8 (1 - 2 I_1(x)/(x I_0(x)))/x^2,                                                       (F.15)

``psi(0) = 1`` (F.14 at nu = 1/2) and ``psi ~ 8/x^2 - 16/x^3 + 8/x^4`` for large ``x``, which gives (F.12)
(``h_(I.12) - sqrt(m_1)`` is the paper's ``h*``).  One formula from ``nu = 1/4`` to ``nu = 1/2``.

(F.16) *Error estimate of the thin model* (:meth:`ThinFlatPunch.error_estimate`).  An envelope of the
remainders measured against the exact solver, not a derived bound: relative
``min((|m_1| + h*^2 + 0.02)/lambda^3, 2.5/lambda^2)``.  The compressible remainder of (F.12) is
``(pi/(4A)) c/lambda^2`` with ``c`` between 0.003 and 1.33 for ``-0.5 <= nu <= 0.45`` (about ``m_1/2`` plus a part
of order ``h^2``); that of (F.14), (F.15) is ``O(lambda^-2)`` relative.  The measured error is at most 0.7 times
the estimate on 26 Poisson ratios in ``[-0.99, 1/2]`` (frictionless base included) and 13 values
``1 <= lambda <= 200`` (a sample is tested, the whole grid with ``THINLAYER_SLOW=1``).

Thick layer (lambda -> 0)
-------------------------
(F.17) Expand the kernel of (F.6): ``cos(lambda u x) cos(lambda u y)`` in powers of ``lambda`` integrates term by
term against ``1 - L(u) = O(u^2 e^{-2u})`` (2.4), with the moments ``b_n = int_0^oo u^{2n} (1 - L(u)) du``::

    k(x, y) = (2/pi) sum_n (-1)^n lambda^{2n+1} b_n sum_{j+l=n} x^{2j} y^{2l} / ((2j)! (2l)!),          (F.17)

a degenerate kernel at each order.  (F.18) With ``f = sum_k lambda^k f_k`` (polynomials in ``x^2``),
``f_0 = 1`` and ``f_k = sum_{2n+1 <= k} K_n f_{k-2n-1}``, ``K_n`` the ``lambda^{2n+1}`` part of (F.17)
acting through the moments ``int_0^1 y^{2l} f dy``; by (F.7)

    kappa = sum_k c_k lambda^k,   c_1 = 2 b_0/pi,   c_2 = c_1^2,   c_3 = c_1^3 - 2 b_1/(3 pi),  ...    (F.18)

polynomials in ``b_n/pi`` with rational coefficients (:func:`thick_flat_punch_coefficients`); for the bonded
layer the ``b_n`` are functions of nu, evaluated by mpmath quadrature (:func:`flat_punch_moments`).  The
kernel is analytic for ``|Im lambda| < 1`` only, and the series converges for ``lambda`` below about 0.8.
(F.19) Error estimate: the last two terms, ``(|c_N lambda^N| + |c_{N-1} lambda^{N-1}|)/kappa``; none beyond
``lambda = 0.8`` (inf).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, InputTypeError, check_bounded, check_int
from ..display import RichDisplay, fmt
from ..layers.kernels import GenericLayer, IncompressibleLayer, LayerKernel
from ..normal import join_signed, normal_latex
from ..punch import Punch
from .force_law import layer_label
from .incompressible import thin_layer_operator, two_term_edge_shift
from .inner import inner_pressure
from .wiener_hopf import edge_shift_exact

__all__ = [
    "MAX_THICK_ORDER",
    "THICK_LIMIT",
    "ThickFlatPunch",
    "ThinFlatPunch",
    "flat_punch_moments",
    "lam",
    "psi",
    "thick_flat_punch",
    "thick_flat_punch_coefficients",
    "thin_flat_punch",
    "thin_flat_punch_derivation",
]

#: lambda = a/H, the variable of every formula here
lam = sp.Symbol("lambda", positive=True)
#: punch radius, disc radius of the outer problem, radial coordinate
_a, _ae, _r = sp.symbols("a a_e r", positive=True)
#: largest order of the thick series (order 40 takes 0.1 s numerically)
MAX_THICK_ORDER = 40
#: beyond this lambda the thick series is not used (it converges below ~0.8; estimate inf)
THICK_LIMIT = 0.8


# =============================================================================================
# the layer
# =============================================================================================
def _check_layer(layer: Any) -> LayerKernel:
    """A layer of finite thickness with a numeric kernel; the frictionless base (nu-free) as one cache key."""
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer LayerKernel (BondedLayer(0.3), FrictionlessLayer(), "
                        f"IncompressibleLayer()), got {layer!r} ({type(layer).__name__})")
    if not layer.has_thickness or layer.symbolic_coefficients or layer.parameter is not None:
        raise InputError(f"the flat-punch asymptotics need a layer of finite thickness with a numeric kernel: "
                         f"BondedLayer(0.3), FrictionlessLayer() or IncompressibleLayer(); got {layer!r}")
    return layer.kernel_key  # a frictionless kernel does not depend on nu: one cache entry


def _regime(layer: LayerKernel) -> str:
    """``"compressible"`` (frictionless base or nu <= 1/4), ``"two-term"`` or ``"incompressible"``."""
    if not layer.has_compressible_expansion:
        return "incompressible"
    if layer.has_two_term_model and layer.numeric_nu > 0.25:  # m_1 > 0: the two-term operator (I.10) is elliptic
        return "two-term"
    return "compressible"


# =============================================================================================
# thin layer: the derivation (symbolic, once)
# =============================================================================================
@dataclass(frozen=True)
class ThinDerivation:
    """The symbolic steps (F.10)-(F.15): generic in ``A``, ``c_1``, ``m_1``, ``h`` (symbols).

    Attributes
    ----------
    p0 : sympy.Expr
        Inner pressure of the flat punch (F.10): ``vartheta delta_0/(A H)``.
    leading, two_term, resummed : sympy.Expr
        sympy.Expr
        ``kappa`` of (F.10), (F.11), (F.12) in ``lambda``, ``A``, ``h``.
    incompressible_pressure : sympy.Expr
        ``p(r)`` of (F.13) on the disc ``r < a_e``.
    incompressible_leading, incompressible_two_term, incompressible_resummed : sympy.Expr
        sympy.Expr
        (F.13), (F.14) in ``lambda`` and ``h`` (``c_1 = 2/3``, ``vartheta = 2 mu``).
    """

    p0: sp.Expr
    leading: sp.Expr
    two_term: sp.Expr
    resummed: sp.Expr
    incompressible_pressure: sp.Expr
    incompressible_leading: sp.Expr
    incompressible_two_term: sp.Expr
    incompressible_resummed: sp.Expr

    A = GenericLayer.A_symbol
    c1 = sp.Symbol("c_1", positive=True)
    h = sp.Symbol("h", real=True)


def _kappa_of_force(P: sp.Expr, vartheta: sp.Expr = S.vartheta) -> sp.Expr:
    """``kappa = P/(4 vartheta a w0)`` (F.1) written in ``lambda`` (``a = lambda H``, ``w0 = delta_0``)."""
    return sp.simplify((P / (4 * vartheta * _a * S.delta0)).subs(_a, lam * S.H))


@lru_cache(maxsize=1)
def thin_flat_punch_derivation() -> ThinDerivation:
    """(F.10)-(F.14) derived with the engine's stages (cached; ~1 s).

    (F.10): the paraboloid's inner pressure (:func:`inner_pressure` on the GenericLayer, symbols ``A``,
    ``m_n``) as ``R -> oo``; (F.13): the operator (I.2) of the incompressible layer
    (:func:`thin_layer_operator`, ``c_0 = 0``, ``c_1 = 2/3``, ``vartheta = 2 mu``) applied to ``C (a_e^2 - r^2)``.
    """
    d = ThinDerivation
    R = sp.Symbol("R", positive=True)
    ip = inner_pressure(GenericLayer(), Punch.paraboloid(R))
    p0 = sp.limit(ip.pressure, R, sp.oo)  # (F.10): the flat punch as R -> oo; every Delta^k of a constant is 0
    leading = _kappa_of_force(sp.pi * _a**2 * p0)
    # (F.11): the edge layer's excess force 2 pi a (h H) p0; (F.12): the disc of radius a + h H
    two_term = _kappa_of_force(sp.pi * _a**2 * p0 + 2 * sp.pi * _a * d.h * S.H * p0)
    resummed = sp.factor(_kappa_of_force(sp.pi * (_a + d.h * S.H) ** 2 * p0))
    # (F.13): u3 = w0 on the disc with the operator (I.2) through Delta, p = C (a_e^2 - r^2)
    op = thin_layer_operator(IncompressibleLayer(), 1)
    C = sp.Symbol("C")
    u3 = sp.expand(op.apply(C * (_ae**2 - S.x1**2 - S.x2**2)))
    Csol = sp.solve(sp.Eq(u3, S.delta0), C)[0]
    p_inc = Csol * (_ae**2 - _r**2)
    P_inc = sp.integrate(2 * sp.pi * p_inc * _r, (_r, 0, _ae))
    vt = op.vartheta
    inc_leading = _kappa_of_force(P_inc.subs(_ae, _a), vt)
    # (F.14): the Dirichlet condition at a_e = a + h H; first order in h, and resummed
    inc_resummed = sp.factor(_kappa_of_force(P_inc.subs(_ae, _a + d.h * S.H), vt))
    t = sp.Symbol("t")
    inc_two = sp.expand(sp.series(inc_resummed.subs(d.h, d.h * t), t, 0, 2).removeO().subs(t, 1))
    return ThinDerivation(p0, leading, sp.expand(two_term), resummed, p_inc, inc_leading, inc_two, inc_resummed)


def _incompressible_c1() -> sp.Expr:
    """``c_1`` of the operator (I.2) at nu = 1/2 (its leading coefficient, from (I.1))."""
    return thin_layer_operator(IncompressibleLayer(), 1).c[1]


# =============================================================================================
# psi(x) of (F.15)
# =============================================================================================
def _psi_series(terms: int = 32) -> list[Fraction]:
    """Maclaurin coefficients of ``psi`` in ``y = x^2/4``: ``psi = 2 (1 - (2 I_1/x)/I_0)/y``.

    ``I_0 = sum y^k/(k!)^2``, ``2 I_1/x = sum y^k/(k! (k+1)!)``; exact power-series division.
    """
    b = [Fraction(1, math.factorial(k) ** 2) for k in range(terms + 1)]
    a = [Fraction(1, math.factorial(k) * math.factorial(k + 1)) for k in range(terms + 1)]
    q = []  # a/b
    for k in range(terms + 1):
        q.append((a[k] - sum(q[j] * b[k - j] for j in range(k))) / b[0])
    one_minus = [-c for c in q]
    one_minus[0] += 1  # = 0
    return [2 * c for c in one_minus[1:]]  # psi = 2 (1 - q)/y


_PSI = [float(c) for c in _psi_series()]


def psi(x: Any) -> np.ndarray:
    """``psi(x) = 8 (1 - 2 I_1(x)/(x I_0(x)))/x^2`` of (F.15), vectorised, ``psi(0) = 1``.

    Series in ``y = x^2/4`` below ``x = 1`` (no cancellation; its radius is ``y = j_{0,1}^2/4 = 1.45``, the first
    zero of ``I_0(2 sqrt(y))``, so 32 terms reach 1e-22 at ``x = 1``), scaled Bessel functions above.
    """
    from scipy import special

    x = np.asarray(x, dtype=float)
    small = x < 1.0
    y = (x * x) / 4.0
    ser = np.polynomial.polynomial.polyval(np.where(small, y, 0.0), _PSI)
    xs = np.where(small, 1.0, x)
    with np.errstate(over="ignore"):
        big = 8.0 * (1.0 - 2.0 * special.ive(1, xs) / (xs * special.ive(0, xs))) / (xs * xs)
    return np.where(small, ser, big)


# =============================================================================================
# thin layer: numbers per layer
# =============================================================================================
@dataclass(frozen=True)
class ThinFlatPunch(RichDisplay):
    """Thin-layer stiffness of a flat punch on one layer (F.10)-(F.16); every method is vectorised in ``lambda``.

    Attributes
    ----------
    layer : LayerKernel
        The layer.
    regime : str
        ``"compressible"`` (frictionless base, or nu <= 1/4), ``"two-term"`` (1/4 < nu < 1/2) or
        ``"incompressible"`` (nu = 1/2).
    A, m1 : float
        float
        ``A`` (2.4) and ``m_1`` (2.20) (``A = 0``, ``m_1 = inf`` at nu = 1/2).
    h : float
        The edge shift of the two-term form: the paper's ``h*`` (3.18) (compressible), ``h(1/2)`` (I.12).
    h_model : float
        The edge correction (I.12) of the two-term operator (nearly incompressible, nu = 1/2); nan otherwise.
    c1 : float
        ``c_1 = A m_1`` (2/3 at nu = 1/2).
    """

    layer: LayerKernel
    regime: str
    A: float
    m1: float
    h: float
    h_model: float
    c1: float

    equation = "F.12"

    def _x(self, a_over_H: Any) -> np.ndarray:
        x = np.asarray(a_over_H, dtype=float)
        if not np.all(np.isfinite(x)) or np.any(x <= 0):
            raise InputError("a_over_H must be finite and positive")
        return x

    def leading(self, a_over_H: Any) -> np.ndarray:
        """``pi lambda/(4A)`` (F.10), or ``3 pi lambda^3/64`` at nu = 1/2 (F.13)."""
        x = self._x(a_over_H)
        if self.regime == "incompressible":
            return math.pi * x**3 / (32.0 * self.c1)
        return math.pi * x / (4.0 * self.A)

    def two_term(self, a_over_H: Any) -> np.ndarray:
        """``(pi/(4A))(lambda + 2h)`` (F.11), or ``(3 pi/64)(lambda^3 + 4 h lambda^2)`` at nu = 1/2 (F.14)."""
        x = self._x(a_over_H)
        if self.regime == "incompressible":
            return math.pi * (x**3 + 4.0 * self.h * x**2) / (32.0 * self.c1)
        return math.pi * (x + 2.0 * self.h) / (4.0 * self.A)

    def resummed(self, a_over_H: Any) -> np.ndarray:
        """The effective-radius forms: (F.12), (F.15) for 1/4 < nu < 1/2, (F.14) at nu = 1/2."""
        x = self._x(a_over_H)
        if self.regime == "compressible":
            return math.pi * (x + self.h) ** 2 / (4.0 * self.A * x)
        xe = x + self.h_model
        arg = xe / math.sqrt(self.m1) if math.isfinite(self.m1) else np.zeros_like(xe)
        return math.pi * xe**4 * psi(arg) / (32.0 * self.c1 * x)

    def __call__(self, a_over_H: Any) -> np.ndarray:
        """The resummed form (the thin model of :func:`thinlayer.contact.flat_punch.flat_punch_stiffness`)."""
        return self.resummed(a_over_H)

    def error_estimate(self, a_over_H: Any) -> np.ndarray:
        """Relative error estimate of :meth:`resummed` (F.16): ``min((|m_1| + h*^2 + 0.02)/lambda^3, 2.5/lambda^2)``."""
        x = self._x(a_over_H)
        inc = 2.5 / x**2
        if self.regime == "incompressible":
            return inc
        hs = self.h if self.regime == "compressible" else self.h_model - math.sqrt(self.m1)
        return np.minimum((abs(self.m1) + hs * hs + 0.02) / x**3, inc)

    def latex(self) -> str:
        d = thin_flat_punch_derivation()
        if self.regime == "incompressible":
            expr = d.incompressible_resummed.subs({d.c1: sp.Rational(2, 3), d.h: sp.Float(self.h, 10)})
            return rf"\kappa \simeq {normal_latex(expr)} \tag{{F.14}}"
        if self.regime == "compressible":
            expr = d.resummed.subs({d.A: sp.Float(self.A, 10), d.h: sp.Float(self.h, 10)})
            return rf"\kappa \simeq {normal_latex(expr)} \tag{{F.12}}"
        return (rf"\kappa \simeq \frac{{\pi (\lambda + {self.h_model:.6g})^4}}{{32 \cdot {self.c1:.6g}\,\lambda}}"
                rf"\,\psi\!\left(\frac{{\lambda + {self.h_model:.6g}}}{{{math.sqrt(self.m1):.6g}}}\right) \tag{{F.15}}")

    codegen_name = "flat_punch_kappa_thin"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``(arguments, outputs)`` for code generation: ``kappa(a_over_H)`` of :meth:`resummed` ((F.12), (F.15)
        with Bessel functions, (F.14)) and its ``error_estimate`` (F.16), in this layer's numbers ``A``, ``h^*``,
        ``m_1``, ``c_1``, ``h`` (:meth:`codegen_constants`: named constants of the generated code).
        """
        x = sp.Symbol("a_over_H", positive=True)
        A, hs, m1, c1, h = (sp.Symbol(n, real=True) for n in ("A", "h^*", "m_1", "c_1", "h"))
        inc = sp.Float(2.5, 17) / x**2
        if self.regime == "incompressible":
            return (x,), {"kappa": sp.pi * (x + h) ** 4 / (32 * c1 * x), "error_estimate": inc}
        if self.regime == "compressible":
            kappa = sp.pi * (x + hs) ** 2 / (4 * A * x)
            shift = hs
        else:  # (F.15): psi(z) = 8 (1 - 2 I_1(z)/(z I_0(z)))/z^2
            xe = x + h
            z = xe / sp.sqrt(m1)
            psi_z = 8 * (1 - 2 * sp.besseli(1, z) / (z * sp.besseli(0, z))) / z**2
            kappa = sp.pi * xe**4 * psi_z / (32 * c1 * x)
            shift = h - sp.sqrt(m1)
        cubic = (sp.Abs(m1) + shift**2 + sp.Float(0.02, 17)) / x**3
        return (x,), {"kappa": kappa, "error_estimate": sp.Piecewise((cubic, cubic < inc), (inc, True))}  # the min

    def codegen_constants(self) -> dict:
        """The numbers of this layer in :meth:`codegen_expressions`, each with where it comes from."""
        f = lambda v: sp.Float(v, 17)  # noqa: E731 - the layer's numbers, to double precision
        lay = layer_label(self.layer)
        model = "incompressible" if self.regime == "incompressible" else "two-term"
        notes = {"A": (self.A, f"A({lay}) = lim L(s)/s (2.4)"),
                 "m_1": (self.m1, f"m_1({lay}): L(s)/s = A (1 + m_1 s^2 + ...) (2.20)"),
                 "h^*": (self.h, f"edge shift h*({lay}), exact Wiener-Hopf solution (3.18), (3.25)"),
                 "c_1": (self.c1, f"c_1({lay}) = A m_1, coefficient of Delta in the thin-layer operator (I.2)"),
                 "h": (self.h if self.regime == "incompressible" else self.h_model,
                       f"edge correction h({lay}) of the {model} operator (I.12)")}
        used = {"compressible": ("A", "m_1", "h^*"), "two-term": ("m_1", "c_1", "h"), "incompressible": ("c_1", "h")}
        return {sp.Symbol(n, real=True): (f(notes[n][0]), notes[n][1]) for n in used[self.regime]}

    def text_lines(self) -> list[str]:
        lines = [f"ThinFlatPunch: {self.layer}, {self.regime}   (F.10)-(F.16)"]
        if self.regime != "incompressible":
            lines.append(f"  𝒜 = {self.A:.12g}, m₁ = {self.m1:.12g}, h* = {self.h:.12g}")
            lines.append("  κ ~ (π/(4𝒜)) (λ + 2h*)   (F.11)")
        else:
            lines.append(f"  c₁ = {self.c1:.12g}, h = {self.h:.12g}")
            lines.append("  κ ~ (3π/64) (λ³ + 4h λ²)   (F.14)")
        if self.regime == "two-term":
            lines.append(f"  two-term operator (I.10): h (I.12) = {self.h_model:.12g}   (F.15)")
        return lines


@lru_cache(maxsize=64)
def _thin(layer: LayerKernel) -> ThinFlatPunch:
    regime = _regime(layer)
    if regime == "incompressible":
        c1 = float(_incompressible_c1())
        h = float(two_term_edge_shift(layer, dps=16))
        return ThinFlatPunch(layer, regime, 0.0, math.inf, h, h, c1)
    A = float(layer.A)
    m1 = float(layer.m(1))
    h = float(edge_shift_exact(layer.edge_shift_key, dps=16))
    h_model = float(two_term_edge_shift(layer, dps=16)) if regime == "two-term" else math.nan
    return ThinFlatPunch(layer, regime, A, m1, h, h_model, A * m1)


def thin_flat_punch(layer: LayerKernel) -> ThinFlatPunch:
    """The thin-layer stiffness of a flat-ended punch (F.10)-(F.16), cached per layer (0.02-0.4 s the first time).

    The first call per layer computes the edge shifts (:func:`edge_shift_exact`, (I.12)); the symbolic derivation
    (:func:`thin_flat_punch_derivation`) is needed only by ``latex()``.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` (numeric, -1 < nu < 1/2), ``IncompressibleLayer()`` or ``FrictionlessLayer()``.

    Returns
    -------
    ThinFlatPunch
        ``leading``, ``two_term``, ``resummed`` (= calling it) and ``error_estimate``, vectorised in ``a/H``.

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> thin = thin_flat_punch(BondedLayer(0.3))
    >>> round(float(thin.leading(10.0)), 6), round(float(thin.two_term(10.0)), 6)
    (19.242255, 19.712038)
    """
    return _thin(_check_layer(layer))


# =============================================================================================
# thick layer
# =============================================================================================
def _thick_recursion(order: int, b: list, pi: Any, one: Any) -> list:
    """``c_0 .. c_order`` of (F.18) for the moments ``b`` (sympy symbols or mpmath numbers), ``pi`` to match."""
    two_over_pi = 2 * one / pi
    fact = [one * math.factorial(k) for k in range(2 * order + 2)]

    def moment(fk: dict, l: int):  # int_0^1 y^{2l} f_k(y) dy
        return sum((c / (2 * i + 2 * l + 1) for i, c in fk.items()), 0 * one)

    f = [{0: one}]
    c = [one]
    for k in range(1, order + 1):
        new: dict = {}
        for n in range((k - 1) // 2 + 1):
            src = f[k - 2 * n - 1]
            for j in range(n + 1):
                l = n - j
                term = two_over_pi * (-1) ** n * b[n] * moment(src, l) / (fact[2 * j] * fact[2 * l])
                new[j] = new.get(j, 0 * one) + term
        if isinstance(one, sp.Basic):
            new = {j: sp.expand(v) for j, v in new.items()}
        f.append(new)
        c.append(moment(new, 0))
    return c


def _check_thick_order(order: Any) -> int:
    n = check_int(order, "order", 2)
    return check_bounded(n, "order", MAX_THICK_ORDER, "the series converges only for a/H < 0.8; order 40 "
                                                     "already gives 1e-4 at a/H = 0.6")


@lru_cache(maxsize=8)
def _thick_symbolic(order: int) -> tuple:
    b = [sp.Symbol(f"b_{k}", positive=True) for k in range((order - 1) // 2 + 1)]
    return tuple(sp.expand(v) for v in _thick_recursion(order, b, sp.pi, sp.Integer(1)))


def thick_flat_punch_coefficients(order: int = 6) -> tuple:
    """``c_0 .. c_order`` of ``kappa = sum c_k lambda^k`` (F.18), polynomials in ``b_k/pi`` (sympy).

    Examples
    --------
    >>> thick_flat_punch_coefficients(3)
    (1, 2*b_0/pi, 4*b_0**2/pi**2, 8*b_0**3/pi**3 - 2*b_1/(3*pi))
    """
    n = _check_thick_order(order)
    check_bounded(n, "order (symbolic)", 16, "sympy's expansion of order 16 takes 3 s; the numeric series "
                                              "(thick_flat_punch) goes to order 40")
    return _thick_symbolic(n)


@lru_cache(maxsize=64)
def _moments(layer: LayerKernel, K: int, dps: int) -> tuple:
    with mpmath.workdps(dps + 10):
        out = []
        for k in range(K + 1):
            peak = mpmath.mpf(k + 1)  # u^{2k+2} e^{-2u} peaks at u = k + 1

            def f(u, k=k):
                return u ** (2 * k) * (1 - layer.L_numeric(u, "mpmath"))

            pts = [0, mpmath.mpf(1) / 2, 1] + [peak * s for s in (2, 4, 8)] + [mpmath.inf]
            out.append(mpmath.quad(f, sorted(set(pts))))
    return tuple(+v for v in out)


def flat_punch_moments(layer: LayerKernel, K: int, dps: int = 20) -> tuple:
    """``b_k = int_0^oo u^{2k} (1 - L(u)) du``, ``k = 0..K`` (F.17), by mpmath quadrature at ``dps`` digits."""
    layer = _check_layer(layer)
    K = check_int(K, "K", 0)
    check_bounded(K, "K", MAX_THICK_ORDER, "order 2K+1 of the thick series needs b_0..b_K")
    dps = check_int(dps, "dps", 10)
    check_bounded(dps, "dps", 100, "20 digits are far more than the series' accuracy")
    return _moments(layer, K, dps)


@dataclass(frozen=True)
class ThickFlatPunch(RichDisplay):
    """The thick-layer series ``kappa = sum_k c_k lambda^k`` (F.18) for one layer, vectorised in ``lambda``.

    Attributes
    ----------
    layer : LayerKernel
        The layer.
    order : int
        Last power kept.
    coefficients : tuple of float
        ``c_0 = 1, c_1, ..., c_order``.
    """

    layer: LayerKernel
    order: int
    coefficients: tuple

    equation = "F.18"

    def __call__(self, a_over_H: Any) -> np.ndarray:
        """``sum_k c_k lambda^k`` (F.18)."""
        x = np.asarray(a_over_H, dtype=float)
        if not np.all(np.isfinite(x)) or np.any(x <= 0):
            raise InputError("a_over_H must be finite and positive")
        return np.polynomial.polynomial.polyval(x, self.coefficients)

    def partial(self, a_over_H: Any, n: int) -> np.ndarray:
        """The series truncated after ``lambda^n`` (``n <= order``)."""
        n = check_int(n, "n", 0)
        if n > self.order:
            raise InputError(f"n = {n} exceeds the order {self.order} of this series")
        return np.polynomial.polynomial.polyval(np.asarray(a_over_H, dtype=float), self.coefficients[: n + 1])

    def error_estimate(self, a_over_H: Any) -> np.ndarray:
        """Relative estimate (F.19): the last two terms; inf beyond ``lambda = 0.8``."""
        x = np.asarray(a_over_H, dtype=float)
        c = self.coefficients
        N = self.order
        xs = np.minimum(x, THICK_LIMIT)  # beyond the limit the estimate is inf (and the polynomial not evaluated)
        est = (np.abs(c[N] * xs**N) + np.abs(c[N - 1] * xs ** (N - 1))) / np.abs(self(xs))
        return np.where(x < THICK_LIMIT, est, np.inf)

    codegen_name = "flat_punch_kappa_thick"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``(arguments, outputs)`` for code generation: ``kappa(a_over_H)`` (F.18) and its ``error_estimate`` (F.19),
        which is 1 (no accuracy) from ``a/H = 0.8`` on, where the series is not used.
        """
        x = sp.Symbol("a_over_H", positive=True)
        c = [sp.Integer(1)] + [sp.Symbol(f"c_{k}", real=True) for k in range(1, self.order + 1)]  # codegen_constants
        kappa = sp.Add(*[ck * x**k for k, ck in enumerate(c)])
        N = self.order
        est = (sp.Abs(c[N] * x**N) + sp.Abs(c[N - 1] * x ** (N - 1))) / sp.Abs(kappa)
        return (x,), {"kappa": kappa, "error_estimate": sp.Piecewise((est, x < THICK_LIMIT), (1, True))}

    def codegen_constants(self) -> dict:
        """The series coefficients ``c_k`` (F.18) of this layer, named constants of the generated code."""
        lay = layer_label(self.layer)
        return {sp.Symbol(f"c_{k}", real=True): (sp.Float(self.coefficients[k], 17),
                                                 f"c_{k}({lay}): coefficient of (a/H)^{k}, thick-layer series (F.18)")
                for k in range(1, self.order + 1)}

    def latex(self) -> str:
        terms = join_signed(["1"] + [f"{self.coefficients[k]:.6g}\\,\\lambda" + (f"^{{{k}}}" if k > 1 else "")
                                     for k in range(1, min(self.order, 4) + 1)])
        return rf"\kappa = {terms} + \dots \tag{{F.18}}"

    def text_lines(self) -> list[str]:
        lines = [f"ThickFlatPunch: {self.layer}, κ = 1 + Σ c_k (a/H)^k through order {self.order}   (F.18)"]
        sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
        lines += [f"  c{str(k).translate(sub)} = {fmt(self.coefficients[k])}" for k in range(1, min(self.order, 6) + 1)]
        return lines


@lru_cache(maxsize=64)
def _thick(layer: LayerKernel, order: int) -> ThickFlatPunch:
    K = (order - 1) // 2
    with mpmath.workdps(25):
        b = list(_moments(layer, K, 20))
        c = _thick_recursion(order, b, mpmath.pi, mpmath.mpf(1))
    return ThickFlatPunch(layer, order, tuple(float(v) for v in c))


def thick_flat_punch(layer: LayerKernel, order: int = 12) -> ThickFlatPunch:
    """The thick-layer series (F.18) of the flat-punch stiffness for one layer, cached (~0.1 s the first time).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``IncompressibleLayer()`` or ``FrictionlessLayer()``.
    order : int
        Last power of ``a/H`` kept (2 <= order <= 40).

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> series = thick_flat_punch(BondedLayer(0.3))
    >>> round(float(series(0.1)), 8)
    1.09544069
    """
    return _thick(_check_layer(layer), _check_thick_order(order))

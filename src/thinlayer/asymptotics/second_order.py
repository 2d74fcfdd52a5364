r"""Second order: the boundary layer at a curved contour, the force to O(P0 (H/a)^4), the area to O(|omega_0| (H/a)^3).

The paper stops at the first approximation (3.15)-(3.25); :mod:`.force_law` carries it to the force with remainder
``O(P0 (H/a)^3)`` and the area with remainder ``O(|omega_0| (H/a)^2)``.  This module derives the next order.

Derivation (own; each step is carried out by :func:`second_order_boundary_layer` or checked in the tests)
-------------------------------------------------------------------------------------------------------
(SO.1) *The operator.*  With the normalisation of (2.1), (2.3) and (4.1) the layer's surface displacement under
the pressure ``p`` is ``u = (H/vartheta) F(H |D|) p``, ``F(s) = L(s)/s = A (1 + m_1 s^2 + ...)``, a function of the
plane's Laplacian: ``F(H|D|) = G(-H^2 Laplacian)`` with ``G(z) = F(sqrt z)``.  (The Winkler limit
``p = vartheta (delta0 - Phi)/(A H)`` is (2.27), and ``1/F = (1 - m_1 s^2)/A`` gives ``p_1`` of (4.1).)

(SO.2) *Curvilinear coordinates.*  Near Gamma_0 let ``n`` be the distance along the inward normal (3.4), ``s``
the arc length, ``kappa(s)`` the curvature (> 0 where omega_0 is convex) and ``v = n/H`` (3.7).  The Laplacian
is ``(1 - kappa n)^{-1} [d_n (1 - kappa n) d_n + d_s (1 - kappa n)^{-1} d_s]``; in ``v`` and to first order in
``eps = kappa H``:  ``-H^2 Laplacian = -d_v^2 + eps d_v + O(eps^2)`` (``d_s`` enters squared: ``O((H/a)^2)``).
``-d_v^2`` and ``d_v`` commute, so ``G(-d_v^2 + eps d_v) = G(-d_v^2) + eps G'(-d_v^2) d_v``; with the transform
``Q+(w) = int_0^oo Q e^{i w tau} dtau`` (``d_v -> -i w``) its symbol is

    S(w) = F(w) - (i eps/2) F'(w).                                                                    (SO.2)

(SO.3) *The right-hand side* to the same order (3.13)-(3.14), with ``g = |grad Phi|`` and
``Phi_nn = n^T Hess(Phi) n`` on Gamma_0:  ``delta0 - Phi = g H (v - beta v^2) + O(H^3)``, ``beta = H Phi_nn/(2 g)``
(``beta = -b_2/(b_1 eps)`` in the paper's starred variables).  Writing ``p = vartheta g Q(v)``, the boundary layer
solves, with ``Q = 0`` for ``v < h``, ``Q(h) = 0`` (3.18) and ``tau = v - h``:

    S(d) Q = (h + tau) - beta (h + tau)^2,    tau > 0.                                                 (SO.3)

(SO.4) *Factorisation.*  ``F = F+ F-`` as in :mod:`.wiener_hopf`; ``log F`` is even, so ``(log F)' = (log F+)' +
(log F-)'`` splits, and to first order ``S+ = F+ exp(-(i eps/2)(log F+)')``, ``S- = F- exp(-(i eps/2)(log F-)')``.
On ``w = i p`` with ``Psi(p) = log F+(ip) = log(sqrt(A) Phi(p))``:

    S+(ip) = sqrt(A) Phi(p) exp(-(eps/2) Phi'(p)/Phi(p)),
    log Phi(p) = -h^* p - (m_1/2) p^2 + r_3 p^3 + O(p^4)                                               (SO.4)

(the even coefficient from ``log F = log A + m_1 w^2 + ...``; ``r_3`` the second Wiener--Hopf constant,
:func:`thinlayer.asymptotics.wiener_hopf.edge_cubic`).

(SO.5) *Solution.*  ``S+ Q+ = R+/S- + G-/S-`` with ``R+ = sum_k c_k k!/(-i w)^{k+1}`` the transform of the
right-hand side.  The principal part of ``R+/S-`` at ``w = 0``, ``a_1/w + a_2/w^2 + a_3/w^3``, goes to the left;
the rest is analytic below, and Liouville (``S+ Q+ = O(w^{-3/2})``) leaves ``Q+ = (a_1/w + a_2/w^2 + a_3/w^3)/S+``.
``a_1`` would give ``Q ~ tau^{-1/2}`` at the edge; (3.18) asks ``a_1 = 0``, which fixes the edge:

    h = h^* + (eps/2 + beta) m_1 + O(eps^2).                                                           (SO.5)

(SO.6) *The boundary layer* (``qhat = A Q``, Laplace variable ``p``):

    int_0^oo qhat e^{-p tau} dtau = [(1 + eps h^*/2)/p^2 - 2 beta/p^3] (1 + (eps/2) Phi'/Phi) / Phi,     (SO.6)

that is, with ``qhat_0`` the first-order layer of :mod:`.wiener_hopf` and ``I_0(tau) = int_0^tau qhat_0``,

    qhat = qhat_0 + eps [(h^* + tau) qhat_0/2 - I_0] - 2 beta I_0.                                     (SO.7)

Far from the edge ``qhat -> (v - beta v^2) - m_1 (eps + 2 beta)``: the inner expansion ``p_0 + p_1`` (2.26), (4.1)
seen from the edge (``Laplacian(delta0 - Phi) = -Phi_nn - kappa g`` on Gamma_0), so the matching holds with no
new constant.  The edge moves by half of what ``p_0 + p_1 = 0`` alone would give.

(SO.8) *Force defect.*  ``P = iint_{omega_0} (p_0 + p_1) + oint vartheta g H D ds + O(P0 (H/a)^4)``, where, with
the area element ``(1 - kappa n) dn ds``,  ``D = int (Q - Q_in 1_{v > 0})(1 - eps v) dv``.  The constant term at
``p -> 0`` of the transforms gives

    A D = m_1/2 + r_3 (eps/2 + 2 beta) + O(eps^2).                                                     (SO.8)

(SO.9) *Force law.*  With ``g kappa = Laplacian Phi - Phi_nn`` on the level set, ``g (kappa/2 + Phi_nn/g) =
(Laplacian Phi + Phi_nn)/2``:

    P = P_0 + P_1 + P_2,   P_2 = (vartheta H^2 r_3/(2 A)) oint_{Gamma_0} (Laplacian Phi + Phi_nn) ds,     (SO.9)

remainder ``O(P0 (H/a)^4)`` (the inner ``p_2 ~ M_2 H^4`` and the next boundary-layer order).

(SO.10) *Area law.*  The contact edge is at ``n = H h(s)``, so ``|omega| = |omega_0| - oint (H h - kappa H^2 h^2/2) ds``
and, with ``oint kappa ds = 2 pi`` and ``kappa + Phi_nn/g = Laplacian Phi/g``:

    |omega| = |omega_0| - h^* H |Gamma_0| + pi h^*^2 H^2
              - (m_1 H^2/2) oint_{Gamma_0} Laplacian Phi/|grad Phi| ds,                                    (SO.10)

remainder ``O(|omega_0| (H/a)^3)``.

Closed forms of the edge integrals ``E_1 = oint (Laplacian Phi + Phi_nn) ds`` and
``E_2 = oint Laplacian Phi/|grad Phi| ds``: for ``Phi = x^T K x/2 + ...`` (eigenvalues ``l_1, l_2`` of K,
``D_0 = delta0 - min Phi``, the modulus ``k = sqrt(1 - l_2/l_1)``; on the ellipse ``ds/|grad Phi| = dt/sqrt(l_1 l_2)``)
``E_2 = 2 pi (l_1 + l_2)/sqrt(l_1 l_2)`` and
``E_1 = (l_1 + l_2) |Gamma_0| + 4 sqrt(2 D_0/(l_1 l_2)) ((l_1 + l_2) sqrt(l_1) E(k) - l_1 l_2 K(k)/sqrt(l_1))``
(``K(k)``, ``E(k)`` the complete elliptic integrals of modulus k: sympy's ``elliptic_k(m)``, ``elliptic_e(m)`` with
``m = k^2``);
for ``Phi = c r^{2k}``: ``E_1 = 4 pi k (4k - 1) c a^{2k-1}``, ``E_2 = 4 pi k``.  Any other
punch: numerical, on the spectral contour.  For the sphere ``P = P_0 (1 - 4 m_1 (H/a)^2 + 12 r_3 (H/a)^3)`` and the
contact radius is ``a - h^* H - m_1 H^2/a``.

Independent checks (tests): the direct axisymmetric solver's ``(P - P_0 - P_1)/(P_0 (H/a)^3)`` tends to ``12 r_3``
(sphere; nu = 0, 0.3, 0.45 and the frictionless base), its Richardson extrapolation gives ``12 r_3`` to 4 digits, and
the remainders of (SO.9) and (SO.10) fall at observed orders about 4 and 3; ``r_3`` agrees between three
factorisations; the far field of (SO.7) reproduces ``p_0 + p_1``.

Error estimates (relative; ``kappa_e^2 = |P_1/P_0| + (1 + h^*^2)(H/a)^2`` as in :mod:`.force_law`):
``E_P = 2 kappa_e^4 (1 + kappa_e)`` for the force and ``E_A = 2 kappa_e^3 (1 + kappa_e)`` for the area, checked against
the direct solver (tests).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, ClassVar

import mpmath
import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, InputTypeError, parse_nu, positive
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..normal import join_signed, normal_latex
from ..punch import Punch, is_polynomial_tip
from ..results import latex_equation
from .force_law import (
    ForceLaw,
    ForceValues,
    force_law,
    h_star,
    lambdify_law,
    law_arguments,
    layer_label,
    radial_monomial,
)
from .inner import inner_pressure

__all__ = [
    "EdgeConstants",
    "SecondOrderBoundaryLayer",
    "SecondOrderLaw",
    "SecondOrderValues",
    "edge_constants",
    "second_order_boundary_layer",
    "second_order_error_estimate",
    "second_order_law",
]

#: the cubic Wiener--Hopf constant (SO.4) as a symbol in the laws (its value is numeric, per nu)
r_3 = sp.Symbol("r_3", real=True)
#: symbols of the derivation: eps = kappa H, beta = H Phi_nn/(2 g), Phi(p) of (SO.4)
eps, beta, p_ = sp.symbols("epsilon beta p")
h0_, m1_ = sp.symbols("h^* m_1", real=True)
Phi_ = sp.Function("Phi")

#: order of accuracy of each second-order result, as (exponent of H/a, statement)
ORDERS = {
    "force": (4, "P = P_0 + P_1 + P_2 + O(P_0 (H/a)^4)   (SO.9)"),
    "contact_area": (3, "|omega| = (SO.10) + O(|omega_0| (H/a)^3)"),
    "pressure_composite": (2, "composite pressure with the second-order boundary layer (SO.7): O(p_max (H/a)^2)"),
}

#: safety factors of the second-order error estimates (module docstring)
ERROR_FACTORS = {"force": 2.0, "contact_area": 2.0}


# ---------------------------------------------------------------------------------------------
# (SO.4)-(SO.8): the boundary layer at second order, carried out in sympy
# ---------------------------------------------------------------------------------------------
def _truncate(expr: sp.Expr, w: sp.Symbol, lam: sp.Symbol, n: int) -> sp.Expr:
    """Keep the terms of degree <= n in w and <= 1 in lam (a polynomial in both)."""
    poly = sp.Poly(sp.expand(expr), w, lam)
    return sum((c * w**i * lam**j for (i, j), c in poly.terms() if i <= n and j <= 1), sp.Integer(0))


def _exp_series(X: sp.Expr, w: sp.Symbol, lam: sp.Symbol, n: int) -> sp.Expr:
    """``exp(X)`` to degree n in w and 1 in lam, for a polynomial X with ``X(0) = O(lam)``."""
    X0 = sp.expand(X).subs(w, 0)
    Y = _truncate(X - X0, w, lam, n)
    out, term = sp.Integer(1), sp.Integer(1)
    for k in range(1, n + 2):
        term = _truncate(term * Y / k, w, lam, n)
        out += term
    return _truncate(out * (1 + X0), w, lam, n)


@dataclass(frozen=True)
class SecondOrderBoundaryLayer(RichDisplay):
    r"""The second-order boundary layer as derived by :func:`second_order_boundary_layer` (SO.5)-(SO.8).

    Attributes (sympy, in ``epsilon = kappa H``, ``beta = H Phi_nn/(2 g)``, ``h^*``, ``m_1``, ``r_3``):
    ``edge_shift`` h of (SO.5); ``force_defect`` A D of (SO.8); ``transform`` the Laplace transform of qhat (SO.6)
    in ``p`` and ``Phi(p)``; ``far_field`` the polynomial qhat tends to, in ``v``; ``a2, a3`` the constants of (SO.5)
    (times sqrt(A)).
    """

    equation: ClassVar[str] = "SO.5"

    edge_shift: sp.Expr
    force_defect: sp.Expr
    transform: sp.Expr
    far_field: sp.Expr
    a2: sp.Expr
    a3: sp.Expr

    def latex(self) -> str:
        v = sp.Symbol("v")
        return " \\\\\n".join([
            latex_equation("h", normal_latex(self.edge_shift), "SO.5"),
            latex_equation(r"\int_0^\infty \hat q\, e^{-p\tau}\, d\tau", normal_latex(self.transform), "SO.6"),
            latex_equation(r"\hat q(v)", normal_latex(self.far_field.subs(sp.Symbol("v"), v))
                           + r" + o(1),\quad v \to \infty", None),
            latex_equation(r"\mathcal{A} D", normal_latex(self.force_defect), "SO.8"),
        ])

    def text_lines(self) -> list[str]:
        return [
            "SecondOrderBoundaryLayer   (SO.5)-(SO.8)",
            f"  h      = {fmt(self.edge_shift)}",
            f"  𝒜 D    = {fmt(self.force_defect)}",
            f"  ℒ[q̂](p) = {fmt(self.transform)}",
            f"  q̂ -> {fmt(self.far_field)}",
        ]


@lru_cache(maxsize=1)
def second_order_boundary_layer() -> SecondOrderBoundaryLayer:
    """Carry out (SO.4)-(SO.8): the Wiener--Hopf solution of (SO.3) to first order in ``eps`` and ``beta``.

    Works with the Taylor series (SO.4) of ``Psi = log F+(ip)`` (``r_4`` kept to show it drops out), the principal
    part at ``w = 0`` and the constant term of the Laplace transforms at ``p = 0``; about 1 s.
    """
    w, lam, t, r4, h1 = sp.symbols("w lambda t r_4 h_1")
    Psi = -h0_ * t - m1_ / 2 * t**2 + r_3 * t**3 + r4 * t**4  # log Phi(t) (SO.4), without log sqrt(A)
    dPsi = sp.diff(Psi, t)
    e_, b_ = lam * eps, lam * beta
    h = h0_ + lam * h1
    c0, c1, c2 = h - b_ * h**2, 1 - 2 * b_ * h, -b_  # (SO.3): c0 + c1 tau + c2 tau^2
    # sqrt(A)/S-(w) = exp(-Psi(iw) - (eps/2) Psi'(iw))   (SO.4), to w^2
    inv_Sm = _exp_series(-(Psi + e_ / 2 * dPsi).subs(t, sp.I * w), w, lam, 2)
    # w^3 R+(w) = i c0 w^2 - c1 w - 2 i c2: the principal part a1/w + a2/w^2 + a3/w^3 of R+/S-   (SO.5)
    prod = _truncate(sp.expand((sp.I * c0 * w**2 - c1 * w - 2 * sp.I * c2) * inv_Sm), w, lam, 2)
    a1, a2, a3 = (sp.expand(prod.coeff(w, k)) for k in (2, 1, 0))
    cond = _truncate(a1, w, lam, 0)
    if sp.expand(cond.coeff(lam, 0)) != 0:  # the first-order edge: h* = i (log F-)'(0)
        raise ArithmeticError(f"first-order edge condition not satisfied: {cond.coeff(lam, 0)}")
    h1_val = sp.solve(cond.coeff(lam, 1), h1)[0]
    hs = h0_ + lam * h1_val
    a2 = _truncate(a2.subs(h1, h1_val), w, lam, 0)
    a3 = _truncate(a3.subs(h1, h1_val), w, lam, 0)
    # qhat~(p) = sqrt(A) (a2/w^2 + a3/w^3)/S+(w), w = ip; p^3 qhat~ = (-a2 p + i a3) exp(-Psi(p) + (eps/2) Psi'(p))
    E = _exp_series(-Psi + e_ / 2 * dPsi, t, lam, 4)
    num = _truncate(sp.expand((-a2 * t + sp.I * a3) * E), t, lam, 5)
    c_0, c_1 = num.coeff(t, 3), num.coeff(t, 4)  # p^0 and p^1 coefficients of qhat~
    fp = (1 - e_ * hs) * c_0 + e_ * c_1  # FP int_0^oo qhat (1 - eps v) dtau, v = h + tau   (SO.8)
    v = sp.Symbol("v")
    q_in = v - b_ * v**2 - m1_ * (e_ + 2 * b_)  # p_0 + p_1 seen from the edge, in qhat units
    D = _truncate(sp.expand(fp - sp.integrate(sp.expand(q_in * (1 - e_ * v)), (v, 0, hs))), t, lam, 0)
    if D.has(r4) or h1_val.has(r4):
        raise ArithmeticError("r_4 should not enter at this order")
    # far field: the polynomial part of qhat, from the poles of qhat~ at p = 0 (tau^k <-> k!/p^(k+1))
    tau = sp.Symbol("tau")
    far = sum((num.coeff(t, j) * tau ** (2 - j) / sp.factorial(2 - j) for j in range(3)), sp.Integer(0))
    far = _truncate(sp.expand(far.subs(tau, v - hs)), v, lam, 2)
    one = {lam: 1}
    transform = ((-a2 / p_**2 + sp.I * a3 / p_**3) * (1 + e_ / 2 * sp.diff(Phi_(p_), p_) / Phi_(p_)) / Phi_(p_))
    transform = sp.expand(sp.series(transform, lam, 0, 2).removeO()).subs(one)
    return SecondOrderBoundaryLayer(
        edge_shift=sp.collect(sp.expand(hs.subs(one)), m1_),
        force_defect=sp.collect(sp.expand(D.subs(one)), r_3),
        transform=sp.collect(transform, [eps, beta]),
        far_field=sp.collect(sp.expand(far.subs(one)), [eps, beta]),
        a2=sp.expand(a2.subs(one)),
        a3=sp.expand(a3.subs(one)),
    )


# ---------------------------------------------------------------------------------------------
# the constants of a layer
# ---------------------------------------------------------------------------------------------
@boundary_methods
@dataclass(frozen=True)
class EdgeConstants(RichDisplay):
    """``h^*`` (3.18), ``m_1`` (2.20) and ``r_3`` (SO.4) of one layer; ``r3_spread`` = largest difference of r_3
    between the three factorisations of :mod:`.wiener_hopf` (an independent check of its digits).
    """

    equation: ClassVar[str] = "SO.4"

    key: Any
    A: float
    m1: float
    h_star: float
    r3: float
    r3_spread: float

    @property
    def sphere_coefficient(self) -> float:
        """``12 r_3``: ``P = P_0 (1 - 4 m_1 (H/a)^2 + 12 r_3 (H/a)^3)`` for the sphere (SO.9)."""
        return 12 * self.r3

    def latex(self) -> str:
        return (rf"h^* = {self.h_star:.10g},\quad m_1 = {self.m1:.10g},\quad r_3 = {self.r3:.10g}"
                r" \tag{SO.4}")

    def text_lines(self) -> list[str]:
        which = self.key
        if which != "frictionless" and len(which) > 12:  # a float nu kept as its exact binary value: show the float
            which = fmt(float(sp.Rational(which)))
        which = "frictionless base" if which == "frictionless" else f"ν = {which}"
        return [f"EdgeConstants ({which}):   (SO.4)",
                f"  h* = {fmt(self.h_star)}, m₁ = {fmt(self.m1)}, r₃ = {fmt(self.r3)}  (spread over factorisations "
                f"{self.r3_spread:.1e})",
                f"  sphere: P = P₀ (1 - 4m₁ (H/a)² + {fmt(12 * self.r3)} (H/a)³)"]


@lru_cache(maxsize=128)
def _edge_constants(key: Any, dps: int) -> EdgeConstants:
    from .wiener_hopf import edge_cubic, edge_shift

    nu = key if key == "frictionless" else sp.Rational(*key)
    rs = [edge_cubic(nu, normaliser=n, dps=dps) for n in ("alexandrov", "sqrt", "tanh")]
    lay = _layer_of(nu)
    return EdgeConstants(str(nu), float(lay.A), float(lay.m(1)), float(edge_shift(nu, dps=dps)), float(rs[0]),
                         float(max(rs) - min(rs)))


def _layer_of(key: Any) -> LayerKernel:
    from ..layers.kernels import BondedLayer, FrictionlessLayer

    return FrictionlessLayer() if key == "frictionless" else BondedLayer(key)


@boundary
def edge_constants(layer: Any, dps: int = 20) -> EdgeConstants:
    """``h^*``, ``m_1``, ``r_3`` of a layer (``BondedLayer(nu)`` with a numeric nu, ``FrictionlessLayer()``, or nu).

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> c = edge_constants(BondedLayer(0.3))
    >>> print(f"{c.r3:.9f} {c.sphere_coefficient:.6f}")
    0.053008374 0.636100
    """
    if isinstance(layer, LayerKernel):
        key = layer.edge_shift_key  # the exact nu (a float as its binary value), or "frictionless"
    elif isinstance(layer, str) and layer == "frictionless":
        key = layer
    else:
        key = parse_nu(layer, floats="exact", symbols=False, example="0.3, '3/10' or BondedLayer(0.3)")
    # cached by (numerator, denominator): a float's exact binary value has 17 digits, more than nu text may have
    return _edge_constants(key if key == "frictionless" else (int(key.p), int(key.q)), int(dps))


# ---------------------------------------------------------------------------------------------
# (SO.9), (SO.10): the laws
# ---------------------------------------------------------------------------------------------
@boundary_methods
@dataclass(frozen=True)
class SecondOrderValues:
    """Numbers of the second-order laws at one point.  ``first`` the first-order :class:`ForceValues`
    (its ``edge_shift`` is h^*); ``P2`` (SO.9); ``area2`` the ``H^2`` terms of (SO.10); ``E1, E2`` the edge integrals;
    ``P_inner_next = iint_{omega_0} p_2`` the first neglected inner term (2.26), part of the error estimate.
    """

    first: ForceValues
    P2: float
    area2: float
    E1: float
    E2: float
    r3: float
    m1: float
    P_inner_next: float = 0.0

    @property
    def P0(self) -> float:
        return self.first.P0

    @property
    def P1(self) -> float:
        return self.first.P1

    @property
    def force(self) -> float:
        return self.first.P0 + self.first.P1 + self.P2

    @property
    def force_first(self) -> float:
        return self.first.force

    @property
    def area0(self) -> float:
        return self.first.area0

    @property
    def perimeter(self) -> float:
        return self.first.perimeter

    @property
    def area(self) -> float:
        return self.first.area + self.area2

    @property
    def area_first(self) -> float:
        return self.first.area

    @property
    def H_over_a(self) -> float:
        return self.first.H_over_a


def second_order_error_estimate(values: SecondOrderValues) -> dict[str, float]:
    """Relative error estimates of (SO.9) and (SO.10): ``2 k^4 (1 + k) + 2 |iint p_2|/P_0`` and ``2 k^3 (1 + k)``,
    ``k^2 = |P_1/P_0| + (1 + h^*^2)(H/a)^2`` (module docstring); ``inf`` where the expansion does not apply.
    """
    f = values.first
    x, h = f.H_over_a, f.edge_shift
    if not f.P0 > 0 or not all(math.isfinite(q) for q in (x, h, f.P1)) or x > 1e100:
        return {"force": math.inf, "contact_area": math.inf}
    k = math.sqrt(abs(f.P1 / f.P0) + (1.0 + h * h) * x * x)
    inner = abs(values.P_inner_next / f.P0)
    return {"force": ERROR_FACTORS["force"] * (k**4 * (1 + k) + inner),
            "contact_area": ERROR_FACTORS["contact_area"] * k**3 * (1 + k)}


def _quadratic_edge_integrals(Phi: sp.Expr, phi_min: sp.Expr, perimeter: sp.Expr) -> tuple[sp.Expr, sp.Expr] | None:
    Hs = sp.hessian(Phi, (S.x1, S.x2))
    if Hs.free_symbols & {S.x1, S.x2}:
        return None
    l1, l2 = (sp.simplify(q) for q in (Hs.trace() / 2 + sp.sqrt((Hs[0, 0] - Hs[1, 1]) ** 2 / 4 + Hs[0, 1] ** 2),
                                        Hs.trace() / 2 - sp.sqrt((Hs[0, 0] - Hs[1, 1]) ** 2 / 4 + Hs[0, 1] ** 2)))
    D0 = S.delta0 - phi_min
    E2 = 2 * sp.pi * (l1 + l2) / sp.sqrt(l1 * l2)
    if sp.simplify(l1 - l2) == 0:
        a = sp.sqrt(2 * D0 / l1)
        return 6 * sp.pi * a * l1, E2
    m = sp.simplify(1 - l2 / l1)
    E1 = (l1 + l2) * perimeter + 4 * sp.sqrt(2 * D0 / (l1 * l2)) * (
        (l1 + l2) * sp.sqrt(l1) * sp.elliptic_e(m) - l1 * l2 * sp.elliptic_k(m) / sp.sqrt(l1))
    return E1, E2


@boundary_methods
@dataclass(frozen=True)
class SecondOrderLaw(RichDisplay):
    r"""``P(delta0)`` to ``O(P0 (H/a)^4)`` and ``|omega|(delta0)`` to ``O(|omega_0| (H/a)^3)`` (SO.9), (SO.10).

    ``first`` is the first-order :class:`~thinlayer.asymptotics.force_law.ForceLaw`; ``E1, E2`` the edge integrals
    (closed forms, or None for a punch evaluated on its numerical contour); ``P2`` and ``area`` in the symbols
    ``r_3`` and ``h^*`` (numbers per nu: :func:`edge_constants`).
    """

    equation: ClassVar[str] = "SO.9"

    first: ForceLaw
    E1: sp.Expr | None
    E2: sp.Expr | None
    P2: sp.Expr | None
    area2: sp.Expr | None
    p2: sp.Expr
    P_inner_next: sp.Expr | None
    _numbers: Any = field(default=None, repr=False, compare=False)
    _contour_fns: Any = field(default=None, repr=False, compare=False)

    @property
    def layer(self) -> LayerKernel:
        return self.first.layer

    @property
    def punch(self) -> Punch:
        return self.first.punch

    @property
    def force(self) -> sp.Expr | None:
        """``P_0 + P_1 + P_2`` (None without a closed form)."""
        return None if self.P2 is None else self.first.force + self.P2

    @property
    def contact_area(self) -> sp.Expr | None:
        """(SO.10) in the symbol ``h^*`` (None without a closed form)."""
        return None if self.area2 is None else self.first.contact_area + self.area2

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        return law_arguments(self.force, self.contact_area)

    def _constants_sub(self) -> dict:
        return {k: v for k, (v, _) in self.codegen_constants().items()}

    def codegen_constants(self) -> dict:
        """``{r_3: (number, note), h^*: (number, note)}``: the layer's constants (SO.4), (3.25), defined as named
        constants in generated code.
        """
        c, lay = edge_constants(self.layer), layer_label(self.layer)
        return {r_3: (sp.Float(c.r3, 17),
                      f"r_3({lay}): log Phi(p) = -h* p - m_1 p^2/2 + r_3 p^3 + ..., Wiener-Hopf (SO.4)"),
                h_star: (sp.Float(c.h_star, 17), f"edge shift h*({lay}), exact Wiener-Hopf solution (3.18), (3.25)")}

    def lambdify(self, args=None, backend: str = "numpy"):
        """``(P, |omega|)`` as one numeric function of :attr:`arguments` with ``r_3``, ``h^*`` substituted."""
        if self.P2 is None:
            raise InputError(f"the second-order law of {self.punch.name} has no closed form; use .evaluate(...)")
        sub = self._constants_sub()
        exprs = tuple(e.subs(sub) for e in (self.force, self.contact_area))
        args = tuple(a for a in self.arguments if a not in sub) if args is None else args
        return lambdify_law(args, exprs, backend)

    codegen_name = "force_law_second_order"

    def codegen_expressions(self):
        """``(arguments, {"force": ..., "contact_area": ...})`` in the layer's constants ``r_3``, ``h^*``
        (:meth:`codegen_constants`; closed forms without elliptic integrals: a circle or a radial monomial).
        """
        if self.P2 is None:
            raise InputError(f"no closed-form second-order law for {self.punch.name}; code generation needs one")
        sub = self.codegen_constants()  # r_3 and h^* stay named: the generated code defines them as constants
        outs = {"force": self.force}
        area = self.contact_area
        if not area.has(sp.elliptic_e, sp.elliptic_k):
            outs["contact_area"] = area
        if outs["force"].has(sp.elliptic_e, sp.elliptic_k):
            raise InputError("the elliptic paraboloid's second-order force has complete elliptic integrals K, E, "
                             "which the target languages lack; use .lambdify() or .evaluate()")
        free = set().union(*(e.free_symbols for e in outs.values())) - set(sub)
        return tuple(a for a in self.arguments if a in free), outs

    def latex(self) -> str:
        th, A = self.layer.vartheta, self.layer.A
        e1 = r"\oint_{\Gamma_0}\left(\Delta\Phi + \Phi_{nn}\right) ds"
        e2 = r"\oint_{\Gamma_0}\frac{\Delta\Phi}{|\nabla\Phi|}\, ds"
        lines = [
            latex_equation("P_2", normal_latex(sp.factor(th * S.H**2 * r_3 / (2 * A))) + e1
                           + r",\qquad P = P_0 + P_1 + P_2 + O\!\left(P_0 \frac{H^4}{a^4}\right)", "SO.9"),
            latex_equation(r"|\omega|", join_signed([r"|\omega_0| - h^* H |\Gamma_0| + \pi h^{*2} H^2",
                                                     normal_latex(-sp.factor(self.layer.m(1) * S.H**2 / 2)) + e2
                                                     if self.layer.m(1) != 0 else ""])
                           + r" + O\!\left(|\omega_0| \frac{H^3}{a^3}\right)", "SO.10"),
        ]
        if self.P2 is not None:
            lines.append(latex_equation("P_2", normal_latex(sp.factor(self.P2)), "SO.9"))
            lines.append(latex_equation(r"|\omega|", normal_latex(self.contact_area), "SO.10"))
        return " \\\\\n".join(lines)

    def text_lines(self) -> list[str]:
        c = edge_constants(self.layer)
        out = [f"SecondOrderLaw: {self.punch.name}, {self.layer.name}   (SO.9), (SO.10)",
               f"  P = P₀ + P₁ + P₂,  P₂ = ϑ H² r₃/(2𝒜) ∮_Γ₀ (ΔΦ + Φ_nn) ds,  r₃ = {fmt(c.r3)}",
               f"  |ω| = |ω₀| - h* H |Γ₀| + π h*² H² - m₁ H²/2 ∮_Γ₀ ΔΦ/|∇Φ| ds,"
               f"  h* = {fmt(c.h_star)}"]
        if self.P2 is not None:
            out.append(f"  P₂ = {fmt(sp.factor(self.P2))}")
            if self.P2.has(sp.elliptic_e, sp.elliptic_k):
                out.append("  K(k), E(k): complete elliptic integrals of the first and second kind, modulus k")
        return out

    # ---- numbers ---------------------------------------------------------------------------
    def evaluate(self, delta0: Any, H: Any, mu: Any = 1.0, parameters: dict | None = None,
                 nu: Any = None) -> SecondOrderValues:
        """Numbers of (SO.9), (SO.10) at one point (floats)."""
        c = edge_constants(self.layer)
        vals = self.first.parameter_values(parameters or {})
        cont = None
        if self.E1 is None:
            from .contour import contact_contour

            Phi = self.punch.expr.xreplace(vals)
            free = Phi.free_symbols - {S.x1, S.x2}
            if free:
                raise InputError(f"the punch parameters {sorted(map(str, free))} need values (parameters=...)")
            cont = contact_contour(Phi, positive(delta0, "delta0"))
        first = self.first.evaluate(delta0, H, mu, edge_shift=c.h_star, parameters=parameters, nu=nu, contour=cont)
        HH = first.H
        sub = {S.delta0: first.delta0, S.H: HH, S.mu: float(mu), **vals}
        if nu is not None:
            sub[S.nu] = parse_nu(nu, floats="float", upper_closed=True, symbols=False)
        if cont is None:
            E1, E2, pin = _numbers(self)(sub)
        else:
            E1, E2, pin = _contour_integrals(self, sub, cont)
        th_over_A = first.P0 * HH / first.V if first.V else 0.0  # vartheta/A, from P0 = vartheta V/(A H)
        P2 = th_over_A * HH * HH * c.r3 * E1 / 2
        area2 = math.pi * c.h_star**2 * HH * HH - c.m1 * HH * HH * E2 / 2
        return SecondOrderValues(first, P2, area2, E1, E2, c.r3, c.m1, pin)


def _numbers(law: SecondOrderLaw):
    """``{symbol: value} -> (E1, E2, iint p_2)`` from the closed forms, compiled once (mpmath, 20 digits)."""
    if law._numbers is None:  # noqa: SLF001 - the law's own cache
        exprs = (law.E1, law.E2, law.P_inner_next)
        syms = tuple(sorted(set().union(*(e.free_symbols for e in exprs)), key=str))
        f = sp.lambdify(syms, exprs, modules="mpmath")

        def num(sub):
            missing = [q for q in syms if q not in sub]
            if missing:
                raise InputError(f"the second-order law needs values of {sorted(map(str, missing))}")
            with mpmath.workdps(20):
                out = f(*(mpmath.mpf(float(sub[q])) for q in syms))
                return tuple(float(mpmath.re(v)) for v in out)

        object.__setattr__(law, "_numbers", num)
    return law._numbers  # noqa: SLF001


def _contour_functions(law: SecondOrderLaw):
    """``Laplacian Phi`` and ``p_2`` as numpy functions of ``(x1, x2, *parameters)``, compiled once per law."""
    if law._contour_fns is None:  # noqa: SLF001 - the law's own cache
        Phi = law.punch.expr
        lap_syms = tuple(sorted(Phi.free_symbols - {S.x1, S.x2}, key=str))
        p2_syms = tuple(sorted(law.p2.free_symbols - {S.x1, S.x2}, key=str))
        lap = sp.lambdify((S.x1, S.x2, *lap_syms), sp.diff(Phi, S.x1, 2) + sp.diff(Phi, S.x2, 2), "numpy")
        p2 = sp.lambdify((S.x1, S.x2, *p2_syms), law.p2, "numpy")
        object.__setattr__(law, "_contour_fns", (lap, lap_syms, p2, p2_syms))
    return law._contour_fns  # noqa: SLF001


def _contour_integrals(law: SecondOrderLaw, sub: dict, c: Any) -> tuple[float, float, float]:
    """``E1, E2`` and ``iint p_2`` on the numerical contour ``c`` (:func:`thinlayer.contact_contour`)."""
    lap, lap_syms, p2, p2_syms = _contour_functions(law)
    missing = [q for q in p2_syms if q not in sub]
    if missing:
        raise InputError(f"the inner term p_2 needs values of {sorted(map(str, missing))}")
    lap_args = [float(sub[q]) for q in lap_syms]
    p2_args = [float(sub[q]) for q in p2_syms]

    def lap_s(s):
        x = c.f(s)
        return np.asarray(lap(x[..., 0], x[..., 1], *lap_args), dtype=float) * np.ones(np.shape(s))

    E1 = c.boundary_integral(lambda s: lap_s(s) - 2 * c.b2(s), of="s")
    E2 = c.boundary_integral(lambda s: lap_s(s) / c.g(s), of="s")
    pin = c.integrate(lambda a, b: np.asarray(p2(a, b, *p2_args), dtype=float) * np.ones(np.shape(a)))
    return E1, E2, pin


@lru_cache(maxsize=64)
def _second_order_law(layer: LayerKernel, punch: Punch) -> SecondOrderLaw:
    first = force_law(layer, punch)
    p2 = inner_pressure(layer, punch, order=3).terms[2]  # the first neglected inner term (2.26)
    if first.kind == "contour":
        return SecondOrderLaw(first, None, None, None, None, p2, None)
    if first.kind == "quadratic":
        E1, E2 = _quadratic_edge_integrals(punch.expr, first.phi_min, first.perimeter)
        P_in = sp.Integer(0) if p2 == 0 else p2 * first.area0  # Laplacian^2 of a quadratic is 0
    else:
        cc, k = radial_monomial(punch.expr)
        a = (S.delta0 / cc) ** sp.Rational(1, 2 * k)
        E1, E2 = 4 * sp.pi * k * (4 * k - 1) * cc * a ** (2 * k - 1), 4 * sp.pi * k * sp.Integer(1)
        r = sp.Symbol("r", positive=True)
        P_in = sp.integrate(p2.subs({S.x1: r, S.x2: 0}) * 2 * sp.pi * r, (r, 0, a))
    P2 = layer.vartheta * S.H**2 * r_3 * E1 / (2 * layer.A)
    area2 = sp.pi * h_star**2 * S.H**2 - layer.m(1) * S.H**2 * E2 / 2
    return SecondOrderLaw(first, E1, E2, P2, area2, p2, P_in)


@boundary
def second_order_law(layer: LayerKernel, punch: Punch) -> SecondOrderLaw:
    """The force law (SO.9) and area law (SO.10) of a polynomial punch on a thin layer.

    Examples
    --------
    The sphere, bonded layer nu = 0.3, R = 1, delta0 = 1/2 (a = 1), H = 0.05:

    >>> from thinlayer import BondedLayer, Punch
    >>> law = second_order_law(BondedLayer(0.3), Punch.paraboloid(R=1))
    >>> v = law.evaluate(0.5, 0.05)
    >>> print(f"{v.P2 / v.P0:.4e} {edge_constants(BondedLayer(0.3)).sphere_coefficient * 0.05**3:.4e}")
    7.9513e-05 7.9513e-05
    """
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a layer kernel such as BondedLayer(0.3), got {type(layer).__name__}")
    if not is_polynomial_tip(punch):
        raise InputTypeError(f"punch must be a Punch, got {type(punch).__name__}")
    try:
        return _second_order_law(layer, punch)
    except TypeError:
        return _second_order_law.__wrapped__(layer, punch)



# ---------------------------------------------------------------------------------------------
# (SO.7): the boundary layer and the composite pressure at second order
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SecondOrderProfile(RichDisplay):
    """The pieces of (SO.7) from the exact first-order layer ``qhat_0`` (:func:`thinlayer.boundary_layer_exact`):
    ``qhat = qhat_0 + eps q_kappa + beta q_beta``, ``q_kappa = (h^* + tau) qhat_0/2 - I_0``, ``q_beta = -2 I_0``.
    """

    equation: ClassVar[str] = "SO.7"

    h_star: float
    m1: float
    tau_max: float
    _q0: Any = field(repr=False)
    _prim: Any = field(repr=False)

    def q0(self, tau: Any) -> np.ndarray:
        return self._q0(np.asarray(tau, dtype=float))

    def I0(self, tau: Any) -> np.ndarray:
        """``int_0^tau qhat_0``: ``tau^2/2 + int_0^sqrt(tau) (qhat_0 - z^2) 2 z dz`` on the table (Chebyshev), exact
        continuation ``qhat_0 = tau + h^*`` beyond it.
        """
        tau = np.asarray(tau, dtype=float)
        t = np.minimum(tau, self.tau_max)
        inside = t * t / 2 + self._prim(np.sqrt(t)) - self._prim(0.0)
        beyond = np.maximum(tau - self.tau_max, 0.0)
        return inside + beyond * (self.tau_max + self.h_star) + beyond * beyond / 2

    def q_kappa(self, tau: Any) -> np.ndarray:
        tau = np.asarray(tau, dtype=float)
        return (self.h_star + tau) * self.q0(tau) / 2 - self.I0(tau)

    def q_beta(self, tau: Any) -> np.ndarray:
        return -2 * self.I0(tau)

    def edge(self, eps_: Any, beta_: Any) -> np.ndarray:
        """``h = h^* + (eps/2 + beta) m_1`` (SO.5)."""
        return self.h_star + (np.asarray(eps_) / 2 + np.asarray(beta_)) * self.m1

    def Qhat(self, v: Any, eps_: Any, beta_: Any) -> np.ndarray:
        """``qhat(v - h)`` of (SO.7) for ``v > h``, 0 otherwise (``v`` measured from Gamma_0, inward)."""
        v = np.asarray(v, dtype=float)
        tau = np.maximum(v - self.edge(eps_, beta_), 0.0)
        q = self.q0(tau) + eps_ * self.q_kappa(tau) + beta_ * self.q_beta(tau)
        return np.where(v > self.edge(eps_, beta_), q, 0.0)

    def decaying(self, v: Any, eps_: Any, beta_: Any) -> np.ndarray:
        """``qhat`` minus its own far field, term by term (each bracket decays like ``e^{-sigma tau}``):
        ``[qhat_0 - tau - h^*] + eps [q_kappa + m_1/2] + beta [q_beta + (tau + h^*)^2 + m_1]``, 0 for ``v <= h``.
        This is what the composite pressure adds to ``p_0 + p_1``.
        """
        v = np.asarray(v, dtype=float)
        edge = self.edge(eps_, beta_)
        tau = np.maximum(v - edge, 0.0)
        hs, m1 = self.h_star, self.m1
        q0 = self.q0(tau)
        I0 = self.I0(tau)
        out = (q0 - tau - hs) + eps_ * ((hs + tau) * q0 / 2 - I0 + m1 / 2) + beta_ * (-2 * I0 + (tau + hs) ** 2 + m1)
        return np.where(v > edge, out, 0.0)

    def far_field(self, v: Any, eps_: Any, beta_: Any) -> np.ndarray:
        """``v - beta v^2 - m_1 (eps + 2 beta)``: the inner ``p_0 + p_1`` seen from the edge (SO.7)."""
        v = np.asarray(v, dtype=float)
        return v - beta_ * v * v - self.m1 * (eps_ + 2 * beta_)

    def latex(self) -> str:
        return (r"\hat q = \hat q_0 + \epsilon\left[\frac{(h^* + \tau)\hat q_0}{2} - I_0\right] - 2\beta I_0,\quad "
                r"I_0 = \int_0^\tau \hat q_0 \tag{SO.7}")

    def text_lines(self) -> list[str]:
        return ["SecondOrderProfile: q̂ = q̂₀ + ε ((h* + τ) q̂₀/2 - I₀) - 2β I₀   (SO.7)",
                f"  h* = {fmt(self.h_star)}, m₁ = {fmt(self.m1)}, table 0 <= τ <= {self.tau_max:.4g}"]


def second_order_profile(layer: LayerKernel) -> SecondOrderProfile:
    """(SO.7) for a layer with a numeric Poisson ratio (``BondedLayer(nu)`` or ``FrictionlessLayer()``)."""
    from .wiener_hopf import boundary_layer_exact

    sol = boundary_layer_exact(layer)
    zmax = math.sqrt(sol.tau_max)
    c = np.polynomial.chebyshev.Chebyshev(np.asarray(sol.cheb), domain=[0, zmax])
    z = np.polynomial.chebyshev.Chebyshev.identity(domain=[0, zmax])
    prim = (c * 2 * z).integ()
    return SecondOrderProfile(float(sol.h), float(sol.m1), float(sol.tau_max), sol.q_numpy, prim)


def composite_pressure_second_order(layer: LayerKernel, punch: Punch, delta0: float, H: float, mu: float = 1.0,
                                    nu: Any = None):
    """The composite pressure with the second-order boundary layer (SO.7): ``p_0 + p_1`` (2.26), (4.1) plus
    ``(vartheta g/A)`` times the decaying part of ``qhat`` (:meth:`SecondOrderProfile.decaying`) at each point near
    Gamma_0, with ``eps = kappa H`` and ``beta = H Phi_nn/(2 g)`` at its foot point, and 0 beyond the edge (SO.5);
    uniformly valid to ``O(p_max (H/a)^2)`` (the first-order composite: ``O(p_max H/a)``).

    Returns a vectorised function ``(x1, x2) -> p``.
    """
    from .composite import composite_pressure

    first = composite_pressure(layer, punch, delta0, H, mu, terms=2, boundary_layer="exact", nu=nu)
    prof = second_order_profile(layer)
    Phi = punch.expr
    d = sp.lambdify((S.x1, S.x2), (sp.diff(Phi, S.x1), sp.diff(Phi, S.x2), sp.diff(Phi, S.x1, 2),
                                   sp.diff(Phi, S.x1, S.x2), sp.diff(Phi, S.x2, 2)), modules="numpy")
    amp, HH, band = first.amplitude, float(H), first.band

    def derivs(a, b):
        return [q if np.ndim(q) else np.full(np.shape(a), float(q)) for q in d(a, b)]

    def pressure(x1: Any, x2: Any) -> np.ndarray:
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        shape = x1.shape
        x1, x2 = x1.ravel(), x2.ravel()
        p_in = first._p_in(x1, x2)  # noqa: SLF001 - p_0 + p_1 of the same stage's composite
        v, _ = first.local(x1, x2)
        gx, gy, _, _, _ = derivs(x1, x2)
        with np.errstate(divide="ignore", invalid="ignore"):
            gn = np.hypot(gx, gy)
            ex, ey = gx / gn, gy / gn
        near = np.isfinite(v) & (v < band + 4 * abs(prof.m1) + 4)
        out = np.where(v > 0, p_in, 0.0)
        if near.any():
            i = np.flatnonzero(near)
            fx, fy = x1[i] + v[i] * HH * ex[i], x2[i] + v[i] * HH * ey[i]  # the foot point on Gamma_0
            Fx, Fy, hxx, hxy, hyy = derivs(fx, fy)
            g = np.hypot(Fx, Fy)
            nx, ny = Fx / g, Fy / g
            phinn = hxx * nx * nx + 2 * hxy * nx * ny + hyy * ny * ny
            kap = (hxx + hyy - phinn) / g
            e_, b_ = kap * HH, HH * phinn / (2 * g)
            corr = prof.decaying(v[i], e_, b_)
            inside = v[i] > prof.edge(e_, b_)
            out[i] = np.where(inside, p_in[i] + amp * g * corr, 0.0)
        return np.maximum(out, 0.0).reshape(shape)

    return pressure

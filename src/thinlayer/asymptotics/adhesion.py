r"""Adhesion (JKR) on a thin layer: the edge stress intensity from the boundary layer, and the JKR relations.

Equation tags ``J.n`` continue those of :mod:`thinlayer.numerics.adhesion` (J.1)-(J.6), the direct solver this
module's results are measured against (in ``tests/adhesion``; this stage never imports the numerics).
Assumptions: frictionless contact, layer bonded to a rigid base (kernel (2.3)), compressible (``A > 0``),
JKR adhesion (short-range: the work of adhesion ``w`` is spent at the contact edge; tension inside the contact).

(J.7) *Half-space (L = 1), from the superposition (J.1).*  With ``L = 1`` the Fredholm equation (F.6) has no
kernel, so Copson's function (F.3) is ``phi(t) = (2 vartheta/pi) G(t)`` with the Abel transform of the surface
displacement ``G(t) = delta - t int_0^t Phi'(r) (t^2 - r^2)^{-1/2} dr`` (F.4).  Then ``P = 2 pi int_0^c phi``,
the edge strength is ``phi(c)``, ``K_I = -phi(c) sqrt(pi/c)`` (J.2), ``G = K_I^2/(4 vartheta)`` (J.3) and
``G = d^2 S'(c)/(4 pi c)`` with ``S = dP/d delta = 4 vartheta c`` (J.4).  :func:`half_space_jkr` carries this out
in sympy for ``Phi = r^2/(2R)`` and finds JKR (1971) with ``E* = 2 vartheta``.

(J.8) *The adhesive edge layer (compressible thin layer).*  Near the edge the outer (inner-expansion) pressure
(2.29) is ``p_out(n) = p_e + p_s n + ...``, ``n`` the distance from the contact edge into the contact.  With
adhesion ``p_e`` need not vanish.  In the boundary layer (``tau = n/H``) the equation (3.15) with this right side
is solved by the factorisation ``F = F+ F-`` of :mod:`thinlayer.asymptotics.wiener_hopf` exactly as in (F.11)
(constant part) and (3.22) (linear part, edge at ``tau = 0``, no condition (3.18))::

    q(tau) = p_e g(tau) + p_s H l(tau),
    int_0^oo g e^{-p tau} dtau = 1/(p Phi(p)),       int_0^oo l e^{-p tau} dtau = (1/Phi(p)) (1/p^2 - h/p),

``Phi(p) = F+(ip)/F+(0) = 1 - h p + ...`` and ``h = h*`` the exact edge shift (3.18).  Hence, with ``qhat`` the
smooth solution (transform ``1/(p^2 Phi)``), ``g = qhat'`` and ``l = qhat - h qhat'``: the adhesive edge layer is

    q(tau) = (p_e - h H p_s) qhat'(tau) + p_s H qhat(tau).

*Edge.*  ``F ~ 1/|s|`` at infinity and ``F+(0)^2 = A`` give ``1/Phi(p) ~ sqrt(A p)`` as ``p -> oo`` *exactly*
(``log Phi - log Phi0 = O(1/p)`` for every normaliser ``Phi0``; for Alexandrov's (3.19) ``sqrt(B/C) = sqrt(A)``
by (3.20)), so ``qhat' ~ sqrt(A/(pi tau))`` and ``qhat ~ 2 sqrt(A tau/pi)`` (bounded).  With
``sigma_zz = -q`` and ``n = H tau``::

    K_I = -sqrt(2 A H) (p_e - h H p_s) = -sqrt(2 A H) p_out(-h H).                                      (J.8)

The stress intensity is the outer pressure extrapolated to the shifted contour ``Gamma_0`` (``n = -h H``), times
``sqrt(2 A H)``: the new layer constant is ``sqrt(2 A)``, *exact* (it does not depend on the factorisation's
precision; ``h`` does, and enters only through the position ``-h H``).  The smooth-edge condition (3.18) is
``K_I = 0``, i.e. ``p_out(-h H) = 0``: the edge shift (3.25) again.  By (J.3)

    G = K_I^2/(4 vartheta) = A H p_out(-h H)^2/(2 vartheta)                                             (J.9)

with a relative remainder ``O(H/c)`` (the edge's curvature ``1/c`` enters the boundary layer at the next order).

(J.10) *First order (the curvature).*  The energy route fixes that order for a disc: the adhesive state is the
smooth one plus a flat punch (J.1), whose ``G = vartheta d^2 (lambda kappa)'/(pi c)`` (J.4) with the thin-layer
stiffness ``kappa_r = (pi/(4A)) (lambda + h)^2/lambda`` (F.12)::

    G = vartheta d^2 (c + h H)/(2 A H c) = (J.9) x (1 + h H/c),                                         (J.10)

i.e. the straight-edge ``K_I`` of (J.8) times ``sqrt(a_e/c)``, ``a_e = c + h H``.

(J.11) *Thin-layer JKR for the paraboloid* ``Phi = r^2/(2R)``.  ``p_out = vartheta (delta - r^2/(2R))/(A H)``
(2.29) (the ``m_1`` term of (2.31) is ``O((H/c)^2)`` relative and is left out); the smooth state at radius ``c``
has its outer contour at ``a_e = c + h H``: ``delta_1 = a_e^2/(2R)``, ``P_1 = pi vartheta a_e^4/(4 A R H)``.
``G = w`` in (J.10)::

    delta = a_e^2/(2R) - sqrt(2 A H w c/(vartheta a_e)),
    P     = pi vartheta a_e^4/(4 A R H) - pi a_e^2 sqrt(2 vartheta w c/(A H a_e)).                       (J.11)

``order=0`` (``a_e = c``): relative remainder ``O(H/c)``; ``order=1``: ``O((H/c)^2)``.  Measured against the
direct solver (``tests/adhesion``, nu = 0.3, ``R = c^2/(2H)``, ``w = 0.05 vartheta H``, c/H = 5 ... 80): order 0
falls with slope -1.0 in ``delta`` and ``P``; order 1 with slope -2.0 in ``delta`` and -3.0 in ``P``.

(J.24) *Second order (the m_1 shift of the smooth edge).*  The energy route needs ``delta_1(c)``, ``P_1(c)``, ``S(c)``
and ``S'(c)``; what the engine's orders give:

* the smooth state: (SO.5) puts the edge of the sphere at ``c = a - h* H - m_1 H^2/a`` (``eps = H/a``,
  ``beta = H/(2a)``), so ``a(c) = c + h* H + m_1 H^2/c + O(H^3/c^2)`` and ``delta_1 = a(c)^2/(2R)`` to relative
  ``O((H/c)^3)``;  with (SO.8), (SO.9) ``P_1(c) = P_0(a)(1 - 4 m_1 (H/a)^2 + ...) = pi vartheta (c + h* H)^4/(4 A R H)
  (1 + O((H/c)^3))``: the ``m_1`` terms cancel, order 1's force is already right to ``(H/c)^2`` (checked in sympy);
* the flat punch: (F.11) is derived, ``kappa = (pi/(4A))(lambda + 2 h* + C_2/lambda + C_3/lambda^2 + ...)``;
  ``S = 4 vartheta c kappa`` gives ``S'(c) = (pi vartheta/(A H))(2 (c + h* H) - C_3 H^3/c^2 + ...)``: ``C_2`` drops
  out, so ``G`` of (J.10) is right to relative ``O((H/c)^2)`` inclusive;  ``S`` itself needs ``C_2``, which (F.12)
  sets to ``h*^2`` (measured to hold, not derived: (F.16)).

Hence the depth to the next order::

    delta = (c + h* H + m_1 H^2/c)^2/(2R) - sqrt(2 A H w c/(vartheta (c + h* H))),                    (J.24)

relative remainder ``O((H/c)^3)``, and ``P`` as at order 1 (its remainder is already ``O((H/c)^3)``).  The next
order of either needs what the engine does not have: the contact radius to ``O(H^3/a^2)`` (the third-order
area law; (SO.10) stops at ``(H/a)^2``) and, for ``P``, the flat punch's ``C_2`` derived and ``C_3``.  Measured
(nu = 0.3, ``R = c^2/(2H)``, ``w = 0.05 vartheta H``, c/H = 5 ... 80): the order-2 depth error times
``(c/H)^3`` is 0.140, 0.138, 0.138, 0.139, 0.139 (slope -3.0; order 1: slope -2.0); at nu = -0.5, 0, 0.45 it
tends to 0.24, 0.057, ~1.8 (about ``2.6 r_3 H``, ``r_3`` of (SO.4)).

(J.12) *Pull-off on the thin layer.*  From (J.11) at order 0, ``P = a X^2 - b X`` in ``X = c^2`` has its minimum
``-b^2/(4a)``: the load-controlled pull-off force is ``2 pi w R`` (the value of DMT and of a Winkler foundation),
at ``c^2 = 2 R sqrt(2 A H w/vartheta)``.  ``delta(c)`` increases with ``c``: under displacement control the contact
is lost at ``c = O(H)``, outside the thin-layer law (no thin-layer value: the direct solver answers).

(J.15) *Incompressible layer (nu = 1/2), paraboloid.*  The outer problem is the operator (I.2),
``-(c_1 H^3/vartheta) Delta p = delta - r^2/(2R)`` (``c_1 = 2/3``, ``vartheta = 2 mu``).  The smooth state at radius
``c`` has ``p = p' = 0`` at its model edge ``a_e = c + h H`` ((I.4), (I.12), ``h = 1.4591``): ``delta_1 = a_e^2/(4R)``,
``P_1 = pi vartheta a_e^6/(64 H^3 R)``; the flat part has ``kappa_r = (3 pi/64)(lambda + h)^4/lambda`` (F.14) and, by
Krein, ``G = 3 vartheta d^2 a_e^3/(16 c H^3)``.  ``G = w``::

    delta = a_e^2/(4R) - (4/sqrt 3) sqrt(w c H^3/(vartheta a_e^3)),
    P = pi vartheta a_e^6/(64 H^3 R) - (sqrt(3) pi/4) sqrt(vartheta w c) a_e^{5/2}/H^{3/2},

and at order 0 the load-controlled pull-off force is ``3 pi w R`` (twice JKR's).  Measured against the direct
solver (``IncompressibleLayer``, ``R = c^2/(8H)``, ``w = 0.05 vartheta c^2/H``, c/H = 5 ... 40): order 0 slope ~1,
order 1 ``delta`` 0.47, 0.13, 0.034, 0.0087 (slope 2), ``P`` 0.30, 0.027, 0.0028, 3.1e-4 relative (slope 3).

(J.13) *Flat punch on the thin layer (Kendall's thin-film problem).*  The detachment force
``P_off = 4 vartheta a kappa sqrt(pi a w/vartheta)/f(1)`` of :mod:`thinlayer.numerics.adhesion` with (F.12) and
Krein's ``f(1)^2 = (lambda kappa)'`` (F.9)::

    P_off = pi a_e^{3/2} a^{1/2} sqrt(2 vartheta w/(A H)),     a_e = a + h* H (order 1),  a (order 0),

i.e. Kendall's thin-film law ``pi a^2 sqrt(2 K w/H)`` with the confined modulus ``K = vartheta/A =
2 mu (1 - nu)/(1 - 2 nu)``, here derived with its first correction.  Relative remainders: order 0
``(3/2) h* H/a``; order 1 ``O((H/a)^2)`` (measured in ``tests/adhesion``).

(J.14) *Flat punch on the incompressible thin layer (nu = 1/2).*  The same with the incompressible stiffness
(F.14) ``kappa_r = (3 pi/64)(lambda + h)^4/lambda`` (``h = 1.4591`` of (I.12)) and Krein's identity::

    f(1)^2 = (3 pi/16)(lambda + h)^3,     P_off = (sqrt(3) pi/4) sqrt(vartheta w) a_e^{5/2} a^{1/2} H^{-3/2},

``vartheta = 2 mu``; order 0 (``a_e = a``) errs like ``(5/2) h H/a``.  Measured against the direct solver
(``IncompressibleLayer``): order 1 remainder 3.5e-3, 5.4e-4, 7.5e-5 at a/H = 10, 20, 40.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, check_choice, positive, positive_radii
from .._checks import work_of_adhesion as check_work
from ..display import RichDisplay
from ..layers.kernels import BondedLayer, GenericLayer, IncompressibleLayer
from ..punch import Punch
from .flat_punch import thin_flat_punch_derivation
from .incompressible import thin_layer_operator, two_term_edge_shift
from .inner import inner_pressure
from .second_order import edge_constants, second_order_boundary_layer
from .wiener_hopf import edge_shift_exact, wiener_hopf_solution

__all__ = ["AdhesionDerivation", "AdhesiveEdgeLayer", "HalfSpaceJKR", "ThinFlatDetachment", "ThinLayerJKR",
           "adhesion_derivation", "adhesive_edge_layer", "half_space_jkr", "thin_flat_detachment", "thin_layer_jkr"]

c, R, w, E_star = sp.symbols("c R w E^*", positive=True)
r, t = sp.symbols("r t", positive=True)
d = sp.Symbol("d", real=True)
A = GenericLayer.A_symbol
h = sp.Symbol("h^*", real=True)
p_e, p_s = sp.symbols("p_e p_s", real=True)
m_1 = sp.Symbol("m_1", real=True)  # m_1 (2.20) in the second-order law (J.24), as (SO.5) names it
vt, H, delta = S.vartheta, S.H, S.delta0
_H, _R = H, R  # the symbols, for methods whose arguments are named H and R


# --------------------------------------------------------------------------- (J.7) the half-space
@dataclass(frozen=True)
class HalfSpaceJKR(RichDisplay):
    """JKR on the half-space derived from the superposition (J.1) with ``L = 1`` (J.7).

    Attributes
    ----------
    force, depth : sympy.Expr
        sympy.Expr
        ``P(c)`` and ``delta(c)`` at ``G = w`` in ``c, R, w, E*`` (``E* = 2 vartheta``).
    release_rate_sif, release_rate_energy : sympy.Expr
        sympy.Expr
        ``G`` from ``K_I`` (J.3) and from the compliance (J.4) in ``vartheta, c, d``.
    pull_off_load, pull_off_displacement : sympy.Expr
        sympy.Expr
        ``-min P`` under load and displacement control (J.6).
    jump_in_radius : sympy.Expr
        Radius of the stable state at ``delta = 0`` (displacement-controlled jump-in).
    """

    force: sp.Expr
    depth: sp.Expr
    release_rate_sif: sp.Expr
    release_rate_energy: sp.Expr
    pull_off_load: sp.Expr
    pull_off_displacement: sp.Expr
    jump_in_radius: sp.Expr

    equation = "J.7"

    def latex(self) -> str:
        return (rf"P = {sp.latex(self.force)},\quad \delta = {sp.latex(self.depth)},\quad "
                rf"P_{{\mathrm{{off}}}} = {sp.latex(self.pull_off_load)}\ (\text{{load}}),\ "
                rf"{sp.latex(self.pull_off_displacement)}\ (\text{{displacement}}) \tag{{J.7}}")

    def text_lines(self) -> list[str]:
        return ["HalfSpaceJKR: JKR from the superposition (J.1) with L = 1   (J.7)",
                f"  P(c) = {self.force}", f"  delta(c) = {self.depth}",
                f"  pull-off: load control {self.pull_off_load}, displacement control {self.pull_off_displacement}"]


def _linear_root(expr: sp.Expr, var: sp.Symbol) -> sp.Expr:
    """The root of ``expr``, linear in ``var`` (checked)."""
    a = sp.diff(expr, var)
    if sp.diff(a, var) != 0:
        raise ArithmeticError(f"{expr} is not linear in {var}")
    return sp.cancel(-expr.subs(var, 0) / a)


def _positive_roots(expr: sp.Expr) -> list:
    """Positive roots ``c`` of ``expr(c)``, a polynomial in ``sqrt(c)`` (``c = x^2``)."""
    x = sp.Symbol("x", positive=True)
    num = sp.numer(sp.together(sp.expand(expr.subs(c, x**2))))
    roots = sp.roots(sp.Poly(num, x))
    return [sp.simplify(rt**2) for rt in roots if rt.is_positive]


@lru_cache(maxsize=1)
def half_space_jkr() -> HalfSpaceJKR:
    """(J.7) in sympy: Copson's function with ``L = 1``, the paraboloid ``r^2/(2R)``, both routes for ``G``.

    Cached; a few seconds of sympy (``tests/adhesion`` compares it with JKR (1971) as printed).
    """
    Phi = r**2 / (2 * R)
    G_abel = delta - t * sp.integrate(sp.diff(Phi, r) / sp.sqrt(t**2 - r**2), (r, 0, t))  # (F.4)
    phi = 2 * vt / sp.pi * G_abel  # (F.6) with no kernel
    P = 2 * sp.pi * sp.integrate(phi, (t, 0, c))  # (F.3)
    delta1 = _linear_root(phi.subs(t, c), delta)  # smooth edge: phi(c) = 0
    S_c = sp.diff(P, delta)  # stiffness at fixed c: 4 vartheta c
    K = -sp.sqrt(sp.pi / c) * (phi.subs(t, c).subs(delta, delta1 + d))  # (J.2)
    G_K = sp.expand(K**2 / (4 * vt))  # (J.3)
    G_E = sp.expand(d**2 * sp.diff(S_c, c) / (4 * sp.pi * c))  # (J.4)
    d_jkr = -sp.sqrt(sp.pi * c * w / vt)  # G = w, tensile root (J.5)
    if sp.simplify(G_K.subs(d, d_jkr) - w) != 0:
        raise ArithmeticError("(J.5): the tensile root does not solve G = w")
    P_c = sp.expand((P.subs(delta, delta1) + S_c * d_jkr).subs(vt, E_star / 2))
    delta_c = sp.expand((delta1 + d_jkr).subs(vt, E_star / 2))
    (c_load,), (c_disp,) = _positive_roots(sp.diff(P_c, c)), _positive_roots(sp.diff(delta_c, c))
    (c_jump,) = _positive_roots(delta_c)
    P_load = sp.simplify(-P_c.subs(c, c_load))
    P_disp = sp.simplify(-P_c.subs(c, c_disp))
    return HalfSpaceJKR(P_c, delta_c, G_K, G_E, P_load, P_disp, c_jump)


# --------------------------------------------------------------------------- (J.8)-(J.9) the edge layer
@dataclass(frozen=True)
class AdhesiveEdgeLayer(RichDisplay):
    """The adhesive boundary layer's stress intensity (J.8) and energy release rate (J.9).

    Attributes
    ----------
    nu : float
        Poisson ratio of the bonded layer.
    A, h : float
        float
        ``A`` (2.4) and the exact edge shift ``h*`` (3.18).
    edge_coefficient : float
        ``lim sqrt(tau) qhat'(tau) = sqrt(A/pi)`` (J.8), exact.
    edge_coefficient_table : float
        The same limit read off the Wiener-Hopf table of :func:`~thinlayer.asymptotics.wiener_hopf.
        wiener_hopf_solution` (de Hoog inversion): the numerical check of the factorisation (``nan`` unless
        asked for).
    stress_intensity_expr, release_rate_expr : sympy.Expr
        sympy.Expr
        ``K_I`` in ``p_e, p_s, A, H, h*`` and ``G`` in ``p_e, p_s, A, H, h*, vartheta``.
    """

    nu: float
    A: float
    h: float
    edge_coefficient: float
    edge_coefficient_table: float
    stress_intensity_expr: sp.Expr
    release_rate_expr: sp.Expr

    equation = "J.8"

    def stress_intensity(self, p_edge: Any, p_slope: Any, H: Any) -> np.ndarray:
        """``K_I = -sqrt(2 A H) (p_e - h* H p_s)`` (J.8), vectorised; ``p`` positive in compression."""
        Hv = np.asarray(H, dtype=float)
        if np.any(Hv <= 0):
            raise InputError("H must be > 0")
        return -np.sqrt(2 * self.A * Hv) * (np.asarray(p_edge, float) - self.h * Hv * np.asarray(p_slope, float))

    def release_rate(self, p_edge: Any, p_slope: Any, H: Any, vartheta: Any) -> np.ndarray:
        """``G = K_I^2/(4 vartheta)`` (J.9)."""
        return self.stress_intensity(p_edge, p_slope, H) ** 2 / (4 * np.asarray(vartheta, dtype=float))

    def latex(self) -> str:
        return (rf"K_I = {sp.latex(self.stress_intensity_expr)},\quad G = {sp.latex(self.release_rate_expr)},"
                rf"\quad \mathcal{{A}} = {self.A:.10g},\ h^* = {self.h:.10g} \tag{{J.8}}")

    def text_lines(self) -> list[str]:
        return [f"AdhesiveEdgeLayer: bonded layer nu = {self.nu:g}   (J.8), (J.9)",
                f"  K_I = {self.stress_intensity_expr}", f"  G = {self.release_rate_expr}",
                f"  A = {self.A:.12g}, h* = {self.h:.12g}; edge coefficient sqrt(A/pi) = {self.edge_coefficient:.12g}"
                f" (Wiener-Hopf table: {self.edge_coefficient_table:.12g})"]


def _edge_limit_symbolic() -> None:
    """``1/Phi(p) ~ sqrt(A p)`` and its inverse Laplace ``sqrt(A/(pi tau))`` (J.8), checked in sympy."""
    p, tau, Bs, Cs = sp.symbols("p tau B C", positive=True)
    phi0 = sp.sqrt(1 + p / Bs) / (1 + p / sp.sqrt(Cs))  # Alexandrov's normaliser (3.19), B = A C (3.20)
    lim = sp.limit((1 / phi0) / sp.sqrt(p), p, sp.oo).subs(Bs, A * Cs)
    if sp.simplify(lim - sp.sqrt(A)) != 0:
        raise ArithmeticError("(J.8): 1/Phi ~ sqrt(A p) fails for Alexandrov's normaliser")
    inv = sp.inverse_laplace_transform(sp.sqrt(A) / sp.sqrt(p), p, tau)
    if sp.simplify(inv - sp.sqrt(A / (sp.pi * tau))) != 0:
        raise ArithmeticError("(J.8): the inverse Laplace transform of sqrt(A/p) is not sqrt(A/(pi tau))")


@lru_cache(maxsize=16)
def _edge_layer(nu: float, table: bool) -> AdhesiveEdgeLayer:
    _edge_limit_symbolic()
    lay = BondedLayer(nu)
    tab = math.nan
    if table:
        sol = wiener_hopf_solution(nu)
        zmax = math.sqrt(sol.tau_max)
        # qhat - tau = g(z), z = sqrt(tau), a Chebyshev series in x = 2 z/zmax - 1:  sqrt(tau) qhat' -> g'(0)/2
        dcheb = np.polynomial.chebyshev.chebder(np.asarray(sol.cheb)) * (2.0 / zmax)
        tab = 0.5 * float(np.polynomial.chebyshev.chebval(-1.0, dcheb))
    K = -sp.sqrt(2 * A * H) * (p_e - h * H * p_s)
    if sp.solve(K, p_e) != [h * H * p_s]:  # K_I = 0 is the smooth edge (3.18): p_out(-h* H) = 0
        raise ArithmeticError("(J.8): K_I = 0 is not the smooth-edge condition")
    Af = float(lay.A)
    return AdhesiveEdgeLayer(float(nu), Af, float(edge_shift_exact(nu, dps=16)), math.sqrt(Af / math.pi), tab, K,
                             sp.factor(sp.expand(K**2 / (4 * vt))))


def adhesive_edge_layer(nu: Any, table: bool = False) -> AdhesiveEdgeLayer:
    """The adhesive edge layer of the compressible bonded layer (J.8), (J.9); cached per nu.

    Parameters
    ----------
    nu : float
        Poisson ratio, ``-1 < nu < 1/2`` (the compressible layer, ``A > 0``).
    table : bool
        Also read the edge coefficient off the Wiener-Hopf table (``edge_coefficient_table``; builds the table,
        10-25 s the first time per nu); otherwise that field is ``nan``.

    Returns
    -------
    AdhesiveEdgeLayer
    """
    try:
        val = float(nu)
    except (TypeError, ValueError):
        raise InputError(f"nu must be a number in (-1, 1/2), got {nu!r}") from None
    if not -1.0 < val < 0.5:
        raise InputError(f"nu must lie in (-1, 1/2) (the compressible layer, A > 0), got {nu!r}")
    return _edge_layer(val, bool(table))


# --------------------------------------------------------------------------- (J.10)-(J.12) thin-layer JKR
@dataclass(frozen=True)
class ThinLayerJKR(RichDisplay):
    """Thin-layer JKR relations for the paraboloid ``r^2/(2R)`` on a compressible bonded layer (J.10)-(J.12).

    Attributes
    ----------
    nu, A, h : float
        float
        Poisson ratio, ``A`` (2.4), exact edge shift ``h*`` (3.18).
    order : int
        0 (relative remainder ``O(H/c)``) or 1 (``O((H/c)^2)``).
    depth, force : sympy.Expr
        sympy.Expr
        ``delta(c)`` and ``P(c)`` at ``G = w`` in ``c, R, w, H, vartheta, A, h*`` (J.11).
    release_rate : sympy.Expr
        ``G`` in ``d = delta - delta_1(c)`` (J.10).
    pull_off_leading : sympy.Expr
        ``2 pi w R`` (J.12).
    depth_display, force_display : sympy.Expr
        sympy.Expr
        The same in ``a_e`` (``= c + h* H`` at orders 1 and 2, ``c`` at order 0; order 2 also
        ``a_2 = a_e + m_1 H^2/c``), as printed by ``latex()``.
    m1 : float
        ``m_1`` (2.20) of the layer (enters the error estimate and, at order 2, the law (J.24)).
    r3 : float
        ``r_3`` (SO.4) of the layer (order 2's error estimate).
    """

    nu: float
    A: float
    h: float
    order: int
    depth: sp.Expr
    force: sp.Expr
    release_rate: sp.Expr
    pull_off_leading: sp.Expr
    depth_display: sp.Expr
    force_display: sp.Expr
    m1: float = 0.0
    r3: float = 0.0

    @property
    def equation(self) -> str:
        """``"J.11"`` (compressible), ``"J.24"`` (compressible, order 2) or ``"J.15"`` (``nu = 1/2``)."""
        return "J.15" if self.A == 0 else ("J.24" if self.order == 2 else "J.11")

    def evaluate(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0) -> tuple[np.ndarray,
                                                                                                     np.ndarray]:
        """``(delta, P)`` of (J.11), vectorised in the contact radius; ``vartheta = mu/(1 - nu)``."""
        fd, fP = _compiled(self.order, self.A, self.h, self.m1)
        cv = positive_radii(radius)
        vals = (cv, positive(H, "H"), positive(R, "R"), check_work(work_of_adhesion),
                positive(mu, "mu") / (1 - self.nu))
        return np.asarray(fd(*vals), dtype=float), np.asarray(fP(*vals), dtype=float)

    def error_estimate(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any,
                       mu: Any = 1.0) -> tuple[np.ndarray, np.ndarray]:
        """Absolute error estimates ``(delta, P)`` of :meth:`evaluate` (J.11).

        Order 1: twice the change from order 0 times ``H/c``, plus ``2 |m_1| H^2/R`` in ``delta`` (the left-out
        ``m_1`` term of (2.31); measured: the true second-order term tends to ``m_1 H^2/R``).  Order 0: twice the
        change to order 1, plus the same ``m_1`` term.  Measured against the direct solver (nu = -0.5, 0, 0.3,
        0.45; ``w/(vartheta H)`` = 0.05, 0.5; ``R = c^2/(2H)``; c/H = 5 ... 40) the true error is at most 0.6 of
        it; smaller ``c/H`` and other scalings are not checked, and below ``c = 5 H`` the law should not be used.
        At ``nu = 1/2`` (J.15) the order-1 factor is doubled (measured: the true error tends to 0.5 of the estimate;
        ``R = c^2/(8H)``, ``w = 0.05 vartheta c^2/H``, c/H = 5 ... 40).
        """
        cv = positive_radii(radius)
        Hv, Rv = positive(H, "H"), positive(R, "R")
        if self.order == 2:  # (J.24): measured error about 2.6 r_3 H^3/(c R) (see the module docstring)
            first = thin_layer_jkr(self.nu, 1)
            d_a = self.evaluate(cv, Hv, Rv, work_of_adhesion, mu)[0]
            flat = np.abs(d_a - self.evaluate(cv, Hv, Rv, 0.0, mu)[0])
            return (4 * abs(self.r3) * Hv**3 / (cv * Rv) + 2 * (Hv / cv) ** 3 * flat,
                    first.error_estimate(cv, Hv, Rv, work_of_adhesion, mu)[1])
        other = thin_layer_jkr(self.nu, 1 - self.order)
        d_a, P_a = self.evaluate(cv, Hv, Rv, work_of_adhesion, mu)
        d_b, P_b = other.evaluate(cv, Hv, Rv, work_of_adhesion, mu)
        k = (Hv / cv if self.A > 0 else 2 * Hv / cv) if self.order == 1 else 1.0
        return 2 * k * np.abs(d_a - d_b) + 2 * abs(self.m1) * Hv**2 / Rv, 2 * k * np.abs(P_a - P_b)

    codegen_name = "thin_layer_jkr"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``(arguments, outputs)`` for code generation (:mod:`thinlayer.export.codegen`): ``delta0(c)`` and
        ``force(c)`` of (J.11) (or (J.15)) in the arguments ``c, H, R, w, mu`` (``vartheta = mu/(1 - nu)``), the
        layer's ``nu``, ``A``, ``h*`` named constants (:meth:`codegen_constants`).
        """
        mu_s, nu_s = sp.Symbol("mu", positive=True), sp.Symbol("nu", real=True)
        sub = {vt: mu_s / (1 - nu_s)}
        return (c, _H, _R, w, mu_s), {"delta0": self.depth.subs(sub), "force": self.force.subs(sub)}

    def codegen_constants(self) -> dict:
        """``{symbol: (number, note)}``: the layer's ``nu``, ``h*`` and (compressible) ``A``."""
        f = lambda v: sp.Float(v, 17)  # noqa: E731 - the layer's numbers, to double precision
        out = {sp.Symbol("nu", real=True): (f(self.nu), "Poisson ratio of the bonded layer"),
               h: (f(self.h), ("edge correction h of the incompressible layer (I.12)" if self.A == 0 else
                               f"edge shift h*(nu={self.nu:g}), exact Wiener-Hopf solution (3.18), (3.25)"))}
        if self.A != 0:
            out[A] = (f(self.A), f"A(nu={self.nu:g}) = (1 - 2 nu)/(2 (1 - nu)^2), lim L(s)/s (2.4)")
        if self.order == 2:
            out[m_1] = (f(self.m1), f"m_1(nu={self.nu:g}), the Maclaurin coefficient of L(s)/(A s) (2.20)")
        return out

    def pull_off(self, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0) -> tuple[float, float]:
        """``(c, -min P)`` under load control from (J.11) (numerical minimum; order 0: ``2 pi w R``)."""
        Hv, Rv, wv = positive(H, "H"), positive(R, "R"), positive(work_of_adhesion, "work_of_adhesion")
        # the minimum of P(c), located on a grid, refined; the law needs a_e = c + h* H > 0 (h* < 0 near nu = 1/2),
        # so the grid starts beyond -h* H: a point with no value (nan) is never taken for the minimum
        c_min = max(1e-2, -2.0 * self.h) if self.order else 1e-2
        grid = Hv * np.geomspace(c_min, 1e6, 801)
        with np.errstate(invalid="ignore"):
            P = np.asarray(self.evaluate(grid, Hv, Rv, wv, mu)[1], dtype=float)
        if not np.isfinite(P).any():
            raise InputError(f"ThinLayerJKR.pull_off: the law (nu = {self.nu:g}, order {self.order}) has no finite "
                             f"force for c/H in [{c_min:g}, 1e6]")
        c0 = float(grid[int(np.nanargmin(np.where(np.isfinite(P), P, np.nan)))])
        return _minimise(lambda x: float(self.evaluate(x, Hv, Rv, wv, mu)[1]), c0)

    def latex(self) -> str:
        ae = r"a_e = c" if self.order == 0 else r"a_e = c + h^* H"
        if self.order == 2:
            ae += r",\ a_2 = a_e + \frac{m_1 H^2}{c}"
        tag = self.equation
        return (rf"G = {sp.latex(self.release_rate)} = w:\quad "
                rf"\delta = {sp.latex(self.depth_display)},\quad P = {sp.latex(self.force_display)},\quad {ae}"
                rf"\quad (\text{{order {self.order}}}) \tag{{{tag}}}")

    def text_lines(self) -> list[str]:
        tags = "(J.15)" if self.A == 0 else "(J.10)-(J.12)"
        return [f"ThinLayerJKR: paraboloid on a bonded layer, nu = {self.nu:g}, order {self.order}   {tags}",
                f"  delta = {self.depth_display}", f"  P = {self.force_display}",
                "  a_e = " + ("c" if self.order == 0 else "c + h* H") + (", a_2 = a_e + m_1 H^2/c" if self.order == 2
                                                                       else ""),
                f"  A = {self.A:.12g}, h* = {self.h:.12g}; pull-off (order 0) {self.pull_off_leading}"]


@lru_cache(maxsize=32)
def _compiled(order: int, A_val: float, h_val: float, m1_val: float = 0.0) -> tuple:
    """Numpy functions ``(c, H, R, w, vartheta) -> delta, P`` of (J.11), (J.24) (``A = 0``: incompressible (J.15))."""
    depth, force = (_thin_incompressible(order) if A_val == 0 else _thin_symbolic(order))[:2]
    args = (c, _H, _R, w, vt)
    num = {A: A_val, h: h_val, m_1: m1_val}
    return sp.lambdify(args, depth.subs(num), "numpy"), sp.lambdify(args, force.subs(num), "numpy")


def _minimise(f, c0: float) -> tuple[float, float]:
    """Golden-section minimum of ``f`` on ``[c0/4, 4 c0]`` (f unimodal there), to 1e-12 relative in c."""
    a, b = 0.25 * c0, 4.0 * c0
    g = (math.sqrt(5) - 1) / 2
    x1, x2 = b - g * (b - a), a + g * (b - a)
    f1, f2 = f(x1), f(x2)
    while b - a > 1e-12 * c0:
        if f1 < f2:
            b, x2, f2 = x2, x1, f1
            x1 = b - g * (b - a)
            f1 = f(x1)
        else:
            a, x1, f1 = x1, x2, f2
            x2 = a + g * (b - a)
            f2 = f(x2)
    x = 0.5 * (a + b)
    return x, -f(x)


@lru_cache(maxsize=1)
def _second_order_radius() -> sp.Expr:
    """(J.24): ``a(c) = c + h* H + m_1 H^2/c`` from the edge shift (SO.5) of the sphere, and the check that the force
    (SO.8)-(SO.9) at that ``a`` is ``pi vartheta (c + h* H)^4/(4 A R H)`` to relative ``O((H/c)^2)``.
    """
    bl = second_order_boundary_layer()
    sym = {s.name: s for s in bl.edge_shift.free_symbols | bl.force_defect.free_symbols}
    t, aa, a1, a2 = sp.symbols("t a a_1 a_2", positive=True)
    sphere = {sym["epsilon"]: t * H / aa, sym["beta"]: t * H / (2 * aa)}  # kappa = 1/a, Phi_nn/|grad Phi| = 1/a
    hs = bl.edge_shift.subs(sphere).subs(sym["m_1"], m_1)
    ansatz = c + a1 * t * H + a2 * (t * H) ** 2 / c
    resid = (aa - t * H * hs).subs(aa, ansatz) - c

    def taylor(expr: sp.Expr, j: int) -> sp.Expr:  # j! times the t^j coefficient at t = 0
        return sp.cancel(sp.diff(expr, t, j).subs(t, 0))

    sol = sp.solve([taylor(resid, 1), taylor(resid, 2)], [a1, a2], dict=True)
    if len(sol) != 1 or sol[0] != {a1: h, a2: m_1}:
        raise ArithmeticError(f"(J.24): the inverse of (SO.5) is not a = c + h* H + m_1 H^2/c: {sol}")
    a_c = ansatz.subs(sol[0]).subs(t, 1)
    # the force (SO.8): the inner pressure p_0 + p_1 (2.26), (4.1) over the disc of radius a plus the edge defect
    ip = inner_pressure(GenericLayer(), Punch.paraboloid(R)).pressure
    ip = ip.subs({s: m_1 for s in ip.free_symbols if s.name == "m_1"}).subs({S.x1: r, S.x2: 0})
    delta_a = aa**2 / (2 * R)  # Gamma_0: p_0 = 0 at r = a
    P_in = 2 * sp.pi * sp.integrate(ip.subs(delta, delta_a) * r, (r, 0, aa))
    D = bl.force_defect.subs(sphere).subs(t, 1).subs(sym["m_1"], m_1) / A  # (SO.8), |grad Phi| = a/R
    P = P_in + 2 * sp.pi * aa * vt * (aa / R) * H * D
    P = P.subs(H, t * H).subs(aa, ansatz.subs(sol[0]))
    ref = sp.pi * vt * (c + h * t * H) ** 4 / (4 * A * R * t * H)
    # vartheta, A, R are overall factors and H comes with t: set them to 1 (the identity is homogeneous in each)
    F = sp.cancel(sp.expand((t * (P - ref)).subs({vt: 1, A: 1, R: 1, H: 1})))
    left = [taylor(F, j) for j in range(3)]  # t ref = O(1): P/ref = 1 + O(t^3) iff these vanish
    if any(v != 0 for v in left):
        raise ArithmeticError(f"(J.24): P_1(c) - pi vartheta (c + h* H)^4/(4 A R H) has the terms {left}")
    return a_c


@lru_cache(maxsize=3)
def _thin_symbolic(order: int) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
    """(J.10)-(J.12) in sympy with the engine's stages: (2.29) via ``inner_pressure``, (F.12) via the flat punch;
    order 2: (J.24) with the radius of (SO.5).
    """
    if order == 2:
        depth, force, G, pull, depth_ae, force_ae = _thin_symbolic(1)
        a_e = sp.Symbol("a_e", positive=True)
        smooth = sp.expand(depth - depth.subs(w, 0))
        if sp.expand(depth.subs(w, 0) - (c + h * H) ** 2 / (2 * R)) != 0:
            raise ArithmeticError("(J.11): delta_1 is not (c + h* H)^2/(2R)")
        a_c = _second_order_radius()
        a_2 = sp.Symbol("a_2", positive=True)  # printed: a_2 = a_e + m_1 H^2/c
        return (smooth + a_c**2 / (2 * R), force, G, pull, depth_ae - a_e**2 / (2 * R) + a_2**2 / (2 * R), force_ae)
    ip = inner_pressure(GenericLayer(), Punch.paraboloid(R)).pressure
    m1 = [s for s in ip.free_symbols if s.name == "m_1"]
    p_out = ip.subs({m: 0 for m in m1}).subs({S.x1: r, S.x2: 0})  # (2.29); the m_1 term is O((H/c)^2)
    hh = h if order == 1 else 0
    a_e = sp.Symbol("a_e", positive=True)  # the outer contour c + h* H (order 1) or c (order 0)
    delta1 = _linear_root(p_out.subs(r, a_e), delta)  # K_I = 0 at radius c: (3.25)
    P_of = 2 * sp.pi * sp.integrate(p_out * r, (r, 0, a_e))  # outer pressure over the disc of radius a_e
    P1 = sp.expand(P_of.subs(delta, delta1))
    S_c = sp.diff(P_of, delta)  # flat-punch stiffness at fixed c: pi vartheta a_e^2/(A H), i.e. (F.12)
    lam = sp.Symbol("lambda", positive=True)
    der = thin_flat_punch_derivation()
    kr = der.resummed.subs({der.h: hh, der.A: A})
    if sp.simplify((S_c - 4 * vt * c * kr.subs(lam, c / H)).subs(a_e, c + hh * H)) != 0:
        raise ArithmeticError("(J.10): the outer stiffness is not (F.12)")
    f1sq = sp.diff(lam * kr, lam).subs(lam, c / H)  # Krein (F.9)
    G = sp.factor(vt * d**2 * f1sq / (sp.pi * c))  # (J.4), (J.10)
    d_jkr = -sp.sqrt(w * c / sp.factor(G * c / d**2).subs(c + hh * H, a_e))
    depth_ae = delta1 + d_jkr
    force_ae = P1 + sp.expand(S_c * d_jkr)
    depth, force = depth_ae.subs(a_e, c + hh * H), force_ae.subs(a_e, c + hh * H)
    if order == 0:
        depth_ae, force_ae = depth, force
    # (J.12) order 0: P = a X^2 - b X, X = c^2
    P0 = force.subs(h, 0)
    X = sp.Symbol("X", positive=True)
    PX = sp.expand(P0.subs(c, sp.sqrt(X)))
    a2, b1 = PX.coeff(X, 2), -PX.coeff(X, 1)
    pull = sp.simplify(b1**2 / (4 * a2))
    # leading order of (J.10) equals the straight-edge boundary layer (J.9)
    # p_out at the distance n = x1 from the edge
    p_lin = sp.expand(p_out.subs(delta, delta1.subs(a_e, c + hh * H) + d).subs(r, c - S.x1))
    pe, ps = p_lin.subs(S.x1, 0), sp.diff(p_lin, S.x1).subs(S.x1, 0)
    G9 = (sp.sqrt(2 * A * H) * (pe - h * H * ps)) ** 2 / (4 * vt)
    ratio = sp.series((G / G9).subs(H, t * H), t, 0, 2).removeO().subs(t, 1)
    if order == 1 and sp.simplify(ratio - (1 + h * H / c)) != 0:
        raise ArithmeticError("(J.10): G / (J.9) is not 1 + h* H/c + O(H^2)")
    return depth, force, G, pull, depth_ae, force_ae


@lru_cache(maxsize=2)
def _thin_incompressible(order: int) -> tuple:
    """(J.15) in sympy: the operator (I.2) at nu = 1/2 for the smooth part, (F.14) and Krein for the flat part."""
    op = thin_layer_operator(IncompressibleLayer(), 1)
    (mu,) = op.vartheta.free_symbols
    b0, b1, b2 = sp.symbols("b_0 b_1 b_2")
    rr = S.x1**2 + S.x2**2
    resid = sp.Poly(sp.expand(op.apply(b0 + b1 * rr + b2 * rr**2) - (delta - rr / (2 * R))), S.x1, S.x2)
    sol = sp.solve(resid.coeffs(), [b1, b2], dict=True)[0]  # (I.2) inside the contact, u3 = delta - Phi
    p_out = (b0 + sol[b1] * r**2 + sol[b2] * r**4).subs(mu, vt / 2)
    hh = h if order == 1 else 0
    a_e = sp.Symbol("a_e", positive=True)
    b0v = _linear_root(p_out.subs(r, a_e), b0)  # p = 0 at the model's edge ...
    p_out = p_out.subs(b0, b0v)
    delta1 = _linear_root(sp.diff(p_out, r).subs(r, a_e), delta)  # ... and p' = 0 there (I.4): the smooth edge
    P1 = sp.factor(2 * sp.pi * sp.integrate(p_out.subs(delta, delta1) * r, (r, 0, a_e)))
    lam = sp.Symbol("lambda", positive=True)
    der = thin_flat_punch_derivation()
    kr = der.incompressible_resummed.subs({der.h: hh})  # (F.14), vartheta = 2 mu
    def in_ae(expr: sp.Expr) -> sp.Expr:  # written in a_e = c + h* H (order 1)
        return sp.factor(expr.subs(h, (a_e - c) / H)) if order == 1 else expr.subs(a_e, c)

    S_c = in_ae(4 * vt * c * kr.subs(lam, c / H))
    f1sq = sp.diff(lam * kr, lam).subs(lam, c / H)  # Krein (F.9)
    G = sp.factor(vt * d**2 * f1sq / (sp.pi * c))
    d_jkr = -sp.sqrt(w * c / in_ae(G * c / d**2))
    depth_ae, force_ae = delta1 + d_jkr, P1 + sp.expand(S_c * d_jkr)
    depth, force = depth_ae.subs(a_e, c + hh * H), force_ae.subs(a_e, c + hh * H)
    if order == 0:
        depth_ae, force_ae = depth, force
    P0 = force.subs(h, 0)
    (c_min,) = _positive_roots(sp.diff(P0, c))
    pull = sp.simplify(-P0.subs(c, c_min))
    return depth, force, G, pull, depth_ae, force_ae


def thin_layer_jkr(nu: Any, order: int = 1) -> ThinLayerJKR:
    """Thin-layer JKR for the paraboloid on a bonded layer (J.10)-(J.12); at ``nu = 1/2`` (J.15).

    Parameters
    ----------
    nu : float
        Poisson ratio, ``-1 < nu < 1/2`` (compressible), or exactly ``1/2`` (incompressible, (J.15)).  Nearly
        incompressible layers need ``(c/H)^2 >> m_1``: see :meth:`ThinLayerJKR.error_estimate`.
    order : int
        0, 1 or (compressible only) 2 (see the module docstring); the law is valid for ``c >> H``.

    Returns
    -------
    ThinLayerJKR
    """
    check_choice(order, (0, 1, 2), "order")
    try:
        val = float(nu)
    except (TypeError, ValueError):
        raise InputError(f"nu must be a number in (-1, 1/2], got {nu!r}") from None
    if val == 0.5 and order == 2:
        raise InputError("order 2 (J.24) is derived for the compressible layer (nu < 1/2); at nu = 1/2 use order 1")
    if val == 0.5:  # (J.15)
        depth, force, G, pull, depth_ae, force_ae = _thin_incompressible(order)
        return ThinLayerJKR(val, 0.0, float(two_term_edge_shift(dps=16)), order, depth, force, G, pull, depth_ae,
                            force_ae, 0.0)
    if not -1.0 < val < 0.5:
        raise InputError(f"nu must lie in (-1, 1/2) (the compressible layer, A > 0) or be 1/2, got {nu!r}")
    lay = BondedLayer(val)
    depth, force, G, pull, depth_ae, force_ae = _thin_symbolic(order)
    r3 = float(edge_constants(lay, dps=16).r3) if order == 2 else 0.0
    return ThinLayerJKR(val, float(lay.A), float(edge_shift_exact(val, dps=16)), order, depth, force, G, pull,
                        depth_ae, force_ae, float(lay.m(1)), r3)


# --------------------------------------------------------------------------- (J.13) the flat punch
@dataclass(frozen=True)
class ThinFlatDetachment(RichDisplay):
    """Thin-layer detachment force of a flat punch on a bonded layer: compressible (J.13) or incompressible (J.14).

    Attributes
    ----------
    nu, A, h : float
        float
        Poisson ratio, ``A`` (2.4), ``h*`` (3.18).
    order : int
        0 or 1.
    force : sympy.Expr
        ``P_off`` in ``a, H, w, vartheta, A, h*`` (``a`` is the symbol ``c``).
    """

    nu: float
    A: float
    h: float
    order: int
    force: sp.Expr

    equation = "J.13"

    def __call__(self, radius: Any, H: Any, work_of_adhesion: Any, mu: Any = 1.0) -> np.ndarray:
        """``P_off`` (a magnitude), vectorised in the radius."""
        a = positive_radii(radius)
        Hv, wv = positive(H, "H"), check_work(work_of_adhesion)
        vtv = positive(mu, "mu") / (1 - self.nu)
        return np.asarray(_flat_compiled(self.force, self.A, self.h)(a, Hv, wv, vtv), dtype=float)

    def latex(self) -> str:
        tag = "J.14" if self.nu == 0.5 else "J.13"
        return rf"P_{{\mathrm{{off}}}} = {sp.latex(self.force)} \tag{{{tag}}}"

    def text_lines(self) -> list[str]:
        return [f"ThinFlatDetachment: flat punch, bonded layer nu = {self.nu:g}, order {self.order}   (J.13)",
                f"  P_off = {self.force}", f"  A = {self.A:.12g}, h* = {self.h:.12g}"]


@lru_cache(maxsize=8)
def _flat_compiled(expr: sp.Expr, A_val: float, h_val: float) -> Any:
    return sp.lambdify((c, H, w, vt), expr.subs({A: A_val, h: h_val}), "numpy")


@lru_cache(maxsize=4)
def _flat_symbolic(order: int, incompressible: bool) -> sp.Expr:
    lam = sp.Symbol("lambda", positive=True)
    der = thin_flat_punch_derivation()
    hh = h if order == 1 else 0
    if incompressible:  # (F.14), (J.14)
        kr = der.incompressible_resummed.subs({der.h: hh})
        ref = (sp.sqrt(3) * sp.pi / 4 * sp.sqrt(vt * w) * (c + hh * H) ** sp.Rational(5, 2) * sp.sqrt(c)
               / H ** sp.Rational(3, 2))
    else:  # (F.12), (J.13)
        kr = der.resummed.subs({der.h: hh, der.A: A})
        ref = sp.pi * (c + hh * H) ** sp.Rational(3, 2) * sp.sqrt(c) * sp.sqrt(2 * vt * w / (A * H))
    f1sq = sp.diff(lam * kr, lam)  # Krein (F.9)
    P = (4 * vt * c * kr * sp.sqrt(sp.pi * c * w / vt) / sp.sqrt(f1sq)).subs(lam, c / H)
    ae = sp.Symbol("a_e", positive=True)  # a_e = c + h* H > 0 on the law's range (c >> H)
    ratio = (P / ref).subs(h, (ae - c) / H) if order == 1 else P / ref
    if sp.simplify(sp.expand_power_base(sp.powsimp(ratio, force=True), force=True)) != 1:
        raise ArithmeticError("(J.13)/(J.14): the detachment force differs from its closed form")
    return ref


def thin_flat_detachment(nu: Any, order: int = 1) -> ThinFlatDetachment:
    """Kendall's thin-film detachment force with its first correction (J.13), (J.14); valid for ``a >> H``.

    Parameters
    ----------
    nu : float
        Poisson ratio, ``-1 < nu < 1/2`` (J.13), or exactly ``1/2`` (the incompressible layer, J.14).
        Nearly incompressible layers (``nu`` near 1/2, ``(a/H)^2`` not large against ``m_1``) are outside both.
    order : int
        0 or 1.

    Returns
    -------
    ThinFlatDetachment
    """
    check_choice(order, (0, 1), "order")
    try:
        val = float(nu)
    except (TypeError, ValueError):
        raise InputError(f"nu must be a number in (-1, 1/2], got {nu!r}") from None
    if val == 0.5:  # (J.14)
        return ThinFlatDetachment(val, 0.0, float(two_term_edge_shift(dps=16)), order, _flat_symbolic(order, True))
    if not -1.0 < val < 0.5:
        raise InputError(f"nu must lie in (-1, 1/2) (the compressible layer, A > 0) or be 1/2, got {nu!r}")
    lay = BondedLayer(val)
    return ThinFlatDetachment(val, float(lay.A), float(edge_shift_exact(val, dps=16)), order,
                              _flat_symbolic(order, False))


# --------------------------------------------------------------------------- every step
@dataclass(frozen=True)
class AdhesionDerivation(RichDisplay):
    """The steps (J.7)-(J.13) for one compressible bonded layer, each a result with its LaTeX.

    Attributes
    ----------
    nu : float
        Poisson ratio.
    assumptions : str
        The assumptions, as printed.
    half_space : HalfSpaceJKR
        (J.7).
    edge_layer : AdhesiveEdgeLayer
        (J.8), (J.9).
    jkr : tuple of ThinLayerJKR
        (J.10)-(J.12) at orders 0 and 1.
    flat : ThinFlatDetachment
        (J.13) at order 1.
    """

    nu: float
    assumptions: str
    half_space: HalfSpaceJKR
    edge_layer: AdhesiveEdgeLayer
    jkr: tuple
    flat: ThinFlatDetachment

    equation = "J.7-J.13"

    def steps(self) -> list[tuple[str, str]]:
        """``(tag, LaTeX)`` of every step, in order."""
        return [("J.7", self.half_space.latex()), ("J.8", self.edge_layer.latex()),
                *((f"J.11 (order {t.order})", t.latex()) for t in self.jkr),
                ("J.12", rf"P_{{\mathrm{{off}}}} = {sp.latex(self.jkr[0].pull_off_leading)}"
                         r"\quad (\text{load control, order 0}) \tag{J.12}"),
                ("J.13", self.flat.latex())]

    def latex(self) -> str:
        return "\n".join(rf"\[ {tex} \]" for _, tex in self.steps())

    def text_lines(self) -> list[str]:
        return [f"AdhesionDerivation: JKR on a bonded layer, nu = {self.nu:g}   (J.7)-(J.13)",
                f"  assumptions: {self.assumptions}", *(f"  ({tag}) see .latex()" for tag, _ in self.steps())]


def adhesion_derivation(nu: Any) -> AdhesionDerivation:
    """Every step (J.7)-(J.13) for the compressible bonded layer of Poisson ratio ``nu`` (a few seconds of sympy)."""
    edge = adhesive_edge_layer(nu)
    return AdhesionDerivation(edge.nu, "frictionless contact, layer bonded to a rigid base (no slip), compressible "
                              "(A > 0), JKR adhesion (short-range: w spent at the contact edge), c >> H for "
                              "(J.8)-(J.13)", half_space_jkr(), edge,
                              (thin_layer_jkr(nu, 0), thin_layer_jkr(nu, 1)), thin_flat_detachment(nu, 1))

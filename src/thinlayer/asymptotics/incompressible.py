r"""The incompressible bonded layer (nu = 1/2) and nearly incompressible layers.

At ``nu = 1/2`` the bonded-layer kernel (2.3) has ``kappa = 1`` and ``A = 0`` (2.4): the leading
term of the inner problem (2.27) is no longer algebraic.  This module derives the thin-layer
model from the same moment expansion (2.14)-(2.23), solves it, and joins it to the compressible
expansion of the paper.  Equations that the paper does not have carry tags ``I.n``.

Kernel and operator (I.1), (I.2)
--------------------------------
With ``kappa = 1`` the Maclaurin data of ``L(s)/s`` (power-series arithmetic on sinh, cosh, as in
:mod:`thinlayer.layers.coefficients`) start one order later::

    L(s)/s = c_1 s^2 + c_2 s^4 + ...,   c_0 = A = 0,   c_1 = 2/3,   c_2 = -6/5, ...      (I.1)

The moment expansion (2.22) with weights ``(-1)^n pi^2 c_n`` (in the compressible case
``c_n = A m_n``) acts on a smooth density as the operator series (2.23); written in dimensional
variables (``Lambda^{-2} Delta_xi = H^2 Delta_x``) the surface displacement is::

    u_3 = (H/vartheta) sum_n (-1)^n c_n H^{2n} Delta^n p,   vartheta = mu/(1 - nu).       (I.2)

At ``nu = 1/2`` (``vartheta = 2 mu``) the leading term is ``u_3 = -(H^3/(3 mu)) Delta p``: the
classical thin incompressible layer (Jaffar; Barber), here obtained from the kernel.

The free-boundary problem (I.3), (I.4)
--------------------------------------
The unilateral conditions (1.5) with the leading operator become: ``p >= 0``,
``-(c_1 H^3/vartheta) Delta p >= delta0 - Phi``, with equality where ``p > 0``.  Dividing by
``c_1 H^3/vartheta``::

    -Delta p = f  in omega,   f = (vartheta/(c_1 H^3)) (delta0 - Phi) = (3 mu/H^3)(delta0 - Phi),   (I.3)
    p = 0,  dp/dn = 0  on the contour of omega.                                               (I.4)

Two conditions on the unknown contour: extended by zero, ``p`` has the distributional Laplacian
``Delta p 1_omega - (dp/dn) delta_Gamma``; a non-zero normal derivative would put a line load of
*displacement* on the contour, which is not a function, so ``dp/dn = 0``.  Equivalently (I.3)-(I.4)
is the obstacle problem ``min int (|grad p|^2/2 - f p) dx`` over ``p >= 0``, whose solution is
``C^{1,1}``.  Integrating ``-Delta p = f`` against any harmonic ``v`` (Green's formula, both
boundary terms vanish by (I.4)) gives the *quadrature-domain identities*::

    int_omega f v dx = 0   (v harmonic),   in particular   int_omega (delta0 - Phi) dx = 0,   (I.5)

(the penetrated volume is pushed up inside the contact: incompressibility), and, with ``v = |x|^2``
(``Delta v = 4``), the force ``P = -(1/4) int_omega f |x|^2 dx``.

Elliptic paraboloid (I.6)-(I.8)
-------------------------------
``p = C (1 - x1^2/a^2 - x2^2/b^2)^2`` satisfies (I.4) identically and (I.3) when three polynomial
coefficients match.  Eliminating ``C`` and ``a`` leaves, for the aspect ratio ``t = a^2/b^2`` and
``r = R1/R2``::

    3 t^2 + (1 - r) t - 3 r = 0,   t = (r - 1 + sqrt(r^2 + 34 r + 1))/6                       (I.6)

(the product of the roots is ``-r < 0``: exactly one positive root).  ``t = 1`` for ``r = 1``,
``t ~ r/3`` for ``r -> oo`` and ``t ~ 3r`` for ``r -> 0``: the incompressible contact ellipse is
rounder than the compressible one, ``b^2/a^2 = R2/R1`` (3.1).  Then::

    a^2 = 2 R1 delta0 (3 + t)/(1 + t),  b^2 = 2 R2 delta0 (3 t + 1)/(1 + t),
    C = 3 mu R1 delta0^2 (3 + t)/(2 H^3 (1 + t)^2),                                          (I.7)
    P = pi a b C/3 = pi mu R1^2 delta0^3 (3 + t)^2 / (H^3 (1 + t)^3 sqrt(t)),                (I.8)

and for the sphere ``a^2 = 4 R delta0``, ``P = 2 pi mu R^2 delta0^3/H^3``.  The relation (I.6)
also follows, independently of the ansatz, from the harmonic moments (I.5) with ``v = 1`` and
``v = x1^2 - x2^2`` (tested).

Axisymmetric punches (I.9)
--------------------------
For ``Phi = Phi(r)`` the radial form of (I.3) integrates twice: ``p'(r) = -(1/r) int_0^r f s ds``,
so (I.4) gives the radius from ``int_0^c (delta0 - Phi) r dr = 0`` and
``p(r) = int_r^c (1/rho) int_0^rho f s ds d rho``.

Nearly incompressible layers: the two-term model (I.10)-(I.13)
--------------------------------------------------------------
The compressible expansion (2.26)-(2.31) is a series in ``m_1 (H/a)^2``, and
``m_1 = nu (4 nu - 1)/(3 (1 - 2 nu)(1 - nu)) ~ 1/(3 (1 - 2 nu))`` blows up as ``nu -> 1/2``
(the inner correction (2.30) of the sphere's force, ``-2 m_1 H^2/(R delta0)``, exceeds 1 at
``nu = 0.499``, ``a/H = 20``).  Keeping *both* ``c_0 = A`` and ``c_1 = A m_1`` in (I.2)::

    (H/vartheta)(A p - A m_1 H^2 Delta p) = delta0 - Phi  in omega,  p = dp/dn = 0  on its contour,   (I.10)

i.e. ``-Delta p + k^2 p = f`` with ``k^2 = 1/(m_1 H^2)`` and ``f = vartheta (delta0 - Phi)/(A m_1 H^3)``,
an obstacle problem again (``m_1 > 0`` needs ``1/4 < nu <= 1/2``).  Both limits are contained:
for ``k a >> 1`` its inner solution is ``(vartheta/(A H))(delta0 - Phi - m_1 H^2 Delta Phi)`` (2.26), (4.1)
and its edge layer, ``q = g (v + l e^{-(v + l)/l})`` with ``l = sqrt(m_1)``, has the force defect
``l^2/2 = m_1/2`` -- the same as the Wiener--Hopf boundary layer (see :mod:`thinlayer.asymptotics.force_law`), so
the force is right to first order; for ``k a << 1`` it is (I.3).  The ratio of the two terms is

    lambda^2 = (a/H)^2 / m_1  ~  3 (1 - 2 nu) (a/H)^2:                                      (I.13)

the compressible expansion holds for ``lambda^2 >> 1`` (``1 - 2 nu >> (H/a)^2/3``), the
incompressible model for ``lambda^2 << 1`` (its force is off by ``-(3/16) lambda^2`` for the sphere),
the two-term model everywhere (``nu > 1/4``).  See :func:`regime`.

For the sphere, ``p = (f0 - f2 r^2)/k^2 - 4 f2/k^4 + B I_0(k r)`` and (I.4) give, with ``x = k c``::

    delta0 = c^2 (1 - 2 psi(x))/(2 R),   P = 2 pi f2 c^6 chi(x),                             (I.11)
    psi(x) = (x I_0(x)/I_1(x) - 2)/x^2,   chi(x) = (1/4 - psi(x))/x^2,   f2 = vartheta/(2 R A m_1 H^3),

smooth at ``x = 0`` (``psi = 1/4 - x^2/96 + ...``, ``chi = 1/96 - ...``): one formula from the
compressible to the incompressible limit, evaluated without cancellation.

Edge correction (I.12).  The local models put the contact edge where the outer solution ends;
the true edge lies ``h(nu) H`` inside it, with the Wiener--Hopf factor ``K = F/(c_0 + c_1 s^2)``
(``F = L(s)/s``; ``K -> 1`` at ``s = 0``)::

    h(nu) = -(1/pi) int_0^oo log(F(t)/(c_0 + c_1 t^2)) t^{-2} dt,      h(1/2) = 1.4591...

With ``K = K_+ K_-`` and ``K_+(s) = 1 + K_1 s + ...``, the half-line problems of the true kernel and of
the model, driven by the same outer solution, have edges ``-i K_1`` apart (the argument of (3.25),
now relative to the model; the outer forcing -- linear in the compressible, constant in the
incompressible case -- does not enter).  For ``nu < 1/2``, ``h = h^*(nu) + sqrt(m_1)``: the paper's
edge shift plus the model's outward shift ``sqrt(m_1)`` (tested against
:func:`thinlayer.asymptotics.wiener_hopf.edge_shift_exact`).

Accuracy, measured against the direct solver (sphere, tests): at ``nu = 1/2`` the force of (I.8) is
low by ``~21 (H/a)^2`` (rate 1.93 between ``a/H = 20`` and 40) and ``(a - c)/H -> h(1/2)`` at rate ``H/a``;
the two-term force is within 2.5 % at ``a/H = 20`` for every ``0.45 <= nu <= 1/2`` (0.1 % at 0.45,
0.4 % at 0.49, 1.5 % at 0.499, 2.45 % at 1/2 where it is (I.8)) and its corrected radius within
0.5 %, where the compressible law fails by 249 % (nu = 0.499) and the
incompressible one by a factor 37 (nu = 0.45).

Numerics: :func:`solve_obstacle_grid` solves (I.3)/(I.10) for any punch on a grid (5-point
Laplacian, primal-dual active-set iteration with sparse LU); the direct solver
:func:`thinlayer.numerics.direct.solve_axisymmetric` accepts :class:`IncompressibleLayer` at ``nu = 1/2``.
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import check_order as _check_order
from .._series import quotient_field
from ..layers.coefficients import IncompressibleCoefficients, incompressible_coefficients
from ..layers.kernels import HALF, BondedLayer, IncompressibleLayer, LayerKernel
from ..punch import Punch, PunchError
from ..results import checked_lambdify, latex_equation
from ..symbols import laplacian

__all__ = [
    "EllipseValues",
    "GridContact",
    "IncompressibleCoefficients",
    "IncompressibleEllipse",
    "IncompressibleLayer",
    "IncompressibleRadial",
    "ObstacleProblem",
    "RadialValues",
    "Regime",
    "SphereModels",
    "SphereValues",
    "ThinLayerOperator",
    "TwoTermEdgeLayer",
    "TwoTermSphere",
    "compare_sphere_models",
    "incompressible_axisymmetric",
    "incompressible_coefficients",
    "incompressible_ellipse",
    "obstacle_problem",
    "regime",
    "solve_obstacle_grid",
    "thin_layer_operator",
    "two_term_edge_layer",
    "two_term_edge_shift",
    "two_term_sphere",
]

HALF = sp.Rational(1, 2)
QUARTER = sp.Rational(1, 4)
#: the pressure as an unknown function in the free-boundary problems (I.3), (I.10)
p_fun = sp.Function("p")
#: aspect ratio t = a^2/b^2 and radius ratio r = R1/R2 of (I.6)
t_sym = sp.Symbol("t", positive=True)
r_sym = sp.Symbol("r", positive=True)
#: contact radius and the radial coordinate of axisymmetric results
c_sym = sp.Symbol("c", positive=True)
rho = sp.Symbol("r", nonnegative=True)


# =============================================================================================
# (I.2) the operator series
# =============================================================================================
def _layer_vartheta(layer: LayerKernel) -> sp.Expr:
    v = getattr(layer, "vartheta", None)
    return v if v is not None else S.VARTHETA


@dataclass(frozen=True)
class ThinLayerOperator:
    """The thin-layer operator (2.22)-(2.23) in dimensional form (I.2)::

        u_3 = (H/vartheta) sum_{n=0}^{order} (-1)^n c_n H^{2n} Delta^n p,   c_n = [s^{2n}] L(s)/s,

    for any layer with a small-s expansion (``c_n = A m_n`` for ``nu < 1/2``, (I.1) at ``nu = 1/2``).

    Attributes
    ----------
    layer, order:
        The layer kernel and the highest power of the Laplacian kept.
    c:
        ``(c_0, ..., c_order)``.
    """

    layer: LayerKernel
    order: int
    c: tuple

    equation = "I.2"

    @property
    def vartheta(self) -> sp.Expr:
        return _layer_vartheta(self.layer)

    def weights(self) -> tuple:
        """Weights ``(-1)^n pi^2 c_n`` of ``Lambda^{-2n-2} Delta^n delta`` in the moment expansion (2.22)."""
        return tuple((-1) ** n * sp.pi**2 * cn for n, cn in enumerate(self.c))

    def apply_scaled(self, f: sp.Expr, v1: sp.Symbol = S.xi1, v2: sp.Symbol = S.xi2,
                     Lam: sp.Expr = S.Lambda) -> sp.Expr:
        """The operator series (2.23) on a density ``f(xi)``: ``sum_n w_n Lambda^{-2n-2} Delta^n f``."""
        return sp.Add(*[w * Lam ** (-2 * n - 2) * laplacian(f, v1, v2, n) for n, w in enumerate(self.weights())])

    def pairing(self, phi: sp.Expr, v1: sp.Symbol = S.xi1, v2: sp.Symbol = S.xi2,
                Lam: sp.Expr = S.Lambda) -> sp.Expr:
        """``<k(Lambda xi), phi>`` by (2.16), built from the individual moments ``mu_alpha`` (2.15).

        Comparing it with :meth:`apply_scaled` checks the moments against the Laplacian form (2.22).
        """
        moment = self.layer.moment if isinstance(self.layer, IncompressibleLayer) else None
        if moment is None:
            from ..layers.moments import kernel_moment

            def moment(a1: int, a2: int, _l=self.layer):
                return kernel_moment(_l, a1, a2)
        terms = []
        for total in range(2 * self.order + 2):
            for a1 in range(total + 1):
                a2 = total - a1
                mu_a = moment(a1, a2)
                if mu_a == 0:
                    continue
                d = sp.diff(phi, v1, a1, v2, a2) if (a1 or a2) else phi
                terms.append(mu_a * d.subs({v1: 0, v2: 0}) / (sp.factorial(a1) * sp.factorial(a2)
                                                                 * Lam ** (total + 2)))
        return sp.Add(*terms)

    def apply(self, p: sp.Expr, v1: sp.Symbol = S.x1, v2: sp.Symbol = S.x2) -> sp.Expr:
        """``u_3`` of (I.2) for a pressure ``p(x1, x2)`` (dimensional)."""
        return self.vartheta ** -1 * sp.Add(*[(-1) ** n * cn * S.H ** (2 * n + 1) * laplacian(p, v1, v2, n)
                                             for n, cn in enumerate(self.c)])

    def leading(self) -> sp.Expr:
        """The leading non-zero term of (I.2) applied to ``p(x1, x2)`` (``-(H^3/(3 mu)) Delta p`` at nu = 1/2)."""
        for n, cn in enumerate(self.c):
            if cn != 0:
                pf = p_fun(S.x1, S.x2)
                return sp.factor((-1) ** n * cn * S.H ** (2 * n + 1) / self.vartheta) * laplacian(pf, S.x1, S.x2, n)
        raise ValueError(f"all coefficients c_0..c_{self.order} vanish; raise the order")

    def latex(self) -> str:
        parts = []
        for n, cn in enumerate(self.c):
            if cn == 0:
                continue
            coef = sp.factor((-1) ** n * cn * S.H ** (2 * n + 1) / self.vartheta)
            op = "p" if n == 0 else (r"\Delta p" if n == 1 else rf"\Delta^{{{n}}} p")
            parts.append(rf"\left({sp.latex(coef)}\right) {op}")
        return r"u_3 = " + " + ".join(parts) + r" + \dots \tag{I.2}"

    def lambdify(self, backend: str = "numpy") -> Callable:
        """Numeric ``(c_0, ..., c_order)`` as a function of the layer's parameter (none at nu = 1/2)."""
        prm = self.layer.parameter if not isinstance(self.layer, IncompressibleLayer) else None
        return checked_lambdify([prm] if prm is not None else [], list(self.c), backend)


def thin_layer_operator(layer: LayerKernel, order: int = 1) -> ThinLayerOperator:
    """The operator series (I.2) through ``Delta^order``, from the moment expansion (2.22).

    Parameters
    ----------
    layer:
        :class:`IncompressibleLayer`, or a compressible layer (``BondedLayer(nu)``, symbolic or numeric).
    order:
        Highest power of the Laplacian (non-negative integer).

    Examples
    --------
    >>> thin_layer_operator(IncompressibleLayer()).leading()
    -H**3*(Derivative(p(x_1, x_2), (x_1, 2)) + Derivative(p(x_1, x_2), (x_2, 2)))/(3*mu)
    """
    if not isinstance(layer, LayerKernel):
        raise TypeError(f"layer must be a thinlayer LayerKernel (IncompressibleLayer(), BondedLayer(nu)), "
                        f"got {layer!r}")
    order = _check_order(order, "order")
    return ThinLayerOperator(layer, order, layer.taylor_coefficients(order))


# =============================================================================================
# Poisson ratio of the models
# =============================================================================================
def _parse_nu(nu: Any) -> sp.Basic:
    """A Poisson ratio for the two-term / incompressible models: Symbol, exact Rational or Float in (1/4, 1/2]."""
    if nu is None:
        return S.nu
    if isinstance(nu, sp.Symbol):
        return nu
    if isinstance(nu, bool):
        raise TypeError("nu must be a number in (1/4, 1/2] or a sympy Symbol, got a bool")
    if isinstance(nu, str):
        try:
            val = sp.Rational(nu)
        except (TypeError, ValueError, sp.SympifyError) as exc:
            raise ValueError(f"nu={nu!r} is not a number; give e.g. '49/100', 0.49 or 0.5") from exc
    elif isinstance(nu, (sp.Rational, numbers.Integral, Fraction)):
        val = sp.Rational(nu)
    elif isinstance(nu, (float, sp.Float, mpmath.mpf, numbers.Real)):
        f = float(nu)
        if not math.isfinite(f):
            raise ValueError(f"nu must be finite, got {nu!r}")
        val = HALF if f == 0.5 else sp.Float(f, 17)
    else:
        raise TypeError(f"nu must be a number in (1/4, 1/2] or a sympy Symbol, got {type(nu).__name__}")
    if not (QUARTER < val <= HALF):
        raise ValueError(
            f"nu={nu!r}: the incompressible/two-term models need 1/4 < nu <= 1/2 (m_1 > 0, so that "
            "-m_1 H^2 Delta + 1 is elliptic); for nu <= 1/4 use the compressible expansion "
            "(thinlayer.inner_pressure, thinlayer.solve)"
        )
    return val


def _model_coefficients(nu: sp.Basic) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """``(c_0, c_1, vartheta)`` of the two-term operator (I.10) for a parsed nu (exact, symbolic or float)."""
    if nu == HALF:
        c = incompressible_coefficients(1).c
        return c[0], c[1], IncompressibleLayer().vartheta
    if isinstance(nu, sp.Symbol):
        co = BondedLayer().coefficients(1)
        c0, c1 = co.A_expr, co.A_expr * co.m_expr(1)
        if nu != S.nu:
            c0, c1 = c0.subs(S.nu, nu), c1.subs(S.nu, nu)
        return c0, sp.factor(c1), S.mu / (1 - nu)
    if isinstance(nu, sp.Float):
        co = BondedLayer(mpmath.mpf(str(nu)), dps=30).coefficients(1)
        c0, c1 = sp.Float(co.A, 20), sp.Float(co.A * co.m[1], 20)
        return c0, c1, S.mu / (1 - nu)
    co = BondedLayer(nu).coefficients(1)
    return co.A_expr, co.A_expr * co.m_expr(1), S.mu / (1 - nu)


def _model_floats(nu: Any) -> tuple[float, float, float, float]:
    """``(nu, c_0, c_1, vartheta/mu)`` as floats for a numeric nu in (1/4, 1/2]."""
    nv = _parse_nu(nu)
    if isinstance(nv, sp.Symbol):
        raise TypeError(f"a numeric Poisson ratio in (1/4, 1/2] is needed here (e.g. nu=0.49), got the symbol {nv}")
    c0, c1, th = _model_coefficients(nv)
    return float(nv), float(c0), float(c1), float(th / S.mu)


# =============================================================================================
# (I.3), (I.4), (I.10): the free-boundary problem
# =============================================================================================
@dataclass(frozen=True)
class ObstacleProblem:
    """The thin-layer free-boundary problem for one punch, (I.3)-(I.4) at ``nu = 1/2``, (I.10) below::

        -Delta p + k^2 p = f  in omega,   p = dp/dn = 0  on its contour,   p >= 0,
        f = vartheta (delta0 - Phi)/(c_1 H^3),   k^2 = c_0/(c_1 H^2),

    i.e. ``min int (|grad p|^2/2 + k^2 p^2/2 - f p) dx`` over ``p >= 0``.

    Attributes
    ----------
    punch, nu:
        The punch and Poisson's ratio (1/2, an exact or float value in (1/4, 1/2), or a Symbol).
    c0, c1, vartheta:
        ``c_0 = A``, ``c_1 = A m_1`` (``2/3`` at nu = 1/2) and ``vartheta = mu/(1 - nu)``.
    source, k2:
        ``f(x1, x2)`` and ``k^2`` (zero at nu = 1/2).
    """

    punch: Punch
    nu: Any
    c0: sp.Expr
    c1: sp.Expr
    vartheta: sp.Expr
    source: sp.Expr
    k2: sp.Expr

    @property
    def equation(self) -> str:
        return "I.3" if self.is_incompressible else "I.10"

    @property
    def is_incompressible(self) -> bool:
        return self.c0 == 0

    def residual(self, p: sp.Expr) -> sp.Expr:
        """``-Delta p + k^2 p - f`` for a candidate pressure ``p(x1, x2)`` (zero inside the contact)."""
        return -laplacian(p, S.x1, S.x2) + self.k2 * p - self.source

    def boundary_values(self, p: sp.Expr, x1: sp.Expr, x2: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """``(p, dp/dx1, dp/dx2)`` at a point -- all three vanish on the contour (I.4)."""
        at = {S.x1: x1, S.x2: x2}
        return p.subs(at), sp.diff(p, S.x1).subs(at), sp.diff(p, S.x2).subs(at)

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        base = (S.x1, S.x2, S.delta0, S.H, S.mu)
        rest = sorted((self.source.free_symbols | self.k2.free_symbols) - set(base), key=lambda q: q.name)
        return base + tuple(rest)

    def lambdify(self, args=None, backend: str = "numpy") -> Callable:
        """``(f, k^2)`` as one numeric function of :attr:`arguments` (x1, x2, delta0, H, mu, then the rest)."""
        return checked_lambdify(self.arguments if args is None else args, (self.source, self.k2), backend)

    def latex(self) -> str:
        lhs = r"-\Delta p" if self.is_incompressible else rf"-\Delta p + {sp.latex(self.k2)}\, p"
        tag = self.equation
        lines = [
            latex_equation(lhs, sp.latex(sp.factor(self.source)) + r",\quad \mathbf{x} \in \omega", tag),
            (r"p = \frac{\partial p}{\partial n} = 0 \ \text{on}\ \partial\omega,\quad p > 0 \ \text{in}\ \omega"
             r" \tag{I.4}"),
        ]
        if self.is_incompressible:
            lines.append(rf"\iint_\omega \left({sp.latex(S.delta0 - self.punch.expr)}\right) d\mathbf{{x}} = 0"
                         r" \tag{I.5}")
        return " \\\\\n".join(lines)


def obstacle_problem(punch: Punch, nu: Any = HALF) -> ObstacleProblem:
    """The free-boundary problem (I.3)-(I.4) (``nu = 1/2``) or the two-term problem (I.10) (``1/4 < nu < 1/2``).

    The source ``f = vartheta (delta0 - Phi)/(c_1 H^3)`` and ``k^2 = c_0/(c_1 H^2)`` come from the
    operator (I.2): ``c_1 = 2/3`` from (I.1) at ``nu = 1/2``, ``c_0 = A``, ``c_1 = A m_1`` from
    :func:`thinlayer.kernel_coefficients` otherwise.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> sp.factor(obstacle_problem(Punch.paraboloid()).source)
    3*mu*(2*R*delta_0 - x_1**2 - x_2**2)/(2*H**3*R)
    """
    if not isinstance(punch, Punch):
        raise TypeError(f"punch must be a thinlayer.Punch, got {type(punch).__name__}")
    nv = _parse_nu(nu)
    c0, c1, th = _model_coefficients(nv)
    f = th * (S.delta0 - punch.expr) / (c1 * S.H**3)
    k2 = c0 / (c1 * S.H**2)
    return ObstacleProblem(punch, nv, c0, c1, th, f, k2)


# =============================================================================================
# (I.6)-(I.8): the elliptic paraboloid
# =============================================================================================
@dataclass(frozen=True)
class EllipseValues:
    """Numbers of the incompressible elliptic-paraboloid solution (I.6)-(I.8)."""

    a: float
    b: float
    C: float
    force: float
    t: float

    @property
    def area(self) -> float:
        return math.pi * self.a * self.b


@dataclass(frozen=True)
class IncompressibleEllipse:
    """Closed-form solution of (I.3)-(I.4) for ``Phi = x1^2/(2 R1) + x2^2/(2 R2)`` (1.1).

    ``p = C (1 - x1^2/a^2 - x2^2/b^2)^2`` on the ellipse, zero outside.

    Attributes
    ----------
    R1, R2:
        Punch radii (symbols or numbers).
    aspect_equation:
        ``3 t^2 + (1 - r) t - 3 r`` (I.6) in ``t = a^2/b^2`` and ``r = R1/R2`` (the symbols
        ``t_sym``, ``r_sym`` of this module).
    t:
        Its positive root in terms of R1, R2.
    a2, b2, C, force:
        ``a^2``, ``b^2``, the amplitude C (I.7) and ``P`` (I.8), in delta0, H, mu, R1, R2.
    a2_t, b2_t, C_t, force_t:
        The same in terms of ``t`` (the compact forms (I.7), (I.8)).
    """

    R1: sp.Expr
    R2: sp.Expr
    aspect_equation: sp.Expr
    t: sp.Expr
    a2_t: sp.Expr
    b2_t: sp.Expr
    C_t: sp.Expr
    force_t: sp.Expr

    equation = "I.8"

    def _sub(self, e: sp.Expr) -> sp.Expr:
        return e.subs(t_sym, self.t)

    @property
    def a2(self) -> sp.Expr:
        return self._sub(self.a2_t)

    @property
    def b2(self) -> sp.Expr:
        return self._sub(self.b2_t)

    @property
    def C(self) -> sp.Expr:
        return self._sub(self.C_t)

    @property
    def force(self) -> sp.Expr:
        return self._sub(self.force_t)

    @property
    def pressure(self) -> sp.Expr:
        """``C (1 - x1^2/a^2 - x2^2/b^2)^2`` inside the ellipse (in t)."""
        return self.C_t * (1 - S.x1**2 / self.a2_t - S.x2**2 / self.b2_t) ** 2

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        base = (S.delta0, S.H, S.mu)
        rest = sorted((self.force.free_symbols | self.a2.free_symbols) - set(base), key=lambda q: q.name)
        return base + tuple(rest)

    def lambdify(self, args=None, backend: str = "numpy") -> Callable:
        """``(P, a, b, C)`` as one numeric function of :attr:`arguments` (delta0, H, mu, then R1, R2 if symbolic)."""
        exprs = (self.force, sp.sqrt(self.a2), sp.sqrt(self.b2), self.C)
        return checked_lambdify(self.arguments if args is None else args, exprs, backend)

    def evaluate(self, delta0: float, H: float, mu: float = 1.0, R1: float | None = None,
                 R2: float | None = None) -> EllipseValues:
        """Numbers of (I.6)-(I.8); R1, R2 are needed when the result is symbolic in them."""
        d0, HH, mm = (_pos(v, n) for v, n in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
        sub = {S.delta0: d0, S.H: HH, S.mu: mm}
        for sym, val, nm in ((self.R1, R1, "R1"), (self.R2, R2, "R2")):
            if isinstance(sym, sp.Symbol):
                if val is None:
                    raise ValueError(f"{nm} is symbolic in this result: pass {nm}=<positive number>")
                sub[sym] = _pos(val, nm)
        t = float(self.t.subs(sub))

        def num(e):
            return float(e.subs(t_sym, t).subs(sub))

        return EllipseValues(math.sqrt(num(self.a2_t)), math.sqrt(num(self.b2_t)), num(self.C_t),
                             num(self.force_t), t)

    def latex(self) -> str:
        return " \\\\\n".join([
            latex_equation(sp.latex(self.aspect_equation), "0", "I.6"),
            latex_equation("t", sp.latex(self.t), "I.6"),
            latex_equation("a^2", sp.latex(self.a2_t), "I.7"),
            latex_equation("b^2", sp.latex(self.b2_t), "I.7"),
            latex_equation("C", sp.latex(self.C_t), "I.7"),
            latex_equation("P", sp.latex(self.force_t), "I.8"),
        ])


def _pos(value: Any, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, sp.Number, mpmath.mpf)):
        raise TypeError(f"{name} must be a positive real number, got {value!r} ({type(value).__name__})")
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name} must be a finite positive number, got {value!r}")
    return v


@lru_cache(maxsize=1)
def _ellipse_generic() -> IncompressibleEllipse:
    """The derivation with generic radii R_1, R_2 (specialised afterwards by substitution)."""
    R1, R2 = sp.symbols("R_1 R_2", positive=True)
    punch = Punch.elliptic_paraboloid(R1, R2)
    f = obstacle_problem(punch, HALF).source
    C, al, be = sp.symbols("C alpha beta", positive=True)  # alpha = 1/a^2, beta = 1/b^2
    p = C * (1 - al * S.x1**2 - be * S.x2**2) ** 2
    res = sp.Poly(sp.expand(-laplacian(p, S.x1, S.x2) - f), S.x1, S.x2)
    if res.total_degree() > 2 or res.coeff_monomial(S.x1 * S.x2) != 0 or res.coeff_monomial(S.x1) != 0:
        raise ArithmeticError(f"unexpected residual structure {res}")
    e0, e1, e2 = (res.coeff_monomial(m) for m in (1, S.x1**2, S.x2**2))
    # each coefficient is linear in C: C from the constant term, then two conditions on alpha, beta
    Csol = sp.solve(e0, C)[0]
    g1 = sp.numer(sp.together(e1.subs(C, Csol)))
    g2 = sp.numer(sp.together(e2.subs(C, Csol)))
    # beta = t alpha; alpha from the x1^2 condition, then the x2^2 condition is a relation for t
    h1 = sp.factor(g1.subs(be, t_sym * al))
    h2 = sp.factor(g2.subs(be, t_sym * al))
    alpha_sols = [s_ for s_ in sp.solve(h1, al) if s_ != 0]
    if len(alpha_sols) != 1:
        raise ArithmeticError(f"expected one non-zero alpha from {h1}")
    alpha_t = sp.factor(alpha_sols[0])
    rel = sp.factor(sp.numer(sp.together(h2.subs(al, alpha_t))))
    quads = [f_ for f_, _ in sp.factor_list(rel)[1] if sp.degree(f_, t_sym) == 2]
    if len(quads) != 1:
        raise ArithmeticError(f"the aspect relation is not a single quadratic in t: {rel}")
    quad = sp.Poly(quads[0], t_sym)
    # normalised to leading coefficient 3, in r = R1/R2
    aspect = sp.expand(sp.cancel(3 * quad.as_expr() / quad.LC()).subs(R1, r_sym * R2))
    if aspect.has(R2):
        raise ArithmeticError(f"the aspect relation does not depend on R1/R2 only: {aspect}")
    roots = sp.solve(quad.as_expr(), t_sym)
    # product of the roots is -3r/3 = -r < 0: exactly one positive root; pick it at a probe point
    pos = [rt for rt in roots if sp.N(rt.subs({R1: 2, R2: 1})) > 0]
    if len(pos) != 1:
        raise ArithmeticError(f"expected exactly one positive root of {quad}, got {roots}")
    t_expr = sp.radsimp(pos[0])
    a2_t = sp.factor(1 / alpha_t)
    b2_t = sp.factor(a2_t / t_sym)
    C_t = sp.factor(Csol.subs({al: alpha_t, be: t_sym * alpha_t}))
    # force (1.8): x1 = a rho cos th, x2 = b rho sin th, dA = a b rho d rho d th
    rr, th = sp.symbols("rho theta", nonnegative=True)
    integrand = C_t * (1 - rr**2) ** 2 * sp.sqrt(a2_t) * sp.sqrt(b2_t) * rr
    force_t = sp.factor(sp.integrate(sp.integrate(integrand, (rr, 0, 1)), (th, 0, 2 * sp.pi)))
    return IncompressibleEllipse(R1, R2, aspect, t_expr, a2_t, b2_t, C_t, force_t)


@lru_cache(maxsize=16)
def _ellipse(R1: sp.Expr, R2: sp.Expr) -> IncompressibleEllipse:
    g = _ellipse_generic()
    sub = {g.R1: R1, g.R2: R2}
    t = sp.simplify(g.t.subs(sub))

    def s(e):
        return e.subs(sub)

    return IncompressibleEllipse(R1, R2, g.aspect_equation.subs(r_sym, R1 / R2) if not (
        isinstance(R1, sp.Symbol) and isinstance(R2, sp.Symbol) and R1 != R2) else g.aspect_equation,
        t, s(g.a2_t), s(g.b2_t), s(g.C_t), s(g.force_t))


def incompressible_ellipse(R1: Any = None, R2: Any = None) -> IncompressibleEllipse:
    """Closed-form incompressible solution for the elliptic paraboloid (1.1): (I.6)-(I.8).

    Derived from the ansatz ``p = C (1 - x1^2/a^2 - x2^2/b^2)^2`` (which satisfies (I.4)) by matching
    the coefficients of ``1, x1^2, x2^2`` in ``-Delta p = f`` (I.3), eliminating C and ``a`` and taking
    the positive root of the quadratic for ``t = a^2/b^2``.

    Parameters
    ----------
    R1, R2:
        Radii of curvature (positive numbers or symbols; default symbols ``R_1, R_2``).  Equal
        values give the sphere.

    Examples
    --------
    >>> R = sp.Symbol("R", positive=True)
    >>> e = incompressible_ellipse(R, R)
    >>> e.t, e.a2, e.force
    (1, 4*R*delta_0, 2*pi*R**2*delta_0**3*mu/H**3)
    """
    r1 = sp.Symbol("R_1", positive=True) if R1 is None else sp.sympify(R1)
    r2 = sp.Symbol("R_2", positive=True) if R2 is None else sp.sympify(R2)
    for nm, r in (("R1", r1), ("R2", r2)):
        if r.is_number and not r > 0:
            raise PunchError(f"{nm} must be positive, got {r}")
        if not r.is_number and not isinstance(r, sp.Symbol):
            raise PunchError(f"{nm} must be a positive number or a Symbol, got {r}")
    return _ellipse(r1, r2)


# =============================================================================================
# (I.9): axisymmetric punches
# =============================================================================================
@dataclass(frozen=True)
class RadialValues:
    """Numbers of the axisymmetric incompressible solution (I.9)."""

    radius: float
    force: float
    pressure: Callable = field(repr=False)


@dataclass(frozen=True)
class IncompressibleRadial:
    """Incompressible solution (I.3)-(I.4) for an axisymmetric punch, in quadratures (I.9).

    Attributes
    ----------
    punch:
        The punch (Phi depends on ``x1^2 + x2^2`` only).
    profile:
        ``Phi(r)``.
    radius_equation:
        ``G(c) = int_0^c (delta0 - Phi(r)) r dr`` -- the contact radius is its positive root.
    pressure_of_c:
        ``p(r)`` on ``0 <= r <= c`` in terms of ``c`` (a polynomial in r for a polynomial punch).
    force_of_c:
        ``P = 2 pi int_0^c p r dr`` in terms of ``c``.
    """

    punch: Punch
    profile: sp.Expr
    radius_equation: sp.Expr
    pressure_of_c: sp.Expr
    force_of_c: sp.Expr

    equation = "I.9"

    def latex(self) -> str:
        return " \\\\\n".join([
            latex_equation(sp.latex(self.radius_equation), "0", "I.9"),
            latex_equation("p(r)", sp.latex(sp.factor(self.pressure_of_c)), "I.9"),
            latex_equation("P", sp.latex(sp.factor(self.force_of_c)), "I.9"),
        ])

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        base = (c_sym, S.delta0, S.H, S.mu)
        rest = sorted(self.force_of_c.free_symbols - set(base) - {rho}, key=lambda q: q.name)
        return base + tuple(rest)

    def lambdify(self, args=None, backend: str = "numpy") -> Callable:
        """``(G(c), P(c))`` as a numeric function of :attr:`arguments` (c, delta0, H, mu, punch parameters)."""
        return checked_lambdify(self.arguments if args is None else args,
                                (self.radius_equation, self.force_of_c), backend)

    def evaluate(self, delta0: float, H: float, mu: float = 1.0, parameters: dict | None = None) -> RadialValues:
        """Radius (smallest positive root of ``G`` with ``p >= 0`` on ``[0, c]``), force and ``p(r)``."""
        d0, HH, mm = (_pos(v, n) for v, n in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
        by_name = {q.name: q for q in self.punch.parameters}
        sub = {S.delta0: d0, S.H: HH, S.mu: mm}
        for k, v in (parameters or {}).items():
            nm = k if isinstance(k, str) else getattr(k, "name", None)
            if nm not in by_name:
                raise ValueError(f"{k!r} is not a parameter of the punch; its parameters are "
                                 f"{', '.join(by_name) or 'none'}")
            sub[by_name[nm]] = v
        # G(c) = c^2 (delta0 - Phi(0))/2 + ...: divide out the double root c = 0
        G = sp.Poly(sp.quo(sp.expand(self.radius_equation.subs(sub)), c_sym**2, c_sym), c_sym)
        if G.free_symbols - {c_sym}:
            raise ValueError(f"the punch parameters {sorted(map(str, G.free_symbols - {c_sym}))} need values "
                             "(parameters={...})")
        roots = sorted(float(z.real) for z in np.roots([float(x) for x in G.all_coeffs()])
                       if abs(z.imag) < 1e-9 * max(1.0, abs(z)) and z.real > 0)
        pc = sp.lambdify((rho, c_sym), self.pressure_of_c.subs(sub), "numpy")
        for c in roots:
            rr = np.linspace(0, c, 401)
            if np.all(np.asarray(pc(rr, c) + 0 * rr) >= -1e-12 * abs(pc(0.0, c))):
                force = float(self.force_of_c.subs(sub).subs(c_sym, c))

                def pressure(r, _c=c, _f=pc):
                    r = np.abs(np.asarray(r, dtype=float))
                    return np.where(r < _c, _f(np.minimum(r, _c), _c) + 0 * r, 0.0)

                return RadialValues(c, force, pressure)
        raise ValueError("no contact radius with a non-negative pressure: is Phi increasing with Phi(0) < delta0?")


def incompressible_axisymmetric(punch: Punch) -> IncompressibleRadial:
    """The incompressible solution for an axisymmetric polynomial punch (I.9), by integrating (I.3) twice.

    ``-(1/r)(r p')' = f`` with ``p'(0)`` finite gives ``r p'(r) = -int_0^r f s ds``; ``p'(c) = 0``
    (I.4) is ``int_0^c f s ds = 0`` and ``p(c) = 0`` fixes ``p(r) = int_r^c (1/rho) int_0^rho f s ds d rho``.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> sol = incompressible_axisymmetric(Punch.paraboloid())
    >>> sp.solve(sol.radius_equation, c_sym)
    [2*sqrt(R)*sqrt(delta_0)]
    """
    if not isinstance(punch, Punch):
        raise TypeError(f"punch must be a thinlayer.Punch, got {type(punch).__name__}")
    ang = sp.expand(S.x1 * sp.diff(punch.expr, S.x2) - S.x2 * sp.diff(punch.expr, S.x1))
    if ang != 0:
        raise PunchError(f"the punch Phi = {punch.expr} is not axisymmetric (x1 dPhi/dx2 - x2 dPhi/dx1 = {ang}); "
                         "use solve_obstacle_grid for a general punch")
    prob = obstacle_problem(punch, HALF)
    s = sp.Symbol("s", nonnegative=True)
    prof = punch.expr.subs({S.x1: rho, S.x2: 0})
    f_s = prob.source.subs({S.x1: s, S.x2: 0})
    inner = sp.integrate(sp.expand(f_s * s), (s, 0, rho))  # int_0^r f s ds
    G = sp.expand(sp.integrate(sp.expand((S.delta0 - prof.subs(rho, s)) * s), (s, 0, c_sym)))
    q = sp.Symbol("q", positive=True)
    pr = sp.expand(sp.integrate(sp.expand(inner.subs(rho, q) / q), (q, rho, c_sym)))
    force = sp.expand(2 * sp.pi * sp.integrate(sp.expand(pr * rho), (rho, 0, c_sym)))
    return IncompressibleRadial(punch, prof, G, pr, force)


# =============================================================================================
# (I.12): edge correction
# =============================================================================================
def _mp(x: Any) -> mpmath.mpf:
    """An exact rational (sympy) or an mpmath number as an mpmath number at the working precision."""
    if isinstance(x, mpmath.mpf):
        return +x
    x = sp.Rational(x)
    return mpmath.mpf(int(x.p)) / int(x.q)


@lru_cache(maxsize=64)
def _edge_shift_cached(nu_key: str, dps: int) -> mpmath.mpf:
    with mpmath.workdps(dps + 30):
        if nu_key == "1/2":
            layer: LayerKernel = IncompressibleLayer()
            c = layer.taylor_coefficients(2)
        else:
            nv = sp.Rational(nu_key) if "/" in nu_key else mpmath.mpf(nu_key)
            layer = BondedLayer(nv, dps=dps + 30)
            co = layer.coefficients(2)
            c = [co.A * co.m[n] for n in range(3)]
        c0, c1, c2 = (_mp(x) for x in c)

        def f(t):
            return mpmath.log(layer.L_numeric(t, "mpmath", over_u=True) / (c0 + c1 * t * t)) / (t * t)

        # near 0, f = c2 t^2/(c0 + c1 t^2) + O(t^4) (F = c0 + c1 t^2 + c2 t^4 + ...): integrate that in closed
        # form on [0, t0]; beyond, f ~ -2 log(t)/t^2 at infinity
        t0 = mpmath.mpf("1e-6")
        head = c2 / c1 * (t0 - (mpmath.sqrt(c0 / c1) * mpmath.atan(t0 * mpmath.sqrt(c1 / c0)) if c0 else 0))
        val = head + mpmath.quad(f, [t0, mpmath.mpf(1) / 4, 1, 4, 16, 64, mpmath.inf])
        return -val / mpmath.pi


def two_term_edge_shift(nu: Any = HALF, dps: int = 20) -> mpmath.mpf:
    """Edge correction ``h(nu)`` (I.12): the true contact edge lies ``h H`` inside the model's edge.

    ``h(nu) = -(1/pi) int_0^oo log(F(t)/(c_0 + c_1 t^2)) t^{-2} dt`` with ``F = L(t)/t`` (2.3); at
    ``nu = 1/2`` (``c_0 = 0``) the edge of the incompressible model (I.3)-(I.4).

    Examples
    --------
    >>> round(float(two_term_edge_shift()), 6)
    1.459081
    """
    nv = _parse_nu(nu)
    if isinstance(nv, sp.Symbol):
        raise TypeError(f"two_term_edge_shift needs a numeric nu in (1/4, 1/2], got the symbol {nv}")
    if isinstance(dps, bool) or not isinstance(dps, int) or dps < 10:
        raise ValueError(f"dps must be an integer >= 10, got {dps!r}")
    key = "1/2" if nv == HALF else (str(nv) if isinstance(nv, sp.Rational) else repr(float(nv)))
    with mpmath.workdps(dps):
        return +_edge_shift_cached(key, dps)


# =============================================================================================
# the two-term model's edge layer in the compressible limit
# =============================================================================================
@dataclass(frozen=True)
class TwoTermEdgeLayer:
    """Edge layer of the two-term model (I.10) in the compressible limit (``k a >> 1``).

    In ``v = n/H`` (inward distance over H) and units of the outer slope ``g``:
    ``-m_1 q'' + q = v`` for ``v > v_0``, ``q(v_0) = q'(v_0) = 0``, ``q - v -> 0`` inside.

    Attributes
    ----------
    q:
        ``v + l e^{-(v + l)/l}``, ``l = sqrt(m_1)``.
    edge:
        ``v_0 = -sqrt(m_1)`` (the model's contact extends beyond the leading contour).
    force_defect:
        ``D = int (q - max(v, 0)) dv = m_1/2`` -- the same as the Wiener--Hopf boundary layer's
        (:func:`thinlayer.asymptotics.force_law.boundary_layer_force_defect`).
    """

    m1: sp.Symbol
    v: sp.Symbol
    q: sp.Expr
    edge: sp.Expr
    force_defect: sp.Expr

    equation = "I.10"

    def latex(self) -> str:
        return " \\\\\n".join([latex_equation("q(v)", sp.latex(self.q), "I.10"),
                                 latex_equation("v_0", sp.latex(self.edge), "I.10"),
                                 latex_equation(r"\int (q - \max(v, 0))\,dv", sp.latex(self.force_defect), "I.10")])

    def lambdify(self, backend: str = "numpy") -> Callable:
        """``q(v, m_1)`` (valid for ``v >= v_0``)."""
        return checked_lambdify([self.v, self.m1], self.q, backend)


@lru_cache(maxsize=1)
def two_term_edge_layer() -> TwoTermEdgeLayer:
    """Solve the two-term model's edge problem in the compressible limit (see :class:`TwoTermEdgeLayer`).

    Examples
    --------
    >>> two_term_edge_layer().force_defect
    m_1/2
    """
    m1 = sp.Symbol("m_1", positive=True)
    v, v0, B = sp.symbols("v v_0 B", real=True)
    ell = sp.sqrt(m1)
    # general solution with q - v -> 0 inside: particular v plus the decaying homogeneous solution
    q = v + B * sp.exp(-(v - v0) / ell)
    if sp.simplify(-m1 * sp.diff(q, v, 2) + q - v) != 0:
        raise ArithmeticError("the trial solution does not satisfy -m_1 q'' + q = v")
    sol = sp.solve([q.subs(v, v0), sp.diff(q, v).subs(v, v0)], [B, v0], dict=True)
    if len(sol) != 1:
        raise ArithmeticError(f"the edge conditions do not fix the edge: {sol}")
    qs = sp.simplify(q.subs(sol[0]))
    edge = sol[0][v0]
    D = sp.simplify(sp.integrate(qs, (v, edge, 0)) + sp.integrate(qs - v, (v, 0, sp.oo)))
    return TwoTermEdgeLayer(m1, v, qs, edge, D)


# =============================================================================================
# (I.11): the two-term sphere
# =============================================================================================
_SERIES_TERMS = 40
_SERIES_CUT = 2.0


@lru_cache(maxsize=1)
def _ratio_series() -> np.ndarray:
    """``q_j`` of ``x I_0(x)/I_1(x) = 2 sum_j q_j y^j``, ``y = x^2`` (exact division of the Bessel series)."""
    a = [Fraction(1, 4**j * math.factorial(j) ** 2) for j in range(_SERIES_TERMS)]
    b = [Fraction(1, 4**j * math.factorial(j) * math.factorial(j + 1)) for j in range(_SERIES_TERMS)]
    return np.array([float(x) for x in quotient_field(a, b, _SERIES_TERMS - 1)])


def _psi_chi(x: Any) -> tuple[np.ndarray, np.ndarray]:
    """``psi(x) = (x I0/I1 - 2)/x^2`` and ``chi(x) = (1/4 - psi)/x^2`` (I.11), stable for every x >= 0."""
    from scipy import special

    x = np.asarray(x, dtype=float)
    if np.any(x < 0) or not np.all(np.isfinite(x)):
        raise ValueError("x = k c must be finite and >= 0")
    q = _ratio_series()
    y = x * x
    small = x < _SERIES_CUT
    psi = np.empty_like(x)
    chi = np.empty_like(x)
    ys = y[small]
    psi[small] = 2 * np.polyval(q[1:][::-1], ys)
    chi[small] = -2 * np.polyval(q[2:][::-1], ys)
    xl = x[~small]
    ratio = xl * special.ive(0, xl) / special.ive(1, xl)
    psi[~small] = (ratio - 2) / (xl * xl)
    chi[~small] = (0.25 - psi[~small]) / (xl * xl)
    return psi, chi


@dataclass(frozen=True)
class SphereValues:
    """Numbers of a sphere model: contact radius (model edge and corrected by (I.12)) and force."""

    nu: float
    delta0: float
    R: float
    H: float
    mu: float
    radius: float
    radius_corrected: float
    force: float
    x: float

    @property
    def lambda2(self) -> float:
        """``(k c)^2 = (c/H)^2/m_1`` (I.13), zero at nu = 1/2."""
        return self.x**2


#: the decay rate k of the two-term model, ``k^2 = c_0/(c_1 H^2) = 1/(m_1 H^2)`` (I.10)
k_sym = sp.Symbol("k", positive=True)


@dataclass(frozen=True)
class TwoTermSphere:
    """The two-term model (I.10) for the sphere ``Phi = r^2/(2R)``, in parametric form in the radius c (I.11).

    Attributes
    ----------
    nu, c0, c1, vartheta:
        Poisson ratio and the model's coefficients (see :class:`ObstacleProblem`).
    k2:
        ``k^2 = c_0/(c_1 H^2)``; the expressions below keep the symbol ``k`` (``k_sym``), zero at nu = 1/2.
    pressure_of_c:
        ``p(r)`` for ``0 <= r <= c`` in terms of ``c`` (Bessel functions of ``k r``; a polynomial at nu = 1/2).
    delta0_of_c, force_of_c:
        ``delta0(c)`` and ``P(c)``, derived with sympy from the general regular radial solution and (I.4).
    """

    nu: Any
    c0: sp.Expr
    c1: sp.Expr
    vartheta: sp.Expr
    k2: sp.Expr
    pressure_of_c: sp.Expr
    delta0_of_c: sp.Expr
    force_of_c: sp.Expr

    equation = "I.11"
    R = sp.Symbol("R", positive=True)

    @property
    def is_incompressible(self) -> bool:
        return self.c0 == 0

    def _with_k(self, e: sp.Expr) -> sp.Expr:
        return e if self.is_incompressible else e.subs(k_sym, sp.sqrt(self.k2))

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        return (c_sym, self.R, S.H, S.mu) + ((S.nu,) if isinstance(self.nu, sp.Symbol) else ())

    def lambdify(self, args=None, backend: str = "numpy") -> Callable:
        """``(delta0(c), P(c))`` as a numeric function of :attr:`arguments` ``(c, R, H, mu)``.

        ``backend="numpy"`` (default arguments): the stable form (I.11) through ``psi`` and ``chi``,
        free of overflow and cancellation for every ``k c``; other backends (or explicit ``args``):
        sympy's lambdify of the derived Bessel expressions.
        """
        if args is None and backend == "numpy" and not isinstance(self.nu, sp.Symbol):
            c0, c1, th = float(self.c0), float(self.c1), float(self.vartheta / S.mu)

            def f(c, R, H, mu):
                c, R, H, mu = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (c, R, H, mu)))
                psi, chi = _psi_chi(np.sqrt(c0 / c1) * c / H)
                f2 = th * mu / (2 * R * c1 * H**3)
                return c * c * (1 - 2 * psi) / (2 * R), 2 * np.pi * f2 * c**6 * chi

            return f
        exprs = (self._with_k(self.delta0_of_c), self._with_k(self.force_of_c))
        return checked_lambdify(self.arguments if args is None else args, exprs, backend)

    def evaluate(self, delta0: float, R: float, H: float, mu: float = 1.0, edge_correction: bool = True
                 ) -> SphereValues:
        """Radius and force for a prescribed depth.

        Brent's method on ``delta0(c)``, bracketed by ``2 R delta0 <= c^2 <= 4 R delta0`` (``0 <= psi <= 1/4``);
        ``radius_corrected`` subtracts ``h(nu) H`` (I.12) unless ``edge_correction=False``.
        """
        from scipy import optimize

        if isinstance(self.nu, sp.Symbol):
            raise TypeError(f"evaluate needs a numeric nu, not the symbol {self.nu}: build two_term_sphere(0.49)")
        d0, RR, HH, mm = (_pos(v, n) for v, n in ((delta0, "delta0"), (R, "R"), (H, "H"), (mu, "mu")))
        f = self.lambdify()
        lo, hi = math.sqrt(2 * RR * d0), 2 * math.sqrt(RR * d0)

        def g(c: float) -> float:
            return float(f(c, RR, HH, mm)[0]) - d0

        c = hi if g(hi) <= 0 else optimize.brentq(g, lo, hi, xtol=1e-15 * hi, rtol=1e-15)
        P = float(f(c, RR, HH, mm)[1])
        h = float(two_term_edge_shift(self.nu, dps=15)) if edge_correction else 0.0
        x = math.sqrt(float(self.c0) / float(self.c1)) * c / HH
        return SphereValues(float(self.nu), d0, RR, HH, mm, c, c - h * HH, P, x)

    def latex(self) -> str:
        lines = [latex_equation(r"\delta_0", sp.latex(self.delta0_of_c), "I.11"),
                 latex_equation("P", sp.latex(self.force_of_c), "I.11")]
        if not self.is_incompressible:
            lines.append(latex_equation("k^2", sp.latex(self.k2), "I.10"))
            lines.append(latex_equation(r"\delta_0", r"\frac{c^2 (1 - 2\psi(kc))}{2R},\quad P = 2\pi f_2 c^6 \chi(kc),"
                                        r"\quad \psi(x) = \frac{x I_0(x)/I_1(x) - 2}{x^2},\quad "
                                        r"\chi(x) = \frac{1/4 - \psi(x)}{x^2}", "I.11"))
        return " \\\\\n".join(lines)


@lru_cache(maxsize=2)
def _sphere_generic(incompressible: bool) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Symbol]:
    """``(p(r), delta0(c), P(c), F)`` for ``-Delta p + k^2 p = F (delta0 - r^2/(2R))`` with (I.4) at r = c."""
    R = TwoTermSphere.R
    F = sp.Symbol("F", positive=True)
    f_r = F * (S.delta0 - rho**2 / (2 * R))
    B = sp.Symbol("B")
    k2 = 0 if incompressible else k_sym**2
    # a polynomial particular solution by undetermined coefficients ...
    coeffs = sp.symbols("alpha_0:3")
    trial = sp.Add(*[cf * rho ** (2 * j) for j, cf in enumerate(coeffs)])
    lap = sp.diff(trial, rho, 2) + sp.diff(trial, rho) / rho
    eqs = sp.Poly(sp.expand(-lap + k2 * trial - f_r), rho).all_coeffs()
    part = trial.subs(sp.solve(eqs, coeffs[1:] if incompressible else coeffs, dict=True)[0])
    # ... plus the regular homogeneous solution: a constant at k = 0, I_0(k r) otherwise
    if incompressible:
        p = part.subs(coeffs[0], B)
    else:
        p = part.subs(coeffs[2], 0) + B * sp.besseli(0, k_sym * rho)
    # (I.4) at r = c: p(c) = p'(c) = 0, linear in B and delta0
    sol = sp.solve([p.subs(rho, c_sym), sp.diff(p, rho).subs(rho, c_sym)], [B, S.delta0], dict=True)
    if len(sol) != 1:
        raise ArithmeticError(f"the edge conditions do not determine B and delta0: {sol}")
    d0c = sol[0][S.delta0]
    p_c = sp.expand(p.subs(B, sol[0][B]).subs(S.delta0, d0c))
    force = 2 * sp.pi * sp.integrate(sp.expand(p_c * rho), (rho, 0, c_sym))
    if incompressible:
        return sp.factor(p_c), sp.factor(d0c), sp.factor(force), F
    return p_c, sp.simplify(d0c), sp.simplify(force), F


@lru_cache(maxsize=32)
def _two_term_sphere(nv: sp.Basic) -> TwoTermSphere:
    prob = obstacle_problem(Punch.paraboloid(TwoTermSphere.R), nv)
    p_c, d0c, force, F = _sphere_generic(prob.is_incompressible)
    Fv = prob.vartheta / (prob.c1 * S.H**3)
    return TwoTermSphere(nv, prob.c0, prob.c1, prob.vartheta, prob.k2, p_c.subs(F, Fv), d0c, force.subs(F, Fv))


def two_term_sphere(nu: Any = HALF) -> TwoTermSphere:
    """The sphere in the two-term model (I.10)/(I.11): ``delta0(c)``, ``P(c)``, ``p(r)`` in closed form.

    At ``nu = 1/2`` this is the incompressible model (I.3) (``delta0 = c^2/(4R)``,
    ``P = 2 pi mu R^2 delta0^3/H^3``); for ``1/4 < nu < 1/2`` Bessel functions of ``k r``,
    ``k^2 = 1/(m_1 H^2)``.  :meth:`TwoTermSphere.evaluate` gives numbers for a prescribed depth.

    Examples
    --------
    >>> two_term_sphere().delta0_of_c
    c**2/(4*R)
    >>> v = two_term_sphere(0.45).evaluate(delta0=0.2, R=1000.0, H=1.0)
    >>> round(v.radius, 3), round(v.force, 1)
    (21.371, 1354.5)
    """
    return _two_term_sphere(_parse_nu(nu))


# =============================================================================================
# (I.13): which model where
# =============================================================================================
@dataclass(frozen=True)
class Regime:
    """Where the compressible expansion and the incompressible model hold (I.13).

    Attributes
    ----------
    nu, H_over_a:
        Poisson ratio and thickness over contact half-width.
    m1:
        ``m_1(nu)`` (2.20), ``~ 1/(3 (1 - 2 nu))`` near 1/2 (``inf`` at nu = 1/2).
    lambda2:
        ``(a/H)^2/m_1``, the ratio of the two terms of (I.10).
    compressible_correction:
        ``4 m_1 (H/a)^2 = 4/lambda^2``: size of the first correction of the compressible force law
        (the paraboloid's ``2 m_1 H^2/(R delta0)``); the expansion needs it small.
    incompressible_correction:
        ``(3/16) lambda^2``: the relative force change of the sphere caused by ``c_0 = A``, neglected by
        the incompressible model (from the series of (I.11) at ``x = 0``).
    model:
        ``"compressible"``, ``"incompressible"`` or ``"two-term"``: the simplest model whose neglected
        term is below ``tol``.
    """

    nu: float
    H_over_a: float
    tol: float
    m1: float
    lambda2: float
    compressible_correction: float
    incompressible_correction: float
    model: str

    equation = "I.13"

    def latex(self) -> str:
        return (rf"\lambda^2 = \frac{{(a/H)^2}}{{m_1}} = {self.lambda2:.4g},\quad "
                rf"4 m_1 (H/a)^2 = {self.compressible_correction:.3g},\quad "
                rf"\tfrac{{3}}{{16}}\lambda^2 = {self.incompressible_correction:.3g}"
                rf"\ \Rightarrow\ \text{{{self.model}}} \tag{{I.13}}")

    def lambdify(self, backend: str = "numpy") -> Callable:
        """``(lambda^2, 4/lambda^2, 3 lambda^2/16)`` as a numeric function of ``(nu, H_over_a)``."""
        m1 = BondedLayer().coefficients(1).m_expr(1)
        ha = sp.Symbol("H_over_a", positive=True)
        lam2 = 1 / (ha**2 * m1)
        return checked_lambdify([S.nu, ha], (lam2, 4 / lam2, sp.Rational(3, 16) * lam2), backend)


def regime(nu: Any, H_over_a: float, tol: float = 0.05) -> Regime:
    """Which thin-layer model to use at ``(nu, H/a)`` (I.13).

    The compressible expansion (2.26)-(2.31) is a series in ``m_1 (H/a)^2`` and needs
    ``lambda^2 = (a/H)^2/m_1 >> 1``, i.e. ``1 - 2 nu >> (H/a)^2/3`` near 1/2; the incompressible model
    (I.3) needs ``lambda^2 << 1``; the two-term model (I.10) holds for both (``nu > 1/4``).

    Parameters
    ----------
    nu:
        Poisson ratio, ``-1 < nu <= 1/2``.
    H_over_a:
        Thickness over contact half-width (> 0).
    tol:
        Accepted size of the neglected relative force term.

    Examples
    --------
    >>> [regime(nu, 0.05).model for nu in (0.3, 0.45, 0.49, 0.4999, 0.5)]
    ['compressible', 'compressible', 'two-term', 'incompressible', 'incompressible']
    """
    ha = _pos(H_over_a, "H_over_a")
    tl = _pos(tol, "tol")
    if isinstance(nu, bool) or not isinstance(nu, (numbers.Real, sp.Number, str)):
        raise TypeError(f"nu must be a number in (-1, 1/2], got {nu!r}")
    nv = float(sp.Rational(nu)) if isinstance(nu, str) else float(nu)
    if not -1 < nv <= 0.5:
        raise ValueError(f"nu={nu!r} is outside the admissible range -1 < nu <= 1/2")
    if nv == 0.5:
        m1 = math.inf
    else:
        m1 = float(BondedLayer(mpmath.mpf(nv), dps=20).m(1))
    if m1 <= 0:
        # nu <= 1/4: m_1 <= 0, the expansion parameter |m_1| (H/a)^2 stays small; no two-term model
        return Regime(nv, ha, tl, m1, math.inf, 4 * abs(m1) * ha**2, math.inf, "compressible")
    lam2 = 0.0 if math.isinf(m1) else 1.0 / (m1 * ha**2)
    comp = math.inf if lam2 == 0 else 4.0 / lam2
    inc = 3.0 * lam2 / 16.0
    model = "compressible" if comp <= tl else "incompressible" if inc <= tl else "two-term"
    return Regime(nv, ha, tl, m1, lam2, comp, inc, model)


# =============================================================================================
# numerics on a grid: (I.3)-(I.4) and (I.10) for any punch
# =============================================================================================
@dataclass(frozen=True)
class GridContact:
    """Grid solution of the obstacle problem (I.3)-(I.4) / (I.10).

    Attributes
    ----------
    nu, delta0, H, mu:
        Parameters.  ``k2`` is ``c_0/(c_1 H^2)`` (zero at nu = 1/2).
    x1, x2:
        Grid coordinates (1-D, read-only); ``pressure[i, j]`` is ``p(x1[i], x2[j])``.
    pressure, contact:
        Pressure and contact set ``p > 0`` (read-only arrays).
    force:
        ``P = sum p h1 h2`` (1.8).
    area:
        Number of contact nodes times ``h1 h2`` (first-order accurate).
    iterations:
        Active-set iterations on the finest grid.
    volume_residual:
        ``int_omega f / int_omega |f|`` -- zero for the exact solution at nu = 1/2 (I.5).
    """

    nu: float
    delta0: float
    H: float
    mu: float
    k2: float
    x1: np.ndarray = field(repr=False)
    x2: np.ndarray = field(repr=False)
    pressure: np.ndarray = field(repr=False)
    contact: np.ndarray = field(repr=False)
    force: float = 0.0
    area: float = 0.0
    iterations: int = 0
    volume_residual: float = 0.0

    equation = "I.3"

    @property
    def h(self) -> tuple[float, float]:
        return float(self.x1[1] - self.x1[0]), float(self.x2[1] - self.x2[0])

    def moments(self) -> tuple[float, float, float, float, float]:
        """``(x1c, x2c, <dx1^2>, <dx1 dx2>, <dx2^2>)``: pressure-weighted centroid and second moments.

        For ``p = C (1 - x1^2/a^2 - x2^2/b^2)^2``, ``<x1^2> = a^2/8`` and ``<x2^2> = b^2/8``.
        """
        X1, X2 = np.meshgrid(self.x1, self.x2, indexing="ij")
        w = self.pressure / self.pressure.sum()
        c1, c2 = float((w * X1).sum()), float((w * X2).sum())
        d1, d2 = X1 - c1, X2 - c2
        return c1, c2, float((w * d1 * d1).sum()), float((w * d1 * d2).sum()), float((w * d2 * d2).sum())

    def extent(self) -> tuple[float, float, float, float]:
        """``(x1 min, x1 max, x2 min, x2 max)`` of the contact nodes, widened by half a cell."""
        i, j = np.nonzero(self.contact)
        h1, h2 = self.h
        return (float(self.x1[i.min()] - h1 / 2), float(self.x1[i.max()] + h1 / 2),
                float(self.x2[j.min()] - h2 / 2), float(self.x2[j.max()] + h2 / 2))

    def pressure_at(self, x1: Any, x2: Any) -> np.ndarray:
        """Bilinear interpolation of the grid pressure (zero outside the grid)."""
        from scipy.interpolate import RegularGridInterpolator

        f = RegularGridInterpolator((self.x1, self.x2), self.pressure, bounds_error=False, fill_value=0.0)
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        return f(np.stack([x1.ravel(), x2.ravel()], axis=-1)).reshape(x1.shape)

    def lambdify(self) -> Callable:
        """The pressure as a numeric function ``p(x1, x2)`` (bilinear interpolation)."""
        return self.pressure_at

    def latex(self) -> str:
        h1, h2 = self.h
        return (rf"P = {self.force:.8g},\quad |\omega| = {self.area:.6g},\quad h = ({h1:.3g}, {h2:.3g}),\quad "
                rf"\nu = {self.nu:g},\quad \delta_0 = {self.delta0:g},\quad H = {self.H:g} \tag{{I.3}}")


def _numeric_phi(punch: Any, parameters: dict | None) -> Callable:
    if isinstance(punch, Punch):
        pn = punch.subs(parameters) if parameters else punch
        if pn.parameters:
            raise ValueError(f"the punch parameters {[q.name for q in pn.parameters]} need values (parameters=...)")
        f = sp.lambdify((S.x1, S.x2), pn.expr, "numpy")
        return lambda a, b: np.broadcast_to(np.asarray(f(a, b), dtype=float), np.broadcast(a, b).shape)
    if callable(punch):
        if parameters:
            raise ValueError("parameters= only applies to a Punch")
        return lambda a, b: np.broadcast_to(np.asarray(punch(a, b), dtype=float), np.broadcast(a, b).shape)
    raise TypeError(f"punch must be a thinlayer.Punch or a callable Phi(x1, x2), got {type(punch).__name__}")


def _default_box(phi: Callable, delta0: float) -> tuple[float, float, float, float]:
    """Twice the bounding box of ``{Phi < delta0}`` (found along 256 rays from the origin)."""
    if not phi(np.array(0.0), np.array(0.0)) < delta0:
        raise ValueError(f"Phi(0, 0) >= delta0 = {delta0}: the punch does not touch the layer at the origin; "
                         "give box=(x1min, x1max, x2min, x2max)")
    th = np.linspace(0, 2 * np.pi, 256, endpoint=False)
    c, s = np.cos(th), np.sin(th)
    hi = np.ones_like(th)
    for _ in range(200):
        grow = phi(hi * c, hi * s) < delta0
        if not grow.any():
            break
        hi = np.where(grow, hi * 2, hi)
    else:
        raise ValueError("Phi does not reach delta0 along some rays: the contact region is unbounded")
    lo = np.zeros_like(th)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        inside = phi(mid * c, mid * s) < delta0
        lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    x, y = hi * c, hi * s
    cx, cy = 0.5 * (x.max() + x.min()), 0.5 * (y.max() + y.min())
    wx, wy = x.max() - cx, y.max() - cy
    return cx - 2 * wx, cx + 2 * wx, cy - 2 * wy, cy + 2 * wy


def _pdas(A, b: np.ndarray, inactive: np.ndarray, maxit: int) -> tuple[np.ndarray, int]:
    """Primal-dual active set (semismooth Newton) for ``A p - b = lam >= 0, p >= 0, p lam = 0``."""
    from scipy.sparse.linalg import spsolve

    for it in range(1, maxit + 1):
        p = np.zeros_like(b)
        idx = np.nonzero(inactive)[0]
        if idx.size:
            p[idx] = spsolve(A[idx][:, idx].tocsc(), b[idx])
        lam = A @ p - b
        lam[idx] = 0.0
        new = ~((lam > 0) | (p < 0))  # active: lam - c p > 0 (p = 0 there, lam = 0 elsewhere)
        if np.array_equal(new, inactive):
            return np.maximum(p, 0.0), it
        inactive = new
    raise RuntimeError(f"the active-set iteration did not converge in {maxit} steps")


def _grid_solve(phi, d0, th, c0, c1, H, mu, box, n, maxit, coarsest=41):
    import scipy.sparse as sps

    x1 = np.linspace(box[0], box[1], n)
    x2 = np.linspace(box[2], box[3], n)
    h1, h2 = x1[1] - x1[0], x2[1] - x2[0]
    m = n - 2
    X1, X2 = np.meshgrid(x1[1:-1], x2[1:-1], indexing="ij")
    f = th * mu * (d0 - phi(X1, X2)) / (c1 * H**3)
    k2 = c0 / (c1 * H**2)
    T1 = sps.diags([-np.ones(m - 1), 2 * np.ones(m), -np.ones(m - 1)], [-1, 0, 1]) / h1**2
    T2 = sps.diags([-np.ones(m - 1), 2 * np.ones(m), -np.ones(m - 1)], [-1, 0, 1]) / h2**2
    I = sps.identity(m)
    A = (sps.kron(T1, I) + sps.kron(I, T2) + k2 * sps.identity(m * m)).tocsr()
    b = f.ravel()
    if (n - 1) % 2 == 0 and (n - 1) // 2 + 1 >= coarsest:
        # nested iteration: the coarse solution's support is the initial inactive set
        pc, *_ = _grid_solve(phi, d0, th, c0, c1, H, mu, box, (n - 1) // 2 + 1, maxit, coarsest)
        from scipy.interpolate import RegularGridInterpolator

        xc1, xc2 = np.linspace(box[0], box[1], (n - 1) // 2 + 1), np.linspace(box[2], box[3], (n - 1) // 2 + 1)
        pi = RegularGridInterpolator((xc1, xc2), pc)(np.stack([X1.ravel(), X2.ravel()], axis=-1))
        inactive = pi > 0
    else:
        inactive = b > 0
    p, its = _pdas(A, b, inactive, maxit)
    P = np.zeros((n, n))
    P[1:-1, 1:-1] = p.reshape(m, m)
    return P, x1, x2, f, its, k2


def solve_obstacle_grid(punch: Any, delta0: float, H: float, mu: float = 1.0, *, nu: Any = HALF,
                        n: int = 161, box: Any = None, parameters: dict | None = None,
                        maxit: int = 500) -> GridContact:
    """Solve the free-boundary problem (I.3)-(I.4) (or (I.10) for ``1/4 < nu < 1/2``) on a grid.

    The obstacle problem ``min sum (|grad_h p|^2/2 + k^2 p^2/2 - f p)`` over ``p >= 0`` with the
    5-point Laplacian on ``n x n`` nodes (``p = 0`` on the box boundary) is solved exactly by the
    primal-dual active-set method (each step a sparse LU solve, scipy.sparse), started from the
    interpolated solution on the grid with ``(n - 1)/2 + 1`` nodes (nested iteration).  The error
    is ``O(h^2)`` (measured in the tests).

    Parameters
    ----------
    punch:
        A :class:`~thinlayer.punch.Punch` (numeric, or with ``parameters``) or a callable
        ``Phi(x1, x2)`` (numpy-vectorised).
    delta0, H, mu:
        Indentation, thickness, shear modulus.
    nu:
        1/2 (default) for (I.3); ``1/4 < nu < 1/2`` for the two-term model (I.10).
    n:
        Nodes per side (odd, >= 21).
    box:
        ``(x1min, x1max, x2min, x2max)``; default twice the bounding box of ``{Phi < delta0}``.
    parameters:
        Values of the punch's parameters, e.g. ``{"R": 2.0}``.
    maxit:
        Maximum active-set iterations.

    Raises
    ------
    ValueError
        When the contact set reaches the box boundary (enlarge ``box``).
    """
    d0, HH, mm = (_pos(v, nm) for v, nm in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
    nv, c0, c1, th = _model_floats(nu)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 21 or n % 2 == 0:
        raise ValueError(f"n (nodes per side) must be an odd integer >= 21, got {n!r}")
    if isinstance(maxit, bool) or not isinstance(maxit, int) or maxit < 1:
        raise ValueError(f"maxit must be a positive integer, got {maxit!r}")
    phi = _numeric_phi(punch, parameters)
    if box is None:
        bx = _default_box(phi, d0)
    else:
        try:
            bx = tuple(float(v) for v in box)
        except (TypeError, ValueError) as exc:
            raise ValueError(f"box must be (x1min, x1max, x2min, x2max), got {box!r}") from exc
        if len(bx) != 4 or not (bx[0] < bx[1] and bx[2] < bx[3]) or not all(map(math.isfinite, bx)):
            raise ValueError(f"box must be (x1min, x1max, x2min, x2max) with min < max, got {box!r}")
    P, x1, x2, f, its, k2 = _grid_solve(phi, d0, th, c0, c1, HH, mm, bx, int(n), maxit)
    contact = P > 0
    if contact[:3, :].any() or contact[-3:, :].any() or contact[:, :3].any() or contact[:, -3:].any():
        raise ValueError(f"the contact region reaches the boundary of the box {bx}: pass a larger box=")
    if not contact.any():
        raise ValueError("no contact: the pressure vanishes on the grid (is delta0 > min Phi?)")
    h1, h2 = x1[1] - x1[0], x2[1] - x2[0]
    fin = f[contact[1:-1, 1:-1]]
    vol = float(fin.sum() / np.abs(fin).sum())
    for arr in (x1, x2, P, contact):
        arr.setflags(write=False)
    return GridContact(nv, d0, HH, mm, k2, x1, x2, P, contact, float(P.sum() * h1 * h2),
                       float(contact.sum() * h1 * h2), its, vol)


# =============================================================================================
# the sphere in every model, side by side
# =============================================================================================
@dataclass(frozen=True)
class SphereModels:
    """Force and contact radius of a sphere ``Phi = r^2/(2R)`` in each thin-layer model (and the direct solver).

    Attributes
    ----------
    compressible:
        ``(P, c)`` from :func:`thinlayer.solve` (force with first correction (2.31), area with (3.25));
        ``None`` at nu = 1/2 (``A = 0``).
    incompressible:
        ``(P, c)`` of (I.8) with nu = 1/2 constants, ``c = 2 sqrt(R delta0) - h(1/2) H`` (I.12).
    two_term:
        ``(P, c)`` of (I.11), ``c`` corrected by (I.12).
    direct:
        ``(P, c)`` of :func:`thinlayer.numerics.direct.solve_axisymmetric`, or ``None``.
    regime:
        :func:`regime` at ``H/a`` with ``a`` the two-term radius.
    """

    nu: float
    R: float
    delta0: float
    H: float
    mu: float
    compressible: tuple | None
    incompressible: tuple
    two_term: tuple
    direct: tuple | None
    regime: Regime

    def errors(self) -> dict[str, tuple[float, float]]:
        """Relative errors ``(P/P_direct - 1, c/c_direct - 1)`` of each model (needs ``direct``)."""
        if self.direct is None:
            raise ValueError("no direct solution: call compare_sphere_models(..., direct=True)")
        out = {}
        for name in ("compressible", "incompressible", "two_term"):
            v = getattr(self, name)
            if v is not None:
                out[name] = (v[0] / self.direct[0] - 1.0, v[1] / self.direct[1] - 1.0)
        return out

    def latex(self) -> str:
        rows = []
        for name in ("compressible", "incompressible", "two_term", "direct"):
            v = getattr(self, name)
            if v is not None:
                rows.append(rf"\text{{{name.replace('_', '-')}}} & {v[0]:.6g} & {v[1]:.6g}")
        return (r"\begin{array}{lrr} \text{model} & P & c \\ " + r" \\ ".join(rows)
                + rf"\end{{array}}\quad \nu = {self.nu:g},\ \lambda^2 = {self.regime.lambda2:.3g}")

    def lambdify(self) -> Callable:
        """``model name -> (P, c)`` as a function (the numbers of this comparison)."""
        table = {n: getattr(self, n) for n in ("compressible", "incompressible", "two_term", "direct")}
        return lambda name: table[name]


def compare_sphere_models(nu: Any, R: float, delta0: float, H: float, mu: float = 1.0,
                          direct: bool = False) -> SphereModels:
    """Sphere in the compressible, incompressible and two-term models, optionally against the direct solver.

    Parameters
    ----------
    nu:
        Poisson ratio in (1/4, 1/2].
    R, delta0, H, mu:
        Sphere radius, indentation, thickness, shear modulus.
    direct:
        Also run :func:`thinlayer.numerics.direct.solve_axisymmetric` (``BondedLayer(nu)``, or
        :class:`IncompressibleLayer` at 1/2).
    """
    nv = _model_floats(nu)[0]
    RR, d0, HH, mm = (_pos(v, n) for v, n in ((R, "R"), (delta0, "delta0"), (H, "H"), (mu, "mu")))
    two = two_term_sphere(nv if nv != 0.5 else HALF).evaluate(d0, RR, HH, mm)
    inc = incompressible_ellipse(sp.Symbol("R", positive=True), sp.Symbol("R", positive=True))
    inc_v = inc.evaluate(d0, HH, mm, R1=RR, R2=RR)
    h_half = float(two_term_edge_shift(HALF, dps=15))
    incompressible = (inc_v.force, inc_v.a - h_half * HH)
    comp = None
    if nv < 0.5:
        from .solution import solve

        sol = solve(BondedLayer(nv), Punch.paraboloid(RR), d0, HH, mm)
        comp = (float(sol.force), math.sqrt(float(sol.contact_area) / math.pi))
    dres = None
    if direct:
        from ..numerics.direct import solve_axisymmetric

        layer = IncompressibleLayer() if nv == 0.5 else BondedLayer(nv)
        res = solve_axisymmetric(layer, lambda r: r * r / (2 * RR), d0, HH, mm)
        dres = (float(res.force), float(res.radius))
    return SphereModels(nv, RR, d0, HH, mm, comp, incompressible, (two.force, two.radius_corrected), dres,
                        regime(nv, HH / two.radius))

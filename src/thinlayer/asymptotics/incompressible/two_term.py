r"""Nearly incompressible layers: the two-term model (I.10)-(I.12).

The sphere in the two-term model (I.11) (:func:`two_term_sphere`), the edge correction (I.12)
(:func:`two_term_edge_shift`) and the model's edge layer in the compressible limit
(:func:`two_term_edge_layer`).  Each model function takes the layer first:
``BondedLayer(nu)`` with ``1/4 < nu < 1/2`` or ``IncompressibleLayer()`` (the default).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ... import symbols as S
from ..._cache import cached
from ..._checks import InputError, InputTypeError, positive
from ..._series import quotient_field
from ...display import RichDisplay, fmt
from ...errors import boundary, boundary_methods
from ...layers.kernels import BondedLayer, IncompressibleLayer, LayerKernel
from ...normal import normal_latex
from ...punch import Punch
from ...results import checked_lambdify, latex_equation
from .leading import c_sym, rho, rho_out
from .operator import HALF, model_layer, obstacle_problem

__all__ = [
    "SphereValues",
    "TwoTermEdgeLayer",
    "TwoTermSphere",
    "two_term_edge_layer",
    "two_term_edge_shift",
    "two_term_sphere",
]


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
    # h(nu) (I.12) is kept on disk per nu and precision (thinlayer._cache): a quadrature of seconds
    return cached("two_term_edge_shift", (nu_key, dps), lambda: _edge_shift_computed(nu_key, dps))


def _edge_shift_computed(nu_key: str, dps: int) -> mpmath.mpf:
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


@lru_cache(maxsize=64)
def _edge_shift_float(layer: LayerKernel) -> float:
    """``h(nu)`` (I.12) as a float, kept per layer for repeated evaluations."""
    return float(two_term_edge_shift(layer, dps=15))


def two_term_edge_shift(layer: LayerKernel | None = None, dps: int = 20) -> mpmath.mpf:
    """Edge correction ``h(nu)`` (I.12): the true contact edge lies ``h H`` inside the model's edge.

    ``h(nu) = -(1/pi) int_0^oo log(F(t)/(c_0 + c_1 t^2)) t^{-2} dt`` with ``F = L(t)/t`` (2.3); at
    ``nu = 1/2`` (``c_0 = 0``) the edge of the incompressible model (I.3)-(I.4).

    Parameters
    ----------
    layer : LayerKernel, optional
        ``IncompressibleLayer()`` (default, ``h(1/2)``) or ``BondedLayer(nu)`` with a numeric
        ``1/4 < nu < 1/2``.  A bare Poisson ratio still works, with a DeprecationWarning.
    dps : int
        Decimal digits of the result (>= 10).

    Returns
    -------
    mpmath.mpf

    Examples
    --------
    >>> round(float(two_term_edge_shift()), 6)
    1.459081
    """
    layer, nv = model_layer(layer, "two_term_edge_shift({layer})", numeric=True)
    if isinstance(dps, bool) or not isinstance(dps, int) or dps < 10:
        raise InputError(f"dps must be an integer >= 10, got {dps!r}")
    key = "1/2" if nv == HALF else (str(nv) if isinstance(nv, sp.Rational) else repr(float(nv)))
    with mpmath.workdps(dps):
        return +_edge_shift_cached(key, dps)


# =============================================================================================
# the two-term model's edge layer in the compressible limit
# =============================================================================================
@dataclass(frozen=True)
class TwoTermEdgeLayer(RichDisplay):
    """Edge layer of the two-term model (I.10) in the compressible limit (``k a >> 1``).

    In ``v = n/H`` (inward distance over H) and units of the outer slope ``g``:
    ``-m_1 q'' + q = v`` for ``v > v_0``, ``q(v_0) = q'(v_0) = 0``, ``q - v -> 0`` inside.

    Attributes
    ----------
    q : sympy.Expr
        ``v + l e^{-(v + l)/l}``, ``l = sqrt(m_1)``.
    edge : sympy.Expr
        ``v_0 = -sqrt(m_1)`` (the model's contact extends beyond the leading contour).
    force_defect : sympy.Expr
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
        return " \\\\\n".join([latex_equation("q(v)", normal_latex(self.q), "I.10"),
                                 latex_equation("v_0", normal_latex(self.edge), "I.10"),
                                 latex_equation(r"\int (q - \max(v, 0))\,dv", normal_latex(self.force_defect), "I.10")])

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return ["TwoTermEdgeLayer: -m₁ q'' + q = v for v > v₀, q(v₀) = q'(v₀) = 0   (I.10)",
                f"  q(v) = {fmt(self.q)}",
                f"  v₀   = {fmt(self.edge)}",
                f"  ∫ (q - max(v, 0)) dv = {fmt(self.force_defect)}"]

    def lambdify(self, backend: str = "numpy") -> Callable:
        """``q(v, m_1)`` (valid for ``v >= v_0``)."""
        return checked_lambdify([self.v, self.m1], self.q, backend)


@lru_cache(maxsize=1)
def two_term_edge_layer() -> TwoTermEdgeLayer:
    """Solve the two-term model's edge problem in the compressible limit (I.10) (see :class:`TwoTermEdgeLayer`).

    Returns
    -------
    TwoTermEdgeLayer

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
        raise InputError("x = k c must be finite and >= 0")
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


def _psi_chi_scalar(x: float) -> tuple[float, float]:
    """:func:`_psi_chi` for one float, without array overhead (the same Horner sums, term by term)."""
    if not (x >= 0 and math.isfinite(x)):
        raise InputError("x = k c must be finite and >= 0")
    if x < _SERIES_CUT:
        q = _ratio_series_list()
        y = x * x
        psi = 0.0
        for coef in q[:0:-1]:  # np.polyval(q[1:][::-1], y): Horner from the highest power
            psi = psi * y + coef
        chi = 0.0
        for coef in q[:1:-1]:
            chi = chi * y + coef
        return 2 * psi, -2 * chi
    from scipy import special

    ratio = x * float(special.ive(0, x)) / float(special.ive(1, x))
    psi = (ratio - 2) / (x * x)
    return psi, (0.25 - psi) / (x * x)


@lru_cache(maxsize=1)
def _ratio_series_list() -> list:
    return [float(v) for v in _ratio_series()]


@boundary_methods
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


@boundary_methods
@dataclass(frozen=True)
class TwoTermSphere(RichDisplay):
    """The two-term model (I.10) for the sphere ``Phi = r^2/(2R)``, in parametric form in the radius c (I.11).

    Attributes
    ----------
    layer : LayerKernel
        ``IncompressibleLayer()`` or ``BondedLayer(nu)``.
    nu, c0, c1, vartheta
        Poisson ratio and the model's coefficients (see :class:`ObstacleProblem`).
    k2 : sympy.Expr
        ``k^2 = c_0/(c_1 H^2)``; the expressions below keep the symbol ``k`` (``k_sym``), zero at nu = 1/2.
    pressure_of_c : sympy.Expr
        ``p(r)`` for ``0 <= r <= c`` in terms of ``c`` (Bessel functions of ``k r``; a polynomial at nu = 1/2).
    delta0_of_c, force_of_c : sympy.Expr
        ``delta0(c)`` and ``P(c)``, derived with sympy from the general regular radial solution and (I.4).
    """

    layer: LayerKernel
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

    codegen_name = "two_term_sphere"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``(arguments, outputs)`` for code generation, in terms of the contact radius ``c`` (I.11):
        ``delta0`` ``delta0(c)``, ``force`` ``P(c)`` and ``pressure`` ``p(r)`` (zero for ``r >= c``).

        At nu = 1/2 the outputs are polynomials; for nu < 1/2 they hold the modified Bessel functions
        ``I_0, I_1`` of ``k r`` (languages without them refuse with ``NotImplementedError``).
        """
        outs = {"delta0": self._with_k(self.delta0_of_c), "force": self._with_k(self.force_of_c),
                "pressure": sp.Piecewise((self._with_k(self.pressure_of_c), rho < c_sym), (0, True)).subs(rho, rho_out)}
        return (rho_out,) + self.arguments, outs

    def evaluate(self, delta0: float, R: float, H: float, mu: float = 1.0, edge_correction: bool = True
                 ) -> SphereValues:
        """Radius and force for a prescribed depth.

        Brent's method on ``delta0(c)``, bracketed by ``2 R delta0 <= c^2 <= 4 R delta0`` (``0 <= psi <= 1/4``);
        ``radius_corrected`` subtracts ``h(nu) H`` (I.12) unless ``edge_correction=False``.
        """
        from scipy import optimize

        if isinstance(self.nu, sp.Symbol):
            raise InputTypeError(f"evaluate needs a numeric nu, not the symbol {self.nu}: "
                            "build two_term_sphere(BondedLayer(0.49))")
        d0, RR, HH, mm = (positive(v, n) for v, n in ((delta0, "delta0"), (R, "R"), (H, "H"), (mu, "mu")))
        c0, c1, th = float(self.c0), float(self.c1), float(self.vartheta / S.mu)
        k = math.sqrt(c0 / c1)  # x = k c/H, rounded as lambdify() forms it: the same numbers to the last bit
        lo, hi = math.sqrt(2 * RR * d0), 2 * math.sqrt(RR * d0)

        def g(c: float) -> float:  # delta0(c) - delta0 of (I.11), the scalar form of lambdify()
            return c * c * (1 - 2 * _psi_chi_scalar(k * c / HH)[0]) / (2 * RR) - d0

        c = hi if g(hi) <= 0 else optimize.brentq(g, lo, hi, xtol=1e-15 * hi, rtol=1e-15)
        # numpy's powers (as lambdify(): the same rounding; inf past the double range, never OverflowError)
        P = float(2 * math.pi * (th * mm / (2 * RR * c1 * np.power(HH, 3))) * np.power(c, 6)
                  * _psi_chi_scalar(k * c / HH)[1])
        h = _edge_shift_float(self.layer) if edge_correction else 0.0
        x = math.sqrt(float(self.c0) / float(self.c1)) * c / HH
        return SphereValues(float(self.nu), d0, RR, HH, mm, c, c - h * HH, P, x)

    def latex(self) -> str:
        lines = [latex_equation(r"\delta_0", normal_latex(self.delta0_of_c), "I.11"),
                 latex_equation("P", normal_latex(self.force_of_c), "I.11")]
        if not self.is_incompressible:
            lines.append(latex_equation("k^2", normal_latex(self.k2), "I.10"))
            lines.append(latex_equation(r"\delta_0", r"\frac{c^2 (1 - 2\psi(kc))}{2R},\quad P = 2\pi f_2 c^6 \chi(kc),"
                                        r"\quad \psi(x) = \frac{x I_0(x)/I_1(x) - 2}{x^2},\quad "
                                        r"\chi(x) = \frac{1/4 - \psi(x)}{x^2}", "I.11"))
        return " \\\\\n".join(lines)

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``: (I.11) in the contact radius c."""
        out = [f"TwoTermSphere: sphere Φ = r²/(2R) on {self.layer}, in the contact radius c   (I.10)-(I.11)",
               f"  δ₀ = {fmt(self.delta0_of_c)}",
               f"  P  = {fmt(self.force_of_c)}"]
        if not self.is_incompressible:
            out.append(f"  k² = {fmt(self.k2)}")
        return out


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
def _two_term_sphere(layer: LayerKernel) -> TwoTermSphere:
    prob = obstacle_problem(layer, Punch.paraboloid(TwoTermSphere.R))
    p_c, d0c, force, F = _sphere_generic(prob.is_incompressible)
    Fv = prob.vartheta / (prob.c1 * S.H**3)
    return TwoTermSphere(layer, prob.nu, prob.c0, prob.c1, prob.vartheta, prob.k2, p_c.subs(F, Fv), d0c,
                         force.subs(F, Fv))


@boundary
def two_term_sphere(layer: LayerKernel | None = None) -> TwoTermSphere:
    """The sphere in the two-term model (I.10)/(I.11): ``delta0(c)``, ``P(c)``, ``p(r)`` in closed form.

    At ``nu = 1/2`` this is the incompressible model (I.3) (``delta0 = c^2/(4R)``,
    ``P = 2 pi mu R^2 delta0^3/H^3``); for ``1/4 < nu < 1/2`` Bessel functions of ``k r``,
    ``k^2 = 1/(m_1 H^2)``.  :meth:`TwoTermSphere.evaluate` gives numbers for a prescribed depth.

    Parameters
    ----------
    layer : LayerKernel, optional
        ``IncompressibleLayer()`` (default), ``BondedLayer(nu)`` with ``1/4 < nu < 1/2``, or
        ``BondedLayer()`` (symbolic nu).  A bare Poisson ratio still works, with a DeprecationWarning.

    Returns
    -------
    TwoTermSphere

    Examples
    --------
    >>> two_term_sphere().delta0_of_c
    c**2/(4*R)
    >>> v = two_term_sphere(BondedLayer(0.45)).evaluate(delta0=0.2, R=1000.0, H=1.0)
    >>> round(v.radius, 3), round(v.force, 1)
    (21.371, 1354.5)
    """
    layer, _ = model_layer(layer, "two_term_sphere({layer})")
    return _two_term_sphere(layer)

r"""The incompressible model (I.3)-(I.4) for a tip of revolution that is not a polynomial (issue 24): cone, exact
sphere, blunted cone, power law, any profile ``Phi(r)``.

(I.9) integrates the radial form of (I.3), ``-(H^3/(3 mu)) (1/r)(r p')' = delta0 - Phi(r)``, twice.  With the
profile's moment ``M(r) = int_0^r Phi(s) s ds`` and ``F(r) = delta0 r^2/2 - M(r)``:

    r p'(r) = -(3 mu/H^3) F(r),        F(c) = 0   (p'(c) = 0, (I.4)),                                 (I.9a)
    p(r) = (3 mu/H^3) int_r^c F(q)/q dq,                                                               (I.9b)
    P = 2 pi int_0^c p r dr = pi (3 mu/H^3) int_0^c r F(r) dr = (3 pi mu/(2 H^3)) int_0^c r^3 (Phi - delta0) dr,  (I.9c)

the last form by parts (``F(c) = 0``, ``F' = (delta0 - Phi) r``).  Nothing here needs ``Phi`` to be a polynomial,
smooth or even differentiable: (I.9a)-(I.9c) only integrate it, so the cone's apex and the blunted cone's join enter
through ``M`` alone.  For the cone (``Phi = r cot(alpha)``): ``c = 3 delta0 tan(alpha)/2`` and

    P = 243 pi mu tan^4(alpha) delta0^5/(640 H^3);

for the power law ``C r^n``: ``c^n = (n + 2) delta0/(2 C)`` and ``P = 3 pi mu n delta0 c^4/(8 (n + 4) H^3)``.

Error: the model neglects the edge layer (I.12) of width ``H`` as for polynomial punches, an ``O(h H/c)`` change of
the force; the next inner term is ``p_2 ~ H^2 Laplacian(delta0 - Phi)``, integrable for every tip here
(``Laplacian Phi ~ cot(alpha)/r`` at a cone's apex), so it is ``O((H/c)^2)``.  The estimate ``2 h H/c`` of
:mod:`thinlayer.contact.models.two_term` covers both; the acceptance tests check it against the direct solver.
"""
from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import sympy as sp

from ... import symbols as S
from ..._checks import InputError, InputTypeError, positive
from ...display import RichDisplay, fmt
from ...normal import normal_latex
from ...parse import RADIUS as r_sym
from ...punch import Tip, is_polynomial_tip
from ...results import latex_equation
from .leading import c_sym

__all__ = ["IncompressibleTip", "TipValues", "incompressible_tip"]

#: points of the pressure table on [0, c] (cumulative trapezoid on a grid refined at the apex and the joins)
_GRID = 4001


@dataclass(frozen=True)
class TipValues:
    """Numbers of (I.9a)-(I.9c) at one depth: contact radius ``radius``, force ``force`` and ``pressure(r)``."""

    radius: float
    force: float
    pressure: Callable = field(repr=False)


def _cap(expr: sp.Expr) -> sp.Expr:
    """The profile where the tip exists: the first piece of a ``Piecewise(..., (oo, True))`` (the exact sphere)."""
    if isinstance(expr, sp.Piecewise) and expr.args[-1].expr == sp.oo and len(expr.args) == 2:
        return expr.args[0].expr
    return expr


@dataclass(frozen=True)
class IncompressibleTip(RichDisplay):
    """(I.9a)-(I.9c) for a tip of revolution (module docstring).

    Attributes
    ----------
    tip : Tip
        An axisymmetric tip (``radial_profile``).
    moment : sympy.Expr or None
        ``M(r) = int_0^r Phi s ds`` in closed form (None when sympy gives none: then by quadrature).
    radius_equation : sympy.Expr or None
        ``F(c) = delta0 c^2/2 - M(c)``: the contact radius is its root beyond the overlap radius.
    radius : sympy.Expr or None
        ``c(delta0)`` in closed form where (I.9a) solves explicitly (cone, power law).
    force : sympy.Expr or None
        ``P(delta0, H, mu)`` in closed form where ``radius`` exists.
    """

    tip: Tip

    @cached_property
    def _forms(self) -> tuple[sp.Expr | None, sp.Expr | None, sp.Expr | None, sp.Expr | None]:
        try:
            return _closed_forms(self.tip)
        except (NotImplementedError, ValueError, TypeError):  # sympy gives up: the numbers are by quadrature
            return None, None, None, None

    @property
    def moment(self) -> sp.Expr | None:
        return self._forms[0]

    @property
    def radius_equation(self) -> sp.Expr | None:
        return self._forms[1]

    @property
    def radius(self) -> sp.Expr | None:
        return self._forms[2]

    @property
    def force(self) -> sp.Expr | None:
        return self._forms[3]

    equation = "I.9"

    def latex(self) -> str:
        lines = []
        if self.radius_equation is not None:
            lines.append(latex_equation(normal_latex(self.radius_equation), "0", "I.9a"))
        if self.radius is not None:
            lines.append(latex_equation("c", normal_latex(self.radius), "I.9a"))
        if self.force is not None:
            lines.append(latex_equation("P", normal_latex(self.force), "I.9c"))
        else:
            lines.append(latex_equation("P", r"\frac{3 \pi \mu}{2 H^{3}} \int_{0}^{c} r^{3} "
                                             r"\left(\Phi(r) - \delta_{0}\right) dr", "I.9c"))
        return " \\\\\n".join(lines)

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        out = [f"IncompressibleTip: {self.tip.name}, ν = 1/2   (I.9a)-(I.9c)"]
        if self.radius_equation is not None:
            out.append(f"  {fmt(self.radius_equation)} = 0")
        if self.radius is not None:
            out.append(f"  c = {fmt(self.radius)}")
        out.append(f"  P = {fmt(self.force)}" if self.force is not None
                   else "  P = (3πμ/(2H³)) ∫₀ᶜ r³ (Φ(r) − δ₀) dr   (quadrature)")
        return out

    def evaluate(self, delta0: float, H: float, mu: float = 1.0) -> TipValues:
        """Contact radius (root of (I.9a) beyond the overlap radius), force (I.9c) and pressure (I.9b), in floats."""
        from scipy import integrate, optimize  # lazy: the asymptotic stages load no scipy at import

        d0, HH, mm = (positive(v, n) for v, n in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
        tip = self.tip
        a = tip.level_set(d0).radius
        joins = [b for b in tip.radial_breakpoints if 0 < b]
        rim = tip.support_radius

        def phi(x):
            return float(tip.radial_profile(np.array([x]))[0])

        def quad(f, lo, hi):
            pts = [b for b in joins if lo < b < hi] or None
            with warnings.catch_warnings():  # the join's kink: quad reaches ~1e-14, below its 1e-12 goal it warns
                warnings.simplefilter("ignore", integrate.IntegrationWarning)
                return integrate.quad(f, lo, hi, points=pts, limit=200, epsabs=0.0, epsrel=1e-12)[0]

        def F(c):  # delta0 c^2/2 - M(c)
            return quad(lambda s: (d0 - phi(s)) * s, 0.0, c)

        hi = 1.5 * a
        while F(hi) > 0:
            hi *= 1.5
            if hi >= rim or hi > 1e6 * a:
                raise InputError(f"the incompressible contact of the {tip.name} at delta0 = {d0:g} reaches its rim "
                                 f"(r = {rim:g}): (I.9a) has no root on the tip")
        c = optimize.brentq(F, a, hi, xtol=1e-15 * a, rtol=1e-15, maxiter=200)
        k = 3.0 * mm / HH**3
        force = 0.5 * math.pi * k * quad(lambda s: s**3 * (phi(s) - d0), 0.0, c)
        # (I.9b) on a grid: F by cumulative trapezoid of (delta0 - Phi) s, then int_r^c F/q dq
        u = np.linspace(0.0, 1.0, _GRID)
        q = c * u * u * (3 - 2 * u)  # clustered at 0 and c
        Fq = integrate.cumulative_trapezoid((d0 - tip.radial_profile(q)) * q, q, initial=0.0)
        g = np.where(q > 0, Fq / np.where(q > 0, q, 1.0), 0.0)
        tail = integrate.cumulative_trapezoid(g[::-1], q[::-1], initial=0.0)[::-1]  # int_c^r, i.e. -int_r^c
        table = -k * tail

        def pressure(rr, _c=c, _q=q, _t=table):
            rr = np.abs(np.asarray(rr, dtype=float))
            return np.where(rr < _c, np.interp(np.minimum(rr, _c), _q, _t), 0.0)

        return TipValues(c, force, pressure)


def _closed_forms(tip: Tip) -> tuple[sp.Expr | None, sp.Expr | None, sp.Expr | None, sp.Expr | None]:
    """``M(r)``, ``F(c)``, ``c(delta0)`` and ``P`` by sympy where it integrates the profile without Piecewise."""
    prof = _cap(tip.radial_expr)
    if prof.has(sp.Piecewise):  # a join (blunted cone): by quadrature
        return None, None, None, None
    s = sp.Symbol("s", positive=True)
    M = sp.integrate(sp.expand(prof.xreplace({r_sym: s}) * s), (s, 0, r_sym))
    if M.has(sp.Integral, sp.Piecewise):
        return None, None, None, None
    M = sp.simplify(M)
    F = S.delta0 * c_sym**2 / 2 - M.xreplace({r_sym: c_sym})
    if any(w.base != c_sym and w.base.has(c_sym) for w in F.atoms(sp.Pow)):  # sqrt(R^2 - c^2): no explicit root
        return M, F, None, None
    roots = [z for z in sp.solve(sp.simplify(F / c_sym**2), c_sym) if z.is_positive is not False]
    if len(roots) != 1 or roots[0].has(sp.I):
        return M, F, None, None
    c = sp.simplify(roots[0])
    P = 3 * sp.pi * S.mu / (2 * S.H**3) * sp.integrate(
        sp.expand(r_sym**3 * (prof - S.delta0)), (r_sym, 0, c_sym))
    P = sp.simplify(P.subs(c_sym, c))
    return M, F, c, P


def incompressible_tip(tip: Tip) -> IncompressibleTip:
    """The incompressible thin-layer solution (I.9a)-(I.9c) for a tip of revolution (module docstring).

    Parameters
    ----------
    tip : Tip
        An axisymmetric tip that is not a polynomial punch (those take
        :func:`~thinlayer.asymptotics.incompressible.incompressible_axisymmetric`).

    Examples
    --------
    >>> from thinlayer import Punch
    >>> sol = incompressible_tip(Punch.cone())
    >>> sol.radius                    # alpha in degrees: the expressions carry pi alpha/180
    3*delta_0*tan(pi*alpha/180)/2
    """
    if not isinstance(tip, Tip) or is_polynomial_tip(tip) or not tip.axisymmetric:
        raise InputTypeError(f"incompressible_tip() takes a tip of revolution that is not a polynomial punch "
                             f"(Punch.cone, Punch.sphere, ...), got {tip!r}")
    return IncompressibleTip(tip)


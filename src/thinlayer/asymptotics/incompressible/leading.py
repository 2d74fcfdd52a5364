r"""The incompressible model at ``nu = 1/2``: the elliptic paraboloid (I.6)-(I.8) and axisymmetric punches (I.9).

:func:`incompressible_ellipse` solves the free-boundary problem (I.3)-(I.4) in closed form for
``Phi = x1^2/(2 R1) + x2^2/(2 R2)`` (the aspect relation (I.6), the semi-axes and amplitude (I.7),
the force (I.8)); :func:`incompressible_axisymmetric` integrates (I.3) twice for an axisymmetric
polynomial punch (I.9).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ... import symbols as S
from ..._checks import InputError, InputTypeError, positive
from ...display import RichDisplay, fmt
from ...layers.kernels import IncompressibleLayer
from ...normal import normal_latex
from ...parse import as_expr
from ...punch import Punch, PunchError, is_polynomial_tip
from ...results import checked_lambdify, latex_equation
from ...symbols import laplacian
from .operator import obstacle_problem

__all__ = [
    "EllipseValues",
    "IncompressibleEllipse",
    "IncompressibleRadial",
    "RadialValues",
    "incompressible_axisymmetric",
    "incompressible_ellipse",
]

#: aspect ratio t = a^2/b^2 and radius ratio r = R1/R2 of (I.6)
t_sym = sp.Symbol("t", positive=True)
r_sym = sp.Symbol("r", positive=True)
#: contact radius and the radial coordinate of axisymmetric results
c_sym = sp.Symbol("c", positive=True)
rho = sp.Symbol("r", nonnegative=True)
#: the radial coordinate of generated code (``rho``: Fortran ignores case, and ``r`` would collide with ``R``)
rho_out = sp.Symbol("rho", nonnegative=True)


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
class IncompressibleEllipse(RichDisplay):
    """Closed-form solution of (I.3)-(I.4) for ``Phi = x1^2/(2 R1) + x2^2/(2 R2)`` (1.1).

    ``p = C (1 - x1^2/a^2 - x2^2/b^2)^2`` on the ellipse, zero outside.

    Attributes
    ----------
    R1, R2 : sympy.Expr
        Punch radii (symbols or numbers).
    aspect_equation : sympy.Expr
        ``3 t^2 + (1 - r) t - 3 r`` (I.6) in ``t = a^2/b^2`` and ``r = R1/R2`` (the symbols
        ``t_sym``, ``r_sym`` of this module).
    t : sympy.Expr
        Its positive root in terms of R1, R2.
    a2, b2, C, force
        ``a^2``, ``b^2``, the amplitude C (I.7) and ``P`` (I.8), in delta0, H, mu, R1, R2.
    a2_t, b2_t, C_t, force_t : sympy.Expr
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

    codegen_name = "incompressible_ellipse"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``(arguments, outputs)`` for code generation: ``force`` (I.8), ``semi_axis_a``, ``semi_axis_b`` (I.7) and
        ``pressure`` ``C (1 - x1^2/a^2 - x2^2/b^2)^2`` inside the ellipse, zero outside (I.7), at ``(x1, x2)``
        in the punch's principal axes.
        """
        q = 1 - S.x1**2 / self.a2 - S.x2**2 / self.b2
        outs = {"force": self.force, "semi_axis_a": sp.sqrt(self.a2), "semi_axis_b": sp.sqrt(self.b2),
                "pressure": sp.Piecewise((self.C * q**2, q > 0), (0, True))}
        return (S.x1, S.x2) + self.arguments, outs

    def evaluate(self, delta0: float, H: float, mu: float = 1.0, R1: float | None = None,
                 R2: float | None = None) -> EllipseValues:
        """Numbers of (I.6)-(I.8); R1, R2 are needed when the result is symbolic in them."""
        d0, HH, mm = (positive(v, n) for v, n in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
        sub = {S.delta0: d0, S.H: HH, S.mu: mm}
        for sym, val, nm in ((self.R1, R1, "R1"), (self.R2, R2, "R2")):
            if isinstance(sym, sp.Symbol):
                if val is None:
                    raise InputError(f"{nm} is symbolic in this result: pass {nm}=<positive number>")
                sub[sym] = positive(val, nm)
        keys = tuple(sorted(sub, key=str))
        t_of, rest = _ellipse_functions(self, keys)  # compiled once per result and set of symbols
        with mpmath.workdps(20):
            args = [mpmath.mpf(float(sub[k])) for k in keys]
            t = float(t_of(*args))
            a2, b2, C, P = (float(v) for v in rest(mpmath.mpf(t), *args))
        return EllipseValues(math.sqrt(a2), math.sqrt(b2), C, P, t)

    def latex(self) -> str:
        return " \\\\\n".join([
            latex_equation(normal_latex(self.aspect_equation), "0", "I.6"),
            latex_equation("t", normal_latex(self.t), "I.6"),
            latex_equation("a^2", normal_latex(self.a2_t), "I.7"),
            latex_equation("b^2", normal_latex(self.b2_t), "I.7"),
            latex_equation("C", normal_latex(self.C_t), "I.7"),
            latex_equation("P", normal_latex(self.force_t), "I.8"),
        ])

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``: (I.6)-(I.8) in ``t = a²/b²``, ``r = R₁/R₂``."""
        return ["IncompressibleEllipse: p = C (1 - x₁²/a² - x₂²/b²)² in the ellipse, ν = 1/2   (I.6)-(I.8)",
                f"  {fmt(self.aspect_equation)} = 0,  t = a²/b², r = R₁/R₂   (I.6)",
                f"  t  = {fmt(self.t)}",
                f"  a² = {fmt(self.a2_t)},  b² = {fmt(self.b2_t)}   (I.7)",
                f"  C  = {fmt(self.C_t)}   (I.7)",
                f"  P  = {fmt(self.force_t)}   (I.8)"]


@lru_cache(maxsize=128)
def _ellipse_functions(result: IncompressibleEllipse, keys: tuple) -> tuple:
    """``t(*keys)`` and ``(a^2, b^2, C, P)(t, *keys)`` of (I.6)-(I.8) as mpmath functions."""
    return (sp.lambdify(keys, result.t, modules="mpmath"),
            sp.lambdify((t_sym, *keys), [result.a2_t, result.b2_t, result.C_t, result.force_t], modules="mpmath"))


@lru_cache(maxsize=1)
def _ellipse_generic() -> IncompressibleEllipse:
    """The derivation with generic radii R_1, R_2 (specialised afterwards by substitution)."""
    R1, R2 = sp.symbols("R_1 R_2", positive=True)
    punch = Punch.elliptic_paraboloid(R1, R2)
    f = obstacle_problem(IncompressibleLayer(), punch).source
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
    R1, R2 : Any
        number or Symbol, optional
        Radii of curvature (positive numbers or symbols; default symbols ``R_1, R_2``).  Equal
        values give the sphere.

    Returns
    -------
    IncompressibleEllipse

    Examples
    --------
    >>> R = sp.Symbol("R", positive=True)
    >>> e = incompressible_ellipse(R, R)
    >>> e.t, e.a2, e.force
    (1, 4*R*delta_0, 2*pi*R**2*delta_0**3*mu/H**3)
    """
    r1 = sp.Symbol("R_1", positive=True) if R1 is None else as_expr(R1, "R1")
    r2 = sp.Symbol("R_2", positive=True) if R2 is None else as_expr(R2, "R2")
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
class IncompressibleRadial(RichDisplay):
    """Incompressible solution (I.3)-(I.4) for an axisymmetric punch, in quadratures (I.9).

    Attributes
    ----------
    punch : Punch
        The punch (Phi depends on ``x1^2 + x2^2`` only).
    profile : sympy.Expr
        ``Phi(r)``.
    radius_equation : sympy.Expr
        ``G(c) = int_0^c (delta0 - Phi(r)) r dr`` -- the contact radius is its positive root.
    pressure_of_c : sympy.Expr
        ``p(r)`` on ``0 <= r <= c`` in terms of ``c`` (a polynomial in r for a polynomial punch).
    force_of_c : sympy.Expr
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
            latex_equation(normal_latex(self.radius_equation), "0", "I.9"),
            latex_equation("p(r)", normal_latex(sp.factor(self.pressure_of_c)), "I.9"),
            latex_equation("P", normal_latex(sp.factor(self.force_of_c)), "I.9"),
        ])

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``: (I.9) in the contact radius c."""
        return [f"IncompressibleRadial: {self.punch.name}, ν = 1/2, in the contact radius c   (I.9)",
                f"  Φ(r) = {fmt(self.profile)}",
                f"  {fmt(self.radius_equation)} = 0",
                f"  p(r) = {fmt(sp.factor(self.pressure_of_c))}",
                f"  P    = {fmt(sp.factor(self.force_of_c))}"]

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        base = (c_sym, S.delta0, S.H, S.mu)
        rest = sorted(self.force_of_c.free_symbols - set(base) - {rho}, key=lambda q: q.name)
        return base + tuple(rest)

    def lambdify(self, args=None, backend: str = "numpy") -> Callable:
        """``(G(c), P(c))`` as a numeric function of :attr:`arguments` (c, delta0, H, mu, punch parameters)."""
        return checked_lambdify(self.arguments if args is None else args,
                                (self.radius_equation, self.force_of_c), backend)

    codegen_name = "incompressible_axisymmetric"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``(arguments, outputs)`` for code generation, in terms of the contact radius ``c`` (I.9):
        ``radius_equation`` ``G(c)`` (zero at the contact radius), ``force`` ``P(c)`` and ``pressure`` ``p(r)``
        (zero for ``r >= c``).
        """
        outs = {"radius_equation": self.radius_equation, "force": self.force_of_c,
                "pressure": sp.Piecewise((self.pressure_of_c, rho < c_sym), (0, True)).subs(rho, rho_out)}
        return (rho_out,) + self.arguments, outs

    def evaluate(self, delta0: float, H: float, mu: float = 1.0, parameters: dict | None = None) -> RadialValues:
        """Radius (smallest positive root of ``G`` with ``p >= 0`` on ``[0, c]``), force and ``p(r)``."""
        d0, HH, mm = (positive(v, n) for v, n in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
        by_name = {q.name: q for q in self.punch.parameters}
        sub = {S.delta0: d0, S.H: HH, S.mu: mm}
        for k, v in (parameters or {}).items():
            nm = k if isinstance(k, str) else getattr(k, "name", None)
            if nm not in by_name:
                raise InputError(f"{k!r} is not a parameter of the punch; its parameters are "
                                 f"{', '.join(by_name) or 'none'}")
            sub[by_name[nm]] = v
        # G(c) = c^2 (delta0 - Phi(0))/2 + ...: divide out the double root c = 0
        G = sp.Poly(sp.quo(sp.expand(self.radius_equation.subs(sub)), c_sym**2, c_sym), c_sym)
        if G.free_symbols - {c_sym}:
            raise InputError(f"the punch parameters {sorted(map(str, G.free_symbols - {c_sym}))} need values "
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
        raise InputError("no contact radius with a non-negative pressure: is Phi increasing with Phi(0) < delta0?")


def incompressible_axisymmetric(punch: Punch) -> IncompressibleRadial:
    """The incompressible solution for an axisymmetric polynomial punch (I.9), by integrating (I.3) twice.

    ``-(1/r)(r p')' = f`` with ``p'(0)`` finite gives ``r p'(r) = -int_0^r f s ds``; ``p'(c) = 0``
    (I.4) is ``int_0^c f s ds = 0`` and ``p(c) = 0`` fixes ``p(r) = int_r^c (1/rho) int_0^rho f s ds d rho``.

    Parameters
    ----------
    punch : Punch
        An axisymmetric polynomial punch (``Phi`` depends on ``x1^2 + x2^2`` only).

    Returns
    -------
    IncompressibleRadial

    Examples
    --------
    >>> from thinlayer import Punch
    >>> sol = incompressible_axisymmetric(Punch.paraboloid())
    >>> sp.solve(sol.radius_equation, c_sym)
    [2*sqrt(R)*sqrt(delta_0)]
    """
    if not is_polynomial_tip(punch):
        raise InputTypeError(f"punch must be a thinlayer.Punch, got {type(punch).__name__}")
    if not punch.axisymmetric:
        ang = sp.expand(S.x1 * sp.diff(punch.expr, S.x2) - S.x2 * sp.diff(punch.expr, S.x1))
        raise PunchError(f"the punch Phi = {punch.expr} is not axisymmetric (x1 dPhi/dx2 - x2 dPhi/dx1 = {ang}); "
                         "use solve_obstacle_grid for a general punch")
    prob = obstacle_problem(IncompressibleLayer(), punch)
    s = sp.Symbol("s", nonnegative=True)
    prof = punch.expr.subs({S.x1: rho, S.x2: 0})
    f_s = prob.source.subs({S.x1: s, S.x2: 0})
    inner = sp.integrate(sp.expand(f_s * s), (s, 0, rho))  # int_0^r f s ds
    G = sp.expand(sp.integrate(sp.expand((S.delta0 - prof.subs(rho, s)) * s), (s, 0, c_sym)))
    q = sp.Symbol("q", positive=True)
    pr = sp.expand(sp.integrate(sp.expand(inner.subs(rho, q) / q), (q, rho, c_sym)))
    force = sp.expand(2 * sp.pi * sp.integrate(sp.expand(pr * rho), (rho, 0, c_sym)))
    return IncompressibleRadial(punch, prof, G, pr, force)

"""Tests of the incompressible bonded layer (nu = 1/2) and the two-term model (:mod:`thinlayer.asymptotics.incompressible`).

Every formula is checked by a route independent of the one the module uses:

* the coefficients (I.1) by sympy's own series of (2.3), by the nu -> 1/2 limit of the compressible
  coefficients A m_n (2.20), and by mpmath numerical differentiation of the stable kernel;
* the moments (2.21) by numerical derivatives of L(s)/s (2.19), the operator (I.2) against (2.16);
* the leading operator against the literature value u_3 = -(H^3/(3 mu)) Delta p (Jaffar; Barber);
* the ellipse (I.6)-(I.8) by substitution into (I.3)-(I.4), by the harmonic-moment identities (I.5)
  (a derivation that does not use the ansatz), by the force identity P = -(1/4) int f |x|^2, and by the
  grid solver; the sphere against the literature (a^2 = 4 R delta0, P = 2 pi mu R^2 delta0^3/H^3);
* the models against the direct solver :func:`thinlayer.numerics.direct.solve_axisymmetric`, which knows only L(u).

Expected numbers are either closed forms derived here or literature values, never the module's output.
"""
from __future__ import annotations

import math
from dataclasses import FrozenInstanceError

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, IncompressibleLayerError, Punch, PunchError
from thinlayer import symbols as S
from thinlayer.asymptotics.incompressible import (
    IncompressibleLayer,
    _psi_chi,
    c_sym,
    compare_sphere_models,
    incompressible_axisymmetric,
    incompressible_coefficients,
    incompressible_ellipse,
    obstacle_problem,
    r_sym,
    regime,
    rho,
    solve_obstacle_grid,
    t_sym,
    thin_layer_operator,
    two_term_edge_layer,
    two_term_edge_shift,
    two_term_sphere,
)
from thinlayer.numerics.direct import solve_axisymmetric
from thinlayer.results import MissingArgumentError

slow = pytest.mark.slow
u = S.u
R = sp.Symbol("R", positive=True)


def lap(f, a=S.x1, b=S.x2):
    return sp.diff(f, a, 2) + sp.diff(f, b, 2)


def rate(e1: float, e2: float, ratio: float = 2.0) -> float:
    """Observed order of convergence from errors at step sizes h and h/ratio."""
    return math.log(abs(e1) / abs(e2)) / math.log(ratio)


# =========================================================================== kernel (2.3), (I.1)
def test_layer_kernel_is_the_nu_half_member_of_23():
    layer = IncompressibleLayer()
    bonded = BondedLayer().L(u).subs(S.nu, sp.Rational(1, 2))
    lhs = layer.L(u)
    assert lhs == bonded or sp.expand(lhs - bonded) == 0 or sp.simplify(lhs - bonded) == 0  # (2.3), kappa = 1
    assert float(lhs.subs(u, 0.7)) == pytest.approx(float(layer.L_numeric(0.7)), rel=1e-14)
    assert layer.kappa == 1 and layer.nu == sp.Rational(1, 2)
    assert sp.simplify(layer.vartheta - 2 * S.mu) == 0  # vartheta = mu/(1 - nu) (2.1)
    with pytest.raises(IncompressibleLayerError):
        BondedLayer(0.5)  # the compressible kernel class refuses nu = 1/2 (A = 0)


def test_coefficients_against_sympy_series():
    # route 2: sympy's series of L(u)/u for (2.3) at kappa = 1 (no power-series arithmetic of ours)
    c = incompressible_coefficients(5).c
    ser = sp.series(IncompressibleLayer().L(u) / u, u, 0, 12).removeO()
    for n in range(6):
        assert ser.coeff(u, 2 * n) == c[n]
    assert c[0] == 0 and c[1] == sp.Rational(2, 3)  # A = 0 (2.4); the leading coefficient of (I.1)


def test_coefficients_are_the_limit_of_the_compressible_ones():
    # route 3: A m_n (2.20) of the symbolic compressible layer, nu -> 1/2
    co = BondedLayer().coefficients(3)
    c = incompressible_coefficients(3).c
    for n in range(4):
        lim = sp.limit(co.A_expr * co.m_expr(n), S.nu, sp.Rational(1, 2))
        assert lim == c[n]
    # while m_1 alone blows up like 1/(3 (1 - 2 nu)): the compressible expansion breaks down
    assert sp.limit(co.m_expr(1) * (1 - 2 * S.nu), S.nu, sp.Rational(1, 2)) == sp.Rational(1, 3)


def test_coefficients_against_numerical_differentiation():
    # route 4: mpmath Taylor coefficients of the stable numerics of L(s)/s (an even function)
    layer = IncompressibleLayer()
    c = incompressible_coefficients(3).c
    with mpmath.workdps(40):
        tay = mpmath.taylor(lambda s: layer.L_numeric(abs(s), "mpmath", over_u=True), 0, 6)
    for n in range(4):
        assert float(tay[2 * n]) == pytest.approx(float(c[n]), rel=1e-12, abs=1e-25)


def test_compressible_stages_refuse_with_a_clear_message():
    layer = IncompressibleLayer()
    assert layer.A == 0
    for call in (lambda: layer.coefficients(1), lambda: layer.m(1), lambda: layer.M(1)):
        with pytest.raises(IncompressibleLayerError, match="incompressible_coefficients"):
            call()


@pytest.mark.parametrize("uu", [1e-6, 1e-3, 0.3, 2.0, 9.0, 40.0])
def test_numeric_kernel_matches_symbolic(uu):
    layer = IncompressibleLayer()
    ref = layer.L(u).subs(u, sp.Rational(str(uu))).evalf(40)
    assert float(layer.L_numeric(uu)) == pytest.approx(float(ref), rel=1e-13)
    assert float(layer.L_numeric(uu, "mpmath")) == pytest.approx(float(ref), rel=1e-13)
    assert float(layer.L_numeric(uu, over_u=True)) == pytest.approx(float(ref) / uu, rel=1e-13)
    with pytest.raises(ValueError, match="backend"):
        layer.L_numeric(uu, "cupy")


def test_small_and_large_u():
    layer = IncompressibleLayer()
    # (2.4) with kappa = 1: L = c_1 u^3 + ... and L - 1 ~ -(4u^2 + 4u + 2) e^{-2u}
    assert sp.expand(layer.small_u(2) - sp.series(layer.L(u), u, 0, 6).removeO()) == 0
    big = 15.0
    assert float(layer.L_numeric(big)) - 1 == pytest.approx(float(layer.large_u(u).subs(u, big)), rel=1e-6)


# =========================================================================== moments (2.15)-(2.23), (I.2)
@pytest.mark.parametrize("a1,a2", [(2, 0), (0, 2), (4, 0), (2, 2)])
def test_moments_against_numerical_derivatives(a1, a2):
    # (2.19): mu_{a1 a2} = (-1)^n pi^2 d^{a1}_{s1} d^{a2}_{s2} F(0),  F(s1, s2) = L(|s|)/|s|
    layer = IncompressibleLayer()
    n = (a1 + a2) // 2
    with mpmath.workdps(40):
        def F(s1, s2):
            return layer.L_numeric(mpmath.sqrt(s1 * s1 + s2 * s2), "mpmath", over_u=True)

        d = mpmath.diff(F, (0, 0), (a1, a2))
    assert float(layer.moment(a1, a2)) == pytest.approx(float((-1) ** n * mpmath.pi**2 * d), rel=1e-10)
    assert layer.moment(1, 2) == 0 and layer.moment(3, 0) == 0


def test_operator_pairing_equals_laplacian_form():
    # (2.16) built from the moments against the Laplacian series (2.22)/(2.23), at xi = 0
    op = thin_layer_operator(IncompressibleLayer(), 2)
    phi = 1 + 3 * S.xi1**2 - S.xi1 * S.xi2 + S.xi2**4 + 2 * S.xi1**2 * S.xi2**2 - S.xi1**6 + S.xi1**5
    a = op.pairing(phi)
    b = op.apply_scaled(phi).subs({S.xi1: 0, S.xi2: 0})
    assert a == b or sp.expand(a - b) == 0
    # numeric check of the same identity
    assert float(a.subs(S.Lambda, 3)) == pytest.approx(float(b.subs(S.Lambda, 3)), rel=1e-14)


def test_leading_operator_is_the_thin_incompressible_layer_of_the_literature():
    # Jaffar; Barber: delta0 - Phi = u_3 = -(H^3/(3 mu)) Delta p  for a thin bonded incompressible layer
    p = sp.Function("p")(S.x1, S.x2)
    lead = thin_layer_operator(IncompressibleLayer(), 1).leading()
    lit = -S.H**3 / (3 * S.mu) * lap(p)
    assert lead == lit or sp.expand(lead - lit) == 0
    # and the first operator term vanishes: no algebraic term at nu = 1/2 (A = 0)
    assert thin_layer_operator(IncompressibleLayer(), 1).c[0] == 0


def test_dimensional_operator_from_the_scaled_series():
    # (2.10) with (1.2), (2.8): u_3 = (Lambda H_*/(pi^2 vartheta)) * (2.23) with x = H_* xi, H = H_*/Lambda
    op = thin_layer_operator(IncompressibleLayer(), 2)
    q = S.x1**4 + 2 * S.x1**2 * S.x2 + S.x2**6
    dim = op.apply(q).subs(S.H, S.H_s / S.Lambda).subs({S.x1: S.H_s * S.xi1, S.x2: S.H_s * S.xi2})
    scaled = op.apply_scaled(q.subs({S.x1: S.H_s * S.xi1, S.x2: S.H_s * S.xi2}))
    expr = S.Lambda * S.H_s / (sp.pi**2 * op.vartheta) * scaled
    assert sp.expand(dim - expr) == 0
    vals = {S.Lambda: 7, S.H_s: 0.3, S.xi1: 0.4, S.xi2: -1.1, S.mu: 2.0}
    assert float(dim.subs(vals)) == pytest.approx(float(expr.subs(vals)), rel=1e-13)


def test_operator_for_a_compressible_layer_and_lambdify():
    op = thin_layer_operator(BondedLayer(), 1)
    co = BondedLayer().coefficients(1)
    assert op.c[0] == co.A_expr and sp.cancel(op.c[1] - co.A_expr * co.m_expr(1)) == 0
    f = op.lambdify()
    assert f(0.3)[1] == pytest.approx(float(co.A_expr.subs(S.nu, 0.3) * co.m_expr(1).subs(S.nu, 0.3)), rel=1e-14)
    assert "tag{I.2}" in thin_layer_operator(IncompressibleLayer(), 2).latex()
    with pytest.raises(TypeError, match="LayerKernel"):
        thin_layer_operator("bonded", 1)


# =========================================================================== (I.3)-(I.5), (I.10)
def test_obstacle_source_constant():
    prob = obstacle_problem(Punch.paraboloid())
    Phi = (S.x1**2 + S.x2**2) / (2 * R)
    expected = 3 * S.mu / S.H**3 * (S.delta0 - Phi)  # from u_3 = -(H^3/(3 mu)) Delta p (literature)
    assert prob.source == expected or sp.expand(prob.source - expected) == 0
    assert prob.k2 == 0 and prob.is_incompressible and prob.equation == "I.3"
    f = prob.lambdify()
    assert f(0.1, 0.2, 0.05, 0.1, 2.0, 3.0)[0] == pytest.approx(3 * 2.0 / 0.1**3 * (0.05 - 0.05 / 6), rel=1e-14)
    assert "tag{I.3}" in prob.latex() and "tag{I.4}" in prob.latex() and "tag{I.5}" in prob.latex()


def test_two_term_problem_coefficients_and_limit():
    prob = obstacle_problem(Punch.paraboloid(), nu=S.nu)
    m1 = BondedLayer().m(1)
    assert sp.cancel(prob.k2 - 1 / (m1 * S.H**2)) == 0  # k^2 = c_0/(c_1 H^2) = 1/(m_1 H^2) (I.10)
    lim = sp.limit(prob.source / (S.delta0 - Punch.paraboloid().expr), S.nu, sp.Rational(1, 2))
    assert sp.simplify(lim - 3 * S.mu / S.H**3) == 0  # continuous in nu up to (I.3)
    assert prob.equation == "I.10"
    p = prob.lambdify()
    _, k2_num = p(0.0, 0.0, 0.1, 1.0, 1.0, 2.0, 0.45)
    m1v = float(m1.subs(S.nu, 0.45))
    assert k2_num == pytest.approx(1 / m1v, rel=1e-14)


@pytest.mark.parametrize("nu", [0.2, 0.25, 0.51, "x", True, float("nan")])
def test_models_refuse_bad_nu(nu):
    with pytest.raises((ValueError, TypeError), match="nu"):
        obstacle_problem(Punch.paraboloid(), nu)


# =========================================================================== ellipse (I.6)-(I.8)
@pytest.fixture(scope="module")
def ellipse():
    return incompressible_ellipse()


def test_ellipse_solves_the_free_boundary_problem(ellipse):
    R1, R2 = ellipse.R1, ellipse.R2
    prob = obstacle_problem(Punch.elliptic_paraboloid(R1, R2))
    p = ellipse.pressure.subs(t_sym, ellipse.t)
    res = prob.residual(p)
    assert res == 0 or sp.expand(res) == 0 or sp.simplify(res) == 0  # (I.3)
    # numeric check of the residual at a point
    vals = {R1: 2.7, R2: 1.3, S.delta0: 0.11, S.H: 0.2, S.mu: 1.7, S.x1: 0.1, S.x2: -0.2}
    assert abs(float(res.subs(vals))) < 1e-9 * float(prob.source.subs(vals))
    # (I.4): p and its gradient vanish all along the contour
    a, b = sp.sqrt(ellipse.a2), sp.sqrt(ellipse.b2)
    for th in (0.0, 0.7, 2.0, 4.4):
        pt = prob.boundary_values(p, a * math.cos(th), b * math.sin(th))
        for v in pt:
            assert abs(float(v.subs(vals))) < 1e-12 * float(ellipse.C.subs(vals))


def test_ellipse_complementarity_outside_contact(ellipse):
    # outside omega: u_3 = 0 must be >= delta0 - Phi (1.5), i.e. f <= 0; inside p > 0 (2.7)
    vals = {"delta0": 0.1, "H": 0.1, "mu": 1.0, "R1": 3.0, "R2": 1.0}
    ev = ellipse.evaluate(**vals)
    th = np.linspace(0, 2 * np.pi, 97)
    for s in (1.0 + 1e-9, 1.1, 2.0):
        x, y = s * ev.a * np.cos(th), s * ev.b * np.sin(th)
        assert np.all(x**2 / 6.0 + y**2 / 2.0 >= 0.1)
    assert ev.C > 0 and ev.t > 1


def test_aspect_relation_from_harmonic_moments(ellipse):
    # (I.5), independent of the ansatz: int_omega f v = 0 for v = 1 and v = x1^2 - x2^2 over an ellipse
    a, b, R1, R2 = sp.symbols("a b R_1 R_2", positive=True)
    rr, th = sp.symbols("rho theta", nonnegative=True)
    f = S.delta0 - S.x1**2 / (2 * R1) - S.x2**2 / (2 * R2)
    sub = {S.x1: a * rr * sp.cos(th), S.x2: b * rr * sp.sin(th)}

    def integral(v):
        g = sp.expand((f * v).subs(sub) * a * b * rr)
        return sp.integrate(sp.integrate(g, (th, 0, 2 * sp.pi)), (rr, 0, 1))

    d0 = sp.solve(integral(1), S.delta0)[0]  # the volume condition
    rel = sp.cancel(integral(S.x1**2 - S.x2**2).subs(S.delta0, d0) / (sp.pi * a * b))
    rel_t = sp.cancel(rel.subs(a, sp.sqrt(t_sym) * b).subs(R1, r_sym * R2))
    target = ellipse.aspect_equation  # 3 t^2 + (1 - r) t - 3 r
    ratio = sp.cancel(sp.numer(sp.together(rel_t)) / target)
    assert not ratio.has(t_sym) and not ratio.has(r_sym) and ratio != 0  # the same quadratic, up to a factor
    assert sp.expand(target - (3 * t_sym**2 + (1 - r_sym) * t_sym - 3 * r_sym)) == 0
    # and the volume condition holds for the closed form: delta0 = (a^2/R1 + b^2/R2)/8
    e = ellipse
    chk = d0.subs({a: sp.sqrt(e.a2_t), b: sp.sqrt(e.b2_t), R1: e.R1, R2: e.R2}) - S.delta0
    num = sp.numer(sp.together(chk.subs(e.R1, r_sym * e.R2)))
    assert sp.rem(sp.Poly(num, t_sym), sp.Poly(target, t_sym)).is_zero  # zero modulo (I.6)
    vals = {e.R1: 2.0, e.R2: 1.0, S.delta0: 0.1}
    assert abs(float(chk.subs(t_sym, e.t).subs(vals))) < 1e-14


def test_aspect_ratio_root_and_limits(ellipse):
    R1, R2 = ellipse.R1, ellipse.R2
    t = ellipse.t.subs(R1, r_sym * R2)
    assert sp.simplify(t.subs(r_sym, 1)) == 1  # the sphere: a circle
    assert sp.limit(t / r_sym, r_sym, sp.oo) == sp.Rational(1, 3)  # much rounder than ...
    assert sp.limit(t / r_sym, r_sym, 0) == 3
    for rv in (1.5, 2.0, 10.0, 100.0):  # ... the compressible ellipse a^2/b^2 = R1/R2 (3.1)
        tv = float(t.subs(r_sym, rv))
        assert 1 < tv < rv
        roots = np.roots([3, 1 - rv, -3 * rv])
        assert min(roots) < 0 and tv == pytest.approx(max(roots), rel=1e-14)
    # slope at the sphere: dt/dr = 2/3 (compressible: 1)
    assert sp.limit(sp.diff(t, r_sym), r_sym, 1) == sp.Rational(2, 3)


def test_sphere_literature_values():
    # Jaffar; Chadwick (2002): a^2 = 4 R delta0, P = 2 pi mu R^2 delta0^3 / H^3 for a thin incompressible layer
    e = incompressible_ellipse(R, R)
    assert e.t == 1
    for got, lit in ((e.a2, 4 * R * S.delta0), (e.b2, 4 * R * S.delta0),
                     (e.force, 2 * sp.pi * S.mu * R**2 * S.delta0**3 / S.H**3)):
        assert got == lit or sp.expand(got - lit) == 0 or sp.simplify(got - lit) == 0
    ev = e.evaluate(0.03, 0.2, 1.5, R1=2.5, R2=2.5)
    assert ev.a == pytest.approx(math.sqrt(4 * 2.5 * 0.03), rel=1e-14)
    assert ev.force == pytest.approx(2 * math.pi * 1.5 * 2.5**2 * 0.03**3 / 0.2**3, rel=1e-14)


def test_force_by_the_second_moment_identity(ellipse):
    # P = -(1/4) int_omega f |x|^2 (Green's formula with v = |x|^2), independent of the force integral (1.8)
    e = ellipse
    rr, th = sp.symbols("rho theta", nonnegative=True)
    a, b = sp.sqrt(e.a2_t), sp.sqrt(e.b2_t)
    f = obstacle_problem(Punch.elliptic_paraboloid(e.R1, e.R2)).source
    g = sp.expand((f * (S.x1**2 + S.x2**2)).subs({S.x1: a * rr * sp.cos(th), S.x2: b * rr * sp.sin(th)}) * a * b * rr)
    P2 = -sp.integrate(sp.integrate(g, (th, 0, 2 * sp.pi)), (rr, 0, 1)) / 4
    diff = (P2 - e.force_t).subs(e.R1, r_sym * e.R2)
    # equal modulo the aspect relation (I.6): substitute its root
    tval = sp.solve(e.aspect_equation, r_sym)[0]
    assert sp.simplify(diff.subs(r_sym, tval)) == 0
    vals = {e.R1: 2.0, e.R2: 1.0, S.delta0: 0.1, S.H: 0.1, S.mu: 1.0}
    assert float(P2.subs(t_sym, e.t).subs(vals)) == pytest.approx(float(e.force.subs(vals)), rel=1e-12)


def test_ellipse_numbers_lambdify_and_latex(ellipse):
    f = ellipse.lambdify()
    assert ellipse.arguments == (S.delta0, S.H, S.mu, ellipse.R1, ellipse.R2)
    P, a, b, C = f(0.1, 0.1, 1.0, 2.0, 1.0)
    ev = ellipse.evaluate(0.1, 0.1, 1.0, R1=2.0, R2=1.0)
    assert (P, a, b, C) == pytest.approx((ev.force, ev.a, ev.b, ev.C), rel=1e-13)
    assert P == pytest.approx(math.pi * a * b * C / 3, rel=1e-13)  # int C (1 - X)^2 over the ellipse
    for tag in ("I.6", "I.7", "I.8"):
        assert f"tag{{{tag}}}" in ellipse.latex()
    with pytest.raises(MissingArgumentError, match="R_2"):
        ellipse.lambdify(args=(S.delta0, S.H, S.mu, ellipse.R1))
    with pytest.raises(ValueError, match="R1"):
        ellipse.evaluate(0.1, 0.1)
    with pytest.raises(PunchError, match="R1"):
        incompressible_ellipse(-1, 2)
    with pytest.raises(FrozenInstanceError):
        ellipse.t = 1


# =========================================================================== axisymmetric (I.9)
def test_radial_solution_of_the_paraboloid_agrees_with_the_ellipse():
    rad = incompressible_axisymmetric(Punch.paraboloid())
    c = sp.solve(rad.radius_equation, c_sym)
    assert c == [2 * sp.sqrt(R * S.delta0)] or sp.simplify(c[0] - 2 * sp.sqrt(R * S.delta0)) == 0
    P = rad.force_of_c.subs(c_sym, c[0])
    lit = 2 * sp.pi * S.mu * R**2 * S.delta0**3 / S.H**3
    assert sp.expand(P - lit) == 0
    v = rad.evaluate(0.03, 0.2, 1.5, {"R": 2.5})
    assert (v.radius, v.force) == (pytest.approx(math.sqrt(4 * 2.5 * 0.03), rel=1e-12),
                                   pytest.approx(2 * math.pi * 1.5 * 2.5**2 * 0.03**3 / 0.2**3, rel=1e-12))
    assert sp.expand(rad.pressure_of_c.subs(c_sym, c[0]) - incompressible_ellipse(R, R).pressure.subs(
        {t_sym: 1, S.x1: rho, S.x2: 0})) == 0


def test_radial_quartic_solves_the_ode_with_both_edge_conditions():
    punch = Punch.fourth_degree()
    rad = incompressible_axisymmetric(punch)
    p = rad.pressure_of_c
    f = obstacle_problem(punch).source.subs({S.x1: rho, S.x2: 0})
    ode = -(sp.diff(p, rho, 2) + sp.diff(p, rho) / rho) - f
    assert sp.expand(ode) == 0
    assert sp.expand(p.subs(rho, c_sym)) == 0
    # p'(c) = 0 exactly when the radius equation holds: p'(c) = -(3 mu/H^3) (2/c) G(c)
    dp = sp.diff(p, rho).subs(rho, c_sym)
    assert sp.expand(dp + 3 * S.mu / S.H**3 / c_sym * rad.radius_equation) == 0
    # force identity P = -(pi/2) int_0^c f r^3 dr, modulo the radius equation
    P2 = -sp.pi / 2 * sp.integrate(sp.expand(f * rho**3), (rho, 0, c_sym))
    d0 = sp.solve(rad.radius_equation, S.delta0)[0]
    assert sp.simplify((P2 - rad.force_of_c).subs(S.delta0, d0)) == 0
    v = rad.evaluate(0.1, 0.01, 1.0, {"R": 1.0, "K": 1.0})
    prm = {q: 1.0 for q in punch.parameters}
    assert float(rad.radius_equation.subs({c_sym: v.radius, S.delta0: 0.1, **prm})) == pytest.approx(0, abs=1e-15)
    assert v.pressure(np.array([0.0]))[0] > 0 and v.pressure(np.array([v.radius * 1.01]))[0] == 0
    assert "tag{I.9}" in rad.latex()
    with pytest.raises(PunchError, match="axisymmetric"):
        incompressible_axisymmetric(Punch.elliptic_paraboloid(2, 1))
    with pytest.raises(ValueError, match="parameters"):
        rad.evaluate(0.1, 0.01, 1.0)


# =========================================================================== grid solver
@pytest.fixture(scope="module")
def grid_ellipse():
    ev = incompressible_ellipse(2, 1).evaluate(0.1, 0.1, 1.0)
    runs = {n: solve_obstacle_grid(Punch.elliptic_paraboloid(2, 1), 0.1, 0.1, 1.0, n=n) for n in (41, 81, 161)}
    return ev, runs


def test_grid_reproduces_the_ellipse_with_second_order_convergence(grid_ellipse):
    ev, runs = grid_ellipse
    errP = {n: g.force / ev.force - 1 for n, g in runs.items()}
    errp = {}
    for n, g in runs.items():
        X1, X2 = np.meshgrid(g.x1, g.x2, indexing="ij")
        pex = ev.C * np.maximum(1 - X1**2 / ev.a**2 - X2**2 / ev.b**2, 0) ** 2
        errp[n] = np.abs(g.pressure - pex).max() / ev.C
    assert abs(errP[161]) < 5e-4 and errp[161] < 5e-4
    assert rate(errP[81], errP[161]) > 1.7 and rate(errp[81], errp[161]) > 1.7  # O(h^2)
    g = runs[161]
    # semi-axes: from the pressure moments (<x1^2> = a^2/8 for the (1 - X)^2 profile) and from the contact set
    _, _, m11, m12, m22 = g.moments()
    assert math.sqrt(8 * m11) == pytest.approx(ev.a, rel=5e-4)
    assert math.sqrt(8 * m22) == pytest.approx(ev.b, rel=5e-4)
    assert abs(m12) < 1e-12
    x1a, x1b, _, x2b = g.extent()
    h1, h2 = g.h
    assert abs(x1b - ev.a) < 1.5 * h1 and abs(-x1a - ev.a) < 1.5 * h1 and abs(x2b - ev.b) < 1.5 * h2
    assert g.area == pytest.approx(ev.area, rel=0.03)
    assert abs(g.volume_residual) < abs(runs[81].volume_residual) < 0.1  # (I.5), first order on the grid


def test_grid_quartic_against_the_radial_quadrature():
    punch = Punch.fourth_degree(R=1, K=1)
    ref = incompressible_axisymmetric(Punch.fourth_degree()).evaluate(0.1, 0.01, 1.0, {"R": 1.0, "K": 1.0})
    e = {n: solve_obstacle_grid(punch, 0.1, 0.01, n=n).force / ref.force - 1 for n in (81, 161)}
    assert abs(e[161]) < 5e-4 and rate(e[81], e[161]) > 1.7


def test_grid_general_punch_converges_and_satisfies_the_conditions():
    punch = Punch("x_1**2/2 + x_2**2/4 + x_1**3/3 + x_1*x_2/5")
    g = {n: solve_obstacle_grid(punch, 0.1, 0.01, n=n) for n in (41, 81, 161)}
    d1, d2 = g[41].force - g[81].force, g[81].force - g[161].force
    assert rate(d1, d2) > 1.6  # Richardson: O(h^2)
    s = g[161]
    assert np.all(s.pressure >= 0) and s.pressure[0, :].max() == 0
    # discrete (I.3) on the contact nodes away from the free boundary
    P = s.pressure
    h1, h2 = s.h
    L = ((P[2:, 1:-1] - 2 * P[1:-1, 1:-1] + P[:-2, 1:-1]) / h1**2 + (P[1:-1, 2:] - 2 * P[1:-1, 1:-1] + P[1:-1, :-2]) / h2**2)
    X1, X2 = np.meshgrid(s.x1[1:-1], s.x2[1:-1], indexing="ij")
    f = 3.0 / 0.01**3 * (0.1 - (X1**2 / 2 + X2**2 / 4 + X1**3 / 3 + X1 * X2 / 5))
    inner = s.contact[1:-1, 1:-1]
    assert np.max(np.abs(-L - f)[inner]) < 1e-8 * np.abs(f).max()
    # outside: u_3 = -(H^3/3 mu) Delta_h p >= delta0 - Phi (complementarity (1.5)), discretely
    assert np.all((-L - f)[~inner] >= -1e-8 * np.abs(f).max())
    assert s.pressure_at(0.0, 0.0) > 0 and s.lambdify()(10.0, 10.0) == 0


def test_grid_two_term_matches_the_bessel_sphere():
    # nu = 0.49, R = 1, delta0 = 0.02, H = 0.01: k c ~ 5, both terms of (I.10) matter
    ts = two_term_sphere("49/100").evaluate(0.02, 1.0, 0.01)
    e = {n: solve_obstacle_grid(Punch.paraboloid(R=1), 0.02, 0.01, nu="49/100", n=n).force / ts.force - 1
         for n in (81, 161)}
    assert abs(e[161]) < 1e-3 and rate(e[81], e[161]) > 1.7


def test_grid_input_errors():
    pun = Punch.paraboloid(R=1)
    with pytest.raises(ValueError, match="odd"):
        solve_obstacle_grid(pun, 0.1, 0.1, n=40)
    with pytest.raises(ValueError, match="box"):
        solve_obstacle_grid(pun, 0.1, 0.1, n=41, box=(-0.3, 0.3, -0.3, 0.3))
    with pytest.raises(ValueError, match="parameters"):
        solve_obstacle_grid(Punch.paraboloid(), 0.1, 0.1, n=41)
    with pytest.raises(ValueError, match="delta0"):
        solve_obstacle_grid(pun, -0.1, 0.1, n=41)
    with pytest.raises(ValueError, match="1/4 < nu"):
        solve_obstacle_grid(pun, 0.1, 0.1, nu=0.2, n=41)
    with pytest.raises(TypeError, match="Punch"):
        solve_obstacle_grid("x^2", 0.1, 0.1, n=41)
    g = solve_obstacle_grid(lambda a, b: (a * a + b * b) / 2, 0.1, 0.1, n=41)  # a callable punch
    assert g.force == pytest.approx(2 * math.pi * 0.1**3 / 0.1**3, rel=0.02)  # 2 pi mu R^2 delta0^3/H^3, R = 1
    with pytest.raises(ValueError):
        g.pressure[0, 0] = 1.0
    assert "tag{I.3}" in g.latex()


# =========================================================================== against the direct solver
def test_direct_solver_accepts_the_incompressible_layer_only():
    res = solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000, 0.025, 1.0)
    assert res.nu == 0.5 and res.vartheta == pytest.approx(2.0)
    with pytest.raises(ValueError, match="disagrees"):
        solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000, 0.025, 1.0, nu=0.3)
    with pytest.raises(ValueError, match="nu"):
        solve_axisymmetric(FrictionlessLayer(), lambda r: r * r / 2000, 0.025, 1.0, nu=0.5)


@pytest.fixture(scope="module")
def direct_sphere():
    """Direct solutions at nu = 1/2 with the model radius a = 2 sqrt(R delta0) = (a/H) H, H = 1, R = 1000."""
    out = {}
    for aH in (10, 20, 40):
        d0 = aH**2 / 4000.0
        out[aH] = (d0, solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000.0, d0, 1.0))
    return out


def test_direct_force_converges_to_the_incompressible_law(direct_sphere):
    # (I.8) with R1 = R2: P = 2 pi mu R^2 delta0^3/H^3; measured error ~ 21 (H/a)^2
    e = {aH: res.force / (2 * math.pi * 1000.0**2 * d0**3) - 1 for aH, (d0, res) in direct_sphere.items()}
    assert e[10] > e[20] > e[40] > 0
    assert e[40] < 0.02
    assert 1.7 < rate(e[20], e[40]) < 2.3 and 1.6 < rate(e[10], e[20]) < 2.3


def test_direct_radius_converges_with_the_edge_shift(direct_sphere):
    # c = a - h(1/2) H + O(H^2/a), a = 2 sqrt(R delta0) (I.7), h from (I.12)
    h = float(two_term_edge_shift())
    shift = {aH: (aH - res.radius) for aH, (d0, res) in direct_sphere.items()}
    dev = {aH: h - s for aH, s in shift.items()}
    assert abs(dev[40]) < 0.12 and rate(dev[20], dev[40]) > 0.8  # (a - c)/H -> h at rate H/a
    assert 2 * shift[40] - shift[20] == pytest.approx(h, abs=0.02)  # Richardson extrapolation
    assert 0.8 < rate(1 - direct_sphere[20][1].radius / 20, 1 - direct_sphere[40][1].radius / 40) < 1.2


def test_direct_quartic_punch_against_the_radial_solution():
    rad = incompressible_axisymmetric(Punch.fourth_degree())
    errs = []
    for H in (0.04, 0.02):
        v = rad.evaluate(0.1, H, 1.0, {"R": 1.0, "K": 1.0})
        res = solve_axisymmetric(IncompressibleLayer(), lambda r: r**2 / 2 + r**4, 0.1, H)
        errs.append(res.force / v.force - 1)
    assert abs(errs[1]) < 0.04 and 1.6 < rate(*errs) < 2.4


@slow
def test_direct_sphere_fine_layers():
    e, sh = [], []
    for aH in (40, 80):
        d0 = aH**2 / 4000.0
        res = solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000.0, d0, 1.0)
        e.append(res.force / (2 * math.pi * 1000.0**2 * d0**3) - 1)
        sh.append(aH - res.radius)
    assert e[1] < 0.005 and 1.8 < rate(*e) < 2.2
    assert 2 * sh[1] - sh[0] == pytest.approx(float(two_term_edge_shift()), abs=0.01)


# =========================================================================== two-term model (I.10)-(I.13)
@pytest.mark.parametrize("x", [1e-4, 0.3, 1.0, 1.99, 2.01, 5.0, 30.0, 300.0, 900.0, 1e5])
def test_psi_chi_against_high_precision_bessel(x):
    psi, chi = _psi_chi(np.array([x]))
    with mpmath.workdps(60):
        X = mpmath.mpf(x)
        ps = (X * mpmath.besseli(0, X) / mpmath.besseli(1, X) - 2) / X**2
        ch = (mpmath.mpf(1) / 4 - ps) / X**2
    assert psi[0] == pytest.approx(float(ps), rel=1e-13)
    assert chi[0] == pytest.approx(float(ch), rel=1e-12)


def test_psi_chi_at_zero_from_the_bessel_series():
    xx = sp.Symbol("x", positive=True)
    ser = sp.series(xx * sp.besseli(0, xx) / sp.besseli(1, xx), xx, 0, 8).removeO()
    psi0 = sp.limit((ser - 2) / xx**2, xx, 0)
    chi0 = sp.limit((sp.Rational(1, 4) - (ser - 2) / xx**2) / xx**2, xx, 0)
    psi, chi = _psi_chi(np.array([0.0]))
    assert psi[0] == float(psi0) and chi[0] == pytest.approx(float(chi0), rel=1e-15)


@pytest.mark.parametrize("nu", ["9/20", 0.49, 0.499])
def test_two_term_sphere_stable_form_equals_the_derived_bessel_form(nu):
    ts = two_term_sphere(nu)
    stable = ts.lambdify()
    with mpmath.workdps(30):
        exact = ts.lambdify(backend="mpmath")
        for c in (3.0, 21.0, 60.0):
            d_s, P_s = stable(c, 1000.0, 1.0, 1.3)
            d_e, P_e = exact(c, 1000.0, 1.0, 1.3)
            assert float(d_s) == pytest.approx(float(d_e), rel=1e-12)
            assert float(P_s) == pytest.approx(float(P_e), rel=1e-11)


def test_two_term_sphere_solves_its_problem():
    # the derived p(r) satisfies -Delta p + k^2 p = f, p(c) = 0, and p'(c) = 0 with delta0 = delta0(c)
    ts = two_term_sphere("49/100")
    k = sp.sqrt(ts.k2)
    p = ts.pressure_of_c.subs(sp.Symbol("k", positive=True), k)
    vals = {c_sym: 20.0, ts.R: 1000.0, S.H: 1.0, S.mu: 1.0}
    f = (ts.vartheta * (S.delta0 - rho**2 / (2 * ts.R)) / (ts.c1 * S.H**3)).subs(
        S.delta0, ts.delta0_of_c.subs(sp.Symbol("k", positive=True), k))
    ode = -(sp.diff(p, rho, 2) + sp.diff(p, rho) / rho) + ts.k2 * p - f
    for r in (1.0, 10.0, 19.0):
        assert abs(float(ode.subs(vals).subs(rho, r))) < 1e-9 * float(f.subs(vals).subs(rho, 0))
    assert abs(float(p.subs(vals).subs(rho, 20.0))) < 1e-9 * float(p.subs(vals).subs(rho, 0))
    assert abs(float(sp.diff(p, rho).subs(vals).subs(rho, 20.0))) < 1e-9 * float(p.subs(vals).subs(rho, 0))
    assert "tag{I.11}" in ts.latex()


def test_two_term_limits():
    # nu = 1/2: the incompressible sphere; the generic Bessel form tends to it as k -> 0
    inc = two_term_sphere()
    assert inc.delta0_of_c == c_sym**2 / (4 * R) or sp.expand(inc.delta0_of_c - c_sym**2 / (4 * R)) == 0
    gen = two_term_sphere("9/20")
    k = sp.Symbol("k", positive=True)
    # the Bessel forms at k c = 1e-6 (60 digits: their terms cancel like (k c)^-4) against the k = 0 forms;
    # P(c) with F = vartheta/(c_1 H^3) divided out must tend to the incompressible P/F = pi c^6/(96 R)
    # (the polynomial derivation at k = 0; P = 2 pi mu R^2 delta0^3/H^3 with c^2 = 4 R delta0)
    F = gen.vartheta / (gen.c1 * S.H**3)
    assert sp.simplify(inc.force_of_c / (inc.vartheta / (inc.c1 * S.H**3)) - sp.pi * c_sym**6 / (96 * R)) == 0
    d0 = sp.lambdify((k, c_sym, R), gen.delta0_of_c, "mpmath")
    PF = sp.lambdify((k, c_sym, R, S.H, S.mu), gen.force_of_c / F, "mpmath")
    with mpmath.workdps(60):
        kk, cc, RR = mpmath.mpf("1e-6"), mpmath.mpf(3), mpmath.mpf(7)
        assert float(d0(kk, cc, RR) / (cc**2 / (4 * RR)) - 1) == pytest.approx(0, abs=1e-11)
        assert float(PF(kk, cc, RR, 2, 3) / (mpmath.pi * cc**6 / (96 * RR)) - 1) == pytest.approx(0, abs=1e-11)
    # continuity in nu of the numbers
    a = two_term_sphere(0.4999999).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
    b = two_term_sphere(0.5).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
    assert a.force == pytest.approx(b.force, rel=1e-4) and a.radius == pytest.approx(b.radius, rel=1e-5)


def test_two_term_edge_layer_reproduces_the_boundary_layer_force_defect():
    from thinlayer.asymptotics.force_law import boundary_layer_force_defect

    e = two_term_edge_layer()
    ref = boundary_layer_force_defect()  # from Alexandrov's transform with (3.21): m_1/2
    m1_ref = sp.Symbol("m_1", real=True)
    assert sp.simplify(e.force_defect.subs(e.m1, m1_ref) - ref) == 0
    assert e.edge == -sp.sqrt(e.m1)
    # numeric check of the defect by quadrature
    m1 = 2.3
    q = e.lambdify()
    from scipy import integrate

    v0 = -math.sqrt(m1)
    D = integrate.quad(lambda v: q(v, m1), v0, 0)[0] + integrate.quad(lambda v: q(v, m1) - v, 0, 60)[0]
    assert D == pytest.approx(m1 / 2, rel=1e-10)


def test_two_term_force_keeps_the_compressible_first_correction():
    # for k a >> 1 the two-term force agrees with the compressible law (2.31)/(1.8) up to O((H/a)^3):
    # P_two/P_0 = 1 - 4/(k a)^2 + 4/(k a)^3 + ... with k^2 = 1/(m_1 H^2), a = sqrt(2 R delta0)
    from thinlayer import force_law

    law = force_law(BondedLayer(sp.Rational(9, 20)), Punch.paraboloid())
    diffs = []
    for aH in (40, 80):
        d0 = aH**2 / 2000.0  # sqrt(2 R delta0) = aH, H = 1, R = 1000
        ref = law.evaluate(d0, 1.0, 1.0, parameters={"R": 1000.0})
        two = two_term_sphere("9/20").evaluate(d0, 1000.0, 1.0)
        diffs.append(two.force / ref.force - 1)
        assert abs(two.force / ref.force - 1) < 0.1 * abs(ref.P1 / ref.P0)  # the correction itself is kept
    assert rate(*diffs) > 2.6  # O((H/a)^3): a wrong first correction would leave O((H/a)^2)


def test_edge_shift_identity_with_the_paper_edge_shift():
    # (I.12) = h*(nu) + sqrt(m_1): log K splits into the paper's factor and log(1 + m_1 t^2)
    from thinlayer.asymptotics.wiener_hopf import edge_shift_exact

    for nu in ("3/10", "9/20"):
        m1 = float(BondedLayer(nu).m(1))
        assert float(two_term_edge_shift(nu)) == pytest.approx(float(edge_shift_exact(nu)) + math.sqrt(m1),
                                                               rel=1e-10)
    assert float(two_term_edge_shift(0.45)) == pytest.approx(float(two_term_edge_shift("9/20")), rel=1e-12)


@pytest.fixture(scope="module")
def nearly_incompressible():
    """Sphere, R = 1000, H = 1, delta0 = 0.2 (sqrt(2 R delta0) = 20 H), in every model and the direct solver."""
    return {nu: compare_sphere_models(nu, 1000.0, 0.2, 1.0, direct=True) for nu in (0.45, 0.49, 0.499)}


def test_two_term_beats_both_limits_where_they_fail(nearly_incompressible):
    err = {nu: m.errors() for nu, m in nearly_incompressible.items()}
    for e in err.values():
        assert abs(e["two_term"][0]) < 0.02  # force within 2 % across the transition
        assert abs(e["two_term"][1]) < 0.005  # radius with the edge correction (I.12)
    # nu = 0.45 (lambda^2 ~ 180): compressible expansion fine, incompressible model off by a factor
    assert abs(err[0.45]["compressible"][0]) < 0.01 and err[0.45]["incompressible"][0] > 10
    # nu = 0.49 (lambda^2 ~ 26): the compressible correction is 15 %; the two-term model is 5x better
    assert abs(err[0.49]["two_term"][0]) < 0.2 * abs(err[0.49]["compressible"][0])
    assert abs(err[0.49]["two_term"][0]) < 0.01 * abs(err[0.49]["incompressible"][0])
    # nu = 0.499 (lambda^2 ~ 2.4): both limits fail
    assert abs(err[0.499]["compressible"][0]) > 1 and abs(err[0.499]["incompressible"][0]) > 0.3
    assert abs(err[0.499]["two_term"][0]) < 0.05 * min(abs(err[0.499]["compressible"][0]),
                                                        abs(err[0.499]["incompressible"][0]))


def test_regime_criterion(nearly_incompressible):
    # the compressible correction 4 m_1 (H/a)^2 (the sphere's 2 m_1 H^2/(R delta0)) and (3/16) lambda^2
    for nu, m in nearly_incompressible.items():
        rg = m.regime
        m1 = float(BondedLayer(sp.Rational(str(nu))).m(1))
        assert rg.lambda2 == pytest.approx(1 / (m1 * rg.H_over_a**2), rel=1e-12)
        assert rg.compressible_correction * rg.lambda2 == pytest.approx(4.0, rel=1e-12)
        # the recommended model is within 2 % of the direct solution
        best = {"compressible": "compressible", "incompressible": "incompressible", "two-term": "two_term"}
        assert abs(m.errors()[best[rg.model]][0]) < 0.02
    assert [regime(nu, 0.05).model for nu in (0.3, 0.45, 0.49, 0.5)] == \
        ["compressible", "compressible", "two-term", "incompressible"]
    assert regime(0.2, 0.05).model == "compressible"  # m_1 < 0: no breakdown below nu = 1/4
    # near 1/2: lambda^2 ~ 3 (1 - 2 nu) (a/H)^2 (I.13)
    rg = regime(0.49999, 0.1)
    assert rg.lambda2 == pytest.approx(3 * 2e-5 * 100, rel=1e-3)
    # the incompressible model's force error (3/16) lambda^2, from the two-term sphere at small k c
    a = two_term_sphere(0.499999).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
    b = two_term_sphere(0.5).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
    x2 = b.radius**2 / float(BondedLayer(0.499999).m(1))  # (k c)^2 with H = 1
    # divide out the O(1 - 2 nu) change of the prefactor vartheta/c_1 of f (I.10)
    ta, tb = two_term_sphere(0.499999), two_term_sphere(0.5)
    pref = float((ta.vartheta / ta.c1) / (tb.vartheta / tb.c1))
    assert a.force / (b.force * pref) - 1 == pytest.approx(-3 / 16 * x2, rel=0.01)
    f = rg.lambdify()
    assert f(0.49999, 0.1)[0] == pytest.approx(rg.lambda2, rel=1e-10)
    assert "tag{I.13}" in rg.latex()
    with pytest.raises(ValueError, match="nu"):
        regime(0.6, 0.1)
    with pytest.raises(ValueError, match="H_over_a"):
        regime(0.49, 0.0)


def test_compressible_first_correction_blows_up_like_one_over_one_minus_two_nu():
    from thinlayer import force_law

    law = force_law(BondedLayer(), Punch.paraboloid())
    rel = sp.cancel(law.P1 / law.P0)  # -2 m_1 H^2/(R delta0)
    lim = sp.limit(rel * (1 - 2 * S.nu), S.nu, sp.Rational(1, 2))
    assert sp.simplify(lim + 2 * S.H**2 / (3 * R * S.delta0)) == 0
    # numerically, with the numbers of the law at nu = 0.4999 (a float layer)
    v = force_law(BondedLayer(0.4999), Punch.paraboloid()).evaluate(0.2, 1.0, parameters={"R": 1000.0})
    assert v.P1 / v.P0 * (1 - 2 * 0.4999) == pytest.approx(-2 / (3 * 1000.0 * 0.2), rel=1e-3)


def test_sphere_models_api(nearly_incompressible):
    m = nearly_incompressible[0.49]
    assert m.lambdify()("direct") == m.direct
    assert "two-term" in m.latex()
    with pytest.raises(FrozenInstanceError):
        m.nu = 0.3
    nod = compare_sphere_models(0.5, 1000.0, 0.2, 1.0)
    assert nod.compressible is None and nod.direct is None
    with pytest.raises(ValueError, match="direct"):
        nod.errors()


@slow
@pytest.mark.parametrize("nu", [0.4999, 0.49999])
def test_two_term_near_the_incompressible_limit(nu):
    m = compare_sphere_models(nu, 1000.0, 0.2, 1.0, direct=True)
    e = m.errors()
    assert abs(e["two_term"][0]) < 0.03 and abs(e["two_term"][1]) < 0.005
    assert abs(e["compressible"][0]) > 10


@slow
def test_grid_fine_ellipse():
    ev = incompressible_ellipse(2, 1).evaluate(0.1, 0.1, 1.0)
    e = [solve_obstacle_grid(Punch.elliptic_paraboloid(2, 1), 0.1, 0.1, n=n).force / ev.force - 1
         for n in (161, 321)]
    assert abs(e[1]) < 1e-4 and rate(*e) > 1.7

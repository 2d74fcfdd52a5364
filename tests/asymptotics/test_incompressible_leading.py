"""Tests of the incompressible model's closed forms: the ellipse (I.6)-(I.8) and axisymmetric punches (I.9).

Module :mod:`thinlayer.asymptotics.incompressible.leading`.  The ellipse is checked by substitution into
(I.3)-(I.4), by the harmonic-moment identities (I.5) (a derivation that does not use the ansatz) and by the
force identity P = -(1/4) int f |x|^2; the sphere against the literature (a^2 = 4 R delta0,
P = 2 pi mu R^2 delta0^3/H^3).  Expected numbers are closed forms derived here or literature values.
"""
from __future__ import annotations

import math
from dataclasses import FrozenInstanceError

import numpy as np
import pytest
import sympy as sp

from thinlayer import Punch, PunchError
from thinlayer import symbols as S
from thinlayer.asymptotics.incompressible import (
    IncompressibleLayer,
    incompressible_axisymmetric,
    incompressible_ellipse,
    obstacle_problem,
)
from thinlayer.asymptotics.incompressible.leading import c_sym, r_sym, rho, t_sym
from thinlayer.results import MissingArgumentError

R = sp.Symbol("R", positive=True)


# =========================================================================== ellipse (I.6)-(I.8)
@pytest.fixture(scope="module")
def ellipse():
    return incompressible_ellipse()


def test_ellipse_solves_the_free_boundary_problem(ellipse):
    R1, R2 = ellipse.R1, ellipse.R2
    prob = obstacle_problem(IncompressibleLayer(), Punch.elliptic_paraboloid(R1, R2))
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
    f = obstacle_problem(IncompressibleLayer(), Punch.elliptic_paraboloid(e.R1, e.R2)).source
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
    f = obstacle_problem(IncompressibleLayer(), punch).source.subs({S.x1: rho, S.x2: 0})
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

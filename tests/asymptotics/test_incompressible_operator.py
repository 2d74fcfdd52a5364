"""Tests of the incompressible kernel (2.3), (I.1), the operator (I.2), the free-boundary problem (I.3)-(I.5), (I.10).

Modules :mod:`thinlayer.layers.kernels` (``IncompressibleLayer``) and
:mod:`thinlayer.asymptotics.incompressible.operator`.  Every formula is checked by a route independent of
the one the module uses: the coefficients (I.1) by sympy's own series of (2.3), by the nu -> 1/2 limit of
the compressible coefficients A m_n (2.20), and by mpmath numerical differentiation of the stable kernel;
the moments (2.21) by numerical derivatives of L(s)/s (2.19), the operator (I.2) against (2.16); the
leading operator against the literature value u_3 = -(H^3/(3 mu)) Delta p (Jaffar; Barber).
"""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from thinlayer import BondedLayer, IncompressibleLayerError, Punch
from thinlayer import symbols as S
from thinlayer.asymptotics.incompressible import (
    IncompressibleLayer,
    incompressible_coefficients,
    obstacle_problem,
    thin_layer_operator,
)

u = S.u
R = sp.Symbol("R", positive=True)


def lap(f, a=S.x1, b=S.x2):
    return sp.diff(f, a, 2) + sp.diff(f, b, 2)


# =========================================================================== kernel (2.3), (I.1)
def test_layer_kernel_is_the_nu_half_member_of_23():
    layer = IncompressibleLayer()
    bonded = BondedLayer().L(u).subs(S.nu, sp.Rational(1, 2))
    lhs = layer.L(u)
    assert lhs == bonded or sp.expand(lhs - bonded) == 0 or sp.simplify(lhs - bonded) == 0  # (2.3), kappa = 1
    assert float(lhs.subs(u, 0.7)) == pytest.approx(float(layer.L_numeric(0.7)), rel=1e-14)
    assert layer.kappa == 1 and layer.nu == sp.Rational(1, 2)
    assert sp.simplify(layer.vartheta - 2 * S.mu) == 0  # vartheta = mu/(1 - nu) (2.1)
    # nu = 1/2 spelled as a bonded layer is the incompressible layer (A = 0 in (2.4): no compressible data)
    assert BondedLayer(0.5) == layer and BondedLayer("1/2") == layer
    with pytest.raises(IncompressibleLayerError):
        BondedLayer(0.5).m(1)


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
    prob = obstacle_problem(IncompressibleLayer(), Punch.paraboloid())
    Phi = (S.x1**2 + S.x2**2) / (2 * R)
    expected = 3 * S.mu / S.H**3 * (S.delta0 - Phi)  # from u_3 = -(H^3/(3 mu)) Delta p (literature)
    assert prob.source == expected or sp.expand(prob.source - expected) == 0
    assert prob.k2 == 0 and prob.is_incompressible and prob.equation == "I.3"
    f = prob.lambdify()
    assert f(0.1, 0.2, 0.05, 0.1, 2.0, 3.0)[0] == pytest.approx(3 * 2.0 / 0.1**3 * (0.05 - 0.05 / 6), rel=1e-14)
    assert "tag{I.3}" in prob.latex() and "tag{I.4}" in prob.latex() and "tag{I.5}" in prob.latex()


def test_two_term_problem_coefficients_and_limit():
    prob = obstacle_problem(BondedLayer(), Punch.paraboloid())
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
        obstacle_problem(BondedLayer(nu), Punch.paraboloid())
    with pytest.raises((ValueError, TypeError), match="nu"):  # the deprecated form
        obstacle_problem(Punch.paraboloid(), nu)


def test_models_refuse_other_layers():
    from thinlayer import FrictionlessLayer, HalfSpace

    for layer in (FrictionlessLayer(), HalfSpace()):
        with pytest.raises(ValueError, match="bonded"):
            obstacle_problem(layer, Punch.paraboloid())
    with pytest.raises(TypeError, match="Punch"):
        obstacle_problem(IncompressibleLayer(), "x_1**2")


def test_obstacle_problem_deprecated_nu_form_still_works():
    # obstacle_problem(punch, nu) of earlier releases: the same problem, with a DeprecationWarning naming the new call
    punch = Punch.paraboloid()
    with pytest.warns(DeprecationWarning, match=r"obstacle_problem\(IncompressibleLayer\(\), punch\)"):
        old = obstacle_problem(punch)
    assert old.source == obstacle_problem(IncompressibleLayer(), punch).source
    with pytest.warns(DeprecationWarning, match=r"BondedLayer\('49/100'\)"):
        old = obstacle_problem(punch, "49/100")
    new = obstacle_problem(BondedLayer("49/100"), punch)
    assert (old.source, old.k2, old.nu) == (new.source, new.k2, new.nu)
    with pytest.warns(DeprecationWarning, match=r"BondedLayer\(\)"):
        old = obstacle_problem(punch, nu=S.nu)
    assert sp.cancel(old.k2 - obstacle_problem(BondedLayer(), punch).k2) == 0

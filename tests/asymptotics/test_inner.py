"""Inner expansion of the contact pressure (2.24)-(2.31), (4.1)."""

import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thinlayer import (
    BondedLayer,
    FrictionlessLayer,
    GenericLayer,
    MissingArgumentError,
    Punch,
    PunchError,
    inner_pressure,
    moment_expansion,
)
from thinlayer import symbols as S

A, m1 = GenericLayer.A_symbol, GenericLayer.m_symbol(1)
R1s, R2s = sp.Symbol("R_1^*", positive=True), sp.Symbol("R_2^*", positive=True)


def test_elliptic_paraboloid_2_29_2_30_2_31_as_derived():
    ip = inner_pressure(GenericLayer(), Punch.elliptic_paraboloid())
    assert ip.order == 2 and ip.nonzero_terms == 2  # (2.30): p_k = 0 for k >= 2
    Phis = S.H_s**2 * (S.xi1**2 / (2 * R1s) + S.xi2**2 / (2 * R2s))  # (2.13)
    p0 = S.vartheta / (A * S.H_s) * (S.delta0_s - Phis)  # (2.29)
    p1 = -S.vartheta * m1 * S.H_s / A * (1 / R1s + 1 / R2s)  # (2.30) derived: minus sign (errata)
    assert sp.expand(ip.scaled_terms[0] - p0) == 0
    assert sp.expand(ip.scaled_terms[1] - p1) == 0
    Rs = 2 / (1 / R1s + 1 / R2s)
    total = S.vartheta / (A * S.H_s) * (S.delta0_s - Phis - 2 * m1 * S.H_s**2 / (S.Lambda**2 * Rs))  # (2.31)
    assert sp.expand(ip.scaled_pressure - total) == 0
    more = inner_pressure(GenericLayer(), Punch.elliptic_paraboloid(), order=5)
    assert all(t == 0 for t in more.scaled_terms[2:])  # p_k = 0 (k = 2, 3, ...)


def test_inner_solution_satisfies_2_24_to_its_order():
    # independent route: substitute the truncated p* back into the operator series (2.24)
    punch = Punch(S.x1**4 / 7 + S.x1 * S.x2**3 / 3 - S.x1**2 * S.x2 + S.x2**2 / 2 + S.x1 / 5)
    layer = GenericLayer()
    ip = inner_pressure(layer, punch, order=3)
    me = moment_expansion(layer, 3)
    lhs = me.apply(ip.scaled_pressure) * S.Lambda**2
    phi_star = sp.pi**2 * S.vartheta / S.H_s * (S.delta0_s - punch.scaled())  # (2.25)
    resid = sp.expand(lhs - phi_star)
    # degree 4: the series (2.26) is exact through p_2, so every power of Lambda cancels exactly
    assert resid == 0


def test_dimensional_and_scaled_forms_agree():
    # (1.2), (2.8), (2.9): H = eps H_*, delta0 = eps delta0^*, R_j = R_j^*/eps, x = H_* xi, Lambda = 1/eps
    ip = inner_pressure(BondedLayer(), Punch.elliptic_paraboloid())
    eps = sp.Symbol("epsilon", positive=True)
    R1, R2 = sp.symbols("R_1 R_2", positive=True)
    dim = ip.pressure.subs({S.H: eps * S.H_s, S.delta0: eps * S.delta0_s, R1: R1s / eps, R2: R2s / eps,
                            S.x1: S.H_s * S.xi1, S.x2: S.H_s * S.xi2})
    scaled = ip.scaled_pressure.subs({S.Lambda: 1 / eps, S.vartheta: S.mu / (1 - S.nu)})
    assert sp.simplify(dim - scaled) == 0


def random_poly(draw_coeffs, degree):
    terms = []
    k = 0
    for i in range(degree + 1):
        for j in range(degree + 1 - i):
            if i + j >= 1:
                terms.append(sp.Rational(draw_coeffs[k % len(draw_coeffs)], 7) * S.x1**i * S.x2**j)
                k += 1
    return sp.Add(*terms)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(degree=st.integers(1, 7), coeffs=st.lists(st.integers(-9, 9), min_size=1, max_size=40),
       nu=st.sampled_from(["1/5", "3/10", "-1/3", "0"]))
def test_recursion_2_28_equals_closed_form_4_1(degree, coeffs, nu):
    expr = random_poly(coeffs, degree)
    if sp.Poly(expr, S.x1, S.x2).total_degree() < 1:
        return
    punch = Punch(expr)
    layer = BondedLayer(nu)
    a = inner_pressure(layer, punch, method="closed")
    b = inner_pressure(layer, punch, method="recursion")
    deg = punch.degree
    assert a.order == deg // 2 + 1  # the series terminates after floor(degree/2) corrections
    for ta, tb in zip(a.terms, b.terms):
        assert sp.expand(ta - tb) == 0
    for ta, tb in zip(a.scaled_terms, b.scaled_terms):
        assert sp.expand(ta - tb) == 0
    longer = inner_pressure(layer, punch, order=deg // 2 + 3, method="recursion")
    assert all(sp.expand(t) == 0 for t in longer.terms[deg // 2 + 1:])


def test_symbolic_coefficients_any_degree_recursion_equals_closed():
    c = sp.symbols("c0:20")
    expr = c[0] * S.x1**5 + c[1] * S.x1**2 * S.x2**3 + c[2] * S.x2**4 + c[3] * S.x1 * S.x2 + c[4] * S.x1**3
    a = inner_pressure(BondedLayer(), Punch(expr))
    b = inner_pressure(BondedLayer(), Punch(expr), method="recursion")
    for ta, tb in zip(a.terms, b.terms):
        assert sp.cancel(sp.expand(ta - tb)) == 0


def test_numeric_layer_and_lambdify():
    ip = inner_pressure(BondedLayer("3/10"), Punch.elliptic_paraboloid(R1=2, R2=1))
    assert ip.arguments == (S.x1, S.x2, S.delta0, S.H, S.mu)
    f = ip.lambdify()
    x = np.linspace(-1, 1, 11)
    vals = f(x, 0.5 * x, 0.3, 0.1, 2.0)
    # direct: vartheta/(A H) (delta0 - Phi) - (vartheta/A) m1 H (1/R1 + 1/R2), nu = 3/10: A = 20/49, m1 = 1/14
    th, Av, m1v = 2.0 / 0.7, 20 / 49, 1 / 14
    ref = th / (Av * 0.1) * (0.3 - x**2 / 4 - (0.5 * x) ** 2 / 2) - th / Av * m1v * 0.1 * 1.5
    np.testing.assert_allclose(vals, ref, rtol=1e-13)
    g = ip.lambdify(backend="mpmath")
    with mp.workdps(30):
        v = g(mp.mpf("0.1"), mp.mpf("0.2"), mp.mpf("0.3"), mp.mpf("0.1"), mp.mpf(2))
    assert abs(float(v) - f(0.1, 0.2, 0.3, 0.1, 2.0)) < 1e-12


def test_lambdify_refuses_missing_symbol():
    ip = inner_pressure(BondedLayer(), Punch.elliptic_paraboloid())
    with pytest.raises(MissingArgumentError, match="R_1, R_2, nu"):
        ip.lambdify(args=(S.x1, S.x2, S.delta0, S.H, S.mu))
    f = ip.lambdify()
    assert [a.name for a in ip.arguments] == ["x_1", "x_2", "delta_0", "H", "mu", "R_1", "R_2", "nu"]
    assert np.isfinite(f(0.0, 0.0, 0.1, 0.05, 1.0, 2.0, 1.0, 0.3))


def test_scaled_lambdify():
    ip = inner_pressure(BondedLayer("1/4"), Punch.elliptic_paraboloid())
    f = ip.lambdify(scaled=True)
    names = [a.name for a in ip.scaled_arguments]
    assert names[:6] == ["xi_1", "xi_2", "delta_0^*", "H_*", "Lambda", "vartheta"]
    assert np.isfinite(f(0.1, 0.2, 1.0, 1.0, 10.0, 1.0, 2.0, 1.0))


def test_latex_has_equation_tags():
    tex = inner_pressure(BondedLayer(), Punch.elliptic_paraboloid()).latex()
    assert r"\tag{2.27}" in tex and r"\tag{4.1}" in tex and r"\tag{2.26}" in tex


def test_frictionless_layer_inner_pressure():
    ip = inner_pressure(FrictionlessLayer(), Punch.paraboloid(R=1))
    # A = 1/2, m_1 = 0 for the frictionless base: no O(H) correction
    assert ip.terms[1] == 0


def test_degree_12_symbolic_performance_smoke():
    punch = Punch.general(12)
    assert len(punch.parameters) == 90  # every monomial of degree 1..12
    ip = inner_pressure(BondedLayer(), punch)
    assert ip.nonzero_terms == 7  # degree 12: p_0..p_6
    assert ip.terms[6].free_symbols >= {S.mu, S.H, S.nu}


@pytest.mark.parametrize("bad", ["sqrt(x_1) + x_2**2", "exp(x_1)", "x_1**2/x_2", "Abs(x_1)", "5"])
def test_non_polynomial_punch(bad):
    with pytest.raises(PunchError, match="polynomial|constant"):
        Punch(bad)


@pytest.mark.parametrize("bad", [0, -1])
def test_bad_order(bad):
    with pytest.raises(ValueError, match="positive integer"):
        inner_pressure(BondedLayer(), Punch.paraboloid(), order=bad)


def test_bad_types():
    with pytest.raises(TypeError, match="positive integer"):
        inner_pressure(BondedLayer(), Punch.paraboloid(), order=1.5)
    with pytest.raises(TypeError, match="Punch"):
        inner_pressure(BondedLayer(), S.x1**2)
    with pytest.raises(ValueError, match="method"):
        inner_pressure(BondedLayer(), Punch.paraboloid(), method="magic")


def test_user_symbols_are_mapped():
    a, b = sp.symbols("a b")
    p = Punch(a**2 + b**2 / 3, a, b)
    assert p.expr == S.x1**2 + S.x2**2 / 3

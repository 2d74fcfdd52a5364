"""Coefficients A, m_n (2.20) and M_k (4.2)."""
import mpmath as mp
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, kernel_coefficients
from thinlayer import symbols as S
from thinlayer.layers.coefficients import reciprocal_by_inversion


def sympy_series_coeffs(expr, n):
    """Independent route: sympy's series of the whole expression (slow; small n only)."""
    ser = sp.series(expr, S.s, 0, 2 * n + 1).removeO()
    return [ser.coeff(S.s, 2 * k) for k in range(n + 1)]


def test_m1_closed_form_2_20():
    # derived by hand: m_1 = 2(kappa-2)(kappa-3)/(3(kappa^2-1)) = -nu(1-4nu)/(3(1-2nu)(1-nu))
    m1 = BondedLayer().m(1)
    nu = S.nu
    assert sp.cancel(m1 - (-nu * (1 - 4 * nu) / (3 * (1 - 2 * nu) * (1 - nu)))) == 0
    k1 = BondedLayer(parameter="kappa").m(1)
    k = S.kappa
    assert sp.cancel(k1 - 2 * (k - 2) * (k - 3) / (3 * (k**2 - 1))) == 0


def test_symbolic_coefficients_match_sympy_series():
    # (2.20): A, m_1, m_2 against sympy.series of L(s)/s with symbolic nu
    layer = BondedLayer()
    ref = sympy_series_coeffs(layer.L(S.s) / S.s, 2)
    c = kernel_coefficients(layer, 2)
    assert sp.cancel(c.A - ref[0]) == 0
    for n in (1, 2):
        assert sp.cancel(c.A * c.m[n] - ref[n]) == 0


@pytest.mark.parametrize("nu", [sp.Rational(3, 10), sp.Rational(-1, 2), sp.Integer(0), sp.Rational(49, 100)])
def test_rational_nu_gives_exact_rationals(nu):
    layer = BondedLayer(nu)
    c = kernel_coefficients(layer, 6)
    assert all(isinstance(x, sp.Rational) for x in c.m + c.M)
    ref = sympy_series_coeffs(layer.L(S.s) / S.s, 4)
    assert c.A == ref[0]
    assert [c.A * c.m[n] for n in range(5)] == ref
    sym = kernel_coefficients(BondedLayer(), 6)
    assert all(sym.m[n].subs(S.nu, nu) == c.m[n] for n in range(7))
    assert all(sym.M[n].subs(S.nu, nu) == c.M[n] for n in range(7))


def test_float_nu_gives_mpmath_numbers_at_precision():
    c = kernel_coefficients(BondedLayer(0.3, dps=40), 8)
    exact = kernel_coefficients(BondedLayer(sp.Rational(3, 10)), 8)
    assert all(isinstance(x, mp.mpf) for x in c.m[1:])
    nu_bin = sp.Rational(0.3)  # the binary value of the float 0.3
    ex_bin = kernel_coefficients(BondedLayer(nu_bin), 8)
    with mp.workdps(40):
        for n in range(1, 9):
            ref = mp.mpf(ex_bin.m[n].p) / ex_bin.m[n].q
            assert abs(c.m[n] - ref) <= mp.mpf(10) ** -36 * abs(ref)
            assert abs(float(c.M[n]) - float(exact.M[n])) <= 1e-12 * abs(float(exact.M[n])) + 1e-15


@pytest.mark.parametrize("order", [1, 4, 10])
def test_recurrence_4_2_equals_direct_inversion(order):
    # (4.2) against the independent division s/L(s) = D(s^2)/N(s^2)
    layer = BondedLayer()
    c = kernel_coefficients(layer, order)
    direct = reciprocal_by_inversion(layer, order)
    for k in range(order + 1):
        assert sp.cancel(c.M[k] - direct[k]) == 0


@settings(max_examples=25, deadline=None)
@given(p=st.integers(-99, 49), order=st.integers(1, 12))
def test_series_times_reciprocal_is_one(p, order):
    # (2.20) x (4.2): (sum m_n z^n)(sum M_k z^k) = 1 + O(z^(order+1)), exactly for rational nu
    layer = BondedLayer(sp.Rational(p, 100))
    c = kernel_coefficients(layer, order)
    for k in range(1, order + 1):
        assert sum(c.m[k - j] * c.M[j] for j in range(k + 1)) == 0
    direct = reciprocal_by_inversion(layer, order)
    assert tuple(direct) == c.M


def test_generic_layer_M_in_terms_of_m():
    c = kernel_coefficients(GenericLayer(), 3)
    m1, m2, m3 = (GenericLayer.m_symbol(i) for i in (1, 2, 3))
    # (4.2) by hand
    assert c.M[1] == -m1
    assert sp.expand(c.M[2] - (m1**2 - m2)) == 0
    assert sp.expand(c.M[3] - (-m1**3 + 2 * m1 * m2 - m3)) == 0


def test_frictionless_coefficients_against_series():
    layer = FrictionlessLayer()
    c = kernel_coefficients(layer, 4)
    ref = sympy_series_coeffs(layer.L(S.s) / S.s, 4)
    assert [c.A * c.m[n] for n in range(5)] == ref


def test_latex_and_lambdify_of_coefficients():
    c = kernel_coefficients(BondedLayer(), 2)
    tex = c.latex()
    assert r"\tag{2.20}" in tex and r"\tag{4.2}" in tex and r"\tag{2.4}" in tex
    f = c.lambdify("mpmath")
    exact = kernel_coefficients(BondedLayer("3/10"), 2)
    with mp.workdps(30):
        vals = f(mp.mpf(3) / 10)
        assert abs(vals[1] - mp.mpf(exact.m[1].p) / exact.m[1].q) < 1e-27


@pytest.mark.parametrize("bad", [-1, 1.5, "2"])
def test_bad_order(bad):
    with pytest.raises((ValueError, TypeError), match="non-negative integer"):
        kernel_coefficients(BondedLayer(), bad)

"""Tests of the two-term model (I.10)-(I.12) (:mod:`thinlayer.asymptotics.incompressible.two_term`).

psi and chi of (I.11) against high-precision Bessel functions, the sphere's derived forms against the
ODE and each other, the limits nu -> 1/2 and k a >> 1 (the compressible force law), the edge layer's force
defect against the Wiener--Hopf boundary layer, and the edge shift (I.12) against the paper's h*(nu).
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, Punch
from thinlayer import symbols as S
from thinlayer.asymptotics.incompressible import (
    IncompressibleLayer,
    two_term_edge_layer,
    two_term_edge_shift,
    two_term_sphere,
)
from thinlayer.asymptotics.incompressible.leading import c_sym, rho
from thinlayer.asymptotics.incompressible.two_term import _psi_chi

R = sp.Symbol("R", positive=True)


def rate(e1: float, e2: float, ratio: float = 2.0) -> float:
    """Observed order of convergence from errors at step sizes h and h/ratio."""
    return math.log(abs(e1) / abs(e2)) / math.log(ratio)


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
    ts = two_term_sphere(BondedLayer(nu))
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
    ts = two_term_sphere(BondedLayer("49/100"))
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
    gen = two_term_sphere(BondedLayer("9/20"))
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
    a = two_term_sphere(BondedLayer(0.4999999)).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
    b = two_term_sphere(IncompressibleLayer()).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
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
        two = two_term_sphere(BondedLayer("9/20")).evaluate(d0, 1000.0, 1.0)
        diffs.append(two.force / ref.force - 1)
        assert abs(two.force / ref.force - 1) < 0.1 * abs(ref.P1 / ref.P0)  # the correction itself is kept
    assert rate(*diffs) > 2.6  # O((H/a)^3): a wrong first correction would leave O((H/a)^2)


def test_edge_shift_identity_with_the_paper_edge_shift():
    # (I.12) = h*(nu) + sqrt(m_1): log K splits into the paper's factor and log(1 + m_1 t^2)
    from thinlayer.asymptotics.wiener_hopf import edge_shift_exact

    for nu in ("3/10", "9/20"):
        m1 = float(BondedLayer(nu).m(1))
        assert float(two_term_edge_shift(BondedLayer(nu))) == pytest.approx(float(edge_shift_exact(nu)) + math.sqrt(m1),
                                                               rel=1e-10)
    assert float(two_term_edge_shift(BondedLayer(0.45))) == pytest.approx(
        float(two_term_edge_shift(BondedLayer("9/20"))), rel=1e-12)


def test_compressible_first_correction_blows_up_like_one_over_one_minus_two_nu():
    from thinlayer import force_law

    law = force_law(BondedLayer(), Punch.paraboloid())
    rel = sp.cancel(law.P1 / law.P0)  # -2 m_1 H^2/(R delta0)
    lim = sp.limit(rel * (1 - 2 * S.nu), S.nu, sp.Rational(1, 2))
    assert sp.simplify(lim + 2 * S.H**2 / (3 * R * S.delta0)) == 0
    # numerically, with the numbers of the law at nu = 0.4999 (a float layer)
    v = force_law(BondedLayer(0.4999), Punch.paraboloid()).evaluate(0.2, 1.0, parameters={"R": 1000.0})
    assert v.P1 / v.P0 * (1 - 2 * 0.4999) == pytest.approx(-2 / (3 * 1000.0 * 0.2), rel=1e-3)


def test_two_term_sphere_deprecated_nu_form_still_works():
    # two_term_sphere(nu) of earlier releases: the same model, with a DeprecationWarning naming the new call
    with pytest.warns(DeprecationWarning, match=r"two_term_sphere\(BondedLayer\(0.45\)\)"):
        old = two_term_sphere(0.45)
    assert old is two_term_sphere(BondedLayer(0.45))
    with pytest.warns(DeprecationWarning, match=r"two_term_sphere\(IncompressibleLayer\(\)\)"):
        old = two_term_sphere(0.5)
    assert old is two_term_sphere(IncompressibleLayer()) and old is two_term_sphere()
    with pytest.warns(DeprecationWarning, match=r"two_term_sphere\(BondedLayer\(\)\)"):
        old = two_term_sphere(S.nu)
    assert old.delta0_of_c == two_term_sphere(BondedLayer()).delta0_of_c
    with pytest.raises(ValueError, match="1/4 < nu"):
        two_term_sphere(BondedLayer(0.2))
    with pytest.raises(TypeError, match="numeric"):
        two_term_sphere(BondedLayer()).evaluate(0.2, 1000.0, 1.0)


def test_two_term_edge_shift_deprecated_nu_form_still_works():
    with pytest.warns(DeprecationWarning, match=r"two_term_edge_shift\(IncompressibleLayer\(\)\)"):
        old = two_term_edge_shift(0.5)
    assert old == two_term_edge_shift(IncompressibleLayer()) == two_term_edge_shift()
    with pytest.warns(DeprecationWarning, match=r"two_term_edge_shift\(BondedLayer\('9/20'\)\)"):
        old = two_term_edge_shift("9/20")
    assert old == two_term_edge_shift(BondedLayer("9/20"))
    with pytest.raises(TypeError, match="numeric"):
        two_term_edge_shift(BondedLayer())

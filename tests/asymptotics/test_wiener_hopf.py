"""Tests of the exact boundary layer by Wiener--Hopf factorisation (3.15)-(3.25).

Every expected value comes from an independent route: a closed form derived by hand,
a different factorisation, the layer's series coefficients (2.20), direct quadrature of the
integral equation (3.22) with N from (3.17), or a limit.
"""
from __future__ import annotations

import dataclasses
import itertools
import math
import os

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy import integrate, special

from thinlayer import BondedLayer
from thinlayer.asymptotics.wiener_hopf import (
    boundary_kernel_N,
    boundary_layer_exact,
    edge_shift,
    edge_shift_alexandrov,
    edge_shift_exact,
    edge_shift_table,
    wiener_hopf_solution,
)

slow = pytest.mark.skipif(not os.environ.get("THINLAYER_SLOW"), reason="slow: set THINLAYER_SLOW=1")
NUS = [-0.999, -0.5, 0.0, 0.1, 0.25, 0.3, 0.4, 0.45, 0.49, 0.4999]


def _A_m1(nu):
    lay = BondedLayer(sp.Rational(nu))
    return float(lay.A), float(lay.m(1))


@pytest.fixture(scope="module")
def exact03():
    return boundary_layer_exact("3/10")


@pytest.fixture(scope="module")
def alex03():
    return wiener_hopf_solution("3/10", kernel="alexandrov", normaliser="sqrt")


# ------------------------------------------------------------------ Alexandrov's constants
@pytest.mark.parametrize("nu", ["3/10", "1/10", "-1/2", "49/100"])
def test_alexandrov_kernel_matches_A_and_m1(nu):
    # (3.19)-(3.21): F~ = sqrt(s^2+B^2)/(s^2+C) = A (1 + m_1 s^2 + ...) with B = A C and
    # 1/C - 1/(2B^2) = -m_1.  Expand F~ by sympy and compare with the layer's (2.20).
    lay = BondedLayer(nu)
    A, m1 = lay.A, lay.m(1)
    s = sp.Symbol("s")
    invC = A**2 * (1 + sp.sqrt(1 + 2 * m1 / A**2))
    C = 1 / invC
    B = A * C
    ser = sp.series(sp.sqrt(s**2 + B**2) / (s**2 + C), s, 0, 4).removeO()
    assert sp.simplify(ser.coeff(s, 0) - A) == 0  # (3.20)
    assert sp.simplify(ser.coeff(s, 2) - A * m1) == 0  # (3.21), corrected
    # the printed (3.21) "1/C - 1/(2B^2) = -2 m_1" would give the s^2 coefficient 2 A m_1
    assert sp.simplify(ser.coeff(s, 2) - 2 * A * m1) != 0
    # (3.25): sqrt(A/B) - 1/(2B) is the closed form, evaluated independently of the module
    expected = float(sp.sqrt(A / B) - 1 / (2 * B))
    assert float(edge_shift_alexandrov(nu)) == pytest.approx(expected, rel=1e-14, abs=1e-15)


def test_alexandrov_closed_form_at_nu0():
    # nu = 0: kappa = 3, A = 1/2, m_1 = 0 -> 1/C = 2 A^2 = 1/2, B = A C = 1, h~ = 1/sqrt 2 - 1/2 (3.25)
    assert edge_shift_alexandrov(0) == pytest.approx(1 / math.sqrt(2) - 0.5, rel=1e-15)


# ------------------------------------------------------------------ the edge shift
@pytest.mark.parametrize("nu", NUS)
def test_three_normalisers_agree(nu):
    # h = h[F0] - (1/pi) int log(F/F0)/t^2 dt with three different exact factorisations
    hs = [edge_shift_exact(nu, normaliser=n) for n in ("sqrt", "alexandrov", "tanh")]
    scale = max(1.0, abs(float(hs[0])))
    assert abs(hs[0] - hs[1]) < 1e-12 * scale
    assert abs(hs[0] - hs[2]) < 1e-12 * scale


@pytest.mark.parametrize("nu", ["3/10", "-1/2", "49/100", 0.1])
@pytest.mark.parametrize("normaliser", ["sqrt", "tanh"])
def test_factorisation_formula_reproduces_3_25(nu, normaliser):
    # applying the exact-kernel formula to F := F~ must give Alexandrov's closed form (3.25)
    h = edge_shift(nu, kernel="alexandrov", normaliser=normaliser)
    assert abs(h - edge_shift_alexandrov(nu)) < 1e-13


@pytest.mark.parametrize("nu", [-0.9, 0.3, 0.49])
def test_edge_shift_converges_with_precision(nu):
    assert abs(edge_shift_exact(nu, dps=20) - edge_shift_exact(nu, dps=32)) < 1e-15


def test_edge_shift_near_incompressible_limit():
    # nu -> 1/2: F(t) ~ A + (2/3) t^2 on the inner scale t ~ sqrt(A) (L(u) ~ 2u^3/3 at kappa = 1), so
    # h ~ -(1/pi) int_0^oo log(1 + 2 t^2/(3A))/t^2 dt = -sqrt(2/(3A)); the error is O(sqrt(A)) relative.
    errs = []
    for eps in ["1e-4", "1e-6", "1e-8"]:
        nu = sp.Rational(1, 2) - sp.Rational(eps)
        A = float(BondedLayer(nu).A)
        h = float(edge_shift_exact(nu))
        errs.append(abs(h * math.sqrt(A) + math.sqrt(2 / 3)))
    assert errs[2] < 1e-3
    assert errs[1] < errs[0] / 5 and errs[2] < errs[1] / 5


def test_inputs_and_errors():
    assert edge_shift_exact(BondedLayer(0.3)) == edge_shift_exact(0.3)
    assert abs(edge_shift_exact("3/10") - edge_shift_exact(0.3)) < 1e-14
    with pytest.raises(ValueError, match="nu"):
        edge_shift_exact(0.5)
    with pytest.raises(ValueError, match="nu"):
        edge_shift_exact(-1)
    with pytest.raises(TypeError, match="nu"):
        edge_shift_exact(True)
    with pytest.raises(ValueError, match="symbolic"):
        edge_shift_exact(BondedLayer())
    with pytest.raises(ValueError, match="normaliser"):
        edge_shift_exact(0.3, normaliser="pade")
    with pytest.raises(ValueError, match="kernel"):
        edge_shift(0.3, kernel="frictionless")
    with pytest.raises(ValueError, match="dps"):
        edge_shift_exact(0.3, dps=5)


def test_table():
    tab = edge_shift_table([0, "3/10"])
    assert len(tab.rows) == 2
    assert tab.rows[0][2] == pytest.approx(1 / math.sqrt(2) - 0.5, rel=1e-15)
    assert r"\tilde h" in tab.latex() and "0.3" in str(tab)


# ------------------------------------------------------------------ the kernel N (3.17)
@pytest.mark.parametrize("t", [0.05, 0.7, 2.5])
def test_kernel_N_against_direct_quadrature(t):
    lay = BondedLayer("3/10")
    with mpmath.workdps(20):
        F = lambda s: lay.L_numeric(s, backend="mpmath", over_u=True) if s > 0 else mpmath.mpf(lay.A)
        ref = mpmath.pi * mpmath.quadosc(lambda s: F(s) * mpmath.cos(s * t), [0, mpmath.inf], omega=t)
    assert float(boundary_kernel_N("3/10", t)) == pytest.approx(float(ref), abs=1e-12)


# ------------------------------------------------------------------ the boundary layer
def test_alexandrov_pipeline_reproduces_3_24(alex03):
    # the numerical Wiener-Hopf solution with F := F~ against the closed form (3.24):
    # qhat = (tau + h~) erf sqrt(B tau) + sqrt(tau/(pi B)) e^{-B tau}
    lay = BondedLayer("3/10")
    A, m1 = float(lay.A), float(lay.m(1))
    invC = A**2 * (1 + math.sqrt(1 + 2 * m1 / A**2))
    B = A / invC
    h = math.sqrt(A / B) - 1 / (2 * B)
    tau = np.concatenate([np.logspace(-9, 0, 60), np.linspace(1, 1.5 * alex03.tau_max, 400)])
    exact = (tau + h) * special.erf(np.sqrt(B * tau)) + np.sqrt(tau / (np.pi * B)) * np.exp(-B * tau)
    assert np.max(np.abs(alex03.q_numpy(tau) - exact)) < 1e-10
    assert float(alex03.h) == pytest.approx(h, abs=1e-14)


def test_edge_behaviour_and_positivity(exact03):
    # (3.18): q(0) = 0; F ~ 1/|s| gives the square-root edge qhat ~ 2 sqrt(A tau/pi); q > 0
    A = float(BondedLayer("3/10").A)
    assert abs(exact03.q_numpy(0.0)) < 1e-10
    tau = 1e-12
    assert float(exact03.q(tau)) / math.sqrt(tau) == pytest.approx(2 * math.sqrt(A / math.pi), rel=1e-5)
    grid = np.linspace(0, 1.2 * exact03.tau_max, 5001)[1:]
    q = exact03.q_numpy(grid)
    assert np.all(q > 0)
    assert np.all(np.diff(q) > 0)


def test_far_field_and_decay_rate(exact03):
    # qhat - tau - h -> 0 like e^{-sigma tau}: -sigma is the pole of 1/Phi(p), i.e. the zero
    # F(-i sigma) = 0 of the kernel: sin(2 sigma)/(2 sigma) = 1/kappa (kappa = 3 - 4 nu = 9/5)
    sigma = 0.5 * float(mpmath.findroot(lambda x: mpmath.sin(x) / x - mpmath.mpf(5) / 9, 1.8))
    h = exact03.h
    r1, r2 = (exact03.q(t) - t - h for t in (8, 12))
    assert abs(r2) < 1e-4 * (1 + abs(h))
    assert float(r2 / r1) == pytest.approx(math.exp(-4 * sigma), rel=1e-7)


def test_q_mpmath_matches_table(exact03):
    for tau in (1e-4, 0.7, 5.0):
        assert float(exact03.q(tau)) == pytest.approx(float(exact03.q_numpy(tau)), abs=1e-10)


def test_panel_sum_in_mpfr_is_mpmaths_to_the_bit(exact03):
    """log Phi(p) of the panel rule (3.19)-(3.21): the node sum runs in gmpy2's MPFR; the same sum in mpmath's own
    arithmetic (each operation rounded at mpmath's precision) gives the same bits, at several precisions and p."""
    tr = exact03._transform

    def mpmath_sum(p):
        t2, wl = tr.mp_rule(mpmath.mp.dps + 5)
        P = p * p
        re, im = mpmath.re(P), mpmath.im(P)
        sr = si = mpmath.mpf(0)
        for a0, c in zip(t2, wl):
            a = a0 + re
            d = c / (a * a + im * im)
            sr += d * a
            si += d
        return tr.norm.log_phi0_mp(p) + p * mpmath.mpc(sr, -im * si)

    for dps in (15, 33):
        with mpmath.workdps(dps):
            for p in (mpmath.mpc(0.3, 0.2), mpmath.mpc(40, -100), mpmath.mpf(2)):
                assert tr.log_phi_panel_mp(p) == mpmath_sum(p)


def test_integral_equation_3_22(exact03):
    # int_0^oo qhat(tau') N(tau' - tau) dtau' = pi^2 A (tau + h), with N from (3.17)
    A = float(BondedLayer("3/10").A)
    h = float(exact03.h)

    def lhs(tau):
        f = lambda x: float(exact03.q_numpy(x)) * float(boundary_kernel_N("3/10", x - tau))
        pts = [0.0, tau, tau + 1, tau + 5, tau + 60] if tau > 0 else [0.0, 1, 5, 60]
        return sum(integrate.quad(f, a, b, limit=200, epsabs=1e-13, epsrel=1e-13)[0]
                   for a, b in itertools.pairwise(pts))

    for tau in (0.0, 0.4, 3.0):
        val = lhs(tau)
        assert val == pytest.approx(np.pi**2 * A * (tau + h), rel=1e-9, abs=1e-10)
        # the equation discriminates: Alexandrov's h~ misses it by pi^2 A |h - h~|
        assert abs(val - np.pi**2 * A * (tau + float(exact03.h_alexandrov))) > 1e-3


def test_force_defect_is_half_m1(exact03, alex03):
    # int (Qhat(v) - max(v,0)) dv = m_1/2 with m_1 from the kernel series (2.20), for the exact
    # kernel and for Alexandrov's (3.19) (whose m_1 is matched by (3.21))
    _, m1 = _A_m1("3/10")
    assert exact03.force_defect() == pytest.approx(m1 / 2, abs=1e-9)
    assert alex03.force_defect() == pytest.approx(m1 / 2, abs=1e-9)
    _, m1 = _A_m1("-1/2")
    assert boundary_layer_exact("-1/2").force_defect() == pytest.approx(m1 / 2, abs=1e-9)


def test_force_defect_by_direct_quadrature_for_negative_h():
    # nu = 2/5 has h < 0: the identity needs the whole line, int_{-oo}^{oo} (Qhat(v) - max(v, 0)) dv;
    # the half-line integral int_0^oo (Qhat - v) dv misses int_h^0 Qhat dv > 0
    sol = boundary_layer_exact("2/5")
    _, m1 = _A_m1("2/5")
    h = float(sol.h)
    assert h < 0
    f = lambda v: float(sol.pressure(v)) - max(v, 0.0)
    V = h + sol.tau_max
    whole = sum(integrate.quad(f, a, b, limit=400, epsabs=1e-13)[0]
                for a, b in itertools.pairwise([h, 0.0, 1.0, 10.0, V]))
    assert whole == pytest.approx(m1 / 2, abs=1e-9)
    missed = integrate.quad(lambda v: float(sol.pressure(v)), h, 0.0, epsabs=1e-14)[0]
    assert missed > 1e-4


def test_3_21_as_printed_is_read_as_a_derivative_of_L_over_s():
    # (3.21) m_1 = (1/(2A)) lim d^2/ds^2 [L(s)/s]; read literally as lim L''(s)/s it gives 3 m_1
    lay = BondedLayer("3/10")
    s = sp.Symbol("s")
    Ls = sp.series(lay.L(s), s, 0, 6).removeO()
    A, m1 = lay.A, lay.m(1)
    assert sp.nsimplify(sp.limit(sp.diff(Ls / s, s, 2), s, 0) / (2 * A)) == m1
    assert sp.nsimplify(sp.limit(sp.diff(Ls, s, 2) / s, s, 0) / (2 * A)) == 3 * m1


def test_h_from_panel_rule_matches_adaptive_quadrature(exact03):
    assert exact03._transform.h_np() == pytest.approx(float(exact03.h), abs=1e-12)


def test_solution_object(exact03):
    with pytest.raises(dataclasses.FrozenInstanceError):
        exact03.h = 0
    assert "3.25" in exact03.latex()
    with pytest.raises(ValueError, match="tau"):
        exact03.q(-1)
    with pytest.raises(ValueError, match="tau"):
        exact03.q_numpy([-1.0])
    with pytest.raises(ValueError, match="Re p"):
        exact03.laplace(-1)
    v = np.array([-1.0, float(exact03.h), 3.0])
    p = exact03.pressure(v)
    assert p[0] == 0 and p[1] == 0 and p[2] == pytest.approx(float(exact03.q_numpy(3.0 - float(exact03.h))))


def test_laplace_transform_small_p(exact03):
    # 1/(p^2 Phi) = 1/p^2 + h/p + (h^2/2 + m_1/2) + O(p): the p^2 term of log Phi is m_1/2 (2.20)
    _, m1 = _A_m1("3/10")
    h = exact03.h
    p = mpmath.mpf("1e-4")
    val = exact03.laplace(p) - 1 / p**2 - h / p
    assert float(val) == pytest.approx(float(h**2 / 2 + m1 / 2), abs=1e-3)


# ------------------------------------------------------------------ slow validation
@slow
@pytest.mark.slow
def test_q_quad_route_matches_panel_route(exact03):
    for tau in (0.05, 2.0):
        a = exact03.q(tau, dps=20, method="quad")
        b = exact03.q(tau, dps=20, method="panel")
        assert abs(a - b) < 1e-15


@slow
@pytest.mark.slow
@pytest.mark.parametrize("nu", [-0.999, 0.45, 0.49, 0.499])
def test_table_across_range(nu):
    sol = boundary_layer_exact(nu)
    _, m1 = _A_m1(nu)
    scale = 1 + abs(float(sol.h))
    for tau in (1e-3 * sol.tau_max, 0.05 * sol.tau_max, 0.3 * sol.tau_max):
        assert float(sol.q(tau)) == pytest.approx(float(sol.q_numpy(tau)), abs=1e-10 * scale)
    assert sol.force_defect() == pytest.approx(m1 / 2, abs=1e-9 * scale)


# ------------------------------------------------------------------ the shipped tables (issue 28 item 7)
def _shipped():
    from thinlayer.asymptotics import _wiener_hopf_tables as T

    return [(nu, T.table_key(nu, *T.SHIPPED_ARGS)) for nu in T.SHIPPED_NUS]


def test_every_shipped_nu_has_its_table():
    from thinlayer.asymptotics import _wiener_hopf_tables as T

    assert sorted(T.shipped_keys()) == sorted(k for _, k in _shipped())
    # a float is its exact binary value, not the decimal it prints as
    assert T.table_key(0.3, *T.SHIPPED_ARGS) != T.table_key("3/10", *T.SHIPPED_ARGS)
    assert T.shipped_table("1/7", *T.SHIPPED_ARGS) is None


#: checked in the default run (each check builds the solution's kernel and edge shift: ~1 s); all with THINLAYER_SLOW=1
DEFAULT_CHECKED = ("3/10", 0.45, "frictionless")


@pytest.mark.parametrize("nu,key", [pytest.param(nu, k, marks=[] if nu in DEFAULT_CHECKED else [pytest.mark.slow])
                                    for nu, k in _shipped()], ids=lambda v: str(v))
def test_shipped_table_equals_a_fresh_inversion_between_its_nodes(nu, key):
    """The shipped series at a point between its Chebyshev nodes (the midpoint in the node angle of nodes 5 and 6)
    equals q̂(τ) - τ computed now by the route that built it (de Hoog), to the table's accuracy 2e-11 (1 + |h|)."""
    from thinlayer.asymptotics import _wiener_hopf_tables as T

    layer = "frictionless" if nu == "frictionless" else nu
    sol = wiener_hopf_solution(layer)
    assert np.array_equal(np.asarray(sol.cheb), T.shipped_table(nu, *T.SHIPPED_ARGS))  # it is what the solution uses
    n = len(sol.cheb)
    x = math.cos(math.pi * 6 / n)  # between the nodes cos(pi (5.5)/n) and cos(pi (6.5)/n)
    tau = (0.5 * math.sqrt(sol.tau_max) * (x + 1)) ** 2
    fresh = float(sol.table_check(tau)[0])
    assert float(sol.q_numpy(tau)) - tau == pytest.approx(fresh, abs=2e-11 * (1 + abs(float(sol.h))))


def test_a_table_that_is_not_shipped_is_built_and_cached():
    from thinlayer.asymptotics import _wiener_hopf_tables as T
    from thinlayer.asymptotics.wiener_hopf import fresh_table

    assert T.shipped_table("1/7", "exact", "alexandrov", 20, 16) is None
    cheb = fresh_table("1/7", n=16)
    sol = wiener_hopf_solution("1/7", n=16)
    assert np.array_equal(cheb, np.asarray(sol.cheb)) and len(cheb) == 16
    tau = 0.37 * sol.tau_max
    # 16 nodes resolve q̂ - τ to ~1e-5 of its scale: the table against the mpmath inversion
    assert float(sol.q_numpy(tau)) == pytest.approx(float(sol.q(tau)), abs=1e-4 * (1 + abs(float(sol.h))))


@slow
@pytest.mark.parametrize("nu,key", _shipped(), ids=lambda v: str(v))
def test_shipped_table_rebuilt(nu, key):
    from thinlayer.asymptotics import _wiener_hopf_tables as T
    from thinlayer.asymptotics.wiener_hopf import fresh_table

    new = fresh_table(nu, *T.SHIPPED_ARGS)
    old = T.shipped_table(nu, *T.SHIPPED_ARGS)
    assert new.shape == old.shape and np.max(np.abs(new - old)) < 1e-13

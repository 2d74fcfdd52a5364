"""Kernel moments (2.15)-(2.21) and the moment asymptotic expansion (2.14), (2.16), (2.22)-(2.23)."""
import math

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, kernel_moment, moment_expansion
from thinlayer import symbols as S

NU = sp.Rational(3, 10)


def test_odd_moments_vanish_2_19():
    layer = BondedLayer()
    for a1 in range(6):
        for a2 in range(6):
            if a1 % 2 or a2 % 2:
                assert kernel_moment(layer, a1, a2) == 0  # (2.19), first two lines


def test_moment_weights_are_those_of_2_22():
    # mu_alpha / alpha! = (-1)^n pi^2 A m_n C(n, k): the weights of (2.22)
    layer = BondedLayer()
    for n in range(4):
        for k in range(n + 1):
            mu = kernel_moment(layer, 2 * k, 2 * n - 2 * k)
            w = (-1) ** n * sp.pi**2 * layer.A * layer.m(n) * sp.binomial(n, k)
            assert sp.cancel(mu / (sp.factorial(2 * k) * sp.factorial(2 * n - 2 * k)) - w) == 0


def test_pairing_equals_operator_series():
    # (2.16) built from single moments (2.21) equals the Laplacian form (2.22)-(2.23) at the origin
    me = moment_expansion(BondedLayer(), 3)
    x, y = S.xi1, S.xi2
    phi = sp.exp(-(x**2 + 2 * y**2) / 2) * (1 + x + x**2 * y + y**4)
    a = me.pairing(phi)
    b = me.apply(phi).subs({x: 0, y: 0})
    assert sp.simplify(sp.expand(a - b)) == 0


# ---------------------------------------------------------------- numerical moments of k(xi)
def _line_kernel_factory(layer, dps=16, smax=21, panel=0.5, nodes=16):
    """N(t) = int k(sigma, t) d sigma (3.16) as pi int_0^oo F(s) cos(st) ds (3.17), F = L(s)/s.

    The slowly decaying 1/s tail is removed with tanh(s)/s, whose cosine transform is
    log coth(pi t / 4) (checked in test_subtraction_identity); the rest decays like s^2 e^{-2s}
    and is integrated with fixed Gauss-Legendre panels whose nodes are reused for every t.
    """
    mp.mp.dps = dps
    xs, ws = np.polynomial.legendre.leggauss(nodes)
    S_, W_, G_ = [], [], []
    for a in np.arange(0, smax, panel):
        for xi, wi in zip(xs, ws):
            s = mp.mpf(a) + mp.mpf(panel) * (1 + mp.mpf(xi)) / 2
            S_.append(s)
            W_.append(mp.mpf(panel) / 2 * mp.mpf(wi))
            G_.append((layer.L_numeric(s, "mpmath") - mp.tanh(s)) / s)

    def remainder(t):
        return mp.pi * mp.fsum(w * g * mp.cos(s * t) for s, w, g in zip(S_, W_, G_))

    def N(t):
        t = mp.mpf(t)
        return mp.pi * mp.log(mp.coth(mp.pi * t / 4)) + remainder(t)

    N.log_part = lambda t: mp.pi * mp.log(mp.coth(mp.pi * mp.mpf(t) / 4))
    N.remainder = remainder
    return N


def test_subtraction_identity():
    for t in (0.2, 1.3):
        v = mp.quadosc(lambda s: mp.tanh(s) / s * mp.cos(s * t), [0, mp.inf], omega=t)
        assert abs(v - mp.log(mp.coth(mp.pi * t / 4))) < 1e-15


def test_mu00_mu20_by_quadrature_of_the_kernel():
    # (2.15) for alpha = (0,0) and (0,2): mu = int t^a2 N(t) dt with N(t) = int k(sigma, t) d sigma (3.16)
    layer = BondedLayer(NU)
    N = _line_kernel_factory(layer)
    # the log-singular part by tanh-sinh, the smooth (entire) remainder by Gauss-Legendre panels
    ts, wt = [], []
    xs, ws = np.polynomial.legendre.leggauss(20)
    for a, b in ((0, 2.5), (2.5, 5), (5, 9), (9, 14), (14, 20), (20, 28), (28, 36)):
        for x, w in zip(xs, ws):
            ts.append(mp.mpf(a) + (b - a) * (1 + mp.mpf(x)) / 2), wt.append(mp.mpf(w) * (b - a) / 2)
    Rt = [N.remainder(t) for t in ts]
    pts = [0, 1, 4, 10, 20, 40]
    mu00 = 2 * (mp.quad(N.log_part, pts) + mp.fsum(w * r for w, r in zip(wt, Rt)))
    mu02 = 2 * (mp.quad(lambda t: t**2 * N.log_part(t), pts) + mp.fsum(w * t**2 * r for w, t, r in zip(wt, ts, Rt)))
    mu00_exact = mp.mpf(sp.N(kernel_moment(layer, 0, 0), 25))
    mu02_exact = mp.mpf(sp.N(kernel_moment(layer, 0, 2), 25))
    assert abs(mu00 - mu00_exact) < 1e-10 * abs(mu00_exact)  # (2.21), n = 0
    assert abs(mu02 - mu02_exact) < 1e-9 * abs(mu02_exact)  # (2.21), n = 1
    assert kernel_moment(layer, 2, 0) == kernel_moment(layer, 0, 2)


@pytest.mark.slow
def test_mu00_mu20_by_radial_quadrature_of_k():
    # (2.12), (2.15) fully in 2-D: k(r) = (pi/2) int_0^oo L(s) J0(s r) ds = (pi/2)[1/r + int (L-1) J0 ds]
    layer = BondedLayer(NU)
    mp.mp.dps = 15
    xs, ws = np.polynomial.legendre.leggauss(10)
    nodes = []
    for a in np.arange(0, 20, 0.5):
        for xi, wi in zip(xs, ws):
            s = a + 0.25 * (1 + xi)
            nodes.append((mp.mpf(s), mp.mpf(0.25 * wi), layer.L_numeric(mp.mpf(s), "mpmath") - 1))

    def k(r):
        return mp.pi / 2 * (1 / r + mp.fsum(w * g * mp.besselj(0, s * r) for s, w, g in nodes))

    pts = [0, 1, 3, 6, 10, 15, 22]
    mu00 = 2 * mp.pi * mp.quad(lambda r: k(r) * r, pts)
    mu20 = mp.pi * mp.quad(lambda r: k(r) * r**3, pts)
    assert abs(mu00 - mp.mpf(sp.N(kernel_moment(layer, 0, 0)))) < 1e-6
    assert abs(mu20 - mp.mpf(sp.N(kernel_moment(layer, 2, 0)))) < 1e-5


# ---------------------------------------------------------------- (2.16): rate of the expansion
def _gaussian_pairing_exact(layer, Lam):
    """<k(Lambda xi), e^{-|xi|^2/2}> = pi^2 int_0^oo L(s) e^{-Lambda^2 s^2/2} ds (Parseval with (3.10))."""
    Lam = mp.mpf(Lam)
    return mp.pi**2 * mp.quad(lambda s: layer.L_numeric(s, "mpmath") * mp.exp(-Lam**2 * s**2 / 2),
                              [0, 1 / Lam, 4 / Lam, 12 / Lam, 40 / Lam])


@pytest.mark.parametrize("order", [0, 1, 2])
def test_truncation_error_falls_at_predicted_rate_2_16(order):
    layer = BondedLayer(NU)
    phi = sp.exp(-(S.xi1**2 + S.xi2**2) / 2)
    series = moment_expansion(layer, order).pairing(phi)
    f = sp.lambdify(S.Lambda, series, "mpmath")
    with mp.workdps(40):
        lams = [8, 16, 32, 64]
        errs = [abs(_gaussian_pairing_exact(layer, L) - f(mp.mpf(L))) for L in lams]
        slopes = [float(mp.log(errs[i + 1] / errs[i]) / mp.log(2)) for i in range(len(lams) - 1)]
    predicted = -(2 * order + 4)  # first omitted term: n = order + 1, i.e. Lambda^{-2 order - 4}
    print(f"order {order}: measured slopes {slopes}, predicted {predicted}")
    assert abs(slopes[-1] - predicted) < 0.05
    assert all(abs(sl - predicted) < 0.5 for sl in slopes)


def test_operator_apply_on_polynomial_is_finite_2_23():
    # on a polynomial density the operator series terminates: (2.23) with Delta^n p = 0 for 2n > degree
    me = moment_expansion(BondedLayer(), 5)
    p = S.xi1**4 + S.xi2**2
    out = me.apply(p)
    w = me.weights()
    expected = (w[0] * p * S.Lambda**-2 + w[1] * (12 * S.xi1**2 + 2) * S.Lambda**-4 + w[2] * 24 * S.Lambda**-6)
    assert sp.simplify(out - expected) == 0
    assert math.isclose(float(w[0].subs(S.nu, 0.3)), math.pi**2 * (0.4 / 0.98))

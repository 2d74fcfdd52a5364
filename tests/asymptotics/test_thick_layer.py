"""Thick-layer expansion (T.1)-(T.8): each step checked by an independent route.

Independent routes: mpmath/scipy quadrature of the closed-form kernels written out here (not the layer
classes), the angular average by quadrature, sympy's own ``series`` for the reversion (T.7), and the direct
spectral solver (:func:`thinlayer.numerics.solve_axisymmetric`, ~1e-12), which never uses the moments.
"""
import math
import os

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy import integrate, special

from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, Punch
from thinlayer._checks import WorkLimitError
from thinlayer.asymptotics.thick_layer import (
    PUBLISHED_SERIES,
    moment_symbols,
    regular_kernel,
    thick_flat_punch_series,
    thick_layer_expansion,
    thick_moments,
    thick_sphere_series,
)
from thinlayer.layers.kernels import IncompressibleLayer
from thinlayer.numerics import contact_for_radius, solve_axisymmetric

SLOW = os.environ.get("THINLAYER_SLOW") == "1"


def L_bonded(u, nu):
    """(2.3), written out again (numpy)."""
    k = 3 - 4 * nu
    return (2 * k * np.sinh(2 * u) - 4 * u) / (2 * k * np.cosh(2 * u) + 1 + k**2 + 4 * u**2)


def one_minus_L(u, nu=None):
    """1 - L(u) in the overflow-free form (e^{-2u} scaled), bonded (nu) or frictionless (nu=None)."""
    e = np.exp(-2 * u)
    if nu is None:  # times 2 e^{-2u}: L = (1 - e)^2/(1 - e^2 + 4 u e)
        return (2 * e - 2 * e * e + 4 * u * e) / (1 - e * e + 4 * u * e)
    k = 3 - 4 * nu  # times e^{-2u}: den = kappa (1 + e^2) + (1 + kappa^2 + 4u^2) e, den - num free of cancellation
    den = k * (1 + e * e) + (1 + k**2 + 4 * u**2) * e
    return (2 * k * e * e + (1 + k**2 + 4 * u**2 + 4 * u) * e) / den


# --------------------------------------------------------------------------- (T.2)
@pytest.mark.parametrize("nu", [0.3, 0.5, None])
def test_moments_against_scipy_quadrature(nu):
    layer = FrictionlessLayer() if nu is None else IncompressibleLayer() if nu == 0.5 else BondedLayer(nu)
    b = thick_moments(layer, 4)
    for k in range(5):
        ref = sum(integrate.quad(lambda u: u ** (2 * k) * one_minus_L(u, nu), lo, hi, limit=200, epsabs=0,
                                 epsrel=1e-12)[0] for lo, hi in [(0, 1), (1, 4), (4, 12), (12, 30), (30, 90)])
        assert float(b[k]) == pytest.approx(ref, rel=1e-10)


def test_moments_precision_and_frictionless_independent_of_nu():
    hi = thick_moments(BondedLayer(0.3), 2, dps=50)
    lo = thick_moments(BondedLayer(0.3), 2, dps=20)
    assert all(abs(a - b) < mpmath.mpf(10) ** -19 for a, b in zip(hi, lo))
    assert thick_moments(FrictionlessLayer(0.1), 3) == thick_moments(FrictionlessLayer(0.45), 3)


def test_regular_kernel_series_against_quadrature():
    """K(s) by quadrature of (L - 1) J_0 (T.1) vs the moment series (T.2), s < 2H."""
    nu, H, K = 0.3, 1.0, 14
    b = [float(v) for v in thick_moments(BondedLayer(nu), K, dps=16)]
    f = sp.lambdify((sp.Symbol("s", nonnegative=True), sp.Symbol("H", positive=True), *moment_symbols(K)),
                    regular_kernel(K))
    for s in (0.3, 0.6):
        val, _ = integrate.quad(lambda a: (L_bonded(a * H, nu) - 1) * special.j0(a * s), 0, 60, limit=500,
                                epsabs=1e-14)
        assert f(s, H, *b) / H == pytest.approx(val, rel=1e-8, abs=1e-12)


def test_ring_average_against_quadrature():
    from thinlayer.asymptotics.thick_layer import _ring_average

    r, rho = 0.7, 0.4
    for k in range(6):
        avg, _ = integrate.quad(lambda t: (r * r + rho * rho - 2 * r * rho * math.cos(t)) ** k, 0, 2 * math.pi)
        poly = sum(float(a) * r ** (2 * i) * rho ** (2 * j) for (i, j), a in _ring_average(k).items())
        assert poly == pytest.approx(avg / (2 * math.pi), rel=1e-13)


# --------------------------------------------------------------------------- (T.4)-(T.6)
def test_order_zero_is_the_half_space_solution():
    """Order 0 of a quartic punch against the direct solver on the half-space (L = 1), and Hertz symbolically."""
    ex = thick_layer_expansion(Punch.paraboloid(), order=1)
    c, R, vt = sp.symbols("c R vartheta", positive=True)
    assert sp.simplify(ex.delta_terms[0] - c**2 / R) == 0
    assert sp.simplify(ex.force_terms[0] - 8 * vt * c**3 / (3 * R)) == 0
    punch = Punch("x_1**2/4 + x_2**2/4 + (x_1**2 + x_2**2)**2")
    ex = thick_layer_expansion(punch, order=0)
    res = contact_for_radius(HalfSpace(), punch, 0.6, nu=0.3, mu=1.0)
    subs = {sp.Symbol("c", positive=True): 0.6, sp.Symbol("vartheta", positive=True): 1 / 0.7}
    assert float(ex.delta_terms[0].subs(subs)) == pytest.approx(res.delta0, rel=1e-11)
    assert float(ex.force_terms[0].subs(subs)) == pytest.approx(res.force, rel=1e-11)
    p = sp.lambdify(sp.Symbol("r", nonnegative=True), ex.pressure_terms[0].subs(subs))
    rr = np.array([0.0, 0.3, 0.55, 0.599])
    assert np.allclose([p(x) for x in rr], res.pressure_at(rr), rtol=1e-9, atol=1e-12)


def test_first_correction_is_a_rigid_shift():
    """(T.2) with k = 0: the regular part adds the constant -b_0 P/(2 pi vartheta H) to u_3 (T.5)."""
    ex = thick_layer_expansion(Punch.paraboloid(), order=2)
    c, R, H, vt = sp.symbols("c R H vartheta", positive=True)
    b0 = moment_symbols(0)[0]
    P0 = ex.force_terms[0]
    assert sp.simplify(ex.delta_terms[1] * c / H - (-b0 * P0 / (2 * sp.pi * vt * H))) == 0
    assert ex.force_terms[1] == 0 and ex.delta_terms[2] == 0


@pytest.mark.parametrize("layer", [BondedLayer(0.3), IncompressibleLayer(), FrictionlessLayer(0.3)],
                         ids=["nu=0.3", "nu=0.5", "frictionless"])
def test_general_punch_against_direct_solver(layer):
    """Quartic punch at c/H = 0.25: delta0(c), P(c) through (c/H)^10 and p(r) against contact_for_radius."""
    punch = Punch("x_1**2/2 + x_2**2/2 + (x_1**2 + x_2**2)**2/3")
    ex = thick_layer_expansion(punch, order=16)
    H, c, mu = 5.0, 1.0, 1.3
    nu = layer.numeric_nu if layer.numeric_nu is not None else 0.3
    f = ex.numeric(layer)
    d, P, _, _ = f(c, H, mu, nu)
    res = contact_for_radius(layer, punch, c, H=H, mu=mu, nu=None if layer.numeric_nu is not None else nu)
    assert d == pytest.approx(res.delta0, rel=1e-8)
    assert P == pytest.approx(res.force, rel=1e-8)
    v = ex.evaluate(layer, res.delta0, H, mu, nu)
    assert v.radius == pytest.approx(c, rel=1e-8)
    assert v.force_error < 1e-6 and abs(v.force / res.force - 1) < v.force_error


# --------------------------------------------------------------------------- (T.7)
def test_sphere_series_against_sympy_reversion():
    """(T.7) by an independent reversion of the (T.5) terms, through chi^5: sympy's power-series ring
    (``rs_nth_root``, ``rs_series_reversion``, ``rs_subs``; exact over QQ[b_k, 1/pi]), not the engine's algorithm."""
    from sympy.polys.ring_series import rs_mul, rs_nth_root, rs_pow, rs_series_inversion, rs_series_reversion, rs_subs
    from sympy.polys.rings import ring

    N = 5
    ex = thick_layer_expansion(Punch.paraboloid(), order=N)
    c, R, vt = sp.symbols("c R vartheta", positive=True)
    dn = [sp.expand(t / (c**2 / R)) for t in ex.delta_terms]  # D(eps) = delta0/(c^2/R)
    fn = [sp.expand(t / (8 * vt * c**3 / (3 * R))) for t in ex.force_terms]  # F(eps) = P/(8 vartheta c^3/(3R))
    q, E, X = sp.symbols("q e x")  # q = 1/pi, eps = H/c, chi
    bs = sorted({s for t in dn + fn for s in t.free_symbols if s.name.startswith("b_")}, key=lambda s: s.name)
    Rg, *gens = ring([*bs, q, E, X], sp.QQ)
    e, x = gens[-2], gens[-1]
    D = sum((Rg(sp.expand(t.subs(sp.pi, 1 / q))) * e**m for m, t in enumerate(dn)), Rg(0))
    F = sum((Rg(sp.expand(t.subs(sp.pi, 1 / q))) * e**m for m, t in enumerate(fn)), Rg(0))
    # chi = eps sqrt(D(eps)) (the contact radius a = c sqrt(D)), reverted: eps(chi)
    eps = rs_series_reversion(rs_mul(e, rs_nth_root(D, 2, e, N + 1), e, N + 1), e, N + 1, x)
    inv_sqrt_D = rs_series_inversion(rs_nth_root(rs_subs(D, {e: eps}, x, N + 1), 2, x, N + 1), x, N + 1)
    ratio = rs_mul(rs_subs(F, {e: eps}, x, N + 1), rs_pow(inv_sqrt_D, 3, x, N + 1), x, N + 1)  # F D^{-3/2}

    def coeff(series, n):
        return sum((Rg({k: v}).as_expr() / X**n for k, v in series.terms() if k[-1] == n), sp.S(0)).subs(q, 1 / sp.pi)

    s = thick_sphere_series(N)
    for n in range(N + 1):
        assert sp.expand(coeff(ratio, n) - s.force[n]) == 0, n
        assert sp.expand(coeff(inv_sqrt_D, n) - s.radius[n]) == 0, n
    b0 = moment_symbols(0)[0]
    assert s.force[1] == 2 * b0 / sp.pi  # the flat-punch/rigid-shift term (T.2), k = 0
    assert s.force[2] == sp.Rational(14, 3) * b0**2 / sp.pi**2


@pytest.mark.parametrize("layer", [IncompressibleLayer(), BondedLayer(0.3), FrictionlessLayer(0.3)],
                         ids=["nu=0.5", "nu=0.3", "frictionless"])
def test_sphere_series_observed_order(layer):
    """Against the direct solver: the remainder after chi^N falls at least like chi^{N+1} (N = 1, 2, 3), and it is
    the next term beta_{N+1} chi^{N+1} to leading order (where that term is not accidentally small)."""
    s = thick_sphere_series(16)
    fc, rc = s.coefficients(layer)
    nu = layer.numeric_nu if layer.numeric_nu is not None else 0.3
    rem = {}
    for chi in (0.02, 0.04, 0.1):
        res = solve_axisymmetric(layer, Punch.paraboloid(1), chi**2, H=1.0, mu=1.0,
                                 nu=None if layer.numeric_nu is not None else nu)
        ratio = res.force / (8 / 3 / (1 - nu) * chi**3)
        for N in range(1, 7):
            rem[chi, N] = ratio - np.polynomial.polynomial.polyval(chi, fc[: N + 1])
        assert abs(np.polynomial.polynomial.polyval(chi, fc) / ratio - 1) < 1e-12
        assert abs(np.polynomial.polynomial.polyval(chi, rc) * chi / res.radius - 1) < 1e-11
    for N in (1, 2, 3):
        if abs(fc[N + 1]) > 0.1:  # (frictionless: beta_4 = 0.0076, the remainder after chi^3 is beta_5 chi^5)
            order = math.log2(abs(rem[0.04, N] / rem[0.02, N]))
            assert N + 0.6 < order < N + 1.4, (N, order)
    for N in range(1, 6):
        nxt = fc[N + 1] * 0.1 ** (N + 1)
        if abs(fc[N + 1]) > 0.1:
            assert abs(rem[0.1, N] - nxt) < 0.35 * abs(nxt), (N, rem[0.1, N], nxt)


def test_series_estimate_covers_the_error():
    s = thick_sphere_series(16)
    layer = IncompressibleLayer()
    fc, _ = s.coefficients(layer)
    for chi in (0.4, 0.55):
        res = solve_axisymmetric(layer, Punch.paraboloid(1), chi**2, H=1.0, mu=1.0)
        err = abs(np.polynomial.polynomial.polyval(chi, fc) / (res.force / (16 / 3 * chi**3)) - 1)
        est, _ = s.error_estimate(chi, layer)
        assert err < est < 20 * err + 1e-12


def test_flat_punch_series():
    """Flat punch (no edge condition): the rigid shift b_0 P/(2 pi vartheta H) iterated gives the geometric
    series 1 + q + q^2 + ..., q = 2 b_0 c/(pi H) (P = 4 vartheta c delta for the half-space), until b_1 enters at
    (c/H)^3 through the parabolic part of the kernel: its displacement (b_1/(8 pi vartheta H^3)) <|x-y|^2>
    averaged with the flat-punch pressure gives -2 b_1/(3 pi)."""
    s = thick_flat_punch_series(4)
    b0, b1 = moment_symbols(1)
    assert s.force[1] == 2 * b0 / sp.pi and s.force[2] == 4 * b0**2 / sp.pi**2
    assert sp.expand(s.force[3] - (8 * b0**3 / sp.pi**3 - 2 * b1 / (3 * sp.pi))) == 0


def test_published_series_differ_where_the_errata_say():
    """The printed coefficients vs (T.7) at nu = 1/2: D02 misses the contact-radius change from chi^2 on; the
    coefficients G&G print for the sphere agree at chi^3 only (to their last digit)."""
    fc, _ = thick_sphere_series(4).coefficients(IncompressibleLayer())
    ff, _ = thick_sphere_series(4).coefficients(FrictionlessLayer())
    d02 = PUBLISHED_SERIES["dimitriadis2002-bonded"]["coefficients"]
    gg = PUBLISHED_SERIES["garcia2018-sphere"]["coefficients"]
    nb = PUBLISHED_SERIES["dimitriadis2002-nonbonded"]["coefficients"]
    assert all(abs(a - b) > 0.005 for a, b in zip(d02, fc[1:]))
    assert [abs(a - b) > 0.0015 for a, b in zip(gg, fc[1:])] == [True, True, False, True]
    assert all(abs(a - b) > 0.004 for a, b in zip(nb[:3], ff[1:4]))


# --------------------------------------------------------------------------- errors
def test_errors():
    with pytest.raises(ValueError, match="axisymmetric"):
        thick_layer_expansion(Punch.elliptic_paraboloid(2, 1))
    with pytest.raises(WorkLimitError):
        thick_layer_expansion(Punch.paraboloid(), order=41)
    with pytest.raises(ValueError, match="numeric kernel"):
        thick_moments(BondedLayer(), 2)
    with pytest.raises(ValueError, match="c < 0.9 H"):
        thick_layer_expansion(Punch.paraboloid(1), order=4).evaluate(BondedLayer(0.3), 5.0, H=1.0)
    with pytest.raises(ValueError, match="at least 2"):
        thick_sphere_series(1)


@pytest.mark.skipif(not SLOW, reason="slow: set THINLAYER_SLOW=1 (sympy solves the Navier equations, ~40 s)")
def test_kernels_from_elasticity():
    """Plane-strain Navier equations of the layer (sympy): the frictionless-base kernel does not depend on nu,
    which is why its thick-layer moments (and a published nu-dependence, see the errata) cannot."""
    z, a, H, mu, nu, x = sp.symbols("z alpha H mu nu x", positive=True)
    lam = 2 * mu * nu / (1 - 2 * nu)
    C = sp.symbols("C0:8")
    E = sp.exp(a * z)
    U = (C[0] + C[1] * z) * E + (C[2] + C[3] * z) / E
    W = (C[4] + C[5] * z) * E + (C[6] + C[7] * z) / E

    def fields(U, W):
        ux, uz = U * sp.sin(a * x), W * sp.cos(a * x)
        div = sp.diff(ux, x) + sp.diff(uz, z)
        e1 = mu * (sp.diff(ux, x, 2) + sp.diff(ux, z, 2)) + (lam + mu) * sp.diff(div, x)
        e2 = mu * (sp.diff(uz, x, 2) + sp.diff(uz, z, 2)) + (lam + mu) * sp.diff(div, z)
        szz = lam * div + 2 * mu * sp.diff(uz, z)
        sxz = mu * (sp.diff(ux, z) + sp.diff(uz, x))
        return [sp.expand(sp.simplify(q)) for q in (e1 / sp.sin(a * x), e2 / sp.cos(a * x), szz / sp.cos(a * x),
                                                    sxz / sp.sin(a * x))]

    t = sp.Symbol("t", positive=True)
    e1, e2, _, _ = fields(U, W)
    eqs = []
    for e in (e1, e2):
        e = sp.expand(sp.expand(sp.cancel(e * (1 - 2 * nu)).subs(E, t)) * t)
        eqs += sp.Poly(e, t, z).coeffs()
    sol = sp.solve(eqs, C[:4], dict=True)[0]
    U, W = U.subs(sol), W.subs(sol)
    _, _, szz, sxz = fields(U, W)
    bcs = [szz.subs(z, 0) + 1, sxz.subs(z, 0), W.subs(z, H), sxz.subs(z, H)]
    s = sp.solve(bcs, C[4:], dict=True)[0]
    L = W.subs(s).subs(z, 0) * mu / (1 - nu) * a
    for nv in (sp.Rational(1, 10), sp.Rational(4, 10)):
        for u in (sp.Rational(1, 2), 2):
            val = float(L.subs({nu: nv, H: u / a}).subs(a, 1))
            assert val == pytest.approx(float((sp.cosh(2 * u) - 1) / (sp.sinh(2 * u) + 2 * u)), rel=1e-12)

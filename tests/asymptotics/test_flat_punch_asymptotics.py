"""Tests of the flat-punch asymptotics :mod:`thinlayer.asymptotics.flat_punch` (F.10)-(F.19).

References independent of the formulas under test:

* sympy's own calculus (the radial Laplacian, ``integrate``, series of Bessel functions written as sums) and
  mpmath's Bessel functions and quadrature;
* the paper's (2.27), ``p_0 = phi^*/(pi^2 A)`` with (2.25), for the inner pressure of a constant gap;
* the exact stiffness of :mod:`thinlayer.numerics.flat_punch` (a Fredholm equation of the exact kernel, no
  expansion): the observed orders of the remainders (log-log slopes) and their coefficients;
* the thick-layer series of :mod:`thinlayer.asymptotics.thick_layer` (ring averages and Galin's theorem in the
  pressure plane, not the Abel-plane Fredholm kernel expanded here), symbolically;
* the Wiener-Hopf solution's own Laplace transform for the flat-punch edge layer ``1/(p Phi(p)) = 1/p + h + ...``.
"""
from __future__ import annotations

import math
import os

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, HalfSpace
from thinlayer import symbols as S
from thinlayer._checks import WorkLimitError
from thinlayer.asymptotics.flat_punch import (
    ThinDerivation,
    flat_punch_moments,
    lam,
    psi,
    thick_flat_punch,
    thick_flat_punch_coefficients,
    thin_flat_punch,
    thin_flat_punch_derivation,
)
from thinlayer.asymptotics.wiener_hopf import boundary_layer_exact, edge_shift_exact
from thinlayer.layers.kernels import IncompressibleLayer
from thinlayer.numerics.flat_punch import flat_punch_kappa

SLOW = os.environ.get("THINLAYER_SLOW") == "1"


def slope(x, y) -> float:
    """Least-squares slope of log|y| against log x."""
    return float(np.polyfit(np.log(x), np.log(np.abs(y)), 1)[0])


def exact(layer, xs) -> np.ndarray:
    return np.array([flat_punch_kappa(layer, float(x), error_estimate=False).kappa for x in xs])


# --------------------------------------------------------------------------- (F.10)-(F.14): symbolic
def test_leading_term_from_the_inner_expansion():
    """(F.10): p_0 of the R -> oo paraboloid is (2.27) with phi^* = pi^2 vartheta delta0^*/H_* (2.25), a constant."""
    d = thin_flat_punch_derivation()
    A = ThinDerivation.A
    phi_star = sp.pi**2 * S.vartheta / S.H * S.delta0  # (2.25) with Phi = 0, dimensional
    assert sp.simplify(d.p0 - phi_star / (sp.pi**2 * A)) == 0  # (2.27)
    # P = pi a^2 p0, kappa = P/(4 vartheta a w0), a = lambda H
    assert sp.simplify(d.leading - sp.pi * lam / (4 * A)) == 0
    assert sp.expand(d.two_term - sp.pi * (lam + 2 * ThinDerivation.h) / (4 * A)) == 0
    assert sp.simplify(d.resummed - sp.pi * (lam + ThinDerivation.h) ** 2 / (4 * A * lam)) == 0


def test_incompressible_outer_problem_by_hand():
    """(F.13): -(H^3/(3 mu)) Delta p = w0 with p(a_e) = 0, checked with the radial Laplacian (no engine operator)."""
    d = thin_flat_punch_derivation()
    r, ae, a = sp.symbols("r a_e a", positive=True)
    p = d.incompressible_pressure
    lap = sp.diff(p, r, 2) + sp.diff(p, r) / r
    assert sp.simplify(-(S.H**3 / (3 * S.mu)) * lap - S.delta0) == 0
    assert p.subs(r, ae) == 0
    P = sp.integrate(2 * sp.pi * r * p.subs(ae, a), (r, 0, a))
    kappa = sp.simplify((P / (4 * 2 * S.mu * a * S.delta0)).subs(a, lam * S.H))  # vartheta = 2 mu at nu = 1/2
    assert sp.simplify(kappa - 3 * sp.pi * lam**3 / 64) == 0 and sp.simplify(d.incompressible_leading - kappa) == 0
    h = ThinDerivation.h
    assert sp.expand(d.incompressible_two_term - 3 * sp.pi * (lam**3 + 4 * h * lam**2) / 64) == 0
    assert sp.simplify(d.incompressible_resummed - 3 * sp.pi * (lam + h) ** 4 / (64 * lam)) == 0


def test_two_term_model_solution_and_force():
    """(F.15): p = p_inf (1 - I0(kr)/I0(k a_e)) solves c0 p - c1 H^2 (p'' + p'/r) = vartheta w0/H, and
    int_0^{a_e} I0(k r) r dr = a_e I1(k a_e)/k (mpmath quadrature)."""
    r, k, ae, c0, c1 = sp.symbols("r k a_e c_0 c_1", positive=True)
    pinf = S.vartheta * S.delta0 / (c0 * S.H)
    p = pinf * (1 - sp.besseli(0, k * r) / sp.besseli(0, k * ae))
    residual = c0 * p - c1 * S.H**2 * (sp.diff(p, r, 2) + sp.diff(p, r) / r) - S.vartheta * S.delta0 / S.H
    residual = residual.subs(k, sp.sqrt(c0 / c1) / S.H)
    vals = {r: sp.Rational(7, 10), ae: sp.Rational(13, 10), c0: sp.Rational(2, 5), c1: sp.Rational(3, 10),
            S.H: sp.Rational(9, 10), S.vartheta: sp.Rational(17, 10), S.delta0: sp.Rational(1, 100)}
    assert abs(sp.N(residual.subs(vals), 40)) < 1e-35
    for kv, aev in ((0.5, 2.0), (3.0, 7.0)):
        quad = mpmath.quad(lambda x: mpmath.besseli(0, kv * x) * x, [0, aev])
        assert quad == pytest.approx(float(aev * mpmath.besseli(1, kv * aev) / kv), rel=1e-14)


def test_psi_against_mpmath_and_its_limits():
    """psi(x) = 8 (1 - 2 I1/(x I0))/x^2 (F.15): series below x = 1, Bessel ratio above; psi(0) = 1."""
    xs = np.array([0.0, 1e-6, 0.1, 0.5, 0.999, 1.0, 1.001, 3.0, 20.0, 700.0, 1e5])
    with mpmath.workdps(60):  # the cancellation 1 - 2 I1/(x I0) = x^2/8 + ... at small x
        ref = [1.0 if x == 0 else float(8 * (1 - 2 * mpmath.besseli(1, x) / (x * mpmath.besseli(0, x))) / x**2)
               for x in map(mpmath.mpf, xs)]
    np.testing.assert_allclose(psi(xs), ref, rtol=1e-13)
    big = 1e4
    assert float(psi(big)) == pytest.approx(8 / big**2 - 16 / big**3, rel=1e-7)  # -> (F.12) for large x


def test_flat_edge_layer_is_the_derivative_of_the_smooth_one():
    """(F.11): the flat punch's edge layer has the transform 1/(p Phi) = p x (smooth punch's 1/(p^2 Phi)), whose
    expansion 1/p + h + O(p) gives the excess force h: checked on the Wiener-Hopf solution's own transform."""
    sol = boundary_layer_exact(0.3, dps=20)
    h = float(edge_shift_exact(0.3))
    for p in (1e-3, 2e-3):
        flat = p * sol.laplace(p)  # int_0^oo qhat' e^{-p tau} dtau = p L[qhat] (qhat(0) = 0)
        assert float(flat - 1 / mpmath.mpf(p)) == pytest.approx(h, abs=3 * p)


# --------------------------------------------------------------------------- thin layer against the exact solver
@pytest.mark.parametrize("layer", [BondedLayer(0.3), BondedLayer(0.0), FrictionlessLayer()], ids=str)
def test_compressible_orders_and_the_h_squared_term(layer):
    """Two-term (F.11) remainder: slope -1 and coefficient pi h^2/(4A); resummed (F.12): slope -2."""
    th = thin_flat_punch(layer)
    xs = np.array([40.0, 60.0, 90.0, 130.0])
    ex = exact(layer, xs)
    r2 = ex - th.two_term(xs)
    assert slope(xs, ex - th.leading(xs)) == pytest.approx(0.0, abs=0.01)
    assert slope(xs, r2) == pytest.approx(-1.0, abs=0.06)
    assert (r2 * xs)[-1] == pytest.approx(math.pi * th.h**2 / (4 * th.A), rel=0.03)
    # the compressible form (F.12) itself, whatever model the layer's resummed() uses
    r12 = ex - math.pi * (xs + th.h) ** 2 / (4 * th.A * xs)
    assert slope(xs, r12) == pytest.approx(-2.0, abs=0.06)
    assert slope(xs, ex - th.resummed(xs)) == pytest.approx(-2.0, abs=0.06)


def test_incompressible_orders():
    """nu = 1/2: leading slope 2 (of the remainder), two-term (F.14) remainder ~ (3 pi/64) 6 h^2 lambda (slope 1),
    resummed remainder O(1) (slope 0)."""
    layer = IncompressibleLayer()
    th = thin_flat_punch(layer)
    assert th.c1 == pytest.approx(2 / 3, rel=1e-15) and th.h == pytest.approx(1.459081136, rel=1e-9)
    xs = np.array([30.0, 50.0, 80.0, 120.0])
    ex = exact(layer, xs)
    assert slope(xs, ex - th.leading(xs)) == pytest.approx(2.0, abs=0.05)
    r2 = ex - th.two_term(xs)
    assert slope(xs, r2) == pytest.approx(1.0, abs=0.03)
    assert (r2 / xs)[-1] == pytest.approx(3 * math.pi / 64 * 6 * th.h**2, rel=0.01)
    assert abs(slope(xs, ex - th.resummed(xs))) < 0.1


def test_two_term_model_bridges_to_incompressible():
    """(F.15) at nu -> 1/2 tends to (F.14) (slowly: the edge correction (I.12) converges like sqrt(1 - 2 nu)), and
    for 1/4 < nu its error is within the estimate at a/H = 5."""
    th_inc = thin_flat_punch(IncompressibleLayer())
    assert th_inc.regime == "incompressible"
    gaps = []
    for nu in (0.49999, 0.499999, 0.4999999):
        th = thin_flat_punch(BondedLayer(nu))
        assert th.regime == "two-term"
        gaps.append(abs(float(th(5.0)) / float(th_inc(5.0)) - 1))
    assert gaps[0] > gaps[1] > gaps[2] and gaps[2] < 5e-4
    assert gaps[0] / gaps[1] == pytest.approx(math.sqrt(10), rel=0.1)
    for nu in (0.3, 0.45, 0.49, 0.499):
        layer = BondedLayer(nu)
        t = thin_flat_punch(layer)
        err = abs(float(t(5.0)) / flat_punch_kappa(layer, 5.0).kappa - 1)
        assert err <= float(t.error_estimate(5.0))


GRID_NU = [-0.99, -0.5, 0.0, 0.25, 0.3, 0.45, 0.49, 0.499, 0.4999, 0.5, "frictionless"]
GRID_LAMBDA = [1.0, 2.0, 5.0, 12.0, 30.0, 80.0]


def _layer(nu):
    return FrictionlessLayer() if nu == "frictionless" else BondedLayer(nu)


@pytest.mark.parametrize("nu", GRID_NU)
def test_thin_error_estimate_covers_the_error(nu):
    """(F.16) is an envelope: measured error <= 0.75 x estimate (the full 26 x 13 grid: THINLAYER_SLOW=1)."""
    layer = _layer(nu)
    th = thin_flat_punch(layer)
    xs = np.array(GRID_LAMBDA)
    err = np.abs(th(xs) / exact(layer, xs) - 1)
    assert np.all(err <= 0.75 * th.error_estimate(xs))


@pytest.mark.slow
@pytest.mark.skipif(not SLOW, reason="full envelope grid: THINLAYER_SLOW=1")
def test_thin_error_estimate_full_grid():
    nus = [-0.99, -0.9, -0.5, -0.2, 0.0, 0.1, 0.2, 0.25, 0.2501, 0.26, 0.3, 0.35, 0.4, 0.45, 0.47, 0.48, 0.49, 0.495,
           0.498, 0.499, 0.4995, 0.4999, 0.49995, 0.49999, 0.5, "frictionless"]
    xs = np.array([1, 1.5, 2, 3, 5, 8, 12, 20, 30, 50, 80, 120, 200.0])
    worst = 0.0
    for nu in nus:
        layer = _layer(nu)
        th = thin_flat_punch(layer)
        worst = max(worst, float(np.max(np.abs(th(xs) / exact(layer, xs) - 1) / th.error_estimate(xs))))
    assert worst <= 0.75


def test_thin_is_vectorised_and_nu_free_on_a_frictionless_base():
    th = thin_flat_punch(FrictionlessLayer(0.2))
    assert th is thin_flat_punch(FrictionlessLayer(0.45)) and th.A == 0.5
    x = np.linspace(5, 50, 7).reshape(7, 1)
    for f in (th.leading, th.two_term, th.resummed, th.error_estimate):
        assert f(x).shape == (7, 1)
    assert "ThinFlatPunch" in str(th) and r"\tag{F.12}" in th.latex()
    assert r"\tag{F.14}" in thin_flat_punch(IncompressibleLayer()).latex()
    assert r"\tag{F.15}" in thin_flat_punch(BondedLayer(0.4)).latex()


# --------------------------------------------------------------------------- thick layer
def test_thick_coefficients_by_hand():
    """(F.18) low orders, from the Neumann series by hand: f_1 = 2 b0/pi, f_2 = (2 b0/pi)^2,
    f_3 adds K_1 1 = -(2/pi) b1 (x^2/2 + 1/6), whose mean is -2 b1/(3 pi)."""
    c = thick_flat_punch_coefficients(3)
    b0, b1 = sp.symbols("b_0 b_1", positive=True)
    q = 2 * b0 / sp.pi
    assert [sp.expand(v) for v in c] == [1, q, sp.expand(q**2), sp.expand(q**3 - 2 * b1 / (3 * sp.pi))]


def test_thick_series_equals_the_pressure_plane_derivation():
    """(F.18) (Abel-plane kernel) == (T.7) flat punch (ring averages and Galin's theorem), symbolically."""
    thick_layer = pytest.importorskip("thinlayer.asymptotics.thick_layer")
    ours = thick_flat_punch_coefficients(9)
    theirs = thick_layer.thick_flat_punch_series(9).force
    assert all(sp.expand(a - b) == 0 for a, b in zip(ours, theirs))
    for layer in (BondedLayer(0.3), IncompressibleLayer()):
        ref = thick_layer.thick_moments(layer, 3)
        assert [float(v) for v in flat_punch_moments(layer, 3)] == pytest.approx([float(v) for v in ref], rel=1e-15)


def test_moment_b0_by_an_independent_quadrature():
    """b_0 = int_0^oo (1 - L) du: scipy's adaptive quadrature on the numpy kernel against the mpmath value."""
    from scipy import integrate

    for layer in (BondedLayer(0.3), FrictionlessLayer(), IncompressibleLayer()):
        val, _ = integrate.quad(lambda u: 1 - float(layer.L_numeric(u)), 0, 60, limit=200, epsabs=1e-14)
        assert float(flat_punch_moments(layer, 0)[0]) == pytest.approx(val, rel=1e-11)


@pytest.mark.parametrize("layer", [BondedLayer(0.3), IncompressibleLayer(), FrictionlessLayer()], ids=str)
def test_thick_orders_against_the_exact_solver(layer):
    """Truncated after lambda^N, the remainder falls like lambda^(N+1): slopes over 0.02 <= lambda <= 0.1."""
    series = thick_flat_punch(layer)
    xs = np.array([0.02, 0.04, 0.06, 0.08, 0.1])
    ex = exact(layer, xs)
    for N in range(1, 6):
        assert slope(xs, ex - series.partial(xs, N)) == pytest.approx(N + 1, abs=0.25)
    assert np.max(np.abs(series(xs) / ex - 1)) < 1e-12


@pytest.mark.parametrize("layer", [BondedLayer(-0.5), BondedLayer(0.3), IncompressibleLayer()], ids=str)
def test_thick_error_estimate_covers_the_error(layer):
    series = thick_flat_punch(layer)
    xs = np.array([0.05, 0.2, 0.4, 0.6, 0.75])
    err = np.abs(series(xs) / exact(layer, xs) - 1)
    assert np.all(err <= series.error_estimate(xs))
    assert series.error_estimate(0.85) == np.inf


# --------------------------------------------------------------------------- inputs
@pytest.mark.parametrize("layer", [HalfSpace(), BondedLayer(), GenericLayer()], ids=str)
def test_layers_without_numeric_thickness_are_refused(layer):
    with pytest.raises(ValueError, match="finite thickness with a numeric kernel") as exc:
        thin_flat_punch(layer)
    assert "\n" not in str(exc.value)
    with pytest.raises(ValueError, match="finite thickness"):
        thick_flat_punch(layer)


def test_bounds_and_arguments():
    with pytest.raises(WorkLimitError, match="order = 50 exceeds the limit 40"):
        thick_flat_punch(BondedLayer(0.3), 50)
    with pytest.raises(WorkLimitError, match="order \\(symbolic\\) = 20 exceeds the limit 16"):
        thick_flat_punch_coefficients(20)
    with pytest.raises(ValueError, match="order must be an integer >= 2"):
        thick_flat_punch(BondedLayer(0.3), 1)
    with pytest.raises(ValueError, match="a_over_H must be finite and positive"):
        thin_flat_punch(BondedLayer(0.3))(-1.0)
    with pytest.raises(ValueError, match="exceeds the order"):
        thick_flat_punch(BondedLayer(0.3), 4).partial(0.1, 6)
